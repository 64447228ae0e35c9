"""Interactive plots of the studio as plotly.js figure specifications (JSON-ready dicts).

The numbers come from the library's functions (the ANSI/ACA rating, the tensioner
span's Campbell data and resonance map); this module only arranges them for plotly.js,
which the app serves from the installed ``plotly`` package (nothing from the internet).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from ..display import DISPLAY, kn_per_m
from ..errors import ChainDriveError
from ..units import angular_velocity_to_rpm, rpm_to_angular_velocity
from .display import IMPERIAL

if TYPE_CHECKING:
    from ..analysis.vibration import _Excitation
    from ..drive.model import Drive
    from ..vibration import TensionerSpan
    from .design import Design

__all__ = ["rating_chart", "campbell_chart", "resonance_map_chart", "tensioner_span_of"]

_LAYOUT = {"margin": {"l": 60, "r": 20, "t": 40, "b": 60}, "height": 400,
           "font": {"family": "DejaVu Sans, Arial, sans-serif", "size": 12},
           "paper_bgcolor": "#ffffff", "plot_bgcolor": "#fbfcfe",
           "legend": {"orientation": "h", "y": -0.3}}


def _power_unit(units: str) -> tuple[str, float]:
    return IMPERIAL["W"] if units == "imperial" else DISPLAY["W"]


def rating_chart(design: Design, *, units: str = "metric") -> dict[str, Any]:
    """Rating chart: rated power against small-wheel speed of the candidates, the duty marked.

    Roller chains: each by the rating method of its family (:func:`chaindrive.rating.default_method`:
    ANSI/ACA ``K2 min(H1, H2)``, Shigley eqs (17-32), (17-33), for the A series and ANSI;
    ISO 10823 for the B series) with the candidate's teeth; the title names the methods and
    a curve its method when they differ. Round link chains: the power the chain carries at
    the required static safety, ``F_B v / S`` (DIN 22252 breaking force).

    Examples
    --------
    >>> from chaindrive.web.design import design_from_state, normalise_state
    >>> d, _ = design_from_state(normalise_state({}))
    >>> fig = rating_chart(d)
    >>> fig["data"][-1]["name"]
    'operating point'
    """
    from ..chains import get
    from ..design.link import power_at_safety
    from ..rating import default_method, rated_power_curve

    method_labels = {"ansi": "ANSI/ACA", "iso10823": "ISO 10823"}

    label, factor = _power_unit(units)
    speeds = rpm_to_angular_velocity(np.geomspace(10, 6000, 120))
    traces = []
    names = [c["chain"] for c in design.candidates[:5]]
    if design.chain.name not in names:
        names.insert(0, design.chain.name)
    methods = {n: default_method(get(n)) for n in names if not get(n).is_link_chain}
    mixed = len(set(methods.values())) > 1
    for name in names:
        ch = get(name)
        if ch.is_link_chain:
            if ch.breaking_force is None:
                continue
            required = design.drive.static_safety_required if design.drive is not None else None
            power = power_at_safety(ch, design.teeth_driving, speeds, required)
        else:
            power = rated_power_curve(ch, design.teeth_driving, speeds)
        ok = np.isfinite(power) & (power > 0)
        shown = f"{name} ({method_labels.get(methods[name], methods[name])})" if mixed and name in methods else name
        traces.append({"type": "scatter", "mode": "lines", "name": shown,
                       "x": angular_velocity_to_rpm(speeds[ok]).round(3).tolist(), "y": (power[ok] * factor).round(5).tolist(),
                       "line": {"width": 3 if name == design.chain.name else 1.5},
                       "hovertemplate": f"{name}<br>%{{x:.0f}} rpm<br>%{{y:.3g}} {label}<extra></extra>"})
    traces.append({"type": "scatter", "mode": "markers", "name": "operating point",
                   "x": [angular_velocity_to_rpm(design.speed)], "y": [design.design_power * factor],
                   "marker": {"size": 13, "symbol": "x", "color": "#c0392b"},
                   "hovertemplate": f"design power K_s P<br>%{{x:.0f}} rpm<br>%{{y:.3g}} {label}<extra></extra>"})
    used = sorted({method_labels.get(m, m) for m in methods.values()}, key=lambda m: m != "ISO 10823")
    if not used:
        title = "Power at the required static safety, F_B v / S"
    elif len(used) > 1:
        title = f"Rated power by each chain's method ({', '.join(used)}), z1 = {design.teeth_driving}"
    elif used[0] == "ISO 10823":
        title = f"ISO 10823 rating, z1 = {design.teeth_driving}"
    else:
        title = f"ANSI/ACA rating (Shigley eqs 17-32, 17-33), z1 = {design.teeth_driving}"
    return {"data": traces, "layout": {**_LAYOUT, "title": {"text": title, "font": {"size": 13}},
                                       "xaxis": {"type": "log", "dtick": 1, "title": {"text": "small wheel speed [rpm]"}},
                                       "yaxis": {"type": "log", "dtick": 1, "title": {"text": f"power [{label}]"}}}}


def tensioner_span_of(drive: Drive) -> tuple[TensionerSpan, _Excitation] | None:
    """The ``TensionerSpan`` of a drive and the excitation keywords, or ``None``.

    ``None`` also when the tensioner moves almost along the chain (span parts inclined
    more than :data:`chaindrive.analysis.vibration.COUPLING_LIMIT_ANGLE` to the normal of its
    axis), where the tensioner paper's coupling vanishes.
    """
    from ..analysis.vibration import COUPLING_LIMIT_ANGLE
    from .engine import tensioner_span

    got = tensioner_span(drive)
    if got is None or max(got[0].angle_1, got[0].angle_2) > COUPLING_LIMIT_ANGLE:
        return None
    return got


def campbell_chart(drive: Drive) -> dict[str, Any] | None:
    """Campbell diagram of the slack span with its tensioner (the tensioner paper), or ``None``.

    Over the speed range of the analysis (:data:`chaindrive.analysis.vibration.CAMPBELL_RANGE`).

    Natural frequencies ``P_i`` against the driving speed, the excitations ``k_j ω`` and
    their forbidden bands ``0.7 k_j ω <= P <= 1.4 k_j ω``.
    """
    from ..analysis.vibration import CAMPBELL_RANGE
    from ..vibration import campbell

    got = tensioner_span_of(drive)
    if got is None:
        return None
    span, exc = got
    omega = float(drive.speed)
    res = campbell(span, (CAMPBELL_RANGE[0] * omega, CAMPBELL_RANGE[1] * omega), speeds=120, design_speed=omega, **exc)
    x = res.speed
    traces = []
    palette = ["#e67e22", "#16a085", "#8e44ad", "#2c3e50", "#d35400"]
    for j, (name, k) in enumerate(zip(res.excitation_names, res.excitation_multipliers, strict=True)):
        colour = palette[j % len(palette)]
        lo, hi = res.band
        traces.append({"type": "scatter", "mode": "lines", "x": x.tolist(), "y": (lo * k * x).tolist(),
                       "line": {"width": 0}, "showlegend": False, "hoverinfo": "skip"})
        traces.append({"type": "scatter", "mode": "lines", "x": x.tolist(), "y": (hi * k * x).tolist(),
                       "fill": "tonexty", "fillcolor": "rgba(231, 76, 60, 0.10)", "line": {"width": 0},
                       "name": f"forbidden band {lo}…{hi} × {name}", "hoverinfo": "skip",
                       "showlegend": j == 0})
        traces.append({"type": "scatter", "mode": "lines", "x": x.tolist(), "y": (k * x).tolist(),
                       "name": f"excitation {name}", "line": {"dash": "dash", "color": colour},
                       "hovertemplate": f"{name}<br>ω1 = %{{x:.3g}} rad/s<br>%{{y:.4g}} rad/s<extra></extra>"})
    for i in range(res.natural_frequencies.shape[1]):
        traces.append({"type": "scatter", "mode": "lines", "x": x.tolist(),
                       "y": res.natural_frequencies[:, i].tolist(), "name": f"P{i + 1}",
                       "line": {"width": 2.5, "color": "#2471a3"},
                       "hovertemplate": f"P{i + 1}<br>ω1 = %{{x:.3g}} rad/s<br>%{{y:.4g}} rad/s<extra></extra>"})
    ymax = float(np.max(res.natural_frequencies)) * 1.3
    return {"data": traces, "layout": {
        **_LAYOUT, "title": {"text": "Campbell diagram of the slack span with the tensioner", "font": {"size": 13}},
        "legend": {"orientation": "v", "x": 1.02, "y": 1, "font": {"size": 10}},
        "margin": {"l": 60, "r": 10, "t": 40, "b": 50},
        "xaxis": {"title": {"text": "driving wheel speed ω1 [rad/s]"}},
        "yaxis": {"title": {"text": "frequency [rad/s]"}, "range": [0, ymax]},
        "shapes": [{"type": "line", "x0": omega, "x1": omega, "y0": 0, "y1": ymax,
                    "line": {"color": "#c0392b", "width": 2}}],
        "annotations": [{"x": omega, "y": ymax, "text": "design speed", "showarrow": False,
                         "yanchor": "bottom", "font": {"color": "#c0392b"}}]}}


def resonance_map_chart(drive: Drive, *, points: int = 31) -> dict[str, Any] | None:
    """Resonance-free region over tensioner mass and stiffness (±1.5 decades), or ``None``.

    The smallest margin to the forbidden band over ±10 % of the design speed
    (:func:`chaindrive.vibration.resonance_map`, the tensioner paper's criterion); the
    region ``margin >= 0`` is free of resonance. The design is marked.
    """
    from ..analysis.vibration import PROPOSAL_RANGE
    from ..vibration import resonance_map

    got = tensioner_span_of(drive)
    if got is None:
        return None
    span, exc = got
    omega = float(drive.speed)
    m0, c0 = float(span.mass), float(span.stiffness)
    masses = np.geomspace(m0 / 31.6, m0 * 31.6, points)
    stiff = np.geomspace(c0 / 31.6, c0 * 31.6, points)
    try:
        res = resonance_map(span, masses, stiff, (PROPOSAL_RANGE[0] * omega, PROPOSAL_RANGE[1] * omega), speeds=7, **exc)
    except ChainDriveError:
        return None
    z = np.clip(np.asarray(res.min_margin, dtype=float), -1.0, 1.0)
    z = np.where(np.isfinite(z), z, -1.0)
    return {"data": [
        {"type": "heatmap", "x": kn_per_m(stiff).tolist(), "y": masses.tolist(), "z": z.tolist(),
         "zmin": -0.5, "zmax": 0.5, "colorscale": [[0, "#e74c3c"], [0.5, "#fdfefe"], [1, "#27ae60"]],
         "colorbar": {"title": {"text": "margin"}},
         "hovertemplate": "C = %{x:.4g} kN/m<br>m = %{y:.4g} kg<br>margin %{z:.3f}<extra></extra>"},
        {"type": "contour", "x": kn_per_m(stiff).tolist(), "y": masses.tolist(), "z": z.tolist(),
         "contours": {"start": 0, "end": 0, "size": 1, "coloring": "lines"}, "showscale": False,
         "line": {"width": 2, "color": "#1e8449"}, "hoverinfo": "skip", "name": "margin = 0"},
        {"type": "scatter", "mode": "markers", "x": [kn_per_m(c0)], "y": [m0], "name": "design",
         "marker": {"size": 14, "symbol": "circle-open", "color": "#111", "line": {"width": 3}},
         "hovertemplate": "design<br>C = %{x:.4g} kN/m<br>m = %{y:.4g} kg<extra></extra>"}],
        "layout": {**_LAYOUT, "title": {"text": "Resonance-free tensioners (green: margin >= 0 over ±10 % speed)",
                                        "font": {"size": 13}},
                   "xaxis": {"type": "log", "dtick": 1, "title": {"text": "tensioner stiffness C [kN/m]"}},
                   "yaxis": {"type": "log", "dtick": 1, "title": {"text": "tensioner mass m [kg]"}}}}
