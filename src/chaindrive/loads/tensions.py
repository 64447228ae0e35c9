"""Chain tensions from the driving torque and the speed, and the shaft load they make.
All SI (N, N·m, m, kg/m, m/s, rad).

Re-exported by :mod:`chaindrive.loads`.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from .._typing import FloatOrArray
from .._validation import as_float_array, check_nonnegative, check_positive


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
    >>> round(float(tight_side_tension(149.21, 0.077159)), 1)   # T / R
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
    >>> round(float(centrifugal_tension(2.6, 7.72)), 1)   # q v² = 2.6 × 7.72²
    155.0
    """
    q = check_positive("mass_per_length", mass_per_length, "kg/m")
    v = check_nonnegative("chain_speed", chain_speed, "m/s")
    return q * v**2


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


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
