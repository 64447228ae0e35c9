"""Benchmark of ``chaindrive.simulation.steady.steady_state`` against long reference runs.

Drive: the 16B, 100-link drive of ``benchmarks/simulate.py`` (two 17-tooth sprockets,
20 rad/s, 200 N m); also the 2,194-link 100 m conveyor (``conveyor_example()``).

The steady state (defaults: warm start, settling detected, implicit step checked against
its half, 12 tooth periods measured) is timed from nothing (assembly included) in CPU time
(``time.process_time``), the best of ``--repeat`` calls after one warm-up call (the
numba cache loaded; the first call's time is printed as well).

The reference is an ensemble of ``--members`` runs of the explicit integrator from the
same warm start, each at its own step (the stable step times 1, 0.995, 0.99, ...), one
tooth period per call, ``--settle`` seconds of running (default 8) then ``--reference``
seconds measured (default 8) with the same statistics. The running tension builds up
for seconds: the slack span's vibration grows (its mean tension from about 190 N at the
warm start towards 200-320 N, the tight span's mean with it), and a response at eight
times the tooth frequency (433 Hz) carries about 100 N for the first 6-8 s and 20-40 N
after; a reference that begins 0.5 s after the warm start (the reference before
2026-11-29) averages over that build-up. The same runs give, without extra cost:

* the early reference (0.5 s running, 8 s measured; the former reference);
* the floor: each run over the steady state's own window (the same simulated time after
  the warm start, the same number of periods) against the reference: what the exact
  integrator measures that early and that briefly.

Printed: the reference (its mean's standard error from the members' spread), the
members' scatter about their ensemble, the floor, the steady state's mean, waveform
peak, period peak (mean of each period's largest value) and the RMS difference of the
waveforms (relative to the reference's mean or value), and

    steady state, 16B 100 links: X s CPU, within Y % of the reference

with ``Y`` the largest of the mean's and the waveform peak's differences and the
waveforms' RMS difference against the ensemble. ``--spread`` also runs the steady state
at its step times 0.995 ... 1.01 (each run a sample of the same wandering state) and
prints the spread of ``Y``.

Run:  .venv/bin/python benchmarks/_steady.py (or benchmarks/simulate.py --steady) [--settle 8] [--reference 8] [--members 4] [--repeat 5] [--spread] [--conveyor]
"""

from __future__ import annotations

import argparse
import math
import os
import time
from dataclasses import dataclass

import numpy as np

from chaindrive.simulation import assemble, conveyor_example, roller_example
from chaindrive.simulation.steady import _Runner, span_period, steady_state, summarise, warm_start


def bench_model():
    return roller_example(links=100, teeth=17, angular_velocity=20.0, load_torque=200.0,
                          ramp_time=0.1)


@dataclass(frozen=True)
class Reference:
    """The ensemble of long runs: its statistics and its members' (``SteadyState``)."""

    mean_tension: float
    peak_tension: float
    period_peak_tension: float
    standard_error: float
    waveform: np.ndarray
    members: tuple
    cpu_time: float


#: the members' steps, times the stable step
MEMBER_STEPS = (1.0, 0.995, 0.99, 0.985, 0.98, 0.975, 0.97, 0.965)
#: samples per tooth period of the members (those of the steady state: 48)
SAMPLES = 48


@dataclass(frozen=True)
class Member:
    """One long explicit run from the warm start: every tooth period's tight-span tension
    and driver angle (``tens``, ``angles``), the period's length in steps of ``dt``."""

    tens: list
    angles: list
    steps: int
    dt: float

    @property
    def period_time(self):
        return self.steps * self.dt

    def window(self, model, start, t0, count, bins=16):
        """The statistics (``SteadyState``) of ``count`` periods from ``t0`` s after the
        warm start."""
        k = int(round(t0 / self.period_time))
        period = 2.0 * math.pi / (model.seats_per_turn(model.wheels[0].teeth)
                                  * abs(model.wheels[0].angular_velocity))
        return summarise(model, start, 0, period, bins, self.tens[k:k + count],
                         self.angles[k:k + count], k * self.period_time, False, self.steps,
                         self.dt, float("nan"), "explicit", time.process_time())


def member(model, start, dt, seconds):
    """An explicit run of ``seconds`` from ``start`` at step ``dt``, one tooth period per
    call of the integrator (:class:`Member`)."""
    period = 2.0 * math.pi / (model.seats_per_turn(model.wheels[0].teeth)
                              * abs(model.wheels[0].angular_velocity))
    run = _Runner(model, start, "explicit", dt, period, SAMPLES, 0)
    tens, angles = [], []
    for _ in range(int(math.ceil(seconds / (run.steps * dt)))):
        run.state, ten, ang = run.period()
        tens.append(ten)
        angles.append(ang)
    return Member(tens, angles, run.steps, dt)


