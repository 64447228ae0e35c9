"""The reduced compliant jump-over model (chaindrive.life.jump_table) and the analysis' jump-over check."""

from __future__ import annotations

import json
import math
import warnings

import numpy as np
import pytest

from chaindrive.errors import InputError, ValidityRangeWarning
from chaindrive.life import holding_limit, jump_onset, tension_ratio, wrap_jump_range
from chaindrive.life.jump_table import _DATA

P16B, D16B = 0.0254, 0.01588  # 16B pitch and roller diameter (ISO 606 table 1)
EA16B = 1.0e8  # the simulation's 16B link stiffness (chaindrive.chains.stiffness)

#: The simulation's quasi-static onset load ratio rho = M/(R_e T2,nom) of the ten jump-over cases (benchmarks/life.py
#: quasi_static_jump_ratio, branch jump6, commits 34abe64 and eda6930: 16B, the driven wheel's slide pulled by the constant F, no
#: spring; the slowest onset of the speeds halved from 0.5 rad/s (up to 17 teeth) or 0.125 rad/s until it settled
#: within the bisections' ~0.9 %; the onsets at every speed in benchmarks/life.py SIMULATED): the seven of docs/life.md
#: at F = 3 kN and the three chosen before they were run (15 teeth at 12 %, 19 at 3 % under F = 1.5 kN, 31 at 7 % under
#: 6 kN): (teeth, elongation, rho, F [N]).
SIMULATED = [(9, 0.20, 14.7, 3000.0), (11, 0.20, 20.6, 3000.0), (11, 0.10, 23.0, 3000.0), (13, 0.15, 29.2, 3000.0),
             (17, 0.10, 50.9, 3000.0), (21, 0.08, 77.1, 3000.0), (25, 0.06, 110.5, 3000.0),
             (15, 0.12, 39.2, 3000.0), (19, 0.03, 69.7, 1500.0), (31, 0.07, 159.1, 6000.0)]


def _stored():
    return json.loads(_DATA.read_text())


# --------------------------------------------------------------------------- the table itself
def test_table_has_its_provenance_and_range():
    raw = _stored()
    assert "wrap_jump_ratio" in raw["provenance"] and "commit" in raw["provenance"]
    assert "d_a max" in raw["provenance"]  # the tooth form of holding_limit: the table reaches it
    # 40 wheel positions per pitch with the torque held (10 missed the slack span's dip: docs/life.md)
    assert raw["torque"]["phases"] == 40 and raw["tensions"]["phases"] == 10
    for loading in ("torque", "tensions"):
        c = np.asarray(raw[loading]["correction"])
        assert c.shape == (len(raw["teeth"]), len(raw["fraction"])) and np.all(c > 0)
    r = wrap_jump_range("torque")
    assert r["teeth"] == (9.0, 57.0) and r["fraction"] == (0.0, 0.999)
    assert r["load_stiffness"][0] < 3e-5 < r["load_stiffness"][1]


