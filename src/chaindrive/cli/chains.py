"""``chaindrive chains`` and ``chaindrive chain``: the chain catalogue on the command line.

Tables show millimetres, kilonewtons and kg/m (as the standards print them); ``--json``
prints SI units (m, N, kg/m), the same numbers the Python API returns.
"""

from __future__ import annotations

import typer

from ..chains import FAMILIES, Chain, catalogue, get
from ..display import display
from .app import app, echo_json

#: (header, attribute, SI unit, format): shown in the unit's display unit (chaindrive.display)
_COLUMNS: tuple[tuple[str, str, str, str], ...] = (
    ("pitch p [mm]", "pitch", "m", "{:.3f}"),
    ("roller d1 / bar d [mm]", "_diameter", "m", "{:.2f}"),
    ("inner width b1 [mm]", "inner_width", "m", "{:.2f}"),
    ("pin d2 [mm]", "pin_diameter", "m", "{:.2f}"),
    ("plate h2 [mm]", "plate_height", "m", "{:.2f}"),
    ("transv. pitch pt [mm]", "transverse_pitch", "m", "{:.2f}"),
    ("min. breaking F [kN]", "breaking_force", "N", "{:.1f}"),
    ("mass q [kg/m]", "mass_per_length", "kg/m", "{:.3f}"),
)


def _cell(chain: Chain, attribute: str, unit: str, fmt: str) -> str:
    if attribute == "_diameter":
        value = chain.roller_diameter if chain.is_roller_chain else chain.bar_diameter
    else:
        value = getattr(chain, attribute)
    return "-" if value is None else fmt.format(display(value, unit)[0])


def _console():
    from rich.console import Console

    console = Console()
    if not console.is_terminal:  # piped or captured: do not squeeze the table to 80 columns
        console = Console(width=200)
    return console


@app.command("chains")
def chains_command(
    family: str | None = typer.Option(
        None,
        "--family",
        "-f",
        help=(
            "Show one family only: iso606 (ISO 606 roller chains, A/B/C series), "
            "ansi (ANSI B29.1 numbers) or din22252 (DIN 22252 round link chains, grade C)."
        ),
    ),
    as_json: bool = typer.Option(
        False,
        "--json",
        help="Print the chains as JSON in SI units (m, N, kg/m) instead of a table in mm/kN.",
    ),
) -> None:
    """List the chain catalogue (ISO 606, ANSI B29.1, DIN 22252); table in mm, kN, kg/m.

    A dash marks a value the standard does not give or that could not be confirmed
    from a published source (see docs/chains.md).
    """
    rows = catalogue(family)  # raises UnknownNameError (exit 2) for a bad family
    if as_json:
        echo_json([c.to_dict() for c in rows])
        return
    from rich.markup import escape
    from rich.table import Table

    title = "Chain catalogue" + (f" ({family})" if family else f" ({', '.join(FAMILIES)})")
    table = Table(title=title)
    table.add_column("name", no_wrap=True)
    table.add_column("family", overflow="fold")
    table.add_column("strands", justify="right")
    for header, *_ in _COLUMNS:
        table.add_column(escape(header), justify="right", overflow="fold")
    for chain in rows:
        table.add_row(
            escape(chain.name),
            chain.family,
            str(chain.strands),
            *(_cell(chain, attr, unit, fmt) for _, attr, unit, fmt in _COLUMNS),
        )
    _console().print(table)


@app.command("chain")
def chain_command(
    name: str = typer.Argument(
        ...,
        help=(
            "Chain designation, case and blank insensitive: 16B (simplex), 16B-2, 08A-3, "
            "ANSI 80, 80-2, 18x64 (DIN 22252 bar diameter x pitch in mm)."
        ),
    ),
    as_json: bool = typer.Option(
        False,
        "--json",
        help="Print the chain as JSON in SI units (m, N, kg/m) instead of a table in mm/kN.",
    ),
) -> None:
    """Show one chain of the catalogue (table in mm, kN, kg/m; --json in SI units)."""
    chain = get(name)  # raises UnknownNameError (exit 2) with the closest names
    if as_json:
        echo_json(chain.to_dict())
        return
    from rich.markup import escape
    from rich.table import Table

    table = Table(title=f"{chain.name} ({chain.family})", show_header=True)
    table.add_column("quantity", overflow="fold")
    table.add_column("value", justify="right", overflow="fold")
    table.add_row("strands", str(chain.strands))
    table.add_row("type", "round link chain" if chain.is_link_chain else "roller chain")
    for header, attr, unit, fmt in _COLUMNS:
        table.add_row(escape(header), _cell(chain, attr, unit, fmt))
    table.add_row("source", escape(chain.source))
    _console().print(table)
