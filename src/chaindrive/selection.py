r"""Power rating and selection of roller chains (ANSI/ACA method).

The American Chain Association rating gives the power a single-strand roller chain
transmits for the rating life (15 000 h) on a small sprocket of ``z1`` teeth at ``n1``
rpm as the smaller of two limits,

* link-plate fatigue: ``H1 = K_p z1^1.08 n1^0.9 p^(3 - 0.07 p)`` hp (p in inches),
  ``K_p = 0.004`` (0.0022 for the lightweight No. 41 chain);
* roller–bushing impact fatigue: ``H2 = 1000 K_r z1^1.5 p^0.8 / n1^1.5`` hp,
  ``K_r = 29`` (Nos. 25 and 35), 3.4 (No. 41), 17 (Nos. 40–240);

and it is checked against galling of pins and bushings, a speed limit that falls
with the chain tension (Shigley §17-5; :func:`galling_speed`, and as a power at a given
speed :func:`galling_power`): above it the tables mark the galling region (type C').

The lubrication the rating assumes depends on the chain speed: type A (manual or
drip), B (oil bath or slinger disc), C (oil stream), C' (oil stream in the galling
region: submit the design to the manufacturer). :func:`chain_rating` gathers all of it
for one chain on one sprocket; :func:`select` ranks the catalogue chains that carry a
power. ISO 10823:2004 gives its ratings as charts without a published closed form; they
are not reproduced here. Sources, checks against published tables and the No. 25
question: ``docs/rating.md``.
"""

from __future__ import annotations

import csv
import math
import re
import warnings
from dataclasses import dataclass
from functools import lru_cache
from importlib import resources
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike

from ._finite import finite_guard
from ._results import Result, quantity
from ._validation import check_nonnegative, check_positive, check_teeth, warn_outside
from .errors import InfeasibleError, InputError, UnknownNameError, ValidityRangeWarning
from .loads import mean_chain_speed
from .units import angular_velocity_to_rpm, rpm_to_angular_velocity

if TYPE_CHECKING:
    from .chains import Chain

__all__ = [
    "HP",
    "ansi_link_plate_power",
    "ansi_roller_bushing_power",
    "ansi_rated_power",
    "ansi_constants",
    "multi_strand_factor",
    "tooth_correction_factor",
    "galling_speed",
    "galling_tension",
    "galling_power",
    "lubrication_region",
    "lubrication_limits",
    "lubrication_type",
    "LUBRICATION_REGIONS",
    "LUBRICATION_TYPES",
    "ChainRating",
    "chain_rating",
    "Candidate",
    "select",
    "candidate_project",
]

HP = 745.69987158227022
_INCH = 0.0254


def _inputs(teeth, angular_velocity, pitch):
    z = check_teeth("teeth", teeth)
    w = check_positive("angular_velocity", angular_velocity, "rad/s")
    p = check_positive("pitch", pitch, "m")
    warn_outside("teeth", z, 9, 45, "the ANSI/ACA rating (tables for 9…45 teeth)", stacklevel=4)
    return z, angular_velocity_to_rpm(w), p / _INCH


def ansi_link_plate_power(teeth: ArrayLike, angular_velocity: ArrayLike, pitch: ArrayLike,
                          plate_constant: float = 0.004) -> np.ndarray:
    r"""ANSI/ACA power limit set by link-plate fatigue.

    .. math:: H_1 = K_p\,z_1^{1.08}\,n_1^{0.9}\,p^{3 - 0.07p}\ \text{hp}
              \quad (p\ \text{in inches},\ n_1\ \text{in rpm})

    Parameters
    ----------
    teeth : int or array_like
        Teeth ``z1`` of the small sprocket [-].
    angular_velocity : float or array_like
        Speed of the small sprocket [rad/s].
    pitch : float or array_like
        Chain pitch [m].
    plate_constant : float
        ``K_p`` = 0.004 (0.0022 for ANSI 41) [hp units].

    Returns
    -------
    ndarray
        Rated power of one strand [W].

    Notes
    -----
    Empirical, for ANSI B29.1 proportions, ``z1`` in 9…45 (warns outside), rating
    life 15 000 h. Checked against the published ANSI 40 and 41 rating tables.

    References
    ----------
    American Chain Association, "Chains for Power Transmission and Material
    Handling"; Shigley, 10th ed., eq. (17-32); Engineers Edge, "Roller chain No. 40 /
    No. 41 horsepower ratings" (tables); Roller chains data sheet (scribd 232681759):
    ``K = 0.004``, 0.0022 for No. 41.

    Examples
    --------
    >>> round(float(ansi_link_plate_power(17, 1000 * 2 * np.pi / 60, 0.0127)) / HP, 2)
    5.49
    """
    z, n, p = _inputs(teeth, angular_velocity, pitch)
    return plate_constant * z**1.08 * n**0.9 * p ** (3.0 - 0.07 * p) * HP


def ansi_roller_bushing_power(teeth: ArrayLike, angular_velocity: ArrayLike, pitch: ArrayLike,
                              roller_constant: float = 17.0) -> np.ndarray:
    r"""ANSI/ACA power limit set by roller–bushing impact fatigue.

    .. math:: H_2 = \frac{1000\,K_r\,z_1^{1.5}\,p^{0.8}}{n_1^{1.5}}\ \text{hp}

    Parameters
    ----------
    teeth : int or array_like
        Teeth of the small sprocket [-].
    angular_velocity : float or array_like
        Speed of the small sprocket [rad/s].
    pitch : float or array_like
        [m].
    roller_constant : float
        ``K_r`` = 29 (ANSI 25, 35), 3.4 (ANSI 41), 17 (ANSI 40…240) [-].

    Returns
    -------
    ndarray
        [W].

    References
    ----------
    ACA; Shigley, 10th ed., eq. (17-33); Engineers Edge ANSI 40 table (1800 rpm
    column).

    Examples
    --------
    >>> round(float(ansi_roller_bushing_power(17, 1800 * 2 * np.pi / 60, 0.0127)) / HP, 2)
    8.96
    """
    z, n, p = _inputs(teeth, angular_velocity, pitch)
    return 1000.0 * roller_constant * z**1.5 * p**0.8 / n**1.5 * HP


