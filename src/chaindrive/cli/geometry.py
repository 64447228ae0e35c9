"""``chaindrive sprocket``, ``chaindrive pocket-wheel``, ``chaindrive track-wheel``: wheel geometry.

Text output is in millimetres and degrees; ``--json`` prints every computed dimension in
SI units (m, rad), the same numbers the Python API returns. ``--dxf``/``--svg`` write the
outline (in mm).
"""

from __future__ import annotations

import dataclasses
import functools
import inspect
from collections.abc import Callable
from pathlib import Path
from typing import Annotated, Any

import numpy as np
import typer

from ..display import mm
from ..errors import InputError
from .app import app, echo_json, print_rows, quantity, unit_help

# Help of the file options (the wheel-part commands build theirs in _part_parameters); the
# track wheel's options as module-level singletons (ruff B008)
_SPROCKET_DXF = "Write the workshop drawing to this DXF file (mm): front view with measuring pins, section A-A with the tooth chamfer, hub, bore H7 and DIN 6885-1 keyway, ISO 606:2015 dimensions, data table, title block. Needs the tooth width (a catalogue chain or --inner-width)."
_SPROCKET_STEP = "Write the 3-D solid to this STEP file (mm; build123d, extra 'cad3d'): ISO 606 teeth with the tooth side chamfer rx, ba (5.6.2), hub, bore and DIN 6885-1 keyway."
_POCKET_DXF = "Write the workshop drawing to this DXF file (mm): front view, section A-A with pockets and the groove for the vertical links, hub, bore H7 and DIN 6885-1 keyway, data table, title block."
_POCKET_STEP = "Write the 3-D solid to this STEP file (mm; build123d, extra 'cad3d'): pockets for the horizontal links, groove for the vertical links, hub, bore, DIN 6885-1 keyway."
_SVG_HELP = "Write the outline to this SVG file (viewBox in mm)."
_FORCE_HELP = "Overwrite existing output files (default: refuse)."
_FORCE = typer.Option(False, "--force", help=_FORCE_HELP)
_TRACK_DXF = typer.Option(None, "--dxf", help="Write the outline to this DXF file (mm; layers OUTLINE, PITCH_CIRCLE, CENTRES, ROOT, TIP).")
_TRACK_SVG = typer.Option(None, "--svg", help=_SVG_HELP)


@dataclasses.dataclass(frozen=True)
class _PartOptions:
    """The options every wheel-part command shares (``sprocket``, ``pocket-wheel``): the files
    it writes and the part's hub and material, as typed (see :func:`_part_command`)."""

    dxf: Path | None
    svg: Path | None
    step: Path | None
    bore: str | None
    hub_diameter: str | None
    hub_length: str | None
    material: str | None
    force: bool
    as_json: bool

    def part_kwargs(self) -> dict[str, Any]:
        """The hub options in SI units and the material note (if given) of the part builder."""
        out: dict[str, Any] = {name: quantity(getattr(self, name), "m", name)
                               for name in ("bore", "hub_diameter", "hub_length")}
        if self.material:
            out["material"] = self.material
        return out


def _part_parameters(dxf_help: str, step_help: str) -> list[inspect.Parameter]:
    """The shared options of a wheel-part command, in ``--help`` order (Typer ``Annotated`` style)."""
    def opt(name: str, kind: Any, default: Any, *decls: str, help: str) -> inspect.Parameter:
        return inspect.Parameter(name, inspect.Parameter.KEYWORD_ONLY, default=default,
                                 annotation=Annotated[kind, typer.Option(*decls, help=help)])

    return [
        opt("dxf", Path | None, None, "--dxf", help=dxf_help),
        opt("svg", Path | None, None, "--svg", help=_SVG_HELP),
        opt("step", Path | None, None, "--step", help=step_help),
        opt("bore", str | None, None, "--bore", help=unit_help("Bore diameter d (tolerance H7); default hub diameter / 1.8 rounded down to 5 mm. Refused when its DIN 6885-1 keyway leaves less than one key height h of wall to the hub (or to the root / groove bottom without hub); the message gives the range.", "m", "40 mm")),
        opt("hub_diameter", str | None, None, "--hub-diameter", help=unit_help("Hub diameter; at most ISO 606:2015 5.6.2 dg (sprocket) or the groove bottom (pocket wheel); default 1.8 x bore rounded up to 5 mm.", "m", "100 mm")),
        opt("hub_length", str | None, None, "--hub-length", help=unit_help("Hub projection beyond the plate on one side ('0 mm' for a plate wheel); default 1.2 x bore overall, rounded up to 5 mm.", "m", "50 mm")),
        opt("material", str | None, None, "--material", help="Material and heat-treatment note for the title block, e.g. 'C45, teeth induction hardened 45...55 HRC'."),
        opt("force", bool, False, "--force", help=_FORCE_HELP),
        opt("as_json", bool, False, "--json", help="Print every computed dimension as JSON in SI units (m, rad)."),
    ]


