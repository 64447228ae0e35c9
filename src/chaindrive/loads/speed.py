"""Torque, power and the mean chain speed of a wheel. All SI (W, N·m, rad/s, m/s).

Re-exported by :mod:`chaindrive.loads`.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from .._typing import FloatOrArray
from .._validation import check_nonnegative, check_positive, check_teeth


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
    >>> float(power_from_torque(100.0, 10.0))   # T ω = 100 N·m × 10 rad/s
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


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
