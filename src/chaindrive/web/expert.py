"""Expert pages: entry kinematics with guides, crawler drive, pocket wheel, track drive wheel,
dynamic simulation (a background job with progress).

Each page is a GET form: the state is in the URL, the values typed are kept, and an
error is shown at the field that caused it. Results come from the library's result
objects (their names and SI values); plots are plotly.js figures.
"""

from __future__ import annotations

import base64
import math
from typing import Any

import numpy as np
from fastapi import APIRouter, Request
from fastapi.responses import HTMLResponse, JSONResponse, Response

from ..display import mm
from ..errors import ChainDriveError
from ..limits import MAX_SPEED, MAX_TEETH, MIN_TEETH
from .bodies import SimulationBody, openapi_body, read_body
from .drawing import workshop_drawing
from .fields import FieldError, FieldSpec, parse_field, parse_integer

__all__ = ["router", "kinematics_result", "crawler_result", "wheel_result", "summary_table", "dimension_rows",
           "simulation_rows", "MAX_POINTS"]

#: Longest simulated time a web job may ask for [s].
MAX_SIMULATED_TIME = 3.0
#: Most animation frames a web job may ask for.
MAX_FRAMES = 60

#: Samples per period on the expert pages and in ``/api/kinematics``.
MAX_POINTS = 5001

PAGES = {
    "kinematics": "Entry kinematics",
    "crawler": "Crawler drive",
    "pocket-wheel": "Pocket wheel",
    "track-wheel": "Track drive wheel",
    "simulation": "Simulation",
}

_SPEED = FieldSpec("rad/s", 0.0, MAX_SPEED, example="5 rad/s")
_LENGTH = FieldSpec("m", 0.0, 10.0, example="256 mm")
_ELONGATION = FieldSpec("", 0.0, 0.1, example="0.03")
_FORCE = FieldSpec("N", 0.0, 1e8, open_minimum=False, example="10 kN")
_STIFFNESS = FieldSpec("N", 0.0, 1e11, example="5 MN")
_ANGLE = FieldSpec("rad", 0.0, 1.5707, open_minimum=False, example="15 deg")

DEFAULTS = {
    "kinematics": {"chain": "18x64", "teeth": "8", "speed": "5 rad/s", "guide_end": "256 mm", "model": "exact"},
    "crawler": {"chain": "", "pitch": "100 mm", "teeth": "8", "speed": "30 rpm", "stiffness": "",
                "sprocket_distance": "", "cam_distance": "", "traction_force": "0 N", "tension": "",
                "cam_face_angle": "0 deg"},
    "pocket-wheel": {"chain": "18x64", "teeth": "8"},
    "track-wheel": {"pitch": "170 mm", "teeth": "13", "pin_radius": "25 mm", "link": "cast",
                    "elongation_limit": "0.03"},
    "simulation": {"example": "link", "speed": "5 rad/s", "load": "2000 N*m", "duration": "0.5 s",
                   "frames": "30", "design": ""},
}
CHOICES = {"model": ("exact", "paper"), "link": ("cast", "built-up"), "example": ("link", "roller", "studio")}


def _state(page: str, params: dict[str, Any]) -> dict[str, str]:
    out = {}
    for key, default in DEFAULTS[page].items():
        value = str(params.get(key, default))[:200]
        if key in CHOICES and value not in CHOICES[key]:
            value = default
        out[key] = value
    return out


def _chain(name: str, field: str = "chain"):
    from ..chains import get

    try:
        return get(name.strip())
    except ChainDriveError as exc:
        raise FieldError(field, str(exc)) from None


_UNIT_TEXT = {"m/s^2": "m/s²", "m^2": "mm²", "1": "", "-": ""}


def _unit_text(unit: str) -> str:
    return _UNIT_TEXT.get(unit, unit)


def _shown(value: Any, unit: str, display: str | None = None, scale: float | None = None) -> tuple[str, str]:
    """A value in its display unit, rounding noise shown as 0 (``scale``: the largest value
    it is shown with), and the unit's text."""
    from ..display import convert, fmt
    from ..workflows.notebook import tidy

    if value is None:
        return "—", ""
    if isinstance(value, (bool, np.bool_)):
        return ("yes" if value else "no"), ""
    if unit == "":
        return fmt(value), ""
    shown_value, shown_unit = convert(float(value), unit, display)
    if scale is not None:
        shown_scale = abs(convert(float(scale), unit, display)[0] or 0.0)
        shown_value = tidy(shown_value or 0.0, shown_scale)
    else:
        shown_value = tidy(shown_value or 0.0)
    if isinstance(value, (int, np.integer)) and unit == "1":
        return str(int(value)), ""
    return fmt(shown_value), _unit_text(shown_unit)


