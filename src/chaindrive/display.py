"""Engineering display units for SI values (the presenters' one table: report, CLI, web page, plots).

The core and every result object hold SI values. A presenter shows a force in kN, a
power in kW, a stress in MPa, an angle in degrees and a length in mm: one table here, so
that every surface shows the same units.

>>> display(12500.0, "N")
(12.5, 'kN')
>>> check_line_parts(1.2e6, "W")
'1200 kW'
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from .units import RAD_S_PER_RPM

if TYPE_CHECKING:
    from .analysis.checks import Check

__all__ = ["verdict_text", "DISPLAY", "CONVERSIONS", "convert", "display_of", "display", "fmt", "check_line_parts",
           "check_value_text", "check_limit_text", "check_margin_text", "scaled", "mm", "um", "kn", "kw", "mpa", "kn_per_m", "ms"]

#: SI unit -> (display unit, factor).
DISPLAY: dict[str, tuple[str, float]] = {
    "N": ("kN", 1e-3),
    "W": ("kW", 1e-3),
    "Pa": ("MPa", 1e-6),
    "rad": ("°", 180.0 / math.pi),
    "m": ("mm", 1e3),
    "rad/s": ("rpm", 1.0 / RAD_S_PER_RPM),
    "N*m": ("N·m", 1.0),
}


#: (SI unit, display unit) -> factor, for the display units a result field may declare
#: (``quantity(unit, display=...)``) besides the defaults of :data:`DISPLAY`.
CONVERSIONS: dict[tuple[str, str], float] = {
    **{(si, shown): factor for si, (shown, factor) in DISPLAY.items()},
    ("m", "m"): 1.0,
    ("m", "µm"): 1e6,
    ("N", "N"): 1.0,
    ("W", "W"): 1.0,
    ("Pa", "GPa"): 1e-9,
    ("rad/s", "rad/s"): 1.0,
    ("rad/s", "Hz"): 1.0 / (2.0 * math.pi),
    ("s", "h"): 1.0 / 3600.0,
    ("m^2", "mm^2"): 1e6,
    ("m^3", "cm^3"): 1e6,
    ("1", "%"): 100.0,
    ("-", "%"): 100.0,
    ("rad", "arcmin"): math.degrees(1.0) * 60.0,
    ("N/m", "kN/m"): 1e-3,
    ("s", "ms"): 1e3,
}


def scaled(value: Any, unit: str, shown: str) -> Any:
    """``value`` [``unit``, SI; a number or an array] in the display unit ``shown``: the presenters'
    one conversion (:data:`CONVERSIONS`), for a number written into a text. A factor below one
    that is the reciprocal of a whole number divides (``12345.0 / 1e3``, exactly as written by hand).

    Examples
    --------
    >>> scaled(0.0125, "m", "mm"), scaled(12345.0, "N", "kN"), scaled(2.5e-6, "m", "µm")
    (12.5, 12.345, 2.5)
    """
    factor = CONVERSIONS[(unit, shown)]
    if factor < 1.0 and float(1.0 / factor).is_integer():
        return value / (1.0 / factor)
    return value * factor


def _in(unit: str, shown: str, what: str) -> Callable[[Any], Any]:
    """The function that shows a value [``unit``] in ``shown`` (:func:`scaled`), named after ``shown``."""
    def show(value: Any) -> Any:
        return scaled(value, unit, shown)

    show.__name__ = show.__qualname__ = {"µm": "um", "kN/m": "kn_per_m"}.get(shown, shown.lower())
    show.__doc__ = f"{what} [{unit}] in {shown} (:func:`scaled`)."
    return show


#: A length [m] in mm, e.g. ``f"{mm(0.0254):.1f} mm"`` -> ``'25.4 mm'``.
mm = _in("m", "mm", "A length")
#: A length [m] in µm.
um = _in("m", "µm", "A length")
#: A force [N] in kN.
kn = _in("N", "kN", "A force")
#: A power [W] in kW.
kw = _in("W", "kW", "A power")
#: A stress [Pa] in MPa.
mpa = _in("Pa", "MPa", "A stress")
#: A stiffness [N/m] in kN/m.
kn_per_m = _in("N/m", "kN/m", "A stiffness")
#: A time [s] in ms.
ms = _in("s", "ms", "A time")


def convert(value: float | None, unit: str, shown: str | None = None) -> tuple[float | None, str]:
    """``value`` [``unit``, SI] in the unit ``shown`` (default: its display unit of :data:`DISPLAY`).

    A unit with no display entry is shown as it is; an unknown (unit, shown) pair is a
    programming error (``KeyError``).

    >>> convert(0.0125, "m"), convert(10.0, "rad/s", "Hz")[1], convert(3.0, "kg")
    ((12.5, 'mm'), 'Hz', (3.0, 'kg'))
    """
    if shown is None or shown == unit:
        return display(value, unit) if shown is None else (value if value is None else float(value), unit)
    factor = CONVERSIONS[(unit, shown)]
    return (None if value is None else float(value) * factor), shown


def display_of(result: Any, name: str) -> tuple[float | None, str]:
    """Field ``name`` of a result object (:class:`chaindrive._results.Result`) in its display unit.

    >>> from chaindrive.vibration import TensionerSpan
    >>> display_of(TensionerSpan(2000.0, 2.6, 0.8, 0.8, 0.35, 0.35, 3.0, 5e4), "length_1")
    (800.0, 'mm')
    """
    unit = type(result).unit_of(name) or "1"
    value = getattr(result, name)
    return convert(None if value is None else float(value), unit, type(result).display_unit_of(name))


def display(value: float | None, unit: str) -> tuple[float | None, str]:
    """``value`` [``unit``, SI] in its display unit."""
    shown, factor = DISPLAY.get(unit, (unit, 1.0))
    return (None if value is None else float(value) * factor), shown


def fmt(value: Any, digits: int = 4) -> str:
    """A number with ``digits`` significant digits; text and booleans as words.

    Examples
    --------
    >>> fmt(1234.5678), fmt(26031.7), fmt(True), fmt(None), fmt(2.5e-5)
    ('1235', '26032', 'yes', '—', '2.50e-05')
    """
    if value is None:
        return "—"
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if not math.isfinite(value):
            return "—"
        if value != 0 and (abs(value) >= 1e6 or abs(value) < 1e-3):
            return f"{value:.{digits - 1}e}"
        if abs(value) >= 10**digits:
            return f"{value:.0f}"
        return f"{value:.{digits}g}"
    return str(value)


def check_line_parts(value: float | None, unit: str, shown: str | None = None) -> str:
    v, u = convert(value, unit, shown or None)
    return f"{fmt(v)} {u}".strip() if u != "-" else fmt(v)


def check_value_text(check: Check) -> str:
    """The check's value with its display unit (``"—"`` when unknown)."""
    if check.value is None:
        return "unknown"
    return check_line_parts(check.value, check.unit, check.display)


