"""Plots of wheel outlines: sprockets, pocket wheels, track drive wheels."""

from __future__ import annotations

import numpy as np

__all__ = ["geometry_plot"]


def geometry_plot(wheel, *, ax=None, form=None, detail: bool = False):
    """Plot a wheel outline (mm) with its pitch circle, reference circles and centres.

    Parameters
    ----------
    wheel : Sprocket, PocketWheel, TrackDriveWheel or Outline
        Anything with ``.outline()`` (the ``form`` argument is passed to sprockets), or an
        :class:`~chaindrive.geometry.outline.Outline`.
    ax : matplotlib.axes.Axes, optional
        Axes to draw into; a new figure is made when omitted.
    form : str, optional
        Tooth form for sprockets (``"min"``/``"max"``); ignored by other wheels.
    detail : bool
        Zoom on the top tooth gap / pocket instead of the whole wheel.

    Returns
    -------
    matplotlib.figure.Figure
    """
    import matplotlib.pyplot as plt

    from ..geometry.outline import Outline

    if isinstance(wheel, Outline):
        outline, title = wheel, "Outline"
    else:
        try:
            outline = wheel.outline(form=form) if form is not None else wheel.outline()
        except TypeError:
            outline = wheel.outline()
        title = wheel.label() if hasattr(wheel, "label") else type(wheel).__name__
    if ax is None:
        fig, ax = plt.subplots(figsize=(7, 7))
    else:
        fig = ax.figure
    mm = 1e3
    poly = outline.polyline(48) * mm
    ax.fill(poly[:, 0], poly[:, 1], color="#d9e3ef", zorder=1)
    ax.plot(poly[:, 0], poly[:, 1], color="black", lw=1.0, label="outline", zorder=3)
    t = np.linspace(0, 2 * np.pi, 721)
    r = outline.pitch_radius * mm
    ax.plot(r * np.cos(t), r * np.sin(t), "r-.", lw=0.8, label=f"pitch circle Ø{2 * r:.2f} mm", zorder=2)
    styles = ["--", ":", (0, (5, 1, 1, 1))]
    for i, (name, rad) in enumerate(outline.circles.items()):
        rr = float(rad) * mm
        ax.plot(rr * np.cos(t), rr * np.sin(t), color="grey", ls=styles[i % 3], lw=0.7,
                label=f"{name.lower()} circle Ø{2 * rr:.2f} mm", zorder=2)
    c = np.asarray(outline.centres) * mm
    ax.plot(c[:, 0], c[:, 1], "g+", ms=8, label="seat / pin / pocket centres", zorder=4)
    ax.set_aspect("equal")
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("y [mm]")
    ax.set_title(title)
    ax.grid(True, lw=0.3)
    if detail:
        rmax = float(np.max(np.hypot(poly[:, 0], poly[:, 1])))
        span = 2.2 * np.pi * rmax / max(len(c), 1)
        ax.set_xlim(-span, span)
        ax.set_ylim(r - span, r + 0.8 * span)
    ax.legend(loc="lower right" if not detail else "lower center", fontsize=8)
    return fig
