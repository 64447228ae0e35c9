"""Design studies without a cluster: plans, the study file, paths, one variant, summary statistics."""

from __future__ import annotations

import hashlib
import json
import math
import re
from pathlib import Path

import numpy as np
import pytest
import scipy.stats as st
from hypothesis import given, settings
from hypothesis import strategies as hs

from _shared import EXAMPLES
from chaindrive.errors import InputError, UnknownNameError
from chaindrive.study.plan import (
    MAXIMUM_VARIANTS,
    Variable,
    format_value,
    frozen_distribution,
    full_grid,
    latin_hypercube,
    monte_carlo,
    plan_rows,
    transform,
)
from chaindrive.study.run import evaluate_variant, lookup
from chaindrive.study.spec import canonical_hash, load_study, parse_study, remove_path, set_path
from chaindrive.study.summary import column_statistics, output_unit

# --------------------------------------------------------------------------- plans


def test_grid_size_and_order():
    # full factorial: prod of the level counts, last variable fastest (itertools.product)
    rows = full_grid([[1, 2, 3], ["a", "b"], [0.5, 1.5, 2.5, 3.5]])
    assert len(rows) == 3 * 2 * 4
    assert rows[:3] == [(1, "a", 0.5), (1, "a", 1.5), (1, "a", 2.5)]
    assert len(set(rows)) == len(rows)


def test_grid_levels_linear_and_log():
    v = Variable("drive.speed", "rpm", low=500.0, high=1500.0, count=5)
    assert v.levels() == [500.0, 750.0, 1000.0, 1250.0, 1500.0]
    g = Variable("tensioner.mass", "kg", low=5.0, high=2000.0, count=16, scale="log").levels()
    ratios = np.array(g[1:]) / np.array(g[:-1])
    # geometric spacing: (2000/5)^(1/15) between neighbours; the ends exact
    assert np.allclose(ratios, (2000 / 5) ** (1 / 15), rtol=1e-12)
    assert (g[0], g[-1]) == (5.0, 2000.0)
    assert Variable("x", low=2.0, high=2.0, count=1).levels() == [2.0]
    assert Variable("wheels.0.teeth", low=17, high=25, count=3, integer=True).levels() == [17, 21, 25]


def test_latin_hypercube_stratification():
    # McKay et al. 1979: each of the n equal strata of every axis holds exactly one point
    n, d = 50, 3
    u = latin_hypercube(n, d, seed=11)
    assert u.shape == (n, d)
    for j in range(d):
        assert sorted(np.floor(u[:, j] * n).astype(int).tolist()) == list(range(n))


@settings(max_examples=30, deadline=None)
@given(n=hs.integers(1, 200), d=hs.integers(1, 5), seed=hs.integers(0, 2**31))
def test_latin_hypercube_stratification_property(n, d, seed):
    u = latin_hypercube(n, d, seed=seed)
    assert np.all((u >= 0) & (u < 1))
    for j in range(d):
        assert np.array_equal(np.sort(np.floor(u[:, j] * n)), np.arange(n))


def test_monte_carlo_reproducible_by_seed():
    a = monte_carlo(100, 2, seed=2026)
    assert np.array_equal(a, monte_carlo(100, 2, seed=2026))
    assert not np.array_equal(a, monte_carlo(100, 2, seed=2027))
    vs = [Variable("contact.skew", "arcmin", distribution="uniform", parameters={"loc": 42, "scale": 164})]
    assert plan_rows("monte_carlo", vs, samples=20, seed=5) == plan_rows("monte_carlo", vs, samples=20, seed=5)


