"""The drive drawn to scale as SVG: wheels, spans, wraps, idler, tensioner, guides.

Built from :func:`chaindrive.web.engine.layout_summary` (the exact tangent spans of the
layout), so what is drawn is what is computed. Every text in the SVG is escaped.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any
from xml.sax.saxutils import escape

from ..display import kn_per_m, mm

if TYPE_CHECKING:
    from ..drive.model import Drive

__all__ = ["drive_svg", "workshop_drawing"]

_COLOURS = {"tight": "#c0392b", "slack": "#2471a3", "": "#555"}


def _f(x: float) -> str:
    return f"{x:.2f}"


def _length_text(metres: float, units: str) -> str:
    if units == "imperial":
        return f"{metres / 0.0254:.2f} in"
    return f"{mm(metres):.1f} mm"


def drive_svg(layout: dict[str, Any], drive: Drive, *, units: str = "metric", width: int = 760) -> str:
    """SVG document of the drive (viewBox in mm, y up in the drawing).

    Parameters
    ----------
    layout : dict
        :func:`chaindrive.web.engine.layout_summary` of ``drive``.
    drive : chaindrive.drive.Drive
        For the tensioner and the guides.
    units : {"metric", "imperial"}
        Units of the dimension texts.
    width : int
        Width attribute [px]; the height follows the aspect.

    Returns
    -------
    str

    Examples
    --------
    >>> from chaindrive.drive.project import parse_project, template
    >>> from chaindrive.web.engine import layout_summary
    >>> d = parse_project(template("roller"))
    >>> drive_svg(layout_summary(d), d).startswith("<svg")
    True
    """
    wheels = layout["wheels"]
    xs = [w["centre"][0] for w in wheels]
    ys = [w["centre"][1] for w in wheels]
    rmax = max(w["radius"] for w in wheels)
    x0, x1 = min(xs) - rmax, max(xs) + rmax
    y0, y1 = min(ys) - rmax, max(ys) + rmax
    span = max(x1 - x0, y1 - y0)
    pad = 0.12 * span + 0.02
    scale = mm(span)
    stroke = max(scale / 400, 0.3)
    font = max(scale / 42, 2.0)
    x0, x1, y0, y1 = (mm(v) for v in (x0 - pad, x1 + pad, y0 - pad, y1 + 0.6 * pad))
    y1 = max(y1, mm(max(w["centre"][1] + w["radius"] for w in wheels)) + 4.5 * font)
    w_mm, h_mm = x1 - x0, y1 - y0
    height = int(width * h_mm / w_mm)
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="{_f(x0)} {_f(-y1)} {_f(w_mm)} {_f(h_mm)}" '
           f'width="{width}" height="{height}" role="img" aria-label="drive drawn to scale" '
           f'font-family="DejaVu Sans, Arial, sans-serif">',
           f'<rect x="{_f(x0)}" y="{_f(-y1)}" width="{_f(w_mm)}" height="{_f(h_mm)}" fill="#fbfcfe"/>']
    # wheels
    for w in wheels:
        cx, cy = mm(w["centre"][0]), -mm(w["centre"][1])
        r = mm(w["radius"])
        idler = w["kind"] == "idler"
        fill = "#e8ecf2" if not idler else "#f4efe4"
        edge = "#34495e" if not idler else "#9a7d46"
        out.append(f'<circle class="wheel" cx="{_f(cx)}" cy="{_f(cy)}" r="{_f(r * 0.93)}" fill="{fill}" '
                   f'stroke="{edge}" stroke-width="{_f(stroke)}"/>')
        out.append(f'<circle cx="{_f(cx)}" cy="{_f(cy)}" r="{_f(r)}" fill="none" stroke="{edge}" '
                   f'stroke-width="{_f(stroke * 0.6)}" stroke-dasharray="{_f(stroke * 6)} {_f(stroke * 3)}"/>')
        teeth = w["teeth"]
        if teeth:
            step = 2 * math.pi / teeth
            ticks = []
            for k in range(teeth):
                a = k * step
                ticks.append(f"M{_f(cx + 0.93 * r * math.cos(a))} {_f(cy - 0.93 * r * math.sin(a))}"
                             f"L{_f(cx + 1.06 * r * math.cos(a))} {_f(cy - 1.06 * r * math.sin(a))}")
            out.append(f'<path d="{" ".join(ticks)}" stroke="{edge}" stroke-width="{_f(stroke * 1.4)}"/>')
        out.append(f'<circle cx="{_f(cx)}" cy="{_f(cy)}" r="{_f(max(r * 0.12, stroke * 2))}" fill="{edge}"/>')
        label = f"{w['name']}" + (f" z={teeth}" if teeth else "")
        if w["driving"] and w["name"] != "driving":
            label += " (driving)"
        out.append(f'<text x="{_f(cx)}" y="{_f(cy + r + 1.6 * font)}" font-size="{_f(font)}" '
                   f'text-anchor="middle" fill="#222">{escape(label)}</text>')
    # wraps (arcs on the pitch circles from the arriving span to the leaving span)
    n = len(wheels)
    spans = layout["spans"]
    for i, w in enumerate(wheels):
        start = spans[(i - 1) % n]["end"]
        end = spans[i]["start"]
        r = mm(w["radius"])
        large = 1 if w["wrap"] > math.pi else 0
        sweep = 0 if w["side"] > 0 else 1  # y flipped: counter-clockwise is SVG sweep 0
        out.append(f'<path d="M{_f(mm(start[0]))} {_f(-mm(start[1]))} A{_f(r)} {_f(r)} 0 {large} {sweep} '
                   f'{_f(mm(end[0]))} {_f(-mm(end[1]))}" fill="none" stroke="#555" '
                   f'stroke-width="{_f(stroke * 2.2)}"/>')
    # spans
    for s in spans:
        colour = _COLOURS.get(s["role"], "#555")
        out.append(f'<line class="span {escape(s["role"])}" x1="{_f(mm(s["start"][0]))}" y1="{_f(-mm(s["start"][1]))}" '
                   f'x2="{_f(mm(s["end"][0]))}" y2="{_f(-mm(s["end"][1]))}" stroke="{colour}" '
                   f'stroke-width="{_f(stroke * 2.6)}"/>')
        if s["role"]:
            mx = mm((s["start"][0] + s["end"][0]) / 2)
            my = -mm((s["start"][1] + s["end"][1]) / 2)
            out.append(f'<text x="{_f(mx)}" y="{_f(my - 0.6 * font)}" font-size="{_f(font * 0.85)}" '
                       f'text-anchor="middle" fill="{colour}">{escape(s["role"])} span</text>')
    # tensioner: arrow along its travel from the idler centre
    t = drive.tensioner
    if t is not None:
        w = next(w for w in wheels if w["name"] == t.wheel)
        dx, dy = t.direction
        norm = math.hypot(dx, dy) or 1.0
        dx, dy = dx / norm, dy / norm
        cx, cy = mm(w["centre"][0]), mm(w["centre"][1])
        r = mm(w["radius"])
        length = max(0.08 * scale, 2.5 * r)
        ax0, ay0 = cx + dx * r * 1.2, cy + dy * r * 1.2
        ax1, ay1 = ax0 + dx * length, ay0 + dy * length
        hx, hy = -dy * length * 0.12, dx * length * 0.12
        out.append(f'<g class="tensioner" stroke="#8e44ad" fill="#8e44ad" stroke-width="{_f(stroke * 1.6)}">'
                   f'<line x1="{_f(ax1)}" y1="{_f(-ay1)}" x2="{_f(ax0)}" y2="{_f(-ay0)}"/>'
                   f'<path d="M{_f(ax0)} {_f(-ay0)} L{_f(ax0 + dx * length * 0.25 + hx)} {_f(-(ay0 + dy * length * 0.25 + hy))} '
                   f'L{_f(ax0 + dx * length * 0.25 - hx)} {_f(-(ay0 + dy * length * 0.25 - hy))} Z"/></g>')
        out.append(f'<text x="{_f(ax1 + font * 0.5)}" y="{_f(-ay1)}" font-size="{_f(font * 0.85)}" fill="#8e44ad">'
                   f'tensioner {t.mass:g} kg, {kn_per_m(t.stiffness):g} kN/m</text>')
    # guides: a bar along the span arriving at the guided wheel, from its end at l outwards
    for g in drive.guides:
        gi = next((k for k, w in enumerate(wheels) if w["name"] == g.wheel), None)
        if gi is None:
            continue
        s = spans[(gi - 1) % n] if drive.travel == "ccw" else spans[gi]
        c = wheels[gi]["centre"]
        a, b = (s["end"], s["start"]) if drive.travel == "ccw" else (s["start"], s["end"])
        ux, uy = b[0] - a[0], b[1] - a[1]
        norm = math.hypot(ux, uy) or 1.0
        ux, uy = ux / norm, uy / norm
        # the point of the span at distance l from the wheel axis (beyond the tangent point)
        along = math.sqrt(max(g.end_distance**2 - wheels[gi]["radius"] ** 2, 0.0))
        px, py = a[0] + ux * along, a[1] + uy * along
        qx, qy = px + ux * 1.5 * g.end_distance, py + uy * 1.5 * g.end_distance
        nx, ny = -uy, ux
        off = 0.012 * span * (1 if (px - c[0]) * nx + (py - c[1]) * ny > 0 else -1)
        out.append(f'<line class="guide" x1="{_f(mm(px + nx * off))}" y1="{_f(-mm(py + ny * off))}" '
                   f'x2="{_f(mm(qx + nx * off))}" y2="{_f(-mm(qy + ny * off))}" stroke="#16a085" '
                   f'stroke-width="{_f(stroke * 4)}" stroke-linecap="round"/>')
        out.append(f'<text x="{_f(mm(qx))}" y="{_f(-mm(qy + ny * off * 3))}" font-size="{_f(font * 0.85)}" '
                   f'fill="#16a085">{escape(g.kind)} guide, l = {escape(_length_text(g.end_distance, units))}</text>')
    # centre distance dimension between the driving wheel and the first other non-idler
    main = [w for w in wheels if w["kind"] != "idler"]
    if len(main) >= 2:
        a, b = main[0]["centre"], main[1]["centre"]
        ymax = mm(max(w["centre"][1] + w["radius"] for w in wheels)) + 2.2 * font
        dist = math.hypot(b[0] - a[0], b[1] - a[1])
        out.append(f'<g stroke="#444" stroke-width="{_f(stroke * 0.8)}">'
                   f'<line x1="{_f(mm(a[0]))}" y1="{_f(-ymax)}" x2="{_f(mm(b[0]))}" y2="{_f(-ymax)}"/>'
                   f'<line x1="{_f(mm(a[0]))}" y1="{_f(-ymax - font * 0.5)}" x2="{_f(mm(a[0]))}" y2="{_f(-ymax + font * 0.5)}"/>'
                   f'<line x1="{_f(mm(b[0]))}" y1="{_f(-ymax - font * 0.5)}" x2="{_f(mm(b[0]))}" y2="{_f(-ymax + font * 0.5)}"/></g>')
        out.append(f'<text class="centre-distance" x="{_f(mm((a[0] + b[0]) / 2))}" y="{_f(-ymax - 0.5 * font)}" '
                   f'font-size="{_f(font)}" text-anchor="middle" fill="#222">C = {escape(_length_text(dist, units))}, '
                   f'{layout["links"]} links</text>')
    out.append("</svg>")
    return "".join(out)


def workshop_drawing(wheel: Any) -> bytes:
    """The workshop drawing of a sprocket or a pocket wheel as DXF (what ``chaindrive
    sprocket --dxf`` / ``pocket-wheel --dxf`` write: views, bore, keyway, tables, title block)."""
    import io

    from ..geometry import PocketWheel
    from ..geometry.drawing import part_drawing
    from ..geometry.part import pocket_wheel_part, sprocket_part

    part = pocket_wheel_part(wheel) if isinstance(wheel, PocketWheel) else sprocket_part(wheel)
    buf = io.StringIO()
    part_drawing(part).write(buf)
    return buf.getvalue().encode("utf-8")
