"""Tests of chaindrive.strength.fretting (Vikulov): latent period, pin beam."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from chaindrive.errors import InfeasibleError, InputError, UnknownNameError
from chaindrive.strength import MultiRowPin, beam_solve, fretting_comparison, fretting_latent_period

# ---------------------------------------------------------------- latent period


def test_latent_period_formula_and_sign():
    # tau = K1 Ra exp(-k2 A N f / Ra): by hand
    ra, a, n, f, k1, k2 = 0.8e-6, 2e-6, 2e3, 10.0, 1e12, 1e-5
    assert fretting_latent_period(ra, a, n, f, k1, k2) == pytest.approx(k1 * ra * np.exp(-0.5), rel=1e-12)
    # no slip: tau = K1 Ra
    assert fretting_latent_period(ra, 0.0, n, f, k1, k2) == pytest.approx(k1 * ra)


@settings(max_examples=40, deadline=None)
@given(
    a=st.floats(1e-8, 1e-4), n=st.floats(1.0, 1e5), f=st.floats(0.1, 1e3), k=st.floats(1.01, 4.0)
)
def test_latent_period_falls_with_slip_load_frequency(a, n, f, k):
    ra, k1, k2 = 1e-6, 1e12, 1e-9
    t = fretting_latent_period(ra, a, n, f, k1, k2)
    assert fretting_latent_period(ra, a * k, n, f, k1, k2) <= t
    assert fretting_latent_period(ra, a, n * k, f, k1, k2) <= t
    assert fretting_latent_period(ra, a, n, f * k, k1, k2) <= t
    assert t <= k1 * ra


def test_latent_period_errors_and_arrays():
    with pytest.raises(InputError, match=r"decay_coefficient must be positive"):
        fretting_latent_period(1e-6, 1e-6, 1e3, 10, 1e12, -1e-9)
    with pytest.raises(InputError, match=r"roughness must be positive"):
        fretting_latent_period(0.0, 1e-6, 1e3, 10, 1e12, 1e-9)
    with pytest.raises(InputError, match=r"slip_amplitude must be non-negative"):
        fretting_latent_period(1e-6, -1e-6, 1e3, 10, 1e12, 1e-9)
    with pytest.raises(InputError, match=r"latent_coefficient must be positive"):
        fretting_latent_period(1e-6, 1e-6, 1e3, 10, 0.0, 1e-9)
    arr = fretting_latent_period(1e-6, np.array([0.0, 1e-6, 2e-6]), 1e3, 10, 1e12, 1e-5)
    assert arr.shape == (3,) and np.all(np.diff(arr) < 0)
    assert arr[1] == pytest.approx(fretting_latent_period(1e-6, 1e-6, 1e3, 10, 1e12, 1e-5))


# ---------------------------------------------------------------- beam model


def test_beam_simply_supported_point_and_uniform_load():
    # Roark 7th ed. Table 8.1 cases 1e / 2e (simply supported): central point load
    # theta_end = P L^2 / (16 EI), y_max = P L^3 / (48 EI); uniform load
    # theta_end = w L^3 / (24 EI), y_max = 5 w L^4 / (384 EI), M_max = w L^2 / 8.
    L, EI, P = 0.3, 250.0, 1000.0
    s = beam_solve([0.0, L], [(L / 2, L / 2, P)], EI)
    assert s.support_slopes[0] == pytest.approx(P * L**2 / (16 * EI), rel=1e-10)
    assert np.max(np.abs(s.deflection)) == pytest.approx(P * L**3 / (48 * EI), rel=1e-10)
    w = 2000.0
    s = beam_solve([0.0, L], [(0.0, L, w * L)], EI)
    assert s.support_slopes[0] == pytest.approx(w * L**3 / (24 * EI), rel=1e-10)
    assert np.max(np.abs(s.deflection)) == pytest.approx(5 * w * L**4 / (384 * EI), rel=1e-10)
    assert np.max(np.abs(s.moment)) == pytest.approx(w * L**2 / 8, rel=1e-10)
    assert np.sum(s.reactions) == pytest.approx(w * L)


def test_beam_statically_indeterminate_cases():
    # two equal spans, uniform load: reactions 3/8, 10/8, 3/8 wL, support moment wL^2/8
    s = beam_solve([0.0, 1.0, 2.0], [(0.0, 2.0, 2.0)], 1.0)
    assert np.allclose(s.reactions, [0.375, 1.25, 0.375], rtol=1e-10)
    assert np.max(np.abs(s.moment)) == pytest.approx(0.125, rel=1e-10)
    # fixed-fixed, uniform load: end moments wL^2/12, centre wL^2/24, y_max wL^4/(384 EI)
    s = beam_solve([0.0, 1.0], [(0.0, 1.0, 1.0)], 1.0, end_fixity="clamped")
    mid = len(s.x) // 2
    assert abs(s.moment[0]) == pytest.approx(1 / 12, rel=1e-10)
    assert abs(s.moment[mid]) == pytest.approx(1 / 24, rel=1e-10)
    assert np.max(np.abs(s.deflection)) == pytest.approx(1 / 384, rel=1e-10)
    assert s.support_slopes[0] == 0.0


def test_beam_errors():
    with pytest.raises(InputError, match=r"supports must be at least two increasing"):
        beam_solve([0.0], [], 1.0)
    with pytest.raises(InputError, match=r"supports must be at least two increasing"):
        beam_solve([1.0, 0.0], [], 1.0)
    with pytest.raises(InfeasibleError, match=r"outside the beam"):
        beam_solve([0.0, 1.0], [(0.5, 1.5, 1.0)], 1.0)
    with pytest.raises(InputError, match=r"bending_stiffness must be positive"):
        beam_solve([0.0, 1.0], [], 0.0)
    with pytest.raises(UnknownNameError, match=r"valid: 'pinned', 'clamped'"):
        beam_solve([0.0, 1.0], [], 1.0, end_fixity="free")


# ---------------------------------------------------------------- multi-row pin


def _pin_16b3(**kw):
    # ISO 606 16B-3: d2 = 8.28 mm, pt = 31.88 mm, b1 = 17.02 mm (catalogue, chains/data/iso606.csv)
    return MultiRowPin(8.28e-3, 31.88e-3, 3, 17.02e-3, **kw)


def test_pin_without_intermediate_plates_is_statically_determinate():
    # By hand: reactions F/2 at the outer plates (-pt/2 and 2.5 pt); moment at the middle
    # row (x = pt): M = F/2 * 1.5 pt - F/3 * pt - (F/6) * (lb/4), lb the bushing length.
    pin = _pin_16b3()
    f = 6000.0
    r = pin.bending(f, intermediate_plates=False)
    pt = pin.transverse_pitch
    lb = pin.inner_width + 2 * pin.plate_thickness
    assert np.allclose(r.reactions, [f / 2, 0, 0, f / 2])
    m = f / 2 * 1.5 * pt - f / 3 * pt - f / 6 * lb / 4
    assert r.max_moment == pytest.approx(m, rel=1e-7)
    assert r.max_stress == pytest.approx(32 * m / (np.pi * 8.28e-3**3), rel=1e-7)


def test_intermediate_plates_reduce_slip_sample_16b3():
    pin = _pin_16b3()
    free = pin.bending(5e3, intermediate_plates=False)
    held = pin.bending(5e3, intermediate_plates=True)
    # regression of the documented sample (docs/strength.md)
    assert free.slip_amplitude == pytest.approx(165.42e-6, rel=1e-4)
    assert held.slip_amplitude == pytest.approx(4.1369e-6, rel=1e-4)
    assert free.slip_amplitude / held.slip_amplitude == pytest.approx(39.99, rel=1e-3)
    assert free.max_stress / held.max_stress == pytest.approx(10.01, rel=1e-3)
    assert np.sum(held.reactions) == pytest.approx(5e3)
    assert held.reactions[1] == pytest.approx(held.reactions[2])  # symmetry
    assert np.all(held.reactions > 0)


@pytest.mark.parametrize("strands", [2, 3, 4])
@pytest.mark.parametrize("fixity", ["pinned", "clamped"])
def test_intermediate_plates_always_help(strands, fixity):
    pin = MultiRowPin(8.28e-3, 31.88e-3, strands, 17.02e-3, end_fixity=fixity)
    free = pin.bending(5e3, intermediate_plates=False)
    held = pin.bending(5e3, intermediate_plates=True)
    assert held.slip_amplitude < free.slip_amplitude / 5
    assert held.max_stress < free.max_stress
    assert held.max_deflection < free.max_deflection


def test_simplex_pin_has_no_intermediate_plate():
    pin = MultiRowPin(8.28e-3, 31.88e-3, 1, 17.02e-3)
    a = pin.bending(5e3, intermediate_plates=False)
    b = pin.bending(5e3, intermediate_plates=True)
    assert a.slip_amplitude == pytest.approx(b.slip_amplitude)


def test_pin_scalar_vs_array_and_linearity():
    pin = _pin_16b3()
    loads = np.array([1e3, 2e3, 5e3])
    arr = pin.bending(loads)
    assert arr.slip_amplitude.shape == (3,) and arr.seat_slopes.shape == (3, 4)
    for i, f in enumerate(loads):
        assert pin.bending(float(f)).slip_amplitude == pytest.approx(arr.slip_amplitude[i], rel=1e-12)
    assert np.allclose(arr.slip_amplitude / loads, arr.slip_amplitude[0] / loads[0])


def test_pin_from_chain_and_errors():
    pin = MultiRowPin.from_chain("16B-3")
    assert pin.strands == 3 and pin.transverse_pitch == pytest.approx(31.88e-3)
    with pytest.raises(InputError, match=r"lacks transverse_pitch"):
        MultiRowPin.from_chain("16B-1")
    with pytest.raises(InputError, match=r"strands must be a whole number in \[1, 100\]"):
        MultiRowPin(8.28e-3, 31.88e-3, 0, 17.02e-3)
    with pytest.raises(InfeasibleError, match=r"inner_width must be smaller than transverse_pitch"):
        MultiRowPin(8.28e-3, 31.88e-3, 3, 40e-3)
    with pytest.raises(InputError, match=r"row_shares must be 3 non-negative fractions summing to 1"):
        MultiRowPin(8.28e-3, 31.88e-3, 3, 17.02e-3, row_shares=(0.5, 0.5, 0.5))
    with pytest.raises(InputError, match=r"pin_diameter must be positive"):
        MultiRowPin(0.0, 31.88e-3, 3, 17.02e-3)
    with pytest.raises(InputError, match=r"load must be positive"):
        _pin_16b3().bending(-1.0)


def test_unequal_row_shares_tilt_even_a_duplex_pin():
    sym = MultiRowPin(8.28e-3, 31.88e-3, 2, 17.02e-3, end_fixity="clamped")
    skew = MultiRowPin(8.28e-3, 31.88e-3, 2, 17.02e-3, end_fixity="clamped", row_shares=(0.6, 0.4))
    a = sym.bending(5e3).reactions
    b = skew.bending(5e3).reactions
    assert a[0] == pytest.approx(a[2]) and b[0] > b[2]


def test_fretting_comparison_shows_the_seed_claim():
    # Vikulov: intermediate plates reduce pin bending and micro-slip and raise life.
    pin = _pin_16b3()
    ra, f = 0.8e-6, 10.0
    a0 = pin.bending(5e3, intermediate_plates=False).slip_amplitude
    n = 5e3 / 3
    k2 = ra / (a0 * n * f)  # chosen so that the exponent without plates is 1
    c = fretting_comparison(pin, 5e3, ra, f, 1e12, k2)
    assert c.normal_load == pytest.approx(n)
    assert c.latent_without == pytest.approx(1e12 * ra * np.exp(-1.0), rel=1e-9)
    assert c.life_ratio == pytest.approx(np.exp(1 - 1 / c.slip_ratio), rel=1e-9)
    assert c.life_ratio == pytest.approx(2.65, rel=2e-3)
    assert c.to_dict()["life_ratio"] > 1
