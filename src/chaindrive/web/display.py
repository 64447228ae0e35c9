"""Display of numbers with units on the pages: metric or imperial (conversion for display only).

Values stay SI inside; a number is converted only when it is written on a page. Metric
display units are the library's one table (:data:`chaindrive.workflows.display.DISPLAY`:
kN, kW, MPa, °, mm, rpm), the same as in the report and at the command line. Imperial
display converts the SI value with the factors below (definitions of the units, NIST
SP 811 appendix B). Units not listed are shown as they come from the result objects.
"""

from __future__ import annotations

from typing import Any

from ..display import DISPLAY, fmt

__all__ = ["show", "fmt", "IMPERIAL"]

#: SI unit -> (imperial display unit, factor from SI).
IMPERIAL: dict[str, tuple[str, float]] = {
    "N": ("lbf", 1 / 4.4482216152605),
    "W": ("hp", 1 / 745.69987158227022),
    "Pa": ("psi", 1 / 6894.757293168361),
    "m": ("in", 1 / 0.0254),
    "m/s": ("ft/min", 60 / 0.3048),
    "N*m": ("lbf·ft", 1 / 1.3558179483314004),
    "N·m": ("lbf·ft", 1 / 1.3558179483314004),
    "kg/m": ("lb/ft", 0.3048 / 0.45359237),
    "kg": ("lb", 1 / 0.45359237),
    "N/m": ("lbf/in", 0.0254 / 4.4482216152605),
    # display units of the report's tables
    "kN": ("lbf", 1e3 / 4.4482216152605),
    "kW": ("hp", 1e3 / 745.69987158227022),
    "MPa": ("psi", 1e6 / 6894.757293168361),
    "mm": ("in", 1 / 25.4),
    "m/s²": ("ft/s²", 1 / 0.3048),
}


def show(value: Any, unit: str, units: str = "metric") -> tuple[str, str]:
    """``(number text, unit text)`` of an SI value for the page.

    Parameters
    ----------
    value : float
        In ``unit`` (SI).
    unit : str
        SI unit of the value, as the result object gives it (``"N"``, ``"m"``, ``"W"``...).
    units : {"metric", "imperial"}

    Examples
    --------
    >>> show(0.5021, "m"), show(0.5021, "m", "imperial")
    (('502.1', 'mm'), ('19.77', 'in'))
    """
    if not isinstance(value, (int, float)) or isinstance(value, bool):
        return fmt(value), "" if unit == "-" else (unit or "")
    if units == "imperial" and unit in IMPERIAL:
        shown, factor = IMPERIAL[unit]
    else:
        shown, factor = DISPLAY.get(unit, (unit, 1.0))
    return fmt(float(value) * factor), "" if shown == "-" else (shown or "")