_STRANDS = {1: 1.0, 2: 1.7, 3: 2.5, 4: 3.3}


def multi_strand_factor(strands: int) -> float:
    r"""ANSI multiple-strand factor ``K_2``.

    .. math:: P_{k\ strands} = K_2(k)\,P_{1\ strand},\quad K_2 = 1, 1.7, 2.5, 3.3

    Parameters
    ----------
    strands : int
        1…4.

    Returns
    -------
    float

    Raises
    ------
    InputError
        Outside 1…4 (no published factor used here).

    References
    ----------
    ACA; Shigley, 10th ed., Table 17-23; Engineers Edge ANSI tables ("for two strands
    1.7, three 2.5, four 3.3").

    Examples
    --------
    >>> multi_strand_factor(2)
    1.7
    """
    try:
        return _STRANDS[int(strands)]
    except (KeyError, TypeError, ValueError):
        raise InputError(f"strands must be a whole number in [1, 4], got {strands!r}") from None


def tooth_correction_factor(teeth: ArrayLike, regime: str = "link_plate") -> np.ndarray:
    r"""Tooth correction ``K_1`` relative to the 17-tooth rating column.

    .. math:: K_1 = (z_1/17)^{1.08}\ \text{(link plate)},\qquad
              K_1 = (z_1/17)^{1.5}\ \text{(roller–bushing)}

    Parameters
    ----------
    teeth : int or array_like
        [-].
    regime : {"link_plate", "roller_bushing"}
        Which limit governs (pre-extreme / post-extreme power).

    Returns
    -------
    ndarray

    Notes
    -----
    Follows from the exponents of ``z1`` in the two limits; it converts a 17-tooth
    table value to another sprocket.

    References
    ----------
    Shigley, 10th ed., Table 17-22.

    Examples
    --------
    >>> round(float(tooth_correction_factor(19)), 4)
    1.1276
    """
    z = check_teeth("teeth", teeth)
    if regime == "link_plate":
        return (z / 17.0) ** 1.08
    if regime == "roller_bushing":
        return (z / 17.0) ** 1.5
    raise UnknownNameError(f"unknown regime {regime!r}; valid: 'link_plate', 'roller_bushing'")


def ansi_constants(name: str) -> tuple[float, float]:
    r"""Plate and roller constants ``(K_p, K_r)`` for a chain name.

    ANSI 25/35 and ISO 04C/06C: (0.004, 29); ANSI 41: (0.0022, 3.4); others
    (0.004, 17).

    .. math:: (K_p, K_r)

    Parameters
    ----------
    name : str
        Chain name (``"ANSI 40-1"``, ``"08A-1"``, ``"16B-1"``).

    Returns
    -------
    tuple of float

    References
    ----------
    Shigley, 10th ed., text after eq. (17-33); roller chain data sheet (scribd 232681759).

    Examples
    --------
    >>> ansi_constants("ANSI 35-2"), ansi_constants("16B-1")
    ((0.004, 29.0), (0.004, 17.0))
    """
    key = re.sub(r"\s+", "", str(name)).upper()
    if re.match(r"^(ANSI)?(25|35)(-\d)?$", key) or re.match(r"^0[46]C", key):
        return 0.004, 29.0
    if re.match(r"^(ANSI)?41(-\d)?$", key):
        return 0.0022, 3.4
    return 0.004, 17.0


@finite_guard
def ansi_rated_power(pitch: ArrayLike, teeth: ArrayLike, angular_velocity: ArrayLike, *, strands: int = 1,
                     plate_constant: float = 0.004, roller_constant: float = 17.0) -> np.ndarray:
    r"""Rated power of a roller chain by the ANSI/ACA method (both limits, strands).

    .. math:: P = K_2\,\min(H_1, H_2)

    Parameters
    ----------
    pitch : float or array_like
        [m].
    teeth : int or array_like
        Small-sprocket teeth [-].
    angular_velocity : float or array_like
        Small-sprocket speed [rad/s].
    strands : int
        Number of strands (1…4).
    plate_constant, roller_constant : float
        See :func:`ansi_constants`.

    Returns
    -------
    ndarray
        [W].

    Notes
    -----
    Applied to ISO 606 B-series chains with the same constants as the A series of
    equal pitch (an approximation: B-series plates differ; ISO 10823 charts would be
    the proper source).

    References
    ----------
    ACA; Shigley, 10th ed., eqs (17-32), (17-33), Table 17-23.

    Examples
    --------
    >>> round(float(ansi_rated_power(0.0127, 17, 900 * 2 * np.pi / 60)) / HP, 2)
    4.98
    """
    k2 = multi_strand_factor(strands)
    h1 = ansi_link_plate_power(teeth, angular_velocity, pitch, plate_constant)
    h2 = ansi_roller_bushing_power(teeth, angular_velocity, pitch, roller_constant)
    return k2 * np.minimum(h1, h2)




# --------------------------------------------------------------------------- galling

_LBF = 4.4482216152605  # N per lbf
_GALLING_PITCH_RANGE_IN = (0.2499, 3.0001)  # ANSI nos. 25 ... 240 (float margin)


def _galling_exponent(pitch_in: np.ndarray) -> np.ndarray:
    return 1.0 / (1.59 * np.log10(pitch_in) + 1.873)


