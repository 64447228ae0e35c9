"""The design studio: the guided page, its live update, its charts, the downloads, projects.

Routes (the page state is the query string, so a link reproduces a design):

* ``GET /`` the page; ``GET /api/design`` the live update (drawing, layout, loads,
  checks; the analysis without figures); ``GET /api/design/charts`` the slow part
  (rating chart, Campbell diagram, resonance map);
* ``GET /download/{project.toml, results.json, report.html, report.pdf, wheel.dxf, wheel.svg}``;
* ``POST /open`` a project file (upload or text) -> the page with its state.
"""

from __future__ import annotations

import json
import time
from pathlib import Path
from typing import Any
from urllib.parse import urlencode

from fastapi import APIRouter, Request, UploadFile
from fastapi.responses import HTMLResponse, JSONResponse, RedirectResponse, Response
from starlette.datastructures import UploadFile as StarletteUpload

from .._results import jsonable
from ..analysis.loads import REQUIRED_STATIC_SAFETY
from ..design.duty import service_factor_of
from ..display import check_margin_text, ms, verdict_text
from ..errors import ChainDriveError, InputError
from ..units import angular_velocity_to_rpm
from .design import (
    DEFAULTS,
    FIELDS,
    design_from_state,
    load_character_of,
    normalise_state,
    service_factor_table,
    state_from_project,
)
from .display import fmt, show
from .wheels import MAX_EXTRA_WHEELS, extra_rows

__all__ = ["router", "studio_payload", "studio_json", "charts_payload", "charts_json", "state_query"]

DOWNLOADS = {
    "project.toml": "Project file (TOML): opens with chaindrive layout / analyze",
    "report.html": "Calculation report (HTML, figures inside)",
    "report.pdf": "Calculation report (PDF)",
    "results.json": "Every number of the analysis (JSON, SI units)",
    "wheel.dxf": "Driving wheel workshop drawing (DXF, mm)",
    "wheel.svg": "Driving wheel outline (SVG, mm)",
}


def state_query(state: dict[str, str]) -> str:
    """The query string of a state (fields equal to the default are left out).

    Examples
    --------
    >>> state_query(normalise_state({"power": "10 kW"}))
    'power=10+kW'
    """
    return urlencode({k: v for k, v in state.items() if DEFAULTS.get(k) != v})


def _checks_for_page(checks: list[dict], units: str) -> list[dict]:
    """Value, limit and margin texts of the checks in the page's units (names from the checks)."""
    out = []
    from ..display import convert

    for c in checks:
        if c.get("display") and isinstance(c["value"], (int, float)):  # a declared display unit ("%")
            shown = convert(float(c["value"]), c["unit"], c["display"])
            value, unit = fmt(shown[0]), shown[1]
        else:
            value, unit = show(c["value"], c["unit"], units)
        limit, relation = c["limit"], c.get("relation", ">=")
        if relation == "info" or limit is None:
            limit_text = "" if limit is None or relation == "info" else str(limit)
        elif isinstance(limit, (list, tuple)):
            lo, hi = (show(x, c["unit"], units) for x in limit)
            limit_text = f"{lo[0]} … {hi[0]} {hi[1]}".strip()
        elif isinstance(limit, (int, float)) and not isinstance(limit, bool):
            limit_text = f"{relation} " + " ".join(show(limit, c["unit"], units)).strip()
        else:
            limit_text = str(limit)
        out.append({**c, "value_text": value, "unit_text": unit, "limit_text": limit_text,
                    "margin_text": check_margin_text(c["margin"])})
    return out


def _exact_centre_text(design: Any, layout: Any, units: str) -> str | None:
    """The centre distance that fits the links: the two-wheel solution, or where the layout moved the
    driven wheel (a drive with further wheels; it moves along the line of centres from the origin)."""
    exact = design.exact_centre_distance
    adjustment = getattr(layout, "adjustment", None)
    if exact is None and adjustment is not None:
        exact = float(adjustment.position[0])
    return None if exact is None else " ".join(show(exact, "m", units))


