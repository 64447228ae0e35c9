r"""ISO 10823 power rating of ISO 606 roller chains (A and B series), in the ACA branch form.

ISO 10823:2004 ("Guidance on the selection of roller chain drives") gives the power a
simplex chain transmits as rating *charts* (one line per chain over small-sprocket speed,
for a 19-tooth small sprocket), bounded at low speed by link-plate fatigue and at high
speed by roller–bushing impact fatigue, with tooth and strand factors and lubrication
regions. Its closed form, if it has one, was not available here; this module therefore
writes each chart line in the branch form of the American Chain Association rating
(:mod:`chaindrive.rating.ansi`), whose exponents describe the same two failure modes:

.. math:: P_1 = K_p\,z_1^{1.08}\,n_1^{0.9}\,p^{3 - 0.07p}\ \text{hp},\qquad
          P_2 = \frac{1000\,K_r\,z_1^{1.5}\,p^{0.8}}{n_1^{1.5}}\ \text{hp}
          \qquad (p\ \text{in inches},\ n_1\ \text{in rpm})

and takes the *constants* per ISO 606 series (:func:`iso10823_constants`):

* **A series** (``08A`` … ``48A``, ANSI twins): the ACA constants (``K_p = 0.004``,
  ``K_r = 17``; 29 for the rollerless 04C/06C), i.e. the ANSI ratings;
* **B series** (``05B`` … ``48B``): both constants solved from one published table,
  Bhandari, *Design of Machine Elements*, Table 14.2 (kW, 17-tooth small sprocket):
  ``K_p = 0.00434`` from its link-plate entry (10B at 1400 rpm, 11.67 kW) and
  ``K_r = 22.9`` from its roller–bushing entry (12B at 1400 rpm, 18.15 kW). Checked,
  not fitted, against three other textbook tables of B-series kW ratings (Khurmi & Gupta
  Table 21.4, the PSG *Design Data* book, Jindal Table 30-8): within ±8 %, worst −7.8 %.
  No chain maker's B-series table could be read and no second source has a point in
  the roller–bushing branch, so the B-series constants stay **provisional**: every
  B-series rating says so in its ``warnings``.

The rating basis of the charts is a 19-tooth small sprocket
(:data:`REFERENCE_TEETH`); other tooth counts follow the exponents of the two branches
(:func:`iso_tooth_factor`); strands multiply by 1, 1.7, 2.5, 3.3
(:func:`~chaindrive.rating.ansi.multi_strand_factor`). The derivation, the data and its
limits: ``docs/rating.md`` ("ISO 10823").
"""

from __future__ import annotations

import re

import numpy as np
from numpy.typing import ArrayLike

from .._finite import finite_guard
from .._validation import check_teeth
from ..errors import UnknownNameError
from .ansi import ansi_constants, ansi_rated_power

__all__ = [
    "REFERENCE_TEETH",
    "B_SERIES_PLATE_CONSTANT",
    "B_SERIES_ROLLER_CONSTANT",
    "B_SERIES_NOTE",
    "ISO10823_SOURCE",
    "iso10823_constants",
    "iso10823_rated_power",
    "iso_tooth_factor",
    "is_b_series",
]

#: Teeth of the small sprocket the ISO 10823 rating charts are drawn for [-].
REFERENCE_TEETH = 19

#: Link-plate constant ``K_p`` of the B series [hp units of eq. (17-32)]: from Bhandari Table 14.2,
#: 10B at 1400 rpm on 17 teeth = 11.67 kW (0.004 x 11.67 / 10.75 = 0.00434; docs/rating.md, "ISO 10823").
B_SERIES_PLATE_CONSTANT = 0.00434

#: Roller–bushing constant ``K_r`` of the B series [-]: from Bhandari Table 14.2, 12B at
#: 1400 rpm on 17 teeth = 18.15 kW (docs/rating.md, "ISO 10823"; provisional).
B_SERIES_ROLLER_CONSTANT = 22.9

#: The note every B-series rating carries.
B_SERIES_NOTE = ("ISO 10823 B-series constants provisional: K_p = 0.00434 and K_r = 22.9 are solved from "
                 "Bhandari, Design of Machine Elements, Table 14.2 (10B and 12B, 17 teeth, 1400 rpm); K_p agrees "
                 "within 8 % with three other textbook tables, K_r rests on that one point, and no chain maker's "
                 "B-series table was available to check either")

ISO10823_SOURCE = ("ISO 10823:2004 rating basis (19-tooth small sprocket) in the ACA branch form (Shigley, 10th ed., "
                   "eqs (17-32), (17-33)); B-series constants from Bhandari, Design of Machine Elements, Table 14.2")

_B_NAME = re.compile(r"^\s*(\d{2})B(-\d+)?\s*$", re.IGNORECASE)


