"""Export of :class:`~chaindrive.geometry.outline.Outline` to DXF (ezdxf) and SVG, in millimetres.

DXF layout (units mm, ``$INSUNITS = 4``):

* ``OUTLINE``: the wheel contour as one closed LWPOLYLINE; arcs are exact (bulges).
* ``PITCH_CIRCLE``: the pitch circle (CIRCLE, linetype CENTER).
* ``CENTRES``: one POINT per roller seat / pin / pocket centre.
* one CIRCLE layer per reference circle of the outline (``ROOT``, ``TIP``, ``SLOT`` ...).
* ``TEXT``: the title.

ezdxf is an optional dependency (``pip install 'chaindrive[cad]'``).
"""

from __future__ import annotations

import math
import os
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from ..errors import InputError
from .outline import Arc, Outline

if TYPE_CHECKING:
    from ezdxf.document import Drawing

__all__ = ["outline_to_dxf", "outline_to_svg", "dxf_document", "svg_text"]

_MM = 1e3
_LAYER_COLOURS = {"OUTLINE": 7, "PITCH_CIRCLE": 1, "CENTRES": 3, "ROOT": 8, "TIP": 8, "SLOT": 5, "TEXT": 7}


def _bulge_vertices(outline: Outline) -> list[tuple[float, float, float]]:
    verts = []
    for prim in outline.primitives:
        x, y = prim.start
        verts.append((x * _MM, y * _MM, prim.bulge))
    return verts


def new_dxf_document() -> Drawing:
    """An empty DXF document (R2010) in millimetres, metric header; ezdxf is required.

    Raises
    ------
    InputError
        ezdxf is not installed (the ``cad`` extra).
    """
    try:
        import ezdxf
    except ImportError as exc:  # pragma: no cover - depends on install
        raise InputError("DXF export needs ezdxf: pip install 'chaindrive[cad]'") from exc
    doc = ezdxf.new("R2010", setup=True)
    doc.units = ezdxf.units.MM
    doc.header["$MEASUREMENT"] = 1
    return doc


def dxf_document(outline: Outline, title: str = "") -> Drawing:
    """Build the ezdxf document of an outline (mm).

    Examples
    --------
    >>> from chaindrive.geometry.sprocket import sprocket_outline
    >>> doc = dxf_document(sprocket_outline(0.0254, 19, 0.01588))
    >>> [e.dxftype() for e in doc.modelspace()][:2]
    ['LWPOLYLINE', 'CIRCLE']
    """
    doc = new_dxf_document()
    layers = ["OUTLINE", "PITCH_CIRCLE", "CENTRES", *outline.circles.keys(), "TEXT"]
    for name in layers:
        if name not in doc.layers:
            doc.layers.add(name, color=_LAYER_COLOURS.get(name, 7))
    doc.layers.get("PITCH_CIRCLE").dxf.linetype = "CENTER"
    msp = doc.modelspace()
    msp.add_lwpolyline(_bulge_vertices(outline), format="xyb", close=True, dxfattribs={"layer": "OUTLINE"})
    msp.add_circle((0.0, 0.0), outline.pitch_radius * _MM, dxfattribs={"layer": "PITCH_CIRCLE"})
    for name, radius in outline.circles.items():
        msp.add_circle((0.0, 0.0), float(radius) * _MM, dxfattribs={"layer": name})
    for cx, cy in np.asarray(outline.centres):
        msp.add_point((cx * _MM, cy * _MM), dxfattribs={"layer": "CENTRES"})
    if title:
        xmin, ymin, xmax, ymax = outline.extents()
        h = 0.04 * (ymax - ymin) * _MM
        msp.add_text(title, height=h, dxfattribs={"layer": "TEXT"}).set_placement(
            (xmin * _MM, ymin * _MM - 1.8 * h)
        )
    return doc


def outline_to_dxf(outline: Outline, path: str | os.PathLike[str], title: str = "") -> Drawing:
    """Write ``outline`` to the DXF file ``path`` (mm) and return the ezdxf document.

    The document passes ezdxf's ``audit()`` without errors (checked in the tests).
    """
    doc = dxf_document(outline, title)
    doc.saveas(str(Path(path)))
    return doc


