"""Unit parsing at the boundary (CLI, project files, web page).

The core works in SI units only. Text typed by a user (``"64 mm"``, ``"300 rpm"``,
``"15 kW"``) is parsed here, once, and converted to the SI unit the core expects.

The parser is strict: the text is a number and a unit, nothing else.

* grammar ``<number> [<unit expression>]``, at most :data:`MAX_TEXT_LENGTH` characters;
  the number is a plain decimal (``1450``, ``-0.5``, ``2.5e3``), read with Python's
  ``float``; the unit expression is unit names (with SI prefixes) joined by ``*``,
  ``/``, ``·`` or a blank, each with an optional small integer exponent (``^2``,
  ``**2``, ``²``); ``1/s`` is allowed (for a frequency). No arithmetic, no parentheses, no powers of
  powers: ``"9**9**9"`` is refused before anything is evaluated;
* only the unit goes to `pint <https://pint.readthedocs.io>`_ (``parse_units``, cached);
* values that are not finite, or overflow on conversion, are refused;
* a dimensional quantity typed without a unit is refused (``require_unit=True``, the
  default): ``1450`` could be rpm or rad/s, and guessing is how 1450 rpm became
  13,800 rpm. Dimensionless inputs (teeth, ratio, service factor) stay bare;
* angular speed and frequency are kept apart: ``"5 Hz"`` as a wheel speed is five
  turns per second (31.4 rad/s, not 5 rad/s as pint's ``Hz = 1/s`` would give) and
  ``"300 rpm"`` as a frequency is 5 Hz. ``"5 1/s"`` or ``"1450 1/min"`` as a wheel speed
  is refused (radians or turns per unit time? Dolipiński et al. write ω = 5 1/s for
  rad/s, DIN practice writes n = 1450 min⁻¹ for rpm).

A real number passed from Python (``float``, ``int``) is taken as already in SI units:
the Python API stays SI floats.
"""

from __future__ import annotations

import dataclasses
import math
import re
from functools import lru_cache
from typing import Any

from .errors import InputError

#: One revolution per minute in rad/s: the one rpm <-> rad/s conversion of the package
#: (everything else calls :func:`rpm_to_angular_velocity` / :func:`angular_velocity_to_rpm`).
RAD_S_PER_RPM = math.pi / 30.0


def rpm_to_angular_velocity(rpm: Any) -> Any:
    """Revolutions per minute to rad/s (scalars or arrays).

    >>> round(rpm_to_angular_velocity(960.0), 4)
    100.531
    """
    return rpm * RAD_S_PER_RPM


def angular_velocity_to_rpm(angular_velocity: Any) -> Any:
    """rad/s to revolutions per minute (scalars or arrays).

    >>> round(angular_velocity_to_rpm(100.0), 3)
    954.93
    """
    return angular_velocity / RAD_S_PER_RPM

__all__ = [
    "parse_quantity",
    "parse_speed_text",
    "SI_UNITS",
    "to_si",
    "unit_example",
    "is_dimensional",
    "MAX_TEXT_LENGTH",
    "normalise_unit",
    "SPELLINGS",
    "AMBIGUOUS",
    "convert_from_si",
]

#: The SI unit the core expects for each kind of quantity, as pint spells it.
SI_UNITS: dict[str, str] = {
    "length": "m",
    "angle": "rad",
    "angular_velocity": "rad/s",
    "velocity": "m/s",
    "acceleration": "m/s**2",
    "force": "N",
    "mass": "kg",
    "mass_per_length": "kg/m",
    "stiffness": "N/m",
    "torque": "N*m",
    "power": "W",
    "pressure": "Pa",
    "time": "s",
    "frequency": "Hz",
    "dimensionless": "",
}

#: Longest quantity text accepted [characters].
MAX_TEXT_LENGTH = 64

