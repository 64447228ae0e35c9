"""Layout of a drive: chain length, centre distance for whole links, wraps, spans, take-up, sag."""

from __future__ import annotations

import dataclasses
import math
import warnings
from dataclasses import dataclass

import numpy as np

from .. import layout as L
from .._finite import finite_guard
from .._results import Result, quantity
from ..drive.model import Drive
from ..errors import InfeasibleError, ValidityRangeWarning
from ..limits import check_links_needed
from ._memo import freeze, memo
from ._wheels import MINIMUM_POWER_WRAP, clearance_error, wheel_checks, wheel_teeth, wrap_advice
from .checks import Check
from .parts import Part, PartContext, register_part

__all__ = ["DriveLayout", "drive_layout", "span_inclination", "slack_span_sag", "wrap_check", "MINIMUM_WRAP"]

#: Wear elongations for which the take-up is reported [-].
TAKE_UP_ELONGATIONS = (0.01, 0.02, 0.03)


@dataclass(frozen=True)
class DriveLayout(Result):
    """Layout of a drive (see :func:`drive_layout`).

    Attributes
    ----------
    wrap : WrapLayout
        Spans and wraps on the pitch circles, wheels in chain order.
    wheel_names : tuple of str
    pitch_radii : ndarray
        [m].
    teeth_in_mesh : tuple of int or None
        Whole teeth (pockets) inside the wrap; ``None`` for toothless idlers.
    chain_length_circles : float
        Length on the pitch circles [m].
    links_required : float
        Chain length at the given positions, wraps counted in links [pitches].
    links : int
        Chain length used (given, or ``links_required`` rounded up to even).
    chain_length : float
        ``links`` × pitch [m].
    chain_mass : float or None
        [kg] (``None`` when the chain has no mass per length).
    polygon : PolygonLength or None
        Exact polygon length (two-wheel drives).
    centre_distance : float or None
        Given centre distance (two-wheel drives) [m].
    centre_distance_for_links : PolygonCentreDistance or None
        Centre distance that fits ``links`` (two-wheel drives) [m].
    tight_span, slack_span : int
        Index of the span arriving at / leaving the driving wheel.
    elongations : ndarray
        0.01, 0.02, 0.03.
    take_up : ndarray or None
        Tensioner travel (or centre-distance increase) for ``elongations`` [m].
    take_up_kind : str
    chain_speed : float
        Mean chain speed [m/s].
    angular_velocities : ndarray
        Mean angular velocity of every wheel [rad/s].
    loop : LoopLength or None
        Exact polygon length of a drive of three or more wheels
        (:func:`chaindrive.layout.chain_length_loop`); ``links`` follows from its
        ``links_max`` unless the pitch circles stood in (``loop.exact`` False).
    adjustment : LoopAdjustment or None
        The adjustable wheel's setting for ``links``; the layout is at that position.
    """

    wrap: L.WrapLayout
    wheel_names: tuple[str, ...]
    pitch_radii: np.ndarray = quantity("m")
    teeth_in_mesh: tuple[int | None, ...] = quantity("1")
    chain_length_circles: float = quantity("m", display="m")
    links_required: float = quantity("1")
    links: int = quantity("1")
    chain_length: float = quantity("m", display="m")
    chain_mass: float | None = quantity("kg")
    polygon: L.PolygonLength | None
    centre_distance: float | None = quantity("m")
    centre_distance_for_links: L.PolygonCentreDistance | None
    tight_span: int = quantity("1")
    slack_span: int = quantity("1")
    elongations: np.ndarray = quantity("1")
    take_up: np.ndarray | None = quantity("m")
    take_up_kind: str
    chain_speed: float = quantity("m/s")
    angular_velocities: np.ndarray = quantity("rad/s")
    loop: L.LoopLength | None = None
    adjustment: L.LoopAdjustment | None = None


def drive_layout(drive: Drive, *, phases: int = 8) -> DriveLayout:
    """Chain length, centre distance for whole links, wraps, spans and take-up of ``drive``.

    Two toothed wheels: the exact polygon length (:func:`chaindrive.layout.chain_length_polygon`)
    and the centre distance for the even link count. More wheels: the exact polygon length
    of the loop (:func:`chaindrive.layout.chain_length_loop`, the pitch circles with a
    warning where no polygon path exists) sets the even link count; ``links_required``
    keeps the pitch-circle length with the wraps counted in seated links. With an
    ``adjustable`` wheel, it is moved along its direction until the links fit
    (:func:`chaindrive.layout.adjust_loop`) and the layout is drawn there. Spans and
    wraps: tangents on the pitch circles (:func:`~chaindrive.layout.wrap_layout`). The
    take-up for 1, 2 and 3 % wear is the tensioner travel (with a tensioner) or the
    centre-distance increase (two wheels).

    Parameters
    ----------
    drive : Drive
    phases : int
        Relative tooth phases tried for the polygon length (two-wheel drives).

    Returns
    -------
    DriveLayout

    Warns
    -----
    ValidityRangeWarning
        A given link count shorter than the path needs (no tensioner, more than two wheels).

    References
    ----------
    docs/drive.md (chain length of the polygon, ISO 10823:2004 clause 7 approximation as
    the limiting case).

    Examples
    --------
    >>> from chaindrive.chains import get
    >>> from chaindrive.drive import Drive, Wheel, Load
    >>> d = Drive(chain=get("18x64"), speed=5.0, load=Load(power=25e3, service_factor=1.5),
    ...           wheels=[Wheel("drive", "pocket_wheel", 8, (0, 0), driving=True),
    ...                   Wheel("return", "pocket_wheel", 8, (4.0, 0))])
    >>> lay = drive_layout(d)
    >>> lay.links, round(lay.centre_distance_for_links.taut, 4)
    (142, 4.0)
    """
    lay = _geometry(drive, int(phases))
    speed = drive.chain_speed()
    if lay.chain_speed != speed:  # kept from a drive that differs only in its speed
        lay = dataclasses.replace(lay, chain_speed=speed, angular_velocities=drive.angular_velocities())
        freeze(lay.angular_velocities)
    return lay


