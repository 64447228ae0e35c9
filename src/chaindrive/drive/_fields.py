"""Checks of the fields of the drive description (internal): each error names its field."""

from __future__ import annotations

import math
from typing import Any

from ..errors import InputError

__all__: list[str] = []


def _finite(value: Any, what: str, *, positive: bool = False, nonnegative: bool = False) -> float:
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise InputError(f"{what} must be a number, got {value!r}", field=what) from None
    if not math.isfinite(x):
        raise InputError(f"{what} must be finite, got {x}", field=what)
    if positive and not x > 0:
        raise InputError(f"{what} must be positive (0 < {what} < inf), got {x:g}", field=what)
    if nonnegative and not x >= 0:
        raise InputError(f"{what} must be non-negative (0 <= {what} < inf), got {x:g}", field=what)
    return x


def _whole(value: Any, what: str, minimum: int, maximum: int | None = None, *, field: str | None = None) -> int:
    """``value`` as an ``int``: a whole number (not a bool) in ``[minimum, maximum]``."""
    try:
        ok = not isinstance(value, bool) and int(value) == value and minimum <= value
    except (TypeError, ValueError, OverflowError):
        ok = False
    if ok and (maximum is None or value <= maximum):
        return int(value)
    bounds = f">= {minimum}" if maximum is None else f"in [{minimum}, {maximum}]"
    raise InputError(f"{what} must be a whole number {bounds}, got {value!r}", field=field or what)


def _direction(value: Any, what: str) -> tuple[float, float]:
    d = tuple(value)
    if len(d) != 2:
        raise InputError(f"{what} must be (x, y), got {value!r}", field=what)
    dx, dy = _finite(d[0], f"{what} x"), _finite(d[1], f"{what} y")
    if not math.hypot(dx, dy) > 0:
        raise InputError(f"{what} must be a non-zero vector", field=what)
    return dx, dy
