"""``chaindrive new``, ``chaindrive layout`` and ``chaindrive select``: drive projects.

``new`` writes a commented TOML project template; ``layout`` reads a project and
prints chain length, centre distance for whole links, wraps, spans, tensions and
take-up; ``select`` lists roller chains that carry a power (ANSI/ACA rating).
``--json`` prints SI units.
"""

from __future__ import annotations

import math

import typer

from ..errors import ChainDriveError
from ..units import angular_velocity_to_rpm
from .app import OPTION_ALIASES, app, echo_json, quantity, unit_help


def _console():
    from rich.console import Console

    console = Console()
    if not console.is_terminal:
        console = Console(width=160)
    return console


@app.command("new")
def new_command(
    file: str = typer.Argument(..., help="Project file to write (TOML), e.g. drive.toml."),
    kind: str = typer.Option(
        "roller", "--kind", "-k",
        help="Template: roller (ISO 606 16B industrial drive), mining (Dolipiński et al.: 18x64 "
             "chain, 8-pocket wheels, tensioner, tangential guide) or crawler (Sharipov: "
             "tracked-tractor drive wheel).",
    ),
    force: bool = typer.Option(False, "--force", help="Overwrite an existing file."),
) -> None:
    """Write a commented project template (edit it, then run `chaindrive layout FILE`)."""
    from .._io import atomic_write_text, check_output_path
    from ..drive.project import template

    path = check_output_path(file, (".toml",), option="FILE", force=force)
    text = template(kind).replace("{file}", path.name)
    atomic_write_text(path, text, force=force, option="FILE")
    typer.echo(f"wrote {path} ({kind} template)")


@app.command("layout")
def layout_command(
    file: str = typer.Argument(..., help="Project file (TOML), see `chaindrive new`."),
    as_json: bool = typer.Option(False, "--json", help="Print every number as JSON in SI units."),
) -> None:
    """Chain length (polygon model and ISO 10823 approximation), centre distance for a
    whole even number of links, wraps, spans, tensions, sag and tensioner take-up."""
    from rich.markup import escape

    from ..analysis import analyze_drive
    from ..drive.project import load_project
    from ..workflows.display import check_limit_text, check_value_text

    drive = load_project(file)
    analysis = analyze_drive(drive, include=["layout", "loads", "rating"])
    lay, ten = analysis.layout, analysis.loads
    if lay is None or ten is None:  # both asked for above: an analysis always returns them
        raise ChainDriveError("internal: the analysis returned no layout or loads")
    if as_json:
        echo_json({"name": drive.name, "chain": drive.chain.name, "layout": lay, "loads": ten,
                   "slack_sag": analysis.slack_sag, "checks": list(analysis.checks), "passed": analysis.passed,
                   "warnings": list(analysis.warnings)})
        return
    from rich.table import Table

    con = _console()
    con.print(f"[bold]{escape(drive.name)}[/bold]  chain {escape(drive.chain.name)}, pitch "
              f"{drive.pitch * 1e3:.3f} mm, speed {drive.speed:.4g} rad/s = {drive.speed * 30 / math.pi:.4g} rpm, "
              f"v = {ten.chain_speed:.3f} m/s")
    con.print(f"links required {lay.links_required:.3f}, chosen {lay.links}")
    cd = lay.centre_distance_for_links
    if lay.polygon is not None and lay.centre_distance is not None and cd is not None:
        pg = lay.polygon
        approx = "" if pg.links_approx is None else f", ISO 10823 approx. {pg.links_approx:.3f}"
        con.print(f"polygon length at a = {lay.centre_distance * 1e3:.2f} mm: "
                  f"{pg.links_min:.4f}…{pg.links_max:.4f} pitches (circles {pg.links_circles:.4f}{approx})")
        con.print(f"centre distance for {cd.links} links: {cd.taut * 1e3:.3f} mm (taut at tightest phase), "
                  f"{cd.loose * 1e3:.3f} mm (loosest)")
    t = Table(title="Wheels")
    for h in ("wheel", "pitch radius [mm]", "wrap [°]", "teeth in mesh", "shaft load [kN]"):
        t.add_column(escape(h), overflow="fold")  # '[mm]' is not rich markup
    for i, name in enumerate(lay.wheel_names):
        t.add_row(name, f"{lay.pitch_radii[i] * 1e3:.2f}", f"{math.degrees(lay.wrap.wrap_angle[i]):.1f}",
                  "-" if lay.teeth_in_mesh[i] is None else str(lay.teeth_in_mesh[i]),
                  f"{ten.shaft_loads[i] / 1e3:.3f}")
    con.print(t)
    t = Table(title="Spans")
    for h in ("span", "length [mm]", "angle [°]", "tension [kN]", ""):
        t.add_column(escape(h), overflow="fold")
    n = len(lay.wheel_names)
    for i in range(n):
        tag = "tight" if i == lay.tight_span else ("slack" if i == lay.slack_span else "")
        t.add_row(f"{lay.wheel_names[i]} → {lay.wheel_names[(i + 1) % n]}",
                  f"{lay.wrap.span_length[i] * 1e3:.1f}", f"{math.degrees(lay.wrap.span_angle[i]):.1f}",
                  f"{ten.span_tensions[i] / 1e3:.3f}", tag)
    con.print(t)
    con.print(f"effective pull {ten.effective_pull / 1e3:.3f} kN, slack {ten.slack / 1e3:.3f} kN "
              f"({ten.slack_source}), centrifugal {ten.centrifugal / 1e3:.3f} kN, dynamic "
              f"{ten.dynamic / 1e3:.3f} kN, max {ten.maximum / 1e3:.3f} kN"
              + ("" if analysis.slack_sag is None else f"; slack sag {analysis.slack_sag * 1e3:.1f} mm"))
    if lay.take_up is not None:
        con.print(f"{lay.take_up_kind} for 1/2/3 % elongation: "
                  + ", ".join(f"{x * 1e3:.1f} mm" for x in lay.take_up))
    for c in analysis.checks:
        verdict = {"pass": "[green]pass[/green]", "FAIL": "[red]FAIL[/red]"}.get(c.verdict, c.verdict)
        con.print(f"{verdict}  " + escape(f"{c.name}: {check_value_text(c)} (limit {check_limit_text(c)}) "
                                          f"[{c.source}] {c.note}"))
    for w in analysis.warnings:
        con.print(f"warning: {w}", markup=False)


