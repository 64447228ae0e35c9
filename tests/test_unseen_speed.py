"""The shortcuts that make the analysis of a drive never seen faster (issue 33) give the same
numbers as the computations they replace, bit for bit:

* the seating scan of the entry kinematics starts next to the estimate
  (:func:`chaindrive.kinematics.solver._find_crossing`) and brackets the same root as the
  whole 1441-point scan;
* :func:`~chaindrive.kinematics.solver.taut_entry` evaluates the angles asked for and
  ``φ = 0`` in one pass: pointwise, the same as one angle at a time;
* the root search's gap in Python floats equals numpy's;
* the kept wrap layouts, bi-regular polygons, drive speeds and track-wheel dimensions equal
  fresh ones, are not shared with a caller, and :func:`chaindrive.analysis._memo.clear`
  empties them.

The references are the full computations themselves (run here without the shortcut).
"""

from __future__ import annotations

import dataclasses
import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from _shared import EXAMPLES
from chaindrive._roots import brentq
from chaindrive.analysis import _memo, analyze_drive
from chaindrive.drive import load_project
from chaindrive.drive import model as drive_model
from chaindrive.errors import InfeasibleError, InputError
from chaindrive.geometry import polygon
from chaindrive.geometry.track_wheel import TrackDriveWheel
from chaindrive.kinematics import solver
from chaindrive.layout import wrap
from chaindrive.layout.wrap import wrap_layout


def _polygon(z, radius, phase, split):
    """A regular (``split`` None) or bi-regular pitch polygon of ``z`` teeth."""
    if split is None:
        d = 2 * np.pi / z
        return solver.WheelPolygon(radius, (2 * radius * np.sin(d / 2),), (d,), phase * d)
    a1 = split * 2 * np.pi / z
    a2 = 2 * np.pi / z - a1
    return solver.WheelPolygon(radius, (2 * radius * np.sin(a1 / 2), 2 * radius * np.sin(a2 / 2)), (a1, a2),
                               phase * a1)


def _full_scan_crossing(fun, estimate, what):
    """_find_crossing as it was: the whole 1441-point scan, then Brent's method."""
    grid = estimate + np.linspace(-0.5 * np.pi, 0.5 * np.pi, 1441)
    g = fun(grid)
    idx = np.nonzero((g[:-1] > 0) & (g[1:] <= 0))[0]
    if idx.size == 0:
        raise InfeasibleError(f"no seating of {what} found")
    i = idx[np.argmin(np.abs(grid[idx] - estimate))]
    if g[i + 1] == 0.0:
        return float(grid[i + 1])
    return float(brentq(fun, grid[i], grid[i + 1], xtol=1e-15, rtol=1e-15, maxiter=200))


_wheels = st.tuples(st.integers(5, 60), st.floats(0.02, 0.6), st.floats(0.0, 0.999),
                    st.one_of(st.none(), st.floats(0.3, 0.7)),
                    st.one_of(st.none(), st.tuples(st.floats(1.05, 5.0), st.floats(0.0, 1.0))))


@settings(max_examples=150, deadline=None)
@given(_wheels)
def test_seatings_equal_those_of_the_whole_scan(wheel):
    z, radius, phase, split, guide_rel = wheel
    poly = _polygon(z, radius, phase, split)
    guide = None if guide_rel is None else (radius * guide_rel[0], radius * guide_rel[1])
    try:
        fast = solver.taut_seating_angles(poly, guide)
    except InfeasibleError as exc:
        fast = str(exc)
    original = solver._find_crossing
    solver._find_crossing = _full_scan_crossing
    try:
        reference = solver.taut_seating_angles(poly, guide)
    except InfeasibleError as exc:
        reference = str(exc)
    finally:
        solver._find_crossing = original
    if isinstance(reference, str) or isinstance(fast, str):
        assert isinstance(fast, str) and isinstance(reference, str)
    else:
        assert np.array_equal(fast, reference)


@settings(max_examples=60, deadline=None)
@given(_wheels, st.integers(0, 2**31 - 1))
def test_taut_entry_is_pointwise(wheel, seed):
    z, radius, phase, split, guide_rel = wheel
    poly = _polygon(z, radius, phase, split)
    guide = None if guide_rel is None else (radius * guide_rel[0], radius * guide_rel[1])
    try:
        seats = solver.taut_seating_angles(poly, guide)
    except InfeasibleError:
        return
    phi = np.random.default_rng(seed).uniform(-1.0, 2.0, 57)
    whole = solver.taut_entry(poly, phi, 3.0, guide, seats)
    for i in (0, 13, 56):
        one = solver.taut_entry(poly, phi[i:i + 1], 3.0, guide, seats)
        for name in ("x", "velocity", "acceleration", "y", "vy", "ay", "k") + (() if guide is None else ("span",)):
            assert getattr(one, name)[0] == getattr(whole, name)[i], name
    if guide is not None:  # the reach check's span alone
        assert np.array_equal(solver._taut_span_length(poly, phi, guide, seats), whole.span)
    # x is measured from φ = 0, exactly; a scalar angle gives 0-d arrays
    assert solver.taut_entry(poly, 0.0, 3.0, guide, seats).x == 0.0
    assert solver.taut_entry(poly, 0.3, 3.0, guide, seats).velocity.shape == ()
    assert solver.taut_entry(poly, phi.reshape(3, 19), 3.0, guide, seats).acceleration.shape == (3, 19)


