"""Hertz line contact of two parallel cylinders, and Garshniev & Maksymovych form of it.

Garshniev & Maksymovych (Garshnev & Maksymovych, Lviv) prints the roller–tooth contact stress as

.. math:: \\sigma = 0.418 \\sqrt{\\frac{Q_n E}{L_p \\rho}},\\qquad
          \\rho = \\frac{D_p r_1}{2 (r_1 \\pm 0.5 D_p)}

This module gives the general Hertz solution for two materials (Johnson 1985, §4.3)
and shows that the paper's form is its special case for two bodies of the same
material with Poisson's ratio 0.3: ``0.418 = sqrt(1 / (2π (1 − ν²)))`` and ``ρ`` is
the reduced radius of curvature ``1/ρ = 1/R1 ± 1/R2`` with ``R1 = D_p/2`` (roller)
and ``R2 = r1`` (tooth profile), ``+`` for a convex flank, ``−`` for a concave seat.
The printed ``ρ`` is correct (derivation in ``docs/strength.md``).
"""

from __future__ import annotations

import warnings

import numpy as np
from numpy.typing import ArrayLike

from .._deprecation import renamed_attributes as _renamed_attributes
from .._docs import Fragments
from .._finite import finite_guard
from .._registry import Registry
from .._typing import FloatOrArray
from .._validation import check_positive, check_range
from ..errors import InfeasibleError, ValidityRangeWarning

__all__ = [
    "STEEL_ELASTIC_MODULUS",
    "STEEL_POISSON_RATIO",
    "CONTACT_KINDS",
    "effective_modulus",
    "reduced_radius",
    "hertz_line_pressure",
    "hertz_line_half_width",
    "skew_paper_contact_coefficient",
    "skew_paper_contact_stress",
    "CONFORMITY_LIMIT",
    "warn_conformal",
]

#: Largest contact half-width / body radius for which Hertz theory is used without a
#: warning (Hertz assumes the contact small against the radii; Johnson 1985 §4.1).
CONFORMITY_LIMIT = 0.1

#: Young's modulus of steel used as default [Pa] (2.1e5 MPa, the value of Russian texts).
STEEL_ELASTIC_MODULUS = 2.1e11
#: Poisson's ratio of steel used as default [-].
STEEL_POISSON_RATIO = 0.3

#: Sign of the second curvature: convex (roller on a convex flank) or concave
#: (roller in a concave seat).
CONTACT_KINDS = Registry("contact")
CONTACT_KINDS.add("convex", 1.0)
CONTACT_KINDS.add("concave", -1.0)


def _out(x: ArrayLike) -> FloatOrArray:
    x = np.asarray(x, dtype=float)
    return float(x) if x.ndim == 0 else x


@finite_guard
def effective_modulus(elastic_modulus_1: ArrayLike, poisson_ratio_1: ArrayLike,
                      elastic_modulus_2: ArrayLike | None = None,
                      poisson_ratio_2: ArrayLike | None = None) -> FloatOrArray:
    r"""Contact (plane-strain effective) modulus ``E*`` of two elastic bodies.

    .. math:: \frac{1}{E^*} = \frac{1-\nu_1^2}{E_1} + \frac{1-\nu_2^2}{E_2}

    Parameters
    ----------
    elastic_modulus_1, poisson_ratio_1 : float or array_like
        Young's modulus [Pa] and Poisson's ratio [-] of body 1.
    elastic_modulus_2, poisson_ratio_2 : float or array_like, optional
        The same for body 2 (default: equal to body 1).

    Returns
    -------
    float or ndarray
        ``E*`` [Pa].

    Notes
    -----
    Valid for linear elastic isotropic bodies; ``0 <= ν < 0.5``.

    References
    ----------
    K. L. Johnson, *Contact Mechanics*, Cambridge University Press 1985, §4.3, eq. (4.44)
    (definition of ``E*``, pp. 99–104).

    Examples
    --------
    >>> round(effective_modulus(2.1e11, 0.3) / 1e9, 3)
    115.385
    """
    e1 = check_positive("elastic_modulus_1", elastic_modulus_1, "Pa")
    n1 = check_range("poisson_ratio_1", poisson_ratio_1, 0.0, 0.5, high_inclusive=False)
    e2 = e1 if elastic_modulus_2 is None else check_positive("elastic_modulus_2", elastic_modulus_2, "Pa")
    n2 = n1 if poisson_ratio_2 is None else check_range(
        "poisson_ratio_2", poisson_ratio_2, 0.0, 0.5, high_inclusive=False
    )
    return _out(1.0 / ((1 - n1**2) / e1 + (1 - n2**2) / e2))