def is_b_series(name: str) -> bool:
    """True for an ISO 606 B-series chain name (``"08B-1"``, ``"16B"``).

    >>> is_b_series("16B-2"), is_b_series("16A-2"), is_b_series("ANSI 80")
    (True, False, False)
    """
    return bool(_B_NAME.match(str(name)))


def iso10823_constants(name: str) -> tuple[float, float]:
    r"""Branch constants ``(K_p, K_r)`` of the ISO 10823 rating for a chain name.

    .. math:: (K_p, K_r) = (0.00434,\ 22.9)\ \text{(B series)};\quad
              \text{ACA constants (A series, ANSI)}

    Parameters
    ----------
    name : str
        Chain name (``"08B-1"``, ``"12A-1"``, ``"ANSI 60"``).

    Returns
    -------
    tuple of float
        ``K_p`` [hp units of eq. (17-32)], ``K_r`` [-].

    Notes
    -----
    B series: ``K_p`` solved from Bhandari's 10B entry (link-plate branch), ``K_r`` from
    his 12B entry (roller–bushing branch); provisional, :data:`B_SERIES_NOTE`. A series and
    ANSI names: the ACA constants
    (:func:`~chaindrive.rating.ansi.ansi_constants`).

    References
    ----------
    Bhandari, *Design of Machine Elements*, Table 14.2 (kW ratings, 17 teeth); Shigley,
    10th ed., eqs (17-32), (17-33); ISO 10823:2004 (rating charts).

    Examples
    --------
    >>> iso10823_constants("12B-1"), iso10823_constants("12A-1")
    ((0.00434, 22.9), (0.004, 17.0))
    """
    if is_b_series(name):
        return B_SERIES_PLATE_CONSTANT, B_SERIES_ROLLER_CONSTANT
    return ansi_constants(name)


def iso_tooth_factor(teeth: ArrayLike, regime: str = "link_plate") -> np.ndarray:
    r"""Tooth factor relative to the 19-tooth ISO 10823 chart: rated power on ``z1`` teeth / chart value.

    .. math:: f_z = (z_1/19)^{1.08}\ \text{(link plate)},\qquad
              f_z = (z_1/19)^{1.5}\ \text{(roller–bushing)}

    Parameters
    ----------
    teeth : int or array_like
        Small-sprocket teeth [-].
    regime : {"link_plate", "roller_bushing"}
        The branch that governs at the operating speed.

    Returns
    -------
    ndarray
        [-]; 1 at 19 teeth.

    Notes
    -----
    Follows from the tooth exponents of the two branches; makers' catalogues print a
    single factor (often ``19/z1`` as a divisor of the design power), which lies between
    the two branch factors for 15 … 25 teeth.

    References
    ----------
    Shigley, 10th ed., Table 17-22 (the same exponents on a 17-tooth basis);
    ISO 10823:2004 (19-tooth basis of the charts).

    Examples
    --------
    >>> round(float(iso_tooth_factor(25)), 4), round(float(iso_tooth_factor(25, "roller_bushing")), 4)
    (1.345, 1.5093)
    """
    z = check_teeth("teeth", teeth)
    if regime == "link_plate":
        return (z / REFERENCE_TEETH) ** 1.08
    if regime == "roller_bushing":
        return (z / REFERENCE_TEETH) ** 1.5
    raise UnknownNameError(f"unknown regime {regime!r}; valid: 'link_plate', 'roller_bushing'")


@finite_guard
def iso10823_rated_power(name: str, pitch: ArrayLike, teeth: ArrayLike, angular_velocity: ArrayLike, *,
                         strands: int = 1) -> np.ndarray:
    r"""ISO 10823 rated power of a chain: the smaller branch times the strand factor.

    .. math:: P = K_2\,\min(P_1, P_2),\qquad (K_p, K_r) = \text{iso10823\_constants(name)}

    Parameters
    ----------
    name : str
        Chain name, selects the series constants (:func:`iso10823_constants`).
    pitch : float or array_like
        [m].
    teeth : int or array_like
        Small-sprocket teeth [-] (9 … 45; warns outside).
    angular_velocity : float or array_like
        Small-sprocket speed [rad/s].
    strands : int
        1 … 4.

    Returns
    -------
    ndarray
        [W].

    References
    ----------
    See :func:`iso10823_constants`; Shigley, 10th ed., Table 17-23 (strand factors).

    Examples
    --------
    >>> w = 1400 * np.pi / 30
    >>> round(float(iso10823_rated_power("12B-1", 0.01905, 17, w)) / 1e3, 2)   # Bhandari: 18.15 kW
    18.15
    """
    kp, kr = iso10823_constants(name)
    return ansi_rated_power(pitch, teeth, angular_velocity, strands=strands, plate_constant=kp,
                            roller_constant=kr)
