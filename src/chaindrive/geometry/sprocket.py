"""Roller-chain sprockets: ISO 606:2015 clause 5 dimensions and tooth forms, ANSI B29.1 tooth form.

Layer 1 holds one published formula per function (vectorised, SI units); the tooth
outline builders and the thin :class:`Sprocket` object sit on top of them.

Sources (see docs/geometry.md for the full discussion)
------------------------------------------------------
* ISO 606:2015, *Short-pitch transmission precision roller and bush chains, attachments
  and associated chain sprockets*, clause 5 "Chain sprockets": 5.3 diametral dimensions,
  5.4 tooth gap forms, 5.5 tooth heights and tip diameters, 5.6 rim profiles
  (DIN 8196 and GB/T 1243 carry the same formulas).
* ASME B29.1 tooth form as printed in Machinery's Handbook ("Sprocket tooth form") and
  the American Chain Association, *Chains for Power Transmission and Material Handling*.

Correction of the task's list: ISO 606 pairs the *minimum tooth gap form* with
``ri min = 0.505 d1``, ``α max = 140° − 90°/z`` and ``re max = 0.008 d1 (z² + 180)``;
the *maximum tooth gap form* with ``ri max``, ``α min = 120° − 90°/z`` and
``re min = 0.12 d1 (z + 2)``. (The brief had α and re min/max swapped: 140° − 90°/z
cannot be the minimum of a range whose other end is 120° − 90°/z.)
"""

from __future__ import annotations

import os
import warnings
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike

from .._finite import finite_guard
from .._registry import Registry
from .._results import Result, quantity
from .._typing import FloatOrArray
from .._validation import as_float_array, check_positive
from ..errors import InfeasibleError, InputError, ValidityRangeWarning
from ..limits import MAX_TEETH
from .outline import Arc, Line, Outline, _drop_short, _repeat

if TYPE_CHECKING:
    from ezdxf.document import Drawing

    from ..chains import Chain

__all__ = [
    "MIN_TEETH",
    "MAX_TEETH_TABULATED",
    "pitch_diameter",
    "root_diameter",
    "tip_diameter_limits",
    "seating_radius_limits",
    "seating_angle_limits",
    "flank_radius_limits",
    "tooth_height_limits",
    "tooth_width",
    "tooth_side_radius",
    "tooth_side_relief_limits",
    "measurement_over_pins",
    "max_hub_diameter",
    "ansi_tooth_form",
    "AnsiToothForm",
    "iso_tooth_form",
    "IsoToothForm",
    "SprocketDimensions",
    "Sprocket",
    "sprocket_outline",
    "TOOTH_FORMS",
]

#: Smallest tooth count accepted (ISO 606:2015 Annex A tabulates pitch circle
#: diameters for z = 9 ... 150; the ANSI formulas are used over the same range).
MIN_TEETH = 9
#: Largest tooth count of ISO 606:2015 Annex A; above it a ValidityRangeWarning.
MAX_TEETH_TABULATED = 150

_INCH = 0.0254
_MM = 1e-3


def _teeth(teeth) -> np.ndarray:
    z = as_float_array("teeth", teeth)
    if np.any(z != np.round(z)) or np.any(z < MIN_TEETH):
        got = f"{float(z):g}" if z.ndim == 0 else str(z.tolist())
        raise InputError(
            f"teeth must be a whole number >= {MIN_TEETH} (ISO 606:2015 Annex A covers "
            f"z = {MIN_TEETH}...{MAX_TEETH_TABULATED}), got {got}"
        )
    if np.any(z > MAX_TEETH):  # size-like: a bound before anything is drawn (chaindrive.limits)
        got = f"{float(np.max(z)):.6g}"
        raise InputError(f"teeth must be at most {MAX_TEETH} (chaindrive.limits.MAX_TEETH; ISO 606:2015 "
                         f"Annex A tabulates z = {MIN_TEETH}...{MAX_TEETH_TABULATED}), got {got}",
                         field="teeth")
    if np.any(z > MAX_TEETH_TABULATED):
        warnings.warn(
            f"teeth above {MAX_TEETH_TABULATED}: outside ISO 606:2015 Annex A "
            f"(z = {MIN_TEETH}...{MAX_TEETH_TABULATED}); formulas extrapolated",
            ValidityRangeWarning,
            stacklevel=3,
        )
    return z


def _roller(pitch, roller_diameter):
    p = check_positive("pitch", pitch, "m")
    d1 = check_positive("roller_diameter", roller_diameter, "m")
    if np.any(d1 >= p):
        raise InputError("roller_diameter must be smaller than pitch (0 < d1 < p)")
    return p, d1


@finite_guard
def pitch_diameter(pitch: ArrayLike, teeth: ArrayLike) -> FloatOrArray:
    r"""Pitch circle diameter of a sprocket, ISO 606:2015 clause 5.3.

    .. math:: d = \frac{p}{\sin(180°/z)}

    Parameters
    ----------
    pitch : float or array_like
        Chain pitch ``p`` [m].
    teeth : int or array_like
        Number of teeth ``z`` (9...150) [-].

    Returns
    -------
    ndarray
        Pitch diameter ``d`` [m].

    Notes
    -----
    The rollers' centres of a chain seated without clearance lie on a regular ``z``-gon of
    side ``p``; ``d`` is its circumscribed circle. Valid for ``z >= 9`` (ISO 606 Annex A).

    References
    ----------
    ISO 606:2015, clause 5.3.2 and Annex A.

    Examples
    --------
    16B (p = 25.4 mm), 19 teeth; ISO 606 Annex A gives d/p = 6.0755:

    >>> round(float(pitch_diameter(0.0254, 19)) / 0.0254, 4)
    6.0755
    """
    p = check_positive("pitch", pitch, "m")
    z = _teeth(teeth)
    return p / np.sin(np.pi / z)


