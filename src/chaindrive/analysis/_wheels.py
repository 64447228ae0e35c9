"""Wheel accessors shared by the analysis parts (internal)."""

from __future__ import annotations

import math

import numpy as np

from .. import layout as L
from ..drive.clearance import clearance_error
from ..drive.model import Drive, Wheel
from ..errors import InfeasibleError, InputError
from .checks import Check

__all__ = ["wheel_teeth", "wheel_checks", "clearance_error", "power_wheels", "wrap_advice", "MINIMUM_POWER_WRAP",
           "MINIMUM_POWER_TEETH_IN_MESH"]


def wheel_teeth(wheel: Wheel, purpose: str) -> int:
    """Teeth of a wheel that must have them; a toothless idler raises :class:`InputError`.

    Parameters
    ----------
    wheel : Wheel
        The wheel.
    purpose : str
        What needs the teeth, for the message (e.g. ``"the entry kinematics"``).

    Returns
    -------
    int
        Number of teeth ``z >= 3`` [-].

    Examples
    --------
    >>> wheel_teeth(Wheel("a", "sprocket", 17, (0.0, 0.0), driving=True), "the layout")
    17
    """
    if wheel.teeth is None:
        raise InputError(f"wheel {wheel.name!r}: {purpose} needs teeth (a whole number >= 3); "
                         "a toothless idler cannot take this role", field="teeth")
    return wheel.teeth


# --------------------------------------------------------------------------- every wheel
#: Least wrap of the chain on a sprocket that transmits power [rad]: 120° (ISO 10823:2004
#: guidance for the small sprocket; Diamond Chain, "What is the recommended minimum chain
#: wrap in a roller chain drive?": 120°, down to 90° only where the chain tension is
#: closely maintained, else the chain can jump teeth).
MINIMUM_POWER_WRAP = math.radians(120.0)

#: Least whole teeth (pockets) in mesh on a sprocket that transmits power [-]: the 120°
#: above on a 9-tooth sprocket, the smallest of the ANSI/ACA rating tables (ASME B29.1,
#: ACA power tables): 9 × 120/360 = 3.
MINIMUM_POWER_TEETH_IN_MESH = 3

WRAP_SOURCE = ("ISO 10823:2004 guidance; Diamond Chain, recommended minimum chain wrap (120°, 90° only with the "
               "chain tension closely maintained)")
TEETH_SOURCE = ("the 120° minimum wrap on a 9-tooth sprocket, the smallest of the ANSI/ACA rating tables "
                "(9 × 120°/360° = 3 teeth)")


def power_wheels(drive: Drive) -> list[int]:
    """Indices of the wheels that transmit power: the driving wheel, every wheel given a
    ``power_share > 0`` (without shares, the wheel that takes the power in the loads,
    :meth:`~chaindrive.drive.Drive.power_shares`, unless the load is not taken off at a
    wheel: a conveyor's pans, a track's ground), the driven wheel of a two-wheel drive, a
    conveyor's tail drive."""
    out = {drive.driving_index}
    if any(w.power_share is not None for w in drive.wheels) or (
            drive.conveyor is None and drive.track is None and drive.crawler is None):
        out.update(int(i) for i in np.nonzero(drive.power_shares() > 0)[0])
    if drive.is_two_wheel():
        out.update(range(2))
    conv = drive.conveyor
    if conv is not None and conv.head_share < 1.0:
        n = len(drive.wheels)
        out.add((drive.driving_index - 1) % n if drive.travel == "ccw" else (drive.driving_index + 1) % n)
    return sorted(out)


#: Margin over a minimum wrap that a move advised by the checks aims at [rad], so that the
#: position rounded to whole millimetres still passes.
ADVICE_MARGIN = math.radians(0.5)


