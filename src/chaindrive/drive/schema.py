"""The input tables of a project file, each declared once (:class:`InputTable`).

A table declares its fields (:class:`Input`: kind, SI unit, bounds, default, help text
and source) and is registered with :func:`register_table`, like an analysis part with
:func:`chaindrive.analysis.parts.register_part`. From the declarations come

* the TOML reader's validation: :func:`chaindrive.drive._reader.reader_model` builds a
  pydantic model per table (:mod:`chaindrive.drive.project` reports its errors with field
  and line);
* the writer's lines (:func:`field_text`, used by :mod:`chaindrive.drive.writer`);
* the docs table of every input (:func:`docs_table`, checked against docs/drive.md).

The tables of the drive itself are declared in :mod:`chaindrive.drive.tables` (imported
with :mod:`chaindrive.drive`).

Examples
--------
>>> t = InputTable("demo", (Input("gap", "quantity", unit="m", default=0.001, minimum=0.0,
...                               help="clearance"),), help="a demo table")
>>> t.field("gap").range_text()
'>= 0'
>>> field_text(t.field("gap"), 0.002)
'"0.002 m"'
"""

from __future__ import annotations

import importlib
import json
import math
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from typing import Any

from ..errors import InputError

__all__ = ["REQUIRED", "Input", "InputTable", "register_table", "unregister_table", "get_table", "all_tables", "load_providers", "TABLE_PROVIDERS",
           "children", "check_declared", "check_rules", "field_text", "number_text", "value_text", "quantity_text", "toml_string", "docs_table"]

#: The default of a field that must be given.
REQUIRED: Any = object()

#: The kinds of a field: a quantity with its unit (``"64 mm"``; a bare number only when
#: the unit is ``""``), a bare number or whole number (pydantic's bounds and messages), a
#: text, one of ``choices``, a flag, a pair of quantities (``unit``) or numbers (``""``), a
#: wheel speed (an angular speed or the mean chain speed), a free mapping.
KINDS = ("quantity", "number", "integer", "text", "choice", "flag", "pair", "speed", "mapping")


@dataclass(frozen=True)
class Input:
    """One field of an input table.

    Parameters
    ----------
    name : str
        The key in the TOML table.
    kind : str
        One of :data:`KINDS`.
    unit : str
        The SI unit of a quantity or a pair (``""``: dimensionless).
    default : object
        :data:`REQUIRED`, ``None`` (optional) or the value in SI units.
    minimum, maximum : float, optional
        The valid range (``None``: unbounded); ``open_minimum``/``open_maximum`` exclude the end.
    choices : tuple
        The values of a ``choice`` field.
    help : str
        What the field means (docs table, templates, form fields).
    source : str
        Where its meaning or default comes from (author, standard).
    plausible : bool
        Warn when an angular speed, power or force lies outside the plausible ranges.
    shown : bool
        Written to a project file even at its default.
    """

    name: str
    kind: str
    unit: str = ""
    default: Any = None
    minimum: float | None = None
    maximum: float | None = None
    open_minimum: bool = False
    open_maximum: bool = False
    choices: tuple = ()
    help: str = ""
    source: str = ""
    plausible: bool = True
    shown: bool = False

    def __post_init__(self) -> None:
        if self.kind not in KINDS:
            raise ValueError(f"{self.name}: kind must be one of {', '.join(KINDS)}, got {self.kind!r}")

    @property
    def required(self) -> bool:
        return self.default is REQUIRED

    def bound_error(self, name: str, x: float) -> str | None:
        """What is wrong with the value ``x`` of this field named ``name`` (``None``: it is valid).

        >>> Input("efficiency", "number", minimum=0.0, open_minimum=True, maximum=1.0).bound_error("efficiency", 2.0)
        'efficiency must lie in (0, 1], got 2'
        """
        lo, hi, unit = self.minimum, self.maximum, self.unit
        if lo == 0 and hi is None:
            if self.open_minimum and not x > 0:
                return f"{name} must be positive (0 < {name} < inf {unit}), got {x:g}"
            if not self.open_minimum and not x >= 0:
                return f"{name} must be non-negative (0 <= {name} < inf {unit}), got {x:g}"
        elif lo is not None or hi is not None:
            ok = ((lo is None or (x > lo if self.open_minimum else x >= lo))
                  and (hi is None or (x < hi if self.open_maximum else x <= hi)))
            if not ok:
                verb = "lie in " if lo is not None and hi is not None else "be "
                return f"{name} must {verb}{self.range_text()}, got {x:g}"
        if x != x or x in (math.inf, -math.inf):
            return f"{name} must be finite, got {x}"
        return None

    def range_text(self) -> str:
        """The valid range in words, e.g. ``"(0, 0.2]"`` or ``">= 1"`` (``""``: unbounded)."""
        lo, hi = self.minimum, self.maximum
        if lo is None and hi is None:
            return ""
        if hi is None:
            return f"{'>' if self.open_minimum else '>='} {lo:g}"
        if lo is None:
            return f"{'<' if self.open_maximum else '<='} {hi:g}"
        return f"{'(' if self.open_minimum else '['}{lo:g}, {hi:g}{')' if self.open_maximum else ']'}"