def test_monte_carlo_follows_the_named_distribution():
    # inverse-transform sampling (Devroye 1986, II.2.1): a Kolmogorov-Smirnov test against
    # scipy's own CDF, and the sample mean within 4 standard errors
    v = Variable("x", "kg", distribution="norm", parameters={"loc": 50.0, "scale": 10.0})
    x = np.array([r[0] for r in plan_rows("monte_carlo", [v], samples=4000, seed=3)])
    assert st.kstest(x, st.norm(50, 10).cdf).pvalue > 1e-3
    assert abs(x.mean() - 50.0) < 4 * 10 / math.sqrt(x.size)
    w = Variable("y", distribution="lognorm", parameters={"s": 0.5, "scale": 2.0})
    y = np.array([r[0] for r in plan_rows("latin_hypercube", [w], samples=2000, seed=4)])
    assert st.kstest(y, st.lognorm(s=0.5, scale=2.0).cdf).pvalue > 1e-3


@settings(max_examples=40, deadline=None)
@given(low=hs.floats(-1e6, 1e6), width=hs.floats(0, 1e6), u=hs.lists(hs.floats(0, 1), min_size=1, max_size=20))
def test_transform_stays_in_range(low, width, u):
    v = Variable("x", low=low, high=low + width)
    x = transform(np.array(u), v)
    assert np.all(x >= low - 1e-9 * (1 + abs(low))) and np.all(x <= low + width + 1e-9 * (1 + abs(low + width)))


@settings(max_examples=60, deadline=None)
@given(x=hs.floats(1e-9, 1e9))
def test_format_value_roundtrips_through_the_unit_parser(x):
    from chaindrive.units import parse_quantity

    text = format_value(x, "kg")
    assert parse_quantity(text, "kg", field="mass") == pytest.approx(x, rel=1e-11)


def test_format_value():
    assert format_value(50.0, "arcmin") == "50 arcmin"
    assert format_value(19, "") == 19
    assert format_value(True, "") is True
    assert format_value("16B", "") == "16B"


def test_plan_errors():
    with pytest.raises(InputError, match="exactly one of values"):
        Variable("x", values=(1, 2), low=1.0, high=2.0)
    with pytest.raises(InputError, match="exactly one of values"):
        Variable("x")
    with pytest.raises(InputError, match="at least 1 value"):
        Variable("x", values=())
    with pytest.raises(InputError, match="give both low and high"):
        Variable("x", low=1.0)
    with pytest.raises(InputError, match=r"finite low <= high, got low = 3, high = 2"):
        Variable("x", low=3.0, high=2.0)
    with pytest.raises(InputError, match=r"scale = 'log' needs 0 < low"):
        Variable("x", low=0.0, high=2.0, scale="log")
    with pytest.raises(InputError, match="scale must be 'linear' or 'log'"):
        Variable("x", low=1.0, high=2.0, scale="cubic")
    with pytest.raises(InputError, match=r"count needs low and high and must lie in \[1, 2000000\]"):
        Variable("x", low=1.0, high=2.0, count=0)
    with pytest.raises(UnknownNameError, match="unknown distribution 'gauss'"):
        Variable("x", distribution="gauss")
    with pytest.raises(InputError, match=r"takes the parameters \(loc, scale\)"):
        frozen_distribution("norm", {"mu": 1.0})
    with pytest.raises(InputError, match="outside the domain"):
        frozen_distribution("norm", {"loc": 0.0, "scale": -1.0})
    with pytest.raises(InputError, match=r"plan.samples must be a whole number in \[1, 2000000\]"):
        monte_carlo(0, 1, seed=1)
    with pytest.raises(InputError, match="plan.samples"):
        latin_hypercube(MAXIMUM_VARIANTS + 1, 1, seed=1)
    with pytest.raises(InputError, match="at most 2000000 per study"):
        full_grid([range(2000), range(1001)])
    with pytest.raises(InputError, match="vary at least 1 input"):
        plan_rows("grid", [])
    with pytest.raises(InputError, match="needs the number of samples"):
        plan_rows("monte_carlo", [Variable("x", low=0.0, high=1.0)])
    with pytest.raises(InputError, match="need \\(low, high\\) or a distribution"):
        plan_rows("latin_hypercube", [Variable("x", values=(1, 2))], samples=3)
    with pytest.raises(InputError, match="a grid needs values, or low, high and count"):
        plan_rows("grid", [Variable("x", low=0.0, high=1.0)])
    with pytest.raises(UnknownNameError, match="unknown plan 'sobol'"):
        plan_rows("sobol", [Variable("x", low=0.0, high=1.0)], samples=2)
    with pytest.raises(InputError, match="non-finite values"):
        transform(np.array([1.0]), Variable("x", distribution="pareto", parameters={"b": 0.005}))


