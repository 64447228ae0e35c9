"""One steady state: the conveyor analysis and the simulation on the same conveyors.

For each example (the 30 m scraper conveyor and the 100 m long conveyor) the analysis
(:func:`chaindrive.analysis.conveyor.conveyor_pull`: friction on the pans, the material,
the free return strand as a catenary, the spring tensioner with the chain's length
fixed) and a simulation of the same project file (pans as unilateral contacts with
regularised Coulomb friction, the material scraped along the carrying pan; the head's
speed ramped up over RAMP, the means taken over the last WINDOW of the run) are
compared: the tension leaving the head (slack), arriving at it (tight), the largest
sag of the free return strand and the force of the spring tensioner (the analysis: the
chain's pull on the tensioner wheel along the catenary's end tangents; the simulation:
preload less stiffness times the mean slide travel).

Usage: ``python benchmarks/conveyor.py [--duration S]``. Prints per example

    steady state NAME: slack tension analysis X N, simulation Y N, difference Z %

and the same for ``tight tension``, ``sag`` (then in m) and ``tensioner force``; exits 1 if any difference
exceeds 5 %.

``--steady [--reference S]`` (also at the end of the default run): the running steady state of the 2,194-link 100 m conveyor
(``conveyor_example()``) from nothing, :func:`chaindrive.simulation.conveyor_steady.running_steady_state`
(assembly included, CPU time, the best of ``--repeat`` calls after a first one that loads the
numba cache), against a long reference: one implicit run from the same warm start, 2 s, then
``--reference`` seconds (default 40) measured with the same statistics (its two halves against
it: the reference's own uncertainty; the drive's tension beats over 20-30 s); also
``steady_state``'s default (settling two periods of the span's 2.26 s mode) in the same run.
Prints

    steady state, conveyor 2194 links: X s CPU, within Y % of the reference

``Y`` the largest of the mean's and the waveform peak's differences and the waveforms' RMS
difference (relative to the reference's mean), as ``benchmarks/_steady.py``.
"""

from __future__ import annotations

import argparse
import pathlib
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]
EXAMPLES = {"scraper_conveyor": ROOT / "examples" / "scraper_conveyor.toml",
            "long_conveyor": ROOT / "examples" / "long_conveyor.toml"}
RAMP = 1.5        # head speed ramp [s]
WINDOW = 0.4      # fraction of the run averaged
LIMIT = 5.0       # [%]


def _differences(s, ref):
    """Mean, waveform peak, waveform RMS of ``s`` against ``ref`` (relative) and their worst."""
    import numpy as np

    rms = float(np.sqrt(np.nanmean((s.waveform - ref.waveform) ** 2)) / ref.mean_tension)
    d = (s.mean_tension / ref.mean_tension - 1.0, s.peak_tension / ref.peak_tension - 1.0, rms)
    return (*d, max(abs(d[0]), abs(d[1]), d[2]))


def _reference(model, state, settle=2.0, seconds=40.0):
    """The long run (implicit, the steady state's step, warm start): its statistics over
    ``seconds`` after ``settle`` and over each half (``SteadyState`` of
    :mod:`chaindrive.simulation.steady`), and its CPU time."""
    import math

    import numpy as np

    from chaindrive.simulation import steady as S

    cpu0 = time.process_time()
    start = S.warm_start(model, state)
    om = abs(model.wheels[0].angular_velocity)
    period = 2.0 * math.pi / (model.seats_per_turn(model.wheels[0].teeth) * om)
    run = S._Runner(model, start, "implicit", model.accurate_time_step(), period, 48, 0)
    run.state = run.period(count=int(round(settle / period)))[0]
    tens, angles = [], []
    for _ in range(int(seconds / period)):
        run.state, ten, ang = run.period()
        tens.append(ten)
        angles.append(ang)
    half = len(tens) // 2

    def stats(a, b):
        return S.summarise(model, start, 0, period, 16, tens[a:b], angles[a:b], settle, True,
                           run.steps, run.dt, float("nan"), "implicit", cpu0)

    whole = stats(0, len(tens))
    return whole, (stats(0, half), stats(half, len(tens))), time.process_time() - cpu0, np.float64(period)


