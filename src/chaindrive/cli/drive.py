"""``chaindrive new``, ``layout``, ``select`` and ``rating``: drive projects.

``new`` writes a commented TOML project template; ``layout`` reads a project and
prints chain length, centre distance for whole links, wraps, spans, tensions and
take-up; ``select`` designs a drive for a duty (:func:`chaindrive.design.design_drive`);
``rating`` rates one chain.
``--json`` prints SI units.
"""

from __future__ import annotations

import math

import typer

from ..display import check_limit_text, check_margin_text, check_value_text, kn, kw, mm
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
             "chain, 8-pocket wheels, tensioner, tangential guide), conveyor (a 30 m scraper "
             "conveyor with its [conveyor] table: pans, material, drives), track (Sharipov: "
             "tracked-tractor drive wheel, tooth and rim-bolt checks) or crawler-conveyor (the conveyor "
             "crawler drive: drive chain with cams, guide, cam force). 'crawler' is the former name of "
             "'track' (deprecated).",
    ),
    force: bool = typer.Option(False, "--force", help="Overwrite an existing file."),
) -> None:
    """Write a commented project template (edit it, then run `chaindrive layout FILE`)."""
    import warnings

    from .._io import atomic_write_text, check_output_path
    from ..drive.project import template

    path = check_output_path(file, (".toml",), option="FILE", force=force)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", FutureWarning)
        text = template(kind).replace("{file}", path.name)
    for w in caught:
        typer.echo(f"warning: {w.message}", err=True)
    atomic_write_text(path, text, force=force, option="FILE")
    typer.echo(f"wrote {path} ({kind} template)")


@app.command("layout")
def layout_command(
    file: str = typer.Argument(..., help="Project file (TOML), see `chaindrive new`."),
    as_json: bool = typer.Option(False, "--json", help="Print every number as JSON in SI units."),
    place: str | None = typer.Option(None, "--place", help="Name of a wheel to move until it (or the wheel "
                                     "named by --of) has the wrap given by --wrap; prints its new position."),
    wrap: str | None = typer.Option(None, "--wrap", help=unit_help("Wrap requested with --place.", "rad",
                                                                   "150 deg")),
    along: str | None = typer.Option(None, "--along", help="Line of travel of the --place wheel as 'dx,dy' "
                                     "(bare numbers, a direction); default away from the other wheels."),
    of: str | None = typer.Option(None, "--of", help="Wheel whose wrap --wrap sets (default the --place wheel)."),
) -> None:
    """Chain length (polygon model and ISO 10823 approximation), centre distance for a
    whole even number of links, wraps, spans, tensions, sag and tensioner take-up; with
    ``--place WHEEL --wrap ANGLE`` the position of a wheel for a requested wrap."""
    from rich.markup import escape

    from ..analysis import analyze_drive
    from ..drive.project import load_project

    drive = load_project(file)
    if place is not None or wrap is not None:
        _place(drive, place, wrap, along, of, as_json)
        return
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
              f"{mm(drive.pitch):.3f} mm, speed {drive.speed:.4g} rad/s = {angular_velocity_to_rpm(drive.speed):.4g} rpm, "
              f"v = {ten.chain_speed:.3f} m/s")
    con.print(f"links required {lay.links_required:.3f}, chosen {lay.links}")
    cd = lay.centre_distance_for_links
    if lay.polygon is not None and lay.centre_distance is not None and cd is not None:
        pg = lay.polygon
        approx = "" if pg.links_approx is None else f", ISO 10823 approx. {pg.links_approx:.3f}"
        con.print(f"polygon length at a = {mm(lay.centre_distance):.2f} mm: "
                  f"{pg.links_min:.4f}…{pg.links_max:.4f} pitches (circles {pg.links_circles:.4f}{approx})")
        con.print(f"centre distance for {cd.links} links: {mm(cd.taut):.3f} mm (taut at tightest phase), "
                  f"{mm(cd.loose):.3f} mm (loosest)")
    t = Table(title="Wheels")
    for h in ("wheel", "pitch radius [mm]", "wrap [°]", "teeth in mesh", "shaft load [kN]"):
        t.add_column(escape(h), overflow="fold")  # '[mm]' is not rich markup
    for i, name in enumerate(lay.wheel_names):
        t.add_row(name, f"{mm(lay.pitch_radii[i]):.2f}", f"{math.degrees(lay.wrap.wrap_angle[i]):.1f}",
                  "-" if lay.teeth_in_mesh[i] is None else str(lay.teeth_in_mesh[i]),
                  f"{kn(ten.shaft_loads[i]):.3f}")
    con.print(t)
    t = Table(title="Spans")
    for h in ("span", "length [mm]", "angle [°]", "tension [kN]", ""):
        t.add_column(escape(h), overflow="fold")
    n = len(lay.wheel_names)
    for i in range(n):
        tag = "tight" if i == lay.tight_span else ("slack" if i == lay.slack_span else "")
        t.add_row(f"{lay.wheel_names[i]} → {lay.wheel_names[(i + 1) % n]}",
                  f"{mm(lay.wrap.span_length[i]):.1f}", f"{math.degrees(lay.wrap.span_angle[i]):.1f}",
                  f"{kn(ten.span_tensions[i]):.3f}", tag)
    con.print(t)
    con.print(f"effective pull {kn(ten.effective_pull):.3f} kN, slack {kn(ten.slack):.3f} kN "
              f"({ten.slack_source}), centrifugal {kn(ten.centrifugal):.3f} kN, dynamic "
              f"{kn(ten.dynamic):.3f} kN, peak {kn(ten.maximum):.3f} kN"
              + ("" if analysis.slack_sag is None else f"; slack sag {mm(analysis.slack_sag):.1f} mm"))
    if lay.take_up is not None:
        con.print(f"{lay.take_up_kind} for 1/2/3 % elongation: "
                  + ", ".join(f"{mm(x):.1f} mm" for x in lay.take_up))
    for c in analysis.checks:
        verdict = {"pass": "[green]pass[/green]", "FAIL": "[red]FAIL[/red]"}.get(c.verdict, c.verdict)
        margin = check_margin_text(c)
        con.print(f"{verdict}  " + escape(f"{c.name}: {check_value_text(c)} (limit {check_limit_text(c)}"
                                          + (f", margin {margin}" if margin else "") + f") [{c.source}] {c.note}"))
    for w in analysis.warnings:
        con.print(f"warning: {w}", markup=False)


