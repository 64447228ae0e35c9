r"""The self-regulating chain drive: slack tension set by the load and the wear through
the centre distance, with the regulation coefficient ψ.

One wheel of a two-wheel drive sits on a *carrier*: a plate that swings about a pivot
(``kind="pivot"``, the pivoted or "reactive-torque" motor base) or runs along a straight
slide (``kind="slide"``). The chain length (whole links, lengthened by wear) fixes the
centre distance ``a`` and so the carrier position; the balance of the carrier under the
two span tensions, its weight and an optional spring fixes the tensions:

.. math::
    S_2 = \psi\,F_t + S_0,\qquad
    \psi = -\frac{g_1}{g_1 + g_2},\qquad S_0 = -\frac{Q_r}{g_1 + g_2}

with ``F_t`` the effective pull, ``g_1, g_2`` the generalized lever arms of the tight
and slack spans (virtual work of a unit span tension per unit carrier coordinate) and
``Q_r`` the generalized force of weight and spring. When the wheel's torque is reacted
on the carrier (the motor or gear unit sits on it), ``ψ`` is positive for a pivot placed
between the spans nearer the tight one: the slack tension grows with the load. As the
chain wears the carrier moves, the arms change, and so does ψ; the range of ``a`` the
wear covers must keep ψ near its rational value.

What is whose
-------------
The self-regulating drive paper survives only in its conclusions: a sprocket design
that regulates the chain tightening with the useful load, the influence of the
geometric parameters of sprocket and transmission on the regulation, and a coefficient
ψ that stays close to its most rational value over the limits of change of the centre
distance ``a`` caused by chain wear. Everything else here is derived in this package
(``docs/self_regulating.md``): the carrier statics, the definition of ψ as the
load-proportional part ``∂S2/∂F_t`` (a reconstruction), the wear and sag coupling, and
the rational ψ (the smallest slack tension that keeps the slack span's sag within the
allowance at the rated load). The closed forms are checked against a full numerical
equilibrium (:func:`solve_equilibrium`: exact polygon chain length, catenary spans,
moments from the tangent points, Brent's method).

Layers: pure vectorised closed forms (:func:`worn_centre_distance`,
:func:`carrier_position`, :func:`span_arms`, :func:`regulation_coefficient`,
:func:`slack_tension`, :func:`restoring_force`, :func:`sag_length_excess`,
:func:`pivot_offset_for_coefficient`, :func:`sag_stiffness`,
:func:`carrier_natural_frequency`); the full equilibrium :func:`solve_equilibrium`
and the design helper :func:`rational_pivot` on a :class:`CarrierGeometry`; the grid
solver :func:`self_regulating_drive` returning :class:`SelfRegulatingDriveResult`;
:class:`SelfRegulatingSpec` and :func:`self_regulating_analysis` for a
:class:`chaindrive.drive.Drive`. Plot: :func:`chaindrive.plotting.self_regulating.self_regulating_plot`.

References
----------
Self-regulating drive paper (conclusions). E. J. Bees, "Motor base how-to", *Power
Transmission Design* (Overly Hautz Motor Base Co.): spring-loaded and reactive-torque
(pivoted) motor bases that change the centre distance with the load. ISO 10823:2004
(chain length and centre distance). Irvine, H. M., *Cable Structures*, MIT Press 1981,
ch. 1 (catenary and the parabolic length excess).
"""

from __future__ import annotations

import dataclasses
import math
import warnings
from collections.abc import Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike

from .. import layout as L
from .._results import Result
from .._validation import as_float_array, check_nonnegative, check_positive, check_range
from ..errors import ConvergenceError, InfeasibleError, InputError, ValidityRangeWarning

if TYPE_CHECKING:
    from .model import Drive

__all__ = [
    "CARRIER_KINDS",
    "TORQUE_REACTIONS",
    "worn_centre_distance",
    "carrier_position",
    "span_arms",
    "regulation_coefficient",
    "slack_tension",
    "restoring_force",
    "sag_length_excess",
    "pivot_offset_for_coefficient",
    "sag_stiffness",
    "carrier_natural_frequency",
    "CarrierGeometry",
    "solve_equilibrium",
    "rational_pivot",
    "self_regulating_drive",
    "SelfRegulatingDriveResult",
    "SelfRegulatingSpec",
    "self_regulating_analysis",
    "self_regulating_checks",
]

CARRIER_KINDS = ("pivot", "slide")
TORQUE_REACTIONS = ("carrier", "frame")
GRAVITY = L.GRAVITY
_GRAVITY_DIRECTION = np.array([0.0, -1.0])  # drive coordinates: y up
_SOURCE = "self-regulating drive paper (conclusions); carrier statics derived in docs/self_regulating.md"


# --------------------------------------------------------------------------- helpers


def _cross(u, v):
    """z-component of the 2-D cross product, broadcasting over leading axes."""
    u = np.asarray(u, dtype=float)
    v = np.asarray(v, dtype=float)
    return u[..., 0] * v[..., 1] - u[..., 1] * v[..., 0]


def _perp(u):
    """ẑ × u (rotation by +90°)."""
    u = np.asarray(u, dtype=float)
    return np.stack([-u[..., 1], u[..., 0]], axis=-1)


def _point(name: str, value) -> np.ndarray:
    arr = as_float_array(name, value)
    if arr.shape != (2,) or not np.all(np.isfinite(arr)):
        raise InputError(f"{name} must be a finite 2-vector (x, y) in m, got {value!r}")
    return arr


def _unit(name: str, value) -> np.ndarray:
    arr = _point(name, value)
    norm = float(np.hypot(*arr))
    if not norm > 0:
        raise InputError(f"{name} must be a non-zero 2-vector, got {value!r}")
    return arr / norm


def _sides_per_turn(teeth, bar_diameter):
    return 2.0 * teeth if bar_diameter else 1.0 * teeth



def _slide_direction(geo: Any) -> np.ndarray:
    """The slide direction of a slide carrier (every slide has one: checked by the spec)."""
    if geo.direction is None:
        raise InputError("self_regulating.direction: a slide carrier needs its direction (x, y)")
    return np.asarray(geo.direction, dtype=float)

def _kind(kind: str) -> str:
    if kind not in CARRIER_KINDS:
        raise InputError(f"kind must be one of {', '.join(CARRIER_KINDS)}, got {kind!r}")
    return kind


def _reaction(torque_reaction: str) -> str:
    if torque_reaction not in TORQUE_REACTIONS:
        raise InputError(
            f"torque_reaction must be one of {', '.join(TORQUE_REACTIONS)}, got {torque_reaction!r}")
    return torque_reaction


# --------------------------------------------------------------------------- closed forms


def worn_centre_distance(links: ArrayLike, pitch: ArrayLike, teeth_1: int, teeth_2: int,
                         elongation: ArrayLike = 0.0, *, bar_diameter: float | None = None,
                         length_deficit: ArrayLike = 0.0) -> np.ndarray:
    r"""Centre distance at which a worn chain of ``links`` pitches is taut (closed form).

    .. math::
        a = \frac{b + \sqrt{b^2 - 8 (r_2 - r_1)^2}}{4},\quad
        b = N p' - \Delta - \pi (r_1 + r_2),\quad r_i = \frac{n_i p'}{2\pi},\quad
        p' = p (1 + e)

    Parameters
    ----------
    links : int or array_like
        Chain length ``N`` [pitches].
    pitch : float or array_like
        New chain pitch ``p`` (inner link length of a link chain) [m].
    teeth_1, teeth_2 : int
        Teeth (pockets) of the two wheels [-].
    elongation : float or array_like
        Relative wear elongation ``e`` of the chain, ``0 <= e < 0.1`` [-].
    bar_diameter : float, optional
        Bar diameter of a round link chain [m]: the wheels seat ``n = 2z`` links per
        turn (``z`` for a roller chain).
    length_deficit : float or array_like
        Chain length not available to the taut path ``Δ >= 0`` [m] (the length taken by
        the sag of the spans, :func:`sag_length_excess`).

    Returns
    -------
    ndarray
        Centre distance ``a`` [m].

    Raises
    ------
    InfeasibleError
        The chain is too short for the two wheels.

    Notes
    -----
    The worn chain, pitch ``p' = p(1+e)``, rides higher on the teeth: its hinges form a
    polygon of side ``p'`` on each wheel, so the model is the new-chain one with ``p'``.
    The taut length is ISO 10823's approximation ``L = 2a + π(r1+r2) + (r2-r1)²/a``
    written with the perimeter radii ``r = n p'/2π`` (a wrap of a full turn is ``n``
    links); the larger root of ``2a² - b a + (r2-r1)² = 0`` inverts it. Against the
    exact polygon length (:func:`chaindrive.layout.chain_length_polygon`, phase
    mean) the error in ``a`` is below 0.02 p for roller chains at ``a >= 20 p``
    (tested). Valid for ``e < 0.1``; ISO 10823 limits ``e`` to about 3 %.

    References
    ----------
    ISO 10823:2004 (chain length and centre distance formula); the worn chain on the
    pitch polygon of side ``p(1+e)``: this package, docs/self_regulating.md.

    Examples
    --------
    >>> round(float(worn_centre_distance(122, 0.0254, 19, 57)), 4)
    1.0556
    >>> round(float(worn_centre_distance(122, 0.0254, 19, 57, 0.02)), 4)
    1.0767
    """
    N = check_positive("links", links)
    p = check_positive("pitch", pitch, "m")
    e = check_range("elongation", elongation, 0.0, 0.1, high_inclusive=False)
    deficit = check_nonnegative("length_deficit", length_deficit, "m")
    z1 = float(teeth_1)
    z2 = float(teeth_2)
    pw = p * (1.0 + e)
    r1 = _sides_per_turn(z1, bar_diameter) * pw / (2.0 * np.pi)
    r2 = _sides_per_turn(z2, bar_diameter) * pw / (2.0 * np.pi)
    b = N * pw - deficit - np.pi * (r1 + r2)
    disc = b**2 - 8.0 * (r2 - r1) ** 2
    if np.any(b <= 0) or np.any(disc < 0):
        raise InfeasibleError(
            f"a chain of {N} links is too short for wheels of {teeth_1} and {teeth_2} teeth "
            "(the closed form needs N p' - Δ - π(r1 + r2) > 2√2 |r2 - r1|)")
    return (b + np.sqrt(disc)) / 4.0


