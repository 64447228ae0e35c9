"""Plots of wheel outlines: sprockets, pocket wheels, track drive wheels."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from ._axes import figure_of, subplots

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from ..geometry.outline import Outline
    from ..geometry.pocket_wheel import PocketWheel
    from ..geometry.sprocket import Sprocket
    from ..geometry.track_wheel import TrackDriveWheel

__all__ = ["geometry_plot", "circle_labels"]


def _chain_overlay(ax, wheel, mm):
    """Draw the chain on the wheel: rollers, pins, or round links (internal)."""
    from matplotlib.patches import Circle, FancyBboxPatch, Rectangle
    from matplotlib.transforms import Affine2D

    cls = type(wheel).__name__
    if cls in ("Sprocket", "TrackDriveWheel"):
        radius = wheel.roller_diameter / 2 if cls == "Sprocket" else wheel.pin_radius
        name = "rollers" if cls == "Sprocket" else "pins"
        c = wheel.outline().centres
        for i, (x, y) in enumerate(c):
            ax.add_patch(Circle((x * mm, y * mm), radius * mm, fill=False, ec="tab:orange", lw=0.8,
                                label=name if i == 0 else None, zorder=5))
    elif cls == "PocketWheel":
        d = wheel.dimensions()
        t, bar = d.pitch, d.bar_diameter
        b = wheel.inner_width if wheel.inner_width is not None else 21.0 / 18.0 * bar
        for i, th in enumerate(d.pocket_angles):
            # horizontal link seen edge-on: outer length t + 2d, thickness d, centre on the chord
            rot = Affine2D().rotate(th - np.pi / 2) + ax.transData
            hc = d.horizontal_link_centre_distance * mm
            ax.add_patch(Rectangle((-(t / 2 + bar) * mm, hc - bar / 2 * mm), (t + 2 * bar) * mm, bar * mm,
                                   fill=False, ec="tab:orange", lw=0.8, transform=rot, zorder=5,
                                   label="horizontal links (edge-on)" if i == 0 else None))
        for i, th in enumerate(d.vertical_link_angles):
            # vertical link in the wheel plane: outer length t + 2d, outer width b + 2d
            rot = Affine2D().rotate(th - np.pi / 2) + ax.transData
            vc = d.vertical_link_centre_distance * mm
            w_out, l_out = (b + 2 * bar) * mm, (t + 2 * bar) * mm
            ax.add_patch(FancyBboxPatch((-l_out / 2 + w_out / 2, vc - w_out / 2 + w_out / 2), l_out - w_out, 0.0,
                                        boxstyle=f"round,pad={w_out / 2}", fill=False, ec="tab:purple", lw=0.8,
                                        transform=rot, zorder=5,
                                        label="vertical links (in plane)" if i == 0 else None))


def circle_labels(wheel: Any, outline: Any) -> list[tuple[float, str]]:
    """The radius [mm] and legend label of each circle of a wheel's outline (tip, root...):
    a sprocket's drawn gap bottom beside its ISO 606 root diameter df = d − d1 when the two
    differ."""
    from ..geometry.outline import Outline

    mm = 1e3
    nominal_root = None
    if not isinstance(wheel, Outline) and hasattr(wheel, "dimensions"):
        nominal_root = getattr(wheel.dimensions(), "root_diameter", None)
    out = []
    for name, rad in outline.circles.items():
        rr = float(rad) * mm
        label = f"{name.lower()} circle Ø{2 * rr:.2f} mm"
        if name == "ROOT" and nominal_root is not None and abs(2 * rr - nominal_root * mm) > 0.005:
            label = (f"gap bottom of the drawn form Ø{2 * rr:.2f} mm "
                     f"(ISO 606 root diameter df = {nominal_root * mm:.2f} mm)")
        out.append((rr, label))
    return out


def geometry_plot(
    wheel: Sprocket | PocketWheel | TrackDriveWheel | Outline,
    *,
    ax: Axes | None = None,
    form: str | None = None,
    detail: bool = False,
    chain: bool = True,
) -> Figure:
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
    chain : bool
        Draw the chain seated on the wheel: rollers (sprockets), pins (track wheels), or
        the horizontal links edge-on and the vertical links in plane (pocket wheels).

    Returns
    -------
    matplotlib.figure.Figure
    """

    from ..geometry.outline import Outline

    if isinstance(wheel, Outline):
        outline, title = wheel, "Outline"
    else:
        try:
            outline = wheel.outline(form=form) if form is not None else wheel.outline()
        except TypeError:
            outline = wheel.outline()
        title = wheel.label() if hasattr(wheel, "label") else type(wheel).__name__
    own_figure = ax is None
    if ax is None:
        fig, ax = subplots(figsize=(7.8, 7.4))  # room for the legend of long labels below
        # fixed margins [in]: tick and axis labels, the title, the legend's rows below
        fig.subplots_adjust(left=0.7 / 7.8, right=1 - 0.5 / 7.8, bottom=1.3 / 7.4, top=1 - 0.4 / 7.4)
    else:
        fig = figure_of(ax)
    mm = 1e3
    poly = outline.polyline(48) * mm
    # a collection, not ax.fill: a patch's data limits walk its thousands of vertices in Python (0.1 s)
    from matplotlib.collections import PolyCollection

    ax.add_collection(PolyCollection([poly], facecolors="#d9e3ef", edgecolors="#d9e3ef", linewidths=1.0,
                                     zorder=1))
    ax.plot(poly[:, 0], poly[:, 1], color="black", lw=1.0, label="outline", zorder=3)
    t = np.linspace(0, 2 * np.pi, 721)
    r = outline.pitch_radius * mm
    ax.plot(r * np.cos(t), r * np.sin(t), "r-.", lw=0.8, label=f"pitch circle Ø{2 * r:.2f} mm", zorder=2)
    styles = ["--", ":", (0, (5, 1, 1, 1))]
    for i, (rr, label) in enumerate(circle_labels(wheel, outline)):
        ax.plot(rr * np.cos(t), rr * np.sin(t), color="grey", ls=styles[i % 3], lw=0.7, label=label, zorder=2)
    c = np.asarray(outline.centres) * mm
    ax.plot(c[:, 0], c[:, 1], "g+", ms=8, label="seat / pin / pocket centres", zorder=4)
    if chain and not isinstance(wheel, Outline):
        _chain_overlay(ax, wheel, mm)
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
    # below the drawing, never over the teeth
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.09), ncol=2, fontsize=8, frameon=False)
    if own_figure:
        from matplotlib.layout_engine import PlaceHolderLayoutEngine

        # laid out here: a report keeps these margins (an engine that moves nothing)
        fig.set_layout_engine(PlaceHolderLayoutEngine(adjust_compatible=True, colorbar_gridspec=True))
    elif fig.get_layout_engine() is None and ax is fig.axes[0] and len(fig.axes) == 1:
        fig.tight_layout()
    return fig
