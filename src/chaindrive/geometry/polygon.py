"""Pitch polygons: regular (roller and track chains) and bi-regular (round link chains).

The hinge centres of a chain seated on a wheel are the vertices of a polygon inscribed
in the pitch circle. A roller chain (pitch ``p``, ``z`` teeth) gives a regular
``z``-gon. A round link chain (inner link length ``t``, bar diameter ``d``) on a pocket
wheel with ``z`` pockets gives a *bi-regular* ``2z``-gon whose sides alternate
``t + d`` (horizontal link, centre line of the bar to centre line) and ``t - d``
(vertical link) (Dolipiński et al., eq. 6). Both are the same function of the two side lengths: the roller
chain is the case ``d -> 0`` with ``z/2`` pairs of equal sides.
"""

from __future__ import annotations

import functools

import numpy as np
from numpy.typing import ArrayLike

from .._docs import Fragments
from .._typing import FloatOrArray
from .._validation import check_nonnegative, check_positive, check_teeth
from ..errors import InputError

__all__ = [
    "bi_regular_polygon",
    "link_chain_pitch_radius",
    "link_chain_central_angles",
    "roller_chain_pitch_radius",
]


def bi_regular_polygon(
    long_side: ArrayLike, short_side: ArrayLike, pairs: ArrayLike
) -> tuple[FloatOrArray, FloatOrArray, FloatOrArray]:
    r"""Circumradius and central angles of a polygon of ``pairs`` alternating side pairs.

    .. math::
        R = \tfrac12\sqrt{\left(\frac{t}{\sin\frac{\pi}{2n}}\right)^2
              + \left(\frac{d}{\cos\frac{\pi}{2n}}\right)^2},\quad
        t = \tfrac{a+b}{2},\ d = \tfrac{a-b}{2},\quad
        \delta_1 = 2\arcsin\frac{a}{2R},\ \delta_2 = 2\arcsin\frac{b}{2R}

    Parameters
    ----------
    long_side : float or array_like
        Length ``a`` of the longer side [m].
    short_side : float or array_like
        Length ``b <= a`` of the shorter side [m].
    pairs : float or array_like
        Number ``n`` of (long, short) side pairs; real values are allowed so that a
        regular polygon with an odd number ``z`` of sides is ``a = b``, ``n = z/2`` [-].

    Returns
    -------
    radius : ndarray
        Circumradius ``R`` [m].
    delta_long, delta_short : ndarray
        Central angles ``δ1``, ``δ2`` subtended by the long and the short side [rad];
        ``δ1 + δ2 = 2π/n``.

    Notes
    -----
    Derivation: with ``θ = π/(2n)``, ``δ1/2 = θ + ε``, ``δ2/2 = θ - ε``, the chords give
    ``t = 2R sin θ cos ε`` and ``d = 2R cos θ sin ε``; eliminating ``ε`` gives Dolipiński et al.
    eq. (6). Valid for ``0 < b <= a`` and ``n > 1``.

    References
    ----------
    .. [1] Dolipiński M., Reich K., Adamowicz H., Ziegler H., "Wymuszone nabieganie
       łańcucha ogniwowego na koło gniazdowe", Dolipiński et al., eqs (6)-(9).

    Examples
    --------
    >>> R, d1, d2 = bi_regular_polygon(0.064 + 0.018, 0.064 - 0.018, 8)
    >>> round(float(R), 6), round(float(d1 + d2), 6), round(2 * np.pi / 8, 6)
    (0.164283, 0.785398, 0.785398)
    """
    key = (_plain(long_side), _plain(short_side), _plain(pairs))
    if None not in key:
        # one polygon asked for again (the layout, the entry and the wheel speeds of one drive;
        # a number or a 0-d array of it: the checks below make the same 0-d float arrays of both)
        return _bi_regular_kept(*key)
    return _bi_regular(long_side, short_side, pairs)


#: Plain number types whose value is the whole key of a kept polygon.
_PLAIN = frozenset({float, int, np.float64, np.int64})


def _plain(value: object) -> float | int | None:
    """``value`` as a plain number when it is one, or a 0-d numeric array of one; else None."""
    if type(value) in _PLAIN:
        return value  # type: ignore[return-value]
    if type(value) is np.ndarray and value.ndim == 0 and value.dtype.kind in "fi":
        return value.item()
    return None


@functools.lru_cache(maxsize=256)
def _bi_regular_kept(long_side: float, short_side: float,
                     pairs: float) -> tuple[FloatOrArray, FloatOrArray, FloatOrArray]:
    # the results are numpy scalars (immutable); an InputError is raised, not kept
    return _bi_regular(long_side, short_side, pairs)


