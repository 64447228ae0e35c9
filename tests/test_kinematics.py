"""Public API of chaindrive.kinematics: chain_entry, summaries, Dolipiński et al.'s conclusions.

Provenance of reference values is given next to each. "Regression" marks values computed
with this code after the independent checks in test_kinematics_paper.py passed.
"""

from __future__ import annotations

import json

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from chaindrive.errors import InfeasibleError, InputError, UnknownNameError
from chaindrive.kinematics import SUMMARY_KEYS, chain_entry, dolipinski_worked_case

T18, D18 = 0.064, 0.018  # chain 18x64 (DIN 22252): t = 64 mm, d = 18 mm (Dolipiński et al.)
R18 = 0.164283  # Dolipiński et al. eq. (6), also geometry/polygon.py doctest


def _entry(**kw):
    base = dict(bar_diameter=D18, guide_end_distance=0.256)
    base.update(kw)
    return chain_entry(T18, 8, 5.0, **base)


# ----------------------------------------------------------------------------- limiting cases


@pytest.mark.parametrize("z", [3, 6, 11, 25])
def test_roller_free_entry_velocity_ratio_is_cos_pi_over_z(z):
    # classical polygonal effect: v = ωR cos β, |β| <= π/z  ->  v_min/v_max = cos(π/z)
    r = chain_entry(0.0254, z, 12.0)
    assert r.summary["v_min"] / r.summary["v_max"] == pytest.approx(np.cos(np.pi / z), rel=1e-12)
    R = 0.0254 / (2 * np.sin(np.pi / z))
    assert r.summary["v_max"] == pytest.approx(12.0 * R, rel=1e-12)
    assert r.summary["transverse_throw"] == pytest.approx(R * (1 - np.cos(np.pi / z)), rel=1e-9)


@pytest.mark.parametrize("model", ["exact", "paper", "as_printed"])
@pytest.mark.parametrize("entry", ["free", "chordal", "tangential"])
@pytest.mark.parametrize("chain", ["link", "roller"])
def test_mean_speed_equals_advance_times_z_omega_over_2pi(model, entry, chain):
    # mean speed = chain per period (2t, or p) * z ω / 2π; checked against the numerical
    # mean of v (trapezoid on a fine grid, independent of the summary's computation)
    if chain == "link":
        t, z, kw, per = T18, 8, dict(bar_diameter=D18), 2 * T18
    else:
        t, z, kw, per = 0.0254, 11, {}, 0.0254
    w = 4.0
    r = chain_entry(t, z, w, entry=entry, guide_end_distance=0.4, model=model, points=200001, **kw)
    mean_num = np.trapezoid(r.velocity, r.phi) / r.period
    assert r.summary["v_mean"] == pytest.approx(mean_num, rel=1e-8)
    expected = per * z * w / (2 * np.pi)
    if model == "as_printed" and entry == "chordal" and chain == "link":
        # the printed chordal rod is reset at π/z: it advances a little more than 2t
        assert r.summary["v_mean"] > expected * (1 + 1e-7)
        assert r.summary["advance_per_period"] - per == pytest.approx(8.525e-7, rel=1e-3)  # regression
    else:
        assert r.summary["v_mean"] == pytest.approx(expected, rel=1e-13)
        assert r.x[-1] - r.x[0] == pytest.approx(per, rel=1e-12)


@pytest.mark.parametrize("H", [0.12, 0.159085, R18, 0.2, 0.5])
def test_exact_custom_height_advance_and_velocity_bounds(H):
    # taut span: chain speed = hinge velocity projected on the span, so
    # ωR cos(δ1/2) <= v <= ωR whatever H and l (derivation in docs/kinematics.md)
    r = chain_entry(T18, 8, 5.0, bar_diameter=D18, guide_height=H, guide_end_distance=0.3)
    assert r.entry == "guided"
    assert r.summary["advance_per_period"] == pytest.approx(2 * T18, rel=1e-14)
    assert r.summary["v_min"] == pytest.approx(5 * r.radius * np.cos(r.delta1 / 2), rel=1e-9)
    assert r.summary["v_max"] == pytest.approx(5 * r.radius, rel=1e-7)


