"""A wheel placed for a requested wrap (``chaindrive layout FILE --place WHEEL --wrap ...``).

The geometry is :func:`chaindrive.layout.place_for_wrap`; this module takes a drive's
wheels, picks the line of travel (given, or straight away from the other wheels'
centroid: the way that opens the chain's angle round the wheel) and re-checks the
result with the drive's own layout.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np

from .. import layout as L
from .._results import Result, quantity
from ..drive.model import Drive
from ..errors import InputError

__all__ = ["Placement", "place_wheel"]


@dataclass(frozen=True)
class Placement(Result):
    """Where a wheel goes for a requested wrap (:func:`place_wheel`).

    Attributes
    ----------
    wheel, target : str
        The wheel moved and the wheel whose wrap is set.
    direction : ndarray
        Unit vector of the move [-] (the given line, either way).
    distance : float
        Length of the move [m], >= 0.
    position : ndarray
        The wheel's new centre [m].
    wrap : float
        Wrap on ``target`` there, re-computed [rad].
    requested : float
        [rad].
    refitted_wrap : float
        Wrap on ``target`` once the drive's links are fitted again (an adjustable wheel
        moves; links rounded to an even number) [rad].
    drive : Drive
        The drive with the wheel moved (an adjustable wheel at its setting; ``links``
        left to be fitted again).
    """

    wheel: str
    target: str
    direction: np.ndarray = quantity("1")
    distance: float = quantity("m", display="mm")
    position: np.ndarray = quantity("m", display="mm")
    wrap: float = quantity("rad")
    requested: float = quantity("rad")
    refitted_wrap: float = quantity("rad", default=0.0)
    drive: Drive | None = None


def place_wheel(drive: Drive, wheel: str, wrap: float, *, along: tuple[float, float] | None = None,
                target: str | None = None) -> Placement:
    """Move ``wheel`` along a line (the nearer way) until ``target`` (default the wheel
    itself) has ``wrap``.

    Parameters
    ----------
    drive : Drive
    wheel : str
        Name of the wheel to move.
    wrap : float
        Requested wrap [rad], ``0 < wrap < 2π``.
    along : (float, float), optional
        Line of travel; default straight away from the centroid of the other wheels.
    target : str, optional
        Wheel whose wrap is set.

    Returns
    -------
    Placement

    Raises
    ------
    InputError
        Unknown wheel (field ``wheel``), no position on the line gives the wrap with
        the wheels and spans clear (field ``wrap``).

    References
    ----------
    :func:`chaindrive.layout.place_for_wrap`.

    Examples
    --------
    >>> from chaindrive.drive.project import load_project
    >>> d = load_project("examples/multi_wheel.toml")
    >>> p = place_wheel(d, "machine B", math.radians(125))
    >>> round(math.degrees(p.wrap), 6), round(p.distance * 1e3)
    (125.0, 57)
    """
    names = list(drive.wheel_names)
    if wheel not in names:
        raise InputError(f"wheel {wheel!r} is not in the drive (wheels: {', '.join(names)})", field="wheel")
    tgt_name = wheel if target is None else target
    if tgt_name not in names:
        raise InputError(f"target {tgt_name!r} is not in the drive (wheels: {', '.join(names)})", field="target")
    i, k = names.index(wheel), names.index(tgt_name)
    from .layout import drive_layout

    # the wheels as the layout sets them (an adjustable wheel at its setting for the links)
    centres = np.array(drive_layout(drive).wrap.centres, dtype=float)
    if along is None:
        d = centres[i] - np.delete(centres, i, axis=0).mean(axis=0)
        if not float(np.hypot(*d)) > 0:
            raise InputError(f"wheel {wheel!r} sits at the centroid of the others: give the line of travel",
                             field="along")
    else:
        d = np.asarray(along, dtype=float)
    radii = drive.pitch_radii()
    sides = [w.side for w in drive.wheels]
    s = L.place_for_wrap(centres, radii, sides, i, d, float(wrap), target=k)
    d = d / float(np.hypot(*d))
    if s < 0:                     # the nearer position lies the other way along the line
        d, s = -d, -s
    at = centres[i] + s * d
    centres[i] = at
    got = float(L.wrap_layout(centres, radii, sides).wrap_angle[k])
    if abs(got - float(wrap)) > 1e-6 or L.clearance_problems(centres, radii, sides):
        raise InputError(f"placing {wheel!r} did not re-check (wrap {math.degrees(got):.4f}°)", field="wrap")
    moved = drive.with_wheel(wheel, position=(float(at[0]), float(at[1])))
    if drive.adjustable is not None and drive.adjustable.wheel != wheel:
        j = names.index(drive.adjustable.wheel)
        moved = moved.with_wheel(drive.adjustable.wheel, position=(float(centres[j][0]), float(centres[j][1])))
    moved = dataclasses.replace(moved, links=None)
    refitted = float(drive_layout(moved).wrap.wrap_angle[k])
    return Placement(wheel=wheel, target=tgt_name, direction=d, distance=float(s), position=at, wrap=got,
                     requested=float(wrap), refitted_wrap=refitted, drive=moved)
