"""chaindrive: design and analysis of chain drives.

Layers (docs/architecture.md; tests/test_architecture.py keeps them apart)
--------------------------------------------------------------------------
1. Formulas: pure vectorised functions, one published formula each
   (``chaindrive.kinematics``, ``.vibration``, ``.strength``, ``.geometry``, ``.layout``,
   ``.loads``, ``.selection``, ``.wear``, ``.chains``, ``.self_regulating``,
   ``.simulation``), with ``chaindrive.units`` and ``chaindrive.limits``.
2. The description: the immutable ``Drive`` and its parts, project files
   (``chaindrive.drive``).
3. The analysis: declared parts, each drive-level decision once, typed results with
   units (``chaindrive.analysis``).
4. Presenters that only format: report (``chaindrive.workflows``), CLI
   (``chaindrive.cli``), web studio (``chaindrive.web``), studies (``chaindrive.study``),
   plots (``chaindrive.plotting``).

All quantities are SI (m, N, s, rad, kg, Pa, W) inside.
"""

from . import _interrupt

if _interrupt.is_command():  # Ctrl-C while the command starts: one line, exit 130
    _interrupt.install_early()

from .errors import (  # noqa: E402
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
