"""The report's charts as data for the browser (plotly.js figure objects): what ``report.html``
draws itself, offline, with the plotly.js file written beside it.

Each builder takes the analysis' result (never computes engineering) and returns a plotly
figure as plain data (``{"data": [...], "layout": {...}}``): the same lines, limits, labels
and units as the matplotlib figure of :mod:`chaindrive.plotting` that ``--pdf`` and ``--png``
draw. A figure without a builder here is drawn as PNG (matplotlib) in every case.

Examples
--------
>>> chart = figure([line([0, 1], [0, 2], "a")], x="time [s]", y="length [m]", title="t")
>>> chart["layout"]["xaxis"]["title"]["text"]
'time [s]'
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from ..display import convert

__all__ = ["figure", "line", "hline", "vline", "vspan", "wear_chart", "kinematics_chart", "skew_chart",
           "rating_chart", "life_chart", "layout_chart", "wheel_chart", "conveyor_chart", "campbell_chart",
           "crawler_chart", "self_regulating_chart", "viridis"]

Chart = dict[str, Any]
#: matplotlib's line styles as plotly dashes.
_DASH = {"-": "solid", "--": "dash", ":": "dot", "-.": "dashdot"}
#: matplotlib's default colour cycle (tab10), for "C0".."C9" and "tab:..." names.
_TAB = {"blue": "#1f77b4", "orange": "#ff7f0e", "green": "#2ca02c", "red": "#d62728", "purple": "#9467bd",
        "brown": "#8c564b", "pink": "#e377c2", "gray": "#7f7f7f", "olive": "#bcbd22", "cyan": "#17becf"}
_CYCLE = list(_TAB.values())


def _list(values: Any, digits: int = 7) -> list[Any]:
    """Numbers as a JSON list rounded to ``digits`` significant digits (a chart, not a record:
    results.json holds the numbers); NaN as null (a gap)."""
    out = []
    for v in np.asarray(values, dtype=float).ravel().tolist():
        out.append(None if not math.isfinite(v) else float(f"{v:.{digits}g}"))
    return out


def color(name: str | None) -> str | None:
    """A matplotlib colour name (``"tab:red"``, ``"C3"``, ``"0.4"``, ``"k"``) as CSS."""
    if name is None:
        return None
    if name.startswith("tab:"):
        return _TAB.get(name[4:], name[4:])
    if len(name) == 2 and name[0] == "C" and name[1].isdigit():
        return _CYCLE[int(name[1])]
    try:
        grey = float(name)
        level = round(255 * grey)
        return f"rgb({level},{level},{level})"
    except ValueError:
        return {"k": "black", "r": "red", "g": "green", "b": "blue"}.get(name, name)


def line(x: Any, y: Any, name: str | None = None, *, color_: str | None = None, dash: str = "-",
         width: float = 1.5, markers: bool = False, axis: int = 1, yaxis2: bool = False,
         legend: bool = True) -> dict[str, Any]:
    """A line (``markers``: with points) in panel ``axis`` (1, 2, ...)."""
    trace: dict[str, Any] = {"type": "scatter", "mode": "lines+markers" if markers else "lines",
                             "x": _list(x), "y": _list(y), "line": {"dash": _DASH.get(dash, dash), "width": width}}
    if color_ is not None:
        trace["line"]["color"] = color(color_)
    if markers:
        trace["marker"] = {"size": 5}
    if name:
        trace["name"] = name
    trace["showlegend"] = bool(name) and legend
    if axis > 1:
        trace["xaxis"], trace["yaxis"] = f"x{axis}", f"y{axis}"
    if yaxis2:
        trace["yaxis"] = "y2"
    return trace


def points(x: Any, y: Any, name: str | None = None, *, color_: str = "black", symbol: str = "circle",
           size: float = 8, axis: int = 1) -> dict[str, Any]:
    """Markers only."""
    trace = line(x, y, name, axis=axis)
    edge = "black" if symbol == "circle" else color(color_)
    trace.update(mode="markers", marker={"color": color(color_), "symbol": symbol, "size": size,
                                         "line": {"color": edge, "width": 1}})
    del trace["line"]
    return trace


def _ref(axis: int) -> tuple[str, str]:
    return ("x", "y") if axis == 1 else (f"x{axis}", f"y{axis}")


def hline(y: float, name: str | None = None, *, color_: str = "0.4", dash: str = "--", axis: int = 1,
          x: tuple[float, float] | None = None) -> dict[str, Any]:
    """A horizontal line across the panel (a legend entry when named), as a trace over ``x``
    or, without ``x``, as a shape spanning the panel."""
    xr, yr = _ref(axis)
    return {"type": "line", "xref": f"{xr} domain", "yref": yr, "x0": 0, "x1": 1, "y0": float(y), "y1": float(y),
            "line": {"color": color(color_), "dash": _DASH.get(dash, dash), "width": 1.2}, "name": name}


def vline(x: float, name: str | None = None, *, color_: str = "0.4", dash: str = ":", axis: int = 1) -> dict[str, Any]:
    """A vertical line through the panel."""
    xr, yr = _ref(axis)
    return {"type": "line", "xref": xr, "yref": f"{yr} domain", "x0": float(x), "x1": float(x), "y0": 0, "y1": 1,
            "line": {"color": color(color_), "dash": _DASH.get(dash, dash), "width": 1.2}, "name": name}


def vspan(x0: float, x1: float, *, color_: str = "0.92", axis: int = 1, name: str | None = None) -> dict[str, Any]:
    """A shaded band between ``x0`` and ``x1`` over the panel's height."""
    xr, yr = _ref(axis)
    return {"type": "rect", "xref": xr, "yref": f"{yr} domain", "x0": float(x0), "x1": float(x1), "y0": 0, "y1": 1,
            "fillcolor": color(color_), "line": {"width": 0}, "layer": "below", "name": name}