def wrap_advice(drive: Drive, centres: np.ndarray, index: int, minimum: float = MINIMUM_POWER_WRAP) -> str:
    """Where to move wheel ``index`` so that its wrap reaches ``minimum``: the smallest move
    along eight directions found by :func:`chaindrive.layout.place_for_wrap` for ``minimum``
    + :data:`ADVICE_MARGIN`, the position rounded to whole millimetres and re-checked (every
    power sprocket's wrap at least ``minimum``, wheels and spans clear)."""
    radii = drive.pitch_radii()
    sides = [w.side for w in drive.wheels]
    power = power_wheels(drive)
    best = None
    for k in range(8):
        d = np.array([math.cos(k * math.pi / 4), math.sin(k * math.pi / 4)])
        try:
            s = L.place_for_wrap(centres, radii, sides, index, d, minimum + ADVICE_MARGIN, steps=40,
                                 tolerance=1e-5)
        except InputError:
            continue
        if best is not None and abs(s) >= best[0]:
            continue
        moved = centres.copy()
        moved[index] = np.round((centres[index] + s * d) * 1e3) / 1e3
        try:
            wraps = L.wrap_layout(moved, radii, sides).wrap_angle
        except InfeasibleError:
            continue
        if all(wraps[i] >= minimum for i in power) and not L.clearance_problems(moved, radii, sides):
            best = (abs(s), s * d, moved[index], float(wraps[index]))
    name = drive.wheels[index].name
    idler = _idler_advice(drive, centres, index, minimum)
    if best is None:
        return (f"no move of {name!r} within twice the drive's size gives it {math.degrees(minimum):.0f}° with "
                f"every power sprocket keeping {math.degrees(minimum):.0f}°; " + (idler or
                f"add an idler on the back of a span next to {name!r} that presses the chain round it"))
    dist, move, at, wrap = best
    return (f"move {name!r} by ({move[0] * 1e3:.0f} mm, {move[1] * 1e3:.0f} mm) to position = "
            f"[\"{at[0] * 1e3:.0f} mm\", \"{at[1] * 1e3:.0f} mm\"]: wrap {math.degrees(wrap):.1f}° there, every "
            f"power sprocket at least {math.degrees(minimum):.0f}°, wheels and spans clear (or any wrap: "
            f"`chaindrive layout FILE --place \"{name}\" --wrap \"130 deg\"`); or "
            + (idler or "add an idler on the back of a span next to it") + "; then fit the links again")


#: Teeth of the idler the advice proposes (a common idler size, e.g. the examples' take-up idler).
ADVICE_IDLER_TEETH = 17


def _idler_advice(drive: Drive, centres: np.ndarray, index: int, minimum: float) -> str:
    """An idler on the back of a span next to wheel ``index``, a third of the span from it,
    pushed into the loop until the wheel has ``minimum`` + :data:`ADVICE_MARGIN` (computed
    with :func:`chaindrive.layout.place_for_wrap`, the position rounded to whole
    millimetres and re-checked: every power sprocket at least ``minimum``, the layout
    clear); ``""`` where none is found (or the chain has no teeth-based idler size)."""
    if drive.chain.is_link_chain:
        return ""
    radii = list(drive.pitch_radii())
    sides = [float(w.side) for w in drive.wheels]
    n = len(radii)
    r_id = float(L.pitch_radius(drive.pitch, ADVICE_IDLER_TEETH))
    wrap = L.wrap_layout(centres, radii, sides)
    power = power_wheels(drive)
    best = None
    for span, near_start in (((index - 1) % n, False), (index, True)):
        a, b = np.asarray(wrap.span_start[span]), np.asarray(wrap.span_end[span])
        t = (b - a) / float(np.hypot(*(b - a)))
        outside = np.array([t[1], -t[0]])           # right of travel: outside the loop
        point = a + (b - a) * (1 / 3 if near_start else 2 / 3)
        at = span + 1                               # inserted after wheel `span`
        c2 = np.insert(centres, at, point + r_id * outside, axis=0)
        r2 = np.insert(np.asarray(radii), at, r_id)
        s2 = np.insert(np.asarray(sides), at, -1.0)
        target = index + 1 if index >= at else index
        try:
            s = L.place_for_wrap(c2, r2, s2, at, -outside, minimum + ADVICE_MARGIN, target=target,
                                 steps=40, tolerance=1e-5)
        except InputError:
            continue
        c2[at] = np.round((c2[at] - s * outside) * 1e3) / 1e3
        try:
            wraps = L.wrap_layout(c2, r2, s2).wrap_angle
        except InfeasibleError:
            continue
        shifted = [i + 1 if i >= at else i for i in power]
        if all(wraps[i] >= minimum for i in shifted) and not L.clearance_problems(c2, r2, s2) \
                and (best is None or abs(s) < best[0]):
            best = (abs(s), span, c2[at], float(wraps[target]))
    if best is None:
        return ""
    _, span, pos, got = best
    names = drive.wheel_names
    return (f"add a {ADVICE_IDLER_TEETH}-tooth idler (side = -1) on the back of the span {names[span]!r} → "
            f"{names[(span + 1) % n]!r}, listed between them, at position = [\"{pos[0] * 1e3:.0f} mm\", "
            f"\"{pos[1] * 1e3:.0f} mm\"]: wrap on {names[index]!r} {math.degrees(got):.1f}° there, every power "
            f"sprocket at least {math.degrees(minimum):.0f}°, wheels and spans clear")


