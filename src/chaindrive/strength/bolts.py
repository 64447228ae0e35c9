"""Bolts fastening a toothed rim to the drive wheel hub under the transmitted torque.

Sharipov says the rim's bolts are calculated too (its Fig. 14 is not in the text). The
usual two joint types are covered, with the simplifications of machine-design texts:

* Fitted (reamed) bolts in shear: the torque is shared equally by ``n`` bolts on the
  bolt circle (rigid flanges, symmetric pattern), ``F = T / (n R_b)``; shear
  ``τ = F / (m π d² / 4)`` over ``m`` shear planes and bearing ``p = F / (d t)``.
* Friction (slip-resistant) joint: the clamp load per bolt needed so that friction on
  ``q`` interfaces carries the torque with a slip safety ``S``,
  ``F_V = S T / (μ q n R_b)`` (VDI 2230-1 step R2, ``F_KQerf = M_Y / (q_M r_a μ_T)``
  per bolt), and the preload stress ``F_V / A_s`` against the yield strength
  (tightening torsion and prestress loss by embedding are not included: add them
  with the slip safety or use a full VDI 2230 calculation).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from .._finite import finite_guard
from .._results import Result, quantity
from .._typing import FloatOrArray
from .._validation import check_positive, check_range
from ..errors import InputError

__all__ = [
    "bolt_stress_area",
    "bolt_force_from_torque",
    "FittedBoltResult",
    "fitted_bolt_check",
    "FrictionBoltResult",
    "friction_bolt_preload",
]


def _out(x: ArrayLike) -> FloatOrArray:
    x = np.asarray(x, dtype=float)
    return float(x) if x.ndim == 0 else x


def _count(name: str, value: ArrayLike, low: int = 1) -> np.ndarray:
    v = np.asarray(value)
    if v.dtype.kind not in "iuf" or np.any(v != np.round(v)) or np.any(v < low):
        raise InputError(f"{name} must be a whole number >= {low}, got {value!r}")
    return v.astype(float)


@finite_guard
def bolt_stress_area(diameter: ArrayLike, thread_pitch: ArrayLike) -> FloatOrArray:
    r"""Tensile stress area of an ISO metric thread.

    .. math:: A_s = \frac{\pi}{4}\left(\frac{d_2 + d_3}{2}\right)^2,\quad
              d_2 = d - 0.649519 P,\ d_3 = d - 1.226869 P

    Parameters
    ----------
    diameter : float or array_like
        Nominal diameter ``d`` [m].
    thread_pitch : float or array_like
        Thread pitch ``P`` [m], ``0 < P < d/2``.

    Returns
    -------
    float or ndarray
        ``A_s`` [m²].

    References
    ----------
    ISO 898-1:2013, clause 9.1.6.1, eq. for ``A_s,nom`` (Table 4/5 values: M12 84.3,
    M16 157, M20 245 mm²).

    Examples
    --------
    >>> round(bolt_stress_area(0.016, 0.002) * 1e6, 1)
    156.7
    """
    d = check_positive("diameter", diameter, "m")
    p = check_positive("thread_pitch", thread_pitch, "m")
    if np.any(p >= d / 2):
        raise InputError("thread_pitch must lie in (0, diameter/2) m")
    d2 = d - 0.649519 * p
    d3 = d - 1.226869 * p
    return _out(np.pi / 4 * ((d2 + d3) / 2) ** 2)


@finite_guard
def bolt_force_from_torque(torque: ArrayLike, bolt_circle_radius: ArrayLike, bolts: ArrayLike) -> FloatOrArray:
    r"""Transverse force per bolt of a circular pattern transmitting a torque.

    .. math:: F = \frac{T}{n R_b}

    Parameters
    ----------
    torque : float or array_like
        Transmitted torque ``T`` [N m].
    bolt_circle_radius : float or array_like
        ``R_b`` [m].
    bolts : int or array_like
        Number of bolts ``n >= 1``.

    Returns
    -------
    float or ndarray
        ``F`` [N].

    Notes
    -----
    Rigid flanges, bolts equally spaced: each bolt takes ``F_i = T r_i / Σ r_j²``,
    which is ``T / (n R_b)`` on one circle.

    References
    ----------
    Budynas & Nisbett, *Shigley's Mechanical Engineering Design*, 9th ed., §8-12
    (bolted joints loaded in shear, secondary shear ``F'' = M r_n / Σ r²``).

    Examples
    --------
    >>> round(bolt_force_from_torque(6900.0, 0.25, 12), 1)
    2300.0
    """
    t = check_positive("torque", torque, "N m")
    r = check_positive("bolt_circle_radius", bolt_circle_radius, "m")
    n = _count("bolts", bolts)
    return _out(t / (n * r))


@dataclass(frozen=True)
class FittedBoltResult(Result):
    """Fitted bolts in shear (SI): ``bolt_force`` [N], ``shear_stress`` [Pa],
    ``bearing_stress`` [Pa] (None without a clamp thickness), ``shear_safety``,
    ``bearing_safety`` [-] (None without an allowable), ``passes``."""

    bolt_force: float = quantity("N")
    shear_stress: float = quantity("Pa")
    bearing_stress: float | None = quantity("Pa")
    shear_safety: float | None = quantity("1")
    bearing_safety: float | None = quantity("1")
    passes: bool


@finite_guard
def fitted_bolt_check(torque: float, bolt_circle_radius: float, bolts: int, shank_diameter: float, *,
                      shear_planes: int = 1, plate_thickness: float | None = None,
                      allowable_shear: float | None = None,
                      allowable_bearing: float | None = None) -> FittedBoltResult:
    r"""Fitted (reamed) bolts of a rim: shear and bearing under the torque.

    .. math:: \tau = \frac{4 F}{m \pi d^2},\qquad p = \frac{F}{d\, t_{min}},\qquad
              F = \frac{T}{n R_b}

    Parameters
    ----------
    torque : float
        Torque carried by the rim [N m] (for one rim: ``P_Р R_о``).
    bolt_circle_radius : float
        ``R_b`` [m].
    bolts : int
        ``n``.
    shank_diameter : float
        Fitted shank diameter ``d`` [m].
    shear_planes : int
        ``m`` (1 for rim on a flange, 2 for a rim between two flanges).
    plate_thickness : float, optional
        Smallest clamped part thickness for bearing ``t_min`` [m].
    allowable_shear, allowable_bearing : float, optional
        User allowables [Pa].

    Returns
    -------
    FittedBoltResult

    References
    ----------
    Shigley 9th ed. §8-12 (shear of bolts, bearing on members); Roloff/Matek,
    *Maschinenelemente*, ch. 8 (Passschrauben: ``τ = F_Q/(A m)``, ``p = F_Q/(d t)``).

    Examples
    --------
    >>> r = fitted_bolt_check(6900.0, 0.25, 12, 0.017, plate_thickness=0.02,
    ...                       allowable_shear=150e6, allowable_bearing=300e6)
    >>> round(r.shear_stress / 1e6, 2), round(r.bearing_stress / 1e6, 2), round(r.shear_safety, 1)
    (10.13, 6.76, 14.8)
    """
    f = float(bolt_force_from_torque(torque, bolt_circle_radius, bolts))
    d = float(check_positive("shank_diameter", shank_diameter, "m"))
    m = float(_count("shear_planes", shear_planes))
    tau = 4 * f / (m * np.pi * d**2)
    pb = None
    if plate_thickness is not None:
        pb = f / (d * float(check_positive("plate_thickness", plate_thickness, "m")))
    fs = None if allowable_shear is None else float(check_positive("allowable_shear", allowable_shear, "Pa")) / tau
    fb = None
    if allowable_bearing is not None:
        if pb is None:
            raise InputError("plate_thickness (> 0 m) is needed for the bearing check with allowable_bearing")
        fb = float(check_positive("allowable_bearing", allowable_bearing, "Pa")) / pb
    return FittedBoltResult(f, tau, pb, fs, fb, all(v is None or v >= 1 for v in (fs, fb)))


@dataclass(frozen=True)
class FrictionBoltResult(Result):
    """Friction joint (SI): ``bolt_force`` transverse force per bolt [N],
    ``required_preload`` per bolt [N], ``preload_stress`` F_V/A_s [Pa] (None without
    a stress area), ``yield_safety`` R_p0.2 / σ_V [-] (None without a yield strength),
    ``passes``."""

    bolt_force: float = quantity("N")
    required_preload: float = quantity("N")
    preload_stress: float | None = quantity("Pa")
    yield_safety: float | None = quantity("1")
    passes: bool


@finite_guard
def friction_bolt_preload(torque: float, bolt_circle_radius: float, bolts: int, friction: float, *,
                          friction_faces: int = 1, slip_safety: float = 1.25, stress_area: float | None = None,
                          yield_strength: float | None = None) -> FrictionBoltResult:
    r"""Required preload of the bolts of a friction-type (slip-resistant) rim joint.

    .. math:: F_V = \frac{S\, T}{\mu\, q\, n\, R_b}

    Parameters
    ----------
    torque : float
        Torque [N m].
    bolt_circle_radius : float
        ``R_b`` [m] (mean radius of the friction faces taken equal to it).
    bolts : int
        ``n``.
    friction : float
        Coefficient of static friction ``μ`` [-], ``0 < μ <= 1`` (steel dry 0.1…0.2).
    friction_faces : int
        Number of frictional interfaces ``q``.
    slip_safety : float
        Safety against slipping ``S >= 1`` (VDI 2230-1 recommends 1.2 static, 1.8
        alternating loads).
    stress_area : float, optional
        ``A_s`` [m²] (:func:`bolt_stress_area`).
    yield_strength : float, optional
        ``R_p0.2`` of the bolt [Pa] (8.8: 640 MPa; 10.9: 940 MPa, ISO 898-1).

    Returns
    -------
    FrictionBoltResult

    References
    ----------
    VDI 2230 Blatt 1:2015, step R2 (required clamp load for transverse force and
    torque, ``F_KQerf = M_Y / (q_M r_a μ_Tmin)``) and clause 5.5.6 (slip safety).

    Examples
    --------
    >>> r = friction_bolt_preload(6900.0, 0.25, 12, 0.15, stress_area=157e-6, yield_strength=640e6)
    >>> round(r.required_preload), round(r.preload_stress / 1e6, 1), round(r.yield_safety, 1)
    (19167, 122.1, 5.2)
    """
    f = float(bolt_force_from_torque(torque, bolt_circle_radius, bolts))
    mu = float(check_range("friction", friction, 0.0, 1.0, low_inclusive=False))
    q = float(_count("friction_faces", friction_faces))
    s = float(check_range("slip_safety", slip_safety, 1.0, np.inf, high_inclusive=False))
    fv = s * f / (mu * q)
    sv = None if stress_area is None else fv / float(check_positive("stress_area", stress_area, "m^2"))
    fy = None
    if yield_strength is not None:
        if sv is None:
            raise InputError("stress_area (> 0 m^2) is needed for the yield check with yield_strength")
        fy = float(check_positive("yield_strength", yield_strength, "Pa")) / sv
    return FrictionBoltResult(f, fv, sv, fy, fy is None or fy >= 1)
