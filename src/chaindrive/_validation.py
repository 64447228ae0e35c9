"""Input checks shared by the pure functions (internal).

Each check names the parameter and the valid range in its message and raises
:class:`chaindrive.errors.InputError`; nothing is clamped silently.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
from numpy.typing import ArrayLike

from .errors import InputError, ValidityRangeWarning
from .limits import MAX_TEETH

__all__ = [
    "as_float_array",
    "check_positive",
    "check_nonnegative",
    "check_range",
    "check_teeth",
    "warn_outside",
]


_SCALARS = (float, int, np.floating, np.integer)


def _scalar(value: object) -> float | None:
    """``value`` as a float when it is one plain number (the fast path of the checks)."""
    if isinstance(value, _SCALARS) and not isinstance(value, bool):
        return float(value)
    return None


def _has_nan(arr: np.ndarray) -> bool:
    """Whether the float array ``arr`` holds a NaN (a short one in Python floats)."""
    if arr.size <= 16:
        return any(map(math.isnan, arr.ravel().tolist()))
    return bool(np.isnan(arr).any())


def _within(arr: np.ndarray, low: float, strict: bool) -> bool:
    """Whether every element of the NaN-free float array ``arr`` is ``> low`` (``strict``) or
    ``>= low``, and ``< inf`` (``(arr <= low).any() or not np.isfinite(arr).all()`` negated)."""
    if not arr.size:
        return True
    if arr.size <= 16:
        values = arr.ravel().tolist()
        lo, hi = min(values), max(values)
    else:
        lo, hi = float(np.minimum.reduce(arr, axis=None)), float(np.maximum.reduce(arr, axis=None))
    return (lo > low if strict else lo >= low) and hi < math.inf


def as_float_array(name: str, value: ArrayLike) -> np.ndarray:
    """Convert ``value`` to a float array, rejecting NaN and non-numbers."""
    x = _scalar(value)
    if x is not None:
        if x != x:
            raise InputError(f"{name} must not be NaN")
        return np.asarray(x)
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError) as exc:
        raise InputError(f"{name} must be a number or an array of numbers, got {value!r}") from exc
    if _has_nan(arr):
        raise InputError(f"{name} must not be NaN")
    return arr


def check_positive(name: str, value: ArrayLike, unit: str = "") -> np.ndarray:
    """Require ``0 < value < inf``."""
    x = _scalar(value)
    if x is not None and 0.0 < x < math.inf:
        return np.asarray(x)
    arr = as_float_array(name, value)
    if not _within(arr, 0.0, True):
        raise InputError(
            f"{name} must be positive and finite (0 < {name} < inf{' ' + unit if unit else ''}), "
            f"got {_show(arr)}"
        )
    return arr


def check_nonnegative(name: str, value: ArrayLike, unit: str = "") -> np.ndarray:
    """Require ``0 <= value < inf``."""
    x = _scalar(value)
    if x is not None and 0.0 <= x < math.inf:
        return np.asarray(x)
    arr = as_float_array(name, value)
    if not _within(arr, 0.0, False):
        raise InputError(
            f"{name} must be non-negative and finite (0 <= {name} < inf{' ' + unit if unit else ''}), "
            f"got {_show(arr)}"
        )
    return arr


def check_range(
    name: str,
    value: ArrayLike,
    low: float = -np.inf,
    high: float = np.inf,
    *,
    low_inclusive: bool = True,
    high_inclusive: bool = True,
    unit: str = "",
) -> np.ndarray:
    """Require ``low <(=) value <(=) high``."""
    x = _scalar(value)
    if (x is not None and (x >= low if low_inclusive else x > low)
            and (x <= high if high_inclusive else x < high)):
        return np.asarray(x)
    arr = as_float_array(name, value)
    if arr.size <= 16:  # a short array in Python floats (the same comparisons)
        ok = all((v >= low if low_inclusive else v > low) and (v <= high if high_inclusive else v < high)
                 for v in arr.ravel().tolist())
    else:
        lo_ok = arr >= low if low_inclusive else arr > low
        hi_ok = arr <= high if high_inclusive else arr < high
        ok = bool((lo_ok & hi_ok).all())
    if not ok:
        lb = "[" if low_inclusive else "("
        hb = "]" if high_inclusive else ")"
        raise InputError(
            f"{name} must lie in {lb}{low:g}, {high:g}{hb}{' ' + unit if unit else ''}, got {_show(arr)}"
        )
    return arr


def check_teeth(name: str, value: ArrayLike, minimum: int = 3) -> np.ndarray:
    """Require an integer tooth count ``>= minimum`` and ``<= chaindrive.limits.MAX_TEETH``."""
    x = _scalar(value)
    if x is not None and minimum <= x <= MAX_TEETH and x == int(x):  # the range first: NaN, inf fail it
        return np.asarray(int(x))
    arr = as_float_array(name, value)
    if np.any(arr != np.round(arr)) or np.any(arr < minimum):
        raise InputError(f"{name} must be a whole number >= {minimum}, got {_show(arr)}")
    if np.any(arr > MAX_TEETH):
        raise InputError(f"{name} must be a whole number in [{minimum}, {MAX_TEETH}], got {_show(arr)}")
    return arr.astype(int) if arr.ndim else arr.astype(int)


def warn_outside(name: str, value: ArrayLike, low: float, high: float, source: str, stacklevel: int = 3) -> None:
    """Warn (do not raise) when an empirical formula is used outside its range."""
    x = _scalar(value)
    if x is not None and low <= x <= high:
        return
    arr = np.asarray(value, dtype=float)
    if arr.size <= 16:  # a short array in Python floats (a NaN is outside neither bound, as below)
        outside = any(v < low or v > high for v in arr.ravel().tolist())
    else:
        outside = bool((arr < low).any() or (arr > high).any())
    if outside:
        warnings.warn(
            f"{name} = {_show(arr)} is outside the validity range [{low:g}, {high:g}] of {source}",
            ValidityRangeWarning,
            stacklevel=stacklevel,
        )


def _show(arr: np.ndarray) -> str:
    if arr.ndim == 0:
        return f"{float(arr):g}"
    bad = arr.ravel()
    return "[" + ", ".join(f"{v:g}" for v in bad[:5]) + (", ...]" if bad.size > 5 else "]")
