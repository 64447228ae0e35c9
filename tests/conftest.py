"""Fixtures shared by the test modules (helpers in tests/_shared.py)."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

import _shared

#: Test files that run a door end to end (reports written, CLI processes, a Dask cluster,
#: OpenCascade solids, every example's proposal): marked ``whole``, so that ``make test-fast``
#: (the everyday subset) stays under a minute on 2 cores; ``make test`` runs them.
WHOLE = {
    "test_analyze.py", "test_report_charts.py", "test_proposal_roundtrip.py", "test_run_folders.py",
    "test_study_run.py", "test_geometry_solid.py", "test_simulation_cli.py", "test_doors_robust.py",
    "test_report_figures.py", "test_geometry_export.py",
    # the web server's pages and API through its test client, request to rendered answer
    "test_web.py", "test_web_limits.py", "test_web_wheels.py", "test_web_conveyor.py", "test_web_load.py",
}


def _clear_stale_numba_cache() -> None:
    """Delete the package's compiled numba files when a source they may call has changed.

    Numba's on-disk cache checks only the source file of the compiled function itself
    (``numba.core.caching``: its stamp is a hash of that one file), not the modules it
    calls, so a working tree could run stale compiled code after an edit of a callee. A hash
    of every package source that holds a compiled function is kept beside the caches; when it
    differs, the ``*.nbi``/``*.nbc`` files go and numba compiles afresh (a fresh clone has none).
    """
    import hashlib

    package = Path(__file__).resolve().parents[1] / "src" / "chaindrive"
    if not package.is_dir():
        return
    digest = hashlib.sha256()
    for path in sorted(package.rglob("*.py")):
        text = path.read_bytes()
        if b"njit" in text or path.parent.name == "simulation":
            digest.update(path.relative_to(package).as_posix().encode() + b"\0" + text)
    stamp = package / "simulation" / "__pycache__" / "numba-sources.sha256"
    if stamp.is_file() and stamp.read_text() == digest.hexdigest():
        return
    for pattern in ("*.nbi", "*.nbc"):
        for path in package.rglob(pattern):
            path.unlink(missing_ok=True)
    stamp.parent.mkdir(exist_ok=True)
    stamp.write_text(digest.hexdigest())


def pytest_configure(config: pytest.Config) -> None:
    """Once per run, in the controlling process (before any worker compiles): clear
    stale numba caches (:func:`_clear_stale_numba_cache`)."""
    if not hasattr(config, "workerinput"):
        _clear_stale_numba_cache()


def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    """Mark the tests of the :data:`WHOLE` files ``whole``."""
    for item in items:
        if item.path.name in WHOLE:
            item.add_marker(pytest.mark.whole)


@pytest.fixture(scope="session")
def examples_dir() -> Path:
    """The repository's examples/ folder."""
    return _shared.EXAMPLES


@pytest.fixture
def free_port() -> int:
    """A TCP port free on 127.0.0.1."""
    return _shared.free_port()


@pytest.fixture(scope="session")
def web_server() -> Callable[..., Any]:
    """``with web_server("max_jobs=2") as base_url:`` a real uvicorn server of the studio."""
    return _shared.web_server


@pytest.fixture(scope="session")
def roller_drive() -> Callable[..., Any]:
    """``roller_drive(**changes)``: the 16B 19/57 15 kW drive (:func:`_shared.roller_drive`)."""
    return _shared.roller_drive
