r"""Steady states of many drives at once, each the same as alone: :func:`steady_states_implicit`.

Each drive follows the rule of :func:`~chaindrive.simulation.steady.steady_state` with its
defaults (warm start, settling at the coarser step detected a tooth period at a time,
the step checked against its half, ``periods`` tooth periods measured, the explicit
integrator where the implicit step does not hold the accuracy), and every call that
``steady_state`` makes of the linearly implicit kernel is made instead by the batched
one (:mod:`._batched_implicit`): the drives of one layout (the same numbers of pins,
wheels and guides) are its lanes, each lane running its drive's calls one after another
while the other lanes run theirs. A lane's arithmetic is the single kernel's, so each
result equals ``steady_state(model, ...)`` to the last bit (``cpu_time`` apart:
``tests/test_simulation_steady_lanes.py``). The explicit measurement of a drive whose
implicit step does not hold runs with the single explicit kernel.
"""

from __future__ import annotations

import dataclasses
import math
import time
from collections.abc import Generator, Sequence
from typing import Any

import numpy as np

from ..errors import InputError
from . import _kernel as K
from ._batched_implicit import Lanes, integrate_implicit_lanes
from .model import SimulationModel
from .results import default_probes, slack_span, tight_span
from .run import INTEGRATORS, State, assemble
from .steady import (
    EXPLICIT_BELOW,
    SETTLE_FACTOR,
    SETTLE_PER_PERIOD,
    SteadyState,
    _driver,
    _driver_speed,
    _model_of,
    _Runner,
    _span_tension,
    check_counts,
    default_settle_time,
    summarise,
    warm_start,
)
from .steady_batch import check_many

__all__ = ["steady_states_implicit"]

# a request of a drive's program: (method, dt, steps, every, state)
_Request = tuple[str, float, int, int, State]
_Reply = tuple[State, np.ndarray, np.ndarray]


class _Steps(_Runner):
    """The step bookkeeping of ``steady._Runner`` (its own ``set_step`` and ``halve``: step,
    steps per period, record interval), without its integrator."""

    def __init__(self, dt: float, period: float, samples: int):  # noqa: D107
        self.set_step(dt, period, samples)

    def request(self, method: str, state: State, count: int = 1) -> _Request:
        steps = count * self.steps
        return method, self.dt, steps, self.every if count == 1 else steps, state


def _program(model: SimulationModel, start: State, drv: int, period: float, dt: float,
             o: dict[str, Any]) -> Generator[_Request, _Reply, tuple[Any, ...]]:
    """The calls of ``steady_state`` for one drive, step for step: yields each integrator
    call as a request, receives ``(state after, tight-span tension, driver angle)``;
    returns the arguments of :func:`~chaindrive.simulation.steady.summarise` after the
    model, start, driver and period."""
    method = "implicit"
    settle_dt = dt
    seg = np.diff(np.vstack([start.pos, start.pos[:1]]), axis=0)
    s_max = max(float(np.max(start.par[K.P_K] * (np.hypot(seg[:, 0], seg[:, 1])
                                                 - start.par[K.P_PITCH]))), 1.0)
    transverse = 2.0 / (2.0 * math.sqrt(1.5 * s_max / (model.pitch * model.link_mass)))
    settle_dt = max(dt, min(SETTLE_FACTOR * dt, period / SETTLE_PER_PERIOD, 0.5 * transverse))
    samples, window = o["samples"], o["window"]
    run = _Steps(settle_dt, period, samples)
    min_settle_time = o["min_settle_time"]
    if min_settle_time is None:
        min_settle_time = default_settle_time(model, start, period)
    means: list[float] = []
    peaks: list[float] = []
    settled = False
    least = math.ceil(min_settle_time / period - 1e-9)
    bulk = max(least - 2 * window, 0)
    state = start
    if bulk:
        state = (yield run.request(method, state, bulk))[0]
    for _ in range(least - bulk + o["max_settle"]):
        state, ten, _ang = yield run.request(method, state)
        means.append(float(np.mean(ten)))
        peaks.append(float(np.max(ten)))
        if len(means) >= 2 * window and state.time - start.time >= min_settle_time:
            a = slice(-window, None)
            b = slice(-2 * window, -window)
            if all(abs(np.mean(x[a]) / np.mean(x[b]) - 1.0) <= o["settle_tolerance"]
                   for x in (means, peaks)):
                settled = True
                break
    settle_time = state.time - start.time
    run.set_step(dt, period, samples)
    step_error = float("nan")
    tens: list[np.ndarray] = []
    angles: list[np.ndarray] = []
    if o["check_step"]:
        while True:
            after, full, ang = yield run.request(method, state)
            run.halve()
            half = (yield run.request(method, state))[1]
            step_error = max(abs(float(np.mean(full)) / float(np.mean(half)) - 1.0),
                             abs(float(np.max(full)) / float(np.max(half)) - 1.0))
            if step_error <= o["step_tolerance"]:
                run.set_step(2.0 * run.dt, period, samples)
                state = after
                tens.append(full)
                angles.append(ang)
                break
            needed = 2.0 * run.dt * o["step_tolerance"] / max(step_error, 1e-300)
            if min(needed, 0.5 * run.dt) < EXPLICIT_BELOW * model.stable_time_step():
                method = "explicit"
                run.set_step(model.stable_time_step(), period, samples)
                break
    while len(tens) < o["periods"]:
        state, ten, ang = yield run.request(method, state)
        tens.append(ten)
        angles.append(ang)
    return (o["bins"], tens, angles, settle_time, settled, run.steps, run.dt, step_error, method)


