"""TOML project files: a drive described once, with units, validated with line numbers.

A project file has the tables ``[drive]``, ``[chain]``, ``[load]``, an array
``[[wheels]]`` (in the order the chain passes them, counter-clockwise), and the
optional ``[tensioner]`` and ``[[guides]]``. Every physical quantity is written with its
unit (``"64 mm"``, ``"300 rpm"``, ``"15 kW"``); a bare number is refused for it (1450
could be rpm or rad/s), and stays for counts and ratios (teeth, service factor). The
driving wheel's ``speed`` may be the mean chain speed (``"1.2 m/s"``, how scraper
conveyors are specified). The
schema is checked with pydantic; every mistake is reported with its field and its line
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
from typing import Annotated, Any, Literal

import numpy as np
from pydantic import (
    BaseModel,
    BeforeValidator,
    ConfigDict,
    Field,
    ValidationError,
    ValidationInfo,
    field_validator,
)

from ..errors import ChainDriveError, InputError, UnknownNameError
from ..kinematics.speed import chain_speed_to_angular_velocity
from ..limits import MAX_LINKS, MAX_TEETH, warn_implausible
from ..loads import mean_chain_speed
from ..units import is_dimensional, parse_quantity, unit_example
from . import model as _model
from .clearance import clearance_error
from .model import Adjustable, Drive, Guide, Load, Tensioner, Wheel
from .templates import TEMPLATES, template  # the templates of `chaindrive new`

__all__ = ["Project", "load_project", "parse_project", "project_from_mapping", "line_index", "template", "TEMPLATES"]


# --------------------------------------------------------------------------- quantities


#: Plausibility check (chaindrive.limits.PLAUSIBLE) by target unit.
_PLAUSIBLE_KIND = {"rad/s": "angular_velocity", "W": "power", "N": "force"}


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


def _quantity(unit: str, *, positive: bool = True, allow_zero: bool = False, signed: bool = False,
              plausible: bool = True):
    def parse(value: Any, info: ValidationInfo) -> float:
        name = info.field_name or "value"
        x = _parse_quantity_field(value, unit, name, plausible)
        if not signed:
            if positive and not allow_zero and not x > 0:
                raise ValueError(f"{name} must be positive (0 < {name} < inf {unit}), got {x:g}")
            if allow_zero and not x >= 0:
                raise ValueError(f"{name} must be non-negative (0 <= {name} < inf {unit}), got {x:g}")
        if x != x or x in (float("inf"), float("-inf")):
            raise ValueError(f"{name} must be finite, got {x}")
        return x

    return BeforeValidator(parse)


Length = Annotated[float, _quantity("m")]
Coordinate = Annotated[float, _quantity("m", signed=True)]
Mass = Annotated[float, _quantity("kg")]
MassPerLength = Annotated[float, _quantity("kg/m")]
Force = Annotated[float, _quantity("N")]
ForceOrZero = Annotated[float, _quantity("N", allow_zero=True)]
Stiffness = Annotated[float, _quantity("N/m")]
Power = Annotated[float, _quantity("W")]
Torque = Annotated[float, _quantity("N*m")]
AngularVelocity = Annotated[float, _quantity("rad/s")]
WearCoefficient = Annotated[float, _quantity("m**2/N")]
Ratio = Annotated[float, _quantity("")]
Angle = Annotated[float, _quantity("rad", allow_zero=True)]
Stress = Annotated[float, _quantity("Pa")]


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
        try:
            v = parse_quantity(value, "m/s", field=name)
        except InputError:
            v = None
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


WheelSpeed = Annotated[float | ChainSpeedSpec, BeforeValidator(_wheel_speed)]


class _Model(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class ChainSpec(_Model):
    """``[chain]``: a catalogue name, optionally with fields overridden, or a custom chain."""

    name: str
    pitch: Length | None = None
    roller_diameter: Length | None = None
    bar_diameter: Length | None = None
    strands: int | None = Field(default=None, ge=1, le=4)
    inner_width: Length | None = None
    pin_diameter: Length | None = None
    plate_height: Length | None = None
    breaking_force: Force | None = None
    mass_per_length: MassPerLength | None = None
    source: str | None = None


class DriveSpec(_Model):
    """``[drive]``."""

    name: str = "chain drive"
    description: str = ""
    speed: WheelSpeed
    links: int | None = Field(default=None, gt=0, le=MAX_LINKS)
    slack_tension: Force | None = None
    slack_sag_ratio: Ratio = 0.02
    required_static_safety: Ratio | None = None
    elongation_limit: Ratio = 0.03
    wear_coefficient: WearCoefficient | None = None
    travel: Literal["ccw", "cw"] = "ccw"

    @field_validator("slack_sag_ratio")
    @classmethod
    def _sag(cls, v):
        if not 0 < v <= 0.2:
            raise ValueError(f"slack_sag_ratio must lie in (0, 0.2], got {v:g}")
        return v

    @field_validator("elongation_limit")
    @classmethod
    def _elong(cls, v):
        if not 0 < v <= 0.1:
            raise ValueError(f"elongation_limit must lie in (0, 0.1], got {v:g}")
        return v


class LoadSpec(_Model):
    """``[load]``: power or torque of the driving wheel, service factor."""

    power: Power | None = None
    torque: Torque | None = None
    service_factor: Ratio = 1.0

    @field_validator("service_factor")
    @classmethod
    def _sf(cls, v):
        if v < 1:
            raise ValueError(f"service_factor must be >= 1, got {v:g}")
        return v

    def model_post_init(self, _context: Any) -> None:
        if (self.power is None) == (self.torque is None):
            raise ValueError("give exactly one of power and torque")


class WheelSpec(_Model):
    """``[[wheels]]``."""

    name: str
    kind: Literal["sprocket", "pocket_wheel", "track_wheel", "idler"]
    teeth: int | None = Field(default=None, ge=3, le=MAX_TEETH)
    diameter: Length | None = None
    position: tuple[Coordinate, Coordinate]
    driving: bool = False
    side: Literal[1, -1] = 1
    power_share: float | None = Field(default=None, gt=0, le=1)


class AdjustableSpec(_Model):
    """``[adjustable]``: the wheel moved to fit the link count."""

    wheel: str
    direction: tuple[float, float] = (1.0, 0.0)


LengthOrZero = Annotated[float, _quantity("m", allow_zero=True)]
MassOrZero = Annotated[float, _quantity("kg", allow_zero=True)]
Inertia = Annotated[float, _quantity("kg*m**2", allow_zero=True)]
StiffnessOrZero = Annotated[float, _quantity("N/m", allow_zero=True)]
TorsionStiffness = Annotated[float, _quantity("N*m/rad", allow_zero=True)]


class TensionerSpec(_Model):
    """``[tensioner]``: mass and stiffness reduced to the axis, or the parts of a ``mechanism``."""

    wheel: str
    mass: Mass | None = None
    stiffness: Stiffness | None = None
    kind: Literal["spring", "weight", "screw", "hydraulic"] = "spring"
    direction: tuple[float, float] = (0.0, 1.0)
    force: ForceOrZero | None = None
    mechanism: Literal["lever", "sliding"] | None = None
    arm_length: Length | None = None
    arm_inertia: Inertia | None = None
    arm_mass: MassOrZero | None = None
    wheel_mass: MassOrZero | None = None
    carriage_mass: MassOrZero | None = None
    spring_stiffness: StiffnessOrZero | None = None
    spring_lever: LengthOrZero | None = None
    spring_angle: Angle | None = None
    spring_mass: MassOrZero | None = None
    torsion_stiffness: TorsionStiffness | None = None

    def model_post_init(self, _context: Any) -> None:
        parts = [k for k in _model.TENSIONER_PARTS["lever"] | _model.TENSIONER_PARTS["sliding"]
                 if getattr(self, k) is not None]
        if self.mechanism is None:
            if self.mass is None or self.stiffness is None:
                raise ValueError("give mass and stiffness (reduced to the tensioner axis), or mechanism = "
                                 '"lever" or "sliding" with its parts (see docs/vibration.md §5)')
            if parts:
                raise ValueError(f"{', '.join(parts)}: parts need mechanism = \"lever\" or \"sliding\"")
        elif self.mass is not None or self.stiffness is not None:
            raise ValueError(f"mechanism = {self.mechanism!r} computes mass and stiffness from the parts; "
                             "give one or the other")
        else:
            foreign = [k for k in parts if k not in _model.TENSIONER_PARTS[self.mechanism]]
            if foreign:
                raise ValueError(f"{', '.join(foreign)}: not a part of a {self.mechanism} tensioner (parts: "
                                 f"{', '.join(_model.TENSIONER_PARTS[self.mechanism])})")

    def to_tensioner(self) -> Tensioner:
        """The model's tensioner (its parts reduced to the axis when a mechanism is given)."""
        if self.mechanism is None:
            assert self.mass is not None and self.stiffness is not None
            return Tensioner(self.wheel, self.mass, self.stiffness, kind=self.kind, direction=self.direction,
                             force=self.force)
        parts = {k: getattr(self, k) for k in _model.TENSIONER_PARTS[self.mechanism] if getattr(self, k) is not None}
        return Tensioner.from_parts(self.wheel, self.mechanism, parts, kind=self.kind, direction=self.direction,
                                    force=self.force)


