"""Planar dynamic simulation of a chain drive (point-mass pins, elastic links,
penalty roller-tooth contact, guides, tensioner, gravity), compiled with numba.

Roller chains on sprockets and round link chains on pocket wheels (links ``t + d`` and
``t − d`` alternating, seats on the bi-regular polygon of Dolipiński et al. eq. (6)).

See ``docs/simulation.md`` for the model, the integrator and the validation.
"""

from .examples import link_example, roller_example
from .from_drive import (
    channel_guides,
    conveyor_drive,
    conveyor_example,
    guide_channel,
    model_from_drive,
)
from .model import (
    AXIAL_STIFFNESS_16B,
    SimGuide,
    SimTensioner,
    SimulationModel,
    SimWheel,
)
from .run import SimulationResult, State, assemble, simulate
from .startup import start_up
from .steady import SteadyState, steady_state

__all__ = ["start_up", "AXIAL_STIFFNESS_16B", "SimGuide", "SimTensioner", "SimulationModel", "SimWheel",
           "roller_example", "link_example", "conveyor_drive", "conveyor_example", "model_from_drive", "guide_channel", "channel_guides", "SimulationResult", "State", "assemble", "simulate",
           "SteadyState", "steady_state"]
