"""The input tables of the drive description, declared once (:mod:`chaindrive.drive.schema`).

The reader (:mod:`chaindrive.drive.project`), the writer (:mod:`chaindrive.drive.writer`)
and the docs table of docs/drive.md are generated from these declarations.

Examples
--------
>>> from chaindrive.drive.schema import get_table
>>> f = get_table("drive").field("slack_sag_ratio")
>>> f.default, f.range_text()
(0.02, '(0, 0.2]')
"""

from __future__ import annotations

import functools
from typing import Any

from ..limits import MAX_LINKS, MAX_TEETH, MIN_TEETH
from .model import GUIDE_KINDS, TENSIONER_KINDS, TENSIONER_PARTS, WHEEL_KINDS
from .schema import REQUIRED, Input, InputTable, all_tables, register_table
from .specs import RETURN_STRANDS

__all__ = ["table_objects", "table_values", "warn_implausible_inputs", "is_further", "further_inputs"]


def _q(name: str, unit: str, default: Any = None, help: str = "", **kw: Any) -> Input:
    """A quantity, positive unless bounds are given."""
    kw.setdefault("minimum", 0.0)
    kw.setdefault("open_minimum", kw["minimum"] == 0.0 and "open_minimum" not in kw)
    return Input(name, "quantity", unit=unit, default=default, help=help, **kw)


def _q0(name: str, unit: str, default: Any = None, help: str = "", **kw: Any) -> Input:
    """A quantity >= 0."""
    return Input(name, "quantity", unit=unit, default=default, help=help, minimum=0.0, **kw)


register_table(InputTable("drive", (
    Input("name", "text", default="chain drive", help="title of the drive", shown=True),
    Input("description", "text", default="", help="what the drive is for"),
    Input("speed", "speed", default=REQUIRED,
          help='angular speed of the driving wheel ("960 rpm"), or the mean chain speed ("1.2 m/s")'),
    Input("links", "integer", minimum=0, open_minimum=True, maximum=MAX_LINKS,
          help="chain length in pitches (default: the required length, rounded up to even)"),
    _q("slack_tension", "N", help="tension of the slack span (default: from the sag)"),
    _q("slack_sag_ratio", "", 0.02, minimum=0.0, open_minimum=True, maximum=0.2,
       help="sag of the slack span over its length", source="ISO 10823 (about 2 %)"),
    _q("required_static_safety", "", help="static safety wanted, F_B / (K_s F_t + S_slack + q v²)",
       source="default: Chernavsky et al., Table 7.19 (pitch, speed)"),
    _q("elongation_limit", "", 0.03, minimum=0.0, open_minimum=True, maximum=0.1,
       help="wear elongation at which the chain is replaced"),
    _q("wear_coefficient", "m**2/N", help="Archard wear coefficient of the joints"),
    Input("travel", "choice", default="ccw", choices=("ccw", "cw"),
          help="the chain runs along the wheel list (ccw) or against it (cw)"),
), help="the drive: name, speed, chain length, slack span", required=True, order=0))

register_table(InputTable("chain", (
    Input("name", "text", default=REQUIRED, help="catalogue name (`chaindrive chains`) or a custom chain's name"),
    _q("pitch", "m", help="pitch p"),
    _q("roller_diameter", "m", help="roller diameter d1 (roller chains)"),
    _q("bar_diameter", "m", help="bar diameter d (round-link chains)"),
    Input("strands", "integer", minimum=1, maximum=4, help="strands of a roller chain"),
    _q("inner_width", "m", help="inner width b1"),
    _q("pin_diameter", "m", help="pin diameter d2"),
    _q("plate_height", "m", help="inner plate height h2"),
    _q("breaking_force", "N", help="minimum tensile strength F_B"),
    _q("mass_per_length", "kg/m", help="mass per metre q"),
    Input("source", "text", help="where a custom chain's data come from"),
), help="the chain: a catalogue name, fields overridden, or a custom chain", required=True, order=1))

