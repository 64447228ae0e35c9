r"""Chain pull of scraper (drag) chain conveyors on their pans: resistance to motion of a strand,
the material load, the mean tension of a closed loop and the drive power.

All functions take and return SI units (N, m, kg, rad, W). The loop walk (which strand
is on the pans, where the drives sit, the tensioner) is
:mod:`chaindrive.analysis.conveyor`; these are its single formulas.

A strand moving a distance ``L`` along a pan inclined by ``α`` (rising in the direction
of travel) changes the chain tension by the friction of the chain on the pan, the
friction of the scraped material on the pan and the weight components of both:

.. math::
    ΔT = g L\,[(q μ + q_m μ_m)\cos α + (q + q_m)\sin α]

(Tsubakimoto, *Large size conveyor chain, selection*, Table 3; the same method,
strand by strand with a factor at each sprocket, in the "Calculation formula of
tension acting on the chain" sheets 20-2 to 20-4 of e-uparts' machine handbook:
``T = W(L f + H) + M(L f_1 + H) + T_2`` with ``L`` the horizontal and ``H`` the
vertical distance, i.e. ``L = ℓ cos α``, ``H = ℓ sin α``).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike

from .._finite import finite_guard
from .._typing import FloatOrArray
from .._validation import as_float_array, check_nonnegative, check_positive, check_range
from ..errors import InputError
from ..layout import GRAVITY

__all__ = ["pan_end_clearance", "material_mass_per_length", "strand_resistance", "drive_power", "mean_tension",
           "pretension_for_minimum"]



@finite_guard
def pan_end_clearance(pitch_radius: ArrayLike, tip_height: ArrayLike, pitch: ArrayLike) -> FloatOrArray:
    r"""Distance [m] from a wheel's tangent point to the end of the pan under the strand.

    The pan holds the strand on the wheel's tangent line; it must stop where that line
    enters the wheel's tip circle (radius ``R + h_a``), and one link before it:

    .. math:: c = \sqrt{(R + h_a)^2 - R^2} + t

    Parameters
    ----------
    pitch_radius : float or array_like
        ``R`` [m].
    tip_height : float or array_like
        ``h_a`` [m] (a pocket wheel: ``d/2``).
    pitch : float or array_like
        Link length ``t`` [m].

    Returns
    -------
    ndarray
        [m]. Over this length at each end the strand hangs free (no pan friction, no
        material).

    References
    ----------
    Geometry (secant of the tip circle along the tangent line).

    Examples
    --------
    >>> round(float(pan_end_clearance(0.16428, 0.009, 0.064)), 4)
    0.1191
    """
    R = check_positive("pitch_radius", pitch_radius, "m")
    h = check_nonnegative("tip_height", tip_height, "m")
    t = check_positive("pitch", pitch, "m")
    return np.sqrt((R + h) ** 2 - R**2) + t


@finite_guard
def material_mass_per_length(capacity: ArrayLike, chain_speed: ArrayLike) -> FloatOrArray:
    r"""Mass of conveyed material per metre of conveyor, ``q_m = Q / v`` [kg/m].

    .. math:: q_m = \frac{Q}{v}

    Parameters
    ----------
    capacity : float or array_like
        Mass flow ``Q >= 0`` [kg/s] (1 t/h = 1/3.6 kg/s).
    chain_speed : float or array_like
        ``v > 0`` [m/s].

    Returns
    -------
    ndarray
        ``q_m`` [kg/m].

    References
    ----------
    Tsubakimoto, *Large size conveyor chain, selection*, 9.1: ``W = 16.7 Q / V``
    (``Q`` in t/h, ``V`` in m/min, ``16.7 = 1000/60``), the same relation.

    Examples
    --------
    >>> round(float(material_mass_per_length(500 / 3.6, 1.0)), 2)   # 500 t/h at 1 m/s
    138.89
    """
    Q = check_nonnegative("capacity", capacity, "kg/s")
    v = check_positive("chain_speed", chain_speed, "m/s")
    return Q / v


@finite_guard
def strand_resistance(length: ArrayLike, mass_per_length: ArrayLike, friction: ArrayLike,
                      inclination: ArrayLike = 0.0, material_mass_per_length: ArrayLike = 0.0,
                      material_friction: ArrayLike = 0.0, gravity: float = GRAVITY) -> FloatOrArray:
    r"""Tension gained by a chain strand dragged along a pan, ``ΔT`` [N].

    .. math::
        ΔT = g L\,[(q μ + q_m μ_m)\cos α + (q + q_m)\sin α]

    Parameters
    ----------
    length : float or array_like
        Length ``L > 0`` of the strand along the pan [m].
    mass_per_length : float or array_like
        Chain mass per length ``q > 0`` [kg/m] (all chains of the strand).
    friction : float or array_like
        Friction coefficient ``μ`` of the chain on the pan, ``0 <= μ <= 1.5``
        (0 for a strand hanging free: only the weight term is left).
    inclination : float or array_like
        ``α`` [rad], positive when the strand rises in its direction of travel,
        ``|α| <= π/2``.
    material_mass_per_length : float or array_like
        Material scraped along the pan ``q_m >= 0`` [kg/m].
    material_friction : float or array_like
        ``μ_m`` of the material on the pan, ``0 <= μ_m <= 1.5``.
    gravity : float
        [m/s²].

    Returns
    -------
    ndarray
        ``ΔT`` [N]: the tension at the strand's end minus that at its start (negative
        on a steep enough descent).

    Notes
    -----
    Coulomb friction of a strand lying on its pan with its own and the material's
    weight, the material pushed by the scrapers (so its friction acts on the chain).
    Valid while the strand lies on the pan (tension small against ``q g R`` of the
    pan's curvature: a straight pan line); no sprocket or bend losses (a chain maker's
    factor 1.05–1.1 per sprocket is applied by the caller when wanted).

    References
    ----------
    Tsubakimoto, *Large size conveyor chain, selection*, Table 3 (chain and scraped
    material: ``f = f_2/f_1``); e-uparts machine handbook, sheet 20-3 (inclined
    transport: ``T = W(L f + H) + M(L f_1 + H) + T_2``).

    Examples
    --------
    >>> round(float(strand_resistance(100.0, 14.3, 0.4)), 1)          # chain alone, level
    5609.4
    >>> round(float(strand_resistance(100.0, 14.3, 0.4, material_mass_per_length=100.0,
    ...                               material_friction=0.6)), 1)
    64449.3
    """
    L = check_positive("length", length, "m")
    q = check_positive("mass_per_length", mass_per_length, "kg/m")
    mu = check_range("friction", friction, 0.0, 1.5)
    a = check_range("inclination", inclination, -math.pi / 2, math.pi / 2, unit="rad")
    qm = check_nonnegative("material_mass_per_length", material_mass_per_length, "kg/m")
    mum = check_range("material_friction", material_friction, 0.0, 1.5)
    g = check_positive("gravity", gravity, "m/s^2")
    return g * L * ((q * mu + qm * mum) * np.cos(a) + (q + qm) * np.sin(a))


@finite_guard
def drive_power(force: ArrayLike, chain_speed: ArrayLike, efficiency: ArrayLike = 1.0) -> FloatOrArray:
    r"""Power of a drive pulling the chain with ``force`` at ``chain_speed``, ``P = F v / η`` [W].

    .. math:: P = \frac{F v}{η}

    Parameters
    ----------
    force : float or array_like
        Drive force (tension entering minus tension leaving the sprocket) [N], >= 0.
    chain_speed : float or array_like
        [m/s], > 0.
    efficiency : float or array_like
        Efficiency ``0 < η <= 1`` of the drive (gearbox, coupling) between motor and
        sprocket; 1 gives the power at the sprocket shaft.

    Returns
    -------
    ndarray
        Drive power ``P`` [W], at the drive's input (``η`` included).

    References
    ----------
    Tsubakimoto, *Large size conveyor chain, selection*, Table 3 (``kW = T V /
    (60 η)`` with ``T`` in kN and ``V`` in m/min).

    Examples
    --------
    >>> round(float(drive_power(50e3, 0.8, 0.85)))   # F v / η = 50 kN × 0.8 m/s / 0.85
    47059
    """
    F = check_nonnegative("force", force, "N")
    v = check_positive("chain_speed", chain_speed, "m/s")
    eta = check_range("efficiency", efficiency, 0.0, 1.0)
    if np.any(eta <= 0):
        raise InputError(f"efficiency must lie in (0, 1], got {eta}", field="efficiency")
    return F * v / eta


def mean_tension(position: ArrayLike, tension: ArrayLike) -> float:
    r"""Mean tension of a closed chain loop, ``(1/L) ∮ T ds`` [N].

    .. math:: \bar T = \frac1L \oint T\,ds

    The running chain's elongation is ``∮ T ds / EA``; a loop of fixed length between
    fixed (or locked) wheels keeps that integral, so the tension at rest — the
    *pretension*, uniform at standstill on level pans — equals the running loop's
    mean tension (Hooke's law on the whole loop; the small change of the sag of free
    strands neglected).

    Parameters
    ----------
    position : array_like
        Path coordinate round the loop [m], increasing, from 0 to the loop length.
    tension : array_like
        Tension at those positions [N] (piecewise linear between them).

    Returns
    -------
    float
        [N].

    References
    ----------
    Derived here (compatibility of elongations of a linear-elastic chain of fixed
    length); the "elongation balance" used for AFC pretension in the chain makers'
    and the AFC literature.

    Examples
    --------
    >>> mean_tension([0.0, 100.0, 100.0, 200.0], [10e3, 10e3, 30e3, 50e3])
    25000.0
    """
    s = as_float_array("position", position)
    T = as_float_array("tension", tension)
    if s.ndim != 1 or s.shape != T.shape or s.size < 2:
        raise InputError("position and tension must be 1-D arrays of the same length (>= 2)")
    if np.any(np.diff(s) < 0) or not s[-1] > s[0]:
        raise InputError("position must increase along the loop")
    return float(np.sum(0.5 * (T[1:] + T[:-1]) * np.diff(s)) / (s[-1] - s[0]))


def pretension_for_minimum(minimum: float, lowest: float, mean: float) -> float:
    r"""Pretension [N] that lifts a running profile's lowest tension to ``minimum``.

    A running profile ``T(s) = S_0 + τ(s)`` with mean ``\bar T`` and lowest value
    ``T_min`` is shifted by ``minimum − T_min``; its mean (:func:`mean_tension`) is then
    the standstill tension of the loop:

    .. math:: S_{pre} = \bar T + (T_{req} − T_{min})

    Parameters
    ----------
    minimum : float
        Required lowest running tension [N], >= 0.
    lowest, mean : float
        Lowest and mean tension of the profile as computed [N].

    Returns
    -------
    float
        [N].

    Examples
    --------
    >>> pretension_for_minimum(5e3, 2e3, 20e3)
    23000.0
    """
    m = float(check_nonnegative("minimum", minimum, "N"))
    return float(mean) + (m - float(lowest))


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