class GuideSpec(_Model):
    """``[[guides]]``."""

    wheel: str
    end_distance: Length
    kind: Literal["tangential", "chordal", "guided"] = "tangential"
    height: Annotated[float, _quantity("m", allow_zero=True)] | None = None


class ContactSpec(_Model):
    """``[contact]``: roller–tooth contact with skew (Garshniev & Maksymovych), roller chains."""

    skew: Angle | None = None
    skew_height_difference: Annotated[float, _quantity("m", allow_zero=True)] | None = None
    skew_base: Length | None = None
    wear_factor: Ratio = 0.65
    seat_radius: Length | None = None
    contact_length: Length | None = None

    def model_post_init(self, _context: Any) -> None:
        if self.skew is None and (self.skew_height_difference is None or self.skew_base is None):
            raise ValueError("give skew, or both skew_height_difference and skew_base")
        if self.skew is not None and self.skew_height_difference is not None:
            raise ValueError("give skew or the measurement (skew_height_difference, skew_base), not both")


class RimBoltsSpec(_Model):
    """``[track.bolts]``: the bolts of a toothed rim (Sharipov, Fig. 14)."""

    count: int = Field(ge=1, le=1000)
    circle_radius: Length
    diameter: Length
    joint: Literal["fitted", "friction"] = "fitted"
    shear_planes: int = Field(default=1, ge=1, le=10)
    plate_thickness: Length | None = None
    allowable_shear: Stress | None = None
    allowable_bearing: Stress | None = None
    friction: Ratio = 0.15
    friction_faces: int = Field(default=1, ge=1, le=10)
    slip_safety: Ratio = 1.25
    thread_pitch: Length | None = None
    yield_strength: Stress | None = None


