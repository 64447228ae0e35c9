"""Pitch radius and pitch polygon of a wheel (the shapes the chain wraps)."""

from __future__ import annotations

import functools

import numpy as np
from numpy.typing import ArrayLike

from .._finite import finite_guard
from .._typing import FloatOrArray
from .._validation import check_positive, check_teeth
from ..errors import InputError


@finite_guard
def pitch_radius(pitch: ArrayLike, teeth: ArrayLike, bar_diameter: float | None = None) -> FloatOrArray:
    r"""Pitch radius of a sprocket (regular polygon) or pocket wheel (bi-regular polygon).

    .. math::
        R = \frac{p}{2\sin(\pi/z)}\quad\text{(roller)},\qquad
        R = \tfrac12\sqrt{\left(\frac{t}{\sin\frac{\pi}{2z}}\right)^2
            + \left(\frac{d}{\cos\frac{\pi}{2z}}\right)^2}\quad\text{(link chain)}

    Parameters
    ----------
    pitch : float or array_like
        Chain pitch ``p`` (roller) or inner link length ``t`` (link chain) [m].
    teeth : int or array_like
        Teeth, or pockets ``z`` of a pocket wheel (the polygon has ``2z`` sides) [-].
    bar_diameter : float, optional
        Bar diameter ``d`` of a round link chain [m]; ``None`` or 0 for a roller chain.

    Returns
    -------
    ndarray
        Pitch radius [m].

    Notes
    -----
    Delegates to :mod:`chaindrive.geometry.polygon` (ISO 606:2015 clause 8.2; Dolipiński et al.
    eq. (6)). A pocket wheel needs ``z >= 2`` pockets.

    References
    ----------
    Dolipiński et al., eq. (6); ISO 606:2015, 8.2.

    Examples
    --------
    >>> round(float(pitch_radius(0.0254, 19)), 6)
    0.077159
    >>> round(float(pitch_radius(0.064, 8, 0.018)), 5)
    0.16428
    """
    from ..geometry.polygon import link_chain_pitch_radius, roller_chain_pitch_radius

    if bar_diameter is None or np.all(np.asarray(bar_diameter, dtype=float) == 0):
        return roller_chain_pitch_radius(pitch, teeth)
    check_teeth("teeth", teeth, minimum=2)
    return link_chain_pitch_radius(pitch, bar_diameter, teeth)


@finite_guard
def pitch_polygon_vertices(
    pitch: float,
    teeth: int,
    phase: float = 0.0,
    bar_diameter: float | None = None,
    centre: tuple[float, float] = (0.0, 0.0),
) -> np.ndarray:
    r"""Hinge centres of the chain seated on a wheel: vertices of its pitch polygon.

    .. math:: P_k = C + R\,(\cos\theta_k, \sin\theta_k),\quad
              \theta_{k+1} - \theta_k = \delta_1, \delta_2, \delta_1, \dots

    Parameters
    ----------
    pitch : float
        Chain pitch / inner link length [m].
    teeth : int
        Teeth or pockets ``z`` [-].
    phase : float
        Angle of the first vertex [rad].
    bar_diameter : float, optional
        Bar diameter of a round link chain [m] (bi-regular ``2z``-gon); ``None`` for a
        regular ``z``-gon.
    centre : (float, float)
        Wheel centre [m].

    Returns
    -------
    ndarray, shape (n, 2)
        Vertices [m], counter-clockwise.

    Notes
    -----
    Side lengths are ``p`` (regular) or alternately ``t + d`` and ``t - d``
    (bi-regular, Dolipiński et al.); the perimeter is ``z p`` or ``2 z t``.

    References
    ----------
    Dolipiński et al., eq. (6) and the central angles δ1, δ2.

    Examples
    --------
    >>> v = pitch_polygon_vertices(0.0254, 6)
    >>> round(float(np.hypot(*(v[1] - v[0]))), 6)
    0.0254
    """
    cx, cy = (float(c) for c in centre)
    R, offsets = _radius_and_offsets(pitch, teeth, bar_diameter)
    theta = float(phase) + offsets
    return np.column_stack([cx + R * np.cos(theta), cy + R * np.sin(theta)])


def _radius_and_offsets(pitch, teeth, bar_diameter):
    """Pitch radius [m] and vertex angles from the first vertex [rad] (checked inputs)."""
    z = int(check_teeth("teeth", teeth, minimum=2))
    t = float(check_positive("pitch", pitch, "m"))
    if bar_diameter is None or float(bar_diameter) == 0.0:
        if z < 3:
            raise InputError(f"teeth must be a whole number >= 3 for a roller chain, got {z}")
        R = t / (2.0 * np.sin(np.pi / z))
        steps = np.empty(z)  # np.full(z, 2π/z)
        steps.fill(2.0 * np.pi / z)
    else:
        from ..geometry.polygon import link_chain_central_angles

        d = float(bar_diameter)
        R = cached_pitch_radius(t, z, d)  # float(pitch_radius(t, z, d)), kept
        d1, d2 = (float(x) for x in link_chain_central_angles(t, d, z))
        steps = np.array([d1, d2] * z)  # np.tile([d1, d2], z)
    offsets = np.zeros(steps.size)  # [0, cumsum(steps)[:-1]] (np.concatenate of the same values)
    np.cumsum(steps[:-1], out=offsets[1:])
    return R, offsets


@functools.lru_cache(maxsize=256)
def cached_pitch_radius(pitch: float, teeth: int, bar_diameter: float | None = None) -> float:
    """``float(pitch_radius(pitch, teeth, bar_diameter))`` for scalars, kept (an analysis asks
    for the same wheels' radii many times; errors are raised each time, not kept) [m]."""
    return float(pitch_radius(pitch, teeth, bar_diameter))
