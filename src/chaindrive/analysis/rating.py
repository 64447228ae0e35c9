"""The power rating of a drive's chain on its smallest toothed wheel, by its family's method (ANSI/ACA or ISO 10823)."""

from __future__ import annotations

from dataclasses import dataclass

from .._results import Result
from ..drive.model import Drive
from ..selection import ChainRating, chain_rating
from .checks import Check
from .parts import Part, PartContext, register_part

__all__ = ["DriveRating", "drive_rating", "rating_checks"]


@dataclass(frozen=True)
class DriveRating(Result):
    """The rating of the chain on the smallest toothed, non-idler wheel of a drive.

    Attributes
    ----------
    wheel : str
        The wheel the rating is taken on.
    rating : ChainRating
        Link-plate and roller–bushing limits, galling and lubrication region
        (:func:`chaindrive.selection.chain_rating`) at the design power.
    """

    wheel: str
    rating: ChainRating

    def to_dict(self) -> dict:
        return {"wheel": self.wheel, **self.rating.to_dict()}


def drive_rating(drive: Drive) -> DriveRating | None:
    """Power rating of ``drive``'s chain on its smallest toothed wheel by its family's method.

    ANSI/ACA (Shigley eqs (17-32), (17-33), §17-5) or ISO 10823 (ISO 606 B series), as
    :func:`chaindrive.rating.default_method` says.

    ``None`` for chains outside the method: round link chains, custom chains (crawler and
    track chains are not ANSI roller chains), more than 4 strands.

    >>> from chaindrive.chains import get
    >>> from chaindrive.drive import Drive, Wheel, Load
    >>> d = Drive(chain=get("16B"), speed=100.53, load=Load(power=15e3),
    ...           wheels=[Wheel("motor", "sprocket", 19, (0, 0), driving=True),
    ...                   Wheel("fan", "sprocket", 57, (1.05, 0))])
    >>> r = drive_rating(d)
    >>> r.wheel, r.rating.governing_limit
    ('motor', 'link_plate')
    """
    chain = drive.chain
    if chain.family not in ("iso606", "ansi") or chain.strands > 4:
        return None
    om = drive.angular_velocities()
    z, omega, name = min((w.teeth, float(o), w.name) for w, o in zip(drive.wheels, om, strict=True)
                         if w.teeth is not None and w.kind != "idler")
    return DriveRating(name, chain_rating(chain, z, omega, power=drive.design_power()))


def rating_checks(drive: Drive, rating: DriveRating) -> tuple[Check, ...]:
    """Rated power ``>=`` design power; the joints outside the galling region."""
    r = rating.rating
    design = drive.design_power()
    return (
        Check(name="rated power >= design power", value=r.rated_power, limit=design, unit="W",
              passed=bool(r.rated_power >= design), source=r.source,
              note=f"governed by {r.governing_limit.replace('_', '-')}"),
        Check(name="speed below the galling limit", value=r.angular_velocity, limit=r.galling_speed, unit="rad/s",
              passed=not r.galling_exceeded, relation="<=", source="ACA galling limit; Shigley §17-5",
              note=f"lubrication {r.lubrication}: {r.lubrication_method}"),
    )


# --------------------------------------------------------------------------- declared parts
def _rating_part(ctx: PartContext) -> DriveRating | None:
    rating = drive_rating(ctx.drive)
    for text in () if rating is None else rating.rating.warnings:
        ctx.note(text)
    return rating


register_part(Part("rating", "Power rating", _rating_part, checks=lambda ctx, r: rating_checks(ctx.drive, r),
                   order=30, section="chaindrive.workflows.sections:loads_section"))
