"""The linearly implicit integrator (``simulate(..., method="implicit")``).

Its banded (cyclic tridiagonal) solve against a dense solve, the conservation laws of a
free chain loop, and the validation cases of docs/simulation.md run with both
integrators: the implicit step must give the explicit one's results. No timing here
(speed figures: benchmarks/simulate.py).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from chaindrive.errors import InputError, UnknownNameError
from chaindrive.simulation import _kernel as K
from chaindrive.simulation import assemble, link_example, roller_example, simulate
from chaindrive.simulation._implicit import cyclic_tridiagonal_solve, integrate_implicit


def _cyclic(d, e):
    n = len(d)
    a = np.diag(d)
    for i in range(n):
        j = (i + 1) % n
        a[i, j] += e[i]
        a[j, i] += e[i]
    return a


@pytest.mark.parametrize("n", [3, 4, 5, 8, 101])
def test_cyclic_tridiagonal_solve_equals_dense_solve(n):
    rng = np.random.default_rng(n)
    e = rng.normal(size=n)
    # symmetric positive definite (diagonally dominant), like 1/a + G W Gᵀ
    d = np.abs(e) + np.abs(np.roll(e, 1)) + rng.uniform(0.01, 1.0, n)
    b = rng.normal(size=n)
    x = np.empty(n)
    cyclic_tridiagonal_solve(d, e, b, x)
    np.testing.assert_allclose(x, np.linalg.solve(_cyclic(d, e), b), rtol=1e-10, atol=1e-12)


@pytest.mark.parametrize("n", [3, 4, 7, 101])
def test_fused_solves_equal_the_separate_ones_to_the_last_bit(n):
    # _factor_solve4 (the implicit step's link system with up to three wheel unknowns)
    # against the factorisation and one substitution per right-hand side: the same
    # arithmetic, so bit-equal; and the solution against the dense solve
    from chaindrive.simulation._banded import (
        _factor_solve4,
        cyclic_tridiagonal_factor,
        cyclic_tridiagonal_substitute,
    )

    rng = np.random.default_rng(n)
    e = rng.normal(size=n)
    d = np.abs(e) + np.abs(np.roll(e, 1)) + rng.uniform(0.01, 1.0, n)
    bs = rng.normal(size=(4, n))
    idd, ff = np.empty(n), np.empty(n)
    dlast = cyclic_tridiagonal_factor(d, e, idd, ff)
    sep = np.empty_like(bs)
    for k in range(4):
        cyclic_tridiagonal_substitute(e, idd, ff, dlast, bs[k], sep[k])
    idd4, ff4 = np.empty(n), np.empty(n)
    four = bs.copy()
    dlast4 = _factor_solve4(d, e, idd4, ff4, four[0], four[1], four[2], four[3], True)
    two = bs.copy()
    dlast2 = _factor_solve4(d, e, np.empty(n), np.empty(n), two[0], two[1], two[2], two[3],
                            False)
    assert dlast4 == dlast2 == dlast
    assert np.array_equal(two[:2], sep[:2]) and np.array_equal(two[2:], bs[2:])
    # (entry n - 1 of the factors is not used)
    assert np.array_equal(idd4[:-1], idd[:-1]) and np.array_equal(ff4[:-1], ff[:-1])
    assert np.array_equal(four, sep)
    np.testing.assert_allclose(four.T, np.linalg.solve(_cyclic(d, e), bs.T), rtol=1e-10,
                               atol=1e-12)


def test_cyclic_tridiagonal_solve_chain_laplacian():
    # the integrator's matrix for a straight-sided loop: 1/a + h/m (2, -1 cyclic), nearly
    # singular (1/a ≪ h/m): the loop's uniform-tension mode
    n, hm, inv_a = 500, 1.5e-3, 2.6e-6
    d = np.full(n, inv_a + 2 * hm)
    e = np.full(n, -hm)
    b = np.random.default_rng(0).normal(size=n)
    x = np.empty(n)
    cyclic_tridiagonal_solve(d, e, b, x)
    a = _cyclic(d, e)
    assert np.linalg.norm(a @ x - b) / np.linalg.norm(b) < 1e-9


def _free_loop(n=60, omega=30.0, drift=(0.3, -0.2), steps=4000, dt=2e-5, damping=0.0):
    """A free closed loop of links (no wheels, no gravity) spinning and drifting."""
    p, m = 0.0254, 0.066
    radius = p / (2 * math.sin(math.pi / n))
    a = 2 * math.pi * np.arange(n) / n
    pos = np.column_stack([radius * np.cos(a), radius * np.sin(a)])
    vel = omega * np.column_stack([-pos[:, 1], pos[:, 0]]) + np.asarray(drift)
    par = np.zeros(K.NPAR)
    par[K.P_MASS] = m
    par[K.P_K] = 1e8 / p
    par[K.P_C] = damping
    par[K.P_PITCH] = par[K.P_PITCH2] = p
    par[K.P_RROLLER] = 0.005
    par[K.P_DT] = dt
    par[K.P_DTREF] = 6e-6
    par[K.P_VEPS] = 1e-3
    par[K.P_THETA] = 1.0
    ws = np.zeros((0, 6))
    wp = np.zeros((0, K.NWP))
    gd = np.zeros((0, K.NGD))
    tab = np.zeros((0, 1, 6))
    nrec = max(steps // 100, 1)
    recs = K.empty_records(nrec, n, 0, 0)
    integrate_implicit(pos, vel, np.zeros_like(pos), np.zeros_like(pos), np.zeros(n), np.zeros(n),
                       ws, wp, gd, tab, par, 0.0, steps, 100, np.zeros((0, 4)), *recs, 0)
    return pos, vel, m, recs


def test_free_loop_conserves_momentum_and_does_not_gain_energy():
    n = 60
    p0, v0, m, _ = _free_loop(n, steps=0)
    pos, vel, m, recs = _free_loop(n)
    # linear momentum: the link forces are internal
    np.testing.assert_allclose(vel.sum(axis=0), v0.sum(axis=0), rtol=1e-9, atol=1e-9)
    # angular momentum about the origin: central link forces, x ← x + h v⁺
    def ang(p, v):
        return float(np.sum(p[:, 0] * v[:, 1] - p[:, 1] * v[:, 0]))
    assert ang(pos, vel) == pytest.approx(ang(p0, v0), rel=1e-9)
    # energy: the implicit step dissipates only the unresolved stiff (axial) motion
    energy = recs[-1]
    assert np.all(np.diff(energy) <= 1e-9 * abs(energy[0]))
    assert energy[-1] == pytest.approx(energy[0], rel=0.01)
    # the loop keeps its links' length (to the centrifugal strain)
    lengths = np.hypot(*(np.roll(pos, -1, axis=0) - pos).T)
    assert np.max(np.abs(lengths / 0.0254 - 1.0)) < 1e-4


def test_unknown_method_and_bad_step_are_refused():
    m = roller_example(links=30, teeth=11)
    with pytest.raises(UnknownNameError, match="method must be one of explicit, implicit"):
        simulate(m, 0.01, method="rk4")
    with pytest.raises(InputError, match="dt"):
        simulate(m, 0.01, dt=-1e-5, method="implicit")


def _means(r, teeth, omega, periods=4):
    sel = r.time >= r.time[-1] - periods * 2 * np.pi / teeth / omega
    return float(np.mean(r.chain_velocity[sel, 0])), float(np.mean(r.tight_side_tension()[sel]))


def test_implicit_equals_explicit_on_the_roller_drive():
    # the time-step halving case of test_simulation.py: friction, damping, load
    teeth, w = 16, 10.0
    m = roller_example(links=40, teeth=teeth, angular_velocity=w, load_torque=100.0,
                       pretension=2000.0, ramp_time=0.05)
    st = assemble(m)
    ve, se = _means(simulate(m, 0.3, state=st), teeth, w)
    # the implicit step's error is first order (its numerical damping of the resolved
    # span dynamics): measured mean tension -9.5 %, -4.6 %, -1.9 %, -0.7 %, -0.1 % at
    # 100, 45 (the default step), 22, 11, 5 µs against the explicit 3 µs
    r = simulate(m, 0.3, state=st, method="implicit", dt=1.1e-5)
    vi, si = _means(r, teeth, w)
    assert vi == pytest.approx(ve, rel=0.002)
    assert si == pytest.approx(se, rel=0.01)
    assert m.accurate_time_step() == pytest.approx(15 * m.stable_time_step())


def test_implicit_static_tension_equals_load_over_pitch_radius():
    load = 100.0
    m = roller_example(links=40, teeth=16, angular_velocity=0.0, load_torque=load,
                       gravity=False, pretension=200.0)
    r = simulate(m, 0.01, samples=20, method="implicit")
    tight = float(np.mean(r.tight_side_tension()[-5:]))
    slack = float(np.mean(r.slack_side_tension()[-5:]))
    assert tight - slack == pytest.approx(load / r.pitch_radii[1], rel=0.005)


def test_implicit_rigid_limit_free_entry_chordal_speed():
    # test_simulation.py's rigid-limit case with the implicit step
    teeth, omega = 12, 2.0
    m = roller_example(links=40, teeth=teeth, angular_velocity=omega, load_torque=20.0,
                       ramp_time=0.05, gravity=False)
    r = simulate(m, 0.6, samples=3000, method="implicit")
    radius = r.pitch_radii[0]
    ph = np.mod(r.wheel_angle[:, 0] - np.pi / 2 + np.pi / teeth, 2 * np.pi / teeth) - np.pi / teeth
    law = r.wheel_speed[:, 0] * radius * np.cos(ph)
    sel = (r.time > 0.15) & (np.abs(np.abs(ph) - np.pi / teeth) > 0.05 * 2 * np.pi / teeth)
    v = r.chain_velocity[sel, 0]
    assert np.max(np.abs(v - law[sel])) / float(np.mean(law[sel])) < 0.01


def test_implicit_round_link_chain_mean_speed():
    omega, z, t = 2.0, 8, 0.064
    m = link_example(links=40, angular_velocity=omega, load_torque=500.0, ramp_time=0.05,
                     gravity=True)
    period = 2 * np.pi / z / omega
    r = simulate(m, 0.2 + 3 * period, samples=6000, method="implicit")
    sel = r.time >= r.time[-1] - 3 * period
    assert float(np.mean(r.chain_velocity[sel, 0])) == pytest.approx(2 * t * z * omega / (2 * np.pi),
                                                                     rel=0.005)


def test_step_for_accuracy_returns_a_step_that_holds_against_its_half():
    from chaindrive.simulation.run import step_for_accuracy

    m = roller_example(links=30, teeth=11, angular_velocity=5.0, load_torque=20.0, ramp_time=0.005,
                       gravity=False)
    st = assemble(m)
    dt = step_for_accuracy(m, 0.03, state=st, tolerance=0.01)
    a = simulate(m, 0.03, state=st, dt=dt, method="implicit", samples=400).summary
    b = simulate(m, 0.03, state=st, dt=dt / 2, method="implicit", samples=400).summary
    assert a["tight_side_tension_mean"] == pytest.approx(b["tight_side_tension_mean"], rel=0.01)
    assert a["chain_velocity_mean"][0] == pytest.approx(b["chain_velocity_mean"][0], rel=0.01)


def test_step_for_accuracy_errors():
    from chaindrive.errors import ConvergenceError
    from chaindrive.simulation.run import step_for_accuracy

    m = roller_example(links=30, teeth=11, angular_velocity=5.0, ramp_time=0.005)
    with pytest.raises(InputError, match="tolerance must be in"):
        step_for_accuracy(m, 0.01, tolerance=0.0)
    with pytest.raises(ConvergenceError, match="no step from"):
        step_for_accuracy(m, 0.01, tolerance=1e-9, max_halvings=1)
    # the API fuzz at 10,000 inputs (seed 20261129): tolerance 5e-324 with 19 halvings ran 37 s
    with pytest.raises(InputError, match=r"tolerance must be in \[1e-9, 1\)"):
        step_for_accuracy(m, 0.01, tolerance=5e-324)
    with pytest.raises(InputError, match=r"max_halvings must be a whole number in \[0, 10\]"):
        step_for_accuracy(m, 0.01, max_halvings=19)