def summary_table(summaries: dict[str, dict[str, Any]]) -> dict[str, Any]:
    """The summaries of several cases as one table: a row per quantity (label and unit from
    :data:`chaindrive.kinematics.entry.SUMMARY_QUANTITIES`), a column per case.

    Examples
    --------
    >>> t = summary_table({"free": {"v_mean": 0.8149, "a_end_left": 7.694e-12, "a_max": 1.025}})
    >>> t["columns"], t["rows"][0]
    (['free'], ('mean chain speed', 'm/s', ['0.8149']))
    >>> [r for r in t["rows"] if r[0].startswith("acceleration just before")][0][2]
    ['0']
    """
    from ..kinematics.entry import SUMMARY_QUANTITIES

    columns = list(summaries)
    keys = [k for k in SUMMARY_QUANTITIES if any(k in s for s in summaries.values())]
    # acceleration-like values are compared with the largest acceleration of the case
    rows = []
    for key in keys:
        label, unit = SUMMARY_QUANTITIES[key]
        cells, shown_unit = [], ""
        for case in columns:
            s = summaries[case]
            value = s.get(key)
            scale = None
            if unit == "m/s^2":
                scale = max(abs(float(s.get(k, 0.0) or 0.0)) for k in ("a_min", "a_max", "a_abs_max") if k in s) or None
            elif unit == "m/s":
                scale = abs(float(s.get("v_mean", 0.0) or 0.0)) or None
            text, u = _shown(value, unit, scale=scale)
            cells.append(text)
            shown_unit = u or shown_unit
        rows.append((label, shown_unit, cells))
    return {"columns": columns, "rows": rows}


def dimension_rows(result: Any) -> list[tuple[str, str, str]]:
    """(label, value, unit) of every scalar or range field of a dimensions result, in its
    display unit (labels and units from the result class: :meth:`Result.unit_of`)."""
    import dataclasses

    rows = []
    cls = type(result)
    for f in dataclasses.fields(result):
        value = getattr(result, f.name)
        unit = f.metadata.get("unit")
        label = f.name.replace("_", " ")
        if isinstance(value, (str, bool, np.bool_)) and unit is None:
            rows.append((label, _shown(value, "")[0] if not isinstance(value, str) else value, ""))
            continue
        if unit is None:
            continue
        display = cls.display_unit_of(f.name)
        if isinstance(value, (tuple, list)) and len(value) == 2:
            lo, u = _shown(value[0], unit, display)
            hi, _ = _shown(value[1], unit, display)
            rows.append((label, f"{lo} … {hi}", u))
        elif isinstance(value, (int, float, np.integer, np.floating)):
            text, u = _shown(value, unit, display)
            rows.append((label, text, u))
    return rows


def _wheel_speed(text: str, *, pitch: float, teeth: int, link_chain: bool) -> float:
    """The speed field: an angular speed ("5 rad/s", "48 rpm") or the mean chain speed
    ("0.8 m/s"), as at the command line (:func:`chaindrive.kinematics.speed.parse_wheel_speed`)."""
    from ..errors import InputError
    from ..kinematics.speed import parse_wheel_speed

    parse_field("speed", text, FieldSpec("", 0.0, math.inf, example="5 rad/s")) if not text.strip() else None
    try:
        omega = parse_wheel_speed(text.strip(), pitch=pitch, teeth=teeth, link_chain=link_chain, field="speed")
    except InputError as exc:
        raise FieldError("speed", str(exc).removeprefix("speed: ")) from None
    return parse_field("speed", f"{omega!r} rad/s", _SPEED)


