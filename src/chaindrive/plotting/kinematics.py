"""Plots of chain-entry kinematics (Dolipiński et al., Figs 2 and 3)."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING

import numpy as np

from ._axes import figure_of, results_list, subplots

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from ..kinematics.entry import EntryKinematics

__all__ = ["kinematics_plot"]

_STYLES = {
    "free": ("-", "free entry"),
    "tangential": ("--", "tangential entry"),
    "chordal": ("-.", "chordal entry"),
    "guided": (":", "guided entry"),
}


def kinematics_plot(results: EntryKinematics | Mapping[str, EntryKinematics] | Sequence[EntryKinematics],
                    *, ax: Sequence[Axes] | None = None, degrees: bool = True) -> Figure:
    """Velocity and acceleration of the chain over one period, like Dolipiński et al.'s Figs 2-3.

    Parameters
    ----------
    results : EntryKinematics or dict or sequence of EntryKinematics
        One result, or several (e.g. :func:`chaindrive.kinematics.dolipinski_worked_case`); drawn
        with the paper's line styles: free solid, tangential dashed, chordal dash-dot.
    ax : sequence of two matplotlib Axes, optional
        Axes for velocity and acceleration; a new figure with two panels if omitted.
    degrees : bool
        Wheel angle in degrees (else radians) on the horizontal axis.

    Returns
    -------
    matplotlib.figure.Figure
        The velocity and acceleration panels against the wheel angle, one line per
        result; never shown.

    Examples
    --------
    >>> from chaindrive.kinematics import dolipinski_worked_case
    >>> fig = kinematics_plot(dolipinski_worked_case(points=91))
    >>> len(fig.axes)
    2
    """

    from ..kinematics.entry import EntryKinematics

    items = results_list(results, EntryKinematics)
    if ax is None:
        fig, axes = subplots(2, 1, sharex=True, figsize=(7.5, 7.0))
    else:
        axes = list(ax)
        if len(axes) != 2:
            from ..errors import InputError

            raise InputError("ax must be a pair of Axes (velocity, acceleration)")
        fig = figure_of(axes[0])
    scale = 180.0 / np.pi if degrees else 1.0
    for r in items:
        style, label = _STYLES.get(r.entry, ("-", r.entry))
        if r.entry == "guided" and r.guide_height is not None:
            label = f"guided entry, H = {r.guide_height * 1000:.1f} mm"
        phi = np.asarray(r.phi) * scale
        axes[0].plot(phi, r.velocity, style, color="k", lw=1.4, label=label)
        axes[1].plot(phi, r.acceleration, style, color="k", lw=1.4, label=label)
    first = items[0]
    chain = (
        f"link chain {first.bar_diameter * 1000:g}x{first.pitch * 1000:g}"
        if first.chain_type == "link"
        else f"roller chain p = {first.pitch * 1000:g} mm"
    )
    cond = f"z = {first.teeth}, ω = {first.angular_velocity:g} s⁻¹"
    ls = [r.guide_end_distance for r in items if r.guide_end_distance is not None]
    if ls:
        cond += f", l = {ls[0]:g} m"
    axes[0].set_title(f"Chain velocity, {chain}, {cond} (model: {first.model})", fontsize=10)
    axes[1].set_title(f"Chain acceleration, {chain}, {cond} (model: {first.model})", fontsize=10)
    axes[0].set_ylabel("velocity v [m/s]")
    axes[1].set_ylabel("acceleration a [m/s²]")
    axes[1].set_xlabel("wheel angle φ [°]" if degrees else "wheel angle φ [rad]")
    axes[1].axhline(0.0, color="0.6", lw=0.6)
    for a in axes:
        a.grid(True, color="0.85", lw=0.5)
        a.legend(fontsize=8, loc="best")
        a.set_xlim(0.0, first.period * scale)
    if ax is None:  # a new figure: laid out when drawn, so that a report's own layout engine replaces it
        fig.set_layout_engine("tight")
    else:
        fig.tight_layout()
    return fig
