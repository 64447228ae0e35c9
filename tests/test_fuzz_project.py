"""Fuzzing the project loader (bounded; ``make fuzz`` runs 10,000 files): mutated
templates, hostile bytes, deep nesting, many tables. Every input is loaded and analysed
or refused with a chaindrive error of at most ~20 lines; no NaN/inf in an analysis."""

from __future__ import annotations

import random
import tempfile
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from _fuzz_loader import load_fuzz

pytestmark = pytest.mark.fuzz

fuzz = load_fuzz()
TEXTS = fuzz.project_texts()
FOLDER = Path(tempfile.mkdtemp(prefix="chaindrive-fuzz-test-"))


@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(seed=st.integers(0, 2**32 - 1))
def test_project_inputs(seed):
    rnd = random.Random(seed)
    tally = fuzz.Tally("project")
    fuzz.run_project(fuzz.project_input(rnd, TEXTS), tally, rnd, FOLDER)
    # timing is measured by `make fuzz` (calls over 30 s), never asserted in tests
    assert not (tally.tracebacks or tally.bad_exit or tally.nonfinite), tally.examples


@settings(max_examples=25, deadline=None)
@given(data=st.binary(max_size=600))
def test_arbitrary_bytes(data):
    tally = fuzz.Tally("project")
    fuzz.run_project(data, tally, random.Random(0), FOLDER)
    # timing is measured by `make fuzz` (calls over 30 s), never asserted in tests
    assert not (tally.tracebacks or tally.bad_exit or tally.nonfinite), tally.examples


@settings(max_examples=25, deadline=None)
@given(text=st.text(max_size=300))
def test_arbitrary_text(text):
    tally = fuzz.Tally("project")
    fuzz.run_project(text, tally, random.Random(1), FOLDER)
    # timing is measured by `make fuzz` (calls over 30 s), never asserted in tests
    assert not (tally.tracebacks or tally.bad_exit or tally.nonfinite), tally.examples


def test_templates_and_examples_load():
    assert len(TEXTS) >= 4  # three templates and the example projects


def test_self_regulating_table_reproducers():
    # first full `make fuzz` run: a [self_regulating] table without `wheel`, or with a
    # bool where a pair belongs, raised TypeError instead of a one-line InputError
    import pytest

    from chaindrive.drive.carrier import SelfRegulatingSpec
    from chaindrive.errors import InputError

    with pytest.raises(InputError, match="required key.* missing: wheel"):
        SelfRegulatingSpec.from_table({"pivot": ["625 mm", "-71 mm"], "weight": "30 N"})
    with pytest.raises(InputError, match=r"self_regulating.pivot must be a pair \(x, y\), got True"):
        SelfRegulatingSpec.from_table({"wheel": "motor", "pivot": True, "weight": "30 N"})