def galling_speed(pitch: ArrayLike, teeth: ArrayLike, tension: ArrayLike) -> np.ndarray:
    r"""Small-sprocket speed at which the pins and bushings of a roller chain gall.

    .. math:: n_1 = 1000\left[\frac{82.5}{7.95^{p}\,1.0278^{z_1}\,1.323^{F/1000}}
              \right]^{1/(1.59 \log_{10} p + 1.873)}\ \text{rpm}
              \quad (p\ \text{in inches},\ F\ \text{in lbf})

    Parameters
    ----------
    pitch : float or array_like
        Chain pitch [m].
    teeth : int or array_like
        Teeth ``z1`` of the small sprocket [-].
    tension : float or array_like
        Chain tension ``F`` of one strand [N], ``>= 0``.

    Returns
    -------
    ndarray
        Galling speed of the small sprocket [rad/s]; above it the drive runs in the
        galling region (ANSI lubrication type C').

    Notes
    -----
    Empirical ("tests suggest"); the speed falls with pitch, teeth and tension and
    stays positive for every tension. Stated for ANSI chains; warns for pitches
    outside 1/4 … 3 in (Nos. 25 … 240). The exponent ``1.59 log p + 1.873`` is
    positive for ``p > 0.066 in``.

    References
    ----------
    Shigley, 10th ed., §17-5, the galling speed limit stated after eq. (17-33) ("The
    maximum speed (rev/min) for a chain drive is limited by galling between the pin
    and the bushing"); Table 17-20, footnote to type C' lubrication.

    Examples
    --------
    >>> round(float(galling_speed(0.0127, 17, 1000.0)) * 30 / np.pi)   # No. 40, 1 kN
    7705
    """
    p = check_positive("pitch", pitch, "m") / _INCH
    z = check_teeth("teeth", teeth)
    f = check_nonnegative("tension", tension, "N") / _LBF
    warn_outside("pitch [in]", p, *_GALLING_PITCH_RANGE_IN, "the galling limit (ANSI nos. 25-240)",
                 stacklevel=3)
    log_ratio = math.log(82.5) - p * math.log(7.95) - z * math.log(1.0278) - f / 1000.0 * math.log(1.323)
    return rpm_to_angular_velocity(1000.0 * np.exp(_galling_exponent(p) * log_ratio))


def _galling_tension_lbf(p_in, z, n_rpm):
    return 1000.0 * (math.log(82.5) - p_in * math.log(7.95) - z * math.log(1.0278)
                     - np.log(n_rpm / 1000.0) / _galling_exponent(p_in)) / math.log(1.323)


def galling_tension(pitch: ArrayLike, teeth: ArrayLike, angular_velocity: ArrayLike) -> np.ndarray:
    r"""Strand tension at which the joints gall at a given speed (inverse of :func:`galling_speed`).

    .. math:: F = \frac{1000}{\ln 1.323}\left[\ln 82.5 - p\ln 7.95 - z_1 \ln 1.0278
              - (1.59\log_{10} p + 1.873)\ln\frac{n_1}{1000}\right]\ \text{lbf}

    Parameters
    ----------
    pitch : float or array_like
        Chain pitch [m].
    teeth : int or array_like
        Small-sprocket teeth [-].
    angular_velocity : float or array_like
        Small-sprocket speed [rad/s].

    Returns
    -------
    ndarray
        Tension of one strand [N], ``>= 0``. Where the speed exceeds the galling speed
        at zero tension the formula gives a negative tension: 0 is returned there with
        a :class:`~chaindrive.errors.ValidityRangeWarning` (the chain galls unloaded).

    References
    ----------
    Shigley, 10th ed., §17-5 (galling speed limit), solved for ``F``.

    Examples
    --------
    >>> w = float(galling_speed(0.0254, 17, 5000.0))
    >>> round(float(galling_tension(0.0254, 17, w)), 6)
    5000.0
    """
    p = check_positive("pitch", pitch, "m") / _INCH
    z = check_teeth("teeth", teeth)
    n = angular_velocity_to_rpm(check_positive("angular_velocity", angular_velocity, "rad/s"))
    warn_outside("pitch [in]", p, *_GALLING_PITCH_RANGE_IN, "the galling limit (ANSI nos. 25-240)",
                 stacklevel=3)
    f = _galling_tension_lbf(p, z, n) * _LBF
    if np.any(f < 0):
        n0 = float(np.min(np.broadcast_to(galling_speed(pitch, teeth, 0.0), np.shape(f))[f < 0]))
        n0 = angular_velocity_to_rpm(n0)
        warnings.warn(
            f"angular_velocity is above the galling speed at zero tension ({n0:.4g} rpm): the "
            "chain galls unloaded, galling tension 0 returned",
            ValidityRangeWarning, stacklevel=2,
        )
    return np.maximum(f, 0.0)


def galling_power(pitch: ArrayLike, teeth: ArrayLike, angular_velocity: ArrayLike) -> np.ndarray:
    r"""Power one strand carries at the onset of galling: galling tension × chain speed.

    .. math:: H_3 = F_g(n_1)\,v,\qquad v = \frac{z_1\,p\,\omega}{2\pi}

    Parameters
    ----------
    pitch : float or array_like
        Chain pitch [m].
    teeth : int or array_like
        Small-sprocket teeth [-].
    angular_velocity : float or array_like
        Small-sprocket speed [rad/s].

    Returns
    -------
    ndarray
        [W] per strand; 0 above the zero-tension galling speed (warned).

    Notes
    -----
    Plotted against speed this is the galling line of the rating chart: right of it
    (or above it) the drive is in the galling region.

    References
    ----------
    Shigley, 10th ed., §17-5 (galling speed limit) and eq. (17-30) (chain speed).

    Examples
    --------
    >>> round(float(galling_power(0.0254, 17, 2000 * np.pi / 30)) / 1e3, 1)   # No. 80
    131.6
    """
    f = galling_tension(pitch, teeth, angular_velocity)
    v = mean_chain_speed(np.asarray(teeth), np.asarray(pitch, dtype=float), np.asarray(angular_velocity, dtype=float))
    return f * v


