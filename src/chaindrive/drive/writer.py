"""The one project-file writer: a :class:`~chaindrive.drive.model.Drive` (plus comments) as
TOML text that :func:`chaindrive.drive.project.parse_project` reads back to an equal Drive,
generated from the input tables' declarations (:mod:`chaindrive.drive.tables`).

``chaindrive new`` (:func:`chaindrive.drive.project.template`), ``chaindrive select --write``
(:func:`candidate_project_text`) write through it. Every quantity is written in
its SI unit with the shortest text that reads back to the same float (``repr``), so the
round trip is exact; a comment may follow any key (``comments={"drive.speed": "driving
wheel"}``) and a header may open the file.

Examples
--------
>>> from chaindrive.chains import get
>>> from chaindrive.drive import Drive, Load, Wheel
>>> d = Drive(chain=get("16B"), speed=100.0, load=Load(power=15e3),
...           wheels=(Wheel("motor", "sprocket", 19, (0.0, 0.0), driving=True),
...                   Wheel("fan", "sprocket", 57, (1.05, 0.0))))
>>> text = project_text(d, comments={"drive.speed": "driving wheel"})
>>> 'speed = "100.0 rad/s"  # driving wheel' in text
True
>>> from chaindrive.drive.project import parse_project
>>> parse_project(text) == d
True
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping
from typing import Any, Protocol

from ..errors import InputError
from .model import Drive, Load, Wheel
from .schema import (
    InputTable,
    all_tables,
    field_text,
    number_text,
    quantity_text,
    toml_string,
    value_text,
)
from .tables import table_objects, table_values


class Candidate(Protocol):
    """What the writer reads of a selection row (:class:`chaindrive.selection.Candidate`):
    the chain, the wheels, the duty and the rating's lubrication."""

    chain: str
    names: tuple[str, ...]
    speed: float
    power: float
    service_factor: float
    rated_power: float
    design_power: float
    power_margin: float
    lubrication: str
    lubrication_method: str
    centre_distance: float
    links: int
    teeth_driving: int
    teeth_driven: int

__all__ = ["project_text", "mapping_text", "drive_to_toml", "edit_project_text", "candidate_drive",
           "candidate_project_text", "toml_string",
           "quantity_text"]


class _Lines:
    def __init__(self, comments: Mapping[str, str]) -> None:
        self.lines: list[str] = []
        self.comments = comments
        self.used: set[str] = set()

    def table(self, name: str, array: bool = False) -> None:
        if self.lines and self.lines[-1] != "":
            self.lines.append("")
        self.lines.append(f"[[{name}]]" if array else f"[{name}]")

    def key(self, where: str, key: str, text: str) -> None:
        path = f"{where}.{key}"
        note = self.comments.get(path)
        self.used.add(path)
        self.lines.append(f"{key} = {text}" + (f"  # {note}" if note else ""))


def _write_table(out: _Lines, table: InputTable, obj: Any, where: str) -> None:
    """The fields of ``obj`` that are required, differ from their defaults or carry a comment."""
    for f, value in zip(table.fields, table_values(table, obj).values(), strict=True):
        if value is None:
            continue
        if not (f.required or f.shown or value != f.default or f"{where}.{f.name}" in out.comments):
            continue
        out.key(where, f.name, field_text(f, value))


def project_text(drive: Drive, *, header: str | None = None, comments: Mapping[str, str] | None = None) -> str:
    """The project file (TOML) of ``drive``: :func:`~chaindrive.drive.project.parse_project`
    reads it back to an equal :class:`Drive`.

    Every declared input table (:mod:`chaindrive.drive.tables`) present in the drive is
    written, its fields in their declared units and order.

    Parameters
    ----------
    drive : Drive
        The drive to write.
    header : str, optional
        Comment lines for the top of the file (``#`` added where missing).
    comments : mapping, optional
        ``{"table.key": "comment"}`` written after that key (``"wheels.0.teeth"`` for the
        first wheel, ``"guides.0.kind"`` ...).

    Returns
    -------
    str
        TOML text, quantities as strings with SI units.

    Raises
    ------
    InputError
        A non-finite quantity.
    """
    out = _Lines(comments or {})
    if header:
        out.lines += [ln if ln.startswith("#") or not ln else f"# {ln}" for ln in header.strip("\n").splitlines()]
    for table in all_tables():
        for i, obj in enumerate(table_objects(drive, table)):
            out.table(table.name, array=table.array)
            if table.extra.get("mapping"):
                _self_regulating(out, obj)
            else:
                _write_table(out, table, obj, f"{table.name}.{i}" if table.array else table.name)
    return "\n".join(out.lines) + "\n"