def _part_command(name: str, *, dxf_help: str, step_help: str) -> Callable[[Callable[..., None]], Callable[..., None]]:
    """Register a wheel-part command whose last parameter ``opts: _PartOptions`` stands for the
    shared options of :func:`_part_parameters` (one declaration, not one copy per command)."""
    def register(func: Callable[..., None]) -> Callable[..., None]:
        own = [p for p in inspect.signature(func, eval_str=True).parameters.values() if p.name != "opts"]
        shared = _part_parameters(dxf_help, step_help)

        @functools.wraps(func)
        def command(**kwargs: Any) -> None:
            opts = _PartOptions(**{p.name: kwargs.pop(p.name) for p in shared})
            func(**kwargs, opts=opts)

        command.__signature__ = inspect.Signature(own + shared, return_annotation=None)  # type: ignore[attr-defined]
        command.__annotations__ = {p.name: p.annotation for p in own + shared}
        return app.command(name)(command)
    return register


def _chain(name: str | None):
    if name is None:
        return None
    from .. import chains

    return chains.get(name)


def _check_paths(dxf: Path | None, svg: Path | None, step: Path | None = None, force: bool = True) -> None:
    """Refuse unwritable output paths before any work (one line, exit 2)."""
    from .._io import check_output_path

    if dxf is not None:
        check_output_path(dxf, (".dxf",), option="--dxf", force=force)
    if svg is not None:
        check_output_path(svg, (".svg",), option="--svg", force=force)
    if step is not None:
        from ..geometry.solid import STEP_SUFFIXES, have_build123d

        check_output_path(step, STEP_SUFFIXES, option="--step", force=force)
        if not have_build123d():
            raise InputError("--step needs build123d (OpenCascade): pip install 'chaindrive[cad3d]'")


def _write_part(part, dxf: Path | None, step: Path | None, force: bool) -> None:
    """Write the workshop drawing (DXF) and the solid (STEP) of a wheel part, atomically."""
    if dxf is not None:
        from ..geometry.drawing import write_drawing

        write_drawing(part, dxf, force=force, option="--dxf")
    if step is not None:
        from ..geometry.solid import write_step

        write_step(part, step, force=force, option="--step")


def _part_rows(part) -> list[tuple[str, str, str]]:
    hub = part.hub
    key = "-" if hub.key is None else f"{hub.key.label()} mm, d + t2 = {mm(hub.bore + hub.key.hub_depth):.1f} mm"
    return [
        ("bore d (H7)", _mm(hub.bore), "allowed " + _rng(*hub.bore_range)),
        ("hub diameter x projection", f"{mm(hub.hub_diameter):.1f} x {mm(hub.hub_length):.1f} mm", "allowed diameter " + _rng(*hub.hub_diameter_range)),
        ("keyway b x h", key, "DIN 6885-1:1968 table 1"),
        ("part width (plate/rim + hub)", _mm(part.total_width), "drawing and solid"),
    ]


