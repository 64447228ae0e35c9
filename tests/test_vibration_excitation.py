"""Excitation amplitudes and the forced response of the slack span (issue 20, item 4b)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from chaindrive.errors import InputError
from chaindrive.vibration import TensionerSpan, tensioner_frequencies
from chaindrive.vibration.excitation import (
    AMPLIFICATION_LIMIT,
    forced_span_response,
    polygon_transverse_harmonics,
    runout_tolerance,
    span_excitations,
    unequal_link_amplitude,
)
from chaindrive.vibration.planar import planar_forced_response

SPAN = TensionerSpan(2000.0, 2.6, 0.8, 1.1, 0.3, 0.3, 3.0, 5e4)


@pytest.mark.parametrize("z", [8, 17, 25])
def test_polygon_fundamental_closed_form(z):
    # independent reference: a1 = (2/T) ∫ R cos φ cos(zφ) dφ over |φ| <= π/z
    #                           = (2z/π) R sin(π/z) / (z² − 1)
    r = 0.1
    a = polygon_transverse_harmonics(r, [2 * np.pi / z], 1)[0]
    assert a == pytest.approx(2 * z / np.pi * r * np.sin(np.pi / z) / (z * z - 1), rel=1e-6)


def test_bi_regular_polygon_has_a_fundamental_at_the_pair_period():
    # the regular polygon (d = 0) has no component at the pair period, a round link chain does
    z, t, d = 8, 0.064, 0.018
    R = 0.5 * math.hypot(t / math.sin(math.pi / (2 * z)), d / math.cos(math.pi / (2 * z)))  # Dolipiński eq. (6)
    d1 = 2 * math.asin((t + d) / (2 * R))
    a = polygon_transverse_harmonics(R, [d1, 2 * math.pi / z - d1], 2)
    regular = polygon_transverse_harmonics(R, [math.pi / z, math.pi / z], 2)
    assert regular[0] < 1e-12 * R and a[0] > 0.05 * a[1] > 0
    # 18x64 on 8 pockets: the pair period's component is 0.149 mm, each link's 1.69 mm (regression)
    assert a[0] == pytest.approx(0.149e-3, rel=1e-2) and a[1] == pytest.approx(1.693e-3, rel=1e-2)


@pytest.mark.parametrize("sides", [[2 * np.pi / 17], [0.504471, 2 * np.pi / 8 - 0.504471], [np.pi / 8, np.pi / 8],
                                   [0.3, 0.2, 0.1]])
def test_polygon_harmonics_closed_form_is_the_limit_of_the_sampled_transform(sides):
    # independent: the FFT of 2**16 and 2**20 samples (the former default took 4,096); a
    # motion continuous at the seatings (equal sides) converges as 1/N², one that jumps (a round
    # link chain's unequal sides) as 1/N: the closed form is their limit
    r = 0.1
    exact = polygon_transverse_harmonics(r, sides, 3)
    coarse = polygon_transverse_harmonics(r, sides, 3, samples=2**16)
    fine = polygon_transverse_harmonics(r, sides, 3, samples=2**20)
    err_coarse, err_fine = (float(np.abs(x - exact).max() / exact.max()) for x in (coarse, fine))
    assert err_fine <= max(1e-11, err_coarse / 8)  # 16 times the samples: at least 8 times closer
    assert err_fine <= 2e-6


def test_runout_and_unequal_links():
    assert runout_tolerance(0.1) == pytest.approx(0.16e-3)
    assert runout_tolerance(5.0) == pytest.approx(0.76e-3)  # the cap
    # p = 25.4 mm, z = 17: Δp = 0.15 % p = 38.1 µm, ± Δp/(4 sin(π/17)) = ±51.8 µm, fundamental 4/π of it
    assert unequal_link_amplitude(0.0254, 17) == pytest.approx(4 / math.pi * 0.0015 * 0.0254 / (4 * math.sin(math.pi / 17)))
    with pytest.raises(InputError, match="diameter"):
        runout_tolerance(0.0)
    with pytest.raises(InputError, match="tolerance"):
        unequal_link_amplitude(0.0254, 17, tolerance=0.5)


@pytest.mark.parametrize("omega", [1.0, 40.0, 77.0, 150.0])
def test_forced_response_matches_planar_bead_model(omega):
    # independent reference: the planar bead chain driven at the far end of part 1 (direct solve)
    w, u = forced_span_response(SPAN, omega, 1e-3, damping_ratio=0.02)
    wp, up = planar_forced_response(2000.0, 2.6, 0.8, 1.1, 0.3, 0.3, 3.0, 5e4, omega, end_amplitude=1e-3,
                                    damping_ratio=0.02, elements=200)
    assert w[0] == pytest.approx(wp, rel=5e-3)
    assert u[0] == pytest.approx(up, rel=5e-3)


def test_forced_response_limits_and_resonance():
    # fixed tensioner (C huge): part 1 a fixed-fixed string driven at one end
    stiff = TensionerSpan(2000.0, 2.6, 0.8, 1.1, 0.0, 0.0, 3.0, 1e12)
    om = 30.0
    k = om / math.sqrt(2000.0 / 2.6)
    w, u = forced_span_response(stiff, om, 1e-3, damping_ratio=1e-6)
    s = np.linspace(0, 0.8, 2001)
    assert w[0] == pytest.approx(np.max(np.abs(1e-3 * np.sin(k * (0.8 - s)) / np.sin(k * 0.8))), rel=1e-4)
    assert u[0] < 1e-9
    # at a natural frequency the response is ~1/(2ζ) times larger than off it, and halving ζ doubles it
    p1 = tensioner_frequencies(2000.0, 2.6, 0.8, 1.1, 0.3, 0.3, 3.0, 5e4)[0]
    a, _ = forced_span_response(SPAN, p1, 1e-3, damping_ratio=0.02)
    b, _ = forced_span_response(SPAN, p1, 1e-3, damping_ratio=0.01)
    assert b[0] / a[0] == pytest.approx(2.0, rel=0.05)
    regression, _ = forced_span_response(SPAN, 77.0, 1e-3)
    assert regression[0] == pytest.approx(3.5134e-3, rel=1e-3)


@settings(max_examples=30, deadline=None)
@given(om=st.floats(0.5, 300.0), y=st.floats(1e-6, 1e-2))
def test_forced_response_is_linear_in_the_amplitude(om, y):
    w1, u1 = forced_span_response(SPAN, om, y)
    w2, u2 = forced_span_response(SPAN, om, 2 * y)
    assert np.allclose(w2, 2 * w1, rtol=1e-9) and np.allclose(u2, 2 * u1, rtol=1e-9)
    assert w1[0] >= y * (1 - 1e-9)  # the excited end itself moves by y


def test_span_excitations_rows_and_errors():
    rows = span_excitations(SPAN, 10.0, ratio=2.0, teeth_driving=17, teeth_driven=34, radius_driving=0.069,
                            radius_driven=0.1376, pitch=0.0254)
    assert [r.name for r in rows] == ["driving sprocket", "driven sprocket", "unequal links (inner/outer)", "meshing"]
    # every excitation judged by the amplification of its response (issue 30: one criterion)
    assert all(r.source for r in rows) and [r.criterion for r in rows] == ["response"] * 4
    assert [r.passed for r in rows] == [r.amplification <= AMPLIFICATION_LIMIT for r in rows]
    assert rows[0].amplification == pytest.approx(1.0, abs=0.1)  # 10 rad/s: far below the first mode
    link = span_excitations(SPAN, 5.0, ratio=1.0, teeth_driving=8, teeth_driven=8, radius_driving=0.1643,
                            radius_driven=0.1643, pitch=0.064, bar_diameter=0.018)
    assert [r.name for r in link][-2:] == ["link pair (t ± d)", "link passing"]
    assert link[-1].criterion == "response" and link[-1].passed is not None
    # a link chain has no unequal inner/outer links: no amplitude, no verdict
    assert all(r.passed is None for r in link if r.end_amplitude == 0.0)
    with pytest.raises(InputError, match="damping_ratio"):
        forced_span_response(SPAN, 10.0, 1e-3, damping_ratio=0.0)
    with pytest.raises(InputError, match="frequency"):
        forced_span_response(SPAN, -1.0, 1e-3)


def test_span_excitations_equal_one_forced_response_each():
    # the excitations are answered in one call, each frequency with its own amplitude; each
    # equals forced_span_response asked alone, bit for bit
    from chaindrive.vibration.excitation import forced_span_response, span_excitations
    from chaindrive.vibration.resonance import TensionerSpan

    s = TensionerSpan(2000.0, 2.6, 0.8, 1.1, 0.3, 0.3, 3.0, 5e4)
    rows = span_excitations(s, 10.0, ratio=2.0, teeth_driving=17, teeth_driven=34, radius_driving=0.069,
                            radius_driven=0.1376, pitch=0.0254)
    for r in rows:
        w, u = forced_span_response(s, [r.frequency, 1e-6 * 10.0], r.end_amplitude, r.end_amplitude)
        assert r.response == float(w[0]) and r.tensioner_amplitude == float(u[0])
        assert r.amplification == (float(w[0] / w[1]) if r.end_amplitude > 0 else 0.0)
