"""The drive over its life: the figures of issue #32.

Prints

* ``efficiency vs measured: CASE X points``: the articulation-friction model
  (:mod:`chaindrive.life.efficiency`) against published chain-efficiency measurements
  (provenance in ``tests/test_life.py``; aim within 0.5 percentage point);
* ``holding limit vs makers' rule: z = N``: the largest elongation the ISO 606 tooth form
  holds (the roller centre at the tooth corner) next to the makers' replacement limit;
* ``jump-over, analysis vs simulation: CASE X %``: the worn chain in the dynamic
  simulation (``SimulationModel.wheel_pitch``), its slack side slackening as the load
  grows, driven until a tooth is skipped: the span tensions' ratio ``T1/T2`` at the onset
  against the analysis' jump ratio ``β^-n``, five cases (``JUMP_CASES``; docs/life.md,
  "Jump-over");
* the lives by mechanism of the example drives (``chaindrive life``).

Run: ``PYTHONPATH=src python benchmarks/life.py``.
"""

from __future__ import annotations

import math
import warnings
from pathlib import Path

from chaindrive.analysis import analyze_drive
from chaindrive.drive.project import load_project
from chaindrive.life import (
    articulation_power_loss,
    holding_limit,
    replacement_limit,
    transmission_efficiency,
)

ROOT = Path(__file__).resolve().parents[1]

# (case, power [W], cadence [rpm], chainring, sprocket, measured efficiency); provenance in tests/test_life.py
MEASURED = [("Friction Facts 53/11 chain A (calibration)", 250.0, 95.0, 53, 11, 1 - 6.67 / 250),
            ("Friction Facts 53/11 chain B", 250.0, 95.0, 53, 11, 1 - 6.44 / 250),
            ("Spicer et al. 52/21", 200.0, 80.0, 52, 21, 0.986)]


def bicycle_efficiency(power: float, cadence: float, front: int, rear: int) -> float:
    """The model's efficiency of a 1/2-inch bicycle chain (pin 3.6 mm), slack side unloaded."""
    pitch = 0.0127
    omega = cadence * math.pi / 30
    radius = pitch / (2 * math.sin(math.pi / front))
    tension = power / omega / radius
    loss = articulation_power_loss(omega * radius, pitch, 0.0036, [front, rear], [tension, 0.0], [0.0, tension])
    return float(transmission_efficiency(power, float(loss)))


def _run_worn(teeth, elongation, tight, back_force, duration=0.8):
    """The worn chain on two ``teeth`` wheels (16B, no friction, no gravity), the driven wheel on a
    slide pulled by ``back_force`` (a soft spring), the load torque for the tight tension ``tight``.
    Returns (teeth skipped over the run, T1/T2 over its second half: the medians of the tensions of
    the links in the middle of the tight and of the slack span, the analysis' ``T_1`` and ``T_2``)."""
    import numpy as np

    from chaindrive.simulation import simulate
    from chaindrive.simulation.examples import roller_example
    from chaindrive.simulation.model import SimTensioner
    from chaindrive.simulation.run import assemble

    p = 0.0254
    radius = p * (1 + elongation) / (2 * math.sin(math.pi / teeth))
    slide = SimTensioner.at(1, (1.0, 0.0), 2.0, 1000.0, damping=200.0, preload=back_force)
    m = roller_example(teeth=teeth, links=40, angular_velocity=2.0, load_torque=tight * radius, ramp_time=0.05,
                       gravity=False, pitch=p * (1 + elongation), wheel_pitch=p, friction=0.0, pretension=10.0,
                       tensioner=slide)
    r = simulate(m, duration, samples=400, state=assemble(m, method="relaxation"))
    rel = (r.wheel_angle[:, 1] - r.wheel_angle[:, 0]) * teeth / (2 * np.pi)
    half = len(r.time) // 2
    t1 = float(np.median(r.tight_side_tension()[half:]))
    t2 = float(np.median(r.slack_side_tension()[half:]))
    return float(np.ptp(rel)), t1 / max(t2, 1e-9)