@finite_guard
def root_diameter(pitch: ArrayLike, teeth: ArrayLike, roller_diameter: ArrayLike) -> FloatOrArray:
    r"""Root diameter ``df = d − d1``, ISO 606:2015 clause 5.3.

    .. math:: d_f = d - d_1

    Parameters
    ----------
    pitch : float or array_like
        Chain pitch ``p`` [m].
    teeth : int or array_like
        Number of teeth ``z`` [-].
    roller_diameter : float or array_like
        Maximum roller diameter ``d1`` of the chain [m].

    Returns
    -------
    ndarray
        Root diameter [m].

    Notes
    -----
    ``df`` is the nominal (toleranced h11) root diameter. The bottom of the drawn seating
    arc of radius ``ri >= 0.505 d1`` lies slightly deeper, at ``d − 2 ri``.

    References
    ----------
    ISO 606:2015, clause 5.3.2; worked example in DIN 8196 use: z = 34, p = 12.7 mm,
    d1 = 7.75 mm gives d = 137.64 mm, df = 129.89 mm.

    Examples
    --------
    >>> round(float(root_diameter(0.0127, 34, 0.00775)) * 1e3, 2)
    129.89
    """
    p, d1 = _roller(pitch, roller_diameter)
    return pitch_diameter(p, teeth) - d1


@finite_guard
def tip_diameter_limits(
    pitch: ArrayLike, teeth: ArrayLike, roller_diameter: ArrayLike
) -> tuple[FloatOrArray, FloatOrArray]:
    r"""Smallest and largest tip diameter, ISO 606:2015 clause 5.5.

    .. math:: d_{a,\max} = d + 1.25\,p - d_1,\qquad
              d_{a,\min} = d + p\left(1 - \frac{1.6}{z}\right) - d_1

    Parameters
    ----------
    pitch, teeth, roller_diameter : float or array_like
        ``p`` [m], ``z`` [-], ``d1`` [m].

    Returns
    -------
    da_min, da_max : ndarray
        Tip diameter limits [m].

    Notes
    -----
    ISO 606 allows any tip between the two, with the proviso that ``da max`` may be
    reduced when the tooth becomes pointed (the outline builder does that).

    References
    ----------
    ISO 606:2015, clause 5.5.2.

    Examples
    --------
    >>> lo, hi = tip_diameter_limits(0.0254, 19, 0.01588)
    >>> round(float(lo) * 1e3, 2), round(float(hi) * 1e3, 2)
    (161.7, 170.19)
    """
    p, d1 = _roller(pitch, roller_diameter)
    return _tip_diameter_range(p, _teeth(teeth), d1)


def _tip_diameter_range(p, z, d1):
    """ISO 606:2015 clause 5.5.2 formulas, any ``z`` (internal; see tip_diameter_limits)."""
    d = p / np.sin(np.pi / z)
    return d + p * (1.0 - 1.6 / z) - d1, d + 1.25 * p - d1


@finite_guard
def seating_radius_limits(roller_diameter: ArrayLike) -> tuple[FloatOrArray, FloatOrArray]:
    r"""Roller seating radius limits, ISO 606:2015 clause 5.4.

    .. math:: r_{i,\min} = 0.505\,d_1,\qquad
              r_{i,\max} = 0.505\,d_1 + 0.069\,\sqrt[3]{d_1}\quad(d_1\ \text{in mm})

    Parameters
    ----------
    roller_diameter : float or array_like
        Roller diameter ``d1`` [m].

    Returns
    -------
    ri_min, ri_max : ndarray
        [m]. ``ri min`` belongs to the minimum tooth gap form, ``ri max`` to the maximum.

    Notes
    -----
    The cube-root term is dimensionally inconsistent: it is written for ``d1`` in
    millimetres with the result in millimetres; here it is evaluated that way and
    converted back to metres.

    References
    ----------
    ISO 606:2015, clause 5.4.2.

    Examples
    --------
    >>> lo, hi = seating_radius_limits(0.01588)
    >>> round(float(lo) * 1e3, 4), round(float(hi) * 1e3, 4)
    (8.0194, 8.1928)
    """
    d1 = check_positive("roller_diameter", roller_diameter, "m")
    lo = 0.505 * d1
    return lo, lo + 0.069 * np.cbrt(d1 / _MM) * _MM


@finite_guard
def seating_angle_limits(teeth: ArrayLike) -> tuple[FloatOrArray, FloatOrArray]:
    r"""Roller seating angle limits, ISO 606:2015 clause 5.4.

    .. math:: \alpha_{\min} = 120° - \frac{90°}{z},\qquad \alpha_{\max} = 140° - \frac{90°}{z}

    Parameters
    ----------
    teeth : int or array_like
        Number of teeth ``z`` [-].

    Returns
    -------
    alpha_min, alpha_max : ndarray
        Included seating angle [rad]; ``α max`` belongs to the minimum tooth gap form.

    References
    ----------
    ISO 606:2015, clause 5.4.2 (the task brief had min and max swapped).

    Examples
    --------
    >>> lo, hi = seating_angle_limits(19)
    >>> round(float(np.degrees(lo)), 4), round(float(np.degrees(hi)), 4)
    (115.2632, 135.2632)
    """
    return _seating_angle_range(_teeth(teeth))


def _seating_angle_range(z):
    """ISO 606:2015 clause 5.4.2 formulas, any ``z`` (internal; see seating_angle_limits)."""
    return np.radians(120.0 - 90.0 / z), np.radians(140.0 - 90.0 / z)


@finite_guard
def flank_radius_limits(roller_diameter: ArrayLike, teeth: ArrayLike) -> tuple[FloatOrArray, FloatOrArray]:
    r"""Tooth flank radius limits, ISO 606:2015 clause 5.4.

    .. math:: r_{e,\min} = 0.12\,d_1 (z + 2),\qquad r_{e,\max} = 0.008\,d_1 (z^2 + 180)

    Parameters
    ----------
    roller_diameter : float or array_like
        Roller diameter ``d1`` [m].
    teeth : int or array_like
        Number of teeth ``z`` [-].

    Returns
    -------
    re_min, re_max : ndarray
        [m]; ``re max`` belongs to the minimum tooth gap form.

    Notes
    -----
    ``re max > re min`` for every ``z``:
    ``0.008 (z² + 180) − 0.12 (z + 2) = 0.008 (z − 7.5)² + 0.75 > 0``.

    References
    ----------
    ISO 606:2015, clause 5.4.2 (the task brief had min and max swapped).

    Examples
    --------
    >>> lo, hi = flank_radius_limits(0.01588, 19)
    >>> round(float(lo) * 1e3, 3), round(float(hi) * 1e3, 3)
    (40.018, 68.729)
    """
    d1 = check_positive("roller_diameter", roller_diameter, "m")
    return _flank_radius_range(d1, _teeth(teeth))


