"""The scalar fast paths of the layout solvers give the array paths' results bit for bit."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from chaindrive.errors import InputError
from chaindrive.layout import catenary_sag, tension_for_sag
from chaindrive.layout.two_wheels import _abs_cos_primitive, _hull_perimeter, _polygon_links
from test_batch_parts import _equal_to_analyze_drive, _roller


@settings(max_examples=60, deadline=None)
@given(chord=st.floats(0.05, 20.0), incl=st.floats(-1.4, 1.4), ratio=st.floats(1e-4, 0.3),
       q=st.floats(0.1, 100.0))
def test_tension_for_sag_scalar_equals_array(chord, incl, ratio, q):
    one = tension_for_sag(chord, incl, ratio * chord, q)
    arr = tension_for_sag(np.array([chord, chord]), np.array([incl, incl]), np.array([ratio * chord] * 2), q)
    assert isinstance(one, np.floating) and np.ndim(one) == 0
    assert float(one) == float(arr[0]) == float(arr[1])
    back = float(catenary_sag(chord, incl, float(one), q))
    assert back == pytest.approx(ratio * chord, rel=1e-7)  # the bisection's own accuracy


def test_tension_for_sag_scalar_refuses_bad_sag():
    with pytest.raises(InputError, match="sag must be positive"):
        tension_for_sag(2.0, 0.0, -0.01, 2.6)


def test_abs_cos_primitive_with_given_sine_is_the_same():
    x = np.linspace(-20.0, 20.0, 4001)
    assert np.array_equal(_abs_cos_primitive(x), _abs_cos_primitive(x, np.sin(x)))
    # reference: 2m + (-1)^m sin x with the parity from m % 2
    m = np.floor((x + np.pi / 2) / np.pi)
    assert np.array_equal(_abs_cos_primitive(x), 2.0 * m + np.where(m % 2 == 0, 1.0, -1.0) * np.sin(x))
    # a primitive of |cos|: its derivative
    h = 1e-6
    assert np.allclose((_abs_cos_primitive(x + h) - _abs_cos_primitive(x - h)) / (2 * h), np.abs(np.cos(x)),
                       atol=1e-6)


@pytest.mark.parametrize("z1,z2,a,d", [(17, 57, 0.9, None), (25, 57, 1.2, None), (8, 8, 2.0, 0.018)])
def test_polygon_links_equal_qhull(z1, z2, a, d):
    from chaindrive.layout.two_wheels import _phase_vertices, _shifted

    p = 0.0254 if d is None else 0.064
    ph1, ph2, X = _polygon_links(p, z1, z2, a, d, 3)
    v1, v2 = _phase_vertices(p, z1, ph1, d), _shifted(_phase_vertices(p, z2, ph2, d), a)
    for i in range(3):
        for j in range(3):
            ref = _hull_perimeter(np.concatenate([v1[i], v2[j]])) / p
            assert X[i, j] == pytest.approx(ref, rel=1e-12)


def test_grid_memo_returns_the_polygon_grid_and_stays_small():
    from chaindrive.layout.two_wheels import _GRIDS, _grid_at

    for a in (0.8, 0.9, 1.0, 1.1, 1.2, 0.8):
        got = _grid_at(0.0254, 19, 57, a, None, 4)
        ref = _polygon_links(0.0254, 19, 57, a, None, 4)
        assert all(np.array_equal(x, y) for x, y in zip(got, ref, strict=True))
        assert len(_GRIDS.grids) <= 4


def test_centre_distance_polygon_fits_the_links_at_both_roots():
    from chaindrive.layout import centre_distance_polygon

    r = centre_distance_polygon(0.0254, 19, 57, 120, phases=6)
    assert _polygon_links(0.0254, 19, 57, r.taut, None, 6)[2].max() == pytest.approx(120, abs=1e-8)
    assert _polygon_links(0.0254, 19, 57, r.loose, None, 6)[2].min() == pytest.approx(120, abs=1e-8)


@settings(max_examples=4, deadline=None)
@given(st.lists(st.tuples(st.integers(17, 25), st.floats(0.9, 1.2), st.floats(0.0, 0.06)), min_size=2, max_size=4))
def test_varying_geometry_variants_equal_analyze_drive(variants):
    # the study benchmark's varying geometry: teeth, centre distance and skew; every layout
    # solved per variant by the solvers above, equal to the analysis of each variant's drive
    changes = [{("wheels", 0, "teeth"): z, ("wheels", 1, "position"): (a, 0.0), ("contact", "skew"): s}
               for z, a, s in variants]
    _equal_to_analyze_drive(_roller(), changes)


def test_varying_geometry_errors_are_each_variants_own():
    # a centre distance inside the larger wheel: that variant's own error, the others' results
    changes = [{("wheels", 0, "teeth"): 19, ("wheels", 1, "position"): (a, 0.0)} for a in (1.0, 0.05, 1.1)]
    out = _equal_to_analyze_drive(_roller(), changes, include=["layout", "loads"])
    assert isinstance(out[1], Exception) and not isinstance(out[0], Exception)


@settings(max_examples=60, deadline=None)
@given(chord=st.floats(0.05, 20.0), incl=st.floats(-1.4, 1.4), ratio=st.floats(1e-5, 0.3),
       q=st.floats(0.1, 100.0))
def test_tension_for_sag_stops_where_the_100_halvings_end(chord, incl, ratio, q):
    # the bisection stops once lo and hi are adjacent floats; the full 100 halvings of the
    # documented method (written out here) end on the same number, bit for bit
    from chaindrive.layout.sag import _catenary_parts, _catenary_sag

    span, rise, w = _catenary_parts(chord, incl, 1.0, q, 9.80665)
    f = ratio * chord
    H0 = w * span**2 / (8.0 * f)
    lo, hi = np.log(H0) - 15.0 * np.log(10.0), np.log(H0) + 15.0 * np.log(10.0)
    with np.errstate(all="ignore"):  # as the guarded function (a far halving may overflow)
        for _ in range(100):
            mid = 0.5 * (lo + hi)
            if _catenary_sag(span, rise, w / np.exp(mid)) > f:
                lo = mid
            else:
                hi = mid
    assert float(tension_for_sag(chord, incl, f, q)) == float(np.exp(0.5 * (lo + hi)))
    both = tension_for_sag(np.array([chord, chord]), np.array([incl, incl]), np.array([f, f]), q)
    assert float(both[0]) == float(np.exp(0.5 * (lo + hi)))


def test_log_tension_near_holds_the_root_or_declines():
    # the Python-float root the bisection skips its far halvings by: within 2e-12 of the
    # sag's root where it answers (tension_for_sag is then bit-equal to the full bisection,
    # tested above); None for a nearly straight span whose sag loses its digits
    from chaindrive.layout.sag import _catenary_parts, _log_tension_near, _sag_at

    span, rise, w = (float(v) for v in _catenary_parts(1.4, 0.2, 1.0, 6.0, 9.80665))
    for ratio, answers in ((0.02, True), (0.3, True), (1e-6, False)):
        f = ratio * 1.4
        t0 = math.log(w * span**2 / (8.0 * f))
        t = _log_tension_near(t0 - 34.5, t0 + 34.5, span, rise, w, f)
        assert (t is not None) == answers
        if t is not None:
            assert _sag_at(t - 2e-12 * abs(t), span, rise, w) > f >= _sag_at(t + 2e-12 * abs(t), span, rise, w)
