"""The drive over its life: the figures of issue #32.

Prints

* ``efficiency vs measured: CASE X points``: the articulation-friction model
  (:mod:`chaindrive.life.efficiency`) against every published chain-efficiency measurement kept in
  ``tests/data/published/`` (provenance in each file's header), each with its configuration;
  the slack side unloaded where the rig had no derailleur, else at the measured derailleur spring
  tension over two 11T jockey wheels (assumed) with the cage's drag
  (:data:`~chaindrive.life.DERAILLEUR_DRAG`, fitted on Wilson's 50 W points), and a count of the
  points within the 0.5 percentage-point aim;
* ``efficiency vs stated: CASE``: industrial (single-speed) drives, for which no measurement with its drive
  stated was readable: the model's range over the makers' usual design envelope against what the sources
  state without conditions (``industrial_efficiency_statements.csv``; not counted with the measured points);
* ``holding limit vs makers' rule: z = N``: the largest elongation the ISO 606 tooth form
  holds (the roller centre at the tooth corner) next to the makers' replacement limit;
* ``jump-over, analysis vs simulation: CASE X %``: the worn chain in the dynamic
  simulation (``SimulationModel.wheel_pitch``), its slack side slackening as the load
  grows, driven until a tooth is skipped, against the compliant quasi-static wrap
  (:func:`chaindrive.life.wrap_jump_ratio`) under the same torque and span-tension sum: the
  onset's load ratio ``M/(R_e T_2)``, seven cases at 3 kN and three chosen before they were run
  (``JUMP_CASES_NEW``: other loads ``F``), the simulation driven slowly (quasi-static) and at
  2 rad/s (``JUMP_CASES``, ``JUMP_CASES_MORE``; docs/life.md, "Jump-over");
* ``jump-over, reduced model vs simulation: CASE X %``: the analysis' jump-over onset (the
  compliant wrap's table, :func:`chaindrive.life.jump_onset`) against the slowly driven
  simulation's onsets of the table of docs/life.md (``SIMULATED``), with its CPU time per call
  next to a fresh :func:`chaindrive.life.wrap_jump_ratio` of one case (``--table`` prints these
  lines only: no simulation);
* the lives by mechanism of the example drives (``chaindrive life``).

Run: ``PYTHONPATH=src python benchmarks/life.py [--table]``.
"""

from __future__ import annotations

import csv
import math
import sys
import time
import warnings
from pathlib import Path

from chaindrive import chains
from chaindrive.analysis import analyze_drive
from chaindrive.drive.project import load_project
from chaindrive.life import (
    DERAILLEUR_DRAG,
    full_tension_rig_loss,
    holding_limit,
    replacement_limit,
    transmission_efficiency,
    two_wheel_power_loss,
)

ROOT = Path(__file__).resolve().parents[1]

PUBLISHED = ROOT / "tests" / "data" / "published"
PITCH, PIN, JOCKEYS = 0.0127, 0.0036, (11, 11)  # 1/2-inch bicycle chain; jockey wheels 11T (assumed)


def published(name: str) -> list[dict[str, str]]:
    """Rows of a published-data CSV (its ``#`` provenance header skipped)."""
    with (PUBLISHED / name).open(encoding="utf-8") as fh:
        return list(csv.DictReader(line for line in fh if not line.startswith("#")))


def bicycle_efficiency(power: float, cadence: float, front: int, rear: int, slack: float = 0.0) -> float:
    """The model's efficiency of a 1/2-inch bicycle chain (pin 3.6 mm) transmitting ``power``; with
    ``slack`` [N] a derailleur holds the lower span at that tension over two jockey wheels, its cage
    dragging the chain by :data:`~chaindrive.life.DERAILLEUR_DRAG`."""
    speed = cadence * math.pi / 30 * PITCH / (2 * math.sin(math.pi / front))
    loss = two_wheel_power_loss(power, speed, PITCH, PIN, [front, rear], slack_tension=slack,
                                idler_teeth=JOCKEYS if slack else (), drag_force=DERAILLEUR_DRAG if slack else 0.0)
    return float(transmission_efficiency(power, float(loss)))