# --------------------------------------------------------------------------- paths, hashes


def test_set_and_remove_paths():
    d = {"drive": {"speed": "5 rad/s"}, "wheels": [{"teeth": 8}, {"teeth": 6}]}
    set_path(d, "wheels.1.teeth", 9)
    set_path(d, "contact.skew", "50 arcmin")
    assert d["wheels"][1]["teeth"] == 9 and d["contact"] == {"skew": "50 arcmin"}
    remove_path(d, "contact.skew")
    assert d["contact"] == {}
    with pytest.raises(InputError, match=r"valid indices 0\.\.\.1"):
        set_path(d, "wheels.5.teeth", 3)
    with pytest.raises(InputError, match="index 7 is outside"):
        set_path(d, "wheels.7", 3)
    with pytest.raises(InputError, match="no table to hold .value."):
        set_path(d, "drive.speed.value", 3)
    with pytest.raises(InputError, match="empty part"):
        set_path(d, "drive..speed", 3)
    with pytest.raises(InputError, match="is not in the base project"):
        remove_path(d, "drive.links")
    with pytest.raises(InputError, match="has no 'track'"):
        remove_path(d, "track.rims")


def test_canonical_hash_is_sha256_of_sorted_json():
    # independent: hashlib on json.dumps with sorted keys and no spaces
    obj = {"inputs": {"b": "2 kg", "a": 1.5}, "base": {"x": [1, 2]}}
    text = '{"base":{"x":[1,2]},"inputs":{"a":1.5,"b":"2 kg"}}'
    assert canonical_hash(obj) == hashlib.sha256(text.encode()).hexdigest()


def test_lookup():
    r = {"vibration": {"tensioner": {"frequencies_rad_s": [44.6, 59.4], "check": {"passed": False}}},
         "entry": {"drive: free": {"v_max": 1.0}, "a.b": {"c": 2}},
         "checks": [{"name": "static safety F_B / F_max", "passed": True}], "passed": True}
    assert lookup(r, "vibration.tensioner.frequencies_rad_s.1") == 59.4
    assert lookup(r, "vibration.tensioner.frequencies_rad_s.-1") == 59.4
    assert lookup(r, "vibration.tensioner.check.passed") is False
    assert lookup(r, "checks.static safety F_B / F_max.passed") is True
    assert lookup(r, "entry.a.b.c") == 2  # a key that holds a dot
    assert lookup(r, "vibration.tensioner.frequencies_rad_s.5") is None
    assert lookup(r, "checks.no such check.passed") is None
    assert lookup(r, "passed.more") is None
    assert lookup(r, "wear.hours_to_limit") is None


# --------------------------------------------------------------------------- the study file


def _study(tmp_path: Path, body: str, base: str = "roller_industrial.toml") -> Path:
    f = tmp_path / "s.toml"
    f.write_text(f'[study]\nbase = "{EXAMPLES / base}"\n' + body, encoding="utf-8")
    return f


def test_example_studies_load():
    skew = load_study(EXAMPLES / "skew_study.toml")
    assert skew.plan == "monte_carlo" and len(skew.rows()) == 400
    skews = np.array([r[0] for r in skew.rows()])
    # Garshniev & Maksymovych's measured range 0°42'...3°26' = 42...206 arcmin
    assert skews.min() >= 42 and skews.max() <= 206
    assert "skew_height_difference" not in skew.base["contact"]
    tens = load_study(EXAMPLES / "tensioner_study.toml")
    assert len(tens.rows()) == 16 * 16 * 4
    assert tens.axes == ("tensioner.mass", "tensioner.stiffness")
    assert tens.parts == ("vibration",)


