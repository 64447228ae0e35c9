"""Columns of a study's Parquet part files: the type of an output column from its values,
and values converted to it (non-finite floats and values of another kind null)."""

from __future__ import annotations

import json
import math
from collections.abc import Iterable
from typing import Any

__all__ = ["column_type", "convert", "array"]


def _kind(value: Any) -> str:
    if value is None:
        return "null"
    if isinstance(value, bool):
        return "bool"
    if isinstance(value, (int, float)):
        return "float"
    return "string"


def column_type(values: Iterable[Any], established: Any, pa: Any) -> Any:
    """The Parquet type of an output column: the type of its earlier part files, else text
    if any value is text, bool if all are bools, else float (null: no value yet)."""
    if established is not None and not pa.types.is_null(established):
        return established
    kinds = {_kind(v) for v in values} - {"null"}
    if not kinds:
        return pa.null()
    if "string" in kinds:
        return pa.string()
    if kinds == {"bool"}:
        return pa.bool_()
    return pa.float64()


def convert(value: Any, type_: Any, pa: Any) -> Any:
    """``value`` as a value of the column type ``type_`` (lists and dicts as JSON text;
    ``None`` where it does not fit)."""
    if value is None:
        return None
    if pa.types.is_string(type_):
        return value if isinstance(value, str) else json.dumps(value)
    if pa.types.is_boolean(type_):
        return bool(value) if isinstance(value, bool) else None
    if pa.types.is_floating(type_):
        if isinstance(value, (bool, int, float)):
            x = float(value)
            return x if math.isfinite(x) else None
        return None
    if pa.types.is_integer(type_):
        return int(value) if isinstance(value, (int, float)) and not isinstance(value, bool) else None
    return None


def array(values: list[Any], type_: Any, pa: Any) -> Any:
    """``values`` as a pyarrow array of ``type_``, each converted as :func:`convert` does;
    a column of plain floats (or bools, or strings) in one call (non-finite floats null)."""
    kind = {float: pa.types.is_floating, bool: pa.types.is_boolean, str: pa.types.is_string}
    for cls, test in kind.items():
        if test(type_) and all(type(v) is cls for v in values):
            if cls is float:
                import numpy as np

                arr = np.array(values, dtype=float)
                bad = ~np.isfinite(arr)
                return pa.array(arr, type=type_, mask=bad if bad.any() else None)
            return pa.array(values, type=type_)
    return pa.array([convert(v, type_, pa) for v in values], type=type_)
