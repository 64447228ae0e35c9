"""Workshop drawings of wheel parts (DXF, ezdxf): views, dimensions, data table, title block.

One sheet (ISO 5457 A3 or A2 landscape, scale from ISO 5455: 1:1, 1:2, 1:5, 1:10) holds

* the **front view** (face outline with exact arcs, pitch circle as a centre line, hub,
  bore and keyway, centre lines, the cutting plane A-A), dimensioned with the tip, root
  and pitch diameters, the measurement over pins ``MR`` between two measuring pins
  ``dR = d1`` drawn in the gaps (sprockets, ISO 606:2015 5.3.2) and the keyway width;
* the **section A-A** through the axis and the keyway (hatched cut, the chamfered tooth
  or the pocket-wheel groove, hub, bore), dimensioned with the tooth or rim width, the
  tooth side relief ``ba`` and radius ``rx`` (ISO 606:2015 5.6.2), hub diameter and
  length, bore ``H7`` and the keyway depth ``d + t2`` (DIN 6885-1);
* a **data table** (chain, teeth, tooth form and every ISO 606 / Dolipiński et al.
  dimension with its tolerance) and a **title block** (part name, chain, teeth,
  material and heat treatment, scale, units mm, date, ``chaindrive <version>``).

Model space is in millimetres at full size (1 drawing unit = 1 mm of the part); the
frame, texts and dimension style are scaled by the sheet scale, so the sheet prints at
the stated scale. The document passes ezdxf's ``audit()`` (tests).
"""

from __future__ import annotations

import datetime as _dt
import math
import os
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from ..errors import InputError
from .part import Groove, WheelPart, check_part_size, side_chamfer_thickness

if TYPE_CHECKING:
    from ezdxf.document import Drawing
    from ezdxf.entities import Circle as DxfCircle
    from ezdxf.entities import Line as DxfLine
    from ezdxf.entities import LWPolyline, Text
    from ezdxf.enums import TextEntityAlignment

__all__ = ["SHEETS", "SCALES", "Sheet", "choose_sheet", "part_drawing", "write_drawing", "render_png"]

_MM = 1e3

#: ISO 5457 sheet sizes, landscape (width, height) [mm].
SHEETS = {"A3": (420.0, 297.0), "A2": (594.0, 420.0), "A1": (841.0, 594.0)}
#: ISO 5455 reduction scales tried in turn (paper mm per part mm).
SCALES = (1.0, 0.5, 0.2, 0.1, 0.05)

_TITLE_W, _TITLE_H = 180.0, 56.0  # title block [paper mm]
_TABLE_ROW = 6.0
_LEFT, _MARGIN = 20.0, 10.0

_LAYERS = {
    # name: (colour, linetype, lineweight [1/100 mm])
    "OUTLINE": (7, "CONTINUOUS", 50),
    "THIN": (7, "CONTINUOUS", 25),
    "HIDDEN": (8, "DASHED", 25),
    "CENTER": (1, "CENTER", 18),
    "DIMENSIONS": (3, "CONTINUOUS", 18),
    "HATCH": (8, "CONTINUOUS", 18),
    "TEXT": (7, "CONTINUOUS", 25),
    "FRAME": (7, "CONTINUOUS", 50),
    "TITLE": (7, "CONTINUOUS", 25),
    "PINS": (5, "PHANTOM", 18),
}


@dataclass(frozen=True)
class Sheet:
    """Sheet size name, size [paper mm] and scale (paper mm per part mm)."""

    name: str
    width: float
    height: float
    scale: float

    @property
    def scale_label(self) -> str:
        """``"1:2"`` or ``"2:1"``."""
        s = self.scale
        return f"1:{1 / s:g}" if s <= 1 else f"{s:g}:1"



def _groove(part: WheelPart) -> Groove:
    """The groove of a pocket-wheel part (every pocket wheel has one)."""
    if part.groove is None:
        raise InputError("drawing: a pocket wheel part needs its groove for the vertical links")
    return part.groove

def _views_size(part: WheelPart) -> tuple[float, float]:
    """Width and height [part mm] the two views and their dimensions need at scale 1."""
    d = 2 * part.tip_radius * _MM
    w = part.total_width * _MM
    return d + w, d