@finite_guard
def reduced_radius(radius_1: ArrayLike, radius_2: ArrayLike, contact: str = "convex") -> FloatOrArray:
    r"""Reduced radius of curvature ``ρ`` of two parallel cylinders.

    .. math:: \frac{1}{\rho} = \frac{1}{R_1} \pm \frac{1}{R_2}

    ``+`` for two convex bodies (roller on a convex flank), ``−`` when body 2 is
    concave and wraps body 1 (roller in a seat). With ``R1 = D_p/2`` and ``R2 = r1``
    this is Garshniev & Maksymovych's ``ρ = D_p r1 / (2 (r1 ± 0.5 D_p))``.

    Parameters
    ----------
    radius_1 : float or array_like
        Radius of the convex body 1 (roller, pin) [m].
    radius_2 : float or array_like
        Radius of body 2 (tooth profile) [m]; for ``contact="concave"`` it must exceed
        ``radius_1``.
    contact : {"convex", "concave"}
        Curvature of body 2 as seen from body 1.

    Returns
    -------
    float or ndarray
        ``ρ`` [m].

    Raises
    ------
    InfeasibleError
        Concave seat not larger than the roller (``radius_2 <= radius_1``).

    References
    ----------
    Johnson 1985, §4.3 (``1/R = 1/R1 + 1/R2``, concave radius negative); Garshniev & Maksymovych, text
    after eq. (1).

    Examples
    --------
    >>> round(reduced_radius(0.00794, 0.0081, "concave") * 1e3, 2)
    401.95
    >>> round(reduced_radius(0.00794, 0.0081, "convex") * 1e3, 3)
    4.01
    """
    sign = CONTACT_KINDS.get(contact)
    r1 = check_positive("radius_1", radius_1, "m")
    r2 = check_positive("radius_2", radius_2, "m")
    if sign < 0 and np.any(r2 <= r1):
        raise InfeasibleError(
            "concave contact needs the seat radius larger than the roller/pin radius "
            "(radius_2 > radius_1); equal radii are a conformal fit, not a Hertz contact"
        )
    return _out(1.0 / (1.0 / r1 + sign / r2))


#: The parameters of a line contact, described once (:mod:`chaindrive._docs`).
_DOCS = Fragments(line_contact="""
    load : float or array_like
        Normal force ``F`` [N].
    length : float or array_like
        Contact length ``L`` [m].
    radius : float or array_like
        Reduced radius of curvature ``R`` (:func:`reduced_radius`) [m].
    modulus : float or array_like
        Contact modulus ``E*`` (:func:`effective_modulus`) [Pa].
""")
_DOCS.section("line_contact_parameters", "line_contact")


@finite_guard
@_DOCS
def hertz_line_pressure(load: ArrayLike, length: ArrayLike, radius: ArrayLike, modulus: ArrayLike) -> FloatOrArray:
    r"""Peak Hertz pressure of a line contact (two parallel cylinders).

    .. math:: p_{max} = \sqrt{\frac{F E^*}{\pi L R}}

    %(line_contact_parameters)s

    Returns
    -------
    float or ndarray
        Peak pressure ``p_max`` at the middle of the contact strip [Pa].

    Notes
    -----
    Elastic, frictionless, long cylinders (``L`` much larger than the contact width),
    small contact width compared with the radii; uniform load along ``L`` (no skew).

    References
    ----------
    Johnson 1985, §4.3, eq. (4.45), pp. 99–104; Young & Budynas, *Roark's Formulas for
    Stress and Strain*, 7th ed., Table 14.1, case 2 (``σ_max = 0.798 sqrt(p/(K_D C_E))``).

    Examples
    --------
    >>> round(hertz_line_pressure(10e3, 0.02, 0.005, 115.385e9) / 1e6, 1)
    1916.5
    """
    f = check_positive("load", load, "N")
    ln = check_positive("length", length, "m")
    r = check_positive("radius", radius, "m")
    e = check_positive("modulus", modulus, "Pa")
    return _out(np.sqrt(f * e / (np.pi * ln * r)))


@finite_guard
@_DOCS
def hertz_line_half_width(load: ArrayLike, length: ArrayLike, radius: ArrayLike, modulus: ArrayLike) -> FloatOrArray:
    r"""Half-width ``b`` of the Hertz contact strip of a line contact.

    .. math:: b = \sqrt{\frac{4 F R}{\pi L E^*}}

    %(line_contact_parameters)s

    Returns
    -------
    float or ndarray
        Half width ``b`` of the contact strip [m].

    References
    ----------
    Johnson 1985, §4.3, eq. (4.43), pp. 99–104.

    Examples
    --------
    >>> round(hertz_line_half_width(10e3, 0.02, 0.005, 115.385e9) * 1e6, 1)
    166.2
    """
    f = check_positive("load", load, "N")
    ln = check_positive("length", length, "m")
    r = check_positive("radius", radius, "m")
    e = check_positive("modulus", modulus, "Pa")
    return _out(np.sqrt(4 * f * r / (np.pi * ln * e)))