def _flank_radius_range(d1, z):
    """ISO 606:2015 clause 5.4.2 formulas, any ``z`` (internal; see flank_radius_limits)."""
    return 0.12 * d1 * (z + 2.0), 0.008 * d1 * (z * z + 180.0)


@finite_guard
def tooth_height_limits(
    pitch: ArrayLike, teeth: ArrayLike, roller_diameter: ArrayLike
) -> tuple[FloatOrArray, FloatOrArray]:
    r"""Tooth height above the pitch polygon, ISO 606:2015 clause 5.5.

    .. math:: h_{a,\min} = 0.5\,(p - d_1),\qquad h_{a,\max} = 0.625\,p - 0.5\,d_1 + \frac{0.8\,p}{z}

    Parameters
    ----------
    pitch, teeth, roller_diameter : float or array_like
        ``p`` [m], ``z`` [-], ``d1`` [m].

    Returns
    -------
    ha_min, ha_max : ndarray
        [m].

    References
    ----------
    ISO 606:2015, clause 5.5.2 (used for drawing the tooth to a turning diameter).

    Examples
    --------
    >>> lo, hi = tooth_height_limits(0.0254, 19, 0.01588)
    >>> round(float(lo) * 1e3, 3), round(float(hi) * 1e3, 3)
    (4.76, 9.004)
    """
    p, d1 = _roller(pitch, roller_diameter)
    z = _teeth(teeth)
    return 0.5 * (p - d1), 0.625 * p - 0.5 * d1 + 0.8 * p / z


@finite_guard
def tooth_width(pitch: ArrayLike, inner_width: ArrayLike, strands: int = 1) -> FloatOrArray:
    r"""Tooth width ``bf1``, ISO 606:2015 clause 5.6.

    .. math:: b_{f1} = k\,b_1,\quad k = \begin{cases}0.93 & p \le 12.7\ \text{mm}\\
              0.95 & p > 12.7\ \text{mm}\end{cases}\ \text{(simplex)}

    Parameters
    ----------
    pitch : float or array_like
        Chain pitch [m].
    inner_width : float or array_like
        Minimum width between inner plates ``b1`` [m].
    strands : int
        1 (simplex), 2 or 3 (k = 0.91 / 0.93), 4 and more (k = 0.88 / 0.93).

    Returns
    -------
    ndarray
        Tooth width [m], tolerance h14.

    Notes
    -----
    Factors as in the ISO 606 / DIN 8196 table (simplex 0.93/0.95, duplex and triplex
    0.91/0.93, quadruple 0.88/0.93; summarised on tandwiel.info "Roller chain wheels");
    the simplex 0.95 b1 also appears in a textbook worked example (docs/geometry.md).

    References
    ----------
    ISO 606:2015, clause 5.6.2.

    Examples
    --------
    >>> round(float(tooth_width(0.0254, 0.01702)) * 1e3, 3)
    16.169
    """
    p = check_positive("pitch", pitch, "m")
    b1 = check_positive("inner_width", inner_width, "m")
    if int(strands) != strands or strands < 1:
        raise InputError(f"strands must be a whole number >= 1, got {strands!r}")
    small = p <= 12.7 * _MM + 1e-12
    if strands == 1:
        k = np.where(small, 0.93, 0.95)
    elif strands <= 3:
        k = np.where(small, 0.91, 0.93)
    else:
        k = np.where(small, 0.88, 0.93)
    return k * b1


@finite_guard
def tooth_side_radius(pitch: ArrayLike) -> FloatOrArray:
    r"""Nominal tooth side radius ``rx = p``, ISO 606:2015 clause 5.6.

    .. math:: r_x = p

    Parameters
    ----------
    pitch : float or array_like
        Chain pitch [m].

    Returns
    -------
    ndarray
        [m].

    Examples
    --------
    >>> float(tooth_side_radius(0.0254))
    0.0254
    """
    return check_positive("pitch", pitch, "m") * 1.0


@finite_guard
def tooth_side_relief_limits(pitch: ArrayLike) -> tuple[FloatOrArray, FloatOrArray]:
    r"""Nominal tooth side relief ``ba`` from 0.1 p to 0.15 p, ISO 606:2015 clause 5.6.

    .. math:: b_a = (0.10 \dots 0.15)\,p

    Parameters
    ----------
    pitch : float or array_like
        Chain pitch [m].

    Returns
    -------
    ba_min, ba_max : ndarray
        [m].

    Examples
    --------
    >>> [round(float(v) * 1e3, 3) for v in tooth_side_relief_limits(0.0254)]
    [2.54, 3.81]
    """
    p = check_positive("pitch", pitch, "m")
    return 0.10 * p, 0.15 * p


@finite_guard
def measurement_over_pins(pitch: ArrayLike, teeth: ArrayLike, roller_diameter: ArrayLike) -> FloatOrArray:
    r"""Measurement over measuring pins of diameter ``dR = d1``, ISO 606:2015 clause 5.3.

    .. math:: M_R = d + d_R\ (z\ \text{even}),\qquad M_R = d\cos\frac{90°}{z} + d_R\ (z\ \text{odd})

    Parameters
    ----------
    pitch, teeth, roller_diameter : float or array_like
        ``p`` [m], ``z`` [-], ``d1`` [m] (the pin diameter is taken equal to ``d1``).

    Returns
    -------
    ndarray
        ``MR`` [m].

    Notes
    -----
    Odd ``z``: the pins sit in the gaps nearest to opposite, whose centres are
    ``180° − 180°/z`` apart, so their distance is ``d cos(90°/z)``. This is checked in the
    tests against the distance of the roller seat centres of the drawn outline.

    References
    ----------
    ISO 606:2015, clause 5.3.2; ASME B29.1 caliper diameter (= MR − 2 d1).

    Examples
    --------
    >>> round(float(measurement_over_pins(0.0254, 19, 0.01588)) * 1e3, 3)
    169.671
    """
    p, d1 = _roller(pitch, roller_diameter)
    z = _teeth(teeth)
    d = p / np.sin(np.pi / z)
    odd = (z.astype(int) % 2) == 1
    return np.where(odd, d * np.cos(np.pi / (2.0 * z)), d) + d1