def full_tension_efficiency(power: float, cadence: float, front: int, rear: int) -> float:
    """Friction Facts' Full Tension Test read by the model: no power transmitted, the whole loop at
    the tension of ``power`` (:func:`~chaindrive.life.full_tension_rig_loss`), the loss stated
    against ``power``."""
    speed = cadence * math.pi / 30 * PITCH / (2 * math.sin(math.pi / front))
    return 1.0 - float(full_tension_rig_loss(speed, PITCH, PIN, [front, rear], power / speed)) / power


#: What each series' source does not state that the model needs (printed with the series).
MISSING = {
    "Friction Facts chains": "chain C: its own friction (factory lube, not characterised) - not predictable",
    "Friction Facts differences": "power, cadence, lower-span tension of these reports not readable (assumed)",
    "Wilson 100-400 W": "chainring, cadence, chain line, derailleur tension not stated (52T, 80 rpm, 11.6 N "
                        "assumed); the 13T's extra loss at 50-100 W is cog-specific (a chain-line offset?)",
    "Spicer et al. cadence": "NOT MATCHABLE: the rig's slack-side tension and the bearings between its torque "
                             "sensors not stated; the series extrapolates to 103.9 % at infinite tension",
    "Spicer sprocket difference": "conditions of the 2-5 points not stated",
}


