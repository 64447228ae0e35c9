"""The fast paths of the analysis give the values of the plain algorithms they replace.

Each fast path is compared with an independent or the previous implementation, kept
here (or in the module, private) as the reference:

* hull perimeters of two pitch polygons (Cauchy's formula, vectorised) against Qhull;
* the loop length of :func:`~chaindrive.layout.tensioner_travel` against
  :func:`~chaindrive.layout.wrap_layout`, and the travel against the previous
  implementation (a root of ``wrap_layout(...).length`` by SciPy);
* :func:`chaindrive._roots.brentq` against ``scipy.optimize.brentq`` (bit for bit);
* :func:`~chaindrive.vibration.tensioner_design.propose_safe_tensioner` (branch and bound)
  against the whole resonance map (the previous implementation).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from scipy.optimize import brentq as scipy_brentq

from chaindrive import layout as L
from chaindrive._roots import brentq
from chaindrive.errors import InfeasibleError, InputError
from chaindrive.vibration.resonance import TensionerSpan, excitation_multipliers
from chaindrive.vibration.tensioner_design import (
    SafeTensioner,
    _min_margin,
    _speed_grid,
    _unsafe_frequencies,
    propose_safe_tensioner,
    resonance_map,
)

# --------------------------------------------------------------------------- hull perimeters


def _qhull_grid(p, z1, z2, a, d, n):
    """The previous ``_polygon_links``: one Qhull hull per phase pair."""
    ph1 = np.arange(n) * (2 * np.pi / z1) / n
    ph2 = np.arange(n) * (2 * np.pi / z2) / n
    out = np.empty((n, n))
    for i, f1 in enumerate(ph1):
        for j, f2 in enumerate(ph2):
            v1 = L.pitch_polygon_vertices(p, z1, f1, d)
            v2 = L.pitch_polygon_vertices(p, z2, f2, d, centre=(a, 0.0))
            out[i, j] = L._hull_perimeter(np.vstack([v1, v2])) / p
    return out


@settings(max_examples=60, deadline=None)
@given(z1=st.integers(3, 60), z2=st.integers(3, 60), pitch=st.floats(0.005, 0.2),
       gap=st.floats(1e-3, 4.0), link=st.booleans(), ratio=st.floats(0.05, 0.45), phases=st.integers(1, 5))
def test_polygon_grid_equals_qhull(z1, z2, pitch, gap, link, ratio, phases):
    # reference: scipy.spatial.ConvexHull (Qhull) of the union of the two vertex sets
    d = ratio * pitch if link else None
    r1, r2 = float(L.pitch_radius(pitch, z1, d)), float(L.pitch_radius(pitch, z2, d))
    a = abs(r2 - r1) + gap * (r1 + r2)  # from nested-but-not-concentric to far apart
    fast = L._polygon_links(pitch, z1, z2, a, d, phases)[2]
    np.testing.assert_allclose(fast, _qhull_grid(pitch, z1, z2, a, d, phases), rtol=1e-12)


def _random_convex(rng, n, centre, radius):
    angles = np.sort(rng.uniform(0, 2 * np.pi, n))
    radii = radius * rng.uniform(0.999, 1.0, n)  # near-circular: convex for n >= 3 spread points
    pts = np.column_stack([centre[0] + radii * np.cos(angles), centre[1] + radii * np.sin(angles)])
    from scipy.spatial import ConvexHull

    return pts[ConvexHull(pts).vertices]  # counter-clockwise hull vertices


@settings(max_examples=60, deadline=None)
@given(random_state=st.integers(0, 2**32 - 1), n1=st.integers(3, 30), n2=st.integers(3, 30),
       dx=st.floats(-3.0, 3.0), dy=st.floats(-3.0, 3.0), scale=st.floats(0.2, 5.0))
def test_cauchy_perimeter_of_any_two_convex_polygons(random_state, n1, n2, dx, dy, scale):
    # Cauchy's formula holds for any pair of convex polygons, crossing or nested: Qhull agrees
    rng = np.random.default_rng(random_state)
    v1 = _random_convex(rng, n1, (0.0, 0.0), 1.0)
    v2 = _random_convex(rng, n2, (dx, dy), scale)
    assume(len(v1) >= 3 and len(v2) >= 3)
    fast = L._hull_perimeters(v1[None], v2[None])[0, 0]
    assert fast == pytest.approx(L._hull_perimeter(np.vstack([v1, v2])), rel=1e-12)


def test_polygon_length_exact_cases_and_regression():
    # equal wheels in equal phase: the hull is the polygon swept along the centre line,
    # X = z + 2a/p exactly (docs/drive.md), for every phase on the grid diagonal
    r = L.chain_length_polygon(0.0254, 19, 19, 1.0, phases=4)
    np.testing.assert_allclose(np.diag(r.links), 19 + 2 * 1.0 / 0.0254, rtol=1e-13)
    # regression: the values of the previous (Qhull) implementation, commit 6b56522
    r = L.chain_length_polygon(0.0254, 19, 57, 1.05, phases=8)
    assert r.links_max == pytest.approx(121.56539811591531, rel=1e-13)
    assert r.links_min == pytest.approx(121.56193774520146, rel=1e-13)


def test_centre_distance_polygon_unchanged():
    # the example drive roller_industrial (16B, 19/57 teeth, 122 links): the values of the
    # previous implementation (Qhull hulls, scipy's brentq), commit 6b56522
    cd = L.centre_distance_polygon(0.0254, 19, 57, 122, phases=8)
    assert cd.taut == pytest.approx(1.055579277377267, rel=1e-12)
    assert cd.loose == pytest.approx(1.0556233121300698, rel=1e-12)


# --------------------------------------------------------------------------- loop length


@st.composite
def _loops(draw):
    n = draw(st.integers(2, 5))
    angles = np.sort(np.array(draw(st.lists(st.floats(0, 2 * np.pi), min_size=n, max_size=n, unique=True))))
    ring = draw(st.floats(0.5, 3.0))
    centres = np.column_stack([ring * np.cos(angles), ring * np.sin(angles)])
    centres += np.array(draw(st.lists(st.floats(-0.3, 0.3), min_size=2 * n, max_size=2 * n))).reshape(n, 2)
    radii = np.array(draw(st.lists(st.floats(0.02, 0.6), min_size=n, max_size=n)))
    sides = np.array(draw(st.lists(st.sampled_from([1.0, 1.0, -1.0]), min_size=n, max_size=n)))
    return centres, radii, sides


@settings(max_examples=150, deadline=None)
@given(_loops())
def test_loop_lengths_equal_wrap_layout(loop):
    centres, radii, sides = loop
    fast = float(L._loop_lengths(centres[None], radii, sides)[0])
    try:
        slow = L.wrap_layout(centres, radii, sides).length
    except InfeasibleError:
        assert fast == -np.inf
        return
    assert fast == pytest.approx(slow, rel=1e-14)


def _travel_reference(centres, radii, sides, index, direction, elongation, chain_length=None, extra_length=0.0):
    """The previous tensioner_travel: wrap_layout in a Python loop, scipy's brentq."""
    c = np.asarray(centres, dtype=float)
    lay0 = L.wrap_layout(c, radii, sides)
    u = np.asarray(direction, dtype=float) / np.hypot(*direction)
    length_chain = lay0.length if chain_length is None else chain_length

    def length(s):
        cc = c.copy()
        cc[index] = cc[index] + s * u
        try:
            return L.wrap_layout(cc, radii, sides).length
        except InfeasibleError:
            return -np.inf

    smax = float(np.max(np.hypot(*(c - c[index]).T))) + float(np.max(lay0.radii)) * 4
    grid = np.linspace(0, smax, 120)
    vals = np.array([length(s) for s in grid])
    out = []
    for e in np.atleast_1d(elongation):
        target = lay0.length + extra_length + e * length_chain
        if target <= lay0.length:
            out.append(0.0)
            continue
        j = int(np.nonzero(vals >= target)[0][0])
        out.append(scipy_brentq(lambda s, t=target: length(s) - t, grid[j - 1], grid[j]))
    return np.array(out)