def check_limit_text(check: Check) -> str:
    """``">= 7"``, ``"48 … 60 HRC"``, ``""`` for information."""
    if check.relation == "info" or check.limit is None:
        return ""
    limit = check.limit
    if isinstance(limit, tuple):  # a "within" range
        lo, hi = limit
        (a, u), (b, _) = convert(lo, check.unit, check.display or None), convert(hi, check.unit, check.display or None)
        return f"{fmt(a)} … {fmt(b)} {u if u != '-' else ''}".strip()
    return f"{check.relation} {check_line_parts(limit, check.unit, check.display)}"


def check_margin_text(check: Check | float | None) -> str:
    """The relative margin of a check to its limit in per cent (:attr:`Check.margin
    <chaindrive.analysis.checks.Check.margin>`, the check's own number; ``""`` without one).

    Examples
    --------
    >>> from chaindrive.analysis.checks import Check
    >>> check_margin_text(Check("static safety", 9.1, 7.0, "-", True, "ISO 10823:2004"))
    '+30 %'
    >>> check_margin_text(-0.052), check_margin_text(None)
    ('-5 %', '')
    """
    margin = check if check is None or isinstance(check, (int, float)) else check.margin
    if margin is None or not math.isfinite(margin):
        return ""
    return f"{margin * 100:+.0f} %"


def verdict_text(failed: int, warnings: int) -> str:
    """The overall verdict in words: never "all checks pass" beside a warning.

    Parameters
    ----------
    failed : int
        Checks that fail.
    warnings : int
        Warnings of the analysis.

    Examples
    --------
    >>> verdict_text(0, 0), verdict_text(0, 3), verdict_text(2, 1)
    ('passes', 'passes, 3 warnings', 'fails: 2 checks fail, 1 warning')
    """
    w = f"{warnings} warning{'s' if warnings != 1 else ''}"
    if failed:
        return f"fails: {failed} check{'s' if failed != 1 else ''} fail{'s' if failed == 1 else ''}" + (
            f", {w}" if warnings else "")
    return "passes" + (f", {w}" if warnings else "")