def studio_payload(state: dict[str, str]) -> dict[str, Any]:
    """Everything the page shows after a field edit (no figures): JSON-ready.

    Examples
    --------
    >>> p = studio_payload(normalise_state({}))
    >>> p["errors"], p["layout"]["links"] % 2, p["chain"]["name"] == p["candidates"][0]["chain"]
    ({}, 0, True)
    """
    from .drawing import drive_svg
    from .engine import layout_summary, light_analysis, loads_table

    t0, c0 = time.perf_counter(), time.process_time()
    units = state["units"]
    design, errors = design_from_state(state)
    out: dict[str, Any] = {"errors": errors, "query": state_query(state), "state": state}
    table = service_factor_table()
    character = load_character_of(state)
    out["service_factor_table"] = {"value": service_factor_of(state["driver"], load_character=character).value,
                                   "character": table["characters"][character],
                                   "driver": table["drivers"][state["driver"]],
                                   "source": table["source"]}
    if design is None:
        return out
    drive = design.drive
    try:
        analysis = light_analysis(drive)
    except ChainDriveError as exc:
        out["errors"] = {**errors, "centre_distance": str(exc)}
        return out
    lay = layout_summary(drive, analysis.layout)
    out["duty"] = {
        "power": show(design.power, "W", units), "design_power": show(design.design_power, "W", units),
        "speed_rpm": fmt(angular_velocity_to_rpm(design.speed)), "ratio": fmt(design.ratio),
        "service_factor": fmt(design.service_factor), "service_factor_source": design.service_factor_source,
        "load_character": table["characters"][design.load_character],
        "hours_per_day": fmt(design.hours_per_day),
    }
    out["candidates"] = [
        {**c, "margin_text": f"{(c['margin'] - 1) * 100:+.0f} %",
         "rated": " ".join(show(c["rated_power"], "W", units)),
         "pitch_text": " ".join(show(c["pitch"], "m", units)),
         "safety_text": fmt(c["static_safety"], 3), "chosen": c["chain"] == design.chain.name}
        for c in design.candidates]
    out["candidate_note"] = design.candidate_note
    out["advice"] = list(design.advice)  # the design procedure's advice, with sources
    out["chain"] = {"name": design.chain.name, "family": design.chain.family,
                    "pitch": " ".join(show(design.chain.pitch, "m", units)),
                    "breaking_force": " ".join(show(design.chain.breaking_force, "N", units)),
                    "source": design.chain.source}
    out["layout"] = {
        "links": lay["links"], "links_required": fmt(lay["links_required"]),
        "teeth_driving": design.teeth_driving, "teeth_driven": design.teeth_driven,
        "centre_distance_given": " ".join(show(design.centre_distance, "m", units)),
        "centre_distance_exact": _exact_centre_text(design, analysis.layout, units),
        "chain_length": " ".join(show(lay["chain_length"], "m", units)),
        "chain_speed": " ".join(show(lay["chain_speed"], "m/s", units)),
    }
    out["drawing"] = drive_svg(lay, drive, units=units)
    checks = _checks_for_page(analysis.checks, units)
    loads: Any
    try:
        loads = loads_table(analysis)
    except Exception:  # noqa: BLE001 - the loads table is a presentation extra; checks stand alone
        loads = None
    if loads is not None:
        rows = []
        for row in loads.rows:
            name, value, unit, *rest = row
            value_text, unit_text = show(value, unit, units)
            rows.append([str(name), value_text, unit_text, " ".join(str(x) for x in rest)])
        out["loads"] = {"caption": loads.caption, "rows": rows + _conveyor_rows(analysis, units)}
    fretting = None if analysis.analysis is None else getattr(analysis.analysis, "fretting", None)
    if fretting is not None:  # a multi-strand chain: Vikulov's pin slip with and without intermediate plates
        rows = []
        for name, unit in type(fretting).field_units().items():
            value = getattr(fretting, name)
            if value is not None:
                rows.append([name.replace("_", " "), *show(value, "-" if unit == "1" else unit, units)])
        out["fretting"] = {"caption": "Fretting and pin slip of the multi-strand chain (Vikulov)", "rows": rows}
    life = next((c for c in analysis.checks if "hours" in c["name"] and isinstance(c["value"], (int, float))), None)
    over_life = None if analysis.analysis is None else analysis.analysis.results.get("life")
    if over_life is not None:  # the shortest life of wear, jump-over and fatigue (docs/life.md)
        life = {"value": over_life.life_hours}
    if life is not None and design.hours_per_day > 0:
        out["life_years"] = fmt(life["value"] / (design.hours_per_day * 365.0), 3)
    out["checks"] = checks
    out["warnings"] = analysis.warnings
    out["passed"] = analysis.passed
    failed = sum(1 for c in analysis.checks if c["passed"] is False)
    out["verdict"] = verdict_text(failed, len(analysis.warnings))  # "passes, 2 warnings" (issue 30)
    out["downloads"] = {name: f"/download/{name}?{out['query']}" for name in DOWNLOADS}
    out["has_tensioner"] = drive.tensioner is not None
    out["elapsed_ms"] = round(ms(time.perf_counter() - t0), 1)
    out["cpu_ms"] = round(ms(time.process_time() - c0), 1)  # the server's CPU time: its work without the waits
    return out