def test_named_heights():
    # chordal H = R cos(δ1/2), tangential H = R (Dolipiński et al., section 3)
    c, t = _entry(entry="chordal"), _entry(entry="tangential")
    assert c.guide_height == pytest.approx(c.radius * np.cos(c.delta1 / 2), rel=1e-14)
    assert t.guide_height == pytest.approx(R18, rel=1e-6)
    assert t.guide_height == t.radius
    # same as the custom height (phases coincide for chordal)
    g = _entry(guide_height=c.guide_height)
    np.testing.assert_allclose(g.velocity, c.velocity, rtol=1e-13)


def test_velocity_continuous_at_every_seating():
    for entry in ("chordal", "tangential"):
        r = _entry(entry=entry)
        for s in r.seating_angles:
            lo = chain_entry(T18, 8, 5.0, bar_diameter=D18, entry=entry, guide_end_distance=0.256,
                             phi=np.array([s - 1e-10, s + 1e-10]))
            assert abs(lo.velocity[1] - lo.velocity[0]) < 1e-9
            assert abs(lo.x[1] - lo.x[0]) < 1e-9
            assert abs(lo.acceleration[1] - lo.acceleration[0]) > 1.0  # a jumps at a seating


@pytest.mark.parametrize("model", ["exact", "paper"])
def test_guided_entry_tends_to_free_entry_as_l_grows(model):
    free = _entry()
    errs = []
    for l in (0.5, 5.0, 50.0):
        c = _entry(entry="chordal", guide_end_distance=l, model=model)
        # tangential phase = free phase shifted by δ1/2 (a hinge at the top at φ = 0)
        tg = _entry(entry="tangential", guide_end_distance=l, model=model)
        ff = _entry(phi=np.mod(tg.phi - tg.delta1 / 2, tg.period))
        errs.append(max(np.max(np.abs(c.velocity - free.velocity)),
                        np.max(np.abs(tg.velocity - ff.velocity)),
                        abs(c.summary["a_max"] - free.summary["a_max"]),
                        abs(c.summary["a_min"] - free.summary["a_min"]),
                        abs(tg.summary["a_max"] - free.summary["a_max"])))
    assert errs[0] > errs[1] > errs[2]
    assert errs[2] < 5e-3  # ~ 1/l


# ----------------------------------------------------------------------------- Dolipiński et al.


def test_dolipinski_worked_case_regression_exact():
    # regression (exact model), 18x64, z = 8, ω = 5 1/s, l = 0.256 m
    c = dolipinski_worked_case("exact")
    f, ch, tg = c["free"].summary, c["chordal"].summary, c["tangential"].summary
    assert f["a_max"] == pytest.approx(5**2 * R18 * np.sin(c["free"].delta1 / 2), rel=1e-5)  # eq. (10)
    assert ch["a_max"] == pytest.approx(1.220465, abs=2e-6)
    assert ch["a_min"] == pytest.approx(-0.883502, abs=2e-6)
    assert tg["a_max"] == pytest.approx(1.217543, abs=2e-6)
    assert tg["a_min"] == pytest.approx(-0.885039, abs=2e-6)
    np.testing.assert_allclose(c["tangential"].seating_angles, [0.272412, 0.651242], atol=2e-6)


def _claims(cases):
    f, ch, tg = (cases[k].summary for k in ("free", "chordal", "tangential"))
    return {
        # conclusion 1: forced entry gives a more favourable acceleration course than free
        "guided_smaller_extreme_acc_than_free": max(ch["a_abs_max"], tg["a_abs_max"]) < f["a_abs_max"],
        # tangential entry: the smallest extreme accelerations of the three
        "tangential_smallest_extreme_acc": tg["a_abs_max"] < min(ch["a_abs_max"], f["a_abs_max"]),
        "tangential_smaller_than_chordal": tg["a_abs_max"] < ch["a_abs_max"],
        # tangential: no sign change of the acceleration at the end of the period
        "tangential_no_sign_change_at_end": not tg["sign_change_at_period_end"],
        "free_sign_change_at_end": f["sign_change_at_period_end"],
        # the jump at the period end is smaller for chordal than for free entry
        "chordal_jump_smaller_than_free": abs(ch["a_jump_at_period_end"]) < abs(f["a_jump_at_period_end"]),
        # largest acceleration jump anywhere in the period: tangential below free
        "tangential_max_jump_below_free": tg["a_jump_max"] < f["a_jump_max"],
    }


