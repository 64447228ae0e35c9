"""Golden regression: each example's results.json, field by field (JSON path, rel 1e-9, abs
1e-12), against tests/data/golden/ (regenerate and see the diff: scripts/regen_golden.py).

Provenance: the stored files are what ``chaindrive analyze`` wrote for the examples when
the analysis was declared in parts (issue 18); tests/test_analysis.py keeps the older check
against the results before the analysis layer.
"""

from __future__ import annotations

import json

import pytest

from _golden import GOLDEN, NAMES, differences, leaves, results_of

pytest.importorskip("pydantic")


@pytest.mark.parametrize("name", NAMES)
def test_results_json_unchanged(name, tmp_path):
    old = json.loads((GOLDEN / f"{name}.json").read_text(encoding="utf-8"))
    new = results_of(name, tmp_path)
    diff = differences(old, new)
    assert not diff, (f"{name}: {len(diff)} differences (run scripts/regen_golden.py to see and accept them):\n"
                      + "\n".join(diff[:40]))


def test_differences_by_path():
    old = {"created": "x", "a": {"b": [1.0, 2.0], "c": "t"}, "d": True}
    assert differences(old, {"created": "y", "a": {"b": [1.0 + 1e-12, 2.0], "c": "t"}, "d": True}) == []
    diff = differences(old, {"a": {"b": [1.1, 2.0], "c": "u", "e": 1}, "d": False})
    assert [line.split()[1] for line in diff] == ["a.b[0]:", "a.c:", "a.e", "d:"]
    assert dict(leaves({"x": []}))["x"] == []