class CrawlerSpec(_Model):
    """``[crawler]``: the conveyor crawler drive (cams on the drive chain, guide, stiffness)."""

    stiffness: Annotated[float, _quantity("N", plausible=False)]  # axial rigidity EA, not a force
    guide: Literal["tangent", "none"] = "tangent"
    cam_distance: Length | None = None
    engagement_distance: Length | None = None
    cam_pitch: Length | None = None
    cam_index: int = Field(default=0, ge=0, le=10_000)
    cam_face_angle: Angle = 0.0
    return_guide: Literal["tangent", "none"] = "none"


class FrettingSpec(_Model):
    """``[fretting]``: empirical constants of the fretting latent period (Vikulov)."""

    roughness: Length
    latent_coefficient: Annotated[float, _quantity("s/m")]
    decay_coefficient: Annotated[float, _quantity("s/N")]
    frequency: Annotated[float, _quantity("Hz")] | None = None


class TrackSpec(_Model):
    """``[track]``: tracked-tractor drive wheel strength (Sharipov)."""

    tractor_weight: Force
    adhesion: Ratio = 1.0
    rims: Literal[1, 2] = 1
    tooth_width: Length
    pin_radius: Length
    link: Literal["built-up", "cast"] = "cast"
    hardness: float | None = Field(default=None, gt=0, le=70)
    allowable_bending: Stress | None = None
    allowable_contact: Stress | None = None
    bolts: RimBoltsSpec | None = None


class ConveyorSpec(_Model):
    """``[conveyor]``: scraper conveyor pans, material and drives (:class:`chaindrive.drive.Conveyor`)."""

    chain_friction: float = Field(default=0.4, ge=0, le=1.5)
    material_friction: float = Field(default=0.6, ge=0, le=1.5)
    material_load: Annotated[float, _quantity("kg/m", allow_zero=True)] | None = None
    capacity: Annotated[float, _quantity("kg/s", allow_zero=True)] | None = None
    inclination: Annotated[float, _quantity("rad", signed=True)] = 0.0
    return_strand: Literal["supported", "free"] = "supported"
    return_friction: float | None = Field(default=None, ge=0, le=1.5)
    head_share: float = Field(default=1.0, gt=0, le=1)
    minimum_tension: ForceOrZero = 2000.0
    efficiency: float = Field(default=1.0, gt=0, le=1)


class Project(_Model):
    """The whole project file."""

    drive: DriveSpec
    chain: ChainSpec
    load: LoadSpec
    wheels: list[WheelSpec] = Field(min_length=2)
    tensioner: TensionerSpec | None = None
    adjustable: AdjustableSpec | None = None
    guides: list[GuideSpec] = []
    contact: ContactSpec | None = None
    track: TrackSpec | None = None
    self_regulating: dict[str, Any] | None = None
    crawler: CrawlerSpec | None = None
    fretting: FrettingSpec | None = None
    conveyor: ConveyorSpec | None = None


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
        lines.append(f"{_where(filename, _line_for(loc, index))}: {_path(loc)}: {msg}")
    from .._io import cap_lines

    return "\n".join(cap_lines(list(dict.fromkeys(lines)), 20))


# --------------------------------------------------------------------------- loading


def _chain(spec: ChainSpec, index, filename):
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
    try:
        proj = Project.model_validate(data)
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
            tensioner=None if proj.tensioner is None else proj.tensioner.to_tensioner(),
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

    for key in ("pivot", "weight", "weight_offset", "stiffness", "preload"):
        values = table.get(key)
        for v in values if isinstance(values, (list, tuple)) else [values]:
            if isinstance(v, (int, float)) and not isinstance(v, bool) and v != 0:
                raise InputError(f"{_where(filename, _line_for(('self_regulating', key), index))}: "
                                 f"self_regulating.{key}: give a unit, e.g. {key} = \"{v} mm\" or \"{v} N\" "
                                 "as the field needs (see docs/self_regulating.md)", field=f"self_regulating.{key}")

    try:
        return SelfRegulatingSpec.from_table(table)
    except ChainDriveError as exc:
        raise _located(exc, ("self_regulating",), filename, index) from None


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
    """``exc`` with ``filename:line`` of ``loc`` in front of its message."""
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