@pytest.mark.parametrize("model", ["exact", "paper", "as_printed"])
def test_dolipinski_conclusions_as_they_are(model):
    # The outcome is asserted as the numbers give it (nothing tuned); docs/kinematics.md
    # states it. The consistent chordal rod ("paper") seats the hinge instead of resetting
    # the rod at π/z: its largest acceleration jump drops below the free entry's.
    got = _claims(dolipinski_worked_case(model))
    assert got == {
        "guided_smaller_extreme_acc_than_free": False,
        "tangential_smallest_extreme_acc": False,
        "tangential_smaller_than_chordal": model == "exact",
        "tangential_no_sign_change_at_end": True,
        "free_sign_change_at_end": True,
        "chordal_jump_smaller_than_free": model == "paper",
        "tangential_max_jump_below_free": False,
    }


def test_paper_chordal_rod_seats_as_the_tangential_one():
    # model="paper": one mechanism for both guides, the rod shortened by a link when the next
    # hinge seats. Chordal worked case: seating at 0.3741950302 rad (the rod collinear with the
    # chord), found independently here by brentq on the collinearity of the rod and the chord;
    # x and v continuous there; "as_printed" keeps the reset at π/z with its 3.68 mm/s jump.
    from scipy.optimize import brentq

    from chaindrive.geometry.polygon import bi_regular_polygon

    t, d, z, l, w = T18, D18, 8, 0.256, 5.0
    R, d1, d2 = (float(v) for v in bi_regular_polygon(t + d, t - d, z))
    H = R * np.cos(d1 / 2)
    L0 = l - (t + d) / 2

    def collinear(phi):
        # seated hinge S at δ1/2 - φ from the top (incoming side +x), next hinge N at
        # δ1/2 - φ + δ2 ... measured backwards: N at angle δ1/2 + δ2 - φ
        a, b = d1 / 2 - phi, d1 / 2 + d2 - phi
        sx, sy = R * np.sin(a), R * np.cos(a)
        px = sx + np.sqrt(L0**2 - (H - sy) ** 2)
        nx, ny = R * np.sin(b), R * np.cos(b)
        return (nx - sx) * (H - sy) - (ny - sy) * (px - sx)

    seat = brentq(collinear, 0.2, 0.45, xtol=1e-15)
    assert seat == pytest.approx(0.3741950302, abs=1e-10)
    r = chain_entry(t, z, w, bar_diameter=d, entry="chordal", guide_end_distance=l, model="paper")
    assert r.seating_angles[1] == pytest.approx(seat, abs=1e-12)
    at = np.array([seat - 1e-10, seat + 1e-10])
    e = chain_entry(t, z, w, bar_diameter=d, entry="chordal", guide_end_distance=l, model="paper", phi=at)
    assert abs(e.velocity[1] - e.velocity[0]) < 1e-8 and abs(e.x[1] - e.x[0]) < 1e-10
    assert r.summary["advance_per_period"] == pytest.approx(2 * t, rel=1e-13)
    p = chain_entry(t, z, w, bar_diameter=d, entry="chordal", guide_end_distance=l, model="as_printed",
                    phi=np.array([np.pi / z - 1e-12, np.pi / z]))
    assert p.velocity[1] - p.velocity[0] == pytest.approx(3.6827e-3, rel=1e-3)
    # the tangential entry is the same under both names
    a = chain_entry(t, z, w, bar_diameter=d, entry="tangential", guide_end_distance=l, model="paper")
    b = chain_entry(t, z, w, bar_diameter=d, entry="tangential", guide_end_distance=l, model="as_printed")
    np.testing.assert_array_equal(a.velocity, b.velocity)


def test_tangential_acceleration_drops_to_zero_at_period_end():
    # Dolipiński et al.: "only a drop of the acceleration to zero" at the period end; at φ = 2π/z
    # the seated hinge is at the top and the span horizontal, so a = 0 exactly.
    for model in ("exact", "paper"):
        s = _entry(entry="tangential", model=model).summary
        assert abs(s["a_end_left"]) < 1e-9 and abs(s["a_end_right"]) < 1e-9


