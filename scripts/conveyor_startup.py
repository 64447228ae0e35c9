"""The loaded start-up of the 100 m conveyor (examples/long_conveyor.toml) for docs/conveyor.md.

Writes docs/img/conveyor_startup.png and docs/img/conveyor_pull.png and prints the numbers
the document quotes. Usage: ``python scripts/conveyor_startup.py [--inertia-factor F]``.
"""

from __future__ import annotations

import argparse
import math
import pathlib

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[1]

#: The motor of the worked example: rated power = the installed 40 kW, a high-slip
#: mining motor (rated slip 5 %, breakdown torque 2.8 x rated), 1500 rpm synchronous,
#: rotor and coupling 0.6 kg m^2 (illustrative values of a 40 kW 4-pole motor).
RATED_SLIP, BREAKDOWN_RATIO, MOTOR_SYNC_RPM, ROTOR_INERTIA = 0.05, 2.8, 1500.0, 0.6


def main() -> None:
    import matplotlib

    matplotlib.use("Agg")
    from chaindrive.analysis.conveyor import conveyor_pull
    from chaindrive.drive.project import load_project
    from chaindrive.motor import Motor
    from chaindrive.plotting.conveyor import conveyor_plot, startup_plot
    from chaindrive.simulation.conveyor import start_up
    from chaindrive.simulation.profiles import link_chain_axial_stiffness

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--inertia-factor", type=float, default=1.0)
    ap.add_argument("--duration", type=float, default=5.0)
    ap.add_argument("--no-figures", action="store_true")
    args = ap.parse_args()
    drive = load_project(ROOT / "examples" / "long_conveyor.toml")
    pull = conveyor_pull(drive)
    motor = Motor.rated(float(drive.load.power), drive.speed, rated_slip=RATED_SLIP,
                        breakdown_ratio=BREAKDOWN_RATIO)
    ratio = MOTOR_SYNC_RPM * math.pi / 30.0 / motor.synchronous_speed
    inertia = args.inertia_factor * ROTOR_INERTIA * ratio**2
    su, res, model = start_up(drive, args.duration, motor=motor, motor_inertia=inertia)
    radius = float(model.pitch_radii()[0])
    start_torque = float(motor.torque(0.0))
    ea = link_chain_axial_stiffness(float(drive.chain.bar_diameter))
    q = float(drive.chain.mass_per_length)
    c_return = math.sqrt(ea / q)
    c_carry = math.sqrt(ea / (q + pull.material_load))
    loop = float(pull.tension_profile.position[-1])
    carry = 100.0
    transit = carry / c_carry + (loop - carry) / c_return
    tt = su.tight_tension
    t = su.time
    # period of the tension oscillation: mean spacing of the maxima of the first second
    early = t < 1.5
    peaks = [i for i in range(1, int(np.sum(early)) - 1) if tt[i] >= tt[i - 1] and tt[i] > tt[i + 1]
             and tt[i] > np.mean(tt[early])]
    print(f"motor: synchronous {motor.synchronous_speed:.4g} rad/s at the head, T_k {motor.breakdown_torque:.4g} N m, "
          f"s_k {motor.breakdown_slip:.4g}; gear ratio {ratio:.4g}; reduced inertia {inertia:.4g} kg m^2 "
          f"({inertia / radius**2 / 1e3:.4g} t at the pitch radius {radius:.4g} m)")
    print(f"starting torque (Kloss, s = 1) {start_torque:.4g} N m = pull {start_torque / radius:.4g} N")
    print(f"analysis: running slack {pull.slack_tension:.4g} N, tight {pull.tight_tension:.4g} N, "
          f"drive force {pull.drive_force:.4g} N; chain {q * loop:.4g} kg, material {pull.material_load * carry:.4g} kg")
    print(f"standstill tension at the head inlet (t = 0) {tt[0]:.4g} N; leaving {su.slack_tension[0]:.4g} N")
    print(f"peak {su.peak_tension:.4g} N at {su.peak_position:.4g} m along the path, t = {su.peak_time:.4g} s")
    print(f"end of run: speed {su.chain_speed[-1]:.4g} m/s, tight {np.mean(tt[t > t[-1] - 1]):.4g} N")
    print(f"wave speeds: return {c_return:.4g} m/s, carrying (with material) {c_carry:.4g} m/s; "
          f"one transit of the loop {transit:.4g} s, twice {2 * transit:.4g} s")
    if len(peaks) > 1:
        print(f"tension maxima at {[round(float(t[i]), 3) for i in peaks]} s: mean period "
              f"{float(np.mean(np.diff(t[peaks]))):.4g} s")
    if not args.no_figures:
        out = ROOT / "docs" / "img"
        startup_plot(su).savefig(out / "conveyor_startup.png", dpi=100)
        conveyor_plot(pull).savefig(out / "conveyor_pull.png", dpi=100)
        print(f"wrote {out / 'conveyor_startup.png'} and {out / 'conveyor_pull.png'}")


if __name__ == "__main__":
    main()
