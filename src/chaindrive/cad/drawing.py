"""The assembly as a 2-D drawing (DXF, millimetres, layers): the view along the wheels' axes.

Each wheel's face outline (lines and exact arcs as bulges, :mod:`chaindrive.geometry.outline`)
turned to its assembled angle and moved to its centre; the chain as it lies at the
assembly: roller chains the outer and inner plates (slots round the joints) and the
rollers, round link chains the vertical links (outer and inner stadium) and the
horizontal links seen edge-on (a rectangle ``t + 2d`` by ``d``); the guides' rails and
the tensioner's slide. Every contour is one closed LWPOLYLINE (or a CIRCLE).

Layers: ``WHEELS``, ``PITCH_CIRCLES``, ``CHAIN_PLATES``, ``CHAIN_ROLLERS``, ``CHAIN_LINKS``,
``GUIDES``, ``TENSIONER``, ``TEXT``.
"""

from __future__ import annotations

import math
import os
from pathlib import Path
from typing import Any

import numpy as np

from ..geometry.export import new_dxf_document
from .assembly import DriveAssembly

__all__ = ["assembly_document", "write_dxf", "contour_gaps", "LAYERS"]

_MM = 1e3
#: Layers and their colours (AutoCAD colour index).
LAYERS = {"WHEELS": 7, "PITCH_CIRCLES": 1, "CHAIN_PLATES": 5, "CHAIN_ROLLERS": 8, "CHAIN_LINKS": 5,
          "GUIDES": 3, "TENSIONER": 6, "TEXT": 7}


def _xy(matrix: np.ndarray, points: np.ndarray) -> np.ndarray:
    m = np.asarray(matrix)
    return (np.asarray(points) @ m[:2, :2].T + m[:2, 3]) * _MM


def _slot(length: float, radius: float) -> list[tuple[float, float, float]]:
    """Closed slot round (0, 0) and (length, 0), radius ``radius`` [m], as (x, y, bulge) [m]."""
    return [(0.0, -radius, 0.0), (length, -radius, 1.0), (length, radius, 0.0), (0.0, radius, 1.0)]


def _rectangle(x0: float, y0: float, x1: float, y1: float) -> list[tuple[float, float, float]]:
    return [(x0, y0, 0.0), (x1, y0, 0.0), (x1, y1, 0.0), (x0, y1, 0.0)]


def _polyline(msp: Any, matrix: np.ndarray, verts: list[tuple[float, float, float]], layer: str) -> None:
    pts = _xy(matrix, np.array([v[:2] for v in verts]))
    msp.add_lwpolyline([(x, y, b) for (x, y), (_, _, b) in zip(pts, verts, strict=True)], format="xyb",
                       close=True, dxfattribs={"layer": layer})


def assembly_document(assembly: DriveAssembly) -> Any:
    """The ezdxf document of the assembly's view along the axes (mm).

    Examples
    --------
    >>> # assembly_document(drive_assembly(drive)).audit().has_errors
    False
    """
    doc = new_dxf_document()
    for name, colour in LAYERS.items():
        doc.layers.add(name, color=colour)
    doc.layers.get("PITCH_CIRCLES").dxf.linetype = "CENTER"
    msp = doc.modelspace()
    for part in assembly.parts:
        spec = assembly.shapes[part.shape]
        m = np.asarray(part.matrix)
        centre = tuple(m[:2, 3] * _MM)
        if spec.kind == "wheel":
            outline = spec.data.outline
            verts = [(prim.start[0], prim.start[1], prim.bulge) for prim in outline.primitives]
            _polyline(msp, m, verts, "WHEELS")
            msp.add_circle(centre, outline.pitch_radius * _MM, dxfattribs={"layer": "PITCH_CIRCLES"})
            msp.add_circle(centre, spec.data.hub.bore / 2 * _MM, dxfattribs={"layer": "WHEELS"})
        elif spec.kind == "disc":
            msp.add_circle(centre, spec.data[0] / 2 * _MM, dxfattribs={"layer": "WHEELS"})
        elif spec.kind == "chain part":
            dims, name = spec.data
            if name in ("outer plate", "inner plate") and m[2, 3] > 0:  # the plates on the +z side
                height = dims.outer_plate_height if name == "outer plate" else dims.plate_height
                _polyline(msp, m, _slot(dims.pitch, height / 2), "CHAIN_PLATES")
            elif name == "roller":
                msp.add_circle(centre, dims.roller_diameter / 2 * _MM, dxfattribs={"layer": "CHAIN_ROLLERS"})
        elif spec.kind == "round link":
            d, b, t = spec.data.bar_diameter, spec.data.inner_width, spec.data.pitch
            half = (t - b) / 2
            if abs(m[2, 1]) > 0.5:  # upright (horizontal link, flat on the pockets): seen edge-on
                _polyline(msp, m, _rectangle(-half - (b / 2 + d), -d / 2, half + b / 2 + d, d / 2), "CHAIN_LINKS")
            else:
                for r in (b / 2 + d, b / 2):
                    verts = [(v[0] - half, v[1], v[2]) for v in _slot(2 * half, r)]
                    _polyline(msp, m, verts, "CHAIN_LINKS")
        elif spec.kind == "box":
            length, height, _, x0, y0 = spec.data
            layer = "GUIDES" if part.group == "guides" else "TENSIONER"
            _polyline(msp, m, _rectangle(x0, y0, x0 + length, y0 + height), layer)
    xs = [p.matrix[0, 3] for p in assembly.parts]
    ys = [p.matrix[1, 3] for p in assembly.parts]
    h = max(0.015 * (max(xs) - min(xs) + max(ys) - min(ys)), 0.005) * _MM
    msp.add_text(assembly.title, height=h, dxfattribs={"layer": "TEXT"}).set_placement(
        (min(xs) * _MM, min(ys) * _MM - 0.25 * _MM - 2 * h))
    return doc


def write_dxf(assembly: DriveAssembly, path: str | os.PathLike[str], *, force: bool = False,
              option: str = "--dxf") -> Path:
    """Write the assembly's view to a DXF file (mm) atomically; refused if it exists unless ``force``.

    Examples
    --------
    >>> # write_dxf(drive_assembly(drive), "drive.dxf")
    """
    from .._io import save_dxf

    return save_dxf(assembly_document(assembly), path, option=option, force=force)


def contour_gaps(assembly: DriveAssembly) -> float:
    """Largest gap [m] between consecutive primitives of the wheels' outlines (0 for closed
    contours; the drawing's polylines are closed by construction).

    Examples
    --------
    >>> # contour_gaps(drive_assembly(drive)) <= 1e-9
    """
    gap = 0.0
    for spec in assembly.shapes.values():
        if spec.kind != "wheel":
            continue
        prims = spec.data.outline.primitives
        for a, b in zip(prims, prims[1:] + prims[:1], strict=True):
            gap = max(gap, math.hypot(b.start[0] - a.end[0], b.start[1] - a.end[1]))
    return gap
