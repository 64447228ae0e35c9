"""A small registry for ``method=`` alternatives (internal)."""

from __future__ import annotations

import difflib
from collections.abc import Callable
from typing import Any

from .errors import UnknownNameError

__all__ = ["Registry"]


class Registry:
    """Named alternatives of one computation.

    >>> r = Registry("method")
    >>> @r.register("double")
    ... def _d(x):
    ...     return 2 * x
    >>> r.get("double")(2)
    4
    >>> r.get("tripel")
    Traceback (most recent call last):
    ...
    chaindrive.errors.UnknownNameError: unknown method 'tripel'; valid: 'double'
    """

    def __init__(self, kind: str):
        self.kind = kind
        self._items: dict[str, Any] = {}

    def register(self, name: str) -> Callable[[Any], Any]:
        def deco(obj: Any) -> Any:
            self._items[name] = obj
            return obj

        return deco

    def add(self, name: str, obj: Any) -> None:
        self._items[name] = obj

    def names(self) -> list[str]:
        return list(self._items)

    def get(self, name: str) -> Any:
        try:
            return self._items[name]
        except (KeyError, TypeError):
            valid = ", ".join(repr(n) for n in self._items)
            close = difflib.get_close_matches(str(name), list(self._items), n=1)
            hint = f" (did you mean {close[0]!r}?)" if close else ""
            raise UnknownNameError(f"unknown {self.kind} {name!r}; valid: {valid}{hint}") from None

    def __contains__(self, name: object) -> bool:
        return name in self._items
