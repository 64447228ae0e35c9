"""Tests of the pocket wheel (Dolipiński et al.) and the track drive wheel (Sharipov)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.optimize import brentq

from chaindrive.errors import InfeasibleError, InputError, UnknownNameError
from chaindrive.geometry import (
    PocketWheel,
    TrackDriveWheel,
    pin_seat_radius_range,
    pocket_angles,
    root_radius,
    root_radius_range,
    tip_radius,
    tip_radius_range,
    track_wheel_pitch_radius,
)
from chaindrive.geometry.outline import Arc

T, D = 0.064, 0.018  # chain 18x64 (Dolipiński et al. worked case)


# ----------------------------------------------------------------- pocket wheel
def _radius_numeric(t, d, z):
    # independent: R such that the two chords t+d and t-d subtend 2π/z together
    f = lambda r: 2 * math.asin((t + d) / (2 * r)) + 2 * math.asin((t - d) / (2 * r)) - 2 * math.pi / z  # noqa: E731
    return brentq(f, (t + d) / 2 * (1 + 1e-12), 100 * t, xtol=1e-15)


@pytest.mark.parametrize("z", [3, 5, 8, 12])
def test_pocket_wheel_pitch_radius_numeric(z):
    w = PocketWheel(T, D, z)
    assert w.dimensions().pitch_radius == pytest.approx(_radius_numeric(T, D, z), rel=1e-12)


def test_pocket_wheel_18x64_z8_regression_and_positions():
    d = PocketWheel(T, D, 8).dimensions()
    assert d.pitch_radius == pytest.approx(0.1642830686421091, rel=1e-12)
    assert d.central_angle_horizontal + d.central_angle_vertical == pytest.approx(2 * math.pi / 8)
    # hinge centres: alternate chords t+d and t-d, all on the pitch circle
    pk, hg, vt = pocket_angles(T, D, 8)
    pts = d.pitch_radius * np.stack([np.cos(hg), np.sin(hg)], axis=-1)
    chords = np.hypot(*(np.roll(pts, -1, axis=0) - pts).T)
    assert chords[0::2] == pytest.approx(np.full(8, T + D), abs=1e-12)
    assert chords[1::2] == pytest.approx(np.full(8, T - D), abs=1e-12)
    assert np.degrees(pk) == pytest.approx(np.mod(90 + 45 * np.arange(8), 360))
    assert np.degrees(vt) == pytest.approx(np.mod(90 + 22.5 + 45 * np.arange(8), 360))
    assert d.pocket_floor_distance == pytest.approx(d.pitch_radius * math.cos(d.central_angle_horizontal / 2) - D / 2)


def test_pocket_wheel_outline():
    w = PocketWheel(T, D, 8, clearance=0.5e-3)
    o = w.outline()
    d = w.dimensions()
    assert o.closure_gap() < 1e-12
    assert o.area() > 0
    assert len(o.centres) == 16
    assert np.all(np.abs(np.hypot(*o.centres.T) - d.pitch_radius) < 1e-6)
    r = np.hypot(*o.polyline(32).T)
    assert r.min() == pytest.approx(d.pocket_floor_distance, abs=1e-9)
    assert r.max() == pytest.approx(d.tip_radius, abs=1e-9)
    floors = [p for p in o.primitives if not isinstance(p, Arc) and abs(p.start[1] - p.end[1]) < 1e-15
              and abs(p.start[1] - d.pocket_floor_distance) < 1e-12]
    assert len(floors) >= 2  # the pocket at +y has its two half floors


def test_pocket_wheel_from_chain_catalogue():
    chains = pytest.importorskip("chaindrive.chains")
    if not hasattr(chains, "get"):
        pytest.skip("chain catalogue not available")
    w = PocketWheel.from_chain("18x64", 8)
    assert w.dimensions().pitch_radius == pytest.approx(0.1642830686421091, rel=1e-12)
    with pytest.raises(InputError, match="no bar_diameter"):
        PocketWheel.from_chain("16B", 8)


def test_pocket_wheel_errors():
    with pytest.raises(InputError, match="bar_diameter must be smaller than pitch"):
        PocketWheel(0.018, 0.018, 8)
    with pytest.raises(InputError, match="teeth must be a whole number >= 3"):
        PocketWheel(T, D, 2)
    with pytest.raises(InputError, match="clearance must be non-negative"):
        PocketWheel(T, D, 8, clearance=-1e-3)
    with pytest.raises(InputError, match="tip_radius must exceed"):
        PocketWheel(T, D, 8, tip_radius=0.1).outline()
    with pytest.raises(InfeasibleError, match="pockets overlap"):
        PocketWheel(T, D, 8, clearance=0.02).outline()
    with pytest.raises(InfeasibleError, match="slot bottom radius"):
        PocketWheel(T, D, 3, inner_width=0.2).outline()


# ----------------------------------------------------------------- track drive wheel
def test_track_wheel_sharipov_ranges():
    # Sharipov: r_цо = (1.1...1.3) r_ц, R_В = R_о − r_цо, R_Г = R_о + (0.2...0.5) r_ц built-up,
    # (0.8...1.2) r_ц cast. Example: t = 170 mm, z = 13, r_ц = 25 mm.
    r0 = float(track_wheel_pitch_radius(0.17, 13))
    assert r0 == pytest.approx(0.17 / (2 * math.sin(math.pi / 13)))
    assert np.array(pin_seat_radius_range(0.025)) == pytest.approx([0.0275, 0.0325])
    assert np.array(root_radius_range(r0, 0.025)) == pytest.approx([r0 - 0.0325, r0 - 0.0275])
    assert np.array(tip_radius_range(r0, 0.025, "built-up")) == pytest.approx([r0 + 0.005, r0 + 0.0125])
    assert np.array(tip_radius_range(r0, 0.025, "cast")) == pytest.approx([r0 + 0.020, r0 + 0.030])
    assert float(root_radius(r0, 0.03)) == pytest.approx(r0 - 0.03)
    assert float(tip_radius(r0, 0.025, 1.0, "cast")) == pytest.approx(r0 + 0.025)


def test_track_wheel_scalar_vs_array():
    r = np.array([0.02, 0.025, 0.03])
    lo, hi = tip_radius_range(0.355, r, "cast")
    for i, ri in enumerate(r):
        assert float(tip_radius_range(0.355, ri, "cast")[1]) == hi[i]
    assert float(track_wheel_pitch_radius(0.17, np.array([13]))[0]) == float(track_wheel_pitch_radius(0.17, 13))


@pytest.mark.parametrize("link", ["built-up", "cast"])
def test_track_wheel_outline(link):
    w = TrackDriveWheel(0.17, 13, 0.025, link=link)
    o = w.outline()
    d = w.dimensions()
    assert o.closure_gap() < 1e-12
    assert len(o.centres) == 13
    assert np.all(np.abs(np.hypot(*o.centres.T) - d.pitch_radius) < 1e-6)
    r = np.hypot(*o.polyline(48).T)
    assert r.min() == pytest.approx(d.root_radius, abs=1e-9)
    assert not d.tooth_pointed
    assert r.max() == pytest.approx(d.tip_radius, abs=1e-9)
    # seat arcs (radius r_цо) centred on the pins
    seats = [p for p in o.primitives if isinstance(p, Arc) and abs(p.radius - d.pin_seat_radius) < 1e-12]
    assert len(seats) == 26


def test_track_wheel_pointed_teeth_flag():
    # short pitch vs pin: the flanks meet below R_Г -> reported, outline still closed
    w = TrackDriveWheel(0.07, 9, 0.025, link="cast", root_factor=1.3)
    d = w.dimensions()
    assert d.tooth_pointed
    assert w.outline().closure_gap() < 1e-12
    assert np.hypot(*w.outline().polyline(48).T).max() == pytest.approx(d.pointed_tip_radius, abs=1e-9)


def test_track_wheel_errors():
    with pytest.raises(InputError, match=r"tip_factor must lie in \[0.8, 1.2\] for cast links \(Sharipov"):
        TrackDriveWheel(0.17, 13, 0.025, link="cast", tip_factor=0.5)
    with pytest.raises(InputError, match=r"tip_factor must lie in \[0.2, 0.5\] for built-up links"):
        TrackDriveWheel(0.17, 13, 0.025, tip_factor=1.0)
    with pytest.raises(InputError, match=r"root_factor must lie in \[1.1, 1.3\]"):
        TrackDriveWheel(0.17, 13, 0.025, root_factor=1.0)
    with pytest.raises(UnknownNameError, match="unknown link 'welded'; valid: 'built-up', 'cast'"):
        TrackDriveWheel(0.17, 13, 0.025, link="welded")
    with pytest.raises(InfeasibleError, match="must be < pitch/2"):
        TrackDriveWheel(0.05, 13, 0.025)
    with pytest.raises(InputError, match="pin_radius must be positive"):
        TrackDriveWheel(0.17, 13, 0.0)
    with pytest.raises(InputError, match="pin_seat_radius must be smaller than pitch_radius"):
        root_radius(0.1, 0.2)
    with pytest.raises(InputError, match="tip_factor must lie in"):
        tip_radius(0.355, 0.025, [0.3, 0.6])


@settings(max_examples=30, deadline=None)
@given(
    z=st.integers(min_value=7, max_value=40),
    k_root=st.floats(min_value=1.1, max_value=1.3),
    u=st.floats(min_value=0.0, max_value=1.0),
    link=st.sampled_from(["built-up", "cast"]),
)
def test_property_track_wheel(z, k_root, u, link):
    lo, hi = {"built-up": (0.2, 0.5), "cast": (0.8, 1.2)}[link]
    k_tip = lo + u * (hi - lo)
    w = TrackDriveWheel(0.17, z, 0.025, link=link, root_factor=k_root, tip_factor=k_tip)
    d = w.dimensions()
    assert d.root_radius_range[0] - 1e-12 <= d.root_radius <= d.root_radius_range[1] + 1e-12
    assert d.tip_radius_range[0] - 1e-12 <= d.tip_radius <= d.tip_radius_range[1] + 1e-12
    o = w.outline()
    assert o.closure_gap() < 1e-12
    r = np.hypot(*o.polyline(16).T)
    assert r.min() >= d.root_radius - 1e-12
    assert r.max() <= d.tip_radius + 1e-12


@settings(max_examples=30, deadline=None)
@given(z=st.integers(min_value=4, max_value=20), ratio=st.floats(min_value=0.15, max_value=0.35))
def test_property_pocket_wheel(z, ratio):
    d = ratio * T
    w = PocketWheel(T, d, z)
    dim = w.dimensions()
    assert dim.central_angle_horizontal > dim.central_angle_vertical > 0
    assert dim.pitch_radius == pytest.approx(_radius_numeric(T, d, z), rel=1e-10)
    try:
        o = w.outline()
    except InfeasibleError:
        return
    assert o.closure_gap() < 1e-12


def test_track_wheel_refuses_a_non_finite_elongation_limit():
    # found by `make fuzz` (API surface): a NaN elongation limit was kept in the dimensions
    import math

    from chaindrive.errors import InputError
    from chaindrive.geometry import TrackDriveWheel

    for bad in (float("nan"), math.inf, 0.0, 0.2):
        with pytest.raises(InputError, match=r"elongation_limit must (lie in \(0, 0.1\]|not be NaN)"):
            TrackDriveWheel(pitch=0.1, teeth=12, pin_radius=0.02, elongation_limit=bad)
