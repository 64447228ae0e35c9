r"""Crawler (caterpillar) drive unit of a conveyor: the drive chain and its cams (the crawler drive text).

A *drive chain* (pitch ``t``) carrying cams runs around a driving and a tensioning
sprocket with the same tooth count ``z``, turning **in phase**, at centre distance ``A``
(a whole number of pitches). The cams engage the traction chain of the conveyor.

Sketch (SI units)::

        tensioning sprocket 1                          driving sprocket 2
              ___                 cam at l                  ___
        ..o--/   \--o-----o-----o--[K]--o-----o-----o-----o/   \o..   y = R (guide)
             \ O1/             chain moves -->              \O2 /
              ---                                            ---
        |<--------------------------- A ------------------------->|
        |<------ l ------>|

Two cases (``guide=``):

``"none"`` (no guide, the crawler drive text eq. (6.7), Fig. 6.9 a)
    The straight span rests on the highest vertex of each pitch polygon; with both
    sprockets in phase it stays horizontal, keeps its length ``A`` and moves sideways
    (transverse throw ``R(1 - cos γ)``, ``γ = π/z``). Its longitudinal displacement,
    velocity and acceleration follow the chordal-action law

    .. math::
        u = R\,[\sin(ψ - γ) + \sin γ],\quad v = ωR\cos(ψ - γ),\quad
        a = -ω^2R\sin(ψ - γ),\qquad 0 \le ψ < 2γ,

    where ``ψ`` is the sprocket angle counted from the moment the highest vertex
    changes (then two vertices at ``±γ`` are equally high), so the span rests on the
    vertex at angle ``β = ψ - γ`` from the top.

``"tangent"`` (guide holding the chain axis tangent to the pitch circles, Fig. 6.9 b)
    The chain lies on the guide line ``y = R``. At the driving sprocket (chain running
    on) the last seated hinge ``S`` is at angle ``ψ1`` past the top (the tangency point
    ``T``), at ``(-R sin ψ1, R cos ψ1)``; the next hinge ``G`` lies on the guide line at
    ``(x_G, R)``; the link ``SG`` of length ``t`` is inclined at ``φ1`` to the guide.
    Heights give eq. (6.15), **printed form correct**:

    .. math:: R = R\cos ψ_1 + t\sin φ_1
              \;\Rightarrow\; \sin φ_1 = \frac{2R\sin^2(ψ_1/2)}{t},

    and ``x_G = -R sin ψ1 + t cos φ1`` goes from ``t`` (``ψ1 = 0``) to ``0``
    (``ψ1 = 2γ``, ``φ1 = γ``: ``G`` reaches ``T`` and seats). The displacement of the
    chain towards the sprocket, ``u_З = t - x_G``, is eq. (6.16), **printed form
    correct, sign ``+`` confirmed**:

    .. math:: u_З = R\sin ψ_1 + t\,(1 - \cos φ_1)

    and by differentiation (eq. 6.14) with ``dφ1/dψ1 = R sin ψ1 / (t cos φ1)``:

    .. math::
        v = ωR\,\frac{\cos(ψ_1 - φ_1)}{\cos φ_1},\qquad
        a = ω^2R\left[-\sin ψ_1 + \cos ψ_1\tan φ_1
            + \frac{R\sin^2 ψ_1}{t\cos^3 φ_1}\right].

    Seating event (``ψ1 = 2γ``): ``G`` reaches the tangency point, becomes the seated
    hinge at ``ψ1 = 0`` and the next hinge on the guide takes its place. Displacement
    and velocity are continuous there (``v = ωR`` on both sides); the acceleration
    jumps from ``ω²R tan γ`` to ``0`` (the "kink" of curve 1 in Fig. 6.9 c). At the
    tensioning sprocket (chain running off) the motion is the mirror image in time:
    ``u_1(ψ) = t - u_З(2γ - ψ)``, ``v_1(ψ) = v(2γ - ψ)``.

Both laws have the mean speed ``z t ω / 2π`` (advance ``t`` per period ``2γ``).

Elastic drive chain and the force on the cam (formula lost in the OCR of the crawler drive text,
rebuilt here): see :func:`cam_stiffness` and :func:`cam_force`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from .._finite import finite_guard
from .._registry import Registry
from .._results import Result, quantity
from .._typing import FloatOrArray
from .._validation import as_float_array, check_positive, check_teeth
from ..errors import InfeasibleError, InputError
from ..geometry.polygon import roller_chain_pitch_radius
from ..loads import mean_chain_speed

__all__ = [
    "GUIDES",
    "MEASURES",
    "CrawlerKinematics",
    "cam_force",
    "cam_hinge_distance",
    "cam_stiffness",
    "crawler_drive",
    "crawler_nonuniformity",
    "free_span_acceleration",
    "free_span_displacement",
    "free_span_height",
    "free_span_velocity",
    "guide_link_angle",
    "guided_acceleration",
    "guided_displacement",
    "guided_velocity",
    "leaving_displacement",
]

#: Guide types of the crawler drive: ``"none"`` (free span) and ``"tangent"``.
GUIDES = Registry("guide")
GUIDES.add("none", "none")
GUIDES.add("tangent", "tangent")


# ----------------------------------------------------------------------------- helpers


def _geometry(pitch, teeth):
    t = check_positive("pitch", pitch, "m")
    z = check_teeth("teeth", teeth)
    gamma = np.pi / z
    R = roller_chain_pitch_radius(t, z)
    return t, z, gamma, R


def _reduce(sprocket_angle, gamma):
    """Split ψ into whole periods ``n`` and the phase ``s`` in ``[0, 2γ)``."""
    psi = as_float_array("sprocket_angle", sprocket_angle)
    if np.any(~np.isfinite(psi)):
        raise InputError("sprocket_angle must be finite (-inf < ψ < inf rad)")
    period = 2.0 * gamma
    n = np.floor(psi / period)
    s = psi - n * period
    # guard round-off: s must lie in [0, period)
    over = s >= period
    n = np.where(over, n + 1, n)
    s = np.where(over, s - period, s)
    return n, np.clip(s, 0.0, None), period


def _omega(angular_velocity):
    return check_positive("angular_velocity", angular_velocity, "rad/s")


def _out(x):
    return x[()] if isinstance(x, np.ndarray) and x.ndim == 0 else x


# ----------------------------------------------------------------------------- free span


def free_span_displacement(sprocket_angle: ArrayLike, pitch: float, teeth: int) -> FloatOrArray:
    r"""Longitudinal displacement of the free (unguided) span [m].

    .. math:: u = n\,t + R\,[\sin(s - γ) + \sin γ],\quad ψ = 2γ n + s,\ 0 \le s < 2γ

    Parameters
    ----------
    sprocket_angle : float or array_like
        Sprocket angle ``ψ`` from the change of the supporting vertex [rad]; any real
        value (periodic continuation, ``t`` per period ``2π/z``).
    pitch : float
        Chain pitch ``t`` [m].
    teeth : int
        Tooth count ``z >= 3`` of both sprockets [-].

    Returns
    -------
    ndarray or float
        Displacement ``u`` of the span along its length, ``u(0) = 0`` [m].

    Notes
    -----
    The span rests on the highest polygon vertex, at ``β = s - γ`` from the top, so its
    ends move with that vertex: ``x = R sin β``. Valid for in-phase sprockets with the
    same ``z`` and a centre distance that is a whole number of pitches (the span stays
    horizontal and rigid).

    References
    ----------
    the crawler drive text, eq. (6.7) (chordal-action law, printed formula lost in the OCR; derived).

    Examples
    --------
    >>> import numpy as np
    >>> float(free_span_displacement(2 * np.pi / 8, 0.1, 8))
    0.1
    """
    t, z, gamma, R = _geometry(pitch, teeth)
    n, s, _ = _reduce(sprocket_angle, gamma)
    return _out(n * t + R * (np.sin(s - gamma) + np.sin(gamma)))


def free_span_velocity(sprocket_angle: ArrayLike, pitch: float, teeth: int, angular_velocity: float) -> FloatOrArray:
    r"""Longitudinal velocity of the free span, the chordal-action law [m/s].

    .. math:: v = ωR\cos(s - γ),\qquad γ = π/z

    Parameters
    ----------
    sprocket_angle : float or array_like
        ``ψ`` [rad] (see :func:`free_span_displacement`).
    pitch : float
        ``t`` [m].
    teeth : int
        ``z >= 3`` [-].
    angular_velocity : float
        Sprocket angular velocity ``ω > 0`` [rad/s].

    Returns
    -------
    ndarray or float
        ``v`` [m/s]; ``ωR cos γ <= v <= ωR``.

    Notes
    -----
    Right-continuous at ``ψ = 2γk`` (continuous anyway: ``v = ωR cos γ`` on both sides).

    References
    ----------
    the crawler drive text, eq. (6.7); Dolipiński et al., eqs (1)-(2) for ``d = 0``.

    Examples
    --------
    >>> round(float(free_span_velocity(0.0, 0.1, 8, 1.0)), 6)   # ωR cos(π/8) = ωt/(2 tan(π/8))
    0.12071
    """
    t, z, gamma, R = _geometry(pitch, teeth)
    w = _omega(angular_velocity)
    _, s, _ = _reduce(sprocket_angle, gamma)
    return _out(w * R * np.cos(s - gamma))


def free_span_acceleration(sprocket_angle: ArrayLike, pitch: float, teeth: int, angular_velocity: float) -> FloatOrArray:
    r"""Longitudinal acceleration of the free span [m/s²].

    .. math:: a = -ω^2R\sin(s - γ)

    Parameters
    ----------
    sprocket_angle : float or array_like
        ``ψ`` [rad].
    pitch : float
        ``t`` [m].
    teeth : int
        ``z >= 3`` [-].
    angular_velocity : float
        ``ω > 0`` [rad/s] (constant).

    Returns
    -------
    ndarray or float
        ``a`` [m/s²]; right-continuous: at ``ψ = 2γk`` it jumps from ``-ω²R sin γ``
        to ``+ω²R sin γ``.

    Notes
    -----
    Valid for constant ``ω``, in-phase sprockets.

    References
    ----------
    the crawler drive text, eq. (6.7) differentiated; Dolipiński et al., eqs (10)-(11) for ``d = 0``.

    Examples
    --------
    >>> round(float(free_span_acceleration(0.0, 0.1, 8, 1.0)), 6)   # ω²R sin γ = ω² t / 2
    0.05
    """
    t, z, gamma, R = _geometry(pitch, teeth)
    w = _omega(angular_velocity)
    _, s, _ = _reduce(sprocket_angle, gamma)
    return _out(-(w**2) * R * np.sin(s - gamma))


def free_span_height(sprocket_angle: ArrayLike, pitch: float, teeth: int) -> FloatOrArray:
    r"""Height of the free span above the sprocket axes (its sideways motion) [m].

    .. math:: y = R\cos(s - γ)

    Parameters
    ----------
    sprocket_angle : float or array_like
        ``ψ`` [rad].
    pitch : float
        ``t`` [m].
    teeth : int
        ``z >= 3`` [-].

    Returns
    -------
    ndarray or float
        ``y`` [m], between ``R cos γ`` and ``R``: the transverse throw is ``R(1 - cos γ)``.

    Notes
    -----
    The span moves parallel to itself (both sprockets in phase).

    References
    ----------
    the crawler drive text, text to Fig. 6.9 a (transverse motion of the sides AB, ВГ).

    Examples
    --------
    >>> round(float(free_span_height(0.0, 0.1, 8)), 6)   # R cos(π/8)
    0.12071
    """
    t, z, gamma, R = _geometry(pitch, teeth)
    _, s, _ = _reduce(sprocket_angle, gamma)
    return _out(R * np.cos(s - gamma))


# ----------------------------------------------------------------------------- tangent guide


def guide_link_angle(sprocket_angle: ArrayLike, pitch: float, teeth: int) -> FloatOrArray:
    r"""Inclination ``φ1`` of the link between the sprocket and the guide, eq. (6.15) [rad].

    .. math:: R = R\cos ψ_1 + t\sin φ_1 \;\Rightarrow\;
              φ_1 = \arcsin\frac{2R\sin^2(ψ_1/2)}{t},\quad 0 \le ψ_1 < 2γ

    Parameters
    ----------
    sprocket_angle : float or array_like
        ``ψ1``: angle of the last seated hinge past the tangency point [rad]; reduced
        modulo ``2γ = 2π/z``.
    pitch : float
        ``t`` [m].
    teeth : int
        ``z >= 3`` [-].

    Returns
    -------
    ndarray or float
        ``φ1`` in ``[0, γ)`` [rad]; ``φ1 -> γ`` as ``ψ1 -> 2γ`` (the link becomes a
        polygon side).

    Notes
    -----
    Derivation: the seated hinge is at height ``R cos ψ1``, the hinge on the guide at
    height ``R``; the link of length ``t`` between them rises by ``t sin φ1``. The
    printed eq. (6.15) is correct (``t_П`` = the drive-chain pitch ``t``).

    References
    ----------
    the crawler drive text, eq. (6.15).

    Examples
    --------
    >>> import numpy as np
    >>> round(float(guide_link_angle(2 * np.pi / 8 - 1e-12, 0.1, 8)), 6), round(np.pi / 8, 6)
    (0.392699, 0.392699)
    """
    t, z, gamma, R = _geometry(pitch, teeth)
    _, s, _ = _reduce(sprocket_angle, gamma)
    return _out(np.arcsin(np.minimum(2.0 * R * np.sin(0.5 * s) ** 2 / t, 1.0)))


def _guided_parts(s, t, R):
    sin_phi = 2.0 * R * np.sin(0.5 * s) ** 2 / t
    cos_phi = np.sqrt(1.0 - sin_phi**2)
    return sin_phi, cos_phi


def guided_displacement(sprocket_angle: ArrayLike, pitch: float, teeth: int) -> FloatOrArray:
    r"""Displacement of the chain on the tangent guide towards the sprocket, eq. (6.16) [m].

    .. math:: u_З = n\,t + R\sin s + t\,(1 - \cos φ_1),\quad ψ_1 = 2γ n + s

    Parameters
    ----------
    sprocket_angle : float or array_like
        ``ψ1`` [rad]; any real value (``t`` per period ``2γ``).
    pitch : float
        ``t`` [m].
    teeth : int
        ``z >= 3`` [-].

    Returns
    -------
    ndarray or float
        ``u_З``, ``u_З(0) = 0``, ``u_З(2γ) = t`` [m].

    Notes
    -----
    ``u_З = t - x_G`` with ``x_G = -R sin ψ1 + t cos φ1`` the abscissa of the hinge on
    the guide (origin at the sprocket axis, tangency point at ``x = 0``). The printed
    eq. (6.16), ``u_З = R sin ψ1 + t(1 - cos φ1)``, is correct including the ``+``
    sign of the second term; ``t_T`` there is the drive-chain pitch ``t`` (OCR). For
    the tensioning sprocket (chain running off) see :func:`leaving_displacement`.

    References
    ----------
    the crawler drive text, eqs (6.15)-(6.16).

    Examples
    --------
    >>> import numpy as np
    >>> round(float(guided_displacement(2 * np.pi / 8 - 1e-12, 0.1, 8)), 9)
    0.1
    """
    t, z, gamma, R = _geometry(pitch, teeth)
    n, s, _ = _reduce(sprocket_angle, gamma)
    sin_phi, cos_phi = _guided_parts(s, t, R)
    return _out(n * t + R * np.sin(s) + t * (1.0 - cos_phi))


def guided_velocity(sprocket_angle: ArrayLike, pitch: float, teeth: int, angular_velocity: float) -> FloatOrArray:
    r"""Velocity of the chain on the tangent guide, eq. (6.14) with (6.15) [m/s].

    .. math:: v = ωR\left(\cos ψ_1 + \sin ψ_1\tan φ_1\right)
              = ωR\,\frac{\cos(ψ_1 - φ_1)}{\cos φ_1}

    Parameters
    ----------
    sprocket_angle : float or array_like
        ``ψ1`` [rad].
    pitch : float
        ``t`` [m].
    teeth : int
        ``z >= 3`` [-].
    angular_velocity : float
        ``ω > 0`` [rad/s].

    Returns
    -------
    ndarray or float
        ``v`` [m/s]; ``v = ωR`` at both ends of the period (continuous at seating).

    Notes
    -----
    From ``d(6.16)/dψ1`` with ``dφ1/dψ1 = R sin ψ1 / (t cos φ1)`` (from 6.15). The
    printed (6.4)/(6.14) are lost in the OCR; this is derived.

    References
    ----------
    the crawler drive text, eqs (6.14)-(6.16).

    Examples
    --------
    >>> r = 0.1 / (2 * np.sin(np.pi / 8))
    >>> round(float(guided_velocity(0.0, 0.1, 8, 1.0) / r), 12)
    1.0
    """
    t, z, gamma, R = _geometry(pitch, teeth)
    w = _omega(angular_velocity)
    _, s, _ = _reduce(sprocket_angle, gamma)
    sin_phi, cos_phi = _guided_parts(s, t, R)
    return _out(w * R * (np.cos(s) + np.sin(s) * sin_phi / cos_phi))


def guided_acceleration(sprocket_angle: ArrayLike, pitch: float, teeth: int, angular_velocity: float) -> FloatOrArray:
    r"""Acceleration of the chain on the tangent guide [m/s²].

    .. math:: a = ω^2R\left[-\sin ψ_1 + \cos ψ_1\tan φ_1
              + \frac{R\sin^2 ψ_1}{t\cos^3 φ_1}\right]

    Parameters
    ----------
    sprocket_angle : float or array_like
        ``ψ1`` [rad].
    pitch : float
        ``t`` [m].
    teeth : int
        ``z >= 3`` [-].
    angular_velocity : float
        ``ω > 0`` [rad/s] (constant).

    Returns
    -------
    ndarray or float
        ``a`` [m/s²]; right-continuous: ``a(0+) = 0``, ``a(2γ-) = ω²R tan γ``, so it
        jumps by ``-ω²R tan γ`` at each seating.

    Notes
    -----
    Second derivative of (6.16) in ``ψ1`` times ``ω²``.

    References
    ----------
    the crawler drive text, eqs (6.14)-(6.16) (derived).

    Examples
    --------
    >>> float(guided_acceleration(0.0, 0.1, 8, 1.0))
    0.0
    """
    t, z, gamma, R = _geometry(pitch, teeth)
    w = _omega(angular_velocity)
    _, s, _ = _reduce(sprocket_angle, gamma)
    sin_phi, cos_phi = _guided_parts(s, t, R)
    val = -np.sin(s) + np.cos(s) * sin_phi / cos_phi + R * np.sin(s) ** 2 / (t * cos_phi**3)
    return _out(w**2 * R * val)


def leaving_displacement(sprocket_angle: ArrayLike, pitch: float, teeth: int, guide: str="tangent") -> FloatOrArray:
    r"""Displacement of the chain running *off* the tensioning sprocket, in phase [m].

    .. math:: u_1(ψ) = t - u(2γ - s) + n\,t \quad(\text{tangent guide}),\qquad
              u_1 = u \quad(\text{no guide})

    Parameters
    ----------
    sprocket_angle : float or array_like
        ``ψ`` [rad], same clock as the driving sprocket (sprockets in phase).
    pitch : float
        ``t`` [m].
    teeth : int
        ``z >= 3`` [-].
    guide : {"tangent", "none"}
        Guide type.

    Returns
    -------
    ndarray or float
        ``u_1`` [m], ``u_1(0) = 0``.

    Notes
    -----
    Running off is running on mirrored in space and reversed in time. Without a guide
    the span is rigid, so both ends move alike; with the tangent guide the two ends
    follow the mirrored laws and the span between them is stretched by
    ``u_З - u_1`` (zero mean, period ``2γ``).

    References
    ----------
    the crawler drive text, Fig. 6.9 (in-phase sprockets); derived.

    Examples
    --------
    >>> import numpy as np
    >>> round(float(leaving_displacement(np.pi / 8, 0.1, 8)), 9) == round(0.1 - float(guided_displacement(np.pi / 8, 0.1, 8)), 9)
    True
    """
    kind = GUIDES.get(guide)
    t, z, gamma, R = _geometry(pitch, teeth)
    if kind == "none":
        return free_span_displacement(sprocket_angle, pitch, teeth)
    n, s, period = _reduce(sprocket_angle, gamma)
    m = period - s  # in (0, 2γ]
    sin_phi, cos_phi = _guided_parts(m, t, R)
    u_in = R * np.sin(m) + t * (1.0 - cos_phi)
    return _out(n * t + t - u_in)


# ----------------------------------------------------------------------------- elastic chain


def cam_stiffness(stiffness: ArrayLike, sprocket_distance: ArrayLike, cam_distance: ArrayLike) -> FloatOrArray:
    r"""Stiffness of the drive chain at the cam hinge, two segments in parallel [N/m].

    .. math:: k = \frac{E_П}{l} + \frac{E_П}{A - l} = \frac{E_П\,A}{l\,(A - l)}

    Parameters
    ----------
    stiffness : float or array_like
        Reduced stiffness ``E_П`` of the drive chain, as axial rigidity ``EA`` [N]
        (force per unit strain; a segment of length ``L`` has stiffness ``E_П/L``).
    sprocket_distance : float or array_like
        Centre distance ``A`` between the sprockets [m].
    cam_distance : float or array_like
        Distance ``l`` of the cam hinge from the tensioning sprocket, ``0 < l < A`` [m].

    Returns
    -------
    ndarray or float
        ``k`` [N/m]; smallest, ``4E_П/A``, at ``l = A/2``; ``k -> inf`` as ``l -> 0``
        or ``l -> A`` (the cam sits on a sprocket).

    Notes
    -----
    The cam hinge splits the working span into a segment ``l`` to the tensioning
    sprocket and ``A - l`` to the driving sprocket. Both sprocket ends impose
    displacements on the chain and the cam hinge is displaced against both, so the
    segments act in **parallel** (same displacement difference, forces add), not in
    series. Linear elastic chain, massless, tension always positive (pre-tension),
    no friction on the guide.

    References
    ----------
    the crawler drive text, text after eq. (6.16) (formula lost in the OCR; rebuilt).

    Examples
    --------
    >>> float(cam_stiffness(1e6, 2.0, 1.0))   # 4 E/A
    2000000.0
    """
    E = check_positive("stiffness", stiffness, "N")
    A = check_positive("sprocket_distance", sprocket_distance, "m")
    l = as_float_array("cam_distance", cam_distance)
    if np.any(~(l > 0)) or np.any(~(l < A)) or np.any(~np.isfinite(l)):
        raise InputError(
            f"cam_distance must lie in (0, sprocket_distance) = (0, A) m, got l = {l} with A = {A}"
        )
    return _out(E * A / (l * (A - l)))


def cam_force(stiffness: ArrayLike, sprocket_distance: ArrayLike, cam_distance: ArrayLike, sprocket_displacement: ArrayLike,
              cam_displacement: ArrayLike, tensioning_displacement: ArrayLike | None=None) -> FloatOrArray:
    r"""Force of the elastic drive chain on the cam hinge [N].

    .. math::
        P = E_П\left[\frac{u_З - u_П}{A - l} + \frac{u_1 - u_П}{l}\right]
        \;\overset{u_1 = u_З}{=}\; \frac{E_П\,A}{l\,(A - l)}\,(u_З - u_П)

    Parameters
    ----------
    stiffness : float or array_like
        ``E_П`` = ``EA`` of the drive chain [N].
    sprocket_distance : float or array_like
        ``A`` [m].
    cam_distance : float or array_like
        ``l`` from the tensioning sprocket, ``0 < l < A`` [m]; ``l = l1 + k t_K``
        (:func:`cam_hinge_distance`).
    sprocket_displacement : float or array_like
        ``u_З``: displacement of the drive chain at the driving sprocket [m].
    cam_displacement : float or array_like
        ``u_П``: displacement of the cam hinge (imposed by the traction chain) [m].
    tensioning_displacement : float or array_like, optional
        ``u_1``: displacement of the drive chain at the tensioning sprocket [m];
        default ``u_З`` (sprockets in phase with the same law: exact without a guide).

    Returns
    -------
    ndarray or float
        ``P`` [N], positive in the direction of motion (the chain pulls the cam ahead).

    Notes
    -----
    Equilibrium of the cam hinge between the two segments: segment ``A - l`` is
    stretched by ``u_З - u_П`` (force ``E_П (u_З - u_П)/(A - l)``), segment ``l`` by
    ``u_1 - u_П``; the forces add (parallel). With a common end law the paper's
    quantities ``E_П, A, l, u_З, u_П`` give the closed form above. Forces are changes
    about the static pre-tension. Limits: ``l -> 0`` gives ``E_П (u_1 - u_П)/l`` (the
    near segment dominates); ``E_П -> inf`` at fixed force forces ``u_П -> u_З``.

    References
    ----------
    the crawler drive text, text after eq. (6.16) (formula lost in the OCR; rebuilt).

    Examples
    --------
    >>> float(cam_force(1e6, 2.0, 0.5, 1e-3, 0.0))   # 1e6*2/(0.5*1.5) * 1e-3
    2666.6666666666665
    """
    E = check_positive("stiffness", stiffness, "N")
    A = check_positive("sprocket_distance", sprocket_distance, "m")
    cam_stiffness(E, A, cam_distance)  # validates l
    l = as_float_array("cam_distance", cam_distance)
    u2 = as_float_array("sprocket_displacement", sprocket_displacement)
    up = as_float_array("cam_displacement", cam_displacement)
    u1 = u2 if tensioning_displacement is None else as_float_array(
        "tensioning_displacement", tensioning_displacement)
    for name, arr in (("sprocket_displacement", u2), ("cam_displacement", up),
                      ("tensioning_displacement", u1)):
        if np.any(~np.isfinite(arr)):
            raise InputError(f"{name} must be finite (-inf < u < inf m)")
    return _out(E * ((u2 - up) / (A - l) + (u1 - up) / l))


def cam_hinge_distance(engagement_distance: float, cam_pitch: float, index: ArrayLike) -> FloatOrArray:
    r"""Distance ``l = l1 + k t_K`` of the k-th cam hinge from the tensioning sprocket [m].

    .. math:: l = l_1 + k\,t_K

    Parameters
    ----------
    engagement_distance : float
        ``l1``: value of ``l`` at which a cam engages a hinge of the traction chain [m].
    cam_pitch : float
        Cam pitch ``t_K`` [m].
    index : int or array_like
        ``k = 0, 1, 2, ...`` [-].

    Returns
    -------
    ndarray or float
        ``l`` [m].

    Notes
    -----
    Pure bookkeeping; check ``0 < l < A`` with :func:`cam_stiffness`.

    References
    ----------
    the crawler drive text, last line.

    Examples
    --------
    >>> float(cam_hinge_distance(0.3, 0.4, 2))
    1.1
    """
    l1 = check_positive("engagement_distance", engagement_distance, "m")
    tk = check_positive("cam_pitch", cam_pitch, "m")
    k = as_float_array("index", index)
    if np.any(k < 0) or np.any(k != np.round(k)):
        raise InputError(f"index must be a whole number >= 0, got {k}")
    return _out(l1 + k * tk)


# ----------------------------------------------------------------------------- workflow

#: Keys of :attr:`CrawlerKinematics.summary` always present.
SUMMARY_KEYS = (
    "v_mean", "v_min", "v_max", "nonuniformity", "a_min", "a_max",
    "sign_change_at_period_end", "transverse_throw",
)


@dataclass(frozen=True)
class CrawlerKinematics(Result):
    """Kinematics (and optionally the cam force) of the crawler drive over ``psi``.

    Attributes
    ----------
    psi : ndarray
        Sprocket angles ``ψ`` [rad] (default one period ``0 ... 2π/z``).
    displacement, velocity, acceleration : ndarray
        ``u`` [m], ``v`` [m/s], ``a`` [m/s²] of the drive chain at the driving sprocket
        (right-continuous at the period ends).
    transverse_position : ndarray
        Height of the chain above the sprocket axes [m] (``R`` with the guide).
    link_angle : ndarray or None
        ``φ1`` of eq. (6.15) [rad] (tangent guide only).
    force : ndarray or None
        Force on the cam [N] (:func:`cam_force`) with the cam driven at the mean speed
        (``u_П = v_mean t``), minus its mean over a period (the mean is the transmitted
        load, not a kinematic quantity); ``None`` without ``stiffness``.
    summary : dict
        ``v_mean``, ``v_min``, ``v_max`` [m/s], ``nonuniformity`` = (v_max - v_min)/v_mean
        [-], ``a_min``, ``a_max`` [m/s²], ``sign_change_at_period_end`` (bool),
        ``transverse_throw`` [m], ``a_end_left``, ``a_end_right``, ``a_jump_at_period_end``
        [m/s²], ``psi_v_min`` [rad], ``peak_deviation`` = max|v - v_mean| [m/s]; with stiffness ``cam_stiffness`` [N/m],
        ``force_min``, ``force_max``, ``force_range`` [N]. Exact over a whole period
        (the minimum of the guided speed is found by root finding), not on ``psi``.
    guide : str
        ``"none"`` or ``"tangent"``.
    pitch, radius : float
        ``t``, ``R`` [m].
    teeth : int
        ``z``.
    angular_velocity : float
        ``ω`` [rad/s].
    period : float
        ``2π/z`` [rad].
    stiffness, sprocket_distance, cam_distance : float or None
        ``E_П`` [N], ``A`` [m], ``l`` [m].
    """

    psi: np.ndarray = quantity("rad")
    displacement: np.ndarray = quantity("m")
    velocity: np.ndarray = quantity("m/s")
    acceleration: np.ndarray = quantity("m/s^2")
    transverse_position: np.ndarray = quantity("m")
    link_angle: np.ndarray | None = quantity("rad")
    force: np.ndarray | None = quantity("N")
    summary: dict
    guide: str
    pitch: float = quantity("m")
    radius: float = quantity("m")
    teeth: int = quantity("1")
    angular_velocity: float = quantity("rad/s")
    period: float = quantity("rad")
    stiffness: float | None = quantity("N", default=None)
    sprocket_distance: float | None = quantity("m", default=None)
    cam_distance: float | None = quantity("m", default=None)


def _guided_vmin_angle(t, R, gamma):
    """Angle of the guided speed minimum: root of a(ψ) in (0, 2γ), vectorised bisection."""
    t, R, gamma = np.broadcast_arrays(np.asarray(t, float), np.asarray(R, float),
                                      np.asarray(gamma, float))
    lo = 1e-6 * gamma
    hi = 2.0 * gamma * (1.0 - 1e-12)

    def acc(s):
        sp, cp = _guided_parts(s, t, R)
        return -np.sin(s) + np.cos(s) * sp / cp + R * np.sin(s) ** 2 / (t * cp**3)

    for _ in range(80):
        mid = 0.5 * (lo + hi)
        neg = acc(mid) < 0
        lo = np.where(neg, mid, lo)
        hi = np.where(neg, hi, mid)
    return 0.5 * (lo + hi)


#: Measures of speed non-uniformity for :func:`crawler_nonuniformity`.
MEASURES = Registry("measure")
MEASURES.add("range", "range")
MEASURES.add("peak_deviation", "peak_deviation")


def crawler_nonuniformity(teeth: ArrayLike, guide: str="tangent", measure: str="range") -> FloatOrArray:
    r"""Speed non-uniformity ``(v_max - v_min)/v_mean`` of the crawler drive chain [-].

    .. math::
        δ_{none} = (1 - \cos γ)\,\frac{γ}{\sin γ},\qquad
        δ_{tangent} = \left(1 - \frac{\cos(ψ^* - φ^*)}{\cos φ^*}\right)\frac{γ}{\sin γ}

    Parameters
    ----------
    teeth : int or array_like
        ``z >= 3`` [-] (vectorised).
    guide : {"tangent", "none"}
        Guide type.
    measure : {"range", "peak_deviation"}
        ``"range"``: ``(v_max - v_min)/v_mean`` (the usual coefficient);
        ``"peak_deviation"``: ``max|v - v_mean| / v_mean``.

    Returns
    -------
    ndarray or float
        Non-uniformity, independent of pitch and speed [-].

    Notes
    -----
    ``v_max = ωR`` in both cases and ``v_mean = zωt/2π = ωR sin γ / γ``. With the guide
    ``ψ*`` is the root of ``a(ψ) = 0`` in ``(0, 2γ)`` (≈ ``4γ/3``). For small ``γ``:
    ``δ_none ≈ γ²/2``, ``δ_tangent ≈ 8γ²/27``; the ratio tends to ``16/27 ≈ 0.593``
    (the crawler drive text claims "almost 2 times"; it is a factor of about 1.69). The peak
    deviation from the mean, ``max|v - v_mean|``, is halved: free ``v_mean - v_min ≈
    ωRγ²/3``, guided ``v_max - v_mean ≈ ωRγ²/6``.

    References
    ----------
    the crawler drive text, eqs (6.7), (6.14)-(6.16) and the text to Fig. 6.9 c.

    Examples
    --------
    >>> r = crawler_nonuniformity(8, "tangent") / crawler_nonuniformity(8, "none")
    >>> round(float(r), 4)
    0.5923
    """
    kind = GUIDES.get(guide)
    how = MEASURES.get(measure)
    z = check_teeth("teeth", teeth)
    gamma = np.pi / z
    vmean = np.sin(gamma) / gamma  # in units of ωR
    if kind == "none":
        vmin = np.cos(gamma)
    else:
        t = 1.0
        R = 0.5 / np.sin(gamma)
        s = _guided_vmin_angle(t, R, gamma)
        sp, cp = _guided_parts(s, t, R)
        vmin = np.cos(s) + np.sin(s) * sp / cp
    if how == "range":
        return _out((1.0 - vmin) / vmean)
    return _out(np.maximum(1.0 - vmean, vmean - vmin) / vmean)


@finite_guard
def crawler_drive(pitch: float, teeth: int, angular_velocity: float, *, guide: str="tangent", with_guide: bool | None=None,
                  points: int=361, psi: ArrayLike | None=None, stiffness: float | None=None, sprocket_distance: float | None=None,
                  cam_distance: float | None=None) -> CrawlerKinematics:
    r"""Kinematics of the crawler drive chain with or without the tangent guide (the crawler drive text).

    .. math:: v_{none} = ωR\cos(ψ - γ),\qquad
              v_{tangent} = ωR\,\frac{\cos(ψ_1 - φ_1)}{\cos φ_1},\ \
              R = R\cos ψ_1 + t\sin φ_1

    Parameters
    ----------
    pitch : float
        Drive-chain pitch ``t`` [m].
    teeth : int
        Tooth count ``z >= 3`` of both sprockets [-].
    angular_velocity : float
        Sprocket angular velocity ``ω > 0`` [rad/s].
    guide : {"tangent", "none"}
        Tangent guide (chain axis tangent to the pitch circles) or no guide.
    with_guide : bool, optional
        Alternative to ``guide``: ``True`` -> ``"tangent"``, ``False`` -> ``"none"``.
    points : int
        Samples over one period when ``psi`` is not given (``>= 2``).
    psi : array_like, optional
        Sprocket angles [rad] to evaluate at instead of one period.
    stiffness : float, optional
        ``E_П`` = ``EA`` of the drive chain [N]; with ``sprocket_distance`` and
        ``cam_distance`` adds the cam force.
    sprocket_distance : float, optional
        ``A`` [m], a whole number of pitches (sprockets in phase).
    cam_distance : float, optional
        ``l`` from the tensioning sprocket, ``0 < l < A`` [m].

    Returns
    -------
    CrawlerKinematics

    Notes
    -----
    The cam force assumes the traction chain moves the cam at the mean speed
    (``u_П = v_mean t``, a heavy conveyor) and, with the guide, takes the running-off
    law at the tensioning sprocket (:func:`leaving_displacement`). Valid for constant
    ``ω``, rigid sprockets, in-phase sprockets with equal ``z``.

    References
    ----------
    the crawler drive text, eqs (6.7), (6.14)-(6.16), Fig. 6.9; cam force rebuilt (see :func:`cam_force`).

    Examples
    --------
    >>> r = crawler_drive(0.1, 8, 3.0, guide="tangent", points=5)
    >>> round(r.summary["v_mean"], 9) == round(8 * 0.1 * 3.0 / (2 * np.pi), 9)
    True
    >>> round(r.summary["nonuniformity"], 5)
    0.04627
    """
    if with_guide is not None:
        if not isinstance(with_guide, (bool, np.bool_)):
            raise InputError(f"with_guide must be True or False, got {with_guide!r}")
        kind = "tangent" if with_guide else "none"
    else:
        kind = GUIDES.get(guide)
    t, z, gamma, R = _geometry(pitch, teeth)
    if t.ndim or z.ndim:
        raise InputError("pitch and teeth must be scalars in crawler_drive (vectorise over psi)")
    t, z, R = float(t), int(z), float(R)
    w = _omega(angular_velocity)
    if w.ndim:
        raise InputError("angular_velocity must be a scalar in crawler_drive")
    w = float(w)
    period = 2.0 * gamma
    if psi is None:
        from ..limits import MAX_POINTS, check_size

        psi = np.linspace(0.0, period, check_size("points", points, MAX_POINTS, minimum=2))
    psi = np.atleast_1d(as_float_array("psi", psi))
    if kind == "none":
        u = free_span_displacement(psi, t, z)
        v = free_span_velocity(psi, t, z, w)
        a = free_span_acceleration(psi, t, z, w)
        y = free_span_height(psi, t, z)
        link = None
    else:
        u = guided_displacement(psi, t, z)
        v = guided_velocity(psi, t, z, w)
        a = guided_acceleration(psi, t, z, w)
        y = np.full_like(psi, R)
        link = guide_link_angle(psi, t, z)
    # right-continuous at the end of the period: keep the value at exactly 2γ left-sided
    # when psi is the default grid so that the curves close the period
    end = np.isclose(psi, period, rtol=0, atol=1e-12 * period)
    if np.any(end):
        left = period * (1.0 - 1e-13)
        if kind == "none":
            a = np.where(end, free_span_acceleration(left, t, z, w), a)
        else:
            a = np.where(end, guided_acceleration(left, t, z, w), a)
    v_mean = mean_chain_speed(z, t, w)
    v_max = w * R
    if kind == "none":
        psi_min = 0.0
        v_min = w * R * np.cos(gamma)
        a_left, a_right = -(w**2) * R * np.sin(gamma), w**2 * R * np.sin(gamma)
        a_min, a_max = a_left, a_right
        throw = R * (1.0 - np.cos(gamma))
    else:
        psi_min = float(_guided_vmin_angle(t, R, gamma))
        v_min = float(guided_velocity(psi_min, t, z, w))
        a_left, a_right = w**2 * R * np.tan(gamma), 0.0
        grid = np.linspace(0.0, period * (1.0 - 1e-13), 4001)
        ag = guided_acceleration(grid, t, z, w)
        i = int(np.argmin(ag))
        from scipy.optimize import minimize_scalar

        opt = minimize_scalar(lambda p: float(guided_acceleration(p, t, z, w)),
                              bounds=(grid[max(i - 1, 0)], grid[min(i + 1, grid.size - 1)]),
                              method="bounded", options={"xatol": 1e-14 * period})
        a_min = min(float(np.min(ag)), float(opt.fun))
        a_max = max(float(np.max(ag)), a_left)
        throw = 0.0
    summary = {
        "v_mean": v_mean,
        "v_min": float(v_min),
        "v_max": float(v_max),
        "nonuniformity": float((v_max - v_min) / v_mean),
        "a_min": float(a_min),
        "a_max": float(a_max),
        "sign_change_at_period_end": bool(a_left * a_right < 0),
        "transverse_throw": float(throw),
        "a_end_left": float(a_left),
        "a_end_right": float(a_right),
        "a_jump_at_period_end": float(a_right - a_left),
        "psi_v_min": float(psi_min),
        "peak_deviation": float(max(v_max - v_mean, v_mean - v_min)),
    }
    force = None
    given = [x is not None for x in (stiffness, sprocket_distance, cam_distance)]
    if any(given) and not all(given):
        raise InputError("the cam force needs all of stiffness (E_П > 0 N), "
                         "sprocket_distance (A > 0 m) and cam_distance (0 < l < A m)")
    if stiffness is not None and sprocket_distance is not None and cam_distance is not None:
        if any(np.ndim(x) for x in (stiffness, sprocket_distance, cam_distance)):
            raise InputError("stiffness, sprocket_distance and cam_distance must be scalars in "
                             "crawler_drive (use cam_force for arrays)")
        E = float(check_positive("stiffness", stiffness, "N"))
        A = float(check_positive("sprocket_distance", sprocket_distance, "m"))
        ratio = A / t
        if abs(ratio - round(ratio)) > 1e-9 * max(ratio, 1.0) or round(ratio) < 1:
            lo_, hi_ = max(np.floor(ratio), 1.0) * t, np.ceil(ratio) * t
            raise InfeasibleError(
                f"sprocket_distance must be a whole number of pitches (in-phase sprockets): "
                f"A = {A:g} m is {ratio:g} t; nearest valid {lo_:g} m or {hi_:g} m")
        k = float(cam_stiffness(E, A, cam_distance))
        l = float(cam_distance)

        def _force(p):
            u2 = guided_displacement(p, t, z) if kind == "tangent" else free_span_displacement(p, t, z)
            u1 = leaving_displacement(p, t, z, kind)
            return cam_force(E, A, l, u2, v_mean * p / w, u1)

        fine = np.linspace(0.0, period, 4001)
        ff = _force(fine)
        mean = float(np.trapezoid(ff, fine) / period)
        force = _force(psi) - mean
        summary.update({
            "cam_stiffness": k,
            "force_min": float(ff.min() - mean),
            "force_max": float(ff.max() - mean),
            "force_range": float(ff.max() - ff.min()),
        })
    return CrawlerKinematics(
        psi=psi, displacement=np.asarray(u), velocity=np.asarray(v),
        acceleration=np.asarray(a), transverse_position=np.asarray(y),
        link_angle=None if link is None else np.asarray(link), force=force,
        summary=summary, guide=kind, pitch=t, radius=R, teeth=z, angular_velocity=w,
        period=period,
        stiffness=None if stiffness is None else float(stiffness),
        sprocket_distance=None if sprocket_distance is None else float(sprocket_distance),
        cam_distance=None if cam_distance is None else float(cam_distance),
    )