# <number> [<unit expression>]: the number is a plain decimal; a unit name is letters
# (with the micro sign, Greek mu, ohm, degree and percent signs), an exponent is a small
# integer written ^n, **n, or as a superscript.
_NUMBER = r"[+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d{1,3})?"
_NAME = r"(?:[A-Za-zµμΩ_]+|°|%)"
_EXPONENT = r"(?:(?:\^|\*\*)[+-]?[1-4]|[²³])"
_FACTOR = rf"{_NAME}{_EXPONENT}?"
_UNIT = rf"(?:1\s*/\s*)?{_FACTOR}(?:\s*[*/·]\s*{_FACTOR}|\s+{_FACTOR})*"
_GRAMMAR = re.compile(rf"^\s*(?P<number>{_NUMBER})\s*(?P<unit>{_UNIT})?\s*$")

#: Spellings engineers type that pint does not know, each with one meaning: token -> unit.
#: (Case matters to pint: "KW" is no unit there, but nobody means kelvin-watts by it.)
SPELLINGS: dict[str, str] = {
    "RPM": "rpm", "Rpm": "rpm", "rpms": "rpm", "RPMs": "rpm",
    "kw": "kW", "KW": "kW", "Kw": "kW",
    "KN": "kN", "Kn": "kN",
    "KG": "kg", "Kg": "kg",
    "HP": "hp", "Hp": "hp",
    "MPA": "MPa", "Mpa": "MPa",
    "GPA": "GPa", "Gpa": "GPa",
    "MM": "mm", "Mm": "mm",
    "Nm": "N*m", "kNm": "kN*m", "KNm": "kN*m",
    "sec": "s", "secs": "s",
}

#: Whole unit texts with one meaning (a revolution per minute written out).
WHOLE_SPELLINGS: dict[str, str] = {
    "rev/min": "rpm", "revs/min": "rpm", "r/min": "rpm", "U/min": "rpm", "rev/mn": "rpm",
    "r/s": "rev/s", "revs/s": "rev/s",
}

#: Spellings that mean two different things: refused with both readings.
AMBIGUOUS: dict[str, str] = {
    "mw": "'mW' (milliwatt) or 'MW' (megawatt)",
    "mpa": "'MPa' (megapascal) or 'mPa' (millipascal)",
    "kn": "'kN' (kilonewton) or 'knot' (a speed)",
    "gpa": "'GPa' (gigapascal)",
}

_TOKEN = re.compile(r"[A-Za-zµμΩ_]+")


def normalise_unit(given: str, *, field: str = "value", text: str | None = None) -> str:
    """The unit text ``given`` with the usual engineering spellings made pint's.

    "RPM", "rev/min", "r/min" are rpm; "kw", "KW" are kW; "KN" is kN; "Nm" is N*m. A
    spelling with two readings ("mw": milliwatt or megawatt?) is refused naming both.

    Examples
    --------
    >>> normalise_unit("RPM"), normalise_unit("rev/min"), normalise_unit("KW"), normalise_unit("kN/m")
    ('rpm', 'rpm', 'kW', 'kN/m')
    >>> normalise_unit("mw", field="power")
    Traceback (most recent call last):
    ...
    chaindrive.errors.InputError: power: unit 'mw' is ambiguous: write 'mW' (milliwatt) or 'MW' (megawatt)
    """
    stripped = given.strip()
    if stripped in WHOLE_SPELLINGS:
        return WHOLE_SPELLINGS[stripped]
    for token in _TOKEN.findall(stripped):
        if token in AMBIGUOUS:
            where = f" in {text!r}" if text is not None and text.strip() != stripped else ""
            raise InputError(f"{field}: unit {token!r}{where} is ambiguous: write {AMBIGUOUS[token]}",
                             field=field)
    return _TOKEN.sub(lambda m: SPELLINGS.get(m.group(0), m.group(0)), stripped)


#: Two example units for a bare number, by the target unit.
_EXAMPLES: dict[str, tuple[str, str]] = {
    "m": ("mm", "m"),
    "rad": ("deg", "rad"),
    "rad/s": ("rpm", "rad/s"),
    "m/s": ("m/s", "m/min"),
    "m/s**2": ("m/s**2", "mm/s**2"),
    "N": ("N", "kN"),
    "kg": ("kg", "t"),
    "kg/m": ("kg/m", "g/m"),
    "N/m": ("N/m", "kN/m"),
    "N*m": ("N*m", "kN*m"),
    "W": ("W", "kW"),
    "Pa": ("MPa", "Pa"),
    "s": ("s", "ms"),
    "Hz": ("Hz", "rpm"),
    "m**2/N": ("m**2/N", "mm**2/N"),
    "s/m": ("s/m", "s/mm"),
    "s/N": ("s/N", "s/kN"),
}


