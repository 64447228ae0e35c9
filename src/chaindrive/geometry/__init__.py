"""Wheel geometry: pitch polygons, sprockets, pocket wheels, track drive wheels."""

from .polygon import (
    bi_regular_polygon,
    link_chain_central_angles,
    link_chain_pitch_radius,
    roller_chain_pitch_radius,
)

__all__ = [
    "bi_regular_polygon",
    "link_chain_central_angles",
    "link_chain_pitch_radius",
    "roller_chain_pitch_radius",
]
