"""The guided design of the studio page: form state -> design request -> chain -> layout -> Drive.

The form state is a flat dict of strings (exactly what the page's URL carries). Its duty
fields are parsed into SI units and mapped to a :class:`chaindrive.design.DesignRequest`
(:data:`REQUEST_FIELDS`); the design layer answers it (:func:`chaindrive.design.design_drive`:
service factor, design power, teeth, rating, layout), the page designs nothing itself. A
request's :class:`~chaindrive.errors.InputError` is shown at the form field its ``field``
names. Every bound of a field comes from :mod:`chaindrive.limits` or the project schema's
declaration (:mod:`chaindrive.drive.tables`). The drive is built in code from the project
mapping, the same one ``chaindrive new`` writes, so the studio, the command line and the
downloads describe one and the same drive. Errors are :class:`~chaindrive.web.fields.FieldError`
naming the form field.
"""

from __future__ import annotations

import dataclasses
import math
import warnings
from dataclasses import dataclass, field
from functools import lru_cache
from typing import Any

from ..analysis.loads import REQUIRED_STATIC_SAFETY, required_static_safety
from ..design import service_factor_table
from ..design.duty import check_duty_value, design_power, duty_class, service_factor_of
from ..design.link import link_candidates
from ..design.policy import BASE_TEETH, default_centre_distance, driven_teeth
from ..design.request import DesignRequest
from ..display import kn_per_m, kw, mm
from ..errors import ChainDriveError, InputError, ValidityRangeWarning
from ..limits import DUTY_RANGES, FORM_RANGES, MAX_TEETH, MIN_TEETH
from ..units import angular_velocity_to_rpm
from .fields import FieldError, FieldSpec, input_field, parse_field, parse_integer
from .wheels import EXTRA_CHOICES, EXTRA_DEFAULTS, add_extra_wheels, extra_wheels

__all__ = ["DEFAULTS", "FIELDS", "REQUEST_FIELDS", "Design", "service_factor_table", "normalise_state",
           "design_request", "design_from_state", "state_from_project", "MINING_EXAMPLE", "ROLLER_EXAMPLE"]


#: Every field of the studio form, its default text (roller-chain example).
DEFAULTS: dict[str, str] = {
    "name": "Chain drive",
    "units": "metric",
    "kind": "roller",
    "power": "7.5 kW",
    "speed": "1450 rpm",
    "ratio": "3",
    "driven_speed": "",
    "driver": "electric_motor",
    "driven": "uniform_conveyor",
    "load_character": "",   # empty: the driven machine's (the service-factor table)
    "service_factor": "",
    "hours_per_day": "8",
    "chain": "",
    "teeth_driving": "",
    "teeth_driven": "",
    "centre_distance": "500 mm",
    "tensioner": "",
    "idler_teeth": "17",
    "idler_position": "0.3",
    "idler_offset": "60 mm",
    "tensioner_mass": "2 kg",
    "tensioner_stiffness": "20 kN/m",
    "tensioner_force": "200 N",
    "tensioner_mechanism": "",
    **{f"tensioner_{k}": "" for k in ("arm_length", "arm_mass", "wheel_mass", "carriage_mass", "spring_stiffness",
                                      "spring_lever", "spring_angle")},
    "guide": "",
    "guide_end": "100 mm",
    "skew": "",
    "required_static_safety": "",
    "wear_coefficient": "",
    # a scraper conveyor's [conveyor] table as "key=value;..." (opened from a project file)
    "conveyor": "",
    **EXTRA_DEFAULTS,  # further wheels (chaindrive.web.wheels)
}

#: The mining scraper conveyor of Dolipiński et al. (DIN 22252 18x64 on 8-pocket wheels).
MINING_EXAMPLE: dict[str, str] = {
    **DEFAULTS,
    "name": "Mining scraper conveyor", "kind": "link", "power": "25 kW", "speed": "5 rad/s",
    "ratio": "1", "driven": "mining_scraper_conveyor", "hours_per_day": "16",
    "chain": "18x64", "teeth_driving": "8", "teeth_driven": "8", "centre_distance": "4.05 m",
    "tensioner": "on", "idler_teeth": "6", "idler_position": "0.3", "idler_offset": "400 mm",
    "tensioner_mass": "60 kg", "tensioner_stiffness": "200 kN/m", "tensioner_force": "5 kN",
    "guide": "tangential", "guide_end": "256 mm",
    "required_static_safety": f"{REQUIRED_STATIC_SAFETY['link']:g}",
    "wear_coefficient": "2e-16 m**2/N",
}