@lru_cache(maxsize=1)
def _registry():
    import sys

    # pint.compat imports dask when it is installed (0.1-0.3 s, with yaml and jinja2) only
    # to wrap dask arrays, which never reach pint here: hide it while pint loads
    hide_dask = "dask" not in sys.modules
    if hide_dask:
        # typeshed types sys.modules' values as ModuleType; None is the documented way to
        # block an import (Python reference, "The module cache")
        sys.modules["dask"] = None  # type: ignore[assignment]
    try:
        import pint
    except ImportError as exc:  # pragma: no cover - depends on install
        raise InputError(
            "parsing quantities with units needs pint: pip install 'chaindrive[units]'"
        ) from exc
    finally:
        if hide_dask and sys.modules.get("dask", 0) is None:
            del sys.modules["dask"]
    try:
        # pint's parsed-definitions cache in the user's cache folder (pint's own benchmark
        # test_01_registry_creation.py::test_create_default_registry_use_cache: 54 ms
        # against 690 ms without; measured here 0.04 s against 0.3 s)
        ureg = pint.UnitRegistry(cache_folder=":auto:")
    except Exception:  # noqa: BLE001 - an unwritable cache folder must not stop parsing
        ureg = pint.UnitRegistry()
    if "rpm" not in ureg:  # a cached registry may hold it already
        ureg.define("rpm = revolution / minute")
    if "rev" not in ureg:
        ureg.define("rev = revolution")
    return ureg


@dataclasses.dataclass(frozen=True)
class _Dims:
    """A dimensionality: its exponents (compared) and pint's text of it (for messages)."""

    items: tuple[tuple[str, float], ...]
    text: str = dataclasses.field(compare=False)

    def __bool__(self) -> bool:
        return bool(self.items)

    def __str__(self) -> str:
        return self.text


