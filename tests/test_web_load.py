"""The web server under 50 parallel mixed requests stays responsive (front-door bounds).

A real ``uvicorn`` server runs in a subprocess on 127.0.0.1. Heavy requests (reports with
figures: jobs in worker processes; whole analyses: the live-analysis pool) and light ones
(pages, health, catalogue) are sent at once; while they are in flight a light request must
answer within 1 s and a request for unbounded work must be refused (4xx) within 1 s.
Heavy requests beyond the caps are answered 503 with a message, never left stalled.
"""

from __future__ import annotations

import concurrent.futures as cf
import json
import time
import urllib.error
import urllib.parse
import urllib.request

import pytest

pytest.importorskip("fastapi")
pytest.importorskip("uvicorn")


def _get(url: str, data: bytes | None = None, timeout: float = 120.0) -> tuple[int, float, bytes]:
    t0 = time.perf_counter()
    try:
        with urllib.request.urlopen(urllib.request.Request(url, data=data), timeout=timeout) as r:
            return r.status, time.perf_counter() - t0, r.read()
    except urllib.error.HTTPError as exc:
        return exc.code, time.perf_counter() - t0, exc.read()
    except OSError:
        return 0, time.perf_counter() - t0, b""


@pytest.fixture(scope="module")
def server(web_server):
    with web_server("max_jobs=2") as base:
        _get(base + "/api/design")  # warm the analysis workers
        _get(base + "/")  # and the page template
        yield base


def test_fifty_parallel_mixed_requests(server):
    from chaindrive.drive.project import template

    project = urllib.parse.urlencode({"project": template("roller")}).encode()
    heavy = [(f"{server}/download/report.html?centre_distance={500 + 10 * i}+mm", None) for i in range(10)]
    heavy += [(f"{server}/api/analyze", project) for _ in range(10)]
    live = [(f"{server}/api/design?centre_distance={600 + 5 * i}+mm", None) for i in range(15)]
    light = [(f"{server}/{p}", None) for p in ("health", "static/style.css", "api/chains", "about", "")] * 3
    requests = heavy + live + light
    assert len(requests) == 50
    pool = cf.ThreadPoolExecutor(max_workers=54)
    try:
        futures = [pool.submit(_get, url, data, 90.0) for url, data in requests]
        time.sleep(0.5)  # everything is in flight now
        status, seconds, _ = _get(server + "/health", timeout=5)
        assert status == 200 and seconds < 1.0, (status, seconds)
        status, seconds2, _ = _get(server + "/", timeout=5)
        assert status == 200 and seconds2 < 1.0, (status, seconds2)
        print(f"under load: /health {seconds * 1e3:.0f} ms, / {seconds2 * 1e3:.0f} ms")
        status, seconds, body = _get(server + "/api/kinematics?chain=18x64&teeth=8&speed=5+rad/s&points=20000000",
                                     timeout=5)
        assert 400 <= status < 500 and seconds < 1.0, (status, seconds)
        assert "points" in json.loads(body)["error"]
        status, seconds, _ = _get(server + "/api/design?power=" + "9" * 9000, timeout=5)
        assert status == 414 and seconds < 1.0
        # the light requests of the batch answered quickly and successfully
        light_results = [f.result(timeout=30) for f in futures[-len(light):]]
        assert all(s == 200 for s, _, _ in light_results), light_results
        # heavy ones beyond the caps are refused at once with a message, never stalled
        busy = [f.result(timeout=90) for f in futures[:len(heavy)] if f.done()]
        for s, t, body in busy:
            if s == 503:
                assert t < 2.0 and "busy" in json.loads(body)["error"]
    finally:
        pool.shutdown(wait=False, cancel_futures=True)
