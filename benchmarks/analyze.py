"""Speed of the analysis layer and of ``chaindrive analyze``.

Prints, for each example project, ``analysis without plots: <name> <ms> ms`` (warm,
median of repeated runs of :func:`chaindrive.analysis.analyze_drive`; aim < 50 ms), then
the whole ``chaindrive analyze examples/roller_industrial.toml -o DIR`` process (a new
Python process each time, imports, five figures and the files included; aim < 2 s,
median of 5), and the report's time per section.
"""

from __future__ import annotations

import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from chaindrive.analysis import analyze_drive
from chaindrive.drive.project import load_project
from chaindrive.workflows.analyze import analyze

ROOT = Path(__file__).resolve().parents[1]
NAMES = ("mining_conveyor", "roller_industrial", "tractor_track")


def median_ms(fn, repeat: int = 15) -> float:
    fn()  # warm
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t)
    return statistics.median(times) * 1e3


def main() -> None:
    for name in NAMES:
        drive = load_project(ROOT / "examples" / f"{name}.toml")
        # the remedy search runs only when the resonance check fails (about a second); it is
        # timed on its own, the aim is for the analysis of one design
        print(f"analysis without plots: {name} "
              f"{median_ms(lambda d=drive: analyze_drive(d, exclude=['remedy'])):.1f} ms (aim < 50 ms)")
        if analyze_drive(drive, include=["remedy"]).remedy is not None:
            print(f"  remedy search of the failed resonance check: {name} "
                  f"{median_ms(lambda d=drive: analyze_drive(d, include=['remedy'])):.0f} ms")
    runs = []
    for _ in range(5):
        with tempfile.TemporaryDirectory() as tmp:
            t = time.perf_counter()
            subprocess.run([str(Path(sys.executable).parent / "chaindrive"), "analyze",
                            str(ROOT / "examples" / "roller_industrial.toml"), "-o", str(Path(tmp) / "out"), "-q"],
                           check=False)
            runs.append(time.perf_counter() - t)
    print(f"chaindrive analyze roller_industrial.toml (whole process, 5 figures): median {statistics.median(runs):.2f} s,"
          f" best {min(runs):.2f} s (aim < 2 s)")
    with tempfile.TemporaryDirectory() as tmp:
        outcome = analyze(load_project(ROOT / "examples" / "mining_conveyor.toml"), tmp)
    print("report of mining_conveyor.toml, seconds per part:")
    for key, sec in outcome.timings.items():
        print(f"  {key:16s} {sec:6.3f} s")


if __name__ == "__main__":
    main()