def choose_sheet(part: WheelPart) -> Sheet:
    """The smallest sheet and largest scale (ISO 5457 / ISO 5455) on which the views fit.

    Parameters
    ----------
    part : WheelPart
        The part whose plan and section views are to fit.

    Returns
    -------
    Sheet

    Examples
    --------
    >>> from chaindrive.geometry import Sprocket
    >>> from chaindrive.geometry.part import sprocket_part
    >>> s = choose_sheet(sprocket_part(Sprocket.from_chain("16B", 19)))
    >>> s.name, s.scale_label
    ('A2', '1:1')
    """
    need_w, need_h = _views_size(part)
    for scale in SCALES:
        for name in ("A3", "A2"):
            width, height = SHEETS[name]
            room_w = width - _LEFT - _MARGIN - _TITLE_W - 10.0 - 100.0  # dims and gap between views
            room_h = height - 2 * _MARGIN - 60.0
            if need_w * scale <= room_w and need_h * scale <= room_h:
                return Sheet(name, width, height, scale)
    raise InputError(
        f"the part is too large for an A2 sheet at 1:{1 / SCALES[-1]:g} "
        f"(tip diameter {2 * part.tip_radius * _MM:.0f} mm)"
    )


# --------------------------------------------------------------------------- helpers
def _version() -> str:
    try:
        from importlib.metadata import version

        return version("chaindrive")
    except Exception:  # pragma: no cover - not installed as a distribution
        return "0+unknown"


def _radius_at(outline, angle: float) -> float:
    """Radius of a star-shaped outline along the ray at polar ``angle`` [m]."""
    p = outline.polyline(90)
    ang = np.unwrap(np.arctan2(p[:, 1], p[:, 0]))
    r = np.hypot(p[:, 0], p[:, 1])
    target = angle
    while target < ang.min():
        target += 2 * np.pi
    while target > ang.max():
        target -= 2 * np.pi
    return float(np.interp(target, ang, r)) if ang[-1] > ang[0] else float(np.interp(-target, -ang, r))


def _bulge(p0, p1, centre, ccw: bool) -> float:
    a0 = math.atan2(p0[1] - centre[1], p0[0] - centre[0])
    a1 = math.atan2(p1[1] - centre[1], p1[0] - centre[0])
    sweep = (a1 - a0) % (2 * math.pi)
    if not ccw:
        sweep -= 2 * math.pi
    return math.tan(sweep / 4)


class _Sheet:
    """Model-space drawing helper: paper coordinates -> model mm."""

    def __init__(self, doc: Drawing, sheet: Sheet) -> None:
        self.doc = doc
        self.msp = doc.modelspace()
        self.sheet = sheet
        self.k = 1.0 / sheet.scale  # model mm per paper mm

    def text(self, s: str, xy: Sequence[float], height: float = 3.5, layer: str = "TEXT",
             align: TextEntityAlignment | None = None, rotation: float = 0.0) -> Text:
        from ezdxf.enums import TextEntityAlignment

        t = self.msp.add_text(s, height=height * self.k, rotation=rotation, dxfattribs={"layer": layer, "style": "CD"})
        t.set_placement(xy, align=align or TextEntityAlignment.BOTTOM_LEFT)
        return t

    def line(self, p0: Sequence[float], p1: Sequence[float], layer: str = "OUTLINE") -> DxfLine:
        return self.msp.add_line(p0, p1, dxfattribs={"layer": layer})

    def poly(self, points: Iterable[Sequence[float]], layer: str = "OUTLINE", close: bool = False,
             fmt: str = "xy") -> LWPolyline:
        return self.msp.add_lwpolyline(points, format=fmt, close=close, dxfattribs={"layer": layer})

    def circle(self, centre: Sequence[float], radius: float, layer: str = "OUTLINE") -> DxfCircle:
        return self.msp.add_circle(centre, radius, dxfattribs={"layer": layer})


def _setup(sheet: Sheet):
    import ezdxf

    doc = ezdxf.new("R2010", setup=True)
    doc.units = ezdxf.units.MM
    doc.header["$MEASUREMENT"] = 1
    doc.header["$LTSCALE"] = 1.0 / sheet.scale
    if "CD" not in doc.styles:
        doc.styles.add("CD", font="DejaVuSans.ttf")
    for name, (colour, ltype, weight) in _LAYERS.items():
        if name not in doc.layers:
            doc.layers.add(name, color=colour, linetype=ltype, lineweight=weight)
    k = 1.0 / sheet.scale
    style = doc.dimstyles.duplicate_entry("EZDXF", "CD") if "CD" not in doc.dimstyles else doc.dimstyles.get("CD")
    # the dimension style on the sheet in mm: text 3.5, arrows 3, gaps 1-2, two decimals, text
    # above the line, colours 3 (lines) and 7 (text), trailing zeros suppressed (dimzin 8);
    # dimlfac 1: the EZDXF template shows metres as centimetres
    for key, value in dict(dimtxsty="CD", dimscale=k, dimtxt=3.5, dimasz=3.0, dimexe=2.0, dimexo=1.0,
                           dimgap=1.0, dimdec=2, dimtad=1, dimtih=0, dimtoh=0, dimclrd=3, dimclre=3,
                           dimclrt=7, dimzin=8, dimlfac=1.0).items():
        style.dxf.set(key, value)
    return doc


