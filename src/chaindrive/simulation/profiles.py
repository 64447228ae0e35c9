"""Seat profiles and the axial stiffness of the simulated chains (constants and formulas
of :mod:`chaindrive.simulation.model`): the pocket-wheel seat of a round link chain, ISO
606's convex flank of a sprocket gap, ``EA`` of a roller chain and of a round link chain.
"""

from __future__ import annotations

import math

from ..chains.stiffness import (
    AXIAL_STIFFNESS_16B,
    AXIAL_STIFFNESS_LINK_PER_D2,
    link_chain_axial_stiffness,
)

__all__ = ["AXIAL_STIFFNESS_16B", "AXIAL_STIFFNESS_LINK_PER_D2", "link_chain_axial_stiffness",
           "link_seat_profile", "iso_flank"]

def link_seat_profile(pitch: float, bar_diameter: float, teeth: int,
                      tip_height: float | None = None) -> tuple[float, float]:
    r"""Flank angle ``ψ_s`` [rad] and tip height ``h_a`` [m] of the pocket-wheel seats.

    Every hinge of a round link chain on a pocket wheel gets the symmetric arc-and-flank
    seat of the sprocket model, with

    .. math::
        h_a = \frac d2,\qquad
        ψ_s = \frac\pi2 - \max\left(\frac{δ_1}2 + \frac{h_a}{2(t+d)},\;
                                     \frac{δ_2}2 + \frac{h_a}{2(t-d)}\right)

    Parameters
    ----------
    pitch : float
        Inner link length ``t`` [m].
    bar_diameter : float
        Bar diameter ``d`` [m], ``0 < d < t/2``.
    teeth : int
        Number of pockets ``z >= 3``.
    tip_height : float, optional
        ``h_a`` [m]; default ``d/2``.

    Returns
    -------
    psi, tip_height : float
        Half seating angle ``ψ_s`` [rad] and ``h_a`` [m].

    Notes
    -----
    Geometry of :class:`chaindrive.geometry.PocketWheel`: each horizontal link lies in a
    pocket whose floor ends in arcs of radius ``d/2 + c`` round the two hinges, and the
    pocket walls run parallel to the pocket axis up to the tip circle ``R + d/2``. So
    ``h_a = d/2`` (the tip flush with the top of the bar at the hinge) and the seat arc
    is ``r_s = d/2 + c`` (``c = 0.005 d`` by default, as ISO 606's ``0.505 d_1``).

    The real seat of a hinge is *asymmetric*: the pocket floor on the side of the pocket
    centre, the wall (parallel to the pocket axis, i.e. inclined by ``δ1/2`` to the
    hinge's radius) on the other; the horizontal link is held tangentially by the two
    walls of its pocket. The planar point-hinge model uses the symmetric sprocket profile
    instead (one formula for both chain types); its flanks must let a hinge in and out
    along the paths of the rigid kinematics, i.e. turning about either neighbouring
    hinge: such a path starts inclined by ``δ/2`` to the hinge's radius (``δ`` of the
    link it turns with) and, being a circle of radius ``t ± d`` about the neighbour, its
    secant up to the height ``h_a`` is inclined by about ``h_a/(2(t ± d))`` more. The
    flank angle above is the steepest that clears both paths up to the tip; for 18x64 on
    8 pockets ``ψ_s ≈ 72.4°`` (flanks 17.6° from the radius, the real wall 14.5°).
    Simplifications, stated plainly: symmetric seats at every hinge (the real pocket
    has a wall on one side of each hinge only, the floor on the other), the links as
    point-to-point springs (no link shape, no contact of the vertical links with the
    slot or the tooth tops, no out-of-plane motion).

    References
    ----------
    Dolipiński et al., eqs (6)-(9) (``R``, ``δ1``, ``δ2``); pocket geometry as in
    :mod:`chaindrive.geometry.pocket_wheel`.

    Examples
    --------
    >>> psi, h = link_seat_profile(0.064, 0.018, 8)
    >>> round(math.degrees(psi), 2), h
    (72.4, 0.009)
    """
    from ..geometry.polygon import link_chain_central_angles

    t, d = float(pitch), float(bar_diameter)
    d1, d2 = (float(v) for v in link_chain_central_angles(t, d, teeth))
    h = 0.5 * d if tip_height is None else float(tip_height)
    tilt = max(0.5 * d1 + h / (2 * (t + d)), 0.5 * d2 + h / (2 * (t - d)))
    return 0.5 * math.pi - tilt, h


def iso_flank(pitch: float, teeth: int, roller_radius: float, seat_radius: float,
              seat_half_angle: float, tip_height: float) -> tuple[float, ...]:
    r"""ISO 606 convex tooth flank of a sprocket gap in the simulation's gap frame.

    Gap frame: ``a`` radial from the seat centre (on the pitch circle), ``b`` tangential
    (``|b|``, the gap is symmetric). The seating arc (radius ``r_i``) ends at
    ``±ψ`` from the gap's inward radius; the flank arc of radius ``r_e`` continues it
    tangentially, its centre on the same ray, ``C_e = (r_i + r_e)(−cos ψ, sin ψ)``, and
    runs up to the tip circle (radius ``R + h_a`` about the wheel axis at ``a = −R``) or
    to the tooth centreline if it gets there first (a pointed tooth):
    :func:`chaindrive.geometry.sprocket.iso_tooth_form` (valid for any ``z >= 3``), whose
    frame is this gap frame. ``r_e`` is ISO 606's
    largest, ``r_e,max = 0.008 d_1 (z² + 180)``, which goes with ``r_i,min`` and ``α_max``
    (the minimum tooth form of :func:`chaindrive.geometry.sprocket.sprocket_outline`).

    .. math:: r_e = 0.008\,d_1 (z^2 + 180)

    Parameters
    ----------
    pitch : float
        [m].
    teeth : int
    roller_radius : float
        [m].
    seat_radius : float
        ``r_i`` [m].
    seat_half_angle : float
        ``ψ = α/2`` [rad].
    tip_height : float
        ``h_a`` above the pitch circle [m].

    Returns
    -------
    tuple
        ``(r_e, C_e,a, C_e,b, T_a, T_b, d_a, d_b)``: flank radius, flank centre, tooth
        corner ``T`` and the unit direction from ``C_e`` to ``T`` [m, -].

    References
    ----------
    ISO 606:2015, clause 8.3 (tooth form: ``r_e``, ``r_i``, ``α``, ``d_a``).

    Examples
    --------
    >>> re, *_ = iso_flank(0.0254, 17, 0.00794, 0.0080194, 1.1755, 0.00575)
    >>> round(re, 5)
    0.05958
    """
    from ..geometry.sprocket import iso_tooth_form

    z = int(teeth)
    radius = pitch / (2.0 * math.sin(math.pi / z))
    form = iso_tooth_form(pitch, z, 2.0 * roller_radius, seat_radius=seat_radius,
                          seat_angle=2.0 * seat_half_angle,
                          tip_diameter=2.0 * (radius + tip_height))
    re = form.flank_radius
    ce, corner = form.flank_centre, form.tooth_corner
    d = (corner - ce) / re
    return (float(re), float(ce[0]), float(ce[1]), float(corner[0]), float(corner[1]),
            float(d[0]), float(d[1]))


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
