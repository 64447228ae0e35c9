"""The analysis's dynamic load of the polygonal action against the simulation's peak tension.

For roller-chain drives (the roller example, the design procedure's drive of issue 19 and
the ``chaindrive new`` roller template) it prints the analysis's tight-side tension
``F_tight = K_s T/R + S + q v²``, its dynamic part ``m a_max`` and ``F_max``, and the
simulation's tight-span tension after settling (mean, median of the per-tooth-period
peaks, overall peak; :func:`chaindrive.simulation.model_from_drive` +
:func:`chaindrive.simulation.simulate`), with the ratio ``F_max / peak``. Not a timed
benchmark: it documents the comparison of issue 19 item 4 (docs/design.md).

Run: ``PYTHONPATH=src python benchmarks/dynamic_load.py``.
"""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import numpy as np

from chaindrive.analysis import analyze_drive
from chaindrive.drive.project import load_project, parse_project, template
from chaindrive.simulation import model_from_drive, simulate

ROOT = Path(__file__).resolve().parents[1]


def drives():
    yield "examples/roller_industrial.toml", load_project(ROOT / "examples" / "roller_industrial.toml")
    yield "chaindrive new (roller template)", parse_project(template("roller"))
    from chaindrive.design import Duty, design_drive

    duty = Duty(11e3, 1460 * math.pi / 30, driven_speed=480 * math.pi / 30, driven_machine="varying_conveyor",
                centre_distance=0.6)
    yield "issue 19 duty (design_drive)", design_drive(duty).recommended.drive()


def main(periods: int = 12, settle: float = 0.3) -> None:
    warnings.simplefilter("ignore")
    print(f"{'drive':34s} {'F_tight':>8s} {'m a':>8s} {'F_max':>8s} | {'sim mean':>8s} {'sim peak':>8s} "
          f"{'sim max':>8s} | F_max/peak  [N]")
    for name, drive in drives():
        loads = analyze_drive(drive, include=["loads"]).loads
        z = drive.driving_wheel.teeth
        tooth = 2 * math.pi / drive.speed / z
        res = simulate(model_from_drive(drive), settle + periods * z * tooth / 4, settle=settle, samples=20000)
        t = np.asarray(res.time)
        ts = res.tight_side_tension()
        keep = t > settle
        peaks = [ts[(t >= t0) & (t < t0 + tooth)].max() for t0 in np.arange(settle, t[-1] - tooth, tooth)]
        peak = float(np.median(peaks))
        print(f"{name:34s} {loads.tight:8.0f} {loads.dynamic:8.0f} {loads.maximum:8.0f} | {ts[keep].mean():8.0f} "
              f"{peak:8.0f} {ts[keep].max():8.0f} | {loads.maximum / peak:.2f}")


if __name__ == "__main__":
    main()
