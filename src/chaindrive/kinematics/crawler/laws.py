r"""Crawler (caterpillar) drive unit of a conveyor: the kinematic laws of the drive chain (the crawler drive text).

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

import numpy as np
from numpy.typing import ArrayLike

from ..._docs import Fragments
from ..._registry import Registry
from ..._typing import FloatOrArray
from ..._validation import as_float_array, check_positive, check_teeth
from ...errors import InputError
from ...geometry.polygon import roller_chain_pitch_radius

__all__ = [
    "GUIDES",
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


#: The parameters the motion laws share, described once (:mod:`chaindrive._docs`).
_DOCS = Fragments(
    pitch_teeth="""
        pitch : float
            Chain pitch ``t`` [m].
        teeth : int
            Tooth count ``z >= 3`` of both sprockets [-].
    """,
    angular_velocity="""
        angular_velocity : float
            Sprocket angular velocity ``ω > 0`` [rad/s], constant.
    """,
    free_angle="""
        sprocket_angle : float or array_like
            Sprocket angle ``ψ`` from the change of the supporting vertex [rad]; any real
            value (periodic continuation, ``t`` per period ``2π/z``).
    """,
    guided_angle="""
        sprocket_angle : float or array_like
            ``ψ1``: angle of the last seated hinge past the tangency point [rad]; any real
            value (periodic continuation, ``t`` per period ``2γ = 2π/z``).
    """,
)
_DOCS.section("free_parameters", "free_angle", "pitch_teeth")
_DOCS.section("free_speed_parameters", "free_angle", "pitch_teeth", "angular_velocity")
_DOCS.section("guided_parameters", "guided_angle", "pitch_teeth")
_DOCS.section("guided_speed_parameters", "guided_angle", "pitch_teeth", "angular_velocity")


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


@_DOCS
def free_span_displacement(sprocket_angle: ArrayLike, pitch: float, teeth: int) -> FloatOrArray:
    r"""Longitudinal displacement of the free (unguided) span [m].

    .. math:: u = n\,t + R\,[\sin(s - γ) + \sin γ],\quad ψ = 2γ n + s,\ 0 \le s < 2γ

    %(free_parameters)s

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


@_DOCS
def free_span_velocity(sprocket_angle: ArrayLike, pitch: float, teeth: int, angular_velocity: float) -> FloatOrArray:
    r"""Longitudinal velocity of the free span, the chordal-action law [m/s].

    .. math:: v = ωR\cos(s - γ),\qquad γ = π/z

    %(free_speed_parameters)s

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


@_DOCS
def free_span_acceleration(sprocket_angle: ArrayLike, pitch: float, teeth: int, angular_velocity: float) -> FloatOrArray:
    r"""Longitudinal acceleration of the free span [m/s²].

    .. math:: a = -ω^2R\sin(s - γ)

    %(free_speed_parameters)s

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


@_DOCS
def free_span_height(sprocket_angle: ArrayLike, pitch: float, teeth: int) -> FloatOrArray:
    r"""Height of the free span above the sprocket axes (its sideways motion) [m].

    .. math:: y = R\cos(s - γ)

    %(free_parameters)s

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


@_DOCS
def guide_link_angle(sprocket_angle: ArrayLike, pitch: float, teeth: int) -> FloatOrArray:
    r"""Inclination ``φ1`` of the link between the sprocket and the guide, eq. (6.15) [rad].

    .. math:: R = R\cos ψ_1 + t\sin φ_1 \;\Rightarrow\;
              φ_1 = \arcsin\frac{2R\sin^2(ψ_1/2)}{t},\quad 0 \le ψ_1 < 2γ

    %(guided_parameters)s

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


@_DOCS
def guided_displacement(sprocket_angle: ArrayLike, pitch: float, teeth: int) -> FloatOrArray:
    r"""Displacement of the chain on the tangent guide towards the sprocket, eq. (6.16) [m].

    .. math:: u_З = n\,t + R\sin s + t\,(1 - \cos φ_1),\quad ψ_1 = 2γ n + s

    %(guided_parameters)s

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


@_DOCS
def guided_velocity(sprocket_angle: ArrayLike, pitch: float, teeth: int, angular_velocity: float) -> FloatOrArray:
    r"""Velocity of the chain on the tangent guide, eq. (6.14) with (6.15) [m/s].

    .. math:: v = ωR\left(\cos ψ_1 + \sin ψ_1\tan φ_1\right)
              = ωR\,\frac{\cos(ψ_1 - φ_1)}{\cos φ_1}

    %(guided_speed_parameters)s

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


@_DOCS
def guided_acceleration(sprocket_angle: ArrayLike, pitch: float, teeth: int, angular_velocity: float) -> FloatOrArray:
    r"""Acceleration of the chain on the tangent guide [m/s²].

    .. math:: a = ω^2R\left[-\sin ψ_1 + \cos ψ_1\tan φ_1
              + \frac{R\sin^2 ψ_1}{t\cos^3 φ_1}\right]

    %(guided_speed_parameters)s

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


@_DOCS
def leaving_displacement(sprocket_angle: ArrayLike, pitch: float, teeth: int, guide: str="tangent") -> FloatOrArray:
    r"""Displacement of the chain running *off* the tensioning sprocket, in phase [m].

    .. math:: u_1(ψ) = t - u(2γ - s) + n\,t \quad(\text{tangent guide}),\qquad
              u_1 = u \quad(\text{no guide})

    Parameters
    ----------
    sprocket_angle : float or array_like
        ``ψ`` [rad], same clock as the driving sprocket (sprockets in phase).
    %(pitch_teeth)s
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




from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
