"""Wheels that cannot be where they are drawn: overlapping pitch circles, a span through a
wheel (the rule of the drive itself, checked where a project file is read, with its
line, and by the layout on the positions it draws)."""

from __future__ import annotations

import numpy as np

from .. import layout as L
from .._validation import as_float_array
from ..errors import InputError
from .model import Drive

__all__ = ["clearance_error"]


def clearance_error(drive: Drive, centres: np.ndarray) -> L.WrapLayout | None:
    """Refuse overlapping wheels (coincident centres included) and spans crossing a wheel,
    naming the wheels (:func:`chaindrive.layout.clearance_problems`).

    Parameters
    ----------
    drive : Drive
    centres : ndarray, shape (n, 2)
        Where the wheels are [m] (as drawn, or as the layout sets an adjustable wheel).

    Returns
    -------
    WrapLayout or None
        The chain path on the pitch circles the check drew (:func:`chaindrive.layout.wrap_layout`
        of ``centres``, the drive's pitch radii and sides), for reuse; ``None`` where there is none.

    Raises
    ------
    InputError
        Field ``wheels[i].position`` of the wheel to move.

    References
    ----------
    Plane geometry (:func:`chaindrive.layout.clearance_problems`).

    Examples
    --------
    >>> from chaindrive.drive.project import load_project
    >>> d = load_project("examples/multi_wheel.toml")
    >>> c = np.array([w.position for w in d.wheels]); c[3] = (1.15, -0.05)
    >>> clearance_error(d, c)
    Traceback (most recent call last):
    ...
    chaindrive.errors.InputError: wheels 'machine A' and 'machine B' overlap: centres 150.0 mm apart, pitch radii 153.8 + 121.5 = 275.3 mm; move 'machine B' so that the centres are at least 275.3 mm apart (the sum of the pitch radii)
    """
    from ..layout.placement import _clearance

    radii = drive.pitch_radii()
    centres = as_float_array("centres", centres)
    if centres.shape != (len(radii), 2) or not np.isfinite(centres).all():
        raise InputError(f"centres must have shape ({len(radii)}, 2): a point [m] for each of the drive's "
                         f"{len(radii)} wheels, finite, got shape {centres.shape}", field="centres")
    problems, wrap = _clearance(centres, radii, [w.side for w in drive.wheels])
    if not problems:
        return wrap
    kind, i, j, dist = problems[0]
    names = drive.wheel_names
    n = len(names)
    if kind == "overlap":
        what = ("have the same centre" if dist < 1e-12 else
                f"overlap: centres {dist * 1e3:.1f} mm apart, pitch radii {radii[i] * 1e3:.1f} + "
                f"{radii[j] * 1e3:.1f} = {(radii[i] + radii[j]) * 1e3:.1f} mm")
        raise InputError(f"wheels {names[i]!r} and {names[j]!r} {what}; move {names[j]!r} so that the centres "
                         f"are at least {(radii[i] + radii[j]) * 1e3:.1f} mm apart (the sum of the pitch radii)",
                         field=f"wheels[{j}].position")
    raise InputError(f"the chain from {names[i]!r} to {names[(i + 1) % n]!r} runs through wheel {names[j]!r} "
                     f"({dist * 1e3:.1f} mm from its centre, pitch radius {radii[j] * 1e3:.1f} mm); move "
                     f"{names[j]!r}, or list the wheels in the order the chain passes them",
                     field=f"wheels[{j}].position")