def _place(drive, place: str | None, wrap: str | None, along: str | None, of: str | None, as_json: bool) -> None:
    """``layout --place``: a wheel's position for a requested wrap, re-checked."""
    from ..analysis.placement import place_wheel
    from ..errors import InputError

    if place is None or wrap is None:
        raise InputError("--place and --wrap go together, e.g. --place 'machine B' --wrap '130 deg'",
                         field="place" if place is None else "wrap")
    direction = None
    if along is not None:
        try:
            parts = [float(x) for x in along.split(",")]
        except ValueError:
            parts = []
        if len(parts) != 2 or not math.hypot(*parts) > 0 or not all(map(math.isfinite, parts)):
            raise InputError(f"--along must be two numbers 'dx,dy' (a direction, not both 0), got {along!r}",
                             field="along")
        direction = (parts[0], parts[1])
    p = place_wheel(drive, place, quantity(wrap, "rad", "wrap"), along=direction, target=of)
    if as_json:
        echo_json({"placement": p})
        return
    con = _console()
    con.print(f"move {p.wheel!r} {mm(p.distance):.1f} mm along ({p.direction[0]:.4f}, {p.direction[1]:.4f}):",
              markup=False)
    con.print(f'position = ["{mm(p.position[0]):.1f} mm", "{mm(p.position[1]):.1f} mm"]', markup=False)
    con.print(f"wrap on {p.target!r} there {math.degrees(p.wrap):.2f}° (requested {math.degrees(p.requested):.2f}°), "
              f"wheels and spans clear; with the links fitted again {math.degrees(p.refitted_wrap):.2f}°",
              markup=False)


OPTION_ALIASES["select"] = {"teeth_driving": "--teeth", "service_factor": "--service-factor",
                            "centre_distance_range": "--min-centre-distance/--max-centre-distance",
                            "load_character": "--load-character", "hours_per_day": "--hours-per-day"}


