"""Benchmark: the tensioner coupling settled by an independent planar model (issue 20, item 5).

The slack span split by a tensioner is built as a planar bead chain
(:func:`chaindrive.vibration.planar.planar_tensioner_frequencies`): point masses in x-y
joined by pretensioned links, the tensioner one of the beads, free along its axis only,
with its mass and spring. Nothing in it says how the tensioner's motion is shared
between the normal and the longitudinal motion of the parts: the link geometry does.
Its frequencies, extrapolated to zero link length (Richardson, 200 and 400 links per
part: the model converges as O(h)), are compared at β = 0°, 20°, 35°, 50° (both parts
at β) with the two coupling models of the frequency equation: ``projected`` (g = cos β,
derived in docs/vibration.md) and ``as_printed`` (the tensioner paper's eq. (7) as
printed, g = 1). Then the paper's claim "a larger β1 raises all natural frequencies" is
tested on random designs.

Run: .venv/bin/python benchmarks/tensioner_coupling.py   (about 10 s on one core)
Prints one line per angle and a last line with the default model and its worst
difference over the first three modes; no assertions (tests/test_vibration_planar.py
asserts the same comparison).
"""

from __future__ import annotations

import math

import numpy as np

from chaindrive.vibration import COUPLING_MODELS, tensioner_frequencies
from chaindrive.vibration.planar import planar_tensioner_frequencies

#: a light tensioner on a roller-chain slack span (the coupling matters most: as printed is −6 % at 50°)
CASE = dict(tension=2000.0, mass_per_length=2.6, length_1=0.8, length_2=1.1, mass=3.0, stiffness=5e4)
ANGLES = (0.0, 20.0, 35.0, 50.0)
MODES = 3
DEFAULT = "projected"


def simulated(beta: float, **case: float) -> np.ndarray:
    """Planar bead model at 200 and 400 links per part, extrapolated (O(h) error)."""
    coarse = planar_tensioner_frequencies(angle_1=beta, angle_2=beta, modes=MODES, elements=200, **case)
    fine = planar_tensioner_frequencies(angle_1=beta, angle_2=beta, modes=MODES, elements=400, **case)
    return 2.0 * fine - coarse


def compare(case: dict[str, float] = CASE) -> list[dict[str, object]]:
    """Per angle: the simulated frequencies and each model's, with relative differences."""
    rows = []
    for deg in ANGLES:
        b = math.radians(deg)
        sim = simulated(b, **case)
        row: dict[str, object] = {"beta": deg, "simulation": sim}
        for model in COUPLING_MODELS.names():
            p = tensioner_frequencies(angle_1=b, angle_2=b, modes=MODES, model=model, **case)
            row[model] = p
            row[f"d_{model}"] = p / sim - 1.0
        rows.append(row)
    return rows


def beta_claim(cases: int = 300, seed: int = 1) -> dict[str, int]:
    """In how many random designs does a larger β1 raise all of the first three frequencies?"""
    rng = np.random.default_rng(seed)
    out = dict.fromkeys(COUPLING_MODELS.names(), 0)
    for _ in range(cases):
        c = dict(tension=rng.uniform(500, 20e3), mass_per_length=rng.uniform(0.5, 10),
                 length_1=rng.uniform(0.3, 3), length_2=rng.uniform(0.3, 3),
                 angle_2=math.radians(rng.uniform(0, 40)), mass=10 ** rng.uniform(-1, 2),
                 stiffness=10 ** rng.uniform(2, 6))
        b1 = math.radians(rng.uniform(0, 40))
        for model in COUPLING_MODELS.names():
            lo = tensioner_frequencies(angle_1=b1, modes=MODES, model=model, **c)
            hi = tensioner_frequencies(angle_1=b1 + math.radians(5), modes=MODES, model=model, **c)
            out[model] += bool(np.all(hi > lo))
    return out


def main() -> None:
    rows = compare()
    for r in rows:
        sim, d = r["simulation"], {m: r[f"d_{m}"] for m in COUPLING_MODELS.names()}
        print(f"beta {r['beta']:g} deg: simulation {sim[0]:.3f} rad/s, projected {r['projected'][0]:.3f} "
              f"({100 * d['projected'][0]:+.2f} %), as_printed {r['as_printed'][0]:.3f} ({100 * d['as_printed'][0]:+.2f} %)"
              f"   [modes 2-3: projected {', '.join(f'{100 * v:+.2f} %' for v in d['projected'][1:])}; "
              f"as_printed {', '.join(f'{100 * v:+.2f} %' for v in d['as_printed'][1:])}]")
    claim = beta_claim()
    print("paper's claim 'a larger beta1 raises all frequencies' (beta1 + 5 deg, 300 random designs): "
          + ", ".join(f"{m} {n}/300" for m, n in claim.items()))
    worst = max(float(np.max(np.abs(r[f"d_{DEFAULT}"]))) for r in rows)
    print(f"default model: {DEFAULT}, worst difference to the simulation {100 * worst:.3f} %")


if __name__ == "__main__":
    main()
