r"""Where a worn chain seats on an ISO 606 tooth form, and when it rides over the teeth.

A chain stretched by ``e`` no longer fits the wheel's pitch polygon: its rollers lie on a
polygon of pitch ``p (1 + e)``, whose radius is ``R_e = R (1 + e)`` with
``R = p / (2 sin(π/z))``, so every roller rides out of its seat and up the tooth flank
(the uniform ride-up of a chain whose links have all worn alike; Binder, *Mechanics of the
Roller Chain Drive*, 1956, ch. 5). In the frame of one tooth gap (``a`` radial from the
seat centre on the pitch circle, ``b`` tangential towards the loaded flank, the wheel
centre at ``(-R, 0)``) the roller centre (radius ``r = d_1/2``) lies on

- the seat path ``a² + b² = (r_i - r)²`` while its contact stays on the seating arc
  (within ``α/2`` of the inward radial), then
- the flank path ``|X - C_e| = r_e + r`` (``C_e`` the centre of the convex ISO 606 flank
  arc, :func:`chaindrive.geometry.tooth_form.iso_tooth_form`) up to the tooth corner.

The roller centre is where that path meets the circle ``|X - O| = R_e``. The tooth pushes
the roller along the contact normal ``n``; with the two links of the roller (towards the
tight side, tension ``T_k``, and away from it, ``T_{k+1}``) the frictionless balance of the
roller

.. math:: T_k\,\mathbf u_k + T_{k+1}\,\mathbf u_{k+1} + N\,\mathbf n = 0

gives the share a roller passes on, ``β = T_{k+1}/T_k`` (the geometric decay of the link
tensions round the wrap, Binder ch. 5; Naji & Marshek, Mech. Mach. Theory 18 (1983) 349).
``n`` seated rollers pass on ``β^n``: the wrap holds the tight-side tooth load ``T_1`` only
while the back tension ``T_2`` (slack side, without the centrifugal part that loads no
tooth) is at least ``β^n T_1``. The chain rides over the teeth at

.. math:: T_{1,jump} = T_2\,β(e)^{-n}

and at any tension once the roller centre passes the tooth corner: the elongation the
tooth form can hold at all (:func:`holding_limit`).

The model is frictionless (friction at the flank helps to hold the chain: conservative)
and quasi-static (no impact, no centrifugal lift of the rollers). It assumes every seated
roller rides up alike; a worn chain seats unevenly (the tight-end rollers highest, one at
the bottom of its gap, the rest on the back flank), and the holding is very sensitive to
that seating. With the span tensions held the compliant load distribution
(:mod:`chaindrive.life.wrap_statics`) holds 1.5–1.7 times it (9 and 17 teeth, docs/life.md);
with the torque and the sum of the span tensions held (a wheel on a slide) the chain jumps at
a far lower mean ratio, which :func:`chaindrive.life.wrap_jump_ratio` gives (docs/life.md,
"Jump-over"). The analysis' check takes the compliant onset from its table
(:func:`chaindrive.life.jump_onset`) as a correction to ``β^-n``.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from .._results import Result, quantity
from .._typing import FloatOrArray
from .._validation import check_nonnegative, check_positive
from ..errors import InputError
from ..geometry.tooth_form import iso_tooth_form

__all__ = ["WornSeat", "worn_seat", "holding_limit", "tension_ratio", "jump_over_tension"]


@dataclass(frozen=True)
class WornSeat(Result):
    """Seat of a roller of a chain stretched by ``elongation`` (see :func:`worn_seat`)."""

    elongation: float = quantity("1")
    radius: float = quantity("m")
    rise: float = quantity("m")
    position: np.ndarray = quantity("m")
    normal: np.ndarray = quantity("1")
    pressure_angle: float = quantity("rad")
    on_flank: bool = False
    holding_limit: float = quantity("1", default=0.0)


def _form(pitch, teeth, roller_diameter, form):
    """The tooth form and the roller's paths (cached: a pure function of four numbers)."""
    return _form_cached(float(pitch), int(teeth), float(roller_diameter), str(form))