OPTION_ALIASES["select"] = {"teeth_driving": "--teeth", "service_factor": "--service-factor"}


@app.command("select")
def select_command(
    power: str = typer.Option(..., "--power", "-P", help=unit_help(
        "Transmitted power (before the service factor).", "W", "7.5 kW")),
    speed: str = typer.Option(..., "--speed", "-n", help=unit_help(
        "Speed of the small (driving) sprocket.", "rad/s", "1450 rpm")),
    ratio: float = typer.Option(..., "--ratio", "-i", help="Speed ratio n1/n2 >= 1, a bare number "
                                "(driven teeth = round(z1 · ratio))."),
    centre_distance: str | None = typer.Option(None, "--centre-distance", "-a", help=unit_help(
        "Wanted centre distance; default 40 pitches of each chain (ISO 10823: 30-50 pitches). "
        "Gives the link count (ISO 10823 chain length, rounded up to even) and the centre "
        "distance for it.", "m", "650 mm")),
    service_factor: float = typer.Option(1.0, "--service-factor", "-K", help="ANSI/ACA service factor "
                                         "K_s >= 1, a bare number (Shigley Table 17-15)."),
    teeth: int = typer.Option(17, "--teeth", "-z", help="Teeth of the small sprocket, a dimensionless count (ANSI tables: 17)."),
    family: str | None = typer.Option(None, "--family", "-f", help="ansi or iso606 (default both: an "
                                      "ANSI number and its ISO 606 twin are one row with both names)."),
    strands: str = typer.Option("1,2,3", "--strands", help="Strand counts admitted, e.g. '1,2' (1 to 4)."),
    min_static_safety: float = typer.Option(6.0, "--min-static-safety", help="Required breaking force / "
                                            "working tension, dimensionless (Diamond Chain: working load <= 1/6 UTS)."),
    all_sizes: bool = typer.Option(False, "--all-sizes", help="List every adequate chain, not only the "
                                   "smallest adequate pitch per series (ISO B, ISO A = ANSI) and strand count."),
    limit: int = typer.Option(10, "--limit", help="Show at most this many chains (a count)."),
    write: str | None = typer.Option(None, "--write", "-w", help="Write a complete project file (TOML) "
                                     "for the chosen row, e.g. drive.toml; check it with `chaindrive "
                                     "layout drive.toml`."),
    choose: int = typer.Option(1, "--choose", help="Row written by --write (1 = the first)."),
    force: bool = typer.Option(False, "--force", help="Overwrite the --write file if it exists."),
    as_json: bool = typer.Option(False, "--json", help="JSON in SI units (W, m, m/s, N, rad/s)."),
) -> None:
    """Roller chains that carry POWER at SPEED by the ANSI/ACA rating: link-plate and
    roller-bushing limits (Shigley eqs 17-32, 17-33; multi-strand factors 1/1.7/2.5/3.3),
    galling check (Shigley §17-5) and lubrication region (A manual/drip, B bath/disc,
    C oil stream, C' galling region). One row per chain (ANSI number and ISO twin
    together), simplex before multi-strand, smallest adequate pitch first; margin =
    rated / design power; links and centre distance for the wanted centre distance."""
    from ..errors import InputError
    from ..selection import candidate_project, select

    out_file = None
    if write is not None:
        from .._io import check_output_path

        out_file = check_output_path(write, (".toml",), option="--write", force=force)
    P = quantity(power, "W", "power")
    w = quantity(speed, "rad/s", "speed")
    a = quantity(centre_distance, "m", "centre_distance")
    counts = _strand_counts(strands)
    from ..limits import MAX_TEETH, check_size

    check_size("--teeth", teeth, MAX_TEETH, minimum=3)
    if not (math.isfinite(ratio) and 1.0 <= ratio <= MAX_TEETH / max(teeth, 1)):
        # the driven wheel has round(z1 ratio) teeth, at most chaindrive.limits.MAX_TEETH
        raise InputError(f"--ratio must lie in [1, {MAX_TEETH / max(teeth, 1):.6g}] (driven teeth = "
                         f"round({teeth} x ratio) <= {MAX_TEETH}), got {ratio:.6g}")
    if limit < 1:
        raise InputError(f"--limit must be a whole number >= 1, got {limit}")
    found = select(P, w, ratio, service_factor=service_factor, teeth_driving=teeth, family=family,
                   centre_distance=a, strands=counts, min_static_safety=min_static_safety,
                   all_sizes=all_sizes, limit=limit)
    if not 1 <= choose <= len(found):
        raise InputError(f"--choose must lie in [1, {len(found)}] (the rows listed), got {choose}")
    if out_file is not None:
        from .._io import atomic_write_text

        atomic_write_text(out_file, candidate_project(found[choose - 1]), force=force, option="--write")
    if as_json:  # the rows, as a list; the written file is reported on stderr
        echo_json(found)
        if out_file is not None:
            typer.echo(f"wrote {out_file} (row {choose}: {found[choose - 1].chain})", err=True)
        return
    from rich.table import Table

    first = found[0]
    where = ("centre distance 40 pitches (default)" if a is None
             else f"centre distance about {a * 1e3:g} mm")
    t = Table(title=f"Chains for {P / 1e3:g} kW × {service_factor:g} at {angular_velocity_to_rpm(w):g} rpm, "
                    f"{first.teeth_driving}/{first.teeth_driven} teeth, {where}")
    from rich.markup import escape

    for h in ("#", "chain", "pitch [mm]", "strands", "rated [kW]", "margin", "limit", "links",
              "centre distance [mm]", "v [m/s]", "static safety", "lubrication", "notes"):
        # cells wrap (long words fold) rather than end in "…": every word is read in full
        t.add_column(escape(h), no_wrap=h in ("chain", "pitch [mm]", "rated [kW]", "limit"), overflow="fold")
    for k, c in enumerate(found, 1):
        t.add_row(str(k), " / ".join(c.names), f"{c.pitch * 1e3:.3f}", str(c.strands),
                  f"{c.rated_power / 1e3:.2f}", f"{c.power_margin:.2f}", c.governing_limit.replace("_", "-"),
                  str(c.links), f"{c.centre_distance * 1e3:.1f}", f"{c.chain_speed:.2f}",
                  "-" if c.static_safety is None else f"{c.static_safety:.1f}",
                  f"{c.lubrication} ({c.lubrication_method.split(';')[0]})", "; ".join(c.notes))
    con = _console()
    con.print(t)
    if out_file is not None:
        typer.echo(f"wrote {out_file} (row {choose}: {found[choose - 1].chain}); check it with "
                   f"`chaindrive layout {out_file}`")


def _strand_counts(text: str) -> tuple[int, ...]:
    """``"1,2,3"`` -> ``(1, 2, 3)``; each a whole number in 1 ... 4."""
    from ..errors import InputError

    try:
        counts = tuple(int(s) for s in str(text).replace(" ", "").split(",") if s)
    except ValueError:
        counts = ()
    if not counts or any(not 1 <= k <= 4 for k in counts):
        raise InputError(f"--strands must be whole numbers in [1, 4] separated by commas, e.g. '1,2', "
                         f"got {text!r}")
    return counts