# --------------------------------------------------------------------------- lubrication

_FPM = 0.00508  # m/s per ft/min

#: ANSI lubrication regions: name -> method.
LUBRICATION_REGIONS: dict[str, str] = {
    "A": "manual or drip",
    "B": "oil bath or slinger disc",
    "C": "oil stream",
    "C'": "oil stream; galling region: submit the design to the chain manufacturer",
}
_LUBRICATION_SOURCE = ("McGuire Bearing Co., chain lubrication table by chain number (ft/min), as in "
                       "chaindrive/chains/data/ansi_lubrication.csv; regions as in Shigley, 10th ed., "
                       "Table 17-20 footnotes")


@lru_cache(maxsize=1)
def _lubrication_table() -> dict[str, np.ndarray]:
    text = resources.files("chaindrive.chains").joinpath("data", "ansi_lubrication.csv").read_text("utf-8")
    rows = list(csv.DictReader(line for line in text.splitlines() if line.strip() and not line.startswith("#")))
    return {
        "chain_number": np.array([int(r["chain_number"]) for r in rows]),
        "pitch_in": np.array([float(r["pitch_in"]) for r in rows]),
        "type_a_fpm": np.array([float(r["type_a_max_fpm"]) for r in rows]),
        "type_b_fpm": np.array([float(r["type_b_max_fpm"]) for r in rows]),
    }


#: Chain-speed limits of ANSI lubrication types A and B [ft/min] by pitch [in] (the data
#: file ``chaindrive/chains/data/ansi_lubrication.csv``; McGuire Bearing Co.).
LUBRICATION_TYPES: dict[str, np.ndarray] = _lubrication_table()