@finite_guard
def max_hub_diameter(pitch: ArrayLike, teeth: ArrayLike, plate_height: ArrayLike) -> FloatOrArray:
    r"""Largest hub (shroud) diameter that clears the chain plates, ISO 606:2015 clause 5.6.

    .. math:: d_g = p\cot\frac{180°}{z} - 1.04\,h_2 - 0.76\ \text{mm}

    Parameters
    ----------
    pitch : float or array_like
        Chain pitch [m].
    teeth : int or array_like
        Number of teeth [-].
    plate_height : float or array_like
        Maximum inner plate depth ``h2`` [m].

    Returns
    -------
    ndarray
        ``dg`` [m].

    Notes
    -----
    ``p cot(180°/z)`` is twice the distance of a pitch chord from the centre; the plate
    reaches ``0.52 h2`` below it and 0.38 mm is kept as radial clearance.

    References
    ----------
    ISO 606:2015, clause 5.6.2, as given in the task brief: NOT verified against the text
    of the standard (not available). DIN 8196-1:1987 gives the absolute maximum shroud
    diameter as ``d5 = p cot(180°/z) − 1.05 h2 − 2 r4 − 1 mm`` (r4 shroud fillet radius),
    which is a few mm smaller. Compare ASME B29.1's maximum hub diameter
    ``p (cot(180°/z) − 1) − 0.030 in``.

    Examples
    --------
    >>> round(float(max_hub_diameter(0.0254, 19, 0.02108)) * 1e3, 3)
    129.531
    """
    p = check_positive("pitch", pitch, "m")
    h2 = check_positive("plate_height", plate_height, "m")
    z = _teeth(teeth)
    dg = p / np.tan(np.pi / z) - 1.04 * h2 - 0.76 * _MM
    if np.any(dg <= 0):
        raise InfeasibleError("max_hub_diameter: p cot(180°/z) − 1.04 h2 − 0.76 mm <= 0; no hub fits")
    return dg


# --------------------------------------------------------------------------- ANSI form
@dataclass(frozen=True)
class AnsiToothForm(Result):
    """ASME B29.1 tooth form constants (Machinery's Handbook "Sprocket tooth form"), SI."""

    seating_curve_diameter: Any = quantity("m")
    seating_radius: Any = quantity("m")
    angle_a: Any = quantity("rad")
    angle_b: Any = quantity("rad")
    ac: Any = quantity("m")
    m: Any = quantity("m")
    t: Any = quantity("m")
    working_radius: Any = quantity("m")
    chord_xy: Any = quantity("m")
    line_yz: Any = quantity("m")
    ab: Any = quantity("m")
    w: Any = quantity("m")
    v: Any = quantity("m")
    topping_radius: Any = quantity("m")
    h: Any = quantity("m")
    s: Any = quantity("m")
    outside_diameter_turned: Any = quantity("m")
    outside_diameter_pointed: Any = quantity("m")


@finite_guard
def ansi_tooth_form(pitch: ArrayLike, teeth: ArrayLike, roller_diameter: ArrayLike) -> AnsiToothForm:
    r"""ASME B29.1 sprocket tooth form (seating, working and topping curves).

    .. math::
        D_s = 1.005\,D_r + 0.003\ \text{in},\ R = D_s/2,\ A = 35° + 60°/N,\ B = 18° - 56°/N,\
        ac = 0.8 D_r,\ E = 1.3025 D_r + 0.0015\ \text{in},\
        F = D_r[0.8\cos B + 1.4\cos(17° - 64°/N) - 1.3025] - 0.0015\ \text{in}

    and ``M = ac cos A``, ``T = ac sin A``, ``xy = (2.605 Dr + 0.003 in) sin(9° − 28°/N)``,
    ``yz = Dr [1.4 sin(17° − 64°/N) − 0.8 sin B]``, ``ab = 1.4 Dr``,
    ``W = 1.4 Dr cos(180°/N)``, ``V = 1.4 Dr sin(180°/N)``,
    ``H = sqrt(F² − (1.4 Dr − P/2)²)``, ``S = P/2 cos(180°/N) + H sin(180°/N)``,
    ``OD (turned, J = 0.3 P) = P (0.6 + cot(180°/N))``,
    ``OD (pointed) = P cot(180°/N) + cos(180°/N)(Ds − Dr) + 2H``.

    Parameters
    ----------
    pitch, teeth, roller_diameter : float or array_like
        ``P`` [m], ``N`` [-], ``Dr`` [m]. The inch constants are converted to metres.

    Returns
    -------
    AnsiToothForm
        All lengths [m], angles A and B [rad].

    Notes
    -----
    The straight line ``yz`` is derived in :func:`sprocket_outline` as the common
    tangent of the working circle ``E`` (centre ``c``) and the topping circle ``F``
    (centre ``b``); its length reproduces the printed ``yz`` to 1e-15 (tests).

    References
    ----------
    ASME B29.1; Machinery's Handbook, "Sprocket tooth form" (formulas above); worked
    numbers for P = 1 in, N = 28, Dr = 0.625 in in the GEARS-IDS "Equations for the
    design of standard sprocket teeth" sheet.

    Examples
    --------
    >>> f = ansi_tooth_form(0.0254, 28, 0.625 * 0.0254)
    >>> round(float(f.topping_radius) / 0.0254, 4), round(float(f.h) / 0.0254, 4)
    (0.5114, 0.3477)
    """
    p, dr = _roller(pitch, roller_diameter)
    n = _teeth(teeth)
    deg = np.pi / 180.0
    ds = 1.005 * dr + 0.003 * _INCH
    a = (35.0 + 60.0 / n) * deg
    b = (18.0 - 56.0 / n) * deg
    ac = 0.8 * dr
    e = 1.3025 * dr + 0.0015 * _INCH
    f = dr * (0.8 * np.cos(b) + 1.4 * np.cos((17.0 - 64.0 / n) * deg) - 1.3025) - 0.0015 * _INCH
    arg = f**2 - (1.4 * dr - p / 2.0) ** 2
    if np.any(arg < 0):
        raise InfeasibleError("ANSI tooth form: topping radius F < |1.4 Dr − P/2|; roller too small for pitch")
    h = np.sqrt(arg)
    half = np.pi / n
    return AnsiToothForm(
        seating_curve_diameter=ds,
        seating_radius=ds / 2.0,
        angle_a=a,
        angle_b=b,
        ac=ac,
        m=ac * np.cos(a),
        t=ac * np.sin(a),
        working_radius=e,
        chord_xy=(2.605 * dr + 0.003 * _INCH) * np.sin((9.0 - 28.0 / n) * deg),
        line_yz=dr * (1.4 * np.sin((17.0 - 64.0 / n) * deg) - 0.8 * np.sin(b)),
        ab=1.4 * dr,
        w=1.4 * dr * np.cos(half),
        v=1.4 * dr * np.sin(half),
        topping_radius=f,
        h=h,
        s=p / 2.0 * np.cos(half) + h * np.sin(half),
        outside_diameter_turned=p * (0.6 + 1.0 / np.tan(half)),
        outside_diameter_pointed=p / np.tan(half) + np.cos(half) * (ds - dr) + 2.0 * h,
    )


