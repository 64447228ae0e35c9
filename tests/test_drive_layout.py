"""Tests of chaindrive.layout: chain length, centre distance, wraps, sag, take-up."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from chaindrive import layout as L
from chaindrive.errors import InfeasibleError, InputError

P = 0.0254


# ---------------------------------------------------------------- approximation
def test_approx_hand_value():
    # Hand computation of ISO 10823 / Shigley eq. (17-34): 2·1050/25.4 + 76/2
    # + (38/2π)²·25.4/1050 = 82.677165 + 38 + 0.884814 = 121.561979
    X = L.chain_length_approx(P, 19, 57, 1.05)
    assert float(X) == pytest.approx(2 * 1050 / 25.4 + 38 + (38 / (2 * math.pi)) ** 2 * 25.4 / 1050, rel=1e-12)
    assert float(X) == pytest.approx(121.561979, abs=1e-6)


def test_approx_inverse_is_exact():
    a = np.array([0.4, 0.8, 1.05, 2.0])
    X = L.chain_length_approx(P, 17, 51, a)
    assert np.allclose(L.centre_distance_approx(P, 17, 51, X), a, rtol=1e-12)


def test_approx_engpowerdata_constant():
    # engpowerdata.com "ketting" uses (z2 - z1)² / (39.6 a') with 39.6 ≈ 4π² = 39.478:
    # the two agree to 0.3 % of the last term
    a_p = 40.0
    ours = float(L.chain_length_approx(1.0, 15, 45, a_p))
    theirs = 2 * a_p + 30 + 30**2 / (39.6 * a_p)
    assert ours == pytest.approx(theirs, abs=0.002)


def test_approx_against_exact_circles_and_polygon():
    # the approximation replaces arcs by whole pitches (R ≈ z p / 2π); against the exact
    # polygon model it is within 0.01 pitch here, the pitch-circle belt is 0.06 above
    pg = L.chain_length_polygon(P, 19, 57, 1.05, phases=6)
    assert pg.links_min - 0.01 < pg.links_approx < pg.links_max + 0.01
    assert pg.links_circles - pg.links_mean == pytest.approx(0.055, abs=0.01)


@pytest.mark.parametrize("ratio", [1, 2, 3, 5, 7])
def test_approx_close_to_circles_for_long_centres(ratio):
    z1 = 17
    z2 = z1 * ratio
    a = 40 * P
    d = float(L.chain_length_circles(P, z1, z2, a)) - float(L.chain_length_approx(P, z1, z2, a))
    # circles are longer (arc vs chord per tooth: R θ vs p), ≈ (z1+z2)/2·(π/z/ sin(π/z) - 1)·...
    assert 0 <= d < 0.1 + 0.01 * ratio


def test_approx_errors():
    with pytest.raises(InputError, match="pitch must be positive"):
        L.chain_length_approx(-1, 19, 57, 1.0)
    with pytest.raises(InputError, match="teeth_1 must be a whole number >= 3"):
        L.chain_length_approx(P, 2.5, 57, 1.0)
    with pytest.raises(InputError, match="centre_distance must be positive"):
        L.chain_length_approx(P, 19, 57, 0.0)
    with pytest.raises(InfeasibleError, match="too short"):
        L.centre_distance_approx(P, 19, 57, 30)


def test_approx_scalar_vs_array():
    a = np.linspace(0.5, 2.0, 7)
    arr = L.chain_length_approx(P, 19, 57, a)
    assert arr.shape == (7,)
    assert np.allclose(arr, [float(L.chain_length_approx(P, 19, 57, x)) for x in a])


@settings(max_examples=40, deadline=None)
@given(z1=st.integers(9, 30), k=st.floats(1.0, 4.0), a1=st.floats(30, 80), da=st.floats(0.1, 20))
def test_length_grows_with_centre_distance(z1, k, a1, da):
    z2 = int(round(z1 * k))
    x1 = float(L.chain_length_approx(P, z1, z2, a1 * P))
    x2 = float(L.chain_length_approx(P, z1, z2, (a1 + da) * P))
    assert x2 > x1
    c1 = float(L.chain_length_circles(P, z1, z2, a1 * P))
    c2 = float(L.chain_length_circles(P, z1, z2, (a1 + da) * P))
    assert c2 > c1


# ---------------------------------------------------------------- circles and polygons
def test_circles_equal_wheels_exact():
    # equal wheels: L = 2a + 2πR exactly
    R = P / (2 * math.sin(math.pi / 19))
    assert float(L.chain_length_circles(P, 19, 19, 1.0)) == pytest.approx((2.0 + 2 * math.pi * R) / P, rel=1e-14)


def test_polygon_equal_wheels_equal_phase_exact():
    # equal wheels in equal phase: hull = polygon swept along the centre line,
    # perimeter = z p + 2a exactly (Minkowski sum with a segment)
    for z, a in [(19, 1.0), (8, 0.3), (40, 2.5)]:
        v1 = L.pitch_polygon_vertices(P, z, 0.1)
        v2 = L.pitch_polygon_vertices(P, z, 0.1, centre=(a, 0.0))
        per = L._hull_perimeter(np.vstack([v1, v2])) / P
        assert per == pytest.approx(z + 2 * a / P, rel=1e-13)


def test_polygon_tends_to_circles_for_many_teeth():
    # many teeth: polygon -> circle; the length difference per wheel ~ (πR θ)(π/z)²/6
    pg = L.chain_length_polygon(P, 200, 400, 5.0, phases=3)
    assert pg.links_mean == pytest.approx(pg.links_circles, rel=2e-5)


def test_polygon_bi_regular_perimeter():
    # a pocket wheel of z pockets: 2z sides alternating t+d and t-d, perimeter 2 z t
    v = L.pitch_polygon_vertices(0.064, 8, 0.0, bar_diameter=0.018)
    sides = np.hypot(*(np.roll(v, -1, axis=0) - v).T)
    assert np.allclose(sides[0::2], 0.082) and np.allclose(sides[1::2], 0.046)
    # equal pocket wheels in equal phase: links = 2 z + 2a/t exactly
    pg = L.chain_length_polygon(0.064, 8, 8, 3.0, bar_diameter=0.018, phases=1)
    assert pg.links_min == pytest.approx(16 + 2 * 3.0 / 0.064, rel=1e-13)
    assert pg.links_approx is None


def test_polygon_regression():
    pg = L.chain_length_polygon(P, 19, 57, 1.05, phases=6)
    assert pg.links_min == pytest.approx(121.56194, abs=2e-5)
    assert pg.links_max == pytest.approx(121.56540, abs=2e-5)
    assert pg.links.shape == (6, 6)


def test_centre_distance_polygon_roundtrip():
    cd = L.centre_distance_polygon(P, 19, 57, 122, phases=6)
    assert cd.taut <= cd.loose
    # taut: the chain of 122 links is just taut at the tightest sampled phase
    pg = L.chain_length_polygon(P, 19, 57, cd.taut, phases=6)
    assert pg.links_max == pytest.approx(122, abs=1e-9)
    pg = L.chain_length_polygon(P, 19, 57, cd.loose, phases=6)
    assert pg.links_min == pytest.approx(122, abs=1e-9)
    # regression and the ISO approximation within 0.1 mm
    assert cd.taut == pytest.approx(1.0555793, abs=1e-6)
    assert cd.approx == pytest.approx(cd.taut, abs=1e-4)
    assert cd.circles < cd.taut


def test_centre_distance_polygon_errors():
    with pytest.raises(InputError, match="links must be a whole number"):
        L.centre_distance_polygon(P, 19, 57, 121.5)
    with pytest.raises(InfeasibleError, match="too short"):
        L.centre_distance_polygon(P, 19, 57, 30)
    with pytest.raises(InputError, match="phases"):
        L.chain_length_polygon(P, 19, 57, 1.0, phases=0)


def test_even_links():
    assert list(L.even_links([121.2, 122.0, 122.0001, 1.0])) == [122, 122, 124, 2]
    with pytest.raises(InputError, match="links must be positive"):
        L.even_links(0)


# ---------------------------------------------------------------- many wheels
def test_wrap_two_wheels_matches_belt_formula():
    r1, r2, a = 0.08, 0.23, 1.05
    lay = L.wrap_layout([[0, 0], [a, 0]], [r1, r2])
    beta = math.asin((r2 - r1) / a)
    assert lay.length == pytest.approx(2 * math.sqrt(a * a - (r2 - r1) ** 2)
                                       + r1 * (math.pi - 2 * beta) + r2 * (math.pi + 2 * beta), rel=1e-14)
    assert lay.wrap_angle[0] == pytest.approx(math.pi - 2 * beta)
    assert lay.wrap_angle[1] == pytest.approx(math.pi + 2 * beta)
    # the tangent points lie on the circles and the spans are tangent (perpendicular radius)
    for i in range(2):
        t = np.array([math.cos(lay.span_angle[i]), math.sin(lay.span_angle[i])])
        for pt, j in ((lay.span_start[i], i), (lay.span_end[i], (i + 1) % 2)):
            rad = pt - lay.centres[j]
            assert np.hypot(*rad) == pytest.approx(lay.radii[j])
            assert abs(np.dot(rad, t)) < 1e-12


def test_wrap_equilateral_three_wheels():
    s = 1.0
    c = [[0, 0], [s, 0], [s / 2, s * math.sqrt(3) / 2]]
    lay = L.wrap_layout(c, [0.1] * 3)
    assert lay.length == pytest.approx(3 * s + 2 * math.pi * 0.1, rel=1e-14)
    assert np.allclose(lay.wrap_angle, 2 * math.pi / 3)


def test_wrap_back_side_idler():
    c = [[0, 0], [1, -0.2], [2, 0]]
    lay = L.wrap_layout(c, [0.2, 0.05, 0.2], [1, -1, 1])
    assert np.sum(lay.sides * lay.wrap_angle) == pytest.approx(2 * math.pi)
    # symmetric: both spans to the idler have equal length
    assert lay.span_length[0] == pytest.approx(lay.span_length[1])
    assert lay.wrap_angle[1] > 0


def test_wrap_errors():
    with pytest.raises(InputError, match="centres must have shape"):
        L.wrap_layout([[0, 0]], [0.1])
    with pytest.raises(InputError, match="radii must have shape"):
        L.wrap_layout([[0, 0], [1, 0]], [0.1])
    with pytest.raises(InputError, match="sides must be"):
        L.wrap_layout([[0, 0], [1, 0]], [0.1, 0.1], [1, 2])
    with pytest.raises(InfeasibleError, match="overlap"):
        L.wrap_layout([[0, 0], [0.05, 0]], [0.1, 0.3])
    with pytest.raises(InfeasibleError, match="simple counter-clockwise loop"):
        # wheels listed clockwise: the left turns add up to 4π, not 2π
        L.wrap_layout([[0, 0], [0, 1], [1, 0]], [0.1, 0.1, 0.1])


def test_teeth_in_mesh():
    assert list(L.teeth_in_mesh(np.array([math.pi, 2 * math.pi / 3]), 18)) == [9, 6]
    with pytest.raises(InputError, match="wrap_angle"):
        L.teeth_in_mesh(7.0, 18)


# ---------------------------------------------------------------- sag
def test_catenary_matches_closed_form_level_span():
    # level span: f = (H/w)(cosh(wℓ/2H) - 1)
    H, q, ell = 500.0, 2.6, 2.0
    w = q * L.GRAVITY
    assert float(L.catenary_sag(ell, 0.0, H, q)) == pytest.approx(H / w * (math.cosh(w * ell / (2 * H)) - 1), rel=1e-12)


def test_catenary_inclined_by_direct_search():
    # independent check: sample the catenary through both supports and take the
    # largest vertical distance to the chord
    Lc, g, H, q = 3.0, 0.4, 300.0, 5.0
    k = q * L.GRAVITY / H
    ell, h = Lc * math.cos(g), Lc * math.sin(g)
    from scipy.optimize import brentq

    x0 = brentq(lambda x0: (math.cosh(k * (ell - x0)) - math.cosh(k * x0)) / k - h, -50, 50)
    x = np.linspace(0, ell, 200001)
    y = (np.cosh(k * (x - x0)) - np.cosh(k * x0)) / k
    f = np.max(h / ell * x - y)
    assert float(L.catenary_sag(Lc, g, H, q)) == pytest.approx(f, rel=1e-8)


@pytest.mark.parametrize("g", [0.0, 0.3, -0.5])
def test_parabola_limit(g):
    # taut: sag/span < 0.5 %: catenary and parabola (weight q g / cos γ per horizontal
    # length) within 0.2 %
    c = float(L.catenary_sag(2.0, g, 5000.0, 2.6))
    p = float(L.parabolic_sag(2.0, g, 5000.0, 2.6))
    assert c == pytest.approx(p, rel=2e-3)


def test_tension_for_sag_inverse_and_arrays():
    H = np.array([50.0, 500.0, 5e4])
    f = L.catenary_sag(2.0, 0.2, H, 2.6)
    assert np.allclose(L.tension_for_sag(2.0, 0.2, f, 2.6), H, rtol=1e-9)
    assert float(L.tension_for_sag(2.0, 0.0, 0.025502816, 2.6)) == pytest.approx(500.0, rel=1e-6)


@settings(max_examples=30, deadline=None)
@given(H1=st.floats(10, 1e5), r=st.floats(1.01, 10), g=st.floats(-1.2, 1.2))
def test_sag_decreases_with_tension(H1, r, g):
    assert float(L.catenary_sag(1.5, g, H1 * r, 3.0)) < float(L.catenary_sag(1.5, g, H1, 3.0))


def test_sag_errors():
    with pytest.raises(InputError, match="inclination must lie in"):
        L.catenary_sag(1.0, math.pi / 2, 100, 1.0)
    with pytest.raises(InputError, match="tension must be positive"):
        L.catenary_sag(1.0, 0, -1, 1.0)
    with pytest.raises(InputError, match="mass_per_length must be positive"):
        L.parabolic_sag(1.0, 0, 100, 0)
    with pytest.raises(InputError, match="sag must be positive"):
        L.tension_for_sag(1.0, 0, 0, 1.0)


# ---------------------------------------------------------------- take-up
def test_centre_distance_travel_about_half_elongation():
    e = np.array([0.01, 0.02, 0.03])
    da = L.centre_distance_travel(P, 19, 57, 1.05, e)
    L0 = float(L.chain_length_circles(P, 19, 57, 1.05)) * P
    # two spans absorb the length: Δa ≈ e L0 / (2 cos β); β small here
    assert np.allclose(da, e * L0 / 2, rtol=0.02)
    assert float(L.centre_distance_travel(P, 19, 57, 1.05, 0.0)) == 0.0


def test_tensioner_travel_symmetric_idler_closed_form():
    # a back-side idler of radius r between two equal wheels (radius R) moved up by s:
    # length(s) from wrap_layout; check against the independent closed form for the
    # symmetric case: spans sqrt(D² - (R + r)²) with D = hypot(1, y)
    c = [[0, 0], [1, -0.2], [2, 0]]
    s = L.tensioner_travel(c, [0.2, 0.05, 0.2], [1, -1, 1], 1, [0, 1], [0.01, 0.03])
    lay0 = L.wrap_layout(c, [0.2, 0.05, 0.2], [1, -1, 1])
    for si, e in zip(s, [0.01, 0.03], strict=True):
        cc = np.array(c, dtype=float)
        cc[1, 1] += si
        assert L.wrap_layout(cc, [0.2, 0.05, 0.2], [1, -1, 1]).length == pytest.approx(lay0.length * (1 + e))
    assert s[1] > s[0] > 0


def test_tensioner_travel_errors():
    c = [[0, 0], [1, -0.2], [2, 0]]
    with pytest.raises(InputError, match="direction must be a non-zero 2-vector"):
        L.tensioner_travel(c, [0.2, 0.05, 0.2], [1, -1, 1], 1, [0, 0], 0.01)
    with pytest.raises(InputError, match="index must lie in"):
        L.tensioner_travel(c, [0.2, 0.05, 0.2], [1, -1, 1], 5, [0, 1], 0.01)
    with pytest.raises(InfeasibleError, match="cannot take up"):
        # moving the idler away from the chain (downwards) shortens the path
        L.tensioner_travel(c, [0.2, 0.05, 0.2], [1, -1, 1], 1, [0, -1], 0.01)


def test_jindal_example_30_1_roundtrip():
    # U. C. Jindal, Machine Design (Pearson), Example 30-1, p. 778 (as reproduced by the
    # FOSSEE Python/Scilab textbook companion, "sum 30-1"): 17/51 teeth, p = 9.52 mm,
    # C = 300 mm: chain length from the approximation, then C from the inverse formula
    # C = (p/4)[(Ln - (n1+n2)/2) + sqrt((Ln - (n1+n2)/2)² - 8((n2-n1)/2π)²)] = 300.00 mm.
    p = 9.52e-3
    Ln = float(L.chain_length_approx(p, 17, 51, 0.300))
    z = Ln - 34
    book = p / 4 * (z + math.sqrt(z * z - 8 * (34 / (2 * math.pi)) ** 2))
    assert book == pytest.approx(0.300, abs=5e-6)
    assert float(L.centre_distance_approx(p, 17, 51, Ln)) == pytest.approx(book, rel=1e-12)
    assert Ln == pytest.approx(2 * 300 / 9.52 + 34 + (34 / (2 * math.pi)) ** 2 * 9.52 / 300, rel=1e-12)


def test_tensioner_travel_extra_length_first():
    c = [[0, 0], [1, -0.2], [2, 0]]
    args = (c, [0.2, 0.05, 0.2], [1, -1, 1], 1, [0, 1])
    L0 = L.wrap_layout(*args[:3]).length
    # 10 mm of initial slack plus 1 % of a chain 10 mm longer than the path
    s = L.tensioner_travel(*args, [0.0, 0.01], chain_length=L0 + 0.01, extra_length=0.01)
    s_plain = L.tensioner_travel(*args, (0.01 + 0.01 * (L0 + 0.01)) / L0)
    assert s[1] == pytest.approx(float(s_plain), rel=1e-9)
    cc = np.array(c, dtype=float)
    cc[1, 1] += s[0]
    assert L.wrap_layout(cc, *args[1:3]).length == pytest.approx(L0 + 0.01)
    with pytest.raises(InputError, match="extra_length must be non-negative"):
        L.tensioner_travel(*args, 0.01, extra_length=-1)