@settings(max_examples=40, deadline=None)
@given(drop=st.floats(0.05, 0.5), idler=st.floats(0.03, 0.15), span=st.floats(1.0, 4.0),
       extra=st.floats(0.0, 0.05), angle=st.floats(-0.5, 0.5))
def test_tensioner_travel_equals_previous_implementation(drop, idler, span, extra, angle):
    centres = [[0.0, 0.0], [span / 2, -drop], [span, 0.0]]  # back-side idler under the lower span
    radii, sides = [0.2, idler, 0.25], [1, -1, 1]
    direction = [math.sin(angle), math.cos(angle)]
    elong = np.array([0.01, 0.02, 0.03])
    try:
        ref = _travel_reference(centres, radii, sides, 1, direction, elong, extra_length=extra)
    except (IndexError, InfeasibleError):  # wheels overlapping, or the reference running out of travel
        with pytest.raises(InfeasibleError, match="cannot take up|overlap|loop"):
            L.tensioner_travel(centres, radii, sides, 1, direction, elong, extra_length=extra)
        return
    fast = L.tensioner_travel(centres, radii, sides, 1, direction, elong, extra_length=extra)
    np.testing.assert_allclose(fast, ref, rtol=1e-12, atol=1e-13)


def test_tensioner_travel_regression():
    # the docstring example (back-side idler), values of the previous implementation (commit 6b56522)
    s = L.tensioner_travel([[0, 0], [1, -0.2], [2, 0]], [0.2, 0.05, 0.2], [1, -1, 1], 1, [0, 1], [0.01, 0.03])
    np.testing.assert_allclose(s, [0.18404275180809668, 0.35171500837768316], rtol=1e-12)