def carrier_position(centre_distance: ArrayLike, fixed_centre: ArrayLike,
                     carrier_centre: ArrayLike, *, kind: str, pivot: ArrayLike | None = None,
                     direction: ArrayLike | None = None) -> tuple[np.ndarray, np.ndarray]:
    r"""Carrier position that puts the carrier wheel at ``centre_distance`` from the fixed wheel.

    .. math::
        \text{pivot: } C = F + \xi\,\mathbf{e} + \eta\,\mathbf{e}_\perp,\
        \xi = \frac{a^2 - \rho^2 + D^2}{2D},\ \eta = \pm\sqrt{a^2 - \xi^2};\qquad
        \text{slide: } s = -b + \operatorname{sign}(b)\sqrt{b^2 - |C_0 - F|^2 + a^2}

    Parameters
    ----------
    centre_distance : float or array_like
        Required centre distance ``a`` [m].
    fixed_centre : (float, float)
        Centre ``F`` of the fixed wheel [m].
    carrier_centre : (float, float)
        Centre ``C0`` of the carrier wheel at the reference (given) position [m].
    kind : {"pivot", "slide"}
    pivot : (float, float), optional
        Pivot ``O`` of a swinging carrier [m] (``kind="pivot"``).
    direction : (float, float), optional
        Direction ``u`` of a slide (``kind="slide"``); its length does not matter.

    Returns
    -------
    coordinate : ndarray
        Carrier coordinate from the reference position, signed so that it grows with
        ``a``: the swing angle [rad] (pivot) or the travel along the slide [m].
    centre : ndarray, shape (..., 2)
        Carrier wheel centre [m].

    Raises
    ------
    InfeasibleError
        ``a`` outside the range the carrier reaches (``|D - ρ| <= a <= D + ρ`` for a
        pivot at distance ``D`` from ``F`` and radius ``ρ = |C0 - O|``; a slide whose
        line passes farther than ``a`` from ``F``), or a carrier that does not change
        ``a`` at the reference position (pivot on the centre line, slide across it).

    Notes
    -----
    Pivot: intersection of the circle of radius ``ρ`` about ``O`` with the circle of
    radius ``a`` about ``F``, on the side of line ``FO`` where ``C0`` lies; ``e`` is the
    unit vector from ``F`` to ``O``, ``D = |O - F|``. Slide: ``C = C0 + s u`` with
    ``|C - F| = a``, ``b = u·(C0 - F)``, the root that is 0 at the reference position.

    References
    ----------
    Geometry of the carrier (this package, docs/self_regulating.md).

    Examples
    --------
    >>> q, c = carrier_position(1.1, (0, 0), (1.0, 0.0), kind="slide", direction=(1, 0))
    >>> round(float(q), 6), c.round(6).tolist()
    (0.1, [1.1, 0.0])
    """
    a = check_positive("centre_distance", centre_distance, "m")
    F = _point("fixed_centre", fixed_centre)
    C0 = _point("carrier_centre", carrier_centre)
    if _kind(kind) == "pivot":
        if pivot is None:
            raise InputError("pivot: a pivoted carrier needs the pivot position (x, y) in m")
        O = _point("pivot", pivot)
        r0 = C0 - O
        rho = float(np.hypot(*r0))
        D = float(np.hypot(*(O - F)))
        if not rho > 0:
            raise InputError("pivot must not coincide with the carrier wheel centre")
        n0 = (C0 - F) / float(np.hypot(*(C0 - F)))
        lever = float(_cross(r0, n0))
        if abs(lever) < 1e-9 * rho:
            raise InfeasibleError(
                "the pivot lies on the centre line through the carrier wheel: swinging the "
                "carrier does not change the centre distance (move the pivot off the line)")
        if not D > 0:
            raise InfeasibleError("the pivot must not coincide with the fixed wheel centre")
        lo, hi = abs(D - rho), D + rho
        if np.any(a < lo) or np.any(a > hi):
            raise InfeasibleError(
                f"centre_distance must lie in [{lo:g}, {hi:g}] m for this pivot (carrier radius "
                f"{rho:g} m, pivot {D:g} m from the fixed wheel), got {np.asarray(a)}")
        e = (O - F) / D
        ep = _perp(e)
        side = 1.0 if float(np.dot(C0 - F, ep)) >= 0 else -1.0
        xi = (a**2 - rho**2 + D**2) / (2.0 * D)
        eta = side * np.sqrt(np.maximum(a**2 - xi**2, 0.0))
        C = F + xi[..., None] * e + eta[..., None] * ep
        kappa = 1.0 if lever > 0 else -1.0
        ang = np.arctan2(_cross(r0, C - O), np.sum(r0 * (C - O), axis=-1))
        return kappa * ang, C
    if direction is None:
        raise InputError("direction: a sliding carrier needs the slide direction (x, y)")
    u = _unit("direction", direction)
    d0 = C0 - F
    b = float(np.dot(u, d0))
    if abs(b) < 1e-9 * float(np.hypot(*d0)):
        raise InfeasibleError(
            "the slide runs across the centre line: moving the carrier does not change the "
            "centre distance (give a direction with a component along the centre line)")
    c0 = float(np.dot(d0, d0))
    disc = b**2 - c0 + a**2
    if np.any(disc < 0):
        amin = math.sqrt(max(c0 - b**2, 0.0))
        raise InfeasibleError(
            f"centre_distance must be >= {amin:g} m on this slide (its line passes {amin:g} m "
            f"from the fixed wheel), got {np.asarray(a)}")
    s = -b + math.copysign(1.0, b) * np.sqrt(disc)
    C = C0 + s[..., None] * u
    return math.copysign(1.0, b) * s, C


def span_arms(carrier_centre: ArrayLike, fixed_centre: ArrayLike, carrier_radius: ArrayLike,
              fixed_radius: ArrayLike, *, tight_side: int, kind: str,
              pivot: ArrayLike | None = None, direction: ArrayLike | None = None,
              reference_centre: ArrayLike | None = None,
              torque_reaction: str = "carrier") -> tuple[np.ndarray, np.ndarray]:
    r"""Generalized lever arms of the tight and slack spans on the carrier.

    .. math::
        g_\sigma = \mathbf{u}_\sigma\cdot\mathbf{v}_C + \omega\,\sigma R_C,\qquad
        \mathbf{u}_\sigma = -\cos\beta\,\mathbf{n} - \sigma\sin\beta\,\mathbf{m},\quad
        \sin\beta = \frac{R_C - R_F}{a}

    Parameters
    ----------
    carrier_centre : array_like, shape (..., 2)
        Carrier wheel centre ``C`` [m].
    fixed_centre : (float, float)
        Fixed wheel centre ``F`` [m].
    carrier_radius, fixed_radius : float or array_like
        Pitch radii ``R_C, R_F`` [m] (of the worn chain: ``∝ 1 + e``).
    tight_side : {+1, -1}
        Side of the centre line on which the tight span runs: ``+1`` on the left of
        ``n = (C - F)/a`` (the side of ``m = ẑ × n``), ``-1`` on the right.
    kind : {"pivot", "slide"}
    pivot, direction
        As for :func:`carrier_position`.
    reference_centre : (float, float), optional
        The carrier wheel centre at the reference position (sets the sign of the
        coordinate, see :func:`carrier_position`); default ``carrier_centre``.
    torque_reaction : {"carrier", "frame"}
        ``"carrier"``: the wheel's torque is reacted on the carrier (motor or gear unit
        on it: the span forces act at the tangent points); ``"frame"``: the torque
        leaves through a shaft joint coaxial with nothing on the carrier (only the
        bearing force acts).

    Returns
    -------
    arm_tight, arm_slack : ndarray
        ``g_1, g_2``: virtual work of a unit tension of the span per unit carrier
        coordinate [m] (pivot, per radian) or [-] (slide).

    Notes
    -----
    A span pulls the carrier wheel along ``u_σ`` (toward the fixed wheel) at its
    tangent point ``P = C + R_C ν_σ``; the virtual work per unit coordinate of a rigid
    carrier is ``u·v_C + ω (P - C) × u`` with ``(P - C) × u = σ R_C``. Pivot:
    ``v_C = κ ẑ × (C - O)``, ``ω = κ``; slide: ``v_C = κ û``, ``ω = 0``; ``κ = ±1``
    makes the coordinate grow with ``a``. In every case ``g_1 + g_2 = -2 cos β ∂a/∂q < 0``:
    equal tensions pull the carrier in. Derived here; tested against the moments of the
    span forces about the pivot taken from :func:`chaindrive.layout.wrap_layout`.

    References
    ----------
    Carrier statics (this package, docs/self_regulating.md); the reactive-torque
    (pivoted) motor base: Bees, "Motor base how-to", Power Transmission Design.

    Examples
    --------
    >>> g1, g2 = span_arms((0.0, 0.0), (-1.0, 0.0), 0.08, 0.08, tight_side=1,
    ...                    kind="pivot", pivot=(0.0, 0.03))
    >>> round(float(g1), 6), round(float(g2), 6)
    (0.05, -0.11)
    """
    C = as_float_array("carrier_centre", carrier_centre)
    if C.shape[-1:] != (2,):
        raise InputError(f"carrier_centre must have shape (..., 2), got {C.shape}")
    F = _point("fixed_centre", fixed_centre)
    RC = check_positive("carrier_radius", carrier_radius, "m")
    RF = check_positive("fixed_radius", fixed_radius, "m")
    if tight_side not in (1, -1):
        raise InputError(f"tight_side must be +1 or -1, got {tight_side!r}")
    react = _reaction(torque_reaction)
    d = C - F
    a = np.hypot(d[..., 0], d[..., 1])
    if np.any(a <= np.abs(RC - RF)):
        raise InfeasibleError("the carrier wheel overlaps the fixed wheel (a <= |R_C - R_F|)")
    n = d / a[..., None]
    m = _perp(n)
    sb = (RC - RF) / a
    cb = np.sqrt(1.0 - sb**2)
    C_ref = C if reference_centre is None else _point("reference_centre", reference_centre)
    kappa = _kappa(C_ref, F, kind, pivot, direction)
    if kind == "pivot":
        vC = kappa[..., None] * _perp(C - _point("pivot", pivot))
        omega = kappa if react == "carrier" else 0.0 * kappa
    else:
        vC = kappa[..., None] * _unit("direction", direction)
        omega = 0.0 * kappa
    arms = []
    for sigma in (tight_side, -tight_side):
        u_s = -cb[..., None] * n - sigma * sb[..., None] * m
        arms.append(np.sum(u_s * vC, axis=-1) + omega * sigma * RC)
    return arms[0], arms[1]


def regulation_coefficient(arm_tight: ArrayLike, arm_slack: ArrayLike) -> np.ndarray:
    r"""Regulation coefficient ψ: the load-proportional part of the slack tension.

    .. math:: \psi = \frac{\partial S_2}{\partial F_t} = -\frac{g_1}{g_1 + g_2}

    Parameters
    ----------
    arm_tight, arm_slack : float or array_like
        Generalized arms ``g_1, g_2`` of :func:`span_arms`; ``g_1 + g_2 < 0``.

    Returns
    -------
    ndarray
        ψ [-]. Positive: the slack tension grows with the load (self-regulation);
        ``-1/2``: a carrier that sees only the resultant pull (an ordinary spring
        take-up, ``S1 + S2`` constant).

    Raises
    ------
    InfeasibleError
        ``g_1 + g_2 >= 0`` (equal tensions would push the carrier out: no equilibrium).

    Notes
    -----
    The self-regulating drive paper names ψ and says it must stay close to its most
    rational value over the wear range of ``a``; its definition is lost with the
    paper's body. This is the reconstruction used here (derived from the carrier's
    balance ``S1 g1 + S2 g2 + Q_r = 0`` with ``S1 = S2 + F_t``). For the pivoted
    carrier with the torque reacted on it and spans parallel to the centre line,
    ``ψ = (R_C - y)/(2y)`` with ``y`` the pivot's offset from the centre line toward the
    tight span (see :func:`pivot_offset_for_coefficient`).

    References
    ----------
    Self-regulating drive paper (the coefficient ψ, conclusions); derivation in
    docs/self_regulating.md.

    Examples
    --------
    >>> round(float(regulation_coefficient(0.05, -0.11)), 6)
    0.833333
    """
    g1 = as_float_array("arm_tight", arm_tight)
    g2 = as_float_array("arm_slack", arm_slack)
    total = g1 + g2
    if np.any(total >= 0):
        raise InfeasibleError(
            "arm_tight + arm_slack must be negative (equal span tensions must pull the "
            f"carrier in), got {total}")
    return -g1 / total


def slack_tension(effective_pull: ArrayLike, arm_tight: ArrayLike, arm_slack: ArrayLike,
                  restoring: ArrayLike) -> np.ndarray:
    r"""Slack-span tension from the balance of the carrier.

    .. math:: S_2 = -\frac{F_t g_1 + Q_r}{g_1 + g_2} = \psi F_t + S_0

    Parameters
    ----------
    effective_pull : float or array_like
        ``F_t = S1 - S2 >= 0`` [N] (torque over pitch radius of the driving wheel).
    arm_tight, arm_slack : float or array_like
        ``g_1, g_2`` of :func:`span_arms`.
    restoring : float or array_like
        Generalized force ``Q_r`` of weight and spring on the carrier (positive: it
        pushes the carrier out, tightening the chain), from :func:`restoring_force`
        [N·m] (pivot) or [N] (slide).

    Returns
    -------
    ndarray
        Static slack tension ``S2`` [N] (without the centrifugal part ``q v²``, which
        adds to both spans and exerts no net force on a wheel).

    Raises
    ------
    InfeasibleError
        ``S2 <= 0``: the carrier cannot keep the chain taut at that load (a slack
        chain: more preload or weight, or a pivot nearer the slack span's far side).

    References
    ----------
    Carrier statics (docs/self_regulating.md).

    Examples
    --------
    >>> round(float(slack_tension(1000.0, 0.05, -0.11, 6.0)), 3)
    933.333
    """
    Ft = check_nonnegative("effective_pull", effective_pull, "N")
    psi = regulation_coefficient(arm_tight, arm_slack)
    total = np.asarray(arm_tight, dtype=float) + np.asarray(arm_slack, dtype=float)
    Q = as_float_array("restoring", restoring)
    S2 = psi * Ft - Q / total
    if np.any(S2 <= 0):
        bad = np.broadcast_to(Ft, S2.shape)[S2 <= 0]
        raise InfeasibleError(
            "the slack tension S2 = ψ F_t + S0 would be <= 0 (the chain goes slack) for "
            f"F_t in [{np.min(bad):g}, {np.max(bad):g}] N: the carrier cannot hold the chain "
            "taut there; S2 > 0 needs S0 > 0 (weight or spring pushing the carrier out) and "
            "ψ F_t + S0 > 0 (more preload or weight, or a pivot that gives ψ >= 0)")
    return S2


