"""Sag coupling of the self-regulating drive: the catenary length excess, the pivot offset
for a coefficient, the sag stiffness and the carrier's natural frequency (closed forms)."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from .._validation import as_float_array, check_nonnegative, check_positive, check_range
from ..errors import InfeasibleError, InputError
from .statics import GRAVITY

__all__ = [
    "sag_length_excess",
    "pivot_offset_for_coefficient",
    "sag_stiffness",
    "carrier_natural_frequency",
]

def sag_length_excess(chord_length: ArrayLike, inclination: ArrayLike, tension: ArrayLike,
                      mass_per_length: ArrayLike, gravity: float = GRAVITY) -> np.ndarray:
    r"""Chain length taken up by the sag of a span, parabolic closed form.

    .. math:: \Delta = \frac{(q g)^2 \ell^3 \cos^2\gamma}{24\,S^2}

    Parameters
    ----------
    chord_length : float or array_like
        Span chord ``ℓ`` [m].
    inclination : float or array_like
        Chord angle ``γ`` above the horizontal [rad].
    tension : float or array_like
        Static span tension ``S > 0`` along the chord [N] (horizontal component
        ``H = S cos γ``).
    mass_per_length : float or array_like
        ``q`` [kg/m].
    gravity : float
        [m/s²].

    Returns
    -------
    ndarray
        Arc length minus chord ``Δ`` [m].

    Notes
    -----
    Derivation: the span hangs as a parabola about its chord under ``w = q g / cos γ``
    per horizontal length; expanding the arc length to second order in the deflection
    slope gives ``Δ = w² ℓx³ cos³γ / (24 H²)`` with ``ℓx = ℓ cos γ``; with ``H = S cos γ``
    the form above (horizontal span: the classic ``8 f² / 3ℓ``). Within 1 % of the exact
    catenary arc for a sag ratio ``f/ℓ <= 0.05`` (tested).

    References
    ----------
    Irvine, H. M., Cable Structures, MIT Press 1981, ch. 1 (parabolic cable, length).

    Examples
    --------
    >>> round(float(sag_length_excess(1.0, 0.0, 500.0, 2.6)) * 1e6, 2)  # 8 f²/3ℓ, f = 6.37 mm
    108.35
    """
    ell = check_positive("chord_length", chord_length, "m")
    g = as_float_array("inclination", inclination)
    S = check_positive("tension", tension, "N")
    q = check_positive("mass_per_length", mass_per_length, "kg/m")
    gr = check_positive("gravity", gravity, "m/s^2")
    return (q * gr) ** 2 * ell**3 * np.cos(g) ** 2 / (24.0 * S**2)


def _catenary_excess(chord_length, inclination, tension, mass_per_length, gravity=GRAVITY):
    """Exact arc length minus chord of a catenary span (tension along the chord, H = S cos γ)."""
    ell = np.asarray(chord_length, dtype=float)
    cg = np.abs(np.cos(inclination))
    H = np.asarray(tension, dtype=float) * cg
    lx = ell * cg
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        X = np.where(cg > 1e-9, mass_per_length * gravity * lx / (2.0 * np.maximum(H, 1e-300)), 0.0)
        small = X < 1e-3
        Xs = np.where(small, 1.0, X)
        A = np.where(small, X**2 / 6.0 + X**4 / 120.0, np.sinh(Xs) / Xs - 1.0)
        ds2 = lx**2 * A * (A + 2.0)  # s² - ℓ², s² = h² + (2 sinh X / k)²
        s = np.sqrt(ell**2 + ds2)
    return ds2 / (s + ell)


def pivot_offset_for_coefficient(coefficient: ArrayLike, pitch_radius: ArrayLike,
                                 span_angle: ArrayLike = 0.0, along: ArrayLike = 0.0) -> np.ndarray:
    r"""Offset of the pivot from the centre line that gives a regulation coefficient ψ.

    .. math:: y = \frac{R_C + x \sin\beta}{(2\psi + 1)\cos\beta}

    Parameters
    ----------
    coefficient : float or array_like
        Wanted ψ, ``ψ > -1/2`` [-].
    pitch_radius : float or array_like
        Pitch radius ``R_C`` of the carrier wheel [m].
    span_angle : float or array_like
        ``β = asin((R_C - R_F)/a)``, the spans' angle to the centre line [rad].
    along : float or array_like
        Position ``x = (O - C)·n`` of the pivot along the centre line, measured from the
        carrier wheel centre away from the fixed wheel [m].

    Returns
    -------
    ndarray
        Offset ``y`` [m] of the pivot from the centre line, on the side of the tight
        span (pivoted carrier, torque reacted on the carrier).

    Notes
    -----
    Inverse of :func:`regulation_coefficient` for the pivoted carrier with the torque
    reacted on it: ``ψ = -1/2 + (R_C + x sin β)/(2 y cos β)`` (docs/self_regulating.md).
    ``ψ = 0`` puts the pivot on the tight span's line (``y = R_C`` for ``β = 0``); a
    larger ψ moves it toward the centre line. The carrier wheel then moves ``y``
    per radian of swing along the centre line, so a small ψ also means a long lever
    for the wear take-up.

    References
    ----------
    Derived here from the carrier statics (docs/self_regulating.md); the self-regulating drive
    paper's conclusion that the geometric parameters set the regulation.

    Examples
    --------
    >>> round(float(pivot_offset_for_coefficient(0.5, 0.08)), 6)
    0.04
    """
    psi = check_range("coefficient", coefficient, -0.5, np.inf, low_inclusive=False)
    R = check_positive("pitch_radius", pitch_radius, "m")
    b = check_range("span_angle", span_angle, -np.pi / 2, np.pi / 2, low_inclusive=False,
                    high_inclusive=False, unit="rad")
    x = as_float_array("along", along)
    y = (R + x * np.sin(b)) / ((2.0 * psi + 1.0) * np.cos(b))
    if np.any(y <= 0):
        raise InfeasibleError(f"no pivot offset gives ψ = {np.asarray(coefficient)}: R_C + x sin β must be > 0")
    return y


def sag_stiffness(centre_distance_rate: ArrayLike, length_rate: ArrayLike, span_angle: ArrayLike,
                  sag_excess_tight: ArrayLike, tight_tension: ArrayLike, sag_excess_slack: ArrayLike,
                  slack_tension: ArrayLike, elastic_compliance: ArrayLike = 0.0) -> np.ndarray:
    r"""Stiffness of the carrier on the sag of the spans (the chain as a spring).

    .. math::
        K_s = \frac{\cos\beta\, L'(a)\, a_q^2}{\Delta_1/S_1 + \Delta_2/S_2 + L/(2EA)}

    Parameters
    ----------
    centre_distance_rate : float or array_like
        ``a_q = ∂a/∂q`` [m/rad] (pivot) or [-] (slide).
    length_rate : float or array_like
        ``L'(a) = dL_taut/da`` [-] (about 2; ISO form ``2 - (r2 - r1)²/a²``).
    span_angle : float or array_like
        ``β`` [rad].
    sag_excess_tight, sag_excess_slack : float or array_like
        Lengths ``Δ1, Δ2`` taken by the sag (:func:`sag_length_excess`) [m].
    tight_tension, slack_tension : float or array_like
        ``S1, S2 > 0`` [N].
    elastic_compliance : float or array_like
        ``L/(2EA) >= 0`` of the chain of length ``L`` and axial stiffness ``EA`` [m/N];
        0 for an inextensible chain.

    Returns
    -------
    ndarray
        ``K_s`` [N·m/rad] (pivot) or [N/m] (slide).

    Notes
    -----
    Derivation: at a fixed torque both tensions change by the same ``δS``; the carrier
    moving by ``δq`` lengthens the taut path by ``L' a_q δq``, which the sag gives back,
    ``δΔ = -2 (Δ1/S1 + Δ2/S2) δS`` (``Δ ∝ S⁻²``), and the elastic stretch, ``L δS/EA``
    (both tensions rise by ``δS`` along the whole chain); the generalized force of the tensions
    changes by ``(g1 + g2) δS = -2 cos β a_q δS``. The carrier's full stiffness adds the
    change of the arms and of weight and spring at fixed tensions (see
    :func:`self_regulating_drive`). Tested against the numerical equilibrium (preload
    perturbed).

    References
    ----------
    Derived here (docs/self_regulating.md, "Carrier stiffness and resonance").

    Examples
    --------
    >>> round(float(sag_stiffness(0.045, 2.0, 0.0, 1e-5, 300.0, 1e-4, 100.0)), 1)
    3919.4
    """
    aq = as_float_array("centre_distance_rate", centre_distance_rate)
    Lp = check_positive("length_rate", length_rate)
    b = check_range("span_angle", span_angle, -np.pi / 2, np.pi / 2, low_inclusive=False,
                    high_inclusive=False, unit="rad")
    d1 = check_nonnegative("sag_excess_tight", sag_excess_tight, "m")
    d2 = check_nonnegative("sag_excess_slack", sag_excess_slack, "m")
    s1 = check_positive("tight_tension", tight_tension, "N")
    s2 = check_positive("slack_tension", slack_tension, "N")
    compliance = d1 / s1 + d2 / s2 + check_nonnegative("elastic_compliance", elastic_compliance, "m/N")
    if np.any(compliance <= 0):
        raise InputError("sag_excess_tight, sag_excess_slack and elastic_compliance must not all "
                         "be 0 (a chain without sag or stretch is rigid: infinite stiffness)")
    return np.cos(b) * Lp * aq**2 / compliance


def carrier_natural_frequency(stiffness: ArrayLike, inertia: ArrayLike) -> np.ndarray:
    r"""Natural angular frequency of the carrier on its stiffness.

    .. math:: P_c = \sqrt{K / J}

    Parameters
    ----------
    stiffness : float or array_like
        ``K > 0`` [N·m/rad] (pivot) or [N/m] (slide).
    inertia : float or array_like
        ``J > 0``: moment of inertia about the pivot [kg·m²] or mass on the slide [kg].

    Returns
    -------
    ndarray
        ``P_c`` [rad/s].

    Raises
    ------
    InfeasibleError
        ``K <= 0``: the carrier's equilibrium is statically unstable.

    References
    ----------
    One degree of freedom, undamped (docs/self_regulating.md).

    Examples
    --------
    >>> round(float(carrier_natural_frequency(400.0, 0.25)), 3)
    40.0
    """
    K = as_float_array("stiffness", stiffness)
    if np.any(K <= 0) or not np.all(np.isfinite(K)):
        raise InfeasibleError(
            f"stiffness must be positive and finite (0 < K < inf), got {K}: the carrier's "
            "equilibrium is statically unstable")
    J = check_positive("inertia", inertia)
    return np.sqrt(K / J)


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