@functools.lru_cache(maxsize=256)
def _form_cached(pitch, teeth, roller_diameter, form):
    f = iso_tooth_form(pitch, teeth, roller_diameter, form=form)
    r = 0.5 * float(roller_diameter)
    c = f.seat_radius - r
    cf = np.asarray(f.flank_centre, float)
    corner = np.asarray(f.tooth_corner, float)
    rho = f.flank_radius + r
    # the roller centre when its contact reaches the tooth corner
    u = (corner - cf) / float(np.hypot(*(corner - cf)))
    x_corner = cf + rho * u
    return f, r, c, cf, rho, x_corner


def _centres_at(elongations, rp, c, half_seat, cf, rho):
    """Roller centre on the seat or flank path at distance ``R_e = rp (1 + e)`` from the wheel centre,
    for each elongation ``e`` of a list, in Python floats (short loops of them beat numpy's per-call
    cost): a list of ``(x_a, x_b, n_a, n_b, on_flank)``, the centre and the unit contact normal on the
    roller, or ``None`` where neither path reaches ``R_e``."""
    rp, c, rho, cf_a, cf_b = float(rp), float(c), float(rho), float(cf[0]), float(cf[1])
    seat_edge = c * math.cos(half_seat)
    scale = max(c, 1e-300)
    # the flank path, circle of radius rho about cf, met by |X - O| = R_e, O = (-rp, 0)
    # (the construction of chaindrive.geometry.outline.circle_intersections, in floats)
    da, db = cf_a + rp, cf_b
    d = math.hypot(da, db)
    ua, ub = da / d, db / d
    out = []
    for e in elongations:
        radius = rp * (1.0 + e)
        # seat path: circle of radius c about the origin
        a = (radius**2 - rp**2 - c**2) / (2.0 * rp)
        if abs(a) <= c and -a >= seat_edge:  # contact on the seating arc
            b = math.sqrt(max(c * c - a * a, 0.0))
            out.append((a, b, -a / scale, -b / scale, False))
            continue
        if d > radius + rho or d < abs(radius - rho) or d == 0:
            out.append(None)
            continue
        along = (radius**2 - rho**2 + d**2) / (2 * d)
        h = math.sqrt(max(radius**2 - along**2, 0.0))
        ma, mb = -rp + along * ua, along * ub
        # the one on the gap side of the flank centre (b below the flank centre's b; the first on a tie)
        xa, xb = (ma - h * ub, mb + h * ua) if mb + h * ua <= mb - h * ua else (ma + h * ub, mb - h * ua)
        out.append((xa, xb, (xa - cf_a) / rho, (xb - cf_b) / rho, True))
    return out


