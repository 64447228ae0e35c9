"""Web JSON bodies validated by their schema (issue 34, item 4): malformed JSON 400, a body
that is not the schema's 422 naming the field, never a 500; no leaked semaphores at shutdown."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
import types
import urllib.request
from pathlib import Path

import pytest

pytest.importorskip("fastapi")
from fastapi.testclient import TestClient  # noqa: E402
from hypothesis import HealthCheck, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

from _shared import free_port  # noqa: E402
from chaindrive.web import create_app  # noqa: E402
from chaindrive.web.bodies import SimulationBody, validate_body  # noqa: E402

SRC = Path(__file__).resolve().parents[1] / "src"


@pytest.fixture(scope="module")
def client():
    return TestClient(create_app(max_jobs=2, job_time_limit=60.0))


@pytest.fixture
def no_jobs(monkeypatch):
    """A valid body would start a simulation: record it instead."""
    from chaindrive.web.jobs import JobManager

    started = []

    def submit(self, kind, payload, *, time_limit=None):  # noqa: ARG001
        started.append(payload)
        return types.SimpleNamespace(id="test-job")

    monkeypatch.setattr(JobManager, "submit", submit)
    return started


@pytest.mark.parametrize(("body", "status", "field"), [
    # reproducers: null, "x", [] and 5 gave HTTP 500; `[1,2` gave 200 and started a default job
    ("null", 422, "body"), ('"x"', 422, "body"), ("[]", 422, "body"), ("5", 422, "body"),
    ("[1,2", 400, None), ("{", 400, None), ("\x00", 400, None), ('{"a": NaN}', 422, "a"),
    ('{"speed": 5}', 422, "speed"), ('{"bogus": 1}', 422, "bogus"), ('{"frames": 1.5}', 422, "frames"),
    ('{"example": "tank"}', 422, "example"), ('{"design": ' + json.dumps("x" * 5000) + "}", 422, "design"),
    ('{"speed": "5"}', 422, "speed"),  # a bare number: the field's own check names it
    ('{"duration": "1e300 s"}', 422, "duration"),
])
def test_bad_bodies_are_refused_by_field(client, no_jobs, body, status, field):
    r = client.post("/api/jobs/simulate", content=body.encode(), headers={"content-type": "application/json"})
    assert r.status_code == status, r.text
    data = r.json()
    if field is not None:
        assert field in data["errors"], data
    else:
        assert "malformed JSON" in data["error"]
    assert not no_jobs


def test_valid_bodies_start_a_job(client, no_jobs):
    r = client.post("/api/jobs/simulate", json={"example": "roller", "speed": "5 rad/s", "frames": 0})
    assert r.status_code == 200 and r.json() == {"job": "test-job"}
    r = client.post("/api/jobs/simulate", content=b"")  # no body: the page's defaults
    assert r.status_code == 200
    r = client.post("/api/jobs/simulate", data={"example": "link", "duration": "0.1 s"})  # the page's form
    assert r.status_code == 200
    assert [p["example"] for p in no_jobs] == ["roller", "link", "link"]


def test_schema_in_openapi(client):
    spec = client.get("/openapi.json").json()
    body = spec["paths"]["/api/jobs/simulate"]["post"]["requestBody"]["content"]["application/json"]["schema"]
    assert set(body["properties"]) == set(SimulationBody.model_fields)


_json = st.recursive(st.none() | st.booleans() | st.floats(allow_nan=False) | st.integers() | st.text(max_size=20),
                     lambda inner: st.lists(inner, max_size=4) | st.dictionaries(st.text(max_size=10), inner, max_size=4),
                     max_leaves=10)


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(body=_json | st.fixed_dictionaries({}, optional={k: st.one_of(st.none(), st.text(max_size=12), st.integers(),
                                                                       st.floats())
                                                          for k in SimulationBody.model_fields}))
def test_no_body_gives_a_500(client, no_jobs, body):
    r = client.post("/api/jobs/simulate", content=json.dumps(body).encode(),
                    headers={"content-type": "application/json"})
    assert r.status_code in (200, 400, 413, 422), r.text


@settings(max_examples=60, deadline=None)
@given(raw=st.binary(max_size=60))
def test_no_bytes_give_a_500(raw):
    refused = validate_body(SimulationBody, raw)[1]
    assert refused is None or refused.status_code in (400, 413, 422)


@pytest.mark.slow
def test_no_leaked_semaphores_at_shutdown():
    # reproducer: the server reported "5 leaked semaphore objects" when stopped with a job
    # and the analysis pool running
    port = free_port()
    code = ("import uvicorn; from chaindrive.web import create_app; "
            f"uvicorn.run(create_app(), host='127.0.0.1', port={port}, log_level='error')")
    env = {**os.environ, "PYTHONPATH": f"{SRC}{os.pathsep}{os.environ.get('PYTHONPATH', '')}", "MPLBACKEND": "Agg"}
    proc = subprocess.Popen([sys.executable, "-c", code], env=env, stderr=subprocess.PIPE, text=True)
    base = f"http://127.0.0.1:{port}"
    try:
        for _ in range(200):
            try:
                urllib.request.urlopen(base + "/health", timeout=1)
                break
            except OSError:
                time.sleep(0.2)
        urllib.request.urlopen(base + "/api/kinematics?chain=16B&teeth=19&speed=5%20rad/s", timeout=60).read()
        req = urllib.request.Request(base + "/api/jobs/simulate", data=b'{"duration": "0.05 s", "frames": 0}',
                                     headers={"content-type": "application/json"})
        urllib.request.urlopen(req, timeout=60).read()
        time.sleep(0.2)  # the job is running
    finally:
        proc.send_signal(signal.SIGTERM)
        err = proc.communicate(timeout=60)[1]
    assert "leaked" not in err, err