def simulation_rows(summary: dict[str, Any]) -> list[tuple[str, str, str]]:
    """(label, value, unit) of a simulation summary (labels and units declared with the
    summary: :data:`chaindrive.simulation.run.SUMMARY_QUANTITIES`); a list of values (one
    per wheel or probe) is shown as a list; a speed in rad/s with its rpm.

    Examples
    --------
    >>> simulation_rows({"tight_side_tension_mean": 12500.0, "wheel_speed_mean": [5.0, 5.0]})
    [('tight-side tension, mean', '12.5', 'kN'), ('wheel speeds, mean', '47.75, 47.75', 'rpm')]
    """
    from ..simulation.run import SUMMARY_QUANTITIES

    rows = []
    for key, (label, unit) in SUMMARY_QUANTITIES.items():
        if key not in summary or summary[key] is None:
            continue
        value = summary[key]
        values = value if isinstance(value, list) else [value]
        if unit == "rad/s":  # shaft speeds: in rpm, one unit per quantity (issue 30)
            rows.append((label, ", ".join(_shown(v, "rad/s", "rpm")[0] for v in values), "rpm"))
            continue
        cells = [_shown(v, unit) for v in values]
        rows.append((label, ", ".join(c[0] for c in cells), cells[0][1] if cells else ""))
    return rows


def _line(x: Any, ys: dict[str, np.ndarray], xtitle: str, ytitle: str, title: str) -> dict[str, Any]:
    return {"data": [{"type": "scatter", "mode": "lines", "name": k, "x": np.asarray(x).tolist(),
                      "y": np.asarray(v).tolist(),
                      "hovertemplate": f"{k}<br>%{{x:.4g}}<br>%{{y:.5g}}<extra></extra>"} for k, v in ys.items()],
            "layout": {"title": {"text": title, "font": {"size": 13}}, "height": 340,
                       "margin": {"l": 60, "r": 20, "t": 40, "b": 50},
                       "xaxis": {"title": {"text": xtitle}}, "yaxis": {"title": {"text": ytitle}},
                       "legend": {"orientation": "h", "y": -0.3}}}


def kinematics_result(state: dict[str, str], points: int = 361) -> dict[str, Any]:
    """Free, chordal and tangential entry of a catalogue chain (Dolipiński et al.).

    Examples
    --------
    >>> r = kinematics_result(DEFAULTS["kinematics"])
    >>> sorted(r["summaries"])
    ['chordal', 'free', 'tangential']
    """
    from ..kinematics import chain_entry

    chain = _chain(state["chain"])
    teeth = parse_integer("teeth", state["teeth"], MIN_TEETH, MAX_TEETH)
    omega = _wheel_speed(state["speed"], pitch=chain.pitch, teeth=teeth, link_chain=chain.is_link_chain)
    l_end = parse_field("guide_end", state["guide_end"], _LENGTH)
    results = {}
    for entry in ("free", "chordal", "tangential"):
        try:
            results[entry] = chain_entry(chain.pitch, teeth, omega, bar_diameter=chain.bar_diameter,
                                         entry=entry, guide_end_distance=None if entry == "free" else l_end,
                                         model=state["model"], points=points)
        except ChainDriveError as exc:
            field = "guide_end" if "guide" in str(exc) else "teeth"
            raise FieldError(field, str(exc)) from None
    phi = np.degrees(next(iter(results.values())).phi)
    return {
        "summaries": {k: r.summary for k, r in results.items()},
        "table": summary_table({f"{k} entry": r.summary for k, r in results.items()}),
        "plots": [
            _line(phi, {k: r.velocity for k, r in results.items()}, "wheel angle φ [°]",
                  "chain velocity [m/s]", f"{chain.name}, z = {teeth}: chain velocity at the entry"),
            _line(phi, {k: r.acceleration for k, r in results.items()}, "wheel angle φ [°]",
                  "chain acceleration [m/s²]", "chain acceleration at the entry"),
        ],
    }


def crawler_result(state: dict[str, str], points: int = 361) -> dict[str, Any]:
    """Crawler drive chain with and without the tangent guide (the crawler drive text).

    Examples
    --------
    >>> r = crawler_result(DEFAULTS["crawler"])
    >>> sorted(r["summaries"])
    ['no guide', 'tangent guide']
    """
    from ..kinematics.crawler import crawler_drive

    pitch = _chain(state["chain"]).pitch if state["chain"].strip() else parse_field("pitch", state["pitch"], _LENGTH)
    teeth = parse_integer("teeth", state["teeth"], MIN_TEETH, MAX_TEETH)
    omega = _wheel_speed(state["speed"], pitch=pitch, teeth=teeth, link_chain=False)
    cam: dict[str, Any] = {}  # the cam force and the guide reaction, when their inputs are given
    for key, spec in (("stiffness", _STIFFNESS), ("sprocket_distance", _LENGTH), ("cam_distance", _LENGTH),
                      ("tension", _FORCE)):
        if state.get(key, "").strip():
            cam[key] = parse_field(key, state[key], spec)
    cam["traction_force"] = parse_field("traction_force", state.get("traction_force") or "0 N", _FORCE)
    cam["cam_face_angle"] = parse_field("cam_face_angle", state.get("cam_face_angle") or "0 deg", _ANGLE)
    res = {}
    for name, guide in (("tangent guide", True), ("no guide", False)):
        try:
            res[name] = crawler_drive(pitch, teeth, omega, with_guide=guide, points=points, **cam)
        except ChainDriveError as exc:
            named = [k for k in ("sprocket_distance", "cam_distance", "stiffness", "tension", "traction_force",
                                 "cam_face_angle") if str(exc).startswith(k) or f" {k} " in str(exc)]
            raise FieldError(named[0] if named else "teeth", str(exc)) from None
    psi = np.degrees(res["no guide"].psi)
    return {"summaries": {k: r.summary for k, r in res.items()},
            "table": summary_table({k: r.summary for k, r in res.items()}),
            "plots": [_line(psi, {k: r.velocity for k, r in res.items()}, "sprocket angle ψ [°]",
                            "chain velocity [m/s]", f"Crawler drive chain, t = {mm(pitch):g} mm, z = {teeth}")]}


