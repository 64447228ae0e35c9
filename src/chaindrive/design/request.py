r"""The one question every door asks the design layer: a :class:`DesignRequest`.

A request is the duty (:class:`~chaindrive.design.duty.Duty`: power, speeds or ratio, driving
machine, duty class or service factor, hours, centre distance, environment, lubrication) and
the constraints of the selection (small-sprocket teeth, chain family, strand counts, rating
method, required static safety, how many candidates). :func:`chaindrive.design.design_drive`
takes it; the Python API, ``chaindrive select``, the design studio and studies build one, so
that one duty gives one answer at every door.

A request is immutable and refuses a bad value when it is built
(:class:`~chaindrive.errors.InputError` whose ``field`` is the request's field name, the name
the studio's form and ``select``'s options map back to); every bound comes from
:mod:`chaindrive.limits`.

Examples
--------
>>> import math
>>> r = DesignRequest.of(power=11e3, speed=1460 * math.pi / 30, driven_speed=480 * math.pi / 30,
...                      driven_machine="varying_conveyor", centre_distance=0.6, strands=(1, 2))
>>> r.duty.character, r.strands
('moderate', (1, 2))
>>> DesignRequest.of(power=11e3, speed=150.0, ratio=3.0, service_factor=1.3, teeth_driving=2)
Traceback (most recent call last):
...
chaindrive.errors.InputError: teeth_driving must be a whole number in [3, 10000], got 2
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from typing import Any

from .._results import Result, quantity
from ..errors import InputError
from ..limits import DUTY_RANGES, MAX_RATED_STRANDS, MAX_TEETH, MIN_TEETH, check_size
from .duty import Duty
from .policy import default_centre_distance

__all__ = ["DesignRequest", "FAMILIES", "DUTY_FIELDS", "OPTION_FIELDS"]

#: Roller-chain families the procedure selects from (``None``: both).
FAMILIES = ("ansi", "iso606")
#: The request's fields that belong to the duty (:class:`~chaindrive.design.duty.Duty`).
DUTY_FIELDS = tuple(f.name for f in dataclasses.fields(Duty))
#: The request's constraints of the selection.
OPTION_FIELDS = ("teeth_driving", "family", "strands", "method", "required_static_safety", "all_sizes", "limit",
                 "centre_distance_range")


@dataclass(frozen=True)
class DesignRequest(Result):
    """A duty and the constraints of the selection (SI units), checked when built.

    :func:`~chaindrive.design.design_drive` reads nothing else; a door (the API, ``select``, the
    studio, a study) only maps its inputs to these fields.

    Parameters
    ----------
    duty : Duty
        What the drive must do.
    teeth_driving : int, optional
        Small-sprocket teeth, ``MIN_TEETH <= z <= MAX_TEETH`` (:mod:`chaindrive.limits`);
        default the tooth-count policy per chain (:mod:`chaindrive.design.policy`).
    family : {None, "ansi", "iso606"}
        Catalogue family (``None``: both; an ANSI chain and its ISO 606 twin are one row).
    strands : tuple of int
        Strand counts admitted, each in ``1 ... MAX_RATED_STRANDS``.
    method : str, optional
        Rating method for every chain (default: the method of each chain's family).
    required_static_safety : float, optional
        Required static safety ``[s] >= 1`` (default: the drive's, Chernavsky et al. Table 7.19).
    all_sizes : bool
        Every adequate chain, not only the smallest adequate pitch per series and strands.
    limit : int, optional
        At most this many candidates (``>= 1``).
    centre_distance_range : (float, float), optional
        Bounds ``(low, high)`` [m] of the centre distance when the duty wants none: each chain is
        laid out at :data:`~chaindrive.design.policy.DEFAULT_CENTRE_PITCHES` pitches moved into
        the bounds (:meth:`wanted_centre`); ``0 <= low <= high <=`` the duty's largest centre distance.

    Raises
    ------
    InputError
        A value outside its range; ``field`` is the request's field name.
    UnknownNameError
        Unknown family or rating method.
    """

    duty: Duty
    teeth_driving: int | None = quantity("1", default=None)
    family: str | None = None
    strands: tuple[int, ...] = quantity("1", default=(1, 2, 3))
    method: str | None = None
    required_static_safety: float | None = quantity("1", default=None)
    all_sizes: bool = False
    limit: int | None = quantity("1", default=None)
    centre_distance_range: tuple[float, float] | None = quantity("m", display="mm", default=None)

    def __post_init__(self) -> None:
        if not isinstance(self.duty, Duty):
            raise InputError(f"duty must be a chaindrive.design.Duty, got {type(self.duty).__name__}", field="duty")
        if self.teeth_driving is not None:
            object.__setattr__(self, "teeth_driving", check_size("teeth_driving", self.teeth_driving, MAX_TEETH,
                                                                 minimum=MIN_TEETH, field="teeth_driving"))
        from ..chains import check_roller_family

        check_roller_family(self.family)
        if self.method is not None:
            from ..rating import RATING_METHODS

            RATING_METHODS.get(self.method)
        strands = tuple(self.strands) if isinstance(self.strands, (tuple, list)) else ()
        if not strands or any(isinstance(k, bool) or k not in range(1, MAX_RATED_STRANDS + 1) for k in strands):
            raise InputError(f"strands must be a non-empty selection of whole numbers in [1, {MAX_RATED_STRANDS}], "
                             f"got {self.strands!r}", field="strands")
        object.__setattr__(self, "strands", strands)
        s = self.required_static_safety
        high = DUTY_RANGES["required_static_safety"][1]
        if s is not None and (isinstance(s, bool) or not isinstance(s, (int, float)) or not math.isfinite(s)
                              or not 1 <= s <= high):
            raise InputError(f"required_static_safety must be a number in [1, {high:g}], got {s!r}",
                             field="required_static_safety")
        if not isinstance(self.all_sizes, bool):
            raise InputError(f"all_sizes must be True or False, got {self.all_sizes!r}", field="all_sizes")
        if self.limit is not None:
            object.__setattr__(self, "limit", check_size("limit", self.limit, 10**6, field="limit"))
        if self.centre_distance_range is not None:
            object.__setattr__(self, "centre_distance_range", _centre_range(self.centre_distance_range,
                                                                             self.duty.centre_distance))

    def wanted_centre(self, pitch: float) -> float:
        """The centre distance [m] a chain of ``pitch`` [m] is laid out at: the duty's, else
        :data:`~chaindrive.design.policy.DEFAULT_CENTRE_PITCHES` pitches (ISO 10823: 30-50)
        moved into :attr:`centre_distance_range`.

        Examples
        --------
        >>> r = DesignRequest.of(power=5e3, speed=100.0, ratio=2.0, load_character="smooth",
        ...                      centre_distance_range=(0.3, 0.45))
        >>> r.wanted_centre(0.0127), r.wanted_centre(0.00635)
        (0.45, 0.3)
        """
        if self.duty.centre_distance is not None:
            return float(self.duty.centre_distance)
        a = default_centre_distance(pitch)
        if self.centre_distance_range is None:
            return a
        low, high = self.centre_distance_range
        return min(max(a, low), high)

    @classmethod
    def of(cls, **values: Any) -> DesignRequest:
        """A request from flat keyword values: the duty's fields (:data:`DUTY_FIELDS`) and the
        constraints (:data:`OPTION_FIELDS`); an unknown name is refused (field named).

        Examples
        --------
        >>> DesignRequest.of(power=5e3, speed=100.0, ratio=2.0, load_character="smooth").duty.power
        5000.0
        >>> DesignRequest.of(power=5e3, speed=100.0, ratio=2.0, colour="red")
        Traceback (most recent call last):
        ...
        chaindrive.errors.InputError: unknown design request field 'colour'; valid: power, speed, ratio, driven_speed, driver, driven_machine, load_character, service_factor, hours_per_day, centre_distance, environment, lubrication, teeth_driving, family, strands, method, required_static_safety, all_sizes, limit, centre_distance_range
        """
        unknown = [k for k in values if k not in DUTY_FIELDS and k not in OPTION_FIELDS]
        if unknown:
            raise InputError(f"unknown design request field {unknown[0]!r}; valid: "
                             f"{', '.join((*DUTY_FIELDS, *OPTION_FIELDS))}", field=unknown[0])
        duty = Duty(**{k: v for k, v in values.items() if k in DUTY_FIELDS})
        return cls(duty, **{k: v for k, v in values.items() if k in OPTION_FIELDS})


def _centre_range(bounds: Any, wanted: float | None) -> tuple[float, float]:
    """``(low, high)`` [m] checked: two finite numbers, ``0 <= low <= high <=`` the largest centre distance."""
    high_max = DUTY_RANGES["centre_distance"][1]
    try:
        low, high = (float(b) for b in bounds)
    except (TypeError, ValueError):
        low = high = math.nan
    if not (math.isfinite(low) and math.isfinite(high) and 0 <= low <= high <= high_max):
        raise InputError(f"centre_distance_range must be (low, high) in m with 0 <= low <= high <= {high_max:g} m, "
                         f"got {bounds!r}", field="centre_distance_range")
    if wanted is not None:
        raise InputError("give the centre distance or its bounds (centre_distance_range), not both",
                         field="centre_distance_range")
    return low, high


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