def test_variant_keys_depend_on_inputs_base_and_outputs(tmp_path):
    body = ('outputs = ["loads.maximum"]\n[plan]\nkind = "grid"\n'
            '[[vary]]\npath = "drive.speed"\nunit = "rpm"\nvalues = [900, 960]\n')
    s = load_study(_study(tmp_path, body))
    k = [s.key(s.variant_inputs(r)) for r in s.rows()]
    assert len(set(k)) == 2 and all(re.fullmatch(r"[0-9a-f]{64}", x) for x in k)
    assert s.variant_inputs(s.rows()[0]) == {"drive.speed": "900 rpm"}
    s2 = load_study(_study(tmp_path, body.replace('"loads.maximum"', '"loads.maximum", "passed"')))
    assert s2.key(s2.variant_inputs(s2.rows()[0])) != k[0]
    s3 = load_study(_study(tmp_path, body.replace("[plan]\n", '[set]\n"load.power" = "20 kW"\n[plan]\n')))
    assert s3.base["load"]["power"] == "20 kW"
    assert s3.key(s3.variant_inputs(s3.rows()[0])) != k[0]


@pytest.mark.parametrize("body, message", [
    ('outputs = ["load.maximum"]\n[[vary]]\npath = "drive.speed"\nvalues = [1]\n',
     r"s.toml:3: study.outputs: .*must start with one of inputs, layout, loads"),
    ('outputs = ["passed", "passed"]\n[[vary]]\npath = "drive.speed"\nvalues = [1]\n',
     "outputs must not repeat a path"),
    ('outputs = ["passed"]\ncolour = 1\n[[vary]]\npath = "drive.speed"\nvalues = [1]\n',
     "s.toml:4: study.colour: unknown field"),
    ('outputs = ["passed"]\n', "vary: required field is missing"),
    ('outputs = ["passed"]\n[[vary]]\npath = "drive.speed"\nvalues = ["1 rad/s"]\n'
     '[[vary]]\npath = "drive.speed"\nvalues = ["2 rad/s"]\n', r"vary\[1\].path: 'drive.speed' is varied twice"),
    ('outputs = ["passed"]\n[[vary]]\npath = "wheels.4.teeth"\nvalues = [1]\n',
     r"vary\[0\]: path 'wheels.4.teeth': wheels.4 is not an entry .*valid indices 0...1"),
    ('outputs = ["passed"]\n[[vary]]\npath = "drive.speed"\nunit = "wibbles"\nvalues = [1]\n',
     r"vary\[0\].unit: unknown unit"),
    ('outputs = ["passed"]\n[[vary]]\npath = "drive.speed"\nunit = "rpm"\nlow = 9\nhigh = 1\n',
     r"vary\[0\]: variable 'drive.speed': need finite low <= high"),
    ('outputs = ["passed"]\nremove = ["drive.links"]\n[[vary]]\npath = "drive.speed"\nvalues = [1]\n',
     "study.remove: .*'drive.links' is not in the base project"),
    ('outputs = ["passed"]\n[[vary]]\npath = "drive.speed"\nunit = "rpm"\nvalues = [900]\n'
     '[summary]\nfeasible = "loads.maximum"\n', "summary.feasible: 'loads.maximum' must be one of the outputs"),
    ('outputs = ["passed"]\n[[vary]]\npath = "drive.speed"\nunit = "rpm"\nvalues = [900]\n'
     '[summary]\naxes = ["drive.speed", "load.power"]\n', "summary.axes: give two different varied paths"),
    ('outputs = ["simulation.max_link_tension"]\n[[vary]]\npath = "drive.speed"\nunit = "rpm"\nvalues = [900]\n'
     '[simulation]\nduration = "1 min"\n', r"simulation.duration must lie in \(0, 10\] s, got 60 s"),
    ('outputs = ["loads.maximum"]\n[[vary]]\npath = "loads.maximum"\nvalues = [1]\n',
     "also varied"),
    ('outputs = ["passed"]\n[plan]\nkind = "latin_hypercube"\n[[vary]]\npath = "drive.speed"\nunit = "rpm"\n'
     'low = 1\nhigh = 2\n', "needs the number of samples"),
    ('outputs = ["passed"]\n[plan]\nkind = "sobol"\n[[vary]]\npath = "drive.speed"\nvalues = [1]\n',
     "plan.kind: Input should be 'grid', 'latin_hypercube' or 'monte_carlo'"),
    ('outputs = ["passed"]\n[[vary]]\npath = "drive.speed"\nunit = "kg"\nvalues = [1]\n',
     "the first variant .* is not a valid project: .*drive.speed"),
    ('outputs = ["passed"\n', "TOML syntax error"),
])
def test_study_file_errors(tmp_path, body, message):
    with pytest.raises(InputError, match=message):
        load_study(_study(tmp_path, body))


