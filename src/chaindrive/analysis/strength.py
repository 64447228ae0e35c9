"""Strength of a drive: roller–tooth contact with skew, track drive wheel teeth and rim bolts.

Decisions made here (one place) for the track drive wheel (Sharipov, p. 34): the design
force is ``P_Р = P / i`` with ``P = 0.65 G_T φ`` the adhesion force of *one track* and ``i``
the toothed rims of its drive wheel (the text: «i — число зубчатых венцов у ведущего
колеса»); the wheel's design torque is ``P R_о``; each rim passes ``P_Р R_о`` to the hub
through its bolts (Fig. 14); the tip radius must reach the pin circle of the chain at its
largest allowed pitch (the drive's elongation limit).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from .._results import Result, quantity
from ..drive.model import Drive
from ..errors import InputError
from ..strength import RollerToothContact, skew_from_measurement, track_tooth_check
from .checks import Check
from .loads import DriveLoads
from .parts import Part, PartContext, register_part

if TYPE_CHECKING:
    from ..geometry.track_wheel import TrackDriveWheel
    from ..strength.skew import RollerContactResult
    from ..strength.track_tooth import TrackToothResult

__all__ = ["ContactAnalysis", "RimBolts", "drive_contact", "drive_track_tooth", "drive_rim_bolts", "HARDNESS_RANGE"]

SHARIPOV = "Sharipov, p. 34; docs/strength.md"

#: Surface hardness of track drive wheel rims [HRC] (Sharipov, p. 34).
HARDNESS_RANGE = (48.0, 60.0)


@dataclass(frozen=True)
class ContactAnalysis(Result):
    """Roller–tooth contact with skew at the tight-side tension.

    Attributes
    ----------
    load : float
        Roller load ``Q_nom``: the tight-side tension on the first tooth [N].
    skew : float
        Largest measured skew ``φ_p,max`` [rad].
    contact : RollerToothContact
        The contact (radii, length, material).
    result : RollerContactResult
        :meth:`RollerToothContact.stress` at ``load`` and ``skew``.
    """

    load: float = quantity("N")
    skew: float = quantity("rad")
    wear_factor: float = quantity("1")
    contact: RollerToothContact
    result: RollerContactResult

    def to_dict(self) -> dict[str, Any]:
        return {"load": self.load, "skew": self.skew, "wear_factor": self.wear_factor, **self.result.to_dict()}


def drive_contact(drive: Drive, loads: DriveLoads) -> ContactAnalysis | None:
    """Contact stress with skew (Garshniev & Maksymovych eqs (1)–(3)) for a roller chain with ``[contact]``.

    ``None`` when the drive has no contact inputs or its chain has no rollers.
    """
    con = drive.contact
    c = drive.chain
    if con is None or not c.is_roller_chain or c.roller_diameter is None:
        return None
    if con.skew is not None:
        skew = float(con.skew)
    elif con.skew_height_difference is not None and con.skew_base is not None:
        skew = float(skew_from_measurement(con.skew_height_difference, con.skew_base))
    else:  # ContactSpec() refuses this; the check narrows the types
        raise InputError("contact: give skew, or both skew_height_difference and skew_base", field="contact")
    obj = RollerToothContact.from_chain(c, seat_radius=con.seat_radius, length=con.contact_length)
    res = obj.stress(loads.tight, max_skew=skew, wear_factor=con.wear_factor)
    return ContactAnalysis(float(loads.tight), skew, float(con.wear_factor), obj, res)


def contact_checks(contact: ContactAnalysis) -> tuple[Check, ...]:
    r = contact.result
    return (Check("contact stress with skew", float(r.stress), None, "Pa", None, "Garshniev & Maksymovych, eqs (1)–(2)",
                  f"skew raises it {float(r.stress_ratio):.2f} times", relation="info"),
            Check("life with skew relative to none (wear law)", float(r.relative_life_wear), None, "-", None,
                  "Garshniev & Maksymovych; docs/strength.md", relation="info"))


def drive_track_tooth(drive: Drive, wheel_object: TrackDriveWheel | None) -> TrackToothResult | None:
    """Track drive wheel tooth in bending and contact (Sharipov, p. 34: ``P = 0.65 G φ / i``)."""
    tr = drive.track
    if tr is None or wheel_object is None:
        return None
    return track_tooth_check(wheel_object, tr.tractor_weight, tr.tooth_width, adhesion=tr.adhesion, rims=tr.rims,
                             hardness=tr.hardness, allowable_bending=tr.allowable_bending,
                             allowable_contact=tr.allowable_contact)


def track_tooth_checks(drive: Drive, result: TrackToothResult) -> tuple[Check, ...]:
    tr = drive.track
    if tr is None:  # no [track] section: nothing to check
        return ()
    out = []
    rd = result.to_dict()
    for key, name, allow in (("bending", "tooth bending", tr.allowable_bending),
                             ("contact", "pin–tooth contact", tr.allowable_contact)):
        stress = rd[f"{key}_stress"]
        if allow is not None:
            out.append(Check(f"{name} safety (allowable / stress)", allow / stress, 1.0, "-",
                             bool(allow / stress >= 1), "Sharipov, p. 34; docs/strength.md"))
    if tr.hardness is not None:
        h = float(tr.hardness)
        out.append(Check("surface hardness", h, HARDNESS_RANGE, "HRC",
                         bool(HARDNESS_RANGE[0] <= h <= HARDNESS_RANGE[1]), "Sharipov, p. 34", relation="within"))
    load = drive.torque() * drive.load.service_factor
    out.append(Check("design torque of the drive wheel P R_0 (P = 0.65 G_T φ, one track)", result.design_torque,
                     None, "N*m", None, SHARIPOV,
                     f"the [load] torque with service factor is {load / 1e3:.4g} kN·m; "
                     f"each of the {result.rims} rim(s) carries P_P = P / i = {result.design_force / 1e3:.4g} kN "
                     "on one tooth", relation="info"))
    return tuple(out)


def worn_tip_check(wheel: TrackDriveWheel) -> Check | None:
    """The tip radius reaches the pin circle of the chain at its largest allowed pitch."""
    d = wheel.dimensions()
    if d.worn_tip_radius is None:
        return None
    return Check("tip radius holds the worn chain (R_tip >= t (1 + Δ) / (2 sin(π/z)))", d.tip_radius,
                 d.worn_tip_radius, "m", bool(d.tip_radius >= d.worn_tip_radius), SHARIPOV,
                 f"elongation limit Δ = {100 * (d.elongation_limit or 0):.3g} %: smallest tip factor "
                 f"{d.worn_tip_factor:.3g}, used {d.tip_factor:.3g} ({d.link} links: "
                 f"{d.tip_factor_range[0]:g}…{d.tip_factor_range[1]:g})")


@dataclass(frozen=True)
class RimBolts(Result):
    """The bolts of one toothed rim under the rim's torque ``P_Р R_о`` (Sharipov, Fig. 14)."""

    joint: str
    count: int = quantity("1")
    circle_radius: float = quantity("m", display="mm")
    rim_torque: float = quantity("N*m")
    bolt_force: float = quantity("N")
    shear_stress: float | None = quantity("Pa", default=None)
    bearing_stress: float | None = quantity("Pa", default=None)
    shear_safety: float | None = quantity("1", default=None)
    bearing_safety: float | None = quantity("1", default=None)
    required_preload: float | None = quantity("N", default=None)
    preload_stress: float | None = quantity("Pa", default=None)
    yield_safety: float | None = quantity("1", default=None)


