"""Batched evaluation of study variants equals the per-variant analysis (to 1e-12), rows,
errors and warnings included (performance issue: studies by the million)."""

from __future__ import annotations

import dataclasses
import json
import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from chaindrive.analysis import analyze_drive
from chaindrive.analysis.batch import analyze_variants, replace_path, replace_paths
from chaindrive.drive.project import load_project
from chaindrive.errors import InputError
from chaindrive.study.batch import evaluate_batch, probe_path
from chaindrive.study.run import evaluate_variant, run_batch, run_batch_columns
from chaindrive.study.spec import parse_study

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def _same(a, b) -> bool:
    if isinstance(a, float) and isinstance(b, float):
        return math.isclose(a, b, rel_tol=1e-12, abs_tol=1e-300)
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(_same(a[k], b[k]) for k in a)
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(_same(x, y) for x, y in zip(a, b, strict=True))
    return a == b


def _compare(study, count: int) -> None:
    variants = [study.variant_inputs(r) for r in study.rows()[:count]]
    batched = evaluate_batch(study.base, variants, study.outputs, parts=study.parts)
    for v, got in zip(variants, batched, strict=True):
        ref = evaluate_variant(study.base, v, study.outputs, parts=study.parts)
        for key in [*study.outputs, "error", "warnings"]:
            assert _same(ref[key], got[key]), (v, key, ref[key], got[key])


def test_skew_monte_carlo_batched_equals_per_variant():
    text = (EXAMPLES / "skew_study.toml").read_text()
    _compare(parse_study(text, filename="skew_study.toml", folder=EXAMPLES), 60)


def test_tensioner_grid_batched_equals_per_variant():
    text = (EXAMPLES / "tensioner_study.toml").read_text().replace("count = 16", "count = 3")
    _compare(parse_study(text, filename="tensioner_study.toml", folder=EXAMPLES), 9)


STUDY = """
[study]
base = "roller_industrial.toml"
remove = ["contact.skew_height_difference", "contact.skew_base"]
outputs = ["contact.stress", "contact.relative_life_wear", "loads.maximum", "layout.links", "passed",
           "checks.static safety.value", "inputs.speed"]
[plan]
kind = "latin_hypercube"
samples = 12
seed = 5
{vary}
"""


def test_varying_geometry_and_speed_batched_equals_per_variant():
    vary = """
[[vary]]
path = "wheels.0.teeth"
low = 17
high = 25
integer = true
[[vary]]
path = "drive.speed"
unit = "rpm"
low = 300
high = 1500
[[vary]]
path = "contact.skew"
unit = "arcmin"
low = 42
high = 206
"""
    _compare(parse_study(STUDY.format(vary=vary), filename="s.toml", folder=EXAMPLES), 12)


def test_invalid_variants_give_the_same_errors():
    # wear factors above 1 are refused by the formula: the vectorised call fails and the
    # variants are computed one by one, each with its own message
    vary = """
[[vary]]
path = "contact.wear_factor"
low = 0.5
high = 1.5
[[vary]]
path = "contact.skew"
unit = "arcmin"
low = 42
high = 206
"""
    study = parse_study(STUDY.format(vary=vary), filename="s.toml", folder=EXAMPLES)
    variants = [study.variant_inputs(r) for r in study.rows()]
    rows = evaluate_batch(study.base, variants, study.outputs, parts=study.parts)
    assert any(r["error"] for r in rows) and any(r["error"] is None for r in rows)
    _compare(study, 12)


def test_the_skew_path_is_probed_as_linear():
    text = (EXAMPLES / "skew_study.toml").read_text()
    study = parse_study(text, filename="skew_study.toml", folder=EXAMPLES)
    v = study.variant_inputs(study.rows()[0])
    leaf, factor = probe_path(study.base, v, "contact.skew")
    assert leaf == ("contact", "skew") and factor == pytest.approx(math.pi / 180 / 60, rel=1e-12)
    assert probe_path(study.base, {**v, "wheels.0.teeth": 21}, "wheels.0.teeth") is None  # a count
    # one number of a wheel's position (a tuple): that item is the leaf
    leaf, factor = probe_path(study.base, {**v, "wheels.1.position.0": "1000 mm"}, "wheels.1.position.0")
    assert leaf == ("wheels", 1, "position", 0) and factor == pytest.approx(1e-3, rel=1e-12)


def test_varying_centre_distance_batched_equals_per_variant():
    # the position is set directly in the variants' drives; each group (one per number of
    # teeth) is analysed from one project read
    vary = """
[[vary]]
path = "wheels.0.teeth"
values = [19, 21]
[[vary]]
path = "wheels.1.position.0"
unit = "mm"
low = 900
high = 1200
count = 4
[[vary]]
path = "contact.skew"
unit = "arcmin"
values = [50, 150]
"""
    text = STUDY.format(vary=vary).replace('kind = "latin_hypercube"\nsamples = 12\nseed = 5', 'kind = "grid"')
    _compare(parse_study(text, filename="s.toml", folder=EXAMPLES), 16)


