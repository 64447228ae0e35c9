"""The wheel geometry objects of a drive (ISO 606 sprockets, pocket wheels, track drive wheels)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from .._results import Result, quantity
from ..drive.model import Drive, Wheel
from .parts import Part, register_part

if TYPE_CHECKING:
    from ..geometry.pocket_wheel import PocketWheel, PocketWheelDimensions
    from ..geometry.sprocket import Sprocket, SprocketDimensions
    from ..geometry.track_wheel import TrackDriveWheel, TrackDriveWheelDimensions

__all__ = ["WheelGeometry", "wheel_geometry", "drive_geometry", "ISO_MINIMUM_TEETH"]

#: Smallest tooth count of the ISO 606:2015 clause 5 sprocket form.
ISO_MINIMUM_TEETH = 9


@dataclass(frozen=True)
class WheelGeometry(Result):
    """One toothed wheel: its kind, the geometry object and its dimensions."""

    wheel: str
    kind: str
    teeth: int = quantity("1")
    basis: str
    object: Sprocket | PocketWheel | TrackDriveWheel

    def dimensions(self) -> SprocketDimensions | PocketWheelDimensions | TrackDriveWheelDimensions:
        return self.object.dimensions()

    def to_dict(self) -> dict[str, Any]:
        return {"wheel": self.wheel, "kind": self.kind, "teeth": self.teeth, "basis": self.basis,
                **self.dimensions().to_dict()}


def wheel_geometry(drive: Drive, wheel: Wheel) -> WheelGeometry | None:
    """The geometry of ``wheel`` on ``drive``'s chain, or ``None`` where no form applies.

    Round link chains: a pocket wheel (Dolipiński et al., eq. (6)). Track wheels: the
    track drive wheel of Sharipov (pin radius from ``[track]``, else the roller). Roller
    chains: the ISO 606 sprocket, for ``z >= 9`` (ISO 606:2015 clause 5).
    """
    from ..geometry import PocketWheel, Sprocket, TrackDriveWheel

    c = drive.chain
    if wheel.teeth is None:
        return None
    if c.is_link_chain:
        return WheelGeometry(wheel.name, "pocket wheel", wheel.teeth, "Dolipiński et al., eq. (6)",
                             PocketWheel.from_chain(c, wheel.teeth))
    if wheel.kind == "track_wheel":
        r = drive.track.pin_radius if drive.track is not None else (c.roller_diameter / 2 if c.roller_diameter else None)
        if r is None:
            return None
        link = drive.track.link if drive.track is not None else "built-up"
        return WheelGeometry(wheel.name, "track drive wheel", wheel.teeth, "Sharipov, p. 34",
                             TrackDriveWheel(pitch=c.pitch, teeth=wheel.teeth, pin_radius=r, link=link, name=wheel.name,
                                             elongation_limit=drive.elongation_limit))
    if wheel.teeth < ISO_MINIMUM_TEETH:
        return None
    return WheelGeometry(wheel.name, "sprocket", wheel.teeth, "ISO 606:2015 clause 5",
                         Sprocket.from_chain(c, wheel.teeth))


def drive_geometry(drive: Drive) -> tuple[WheelGeometry, ...]:
    """:func:`wheel_geometry` of every toothed wheel that has a form."""
    out = (wheel_geometry(drive, w) for w in drive.wheels)
    return tuple(g for g in out if g is not None)


# --------------------------------------------------------------------------- declared parts
register_part(Part("geometry", "Wheel geometry", lambda ctx: drive_geometry(ctx.drive), order=60,
                   section="chaindrive.workflows.sections:geometry_section",
                   json=lambda wheels: {g.wheel: g.to_dict() for g in wheels}))