def restoring_force(coordinate: ArrayLike, carrier_centre: ArrayLike, fixed_centre: ArrayLike, *,
                    kind: str, pivot: ArrayLike | None = None, direction: ArrayLike | None = None,
                    reference_centre: ArrayLike | None = None, weight: float = 0.0,
                    weight_offset: ArrayLike = (0.0, 0.0), stiffness: float = 0.0,
                    preload: float = 0.0) -> np.ndarray:
    r"""Generalized force of the carrier's weight and spring (positive: pushes it out).

    .. math::
        Q_r = W\,\hat{\mathbf{g}}\cdot\mathbf{v}_G + Q_0 - k\,q,\qquad
        \mathbf{v}_G = \kappa\,\hat z\times(G - O)\ \text{(pivot)},\
        \kappa\,\hat{\mathbf u}\ \text{(slide)}

    Parameters
    ----------
    coordinate : float or array_like
        Carrier coordinate ``q`` from the reference position [rad] or [m]
        (:func:`carrier_position`).
    carrier_centre : array_like, shape (..., 2)
        Carrier wheel centre at ``q`` [m].
    fixed_centre : (float, float)
        Fixed wheel centre [m] (sets the sign ``κ`` of the coordinate).
    kind, pivot, direction, reference_centre
        As for :func:`span_arms`.
    weight : float
        Weight ``W >= 0`` of the carrier and everything on it [N].
    weight_offset : (float, float)
        Centre of gravity ``G`` relative to the carrier wheel centre at the reference
        position [m]; it turns with a pivoted carrier.
    stiffness : float
        Spring stiffness ``k >= 0`` [N·m/rad] (pivot, torsional) or [N/m] (slide).
    preload : float
        Spring force ``Q_0`` at the reference position [N·m] or [N], positive when it
        pushes the carrier out.

    Returns
    -------
    ndarray
        ``Q_r`` [N·m] (pivot) or [N] (slide).

    Notes
    -----
    Gravity acts along ``-y`` of the drive's coordinates (``ĝ = (0, -1)``). Linear
    spring; the stops of a real carrier are not modelled.

    References
    ----------
    Virtual work of weight and spring on the carrier (docs/self_regulating.md).

    Examples
    --------
    >>> round(float(restoring_force(0.0, (0.0, 0.0), (-1.0, 0.0), kind="pivot",
    ...     pivot=(0.0, 0.03), weight=200.0, weight_offset=(-0.1, 0.0))), 6)
    20.0
    """
    q = as_float_array("coordinate", coordinate)
    C = as_float_array("carrier_centre", carrier_centre)
    F = _point("fixed_centre", fixed_centre)
    W = float(check_nonnegative("weight", weight, "N"))
    off = _point("weight_offset", weight_offset)
    k = float(check_nonnegative("stiffness", stiffness))
    Q0 = as_float_array("preload", preload)
    if Q0.ndim or not np.isfinite(Q0):
        raise InputError(f"preload must be a finite number, got {preload!r}")
    C_ref = C if reference_centre is None else _point("reference_centre", reference_centre)
    kappa = _kappa(C_ref, F, kind, pivot, direction)
    if kind == "pivot":
        O = _point("pivot", pivot)
        r_ref = C_ref - O
        ang = np.arctan2(_cross(r_ref, C - O), np.sum(r_ref * (C - O), axis=-1))
        c, s = np.cos(ang), np.sin(ang)
        G = C + np.stack([c * off[0] - s * off[1], s * off[0] + c * off[1]], axis=-1)
        vG = kappa[..., None] * _perp(G - O)
    else:
        vG = kappa[..., None] * _unit("direction", direction)
    return W * np.sum(_GRAVITY_DIRECTION * vG, axis=-1) + float(Q0) - k * q


def _kappa(reference_centre, fixed_centre, kind, pivot, direction):
    """Sign κ that makes the carrier coordinate grow with the centre distance."""
    C_ref = np.asarray(reference_centre, dtype=float)
    F = np.asarray(fixed_centre, dtype=float)
    n_ref = (C_ref - F) / np.hypot(C_ref[..., 0] - F[0], C_ref[..., 1] - F[1])[..., None]
    if _kind(kind) == "pivot":
        if pivot is None:
            raise InputError("pivot: a pivoted carrier needs the pivot position (x, y) in m")
        O = _point("pivot", pivot)
        return np.where(_cross(C_ref - O, n_ref) >= 0, 1.0, -1.0)
    if direction is None:
        raise InputError("direction: a sliding carrier needs the slide direction (x, y)")
    u = _unit("direction", direction)
    return np.where(np.sum(u * n_ref, axis=-1) >= 0, 1.0, -1.0)


def sag_length_excess(chord_length: ArrayLike, inclination: ArrayLike, tension: ArrayLike,
                      mass_per_length: ArrayLike, gravity: float = GRAVITY) -> np.ndarray:
    r"""Chain length taken up by the sag of a span, parabolic closed form.

    .. math:: \Delta = \frac{(q g)^2 \ell^3 \cos^2\gamma}{24\,S^2}

    Parameters
    ----------
    chord_length : float or array_like
        Span chord ``ℓ`` [m].
    inclination : float or array_like
        Chord angle ``γ`` above the horizontal [rad].
    tension : float or array_like
        Static span tension ``S > 0`` along the chord [N] (horizontal component
        ``H = S cos γ``).
    mass_per_length : float or array_like
        ``q`` [kg/m].
    gravity : float
        [m/s²].

    Returns
    -------
    ndarray
        Arc length minus chord ``Δ`` [m].

    Notes
    -----
    Derivation: the span hangs as a parabola about its chord under ``w = q g / cos γ``
    per horizontal length; expanding the arc length to second order in the deflection
    slope gives ``Δ = w² ℓx³ cos³γ / (24 H²)`` with ``ℓx = ℓ cos γ``; with ``H = S cos γ``
    the form above (horizontal span: the classic ``8 f² / 3ℓ``). Within 1 % of the exact
    catenary arc for a sag ratio ``f/ℓ <= 0.05`` (tested).

    References
    ----------
    Irvine, H. M., Cable Structures, MIT Press 1981, ch. 1 (parabolic cable, length).

    Examples
    --------
    >>> round(float(sag_length_excess(1.0, 0.0, 500.0, 2.6)) * 1e6, 2)  # 8 f²/3ℓ, f = 6.37 mm
    108.35
    """
    ell = check_positive("chord_length", chord_length, "m")
    g = as_float_array("inclination", inclination)
    S = check_positive("tension", tension, "N")
    q = check_positive("mass_per_length", mass_per_length, "kg/m")
    gr = check_positive("gravity", gravity, "m/s^2")
    return (q * gr) ** 2 * ell**3 * np.cos(g) ** 2 / (24.0 * S**2)


def _catenary_excess(chord_length, inclination, tension, mass_per_length, gravity=GRAVITY):
    """Exact arc length minus chord of a catenary span (tension along the chord, H = S cos γ)."""
    ell = np.asarray(chord_length, dtype=float)
    cg = np.abs(np.cos(inclination))
    H = np.asarray(tension, dtype=float) * cg
    lx = ell * cg
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        X = np.where(cg > 1e-9, mass_per_length * gravity * lx / (2.0 * np.maximum(H, 1e-300)), 0.0)
        small = X < 1e-3
        Xs = np.where(small, 1.0, X)
        A = np.where(small, X**2 / 6.0 + X**4 / 120.0, np.sinh(Xs) / Xs - 1.0)
        ds2 = lx**2 * A * (A + 2.0)  # s² - ℓ², s² = h² + (2 sinh X / k)²
        s = np.sqrt(ell**2 + ds2)
    return ds2 / (s + ell)


def pivot_offset_for_coefficient(coefficient: ArrayLike, pitch_radius: ArrayLike,
                                 span_angle: ArrayLike = 0.0, along: ArrayLike = 0.0) -> np.ndarray:
    r"""Offset of the pivot from the centre line that gives a regulation coefficient ψ.

    .. math:: y = \frac{R_C + x \sin\beta}{(2\psi + 1)\cos\beta}

    Parameters
    ----------
    coefficient : float or array_like
        Wanted ψ, ``ψ > -1/2`` [-].
    pitch_radius : float or array_like
        Pitch radius ``R_C`` of the carrier wheel [m].
    span_angle : float or array_like
        ``β = asin((R_C - R_F)/a)``, the spans' angle to the centre line [rad].
    along : float or array_like
        Position ``x = (O - C)·n`` of the pivot along the centre line, measured from the
        carrier wheel centre away from the fixed wheel [m].

    Returns
    -------
    ndarray
        Offset ``y`` [m] of the pivot from the centre line, on the side of the tight
        span (pivoted carrier, torque reacted on the carrier).

    Notes
    -----
    Inverse of :func:`regulation_coefficient` for the pivoted carrier with the torque
    reacted on it: ``ψ = -1/2 + (R_C + x sin β)/(2 y cos β)`` (docs/self_regulating.md).
    ``ψ = 0`` puts the pivot on the tight span's line (``y = R_C`` for ``β = 0``); a
    larger ψ moves it toward the centre line. The carrier wheel then moves ``y``
    per radian of swing along the centre line, so a small ψ also means a long lever
    for the wear take-up.

    References
    ----------
    Derived here from the carrier statics (docs/self_regulating.md); the self-regulating drive
    paper's conclusion that the geometric parameters set the regulation.

    Examples
    --------
    >>> round(float(pivot_offset_for_coefficient(0.5, 0.08)), 6)
    0.04
    """
    psi = check_range("coefficient", coefficient, -0.5, np.inf, low_inclusive=False)
    R = check_positive("pitch_radius", pitch_radius, "m")
    b = check_range("span_angle", span_angle, -np.pi / 2, np.pi / 2, low_inclusive=False,
                    high_inclusive=False, unit="rad")
    x = as_float_array("along", along)
    y = (R + x * np.sin(b)) / ((2.0 * psi + 1.0) * np.cos(b))
    if np.any(y <= 0):
        raise InfeasibleError(f"no pivot offset gives ψ = {np.asarray(coefficient)}: R_C + x sin β must be > 0")
    return y


def sag_stiffness(centre_distance_rate: ArrayLike, length_rate: ArrayLike, span_angle: ArrayLike,
                  sag_excess_tight: ArrayLike, tight_tension: ArrayLike, sag_excess_slack: ArrayLike,
                  slack_tension: ArrayLike, elastic_compliance: ArrayLike = 0.0) -> np.ndarray:
    r"""Stiffness of the carrier on the sag of the spans (the chain as a spring).

    .. math::
        K_s = \frac{\cos\beta\, L'(a)\, a_q^2}{\Delta_1/S_1 + \Delta_2/S_2 + L/(2EA)}

    Parameters
    ----------
    centre_distance_rate : float or array_like
        ``a_q = ∂a/∂q`` [m/rad] (pivot) or [-] (slide).
    length_rate : float or array_like
        ``L'(a) = dL_taut/da`` [-] (about 2; ISO form ``2 - (r2 - r1)²/a²``).
    span_angle : float or array_like
        ``β`` [rad].
    sag_excess_tight, sag_excess_slack : float or array_like
        Lengths ``Δ1, Δ2`` taken by the sag (:func:`sag_length_excess`) [m].
    tight_tension, slack_tension : float or array_like
        ``S1, S2 > 0`` [N].
    elastic_compliance : float or array_like
        ``L/(2EA) >= 0`` of the chain of length ``L`` and axial stiffness ``EA`` [m/N];
        0 for an inextensible chain.

    Returns
    -------
    ndarray
        ``K_s`` [N·m/rad] (pivot) or [N/m] (slide).

    Notes
    -----
    Derivation: at a fixed torque both tensions change by the same ``δS``; the carrier
    moving by ``δq`` lengthens the taut path by ``L' a_q δq``, which the sag gives back,
    ``δΔ = -2 (Δ1/S1 + Δ2/S2) δS`` (``Δ ∝ S⁻²``), and the elastic stretch, ``L δS/EA``
    (both tensions rise by ``δS`` along the whole chain); the generalized force of the tensions
    changes by ``(g1 + g2) δS = -2 cos β a_q δS``. The carrier's full stiffness adds the
    change of the arms and of weight and spring at fixed tensions (see
    :func:`self_regulating_drive`). Tested against the numerical equilibrium (preload
    perturbed).

    References
    ----------
    Derived here (docs/self_regulating.md, "Carrier stiffness and resonance").

    Examples
    --------
    >>> round(float(sag_stiffness(0.045, 2.0, 0.0, 1e-5, 300.0, 1e-4, 100.0)), 1)
    3919.4
    """
    aq = as_float_array("centre_distance_rate", centre_distance_rate)
    Lp = check_positive("length_rate", length_rate)
    b = check_range("span_angle", span_angle, -np.pi / 2, np.pi / 2, low_inclusive=False,
                    high_inclusive=False, unit="rad")
    d1 = check_nonnegative("sag_excess_tight", sag_excess_tight, "m")
    d2 = check_nonnegative("sag_excess_slack", sag_excess_slack, "m")
    s1 = check_positive("tight_tension", tight_tension, "N")
    s2 = check_positive("slack_tension", slack_tension, "N")
    compliance = d1 / s1 + d2 / s2 + check_nonnegative("elastic_compliance", elastic_compliance, "m/N")
    if np.any(compliance <= 0):
        raise InputError("sag_excess_tight, sag_excess_slack and elastic_compliance must not all "
                         "be 0 (a chain without sag or stretch is rigid: infinite stiffness)")
    return np.cos(b) * Lp * aq**2 / compliance


