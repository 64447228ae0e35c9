"""The hull perimeter of two pitch polygons by their two bridges (chaindrive.layout._bridges)
equals Cauchy's support-function integral and Qhull's hull (independent computations)."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from chaindrive.errors import InputError
from chaindrive.layout._bridges import bridge_perimeters, edge_sums
from chaindrive.layout.two_wheels import (
    _hull_perimeter,
    _hull_perimeters,
    _phase_vertices,
    _radius,
    _shifted,
)


def _pairs(p, z1, z2, a, d, n, shift=0.0):
    ph1 = shift + np.arange(n) * (2 * np.pi / z1) / n
    ph2 = np.arange(n) * (2 * np.pi / z2) / n
    v1 = _phase_vertices(p, z1, ph1, d)
    v2 = _shifted(_phase_vertices(p, z2, ph2, d), a)
    return v1, v2, _radius(p, z1, d), _radius(p, z2, d)


@settings(max_examples=80, deadline=None)
@given(z1=st.integers(3, 80), z2=st.integers(3, 80), gap=st.floats(1.0001, 8.0), n=st.integers(1, 6),
       shift=st.floats(0.0, 6.3), link_chain=st.booleans())
def test_bridges_equal_the_support_function_integral(z1, z2, gap, n, shift, link_chain):
    p, d = (0.064, 0.018) if link_chain else (0.0254, None)
    if link_chain and min(z1, z2) < 4:
        z1, z2 = max(z1, 4), max(z2, 4)
    v1, v2, r1, r2 = _pairs(p, z1, z2, 0.0, d, n, shift)
    a = (r1 + r2) * gap
    v2 = _shifted(v2, a)
    got = bridge_perimeters(v1, v2, edge_sums(v1), edge_sums(v2), r1, r2, a)
    ref = _hull_perimeters(v1, v2)
    assert not np.isnan(got).any()
    np.testing.assert_allclose(got, ref, rtol=1e-13, atol=0)


@pytest.mark.parametrize("z1,z2,a,d", [(19, 57, 1.05, None), (8, 8, 2.0, 0.018), (3, 40, 0.5, None)])
def test_bridges_equal_qhull(z1, z2, a, d):
    # provenance: Qhull (scipy.spatial.ConvexHull), an independent hull algorithm
    p = 0.0254 if d is None else 0.064
    v1, v2, r1, r2 = _pairs(p, z1, z2, a, d, 3)
    got = bridge_perimeters(v1, v2, edge_sums(v1), edge_sums(v2), r1, r2, a)
    for i in range(3):
        for j in range(3):
            assert got[i, j] == pytest.approx(_hull_perimeter(np.concatenate([v1[i], v2[j]])), rel=1e-13)


def test_equal_wheels_in_phase_give_the_swept_polygon():
    # exact: two equal wheels in equal phase, X = z + 2a/p (chain_length_polygon's docstring)
    p, z, a = 0.0254, 19, 1.0
    v1, v2, r1, r2 = _pairs(p, z, z, a, None, 1)
    got = float(bridge_perimeters(v1, v2, edge_sums(v1), edge_sums(v2), r1, r2, a)[0, 0])
    assert got / p == pytest.approx(z + 2 * a / p, rel=1e-14)


def test_edge_sums_of_a_square():
    sq = np.array([[[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -1.0]]])
    np.testing.assert_allclose(edge_sums(sq), [[0.0, 2**0.5, 2 * 2**0.5, 3 * 2**0.5, 4 * 2**0.5]])


def test_pair_root_is_the_root_of_the_pair_with_its_bridges():
    # the root with the bridges' vertices held: the pair's hull perimeter (by the integral,
    # an independent computation) equals the length asked for there
    from chaindrive.layout._bridges import pair_root

    p, z1, z2, a0 = 0.0254, 19, 57, 1.05
    v1, v2, r1, r2 = _pairs(p, z1, z2, 0.0, None, 1)
    _, k1, k2 = bridge_perimeters(v1, _shifted(v2, a0), edge_sums(v1), edge_sums(v2), r1, r2, a0, vertices=True)
    length = 122 * p
    a = pair_root(edge_sums(v1)[0], edge_sums(v2)[0], v1[0], v2[0], (int(k1[0, 0, 0]), int(k1[1, 0, 0])),
                  (int(k2[0, 0, 0]), int(k2[1, 0, 0])), length, a0)
    assert float(_hull_perimeters(v1, _shifted(v2, a))[0, 0]) == pytest.approx(length, rel=1e-14)


def test_centre_distance_polygon_roots_where_the_grid_reaches_the_links():
    from chaindrive.layout import centre_distance_polygon
    from chaindrive.layout.two_wheels import _phase_grid

    p, z1, z2, n = 0.0254, 17, 45, 5
    r = centre_distance_polygon(p, z1, z2, 110, phases=n)
    ph1, ph2 = _phase_grid(z1, n), _phase_grid(z2, n)
    v1, v2 = _phase_vertices(p, z1, ph1, None), _phase_vertices(p, z2, ph2, None)
    assert _hull_perimeters(v1, _shifted(v2, r.taut)).max() / p == pytest.approx(110, rel=1e-14)
    assert _hull_perimeters(v1, _shifted(v2, r.loose)).min() / p == pytest.approx(110, rel=1e-14)


@settings(max_examples=40, deadline=None)
@given(scales=st.lists(st.floats(0.9, 1.05), min_size=1, max_size=8), tractor=st.booleans())
def test_span_lengths_equal_wrap_layout_row_by_row(scales, tractor):
    from chaindrive.layout import wrap_layout
    from chaindrive.layout.wrap import span_lengths

    if tractor:  # a back-side idler among four wheels
        c = np.array([[0.0, 0.5], [0.55, 0.2], [1.9, 0.2], [2.52, 0.35]])
        r, s = np.array([0.35, 0.2, 0.2, 0.3]), np.array([1.0, -1.0, 1.0, 1.0])
        c[1, 1] = 0.9
    else:
        c, r, s = np.array([[0.0, 0.0], [1.05, 0.0]]), np.array([0.078, 0.23]), np.ones(2)
    rows = r[None, :] * np.array(scales)[:, None]
    got = span_lengths(c, rows, s)
    try:
        ref = np.stack([wrap_layout(c, row, s).span_length for row in rows])
    except Exception:
        assert got is None
        return
    assert got is not None and np.array_equal(got, ref)


def test_loop_length_in_floats_equals_the_array_path():
    # tensioner_travel's root search evaluates one layout at a time in Python floats; the
    # numbers must be those of the array path bit for bit (the root search follows them)
    from chaindrive.layout.wrap import _loop_length, _loop_lengths

    rng = np.random.default_rng(0)
    for _ in range(400):
        n = int(rng.integers(2, 8))
        ang = np.sort(rng.uniform(0, 2 * np.pi, n))
        rad = rng.uniform(0.5, 3, n)
        c = np.stack([rad * np.cos(ang), rad * np.sin(ang)], 1)
        r, s = rng.uniform(0.01, 0.3, n), np.where(rng.random(n) < 0.2, -1.0, 1.0)
        ref = float(_loop_lengths(c[None], r, s)[0])
        got = _loop_length(c[:, 0].tolist(), c[:, 1].tolist(), r.tolist(), s.tolist())
        assert got == ref or (got == ref == -np.inf)


@settings(max_examples=60, deadline=None)
@given(z1=st.integers(3, 90), z2=st.integers(3, 90), gap=st.floats(1.0001, 6.0), n=st.integers(1, 8),
       shift=st.floats(0.0, 6.3))
def test_regular_polygons_find_the_same_bridges_without_a_search(z1, z2, gap, n, shift):
    # a roller chain's wheels: the extreme vertex is the one nearest the direction; the same
    # vertices, the same perimeters as the search over every vertex
    p = 0.0254
    v1, v2, r1, r2 = _pairs(p, z1, z2, 0.0, None, n, shift)
    a = (r1 + r2) * gap
    v2 = _shifted(v2, a)
    ph1 = shift + np.arange(n) * (2 * np.pi / z1) / n
    ph2 = np.arange(n) * (2 * np.pi / z2) / n
    s1, s2 = edge_sums(v1), edge_sums(v2)
    searched = bridge_perimeters(v1, v2, s1, s2, r1, r2, a, vertices=True)
    nearest = bridge_perimeters(v1, v2, s1, s2, r1, r2, a, vertices=True, regular=(ph1, z1, ph2, z2))
    np.testing.assert_allclose(nearest[0], searched[0], rtol=1e-15, atol=0)
    np.testing.assert_allclose(nearest[0], _hull_perimeters(v1, v2), rtol=1e-13, atol=0)


def test_loop_length_with_fixed_spans_equals_computing_every_span():
    from chaindrive.layout.wrap import _loop_length, _span_scalar

    rng = np.random.default_rng(5)
    for _ in range(200):
        n = int(rng.integers(3, 8))
        ang = np.sort(rng.uniform(0, 2 * np.pi, n))
        c = np.stack([np.cos(ang), np.sin(ang)], 1) * rng.uniform(1.0, 2.0, n)[:, None]
        r, s = rng.uniform(0.05, 0.2, n).tolist(), [1.0] * n
        xs, ys = c[:, 0].tolist(), c[:, 1].tolist()
        k = int(rng.integers(0, n))
        rho = [a * b for a, b in zip(s, r, strict=True)]
        fixed = [None if i in ((k - 1) % n, k) else _span_scalar(xs, ys, rho, i) for i in range(n)]
        xs[k] += 0.01
        assert _loop_length(xs, ys, r, s, fixed) == _loop_length(xs, ys, r, s)


@pytest.mark.parametrize("centres, radii, sides, match", [
    ([0.0489, np.inf], [[0.1, 0.1]], [1, 1], r"centres must be finite \[m\] with shape \(n, 2\)"),
    ([[0, 0], [1, np.inf]], [[0.1, 0.1]], [1, 1], r"centres must be finite"),
    ([[0, 0], [1, 0]], [0.1, 0.1, 0.1, 0.1, 0.1], [1, 1], r"radii must have shape \(m, 2\)"),
    ([[0, 0], [1, 0]], [[0.1, -0.1]], [1, 1], r"radii"),
    ([[0, 0], [1, 0]], [[0.1, 0.1]], [1, 0], r"sides must be \+1 or -1 for each of the 2 wheels"),
])
def test_span_lengths_refuses_bad_shapes(centres, radii, sides, match):
    # found by the API fuzz (tests/test_public_api_finite.py): a 1-D centres or radii broadcast wrongly
    from chaindrive.layout.wrap import span_lengths

    with pytest.raises(InputError, match=match):
        span_lengths(np.array(centres, float), np.array(radii, float), np.array(sides, float))