#: The acceptance example: 7.5 kW, 1450 rpm, ratio 3, about 500 mm, motor and conveyor.
ROLLER_EXAMPLE: dict[str, str] = dict(DEFAULTS)

CHOICES: dict[str, tuple[str, ...]] = {
    "units": ("metric", "imperial"),
    "kind": ("roller", "link"),
    "tensioner": ("", "on"),
    "tensioner_mechanism": ("", "lever", "sliding"),
    "guide": ("", "tangential", "chordal"),
    "load_character": ("", "smooth", "moderate", "heavy"),
    **EXTRA_CHOICES,
}

def _duty_field(name: str, example: str, unit: str | None = None) -> FieldSpec:
    """A duty field: its range from :data:`chaindrive.limits.DUTY_RANGES` (``unit``: the form's unit
    when it differs, e.g. hours as a bare number)."""
    low, high, si = DUTY_RANGES[name]
    return FieldSpec(si if unit is None else unit, low, high, example=example)


def _cap(name: str) -> float:
    """The form's upper bound of a drive field (:data:`chaindrive.limits.FORM_RANGES`)."""
    return FORM_RANGES[name][1]


#: Ranges of the numeric fields (SI unit, minimum, maximum, example): a duty field's from
#: :data:`chaindrive.limits.DUTY_RANGES`; a project-file input's unit and lower bound from
#: the input's declaration.
FIELDS: dict[str, FieldSpec] = {
    "power": input_field("load.power", maximum=DUTY_RANGES["power"][1], example="7.5 kW"),
    "speed": input_field("drive.speed", maximum=DUTY_RANGES["speed"][1], example="1450 rpm"),
    "ratio": _duty_field("ratio", "3"),
    "driven_speed": _duty_field("driven_speed", "480 rpm"),
    "service_factor": input_field("load.service_factor", maximum=DUTY_RANGES["service_factor"][1], example="1.3"),
    "hours_per_day": _duty_field("hours_per_day", "8", unit=""),
    "centre_distance": _duty_field("centre_distance", "500 mm"),
    "idler_position": FieldSpec("", *FORM_RANGES["idler_position"][:2], open_minimum=False, example="0.3"),
    "idler_offset": FieldSpec("m", *FORM_RANGES["idler_offset"][:2], open_minimum=False, example="60 mm"),
    "tensioner_mass": input_field("tensioner.mass", maximum=_cap("tensioner_mass"), example="2 kg"),
    "tensioner_stiffness": input_field("tensioner.stiffness", maximum=_cap("tensioner_stiffness"), example="20 kN/m"),
    "tensioner_force": input_field("tensioner.force", maximum=_cap("tensioner_force"), example="200 N"),
    # a tensioner described by its parts (chaindrive.drive.model.Tensioner.from_parts)
    "tensioner_arm_length": input_field("tensioner.arm_length", maximum=_cap("tensioner_arm_length"), example="400 mm"),
    "tensioner_arm_mass": input_field("tensioner.arm_mass", maximum=_cap("tensioner_arm_mass"), example="30 kg"),
    "tensioner_wheel_mass": input_field("tensioner.wheel_mass", maximum=_cap("tensioner_wheel_mass"), example="40 kg"),
    "tensioner_carriage_mass": input_field("tensioner.carriage_mass", maximum=_cap("tensioner_carriage_mass"), example="25 kg"),
    "tensioner_spring_stiffness": FieldSpec("N/m", *FORM_RANGES["tensioner_spring_stiffness"][:2], example="600 kN/m"),
    "tensioner_spring_lever": input_field("tensioner.spring_lever", maximum=_cap("tensioner_spring_lever"), example="250 mm"),
    "tensioner_spring_angle": input_field("tensioner.spring_angle", maximum=_cap("tensioner_spring_angle"), example="10 deg"),
    "guide_end": input_field("guides.end_distance", maximum=_cap("guide_end"), example="100 mm"),
    "skew": input_field("contact.skew", maximum=_cap("skew"), example="50 arcmin"),
    "required_static_safety": input_field("drive.required_static_safety", minimum=1.0,
                                          maximum=DUTY_RANGES["required_static_safety"][1], example="7"),
    "wear_coefficient": input_field("drive.wear_coefficient", maximum=_cap("wear_coefficient"), example="2e-16 m**2/N"),
}

#: Teeth of a wheel: the project schema's declaration (wheels.teeth, :mod:`chaindrive.limits`).
TEETH_RANGE = (MIN_TEETH, MAX_TEETH)

