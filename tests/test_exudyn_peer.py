"""The Exudyn peer of benchmarks/simulate.py builds (benchmarks/peers/exudyn_drive.py).

A smoke test, not a benchmark: the model of a short drive is assembled and stepped a few
times; skipped without exudyn (the ``bench`` extra).
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("exudyn")
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks" / "peers"))

import exudyn_drive as E  # noqa: E402

from chaindrive.simulation import assemble, roller_example  # noqa: E402


@pytest.mark.slow
def test_exudyn_peer_builds_and_steps():
    model = roller_example(links=30, teeth=11, ramp_time=0.005)
    state = assemble(model)
    segments = E.tooth_segments(model, 11)
    # seat faces (and the two joins), flank chords, tip chords: every class equally long
    assert sum(len(s) for s in segments.values()) == 11 * (E.SEAT_FACES + 2 + 2 * E.FLANK_FACES + 1)
    for length, seg in segments.items():
        assert seg.shape[1] == 4
        lengths = np.hypot(seg[:, 2] - seg[:, 0], seg[:, 3] - seg[:, 1])
        big = lengths > 1e-4  # the seat's two short joins to the flanks aside
        np.testing.assert_allclose(lengths[big], length, rtol=1e-9)
    sc, mbs, handles = E.build(model, state)
    mbs.Assemble()
    assert len(handles["rollers"]) == len(handles["links"]) == 30
    import exudyn as exu

    mbs.SolveDynamic(E.settings(2e-6, 2e-5), solverType=exu.DynamicSolverType.VelocityVerlet)
    xy = np.array([mbs.GetNodeOutput(n, exu.OutputVariableType.Position)[:2] for n in handles["rollers"]])
    # 10 steps from the static assembly: the rollers stay where they were (within 10 µm)
    assert np.abs(xy - state.pos).max() < 1e-5


def test_ramp_matches_the_kernel_convention():
    class W:
        angular_velocity, ramp_time = 20.0, 0.1

    assert E.ramp(W, 0.05) == pytest.approx((0.25, 10.0))  # 0.5 * 20 * 0.05**2 / 0.1
    assert E.ramp(W, 0.2) == pytest.approx((20.0 * 0.15, 20.0))


def test_near_rollers_cover_every_roller_that_reaches_a_wheel():
    # the broad phase by hand against chaindrive's own run: every roller that comes within
    # a roller radius and 3 mm of a wheel's pitch circle during the run is in its list
    from chaindrive.simulation import simulate

    model = roller_example(links=30, teeth=11, angular_velocity=20.0, ramp_time=0.005)
    state = assemble(model)
    near = E.near_rollers(model, state, 0.05)
    r = simulate(model, 0.05, state=state, samples=200)
    for j, ids in enumerate(near):
        c, rad = r.wheel_centres[j], r.pitch_radii[j]
        d = np.hypot(r.positions[..., 0] - c[0], r.positions[..., 1] - c[1])
        reached = set(np.nonzero(d < rad + model.roller_radius + 0.003)[1].tolist())
        assert reached <= set(ids.tolist())
        assert len(ids) < model.links  # a broad phase: not every roller