@dataclass(frozen=True)
class InputTable:
    """One table of a project file.

    Parameters
    ----------
    name : str
        The TOML table (``"track.bolts"`` nests in ``[track]``).
    fields : tuple of Input
        In the order they are written.
    help, source : str
        What the table describes; its source.
    array : bool
        An array of tables (``[[wheels]]``).
    required : bool
        The project file must have it.
    min_items : int
        Fewest entries of an array.
    check : callable, optional
        ``check(model)`` raising ``ValueError`` for rules between fields (message as shown).
    order : float
        Place in a written file.
    target : callable, optional
        A further table (not a field of :class:`~chaindrive.drive.model.Drive`): builds its
        value from the fields, ``target(**fields)`` (default: the validated, frozen model);
        the drive holds it in ``Drive.extra_inputs`` (:meth:`~chaindrive.drive.model.Drive.input`).
    """

    name: str
    fields: tuple[Input, ...]
    help: str = ""
    source: str = ""
    array: bool = False
    required: bool = False
    min_items: int = 0
    check: Callable[[Any], None] | None = None
    order: float = 100.0
    target: Callable[..., Any] | None = None
    extra: dict[str, Any] = field(default_factory=dict, compare=False)

    def field(self, name: str) -> Input:
        for f in self.fields:
            if f.name == name:
                return f
        raise KeyError(name)


_TABLES: dict[str, InputTable] = {}


def register_table(table: InputTable) -> InputTable:
    """Declare an input table (its reader, writer lines and docs row follow); returns it."""
    if table.name in _TABLES and _TABLES[table.name] != table:
        raise ValueError(f"input table {table.name!r} is declared twice")
    _TABLES[table.name] = table
    return table


def unregister_table(name: str) -> None:
    """Remove a declared table (tests)."""
    _TABLES.pop(name, None)


def get_table(name: str) -> InputTable:
    """The declaration of table ``name``."""
    return _TABLES[name]


def all_tables() -> tuple[InputTable, ...]:
    """Every declared table, in the order of a written file."""
    return tuple(sorted(_TABLES.values(), key=lambda t: t.order))


#: ``module:function`` that declare further input tables (the analysis parts' inputs),
#: called by name (no import: the lower layer names no module above it in code) the first
#: time a project names a table not declared yet, as :data:`chaindrive._presenters.DEFAULT_PRESENTERS`.
TABLE_PROVIDERS: list[str] = ["chaindrive.analysis.parts:all_parts"]
_PROVIDED = False


def load_providers() -> None:
    """Let :data:`TABLE_PROVIDERS` declare their tables (once)."""
    global _PROVIDED
    if _PROVIDED:
        return
    _PROVIDED = True
    for spec in TABLE_PROVIDERS:
        module, _, function = spec.partition(":")
        getattr(importlib.import_module(module), function)()


def check_rules(obj: Any, table: str) -> None:
    """The rules between the fields of ``[table]`` (its declared ``check``) on an object built
    in code; :class:`~chaindrive.errors.InputError` ``"table: ..."`` naming the table."""
    check = _TABLES[table].check
    if check is None:
        return
    try:
        check(obj)
    except ValueError as exc:
        raise InputError(f"{table}: {exc}", field=table) from None