def test_set_table_dotted_keys_quoted_or_not(tmp_path):
    # TOML reads `contact.wear_factor = 0.6` as a nested table; both spellings set one value
    body = ('outputs = ["passed"]\n[[vary]]\npath = "drive.speed"\nunit = "rpm"\nvalues = [900]\n'
            '[set]\ncontact.wear_factor = 0.6\n"load.service_factor" = 1.3\n')
    s = load_study(_study(tmp_path, body))
    assert s.base["contact"]["wear_factor"] == 0.6 and "skew_base" in s.base["contact"]
    assert s.base["load"]["service_factor"] == 1.3


def test_study_file_missing_files(tmp_path):
    with pytest.raises(InputError, match="study file .*does not exist"):
        load_study(tmp_path / "none.toml")
    with pytest.raises(InputError, match="study.base: project file .*does not exist"):
        parse_study('[study]\nbase = "nowhere.toml"\noutputs = ["passed"]\n[[vary]]\npath = "a"\nvalues = [1]\n',
                    filename="s.toml", folder=tmp_path)


# --------------------------------------------------------------------------- one variant


def test_variant_equals_the_hand_edited_project(tmp_path):
    # independent path: the value written into the project TOML text by hand, loaded by
    # load_project and analysed by analyze_drive, must give the study row's numbers
    from chaindrive.analysis import analyze_drive
    from chaindrive.drive.project import load_project

    s = load_study(EXAMPLES / "skew_study.toml")
    inputs = {"contact.skew": "120 arcmin", "contact.wear_factor": 0.65}
    row = evaluate_variant(s.base, inputs, s.outputs, parts=s.parts)
    assert row["error"] is None
    text = (EXAMPLES / "roller_industrial.toml").read_text(encoding="utf-8")
    text = re.sub(r'skew_height_difference = .*\n', "", text)
    text = re.sub(r'skew_base = .*\n', 'skew = "2 deg"\n', text)
    f = tmp_path / "edited.toml"
    f.write_text(text, encoding="utf-8")
    ref = analyze_drive(load_project(f)).to_dict()
    assert row["contact.stress"] == pytest.approx(ref["contact"]["stress"], rel=1e-12)
    assert row["loads.maximum"] == pytest.approx(ref["loads"]["maximum"], rel=1e-12)
    assert row["passed"] is ref["passed"]
    # Garshniev & Maksymovych eq. (2): Q_n = Q (1 + gamma phi_p^2), phi_p = K_phi phi_max in arcmin,
    # gamma = 0.0012 for p = 25.4 mm; sigma ~ sqrt(Q_n) (eq. (1)): the stress ratio
    assert row["contact.stress_ratio"] == pytest.approx(math.sqrt(1 + 0.0012 * (0.65 * 120) ** 2), rel=1e-9)
    # regression (16B, 19/57 teeth, 15 kW at 960 rpm, skew 2°, K_phi 0.65)
    assert row["contact.stress"] == pytest.approx(2.24385e8, rel=1e-5)