#: The units a project and the report use most, as pint defines them (SI brochure, 9th ed.):
#: unit text -> (factor to pint's root units, dimensionality exponents, its text, radian
#: exponent, Hz-like). Read without loading pint (~0.2 s a process); every entry equals
#: pint's own value exactly (tests/test_units_table.py); any other unit goes to pint.
_TABLE: dict[str, tuple[float, tuple[tuple[str, float], ...], str, int, bool]] = {
    '': (1.0, (), 'dimensionless', 0, False),
    'Hz': (1.0, (('[time]', -1),), '1 / [time]', 0, True),
    'MN': (1000000000.0, (('[length]', 1), ('[mass]', 1), ('[time]', -2)), '[mass] * [length] / [time] ** 2', 0, False),
    'MN/m': (1000000000.0, (('[mass]', 1), ('[time]', -2)), '[mass] / [time] ** 2', 0, False),
    'MPa': (1000000000.0, (('[length]', -1), ('[mass]', 1), ('[time]', -2)), '[mass] / [length] / [time] ** 2', 0, False),
    'N': (1000.0, (('[length]', 1), ('[mass]', 1), ('[time]', -2)), '[mass] * [length] / [time] ** 2', 0, False),
    'N*m': (1000.0, (('[length]', 2), ('[mass]', 1), ('[time]', -2)), '[mass] * [length] ** 2 / [time] ** 2', 0, False),
    'N/m': (1000.0, (('[mass]', 1), ('[time]', -2)), '[mass] / [time] ** 2', 0, False),
    'Pa': (1000.0, (('[length]', -1), ('[mass]', 1), ('[time]', -2)), '[mass] / [length] / [time] ** 2', 0, False),
    'W': (1000.0, (('[length]', 2), ('[mass]', 1), ('[time]', -3)), '[mass] * [length] ** 2 / [time] ** 3', 0, False),
    'deg': (0.017453292519943295, (), 'dimensionless', 1, False),
    'kN': (1000000.0, (('[length]', 1), ('[mass]', 1), ('[time]', -2)), '[mass] * [length] / [time] ** 2', 0, False),
    'kN*m': (1000000.0, (('[length]', 2), ('[mass]', 1), ('[time]', -2)), '[mass] * [length] ** 2 / [time] ** 2', 0, False),
    'kN/m': (1000000.0, (('[mass]', 1), ('[time]', -2)), '[mass] / [time] ** 2', 0, False),
    'kW': (1000000.0, (('[length]', 2), ('[mass]', 1), ('[time]', -3)), '[mass] * [length] ** 2 / [time] ** 3', 0, False),
    'kg': (1000.0, (('[mass]', 1),), '[mass]', 0, False),
    'kg/m': (1000.0, (('[length]', -1), ('[mass]', 1)), '[mass] / [length]', 0, False),
    'm': (1.0, (('[length]', 1),), '[length]', 0, False),
    'm**2/N': (0.001, (('[length]', 1), ('[mass]', -1), ('[time]', 2)), '[length] * [time] ** 2 / [mass]', 0, False),
    'm/s': (1.0, (('[length]', 1), ('[time]', -1)), '[length] / [time]', 0, False),
    'mm': (0.001, (('[length]', 1),), '[length]', 0, False),
    'rad': (1.0, (), 'dimensionless', 1, False),
    'rad/s': (1.0, (('[time]', -1),), '1 / [time]', 1, False),
    'rpm': (0.10471975511965977, (('[time]', -1),), '1 / [time]', 1, False),
    's': (1.0, (('[time]', 1),), '[time]', 0, False),
    'min': (60.0, (('[time]', 1),), '[time]', 0, False),
    'h': (3600.0, (('[time]', 1),), '[time]', 0, False),
    'arcmin': (0.00029088820866572163, (), 'dimensionless', 1, False),
    'cm': (0.01, (('[length]', 1),), '[length]', 0, False),
    'um': (1e-06, (('[length]', 1),), '[length]', 0, False),
    't': (1000000.0, (('[mass]', 1),), '[mass]', 0, False),
    'GPa': (1000000000000.0, (('[length]', -1), ('[mass]', 1), ('[time]', -2)), '[mass] / [length] / [time] ** 2', 0, False),
    'kPa': (1000000.0, (('[length]', -1), ('[mass]', 1), ('[time]', -2)), '[mass] / [length] / [time] ** 2', 0, False),
    'J': (1000.0, (('[length]', 2), ('[mass]', 1), ('[time]', -2)), '[mass] * [length] ** 2 / [time] ** 2', 0, False),
    'm/s**2': (1.0, (('[length]', 1), ('[time]', -2)), '[length] / [time] ** 2', 0, False),
    'kg*m**2': (1000.0, (('[length]', 2), ('[mass]', 1)), '[mass] * [length] ** 2', 0, False),
    'N/mm': (1000000.0, (('[mass]', 1), ('[time]', -2)), '[mass] / [time] ** 2', 0, False),
    'rad/s**2': (1.0, (('[time]', -2),), '1 / [time] ** 2', 1, False),
    't/h': (277.77777777777777, (('[mass]', 1), ('[time]', -1)), '[mass] / [time]', 0, False),
    'kg/s': (1000.0, (('[mass]', 1), ('[time]', -1)), '[mass] / [time]', 0, False),
}


@lru_cache(maxsize=512)
def _unit_info(unit: str) -> tuple[Any, float, _Dims, int, bool]:
    """(pint unit or None for a unit of :data:`_TABLE`, factor to root units, root
    dimensionality, radian exponent, is Hz-like)."""
    known = _TABLE.get(unit)
    if known is not None:
        factor, items, text, radians, hertz = known
        return None, factor, _Dims(items, text), radians, hertz
    return _pint_unit_info(unit)


def _pint_unit_info(unit: str) -> tuple[Any, float, _Dims, int, bool]:
    """:func:`_unit_info` by pint."""
    ureg = _registry()
    parsed = ureg.parse_units(unit) if unit else ureg.dimensionless
    factor, root = ureg.get_root_units(parsed)
    radians = int(dict(root._units).get("radian", 0))
    hertz = any(name in ("hertz",) or name.endswith("hertz") for name in dict(parsed._units))
    dims = ureg.Quantity(1.0, parsed).dimensionality
    return parsed, float(factor), _Dims(tuple(sorted(dict(dims).items())), str(dims)), radians, hertz


