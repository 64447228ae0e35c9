"""Steady states of many drives with their implicit steps taken together
(``chaindrive.simulation.steady_lanes``): each result that of ``steady_state`` alone.

The reference is :func:`chaindrive.simulation.steady.steady_state` itself (its defaults):
every statistic, the waveform, the settling time, the step and its error, the method
equal to the last bit (tolerance 0), for drives that measure implicitly and drives that
fall back to the explicit integrator, batched with drives of another layout, in chunks
of fewer lanes than drives. Every error path. No timing here (benchmarks/study.py).
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from chaindrive.errors import InputError
from chaindrive.simulation import SimWheel, roller_example
from chaindrive.simulation.steady import steady_state
from chaindrive.simulation.steady_lanes import steady_states_implicit

FIELDS = ("mean_tension", "peak_tension", "period_peak_tension", "max_tension", "min_tension",
          "standard_error", "tooth_period", "chain_speed", "settle_time", "settled",
          "measured_time", "dt", "step_error", "method")


def _models():
    # 40-link drives at different speeds and loads (different tooth periods, settling
    # times and step counts per period), and one on 17-tooth sprockets whose implicit step
    # does not hold (measured with the explicit integrator)
    ms = [roller_example(links=40, teeth=12, angular_velocity=w, load_torque=tq, gravity=g)
          for w, tq, g in ((10.0, 50.0, False), (16.0, 80.0, True), (60.0, 20.0, False))]
    return [*ms, roller_example(links=40, teeth=17, angular_velocity=80.0, load_torque=50.0)]


def _assert_same(a, b):
    for name in FIELDS:
        x, y = getattr(a, name), getattr(b, name)
        assert x == y or (isinstance(x, float) and np.isnan(x) and np.isnan(y)), name
    np.testing.assert_array_equal(a.waveform, b.waveform)
    np.testing.assert_array_equal(a.phase, b.phase)


@pytest.fixture(scope="module")
def pair():
    models = _models()
    kw = dict(periods=3, max_settle=8)
    return ([steady_state(m, **kw) for m in models],
            steady_states_implicit(models, lanes=2, **kw))


@pytest.mark.parametrize("v", range(4))
def test_each_drive_equals_its_steady_state_alone(pair, v):
    single, batched = pair
    _assert_same(batched[v], single[v])
    assert batched[v].cpu_time > 0.0


def test_both_integrators_are_covered(pair):
    # the explicit fallback (a step that does not hold) and an implicit measurement
    single, _ = pair
    assert {s.method for s in single} == {"implicit", "explicit"}


def test_a_drive_that_cannot_run_is_its_result_the_others_go_on():
    good = roller_example(links=40, teeth=12, angular_velocity=10.0, load_torque=50.0)
    free = roller_example(links=40, teeth=12)
    free = dataclasses.replace(free, wheels=[SimWheel.at(w.centre, w.teeth, mode="free")
                                             for w in free.wheels])
    out = steady_states_implicit([free, good], periods=2, max_settle=2)
    assert isinstance(out[0], InputError) and "driven at a prescribed speed" in str(out[0])
    _assert_same(out[1], steady_state(good, periods=2, max_settle=2))


@pytest.mark.parametrize(("args", "kwargs", "match"), [
    (([],), {}, "1 to 100000 drives"),
    (("abc",), {}, "sequence of drives"),
    ((None,), {"lanes": 0}, "lanes must be a whole number"),
    ((None,), {"periods": 0}, "periods must be a whole number"),
    ((None,), {"step_tolerance": 1.5}, "step_tolerance must be in"),
    ((None,), {"min_settle_time": -1.0}, "min_settle_time must be >= 0"),
    ((None,), {"states": [None, None]}, "states: one per drive"),
])
def test_bad_arguments_are_refused_by_name(args, kwargs, match):
    if args == (None,):
        args = ([roller_example(links=40, teeth=12)],)
    with pytest.raises(InputError, match=match):
        steady_states_implicit(*args, **kwargs)
