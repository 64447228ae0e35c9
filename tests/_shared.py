"""Helpers shared by the test modules (the fixtures wrapping them are in tests/conftest.py).

Import what a parametrisation needs at collection time (``EXAMPLES``); use the fixtures
(``examples_dir``, ``free_port``, ``web_server``, ``roller_drive``) everywhere else.
"""

from __future__ import annotations

import contextlib
import math
import os
import socket
import subprocess
import sys
import time
import urllib.error
import urllib.request
from collections.abc import Iterator
from pathlib import Path
from typing import Any

#: The example projects and studies of the repository.
EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def free_port() -> int:
    """A TCP port free on 127.0.0.1 now."""
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def _health(url: str) -> bool:
    try:
        with urllib.request.urlopen(url, timeout=1) as r:
            return r.read() == b"ok"
    except (OSError, urllib.error.URLError):
        return False


@contextlib.contextmanager
def web_server(create_app_arguments: str = "", *, env: dict[str, str] | None = None,
               log_level: str = "error", stop_timeout: float = 20.0) -> Iterator[str]:
    """A real uvicorn server of ``create_app(<create_app_arguments>)`` in a subprocess; yields its base URL."""
    import pytest

    port = free_port()
    code = ("import uvicorn; from chaindrive.web import create_app; "
            f"uvicorn.run(create_app({create_app_arguments}), host='127.0.0.1', port={port}, log_level={log_level!r})")
    proc = subprocess.Popen([sys.executable, "-c", code], env={**os.environ, "MPLBACKEND": "Agg", **(env or {})})
    base = f"http://127.0.0.1:{port}"
    deadline = time.monotonic() + 60
    while not _health(base + "/health"):
        if time.monotonic() > deadline or proc.poll() is not None:
            proc.kill()
            pytest.fail("the web server did not start")
        time.sleep(0.2)
    try:
        yield base
    finally:
        proc.terminate()  # uvicorn exits cleanly and multiprocessing ends the job processes
        try:
            proc.wait(timeout=stop_timeout)
        except subprocess.TimeoutExpired:
            proc.kill()


def chromium_or_skip() -> str:
    """Debian's chromium for a browser test module (``$CHROMIUM``, ``chromium`` on the path or
    /usr/bin/chromium): its path; without one the module is skipped, or fails under ``CI``."""
    import shutil

    import pytest

    found = next((p for p in (os.environ.get("CHROMIUM"), shutil.which("chromium"), "/usr/bin/chromium")
                  if p and Path(p).exists()), None)
    if found is None:
        if os.environ.get("CI"):
            pytest.fail("CI: the browser tests need Debian's chromium (.ci/run installs it)", pytrace=False)
        pytest.skip("no chromium found (apt-get install chromium); CI runs these tests", allow_module_level=True)
    return str(found)


def roller_drive(speed: float = 960 * math.pi / 30, **changes: Any) -> Any:
    """The industrial roller drive of the tests: 16B, 19/57 teeth, 15 kW, 1.05 m apart."""
    import dataclasses

    from chaindrive.chains import get
    from chaindrive.drive import Drive, Load, Wheel

    d = Drive(chain=get("16B"), speed=speed, load=Load(power=15e3),
              wheels=[Wheel("motor", "sprocket", 19, (0, 0), driving=True),
                      Wheel("fan", "sprocket", 57, (1.05, 0))])
    return dataclasses.replace(d, **changes) if changes else d
