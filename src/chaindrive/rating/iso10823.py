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

evaluates them on the charts' 19-tooth basis, and takes the *constants* per ISO 606 series
(:func:`iso10823_constants`):

* **A series** (``08A`` … ``48A``, ANSI twins): the ACA constants (``K_p = 0.004``,
  ``K_r = 17``; 29 for the rollerless 04C/06C), i.e. the ANSI ratings on 19 teeth;
* **B series** (``05B`` … ``48B``): both constants solved from one published table,
  Bhandari, *Design of Machine Elements*, Table 14.2 (kW, 17-tooth small sprocket, converted
  to the 19-tooth basis by the standard's tooth factor): ``K_p = 0.00434`` from its
  link-plate entry (10B at 1400 rpm, 11.67 kW) and ``K_r = 21.85`` from its roller–bushing
  entry (12B at 1400 rpm, 18.15 kW). Checked, not fitted, against three other textbook
  tables of B-series kW ratings (Khurmi & Gupta Table 21.4, the PSG *Design Data* book,
  Jindal Table 30-8): within ±8 %, worst −7.8 %. No chain maker's B-series table could be
  read and no second source has a point in the roller–bushing branch, so the B-series
  constants stay **provisional**: every B-series rating says so in its ``warnings``.

Other tooth counts follow the standard's own **tooth factor** ``f_2 = (19/z_1)^{1.08}``
(ISO 10823:2004, 4.2: the corrected power ``P_c = f_1 f_2 P`` is compared with the 19-tooth
chart), one factor for the whole chart line (:func:`iso_tooth_factor`): the rated power on
``z_1`` teeth is the chart value divided by ``f_2``. Strands multiply by 1, 1.7, 2.5, 3.3
(:func:`~chaindrive.rating.ansi.multi_strand_factor`). In the link-plate branch this is the
ACA law exactly (its tooth exponent is the same 1.08); in the roller–bushing branch the ACA
law scales with ``z_1^{1.5}`` instead, so the two methods differ there for ``z_1 ≠ 19``. The
derivation, the data and its limits: ``docs/rating.md`` ("ISO 10823").
"""

from __future__ import annotations

import re

import numpy as np
from numpy.typing import ArrayLike

from .._finite import finite_guard
from .._validation import check_teeth
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
#: 10B at 1400 rpm on 17 teeth = 11.67 kW (0.004 x 11.67 / 10.75 = 0.00434; the same on the 19-tooth
#: basis, the branch's tooth exponent being the standard's 1.08; docs/rating.md, "ISO 10823").
B_SERIES_PLATE_CONSTANT = 0.00434

#: Roller–bushing constant ``K_r`` of the B series [-]: from Bhandari Table 14.2, 12B at
#: 1400 rpm on 17 teeth = 18.15 kW, i.e. 18.15 (19/17)^1.08 = 20.47 kW on the 19-tooth basis
#: (docs/rating.md, "ISO 10823"; provisional).
B_SERIES_ROLLER_CONSTANT = 21.85

#: The note every B-series rating carries.
B_SERIES_NOTE = ("ISO 10823 B-series constants provisional: K_p = 0.00434 and K_r = 21.85 are solved from "
                 "Bhandari, Design of Machine Elements, Table 14.2 (10B and 12B, 17 teeth, 1400 rpm); K_p agrees "
                 "within 8 % with three other textbook tables, K_r rests on that one point, and no chain maker's "
                 "B-series table was available to check either")

ISO10823_SOURCE = ("ISO 10823:2004 rating basis (19-tooth small sprocket, tooth factor f2 = (19/z1)^1.08, clause 4.2) "
                   "in the ACA branch form (Shigley, 10th ed., eqs (17-32), (17-33)); B-series constants from "
                   "Bhandari, Design of Machine Elements, Table 14.2")

_B_NAME = re.compile(r"^\s*(\d{2})B(-\d+)?\s*$", re.IGNORECASE)


def is_b_series(name: str) -> bool:
    """True for an ISO 606 B-series chain name (``"08B-1"``, ``"16B"``).

    >>> is_b_series("16B-2"), is_b_series("16A-2"), is_b_series("ANSI 80")
    (True, False, False)
    """
    return bool(_B_NAME.match(str(name)))


def iso10823_constants(name: str) -> tuple[float, float]:
    r"""Branch constants ``(K_p, K_r)`` of the ISO 10823 rating for a chain name.

    .. math:: (K_p, K_r) = (0.00434,\ 21.85)\ \text{(B series)};\quad
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
    his 12B entry (roller–bushing branch), both on the 19-tooth basis (his 17-tooth values
    times ``(19/17)^{1.08}``, the tooth factor of ISO 10823 and of his own Table 14.5);
    provisional, :data:`B_SERIES_NOTE`. A series and
    ANSI names: the ACA constants
    (:func:`~chaindrive.rating.ansi.ansi_constants`).

    References
    ----------
    Bhandari, *Design of Machine Elements*, Table 14.2 (kW ratings, 17 teeth); Shigley,
    10th ed., eqs (17-32), (17-33); ISO 10823:2004 (rating charts).

    Examples
    --------
    >>> iso10823_constants("12B-1"), iso10823_constants("12A-1")
    ((0.00434, 21.85), (0.004, 17.0))
    """
    if is_b_series(name):
        return B_SERIES_PLATE_CONSTANT, B_SERIES_ROLLER_CONSTANT
    return ansi_constants(name)


def iso_tooth_factor(teeth: ArrayLike, regime: str | None = None) -> np.ndarray:
    r"""Rated power on ``z1`` teeth relative to the 19-tooth ISO 10823 chart: ``1 / f_2``.

    .. math:: \frac{P_r(z_1)}{P_r(19)} = \frac{1}{f_2} = \left(\frac{z_1}{19}\right)^{1.08}

    Parameters
    ----------
    teeth : int or array_like
        Small-sprocket teeth [-].
    regime : str, optional
        Deprecated and ignored (``FutureWarning``): the standard's factor is one for both
        branches (until 0.2 the roller–bushing branch took ``(z_1/19)^{1.5}``).

    Returns
    -------
    ndarray
        [-]; 1 at 19 teeth.

    Notes
    -----
    ISO 10823 corrects the transmitted power, ``P_c = f_1 f_2 P`` with the tooth factor
    ``f_2 = (19/z_1)^{1.08}``, and compares ``P_c`` with the 19-tooth chart; dividing the
    chart by ``f_2`` instead is the same test. One factor for the whole chart line: in the
    roller–bushing branch the ACA law would scale with ``z_1^{1.5}``
    (:mod:`chaindrive.rating.ansi`). The same factor is printed by the Chinese GB/T 18150
    (identical to ISO 10823) calculators and used by KISSsoft's DIN ISO 10823 module, and
    Bhandari's Table 14.5 (17-tooth basis: 1.11 at 19 teeth, 1.26 at 21) follows it.

    References
    ----------
    ISO 10823:2004, clause 4.2 (corrected power, tooth factor ``f_2``); JIS B 1810:2011
    (identical), 4.2; Bhandari, *Design of Machine Elements*, Table 14.5.

    Examples
    --------
    >>> round(float(iso_tooth_factor(25)), 4), round(float(iso_tooth_factor(17)), 4)
    (1.345, 0.8869)
    """
    if regime is not None:
        import warnings

        warnings.warn("iso_tooth_factor(regime=...) is deprecated and ignored: ISO 10823's tooth factor "
                      "f2 = (19/z1)^1.08 is one factor for both branches", FutureWarning, stacklevel=2)
    z = check_teeth("teeth", teeth)
    return (z / REFERENCE_TEETH) ** 1.08


@finite_guard
def iso10823_rated_power(name: str, pitch: ArrayLike, teeth: ArrayLike, angular_velocity: ArrayLike, *,
                         strands: int = 1) -> np.ndarray:
    r"""ISO 10823 rated power of a chain: the smaller branch on 19 teeth, the tooth factor, the strand factor.

    .. math:: P = \frac{K_2}{f_2}\,\min\big(P_1(19), P_2(19)\big),\qquad
              f_2 = \left(\frac{19}{z_1}\right)^{1.08},\qquad
              (K_p, K_r) = \text{iso10823\_constants(name)}

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
        Rated power of the chain (all its strands) [W].

    References
    ----------
    See :func:`iso10823_constants`, :func:`iso_tooth_factor`; Shigley, 10th ed., Table 17-23
    (strand factors; ISO 10823:2004 the same 1, 1.7, 2.5).

    Examples
    --------
    >>> w = 1400 * np.pi / 30
    >>> round(float(iso10823_rated_power("12B-1", 0.01905, 17, w)) / 1e3, 2)   # Bhandari: 18.15 kW
    18.15
    """
    kp, kr = iso10823_constants(name)
    chart = ansi_rated_power(pitch, REFERENCE_TEETH, angular_velocity, strands=strands, plate_constant=kp,
                             roller_constant=kr)
    return chart * iso_tooth_factor(teeth)