def carrier_natural_frequency(stiffness: ArrayLike, inertia: ArrayLike) -> np.ndarray:
    r"""Natural angular frequency of the carrier on its stiffness.

    .. math:: P_c = \sqrt{K / J}

    Parameters
    ----------
    stiffness : float or array_like
        ``K > 0`` [N·m/rad] (pivot) or [N/m] (slide).
    inertia : float or array_like
        ``J > 0``: moment of inertia about the pivot [kg·m²] or mass on the slide [kg].

    Returns
    -------
    ndarray
        ``P_c`` [rad/s].

    Raises
    ------
    InfeasibleError
        ``K <= 0``: the carrier's equilibrium is statically unstable.

    References
    ----------
    One degree of freedom, undamped (docs/self_regulating.md).

    Examples
    --------
    >>> round(float(carrier_natural_frequency(400.0, 0.25)), 3)
    40.0
    """
    K = as_float_array("stiffness", stiffness)
    if np.any(K <= 0) or not np.all(np.isfinite(K)):
        raise InfeasibleError(
            f"stiffness must be positive and finite (0 < K < inf), got {K}: the carrier's "
            "equilibrium is statically unstable")
    J = check_positive("inertia", inertia)
    return np.sqrt(K / J)


# --------------------------------------------------------------------------- the drive


@dataclass
class SelfRegulatingDriveResult(Result):
    """Slack tension, centre distance and ψ of a self-regulating drive over load and wear.

    Arrays of shape ``(loads, elongations)`` unless said otherwise; SI units.

    Attributes
    ----------
    wheel : str
        The wheel on the carrier.
    kind : {"pivot", "slide"}
    torque_reaction : {"carrier", "frame"}
    carrier_driving : bool
        The carrier wheel is the driving wheel.
    links : int
        Chain length [pitches].
    nominal_torque : float
        Torque on the driving wheel at load factor 1 [N·m].
    load_factor : ndarray, shape (loads,)
        Torque / nominal torque [-] (contains 1).
    elongation : ndarray, shape (elongations,)
        Wear elongation ``e`` [-].
    effective_pull : ndarray
        ``F_t`` [N].
    centre_distance : ndarray
        ``a`` [m] (closed form).
    carrier_coordinate : ndarray
        Swing [rad] (pivot) or travel [m] (slide) from the given position, growing with ``a``.
    coordinate_unit : str
    slack_tension, tight_tension : ndarray
        Static span tensions ``S2``, ``S1 = S2 + F_t`` [N] (closed form).
    base_tension : ndarray
        ``S0``, the part of ``S2`` set by weight and spring [N].
    psi : ndarray
        Regulation coefficient ψ [-].
    sag_ratio : ndarray
        Slack-span catenary sag / chord [-].
    shaft_load : ndarray
        Resultant of the span tensions on the carrier wheel [N].
    centre_distance_range : tuple of float
        Smallest and largest ``a`` over the grid [m].
    carrier_travel : float
        Range of the carrier coordinate [rad] or [m].
    rated_ratio : ndarray, shape (elongations,)
        ``S2 / F_t`` at load factor 1 [-].
    psi_rational : float
        ``S2* / F_t`` at load factor 1 for the least worn chain of the grid, ``S2*`` the
        smallest slack tension that keeps the sag within ``sag_allowance`` [-].
    slack_tension_rational : float
        ``S2*`` [N].
    sag_allowance : float
        [-].
    pivot_offset : float or None
        The given pivot's offset from the centre line toward the tight span [m] (pivot
        with the torque reacted on the carrier).
    pivot_rational : tuple of float or None
        A pivot (x, y) [m] that makes ψ equal ``psi_rational`` for the new and for the
        most worn chain (:func:`rational_pivot`), same carrier wheel position.
    pivot_rational_deviation : float or None
        Largest ``|ψ - psi_rational|`` over the wear range with that pivot [-].
    carrier_stiffness : ndarray
        ``K`` of the carrier at equilibrium [N·m/rad] or [N/m] (sag of the spans, arms,
        weight and spring).
    carrier_inertia : float or None
        [kg·m²] or [kg].
    carrier_frequency : ndarray or None
        ``sqrt(K/J)`` [rad/s].
    excitations : dict or None
        Exciting frequencies [rad/s] (driving, driven, meshing).
    resonance_margin : ndarray or None
        Smallest distance of ``P_c/ω_j`` to the band 0.7…1.4 over the excitations [-]
        (> 0 outside).
    numerical_centre_distance, numerical_slack_tension : ndarray or None
        Full nonlinear equilibrium (:func:`solve_equilibrium`) [m], [N].
    centre_distance_difference : float or None
        Largest ``|a - a_numerical|`` [m].
    slack_tension_difference : float or None
        Largest ``|S2 - S2_numerical| / S2_numerical`` [-].
    checks : tuple of dict
        ``name, value, limit, unit, passed, source, note, relation`` of each check
        (the fields of :class:`chaindrive.analysis.Check`; see
        :func:`self_regulating_checks`).
    warnings : tuple of str
    """

    wheel: str
    kind: str
    torque_reaction: str
    carrier_driving: bool
    links: int
    nominal_torque: float
    load_factor: np.ndarray
    elongation: np.ndarray
    effective_pull: np.ndarray
    centre_distance: np.ndarray
    carrier_coordinate: np.ndarray
    coordinate_unit: str
    slack_tension: np.ndarray
    tight_tension: np.ndarray
    base_tension: np.ndarray
    psi: np.ndarray
    sag_ratio: np.ndarray
    shaft_load: np.ndarray
    centre_distance_range: tuple
    carrier_travel: float
    rated_ratio: np.ndarray
    psi_rational: float
    slack_tension_rational: float
    sag_allowance: float
    pivot_offset: float | None
    pivot_rational: tuple | None
    pivot_rational_deviation: float | None
    carrier_stiffness: np.ndarray
    carrier_inertia: float | None
    carrier_frequency: np.ndarray | None
    excitations: dict | None
    resonance_margin: np.ndarray | None
    numerical_centre_distance: np.ndarray | None
    numerical_slack_tension: np.ndarray | None
    centre_distance_difference: float | None
    slack_tension_difference: float | None
    checks: tuple
    warnings: tuple

    @property
    def passed(self) -> bool:
        """All checks passed (checks without a verdict do not count)."""
        return all(c["passed"] is not False for c in self.checks)


