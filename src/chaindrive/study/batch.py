"""A batch of study variants evaluated together (what a Dask task carries).

:func:`evaluate_batch` gives the same rows as :func:`~chaindrive.study.run.evaluate_variant`
called once per variant, faster:

1. each varied project path is probed once per batch: when the project loader maps its
   number linearly onto one field of the :class:`~chaindrive.drive.Drive` (a skew in
   arcmin onto ``contact.skew`` in rad, a mass, a stiffness, a speed), the variants set
   that field directly (the drive validates it again) instead of reading a whole
   project file each;
2. the variants that agree on every other varied path share one project read and go
   to :func:`chaindrive.analysis.batch.analyze_variants`, which computes the parts that
   do not read a varied field once;
3. each output is read from the part's JSON, computed once per distinct result object.

Rows equal those of the per-variant evaluation (tests compare every output to 1e-12).
"""

from __future__ import annotations

import copy
import dataclasses
import math
import re
import time
import warnings
from collections.abc import Sequence
from typing import Any

from .._results import Result, jsonable
from .spec import set_path
from .variant import evaluate_variant, lookup, one_line

__all__ = ["evaluate_batch", "evaluate_columns", "probe_path"]

_NUMBER = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*$")

#: Relative step of the probes and the tolerance of their linearity test.
_PROBE_STEP = 1e-3
_LINEAR_TOLERANCE = 1e-12


def _number(value: Any) -> tuple[float, str] | None:
    """(number, unit text) of a study value, or None for a value that is not a float
    quantity (whole numbers are counts: teeth, links, indices)."""
    if isinstance(value, bool) or isinstance(value, int):
        return None
    if isinstance(value, float):
        return (value, "") if math.isfinite(value) else None
    if isinstance(value, str):
        m = _NUMBER.match(value)
        if m is None:
            return None
        x = float(m.group(1))
        return (x, m.group(2)) if math.isfinite(x) else None
    return None


def _with(value: Any, x: float, unit: str) -> Any:
    return f"{x!r} {unit}".strip() if isinstance(value, str) else x


def _leaves(obj: Any, path: tuple[Any, ...] = ()) -> dict[tuple[Any, ...], Any]:
    """Every leaf of a drive (through dataclasses and tuples), by field path."""
    from ..chains import Chain

    if dataclasses.is_dataclass(obj) and not isinstance(obj, (type, Chain)):
        out: dict[tuple[Any, ...], Any] = {}
        for f in dataclasses.fields(obj):
            out.update(_leaves(getattr(obj, f.name), (*path, f.name)))
        return out
    if isinstance(obj, tuple) and obj and any(dataclasses.is_dataclass(v) for v in obj):
        out = {}
        for i, v in enumerate(obj):
            out.update(_leaves(v, (*path, i)))
        return out
    return {path: obj}


def probe_path(base: dict, inputs: dict[str, Any], path: str) -> tuple[tuple[Any, ...], float] | None:
    """``(field path, factor)`` when the project value at ``path`` maps linearly onto one
    field of the drive (field = factor × number), else ``None``.

    Three drives are read with the number at x, x(1 + 1e-3) and x(1 − 1e-3); exactly one
    leaf must change (or one number of a tuple of numbers, such as a wheel's position),
    and proportionally to 1e-12.
    """
    from ..drive.project import project_from_mapping

    parsed = _number(inputs[path])
    if parsed is None or parsed[0] == 0.0:
        return None
    x, unit = parsed
    drives = []
    for xi in (x, x * (1 + _PROBE_STEP), x * (1 - _PROBE_STEP)):
        data = copy.deepcopy(base)
        for p, v in inputs.items():
            set_path(data, p, _with(v, xi, unit) if p == path else v)
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                drives.append(_leaves(project_from_mapping(data, filename="probe")))
        except Exception:  # noqa: BLE001 - a probe outside the valid range: evaluate per variant
            return None
    first, second, third = drives
    changed = [k for k in first if first[k] is not second.get(k) and first[k] != second.get(k)]
    if len(changed) != 1 or set(first) != set(second) or set(first) != set(third):
        return None
    leaf = key = changed[0]
    values = (first[leaf], second[leaf], third[leaf])
    if all(isinstance(v, tuple) for v in values) and len({len(v) for v in values}) == 1:
        # a number inside a tuple of numbers (a wheel's position): that item is the leaf
        items = [j for j in range(len(values[0])) if values[0][j] != values[1][j]]
        if len(items) != 1 or any(values[0][j] != values[2][j] for j in range(len(values[0])) if j != items[0]):
            return None
        leaf = (*leaf, items[0])
        values = tuple(v[items[0]] for v in values)
    if not all(isinstance(v, float) and math.isfinite(v) for v in values):
        return None
    factor = values[0] / x
    for xi, v in zip((x * (1 + _PROBE_STEP), x * (1 - _PROBE_STEP)), values[1:], strict=True):
        if abs(v - factor * xi) > _LINEAR_TOLERANCE * max(abs(v), 1e-300):
            return None
    if any(first[k] != third[k] for k in first if k != key):
        return None
    return leaf, factor


