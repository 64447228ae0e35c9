"""Planar dynamic simulation of a chain drive (point-mass pins, elastic links,
penalty roller-tooth contact, guides, tensioner, gravity), compiled with numba.

See ``docs/simulation.md`` for the model, the integrator and the validation.
"""

from .model import (
    AXIAL_STIFFNESS_16B,
    SimGuide,
    SimTensioner,
    SimulationModel,
    SimWheel,
    roller_example,
)
from .run import SimulationResult, State, assemble, simulate

__all__ = ["AXIAL_STIFFNESS_16B", "SimGuide", "SimTensioner", "SimulationModel", "SimWheel",
           "roller_example", "SimulationResult", "State", "assemble", "simulate"]
