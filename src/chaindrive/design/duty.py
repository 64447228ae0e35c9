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
from ..errors import InputError
from ..loads import SERVICE_FACTORS, service_factor

__all__ = ["Duty", "Factor", "service_factor_table", "duty_factors", "service_factor_text",
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
        def positive(name: str, value: float | None, unit: str, upper: float = math.inf) -> None:
            if value is None:
                return
            if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) \
                    or not 0 < value <= upper:
                where = f"(0, {upper:g}] {unit}".rstrip()
                raise InputError(f"{name} must be a finite number in {where}, got {value!r}", field=name)

        positive("power", self.power, "W", 1e8)
        positive("speed", self.speed, "rad/s", 1e4)
        positive("ratio", self.ratio, "", 20.0)
        positive("driven_speed", self.driven_speed, "rad/s", 1e4)
        positive("hours_per_day", self.hours_per_day, "h", 24.0)
        positive("centre_distance", self.centre_distance, "m", 50.0)
        positive("service_factor", self.service_factor, "", 5.0)
        if self.service_factor is not None and self.service_factor < 1:
            raise InputError(f"service_factor must be >= 1, got {self.service_factor:g}", field="service_factor")
        if (self.ratio is None) == (self.driven_speed is None):
            raise InputError("give exactly one of ratio and driven_speed", field="ratio")
        if self.speed_ratio < 1:
            raise InputError(f"the drive must reduce the speed: ratio n_driving / n_driven must be >= 1, "
                             f"got {self.speed_ratio:.4g}", field="ratio" if self.ratio is not None else "driven_speed")
        if self.driver not in DRIVERS:
            raise InputError(f"unknown driver {self.driver!r}; valid: {', '.join(DRIVERS)}", field="driver")
        table = service_factor_table()
        if self.driven_machine is not None and self.driven_machine not in table["driven_machines"]:
            raise InputError(f"unknown driven machine {self.driven_machine!r}; valid: "
                             f"{', '.join(table['driven_machines'])}", field="driven_machine")
        if self.load_character is not None and self.load_character not in LOAD_CHARACTERS:
            raise InputError(f"unknown load character {self.load_character!r}; valid: "
                             f"{', '.join(LOAD_CHARACTERS)}", field="load_character")
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
        if self.load_character is not None:
            return self.load_character
        if self.driven_machine is not None:
            return str(service_factor_table()["driven_machines"][self.driven_machine][1])
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
    table = service_factor_table()
    if duty.service_factor is not None:
        return (Factor("service factor", "K_s", float(duty.service_factor), "given by the user"),)
    character = duty.character
    if character is None:
        raise InputError("no duty class: give the driven machine or the load character (smooth, moderate, "
                         "heavy) or an explicit service factor; the table used:\n" + service_factor_text(),
                         field="service_factor")
    what = (f"{table['driven_machines'][duty.driven_machine][0]} -> {character}"
            if duty.driven_machine is not None and duty.load_character is None else character)
    return (Factor("service factor", "K_s", service_factor(character, duty.driver), table["source"],
                   note=f"{what}, {table['drivers'][duty.driver]}"),)


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
