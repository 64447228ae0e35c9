"""``chaindrive simulate``: planar dynamic simulation of a chain drive.

Writes ``simulation.npz`` (all arrays) and ``simulation.json`` (summary) into the output
directory; with ``--plots`` also ``simulation.png`` (standard views) and ``frame.png`` (the
drive at the last instant), with ``--gif`` (or ``--frames N``) ``simulation.gif``
(animation). The pictures are on request: matplotlib costs the 0.5 s example run about
1 s and 30 MB (docs/simulation.md).
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import typer

from .._io import note_earlier_run
from ..errors import InputError
from ..limits import MAX_DURATION, MAX_FRAMES, check_duration, check_size
from .app import app, echo_json, quantity, unit_help, wheel_speed


@app.command("simulate")
@note_earlier_run("output")  # an error says the files already in OUTPUT are from an earlier run
def simulate_command(
    project: Path | None = typer.Argument(None, help="Project file (TOML, same as `analyze`); or use --example."),
    example: str | None = typer.Option(None, "--example", help="Built-in model instead of a project file: 'roller' (16B, two 17-tooth sprockets, 100 links, centre distance 1.054 m), 'link' (18x64 round link chain, DIN 22252, two 8-pocket wheels, 60 links) or 'conveyor' (26x92 round link chain, DIN 22252, two 7-pocket wheels 100 m apart, spring tensioner, 2194 links; examples/long_conveyor.toml)."),
    duration: str | None = typer.Option(None, "--duration", "-t", help=unit_help(f"Simulated time, 0 < t <= {MAX_DURATION:g} s (default 0.5 s; 3 s for --example conveyor).", "s", "2 s")),
    output: Path = typer.Option(Path("simulation_out"), "--output", "-o", help="Output directory."),
    speed: str | None = typer.Option(None, "--speed", help=unit_help("Driver speed for --example (default 20 rad/s roller, 5 rad/s link, 4 rad/s conveyor), or the mean chain speed.", "rpm or rad/s, or m/s for the chain speed", "190 rpm")),
    load: str | None = typer.Option(None, "--load", help=unit_help("Load torque on the driven wheel for --example (default 200 N*m roller, 2000 N*m link, 10 kN*m conveyor); T/R gives the tight-side static tension.", "N*m", "200 N*m")),
    ramp: str | None = typer.Option(None, "--ramp", help=unit_help("Speed ramp of the driver (default 0.1 s; 2 s for --example conveyor: a 100 m chain started faster runs into longitudinal shocks near its breaking force).", "s", "100 ms")),
    gif: bool = typer.Option(False, "--gif", help="Also write the animation simulation.gif (60 frames unless --frames; about 1 s more)."),
    frames: int | None = typer.Option(None, "--frames", help=f"Frames of the GIF animation, 0...{MAX_FRAMES} (dimensionless count; a number above 0 implies --gif; default 60 with --gif, else 0: none)."),
    plots: bool | None = typer.Option(None, "--plots/--no-plots", help="--plots: also draw the PNGs (simulation.png: tensions, speeds and contact forces; frame.png: the drive at the last instant; startup.png of a project run; about 1 s more). --no-plots: no pictures at all, not even a --gif. Default: the GIF only if asked, no PNGs."),
    as_json: bool = typer.Option(False, "--json", help="Print the summary as JSON (SI units)."),
    motor: bool = typer.Option(False, "--motor", help="Project files: drive the driving wheel with an induction motor on the Kloss curve, rated at [load] power at the drive speed (chaindrive.drivetrain.motor.Motor.rated: rated slip and breakdown-torque ratio of a high-slip mining motor), switched on direct at t = 0, instead of the prescribed speed ramp."),
    motor_inertia: str | None = typer.Option(None, "--motor-inertia", help=unit_help("With --motor: rotor and coupling inertia reduced to the driving wheel's shaft (J_motor times the gear ratio squared), added to the wheel's (default 0); with --coupling the inertia of the motor's own degree of freedom (required, > 0).", "kg*m**2", "835 kg*m**2")),
    stop: str | None = typer.Option(None, "--stop", help=unit_help("Project files: from this time the motor is switched off (--motor) or the prescribed speed falls to rest over --stop-ramp (default: no stop).", "s", "3 s")),
    stop_ramp: str | None = typer.Option(None, "--stop-ramp", help=unit_help("Project files: time for the prescribed speed to fall to rest after --stop (default 0: at once).", "s", "1 s")),
    ripple: float = typer.Option(0.0, "--ripple", help="Project files: relative amplitude a of a ripple 1 + a sin(Omega t) of the motor torque (--motor) or of the prescribed speed, -1 < a < 1 (dimensionless; default 0)."),
    ripple_frequency: str | None = typer.Option(None, "--ripple-frequency", help=unit_help("Angular frequency Omega of the --ripple (default 0).", "rad/s or Hz", "50 Hz")),
    coupling: bool = typer.Option(False, "--coupling", help="With --motor: the motor drives through a constant-fill fluid coupling sized on its rated point (nominal torque = [load] power over the drive speed, at the drive speed; chaindrive.drivetrain.coupling); the motor rotor and coupling primary (--motor-inertia, then required) turn at their own speed."),
    coupling_slip: float = typer.Option(0.03, "--coupling-slip", help="With --coupling: its nominal slip s_n, 0.005 <= s_n <= 0.2 (dimensionless; default 0.03)."),
    coupling_stall: float = typer.Option(1.5, "--coupling-stall", help="With --coupling: its stall-torque ratio k = T(s = 1)/T_n, 1.1 <= k <= 6 and k s_n < 1 (dimensionless; default 1.5)."),
    secondary_inertia: str | None = typer.Option(None, "--secondary-inertia", help=unit_help("With --coupling: coupling secondary and gearbox reduced to the driving wheel's shaft, added to the wheel's, >= 0 (default 0).", "kg*m**2", "209 kg*m**2")),
    cad_frame: str | None = typer.Option(None, "--cad-frame", help=unit_help("Project files: also write the drive at this instant of the run as a STEP assembly (cad_frame.step in the output directory; wheels, links, guides, tensioner, as `chaindrive cad`).", "s", "0.4 s")),
    force: bool = typer.Option(False, "--force", help="Replace an earlier run in the output directory (the results are built in a temporary folder and moved into place when complete; a failed run leaves an earlier one unchanged)."),
) -> None:
    """Simulate the drive: point-mass pins, elastic links (EA), penalty contact of rollers
    with ISO 606 tooth gaps or of round-link hinges with pocket seats, the project's
    guides (channels) and idlers (toothed, toothless, outside), tensioner, prescribed
    driver speed, driven inertia and load, gravity; assembled in static equilibrium
    first (see docs/simulation.md)."""
    from .._io import claim_output_dir

    # before any work: the folder locked (a second run into it is refused), an earlier run
    # needs --force, a folder with other files is refused
    with claim_output_dir(output, force=force, inputs=(project,) if project is not None else ()):
        _simulate(project, example, duration, output, speed, load, ramp,
                  (60 if gif else 0) if frames is None else frames, plots, as_json, force,
                  DriveProfile(motor, motor_inertia, stop, stop_ramp, ripple, ripple_frequency, coupling,
                               coupling_slip, coupling_stall, secondary_inertia), cad_frame)


@dataclass(frozen=True)
class DriveProfile:
    """The time-varying drive options as typed (--motor ... --ripple-frequency)."""

    motor: bool = False
    motor_inertia: str | None = None
    stop: str | None = None
    stop_ramp: str | None = None
    ripple: float = 0.0
    ripple_frequency: str | None = None
    coupling: bool = False
    coupling_slip: float = 0.03
    coupling_stall: float = 1.5
    secondary_inertia: str | None = None


def _simulate(project: Path | None, example: str | None, duration: str | None, output: Path,
              speed: str | None, load: str | None, ramp: str | None, frames: int, plots: bool | None,
              as_json: bool, force: bool, profile: DriveProfile | None = None, cad_frame: str | None = None) -> None:
    profile = DriveProfile() if profile is None else profile
    motor, motor_inertia, stop, stop_ramp = profile.motor, profile.motor_inertia, profile.stop, profile.stop_ramp
    ripple, ripple_frequency = profile.ripple, profile.ripple_frequency
    from .._io import atomic_output_dir

    long = example == "conveyor"
    frame_time = quantity(cad_frame, "s", "cad-frame") if cad_frame else None
    if frame_time is not None and project is None:
        raise InputError("--cad-frame needs a project file (the wheels' parts come from the project)")
    # the defaults as numbers: a run without unit options never loads the unit registry
    dur = check_duration("--duration", quantity(duration, "s", "duration") if duration
                         else (3.0 if long else 0.5))
    if frame_time is not None and not 0.0 <= frame_time <= dur:
        raise InputError(f"--cad-frame must lie in [0, {dur:g}] s (the simulated time), got {frame_time:g} s",
                         field="cad-frame")
    ramp_time = quantity(ramp, "s", "ramp") if ramp else (2.0 if long else 0.1)
    check_size("--frames", frames, MAX_FRAMES, minimum=0)
    if (project is None) == (example is None):
        raise InputError("give a project file or --example roller|link|conveyor (exactly one)")
    if example is not None and (motor or stop or stop_ramp or ripple or ripple_frequency or motor_inertia
                                or profile.coupling):
        raise InputError("--motor, --motor-inertia, --coupling, --stop, --stop-ramp, --ripple and "
                         "--ripple-frequency apply to project files, not to --example")
    typer.echo("assembling the model...", err=True)  # the options above read: progress from here
    from ..simulation import (
        conveyor_example,
        link_example,
        model_from_drive,
        roller_example,
        simulate,
    )
    if example is not None:

        def conveyor(angular_velocity: float, load_torque: float, ramp_time: float) -> Any:
            return conveyor_example(angular_velocity=angular_velocity,
                                    power=load_torque * angular_velocity, ramp_time=ramp_time)

        builders: dict[str, tuple[Any, float, float]] = {"roller": (roller_example, 20.0, 200.0), "link": (link_example, 5.0, 2000.0),
                    "conveyor": (conveyor, 4.0, 10e3)}
        if example not in builders:
            raise InputError(f"--example must be one of {', '.join(builders)}, got {example!r}")
        build, w, t = builders[example]
        if speed:  # the examples' driving wheels: 16B on 17 teeth, 18x64 on 8, 26x92 on 7 pockets
            from ..chains import get

            chain, teeth = {"roller": ("16B", 17), "link": ("18x64", 8),
                            "conveyor": ("26x92", 7)}[example]
            w = wheel_speed(speed, pitch=get(chain).pitch, teeth=teeth, link_chain=example != "roller")
        t = quantity(load, "N*m", "load") if load else t
        if long and not (w > 0 and t > 0):
            raise InputError(f"--speed and --load of the conveyor example must be positive (0 < "
                             f"value < inf), got {w:g} rad/s and {t:g} N*m")
        if not w >= 0:
            raise InputError(f"--speed must be non-negative (0 <= speed < inf rad/s; the example "
                             f"runs counter-clockwise, reverse a drive with travel = \"cw\" in a "
                             f"project file), got {w:g} rad/s")
        if not t >= 0:
            raise InputError(f"--load must be non-negative (0 <= load < inf N*m, the torque the "
                             f"driven wheel resists with), got {t:g} N*m")
        model = build(angular_velocity=w, load_torque=t, ramp_time=ramp_time)
    elif project is not None:
        from ..drive.project import load_project
        from ..simulation.conveyor import with_drive_profile

        drive = load_project(project)
        model = model_from_drive(drive, ramp_time=ramp_time)
        motor_spec = None
        if motor:
            from ..drivetrain.motor import Motor

            if drive.load.power is None:
                raise InputError("--motor needs the installed power: give [load] power in the project")
            motor_spec = Motor.rated(float(drive.load.power), float(drive.speed))
        elif motor_inertia is not None:
            raise InputError("--motor-inertia needs --motor")
        coupling_spec = _coupling(profile, drive, motor_spec)
        if profile.secondary_inertia is not None and coupling_spec is None:
            raise InputError("--secondary-inertia needs --coupling")
        model = with_drive_profile(
            model, motor=motor_spec, coupling=coupling_spec,
            secondary_inertia=quantity(profile.secondary_inertia, "kg*m**2", "secondary-inertia")
            if profile.secondary_inertia else 0.0,
            motor_inertia=quantity(motor_inertia, "kg*m**2", "motor-inertia") if motor_inertia else 0.0,
            stop_time=quantity(stop, "s", "stop") if stop else 0.0,
            stop_ramp=quantity(stop_ramp, "s", "stop-ramp") if stop_ramp else 0.0,
            ripple=ripple,
            ripple_frequency=quantity(ripple_frequency, "rad/s", "ripple-frequency") if ripple_frequency else 0.0)
    else:  # refused above: exactly one of a project and --example
        raise InputError("give a project file or --example roller|link|conveyor (exactly one)")

    from rich.progress import (
        BarColumn,
        Progress,
        TextColumn,
        TimeElapsedColumn,
        TimeRemainingColumn,
    )

    typer.echo("compiling the kernel (first run only) and simulating...", err=True)
    with Progress(TextColumn("simulating"), BarColumn(), TextColumn("{task.percentage:>3.0f}%"),
                  TimeElapsedColumn(), TextColumn("ETA"), TimeRemainingColumn(),
                  transient=True) as prog:
        task = prog.add_task("sim", total=1.0)
        # about 2,000 samples, fewer for long chains (the link tensions, contact forces and
        # positions are stored at every sample: about 32 bytes per link and sample)
        samples = int(min(2000, max(200, 2e6 // model.links)))
        res = simulate(model, dur, samples=samples,
                       progress=lambda done, total: prog.update(task, completed=done / total))
    final_output = output
    with atomic_output_dir(final_output, force=force,
                           inputs=(project,) if project is not None else ()) as output:  # moved into place when complete
        _write_outputs(res, output, plots, frames)
        if project is not None:
            _write_start_up(res, model, output, bool(plots))
        if frame_time is not None:
            from ..cad.assembly import frame_assembly
            from .cad import export_assembly

            typer.echo(f"writing the drive at t = {frame_time:g} s as STEP...", err=True)
            export_assembly(frame_assembly(drive, res, model, frame_time), output / "cad_frame.step", None,
                            True, False)
    output = final_output
    _report(res, output, as_json)


def _coupling(profile: DriveProfile, drive: Any, motor: Any) -> Any:
    """The fluid coupling of ``--coupling`` (sized on the motor's rated point), or None."""
    from ..drivetrain.coupling import NOMINAL_SLIP_RANGE, STALL_RATIO_RANGE, FluidCoupling

    if not profile.coupling:
        return None
    if motor is None:
        raise InputError("--coupling needs --motor (the motor in front of the coupling)")
    if profile.motor_inertia is None:
        raise InputError("--coupling needs --motor-inertia (motor rotor and coupling primary reduced to the "
                         "driving wheel, > 0 kg*m**2): behind a coupling the motor turns at its own speed")
    s_n, k = profile.coupling_slip, profile.coupling_stall
    if not NOMINAL_SLIP_RANGE[0] <= s_n <= NOMINAL_SLIP_RANGE[1]:
        raise InputError(f"--coupling-slip must lie in [{NOMINAL_SLIP_RANGE[0]:g}, {NOMINAL_SLIP_RANGE[1]:g}] "
                         f"(dimensionless), got {s_n!r}")
    if not (STALL_RATIO_RANGE[0] <= k <= STALL_RATIO_RANGE[1] and k * s_n < 1):
        raise InputError(f"--coupling-stall must lie in [{STALL_RATIO_RANGE[0]:g}, {STALL_RATIO_RANGE[1]:g}] "
                         f"with --coupling-stall times --coupling-slip below 1, got {k!r}")
    return FluidCoupling.sized(float(drive.load.power) / float(drive.speed), float(drive.speed),
                               nominal_slip=s_n, stall_ratio=k)


def _write_outputs(res, output: Path, plots: bool | None, frames: int) -> None:
    """Write the npz and JSON of a run into ``output``; the PNGs if ``plots``, the GIF if
    ``frames`` and not ``plots is False`` (``--no-plots``: no pictures at all)."""
    res.save_npz(output / "simulation.npz")
    (output / "simulation.json").write_text(json.dumps(res.summary, indent=2) + "\n")
    if plots:
        # bare Agg figures, without pyplot (plotting._axes.subplots): 0.2-0.3 s and 25 MB less
        from ..plotting.simulation import drive_frame_plot, simulation_plot

        simulation_plot(res).savefig(output / "simulation.png", dpi=100)
        drive_frame_plot(res).savefig(output / "frame.png", dpi=100)
    if frames > 0 and plots is not False:
        from ..plotting.simulation import simulation_animation

        simulation_animation(res, output / "simulation.gif", frames=frames)


def _write_start_up(res, model, output: Path, plots: bool) -> None:
    """The start-up's tensions at the head and the peak-tension envelope along the path:
    ``startup.json`` (SI units) and, if ``plots``, ``startup.png``."""
    from ..simulation.conveyor import start_up_of

    su = start_up_of(res, model)
    data = {"peak_tension": su.peak_tension, "peak_position": su.peak_position, "peak_time": su.peak_time,
            "envelope": {"position": su.envelope_position.tolist(), "peak": su.envelope_peak.tolist(),
                         "low": su.envelope_low.tolist()}}
    (output / "startup.json").write_text(json.dumps(data) + "\n")
    if plots:
        import matplotlib.pyplot as plt

        from ..plotting.conveyor import startup_plot

        fig = startup_plot(su)
        fig.savefig(output / "startup.png", dpi=100)
        plt.close(fig)


def _report(res, output: Path, as_json: bool) -> None:
    """Print the summary of a run."""
    if as_json:
        echo_json(res.summary)
    else:
        s = res.summary
        typer.echo(f"simulated {s['duration']:.4g} s in {s['wall_time']:.3g} s wall "
                   f"({s['link_steps_per_second']:.3g} link-steps/s, dt = {s['dt']:.3g} s)")
        speed = s.get("chain_velocity_mean")
        typer.echo(f"tight-side tension mean {s['tight_side_tension_mean']:.1f} N, max "
                   f"{s['tight_side_tension_max']:.1f} N; chain speed mean "
                   + (f"{speed[0]:.4g} m/s" if speed else "-"))
        typer.echo(f"results in {output}/")
