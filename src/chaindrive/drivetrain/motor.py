r"""Drive motors for a time-varying simulation: the Kloss torque–speed curve of an
induction motor.

All functions take and return SI units (N m, rad/s).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from .._finite import finite_guard
from .._results import Result, quantity
from .._typing import FloatOrArray
from .._validation import as_float_array, check_positive, check_range, warn_outside
from ..errors import InputError

__all__ = ["kloss_torque", "breakdown_slip", "Motor"]


@finite_guard
def kloss_torque(slip: ArrayLike, breakdown_torque: ArrayLike, breakdown_slip: ArrayLike) -> FloatOrArray:
    r"""Torque of an induction motor at ``slip`` on the Kloss curve [N m].

    .. math:: T = \frac{2 T_k}{s/s_k + s_k/s} = \frac{2 T_k\, s\, s_k}{s^2 + s_k^2}

    Parameters
    ----------
    slip : float or array_like
        ``s = (ω_s − ω)/ω_s`` [-], ``-2 <= s <= 2`` (negative: generating; above 1 the
        rotor turns backwards, plugging: outside ``[-1, 1]`` a ValidityRangeWarning).
    breakdown_torque : float or array_like
        Pull-out (breakdown) torque ``T_k > 0`` [N m].
    breakdown_slip : float or array_like
        Slip at the breakdown torque, ``0 < s_k < 1``.

    Returns
    -------
    ndarray
        [N m]; ``T_k`` at ``s = s_k``, 0 at synchronous speed.

    Notes
    -----
    The Kloss formula neglects the stator resistance (exact for ``R_1 = 0`` in the
    equivalent circuit); it describes a standard cage motor above the pull-up region
    well and underestimates a deep-bar motor's starting torque. Valid for ``|s| <= 1``.

    References
    ----------
    Kloss, M. (1909); e.g. Fischer, R., *Elektrische Maschinen*, Hanser, ch. on the
    asynchronous machine ("Kloßsche Formel", ``M/M_K = 2/(s/s_K + s_K/s)``).

    Examples
    --------
    >>> round(float(kloss_torque(0.1, 1000.0, 0.1)), 6)
    1000.0
    >>> round(float(kloss_torque(1.0, 1000.0, 0.2)), 1)      # locked rotor
    384.6
    """
    s = check_range("slip", slip, -2.0, 2.0)
    warn_outside("slip", s, -1.0, 1.0, "the Kloss formula (motoring and generating)")
    tk = check_positive("breakdown_torque", breakdown_torque, "N m")
    sk = check_range("breakdown_slip", breakdown_slip, 0.0, 1.0)
    if np.any(sk <= 0) or np.any(sk >= 1):
        raise InputError(f"breakdown_slip must lie in (0, 1), got {sk}", field="breakdown_slip")
    return 2.0 * tk * s * sk / (s * s + sk * sk)


@finite_guard
def breakdown_slip(rated_slip: ArrayLike, breakdown_ratio: ArrayLike) -> FloatOrArray:
    r"""Breakdown slip from the rated point: ``s_k = s_N (m + sqrt(m² − 1))``, ``m = T_k/T_N``.

    .. math:: s_k = s_N\left(m + \sqrt{m^2 - 1}\right)

    Solves the Kloss formula for ``s_k`` through the rated point ``(s_N, T_N)`` (the
    root with ``s_k > s_N``).

    Parameters
    ----------
    rated_slip : float or array_like
        ``0 < s_N < 1``.
    breakdown_ratio : float or array_like
        ``m = T_k / T_N > 1``.

    Returns
    -------
    ndarray

    References
    ----------
    Kloss formula (see :func:`kloss_torque`), solved here.

    Examples
    --------
    >>> round(float(breakdown_slip(0.02, 2.5)), 5)
    0.09583
    """
    sn = check_range("rated_slip", rated_slip, 0.0, 1.0)
    m = as_float_array("breakdown_ratio", breakdown_ratio)
    if np.any(m <= 1) or np.any(~np.isfinite(m)):
        raise InputError(f"breakdown_ratio must be > 1 (the breakdown torque above the rated), got {m}",
                         field="breakdown_ratio")
    return sn * (m + np.sqrt(m * m - 1.0))


@dataclass(frozen=True)
class Motor(Result):
    """An induction motor reduced to the wheel it drives (Kloss curve).

    Parameters
    ----------
    synchronous_speed : float
        ``ω_s`` at the wheel [rad/s] (motor synchronous speed over the gear ratio).
    breakdown_torque : float
        ``T_k`` at the wheel [N m].
    breakdown_slip : float
        ``s_k`` (0, 1).
    """

    synchronous_speed: float = quantity("rad/s")
    breakdown_torque: float = quantity("N*m")
    breakdown_slip: float = quantity("1")

    def __post_init__(self) -> None:
        check_positive("synchronous_speed", self.synchronous_speed, "rad/s")
        check_positive("breakdown_torque", self.breakdown_torque, "N m")
        if not 0 < float(self.breakdown_slip) < 1:
            raise InputError(f"breakdown_slip must lie in (0, 1), got {self.breakdown_slip!r}",
                             field="breakdown_slip")

    @classmethod
    def rated(cls, power: float, wheel_speed: float, *, rated_slip: float = 0.02,
              breakdown_ratio: float = 2.5) -> Motor:
        """A motor of rated ``power`` [W] running the wheel at ``wheel_speed`` [rad/s] at
        rated slip; ``T_k = m T_N`` with ``T_N = P / ω_N``.

        Examples
        --------
        >>> m = Motor.rated(40e3, 4.0)
        >>> round(m.synchronous_speed, 4), round(m.breakdown_torque)
        (4.0816, 25000)
        """
        check_positive("power", power, "W")
        check_positive("wheel_speed", wheel_speed, "rad/s")
        sk = float(breakdown_slip(rated_slip, breakdown_ratio))
        return cls(wheel_speed / (1.0 - rated_slip), breakdown_ratio * power / wheel_speed, sk)

    def torque(self, angular_velocity: ArrayLike) -> FloatOrArray:
        """Torque at the wheel [N m] at ``angular_velocity`` [rad/s] (:func:`kloss_torque`)."""
        w = as_float_array("angular_velocity", angular_velocity)
        return kloss_torque((self.synchronous_speed - w) / self.synchronous_speed, self.breakdown_torque,
                            self.breakdown_slip)