def worn_seat(pitch: float, teeth: int, roller_diameter: float, elongation: float, *,
              form: str = "min") -> WornSeat:
    r"""Where the rollers of a chain stretched by ``elongation`` seat on an ISO 606 wheel.

    .. math:: R_e = \frac{p\,(1+e)}{2\sin(\pi/z)},\qquad
              |X - O| = R_e,\ X \text{ on the seat or flank path}

    Parameters
    ----------
    pitch : float
        Nominal chain (and wheel) pitch ``p`` [m].
    teeth : int
        ``z`` (3 … ISO 606's maximum).
    roller_diameter : float
        ``d_1`` [m].
    elongation : float
        Wear elongation ``e >= 0`` [-].
    form : {"min", "max"}
        ISO 606 tooth gap (minimum gap: the default, the one the simulation uses).

    Returns
    -------
    WornSeat
        ``radius`` ``R_e`` [m]; ``rise`` ``R_e − R`` [m]; ``position`` roller centre in the
        gap frame (``a`` radial, ``b`` tangential) [m]; ``normal`` the unit contact normal on
        the roller; ``pressure_angle`` the angle between that normal and the chain line at
        the roller (the tangent), [rad]; ``on_flank``; ``holding_limit`` the largest
        elongation the form holds (:func:`holding_limit`).

    Raises
    ------
    InputError
        Negative elongation, or the tooth form cannot hold a chain this worn (the roller
        centre would lie past the tooth corner).

    References
    ----------
    ISO 606:2015, clause 5.4.2 (tooth form); Binder, *Mechanics of the Roller Chain
    Drive* (1956), ch. 5 (a worn chain rides out on the wheel).

    Examples
    --------
    >>> s = worn_seat(0.0254, 19, 0.01588, 0.02)
    >>> round(s.rise * 1e3, 3), s.on_flank
    (1.543, True)
    """
    e = float(check_nonnegative("elongation", elongation))
    f, r, c, cf, rho, x_corner = _form(pitch, teeth, roller_diameter, form)
    rp = f.pitch_radius
    limit = float(np.hypot(x_corner[0] + rp, x_corner[1])) / rp - 1.0
    if e > limit:
        raise InputError(f"elongation {e:.4g} is more than the ISO 606 tooth form of a {f.teeth}-tooth wheel "
                         f"can hold ({limit:.4g}): the rollers would ride over the tooth corner", field="elongation")
    radius = rp * (1.0 + e)
    got = _centres_at([e], rp, c, 0.5 * f.seat_angle, cf, rho)[0]
    if got is None:  # pragma: no cover - excluded by the limit above
        raise InputError(f"no seat for elongation {e:.4g} on a {f.teeth}-tooth wheel", field="elongation")
    x, n, on_flank = np.array(got[:2]), np.array(got[2:4]), got[4]
    # chain line at the roller: tangent to the circle |X - O| = R_e, towards +b
    radial = (x - np.array([-rp, 0.0])) / radius
    tangent = np.array([-radial[1], radial[0]])
    if tangent[1] < 0:
        tangent = -tangent
    pa = math.acos(max(-1.0, min(1.0, float(-n @ tangent))))
    return WornSeat(e, radius, radius - rp, x, n, pa, bool(on_flank), limit)


def holding_limit(pitch: float, teeth: int, roller_diameter: float, *, form: str = "min") -> float:
    r"""The largest elongation an ISO 606 tooth form holds: the roller centre at the tooth corner.

    .. math:: e_{max} = \frac{|X_T - O|}{R} - 1,\qquad
              X_T = C_e + (r_e + r)\,\frac{T - C_e}{|T - C_e|}

    Parameters
    ----------
    pitch, teeth, roller_diameter, form
        As in :func:`worn_seat`.

    Returns
    -------
    float
        [-]. Falls roughly as ``1/z`` (the makers' ``200/z`` % rule,
        :func:`chaindrive.life.elongation.replacement_limit`, keeps a margin below it).

    References
    ----------
    ISO 606:2015, clauses 5.4.2 and 5.5.2 (flank radius, tip diameter).

    Examples
    --------
    >>> round(holding_limit(0.0254, 19, 0.01588), 4)
    0.1475
    """
    f, r, c, cf, rho, x_corner = _form(pitch, teeth, roller_diameter, form)
    return float(np.hypot(x_corner[0] + f.pitch_radius, x_corner[1])) / f.pitch_radius - 1.0


