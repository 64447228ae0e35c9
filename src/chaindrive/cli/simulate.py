"""``chaindrive simulate``: planar dynamic simulation of a chain drive.

Writes ``simulation.npz`` (all arrays), ``simulation.json`` (summary), ``simulation.png``
(standard views), ``frame.png`` (the drive at the last instant) and ``simulation.gif``
(animation) into the output directory.
"""

from __future__ import annotations

import json
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
    frames: int = typer.Option(60, "--frames", help=f"Frames of the GIF animation, 0...{MAX_FRAMES} (dimensionless count; 0: none)."),
    no_plots: bool = typer.Option(False, "--no-plots", help="Skip PNGs and GIF."),
    as_json: bool = typer.Option(False, "--json", help="Print the summary as JSON (SI units)."),
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
    with claim_output_dir(output, force=force):
        _simulate(project, example, duration, output, speed, load, ramp, frames, no_plots, as_json, force)


def _simulate(project: Path | None, example: str | None, duration: str | None, output: Path,
              speed: str | None, load: str | None, ramp: str | None, frames: int, no_plots: bool,
              as_json: bool, force: bool) -> None:
    from .._io import atomic_output_dir

    typer.echo("assembling the model...", err=True)
    from ..simulation import (
        conveyor_example,
        link_example,
        model_from_drive,
        roller_example,
        simulate,
    )

    long = example == "conveyor"
    dur = check_duration("--duration", quantity(duration or ("3 s" if long else "0.5 s"), "s",
                                                "duration"))
    ramp_time = quantity(ramp or ("2 s" if long else "0.1 s"), "s", "ramp")
    check_size("--frames", frames, MAX_FRAMES, minimum=0)
    if (project is None) == (example is None):
        raise InputError("give a project file or --example roller|link|conveyor (exactly one)")
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

        model = model_from_drive(load_project(project), ramp_time=ramp_time)
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
    with atomic_output_dir(final_output, force=force) as output:  # moved into place when complete
        _write_outputs(res, output, no_plots, frames)
    output = final_output
    _report(res, output, as_json)


def _write_outputs(res, output: Path, no_plots: bool, frames: int) -> None:
    """Write the npz, JSON, PNGs and GIF of a run into ``output``."""
    res.save_npz(output / "simulation.npz")
    (output / "simulation.json").write_text(json.dumps(res.summary, indent=2) + "\n")
    if not no_plots:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        from ..plotting.simulation import drive_frame_plot, simulation_animation, simulation_plot

        fig = simulation_plot(res)
        fig.savefig(output / "simulation.png", dpi=100)
        plt.close(fig)
        fig = drive_frame_plot(res)
        fig.savefig(output / "frame.png", dpi=100)
        plt.close(fig)
        if frames > 0:
            simulation_animation(res, output / "simulation.gif", frames=frames)


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
