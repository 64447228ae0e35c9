"""Plots of a drive: layout (wheels, spans, tensions), wear life, ANSI rating curve."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from ..units import angular_velocity_to_rpm, rpm_to_angular_velocity
from ._axes import figure_of, subplots

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from ..analysis import DriveAnalysis
    from ..analysis.layout import DriveLayout
    from ..analysis.loads import DriveLoads
    from ..drive.model import Drive
    from ..life.wear import WearLife
    from ..selection import ChainRating

__all__ = ["layout_plot", "wear_plot", "rating_plot", "rating_curves"]


def layout_plot(result: DriveAnalysis | DriveLayout | Drive, *, ax: Axes | None = None,
                tensions: DriveLoads | None = None, title: str | None = None) -> Figure:
    """Drive layout: pitch circles, spans (tight/slack), wraps, shaft loads.

    Parameters
    ----------
    result : chaindrive.analysis.DriveAnalysis, chaindrive.analysis.DriveLayout or chaindrive.drive.Drive
        An analysis (its layout and loads are drawn), a layout, or a drive (analysed
        for its layout and loads).
    ax : matplotlib.axes.Axes, optional
    tensions : chaindrive.analysis.DriveLoads, optional
        Adds span tensions and shaft-load arrows (taken from an analysis when given one).
    title : str, optional

    Returns
    -------
    matplotlib.figure.Figure
    """
    from matplotlib.patches import Circle

    from ..analysis import DriveAnalysis, analyze_drive
    from ..drive.model import Drive
    from ..errors import ChainDriveError, InputError

    if isinstance(result, Drive):
        given = result
        try:
            result = analyze_drive(given, include=["layout", "loads"])
        except ChainDriveError:  # mass unknown etc.: plot the geometry only
            result = analyze_drive(given, include=["layout"])
    if isinstance(result, DriveAnalysis):
        drive = result.drive
        tensions = result.loads if tensions is None else tensions
        if result.layout is None:
            raise InputError("layout_plot needs an analysis with its layout (include 'layout')", field="result")
        layout = result.layout
        title = title or f"{drive.name} — chain {drive.chain.name}, {layout.links} links"
    else:
        layout = result
    mm = 1e3
    w = layout.wrap
    n = len(layout.wheel_names)
    # extents of the drawing: every pitch circle and span end, with a margin for the labels
    pts = np.vstack([w.centres - w.radii[:, None], w.centres + w.radii[:, None], w.span_start, w.span_end]) * mm
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    size = max(float(np.max(hi - lo)), 1e-9)
    margin = 0.07 * size
    lo, hi = lo - margin, hi + margin
    own_figure = ax is None
    if ax is None:
        # fixed margins [in] (tick labels and axis labels; the legend below the x label), and
        # the figure's height fitted to the drawing's aspect: no layout pass when drawn
        left, right, bottom, top, width = 0.85, 0.25, 0.85, 0.45, 10.0
        aspect = float((hi[1] - lo[1]) / (hi[0] - lo[0]))
        height = float(np.clip((width - left - right) * aspect + bottom + top, 3.4, 9.5))
        fig, ax = subplots(figsize=(width, height))
        fig.subplots_adjust(left=left / width, right=1 - right / width, bottom=bottom / height, top=1 - top / height)
    else:
        fig = figure_of(ax)
    for i, name in enumerate(layout.wheel_names):
        c = w.centres[i] * mm
        ax.add_patch(Circle(c, w.radii[i] * mm, fill=False, ls="--", lw=0.8, ec="0.4"))
        ax.plot(*c, "+", color="0.3")
        txt = name
        if layout.teeth_in_mesh[i] is not None:
            txt += f"\nwrap {np.degrees(w.wrap_angle[i]):.0f}°, {layout.teeth_in_mesh[i]} in mesh"
        right = c[0] > lo[0] + 0.75 * (hi[0] - lo[0])  # names near the right edge read leftwards, inside the figure
        ax.annotate(txt, c, xytext=(-4 if right else 4, 4), textcoords="offset points", fontsize=8,
                    ha="right" if right else "left")
        # wrapped arc
        a0 = np.arctan2(*(w.span_end[(i - 1) % n] - w.centres[i])[::-1])
        th = a0 + w.sides[i] * np.linspace(0, w.wrap_angle[i], 60)
        ax.plot((w.centres[i, 0] + w.radii[i] * np.cos(th)) * mm,
                (w.centres[i, 1] + w.radii[i] * np.sin(th)) * mm, color="tab:blue", lw=2)
    for j in range(n):
        kind = "tight" if j == layout.tight_span else ("slack" if j == layout.slack_span else "")
        color = {"tight": "tab:red", "slack": "tab:green"}.get(kind, "tab:blue")
        xs = np.array([w.span_start[j, 0], w.span_end[j, 0]]) * mm
        ys = np.array([w.span_start[j, 1], w.span_end[j, 1]]) * mm
        label = f"{kind} span" if kind else None
        ax.plot(xs, ys, color=color, lw=2, label=label)
        mid = (w.span_start[j] + w.span_end[j]) / 2 * mm
        text = f"{w.span_length[j] * mm:.0f} mm"
        if tensions is not None:
            text += f", {tensions.span_tensions[j] / 1e3:.2f} kN"
        ax.annotate(text, mid, xytext=(0, -12), textcoords="offset points", fontsize=8,
                    ha="center", color=color)
    if tensions is not None:
        scale = 0.25 * np.ptp(w.centres[:, 0] * mm) / max(np.max(tensions.shaft_loads), 1e-9)
        for i in range(n):
            c = w.centres[i] * mm
            F, a = tensions.shaft_loads[i], tensions.shaft_load_angles[i]
            ax.annotate("", xy=(c[0] + scale * F * np.cos(a), c[1] + scale * F * np.sin(a)), xytext=c,
                        arrowprops=dict(arrowstyle="->", color="tab:purple", lw=1.5))
        ax.plot([], [], color="tab:purple", label="shaft load (to scale)")
    ax.set_aspect("equal", adjustable="datalim" if not own_figure else "box")
    ax.set_xlim(lo[0], hi[0])  # fitted to the wheels and spans, 7 % margin
    ax.set_ylim(lo[1], hi[1])
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("y [mm]")
    ax.set_title(title or f"Drive layout, {layout.links} links")
    ax.plot([], [], color="tab:blue", lw=2, label="wrapped chain, other spans")
    ax.plot([], [], color="0.4", ls="--", lw=0.8, label="pitch circle")
    if own_figure:  # legend outside the drawing, below it
        fig.legend(*ax.get_legend_handles_labels(), loc="lower center", ncol=5, fontsize=8, frameon=False)
        from matplotlib.layout_engine import PlaceHolderLayoutEngine

        # laid out here: a report keeps these margins (an engine that moves nothing)
        fig.set_layout_engine(PlaceHolderLayoutEngine(adjust_compatible=True, colorbar_gridspec=True))
    else:
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0, fontsize=8, frameon=False)
    ax.grid(True, lw=0.3)
    return fig


def wear_plot(result: WearLife, *, ax: Axes | None = None) -> Figure:
    """Chain elongation over operating hours, with the limit and the hours to it.

    Parameters
    ----------
    result : chaindrive.life.wear.WearLife
    ax : matplotlib.axes.Axes, optional

    Returns
    -------
    matplotlib.figure.Figure
    """

    if ax is None:
        fig, ax = subplots(figsize=(7, 4))
    else:
        fig = figure_of(ax)
    ax.plot(result.hours, 100 * result.elongation, label=f"elongation ({result.model} model)")
    ax.axhline(100 * result.elongation_limit, color="tab:red", ls="--",
               label=f"limit {100 * result.elongation_limit:g} %")
    ax.axvline(result.hours_to_limit, color="0.4", ls=":",
               label=f"{result.hours_to_limit:,.0f} h to the limit")
    ax.set_xlabel("operating time [h]")
    ax.set_ylabel("chain elongation [%]")
    ax.set_title("Wear life")
    ax.legend()
    ax.grid(True, lw=0.3)
    return fig


def rating_plot(result: ChainRating | float, teeth: int | None = None, *, strands: int = 1,
                plate_constant: float = 0.004, roller_constant: float = 17.0,
                speed_range: tuple[float, float] | None = None, operating: tuple[float, float] | None = None,
                ax: Axes | None = None, name: str = "") -> Figure:
    """Rating chart (ANSI/ACA or ISO 10823 form): both limits, the galling line, lubrication regions, operating point.

    Parameters
    ----------
    result : chaindrive.selection.ChainRating or float
        A rating (:func:`~chaindrive.selection.chain_rating`: chain, teeth,
        strands and the operating point are taken from it), or the chain pitch [m]
        (then ``teeth`` is required).
    teeth : int, optional
        Small-sprocket teeth (with a pitch).
    strands : int
        Number of strands (with a pitch).
    plate_constant, roller_constant : float
        See :func:`chaindrive.selection.ansi_constants` (with a pitch).
    speed_range : (float, float), optional
        Small-sprocket speeds plotted [rpm]; default 10 rpm to the galling speed at
        zero tension (at most 20 000 rpm).
    operating : (float, float), optional
        Operating point (speed [rad/s], design power [W]); with a rating, default its
        speed and the power of its galling check.
    ax : matplotlib.axes.Axes, optional
    name : str
        Chain name for the title.

    Returns
    -------
    matplotlib.figure.Figure

    Notes
    -----
    Power in kW, all strands (multi-strand factor). The galling line is the power at
    which the joints gall at each speed (Shigley §17-5); above it (hatched) lies the
    galling region, type C' lubrication. Only its falling branch is drawn: below the
    speed of its maximum the galling tension is of the order of the breaking force. The lubrication bands A (manual/drip),
    B (bath/disc), C (oil stream) are the chain-speed limits of
    :func:`~chaindrive.selection.lubrication_limits` converted to sprocket speed.
    """
    c = rating_curves(result, teeth, strands=strands, plate_constant=plate_constant,
                      roller_constant=roller_constant, speed_range=speed_range, operating=operating, name=name)
    if ax is None:
        fig, ax = subplots(figsize=(8, 5))
    else:
        fig = figure_of(ax)
    ymax = c["ylim"][1]
    for region, (a, b, fill, text) in c["bands"].items():
        ax.axvspan(a, b, color=fill, zorder=0)
        ax.text(np.sqrt(a * b), ymax / 1.15, f"{region}: {text}", ha="center", va="top", fontsize=7, color="0.35")
    rpm = c["rpm"]
    ax.loglog(rpm, c["h1"], ls="--", color="tab:blue", label="link-plate fatigue (Shigley eq. 17-32)")
    ax.loglog(rpm, c["h2"], ls="--", color="tab:orange", label="roller–bushing impact (Shigley eq. 17-33)")
    ax.loglog(rpm, c["rated"], color="k", lw=2, label="rated power")
    if c["galling"] is not None:  # the galling speed may lie beyond the plotted range (small chains)
        g_rpm, hg, top, bottom = c["galling"]
        ax.loglog(g_rpm, hg, color="tab:red", lw=1.5, label="galling line (Shigley §17-5)")
        ax.fill_between(g_rpm, bottom, top, facecolor="none", hatch="///",
                        edgecolor="tab:red", lw=0, alpha=0.35, label="galling region (C')")
    if c["operating"] is not None:
        ax.loglog(*c["operating"], "o", color="tab:red", mec="k", ms=8, label="operating point", zorder=5)
    ax.set_xlim(*c["xlim"])
    ax.set_ylim(*c["ylim"])
    ax.set_xlabel("small-sprocket speed [rpm]")
    ax.set_ylabel("power, all strands [kW]")
    ax.set_title(c["title"], fontsize=10)
    ax.legend(fontsize=7, loc="lower left")
    ax.grid(True, which="both", lw=0.3)
    return fig


def rating_curves(result: ChainRating | float, teeth: int | None = None, *, strands: int = 1,
                  plate_constant: float = 0.004, roller_constant: float = 17.0,
                  speed_range: tuple[float, float] | None = None, operating: tuple[float, float] | None = None,
                  name: str = "") -> dict[str, Any]:
    """The lines of :func:`rating_plot` as data (speeds [rpm], powers [kW]): ``rpm``, ``h1``
    (link-plate), ``h2`` (roller-bushing), ``rated``, ``galling`` (speeds, galling power, top
    and bottom of the galling region on its falling branch; None when outside the range),
    ``bands`` (lubrication region: (from, to, colour, text)), ``operating`` (speed, power),
    ``xlim``, ``ylim``, ``title``. Parameters as :func:`rating_plot`.

    Examples
    --------
    >>> c = rating_curves(0.0254, 19)
    >>> float(c["rpm"][0]), sorted(c["bands"])[0]
    (10.0, 'A')
    """
    import warnings

    from .. import selection as S
    from ..errors import ValidityRangeWarning
    from ..rating import branch_powers

    basis: int | None = None   # ISO 10823: the branches on its 19-tooth basis, then f2
    if isinstance(result, S.ChainRating):
        r = result
        pitch, teeth, strands = r.pitch, r.teeth, r.strands
        from ..rating import rating_constants

        plate_constant, roller_constant = rating_constants(r.chain, r.method)
        method_label = "ISO 10823" if r.method == "iso10823" else "ANSI/ACA"
        if r.method == "iso10823":
            from ..rating.iso10823 import REFERENCE_TEETH

            basis = REFERENCE_TEETH
        name = name or r.chain
        if operating is None:
            operating = (r.angular_velocity, r.tension * r.chain_speed * S.multi_strand_factor(strands))
    else:
        method_label = "ANSI/ACA"
        pitch = float(result)
        if teeth is None:
            raise TypeError("rating_plot needs teeth when given a pitch")
    k2 = S.multi_strand_factor(strands)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityRangeWarning)
        n0 = angular_velocity_to_rpm(float(S.galling_speed(pitch, teeth, 0.0)))
        lo, hi = speed_range if speed_range is not None else (10.0, min(max(1.05 * n0, 100.0), 20000.0))
        rpm = np.geomspace(lo, hi, 400)
        w = rpm_to_angular_velocity(rpm)
        b1, b2 = branch_powers(pitch, teeth, w, plate_constant=plate_constant, roller_constant=roller_constant,
                               basis_teeth=basis)   # the rating's own branches (ISO 10823: on 19 teeth, f2)
        h1, h2 = k2 * b1 / 1e3, k2 * b2 / 1e3
        hg = k2 * S.galling_power(pitch, teeth, w) / 1e3
        va, vb = S.lubrication_limits(pitch)
    rated = np.minimum(h1, h2)
    ymin, ymax = float(np.min(rated)) * 0.5, float(np.max(rated)) * 3
    if operating is not None:
        ymin, ymax = min(ymin, operating[1] / 1e3 * 0.8), max(ymax, operating[1] / 1e3 * 1.5)
    # lubrication bands: chain speed v = z p w / (2 pi) -> sprocket speed
    to_rpm = 60.0 / (teeth * pitch)
    edges = [lo, float(va) * to_rpm, float(vb) * to_rpm, hi]
    colors = {"A": "#e8f5e9", "B": "#fff8e1", "C": "#fdecea"}
    bands = {}
    for k, region in enumerate("ABC"):
        a, b = max(edges[k], lo), min(edges[k + 1], hi)
        if a < b:
            bands[region] = (a, b, colors[region], S.LUBRICATION_REGIONS[region])
    # the galling power rises with speed to a maximum, then falls to 0 at the zero-tension
    # galling speed; the rising branch lies at tensions of the order of the breaking force
    # and is not drawn
    falling = rpm >= rpm[int(np.argmax(hg))]
    ok = falling & (hg > 0)
    top = np.full_like(rpm, ymax)
    bottom = np.where(ok, np.clip(hg, ymin, ymax), ymin)
    shown = falling & (bottom < top)
    galling = (rpm[ok], hg[ok], top[ok], bottom[ok]) if np.any(shown) else None
    point = None if operating is None else (angular_velocity_to_rpm(operating[0]), operating[1] / 1e3)
    title = (f"{method_label} rating {name} ({teeth} teeth, {strands} strand{'s' if strands > 1 else ''}); "
             "lubrication A/B/C by chain speed")
    return {"rpm": rpm, "h1": h1, "h2": h2, "rated": rated, "galling": galling, "bands": bands, "operating": point,
            "xlim": (lo, hi), "ylim": (ymin, ymax), "title": title}

