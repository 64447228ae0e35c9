"""The one project-file writer: a :class:`~chaindrive.drive.model.Drive` (plus comments) as
TOML text that :func:`chaindrive.drive.project.parse_project` reads back to an equal Drive.

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
import json
import math
from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

from ..errors import InputError
from .model import TENSIONER_PARTS, Drive, Load, Wheel

if TYPE_CHECKING:
    from ..selection import Candidate

__all__ = ["project_text", "drive_to_toml", "edit_project_text", "candidate_drive", "candidate_project_text", "toml_string",
           "quantity_text"]


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


def _number(value: float | int) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    return repr(float(value))


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


_CHAIN_FIELDS = {"pitch": "m", "roller_diameter": "m", "bar_diameter": "m", "strands": None, "inner_width": "m",
                 "pin_diameter": "m", "plate_height": "m", "breaking_force": "N", "mass_per_length": "kg/m",
                 "source": ""}


def _chain(out: _Lines, chain: Any) -> None:
    from ..chains import get
    from ..errors import UnknownNameError

    out.table("chain")
    out.key("chain", "name", toml_string(chain.name))
    try:
        base = get(chain.name)
    except UnknownNameError:
        base = None
    for key, unit in _CHAIN_FIELDS.items():
        value = getattr(chain, key)
        if value is None or (base is not None and getattr(base, key) == value):
            continue
        if unit is None:
            out.key("chain", key, str(int(value)))
        elif unit == "":
            out.key("chain", key, toml_string(value))
        else:
            out.key("chain", key, quantity_text(value, unit))


def _pair(values: tuple[float, float], unit: str) -> str:
    return "[" + ", ".join(quantity_text(v, unit) if unit else _number(float(v)) for v in values) + "]"


def _optional_fields(out: _Lines, table: str, obj: Any, units: Mapping[str, str | None]) -> None:
    """The fields of ``obj`` that differ from their defaults (required ones always)."""
    for f in dataclasses.fields(obj):
        if f.name not in units:
            continue
        value = getattr(obj, f.name)
        default = f.default
        if f.default is not dataclasses.MISSING and value == default:
            continue
        if value is None:
            continue
        unit = units[f.name]
        if isinstance(value, tuple):
            out.key(table, f.name, _pair(value, unit or ""))
        elif isinstance(value, str):
            out.key(table, f.name, toml_string(value))
        elif unit:
            out.key(table, f.name, quantity_text(value, unit))
        else:
            out.key(table, f.name, _number(value))


#: The SI unit of the physical fields of the tables written generically (the others are numbers or text).
_SPEC_UNITS: dict[str, dict[str, str]] = {
    "track.bolts": {"circle_radius": "m", "diameter": "m", "plate_thickness": "m", "allowable_shear": "Pa",
                    "allowable_bearing": "Pa", "thread_pitch": "m", "yield_strength": "Pa"},
    "crawler": {"stiffness": "N", "cam_distance": "m", "engagement_distance": "m", "cam_pitch": "m",
                "cam_face_angle": "rad"},
    "fretting": {"roughness": "m", "latent_coefficient": "s/m", "decay_coefficient": "s/N", "frequency": "Hz"},
    "conveyor": {"material_load": "kg/m", "capacity": "kg/s", "inclination": "rad", "minimum_tension": "N"},
}


def _all_fields(spec: Any, units: Mapping[str, str]) -> dict[str, str | None]:
    """Every field of a spec with its unit (``None``: a number, a flag or text)."""
    return {f.name: units.get(f.name) for f in dataclasses.fields(spec)}


def project_text(drive: Drive, *, header: str | None = None, comments: Mapping[str, str] | None = None) -> str:
    """The project file (TOML) of ``drive``: :func:`~chaindrive.drive.project.parse_project`
    reads it back to an equal :class:`Drive`.

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
    d = drive
    out.table("drive")
    out.key("drive", "name", toml_string(d.name))
    if d.description:
        out.key("drive", "description", toml_string(d.description))
    out.key("drive", "speed", quantity_text(d.speed, "rad/s"))
    if d.links is not None:
        out.key("drive", "links", str(int(d.links)))
    if d.slack_tension is not None:
        out.key("drive", "slack_tension", quantity_text(d.slack_tension, "N"))
    defaults = {f.name: f.default for f in dataclasses.fields(Drive)}
    for key in ("slack_sag_ratio", "required_static_safety", "elongation_limit"):
        if getattr(d, key) != defaults[key] or f"drive.{key}" in out.comments:
            out.key("drive", key, _number(getattr(d, key)))
    if d.wear_coefficient is not None:
        out.key("drive", "wear_coefficient", quantity_text(d.wear_coefficient, "m**2/N"))
    if d.travel != "ccw" or "drive.travel" in out.comments:
        out.key("drive", "travel", toml_string(d.travel))
    _chain(out, d.chain)
    out.table("load")
    if d.load.power is not None:
        out.key("load", "power", quantity_text(d.load.power, "W"))
    if d.load.torque is not None:
        out.key("load", "torque", quantity_text(d.load.torque, "N*m"))
    out.key("load", "service_factor", _number(d.load.service_factor))
    for i, w in enumerate(d.wheels):
        out.table("wheels", array=True)
        where = f"wheels.{i}"
        out.key(where, "name", toml_string(w.name))
        out.key(where, "kind", toml_string(w.kind))
        if w.teeth is not None:
            out.key(where, "teeth", str(int(w.teeth)))
        if w.diameter is not None:
            out.key(where, "diameter", quantity_text(w.diameter, "m"))
        out.key(where, "position", _pair(w.position, "m"))
        if w.driving:
            out.key(where, "driving", "true")
        if w.side != 1:
            out.key(where, "side", str(int(w.side)))
        if w.power_share is not None:
            out.key(where, "power_share", _number(w.power_share))
    if d.adjustable is not None:
        out.table("adjustable")
        out.key("adjustable", "wheel", toml_string(d.adjustable.wheel))
        out.key("adjustable", "direction", _pair(d.adjustable.direction, ""))
    if d.tensioner is not None:
        t = d.tensioner
        out.table("tensioner")
        if t.mechanism is None:
            _optional_fields(out, "tensioner", t, {"wheel": None, "mass": "kg", "stiffness": "N/m",
                                                  "kind": None, "direction": "", "force": "N"})
        else:  # described by its parts: the reader reduces them to mass and stiffness again
            _optional_fields(out, "tensioner", t, {"wheel": None, "kind": None, "direction": "", "force": "N",
                                                  "mechanism": None})
            units = TENSIONER_PARTS[t.mechanism]
            for key, value in t.parts:
                out.key("tensioner", key, quantity_text(value, units[key]))
    for i, g in enumerate(d.guides):
        out.table("guides", array=True)
        out.key(f"guides.{i}", "wheel", toml_string(g.wheel))
        out.key(f"guides.{i}", "kind", toml_string(g.kind))
        out.key(f"guides.{i}", "end_distance", quantity_text(g.end_distance, "m"))
        if g.height is not None:
            out.key(f"guides.{i}", "height", quantity_text(g.height, "m"))
    if d.contact is not None:
        out.table("contact")
        _optional_fields(out, "contact", d.contact, {"skew": "rad", "skew_height_difference": "m", "skew_base": "m",
                                                      "wear_factor": None, "seat_radius": "m", "contact_length": "m"})
    if d.track is not None:
        out.table("track")
        _optional_fields(out, "track", d.track, {"tractor_weight": "N", "tooth_width": "m", "pin_radius": "m",
                                                  "adhesion": None, "rims": None, "link": None, "hardness": None,
                                                  "allowable_bending": "Pa", "allowable_contact": "Pa"})
    bolts = getattr(d.track, "bolts", None) if d.track is not None else None
    if bolts is not None:
        out.table("track.bolts")
        _optional_fields(out, "track.bolts", bolts, _all_fields(bolts, _SPEC_UNITS["track.bolts"]))
    for name in ("crawler", "fretting", "conveyor"):
        spec = getattr(d, name, None)
        if spec is not None:
            out.table(name)
            _optional_fields(out, name, spec, _all_fields(spec, _SPEC_UNITS[name]))
    if d.self_regulating is not None:
        sr = d.self_regulating
        pivot = sr.kind == "pivot"
        out.table("self_regulating")
        _optional_fields(out, "self_regulating", sr, {
            "wheel": None, "kind": None, "pivot": "m", "direction": "", "torque_reaction": None,
            "weight": "N", "weight_offset": "m", "stiffness": "N*m/rad" if pivot else "N/m",
            "preload": "N*m" if pivot else "N", "load_max_factor": None, "load_steps": None,
            "elongation_steps": None, "sag_allowance": None, "psi_tolerance": None, "numerical": None,
            "inertia": "kg*m^2" if pivot else "kg", "axial_stiffness": "N"})
    return "\n".join(out.lines) + "\n"


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