register_table(InputTable("load", (
    _q("power", "W", help="power of the driving wheel"),
    _q("torque", "N*m", help="torque of the driving wheel"),
    _q("service_factor", "", 1.0, minimum=1.0, open_minimum=False, help="service factor K_s", shown=True,
       source="ANSI/ACA service factors"),
), help="power or torque of the driving wheel, service factor", required=True, order=2,
    check=lambda m: _one_of(m, "power", "torque")))


def _one_of(m: Any, a: str, b: str) -> None:
    if (getattr(m, a) is None) == (getattr(m, b) is None):
        raise ValueError(f"give exactly one of {a} and {b}")


register_table(InputTable("wheels", (
    Input("name", "text", default=REQUIRED, help="name of the wheel"),
    Input("kind", "choice", default=REQUIRED, choices=WHEEL_KINDS, help="what the wheel is"),
    Input("teeth", "integer", minimum=MIN_TEETH, maximum=MAX_TEETH, help="teeth (pockets of a pocket wheel)"),
    _q("diameter", "m", help="diameter of a wheel without teeth"),
    Input("position", "pair", unit="m", default=REQUIRED, help="centre (x, y)"),
    Input("driving", "flag", default=False, help="the driving wheel (exactly one)"),
    Input("side", "choice", default=1, choices=(1, -1), help="-1: an idler on the outside of the chain"),
    Input("power_share", "number", minimum=0.0, open_minimum=True, maximum=1.0,
          help="share of the power taken off by a driven wheel (the shares sum to 1)"),
), help="the wheels in the order the chain passes them", array=True, required=True, min_items=2, order=3))

register_table(InputTable("adjustable", (
    Input("wheel", "text", default=REQUIRED, help="the wheel moved to fit the link count"),
    Input("direction", "pair", default=(1.0, 0.0), help="direction it moves in (x, y)"),
), help="the wheel moved to fit the link count", order=4))


def _tensioner_check(m: Any) -> None:
    parts = [k for k in TENSIONER_PARTS["lever"] | TENSIONER_PARTS["sliding"] if getattr(m, k) is not None]
    if m.mechanism is None:
        if m.mass is None or m.stiffness is None:
            raise ValueError("give mass and stiffness (reduced to the tensioner axis), or mechanism = "
                             '"lever" or "sliding" with its parts (see docs/vibration.md §5)')
        if parts:
            raise ValueError(f"{', '.join(parts)}: parts need mechanism = \"lever\" or \"sliding\"")
    elif m.mass is not None or m.stiffness is not None:
        raise ValueError(f"mechanism = {m.mechanism!r} computes mass and stiffness from the parts; "
                         "give one or the other")
    else:
        foreign = [k for k in parts if k not in TENSIONER_PARTS[m.mechanism]]
        if foreign:
            raise ValueError(f"{', '.join(foreign)}: not a part of a {m.mechanism} tensioner (parts: "
                             f"{', '.join(TENSIONER_PARTS[m.mechanism])})")


_PART_HELP = {"arm_length": "lever arm from the pivot to the wheel", "arm_inertia": "lever's inertia about the pivot",
              "arm_mass": "lever's mass", "wheel_mass": "tensioning wheel's mass", "carriage_mass": "carriage's mass",
              "spring_stiffness": "spring stiffness", "spring_lever": "spring's arm about the pivot",
              "spring_angle": "spring's angle to the tensioner axis", "spring_mass": "spring's mass",
              "torsion_stiffness": "torsion spring at the pivot"}
_PART_UNITS = {**TENSIONER_PARTS["lever"], **TENSIONER_PARTS["sliding"]}

