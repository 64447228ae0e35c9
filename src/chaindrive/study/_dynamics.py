"""The ``dynamics.*`` outputs of a study: the running drive's steady state per variant.

``dynamics.mean_tension``, ``dynamics.peak_tension``, ``dynamics.period_peak_tension``,
``dynamics.max_tension``, ... are the fields of
:class:`chaindrive.simulation.steady.SteadyState` (SI units) of the variant's drive
(:func:`chaindrive.simulation.model_from_drive`, then
:func:`chaindrive.simulation.steady_state` with its defaults): the tight-span tension of
the running drive, about 0.1 s of computing per 100-link roller drive. Computed only
when an output asks for them. The variants of a batch go through
:func:`dynamics_results`: one ``steady_state`` per variant (``LANES = 0``, the default),
or, with ``LANES`` > 0, :func:`chaindrive.simulation.steady_lanes.steady_states_implicit`
(the implicit steps of up to ``LANES`` drives taken together by the batched implicit
kernel), whose every result is the one ``steady_state`` gives the variant alone, to the
last bit (``cpu_time`` apart: the batched one is the variant's share). The default is the
per-variant path because it measured faster: 1,000 variants of
``examples/roller_industrial.toml`` on two workers, 261 s against 346 s with 64 lanes
(``benchmarks/study.py --dynamic 1000``, docs/studies.md).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

__all__ = ["HEAD", "LANES", "wanted", "dynamics_result", "dynamics_results"]

#: The head of the outputs (``dynamics.peak_tension``).
HEAD = "dynamics"

#: Drives stepped together by :func:`dynamics_results` (0: one ``steady_state`` per
#: variant, the default; the results are the same to the last bit).
LANES = 0


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


def dynamics_results(drives: Sequence[Any]) -> list[dict[str, Any] | Exception]:
    """The steady states of many drives as JSON-ready data (SI units), each equal to
    :func:`dynamics_result` of the drive alone; a drive that cannot be simulated gives its
    exception in its place.

    Examples
    --------
    >>> from chaindrive.drive.project import load_project
    >>> d = load_project("examples/roller_industrial.toml")
    >>> [r["peak_tension"] == dynamics_result(d)["peak_tension"] for r in dynamics_results([d])]
    [True]
    """
    from ..simulation import model_from_drive
    from ..simulation.steady_lanes import steady_states_implicit

    if not LANES:
        out: list[dict[str, Any] | Exception] = []
        for drive in drives:
            try:
                out.append(dynamics_result(drive))
            except Exception as exc:  # noqa: BLE001 - one variant's failure is its result
                out.append(exc)
        return out
    models: list[Any] = []
    for drive in drives:
        try:
            models.append(model_from_drive(drive))
        except Exception as exc:  # noqa: BLE001 - one variant's failure is its result
            models.append(exc)
    ok = [m for m in models if not isinstance(m, Exception)]
    found = iter(steady_states_implicit(ok, lanes=LANES) if ok else [])
    return [m if isinstance(m, Exception) else _json(next(found)) for m in models]


def _json(result: Any) -> Any:
    return result if isinstance(result, Exception) else result.to_dict()