def check_declared(obj: Any, table: str, names: tuple[str, ...]) -> None:
    """Check the fields ``names`` of a drive-description object against the bounds declared
    for ``[table]`` (an object built in code gets the reader's checks); each value made a
    float. Raises :class:`~chaindrive.errors.InputError` naming ``table.field``."""
    decl = _TABLES[table]
    for name in names:
        value = getattr(obj, name)
        if value is None:
            continue
        path = f"{table}.{name}"
        try:
            x = float(value)
        except (TypeError, ValueError):
            raise InputError(f"{path} must be a number, got {value!r}", field=path) from None
        message = decl.field(name).bound_error(path, x)
        if message:
            raise InputError(message, field=path)
        object.__setattr__(obj, name, x)


def children(table: InputTable) -> tuple[InputTable, ...]:
    """The tables nested directly in ``table`` (``track.bolts`` in ``track``)."""
    return tuple(t for t in _TABLES.values() if t.name.rsplit(".", 1)[0] == table.name and t.name != table.name)


# --------------------------------------------------------------------------- writing


def toml_string(text: str) -> str:
    """A TOML basic string (JSON escapes are valid TOML)."""
    # JSON escapes are TOML escapes; DEL (U+007F), a control character TOML refuses raw, is
    # the one JSON leaves as it is
    return json.dumps(str(text), ensure_ascii=False).replace("\x7f", "\\u007f")


def quantity_text(value: float, unit: str) -> str:
    """``"<value> <unit>"`` as a TOML string, the value exact (``repr``).

    >>> quantity_text(0.0254, "m")
    '"0.0254 m"'
    """
    v = float(value)
    if not math.isfinite(v):
        raise InputError(f"cannot write a non-finite quantity ({value!r} {unit}) to a project file")
    return toml_string(f"{v!r} {unit}")


def number_text(value: float | int) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    return repr(float(value))


def value_text(value: Any) -> str:
    """A value as typed (a text, a number, a flag, a list of them) as TOML.

    >>> value_text(["0 mm", 1.5, True])
    '["0 mm", 1.5, true]'
    """
    if isinstance(value, str):
        return toml_string(value)
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(value_text(v) for v in value) + "]"
    return number_text(value)


def field_text(f: Input, value: Any) -> str:
    """The TOML text of ``value`` (SI) for field ``f``: read back by the reader to the same value."""
    if f.kind in ("quantity", "speed"):
        unit = "rad/s" if f.kind == "speed" else f.unit
        return quantity_text(value, unit) if unit else number_text(value)
    if f.kind == "integer":
        return str(int(value))
    if f.kind == "number":
        return number_text(value)
    if f.kind == "flag":
        return "true" if value else "false"
    if f.kind == "pair":
        return "[" + ", ".join(quantity_text(v, f.unit) if f.unit else number_text(float(v)) for v in value) + "]"
    if f.kind == "choice" and not isinstance(value, str):
        return str(int(value))
    return toml_string(value)


# --------------------------------------------------------------------------- docs


def _default_text(f: Input) -> str:
    if f.required:
        return "required"
    if f.default is None:
        return "optional"
    return f"`{field_text(f, f.default) if f.kind != 'pair' else f.default}`"


def docs_rows() -> Iterator[tuple[str, ...]]:
    """(key, kind and unit, range, default, meaning, source) of every declared field."""
    for t in all_tables():
        prefix = f"{t.name}[]" if t.array else t.name
        if not t.fields:
            yield (f"`{prefix}.*`", "table", "", "optional", t.help, t.source)
        for f in t.fields:
            kind = f"{f.kind} [{f.unit}]" if f.unit else ("number" if f.kind == "quantity" else f.kind)
            rng = " / ".join(map(str, f.choices)) if f.choices else f.range_text()
            yield (f"`{prefix}.{f.name}`", kind, rng, _default_text(f), f.help, f.source or t.source)


def docs_table() -> str:
    """The Markdown table of every input of a project file (docs/drive.md holds it)."""
    lines = ["| key | kind [SI unit] | valid | default | meaning | source |", "|---|---|---|---|---|---|"]
    lines += ["| " + " | ".join(c.replace("|", "\\|") for c in row) + " |" for row in docs_rows()]
    return "\n".join(lines) + "\n"
