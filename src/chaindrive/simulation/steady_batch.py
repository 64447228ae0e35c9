r"""Steady states of many drives at once: :func:`steady_states`.

The rule of :func:`~chaindrive.simulation.steady.steady_state` (warm start, settling
detected a tooth period at a time, ``periods`` tooth periods measured) with the explicit
integrator, the drives of one layout (the same number of pins, wheels and guides)
stepped together by the batched kernel (``_batched.integrate_batch``: the variants the
inner, vectorised dimension of the link forces and the pins' update). A drive leaves
the batch when it is measured.

Step. Every drive runs at ``Δt = T/S``, ``T`` its tooth period and ``S`` the least
number of steps per period on the ladder ``⌈8·2^{k/8}⌉`` at which ``Δt`` is within the
explicit stable step (:meth:`SimulationModel.stable_time_step`): a period is a whole
number of steps, drives on the same rung of the ladder share their periods' step
counts (at most 9 % more steps than the stable step needs), and each drive's step
depends on itself only, so its result does not depend on the drives batched with it.
:func:`batch_step` gives that step.

Each result equals ``steady_state(model, method="explicit", dt=batch_step(model),
min_settle_time=..., ...)`` to the last bit when no period is run in bulk there
(``min_settle_time`` at most ``2·window`` tooth periods); with a longer minimum settling
time the single run steps its first periods in one call, which places its records (and
their rounding) differently.
"""

from __future__ import annotations

import math
import time
from collections.abc import Sequence
from typing import Any

import numpy as np

from ..errors import InputError
from . import _kernel as K
from ._batched import empty_batch_records, integrate_batch, stack_tables
from .model import SimulationModel
from .results import slack_span, tight_span
from .run import State, assemble
from .steady import (
    MAX_AUTO_SETTLE,
    SteadyState,
    _driver,
    _driver_speed,
    _model_of,
    _span_tension,
    check_counts,
    span_period,
    summarise,
    warm_start,
)

#: Drives one call takes at most (a study hands its variants over in batches of this size or fewer).
MAX_BATCH_DRIVES = 100_000

__all__ = ["batch_step", "steady_states"]

#: rungs of the steps-per-period ladder per doubling
LADDER = 8


def _period(model: SimulationModel) -> tuple[int, float, float]:
    drv = _driver(model)
    om0 = _driver_speed(model, drv)
    if om0 == 0.0:
        raise InputError("the driver's speed is 0: no running state", field="angular_velocity")
    return drv, om0, 2.0 * math.pi / (model.seats_per_turn(model.wheels[drv].teeth) * abs(om0))


def _steps(period: float, stable: float) -> int:
    need = period / stable
    k = max(math.ceil(LADDER * math.log2(max(need, 8.0) / 8.0) - 1e-9), 0)
    steps = math.ceil(8.0 * 2.0 ** (k / LADDER))
    while period / steps > stable:  # the rounding of the ladder
        k += 1
        steps = math.ceil(8.0 * 2.0 ** (k / LADDER))
    return steps


def batch_step(model: SimulationModel) -> float:
    """Time step [s] of ``model`` in :func:`steady_states`: its tooth period over the least
    steps per period of the ladder ``⌈8·2^{k/8}⌉`` within the stable step.

    Examples
    --------
    >>> from chaindrive.simulation import roller_example
    >>> m = roller_example(links=40, teeth=12, gravity=False, angular_velocity=10.0)
    >>> 0.91 * m.stable_time_step() < batch_step(m) <= m.stable_time_step()
    True
    """
    _, _, period = _period(model)
    return period / _steps(period, model.stable_time_step())