def _reads(base: dict, inputs: dict[str, Any], path: str, x: float, unit: str | None) -> bool:
    """The project reads with the number ``x`` at ``path`` (the other inputs as given)."""
    from ..drive.project import project_from_mapping

    data = copy.deepcopy(base)
    for p, v in inputs.items():
        set_path(data, p, _with(v, x, unit or "") if p == path else v)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            project_from_mapping(data, filename="probe")
    except Exception:  # noqa: BLE001 - refused: those variants are read one by one
        return False
    return True


_MISSING = object()


class _Outputs:
    """The outputs of a row, each read with :func:`~chaindrive.study.run.lookup` from its
    head's JSON; a part's JSON and the outputs read from it once per distinct result
    object (the parts computed once serve every variant)."""

    def __init__(self, outputs: Sequence[str]) -> None:
        from ..analysis.parts import get_part, part_names

        self.lookup = lookup
        names = set(part_names())
        self.plan = [(out, out.split(".", 1)[0], out.split(".", 1)[1] if "." in out else None) for out in outputs]
        self.parts = {head: get_part(head) for _, head, _ in self.plan if head in names}
        self._cache: dict[int, list[Any]] = {}  # id -> [result, its JSON or _MISSING, {output: value}]
        self._names: dict[type, frozenset[str]] = {}
        from ._dynamics import wanted

        self.dynamics = wanted(outputs)
        #: the dynamics of rows computed together (:meth:`prepare`), by row
        self.steady: dict[int, Any] = {}

    def prepare(self, rows: Sequence[tuple[int, Any]]) -> None:
        """The dynamics of the rows ``(i, analysis)`` computed together
        (:func:`chaindrive.study._dynamics.dynamics_results`), when an output reads them."""
        if self.dynamics and rows:
            from ._dynamics import dynamics_results

            found = dynamics_results([analysis.drive for _, analysis in rows])
            self.steady.update(zip((i for i, _ in rows), found, strict=True))

    def _field(self, part: Any, result: Any, head: str, rest: str | None, out: str) -> Any:
        """The output read from the JSON of the one field it starts with, where the part's
        JSON is :meth:`Result.to_dict` (a dict of the fields' JSON, names without dots, so
        :func:`~chaindrive.study.run.lookup` finds nothing else); else ``_MISSING``."""
        cls = type(result)
        if rest is None or part.json is not None or not isinstance(result, Result) or cls.to_dict is not Result.to_dict:
            return _MISSING
        names = self._names.get(cls)
        if names is None:
            names = self._names[cls] = frozenset(f.name for f in dataclasses.fields(result))  # type: ignore[arg-type]
        first = rest.split(".", 1)[0]
        if first not in names:
            return _MISSING
        sub = jsonable(getattr(result, first))
        return sub if first == rest else self.lookup({head: {first: sub}}, out)

    def fill(self, columns: dict[str, list[Any]], i: int, analysis: Any) -> None:
        """Put the outputs of ``analysis`` at row ``i`` of ``columns``."""
        special: dict[str, Any] = {}
        if self.dynamics:
            # as evaluate_variant: a drive that cannot be simulated is the row's error,
            # every output of the row empty
            from ._dynamics import HEAD, dynamics_result

            try:
                found = self.steady.pop(i, None)
                if isinstance(found, Exception):
                    raise found
                special[HEAD] = found if found is not None else dynamics_result(analysis.drive)
            except Exception as exc:  # noqa: BLE001 - a failing variant is a result, not a stop
                columns["error"][i] = one_line(exc)
                return
        for out, head, rest in self.plan:
            part = self.parts.get(head)
            if part is not None:
                result = analysis.results.get(head)
                hit = self._cache.get(id(result))
                if hit is None or hit[0] is not result:
                    hit = [result, _MISSING, {}]
                    self._cache[id(result)] = hit
                values = hit[2]
                if out not in values:
                    value = self._field(part, result, head, rest, out)
                    if value is _MISSING:
                        if hit[1] is _MISSING:
                            hit[1] = part.to_json(result)
                        data = hit[1]
                        value = data[rest] if isinstance(data, dict) and rest in data else self.lookup({head: data}, out)
                    values[out] = value
                columns[out][i] = values[out]
                continue
            if out == "passed":
                columns[out][i] = analysis.passed
                continue
            if head not in special:
                if head == "passed":
                    special[head] = analysis.passed
                elif head == "checks":
                    special[head] = [c.to_dict() for c in analysis.checks]
                elif head == "warnings":
                    special[head] = list(analysis.warnings)
                elif head == "inputs":
                    special[head] = analysis.drive.inputs()

                else:  # not a head of the analysis' dict
                    special[head] = None
            columns[out][i] = self.lookup({head: special[head]}, out)