# ----------------------------------------------------------------------------- API shape


def test_scalar_and_array_phi():
    arr = _entry(entry="tangential", phi=np.array([0.1, 0.2]))
    one = _entry(entry="tangential", phi=0.2)
    assert np.shape(one.velocity) == ()
    assert float(one.velocity) == pytest.approx(arr.velocity[1], rel=1e-15)
    assert float(one.acceleration) == pytest.approx(arr.acceleration[1], rel=1e-15)
    grid = _entry(entry="tangential", phi=np.zeros((2, 3)) + 0.3)
    assert grid.velocity.shape == (2, 3)


def test_periodicity_beyond_one_period():
    r = _entry(entry="chordal", phi=np.array([0.3, 0.3 + np.pi / 4, 0.3 + 5 * np.pi / 4]))
    np.testing.assert_allclose(r.velocity, r.velocity[0], rtol=1e-12)
    np.testing.assert_allclose(np.diff(r.x), [2 * T18, 8 * T18], rtol=1e-12)


def test_result_json_and_summary_keys():
    r = _entry(entry="tangential", points=5)
    d = json.loads(r.to_json())
    for key in ("phi", "x", "velocity", "acceleration", "summary"):
        assert key in d
    for key in SUMMARY_KEYS:
        assert key in d["summary"]
    assert d["transverse_position"] is None
    assert r.phi[-1] == pytest.approx(np.pi / 4)


# ----------------------------------------------------------------------------- errors


@pytest.mark.parametrize(
    "kwargs, exc, match",
    [
        (dict(teeth=2), InputError, r"teeth must be a whole number >= 3"),
        (dict(teeth=7.5), InputError, r"teeth must be a whole number >= 3"),
        (dict(pitch=0.0), InputError, r"pitch must be positive.*0 < pitch < inf"),
        (dict(pitch=-1.0), InputError, r"pitch must be positive"),
        (dict(angular_velocity=0.0), InputError, r"angular_velocity must be positive.*rad/s"),
        (dict(angular_velocity=-5.0), InputError, r"angular_velocity must be positive"),
        (dict(bar_diameter=0.064), InputError, r"bar_diameter must lie in \[0, pitch\)"),
        (dict(bar_diameter=-0.01), InputError, r"bar_diameter must be non-negative"),
        (dict(entry="sideways"), UnknownNameError, r"unknown entry 'sideways'; valid: 'free'"),
        (dict(model="exakt"), UnknownNameError, r"unknown model 'exakt'.*did you mean 'exact'"),
        (dict(entry="tangential", guide_end_distance=None), InputError,
         r"needs guide_end_distance \[m\] \(0 < l < inf\)"),
        (dict(entry="tangential", guide_end_distance=-0.1), InputError,
         r"guide_end_distance must be positive"),
        (dict(guide_height=-0.01), InputError, r"guide_height must be non-negative.*0 <= guide_height"),
        (dict(entry="guided"), InputError, r"needs guide_height"),
        (dict(entry="chordal", guide_height=0.15), InputError, r"either entry='chordal'.*or guide_height"),
        (dict(guide_height=0.15, model="paper"), InputError, r"model='paper' and 'as_printed' cover entry"),
        (dict(points=1), InputError, r"points must be a whole number in \[2, 1000000\]"),
        (dict(phi=[0.1, np.nan]), InputError, r"phi must not be NaN"),
        (dict(phi=[np.inf]), InputError, r"phi must be finite"),
    ],
)
def test_input_errors(kwargs, exc, match):
    base = dict(pitch=T18, teeth=8, angular_velocity=5.0, bar_diameter=D18, guide_end_distance=0.256)
    base.update(kwargs)
    with pytest.raises(exc, match=match):
        chain_entry(base.pop("pitch"), base.pop("teeth"), base.pop("angular_velocity"), **base)