def _legend_of_shapes(shapes: Sequence[dict[str, Any]], axis: int = 1) -> list[dict[str, Any]]:
    """Legend entries for the named shapes (plotly lists traces only): an empty trace each."""
    out = []
    for s in shapes:
        if s.get("name"):
            style = s.get("line", {}) if s["type"] == "line" else {"color": s.get("fillcolor"), "width": 8}
            trace = {"type": "scatter", "mode": "lines", "x": [None], "y": [None], "name": s["name"],
                     "line": dict(style), "hoverinfo": "skip"}
            if axis > 1:
                trace["xaxis"], trace["yaxis"] = _ref(axis)
            out.append(trace)
    return out


def _axis(title: str, log: bool = False, **extra: Any) -> dict[str, Any]:
    out: dict[str, Any] = {"title": {"text": title}, "showline": True, "mirror": True, "linecolor": "#444",
                           "gridcolor": "#e5e5e5", "zeroline": False, "ticks": "outside", **extra}
    if log:
        out.update(type="log", tickformat=".3~g")
    return out


def figure(traces: list[dict[str, Any]], *, x: str, y: str, title: str, shapes: Sequence[dict[str, Any]] = (),
           xlog: bool = False, ylog: bool = False, equal: bool = False, height: int = 420,
           y2: str | None = None, y2log: bool = False, annotations: Sequence[dict[str, Any]] = ()) -> Chart:
    """A one-panel chart: ``x`` and ``y`` are the axis titles with their units."""
    shapes = [{k: v for k, v in s.items() if k != "name"} | ({"name": s["name"]} if s.get("name") else {})
              for s in shapes]
    layout: dict[str, Any] = {
        "title": {"text": title, "font": {"size": 13}}, "height": height, "margin": {"l": 70, "r": 70 if y2 else 20,
                                                                                       "t": 50, "b": 60},
        "xaxis": _axis(x, xlog), "yaxis": _axis(y, ylog), "shapes": list(shapes),
        "legend": {"orientation": "h", "y": -0.18, "font": {"size": 10}}, "annotations": list(annotations),
        "plot_bgcolor": "white", "hovermode": "closest"}
    if equal:
        layout["yaxis"].update(scaleanchor="x", scaleratio=1)
    if y2 is not None:
        layout["yaxis2"] = _axis(y2, y2log, overlaying="y", side="right", showgrid=False, mirror=False)
        layout["yaxis"]["mirror"] = False
    return {"data": traces + _legend_of_shapes(shapes), "layout": layout}


def _on(ref: str, n: int) -> str:
    """An axis reference (``"x"``, ``"y domain"``) moved to panel ``n``'s axes."""
    axis, _, rest = ref.partition(" ")
    return f"{axis[0]}{'' if n == 1 else n}" + (f" {rest}" if rest else "")


def panels(grid: tuple[int, int], items: list[dict[str, Any]], *, height: int = 700, title: str = "") -> Chart:
    """A chart of several panels: ``items`` each ``{"traces", "x", "y", "title", "shapes", "ylog"}``,
    row by row."""
    rows, cols = grid
    layout: dict[str, Any] = {"height": height, "margin": {"l": 70, "r": 20, "t": 60, "b": 60}, "shapes": [],
                              "annotations": [], "plot_bgcolor": "white", "hovermode": "closest",
                              "legend": {"orientation": "h", "y": -0.12, "font": {"size": 10}}}
    if title:
        layout["title"] = {"text": title, "font": {"size": 13}}
    data: list[dict[str, Any]] = []
    gap_x, gap_y = 0.1, 0.16
    for k, item in enumerate(items):
        r, c = divmod(k, cols)
        n = k + 1
        x0 = c * (1 + gap_x) / cols
        x1 = x0 + (1 - gap_x * (cols - 1)) / cols
        y1 = 1 - r * (1 + gap_y) / rows
        y0 = y1 - (1 - gap_y * (rows - 1)) / rows
        suffix = "" if n == 1 else str(n)
        layout[f"xaxis{suffix}"] = _axis(item["x"], anchor=f"y{suffix}", domain=[x0, x1])
        layout[f"yaxis{suffix}"] = _axis(item["y"], item.get("ylog", False), anchor=f"x{suffix}", domain=[y0, y1])
        for t in item["traces"]:
            if n > 1:
                t["xaxis"], t["yaxis"] = f"x{n}", f"y{n}"
            t.setdefault("legendgroup", str(n))
            data.append(t)
        for s in item.get("shapes", ()):
            placed = {k: v for k, v in s.items() if k != "name"}
            placed["xref"], placed["yref"] = _on(s["xref"], n), _on(s["yref"], n)
            layout["shapes"].append(placed)
        data += _legend_of_shapes(item.get("shapes", ()), n)
        layout["annotations"].append({"text": f"<b>{item['title']}</b>", "xref": "paper", "yref": "paper",
                                      "x": (x0 + x1) / 2, "y": y1 + 0.01, "xanchor": "center", "yanchor": "bottom",
                                      "showarrow": False, "font": {"size": 11}})
        for note in item.get("notes", ()):
            layout["annotations"].append({"text": note, "xref": f"x{suffix} domain", "yref": f"y{suffix} domain",
                                          "x": 0.5, "y": 0.5, "showarrow": False})
    return {"data": data, "layout": layout}


