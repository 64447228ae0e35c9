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


@pytest.mark.parametrize("slope, converged", [(60.0, False), (0.5, True)])
def test_quasi_static_onset_extrapolates_to_zero_speed(monkeypatch, slope, converged):
    # an onset that falls linearly with the speed (a damper's force, proportional to the speed of the
    # quasi-static motion): the Richardson extrapolation of the two slowest, 2 rho(w/4) - rho(w/2), is the
    # zero-speed onset within the bisections' resolution; where the last halving moves it by no more than
    # two resolutions the slowest run's onset is taken (converged)
    bench = _bench()
    runs = _fake(bench, monkeypatch, lambda w: 60.0 * (1.0 + slope / 60.0 * w))
    q = bench.quasi_static_jump_ratio(19, 0.03, 1500.0)
    assert q.speeds == (0.125, 0.0625, 0.03125)
    assert [w for w, _ in runs[:10]] == [0.125] * 10 and {w for w, _ in runs[10:]} == {0.0625, 0.03125}
    for w, rho in zip(q.speeds, q.rho, strict=True):
        assert rho <= 60.0 + slope * w < rho * (1 + q.resolution) * 1.0001
    assert q.extrapolated == pytest.approx(60.0, rel=3 * q.resolution)
    assert q.converged is converged
    assert q.reference == (q.rho[-1] if converged else q.extrapolated)
    assert q.tension_ratio == pytest.approx(1.1 * q.rho[-1]) and q.slack == (1.0, 5.0, 9.0)
    assert math.isfinite(q.reference)