def test_guide_end_too_close_exact():
    # l_min: smallest l keeping a whole link (t + d = 82 mm) in the free span (regression)
    with pytest.raises(InfeasibleError, match=r"guide_end_distance = 0.08 m is too close.*must be > 0.1158"):
        _entry(entry="tangential", guide_end_distance=0.08)
    with pytest.raises(InfeasibleError, match=r"must be > 0.123 m"):
        _entry(entry="chordal", guide_end_distance=0.05)
    _entry(entry="tangential", guide_end_distance=0.116)  # just feasible


def test_guide_end_too_close_paper():
    # the paper's last rod l - 2t must stay positive: l > 2t = 0.128 m
    with pytest.raises(InfeasibleError, match=r"must be > 0.128 m"):
        _entry(entry="tangential", guide_end_distance=0.1, model="paper")


def test_guide_height_infeasible_names_range():
    with pytest.raises(InfeasibleError, match=r"guide_height must lie in \[0.1074\d*, inf\) m"):
        _entry(guide_height=0.0, guide_end_distance=0.17)


# ----------------------------------------------------------------------------- properties


@settings(max_examples=25, deadline=None)
@given(
    z=st.integers(3, 30),
    frac=st.floats(0.0, 0.4),
    w=st.floats(0.1, 50.0),
    extra=st.floats(0.2, 3.0),
    entry=st.sampled_from(["free", "chordal", "tangential"]),
)
def test_property_exact_model(z, frac, w, extra, entry):
    t = 0.05
    r0 = chain_entry(t, z, w, bar_diameter=frac * t, points=3)
    l = r0.radius * (1 + extra) + 2 * t
    r = chain_entry(t, z, w, bar_diameter=frac * t, entry=entry, guide_end_distance=l, points=257)
    s = r.summary
    # exact advance and mean speed
    assert s["v_mean"] == pytest.approx(2 * t * z * w / (2 * np.pi), rel=1e-12)
    # taut span: ωR cos(δ1/2) <= v <= ωR
    assert s["v_min"] >= w * r.radius * np.cos(r.delta1 / 2) * (1 - 1e-9)
    assert s["v_max"] <= w * r.radius * (1 + 1e-9)
    # x monotone (the chain never runs back)
    assert np.all(np.diff(r.x) > 0)


@pytest.mark.parametrize("kwargs", [dict(), dict(bar_diameter=0.018, entry="tangential", guide_end_distance=0.256),
                                    dict(bar_diameter=0.018, entry="free")])
def test_summary_limits_equal_separate_evaluations(kwargs):
    # the summary evaluates the grid and the one-sided limits in one call of the exact model;
    # each limit equals the kinematics asked for at that angle alone, bit for bit
    pitch = 0.064 if kwargs else 0.0254
    r = chain_entry(pitch, 8, 5.0, **kwargs)
    T = r.period
    left = chain_entry(pitch, 8, 5.0, phi=[T - 1e-12 * T], **kwargs).acceleration[0]
    right = chain_entry(pitch, 8, 5.0, phi=[1e-12 * T], **kwargs).acceleration[0]
    assert r.summary["a_end_left"] == left and r.summary["a_end_right"] == right


@pytest.mark.parametrize("phi", [None, 0.1, [-1.0, 0.0, 2 * np.pi / 8, 5.0], np.linspace(0.0, 1.0, 12).reshape(3, 4)])
def test_exact_entry_at_angles_equals_each_angle_alone(phi):
    # the exact model evaluates the angles asked for with the summary's in one call; each
    # angle alone gives the same numbers, bit for bit
    r = chain_entry(0.0254, 8, 5.0, phi=phi)
    flat = np.ravel(r.phi)
    alone = [chain_entry(0.0254, 8, 5.0, phi=[x]) for x in flat]
    for name in ("x", "velocity", "acceleration", "transverse_position"):
        assert np.array_equal(np.ravel(getattr(r, name)), [getattr(a, name)[0] for a in alone])
    assert np.shape(r.velocity) == np.shape(r.phi)