#: Form field -> field of the :class:`~chaindrive.design.DesignRequest` (the same name when not listed).
REQUEST_FIELDS = {"driven": "driven_machine"}
#: Field of a request's :class:`~chaindrive.errors.InputError` -> the form field that shows it.
FORM_FIELDS = {v: k for k, v in REQUEST_FIELDS.items()}


def normalise_state(params: dict[str, Any]) -> dict[str, str]:
    """The form state: every known field as a string (defaults for missing ones).

    Unknown keys are dropped; choice fields outside their choices fall back to the
    default (the page shows the choices only).

    Examples
    --------
    >>> normalise_state({"power": "10 kW", "evil": "x"})["power"]
    '10 kW'
    """
    base = dict(DEFAULTS)
    if params.get("kind") == "link" and "chain" not in params:
        base.update(MINING_EXAMPLE)
    out = {}
    for key, default in base.items():
        value = params.get(key, default)
        value = "" if value is None else str(value)[:200]
        out[key] = value
    table = service_factor_table()
    for key, choices in CHOICES.items():
        if out[key] not in choices:
            out[key] = DEFAULTS[key]
    if out["driver"] not in table["drivers"]:
        out["driver"] = DEFAULTS["driver"]
    if out["driven"] not in table["driven_machines"]:
        out["driven"] = DEFAULTS["driven"]
    return out


@dataclass
class Design:
    """The studio's design: duty, chosen chain, candidates, the project text and the Drive."""

    state: dict[str, str]
    power: float
    speed: float
    ratio: float
    service_factor: float
    service_factor_source: str
    load_character: str
    design_power: float
    hours_per_day: float
    teeth_driving: int
    teeth_driven: int
    chain: Any
    candidates: list = field(default_factory=list)
    candidate_note: str = ""
    project_text: str = ""
    drive: Any = None
    links: int | None = None
    centre_distance: float | None = None
    exact_centre_distance: float | None = None
    advice: tuple = ()


def _number(state: dict[str, str], name: str, errors: dict[str, str]) -> float | None:
    try:
        return parse_field(name, state[name], FIELDS[name])
    except FieldError as exc:
        errors[exc.field] = exc.message
        return None


def load_character_of(state: dict[str, str]) -> str:
    """The load character of the form: the one chosen, or the driven machine's (the name
    ``load_character`` of :class:`chaindrive.design.Duty` and ``select --load-character``;
    :func:`chaindrive.design.duty.duty_class`)."""
    return str(duty_class(state["driven"], state.get("load_character") or None))


def _put(errors: dict[str, str], exc: ChainDriveError) -> None:
    """A design-layer error at the form field its ``field`` names (:data:`FORM_FIELDS`)."""
    name = exc.field or "chain"
    name = FORM_FIELDS.get(name, name)
    errors[name] = str(exc).removeprefix(f"{name}: ")


def _duty(state: dict[str, str], errors: dict[str, str]) -> dict[str, Any]:
    """The duty fields of the form in SI units, named as the :class:`~chaindrive.design.DesignRequest`'s
    (``None``: a field error, in ``errors``), with the ``ratio`` of the drive and the service factor
    (:func:`chaindrive.design.duty.service_factor_of`)."""
    values: dict[str, Any] = {"power": _number(state, "power", errors), "speed": _number(state, "speed", errors)}
    if state["driven_speed"].strip():
        values["driven_speed"] = driven = _number(state, "driven_speed", errors)
        ratio = None
        if driven is not None and values["speed"] is not None:
            ratio = values["speed"] / driven
            try:
                check_duty_value("ratio", ratio)
            except InputError as exc:
                errors["driven_speed"] = f"gives a ratio n_driving / n_driven outside its range: {exc}"
                ratio = None
    else:
        values["ratio"] = ratio = _number(state, "ratio", errors)
    values.update(driver=state["driver"], driven_machine=state["driven"],
                  load_character=state["load_character"] or None,
                  service_factor=_number(state, "service_factor", errors) if state["service_factor"].strip() else None,
                  hours_per_day=_number(state, "hours_per_day", errors))
    factor = None
    if "service_factor" not in errors:
        try:
            factor = service_factor_of(state["driver"], driven_machine=state["driven"],
                                       load_character=values["load_character"], given=values["service_factor"])
        except InputError as exc:
            _put(errors, exc)
    return {"values": values, "ratio": ratio, "factor": factor}


