r"""The design layer: from a duty to the drive an engineer signs.

:func:`design_drive` answers a :class:`DesignRequest` (the duty and the constraints of the
selection, checked when built) and runs the procedure once (docs/design.md): duty -> service factor
(:mod:`chaindrive.design.duty`) -> tooth-count policy (:mod:`chaindrive.design.policy`) -> candidate chains rated by the
method of their family (:mod:`chaindrive.rating`) -> layout with an even link count and
the exact centre distance -> the analysis (loads, static safety, rating checks) -> advice
(:mod:`chaindrive.design.advice`). The Python API, ``chaindrive select``, the design studio and studies
call it.

Examples
--------
>>> import math
>>> duty = Duty(11e3, 1460 * math.pi / 30, driven_speed=480 * math.pi / 30,
...             driven_machine="varying_conveyor", centre_distance=0.6)
>>> design_drive(duty).recommended.chain
'12A-1'
>>> design_drive(DesignRequest(duty, strands=(1,))).drive().links
104
"""

from .advice import drive_advice
from .duty import Duty, Factor, duty_factors, service_factor_table, service_factor_text
from .procedure import DesignCandidate, DesignResult, design_drive, project_text
from .rating import rate_chain
from .request import DesignRequest

__all__ = ["Duty", "Factor", "DesignRequest", "DesignCandidate", "DesignResult", "design_drive", "duty_factors",
           "service_factor_table", "service_factor_text", "drive_advice", "project_text", "rate_chain"]
