r"""Chain loads: tight- and slack-side tension, centrifugal tension, dynamic load,
shaft loads, static safety, service factors.

All functions take and return SI units (N, N·m, W, m, rad/s, kg). The package is split by
topic (:mod:`.speed`, :mod:`.tensions`, :mod:`.dynamic`, :mod:`.safety`, :mod:`.service`);
every public name is importable from :mod:`chaindrive.loads`.
"""

from __future__ import annotations

from .dynamic import (
    POLYGONAL_DAMPING_RATIO,
    disc_inertia,
    dynamic_factor,
    dynamic_tension,
    free_entry_acceleration_peak,
    polygonal_dynamic_tension,
)
from .safety import (
    PEAK_TENSION_RATIO,
    REQUIRED_SAFETY_PITCHES,
    REQUIRED_SAFETY_SPEEDS,
    REQUIRED_SAFETY_TABLE,
    REQUIRED_STATIC_SAFETY,
    outside_required_safety_table,
    required_static_safety_for,
    required_static_safety_table,
    static_safety,
    static_safety_factor,
)
from .service import SERVICE_FACTORS, service_factor
from .speed import (
    chain_speed,
    mean_chain_speed,
    power_from_torque,
    sides_per_turn,
    torque_from_power,
)
from .tensions import centrifugal_tension, shaft_load, tight_side_tension

__all__ = [
    "torque_from_power",
    "power_from_torque",
    "chain_speed",
    "mean_chain_speed",
    "sides_per_turn",
    "tight_side_tension",
    "centrifugal_tension",
    "free_entry_acceleration_peak",
    "dynamic_tension",
    "polygonal_dynamic_tension",
    "disc_inertia",
    "POLYGONAL_DAMPING_RATIO",
    "dynamic_factor",
    "shaft_load",
    "static_safety_factor",
    "static_safety",
    "required_static_safety_table",
    "required_static_safety_for",
    "outside_required_safety_table",
    "REQUIRED_SAFETY_PITCHES",
    "REQUIRED_SAFETY_SPEEDS",
    "REQUIRED_SAFETY_TABLE",
    "PEAK_TENSION_RATIO",
    "service_factor",
    "SERVICE_FACTORS",
    "REQUIRED_STATIC_SAFETY",
]