def _teeth(state: dict[str, str], errors: dict[str, str], ratio: float | None,
           kind: str) -> tuple[int | None, int | None]:
    lo, hi = TEETH_RANGE
    z1 = z2 = None
    if kind == "roller" and not state["teeth_driving"].strip():
        return None, None  # the tooth-count policy of the design procedure decides
    try:
        z1 = parse_integer("teeth_driving", state["teeth_driving"], lo, hi)
    except FieldError as exc:
        errors[exc.field] = exc.message
    if state["teeth_driven"].strip():
        try:
            z2 = parse_integer("teeth_driven", state["teeth_driven"], lo, hi)
        except FieldError as exc:
            errors[exc.field] = exc.message
    elif z1 is not None and ratio is not None:
        z2 = _driven_teeth(z1, ratio, errors)
    return z1, z2


def _driven_teeth(z1: int, ratio: float, errors: dict[str, str]) -> int | None:
    """The driven wheel's teeth of the design policy (:func:`chaindrive.design.policy.driven_teeth`),
    refused outside the schema's range."""
    z2 = driven_teeth(z1, ratio)
    if not TEETH_RANGE[0] <= z2 <= TEETH_RANGE[1]:
        errors["teeth_driven"] = (f"ratio x teeth_driving gives {z2} teeth, outside "
                                  f"{TEETH_RANGE[0]} <= teeth_driven <= {TEETH_RANGE[1]}")
        return None
    return z2


#: Candidates the studio lists.
STUDIO_CANDIDATES = 8


def design_request(state: dict[str, str]) -> tuple[DesignRequest | None, dict[str, str]]:
    """The :class:`~chaindrive.design.DesignRequest` of a (normalised) roller form state and the field
    errors ``{form field: message}`` (a request's :class:`~chaindrive.errors.InputError` at the field
    its ``field`` names). The page asks the design layer exactly this.

    Examples
    --------
    >>> r, errors = design_request(normalise_state({"power": "11 kW", "driven": "varying_conveyor"}))
    >>> errors, r.duty.power, r.duty.character, r.limit
    ({}, 11000.0, 'moderate', 8)
    >>> design_request(normalise_state({"hours_per_day": "30"}))[1]
    {'hours_per_day': '30 is outside the valid range 0 < hours_per_day <= 24'}
    """
    errors: dict[str, str] = {}
    duty = _duty(state, errors)
    z1, _ = _teeth(state, errors, duty["ratio"], "roller")
    centre = _number(state, "centre_distance", errors) if state["centre_distance"].strip() else None
    required = (_number(state, "required_static_safety", errors) if state["required_static_safety"].strip()
                else None)
    if errors:
        return None, errors
    try:
        return _request(tuple(duty["values"].items()), z1, centre, required), errors
    except InputError as exc:
        _put(errors, exc)
        return None, errors


@lru_cache(maxsize=256)
def _request(values: tuple, teeth: int | None, centre: float | None, required: float | None) -> DesignRequest:
    return DesignRequest.of(**dict(values), teeth_driving=teeth, centre_distance=centre,
                            required_static_safety=required, limit=STUDIO_CANDIDATES)


@lru_cache(maxsize=128)
def _roller_design(request: DesignRequest) -> Any:
    """The design layer's answer for the form's request (cached by the request)."""
    from ..design import design_drive

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityRangeWarning)
        return design_drive(request)


def _candidate_rows(result: Any) -> list[dict]:
    return [{"chain": c.chain, "strands": c.strands, "pitch": c.pitch, "rated_power": c.rated_power,
             "design_power": c.design_power, "margin": c.power_margin, "static_safety": c.static_safety,
             "required_static_safety": c.required_static_safety, "dynamic_tension": c.dynamic_tension,
             "peak_tension": c.peak_tension, "peak_tension_limit": c.peak_tension_limit,
             "lubrication": c.lubrication, "governing_limit": c.limited_by, "notes": tuple(c.notes),
             "teeth_driving": c.driving_teeth, "teeth_driven": c.driven_teeth, "links": c.links,
             "centre_distance": c.centre_distance,
             "advice": tuple({"name": a.name, "note": a.note, "source": a.source} for a in c.advice)}
            for c in result.candidates]


#: The parts of each tensioner mechanism the studio offers (a subset of chaindrive.drive.model.TENSIONER_PARTS).
_TENSIONER_PARTS = {"lever": ("arm_length", "arm_mass", "wheel_mass", "spring_stiffness", "spring_lever",
                              "spring_angle"),
                    "sliding": ("carriage_mass", "wheel_mass", "spring_stiffness", "spring_angle")}


#: The header of the studio's project file.
_HEADER = ("chaindrive project file written by the web studio (TOML). Quantities carry units;\n"
           "a physical quantity without its unit is refused. Check it with:  chaindrive layout <file>")


