"""Fixtures shared by the test modules (helpers in tests/_shared.py)."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

import _shared


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
