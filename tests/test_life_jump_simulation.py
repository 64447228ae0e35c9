"""The simulated jump-over reference of benchmarks/life.py: the bisection of the onset, its bracket
checks and the quasi-static onset (three speeds, the extrapolation to zero speed)."""

from __future__ import annotations

import importlib.util
import math
from pathlib import Path

import pytest


def _bench():
    spec = importlib.util.spec_from_file_location("bench_life_jump", Path(__file__).parents[1] / "benchmarks" / "life.py")
    bench = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(bench)
    return bench


def _fake(bench, monkeypatch, onset):
    """Replace the simulation by a chain that skips above ``onset(speed)`` (a load ratio); the runs in a list."""
    runs = []

    def run_worn(teeth, elongation, tight, back_force, duration=0.8, angular_velocity=2.0, slide_stiffness=0.0):
        rho = tight / (back_force - tight)
        runs.append((angular_velocity, rho))
        skipped = 3.0 if rho > onset(angular_velocity) else 0.1
        return skipped, rho * 1.1, (1.0, 5.0, 9.0)

    monkeypatch.setattr(bench, "_run_worn", run_worn)
    return runs


def test_bisection_brackets_the_onset_and_moves_a_bracket_that_misses_it(monkeypatch):
    bench = _bench()
    _fake(bench, monkeypatch, lambda w: 40.0)
    held, rho, slack, width = bench.simulated_jump_ratio(11, 0.2, 3000.0, steps=10, angular_velocity=0.5)
    assert rho <= 40.0 < rho * width and width < 1.01 and held == pytest.approx(1.1 * rho)
    # a bracket wholly above the onset, and one wholly below it: shifted by its width until it holds the onset
    for bracket in ((50.0, 60.0), (20.0, 25.0)):
        held, rho, slack, width = bench.simulated_jump_ratio(11, 0.2, 3000.0, steps=5, angular_velocity=0.5,
                                                             bracket=bracket)
        assert rho <= 40.0 < rho * width and held is not None


def test_bisection_without_a_held_load_says_so(monkeypatch):
    bench = _bench()
    _fake(bench, monkeypatch, lambda w: 1.0)
    held, rho, _slack, _width = bench.simulated_jump_ratio(11, 0.2, 3000.0, steps=4, angular_velocity=0.5)
    assert held is None
    with pytest.raises(RuntimeError, match="no load held"):
        bench.quasi_static_jump_ratio(11, 0.2, 3000.0)


ONSETS = {"linear, slight": lambda w: 60.0 + 0.5 * w, "settles abruptly": lambda w: 60.0 + (100.0 * w if w > 0.04 else 0.0),
          "linear, steep": lambda w: 60.0 + 200.0 * w}


@pytest.mark.parametrize("onset, speeds, converged", [("linear, slight", 3, True), ("settles abruptly", 4, True),
                                                      ("linear, steep", 5, False)])
def test_quasi_static_onset_halves_the_speed_until_it_settles(monkeypatch, onset, speeds, converged):
    # an onset that falls with the speed (linearly: a damper's force, proportional to the speed of the quasi-static
    # motion; or abruptly, as 17 teeth at 10 %): the speed halved twice, and up to twice more while the last halving
    # moved the onset by more than two bisection resolutions; the reference is the slowest onset, converged or not (said);
    # the Richardson extrapolation of the two slowest, 2 rho(w/2^k) - rho(w/2^(k-1)), is the zero-speed onset
    # within the bisections' resolution here (linear, or settled)
    bench = _bench()
    runs = _fake(bench, monkeypatch, ONSETS[onset])
    q = bench.quasi_static_jump_ratio(19, 0.03, 1500.0)
    assert q.speeds == (0.125, 0.0625, 0.03125, 0.015625, 0.0078125)[:speeds]
    assert [w for w, _ in runs[:10]] == [0.125] * 10 and {w for w, _ in runs[10:]} == set(q.speeds[1:])
    for w, rho in zip(q.speeds, q.rho, strict=True):
        assert rho <= ONSETS[onset](w) < rho * (1 + q.resolution) * 1.0001
    assert q.extrapolated == pytest.approx(60.0, rel=3 * q.resolution)
    assert q.converged is converged and q.reference == q.rho[-1]
    assert q.tension_ratio == pytest.approx(1.1 * q.rho[-1]) and q.slack == (1.0, 5.0, 9.0)
    assert math.isfinite(q.reference)
