"""Dynamic (polygonal-action) chain load: the entry acceleration peak, the dynamic tension
and the dynamic factor, the wheel inertia assumed. All SI.

Re-exported by :mod:`chaindrive.loads`.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from .._typing import FloatOrArray
from .._validation import check_nonnegative, check_positive
from ..errors import InputError


def free_entry_acceleration_peak(angular_velocity: ArrayLike, pitch_radius: ArrayLike, half_angle: ArrayLike) -> FloatOrArray:
    r"""Peak longitudinal chain acceleration of free (unguided) entry on a polygon.

    .. math:: a_{max} = \omega^2 R \sin\frac{\delta}{2}

    Parameters
    ----------
    angular_velocity : float or array_like
        Wheel speed ``ω`` [rad/s].
    pitch_radius : float or array_like
        Pitch radius ``R`` [m].
    half_angle : float or array_like
        Half the central angle ``δ/2`` of the link entering [rad]: ``π/z`` for a
        roller chain; ``δ1/2`` of the horizontal link of a round link chain.

    Returns
    -------
    ndarray
        [m/s²].

    Notes
    -----
    Derivation: the chain moves with the hinge that has just seated; its speed is
    ``v = ωR cos φ`` for ``φ ∈ [-δ/2, δ/2]``, so ``dv/dt = -ω² R sin φ`` with peak
    ``ω² R sin(δ/2)`` at the ends of the period (``= ω² p/2`` for a roller chain).
    Checked by finite differences (tests). Guided entry: use
    :func:`chaindrive.kinematics.chain_entry`.

    References
    ----------
    Dolipiński et al., eqs (1)–(13) (free entry).

    Examples
    --------
    >>> round(float(free_entry_acceleration_peak(100.0, 0.077159, np.pi / 19)), 1)
    127.0
    """
    w = check_positive("angular_velocity", angular_velocity, "rad/s")
    R = check_positive("pitch_radius", pitch_radius, "m")
    h = check_positive("half_angle", half_angle, "rad")
    if np.any(h > np.pi / 2):
        raise InputError(f"half_angle must lie in (0, π/2] rad, got {h}")
    return w**2 * R * np.sin(h)


def dynamic_tension(moving_mass: ArrayLike, acceleration: ArrayLike) -> FloatOrArray:
    r"""Inertia force of the moving chain (and masses moving with it).

    .. math:: F_d = m\,a_{max}

    Parameters
    ----------
    moving_mass : float or array_like
        Mass accelerated by the polygonal action [kg] (the chain ``q L``, plus the
        load reduced to the chain where it moves with it).
    acceleration : float or array_like
        Peak acceleration [m/s²] (:func:`free_entry_acceleration_peak` or the
        kinematics module).

    Returns
    -------
    ndarray
        [N].

    References
    ----------
    Dolipiński et al. (the acceleration); Newton's second law.

    Examples
    --------
    >>> float(dynamic_tension(10.0, 2.0))   # m a = 10 kg × 2 m/s²
    20.0
    """
    m = check_nonnegative("moving_mass", moving_mass, "kg")
    a = check_nonnegative("acceleration", acceleration, "m/s^2")
    return m * a


#: Damping ratio ``ζ`` of the driven wheel's spring-type vibration on the chain spans [-]
#: used by :func:`polygonal_dynamic_tension` in the analysis: light damping (bearings,
#: friction of the rollers in their seats). An assumed value, not a measurement: with
#: ζ = 0.05…0.2 F_max of the roller example is 1.08…0.97 of the simulated peak, of the
#: 10B-2 drive of issue 19 1.36…0.91 (its ω_n is near twice the tooth frequency). The
#: simulation's own wheel mode rings at ζ ≈ 0.002–0.006 without the roller–tooth friction
#: and 0.17–0.23 with it (docs/design.md, "The dynamic load and the simulation").
POLYGONAL_DAMPING_RATIO = 0.1


def disc_inertia(radius: ArrayLike, thickness: float = 0.02, density: float = 7800.0) -> FloatOrArray:
    r"""Moment of inertia of a solid steel disc, the wheel inertia chaindrive assumes.

    .. math:: J = \tfrac12 \rho \pi r^4 b

    A drive description carries no wheel inertia; the analysis (dynamic load, torsional
    critical speed) and the simulation all assume a steel disc ``b = 20 mm`` thick at the
    wheel's pitch radius, defined here once.

    Parameters
    ----------
    radius : float or array_like
        Disc radius ``r > 0`` [m] (the pitch radius).
    thickness : float
        ``b > 0`` [m].
    density : float
        ``ρ > 0`` [kg/m³] (steel 7800).

    Returns
    -------
    ndarray
        [kg·m²].

    References
    ----------
    Solid cylinder about its axis (any dynamics text, e.g. Meriam & Kraige, Dynamics, table D/4).

    Examples
    --------
    >>> round(float(disc_inertia(0.2305412)), 4)  # the 57-tooth 16B sprocket
    0.6922
    """
    r = check_positive("radius", radius, "m")
    b = check_positive("thickness", thickness, "m")
    rho = check_positive("density", density, "kg/m^3")
    return 0.5 * rho * np.pi * r**4 * b


def polygonal_dynamic_tension(angular_velocity: ArrayLike, pitch_radius: ArrayLike, half_angle: ArrayLike,
                              stiffness: ArrayLike, mass: ArrayLike,
                              damping_ratio: ArrayLike = POLYGONAL_DAMPING_RATIO) -> FloatOrArray:
    r"""Peak dynamic chain tension of the polygonal action: the driven side as a mass on the
    elastic chain, driven by the polygonal speed of the driving wheel (periodic response).

    The chain leaves the driving wheel at ``v_b = ωR cos φ``, ``φ = ωt ∈ [-δ/2, δ/2]``
    (free entry), one period per seating; the driven side (driven wheel and load reduced to
    the chain, chain on it and the consistent part of the spans' mass) is a mass ``m``
    held by the spans' stiffness ``k``, with viscous damping ``c = 2ζ sqrt(k m)``. With the
    spring's extension ``u = x_b − x``:

    .. math::

        m\ddot u + c\dot u + k u = m\,a_b(t), \qquad a_b = -\omega^2 R \sin\omega t,
        \qquad F_d(t) = k u + c \dot u

    solved exactly for the periodic steady state (period ``T = δ/ω``): the particular
    solution ``u_p = P \sin ωt + Q \cos ωt`` of the sine forcing plus the free vibration
    whose initial state makes ``[u, \dot u]`` periodic, ``(I − Φ(T)) y_0 = y_p(T/2) −
    Φ(T) y_p(−T/2)`` with ``Φ`` the transition matrix of the free damped oscillator. The
    result is the largest ``F_d`` over the period (sampled at 1024 points: accurate for ``ω_n T`` up to about 150); its mean is 0,
    so it adds to the static tight-side tension.

    Parameters
    ----------
    angular_velocity : float or array_like
        Driving wheel ``ω > 0`` [rad/s].
    pitch_radius : float or array_like
        Its pitch radius ``R > 0`` [m].
    half_angle : float or array_like
        Half the central angle of a link ``δ/2 ∈ (0, π/2]`` [rad] (``π/z``).
    stiffness : float or array_like
        Longitudinal stiffness ``k > 0`` holding the driven side [N/m] (``Σ EA/l`` of its spans).
    mass : float or array_like
        Driven-side mass reduced to the chain ``m > 0`` [kg] (``J/R_2² + …``).
    damping_ratio : float or array_like
        ``ζ ∈ [0, 1)`` [-]; default :data:`POLYGONAL_DAMPING_RATIO`.

    Returns
    -------
    ndarray
        Peak dynamic tension ``max F_d`` [N].

    Notes
    -----
    Limits (tests): a very heavy driven side (``m → ∞``, ``ζ → 0``) stands still in the
    frame of the mean chain speed and ``F_d → k R (δ/2)³/(9√3)``, the spring stretched by
    the polygon's displacement error ``R(sin θ − θ sin(δ/2)/(δ/2))``; a stiff spring
    (``ω_n T ≫ 1``) follows the inertia force ``m a_b`` plus the free vibration started at
    each seating, where ``a_b`` jumps by ``2 a_max``: ``F_d → m a_max (1 + 2 e^{−πζ/√(1−ζ²)})``,
    ``= m a_max`` (:func:`dynamic_tension`) only at critical damping. Near resonance
    (``ω_n ≈ n z ω``) the result depends on ``ζ``. Checked against a numerical integration
    of the same equation (scipy ``solve_ivp``) in the tests.

    References
    ----------
    Polygonal speed of free entry: Dolipiński et al., eqs (1)–(13); single-degree-of-freedom
    response to base excitation and the transition matrix: S. S. Rao, Mechanical Vibrations,
    5th ed., §§3.6, 4.2 (periodic forcing), 2.6 (free damped vibration).

    Examples
    --------
    >>> # 16B on 19 teeth at 960 rpm, 57-tooth driven disc wheel on two 1.039 m spans
    >>> round(float(polygonal_dynamic_tension(100.531, 0.0771593, np.pi / 19, 1.9255e8, 16.9, 0.1)))
    3934
    """
    w = check_positive("angular_velocity", angular_velocity, "rad/s")
    R = check_positive("pitch_radius", pitch_radius, "m")
    h = check_positive("half_angle", half_angle, "rad")
    if np.any(h > np.pi / 2):
        raise InputError(f"half_angle must lie in (0, π/2] rad, got {h}", field="half_angle")
    k = check_positive("stiffness", stiffness, "N/m")
    m = check_positive("mass", mass, "kg")
    zeta = check_nonnegative("damping_ratio", damping_ratio)
    if np.any(zeta >= 1.0):
        raise InputError(f"damping_ratio must lie in [0, 1), got {zeta}", field="damping_ratio")
    w, R, h, k, m, zeta = np.broadcast_arrays(w, R, h, k, m, zeta)
    T = 2.0 * h / w
    wn = np.sqrt(k / m)
    c = 2.0 * zeta * np.sqrt(k * m)
    s, wd = zeta * wn, wn * np.sqrt(1.0 - zeta**2)
    # particular solution of m u'' + c u' + k u = -m ω²R sin ωt
    a, b = k - m * w**2, c * w
    den = a**2 + b**2
    P, Q = -m * w**2 * R * a / den, m * w**2 * R * b / den

    def particular(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        return P * np.sin(w * t) + Q * np.cos(w * t), w * (P * np.cos(w * t) - Q * np.sin(w * t))

    # transition matrix of the free damped oscillator over one period
    e, cd, sd = np.exp(-s * T), np.cos(wd * T), np.sin(wd * T)
    p11, p12 = e * (cd + s / wd * sd), e * sd / wd
    p21, p22 = -e * wn**2 / wd * sd, e * (cd - s / wd * sd)
    (u0, v0), (u1, v1) = particular(-T / 2), particular(T / 2)
    r1, r2 = u1 - (p11 * u0 + p12 * v0), v1 - (p21 * u0 + p22 * v0)
    det = (1 - p11) * (1 - p22) - p12 * p21
    z0 = ((1 - p22) * r1 + p12 * r2) / det - u0   # free vibration's state at t = -T/2
    z1 = (p21 * r1 + (1 - p11) * r2) / det - v0
    x = lambda q: np.asarray(q)[..., None]  # noqa: E731 - broadcast over the period's samples
    tau = x(T) * np.linspace(0.0, 1.0, 1024)
    E, C, S = np.exp(-x(s) * tau), np.cos(x(wd) * tau), np.sin(x(wd) * tau)
    uh = E * (x(z0) * (C + x(s / wd) * S) + x(z1) * S / x(wd))
    vh = E * (-x(z0) * x(wn**2 / wd) * S + x(z1) * (C - x(s / wd) * S))
    t = tau - x(T) / 2
    up = x(P) * np.sin(x(w) * t) + x(Q) * np.cos(x(w) * t)
    vp = x(w) * (x(P) * np.cos(x(w) * t) - x(Q) * np.sin(x(w) * t))
    return np.max(x(k) * (uh + up) + x(c) * (vh + vp), axis=-1)


def dynamic_factor(tension: ArrayLike, dynamic_tension: ArrayLike) -> FloatOrArray:
    r"""Dynamic factor ``K_d = (F + F_d) / F``.

    .. math:: K_d = 1 + \frac{F_d}{F}

    Parameters
    ----------
    tension : float or array_like
        Static tight-side tension ``F > 0`` [N].
    dynamic_tension : float or array_like
        Inertia force ``F_d >= 0`` [N].

    Returns
    -------
    ndarray
        [-], ``>= 1``.

    Examples
    --------
    >>> float(dynamic_factor(1000.0, 250.0))   # 1 + F_d / F = 1 + 250/1000
    1.25
    """
    F = check_positive("tension", tension, "N")
    Fd = check_nonnegative("dynamic_tension", dynamic_tension, "N")
    return 1.0 + Fd / F


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
