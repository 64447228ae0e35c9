"""Upper bounds of size-like inputs and the plausible ranges of physical inputs.

Every size-like input (samples, grid sizes, teeth, links, simulated time, number of
modes, animation frames) has a maximum here; the public functions that take one check it
with :func:`check_size` before anything is allocated, so the command line, project
files, the web page and studies all inherit the same bounds. The maxima are far above
any real drive and far below what would exhaust memory or time on a laptop:

==================  ===========  ===================================================
name                maximum      why
==================  ===========  ===================================================
MAX_POINTS          1 000 000    samples per period; 1e6 takes about 0.5 s
MAX_TEETH           10 000       teeth or pockets of a wheel (ISO 606 tables: 150)
MAX_LINKS           10 000       links of a chain loop (a 250 m conveyor at 25 mm)
MAX_DURATION        60 s         simulated time of the dynamic simulation
MAX_MODES           100          natural frequencies asked for
MAX_GRID            1 000        points per axis of a speed sweep or resonance map
MAX_FRAMES          1 000        frames of an animation
MAX_STRANDS         100          rows of a multi-row chain (ISO 606: up to 3)
MAX_SOLID_TEETH     150          teeth of a 3-D solid (STEP); ISO 606 Annex A ends at
                                 150, and OpenCascade takes minutes beyond
MAX_CAD_PARTS       20 000       parts (solids) of a drive's 3-D assembly: links x
                                 parts per link + wheels (a 2,000-link roller chain)
MAX_PRIMITIVES      200 000      lines and arcs of one outline (20 per tooth)
MAX_ARC_POINTS      10 000       points per arc when an outline is sampled
==================  ===========  ===================================================

The ranges of a duty (:class:`chaindrive.design.Duty`, :class:`chaindrive.design.DesignRequest`,
the studio's form, ``chaindrive select``) are here too, so that every door refuses the same
values with the same words (:data:`DUTY_RANGES`).

:func:`warn_implausible` warns (:class:`~chaindrive.errors.ValidityRangeWarning`, never
raises) when a value typed at the boundary is physically implausible: a chain faster
than any chain runs, a power below 1 W, and so on (:data:`PLAUSIBLE`). These are
warnings because an unusual design may be meant; a value beyond a maximum above is an
error because it would only burn time or memory.
"""

from __future__ import annotations

import math
import numbers
import warnings

from .errors import InputError, ValidityRangeWarning
from .units import RAD_S_PER_RPM, rpm_to_angular_velocity

__all__ = [
    "MAX_POINTS",
    "MAX_TEETH",
    "MAX_LINKS",
    "MAX_DURATION",
    "MAX_MODES",
    "MAX_GRID",
    "MAX_FRAMES",
    "MAX_STRANDS",
    "MAX_SOLID_TEETH",
    "MAX_CAD_PARTS",
    "MAX_PRIMITIVES",
    "MAX_ARC_POINTS",
    "MIN_TEETH",
    "MAX_SPEED",
    "MAX_RATED_STRANDS",
    "DUTY_RANGES",
    "FORM_RANGES",
    "PLAUSIBLE",
    "check_size",
    "check_duration",
    "check_links_needed",
    "warn_implausible",
]

#: Samples over one period (kinematics, crawler drive).
MAX_POINTS = 1_000_000
#: Teeth or pockets of one wheel.
MAX_TEETH = 10_000
#: Links of one chain loop (simulation, layout).
MAX_LINKS = 10_000
#: Simulated time of one dynamic simulation [s].
MAX_DURATION = 60.0
#: Natural frequencies asked for at once.
MAX_MODES = 100
#: Points per axis of a sweep or map (speeds, masses, stiffnesses).
MAX_GRID = 1_000
#: Frames of one animation.
MAX_FRAMES = 1_000
#: Rows of a multi-row chain (a pin model with one beam element per row and plate).
MAX_STRANDS = 100
#: Teeth or pockets of a wheel built as a 3-D solid (STEP): ISO 606 Annex A ends at 150,
#: and an OpenCascade solid of 150 teeth already takes minutes.
MAX_SOLID_TEETH = 150
#: Parts (solids) of a drive's 3-D assembly (STEP, glTF): the links times their parts
#: (7 for a simplex roller chain, 1 for a round link chain) plus wheels, guides and the
#: tensioner. 20,000 is a 2,800-link roller chain; STEP writes it in seconds (each
#: distinct solid once, the rest placed copies) but a CAD system's re-import takes minutes.
MAX_CAD_PARTS = 20_000
#: Lines and arcs of one outline (drawings, DXF, SVG): 20 per tooth at MAX_TEETH.
MAX_PRIMITIVES = 20 * MAX_TEETH
#: Points per arc when an outline is sampled into a polyline.
MAX_ARC_POINTS = 10_000

