"""Tests of chaindrive.vibration (the tensioner paper and the moving string)."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from chaindrive.errors import InfeasibleError, InputError, UnknownNameError
from chaindrive.vibration import (
    TensionerSpan,
    campbell,
    excitation_frequencies,
    excitation_multipliers,
    fe_tensioner_frequencies,
    frequency_function,
    heavy_tensioner_frequency,
    heavy_tensioner_validity,
    moving_string_frequencies,
    pole_free_function,
    propose_safe_tensioner,
    reduced_tensioner,
    resonance_check,
    resonance_map,
    resonance_margin,
    span_vibration,
    static_rod_force,
    tensioner_frequencies,
    wave_speed,
)
from chaindrive.vibration.tensioner_design import _min_margin

B20 = math.radians(20)
BASE = dict(tension=2000.0, mass_per_length=2.6, length_1=0.8, length_2=0.8, angle_1=B20, angle_2=B20)
ASYM = dict(tension=1500.0, mass_per_length=3.1, length_1=0.65, length_2=1.2,
            angle_1=math.radians(25), angle_2=math.radians(8))


def freqs(mass, stiffness, modes=3, **kw):
    args = {**BASE, **kw}
    return tensioner_frequencies(args["tension"], args["mass_per_length"], args["length_1"],
                                 args["length_2"], args["angle_1"], args["angle_2"], mass, stiffness,
                                 modes=modes, model=kw.get("model", "projected"))


def call(fn, par, mass, stiffness, **kw):
    return fn(par["tension"], par["mass_per_length"], par["length_1"], par["length_2"],
              par["angle_1"], par["angle_2"], mass, stiffness, **kw)


# ----------------------------------------------------------------------- moving string
def test_moving_string_published_nondimensional():
    # Wickert & Mote, J. Appl. Mech. 57 (1990) 738, eq. (29): for the axially moving
    # string with fixed ends, ω_n = nπ(1 − v²) in units where c = L = 1.
    w = moving_string_frequencies(1.0, 1.0, 1.0, chain_speed=0.5, modes=3)
    np.testing.assert_allclose(w, np.pi * np.arange(1, 4) * 0.75, rtol=1e-14)


def test_moving_string_stationary_is_classical_string():
    # Classical string f_n = n/(2L) sqrt(S/q) (any vibration textbook, e.g. Rao,
    # Mechanical Vibrations, 5th ed., eq. (8.26)).
    f = moving_string_frequencies(2000.0, 2.6, 0.8, modes=2) / (2 * np.pi)
    np.testing.assert_allclose(f, np.array([1, 2]) / 1.6 * math.sqrt(2000 / 2.6), rtol=1e-14)


def test_moving_string_against_galerkin_gyroscopic():
    # Independent: Galerkin (30 sine modes) of q(w_tt + 2v w_xt + v² w_xx) = S w_xx,
    # gyroscopic quadratic eigenproblem solved in state space.
    S, q, L, v = 1800.0, 2.2, 1.3, 9.0
    n = 30
    k = np.arange(1, n + 1)
    M = q * L / 2 * np.eye(n)
    K = np.diag((S - q * v**2) * (k * np.pi / L) ** 2 * L / 2)
    mm, nn = np.meshgrid(k, k, indexing="ij")
    with np.errstate(divide="ignore", invalid="ignore"):
        G = np.where(mm != nn, 2 * q * v * nn * mm * (1 - (-1.0) ** (mm + nn)) / (mm**2 - nn**2), 0.0)
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-np.linalg.solve(M, K), -np.linalg.solve(M, G)]])
    ev = np.sort(np.abs(np.linalg.eigvals(A).imag))[::2][:3]
    exact = moving_string_frequencies(S, q, L, chain_speed=v, modes=3)
    np.testing.assert_allclose(ev, exact, rtol=2e-3)


def test_moving_string_inclination_factor_and_regression():
    # the tensioner paper eq. (1): c² = S/(q cos β)
    assert wave_speed(2000.0, 2.6, math.radians(60)) == pytest.approx(math.sqrt(2000 / (2.6 * 0.5)), rel=1e-14)
    w = moving_string_frequencies(2000.0, 2.6, 0.8, chain_speed=5.0, inclination=B20)
    # by hand: c = sqrt(2000/(2.6 cos 20°)) = 28.6106 m/s, π c/0.8 (1 − 25/c²) = 108.9244 rad/s
    np.testing.assert_allclose(w[0], 108.924404, rtol=1e-8)


def test_moving_string_scalar_vs_array_and_errors():
    L = np.array([0.5, 0.8, 1.4])
    arr = moving_string_frequencies(2000.0, 2.6, L, chain_speed=3.0)
    for i, li in enumerate(L):
        np.testing.assert_allclose(arr[i], moving_string_frequencies(2000.0, 2.6, li, chain_speed=3.0))
    with pytest.raises(InfeasibleError, match="chain_speed must be below"):
        moving_string_frequencies(2000.0, 2.6, 0.8, chain_speed=30.0)
    with pytest.raises(InputError, match="length must be positive"):
        moving_string_frequencies(2000.0, 2.6, 0.0)
    with pytest.raises(InputError, match="tension must be positive"):
        moving_string_frequencies(-1.0, 2.6, 0.8)
    with pytest.raises(InputError, match="modes must be"):
        moving_string_frequencies(2000.0, 2.6, 0.8, modes=0)
    with pytest.raises(InputError, match=r"inclination must lie in \[0, 1.5708\)"):
        wave_speed(2000.0, 2.6, math.pi / 2)


# ----------------------------------------------------------------------- frequency equation
@pytest.mark.slow
@pytest.mark.parametrize("par", [BASE, ASYM], ids=["symmetric", "asymmetric"])
@pytest.mark.parametrize("model", ["projected", "as_printed"])
@pytest.mark.parametrize("m,c", [(3.0, 5e4), (0.0, 0.0), (25.0, 2e3), (0.5, 2e6)])
def test_roots_match_finite_elements(par, model, m, c):
    # Independent: linear FE of both strings + mass-spring, scipy.linalg.eigh; error
    # falls as h² (ratio ~4 per halving) and is < 2e-5 at 400 elements.
    exact = call(tensioner_frequencies, par, m, c, modes=5, model=model)
    errs = []
    for n in (100, 200, 400):
        fe = call(fe_tensioner_frequencies, par, m, c, modes=5, elements=n, model=model)
        errs.append(np.max(np.abs(fe - exact) / exact))
    assert errs[2] < 1e-4
    assert errs[0] / errs[2] > 10  # ~16 for O(h²)
    assert np.all(fe >= exact * (1 - 1e-12))  # consistent-mass FE bounds from above


def test_roots_are_zeros_of_the_equation():
    p = call(tensioner_frequencies, ASYM, 3.0, 5e4, modes=8)
    g = frequency_function(p, *ASYM.values(), 3.0, 5e4)
    assert np.all(np.abs(g) < 1e-6 * (3.0 * p**2 + 5e4))
    d = pole_free_function(p, *ASYM.values(), 3.0, 5e4)
    scale = pole_free_function(p * 1.001, *ASYM.values(), 3.0, 5e4)
    assert np.all(np.abs(d) < 1e-9 * np.abs(scale))


def test_no_root_missed_against_fine_scan_of_pole_free_function():
    # A fine sign-change scan of the pole-free D(p) (with D = 0 exactly at shared poles)
    # finds the same roots below the 8th.
    for par, m, c in [(ASYM, 3.0, 5e4), (ASYM, 0.0, 1e5), (BASE, 40.0, 1e3), (ASYM, 1e3, 1e8)]:
        p = call(tensioner_frequencies, par, m, c, modes=8)
        grid = np.linspace(1e-6, p[-1] * (1 + 1e-9) + 1e-9, 400001)
        d = pole_free_function(grid, *par.values(), m, c)
        changes = np.count_nonzero(np.sign(d[1:]) != np.sign(d[:-1]))
        assert changes == 8


def test_shared_poles_symmetric_case():
    # ℓ1 = ℓ2, β1 = β2: the antisymmetric modes have a node at the tensioner, p = jπc/ℓ,
    # whatever m and C; they are roots (not poles taken for roots).
    c = wave_speed(2000.0, 2.6, B20)
    for m, C in [(0.0, 0.0), (3.0, 5e4), (100.0, 1e7)]:
        p = freqs(m, C, modes=6)
        for j in (1, 2):
            assert np.min(np.abs(p - j * np.pi * c / 0.8)) < 1e-9 * p[-1]
    # nearly coincident poles: the roots move continuously
    p0 = freqs(3.0, 5e4, modes=6)
    p1 = freqs(3.0, 5e4, modes=6, length_2=0.8 * (1 + 1e-7))
    np.testing.assert_allclose(p1, p0, rtol=1e-6)


def test_limit_infinite_stiffness_is_two_fixed_strings():
    c1, c2 = wave_speed(1500.0, 3.1, ASYM["angle_1"]), wave_speed(1500.0, 3.1, ASYM["angle_2"])
    fixed = np.sort(np.concatenate([np.arange(1, 6) * np.pi * c1 / 0.65, np.arange(1, 6) * np.pi * c2 / 1.2]))[:5]
    np.testing.assert_allclose(call(tensioner_frequencies, ASYM, 3.0, np.inf, modes=5), fixed, rtol=1e-14)
    np.testing.assert_allclose(call(tensioner_frequencies, ASYM, 3.0, 1e12, modes=5), fixed, rtol=1e-6)
    # symmetric: every fixed-fixed frequency twice
    pf = freqs(0.0, np.inf, modes=4)
    np.testing.assert_allclose(pf[0], pf[1])


def test_limit_massless_tensioner():
    # m -> 0 continuous; m = 0, C = 0, symmetric: free end at the tensioner, quarter waves
    np.testing.assert_allclose(freqs(1e-9, 5e4), freqs(0.0, 5e4), rtol=1e-8)
    c = wave_speed(2000.0, 2.6, B20)
    np.testing.assert_allclose(freqs(0.0, 0.0, modes=4), np.array([1, 2, 3, 4]) * np.pi * c / 1.6, rtol=1e-12)


def test_limit_very_heavy_tensioner():
    # m -> ∞: P1 -> 0 and the others approach the lower poles
    p = call(tensioner_frequencies, ASYM, 1e9, 5e4, modes=3)
    assert p[0] < 1e-2
    c1, c2 = wave_speed(1500.0, 3.1, ASYM["angle_1"]), wave_speed(1500.0, 3.1, ASYM["angle_2"])
    poles = np.sort([np.pi * c1 / 0.65, np.pi * c2 / 1.2, 2 * np.pi * c2 / 1.2])
    np.testing.assert_allclose(p[1:], poles[:2], rtol=1e-6)


def test_seed_model_satisfies_printed_eq_11_with_indices_restored():
    # the tensioner paper eq. (11), indices ℓ1 ↔ ℓ2 put back: Σ cot(k_i ℓ_i)/(c_i cos β_i) = (p² m − C)/(S2 p)
    s, q, l1, l2, b1, b2 = ASYM.values()
    m, C = 3.0, 5e4
    p = tensioner_frequencies(s, q, l1, l2, b1, b2, m, C, model="as_printed", modes=4)
    c1, c2 = np.sqrt(s / (q * np.cos(b1))), np.sqrt(s / (q * np.cos(b2)))
    lhs = 1 / np.tan(p / c1 * l1) / (c1 * np.cos(b1)) + 1 / np.tan(p / c2 * l2) / (c2 * np.cos(b2))
    rhs = (p**2 * m - C) / (s * p)
    np.testing.assert_allclose(lhs, rhs, atol=1e-9 * np.max(np.abs(rhs)))


def test_models_agree_for_flat_spans():
    par = {**ASYM, "angle_1": 0.0, "angle_2": 0.0}
    np.testing.assert_allclose(call(tensioner_frequencies, par, 3.0, 5e4, model="as_printed"),
                               call(tensioner_frequencies, par, 3.0, 5e4, model="projected"), rtol=1e-13)


def test_regression_values():
    np.testing.assert_allclose(freqs(3.0, 5e4), [94.6898196, 112.3557495, 146.0242354], rtol=1e-8)


def test_scalar_vs_array_broadcasting():
    m = np.array([0.0, 1.0, 10.0])
    C = np.array([[1e3], [1e5]])
    arr = freqs(m, C, modes=3)
    assert arr.shape == (2, 3, 3)
    for i in range(2):
        for j in range(3):
            np.testing.assert_allclose(arr[i, j], freqs(m[j], C[i, 0]), rtol=1e-12)


def test_chain_speed_correction_fixed_limit():
    # with C = ∞ each part is a fixed-fixed moving string (Wickert & Mote)
    p = call(tensioner_frequencies, ASYM, 3.0, np.inf, modes=2, chain_speed=6.0)
    w1 = moving_string_frequencies(1500.0 / math.cos(ASYM["angle_1"]) * math.cos(ASYM["angle_1"]), 3.1, 0.65,
                                   chain_speed=6.0, inclination=ASYM["angle_1"], modes=2)
    w2 = moving_string_frequencies(1500.0, 3.1, 1.2, chain_speed=6.0, inclination=ASYM["angle_2"], modes=2)
    np.testing.assert_allclose(p, np.sort(np.concatenate([w1, w2]))[:2], rtol=1e-12)


@pytest.mark.parametrize("kw,match", [
    (dict(tension=0.0), r"tension must be positive"),
    (dict(mass_per_length=-1.0), r"mass_per_length must be positive"),
    (dict(length_1=0.0), r"length_1 must be positive"),
    (dict(length_2=-0.2), r"length_2 must be positive"),
    (dict(angle_1=math.pi / 2), r"angle_1 must lie in \[0, 1.5708\)"),
    (dict(angle_2=-0.1), r"angle_2 must lie in \[0, 1.5708\)"),
    (dict(mass=-1.0), r"mass must be non-negative"),
    (dict(stiffness=-5.0), r"stiffness must be non-negative \(0 <= stiffness <= inf"),
    (dict(stiffness=np.nan), r"stiffness must be non-negative"),
    (dict(modes=0), r"modes must be a whole number in \[1, 100\]"),
    (dict(chain_speed=-1.0), r"chain_speed must be non-negative"),
])
def test_errors(kw, match):
    args = {**BASE, "mass": 3.0, "stiffness": 5e4}
    modes = kw.pop("modes", 3)
    v = kw.pop("chain_speed", 0.0)
    args.update(kw)
    with pytest.raises(InputError, match=match):
        tensioner_frequencies(*args.values(), modes=modes, chain_speed=v)


def test_other_errors():
    with pytest.raises(UnknownNameError, match="valid: 'projected', 'as_printed'"):
        freqs(3.0, 5e4, model="exact")
    with pytest.raises(InfeasibleError, match="chain_speed must satisfy"):
        call(tensioner_frequencies, BASE, 3.0, 5e4, chain_speed=100.0)
    with pytest.raises(InputError, match="stiffness must be finite"):
        call(fe_tensioner_frequencies, BASE, 3.0, np.inf)
    with pytest.raises(InputError, match=r"elements must be a whole number in \[2, 400\]"):
        call(fe_tensioner_frequencies, BASE, 3.0, 5e4, elements=1)


@settings(max_examples=40, deadline=None)
@given(
    s=st.floats(100.0, 2e4), q=st.floats(0.3, 20.0), l1=st.floats(0.1, 3.0), l2=st.floats(0.1, 3.0),
    b1=st.floats(0.0, 1.4), b2=st.floats(0.0, 1.4), m=st.floats(0.0, 200.0), c=st.floats(0.0, 1e7),
)
def test_properties(s, q, l1, l2, b1, b2, m, c):
    p = tensioner_frequencies(s, q, l1, l2, b1, b2, m, c, modes=4)
    assert np.all(p > 0) and np.all(np.diff(p) >= -1e-12 * p[-1])  # positive, ordered
    tol = 1e-9 * p
    p_s = tensioner_frequencies(1.3 * s, q, l1, l2, b1, b2, m, c, modes=4)
    assert np.all(p_s >= p - tol)  # rise with tension
    p_m = tensioner_frequencies(s, q, l1, l2, b1, b2, m * 1.5 + 0.1, c, modes=4)
    assert np.all(p_m <= p + tol)  # fall with tensioner mass
    p_c = tensioner_frequencies(s, q, l1, l2, b1, b2, m, c * 1.5 + 10.0, modes=4)
    assert np.all(p_c >= p - tol)  # rise with stiffness


# ----------------------------------------------------------------------- eq. (8), (13)
def test_static_rod_force_by_vector_balance():
    # Part i pulls the sprocket with T_i = S2/cos β_i towards its far end; the rod takes
    # the component along the axis (y), the guide the rest. Eq. (8) must equal it.
    s, b1, b2 = 1500.0, 0.4, 0.15
    t1, t2 = s / math.cos(b1), s / math.cos(b2)
    pull = t1 * np.array([-math.cos(b1), math.sin(b1)]) + t2 * np.array([math.cos(b2), math.sin(b2)])
    assert static_rod_force(s, b1, b2) == pytest.approx(pull[1], rel=1e-14)
    assert pull[0] == pytest.approx(0.0, abs=1e-9)  # S2 is the component across the axis
    np.testing.assert_allclose(static_rod_force(2000.0, [0.0, B20], B20), [727.9404685, 1455.880937])
    with pytest.raises(InputError, match=r"angle_2 must lie in \[0, 1.5708\)"):
        static_rod_force(2000.0, 0.2, 2.0)
    with pytest.raises(InputError, match="tension must be positive"):
        static_rod_force(0.0, 0.2, 0.2)


def test_heavy_tensioner_inside_and_outside_validity():
    b = B20
    rows = []
    for m, c in [(30.0, 5e3), (100.0, 1e4), (300.0, 2e4), (3.0, 5e4), (30.0, 5e4), (0.5, 1e3)]:
        approx = heavy_tensioner_frequency(2000.0, 2.6, 0.8, 0.8, b, b, m, c)
        approx3 = heavy_tensioner_frequency(2000.0, 2.6, 0.8, 0.8, b, b, m, c, chain_mass=True)
        exact = freqs(m, c, modes=1)[0]
        theta = heavy_tensioner_validity(2000.0, 2.6, 0.8, 0.8, b, b, m, c)
        rows.append((theta, abs(approx / exact - 1), abs(approx3 / exact - 1)))
    for theta, err, err3 in rows:
        if theta <= 0.5:
            assert err < 0.03 and err3 < 0.002  # inside: within 3 % (chain-mass term: 0.2 %)
        if theta >= 2.5:
            assert err > 0.05  # far outside: the formula is off by more than 5 % (here 43-98 %)
    # measured (m [kg], C [N/m], θ, error of (13), error with the chain-mass term):
    # (30, 5e3, 0.50, 2.1 %, 0.03 %), (100, 1e4, 0.34, 0.6 %, 0.005 %), (300, 2e4, 0.25, 0.2 %, 0.001 %),
    # (30, 5e4, 1.19, 2.2 %, 0.2 %)  <- heavy tensioner: still fine although θ > 0.5,
    # (3, 5e4, 3.78, 43 %, 20 %), (0.5, 1e3, 2.99, 98 %, 6.7 %)
    assert rows[0][0] == pytest.approx(0.5027, abs=1e-4)
    assert rows[0][1] == pytest.approx(0.0205, abs=5e-4)


def test_heavy_tensioner_printed_eq_13_is_the_square():
    # the tensioner paper eq. (13) as printed: 2 S2/(m ℓ1 cos β1) + C/m  (units s⁻²) = P1² of the paper model
    s, l, b, m, c = 2000.0, 0.8, B20, 50.0, 2e4
    printed = 2 * s / (m * l * math.cos(b)) + c / m
    p1 = heavy_tensioner_frequency(s, 2.6, l, l, b, b, m, c, model="as_printed")
    assert p1**2 == pytest.approx(printed, rel=1e-14)
    with pytest.raises(InputError, match="mass must be positive"):
        heavy_tensioner_frequency(s, 2.6, l, l, b, b, 0.0, c)


# ----------------------------------------------------------------------- reduction
def test_reduced_tensioner_pivot_arm_by_geometry():
    # Independent: exact spring length change for a small arm rotation θ, V = ½ k δ²,
    # and the sprocket path u = L θ: C = 2V/u².
    J, ms, L, k, a, gam = 0.05, 2.0, 0.25, 2e5, 0.1, math.radians(30)
    r = reduced_tensioner("pivot_arm", arm_inertia=J, sprocket_mass=ms, arm_length=L,
                          spring_stiffness=k, spring_lever=a, spring_angle=gam)
    th = 1e-6
    anchor = np.array([a, 0.0]) + 0.4 * np.array([math.sin(gam), math.cos(gam)])  # spring 0.4 m long
    p0, p1 = np.array([a, 0.0]), a * np.array([math.cos(th), math.sin(th)])
    d = np.linalg.norm(anchor - p1) - np.linalg.norm(anchor - p0)
    assert r.stiffness == pytest.approx(k * d**2 / (L * th) ** 2, rel=1e-4)
    assert r.mass == pytest.approx((J + ms * L**2) / L**2)
    assert r.to_dict()["method"] == "pivot_arm"


def test_reduced_tensioner_sliding_and_errors():
    r = reduced_tensioner("sliding", carriage_mass=1.0, sprocket_mass=2.0, spring_stiffness=4e4,
                          spring_mass=0.3, spring_angle=math.radians(60))
    assert r.mass == pytest.approx(3.0 + 0.3 * 0.25 / 3)
    assert r.stiffness == pytest.approx(1e4)
    with pytest.raises(UnknownNameError, match="valid: 'sliding', 'pivot_arm'"):
        reduced_tensioner("lever")
    with pytest.raises(InputError, match="spring_stiffness"):
        reduced_tensioner("sliding", carriage_mass=1.0)
    with pytest.raises(InputError, match="arm_length must be positive"):
        reduced_tensioner("pivot_arm", arm_inertia=0.1, sprocket_mass=1.0, arm_length=0.0,
                          spring_stiffness=1e4, spring_lever=0.1)


# ----------------------------------------------------------------------- excitation, check
def test_excitations():
    # the paper's three (driving, driven, unequal links) and the roller chain's polygon
    assert excitation_multipliers(2.5, 17) == {"driving sprocket": 1.0, "driven sprocket": 0.4,
                                               "unequal links (inner/outer)": 8.5}
    assert excitation_multipliers(2.5, 17, polygon=True)["meshing"] == 17.0  # not the paper's: forced response
    k = excitation_multipliers(2.0, 8, link_chain=True)
    assert k["link pair (t ± d)"] == 8.0 and "link passing" not in k
    assert excitation_multipliers(2.0, 8, link_chain=True, polygon=True)["link passing"] == 16.0
    assert "meshing" not in excitation_multipliers(3.0)
    e = excitation_frequencies(np.array([10.0, 20.0]), 2.0, 9)
    np.testing.assert_allclose(e["unequal links (inner/outer)"], [45.0, 90.0])
    with pytest.raises(InputError, match="ratio must be positive"):
        excitation_multipliers(0.0)
    with pytest.raises(InputError, match="teeth must be a whole number >= 3"):
        excitation_multipliers(1.0, 2)
    with pytest.raises(InputError, match="speed must be positive"):
        excitation_frequencies(-1.0)


def test_resonance_margin_and_check_band_edges():
    np.testing.assert_allclose(resonance_margin([0.7, 1.4, 0.35, 2.8]), [0.0, 0.0, 0.5, 1.0], atol=1e-15)
    r = resonance_check([70.0, 140.0, 50.0, 200.0], {"driving sprocket": 100.0})
    assert [bool(v) for v in r.ok] == [False, False, True, True]  # the band is closed
    assert not r.passed
    row = r.rows()[2]
    assert row == {"mode": 3, "excitation": "driving sprocket", "natural_frequency": 50.0,
                   "exciting_frequency": 100.0, "ratio": 0.5, "margin": pytest.approx(2 / 7), "ok": True}
    assert r.to_dict()["passed"] is False
    with pytest.raises(InputError, match="natural_frequencies must be positive"):
        resonance_check([0.0], {"x": 1.0})


def test_min_margin_equals_brute_force():
    rng = np.random.default_rng(1)
    p = np.sort(rng.uniform(5, 400, (50, 3)), axis=-1)
    w = np.linspace(10, 60, 37)
    mult = [1.0, 0.4, 17.0]
    brute = np.min(np.asarray(resonance_margin(p[:, None, :, None] / (np.array(mult)[None, :, None, None] * w))),
                   axis=(1, 2, 3))
    np.testing.assert_allclose(_min_margin(p, mult, w), brute, rtol=1e-14)


# ----------------------------------------------------------------------- design help
def test_span_object_campbell_map_proposal(tmp_path):
    span = TensionerSpan(*BASE.values(), 30.0, 2e4)
    assert span.static_rod_force() == pytest.approx(1455.880937)
    assert span.heavy_tensioner_frequency() == pytest.approx(
        heavy_tensioner_frequency(*BASE.values(), 30.0, 2e4))
    assert not span.check(31.4159, ratio=2.5, teeth=17).passed
    cb = campbell(span, (10.0, 100.0), ratio=2.5, teeth=17, speeds=40, design_speed=31.4)
    assert cb.natural_frequencies.shape == (40, 3)
    assert cb.to_dict()["excitation_names"] == ["driving sprocket", "driven sprocket",
                                                 "unequal links (inner/outer)"]
    cb2 = campbell(span, (10.0, 100.0), speeds=5, chain_speed_per_speed=0.05)
    assert np.all(np.diff(cb2.natural_frequencies[:, 0]) < 0)  # moving string: falls with speed
    rng = (25.0, 38.0)
    prop = propose_safe_tensioner(span, rng, ratio=2.5, teeth=17, points=81)
    assert prop.changed and prop.margin > 0.05 and prop.design_margin <= 0.05
    # the proposal really is safe: check it at every sampled speed
    safe = TensionerSpan(*BASE.values(), prop.mass, prop.stiffness)
    for w in np.linspace(*rng, 50):
        assert safe.check(w, ratio=2.5, teeth=17).passed
    mp = resonance_map(span, np.geomspace(1, 300, 30), np.geomspace(1e3, 1e6, 30), rng, ratio=2.5, teeth=17)
    assert 0 < mp.safe.mean() < 1
    assert set(mp.to_dict()) >= {"mass", "stiffness", "min_margin", "safe"}
    mp = dataclasses.replace(mp, proposal=(prop.mass, prop.stiffness))
    import matplotlib.pyplot as plt

    for name, fig in (("campbell.png", cb.plot()), ("map.png", mp.plot())):
        fig.savefig(tmp_path / name)
        plt.close(fig)
        assert (tmp_path / name).stat().st_size > 10000
    # unchanged when already safe; infeasible when nothing is safe (symmetric node mode)
    ok = TensionerSpan(*BASE.values(), 3.0, 5e4)
    assert not propose_safe_tensioner(ok, (25.0, 35.0), points=21).changed
    with pytest.raises(InfeasibleError, match="no safe tensioner"):
        propose_safe_tensioner(ok, (90.0, 110.0), points=21)
    with pytest.raises(InputError, match="speed_range must be"):
        resonance_map(ok, [1.0], [1.0], (40.0, 30.0))
    with pytest.raises(InputError, match="tension must be positive"):
        TensionerSpan(0.0, 2.6, 0.8, 0.8, 0.3, 0.3, 3.0, 5e4)


def test_span_vibration_bundle(tmp_path):
    span = TensionerSpan(*BASE.values(), 3.0, 5e4)
    r = span_vibration(span, 31.4159, ratio=2.5, teeth=17)
    assert r.passed is True
    d = r.to_dict()
    assert d["static_rod_force"] == pytest.approx(1455.880937)
    assert len(d["check"]["ratio"]) == 9 and d["campbell"]["speed"][0] == pytest.approx(0.8 * 31.4159)
    assert r.heavy_tensioner_frequency == pytest.approx(heavy_tensioner_frequency(*BASE.values(), 3.0, 5e4))
    fig = r.plot()
    fig.savefig(tmp_path / "c.png")
    bare = span_vibration(TensionerSpan(*BASE.values(), 0.0, 5e4))
    assert bare.passed is None and bare.heavy_tensioner_frequency is None
    with pytest.raises(InputError, match="no Campbell data"):
        bare.plot()


@settings(max_examples=40, deadline=None)
@given(s=st.floats(100.0, 5e4), l1=st.floats(0.1, 3.0), l2=st.floats(0.1, 3.0), b1=st.floats(0.0, 1.2),
       b2=st.floats(0.0, 1.2), m=st.floats(0.0, 200.0), c=st.sampled_from([0.0, 5e4, 1e7, np.inf]),
       modes=st.integers(1, 6))
def test_tensioner_frequencies_scalar_roots_equal_the_array_roots(s, l1, l2, b1, b2, m, c, modes):
    # a handful of roots is iterated in Python floats; the same Illinois steps as the array path
    from chaindrive.vibration import tensioner as T

    few = tensioner_frequencies(s, 2.6, l1, l2, b1, b2, m, c, modes=modes)
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(T, "_SCALAR_ROOTS", 0)
        many = tensioner_frequencies(s, 2.6, l1, l2, b1, b2, m, c, modes=modes)
    np.testing.assert_allclose(few, many, rtol=1e-14, atol=0)


def test_stationary_span_frequencies_kept_and_copied():
    from chaindrive.vibration import TensionerSpan

    s = TensionerSpan(2000.0, 2.6, 0.8, 1.1, 0.3, 0.3, 3.0, 5e4)
    first = s.frequencies(3)
    first[0] = -1.0  # the caller's own copy
    again = s.frequencies(3)
    assert np.array_equal(again, tensioner_frequencies(2000.0, 2.6, 0.8, 1.1, 0.3, 0.3, 3.0, 5e4, modes=3))
