"""Base class for result objects: named arrays, units per field, ``to_dict()`` and ``to_json()``.

Every numeric field of a result class declares its SI unit once, where the field is
defined, with :func:`quantity`::

    @dataclass(frozen=True)
    class SpanTension(Result):
        tension: float = quantity("N")                  # shown in kN (the default for N)
        sag: float | None = quantity("m", display="mm", default=None)
        links: int = quantity("1")                      # a count: dimensionless
        note: str = ""                                  # text: no unit

:meth:`Result.unit_of` and :meth:`Result.display_unit_of` read them; the report, the
command line, the web page and the study summaries show every number through them
(:mod:`chaindrive.workflows.display` converts SI to the display unit). A field holding
another result (or a tuple of them) needs no unit: its own fields carry theirs.
"""

from __future__ import annotations

import dataclasses
import json
from typing import Any

import numpy as np

__all__ = ["Result", "jsonable", "quantity", "DIMENSIONLESS"]

#: The unit of a ratio, a count, a factor or any pure number.
DIMENSIONLESS = "1"

_UNIT_KEY = "unit"
_DISPLAY_KEY = "display"


def quantity(unit: str, *, display: str | None = None, default: Any = dataclasses.MISSING,
             default_factory: Any = dataclasses.MISSING, **kwargs: Any) -> Any:
    """A dataclass field that carries its SI ``unit`` (and optionally its ``display`` unit).

    Parameters
    ----------
    unit : str
        The SI unit of the value held (``"N"``, ``"m"``, ``"rad/s"``, ``"Pa"``, ``"W"``,
        ``"kg/m"``, ...) or :data:`DIMENSIONLESS` (``"1"``) for a pure number.
    display : str, optional
        The unit a presenter shows it in; by default the one of
        :data:`chaindrive.workflows.display.DISPLAY` for ``unit`` (kN for N, mm for m ...).
    default, default_factory, **kwargs
        As for :func:`dataclasses.field`.

    Examples
    --------
    >>> from dataclasses import dataclass
    >>> @dataclass(frozen=True)
    ... class Toy(Result):
    ...     force: float = quantity("N")
    >>> Toy(5.0).unit_of("force"), Toy.display_unit_of("force")
    ('N', None)
    """
    metadata = dict(kwargs.pop("metadata", None) or {})
    metadata[_UNIT_KEY] = unit
    if display is not None:
        metadata[_DISPLAY_KEY] = display
    return dataclasses.field(default=default, default_factory=default_factory, metadata=metadata, **kwargs)


def jsonable(value: Any) -> Any:
    """Convert numpy arrays/scalars, dataclasses and containers to JSON-ready objects."""
    kind = type(value)
    if kind is float:
        return value if value - value == 0.0 else None  # NaN and inf are not JSON numbers
    if kind is int or kind is str or kind is bool or value is None:
        return value
    if isinstance(value, Result):
        return value.to_dict()
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        return {f.name: jsonable(getattr(value, f.name)) for f in dataclasses.fields(value)
                if not (f.metadata.get("omit_empty") and not getattr(value, f.name))}
    if isinstance(value, np.ndarray):
        return jsonable(value.tolist())
    if isinstance(value, (np.floating, float)):
        v = float(value)
        return v if np.isfinite(v) else None
    if isinstance(value, (np.integer,)):
        return int(value)
    if isinstance(value, (np.bool_,)):
        return bool(value)
    if isinstance(value, dict):
        return {str(k): jsonable(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [jsonable(v) for v in value]
    return value


class Result:
    """Mixin for result dataclasses: ``to_dict()`` and ``to_json()`` in SI units, and the
    unit of every numeric field (:func:`quantity`)."""

    def to_dict(self) -> dict[str, Any]:
        if not dataclasses.is_dataclass(self):  # a programming error: Result is a mixin of dataclasses
            raise TypeError(f"{type(self).__name__} must be a dataclass to inherit Result")
        return {f.name: jsonable(getattr(self, f.name)) for f in dataclasses.fields(self)}

    def to_json(self, **kwargs: Any) -> str:
        return json.dumps(self.to_dict(), **kwargs)

    def _repr_html_(self) -> str:
        """Notebook display: a table of the fields with their units (the presenter
        :func:`chaindrive.workflows.notebook.html_of` formats it)."""
        from ._presenters import view

        return view("html", self)

    @classmethod
    def _field(cls, name: str) -> dataclasses.Field[Any]:
        if not dataclasses.is_dataclass(cls):
            raise TypeError(f"{cls.__name__} must be a dataclass to inherit Result")
        for f in dataclasses.fields(cls):
            if f.name == name:
                return f
        raise KeyError(f"{cls.__name__} has no field {name!r}")

    @classmethod
    def unit_of(cls, name: str) -> str | None:
        """The SI unit declared for field ``name`` (``None``: text, a flag or a nested result)."""
        return cls._field(name).metadata.get(_UNIT_KEY)

    @classmethod
    def display_unit_of(cls, name: str) -> str | None:
        """The display unit declared for field ``name``, or ``None`` for the default of its SI unit."""
        return cls._field(name).metadata.get(_DISPLAY_KEY)

    @classmethod
    def field_units(cls) -> dict[str, str]:
        """``{field: SI unit}`` of every field that declares one."""
        if not dataclasses.is_dataclass(cls):
            raise TypeError(f"{cls.__name__} must be a dataclass to inherit Result")
        return {f.name: f.metadata[_UNIT_KEY] for f in dataclasses.fields(cls) if _UNIT_KEY in f.metadata}
