"""The transverse span damping (``SimulationModel.span_damping``, docs/simulation.md "Span
damping"): by default ``α = 2 ζ Ω`` with the resonance check's ``ζ`` at the tooth frequency.

Independent reference: for the viscous term ``−α m v_⊥`` on every pin of a span, each
transverse mode of the span obeys ``q̈ + α q̇ + ω² q = 0`` (the damping is mass-proportional:
the undamped modes decouple), so a plucked span's amplitude decays by ``exp(−α t / 2)`` against
the undamped run whatever its frequency (Rao, *Mechanical Vibrations*, 5th ed., §2.6 for one
mode; mass-proportional damping keeps the undamped modes, its chapter on multidegree-of-freedom
systems). ``span_damping = 0`` leaves the kernels' arithmetic as it was before the term. Both
single-drive integrators take it (the implicit one with its slope in the linearly implicit
step), and so do the batched kernels, each variant with its own rate and each equal to its
single run to the last bit (tests/test_simulation_batched*.py).
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from chaindrive.errors import InputError
from chaindrive.simulation import SimulationModel, SimWheel, assemble, simulate
from chaindrive.simulation._kernel import span_damping_forces
from chaindrive.simulation.results import State
from chaindrive.simulation.steady import steady_state

P, Z, N, EA, Q = 0.0254, 16, 60, 1.0e7, 2.6
TENSION = 500.0


def _model(alpha=0.0):
    # two locked 16-tooth sprockets, exact polygon centre distance (N - z)/2 p, pretensioned
    # by the links' prestrain; no gravity, friction or link damping
    a = (N - Z) / 2 * P
    wheels = [SimWheel.at((0.0, 0.0), Z, 0.01, "speed", 0.0), SimWheel.at((a, 0.0), Z, 0.01, "speed", 0.0)]
    return SimulationModel(pitch=P, links=N, link_mass=Q * P, axial_stiffness=EA, roller_radius=0.00794,
                           wheels=wheels, gravity=(0.0, 0.0), friction=0.0, link_damping_ratio=0.0,
                           prestrain=TENSION / EA, span_damping=alpha)


def _plucked(m):
    st = assemble(m)
    pos = st.pos
    top = np.where((pos[:, 1] > 0.5 * P / math.sin(math.pi / Z) * 0.99)
                   & (pos[:, 0] > 0.0) & (pos[:, 0] < (N - Z) / 2 * P))[0]
    x0, x1 = pos[top, 0].min(), pos[top, 0].max()
    vel = st.vel.copy()
    vel[top, 1] = 0.02 * np.sin(math.pi * (pos[top, 0] - x0) / (x1 - x0))  # mode 1, 20 mm/s
    mid = top[np.argmin(np.abs(pos[top, 0] - 0.5 * (x0 + x1)))]
    return State(pos.copy(), vel, st.ws.copy(), st.wp, st.gd, st.par), mid


@pytest.mark.parametrize("method", ["explicit", "implicit"])
def test_plucked_span_decays_at_half_alpha(method):
    # implicit: the damping's slope in the pins' 2 x 2 blocks, at the model's accurate step
    alpha, t_end = 4.0, 0.4
    undamped = _model()
    st, mid = _plucked(undamped)
    runs = {}
    for a in (0.0, alpha):
        r = simulate(dataclasses.replace(undamped, span_damping=a), t_end, state=st, samples=4000,
                     method=method)
        t = np.asarray(r.time)
        y = r.positions[:, mid, 1] - st.pos[mid, 1]
        runs[a] = (t, y)
    t, y0 = runs[0.0]
    _, y1 = runs[alpha]
    late = t > t_end - 0.1  # more than one period of the mode (about 22 Hz)
    ratio = np.abs(y1[late]).max() / np.abs(y0[late]).max()
    assert ratio == pytest.approx(math.exp(-alpha * (t_end - 0.05) / 2), rel=0.05)
    assert np.abs(y0[late]).max() > 1e-5  # the pluck is there


def test_rigid_rotation_of_a_polygon_feels_no_force():
    # pins on a regular polygon turning rigidly: each moves along the chord of its neighbours
    n, om = 17, 20.0
    phi = 2 * math.pi * np.arange(n) / n
    x, y = 0.1 * np.cos(phi), 0.1 * np.sin(phi)
    vx, vy = -om * y, om * x
    fx, fy = np.zeros(n), np.zeros(n)
    span_damping_forces(x, y, vx, vy, fx, fy, 5.0)
    assert np.abs(fx).max() < 1e-12 and np.abs(fy).max() < 1e-12
    # and a straight chain translating along itself
    x, y = np.arange(n) * P, np.zeros(n)
    fx, fy = np.zeros(n), np.zeros(n)
    span_damping_forces(x[1:-1], y[1:-1], np.ones(n - 2), np.zeros(n - 2), fx[1:-1], fy[1:-1], 5.0)
    assert np.abs(fx[2:-2]).max() == 0.0 and np.abs(fy[2:-2]).max() == 0.0


def test_transverse_velocity_is_damped_normal_to_the_chord():
    x, y = np.array([0.0, P, 2 * P]), np.zeros(3)
    fx, fy = np.zeros(3), np.zeros(3)
    span_damping_forces(x, y, np.array([0.0, 1.0, 0.0]), np.array([0.0, 0.3, 0.0]), fx, fy, 2.0)
    assert fx[1] == pytest.approx(0.0, abs=1e-15) and fy[1] == pytest.approx(-0.6)


def test_implicit_matrix_is_the_forces_velocity_slope():
    # the implicit step's 2 x 2 block per pin, coef n nᵀ, is minus the Jacobian of
    # span_damping_forces in the pin's own velocity (linear: one difference is exact)
    from chaindrive.simulation._implicit import _span_damping_matrix

    rng = np.random.default_rng(3)
    n, cs = 9, 2.5
    x, y = rng.normal(size=n), rng.normal(size=n)
    mxx, mxy, myy = np.zeros(n), np.zeros(n), np.zeros(n)
    _span_damping_matrix(x, y, mxx, mxy, myy, cs)
    for i in range(n):
        for d, col in ((0, (mxx[i], mxy[i])), (1, (mxy[i], myy[i]))):
            v = [np.zeros(n), np.zeros(n)]
            v[d][i] = 1.0
            fx, fy = np.zeros(n), np.zeros(n)
            span_damping_forces(x, y, v[0], v[1], fx, fy, cs)
            assert (-fx[i], -fy[i]) == pytest.approx(col, rel=1e-12, abs=1e-12)
            assert np.count_nonzero(fx) + np.count_nonzero(fy) <= 2  # its own pin only


def test_default_is_zeta_at_the_tooth_frequency():
    # alpha = 2 zeta Omega (Chopra, Dynamics of Structures, 4th ed., 11.4.1: zeta_n = a0/(2 w_n)),
    # Omega = z w of the speed-driven wheel; zeta = 0.02, the resonance check's
    from chaindrive.simulation import link_example, roller_example
    from chaindrive.vibration.excitation import DAMPING_RATIO, span_damping_rate

    m = roller_example(teeth=19, angular_velocity=17.0)
    assert m.span_damping is None
    assert m.tooth_frequency() == pytest.approx(19 * 17.0)
    assert m.span_damping_rate() == pytest.approx(2 * DAMPING_RATIO * 19 * 17.0)
    assert span_damping_rate(340.0, 0.05) == pytest.approx(34.0)
    # a pocket wheel of z pockets seats 2 z links a turn
    lk = link_example(teeth=8, angular_velocity=5.0)
    assert lk.tooth_frequency() == pytest.approx(2 * 8 * 5.0)
    # no wheel with a nominal speed (locked wheels): none; an explicit value wins
    assert _model().span_damping_rate() == 0.0
    assert dataclasses.replace(m, span_damping=0.0).span_damping_rate() == 0.0
    assert dataclasses.replace(m, span_damping=3.5).span_damping_rate() == 3.5


def test_default_follows_a_changed_speed():
    # the rate is resolved when a run starts, so a model replaced at another speed gets its own
    from chaindrive.simulation import roller_example

    m = roller_example(teeth=17, angular_velocity=10.0)
    w0 = dataclasses.replace(m.wheels[0], angular_velocity=20.0)
    m2 = dataclasses.replace(m, wheels=[w0, *m.wheels[1:]])
    assert m2.span_damping_rate() == pytest.approx(2 * m.span_damping_rate())


@pytest.mark.parametrize("call, match", [
    (lambda r: r(-1.0), "frequency"), (lambda r: r(10.0, -0.1), "damping_ratio")])
def test_span_damping_rate_refuses_negative_input(call, match):
    from chaindrive.vibration.excitation import span_damping_rate

    with pytest.raises(InputError, match=match):
        call(span_damping_rate)


def test_negative_span_damping_is_refused():
    with pytest.raises(InputError, match="span_damping"):
        _model(-1.0)


def test_implicit_equals_explicit_with_span_damping():
    # the benchmark drive (benchmarks/_steady.py: 16B, 100 links, 2 x z = 17, 20 rad/s,
    # 200 N m) from its warm start, alpha = 13.6 1/s (zeta = 0.02 at the tooth frequency), the
    # last 10 tooth periods of 0.2 s. The implicit step at its default (accurate) step, 45 us
    # against the explicit 3 us: measured tight-span mean +0.09 % (+0.12 % undamped), slack-span
    # mean +1.3 % (+2.7 % undamped), peak -0.4 %; asserted at the implicit method's usual 1 %
    # (tests/test_simulation_implicit.py) and 3 % on the small slack-span tension
    from chaindrive.simulation import roller_example
    from chaindrive.simulation.steady import warm_start

    base = roller_example(links=100, teeth=17, angular_velocity=20.0, load_torque=200.0, ramp_time=0.1)
    m = dataclasses.replace(base, span_damping=13.6)
    start = warm_start(base, assemble(base))
    period = 2 * math.pi / (17 * 20.0)
    means = {}
    for method in ("explicit", "implicit"):
        r = simulate(m, 0.2, state=start, method=method, samples=4000)
        t = np.asarray(r.time) - r.time[0]
        sel = t >= 0.2 - 10 * period
        means[method] = (r.tight_side_tension()[sel].mean(), r.slack_side_tension()[sel].mean())
    (te, se), (ti, si) = means["explicit"], means["implicit"]
    assert ti == pytest.approx(te, rel=0.01)
    assert si == pytest.approx(se, rel=0.03)


def test_steady_state_implicit_takes_span_damping():
    # the implicit steady state of a damped drive: the explicit one's mean within the 2 % of
    # steady_state's contract, and below the undamped one (the slack span stops ringing)
    from chaindrive.simulation import roller_example

    m = roller_example(links=40, teeth=16, angular_velocity=5.0, load_torque=50.0, span_damping=20.0)
    si = steady_state(m, method="implicit")
    se = steady_state(m, method="explicit")
    assert si.method == "implicit" and si.settled
    assert si.mean_tension == pytest.approx(se.mean_tension, rel=0.02)
    assert si.mean_tension < steady_state(dataclasses.replace(m, span_damping=0.0)).mean_tension


def test_batched_steady_states_of_damped_variants_equal_the_single_runs():
    # variants of one drive with different span damping (0, 5.3, 13.6 1/s) in one batch: each
    # batched steady state (explicit kernel and implicit lanes) equal to the last bit to the
    # single run's (steady_state alone: explicit at the batch step; implicit at its defaults)
    from chaindrive.simulation import roller_example
    from chaindrive.simulation.steady_batch import batch_step, steady_states
    from chaindrive.simulation.steady_lanes import steady_states_implicit

    ms = [roller_example(links=40, teeth=12, angular_velocity=w, load_torque=50.0, gravity=False,
                         span_damping=a) for w, a in ((10.0, 0.0), (12.0, 5.3), (14.0, 13.6))]
    opts = dict(periods=2, max_settle=4, min_settle_time=0.0)
    for m, got in zip(ms, steady_states(ms, **opts), strict=True):
        single = steady_state(m, method="explicit", dt=batch_step(m), **opts)
        assert (got.mean_tension, got.peak_tension) == (single.mean_tension, single.peak_tension)
        np.testing.assert_array_equal(got.waveform, single.waveform)
    for m, got in zip(ms, steady_states_implicit(ms, lanes=2, **opts), strict=True):
        single = steady_state(m, **opts)
        assert (got.mean_tension, got.peak_tension, got.settle_time, got.method, got.dt) == \
            (single.mean_tension, single.peak_tension, single.settle_time, single.method, single.dt)
        np.testing.assert_array_equal(got.waveform, single.waveform)
