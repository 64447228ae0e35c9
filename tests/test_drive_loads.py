"""Tests of chaindrive.loads and chaindrive.life.wear."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from chaindrive import loads as F
from chaindrive.errors import InputError, UnknownNameError
from chaindrive.life import wear as W

RPM = 2 * math.pi / 60


def test_torque_power_roundtrip_and_arrays():
    P = np.array([1e3, 15e3])
    T = F.torque_from_power(P, 960 * RPM)
    assert np.allclose(F.power_from_torque(T, 960 * RPM), P)
    # 15 kW at 960 rpm: T = 9549.3 · 15 / 960 = 149.208 N·m (the "9550 P/n" rule)
    assert float(T[1]) == pytest.approx(9549.2966 * 15 / 960, rel=1e-7)


def test_chain_speed_and_pull():
    # v = z p n: 19 · 25.4 mm · 16 /s = 7.7216 m/s; pull = T/R
    v = F.chain_speed(0.0254, 19, 960 * RPM)
    assert float(v) == pytest.approx(19 * 0.0254 * 16, rel=1e-12)
    R = 0.0254 / (2 * math.sin(math.pi / 19))
    # power balance: pull · mean speed = torque · ω only on average; with the pitch
    # radius F v = T ω · (z p / 2πR) = T ω · sin(π/z)/(π/z)
    Ft = F.tight_side_tension(149.208, R)
    assert float(Ft * v) == pytest.approx(149.208 * 960 * RPM * math.sin(math.pi / 19) / (math.pi / 19), rel=1e-6)


def test_centrifugal_tension_from_element_balance():
    # independent: radial balance of an arc element, F dθ = (q R dθ) v²/R
    q, v, R, dth = 2.6, 7.7, 0.3, 1e-3
    m = q * R * dth
    assert float(F.centrifugal_tension(q, v)) == pytest.approx(m * v**2 / R / dth, rel=1e-12)


def test_free_entry_acceleration_by_finite_differences():
    # v(t) = ω R cos(ω t - δ/2) over one period; its largest |dv/dt| by central
    # differences equals ω² R sin(δ/2) (attained at the period ends)
    w, z, p = 30.0, 11, 0.0254
    R = p / (2 * math.sin(math.pi / z))
    half = math.pi / z
    t = np.linspace(0, 2 * half / w, 20001)
    v = w * R * np.cos(w * t - half)
    a = np.gradient(v, t, edge_order=2)
    assert float(F.free_entry_acceleration_peak(w, R, half)) == pytest.approx(np.max(np.abs(a)), rel=1e-6)
    # roller chain: = ω² p / 2
    assert float(F.free_entry_acceleration_peak(w, R, half)) == pytest.approx(w * w * p / 2, rel=1e-12)


def test_dynamic_factor_and_safety():
    assert float(F.dynamic_tension(8.0, 128.0)) == 1024.0
    assert float(F.dynamic_factor(2000.0, 500.0)) == 1.25
    assert float(F.static_safety_factor(60e3, 3000.0)) == 20.0


def test_shaft_load_vector_sum():
    m, a = F.shaft_load([[1000.0, 100.0], [1.0, 1.0]], [[0.0, math.pi / 2], [0.0, math.pi]])
    assert m[0] == pytest.approx(math.hypot(1000, 100))
    assert a[0] == pytest.approx(math.atan2(100, 1000))
    assert m[1] == pytest.approx(0.0, abs=1e-12)


def test_service_factor_table():
    # Shigley, 9th ed., Table 17-15 (ACA)
    assert F.service_factor() == 1.0
    assert F.service_factor("heavy", "ic_mechanical") == 1.7
    assert F.service_factor("moderate", "ic_hydraulic") == 1.2
    with pytest.raises(UnknownNameError, match="unknown load character 'shock'"):
        F.service_factor("shock")
    with pytest.raises(UnknownNameError, match="unknown driver 'diesel'"):
        F.service_factor("smooth", "diesel")


def test_load_errors():
    with pytest.raises(InputError, match="power must be non-negative"):
        F.torque_from_power(-1, 10)
    with pytest.raises(InputError, match="angular_velocity must be positive"):
        F.torque_from_power(1, 0)
    with pytest.raises(InputError, match="pitch_radius must be positive"):
        F.tight_side_tension(1, 0)
    with pytest.raises(InputError, match="chain_speed must be non-negative"):
        F.centrifugal_tension(1, -1)
    with pytest.raises(InputError, match="half_angle must lie in"):
        F.free_entry_acceleration_peak(1, 1, 2.0)
    with pytest.raises(InputError, match="tension must be positive"):
        F.dynamic_factor(0, 1)
    with pytest.raises(InputError, match="breaking_force must be positive"):
        F.static_safety_factor(0, 1)


@settings(max_examples=30, deadline=None)
@given(w=st.floats(0.1, 200), R=st.floats(0.01, 1), z=st.integers(3, 60))
def test_acceleration_peak_scales_with_omega_squared(w, R, z):
    a1 = float(F.free_entry_acceleration_peak(w, R, math.pi / z))
    a2 = float(F.free_entry_acceleration_peak(2 * w, R, math.pi / z))
    assert a2 == pytest.approx(4 * a1, rel=1e-12)


# ---------------------------------------------------------------- wear
def test_rating_basis_reproduced():
    # at the basis (rated power, 100 pitches, two wheels, 3 %): 15 000 h
    assert float(W.hours_to_elongation_rating(5e3, 5e3, 100)) == pytest.approx(15000.0)
    # Archard: half the load, double the life; longer chain, proportionally longer
    assert float(W.hours_to_elongation_rating(5e3, 2.5e3, 100)) == pytest.approx(30000.0)
    assert float(W.hours_to_elongation_rating(5e3, 5e3, 150)) == pytest.approx(22500.0)
    assert float(W.hours_to_elongation_rating(5e3, 5e3, 100, elongation_limit=0.02)) == pytest.approx(10000.0)
    assert float(W.hours_to_elongation_rating(5e3, 5e3, 100, wheels=4)) == pytest.approx(7500.0)


def test_wear_life_linear_and_models():
    w = W.wear_life("rating", rated_power=10e3, power=5e3, links=120)
    assert w.hours_to_limit == pytest.approx(36000.0)
    i = np.searchsorted(w.hours, w.hours_to_limit)
    assert np.interp(w.hours_to_limit, w.hours, w.elongation) == pytest.approx(0.03)
    assert i > 0
    a = W.wear_life("archard", tension=2000, bearing_area=1e-4, joint_radius=0.004, teeth=19,
                    chain_speed=5.0, links=120, pitch=0.0254, wear_coefficient=1e-16,
                    hours=[0, 1000])
    rate = float(W.elongation_rate_archard(2000, 1e-4, 0.004, 19, 5.0, 120, 0.0254, 1e-16))
    assert a.hours_to_limit == pytest.approx(0.03 / rate)
    assert a.elongation[1] == pytest.approx(1000 * rate)


def test_archard_hand_value():
    # f = 2·2·5/(120·0.0254)·3600 = 23622.05 /h; e' = (2/p) k (F/A) r (2π/z) f
    f = 2 * 2 * 5.0 / (120 * 0.0254) * 3600
    hand = 2 / 0.0254 * 1e-16 * 2000 / 1e-4 * 0.004 * (2 * math.pi / 19) * f
    assert float(W.elongation_rate_archard(2000, 1e-4, 0.004, 19, 5.0, 120, 0.0254, 1e-16)) == pytest.approx(hand)


def test_wear_errors():
    with pytest.raises(UnknownNameError, match="unknown wear model 'iso'"):
        W.wear_life("iso", rated_power=1, power=1, links=1)
    with pytest.raises(InputError, match="wear model 'rating' needs power"):
        W.wear_life("rating", rated_power=1, links=100)
    with pytest.raises(InputError, match=r"elongation_limit must lie in \(0, 0.1\]"):
        W.hours_to_elongation_rating(1, 1, 100, elongation_limit=0.2)
    with pytest.raises(InputError, match="rated_power must be positive"):
        W.hours_to_elongation_rating(0, 1, 100)


def test_wear_scalar_vs_array():
    P = np.array([2e3, 5e3, 10e3])
    arr = W.hours_to_elongation_rating(10e3, P, 120)
    assert arr.shape == (3,)
    assert np.allclose(arr, [float(W.hours_to_elongation_rating(10e3, p, 120)) for p in P])
    assert np.all(np.diff(arr) < 0)  # more load, shorter life


# ---------------------------------------------------------------- power split to several wheels


def test_span_tensions_with_a_power_split():
    # statics by hand: slack 100 N leaves the driving wheel 0; wheel 1 takes 40 %, wheel 2
    # 60 % of F_e = 1000 N, so the spans carry 100, 500, 1100 N (ccw) ...
    from chaindrive.analysis.loads import span_tensions

    shares = np.array([0.0, 0.4, 0.6])
    assert span_tensions(1000.0, 100.0, shares, 0).tolist() == pytest.approx([100, 500, 1100])
    # ... and running clockwise the chain leaves wheel 0 along span 2, meets wheel 2 (+600 N),
    # runs back along span 1, meets wheel 1 (+400 N) and arrives along span 0
    assert span_tensions(1000.0, 100.0, shares, 0, "cw").tolist() == pytest.approx([1100, 700, 100])
    # one driven wheel: the two-wheel tight/slack pair
    assert span_tensions(1000.0, 100.0, np.array([0.0, 1.0]), 0).tolist() == pytest.approx([100, 1100])


def test_shaft_loads_of_a_multi_wheel_drive_balance():
    # independent: the chain loop is in equilibrium, so the shaft loads (the chain's pull on
    # each wheel) sum to zero as vectors; the largest span carries F_e + S_slack
    from chaindrive.analysis import analyze_drive
    from chaindrive.drive import load_project

    drive = load_project(Path(__file__).resolve().parents[1] / "examples" / "multi_wheel.toml")
    t = analyze_drive(drive, include=["loads"]).loads
    fx = np.sum(t.shaft_loads * np.cos(t.shaft_load_angles))
    fy = np.sum(t.shaft_loads * np.sin(t.shaft_load_angles))
    assert math.hypot(fx, fy) < 1e-9 * t.tight
    assert max(t.span_tensions) == pytest.approx(t.effective_pull + t.slack, rel=1e-12)
    assert t.wheel_powers.sum() == pytest.approx(0.0, abs=1e-6)  # the power delivered is taken off
    assert t.wheel_powers[2] == pytest.approx(-0.6 * drive.power())
