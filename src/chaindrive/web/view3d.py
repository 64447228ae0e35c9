"""The studio's 3-D view of the drive and its CAD downloads (:mod:`chaindrive.cad`).

Routes (the state is the studio's query string):

* ``GET /view3d`` the page: the assembly drawn with plotly's ``mesh3d`` (served by the
  app, nothing from the internet); drag to rotate, scroll to zoom, click a part to read its
  numbers;
* ``GET /api/view3d`` the figure as JSON;
* ``GET /download3d/{drive.step, drive.glb}`` the STEP assembly and the binary glTF.

The assembly of a project is built once and kept (the wheels' solids take seconds).
"""

from __future__ import annotations

import asyncio
import threading
from collections import OrderedDict
from typing import Any

from fastapi import APIRouter, Request
from fastapi.responses import HTMLResponse, JSONResponse, Response

from .design import normalise_state

__all__ = ["router", "view_payload", "cad_download"]

#: Downloads of the 3-D model.
CAD_DOWNLOADS = {"drive.step": "The drive as a STEP assembly (mm): wheels, links, guides, tensioner",
                 "drive.glb": "The same model as binary glTF (m)"}

_CACHE: OrderedDict[str, Any] = OrderedDict()
#: One model built at a time (OpenCascade work is CPU-bound; the rest of the app stays free).
_BUILD = threading.Lock()


def _model(state: dict[str, str]) -> tuple[Any, Any, Any]:
    """(assembly, shapes, meshes) of the studio's design, built once per project text (in a
    thread of the app: the live-analysis workers' time limit is shorter than a large model's
    build)."""
    from .studio import _design_or_error

    design = _design_or_error(state)
    key = design.project_text
    with _BUILD:
        return _cached(key, design)


def _cached(key: str, design: Any) -> tuple[Any, Any, Any]:
    from ..cad.assembly import drive_assembly
    from ..cad.build import build_shapes
    from ..cad.mesh import tessellate

    if key not in _CACHE:
        a = drive_assembly(design.drive)
        shapes = build_shapes(a)
        _CACHE[key] = (a, shapes, tessellate(a, shapes))
        while len(_CACHE) > 4:
            _CACHE.popitem(last=False)
    return _CACHE[key]


def view_payload(state: dict[str, str]) -> dict:
    """The plotly figure of the design's assembly and its summary (SI units)."""
    from .._results import jsonable
    from ..cad.mesh import view_figure

    a, _, meshes = _model(state)
    return jsonable({"figure": view_figure(a, meshes), "summary": a.summary()})


def cad_download(name: str, state: dict[str, str]) -> tuple[bytes, str]:
    """``(body, media type)`` of ``drive.step`` or ``drive.glb``."""
    from ..cad.build import step_bytes
    from ..cad.mesh import glb_bytes

    a, shapes, meshes = _model(state)
    if name == "drive.step":
        return step_bytes(a, shapes), "model/step"
    return glb_bytes(a, meshes), "model/gltf-binary"


def router(ctx: Any) -> APIRouter:
    """The 3-D view's routes."""
    r = APIRouter()

    @r.get("/view3d", response_class=HTMLResponse)
    def view_page(request: Request):
        from .studio import state_query

        state = normalise_state(dict(request.query_params))
        return ctx.render(request, "view3d.html", query=state_query(state), downloads=CAD_DOWNLOADS)

    @r.get("/api/view3d")
    async def api_view(request: Request):
        return await asyncio.to_thread(view_payload, normalise_state(dict(request.query_params)))

    @r.get("/download3d/{name}")
    async def download(request: Request, name: str):
        if name not in CAD_DOWNLOADS:
            return JSONResponse({"error": f"unknown download {name!r}; valid: {', '.join(CAD_DOWNLOADS)}"},
                                status_code=404)
        body, media = await asyncio.to_thread(cad_download, name, normalise_state(dict(request.query_params)))
        return Response(body, media_type=media, headers={"Content-Disposition": f'attachment; filename="{name}"'})

    return r