def lubrication_limits(pitch: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    r"""Upper chain speeds of lubrication types A (manual/drip) and B (bath/disc).

    .. math:: v_A(p),\ v_B(p)\ \text{from the table by chain number; linear in } p
              \text{ between the tabulated chains}

    Parameters
    ----------
    pitch : float or array_like
        Chain pitch [m].

    Returns
    -------
    (ndarray, ndarray)
        ``v_A``, ``v_B`` [m/s]; above ``v_B`` type C (oil stream).

    Notes
    -----
    Tabulated for ANSI 40 … 160 (12.7 … 50.8 mm). Smaller pitches (Nos. 25, 35) take the
    No. 40 limits (conservative: the published limits grow as the pitch falls); larger
    pitches (Nos. 180 … 240) continue the No. 140–160 segment as a power law
    ``v ∝ p^k`` (conservative: it keeps falling, and stays positive). Both warn with a
    :class:`~chaindrive.errors.ValidityRangeWarning`.

    References
    ----------
    McGuire Bearing Co., "What are some guidelines for better chain performance?"
    (type A and B limits in ft/min for Nos. 40–160); Engineers Edge ANSI horsepower
    tables and Shigley, 10th ed., Table 17-20 (the meaning of types A, B, C).

    Examples
    --------
    >>> [round(float(v), 3) for v in lubrication_limits(0.0254)]    # No. 80: 170, 1500 ft/min
    [0.864, 7.62]
    """
    p = check_positive("pitch", pitch, "m") / _INCH
    tab = _lubrication_table()
    x, va, vb = tab["pitch_in"], tab["type_a_fpm"], tab["type_b_fpm"]
    lo, hi = x[0], x[-1]
    if np.any(p < lo - 1e-9) or np.any(p > hi + 1e-9):
        warnings.warn(
            f"pitch = {np.round(p * 25.4, 3)} mm is outside the lubrication table (12.7…50.8 mm, "
            "ANSI 40-160): below it the No. 40 limits are used, above it the No. 140-160 trend "
            "is continued",
            ValidityRangeWarning, stacklevel=2,
        )
    ka = math.log(va[-1] / va[-2]) / math.log(x[-1] / x[-2])
    kb = math.log(vb[-1] / vb[-2]) / math.log(x[-1] / x[-2])
    pc = np.clip(p, lo, hi)  # inside: linear interpolation; outside: see below
    a = np.interp(pc, x, va)
    b = np.interp(pc, x, vb)
    big = p > hi
    a = np.where(big, va[-1] * (np.maximum(p, hi) / hi) ** ka, a)
    b = np.where(big, vb[-1] * (np.maximum(p, hi) / hi) ** kb, b)
    return a * _FPM, b * _FPM


def lubrication_region(chain_speed: ArrayLike, pitch: ArrayLike) -> np.ndarray:
    r"""ANSI lubrication region of a chain speed: ``"A"``, ``"B"`` or ``"C"``.

    .. math:: v \le v_A(p) \Rightarrow A;\quad v \le v_B(p) \Rightarrow B;
              \quad \text{else } C

    Parameters
    ----------
    chain_speed : float or array_like
        [m/s].
    pitch : float or array_like
        [m].

    Returns
    -------
    ndarray of str
        ``"A"`` manual or drip, ``"B"`` oil bath or slinger disc, ``"C"`` oil stream
        (:data:`LUBRICATION_REGIONS`). The galling region C' depends on the tension:
        :func:`chain_rating` reports it.

    References
    ----------
    See :func:`lubrication_limits`.

    Examples
    --------
    >>> str(lubrication_region(1.0, 0.0254)), str(lubrication_region(20.0, 0.0254))
    ('B', 'C')
    """
    v = check_nonnegative("chain_speed", chain_speed, "m/s")
    with warnings.catch_warnings():
        warnings.simplefilter("always", ValidityRangeWarning)
        with warnings.catch_warnings(record=True) as rec:
            va, vb = lubrication_limits(pitch)
    for r in rec:
        warnings.warn(str(r.message), ValidityRangeWarning, stacklevel=2)
    return np.where(v <= va, "A", np.where(v <= vb, "B", "C"))


@finite_guard
def lubrication_type(chain_speed: ArrayLike, pitch: ArrayLike) -> np.ndarray:
    r"""ANSI lubrication type as a Roman numeral: I (= A), II (= B), III (= C).

    .. math:: \text{I, II, III} = A, B, C \text{ of } :func:`lubrication_region`

    Kept for callers that use the older names; new code should use
    :func:`lubrication_region` (the letters of the ANSI tables).

    Parameters
    ----------
    chain_speed : float or array_like
        [m/s].
    pitch : float or array_like
        [m].

    Returns
    -------
    ndarray of str

    References
    ----------
    See :func:`lubrication_limits`.

    Examples
    --------
    >>> str(lubrication_type(1.0, 0.0254)), str(lubrication_type(20.0, 0.0254))
    ('II', 'III')
    """
    v = check_nonnegative("chain_speed", chain_speed, "m/s")
    with warnings.catch_warnings(record=True) as rec:
        warnings.simplefilter("always", ValidityRangeWarning)
        va, vb = lubrication_limits(pitch)
    for r in rec:
        warnings.warn(str(r.message), ValidityRangeWarning, stacklevel=2)
    return np.where(v <= va, "I", np.where(v <= vb, "II", "III"))


# --------------------------------------------------------------------------- one chain

_GOVERNING = ("link_plate", "roller_bushing")


@dataclass(frozen=True)
class ChainRating(Result):
    """ANSI/ACA rating of one roller chain on one small sprocket (:func:`chain_rating`).

    Attributes
    ----------
    chain : str
        Chain name.
    pitch : float
        [m].
    strands : int
        Number of strands (1 … 4).
    teeth : int
        Teeth of the small sprocket [-].
    angular_velocity : float
        Speed of the small sprocket [rad/s].
    chain_speed : float
        Mean chain speed ``z p ω / (2π)`` [m/s].
    link_plate, roller_bushing : float
        Power limits of link-plate fatigue and roller–bushing impact, strands included
        (multi-strand factor ``K_2``) [W].
    galling : float
        Power at which the joints start to gall at this speed, strands included [W]
        (:func:`galling_power` × ``K_2``); informative, the galling check is
        ``galling_exceeded``.
    rated_power : float
        The smaller of ``link_plate`` and ``roller_bushing`` [W]: the ANSI table value,
        which the tables also print in the galling region (type C').
    governing_limit : str
        ``"link_plate"`` or ``"roller_bushing"``.
    tension : float
        Strand tension the galling check uses [N]: ``power / (v K_2)`` for a given
        power, else that of the link-plate/roller–bushing rating.
    galling_speed : float
        Small-sprocket speed at which galling starts at ``tension`` [rad/s] (not m/s).
    galling_exceeded : bool
        ``angular_velocity > galling_speed`` (equivalently: power above ``galling``):
        the drive runs in the galling region, lubrication type C'; the ANSI tables
        then ask for the manufacturer's evaluation.
    lubrication : str
        ``"A"``, ``"B"``, ``"C"`` or ``"C'"`` (galling region).
    lubrication_method : str
        Its meaning (:data:`LUBRICATION_REGIONS`).
    lubrication_source : str
        Where the region boundaries come from.
    warnings : tuple of str
        Validity-range and method notes (nothing is emitted as a Python warning).
    """

    chain: str
    pitch: float = quantity("m")
    strands: int = quantity("1")
    teeth: int = quantity("1")
    angular_velocity: float = quantity("rad/s")
    chain_speed: float = quantity("m/s")
    link_plate: float = quantity("W")
    roller_bushing: float = quantity("W")
    galling: float = quantity("W")
    rated_power: float = quantity("W")
    governing_limit: str
    tension: float = quantity("N")
    galling_speed: float = quantity("rad/s")
    galling_exceeded: bool
    lubrication: str
    lubrication_method: str
    lubrication_source: str
    warnings: tuple[str, ...]


def _scalar(name: str, value, check, unit: str) -> float:
    arr = check(name, value, unit)
    if arr.ndim:
        raise InputError(f"{name} must be a single number ({unit}), got an array of shape {arr.shape}")
    return float(arr)


def chain_rating(chain: Chain | str, teeth: int, angular_velocity: float, *,
                 power: float | None = None) -> ChainRating:
    r"""ANSI/ACA rating of a roller chain on its small sprocket, with galling and lubrication.

    .. math:: P_r = K_2 \min(H_1, H_2),\qquad
              \text{galling if } n_1 > n_g\!\left(\frac{P}{K_2 v}\right)

    Parameters
    ----------
    chain : Chain or str
        A roller chain (catalogue name, or a :class:`~chaindrive.chains.Chain`) with
        1 … 4 strands.
    teeth : int
        Teeth of the small sprocket [-] (the ratings are built for 9 … 45; warns outside).
    angular_velocity : float
        Speed of the small sprocket [rad/s].
    power : float, optional
        Transmitted (design) power [W]; sets the strand tension of the galling check.
        Without it the galling check uses the tension at the link-plate/roller–bushing
        rating.

    Returns
    -------
    ChainRating

    Raises
    ------
    InputError
        For a round link chain or more than 4 strands (outside the ANSI method: this
        function raises rather than returning ``None``; check
        ``chain.is_roller_chain and chain.strands <= 4`` first), and for a bad
        ``teeth``, ``angular_velocity`` or ``power``.
    UnknownNameError
        For an unknown chain name.

    Notes
    -----
    Link-plate and roller–bushing limits: :func:`ansi_link_plate_power`,
    :func:`ansi_roller_bushing_power` with the constants of :func:`ansi_constants`,
    times the multi-strand factor ``K_2``. Galling: :func:`galling_power` per strand
    with the strand tension taken as ``F / K_2`` (the load share the rating assumes).
    ISO 606 B-series chains are rated with the constants of the A series of equal
    pitch (an approximation, noted in ``warnings``); so are custom roller chains.

    References
    ----------
    ACA; Shigley, 10th ed., eqs (17-32), (17-33), the galling limit of §17-5, Table 17-20
    (lubrication types A, B, C, C') and Table 17-23 (multi-strand factors); McGuire
    Bearing Co. (type A/B chain-speed limits).

    Examples
    --------
    >>> r = chain_rating("ANSI 40", 17, 1000 * np.pi / 30)
    >>> round(r.rated_power / HP, 2), r.governing_limit, r.lubrication, r.galling_exceeded
    (5.48, 'link_plate', 'B', False)
    """
    from .chains import get

    ch = get(chain)
    if not ch.is_roller_chain:
        raise InputError(f"chain {ch.name} is a round link chain: the ANSI/ACA rating holds for roller "
                         "chains (ISO 606, ANSI B29.1) with 1 to 4 strands")
    if ch.strands > 4:
        raise InputError(f"chain {ch.name} has {ch.strands} strands: the ANSI/ACA multi-strand factors "
                         "cover 1 to 4 strands")
    z = int(_scalar("teeth", teeth, lambda n, v, u: check_teeth(n, v), "whole number >= 3"))
    w = _scalar("angular_velocity", angular_velocity, check_positive, "rad/s")
    design = None if power is None else _scalar("power", power, check_positive, "W")
    notes: list[str] = []
    with warnings.catch_warnings(record=True) as rec:
        warnings.simplefilter("always", ValidityRangeWarning)
        kp, kr = ansi_constants(ch.name)
        k2 = multi_strand_factor(ch.strands)
        h1 = float(ansi_link_plate_power(z, w, ch.pitch, kp))
        h2 = float(ansi_roller_bushing_power(z, w, ch.pitch, kr))
        v = mean_chain_speed(z, ch.pitch, w)
        h3 = float(galling_power(ch.pitch, z, w))
        tension = (min(h1, h2) if design is None else design / k2) / v
        n_gall = float(galling_speed(ch.pitch, z, tension))
        region = str(lubrication_region(v, ch.pitch))
    if ch.family == "iso606" and "B" in ch.name:
        notes.append("ANSI/ACA rating applied to an ISO 606 B-series chain with the constants of the "
                     "A series of equal pitch (an approximation)")
    if ch.family == "custom":
        notes.append(f"custom chain {ch.name}: ANSI B29.1 proportions assumed by the rating")
    limits = (k2 * h1, k2 * h2)
    i = int(np.argmin(limits))
    exceeded = bool(w > n_gall)
    if exceeded:
        region = "C'"
        notes.append(f"galling region: the joints gall above {angular_velocity_to_rpm(n_gall):.4g} rpm at "
                     f"{tension / 1e3:.3g} kN per strand (Shigley §17-5); submit the design to the "
                     "chain manufacturer")
    return ChainRating(
        chain=ch.name, pitch=ch.pitch, strands=ch.strands, teeth=z, angular_velocity=w, chain_speed=v,
        link_plate=limits[0], roller_bushing=limits[1], galling=k2 * h3, rated_power=limits[i],
        governing_limit=_GOVERNING[i], tension=tension, galling_speed=n_gall, galling_exceeded=exceeded,
        lubrication=region, lubrication_method=LUBRICATION_REGIONS[region],
        lubrication_source=_LUBRICATION_SOURCE,
        warnings=tuple(dict.fromkeys([str(r.message) for r in rec] + notes)),
    )


# --------------------------------------------------------------------------- selection

#: Default centre distance of :func:`select` [pitches] (ISO 10823: 30 … 50 pitches).
DEFAULT_CENTRE_PITCHES = 40


def _outside_diameter(pitch: float, teeth: int) -> float:
    # ANSI B29.1 sprocket outside diameter, OD = p (0.6 + cot(180°/N))
    return pitch * (0.6 + 1.0 / math.tan(math.pi / teeth))


@dataclass(frozen=True)
class Candidate(Result):
    """One chain that carries the load (a row of :func:`select`).

    Attributes
    ----------
    chain : str
        Chain name (the ISO 606 name when the chain also has an ANSI number).
    names : tuple of str
        Every catalogue name of this chain, e.g. ``("10A-1", "ANSI 50-1")``.
    family : str
        Catalogue family of ``chain``.
    pitch : float
        [m].
    strands : int
    teeth_driving, teeth_driven : int
    speed : float
        Small (driving) sprocket speed [rad/s].
    power : float
        Transmitted power [W].
    service_factor : float
    chain_speed : float
        [m/s].
    rated_power : float
        ANSI/ACA rating of the chain (all strands, galling included) [W].
    design_power : float
        Power times service factor [W].
    power_margin : float
        ``rated_power / design_power`` [-] (>= 1).
    governing_limit : str
        ``"link_plate"``, ``"roller_bushing"`` or ``"galling"``.
    working_tension : float
        Design pull plus centrifugal tension [N].
    static_safety : float or None
        Breaking force / working tension [-] (``None``: breaking force unknown).
    galling_speed : float
        Small-sprocket speed at which galling starts at the design tension [rad/s].
    lubrication : str
        ANSI lubrication region ``"A"``, ``"B"``, ``"C"``, or ``"C'"`` (galling region:
        the design needs the manufacturer's evaluation; such rows rank last).
    lubrication_method : str
    centre_distance : float
        Centre distance for ``links`` (ISO 10823 approximation) [m].
    links : int
        Chain length [pitches], even.
    notes : tuple of str
    """

    chain: str
    names: tuple[str, ...]
    family: str
    pitch: float = quantity("m")
    strands: int = quantity("1")
    teeth_driving: int = quantity("1")
    teeth_driven: int = quantity("1")
    speed: float = quantity("rad/s")
    power: float = quantity("W")
    service_factor: float = quantity("1")
    chain_speed: float = quantity("m/s")
    rated_power: float = quantity("W")
    design_power: float = quantity("W")
    power_margin: float = quantity("1")
    governing_limit: str
    working_tension: float = quantity("N")
    static_safety: float | None = quantity("1")
    galling_speed: float = quantity("rad/s")
    lubrication: str
    lubrication_method: str
    centre_distance: float = quantity("m")
    links: int = quantity("1")
    notes: tuple[str, ...]


def _series(chain: Chain) -> str:
    """Proportion series: ``"B"`` (ISO B) or ``"A"`` (ISO A/C = ANSI numbers)."""
    return "B" if chain.family == "iso606" and "B" in chain.name else "A"


@finite_guard
def select(power: float, speed: float, ratio: float, *, service_factor: float = 1.0,
           teeth_driving: int = 17, centre_distance: float | None = None, family: str | None = None,
           strands: tuple[int, ...] = (1, 2, 3), min_static_safety: float = 6.0,
           all_sizes: bool = False, limit: int | None = None) -> list[Candidate]:
    r"""Roller chains that carry a power with the required safety, simplex first.

    .. math:: K_2 \min(H_1, H_2, H_3) \ge K_s P,\qquad
              \frac{F_B}{K_s P / v + q v^2} \ge S_{min},\qquad
              X = 2\left\lceil \tfrac{1}{2}\left(\tfrac{2a}{p} + \tfrac{z_1+z_2}{2}
              + \left(\tfrac{z_2-z_1}{2\pi}\right)^2\tfrac{p}{a}\right)\right\rceil

    Parameters
    ----------
    power : float
        Transmitted power ``P > 0`` [W].
    speed : float
        Speed of the driving (small) sprocket [rad/s].
    ratio : float
        Speed ratio ``n1/n2 >= 1``; the driven wheel gets ``round(z1 · ratio)`` teeth.
    service_factor : float
        ``K_s >= 1`` (see :func:`chaindrive.loads.service_factor`).
    teeth_driving : int
        Small-sprocket teeth (the ANSI tables are built on 17).
    centre_distance : float, optional
        Wanted centre distance [m]; default 40 pitches of each chain (ISO 10823:
        30 … 50). Chains whose sprockets would overlap there are left out.
    family : {None, "ansi", "iso606"}
        Catalogue family; ``None`` takes both, an ANSI chain and its ISO 606 twin
        being one row with both names.
    strands : tuple of int
        Strand counts admitted (1 … 4).
    min_static_safety : float
        Required ``F_B / F`` (Diamond Chain: working load <= 1/6 of the breaking force).
    all_sizes : bool
        ``False`` (default): per proportion series (ISO B; ISO A = ANSI) and strand
        count only the smallest adequate pitch outside the galling region (the
        smallest galling one when none is outside). ``True``: every adequate chain.
    limit : int, optional
        Return at most this many candidates.

    Returns
    -------
    list of Candidate
        Ranked: rows outside the galling region first; then simplex before duplex
        before triplex; within a strand count by pitch (smallest first), then by
        static safety (largest first).

    Raises
    ------
    InputError
        Non-positive or non-finite power/speed/centre distance/minimum static safety,
        ratio < 1, service factor < 1, a strand count outside 1 … 4.
    UnknownNameError
        Unknown family.
    InfeasibleError
        No catalogue chain carries the load.

    Notes
    -----
    Only roller chains. The galling limit (Shigley §17-5) is checked at the design
    tension; a chain in the galling region (type C') stays in the list, last, as the
    ANSI tables keep it with "submit the design to the manufacturer". Chains without a
    mass per length are checked with the centrifugal tension omitted and without a
    breaking force with the static check omitted (both noted). The chain length is the
    ISO 10823 approximation rounded up to an even number of links; the centre distance
    is that of the rounded length (``chaindrive layout`` gives the exact polygon value).

    References
    ----------
    ACA rating method (:func:`chain_rating`); Shigley, 10th ed., §17-5 (selection
    procedure, eqs (17-34), (17-35)); ISO 10823:2004 (centre distance 30 … 50 pitches,
    chain length); ANSI B29.1 sprocket outside diameter ``p (0.6 + cot(180°/z))``.

    Examples
    --------
    >>> rows = select(7.5e3, 1450 * np.pi / 30, 3.0)
    >>> [(c.chain, c.strands, round(c.power_margin, 2)) for c in rows][:3]
    [('10B-1', 1, 1.47), ('10A-1', 1, 1.47), ('08B-2', 2, 1.29)]
    >>> rows[1].names, rows[1].links, rows[1].lubrication
    (('10A-1', 'ANSI 50-1'), 116, 'B')
    """
    from .chains import catalogue, equivalent_names
    from .layout import centre_distance_approx, chain_length_approx, even_links

    P = _scalar("power", power, check_positive, "W")
    w = _scalar("speed", speed, check_positive, "rad/s")
    i = _scalar("ratio", ratio, check_positive, "-")
    if i < 1:
        raise InputError(f"ratio must be >= 1 (n_driving / n_driven), got {i:g}")
    ks = _scalar("service_factor", service_factor, check_positive, "-")
    if ks < 1:
        raise InputError(f"service_factor must be >= 1, got {ks:g}")
    z1 = int(_scalar("teeth_driving", teeth_driving, lambda n, v, u: check_teeth(n, v), "whole number >= 3"))
    z2 = int(round(z1 * i))
    a_wanted = None if centre_distance is None else _scalar("centre_distance", centre_distance, check_positive, "m")
    s_min = _scalar("min_static_safety", min_static_safety, check_positive, "-")
    if family not in (None, "ansi", "iso606"):
        raise UnknownNameError(f"unknown roller-chain family {family!r}; valid: None, 'ansi', 'iso606'")
    allowed = tuple(strands)
    if not allowed or any(isinstance(k, bool) or k not in (1, 2, 3, 4) for k in allowed):
        raise InputError(f"strands must be a non-empty selection of 1, 2, 3, 4, got {strands!r}")
    fams = ("iso606", "ansi") if family is None else (family,)
    design = P * ks
    found: dict[str, Candidate] = {}
    too_close: list[str] = []
    for fam in fams:
        for ch in catalogue(fam):
            if ch.strands not in allowed:
                continue
            twins = equivalent_names(ch)
            if family is None and ch.family == "ansi" and twins:
                continue  # one row per chain: the ISO 606 twin carries both names
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", ValidityRangeWarning)
                r = chain_rating(ch, z1, w, power=design)
            if r.rated_power < design:
                continue
            v = r.chain_speed
            notes = ["ISO B series rated with the ANSI A-series constants (approximation)"
                     for n in r.warnings if "B-series" in n]
            if not 9 <= z1 <= 45:
                notes.append(f"{z1} teeth: outside the 9-45 teeth of the ANSI/ACA tables")
            if r.galling_exceeded:
                notes.append(f"galling region above {angular_velocity_to_rpm(r.galling_speed):.4g} rpm: submit to the "
                             "chain manufacturer")
            fc = 0.0
            if ch.mass_per_length is None:
                notes.append("mass per length unknown: centrifugal tension omitted")
            else:
                fc = ch.mass_per_length * v**2
            F = design / v + fc
            sf = None if ch.breaking_force is None else ch.breaking_force / F
            if sf is not None and sf < s_min:
                continue
            if sf is None:
                notes.append("breaking force unknown: static safety not checked")
            a = DEFAULT_CENTRE_PITCHES * ch.pitch if a_wanted is None else a_wanted
            clearance = (_outside_diameter(ch.pitch, z1) + _outside_diameter(ch.pitch, z2)) / 2
            if a <= clearance:
                too_close.append(f"{ch.name} (needs > {clearance * 1e3:.0f} mm)")
                continue
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", ValidityRangeWarning)
                links = int(even_links(chain_length_approx(ch.pitch, z1, z2, a)))
                a_links = float(centre_distance_approx(ch.pitch, z1, z2, links))
            if a_wanted is not None and not 30 <= a / ch.pitch <= 80:
                notes.append(f"centre distance {a / ch.pitch:.0f} pitches (ISO 10823: 30-50, at most 80)")
            if z2 > 120:
                notes.append(f"{z2} teeth on the driven wheel (Shigley §17-5: standard sprockets up to 120)")
            found[ch.name] = Candidate(
                chain=ch.name, names=(ch.name, *twins), family=ch.family, pitch=ch.pitch,
                strands=ch.strands, teeth_driving=z1, teeth_driven=z2, speed=w, power=P,
                service_factor=ks, chain_speed=v, rated_power=r.rated_power, design_power=design,
                power_margin=r.rated_power / design, governing_limit=r.governing_limit,
                working_tension=F, static_safety=sf, galling_speed=r.galling_speed,
                lubrication=r.lubrication, lubrication_method=r.lubrication_method,
                centre_distance=a_links, links=links, notes=tuple(notes),
            )
    if not found:
        extra = f"; sprockets too large for the centre distance: {', '.join(too_close[:4])}" if too_close else ""
        raise InfeasibleError(
            f"no catalogue roller chain carries {design / 1e3:g} kW (design power) at "
            f"{angular_velocity_to_rpm(w):g} rpm with {z1} teeth{extra}; try more teeth, more strands, a lower "
            "speed or a longer centre distance"
        )
    rows = sorted(found.values(), key=lambda c: (c.lubrication == "C'", c.strands, c.pitch,
                                                 -(c.static_safety or 0.0), c.chain))
    if not all_sizes:
        from .chains import get

        def key(c: Candidate) -> tuple[str, int]:
            return _series(get(c.chain)), c.strands

        # per series and strand count: the smallest adequate pitch outside the galling
        # region (rows are sorted so), or, when every adequate chain galls, the smallest
        smallest: dict[tuple[str, int], tuple[bool, float]] = {}
        for c in rows:
            smallest.setdefault(key(c), (c.lubrication == "C'", c.pitch))
        rows = [c for c in rows if smallest[key(c)] == (c.lubrication == "C'", c.pitch)]
    return rows[:limit] if limit else rows


def _toml_string(text: str) -> str:
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def candidate_project(candidate: Candidate, *, name: str | None = None) -> str:
    """A complete project file (TOML) for a row of :func:`select`.

    Two sprockets on a horizontal line at the row's centre distance, the chain, the
    speed, the power and service factor, and the chain length in links; loadable with
    :func:`chaindrive.drive.project.load_project` and ``chaindrive layout``.

    Parameters
    ----------
    candidate : Candidate
        The chosen row.
    name : str, optional
        Drive name (default: the chain and the teeth).

    Returns
    -------
    str
        TOML text with units on every quantity.

    Examples
    --------
    >>> row = select(7.5e3, 1450 * np.pi / 30, 3.0)[0]
    >>> text = candidate_project(row)
    >>> 'name = "10B-1"' in text and "links = 116" in text
    True
    """
    from .drive.writer import candidate_project_text

    return candidate_project_text(candidate, name=name)