register_table(InputTable("tensioner", (
    Input("wheel", "text", default=REQUIRED, help="the tensioning wheel"),
    _q("mass", "kg", help="mass reduced to the tensioner axis"),
    _q("stiffness", "N/m", help="stiffness reduced to the tensioner axis"),
    Input("kind", "choice", default="spring", choices=TENSIONER_KINDS, help="how the tension is held"),
    Input("direction", "pair", default=(0.0, 1.0), help="the tensioner axis (x, y)"),
    _q0("force", "N", help="tensioning force"),
    Input("mechanism", "choice", choices=("lever", "sliding"), help="described by its parts instead"),
    *(_q("arm_length", u, help=_PART_HELP[k]) if k == "arm_length" else
      _q0(k, u, help=_PART_HELP[k]) for k, u in _PART_UNITS.items()),
), help="mass and stiffness reduced to the axis, or the parts of a mechanism",
    source="docs/vibration.md §5", check=_tensioner_check, order=5))

register_table(InputTable("guides", (
    Input("wheel", "text", default=REQUIRED, help="the wheel the guide leads to"),
    Input("kind", "choice", default="tangential", choices=GUIDE_KINDS, help="how it guides the chain",
          shown=True),
    _q("end_distance", "m", default=REQUIRED, help="distance of the guide's end from the wheel"),
    _q0("height", "m", help="height of the guide"),
), help="chain guides at wheel entries", array=True, order=6))


def _contact_check(m: Any) -> None:
    if m.skew is None and (m.skew_height_difference is None or m.skew_base is None):
        raise ValueError("give skew, or both skew_height_difference and skew_base")
    if m.skew is not None and m.skew_height_difference is not None:
        raise ValueError("give skew or the measurement (skew_height_difference, skew_base), not both")


register_table(InputTable("contact", (
    _q0("skew", "rad", help="largest measured skew φ_p,max"),
    _q0("skew_height_difference", "m", help="measured height difference Δh (φ = atan(Δh/B))"),
    _q("skew_base", "m", help="measurement base B"),
    _q("wear_factor", "", 0.65, help="K_φ (0.6…0.7)"),
    _q("seat_radius", "m", help="tooth seat radius (default ISO 606)"),
    _q("contact_length", "m", help="contact length (default from the chain)"),
), help="roller–tooth contact with skew (roller chains)", source="Garshniev & Maksymovych",
    check=_contact_check, order=7))

register_table(InputTable("track", (
    _q("tractor_weight", "N", default=REQUIRED, help="tractor weight G_T"),
    _q("adhesion", "", 1.0, help="adhesion coefficient φ"),
    Input("rims", "choice", default=1, choices=(1, 2), help="toothed rims i"),
    _q("tooth_width", "m", default=REQUIRED, help="tooth width"),
    _q("pin_radius", "m", default=REQUIRED, help="track pin radius r_ц"),
    Input("link", "choice", default="cast", choices=("built-up", "cast"), help="track link"),
    Input("hardness", "number", minimum=0.0, open_minimum=True, maximum=70.0, help="surface hardness [HRC]"),
    _q("allowable_bending", "Pa", help="allowable bending stress"),
    _q("allowable_contact", "Pa", help="allowable contact stress"),
), help="tracked-tractor drive wheel strength", source="Sharipov, p. 34", order=8))

register_table(InputTable("track.bolts", (
    Input("count", "integer", default=REQUIRED, minimum=1, maximum=1000, help="bolts per rim n"),
    _q("circle_radius", "m", default=REQUIRED, help="bolt circle radius R_b"),
    _q("diameter", "m", default=REQUIRED, help="shank (fitted) or thread (friction) diameter"),
    Input("joint", "choice", default="fitted", choices=("fitted", "friction"), help="fitted bolts or friction joint"),
    Input("shear_planes", "integer", default=1, minimum=1, maximum=10, help="shear planes m (fitted)"),
    _q("plate_thickness", "m", help="thinnest clamped part (bearing check)"),
    _q("allowable_shear", "Pa", help="allowable shear (fitted)"),
    _q("allowable_bearing", "Pa", help="allowable bearing (fitted)"),
    _q("friction", "", 0.15, help="friction coefficient μ (friction joint)"),
    Input("friction_faces", "integer", default=1, minimum=1, maximum=10, help="friction interfaces q"),
    _q("slip_safety", "", 1.25, help="slip safety S (friction joint)"),
    _q("thread_pitch", "m", help="thread pitch (stress area)"),
    _q("yield_strength", "Pa", help="yield strength R_p0.2 (friction joint)"),
), help="the bolts of a toothed rim", source="Sharipov, Fig. 14", order=8.5))

