"""chaindrive: design and analysis of chain drives.

Layers
------
1. Pure vectorised functions, one published formula each (``chaindrive.geometry``,
   ``chaindrive.kinematics``, ``chaindrive.vibration``, ``chaindrive.strength``, ...).
2. Thin objects (``Chain``, ``Sprocket``, ``Drive``) passing their attributes to them.
3. Workflows: analysis pipeline, CLI, reports, web page.

All quantities are SI (m, N, s, rad, kg, Pa).
"""

from .errors import (
    ChainDriveError,
    ChainDriveWarning,
    ConvergenceError,
    InfeasibleError,
    InputError,
    UnknownNameError,
    ValidityRangeWarning,
)

__version__ = "0.1.0"

__all__ = [
    "ChainDriveError",
    "ChainDriveWarning",
    "ConvergenceError",
    "InfeasibleError",
    "InputError",
    "UnknownNameError",
    "ValidityRangeWarning",
    "__version__",
]
