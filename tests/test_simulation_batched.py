"""Many drives stepped together (``chaindrive.simulation._batched``, ``steady_batch``).

The batched kernel does each variant's arithmetic in the single kernel's order, so the
reference is the single-drive kernel itself: positions, velocities, wheel states and
recorded tensions equal to the last bit (tolerance 0), and the batched steady states
equal to ``steady_state(method="explicit", dt=batch_step(model))`` (relative 1e-12 on the
statistics; they are in fact bit-equal). Every error path. No timing here
(benchmarks/simulate.py prints the batched rate).
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from chaindrive import chains
from chaindrive.drive.model import Conveyor, Drive, Load, Tensioner, Wheel
from chaindrive.errors import InputError
from chaindrive.simulation import SimWheel, link_example, roller_example
from chaindrive.simulation import _kernel as K
from chaindrive.simulation._batched import LANES, empty_batch_records, integrate_batch, stack_tables
from chaindrive.simulation.from_drive import model_from_drive
from chaindrive.simulation.steady import steady_state, warm_start
from chaindrive.simulation.steady_batch import batch_step, steady_states

STEPS, EVERY = 1500, 100


def _single(st, nsteps=STEPS, every=EVERY):
    pos, vel, ws = st.pos.copy(), st.vel.copy(), st.ws.copy()
    n, nw = pos.shape[0], ws.shape[0]
    recs = K.empty_records(nsteps // every, n, nw, 1)
    K.integrate(pos, vel, np.zeros_like(pos), np.zeros_like(pos), np.zeros(n), np.zeros(n), ws,
                st.wp, st.gd, K.seat_table(st.wp), st.par, st.time, nsteps, every,
                np.zeros((1, 4)), *recs, 0)
    return pos, vel, ws, recs


def _batched(states, nsteps=STEPS, every=EVERY):
    arrays = [np.stack([getattr(s, a) for s in states]) for a in ("pos", "vel", "ws", "wp", "gd",
                                                                    "par")]
    pos, vel, ws, wp, gd, par = arrays
    recs = empty_batch_records(len(states), nsteps // every, pos.shape[1], ws.shape[1])
    written = integrate_batch(pos, vel, ws, wp, gd, stack_tables([K.seat_table(s.wp) for s in states]),
                              par, np.array([s.time for s in states]), nsteps, every, *recs)
    return pos, vel, ws, recs, written


def _idler_drive(load):
    """The roller drive with a free toothless idler under its slack span (the rim contact)."""
    m = roller_example(links=100, teeth=17, angular_velocity=10.0, load_torque=load)
    idler = SimWheel.at((m.wheels[1].centre[0] / 2, -0.25), 3, 2e-3, "free", name="idler",
                        plain_radius=0.06)
    return dataclasses.replace(m, wheels=[m.wheels[0], idler, *m.wheels[1:]])


def _conveyor(material):
    """A 4 m 18x64 conveyor on pans with material, the tail on a spring slide: guides, the
    scraped material's inertia and a slide (tests/test_simulation_conveyor.py's drive)."""
    wheels = (Wheel("head", "pocket_wheel", 8, (0.0, 0.0), driving=True),
              Wheel("tail", "pocket_wheel", 8, (4.0, 0.0)))
    return model_from_drive(Drive(
        chain=chains.get("18x64"), wheels=wheels, speed=5.0, load=Load(power=10e3),
        tensioner=Tensioner("tail", 200.0, 1e6, "spring", (1.0, 0.0), 20e3),
        conveyor=Conveyor(return_strand="supported", material_load=material)))


@pytest.mark.parametrize("models", [
    # roller chain on ISO 606 sprockets: speeds, loads and (so) time steps differ
    [roller_example(links=50, teeth=12, angular_velocity=w, load_torque=tq)
     for w, tq in ((20.0, 60.0), (28.0, 30.0), (14.0, 120.0))],
    # round-link chain on pocket wheels (bi-regular seats), different loads
    [link_example(load_torque=tq) for tq in (200.0, 800.0)],
    # a toothless idler (rim contact, a free wheel)
    [_idler_drive(tq) for tq in (80.0, 150.0)],
    # pans with material (guides, the material's inertia), a tensioner on a slide
    [_conveyor(mat) for mat in (40.0, 60.0)],
])
def test_batched_kernel_equals_the_single_kernel_per_variant(models):
    states = [warm_start(m) for m in models]
    for st, m in zip(states, models, strict=True):
        st.par[K.P_DT] = m.stable_time_step()
    pos, vel, ws, recs, written = _batched(states)
    assert written == STEPS // EVERY
    for v, st in enumerate(states):
        p1, v1, w1, r1 = _single(st)
        np.testing.assert_array_equal(pos[v], p1)
        np.testing.assert_array_equal(vel[v], v1)
        np.testing.assert_array_equal(ws[v], w1)
        np.testing.assert_array_equal(recs[0][v], r1[0])   # times
        np.testing.assert_array_equal(recs[1][v], r1[2])   # link tensions
        np.testing.assert_array_equal(recs[2][v], r1[4])   # wheel states
        np.testing.assert_array_equal(recs[3][v], r1[5])   # positions


#: span damping rates [1/s] of the variants of one batch: none, and two others (each variant
#: its own, as the drives' own rates from their tooth frequencies)
ALPHAS = (0.0, 5.3, 13.6)


def damped(models, alphas=ALPHAS):
    """The models with the span damping ``alphas`` (cycled), one rate per variant."""
    return [dataclasses.replace(m, span_damping=alphas[v % len(alphas)])
            for v, m in enumerate(models)]


@pytest.mark.parametrize("family", ["roller", "round-link", "idler", "conveyor"])
def test_span_damping_per_variant_equals_the_single_kernel(family):
    # variants of different span damping (0, 5.3, 13.6 1/s) batched together: each one equal
    # to the single kernel to the last bit, and the term really on (a damped variant's
    # velocities differ from its undamped run)
    base = {"roller": [roller_example(links=50, teeth=12, angular_velocity=w, load_torque=tq)
                       for w, tq in ((20.0, 60.0), (28.0, 30.0), (14.0, 120.0))],
            "round-link": [link_example(load_torque=tq) for tq in (200.0, 800.0, 500.0)],
            "idler": [_idler_drive(tq) for tq in (80.0, 150.0, 110.0)],
            "conveyor": [_conveyor(mat) for mat in (40.0, 60.0, 50.0)]}[family]
    models = damped(base)
    states = [warm_start(m) for m in models]
    for st, m in zip(states, models, strict=True):
        st.par[K.P_DT] = m.stable_time_step()
    assert [st.par[K.P_CSPAN] for st in states] == list(ALPHAS)
    pos, vel, ws, recs, _ = _batched(states)
    for v, st in enumerate(states):
        p1, v1, w1, r1 = _single(st)
        np.testing.assert_array_equal(pos[v], p1)
        np.testing.assert_array_equal(vel[v], v1)
        np.testing.assert_array_equal(ws[v], w1)
        np.testing.assert_array_equal(recs[1][v], r1[2])
        np.testing.assert_array_equal(recs[3][v], r1[5])
    undamped = states[2].par.copy()
    undamped[K.P_CSPAN] = 0.0
    assert not np.array_equal(vel[2], _single(dataclasses.replace(states[2], par=undamped))[1])


def test_more_variants_than_one_block_of_lanes():
    # LANES + 2 variants: two blocks of the contact loop, the second one partly filled
    # (one drive, each variant with its own link damping, the last two with span damping)
    model = roller_example(links=30, teeth=9, angular_velocity=10.0, load_torque=20.0, gravity=False)
    start = warm_start(model)
    states = []
    for v in range(LANES + 2):
        par = start.par.copy()
        par[K.P_DT] = model.stable_time_step()
        par[K.P_C] *= 1.0 + 0.01 * v
        # the span damping in the second block only (a block without it, one with)
        par[K.P_CSPAN] = 0.0 if v < LANES else ALPHAS[1 + v % 2]
        states.append(dataclasses.replace(start, par=par))
    pos, vel, ws, _, _ = _batched(states, 300, 100)
    for v in (0, LANES - 1, LANES, LANES + 1):
        p1, v1, w1, _ = _single(states[v], 300, 100)
        np.testing.assert_array_equal(pos[v], p1)
        np.testing.assert_array_equal(vel[v], v1)
        np.testing.assert_array_equal(ws[v], w1)


def test_seat_tables_padded_to_the_largest_wheel():
    a = K.seat_table(warm_start(roller_example(links=40, teeth=9, gravity=False)).wp)
    b = K.seat_table(warm_start(roller_example(links=40, teeth=13, gravity=False)).wp)
    t = stack_tables([a, b])
    assert t.shape == (2, 2, 13, 6)
    np.testing.assert_array_equal(t[0, :, :9], a)
    assert not t[0, :, 9:].any()


MODELS = [roller_example(links=40, teeth=12, angular_velocity=w, load_torque=tq)
          for w, tq in ((20.0, 50.0), (23.0, 80.0), (26.0, 30.0))]
OPTS = dict(periods=3, max_settle=6, min_settle_time=0.0)


@pytest.fixture(scope="module", params=["undamped", "damped"])
def batched(request):
    """The models (without span damping, or with 0, 5.3, 13.6 1/s) and their batched
    steady states."""
    models = damped(MODELS, (0.0,) if request.param == "undamped" else ALPHAS)
    return models, steady_states(models, **OPTS)


@pytest.mark.parametrize("v", range(len(MODELS)))
def test_batched_steady_state_equals_the_single_run(batched, v):
    models, out = batched
    single = steady_state(models[v], method="explicit", dt=batch_step(models[v]), **OPTS)
    got = out[v]
    for name in ("mean_tension", "peak_tension", "period_peak_tension", "max_tension",
                 "min_tension", "settle_time", "measured_time", "dt", "chain_speed"):
        assert getattr(got, name) == pytest.approx(getattr(single, name), rel=1e-12, abs=0), name
    np.testing.assert_allclose(got.waveform, single.waveform, rtol=1e-12, atol=0)
    assert got.settled == single.settled
    assert got.method == single.method == "explicit"
    assert got.cpu_time > 0.0


def test_a_drive_s_result_does_not_depend_on_its_batch(batched):
    models, out = batched
    alone = steady_states(models[1:2], **OPTS)[0]
    assert alone.peak_tension == out[1].peak_tension
    assert alone.mean_tension == out[1].mean_tension


def test_the_batch_step_is_a_whole_fraction_of_the_tooth_period_within_the_stable_step():
    for m in MODELS:
        dt = batch_step(m)
        period = 2.0 * np.pi / (m.seats_per_turn(m.wheels[0].teeth) * m.wheels[0].angular_velocity)
        steps = period / dt
        assert abs(steps - round(steps)) < 1e-9
        assert 0.91 * m.stable_time_step() < dt <= m.stable_time_step()


@pytest.mark.parametrize("kwargs, match", [
    (dict(batch=0), "batch must be a whole number from 1 to 4096"),
    (dict(batch=2.5), "batch must be a whole number"),
    (dict(periods=0), "periods must be a whole number from 1"),
    (dict(settle_tolerance=1.5), r"settle_tolerance must be in \(0, 1\)"),
    (dict(min_settle_time=-1.0), "min_settle_time must be >= 0 s"),
    (dict(states=[None, None]), r"states: one per drive \(1\), got 2"),
])
def test_bad_arguments_are_refused_by_name(kwargs, match):
    with pytest.raises(InputError, match=match):
        steady_states(MODELS[:1], **kwargs)


def test_a_drive_without_a_driver_is_refused():
    m = roller_example(links=40, teeth=12, gravity=False, angular_velocity=0.0)
    with pytest.raises(InputError, match="speed is 0|driven at a prescribed speed"):
        steady_states([m])
    with pytest.raises(InputError, match="takes a chaindrive.drive.Drive or a SimulationModel"):
        steady_states(["not a drive"])
