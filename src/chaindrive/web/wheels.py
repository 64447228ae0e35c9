"""Further wheels of a studio design: driven machine sprockets (with their power share) and
idlers beyond the driving and driven wheel.

The studio's form keeps the two main wheels (driving at the origin, driven at the centre
distance, an optional tensioner idler on the slack span between them); the further wheels
follow the driven wheel round the loop (counter-clockwise) back to the driving one. Each
row of the form gives a kind, teeth, a position (with units, the driving wheel at the
origin), the side of the chain and, for a driven sprocket, its power share; the driven
wheel takes the rest of the power. Without a tensioner the driven wheel is the adjustable
one (moved along the line of centres until the even link count fits,
:func:`chaindrive.layout.adjust_loop`). The form only reads and writes text: every rule of
the drive (shares in (0, 1] summing to 1, one driving wheel, a chain path) is checked by
:class:`chaindrive.drive.Drive` and the layout.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from ..display import mm
from .fields import FieldError, FieldSpec, parse_field, parse_integer

__all__ = ["MAX_EXTRA_WHEELS", "EXTRA_DEFAULTS", "EXTRA_CHOICES", "ExtraWheel", "extra_wheels", "add_extra_wheels",
           "extra_rows"]

#: Most further wheels the studio edits (a project file may have any number).
MAX_EXTRA_WHEELS = 4

_ROW_DEFAULTS = {"kind": "sprocket", "teeth": "25", "x": "250 mm", "y": "400 mm", "side": "1", "share": ""}

#: The form fields of the further wheels and their default texts.
EXTRA_DEFAULTS: dict[str, str] = {"extra_wheels": "0", **{
    f"wheel{i}_{key}": value for i in range(MAX_EXTRA_WHEELS) for key, value in _ROW_DEFAULTS.items()}}

#: Choice fields (anything else falls back to the default).
EXTRA_CHOICES: dict[str, tuple[str, ...]] = {
    "extra_wheels": tuple(str(n) for n in range(MAX_EXTRA_WHEELS + 1)),
    **{f"wheel{i}_kind": ("sprocket", "idler") for i in range(MAX_EXTRA_WHEELS)},
    **{f"wheel{i}_side": ("1", "-1") for i in range(MAX_EXTRA_WHEELS)},
}

_COORDINATE = FieldSpec("m", -50.0, 50.0, open_minimum=False, example="400 mm")
_SHARE = FieldSpec("", 0.0, 1.0, example="0.4")


@dataclass(frozen=True)
class ExtraWheel:
    """One further wheel of the form (SI units)."""

    name: str
    kind: str
    teeth: int
    x: float
    y: float
    side: int
    share: float | None


def extra_rows(state: dict[str, str]) -> list[dict[str, str]]:
    """The rows of further wheels the form shows (their field names and texts).

    >>> from chaindrive.web.design import normalise_state
    >>> [r["kind"] for r in extra_rows(normalise_state({"extra_wheels": "2", "wheel1_kind": "idler"}))]
    ['sprocket', 'idler']
    """
    count = int(state.get("extra_wheels", "0") or 0)
    return [{"index": str(i), **{key: state.get(f"wheel{i}_{key}", default) for key, default in _ROW_DEFAULTS.items()}}
            for i in range(count)]


def extra_wheels(state: dict[str, str], errors: dict[str, str], kind: str = "roller") -> list[ExtraWheel]:
    """Parse the further wheels of a (normalised) state; field errors go to ``errors``.

    Examples
    --------
    >>> from chaindrive.web.design import normalise_state
    >>> errors = {}
    >>> extra_wheels(normalise_state({"extra_wheels": "1", "wheel0_share": "0.4"}), errors)[0].share, errors
    (0.4, {})
    >>> extra_wheels(normalise_state({"extra_wheels": "1", "wheel0_y": "400"}), errors), errors
    ([], {'wheel0_y': "give a unit, e.g. '400 mm' (a bare number is ambiguous)"})
    """
    out = []
    minimum_teeth = 3 if kind == "link" else 6
    for i, row in enumerate(extra_rows(state)):
        name = f"wheel{i}"
        values: dict[str, float | int | None] = {}
        for key, spec in (("x", _COORDINATE), ("y", _COORDINATE)):
            try:
                values[key] = parse_field(f"{name}_{key}", row[key], spec)
            except FieldError as exc:
                errors[exc.field] = exc.message
        try:
            values["teeth"] = parse_integer(f"{name}_teeth", row["teeth"], minimum_teeth, 150)
        except FieldError as exc:
            errors[exc.field] = exc.message
        share = None
        if row["kind"] == "sprocket" and row["share"].strip():
            try:
                share = parse_field(f"{name}_share", row["share"], _SHARE)
            except FieldError as exc:
                errors[exc.field] = exc.message
        if any(values.get(k) is None for k in ("x", "y", "teeth")):
            continue
        out.append(ExtraWheel(name=f"{'machine' if row['kind'] == 'sprocket' else 'idler'} {i + 1}",
                              kind=row["kind"], teeth=int(values["teeth"] or 0), x=float(values["x"] or 0.0),
                              y=float(values["y"] or 0.0), side=int(row["side"]), share=share))
    shares = [w.share for w in out if w.share is not None]
    if shares and sum(shares) >= 1.0:
        last = max(i for i, w in enumerate(out) if w.share is not None)
        errors[f"wheel{last}_share"] = (f"the shares of the further wheels sum to {sum(shares):g}; they must "
                                        "stay below 1 (the driven wheel takes the rest)")
    return out


def add_extra_wheels(data: dict[str, Any], extras: list[ExtraWheel], *, wheel_kind: str,
                     adjustable: bool) -> dict[str, Any]:
    """The studio's project mapping with the further wheels after the driven wheel.

    Gives the driven wheel the ``power_share`` the further wheels leave (all of it when
    they take none), and an ``[adjustable]`` table moving the driven wheel along the line of
    centres when ``adjustable``.
    """
    if not extras:
        return data
    wheels = [dict(w) for w in data["wheels"]]
    at = next((i for i, w in enumerate(wheels) if w.get("name") == "driven"), None)
    if at is None:
        raise ValueError("the studio's project has no driven wheel")
    shares = [w.share for w in extras if w.share is not None]
    wheels[at]["power_share"] = float(f"{1.0 - sum(shares):.12g}")  # all of it without further driven wheels
    added = []
    for w in extras:
        entry: dict[str, Any] = {"name": w.name, "kind": wheel_kind if w.kind == "sprocket" else "idler",
                                 "teeth": w.teeth, "position": [f"{mm(w.x):.4f} mm", f"{mm(w.y):.4f} mm"]}
        if w.side != 1:
            entry["side"] = w.side
        if w.share is not None:
            entry["power_share"] = float(f"{w.share:.12g}")
        added.append(entry)
    out = {**data, "wheels": wheels[:at + 1] + added + wheels[at + 1:]}
    if adjustable:
        out["adjustable"] = {"wheel": "driven", "direction": [1, 0]}
    return out