def _shown(values: Any, unit: str, shown: str | None = None) -> tuple[np.ndarray, str]:
    """An SI array in its display unit, and that unit (:func:`chaindrive.display.convert`)."""
    factor, name = convert(1.0, unit, shown)
    return np.asarray(values, float) * float(factor or 0.0), name


# --------------------------------------------------------------------------- charts
def wear_chart(result: Any) -> Chart:
    """Chain elongation over operating hours (as :func:`chaindrive.plotting.drive.wear_plot`)."""
    limit = 100 * result.elongation_limit
    return figure([line(result.hours, 100 * np.asarray(result.elongation), f"elongation ({result.model} model)",
                        color_="C0")],
                  shapes=[hline(limit, f"limit {limit:g} %", color_="tab:red"),
                          vline(result.hours_to_limit, f"{result.hours_to_limit:,.0f} h to the limit")],
                  x="operating time [h]", y="chain elongation [%]", title="Wear life")


_STYLES = {"free": ("-", "free entry"), "tangential": ("--", "tangential entry"),
           "chordal": ("-.", "chordal entry"), "guided": (":", "guided entry")}


def kinematics_chart(results: dict[str, Any]) -> Chart:
    """Chain velocity and acceleration over one tooth period (as
    :func:`chaindrive.plotting.kinematics.kinematics_plot`, angle in degrees)."""
    items = list(results.values())
    first = items[0]
    scale = 180.0 / np.pi
    vel, acc = [], []
    for r in items:
        style, label = _STYLES.get(r.entry, ("-", r.entry))
        if r.entry == "guided" and r.guide_height is not None:
            label = f"guided entry, H = {r.guide_height * 1000:.1f} mm"
        phi = np.asarray(r.phi) * scale
        vel.append(line(phi, r.velocity, label, color_="k", dash=style))
        acc.append(line(phi, r.acceleration, label, color_="k", dash=style, legend=False))
    chain = (f"link chain {first.bar_diameter * 1000:g}x{first.pitch * 1000:g}" if first.chain_type == "link"
             else f"roller chain p = {first.pitch * 1000:g} mm")
    cond = f"z = {first.teeth}, ω = {first.angular_velocity:g} s⁻¹"
    ls = [r.guide_end_distance for r in items if r.guide_end_distance is not None]
    if ls:
        cond += f", l = {ls[0]:g} m"
    chart = panels((2, 1), [
        {"traces": vel, "x": "wheel angle φ [°]", "y": "velocity v [m/s]",
         "title": f"Chain velocity, {chain}, {cond} (model: {first.model})"},
        {"traces": acc, "x": "wheel angle φ [°]", "y": "acceleration a [m/s²]",
         "title": f"Chain acceleration, {chain}, {cond} (model: {first.model})",
         "shapes": [hline(0.0, color_="0.6", dash="-", axis=2)]}], height=640)
    for axis in ("xaxis", "xaxis2"):
        chart["layout"][axis]["range"] = [0.0, first.period * scale]
    return chart


def skew_chart(result: Any) -> Chart:
    """Contact stress and relative life against skew (as :func:`chaindrive.plotting.strength.skew_plot`)."""
    from ..strength.skew import ARCMIN, MEASURED_SKEW_RANGE

    skew = np.atleast_1d(result.max_skew) / ARCMIN
    traces = [line(skew, np.atleast_1d(result.stress) / 1e6, "contact stress σ (Garshniev & Maksymovych eq. 1–2)",
                   color_="C3", width=2),
              line(skew, np.atleast_1d(result.relative_life_wear), "life L/L0, wear (∝ 1/Q_n, Archard)", color_="C0",
                   width=2, yaxis2=True),
              line(skew, np.atleast_1d(result.relative_life_fatigue),
                   "life L/L0, rolling fatigue (∝ Q_n^-10/3, ISO 281)", color_="C2", width=2, yaxis2=True),
              line([50, 50], [1 / 3, 1 / 2], "Garshniev & Maksymovych claim: 0→50′ cuts life 2…3 times",
                   color_="0.3", width=6, yaxis2=True)]
    g = float(np.atleast_1d(result.gamma)[0])
    k = float(np.atleast_1d(result.design_skew)[-1] / np.atleast_1d(result.max_skew)[-1])
    return figure(traces, x="largest skew φ_p,max [arcmin]", y="contact stress σ [MPa]",
                  y2="relative life L/L0 [-]", y2log=True, height=480,
                  shapes=[vspan(MEASURED_SKEW_RANGE[0] / ARCMIN, MEASURED_SKEW_RANGE[1] / ARCMIN,
                                name="measured skews 0°42′…3°26′ (Garshniev & Maksymovych)"),
                          hline(float(np.atleast_1d(result.stress_unskewed)[0]) / 1e6, "σ without skew (Hertz)",
                                color_="C3", dash=":"),
                          vline(50, color_="k", dash="--")],
                  title=f"Roller–tooth contact with skew (γ = {g:.5f}/arcmin², K_φ = {k:.2f})")


