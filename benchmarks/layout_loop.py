"""Exact chain length of a multi-wheel drive: the max-plus envelope against enumerating phases.

Prints the time of :func:`chaindrive.layout.chain_length_loop` (max-plus / min-plus products
of the span matrices, ``N n³``) and of evaluating every phase combination one by one
(:func:`chaindrive.layout.loop_length_at_phases`, ``n^N`` evaluations; on a small grid),
with their envelopes (equal to rounding), for examples/multi_wheel.toml; and the time of
placing its take-up idler for 144 links (:func:`chaindrive.layout.adjust_loop`). No
assertions (conventions: benchmarks print, tests assert).

Run: ``python benchmarks/layout_loop.py`` (or ``make bench``).
"""

from __future__ import annotations

import itertools
import os
import time
from pathlib import Path

os.environ.setdefault("OMP_NUM_THREADS", "1")

import numpy as np  # noqa: E402

from chaindrive import layout as L  # noqa: E402
from chaindrive.drive import load_project  # noqa: E402


def best_of(fn, repeat: int = 5) -> float:
    fn()
    best = np.inf
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


def main() -> None:
    drive = load_project(Path(__file__).resolve().parents[1] / "examples" / "multi_wheel.toml")
    centres = np.array([w.position for w in drive.wheels])
    teeth = [w.teeth for w in drive.wheels]
    sides = [w.side for w in drive.wheels]
    p = drive.pitch
    for phases in (4, 8, 12):
        t = best_of(lambda phases=phases: L.chain_length_loop(p, centres, teeth, sides, phases=phases))
        r = L.chain_length_loop(p, centres, teeth, sides, phases=phases)
        print(f"chain_length_loop, {len(teeth)} wheels, {phases} phases each: {t * 1e3:8.2f} ms "
              f"(X = {r.links_min:.5f} ... {r.links_max:.5f} pitches)")
    phases = 4
    grids = [np.arange(phases) * (2 * np.pi / z) / phases for z in teeth]

    def enumerate_all():
        return [L.loop_length_at_phases(p, centres, teeth, f, sides) for f in itertools.product(*grids)]

    t = best_of(enumerate_all, repeat=1)
    values = np.array(enumerate_all()) / p
    print(f"every phase combination, {phases}^{len(teeth)} = {phases ** len(teeth)} evaluations: {t * 1e3:8.1f} ms "
          f"(X = {values.min():.5f} ... {values.max():.5f} pitches)")
    idx = drive.wheel_index("take-up idler")
    t = best_of(lambda: L.adjust_loop(p, centres, teeth, 144, idx, (0, 1), sides, phases=8), repeat=3)
    print(f"adjust_loop (take-up idler for 144 links, 8 phases): {t * 1e3:8.1f} ms")


if __name__ == "__main__":
    main()