def _known_unit(unit: str, field: str) -> tuple[Any, float, Any, int, bool]:
    """:func:`_unit_info`, a unit pint cannot read refused with InputError naming ``field``."""
    if not isinstance(unit, str):
        raise InputError(f"{field} must be a unit as text, e.g. 'mm', got {unit!r}")
    try:
        return _unit_info(unit)
    except Exception as exc:  # noqa: BLE001 - pint's undefined-unit and syntax errors
        raise InputError(f"{field}: {unit!r} is not a unit chaindrive reads ({_one_line(exc)}); "
                         "e.g. 'mm', 'kN', 'rpm'") from None


def _one_line(exc: BaseException) -> str:
    return " ".join(str(exc).split())[:120] or type(exc).__name__


def convert_from_si(value: float, si_unit: str, unit: str) -> float:
    """``value`` [``si_unit``] expressed in ``unit`` (presenters' display units).

    >>> round(convert_from_si(10.0, "rad/s", "rpm"), 3), convert_from_si(0.5, "m", "mm")
    (95.493, 500.0)
    >>> round(convert_from_si(2 * math.pi, "rad/s", "Hz"), 12)  # Hz counts turns, as parse_quantity
    1.0
    """
    _, f_si, dims_si, rad_si, hz_si = _known_unit(si_unit, "si_unit")
    _, f_unit, dims_unit, rad_unit, hz_unit = _known_unit(unit, "unit")
    if dims_si != dims_unit:
        raise InputError(f"cannot show a value in {si_unit} as {unit}", field="unit")
    factor = f_si / f_unit
    if hz_unit and rad_si == 1 and not hz_si:  # an angular frequency shown in Hz: turns per second
        factor /= 2 * math.pi
    elif hz_si and rad_unit == 1 and not hz_unit:
        factor *= 2 * math.pi
    return float(value) * factor


def is_dimensional(unit: str) -> bool:
    """True when ``unit`` is a physical unit (angles count: a bare angle is ambiguous).

    >>> is_dimensional("rad/s"), is_dimensional("rad"), is_dimensional("")
    (True, True, False)
    """
    if unit in ("", "dimensionless"):
        return False
    _, _, dims, radians, _ = _known_unit(unit, "unit")
    return bool(dims) or radians != 0


def unit_example(number: str, unit: str, units: tuple[str, ...] | None = None) -> str:
    """How to write ``number`` with a unit convertible to ``unit`` (for messages).

    ``units`` overrides the usual two example units (e.g. ``("arcmin", "deg")`` for a skew).

    Examples
    --------
    >>> unit_example("1450", "rad/s")
    '"1450 rpm" or "1450 rad/s"'
    >>> unit_example("50", "rad", ("arcmin", "deg"))
    '"50 arcmin" or "50 deg"'
    """
    first, second = (tuple(units) + tuple(units))[:2] if units else _EXAMPLES.get(unit, (unit, unit))
    if first == second:
        return f'"{number} {first}"'
    return f'"{number} {first}" or "{number} {second}"'