#: Fewest teeth or pockets of one wheel (a pocket wheel of a mining conveyor: 3 and more).
MIN_TEETH = 3
#: Fastest wheel speed a door accepts [rad/s] (about 95,000 rpm; chains run below 10,000 rpm).
MAX_SPEED = 1e4
#: Most strands of a chain the rating methods cover (ANSI multi-strand factor, ISO 10823: up to 4).
MAX_RATED_STRANDS = 4

#: Ranges of a duty: name -> (low, high, SI unit); ``low`` is excluded, ``high`` included.
#: The ratio ``n_driving / n_driven`` of a drive may lie below 1 (a speed-increasing drive of a
#: given chain, the studio); the design procedure asks for a speed-reducing one (ratio >= 1).
DUTY_RANGES: dict[str, tuple[float, float, str]] = {
    "power": (0.0, 1e8, "W"),
    "speed": (0.0, MAX_SPEED, "rad/s"),
    "driven_speed": (0.0, MAX_SPEED, "rad/s"),
    "ratio": (0.0, 20.0, ""),
    "hours_per_day": (0.0, 24.0, "h"),
    "centre_distance": (0.0, 50.0, "m"),
    "service_factor": (0.0, 5.0, ""),
    "required_static_safety": (0.0, 50.0, ""),
}

#: Ranges of the studio form's drive fields that the project schema leaves open above (or that
#: only the form has): name -> (low, high, SI unit; ``""`` a pure number). Far above any real
#: drive; a form value beyond them is refused with the range (a project file may go further,
#: where the schema allows).
FORM_RANGES: dict[str, tuple[float, float, str]] = {
    "idler_position": (0.05, 0.95, ""),      # fraction of the slack span from its start
    "idler_offset": (0.0, 10.0, "m"),         # push of the idler into the span
    "tensioner_mass": (0.0, 1e5, "kg"),
    "tensioner_stiffness": (0.0, 1e10, "N/m"),
    "tensioner_force": (0.0, 1e7, "N"),
    "tensioner_arm_length": (0.0, 10.0, "m"),
    "tensioner_arm_mass": (0.0, 1e5, "kg"),
    "tensioner_wheel_mass": (0.0, 1e5, "kg"),
    "tensioner_carriage_mass": (0.0, 1e5, "kg"),
    "tensioner_spring_stiffness": (0.0, 1e10, "N/m"),
    "tensioner_spring_lever": (0.0, 10.0, "m"),
    "tensioner_spring_angle": (0.0, 1.5, "rad"),
    "guide_end": (0.0, 10.0, "m"),
    "skew": (0.0, 0.2, "rad"),
    "wear_coefficient": (0.0, 1e-10, "m**2/N"),
}

#: Plausible range of a value typed at the boundary, by kind:
#: (low, high, SI unit, display factor, display unit, why). Outside: a warning.
PLAUSIBLE: dict[str, tuple[float, float, str, float, str, str]] = {
    "angular_velocity": (1e-3, rpm_to_angular_velocity(10_000), "rad/s", 1 / RAD_S_PER_RPM, "rpm",
                         "chain drives run between about 0.01 rpm and 10 000 rpm"),
    "chain_speed": (1e-4, 40.0, "m/s", 1.0, "m/s",
                    "no chain runs faster than about 40 m/s; scraper conveyors run at 0.5-2 m/s"),
    "power": (1.0, 10e6, "W", 1e-3, "kW", "chain drives transmit between about 1 W and 10 MW"),
    "pitch": (3e-3, 0.5, "m", 1e3, "mm",
              "chain pitches lie between about 3 mm (ISO 606 03C: 4.76 mm) and 500 mm (track chains)"),
    "force": (0.0, 20e6, "N", 1e-3, "kN",
              "the strongest chains (DIN 22252 60 mm bar) break at about 5 MN"),
}