def _dim(msp, kind: str, **kw):
    kw.setdefault("dimstyle", "CD")
    dxfattribs = {"layer": "DIMENSIONS"}
    if kind == "linear":
        d = msp.add_linear_dim(dxfattribs=dxfattribs, **kw)
    elif kind == "aligned":
        d = msp.add_aligned_dim(dxfattribs=dxfattribs, **kw)
    elif kind == "diameter":
        d = msp.add_diameter_dim(dxfattribs=dxfattribs, **kw)
    else:  # pragma: no cover - internal
        raise ValueError(kind)
    d.render()
    return d


# --------------------------------------------------------------------------- views
def _front_view(sh: _Sheet, part: WheelPart, c) -> None:
    """Face view centred at ``c`` (model mm)."""
    cx, cy = c
    o = part.outline
    hub = part.hub
    verts = [(cx + p.start[0] * _MM, cy + p.start[1] * _MM, p.bulge) for p in o.primitives]
    sh.poly(verts, layer="OUTLINE", close=True, fmt="xyb")
    rp = o.pitch_radius * _MM
    sh.circle((cx, cy), rp, layer="CENTER")
    ra = part.tip_radius * _MM
    # hub circle (hub towards the viewer) and bore with keyway
    if hub.hub_length > 0:
        sh.circle((cx, cy), hub.hub_diameter * _MM / 2, layer="OUTLINE")
    rb = hub.bore * _MM / 2
    if hub.key is None:
        sh.circle((cx, cy), rb, layer="OUTLINE")
    else:
        b = hub.key.width * _MM / 2
        top = rb + hub.key.hub_depth * _MM
        yb = math.sqrt(rb * rb - b * b)
        pts = [(cx + b, cy + yb, 0.0), (cx + b, cy + top, 0.0), (cx - b, cy + top, 0.0)]
        bulge = _bulge((-b, yb), (b, yb), (0.0, 0.0), ccw=True)
        pts.append((cx - b, cy + yb, bulge))
        sh.poly(pts, layer="OUTLINE", close=True, fmt="xyb")
    if part.groove is not None:
        sh.circle((cx, cy), part.groove.bottom_radius * _MM, layer="HIDDEN")
    # centre lines and cutting plane A-A (vertical through the keyway)
    ext = ra + 6 * sh.k
    sh.line((cx - ext, cy), (cx + ext, cy), layer="CENTER")
    sh.line((cx, cy - ext), (cx, cy + ext), layer="CENTER")
    arrow = 8 * sh.k
    for sgn in (1, -1):
        y = cy + sgn * (ra + 8 * sh.k)
        sh.poly([(cx, y), (cx, y + sgn * 6 * sh.k)], layer="OUTLINE")
        sh.poly([(cx, y + sgn * 3 * sh.k), (cx + arrow, y + sgn * 3 * sh.k)], layer="THIN")
        tip = (cx + arrow + 2.5 * sh.k, y + sgn * 3 * sh.k)
        sh.msp.add_solid([tip, (cx + arrow, y + sgn * 3 * sh.k + 1 * sh.k), (cx + arrow, y + sgn * 3 * sh.k - 1 * sh.k)],
                         dxfattribs={"layer": "THIN"})
        sh.text("A", (cx + arrow + 4 * sh.k, y + sgn * 3 * sh.k - 2 * sh.k), height=5)
    if part.chamfer is not None:
        sh.circle((cx, cy), part.dimensions.root_diameter * _MM / 2, layer="THIN")
        _pins(sh, part, (cx, cy))
    if hub.key is not None:
        b = hub.key.width * _MM / 2
        top = rb + hub.key.hub_depth * _MM
        _dim(sh.msp, "linear", base=(cx, cy + top + 8 * sh.k), p1=(cx - b, cy + top), p2=(cx + b, cy + top),
             text="<> JS9")


