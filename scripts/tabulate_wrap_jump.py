"""Tabulate the compliant wrap's jump-over onset for the analysis (issue 32, item 3).

:func:`chaindrive.life.wrap_jump_ratio` (the compliant load distribution of the wrap,
checked against the simulation within 10 %: ``benchmarks/life.py``) costs seconds per call;
the analysis needs a jump-over margin in about a millisecond. This script evaluates it on a
grid of its dimensionless inputs and stores, for each, the correction factor to the rigid,
uniformly seated model

.. math:: c = \\frac{ρ_{jump}}{β(e)^{-n}}

(``ρ_jump`` the onset's load ratio ``M/(R_e T_2)``, ``β`` of
:func:`chaindrive.life.tension_ratio`, ``n`` the rollers of the half wrap,
``teeth_in_mesh(π, z)``; ``β^-n`` is computed exactly where the table is used), over:

- ``teeth`` ``z``;
- ``s = e / e_hold``: the elongation over the tooth form's holding limit
  (:func:`chaindrive.life.holding_limit`);
- ``λ = F / EA``: the span tensions' sum over the chain's axial stiffness (one strand;
  the contact stiffness scaled with the size like ``EA``: ``k_c p = 2 EA`` as the
  simulation's 16B, 2e8 N/m and 1e8 N);
- the loading: ``torque`` (the torque and ``T_1 + T_2`` held: a loaded wheel on a slide) or
  ``tensions`` (the span tensions held: a back tension set by a tensioner on the slack span
  or by the slack span's sag).

The main table is on ``z × s`` at ``λ0 = 3e-5`` (torque: the 3 kN of the simulated cases on 16B)
or ``3e-4`` (tensions: there the load at the onset, ``T_2 (1 + ρ)``, is large); a coarse side table
gives the factor ``c(λ) / c(λ0)`` at ``λ = 6e-6`` and ``1.5e-4`` (torque) or ``6e-5`` and ``7e-4``
(tensions). All on
16B (``d_1/p = 0.625``). Output: ``src/chaindrive/life/data/wrap_jump.json`` with the
commit of the model that made it.

Run: ``PYTHONPATH=src python scripts/tabulate_wrap_jump.py [--workers 2] [--write]``.
"""

from __future__ import annotations

import json
import math
import subprocess
import sys
import time
from multiprocessing import Pool
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
OUT = ROOT / "src" / "chaindrive" / "life" / "data" / "wrap_jump.json"
PITCH, ROLLER = 0.0254, 0.01588  # 16B
EA, KC = 1.0e8, 2.0e8  # the simulation's 16B link and contact stiffness
TEETH = (9, 11, 13, 17, 25, 31, 40, 57)  # 11 and 31 added where the coarser table's interpolation erred most
#: e/e_hold up to the holding limit: the wheel's tip diameter is ISO 606's largest, d_a max, the tooth form of
#: chaindrive.life.holding_limit (with the middle of ISO 606's range, the simulation's, the rollers pass the corner
#: at 0.74 (9 teeth) to 0.83 (57) of it; where both hold, the torque-held onsets are the same: docs/life.md)
FRACTIONS = (0.0, 0.15, 0.3, 0.45, 0.6, 0.7, 0.8, 0.9, 0.999)
#: the main table's F/EA per loading: with the torque held, the 3 kN of the simulated cases on 16B; with
#: the back tension held, the load at the onset is T2 (1 + rho) with rho in the hundreds: 30 kN on 16B
LAMBDA0 = {"torque": 3.0e-5, "tensions": 3.0e-4}
SIDE_TEETH = (9, 25, 57)
SIDE_FRACTIONS = (0.15, 0.6, 0.9)
#: the side table's F/EA per loading: the torque loading's F is the running T1 + T2 (a few per cent of
#: the breaking force and less); the held back tension's is T2 (1 + rho) at the onset, up to the
#: breaking force (F_B / EA: 16B 6e-4, 08B 7.2e-4), beyond which the chain breaks before it jumps
SIDE_LAMBDAS = {"torque": (6.0e-6, 1.5e-4), "tensions": (6.0e-5, 7.0e-4)}
LOADINGS = ("torque", "tensions")
#: the bracket's centre: with the torque held, c of the simulated cases (docs/life.md); with the back tension held,
#: below the c of about 1-2 that brackets about the guess found, because whether the wrap holds is not monotonic in the
#: ratio there: a bracket about 1.6 found onsets 1.5-4 times those of fresh calls from below (docs/life.md)
GUESS = {"torque": 0.1, "tensions": 0.5}
RTOL = 0.015
#: wheel positions per tooth pitch (``wrap_jump_ratio(phases=)``): with the torque held the slack span's tension
#: dips over a small part of the pitch, which 10 positions missed (17 teeth at 10 %: 56.8 against 52.2 at 40 and 80;
#: docs/life.md); the back-tension-held table is still the one of 10 positions (its loading has no such dip)
PHASES = {"torque": 40, "tensions": 10}


def rigid(z: int, e: float) -> float:
    from chaindrive.layout import teeth_in_mesh
    from chaindrive.life import tension_ratio

    n = int(teeth_in_mesh(math.pi, z))
    return float(tension_ratio(PITCH, z, ROLLER, e)) ** -n


def tip(z: int) -> float:
    """The tip diameter of the tabulated wheel [m]: ISO 606's largest (that of :func:`chaindrive.life.holding_limit`)."""
    from chaindrive.geometry.sprocket import tip_diameter_limits

    return float(tip_diameter_limits(PITCH, z, ROLLER)[1])


