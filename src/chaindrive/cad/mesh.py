"""The assembly as triangle meshes: a glTF 2.0 binary file (``.glb``) and an interactive view.

Each distinct shape is tessellated once (OpenCascade ``BRepMesh_IncrementalMesh``); the
glTF file holds one mesh per distinct shape and one named node per part with its
placement matrix (metres, the glTF unit) and the part's numbers in ``extras``, so a viewer
draws copies. :func:`view_figure` builds the plotly figure of the same meshes (one
``mesh3d`` trace per distinct shape, its copies merged), shown by the studio's 3-D view
and in notebooks: rotate, zoom, click a part to read its numbers.
"""

from __future__ import annotations

import json
import os
import struct
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from .assembly import DriveAssembly
from .build import build_shapes, colour_of

__all__ = ["Mesh", "tessellate", "glb_bytes", "write_gltf", "view_figure", "GLTF_SUFFIXES"]

_MM = 1e3
#: Extensions accepted for glTF files (binary glTF).
GLTF_SUFFIXES = (".glb",)


@dataclass(frozen=True)
class Mesh:
    """Triangles of one distinct shape in its own frame: vertices (V, 3) [m], faces (F, 3) indices."""

    vertices: np.ndarray
    faces: np.ndarray


def _mesh_of(shape: Any) -> Mesh:
    from OCP.Bnd import Bnd_Box
    from OCP.BRep import BRep_Tool
    from OCP.BRepBndLib import BRepBndLib
    from OCP.BRepMesh import BRepMesh_IncrementalMesh
    from OCP.TopAbs import TopAbs_FACE, TopAbs_REVERSED
    from OCP.TopExp import TopExp_Explorer
    from OCP.TopLoc import TopLoc_Location
    from OCP.TopoDS import TopoDS

    box = Bnd_Box()
    BRepBndLib.Add_s(shape, box)
    lo, hi = box.CornerMin(), box.CornerMax()
    size = float(np.linalg.norm([hi.X() - lo.X(), hi.Y() - lo.Y(), hi.Z() - lo.Z()]))
    BRepMesh_IncrementalMesh(shape, max(0.05, 0.006 * size), False, 0.5, True)
    verts, faces = [], []
    offset = 0
    exp = TopExp_Explorer(shape, TopAbs_FACE)
    while exp.More():
        face = TopoDS.Face(exp.Current()) if hasattr(TopoDS, "Face") else TopoDS.Face_s(exp.Current())
        loc = TopLoc_Location()
        tri = BRep_Tool.Triangulation_s(face, loc)
        if tri is not None:
            trsf = loc.Transformation()
            pts = np.array([[p.X(), p.Y(), p.Z()] for p in
                            (tri.Node(i).Transformed(trsf) for i in range(1, tri.NbNodes() + 1))])
            tris = np.array([tri.Triangle(i).Get() for i in range(1, tri.NbTriangles() + 1)], dtype=np.int64) - 1
            if face.Orientation() == TopAbs_REVERSED:
                tris = tris[:, [0, 2, 1]]
            verts.append(pts)
            faces.append(tris + offset)
            offset += len(pts)
        exp.Next()
    v = np.concatenate(verts) / _MM if verts else np.zeros((0, 3))
    f = np.concatenate(faces) if faces else np.zeros((0, 3), np.int64)
    return Mesh(vertices=v, faces=f)


def tessellate(assembly: DriveAssembly, shapes: dict[str, Any] | None = None) -> dict[str, Mesh]:
    """Mesh of each distinct shape (built here when ``shapes`` is not given).

    Examples
    --------
    >>> # tessellate(drive_assembly(drive))["roller"].faces.shape[1]
    """
    shapes = build_shapes(assembly) if shapes is None else shapes
    return {key: _mesh_of(shape) for key, shape in shapes.items()}


def _pad(data: bytes, fill: bytes = b"\x00") -> bytes:
    return data + fill * ((4 - len(data) % 4) % 4)


