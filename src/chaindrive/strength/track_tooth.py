"""Strength of the tooth of a tracked vehicle's drive wheel (Sharipov).

Sharipov (Sharipov, *Design of tractor running systems*, p. 34): the tooth is checked
in bending and in contact; the design force is the whole track adhesion force carried
by one tooth, ``P_Р = P / i`` with ``P = 0.65 G_T φ`` (``φ = 1.0``, ``i`` = 1 or 2
toothed rims); in bending the force acts at the tooth tip (Fig. 13). Rims are of alloy
steel hardened to HRC 48…60. The figure and the section model are not on the page;
the models used here are:

* Bending: the tooth as a cantilever (Lewis-type) of rectangular section
  ``s × b`` at its narrowest root section, loaded at the tip by ``P_Р`` normal to
  the tooth centre line: ``σ = K_t 6 P_Р h / (b s²)``; the direct compressive
  component is neglected (conservative on the tensile side, as Lewis does).
* Section of a lantern-wheel tooth (:func:`track_tooth_section`): narrowest width on
  the line joining two neighbouring pin centres, ``s = t − 2 r_цо``, lever arm from
  that line to the tip circle, ``h = R_Г − R_о cos(π/z)``.
* Contact: Hertz line contact of the pin on the convex flank (radius ``t − r_цо``, the
  flank of :mod:`chaindrive.geometry.track_wheel`) or in the concave seat ``r_цо``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike

from .._finite import finite_guard
from .._results import Result, quantity
from .._typing import FloatOrArray
from .._validation import check_positive, check_range, check_teeth, warn_outside
from ..errors import InfeasibleError, InputError
from . import hertz

if TYPE_CHECKING:
    from ..geometry.track_wheel import TrackDriveWheel

__all__ = [
    "HARDNESS_RANGE",
    "DESIGN_WEIGHT_SHARE",
    "track_design_force",
    "track_tooth_section",
    "tooth_bending_stress",
    "pin_tooth_contact_stress",
    "check_hardness",
    "TrackToothResult",
    "track_tooth_check",
]

#: Surface hardness of the rims, Sharipov [HRC].
HARDNESS_RANGE = (48.0, 60.0)
#: The factor 0.65 of ``P = 0.65 G_T φ`` (Sharipov).
DESIGN_WEIGHT_SHARE = 0.65


def _out(x: ArrayLike) -> FloatOrArray:
    x = np.asarray(x, dtype=float)
    return float(x) if x.ndim == 0 else x


@finite_guard
def track_design_force(weight: ArrayLike, adhesion: ArrayLike = 1.0, rims: int = 1) -> FloatOrArray:
    r"""Design force on one tooth of a track drive wheel (Sharipov).

    .. math:: P_Р = \frac{P}{i},\qquad P = 0.65\, G_T\, \varphi

    The text (p. 34): «Расчетное усилие определяется из условия максимального
    сцепления гусеницы с грунтом и передачи всего усилия одним зубом: P_Р = P / i,
    где P = 0,65 G_T φ; i — число зубчатых венцов у ведущего колеса (i = 1 у
    одновенцового колеса и i = 2 у двухвенцового). Здесь φ = 1,0.» — the design force
    follows from the largest adhesion of *the track* with the ground, the whole force
    passed by one tooth (of each rim). So ``P`` is the force of one track (0.65 of the
    tractor's weight: the share one track can carry when the load shifts to it) and
    ``i`` counts the toothed rims of *one* drive wheel, not the tracks: a double-rim
    wheel shares ``P`` between two teeth, one per rim. The drive wheel's design torque is
    ``P R_о`` whatever ``i`` is.

    Parameters
    ----------
    weight : float or array_like
        Tractor weight ``G_T`` [N].
    adhesion : float or array_like
        Adhesion coefficient ``φ`` [-], ``0 < φ <= 1.5`` (Sharipov: 1.0).
    rims : int
        Number of toothed rims ``i``: 1 or 2.

    Returns
    -------
    float or ndarray
        Design force ``P_Р`` on one tooth [N].

    References
    ----------
    Sharipov, p. 34 (``P_Р = P / i``, ``P = 0.65 G_T φ``, ``φ = 1.0``).

    Examples
    --------
    >>> track_design_force(60e3, 1.0, 2)
    19500.0
    """
    g = check_positive("weight", weight, "N")
    phi = check_range("adhesion", adhesion, 0.0, 1.5, low_inclusive=False)
    rims_array = np.asarray(rims)
    if not ((rims_array == 1) | (rims_array == 2)).all():  # np.isin(rims, (1, 2)), without its overhead
        raise InputError(f"rims must be 1 or 2 (Sharipov: i = 1 single-rim, 2 double-rim wheel), got {rims!r}")
    return _out(DESIGN_WEIGHT_SHARE * g * phi / np.asarray(rims, dtype=float))


@finite_guard
def track_tooth_section(pitch: ArrayLike, teeth: ArrayLike, pin_seat_radius: ArrayLike,
                        tip_radius: ArrayLike) -> tuple[FloatOrArray, FloatOrArray]:
    r"""Root section width and lever arm of a lantern-wheel tooth.

    .. math:: s = t - 2 r_{цо},\qquad h = R_Г - R_о \cos(\pi/z),\quad
              R_о = \frac{t}{2\sin(\pi/z)}

    Parameters
    ----------
    pitch : float or array_like
        Track pitch ``t`` [m].
    teeth : int or array_like
        Number of teeth ``z >= 3``.
    pin_seat_radius : float or array_like
        ``r_цо`` [m].
    tip_radius : float or array_like
        ``R_Г`` [m].

    Returns
    -------
    thickness, lever_arm : float or ndarray
        ``s`` and ``h`` [m].

    Raises
    ------
    InfeasibleError
        Seats overlap (``s <= 0``) or the tip is inside the section line.

    Notes
    -----
    The seat arcs of two neighbouring pins come closest on the line joining the pin
    centres; the tooth is narrowest there and widens below it, so this section with
    the lever arm to the tip circle is the critical cantilever section (a simplification
    of Lewis' inscribed parabola for this flank shape).

    References
    ----------
    Geometry as :mod:`chaindrive.geometry.track_wheel` (Sharipov radii).

    Examples
    --------
    >>> s, h = track_tooth_section(0.17, 13, 0.03, 0.38018)
    >>> round(s * 1e3, 1), round(h * 1e3, 1)
    (110.0, 35.3)
    """
    t = check_positive("pitch", pitch, "m")
    z = check_teeth("teeth", teeth)
    rs = check_positive("pin_seat_radius", pin_seat_radius, "m")
    rt = check_positive("tip_radius", tip_radius, "m")
    s = t - 2 * rs
    if np.any(s <= 0):
        raise InfeasibleError("pin_seat_radius must be < pitch/2: neighbouring seats overlap (s = t - 2 r_seat <= 0)")
    r0 = t / (2 * np.sin(np.pi / z))
    h = rt - r0 * np.cos(np.pi / z)
    if np.any(h <= 0):
        raise InfeasibleError("tip_radius must exceed R_o cos(pi/z) (the tooth's root section line)")
    return _out(s), _out(h)


@finite_guard
def tooth_bending_stress(force: ArrayLike, lever_arm: ArrayLike, root_thickness: ArrayLike, tooth_width: ArrayLike,
                         stress_concentration: ArrayLike = 1.0) -> FloatOrArray:
    r"""Bending stress at the tooth root, cantilever (Lewis-type) with the force at the tip.

    .. math:: \sigma_F = K_t \frac{6 P h}{b s^2}

    Parameters
    ----------
    force : float or array_like
        Force at the tip normal to the tooth centre line ``P`` [N].
    lever_arm : float or array_like
        Distance from the root section to the force ``h`` [m].
    root_thickness : float or array_like
        Tooth thickness at the root section ``s`` [m].
    tooth_width : float or array_like
        Tooth (face) width ``b`` [m].
    stress_concentration : float or array_like
        Root fillet factor ``K_t >= 1`` [-] (1: plain beam).

    Returns
    -------
    float or ndarray
        ``σ_F`` [Pa].

    Notes
    -----
    Beam theory; valid while ``h`` is not small compared with ``s`` (stubby teeth are
    over-estimated). The compressive component of an inclined force is neglected.

    References
    ----------
    W. Lewis (1892), as in R. G. Budynas, J. K. Nisbett, *Shigley's Mechanical
    Engineering Design*, 9th ed., McGraw-Hill 2011, §14-1 ("The Lewis bending
    equation", ``σ = 6 W_t l / (F t²)`` before eq. (14-1)).

    Examples
    --------
    >>> round(tooth_bending_stress(19.5e3, 0.0337, 0.110, 0.05) / 1e6, 2)   # [MPa]
    6.52
    """
    p = check_positive("force", force, "N")
    h = check_positive("lever_arm", lever_arm, "m")
    s = check_positive("root_thickness", root_thickness, "m")
    b = check_positive("tooth_width", tooth_width, "m")
    k = check_range("stress_concentration", stress_concentration, 1.0, np.inf, high_inclusive=False)
    return _out(k * 6 * p * h / (b * s**2))


@finite_guard
def pin_tooth_contact_stress(force: ArrayLike, pin_radius: ArrayLike, profile_radius: ArrayLike,
                             contact_length: ArrayLike, *, contact: str = "convex",
                             elastic_modulus: float = hertz.STEEL_ELASTIC_MODULUS,
                             poisson_ratio: float = hertz.STEEL_POISSON_RATIO) -> FloatOrArray:
    r"""Hertz contact stress between a track pin and the wheel tooth.

    .. math:: \sigma_H = \sqrt{\frac{P E^*}{\pi b \rho}},\quad \frac{1}{\rho} = \frac{1}{r_ц} \pm \frac{1}{r}

    Parameters
    ----------
    force : float or array_like
        ``P_Р`` [N].
    pin_radius : float or array_like
        ``r_ц`` [m].
    profile_radius : float or array_like
        Tooth profile radius [m]: flank radius ``t − r_цо`` (``contact="convex"``) or
        seat radius ``r_цо`` (``"concave"``).
    contact_length : float or array_like
        Contact length, the tooth width ``b`` [m].
    contact : {"convex", "concave"}
    elastic_modulus, poisson_ratio : float
        Both bodies [Pa, -].

    Returns
    -------
    float or ndarray
        ``σ_H`` [Pa].

    References
    ----------
    Sharipov, p. 34 (check in contact); Johnson 1985 §4.3 eq. (4.45).

    Examples
    --------
    >>> round(pin_tooth_contact_stress(19.5e3, 0.025, 0.14, 0.05) / 1e6, 1)
    821.7
    """
    rho = hertz.reduced_radius(pin_radius, profile_radius, contact)
    es = hertz.effective_modulus(elastic_modulus, poisson_ratio)
    hertz.warn_conformal(hertz.hertz_line_half_width(force, contact_length, rho, es), pin_radius, "pin-tooth contact")
    return hertz.hertz_line_pressure(force, contact_length, rho, es)


def check_hardness(hardness: ArrayLike) -> FloatOrArray:
    """Check a surface hardness [HRC] against Sharipov's 48…60; warn outside, raise if not in 20…70.

    Examples
    --------
    >>> check_hardness(55)
    55.0
    """
    h = check_range("hardness", hardness, 20.0, 70.0, unit="HRC")
    warn_outside("hardness", h, *HARDNESS_RANGE, "Sharipov (rims hardened to HRC 48...60)")
    return _out(h)


@dataclass(frozen=True)
class TrackToothResult(Result):
    """Tooth check of a track drive wheel (SI units).

    ``design_force`` P_Р [N], ``root_thickness`` s [m], ``lever_arm`` h [m],
    ``bending_stress`` [Pa], ``contact_stress`` [Pa], ``reduced_radius`` ρ [m],
    ``bending_safety`` and ``contact_safety`` allowable/actual [-] (None without an
    allowable), ``passes`` all safety factors >= 1, ``hardness`` [HRC], ``sources``;
    ``wheel_force`` ``P = 0.65 G_T φ``, the adhesion force of the track the wheel
    drives [N]; ``rims`` ``i``; ``pitch_radius`` ``R_о`` [m]; ``design_torque``
    ``P R_о``, the torque on the drive wheel at full adhesion [N·m]; ``rim_torque``
    ``P_Р R_о``, the torque one rim passes to the hub (its bolts) [N·m].
    """

    design_force: float = quantity("N")
    root_thickness: float = quantity("m")
    lever_arm: float = quantity("m")
    bending_stress: float = quantity("Pa")
    contact_stress: float = quantity("Pa")
    reduced_radius: float = quantity("m")
    bending_safety: float | None = quantity("1")
    contact_safety: float | None = quantity("1")
    hardness: float | None = quantity("HRC")
    passes: bool
    sources: dict[str, str]
    wheel_force: float = quantity("N", default=0.0)
    rims: int = quantity("1", default=1)
    pitch_radius: float = quantity("m", default=0.0)
    design_torque: float = quantity("N*m", default=0.0)
    rim_torque: float = quantity("N*m", default=0.0)


@finite_guard
def track_tooth_check(wheel: TrackDriveWheel, weight: float, tooth_width: float, *, adhesion: float = 1.0,
                      rims: int = 1, hardness: float | None = None, allowable_bending: float | None = None,
                      allowable_contact: float | None = None, contact: str = "convex",
                      stress_concentration: float = 1.0) -> TrackToothResult:
    """Bending and contact check of a tooth of a :class:`~chaindrive.geometry.track_wheel.TrackDriveWheel`.

    Parameters
    ----------
    wheel : TrackDriveWheel
        Geometry (pitch, teeth, pin radius, seat and tip radii).
    weight : float
        Tractor weight ``G_T`` [N].
    tooth_width : float
        Tooth width ``b`` (also the contact length) [m].
    adhesion, rims : float, int
        ``φ`` and ``i`` of :func:`track_design_force`.
    hardness : float, optional
        Surface hardness [HRC]; outside 48…60 warns.
    allowable_bending, allowable_contact : float, optional
        User allowable stresses [Pa] for the safety factors.
    contact : {"convex", "concave"}
        Pin on the flank (radius ``t − r_цо``, default, the higher stress) or in the seat.
    stress_concentration : float
        Root fillet factor ``K_t`` [-].

    Examples
    --------
    >>> from chaindrive.geometry.track_wheel import TrackDriveWheel
    >>> w = TrackDriveWheel(pitch=0.17, teeth=13, pin_radius=0.025, link="cast")
    >>> r = track_tooth_check(w, 60e3, 0.05, rims=2, hardness=52,
    ...                       allowable_bending=400e6, allowable_contact=1200e6)
    >>> round(r.bending_stress / 1e6, 2), round(r.contact_stress / 1e6, 1), r.passes
    (6.83, 821.7, True)
    """
    d = wheel.dimensions()
    p = float(track_design_force(weight, adhesion, rims))
    s, h = (float(v) for v in track_tooth_section(d.pitch, d.teeth, d.pin_seat_radius, d.tip_radius))
    sb = float(tooth_bending_stress(p, h, s, tooth_width, stress_concentration))
    prof = d.flank_radius if contact == "convex" else d.pin_seat_radius
    rho = float(hertz.reduced_radius(d.pin_radius, prof, contact))
    sh = float(pin_tooth_contact_stress(p, d.pin_radius, prof, tooth_width, contact=contact))
    hrc = None if hardness is None else float(check_hardness(hardness))
    fb = None if allowable_bending is None else float(check_positive("allowable_bending", allowable_bending, "Pa")) / sb
    fc = None if allowable_contact is None else float(check_positive("allowable_contact", allowable_contact, "Pa")) / sh
    passes = all(f is None or f >= 1.0 for f in (fb, fc))
    r0 = float(d.pitch_radius)
    return TrackToothResult(
        design_force=p, root_thickness=s, lever_arm=h, bending_stress=sb, contact_stress=sh,
        reduced_radius=rho, bending_safety=fb, contact_safety=fc, hardness=hrc, passes=passes,
        wheel_force=p * int(rims), rims=int(rims), pitch_radius=r0, design_torque=p * int(rims) * r0,
        rim_torque=p * r0,
        sources={
            "design_force": "Sharipov p. 34: P_P = P / i, P = 0.65 G_T phi, i the toothed rims of the wheel",
            "design_torque": "P R_o: the whole track's adhesion force on the drive wheel (all its rims)",
            "bending_stress": "cantilever (Lewis-type) sigma = K_t 6 P h / (b s^2), Shigley 9th ed. 14-1",
            "section": "s = t - 2 r_seat on the pin-centre line, h = R_tip - R_o cos(pi/z)",
            "contact_stress": "Hertz line contact, Johnson 1985 4.3 eq. (4.45)",
            "hardness": "Sharipov: HRC 48...60",
        },
    )
