"""``chaindrive life``: the drive over its life, or its worn chain at one point of it.

Without options: the lives by mechanism (wear, jump-over, fatigue), the efficiency and the
power lost (the analysis part ``life``, docs/life.md). ``--hours`` or ``--elongation``: the
worn chain at that point (seating rise and jump-over margin on every sprocket, the take-up,
the span frequencies). ``--json`` prints the result in SI units.
"""

from __future__ import annotations

from pathlib import Path

import typer

from ..display import mm
from .app import app, echo_json, print_rows, quantity, ratio_text, unit_help


@app.command("life")
def life_command(
    project: Path = typer.Argument(..., help="Project file (TOML), e.g. examples/roller_industrial.toml."),
    hours: str | None = typer.Option(None, "--hours", help=unit_help(
        "Running time >= 0, up to the hours to the drive's elongation limit.", "h", "20000 h")),
    elongation: str | None = typer.Option(None, "--elongation", help=unit_help(
        "Wear elongation >= 0, up to the drive's elongation limit.", "1 (a ratio, or %)", "2 %")),
    as_json: bool = typer.Option(False, "--json", help="Print the result as JSON, SI units (h for hours)."),
) -> None:
    """Elongation over hours, jump-over margin, fatigue, efficiency; or the worn chain at one point."""
    from ..analysis import analyze_drive
    from ..analysis.life import worn_state
    from ..drive.project import load_project
    from ..errors import InputError

    t = quantity(hours, "h", "hours")
    e = quantity(elongation, "1", "elongation")
    drive = load_project(project)
    a = analyze_drive(drive, include=["life", "layout", "loads"])
    life = a.life
    if life is None:
        raise InputError("no wear model applies to this drive (a link chain needs wear_coefficient in [drive])",
                         field="drive.wear_coefficient")
    if t is None and e is None:
        if as_json:
            echo_json(life)
            return
        rows = [(f"hours to the elongation limit ({life.wear_basis})", f"{life.replacement_hours:.6g} h"),
                ("elongation limit", ratio_text(life.elongation_limit))]
        if life.replacement_limit is not None:
            rows.append(("makers' replacement limit", ratio_text(life.replacement_limit)))
        if life.jump_over_elongation is not None:
            rows.append((f"jump-over (wheel '{life.jump_over_wheel}')",
                         f"{ratio_text(life.jump_over_elongation)} after {life.jump_over_hours:.6g} h"))
        if life.fatigue_utilisation is not None:
            rows.append(("link-plate fatigue: range / endurance", f"{life.fatigue_utilisation:.3g}"))
        if life.efficiency is not None:
            rows.append(("efficiency", ratio_text(life.efficiency)))
            rows.append(("power lost as heat", f"{life.power_loss:.4g} W"))
        rows.append((f"life (governed by {life.governing})", f"{life.life_hours:.6g} h"))
        print_rows(f"{drive.name}: the drive over its life (docs/life.md)", rows)
        return
    if t is not None and e is not None:
        raise InputError("give --hours or --elongation, not both", field="hours")
    state = worn_state(drive, a.layout, a.loads, life, hours=t, elongation=e)
    if as_json:
        echo_json(state)
        return
    rows = [("running time", f"{state.hours:.6g} h"), ("elongation", ratio_text(state.elongation))]
    for name, rise, m in zip(state.wheel_names, state.seating_rise, state.jump_over_margin, strict=True):
        if rise is not None:
            rows.append((f"'{name}': rollers ride out by", f"{mm(rise):.4g} mm"))
        if m is not None:
            rows.append((f"'{name}': jump-over margin", f"{m:.4g}"))
    if state.take_up is not None:
        rows.append(("take-up of the elongation", f"{mm(state.take_up):.4g} mm"))
    print_rows(f"{drive.name}: the worn chain", rows)