def _bi_regular(long_side: ArrayLike, short_side: ArrayLike,
                pairs: ArrayLike) -> tuple[FloatOrArray, FloatOrArray, FloatOrArray]:
    """:func:`bi_regular_polygon`, computed."""
    a = check_positive("long_side", long_side, "m")
    b = check_positive("short_side", short_side, "m")
    n = check_positive("pairs", pairs)
    if np.any(b > a):
        raise InputError("short_side must not exceed long_side")
    if np.any(n <= 1):
        raise InputError(f"pairs must be > 1 (a polygon needs more than 2 sides), got {n}")
    t = 0.5 * (a + b)
    d = 0.5 * (a - b)
    theta = np.pi / (2.0 * n)
    radius = 0.5 * np.hypot(t / np.sin(theta), d / np.cos(theta))
    delta_long = 2.0 * np.arcsin(np.clip(a / (2.0 * radius), -1.0, 1.0))
    delta_short = 2.0 * np.arcsin(np.clip(b / (2.0 * radius), -1.0, 1.0))
    return radius, delta_long, delta_short


#: The round link chain on its wheel, described once (:mod:`chaindrive._docs`).
_DOCS = Fragments(link_chain="""
    pitch : float or array_like
        Inner link length ``t`` of the chain [m].
    bar_diameter : float or array_like
        Bar (wire) diameter ``d`` of the links [m]; ``0 <= d < t``.
    teeth : int or array_like
        Number of pockets ``z`` (horizontal links seated per turn), ``z >= 3`` [-].
""")
_DOCS.section("link_chain_parameters", "link_chain")


def _link_chain(pitch, bar_diameter, teeth):
    """The checked ``t``, ``d``, ``z`` of a round link chain on a pocket wheel."""
    t = check_positive("pitch", pitch, "m")
    d = check_nonnegative("bar_diameter", bar_diameter, "m")
    z = check_teeth("teeth", teeth)
    if np.any(d >= t):
        raise InputError("bar_diameter must be smaller than pitch (0 <= d < t)")
    return t, d, z


@_DOCS
def link_chain_pitch_radius(pitch: ArrayLike, bar_diameter: ArrayLike, teeth: ArrayLike) -> FloatOrArray:
    r"""Pitch radius of a pocket wheel for a round link chain, Dolipiński et al. eq. (6).

    .. math:: R = \tfrac12\sqrt{\left(\frac{t}{\sin\frac{\pi}{2z}}\right)^2 +
              \left(\frac{d}{\cos\frac{\pi}{2z}}\right)^2}

    %(link_chain_parameters)s

    Returns
    -------
    ndarray
        Pitch radius ``R`` [m].

    References
    ----------
    Dolipiński et al., eq. (6); see :func:`bi_regular_polygon`.

    Examples
    --------
    Chain 18x64 on an 8-pocket wheel (Dolipiński et al.'s worked case):

    >>> round(float(link_chain_pitch_radius(0.064, 0.018, 8)), 6)
    0.164283
    """
    t, d, z = _link_chain(pitch, bar_diameter, teeth)
    return bi_regular_polygon(t + d, t - d, z)[0]


@_DOCS
def link_chain_central_angles(
    pitch: ArrayLike, bar_diameter: ArrayLike, teeth: ArrayLike
) -> tuple[FloatOrArray, FloatOrArray]:
    r"""Central angles ``δ1`` (link ``t + d``) and ``δ2`` (link ``t - d``), Dolipiński et al. eqs (7)-(9).

    .. math:: \delta_1 = 2\arcsin\frac{t+d}{2R},\quad
              \delta_2 = 2\arcsin\frac{t-d}{2R},\quad \delta_1+\delta_2 = \frac{2\pi}{z}

    %(link_chain_parameters)s

    Returns
    -------
    delta1, delta2 : ndarray
        Central angles [rad].

    Examples
    --------
    >>> d1, d2 = link_chain_central_angles(0.064, 0.018, 8)
    >>> round(float(d1), 6), round(float(d2), 6)
    (0.504471, 0.280927)
    """
    t, d, z = _link_chain(pitch, bar_diameter, teeth)
    _, d1, d2 = bi_regular_polygon(t + d, t - d, z)
    return d1, d2


def roller_chain_pitch_radius(pitch: ArrayLike, teeth: ArrayLike) -> FloatOrArray:
    r"""Pitch radius of a roller-chain sprocket, ``R = p / (2 sin(π/z))``.

    .. math:: R = \frac{p}{2\sin(\pi/z)}

    The ``d -> 0`` case of :func:`bi_regular_polygon` with ``z/2`` pairs; ISO 606:2015,
    clause 8.2 gives the pitch diameter ``d = p / sin(180°/z)``.

    Parameters
    ----------
    pitch : float or array_like
        Chain pitch ``p`` [m].
    teeth : int or array_like
        Number of teeth ``z >= 3`` [-].

    Returns
    -------
    ndarray
        Pitch radius [m].

    Examples
    --------
    >>> round(float(roller_chain_pitch_radius(0.0254, 19)), 6)
    0.077159
    """
    p = check_positive("pitch", pitch, "m")
    z = check_teeth("teeth", teeth)
    return p / (2.0 * np.sin(np.pi / z))