def evaluate_batch(base: dict, variants: Sequence[dict[str, Any]], outputs: Sequence[str], *,
                   parts: Sequence[str] = ()) -> list[dict[str, Any]]:
    """Rows of ``variants`` (each ``{project path: value}``), equal to
    ``[evaluate_variant(base, v, outputs, parts=parts) for v in variants]``
    (:func:`evaluate_columns`, one dict per variant).

    Examples
    --------
    >>> import tomllib
    >>> from chaindrive.drive.project import template
    >>> base = tomllib.loads(template("roller"))
    >>> rows = evaluate_batch(base, [{"drive.speed": "1450 rpm"}, {"drive.speed": "960 rpm"}],
    ...                       ["loads.chain_speed"])
    >>> [round(r["loads.chain_speed"], 3) for r in rows]
    [11.663, 7.722]
    """
    columns = evaluate_columns(base, variants, outputs, parts=parts)
    names = list(columns)
    return [dict(zip(names, values, strict=True)) for values in zip(*columns.values(), strict=True)]


def evaluate_columns(base: dict, variants: Sequence[dict[str, Any]], outputs: Sequence[str], *,
                     parts: Sequence[str] = ()) -> dict[str, list[Any]]:
    """The rows of :func:`evaluate_batch` as columns: ``{output: [value per variant], "error":
    [...], "warnings": [...], "seconds": [...], "cpu_seconds": [...]}`` (what a study's
    Parquet part file stores; no dict per variant)."""
    from ..analysis.batch import analyze_variants
    from ..drive.project import project_from_mapping

    n = len(variants)
    columns: dict[str, list[Any]] = {name: [None] * n for name in [*outputs, "error", "warnings"]}
    if not variants:
        columns.update(seconds=[], cpu_seconds=[])
        return columns
    timed: dict[int, tuple[float, float]] = {}  # variants evaluated on their own: their own times
    t0, c0 = time.perf_counter(), time.process_time()
    include = _include(outputs, parts)
    paths = list(variants[0])
    uniform = all(list(v) == paths for v in variants)
    fast: dict[str, tuple[tuple[Any, ...], float]] = {}
    numbers: dict[str, list[float]] = {}
    refused: set[int] = set()
    if uniform and len(variants) > 1:
        for path in paths:
            found = probe_path(base, variants[0], path)
            if found is None:
                continue
            parsed = [_number(v[path]) for v in variants]
            unit = parsed[0][1] if parsed[0] is not None else None
            if all(x is not None and x[1] == unit for x in parsed):
                xs = [x[0] for x in parsed]  # type: ignore[index]
                # the project reader's checks: its ranges hold between the extremes it takes;
                # else each value is tried, and a variant it refuses is read on its own
                if not (_reads(base, variants[0], path, min(xs), unit)
                        and _reads(base, variants[0], path, max(xs), unit)):
                    taken: dict[float, bool] = {}
                    for i, x in enumerate(xs):
                        if x not in taken:
                            taken[x] = _reads(base, variants[0], path, x, unit)
                        if not taken[x]:
                            refused.add(i)
                fast[path] = found
                numbers[path] = xs
    groups: dict[str, list[int]] = {}
    for i, v in enumerate(variants):
        key = repr(sorted((p, repr(x)) for p, x in v.items() if p not in fast)) \
            if uniform and i not in refused else str(i)
        groups.setdefault(key, []).append(i)
    outs = _Outputs(outputs)
    deferred: list[tuple[list[tuple[int, Any]], list[str], bool]] = []
    for members in groups.values():
        first = variants[members[0]]
        rows_of_group: list[tuple[int, Any]] = []
        try:
            data = copy.deepcopy(base)
            for path, value in first.items():
                set_path(data, path, value)
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always")
                drive = project_from_mapping(data, filename="variant")
            read_warnings = [str(w.message) for w in caught]
            # a group of one is its own base (its project read holds every value)
            changes = [{fast[p][0]: fast[p][1] * numbers[p][i] for p in fast} for i in members] \
                if len(members) > 1 else [{}]
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always")
                analyses = analyze_variants(drive, changes, include=include, errors="return")
            extra = read_warnings + [str(w.message) for w in caught]
            rows_of_group = list(zip(members, analyses, strict=True))
        except Exception as exc:  # noqa: BLE001 - the group's project fails: per variant, as before
            extra = []
            rows_of_group = [(i, exc) for i in members]
        deferred.append((rows_of_group, extra, len(members) > 1))
    # the dynamics of every analysed row at once (the drives stepped together), then the rows
    outs.prepare([(i, a) for rows_of_group, _, _ in deferred for i, a in rows_of_group
                  if not isinstance(a, BaseException)])
    for rows_of_group, extra, grouped in deferred:
        joined: dict[tuple[str, ...], str | None] = {}  # the warnings column, per distinct tuple
        for i, analysis in rows_of_group:
            if isinstance(analysis, BaseException):
                if grouped or fast:

                    row = evaluate_variant(base, variants[i], outputs, parts=parts)  # the exact message
                    for name in [*outputs, "error", "warnings"]:
                        columns[name][i] = row[name]
                    timed[i] = (row["seconds"], row["cpu_seconds"])
                else:
                    columns["error"][i] = one_line(analysis)
                continue
            outs.fill(columns, i, analysis)
            own = analysis.warnings
            if own not in joined:
                messages = list(dict.fromkeys([*own, *extra]))
                joined[own] = " | ".join(messages)[:2000] if messages else None
            columns["warnings"][i] = joined[own]
    seconds = (time.perf_counter() - t0) / n
    cpu = (time.process_time() - c0) / n
    columns["seconds"] = [seconds] * n
    columns["cpu_seconds"] = [cpu] * n
    for i, (wall, spent) in timed.items():
        columns["seconds"][i], columns["cpu_seconds"][i] = wall, spent
    return columns


def _include(outputs: Sequence[str], parts: Sequence[str]) -> list[str] | None:
    """The parts to compute: as :func:`chaindrive.study.run.analysis_result` chooses them."""
    from ..analysis.parts import part_names

    if not parts or set(parts) & {"passed", "checks", "warnings"}:
        return None
    names = part_names()
    return [p for p in parts if p in names] or None