def parse_quantity(text: Any, unit: str, *, field: str = "value", require_unit: bool = True,
                   examples: tuple[str, ...] | None = None) -> float:
    """Parse ``text`` (``"64 mm"``, ``"300 rpm"``) and return it in ``unit``.

    Parameters
    ----------
    text : str or float
        A number and a unit, at most 64 characters. A Python ``float``/``int`` is taken
        as already in ``unit`` (the API path).
    unit : str
        Target unit as pint spells it, e.g. ``"m"``, ``"rad/s"``, ``"N"``; ``""`` or
        ``"dimensionless"`` for a pure number.
    field : str
        Name of the field, used in error messages.
    require_unit : bool
        Refuse a string without a unit when ``unit`` is dimensional (default). With
        ``False`` a bare number in a string is taken in ``unit``.
    examples : tuple of str, optional
        Units shown in messages (default: two usual units of ``unit``).

    Returns
    -------
    float
        The magnitude in ``unit``, finite.

    Raises
    ------
    InputError
        Not a number and a unit; arithmetic or nested powers; longer than 64 characters;
        an unknown unit; a unit of another dimension; a missing unit for a dimensional
        quantity; a value that is not finite or overflows on conversion.

    Notes
    -----
    Conversion factors are pint's definitions (SI brochure, 9th ed., 2019); the number
    is read by Python's ``float`` and multiplied by the factor, and only the unit text
    is handed to pint.

    Examples
    --------
    >>> parse_quantity("64 mm", "m")
    0.064
    >>> round(parse_quantity("300 rpm", "rad/s"), 6)
    31.415927
    >>> round(parse_quantity("5 Hz", "rad/s"), 6)  # five turns per second
    31.415927
    >>> parse_quantity("3", "", field="ratio")
    3.0
    >>> parse_quantity("1450", "rad/s", field="speed")
    Traceback (most recent call last):
    ...
    chaindrive.errors.InputError: speed: give a unit, e.g. "1450 rpm" or "1450 rad/s" (got '1450')
    >>> parse_quantity("3 kg", "m", field="pitch")
    Traceback (most recent call last):
    ...
    chaindrive.errors.InputError: pitch: '3 kg' has units of [mass], expected a quantity convertible to 'm' (e.g. "3 mm" or "3 m")

    References
    ----------
    Bureau International des Poids et Mesures, *The International System of Units
    (SI)*, 9th ed., 2019 (the definitions behind pint's conversion factors).
    """
    unit = "" if unit == "dimensionless" else unit
    if isinstance(text, bool):
        raise InputError(f"{field}: expected a number with a unit, got {text!r}")
    if isinstance(text, (int, float)):
        value = float(text)
        if not math.isfinite(value):
            raise InputError(f"{field}: must be a finite number, got {text!r}")
        return value
    if not isinstance(text, str) or not text.strip():
        example = unit_example("64", unit, examples) if unit else '"3"'
        raise InputError(f"{field}: expected a number with a unit, e.g. {example}, got {text!r}")
    if len(text) > MAX_TEXT_LENGTH:
        raise InputError(f"{field}: at most {MAX_TEXT_LENGTH} characters (a number and a unit), "
                         f"got {len(text)}")
    match = _GRAMMAR.match(text)
    if match is None:
        if re.match(r"^\s*[+-]?\d+,\d", text):
            raise InputError(f"{field}: cannot read {text!r}: write the decimal point as '.', e.g. "
                             f"{unit_example(text.strip().split()[0].replace(',', '.'), unit, examples) if unit else chr(34) + '3' + chr(34)}")
        raise InputError(
            f"{field}: cannot read {text!r} as a quantity: write a number and a unit, e.g. "
            f"{unit_example('64', unit, examples) if unit else chr(34) + '3' + chr(34)} "
            "(no arithmetic, no powers of powers)"
        )
    number = match.group("number")
    magnitude = float(number)
    if not math.isfinite(magnitude):
        raise InputError(f"{field}: {number} is too large (|value| < 1.8e308), got {text!r}")
    given = normalise_unit((match.group("unit") or "").strip(), field=field, text=text)
    try:
        _, target_factor, target_dims, target_rad, target_hz = _unit_info(unit)
    except Exception as exc:  # noqa: BLE001 - a bad target is a programming error, still no traceback
        raise InputError(f"{field}: unknown target unit {unit!r} ({exc})") from None
    if not given:
        if unit and is_dimensional(unit) and require_unit:
            raise InputError(f"{field}: give a unit, e.g. {unit_example(number, unit, examples)} (got {text!r})")
        return magnitude
    try:
        _, given_factor, given_dims, given_rad, given_hz = _unit_info(given)
    except Exception as exc:  # noqa: BLE001 - pint's undefined-unit and syntax errors
        name = getattr(exc, "unit_names", None) or str(exc) or given
        name = ", ".join(name) if isinstance(name, (tuple, list)) else name
        raise InputError(f"{field}: unknown unit {name!r} in {text!r}; e.g. "
                         f"{unit_example(number, unit, examples) if unit else chr(34) + number + chr(34)}") from None
    if given_dims != target_dims:
        raise InputError(
            f"{field}: {text!r} has units of {given_dims}, expected a quantity convertible to "
            f"{unit or 'dimensionless'!r}" + (f" (e.g. {unit_example(number, unit, examples)})" if unit else "")
        )
    factor = given_factor / target_factor
    # angles: pint takes the radian as 1. Frequencies in Hz count turns per second.
    if target_hz and given_rad == 1 and not given_hz:  # '300 rpm' as a frequency: 5 Hz
        factor /= 2 * math.pi
        given_rad = 0
    elif given_hz and target_rad == 1:  # '5 Hz' as an angular speed: 5 turns per second
        factor *= 2 * math.pi
        given_rad = 1
    if given_rad > target_rad:
        raise InputError(f"{field}: {text!r} is an angle or an angular unit, expected a quantity "
                         f"convertible to {unit or 'dimensionless'!r}")
    if given_rad < target_rad:
        if not target_dims:  # a pure angle without an angle unit (e.g. '20 %')
            raise InputError(f"{field}: give an angle unit, e.g. {unit_example(number, unit, examples)} (got {text!r})")
        # '5 1/s' for an angular speed: radians or turns per second? Not guessed.
        raise InputError(f"{field}: {text!r} is ambiguous for an angular quantity (radians or turns?): "
                         f"write it with rad or rev, e.g. {unit_example(number, unit, examples)}")
    value = magnitude * factor
    if not math.isfinite(value):
        raise InputError(f"{field}: {text!r} overflows when converted to {unit or 'a number'} "
                         "(|value| < 1.8e308)")
    return value + 0.0  # -0.0 -> 0.0


