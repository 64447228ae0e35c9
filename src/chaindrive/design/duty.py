r"""The duty of a chain drive and the factors published tables give for it.

A :class:`Duty` is what the engineer knows before choosing a chain: the power, the speed
of the driving shaft, the ratio (or the driven speed), the driving machine, the driven
machine (or its load character), the hours per day, the environment and the lubrication
available. :func:`duty_factors` turns it into the factors of the selection, each with
its source:

* the service factor ``K_s`` (driver × load character: ACA table, Shigley 9th ed.
  Table 17-15; U.S. Tsubaki, *The Complete Guide to Chain*, Table 4.2 -- the same
  values, :func:`chaindrive.loads.service_factor`), the driven machines sorted into the
  three load characters by U.S. Tsubaki's table;
* the tooth factor and the multi-strand factor belong to the rating method of each
  chain (:mod:`chaindrive.rating`) and are reported per candidate.

Nothing is defaulted silently: a duty without a driven machine, a load character or an
explicit service factor is refused with the table it would use
(:class:`~chaindrive.errors.InputError`, field ``service_factor``).
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from functools import lru_cache
from importlib import resources
from typing import Any

from .._results import Result, quantity
from ..errors import InputError, UnknownNameError
from ..limits import DUTY_RANGES
from ..loads import SERVICE_FACTORS, service_factor

__all__ = ["Duty", "Factor", "service_factor_table", "duty_factors", "service_factor_text", "service_factor_of",
           "duty_class", "design_power", "check_duty_value",
           "LOAD_CHARACTERS", "DRIVERS", "ENVIRONMENTS", "LUBRICATIONS"]

#: Load characters of the service-factor table.
LOAD_CHARACTERS = ("smooth", "moderate", "heavy")
#: Driving machines of the service-factor table.
DRIVERS = ("electric_motor", "ic_hydraulic", "ic_mechanical")
#: Environments (the rating tables assume a clean one, ISO 10823:2004 clause 4).
ENVIRONMENTS = ("clean", "dusty", "abrasive")
#: Lubrication the site can provide (ANSI regions A, B, C; ``None``: as the rating asks).
LUBRICATIONS = ("A", "B", "C")


@lru_cache(maxsize=1)
def service_factor_table() -> dict[str, Any]:
    """The published service-factor table (driving machine × load character), with its source.

    Returns
    -------
    dict
        ``source``, ``drivers``, ``characters``, ``factors[character][driver]`` (the values
        of :data:`chaindrive.loads.SERVICE_FACTORS`) and ``driven_machines[key] = [label,
        character]``.

    References
    ----------
    U.S. Tsubaki, *The Complete Guide to Chain*, Table 4.2; ACA table in Shigley's
    Mechanical Engineering Design, 9th ed., Table 17-15.

    Examples
    --------
    >>> t = service_factor_table()
    >>> t["factors"]["heavy"]["electric_motor"], t["driven_machines"]["varying_conveyor"][1]
    (1.5, 'moderate')
    """
    text = resources.files("chaindrive.design").joinpath("data", "service_factors.json").read_text("utf-8")
    data = json.loads(text)
    data["factors"] = {c: dict(SERVICE_FACTORS.get(c)) for c in LOAD_CHARACTERS}
    return data


def service_factor_text() -> str:
    """The service-factor table as text (for the message that asks for a duty class)."""
    t = service_factor_table()
    lines = [f"service factor K_s ({t['source']}):",
             "  load character   " + "  ".join(f"{d:>15}" for d in DRIVERS)]
    for c in LOAD_CHARACTERS:
        lines.append(f"  {c:<16} " + "  ".join(f"{t['factors'][c][d]:>15g}" for d in DRIVERS))
    lines.append("driven machines: " + ", ".join(f"{k} ({v[1]})" for k, v in t["driven_machines"].items()))
    return "\n".join(lines)


def check_duty_value(name: str, value: float | None) -> None:
    """Refuse a duty value outside its range of :data:`chaindrive.limits.DUTY_RANGES` (``None``: not given).

    Raises
    ------
    InputError
        Not a finite number in the range (field ``name``).
    UnknownNameError
        ``name`` is not a duty value of :data:`~chaindrive.limits.DUTY_RANGES`.

    Examples
    --------
    >>> check_duty_value("hours_per_day", 8.0)
    >>> check_duty_value("hours_per_day", 25.0)
    Traceback (most recent call last):
    ...
    chaindrive.errors.InputError: hours_per_day must be a finite number in (0, 24] h, got 25.0
    """
    if name not in DUTY_RANGES:
        raise UnknownNameError(f"no duty value {name!r}; valid: {', '.join(DUTY_RANGES)}")
    if value is None:
        return
    low, high, unit = DUTY_RANGES[name]
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) \
            or not low < value <= high:
        where = f"({low:g}, {high:g}] {unit}".rstrip()
        raise InputError(f"{name} must be a finite number in {where}, got {value!r}", field=name)


@dataclass(frozen=True)
class Factor(Result):
    """One factor of the design procedure, with its value and source."""

    name: str
    symbol: str
    value: float = quantity("1")
    source: str = ""
    note: str = ""


@dataclass(frozen=True)
class Duty(Result):
    """What the drive must do (SI units).

    Parameters
    ----------
    power : float
        Transmitted power ``P > 0`` [W] (before the service factor).
    speed : float
        Speed of the driving shaft [rad/s].
    ratio : float, optional
        ``n_driving / n_driven >= 1``; or give ``driven_speed``.
    driven_speed : float, optional
        Speed of the driven shaft [rad/s].
    driver : str
        ``"electric_motor"`` (or turbine), ``"ic_hydraulic"``, ``"ic_mechanical"``.
    driven_machine : str, optional
        A key of the driven-machine table (:func:`service_factor_table`), e.g.
        ``"varying_conveyor"``.
    load_character : str, optional
        ``"smooth"``, ``"moderate"`` or ``"heavy"`` (instead of a driven machine).
    service_factor : float, optional
        An explicit ``K_s >= 1`` (overrides the table).
    hours_per_day : float
        Operating hours per day (0, 24].
    centre_distance : float, optional
        Wanted centre distance [m] (default 40 pitches of each chain, ISO 10823: 30-50).
    environment : str
        ``"clean"``, ``"dusty"`` or ``"abrasive"``.
    lubrication : str, optional
        The best lubrication the site provides: ``"A"`` (manual/drip), ``"B"`` (bath or
        disc), ``"C"`` (oil stream); ``None``: whatever the rating asks.

    Examples
    --------
    >>> d = Duty(11e3, 1460 * math.pi / 30, driven_speed=480 * math.pi / 30,
    ...          driven_machine="varying_conveyor")
    >>> round(d.speed_ratio, 3), d.character
    (3.042, 'moderate')
    """

    power: float = quantity("W")
    speed: float = quantity("rad/s", display="rpm")
    ratio: float | None = quantity("1", default=None)
    driven_speed: float | None = quantity("rad/s", display="rpm", default=None)
    driver: str = "electric_motor"
    driven_machine: str | None = None
    load_character: str | None = None
    service_factor: float | None = quantity("1", default=None)
    hours_per_day: float = quantity("h", default=8.0)
    centre_distance: float | None = quantity("m", display="mm", default=None)
    environment: str = "clean"
    lubrication: str | None = None

    def __post_init__(self) -> None:
        for name in ("power", "speed", "ratio", "driven_speed", "hours_per_day", "centre_distance", "service_factor"):
            check_duty_value(name, getattr(self, name))
        if self.service_factor is not None and self.service_factor < 1:
            raise InputError(f"service_factor must be >= 1, got {self.service_factor:g}", field="service_factor")
        if (self.ratio is None) == (self.driven_speed is None):
            raise InputError("give exactly one of ratio and driven_speed", field="ratio")
        if self.speed_ratio < 1:
            raise InputError(f"the drive must reduce the speed: ratio n_driving / n_driven must be >= 1, "
                             f"got {self.speed_ratio:.4g}", field="ratio" if self.ratio is not None else "driven_speed")
        _check_duty_class(self.driver, self.driven_machine, self.load_character)
        if self.environment not in ENVIRONMENTS:
            raise InputError(f"unknown environment {self.environment!r}; valid: {', '.join(ENVIRONMENTS)}",
                             field="environment")
        if self.lubrication is not None and self.lubrication not in LUBRICATIONS:
            raise InputError(f"unknown lubrication {self.lubrication!r}; valid: {', '.join(LUBRICATIONS)} "
                             "(A manual/drip, B bath/disc, C oil stream)", field="lubrication")

    @property
    def speed_ratio(self) -> float:
        """``n_driving / n_driven`` [-]."""
        if self.ratio is not None:
            return float(self.ratio)
        assert self.driven_speed is not None
        return float(self.speed / self.driven_speed)

    @property
    def character(self) -> str | None:
        """The load character: given, or that of the driven machine (``None``: neither)."""
        return duty_class(self.driven_machine, self.load_character)


def duty_class(driven_machine: str | None, load_character: str | None = None) -> str | None:
    """The load character of a duty: ``load_character`` when given, else the driven machine's
    (U.S. Tsubaki's table, :func:`service_factor_table`); ``None``: neither.

    Raises
    ------
    InputError
        Unknown driven machine or load character (the field named).

    Examples
    --------
    >>> duty_class("varying_conveyor"), duty_class("varying_conveyor", "heavy"), duty_class(None)
    ('moderate', 'heavy', None)
    """
    _check_duty_class(DRIVERS[0], driven_machine, load_character)
    if load_character is not None:
        return load_character
    if driven_machine is not None:
        return str(service_factor_table()["driven_machines"][driven_machine][1])
    return None


def duty_factors(duty: Duty) -> tuple[Factor, ...]:
    """The service factor of ``duty`` with its source (more factors come per candidate).

    Raises
    ------
    InputError
        Neither an explicit service factor, a driven machine nor a load character: the
        message holds the table (field ``service_factor``).

    Examples
    --------
    >>> d = Duty(11e3, 152.9, ratio=3.0, driven_machine="varying_conveyor")
    >>> [(f.symbol, f.value) for f in duty_factors(d)]
    [('K_s', 1.3)]
    """
    return (service_factor_of(duty.driver, driven_machine=duty.driven_machine, load_character=duty.load_character,
                              given=duty.service_factor),)


def service_factor_of(driver: str, *, driven_machine: str | None = None, load_character: str | None = None,
                      given: float | None = None) -> Factor:
    """The service factor ``K_s`` of a driving machine and a duty class, with its source: ``given``
    when given, else the table's value for the load character (given, or the driven machine's).

    Every door takes ``K_s`` from here (the design procedure, the studio), never from the table itself.

    Raises
    ------
    InputError
        Unknown driver, driven machine or load character (each naming its field); no duty class
        (field ``service_factor``, the table in the message).

    Examples
    --------
    >>> f = service_factor_of("electric_motor", driven_machine="varying_conveyor")
    >>> f.value, f.note.split(" -> ")[1]
    (1.3, 'moderate, Electric motor or turbine')
    >>> service_factor_of("ic_mechanical", load_character="heavy").value
    1.7
    """
    table = service_factor_table()
    _check_duty_class(driver, driven_machine, load_character)
    if given is not None:
        check_duty_value("service_factor", given)
        if given < 1:
            raise InputError(f"service_factor must be >= 1, got {given:g}", field="service_factor")
        return Factor("service factor", "K_s", float(given), "given by the user")
    character = duty_class(driven_machine, load_character)
    if character is None:
        raise InputError("no duty class: give the driven machine or the load character (smooth, moderate, "
                         "heavy) or an explicit service factor; the table used:\n" + service_factor_text(),
                         field="service_factor")
    what = (f"{table['driven_machines'][driven_machine][0]} -> {character}"
            if driven_machine is not None and load_character is None else character)
    return Factor("service factor", "K_s", service_factor(character, driver), table["source"],
                  note=f"{what}, {table['drivers'][driver]}")


def _check_duty_class(driver: str, driven_machine: str | None, load_character: str | None) -> None:
    """Refuse an unknown driver, driven machine or load character (each naming its field)."""
    if driver not in DRIVERS:
        raise InputError(f"unknown driver {driver!r}; valid: {', '.join(DRIVERS)}", field="driver")
    if driven_machine is not None and driven_machine not in service_factor_table()["driven_machines"]:
        raise InputError(f"unknown driven machine {driven_machine!r}; valid: "
                         f"{', '.join(service_factor_table()['driven_machines'])}", field="driven_machine")
    if load_character is not None and load_character not in LOAD_CHARACTERS:
        raise InputError(f"unknown load character {load_character!r}; valid: "
                         f"{', '.join(LOAD_CHARACTERS)}", field="load_character")


def design_power(power: float, factor: Factor) -> float:
    """The design power ``K_s P`` [W] (the power the chain's rating must carry).

    References
    ----------
    Shigley's Mechanical Engineering Design, 9th ed., Sec. 17-5 (roller chain selection: the
    nominal power times the service factor ``K_s`` and the design factor ``n_d``; here
    ``n_d = 1``, a design factor belongs to the required static safety); U.S. Tsubaki,
    *The Complete Guide to Chain*, Sec. 4.2 (corrected power = power x service factor).

    Examples
    --------
    >>> design_power(11e3, Factor("service factor", "K_s", 1.3))
    14300.0
    """
    return float(power) * float(factor.value)


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
