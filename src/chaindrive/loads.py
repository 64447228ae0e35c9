r"""Chain loads: tight- and slack-side tension, centrifugal tension, dynamic load,
shaft loads, static safety, service factors.

All functions take and return SI units (N, N·m, W, m, rad/s, kg).
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from ._registry import Registry
from ._typing import FloatOrArray
from ._validation import as_float_array, check_nonnegative, check_positive, check_teeth
from .errors import InputError
from .static_safety import (
    PEAK_TENSION_RATIO,
    REQUIRED_SAFETY_PITCHES,
    REQUIRED_SAFETY_SPEEDS,
    REQUIRED_SAFETY_TABLE,
    REQUIRED_STATIC_SAFETY,
    outside_required_safety_table,
    required_static_safety_for,
    required_static_safety_table,
    static_safety,
)

__all__ = [
    "torque_from_power",
    "power_from_torque",
    "chain_speed",
    "mean_chain_speed",
    "sides_per_turn",
    "tight_side_tension",
    "centrifugal_tension",
    "free_entry_acceleration_peak",
    "dynamic_tension",
    "polygonal_dynamic_tension",
    "disc_inertia",
    "POLYGONAL_DAMPING_RATIO",
    "dynamic_factor",
    "shaft_load",
    "static_safety_factor",
    "static_safety",
    "required_static_safety_table",
    "required_static_safety_for",
    "outside_required_safety_table",
    "REQUIRED_SAFETY_PITCHES",
    "REQUIRED_SAFETY_SPEEDS",
    "REQUIRED_SAFETY_TABLE",
    "PEAK_TENSION_RATIO",
    "service_factor",
    "SERVICE_FACTORS",
    "REQUIRED_STATIC_SAFETY",
]


def torque_from_power(power: ArrayLike, angular_velocity: ArrayLike) -> FloatOrArray:
    r"""Torque from power and speed, ``T = P / ω``.

    .. math:: T = \frac{P}{\omega}

    Parameters
    ----------
    power : float or array_like
        Power ``P >= 0`` [W].
    angular_velocity : float or array_like
        Shaft speed ``ω > 0`` [rad/s].

    Returns
    -------
    ndarray
        Torque [N·m].

    References
    ----------
    Definition of mechanical power of a rotating shaft.

    Examples
    --------
    >>> round(float(torque_from_power(15e3, 960 * 2 * np.pi / 60)), 2)
    149.21
    """
    P = check_nonnegative("power", power, "W")
    w = check_positive("angular_velocity", angular_velocity, "rad/s")
    return P / w


def power_from_torque(torque: ArrayLike, angular_velocity: ArrayLike) -> FloatOrArray:
    r"""Power from torque and speed, ``P = T ω``.

    .. math:: P = T\,\omega

    Parameters
    ----------
    torque : float or array_like
        [N·m], ``>= 0``.
    angular_velocity : float or array_like
        [rad/s], ``> 0``.

    Returns
    -------
    ndarray
        [W].

    Examples
    --------
    >>> float(power_from_torque(100.0, 10.0))
    1000.0
    """
    T = check_nonnegative("torque", torque, "N*m")
    w = check_positive("angular_velocity", angular_velocity, "rad/s")
    return T * w


def sides_per_turn(teeth: int, link_chain: bool) -> int:
    """Chain links seated per turn of a wheel: ``z`` (sprocket, track wheel), ``2z`` (round
    link chain on a pocket wheel: a horizontal and a vertical link per pocket; Dolipiński
    et al., eq. (6): 2z sides of lengths t + d and t − d, 2 z t per turn).

    >>> sides_per_turn(8, True), sides_per_turn(19, False)
    (16, 19)
    """
    return 2 * int(teeth) if link_chain else int(teeth)


def mean_chain_speed(sides: Any, pitch: Any, angular_velocity: Any) -> Any:
    r"""``v = n p ω / 2π`` without input checks: the one chain-speed formula of the package
    (:func:`chain_speed` is its checked public form; ``n`` from :func:`sides_per_turn`).
    Scalars or numpy arrays (broadcast).

    >>> round(float(mean_chain_speed(19, 0.0254, 100.0)), 6)
    7.680818
    """
    return sides * pitch * angular_velocity / (2.0 * np.pi)


def chain_speed(pitch: ArrayLike, teeth: ArrayLike, angular_velocity: ArrayLike) -> FloatOrArray:
    r"""Mean chain speed, one pitch per tooth passing.

    .. math:: v = \frac{z\,p\,\omega}{2\pi}

    Parameters
    ----------
    pitch : float or array_like
        Chain pitch [m] (inner link length ``t``; a pocket wheel with ``z`` pockets
        passes ``2z`` links of mean length ``t`` per turn, so pass ``teeth = 2z``).
    teeth : int or array_like
        Teeth of the wheel turning at ``ω`` (hinges per turn) [-].
    angular_velocity : float or array_like
        [rad/s].

    Returns
    -------
    ndarray
        [m/s].

    Notes
    -----
    The mean over a tooth period; the instantaneous speed varies by the polygonal
    effect (Dolipiński et al., eqs 1–13; :mod:`chaindrive.kinematics`).

    References
    ----------
    ISO 10823:2004 (chain speed); Shigley, 9th ed., eq. (17-29) ``V = N p n``.

    Examples
    --------
    >>> round(float(chain_speed(0.0254, 19, 960 * 2 * np.pi / 60)), 4)
    7.7216
    """
    p = check_positive("pitch", pitch, "m")
    z = check_teeth("teeth", teeth, minimum=2)
    w = check_positive("angular_velocity", angular_velocity, "rad/s")
    return mean_chain_speed(z, p, w)


def tight_side_tension(torque: ArrayLike, pitch_radius: ArrayLike) -> FloatOrArray:
    r"""Effective pull of the chain from the driving torque, ``F = T / R``.

    .. math:: F_t = \frac{T}{R}

    Parameters
    ----------
    torque : float or array_like
        Torque on the driving wheel [N·m], ``>= 0``.
    pitch_radius : float or array_like
        Pitch radius of that wheel [m], ``> 0``.

    Returns
    -------
    ndarray
        Effective (working) pull [N]; the tight-side tension is this plus the
        slack-side and centrifugal tensions.

    Notes
    -----
    With the pitch radius (not the instantaneous polygonal lever ``R cos φ``) this is
    the mean pull; the lever varies within ``R cos(π/z) … R``.

    References
    ----------
    Shigley, 9th ed., §17-5; ISO 10823:2004.

    Examples
    --------
    >>> round(float(tight_side_tension(149.21, 0.077159)), 1)
    1933.8
    """
    T = check_nonnegative("torque", torque, "N*m")
    R = check_positive("pitch_radius", pitch_radius, "m")
    return T / R


def centrifugal_tension(mass_per_length: ArrayLike, chain_speed: ArrayLike) -> FloatOrArray:
    r"""Centrifugal tension of a chain running round a wheel.

    .. math:: F_c = q\,v^2

    Parameters
    ----------
    mass_per_length : float or array_like
        [kg/m], ``> 0``.
    chain_speed : float or array_like
        [m/s], ``>= 0``.

    Returns
    -------
    ndarray
        [N]; it acts along the whole chain and is not carried to the shafts.

    Notes
    -----
    Derivation: an arc ``R dθ`` of mass ``q R dθ`` needs the radial force
    ``q R dθ v²/R`` which the tension supplies as ``F dθ``, so ``F = q v²``
    independent of ``R``.

    References
    ----------
    ISO 10823:2004 (centrifugal force ``F_c = q v²``); Shigley, 9th ed., eq. (17-8)
    for belts.

    Examples
    --------
    >>> round(float(centrifugal_tension(2.6, 7.72)), 1)
    155.0
    """
    q = check_positive("mass_per_length", mass_per_length, "kg/m")
    v = check_nonnegative("chain_speed", chain_speed, "m/s")
    return q * v**2


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
    >>> float(dynamic_tension(10.0, 2.0))
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
    >>> float(dynamic_factor(1000.0, 250.0))
    1.25
    """
    F = check_positive("tension", tension, "N")
    Fd = check_nonnegative("dynamic_tension", dynamic_tension, "N")
    return 1.0 + Fd / F