register_table(InputTable("self_regulating", (),
                          help="self-regulating drive (see docs/self_regulating.md)", order=13,
                          extra={"mapping": True}))

register_table(InputTable("crawler", (
    _q("stiffness", "N", default=REQUIRED, plausible=False, help="axial rigidity EA of the drive chain"),
    Input("guide", "choice", default="tangent", choices=("tangent", "none"), help="guide of the chain axis"),
    _q("cam_distance", "m", help="distance l of the engaged cam's hinge from the tensioning sprocket"),
    _q("engagement_distance", "m", help="l1 of l = l1 + k t_K"),
    _q("cam_pitch", "m", help="t_K of l = l1 + k t_K"),
    Input("cam_index", "integer", default=0, minimum=0, maximum=10_000, help="k of l = l1 + k t_K"),
    _q0("cam_face_angle", "rad", 0.0, help="pressure angle α of the cam's face"),
    Input("return_guide", "choice", default="none", choices=("tangent", "none"), help="guide of the return span"),
), help="the conveyor crawler drive", order=10))

register_table(InputTable("fretting", (
    _q("roughness", "m", default=REQUIRED, help="Ra of the pin and bushing surfaces"),
    _q("latent_coefficient", "s/m", default=REQUIRED, help="K1 of τ = K1 Ra exp(−k2 A N f / Ra)"),
    _q("decay_coefficient", "s/N", default=REQUIRED, help="k2 = −K2 > 0"),
    _q("frequency", "Hz", help="load frequency (default: tooth frequency of the driving wheel)"),
), help="fretting of multi-strand roller chains", source="Vikulov", order=11))

register_table(InputTable("conveyor", (
    Input("chain_friction", "number", default=0.4, minimum=0.0, maximum=1.5, help="μ of the chain on the pans"),
    Input("material_friction", "number", default=0.6, minimum=0.0, maximum=1.5, help="μ_m of the material"),
    _q0("material_load", "kg/m", help="material per metre q_m (or capacity)"),
    _q0("capacity", "kg/s", help="mass flow Q (q_m = Q / v)"),
    Input("inclination", "quantity", unit="rad", default=0.0, help="inclination, positive uphill"),
    Input("return_strand", "choice", default="supported", choices=RETURN_STRANDS, help="on the pans or free"),
    Input("return_friction", "number", minimum=0.0, maximum=1.5, help="μ of the return strand"),
    Input("head_share", "number", default=1.0, minimum=0.0, open_minimum=True, maximum=1.0,
          help="share of the drive force at the head"),
    _q0("minimum_tension", "N", 2000.0, help="smallest tension at every sprocket exit"),
    Input("efficiency", "number", default=1.0, minimum=0.0, open_minimum=True, maximum=1.0,
          help="efficiency of each drive"),
), help="scraper conveyor pans, material and drives", order=12))


# --------------------------------------------------------------------------- a drive's inputs


def table_objects(drive: Any, table: InputTable) -> list[Any]:
    """The objects of ``drive`` written as ``table`` (an array's entries; none when absent)."""
    obj: Any = drive
    if is_further(table):
        obj = drive.input(table.name)
    elif table.name != "drive":
        for part in table.name.split("."):
            obj = getattr(obj, part, None)
    if obj is None:
        return []
    return list(obj) if table.array else [obj]


