"""The units of a study's outputs: read from the unit each result class declares
(:func:`chaindrive._results.quantity`) along an output's path, and their display units
(:mod:`chaindrive.display`). Used by the runner (the units stored in study.json) and by
the summary."""

from __future__ import annotations

import re
from typing import Any

__all__ = ["output_unit", "output_display"]

#: Units of the analysis results by their last name (the results are SI; wear in hours).
#: Units of the outputs that are no result field (the simulation's summary keys).
_UNITS = {
    "stress": "Pa", "stress_unskewed": "Pa", "effective_modulus": "Pa", "hours_to_limit": "h",
    "maximum": "N", "tight": "N", "slack": "N", "effective_pull": "N", "dynamic": "N",
    "centrifugal": "N", "nominal_load": "N", "equivalent_load": "N", "load": "N",
    "chain_speed": "m/s", "torque": "N*m", "frequencies_rad_s": "rad/s", "frequencies_hz": "Hz",
    "static_rod_force": "N", "heavy_tensioner_frequency": "rad/s", "rated_power": "W",
    "design_power": "W", "acceleration_peak": "m/s²", "skew": "rad", "max_skew": "rad",
    "design_skew": "rad", "half_width": "m", "centre_distance": "m", "slack_sag": "m",
    "tight_side_tension_mean": "N", "tight_side_tension_max": "N", "slack_side_tension_mean": "N",
    "max_link_tension": "N", "max_contact_force": "N",
}


def _result_classes() -> dict[str, type]:
    from .._results import Result

    out: dict[str, type] = {}
    stack = list(Result.__subclasses__())
    while stack:
        cls = stack.pop()
        out.setdefault(cls.__name__, cls)
        stack += cls.__subclasses__()
    return out


def _classes_in(annotation: Any) -> list[type]:
    """The result classes named in a (string) annotation."""
    classes = _result_classes()
    return [classes[n] for n in re.findall(r"[A-Za-z_]\w*", str(annotation)) if n in classes]


def _field_unit(cls: type, names: list[str], depth: int = 0) -> tuple[str, str | None] | None:
    """(SI unit, display unit) of the field at ``names`` inside result class ``cls``."""
    import dataclasses

    from .._results import Result

    if not names or not (dataclasses.is_dataclass(cls) and issubclass(cls, Result)):
        return None
    fields = {f.name: f for f in dataclasses.fields(cls)}
    head, rest = names[0], names[1:]
    if head in fields:
        for sub in _classes_in(fields[head].type):
            found = _field_unit(sub, rest)
            if found is not None:
                return found
        unit = cls.unit_of(head)
        # a dict or array field's entries carry the field's unit
        return None if unit is None else (unit, cls.display_unit_of(head))
    if depth < 2:  # a to_dict() that flattens a nested result (ContactAnalysis: its result's fields)
        for f in fields.values():
            for sub in _classes_in(f.type):
                found = _field_unit(sub, names, depth + 1)
                if found is not None:
                    return found
    return None


def _declared(path: str) -> tuple[str, str | None] | None:
    """(SI unit, display unit) declared by the result classes for a study output path."""
    import inspect

    from ..analysis.parts import all_parts

    names = [p for p in path.split(".") if not p.lstrip("-").isdigit()]
    if len(names) < 2:
        return None
    for part in all_parts():
        if part.name == names[0]:
            if part.unit is not None and len(names) == 1:
                return part.unit, None
            for cls in _classes_in(inspect.signature(part.compute).return_annotation):
                found = _field_unit(cls, names[1:])
                if found is not None:
                    return found
    return None


def output_unit(path: str) -> str:
    """SI unit of an analysis output, read from the unit its result class declares
    (:func:`chaindrive._results.quantity`) along the path; ``""`` when unknown or a ratio.

    Examples
    --------
    >>> output_unit("contact.stress"), output_unit("vibration.tensioner.frequencies_rad_s.0")
    ('Pa', 'rad/s')
    """
    found = _declared(path)
    if found is not None:
        return "" if found[0] == "1" else found[0]
    parts = [p for p in path.split(".") if not p.lstrip("-").isdigit()]
    return _UNITS.get(parts[-1], "") if parts else ""


def output_display(path: str) -> tuple[float, str]:
    """(factor, unit) that show an output in its display unit (:mod:`chaindrive.workflows.display`).

    >>> output_display("contact.stress")
    (1e-06, 'MPa')
    """
    from ..display import convert

    found = _declared(path)
    unit, shown = found if found is not None else (output_unit(path), None)
    if not unit or unit == "1":
        return 1.0, unit if unit != "1" else ""
    factor, name = convert(1.0, unit, shown)
    return (1.0 if factor is None else factor), name