def _geometry_key(drive: Drive, phases: int) -> tuple:
    # every field _drive_layout reads, the speed aside (drive_layout sets it)
    t = drive.tensioner
    return (drive.chain, drive.wheels, drive.links, drive.adjustable, drive.travel,
            None if t is None else (t.wheel, t.direction), phases)


@memo(maxsize=64, key=_geometry_key)
def _geometry(drive: Drive, phases: int) -> DriveLayout:
    # drive_layout; kept for reuse by the fields it reads (a drive whose load, speed or
    # tensioner stiffness changed has the same layout)
    wheels = drive.wheels
    p = drive.pitch
    radii = drive.pitch_radii()
    chain = drive.chain
    sides = [w.side for w in wheels]
    positions = np.array([w.position for w in wheels], dtype=float)
    drawn = clearance_error(drive, positions)
    links_required, polygon, loop, centre, wrap = _required_length(drive, positions, phases, drawn)
    needed = loop.links_max if loop is not None and loop.exact else links_required
    check_links_needed(needed)  # chaindrive.limits: the documented maximum at every door
    links = int(drive.links) if drive.links is not None else int(L.even_links(needed))
    adjustment = None
    if drive.adjustable is not None:
        idx = drive.wheel_index(drive.adjustable.wheel)
        adjustment = L.adjust_loop(p, positions, [w.teeth for w in wheels], links, idx, drive.adjustable.direction,
                                   sides, diameters=[w.diameter for w in wheels], bar_diameter=drive.bar_diameter,
                                   phases=phases)
        positions[idx] = adjustment.position
        clearance_error(drive, positions)
        links_required, polygon, loop, centre, wrap = _required_length(drive, positions, phases)
        needed = loop.links_max if loop is not None and loop.exact else links_required
    two = drive.is_two_wheel()
    cd = None
    z1 = z2 = 0
    if two:
        z1, z2 = wheel_teeth(wheels[0], "a two-wheel drive"), wheel_teeth(wheels[1], "a two-wheel drive")
    if links < needed - 1e-9 and drive.tensioner is None and not two:
        warnings.warn(f"links = {links} is shorter than the {needed:.2f} pitches the "
                      "layout needs", ValidityRangeWarning, stacklevel=2)
    if two:
        cd = L.centre_distance_polygon(p, z1, z2, links, bar_diameter=drive.bar_diameter, phases=phases)
    teeth_mesh = tuple(int(L.teeth_in_mesh(min(th, 2 * np.pi), w.teeth)) if w.teeth is not None else None
                       for th, w in zip(wrap.wrap_angle, wheels, strict=True))
    k = drive.driving_index
    n = len(wheels)
    elong = np.array(TAKE_UP_ELONGATIONS)
    take_up, kind = None, "none"
    if drive.tensioner is not None:
        t = drive.tensioner
        idx = drive.wheel_index(t.wheel)
        try:
            # the chain of `links` may be longer than the path: take that up first
            extra = max(0.0, (links - links_required) * p)
            take_up = L.tensioner_travel(positions, radii, sides,
                                         idx, t.direction, elong, chain_length=links * p, extra_length=extra)
            kind = f"travel of tensioner wheel {t.wheel!r}"
        except InfeasibleError as exc:
            kind = f"tensioner cannot take up the elongation: {exc}"
    elif adjustment is not None and drive.adjustable is not None and not two:
        name = drive.adjustable.wheel
        try:
            take_up = L.tensioner_travel(positions, radii, sides, adjustment.wheel, adjustment.direction, elong,
                                         chain_length=links * p)
            kind = f"further travel of the adjustable wheel {name!r} from its setting for {links} links"
        except InfeasibleError as exc:
            kind = f"the adjustable wheel {name!r} cannot take up the elongation: {exc}"
    elif cd is not None:  # a two-wheel drive
        take_up = L.centre_distance_travel(p, z1, z2, cd.taut, elong, bar_diameter=drive.bar_diameter)
        kind = f"increase of centre distance from {cd.taut * 1e3:.2f} mm ({links} links)"
    q = chain.mass_per_length
    return DriveLayout(
        wrap=wrap, wheel_names=drive.wheel_names, pitch_radii=radii, teeth_in_mesh=teeth_mesh,
        chain_length_circles=float(wrap.length), links_required=links_required, links=links,
        chain_length=links * p, chain_mass=None if q is None else float(q) * links * p,
        polygon=polygon, centre_distance=centre, centre_distance_for_links=cd,
        tight_span=(k - 1) % n if drive.travel == "ccw" else k,
        slack_span=k if drive.travel == "ccw" else (k - 1) % n,
        elongations=elong, take_up=take_up, take_up_kind=kind,
        chain_speed=drive.chain_speed(), angular_velocities=drive.angular_velocities(),
        loop=loop, adjustment=adjustment,
    )


