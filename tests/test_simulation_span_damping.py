"""The optional transverse span damping (``SimulationModel.span_damping``, a study:
docs/simulation.md "Span damping: a study").

Independent reference: for the viscous term ``−α m v_⊥`` on every pin of a span, each
transverse mode of the span obeys ``q̈ + α q̇ + ω² q = 0`` (the damping is mass-proportional:
the undamped modes decouple), so a plucked span's amplitude decays by ``exp(−α t / 2)`` against
the undamped run whatever its frequency (Rao, *Mechanical Vibrations*, 5th ed., §2.6 for one
mode; mass-proportional damping keeps the undamped modes, its chapter on multidegree-of-freedom
systems). The default (0) leaves the kernel's arithmetic as it was: the
calibration cache (tests/test_running_tension.py, slow) checks that to the last bit.
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


def test_plucked_span_decays_at_half_alpha():
    alpha, t_end = 4.0, 0.4
    undamped = _model()
    st, mid = _plucked(undamped)
    runs = {}
    for a in (0.0, alpha):
        r = simulate(dataclasses.replace(undamped, span_damping=a), t_end, state=st, samples=4000)
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


def test_negative_span_damping_is_refused():
    with pytest.raises(InputError, match="span_damping"):
        _model(-1.0)


def test_implicit_integrator_refuses_span_damping():
    m = _model(2.0)
    with pytest.raises(InputError, match="explicit integrator only"):
        simulate(m, 1e-3, method="implicit")


def test_steady_state_implicit_refuses_span_damping():
    from chaindrive.simulation import roller_example

    m = roller_example(links=40, teeth=16, angular_velocity=5.0, load_torque=50.0, span_damping=2.0)
    with pytest.raises(InputError, match="explicit integrator only"):
        steady_state(m, method="implicit")
