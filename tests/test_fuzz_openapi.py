"""schemathesis over the web API, bounded (``make fuzz`` runs 10,000 inputs): requests
generated from the app's OpenAPI schema, sent in-process; no HTTP 500, no traceback in an
answer, no NaN/inf in a JSON answer."""

from __future__ import annotations

import random

import pytest

from _fuzz_loader import load_fuzz

pytestmark = pytest.mark.fuzz

pytest.importorskip("fastapi")
pytest.importorskip("schemathesis")
fuzz = load_fuzz()


def test_openapi_operations_found():
    ops = fuzz.openapi_operations(fuzz.web_client().app)
    assert any(op.path == "/api/analyze" for op in ops)


def test_schemathesis_over_the_web_api():
    # no worker processes in the test suite: the job routes are left to `make fuzz`
    tally = fuzz.fuzz_openapi(120, random.Random(20261125), progress=False, include_jobs=False)
    assert tally.inputs >= 100
    assert not (tally.tracebacks or tally.bad_exit or tally.nonfinite), tally.examples