@settings(max_examples=80, deadline=None)
@given(_wheels, st.floats(-2.0, 2.0))
def test_the_root_search_gap_in_floats_equals_numpys(wheel, phi):
    z, radius, phase, split, guide_rel = wheel
    poly = _polygon(z, radius, phase, split)
    guide = None if guide_rel is None else (radius * guide_rel[0], radius * guide_rel[1])
    angles = (poly.vertex(2)[0], poly.vertex(3)[0])
    assert solver._taut_gap(poly, 2, phi, guide, angles) == solver._taut_gap(poly, 2, np.array([phi]), guide,
                                                                              angles)[0]


def test_a_kept_wrap_layout_is_a_copy():
    c = np.array([[0.0, 0.0], [1.0, -0.5], [2.0, 0.0], [1.0, 0.5]])
    r = np.array([0.3, 0.2, 0.2, 0.3])
    wrap._KEPT.clear()
    first = wrap_layout(c, r)
    first.span_length[0] = -1.0  # a caller's change of its own copy
    c[0, 0] = 0.0  # the same inputs
    second = wrap_layout(c, r)
    wrap._KEPT.clear()
    fresh = wrap_layout(c, r)
    for f in dataclasses.fields(fresh):
        assert np.array_equal(getattr(second, f.name), getattr(fresh, f.name)), f.name
    assert second.span_length is not fresh.span_length
    assert second.span_length[0] > 0
    moved = c.copy()
    moved[1, 1] = -0.6
    assert wrap_layout(moved, r).length != fresh.length


def test_a_kept_polygon_equals_a_computed_one_and_errors_are_raised_each_time():
    polygon._bi_regular_kept.cache_clear()
    kept = polygon.bi_regular_polygon(0.082, 0.046, 8)
    again = polygon.bi_regular_polygon(0.082, 0.046, 8)
    computed = polygon._bi_regular(0.082, 0.046, 8)
    assert kept == again == computed
    assert polygon.bi_regular_polygon(np.array([0.082]), 0.046, 8)[0][0] == computed[0]
    # 0-d arrays (what the input checks return) are kept by their value: the same numbers
    zero_d = polygon.bi_regular_polygon(np.asarray(0.082), np.asarray(0.046), np.asarray(8))
    assert zero_d == computed and polygon._bi_regular_kept.cache_info().hits >= 2
    assert polygon.link_chain_pitch_radius(0.064, 0.018, 8) == polygon._bi_regular(0.082, 0.046, 8)[0]
    for _ in range(2):
        with pytest.raises(InputError, match="short_side must not exceed long_side"):
            polygon.bi_regular_polygon(0.04, 0.046, 8)


def test_the_drive_speeds_kept_equal_the_formulas_and_clear_empties_every_new_store():
    drive = load_project(EXAMPLES / "roller_industrial.toml")
    analyze_drive(drive, exclude=["remedy"])
    assert drive_model._mean_chain_speed.cache_info().currsize > 0
    from chaindrive.loads import mean_chain_speed, sides_per_turn

    w = drive.driving_wheel
    assert drive.chain_speed() == float(mean_chain_speed(sides_per_turn(w.teeth, False), drive.pitch, drive.speed))
    _memo.clear()
    for cached in (*drive_model.DERIVED_CACHES, polygon._bi_regular_kept):
        assert cached.cache_info().currsize == 0
    assert not wrap._KEPT


def test_track_wheel_dimensions_follow_a_changed_field_and_replay_their_warnings():
    w = TrackDriveWheel(pitch=0.17, teeth=13, pin_radius=0.025, link="cast")
    first = w.dimensions()
    assert w.dimensions() is first
    w.teeth = 15
    assert w.dimensions().teeth == 15
    assert w.dimensions().pitch_radius == TrackDriveWheel(pitch=0.17, teeth=15, pin_radius=0.025,
                                                          link="cast").dimensions().pitch_radius
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        original = TrackDriveWheel._dimensions

        def warned(self):
            warnings.warn("outside", UserWarning, stacklevel=2)
            return original(self)

        TrackDriveWheel._dimensions = warned
        try:
            v = TrackDriveWheel(pitch=0.17, teeth=13, pin_radius=0.025)
            v.dimensions()
            v.dimensions()
        finally:
            TrackDriveWheel._dimensions = original
    assert [str(c.message) for c in caught] == ["outside", "outside"]


@pytest.mark.parametrize("name", ["roller_industrial", "mining_conveyor", "tractor_track"])
def test_never_seen_analysis_equals_a_reused_one(name):
    """The measure of benchmarks/analyze.py (every store emptied before) against a reused analysis."""
    drive = load_project(EXAMPLES / f"{name}.toml")
    last = drive.wheels[-1]
    moved = drive.with_wheel(last.name, position=(last.position[0] + 0.0073, last.position[1]))
    _memo.clear()
    fresh = analyze_drive(moved, exclude=["remedy"]).to_dict()
    again = analyze_drive(moved, exclude=["remedy"]).to_dict()
    assert repr(fresh) == repr(again)


def test_span_response_of_repeated_frequencies_equals_each_alone():
    from chaindrive.vibration.excitation import _span_response
    from chaindrive.vibration.resonance import TensionerSpan

    span = TensionerSpan(2000.0, 2.6, 0.8, 1.1, 0.3, 0.25, 3.0, 5e4)
    om = np.array([40.0, 1e-5, 77.0, 1e-5, 40.0, 1e-5])
    y = np.array([1e-3, 1e-3, 2e-4, 2e-4, 5e-4, 5e-4])
    mass, stiffness = np.array([3.0, 5.0]), np.array([5e4, 8e4])
    w, u = _span_response(span, om, y, y, 0.02, 101, mass, stiffness)
    for i in range(om.size):
        wi, ui = _span_response(span, om[i:i + 1], y[i:i + 1], y[i:i + 1], 0.02, 101, mass, stiffness)
        assert np.array_equal(w[:, i], wi[:, 0]) and np.array_equal(u[:, i], ui[:, 0])