def _svg_path(outline: Outline) -> str:
    x0, y0 = outline.primitives[0].start
    parts = [f"M {x0 * _MM:.5f} {-y0 * _MM:.5f}"]
    for prim in outline.primitives:
        x, y = prim.end
        if isinstance(prim, Arc):
            r = prim.radius * _MM
            large = 1 if abs(prim.sweep) > math.pi else 0
            sweep = 0 if prim.sweep > 0 else 1  # y is flipped: math CCW is SVG negative-angle
            parts.append(f"A {r:.5f} {r:.5f} 0 {large} {sweep} {x * _MM:.5f} {-y * _MM:.5f}")
        else:
            parts.append(f"L {x * _MM:.5f} {-y * _MM:.5f}")
    parts.append("Z")
    return " ".join(parts)


def svg_text(outline: Outline, title: str = "") -> str:
    """SVG document of an outline: viewBox and size in mm, y axis pointing up in the drawing.

    Examples
    --------
    >>> from chaindrive.geometry.sprocket import sprocket_outline
    >>> svg_text(sprocket_outline(0.0254, 19, 0.01588)).startswith('<?xml')
    True
    """
    xmin, ymin, xmax, ymax = outline.extents()
    rmax = max(outline.pitch_radius, *(abs(v) for v in (xmin, ymin, xmax, ymax)))
    margin = 0.08 * rmax
    lo = -(rmax + margin) * _MM
    size = 2 * (rmax + margin) * _MM
    text_h = 0.05 * size if title else 0.0
    stroke = size / 600.0
    out = [
        '<?xml version="1.0" encoding="UTF-8"?>',
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{size:.3f}mm" height="{size + text_h:.3f}mm" '
        f'viewBox="{lo:.3f} {lo:.3f} {size:.3f} {size + text_h:.3f}">',
        f"<title>{_esc(title)}</title>",
        f'<rect x="{lo:.3f}" y="{lo:.3f}" width="{size:.3f}" height="{size + text_h:.3f}" fill="white"/>',
        f'<g id="OUTLINE"><path d="{_svg_path(outline)}" fill="#d9e3ef" stroke="black" '
        f'stroke-width="{stroke:.4f}" fill-rule="evenodd"/></g>',
        f'<g id="PITCH_CIRCLE"><circle cx="0" cy="0" r="{outline.pitch_radius * _MM:.5f}" fill="none" '
        f'stroke="red" stroke-width="{stroke * 0.7:.4f}" stroke-dasharray="{6 * stroke:.3f} '
        f'{2 * stroke:.3f} {stroke:.3f} {2 * stroke:.3f}"/></g>',
    ]
    for name, radius in outline.circles.items():
        out.append(
            f'<g id="{_esc(name)}"><circle cx="0" cy="0" r="{float(radius) * _MM:.5f}" fill="none" '
            f'stroke="grey" stroke-width="{stroke * 0.5:.4f}" stroke-dasharray="{3 * stroke:.3f} {2 * stroke:.3f}"/></g>'
        )
    dots = "".join(
        f'<circle cx="{cx * _MM:.5f}" cy="{-cy * _MM:.5f}" r="{1.5 * stroke:.4f}" fill="green"/>'
        for cx, cy in np.asarray(outline.centres)
    )
    out.append(f'<g id="CENTRES">{dots}</g>')
    if title:
        out.append(
            f'<text x="{lo + margin * _MM * 0.3:.3f}" y="{lo + size + 0.7 * text_h:.3f}" '
            f'font-family="sans-serif" font-size="{0.6 * text_h:.3f}">{_esc(title)}</text>'
        )
    out.append("</svg>")
    return "\n".join(out) + "\n"


def outline_to_svg(outline: Outline, path: str | os.PathLike[str], title: str = "") -> str:
    """Write ``outline`` to the SVG file ``path`` (viewBox in mm); returns the text."""
    text = svg_text(outline, title)
    Path(path).write_text(text, encoding="utf-8")
    return text


def _esc(s: str) -> str:
    return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace('"', "&quot;")
