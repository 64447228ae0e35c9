r"""Power rating and selection of roller chains (ANSI/ACA method).

The American Chain Association rating gives the power a single-strand roller chain
transmits for the rating life on a small sprocket of ``z1`` teeth at ``n1`` rpm as
the smaller of two limits:

* link-plate fatigue: ``H1 = K_p z1^1.08 n1^0.9 p^(3 - 0.07 p)`` hp (p in inches),
  ``K_p = 0.004`` (0.0022 for the lightweight No. 41 chain);
* roller–bushing impact fatigue: ``H2 = 1000 K_r z1^1.5 p^0.8 / n1^1.5`` hp,
  ``K_r = 29`` (Nos. 25 and 35), 3.4 (No. 41), 17 (Nos. 40–240).

A third, galling limit bounds the highest speeds; its published form is a line on the
rating charts only (no closed form found), so it is not modelled. ISO 10823:2004 gives
its ratings as charts (power against speed, 19-tooth small sprocket) without a
published closed form; they are not reproduced here.
"""

from __future__ import annotations

import re
import warnings
from dataclasses import dataclass

import numpy as np

from .._results import Result
from .._validation import check_nonnegative, check_positive, check_teeth, warn_outside
from ..errors import InputError, UnknownNameError, ValidityRangeWarning

__all__ = [
    "HP",
    "ansi_link_plate_power",
    "ansi_roller_bushing_power",
    "ansi_rated_power",
    "ansi_constants",
    "multi_strand_factor",
    "tooth_correction_factor",
    "lubrication_type",
    "LUBRICATION_TYPES",
    "Candidate",
    "select",
]

#: One mechanical horsepower [W].
HP = 745.69987158227022
_INCH = 0.0254
_RPM = 2.0 * np.pi / 60.0


def _inputs(teeth, angular_velocity, pitch):
    z = check_teeth("teeth", teeth)
    w = check_positive("angular_velocity", angular_velocity, "rad/s")
    p = check_positive("pitch", pitch, "m")
    warn_outside("teeth", z, 9, 45, "the ANSI/ACA rating (tables for 9…45 teeth)", stacklevel=4)
    return z, w / _RPM, p / _INCH


def ansi_link_plate_power(teeth, angular_velocity, pitch, plate_constant=0.004):
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
    Handling"; Shigley, 9th ed., eq. (17-32); Engineers Edge, "Roller chain No. 40 /
    No. 41 horsepower ratings" (tables); Roller chains data sheet (scribd 232681759):
    ``K = 0.004``, 0.0022 for No. 41.

    Examples
    --------
    >>> round(float(ansi_link_plate_power(17, 1000 * 2 * np.pi / 60, 0.0127)) / HP, 2)
    5.49
    """
    z, n, p = _inputs(teeth, angular_velocity, pitch)
    return plate_constant * z**1.08 * n**0.9 * p ** (3.0 - 0.07 * p) * HP


def ansi_roller_bushing_power(teeth, angular_velocity, pitch, roller_constant=17.0):
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
    ACA; Shigley, 9th ed., eq. (17-33); Engineers Edge ANSI 40 table (1800 rpm
    column).

    Examples
    --------
    >>> round(float(ansi_roller_bushing_power(17, 1800 * 2 * np.pi / 60, 0.0127)) / HP, 2)
    8.96
    """
    z, n, p = _inputs(teeth, angular_velocity, pitch)
    return 1000.0 * roller_constant * z**1.5 * p**0.8 / n**1.5 * HP


_STRANDS = {1: 1.0, 2: 1.7, 3: 2.5, 4: 3.3}