def ensemble(runs, cpu_time=0.0):
    """:class:`Reference` of ``runs`` (``SteadyState`` each): their means and waveforms
    averaged; the mean's standard error from the runs' spread."""
    wave = np.mean([r.waveform for r in runs], axis=0)
    means = [r.mean_tension for r in runs]
    sem = float(np.std(means, ddof=1) / math.sqrt(len(runs))) if len(runs) > 1 else float("nan")
    return Reference(float(np.mean(means)), float(np.nanmax(wave)),
                     float(np.mean([r.period_peak_tension for r in runs])), sem, wave,
                     tuple(runs), cpu_time)


def references(model, seconds=8.0, settle=8.0, members=4, early=(0.5, 8.0)):
    """``members`` explicit runs (:data:`MEMBER_STEPS`) of ``settle + seconds`` from the warm
    start: (the reference: their ensemble over the last ``seconds``; the early one over
    ``early`` = (start, length) [s]; the runs, :class:`Member`; the warm start)."""
    t0 = time.process_time()
    start = warm_start(model, assemble(model))
    dt0 = model.stable_time_step()
    span = max(settle + seconds, sum(early))
    runs = [member(model, start, dt0 * f, span) for f in MEMBER_STEPS[:members]]
    cpu = time.process_time() - t0

    def over(t, length):
        return ensemble([r.window(model, start, t, int(length / r.period_time)) for r in runs], cpu)

    return over(settle, seconds), over(*early), runs, start


def timed(model, repeat=5, **kwargs):
    """(result, best CPU time of ``repeat`` calls, first call's CPU time)."""
    t0 = time.process_time()
    s = steady_state(model, **kwargs)
    first = time.process_time() - t0
    best = np.inf
    for _ in range(repeat):
        t0 = time.process_time()
        s = steady_state(model, **kwargs)
        best = min(best, time.process_time() - t0)
    return s, best, first


def compare(s, ref):
    """Relative differences of ``s`` against ``ref``: mean, waveform peak, period peak,
    waveform RMS (relative to the reference's mean)."""
    rms = float(np.sqrt(np.nanmean((s.waveform - ref.waveform) ** 2)) / ref.mean_tension)
    return (s.mean_tension / ref.mean_tension - 1.0, s.peak_tension / ref.peak_tension - 1.0,
            s.period_peak_tension / ref.period_peak_tension - 1.0, rms)


def within(s, ref):
    """``Y``: the largest of the mean's and the waveform peak's relative differences and
    the waveforms' RMS difference."""
    dm, dp, _, rms = compare(s, ref)
    return max(abs(dm), abs(dp), rms)


def steady_lines(ref_seconds=8.0, repeat=5, conveyor=False, members=4, spread=False, settle=8.0):
    load = os.getloadavg()
    print(f"load average {load[0]:.2f} {load[1]:.2f} (2 cores shared); times are CPU times",
          flush=True)
    model = bench_model()
    s, cpu, first = timed(model, repeat)
    ref, early, runs, start = references(model, ref_seconds, settle, members)
    own = [compare(r, ref) for r in ref.members]
    m0 = ref.members[0]
    print(f"reference: {len(ref.members)} explicit runs at "
          f"{', '.join(f'{1e6 * r.dt:.3g}' for r in ref.members)} us, each {m0.measured_time:.2f} s "
          f"after {m0.settle_time:.2f} s of running ({ref.cpu_time:.1f} s CPU): mean "
          f"{ref.mean_tension:.1f} N (standard error {ref.standard_error:.1f} N, from the runs' "
          f"spread), waveform peak {ref.peak_tension:.1f} N, period peak "
          f"{ref.period_peak_tension:.1f} N")
    if len(own) > 1:
        print(f"  the runs against their ensemble (the reference's own scatter): means "
              f"{100 * min(o[0] for o in own):+.2f} to {100 * max(o[0] for o in own):+.2f} %, "
              f"waveform peaks {100 * min(o[1] for o in own):+.2f} to "
              f"{100 * max(o[1] for o in own):+.2f} %, waveform RMS "
              f"{100 * min(o[3] for o in own):.2f} to {100 * max(o[3] for o in own):.2f} %")
    e0 = early.members[0]
    de = compare(early, ref)
    print(f"  the same runs {e0.measured_time:.2f} s after {e0.settle_time:.2f} s (the early "
          f"reference): mean {early.mean_tension:.1f} N ({100 * de[0]:+.2f} %), waveform peak "
          f"{early.peak_tension:.1f} N ({100 * de[1]:+.2f} %), waveform RMS difference "
          f"{100 * de[3]:.2f} %: the running tension still builds up")
    count = int(round(s.measured_time / (s.dt * round(s.tooth_period / s.dt))))
    windows = [r.window(model, start, s.settle_time, count) for r in runs]
    floor = [within(w, ref) for w in windows]
    print(f"  the same runs over the steady state's window ({s.settle_time:.2f} to "
          f"{s.settle_time + s.measured_time:.2f} s after the warm start, {count} periods): "
          f"within {100 * min(floor):.1f} to {100 * max(floor):.1f} % of the reference (the "
          f"exact integrator's own difference, that early and that briefly)")
    same = ensemble(windows)
    dsm, dsp, _, dsr = compare(s, same)
    among = [within(w, same) for w in windows]
    print(f"  the steady state against those windows' ensemble: mean {100 * dsm:+.2f} %, waveform "
          f"peak {100 * dsp:+.2f} %, waveform RMS difference {100 * dsr:.2f} % (the runs among "
          f"themselves {100 * min(among):.1f} to {100 * max(among):.1f} %): its own error at "
          f"equal time (settling at up to twice the step, the implicit integrator)")
    dm, dp, dpp, rms = compare(s, ref)
    print(f"steady state: settled after {s.settle_time:.3f} s ({'detected' if s.settled else 'NOT'}),"
          f" {s.method} at {1e6 * s.dt:.3g} us (error against the half step {100 * s.step_error:.2f} %),"
          f" {s.measured_time:.3f} s measured; first call {first:.3f} s CPU (numba cache)")
    print(f"  mean {s.mean_tension:.1f} N ({100 * dm:+.2f} %), waveform peak {s.peak_tension:.1f} N "
          f"({100 * dp:+.2f} %), waveform RMS difference {100 * rms:.2f} % of the mean; period "
          f"peak {s.period_peak_tension:.1f} N ({100 * dpp:+.2f} %, not in Y: the span "
          f"vibration keeps building up for seconds)")
    if len(own) > 1:
        single = [within(s, ensemble([r])) for r in ref.members]
        print(f"  against each run alone: within {100 * min(single):.1f} to {100 * max(single):.1f} %;"
              f" against the early reference: within {100 * within(s, early):.1f} %")
    worst = within(s, ref)
    if spread:
        ys = [worst]
        for f in (0.995, 1.005, 0.99, 1.01):
            ys.append(within(steady_state(model, dt=f * model.accurate_time_step()), ref))
        print(f"  the steady state at its step times 1, 0.995, 1.005, 0.99, 1.01: within "
              f"{', '.join(f'{100 * y:.1f}' for y in ys)} % (median {100 * np.median(ys):.1f} %)")
    print(f"steady state, 16B 100 links: {cpu:.3f} s CPU, within {100 * worst:.1f} % of the reference",
          flush=True)
    if conveyor:
        conveyor_lines()
    return s, ref


