"""Calibrate the reduced running-tension model against the simulated sweep (issue 29.4).

Reads ``benchmarks/data/dynamic_sweep.csv`` (``python benchmarks/_dynamic_sweep.py 64``:
one row per simulated drive), fits ``a, b, c`` of
``F_peak = F_t (1 + a x^b (z/19)^c)`` (:func:`chaindrive.vibration.running_tension.running_peak_tension`)
to the median per-tooth-period peaks of the calibration drives (S00–S47) by least squares
of the relative error, checks the hold-out drives (S48 on), and with ``--write`` stores the
constants, the validity range and the provenance in
``src/chaindrive/vibration/data/running_tension.json``.

Run: ``PYTHONPATH=src python scripts/calibrate_running_tension.py [--write]``.
"""

from __future__ import annotations

import csv
import json
import math
import sys
from pathlib import Path

import numpy as np
from scipy.optimize import least_squares

ROOT = Path(__file__).resolve().parents[1]
SWEEP = ROOT / "benchmarks" / "data" / "dynamic_sweep.csv"
OUT = ROOT / "src" / "chaindrive" / "vibration" / "data" / "running_tension.json"
CALIBRATION_DRIVES = 48
REFERENCE_TEETH = 19.0
#: the sweep's design ranges (benchmarks/_dynamic_sweep.py, sweep_drives)
RANGES = {"pitch": [0.0127, 0.03175], "teeth": [13, 27], "ratio": [1.0, 3.5], "rpm": [100.0, 1800.0],
          "chain_speed": [0.0, 12.0], "centre_pitches": [25.0, 60.0], "pull_ratio": [0.02, 0.12], "wheels": [2, 2]}


def load() -> dict[str, np.ndarray]:
    with SWEEP.open() as f:
        rows = list(csv.DictReader(f))
    out = {k: np.array([float(r[k]) for r in rows]) for k in rows[0] if k not in ("name", "chain")}
    out["index"] = np.array([int(r["name"][1:]) for r in rows])
    return out


def impact_ratio(a: dict[str, np.ndarray]) -> np.ndarray:
    """``x = ω p √(k_c q p) / F_t`` of each row (the formulas of the module, inlined)."""
    w = a["rpm"] * math.pi / 30
    return w * a["pitch"] * np.sqrt(a["contact_stiffness"] * a["mass_per_length"] * a["pitch"]) / a["tight"]


def model(c: np.ndarray, a: dict[str, np.ndarray]) -> np.ndarray:
    return a["tight"] * (1 + c[0] * impact_ratio(a) ** c[1] * (a["teeth_driving"] / REFERENCE_TEETH) ** c[2])


def main(write: bool) -> None:
    a = load()
    cal = a["index"] < CALIBRATION_DRIVES
    sub = {k: v[cal] for k, v in a.items()}
    fit = least_squares(lambda c: model(c, sub) / sub["sim_peak"] - 1, [0.45, 0.9, -0.5])
    err = model(fit.x, a) / a["sim_peak"] - 1
    worst, rms = float(np.abs(err[cal]).max()), float(np.sqrt(np.mean(err[cal] ** 2)))
    hold = float(np.abs(err[~cal]).max()) if (~cal).any() else float("nan")
    print(f"a = {fit.x[0]:.4f}, b = {fit.x[1]:.4f}, c = {fit.x[2]:.4f}; calibration ({cal.sum()} drives) "
          f"worst {100 * worst:.1f} %, rms {100 * rms:.1f} %; hold-out ({(~cal).sum()} drives) worst {100 * hold:.1f} %")
    if write:
        data = {
            "coefficient": round(float(fit.x[0]), 5), "impact_exponent": round(float(fit.x[1]), 5),
            "teeth_exponent": round(float(fit.x[2]), 5), "reference_teeth": REFERENCE_TEETH, "ranges": RANGES,
            "calibration_worst": round(worst, 4), "calibration_rms": round(rms, 4), "holdout_worst": round(hold, 4),
            "provenance": (
                f"Least squares of the relative error of F_peak against the median per-tooth-period peak of the "
                f"simulated tight-span tension (chaindrive.simulation, seats at seat_contact_stiffness(F_t, b1), "
                f"EA of all strands, 2.5 s settling, 40-80 tooth periods) of {int(cal.sum())} two-sprocket drives "
                f"S00-S{CALIBRATION_DRIVES - 1:02d} of benchmarks/_dynamic_sweep.py (scrambled Halton design, "
                f"seed 29, over the ranges below); hold-out drives S{CALIBRATION_DRIVES}-S{int(a['index'].max()):02d}; "
                f"scripts/calibrate_running_tension.py, cache benchmarks/data/dynamic_sweep.csv."),
        }
        OUT.parent.mkdir(parents=True, exist_ok=True)
        OUT.write_text(json.dumps(data, indent=2) + "\n")
        print(f"wrote {OUT.relative_to(ROOT)}")


if __name__ == "__main__":
    main("--write" in sys.argv[1:])
