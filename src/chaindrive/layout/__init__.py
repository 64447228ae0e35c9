r"""Drive layout: chain length, centre distance, wrap, spans, sag, tensioner travel.

Three models of the chain path are provided:

* **continuous approximation** (:func:`chain_length_approx`,
  :func:`centre_distance_approx`): the textbook/ISO 10823 formula in pitches;
* **pitch circles, exact tangents** (:func:`chain_length_circles`,
  :func:`wrap_layout`): the chain as a belt on the pitch circles (the "belt problem"),
  exact for the circles, for two or more wheels and idlers;
* **pitch polygons** (:func:`chain_length_polygon`, :func:`centre_distance_polygon`):
  the taut chain is the boundary of the convex hull of the pitch polygons of the two
  wheels; its length depends on the phases of the wheels. See the function notes.
  Any number of wheels, inside or outside the loop, toothed or toothless:
  :func:`chain_length_loop`, :func:`adjust_loop` (one wheel moved to fit the links).

All lengths in metres, angles in radians, chain lengths in pitches (links).
"""

from .placement import clearance_problems, place_for_wrap
from .polygon_loop import (
    LoopAdjustment,
    LoopLength,
    adjust_loop,
    chain_length_loop,
    loop_length_at_phases,
)
from .sag import GRAVITY, catenary_sag, parabolic_sag, tension_for_sag
from .travel import centre_distance_travel, tensioner_travel

# the private helpers (_name) are reached as chaindrive.layout._name by tests and benchmarks
from .two_wheels import (  # noqa: F401
    MAX_PHASE_GRID,
    PolygonCentreDistance,
    PolygonLength,
    _belt_length,
    _check_phases,
    _hull_perimeter,
    _hull_perimeters,
    _polygon_links,
    centre_distance_approx,
    centre_distance_polygon,
    chain_length_approx,
    chain_length_circles,
    chain_length_polygon,
    even_links,
)
from .wheels import (
    _radius_and_offsets,  # noqa: F401
    pitch_polygon_vertices,
    pitch_radius,
)
from .wrap import (
    WrapLayout,
    _loop_lengths,  # noqa: F401
    teeth_in_mesh,
    wrap_layout,
)

__all__ = [
    "GRAVITY",
    "pitch_radius",
    "pitch_polygon_vertices",
    "chain_length_approx",
    "centre_distance_approx",
    "chain_length_circles",
    "chain_length_polygon",
    "centre_distance_polygon",
    "even_links",
    "PolygonLength",
    "PolygonCentreDistance",
    "wrap_layout",
    "WrapLayout",
    "chain_length_loop",
    "loop_length_at_phases",
    "adjust_loop",
    "LoopLength",
    "LoopAdjustment",
    "teeth_in_mesh",
    "catenary_sag",
    "parabolic_sag",
    "tension_for_sag",
    "tensioner_travel",
    "clearance_problems",
    "place_for_wrap",
    "centre_distance_travel",
]
