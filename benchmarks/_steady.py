"""Benchmark of ``chaindrive.simulation.steady.steady_state`` against a long reference run.

Drive: the 16B, 100-link drive of ``benchmarks/simulate.py`` (two 17-tooth sprockets,
20 rad/s, 200 N m); also the 2,194-link 100 m conveyor (``conveyor_example()``).

The steady state (defaults: warm start, settling detected, implicit step checked against
its half, 12 tooth periods measured) is timed from nothing (assembly included) in CPU time
(``time.process_time``), the best of ``--repeat`` calls after one warm-up call (the
numba cache loaded; the first call's time is printed as well). The reference is the
explicit integrator at its stable step from the same warm start: 0.5 s settling, then
``--reference`` seconds measured with the same statistics. Printed: the mean tension, the
waveform's peak, each period's peak (mean), the RMS difference of the waveforms (all
relative to the reference's mean or value), and

    steady state, 16B 100 links: X s CPU, within Y % of the reference

with ``Y`` the largest of the mean's and the waveform peak's differences and the
waveforms' RMS difference.

Run:  .venv/bin/python benchmarks/_steady.py (or benchmarks/simulate.py --steady) [--reference 4] [--repeat 5] [--conveyor]
"""

from __future__ import annotations

import argparse
import os
import time

import numpy as np

from chaindrive.simulation import assemble, conveyor_example, roller_example
from chaindrive.simulation.steady import steady_state


def bench_model():
    return roller_example(links=100, teeth=17, angular_velocity=20.0, load_torque=200.0,
                          ramp_time=0.1)


def reference(model, seconds=8.0, settle=0.5):
    """The long explicit run: ``settle`` s from the warm start, then ``seconds`` measured."""
    period = 2.0 * np.pi / (model.seats_per_turn(model.wheels[0].teeth)
                            * abs(model.wheels[0].angular_velocity))
    return steady_state(model, method="explicit", periods=max(int(seconds / period), 1),
                        max_settle=0, min_settle_time=settle,
                        settle_tolerance=1e-12)


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


def steady_lines(ref_seconds=8.0, repeat=5, conveyor=False):
    load = os.getloadavg()
    print(f"load average {load[0]:.2f} {load[1]:.2f} (2 cores shared); times are CPU times",
          flush=True)
    model = bench_model()
    s, cpu, first = timed(model, repeat)
    t0 = time.process_time()
    ref = reference(model, ref_seconds)
    t_ref = time.process_time() - t0
    dm, dp, dpp, rms = compare(s, ref)
    print(f"reference: explicit at {1e6 * ref.dt:.3g} us, {ref.measured_time:.2f} s after "
          f"{ref.settle_time:.2f} s ({t_ref:.2f} s CPU): mean {ref.mean_tension:.1f} N "
          f"(standard error {ref.standard_error:.1f} N), waveform peak {ref.peak_tension:.1f} N, "
          f"period peak {ref.period_peak_tension:.1f} N")
    print(f"steady state: settled after {s.settle_time:.3f} s ({'detected' if s.settled else 'NOT'}),"
          f" implicit at {1e6 * s.dt:.3g} us (error against the half step {100 * s.step_error:.2f} %),"
          f" {s.measured_time:.3f} s measured; first call {first:.3f} s CPU (numba cache)")
    print(f"  mean {s.mean_tension:.1f} N ({100 * dm:+.2f} %), waveform peak {s.peak_tension:.1f} N "
          f"({100 * dp:+.2f} %), waveform RMS difference {100 * rms:.2f} % of the mean; period "
          f"peak {s.period_peak_tension:.1f} N ({100 * dpp:+.2f} %, not in Y: the span "
          f"vibration keeps building up for seconds)")
    worst = max(abs(dm), abs(dp), rms)
    print(f"steady state, 16B 100 links: {cpu:.3f} s CPU, within {100 * worst:.1f} % of the reference",
          flush=True)
    if conveyor:
        cm = conveyor_example()
        assemble(cm)  # the assembly's first call (numba cache) not counted
        c, ccpu, _ = timed(cm, 1)
        print(f"steady state, conveyor {cm.links} links: {ccpu:.3f} s CPU (settled "
              f"{c.settled} after {c.settle_time:.2f} s, step {1e3 * c.dt:.3g} ms, error against "
              f"the half step {100 * c.step_error:.2f} %, mean {c.mean_tension / 1e3:.2f} kN, "
              f"waveform peak {c.peak_tension / 1e3:.2f} kN)", flush=True)
    return s, ref


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--reference", type=float, default=8.0, help="measured seconds of the reference")
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--conveyor", action="store_true")
    a = ap.parse_args()
    steady_lines(a.reference, a.repeat, a.conveyor)


if __name__ == "__main__":
    main()
