"""The typer application shared by the topic modules (internal).

Help text is plain (``rich_markup_mode=None``): square brackets in a help string are
printed as typed, never read as rich markup (they used to swallow units like ``[m]``).
Quantities typed at the command line go through :func:`quantity` (one strict parser,
:func:`chaindrive.units.parse_quantity`; a dimensional quantity needs its unit) and
:func:`wheel_speed` (angular speed, or the mean chain speed in m/s).
"""

from __future__ import annotations

import json
import sys
from collections.abc import Iterable, Mapping, Sequence
from typing import Any, overload

import typer

from .._results import jsonable
from ..display import mm
from ..kinematics.speed import parse_wheel_speed
from ..limits import warn_implausible
from ..units import parse_quantity

app = typer.Typer(
    name="chaindrive",
    help=(
        "chaindrive: design and analysis of chain drives (roller chains, round link "
        "chains, crawler chains). Every physical quantity needs its unit, e.g. '64 mm', "
        "'300 rpm', '2 kN' (a bare number is refused: 1450 could be rpm or rad/s); counts "
        "and ratios (teeth, ratio, service factor) are bare numbers. Each command's --help "
        "gives the unit of every option and an example."
    ),
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
    rich_markup_mode=None,
)

#: Kind of plausibility check (chaindrive.limits.PLAUSIBLE) by target unit.
_PLAUSIBLE_KIND = {"rad/s": "angular_velocity", "W": "power", "N": "force"}


def _print_version(value: bool) -> None:
    if value:
        from .. import __version__

        print(f"chaindrive {__version__}")
        raise typer.Exit()


@app.callback()
def _root(version: bool = typer.Option(False, "--version", callback=_print_version, is_eager=True,
                                       help="Print the chaindrive version and exit.")) -> None:
    """chaindrive: design and analysis of chain drives."""


#: One rule for every output file a command writes (--plot, --svg, --dxf, --step,
#: --campbell, --map, --write, FILE): an existing file is refused unless --force is given.
FORCE_OPTION_HELP = "Replace output files that exist (without it an existing file is refused before any work)."


def force_option() -> Any:
    """The ``--force`` option of a command that writes files."""
    return typer.Option(False, "--force", help=FORCE_OPTION_HELP)


#: Internal parameter names a command's errors may carry, by command, and the option the
#: user typed for each (``contact``: the formula's ``wear_factor`` is ``--k-phi``). The
#: command's own options (``teeth`` -> ``--teeth``) are found without being listed here.
OPTION_ALIASES: dict[str, dict[str, str]] = {}


def command_options(argv: Sequence[str]) -> tuple[dict[str, str], dict[str, str]]:
    """Parameter name -> option typed, and the command's :data:`OPTION_ALIASES`, for the
    command ``argv`` invokes (for error messages)."""
    group = typer.main.get_command(app)
    name = next((a for a in argv if not a.startswith("-")), None)
    command = getattr(group, "commands", {}).get(name) if name else None
    names: dict[str, str] = {}
    if command is not None:
        for p in command.params:
            if (getattr(p, "param_type_name", "") == "option" and p.name and p.opts
                    and not getattr(p, "is_flag", False)):
                names[p.name] = max(p.opts, key=len)
    found = _passed_as(getattr(command, "callback", None), names)
    return names, {**found, **OPTION_ALIASES.get(name or "", {})}


def _passed_as(callback: Any, names: Mapping[str, str]) -> dict[str, str]:
    """Formula parameters a command passes its options to under another name
    (``stress_concentration=kt`` -> ``{"stress_concentration": "--kt"}``), read from its source."""
    import ast
    import inspect
    import textwrap

    try:
        tree = ast.parse(textwrap.dedent(inspect.getsource(inspect.unwrap(callback))))
    except (TypeError, OSError, SyntaxError, ValueError):
        return {}
    out: dict[str, str] = {}
    for node in ast.walk(tree):
        if isinstance(node, ast.keyword) and node.arg and isinstance(node.value, ast.Name):
            option = names.get(node.value.id)
            if option and node.arg != node.value.id and node.arg not in names:
                out[node.arg] = option
    return out