# --------------------------------------------------------------------------- brentq


_FUNCTIONS = (
    lambda x, c: c[0] * x**3 + c[1] * x**2 + c[2] * x + c[3],
    lambda x, c: math.tanh(c[0] * x) + 0.9 * math.tanh(c[1]),
    lambda x, c: math.exp(c[0] * x) - abs(c[1]) - 0.1,
    lambda x, c: math.sin(3 * c[0] * x) + 0.3 * c[1],
)


@settings(max_examples=300, deadline=None)
@given(kind=st.integers(0, 3), coefficients=st.lists(st.floats(-3, 3), min_size=4, max_size=4),
       a=st.floats(-3, 3), b=st.floats(-3, 3), xtol_exponent=st.floats(-15, -2))
def test_brentq_is_scipy_bit_for_bit(kind, coefficients, a, b, xtol_exponent):
    f = _FUNCTIONS[kind]
    xtol = 10.0**xtol_exponent
    try:
        expected = scipy_brentq(f, a, b, args=(coefficients,), xtol=xtol)
    except (ValueError, RuntimeError) as exc:
        with pytest.raises(type(exc), match=str(exc)[:20].replace("(", r"\(").replace(")", r"\)")):
            brentq(f, a, b, args=(coefficients,), xtol=xtol)
        return
    assert brentq(f, a, b, args=(coefficients,), xtol=xtol) == expected


def test_brentq_errors():
    with pytest.raises(ValueError, match="must have different signs"):
        brentq(lambda x: x * x + 1.0, -1.0, 1.0)
    with pytest.raises(ValueError, match="xtol too small"):
        brentq(lambda x: x, -1.0, 1.0, xtol=0.0)
    with pytest.raises(ValueError, match="rtol too small"):
        brentq(lambda x: x, -1.0, 1.0, rtol=1e-20)
    with pytest.raises(ValueError, match="maxiter must be >= 0"):
        brentq(lambda x: x, -1.0, 1.0, maxiter=-1)
    with pytest.raises(ValueError, match="is NaN"):
        brentq(lambda x: math.nan if x > 0 else -1.0, -1.0, 1.0)
    with pytest.raises(RuntimeError, match="Failed to converge after 2 iterations"):
        brentq(lambda x: x**3 - 2.0, 0.0, 2.0, maxiter=2)  # scipy: the same message
    assert brentq(lambda x: x, 0.0, 1.0) == 0.0  # a root at an end is returned as is


# --------------------------------------------------------------------------- safe tensioner