@pytest.mark.parametrize("loading", ["torque", "tensions"])
def test_jump_onset_reproduces_the_table_at_its_points(loading):
    # at a stored point (lambda0) the reduced model is c times the rigid beta^-n recomputed
    raw = _stored()
    lam0 = raw[loading]["load_stiffness"]
    for i, z in enumerate(raw["teeth"]):
        for j, s in enumerate(raw["fraction"]):
            e = s * holding_limit(P16B, z, D16B)
            rigid = float(tension_ratio(P16B, z, D16B, e)) ** -(z // 2)
            c = raw[loading]["correction"][i][j]
            if c > 100.0:  # 9 teeth, a new chain, the back tension held: held every ratio tried (a lower bound, 1e7)
                continue
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", ValidityRangeWarning)
                if loading == "torque":
                    got = jump_onset(P16B, z, D16B, e, load=lam0 * EA16B)
                else:  # the back tension that puts F = T2 (1 + rho) at lambda0
                    got = jump_onset(P16B, z, D16B, e, back_tension=lam0 * EA16B / (1 + c * rigid))
            # (tensions: F = T2 (1 + rho) found by two substitutions, so lambda0 to a per cent or two)
            assert got.correction == pytest.approx(c, rel=2e-2 if loading == "tensions" else 1e-9)
            assert got.load_ratio == pytest.approx(c * rigid, rel=2e-2 if loading == "tensions" else 1e-9)


def test_jump_onset_within_10_percent_of_the_quasi_static_simulation():
    # the reduced model against the simulated quasi-static onsets (SIMULATED: provenance above), torque loading, each
    # case at its own F on 16B, every case inside the table. The aim of the issue is 10 %: all ten meet it (-1.6 ...
    # +5.7 %; the compliant model itself +1.5 ... +4.3 %). Before: the table of 10 wheel positions per pitch against a
    # reference that was not quasi-static (a slide spring of 1000 N/m, one slow speed): 9 of 10 (19 teeth at 3 %: -20.8 %)
    errors = {}
    for teeth, elongation, simulated, load in SIMULATED:
        with warnings.catch_warnings():
            warnings.simplefilter("error", ValidityRangeWarning)
            got = jump_onset(P16B, teeth, D16B, elongation, load=load)
        assert not got.outside
        errors[(teeth, elongation)] = got.load_ratio / simulated - 1
    assert all(abs(e) <= 0.10 for e in errors.values())
    assert errors[(11, 0.20)] == pytest.approx(0.036, abs=0.01)
    assert errors[(19, 0.03)] == pytest.approx(-0.016, abs=0.01)


def test_the_table_reaches_the_holding_limit():
    # the tabulated wheel has ISO 606's largest tip diameter, the tooth form of holding_limit, so every elongation up to
    # 0.999 of the holding limit is inside the table for 9-57 teeth, where the simulation's wheel (the middle of ISO
    # 606's tip range) lets the rollers over at 0.74-0.83 of it; both tips give the same onset with the torque held
    # where both hold (11 teeth at 20 %: 22.1, 17 at 10 %: 56.4; wrap_jump_ratio to 2 % at 10 wheel positions, docs/life.md)
    for teeth in (9, 12, 19, 26, 44, 57):
        limit = holding_limit(P16B, teeth, D16B)
        e = np.array([0.75, 0.9, 0.999]) * limit
        with warnings.catch_warnings():
            warnings.simplefilter("error", ValidityRangeWarning)
            got = jump_onset(P16B, teeth, D16B, e, load=3000.0)
        assert not got.outside and np.all(np.isfinite(got.load_ratio)) and np.all(got.load_ratio > 1.0)


@pytest.mark.slow
@pytest.mark.parametrize("loading, teeth, fraction, lam, measured", [
    # with the torque held: the table and the fresh calls at 40 wheel positions (at 10: -1.1, -1.1, -3.2, -3.2, -9.3, -3.2 %)
    ("torque", 11, 0.38, 3e-5, -0.021),   # the former table's worst torque point (-10.3 %)
    ("torque", 15, 0.65, 3e-5, -0.032),
    ("torque", 35, 0.85, 3e-5, -0.083),   # past the former table's 0.7
    ("torque", 13, 0.95, 3e-5, -0.011),   # near the holding limit
    ("torque", 47, 0.5, 3e-5, -0.103),    # between 40 and 57 teeth, the coarsest teeth interval: low, the safe side
    ("torque", 33, 0.52, 8e-5, -0.063),   # off every axis (the former 31 teeth: -8.3 %)
    ("tensions", 15, 0.4, 3e-4, 0.022),    # the back tension held (former table: -1.1 %)
    ("tensions", 33, 0.22, 1.5e-4, -0.103),  # off every axis (former: -12.2 %)
    ("tensions", 19, 0.85, 3e-4, -0.011),  # past the former table's 0.7
])
def test_jump_onset_against_fresh_wrap_jump_ratio(loading, teeth, fraction, lam, measured):
    # the table interpolated off its grid against a fresh call of the compliant model it tabulates (the same tooth
    # form, d_a max; the bisection to 1.5 % from well below the table's value): the points chosen before they were
    # run, where the former table erred most and in the range it did not cover. Measured (docs/life.md) in the
    # last column; with the torque held within 10 % but one (-10.3 %), all on the low, safe side
    from chaindrive.geometry.sprocket import tip_diameter_limits
    from chaindrive.life import wrap_jump_ratio

    e = fraction * holding_limit(P16B, teeth, D16B)
    if loading == "torque":
        red = jump_onset(P16B, teeth, D16B, e, load=lam * EA16B)
    else:
        red = jump_onset(P16B, teeth, D16B, e, back_tension=lam * EA16B / (1 + 1.6 * float(
            tension_ratio(P16B, teeth, D16B, e)) ** -(teeth // 2)))
    load = float(red.load_stiffness) * EA16B
    fresh = wrap_jump_ratio(P16B, teeth, D16B, e, load, low=max(1.01, red.load_ratio / 8), high=red.load_ratio * 2,
                            rtol=0.015, loading=loading, tip_diameter=float(tip_diameter_limits(P16B, teeth, D16B)[1]),
                            phases=_stored()[loading]["phases"])  # the wheel positions the table was made with
    error = red.load_ratio / fresh.load_ratio - 1
    assert error == pytest.approx(measured, abs=0.02)
    if loading == "torque":  # within 10 %, but 47 teeth (40-57: the coarsest interval) 10.3 % low, the safe side
        assert -0.11 <= error <= 0.10


def test_jump_onset_vectorised_and_regression():
    e = np.array([0.0, 0.01, 0.02, 0.03])
    r = jump_onset(P16B, 19, D16B, e, load=3000.0)
    assert r.load_ratio.shape == (4,)
    for k, ek in enumerate(e):
        assert jump_onset(P16B, 19, D16B, ek, load=3000.0).load_ratio == pytest.approx(r.load_ratio[k], rel=1e-12)
    # the tight-side tooth load at the onset: F rho/(1 + rho) with the torque held, T2 rho with T2 held
    assert r.tight_tension == pytest.approx(3000.0 * r.load_ratio / (1 + r.load_ratio))
    t = jump_onset(P16B, 19, D16B, 0.02, back_tension=500.0, warn=False)  # F/EA at the onset: past the table
    assert t.tight_tension == pytest.approx(500.0 * t.load_ratio)
    # with the sum of the span tensions held the wrap holds an order of magnitude less than beta^-n
    assert np.all(r.correction < 0.3)


def test_jump_onset_warns_outside_the_table():
    with pytest.warns(ValidityRangeWarning, match=r"teeth = 80 outside \[9, 57\]"):
        r = jump_onset(P16B, 80, D16B, 0.01, load=3000.0)
    assert r.outside and r.load_ratio > 0
    with pytest.warns(ValidityRangeWarning, match=r"F/EA = .* outside"):
        jump_onset(P16B, 19, D16B, 0.01, load=1e5)
    with pytest.warns(ValidityRangeWarning, match=r"e/e_hold = .* outside \[0, 0.999\]"):
        jump_onset(P16B, 19, D16B, (1 - 1e-6) * holding_limit(P16B, 19, D16B), load=3000.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert jump_onset(P16B, 80, D16B, 0.01, load=3000.0, warn=False).outside


@pytest.mark.parametrize("kwargs, match", [
    ({"elongation": 0.02}, "give exactly one of load"),
    ({"elongation": 0.02, "load": 3000.0, "back_tension": 100.0}, "give exactly one of load"),
    ({"elongation": 0.02, "load": -1.0}, "load"),
    ({"elongation": 0.02, "back_tension": 0.0}, "back_tension"),
    ({"elongation": -0.01, "load": 3000.0}, "elongation"),
    ({"elongation": 0.5, "load": 3000.0}, "can hold"),  # a tooth form that cannot hold the worn chain
    ({"elongation": 0.02, "load": 3000.0, "teeth": 17.5}, "whole number"),
    ({"elongation": 0.02, "load": 3000.0, "axial_stiffness": 0.0}, "axial_stiffness"),
    ({"elongation": 0.02, "load": 3000.0, "seated": 2.5}, "seated must be a whole number"),
])
def test_jump_onset_bad_input(kwargs, match):
    args = {"pitch": P16B, "teeth": 19, "roller_diameter": D16B, **kwargs}
    with pytest.raises(InputError, match=match):
        jump_onset(**args)
    with pytest.raises(InputError, match="loading must be one of"):
        wrap_jump_range("sag")


# --------------------------------------------------------------------------- the analysis' check
def _analyse(drive):
    from chaindrive.analysis import analyze_drive

    return analyze_drive(drive, include=["life", "layout", "loads"])


def test_analysis_margin_is_the_compliant_wraps(roller_drive):
    # held back tension (the slack span's sag): margin = rho_jump(tensions) T2 / T1 from the table
    a = _analyse(roller_drive())
    r = a.life
    assert r.jump_over_loading == ("tensions", "tensions")
    tens = np.asarray(a.loads.span_tensions)
    hi, lo = tens.max(), tens.min()
    seated = int(a.layout.teeth_in_mesh[0])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityRangeWarning)
        ref = jump_onset(P16B, 19, D16B, r.elongation_limit, back_tension=lo, seated=seated)
    assert r.jump_over_margin[0] == pytest.approx(ref.load_ratio * lo / hi, rel=1e-9)
    assert r.jump_over_tension[0] == pytest.approx(ref.tight_tension, rel=1e-9)
    c = next(c for c in a.checks if c.name == "jump-over margin on 'motor' at the elongation limit")
    assert c.value == pytest.approx(r.jump_over_margin[0]) and c.limit == 1.0 and "Marshek" in c.source
    assert "back tension held" in c.note


def test_analysis_wheel_on_the_tensioners_slide_holds_far_less(roller_drive):
    # the fan on a slide pulled by the tensioner (T1 + T2 held): the torque loading, whose onset
    # the simulation checks; its margin an order of magnitude below the rigid beta^-n's
    from chaindrive.drive import Tensioner

    slide = Tensioner("fan", mass=20.0, stiffness=1e4, kind="weight", direction=(1.0, 0.0), force=2000.0)
    a = _analyse(roller_drive(tensioner=slide))
    r = a.life
    assert r.jump_over_loading == ("tensions", "torque")
    tens = np.asarray(a.loads.span_tensions)
    hi, lo = tens.max(), tens.min()
    e = r.elongation_limit
    rigid = float(tension_ratio(P16B, 57, D16B, e)) ** -int(a.layout.teeth_in_mesh[1])
    assert r.jump_over_margin[1] < 0.3 * rigid * lo / hi
    got = jump_onset(P16B, 57, D16B, e, load=hi + lo, seated=int(a.layout.teeth_in_mesh[1]))
    assert r.jump_over_margin[1] == pytest.approx(got.load_ratio * lo / hi, rel=1e-9)
    assert r.jump_over_tension[1] == pytest.approx((hi + lo) * got.load_ratio / (1 + got.load_ratio), rel=1e-9)
    c = next(c for c in a.checks if c.name == "jump-over margin on 'fan' at the elongation limit")
    assert "slide" in c.note
    # results.json carries the margin and the loading per wheel
    d = a.to_dict()["life"]
    assert d["jump_over_loading"] == ["tensions", "torque"] and len(d["jump_over_margin"]) == 2


def test_analysis_jump_elongation_where_the_margin_reaches_one(roller_drive):
    # a slack span barely loaded on a slide: the margin reaches 1 before the holding limit, at the
    # elongation the analysis names (to the grid's interpolation, 1 %)
    from chaindrive.analysis.life import _jump_elongation, _jump_points, _onset

    a = _analyse(roller_drive())
    tens = np.asarray(a.loads.span_tensions)
    hi = float(tens.max())
    drive = a.drive if hasattr(a, "drive") else roller_drive()
    seated = int(a.layout.teeth_in_mesh[0])
    limit = holding_limit(P16B, 19, D16B)
    for lo in (hi / 300.0, hi / 1000.0):
        notes: list[str] = []
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ValidityRangeWarning)
            on_grid = _onset(drive, 0, 19, seated, hi, lo, _jump_points(limit)).load_ratio * lo / hi
            e = _jump_elongation(drive, 0, on_grid, limit, notes)
            if 0 < e < limit:
                m = jump_onset(P16B, 19, D16B, e, back_tension=lo, seated=seated).load_ratio * lo / hi
                assert m == pytest.approx(1.0, rel=0.05)
    assert math.isfinite(e)


def test_worn_state_margin_is_the_compliant_wraps(roller_drive):
    from chaindrive.analysis.life import worn_state

    a = _analyse(roller_drive())
    tens = np.asarray(a.loads.span_tensions)
    hi, lo = tens.max(), tens.min()
    s = worn_state(roller_drive(), a.layout, a.loads, a.life, elongation=0.02)
    got = jump_onset(P16B, 19, D16B, 0.02, back_tension=lo, seated=int(a.layout.teeth_in_mesh[0]), warn=False)
    assert s.jump_over_margin[0] == pytest.approx(got.load_ratio * lo / hi, rel=1e-9)


def test_studio_shows_the_compliant_margin():
    # the studio lists the life part's checks as the analysis gives them: the jump-over margin there
    # is the compliant wrap's (the same number as results.json's life.jump_over_margin)
    from chaindrive.web import studio as S

    p = S.studio_payload(S.normalise_state({}))
    shown = [c for c in p["checks"] if c["name"].startswith("jump-over margin on")]
    assert shown and all(c["limit"] == 1.0 and "Marshek" in c["source"] for c in shown)
