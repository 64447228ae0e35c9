r"""Hydrodynamic (fluid) couplings of constant fill between a drive motor and the wheel it
drives, for a time-varying simulation (:mod:`chaindrive.simulation.conveyor`).

All functions take and return SI units (N m, rad/s). A coupling's primary (pump) wheel
turns with the motor, its secondary (turbine) wheel with the gearbox; both are reduced
here to the driven wheel's shaft like the motor (:class:`chaindrive.drivetrain.motor.Motor`): a
torque ``T`` and speed ``ω`` on the motor side become ``i T`` and ``ω / i`` at the
wheel, which leaves the slip and the similarity law below unchanged.

The torque transmitted by the circulating oil follows Föttinger's similarity law

.. math:: T = λ(s)\, ρ\, ω_p^2 D^5, \qquad s = \frac{ω_p - ω_t}{ω_p}

(``ρ`` the oil density, ``D`` the profile diameter, ``λ`` the slip-dependent torque
coefficient). Written with the coupling's nominal point — torque ``T_n`` at nominal slip
``s_n`` and primary speed ``ω_n`` — it is

.. math:: T = T_n \left(\frac{ω_p}{ω_n}\right)^2 φ(s), \qquad φ(s_n) = 1,

and a constant-fill coupling's characteristic rises from ``φ(0) = 0`` almost linearly
through the nominal point and flattens towards the stall torque ``k T_n`` at ``s = 1``
(secondary at rest; ``k`` the stall-torque ratio of the catalogues, about 1.5 to 3). This
module takes the rational saturation

.. math:: φ(s) = \frac{(1 + c)\, s/s_n}{1 + c\, |s|/s_n}, \qquad
   c = \frac{1 - k s_n}{k - 1},

the simplest monotonic curve through the two catalogue points ``(s_n, 1)`` and
``(1, k)`` that is linear at small slip (its slope there ``(1 + c)/s_n``) — a model
chosen here, not a published curve: a real coupling's ``λ(s)`` (with or without a delay
chamber) lies near it between the two points and can differ by some 10 % in between.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from .._finite import finite_guard
from .._results import Result, quantity
from .._typing import FloatOrArray
from .._validation import as_float_array, check_positive, check_range
from ..errors import InputError

__all__ = ["coupling_torque", "slip_shape", "FluidCoupling", "NOMINAL_SLIP_RANGE", "STALL_RATIO_RANGE"]

#: Accepted nominal slip ``s_n`` (constant-fill couplings run at 1.5-6 % at nominal load).
NOMINAL_SLIP_RANGE = (0.005, 0.2)
#: Accepted stall-torque ratio ``k = T(s = 1)/T_n``.
STALL_RATIO_RANGE = (1.1, 6.0)


def _check(nominal_slip: ArrayLike, stall_ratio: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    sn = check_range("nominal_slip", nominal_slip, *NOMINAL_SLIP_RANGE)
    k = check_range("stall_ratio", stall_ratio, *STALL_RATIO_RANGE)
    if np.any(k * sn >= 1.0):
        raise InputError(f"stall_ratio times nominal_slip must be below 1 (the stall torque at s = 1 "
                         f"above the linear rise through the nominal point), got {k} x {sn}",
                         field="stall_ratio")
    return sn, k


@finite_guard
def slip_shape(slip: ArrayLike, nominal_slip: ArrayLike, stall_ratio: ArrayLike) -> FloatOrArray:
    r"""The coupling's characteristic ``φ(s) = T / (T_n (ω_p/ω_n)²)`` [-] (module notes).

    .. math:: φ(s) = \frac{(1 + c)\, s/s_n}{1 + c\, |s|/s_n}, \qquad
       c = \frac{1 - k s_n}{k - 1}

    Parameters
    ----------
    slip : float or array_like
        ``s = (ω_p − ω_t)/ω_p`` [-]; ``0 <= s <= 1`` in a start-up, negative when the
        secondary overruns (the torque then reverses: ``φ(−s) = −φ(s)``, a coupling with
        symmetric blading).
    nominal_slip : float or array_like
        ``s_n``, in [0.005, 0.2].
    stall_ratio : float or array_like
        ``k = φ(1)``, in [1.1, 6], with ``k s_n < 1``.

    Returns
    -------
    ndarray
        ``φ``: 1 at ``s_n``, ``k`` at ``s = 1``, 0 at ``s = 0``.

    Notes
    -----
    Valid for ``|s| <= 1`` (beyond, ``φ`` tends to ``(1 + c)/c``); the shape between the
    nominal and the stall point is a model (module notes).

    References
    ----------
    Föttinger's similarity law ``T = λ ρ ω² D⁵`` and the constant-fill characteristic
    ``λ(s)``: Voith Turbo, *Hydrodynamics in Drive Engineering* (Vogel, 1987), ch. on
    hydrodynamic couplings; the interpolating ``φ`` derived here.

    Examples
    --------
    >>> [round(float(slip_shape(s, 0.03, 2.5)), 6) for s in (0.0, 0.03, 1.0)]
    [0.0, 1.0, 2.5]
    """
    s = as_float_array("slip", slip)
    sn, k = _check(nominal_slip, stall_ratio)
    c = (1.0 - k * sn) / (k - 1.0)
    x = s / sn
    return (1.0 + c) * x / (1.0 + c * np.abs(x))


@finite_guard
def coupling_torque(primary_speed: ArrayLike, secondary_speed: ArrayLike, nominal_torque: ArrayLike,
                    nominal_speed: ArrayLike, nominal_slip: ArrayLike, stall_ratio: ArrayLike) -> FloatOrArray:
    r"""Torque [N m] a constant-fill fluid coupling transmits from primary to secondary.

    .. math::
        T = T_n \left(\frac{ω_p}{ω_n}\right)^2 φ(s)
          = \frac{T_n (1 + c)}{ω_n^2}\,\frac{ω_p^2\,(ω_p - ω_t)}{s_n |ω_p| + c\,|ω_p - ω_t|}

    (the right-hand form, equal for ``ω_p > 0``, is regular at ``ω_p = 0``: no torque
    when the primary stands still, whatever the secondary does).

    Parameters
    ----------
    primary_speed : float or array_like
        ``ω_p`` (motor side) [rad/s].
    secondary_speed : float or array_like
        ``ω_t`` (turbine, gearbox side) [rad/s].
    nominal_torque : float or array_like
        ``T_n > 0`` at nominal slip and primary speed [N m].
    nominal_speed : float or array_like
        ``ω_n > 0``, the primary speed of the nominal point [rad/s].
    nominal_slip, stall_ratio : float or array_like
        ``s_n`` and ``k`` as in :func:`slip_shape`.

    Returns
    -------
    ndarray
        [N m], positive when the primary drives.

    Notes
    -----
    Quasi-static: the oil's circulation follows the slip at once (its own time lag,
    a few hundredths of a second, neglected); constant fill (no delay chamber
    emptying during the start); valid for ``|s| <= 1`` (module notes).

    References
    ----------
    Voith Turbo, *Hydrodynamics in Drive Engineering* (Vogel, 1987): similarity law
    ``T = λ ρ ω_p² D⁵``; :func:`slip_shape` for ``λ(s)/λ(s_n)``.

    Examples
    --------
    >>> round(float(coupling_torque(150.0, 145.5, 300.0, 150.0, 0.03, 2.5)), 6)   # nominal
    300.0
    >>> round(float(coupling_torque(75.0, 0.0, 300.0, 150.0, 0.03, 2.5)), 3)      # stall, half speed
    187.5
    >>> float(coupling_torque(0.0, 3.0, 300.0, 150.0, 0.03, 2.5))
    0.0
    """
    wp = as_float_array("primary_speed", primary_speed)
    wt = as_float_array("secondary_speed", secondary_speed)
    tn = check_positive("nominal_torque", nominal_torque, "N m")
    wn = check_positive("nominal_speed", nominal_speed, "rad/s")
    sn, k = _check(nominal_slip, stall_ratio)
    c = (1.0 - k * sn) / (k - 1.0)
    d = wp - wt
    den = sn * np.abs(wp) + c * np.abs(d)
    safe = np.where(den > 0, den, 1.0)
    return np.where(den > 0, tn * (1.0 + c) / (wn * wn) * wp * wp * d / safe, 0.0)


@dataclass(frozen=True)
class FluidCoupling(Result):
    """A constant-fill fluid coupling reduced to the driven wheel's shaft (:func:`coupling_torque`).

    Parameters
    ----------
    nominal_torque : float
        ``T_n`` at the wheel [N m].
    nominal_speed : float
        ``ω_n``, primary speed of the nominal point, at the wheel [rad/s].
    nominal_slip : float
        ``s_n`` in [0.005, 0.2].
    stall_ratio : float
        ``k = T(s = 1)/T_n`` in [1.1, 6] (at ``ω_p = ω_n``).
    """

    nominal_torque: float = quantity("N*m")
    nominal_speed: float = quantity("rad/s")
    nominal_slip: float = quantity("1")
    stall_ratio: float = quantity("1")

    def __post_init__(self) -> None:
        check_positive("nominal_torque", self.nominal_torque, "N m")
        check_positive("nominal_speed", self.nominal_speed, "rad/s")
        _check(self.nominal_slip, self.stall_ratio)

    @property
    def shape_constant(self) -> float:
        """``c = (1 − k s_n)/(k − 1)`` of :func:`slip_shape`."""
        return (1.0 - self.stall_ratio * self.nominal_slip) / (self.stall_ratio - 1.0)

    @classmethod
    def sized(cls, nominal_torque: float, primary_speed: float, *, nominal_slip: float = 0.03,
              stall_ratio: float = 1.5) -> FluidCoupling:
        """A coupling transmitting ``nominal_torque`` [N m] at ``nominal_slip`` when its
        primary turns at ``primary_speed`` [rad/s] (both at the wheel): a coupling sized
        on the motor's rated point.

        Examples
        --------
        >>> c = FluidCoupling.sized(9500.0, 4.2)
        >>> c.nominal_slip, c.stall_ratio, round(c.shape_constant, 4)
        (0.03, 1.5, 1.91)
        """
        return cls(float(nominal_torque), float(primary_speed), float(nominal_slip), float(stall_ratio))

    def kernel_constants(self) -> tuple[float, float, float]:
        """``(T_n (1 + c)/ω_n², s_n, c)``: the constants of the regular form of
        :func:`coupling_torque` (the simulation kernel's)."""
        c = self.shape_constant
        return (self.nominal_torque * (1.0 + c) / self.nominal_speed**2, float(self.nominal_slip), c)

    def torque(self, primary_speed: ArrayLike, secondary_speed: ArrayLike) -> FloatOrArray:
        """Transmitted torque [N m] (:func:`coupling_torque`)."""
        return coupling_torque(primary_speed, secondary_speed, self.nominal_torque, self.nominal_speed,
                               self.nominal_slip, self.stall_ratio)