def test_failing_variant_is_a_row_with_its_error():
    s = load_study(EXAMPLES / "skew_study.toml")
    row = evaluate_variant(s.base, {"contact.skew": "-5 arcmin", "contact.wear_factor": 0.65}, s.outputs)
    assert row["error"].startswith("InputError: variant: contact.skew")
    assert "\n" not in row["error"]
    assert all(row[o] is None for o in s.outputs)
    row = evaluate_variant(s.base, {"wheels.7.teeth": 19}, s.outputs)
    assert "valid indices 0...1" in row["error"]


# --------------------------------------------------------------------------- summary statistics


def test_column_statistics_against_numpy():
    # stresses are stored in Pa and shown in MPa (the unit ContactAnalysis' result declares)
    x = [3e6, 1e6, None, 4e6, 1.5e6, 9e6]
    s = column_statistics("contact.stress", x)
    ref = np.array([v for v in x if v is not None]) / 1e6
    assert s["n"] == 5 and s["unit"] == "MPa"
    assert float(s["mean"]) == pytest.approx(ref.mean(), rel=1e-3)
    assert float(s["std"]) == pytest.approx(ref.std(ddof=1), rel=1e-3)
    assert float(s["p95"]) == pytest.approx(np.quantile(ref, 0.95), rel=1e-3)
    assert column_statistics("passed", [True, None, False, False])["true"] == 1
    assert column_statistics("inputs.name", ["a", "b", "a"])["distinct"] == 2
    assert output_unit("wear.hours_to_limit") == "h" and output_unit("contact.stress_ratio") == ""
    assert json.loads(json.dumps(s))  # JSON-ready


def test_simulation_outputs(tmp_path):
    # the optional simulation summary: a short run of chaindrive.simulation on the variant;
    # independent check: the simulated mean tight-side tension is near the static analysis'
    # tight-side tension (effective pull + slack + centrifugal), here within 10 %
    body = ('outputs = ["simulation.tight_side_tension_mean", "loads.tight"]\n'
            '[[vary]]\npath = "drive.speed"\nunit = "rpm"\nvalues = [300]\n'
            '[simulation]\nduration = "0.1 s"\nsamples = 50\n')
    s = load_study(_study(tmp_path, body))
    assert s.simulation == {"duration": 0.1, "samples": 50}
    assert s.parts == ("simulation", "loads")
    row = evaluate_variant(s.base, s.variant_inputs(s.rows()[0]), s.outputs, parts=s.parts,
                           simulation=s.simulation)
    assert row["error"] is None
    assert row["simulation.tight_side_tension_mean"] == pytest.approx(row["loads.tight"], rel=0.1)


def test_feasible_region_grid_fractions():
    # a 2 x 2 grid, 2 speeds per cell: fractions counted by hand
    from chaindrive.plotting.study import feasible_region_plot

    x = [1, 1, 1, 1, 10, 10, 10, 10]
    y = [5, 5, 50, 50, 5, 5, 50, 50]
    ok = [True, True, True, False, False, False, True, None]
    fig = feasible_region_plot(x, y, ok, xname="tensioner.mass", yname="tensioner.stiffness",
                               xunit="kg", yunit="kN/m", over="drive.speed", log_x=True, log_y=True)
    ax = fig.axes[0]
    mesh = ax.collections[0]
    # rows: y = 5, 50; columns: x = 1, 10; the None (failed variant) is left out
    assert np.asarray(mesh.get_array()).reshape(2, 2).tolist() == [[1.0, 0.0], [0.5, 1.0]]
    assert len(ax.patches) == 2  # the two cells where all pass are outlined
    assert ax.get_xscale() == "log" and fig.axes[1].get_ylabel() == "fraction feasible over drive.speed [-]"