def rating_chart(rating: Any, operating: tuple[float, float] | None = None) -> Chart:
    """The rating chart of a :class:`~chaindrive.selection.ChainRating` (both limits, the galling
    line and region, lubrication bands, the operating point: speed [rad/s], power [W]), from
    :func:`chaindrive.plotting.drive.rating_curves` (as :func:`~chaindrive.plotting.drive.rating_plot`)."""
    from ..plotting.drive import rating_curves

    c = rating_curves(rating, operating=operating)
    shapes = []
    notes = []
    for region, (a, b, fill, text) in c["bands"].items():
        shapes.append(vspan(a, b, color_=fill))
        notes.append({"text": f"{region}: {text}", "x": math.log10(math.sqrt(a * b)), "xref": "x", "y": 0.98,
                      "yref": "y domain", "showarrow": False, "font": {"size": 9, "color": "#595959"},
                      "yanchor": "top"})
    traces = [line(c["rpm"], c["h1"], "link-plate fatigue (Shigley eq. 17-32)", color_="tab:blue", dash="--"),
              line(c["rpm"], c["h2"], "roller–bushing impact (Shigley eq. 17-33)", color_="tab:orange", dash="--"),
              line(c["rpm"], c["rated"], "rated power", color_="k", width=2)]
    if c["galling"] is not None:
        rpm, hg, top, bottom = c["galling"]
        traces.append(line(rpm, hg, "galling line (Shigley §17-5)", color_="tab:red"))
        band = line(list(rpm) + list(rpm)[::-1], list(top) + list(bottom)[::-1], "galling region (C')",
                    color_="tab:red", width=0)
        band.update(fill="toself", fillcolor="rgba(214,39,40,0.15)", fillpattern={"shape": "/", "fgcolor": "#d62728"})
        traces.append(band)
    if c["operating"] is not None:
        traces.append(points([c["operating"][0]], [c["operating"][1]], "operating point", color_="tab:red"))
    chart = figure(traces, x="small-sprocket speed [rpm]", y="power, all strands [kW]", xlog=True, ylog=True,
                   shapes=shapes, annotations=notes, title=c["title"], height=480)
    chart["layout"]["xaxis"]["range"] = [math.log10(c["xlim"][0]), math.log10(c["xlim"][1])]
    chart["layout"]["yaxis"]["range"] = [math.log10(c["ylim"][0]), math.log10(c["ylim"][1])]
    return chart


def life_chart(result: Any) -> Chart:
    """Four panels of the drive over its life (as :func:`chaindrive.plotting.life.life_plot`)."""
    pct = _shown(result.elongations, "1", "%")[0]
    limit = float(_shown(result.elongation_limit, "1", "%")[0])
    shapes1 = [hline(limit, f"drive's limit {limit:.3g} %", color_="tab:red")]
    if result.replacement_limit is not None:
        makers = float(_shown(result.replacement_limit, "1", "%")[0])
        shapes1.append(hline(makers, f"makers' limit {makers:.3g} %", color_="tab:orange", dash=":"))
    shapes1.append(vline(result.replacement_hours, f"{result.replacement_hours:,.0f} h (wear)"))
    if result.fatigue_life_hours is not None and result.fatigue_life_hours < 2 * result.replacement_hours:
        shapes1.append(vline(result.fatigue_life_hours, f"{result.fatigue_life_hours:,.0f} h (fatigue)",
                             color_="tab:purple", dash="-."))
    p1 = {"traces": [line(result.hours, _shown(result.elongation, "1", "%")[0], "wear elongation", color_="C0")],
          "shapes": shapes1, "x": "operating time [h]", "y": "chain elongation [%]",
          "title": f"Elongation over the life (governed by {result.governing})"}
    p2: dict[str, Any] = {"traces": [], "x": "chain elongation [%]", "y": "load ratio at jump-over / running T1/T2 [-]",
                          "title": "Jump-over margin", "ylog": True}
    if result.jump_over_margins is not None:
        for k, (name, curve) in enumerate(zip(result.wheel_names, result.jump_over_margins, strict=True)):
            if not np.all(np.isnan(np.asarray(curve, float))):
                p2["traces"].append(line(pct, curve, name, color_=f"C{k % 10}", markers=True))
        p2["shapes"] = [hline(1.0, "jump-over", color_="tab:red", axis=2)]
    else:
        p2["notes"] = ["no ISO 606 sprocket:<br>jump-over not modelled"]
    p3: dict[str, Any] = {"traces": [], "x": "chain elongation [%]", "y": "tensioner travel / take-up",
                          "title": "Take-up of the elongation"}
    if result.take_up is not None:
        tu, unit = _shown(result.take_up, "m")
        p3["traces"].append(line(pct, tu, None, color_="C0", markers=True))
        p3["y"] = f"tensioner travel / take-up [{unit}]"
    else:
        p3["notes"] = ["fixed centres: no take-up"]
    p4: dict[str, Any] = {"traces": [], "x": "chain elongation [%]", "y": "first span frequency",
                          "title": "Span frequencies of the worn chain"}
    if result.span_frequencies is not None:
        f, unit = _shown(result.span_frequencies, "rad/s", "Hz")
        names = result.wheel_names
        for j, row in enumerate(np.atleast_2d(f)):
            p4["traces"].append(line(pct, row, f"{names[j]} → {names[(j + 1) % len(names)]}", color_=f"C{j % 10}",
                                     markers=True))
        p4["y"] = f"first span frequency [{unit}]"
    return panels((2, 2), [p1, p2, p3, p4], height=760)