def efficiency_vs_measured() -> None:
    """One line per published point, ``efficiency vs measured: CASE X points`` (model minus measured), then
    one line per series: its largest deviation and how many of its points are within 0.5 point."""
    spring = {r["bicycle"]: float(r["force_N"]) for r in published("derailleur_spring_tension.csv")}["road"]
    series: dict[str, list[float]] = {}

    def line(name: str, case: str, model: float, measured: float, config: str) -> None:
        gap = 100 * (model - measured)
        series.setdefault(name, []).append(gap)
        print(f"efficiency vs measured: {case} {gap:+.2f} points (model {100 * model:.2f} %, measured "
              f"{100 * measured:.2f} %; {config})")

    for row in published("friction_facts_chain_runtime.csv"):
        if float(row["run_time_h"]) == 8.0:
            fit = row["chain"] == "A"
            line("calibration" if fit else "Friction Facts chains",
                 f"Friction Facts chain {row['chain']} {row['model']}{' (calibration of mu)' if fit else ''}",
                 full_tension_efficiency(250.0, 95.0, 53, 11), 1 - float(row["loss_W"]) / 250.0,
                 "53/11, 95 rpm, Full Tension Test: both spans at the 234 N of 250 W, 8 h run in; read as a drive "
                 f"with its slack side unloaded the model gives {100 * bicycle_efficiency(250.0, 95.0, 53, 11):.2f} %")
    (ring,) = published("friction_facts_ring_size.csv")
    small, large = ([int(z) for z in ring[k].split("-")] for k in ("small_pair", "large_pair"))
    extra = full_tension_efficiency(250.0, 95.0, *large) - full_tension_efficiency(250.0, 95.0, *small)
    line("Friction Facts differences", f"Friction Facts {ring['small_pair']} minus {ring['large_pair']}", extra,
         float(ring["extra_loss_of_small_pair_W"]) / 250.0,
         "loss difference as points of 250 W, Full Tension Test, 250 W and 95 rpm assumed")
    speed = 95 * math.pi / 30 * PITCH / (2 * math.sin(math.pi / 53))
    for row in published("friction_facts_pulley_size.csv"):
        zs, zl = int(row["small_pulley_teeth"]), int(row["large_pulley_teeth"])
        diff = [float(two_wheel_power_loss(250.0, speed, PITCH, PIN, [53, 11], slack_tension=spring,
                                           idler_teeth=[z, z], drag_force=DERAILLEUR_DRAG)) for z in (zs, zl)]
        line("Friction Facts differences", f"Friction Facts pulleys {zs}T minus {zl}T", (diff[0] - diff[1]) / 250.0,
             float(row["extra_loss_of_small_W"]) / 250.0,
             f"loss difference as points of 250 W, T2 = {spring:.1f} N, 53/11, 95 rpm (assumed)")
    cage = next(r for r in published("friction_facts_derailleur_cage.csv") if "Dura-Ace" in r["cage"])
    low, high = float(cage["loss_low_W"]), float(cage["loss_high_W"])
    model = (1 - bicycle_efficiency(250.0, 95.0, 53, 11, spring) - (1 - bicycle_efficiency(250.0, 95.0, 53, 11))) * 250.0
    nearest = min(max(model, low), high)
    line("Friction Facts differences", "Friction Facts stock Dura-Ace derailleur", model / 250.0, nearest / 250.0,
         f"the model's derailleur {model:.2f} W against the measured {low:g}-{high:g} W (the gap to the range, as "
         f"points of 250 W); T2 = {spring:.1f} N, two 11T pulleys, cage drag {DERAILLEUR_DRAG:g} N, 1.07 m/s assumed")
    for row in published("wilson2004_derailleur_efficiency.csv"):
        power, cog, measured = float(row["power_W"]), int(row["cog_teeth"]), float(row["efficiency_percent"]) / 100
        fit = power == 50.0
        line("calibration" if fit else "Wilson 100-400 W", f"Wilson {power:g} W 52/{cog}{' (fit of the cage drag)' if fit else ''}",
             bicycle_efficiency(power, 80.0, 52, cog, spring), measured,
             f"derailleur T2 = {spring:.1f} N, cage drag {DERAILLEUR_DRAG:g} N, 52T and 80 rpm assumed; slack side "
             f"unloaded, no cage: {100 * (bicycle_efficiency(power, 80.0, 52, cog) - measured):+.2f}")
    for row in published("spicer2001_efficiency_cadence.csv"):
        power, cadence = float(row["power_W"]), float(row["cadence_rpm"])
        front, rear = int(row["chainring"]), int(row["sprocket"])
        measured = float(row["measured_efficiency_percent"]) / 100
        line("Spicer et al. cadence", f"Spicer et al. {front}/{rear} {cadence:g} rpm",
             bicycle_efficiency(power, cadence, front, rear), measured,
             f"{power:g} W, slack side unloaded; with a derailleur (T2 = {spring:.1f} N, cage drag): "
             f"{100 * (bicycle_efficiency(power, cadence, front, rear, spring) - measured):+.2f}")
    (sp,) = published("spicer2000_sprocket_effect.csv")
    front, zs, zl = int(sp["chainring"]), int(sp["small_sprocket"]), int(sp["large_sprocket"])
    line("Spicer sprocket difference", f"Spicer {front}-{zs} minus {front}-{zl}",
         bicycle_efficiency(200.0, 80.0, front, zl) - bicycle_efficiency(200.0, 80.0, front, zs),
         float(sp["loss_difference_min_percent"]) / 100,
         f"loss difference, measured {sp['loss_difference_min_percent']}-{sp['loss_difference_max_percent']} "
         "points (against the lower end)")
    for name, gaps in series.items():
        within = sum(abs(g) <= 0.5 for g in gaps)
        what = ("fits: Friction Facts chain A (mu), Wilson at 50 W (cage drag)" if name == "calibration"
                else MISSING.get(name, ""))
        print(f"efficiency vs measured: series {name}: largest {max(gaps, key=abs):+.2f} points, {within} of "
              f"{len(gaps)} within 0.5 point ({what})")
    checks = [g for name, gaps in series.items() if name != "calibration" for g in gaps]
    print(f"efficiency vs measured: {sum(abs(g) <= 0.5 for g in checks)} of {len(checks)} points not used for "
          "fitting within 0.5 point")