@app.command("select")
def select_command(
    power: str = typer.Option(..., "--power", "-P", help=unit_help(
        "Transmitted power (before the service factor).", "W", "11 kW")),
    speed: str = typer.Option(..., "--speed", "-n", help=unit_help(
        "Speed of the driving (small) sprocket.", "rad/s", "1460 rpm")),
    ratio: float | None = typer.Option(None, "--ratio", "-i", help="Speed ratio n1/n2 >= 1, a bare number "
                                       "(or give --driven-speed)."),
    driven_speed: str | None = typer.Option(None, "--driven-speed", help=unit_help(
        "Speed of the driven shaft (instead of --ratio).", "rad/s", "480 rpm")),
    driver: str = typer.Option("electric_motor", "--driver", help="Driving machine: electric_motor, "
                               "ic_hydraulic or ic_mechanical (service-factor table)."),
    driven_machine: str | None = typer.Option(None, "--driven-machine", help="Driven machine of the "
                                              "service-factor table, e.g. varying_conveyor (moderate shock)."),
    load_character: str | None = typer.Option(None, "--load-character", help="Load character instead of a "
                                              "driven machine: smooth, moderate or heavy."),
    load_old: str | None = typer.Option(None, "--load", hidden=True, help="Deprecated: --load-character."),
    service_factor: float | None = typer.Option(None, "--service-factor", "-K", help="Explicit service "
                                                "factor K_s >= 1, a bare number (instead of the duty class)."),
    hours: float = typer.Option(8.0, "--hours-per-day", help="Operating hours per day, a number in (0, 24]."),
    environment: str = typer.Option("clean", "--environment", help="clean, dusty or abrasive."),
    lubrication: str | None = typer.Option(None, "--lubrication", help="Best lubrication the site provides: "
                                           "A (manual/drip), B (bath/disc) or C (oil stream)."),
    centre_distance: str | None = typer.Option(None, "--centre-distance", "-a", help=unit_help(
        "Wanted centre distance; default 40 pitches of each chain (ISO 10823: 30-50 pitches). "
        "The link count is the chain length rounded up to even; the centre distance printed is "
        "the exact one for that count.", "m", "600 mm")),
    min_centre: str | None = typer.Option(None, "--min-centre-distance", help=unit_help(
        "Without --centre-distance: the shortest centre distance a chain is laid out at (its 40 pitches "
        "moved into the bounds).", "m", "400 mm")),
    max_centre: str | None = typer.Option(None, "--max-centre-distance", help=unit_help(
        "Without --centre-distance: the longest centre distance a chain is laid out at.", "m", "800 mm")),
    teeth: int | None = typer.Option(None, "--teeth", "-z", help="Teeth of the small sprocket, a count "
                                     "(default: the tooth-count policy, 19 or more, odd; docs/design.md)."),
    family: str | None = typer.Option(None, "--family", "-f", help="ansi or iso606 (default both: an "
                                      "ANSI number and its ISO 606 twin are one row with both names)."),
    strands: str = typer.Option("1,2,3", "--strands", help="Strand counts admitted, e.g. '1,2' (1 to 4)."),
    method: str | None = typer.Option(None, "--method", help="Rating method for every chain (default: the "
                                      "method of each chain's family), e.g. ansi."),
    required_static_safety: float | None = typer.Option(
        None, "--required-static-safety", help="Required static safety F_B / (K_s F_t + S + q v²), dimensionless "
        "(default: Chernavsky et al. Table 7.19 by pitch and small-sprocket speed, docs/design.md)."),
    all_sizes: bool = typer.Option(False, "--all-sizes", help="List every adequate chain, not only the "
                                   "smallest adequate pitch per series (ISO B, ISO A = ANSI) and strand count."),
    limit: int = typer.Option(10, "--limit", help="Show at most this many chains (a count)."),
    write: str | None = typer.Option(None, "--write", "-w", help="Write a complete project file (TOML) "
                                     "for the chosen row, e.g. drive.toml; check it with `chaindrive "
                                     "analyze drive.toml`."),
    choose: int = typer.Option(1, "--choose", help="Row written by --write (1 = the recommended one)."),
    force: bool = typer.Option(False, "--force", help="Overwrite the --write file if it exists."),
    as_json: bool = typer.Option(False, "--json", help="JSON in SI units (W, m, m/s, N, rad/s): "
                                 "recommended and candidates."),
) -> None:
    """Design a roller chain drive for a duty: the procedure of docs/design.md (service
    factor from the driver and the driven machine, tooth-count policy, rating by the method
    of each chain's family, even link count and exact centre distance, the analysis's
    static safety, the peak tension of the running chain, advice, near misses). Needs a duty
    class (--driven-machine or --load-character) or an explicit --service-factor; prints every
    factor with its source."""
    from ..design import DesignRequest, design_drive
    from ..errors import InputError

    if load_old is not None:
        if load_character is not None:
            raise InputError("give --load-character only (--load is its deprecated name)", field="--load")
        typer.echo("warning: --load is deprecated; use --load-character", err=True)
        load_character = load_old
    out_file = None
    if write is not None:
        from .._io import check_output_path

        out_file = check_output_path(write, (".toml",), option="--write", force=force)
    request = DesignRequest.of(
        power=quantity(power, "W", "power"), speed=quantity(speed, "rad/s", "speed"), ratio=ratio,
        driven_speed=quantity(driven_speed, "rad/s", "driven_speed"), driver=driver, driven_machine=driven_machine,
        load_character=load_character, service_factor=service_factor, hours_per_day=hours,
        centre_distance=quantity(centre_distance, "m", "centre_distance"), environment=environment,
        lubrication=lubrication, teeth_driving=teeth, family=family, strands=_strand_counts(strands), method=method,
        required_static_safety=required_static_safety, all_sizes=all_sizes, limit=limit,
        centre_distance_range=_centre_range(min_centre, max_centre))
    duty = request.duty
    result = design_drive(request)
    found = result.candidates
    if not 1 <= choose <= len(found):
        raise InputError(f"--choose must lie in [1, {len(found)}] (the rows listed), got {choose}", field="--choose")
    if out_file is not None:
        from .._io import atomic_write_text

        atomic_write_text(out_file, found[choose - 1].project_text, force=force, option="--write")
    if as_json:  # the written file is reported on stderr
        echo_json(result.to_dict())
        if out_file is not None:
            typer.echo(f"wrote {out_file} (row {choose}: {found[choose - 1].chain})", err=True)
        return
    from rich.markup import escape
    from rich.table import Table


    con = _console()
    rec = result.recommended
    con.print(escape(f"Duty: {kw(duty.power):g} kW at {angular_velocity_to_rpm(duty.speed):g} rpm, ratio "
                     f"{duty.speed_ratio:.4g}, {duty.hours_per_day:g} h/day, {duty.environment}"))
    for f in rec.factors:
        con.print(escape(f"  {f.name} {f.symbol} = {f.value:.4g}  [{f.source}]" + (f" ({f.note})" if f.note else "")))
    # two tables, each no wider than needed: a column is at least as wide as its longest
    # cell (no number or word is broken); headers wrap between their words
    rank_rows = [[str(k), " / ".join(c.names), f"{c.driving_teeth}/{c.driven_teeth}", str(c.links),
                  f"{mm(c.centre_distance):.2f}", f"{kw(c.rated_power):.2f}", f"{c.power_margin:.2f}",
                  c.limited_by.replace("_", "-")] for k, c in enumerate(found, 1)]
    more_rows = [[str(k), c.method, f"{c.chain_speed:.2f}", c.lubrication,
                  "-" if c.static_safety is None else f"{c.static_safety:.2f} (>= {c.required_static_safety:.3g})",
                  f"{kn(c.dynamic_tension):.2f}",
                  f"{kn(c.peak_tension):.2f}" + ("" if c.peak_tension_limit is None
                                                   else f" (<= {kn(c.peak_tension_limit):.2f})")]
                 for k, c in enumerate(found, 1)]
    tables = ((f"Candidates (design power {kw(rec.design_power):.4g} kW)",
               ("#", "chain", "teeth", "links", "centre distance [mm]", "rated [kW]", "margin", "limited by"),
               rank_rows),
              ("Candidates: chain speed, lubrication, static safety, dynamic and peak tension",
               ("#", "rating method", "v [m/s]", "lubrication region", "static safety (required)",
                "dynamic tension [kN]", "peak tension [kN] (limit)"), more_rows))
    for title, headers, rows in tables:
        table = Table(title=title)
        for i, h in enumerate(headers):
            words = [len(w) for w in h.split()] + [len(r[i]) for r in rows]
            table.add_column(escape(h), min_width=max(words), overflow="fold")
        for r in rows:
            table.add_row(*r)
        con.print(table)
    for note in dict.fromkeys(n for c in found for n in c.notes):
        con.print(escape(f"note: {note}"))
    con.print(escape(f"Recommended: {rec.chain}, {rec.driving_teeth}/{rec.driven_teeth} teeth, {rec.links} links, "
                     f"centre distance {mm(rec.centre_distance):.2f} mm"))
    for a in rec.advice:
        con.print(escape(f"  advice: {a.name}: {a.note} [{a.source}]"))
    for m in result.near_misses:
        con.print(escape(f"Near miss: {' / '.join(m.names)} on {m.driving_teeth} teeth carries "
                         f"{m.rating_ratio:.1%} of the design power; remedy: {m.remedy}"))
    for c in rec.checks:
        con.print(escape(f"  {c.verdict}: {c.name}: {check_value_text(c)} (limit {check_limit_text(c)}) [{c.source}]"))
    if out_file is not None:
        typer.echo(f"wrote {out_file} (row {choose}: {found[choose - 1].chain}); check it with "
                   f"`chaindrive analyze {out_file}`")