def _project_data(d: Design, state: dict[str, str], positions: list, idler: tuple | None,
                  links: int | None) -> dict[str, Any]:
    """The project mapping of the design (the quantities as typed): the drive is built from it
    by :func:`chaindrive.drive.project.project_from_mapping`, its file written by
    :func:`chaindrive.drive.writer.mapping_text`."""
    kind_wheel = "pocket_wheel" if d.chain.is_link_chain else "sprocket"
    drive: dict[str, Any] = {
        "name": state["name"] or "Chain drive",
        "description": "driven machine: " + service_factor_table()["driven_machines"][state["driven"]][0],
        "speed": state["speed"].strip()}
    if links is not None:
        drive["links"] = int(links)
    if state["required_static_safety"].strip():
        drive["required_static_safety"] = state["required_static_safety"].strip()
    elif d.chain.is_link_chain:
        drive["required_static_safety"] = float(f"{required_static_safety(d.chain):g}")
    if state["wear_coefficient"].strip():
        drive["wear_coefficient"] = state["wear_coefficient"].strip()
    if d.chain.is_link_chain:
        drive["elongation_limit"] = 0.02
    data: dict[str, Any] = {"drive": drive, "chain": {"name": d.chain.name},
                            "load": {"power": state["power"].strip(),
                                     "service_factor": float(f"{d.service_factor:g}")}}
    names = ["driving", "driven"]
    teeth = [d.teeth_driving, d.teeth_driven]
    wheels = [(names[0], kind_wheel, teeth[0], positions[0], True)]
    if idler is not None:
        wheels.append(("tensioner", "idler", idler[0], idler[1], False))
    wheels.append((names[1], kind_wheel, teeth[1], positions[1], False))
    data["wheels"] = [{"name": name, "kind": kind, "teeth": int(z), "position": [f"{mm(x):.4f} mm", f"{mm(y):.4f} mm"],
                       **({"driving": True} if driving else {})} for name, kind, z, (x, y), driving in wheels]
    if idler is not None:
        mechanism = state["tensioner_mechanism"]
        tensioner: dict[str, Any] = {"wheel": "tensioner"}
        if mechanism:  # described by its parts: the project file reduces them to the axis
            tensioner["mechanism"] = mechanism
            tensioner.update({k: state["tensioner_" + k].strip() for k in _TENSIONER_PARTS[mechanism]
                              if state["tensioner_" + k].strip()})
        else:
            tensioner.update(mass=state["tensioner_mass"].strip(), stiffness=state["tensioner_stiffness"].strip())
        tensioner.update(kind="spring", direction=[0, -1], force=state["tensioner_force"].strip())
        data["tensioner"] = tensioner
    if state["guide"]:
        data["guides"] = [{"wheel": "driving", "kind": state["guide"], "end_distance": state["guide_end"].strip()}]
    if state["skew"].strip() and not d.chain.is_link_chain:
        data["contact"] = {"skew": state["skew"].strip(), "wear_factor": 0.65}
    if state.get("conveyor", "").strip():
        data["conveyor"] = _conveyor_table(state["conveyor"])
    return data


#: [conveyor] keys written as TOML numbers (dimensionless); the others are quantities or text.
_CONVEYOR_NUMBERS = ("chain_friction", "material_friction", "return_friction", "head_share", "efficiency")


def _conveyor_table(text: str) -> dict[str, Any]:
    """The ``[conveyor]`` table of the state's ``conveyor`` text ``key=value;...`` (the reader checks it)."""
    out: dict[str, Any] = {}
    for item in text.split(";"):
        key, _, value = item.partition("=")
        key, value = key.strip(), value.strip()
        if not key.isidentifier() or not value:
            continue
        if key in _CONVEYOR_NUMBERS:
            try:
                out[key] = float(value)
                continue
            except ValueError:
                pass
        out[key] = value
    return out


def conveyor_state(conveyor: Any) -> str:
    """A drive's :class:`~chaindrive.drive.Conveyor` as the state's ``key=value;...`` text (SI units)."""
    if conveyor is None:
        return ""
    units = {"material_load": "kg/m", "capacity": "kg/s", "inclination": "rad", "minimum_tension": "N"}
    parts = []
    for key, value in dataclasses.asdict(conveyor).items():
        if value is None:
            continue
        parts.append(f"{key}={value!r} {units[key]}" if key in units else f"{key}={value}")
    return ";".join(parts)


