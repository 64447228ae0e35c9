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


def main(argv: list[str] | None = None) -> int:
    from chaindrive.analysis.conveyor import conveyor_pull
    from chaindrive.drive.project import load_project
    from chaindrive.simulation import simulate
    from chaindrive.simulation.conveyor import compare, steady_state
    from chaindrive.simulation.from_drive import model_from_drive

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--duration", type=float, default=6.0, help="simulated time per example [s]")
    ap.add_argument("--only", choices=sorted(EXAMPLES), help="run one example")
    args = ap.parse_args(argv)
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
    return 0 if worst <= LIMIT else 1


if __name__ == "__main__":
    status = main()
    if status:   # benchmarks/run_all.py runs this file in its own process: exit only on failure
        sys.exit(status)
