"""Form fields of the web pages: text as typed, parsed once into SI units.

Every field keeps the text the user typed (so a page shown again with an error keeps it)
and is parsed with :func:`chaindrive.units.parse_quantity`. A dimensional field refuses a
bare number (``"500"`` could be mm or m): the message asks for a unit. Every size-like
field has an upper bound, checked before anything is allocated.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

from ..errors import InputError
from ..units import parse_quantity

__all__ = ["FieldError", "FieldSpec", "input_field", "parse_field", "parse_integer", "BARE_NUMBER"]

#: A number with no unit after it.
BARE_NUMBER = re.compile(r"^\s*[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?\s*$")

#: Longest text accepted in any field [characters].
MAX_FIELD_LENGTH = 200


class FieldError(InputError):
    """Bad input in one form field; ``field`` names it (the id of the input element)."""

    field: str

    def __init__(self, field: str, message: str) -> None:
        super().__init__(f"{field}: {message}", field=field)
        self.field = field
        self.message = message

    def __reduce__(self) -> tuple:
        return (FieldError, (self.field, self.message))


@dataclass(frozen=True)
class FieldSpec:
    """What one field accepts.

    Attributes
    ----------
    unit : str
        SI unit the value is converted to (``""`` for a plain number).
    minimum, maximum : float
        Valid range in that unit (both inclusive unless ``open_minimum``).
    open_minimum : bool
        ``minimum`` itself is refused (e.g. a positive length).
    example : str
        Shown in the messages.
    """

    unit: str
    minimum: float
    maximum: float
    open_minimum: bool = True
    example: str = ""


def input_field(path: str, *, maximum: float, example: str, minimum: float | None = None) -> FieldSpec:
    """The form field of a project-file input ``"table.key"``: its SI unit and lower bound from
    the input's declaration (:mod:`chaindrive.drive.tables`), the page's upper bound
    ``maximum`` (a size cap; the smaller of it and the declared one), and an example.

    ``minimum`` narrows the declared lower bound for the page (inclusive).

    Examples
    --------
    >>> input_field("load.power", maximum=5e6, example="7.5 kW")
    FieldSpec(unit='W', minimum=0.0, maximum=5000000.0, open_minimum=True, example='7.5 kW')
    >>> input_field("tensioner.force", maximum=1e7, example="200 N").open_minimum
    False
    """
    from ..drive.schema import get_table

    table, _, key = path.rpartition(".")
    f = get_table(table).field(key)
    unit = "rad/s" if f.kind == "speed" else f.unit
    top = maximum if f.maximum is None else min(maximum, f.maximum)
    if minimum is not None:
        return FieldSpec(unit, minimum, top, open_minimum=False, example=example)
    low = 0.0 if f.kind == "speed" else f.minimum
    if low is None:
        raise ValueError(f"{path} has no lower bound: give minimum")
    return FieldSpec(unit, low, top, open_minimum=f.kind == "speed" or f.open_minimum, example=example)


def parse_field(name: str, text: str, spec: FieldSpec) -> float:
    """Parse the text of field ``name`` into SI units and check its range.

    Parameters
    ----------
    name : str
        Field name (reported in the message).
    text : str
        As typed, e.g. ``"500 mm"``.
    spec : FieldSpec

    Returns
    -------
    float
        The value in ``spec.unit`` (SI).

    Raises
    ------
    FieldError
        Empty, too long, bare number for a dimensional field, unknown unit, wrong
        dimension, outside ``[minimum, maximum]``.

    Examples
    --------
    >>> parse_field("centre_distance", "500 mm", FieldSpec("m", 0.0, 100.0, example="500 mm"))
    0.5
    >>> parse_field("centre_distance", "500", FieldSpec("m", 0.0, 100.0, example="500 mm"))
    Traceback (most recent call last):
    ...
    chaindrive.web.fields.FieldError: centre_distance: give a unit, e.g. '500 mm' (a bare number is ambiguous)
    """
    text = (text or "").strip()
    if not text:
        raise FieldError(name, f"required, e.g. {spec.example!r}" if spec.example else "required")
    if len(text) > MAX_FIELD_LENGTH:
        raise FieldError(name, f"at most {MAX_FIELD_LENGTH} characters")
    if spec.unit and BARE_NUMBER.match(text):
        raise FieldError(name, f"give a unit, e.g. {spec.example!r} (a bare number is ambiguous)")
    try:
        value = parse_quantity(text, spec.unit or "dimensionless", field=name)
    except InputError as exc:
        raise FieldError(name, str(exc).removeprefix(f"{name}: ")) from None
    unit = f" {spec.unit}" if spec.unit else ""
    low = "<" if spec.open_minimum else "<="
    rng = f"{spec.minimum:g}{unit} {low} {name} <= {spec.maximum:g}{unit}"
    if not math.isfinite(value):
        raise FieldError(name, f"must be finite ({rng})")
    if value > spec.maximum or value < spec.minimum or (spec.open_minimum and value == spec.minimum):
        raise FieldError(name, f"{value:g}{unit} is outside the valid range {rng}")
    return float(value)


def parse_integer(name: str, text: str, minimum: int, maximum: int) -> int:
    """Parse a whole number in ``[minimum, maximum]``.

    Examples
    --------
    >>> parse_integer("teeth_driving", " 19 ", 9, 150)
    19
    """
    text = (text or "").strip()
    if not re.fullmatch(r"[+]?\d{1,9}", text):
        raise FieldError(name, f"a whole number {minimum} <= {name} <= {maximum}, got {text[:40]!r}")
    value = int(text)
    if not minimum <= value <= maximum:
        raise FieldError(name, f"{value} is outside the valid range {minimum} <= {name} <= {maximum}")
    return value