def design_from_state(state: dict[str, str]) -> tuple[Design | None, dict[str, str]]:
    """Build the design of a (normalised) form state.

    Returns
    -------
    (Design or None, dict)
        The design (``None`` when a field error stops it) and the field errors
        ``{field: message}``.

    Examples
    --------
    >>> d, errors = design_from_state(normalise_state({}))
    >>> errors, d.chain.name == d.candidates[0]["chain"], d.links % 2
    ({}, True, 0)
    """
    from ..chains import get

    errors: dict[str, str] = {}
    kind = state["kind"]
    duty = _duty(state, errors)
    values, ratio, factor = duty["values"], duty["ratio"], duty["factor"]
    power, speed, hours = values["power"], values["speed"], values["hours_per_day"]
    z1, z2 = _teeth(state, errors, ratio, kind)
    required = None
    if state["required_static_safety"].strip():
        required = _number(state, "required_static_safety", errors)
    # a roller drive may leave the centre distance blank: the design procedure's default, 40 pitches
    # of each chain (ISO 10823: 30-50), as `select` and the API
    default_centre = kind == "roller" and not state["centre_distance"].strip()
    centre = None if default_centre else _number(state, "centre_distance", errors)
    if (power is None or speed is None or ratio is None or factor is None or hours is None
            or (centre is None and not default_centre)
            or (kind == "link" and (z1 is None or z2 is None)) or errors):
        return None, errors
    candidates: list[dict] = []
    note = ""
    try:
        if kind == "roller":
            if ratio < 1:
                note = "the design procedure covers speed-reducing drives (ratio >= 1): give a chain"
            else:
                try:  # the form's duty and constraints as the design layer's request
                    request = _request(tuple(values.items()), z1, centre, required)
                except InputError as exc:
                    _put(errors, exc)
                    return None, errors
                result = _roller_design(request)
                candidates = _candidate_rows(result)
                note = " ".join(f"Near miss: {' / '.join(m.names)} on {m.driving_teeth} teeth carries "
                                f"{m.rating_ratio:.1%} of the design power; remedy: {m.remedy}."
                                for m in result.near_misses)
        else:
            assert z1 is not None
            candidates = link_candidates(power, speed, factor.value, z1, required)
    except ChainDriveError as exc:
        note = str(exc)
    chain_name = state["chain"].strip()
    if not chain_name:
        if not candidates:
            if "too large for the centre distance" in note and centre is not None:
                errors["centre_distance"] = f"{mm(centre):.1f} mm is too short: {note}"
            else:
                errors["chain"] = note or "no catalogue chain carries this duty; give a chain name"
            return None, errors
        chain_name = candidates[0]["chain"]
    chosen = next((c for c in candidates if c["chain"] == chain_name and "links" in c), None)
    if z1 is None:
        z1 = chosen["teeth_driving"] if chosen is not None else BASE_TEETH
    if z2 is None:
        z2 = (chosen["teeth_driven"] if chosen is not None and chosen["teeth_driving"] == z1
              else _driven_teeth(z1, ratio, errors))
        if z2 is None:
            return None, errors
    try:
        chain = get(chain_name)
    except ChainDriveError as exc:
        errors["chain"] = str(exc)
        return None, errors
    if centre is None:   # blank (roller): the procedure's centre distance for its chain, else 40 pitches
        centre = chosen["centre_distance"] if chosen is not None else default_centre_distance(chain.pitch)
    if kind == "link" and not chain.is_link_chain:
        errors["chain"] = f"{chain.name} is a roller chain; the link-chain design needs a DIN 22252 chain"
        return None, errors
    if kind == "roller" and chain.is_link_chain:
        errors["chain"] = f"{chain.name} is a round link chain; switch the chain type to link"
        return None, errors
    tensioner = state["tensioner"] == "on"
    idler = None
    if tensioner:
        pos = _number(state, "idler_position", errors)
        off = _number(state, "idler_offset", errors)
        mech = state["tensioner_mechanism"]
        reduced = ("tensioner_mass", "tensioner_stiffness") if not mech else tuple(
            "tensioner_" + k for k in _TENSIONER_PARTS[mech] if state["tensioner_" + k].strip())
        for name in (*reduced, "tensioner_force"):
            _number(state, name, errors)
        try:
            zi = parse_integer("idler_teeth", state["idler_teeth"], *TEETH_RANGE)
        except FieldError as exc:
            errors[exc.field] = exc.message
            zi = None
    if state["guide"]:
        _number(state, "guide_end", errors)
    if state["skew"].strip():
        _number(state, "skew", errors)
    if state["wear_coefficient"].strip():
        _number(state, "wear_coefficient", errors)
    extras = extra_wheels(state, errors, kind)
    if errors or centre is None:
        return None, errors
    d = Design(state=state, power=power, speed=speed, ratio=ratio, service_factor=factor.value,
               service_factor_source=factor.source, load_character=load_character_of(state),
               design_power=design_power(power, factor), hours_per_day=hours, teeth_driving=z1, teeth_driven=z2,
               chain=chain, candidates=candidates, candidate_note=note, centre_distance=centre)
    from ..drive.project import project_from_mapping
    from ..drive.writer import mapping_text

    # first pass: the centre distance as given -> links (even) -> exact centre distance
    r1 = _pitch_radius(chain, z1)
    r2 = _pitch_radius(chain, z2)
    if centre <= r1 + r2 + chain.pitch:
        errors["centre_distance"] = (f"{mm(centre):.1f} mm is too short: the wheels need more than "
                                     f"{mm(r1 + r2 + chain.pitch):.1f} mm (pitch radii plus a pitch)")
        return None, errors
    if tensioner and zi is not None and pos is not None and off is not None:  # field errors returned above
        idler = (zi, (pos * centre, -(min(r1, r2) + off)))
    positions = [(0.0, 0.0), (centre, 0.0)]
    try:
        wheel_kind = "pocket_wheel" if chain.is_link_chain else "sprocket"

        def project(links: int | None) -> dict[str, Any]:
            return add_extra_wheels(_project_data(d, state, positions, idler, links), extras,
                                    wheel_kind=wheel_kind, adjustable=idler is None)

        data = project(None)
        geometry = (chain.name, z1, z2, centre, idler, state["guide"], state["guide_end"], tuple(extras))
        if (chosen is not None and idler is None and not extras
                and (chosen["teeth_driving"], chosen["teeth_driven"]) == (z1, z2)):
            links, exact = chosen["links"], chosen["centre_distance"]  # the design procedure's layout
        else:
            links, exact = _links_and_centre(geometry, data, idler is None and not extras)
        if exact is not None:
            positions = [(0.0, 0.0), (exact, 0.0)]
        data = project(links)
        drive = project_from_mapping(data, filename="studio.toml")
        text = mapping_text(data, header=_HEADER)
    except ChainDriveError as exc:
        errors[_field_of(str(exc))] = str(exc).removeprefix("studio.toml: ")
        return None, errors
    d.project_text, d.drive, d.links, d.exact_centre_distance = text, drive, links, exact
    if chosen is not None:
        d.advice = chosen["advice"]
    return d, errors


