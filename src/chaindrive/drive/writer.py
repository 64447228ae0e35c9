"""A :class:`~chaindrive.drive.model.Drive` written back as a project file (TOML).

:func:`drive_to_toml` writes every field of a drive with its unit, so that
:func:`chaindrive.drive.project.parse_project` reads back an equal drive (tested on every
example). Used for the proposals of the analysis (``analyze -o DIR`` writes
``DIR/proposal.toml``).
"""

from __future__ import annotations

import dataclasses
import json
import math
from typing import Any

from ..errors import InputError
from .model import TENSIONER_PARTS, Drive

__all__ = ["drive_to_toml"]

#: The unit of each physical field of the project file's tables (SI, as the drive holds it).
_UNITS: dict[str, dict[str, str]] = {
    "drive": {"slack_tension": "N"},
    "chain": {"pitch": "m", "roller_diameter": "m", "bar_diameter": "m", "inner_width": "m",
              "pin_diameter": "m", "plate_height": "m", "breaking_force": "N", "mass_per_length": "kg/m"},
    "contact": {"skew": "rad", "skew_height_difference": "m", "skew_base": "m", "seat_radius": "m",
                "contact_length": "m"},
    "track": {"tractor_weight": "N", "tooth_width": "m", "pin_radius": "m", "allowable_bending": "Pa",
              "allowable_contact": "Pa"},
    "tensioner": {"mass": "kg", "stiffness": "N/m", "force": "N", **TENSIONER_PARTS["lever"],
                  **TENSIONER_PARTS["sliding"]},
    "guides": {"end_distance": "m", "height": "m"},
    "track.bolts": {"circle_radius": "m", "diameter": "m", "plate_thickness": "m", "allowable_shear": "Pa",
                    "allowable_bearing": "Pa", "thread_pitch": "m", "yield_strength": "Pa"},
    "crawler": {"stiffness": "N", "cam_distance": "m", "engagement_distance": "m", "cam_pitch": "m",
                "cam_face_angle": "rad"},
    "fretting": {"roughness": "m", "latent_coefficient": "s/m", "decay_coefficient": "s/N", "frequency": "Hz"},
    "wheels": {"diameter": "m"},
}


def _s(text: str) -> str:
    return json.dumps(text, ensure_ascii=False)


def _q(value: float, unit: str) -> str:
    return _s(f"{float(value)!r} {unit}")


def _value(table: str, key: str, value: Any) -> str:
    unit = _UNITS.get(table, {}).get(key)
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return _s(value)
    if isinstance(value, (tuple, list)):
        return "[" + ", ".join(_value(table, key, v) for v in value) + "]"
    if unit is not None:
        return _q(value, unit)
    if isinstance(value, float) and not math.isfinite(value):
        raise InputError(f"{table}.{key}: cannot write {value!r} to a project file", field=f"{table}.{key}")
    return repr(value)


def _table(name: str, values: dict[str, Any], *, array: bool = False) -> list[str]:
    lines = [f"[[{name}]]" if array else f"[{name}]"]
    lines += [f"{k} = {_value(name, k, v)}" for k, v in values.items() if v is not None]
    return [*lines, ""]


def drive_to_toml(drive: Drive, *, header: str = "") -> str:
    """The project file (TOML) of a drive: every quantity with its unit.

    Parameters
    ----------
    drive : Drive
        The drive.
    header : str
        Comment lines put first (each line gets a leading ``#``).

    Returns
    -------
    str
        TOML text that :func:`~chaindrive.drive.project.parse_project` reads back as an
        equal drive. The chain is written by name when it is the catalogue chain of that
        name, otherwise with all its fields.

    Raises
    ------
    InputError
        A ``[self_regulating]`` table (not written yet) or a non-finite value.

    Examples
    --------
    >>> from chaindrive.drive.project import TEMPLATES, parse_project
    >>> d = parse_project(TEMPLATES["roller"])
    >>> parse_project(drive_to_toml(d)) == d
    True
    """
    from ..chains import get
    from ..errors import UnknownNameError

    if drive.self_regulating is not None:
        raise InputError("drive_to_toml: a drive with a [self_regulating] table cannot be written yet",
                         field="self_regulating")
    lines = [f"# {line}".rstrip() for line in header.splitlines()]
    if lines:
        lines.append("")
    lines += _table("drive", {
        "name": drive.name, "description": drive.description, "speed": _q(drive.speed, "rad/s")[1:-1],
        "links": drive.links, "slack_tension": drive.slack_tension, "slack_sag_ratio": drive.slack_sag_ratio,
        "required_static_safety": drive.required_static_safety, "elongation_limit": drive.elongation_limit,
        "wear_coefficient": None if drive.wear_coefficient is None else f"{drive.wear_coefficient!r} m**2/N",
        "travel": drive.travel})
    chain = drive.chain
    try:
        same = get(chain.name) == chain
    except UnknownNameError:
        same = False
    fields = ("pitch", "roller_diameter", "bar_diameter", "strands", "inner_width", "pin_diameter",
              "plate_height", "breaking_force", "mass_per_length", "source")
    lines += _table("chain", {"name": chain.name} if same else
                    {"name": chain.name, **{f: getattr(chain, f) for f in fields}})
    lines += _table("load", {"power": None if drive.load.power is None else _q(drive.load.power, "W")[1:-1],
                             "torque": None if drive.load.torque is None else _q(drive.load.torque, "N m")[1:-1],
                             "service_factor": drive.load.service_factor})
    for w in drive.wheels:
        lines += _table("wheels", {"name": w.name, "kind": w.kind, "teeth": w.teeth, "diameter": w.diameter,
                                   "position": tuple(_q(v, "m")[1:-1] for v in w.position),
                                   "driving": w.driving, "side": w.side, "power_share": w.power_share}, array=True)
    if drive.adjustable is not None:
        lines += _table("adjustable", {"wheel": drive.adjustable.wheel,
                                       "direction": [float(v) for v in drive.adjustable.direction]})
    if drive.tensioner is not None:
        t = drive.tensioner
        reduced = {"mechanism": t.mechanism, **dict(t.parts)} if t.mechanism else {"mass": t.mass,
                                                                                      "stiffness": t.stiffness}
        lines += _table("tensioner", {"wheel": t.wheel, **reduced, "kind": t.kind,
                                      "direction": [float(v) for v in t.direction], "force": t.force})
    for g in drive.guides:
        lines += _table("guides", {"wheel": g.wheel, "end_distance": g.end_distance, "kind": g.kind,
                                   "height": g.height}, array=True)
    for name in ("contact", "track", "crawler", "fretting"):
        spec = getattr(drive, name)
        if spec is not None:
            values = dataclasses.asdict(spec)
            bolts = values.pop("bolts", None)
            lines += _table(name, values)
            if bolts is not None:  # [track.bolts]
                lines += _table(f"{name}.bolts", bolts)
    return "\n".join(lines)
