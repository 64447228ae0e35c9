"""The web server under stalled clients and oversize bodies (chaindrive.web.security).

A real ``uvicorn`` server runs in a subprocess on 127.0.0.1 with the configuration of
``chaindrive web`` (:func:`chaindrive.web.security.server_config`), its deadlines set short
so that the test takes seconds. Stalled clients (no request, half a header, half a body;
sockets on 127.0.0.1 only, bounded in count and time) must be closed by the server while it
keeps answering others; an oversize body gets 413 with or without Content-Length.
"""

from __future__ import annotations

import http.client
import json
import os
import socket
import subprocess
import sys
import time

import pytest

pytest.importorskip("fastapi")
pytest.importorskip("uvicorn")

HOST = "127.0.0.1"
#: Short deadlines of the server under test [s].
DEADLINE = 1.0
#: Stalled clients of each kind (bounded).
STALLED = 8


def _free_port() -> int:
    with socket.socket() as s:
        s.bind((HOST, 0))
        return s.getsockname()[1]


def _status(port: int, method: str, path: str, body: bytes | None = None,
            headers: dict | None = None, timeout: float = 30.0) -> tuple[int, bytes]:
    conn = http.client.HTTPConnection(HOST, port, timeout=timeout)
    try:
        conn.request(method, path, body=body, headers=headers or {})
        r = conn.getresponse()
        return r.status, r.read()
    finally:
        conn.close()


@pytest.fixture(scope="module")
def port():
    port = _free_port()
    code = ("import uvicorn; from chaindrive.web import create_app; "
            "from chaindrive.web.security import server_config; "
            f"uvicorn.Server(server_config(create_app(body_timeout={DEADLINE}), host='{HOST}', port={port}, "
            f"header_timeout={DEADLINE}, keep_alive={DEADLINE}, log_level='error')).run()")
    proc = subprocess.Popen([sys.executable, "-c", code], env={**os.environ, "MPLBACKEND": "Agg"})
    deadline = time.monotonic() + 60
    while True:
        try:
            if _status(port, "GET", "/health", timeout=1)[0] == 200:
                break
        except OSError:
            pass
        if time.monotonic() > deadline or proc.poll() is not None:
            proc.kill()
            pytest.fail("the web server did not start")
        time.sleep(0.2)
    yield port
    proc.terminate()
    try:
        proc.wait(timeout=10)
    except subprocess.TimeoutExpired:
        proc.kill()


def _closed_by_server(sock: socket.socket, within: float) -> bool:
    """True when the server closes ``sock`` (EOF or reset) within ``within`` seconds."""
    sock.settimeout(within)
    end = time.monotonic() + within
    try:
        while time.monotonic() < end:
            data = sock.recv(65536)
            if not data:
                return True
    except (ConnectionResetError, BrokenPipeError):
        return True
    except TimeoutError:
        return False
    return False


def test_stalled_clients_are_closed_and_the_server_answers(port):
    request = (b"POST /api/analyze HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n"
               b"Content-Length: 1000\r\n\r\n{\"dr")
    kinds = {
        "nothing sent": b"",
        "half a header": b"GET /health HTTP/1.1\r\nHost: x\r\nX-Slow: ",
        "half a body": request,
    }
    socks = []
    try:
        for payload in kinds.values():
            for _ in range(STALLED):
                s = socket.create_connection((HOST, port), timeout=5)
                if payload:
                    s.sendall(payload)
                socks.append(s)
        # the server answers others while they stall
        t0 = time.monotonic()
        assert _status(port, "GET", "/health", timeout=5)[0] == 200
        assert time.monotonic() - t0 < 5
        closed = [_closed_by_server(s, within=DEADLINE + 10) for s in socks]
        assert all(closed), {k: sum(closed[i * STALLED:(i + 1) * STALLED]) for i, k in enumerate(kinds)}
        assert _status(port, "GET", "/health", timeout=5)[0] == 200
    finally:
        for s in socks:
            s.close()


def test_late_body_gets_408(port):
    with socket.create_connection((HOST, port), timeout=DEADLINE + 10) as s:
        s.sendall(b"POST /api/analyze HTTP/1.1\r\nHost: x\r\nContent-Length: 100\r\n\r\n{")
        reply = b""
        while chunk := s.recv(65536):
            reply += chunk
    assert reply.startswith(b"HTTP/1.1 408") and b"did not arrive within 1 s" in reply


def test_oversize_body_413_with_and_without_content_length(port):
    big = json.dumps({"drive": "x" * 2_500_000}).encode()
    status, body = _status(port, "POST", "/api/analyze", big, {"Content-Type": "application/json"})
    assert status == 413 and b"larger than the limit" in body

    def chunks():
        for i in range(0, len(big), 65536):
            yield big[i:i + 65536]

    # no Content-Length: http.client sends an iterable chunked (Transfer-Encoding: chunked)
    status, body = _status(port, "POST", "/api/analyze", chunks(), {"Content-Type": "application/json"})
    assert status == 413 and b"larger than the limit of 1000000 bytes" in body
    assert _status(port, "GET", "/health")[0] == 200


def test_headers_too_long_refused(port):
    status, _ = _status(port, "GET", "/health", headers={"X-Big": "y" * 40_000})
    assert status in (400, 431)
