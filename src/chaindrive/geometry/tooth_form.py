"""Sprocket tooth forms and outlines: the ASME B29.1 tooth form (:func:`ansi_tooth_form`), the
ISO 606 tooth gap (:func:`iso_tooth_form`) and the closed outline of a sprocket
(:func:`sprocket_outline`, ``method=`` registry :data:`TOOTH_FORMS`)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike

from .._docs import Fragments
from .._finite import finite_guard
from .._registry import Registry
from .._results import Result, quantity
from .._validation import as_float_array, check_positive
from ..errors import InfeasibleError, InputError
from ..limits import MAX_TEETH
from .iso606 import (
    _INCH,
    _flank_radius_range,
    _roller,
    _seating_angle_range,
    _teeth,
    _tip_diameter_range,
    seating_radius_limits,
    tip_diameter_limits,
)
from .outline import Arc, Line, Outline, _drop_short, _repeat, circle_intersections

if TYPE_CHECKING:

    pass

__all__ = [
    "ansi_tooth_form",
    "AnsiToothForm",
    "iso_tooth_form",
    "IsoToothForm",
    "sprocket_outline",
    "TOOTH_FORMS",
]


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
def _convex_flank_to_tip(centre, radius, start_angle, tip_radius, half_angle):
    """Walk a convex flank circle clockwise from ``start_angle`` until the tip circle or the
    tooth centreline (polar angle π/2 − half_angle), whichever comes first (internal).

    Returns (flank_tip_angle_about_centre, tip_point, pointed).
    """
    centre = np.asarray(centre, float)
    cands = []
    hit = circle_intersections(centre, radius, (0.0, 0.0), tip_radius)
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


#: The sprocket's chain and tooth count, described once (:mod:`chaindrive._docs`).
_DOCS = Fragments(sprocket_chain="""
    pitch : float
        Chain pitch ``p`` [m].
    teeth : int
        Number of teeth ``z`` (>= 9).
    roller_diameter : float
        Roller diameter ``d1`` [m].
""")


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
@_DOCS
def sprocket_outline(pitch: float, teeth: int, roller_diameter: float, *, method: str = "iso606",
                     form: str | None = None, tip_diameter: float | None = None) -> Outline:
    """Closed outline of a whole sprocket (lines and arcs) for the chosen tooth form.

    Parameters
    ----------
    %(sprocket_chain)s
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
