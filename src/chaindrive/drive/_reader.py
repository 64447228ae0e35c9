"""The TOML reader's validation, generated from the input tables' declarations
(:mod:`chaindrive.drive.schema`): one pydantic model per table, its quantity fields parsed
with their units and checked against their bounds, messages naming the field.

Examples
--------
>>> from chaindrive.drive.schema import Input, InputTable
>>> t = InputTable("demo", (Input("gap", "quantity", unit="m", default=0.001, minimum=0.0),))
>>> reader_model(t).model_validate({"gap": "2 mm"}).gap
0.002
"""

from __future__ import annotations

import functools
from typing import Annotated, Any, Literal

from pydantic import BaseModel, BeforeValidator, ConfigDict, Field, ValidationInfo, create_model

from ..errors import InputError
from ..limits import warn_implausible
from ..units import is_dimensional, parse_quantity, parse_speed_text, unit_example
from .schema import Input, InputTable, all_tables, children

__all__ = ["reader_model", "project_model", "ChainSpeedSpec"]


def _parse_quantity_field(value: Any, unit: str, name: str, plausible: bool = True) -> float:
    """A project-file quantity in ``unit``: a string with its unit; a bare number only when
    ``unit`` is dimensionless (a TOML number for a length or a speed is refused)."""
    if isinstance(value, bool):
        raise ValueError(f"expected a quantity in {unit or 'dimensionless'}, got {value!r}")
    if isinstance(value, (int, float)) and is_dimensional(unit):
        number = repr(value)
        raise ValueError(f"give a unit, e.g. {name} = {unit_example(number, unit)} "
                         f"(a bare number {number} could be read in any unit)")
    try:
        x = parse_quantity(value, unit or "dimensionless", field=name)
    except InputError as exc:
        raise ValueError(str(exc).removeprefix(f"{name}: ")) from None
    kind = "pitch" if unit == "m" and name == "pitch" else _PLAUSIBLE_KIND.get(unit)
    if kind is not None and plausible:
        warn_implausible(name, x, kind, stacklevel=2)
    return x


#: Plausibility check (chaindrive.limits.PLAUSIBLE) by target unit.
_PLAUSIBLE_KIND = {"rad/s": "angular_velocity", "W": "power", "N": "force"}


def _bounded(f: Input, name: str, x: float) -> None:
    """The range check of a quantity (:meth:`Input.bound_error`)."""
    message = f.bound_error(name, x)
    if message:
        raise ValueError(message)


def _quantity(f: Input) -> BeforeValidator:
    def parse(value: Any, info: ValidationInfo) -> float:
        name = info.field_name or f.name
        x = _parse_quantity_field(value, f.unit, name, f.plausible)
        _bounded(f, name, x)
        return x

    return BeforeValidator(parse)


class ChainSpeedSpec(BaseModel):
    """``speed = "1.2 m/s"``: the mean chain speed, converted with the driving wheel."""

    model_config = ConfigDict(extra="forbid", frozen=True)
    chain_speed: float


def _wheel_speed(value: Any, info: ValidationInfo) -> float | ChainSpeedSpec:
    """``speed``: angular speed of the driving wheel (``"960 rpm"``) or chain speed (``"1.2 m/s"``)."""
    name = info.field_name or "speed"
    if isinstance(value, ChainSpeedSpec):
        return value
    if isinstance(value, str):
        v = parse_speed_text(value, field=name)
        if v is not None:
            if not (v > 0):
                raise ValueError(f"{name} must be positive (0 < chain speed < inf m/s), got {v:g} m/s")
            warn_implausible(f"{name} (chain speed)", v, "chain_speed", stacklevel=2)
            return ChainSpeedSpec(chain_speed=v)
    try:
        x = _parse_quantity_field(value, "rad/s", name)
    except ValueError as exc:
        raise ValueError(f"{exc}; or the mean chain speed, e.g. {name} = \"1.2 m/s\"") from None
    if not x > 0:
        raise ValueError(f"{name} must be positive (0 < {name} < inf rad/s), got {x:g}")
    return x


def _native_bounds(f: Input) -> dict[str, Any]:
    out: dict[str, Any] = {}
    if f.minimum is not None:
        out["gt" if f.open_minimum else "ge"] = f.minimum
    if f.maximum is not None:
        out["lt" if f.open_maximum else "le"] = f.maximum
    return out


def _annotation(f: Input) -> Any:
    if f.kind == "quantity":
        return Annotated[float, _quantity(f)]
    if f.kind == "number":
        return Annotated[float, Field(**_native_bounds(f))]
    if f.kind == "integer":
        return Annotated[int, Field(**_native_bounds(f))]
    if f.kind == "text":
        return str
    if f.kind == "choice":
        return Literal[f.choices]
    if f.kind == "flag":
        return bool
    if f.kind == "pair":
        if not f.unit:
            return tuple[float, float]
        one = Input(f.name, "quantity", unit=f.unit, plausible=f.plausible)  # a coordinate: any sign
        return tuple[Annotated[float, _quantity(one)], Annotated[float, _quantity(one)]]
    if f.kind == "speed":
        return Annotated[float | ChainSpeedSpec, BeforeValidator(_wheel_speed)]
    return dict[str, Any]


class _Model(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


def _definition(f: Input) -> tuple[Any, Any]:
    ann = _annotation(f)
    if f.required:
        return ann, ...
    return (ann if f.default is not None else ann | None), f.default


def reader_model(table: InputTable) -> type[BaseModel]:
    """The pydantic model of ``table`` (its nested tables, e.g. ``track.bolts``, as fields)."""
    return _reader_model(table, children(table))


@functools.cache
def _reader_model(table: InputTable, nested: tuple[InputTable, ...]) -> type[BaseModel]:
    check = table.check

    def post_init(self: Any, _context: Any) -> None:
        if check is not None:
            check(self)

    base = type(f"_{_class_name(table)}Base", (_Model,), {"model_post_init": post_init, "__module__": __name__})
    defs: dict[str, Any] = {f.name: _definition(f) for f in table.fields}
    for child in nested:
        defs[child.name.rsplit(".", 1)[1]] = (reader_model(child) | None, None)
    model: type[BaseModel] = create_model(_class_name(table), __base__=base, __doc__=f"``[{table.name}]``: {table.help}", **defs)
    return model


def _class_name(table: InputTable) -> str:
    return "".join(p.capitalize() for p in table.name.replace(".", "_").split("_")) + "Spec"


@functools.lru_cache(maxsize=8)
def _project_model(tables: tuple[InputTable, ...]) -> type[BaseModel]:
    defs: dict[str, Any] = {}
    for t in tables:
        if "." in t.name:
            continue
        if t.extra.get("mapping"):
            defs[t.name] = (dict[str, Any] | None, None)
            continue
        model = reader_model(t)
        if t.array:
            defs[t.name] = (list[model], Field(min_length=t.min_items) if t.min_items else [])  # type: ignore[valid-type]
        else:
            defs[t.name] = (model, ...) if t.required else (model | None, None)
    return create_model("Project", __base__=_Model, __doc__="The whole project file.", **defs)


def project_model() -> type[BaseModel]:
    """The pydantic model of a whole project file (every declared top-level table)."""
    return _project_model(all_tables())
