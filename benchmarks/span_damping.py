"""Span damping study (docs/simulation.md "Span damping"): the transverse
span damping ``SimulationModel.span_damping`` (α [1/s]) on the benchmark drive and on two
drives of the dynamic-load sweep. Not imported by the package; not run by CI.

    python benchmarks/span_damping.py bench [α ...]     # 16B benchmark drive, 16 s each
    python benchmarks/span_damping.py steady [α ...]    # steady_state (explicit, implicit) vs 2 runs 8 s after 8 s
    python benchmarks/span_damping.py sweep S13 [α ...] # a sweep drive, as benchmarks/_dynamic_sweep.py
"""

from __future__ import annotations

import dataclasses
import math
import os
import sys
import time
import warnings

import numpy as np

sys.path.insert(0, os.path.dirname(__file__))

from chaindrive.simulation import assemble, simulate  # noqa: E402
from chaindrive.simulation.steady import warm_start  # noqa: E402


def bench(alphas, seconds=16.0):
    from _steady import bench_model

    base = bench_model()
    start = warm_start(base, assemble(base))
    period = 2 * math.pi / (17 * 20.0)
    dt = base.stable_time_step()
    every = max(1, int(round(period / dt / 48)))
    print(f"# load {os.getloadavg()[0]:.1f}; tooth period {period * 1e3:.2f} ms, dt {dt * 1e6:.3f} us")
    for a in alphas:
        m = dataclasses.replace(base, span_damping=a)
        c0 = time.process_time()
        r = simulate(m, seconds, state=start, record_every=every, samples=10**7)
        cpu = time.process_time() - c0
        t = np.asarray(r.time) - r.time[0]
        tt, ts = r.tight_side_tension(), r.slack_side_tension()
        wins = [(t >= s) & (t < s + 1.0) for s in range(int(seconds))]
        tm = [tt[w].mean() for w in wins]
        sm = [ts[w].mean() for w in wins]
        k = np.floor(t / period).astype(int)
        peaks = np.array([tt[k == j].max() for j in range(k.max())])
        tp = t[:len(peaks)] if False else np.arange(len(peaks)) * period
        med = [np.median(peaks[(tp >= s) & (tp < s + 1.0)]) for s in range(int(seconds))]
        print(f"alpha {a:g} 1/s  CPU {cpu:.1f} s")
        print("  tight mean per 1 s [N]: " + " ".join(f"{v:.0f}" for v in tm))
        print("  slack mean per 1 s [N]: " + " ".join(f"{v:.0f}" for v in sm))
        print("  tight median period peak per 1 s [N]: " + " ".join(f"{v:.0f}" for v in med))
        print(f"  0.5-4 s: mean {tt[(t >= 0.5) & (t < 4)].mean():.0f}, 8-16 s: mean {tt[t >= 8].mean():.0f}"
              f" slack {ts[t >= 8].mean():.0f}, median peak {np.median(peaks[tp >= 8]):.0f}")


def steady(alphas, members=2, methods=("explicit", "implicit")):
    from _steady import bench_model, compare, references, timed

    base = bench_model()
    print(f"# load {os.getloadavg()[0]:.1f}; CPU: best of 3 calls (first call in brackets)")
    for a in alphas:
        m = dataclasses.replace(base, span_damping=a)
        ref, early, _, _ = references(m, seconds=8.0, settle=8.0, members=members)
        for method in methods:
            s, cpu, first = timed(m, repeat=3, method=method)
            for name, rf in (("8 s after 8 s", ref), ("early 0.5-8.5 s", early)):
                dm, dp, dpp, rms = compare(s, rf)
                print(f"alpha {a:g} {s.method} ({method}, dt {s.dt * 1e6:.1f} us, step error {s.step_error:.2%}): "
                      f"steady {s.mean_tension:.0f} N (settled {s.settled} at {s.settle_time:.2f} s, "
                      f"CPU {cpu:.3f} s [{first:.3f}]) vs {name} {rf.mean_tension:.0f} N +- {rf.standard_error:.0f}: "
                      f"mean {dm:+.2%} wave peak {dp:+.2%} period peak {dpp:+.2%} rms {rms:.2%}  "
                      f"Y {max(abs(dm), abs(dp), rms):.2%}", flush=True)


def sweep(name, alphas):
    from _dynamic_sweep import (
        drive_of,
        periods_and_settle,
        read_cache,
        settled_run,
        sweep_drives,
        tooth_peaks,
    )

    warnings.simplefilter("ignore")
    s = next(d for d in sweep_drives(64) if d.name == name)
    row = next(r for r in read_cache() if r["name"] == name)
    kc = float(row["contact_stiffness"])
    d = drive_of(s)
    periods, settle = periods_and_settle(d)
    print(f"# {name}: cache mean {float(row['sim_mean']):.0f} peak {float(row['sim_peak']):.0f}; load "
          f"{os.getloadavg()[0]:.1f}")
    for a in alphas:
        c0 = time.process_time()
        t, ts = settled_run(d, periods, settle, contact_stiffness=kc, span_damping=a)
        pk = tooth_peaks(d, t, ts)
        print(f"{name} alpha {a:g}: mean {ts.mean():.0f} median peak {np.median(pk):.0f} p90 "
              f"{np.quantile(pk, 0.9):.0f}  CPU {time.process_time() - c0:.1f} s")


if __name__ == "__main__":
    what = sys.argv[1]
    if what == "sweep":
        sweep(sys.argv[2], [float(v) for v in sys.argv[3:]] or [0.0])
    else:
        vals = [float(v) for v in sys.argv[2:]] or [0.0]
        {"bench": bench, "steady": steady}[what](vals)