def shaft_load(tensions: ArrayLike, directions: ArrayLike) -> tuple[FloatOrArray, FloatOrArray]:
    r"""Load on a shaft: vector sum of the span tensions acting on its wheel.

    .. math:: \mathbf{F} = \sum_i F_i\,(\cos\alpha_i, \sin\alpha_i)

    Parameters
    ----------
    tensions : array_like, shape (..., k)
        Span tensions pulling on the wheel [N], ``>= 0``.
    directions : array_like, shape (..., k)
        Direction of each pull *from the wheel along the span* [rad].

    Returns
    -------
    magnitude : ndarray, shape (...)
        [N].
    angle : ndarray, shape (...)
        Direction of the resultant [rad].

    Notes
    -----
    For a two-wheel drive with span angle ``β`` the two spans pull at ``±β``-ish
    directions; the centrifugal tension does not load the shaft (it is balanced
    inside the wrapped chain) and must be left out of ``tensions``.

    References
    ----------
    Statics; ISO 10823:2004 (shaft load ``≈ F_t``…``1.15 F_t``).

    Examples
    --------
    >>> m, a = shaft_load([1000.0, 100.0], [0.0, 0.0])
    >>> float(m)
    1100.0
    """
    F = check_nonnegative("tensions", tensions, "N")
    a = as_float_array("directions", directions)
    fx = np.sum(F * np.cos(a), axis=-1)
    fy = np.sum(F * np.sin(a), axis=-1)
    return np.hypot(fx, fy), np.arctan2(fy, fx)


