"""Plots of the crawler drive chain (the crawler drive text, Fig. 6.9 c)."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING

import numpy as np

from ._axes import figure_of, results_list

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from ..kinematics.crawler import CrawlerKinematics

__all__ = ["crawler_plot"]

_STYLES = {
    "tangent": ("-", "C0", "1: tangent guide (eqs 6.14-6.16)"),
    "none": ("--", "C3", "2: no guide (eq. 6.7)"),
}


def crawler_plot(result_or_results: CrawlerKinematics | Mapping[str, CrawlerKinematics] | Sequence[CrawlerKinematics],
                 *, ax: Sequence[Axes] | None = None, degrees: bool = True) -> Figure:
    """Velocity and acceleration of the crawler drive chain over a period, with and without guide.

    Parameters
    ----------
    result_or_results : CrawlerKinematics or sequence or dict of them
        Results of :func:`chaindrive.kinematics.crawler.crawler_drive`; curve 1 (tangent
        guide) solid, curve 2 (no guide) dashed, as in the crawler drive text Fig. 6.9 c. If any result
        carries a cam force, a third panel shows it.
    ax : sequence of Axes, optional
        Two (or three, with force) Axes; a new figure if omitted.
    degrees : bool
        Sprocket angle in degrees (else radians).

    Returns
    -------
    matplotlib.figure.Figure
        The velocity and acceleration panels (and the cam force's, when a result carries
        it) against the sprocket angle; never shown.

    Examples
    --------
    >>> from chaindrive.kinematics.crawler import crawler_drive
    >>> rs = [crawler_drive(0.1, 8, 3.14, guide=g, points=61) for g in ("tangent", "none")]
    >>> len(crawler_plot(rs).axes)
    2
    """
    import matplotlib.pyplot as plt

    from ..errors import InputError
    from ..kinematics.crawler import CrawlerKinematics

    items = results_list(result_or_results, CrawlerKinematics)
    if not items:
        raise InputError("crawler_plot needs at least one result")
    with_force = any(r.force is not None for r in items)
    n = 3 if with_force else 2
    if ax is None:
        fig, axes = plt.subplots(n, 1, sharex=True, figsize=(7.5, 3.2 * n + 0.6))
        axes = list(axes)
    else:
        axes = list(ax)
        if len(axes) != n:
            raise InputError(f"ax must be a sequence of {n} Axes (velocity, acceleration"
                             f"{', force' if with_force else ''})")
        fig = figure_of(axes[0])
    scale = 180.0 / np.pi if degrees else 1.0
    for r in items:
        style, color, label = _STYLES.get(r.guide, ("-", "k", r.guide))
        p = np.asarray(r.psi) * scale
        axes[0].plot(p, r.velocity, style, color=color, lw=1.6, label=label)
        axes[1].plot(p, r.acceleration, style, color=color, lw=1.6, label=label)
        if with_force and r.force is not None:
            axes[2].plot(p, np.asarray(r.force) / 1e3, style, color=color, lw=1.6, label=label)
    first = items[0]
    axes[0].axhline(first.summary["v_mean"], color="0.5", lw=0.8, ls=":",
                    label=f"mean z t ω/2π = {first.summary['v_mean']:.4g} m/s")
    axes[1].axhline(0.0, color="0.5", lw=0.6)
    cond = (f"t = {first.pitch * 1e3:g} mm, z = {first.teeth}, "
            f"ω = {first.angular_velocity:.4g} rad/s, R = {first.radius * 1e3:.1f} mm")
    nu = ", ".join(f"{r.guide}: δ = {100 * r.summary['nonuniformity']:.3g} %" for r in items)
    axes[0].set_title(f"Crawler drive chain velocity ({cond})\nnon-uniformity {nu}", fontsize=9)
    axes[1].set_title("Drive chain acceleration (jump at the seating ψ = 2π/z)", fontsize=9)
    axes[0].set_ylabel("velocity v [m/s]")
    axes[1].set_ylabel("acceleration a [m/s²]")
    if with_force:
        fr = next(r for r in items if r.force is not None)
        axes[2].set_title(
            f"Force on the cam about its mean (E_П = {fr.stiffness:.3g} N, A = {fr.sprocket_distance:g} m, "
            f"l = {fr.cam_distance:g} m)", fontsize=9)
        axes[2].set_ylabel("force P − P̄ [kN]")
    unit = "°" if degrees else "rad"
    axes[-1].set_xlabel(f"sprocket angle ψ [{unit}]\n(guide: from a hinge seating at the tangency "
                        "point; no guide: from the change of the supporting vertex)", fontsize=9)
    for a in axes:
        a.grid(True, lw=0.4, alpha=0.6)
        a.legend(fontsize=8, loc="best")
    fig.tight_layout()
    return fig