def _pins(sh: _Sheet, part: WheelPart, c) -> None:
    """Two measuring pins dR = d1 in opposite gaps and the measurement over pins MR."""
    cx, cy = c
    dims = part.dimensions
    z = part.teeth
    rp = part.outline.pitch_radius * _MM
    dr = dims.roller_diameter * _MM
    a1 = math.pi / 2
    a2 = a1 + 2 * math.pi * (z // 2) / z
    p1 = np.array([cx + rp * math.cos(a1), cy + rp * math.sin(a1)])
    p2 = np.array([cx + rp * math.cos(a2), cy + rp * math.sin(a2)])
    for p in (p1, p2):
        sh.circle(tuple(p), dr / 2, layer="PINS")
    u = (p1 - p2) / np.linalg.norm(p1 - p2)
    q1, q2 = p1 + u * dr / 2, p2 - u * dr / 2
    _dim(sh.msp, "aligned", p1=tuple(q2), p2=tuple(q1), distance=part.tip_radius * _MM + 12 * sh.k,
         text=f"<> (MR over pins %%c{dr:g})")


def _half_profile(part: WheelPart, r_cut: float, r_in: float) -> list[tuple[float, float, float]]:
    """Cut region of the section in (z, r) [mm] with bulges, from the bore edge ``r_in`` out."""
    w = part.width * _MM / 2
    hub = part.hub
    pts: list[tuple[float, float, float]] = [(-w, r_in, 0.0)]
    ch = part.chamfer
    if ch is not None and r_cut > ch.start_radius * _MM + 1e-9:
        rt = ch.start_radius * _MM
        t_cut = float(side_chamfer_thickness(r_cut / _MM, part.width, ch.tip_radius, ch.side_radius,
                                             ch.side_relief)) * _MM / 2
        rx = ch.side_radius * _MM
        c_left = (-w + rx, rt)
        c_right = (w - rx, rt)
        pts.append((-w, rt, _bulge((-w, rt), (-t_cut, r_cut), c_left, ccw=False)))
        pts.append((-t_cut, r_cut, 0.0))
        pts.append((t_cut, r_cut, _bulge((t_cut, r_cut), (w, rt), c_right, ccw=False)))
        pts.append((w, rt, 0.0))
    elif part.groove is not None:
        g = part.groove.width * _MM / 2
        rg = part.groove.bottom_radius * _MM
        pts += [(-w, r_cut, 0.0), (-g, r_cut, 0.0), (-g, rg, 0.0), (g, rg, 0.0), (g, r_cut, 0.0), (w, r_cut, 0.0)]
    else:
        pts += [(-w, r_cut, 0.0), (w, r_cut, 0.0)]
    if hub.hub_length > 0:
        rh = hub.hub_diameter * _MM / 2
        end = w + hub.hub_length * _MM
        pts += [(w, rh, 0.0), (end, rh, 0.0), (end, r_in, 0.0)]
    else:
        pts.append((w, r_in, 0.0))
    return pts


def _section_view(sh: _Sheet, part: WheelPart, c) -> None:
    """Section A-A through the axis and the keyway; ``c`` is the axis point at the plate's mid-plane."""
    cx, cy = c
    hub = part.hub
    w = part.width * _MM / 2
    rb = hub.bore * _MM / 2
    ra = part.tip_radius * _MM
    end = w + hub.hub_length * _MM
    top_in = rb + (hub.key.hub_depth * _MM if hub.key is not None else 0.0)
    for sgn, angle, r_in in ((1, math.pi / 2, top_in), (-1, -math.pi / 2, rb)):
        r_cut = _radius_at(part.outline, angle) * _MM
        prof = _half_profile(part, r_cut, r_in)
        pts = [(cx + z, cy + sgn * r, b * sgn) for z, r, b in prof]
        sh.poly(pts, layer="OUTLINE", close=True, fmt="xyb")
        hatch = sh.msp.add_hatch(color=8, dxfattribs={"layer": "HATCH"})
        hatch.set_pattern_fill("ANSI31", scale=0.6 * sh.k)
        hatch.paths.add_polyline_path(pts, is_closed=True)
        _beyond(sh, part, (cx, cy), sgn, r_cut)
    # bore edges seen beyond the keyway, centre line
    if hub.key is not None:
        yb = math.sqrt(rb * rb - (hub.key.width * _MM / 2) ** 2)
        sh.line((cx - w, cy + yb), (cx + end, cy + yb), layer="OUTLINE")
    sh.line((cx - w - 6 * sh.k, cy), (cx + end + 6 * sh.k, cy), layer="CENTER")
    sh.text("A-A", (cx + (end - w) / 2, cy + ra + 18 * sh.k), height=7,
            align=_align("BOTTOM_CENTER"))
    k = sh.k
    # dimensions: width, hub length, total, diameters
    _dim(sh.msp, "linear", base=(cx, cy + ra + 7 * k), p1=(cx - w, cy + ra * 0 + _top_of_side(part)),
         p2=(cx + w, cy + _top_of_side(part)), text="<> h14" if part.chamfer is not None else "<>")
    _dim(sh.msp, "linear", base=(cx, cy - ra - 10 * k), p1=(cx - w, cy - rb), p2=(cx + end, cy - rb))
    if hub.hub_length > 0:
        rh = hub.hub_diameter * _MM / 2
        _dim(sh.msp, "linear", base=(cx + end + 12 * k, cy), p1=(cx + end, cy - rh), p2=(cx + end, cy + rh),
             angle=90, text="%%c<>")
    _dim(sh.msp, "linear", base=(cx + end + 26 * k, cy), p1=(cx + end, cy - rb), p2=(cx + end, cy + rb),
         angle=90, text="%%c<> H7")
    if hub.key is not None:
        _dim(sh.msp, "linear", base=(cx + end + 40 * k, cy), p1=(cx + end, cy - rb), p2=(cx + end, cy + top_in),
             angle=90, text="<> (d + t2)")
    # diameters on the left: tip, root (sprocket) or groove bottom (pocket wheel), pitch (reference)
    rp = part.outline.pitch_radius * _MM
    sh.line((cx - w - 3 * k, cy + rp), (cx + w + 3 * k, cy + rp), layer="CENTER")
    sh.line((cx - w - 3 * k, cy - rp), (cx + w + 3 * k, cy - rp), layer="CENTER")
    if part.chamfer is not None:
        rf = part.dimensions.root_diameter * _MM / 2
        for sgn in (1, -1):
            sh.line((cx - w, cy + sgn * rf), (cx + w, cy + sgn * rf), layer="THIN")
        second, second_text = rf, "%%c<> h11 (df)"
        tip_text, pitch_text = "%%c<> (da)", "(%%c<>) (d)"
    else:
        second, second_text = _groove(part).bottom_radius * _MM, "%%c<> (groove)"
        tip_text, pitch_text = "%%c<>", "(%%c<>) (2R)"
    for offset, radius, text in ((30, ra, tip_text), (20, second, second_text), (10, rp, pitch_text)):
        _dim(sh.msp, "linear", base=(cx - w - offset * k, cy), p1=(cx - w, cy - radius), p2=(cx - w, cy + radius),
             angle=90, text=text)
    ch = part.chamfer
    if ch is not None:
        ba = ch.side_relief * _MM
        rt = ch.start_radius * _MM
        # tooth side relief ba at the tip of the tooth seen in the lower half
        _dim(sh.msp, "linear", base=(cx, cy - ra - 20 * k), p1=(cx - w, cy - rt), p2=(cx - w + ba, cy - ra),
             text="<> (ba)")
        sh.text(f"rx = {ch.side_radius * _MM:g}", (cx + w + 3 * k, cy - ra + 1.5 * k), height=3.5)
    if part.groove is not None:
        g = part.groove.width * _MM / 2
        rg = part.groove.bottom_radius * _MM
        _dim(sh.msp, "linear", base=(cx, cy - ra - 20 * k), p1=(cx - g, cy - rg), p2=(cx + g, cy - rg),
             text="<> (groove)")


def _top_of_side(part: WheelPart) -> float:
    """Height [mm] at which the plate's side faces are dimensioned (below any chamfer)."""
    if part.chamfer is not None:
        return part.chamfer.start_radius * _MM
    return part.tip_radius * _MM


def _beyond(sh: _Sheet, part: WheelPart, c, sgn: int, r_cut: float) -> None:
    """Visible edges behind the cutting plane: teeth tips with their chamfer, or the rim with its groove."""
    cx, cy = c
    w = part.width * _MM / 2
    ra = part.tip_radius * _MM
    if r_cut >= ra - 1e-6:
        return
    ch = part.chamfer
    if ch is not None:
        rt = ch.start_radius * _MM
        ba = ch.side_relief * _MM
        rx = ch.side_radius * _MM
        pts = [(cx - w, cy + sgn * r_cut, 0.0)]
        pts.append((cx - w, cy + sgn * rt, sgn * _bulge((-w, rt), (-w + ba, ra), (-w + rx, rt), ccw=False)))
        pts.append((cx - w + ba, cy + sgn * ra, 0.0))
        pts.append((cx + w - ba, cy + sgn * ra, sgn * _bulge((w - ba, ra), (w, rt), (w - rx, rt), ccw=False)))
        pts.append((cx + w, cy + sgn * rt, 0.0))
        pts.append((cx + w, cy + sgn * r_cut, 0.0))
        sh.poly(pts, layer="OUTLINE", fmt="xyb")
    else:
        g = _groove(part).width * _MM / 2
        sh.poly([(cx - w, cy + sgn * r_cut), (cx - w, cy + sgn * ra), (cx - g, cy + sgn * ra),
                 (cx - g, cy + sgn * r_cut)], layer="OUTLINE")
        sh.poly([(cx + g, cy + sgn * r_cut), (cx + g, cy + sgn * ra), (cx + w, cy + sgn * ra),
                 (cx + w, cy + sgn * r_cut)], layer="OUTLINE")


def _align(name: str):
    from ezdxf.enums import TextEntityAlignment

    return getattr(TextEntityAlignment, name)


# --------------------------------------------------------------------------- tables
def _data_rows(part: WheelPart) -> list[tuple[str, str]]:
    d = part.dimensions

    def mm(v, tol=""):
        return f"{v * _MM:.3f} mm{(' ' + tol) if tol else ''}"

    if part.chamfer is not None:
        form = {"min": "ISO 606 minimum tooth gap form", "max": "ISO 606 maximum tooth gap form"}.get(
            part.form or "", "ASME B29.1 tooth form")
        return [
            ("Chain", part.chain),
            ("Pitch p", mm(d.pitch)),
            ("Roller diameter d1", mm(d.roller_diameter)),
            ("Number of teeth z", f"{part.teeth}"),
            ("Tooth form", form),
            ("Pitch diameter d", mm(d.pitch_diameter)),
            ("Tip diameter da (drawn)", mm(2 * part.tip_radius)),
            ("  da min ... da max", f"{d.tip_diameter_min * _MM:.3f} ... {d.tip_diameter_max * _MM:.3f} mm"),
            ("Root diameter df", mm(d.root_diameter, "h11")),
            ("Seating radius ri", f"{d.seating_radius_min * _MM:.3f} ... {d.seating_radius_max * _MM:.3f} mm"),
            ("Seating angle α",
             f"{math.degrees(d.seating_angle_min):.2f} ... {math.degrees(d.seating_angle_max):.2f}°"),
            ("Flank radius re", f"{d.flank_radius_min * _MM:.2f} ... {d.flank_radius_max * _MM:.2f} mm"),
            ("Measurement over pins MR", f"{d.measurement_over_pins * _MM:.3f} mm (dR = {d.roller_diameter * _MM:g})"),
            ("Tooth width bf1", mm(part.width, "h14")),
            ("Tooth side radius rx", mm(part.chamfer.side_radius)),
            ("Tooth side relief ba", mm(part.chamfer.side_relief)),
            ("Max. shroud diameter dg", "-" if d.max_hub_diameter is None else mm(d.max_hub_diameter)),
            ("Keyway (DIN 6885-1)", _key_text(part)),
        ]
    return [
        ("Chain (DIN 22252)", part.chain),
        ("Link length t x bar d", f"{d.pitch * _MM:g} x {d.bar_diameter * _MM:g} mm"),
        ("Number of pockets z", f"{part.teeth}"),
        ("Pitch radius R (eq. 6)", mm(d.pitch_radius)),
        ("Central angle δ1 (t + d)", f"{math.degrees(d.central_angle_horizontal):.4f}°"),
        ("Central angle δ2 (t − d)", f"{math.degrees(d.central_angle_vertical):.4f}°"),
        ("Pocket floor from axis", mm(d.pocket_floor_distance)),
        ("Pocket length t + 2d + 2c", mm(d.pocket_length)),
        ("Rim width b + 2d + 2c", mm(part.width)),
        ("Groove width d + 2c", mm(_groove(part).width)),
        ("Groove bottom diameter", mm(2 * _groove(part).bottom_radius)),
        ("Tip diameter", mm(2 * part.tip_radius)),
        ("Clearance c", mm(d.clearance)),
        ("Keyway (DIN 6885-1)", _key_text(part)),
    ]


def _key_text(part: WheelPart) -> str:
    k = part.hub.key
    if k is None:
        return "none"
    return f"{k.label()}, d + t2 = {(part.hub.bore + k.hub_depth) * _MM:.1f} mm"


def _table(sh: _Sheet, rows, x0: float, y_top: float, title: str) -> float:
    """Two-column table with its top-left corner at paper (x0, y_top); returns its bottom [paper mm]."""
    k = sh.k
    w1, w2 = 72.0, _TITLE_W - 72.0
    n = len(rows) + 1
    y_bot = y_top - n * _TABLE_ROW
    sh.poly([(x0 * k, y_top * k), ((x0 + w1 + w2) * k, y_top * k), ((x0 + w1 + w2) * k, y_bot * k),
             (x0 * k, y_bot * k)], layer="TITLE", close=True)
    sh.text(title, ((x0 + 2) * k, (y_top - _TABLE_ROW + 1.4) * k), height=3.2)
    for i, (name, value) in enumerate(rows):
        y = y_top - (i + 1) * _TABLE_ROW
        sh.line((x0 * k, y * k), ((x0 + w1 + w2) * k, y * k), layer="TITLE")
        sh.text(name, ((x0 + 2) * k, (y - _TABLE_ROW + 1.6) * k), height=2.8)
        sh.text(value, ((x0 + w1 + 2) * k, (y - _TABLE_ROW + 1.6) * k), height=2.8)
    sh.line(((x0 + w1) * k, (y_top - _TABLE_ROW) * k), ((x0 + w1) * k, y_bot * k), layer="TITLE")
    return y_bot


def _title_block(sh: _Sheet, part: WheelPart, material: str, date: str) -> None:
    """ISO 7200-like title block, 180 x 56 paper mm in the lower right corner."""
    k = sh.k
    sw = sh.sheet.width
    x0 = sw - _MARGIN - _TITLE_W
    y0 = _MARGIN
    x1, y1 = sw - _MARGIN, y0 + _TITLE_H
    sh.poly([(x0 * k, y0 * k), (x1 * k, y0 * k), (x1 * k, y1 * k), (x0 * k, y1 * k)], layer="FRAME", close=True)
    rows = [y0 + 14, y0 + 28, y0 + 42]
    for y in rows:
        sh.line((x0 * k, y * k), (x1 * k, y * k), layer="TITLE")
    cols_low = [x0 + 45, x0 + 75, x0 + 110, x0 + 145]
    for x in cols_low:
        sh.line((x * k, y0 * k), (x * k, (y0 + 14) * k), layer="TITLE")
    sh.line(((x0 + 110) * k, (y0 + 28) * k), ((x0 + 110) * k, (y0 + 42) * k), layer="TITLE")

    def cell(label, value, x, y, h=3.5):
        sh.text(label, ((x + 1.5) * k, (y + 10.5) * k), height=2.0)
        sh.text(value, ((x + 1.5) * k, (y + 3.0) * k), height=h)

    cell("Part name", part.title, x0, y0 + 42, h=5.0)
    cell("Chain", part.chain, x0, y0 + 28)
    cell("Teeth / pockets", f"z = {part.teeth}", x0 + 110, y0 + 28)
    cell("Material, heat treatment", material, x0, y0 + 14, h=3.0)
    cell("Scale", sh.sheet.scale_label, x0, y0)
    cell("Units", "mm", x0 + 45, y0)
    cell("Sheet", sh.sheet.name, x0 + 75, y0)
    cell("Date", date, x0 + 110, y0)
    cell("Drawn with", f"chaindrive {_version()}", x0 + 145, y0, h=2.4)


def _frame(sh: _Sheet) -> None:
    k = sh.k
    sw, shh = sh.sheet.width, sh.sheet.height
    sh.poly([(0, 0), (sw * k, 0), (sw * k, shh * k), (0, shh * k)], layer="THIN", close=True)
    sh.poly([(_LEFT * k, _MARGIN * k), ((sw - _MARGIN) * k, _MARGIN * k), ((sw - _MARGIN) * k, (shh - _MARGIN) * k),
             (_LEFT * k, (shh - _MARGIN) * k)], layer="FRAME", close=True)


# --------------------------------------------------------------------------- public
def part_drawing(part: WheelPart, *, date: str | None = None, sheet: Sheet | None = None) -> Any:
    """The ezdxf document of the workshop drawing of a wheel part (model space in mm).

    Parameters
    ----------
    part : WheelPart
        Sprocket or pocket wheel part.
    date : str, optional
        Date of the title block (ISO 8601); default today (UTC).
    sheet : Sheet, optional
        Sheet and scale; default :func:`choose_sheet`.

    Returns
    -------
    ezdxf.document.Drawing

    References
    ----------
    ISO 606:2015 clause 5 (sprocket dimensions and tolerances h11, h14); DIN 6885-1
    (keyway, hub keyway width JS9); ISO 5457 (sheets), ISO 5455 (scales), ISO 7200
    (title block fields), ISO 128 (line types: continuous, dashed hidden, dash-dot centre).

    Examples
    --------
    >>> from chaindrive.geometry import Sprocket
    >>> from chaindrive.geometry.part import sprocket_part
    >>> doc = part_drawing(sprocket_part(Sprocket.from_chain("16B", 19)), date="2026-01-01")
    >>> len(doc.modelspace().query("DIMENSION")) >= 10, doc.audit().has_errors
    (True, False)
    """
    check_part_size(part)  # bounded before anything is drawn (chaindrive.limits)
    if getattr(part, "rim", None) is not None:
        raise InputError("the workshop drawing is of simplex sprockets; a multi-strand rim is a solid only",
                         field="strands")
    try:
        import ezdxf  # noqa: F401
    except ImportError as exc:  # pragma: no cover - depends on install
        raise InputError("DXF drawings need ezdxf: pip install 'chaindrive[cad]'") from exc
    sheet = sheet or choose_sheet(part)
    doc = _setup(sheet)
    sh = _Sheet(doc, sheet)
    k = sh.k
    date = date or _dt.datetime.now(_dt.UTC).date().isoformat()
    _frame(sh)
    _title_block(sh, part, part.material, date)
    x_right = sheet.width - _MARGIN - _TITLE_W
    bottom = _table(sh, _data_rows(part), x_right, sheet.height - _MARGIN - 6.0,
                    "Sprocket data" if part.chamfer is not None else "Pocket wheel data")
    notes = [
        "General tolerances ISO 2768-m; edges deburred.",
        "Bore H7, hub keyway JS9 (DIN 6885-1).",
        "Tooth form and tolerances ISO 606:2015 clause 5." if part.chamfer is not None
        else "Pitch radius: Dolipiński et al. eq. (6).",
    ]
    for i, line in enumerate(notes):
        sh.text(line, ((x_right + 1) * k, (bottom - 7 - 5 * i) * k), height=2.8)
    ra = part.tip_radius * _MM
    cy = (sheet.height / 2 + 6.0) * k
    cx_front = (_LEFT + 40.0) * k + ra
    _front_view(sh, part, (cx_front, cy))
    cx_sec = cx_front + ra + 45.0 * k + part.width * _MM / 2
    _section_view(sh, part, (cx_sec, cy))
    doc.header["$EXTMIN"] = (0, 0, 0)
    doc.header["$EXTMAX"] = (sheet.width * k, sheet.height * k, 0)
    return doc


def write_drawing(part: WheelPart, path: str | os.PathLike[str], *, force: bool = False, option: str = "--dxf",
                  date: str | None = None) -> Drawing:
    """Write the workshop drawing to a DXF file atomically; returns the ezdxf document.

    Parameters
    ----------
    part : WheelPart
        The part.
    path : str or Path
        ``.dxf`` file; an existing file is kept unless ``force``.
    force : bool
        Overwrite an existing file.
    option : str
        Option or field named in error messages.
    date : str, optional
        Title block date.

    Returns
    -------
    ezdxf.document.Drawing

    Examples
    --------
    >>> import tempfile, pathlib
    >>> from chaindrive.geometry import PocketWheel
    >>> from chaindrive.geometry.part import pocket_wheel_part
    >>> f = pathlib.Path(tempfile.mkdtemp()) / "p.dxf"
    >>> _ = write_drawing(pocket_wheel_part(PocketWheel.from_chain("18x64", 8)), f)
    >>> f.is_file()
    True
    """
    check_part_size(part)
    from .._io import check_output_path, save_dxf

    check_output_path(path, (".dxf",), option=option, force=force)
    doc = part_drawing(part, date=date)
    save_dxf(doc, path, option=option, force=force)
    return doc


def render_png(document: Drawing, path: str | os.PathLike[str], *, dpi: int = 150) -> None:
    """Render a drawing's model space to PNG with ezdxf's matplotlib drawing add-on (white paper).

    Parameters
    ----------
    document : ezdxf.document.Drawing
        The drawing.
    path : str or Path
        PNG file.
    dpi : int
        Resolution.

    Examples
    --------
    >>> render_png(doc, "drawing.png")  # doctest: +SKIP
    """
    import matplotlib

    matplotlib.use("Agg", force=False)
    from ezdxf.addons.drawing import matplotlib as dxf_mpl
    from ezdxf.addons.drawing.config import Configuration, LineweightPolicy

    width, height = document.header["$EXTMAX"][0], document.header["$EXTMAX"][1]
    config = Configuration(lineweight_policy=LineweightPolicy.ABSOLUTE, lineweight_scaling=1.0)
    dxf_mpl.qsave(document.modelspace(), str(path), bg="#FFFFFF", fg="#000000", dpi=dpi, config=config,
                  size_inches=(16.0, 16.0 * height / width))


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
