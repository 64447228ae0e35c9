"""Results of pure computations kept for reuse, keyed on their inputs (internal).

An analysis asks again for what depends only on part of the drive: the same wheel
entry, the same layout geometry, the same slack-span catenary, the same tensioner
frequencies, when the web studio re-analyses a drive after one field changed or a study
varies one input. :func:`memo` keeps the last results of such a function keyed on its
(hashable) arguments, or on a key that a ``key`` function makes of them:

* the arrays of a kept result are made read-only (the results are frozen: a caller that
  tried to change one in place would otherwise change the next caller's result);
* the warnings the computation raised are kept with it and raised again at every reuse,
  so an analysis reports the same warnings whether or not a result was reused;
* an error is not kept (the next call computes again and raises again);
* arguments that cannot be hashed are computed without the store.

:func:`clear` empties every store (``benchmarks/analyze.py`` measures the analysis both
ways).
"""

from __future__ import annotations

import dataclasses
import functools
import warnings
from collections import OrderedDict
from collections.abc import Callable, Hashable
from typing import Any, TypeVar, cast

import numpy as np

from .._finite import _field_names

__all__ = ["memo", "clear", "freeze"]

F = TypeVar("F", bound=Callable[..., Any])

_STORES: list[OrderedDict[Any, Any]] = []


_LEAVES = frozenset({float, int, str, bool, type(None), np.float64})


def freeze(obj: Any, _depth: int = 0) -> None:
    """Make every numpy array reachable in ``obj`` (dataclasses, tuples, lists, dicts) read-only."""
    t = type(obj)
    if _depth > 8 or t in _LEAVES:
        return
    if t is np.ndarray:
        obj.flags.writeable = False
    elif hasattr(t, "__dataclass_fields__") and dataclasses.is_dataclass(t):
        for name in _field_names(t):
            freeze(getattr(obj, name, None), _depth + 1)
    elif isinstance(obj, np.ndarray):
        obj.flags.writeable = False
    elif isinstance(obj, (tuple, list)):
        for v in obj:
            freeze(v, _depth + 1)
    elif isinstance(obj, dict):
        for v in obj.values():
            freeze(v, _depth + 1)


def clear() -> None:
    """Empty every store of :func:`memo` and the formula caches the analysis relies on."""
    for store in _STORES:
        store.clear()
    from ..layout import two_wheels

    for name in ("_chain_length_polygon", "_centre_distance_polygon"):
        cached = getattr(two_wheels, name, None)
        if cached is not None and hasattr(cached, "cache_clear"):
            cached.cache_clear()
    two_wheels._GRIDS.__dict__.clear()  # the phase grids the root search evaluated last
    two_wheels._VERTEX_CACHE.clear()
    from ..layout import wrap

    wrap._KEPT.clear()
    from ..kinematics import entry, solver
    from ..layout import polygon_loop, wheels
    from ..vibration import resonance

    for cached in (wheels.cached_pitch_radius, solver._cumulative, entry._checked_seats, entry._chordal_rod_schedule,
                   resonance._stationary_frequencies, polygon_loop._polygon):
        cached.cache_clear()
    from ..life import jump_over, jump_table
    from ..loads.safety import required_static_safety_for

    for cached in (required_static_safety_for, jump_over._form_cached, jump_table._rows):
        cached.cache_clear()
    from ..drive import model

    for cached in model.DERIVED_CACHES:
        cached.cache_clear()
    from ..geometry import polygon

    polygon._bi_regular_kept.cache_clear()


def memo(*, maxsize: int = 128, key: Callable[..., Hashable] | None = None) -> Callable[[F], F]:
    """Keep the last ``maxsize`` results of the decorated pure function (see the module).

    Parameters
    ----------
    maxsize : int
        Results kept (least recently used dropped first).
    key : callable, optional
        Makes the key from the call's arguments (default: the arguments themselves); it
        must hold everything the result depends on.
    """

    def decorate(fn: F) -> F:
        store: OrderedDict[Any, tuple[Any, tuple[tuple[type[Warning], str], ...]]] = OrderedDict()
        _STORES.append(store)

        @functools.wraps(fn)
        def wrapper(*args: Any, **kwargs: Any) -> Any:
            k = key(*args, **kwargs) if key is not None else (args, tuple(sorted(kwargs.items())))
            try:
                found = store.get(k)
            except TypeError:  # an argument that cannot be hashed
                return fn(*args, **kwargs)
            if found is None:
                with warnings.catch_warnings(record=True) as caught:
                    warnings.simplefilter("always")
                    result = fn(*args, **kwargs)
                freeze(result)
                found = (result, tuple((w.category, str(w.message)) for w in caught))
                store[k] = found
                if len(store) > maxsize:
                    store.popitem(last=False)
            else:
                store.move_to_end(k)
            result, replay = found
            for category, text in replay:
                warnings.warn(text, category, stacklevel=2)
            return result

        return cast(F, wrapper)

    return decorate
