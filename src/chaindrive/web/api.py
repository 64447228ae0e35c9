"""JSON API: catalogue, entry kinematics, the analysis of a project file.

Every size-like parameter has a maximum and is refused (422) before anything is
allocated; the analysis runs in the live-analysis pool, never on the event loop.
"""

from __future__ import annotations

from typing import Any

from fastapi import APIRouter, Form, Query

from .._results import jsonable
from ..limits import MAX_SPEED, MAX_TEETH, MIN_TEETH
from .expert import MAX_POINTS
from .fields import FieldSpec, parse_field

__all__ = ["router"]


def _analyze_text(text: str) -> dict:
    from ..drive.project import parse_project
    from .engine import light_analysis

    drive = parse_project(text, filename="project.toml")
    a = light_analysis(drive)
    return jsonable({"passed": a.passed, "checks": a.checks, "warnings": a.warnings, "results": a.results()})


def kinematics_json(chain: str, teeth: int, speed: str, entry: str, guide_end: str | None, model: str,
                    points: int) -> dict:
    """Entry kinematics of a catalogue chain as JSON-ready data (SI units)."""
    from ..chains import get
    from ..kinematics import chain_entry

    c = get(chain)
    omega = parse_field("speed", speed, FieldSpec("rad/s", 0.0, MAX_SPEED, example="5 rad/s"))
    l_end = parse_field("guide_end", guide_end, FieldSpec("m", 0.0, 10.0, example="256 mm")) if guide_end else None
    res = chain_entry(c.pitch, teeth, omega, bar_diameter=c.bar_diameter, entry=entry,
                      guide_end_distance=l_end, model=model, points=points)
    return {"phi": res.phi.tolist(), "x": res.x.tolist(), "velocity": res.velocity.tolist(),
            "acceleration": res.acceleration.tolist(), "summary": jsonable(res.summary)}


def router(ctx: Any) -> APIRouter:
    """The JSON API routes."""
    r = APIRouter()

    @r.get("/api/chains")
    def chains(family: str | None = Query(None, max_length=20)):
        from ..chains import catalogue

        return [jsonable(c) for c in catalogue(family)]

    @r.get("/api/kinematics")
    async def api_kinematics(
        chain: str = Query(..., max_length=40, description="catalogue name"),
        teeth: int = Query(..., ge=MIN_TEETH, le=MAX_TEETH, description=f"teeth / pockets, {MIN_TEETH}...{MAX_TEETH}"),
        speed: str = Query(..., max_length=64, description="wheel speed with its unit, e.g. '5 rad/s'"),
        entry: str = Query("free", max_length=20, description="free | chordal | tangential"),
        guide_end: str | None = Query(None, max_length=64, description="guide end distance with unit"),
        model: str = Query("exact", max_length=20),
        points: int = Query(361, ge=3, le=MAX_POINTS, description=f"samples per period, 3 <= points <= {MAX_POINTS}"),
    ):
        return await ctx.gate.run(kinematics_json, chain, teeth, speed, entry, guide_end, model, points)

    @r.post("/api/analyze")
    async def api_analyze(project: str = Form(..., max_length=200_000)):
        return await ctx.gate.run(_analyze_text, project)

    return r