def _required_length(drive: Drive, positions: np.ndarray, phases: int, wrap: L.WrapLayout | None = None):
    """Chain length the wheels at ``positions`` need: (links on the circles with the wraps counted in seated
    links, or the two-wheel polygon's largest; the two-wheel polygon; the loop polygon of three or more
    wheels; the two-wheel centre distance; the wrap layout on the pitch circles). ``wrap``: that wrap
    layout when the caller has it (:func:`~chaindrive.drive.clearance.clearance_error` draws it)."""
    wheels = drive.wheels
    p = drive.pitch
    if wrap is None:
        wrap = L.wrap_layout(positions, drive.pitch_radii(), [w.side for w in wheels])
    wrap_links = np.array([
        wrap.wrap_angle[i] * w.sides_per_turn(drive.chain) / (2 * np.pi)
        if w.teeth is not None else wrap.wrap_length[i] / p
        for i, w in enumerate(wheels)
    ])
    required = float(wrap.span_length.sum() / p + wrap_links.sum())
    if drive.is_two_wheel():
        z1, z2 = wheel_teeth(wheels[0], "a two-wheel drive"), wheel_teeth(wheels[1], "a two-wheel drive")
        centre = float(np.hypot(*(positions[1] - positions[0])))
        polygon = L.chain_length_polygon(p, z1, z2, centre, bar_diameter=drive.bar_diameter, phases=phases)
        return polygon.links_max, polygon, None, centre, wrap
    loop = L.chain_length_loop(p, positions, [w.teeth for w in wheels], [w.side for w in wheels],
                               diameters=[w.diameter for w in wheels], bar_diameter=drive.bar_diameter,
                               phases=phases)
    return required, None, loop, None, wrap


@finite_guard  # NaN/inf and out-of-range arguments refused (chaindrive._finite)
def span_inclination(direction: float) -> float:
    """Inclination of a span's chord above the horizontal, in (-π/2, π/2] [rad].

    Independent of the direction of travel: a span pointing at ``direction`` and one
    pointing the opposite way have the same chord.

    >>> round(span_inclination(math.radians(170)), 6) == round(math.radians(-10), 6)
    True
    """
    return math.atan(math.tan(direction)) if abs(math.cos(direction)) > 1e-12 else math.pi / 2


def slack_span_sag(drive: Drive, layout: DriveLayout, tension: float) -> float:
    """Catenary sag of the slack span at ``tension`` [m] (:func:`chaindrive.layout.catenary_sag`)."""
    j = layout.slack_span
    return float(L.catenary_sag(layout.wrap.span_length[j], span_inclination(layout.wrap.span_angle[j]),
                                tension, drive.mass_per_length))


#: Smallest wrap on the driving wheel [rad] (ISO 10823:2004 guidance: 120°; the one value
#: for every power sprocket, :data:`chaindrive.analysis._wheels.MINIMUM_POWER_WRAP`).
MINIMUM_WRAP = MINIMUM_POWER_WRAP


def wrap_check(drive: Drive, layout: DriveLayout) -> Check:
    """Wrap on the driving wheel ``>= 120°`` (ISO 10823:2004 guidance)."""
    wrap = float(layout.wrap.wrap_angle[drive.driving_index])
    return Check(name="wrap on the driving wheel", value=wrap, limit=MINIMUM_WRAP, unit="rad",
                 passed=bool(wrap >= MINIMUM_WRAP - 1e-12), source="ISO 10823:2004 guidance (at least 120°)")


# --------------------------------------------------------------------------- declared parts
def _layout_part(ctx: PartContext) -> DriveLayout:
    lay = drive_layout(ctx.drive)
    if lay.take_up is None:
        ctx.note(f"take-up: {lay.take_up_kind}")
    return lay


def _layout_checks(ctx: PartContext, lay: DriveLayout) -> list[Check]:
    driving = wrap_check(ctx.drive, lay)
    if driving.passed is False:   # where to move the driving wheel, or an idler (computed, re-checked)
        driving = dataclasses.replace(driving, note=wrap_advice(ctx.drive, np.asarray(lay.wrap.centres, float),
                                                                ctx.drive.driving_index))
    return [driving, *wheel_checks(ctx.drive, lay.wrap, lay.teeth_in_mesh)]


register_part(Part("layout", "Layout: chain length, spans, wraps, take-up", _layout_part, checks=_layout_checks,
                   order=10, section="chaindrive.workflows.sections:layout_section"))