def drive_rim_bolts(drive: Drive, tooth: TrackToothResult) -> RimBolts | None:
    """The rim bolts of ``[track.bolts]`` under the rim torque of the tooth check."""
    from ..strength.bolts import bolt_stress_area, fitted_bolt_check, friction_bolt_preload

    tr = drive.track
    if tr is None or tr.bolts is None:
        return None
    b = tr.bolts
    torque = float(tooth.rim_torque)
    if b.joint == "fitted":
        f = fitted_bolt_check(torque, b.circle_radius, b.count, b.diameter, shear_planes=b.shear_planes,
                              plate_thickness=b.plate_thickness, allowable_shear=b.allowable_shear,
                              allowable_bearing=b.allowable_bearing)
        return RimBolts("fitted", int(b.count), float(b.circle_radius), torque, float(f.bolt_force),
                        shear_stress=float(f.shear_stress), bearing_stress=f.bearing_stress,
                        shear_safety=f.shear_safety, bearing_safety=f.bearing_safety)
    area = None if b.thread_pitch is None else float(bolt_stress_area(b.diameter, b.thread_pitch))
    g = friction_bolt_preload(torque, b.circle_radius, b.count, b.friction, friction_faces=b.friction_faces,
                              slip_safety=b.slip_safety, stress_area=area, yield_strength=b.yield_strength)
    return RimBolts("friction", int(b.count), float(b.circle_radius), torque, float(g.bolt_force),
                    required_preload=float(g.required_preload), preload_stress=g.preload_stress,
                    yield_safety=g.yield_safety)


