"""One variant of a study: its drive built from the base project and the variant's inputs,
its analysis as a JSON-ready dict, and its outputs looked up by path (the per-variant path;
:mod:`chaindrive.study.batch` evaluates many variants together and falls back on this one)."""

from __future__ import annotations

import time
import warnings
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from .._results import jsonable
from .spec import set_path

if TYPE_CHECKING:
    from ..drive.model import Drive

__all__ = ["analysis_result", "lookup", "one_line", "evaluate_variant"]


def analysis_result(drive: Drive, parts: Sequence[str] = ()) -> dict[str, Any]:
    """The analysis of ``drive`` as a JSON-ready dict (SI units): the one adapter a study
    evaluates through.

    Parameters
    ----------
    drive : chaindrive.drive.Drive
    parts : sequence of str
        Top-level parts the outputs need (``"loads"``, ``"contact"``, ...); the analysis
        may skip the others.

    Returns
    -------
    dict
        Keys ``layout``, ``loads``, ``rating``, ``entry``, ``vibration``, ``geometry``,
        ``contact``, ``track_tooth``, ``wear``, ``checks``, ``warnings``, ``passed``.

    Notes
    -----
    The verdict ``passed`` and the list ``checks`` cover the parts computed: when an
    output asks for them, every part is computed.

    References
    ----------
    :func:`chaindrive.analysis.analyze_drive` (docs/analysis.md) cites the source of
    every part.

    Examples
    --------
    >>> from chaindrive.drive.project import parse_project, template
    >>> r = analysis_result(parse_project(template("roller")), ["loads"])
    >>> round(r["loads"]["effective_pull"]), r["contact"]
    (1934, None)
    """
    from ..analysis import analyze_drive
    from ..analysis.parts import part_names

    include = None
    if parts and not set(parts) & {"passed", "checks", "warnings"}:
        names = part_names()
        include = [p for p in parts if p in names] or None
    return analyze_drive(drive, include=include).to_dict()


def lookup(result: Any, path: str) -> Any:
    """The value at a dotted ``path`` of a result dict (``None`` where there is none).

    List entries are reached by index, list entries that are dicts with a ``name`` also by
    that name (``"checks.static safety.passed"``).

    Examples
    --------
    >>> r = {"loads": {"maximum": 3.0}, "checks": [{"name": "wrap", "passed": True}]}
    >>> lookup(r, "loads.maximum"), lookup(r, "checks.wrap.passed"), lookup(r, "wear.hours")
    (3.0, True, None)
    """
    node = result
    parts = path.split(".")
    i = 0
    while i < len(parts):
        if node is None:
            return None
        if isinstance(node, dict):
            # keys may themselves hold dots ("drive: free"): the longest match wins
            for j in range(len(parts), i, -1):
                key = ".".join(parts[i:j])
                if key in node:
                    node, i = node[key], j
                    break
            else:
                return None
            continue
        if isinstance(node, list):
            part = parts[i]
            if part.lstrip("-").isdigit() and -len(node) <= int(part) < len(node):
                node, i = node[int(part)], i + 1
                continue
            for j in range(len(parts), i, -1):
                name = ".".join(parts[i:j])
                hit = next((e for e in node if isinstance(e, dict) and e.get("name") == name), None)
                if hit is not None:
                    node, i = hit, j
                    break
            else:
                return None
            continue
        return None
    return node


def one_line(exc: BaseException) -> str:
    """An exception as one line (type and message, at most 1,000 characters): a row's error."""
    text = " ".join(part.strip() for part in str(exc).splitlines() if part.strip())
    text = f"{type(exc).__name__}: {text}" if text else type(exc).__name__
    return text[:1000]


def evaluate_variant(base: dict, inputs: dict[str, Any], outputs: Sequence[str], *,
                     parts: Sequence[str] = (), simulation: dict | None = None,
                     filename: str = "<study>") -> dict[str, Any]:
    """Build one variant's drive and return ``{output: value, "error": ..., "warnings": ...}``.

    Any exception becomes the ``error`` message of the row (outputs ``None``): a study
    never stops for one variant.

    Examples
    --------
    >>> import tomllib
    >>> from chaindrive.drive.project import template
    >>> base = tomllib.loads(template("roller"))
    >>> row = evaluate_variant(base, {"drive.speed": "1450 rpm"}, ["loads.chain_speed"])
    >>> round(row["loads.chain_speed"], 3), row["error"]
    (11.663, None)
    >>> evaluate_variant(base, {"wheels.0.teeth": 2}, ["loads.maximum"])["error"]
    'InputError: variant: wheels[0].teeth: must be a whole number in [3, 10000], got 2'
    """
    import copy

    from ..drive.project import project_from_mapping
    from . import _dynamics as dynamics

    row: dict[str, Any] = dict.fromkeys(outputs)
    row["error"] = None
    row["warnings"] = None
    t0, c0 = time.perf_counter(), time.process_time()
    noted: list[str] = []
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            data = copy.deepcopy(base)
            for path, value in inputs.items():
                set_path(data, path, value)
            drive = project_from_mapping(data, filename="variant")
            result = analysis_result(drive, parts)
            if simulation is not None:
                from ..simulation import model_from_drive, simulate

                sim = simulate(model_from_drive(drive), simulation["duration"],
                               samples=simulation["samples"])
                result["simulation"] = jsonable(sim.summary)
            if dynamics.wanted(outputs):
                result[dynamics.HEAD] = dynamics.dynamics_result(drive)
            noted = [str(w) for w in result.get("warnings") or ()]
            for out in outputs:
                row[out] = lookup(result, out)
        except Exception as exc:  # noqa: BLE001 - a failing variant is a result, not a stop
            row["error"] = one_line(exc)
    messages = list(dict.fromkeys(noted + [str(w.message) for w in caught]))
    if messages:
        row["warnings"] = " | ".join(messages)[:2000]
    row["seconds"] = time.perf_counter() - t0
    row["cpu_seconds"] = time.process_time() - c0
    return row