def multi_strand_factor(strands):
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
    ACA; Shigley, 9th ed., Table 17-23; Engineers Edge ANSI tables ("for two strands
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


def tooth_correction_factor(teeth, regime: str = "link_plate"):
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
    Shigley, 9th ed., Table 17-22.

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
    Shigley, 9th ed., text after eq. (17-33); roller chain data sheet (scribd 232681759).

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


def ansi_rated_power(pitch, teeth, angular_velocity, *, strands=1, plate_constant=0.004,
                     roller_constant=17.0):
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
    ACA; Shigley, 9th ed., eqs (17-32), (17-33), Table 17-23.

    Examples
    --------
    >>> round(float(ansi_rated_power(0.0127, 17, 900 * 2 * np.pi / 60)) / HP, 2)
    4.98
    """
    k2 = multi_strand_factor(strands)
    h1 = ansi_link_plate_power(teeth, angular_velocity, pitch, plate_constant)
    h2 = ansi_roller_bushing_power(teeth, angular_velocity, pitch, roller_constant)
    return k2 * np.minimum(h1, h2)


#: Upper chain-speed limits [ft/min] of ANSI lubrication types A (manual/drip) and B
#: (bath/disc) by ANSI chain number; above B: type C (oil stream).
#: Source: McGuire Bearing, "Guidelines for better chain performance" (ACA practice).
LUBRICATION_TYPES = {
    "pitch_in": np.array([0.5, 0.625, 0.75, 1.0, 1.25, 1.5, 1.75, 2.0]),
    "type_a_fpm": np.array([300, 250, 220, 170, 150, 130, 115, 100], dtype=float),
    "type_b_fpm": np.array([2300, 2000, 1800, 1500, 1300, 1200, 1100, 1000], dtype=float),
}
_FPM = 0.00508  # m/s per ft/min


def lubrication_type(chain_speed, pitch):
    r"""ANSI lubrication type for a chain speed: I (manual/drip), II (bath/disc), III (stream).

    .. math:: v \le v_A(p) \Rightarrow \text{I};\quad v \le v_B(p) \Rightarrow
              \text{II};\quad \text{else III}

    Parameters
    ----------
    chain_speed : float or array_like
        [m/s].
    pitch : float or array_like
        [m]; limits interpolated linearly in pitch between the tabulated chains.

    Returns
    -------
    ndarray of str
        ``"I"``, ``"II"`` or ``"III"`` (ANSI types A, B, C).

    Notes
    -----
    Tabulated for ANSI 40…160 (12.7…50.8 mm); outside, the end values are used with a
    :class:`~chaindrive.errors.ValidityRangeWarning`.

    References
    ----------
    McGuire Bearing Co., "What are some guidelines for better chain performance?"
    (limits in ft/min by chain number); types as in the ANSI rating tables (Engineers
    Edge: Type A manual/drip, B bath/disc, C oil stream).

    Examples
    --------
    >>> str(lubrication_type(1.0, 0.0254)), str(lubrication_type(20.0, 0.0254))
    ('II', 'III')
    """
    v = check_nonnegative("chain_speed", chain_speed, "m/s")
    p = check_positive("pitch", pitch, "m") / _INCH
    tab = LUBRICATION_TYPES
    if np.any(p < tab["pitch_in"][0]) or np.any(p > tab["pitch_in"][-1]):
        warnings.warn(
            f"pitch = {np.round(p * 25.4, 3)} mm is outside the lubrication table "
            "(12.7…50.8 mm); the nearest tabulated chain is used",
            ValidityRangeWarning, stacklevel=2,
        )
    va = np.interp(p, tab["pitch_in"], tab["type_a_fpm"]) * _FPM
    vb = np.interp(p, tab["pitch_in"], tab["type_b_fpm"]) * _FPM
    return np.where(v <= va, "I", np.where(v <= vb, "II", "III"))


@dataclass
class Candidate(Result):
    """One chain that carries the load (result of :func:`select`).

    Attributes
    ----------
    chain : str
        Chain name.
    pitch : float
        [m].
    strands : int
    teeth_driving, teeth_driven : int
    chain_speed : float
        [m/s].
    rated_power : float
        ANSI/ACA rating of the chain (all strands) [W].
    design_power : float
        Power times service factor [W].
    power_margin : float
        ``rated_power / design_power`` [-] (>= 1).
    governing_limit : str
        ``"link_plate"`` or ``"roller_bushing"``.
    working_tension : float
        Design pull plus centrifugal tension [N].
    static_safety : float
        Breaking force / working tension [-].
    lubrication : str
        ANSI type ``"I"``, ``"II"`` or ``"III"``.
    notes : list of str
    """

    chain: str
    pitch: float
    strands: int
    teeth_driving: int
    teeth_driven: int
    chain_speed: float
    rated_power: float
    design_power: float
    power_margin: float
    governing_limit: str
    working_tension: float
    static_safety: float | None
    lubrication: str
    notes: list


def select(power, speed, ratio, *, service_factor=1.0, teeth_driving=17, family=None,
           strands=(1, 2, 3), min_static_safety=6.0, limit: int | None = None) -> list[Candidate]:
    r"""Roller chains that carry a power with the required safety, smallest first.

    .. math:: K_2 \min(H_1, H_2) \ge K_s P,\qquad
              \frac{F_B}{K_s P / v + q v^2} \ge S_{min}

    Parameters
    ----------
    power : float
        Transmitted power ``P > 0`` [W].
    speed : float
        Speed of the driving (small) sprocket [rad/s].
    ratio : float
        Speed ratio ``n1/n2 >= 1``; the driven wheel gets ``round(z1 · ratio)`` teeth.
    service_factor : float
        ``K_s >= 1`` (see :func:`chaindrive.drive.loads.service_factor`).
    teeth_driving : int
        Small-sprocket teeth (the ANSI tables are built on 17).
    family : {None, "ansi", "iso606"}
        Catalogue family; ``None`` takes both roller-chain families.
    strands : tuple of int
        Strand counts admitted.
    min_static_safety : float
        Required ``F_B / F`` (Diamond Chain: working load <= 1/6 of the breaking force).
    limit : int, optional
        Return at most this many candidates.

    Returns
    -------
    list of Candidate
        Sorted by pitch, then strands, then rated power.

    Raises
    ------
    InputError
        Non-positive power/speed, ratio < 1, service factor < 1.
    InfeasibleError
        No catalogue chain carries the load.

    Notes
    -----
    Only roller chains (ISO 606 and ANSI B29.1 families of
    :func:`chaindrive.chains.catalogue`). Chains without a mass per length are
    checked with the centrifugal tension omitted (noted in ``notes``).

    References
    ----------
    ACA rating method (this module); Shigley, 9th ed., §17-5 (selection procedure).

    Examples
    --------
    >>> best = select(15e3, 960 * 2 * np.pi / 60, 3.0, service_factor=1.3, family="iso606")[0]
    >>> best.chain, best.lubrication
    ('12B-2', 'II')
    """
    from ..chains import catalogue
    from ..errors import InfeasibleError

    P = float(check_positive("power", power, "W"))
    w = float(check_positive("speed", speed, "rad/s"))
    i = float(check_positive("ratio", ratio))
    if i < 1:
        raise InputError(f"ratio must be >= 1 (n_driving / n_driven), got {i:g}")
    ks = float(check_positive("service_factor", service_factor))
    if ks < 1:
        raise InputError(f"service_factor must be >= 1, got {ks:g}")
    z1 = int(check_teeth("teeth_driving", teeth_driving))
    z2 = int(round(z1 * i))
    if family not in (None, "ansi", "iso606"):
        raise UnknownNameError(f"unknown roller-chain family {family!r}; valid: None, 'ansi', 'iso606'")
    fams = ("iso606", "ansi") if family is None else (family,)
    design = P * ks
    out: list[Candidate] = []
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityRangeWarning)
        for fam in fams:
            for ch in catalogue(fam):
                if ch.strands not in strands or ch.strands > 4:
                    continue
                kp, kr = ansi_constants(ch.name)
                h1 = float(ansi_link_plate_power(z1, w, ch.pitch, kp))
                h2 = float(ansi_roller_bushing_power(z1, w, ch.pitch, kr))
                rated = multi_strand_factor(ch.strands) * min(h1, h2)
                if rated < design:
                    continue
                v = z1 * ch.pitch * w / (2 * np.pi)
                notes = []
                fc = 0.0
                if ch.mass_per_length is None:
                    notes.append("mass per length unknown: centrifugal tension omitted")
                else:
                    fc = ch.mass_per_length * v**2
                F = design / v + fc
                sf = None if ch.breaking_force is None else ch.breaking_force / F
                if sf is not None and sf < min_static_safety:
                    continue
                if sf is None:
                    notes.append("breaking force unknown: static safety not checked")
                if ch.family == "iso606" and "B" in ch.name:
                    notes.append("ANSI rating applied to an ISO B-series chain (approximation)")
                out.append(Candidate(
                    chain=ch.name, pitch=ch.pitch, strands=ch.strands, teeth_driving=z1,
                    teeth_driven=z2, chain_speed=v, rated_power=rated, design_power=design,
                    power_margin=rated / design,
                    governing_limit="link_plate" if h1 <= h2 else "roller_bushing",
                    working_tension=F, static_safety=sf,
                    lubrication=str(lubrication_type(v, ch.pitch)), notes=notes,
                ))
    if not out:
        raise InfeasibleError(
            f"no catalogue roller chain carries {design / 1e3:g} kW (design power) at "
            f"{w / _RPM:g} rpm with {z1} teeth; try more teeth, more strands or a lower speed"
        )
    out.sort(key=lambda c: (c.pitch, c.strands, c.rated_power))
    return out[:limit] if limit else out
