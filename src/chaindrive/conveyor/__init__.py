r"""Chain pull of scraper (drag) chain conveyors: resistance to motion of a strand,
the material load, a free (hanging) strand, the mean tension of a closed loop and the
drive power.

All functions take and return SI units (N, m, kg, rad, W). The loop walk (which strand
is on the pans, where the drives sit, the tensioner) is
:mod:`chaindrive.analysis.conveyor`; these are its single formulas.

A strand on the pans changes the chain tension by friction and weight (Tsubakimoto,
*Large size conveyor chain, selection*, Table 3; :mod:`.pans`).

The package is split by topic: :mod:`.pans` (a strand on the pans, the material load, the
mean tension, the drive power) and :mod:`.catenary` (a free, hanging strand); every public
name is importable from :mod:`chaindrive.conveyor`.
"""

from __future__ import annotations

from .catenary import FreeStrand, free_strand, free_strand_minimum_tension
from .pans import (
    drive_power,
    material_mass_per_length,
    mean_tension,
    pan_end_clearance,
    pretension_for_minimum,
    strand_resistance,
)

__all__ = ["pan_end_clearance", "material_mass_per_length", "strand_resistance", "drive_power", "mean_tension",
           "FreeStrand", "free_strand", "free_strand_minimum_tension", "pretension_for_minimum"]
