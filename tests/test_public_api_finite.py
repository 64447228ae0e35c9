"""Every public function of the library refuses NaN/inf and out-of-range input with a
chaindrive error and never returns NaN/inf (issue 34, item 3).

The functions are ENUMERATED from the package (every public module's ``__all__``:
``scripts/fuzz.py`` :func:`api_functions`), not listed by hand; each gets generated
arguments by its annotations (numbers including 5e-324, 1e-300, NaN, inf, 1e300, zero,
negatives and arrays; text; valid library objects from the template drives and their
analyses). Left out, each with its stated reason: ``API_EXCLUDED`` (modules reached
through another surface), ``API_SKIP`` (plain records, internals), and below
:data:`TOO_SLOW`.
"""

from __future__ import annotations

import importlib
import inspect
import random

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from _fuzz_loader import load_fuzz

pytestmark = pytest.mark.fuzz

fuzz = load_fuzz()
FUNCTIONS = dict(fuzz.api_functions())

#: Calls of a minute each (OCC solids of a wheel, a halving ladder of simulations): swept by
#: `make fuzz` (scripts/fuzz.py --surface api) with its 45 s cap, not in the test suite.
TOO_SLOW = {"chaindrive.geometry.solid.part_solid": "an OCC solid of a wheel: 30-60 s a call",
            "chaindrive.geometry.solid.write_step": "an OCC solid written as STEP: 30-60 s a call",
            "chaindrive.simulation.run.step_for_accuracy": "up to 7 simulations a call",
            "chaindrive.life.wrap_jump_ratio": "a bisection of quasi-static wrap equilibria: 1-10 min a call"}


def test_the_surface_is_enumerated_from_the_package():
    # every public callable of every public module is swept, unless its module is excluded
    # with a reason or its name is in API_SKIP (records, internals: reasons beside the set)
    swept = {id(f) for f in FUNCTIONS.values()}
    for modname in fuzz.api_modules():
        if fuzz.api_excluded(modname):
            continue
        try:
            mod = importlib.import_module(modname)
        except ImportError:  # an optional extra not installed
            continue
        for n in getattr(mod, "__all__", ()):
            obj = getattr(mod, n, None)
            if (obj is None or n in fuzz.API_SKIP or n.isupper() or inspect.ismodule(obj) or not callable(obj)
                    or (inspect.isclass(obj) and (issubclass(obj, BaseException) or fuzz._is_result_class(obj)))
                    or fuzz.api_excluded(getattr(obj, "__module__", "") or "")):
                continue
            assert id(obj) in swept, f"{modname}.{n}"
    assert len(FUNCTIONS) > 300
    assert {"chaindrive.rating.chain_rating", "chaindrive.conveyor.free_strand_minimum_tension",
            "chaindrive.layout.chain_length_polygon"} <= set(FUNCTIONS)


def test_unreached_functions_have_a_reason():
    rnd = random.Random(1)
    for name, obj in FUNCTIONS.items():
        for _ in range(3):
            fuzz.api_call_args(name, obj, rnd)
    for name, reason in fuzz.API_UNREACHED.items():
        assert reason and name in FUNCTIONS
    # most of the surface is reached
    assert len(fuzz.API_UNREACHED) < 0.15 * len(FUNCTIONS), sorted(fuzz.API_UNREACHED.items())


@pytest.mark.parametrize("name", sorted(n for n in FUNCTIONS if n not in TOO_SLOW))
@settings(max_examples=6, deadline=None, suppress_health_check=list(HealthCheck), database=None)
@given(seed=st.integers(0, 2**32 - 1))
def test_public_function_refuses_or_answers_finite(name, seed):
    rnd = random.Random(seed)
    tally = fuzz.Tally("api")
    fuzz.run_api(name, FUNCTIONS[name], tally, rnd)
    assert not (tally.tracebacks or tally.nonfinite), tally.examples


@pytest.mark.parametrize(("name", "args"), [
    ("chaindrive.rating.chain_rating", ("16B", 50, 1e-300)),
    ("chaindrive.rating.chain_rating", ("ANSI 80", 120, 5e-324)),
    ("chaindrive.conveyor.free_strand_minimum_tension", (5e-324, 1.1, 1.1)),
    ("chaindrive.conveyor.free_strand_minimum_tension", (1.0, float("nan"), 1.0)),
    ("chaindrive.conveyor.free_strand_minimum_tension", (1.0, 0.1, float("inf"))),
])
def test_issue_reproducers_through_the_enumerated_surface(name, args):
    from chaindrive.errors import ChainDriveError

    with pytest.raises(ChainDriveError):
        FUNCTIONS[name](*args)
