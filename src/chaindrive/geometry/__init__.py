"""Wheel geometry: pitch polygons, sprockets, pocket wheels, track drive wheels."""

from . import iso606 as _iso606
from .iso606 import *  # noqa: F403 - the ISO 606 formulas, named once in iso606.__all__
from .outline import Arc, Line, Outline
from .pocket_wheel import PocketWheel, PocketWheelDimensions, pocket_angles
from .polygon import (
    bi_regular_polygon,
    link_chain_central_angles,
    link_chain_pitch_radius,
    roller_chain_pitch_radius,
)
from .sprocket import AnsiToothForm, Sprocket, SprocketDimensions, ansi_tooth_form, sprocket_outline
from .track_wheel import (
    TrackDriveWheel,
    TrackDriveWheelDimensions,
    pin_seat_radius_range,
    root_radius,
    root_radius_range,
    tip_radius,
    tip_radius_range,
    track_wheel_pitch_radius,
)

__all__ = [
    "bi_regular_polygon",
    "link_chain_central_angles",
    "link_chain_pitch_radius",
    "roller_chain_pitch_radius",
    # outlines
    "Arc",
    "Line",
    "Outline",
    # sprockets (ISO 606:2015 clause 5, ASME B29.1)
    "Sprocket",
    "SprocketDimensions",
    "AnsiToothForm",
    "ansi_tooth_form",
    "sprocket_outline",
    # pocket wheels (Dolipiński et al.)
    "PocketWheel",
    "PocketWheelDimensions",
    "pocket_angles",
    # track drive wheels (Sharipov)
    "TrackDriveWheel",
    "TrackDriveWheelDimensions",
    "track_wheel_pitch_radius",
    "pin_seat_radius_range",
    "root_radius",
    "root_radius_range",
    "tip_radius",
    "tip_radius_range",
]
__all__ += [name for name in _iso606.__all__ if not name.isupper()]