def mapping_text(data: Mapping[str, Any], *, header: str | None = None) -> str:
    """A project mapping (tables of values as typed: ``"64 mm"``, numbers, flags) as TOML text,
    the declared tables in their order, each key as given.

    :func:`chaindrive.drive.project.project_from_mapping` builds the drive of the same
    mapping; this is the file a user downloads (the quantities in the units they typed).

    Examples
    --------
    >>> print(mapping_text({"load": {"power": "15 kW"}, "drive": {"speed": "960 rpm", "links": 96}}), end="")
    [drive]
    speed = "960 rpm"
    links = 96
    <BLANKLINE>
    [load]
    power = "15 kW"
    """
    out = _Lines({})
    if header:
        out.lines += [ln if ln.startswith("#") or not ln else f"# {ln}" for ln in header.strip("\n").splitlines()]
    names = [t.name for t in all_tables()]
    names += [k for k in data if k not in names]
    for name in names:
        parts = name.split(".")
        table: Any = data
        for part in parts:
            table = table.get(part) if isinstance(table, Mapping) else None
        if table is None:
            continue
        for i, entry in enumerate(table if isinstance(table, list) else [table]):
            out.table(name, array=isinstance(table, list))
            for key, value in entry.items():
                if not isinstance(value, Mapping):
                    out.key(f"{name}.{i}", key, value_text(value))
    return "\n".join(out.lines) + "\n"


def _pair(values: tuple[float, float], unit: str) -> str:
    return "[" + ", ".join(quantity_text(v, unit) if unit else number_text(float(v)) for v in values) + "]"


def _self_regulating(out: _Lines, sr: Any) -> None:
    """The ``[self_regulating]`` table (its units depend on its kind)."""
    pivot = sr.kind == "pivot"
    units: dict[str, str | None] = {
        "wheel": None, "kind": None, "pivot": "m", "direction": "", "torque_reaction": None,
        "weight": "N", "weight_offset": "m", "stiffness": "N*m/rad" if pivot else "N/m",
        "preload": "N*m" if pivot else "N", "load_max_factor": None, "load_steps": None,
        "elongation_steps": None, "sag_allowance": None, "psi_tolerance": None, "numerical": None,
        "inertia": "kg*m^2" if pivot else "kg", "axial_stiffness": "N"}
    for f in dataclasses.fields(sr):
        if f.name not in units:
            continue
        value = getattr(sr, f.name)
        if value is None or (f.default is not dataclasses.MISSING and value == f.default):
            continue
        unit = units[f.name]
        if isinstance(value, tuple):
            out.key("self_regulating", f.name, _pair(value, unit or ""))
        elif isinstance(value, str):
            out.key("self_regulating", f.name, toml_string(value))
        elif unit:
            out.key("self_regulating", f.name, quantity_text(value, unit))
        else:
            out.key("self_regulating", f.name, number_text(value))


def drive_to_toml(drive: Drive, *, header: str = "") -> str:
    """:func:`project_text` with a header (the analysis' proposal files; kept for its callers)."""
    return project_text(drive, header=header or None)


def candidate_drive(candidate: Candidate, *, name: str | None = None) -> Drive:
    """The two-sprocket :class:`Drive` of a row of :func:`chaindrive.selection.select`: the
    sprockets on a horizontal line at the row's centre distance, its chain, speed, power,
    service factor and chain length."""
    from ..chains import get

    c = candidate
    also = f" (= {', '.join(c.names[1:])})" if len(c.names) > 1 else ""
    return Drive(
        chain=get(c.chain), speed=float(c.speed), links=int(c.links),
        load=Load(power=float(c.power), service_factor=float(c.service_factor)),
        wheels=(Wheel("driving", "sprocket", int(c.teeth_driving), (0.0, 0.0), driving=True),
                Wheel("driven", "sprocket", int(c.teeth_driven), (float(c.centre_distance), 0.0))),
        name=name or f"{c.chain} chain drive, {c.teeth_driving}/{c.teeth_driven} teeth",
        description=(f"{c.chain}{also}: rated {c.rated_power / 1e3:.4g} kW for a design power of "
                     f"{c.design_power / 1e3:.4g} kW (margin {c.power_margin:.2f}), lubrication "
                     f"{c.lubrication} ({c.lubrication_method})"))


def candidate_project_text(candidate: Candidate, *, name: str | None = None) -> str:
    """The project file of a row of :func:`chaindrive.selection.select` (``chaindrive select --write``).

    Examples
    --------
    >>> import numpy as np
    >>> from chaindrive.selection import select
    >>> text = candidate_project_text(select(7.5e3, 1450 * np.pi / 30, 3.0)[0])
    >>> 'name = "10B-1"' in text and "links = 116" in text
    True
    """
    c = candidate
    return project_text(
        candidate_drive(candidate, name=name),
        header="chaindrive project file written by `chaindrive select` (TOML). Quantities carry units\n"
               "(SI, exact); a bare number is refused for them. Check it with:  chaindrive layout <this file>",
        comments={"drive.speed": "driving (small) sprocket", "drive.links": "even number of pitches",
                  "wheels.1.position": f"centre distance for {c.links} links (ISO 10823)"})


#: Display units of the values a proposal may change, when the user's file gives none.
_EDIT_UNITS = {"mass": "kg", "stiffness": "kN/m", "force": "kN", "position": "m"}


