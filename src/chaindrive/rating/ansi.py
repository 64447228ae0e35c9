r"""The ANSI/ACA power rating of roller chains: the two limits, galling and lubrication.

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
for one chain on one sprocket (:mod:`chaindrive.rating`). Sources, checks against
published tables and the No. 25 question: ``docs/rating.md``.
"""

from __future__ import annotations

import csv
import math
import re
import warnings
from functools import lru_cache
from importlib import resources

import numpy as np
from numpy.typing import ArrayLike

from .._docs import Fragments
from .._finite import finite_guard
from .._validation import check_nonnegative, check_positive, check_teeth, warn_outside
from ..errors import InputError, UnknownNameError, ValidityRangeWarning
from ..loads import mean_chain_speed
from ..units import angular_velocity_to_rpm, rpm_to_angular_velocity

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
]

#: The parameters the rating formulas share, described once (:mod:`chaindrive._docs`).
_DOCS = Fragments(
    pitch="""
        pitch : float or array_like
            Chain pitch ``p`` [m].
    """,
    teeth="""
        teeth : int or array_like
            Teeth ``z1`` of the small sprocket [-].
    """,
    angular_velocity="""
        angular_velocity : float or array_like
            Speed ``ω1`` of the small sprocket [rad/s].
    """,
    chain_speed="""
        chain_speed : float or array_like
            Mean chain speed ``v`` [m/s].
    """,
)
_DOCS.section("galling_parameters", "pitch", "teeth", "angular_velocity")
_DOCS.section("lubrication_parameters", "chain_speed", "pitch")

HP = 745.69987158227022
_INCH = 0.0254


def _inputs(teeth, angular_velocity, pitch):
    z = check_teeth("teeth", teeth)
    w = check_positive("angular_velocity", angular_velocity, "rad/s")
    p = check_positive("pitch", pitch, "m")
    warn_outside("teeth", z, 9, 45, "the ANSI/ACA rating (tables for 9…45 teeth)", stacklevel=4)
    return z, angular_velocity_to_rpm(w), p / _INCH


@_DOCS
def ansi_link_plate_power(teeth: ArrayLike, angular_velocity: ArrayLike, pitch: ArrayLike,
                          plate_constant: float = 0.004) -> np.ndarray:
    r"""ANSI/ACA power limit set by link-plate fatigue.

    .. math:: H_1 = K_p\,z_1^{1.08}\,n_1^{0.9}\,p^{3 - 0.07p}\ \text{hp}
              \quad (p\ \text{in inches},\ n_1\ \text{in rpm})

    Parameters
    ----------
    %(teeth)s
    %(angular_velocity)s
    %(pitch)s
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


@_DOCS
def ansi_roller_bushing_power(teeth: ArrayLike, angular_velocity: ArrayLike, pitch: ArrayLike,
                              roller_constant: float = 17.0) -> np.ndarray:
    r"""ANSI/ACA power limit set by roller–bushing impact fatigue.

    .. math:: H_2 = \frac{1000\,K_r\,z_1^{1.5}\,p^{0.8}}{n_1^{1.5}}\ \text{hp}

    Parameters
    ----------
    %(teeth)s
    %(angular_velocity)s
    %(pitch)s
    roller_constant : float
        ``K_r`` = 29 (ANSI 25, 35), 3.4 (ANSI 41), 17 (ANSI 40…240) [-].

    Returns
    -------
    ndarray
        Power of one strand at the roller–bushing limit [W].

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
        Chain name (``"ANSI 40-1"``, ``"08A-1"``, ``"16B-1"``); its ANSI number (or that of
        its ISO 606 twin) sets the constants.

    Returns
    -------
    kp, kr : float
        ``K_p`` of the link-plate branch (hp units of eq. (17-32)) and ``K_r`` of the
        roller–bushing branch [-].

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
@_DOCS
def ansi_rated_power(pitch: ArrayLike, teeth: ArrayLike, angular_velocity: ArrayLike, *, strands: int = 1,
                     plate_constant: float = 0.004, roller_constant: float = 17.0) -> np.ndarray:
    r"""Rated power of a roller chain by the ANSI/ACA method (both limits, strands).

    .. math:: P = K_2\,\min(H_1, H_2)

    Parameters
    ----------
    %(pitch)s
    %(teeth)s
    %(angular_velocity)s
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
    With the default constants this is the A-series (ANSI) rating; ISO 606 B-series
    chains are rated by :mod:`chaindrive.rating.iso10823` (the same form with the
    B-series constants).

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


@_DOCS
def galling_speed(pitch: ArrayLike, teeth: ArrayLike, tension: ArrayLike) -> np.ndarray:
    r"""Small-sprocket speed at which the pins and bushings of a roller chain gall.

    .. math:: n_1 = 1000\left[\frac{82.5}{7.95^{p}\,1.0278^{z_1}\,1.323^{F/1000}}
              \right]^{1/(1.59 \log_{10} p + 1.873)}\ \text{rpm}
              \quad (p\ \text{in inches},\ F\ \text{in lbf})

    Parameters
    ----------
    %(pitch)s
    %(teeth)s
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


