"""Transverse vibration of a free chain span as an axially moving string."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from .._finite import finite_guard
from .._typing import FloatOrArray
from .._validation import check_nonnegative, check_positive, check_range
from ..errors import InfeasibleError, InputError
from ..limits import MAX_MODES

__all__ = ["wave_speed", "moving_string_frequencies"]


@finite_guard
def wave_speed(tension: ArrayLike, mass_per_length: ArrayLike, inclination: ArrayLike = 0.0) -> FloatOrArray:
    r"""Transverse wave speed of an inclined chain span (the tensioner paper, eqs (1)-(3)).

    Parameters
    ----------
    tension : float or array_like
        Span tension S [N]; in the tensioner paper the component S2 perpendicular to the
        tensioner axis ("horizontal"), so that the tension along a span inclined at
        β is S / cos β (this is what makes eq. (8) a force balance).
    mass_per_length : float or array_like
        Chain mass per unit length q [kg/m].
    inclination : float or array_like
        Inclination β of the span [rad], 0 <= β < π/2.

    Returns
    -------
    numpy.ndarray or float
        c = sqrt(S / (q cos β)) [m/s].

    .. math:: c = \sqrt{S / (q \cos\beta)}

    Notes
    -----
    For β = 0 this is the classical string speed sqrt(S/q). The factor 1/cos β is
    the tension along an inclined part whose perpendicular component is S (see
    docs/vibration.md); it is not a gravity term.

    Examples
    --------
    >>> round(float(wave_speed(2000.0, 2.6)), 4)
    27.735
    >>> round(float(wave_speed(2000.0, 2.6, np.pi / 3)), 4)
    39.2232

    References
    ----------
    the tensioner paper, eqs (1)-(3).
    """
    s = check_positive("tension", tension, "N")
    q = check_positive("mass_per_length", mass_per_length, "kg/m")
    b = check_range("inclination", inclination, 0.0, np.pi / 2, high_inclusive=False, unit="rad")
    out = transverse_wave_speed(s, q, b)
    return out if out.ndim else float(out)


def transverse_wave_speed(tension: ArrayLike, mass_per_length: ArrayLike, inclination: ArrayLike = 0.0) -> np.ndarray:
    """``c = sqrt(S / (q cos β))`` [m/s] without input checks: the one wave-speed formula of the
    package (:func:`wave_speed` is its checked public form).

    >>> round(float(transverse_wave_speed(2000.0, 2.6)), 4)
    27.735
    """
    return np.sqrt(np.asarray(tension, dtype=float)
                   / (np.asarray(mass_per_length, dtype=float) * np.cos(np.asarray(inclination, dtype=float))))


@finite_guard
def moving_string_frequencies(tension: ArrayLike, mass_per_length: ArrayLike, length: ArrayLike, *,
                              chain_speed: ArrayLike = 0.0, inclination: ArrayLike = 0.0,
                              modes: int = 3) -> np.ndarray:
    r"""Natural frequencies of a chain span as an axially moving string [rad/s].

    Parameters
    ----------
    tension : float or array_like
        Span tension S [N].
    mass_per_length : float or array_like
        Chain mass per length q [kg/m].
    length : float or array_like
        Span length L between its supports (sprocket tangent points) [m].
    chain_speed : float or array_like
        Axial chain speed v [m/s], 0 <= v < c.
    inclination : float or array_like
        Span inclination β [rad] (the tensioner paper's factor 1/cos β on the tension); 0 gives
        the classical moving string.
    modes : int
        Number of modes n = 1..modes.

    Returns
    -------
    numpy.ndarray
        Shape ``broadcast(inputs) + (modes,)``: ω_n = (nπ c / L)(1 − v²/c²) [rad/s].

    .. math:: \omega_n = \frac{n \pi}{L} c \left(1 - \frac{v^2}{c^2}\right),
              \quad c = \sqrt{S/(q\cos\beta)}

    Notes
    -----
    Exact for the linear, undamped, axially moving string with fixed ends
    (Mote 1965; Wickert & Mote 1988, eq. (29)); valid for 0 <= v < c, no bending
    stiffness, small deflections. At v = c the string loses stability (divergence);
    this raises :class:`~chaindrive.errors.InfeasibleError`.

    Examples
    --------
    >>> w = moving_string_frequencies(2000.0, 2.6, 0.8, chain_speed=5.0)
    >>> np.round(w / (2 * np.pi), 3)
    array([16.771, 33.542, 50.313])

    References
    ----------
    C. D. Mote, "A study of band saw vibrations", J. Franklin Inst. 279 (1965) 430-444;
    J. A. Wickert, C. D. Mote, "Classical vibration analysis of axially moving
    continua", J. Appl. Mech. 57 (1990) 738-744, eq. (29): ω_n = nπ(1 − v²) in
    units c = L = 1; the tensioner paper, eqs (1)-(3) for the inclination factor.
    """
    c = np.asarray(wave_speed(tension, mass_per_length, inclination))
    ell = check_positive("length", length, "m")
    v = check_nonnegative("chain_speed", chain_speed, "m/s")
    if not isinstance(modes, (int, np.integer)) or not 1 <= modes <= MAX_MODES:
        raise InputError(f"modes must be a whole number in [1, {MAX_MODES}], got {modes!r}")
    if np.asarray(v >= c).any():
        raise InfeasibleError(
            "chain_speed must be below the wave speed c = sqrt(S/(q cos β)) "
            "(0 <= v < c m/s): the moving string diverges at v >= c")
    n = np.arange(1, modes + 1)
    base = np.pi * c / ell * (1.0 - v**2 / c**2)
    return np.asarray(base)[..., None] * n