def wheel_result(page: str, state: dict[str, str]) -> dict[str, Any]:
    """Outline (SVG as a data URI) and dimensions of a pocket wheel or a track drive wheel.

    Examples
    --------
    >>> r = wheel_result("pocket-wheel", DEFAULTS["pocket-wheel"])
    >>> r["image"].startswith("data:image/svg+xml;base64,")
    True
    """
    from ..geometry.export import svg_text

    wheel, outline = _wheel(page, state)
    svg = svg_text(outline, title=wheel.label())
    dims = wheel.dimensions()
    sources = getattr(dims, "sources", None) or {}
    return {"image": "data:image/svg+xml;base64," + base64.b64encode(svg.encode()).decode("ascii"),
            "dimensions": dimension_rows(dims), "label": wheel.label(),
            "sources": list(sources.values()), "drawing": page == "pocket-wheel"}


def wheel_file(page: str, state: dict[str, str], kind: str) -> bytes:
    """The wheel of an expert page: the workshop drawing (pocket wheel) or the outline
    (track wheel) as DXF in mm, or the outline as SVG."""
    import io

    from ..geometry.export import dxf_document, svg_text

    wheel, outline = _wheel(page, state)
    if kind == "svg":
        return svg_text(outline, title=wheel.label()).encode("utf-8")
    if page == "pocket-wheel":
        return workshop_drawing(wheel)
    buf = io.StringIO()
    dxf_document(outline, wheel.label()).write(buf)
    return buf.getvalue().encode("utf-8")


def _wheel(page: str, state: dict[str, str]):
    from ..geometry import PocketWheel, TrackDriveWheel

    try:
        if page == "pocket-wheel":
            chain = _chain(state["chain"])
            if not chain.is_link_chain:
                raise FieldError("chain", f"{chain.name} is not a round link chain (DIN 22252, e.g. 18x64)")
            wheel: Any = PocketWheel.from_chain(chain, parse_integer("teeth", state["teeth"], 3, 60))
        else:
            wheel = TrackDriveWheel(pitch=parse_field("pitch", state["pitch"], _LENGTH),
                                    teeth=parse_integer("teeth", state["teeth"], 3, 60),
                                    pin_radius=parse_field("pin_radius", state["pin_radius"], _LENGTH),
                                    link=state["link"],
                                    elongation_limit=parse_field("elongation_limit",
                                                                 state.get("elongation_limit") or "0.03",
                                                                 _ELONGATION))
        outline = wheel.outline()
    except FieldError:
        raise
    except ChainDriveError as exc:
        raise FieldError("teeth", str(exc)) from None
    return wheel, outline