def rim_bolt_checks(result: RimBolts) -> list[Check]:
    source = "Sharipov, Fig. 14 (bolts of the rim); Shigley §8-12, VDI 2230-1; docs/strength.md"
    out = []
    for name, value in (("rim bolt shear safety (allowable / stress)", result.shear_safety),
                        ("rim bolt bearing safety (allowable / stress)", result.bearing_safety),
                        ("rim bolt preload: yield safety R_p0.2 / σ_V", result.yield_safety)):
        if value is not None:
            out.append(Check(name, float(value), 1.0, "-", bool(value >= 1.0), source,
                             f"rim torque P_P R_0 = {result.rim_torque / 1e3:.4g} kN·m on {result.count} bolts"))
    if not out:
        out.append(Check("rim bolt force", result.bolt_force, None, "N", None, source,
                         "give allowable stresses (fitted) or a yield strength and thread pitch (friction) "
                         "for a verdict", relation="info"))
    return out




# --------------------------------------------------------------------------- declared parts
def _track_tooth_part(ctx: PartContext) -> TrackToothResult | None:
    from ..geometry.track_wheel import TrackDriveWheel

    if ctx.drive.track is None:
        return None
    wheel = next((g.object for g in ctx["geometry"] or () if isinstance(g.object, TrackDriveWheel)), None)
    return drive_track_tooth(ctx.drive, wheel)