#: The makers' usual single-speed design envelope the stated efficiencies are compared over: ISO 606 B-series
#: single-strand chains 08B-24B, a small sprocket of 17-25 teeth, ratios 1-4, the slack side unloaded (the model's
#: efficiency is then independent of load and speed).
INDUSTRIAL_CHAINS, INDUSTRIAL_PINIONS, INDUSTRIAL_RATIOS = ("08B-1", "10B-1", "12B-1", "16B-1", "20B-1", "24B-1"), \
    (17, 19, 21, 23, 25), (1, 2, 3, 4)


def efficiency_vs_stated() -> None:
    """Industrial (single-speed) drives: no measurement with its drive stated was readable, only statements without
    conditions (``industrial_efficiency_statements.csv``); one line each, ``efficiency vs stated: CASE``, against the
    model's range over :data:`INDUSTRIAL_CHAINS` x pinions x ratios. Not counted with the measured points."""
    etas = []
    for name in INDUSTRIAL_CHAINS:
        chain = chains.get(name)
        for z1 in INDUSTRIAL_PINIONS:
            for ratio in INDUSTRIAL_RATIOS:
                loss = float(two_wheel_power_loss(1000.0, 1.0, chain.pitch, chain.pin_diameter, [z1, ratio * z1]))
                etas.append((100.0 - loss / 10.0, f"{name} {z1}/{ratio * z1}"))
    etas.sort()
    median = etas[len(etas) // 2][0]
    print(f"efficiency vs stated: the model over the industrial envelope: {etas[0][0]:.2f} % ({etas[0][1]}) ... "
          f"{etas[-1][0]:.2f} % ({etas[-1][1]}), median {median:.2f} % over {len(etas)} drives (08B-24B, z1 17-25, "
          "ratio 1-4, slack side unloaded, no centrifugal tension)")
    gaps = []
    for row in published("industrial_efficiency_statements.csv"):
        low = float(row["efficiency_low_percent"]) if row["efficiency_low_percent"] else None
        high = float(row["efficiency_high_percent"])
        if row["kind"] == "model":
            stated, gap, verdict = f"{low:g}-{high:g} %", None, "another model's estimate, not compared"
        elif low is None:  # an upper bound: how far the model's highest goes past it
            gap = max(etas[-1][0] - high, 0.0)
            stated, verdict = f"at most {high:g} %", f"the model's highest {etas[-1][0] - high:+.2f} points from it"
        elif low == high:  # one number: how far it lies outside the model's range
            gap = min(max(high, etas[0][0]), etas[-1][0]) - high
            stated = f"{high:g} %"
            verdict = "inside the model's range" if gap == 0 else f"{gap:+.2f} points outside the model's range"
        else:  # "about": the model's median against the stated middle
            gap = median - 0.5 * (low + high)
            stated, verdict = f"{low:g}-{high:g} %", f"the model's median {gap:+.2f} points from its middle"
        if gap is not None:
            gaps.append(gap)
        print(f"efficiency vs stated: {row['source']} {stated} ({row['kind']}; conditions: {row['conditions_stated']}): "
              f"{verdict}")
    print(f"efficiency vs stated: series industrial statements (no conditions, not measurements): largest "
          f"{max(gaps, key=abs):+.2f} points, {sum(abs(g) <= 0.5 for g in gaps)} of {len(gaps)} within 0.5 point")


def _run_worn(teeth, elongation, tight, back_force, duration=0.8, angular_velocity=2.0):
    """The worn chain on two ``teeth`` wheels (16B, no friction, no gravity), the driven wheel on a
    slide pulled by ``back_force`` (a soft spring), the load torque for the tight tension ``tight``.

    Returns ``(skipped, ratio, slack)``: the teeth the chain skipped (the driven wheel's angle
    relative to the driver's, in teeth, from the end of the load ramp to the end of the run: equal
    wheels keep it within a fraction of a tooth unless a tooth is skipped), ``T1/T2`` over the
    second half (the medians of the tensions of the links in the middle of the tight and of the
    slack span, the analysis' ``T_1`` and ``T_2``) and the slack span's tension at its 5th, 50th and
    95th percentile over that half [N]."""
    import numpy as np

    from chaindrive.simulation import simulate
    from chaindrive.simulation.examples import roller_example
    from chaindrive.simulation.model import SimTensioner
    from chaindrive.simulation.run import assemble

    p = 0.0254
    ramp = 0.05
    radius = p * (1 + elongation) / (2 * math.sin(math.pi / teeth))
    slide = SimTensioner.at(1, (1.0, 0.0), 2.0, 1000.0, damping=200.0, preload=back_force)
    m = roller_example(teeth=teeth, links=40, angular_velocity=angular_velocity, load_torque=tight * radius,
                       ramp_time=ramp, gravity=False, pitch=p * (1 + elongation), wheel_pitch=p, friction=0.0,
                       pretension=10.0, tensioner=slide)
    r = simulate(m, duration, samples=400, state=assemble(m, method="relaxation"))
    rel = (r.wheel_angle[:, 1] - r.wheel_angle[:, 0]) * teeth / (2 * np.pi)
    after = rel[r.time >= 2 * ramp]
    half = len(r.time) // 2
    t1 = r.tight_side_tension()[half:]
    t2 = r.slack_side_tension()[half:]
    slack = tuple(float(v) for v in np.percentile(t2, [5, 50, 95]))
    return float(np.max(np.abs(after - after[0]))), float(np.median(t1)) / max(slack[1], 1e-9), slack


#: (teeth, elongation) of the jump-over cases (each well inside the tooth form's holding limit).
JUMP_CASES = ((9, 0.2), (11, 0.2), (11, 0.1), (13, 0.15), (17, 0.1))
#: further cases on larger wheels (smaller elongations: the holding limit falls as 1/z)
JUMP_CASES_MORE = ((21, 0.08), (25, 0.06))
#: (teeth, elongation, F [N]): three cases chosen before they were run (issue 32: spread over the teeth, the
#: elongation, 0.2 to 0.8 of the holding limit, and the load F = T1 + T2; not picked by their result)
JUMP_CASES_NEW = ((15, 0.12, 3000.0), (19, 0.03, 1500.0), (31, 0.07, 6000.0))


def simulated_jump_ratio(teeth: int, elongation: float, back_force: float = 3000.0, steps: int = 8,
                         angular_velocity: float = 2.0):
    """The tension ratio ``T_1/T_2`` at which the simulated worn chain skips a tooth: the driven
    wheel on a slide pulled by ``F`` (``T_2 ≈ F − T_1``: the slack side slackens as the load grows),
    the load set for a ratio ``ρ`` (``T_1 = F ρ / (1 + ρ)``), ``ρ`` bisected geometrically between 2
    (held) and 1.5 times the analysis' ratio; a run skipped when the wheels' relative angle moved by
    half a tooth or more after the load ramp. The run lasts as long as 1.6 rad of the driver.
    Returns (the measured ``T_1/T_2`` of the highest load that skipped no tooth, or ``None``, that
    ``ρ``, and the slack span's tension percentiles (5, 50, 95) [N] of that run)."""
    from chaindrive.layout import teeth_in_mesh
    from chaindrive.life import tension_ratio

    seated = int(teeth_in_mesh(math.pi, teeth))
    lo, hi = 2.0, 1.5 * float(tension_ratio(0.0254, teeth, 0.01588, elongation)) ** -seated
    held, slack = None, None
    for _ in range(steps):
        rho = math.sqrt(lo * hi)
        skipped, ratio, spread = _run_worn(teeth, elongation, back_force * rho / (1 + rho), back_force,
                                           duration=1.6 / angular_velocity, angular_velocity=angular_velocity)
        if skipped >= 0.5:  # half a tooth: the chain is riding over
            hi = rho
        else:
            lo, held, slack = rho, ratio, spread
    return held, lo, slack


def quasi_static_speed(teeth: int) -> float:
    """The driver's speed [rad/s] of the quasi-static simulated onset: slow enough that the slide's
    and the slack span's dynamic forces are small against the slack span's few newtons at the
    onset (docs/life.md, "Jump-over"): 0.5 rad/s up to 17 teeth, 0.125 rad/s above."""
    return 0.5 if teeth <= 17 else 0.125


def jump_over_vs_simulation(teeth: int = 11, elongation: float = 0.2, back_force: float = 3000.0) -> None:
    """Print the compliant quasi-static analysis (:func:`chaindrive.life.wrap_jump_ratio`, the
    simulation's contact and link stiffness, the same torque ``M`` and span-tension sum ``F``)
    against :func:`simulated_jump_ratio` driven slowly (:func:`quasi_static_speed`), as the onset's
    load ratio ``ρ = M/(R_e T_2,nom)`` (``T_2,nom = F − M/R_e``: the back tension the torque needs);
    next to it the simulation at 2 rad/s (dynamic), the span tensions' ratios at the onset and the
    rigid, uniformly seated ``β(e)^-n`` (``n`` the rollers in the 180° wrap)."""
    from chaindrive.layout import teeth_in_mesh
    from chaindrive.life import tension_ratio, wrap_jump_ratio

    seated = int(teeth_in_mesh(math.pi, teeth))
    rigid = float(tension_ratio(0.0254, teeth, 0.01588, elongation)) ** -seated
    speed = quasi_static_speed(teeth)
    sim, rho, slack = simulated_jump_ratio(teeth, elongation, back_force, angular_velocity=speed)
    fast, rho_fast, slack_fast = simulated_jump_ratio(teeth, elongation, back_force)
    head = (f"jump-over, analysis vs simulation: z = {teeth}, e = {100 * elongation:g} %, n = {seated} "
            f"(16B, no friction, F = {back_force / 1e3:g} kN)")
    if sim is None or fast is None:
        print(f"{head}: no load held")
        return
    cpu = time.process_time()
    got = wrap_jump_ratio(0.0254, teeth, 0.01588, elongation, back_force, high=1.5 * rigid, rtol=0.02)
    cpu = time.process_time() - cpu
    print(f"{head}: {100 * (got.load_ratio / rho - 1):+.1f} % (onset load ratio M/(R_e T2): analysis "
          f"{got.load_ratio:.1f}, simulation {rho:.1f} at {speed:g} rad/s, {rho_fast:.1f} at 2 rad/s; span "
          f"tensions T1/T2 at the onset: analysis {got.tension_ratio:.0f} (means), simulation {sim:.0f} and "
          f"{fast:.0f} (medians; slack span 5/50/95 %: {slack[0]:.0f}/{slack[1]:.0f}/{slack[2]:.0f} N and "
          f"{slack_fast[0]:.0f}/{slack_fast[1]:.0f}/{slack_fast[2]:.0f} N); rigid uniformly seated beta^-n "
          f"{rigid:.0f}; analysis {cpu:.1f} s of CPU)")


#: The slowly driven simulation's onset load ratio ``ρ = M/(R_e T_2,nom)`` of the jump-over cases
#: (``jump_over_vs_simulation`` at commit c65a478, docs/life.md "Jump-over": 16B, ``F`` = 3 kN, 0.5 rad/s
#: up to 17 teeth, 0.125 rad/s above; 8 bisection steps, about 2 %), and of :data:`JUMP_CASES_NEW`
#: (``simulated_jump_ratio`` at ``quasi_static_speed``, branch life5): (teeth, elongation, ρ, F [N]).
SIMULATED = ((9, 0.20, 14.9, 3000.0), (11, 0.20, 20.5, 3000.0), (11, 0.10, 24.1, 3000.0), (13, 0.15, 30.3, 3000.0),
             (17, 0.10, 54.5, 3000.0), (21, 0.08, 80.3, 3000.0), (25, 0.06, 121.7, 3000.0),
             (15, 0.12, 41.8, 3000.0), (19, 0.03, 86.9, 1500.0), (31, 0.07, 161.9, 6000.0))


def jump_table_vs_simulation() -> None:
    """Print the analysis' reduced compliant model (:func:`chaindrive.life.jump_onset`, the table of
    ``scripts/tabulate_wrap_jump.py``) against :data:`SIMULATED`, its CPU per call (the memo
    cleared) and, for the 17-tooth case, a fresh :func:`chaindrive.life.wrap_jump_ratio`."""
    from chaindrive.life import jump_onset, wrap_jump_ratio
    from chaindrive.life import jump_table as JT

    for teeth, elongation, simulated, back_force in SIMULATED:
        calls = 20
        cpu = time.process_time()
        for _ in range(calls):
            JT._rows.cache_clear()
            with warnings.catch_warnings():  # outside the table: said on the line
                warnings.simplefilter("ignore")
                got = jump_onset(0.0254, teeth, 0.01588, elongation, load=back_force)
        cpu = (time.process_time() - cpu) / calls
        new = " (new case)" if (teeth, elongation, back_force) in JUMP_CASES_NEW else ""
        print(f"jump-over, reduced model vs simulation: z = {teeth}, e = {100 * elongation:g} %, "
              f"F = {back_force / 1e3:g} kN{new}: "
              f"{100 * (got.load_ratio / simulated - 1):+.1f} % (onset load ratio M/(R_e T2): reduced model "
              f"{got.load_ratio:.1f} = {got.correction:.4f} x beta^-n {got.rigid_ratio:.0f}, e/e_hold "
              f"{got.fraction:.2f}{' (outside the table)' if got.outside else ''}, simulation slowly "
              f"{simulated:.1f}; {1e3 * cpu:.2f} ms of CPU per call)")
    cpu = time.process_time()
    fresh = wrap_jump_ratio(0.0254, 17, 0.01588, 0.1, 3000.0, low=20.0, high=120.0, rtol=0.02)
    cpu = time.process_time() - cpu
    print(f"jump-over, the compliant model itself: z = 17, e = 10 %: {fresh.load_ratio:.1f} in {cpu:.1f} s of CPU")


def main() -> None:
    jump_table_vs_simulation()
    if "--table" in sys.argv:
        return
    efficiency_vs_measured()
    efficiency_vs_stated()
    for z in (12, 19, 25, 40, 57, 80, 120):
        h = holding_limit(0.0254, z, 0.01588)
        print(f"holding limit vs makers' rule: z = {z}: ISO 606 form holds {100 * h:.2f} %, makers replace at "
              f"{100 * float(replacement_limit(z)):.2f} %")
    for teeth, elongation in JUMP_CASES + JUMP_CASES_MORE:
        jump_over_vs_simulation(teeth, elongation)
    for teeth, elongation, back_force in JUMP_CASES_NEW:
        jump_over_vs_simulation(teeth, elongation, back_force)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for name in ("roller_industrial", "multi_wheel", "mining_conveyor", "crawler_conveyor"):
            a = analyze_drive(load_project(ROOT / "examples" / f"{name}.toml"), include=["life"])
            r = a.life
            if r is None:
                continue
            jump = "" if r.jump_over_elongation is None else (
                f", jump-over at {100 * r.jump_over_elongation:.2f} % on '{r.jump_over_wheel}'")
            eff = "" if r.efficiency is None else f", efficiency {100 * r.efficiency:.1f} %"
            print(f"life: {name}: {r.life_hours:,.0f} h governed by {r.governing} "
                  f"(wear {r.replacement_hours:,.0f} h to {100 * r.elongation_limit:g} %{jump}{eff})")


if __name__ == "__main__":
    main()