def _write_outline(outline, title: str, dxf: Path | None, svg: Path | None, force: bool = True) -> None:
    """Write the outline atomically (temporary file, then rename)."""
    from .._io import atomic_write_text, save_dxf
    from ..geometry.export import dxf_document, svg_text

    if dxf is not None:
        save_dxf(dxf_document(outline, title), dxf, option="--dxf", force=force)
    if svg is not None:
        atomic_write_text(svg, svg_text(outline, title), force=force, option="--svg")


def _write(wheel, dxf: Path | None, svg: Path | None, form=None, force: bool = False) -> list[str]:
    if dxf is not None or svg is not None:
        _write_outline(wheel.outline() if form is None else wheel.outline(form), wheel.label(), dxf, svg,
                       force=force)
    return [f"wrote {p}" for p in (dxf, svg) if p is not None]


def _table(title: str, rows: list[tuple[str, str, str]]) -> None:
    print_rows(title, rows)


def _mm(v) -> str:
    return "-" if v is None else f"{mm(v):.3f} mm"


def _rng(lo, hi) -> str:
    """A range of lengths [m] in mm."""
    return f"{mm(lo):.3f} ... {mm(hi):.3f} mm"


@_part_command("sprocket", dxf_help=_SPROCKET_DXF, step_help=_SPROCKET_STEP)
def sprocket_command(
    chain: str | None = typer.Option(None, "--chain", "-c", help="Chain designation from the catalogue, e.g. 16B or 80 (ISO 606 / ANSI B29.1)."),
    teeth: int = typer.Option(..., "--teeth", "-z", help="Number of teeth z, dimensionless count, 9...10000 (chaindrive.limits.MAX_TEETH; ISO 606:2015 Annex A tabulates 9...150; a STEP solid at most 150)."),
    form: str | None = typer.Option(None, "--form", help="ISO 606:2015 5.4 tooth gap form for the outline: 'min' (ri min, α max, re max, tip da max) or 'max' (ri max, α min, re min, tip da min). Default min; not used with --method ansi."),
    method: str = typer.Option("iso606", "--method", help="Tooth form: iso606 (ISO 606:2015 clause 5) or ansi (ASME B29.1, Machinery's Handbook)."),
    pitch: str | None = typer.Option(None, "--pitch", help=unit_help("Chain pitch p when no --chain is given.", "m", "25.4 mm")),
    roller_diameter: str | None = typer.Option(None, "--roller-diameter", help=unit_help("Roller diameter d1 when no --chain is given.", "m", "15.88 mm")),
    inner_width: str | None = typer.Option(None, "--inner-width", help=unit_help("Width between inner plates b1 for the tooth width bf1 (ISO 606:2015 5.6).", "m", "17.02 mm")),
    plate_height: str | None = typer.Option(None, "--plate-height", help=unit_help("Inner plate depth h2 for the max hub diameter dg (ISO 606:2015 5.6).", "m", "21 mm")),
    tip_diameter: str | None = typer.Option(None, "--tip-diameter", help=unit_help("Tip diameter da of the outline, inside da min...da max (ISO 606:2015 5.5).", "m", "170 mm")),
    *, opts: _PartOptions,
) -> None:
    """Roller-chain sprocket dimensions and tooth outline to ISO 606:2015 clause 5 (or ASME B29.1).

    d = p / sin(180°/z) (5.3); df = d − d1 (5.3); da min/max (5.5); ri, α, re of the
    minimum and maximum tooth gap forms (5.4); bf1, rx, ba, dg (5.6); measurement over
    pins MR (5.3).
    """
    from ..geometry.part import sprocket_part
    from ..geometry.sprocket import Sprocket

    _check_paths(opts.dxf, opts.svg, opts.step, opts.force)
    ch = _chain(chain)
    if ch is not None:
        s = Sprocket.from_chain(ch, teeth, method=method)
    else:
        if pitch is None or roller_diameter is None:
            raise InputError("give --chain NAME, or both --pitch and --roller-diameter")
        s = Sprocket(
            pitch=quantity(pitch, "m", "pitch"),
            teeth=teeth,
            roller_diameter=quantity(roller_diameter, "m", "roller_diameter"),
            method=method,
        )
    if inner_width is not None:
        s = dataclasses.replace(s, inner_width=quantity(inner_width, "m", "inner_width"))
    if plate_height is not None:
        s = dataclasses.replace(s, plate_height=quantity(plate_height, "m", "plate_height"))
    tip = quantity(tip_diameter, "m", "tip_diameter")
    outline = s.outline(form=form, tip_diameter=tip)  # validates form / tip before any output
    d = s.dimensions()
    part = _write_files(opts, outline, s.label(), lambda **kw: sprocket_part(s, form=form, tip_diameter=tip, **kw))
    if opts.as_json:
        out = s.to_dict()
        out["outline"] = {"form": form or ("min" if method == "iso606" else None),
                          "tip_diameter": 2 * outline.circles["TIP"],
                          "root_seat_diameter": 2 * outline.circles["ROOT"],
                          "primitives": len(outline.primitives)}
        _echo_with_part(out, part)
        return
    deg = np.degrees
    rows = [
        ("pitch diameter d", _mm(d.pitch_diameter), "ISO 606:2015 5.3.2  d = p/sin(180°/z)"),
        ("root diameter df", _mm(d.root_diameter), "ISO 606:2015 5.3.2  df = d − d1"),
        ("tip diameter da", _rng(d.tip_diameter_min, d.tip_diameter_max), "ISO 606:2015 5.5.2"),
        ("roller seating radius ri", _rng(d.seating_radius_min, d.seating_radius_max), "ISO 606:2015 5.4.2"),
        ("roller seating angle α", f"{deg(d.seating_angle_min):.3f} ... {deg(d.seating_angle_max):.3f} °", "ISO 606:2015 5.4.2"),
        ("tooth flank radius re", _rng(d.flank_radius_min, d.flank_radius_max), "ISO 606:2015 5.4.2"),
        ("tooth height ha", _rng(d.tooth_height_min, d.tooth_height_max), "ISO 606:2015 5.5.2"),
        ("measurement over pins MR", _mm(d.measurement_over_pins), "ISO 606:2015 5.3.2"),
        ("tooth width bf1", _mm(d.tooth_width), "ISO 606:2015 5.6.2"),
        ("tooth side radius rx", _mm(d.tooth_side_radius), "ISO 606:2015 5.6.2"),
        ("tooth side relief ba", _rng(d.tooth_side_relief_min, d.tooth_side_relief_max), "ISO 606:2015 5.6.2"),
        ("max hub diameter dg", _mm(d.max_hub_diameter), "ISO 606:2015 5.6.2"),
        ("outline tip diameter", _mm(2 * outline.circles["TIP"]), f"drawn ({method}, form {form or 'min' if method == 'iso606' else 'ASME B29.1'})"),
    ]
    _finish(s.label(), rows, part, opts.dxf, opts.svg, opts.step)