def _circle(cx: float, cy: float, r: float, n: int = 121) -> tuple[np.ndarray, np.ndarray]:
    t = np.linspace(0.0, 2 * np.pi, n)
    return cx + r * np.cos(t), cy + r * np.sin(t)


def layout_chart(analysis: Any) -> Chart:
    """The drive's layout: pitch circles, wrapped chain, spans with lengths and tensions, shaft
    loads to scale (as :func:`chaindrive.plotting.drive.layout_plot`)."""
    drive, layout, tensions = analysis.drive, analysis.layout, analysis.loads
    mm = 1e3
    w = layout.wrap
    n = len(layout.wheel_names)
    traces: list[dict[str, Any]] = []
    notes: list[dict[str, Any]] = []
    for i, name in enumerate(layout.wheel_names):
        cx, cy = w.centres[i] * mm
        traces.append(line(*_circle(cx, cy, w.radii[i] * mm), "pitch circle" if i == 0 else None, color_="0.4",
                           dash="--", width=0.8))
        a0 = np.arctan2(*(w.span_end[(i - 1) % n] - w.centres[i])[::-1])
        th = a0 + w.sides[i] * np.linspace(0, w.wrap_angle[i], 60)
        traces.append(line((w.centres[i, 0] + w.radii[i] * np.cos(th)) * mm,
                           (w.centres[i, 1] + w.radii[i] * np.sin(th)) * mm,
                           "wrapped chain, other spans" if i == 0 else None, color_="tab:blue", width=2))
        text = name
        if layout.teeth_in_mesh[i] is not None:
            text += f"<br>wrap {np.degrees(w.wrap_angle[i]):.0f}°, {layout.teeth_in_mesh[i]} in mesh"
        notes.append({"x": cx, "y": cy, "text": text, "showarrow": False, "font": {"size": 10}, "align": "left",
                      "xanchor": "left", "yanchor": "bottom"})
        traces.append(points([cx], [cy], None, color_="0.3", symbol="cross-thin", size=8))
    for j in range(n):
        kind = "tight" if j == layout.tight_span else ("slack" if j == layout.slack_span else "")
        col = {"tight": "tab:red", "slack": "tab:green"}.get(kind, "tab:blue")
        xs = [w.span_start[j, 0] * mm, w.span_end[j, 0] * mm]
        ys = [w.span_start[j, 1] * mm, w.span_end[j, 1] * mm]
        traces.append(line(xs, ys, f"{kind} span" if kind else None, color_=col, width=2))
        text = f"{w.span_length[j] * mm:.0f} mm"
        if tensions is not None:
            text += f", {tensions.span_tensions[j] / 1e3:.2f} kN"
        notes.append({"x": sum(xs) / 2, "y": sum(ys) / 2, "text": text, "showarrow": False, "yshift": -12,
                      "font": {"size": 10, "color": color(col)}})
    if tensions is not None:
        scale = 0.25 * np.ptp(w.centres[:, 0] * mm) / max(np.max(tensions.shaft_loads), 1e-9)
        for i in range(n):
            cx, cy = w.centres[i] * mm
            force, angle = tensions.shaft_loads[i], tensions.shaft_load_angles[i]
            notes.append({"x": cx + scale * force * np.cos(angle), "y": cy + scale * force * np.sin(angle),
                          "ax": cx, "ay": cy, "axref": "x", "ayref": "y", "text": "", "showarrow": True,
                          "arrowhead": 2, "arrowwidth": 1.5, "arrowcolor": color("tab:purple")})
        traces.append(line([None], [None], "shaft load (to scale)", color_="tab:purple"))
    title = f"{drive.name} — chain {drive.chain.name}, {layout.links} links"
    for note in notes:
        for key in ("x", "y", "ax", "ay"):
            if key in note and note[key] is not None:
                note[key] = float(note[key])
    return figure(traces, x="x [mm]", y="y [mm]", title=title, equal=True, annotations=notes, height=560)


