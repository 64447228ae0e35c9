r"""The drive over its life: elongation, the worn chain on the wheels, jump-over, fatigue, efficiency.

One life per mechanism, each decided here once:

- **wear**: the hours to the drive's elongation limit are the wear part's
  (:mod:`chaindrive.analysis.wear`), or with a skew the service-life part's
  (:mod:`chaindrive.analysis.service_life`), never recomputed; the elongation over hours follows
  it (:func:`chaindrive.life.elongation.elongation_at_hours`). The makers' replacement
  limit by tooth count is a check on the drive's limit.
- **jump-over**: for every loaded ISO 606 sprocket, the load ratio at which the wrap lets
  the chain ride over — the compliant wrap's, checked against the simulation, from its table
  (:mod:`chaindrive.life.jump_table`: ``c β^-n``), the wheel on the tensioner's slide with its
  torque and ``T_1 + T_2`` held, the others with their back tension held — over the running
  ``T_1/T_2`` (the margin), over the elongation from new to the limit; the elongation at which
  the margin reaches 1 (or the tooth form's holding limit) and the hours to it.
- **fatigue**: rainflow counting of one link's tension over a lap (span tensions, the
  centrifugal part and the polygonal dynamic tension on the tight span) against the link
  plate S–N curve tied to the rating's link-plate line (:mod:`chaindrive.life.fatigue`).
- **efficiency**: articulation friction on every wheel (:mod:`chaindrive.life.efficiency`).

The worn chain on the wheels: the rollers ride out to ``R (1 + e)``, so the spans shorten
and the chain is lighter per metre, ``q / (1 + e)``; the span frequencies, the tensioner's
travel (the layout part's take-up) and the jump-over margins are given over the elongation
grid ``elongations`` (new → the drive's limit), the worst point named.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from .. import layout as L
from .._results import Result, quantity
from .._validation import check_nonnegative
from ..chains.stiffness import chain_axial_stiffness
from ..errors import InputError, ValidityRangeWarning
from ..layout.wrap import span_lengths
from ..life import efficiency as EF
from ..life import elongation as EL
from ..life import fatigue as FA
from ..life import jump_over as JO
from ..life import jump_table as JT
from ..vibration.resonance import resonance_margin
from ..vibration.string import moving_string_frequencies
from ._memo import memo
from .checks import Check
from .parts import Part, PartContext, register_part

if TYPE_CHECKING:
    from ..drive.model import Drive
    from .layout import DriveLayout
    from .loads import DriveLoads
    from .rating import DriveRating
    from .vibration import DriveVibration

__all__ = ["DriveLife", "WornState", "drive_life", "worn_state", "ELONGATION_STEPS"]

#: Points of the elongation grid from new to the drive's limit.
ELONGATION_STEPS = 7
_SOURCE_LIMIT = ("makers' replacement rule (Diamond Chain, Regal Rexnord): 3 %, 200/z % above 67 teeth, "
                 "1.5 % on fixed centres")
_SOURCE_JUMP = ("compliant wrap on the ISO 606 tooth form (after Marshek & Naji, Mech. Mach. Theory 18 (1983) 349), "
                "checked against the simulation within 10 %; its table (scripts/tabulate_wrap_jump.py) as a "
                "correction to the rigid roller balance beta^-n (Binder 1956 ch. 5); docs/life.md, 'Jump-over'")
_SOURCE_HOLD = ("ISO 606 tooth form: the roller centre at the tooth corner (Binder 1956 ch. 5); docs/life.md")
_LOADING_NOTE = {"torque": "the wheel on the tensioner's slide: torque and T1 + T2 held",
                 "tensions": "back tension held (tensioner on the slack span, sag or given)"}


@dataclass(frozen=True)
class DriveLife(Result):
    """The drive over its life (see the module notes). Per-wheel tuples are in the wheel order,
    ``None`` where the quantity does not apply (idlers, pocket wheels, toothless wheels)."""

    hours: np.ndarray = quantity("h")
    elongation: np.ndarray = quantity("1")
    elongation_limit: float = quantity("1")
    replacement_limit: float | None = quantity("1")
    replacement_hours: float = quantity("h")
    elongations: np.ndarray = quantity("1")
    wheel_names: tuple[str, ...] = ()
    seating_rise: tuple[float | None, ...] = quantity("m", default=())
    holding_limit: tuple[float | None, ...] = quantity("1", default=())
    jump_over_tension: tuple[float | None, ...] = quantity("N", default=())
    jump_over_margin: tuple[float | None, ...] = quantity("1", default=())
    jump_over_loading: tuple[str | None, ...] = ()
    jump_over_margins: np.ndarray | None = quantity("1", default=None)
    jump_over_elongation: float | None = quantity("1", default=None)
    jump_over_hours: float | None = quantity("h", default=None)
    jump_over_wheel: str = ""
    take_up: np.ndarray | None = quantity("m", default=None)
    span_frequencies: np.ndarray | None = quantity("rad/s", display="rad/s", default=None)
    resonance_margins: np.ndarray | None = quantity("1", default=None)
    resonance_worst: str = ""
    endurance_range: float | None = quantity("N", default=None)
    fatigue_utilisation: float | None = quantity("1", default=None)
    fatigue_life_hours: float | None = quantity("h", default=None)
    efficiency: float | None = quantity("1", default=None)
    power_loss: float | None = quantity("W", default=None)
    life_hours: float = quantity("h", default=0.0)
    governing: str = "wear"
    wear_basis: str = "wear"
    notes: tuple[str, ...] = ()


def _tooth_form_wheels(drive: Drive, layout: DriveLayout) -> list[tuple[int, int, int]]:
    """(index, teeth, teeth in mesh) of the ISO 606 sprockets of a roller chain."""
    chain = drive.chain
    if chain.roller_diameter is None or chain.bar_diameter is not None:
        return []
    out = []
    for i, w in enumerate(drive.wheels):
        if w.kind == "sprocket" and w.teeth is not None:
            out.append((i, int(w.teeth), int(layout.teeth_in_mesh[i] or 0)))
    return out


def _wheel_tensions(loads, n):
    """(arriving, leaving) static span tension of every wheel, without the centrifugal part [N]."""
    s = np.asarray(loads.span_tensions, float)
    return [(float(s[(i - 1) % n]), float(s[i])) for i in range(n)]


def _loading(drive, index):
    """``torque`` for a loaded wheel carried by the tensioner (its slide holds ``T_1 + T_2``), else
    ``tensions`` (the back tension held: by the tensioner on the slack span, by the sag, or given)."""
    t = drive.tensioner
    return "torque" if t is not None and drive.wheel_index(t.wheel) == index else "tensions"


def _onset(drive, index, teeth, seated, tight, back, elongations, notes=None):
    """The compliant wrap's onset (:func:`chaindrive.life.jump_onset`) of wheel ``index`` over
    ``elongations``; with ``notes``, what lies outside its table said (:func:`_table_range`)."""
    ch = drive.chain
    k = float(ch.strands or 1)
    kw = {"load": (tight + back) / k} if _loading(drive, index) == "torque" else {"back_tension": back / k}
    onset = JT.jump_onset(drive.pitch, teeth, ch.roller_diameter, elongations, seated=seated,
                          axial_stiffness=chain_axial_stiffness(ch), warn=False, **kw)
    if notes is not None and onset.outside:
        _table_range(drive, index, onset.outside, float(np.min(onset.tight_tension)), notes)
    return onset


def _table_range(drive, index, outside, tight_min, notes):
    """A ``ValidityRangeWarning`` for what lies outside the compliant wrap's table (``outside``, of
    :func:`chaindrive.life.jump_onset`), except a load beyond the table's where the onset's smallest tooth
    load ``tight_min`` (one strand) exceeds the chain's breaking force (the chain breaks before it jumps:
    said in ``notes``)."""
    ch = drive.chain
    k = float(ch.strands or 1)
    outside = list(outside)
    name = drive.wheels[index].name
    strength = ch.breaking_force
    if strength and any(o.startswith("F/EA") for o in outside) and tight_min * k > float(strength):
        outside = [o for o in outside if not o.startswith("F/EA")]
        notes.append(f"jump-over on '{name}': the wrap holds a tooth load beyond the chain's breaking force "
                     f"({float(strength) / 1e3:.4g} kN): the chain breaks before it jumps (the margin is the "
                     "compliant wrap's at the load edge of its table)")
    if outside:
        warnings.warn(f"jump-over margin on '{name}' (the compliant wrap's table, scripts/tabulate_wrap_jump.py): "
                      f"{'; '.join(outside)}; the nearest edge of the table is used", ValidityRangeWarning,
                      stacklevel=2)


def _margins(drive, layout, loads, grid, notes):
    n = len(drive.wheels)
    wheels = _tooth_form_wheels(drive, layout)
    tens = _wheel_tensions(loads, n)
    rise = [None] * n
    hold = [None] * n
    t_jump = [None] * n
    margin = [None] * n
    loading = [None] * n
    curves = np.full((n, grid.size), np.nan)
    e_jump, wheel_jump = None, ""
    p, d1 = drive.pitch, drive.chain.roller_diameter
    for i, z, seated in wheels:
        hi, lo = max(tens[i]), min(tens[i])
        limit = JO.holding_limit(p, z, d1)
        hold[i] = limit
        rise[i] = float(p / (2 * math.sin(math.pi / z)) * grid[-1])
        # past its holding limit no sprocket holds the chain, loaded or not
        if e_jump is None or limit < e_jump:
            e_jump, wheel_jump = limit, drive.wheels[i].name
        if grid[-1] > limit:
            continue  # the holding check fails; no margin past the corner
        if hi - lo <= 1e-9 * max(hi, 1.0) or seated < 1:
            continue  # no tooth load: an idler sprocket, or nothing seated
        loading[i] = _loading(drive, i)
        if lo <= 0.0:  # no back tension: nothing holds the wrap
            curves[i], t_jump[i], margin[i] = 0.0, 0.0, 0.0
            e_w = 0.0
        else:
            # the grid's points and the jump elongation's search points in one call (pointwise: the same
            # numbers); what lies outside the table said for the grid's
            g = grid.size
            points = _jump_points(limit)
            onset = _onset(drive, i, z, seated, hi, lo, np.concatenate([grid, points]))
            rho, tight = np.asarray(onset.load_ratio), np.asarray(onset.tight_tension)
            outside = JT._outside(onset.loading, z, np.asarray(onset.fraction)[:g].tolist(),
                                  np.asarray(onset.load_stiffness)[:g].tolist())
            if outside:
                _table_range(drive, i, outside, float(np.min(tight[:g])), notes)
            curves[i] = rho[:g] * lo / hi
            t_jump[i] = float(tight[g - 1]) * float(drive.chain.strands or 1)
            margin[i] = float(curves[i][-1])
            e_w = _jump_elongation(drive, i, rho[g:] * lo / hi, limit, notes, points)
        if e_w < e_jump:
            e_jump, wheel_jump = e_w, drive.wheels[i].name
    if not wheels:
        notes.append("jump-over: no ISO 606 sprocket on a roller chain (pocket wheels and track wheels "
                     "are not modelled)")
    curves_out = None if np.all(np.isnan(curves)) else curves
    return rise, hold, t_jump, margin, loading, curves_out, e_jump, wheel_jump


#: Points of the elongation grid (0 … the holding limit) on which the jump-over elongation is sought.
_JUMP_POINTS = 17


def _jump_points(limit):
    """The elongations (0 … the holding limit) on which the jump-over elongation is sought."""
    return np.linspace(0.0, limit * (1 - 1e-9), _JUMP_POINTS)


def _jump_elongation(drive, i, m, limit, notes, points=None):
    """Smallest elongation where the margin ``m = ρ_jump(e) T_2/T_1`` (on :func:`_jump_points`, ``points``
    when the caller has them) reaches 1,
    or the holding limit: the first crossing on the grid, linear in ``ln`` margin between its points."""
    e = _jump_points(limit) if points is None else points
    below = np.flatnonzero(m <= 1.0)
    if below.size == 0:
        return limit
    j = int(below[0])
    if j == 0:
        return 0.0
    a, b = math.log(m[j - 1]), math.log(max(m[j], 1e-300))
    found = float(e[j - 1] + (e[j] - e[j - 1]) * a / (a - b))
    top = JT.wrap_jump_range()["fraction"][1]
    if found > top * limit:
        notes.append(f"jump-over on '{drive.wheels[i].name}' at {found / limit:.2f} of its holding limit, past the "
                     f"compliant wrap's table ({top:g} of it): its last point is used there")
    return found


def _span_frequencies(drive, layout, loads, grid):
    """First transverse frequency of every span over the elongation grid [rad/s] (spans × grid)."""
    q = drive.chain.mass_per_length
    if not q:
        return None
    w = layout.wrap
    v = float(loads.chain_speed)
    tension = np.asarray(loads.span_tensions, float) + float(loads.centrifugal)
    rows = np.asarray(w.radii)[None, :] * (1.0 + grid[:, None])
    lengths = span_lengths(np.asarray(w.centres, float), rows, np.asarray(w.sides, float))
    if lengths is None:  # no layout at some elongation: wrap_layout says why
        lengths = np.stack([L.wrap_layout(w.centres, r, w.sides).span_length for r in rows])
    lengths = lengths.T
    return moving_string_frequencies(tension[:, None], q / (1.0 + grid[None, :]), lengths, chain_speed=v,
                                     modes=1)[..., 0]


def _resonance(freqs, vibration, grid, names):
    """Smallest margin to the 0.7…1.4 band of every excitation against every span's first
    frequency, at each elongation; the worst point in words."""
    if freqs is None or vibration is None or not vibration.excitations:
        return None, ""
    exc = dict(vibration.excitations)
    keys = list(exc)
    omega = np.array([exc[k] for k in keys], float)
    ratio = omega[:, None, None] / freqs[None, :, :]  # excitation × span × elongation
    margin = np.asarray(resonance_margin(ratio), float)
    per_e = margin.min(axis=(0, 1))
    i, j, k = np.unravel_index(int(np.argmin(margin)), margin.shape)
    n = len(names)
    worst = (f"{keys[i]} on span {names[j]} → {names[(j + 1) % n]} at {grid[k]:.4g} elongation "
             f"(P/ω = {ratio[i, j, k]:.3g}, margin {margin[i, j, k]:.3g})")
    return per_e, worst


def _lap_history(drive, layout, loads):
    """Tension of one link over a lap [N]: each span's static tension with the centrifugal part,
    in chain order. The polygonal dynamic tension is not added: the rating's link-plate line,
    to which the endurance is tied, is an empirical basis of chains running on sprockets, so it
    already holds the polygonal action of a drive at that tension."""
    span = np.asarray(loads.span_tensions, float) + float(loads.centrifugal)
    return np.r_[span, span[0]]


def _fatigue(drive, layout, loads, rating, notes):
    if rating is None:
        notes.append("fatigue: no link-plate rating for this chain, so no S–N endurance (roller chains of "
                     "ISO 606 / ANSI only)")
        return None, None, None
    r = rating.rating
    endurance = float(r.link_plate) / float(r.chain_speed)
    try:
        cycles = FA.rainflow_cycles(_lap_history(drive, layout, loads))
    except ImportError:
        notes.append("fatigue: rainflow counting needs the 'rainflow' package (pip install 'chaindrive[life]')")
        return endurance, None, None
    eq = FA.equivalent_range(cycles.ranges, cycles.means)
    util = float(np.max(eq)) / endurance if eq.size else 0.0
    damage = FA.miner_damage(cycles, endurance)
    laps_per_hour = float(loads.chain_speed) * 3600.0 / float(layout.chain_length)
    life = None if damage <= 0 else 1.0 / (damage * laps_per_hour)
    return endurance, util, life


def _efficiency(drive, layout, loads, notes):
    ch = drive.chain
    d = ch.pin_diameter if ch.pin_diameter is not None else ch.bar_diameter
    if d is None:
        notes.append("efficiency: the chain has no pin (or bar) diameter")
        return None, None
    n = len(drive.wheels)
    cf = float(loads.centrifugal)
    tens = _wheel_tensions(loads, n)
    radii = np.asarray(layout.pitch_radii, float)
    # articulation angle per joint on each wheel: 2 asin(p / 2R) (= 2π/z on a sprocket), at most its wrap
    angle = EF.articulation_angle(drive.pitch, radii, np.asarray(layout.wrap.wrap_angle, float))
    bent = angle > 0.0  # a wheel the chain does not wrap turns no joint
    sides = 2.0 * math.pi / angle[bent]
    t_in = np.array([t[0] for t in tens])[bent] + cf
    t_out = np.array([t[1] for t in tens])[bent] + cf
    loss = float(EF.articulation_power_loss(loads.chain_speed, drive.pitch, d, sides, t_in, t_out))
    power = float(loads.effective_pull) * float(loads.chain_speed) / max(float(drive.load.service_factor), 1e-12)
    if power <= 0:
        return None, loss
    return float(EF.transmission_efficiency(power, min(loss, power))), loss


def _life_key(drive, layout, loads, rating, wear_hours, vibration=None, wear_basis="wear"):
    """Everything the life depends on: the drive (layout, loads, rating, vibration follow from
    it), the wear life, and which of the optional parts were there."""
    return (drive, float(wear_hours), rating is None, vibration is None, wear_basis)


@memo(maxsize=64, key=_life_key)
def drive_life(drive: Drive, layout: DriveLayout, loads: DriveLoads, rating: DriveRating | None, wear_hours: float,
               vibration: DriveVibration | None = None, wear_basis: str = "wear") -> DriveLife:
    """The drive over its life (see the module notes).

    ``wear_hours`` are the hours to the drive's elongation limit as the wear part (or, with
    a skew, the service-life part) gives them; ``wear_basis`` names which.

    Raises
    ------
    InputError
        No wear life (the drive needs a wear model: a rating or ``wear_coefficient``).
    """
    if wear_hours is None:
        raise InputError("the life over the hours needs a wear life: a rated roller chain, or "
                         "wear_coefficient in [drive]", field="drive.wear_coefficient")
    notes: list[str] = []
    limit = float(drive.elongation_limit)
    t_lim = float(wear_hours)
    hours = np.linspace(0.0, t_lim, 11)
    elong = EL.elongation_at_hours(hours, t_lim, limit)
    grid = np.linspace(0.0, limit, ELONGATION_STEPS)
    sprockets = [w.teeth for w in drive.wheels if w.kind == "sprocket" and w.teeth is not None]
    replacement = None
    if drive.chain.roller_diameter is not None and sprockets:
        replacement = float(EL.replacement_limit(max(sprockets), fixed_centres=layout.take_up is None))
    rise, hold, t_jump, margin, loading, curves, e_jump, wheel_jump = _margins(drive, layout, loads, grid, notes)
    jump_hours = None if e_jump is None else float(EL.hours_to_elongation(e_jump, t_lim, limit))
    take_up = None
    if layout.take_up is not None:
        # the layout's take-up at 1, 2, 3 %, counted from its setting for the links (which may
        # already take up spare links): linear between them, and beyond them from the nearer
        # step; the travel is counted from the new chain
        e_pts, t_pts = np.asarray(layout.elongations, float), np.asarray(layout.take_up, float)
        take_up = np.interp(grid, e_pts, t_pts)
        lo, hi = grid < e_pts[0], grid > e_pts[-1]
        take_up[lo] = t_pts[0] + (grid[lo] - e_pts[0]) * (t_pts[1] - t_pts[0]) / (e_pts[1] - e_pts[0])
        take_up[hi] = t_pts[-1] + (grid[hi] - e_pts[-1]) * (t_pts[-1] - t_pts[-2]) / (e_pts[-1] - e_pts[-2])
        take_up = take_up - take_up[0]
    freqs = _span_frequencies(drive, layout, loads, grid)
    res_margins, res_worst = _resonance(freqs, vibration, grid, drive.wheel_names)
    endurance, util, fat_hours = _fatigue(drive, layout, loads, rating, notes)
    eff, loss = _efficiency(drive, layout, loads, notes)
    lives = {"wear": t_lim}
    if fat_hours is not None:
        lives["fatigue"] = fat_hours
    if jump_hours is not None:
        lives["jump-over"] = jump_hours
    governing = min(lives, key=lambda k: lives[k])
    return DriveLife(hours=hours, elongation=np.asarray(elong, float), elongation_limit=limit,
                     replacement_limit=replacement, replacement_hours=t_lim, elongations=grid,
                     wheel_names=drive.wheel_names, seating_rise=tuple(rise), holding_limit=tuple(hold),
                     jump_over_tension=tuple(t_jump), jump_over_margin=tuple(margin), jump_over_loading=tuple(loading),
                     jump_over_margins=curves,
                     jump_over_elongation=e_jump, jump_over_hours=jump_hours, jump_over_wheel=wheel_jump,
                     take_up=take_up, span_frequencies=freqs, resonance_margins=res_margins,
                     resonance_worst=res_worst, endurance_range=endurance,
                     fatigue_utilisation=util, fatigue_life_hours=fat_hours, efficiency=eff, power_loss=loss,
                     life_hours=float(lives[governing]), governing=governing, wear_basis=wear_basis,
                     notes=tuple(notes))


@dataclass(frozen=True)
class WornState(Result):
    """The worn chain at one point of its life (see :func:`worn_state`)."""

    hours: float = quantity("h")
    elongation: float = quantity("1")
    wheel_names: tuple[str, ...] = ()
    seating_rise: tuple[float | None, ...] = quantity("m", default=())
    jump_over_margin: tuple[float | None, ...] = quantity("1", default=())
    take_up: float | None = quantity("m", default=None)
    span_frequencies: np.ndarray | None = quantity("rad/s", display="rad/s", default=None)


def worn_state(drive: Drive, layout: DriveLayout, loads: DriveLoads, life: DriveLife, *, hours: float | None = None,
               elongation: float | None = None) -> WornState:
    """The chain after ``hours`` of running, or at ``elongation`` (exactly one of them).

    Raises
    ------
    InputError
        Negative hours or elongation; a point past the drive's elongation limit (the chain
        is due for replacement: the hours to it are named); an elongation the ISO 606 tooth
        form of a wheel cannot hold.
    """
    if (hours is None) == (elongation is None):
        raise InputError("give exactly one of hours (e.g. '20000 h') and elongation (e.g. '2 %')", field="hours")
    limit, t_lim = life.elongation_limit, life.replacement_hours
    if hours is not None:
        e = float(EL.elongation_at_hours(hours, t_lim, limit))
        t = float(hours)
        if e > limit * (1 + 1e-12):
            raise InputError(f"after {t:.6g} h the chain has stretched {100 * e:.3g} %, beyond the replacement "
                             f"limit {100 * limit:.3g} % reached after {t_lim:.6g} h (hours in [0, {t_lim:.6g}] h)",
                             field="hours")
    elif elongation is not None:
        e = float(check_nonnegative("elongation", elongation))
        if e > limit * (1 + 1e-12):
            raise InputError(f"elongation {100 * e:.3g} % is beyond the replacement limit {100 * limit:.3g} % "
                             f"of the drive (elongation in [0, {100 * limit:.3g}] %)", field="elongation")
        t = float(EL.hours_to_elongation(e, t_lim, limit))
    n = len(drive.wheels)
    rise: list[float | None] = [None] * n
    margin: list[float | None] = [None] * n
    tens = _wheel_tensions(loads, n)
    p, d1 = drive.pitch, drive.chain.roller_diameter
    for i, z, seated in _tooth_form_wheels(drive, layout):
        assert d1 is not None  # _tooth_form_wheels yields the sprockets of roller chains only
        seat = JO.worn_seat(p, z, d1, e)  # refuses an elongation the tooth form cannot hold
        rise[i] = float(seat.rise)
        hi, lo = max(tens[i]), min(tens[i])
        if hi - lo > 1e-9 * max(hi, 1.0) and seated >= 1:
            margin[i] = 0.0 if lo <= 0.0 else float(_onset(drive, i, z, seated, hi, lo, e, []).load_ratio) * lo / hi
    take_up = None if life.take_up is None else float(np.interp(e, life.elongations, life.take_up))
    freqs = None
    if life.span_frequencies is not None:
        freqs = np.array([np.interp(e, life.elongations, row) for row in life.span_frequencies])
    return WornState(t, e, drive.wheel_names, tuple(rise), tuple(margin), take_up, freqs)


# --------------------------------------------------------------------------- declared part
def _part(ctx: PartContext) -> DriveLife | None:
    wear = ctx["wear"]
    if wear is None:  # the wear part has said why
        return None
    service = ctx["service_life"]  # the wear life with the skew, where a skew is given
    hours, basis = ((service.hours, "service life with skew") if service is not None else
                    (wear.hours_to_limit, "wear"))
    # what does not apply (jump-over on pocket wheels, fatigue without a rating) is in
    # result.notes, shown by the report section: information, not a warning
    return drive_life(ctx.drive, ctx["layout"], ctx["loads"], ctx["rating"], float(hours), ctx["vibration"], basis)


def _checks(ctx: PartContext, r: DriveLife) -> list[Check]:
    out: list[Check] = []
    if r.replacement_limit is not None:
        out.append(Check("wear elongation limit <= makers' replacement limit", r.elongation_limit,
                         r.replacement_limit, "-", bool(r.elongation_limit <= r.replacement_limit + 1e-12),
                         _SOURCE_LIMIT, relation="<="))
    loadings = r.jump_over_loading or (None,) * len(r.wheel_names)
    for name, hold, m, ld in zip(r.wheel_names, r.holding_limit, r.jump_over_margin, loadings, strict=True):
        if hold is None:
            continue
        if r.elongation_limit > hold:
            out.append(Check(f"tooth form of '{name}' holds the chain at the elongation limit", hold,
                             r.elongation_limit, "-", False, _SOURCE_HOLD, relation=">=",
                             note="the rollers ride over the tooth corner before the limit"))
        elif m is not None:
            out.append(Check(f"jump-over margin on '{name}' at the elongation limit", m, 1.0, "-", bool(m >= 1.0),
                             _SOURCE_JUMP, note="load ratio M/(R_e T2) at jump-over / running T1/T2; "
                             + _LOADING_NOTE.get(ld or "", "")))
    if r.fatigue_life_hours is not None or r.fatigue_utilisation is not None:
        out.append(Check("link-plate fatigue: equivalent range / endurance", r.fatigue_utilisation, None, "-", None,
                         "rainflow (ASTM E1049) + Miner; endurance at the ANSI link-plate line (Tsubaki 1997 "
                         "Fig. 2.19), FKM S–N slope 5", relation="info",
                         note="below 1: no fatigue failure" if (r.fatigue_utilisation or 0) < 1 else
                         f"fatigue life {r.fatigue_life_hours:.0f} h"))
    if r.resonance_margins is not None:
        out.append(Check("span resonance over the life: smallest margin to the 0.7…1.4 band", float(np.min(r.resonance_margins)),
                         None, "-", None, "the tensioner paper's band, span frequencies of the worn chain",
                         relation="info", note=f"worst: {r.resonance_worst}"))
    if r.governing != "wear":  # the wear part's check already gives the wear life: one number per life
        out.append(Check(f"life of the chain (governed by {r.governing})", r.life_hours, None, "h", None,
                         "wear part, jump-over and fatigue of docs/life.md", relation="info"))
    if r.efficiency is not None:
        out.append(Check("efficiency (articulation friction)", r.efficiency, None, "-", None,
                         "Spicer et al., J. Mech. Des. 123 (2001) 598; calibrated, docs/life.md", relation="info"))
    return out


register_part(Part("life", "The drive over its life", _part, needs=("layout", "loads", "rating", "wear", "service_life", "vibration"),
                   checks=_checks, order=110, section="chaindrive.workflows.life_section:life_section"))