# --------------------------------------------------------------------------- outlines
def _circle_circle(c1, r1, c2, r2):
    """Both intersections of two circles (internal); None if they do not meet."""
    c1 = np.asarray(c1, float)
    c2 = np.asarray(c2, float)
    d = np.hypot(*(c2 - c1))
    if d > r1 + r2 or d < abs(r1 - r2) or d == 0:
        return None
    a = (r1**2 - r2**2 + d**2) / (2 * d)
    h = np.sqrt(max(r1**2 - a**2, 0.0))
    u = (c2 - c1) / d
    m = c1 + a * u
    nrm = np.array([-u[1], u[0]])
    return m + h * nrm, m - h * nrm


def _convex_flank_to_tip(centre, radius, start_angle, tip_radius, half_angle):
    """Walk a convex flank circle clockwise from ``start_angle`` until the tip circle or the
    tooth centreline (polar angle π/2 − half_angle), whichever comes first (internal).

    Returns (flank_tip_angle_about_centre, tip_point, pointed).
    """
    centre = np.asarray(centre, float)
    cands = []
    hit = _circle_circle(centre, radius, (0.0, 0.0), tip_radius)
    if hit is not None:
        for q in hit:
            ang = np.arctan2(q[1] - centre[1], q[0] - centre[0])
            dphi = (start_angle - ang) % (2 * np.pi)
            cands.append((dphi, q, False))
    # tooth centreline: points s*(sin h, cos h), s > 0
    u = np.array([np.sin(half_angle), np.cos(half_angle)])
    bq = -2.0 * u @ centre
    cq = centre @ centre - radius**2
    disc = bq * bq - 4 * cq
    if disc >= 0:
        for s in ((-bq - np.sqrt(disc)) / 2, (-bq + np.sqrt(disc)) / 2):
            if s > 0:
                q = s * u
                ang = np.arctan2(q[1] - centre[1], q[0] - centre[0])
                dphi = (start_angle - ang) % (2 * np.pi)
                cands.append((dphi, q, True))
    cands = [c for c in cands if 1e-12 < c[0] < np.pi]
    if not cands:
        raise InfeasibleError("tooth flank reaches neither the tip circle nor the tooth centreline")
    dphi, q, pointed = min(cands, key=lambda c: c[0])
    return start_angle - dphi, q, pointed


def _tip_half(tip_point, half_angle, pointed):
    """Half tip arc from the tooth centreline to the flank's tip point (internal)."""
    r = float(np.hypot(*tip_point))
    th = float(np.arctan2(tip_point[1], tip_point[0]))
    start = np.pi / 2 - half_angle
    if pointed:
        return []
    return [Arc((0.0, 0.0), r, start, th - start)]


def _iso_half_gap(pitch_radius, teeth, seat_radius, seat_angle, flank_radius, tip_radius):
    """Right half of one ISO tooth gap centred on +y, from tooth centreline to gap bottom."""
    half = np.pi / teeth
    p0 = np.array([0.0, pitch_radius])
    dirn = np.array([np.sin(seat_angle / 2), -np.cos(seat_angle / 2)])
    centre = p0 + (seat_radius + flank_radius) * dirn
    phi_e = np.arctan2(-dirn[1], -dirn[0])
    e_point = p0 + seat_radius * dirn
    if tip_radius <= np.hypot(*e_point):
        raise InfeasibleError("tip circle lies below the end of the roller seat; tip diameter too small")
    phi_t, tip, pointed = _convex_flank_to_tip(centre, flank_radius, phi_e, tip_radius, half)
    prims = _tip_half(tip, half, pointed)
    prims.append(Arc(tuple(centre), flank_radius, phi_t, phi_e - phi_t))
    prims.append(Arc(tuple(p0), seat_radius, -np.pi / 2 + seat_angle / 2, -seat_angle / 2))
    return prims, pointed


def _ansi_half_gap(pitch, teeth, roller_diameter, tip_radius):
    """Right half of one ANSI tooth gap centred on +y (internal)."""
    f = ansi_tooth_form(pitch, teeth, roller_diameter)
    rp = pitch / (2 * np.sin(np.pi / teeth))
    half = np.pi / teeth
    a, b = float(f.angle_a), float(f.angle_b)
    p0 = np.array([0.0, rp])
    big_r, e, ff = float(f.seating_radius), float(f.working_radius), float(f.topping_radius)
    c = p0 + float(f.ac) * np.array([-np.cos(a), np.sin(a)])
    y = c + e * np.array([np.cos(a - b), -np.sin(a - b)])
    tdir = np.array([np.sin(a - b), np.cos(a - b)])
    bc = p0 + 1.4 * roller_diameter * np.array([np.cos(half), -np.sin(half)])
    zpt = y + ((bc - y) @ tdir) * tdir
    phi_z = np.arctan2(zpt[1] - bc[1], zpt[0] - bc[0])
    phi_t, tip, pointed = _convex_flank_to_tip(bc, ff, phi_z, tip_radius, half)
    prims = _tip_half(tip, half, pointed)
    prims.append(Arc(tuple(bc), ff, phi_t, phi_z - phi_t))
    prims.append(Line(tuple(zpt), tuple(y)))
    prims.append(Arc(tuple(c), e, -(a - b), -b))
    prims.append(Arc(tuple(p0), big_r, -a, -(np.pi / 2 - a)))
    return prims, pointed, zpt, y


def _full_from_half(half_prims, teeth):
    right = _drop_short(half_prims)
    left = [p.mirrored_x() for p in reversed(right)]
    return _repeat(right + left, teeth)


