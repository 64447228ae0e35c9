"""Speed of the analysis layer and of ``chaindrive analyze``.

Prints, for each example project (warm: the process has analysed it before; median of
repeated runs of :func:`chaindrive.analysis.analyze_drive`, wall and CPU time):

* ``without the remedy search, reused``: every part but ``remedy``, the process having
  analysed that drive before. The analysis keeps the results of its pure sub-computations keyed on
  their inputs (:mod:`chaindrive.analysis._memo`: wheel entries, layout geometry, the
  slack-span catenary, the tensioner frequencies and responses), so a repeated analysis,
  or one after an edit that leaves them unchanged (the web studio), reuses them;
* ``without the remedy search, never seen``: the aim <= 3 ms of issue 33 for a drive the
  process has never analysed: the median CPU time over ``UNSEEN`` distinct drives (the
  last wheel moved by 7.3 mm steps, so the centre distance and most link counts differ),
  each after :func:`chaindrive.analysis._memo.clear` (every store of the analysis and
  every formula cache it relies on emptied: layout grids, polygon vertices, pitch radii,
  entry seatings, the jump-over check's tooth forms and table rows), so nothing of that drive,
  or of its wheels, is known before;
* ``with the remedy search``: every part (the remedy is a search over designs, ~0.1-0.4 s,
  run only when the resonance check fails: the mining conveyor).

Then the whole ``chaindrive analyze examples/roller_industrial.toml -o DIR`` process (a new
Python process each time, imports, the report's charts and the files included; aim < 1.0 s
on a quiet machine, median of 5; and with ``--png``, the seven figures drawn by matplotlib),
and the report's time per section.
"""

from __future__ import annotations

import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from chaindrive.analysis import _memo, analyze_drive
from chaindrive.drive.project import load_project
from chaindrive.workflows.analyze import analyze

ROOT = Path(__file__).resolve().parents[1]
NAMES = ("mining_conveyor", "roller_industrial", "tractor_track")


def median_ms(fn, repeat: int = 15) -> tuple[float, float]:
    """Median wall and CPU milliseconds of ``fn()`` (warm)."""
    fn()  # warm
    walls, cpus = [], []
    for _ in range(repeat):
        t, c = time.perf_counter(), time.process_time()
        fn()
        walls.append(time.perf_counter() - t)
        cpus.append(time.process_time() - c)
    return statistics.median(walls) * 1e3, statistics.median(cpus) * 1e3


#: Distinct drives of the "never seen" figure.
UNSEEN = 40


def unseen_ms(drive, count: int = UNSEEN) -> tuple[float, float]:
    """Median wall and CPU milliseconds of the analysis of ``count`` drives never seen: the
    last wheel moved by 7.3 mm steps along x, every store emptied before each."""
    last = drive.wheels[-1]
    x, y = last.position
    drives = [drive.with_wheel(last.name, position=(x + 0.0073 * (k + 1), y)) for k in range(count)]
    _memo.clear()
    analyze_drive(drive, exclude=["remedy"])  # imports and numpy's first calls
    walls, cpus = [], []
    for d in drives:
        _memo.clear()
        t, c = time.perf_counter(), time.process_time()
        analyze_drive(d, exclude=["remedy"])
        walls.append(time.perf_counter() - t)
        cpus.append(time.process_time() - c)
    return statistics.median(walls) * 1e3, statistics.median(cpus) * 1e3


def main() -> None:
    print(f"load average {' '.join(f'{x:.2f}' for x in os.getloadavg())} (2 cores shared: CPU time is the steadier figure)")
    for name in NAMES:
        drive = load_project(ROOT / "examples" / f"{name}.toml")
        wall, cpu = median_ms(lambda d=drive: analyze_drive(d, exclude=["remedy"]))
        print(f"analysis without plots, without the remedy search, reused:   {name} {wall:.1f} ms wall, {cpu:.1f} ms "
              "CPU")

        wall, cpu = unseen_ms(drive)
        print(f"analysis without plots, without the remedy search, never seen: {name} {wall:.1f} ms wall, "
              f"{cpu:.1f} ms CPU (median of {UNSEEN} distinct drives, every cache emptied; aim <= 3 ms)")
        wall, cpu = median_ms(lambda d=drive: analyze_drive(d), repeat=5 if name == "mining_conveyor" else 15)
        print(f"analysis without plots, with the remedy search:              {name} {wall:.1f} ms wall, {cpu:.1f} ms CPU")
    for label, extra in (("charts drawn by the browser", []), ("--png: 7 PNG figures", ["--png"])):
        walls, cpus = [], []
        for _ in range(5):
            with tempfile.TemporaryDirectory() as tmp:
                before = os.times()
                t = time.perf_counter()
                subprocess.run([str(Path(sys.executable).parent / "chaindrive"), "analyze",
                                str(ROOT / "examples" / "roller_industrial.toml"), "-o", str(Path(tmp) / "out"), "-q",
                                *extra], check=False)
                walls.append(time.perf_counter() - t)
                after = os.times()
                cpus.append(after.children_user + after.children_system - before.children_user
                            - before.children_system)
        print(f"chaindrive analyze roller_industrial.toml (whole process, {label}): median {statistics.median(walls):.2f} s"
              f" wall, best {min(walls):.2f} s, CPU {statistics.median(cpus):.2f} s (aim < 1.0 s on a quiet machine)")
    with tempfile.TemporaryDirectory() as tmp:
        outcome = analyze(load_project(ROOT / "examples" / "mining_conveyor.toml"), tmp)
    print("report of mining_conveyor.toml, seconds per part:")
    for key, sec in outcome.timings.items():
        print(f"  {key:16s} {sec:6.3f} s")


if __name__ == "__main__":
    main()
