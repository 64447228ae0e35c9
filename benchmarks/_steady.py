"""Benchmark of ``chaindrive.simulation.steady.steady_state`` against a long reference run.

Drive: the 16B, 100-link drive of ``benchmarks/simulate.py`` (two 17-tooth sprockets,
20 rad/s, 200 N m); also the 2,194-link 100 m conveyor (``conveyor_example()``).

The steady state (defaults: warm start, settling detected, implicit step checked against
its half, 12 tooth periods measured) is timed from nothing (assembly included) in CPU time
(``time.process_time``), the best of ``--repeat`` calls after one warm-up call (the
numba cache loaded; the first call's time is printed as well).

The reference is an ensemble of ``--members`` long runs of the explicit integrator from
the same warm start, each at its own step (the stable step times 1, 0.995, 0.99, ...):
0.5 s settling, then ``--reference`` seconds measured with the same statistics. The
drive's undamped span vibration makes its tension wander over seconds, so one long run
is itself only a sample: two 8 s runs whose steps differ by 0.5 % differ by up to 0.8 %
in the mean and 1.5 % in the waveform (RMS). The ensemble averages the members' means
and waveforms; the members' own differences from it (printed) are the reference's
uncertainty. Printed: the mean tension, the waveform's peak, each period's peak (mean),
the RMS difference of the waveforms (all relative to the reference's mean or value), and

    steady state, 16B 100 links: X s CPU, within Y % of the reference

with ``Y`` the largest of the mean's and the waveform peak's differences and the
waveforms' RMS difference against the ensemble. ``--spread`` also runs the steady state
at its step times 0.995 ... 1.01 (each run a sample of the same wandering state) and
prints the spread of ``Y``.

Run:  .venv/bin/python benchmarks/_steady.py (or benchmarks/simulate.py --steady) [--reference 8] [--members 4] [--repeat 5] [--spread] [--conveyor]
"""

from __future__ import annotations

import argparse
import os
import time
from dataclasses import dataclass

import numpy as np

from chaindrive.simulation import assemble, conveyor_example, roller_example
from chaindrive.simulation.steady import span_period, steady_state


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


def reference(model, seconds=8.0, settle=0.5, members=4):
    """``members`` long explicit runs (:data:`MEMBER_STEPS`): ``settle`` s from the warm
    start, then ``seconds`` measured; their ensemble (:class:`Reference`)."""
    period = 2.0 * np.pi / (model.seats_per_turn(model.wheels[0].teeth)
                            * abs(model.wheels[0].angular_velocity))
    dt0 = model.stable_time_step()
    t0 = time.process_time()
    runs = tuple(steady_state(model, method="explicit", dt=dt0 * f,
                              periods=max(int(seconds / period), 1), max_settle=0,
                              min_settle_time=settle, settle_tolerance=1e-12)
                 for f in MEMBER_STEPS[:members])
    wave = np.mean([r.waveform for r in runs], axis=0)
    sem = float(np.sqrt(np.sum([r.standard_error ** 2 for r in runs]))) / len(runs)
    return Reference(float(np.mean([r.mean_tension for r in runs])), float(np.nanmax(wave)),
                     float(np.mean([r.period_peak_tension for r in runs])), sem, wave, runs,
                     time.process_time() - t0)


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


def steady_lines(ref_seconds=8.0, repeat=5, conveyor=False, members=4, spread=False):
    load = os.getloadavg()
    print(f"load average {load[0]:.2f} {load[1]:.2f} (2 cores shared); times are CPU times",
          flush=True)
    model = bench_model()
    s, cpu, first = timed(model, repeat)
    ref = reference(model, ref_seconds, members=members)
    own = [compare(r, ref) for r in ref.members]
    m0 = ref.members[0]
    print(f"reference: {len(ref.members)} explicit runs at "
          f"{', '.join(f'{1e6 * r.dt:.3g}' for r in ref.members)} us, each {m0.measured_time:.2f} s "
          f"after {m0.settle_time:.2f} s ({ref.cpu_time:.1f} s CPU): mean {ref.mean_tension:.1f} N "
          f"(standard error {ref.standard_error:.1f} N), waveform peak {ref.peak_tension:.1f} N, "
          f"period peak {ref.period_peak_tension:.1f} N")
    if len(own) > 1:
        print(f"  the runs against their ensemble (the reference's own scatter): means "
              f"{100 * min(o[0] for o in own):+.2f} to {100 * max(o[0] for o in own):+.2f} %, "
              f"waveform peaks {100 * min(o[1] for o in own):+.2f} to "
              f"{100 * max(o[1] for o in own):+.2f} %, waveform RMS "
              f"{100 * min(o[3] for o in own):.2f} to {100 * max(o[3] for o in own):.2f} %")
    dm, dp, dpp, rms = compare(s, ref)
    print(f"steady state: settled after {s.settle_time:.3f} s ({'detected' if s.settled else 'NOT'}),"
          f" {s.method} at {1e6 * s.dt:.3g} us (error against the half step {100 * s.step_error:.2f} %),"
          f" {s.measured_time:.3f} s measured; first call {first:.3f} s CPU (numba cache)")
    print(f"  mean {s.mean_tension:.1f} N ({100 * dm:+.2f} %), waveform peak {s.peak_tension:.1f} N "
          f"({100 * dp:+.2f} %), waveform RMS difference {100 * rms:.2f} % of the mean; period "
          f"peak {s.period_peak_tension:.1f} N ({100 * dpp:+.2f} %, not in Y: the span "
          f"vibration keeps building up for seconds)")
    if len(own) > 1:
        single = [max(abs(a), abs(b), c) for a, b, _, c in (compare(s, r) for r in ref.members)]
        print(f"  against each run alone: within {100 * min(single):.1f} to {100 * max(single):.1f} %")
    worst = max(abs(dm), abs(dp), rms)
    if spread:
        ys = [worst]
        for f in (0.995, 1.005, 0.99, 1.01):
            o = compare(steady_state(model, dt=f * model.accurate_time_step()), ref)
            ys.append(max(abs(o[0]), abs(o[1]), o[3]))
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
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--members", type=int, default=4, help="long runs in the reference's ensemble")
    ap.add_argument("--spread", action="store_true", help="the steady state at five steps")
    ap.add_argument("--conveyor", action="store_true")
    a = ap.parse_args()
    steady_lines(a.reference, a.repeat, a.conveyor, max(1, min(a.members, len(MEMBER_STEPS))),
                 a.spread)


if __name__ == "__main__":
    main()