def _contact_batch(contexts: Sequence[PartContext]) -> list[ContactAnalysis] | None:
    """The contact of many variants in one vectorised call of
    :meth:`~chaindrive.strength.RollerToothContact.stress` (same chain, seat and length;
    tight-side tensions, skews and wear factors vary); ``None`` where they differ."""
    import dataclasses
    import warnings

    import numpy as np

    from ..strength.hertz import CONFORMITY_LIMIT, warn_conformal
    from ..strength.skew import (
        MEASURED_SKEW_RANGE,
        WEAR_FACTOR_RANGE,
        RollerContactResult,
        design_skew,
        skew_gamma,
    )

    first = contexts[0].drive
    con0, c = first.contact, first.chain
    if con0 is None or not c.is_roller_chain or c.roller_diameter is None:
        return None
    skews, factors, tights = [], [], []
    for ctx in contexts:
        con = ctx.drive.contact
        if (ctx.drive.chain is not c or con is None or con.skew is None
                or con.seat_radius != con0.seat_radius or con.contact_length != con0.contact_length):
            return None
        skews.append(float(con.skew))
        factors.append(float(con.wear_factor))
        tights.append(float(ctx["loads"].tight))
    with warnings.catch_warnings(record=True) as shared:
        warnings.simplefilter("always")
        obj = RollerToothContact.from_chain(c, seat_radius=con0.seat_radius, length=con0.contact_length)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # replayed per variant below
        res = obj.stress(tights[0] if len(set(tights)) == 1 else np.array(tights), max_skew=np.array(skews),
                         wear_factor=np.array(factors))
    # each variant's warnings, as its own call of RollerToothContact.stress raises them
    # (roller_contact_stress: design_skew, then skew_gamma, then warn_conformal)
    with warnings.catch_warnings(record=True) as gamma_warnings:
        warnings.simplefilter("always")
        skew_gamma(c.pitch)
    fields = [f.name for f in dataclasses.fields(res)]
    columns = {name: getattr(res, name) for name in fields}
    # the variants whose own call warns (the scalar tests of design_skew's warn_outside
    # and of warn_conformal, vectorised); each of those calls its formula again for the
    # exact message, the others warn only what every variant warns
    phi, k = np.array(skews), np.array(factors)
    lo, hi = MEASURED_SKEW_RANGE[1], WEAR_FACTOR_RANGE
    skew_warns = (~((phi >= 0.0) & (phi <= lo)) | ~((k >= hi[0]) & (k <= hi[1]))).tolist()
    ratio = np.asarray(columns["half_width"], dtype=float) / (c.roller_diameter / 2)
    conformal = np.broadcast_to(ratio > CONFORMITY_LIMIT, phi.shape).tolist()
    common = [str(w.message) for w in (*shared, *gamma_warnings)]
    conformal_messages: dict[str, list[str]] = {}
    half_width = np.broadcast_to(columns["half_width"], phi.shape).tolist()
    cls = RollerContactResult
    scalar = {name: v for name, v in columns.items() if not (isinstance(v, np.ndarray) and v.ndim)}
    arrays = {name: v.tolist() for name, v in columns.items() if isinstance(v, np.ndarray) and v.ndim}
    out = []
    for i, (skew, factor) in enumerate(zip(skews, factors, strict=True)):
        ctx = contexts[i]
        if skew_warns[i] or conformal[i]:
            messages = [str(w.message) for w in shared]
            if skew_warns[i]:
                with warnings.catch_warnings(record=True) as own:
                    warnings.simplefilter("always")
                    design_skew(skew, factor)
                messages += [str(w.message) for w in own]
            messages += [str(w.message) for w in gamma_warnings]
            if conformal[i]:
                # warn_conformal's message shows the ratio to 3 digits: one call per shown value
                x = half_width[i]
                key = f"{x / (c.roller_diameter / 2):.3g}"
                if key not in conformal_messages:
                    with warnings.catch_warnings(record=True) as caught:
                        warnings.simplefilter("always")
                        warn_conformal(x, c.roller_diameter / 2, "roller-tooth contact")
                    conformal_messages[key] = [str(w.message) for w in caught]
                messages += conformal_messages[key]
        else:
            messages = common
        for m in messages:
            ctx.warn(m)
        row = dict(scalar)
        for name, v in arrays.items():
            row[name] = v[i]
        out.append(ContactAnalysis(tights[i], skew, factor, obj, cls(**row)))
    return out


register_part(Part("contact", "Roller–tooth contact with skew", lambda ctx: drive_contact(ctx.drive, ctx["loads"]),
                   needs=("loads",), checks=lambda ctx, con: contact_checks(con), order=70,
                   section="chaindrive.workflows.sections:strength_section", batch=_contact_batch))


def _track_checks(ctx: PartContext, tooth: TrackToothResult) -> list[Check]:
    from ..geometry.track_wheel import TrackDriveWheel

    out = list(track_tooth_checks(ctx.drive, tooth))
    wheel = next((g.object for g in ctx["geometry"] or () if isinstance(g.object, TrackDriveWheel)), None)
    worn = None if wheel is None else worn_tip_check(wheel)
    if worn is not None:
        out.insert(0, worn)
    return out


register_part(Part("track_tooth", "Track drive wheel teeth", _track_tooth_part, needs=("geometry",),
                   checks=_track_checks, order=80,
                   section="chaindrive.workflows.sections:strength_section"))
register_part(Part("rim_bolts", "Bolts of the track drive wheel's rims",
                   lambda ctx: None if ctx["track_tooth"] is None else drive_rim_bolts(ctx.drive, ctx["track_tooth"]),
                   needs=("track_tooth",), checks=lambda ctx, r: rim_bolt_checks(r), order=81,
                   section="chaindrive.workflows.sections:strength_section"))
