"""Sag of a chain span: catenary, parabola and the tension for a given sag."""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike

from .._docs import Fragments
from .._finite import finite_guard
from .._typing import FloatOrArray
from .._validation import as_float_array, check_positive
from ..errors import InputError

#: Standard gravity [m/s²] (CGPM 1901).
GRAVITY = 9.80665

#: The parameters of a hanging span, described once (:mod:`chaindrive._docs`).
_DOCS = Fragments(
    chord="""
        chord_length : float or array_like
            Distance between the span's end hinges [m].
        inclination : float or array_like
            Angle of the chord above the horizontal [rad], ``|γ| < π/2``.
    """,
    weight="""
        mass_per_length : float or array_like
            Chain mass per length ``q`` [kg/m].
        gravity : float
            Acceleration of gravity ``g`` [m/s²].
    """,
    span_tension="""
        %(chord)s
        tension : float or array_like
            Horizontal component ``H`` of the chain tension [N] (constant along a
            catenary; the tension at a point is ``H cosh``).
        %(weight)s
    """,
)
_DOCS.section("span_parameters", "span_tension")


def _catenary_parts(chord_length, inclination, tension, mass_per_length, gravity):
    L = check_positive("chord_length", chord_length, "m")
    g = as_float_array("inclination", inclination)
    if (np.abs(g) >= np.pi / 2).any():  # g an array (as_float_array)
        raise InputError(f"inclination must lie in (-π/2, π/2) rad (not a vertical span), got {g}")
    H = check_positive("tension", tension, "N")
    q = check_positive("mass_per_length", mass_per_length, "kg/m")
    gr = check_positive("gravity", gravity, "m/s^2")
    span = L * np.cos(g)
    rise = L * np.sin(g)
    k = q * gr / H
    return span, rise, k


@finite_guard
@_DOCS
def catenary_sag(chord_length: ArrayLike, inclination: ArrayLike, tension: ArrayLike,
                 mass_per_length: ArrayLike, gravity: float = GRAVITY) -> FloatOrArray:
    r"""Sag of a chain span hanging as a catenary (largest vertical chord-to-chain distance).

    .. math::
        y = \frac{\cosh k(x - x_0) - \cosh k x_0}{k},\quad k = \frac{q g}{H},\quad
        x_0 = \frac{\ell}{2} - \frac1k\operatorname{asinh}\frac{k h}{2\sinh(k\ell/2)},
        \quad f = m x^* - y(x^*),\ \sinh k(x^* - x_0) = m = h/\ell

    %(span_parameters)s

    Returns
    -------
    ndarray
        Vertical sag ``f`` [m].

    Notes
    -----
    Exact for an inextensible chain of uniform weight per *arc* length; ``ℓ = L cos γ``,
    ``h = L sin γ``. For ``k ℓ → 0`` it tends to :func:`parabolic_sag` (tested).
    Valid for spans that are not vertical.

    References
    ----------
    Irvine, H. M., Cable Structures, MIT Press 1981, ch. 1 (inclined catenary).

    Examples
    --------
    >>> round(float(catenary_sag(2.0, 0.0, 500.0, 2.6)) * 1e3, 3)
    25.503
    """
    span, rise, k = _catenary_parts(chord_length, inclination, tension, mass_per_length, gravity)
    return _catenary_sag(span, rise, k)


def _catenary_sag(span, rise, k):
    # the formula of catenary_sag on checked inputs (horizontal span, rise, k = q g / H)
    x0 = span / 2 - np.arcsinh(k * rise / (2 * np.sinh(k * span / 2))) / k
    m = rise / span
    xs = x0 + np.arcsinh(m) / k
    ys = (np.cosh(k * (xs - x0)) - np.cosh(k * x0)) / k
    return m * xs - ys


@finite_guard
@_DOCS
def parabolic_sag(chord_length: ArrayLike, inclination: ArrayLike, tension: ArrayLike,
                  mass_per_length: ArrayLike, gravity: float = GRAVITY) -> FloatOrArray:
    r"""Sag of a span by the parabolic approximation.

    .. math:: f = \frac{q g \ell^2}{8 H \cos\gamma},\qquad \ell = L\cos\gamma

    %(span_parameters)s

    Returns
    -------
    ndarray
        Vertical sag at mid-span [m].

    Notes
    -----
    Derivation: a taut chain lies close to its chord, so its weight per horizontal
    length is ``q g / cos γ``; a load ``w`` uniform per horizontal length on a string
    with horizontal tension ``H`` gives the parabola with mid-span sag ``w ℓ² / 8H``.
    Within 0.2 % of :func:`catenary_sag` for ``f/ℓ < 0.005`` (tested).

    References
    ----------
    Irvine, H. M., Cable Structures (1981), ch. 1 (inclined parabolic cable).

    Examples
    --------
    >>> round(float(parabolic_sag(2.0, 0.0, 500.0, 2.6)) * 1e3, 3)
    25.497
    """
    span, _, k = _catenary_parts(chord_length, inclination, tension, mass_per_length, gravity)
    return k * span**2 / (8.0 * np.cos(np.asarray(inclination, dtype=float)))