@dataclass(frozen=True)
class CarrierGeometry:
    """Everything fixed about one self-regulating drive (SI units), shared by both solvers.

    Built by :func:`self_regulating_drive` from its arguments (same names; ``pivot``,
    ``direction``, the centres and ``weight_offset`` as float arrays, ``direction``
    normalised). ``radii(e)`` gives the worn pitch radii of the carrier and fixed wheel
    [m]; ``tight_side`` the side of the centre line (``+1`` left of ``n = (C - F)/a``)
    on which the tight span runs; ``axial_stiffness`` the chain's ``EA`` [N] (``None``:
    inextensible); ``stretch(S1, S2, chord, e)`` its elastic elongation [m].
    """

    pitch: float
    bar_diameter: float | None
    teeth_carrier: int
    teeth_fixed: int
    carrier_centre: np.ndarray
    fixed_centre: np.ndarray
    links: int
    carrier_driving: bool
    travel: str
    kind: str
    pivot: np.ndarray | None
    direction: np.ndarray | None
    torque_reaction: str
    weight: float
    weight_offset: np.ndarray
    stiffness: float
    preload: float
    mass_per_length: float
    axial_stiffness: float | None = None

    def radii(self, elongation: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
        pw = self.pitch * (1.0 + np.asarray(elongation, dtype=float))
        rc = L.pitch_radius(pw, self.teeth_carrier, self.bar_diameter)
        rf = L.pitch_radius(pw, self.teeth_fixed, self.bar_diameter)
        return np.asarray(rc, dtype=float), np.asarray(rf, dtype=float)

    @property
    def tight_side(self) -> int:
        # ccw travel: the span into the carrier runs on the right of n = (C - F)/a
        into_carrier = -1 if self.travel == "ccw" else 1
        return into_carrier if self.carrier_driving else -into_carrier

    def stretch(self, tight_tension: ArrayLike, slack_tension: ArrayLike, chord: ArrayLike,
                elongation: ArrayLike) -> np.ndarray:
        """Elastic elongation of the whole chain: spans at S1 and S2, wraps at the mean [m]."""
        if self.axial_stiffness is None:
            return np.zeros(np.broadcast(tight_tension, slack_tension, chord).shape)
        S1 = np.asarray(tight_tension, dtype=float)
        S2 = np.asarray(slack_tension, dtype=float)
        ell = np.asarray(chord, dtype=float)
        length = self.links * self.pitch * (1.0 + np.asarray(elongation, dtype=float))
        return (S1 * ell + S2 * ell + 0.5 * (S1 + S2) * (length - 2.0 * ell)) / self.axial_stiffness

    def carrier_kw(self) -> dict[str, Any]:
        return dict(kind=self.kind, pivot=None if self.pivot is None else tuple(self.pivot),
                    direction=None if self.direction is None else tuple(self.direction))


def _closed_form_state(geo: CarrierGeometry, effective_pull, elongation, centre_distance,
                       strict: bool = True):
    """Tensions and geometry at a given centre distance (closed forms).

    ``strict=False`` returns ``S2 <= 0`` instead of raising (used inside the root search).
    """
    kw = geo.carrier_kw()
    q, C = carrier_position(centre_distance, geo.fixed_centre, geo.carrier_centre, **kw)
    rc, rf = geo.radii(elongation)
    g1, g2 = span_arms(C, geo.fixed_centre, rc, rf, tight_side=geo.tight_side,
                       reference_centre=geo.carrier_centre, torque_reaction=geo.torque_reaction,
                       **kw)
    Q = restoring_force(q, C, geo.fixed_centre, reference_centre=geo.carrier_centre,
                        weight=geo.weight, weight_offset=geo.weight_offset,
                        stiffness=geo.stiffness, preload=geo.preload, **kw)
    psi = regulation_coefficient(g1, g2)
    if strict:
        S2 = slack_tension(effective_pull, g1, g2, Q)
    else:
        S2 = psi * effective_pull - Q / (g1 + g2)
    a = np.hypot(C[..., 0] - geo.fixed_centre[0], C[..., 1] - geo.fixed_centre[1])
    n = (C - geo.fixed_centre) / a[..., None]
    m = _perp(n)
    sb = (rc - rf) / a
    cb = np.sqrt(1.0 - sb**2)
    sig = geo.tight_side
    u_t = -cb[..., None] * n - sig * sb[..., None] * m
    u_s = -cb[..., None] * n + sig * sb[..., None] * m
    chord = a * cb
    return dict(q=q, C=C, g1=g1, g2=g2, Q=Q, S2=S2, psi=psi, S0=S2 - psi * effective_pull,
                u_t=u_t, u_s=u_s, chord=chord, incl_t=_inclination(u_t), incl_s=_inclination(u_s))


def _inclination(u):
    """Chord angle above the horizontal in [-π/2, π/2] of a direction vector."""
    return np.arctan2(u[..., 1] * np.sign(np.where(u[..., 0] == 0, 1.0, u[..., 0])),
                      np.abs(u[..., 0]))


def _reach(geo: CarrierGeometry) -> float:
    """Smallest centre distance the carrier reaches [m]."""
    F, C0 = geo.fixed_centre, geo.carrier_centre
    if geo.kind == "pivot":
        return abs(float(np.hypot(*(geo.pivot - F))) - float(np.hypot(*(C0 - geo.pivot))))
    b = float(np.dot(_slide_direction(geo), C0 - F))
    return math.sqrt(max(float(np.dot(C0 - F, C0 - F)) - b * b, 0.0))


def _closed_form(geo: CarrierGeometry, effective_pull, elongation):
    """Closed-form model: taut length (ISO form), carrier statics and parabolic sag; the
    compatibility ``L_taut(a) + Δ1 + Δ2 = N p'`` solved for ``a`` by vectorised bisection."""
    e = np.asarray(elongation, dtype=float)
    shape = np.broadcast(effective_pull, e).shape
    Ft = np.broadcast_to(effective_pull, shape)
    pw = geo.pitch * (1.0 + e)
    r1 = _sides_per_turn(geo.teeth_carrier, geo.bar_diameter) * pw / (2.0 * np.pi)
    r2 = _sides_per_turn(geo.teeth_fixed, geo.bar_diameter) * pw / (2.0 * np.pi)
    qm = geo.mass_per_length

    def mismatch(a):
        st = _closed_form_state(geo, Ft, e, a, strict=False)
        ok = st["S2"] > 0
        S2 = np.where(ok, st["S2"], 1.0)
        sag = (sag_length_excess(st["chord"], st["incl_t"], S2 + Ft, qm)
               + sag_length_excess(st["chord"], st["incl_s"], S2, qm))
        taut = 2.0 * a + np.pi * (r1 + r2) + (r2 - r1) ** 2 / a  # ISO 10823 form
        stretch = geo.stretch(S2 + Ft, S2, st["chord"], e)
        return np.where(ok, taut + sag - geo.links * pw - stretch, np.inf)

    hi = np.broadcast_to(worn_centre_distance(geo.links, geo.pitch, geo.teeth_carrier,
                                              geo.teeth_fixed, e, bar_diameter=geo.bar_diameter),
                         shape).copy()
    carrier_position(hi, geo.fixed_centre, geo.carrier_centre, **geo.carrier_kw())  # reach check
    if geo.axial_stiffness is not None:  # the stretch may exceed the sag: root above a_taut
        step = np.full(shape, 1e-4) * hi
        for _ in range(60):
            short = mismatch(hi) < 0
            if not np.any(short):
                break
            hi = np.where(short, hi + step, hi)
            step = np.where(short, 2.0 * step, step)
        carrier_position(hi, geo.fixed_centre, geo.carrier_centre, **geo.carrier_kw())
    floor = _reach(geo) * (1.0 + 1e-12) + 1e-12
    delta = np.full(shape, 1e-4) * hi
    lo = np.maximum(hi - delta, floor)
    for _ in range(60):
        need = mismatch(lo) >= 0
        if not np.any(need) or np.all(lo[need] <= floor):
            break
        delta = np.where(need, 2.0 * delta, delta)
        lo = np.where(need, np.maximum(hi - delta, floor), lo)
    bad = mismatch(lo) >= 0
    if np.any(bad):
        raise InfeasibleError(
            "no equilibrium with a taut chain for F_t in "
            f"[{np.min(Ft[bad]):g}, {np.max(Ft[bad]):g}] N, e in [{np.min(np.broadcast_to(e, shape)[bad]):g}, "
            f"{np.max(np.broadcast_to(e, shape)[bad]):g}]: the slack tension S2 = ψ F_t + S0 "
            "falls to zero, or the sag takes more chain than the carrier's travel gives; "
            "more weight or spring preload, or a pivot that gives ψ >= 0")
    for _ in range(48):  # the bracket is at most a few cm wide: 2⁻⁴⁸ of it is below 1e-15 m
        mid = 0.5 * (lo + hi)
        low = mismatch(mid) < 0
        lo = np.where(low, mid, lo)
        hi = np.where(low, hi, mid)
    a = 0.5 * (lo + hi)
    st = _closed_form_state(geo, Ft, e, a)
    st["a"] = a
    return st


def _carrier_stiffness(geo: CarrierGeometry, effective_pull, elongation, st) -> np.ndarray:
    """Full stiffness of the carrier at the closed-form equilibrium ``st`` (sag spring, arms,
    weight and spring; the last two by central differences of the closed forms)."""
    e = np.asarray(elongation, dtype=float)
    kw = geo.carrier_kw()
    a = st["a"]
    h = 1e-6 * a
    S2 = st["S2"]
    S1 = S2 + effective_pull
    rc, rf = geo.radii(e)

    def fixed_tension_force(aa):
        q, C = carrier_position(aa, geo.fixed_centre, geo.carrier_centre, **kw)
        g1, g2 = span_arms(C, geo.fixed_centre, rc, rf, tight_side=geo.tight_side,
                           reference_centre=geo.carrier_centre,
                           torque_reaction=geo.torque_reaction, **kw)
        Q = restoring_force(q, C, geo.fixed_centre, reference_centre=geo.carrier_centre,
                            weight=geo.weight, weight_offset=geo.weight_offset,
                            stiffness=geo.stiffness, preload=geo.preload, **kw)
        return q, S1 * g1 + S2 * g2 + Q

    qp, Qp = fixed_tension_force(a + h)
    qm, Qm = fixed_tension_force(a - h)
    dq = qp - qm
    pw = geo.pitch * (1.0 + e)
    r1 = _sides_per_turn(geo.teeth_carrier, geo.bar_diameter) * pw / (2.0 * np.pi)
    r2 = _sides_per_turn(geo.teeth_fixed, geo.bar_diameter) * pw / (2.0 * np.pi)
    qm_ = geo.mass_per_length
    d1 = sag_length_excess(st["chord"], st["incl_t"], S1, qm_)
    d2 = sag_length_excess(st["chord"], st["incl_s"], S2, qm_)
    elastic = 0.0 if geo.axial_stiffness is None else geo.links * pw / (2.0 * geo.axial_stiffness)
    Ks = sag_stiffness(2.0 * h / dq, 2.0 - (r2 - r1) ** 2 / a**2, np.arcsin((rc - rf) / a),
                       d1, S1, d2, S2, elastic)
    return Ks - (Qp - Qm) / dq


def solve_equilibrium(geometry: CarrierGeometry, effective_pull: float, elongation: float, *,
                      phases: int = 4, guess: float | None = None) -> tuple[float, float, float]:
    r"""Full nonlinear equilibrium of the carrier (numerical cross-check of the closed forms).

    .. math::
        \sum_i (P_i - O)\times S_i\mathbf{u}_i + M_W + M_s = 0,\qquad
        p' X_{poly}(a) + \Delta_{cat}(S_1) + \Delta_{cat}(S_2) = N p'

    Parameters
    ----------
    geometry : CarrierGeometry
        The drive.
    effective_pull : float
        ``F_t`` [N].
    elongation : float
        ``e`` [-].
    phases : int
        Phases per wheel for the polygon length (mean over ``phases²`` pairs).
    guess : float, optional
        Carrier coordinate to start the bracket from.

    Returns
    -------
    coordinate, centre_distance, slack_tension : float
        ``q`` [rad or m], ``a`` [m], ``S2`` [N].

    Notes
    -----
    Independent of the closed forms in every part: the tangent points and span
    directions come from :func:`chaindrive.layout.wrap_layout`; the moments are
    the cross products of the span forces about the pivot (or their components along
    the slide); the chain length is the phase mean of the exact polygon length
    (:func:`chaindrive.layout.chain_length_polygon`) of the worn pitch
    ``p(1+e)``; the spans hang as exact catenaries. The balance is linear in ``S2`` at
    a given carrier position; the length compatibility is solved for the coordinate by
    Brent's method.

    References
    ----------
    docs/self_regulating.md ("Numerical check").

    Examples
    --------
    >>> geo = CarrierGeometry(pitch=0.0254, bar_diameter=None, teeth_carrier=19,
    ...     teeth_fixed=38, carrier_centre=np.array([0.6, 0.0]), fixed_centre=np.zeros(2),
    ...     links=76, carrier_driving=True, travel="ccw", kind="pivot",
    ...     pivot=np.array([0.66, -0.045]), direction=None, torque_reaction="carrier",
    ...     weight=400.0, weight_offset=np.array([0.08, 0.0]), stiffness=0.0, preload=0.0,
    ...     mass_per_length=2.7)
    >>> q, a, S2 = solve_equilibrium(geo, 3000.0, 0.0)
    >>> round(a, 4), round(S2, 1)
    (0.5983, 1056.2)
    """
    from scipy.optimize import brentq

    if not isinstance(geometry, CarrierGeometry):
        raise InputError(f"geometry must be a CarrierGeometry, got {type(geometry).__name__}")
    geo = geometry
    e = float(check_range("elongation", elongation, 0.0, 0.1, high_inclusive=False))
    Ft = float(check_nonnegative("effective_pull", effective_pull, "N"))
    if int(phases) < 1:
        raise InputError(f"phases must be a whole number >= 1, got {phases}")
    pw = geo.pitch * (1.0 + e)
    rc, rf = (float(r) for r in geo.radii(e))
    F = geo.fixed_centre
    C0 = geo.carrier_centre
    qm = geo.mass_per_length
    if geo.kind == "pivot":
        O = geo.pivot
        kappa = 1.0 if _cross(C0 - O, C0 - F) >= 0 else -1.0
    else:
        d = _slide_direction(geo)
        u_sl = d / float(np.hypot(*d))
        kappa = 1.0 if float(np.dot(u_sl, C0 - F)) >= 0 else -1.0
    # tight span index in wrap_layout([F, C]): span 0 runs F -> C, span 1 C -> F (ccw loop)
    tight = 0 if (geo.carrier_driving == (geo.travel == "ccw")) else 1

    def centre(q):
        if geo.kind == "pivot":
            th = kappa * q
            c, s = math.cos(th), math.sin(th)
            r = C0 - O
            return O + np.array([c * r[0] - s * r[1], s * r[0] + c * r[1]]), th
        return C0 + kappa * q * u_sl, 0.0

    def state(q):
        C, th = centre(q)
        lay = L.wrap_layout(np.array([F, C]), [rf, rc])
        t = np.column_stack([np.cos(lay.span_angle), np.sin(lay.span_angle)])
        # pulls on the carrier wheel: span 0 ends on it (pull -t0), span 1 starts on it (+t1)
        pts = [lay.span_end[0], lay.span_start[1]]
        dirs = [-t[0], t[1]]
        if geo.kind == "pivot":
            arm_pts = pts if geo.torque_reaction == "carrier" else [C, C]
            A = [kappa * float(_cross(P - O, u)) for P, u in zip(arm_pts, dirs, strict=True)]
            c, s = math.cos(th), math.sin(th)
            G = C + np.array([c * geo.weight_offset[0] - s * geo.weight_offset[1],
                              s * geo.weight_offset[0] + c * geo.weight_offset[1]])
            QW = kappa * float(_cross(G - O, geo.weight * _GRAVITY_DIRECTION))
        else:
            A = [kappa * float(np.dot(u, u_sl)) for u in dirs]
            QW = kappa * geo.weight * float(np.dot(_GRAVITY_DIRECTION, u_sl))
        Qr = QW + geo.preload - geo.stiffness * q
        A_t, A_s = A[tight], A[1 - tight]
        S2 = -(Ft * A_t + Qr) / (A_t + A_s)
        return C, lay, S2

    def residual(q):
        try:
            C, lay, S2 = state(q)
        except InfeasibleError:
            return -geo.links * pw
        if not S2 > 0:
            return geo.links * pw  # a slack chain would need an infinitely long path
        a = float(np.hypot(*(C - F)))
        X = L.chain_length_polygon(pw, geo.teeth_fixed, geo.teeth_carrier, a,
                                   bar_diameter=geo.bar_diameter, phases=phases).links_mean
        S = np.where(np.arange(2) == tight, S2 + Ft, S2)
        incl = np.arctan(np.tan(lay.span_angle))
        sag = _catenary_excess(lay.span_length, incl, S, qm)
        stretch = 0.0
        if geo.axial_stiffness is not None:  # spans at their tensions, wraps at the mean
            wraps = geo.links * pw - float(np.sum(lay.span_length))
            stretch = (float(np.dot(S, lay.span_length)) + 0.5 * float(np.sum(S)) * wraps) / geo.axial_stiffness
        return X * pw + float(np.sum(sag)) - geo.links * pw - stretch

    q0 = 0.0 if guess is None else float(guess)
    step = 0.02 if geo.kind == "pivot" else 0.002
    lo, hi = q0 - step, q0 + step
    flo, fhi = residual(lo), residual(hi)
    for _ in range(60):
        if flo <= 0 <= fhi:
            break
        if flo > 0:
            lo -= step
            flo = residual(lo)
        if fhi < 0:
            hi += step
            fhi = residual(hi)
        step *= 1.6
    else:
        raise ConvergenceError(
            f"could not bracket the carrier position for F_t = {Ft:g} N, e = {e:g}")
    q = brentq(residual, lo, hi, xtol=1e-13, rtol=1e-13, maxiter=200)
    C, _, S2 = state(q)
    return float(q), float(np.hypot(*(C - F))), float(S2)


def _geometric_psi(geo: CarrierGeometry, elongation, pivot):
    """ψ of the taut worn chain (no sag) for a trial pivot."""
    e = np.asarray(elongation, dtype=float)
    a = worn_centre_distance(geo.links, geo.pitch, geo.teeth_carrier, geo.teeth_fixed, e,
                             bar_diameter=geo.bar_diameter)
    _, C = carrier_position(a, geo.fixed_centre, geo.carrier_centre, kind="pivot", pivot=pivot)
    rc, rf = geo.radii(e)
    g1, g2 = span_arms(C, geo.fixed_centre, rc, rf, tight_side=geo.tight_side, kind="pivot",
                       pivot=pivot, reference_centre=geo.carrier_centre)
    return regulation_coefficient(g1, g2)


def rational_pivot(geometry: CarrierGeometry, coefficient: float,
                   elongation_range: tuple[float, float] = (0.0, 0.03)) -> tuple[np.ndarray, float]:
    r"""Pivot that keeps ψ at a wanted value at both ends of the wear range.

    .. math:: \psi(e_0; O) - \psi^* = \psi^* - \psi(e_m; O) = \psi(e_1; O) - \psi^* = d,
              \qquad O = C_{mid} + x\,\mathbf n + \sigma_1 y\,\mathbf m

    Parameters
    ----------
    geometry : CarrierGeometry
        The drive; its ``pivot`` is replaced, the carrier wheel's reference position kept.
    coefficient : float
        Wanted ψ*, ``> -1/2`` [-].
    elongation_range : (float, float)
        New and most worn chain, ``0 <= e0 <= e1 < 0.1`` [-].

    Returns
    -------
    pivot : ndarray, shape (2,)
        [m], in the drive's coordinates.
    deviation : float
        Largest ``|ψ - ψ*|`` over 9 elongations in the range [-].

    Raises
    ------
    ConvergenceError
        No such pivot near the centre line (the root search failed).

    Notes
    -----
    Two effects move ψ as the chain wears: the carrier swings, turning the pivot's
    perpendicular offset ``y' = |(C - O) × n|`` (first order in the swing when the pivot
    lies off the normal through the wheel centre, ``dy'/dφ = -(O - C)·n``), and the
    worn chain rides higher on the teeth, ``R_C ∝ 1 + e``, which raises ψ by
    ``ΔR/(2y)``. Solving for both coordinates ``(x, y)`` of the pivot makes the two
    cancel over the range: ψ(e) is then U-shaped, and the pivot ``(x, y)`` and the
    half-width ``d`` are solved so that ψ is ``ψ* + d`` at both ends and ``ψ* - d`` at
    mid-range (equal ripple, close to the smallest largest deviation). ``C_mid`` is the
    carrier wheel centre on the given centre line at the mid-range taut centre distance. Closed forms of the taut
    chain (:func:`worn_centre_distance`, :func:`span_arms`), no sag; root by
    :func:`scipy.optimize.root` (hybrid Powell) from the one-point design
    :func:`pivot_offset_for_coefficient`. For a single elongation only ``y`` is solved,
    with the pivot on the normal (``x = 0``).

    References
    ----------
    Derived here (docs/self_regulating.md, "The rational ψ"); the self-regulating drive
    paper's conclusion that the limits of change of ``a`` with wear can be chosen so
    that ψ stays near its most rational value.

    Examples
    --------
    >>> geo = CarrierGeometry(pitch=0.0254, bar_diameter=None, teeth_carrier=19,
    ...     teeth_fixed=38, carrier_centre=np.array([0.6, 0.0]), fixed_centre=np.zeros(2),
    ...     links=76, carrier_driving=True, travel="ccw", kind="pivot",
    ...     pivot=np.array([0.66, -0.045]), direction=None, torque_reaction="carrier",
    ...     weight=400.0, weight_offset=np.array([0.08, 0.0]), stiffness=0.0, preload=0.0,
    ...     mass_per_length=2.7)
    >>> pivot, dev = rational_pivot(geo, 0.1, (0.0, 0.03))
    >>> pivot.round(4).tolist(), dev < 0.01
    ([0.621, -0.0627], True)
    """
    from scipy.optimize import root

    if not isinstance(geometry, CarrierGeometry):
        raise InputError(f"geometry must be a CarrierGeometry, got {type(geometry).__name__}")
    geo = geometry
    psi_star = float(check_range("coefficient", coefficient, -0.5, np.inf, low_inclusive=False))
    e0, e1 = (float(x) for x in check_range("elongation_range", elongation_range, 0.0, 0.1,
                                             high_inclusive=False))
    if e1 < e0:
        raise InputError(f"elongation_range must be (new, worn) with new <= worn, got {elongation_range}")
    F, C0 = geo.fixed_centre, geo.carrier_centre
    n0 = (C0 - F) / float(np.hypot(*(C0 - F)))
    m0 = _perp(n0)
    em = 0.5 * (e0 + e1)
    a_mid = float(worn_centre_distance(geo.links, geo.pitch, geo.teeth_carrier, geo.teeth_fixed,
                                       em, bar_diameter=geo.bar_diameter))
    C_mid = F + a_mid * n0
    rc, rf = (float(r) for r in geo.radii(em))
    y0 = float(pivot_offset_for_coefficient(psi_star, rc, math.asin((rc - rf) / a_mid)))

    def pivot_at(v):
        return C_mid + v[1] * n0 + geo.tight_side * v[0] * m0

    def residual(v):
        try:
            return _geometric_psi(geo, [e0, em, e1], pivot_at(v)) - psi_star - v[2] * np.array(
                [1.0, -1.0, 1.0])
        except (InfeasibleError, InputError):
            return np.array([1e3, 1e3, 1e3])

    if e1 - e0 < 1e-12:  # one elongation: ψ(e0) = ψ* with the pivot on the normal (x = 0)
        def fun(v):
            return residual(np.array([v[0], 0.0, 0.0]))[:1]

        sol = root(fun, np.array([y0]), method="hybr", options={"xtol": 1e-12})
        v = np.array([sol.x[0], 0.0, 0.0])
        ok = sol.success and abs(fun(sol.x)[0]) <= 1e-9
    else:
        sol = root(residual, np.array([y0, 0.0, 0.0]), method="hybr", options={"xtol": 1e-12})
        v = sol.x
        ok = sol.success and np.max(np.abs(residual(v))) <= 1e-9
    if not ok:
        raise ConvergenceError(
            f"no pivot found that keeps ψ = {psi_star:g} at e = {e0:g} and e = {e1:g} "
            f"({sol.message})")
    pivot = pivot_at(v)
    dev = float(np.max(np.abs(_geometric_psi(geo, np.linspace(e0, e1, 9), pivot) - psi_star)))
    return pivot, dev


def self_regulating_drive(*, pitch: float, teeth_carrier: int, teeth_fixed: int,
                          carrier_centre: ArrayLike, fixed_centre: ArrayLike, links: int,
                          torque: float,
                          carrier_driving: bool, mass_per_length: float, kind: str = "pivot",
                          pivot: ArrayLike | None = None, direction: ArrayLike | None = None,
                          torque_reaction: str = "carrier", weight: float = 0.0,
                          weight_offset: ArrayLike = (0.0, 0.0), stiffness: float = 0.0,
                          preload: float = 0.0, travel: str = "ccw", bar_diameter: float | None = None,
                          load_factors: ArrayLike | None = None,
                          elongations: ArrayLike | None = None, sag_allowance: float = 0.02,
                          psi_tolerance: float = 1.0, numerical: bool = True, phases: int = 4,
                          wheel: str = "carrier", speed: float | None = None,
                          inertia: float | None = None,
                          axial_stiffness: float | None = None) -> SelfRegulatingDriveResult:
    r"""Slack tension, centre distance and ψ of a self-regulating drive over load and wear.

    .. math::
        S_2(F_t, e) = \psi(a)\,F_t + S_0(a),\qquad a = a(e, S_1, S_2)\ \text{from}\
        L_{taut}(a) + \Delta_1 + \Delta_2 = N p (1 + e)

    Parameters
    ----------
    pitch : float
        Chain pitch (inner link length) [m].
    teeth_carrier, teeth_fixed : int
        Teeth (pockets) of the carrier wheel and the fixed wheel [-].
    carrier_centre, fixed_centre : (float, float)
        Wheel centres [m]; the carrier wheel's is its reference (given) position.
    links : int
        Chain length [pitches].
    torque : float
        Nominal torque on the driving wheel ``T > 0`` [N·m] (load factor 1).
    carrier_driving : bool
        The carrier wheel drives (a motor on a pivoted base) or is driven.
    mass_per_length : float
        Chain mass per length [kg/m].
    kind : {"pivot", "slide"}
    pivot, direction
        Pivot [m] or slide direction; see :func:`carrier_position`.
    torque_reaction : {"carrier", "frame"}
        See :func:`span_arms`.
    weight, weight_offset, stiffness, preload
        See :func:`restoring_force`.
    travel : {"ccw", "cw"}
        Direction the chain circulates.
    bar_diameter : float, optional
        Round link chain [m].
    load_factors : array_like, optional
        Torque / nominal torque, ``>= 0``; default 7 steps over ``[0, 1.5]``; 1 is
        always added.
    elongations : array_like, optional
        Wear elongations ``0 <= e < 0.1``; default ``0, 0.01, 0.02, 0.03``.
    sag_allowance : float
        Largest acceptable slack-span sag / chord at the rated load (0.02 for the
        usual horizontal drives: ISO 10823 guidance and chain makers) [-].
    psi_tolerance : float
        Accepted excess of ``S2/F_t`` at the rated load over the rational value, as a
        fraction [-] (design choice of this package; 1.0: at most twice).
    numerical : bool
        Also solve the full equilibrium (:func:`solve_equilibrium`) at every grid point.
    phases : int
        Phases per wheel of the polygon length in the numerical solution.
    wheel : str
        Name of the carrier wheel (for reports).
    speed : float, optional
        Angular velocity of the driving wheel [rad/s]: the exciting frequencies of the
        carrier resonance check (:func:`chaindrive.vibration.excitation_frequencies`).
    inertia : float, optional
        Moment of inertia of the carrier about the pivot [kg·m²] (pivot) or its mass [kg]
        (slide); default the weight as a point mass at its centre of gravity,
        ``J = (W/g) |G - O|²`` (a lower bound) or ``W/g``.
    axial_stiffness : float, optional
        Axial stiffness ``EA`` of the chain [N]: its elastic stretch joins the length
        compatibility and the carrier stiffness. ``None``: inextensible; the carrier
        stiffness at high load is then an upper bound (the sag spring stiffens without
        limit as the tension rises).

    Returns
    -------
    SelfRegulatingDriveResult

    Raises
    ------
    InputError
        A parameter outside its range (the message names it).
    InfeasibleError
        The carrier cannot reach the centre distance a worn chain needs, or cannot keep
        the chain taut at some load (``S2 <= 0``), or equal tensions do not pull it in.

    Notes
    -----
    Closed-form model (docs/self_regulating.md): at a centre distance ``a`` the carrier
    position (:func:`carrier_position`), the arms and ψ (:func:`span_arms`,
    :func:`regulation_coefficient`) and the tensions (:func:`slack_tension`) are
    explicit; the chain length ``N p'`` equals the taut length in ISO 10823's form
    (:func:`worn_centre_distance`) plus the length the two spans' sag takes
    (:func:`sag_length_excess`), one scalar equation in ``a`` solved by vectorised
    bisection (48 halvings) below the taut value. The numerical solution differs from
    it by the polygon length (ISO approximation vs exact phase mean), the pitch-circle
    tangent points and the parabolic sag length; the result reports both and their
    largest difference. Valid while the slack span's sag ratio stays below about 0.1
    (warned) and the carrier stays clear of its dead point.

    References
    ----------
    Self-regulating drive paper (conclusions: ψ near its rational value over the wear range of
    ``a``); carrier statics and the rest derived in docs/self_regulating.md; ISO 10823:2004
    (chain length, sag guidance).

    Examples
    --------
    >>> r = self_regulating_drive(pitch=0.0254, teeth_carrier=19, teeth_fixed=38,
    ...     carrier_centre=(0.6, 0.0), fixed_centre=(0.0, 0.0), links=76, torque=300.0,
    ...     carrier_driving=True, mass_per_length=2.7, pivot=(0.66, -0.045), weight=400.0,
    ...     weight_offset=(0.08, 0.0), numerical=False)
    >>> r.psi.shape, r.psi[r.load_factor == 1][0].round(3).tolist()
    ((7, 4), [0.323, 0.205, 0.141, 0.103])
    """
    p = float(check_positive("pitch", pitch, "m"))
    from .._validation import check_teeth

    zc = int(check_teeth("teeth_carrier", teeth_carrier, minimum=3 if not bar_diameter else 2))
    zf = int(check_teeth("teeth_fixed", teeth_fixed, minimum=3 if not bar_diameter else 2))
    N = as_float_array("links", links)
    if N.ndim or N != np.round(N) or N <= 0:
        raise InputError(f"links must be a whole number > 0, got {links!r}")
    T = float(check_positive("torque", torque, "N·m"))
    qm = float(check_positive("mass_per_length", mass_per_length, "kg/m"))
    if travel not in ("ccw", "cw"):
        raise InputError(f"travel must be 'ccw' or 'cw', got {travel!r}")
    _kind(kind)
    _reaction(torque_reaction)
    if bar_diameter is not None:
        check_positive("bar_diameter", bar_diameter, "m")
    lam = np.linspace(0.0, 1.5, 7) if load_factors is None else check_nonnegative(
        "load_factors", load_factors)
    lam = np.unique(np.concatenate([np.ravel(lam), [1.0]]))
    e = np.array([0.0, 0.01, 0.02, 0.03]) if elongations is None else np.unique(np.ravel(
        check_range("elongations", elongations, 0.0, 0.1, high_inclusive=False)))
    sag_allow = float(check_range("sag_allowance", sag_allowance, 0.0, 0.5, low_inclusive=False))
    tol = float(check_nonnegative("psi_tolerance", psi_tolerance))
    if int(phases) < 1:
        raise InputError(f"phases must be a whole number >= 1, got {phases}")
    geo = CarrierGeometry(
        pitch=p, bar_diameter=bar_diameter, teeth_carrier=zc, teeth_fixed=zf,
        carrier_centre=_point("carrier_centre", carrier_centre),
        fixed_centre=_point("fixed_centre", fixed_centre), links=int(N),
        carrier_driving=bool(carrier_driving), travel=travel, kind=kind,
        pivot=None if pivot is None else _point("pivot", pivot),
        direction=None if direction is None else _unit("direction", direction),
        torque_reaction=torque_reaction, weight=float(check_nonnegative("weight", weight, "N")),
        weight_offset=_point("weight_offset", weight_offset),
        stiffness=float(check_nonnegative("stiffness", stiffness)),
        preload=float(as_float_array("preload", preload)), mass_per_length=qm,
        axial_stiffness=None if axial_stiffness is None else float(
            check_positive("axial_stiffness", axial_stiffness, "N")),
    )
    if kind == "pivot" and geo.pivot is None:
        raise InputError("pivot: a pivoted carrier needs the pivot position (x, y) in m")
    if kind == "slide" and geo.direction is None:
        raise InputError("direction: a sliding carrier needs the slide direction (x, y)")
    if not math.isfinite(geo.preload):
        raise InputError(f"preload must be a finite number, got {preload!r}")

    rc, rf = geo.radii(e)
    r_drive = rc if geo.carrier_driving else rf
    Ft = lam[:, None] * T / r_drive[None, :]
    EE = np.broadcast_to(e[None, :], Ft.shape)
    st = _closed_form(geo, Ft, EE)
    a, S2 = st["a"], st["S2"]
    S1 = S2 + Ft
    shaft = np.hypot(*(S1[..., None] * st["u_t"] + S2[..., None] * st["u_s"]).transpose(2, 0, 1))
    sag = _sag_ratio(st["chord"], st["incl_s"], S2, qm)
    notes = []
    K = _carrier_stiffness(geo, Ft, EE, st)
    J = None
    if inertia is not None:
        J = float(check_positive("inertia", inertia, "kg·m² or kg"))
    elif geo.weight > 0:
        mass = geo.weight / GRAVITY
        J = mass if kind == "slide" else mass * float(
            np.sum((geo.carrier_centre + geo.weight_offset - geo.pivot) ** 2))
    freq: Any = None
    margin: Any = None
    excitations: Any = None
    if J is not None and J > 0 and np.all(K > 0):
        freq = carrier_natural_frequency(K, J)
        if speed is not None:
            from ..vibration.resonance import excitation_frequencies, resonance_margin

            z_drive = zc if geo.carrier_driving else zf
            z_driven = zf if geo.carrier_driving else zc
            excitations = excitation_frequencies(float(check_positive("speed", speed, "rad/s")),
                                                 z_driven / z_drive, z_drive,
                                                 link_chain=bool(bar_diameter))
            margins: list[Any] = [resonance_margin(freq / w) for w in excitations.values()]
            margin = np.min(np.asarray(margins), axis=0)
    elif J is None:
        notes.append("carrier natural frequency not computed: give the carrier's weight or inertia")
    if geo.axial_stiffness is None:
        notes.append("inextensible chain (no axial_stiffness): the carrier stiffness and frequency "
                     "at high load are upper bounds")
    if np.any(sag > 0.1):
        msg = (f"the slack span sags up to {float(np.max(sag)):.3g} of its chord (at low load): "
               "the parabolic sag length of the closed form is outside its range (sag ratio <= "
               "0.1); the numerical equilibrium stays exact")
        warnings.warn(msg, ValidityRangeWarning, stacklevel=2)
        notes.append(msg)

    # the rational ψ: the smallest slack tension that keeps the sag within the allowance
    i1 = int(np.nonzero(lam == 1.0)[0][0])
    chord0, incl0 = float(st["chord"][i1, 0]), float(st["incl_s"][i1, 0])
    if abs(incl0) > math.radians(80):
        S2_star = qm * GRAVITY * chord0
    else:
        S2_star = float(L.tension_for_sag(chord0, incl0, sag_allow * chord0, qm)) / math.cos(incl0)
    psi_star = S2_star / float(Ft[i1, 0])
    rated_ratio = S2[i1] / Ft[i1]
    offset: Any = None
    pivot_star: Any = None
    pivot_dev: Any = None
    if kind == "pivot" and torque_reaction == "carrier":
        C = geo.carrier_centre
        n = (C - geo.fixed_centre) / float(np.hypot(*(C - geo.fixed_centre)))
        offset = float(geo.tight_side * _cross(n, geo.pivot - C))  # + toward the tight span
        try:
            pivot_star, pivot_dev = rational_pivot(geo, psi_star, (float(e[0]), float(e[-1])))
            pivot_star = (float(pivot_star[0]), float(pivot_star[1]))
        except (ConvergenceError, InfeasibleError) as exc:
            notes.append(f"no rational pivot found: {exc}")

    a_num = S2_num = None
    da: Any = None
    dS: Any = None
    if numerical:
        a_num = np.empty_like(a)
        S2_num = np.empty_like(a)
        for i in range(a.shape[0]):
            for j in range(a.shape[1]):
                _, a_num[i, j], S2_num[i, j] = solve_equilibrium(
                    geo, float(Ft[i, j]), float(e[j]), phases=int(phases), guess=float(st["q"][i, j]))
        da = float(np.max(np.abs(a - a_num)))
        dS = float(np.max(np.abs(S2 - S2_num) / S2_num))

    checks = [
        dict(name="slack-span sag at the rated load within the allowance over the wear range",
             value=float(np.max(sag[i1])), limit=sag_allow, unit="-",
             passed=bool(np.max(sag[i1]) <= sag_allow * (1 + 1e-9)), relation="<=",
             source="ISO 10823:2004 guidance (sag about 2 % of the span); " + _SOURCE,
             note="the self-regulating carrier must keep S2 >= S2* at the rated load as the chain wears"),
        dict(name="slack tension at the rated load near the rational value (S2/F_t <= (1 + tolerance) ψ*)",
             value=float(np.max(rated_ratio) / psi_star), limit=1.0 + tol, unit="-",
             passed=bool(np.max(rated_ratio) / psi_star <= 1.0 + tol), relation="<=",
             source=_SOURCE,
             note=f"ψ* = {psi_star:.4g} (S2* = {S2_star:.4g} N); S2/F_t over wear "
                  f"{float(np.min(rated_ratio)):.4g}…{float(np.max(rated_ratio)):.4g}; tolerance is "
                  "a design choice of this package"),
    ]
    k_unit = "N·m/rad" if kind == "pivot" else "N/m"
    checks.append(dict(
        name="carrier equilibrium statically stable (stiffness > 0) over load and wear",
        value=float(np.min(K)), limit=0.0, unit=k_unit, passed=bool(np.min(K) > 0), relation=">=",
        source=_SOURCE, note="stiffness of the sag of both spans, the arms, weight and spring"))
    if margin is not None:
        worst = np.unravel_index(int(np.argmin(margin)), margin.shape)
        checks.append(dict(
            name="carrier natural frequency outside 0.7…1.4 × every exciting frequency",
            value=float(np.min(margin)), limit=0.0, unit="-", passed=bool(np.min(margin) > 0),
            relation=">=",
            source="the tensioner paper (0.7 <= P/ω <= 1.4 forbidden); carrier stiffness derived "
                   "in docs/self_regulating.md",
            note=f"margin (distance to the band); carrier {float(np.min(freq)):.4g}…"
                 f"{float(np.max(freq)):.4g} rad/s, worst at load factor {lam[worst[0]]:g}, "
                 f"e = {e[worst[1]]:g}"))
    if dS is not None:
        checks.append(dict(
            name="closed form agrees with the numerical equilibrium (slack tension)",
            value=dS, limit=0.02, unit="-", passed=bool(dS <= 0.02), relation="<=", source=_SOURCE,
            note=f"largest centre-distance difference {da * 1e3:.3g} mm"))
    return SelfRegulatingDriveResult(
        wheel=str(wheel), kind=kind, torque_reaction=torque_reaction,
        carrier_driving=geo.carrier_driving, links=geo.links, nominal_torque=T,
        load_factor=lam, elongation=e, effective_pull=Ft, centre_distance=a,
        carrier_coordinate=st["q"], coordinate_unit="rad" if kind == "pivot" else "m",
        slack_tension=S2, tight_tension=S1, base_tension=st["S0"], psi=st["psi"],
        sag_ratio=sag, shaft_load=shaft,
        centre_distance_range=(float(np.min(a)), float(np.max(a))),
        carrier_travel=float(np.ptp(st["q"])), rated_ratio=rated_ratio,
        psi_rational=float(psi_star), slack_tension_rational=float(S2_star),
        sag_allowance=sag_allow, pivot_offset=offset, pivot_rational=pivot_star,
        pivot_rational_deviation=pivot_dev,
        carrier_stiffness=K, carrier_inertia=J, carrier_frequency=freq, excitations=excitations,
        resonance_margin=margin,
        numerical_centre_distance=a_num, numerical_slack_tension=S2_num,
        centre_distance_difference=da, slack_tension_difference=dS,
        checks=tuple(checks), warnings=tuple(notes),
    )


def _sag_ratio(chord, inclination, tension, mass_per_length):
    """Catenary sag / chord of the slack span (0 for a near-vertical span)."""
    chord = np.asarray(chord, dtype=float)
    incl = np.asarray(inclination, dtype=float)
    steep = np.abs(incl) > math.radians(80)
    safe = np.where(steep, 0.0, incl)
    H = np.asarray(tension, dtype=float) * np.cos(safe)
    f = L.catenary_sag(chord, safe, H, mass_per_length)
    return np.where(steep, 0.0, f / chord)


# --------------------------------------------------------------------------- spec and Drive


def _pair(name: str, value) -> tuple[float, float] | None:
    if value is None:
        return None
    arr = _point(name, value)
    return (float(arr[0]), float(arr[1]))


@dataclass(frozen=True)
class SelfRegulatingSpec:
    """The ``[self_regulating]`` table of a project: the carrier of one wheel (SI units).

    Parameters
    ----------
    wheel : str
        Name of the wheel on the carrier (one of the two wheels of the drive).
    kind : {"pivot", "slide"}
        Swinging carrier (pivoted base) or straight slide.
    pivot : (float, float), optional
        Pivot position in the drive's coordinates [m] (``kind="pivot"``).
    direction : (float, float), optional
        Slide direction (``kind="slide"``) [-].
    torque_reaction : {"carrier", "frame"}
        Where the wheel's torque is reacted: on the carrier (motor or gear unit on it,
        the self-regulating arrangement) or on the frame (only the bearing force acts).
    weight : float
        Weight of the carrier and all it carries [N].
    weight_offset : (float, float)
        Its centre of gravity relative to the wheel centre at the given position [m].
    stiffness : float
        Spring stiffness [N·m/rad] (pivot) or [N/m] (slide).
    preload : float
        Spring force at the given position, positive outward [N·m] (pivot) or [N] (slide).
    load_max_factor : float
        Largest torque / nominal torque of the load grid (> 0).
    load_steps : int
        Load steps over ``[0, load_max_factor]`` (>= 2; 1 is added).
    elongation_steps : int
        Elongation steps over ``[0, elongation_limit]`` of the drive (>= 2).
    sag_allowance : float, optional
        Sag / chord allowed at the rated load; default the drive's ``slack_sag_ratio``.
    psi_tolerance : float
        Accepted excess of ``S2/F_t`` over the rational ψ at the rated load [-].
    numerical : bool
        Cross-check every grid point with the full equilibrium.
    inertia : float, optional
        Carrier's moment of inertia about the pivot [kg·m²] (pivot) or mass [kg]
        (slide), for its natural frequency; default from ``weight`` as a point mass.
    axial_stiffness : float, optional
        Chain axial stiffness ``EA`` [N]; default: for a round link chain
        ``EA = 0.854e11 d²`` N (studless chain, OrcaFlex documentation), for a roller
        chain none (inextensible).

    Examples
    --------
    >>> SelfRegulatingSpec(wheel="motor", pivot=(0.66, -0.045), weight=400.0).kind
    'pivot'
    """

    wheel: str
    kind: str = "pivot"
    pivot: tuple[float, float] | None = None
    direction: tuple[float, float] | None = None
    torque_reaction: str = "carrier"
    weight: float = 0.0
    weight_offset: tuple[float, float] = (0.0, 0.0)
    stiffness: float = 0.0
    preload: float = 0.0
    load_max_factor: float = 1.5
    load_steps: int = 7
    elongation_steps: int = 4
    sag_allowance: float | None = None
    psi_tolerance: float = 1.0
    numerical: bool = True
    inertia: float | None = None
    axial_stiffness: float | None = None

    @classmethod
    def from_table(cls, table: Mapping[str, Any]) -> SelfRegulatingSpec:
        """Build the spec from a project file's ``[self_regulating]`` table, parsing units.

        Parameters
        ----------
        table : mapping
            Keys as the fields; quantities as numbers (SI) or strings with units
            (``"660 mm"``, ``"400 N"``, ``"50 N*m/rad"``, ``"5 kN/m"``); ``pivot``,
            ``direction`` and ``weight_offset`` as pairs.

        Returns
        -------
        SelfRegulatingSpec

        Raises
        ------
        InputError
            An unknown key (the message lists the valid ones), a value that is not a
            number with a unit of the right dimension, or a field out of its range.

        Examples
        --------
        >>> spec = SelfRegulatingSpec.from_table({"wheel": "motor", "pivot": ["660 mm", "-45 mm"],
        ...     "weight": "0.4 kN", "weight_offset": ["80 mm", 0], "stiffness": "50 N*m/rad"})
        >>> spec.pivot, spec.weight, spec.stiffness
        ((0.66, -0.045), 400.0, 50.0)
        """
        from ..units import parse_quantity

        try:
            items = dict(table)
        except (TypeError, ValueError) as exc:
            raise InputError(f"self_regulating must be a table, got {table!r}") from exc
        names = [f.name for f in dataclasses.fields(cls)]
        unknown = sorted(set(items) - set(names))
        if unknown:
            raise InputError(f"self_regulating: unknown key(s) {', '.join(unknown)}; valid keys: "
                             f"{', '.join(names)}")
        pivot = items.get("kind", "pivot") == "pivot"
        units = {"weight": "N", "stiffness": "N*m/rad" if pivot else "N/m",
                 "preload": "N*m" if pivot else "N", "load_max_factor": "",
                 "sag_allowance": "", "psi_tolerance": "",
                 "inertia": "kg*m^2" if pivot else "kg", "axial_stiffness": "N"}
        pairs = {"pivot": "m", "weight_offset": "m", "direction": ""}
        out: dict[str, Any] = {}
        for key, value in items.items():
            field = f"self_regulating.{key}"
            if key in units and value is not None:
                out[key] = parse_quantity(value, units[key], field=field)
            elif key in pairs and value is not None:
                if not isinstance(value, (list, tuple)) or len(value) != 2:
                    raise InputError(f"{field} must be a pair (x, y), got {value!r}")
                out[key] = tuple(parse_quantity(v, pairs[key], field=field) for v in value)
            else:
                out[key] = value
        missing = [f.name for f in dataclasses.fields(cls)
                   if f.default is dataclasses.MISSING and f.default_factory is dataclasses.MISSING
                   and f.name not in out]
        if missing:
            raise InputError(f"self_regulating: required key(s) missing: {', '.join(missing)}")
        return cls(**out)

    def __post_init__(self):
        _kind(self.kind)
        _reaction(self.torque_reaction)
        if self.kind == "pivot" and self.pivot is None:
            raise InputError("self_regulating.pivot: a pivoted carrier needs the pivot (x, y) in m")
        if self.kind == "slide" and self.direction is None:
            raise InputError("self_regulating.direction: a sliding carrier needs the slide direction (x, y)")
        object.__setattr__(self, "pivot", _pair("self_regulating.pivot", self.pivot))
        object.__setattr__(self, "direction", _pair("self_regulating.direction", self.direction))
        if self.direction is not None and not np.hypot(*self.direction) > 0:
            raise InputError("self_regulating.direction must be a non-zero 2-vector")
        object.__setattr__(self, "weight_offset", _pair("self_regulating.weight_offset", self.weight_offset))
        check_nonnegative("self_regulating.weight", self.weight, "N")
        check_nonnegative("self_regulating.stiffness", self.stiffness)
        check_range("self_regulating.preload", self.preload)
        if not math.isfinite(float(self.preload)):
            raise InputError(f"self_regulating.preload must be finite, got {self.preload!r}")
        check_positive("self_regulating.load_max_factor", self.load_max_factor)
        for name in ("load_steps", "elongation_steps"):
            v = getattr(self, name)
            if isinstance(v, bool) or not isinstance(v, (int, np.integer)) or v < 2:
                raise InputError(f"self_regulating.{name} must be a whole number >= 2, got {v!r}")
        if self.sag_allowance is not None:
            check_range("self_regulating.sag_allowance", self.sag_allowance, 0.0, 0.5,
                        low_inclusive=False)
        check_nonnegative("self_regulating.psi_tolerance", self.psi_tolerance)
        if self.inertia is not None:
            check_positive("self_regulating.inertia", self.inertia, "kg·m² or kg")
        if self.axial_stiffness is not None:
            check_positive("self_regulating.axial_stiffness", self.axial_stiffness, "N")


def _drive_inputs(drive: Any, spec: SelfRegulatingSpec) -> dict:
    """Read what the model needs from a :class:`chaindrive.drive.Drive` (attributes only).

    The one place that knows the Drive: attribute names shared by the mutable Drive
    and the frozen dataclass that replaces it; nothing is written to the drive.
    """
    wheels = list(drive.wheels)
    if len(wheels) != 2 or any(w.teeth is None or w.kind == "idler" for w in wheels):
        raise InputError(
            "self_regulating: the model covers two-wheel drives of toothed wheels (got "
            f"{len(wheels)} wheels: {', '.join(w.name for w in wheels)})")
    names = [w.name for w in wheels]
    if spec.wheel not in names:
        raise InputError(f"self_regulating.wheel: no wheel named {spec.wheel!r}; wheels: {', '.join(names)}")
    carrier = wheels[names.index(spec.wheel)]
    fixed = wheels[1 - names.index(spec.wheel)]
    chain = drive.chain
    bar = chain.bar_diameter if chain.is_link_chain else None
    if chain.mass_per_length is None:
        raise InputError(f"chain {chain.name!r} has no mass_per_length; give it in the [chain] table")
    load = drive.load
    speed = float(drive.speed)
    torque = float(load.torque) if load.torque is not None else float(load.power) / speed
    links = drive.links
    if links is None:  # the rule of chaindrive.analysis.drive_layout: polygon length, even
        a0 = float(np.hypot(*np.subtract(wheels[1].position, wheels[0].position)))
        req = L.chain_length_polygon(chain.pitch, wheels[0].teeth, wheels[1].teeth, a0,
                                     bar_diameter=bar, phases=8).links_max
        links = int(L.even_links(req))
    return dict(pitch=float(chain.pitch), bar_diameter=bar, teeth_carrier=int(carrier.teeth),
                teeth_fixed=int(fixed.teeth), carrier_centre=tuple(carrier.position),
                fixed_centre=tuple(fixed.position), links=int(links), torque=torque,
                carrier_driving=bool(carrier.driving), mass_per_length=float(chain.mass_per_length),
                travel=str(drive.travel), elongation_limit=float(drive.elongation_limit),
                speed=speed,
                sag_ratio=float(drive.slack_sag_ratio), wheel=carrier.name)


def self_regulating_analysis(drive: Drive, spec: SelfRegulatingSpec | Mapping[str, Any] | None = None
                             ) -> SelfRegulatingDriveResult:
    """The self-regulating drive model for a :class:`chaindrive.drive.Drive` and its spec.

    Parameters
    ----------
    drive : chaindrive.drive.Drive
        A two-wheel drive; read only (never modified).
    spec : SelfRegulatingSpec or mapping, optional
        The carrier; a mapping is read by :meth:`SelfRegulatingSpec.from_table`;
        default the drive's ``self_regulating``.

    Returns
    -------
    SelfRegulatingDriveResult
        Over load factors ``0 … spec.load_max_factor`` (nominal: the drive's load
        without service factor) and elongations ``0 … drive.elongation_limit``.

    Raises
    ------
    InputError, InfeasibleError
        See :func:`self_regulating_drive`.

    References
    ----------
    See :func:`self_regulating_drive`.

    Examples
    --------
    >>> from chaindrive.chains import get
    >>> from chaindrive.drive import Drive, Load, Wheel
    >>> d = Drive(chain=get("16B"), speed=100.0, load=Load(torque=300.0),
    ...           wheels=[Wheel("motor", "sprocket", 19, (0.6, 0.0), driving=True),
    ...                   Wheel("fan", "sprocket", 38, (0.0, 0.0))], links=76)
    >>> spec = SelfRegulatingSpec(wheel="motor", pivot=(0.66, -0.045), weight=400.0,
    ...                           weight_offset=(0.08, 0.0), numerical=False)
    >>> r = self_regulating_analysis(d, spec)
    >>> r.centre_distance.shape, r.links
    ((7, 4), 76)
    """
    if spec is None:
        spec = getattr(drive, "self_regulating", None)
        if spec is None:
            raise InputError("self_regulating: the drive has no [self_regulating] table (carrier spec)")
    if isinstance(spec, Mapping):
        spec = SelfRegulatingSpec.from_table(spec)
    if not isinstance(spec, SelfRegulatingSpec):
        raise InputError(f"spec must be a SelfRegulatingSpec or a table, got {type(spec).__name__}")
    inp = _drive_inputs(drive, spec)
    lam = np.linspace(0.0, float(spec.load_max_factor), int(spec.load_steps))
    e = np.linspace(0.0, inp.pop("elongation_limit"), int(spec.elongation_steps))
    sag = inp.pop("sag_ratio") if spec.sag_allowance is None else float(spec.sag_allowance)
    axial = spec.axial_stiffness
    if axial is None and inp["bar_diameter"] is not None:
        # studless chain: EA = 0.854e8 d² kN with d in m (OrcaFlex, "Chain: axial and
        # bending stiffness", from catalogue data)
        axial = 0.854e11 * inp["bar_diameter"] ** 2
    return self_regulating_drive(
        **inp, kind=spec.kind, pivot=spec.pivot, direction=spec.direction,
        torque_reaction=spec.torque_reaction, weight=float(spec.weight),
        weight_offset=spec.weight_offset, stiffness=float(spec.stiffness),
        preload=float(spec.preload), load_factors=lam, elongations=e, sag_allowance=sag,
        psi_tolerance=float(spec.psi_tolerance), numerical=bool(spec.numerical),
        inertia=spec.inertia, axial_stiffness=axial)


def self_regulating_checks(result: SelfRegulatingDriveResult) -> tuple[Any, ...]:
    """The result's checks as :class:`chaindrive.analysis.Check` verdicts.

    Parameters
    ----------
    result : SelfRegulatingDriveResult

    Returns
    -------
    tuple of chaindrive.analysis.Check
        Sag at the rated load within the allowance over the wear range; ``S2/F_t`` at the
        rated load within ``(1 + tolerance) ψ*``; the carrier statically stable; its
        natural frequency outside the tensioner paper's band (when the speed and an inertia
        or weight are known); closed form against the numerical equilibrium (when it was
        run).

    References
    ----------
    docs/self_regulating.md ("The rational ψ").

    Examples
    --------
    >>> r = self_regulating_drive(pitch=0.0254, teeth_carrier=19, teeth_fixed=38,
    ...     carrier_centre=(0.6, 0.0), fixed_centre=(0.0, 0.0), links=76, torque=300.0,
    ...     carrier_driving=True, mass_per_length=2.7, pivot=(0.66, -0.045), weight=400.0,
    ...     weight_offset=(0.08, 0.0), numerical=False)
    >>> [c.verdict for c in self_regulating_checks(r)]
    ['pass', 'FAIL', 'pass']
    """
    from ..analysis.checks import Check

    if not isinstance(result, SelfRegulatingDriveResult):
        raise InputError(f"result must be a SelfRegulatingDriveResult, got {type(result).__name__}")
    return tuple(Check(**c) for c in result.checks)
