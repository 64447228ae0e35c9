r"""Longitudinal (wave-type) and torsional (spring-type) natural frequencies of a chain drive.

Two closed forms beside the transverse string of :mod:`chaindrive.vibration.string`:

* the **longitudinal** natural frequencies of a span held at both ends by its wheels, an
  elastic rod of axial stiffness ``EA`` and mass per length ``q``:
  ``ω_n = n π c / l``, ``c = sqrt(EA / q)`` (S. S. Rao, *Mechanical Vibrations*, 5th ed.,
  §8.3, longitudinal vibration of a bar fixed at both ends; the chain's running speed
  ``v ≪ c`` changes them by ``(1 - v²/c²)``, Wickert & Mote 1990, and is neglected);
* the **torsional** natural frequency of a wheel of inertia ``J`` held by chain spans of
  axial stiffnesses ``k_i = EA / l_i`` at its pitch radius ``R``:
  ``ω_t = R sqrt(Σ k_i / J)`` (Rao, §2.2, torsional system with one degree of freedom:
  ``ω = sqrt(k_t / J)``, here ``k_t = R² Σ k_i``).

Both are compared with the excitations of the polygonal action (the tooth frequency
``z1 ω1``) by the analysis part :mod:`chaindrive.analysis.critical_speeds`.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from .._validation import check_positive

__all__ = ["longitudinal_frequency", "torsional_frequency"]


def longitudinal_frequency(length: ArrayLike, axial_stiffness: ArrayLike, mass_per_length: ArrayLike,
                           mode: int = 1) -> np.ndarray:
    r"""Longitudinal natural frequency of a chain span held at both ends.

    .. math:: \omega_n = \frac{n\pi}{l}\sqrt{\frac{EA}{q}}

    Parameters
    ----------
    length : float or array_like
        Span length ``l`` [m].
    axial_stiffness : float or array_like
        ``EA`` of the chain [N].
    mass_per_length : float or array_like
        ``q`` [kg/m].
    mode : int
        ``n >= 1``.

    Returns
    -------
    ndarray
        First longitudinal natural frequency of the span [rad/s].

    References
    ----------
    S. S. Rao, *Mechanical Vibrations*, 5th ed., §8.3 (bar fixed at both ends).

    Examples
    --------
    >>> round(float(longitudinal_frequency(1.0, 1e8, 2.6)) / (2 * np.pi))   # about 3.1 kHz
    3101
    """
    l = check_positive("length", length, "m")
    ea = check_positive("axial_stiffness", axial_stiffness, "N")
    q = check_positive("mass_per_length", mass_per_length, "kg/m")
    if isinstance(mode, bool) or int(mode) != mode or mode < 1:
        from ..errors import InputError

        raise InputError(f"mode must be a whole number >= 1, got {mode!r}", field="mode")
    return mode * np.pi / l * np.sqrt(ea / q)


def torsional_frequency(inertia: ArrayLike, radius: ArrayLike, stiffness: ArrayLike) -> np.ndarray:
    r"""Torsional natural frequency of a wheel held by the chain at its pitch radius.

    .. math:: \omega_t = R\sqrt{\frac{\sum_i k_i}{J}}

    Parameters
    ----------
    inertia : float or array_like
        Wheel (and shaft, load) inertia ``J`` [kg m²].
    radius : float or array_like
        Pitch radius ``R`` [m].
    stiffness : float or array_like
        Sum of the axial stiffnesses ``EA / l_i`` of the spans that hold the wheel [N/m].

    Returns
    -------
    ndarray
        Torsional natural frequency of the wheel [rad/s].

    References
    ----------
    S. S. Rao, *Mechanical Vibrations*, 5th ed., §2.2 (torsional vibration, one degree of
    freedom, ``ω = sqrt(k_t / J)``).

    Examples
    --------
    >>> round(float(torsional_frequency(0.693, 0.2306, 1e8 / 1.039)))
    2718
    """
    j = check_positive("inertia", inertia, "kg m^2")
    r = check_positive("radius", radius, "m")
    k = check_positive("stiffness", stiffness, "N/m")
    return r * np.sqrt(k / j)


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