def _centres(radius, teeth):
    ang = np.pi / 2 + 2 * np.pi * np.arange(teeth) / teeth
    return np.stack([radius * np.cos(ang), radius * np.sin(ang)], axis=-1)


@dataclass(frozen=True)
class IsoToothForm(Result):
    """One ISO 606 tooth gap (SI units); see :func:`iso_tooth_form`.

    Attributes
    ----------
    teeth : int
    pitch_radius : float
        ``R = p / (2 sin(π/z))`` [m].
    seat_radius, seat_angle, flank_radius, tip_radius : float
        ``r_i`` [m], included seating angle ``α`` [rad], ``r_e`` [m], ``d_a/2`` [m].
    flank_centre, tooth_corner : ndarray (2,)
        Centre of the right flank arc and the tooth corner where it ends (on the tip
        circle, or on the tooth centreline of a pointed tooth), in the gap frame: ``a``
        radial from the seat centre (on the pitch circle, outwards), ``b`` tangential [m].
    pointed : bool
        The flank reaches the tooth centreline before the tip circle.
    """

    teeth: int = quantity("1")
    pitch_radius: float = quantity("m")
    seat_radius: float = quantity("m")
    seat_angle: float = quantity("rad")
    flank_radius: float = quantity("m")
    tip_radius: float = quantity("m")
    flank_centre: np.ndarray = quantity("m")
    tooth_corner: np.ndarray = quantity("m")
    pointed: bool


def iso_tooth_form(pitch: float, teeth: int, roller_diameter: float, *, form: str = "min",
                   seat_radius: float | None = None, seat_angle: float | None = None,
                   tip_diameter: float | None = None) -> IsoToothForm:
    r"""ISO 606 tooth gap: seating arc, convex flank arc and tip, for any ``z >= 3``.

    The one ISO 606 tooth form of the package: :func:`sprocket_outline` draws it and the
    dynamic simulation (:mod:`chaindrive.simulation`) puts its rollers against it. The
    seating arc of radius ``r_i`` is centred on the pitch circle and spans the included
    angle ``α``; the flank arc of radius ``r_e`` continues it tangentially (its centre on
    the seat's end ray, at ``r_i + r_e`` from the seat centre) up to the tip circle or the
    tooth centreline.

    .. math::
        r_{i,\min} = 0.505\,d_1,\quad α_{\max} = 140° - \frac{90°}{z},\quad
        r_{e,\max} = 0.008\,d_1 (z^2 + 180)\quad\text{(minimum gap form)}

    Parameters
    ----------
    pitch : float
        ``p`` [m].
    teeth : int
        ``z >= 3``.
    roller_diameter : float
        ``d1`` [m], ``0 < d1 < p``.
    form : {"min", "max"}
        Minimum tooth gap (``r_i min``, ``α max``, ``r_e max``; default) or maximum
        (``r_i max``, ``α min``, ``r_e min``).
    seat_radius, seat_angle : float, optional
        ``r_i`` [m] and ``α`` [rad] instead of the form's.
    tip_diameter : float, optional
        ``d_a`` [m]; default ``d_a max`` (form "min") or ``d_a min`` (form "max").

    Returns
    -------
    IsoToothForm

    Raises
    ------
    InputError
        ``teeth`` not a whole number >= 3, ``form`` unknown, bad pitch or roller diameter.
    InfeasibleError
        The tip circle lies below the end of the seat.

    Notes
    -----
    The clause 5.4/5.5 formulas hold for any ``z``; ISO 606 Annex A tabulates sprockets
    of ``z = 9 ... 150`` only, so :func:`sprocket_outline` and :class:`Sprocket` refuse
    ``z < 9``. Below that (the simulation's small wheels) the form is the same formulas
    extrapolated.

    References
    ----------
    ISO 606:2015, clause 5.4.2 (``r_i``, ``α``, ``r_e``) and 5.5.2 (``d_a``).

    Examples
    --------
    >>> f = iso_tooth_form(0.0254, 17, 0.01588)
    >>> round(f.flank_radius * 1e3, 3), round(float(np.degrees(f.seat_angle)), 4)
    (59.582, 134.7059)
    >>> iso_tooth_form(0.0254, 6, 0.01588).pointed
    False
    """
    if form not in ("min", "max"):
        raise InputError(f"form must be 'min' (minimum tooth gap) or 'max' (maximum tooth gap), got {form!r}")
    zf = float(as_float_array("teeth", teeth))
    if zf != round(zf) or not 3 <= zf <= MAX_TEETH:
        raise InputError(f"teeth must be a whole number in [3, {MAX_TEETH}], got {zf:g}", field="teeth")
    z = int(zf)
    p, d1 = (float(v) for v in _roller(pitch, roller_diameter))
    ri_lo, ri_hi = (float(v) for v in seating_radius_limits(d1))
    a_lo, a_hi = (float(v) for v in _seating_angle_range(z))
    re_lo, re_hi = (float(v) for v in _flank_radius_range(d1, z))
    da_lo, da_hi = (float(v) for v in _tip_diameter_range(p, z, d1))
    ri, alpha, re = (ri_lo, a_hi, re_hi) if form == "min" else (ri_hi, a_lo, re_lo)
    ri = ri if seat_radius is None else float(check_positive("seat_radius", seat_radius, "m"))
    alpha = alpha if seat_angle is None else float(seat_angle)
    da = (da_hi if form == "min" else da_lo) if tip_diameter is None else float(
        check_positive("tip_diameter", tip_diameter, "m"))
    rp = p / (2 * np.sin(np.pi / z))
    half, pointed = _iso_half_gap(rp, z, ri, alpha, re, da / 2)
    flank = half[-2]
    centre = np.array([flank.center[1] - rp, flank.center[0]])
    corner = centre + re * np.array([np.sin(flank.start_angle), np.cos(flank.start_angle)])
    return IsoToothForm(z, float(rp), ri, alpha, re, da / 2, centre, corner, bool(pointed))


TOOTH_FORMS = Registry("method")