def _propose_reference(span, speed_range, *, ratio=1.0, teeth=None, link_chain=False, modes=3, speeds=50,
                       required_margin=0.05, decades=1.5, points=241):
    """The previous propose_safe_tensioner: the whole resonance map, nearest safe point."""
    m0, c0 = span.mass, span.stiffness
    f = np.linspace(-decades, decades, int(points))
    mm, cc = m0 * 10.0**f, c0 * 10.0**f
    r = resonance_map(span, mm, cc, speed_range, ratio=ratio, teeth=teeth, link_chain=link_chain,
                      modes=modes, speeds=speeds, required_margin=required_margin)
    w = _speed_grid(speed_range, speeds)
    mult = list(excitation_multipliers(ratio, teeth, link_chain=link_chain).values())
    mu0 = float(_min_margin(span.frequencies(modes), mult, w))
    if mu0 > required_margin:
        return SafeTensioner(m0, c0, mu0, 0.0, m0, c0, mu0, False)
    d = np.where(r.safe, np.hypot(f[:, None], f[None, :]), np.inf)
    if not np.isfinite(d).any():
        return None
    i, j = np.unravel_index(np.argmin(d), d.shape)
    return SafeTensioner(float(mm[i]), float(cc[j]), float(r.min_margin[i, j]), float(d[i, j]), m0, c0, mu0, True)


@settings(max_examples=25, deadline=None)
@given(tension=st.floats(500, 20000), q=st.floats(1, 10), l1=st.floats(0.3, 3), l2=st.floats(0.3, 3),
       b1=st.floats(0, 0.5), b2=st.floats(0, 0.5), mass=st.floats(0.5, 100), stiffness=st.floats(1e3, 1e6),
       omega=st.floats(5, 60), ratio=st.floats(1, 4), teeth=st.integers(6, 25), link=st.booleans(),
       required=st.floats(-0.1, 0.2), decades=st.floats(0.3, 2.0))
def test_propose_safe_tensioner_equals_whole_map(tension, q, l1, l2, b1, b2, mass, stiffness, omega, ratio,
                                                  teeth, link, required, decades):
    span = TensionerSpan(tension, q, l1, l2, b1, b2, mass, stiffness)
    kw = dict(ratio=ratio, teeth=teeth, link_chain=link, required_margin=required, decades=decades, points=41)
    expected = _propose_reference(span, (0.9 * omega, 1.1 * omega), **kw)
    if expected is None:
        with pytest.raises(InfeasibleError, match="no safe tensioner within"):
            propose_safe_tensioner(span, (0.9 * omega, 1.1 * omega), **kw)
    else:
        assert propose_safe_tensioner(span, (0.9 * omega, 1.1 * omega), **kw) == expected