def wheel_chart(wheel: Any) -> Chart:
    """A wheel's outline with its circles, seat centres and the seated chain (as
    :func:`chaindrive.plotting.geometry.geometry_plot`; rollers and pins as circles, a
    pocket wheel's links as their centre lines)."""
    mm = 1e3
    outline = wheel.outline()
    poly = outline.polyline(48) * mm
    outer = line(poly[:, 0], poly[:, 1], "outline", color_="black", width=1.0)
    outer.update(fill="toself", fillcolor="#d9e3ef")
    traces = [outer]
    r = outline.pitch_radius * mm
    traces.append(line(*_circle(0.0, 0.0, r, 361), f"pitch circle Ø{2 * r:.2f} mm", color_="r", dash="-.",
                       width=0.8))
    from ..plotting.geometry import circle_labels

    for i, (rr, label) in enumerate(circle_labels(wheel, outline)):
        traces.append(line(*_circle(0.0, 0.0, rr, 361), label, color_="grey", dash=("--", ":", "-.")[i % 3],
                           width=0.7))
    centres = np.asarray(outline.centres) * mm
    traces.append(points(centres[:, 0], centres[:, 1], "seat / pin / pocket centres", color_="g",
                         symbol="cross-thin", size=9))
    cls = type(wheel).__name__
    if cls in ("Sprocket", "TrackDriveWheel"):
        radius = (wheel.roller_diameter / 2 if cls == "Sprocket" else wheel.pin_radius) * mm
        xs: list[float | None] = []
        ys: list[float | None] = []
        for x, y in centres:
            cx, cy = _circle(x, y, radius, 37)
            xs += [*cx.tolist(), None]
            ys += [*cy.tolist(), None]
        traces.append(line(xs, ys, "rollers" if cls == "Sprocket" else "pins", color_="tab:orange", width=0.8))
    title = wheel.label() if hasattr(wheel, "label") else cls
    return figure(traces, x="x [mm]", y="y [mm]", title=title, equal=True, height=640)


def conveyor_chart(result: Any) -> Chart:
    """The running chain tension along the loop from the head's exit, wheels marked (as
    :func:`chaindrive.plotting.conveyor.conveyor_plot`)."""
    from ..display import DISPLAY

    unit, k = DISPLAY["N"]
    prof = result.tension_profile
    tension = k * np.asarray(prof.tension, dtype=float)
    top = float(np.max(tension)) if tension.size else 1.0
    traces = [line(prof.position, tension, "running tension", color_="C0", width=1.8),
              points([result.minimum_position], [k * float(result.minimum_tension)], "lowest", color_="C3",
                     symbol="triangle-down")]
    shapes = [hline(k * float(result.required_minimum), "stated minimum", color_="C3", dash=":")]
    notes = []
    for name, x in zip(result.wheel_names, result.wheel_positions, strict=True):
        shapes.append(vline(x, color_="0.7", dash="-"))
        notes.append({"x": float(x), "y": top * 1.02, "text": name, "textangle": -90, "showarrow": False,
                      "xanchor": "right", "yanchor": "bottom", "font": {"size": 9, "color": "#4d4d4d"}})
    chart = figure(traces, x="position along the chain from the head exit [m]", y=f"tension [{unit}]",
                   title="Chain pull along the conveyor", shapes=shapes, annotations=notes, height=400)
    chart["layout"]["yaxis"]["range"] = [min(0.0, float(np.min(tension))) if tension.size else 0.0, top * 1.25]
    return chart


def campbell_chart(result: Any) -> Chart:
    """Campbell diagram of the slack span with its tensioner: natural frequencies, excitations
    and their bands, the speeds with a frequency in a band, the design speed; rpm on top and
    Hz on the right (as :func:`chaindrive.plotting.vibration.campbell_plot`)."""
    from ..display import CONVERSIONS
    from ..plotting.vibration import _runs
    from ..units import angular_velocity_to_rpm

    per_hz = CONVERSIONS[("rad/s", "Hz")]
    w = np.asarray(result.speed, dtype=float)
    p = np.asarray(result.natural_frequencies, dtype=float)
    if p.ndim == 1:
        p = p[:, None]
    lo, hi = result.band
    ymax = 1.3 * float(np.max(p))
    traces: list[dict[str, Any]] = []
    for j, (name, mult) in enumerate(zip(result.excitation_names, result.excitation_multipliers, strict=True)):
        col = f"C{(1, 4, 5, 9, 8, 6)[j % 6]}"  # red is kept for the forbidden speeds
        f = mult * w
        above = lo * float(f.min()) > ymax
        where = f" (above the plot: {lo * f.min():.3g}–{hi * f.max():.3g} rad/s)" if above else ""
        band = line(list(w) + list(w)[::-1], list(lo * f) + list(hi * f)[::-1], None, color_=col, width=0)
        band.update(fill="toself", opacity=0.12, fillcolor=color(col), hoverinfo="skip")
        traces.append(band)
        traces.append(line(w, f, f"excitation {name}: {mult:g}·ω₁{where}", color_=col, dash="--", width=1.4))
    mode_colors = ["black", "navy", "darkgreen", "purple", "saddlebrown", "teal"]
    for i in range(p.shape[1]):
        low, high = float(np.min(p[:, i])), float(np.max(p[:, i]))
        value = (f"{low * per_hz:.3g} Hz ({low:.3g} rad/s)" if high - low <= 1e-3 * high
                 else f"{low * per_hz:.3g}…{high * per_hz:.3g} Hz ({low:.3g}…{high:.3g} rad/s) over the speeds")
        traces.append(line(w, p[:, i], f"natural frequency P{i + 1} = {value}", color_=mode_colors[i % 6],
                           dash=["-", "-.", ":"][i] if i < 3 else "-", width=2.0))
    shapes = []
    bad = np.asarray(result.min_margin) <= 0
    step = float(w[1] - w[0]) if w.size > 1 else 0.0
    for n, (a, b) in enumerate(_runs(bad)):
        shapes.append(vspan(max(w[0], w[a] - step / 2), min(w[-1], w[b] + step / 2), color_="rgba(255,0,0,0.07)",
                            name="speeds with a P_i inside the paper's band" if n == 0 else None))
    if result.design_speed is not None:
        shapes.append(vline(result.design_speed, f"design speed {result.design_speed:.3g} rad/s "
                                                 f"({angular_velocity_to_rpm(result.design_speed):.0f} rpm)",
                            color_="0.3"))
    chart = figure(traces, x="driving sprocket speed ω₁ [rad/s]", y="frequency [rad/s]", shapes=shapes,
                   title=("Campbell diagram: slack span with tensioner (the tensioner paper)<br>shaded round each "
                          f"excitation: the paper's band {lo:g} ≤ P/ω ≤ {hi:g} (information)"), height=560,
                   y2="frequency [Hz]")
    layout = chart["layout"]
    layout["xaxis"]["range"] = [float(w[0]), float(w[-1])]
    layout["yaxis"]["range"] = [0.0, ymax]
    layout["yaxis2"]["range"] = [0.0, ymax * per_hz]
    layout["xaxis2"] = _axis("n₁ [rpm]", overlaying="x", side="top", showgrid=False, mirror=False,
                             range=[float(angular_velocity_to_rpm(w[0])), float(angular_velocity_to_rpm(w[-1]))])
    layout["margin"]["t"] = 130
    layout["title"].update(y=0.98, yanchor="top")
    # the secondary axes carry no data of their own: an invisible trace each makes plotly draw them
    chart["data"] += [{"type": "scatter", "x": [None], "y": [None], "showlegend": False, "hoverinfo": "skip", **axis}
                      for axis in ({"yaxis": "y2"}, {"xaxis": "x2"})]
    return chart