def _value_in_unit(value: float, unit: str, si: str) -> str:
    """``value`` [SI] written in ``unit`` with the digits it needs (at most 6 significant)."""
    from ..units import parse_quantity

    factor = parse_quantity(f"1 {unit}", si, field="unit")
    return f"{value / factor:.6g} {unit}"


def _user_unit(item: Any, default: str) -> str:
    """The unit the user wrote for a quantity (``"200 kN/m"`` → ``"kN/m"``)."""
    text = str(item).strip() if item is not None else ""
    parts = text.split(None, 1)
    return parts[1] if len(parts) == 2 else default


def _set(table: Any, key: str, value: Any) -> None:
    """``table[key] = value`` keeping the key's comment in its column."""
    import tomlkit

    old = table.get(key)
    width = len(old.as_string()) if old is not None and hasattr(old, "as_string") else None
    comment_ws = old.trivia.comment_ws if old is not None and hasattr(old, "trivia") else ""
    table[key] = value
    new = table.item(key) if hasattr(table, "item") else table[key]
    if width is not None and old.trivia.comment:
        new.trivia.comment_ws = " " * max(1, width + len(comment_ws) - len(tomlkit.item(value).as_string()))


def _same(a: Drive, b: Drive) -> bool:
    """Equal drives, the values a proposal writes compared to 1e-9 (they went through a unit)."""
    def close(x: Any, y: Any) -> bool:
        if isinstance(x, float) and isinstance(y, float):
            return math.isclose(x, y, rel_tol=1e-9, abs_tol=1e-12)
        if isinstance(x, tuple) and isinstance(y, tuple):
            return len(x) == len(y) and all(close(u, v) for u, v in zip(x, y, strict=True))
        if dataclasses.is_dataclass(x) and type(x) is type(y):
            return all(close(getattr(x, f.name), getattr(y, f.name)) for f in dataclasses.fields(x))
        return bool(x == y)

    return close(a, b)


def edit_project_text(text: str, old: Drive, new: Drive, *, header: str = "") -> str:
    """The user's project file ``text`` (of ``old``) with only what differs in ``new`` changed.

    What a proposal changes is edited in place (tomlkit): the tensioner's mass, stiffness
    and force, and the positions of wheels; every other line, comment and the order stay
    as the user wrote them, and each changed quantity keeps the user's unit.

    Parameters
    ----------
    text : str
        The project file ``old`` was read from.
    old, new : Drive
        The drive of ``text`` and the changed one.
    header : str
        Comment lines put before the file.

    Returns
    -------
    str
        TOML text that :func:`~chaindrive.drive.project.parse_project` reads as ``new``.

    Raises
    ------
    InputError
        ``new`` differs from ``old`` in something else.

    Examples
    --------
    >>> from chaindrive.drive.project import parse_project, template
    >>> import dataclasses
    >>> text = template("conveyor")
    >>> d = parse_project(text)
    >>> t = dataclasses.replace(d.tensioner, stiffness=112e3)
    >>> out = edit_project_text(text, d, dataclasses.replace(d, tensioner=t))
    >>> [ln for ln in out.splitlines() if ln.startswith("stiffness")]
    ['stiffness = "112 kN/m"']
    >>> parse_project(out).tensioner.stiffness
    112000.0
    """
    import tomlkit

    try:
        doc = tomlkit.parse(text)
    except tomlkit.exceptions.ParseError as exc:  # not the project's text: one line, not tomlkit's
        raise InputError(f"text: not a TOML project file ({exc})", field="text") from None
    wheels = doc.get("wheels", [])
    for w0, w1 in zip(old.wheels, new.wheels, strict=True):
        if w0.position != w1.position:
            table = next(t for t in wheels if t.get("name") == w0.name)
            unit = _user_unit(table["position"][0], _EDIT_UNITS["position"])
            _set(table, "position", [_value_in_unit(v, unit, "m") for v in w1.position])
    t0, t1 = old.tensioner, new.tensioner
    if t0 != t1:
        if t0 is None or t1 is None:
            raise InputError("a proposal cannot add or remove the tensioner", field="tensioner")
        table = doc["tensioner"]
        if t1.mechanism is None and t0.mechanism is not None:  # parts replaced by their reduction
            for key in ("mechanism", *dict(t0.parts)):
                if key in table:
                    del table[key]
        for key, si in (("mass", "kg"), ("stiffness", "N/m"), ("force", "N")):
            a, b = getattr(t0, key), getattr(t1, key)
            if b is not None and (a != b or (t0.mechanism is not None and t1.mechanism is None and key != "force")):
                _set(table, key, _value_in_unit(b, _user_unit(table.get(key), _EDIT_UNITS[key]), si))
    from .project import parse_project

    out = tomlkit.dumps(doc)
    if not _same(parse_project(out), new):
        raise InputError("the proposal changes more than the tensioner and the wheel positions", field="proposal")
    if header:
        lines = [ln if ln.startswith("#") or not ln else f"# {ln}" for ln in header.strip("\n").splitlines()]
        out = "\n".join(lines) + "\n\n" + out
    return out