def steady_lines(reference=40.0, repeat=3):
    """The conveyor's running steady state from nothing against the long reference."""
    import os

    from chaindrive.simulation import assemble, conveyor_example
    from chaindrive.simulation.conveyor_steady import running_steady_state
    from chaindrive.simulation.steady import steady_state

    load = os.getloadavg()
    print(f"load average {load[0]:.2f} {load[1]:.2f} (2 cores shared); times are CPU times", flush=True)
    cm = conveyor_example()
    running_steady_state(cm)                 # the numba cache loaded
    best = float("inf")
    for _ in range(repeat):
        t0 = time.process_time()
        s = running_steady_state(cm)
        best = min(best, time.process_time() - t0)
    t0 = time.process_time()
    st = assemble(cm)
    t_asm = time.process_time() - t0
    t0 = time.process_time()
    old = steady_state(cm)
    t_old = time.process_time() - t0
    ref, halves, t_ref, period = _reference(cm, st, seconds=reference)
    print(f"reference: one implicit run at {1e6 * ref.dt:.0f} us, {ref.measured_time:.1f} s after 2 s "
          f"({t_ref:.1f} s CPU): mean {ref.mean_tension / 1e3:.2f} kN, waveform peak "
          f"{ref.peak_tension / 1e3:.2f} kN; its halves against it: "
          + ", ".join("mean {:+.2f} %, peak {:+.2f} %, RMS {:.2f} %".format(*(100 * x for x in
                                                                           _differences(h, ref)[:3]))
                      for h in halves), flush=True)
    for name, x, cpu in (("running_steady_state", s, best),
                         ("steady_state's default (before)", old, t_old)):
        dm, dp, rms, worst = _differences(x, ref)
        print(f"  {name}: {cpu:.3f} s CPU, settled after {x.settle_time:.2f} s, {x.measured_time:.2f} s "
              f"measured at {1e6 * x.dt:.0f} us (step error {100 * x.step_error:.2f} %): mean "
              f"{100 * dm:+.2f} %, waveform peak {100 * dp:+.2f} %, waveform RMS {100 * rms:.2f} % "
              f"(within {100 * worst:.2f} %)", flush=True)
    print(f"steady state, conveyor {cm.links} links: {best:.3f} s CPU (assembly {t_asm:.2f} s), "
          f"within {100 * _differences(s, ref)[3]:.1f} % of the reference", flush=True)


def main(argv: list[str] | None = None) -> int:
    from chaindrive.analysis.conveyor import conveyor_pull
    from chaindrive.drive.project import load_project
    from chaindrive.simulation import simulate
    from chaindrive.simulation.conveyor import compare, steady_state
    from chaindrive.simulation.from_drive import model_from_drive

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--duration", type=float, default=6.0, help="simulated time per example [s]")
    ap.add_argument("--only", choices=sorted(EXAMPLES), help="run one example")
    ap.add_argument("--steady", action="store_true",
                    help="only the 2,194-link conveyor's running steady state against a long run "
                         "(also part of the default run)")
    ap.add_argument("--reference", type=float, default=40.0, help="measured seconds of the reference [s]")
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args(argv)
    if args.steady:
        steady_lines(args.reference, max(args.repeat, 1))
        return 0
    worst = 0.0
    for name, path in EXAMPLES.items():
        if args.only and name != args.only:
            continue
        drive = load_project(path)
        pull = conveyor_pull(drive)
        model = model_from_drive(drive, ramp_time=RAMP)
        t0 = time.perf_counter()
        result = simulate(model, args.duration, samples=600)
        wall = time.perf_counter() - t0
        state = steady_state(result, model, drive, start=(1.0 - WINDOW) * args.duration)
        for what, (a, s, diff) in compare(pull, state).items():
            unit = "m" if what == "sag" else "N"
            fmt = "{:.4g}" if unit == "m" else "{:.0f}"
            print(f"steady state {name}: {what} analysis {fmt.format(a)} {unit}, simulation "
                  f"{fmt.format(s)} {unit}, difference {diff:+.2f} %")
            worst = max(worst, abs(diff))
        print(f"# {name}: {model.links} links, {args.duration:g} s simulated in {wall:.0f} s; "
              f"tension std over the window: slack {state.slack_tension_std:.0f} N, "
              f"tight {state.tight_tension_std:.0f} N; sag std {state.return_sag_std * 1e3:.1f} mm")
    print(f"# worst difference {worst:.2f} % (limit {LIMIT:g} %)")
    if not args.only:
        steady_lines(args.reference, max(args.repeat, 1))
    return 0 if worst <= LIMIT else 1


if __name__ == "__main__":
    status = main()
    if status:   # benchmarks/run_all.py runs this file in its own process: exit only on failure
        sys.exit(status)