def glb_bytes(assembly: DriveAssembly, meshes: dict[str, Mesh]) -> bytes:
    """The binary glTF 2.0 of the assembly: a mesh per distinct shape, a node per part.

    Examples
    --------
    >>> # glb_bytes(a, tessellate(a))[:4] == b"glTF"
    """
    keys = list(meshes)
    blob = bytearray()
    views, accessors, gl_meshes, materials = [], [], [], []
    for n, key in enumerate(keys):
        mesh = meshes[key]
        v = mesh.vertices.astype(np.float32)
        f = mesh.faces.astype(np.uint32)
        for arr, target in ((v, 34962), (f, 34963)):
            views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": arr.nbytes, "target": target})
            blob += _pad(arr.tobytes())
        accessors.append({"bufferView": 2 * n, "componentType": 5126, "count": len(v), "type": "VEC3",
                          "min": v.min(axis=0).tolist() if len(v) else [0, 0, 0],
                          "max": v.max(axis=0).tolist() if len(v) else [0, 0, 0]})
        accessors.append({"bufferView": 2 * n + 1, "componentType": 5125, "count": int(f.size), "type": "SCALAR"})
        r, g, b = colour_of(assembly.shapes[key])
        materials.append({"name": key, "pbrMetallicRoughness": {"baseColorFactor": [r, g, b, 1.0],
                                                                "metallicFactor": 0.6, "roughnessFactor": 0.5}})
        gl_meshes.append({"name": key, "primitives": [{"attributes": {"POSITION": 2 * n}, "indices": 2 * n + 1,
                                                       "material": n}]})
    index = {key: n for n, key in enumerate(keys)}
    nodes = [{"name": p.name, "mesh": index[p.shape], "matrix": np.asarray(p.matrix).T.reshape(-1).tolist(),
              "extras": _jsonable(p.info)} for p in assembly.parts]
    gltf = {"asset": {"version": "2.0", "generator": "chaindrive"},
            "scene": 0, "scenes": [{"name": assembly.title, "nodes": list(range(len(nodes)))}],
            "nodes": nodes, "meshes": gl_meshes, "materials": materials, "accessors": accessors,
            "bufferViews": views, "buffers": [{"byteLength": len(blob)}]}
    text = _pad(json.dumps(gltf, separators=(",", ":")).encode("utf-8"), b" ")
    body = bytes(blob)
    total = 12 + 8 + len(text) + 8 + len(body)
    return (struct.pack("<4sII", b"glTF", 2, total) + struct.pack("<I4s", len(text), b"JSON") + text
            + struct.pack("<I4s", len(body), b"BIN\x00") + body)


def _jsonable(info: dict) -> dict:
    out = {}
    for k, v in info.items():
        if isinstance(v, (np.floating, np.integer)):
            v = v.item()
        out[k] = v
    return out


def write_gltf(assembly: DriveAssembly, path: str | os.PathLike[str], *, force: bool = False,
               option: str = "--gltf", meshes: dict[str, Mesh] | None = None) -> Path:
    """Write the assembly as binary glTF (``.glb``, metres) atomically.

    Examples
    --------
    >>> # write_gltf(drive_assembly(drive), "drive.glb")
    """
    from .._io import atomic_write_bytes, check_output_path

    check_output_path(path, GLTF_SUFFIXES, option=option, force=force)
    meshes = tessellate(assembly) if meshes is None else meshes
    atomic_write_bytes(path, glb_bytes(assembly, meshes), force=force, option=option)
    return Path(path)


def _fmt(key: str, value: Any) -> str:
    """A part's number for the view: metres as mm, newtons as kN (the unit is in the key)."""
    from ..display import convert

    if isinstance(value, float) and key.endswith("]"):
        name, unit = key[:-1].rsplit(" [", 1)
        shown_value, shown = convert(value, unit)
        return f"{name} [{shown}]: {shown_value:.4g}"
    if isinstance(value, float):
        return f"{key}: {value:.4g}"
    return f"{key}: {value}"


