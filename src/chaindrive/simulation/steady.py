r"""The running drive's steady state, fast: :func:`steady_state`.

From nothing to the tight-span tension of the running drive (mean, peak, the waveform
over one tooth period) in a fraction of a second:

1. **Warm start.** The static assembly (:func:`~chaindrive.simulation.run.assemble`) set
   in motion at the steady speed: every wheel at its speed (the driver's prescribed
   speed, the others at the speed the chain's mean speed gives them), the pins on a wheel
   turning with it, the pins of the spans moving along the chain at its mean speed
   ``v = s p ω / 2π`` (``s`` seats per turn of the driver), the clock past the driver's
   ramp. No ramp is simulated.
2. **Settling, detected.** The run goes on one tooth (seat) period ``2π/(s ω)`` at a
   time; the drive counts as settled once the mean and the mean peak of the tight-span
   tension over the last ``window`` periods differ from those over the ``window``
   periods before by at most ``settle_tolerance`` (relative).
3. **The step checked against its half.** The linearly implicit integrator is first
   order: from the settled state one tooth period is run at ``Δt`` and at ``Δt/2``
   (recording at the same instants: on two sample grids the largest sample of a
   period moves with the grid, by up to 1.8 % on the benchmark drive) and
   the relative change of its mean and peak tension is the step's error estimate; above
   ``step_tolerance`` the step is halved (and the check repeated) before measuring. A
   step that would fall below four explicit stable steps (where the implicit step costs
   more than the explicit integrator at its stable step) is not tried, nor halving when
   the first-order estimate of the step that would hold (``Δt · tolerance / error``) is
   below that: the measurement then runs with the explicit integrator (``method`` of the
   result).
4. **Measuring** over ``periods`` tooth periods: the mean, the waveform (the tension
   averaged in ``bins`` bins of the driver's phase within the tooth period) and its
   peak, the mean of each period's largest value, the largest and smallest values and
   the standard error of the mean (from the per-period means).

The tight-span tension is that of :meth:`SimulationResult.tight_side_tension` (the link
nearest the middle of the span entering the driver). A drive whose spans vibrate without
damping (a long, lightly tensioned slack span) has no periodic steady state: its
statistics wander by a few per cent over tenths of a second, and its running tension
builds up over seconds as the slack span's vibration grows (the benchmark drive of
``benchmarks/simulate.py``: means of 8 s windows of one 30 s explicit run from 3.14 kN
at 0.5 s to 3.59 kN at 22 s; the steady state at 0.6 s is 4–5 % below an ensemble of
runs measured 8 s after the warm start, as the exact integrator is over the same
window); ``standard_error`` (of the measured periods only) and ``settled`` say how far
a short measurement can be trusted. docs/simulation.md, "Steady state".
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass
from typing import Any

import numpy as np
from numba import njit

from .._results import Result, quantity
from ..errors import InputError
from . import _kernel as K
from .model import SimulationModel
from .results import default_probes, slack_span, span_tension, tight_span
from .run import INTEGRATORS, State, assemble

__all__ = ["SteadyState", "span_period", "steady_state", "warm_start"]

#: settling step: at most this many times the measuring step and ... (1 since the spans are
#: damped by default: a slow drive's slack-span vibration, which raises its mean tension, then
#: relaxes over ``2/α`` (0.6 s on a 16B 40-link drive at 5 rad/s), and settling at twice the step
#: left it at the coarse step's level: mean 2668 N against 2826 N settled at the measuring step and
#: 2815-2833 N from long explicit runs; the 16B benchmark drive: 3077 against 3078 N)
SETTLE_FACTOR = 1.0
#: ... at least this many steps per tooth period
SETTLE_PER_PERIOD = 50
#: the implicit step is not halved below this many explicit stable steps: the measurement
#: then runs explicitly (the implicit step costs about four explicit ones)
EXPLICIT_BELOW = 4.0
#: the default minimum settling time is at most this many tooth periods
MAX_AUTO_SETTLE = 100


@dataclass(frozen=True)
class SteadyState(Result):
    """Tight-span tension of the running drive in its steady state (SI units).

    Attributes
    ----------
    mean_tension : float
        Mean over the measured periods [N].
    peak_tension : float
        Largest value of ``waveform`` [N]: the peak that repeats every tooth period.
    period_peak_tension : float
        Mean over the measured tooth periods of each period's largest sample [N] (with
        the span vibration that does not repeat; converges more slowly).
    max_tension, min_tension : float
        Largest and smallest sampled value in the measured periods [N].
    standard_error : float
        Standard error of ``mean_tension`` from the per-period means [N].
    waveform : ndarray (B,)
        Tension averaged over the measured periods in ``B`` bins of the driver's phase
        within its tooth period [N].
    phase : ndarray (B,)
        Bin centres, fraction of the tooth period (0: a seat of the driver on the
        line from its centre along +x, turned by the driver's angle).
    tooth_period : float
        Seat period of the driver ``2π/(s ω)`` [s].
    chain_speed : float
        Mean chain speed of the warm start [m/s].
    settle_time : float
        Simulated time before the measurement [s].
    settled : bool
        The settling criterion was met (else the measurement began ``max_settle``
        periods after ``min_settle_time``).
    measured_time : float
        Simulated time measured [s].
    dt : float
        Time step of the measurement [s].
    step_error : float
        Relative change of the mean or peak tension of one tooth period against the
        half step (the larger; NaN when not checked).
    method : str
        Integrator of the measurement (``"explicit"`` where the implicit step did not
        hold the accuracy above four explicit stable steps).
    cpu_time : float
        Processor time of the whole computation, assembly included [s].
    """

    mean_tension: float = quantity("N")
    peak_tension: float = quantity("N")
    period_peak_tension: float = quantity("N")
    max_tension: float = quantity("N")
    min_tension: float = quantity("N")
    standard_error: float = quantity("N")
    waveform: np.ndarray = quantity("N")
    phase: np.ndarray = quantity("1")
    tooth_period: float = quantity("s")
    chain_speed: float = quantity("m/s")
    settle_time: float = quantity("s")
    settled: bool = quantity("1")
    measured_time: float = quantity("s")
    dt: float = quantity("s")
    step_error: float = quantity("1")
    method: str = "implicit"
    cpu_time: float = quantity("s", default=0.0)


def _driver(model: SimulationModel) -> int:
    """Index of the wheel that sets the speed (prescribed speed or a motor)."""
    for i, w in enumerate(model.wheels):
        if w.mode in ("speed", "motor") and w.plain_radius is None:
            if w.stop_time > 0.0:
                raise InputError(f"wheel {i} stops at {w.stop_time:g} s: a drive that stops has "
                                 "no steady state (set stop_time = 0)", field="stop_time")
            return i
    raise InputError("a steady state needs a toothed wheel driven at a prescribed speed or by a "
                     "motor (mode 'speed' or 'motor'), e.g. SimWheel.at((0, 0), 17, mode='speed', "
                     "angular_velocity=20.0)", field="wheels")


def _driver_speed(model: SimulationModel, w: int) -> float:
    wheel = model.wheels[w]
    if wheel.mode == "speed" or wheel.motor is None:
        return float(wheel.angular_velocity)
    return float(wheel.motor.synchronous_speed)


def warm_start(model: SimulationModel, state: State | None = None) -> State:
    """The static state set in motion at the steady speed (step 1 of the module notes).

    Parameters
    ----------
    model : SimulationModel
    state : State, optional
        The static state (:func:`~chaindrive.simulation.run.assemble`); default a fresh
        assembly.

    Returns
    -------
    State
        Pins and wheels moving, its ``time`` past every speed ramp.

    Examples
    --------
    >>> from chaindrive.simulation import roller_example
    >>> m = roller_example(links=40, teeth=12, gravity=False, angular_velocity=10.0)
    >>> st = warm_start(m)
    >>> round(float(st.ws[0, 1]), 6), round(float(st.ws[1, 1]), 6)
    (10.0, 10.0)
    """
    drv = _driver(model)
    state = assemble(model) if state is None else state
    wp, par = state.wp, state.par
    om0 = _driver_speed(model, drv)
    nw = len(model.wheels)
    pbar = 0.5 * (par[K.P_PITCH] + par[K.P_PITCH2]) * (1.0 + model.prestrain)
    v = wp[drv, K.W_NSEAT] * pbar * abs(om0) / (2.0 * math.pi)
    sense = math.copysign(1.0, om0)
    sides = np.sign(model.signed_radii())
    omega = np.zeros(nw)
    for w in range(nw):
        if wp[w, K.W_PLAIN] > 0.5:
            # rollers at chord p on a circle of radius R: one link per 2 asin(p / 2R)
            rate = 2.0 * math.asin(min(pbar / (2.0 * wp[w, K.W_R]), 1.0)) / pbar
        else:
            rate = 2.0 * math.pi / (wp[w, K.W_NSEAT] * pbar)
        omega[w] = sense * sides[w] * v * rate
    omega[drv] = om0
    pos = state.pos.copy()
    n = pos.shape[0]
    centres = np.column_stack([wp[:, K.W_CX], wp[:, K.W_CY]])
    # the pins seated on a wheel (their centre within a quarter roller radius outside its
    # pitch circle) turn with it; the others move along the chain (the mean of their two
    # links' directions) at the chain's speed
    ahead = np.roll(pos, -1, axis=0) - np.roll(pos, 1, axis=0)
    ahead /= np.hypot(ahead[:, 0], ahead[:, 1])[:, None]
    vel = np.empty_like(pos)
    on_wheel = np.full(n, -1)
    for w in range(nw):
        reach = wp[w, K.W_R] + 0.25 * model.roller_radius
        r = pos - centres[w]
        near = (np.hypot(r[:, 0], r[:, 1]) <= reach) & (on_wheel < 0)
        on_wheel[near] = w
    travel = 1.0
    seated = np.flatnonzero(on_wheel == drv)
    if seated.size:
        r = pos[seated] - centres[drv]
        vd = om0 * np.column_stack([-r[:, 1], r[:, 0]])
        travel = math.copysign(1.0, float(np.sum(vd * ahead[seated])))
    vel[:] = travel * v * ahead
    for w in range(nw):
        sel = on_wheel == w
        r = pos[sel] - centres[w]
        vel[sel] = omega[w] * np.column_stack([-r[:, 1], r[:, 0]])
    ws = state.ws.copy()
    ws[:, K.S_OMEGA] = omega
    for w in range(nw):
        if model.wheels[w].coupling is not None:
            ws[w, K.S_MOTOR] = omega[w]
    t_start = max([w.ramp_time for w in model.wheels] + [0.0])
    return State(pos, vel, ws, state.wp, state.gd, state.par, state.relax_time, state.relax_steps,
                 t_start)


@njit(cache=True, fastmath=False)
def _segment_distance2(px, py, seg):
    ux = seg[1, 0] - seg[0, 0]
    uy = seg[1, 1] - seg[0, 1]
    t = ((px - seg[0, 0]) * ux + (py - seg[0, 1]) * uy) / (ux * ux + uy * uy)
    t = min(max(t, 0.0), 1.0)
    dx = px - seg[0, 0] - t * ux
    dy = py - seg[0, 1] - t * uy
    return dx * dx + dy * dy


@njit(cache=True, fastmath=False)
def _span_tension(positions, tension, span, other):
    """:func:`~chaindrive.simulation.results.span_tension`, compiled (the same rule: the
    link nearest the span's middle among those nearer to its line than to the other's)."""
    nrec, n = tension.shape
    mx = 0.5 * (span[0, 0] + span[1, 0])
    my = 0.5 * (span[0, 1] + span[1, 1])
    out = np.empty(nrec)
    for r in range(nrec):
        best = np.inf
        pick = 0
        for i in range(n):
            j = i + 1 if i + 1 < n else 0
            px = 0.5 * (positions[r, i, 0] + positions[r, j, 0])
            py = 0.5 * (positions[r, i, 1] + positions[r, j, 1])
            d = (px - mx) * (px - mx) + (py - my) * (py - my)
            if d < best and _segment_distance2(px, py, span) <= _segment_distance2(px, py, other):
                best = d
                pick = i
        out[r] = tension[r, pick]
    return out


class _Runner:
    """Runs the integrator a tooth period at a time, keeping the tight-span tension."""

    def __init__(self, model: SimulationModel, state: State, method: str, dt: float,
                 period: float, samples: int, drv: int):
        self.model, self.method, self.drv = model, method, drv
        self.integrate = INTEGRATORS[method]
        self.span = np.array(tight_span(model, state))
        self.other = np.array(slack_span(model, state))
        self.probes = np.ascontiguousarray(default_probes(model, state))
        self.tab = K.seat_table(state.wp)
        self.state = state
        self.set_step(dt, period, samples)

    def use(self, method: str, dt: float, period: float, samples: int) -> None:
        """Go on with another integrator at step ``dt``."""
        self.method = method
        self.integrate = INTEGRATORS[method]
        self.set_step(dt, period, samples)

    def set_step(self, dt: float, period: float, samples: int) -> None:
        self.dt = dt
        self.steps = max(int(round(period / dt)), 1)
        self.every = max(self.steps // samples, 1)

    def halve(self) -> None:
        """Go on at half the step, over the same time and with records at the same
        instants (twice the steps between them)."""
        self.dt *= 0.5
        self.steps *= 2
        self.every *= 2

    def period(self, state: State | None = None, count: int = 1
               ) -> tuple[State, np.ndarray, np.ndarray]:
        """``count`` tooth periods from ``state`` (default the current one) in one call of
        the integrator: the new state, the tight-span tension and the driver's angle at
        the records (with ``count`` > 1 the last record only)."""
        st = self.state if state is None else state
        par = st.par.copy()
        par[K.P_DT] = self.dt
        pos, vel, ws = st.pos.copy(), st.vel.copy(), st.ws.copy()
        n, nw = pos.shape[0], ws.shape[0]
        steps = count * self.steps
        every = self.every if count == 1 else steps
        nrec = (steps + every - 1) // every
        recs = K.empty_records(nrec, n, nw, self.probes.shape[0])
        written = self.integrate(pos, vel, np.zeros_like(pos), np.zeros_like(pos), np.zeros(n),
                                 np.zeros(n), ws, st.wp, st.gd, self.tab, par, st.time, steps,
                                 every, self.probes, *recs, 0)
        _, _, rten, _, rws, rpos, _ = (r[:written] for r in recs)
        new = State(pos, vel, ws, st.wp, st.gd, par, st.relax_time, st.relax_steps,
                    st.time + steps * self.dt)
        tension = _span_tension(rpos, rten, self.span, self.other)
        return new, tension, rws[:, self.drv, K.S_THETA]


def steady_state(drive_or_model: Any, *, periods: int = 12, bins: int = 16, window: int = 2,
                 settle_tolerance: float = 0.02, max_settle: int = 40, step_tolerance: float = 0.01,
                 check_step: bool = True, method: str = "implicit", dt: float | None = None,
                 samples: int = 48, min_settle_time: float | None = None,
                 state: State | None = None) -> SteadyState:
    """Tight-span tension of the running drive in its steady state (see the module notes).

    Parameters
    ----------
    drive_or_model : chaindrive.drive.Drive or SimulationModel
        A project drive (through :func:`~chaindrive.simulation.model_from_drive`) or a
        simulation model with a driver at a prescribed speed or on a motor.
    periods : int
        Tooth periods measured, 1 to 10,000.
    bins : int
        Phase bins of the waveform, 2 to 1,000.
    window : int
        Periods compared with the ``window`` before them to detect the settling.
    settle_tolerance : float
        Relative change of the window's mean and mean peak tension below which the drive
        counts as settled, in (0, 1).
    max_settle : int
        Tooth periods run at most after ``min_settle_time`` before measuring.
    step_tolerance : float
        Relative error allowed against the half step, in (0, 1).
    check_step : bool
        Check (and halve) the step against its half before measuring.
    method : {"implicit", "explicit"}
        Integrator (:func:`~chaindrive.simulation.simulate`); the explicit one runs at its
        stable step and is not checked.
    dt : float, optional
        Time step [s]; default :meth:`SimulationModel.accurate_time_step` (implicit).
    samples : int
        Samples per tooth period, at least 4.
    min_settle_time : float, optional
        Simulated time [s] run before the settling test may pass; default the longer of two
        periods of the slowest first transverse mode of the tight and the slack span
        (:func:`span_period`) and three time constants ``2/α`` of the spans' damping
        (:meth:`SimulationModel.span_damping_rate`: every transverse mode decays as
        ``exp(−α t/2)``; 24 tooth periods at the default ``α``), at most 100 tooth periods:
        a span's vibration builds up over its own periods, and the mean tension with it.
    state : State, optional
        Static state to start from (default a fresh assembly).

    Returns
    -------
    SteadyState

    Raises
    ------
    InputError
        Bad arguments, or no driver at a steady speed.

    Examples
    --------
    >>> from chaindrive.simulation import roller_example
    >>> from chaindrive.simulation.steady import steady_state
    >>> s = steady_state(roller_example(links=40, teeth=12, angular_velocity=10.0,
    ...                                 load_torque=50.0, gravity=False), periods=4)
    >>> bool(s.peak_tension >= s.mean_tension > 0), s.waveform.shape
    (True, (16,))

    References
    ----------
    Hairer, E., Wanner, G. *Solving Ordinary Differential Equations II*, Springer (the
    linearly implicit Euler step is first order: its error is estimated from the half
    step).
    """
    cpu0 = time.process_time()
    model = drive_or_model if isinstance(drive_or_model, SimulationModel) else _model_of(drive_or_model)
    check_counts(periods=periods, bins=bins, window=window, max_settle=max_settle, samples=samples,
                 settle_tolerance=settle_tolerance, step_tolerance=step_tolerance)
    if method not in INTEGRATORS:
        raise InputError(f"method must be one of {', '.join(INTEGRATORS)}, got {method!r}",
                         field="method")
    drv = _driver(model)
    if dt is None:
        dt = model.accurate_time_step() if method == "implicit" else model.stable_time_step()
    if not dt > 0.0:
        raise InputError(f"dt must be positive, e.g. 4.5e-5 s, got {dt!r}", field="dt")
    om0 = _driver_speed(model, drv)
    if om0 == 0.0:
        raise InputError("the driver's speed is 0: no running state", field="angular_velocity")
    start = warm_start(model, assemble(model) if state is None else state)
    period = 2.0 * math.pi / (model.seats_per_turn(model.wheels[drv].teeth) * abs(om0))
    # settling at up to twice the step (not measured): within half the explicit limit of
    # the links' transverse stiffness S/p at the largest static tension (docs/simulation.md)
    settle_dt = dt
    if method == "implicit":
        seg = np.diff(np.vstack([start.pos, start.pos[:1]]), axis=0)
        s_max = max(float(np.max(start.par[K.P_K] * (np.hypot(seg[:, 0], seg[:, 1])
                                                     - start.par[K.P_PITCH]))), 1.0)
        transverse = 2.0 / (2.0 * math.sqrt(1.5 * s_max / (model.pitch * model.link_mass)))
        settle_dt = max(dt, min(SETTLE_FACTOR * dt, period / SETTLE_PER_PERIOD, 0.5 * transverse))
    run = _Runner(model, start, method, settle_dt, period, samples, drv)
    if min_settle_time is None:
        min_settle_time = default_settle_time(model, start, period)
    elif not min_settle_time >= 0.0:
        raise InputError(f"min_settle_time must be >= 0 s, got {min_settle_time!r}",
                         field="min_settle_time")
    # 2: settling, a tooth period at a time
    means: list[float] = []
    peaks: list[float] = []
    settled = False
    least = math.ceil(min_settle_time / period - 1e-9)
    bulk = max(least - 2 * window, 0)
    if bulk:
        # the periods before the last 2 window ones of the minimum time are not tested:
        # one call of the integrator
        run.state = run.period(count=bulk)[0]
    for _ in range(least - bulk + max_settle):
        run.state, ten, _ = run.period()
        means.append(float(np.mean(ten)))
        peaks.append(float(np.max(ten)))
        if len(means) >= 2 * window and run.state.time - start.time >= min_settle_time:
            a = slice(-window, None)
            b = slice(-2 * window, -window)
            if all(abs(np.mean(x[a]) / np.mean(x[b]) - 1.0) <= settle_tolerance
                   for x in (means, peaks)):
                settled = True
                break
    settle_time = run.state.time - start.time
    # 3: the step against its half (implicit only)
    run.set_step(dt, period, samples)
    step_error = float("nan")
    tens: list[np.ndarray] = []
    angles: list[np.ndarray] = []

    def keep(ten: np.ndarray, ang: np.ndarray) -> None:
        tens.append(ten)
        angles.append(ang)

    if check_step and method == "implicit":
        while True:
            after, full, ang = run.period()
            run.halve()
            half = run.period()[1]
            step_error = max(abs(float(np.mean(full)) / float(np.mean(half)) - 1.0),
                             abs(float(np.max(full)) / float(np.max(half)) - 1.0))
            if step_error <= step_tolerance:
                # the checked period at the accepted step is the first one measured
                run.set_step(2.0 * run.dt, period, samples)
                run.state = after
                keep(full, ang)
                break
            # the step that would hold, first order: (2 Δt_half) tolerance / error
            needed = 2.0 * run.dt * step_tolerance / max(step_error, 1e-300)
            if min(needed, 0.5 * run.dt) < EXPLICIT_BELOW * model.stable_time_step():
                # a step this fine costs the implicit integrator more than the explicit
                # one at its stable step costs: measure with that
                method = "explicit"
                run.use("explicit", model.stable_time_step(), period, samples)
                break
    # 4: measuring
    while len(tens) < periods:
        run.state, ten, ang = run.period()
        keep(ten, ang)
    return summarise(model, start, drv, period, bins, tens, angles, settle_time, settled,
                     run.steps, run.dt, step_error, method, cpu0)


def summarise(model: SimulationModel, start: State, drv: int, period: float, bins: int,
              tens: list[np.ndarray], angles: list[np.ndarray], settle_time: float, settled: bool,
              steps: int, dt: float, step_error: float, method: str, cpu0: float) -> SteadyState:
    """The :class:`SteadyState` of the measured periods (one tension and driver-angle
    array per period in ``tens``, ``angles``), step 4 of the module notes; ``cpu0`` the
    processor time at the start."""
    periods = len(tens)
    pmeans = [float(np.mean(t)) for t in tens]
    ppeaks = [float(np.max(t)) for t in tens]
    om0 = float(start.ws[drv, K.S_OMEGA])
    ten = np.concatenate(tens)
    nseat = model.seats_per_turn(model.wheels[drv].teeth)
    phase = np.mod(np.concatenate(angles) * nseat / (2.0 * math.pi), 1.0)
    if om0 < 0.0:
        phase = np.mod(-phase, 1.0)
    idx = np.minimum((phase * bins).astype(int), bins - 1)
    count = np.bincount(idx, minlength=bins)
    wave = np.bincount(idx, ten, minlength=bins) / np.maximum(count, 1)
    wave[count == 0] = np.nan
    sem = float(np.std(pmeans, ddof=1) / math.sqrt(periods)) if periods > 1 else float("nan")
    return SteadyState(
        mean_tension=float(np.mean(ten)), peak_tension=float(np.nanmax(wave)),
        period_peak_tension=float(np.mean(ppeaks)),
        max_tension=float(np.max(ten)), min_tension=float(np.min(ten)), standard_error=sem,
        waveform=wave, phase=(np.arange(bins) + 0.5) / bins, tooth_period=period,
        chain_speed=_chain_speed(model, start, drv),
        settle_time=float(settle_time), settled=settled, measured_time=periods * steps * dt,
        dt=dt, step_error=step_error, method=method, cpu_time=time.process_time() - cpu0)


def check_counts(**values: Any) -> None:
    """Refuse a count or tolerance of :func:`steady_state` out of its range (``InputError``
    naming it)."""
    ranges = {"periods": (1, 10_000), "bins": (2, 1000), "window": (1, 100),
              "max_settle": (0, 100_000), "samples": (4, 10_000)}
    for name, value in values.items():
        if name in ranges:
            lo, hi = ranges[name]
            if not isinstance(value, (int, np.integer)) or not lo <= value <= hi:
                raise InputError(f"{name} must be a whole number from {lo} to {hi}, got {value!r}",
                                 field=name)
        elif not 0.0 < value < 1.0:
            raise InputError(f"{name} must be in (0, 1), e.g. 0.02, got {value!r}", field=name)


def default_settle_time(model: SimulationModel, start: State, period: float) -> float:
    """``steady_state``'s default ``min_settle_time`` [s]: the longer of two periods of the
    slowest first span mode (:func:`span_period`) and three time constants ``2/α`` of the
    spans' damping (mass-proportional: every transverse mode's envelope decays as
    ``exp(−α t/2)``, so a start transient is down to 5 %; ``3/(2π ζ)`` = 24 tooth periods at
    the default ``α = 2 ζ Ω``), at most ``MAX_AUTO_SETTLE`` tooth periods of ``period`` [s]."""
    alpha = model.span_damping_rate()
    decay = 6.0 / alpha if alpha > 0.0 else 0.0
    return min(max(2.0 * span_period(model, start), decay), MAX_AUTO_SETTLE * period)


def span_period(model: SimulationModel, state: State) -> float:
    """Period [s] of the slowest first transverse mode of the tight and the slack span.

    ``2L / sqrt(S/q)`` (taut string, Irvine, *Cable Structures*, MIT Press 1981, ch. 3),
    ``L`` the span's length between its tangent points, ``S`` the static tension of its
    middle link in ``state`` (at least 1 N), ``q`` the chain's mass per length.

    Examples
    --------
    >>> from chaindrive.simulation import roller_example, assemble
    >>> m = roller_example(links=40, teeth=12, gravity=False)
    >>> 0.0 < span_period(m, assemble(m)) < 1.0
    True
    """
    pos = state.pos
    n = pos.shape[0]
    seg = np.roll(pos, -1, axis=0) - pos
    length = np.hypot(seg[:, 0], seg[:, 1])
    rest = np.where(np.arange(n) % 2 == 0, state.par[K.P_PITCH], state.par[K.P_PITCH2])
    tension = state.par[K.P_K] * (length - rest)
    q = model.link_mass / model.pitch
    spans = (np.array(tight_span(model, state)), np.array(slack_span(model, state)))
    worst = 0.0
    for span, other in (spans, spans[::-1]):
        s = float(span_tension(pos[None], tension[None], span, other)[0])
        span_length = float(np.hypot(*(span[1] - span[0])))
        worst = max(worst, 2.0 * span_length / math.sqrt(max(s, 1.0) / q))
    return worst


def _chain_speed(model: SimulationModel, state: State, drv: int) -> float:
    par = state.par
    pbar = 0.5 * (par[K.P_PITCH] + par[K.P_PITCH2]) * (1.0 + model.prestrain)
    return float(state.wp[drv, K.W_NSEAT] * pbar * abs(state.ws[drv, K.S_OMEGA]) / (2.0 * math.pi))


def _model_of(drive: Any) -> SimulationModel:
    from ..drive import Drive
    from .from_drive import model_from_drive

    if not isinstance(drive, Drive):
        raise InputError(f"steady_state takes a chaindrive.drive.Drive or a SimulationModel, got "
                         f"{type(drive).__name__}", field="drive")
    return model_from_drive(drive)