def crawler_chart(items: list[Any]) -> Chart:
    """Drive-chain speed, acceleration and cam force (about its mean) over one tooth period of
    a crawler drive, angle in degrees (as :func:`chaindrive.plotting.crawler.crawler_plot`)."""
    from ..plotting.crawler import _STYLES as CRAWLER_STYLES

    with_force = any(r.force is not None for r in items)
    scale = 180.0 / np.pi
    vel, acc, force = [], [], []
    for r in items:
        style, col, label = CRAWLER_STYLES.get(r.guide, ("-", "k", r.guide))
        psi = np.asarray(r.psi) * scale
        vel.append(line(psi, r.velocity, label, color_=col, dash=style, width=1.6))
        acc.append(line(psi, r.acceleration, label, color_=col, dash=style, width=1.6, legend=False))
        if r.force is not None:
            force.append(line(psi, np.asarray(r.force) / 1e3, label, color_=col, dash=style, width=1.6, legend=False))
    first = items[0]
    cond = (f"t = {first.pitch * 1e3:g} mm, z = {first.teeth}, "
            f"ω = {first.angular_velocity:.4g} rad/s, R = {first.radius * 1e3:.1f} mm")
    nu = ", ".join(f"{r.guide}: δ = {100 * r.summary['nonuniformity']:.3g} %" for r in items)
    x = "sprocket angle ψ [°]"
    mean = first.summary["v_mean"]
    panel_list = [
        {"traces": vel, "x": x, "y": "velocity v [m/s]",
         "title": f"Crawler drive chain velocity ({cond})<br>non-uniformity {nu}",
         "shapes": [hline(mean, f"mean z t ω/2π = {mean:.4g} m/s", color_="0.5", dash=":")]},
        {"traces": acc, "x": x, "y": "acceleration a [m/s²]",
         "title": "Drive chain acceleration (jump at the seating ψ = 2π/z)",
         "shapes": [hline(0.0, color_="0.5", dash="-", axis=2)]}]
    if with_force:
        fr = next(r for r in items if r.force is not None)
        panel_list.append({"traces": force, "x": x, "y": "force P − P̄ [kN]",
                           "title": (f"Force on the cam about its mean (E_П = {fr.stiffness:.3g} N, "
                                     f"A = {fr.sprocket_distance:g} m, l = {fr.cam_distance:g} m)")})
    return panels((len(panel_list), 1), panel_list, height=300 * len(panel_list) + 80)


#: matplotlib's viridis at 0, 1/9, ..., 1 (sRGB), for line colours along a parameter.
_VIRIDIS = ((68, 1, 84), (72, 40, 120), (62, 74, 137), (49, 104, 142), (38, 130, 142), (31, 158, 137),
            (53, 183, 121), (109, 205, 89), (180, 222, 44), (253, 231, 37))


def viridis(values: Any) -> list[str]:
    """CSS colours of viridis at ``values`` in [0, 1] (linear between its tenths).

    >>> viridis([0.0, 1.0])
    ['rgb(68,1,84)', 'rgb(253,231,37)']
    """
    out = []
    for v in np.clip(np.asarray(values, dtype=float), 0.0, 1.0):
        x = v * (len(_VIRIDIS) - 1)
        i = min(int(x), len(_VIRIDIS) - 2)
        t = x - i
        rgb = [round(a + (b - a) * t) for a, b in zip(_VIRIDIS[i], _VIRIDIS[i + 1], strict=True)]
        out.append(f"rgb({rgb[0]},{rgb[1]},{rgb[2]})")
    return out