def check_size(name: str, value: float, maximum: int, minimum: int = 1, *, field: str | None = None) -> int:
    """Return ``value`` as an ``int`` after checking ``minimum <= value <= maximum``.

    Parameters
    ----------
    name : str
        Parameter name for the message.
    value : int
        A whole number (a ``float`` with an integral value is accepted).
    maximum : int
        Largest value accepted (one of the ``MAX_*`` constants).
    minimum : int
        Smallest value accepted.
    field : str, optional
        The input the error names (:attr:`~chaindrive.errors.ChainDriveError.field`).

    Returns
    -------
    int
        The value.

    Raises
    ------
    InputError
        Not a whole number, or outside ``[minimum, maximum]``; the message names the
        parameter and the range.

    Examples
    --------
    >>> check_size("points", 361, MAX_POINTS, minimum=2)
    361
    >>> check_size("points", 10**8, MAX_POINTS, minimum=2)
    Traceback (most recent call last):
    ...
    chaindrive.errors.InputError: points must be a whole number in [2, 1000000], got 100000000
    """
    ok = isinstance(value, numbers.Integral) and not isinstance(value, bool)
    if not ok and isinstance(value, numbers.Real) and not isinstance(value, bool):
        ok = math.isfinite(value) and float(value).is_integer()
    if not ok or not minimum <= value <= maximum:
        raise InputError(f"{name} must be a whole number in [{minimum}, {maximum}], got {value!r}", field=field)
    return int(value)


def check_links_needed(needed: float, what: str = "the wheel positions") -> None:
    """Refuse a layout whose chain needs more than :data:`MAX_LINKS` links (every door:
    ``layout``, ``analyze``, ``simulate``, the web, studies).

    Parameters
    ----------
    needed : float
        Chain length the layout needs [pitches].
    what : str
        What sets it, for the message.

    Raises
    ------
    InputError
        More than :data:`MAX_LINKS` links (or not a finite number).

    Examples
    --------
    >>> check_links_needed(122.3)
    >>> check_links_needed(78740196.0)
    Traceback (most recent call last):
    ...
    chaindrive.errors.InputError: links: the chain of this layout needs 78,740,196 links; at most 10,000 (chaindrive.limits.MAX_LINKS): check the wheel positions and their units
    """
    if not (math.isfinite(needed) and needed <= MAX_LINKS):
        shown = f"{needed:,.0f}" if math.isfinite(needed) else str(needed)
        raise InputError(f"links: the chain of this layout needs {shown} links; at most {MAX_LINKS:,} "
                         f"(chaindrive.limits.MAX_LINKS): check {what} and their units", field="links")


def check_duration(name: str, value: float, maximum: float = MAX_DURATION) -> float:
    """Return ``value`` [s] after checking ``0 < value <= maximum``.

    Examples
    --------
    >>> check_duration("duration", 2.0)
    2.0
    >>> check_duration("duration", 3600.0)
    Traceback (most recent call last):
    ...
    chaindrive.errors.InputError: duration must lie in (0, 60] s, got 3600 s
    """
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise InputError(f"{name} must be a number of seconds in (0, {maximum:g}] s, got {value!r}") from None
    if not (math.isfinite(v) and 0 < v <= maximum):
        raise InputError(f"{name} must lie in (0, {maximum:g}] s, got {v:g} s")
    return v


def warn_implausible(field: str, value: float, kind: str | None, *, stacklevel: int = 3) -> bool:
    """Warn when ``value`` (SI units) lies outside the plausible range of ``kind``.

    Parameters
    ----------
    field : str
        Name of the field, for the message.
    value : float
        The value in SI units.
    kind : str or None
        A key of :data:`PLAUSIBLE`; other kinds (and ``None``) are not checked.
    stacklevel : int
        Passed to :func:`warnings.warn`.

    Returns
    -------
    bool
        True when a warning was issued.

    Examples
    --------
    >>> import warnings
    >>> with warnings.catch_warnings(record=True) as w:
    ...     warnings.simplefilter("always")
    ...     warn_implausible("speed", 1450.0, "angular_velocity")
    ...     print(w[0].message)
    True
    speed = 13846 rpm is implausible (chain drives run between about 0.01 rpm and 10 000 rpm); check the unit
    """
    if kind not in PLAUSIBLE or value is None:
        return False
    low, high, _, factor, unit, why = PLAUSIBLE[kind]
    if not value > 0 or low <= value <= high:  # zero and negative values: the range checks refuse them
        return False
    warnings.warn(f"{field} = {value * factor:.5g} {unit} is implausible ({why}); check the unit",
                  ValidityRangeWarning, stacklevel=stacklevel)
    return True