class _Drive:
    """One drive: its program, the request in flight, its spans and its processor time."""

    def __init__(self, index: int, model: SimulationModel, state: State | None,
                 o: dict[str, Any]):
        c0 = time.process_time()
        self.index, self.model = index, model
        self.drv = _driver(model)
        om0 = _driver_speed(model, self.drv)
        if om0 == 0.0:
            raise InputError("the driver's speed is 0: no running state", field="angular_velocity")
        dt = model.accurate_time_step()
        self.start = warm_start(model, assemble(model) if state is None else state)
        self.period = 2.0 * math.pi / (model.seats_per_turn(model.wheels[self.drv].teeth)
                                       * abs(om0))
        self.span = np.array(tight_span(model, self.start))
        self.other = np.array(slack_span(model, self.start))
        self.tab = K.seat_table(self.start.wp)
        self.program = _program(model, self.start, self.drv, self.period, dt, o)
        self.request: _Request | None = None
        self.result: SteadyState | None = None
        self.error: Exception | None = None
        self.cpu = time.process_time() - c0

    def advance(self, reply: _Reply | None) -> None:
        """Hand ``reply`` to the program (None: start it) and take its next request; an
        explicit one is run here, at once, with the single kernel."""
        while True:
            try:
                self.request = self.program.send(reply)  # type: ignore[arg-type]
            except StopIteration as stop:
                self.request = None
                bins, tens, angles, settle_time, settled, steps, dt, error, method = stop.value
                self.result = summarise(self.model, self.start, self.drv, self.period, bins, tens,
                                        angles, settle_time, settled, steps, dt, error, method,
                                        time.process_time())
                return
            if self.request[0] == "implicit":
                return
            reply = self.single(self.request)

    def single(self, request: _Request) -> _Reply:
        """A request run by the single kernel (as ``steady._Runner.period``)."""
        method, dt, steps, every, st = request
        par = st.par.copy()
        par[K.P_DT] = dt
        pos, vel, ws = st.pos.copy(), st.vel.copy(), st.ws.copy()
        n, nw = pos.shape[0], ws.shape[0]
        probes = np.ascontiguousarray(default_probes(self.model, st))
        recs = K.empty_records((steps + every - 1) // every, n, nw, probes.shape[0])
        written = INTEGRATORS[method](pos, vel, np.zeros_like(pos), np.zeros_like(pos),
                                      np.zeros(n), np.zeros(n), ws, st.wp, st.gd, self.tab, par,
                                      st.time, steps, every, probes, *recs, 0)
        _, _, rten, _, rws, rpos, _ = (r[:written] for r in recs)
        return self.reply(st, par, pos, vel, ws, steps, dt, rten, rws, rpos)

    def reply(self, st: State, par: np.ndarray, pos: np.ndarray, vel: np.ndarray,
              ws: np.ndarray, steps: int, dt: float, rten: np.ndarray, rws: np.ndarray,
              rpos: np.ndarray) -> _Reply:
        new = State(pos, vel, ws, st.wp, st.gd, par, st.relax_time, st.relax_steps,
                    st.time + steps * dt)
        return new, _span_tension(rpos, rten, self.span, self.other), rws[:, self.drv, K.S_THETA]


def steady_states_implicit(drives_or_models: Sequence[Any], *, periods: int = 12,
                           bins: int = 16, window: int = 2, settle_tolerance: float = 0.02,
                           max_settle: int = 40, step_tolerance: float = 0.01,
                           check_step: bool = True, samples: int = 48,
                           min_settle_time: float | None = None,
                           states: Sequence[State | None] | None = None,
                           lanes: int = 64) -> list[SteadyState | Exception]:
    """Tight-span tension of each running drive in its steady state, the implicit steps of
    many drives taken together; each result that of
    :func:`~chaindrive.simulation.steady.steady_state` (see the module notes).

    Parameters
    ----------
    drives_or_models : sequence of Drive or SimulationModel
        The drives (:func:`~chaindrive.simulation.model_from_drive`) or models.
    periods, bins, window, settle_tolerance, max_settle, step_tolerance, check_step, samples, min_settle_time
        As :func:`~chaindrive.simulation.steady.steady_state` (its step ``dt`` the
        model's accurate step).
    states : sequence of State or None, optional
        Static states to start from (default fresh assemblies).
    lanes : int
        Drives stepped together at most, 1 to 4,096.

    Returns
    -------
    list of SteadyState or Exception
        In the order of the drives; a drive that cannot run (no driver at a steady speed,
        a failed assembly) gives its exception in its place. ``cpu_time`` is the drive's
        own processor time plus an equal share of each batched call it took part in.

    Raises
    ------
    InputError
        Bad arguments.

    Examples
    --------
    >>> from chaindrive.simulation import roller_example
    >>> ms = [roller_example(links=40, teeth=12, angular_velocity=w, load_torque=50.0,
    ...                      gravity=False) for w in (10.0, 12.0)]
    >>> a, b = steady_states_implicit(ms, periods=4)
    >>> bool(a.peak_tension >= a.mean_tension > 0), b.waveform.shape
    (True, (16,))
    """
    check_counts(periods=periods, bins=bins, window=window, max_settle=max_settle,
                 samples=samples, settle_tolerance=settle_tolerance,
                 step_tolerance=step_tolerance)
    items = check_many(drives_or_models, states, min_settle_time, lanes=lanes)
    o = dict(periods=periods, bins=bins, window=window, settle_tolerance=settle_tolerance,
             max_settle=max_settle, step_tolerance=step_tolerance, check_step=check_step,
             samples=samples, min_settle_time=min_settle_time)
    out: list[SteadyState | Exception | None] = [None] * len(items)
    groups: dict[tuple[int, int, int], list[_Drive]] = {}
    for i, item in enumerate(items):
        try:
            model = item if isinstance(item, SimulationModel) else _model_of(item)
            d = _Drive(i, model, None if states is None else states[i], o)
            c0 = time.process_time()
            d.advance(None)
            d.cpu += time.process_time() - c0
        except Exception as exc:  # noqa: BLE001 - one drive's failure is its result
            out[i] = exc
            continue
        st = d.start
        groups.setdefault((st.pos.shape[0], st.ws.shape[0], st.gd.shape[0]), []).append(d)
    for members in groups.values():
        for lo in range(0, len(members), lanes):
            _run(members[lo:lo + lanes], 2 * samples + 2)
    for members in groups.values():
        for d in members:
            out[d.index] = d.error if d.result is None else \
                dataclasses.replace(d.result, cpu_time=d.cpu)
    return out  # type: ignore[return-value]


def _run(drives: list[_Drive], records: int) -> None:
    """Step ``drives`` (one layout) as lanes until every program has ended."""
    st = drives[0].start
    lanes = Lanes(len(drives), st.pos.shape[0], st.ws.shape[0], st.gd.shape[0],
                  max(d.tab.shape[1] for d in drives), records)
    for v, d in enumerate(drives):
        _load(lanes, v, d)
    while lanes.active.any():
        if len(drives) > 8 and 2 * int(lanes.active.sum()) <= len(drives):
            # half the lanes or more done: the others go on in fewer lanes
            keep = np.flatnonzero(lanes.active)
            lanes = lanes.take(keep)
            drives = [drives[v] for v in keep]
        c0 = time.process_time()
        integrate_implicit_lanes(*lanes.arrays(), 1 << 62)
        stepping = [d for d in drives if d.request is not None]
        share = (time.process_time() - c0) / max(len(stepping), 1)
        for d in stepping:
            d.cpu += share
        for v, d in enumerate(drives):
            if d.request is None or lanes.active[v]:
                continue
            c0 = time.process_time()
            try:
                _, dt, steps, _, rst = d.request
                pos, vel, ws = lanes.state(v)
                nr = int(lanes.nrec[v])
                par = rst.par.copy()
                par[K.P_DT] = dt
                d.advance(d.reply(rst, par, pos, vel, ws, steps, dt,
                                  lanes.rec_tension[v, :nr].copy(), lanes.rec_ws[v, :nr].copy(),
                                  lanes.rec_pos[v, :nr].copy()))
                if d.request is not None:
                    _load(lanes, v, d)
            except Exception as exc:  # noqa: BLE001 - one drive's failure is its result
                d.request = None
                d.error = exc
            d.cpu += time.process_time() - c0


def _load(lanes: Lanes, v: int, d: _Drive) -> None:
    if d.request is None:
        return
    _, dt, steps, every, st = d.request
    if (steps + every - 1) // every > lanes.rec_t.shape[1]:
        raise InputError(f"{steps} steps recorded every {every} need more records than "
                         f"{lanes.rec_t.shape[1]}", field="samples")
    par = st.par.copy()
    par[K.P_DT] = dt
    lanes.load(v, st.pos, st.vel, st.ws, st.wp, st.gd, d.tab, par, st.time, steps, every)