@_DOCS
def galling_tension(pitch: ArrayLike, teeth: ArrayLike, angular_velocity: ArrayLike) -> np.ndarray:
    r"""Strand tension at which the joints gall at a given speed (inverse of :func:`galling_speed`).

    .. math:: F = \frac{1000}{\ln 1.323}\left[\ln 82.5 - p\ln 7.95 - z_1 \ln 1.0278
              - (1.59\log_{10} p + 1.873)\ln\frac{n_1}{1000}\right]\ \text{lbf}

    %(galling_parameters)s

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


@_DOCS
def galling_power(pitch: ArrayLike, teeth: ArrayLike, angular_velocity: ArrayLike) -> np.ndarray:
    r"""Power one strand carries at the onset of galling: galling tension × chain speed.

    .. math:: H_3 = F_g(n_1)\,v,\qquad v = \frac{z_1\,p\,\omega}{2\pi}

    %(galling_parameters)s

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


@_DOCS
def lubrication_limits(pitch: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    r"""Upper chain speeds of lubrication types A (manual/drip) and B (bath/disc).

    .. math:: v_A(p),\ v_B(p)\ \text{from the table by chain number; linear in } p
              \text{ between the tabulated chains}

    Parameters
    ----------
    %(pitch)s

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


def _lubrication_classes(chain_speed, pitch, labels):
    """``labels[0]`` up to the first limit speed, ``labels[1]`` up to the second, else ``labels[2]``;
    the limits' range warnings passed on to the caller of the public function."""
    v = check_nonnegative("chain_speed", chain_speed, "m/s")
    with warnings.catch_warnings(record=True) as rec:
        warnings.simplefilter("always", ValidityRangeWarning)
        va, vb = lubrication_limits(pitch)
    for r in rec:
        warnings.warn(str(r.message), ValidityRangeWarning, stacklevel=3)
    return np.where(v <= va, labels[0], np.where(v <= vb, labels[1], labels[2]))


@_DOCS
def lubrication_region(chain_speed: ArrayLike, pitch: ArrayLike) -> np.ndarray:
    r"""ANSI lubrication region of a chain speed: ``"A"``, ``"B"`` or ``"C"``.

    .. math:: v \le v_A(p) \Rightarrow A;\quad v \le v_B(p) \Rightarrow B;
              \quad \text{else } C

    %(lubrication_parameters)s

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
    >>> str(lubrication_region(1.0, 0.0254)), str(lubrication_region(20.0, 0.0254))   # No. 80
    ('B', 'C')
    """
    return _lubrication_classes(chain_speed, pitch, ("A", "B", "C"))


@finite_guard
@_DOCS
def lubrication_type(chain_speed: ArrayLike, pitch: ArrayLike) -> np.ndarray:
    r"""ANSI lubrication type as a Roman numeral: I (= A), II (= B), III (= C).

    .. math:: \text{I, II, III} = A, B, C \text{ of } :func:`lubrication_region`

    Kept for callers that use the older names; new code should use
    :func:`lubrication_region` (the letters of the ANSI tables).

    %(lubrication_parameters)s

    Returns
    -------
    ndarray of str
        ``"I"``, ``"II"``, ``"III"``: the regions A, B, C of :func:`lubrication_region`.

    References
    ----------
    See :func:`lubrication_limits`.

    Examples
    --------
    >>> str(lubrication_type(1.0, 0.0254)), str(lubrication_type(20.0, 0.0254))
    ('II', 'III')
    """
    return _lubrication_classes(chain_speed, pitch, ("I", "II", "III"))


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
