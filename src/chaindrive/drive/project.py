"""TOML project files: a drive described once, with units, validated with line numbers.

A project file has the tables ``[drive]``, ``[chain]``, ``[load]``, an array
``[[wheels]]`` (in the order the chain passes them, counter-clockwise), and the
optional ``[tensioner]`` and ``[[guides]]``. Every physical quantity is written with its
unit (``"64 mm"``, ``"300 rpm"``, ``"15 kW"``); a bare number is refused for it (1450
could be rpm or rad/s), and stays for counts and ratios (teeth, service factor). The
driving wheel's ``speed`` may be the mean chain speed (``"1.2 m/s"``, how scraper
conveyors are specified). The
tables are declared once (:mod:`chaindrive.drive.tables`); the pydantic models that check
them are generated from the declarations (:func:`chaindrive.drive._reader.reader_model`); every mistake is reported with its field and its line
in the file, e.g. ``drive.toml:14: wheels[1].teeth: must be a whole number >= 3``.

:func:`load_project` returns a :class:`~chaindrive.drive.model.Drive`;
:func:`template` gives the commented templates written by ``chaindrive new``.
"""

from __future__ import annotations

import dataclasses
import os
import re
import tomllib  # noqa: F401 - used by the doctests (Python >= 3.11)
from pathlib import Path
from typing import Any

import numpy as np
from pydantic import ValidationError

from ..errors import ChainDriveError, InputError, UnknownNameError
from ..kinematics.speed import chain_speed_to_angular_velocity
from ..limits import warn_implausible
from ..loads import mean_chain_speed
from . import model as _model
from ._reader import ChainSpeedSpec, project_model
from .clearance import clearance_error
from .model import Adjustable, Drive, Guide, Load, Tensioner, Wheel
from .schema import all_tables, load_providers
from .tables import further_inputs
from .templates import TEMPLATES, template  # the templates of `chaindrive new`

__all__ = ["load_project", "parse_project", "project_from_mapping", "line_index", "template", "TEMPLATES"]


def __getattr__(name: str) -> Any:
    if name == "Project":  # the pydantic model of the whole file, generated from the declarations
        return project_model()
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def _tensioner(spec: Any) -> Tensioner:
    """The model's tensioner of a ``[tensioner]`` table (its parts reduced to the axis when a
    mechanism is given)."""
    if spec.mechanism is None:
        return Tensioner(spec.wheel, spec.mass, spec.stiffness, kind=spec.kind, direction=spec.direction,
                         force=spec.force)
    parts = {k: getattr(spec, k) for k in _model.TENSIONER_PARTS[spec.mechanism] if getattr(spec, k) is not None}
    return Tensioner.from_parts(spec.wheel, spec.mechanism, parts, kind=spec.kind, direction=spec.direction,
                                force=spec.force)


# --------------------------------------------------------------------------- line numbers

_HEADER = re.compile(r"^\s*(\[\[?)\s*([A-Za-z0-9_.\-\" ]+?)\s*\]\]?\s*(#.*)?$")
_KEY = re.compile(r"^\s*([A-Za-z0-9_\-]+|\"[^\"]*\")\s*=")


def line_index(text: str) -> dict[tuple, int]:
    """Map each table and key path of a TOML text to its (1-based) line.

    Array-of-tables entries get their index: ``("wheels", 1, "teeth")``.

    Examples
    --------
    >>> idx = line_index('[drive]\\nspeed = 5\\n[[wheels]]\\nname = "a"\\n[[wheels]]\\nteeth = 8\\n')
    >>> idx[("drive", "speed")], idx[("wheels", 1)], idx[("wheels", 1, "teeth")]
    (2, 5, 6)
    """
    index: dict[tuple, int] = {}
    counters: dict[tuple, int] = {}
    current: tuple = ()
    for n, raw in enumerate(text.splitlines(), start=1):
        line = raw.strip()
        if not line or line.startswith("#"):
            continue
        m = _HEADER.match(raw)
        if m and not _KEY.match(raw):
            parts = tuple(p.strip().strip('"') for p in m.group(2).split("."))
            if m.group(1) == "[[":
                i = counters.get(parts, -1) + 1
                counters[parts] = i
                current = parts + (i,)
            else:
                current = parts
            index.setdefault(current, n)
            if current[-1:] and isinstance(current[-1], int):
                index.setdefault(parts, n)
            continue
        k = _KEY.match(raw)
        if k:
            index.setdefault(current + (k.group(1).strip('"'),), n)
    return index


def _line_for(loc: tuple, index: dict[tuple, int]) -> int | None:
    loc = tuple(loc)
    for cut in range(len(loc), 0, -1):
        if loc[:cut] in index:
            return index[loc[:cut]]
    return None


