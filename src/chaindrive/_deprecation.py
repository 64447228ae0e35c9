"""Deprecation policy (internal): a renamed or moved public name keeps an alias that warns
with :class:`FutureWarning` for one release, and CHANGELOG.md lists it.

:func:`moved_module` makes a module forward every attribute to its new home;
:func:`alias` makes a renamed function that warns and calls the new one.
"""

from __future__ import annotations

import functools
import importlib
import warnings
from collections.abc import Callable
from typing import Any, TypeVar

__all__ = ["alias", "moved_module", "warn_renamed"]

F = TypeVar("F", bound=Callable[..., Any])


def warn_renamed(old: str, new: str, *, stacklevel: int = 3) -> None:
    """Warn once per call site that ``old`` is now ``new`` (removed in the next release)."""
    warnings.warn(f"{old} is deprecated and will be removed in the next release; use {new}",
                  FutureWarning, stacklevel=stacklevel)


def alias(function: F, old: str) -> F:
    """``function`` under its former public name ``old``, warning at each call."""
    new = f"{function.__module__}.{function.__qualname__}"

    @functools.wraps(function)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        warn_renamed(old, new)
        return function(*args, **kwargs)

    wrapper.__doc__ = f"Deprecated alias of :func:`{new}` (removed in the next release)."
    return wrapper  # type: ignore[return-value]


def moved_module(old: str, new: str, *more: str) -> Callable[[str], Any]:
    """A module ``__getattr__`` forwarding every attribute of the moved module ``old`` to ``new``
    (or, for a module split in parts, to the first of ``new, *more`` that has it)."""

    def __getattr__(name: str) -> Any:
        if not name.startswith("__"):
            for home in (new, *more):
                module = importlib.import_module(home)
                if hasattr(module, name):
                    warn_renamed(f"{old}.{name}", f"{home}.{name}")
                    return getattr(module, name)
        raise AttributeError(f"module {old!r} has no attribute {name!r}")

    return __getattr__