def _write_msgs(dxf, svg, step=None):
    return [f"wrote {p}" for p in (dxf, svg, step) if p is not None]


def _write_files(opts: _PartOptions, outline: Any, label: str, make_part: Callable[..., Any]) -> Any:
    """Write a wheel's files (SVG outline, DXF drawing, STEP solid) as ``opts`` asks; the part
    (``make_part(**opts.part_kwargs())``), built only when a drawing or a solid is written, or None."""
    part = None
    if opts.dxf is not None or opts.step is not None:
        part = make_part(**opts.part_kwargs())
    _write_outline(outline, label, None, opts.svg, force=opts.force)
    if part is not None:
        _write_part(part, opts.dxf, opts.step, opts.force)
    return part


def _echo_with_part(out: dict[str, Any], part: Any) -> None:
    """A wheel's JSON, with its part (bore, hub, key, material) when one was built."""
    if part is not None:
        out["part"] = part.to_dict()
    echo_json(out)


def _finish(label: str, rows: list[tuple[str, str, str]], part: Any, dxf, svg, step=None) -> None:
    """The wheel's table (with its part's rows) and the files written."""
    _table(label, rows + (_part_rows(part) if part is not None else []))
    for line in _write_msgs(dxf, svg, step):
        print(line)


@_part_command("pocket-wheel", dxf_help=_POCKET_DXF, step_help=_POCKET_STEP)
def pocket_wheel_command(
    chain: str | None = typer.Option(None, "--chain", "-c", help="Round link chain from the catalogue, e.g. 18x64 (DIN 22252: d x t in mm)."),
    teeth: int = typer.Option(..., "--teeth", "-z", help="Number of pockets z (horizontal links per turn), >= 3 (dimensionless count)."),
    pitch: str | None = typer.Option(None, "--pitch", help=unit_help("Inner link length t when no --chain is given.", "m", "64 mm")),
    bar_diameter: str | None = typer.Option(None, "--bar-diameter", help=unit_help("Bar diameter d when no --chain is given.", "m", "18 mm")),
    inner_width: str | None = typer.Option(None, "--inner-width", help=unit_help("Inner width of a link b; default 21/18 d (DIN 22252, 18x64). Sets the slot depth.", "m", "21 mm")),
    clearance: str = typer.Option("0 mm", "--clearance", help=unit_help("Play round the link in pocket and slot (drawing only).", "m", "1 mm")),
    *, opts: _PartOptions,
) -> None:
    """Pocket wheel for a round link chain: pitch radius (Dolipiński et al. eq. 6), central angles
    δ1, δ2 (Dolipiński et al. eqs 7-9), pocket and hinge positions, and a basic outline."""
    from ..geometry.part import pocket_wheel_part
    from ..geometry.pocket_wheel import PocketWheel

    _check_paths(opts.dxf, opts.svg, opts.step, opts.force)
    kw: dict[str, Any] = {"clearance": quantity(clearance, "m", "clearance")}
    width = quantity(inner_width, "m", "inner_width")
    ch = _chain(chain)
    if ch is not None:
        w = PocketWheel.from_chain(ch, teeth, **kw)
        if width is not None:
            w = dataclasses.replace(w, inner_width=width)  # validated again
    else:
        if width is not None:
            kw["inner_width"] = width
        if pitch is None or bar_diameter is None:
            raise InputError("give --chain NAME, or both --pitch and --bar-diameter")
        w = PocketWheel(pitch=quantity(pitch, "m", "pitch"), bar_diameter=quantity(bar_diameter, "m", "bar_diameter"),
                        teeth=teeth, **kw)
    outline = w.outline()  # validate before output
    part = _write_files(opts, outline, w.label(), lambda **kw: pocket_wheel_part(w, **kw))
    d = w.dimensions()
    if opts.as_json:
        out = w.to_dict()
        _echo_with_part(out, part)
        return
    deg = np.degrees
    rows = [
        ("pitch radius R", _mm(d.pitch_radius), "Dolipiński et al. eq. (6)"),
        ("central angle δ1 (t + d)", f"{deg(d.central_angle_horizontal):.4f} °", "Dolipiński et al. eq. (7)"),
        ("central angle δ2 (t − d)", f"{deg(d.central_angle_vertical):.4f} °", "Dolipiński et al. eq. (8)"),
        ("pocket floor from axis", _mm(d.pocket_floor_distance), "R cos(δ1/2) − d/2 − c"),
        ("pocket length", _mm(d.pocket_length), "t + 2d + 2c"),
        ("slot bottom radius", _mm(d.slot_radius), "R cos(δ2/2) − (b + 2d)/2 − c"),
        ("tip radius", _mm(d.tip_radius), "R + d/2 (drawing choice)"),
        ("pocket centre angles", ", ".join(f"{a:.2f}" for a in deg(d.pocket_angles)) + " °", "θk = 90° + 360° k/z"),
    ]
    _finish(w.label(), rows, part, opts.dxf, opts.svg, opts.step)