def test_run_batch_carries_batches():
    text = (EXAMPLES / "skew_study.toml").read_text()
    study = parse_study(text, filename="skew_study.toml", folder=EXAMPLES)
    batch = [(i, f"k{i}", study.variant_inputs(r)) for i, r in enumerate(study.rows()[:5])]
    rows = run_batch(batch, base=study.base, outputs=study.outputs, parts=study.parts)
    assert [r["variant"] for r in rows] == list(range(5)) and [r["key"] for r in rows] == [f"k{i}" for i in range(5)]
    columns = run_batch_columns(batch, base=study.base, outputs=study.outputs, parts=study.parts)
    for name in [*study.outputs, "error", "warnings", "key", "variant", "worker"]:
        assert columns[name] == [r[name] for r in rows], name


@pytest.mark.slow
@settings(max_examples=6, deadline=None)
@given(skews=st.lists(st.floats(0.0, 0.05), min_size=2, max_size=6), power=st.floats(2e3, 30e3),
       mass=st.floats(1.0, 500.0))
def test_analyze_variants_equals_analyze_drive(skews, power, mass):
    roller = load_project(EXAMPLES / "roller_industrial.toml")
    roller = dataclasses.replace(roller, contact=dataclasses.replace(roller.contact, skew=0.01,
                                                                     skew_height_difference=None, skew_base=None))
    changes = [{("contact", "skew"): s, ("load", "power"): power} for s in skews]
    for a, change in zip(analyze_variants(roller, changes), changes, strict=True):
        ref = analyze_drive(replace_paths(roller, change))
        assert _same(json.loads(json.dumps(ref.to_dict())), json.loads(json.dumps(a.to_dict())))
        assert ref.warnings == a.warnings
    mining = load_project(EXAMPLES / "mining_conveyor.toml")
    out = analyze_variants(mining, [{("tensioner", "mass"): mass}, {("tensioner", "mass"): 2 * mass}],
                           include=["vibration"])
    # the layout reads the tensioner (its wheel), so the layout, the loads and the vibration
    # are per variant; the entry kinematics are not
    assert "entry" in out.shared and "vibration" in out.per_variant
    ref = analyze_drive(replace_path(mining, ("tensioner", "mass"), 2 * mass), include=["vibration"])
    assert _same(json.loads(json.dumps(ref.to_dict())), json.loads(json.dumps(out[1].to_dict())))


def test_batch_errors():
    drive = load_project(EXAMPLES / "roller_industrial.toml")
    with pytest.raises(InputError, match="Drive has no field 'nope'"):
        replace_path(drive, ("nope",), 1.0)
    with pytest.raises(InputError, match="no item 5 in tuple"):
        replace_paths(drive, {("wheels", 5, "teeth"): 21})
    with pytest.raises(InputError, match="errors must be 'raise' or 'return'"):
        analyze_variants(drive, [{}], errors="ignore")
    with pytest.raises(InputError, match="drive must be a chaindrive.drive.Drive"):
        analyze_variants("drive", [{}])
    out = analyze_variants(drive, [{("load", "power"): -1.0}, {}], errors="return")
    assert isinstance(out[0], InputError) and out[1].passed
    with pytest.raises(InputError):
        analyze_variants(drive, [{("load", "power"): -1.0}])


def test_variant_key_is_the_canonical_hash():
    from chaindrive.study.spec import canonical_hash

    text = (EXAMPLES / "skew_study.toml").read_text()
    study = parse_study(text, filename="skew_study.toml", folder=EXAMPLES)
    for inputs in [study.variant_inputs(r) for r in study.rows()[:3]] + [{"wheels.0.teeth": 19, "x": "ü \"q\""}]:
        assert study.key(inputs) == canonical_hash({"base": study.base_hash, "inputs": inputs,
                                                    "outputs": list(study.outputs), "simulation": None})


def test_values_the_project_loader_refuses_give_its_message():
    # negative skews are refused by the project file's reader: their rows carry its message
    # (the batch sets numbers directly only where the reader takes the smallest and the
    # largest of them; else the variants' projects are read)
    vary = """
[[vary]]
path = "contact.skew"
unit = "arcmin"
low = -40
high = 100
[[vary]]
path = "contact.wear_factor"
low = 0.6
high = 0.7
"""
    study = parse_study(STUDY.format(vary=vary), filename="s.toml", folder=EXAMPLES)
    variants = [study.variant_inputs(r) for r in study.rows()]
    rows = evaluate_batch(study.base, variants, study.outputs, parts=study.parts)
    assert any(r["error"] for r in rows) and any(r["error"] is None for r in rows)
    _compare(study, 12)
