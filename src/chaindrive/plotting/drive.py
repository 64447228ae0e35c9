"""Plots of a drive: layout (wheels, spans, tensions), wear life, ANSI rating curve."""

from __future__ import annotations

import numpy as np

__all__ = ["layout_plot", "wear_plot", "rating_plot"]


def layout_plot(result, *, ax=None, tensions=None, title: str | None = None):
    """Drive layout: pitch circles, spans (tight/slack), wraps, shaft loads.

    Parameters
    ----------
    result : chaindrive.drive.DriveLayout or chaindrive.drive.Drive
        A layout result, or a drive (its :meth:`~chaindrive.drive.Drive.layout` and
        :meth:`~chaindrive.drive.Drive.tensions` are used).
    ax : matplotlib.axes.Axes, optional
    tensions : chaindrive.drive.DriveTensions, optional
        Adds span tensions and shaft-load arrows.
    title : str, optional

    Returns
    -------
    matplotlib.figure.Figure
    """
    import matplotlib.pyplot as plt
    from matplotlib.patches import Circle

    if hasattr(result, "layout") and callable(result.layout):
        drive = result
        result = drive.layout()
        if tensions is None:
            try:
                tensions = drive.tensions()
            except Exception:  # mass unknown etc.: plot the geometry only
                tensions = None
        title = title or f"{drive.name} — chain {drive.chain.name}, {result.links} links"
    if ax is None:
        fig, ax = plt.subplots(figsize=(9, 5))
    else:
        fig = ax.figure
    mm = 1e3
    w = result.wrap
    n = len(result.wheel_names)
    for i, name in enumerate(result.wheel_names):
        c = w.centres[i] * mm
        ax.add_patch(Circle(c, w.radii[i] * mm, fill=False, ls="--", lw=0.8, ec="0.4"))
        ax.plot(*c, "+", color="0.3")
        txt = name
        if result.teeth_in_mesh[i] is not None:
            txt += f"\nwrap {np.degrees(w.wrap_angle[i]):.0f}°, {result.teeth_in_mesh[i]} in mesh"
        ax.annotate(txt, c, xytext=(4, 4), textcoords="offset points", fontsize=8)
        # wrapped arc
        a0 = np.arctan2(*(w.span_end[(i - 1) % n] - w.centres[i])[::-1])
        th = a0 + w.sides[i] * np.linspace(0, w.wrap_angle[i], 60)
        ax.plot((w.centres[i, 0] + w.radii[i] * np.cos(th)) * mm,
                (w.centres[i, 1] + w.radii[i] * np.sin(th)) * mm, color="tab:blue", lw=2)
    for j in range(n):
        kind = "tight" if j == result.tight_span else ("slack" if j == result.slack_span else "")
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
    ax.set_aspect("equal")
    ax.autoscale_view()
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("y [mm]")
    ax.set_title(title or f"Drive layout, {result.links} links")
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=3, fontsize=8, frameon=False)
    fig.tight_layout()
    ax.grid(True, lw=0.3)
    return fig


def wear_plot(result, *, ax=None):
    """Chain elongation over operating hours, with the limit and the hours to it.

    Parameters
    ----------
    result : chaindrive.drive.wear.WearLife
    ax : matplotlib.axes.Axes, optional

    Returns
    -------
    matplotlib.figure.Figure
    """
    import matplotlib.pyplot as plt

    if ax is None:
        fig, ax = plt.subplots(figsize=(7, 4))
    else:
        fig = ax.figure
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


def rating_plot(pitch, teeth, *, strands=1, plate_constant=0.004, roller_constant=17.0,
                speed_range=(10.0, 10000.0), operating=None, ax=None, name: str = ""):
    """ANSI/ACA rated power against small-sprocket speed (both limits, log-log).

    Parameters
    ----------
    pitch : float
        [m].
    teeth : int
        Small-sprocket teeth.
    strands : int
    plate_constant, roller_constant : float
        See :func:`chaindrive.drive.selection.ansi_constants`.
    speed_range : (float, float)
        [rpm].
    operating : (float, float), optional
        Operating point (speed [rad/s], design power [W]) to mark.
    ax : matplotlib.axes.Axes, optional
    name : str
        Chain name for the title.

    Returns
    -------
    matplotlib.figure.Figure
    """
    import matplotlib.pyplot as plt

    from ..drive import selection as S

    if ax is None:
        fig, ax = plt.subplots(figsize=(7, 4.5))
    else:
        fig = ax.figure
    rpm = np.geomspace(*speed_range, 300)
    w = rpm * 2 * np.pi / 60
    k2 = S.multi_strand_factor(strands)
    h1 = k2 * S.ansi_link_plate_power(teeth, w, pitch, plate_constant) / 1e3
    h2 = k2 * S.ansi_roller_bushing_power(teeth, w, pitch, roller_constant) / 1e3
    ax.loglog(rpm, h1, ls="--", color="tab:blue", label="link-plate fatigue (eq. 17-32)")
    ax.loglog(rpm, h2, ls="--", color="tab:orange", label="roller–bushing impact (eq. 17-33)")
    ax.loglog(rpm, np.minimum(h1, h2), color="k", lw=2, label="rated power")
    if operating is not None:
        ax.loglog(operating[0] * 60 / (2 * np.pi), operating[1] / 1e3, "o", color="tab:red",
                  label="design point")
    ax.set_ylim(np.min(np.minimum(h1, h2)) * 0.8, np.max(np.minimum(h1, h2)) * 3)
    ax.set_xlabel("small-sprocket speed [rpm]")
    ax.set_ylabel("power [kW]")
    ax.set_title(f"ANSI/ACA rating {name} ({teeth} teeth, {strands} strand{'s' if strands > 1 else ''})")
    ax.legend(fontsize=8)
    ax.grid(True, which="both", lw=0.3)
    return fig
