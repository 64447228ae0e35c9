"""Fuzzing the web API in-process with fastapi's TestClient (bounded; ``make fuzz`` runs
10,000 requests): routes discovered from the OpenAPI schema, form fields from the pages.
No HTTP 500, no traceback in a page, no NaN/inf in a JSON answer or a page."""

from __future__ import annotations

import random

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from _fuzz_loader import load_fuzz

pytestmark = pytest.mark.fuzz

pytest.importorskip("fastapi")
pytest.importorskip("httpx")
fuzz = load_fuzz()


@pytest.fixture(scope="module")
def web():
    client = fuzz.web_client()
    routes = fuzz.web_routes(client)
    fields = fuzz.web_form_fields(client, routes)
    return client, routes, fields, fuzz.project_texts()


def test_routes_discovered(web):
    _, routes, _, _ = web
    assert routes, "the OpenAPI schema lists no routes"


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                   HealthCheck.function_scoped_fixture])
@given(seed=st.integers(0, 2**32 - 1))
def test_web_requests(web, seed):
    client, routes, fields, texts = web
    rnd = random.Random(seed)
    routes = [r for r in routes if "jobs" not in r[1]]  # no worker processes in the test suite
    tally = fuzz.Tally("web")
    fuzz.run_web(client, fuzz.web_request(rnd, routes, texts, fields), tally)
    # timing is measured by `make fuzz` (calls over 30 s), never asserted in tests
    assert not (tally.tracebacks or tally.bad_exit or tally.nonfinite), tally.examples