_LINKS_CACHE: dict[tuple, tuple[int, float | None]] = {}


def _links_and_centre(geometry: tuple, data: dict[str, Any], exact: bool) -> tuple[int, float | None]:
    """Links (even) of the drive at the given positions and the centre distance that fits them.

    Cached by the geometry (chain, teeth, centre distance, idler): edits of the duty or the
    tensioner do not lay the drive out again.
    """
    from ..drive.project import project_from_mapping
    from .engine import layout_summary

    key = (geometry, exact)
    if key not in _LINKS_CACHE:
        lay = layout_summary(project_from_mapping(data, filename="studio.toml"))
        cd = lay["centre_distance_for_links"] if exact else None
        if len(_LINKS_CACHE) > 512:
            _LINKS_CACHE.clear()
        _LINKS_CACHE[key] = (lay["links"], None if cd is None else float(cd))
    return _LINKS_CACHE[key]


def _field_of(message: str) -> str:
    """The form field an engine message is about (the drawing area when unknown)."""
    for part in ("arm_length", "arm_mass", "wheel_mass", "carriage_mass", "spring_stiffness", "spring_lever",
                 "spring_angle"):
        if f"tensioner.{part}" in message or f"tensioner: {part}" in message:
            return "tensioner_" + part
    for key in ("tensioner", "guide", "skew", "teeth", "centre", "chain", "speed", "power"):
        if key in message:
            return {"tensioner": "tensioner_force", "guide": "guide_end", "teeth": "teeth_driving",
                    "centre": "centre_distance"}.get(key, key)
    return "centre_distance"


def _get(spec: Any, key: str) -> Any:
    """A field of a contact spec (a dict today, a dataclass after the model refactor)."""
    if spec is None:
        return None
    if isinstance(spec, dict):
        return spec.get(key)
    return getattr(spec, key, None)


def _pitch_radius(chain: Any, teeth: int) -> float:
    from ..layout import pitch_radius

    bar = chain.bar_diameter if chain.is_link_chain else None
    return float(pitch_radius(chain.pitch, teeth, bar))