def _path(loc) -> str:
    out = ""
    for part in loc:
        if isinstance(part, int):
            out += f"[{part}]"
        else:
            out += ("." if out else "") + str(part)
    return out or "(file)"


def _where(filename: str, line: int | None) -> str:
    return f"{filename}:{line}" if line else filename


#: pydantic errors of a number outside its field's bounds (answered with the bounds, one line).
_BOUND_ERRORS = ("int_parsing_size", "less_than_equal", "greater_than_equal", "less_than", "greater_than",
                 "int_from_float", "finite_number")


def _field_info(loc: tuple) -> Any:
    """The pydantic FieldInfo of the project field at ``loc`` (None when not found)."""
    import types
    import typing

    model: Any = project_model()
    info = None
    for part in loc:
        if isinstance(part, int):
            continue
        fields = getattr(model, "model_fields", None)
        if not fields or part not in fields:
            return None
        info = fields[part]
        model = None
        stack = [info.annotation]
        while stack:  # the model class inside Optional[...] / list[...] / tuple[...]
            t = stack.pop()
            if isinstance(t, type) and hasattr(t, "model_fields"):
                model = t
                break
            if isinstance(t, (types.UnionType,)) or typing.get_origin(t) is not None:
                stack.extend(typing.get_args(t))
    return info


def _constraints(info: Any) -> list:
    """Bounds of a field: its metadata and those inside ``Annotated[...]`` in its annotation."""
    import typing

    found = list(getattr(info, "metadata", ()) or ())
    stack = [info.annotation]
    while stack:
        t = stack.pop()
        args = typing.get_args(t)
        if typing.get_origin(t) is typing.Annotated:
            for extra in args[1:]:
                found.extend(getattr(extra, "metadata", None) or [extra])
            stack.append(args[0])
        else:
            stack.extend(a for a in args if a is not type(None))
    return found


def _bound_message(loc: tuple, value: Any, kind: str) -> str | None:
    """``must be a whole number in [3, 10000], got 1e+300`` for a field with bounds."""
    info = _field_info(loc)
    if info is None:
        return None
    low = high = None
    low_open = high_open = False
    for m in _constraints(info):
        if getattr(m, "ge", None) is not None or getattr(m, "gt", None) is not None:
            low_open = getattr(m, "ge", None) is None
            low = m.gt if low_open else m.ge
        if getattr(m, "le", None) is not None or getattr(m, "lt", None) is not None:
            high_open = getattr(m, "le", None) is None
            high = m.lt if high_open else m.le
    whole = "int" in str(info.annotation)
    if low is None and high is None and not whole:
        return None
    shown = f"{value:g}" if isinstance(value, float) else repr(value)
    what = "a whole number" if whole else "a number"
    if low is not None and high is not None:
        return f"must be {what} in {'(' if low_open else '['}{low:g}, {high:g}{')' if high_open else ']'}, got {shown}"
    if low is not None:
        return f"must be {what} {'>' if low_open else '>='} {low:g}, got {shown}"
    if high is not None:
        return f"must be {what} {'<' if high_open else '<='} {high:g}, got {shown}"
    return f"must be {what}, got {shown}"


def _format_errors(exc: ValidationError, index: dict, filename: str) -> str:
    lines = []
    for err in exc.errors(include_url=False):
        loc = tuple(p for p in err["loc"] if not (isinstance(p, str) and p in ("function-after",)))
        # drop pydantic's internal tags (e.g. tuple/union branch names)
        loc = tuple(p for p in loc if isinstance(p, int) or not p.startswith(("float", "int", "str",
                                                                               "tuple", "list", "none")))
        msg = err["msg"]
        msg = msg.removeprefix("Value error, ")
        if err["type"] == "missing":
            msg = "required field is missing"
            line = _line_for(loc[:-1], index)
            where = _where(filename, line)
            hint = f" (add it to the [{_path(loc[:-1])}] table)" if loc[:-1] else f" (add a [{_path(loc)}] table)"
            lines.append(f"{where}: {_path(loc)}: {msg}{hint}")
            continue
        if err["type"] == "extra_forbidden":
            msg = "unknown field (check the spelling; see `chaindrive new` for a template)"
        elif err["type"] in _BOUND_ERRORS:
            msg = _bound_message(loc, err.get("input"), err["type"]) or msg
        lines.append(f"{_where(filename, _line_for(loc, index))}: {_path(loc)}: {msg}")
    from .._io import cap_lines

    return "\n".join(cap_lines(list(dict.fromkeys(lines)), 20))


# --------------------------------------------------------------------------- loading


