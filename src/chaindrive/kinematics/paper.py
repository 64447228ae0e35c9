r"""The closed forms of Dolipiński et al. (eqs 1-43), with the printed errors corrected.

Coordinates and sign conventions are those of :mod:`chaindrive.kinematics.solver`:
``x`` is the displacement of the chain along the guide towards the wheel, ``φ = ωt``
the wheel angle, ``R`` the pitch radius, ``δ1``/``δ2`` the central angles of the
links ``t + d``/``t - d``, ``l`` the distance of the guide end from the wheel axis
along the guide line, ``H`` the guide height.

The paper's guided mechanism (its Figs 4, 5) is a *rod*: the free span from the seated
hinge ``S`` to a point ``P`` that slides on the guide line is taken as a rigid bar of
fixed length ``L``:

.. math::
    x = l \mp R\sin\gamma - \sqrt{L^2 - R^2(\cos\gamma - H/R)^2}

with ``γ`` the angle of ``S`` from the top. Its derivatives are, for ``γ`` decreasing
with ``φ`` (upper sign; eqs 14, 16, 30, 35 type) and increasing (lower sign; eqs 15,
17, 26, 31 type), with ``Q = sqrt(L² - R²(cos γ - c)²)``, ``c = H/R``:

.. math::
    v = ωR\left[\cos\gamma \pm \frac{R(\cos\gamma - c)\sin\gamma}{Q}\right],\quad
    a = ω^2R\left\{\pm\sin\gamma + \frac{R}{Q}\left[c\cos\gamma - \cos2\gamma
        + \frac{R^2(\cos\gamma - c)^2\sin^2\gamma}{Q^2}\right]\right\}

Corrections of the printed text (each derived from the geometry above and checked in
``tests/test_kinematics_paper.py`` against the general rod solver and by finite
differences):

Free entry, eqs (1)-(13)
    * (1)-(4): the factor ``ω`` is missing: ``V_x = ωR cos(...)``, ``V_y = ωR sin(...)``.
    * (1)-(9): ``s`` is the OCR of ``z``.
    * (2), (4): phase ``δ2 + δ1/2 - φ`` and the split of the period at ``π/z`` checked
      and *correct*: a hinge is the last seated one from the moment the link behind it
      is parallel to the span (``β = δ_prev/2``) to the moment the link ahead is
      (``β = -δ_next/2``), i.e. for ``(δ1 + δ2)/2 = π/z`` each.
    * (10)-(13): correct.
Chordal entry, eqs (14)-(25)  (``H = R cos(δ1/2)``)
    * everywhere: ``1`` is the OCR of ``l``; ``π/2`` and ``2π/2`` mean ``π/z``, ``2π/z``
      (the interval limits of 15-17, 19-21, 23-25 and the angles inside 16, 17, 20, 21,
      24, 25).
    * (19), (21): the sign before the fraction must be ``-`` (printed ``+``): in (15),
      (17) the angle grows with ``φ``, so the chain rule flips the sign of the root's
      derivative.
    * (21): ``sin(δ1/2 + φ - π/2)`` in the numerator must read ``sin(δ1/2 + φ - 2π/z)``.
    * (22)-(25): the bracket ``cos γ - cos 2γ`` must read ``cos(δ1/2) cos γ - cos 2γ``
      (the factor ``H/R = cos(δ1/2)`` is missing; the printed form is the tangential
      ``H = R`` one copied).
    * (22), (24): the sign before ``R/Q`` must be ``+`` (printed ``+ -`` across the line
      break, i.e. ``-``).
    * Mechanism: the switch at ``φ = π/z`` from the hinge at ``δ1/2 - φ`` (rod
      ``l - (t+d)/2``) to the one at ``π/z + δ2/2 - φ`` (rod ``l - (t-d)/2``) is a
      *reset*, not a seating: the rod is not collinear with the next chord there, so
      ``x`` jumps (made continuous here by a constant) and ``v`` jumps; over a period
      the chain advances by :func:`paper_chordal_entry` ``["advance"]`` instead of
      ``2t``. The printed lengths are kept (they are self-consistent in 14-25).
Tangential entry, eqs (26)-(43)  (``H = R``)
    * ``1`` is the OCR of ``l`` (26, 29, 30, 31, 35 ...).
    * (30), (31), (38), (42): the rod length under the root must be ``l - t - d``
      (printed ``l - d``, ``l - d``, ``l - t``, ``l - d``): at ``φ_g1`` the link ``t + d``
      seats on the rod, which then shrinks by exactly that link (otherwise ``x`` jumps);
      (37) and (41) print it right.
    * (33): ``sin ξ2 = R/(l - t - d) [1 - cos(δ2/2 + ξ2)]`` (printed ``l - d`` and
      ``-δ2/2``); (34) follows with ``l - d`` replaced by ``l - t - d`` (its ``+δ2/2``
      form is right).
    * (35): ``-`` under the root (printed ``+``); (35), (39), (43): rod length
      ``l - 2t`` (printed ``l - t``): after the second seating (link ``t - d``) the rod is
      ``l - (t + d) - (t - d)``, and then ``x(2π/z) = 2t``, the advance per period.
    * (41), (43): the sign before ``R/Q`` must be ``+`` (printed ``-``).
    * (42), (43): the square bracket belongs under the root (typesetting).
    * (27)-(29), (32), (36), (37), (40): correct.

Roller chains are the case ``d = 0``, ``t = p`` with one link per period ``2π/z``
(``δ1 = δ2 = 2π/z``); the paper's period then covers two links and only its first
half (one link) is used.

References
----------
Dolipiński et al. (Dolipiński, Reich, Adamowicz, Ziegler), eqs (1)-(43), Figs 1-5.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from .._docs import Fragments
from .._finite import finite_guard
from .histories import PaperEntry

__all__ = [
    "paper_free_entry",
    "paper_chordal_entry",
    "paper_tangential_limit_angles",
    "paper_tangential_entry",
]


#: The parameters the paper's entry laws share, described once (:mod:`chaindrive._docs`).
_DOCS = Fragments(
    phi="""
        phi : array_like
            Wheel angle ``φ`` [rad]; any real value (periodic continuation).
    """,
    geometry="""
        pitch, bar_diameter : float
            Link pitch ``t`` and bar diameter ``d`` [m] (roller chain: ``p`` and 0).
        radius : float
            Pitch radius ``R`` [m].
    """,
    deltas="""
        delta1, delta2 : float
            Central angles of the links ``t + d`` and ``t - d`` [rad].
    """,
    guide_end_distance="""
        guide_end_distance : float
            ``l``, the distance of the guide end from the wheel axis [m].
    """,
    angular_velocity="""
        angular_velocity : float
            Wheel angular velocity ``ω`` [rad/s], constant.
    """,
)
_DOCS.section("rod_parameters", "phi", "geometry", "deltas", "guide_end_distance", "angular_velocity")


def _wrap(phi: ArrayLike, period: float) -> tuple[np.ndarray, np.ndarray]:
    phi = np.asarray(phi, dtype=float)
    q = np.floor(phi / period)
    return q, phi - q * period


@finite_guard
@_DOCS
def paper_free_entry(phi: ArrayLike, radius: float, delta1: float, delta2: float, angular_velocity: float, *,
                     roller: bool = False) -> PaperEntry:
    r"""Free entry, Dolipiński et al. eqs (1)-(4), (10)-(13) with ``ω`` restored.

    .. math::
        V_x = ωR\cos β,\ V_y = ωR\sin β,\ P_x = ω^2R\sin β,\ P_y = -ω^2R\cos β,\quad
        β = \begin{cases}\frac{δ_1}{2} - φ & 0 \le φ < \frac{π}{z}\\
                         δ_2 + \frac{δ_1}{2} - φ & \frac{π}{z} \le φ < \frac{2π}{z}\end{cases}

    Parameters
    ----------
    %(phi)s
    radius : float
        Pitch radius ``R`` [m].
    %(deltas)s
    angular_velocity : float
        ``ω`` [rad/s].
    roller : bool
        Roller chain (one link per period ``δ1``).

    Returns
    -------
    dict
        ``x`` [m] (position from ``x(0) = 0``), ``velocity`` [m/s], ``acceleration``
        [m/s²], ``y`` (height of the span above the axis) [m], ``vy`` [m/s], ``ay``
        [m/s²], ``advance`` [m].

    Notes
    -----
    ``x`` is the integral of (1)-(2): ``x = R sin(δ1/2) - R sin β`` on the first half,
    ``t + R sin(δ2/2) - R sin β`` on the second.

    Examples
    --------
    >>> r = paper_free_entry([0.0, np.pi / 8], 0.164283, 0.504471, 0.280927, 5.0)
    >>> np.round(r["velocity"], 4)
    array([0.7954, 0.8133])
    """
    R, w = float(radius), float(angular_velocity)
    d1, d2 = float(delta1), float(delta2)
    T = d1 if roller else d1 + d2
    half = 0.5 * (d1 + d2) if not roller else d1
    q, r = _wrap(phi, T)
    first = r < half
    beta = np.where(first, 0.5 * d1 - r, d2 + 0.5 * d1 - r)
    base = np.where(first, R * np.sin(0.5 * d1), R * (np.sin(0.5 * d1) + 2 * np.sin(0.5 * d2)))
    advance = 2 * R * np.sin(0.5 * d1) if roller else 2 * R * (np.sin(0.5 * d1) + np.sin(0.5 * d2))
    sb, cb = np.sin(beta), np.cos(beta)
    return PaperEntry(x=base - R * sb + q * advance, velocity=w * R * cb, acceleration=w * w * R * sb,
                      y=R * cb, vy=w * R * sb, ay=-w * w * R * cb, advance=float(advance))


def _rod_pieces(gamma, L, c, R, w, decreasing):
    """x - l, v, a of the rod mechanism for one piece (see module docstring)."""
    sg, cg = np.sin(gamma), np.cos(gamma)
    e = cg - c
    Q = np.sqrt(L * L - R * R * e * e)
    sgn = np.where(decreasing, 1.0, -1.0)
    x = -sgn * R * sg - Q
    v = w * R * (cg + sgn * R * e * sg / Q)
    a = w * w * R * (sgn * sg + (R / Q) * (c * cg - np.cos(2 * gamma) + R * R * e * e * sg * sg / (Q * Q)))
    return x, v, a


@finite_guard
@_DOCS
def paper_chordal_entry(phi: ArrayLike, pitch: float, bar_diameter: float, radius: float, delta1: float,
                        delta2: float, guide_end_distance: float, angular_velocity: float, *,
                        roller: bool = False) -> PaperEntry:
    r"""Chordal entry ``H = R cos(δ1/2)``, Dolipiński et al. eqs (14)-(25), corrected.

    .. math::
        x = l - R\sin\left(\frac{δ_1}{2} - φ\right) - \sqrt{\left(l - \frac{t+d}{2}\right)^2
            - R^2\left[\cos\left(\frac{δ_1}{2} - φ\right) - \cos\frac{δ_1}{2}\right]^2}
        \quad (0 \le φ \le δ_1/2)

    and likewise (15)-(17); velocities (18)-(21), accelerations (22)-(25) in the
    corrected form of the module docstring.

    %(rod_parameters)s
    roller : bool
        Roller chain: one link per period ``δ1``; only (14), (15) are used.

    Returns
    -------
    dict
        ``x`` [m] (made continuous at the reset ``φ = π/z``), ``velocity`` [m/s],
        ``acceleration`` [m/s²], ``advance`` (chain advance per period) [m],
        ``x_printed`` (``x`` exactly as the closed forms give it, jumping at ``π/z``).

    Notes
    -----
    Valid for ``l - (t + d)/2 > R (1 - cos(δ1/2))`` (the rod reaches the guide line).

    Examples
    --------
    >>> r = paper_chordal_entry([0.0], 0.064, 0.018, 0.164283, 0.504471, 0.280927, 0.256, 5.0)
    >>> round(float(r["velocity"][0]), 4)
    0.7954
    """
    t, d, R, w, l, d1, d2 = map(float, (pitch, bar_diameter, radius, angular_velocity, guide_end_distance,
                                        delta1, delta2))
    c = np.cos(0.5 * d1)
    La, Lb = l - 0.5 * t - 0.5 * d, l - 0.5 * t + 0.5 * d
    T = d1 if roller else d1 + d2
    half = d1 if roller else 0.5 * (d1 + d2)  # π/z

    def piece(r):
        r = np.asarray(r, dtype=float)
        in14 = r <= 0.5 * d1
        in15 = (r > 0.5 * d1) & (r < half)
        in16 = (r >= half) & (r <= half + 0.5 * d2)
        gamma = np.select([in14, in15, in16],
                          [0.5 * d1 - r, r - 0.5 * d1, half + 0.5 * d2 - r],
                          0.5 * d1 + r - T)  # (17)
        dec = in14 | in16
        L = np.where(r < half, La, Lb)
        x, v, a = _rod_pieces(gamma, L, c, R, w, dec)
        return l + x, v, a

    x0 = piece(0.0)[0]
    jump = 0.0 if roller else float(piece(np.nextafter(half, 0))[0] - piece(half)[0])
    xend = float(piece(np.nextafter(T, 0.0))[0])
    advance = xend - float(x0) + jump
    q, r = _wrap(phi, T)
    x, v, a = piece(r)
    xc = x - x0 + np.where(r >= half, jump, 0.0) + q * advance
    return PaperEntry(x=xc, velocity=v, acceleration=a, advance=advance, x_printed=x)


@finite_guard
@_DOCS
def paper_tangential_limit_angles(
    pitch: float, bar_diameter: float, radius: float, delta1: float, delta2: float, guide_end_distance: float
) -> tuple[float, float]:
    r"""Limit angles ``φ_g1`` (eq. 29) and ``φ_g2`` (eq. 34, corrected) of tangential entry.

    .. math::
        φ_{g1} = \frac{δ_1}{2} + 2\arctan\frac{l - R\sin\frac{δ_1}{2}
                 - \sqrt{l^2 - 2Rl\sin\frac{δ_1}{2}}}{2R\cos^2\frac{δ_1}{4}},\quad
        φ_{g2} = \frac{2π}{z} - \frac{δ_2}{2} + 2\arctan\frac{L_1 - R\sin\frac{δ_2}{2}
                 - \sqrt{L_1^2 - 2RL_1\sin\frac{δ_2}{2}}}{2R\cos^2\frac{δ_2}{4}}

    with ``L1 = l - t - d`` (printed ``l - d``).

    Parameters
    ----------
    %(geometry)s
    %(deltas)s
    %(guide_end_distance)s

    Returns
    -------
    tuple of float
        ``φ_g1``, ``φ_g2`` [rad].

    Notes
    -----
    Derivation: ``sin ξ = (R/L)(1 - cos(a + ξ))`` is ``A sin ξ + B cos ξ = R`` with
    ``A = L - R sin a``, ``B = R cos a``; the half-angle substitution gives a quadratic
    in ``tan(ξ/2)`` whose small root is the bracket above. Real for ``L >= 2R sin a``.

    Examples
    --------
    >>> g1, g2 = paper_tangential_limit_angles(0.064, 0.018, 0.164283, 0.504471, 0.280927, 0.256)
    >>> round(g1, 5), round(g2, 5)
    (0.27664, 0.65571)
    """
    t, d, R, l = map(float, (pitch, bar_diameter, radius, guide_end_distance))
    d1, d2 = float(delta1), float(delta2)
    g1 = 0.5 * d1 + _xi(l, 0.5 * d1, R)
    g2 = d1 + d2 - 0.5 * d2 + _xi(l - t - d, 0.5 * d2, R)
    return float(g1), float(g2)


def _xi(L: float, a: float, R: float) -> float:
    """Small root of sin ξ = (R/L)(1 - cos(a + ξ)) (eqs 28, 33)."""
    return float(2 * np.arctan((L - R * np.sin(a) - np.sqrt(L * L - 2 * R * L * np.sin(a)))
                               / (2 * R * np.cos(0.5 * a) ** 2)))


@finite_guard
@_DOCS
def paper_tangential_entry(phi: ArrayLike, pitch: float, bar_diameter: float, radius: float, delta1: float,
                           delta2: float, guide_end_distance: float, angular_velocity: float, *,
                           roller: bool = False) -> PaperEntry:
    r"""Tangential entry ``H = R``, Dolipiński et al. eqs (26)-(43), corrected.

    .. math::
        x = l + R\sin φ - \sqrt{l^2 - R^2(1 - \cos φ)^2}\quad (0 \le φ \le φ_{g1})

    then (30) on ``[φ_g1, δ1]``, (31) on ``[δ1, φ_g2]`` with rod ``l - t - d`` and (35) on
    ``[φ_g2, 2π/z]`` with rod ``l - 2t``; velocities (36)-(39), accelerations (40)-(43).

    %(rod_parameters)s
    roller : bool
        Roller chain: period ``δ1``, pieces (26) and (30) only.

    Returns
    -------
    dict
        ``x`` [m], ``velocity`` [m/s], ``acceleration`` [m/s²], ``advance`` [m],
        ``limit_angles`` (``φ_g1``, ``φ_g2``) [rad]; ``φ_g2`` is None for a roller chain
        (it has no second rod piece).

    Examples
    --------
    >>> r = paper_tangential_entry([0.0], 0.064, 0.018, 0.164283, 0.504471, 0.280927, 0.256, 5.0)
    >>> round(float(r.velocity[0]), 6), r.advance == 2 * 0.064   # two links per period
    (0.821415, True)
    """
    t, d, R, w, l, d1, d2 = map(float, (pitch, bar_diameter, radius, angular_velocity, guide_end_distance,
                                        delta1, delta2))
    if roller:
        g1, g2 = 0.5 * d1 + _xi(l, 0.5 * d1, R), np.inf
    else:
        g1, g2 = paper_tangential_limit_angles(t, d, R, d1, d2, l)
    T = d1 if roller else d1 + d2
    L1, L2 = l - t - d, l - 2 * t
    q, r = _wrap(phi, T)
    p26 = r <= g1
    p30 = (r > g1) & (r <= d1)
    p31 = (r > d1) & (r <= g2)
    gamma = np.select([p26, p30, p31], [r, d1 - r, r - d1], T - r)
    L = np.select([p26, p30 | p31], [l, L1], L2)
    dec = p30 | (~p26 & ~p31)
    x, v, a = _rod_pieces(gamma, L, 1.0, R, w, dec)
    advance = (t + d) if roller else 2 * t
    return PaperEntry(x=l + x + q * advance, velocity=v, acceleration=a, advance=float(advance),
                      limit_angles=(g1, None if roller else g2))