def parse_speed_text(text: str, *, field: str = "speed") -> float | None:
    """The chain speed [m/s] a speed field states (``"1.2 m/s"``), or ``None`` when it states none.

    A wheel speed may be given as an angular speed (``"960 rpm"``) or as the mean chain
    speed; the readers try this first and parse an angular speed otherwise.

    Parameters
    ----------
    text : str
        The field's text.
    field : str
        Its name, for messages.

    Returns
    -------
    float or None
        The speed in m/s; ``None`` for a text that is no linear speed (an angular speed,
        a bare number, a bad text: the angular-speed parse then reports it).

    Examples
    --------
    >>> parse_speed_text("1.2 m/s"), parse_speed_text("72 m/min"), parse_speed_text("960 rpm")
    (1.2, 1.2, None)
    """
    try:
        return parse_quantity(text, "m/s", field=field)
    except InputError:
        return None


def to_si(text: Any, kind: str, *, field: str = "value", require_unit: bool = True) -> float:
    """Parse ``text`` as a quantity of ``kind`` (a key of :data:`SI_UNITS`) in SI units.

    Parameters
    ----------
    text : str or float
        A number and a unit (see :func:`parse_quantity`).
    kind : str
        A key of :data:`SI_UNITS`, e.g. ``"mass_per_length"``.
    field : str
        Name of the field, used in error messages.
    require_unit : bool
        Refuse a bare number for a dimensional kind (default).

    Returns
    -------
    float
        The magnitude in the SI unit of ``kind``.

    Examples
    --------
    >>> to_si("2.6 kg/m", "mass_per_length")
    2.6
    """
    try:
        unit = SI_UNITS[kind]
    except KeyError:
        raise InputError(f"unknown quantity kind {kind!r}; valid: {', '.join(SI_UNITS)}") from None
    return parse_quantity(text, unit, field=field, require_unit=require_unit)


# moved to chaindrive.kinematics.speed (deprecated aliases, removed in the next release):
# units is the bottom layer and parses units only; a wheel speed given as a chain speed
# needs the chain kinematics.
_MOVED = {"chain_speed_to_angular_velocity": "chaindrive.kinematics.speed",
          "parse_wheel_speed": "chaindrive.kinematics.speed"}


def __getattr__(name: str) -> Any:
    if name in _MOVED:
        import importlib

        from ._deprecation import warn_renamed

        warn_renamed(f"chaindrive.units.{name}", f"{_MOVED[name]}.{name}")
        return getattr(importlib.import_module(_MOVED[name]), name)
    raise AttributeError(f"module 'chaindrive.units' has no attribute {name!r}")
