"""ISO 606:2015 clause 5 sprocket dimensions: one published formula per function
(vectorised, SI units). The tooth outlines are in :mod:`.tooth_form`, the :class:`Sprocket`
object in :mod:`.sprocket`; sources and corrections: :mod:`chaindrive.geometry.sprocket`, docs/geometry.md."""

from __future__ import annotations

import warnings
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike

from .._docs import Fragments
from .._finite import finite_guard
from .._typing import FloatOrArray
from .._validation import as_float_array, check_positive
from ..errors import InfeasibleError, InputError, ValidityRangeWarning
from ..limits import MAX_TEETH

if TYPE_CHECKING:

    pass

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
]

MIN_TEETH = 9
#: Largest tooth count of ISO 606:2015 Annex A; above it a ValidityRangeWarning.
MAX_TEETH_TABULATED = 150

_INCH = 0.0254
_MM = 1e-3


#: The parameters the ISO 606 formulas share, described once (:mod:`chaindrive._docs`).
_DOCS = Fragments(
    pitch="""
        pitch : float or array_like
            Chain pitch ``p`` [m].
    """,
    pitch_teeth="""
        %(pitch)s
        teeth : int or array_like
            Number of teeth ``z`` >= 9 [-] (ISO 606:2015 Annex A tabulates 9...150;
            above, a :class:`~chaindrive.errors.ValidityRangeWarning`).
    """,
    roller_diameter="""
        roller_diameter : float or array_like
            Roller diameter ``d1`` of the chain (its maximum) [m], ``0 < d1 < p``.
    """,
)
_DOCS.section("p_z_d1_parameters", "pitch_teeth", "roller_diameter")
_DOCS.section("p_z_parameters", "pitch_teeth")
_DOCS.section("p_parameters", "pitch")


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
@_DOCS
def pitch_diameter(pitch: ArrayLike, teeth: ArrayLike) -> FloatOrArray:
    r"""Pitch circle diameter of a sprocket, ISO 606:2015 clause 5.3.

    .. math:: d = \frac{p}{\sin(180°/z)}

    %(p_z_parameters)s

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
@_DOCS
def root_diameter(pitch: ArrayLike, teeth: ArrayLike, roller_diameter: ArrayLike) -> FloatOrArray:
    r"""Root diameter ``df = d − d1``, ISO 606:2015 clause 5.3.

    .. math:: d_f = d - d_1

    %(p_z_d1_parameters)s

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
@_DOCS
def tip_diameter_limits(
    pitch: ArrayLike, teeth: ArrayLike, roller_diameter: ArrayLike
) -> tuple[FloatOrArray, FloatOrArray]:
    r"""Smallest and largest tip diameter, ISO 606:2015 clause 5.5.

    .. math:: d_{a,\max} = d + 1.25\,p - d_1,\qquad
              d_{a,\min} = d + p\left(1 - \frac{1.6}{z}\right) - d_1

    %(p_z_d1_parameters)s

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
@_DOCS
def tooth_height_limits(
    pitch: ArrayLike, teeth: ArrayLike, roller_diameter: ArrayLike
) -> tuple[FloatOrArray, FloatOrArray]:
    r"""Tooth height above the pitch polygon, ISO 606:2015 clause 5.5.

    .. math:: h_{a,\min} = 0.5\,(p - d_1),\qquad h_{a,\max} = 0.625\,p - 0.5\,d_1 + \frac{0.8\,p}{z}

    %(p_z_d1_parameters)s

    Returns
    -------
    ha_min, ha_max : ndarray
        [m].

    References
    ----------
    ISO 606:2015, clause 5.5.2 (used for drawing the tooth to a turning diameter).

    Examples
    --------
    >>> [round(float(h) * 1e3, 3) for h in tooth_height_limits(0.0254, 19, 0.01588)]
    [4.76, 9.004]
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
@_DOCS
def tooth_side_radius(pitch: ArrayLike) -> FloatOrArray:
    r"""Nominal tooth side radius ``rx = p``, ISO 606:2015 clause 5.6.

    .. math:: r_x = p

    %(p_parameters)s

    Returns
    -------
    ndarray
        Tooth side radius ``rx`` [m].

    Examples
    --------
    >>> float(tooth_side_radius(0.0254))
    0.0254
    """
    return check_positive("pitch", pitch, "m") * 1.0


@finite_guard
@_DOCS
def tooth_side_relief_limits(pitch: ArrayLike) -> tuple[FloatOrArray, FloatOrArray]:
    r"""Nominal tooth side relief ``ba`` from 0.1 p to 0.15 p, ISO 606:2015 clause 5.6.

    .. math:: b_a = (0.10 \dots 0.15)\,p

    %(p_parameters)s

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
    >>> round(float(max_hub_diameter(0.0254, 19, 0.02108)) * 1e3, 3)   # [mm], 16B-1 on 19 teeth
    129.531
    """
    p = check_positive("pitch", pitch, "m")
    h2 = check_positive("plate_height", plate_height, "m")
    z = _teeth(teeth)
    dg = p / np.tan(np.pi / z) - 1.04 * h2 - 0.76 * _MM
    if np.any(dg <= 0):
        raise InfeasibleError("max_hub_diameter: p cot(180°/z) − 1.04 h2 − 0.76 mm <= 0; no hub fits")
    return dg