def table_values(table: InputTable, obj: Any) -> dict[str, Any]:
    """The values of ``table``'s fields in ``obj`` (SI; ``None``: not written)."""
    values = {f.name: getattr(obj, f.name, None) for f in table.fields}
    if table.name == "chain":  # a catalogue chain: only the fields changed from the catalogue's
        from ..chains import get
        from ..errors import UnknownNameError

        try:
            base = get(obj.name)
        except UnknownNameError:
            base = None
        if base is not None:
            values = {k: (None if k != "name" and getattr(base, k, None) == v else v) for k, v in values.items()}
    elif table.name == "tensioner" and obj.mechanism is not None:
        # described by its parts: the reader reduces them to mass and stiffness again
        values.update(mass=None, stiffness=None, **dict(obj.parts))
    return values


#: Plausibility check (chaindrive.limits.PLAUSIBLE) by SI unit.
PLAUSIBLE_KIND = {"rad/s": "angular_velocity", "W": "power", "N": "force"}


def warn_implausible_inputs(drive: Any) -> None:
    """Warn (:class:`~chaindrive.errors.ValidityRangeWarning`) for each input of ``drive``
    outside its plausible range, as the project-file reader does: speeds, powers, forces
    and the chain speed ``v = n p ω / 2π`` (:data:`chaindrive.limits.PLAUSIBLE`).

    Examples
    --------
    >>> import warnings
    >>> from chaindrive.chains import get
    >>> from chaindrive.drive import Drive, Load, Wheel
    >>> d = Drive(chain=get("16B"), speed=1450.0, load=Load(power=15e3),
    ...           wheels=(Wheel("a", "sprocket", 19, (0.0, 0.0), driving=True), Wheel("b", "sprocket", 57, (1.0, 0.0))))
    >>> with warnings.catch_warnings(record=True) as w:
    ...     warnings.simplefilter("always")
    ...     warn_implausible_inputs(d)
    >>> str(w[0].message).startswith("speed = 13846 rpm is implausible")
    True
    """
    from ..limits import warn_implausible
    from ..loads import mean_chain_speed

    for table in all_tables():
        for obj in table_objects(drive, table):
            if table.extra.get("mapping"):
                continue
            for f, value in zip(table.fields, table_values(table, obj).values(), strict=True):
                unit = "rad/s" if f.kind == "speed" else f.unit
                kind = "pitch" if unit == "m" and f.name == "pitch" else PLAUSIBLE_KIND.get(unit)
                if value is not None and f.plausible and kind is not None and f.kind in ("quantity", "speed"):
                    warn_implausible(f.name, value, kind, stacklevel=3)
    driving = [w for w in drive.wheels if w.driving]
    if len(driving) == 1 and driving[0].teeth is not None and not warn_implausible(
            "drive.speed", drive.speed, "angular_velocity", stacklevel=3):
        v = mean_chain_speed(driving[0].sides_per_turn(drive.chain), drive.chain.pitch, drive.speed)
        warn_implausible("drive.speed (chain speed n p omega / 2 pi)", v, "chain_speed", stacklevel=3)


def is_further(table: InputTable) -> bool:
    """A table an analysis part declared (held in ``Drive.extra_inputs``), not one of the drive's own."""
    return table.name.split(".")[0] not in _own_tables()


@functools.lru_cache(maxsize=1)
def _own_tables() -> frozenset[str]:
    """The names of the drive's own tables: its fields and ``drive``."""
    import dataclasses

    from .model import Drive

    return frozenset({f.name for f in dataclasses.fields(Drive)} | {"drive"})


def _built(table: InputTable, model: Any) -> Any:
    return model if table.target is None else table.target(**dict(model))


def further_inputs(project: Any) -> tuple[tuple[str, Any], ...]:
    """``Drive.extra_inputs`` of a validated project model: each further table's value, built by its
    ``target`` (default: the frozen model itself)."""
    out = []
    for table in all_tables():
        value = getattr(project, table.name, None) if is_further(table) and "." not in table.name else None
        if value is None:
            continue
        out.append((table.name, tuple(_built(table, v) for v in value) if table.array else _built(table, value)))
    return tuple(out)
