r"""Kinematics of a chain running onto (or off) a polygonal wheel: free and guided entry.

This is the public layer over :mod:`~chaindrive.kinematics.solver` (general mechanism)
and :mod:`~chaindrive.kinematics.paper` (Dolipiński et al.'s closed forms, corrected).

Sketch and definitions (SI units)::

         y ^
           |  S_prev   S                        G = (l, H)
           |     o-----o.                        *=====o=====o====  guide line y = H
           |    /        ` - . _  free span    / |        chain moves towards -x
           |   /  R             ` - . _ N o   /  |
           |  /                         `-.  /   |
      -----O--------------------------------------+-----> x
           |<-------------------- l ------------>|
           O: wheel axis, ω counter-clockwise (the top moves towards -x)

* ``H`` (``guide_height``): distance of the guide line from the wheel axis
  (``H >= 0``, above the axis).
* ``l`` (``guide_end_distance``): distance of the guide end ``G`` from the wheel axis
  measured along the guide line, i.e. from the foot of the perpendicular dropped from
  the axis onto the guide line. ``G = (l, H)``; the chain is in the guide for ``x >= l``.
* ``φ = ωt``: wheel angle; results cover one period ``0 <= φ <= 2π/z``.
* ``x``: displacement of the chain in the guide (or of the free span) towards the wheel;
  ``v = dx/dt``, ``a = dv/dt``.
* Phase ``φ = 0`` (as in Dolipiński et al.'s figures): free, chordal and custom-``H`` entry:
  the link ``t + d`` (roller chain: a link) is centred on the top of the wheel, i.e. its
  leading hinge is at ``δ1/2`` from the top on the side of the incoming chain;
  tangential entry: a hinge (the one followed by the link ``t + d``) is at the top.

Named entries: ``"free"`` (no guide; Dolipiński et al. eqs 1-13), ``"chordal"``
(``H = R cos(δ1/2)``, eqs 14-25), ``"tangential"`` (``H = R``, eqs 26-43), or any
``guide_height`` (``entry="guided"``).

Models (``model=``):

``"exact"`` (default)
    Rigid links, seated hinges on the polygon vertices, a *taut* straight span from the
    last seated hinge to the guide end with the unseated hinges on it, the chain lying
    on the guide line beyond the guide end and wrapping over the guide end (an edge of
    negligible radius). A hinge seats when it reaches the span (found by root finding);
    the span then shortens by exactly the seated link, so ``x`` and ``v`` are
    continuous. Free entry is the same mechanism with ``G`` at infinity.
``"paper"``
    Dolipiński et al.'s own simplified mechanism, one mechanism for both guides: a rigid
    rod of fixed length from the seated hinge to a point sliding on the guide line,
    shortened by exactly one link when the next hinge seats (the rod collinear with
    the chord to it). Tangential entry: the closed forms (26)-(43) with the printed
    errors corrected (their switches are the seatings, eqs 29 and 34). Chordal entry:
    the same rod mechanism solved by :func:`~chaindrive.kinematics.solver.rod_seating_schedule`
    and :func:`~chaindrive.kinematics.solver.rod_entry` (in the worked case the second
    hinge seats at ``φ = 0.3741950302`` rad, not at ``π/z``); ``x`` and ``v`` are
    continuous and the chain advances ``2t`` per period. Free entry: eqs (1)-(13).
``"as_printed"``
    The mechanisms as the paper prints them: the chordal entry's closed forms (14)-(25),
    corrected, with the rod switched at ``π/z`` (a reset, not a seating: ``x`` is made
    continuous by a constant, ``v`` jumps by 3.7 mm/s in the worked case and the chain
    advances 2.3 µm more than ``2t`` per period); free and tangential entry as ``"paper"``.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from functools import lru_cache
from typing import TYPE_CHECKING, Any, cast

import numpy as np
from numpy.typing import ArrayLike

from .._deprecation import renamed_attributes as _renamed_attributes
from .._finite import finite_guard
from .._registry import Registry
from .._results import quantity
from .._validation import as_float_array, check_nonnegative, check_positive, check_teeth
from ..errors import InfeasibleError, InputError
from ..geometry.polygon import bi_regular_polygon, roller_chain_pitch_radius
from . import paper as _paper
from .histories import PaperEntry, PeriodMotion
from .solver import (
    GuideEnd,
    WheelPolygon,
    _taut_extremes,
    _taut_rates,
    _taut_span_length,
    rod_entry,
    rod_seating_schedule,
    taut_entry,
    taut_seating_angles,
)

if TYPE_CHECKING:
    from ..chains import Chain

__all__ = [
    "EntryKinematics",
    "chain_entry",
    "chain_entry_for",
    "dolipinski_worked_case",
    "ENTRIES",
    "MODELS",
    "SUMMARY_KEYS",
    "SUMMARY_QUANTITIES",
]

#: Named entry types.
ENTRIES = Registry("entry")
for _name in ("free", "chordal", "tangential", "guided"):
    ENTRIES.add(_name, _name)

#: Models of the guided mechanism.
MODELS = Registry("model")

#: Keys of :attr:`EntryKinematics.summary` required by the CLI's JSON.
SUMMARY_KEYS = (
    "v_mean",
    "v_min",
    "v_max",
    "nonuniformity",
    "a_min",
    "a_max",
    "sign_change_at_period_end",
    "transverse_throw",
)

#: Every key of :attr:`EntryKinematics.summary` (and of the crawler's): its label and SI
#: unit ("1": a ratio or a count; "": a yes/no), declared where the summary is made, for
#: presenters (the studio's expert pages, the command line).
SUMMARY_QUANTITIES: dict[str, tuple[str, str]] = {
    "v_mean": ("mean chain speed", "m/s"),
    "v_min": ("minimum chain speed", "m/s"),
    "v_max": ("maximum chain speed", "m/s"),
    "nonuniformity": ("speed non-uniformity (vmax − vmin)/vmean", "1"),
    "a_min": ("minimum acceleration", "m/s^2"),
    "a_max": ("maximum acceleration", "m/s^2"),
    "a_abs_max": ("largest |acceleration|", "m/s^2"),
    "sign_change_at_period_end": ("acceleration changes sign at the period end", ""),
    "transverse_throw": ("transverse throw of the span", "m"),
    "advance_per_period": ("chain advance per tooth period", "m"),
    "a_end_left": ("acceleration just before the period end", "m/s^2"),
    "a_end_right": ("acceleration just after the period start", "m/s^2"),
    "a_jump_at_period_end": ("acceleration jump at the period end", "m/s^2"),
    "a_jump_max": ("largest acceleration jump (seatings)", "m/s^2"),
    "sign_changing_jumps": ("acceleration jumps that change sign", "1"),
    "psi_v_min": ("sprocket angle of the minimum speed", "rad"),
    "peak_deviation": ("largest deviation from the mean speed", "m/s"),
    "cam_stiffness": ("stiffness at the cam", "N/m"),
    "force_min": ("cam force minimum (about the mean)", "N"),
    "force_max": ("cam force maximum (about the mean)", "N"),
    "force_range": ("cam force range", "N"),
    "cam_force_max": ("cam force maximum (with the traction force)", "N"),
    "cam_pushing_off_max": ("pushing-off force on the guide at the cam, P tan α", "N"),
    "guide_reaction_max": ("largest guide reaction at the guide end, T tan φ1", "N"),
}


@dataclass(frozen=True)
class EntryKinematics(PeriodMotion):
    """Kinematics of the chain over the requested wheel angles (the fields of
    :class:`~chaindrive.kinematics.histories.PeriodMotion` first).

    Attributes
    ----------
    phi : ndarray
        Wheel angles ``φ`` [rad].
    x : ndarray
        Chain displacement towards the wheel, ``x(0) = 0`` [m].
    velocity : ndarray
        Chain velocity ``v`` [m/s].
    acceleration : ndarray
        Chain acceleration ``a`` [m/s²].
    transverse_position, transverse_velocity, transverse_acceleration : ndarray or None
        Free entry only: height of the span above the axis [m], its rate [m/s] and
        acceleration [m/s²] (Dolipiński et al. eqs 3-4, 12-13); ``None`` for guided entry (the
        chain in the guide has no transverse motion).
    summary : dict
        ``v_mean``, ``v_min``, ``v_max`` [m/s], ``nonuniformity`` [-], ``a_min``,
        ``a_max`` [m/s²], ``sign_change_at_period_end`` (bool: the one-sided limits of
        ``a`` at the period end have opposite signs, neither zero; a continuous passage
        through zero does not count), ``transverse_throw`` [m] (free entry:
        ``R(1 - cos(δ1/2))``; guided entry: 0, the chain in the guide does not move
        sideways),
        plus ``advance_per_period`` [m], ``a_end_left``/``a_end_right`` (acceleration
        just before the end / just after the start of the period) [m/s²],
        ``a_abs_max`` [m/s²], ``a_jump_at_period_end`` [m/s²]. Computed on a dense
        internal grid including both sides of every seating, not on ``phi``.
    entry, model : str
        Entry type and model.
    chain_type : str
        ``"link"`` or ``"roller"``.
    pitch, radius, teeth, angular_velocity, period
        ``t`` (``p``), ``R`` [m], ``z``, ``ω`` [rad/s], ``2π/z`` [rad] (:class:`PeriodMotion`).
    bar_diameter : float
        ``d`` [m] (0 for a roller chain).
    delta1, delta2 : float
        Central angles [rad].
    guide_height, guide_end_distance : float or None
        ``H``, ``l`` [m].
    seating_angles : ndarray
        Wheel angles of the seatings inside ``[0, 2π/z)`` (exact model, and tangential
        paper model ``φ_g1, φ_g2``) [rad].
    """

    phi: np.ndarray = quantity("rad")
    x: np.ndarray = quantity("m")
    transverse_position: np.ndarray | None = quantity("m")
    transverse_velocity: np.ndarray | None = quantity("m/s")
    transverse_acceleration: np.ndarray | None = quantity("m/s^2")
    entry: str
    model: str
    chain_type: str
    bar_diameter: float = quantity("m")
    delta1: float = quantity("rad")
    delta2: float = quantity("rad")
    guide_height: float | None = quantity("m")
    guide_end_distance: float | None = quantity("m")
    seating_angles: np.ndarray = quantity("rad", default_factory=lambda: np.zeros(0))


@dataclass(frozen=True)
class _Case:
    roller: bool
    t: float
    d: float
    z: int
    R: float
    d1: float
    d2: float
    w: float
    entry: str
    H: float | None
    l: float | None

    @property
    def period(self) -> float:
        return 2.0 * np.pi / self.z

    def polygon(self) -> WheelPolygon:
        if self.roller:
            phase = 0.0 if self.entry == "tangential" else 0.5 * self.d1
            return WheelPolygon(self.R, (self.t,), (self.d1,), phase)
        if self.entry == "tangential":
            return WheelPolygon(self.R, (self.t + self.d, self.t - self.d), (self.d1, self.d2), 0.0)
        return WheelPolygon(self.R, (self.t - self.d, self.t + self.d), (self.d2, self.d1), 0.5 * self.d1)

    def guide_end_distance(self) -> float:
        """``l`` [m]; an :class:`InputError` if a guided entry was built without it."""
        if self.l is None:
            raise InputError(f"entry={self.entry!r} needs guide_end_distance [m] (0 < l < inf)")
        return self.l

    def guide_height(self) -> float:
        """``H`` [m]; an :class:`InputError` if a guided entry was built without it."""
        if self.H is None:
            raise InputError(f"entry={self.entry!r} needs guide_height [m] (0 <= H < inf)")
        return self.H

    def guide(self) -> GuideEnd | None:
        return None if self.entry == "free" else (self.guide_end_distance(), self.guide_height())


# ----------------------------------------------------------------------------- models


@MODELS.register("exact")
def _exact(case: _Case, phi):
    poly = case.polygon()
    guide = case.guide()
    seats = _checked_seats(case)
    r = taut_entry(poly, phi, case.w, guide, seats)
    return dataclasses.replace(r, seats=_period_seats(case, seats), advance=poly.advance)


def _period_seats(case: _Case, seats: np.ndarray) -> np.ndarray:
    """The seating angles within one period, sorted (the exact model's ``seats``)."""
    T = case.period
    # np.sort(np.where(np.abs(s - T) <= 1e-12, 0.0, s)) of the one or two seatings, in Python floats
    # (np.isclose(s, T, rtol=0, atol=1e-12) written out)
    return np.array(sorted(0.0 if abs(x - T) <= 1e-12 else x for x in np.mod(seats[:-1], T).tolist()))


@lru_cache(maxsize=64)
def _checked_seats(case: _Case) -> np.ndarray:
    """Seating angles of ``case`` (and the reach check of a guided entry), once per case.

    They do not depend on the wheel angles asked for, and one entry solution asks for
    them several times (the period grid, the one-sided limits at the seatings).
    """
    poly = case.polygon()
    guide = case.guide()
    seats = taut_seating_angles(poly, guide)
    if guide is not None:
        _check_reach(case, poly, seats)
    seats = np.array(seats, dtype=float)
    seats.flags.writeable = False
    return seats


def _check_reach(case, poly, seats):
    """At every instant the free span must hold at least one whole (longest) link."""
    grid = np.linspace(seats[0], seats[-1], 721)
    longest = max(poly.links)
    # every 20th point first: the span changes by at most R per radian (|d|G - S|/dφ| <= |dS/dφ|),
    # so clear of the longest link there by R times their step, it is clear at every point
    coarse = grid[::20]
    if np.min(_taut_span_length(poly, coarse, case.guide(), seats)) - poly.radius * (coarse[1] - coarse[0]) >= longest:
        return
    span = _taut_span_length(poly, grid, case.guide(), seats)
    if np.min(span) < longest:
        raise InfeasibleError(
            f"the free span shrinks to {np.min(span):.6g} m, shorter than one link "
            f"({longest:.6g} m)"
        )


@lru_cache(maxsize=64)
def _chordal_rod_schedule(case: _Case) -> tuple[tuple[float, int, float], ...]:
    """The consistent rod schedule of the chordal entry (seatings, not the printed reset)."""
    return tuple(rod_seating_schedule(case.polygon(), _guide_end(case)))


def _guide_end(case: _Case) -> GuideEnd:
    return (case.guide_end_distance(), case.guide_height())


def _chordal_rod(case: _Case, phi):
    sched = list(_chordal_rod_schedule(case))
    r = rod_entry(case.polygon(), phi, case.w, _guide_end(case), sched, continuous=False)
    return PaperEntry(x=r.x, velocity=r.velocity, acceleration=r.acceleration, advance=r.advance,
                      seats=np.array([p for p, _, _ in sched]))


@MODELS.register("paper")
def _paper_model(case: _Case, phi):
    if case.entry == "chordal":
        r = _chordal_rod(case, phi)
        for key in ("x", "velocity", "acceleration"):
            if not np.all(np.isfinite(r[key])):
                raise InfeasibleError("the rod of the paper's mechanism cannot reach the guide line")
        return r
    return _as_printed_model(case, phi)


@MODELS.register("as_printed")
def _as_printed_model(case: _Case, phi):
    t, d = (case.t, 0.0) if case.roller else (case.t, case.d)
    d1, d2 = case.d1, (case.d1 if case.roller else case.d2)
    with np.errstate(invalid="ignore"):
        if case.entry == "free":
            r = _paper.paper_free_entry(phi, case.R, d1, d2, case.w, roller=case.roller)
            r = dataclasses.replace(r, seats=np.array([0.0]) if case.roller else np.array([0.0, 0.5 * (d1 + d2)]))
        elif case.entry == "chordal":
            r = _paper.paper_chordal_entry(phi, t, d, case.R, d1, d2, case.guide_end_distance(), case.w,
                                           roller=case.roller)
            r = dataclasses.replace(r, seats=np.array([0.0]) if case.roller else np.array([0.0, 0.5 * (d1 + d2)]))
        elif case.entry == "tangential":
            r = _paper.paper_tangential_entry(phi, t, d, case.R, d1, d2, case.guide_end_distance(), case.w,
                                              roller=case.roller)
            g1, g2 = r.limit_angles or (0.0, None)
            if case.roller or g2 is None:
                r = dataclasses.replace(r, seats=np.array([g1]))
            elif not (g1 < d1 < g2 < d1 + d2):
                raise InfeasibleError("limit angles out of order")
            else:
                r = dataclasses.replace(r, seats=np.array([g1, g2]))
        else:
            raise InputError(
                "model='paper' and 'as_printed' cover entry 'free', 'chordal' and 'tangential' only "
                "(the paper gives no closed form for another guide_height); use model='exact'"
            )
    for key in ("x", "velocity", "acceleration"):
        if not np.all(np.isfinite(r[key])):
            raise InfeasibleError("the rod of the paper's mechanism cannot reach the guide line")
    return r


# ----------------------------------------------------------------------------- public API


def _make_case(pitch, teeth, angular_velocity, bar_diameter, entry, guide_end_distance,
               guide_height) -> _Case:
    t = float(check_positive("pitch", pitch, "m"))
    z = int(check_teeth("teeth", teeth))
    w = float(check_positive("angular_velocity", angular_velocity, "rad/s"))
    roller = bar_diameter is None
    if roller:
        d = 0.0
        R = float(roller_chain_pitch_radius(t, z))
        d1 = d2 = 2.0 * np.pi / z
    else:
        d = float(check_nonnegative("bar_diameter", bar_diameter, "m"))
        if d >= t:
            raise InputError(f"bar_diameter must lie in [0, pitch) = [0, {t:g}) m, got {d:g}")
        R, d1, d2 = (float(v) for v in bi_regular_polygon(t + d, t - d, z))
    if entry is None:
        entry = "free" if guide_height is None else "guided"
    entry = ENTRIES.get(entry)
    if guide_height is not None:
        if entry in ("chordal", "tangential"):
            raise InputError(
                f"give either entry='{entry}' (which fixes the guide height) or guide_height, not both"
            )
        entry = "guided"
    H = None
    if entry == "chordal":
        H = R * np.cos(0.5 * d1)
    elif entry == "tangential":
        H = R
    elif entry == "guided":
        if guide_height is None:
            raise InputError("entry='guided' needs guide_height [m], 0 <= guide_height < inf")
        H = float(check_nonnegative("guide_height", guide_height, "m"))
    l = None
    if entry != "free":
        if guide_end_distance is None:
            raise InputError(f"entry={entry!r} needs guide_end_distance [m] (0 < l < inf)")
        l = float(check_positive("guide_end_distance", guide_end_distance, "m"))
    return _Case(roller, t, d, z, R, d1, d2, w, entry, H, l)


def _run(case: _Case, model: str, phi):
    fn = MODELS.get(model)
    return fn(case, phi)


def _feasible(case, model) -> bool:
    try:
        _run(case, model, np.linspace(0.0, case.period, 64))
    except InfeasibleError:
        return False
    return True


def _bisect(pred, lo, hi, n=50):
    """Smallest value in [lo, hi] with pred true (pred(hi) true, monotone)."""
    for _ in range(n):
        mid = 0.5 * (lo + hi)
        if pred(mid):
            hi = mid
        else:
            lo = mid
    return hi


def _explain_infeasible(case: _Case, model: str, exc: Exception):
    from dataclasses import replace

    reason = str(exc)
    hi = case.R + 20 * (case.t + case.d)
    if not _feasible(replace(case, l=hi), model):
        raise InfeasibleError(f"infeasible mechanism: {reason}") from None
    l_min = _bisect(lambda v: _feasible(replace(case, l=v), model), 0.0, hi)
    msg = (
        f"guide_end_distance = {case.l:g} m is too close to the wheel for the chain to reach "
        f"the guide end ({reason}); with guide_height = {case.H:g} m it must be > {l_min:.6g} m"
    )
    if case.entry == "guided":
        Hhi = case.R + 20 * (case.t + case.d)
        if _feasible(replace(case, H=Hhi), model):
            H_min = _bisect(lambda v: _feasible(replace(case, H=v), model), 0.0, Hhi)
            msg += (
                f"; or, with guide_end_distance = {case.l:g} m, guide_height must lie in "
                f"[{H_min:.6g}, inf) m"
            )
    raise InfeasibleError(msg) from None


def _summary(case: _Case, model: str, seats, first: np.ndarray | None = None) -> Any:
    """The summary of the entry (seats: the model's seating angles in one period). With
    ``first`` (the exact model): also the entry at those angles, as ``(summary, entry)``.

    The exact model's extremes are its true ones (:func:`~chaindrive.kinematics.solver._taut_extremes`:
    the ends of each stretch between seatings and the roots of the analytic derivative);
    another model's are taken on a grid of 4,000 angles a period and beside each seating."""
    T = case.period
    eps = 1e-9 * T
    s_in = np.asarray(seats, dtype=float)
    s_in = s_in[(s_in > eps) & (s_in < T - eps)]
    # one-sided limits of the acceleration at the period end (left) and start (right), and
    # at the seatings (and resets) inside the period
    ends = np.array([T - 1e-12 * T, 1e-12 * T])
    head = None
    y_range: tuple[float, float] | None = None
    if model == "exact":
        poly = case.polygon()
        guide = case.guide()
        full = _checked_seats(case)
        (v_lo, v_hi), (a_lo, a_hi), y_range = _taut_extremes(poly, guide, full)
        w = case.w
        v_range, a_range = (w * v_lo, w * v_hi), (w * w * a_lo, w * w * a_hi)
        limits = _taut_rates(poly, np.concatenate([ends, s_in - 1e-12 * T, s_in + 1e-12 * T]), w, guide, full)[1]
        head = _run(case, model, first) if first is not None else None
        advance = float(poly.advance)
    else:
        base = np.linspace(0.0, T, 4001)
        extra = np.concatenate([seats - eps, seats + eps, [T - eps, eps, T - 1e-4 * T, 1e-4 * T]])
        extra = extra[(extra > 0) & (extra < T)]
        grid = np.concatenate([base[:-1], extra])  # unsorted: only its extremes are taken
        r = _run(case, model, grid)
        limits = np.concatenate([_run(case, model, ends[:1])["acceleration"],
                                 _run(case, model, ends[1:])["acceleration"]]
                                + ([_run(case, model, s_in - 1e-12 * T)["acceleration"],
                                    _run(case, model, s_in + 1e-12 * T)["acceleration"]] if s_in.size else []))
        v, a, y = r.velocity, r.acceleration, getattr(r, "y", None)
        v_range, a_range = (float(np.min(v)), float(np.max(v))), (float(np.min(a)), float(np.max(a)))
        if y is not None:
            y_range = (float(np.min(y)), float(np.max(y)))
        advance = float(r.advance)
    v_mean = advance / (T / case.w)
    a_left, a_right = float(limits[0]), float(limits[1])
    amax = max(abs(a_range[0]), abs(a_range[1]))
    tol = 1e-6 * amax
    sign_change = bool((abs(a_left) > tol) and (abs(a_right) > tol) and (a_left * a_right < 0))
    jump_list = [a_right - a_left]
    sign_jumps = np.zeros(0, dtype=bool)
    if s_in.size:
        lo, hi = limits[2:2 + s_in.size], limits[2 + s_in.size:]
        jump_list += list(hi - lo)
        sign_jumps = (np.abs(lo) > tol) & (np.abs(hi) > tol) & (lo * hi < 0)
    jumps = np.asarray(jump_list)
    if case.entry == "free":
        throw = float(case.R - case.R * np.cos(0.5 * max(case.d1, case.d2)))
        y_range = cast(tuple, y_range)  # free entry: every model gives the transverse motion
        throw = max(throw, y_range[1] - y_range[0])
    else:
        throw = 0.0
    summary = {
        "v_mean": v_mean,
        "v_min": v_range[0],
        "v_max": v_range[1],
        "nonuniformity": (v_range[1] - v_range[0]) / v_mean,
        "a_min": a_range[0],
        "a_max": a_range[1],
        "sign_change_at_period_end": sign_change,
        "transverse_throw": throw,
        "advance_per_period": advance,
        "a_end_left": a_left,
        "a_end_right": a_right,
        "a_abs_max": amax,
        "a_jump_at_period_end": a_right - a_left,
        "a_jump_max": float(np.max(np.abs(jumps))),
        "sign_changing_jumps": int(np.sum(sign_jumps) + sign_change),
    }
    return summary if first is None else (summary, head)


@finite_guard
def chain_entry(
    pitch: float,
    teeth: int,
    angular_velocity: float,
    *,
    bar_diameter: float | None=None,
    entry: str | None = "free",
    guide_end_distance: float | None=None,
    guide_height: float | None=None,
    model: str = "exact",
    points: int = 361,
    phi: ArrayLike | None=None,
) -> EntryKinematics:
    r"""Position, velocity and acceleration of a chain entering a wheel, over one period.

    .. math::
        v_{free} = ωR\cos β,\qquad v_{guided} = -ω\,u\cdot\frac{dS}{dφ}
        \ (\text{exact}),\qquad \bar v = \frac{z ω}{2π}\,\sum \text{links}

    Parameters
    ----------
    pitch : float
        Chain pitch: inner link length ``t`` of a round link chain, or roller-chain
        pitch ``p`` [m].
    teeth : int
        Number of pockets/teeth ``z >= 3`` [-].
    angular_velocity : float
        Wheel speed ``ω > 0`` [rad/s].
    bar_diameter : float, optional
        Bar diameter ``d`` of a round link chain, ``0 <= d < t`` [m]; ``None`` for a
        roller chain (regular polygon).
    entry : {"free", "chordal", "tangential", "guided"}
        Entry type; ``"guided"`` (implied by ``guide_height``) takes ``guide_height``.
    guide_end_distance : float, optional
        Distance ``l`` of the guide end from the wheel axis along the guide line [m];
        required for guided entry.
    guide_height : float, optional
        Height ``H >= 0`` of the guide line above the wheel axis [m] (custom guide).
    model : {"exact", "paper", "as_printed"}
        Mechanism (see module docstring).
    points : int
        Number of samples over ``0 <= φ <= 2π/z`` (ignored if ``phi`` is given).
    phi : float or array_like, optional
        Wheel angles to evaluate [rad] (any range; results are periodic with ``2π/z``
        apart from ``x``, which grows by the advance per period).

    Returns
    -------
    EntryKinematics
        Arrays over ``phi`` and the summary.

    Raises
    ------
    InputError
        Non-positive pitch or speed, ``teeth < 3``, bar diameter outside ``[0, t)``,
        a missing or negative guide parameter, or conflicting ``entry``/``guide_height``.
    InfeasibleError
        The guide end is too close to the wheel for the chain to reach it (the message
        gives the smallest feasible ``guide_end_distance`` and, for a custom guide, the
        feasible ``guide_height`` range).
    UnknownNameError
        Unknown ``entry`` or ``model``.

    Notes
    -----
    Valid for a rigid, inextensible chain at constant ``ω``; ``H >= 0``. At a seating
    the acceleration jumps; ``phi`` exactly at the period end takes the limit from the
    left. Mean speed over a period is exactly ``(chain per period) z ω / 2π`` for the
    exact model and the ``"paper"`` model; the ``"as_printed"`` chordal entry resets
    its rod at ``π/z`` and advances slightly more (see ``summary``).

    References
    ----------
    Dolipiński et al., eqs (1)-(43), Figs 2-5.

    Examples
    --------
    Dolipiński et al.'s case: chain 18x64, z = 8, ω = 5 s⁻¹, tangential entry, l = 0.256 m.

    >>> r = chain_entry(0.064, 8, 5.0, bar_diameter=0.018, entry="tangential",
    ...                 guide_end_distance=0.256)
    >>> round(r.summary["v_mean"], 6), round(0.128 * 8 * 5.0 / (2 * np.pi), 6)
    (0.814873, 0.814873)

    Roller chain, free entry: ``v_min / v_max = cos(π/z)``.

    >>> r = chain_entry(0.0254, 12, 10.0)
    >>> round(r.summary["v_min"] / r.summary["v_max"], 6), round(float(np.cos(np.pi / 12)), 6)
    (0.965926, 0.965926)
    """
    case = _make_case(pitch, teeth, angular_velocity, bar_diameter, entry, guide_end_distance,
                      guide_height)
    MODELS.get(model)
    T = case.period
    if phi is None:
        from ..limits import MAX_POINTS, check_size

        n = check_size("points", points, MAX_POINTS, minimum=2)
        phi_arr = np.linspace(0.0, T, n)
    else:
        phi_arr = as_float_array("phi", phi)
        if not np.all(np.isfinite(phi_arr)):
            raise InputError("phi must be finite [rad] (-inf < phi < inf)")
    ev = np.atleast_1d(phi_arr).astype(float).copy()
    at_end = (np.abs(np.mod(ev, T)) <= 1e-14) & (ev > 0)  # np.isclose(.., 0, rtol=0, atol=1e-14)
    ev[at_end] = np.nextafter(ev[at_end], -np.inf)  # left limit at the period end
    try:
        if model == "exact":  # the angles asked for and the summary's in one call
            summary, r = _summary(case, model, _period_seats(case, _checked_seats(case)), ev.ravel())
        else:
            r = _run(case, model, ev)
    except InfeasibleError as exc:
        if case.entry == "free":
            raise
        _explain_infeasible(case, model, exc)
    if model != "exact":
        summary = _summary(case, model, np.asarray(r.seats, dtype=float))
    shape = np.shape(phi_arr)

    def out(key):
        value = getattr(r, key, None)
        return None if value is None else np.reshape(value, shape)

    free = case.entry == "free"
    return EntryKinematics(
        phi=phi_arr,
        x=out("x"),
        velocity=out("velocity"),
        acceleration=out("acceleration"),
        transverse_position=out("y") if free else None,
        transverse_velocity=out("vy") if free else None,
        transverse_acceleration=out("ay") if free else None,
        summary=summary,
        entry=case.entry,
        model=model,
        chain_type="roller" if case.roller else "link",
        pitch=case.t,
        bar_diameter=case.d,
        teeth=case.z,
        angular_velocity=case.w,
        radius=case.R,
        delta1=case.d1,
        delta2=case.d2,
        guide_height=case.H,
        guide_end_distance=case.l,
        period=T,
        seating_angles=np.asarray(r.seats, dtype=float),
    )


@finite_guard
def chain_entry_for(chain: Chain | str, teeth: int, angular_velocity: float, **kwargs: Any) -> EntryKinematics:
    """:func:`chain_entry` for a catalogue chain (``chaindrive.chains.get(name)``).

    Parameters
    ----------
    chain : Chain or str
        A chain object (``pitch`` [m], ``bar_diameter`` [m] or ``None``) or a catalogue
        name such as ``"18x64"`` or ``"16B"``.
    teeth : int
        Number of pockets/teeth ``z >= 3`` [-].
    angular_velocity : float
        ``ω > 0`` [rad/s].
    **kwargs
        Passed to :func:`chain_entry` (``entry``, ``guide_end_distance``, ...).

    Returns
    -------
    EntryKinematics

    Examples
    --------
    >>> r = chain_entry_for("18x64", 8, 5.0, entry="chordal", guide_end_distance=0.256)
    >>> r.chain_type, round(r.radius, 6)
    ('link', 0.164283)
    """
    if isinstance(chain, str):
        from .. import chains

        chain = chains.get(chain)
    bar = getattr(chain, "bar_diameter", None)
    return chain_entry(chain.pitch, teeth, angular_velocity, bar_diameter=bar, **kwargs)


def dolipinski_worked_case(model: str = "exact", points: int = 361) -> dict[str, EntryKinematics]:
    """Free, chordal and tangential entry of Dolipiński et al.'s worked case.

    Chain 18x64 (``t = 0.064 m``, ``d = 0.018 m``), ``z = 8``, ``ω = 5 rad/s``,
    ``l = 0.256 m`` (Dolipiński et al., Figs 2 and 3).

    Parameters
    ----------
    model : {"exact", "paper", "as_printed"}
        Mechanism.
    points : int
        Samples per period.

    Returns
    -------
    dict
        ``{"free": ..., "chordal": ..., "tangential": ...}`` of :class:`EntryKinematics`.

    Examples
    --------
    >>> cases = dolipinski_worked_case()
    >>> sorted(cases)
    ['chordal', 'free', 'tangential']
    """
    return {
        e: chain_entry(0.064, 8, 5.0, entry=e, bar_diameter=0.018, guide_end_distance=0.256, model=model,
                       points=points)
        for e in ("free", "chordal", "tangential")
    }


# former public names (renamed; deprecated, removed in the next release: chaindrive._deprecation)
__getattr__ = _renamed_attributes(
    "chaindrive.kinematics.entry",
    {"seed002_case": "dolipinski_worked_case"})