def _json_default(value: Any) -> Any:
    """numpy scalars and arrays as JSON values (what FastAPI's encoder did for the routes)."""
    out = jsonable(value)
    if out is value:
        raise TypeError(f"{type(value).__name__} is not JSON serialisable")
    return out


def json_bytes(payload: dict[str, Any]) -> bytes:
    """A payload as the JSON body of an answer (compact UTF-8, no NaN: the same text FastAPI's
    ``JSONResponse`` writes), built in the worker that computed it: the server's event loop
    only passes the bytes on."""
    return json.dumps(payload, ensure_ascii=False, allow_nan=False, separators=(",", ":"),
                      default=_json_default).encode("utf-8")


def studio_json(state: dict[str, str]) -> bytes:
    """:func:`studio_payload` as the JSON body of ``GET /api/design``.

    Examples
    --------
    >>> json.loads(studio_json(normalise_state({})))["errors"]
    {}
    """
    return json_bytes(studio_payload(state))


def _conveyor_rows(analysis: Any, units: str) -> list[list[str]]:
    """Rows of the conveyor part's chain pull (a project opened with a [conveyor] table)."""
    pull = None if analysis.analysis is None else analysis.analysis.results.get("conveyor")
    if pull is None:
        return []
    rows = []
    for name in ("tight_tension", "slack_tension", "minimum_tension", "pretension", "drive_force",
                 "drive_power", "return_sag"):
        value_text, unit_text = show(getattr(pull, name), type(pull).unit_of(name), units)
        rows.append([f"conveyor: {name.replace('_', ' ')}", value_text, unit_text,
                     f"chain pull along the loop ({pull.source})"])
    return rows


def charts_payload(state: dict[str, str]) -> dict[str, Any]:
    """The plotly figures of a state (rating chart; Campbell and resonance map with a tensioner).

    Examples
    --------
    >>> sorted(charts_payload(normalise_state({})))
    ['campbell', 'errors', 'rating', 'resonance_map']
    """
    from .charts import campbell_chart, rating_chart, resonance_map_chart

    design, errors = design_from_state(state)
    if design is None:
        return {"errors": errors, "rating": None, "campbell": None, "resonance_map": None}
    return jsonable({"errors": errors, "rating": rating_chart(design, units=state["units"]),
                     "campbell": campbell_chart(design.drive),
                     "resonance_map": resonance_map_chart(design.drive)})


def charts_json(state: dict[str, str]) -> bytes:
    """:func:`charts_payload` as the JSON body of ``GET /api/design/charts``."""
    return json_bytes(charts_payload(state))


def _design_or_error(state: dict[str, str]):
    design, errors = design_from_state(state)
    if design is None:
        field, message = next(iter(errors.items()))
        raise InputError(f"{field}: {message}", field=field)
    return design


def download_body(name: str, state: dict[str, str]) -> tuple[bytes | None, str]:
    """``(body, media type)`` of a small download; ``(None, project text)`` for the reports.

    Raises
    ------
    InputError
        A field of the state is invalid (named).
    """
    design = _design_or_error(state)
    if name == "project.toml":
        return design.project_text.encode("utf-8"), "application/toml"
    if name == "results.json":
        return _results_json(design).encode("utf-8"), "application/json"
    if name in ("wheel.dxf", "wheel.svg"):
        media = "image/svg+xml" if name.endswith("svg") else "application/dxf"
        return _wheel_file(design, name[-3:]), media
    return None, design.project_text


def _results_json(design: Any) -> str:
    """results.json of a design: the project, the verdict, every check and number (SI units)."""
    from .engine import light_analysis

    analysis = light_analysis(design.drive)
    return json.dumps(jsonable({"project": design.project_text, "passed": analysis.passed,
                                "checks": analysis.checks, "warnings": analysis.warnings,
                                "results": analysis.results()}), indent=2)


def _example_query(name: str) -> str:
    """The studio's state of the example project file ``name`` of ``examples/`` (the same
    file ``chaindrive analyze`` reads), as a query string."""
    from .._examples import example_path

    return state_query(normalise_state(state_from_project(example_path(name).read_text(encoding="utf-8"), name)))


def _wheel_file(design: Any, kind: str) -> bytes:
    """The driving wheel: its workshop drawing as DXF (what ``chaindrive sprocket --dxf``
    writes), or its outline as SVG."""
    from ..geometry import PocketWheel, Sprocket
    from ..geometry.export import svg_text
    from .drawing import workshop_drawing

    chain = design.chain
    z = design.teeth_driving
    wheel = PocketWheel.from_chain(chain, z) if chain.is_link_chain else Sprocket.from_chain(chain, z)
    if kind == "svg":
        return svg_text(wheel.outline(), title=wheel.label()).encode("utf-8")
    return workshop_drawing(wheel)