def name_options(message: str, names: Mapping[str, str], aliases: Mapping[str, str] | None = None) -> str:
    """A message with the internal name it starts with (``teeth must ...``) replaced by the
    option the user typed; the ``aliases`` (formula parameters a command passes options
    to) anywhere in it.

    Examples
    --------
    >>> name_options("wear_factor must lie in (0, 1], got -1", {"wear_factor": "--k-phi"})
    '--k-phi must lie in (0, 1], got -1'
    >>> name_options("radius_2 must be positive (0 < radius_2 < inf m)", {}, {"radius_2": "--seat-radius"})
    '--seat-radius must be positive (0 < --seat-radius < inf m)'
    >>> name_options("chain '16B' has no bar_diameter", {"chain": "--chain"})
    "chain '16B' has no bar_diameter"
    """
    import re

    names = {**names, **(aliases or {})}
    m = re.match(r"([A-Za-z_][A-Za-z0-9_]*)(?=\s+(?:must|is|needs|should|cannot)\b|:|\s+\()", message)
    if m and m.group(1) in names:
        message = names[m.group(1)] + message[m.end():]
    for name, option in (aliases or {}).items():
        message = re.sub(rf"(?<![\w-]){re.escape(name)}(?![\w])", option, message)
    return message


def option_name(field: str) -> str:
    """``"guide_end"`` -> ``"--guide-end"`` (messages name the option as typed)."""
    return field if field.startswith("-") else "--" + field.replace("_", "-")


@overload
def quantity(text: str, unit: str, field: str, *, examples: tuple[str, ...] | None = None) -> float: ...


@overload
def quantity(text: None, unit: str, field: str, *, examples: tuple[str, ...] | None = None) -> None: ...


@overload
def quantity(text: str | None, unit: str, field: str, *,
             examples: tuple[str, ...] | None = None) -> float | None: ...


def quantity(text: str | None, unit: str, field: str, *,
             examples: tuple[str, ...] | None = None) -> float | None:
    """Parse an option's text into ``unit`` (``None`` stays ``None``).

    A dimensional quantity needs its unit; an implausible value (a speed above
    10 000 rpm, a power below 1 W, a pitch outside 3...500 mm) warns.
    """
    if text is None:
        return None
    name = option_name(field)
    value = parse_quantity(text, unit, field=name, examples=examples)
    kind = _PLAUSIBLE_KIND.get(unit)
    if kind == "force" and not name.endswith(("load", "tension", "weight", "force")):
        kind = None  # an axial rigidity EA is given in N too
    if unit == "m" and name.endswith("pitch"):
        kind = "pitch"
    warn_implausible(name, value, kind, stacklevel=2)
    return value


def wheel_speed(text: str, *, pitch: float, teeth: int, link_chain: bool = False,
                field: str = "speed") -> float:
    """Wheel angular speed [rad/s] from ``"300 rpm"``/``"5 rad/s"`` or a chain speed ``"1.2 m/s"``."""
    return parse_wheel_speed(text, pitch=pitch, teeth=teeth, link_chain=link_chain,
                             field=option_name(field))


def unit_help(text: str, unit: str, example: str) -> str:
    """Help text of a quantity option: ``text`` then its unit and an example.

    >>> unit_help("Chain pitch p.", "m", "25.4 mm")
    "Chain pitch p. Unit m, e.g. '25.4 mm'."
    """
    return f"{text} Unit {unit}, e.g. '{example}'."


def print_rows(title: str, rows: Sequence[tuple[str, ...]]) -> None:
    """Print a titled table of (name, value with unit[, source]) rows, aligned.

    The one text-table printer of the commands (kinematics, crawler, geometry,
    strength): every value carries its unit.
    """
    print(title)
    if not rows:
        return
    width = max(len(r[0]) for r in rows)
    value_width = max([len(r[1]) for r in rows if len(r[1]) <= 32] or [0])  # long lists do not widen the column
    for row in rows:
        name, value, *source = row
        line = f"  {name:<{width}}  {value:>{value_width}}"
        if source and source[0]:
            line += f"   {source[0]}"
        print(line.rstrip())


def ratio_text(value: float, digits: int = 4) -> str:
    """A dimensionless value with its unit word: ``'0.0765 (7.65 %)'``."""
    return f"{value:.{digits}g} (= {100 * value:.3g} %)"


