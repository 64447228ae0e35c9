"""Many drives stepped together, linearly implicit (``chaindrive.simulation._batched_implicit``).

The batched kernel does each lane's arithmetic in the single implicit kernel's order, so
the reference is :func:`chaindrive.simulation._implicit.integrate_implicit` itself:
positions, velocities, wheel states and the recorded times, link tensions, wheel states
and positions equal to the last bit (tolerance 0), whatever the other lanes do (their
step counts, where a call stops, a lane started again while the others go on). No
timing here (benchmarks/simulate.py prints the batched implicit rate).
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from chaindrive.simulation import _kernel as K
from chaindrive.simulation import link_example, roller_example
from chaindrive.simulation._batched_implicit import Lanes, integrate_implicit_lanes
from chaindrive.simulation._implicit import integrate_implicit
from chaindrive.simulation._lane_passes import BLOCK
from chaindrive.simulation.steady import warm_start
from test_simulation_batched import ALPHAS, _conveyor, _idler_drive, damped


def _single(model, st, nsteps, every):
    """One call of the single implicit kernel at the model's accurate step."""
    par = st.par.copy()
    par[K.P_DT] = model.accurate_time_step()
    pos, vel, ws = st.pos.copy(), st.vel.copy(), st.ws.copy()
    n, nw = pos.shape[0], ws.shape[0]
    recs = K.empty_records((nsteps + every - 1) // every, n, nw, 1)
    written = integrate_implicit(pos, vel, np.zeros_like(pos), np.zeros_like(pos), np.zeros(n),
                                 np.zeros(n), ws, st.wp, st.gd, K.seat_table(st.wp), par, st.time,
                                 nsteps, every, np.zeros((1, 4)), *recs, 0)
    return pos, vel, ws, recs, written, par


def _lanes(models, states, records=64):
    tabs = [K.seat_table(s.wp) for s in states]
    st = states[0]
    return Lanes(len(states), st.pos.shape[0], st.ws.shape[0], st.gd.shape[0],
                 max(t.shape[1] for t in tabs), records), tabs


def _load(lanes, v, model, st, tab, nsteps, every):
    par = st.par.copy()
    par[K.P_DT] = model.accurate_time_step()
    lanes.load(v, st.pos, st.vel, st.ws, st.wp, st.gd, tab, par, st.time, nsteps, every)


def _assert_lane_equals(lanes, v, single):
    pos, vel, ws, recs, written, _ = single
    p, q, w = lanes.state(v)
    np.testing.assert_array_equal(p, pos)
    np.testing.assert_array_equal(q, vel)
    np.testing.assert_array_equal(w, ws)
    assert lanes.nrec[v] == written
    np.testing.assert_array_equal(lanes.rec_t[v, :written], recs[0][:written])
    np.testing.assert_array_equal(lanes.rec_tension[v, :written], recs[2][:written])
    np.testing.assert_array_equal(lanes.rec_ws[v, :written], recs[4][:written])
    np.testing.assert_array_equal(lanes.rec_pos[v, :written], recs[5][:written])


def _run(lanes, chunk=10**9):
    calls = 0
    while lanes.active.any():
        assert integrate_implicit_lanes(*lanes.arrays(), chunk) > 0
        calls += 1
    return calls


@pytest.mark.parametrize("models", [
    # roller chain on ISO 606 sprockets: speeds, loads, gravity and (so) steps differ
    [roller_example(links=40, teeth=12, angular_velocity=w, load_torque=tq, gravity=g)
     for w, tq, g in ((10.0, 50.0, True), (14.0, 60.0, False), (20.0, 70.0, True))],
    # round-link chain on pocket wheels (bi-regular seats), different loads
    [link_example(load_torque=tq) for tq in (200.0, 800.0)],
    # a toothless idler (rim contact; two free wheels: two border rows)
    [_idler_drive(tq) for tq in (80.0, 150.0)],
    # pans with material (guides, the material's inertia), a tensioner on a slide
    [_conveyor(mat) for mat in (40.0, 60.0)],
], ids=["roller", "round-link", "idler", "conveyor"])
def test_each_lane_equals_the_single_implicit_kernel(models):
    states = [warm_start(m) for m in models]
    steps = [240 - 30 * v for v in range(len(models))]   # lanes finish at different calls
    every = [7 + 2 * v for v in range(len(models))]
    lanes, tabs = _lanes(models, states)
    for v, (m, st) in enumerate(zip(models, states, strict=True)):
        _load(lanes, v, m, st, tabs[v], steps[v], every[v])
    assert _run(lanes) == len(set(steps))
    for v, (m, st) in enumerate(zip(models, states, strict=True)):
        _assert_lane_equals(lanes, v, _single(m, st, steps[v], every[v]))


@pytest.mark.parametrize("family", ["roller", "round-link", "idler", "conveyor"])
def test_span_damping_per_lane_equals_the_single_implicit_kernel(family):
    # lanes of different span damping (0, 5.3, 13.6 1/s) stepped together: each one equal to
    # the single implicit kernel to the last bit (the term's force and its slope in the
    # pins' blocks), and the term really on (a damped lane differs from its undamped run)
    base = {"roller": [roller_example(links=40, teeth=12, angular_velocity=w, load_torque=tq,
                                      gravity=g)
                       for w, tq, g in ((10.0, 50.0, True), (14.0, 60.0, False), (20.0, 70.0, True))],
            "round-link": [link_example(load_torque=tq) for tq in (200.0, 800.0, 500.0)],
            "idler": [_idler_drive(tq) for tq in (80.0, 150.0, 110.0)],
            "conveyor": [_conveyor(mat) for mat in (40.0, 60.0, 50.0)]}[family]
    models = damped(base)
    states = [warm_start(m) for m in models]
    assert [st.par[K.P_CSPAN] for st in states] == list(ALPHAS)
    steps = [200 - 30 * v for v in range(len(models))]
    lanes, tabs = _lanes(models, states)
    for v, (m, st) in enumerate(zip(models, states, strict=True)):
        _load(lanes, v, m, st, tabs[v], steps[v], 9)
    _run(lanes)
    for v, (m, st) in enumerate(zip(models, states, strict=True)):
        _assert_lane_equals(lanes, v, _single(m, st, steps[v], 9))
    undamped = dataclasses.replace(models[2], span_damping=0.0)
    assert not np.array_equal(lanes.state(2)[1],
                              _single(undamped, warm_start(undamped), steps[2], 9)[1])


def test_a_segment_split_over_calls_and_a_lane_started_again_change_nothing():
    models = [roller_example(links=40, teeth=12, angular_velocity=w, load_torque=60.0)
              for w in (11.0, 17.0)]
    states = [warm_start(m) for m in models]
    lanes, tabs = _lanes(models, states)
    _load(lanes, 0, models[0], states[0], tabs[0], 200, 9)
    _load(lanes, 1, models[1], states[1], tabs[1], 50, 50)
    # lane 1 finishes first; lane 0 goes on in calls of at most 13 steps
    assert integrate_implicit_lanes(*lanes.arrays(), 10**9) == 50
    assert not lanes.active[1] and lanes.active[0] and lanes.step[0] == 50
    _assert_lane_equals(lanes, 1, _single(models[1], states[1], 50, 50))
    # lane 1 starts a segment of its own from its state now, lane 0 mid-way through its own
    pos, vel, ws = lanes.state(1)
    st1 = states[1]
    later = type(st1)(pos, vel, ws, st1.wp, st1.gd, st1.par, st1.relax_time, st1.relax_steps,
                      st1.time + 50 * models[1].accurate_time_step())
    _load(lanes, 1, models[1], later, tabs[1], 120, 11)
    _run(lanes, chunk=13)
    _assert_lane_equals(lanes, 0, _single(models[0], states[0], 200, 9))
    _assert_lane_equals(lanes, 1, _single(models[1], later, 120, 11))


def test_an_idle_lane_is_left_untouched():
    models = [roller_example(links=40, teeth=12, angular_velocity=w) for w in (10.0, 12.0)]
    states = [warm_start(m) for m in models]
    lanes, tabs = _lanes(models, states)
    _load(lanes, 0, models[0], states[0], tabs[0], 60, 60)
    _load(lanes, 1, models[1], states[1], tabs[1], 0, 1)   # no steps: idle
    assert not lanes.active[1]
    _run(lanes)
    p, q, w = lanes.state(1)
    np.testing.assert_array_equal(p, states[1].pos)
    np.testing.assert_array_equal(q, states[1].vel)
    np.testing.assert_array_equal(w, states[1].ws)
    assert lanes.nrec[1] == 0


def test_more_lanes_than_one_block_of_the_contact_loop():
    # LANES + 2 lanes: two blocks of the slot-wise contact loop, the second partly filled
    from chaindrive.simulation._batched import LANES

    count = LANES + 2
    models = [roller_example(links=40, teeth=12, angular_velocity=8.0 + 0.1 * v, load_torque=50.0)
              for v in range(count)]
    # span damping from the second block of the link passes on (BLOCK lanes a block): a
    # block without it, blocks whose lanes have different rates
    models = models[:BLOCK] + damped(models[BLOCK:], ALPHAS[::-1])
    states = [warm_start(m) for m in models]
    lanes, tabs = _lanes(models, states)
    for v in range(count):
        _load(lanes, v, models[v], states[v], tabs[v], 40 + v % 5, 7)
    _run(lanes)
    for v in (0, BLOCK, BLOCK + 1, LANES - 1, LANES, count - 1):
        _assert_lane_equals(lanes, v, _single(models[v], states[v], 40 + v % 5, 7))