def router(ctx: Any) -> APIRouter:
    """The expert pages and the simulation job API."""
    r = APIRouter()

    def _page(request: Request, page: str, compute: Any) -> Any:
        state = _state(page, dict(request.query_params))
        errors: dict[str, str] = {}
        result = None
        try:  # computed when the page opens (the defaults) and at each submission
            result = compute(state)
        except FieldError as exc:
            errors[exc.field] = exc.message
        except ChainDriveError as exc:
            errors[next(iter(state))] = str(exc)
        from urllib.parse import urlencode

        return ctx.render(request, "expert.html", page=page, pages=PAGES, state=state, errors=errors,
                          result=result, choices=CHOICES, query=urlencode(state),
                          status_code=422 if errors else 200)

    @r.get("/expert/kinematics", response_class=HTMLResponse)
    def kinematics_page(request: Request):
        return _page(request, "kinematics", kinematics_result)

    @r.get("/expert/crawler", response_class=HTMLResponse)
    def crawler_page(request: Request):
        return _page(request, "crawler", crawler_result)

    @r.get("/expert/pocket-wheel", response_class=HTMLResponse)
    def pocket_page(request: Request):
        return _page(request, "pocket-wheel", lambda s: wheel_result("pocket-wheel", s))

    @r.get("/expert/track-wheel", response_class=HTMLResponse)
    def track_page(request: Request):
        return _page(request, "track-wheel", lambda s: wheel_result("track-wheel", s))

    @r.get("/expert/{page}/outline.{kind}")
    async def wheel_download(request: Request, page: str, kind: str):
        if page not in ("pocket-wheel", "track-wheel") or kind not in ("dxf", "svg"):
            return JSONResponse({"error": "outlines: /expert/pocket-wheel or /expert/track-wheel, .dxf or .svg"},
                                status_code=404)
        state = _state(page, dict(request.query_params))
        data = await ctx.gate.run(wheel_file, page, state, kind)
        media = "image/svg+xml" if kind == "svg" else "application/dxf"
        return Response(data, media_type=media,
                        headers={"Content-Disposition": f'attachment; filename="{page}.{kind}"'})

    @r.get("/expert/simulation", response_class=HTMLResponse)
    def simulation_page(request: Request):
        state = _state("simulation", dict(request.query_params))
        return ctx.render(request, "expert.html", page="simulation", pages=PAGES, state=state, errors={},
                          result=None, choices=CHOICES)

    @r.post("/api/jobs/simulate", openapi_extra=openapi_body(SimulationBody))
    async def start_simulation(request: Request):
        form, refused = await read_body(request, SimulationBody)  # 400 malformed, 422 by field
        if refused is not None:
            return refused
        state = _state("simulation", {k: str(v) for k, v in (form or {}).items() if v is not None})
        errors = {}
        payload: dict[str, Any] = {"example": state["example"]}
        for key, spec in (("speed", FieldSpec("rad/s", 0.0, 60.0, example="5 rad/s")),
                          ("load", FieldSpec("N*m", 0.0, 1e6, open_minimum=False, example="2000 N*m")),
                          ("duration", FieldSpec("s", 0.0, MAX_SIMULATED_TIME, example="0.5 s"))):
            try:
                payload[key] = parse_field(key, state[key], spec)
            except FieldError as exc:
                errors[exc.field] = exc.message
        try:
            payload["frames"] = parse_integer("frames", state["frames"], 0, MAX_FRAMES)
        except FieldError as exc:
            errors[exc.field] = exc.message
        if state["example"] == "studio":
            from urllib.parse import parse_qsl

            from .design import normalise_state
            from .studio import download_body

            # the studio's state (its query string; empty: the studio's default design)
            studio_state = normalise_state(dict(parse_qsl(state["design"])))
            try:
                _, payload["project"] = await ctx.gate.run(download_body, "report.html", studio_state)
            except ChainDriveError as exc:
                errors["example"] = f"the studio design is invalid: {exc}"
            payload["example"] = None
        if errors:
            return JSONResponse({"errors": errors, "error": "; ".join(f"{k}: {v}" for k, v in errors.items())},
                                status_code=422)
        job = ctx.jobs.submit("simulate", payload, time_limit=max(60.0, 40.0 * payload["duration"] + 30.0))
        return {"job": job.id}

    @r.get("/api/jobs/{job_id}")
    def job_status(job_id: str):
        job = ctx.jobs.get(job_id[:64])
        if job is None:
            return JSONResponse({"error": "no such job (finished jobs are kept for a while only)"}, status_code=404)
        return job.public()

    @r.get("/api/jobs/{job_id}/files/{name}")
    def job_file(job_id: str, name: str):
        job = ctx.jobs.get(job_id[:64])
        if job is None or name not in job.files:
            return JSONResponse({"error": "no such file"}, status_code=404)
        media = {"png": "image/png", "gif": "image/gif", "json": "application/json",
                 "html": "text/html; charset=utf-8", "pdf": "application/pdf"}[name.rsplit(".", 1)[-1]]
        from pathlib import Path

        return Response(Path(job.files[name]).read_bytes(), media_type=media)

    return r


def _finite(x: float) -> float | None:
    return x if math.isfinite(x) else None