def self_regulating_chart(result: Any) -> Chart:
    """The self-regulating drive against load and wear: slack tension, regulation coefficient,
    centre distance, sag and, with the carrier's frequency, that frequency and the shaft load
    (as :func:`chaindrive.plotting.self_regulating.self_regulating_plot`)."""
    freq = result.carrier_frequency
    lam = np.asarray(result.load_factor)
    e = np.asarray(result.elongation)
    i1 = int(np.argmin(np.abs(lam - 1.0)))
    colours = viridis(np.linspace(0.0, 0.85, e.size))
    num = result.numerical_slack_tension is not None

    def curve(x: Any, y: Any, name: str | None, col: str, dash: str = "-", markers: bool = False,
              legend: bool = True) -> dict[str, Any]:
        trace = line(x, y, name, dash=dash, markers=markers, legend=legend)
        trace["line"]["color"] = col
        return trace

    def open_points(x: Any, y: Any, col: str) -> dict[str, Any]:
        trace = points(x, y, None, symbol="circle-open", size=6)
        trace["marker"].update(color=col, line={"color": col, "width": 1})
        return trace

    s2 = [curve(lam, result.slack_tension[:, j] / 1e3, f"e = {100 * e[j]:.2g} %", c) for j, c in enumerate(colours)]
    if num:
        s2 += [open_points(lam, result.numerical_slack_tension[:, j] / 1e3, c) for j, c in enumerate(colours)]
    p1: dict[str, Any] = {"traces": s2, "x": "load: torque / nominal torque [-]", "y": "slack tension S2 [kN]",
          "title": "Slack tension against load" + (" (○ numerical equilibrium)" if num else ""),
          "shapes": [hline(result.slack_tension_rational / 1e3, "S2* (sag allowance at rated load)", dash=":")]}
    p2 = {"traces": [line(100 * e, result.psi[i1], "ψ = ∂S2/∂F_t", color_="tab:blue", markers=True),
                     line(100 * e, result.rated_ratio, "S2/F_t at rated load", color_="tab:orange", markers=True)],
          "x": "wear elongation e [%]", "y": "coefficient [-]", "title": "Regulation coefficient ψ over the wear range",
          "shapes": [hline(result.psi_rational, f"rational ψ* = {result.psi_rational:.3g}", color_="0.3")]}
    centre = []
    for i, dash in ((0, ":"), (i1, "-"), (lam.size - 1, "--")):
        centre.append(line(100 * e, result.centre_distance[i] * 1e3, f"load {lam[i]:.2g}", color_="tab:green",
                           dash=dash))
        if result.numerical_centre_distance is not None:
            centre.append(open_points(100 * e, result.numerical_centre_distance[i] * 1e3, color("tab:green") or ""))
    unit = "rad" if result.coordinate_unit == "rad" else "mm"
    travel = result.carrier_travel * (1.0 if unit == "rad" else 1e3)
    p3 = {"traces": centre, "x": "wear elongation e [%]", "y": "centre distance a [mm]",
          "title": f"Centre distance (carrier travel {travel:.3g} {unit})"}
    p4 = {"traces": [line(100 * e, 100 * result.sag_ratio[i1], "slack span, rated load", color_="tab:red", markers=True),
                     line(100 * e, 100 * result.sag_ratio[0], f"load {lam[0]:.2g}", color_="tab:red", dash=":")],
          "x": "wear elongation e [%]", "y": "sag / chord [%]", "title": "Slack-span sag",
          "shapes": [hline(100 * result.sag_allowance, "allowance", color_="0.3")]}
    items: list[dict[str, Any]] = [p1, p2, p3, p4]
    grid = (2, 2)
    if freq is not None:
        ok = result.resonance_margin is None or bool(np.min(result.resonance_margin) > 0)
        bands = []
        for k, (name, w) in enumerate((result.excitations or {}).items()):
            band = {"type": "rect", "xref": "x domain", "yref": "y", "x0": 0, "x1": 1, "y0": 0.7 * w, "y1": 1.4 * w,
                    "fillcolor": color(f"C{(k + 1) % 10}"), "opacity": 0.15, "line": {"width": 0}, "layer": "below",
                    "name": f"0.7…1.4 × {name} ({w:.4g} rad/s)"}
            bands.append(band)
        p5 = {"traces": [curve(lam, freq[:, j], f"e = {100 * e[j]:.2g} %", c, markers=True, legend=False)
                         for j, c in enumerate(colours)],
              "x": "load: torque / nominal torque [-]", "y": "frequency [rad/s]", "ylog": True, "shapes": bands,
              "title": "Carrier natural frequency" + ("" if ok else " (in a forbidden band)")}
        with np.errstate(divide="ignore", invalid="ignore"):
            ratio = result.shaft_load[1:] / result.effective_pull[1:]
        p6 = {"traces": [curve(lam[1:], ratio[:, j], f"e = {100 * e[j]:.2g} %", c, legend=False)
                         for j, c in enumerate(colours)],
              "x": "load: torque / nominal torque [-]", "y": "shaft load / F_t [-]",
              "title": "Shaft load on the carrier wheel"}
        items = [p1, p2, p5, p3, p4, p6]  # reading order: S2, ψ, frequency / a, sag, shaft load
        grid = (2, 3)
    return panels(grid, items, height=780, title=(f"Self-regulating drive: wheel {result.wheel!r} on a "
                                                 f"{result.kind} carrier ({result.links} links)"))