def wheel_checks(drive: Drive, wrap: L.WrapLayout, teeth_in_mesh: tuple[int | None, ...]) -> list[Check]:
    """Wrap and teeth in mesh on every wheel: a power-transmitting sprocket (other than
    the driving wheel, whose wrap is :func:`chaindrive.analysis.loads.wrap_check`) against
    :data:`MINIMUM_POWER_WRAP` and every power sprocket against
    :data:`MINIMUM_POWER_TEETH_IN_MESH`, with advice where to move a failing wheel; an
    idler shown for information (no published minimum for idlers in the sources used)."""
    centres = np.asarray(wrap.centres, float)
    power = power_wheels(drive)
    roller = not drive.chain.is_link_chain
    checks: list[Check] = []
    for i, w in enumerate(drive.wheels):
        theta = float(wrap.wrap_angle[i])
        mesh = teeth_in_mesh[i]
        if i in power:
            role = "driving" if i == drive.driving_index else "driven"
            short = theta < MINIMUM_POWER_WRAP - 1e-12
            few = roller and mesh is not None and mesh < MINIMUM_POWER_TEETH_IN_MESH
            advice = wrap_advice(drive, centres, i) if short or few else ""
            if i != drive.driving_index:
                checks.append(Check(f"wrap on {role} wheel {w.name!r}", theta, MINIMUM_POWER_WRAP, "rad",
                                    not short, WRAP_SOURCE, note=advice if short else ""))
            if mesh is not None and roller:
                checks.append(Check(f"teeth in mesh on {role} wheel {w.name!r}", float(mesh),
                                    float(MINIMUM_POWER_TEETH_IN_MESH), "-", not few, TEETH_SOURCE,
                                    note=advice if few else ""))
            elif mesh is not None:
                checks.append(Check(f"pockets in mesh on {role} wheel {w.name!r}", float(mesh), None, "-", None,
                                    "whole pockets inside the wrap (chaindrive.layout.teeth_in_mesh)",
                                    note="a round link chain: the 3-teeth rule of the roller chain tables does "
                                         "not apply; no published minimum in the sources used", relation="info"))
        else:
            what = "idler" if w.kind == "idler" else "idle wheel"
            note = (f"transmits no power: the sources used (ISO 10823, Diamond Chain) give no minimum wrap for it; "
                    f"{mesh if mesh is not None else 'no'} teeth in mesh")
            if mesh == 0:
                note += " (the chain only touches it: it guides nothing)"
            checks.append(Check(f"wrap on {what} {w.name!r}", theta, None, "rad", None, WRAP_SOURCE, note=note,
                                relation="info"))
    return checks