class _Drive:
    """One drive's bookkeeping: start, spans, settling test, measured periods."""

    def __init__(self, index: int, model: SimulationModel, state: State | None,
                 min_settle_time: float | None, samples: int, max_settle: int):
        self.cpu0 = time.process_time()
        self.index, self.model = index, model
        self.drv, _, self.period = _period(model)
        self.start = warm_start(model, assemble(model) if state is None else state)
        self.steps = _steps(self.period, model.stable_time_step())
        self.dt = self.period / self.steps
        self.every = max(self.steps // samples, 1)
        self.span = np.array(tight_span(model, self.start))
        self.other = np.array(slack_span(model, self.start))
        mst = min_settle_time
        if mst is None:
            mst = min(2.0 * span_period(model, self.start), MAX_AUTO_SETTLE * self.period)
        self.min_settle_time = mst
        self.least = math.ceil(mst / self.period - 1e-9)
        self.state = self.start
        self.means: list[float] = []
        self.peaks: list[float] = []
        self.tens: list[np.ndarray] = []
        self.angles: list[np.ndarray] = []
        self.settled = False
        self.settle_time = -1.0 if self.least + max_settle > 0 else 0.0
        self.cpu = 0.0

    def take(self, ten: np.ndarray, ang: np.ndarray, window: int, tolerance: float,
             max_settle: int, periods: int) -> bool:
        """One more period's tension and driver angles; True once measured."""
        if self.settle_time < 0.0:
            self.means.append(float(np.mean(ten)))
            self.peaks.append(float(np.max(ten)))
            elapsed = self.state.time - self.start.time
            if len(self.means) >= 2 * window and elapsed >= self.min_settle_time:
                a, b = slice(-window, None), slice(-2 * window, -window)
                self.settled = all(abs(np.mean(x[a]) / np.mean(x[b]) - 1.0) <= tolerance
                                   for x in (self.means, self.peaks))
            if self.settled or len(self.means) >= self.least + max_settle:
                self.settle_time = elapsed
            return False
        self.tens.append(ten)
        self.angles.append(ang)
        return len(self.tens) >= periods


def steady_states(drives_or_models: Sequence[Any], *, periods: int = 12, bins: int = 16,
                  window: int = 2, settle_tolerance: float = 0.02, max_settle: int = 40,
                  samples: int = 48, min_settle_time: float | None = None,
                  states: Sequence[State | None] | None = None,
                  batch: int = 64) -> list[SteadyState]:
    """Tight-span tension of each running drive in its steady state, many drives stepped
    together (see the module notes).

    Parameters
    ----------
    drives_or_models : sequence of Drive or SimulationModel
        The drives (:func:`~chaindrive.simulation.model_from_drive`) or models.
    periods, bins, window, settle_tolerance, max_settle, samples, min_settle_time
        As :func:`~chaindrive.simulation.steady.steady_state`.
    states : sequence of State or None, optional
        Static states to start from (default fresh assemblies).
    batch : int
        Drives stepped together at most, 1 to 4,096.

    Returns
    -------
    list of SteadyState
        In the order of the drives; ``method`` ``"explicit"``, ``dt`` :func:`batch_step`,
        ``cpu_time`` the drive's share of the processor time.

    Raises
    ------
    InputError
        Bad arguments, or a drive without a driver at a steady speed.

    Examples
    --------
    >>> from chaindrive.simulation import roller_example
    >>> ms = [roller_example(links=40, teeth=12, angular_velocity=w, load_torque=50.0,
    ...                      gravity=False) for w in (10.0, 12.0)]
    >>> a, b = steady_states(ms, periods=4)
    >>> bool(a.peak_tension >= a.mean_tension > 0), b.method
    (True, 'explicit')
    """
    check_counts(periods=periods, bins=bins, window=window, max_settle=max_settle,
                 samples=samples, settle_tolerance=settle_tolerance)
    items = check_many(drives_or_models, states, min_settle_time, batch=batch)
    models = [x if isinstance(x, SimulationModel) else _model_of(x) for x in items]
    drives = [_Drive(i, m, None if states is None else states[i], min_settle_time, samples,
                     max_settle) for i, m in enumerate(models)]
    groups: dict[tuple[int, ...], list[_Drive]] = {}
    for d in drives:
        st = d.start
        groups.setdefault((st.pos.shape[0], st.ws.shape[0], st.gd.shape[0], d.steps, d.every),
                          []).append(d)
    out: list[SteadyState | None] = [None] * len(drives)
    for members in groups.values():
        for lo in range(0, len(members), batch):
            _run(members[lo:lo + batch], window, settle_tolerance, max_settle, periods)
    for d in drives:
        out[d.index] = summarise(d.model, d.start, d.drv, d.period, bins, d.tens, d.angles,
                                 d.settle_time, d.settled, d.steps, d.dt, float("nan"),
                                 "explicit", time.process_time() - d.cpu)
    return out  # type: ignore[return-value]


def check_many(drives_or_models: Any, states: Sequence[State | None] | None,
               min_settle_time: float | None, **lanes: int) -> list[Any]:
    """The drives of a call for many drives as a list, their arguments checked: the one
    keyword ``lanes`` (its name the argument's) 1 to 4,096, ``min_settle_time`` >= 0, 1 to
    ``MAX_BATCH_DRIVES`` drives, one state per drive (``InputError`` naming the argument)."""
    (name, count), = lanes.items()
    if not isinstance(count, (int, np.integer)) or not 1 <= count <= 4096:
        raise InputError(f"{name} must be a whole number from 1 to 4096, got {count!r}",
                         field=name)
    if min_settle_time is not None and not min_settle_time >= 0.0:
        raise InputError(f"min_settle_time must be >= 0 s, got {min_settle_time!r}",
                         field="min_settle_time")
    if isinstance(drives_or_models, (str, bytes)) or not hasattr(drives_or_models, "__iter__"):
        raise InputError("drives_or_models must be a sequence of drives or simulation models, "
                         f"got {type(drives_or_models).__name__}", field="drives_or_models")
    items = list(drives_or_models)
    if not 1 <= len(items) <= MAX_BATCH_DRIVES:
        raise InputError(f"drives_or_models: 1 to {MAX_BATCH_DRIVES} drives, got {len(items)}",
                         field="drives_or_models")
    if states is not None and len(states) != len(items):
        raise InputError(f"states: one per drive ({len(items)}), got {len(states)}",
                         field="states")
    return items


def _run(active: list[_Drive], window: int, tolerance: float, max_settle: int,
         periods: int) -> None:
    """Step ``active`` (one layout, one step count per period) a period at a time until
    every drive is measured; each drive's processor time kept in ``cpu`` (its setup,
    and an equal share of the batch)."""
    steps, every = active[0].steps, active[0].every
    c0 = time.process_time()
    for d in active:
        d.cpu = c0 - d.cpu0
    tabs = [K.seat_table(d.start.wp) for d in active]
    pos = np.stack([d.start.pos for d in active])
    vel = np.stack([d.start.vel for d in active])
    ws = np.stack([d.start.ws for d in active])
    wp = np.stack([d.start.wp for d in active])
    gd = np.stack([d.start.gd for d in active])
    par = np.stack([d.start.par for d in active])
    par[:, K.P_DT] = [d.dt for d in active]
    tab = stack_tables(tabs)
    t0 = np.array([d.start.time for d in active])
    nrec = (steps + every - 1) // every
    while active:
        c0 = time.process_time()
        recs = empty_batch_records(len(active), nrec, pos.shape[1], ws.shape[1])
        written = integrate_batch(pos, vel, ws, wp, gd, tab, par, t0, steps, every, *recs)
        t0 = t0 + steps * par[:, K.P_DT]
        keep = []
        for v, d in enumerate(active):
            d.state = State(pos[v], vel[v], ws[v], d.start.wp, d.start.gd, par[v],
                            d.start.relax_time, d.start.relax_steps, float(t0[v]))
            ten = _span_tension(recs[3][v, :written], recs[1][v, :written], d.span, d.other)
            if not d.take(ten, recs[2][v, :written, d.drv, K.S_THETA].copy(), window, tolerance,
                          max_settle, periods):
                keep.append(v)
        share = (time.process_time() - c0) / len(active)
        for d in active:
            d.cpu += share
        if len(keep) < len(active):
            active = [active[v] for v in keep]
            pos, vel, ws, wp, gd, par, tab, t0 = (a[keep].copy() for a in
                                                  (pos, vel, ws, wp, gd, par, tab, t0))