def view_figure(assembly: DriveAssembly, meshes: dict[str, Mesh] | None = None, *,
                max_triangles: int = 3_000_000) -> dict:
    """The plotly figure (as a dict) of the assembly: one ``mesh3d`` trace per distinct shape.

    Each trace's ``meta`` holds ``verts`` (vertices per copy) and ``parts`` (the text of
    each copy's numbers), so a click on vertex ``i`` shows ``parts[i // verts]``.

    Raises
    ------
    InputError
        More than ``max_triangles`` triangles (export a section of the chain).

    Examples
    --------
    >>> # view_figure(drive_assembly(drive))["data"][0]["type"]
    'mesh3d'
    """
    from ..errors import InputError

    meshes = tessellate(assembly) if meshes is None else meshes
    by_shape: dict[str, list[Any]] = {}
    for p in assembly.parts:
        by_shape.setdefault(p.shape, []).append(p)
    total = sum(len(meshes[k].faces) * len(v) for k, v in by_shape.items())
    if total > max_triangles:
        raise InputError(f"the 3-D view would have {total} triangles, more than {max_triangles}; view a section "
                         "of the chain (--links FIRST:COUNT)", field="links")
    traces = []
    for key, parts in by_shape.items():
        mesh = meshes[key]
        nv = len(mesh.vertices)
        homo = np.c_[mesh.vertices, np.ones(nv)]
        xyz = np.concatenate([(homo @ np.asarray(p.matrix).T)[:, :3] for p in parts])
        faces = np.concatenate([mesh.faces + k * nv for k in range(len(parts))])
        r, g, b = colour_of(assembly.shapes[key])
        texts = ["<b>" + p.name + "</b><br>" + "<br>".join(_fmt(k, v) for k, v in p.info.items()) for p in parts]
        traces.append({
            "type": "mesh3d", "name": key, "x": (xyz[:, 0] * _MM).round(2).tolist(),
            "y": (xyz[:, 1] * _MM).round(2).tolist(), "z": (xyz[:, 2] * _MM).round(2).tolist(),
            "i": faces[:, 0].tolist(), "j": faces[:, 1].tolist(), "k": faces[:, 2].tolist(),
            "color": f"rgb({int(r * 255)},{int(g * 255)},{int(b * 255)})", "flatshading": False,
            "lighting": {"ambient": 0.45, "diffuse": 0.8, "specular": 0.3, "roughness": 0.5},
            "hoverinfo": "name", "showlegend": True, "meta": {"verts": nv, "parts": texts},
        })
    axis = {"title": {"text": "{} [mm]"}, "showbackground": False}
    lo = np.min([np.min(t["x"]) for t in traces]), np.min([np.min(t["y"]) for t in traces]), \
        np.min([np.min(t["z"]) for t in traces])
    hi = np.max([np.max(t["x"]) for t in traces]), np.max([np.max(t["y"]) for t in traces]), \
        np.max([np.max(t["z"]) for t in traces])
    ext = np.maximum(np.subtract(hi, lo), 1e-9)
    ratio = ext / ext.max()
    layout = {"title": {"text": assembly.title}, "margin": {"l": 0, "r": 0, "t": 40, "b": 0},
              "scene": {"aspectmode": "manual", "aspectratio": dict(zip("xyz", ratio.round(4).tolist(), strict=True)),
                        "xaxis": {**axis, "title": {"text": "x [mm]"}},
                        "yaxis": {**axis, "title": {"text": "y [mm]"}}, "zaxis": {**axis, "title": {"text": "z [mm]"}},
                        "camera": {"eye": {"x": 0.1, "y": -0.65, "z": 0.65}}},
              "legend": {"itemclick": "toggle"}}
    return {"data": traces, "layout": layout}


def figure(assembly: DriveAssembly, meshes: dict[str, Mesh] | None = None) -> Any:
    """The view as a ``plotly.graph_objects.Figure`` (notebooks: display it; a click shows a
    part's numbers in the studio, a hover its name here).

    Examples
    --------
    >>> # figure(drive_assembly(drive)).show()
    """
    import plotly.graph_objects as go

    fig = view_figure(assembly, meshes)
    for trace in fig["data"]:
        trace["hovertext"] = None
    return go.Figure(fig)