@app.command("rating")
def rating_command(
    chain: str = typer.Option(..., "--chain", "-c", help="Roller chain name, e.g. 08B-1 or 'ANSI 40'."),
    teeth: int = typer.Option(..., "--teeth", "-z", help="Teeth of the small sprocket, a count."),
    speed: str = typer.Option(..., "--speed", "-n", help=unit_help("Speed of the small sprocket.", "rad/s",
                                                                   "1000 rpm")),
    method: str | None = typer.Option(None, "--method", help="Rating method: ansi or iso10823 (default: "
                                      "the method of the chain's family, iso10823 for ISO 606 B series)."),
    power: str | None = typer.Option(None, "--power", "-P", help=unit_help(
        "Design power, for the galling check (optional).", "W", "5 kW")),
    as_json: bool = typer.Option(False, "--json", help="JSON in SI units: rated_power [W], method, limited_by."),
) -> None:
    """Rated power of one roller chain on its small sprocket (ANSI/ACA or ISO 10823; the family's method)."""
    from ..design.rating import rate_chain

    r = rate_chain(chain, teeth, quantity(speed, "rad/s", "speed"), power=quantity(power, "W", "power"),
                   method=method)
    if as_json:
        echo_json({"chain": r.chain, "teeth": r.teeth, "angular_velocity": r.angular_velocity,
                   "rated_power": r.rated_power, "method": r.method, "limited_by": r.limited_by,
                   "link_plate": r.link_plate, "roller_bushing": r.roller_bushing, "chain_speed": r.chain_speed,
                   "lubrication": r.lubrication, "galling_speed": r.galling_speed, "source": r.source,
                   "warnings": list(r.warnings)})
        return
    typer.echo(f"{r.chain} on {r.teeth} teeth at {angular_velocity_to_rpm(r.angular_velocity):.6g} rpm: rated "
               f"{kw(r.rated_power):.4g} kW ({r.method}; limited by {r.limited_by.replace('_', '-')}); "
               f"link plate {kw(r.link_plate):.4g} kW, roller-bushing {kw(r.roller_bushing):.4g} kW; "
               f"chain speed {r.chain_speed:.3g} m/s, lubrication {r.lubrication} ({r.lubrication_method}) "
               f"[{r.source}]")
    for w in r.warnings:
        typer.echo(f"note: {w}")


def _centre_range(low: str | None, high: str | None) -> tuple[float, float] | None:
    """``--min-centre-distance``/``--max-centre-distance`` as the request's bounds [m] (an open end:
    0, or the largest centre distance of :data:`chaindrive.limits.DUTY_RANGES`)."""
    from ..limits import DUTY_RANGES

    if low is None and high is None:
        return None
    lo = quantity(low, "m", "min_centre_distance")
    hi = quantity(high, "m", "max_centre_distance")
    return (0.0 if lo is None else lo, DUTY_RANGES["centre_distance"][1] if hi is None else hi)


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