def motion_rows(summary: Mapping[str, Any]) -> list[tuple[str, str]]:
    """Rows of the speed summary shared by ``kinematics`` and ``crawler``."""
    s = summary
    return [
        ("mean speed v_mean", f"{s['v_mean']:.6f} m/s"),
        ("minimum speed v_min", f"{s['v_min']:.6f} m/s"),
        ("maximum speed v_max", f"{s['v_max']:.6f} m/s"),
        ("non-uniformity (vmax - vmin)/vmean", f"{100 * s['nonuniformity']:.4g} %"),
        ("minimum acceleration a_min", f"{s['a_min']:.6f} m/s²"),
        ("maximum acceleration a_max", f"{s['a_max']:.6f} m/s²"),
        ("acceleration changes sign at period end", "yes" if s["sign_change_at_period_end"] else "no"),
        ("transverse throw", f"{mm(s['transverse_throw']):.4f} mm"),
    ]


def motion_title(what: str, radius: float, omega: float) -> str:
    """Title of the ``kinematics`` and ``crawler`` tables: ``what``, the pitch radius and the
    wheel speed in rad/s and rpm.

    >>> motion_title("crawler drive chain (z = 9", 0.1, 2.0)
    'crawler drive chain (z = 9, R = 100.000 mm, omega = 2 rad/s = 19.0986 rpm'
    """
    from ..units import angular_velocity_to_rpm

    return f"{what}, R = {mm(radius):.3f} mm, omega = {omega:.6g} rad/s = {angular_velocity_to_rpm(omega):.6g} rpm"


def motion_json(summary: Mapping[str, Any], keys: Sequence[str], arrays: Mapping[str, Any],
                after: Mapping[str, Any] | None = None) -> None:
    """Print the ``--json`` of ``kinematics`` and ``crawler``: the sampled ``arrays``, the
    summary (its declared ``keys`` first), then ``after``."""
    ordered = {k: summary[k] for k in keys}
    ordered.update({k: v for k, v in summary.items() if k not in ordered})
    echo_json({**arrays, "summary": ordered, **(after or {})})


def motion_output(result: Any, keys: Sequence[str], arrays: Mapping[str, Any], *, as_json: bool,
                  head: str, tail: str, rows: Sequence[tuple[str, str]] = (),
                  after: Mapping[str, Any] | None = None, plot: Any = None) -> None:
    """Print the result of ``kinematics`` or ``crawler``: with ``as_json`` its :func:`motion_json`
    (``arrays``, the summary, ``after``); else the table titled ``head``, the pitch radius and
    the wheel speed (:func:`motion_title`), ``tail``, of the speed summary (:func:`motion_rows`)
    and ``rows``, and the ``--plot`` file written."""
    if as_json:
        motion_json(result.summary, keys, arrays, after)
        return
    title = motion_title(head, result.radius, result.angular_velocity)
    print_rows(title + tail, motion_rows(result.summary) + list(rows))
    if plot is not None:
        print(f"wrote {plot}")


def check_plot(plot: Any, force: bool) -> None:
    """Refuse a ``--plot`` file before any work: a figure suffix, not there unless ``--force``."""
    if plot is not None:
        from .._io import FIGURE_SUFFIXES, check_output_path

        check_output_path(plot, FIGURE_SUFFIXES, option="--plot", force=force)


def save_plot(fig: Any, plot: Any, force: bool) -> None:
    """Write the ``--plot`` figure (120 dpi) and close it."""
    import matplotlib.pyplot as plt

    from .._io import save_figure

    save_figure(fig, plot, option="--plot", dpi=120, force=force)
    plt.close(fig)


def echo_json(obj: Any) -> None:
    """Print ``obj`` as JSON (numpy converted), to stdout."""
    sys.stdout.write(json.dumps(jsonable(obj), indent=2) + "\n")


def echo_lines(lines: Iterable[str]) -> None:
    """Print each line (``wrote FILE`` notes and the like)."""
    for line in lines:
        print(line)


def exit_code(code: int) -> None:
    """Leave the command with ``code`` (0 pass, 1 a check failed, 2 bad input)."""
    raise typer.Exit(code)