@finite_guard
def skew_paper_contact_coefficient(poisson_ratio: ArrayLike = STEEL_POISSON_RATIO) -> FloatOrArray:
    r"""The coefficient of Garshniev & Maksymovych eq. (1) for two bodies of one material.

    .. math:: k = \sqrt{\frac{1}{2\pi (1-\nu^2)}}

    For ``ν = 0.3`` it is 0.41821, the printed 0.418.

    Parameters
    ----------
    poisson_ratio : float or array_like
        ``ν`` [-], ``0 <= ν < 0.5``.

    Returns
    -------
    float or ndarray
        ``k`` [-].

    References
    ----------
    Garshniev & Maksymovych, paper 2, eq. (1); derived from Johnson 1985 eq. (4.45) with ``E1 = E2 = E``.

    Examples
    --------
    >>> round(skew_paper_contact_coefficient(0.3), 5)
    0.41821
    """
    nu = check_range("poisson_ratio", poisson_ratio, 0.0, 0.5, high_inclusive=False)
    return _out(np.sqrt(1.0 / (2 * np.pi * (1 - nu**2))))


@finite_guard
def skew_paper_contact_stress(load: ArrayLike, length: ArrayLike, reduced_radius_of_curvature: ArrayLike,
                              elastic_modulus: ArrayLike = STEEL_ELASTIC_MODULUS) -> FloatOrArray:
    r"""Contact stress as printed in Garshniev & Maksymovych, eq. (1) (steel on steel, ``ν = 0.3``).

    .. math:: \sigma = 0.418 \sqrt{\frac{Q E}{L_p \rho}}

    Parameters
    ----------
    load : float or array_like
        Compressive force ``Q_n`` [N].
    length : float or array_like
        Roller length ``L_p`` [m].
    reduced_radius_of_curvature : float or array_like
        ``ρ`` [m] (:func:`reduced_radius`).
    elastic_modulus : float or array_like
        ``E`` of both bodies [Pa].

    Returns
    -------
    float or ndarray
        ``σ`` [Pa].

    Notes
    -----
    Equals :func:`hertz_line_pressure` with ``E* = E / (2 (1 − 0.3²))`` to 4 digits (the
    printed 0.418 is rounded from 0.41821).

    References
    ----------
    Garshniev & Maksymovych, paper 2, eq. (1).

    Examples
    --------
    >>> round(skew_paper_contact_stress(10e3, 0.02, 0.005) / 1e6, 1)
    1915.5
    """
    f = check_positive("load", load, "N")
    ln = check_positive("length", length, "m")
    r = check_positive("reduced_radius_of_curvature", reduced_radius_of_curvature, "m")
    e = check_positive("elastic_modulus", elastic_modulus, "Pa")
    return _out(0.418 * np.sqrt(f * e / (ln * r)))




def warn_conformal(half_width: ArrayLike, radius: ArrayLike, what: str = "contact") -> None:
    """Warn (:class:`ValidityRangeWarning`) when ``half_width / radius > CONFORMITY_LIMIT``.

    Hertz theory assumes the contact strip small against the radii of curvature of
    both bodies (Johnson 1985, §4.1); a roller in a seat only slightly larger than it is
    a conforming contact, for which the Hertz pressure is an upper estimate.

    Examples
    --------
    >>> warn_conformal(0.1e-3, 8e-3)
    """
    ratio = np.asarray(half_width, dtype=float) / np.asarray(radius, dtype=float)
    if np.any(ratio > CONFORMITY_LIMIT):
        warnings.warn(
            f"{what}: contact half-width / radius = {float(np.max(ratio)):.3g} > {CONFORMITY_LIMIT} "
            "(conforming contact): Hertz theory is outside its range (Johnson 1985 4.1), "
            "the stress is an upper estimate",
            ValidityRangeWarning,
            stacklevel=3,
        )


# former public names (renamed; deprecated, removed in the next release: chaindrive._deprecation)
__getattr__ = _renamed_attributes(
    "chaindrive.strength.hertz",
    {"seed_contact_stress": "skew_paper_contact_stress",
     "seed_contact_coefficient": "skew_paper_contact_coefficient"})
