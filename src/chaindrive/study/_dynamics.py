"""The ``dynamics.*`` outputs of a study: the running drive's steady state per variant.

``dynamics.mean_tension``, ``dynamics.peak_tension``, ``dynamics.period_peak_tension``,
``dynamics.max_tension``, ... are the fields of
:class:`chaindrive.simulation.steady.SteadyState` (SI units) of the variant's drive
(:func:`chaindrive.simulation.model_from_drive`, then
:func:`chaindrive.simulation.steady_state` with its defaults): the tight-span tension of
the running drive, about 0.1 s of computing per 100-link roller drive. Computed only
when an output asks for them.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

__all__ = ["HEAD", "wanted", "dynamics_result"]

#: The head of the outputs (``dynamics.peak_tension``).
HEAD = "dynamics"


def wanted(outputs: Sequence[str]) -> bool:
    """Whether any output reads the dynamics."""
    return any(out.split(".", 1)[0] == HEAD for out in outputs)


def dynamics_result(drive: Any) -> dict[str, Any]:
    """The steady state of ``drive`` as JSON-ready data (SI units).

    Examples
    --------
    >>> from chaindrive.drive.project import load_project
    >>> d = dynamics_result(load_project("examples/roller_industrial.toml"))
    >>> d["peak_tension"] >= d["mean_tension"] > 0
    True
    """
    from ..simulation import model_from_drive
    from ..simulation.steady import steady_state

    return steady_state(model_from_drive(drive)).to_dict()