def test_propose_safe_tensioner_cases():
    # the example drive mining_conveyor (18x64 chain, 8 pockets): the band is the paper's, on
    # its three excitations (issue 20); at 5.5 rad/s the link pair z1 ω1 = 44 rad/s meets P1;
    # the answer is what the whole map says
    span = TensionerSpan(11825.020394772118, 6.5, 1.2642691152114252, 2.877651194234193,
                         0.28988998113635517, 0.1254385892522538, 60.0, 200000.0)
    for omega in (2.0, 5.5):
        expected = _propose_reference(span, (0.9 * omega, 1.1 * omega), ratio=1.0, teeth=8, link_chain=True,
                                      points=61)
        if expected is None:
            with pytest.raises(InfeasibleError, match="no safe tensioner"):
                propose_safe_tensioner(span, (0.9 * omega, 1.1 * omega), ratio=1.0, teeth=8, link_chain=True,
                                       points=61)
        else:
            assert propose_safe_tensioner(span, (0.9 * omega, 1.1 * omega), ratio=1.0, teeth=8, link_chain=True,
                                          points=61) == expected
    # nothing safe within ±1.5 decades: a span whose two equal parts share a node mode
    # jπc/ℓ that no tensioner can move, inside the driving sprocket's band
    node = TensionerSpan(2000.0, 2.6, 0.8, 0.8, 0.35, 0.35, 3.0, 5e4)
    p_node = float(node.frequencies(3)[1])
    with pytest.raises(InfeasibleError, match=r"no safe tensioner within ±1.5 decades of m = 3 kg"):
        propose_safe_tensioner(node, (0.95 * p_node, 1.05 * p_node), ratio=1.0, points=61)
    # the docstring span at speeds where it fails, with a safe design nearby (4, 12, 14, 62,
    # 66 rad/s), where nothing is safe (8, 72) and where it passes (30): as the whole map
    span = TensionerSpan(2000.0, 2.6, 0.8, 0.8, 0.35, 0.35, 3.0, 5e4)
    for omega in (4.0, 8.0, 12.0, 14.0, 30.0, 62.0, 66.0, 72.0):
        expected = _propose_reference(span, (0.9 * omega, 1.1 * omega), ratio=2.5, teeth=17, points=61)
        if expected is None:
            with pytest.raises(InfeasibleError, match="no safe tensioner"):
                propose_safe_tensioner(span, (0.9 * omega, 1.1 * omega), ratio=2.5, teeth=17, points=61)
        else:
            assert propose_safe_tensioner(span, (0.9 * omega, 1.1 * omega), ratio=2.5, teeth=17,
                                          points=61) == expected
    # regression: the proposal at 24 rad/s (the whole map's answer): the same numbers as at
    # 12 rad/s before issue 20, where z1 ω1 = 204 rad/s was the meshing excitation; now it is
    # the unequal links' z1 ω1/2 at 24 rad/s (commit 6b56522)
    r = propose_safe_tensioner(span, (21.6, 26.4), ratio=2.5, teeth=17, points=61)
    assert r.changed and r.distance == pytest.approx(0.36055512754639896, rel=1e-12)
    assert (r.mass, r.stiffness) == pytest.approx((5.985786944906639, 31547.867224009664), rel=1e-12)
    assert r.margin == pytest.approx(0.050148612898105016, rel=1e-9)
    # small and tiny grids: the same answers (points in [2, MAX_GRID], decades in (0, 10])
    changed = 0
    for omega in (4.0, 12.0, 66.0):
        for points, decades in ((61, 1.0), (2, 1.0), (3, 0.5)):
            kw = dict(ratio=2.5, teeth=17, points=points, decades=decades)
            expected = _propose_reference(span, (0.9 * omega, 1.1 * omega), **kw)
            if expected is None:
                with pytest.raises(InfeasibleError, match="no safe tensioner"):
                    propose_safe_tensioner(span, (0.9 * omega, 1.1 * omega), **kw)
            else:
                assert propose_safe_tensioner(span, (0.9 * omega, 1.1 * omega), **kw) == expected
                changed += expected.changed
    assert changed >= 1
    # no grid, or a grid read downwards, is refused with the valid range
    with pytest.raises(InputError, match="points"):
        propose_safe_tensioner(span, (27.0, 33.0), ratio=2.5, teeth=17, points=0)
    with pytest.raises(InputError, match=r"decades must lie in \(0, 10\]"):
        propose_safe_tensioner(span, (27.0, 33.0), ratio=2.5, teeth=17, points=61, decades=-1.0)
    # the argument checks of the map still apply
    with pytest.raises(Exception, match="speed_range"):
        propose_safe_tensioner(span, (30.0, 20.0), ratio=2.5, teeth=17, points=61)


@settings(max_examples=100, deadline=None)
@given(frequency=st.floats(0.1, 2000), required=st.floats(-0.2, 0.3), ratio=st.floats(1, 4),
       teeth=st.integers(6, 25), low=st.floats(5, 50), width=st.floats(0, 0.5))
def test_unsafe_set_is_where_the_margin_is_small(frequency, required, ratio, teeth, low, width):
    # the merged intervals of _unsafe_frequencies against the margin computed by _min_margin
    mult = list(excitation_multipliers(ratio, teeth).values())
    w = _speed_grid((low, low * (1 + width)), 50)
    mu = float(_min_margin(np.array([frequency]), mult, w))
    tight_start, tight_end = _unsafe_frequencies(mult, w, required)
    wide_start, wide_end = _unsafe_frequencies(mult, w, required, widen=True)
    inside_tight = bool(np.any((tight_start <= frequency) & (frequency <= tight_end)))
    inside_wide = bool(np.any((wide_start <= frequency) & (frequency <= wide_end)))
    if inside_tight:
        assert mu <= required
    if not inside_wide:
        assert mu > required