@app.command("track-wheel")
def track_wheel_command(
    pitch: str = typer.Option(..., "--pitch", help=unit_help("Track pitch t (pin centre distance); pitch radius R_0 = t/(2 sin(pi/z)).", "m", "170 mm")),
    teeth: int = typer.Option(..., "--teeth", "-z", help="Number of teeth z >= 3 (dimensionless count)."),
    pin_radius: str = typer.Option(..., "--pin-radius", help=unit_help("Lantern pin radius r_pin (Sharipov).", "m", "25 mm")),
    link: str = typer.Option("built-up", "--link", help="Track links: built-up (tip radius R_tip = R_0 + (0.2...0.5) r_pin) or cast (R_tip = R_0 + (0.8...1.2) r_pin), Sharipov p. 34."),
    root_factor: float | None = typer.Option(None, "--root-factor", help="r_seat / r_pin, dimensionless, in [1.1, 1.3] (Sharipov p. 34: root radius R_root = R_0 - r_seat); default 1.2."),
    tip_factor: float | None = typer.Option(None, "--tip-factor", help="(R_tip - R_0) / r_pin, dimensionless, inside Sharipov's range for --link; default its middle."),
    elongation_limit: float | None = typer.Option(None, "--elongation-limit", help="Largest allowed wear elongation of the track pitch, dimensionless fraction in (0, 0.1] (0.03 = 3 %); adds the smallest tip radius that holds the worn chain, R_tip,min = t (1 + elongation) / (2 sin(pi/z)) (Sharipov p. 34: the tip radius follows from the largest pitch of the worn chain)."),
    dxf: Path | None = _TRACK_DXF,
    svg: Path | None = _TRACK_SVG,
    force: bool = _FORCE,
    as_json: bool = typer.Option(False, "--json", help="Print every computed dimension and allowed range as JSON in SI units (m)."),
) -> None:
    """Drive wheel of a tracked vehicle engaging lantern pins (Sharipov p. 34):
    root radius R_root = R_0 - r_seat, r_seat = (1.1...1.3) r_pin; tip radius
    R_tip = R_0 + (0.2...0.5) r_pin (built-up links) or R_0 + (0.8...1.2) r_pin (cast links)."""
    from ..geometry.track_wheel import TrackDriveWheel

    _check_paths(dxf, svg, force=force)
    w = TrackDriveWheel(pitch=quantity(pitch, "m", "pitch"), teeth=teeth,
                        pin_radius=quantity(pin_radius, "m", "pin_radius"), link=link,
                        root_factor=root_factor, tip_factor=tip_factor, elongation_limit=elongation_limit)
    w.outline()
    _write(w, dxf, svg, force=force)
    d = w.dimensions()
    if as_json:
        echo_json(w.to_dict())
        return
    rows = [
        ("pitch radius R_0", _mm(d.pitch_radius), "t / (2 sin(pi/z))"),
        ("pin seat radius r_seat", _mm(d.pin_seat_radius) + f" (k = {d.root_factor:g})", "Sharipov p. 34, k = r_seat/r_pin = 1.1...1.3"),
        ("  allowed", _rng(*d.pin_seat_radius_range), "Sharipov p. 34"),
        ("root radius R_root", _mm(d.root_radius), "Sharipov p. 34: R_root = R_0 - r_seat"),
        ("  allowed", _rng(*d.root_radius_range), "Sharipov p. 34"),
        ("tip radius R_tip", _mm(d.tip_radius) + f" (k = {d.tip_factor:g})", f"Sharipov p. 34, {d.link} links"),
        ("  allowed", _rng(*d.tip_radius_range), "Sharipov p. 34"),
        ("flank radius", _mm(d.flank_radius), "t - r_seat about the next pin (drawing)"),
        ("tooth pointed below R_tip", "yes" if d.tooth_pointed else "no", ""),
    ]
    if d.worn_tip_radius is not None and d.worn_tip_factor is not None:
        holds = "holds" if d.tip_radius >= d.worn_tip_radius else "TOO LOW: the worn chain jumps the teeth"
        rows.append(("smallest tip radius, worn chain", _mm(d.worn_tip_radius) + f" (k = {d.worn_tip_factor:.3g}; {holds})",
                     "Sharipov p. 34: R_tip >= t (1 + elongation) / (2 sin(pi/z))"))
    _finish(w.label(), rows, None, dxf, svg)