def state_from_project(text: str, filename: str = "project.toml") -> dict[str, str]:
    """The form state of a project file (two wheels, optionally a tensioner idler between).

    Raises
    ------
    InputError
        The file is invalid (field and line named) or has a shape the studio does not
        draw (more wheels, a track wheel); the message says to use ``chaindrive analyze``.

    Examples
    --------
    >>> from chaindrive.drive.project import template
    >>> s = state_from_project(template("roller"))
    >>> s["chain"], s["teeth_driving"], s["teeth_driven"], s["centre_distance"]
    ('16B-1', '19', '57', '1050 mm')
    """
    from ..drive.project import parse_project

    drive = parse_project(text, filename=filename)
    main = [w for w in drive.wheels if w.kind != "idler"]
    idlers = [w for w in drive.wheels if w.kind == "idler"]
    if len(main) != 2 or len(idlers) > 1 or any(w.kind == "track_wheel" for w in main):
        raise InputError(
            f"{filename}: the studio edits drives with two sprockets or pocket wheels and at most one "
            f"tensioner idler; this one has {len(drive.wheels)} wheels "
            f"({', '.join(w.kind for w in drive.wheels)}): use `chaindrive analyze` or the expert pages")
    drv = next(w for w in main if w.driving)
    other = next(w for w in main if not w.driving)
    dx = other.position[0] - drv.position[0]
    dy = other.position[1] - drv.position[1]
    centre = math.hypot(dx, dy)
    state = dict(DEFAULTS)
    load = drive.load
    state.update({
        "name": drive.name,
        "kind": "link" if drive.chain.is_link_chain else "roller",
        "speed": f"{angular_velocity_to_rpm(drive.speed):.6g} rpm" if drive.speed > 20 else f"{drive.speed:.6g} rad/s",
        "driven_speed": "",
        "ratio": f"{(other.teeth or 1) / (drv.teeth or 1):.6g}",
        "chain": drive.chain.name,
        "teeth_driving": str(drv.teeth),
        "teeth_driven": str(other.teeth),
        "centre_distance": f"{mm(centre):.6g} mm",
        "service_factor": f"{load.service_factor:g}",
        "required_static_safety": "" if drive.required_static_safety is None else f"{drive.required_static_safety:g}",
        "wear_coefficient": "" if drive.wear_coefficient is None else f"{drive.wear_coefficient:g} m**2/N",
        "tensioner": "", "guide": "", "skew": "",
        "conveyor": conveyor_state(drive.conveyor),
    })
    if load.power is not None:
        state["power"] = f"{kw(load.power):.6g} kW"
    else:
        state["power"] = f"{kw(drive.power()):.6g} kW"
    if idlers and drive.tensioner is not None:
        w = idlers[0]
        t = drive.tensioner
        ux, uy = (dx / centre, dy / centre)
        rx, ry = w.position[0] - drv.position[0], w.position[1] - drv.position[1]
        along = (rx * ux + ry * uy) / centre
        across = abs(-rx * uy + ry * ux)
        r_small = min(float(drv.pitch_radius(drive.chain)), float(other.pitch_radius(drive.chain)))
        state.update({
            "tensioner": "on", "idler_teeth": str(w.teeth or 17),
            "idler_position": f"{min(max(along, 0.05), 0.95):.4g}",
            "idler_offset": f"{mm(max(across - r_small, 0.0)):.6g} mm",
            "tensioner_mass": f"{t.mass:g} kg", "tensioner_stiffness": f"{kn_per_m(t.stiffness):g} kN/m",
            "tensioner_force": f"{(t.force or 0.0):g} N",
        })
        if t.mechanism in _TENSIONER_PARTS:
            parts = dict(t.parts)
            state["tensioner_mechanism"] = t.mechanism
            for k in _TENSIONER_PARTS[t.mechanism]:
                if k in parts:
                    state["tensioner_" + k] = f"{parts[k]:g} {FIELDS['tensioner_' + k].unit}"
    elif idlers:
        raise InputError(f"{filename}: an idler without a [tensioner] table is not edited by the studio; "
                         "use `chaindrive analyze`")
    if drive.guides:
        g = drive.guides[0]
        if g.kind in ("tangential", "chordal"):
            state.update({"guide": g.kind, "guide_end": f"{mm(g.end_distance):.6g} mm"})
    skew, height, base = (_get(drive.contact, k) for k in ("skew", "skew_height_difference", "skew_base"))
    if skew is not None:
        state["skew"] = f"{math.degrees(skew) * 60:.6g} arcmin"
    elif height is not None and base:
        state["skew"] = f"{math.degrees(math.atan(height / base)) * 60:.6g} arcmin"
    return state