def conveyor_lines(settle=8.0, seconds=8.0):
    """The conveyor's steady state from nothing, its cost by phase, and against one long
    run of the implicit integrator (``settle`` s, then ``seconds`` measured)."""
    cm = conveyor_example()
    assemble(cm)  # the assembly's first call (numba cache) not counted
    c, ccpu, _ = timed(cm, 1)
    t0 = time.process_time()
    st = assemble(cm)
    t_asm = time.process_time() - t0
    # link-steps of each phase: the settling (at the measuring step here: the links'
    # transverse stiffness allows no larger one), the check (1.5 periods' cost) and the
    # measurement
    per = int(round(c.tooth_period / c.dt))
    settle_steps = int(round(c.settle_time / c.dt))
    check_steps = 3 * per if not np.isnan(c.step_error) else 0
    meas_steps = int(round(c.measured_time / c.dt)) - (per if check_steps else 0)
    total = settle_steps + check_steps + meas_steps
    print(f"steady state, conveyor {cm.links} links: {ccpu:.3f} s CPU: assembly {t_asm:.2f} s, "
          f"then {total:,} steps of {1e3 * c.dt:.3g} ms x {cm.links} links = "
          f"{total * cm.links / 1e6:.1f} M link-steps ({1e9 * (ccpu - t_asm) / (total * cm.links):.0f}"
          f" ns each): settling {settle_steps:,} ({c.settle_time:.2f} s simulated, "
          f"{'detected' if c.settled else 'NOT settled'}; span_period "
          f"{span_period(cm, st):.2f} s), the check {check_steps:,} (error against the half step "
          f"{100 * c.step_error:.2f} %), measuring {meas_steps:,} ({c.measured_time:.2f} s)",
          flush=True)
    t0 = time.process_time()
    r = steady_state(cm, min_settle_time=settle, max_settle=0, settle_tolerance=1e-12,
                     periods=max(int(seconds / c.tooth_period), 1), state=st)
    dm, dp, _, rms = compare(c, r)
    print(f"  against one implicit run, {r.measured_time:.1f} s after {r.settle_time:.1f} s "
          f"({time.process_time() - t0:.1f} s CPU): mean {c.mean_tension / 1e3:.2f} kN "
          f"({100 * dm:+.2f} %), waveform peak {c.peak_tension / 1e3:.2f} kN ({100 * dp:+.2f} %), "
          f"waveform RMS difference {100 * rms:.2f} % of the mean", flush=True)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--reference", type=float, default=8.0, help="measured seconds of each reference run")
    ap.add_argument("--settle", type=float, default=8.0,
                    help="seconds each reference run runs before its measurement")
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--members", type=int, default=4, help="long runs in the reference's ensemble")
    ap.add_argument("--spread", action="store_true", help="the steady state at five steps")
    ap.add_argument("--conveyor", action="store_true")
    a = ap.parse_args()
    steady_lines(a.reference, a.repeat, a.conveyor, max(1, min(a.members, len(MEMBER_STEPS))),
                 a.spread, a.settle)


if __name__ == "__main__":
    main()
