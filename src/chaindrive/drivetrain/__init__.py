"""What drives the chain: the induction motor on the Kloss curve (:mod:`.motor`) and the
constant-fill fluid coupling between motor and wheel (:mod:`.coupling`).

Every public name of both modules is importable from :mod:`chaindrive.drivetrain`.
"""

from __future__ import annotations

from . import coupling, motor
from .coupling import *  # noqa: F403
from .motor import *  # noqa: F403

__all__ = [*motor.__all__, *coupling.__all__]