def tension_ratio(pitch: float, teeth: int, roller_diameter: float, elongation: ArrayLike, *,
                  form: str = "min") -> FloatOrArray:
    r"""Share of the link tension a seated roller passes on, ``β = T_{k+1}/T_k`` (frictionless).

    .. math:: [\mathbf u_{k+1}\ \ \mathbf n] \begin{bmatrix}β\\ N/T_k\end{bmatrix} = -\mathbf u_k

    with ``u_k`` the unit vector along the link towards the tight side, ``u_{k+1}`` along
    the next link, both between roller centres on the polygon of radius ``R_e`` and
    central angle ``2π/z``, and ``n`` the contact normal of :func:`worn_seat`.

    Parameters
    ----------
    pitch, teeth, roller_diameter, form
        As in :func:`worn_seat`.
    elongation : float or array_like
        ``e >= 0`` [-], each no more than :func:`holding_limit`.

    Returns
    -------
    float or ndarray
        ``β`` in ``[0, 1]`` [-], the shape of ``elongation``.

    References
    ----------
    Binder, *Mechanics of the Roller Chain Drive* (1956), ch. 5 (link tensions decay
    geometrically round the wrap); Naji & Marshek, "Analysis of sprocket load
    distribution", Mech. Mach. Theory 18 (1983) 349–356.

    Examples
    --------
    >>> round(tension_ratio(0.0254, 19, 0.01588, 0.0), 3), round(tension_ratio(0.0254, 19, 0.01588, 0.03), 3)
    (0.422, 0.445)
    """
    e = check_nonnegative("elongation", elongation)
    f, r, c, cf, rho, x_corner = _form(pitch, teeth, roller_diameter, form)
    rp = f.pitch_radius
    limit = float(np.hypot(x_corner[0] + rp, x_corner[1])) / rp - 1.0
    if np.any(e > limit):
        raise InputError(f"elongation {float(np.max(e)):.4g} is more than the ISO 606 tooth form of a "
                         f"{f.teeth}-tooth wheel can hold ({limit:.4g}): the rollers would ride over the tooth "
                         "corner", field="elongation")
    step = 2.0 * math.pi / f.teeth
    ca, sa = math.cos(step), math.sin(step)
    rp = float(rp)
    out = []
    # in floats: the arrays are short (an analysis asks for 7 … 17 points)
    for xa, xb, na, nb, _ in _centres_at(np.ravel(e).tolist(), rp, c, 0.5 * f.seat_angle, cf, rho):
        va, vb = xa + rp, xb  # the roller centre from the wheel centre O = (-rp, 0)
        # the neighbouring roller centres, one pitch angle towards the tight side and away from it
        ka, kb = (-rp + (ca * va - sa * vb)) - xa, (sa * va + ca * vb) - xb
        ta, tb = (-rp + (ca * va + sa * vb)) - xa, (-sa * va + ca * vb) - xb
        lk, ln = math.hypot(ka, kb), math.hypot(ta, tb)
        uka, ukb, una, unb = ka / lk, kb / lk, ta / ln, tb / ln
        # [u_n n] (β, N/T_k) = -u_k by Cramer's rule: β = det[-u_k n] / det[u_n n]
        beta = (na * ukb - uka * nb) / (una * nb - na * unb)
        out.append(min(max(beta, 0.0), 1.0))
    if np.ndim(e) == 0:
        return out[0]
    return np.reshape(np.array(out, float), np.shape(e))


def jump_over_tension(back_tension: float, ratio: float, seated: int) -> float:
    r"""Tight-side tooth load at which a wrap of ``seated`` rollers lets the chain ride over.

    .. math:: T_{1,jump} = T_2\,β^{-n}

    Parameters
    ----------
    back_tension : float
        Tension of the span leaving the wrap on its slack side, without the centrifugal
        part, ``T_2 >= 0`` [N].
    ratio : float
        ``β`` of :func:`tension_ratio`, in ``[0, 1]``.
    seated : int
        Rollers seated in the wrap ``n >= 1`` (teeth in mesh).

    Returns
    -------
    float
        [N]; ``inf`` when ``β = 0`` (a seated roller takes the whole load).

    Examples
    --------
    >>> round(jump_over_tension(500.0, 0.6, 8), 1)
    29768.7
    """
    t2 = float(check_nonnegative("back_tension", back_tension, "N"))
    b = float(ratio)
    if not 0.0 <= b <= 1.0:
        raise InputError(f"ratio must lie in [0, 1], got {b:g}", field="ratio")
    n = float(check_positive("seated", seated))
    if b == 0.0:
        return math.inf
    return t2 * b ** (-n)


from chaindrive._finite import finite_guard  # noqa: E402

# NaN/inf arguments refused, an overflow one line; +inf stays the documented answer of ratio 0
jump_over_tension = finite_guard(jump_over_tension, check_result=False)