@TOOTH_FORMS.register("iso606")
def _iso_outline(pitch, teeth, roller_diameter, form="min", tip_diameter=None):
    if form not in ("min", "max"):
        raise InputError(f"form must be 'min' (minimum tooth gap) or 'max' (maximum tooth gap), got {form!r}")
    z = int(_teeth(teeth))
    p, d1 = (float(v) for v in _roller(pitch, roller_diameter))
    da_lo, da_hi = (float(v) for v in tip_diameter_limits(p, z, d1))
    if tip_diameter is None:
        tip_diameter = da_hi if form == "min" else da_lo
    else:
        tip_diameter = float(as_float_array("tip_diameter", tip_diameter))
        if not (da_lo - 1e-12 <= tip_diameter <= da_hi + 1e-12):
            raise InputError(
                f"tip_diameter must lie in [{da_lo * 1e3:.3f}, {da_hi * 1e3:.3f}] mm "
                f"(ISO 606:2015 clause 5.5, da min...da max), got {tip_diameter * 1e3:.3f} mm"
            )
    f = iso_tooth_form(p, z, d1, form=form, tip_diameter=tip_diameter)
    rp, ri = f.pitch_radius, f.seat_radius
    half, pointed = _iso_half_gap(rp, z, ri, f.seat_angle, f.flank_radius, tip_diameter / 2)
    outline = Outline(_full_from_half(half, z), rp, _centres(rp, z), {"ROOT": rp - ri})
    outline.circles["TIP"] = float(np.hypot(*half[0].end)) if not pointed else float(np.hypot(*half[0].start))
    return outline


@TOOTH_FORMS.register("ansi")
def _ansi_outline(pitch, teeth, roller_diameter, form=None, tip_diameter=None):
    if form not in (None, "standard"):
        raise InputError(
            f"form {form!r} is not defined for method='ansi': ASME B29.1 gives one tooth form "
            "(use form=None; 'min'/'max' are ISO 606 tooth gap forms)"
        )
    z = int(_teeth(teeth))
    p, dr = (float(v) for v in _roller(pitch, roller_diameter))
    f = ansi_tooth_form(p, z, dr)
    od = float(f.outside_diameter_turned) if tip_diameter is None else float(tip_diameter)
    if tip_diameter is not None:
        check_positive("tip_diameter", tip_diameter, "m")
    rp = p / (2 * np.sin(np.pi / z))
    half, pointed, _, _ = _ansi_half_gap(p, z, dr, od / 2)
    outline = Outline(_full_from_half(half, z), rp, _centres(rp, z), {"ROOT": rp - float(f.seating_radius)})
    outline.circles["TIP"] = float(np.hypot(*half[0].end)) if not pointed else float(np.hypot(*half[0].start))
    return outline

@finite_guard
def sprocket_outline(pitch: float, teeth: int, roller_diameter: float, *, method: str = "iso606",
                     form: str | None = None, tip_diameter: float | None = None) -> Outline:
    """Closed outline of a whole sprocket (lines and arcs) for the chosen tooth form.

    Parameters
    ----------
    pitch : float
        Chain pitch [m].
    teeth : int
        Number of teeth (>= 9).
    roller_diameter : float
        Roller diameter ``d1`` [m].
    method : {"iso606", "ansi"}
        Tooth form standard.
    form : {"min", "max"} or None
        ISO 606 minimum tooth gap form (``ri min``, ``α max``, ``re max``, tip ``da max``)
        or maximum tooth gap form (``ri max``, ``α min``, ``re min``, tip ``da min``);
        ``None`` means "min" for ISO and the single ANSI form.
    tip_diameter : float, optional
        Tip diameter [m]; ISO: validated inside ``[da min, da max]``. Where the flanks
        meet below it the tooth is left pointed.

    Returns
    -------
    Outline
        Gap 0 is centred on the +y axis; ``centres`` are the roller seat centres.

    References
    ----------
    ISO 606:2015 clauses 5.4-5.5; ASME B29.1 (Machinery's Handbook).

    Examples
    --------
    >>> o = sprocket_outline(0.0254, 19, 0.01588)
    >>> o.closure_gap() < 1e-12, len(o.centres)
    (True, 19)
    """
    if np.ndim(teeth) or np.ndim(pitch) or np.ndim(roller_diameter):
        raise InputError("sprocket_outline draws one wheel: pitch, teeth and roller_diameter must be scalars")
    _teeth(teeth)  # bounded (MIN_TEETH...chaindrive.limits.MAX_TEETH) before anything is drawn
    fn = TOOTH_FORMS.get(method)
    if method == "iso606" and form is None:
        form = "min"
    return fn(pitch, teeth, roller_diameter, form=form, tip_diameter=tip_diameter)


# --------------------------------------------------------------------------- objects
@dataclass(frozen=True)
class SprocketDimensions(Result):
    """Every computed sprocket dimension in SI units (m, rad)."""

    method: str
    teeth: int = quantity("1")
    pitch: float = quantity("m")
    roller_diameter: float = quantity("m")
    pitch_diameter: float = quantity("m")
    root_diameter: float = quantity("m")
    tip_diameter_min: float = quantity("m")
    tip_diameter_max: float = quantity("m")
    seating_radius_min: float = quantity("m")
    seating_radius_max: float = quantity("m")
    seating_angle_min: float = quantity("rad")
    seating_angle_max: float = quantity("rad")
    flank_radius_min: float = quantity("m")
    flank_radius_max: float = quantity("m")
    tooth_height_min: float = quantity("m")
    tooth_height_max: float = quantity("m")
    measurement_over_pins: float = quantity("m")
    tooth_side_radius: float = quantity("m")
    tooth_side_relief_min: float = quantity("m")
    tooth_side_relief_max: float = quantity("m")
    tooth_width: float | None = quantity("m", default=None)
    max_hub_diameter: float | None = quantity("m", default=None)
    ansi: dict | None = None
    sources: dict = field(default_factory=dict)


_SOURCES = {
    "pitch_diameter": "ISO 606:2015 5.3.2, d = p / sin(180°/z)",
    "root_diameter": "ISO 606:2015 5.3.2, df = d − d1",
    "tip_diameter": "ISO 606:2015 5.5.2, da max = d + 1.25p − d1, da min = d + p(1 − 1.6/z) − d1",
    "seating_radius": "ISO 606:2015 5.4.2, ri min = 0.505 d1, ri max = 0.505 d1 + 0.069 d1^(1/3) [mm]",
    "seating_angle": "ISO 606:2015 5.4.2, α min = 120° − 90°/z, α max = 140° − 90°/z",
    "flank_radius": "ISO 606:2015 5.4.2, re min = 0.12 d1 (z + 2), re max = 0.008 d1 (z² + 180)",
    "tooth_height": "ISO 606:2015 5.5.2, ha min = 0.5(p − d1), ha max = 0.625p − 0.5d1 + 0.8p/z",
    "measurement_over_pins": "ISO 606:2015 5.3.2, MR = d + d1 (z even), d cos(90°/z) + d1 (z odd)",
    "tooth_width": "ISO 606:2015 5.6.2, bf1 = 0.93 b1 (p <= 12.7 mm) / 0.95 b1 (simplex)",
    "tooth_side": "ISO 606:2015 5.6.2, rx = p, ba = 0.1...0.15 p",
    "max_hub_diameter": "ISO 606:2015 5.6.2, dg = p cot(180°/z) − 1.04 h2 − 0.76 mm",
    "ansi": "ASME B29.1 tooth form, Machinery's Handbook 'Sprocket tooth form'",
}