def _chain(spec: Any, index, filename):
    from ..chains import Chain, get

    overrides = {k: v for k, v in spec.model_dump().items()
                 if k not in ("name",) and v is not None}
    try:
        base = get(spec.name)
    except UnknownNameError as exc:
        if "pitch" not in overrides:
            raise UnknownNameError(
                f"{_where(filename, _line_for(('chain', 'name'), index))}: chain.name: {exc} "
                "(or describe a custom chain with pitch, roller_diameter or bar_diameter, ...)"
            ) from None
        try:
            return Chain.custom(spec.name, **overrides)
        except InputError as exc2:
            raise InputError(f"{_where(filename, _line_for(('chain',), index))}: chain: {exc2}") from None
    if overrides:
        return dataclasses.replace(base, **overrides)
    return base


def parse_project(text: str, filename: str = "<project>") -> Drive:
    """Validate a project text and build its :class:`Drive`.

    Raises
    ------
    InputError
        TOML syntax, wrong unit, missing field, negative value, unknown field; the
        message names the field and ``filename:line``.
    UnknownNameError
        Unknown chain name (with the closest catalogue names).

    Examples
    --------
    >>> d = parse_project(template("roller"))
    >>> d.chain.name, len(d.wheels)
    ('16B-1', 2)
    """
    from .._io import load_toml_text

    data = load_toml_text(text, filename)  # syntax, size and nesting (<= 32) checked, one line each
    return project_from_mapping(data, filename=filename, index=line_index(text))


def project_from_mapping(data: dict[str, Any], filename: str = "<project>", *,
                         index: dict[tuple, int] | None = None) -> Drive:
    """Validate a project mapping (a parsed TOML project file) and build its :class:`Drive`.

    Parameters
    ----------
    data : dict
        The project file's tables as a mapping, quantities as in the file (``"64 mm"``
        or SI numbers).
    filename : str
        Name used in error messages.
    index : dict, optional
        Line numbers from :func:`line_index` (error messages name the line when given).

    Raises
    ------
    InputError, UnknownNameError
        As :func:`parse_project`.

    Examples
    --------
    >>> data = tomllib.loads(template("roller"))
    >>> data["drive"]["speed"] = "1450 rpm"
    >>> round(project_from_mapping(data).speed, 3)
    151.844
    """
    if index is None:
        index = {}
    if isinstance(data, dict) and set(data) - {t.name.split(".")[0] for t in all_tables()}:
        load_providers()   # a table an analysis part declares
    try:
        proj: Any = project_model().model_validate(data)
    except ValidationError as exc:
        raise InputError(_format_errors(exc, index, filename)) from None
    chain = _chain(proj.chain, index, filename)
    # every rule of the drive itself (one driving wheel, guides and tensioner naming a
    # wheel, teeth or a diameter, ...) is checked once, by the Drive objects; here the
    # error only gets its line in the file
    wheels = []
    for i, w in enumerate(proj.wheels):
        try:
            wheels.append(Wheel(name=w.name, kind=w.kind, teeth=w.teeth, position=w.position,
                                driving=w.driving, diameter=w.diameter, side=w.side,
                                power_share=w.power_share))
        except ChainDriveError as exc:
            raise _located(exc, ("wheels", i), filename, index) from None
    try:
        drive = Drive(
            chain=chain,
            wheels=tuple(wheels),
            speed=_speed_of(proj.drive.speed, chain, wheels, filename, index),
            load=Load(power=proj.load.power, torque=proj.load.torque,
                      service_factor=proj.load.service_factor),
            tensioner=None if proj.tensioner is None else _tensioner(proj.tensioner),
            adjustable=None if proj.adjustable is None else Adjustable(**proj.adjustable.model_dump()),
            guides=tuple(Guide(**g.model_dump()) for g in proj.guides),
            links=proj.drive.links, slack_tension=proj.drive.slack_tension,
            slack_sag_ratio=proj.drive.slack_sag_ratio,
            required_static_safety=proj.drive.required_static_safety,
            elongation_limit=proj.drive.elongation_limit,
            wear_coefficient=proj.drive.wear_coefficient,
            name=proj.drive.name, description=proj.drive.description, travel=proj.drive.travel,
            contact=None if proj.contact is None else _model.ContactSpec(**proj.contact.model_dump()),
            track=None if proj.track is None else _model.TrackSpec(**proj.track.model_dump()),
            crawler=None if proj.crawler is None else _model.CrawlerSpec(**proj.crawler.model_dump()),
            fretting=None if proj.fretting is None else _model.FrettingSpec(**proj.fretting.model_dump()),
            self_regulating=_self_regulating(proj.self_regulating, filename, index),
            conveyor=None if proj.conveyor is None else _model.Conveyor(**proj.conveyor.model_dump()),
            extra_inputs=further_inputs(proj),
        )
    except ChainDriveError as exc:
        raise _located(exc, _loc_of(exc.field), filename, index) from None
    try:
        clearance_error(drive, np.array([w.position for w in drive.wheels], dtype=float))
    except ChainDriveError as exc:
        raise _located(exc, _loc_of(exc.field), filename, index) from None
    return drive


