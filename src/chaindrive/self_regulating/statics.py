"""Carrier statics of the self-regulating drive: the worn centre distance, the carrier
position, the span lever arms, ψ, the slack tension and the restoring force (closed forms,
vectorised; derived in docs/self_regulating.md)."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from .. import layout as L
from .._validation import as_float_array, check_nonnegative, check_positive, check_range
from ..errors import InfeasibleError, InputError
from ..loads import sides_per_turn

CARRIER_KINDS = ("pivot", "slide")
TORQUE_REACTIONS = ("carrier", "frame")
GRAVITY = L.GRAVITY
_GRAVITY_DIRECTION = np.array([0.0, -1.0])  # drive coordinates: y up
_SOURCE = "self-regulating drive paper (conclusions); carrier statics derived in docs/self_regulating.md"

__all__ = [
    "CARRIER_KINDS",
    "TORQUE_REACTIONS",
    "GRAVITY",
    "worn_centre_distance",
    "carrier_position",
    "span_arms",
    "regulation_coefficient",
    "slack_tension",
    "restoring_force",
]

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
    """:func:`chaindrive.loads.sides_per_turn`, the link chain told by its bar diameter."""
    return float(sides_per_turn(int(teeth), bool(bar_diameter)))



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


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
