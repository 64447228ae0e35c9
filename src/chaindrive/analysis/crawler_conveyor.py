r"""The conveyor crawler drive as an analysis part (the crawler drive text).

A drive with a ``[crawler]`` table is the intermediate crawler (caterpillar) drive of a
conveyor: its drive chain runs round the driving sprocket and the tensioning sprocket
(the drive's two toothed wheels, same tooth count, a whole number of pitches apart) and
carries cams that push the hinges of the conveyor's traction chain. The part computes,
once per drive:

* the kinematics of the working span with or without the tangent guide (eqs 6.7,
  6.14-6.16): mean speed, non-uniformity, accelerations, transverse throw;
* the force on the engaged cam (the rebuilt formula of
  :func:`chaindrive.kinematics.crawler.cam_force`): the mean is the drive's effective
  pull (the traction force the cam passes to the conveyor), the fluctuation is the
  elastic chain's answer to the polygonal motion with the cam moved at the mean speed;
* the same fluctuation with an elastic return span and a free tensioning sprocket
  (:func:`~chaindrive.kinematics.crawler.elastic_loop`): the check of the formula's two
  assumptions (rigid return span; tensioning sprocket in phase, imposing its own
  displacement);
* the guide reactions, the text's "pushing-off forces": the inclined link at each end
  of the guide (``T tan φ1``) and the cam face (``P tan α``).

Decisions made here (one place): the tension of the tensioning-side segment is the
drive's slack tension plus its fluctuation, that of the driving-side segment the slack
tension plus the effective pull plus its fluctuation (the loads part's tight side).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .._results import Result, quantity
from ..drive.model import Drive
from ..errors import InputError
from ..kinematics.crawler import (
    CrawlerKinematics,
    cam_pushing_off_force,
    crawler_drive,
    elastic_loop,
    free_span_displacement,
    guide_link_angle,
    guide_reaction,
    guided_displacement,
    leaving_displacement,
)
from .checks import Check
from .parts import Part, PartContext, register_part

__all__ = ["CrawlerConveyor", "crawler_conveyor"]

SOURCE = "the crawler drive text, eqs (6.7), (6.14)-(6.16); cam force rebuilt (docs/crawler.md)"
#: Samples per tooth period for the extremes of the forces.
POINTS = 721
#: Samples per tooth period of the elastic-loop check (a root finding per sample).
LOOP_POINTS = 49


@dataclass(frozen=True)
class CrawlerConveyor(Result):
    """The conveyor crawler drive: kinematics, force on the cam, guide reactions (SI units)."""

    guide: str
    teeth: int = quantity("1")
    pitch_radius: float = quantity("m", display="mm")
    sprocket_distance: float = quantity("m", display="mm")
    cam_distance: float = quantity("m", display="mm")
    mean_speed: float = quantity("m/s")
    speed_nonuniformity: float = quantity("1", display="%")
    acceleration_min: float = quantity("m/s^2")
    acceleration_max: float = quantity("m/s^2")
    transverse_throw: float = quantity("m", display="mm")
    cam_stiffness: float = quantity("N/m")
    traction_force: float = quantity("N")
    pretension: float = quantity("N")
    cam_force_min: float = quantity("N")
    cam_force_max: float = quantity("N")
    cam_force_range: float = quantity("N")
    cam_force_range_elastic: float | None = quantity("N", default=None)
    tensioning_sprocket_lag: float | None = quantity("rad", display="°", default=None)
    tensioning_side_tension_min: float = quantity("N", default=0.0)
    driving_side_tension_max: float = quantity("N", default=0.0)
    guide_reaction_driving: float | None = quantity("N", default=None)
    guide_reaction_tensioning: float | None = quantity("N", default=None)
    cam_pushing_off: float = quantity("N", default=0.0)
    cam_face_angle: float = quantity("rad", display="°", default=0.0)
    kinematics: CrawlerKinematics | None = None


def _sprockets(drive: Drive) -> tuple[float, int]:
    """Centre distance and tooth count of the driving and the tensioning sprocket."""
    toothed = [w for w in drive.wheels if w.teeth is not None and w.kind == "sprocket"]
    if len(toothed) != 2 or len(drive.wheels) != 2:
        raise InputError("crawler: the conveyor crawler drive has exactly two wheels, the driving and the "
                         f"tensioning sprocket (kind = \"sprocket\"), got {len(drive.wheels)} wheel(s)",
                         field="wheels")
    a, b = toothed
    if a.teeth != b.teeth:
        raise InputError(f"crawler: both sprockets need the same tooth count (the crawler drive text), got "
                         f"{a.teeth} and {b.teeth}", field="wheels")
    distance = math.dist(a.position, b.position)
    t = drive.pitch
    ratio = distance / t
    if abs(ratio - round(ratio)) > 1e-6 * max(ratio, 1.0) or round(ratio) < 1:
        lo, hi = max(math.floor(ratio), 1) * t, math.ceil(ratio) * t
        raise InputError(f"crawler: the sprockets must be a whole number of pitches apart (in phase); "
                         f"{distance * 1e3:.6g} mm is {ratio:.6g} pitches: nearest {lo * 1e3:.6g} mm or "
                         f"{hi * 1e3:.6g} mm", field="wheels")
    return round(ratio) * t, int(a.teeth or 0)


def crawler_conveyor(ctx: PartContext) -> CrawlerConveyor | None:
    """The part's compute function (``None`` without a ``[crawler]`` table)."""
    drive = ctx.drive
    spec = drive.crawler
    if spec is None:
        return None
    loads = ctx["loads"]
    A, z = _sprockets(drive)
    t = drive.pitch
    l = float(spec.cam_distance) if spec.cam_distance is not None else 0.0
    if not 0 < l < A:
        raise InputError(f"crawler.cam_distance must lie in (0, {A * 1e3:.6g} mm) (between the sprockets), "
                         f"got {l * 1e3:.6g} mm", field="crawler.cam_distance")
    E = float(spec.stiffness)
    w = float(drive.speed)
    kin = crawler_drive(t, z, w, guide=spec.guide, points=POINTS, stiffness=E, sprocket_distance=A, cam_distance=l)
    s = kin.summary
    psi = kin.psi
    gamma = math.pi / z
    v_mean = float(s["v_mean"])
    up = v_mean * psi / w
    on = guided_displacement if spec.guide == "tangent" else free_span_displacement
    u2 = np.asarray(on(psi, t, z))
    u1 = np.asarray(leaving_displacement(psi, t, z, spec.guide))
    fa = E * (up - u1) / l            # segment tensioning sprocket - cam
    fb = E * (u2 - up) / (A - l)      # segment cam - driving sprocket
    fa -= np.trapezoid(fa, psi) / kin.period
    fb -= np.trapezoid(fb, psi) / kin.period
    pull = float(loads.effective_pull)
    slack = float(loads.slack)
    force = pull + np.asarray(kin.force)
    ta = slack + fa
    tb = slack + pull + fb
    reaction_drive = reaction_tension = None
    if spec.guide == "tangent":
        s_phase = np.mod(psi, 2 * gamma)
        phi_on = np.asarray(guide_link_angle(psi, t, z))
        phi_off = np.asarray(guide_link_angle(np.clip(2 * gamma - s_phase, 0.0, 2 * gamma * (1 - 1e-12)), t, z))
        reaction_drive = float(np.max(guide_reaction(np.maximum(tb, 0.0), phi_on)))
        reaction_tension = float(np.max(guide_reaction(np.maximum(ta, 0.0), phi_off)))
    else:
        ctx.note("crawler: no guide, so the span moves sideways by the transverse throw and the cams "
                 "rub the traction chain (the crawler drive text); a guide tangent to the pitch circles stops it")
    pushing = float(cam_pushing_off_force(np.max(np.abs(force)), spec.cam_face_angle))
    range_elastic = lag = None
    try:
        grid = np.linspace(0.0, kin.period, LOOP_POINTS)
        k = float(s["cam_stiffness"])
        loop = elastic_loop(grid, t, z, E, A, l, v_mean * grid / w - pull / k, pretension=slack,
                            guide=spec.guide, return_guide=spec.return_guide)
        range_elastic = float(np.ptp(loop.force))
        lag = float(np.max(np.abs(loop.lag)))
    except InputError as exc:
        ctx.note(f"crawler: the elastic-loop check was not computed: {exc}")
    return CrawlerConveyor(
        guide=spec.guide, teeth=z, pitch_radius=float(kin.radius), sprocket_distance=A, cam_distance=l,
        mean_speed=v_mean, speed_nonuniformity=float(s["nonuniformity"]),
        acceleration_min=float(s["a_min"]), acceleration_max=float(s["a_max"]),
        transverse_throw=float(s["transverse_throw"]), cam_stiffness=float(s["cam_stiffness"]),
        traction_force=pull, pretension=slack,
        cam_force_min=float(force.min()), cam_force_max=float(force.max()),
        cam_force_range=float(s["force_range"]), cam_force_range_elastic=range_elastic,
        tensioning_sprocket_lag=lag,
        tensioning_side_tension_min=float(ta.min()), driving_side_tension_max=float(tb.max()),
        guide_reaction_driving=reaction_drive, guide_reaction_tensioning=reaction_tension,
        cam_pushing_off=pushing, cam_face_angle=float(spec.cam_face_angle), kinematics=kin,
    )


