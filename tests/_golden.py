"""The golden regression of the examples' results.json (used by tests/test_golden.py and
scripts/regen_golden.py): every field compared by its JSON path with a tolerance."""

from __future__ import annotations

import json
import math
import re
from collections.abc import Iterator
from pathlib import Path
from typing import Any

from _shared import EXAMPLES

#: Stored results, one file per example project.
GOLDEN = Path(__file__).resolve().parent / "data" / "golden"
#: The example projects (the study files are no projects).
NAMES = ("roller_industrial", "mining_conveyor", "tractor_track", "self_regulating", "long_conveyor",
         "crawler_conveyor")
#: Tolerance of a number: |new - old| <= REL |old| + ABS.
REL, ABS = 1e-9, 1e-12
#: Keys that change with every run (the date, the wall-clock timings, the file path).
VOLATILE = ("created", "timings_s", "subtitle")
#: Paths (regular expressions) that may appear without being in the stored file: a new
#: output added on purpose (a new analysis part or result field). Add the pattern with the
#: change that adds the output, then regenerate (scripts/regen_golden.py).
ALLOWED_ADDED: tuple[str, ...] = (
    r"^analysis\.life\b",                      # the analysis part `life` (#32, docs/life.md)
    r"^sections\.The drive over its life\b",   # its report section
)


def leaves(value: Any, path: str = "") -> Iterator[tuple[str, Any]]:
    """(JSON path, leaf value) of every leaf of a JSON document."""
    if isinstance(value, dict):
        if not value:
            yield path, {}
        for k, v in value.items():
            if path == "" and k in VOLATILE:
                continue
            yield from leaves(v, f"{path}.{k}" if path else str(k))
    elif isinstance(value, list):
        if not value:
            yield path, []
        for i, v in enumerate(value):
            yield from leaves(v, f"{path}[{i}]")
    else:
        yield path, value


def results_of(name: str, folder: Path) -> dict[str, Any]:
    """The results.json that ``chaindrive analyze`` writes for example ``name`` (no figures)."""
    from chaindrive.drive import load_project
    from chaindrive.workflows.analyze import analyze

    outcome = analyze(load_project(EXAMPLES / f"{name}.toml"), folder, figures=False)
    return json.loads(outcome.files["json"].read_text(encoding="utf-8"))


def _same(old: Any, new: Any) -> bool:
    if isinstance(old, bool) or isinstance(new, bool) or not isinstance(old, (int, float)) \
            or not isinstance(new, (int, float)):
        return old == new
    if math.isnan(old) or math.isnan(new):
        return math.isnan(old) and math.isnan(new)
    return abs(new - old) <= REL * abs(old) + ABS


def differences(old: dict[str, Any], new: dict[str, Any]) -> list[str]:
    """Every path whose value changed, went missing or appeared (not in :data:`ALLOWED_ADDED`)."""
    a, b = dict(leaves(old)), dict(leaves(new))
    out = []
    for path, v in a.items():
        if path not in b:
            out.append(f"removed  {path} (was {v!r})")
        elif not _same(v, b[path]):
            out.append(f"changed  {path}: {v!r} -> {b[path]!r}")
    for path in b.keys() - a.keys():
        if not any(re.search(p, path) for p in ALLOWED_ADDED):
            out.append(f"added    {path} = {b[path]!r}")
    return sorted(out, key=lambda line: line[9:])
