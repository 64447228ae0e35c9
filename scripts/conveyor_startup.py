"""The loaded start-up of the 100 m conveyor (examples/long_conveyor.toml) for docs/conveyor.md.

Writes docs/img/conveyor_startup.png and docs/img/conveyor_pull.png and prints the numbers
the document quotes. Usage: ``python scripts/conveyor_startup.py [--inertia-factor F]``;
``--coupling`` starts through a constant-fill fluid coupling (nominal slip
``--coupling-slip``, stall-torque ratio ``--coupling-stall``) and writes
docs/img/conveyor_startup_coupling.png instead.
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
#: The fluid coupling of the second run: constant fill, sized on the motor's rated point
#: (nominal torque = rated torque at the rated speed), nominal slip 3 %, stall torque
#: 1.5 x nominal (illustrative values of a constant-fill coupling with a delay chamber);
#: of the 0.6 kg m^2, 0.45 turn with the motor (rotor, coupling primary) and 0.15 with
#: the head (coupling secondary, gearbox input).
COUPLING_SLIP, COUPLING_STALL, SECONDARY_INERTIA = 0.03, 1.5, 0.15


def main() -> None:
    import matplotlib

    matplotlib.use("Agg")
    from chaindrive.analysis.conveyor import conveyor_pull
    from chaindrive.drive.project import load_project
    from chaindrive.drivetrain.motor import Motor
    from chaindrive.plotting.conveyor import conveyor_plot, startup_plot
    from chaindrive.simulation.profiles import link_chain_axial_stiffness
    from chaindrive.simulation.startup import start_up

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--inertia-factor", type=float, default=1.0)
    ap.add_argument("--duration", type=float, default=5.0)
    ap.add_argument("--no-figures", action="store_true")
    ap.add_argument("--coupling", action="store_true")
    ap.add_argument("--coupling-slip", type=float, default=COUPLING_SLIP)
    ap.add_argument("--coupling-stall", type=float, default=COUPLING_STALL)
    args = ap.parse_args()
    drive = load_project(ROOT / "examples" / "long_conveyor.toml")
    pull = conveyor_pull(drive)
    motor = Motor.rated(float(drive.load.power), drive.speed, rated_slip=RATED_SLIP,
                        breakdown_ratio=BREAKDOWN_RATIO)
    ratio = MOTOR_SYNC_RPM * math.pi / 30.0 / motor.synchronous_speed
    inertia = args.inertia_factor * ROTOR_INERTIA * ratio**2
    coupling = None
    if args.coupling:
        from chaindrive.drivetrain.coupling import FluidCoupling

        coupling = FluidCoupling.sized(float(drive.load.power) / drive.speed, drive.speed,
                                       nominal_slip=args.coupling_slip, stall_ratio=args.coupling_stall)
        print(f"fluid coupling: nominal {coupling.nominal_torque:.4g} N m at {coupling.nominal_speed:.4g} rad/s, "
              f"slip {coupling.nominal_slip:g}, stall ratio {coupling.stall_ratio:g} "
              f"(stall torque at the nominal primary speed {coupling.stall_ratio * coupling.nominal_torque:.4g} N m)")
    secondary = 0.0
    if coupling is not None:
        secondary = args.inertia_factor * SECONDARY_INERTIA * ratio**2
        inertia -= secondary
        print(f"motor side {inertia:.4g} kg m^2, secondary side {secondary:.4g} kg m^2 (at the head)")
    su, res, model = start_up(drive, args.duration, motor=motor, motor_inertia=inertia, coupling=coupling,
                              secondary_inertia=secondary)
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
    v_end = float(np.mean(su.chain_speed[t > t[-1] - 1]))
    reach = t[np.argmax(su.chain_speed >= 0.9 * v_end)]
    print(f"90 % of the final speed ({v_end:.4g} m/s) at {reach:.4g} s; largest drive torque "
          f"{float(np.max(su.drive_torque)):.4g} N m = pull {float(np.max(su.drive_torque)) / radius:.4g} N "
          f"at {float(t[np.argmax(su.drive_torque)]):.4g} s")
    win = (t >= 0.5) & (t <= 1.5)
    print(f"head speed at 0.1 s {float(np.interp(0.1, res.time, res.wheel_speed[:, 0])):.4g} rad/s; tension arriving at the head between 0.5 and 1.5 s: "
          f"{float(np.min(tt[win])):.4g} to {float(np.max(tt[win])):.4g} N")
    if coupling is not None:
        print(f"motor speed at the head: {su.motor_speed[np.searchsorted(t, 0.1)]:.4g} rad/s at 0.1 s, "
              f"{su.motor_speed[np.searchsorted(t, 0.3)]:.4g} at 0.3 s, {su.motor_speed[-1]:.4g} at the end")
    print(f"wave speeds: return {c_return:.4g} m/s, carrying (with material) {c_carry:.4g} m/s; "
          f"one transit of the loop {transit:.4g} s, twice {2 * transit:.4g} s")
    if len(peaks) > 1:
        print(f"tension maxima at {[round(float(t[i]), 3) for i in peaks]} s: mean period "
              f"{float(np.mean(np.diff(t[peaks]))):.4g} s")
    if not args.no_figures:
        out = ROOT / "docs" / "img"
        if coupling is not None:
            startup_plot(su).savefig(out / "conveyor_startup_coupling.png", dpi=100)
            print(f"wrote {out / 'conveyor_startup_coupling.png'}")
        else:
            startup_plot(su).savefig(out / "conveyor_startup.png", dpi=100)
            conveyor_plot(pull).savefig(out / "conveyor_pull.png", dpi=100)
            print(f"wrote {out / 'conveyor_startup.png'} and {out / 'conveyor_pull.png'}")


if __name__ == "__main__":
    main()