def crawler_checks(ctx: PartContext, r: CrawlerConveyor) -> list[Check]:
    out = [
        Check("cam stays on the traction-chain hinge (smallest cam force)", r.cam_force_min, 0.0, "N",
              bool(r.cam_force_min > 0), SOURCE,
              "the cam force is the effective pull plus the elastic chain's fluctuation", relation=">="),
        Check("tensioning-side segment stays taut (smallest tension)", r.tensioning_side_tension_min, 0.0, "N",
              bool(r.tensioning_side_tension_min > 0), SOURCE,
              "slack tension plus the fluctuation of the segment between the tensioning sprocket and the cam"),
    ]
    if r.cam_force_range_elastic is not None:
        ratio = r.cam_force_range_elastic / r.cam_force_range if r.cam_force_range > 0 else float("nan")
        out.append(Check("cam force fluctuation, elastic return span / rigid (the formula's assumption)",
                         ratio, None, "-", None, "docs/crawler.md (elastic loop)",
                         "free tensioning sprocket, return span as stiff as the working span", relation="info"))
    if r.guide_reaction_driving is not None and r.guide_reaction_tensioning is not None:
        out.append(Check("largest guide reaction (pushing-off force on the guide)",
                         max(r.guide_reaction_driving, r.guide_reaction_tensioning, r.cam_pushing_off), None, "N",
                         None, "the crawler drive text, Fig. 6.9 b; docs/crawler.md",
                         "T tan(phi1) at the guide's ends, P tan(alpha) at the cam", relation="info"))
    return out


register_part(Part("crawler_conveyor", "Conveyor crawler drive: cam force and guide reaction", crawler_conveyor,
                   needs=("loads",), checks=crawler_checks, order=36,
                   section="chaindrive.workflows.sections:crawler_section"))