#: (teeth, elongation) of the jump-over cases (each well inside the tooth form's holding limit).
JUMP_CASES = ((9, 0.2), (11, 0.2), (11, 0.1), (13, 0.15), (17, 0.1))


def simulated_jump_ratio(teeth: int, elongation: float, back_force: float = 3000.0, steps: int = 8):
    """The tension ratio ``T_1/T_2`` at which the simulated worn chain skips a tooth: the driven
    wheel on a slide pulled by ``F`` (``T_2 ≈ F − T_1``: the slack side slackens as the load grows),
    the load set for a ratio ``ρ`` (``T_1 = F ρ / (1 + ρ)``), ``ρ`` bisected geometrically between 2
    (held) and 1.5 times the analysis' ratio. Returns (the measured ``T_1/T_2`` of the highest load
    that skipped no tooth, or ``None``, and that ``ρ``)."""
    from chaindrive.layout import teeth_in_mesh
    from chaindrive.life import tension_ratio

    seated = int(teeth_in_mesh(math.pi, teeth))
    lo, hi = 2.0, 1.5 * float(tension_ratio(0.0254, teeth, 0.01588, elongation)) ** -seated
    held = None
    for _ in range(steps):
        rho = math.sqrt(lo * hi)
        skipped, ratio = _run_worn(teeth, elongation, back_force * rho / (1 + rho), back_force)
        if skipped >= 0.5:  # half a tooth: the chain is riding over
            hi = rho
        else:
            lo, held = rho, ratio
    return held, lo


def jump_over_vs_simulation(teeth: int = 11, elongation: float = 0.2) -> None:
    """Print the analysis' jump ratio ``β(e)^-n`` (frictionless, ``n`` the rollers seated in the
    180° wrap, as the layout counts them) against :func:`simulated_jump_ratio`."""
    from chaindrive.layout import teeth_in_mesh
    from chaindrive.life import tension_ratio

    seated = int(teeth_in_mesh(math.pi, teeth))
    analysis = float(tension_ratio(0.0254, teeth, 0.01588, elongation)) ** -seated
    sim, _rho = simulated_jump_ratio(teeth, elongation)
    if sim is None:
        print(f"jump-over, analysis vs simulation: z = {teeth}, e = {100 * elongation:g} %: no load held")
        return
    print(f"jump-over, analysis vs simulation: z = {teeth}, e = {100 * elongation:g} %, n = {seated} (16B, no friction): "
          f"{100 * (analysis / sim - 1):+.1f} % (jump ratio T1/T2: analysis {analysis:.0f}, simulation "
          f"{sim:.0f}, the last load without a skipped tooth)")


def main() -> None:
    for case, power, cadence, front, rear, measured in MEASURED:
        model = bicycle_efficiency(power, cadence, front, rear)
        print(f"efficiency vs measured: {case} {100 * (model - measured):+.2f} points "
              f"(model {100 * model:.2f} %, measured {100 * measured:.2f} %)")
    for z in (12, 19, 25, 40, 57, 80, 120):
        h = holding_limit(0.0254, z, 0.01588)
        print(f"holding limit vs makers' rule: z = {z}: ISO 606 form holds {100 * h:.2f} %, makers replace at "
              f"{100 * float(replacement_limit(z)):.2f} %")
    for teeth, elongation in JUMP_CASES:
        jump_over_vs_simulation(teeth, elongation)
    for teeth, elongation in JUMP_CASES:  # the simulated onset is not a pure ratio: it falls with the load level
        sim, _rho = simulated_jump_ratio(teeth, elongation, back_force=12000.0)
        print(f"jump-over, simulation at a 12 kN slide force: z = {teeth}, e = {100 * elongation:g} %: "
              f"T1/T2 = {sim if sim is None else round(sim)} (3 kN: see above)")
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