@finite_guard
@_DOCS
def tension_for_sag(chord_length: ArrayLike, inclination: ArrayLike, sag: ArrayLike,
                    mass_per_length: ArrayLike, gravity: float = GRAVITY) -> FloatOrArray:
    r"""Horizontal tension that gives a catenary span the stated sag (inverse).

    .. math:: f(H) = f_{given}\ \text{solved for}\ H

    Parameters
    ----------
    %(chord)s
    sag : float or array_like
        Vertical sag ``f > 0`` [m].
    %(weight)s

    Returns
    -------
    ndarray
        Horizontal tension ``H`` [N].

    Notes
    -----
    The sag decreases monotonically with ``H``; vectorised bisection on ``log H``
    (100 halvings of 30 decades, relative error < 1e-12), started from the parabolic
    value. A catenary can take any sag ``f > 0``.

    References
    ----------
    Inverse of :func:`catenary_sag`.

    Examples
    --------
    >>> round(float(tension_for_sag(2.0, 0.0, 0.025502816, 2.6)), 3)
    500.0
    """
    f = check_positive("sag", sag, "m")
    span, _, k1 = _catenary_parts(chord_length, inclination, 1.0, mass_per_length, gravity)
    w = k1  # q g (k for H = 1)
    H0 = w * span**2 / (8.0 * f)
    lo = np.log(H0) - 15.0 * np.log(10.0)
    hi = np.log(H0) + 15.0 * np.log(10.0)
    lo, hi = np.broadcast_arrays(lo, hi)
    lo, hi = lo.astype(float).copy(), hi.astype(float).copy()
    span, rise, w = np.broadcast_arrays(span, *_catenary_parts(chord_length, inclination, 1.0, mass_per_length,
                                                                gravity)[1:])
    if lo.ndim == 0 and np.ndim(f) == 0 and span.ndim == 0:
        return _bisect_scalar(lo[()], hi[()], span[()], rise[()], w[()], np.asarray(f)[()])
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        settled = bool(np.all((mid == lo) | (mid == hi)))
        too_slack = _catenary_sag(span, rise, w / np.exp(mid)) > f
        lo = np.where(too_slack, mid, lo)
        hi = np.where(too_slack, hi, mid)
        if settled:  # see _bisect_scalar: no later halving changes a bit
            break
    return np.exp(0.5 * (lo + hi))


def _bisect_scalar(lo, hi, span, rise, w, f):
    # the bisection of tension_for_sag for one span on numpy float scalars: the same
    # operations and ufuncs in the same order as on the 0-d arrays (so the same result,
    # bit for bit), without the array overhead of np.where
    # _catenary_sag's steps, with those that do not depend on the tension done once
    half, m = span / 2, rise / span
    asinh_m = np.arcsinh(m)
    # the root in log H from Python floats (a few Newton steps): a halving whose midpoint lies
    # farther from it than `near` has the test's answer known (the sag falls with H, and the
    # evaluation's rounding is ~1e-15 of it), so only the halvings near the root evaluate; the
    # same halvings, the same answers, the same result, bit for bit
    root = _log_tension_near(float(lo), float(hi), float(span), float(rise), float(w), float(f))
    near = math.inf if root is None else 1e-11 * max(1.0, abs(root))
    lo, hi = float(lo), float(hi)  # the halvings in Python floats (the same IEEE sums and products)
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        # lo and hi adjacent (or equal): the midpoint rounds to one of them, and from this
        # halving on the state no longer changes (the same test on the same mid), so the
        # remaining halvings of the 100 are skipped with the same result, bit for bit
        settled = mid == lo or mid == hi
        if root is not None and abs(mid - root) > near:
            too_slack = mid < root
        else:
            k = w / np.exp(mid)
            x0 = half - np.arcsinh(k * rise / (2 * np.sinh(k * span / 2))) / k
            xs = x0 + asinh_m / k
            too_slack = m * xs - (np.cosh(k * (xs - x0)) - np.cosh(k * x0)) / k > f
        if too_slack:
            lo = mid
        else:
            hi = mid
        if settled:
            break
    return np.exp(0.5 * (lo + hi))


def _sag_at(t: float, span: float, rise: float, w: float) -> float:
    # _catenary_sag at H = exp(t) in Python floats
    k = w / math.exp(t)
    x0 = span / 2 - math.asinh(k * rise / (2 * math.sinh(k * span / 2))) / k
    xs = x0 + math.asinh(rise / span) / k
    return rise / span * xs - (math.cosh(k * (xs - x0)) - math.cosh(k * x0)) / k


def _log_tension_near(lo: float, hi: float, span: float, rise: float, w: float, f: float) -> float | None:
    """log H where the sag is ``f``, to ~1e-14, by Newton steps in Python floats from the middle
    of [lo, hi]; checked to hold the root within 2e-12 (sag above ``f`` just below, not above
    just above); ``None`` when not (the bisection then evaluates every halving)."""
    try:
        t = 0.5 * (lo + hi)
        for _ in range(40):
            g = _sag_at(t, span, rise, w) - f
            h = 1e-6 * max(1.0, abs(t))
            slope = (_sag_at(t + h, span, rise, w) - _sag_at(t - h, span, rise, w)) / (2 * h)
            step = g / slope
            t -= step
            if not lo < t < hi:
                return None
            if abs(step) <= 1e-14 * max(1.0, abs(t)):
                break
        else:
            return None
        d = 2e-12 * max(1.0, abs(t))
        if _sag_at(t - d, span, rise, w) > f and not _sag_at(t + d, span, rise, w) > f:
            return t
    except (ValueError, OverflowError, ZeroDivisionError):
        pass
    return None