def static_safety_factor(breaking_force: ArrayLike, tension: ArrayLike) -> FloatOrArray:
    r"""Static safety factor against the chain's breaking force.

    .. math:: S = \frac{F_B}{F_{max}}

    Parameters
    ----------
    breaking_force : float or array_like
        Minimum breaking force of the chain (all strands) [N].
    tension : float or array_like
        Largest tension in the chain (tight side + centrifugal + dynamic) [N].

    Returns
    -------
    ndarray
        [-].

    Notes
    -----
    ISO 10823 and chain makers ask for ``S >= 7…8`` in power drives; Diamond Chain
    advises that the working load never exceed 1/6 of the ultimate strength.

    References
    ----------
    ISO 606:2015 (minimum tensile strength); Diamond Chain, Technical Engineering
    Guide (working load <= 1/6 MUTS).

    Examples
    --------
    >>> float(static_safety_factor(60000.0, 5000.0))
    12.0
    """
    Fb = check_positive("breaking_force", breaking_force, "N")
    F = check_positive("tension", tension, "N")
    return Fb / F


#: Service factors K_s (ANSI/ACA, as tabulated in Shigley's Mechanical Engineering
#: Design, 9th ed., Table 17-15): rows load character, columns driver type.
SERVICE_FACTORS = Registry("load character")
SERVICE_FACTORS.add("smooth", {"ic_hydraulic": 1.0, "electric_motor": 1.0, "ic_mechanical": 1.2})
SERVICE_FACTORS.add("moderate", {"ic_hydraulic": 1.2, "electric_motor": 1.3, "ic_mechanical": 1.4})
SERVICE_FACTORS.add("heavy", {"ic_hydraulic": 1.4, "electric_motor": 1.5, "ic_mechanical": 1.7})


def service_factor(load: str = "smooth", driver: str = "electric_motor") -> float:
    r"""Service (shock) factor ``K_s`` for a load character and a driver.

    .. math:: P_{design} = K_s\,P

    Parameters
    ----------
    load : {"smooth", "moderate", "heavy"}
        Character of the driven load (uniform; moderate shock; heavy shock).
    driver : {"ic_hydraulic", "electric_motor", "ic_mechanical"}
        Internal-combustion engine with hydraulic drive; electric motor or turbine;
        internal-combustion engine with mechanical drive.

    Returns
    -------
    float
        [-].

    Raises
    ------
    UnknownNameError
        Unknown load character or driver (lists the valid ones).

    References
    ----------
    American Chain Association; Shigley, 9th ed., Table 17-15.

    Examples
    --------
    >>> service_factor("moderate", "electric_motor")
    1.3
    """
    row = SERVICE_FACTORS.get(load)
    drivers = Registry("driver")
    for k, v in row.items():
        drivers.add(k, v)
    return float(drivers.get(driver))