def router(ctx: Any) -> APIRouter:
    """The studio's routes (``ctx`` holds the templates, the job manager and the gate)."""
    r = APIRouter()

    def _state(request: Request) -> dict[str, str]:
        return normalise_state(dict(request.query_params))

    @r.get("/", response_class=HTMLResponse)
    def studio_page(request: Request):
        state = _state(request)
        table = service_factor_table()
        driven_options = [(k, v[0]) for k, v in table["driven_machines"].items()]
        return ctx.render(request, "studio.html", state=state, table=table, fields=FIELDS,
                          driven_options=driven_options, required_safety=REQUIRED_STATIC_SAFETY,
                          load_characters=[("", "from the driven machine")] + [(c, table["characters"][c]) for c in
                                                                               ("smooth", "moderate", "heavy")],
                          downloads=DOWNLOADS, open_error=request.query_params.get("open_error", "")[:500],
                          mining_query=_example_query("mining_conveyor.toml"),
                          query=state_query(state), extra_rows=extra_rows(state), extra_max=MAX_EXTRA_WHEELS,
                          extra_options=[(str(n), "none" if n == 0 else str(n)) for n in range(MAX_EXTRA_WHEELS + 1)])

    @r.get("/api/design")
    async def api_design(request: Request):
        return Response(await ctx.gate.run(studio_json, _state(request)), media_type="application/json")

    @r.get("/api/design/charts")
    async def api_charts(request: Request):
        return Response(await ctx.gate.run(charts_json, _state(request)), media_type="application/json")

    @r.get("/download/{name}")
    async def download(request: Request, name: str):
        if name not in DOWNLOADS:
            return JSONResponse({"error": f"unknown download {name!r}; valid: {', '.join(DOWNLOADS)}"},
                                status_code=404)
        state = _state(request)
        stem = "".join(ch if ch.isalnum() else "_" for ch in (state["name"] or "drive"))[:40] or "drive"
        disposition = {"Content-Disposition": f'attachment; filename="{stem}-{name}"'}
        body, media = await ctx.gate.run(download_body, name, state)
        if body is not None:
            return Response(body, media_type=media, headers=disposition)
        # one job writes both the HTML and the PDF report of a project; the other download reuses it
        key_text = media  # the project text (download_body gives it for the reports)
        job = ctx.report_jobs.get(key_text)
        if job is None or job.state in ("failed", "timeout") or ctx.jobs.get(job.id) is None:
            job = ctx.jobs.submit("report", {"project": key_text, "pdf": True})
            ctx.report_jobs[key_text] = job
            while len(ctx.report_jobs) > 32:
                ctx.report_jobs.pop(next(iter(ctx.report_jobs)))
        await ctx.jobs.wait(job)
        key = "pdf" if name == "report.pdf" else "html"
        if job.state != "done" or key not in job.files:
            return JSONResponse({"error": job.error or f"the report job ended as {job.state}"},
                                status_code=504 if job.state == "timeout" else 500)
        media = "application/pdf" if key == "pdf" else "text/html; charset=utf-8"
        return Response(Path(job.files[key]).read_bytes(), media_type=media, headers=disposition)

    @r.post("/open")
    async def open_project(request: Request):
        form = await request.form()
        upload = form.get("file")
        text: str | None = ""
        if isinstance(upload, StarletteUpload):  # fastapi's UploadFile derives from it
            raw = await upload.read()
            try:
                text = raw.decode("utf-8")
            except UnicodeDecodeError:
                text = None
        if text == "" and not isinstance(form.get("project"), (UploadFile, type(None))):
            text = str(form.get("project"))
        try:
            if text is None:
                raise InputError("project file: not UTF-8 text")
            if not text.strip():
                raise InputError("project file: empty; choose a .toml file written by chaindrive")
            state = await ctx.gate.run(state_from_project, text, "project.toml")
        except ChainDriveError as exc:
            if "application/json" in request.headers.get("accept", ""):
                return JSONResponse({"error": str(exc), "field": "project"}, status_code=422)
            return RedirectResponse("/?" + urlencode({"open_error": str(exc)[:500]}), status_code=303)
        query = state_query(normalise_state(state))
        if "application/json" in request.headers.get("accept", ""):
            return {"query": query}
        return RedirectResponse("/?" + query, status_code=303)

    return r
