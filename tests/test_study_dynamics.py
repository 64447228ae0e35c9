"""Study outputs ``dynamics.*``: the running drive's steady state per variant
(``chaindrive.study._dynamics``), the same through the batched and the per-variant paths."""

from __future__ import annotations

import tomllib

import pytest

from chaindrive.drive.project import template
from chaindrive.study.batch import evaluate_batch
from chaindrive.study.run import evaluate_variant
from chaindrive.study.spec import parse_study

OUTPUTS = ["dynamics.peak_tension", "dynamics.mean_tension", "dynamics.settled", "loads.chain_speed"]


def test_dynamic_outputs_batched_equal_per_variant():
    base = tomllib.loads(template("roller"))
    variants = [{"drive.speed": "300 rpm"}, {"drive.speed": "400 rpm"}]
    rows = evaluate_batch(base, variants, OUTPUTS)
    for v, row in zip(variants, rows, strict=True):
        one = evaluate_variant(base, v, OUTPUTS)
        assert row["error"] is None and one["error"] is None
        for out in OUTPUTS:
            assert row[out] == one[out]  # the same kernel on the same drive: bit-identical
    # the steady state of the project's drive (16B, 19/57, 300 rpm): mean above the
    # static tight-side tension's order, the waveform's peak above the mean
    assert rows[0]["dynamics.peak_tension"] > rows[0]["dynamics.mean_tension"] > 1000.0
    # the slower drive carries the larger tension for the same power
    assert rows[0]["dynamics.mean_tension"] > rows[1]["dynamics.mean_tension"]


def test_a_drive_that_cannot_be_simulated_is_the_rows_error():
    base = tomllib.loads(template("roller"))
    variants = [{"drive.speed": "300 rpm", "chain.designation": "18x64"}]
    one = evaluate_variant(base, variants[0], OUTPUTS)
    row = evaluate_batch(base, variants, OUTPUTS)[0]
    assert one["error"] is not None
    assert row["error"] == one["error"]
    assert all(row[out] is None for out in OUTPUTS)


def test_study_accepts_dynamics_outputs():
    text = """
[study]
name = "dynamic"
base = "roller_industrial.toml"
outputs = ["dynamics.peak_tension"]
[plan]
kind = "grid"
[[vary]]
path = "drive.speed"
values = ["300 rpm"]
"""
    from pathlib import Path

    study = parse_study(text, filename="d.toml", folder=Path(__file__).parents[1] / "examples")
    assert list(study.outputs) == ["dynamics.peak_tension"]
    with pytest.raises(Exception, match="must start with one of"):
        parse_study(text.replace("dynamics.peak_tension", "dynamic.peak_tension"), filename="d.toml",
                    folder=Path(__file__).parents[1] / "examples")


def test_dynamic_outputs_with_the_batched_implicit_kernel_are_the_same(monkeypatch):
    # the variants' implicit steps taken together (steady_states_implicit): each row the
    # per-variant steady state's to the last bit, a failing variant still its row's error
    from chaindrive.study import _dynamics

    base = tomllib.loads(template("roller"))
    variants = [{"drive.speed": "300 rpm"}, {"drive.speed": "350 rpm"},
                {"drive.speed": "300 rpm", "chain.designation": "18x64"}]
    single = evaluate_batch(base, variants, OUTPUTS)
    monkeypatch.setattr(_dynamics, "LANES", 2)
    batched = evaluate_batch(base, variants, OUTPUTS)
    for a, b in zip(batched, single, strict=True):
        assert a["error"] == b["error"]
        for out in OUTPUTS:
            assert a[out] == b[out]
    assert batched[2]["error"] is not None and batched[0]["error"] is None