def _get(obj, name, default=None):
    return getattr(obj, name, default) if not isinstance(obj, dict) else obj.get(name, default)


@dataclass
class Sprocket:
    """A roller-chain sprocket: chain dimensions + tooth count (thin object).

    Parameters
    ----------
    pitch : float
        Chain pitch [m].
    teeth : int
        Number of teeth (>= 9).
    roller_diameter : float
        Roller diameter ``d1`` [m].
    inner_width : float, optional
        Width between inner plates ``b1`` [m] (for the tooth width).
    plate_height : float, optional
        Inner plate depth ``h2`` [m] (for the max hub diameter).
    strands : int
        Number of chain strands.
    method : {"iso606", "ansi"}
        Tooth form standard.
    name : str
        Chain designation, for labels.

    Examples
    --------
    >>> s = Sprocket(pitch=0.0254, teeth=19, roller_diameter=0.01588)
    >>> round(s.dimensions().pitch_diameter * 1e3, 3)
    154.32
    """

    pitch: float
    teeth: int
    roller_diameter: float
    inner_width: float | None = None
    plate_height: float | None = None
    strands: int = 1
    method: str = "iso606"
    name: str = ""

    def __post_init__(self):
        from .._finite import check_finite_fields

        check_finite_fields(self)  # e.g. inner_width = inf: refused here, not carried into a result
        TOOTH_FORMS.get(self.method)
        _roller(self.pitch, self.roller_diameter)
        self.teeth = int(_teeth(self.teeth))

    @classmethod
    def from_chain(cls, chain: Chain | str | Mapping[str, Any], teeth: int, *, method: str = "iso606") -> Sprocket:
        """Build from a chain object (``chaindrive.chains.get(name)``), a name, or a dict."""
        if isinstance(chain, str):
            from .. import chains as _chains

            if not hasattr(_chains, "get"):
                raise InputError("the chain catalogue is not available yet; give pitch and roller_diameter")
            chain = _chains.get(chain)
        d1 = _get(chain, "roller_diameter")
        if d1 is None:
            raise InputError(f"chain {_get(chain, 'name', '?')!r} has no roller_diameter: not a roller chain")
        return cls(
            pitch=float(_get(chain, "pitch")),
            teeth=teeth,
            roller_diameter=float(d1),
            inner_width=_get(chain, "inner_width"),
            plate_height=_get(chain, "plate_height"),
            strands=int(_get(chain, "strands", 1) or 1),
            method=method,
            name=str(_get(chain, "name", "") or ""),
        )

    def dimensions(self) -> SprocketDimensions:
        """All ISO 606 dimensions (and the ANSI constants when ``method='ansi'``)."""
        p, z, d1 = self.pitch, self.teeth, self.roller_diameter

        def f(v):
            return float(v)

        da = tip_diameter_limits(p, z, d1)
        ri = seating_radius_limits(d1)
        al = seating_angle_limits(z)
        re = flank_radius_limits(d1, z)
        ha = tooth_height_limits(p, z, d1)
        ba = tooth_side_relief_limits(p)
        return SprocketDimensions(
            method=self.method,
            teeth=z,
            pitch=f(p),
            roller_diameter=f(d1),
            pitch_diameter=f(pitch_diameter(p, z)),
            root_diameter=f(root_diameter(p, z, d1)),
            tip_diameter_min=f(da[0]),
            tip_diameter_max=f(da[1]),
            seating_radius_min=f(ri[0]),
            seating_radius_max=f(ri[1]),
            seating_angle_min=f(al[0]),
            seating_angle_max=f(al[1]),
            flank_radius_min=f(re[0]),
            flank_radius_max=f(re[1]),
            tooth_height_min=f(ha[0]),
            tooth_height_max=f(ha[1]),
            measurement_over_pins=f(measurement_over_pins(p, z, d1)),
            tooth_side_radius=f(tooth_side_radius(p)),
            tooth_side_relief_min=f(ba[0]),
            tooth_side_relief_max=f(ba[1]),
            tooth_width=None if self.inner_width is None else f(tooth_width(p, self.inner_width, self.strands)),
            max_hub_diameter=None if self.plate_height is None else f(max_hub_diameter(p, z, self.plate_height)),
            ansi=ansi_tooth_form(p, z, d1).to_dict() if self.method == "ansi" else None,
            sources=dict(_SOURCES),
        )

    def outline(self, form: str | None = None, tip_diameter: float | None = None) -> Outline:
        """Closed tooth outline; see :func:`sprocket_outline`."""
        return sprocket_outline(
            self.pitch, self.teeth, self.roller_diameter, method=self.method, form=form, tip_diameter=tip_diameter
        )

    def to_dict(self) -> dict[str, Any]:
        """Inputs and every computed dimension, SI units."""
        return {"name": self.name, "strands": self.strands, **self.dimensions().to_dict()}

    def label(self) -> str:
        std = "ISO 606" if self.method == "iso606" else "ASME B29.1"
        return f"Sprocket {self.name + ' ' if self.name else ''}z = {self.teeth} ({std})"

    def to_dxf(self, path: str | os.PathLike[str], form: str | None = None) -> Drawing:
        """Write the outline to a DXF file in mm; returns the ezdxf document."""
        from .export import outline_to_dxf

        return outline_to_dxf(self.outline(form), path, title=self.label())

    def to_svg(self, path: str | os.PathLike[str], form: str | None = None) -> str:
        """Write the outline to an SVG file (viewBox in mm); returns the SVG text."""
        from .export import outline_to_svg

        return outline_to_svg(self.outline(form), path, title=self.label())
