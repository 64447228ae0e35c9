"""Wear life of a drive's chain: elongation over hours to the limit."""

from __future__ import annotations

from ..drive.model import Drive
from ..errors import InputError
from ..life import wear as W
from .checks import Check
from .layout import DriveLayout
from .loads import DriveLoads
from .parts import Part, PartContext, register_part
from .rating import DriveRating

__all__ = ["drive_wear"]


def drive_wear(drive: Drive, layout: DriveLayout, loads: DriveLoads, rating: DriveRating | None,
               model: str | None = None) -> W.WearLife | None:
    """Elongation over hours and hours to ``drive.elongation_limit``.

    ``"rating"`` (ANSI/ACA 15 000 h basis) for roller chains with a rating; ``"archard"``
    (wear of the joints) when ``drive.wear_coefficient`` is given (any chain). ``None``
    when neither applies (a link chain without a wear coefficient).

    References
    ----------
    docs/drive.md (wear life); :func:`chaindrive.life.wear.wear_life`.
    """
    nw = len(drive.wheels)
    if model is None:
        model = "archard" if drive.wear_coefficient is not None else "rating"
    if model == "rating":
        if rating is None:
            return None
        return W.wear_life("rating", rated_power=rating.rating.rated_power, power=drive.design_power(),
                           links=layout.links, elongation_limit=drive.elongation_limit, wheels=nw)
    ch = drive.chain
    if ch.bar_diameter is not None:  # a round link chain
        d = ch.bar_diameter
        area, radius = d * d, d / 2
    else:
        if ch.pin_diameter is None or ch.inner_width is None:
            raise InputError(f"chain {ch.name!r} needs pin_diameter and inner_width for the archard wear model",
                             field="chain")
        area, radius = ch.pin_diameter * ch.inner_width * ch.strands, ch.pin_diameter / 2
    zmin = min(w.sides_per_turn(ch) for w in drive.wheels if w.teeth is not None)
    return W.wear_life("archard", tension=loads.tight, bearing_area=area, joint_radius=radius, teeth=zmin,
                       chain_speed=loads.chain_speed, links=layout.links, pitch=drive.pitch,
                       wear_coefficient=drive.wear_coefficient, elongation_limit=drive.elongation_limit, wheels=nw)


# --------------------------------------------------------------------------- declared parts
def _wear_part(ctx: PartContext) -> W.WearLife | None:
    life = drive_wear(ctx.drive, ctx["layout"], ctx["loads"], ctx["rating"])
    if life is None:
        ctx.note("wear life: no wear model applies (a link chain needs wear_coefficient in [drive])")
    return life


def _wear_checks(ctx: PartContext, life: W.WearLife) -> list[Check]:
    return [Check("hours to the elongation limit", float(life.hours_to_limit), None, "h", None,
                  "ANSI/ACA 15 000 h basis" if life.model == "rating" else "Archard wear of the joints",
                  relation="info")]


register_part(Part("wear", "Wear life", _wear_part, needs=("layout", "loads", "rating"), checks=_wear_checks,
                   order=90, section="chaindrive.workflows.sections:wear_section"))