def point(args: tuple[str, int, float, float]) -> dict:
    """One table entry: ``wrap_jump_ratio`` bracketed about the guess, widened where it misses."""
    from chaindrive.errors import InputError
    from chaindrive.life import holding_limit, wrap_jump_ratio

    loading, z, s, lam = args
    e = s * holding_limit(PITCH, z, ROLLER)
    ref = rigid(z, e)
    lo, hi = GUESS[loading] * ref / 2.0, GUESS[loading] * ref * 2.0
    cpu = time.process_time()
    calls = 0
    while True:
        calls += 1
        try:
            got = wrap_jump_ratio(PITCH, z, ROLLER, e, lam * EA, axial_stiffness=EA, contact_stiffness=KC,
                                  low=max(lo, 1.01), high=hi, rtol=RTOL, loading=loading, tip_diameter=tip(z),
                                  phases=PHASES[loading])
        except InputError:  # the low end does not hold: widen down
            if lo <= 1.01:
                raise
            lo, hi = max(lo / 6.0, 1.0), lo
            continue
        if got.load_ratio >= hi * (1 - 1e-12) and calls < 6:  # the high end holds: widen up
            lo, hi = hi, hi * 6.0
            continue
        break
    return {"loading": loading, "teeth": z, "fraction": s, "load_stiffness": lam, "phases": PHASES[loading],
            "elongation": e, "tip_diameter": tip(z),
            "load_ratio": got.load_ratio, "tension_ratio": got.tension_ratio, "rigid": ref,
            "correction": got.load_ratio / ref, "cpu": time.process_time() - cpu}


def tasks() -> list[tuple[str, int, float, float]]:
    main = [(ld, z, s, LAMBDA0[ld]) for ld in LOADINGS for z in TEETH for s in FRACTIONS]
    side = [(ld, z, s, lam) for ld in LOADINGS for z in SIDE_TEETH for s in SIDE_FRACTIONS for lam in SIDE_LAMBDAS[ld]]
    # the validated loading first, the side table last
    return main + side


def main() -> None:
    workers = int(sys.argv[sys.argv.index("--workers") + 1]) if "--workers" in sys.argv else 2
    partial = ROOT / "benchmarks" / "data" / "wrap_jump_points.jsonl"
    done = {}
    if partial.exists():
        for line in partial.read_text().splitlines():
            r = json.loads(line)
            if r.get("phases", 10) == PHASES[r["loading"]]:  # the points of the former wheel positions: kept, not used
                done[(r["loading"], r["teeth"], r["fraction"], r["load_stiffness"])] = r
    todo = [t for t in tasks() if t not in done]
    print(f"{len(done)} points cached, {len(todo)} to go", flush=True)
    with Pool(workers) as pool, partial.open("a") as f:
        for r in pool.imap_unordered(point, todo):
            done[(r["loading"], r["teeth"], r["fraction"], r["load_stiffness"])] = r
            f.write(json.dumps(r) + "\n")
            f.flush()
            print(f"{r['loading']:8s} z={r['teeth']:3d} s={r['fraction']:.2f} lam={r['load_stiffness']:.1e}: "
                  f"rho {r['load_ratio']:8.1f} rigid {r['rigid']:8.1f} c {r['correction']:.3f} ({r['cpu']:.0f} s)",
                  flush=True)
    if "--write" not in sys.argv:
        return
    # the last commit of the model (src/chaindrive/life/wrap_statics.py) the points were computed with
    commit = subprocess.run(["git", "-C", str(ROOT), "log", "-1", "--format=%H", "--",
                             "src/chaindrive/life/wrap_statics.py"], capture_output=True, text=True,
                            check=True).stdout.strip()
    table = {}
    for ld in LOADINGS:
        table[ld] = {
            "load_stiffness": LAMBDA0[ld],
            "correction": [[done[(ld, z, s, LAMBDA0[ld])]["correction"] for s in FRACTIONS] for z in TEETH],
            "load_factor": [[[done[(ld, z, s, lam)]["correction"] / done[(ld, z, s, LAMBDA0[ld])]["correction"]
                              for lam in SIDE_LAMBDAS[ld]] for s in SIDE_FRACTIONS] for z in SIDE_TEETH],
            "side_load_stiffness": list(SIDE_LAMBDAS[ld]),
            "phases": PHASES[ld],
        }
    out = {"teeth": list(TEETH), "fraction": list(FRACTIONS),
           "side_teeth": list(SIDE_TEETH), "side_fraction": list(SIDE_FRACTIONS), "rtol": RTOL, "pitch": PITCH, "roller_diameter": ROLLER,
           "axial_stiffness": EA, "contact_stiffness": KC, **table,
           "provenance": (f"chaindrive.life.wrap_jump_ratio (phases={PHASES['torque']} with the torque held, "
                          f"{PHASES['tensions']} with the back tension, rtol={RTOL}, the held end of the final "
                          f"bracket) of src/chaindrive/life/wrap_statics.py at commit {commit} (unchanged since), 16B (p 25.4 mm, d1 15.88 mm, EA 1e8 N, k_c 2e8 N/m), "
                          "tip diameter d_a max of ISO 606 (the form of chaindrive.life.holding_limit), 180 deg wrap; correction = load_ratio / tension_ratio(e)**-teeth_in_mesh(pi, z); "
                          "scripts/tabulate_wrap_jump.py, points in benchmarks/data/wrap_jump_points.jsonl")}
    OUT.parent.mkdir(exist_ok=True)
    OUT.write_text(json.dumps(out, indent=1) + "\n")
    print(f"wrote {OUT}")


if __name__ == "__main__":
    main()
