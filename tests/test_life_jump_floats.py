"""The jump-over check's point-by-point arithmetic in Python floats (chaindrive.life.jump_over,
chaindrive.life.jump_table) against independent numpy computations of the same quantities."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from chaindrive.geometry.outline import circle_intersections
from chaindrive.life import holding_limit, jump_onset, tension_ratio, worn_seat
from chaindrive.life import jump_table as JT
from chaindrive.life.jump_over import _form

P16B, D16B = 0.0254, 0.01588  # 16B pitch and roller diameter (ISO 606 table 1)


def _beta_by_solve(pitch, teeth, d1, e):
    """β of one elongation the way the balance is written: the roller centre from the circles'
    intersection (geometry.outline) or the seat arc, the 2 x 2 balance solved by numpy."""
    f, r, c, cf, rho, _ = _form(pitch, teeth, d1, "min")
    rp = f.pitch_radius
    o = np.array([-rp, 0.0])
    radius = rp * (1.0 + e)
    a = (radius**2 - rp**2 - c**2) / (2.0 * rp)
    if abs(a) <= c and -a >= c * math.cos(0.5 * f.seat_angle):
        x = np.array([a, math.sqrt(c * c - a * a)])
        n = -x / c
    else:
        x = min(circle_intersections(o, radius, cf, rho), key=lambda q: q[1])
        n = (x - cf) / rho
    step = 2.0 * math.pi / teeth
    rot = np.array([[math.cos(step), -math.sin(step)], [math.sin(step), math.cos(step)]])
    u_k = o + rot @ (x - o) - x
    u_n = o + rot.T @ (x - o) - x
    u_k, u_n = u_k / np.linalg.norm(u_k), u_n / np.linalg.norm(u_n)
    beta, _ = np.linalg.solve(np.column_stack([u_n, n]), -u_k)
    return min(max(float(beta), 0.0), 1.0)


@pytest.mark.parametrize("teeth", [9, 11, 17, 19, 25, 40, 57])
def test_tension_ratio_in_floats_equals_the_solved_balance(teeth):
    limit = holding_limit(P16B, teeth, D16B)
    e = np.linspace(0.0, limit * (1 - 1e-9), 23)  # seat arc, flank, up to the tooth corner
    got = tension_ratio(P16B, teeth, D16B, e)
    want = [_beta_by_solve(P16B, teeth, D16B, float(x)) for x in e]
    np.testing.assert_allclose(got, want, rtol=1e-12, atol=1e-15)
    assert tension_ratio(P16B, teeth, D16B, float(e[5])) == got[5]  # a scalar the same as in an array
    assert tension_ratio(P16B, teeth, D16B, e.reshape(23, 1)).shape == (23, 1)


def test_worn_seat_on_the_flank_is_on_both_circles():
    f, r, c, cf, rho, _ = _form(P16B, 19, D16B, "min")
    s = worn_seat(P16B, 19, D16B, 0.05)
    assert s.on_flank
    assert np.hypot(*(s.position - cf)) == pytest.approx(rho, rel=1e-12)
    assert np.hypot(s.position[0] + f.pitch_radius, s.position[1]) == pytest.approx(s.radius, rel=1e-12)
    assert np.hypot(*s.normal) == pytest.approx(1.0, rel=1e-12)


@settings(max_examples=200, deadline=None)
@given(st.lists(st.floats(-5, 5), min_size=2, max_size=8, unique=True), st.floats(-6, 6))
def test_interp_in_floats_is_numpys(nodes, x):
    xp = sorted(nodes)
    fp = [math.sin(3 * v) + v for v in xp]
    assert JT._interp(x, xp, fp) == pytest.approx(float(np.interp(x, xp, fp)), rel=1e-14, abs=1e-14)
    for v in xp:  # at a node: the node's value
        assert JT._interp(v, xp, fp) == float(np.interp(v, xp, fp))


@pytest.mark.parametrize("loading", ["load", "back_tension"])
def test_jump_onset_point_by_point_equals_its_arrays(loading):
    """Regression of the float loop against the array formula it replaced (ln c interpolated
    with numpy.interp over the side table, c = exp(ln c), ρ = c β^-n)."""
    e = np.linspace(0.0, 0.1, 9)
    kw = {loading: 3000.0 if loading == "load" else 400.0}
    r = jump_onset(P16B, 19, D16B, e, warn=False, **kw)
    t = JT._table()
    ld = "torque" if loading == "load" else "tensions"
    log_z = math.log(19)
    main = JT._along(log_z, t["teeth"], t[ld])
    side = JT._along(log_z, t["side_teeth"], t[ld + "_side"])
    axis = t[ld + "_lambda"]
    lam = np.asarray(r.load_stiffness)
    s = np.asarray(r.fraction)
    per_row = np.array([np.interp(np.clip(np.log(lam), axis[0], axis[-1]), axis, row) for row in side])
    sf = t["side_fraction"]  # the side table's fractions: linear between the two about each s, clipped at the ends
    j = np.clip(np.searchsorted(sf, s, side="left") - 1, 0, len(sf) - 2)
    w = np.clip((s - sf[j]) / (sf[j + 1] - sf[j]), 0.0, 1.0)
    k = np.arange(s.size)
    c = np.exp(np.interp(s, t["fraction"], main) + (1 - w) * per_row[j, k] + w * per_row[j + 1, k])
    np.testing.assert_allclose(r.correction, c, rtol=1e-13)
    beta = tension_ratio(P16B, 19, D16B, e)
    np.testing.assert_allclose(r.load_ratio, c * beta ** (-9.0), rtol=1e-13)
