"""Views of result objects by kind (internal): the notebook's HTML and the standard plots.

A result object of a lower layer (a formula result, the drive description, an analysis, a
simulation) never imports a presenter. Its ``_repr_html_`` and ``plot`` ask this registry
for the view of its class; the presenter modules fill the registry when they are imported
(:func:`register_view`). Like the plotting back-ends of pandas (``pandas.options.plotting.
backend``: a module named by a setting, imported on first use), each kind names the
presenter modules that provide it by default, loaded the first time a view of that kind
is asked for; a user can register another view for a class.

>>> class Thing:
...     pass
>>> @register_view("html", Thing)
... def _thing_html(thing):
...     return "<b>thing</b>"
>>> view("html", Thing())
'<b>thing</b>'
"""

from __future__ import annotations

import importlib
from collections.abc import Callable
from typing import Any

from .errors import ChainDriveError

__all__ = ["DEFAULT_PRESENTERS", "register_view", "view"]

#: kind -> the presenter modules that register the views of that kind when imported.
DEFAULT_PRESENTERS: dict[str, tuple[str, ...]] = {
    "html": ("chaindrive.workflows.notebook",),
    "plot": ("chaindrive.plotting.vibration", "chaindrive.plotting.simulation"),
}

_VIEWS: dict[str, dict[type, Callable[..., Any]]] = {}
_LOADED: set[str] = set()


def register_view(kind: str, cls: type) -> Callable[[Callable[..., Any]], Callable[..., Any]]:
    """Decorator: the function that shows instances of ``cls`` (and its subclasses) as ``kind``."""

    def deco(function: Callable[..., Any]) -> Callable[..., Any]:
        _VIEWS.setdefault(kind, {})[cls] = function
        return function

    return deco


def _find(kind: str, cls: type) -> Callable[..., Any] | None:
    views = _VIEWS.get(kind, {})
    for base in cls.__mro__:
        if base in views:
            return views[base]
    return None


def view(kind: str, subject: Any, **kwargs: Any) -> Any:
    """The ``kind`` view (``"html"``, ``"plot"``) of ``subject``, by the most specific class
    registered; the default presenter modules of ``kind`` are imported on first use."""
    function = _find(kind, type(subject))
    if function is None and kind not in _LOADED:
        _LOADED.add(kind)
        for module in DEFAULT_PRESENTERS.get(kind, ()):
            importlib.import_module(module)
        function = _find(kind, type(subject))
    if function is None:
        raise ChainDriveError(f"no {kind} view of {type(subject).__name__} is registered")
    return function(subject, **kwargs)