def test_entry_and_crawler_share_period_motion():
    # the motion fields of a chain driven over one tooth period, declared once (#31)
    import dataclasses

    from chaindrive.kinematics.crawler import crawler_drive
    from chaindrive.kinematics.histories import PeriodMotion

    shared = {f.name for f in dataclasses.fields(PeriodMotion)}
    assert shared == {"velocity", "acceleration", "summary", "pitch", "radius", "teeth",
                      "angular_velocity", "period"}
    e = chain_entry(0.064, 8, 5.0, bar_diameter=0.018)
    c = crawler_drive(0.1, 9, 3.0)
    for r in (e, c):
        assert isinstance(r, PeriodMotion)
        assert r.period == pytest.approx(2 * np.pi / r.teeth)
        assert set(SUMMARY_KEYS) <= set(r.summary) and shared <= set(r.to_dict())


# ----------------------------------------------------------------------------- the summary's extremes


@pytest.mark.parametrize("guide", [None, (0.256, 0.164283), (0.4, 0.05), (0.3, 0.25)])
def test_motion_derivatives_against_finite_differences(guide):
    # independent: central differences of the solver's own speed, acceleration and height
    # (d/dφ = -d/dβ), step 1e-5 rad: truncation ~1e-11
    from chaindrive.kinematics.solver import _taut_motion

    beta, h = np.linspace(-0.3, 0.3, 13), 1e-5
    at = np.array(_taut_motion(0.16, beta, guide))
    diff = -(np.array(_taut_motion(0.16, beta + h, guide)) - np.array(_taut_motion(0.16, beta - h, guide))) / (2 * h)
    np.testing.assert_allclose(diff[0], at[1], atol=1e-9)  # d(dx/dφ)/dφ = d²x/dφ²
    np.testing.assert_allclose(diff[1], at[2], atol=1e-9)  # d(d²x/dφ²)/dφ = d³x/dφ³
    np.testing.assert_allclose(diff[3], at[4], atol=1e-9)  # dy/dφ
    for i, beta0 in enumerate((-0.2, 0.05, 0.25)):  # the scalar path: the same formulas in floats
        assert _taut_motion(0.16, beta0, guide) == pytest.approx(tuple(a[0] for a in
                                                                      _taut_motion(0.16, np.array([beta0]), guide)),
                                                                rel=1e-13, abs=1e-15), i


@pytest.mark.parametrize("z, bar, kw", [
    (3, D18, {}), (8, D18, {}), (25, D18, {}), (17, None, {}),
    (8, D18, dict(entry="tangential")), (25, D18, dict(entry="tangential", guide_end_distance=0.4)),
    (17, D18, dict(guide_height=0.2, guide_end_distance=0.45)), (11, None, dict(entry="chordal", guide_end_distance=0.5)),
])
def test_summary_extremes_are_the_true_ones(z, bar, kw):
    # independent: 400,000 angles a period and the one-sided values 1e-13 T from each seating;
    # the summary's extremes bound them (to rounding) and are reached by them within 1e-9
    # (a grid of 4,000 angles a period, the summary's before, fell 2.6e-8 short for z = 3)
    base = dict(bar_diameter=bar, guide_end_distance=0.256)
    base.update(kw)
    r = chain_entry(T18, z, 5.0, **base)
    T = r.period
    s = np.sort(np.mod(r.seating_angles, T))
    phi = np.concatenate([np.linspace(0.0, T, 400_001)[:-1], s + 1e-13 * T, s - 1e-13 * T, [T - 1e-13 * T]])
    dense = chain_entry(T18, z, 5.0, phi=phi[(phi >= 0) & (phi < T)], **base)
    for key, values in (("v", dense.velocity), ("a", dense.acceleration)):
        lo, hi = r.summary[f"{key}_min"], r.summary[f"{key}_max"]
        scale = max(abs(lo), abs(hi))
        assert values.max() <= hi + 1e-14 * scale and values.min() >= lo - 1e-14 * scale
        assert values.max() >= hi - 1e-9 * scale and values.min() <= lo + 1e-9 * scale
    assert r.summary["a_abs_max"] == max(abs(r.summary["a_min"]), abs(r.summary["a_max"]))
    if r.entry == "free":  # the throw of the seated hinge: R (1 - cos(δ_max/2)) (its top at β = 0)
        assert r.summary["transverse_throw"] == pytest.approx(
            r.radius * (1 - np.cos(0.5 * max(r.delta1, r.delta2))), rel=1e-12)
