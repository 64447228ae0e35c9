"""Fuzzing the command line in-process (bounded; ``make fuzz`` runs 10,000 command lines):
no traceback, exit code 0/1/2 (3 only for an internal error, which fails here), no NaN/inf
in the output of a successful run, nothing written outside the sandbox."""

from __future__ import annotations

import random
import shutil

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from _fuzz_loader import load_fuzz

pytestmark = pytest.mark.fuzz

fuzz = load_fuzz()
COMMANDS = fuzz.cli_commands()
FAST = {k: v for k, v in COMMANDS.items() if k not in ("analyze", "report", "simulate", "demo", "study")}


@pytest.fixture(scope="module")
def sandbox():
    box = fuzz.make_sandbox()
    yield box
    shutil.rmtree(box, ignore_errors=True)


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                   HealthCheck.function_scoped_fixture])
@given(seed=st.integers(0, 2**32 - 1))
def test_cli_fast_commands(sandbox, seed):
    rnd = random.Random(seed)
    tally = fuzz.Tally("cli")
    fuzz.run_cli(fuzz.cli_argv(rnd, FAST), tally, sandbox)
    fuzz.reset_sandbox(sandbox)
    # timing is measured by `make fuzz` (calls over 30 s), never asserted in tests
    assert not (tally.tracebacks or tally.bad_exit or tally.nonfinite), tally.examples


@settings(max_examples=6, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                  HealthCheck.function_scoped_fixture])
@given(seed=st.integers(0, 2**32 - 1), command=st.sampled_from(["analyze", "simulate"]))
def test_cli_slow_commands(sandbox, seed, command):
    rnd = random.Random(seed)
    tally = fuzz.Tally("cli")
    argv = fuzz.cli_argv(rnd, {command: COMMANDS[command]})
    if command == "analyze" and "--no-figures" not in argv and "--figures" not in argv:
        argv.append("--no-figures")
    if command == "simulate":
        argv += ["--no-plots"]
    fuzz.run_cli(argv, tally, sandbox)
    fuzz.reset_sandbox(sandbox)
    # timing is measured by `make fuzz` (calls over 30 s), never asserted in tests
    assert not (tally.tracebacks or tally.bad_exit or tally.nonfinite), tally.examples


def test_generator_reaches_past_the_parser(sandbox):
    # the generator is useful only if a fair share of its command lines run to the end
    rnd = random.Random(7)
    tally = fuzz.Tally("cli")
    for _ in range(40):
        fuzz.run_cli(fuzz.cli_argv(rnd, FAST), tally, sandbox)
    fuzz.reset_sandbox(sandbox)
    assert tally.outcomes.get("exit 0", 0) >= 4, tally.outcomes
    # timing is measured by `make fuzz` (calls over 30 s), never asserted in tests
    assert not (tally.tracebacks or tally.bad_exit or tally.nonfinite), tally.examples


def test_judge_flags_nonfinite_output():
    assert fuzz.nonfinite_text("sigma = inf MPa") is not None
    assert fuzz.nonfinite_text("v = nan m/s") is not None
    assert fuzz.nonfinite_text("information, infinite, finance") is None
