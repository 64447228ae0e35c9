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

#: The slowly driven simulation's onset load ratio rho = M/(R_e T2,nom) of the seven cases of
#: docs/life.md, "Jump-over" (benchmarks/life.py at commit c65a478: 16B, F = 3 kN, the driven
#: wheel on a slide, 0.5 rad/s up to 17 teeth, 0.125 rad/s above; 8 bisection steps, ~2 %).
SIMULATED = [(9, 0.20, 14.9), (11, 0.20, 20.5), (11, 0.10, 24.1), (13, 0.15, 30.3), (17, 0.10, 54.5),
             (21, 0.08, 80.3), (25, 0.06, 121.7)]


def _stored():
    return json.loads(_DATA.read_text())


# --------------------------------------------------------------------------- the table itself
def test_table_has_its_provenance_and_range():
    raw = _stored()
    assert "wrap_jump_ratio" in raw["provenance"] and "commit" in raw["provenance"]
    for loading in ("torque", "tensions"):
        c = np.asarray(raw[loading]["correction"])
        assert c.shape == (len(raw["teeth"]), len(raw["fraction"])) and np.all(c > 0)
    r = wrap_jump_range("torque")
    assert r["teeth"] == (9.0, 57.0) and r["fraction"] == (0.0, 0.7)
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
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", ValidityRangeWarning)
                if loading == "torque":
                    got = jump_onset(P16B, z, D16B, e, load=lam0 * EA16B)
                else:  # the back tension that puts F = T2 (1 + rho) at lambda0
                    got = jump_onset(P16B, z, D16B, e, back_tension=lam0 * EA16B / (1 + c * rigid))
            # (tensions: F = T2 (1 + rho) found by two substitutions, so lambda0 to a fraction of a per cent)
            assert got.correction == pytest.approx(c, rel=1e-2 if loading == "tensions" else 1e-9)
            assert got.load_ratio == pytest.approx(c * rigid, rel=1e-2 if loading == "tensions" else 1e-9)


def test_jump_onset_within_10_percent_of_the_slowly_driven_simulation():
    # the reduced model against the simulated onsets (SIMULATED: provenance above) at the
    # simulation's F = 3 kN on 16B (lambda = 3e-5, a table row), torque loading: the aim of the issue
    # is 10 %; the compliant model itself is within -1.1 … +8.1 %. 11 teeth at 20 % lies at 0.76 of
    # the holding limit, past the table's 0.7: the table's edge is used, with a warning, and is on the
    # safe side there (a lower onset: -15 %)
    for teeth, elongation, simulated in SIMULATED:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            got = jump_onset(P16B, teeth, D16B, elongation, load=3000.0)
        inside = got.fraction <= 0.7
        assert bool(caught) == (not inside)
        if inside:
            assert got.load_ratio == pytest.approx(simulated, rel=0.10)
        else:
            assert 0.8 * simulated < got.load_ratio < simulated


@pytest.mark.slow
@pytest.mark.parametrize("loading, teeth, fraction, lam", [
    ("torque", 11, 0.38, 3e-5),   # a simulated case (11 teeth at 10 %), off the table's teeth and fractions
    ("torque", 21, 0.22, 3e-5),
    ("torque", 31, 0.52, 8e-5),   # off every axis
    ("tensions", 15, 0.4, 3e-4),
    ("tensions", 33, 0.22, 1.5e-4),  # off every axis
])
def test_jump_onset_against_fresh_wrap_jump_ratio(loading, teeth, fraction, lam):
    # the table interpolated off its grid against a fresh call of the compliant model it tabulates:
    # within 12 % with the torque held (the loading the simulation checks), 15 % with the back tension
    # held (its onsets scatter more over the teeth): the table's own resolution (the bisection's 3 %,
    # and the onset is reproducible to a few per cent: docs/life.md) and the interpolation.
    # Measured (docs/life.md, in the order below): -10.3, +1.1, -8.3 % (torque), -1.1, -12.2 % (tensions)
    from chaindrive.life import wrap_jump_ratio

    e = fraction * holding_limit(P16B, teeth, D16B)
    if loading == "torque":
        red = jump_onset(P16B, teeth, D16B, e, load=lam * EA16B)
    else:
        red = jump_onset(P16B, teeth, D16B, e, back_tension=lam * EA16B / (1 + 1.6 * float(
            tension_ratio(P16B, teeth, D16B, e)) ** -(teeth // 2)))
    load = float(red.load_stiffness) * EA16B
    fresh = wrap_jump_ratio(P16B, teeth, D16B, e, load, low=red.load_ratio / 2, high=red.load_ratio * 2,
                            rtol=0.02, loading=loading)
    assert red.load_ratio == pytest.approx(fresh.load_ratio, rel=0.12 if loading == "torque" else 0.15)


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
    with pytest.warns(ValidityRangeWarning, match=r"e/e_hold = .* outside \[0, 0.7\]"):
        jump_onset(P16B, 19, D16B, 0.9 * holding_limit(P16B, 19, D16B), load=3000.0)
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