def _speed_of(speed: float | ChainSpeedSpec, chain, wheels, filename: str, index: dict) -> float:
    """The driving wheel's angular speed [rad/s]; a chain speed v goes through
    :func:`chaindrive.kinematics.speed.chain_speed_to_angular_velocity` (v = n p omega / 2 pi)."""
    driving = [w for w in wheels if w.driving]
    if not isinstance(speed, ChainSpeedSpec):
        if len(driving) == 1 and driving[0].teeth is not None and not warn_implausible(
                "drive.speed", speed, "angular_velocity", stacklevel=3):
            v = mean_chain_speed(driving[0].sides_per_turn(chain), chain.pitch, speed)
            warn_implausible("drive.speed (chain speed n p omega / 2 pi)", v, "chain_speed", stacklevel=3)
        return speed
    where = _where(filename, _line_for(("drive", "speed"), index))
    if len(driving) != 1 or driving[0].teeth is None:
        raise InputError(f"{where}: drive.speed: a chain speed ({speed.chain_speed:g} m/s) needs exactly one "
                         "driving wheel with teeth; or give the wheel speed, e.g. \"300 rpm\"")
    omega = chain_speed_to_angular_velocity(speed.chain_speed, chain.pitch, driving[0].teeth,
                                            link_chain=chain.is_link_chain)
    warn_implausible("drive.speed", omega, "angular_velocity", stacklevel=3)
    return omega


def _self_regulating(table: dict[str, Any] | None, filename: str, index: dict) -> Any:
    """The ``[self_regulating]`` table as a :class:`~chaindrive.drive.carrier.SelfRegulatingSpec`."""
    if table is None:
        return None
    from .carrier import SelfRegulatingSpec

    for key, unit in _CARRIER_UNITS.items():
        values = table.get(key)
        for v in values if isinstance(values, (list, tuple)) else [values]:
            if isinstance(v, (int, float)) and not isinstance(v, bool) and v != 0:
                shown = f"{v:g}" if isinstance(v, float) else str(v)
                example = f'["{shown} {unit}", "0 {unit}"]' if isinstance(values, (list, tuple)) else f'"{shown} {unit}"'
                raise InputError(f"{_where(filename, _line_for(('self_regulating', key), index))}: "
                                 f"self_regulating.{key}: give a unit, e.g. {key} = {example} "
                                 "(see docs/self_regulating.md)", field=f"self_regulating.{key}")

    try:
        return SelfRegulatingSpec.from_table(table)
    except ChainDriveError as exc:
        named = re.match(r"self_regulating\.(\w+)", str(exc))  # the key the message is about
        loc = _loc_of(exc.field) or (("self_regulating", named.group(1)) if named else ("self_regulating",))
        raise _located(exc, loc, filename, index) from None


#: The unit of each quantity of the [self_regulating] table (for the example of a bare number).
_CARRIER_UNITS = {"pivot": "mm", "weight": "N", "weight_offset": "mm", "stiffness": "N/m", "preload": "N"}


def _loc_of(field: str | None) -> tuple:
    """``"guides[0].wheel"`` -> ``("guides", 0, "wheel")``."""
    if not field:
        return ()
    out: list = []
    for part in field.split("."):
        m = re.fullmatch(r"([A-Za-z_]+)((?:\[\d+\])*)", part)
        if m is None:
            break
        out.append(m.group(1))
        out.extend(int(i) for i in re.findall(r"\[(\d+)\]", m.group(2)))
    return tuple(out)


def _located(exc: ChainDriveError, loc: tuple, filename: str, index: dict) -> ChainDriveError:
    """``exc`` with ``filename:line`` of ``loc`` in front of its message (once: a message
    located already is returned as it is)."""
    if str(exc).startswith(f"{filename}:"):
        return exc
    return type(exc)(f"{_where(filename, _line_for(loc, index) if loc else None)}: {exc}", field=exc.field)


def load_project(path: str | os.PathLike[str]) -> Drive:
    """Read a TOML project file and return its :class:`Drive`.

    Parameters
    ----------
    path : str or pathlib.Path

    Raises
    ------
    InputError
        File missing, a folder, unreadable, larger than 1 MiB, binary, not UTF-8, nested
        deeper than 32, or invalid (field and line named; at most 20 errors listed).

    Examples
    --------
    >>> import pathlib, tempfile
    >>> f = pathlib.Path(tempfile.mkdtemp()) / "drive.toml"
    >>> _ = f.write_text(template("mining"))
    >>> load_project(f).chain.name
    '18x64'
    """
    from .._io import read_text_file

    p = Path(path)
    text = read_text_file(p, what="project file")  # one line for missing/folder/binary/non-UTF-8/> 1 MiB
    return parse_project(text, filename=p.name)
