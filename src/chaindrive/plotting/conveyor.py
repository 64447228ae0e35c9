"""Plots of a conveyor's chain pull and of a conveyor simulation's start-up."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from ._axes import figure_of

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from ..analysis.conveyor import ConveyorPull
    from ..simulation.conveyor import StartUp

__all__ = ["conveyor_plot", "startup_plot"]


def conveyor_plot(result: ConveyorPull, *, ax: Axes | None = None) -> Figure:
    """Running tension along the loop from the head's exit, the wheels marked.

    Parameters
    ----------
    result : chaindrive.analysis.conveyor.ConveyorPull
    ax : matplotlib Axes, optional

    Returns
    -------
    matplotlib.figure.Figure
        The running tension against the position along the chain from the head's exit [m].

    Examples
    --------
    >>> import dataclasses
    >>> from chaindrive.analysis.conveyor import conveyor_pull
    >>> from chaindrive.drive import Conveyor
    >>> from chaindrive.simulation.from_drive import conveyor_drive
    >>> r = conveyor_pull(dataclasses.replace(conveyor_drive(), conveyor=Conveyor()))
    >>> fig = conveyor_plot(r)
    >>> fig.axes[0].get_xlabel()
    'position along the chain from the head exit [m]'
    """
    import matplotlib.pyplot as plt

    from ..display import DISPLAY

    unit, k = DISPLAY["N"]

    if ax is None:
        fig, ax = plt.subplots(figsize=(8, 3.6))
    else:
        fig = figure_of(ax)
    prof = result.tension_profile
    t = k * np.asarray(prof.tension)
    ax.plot(prof.position, t, color="C0", lw=1.8, label="running tension")
    ax.axhline(k * float(result.required_minimum), color="C3", ls=":", lw=1,
               label="stated minimum")
    ax.plot([result.minimum_position], [k * float(result.minimum_tension)], "v", color="C3",
            label="lowest")
    top = float(np.max(t)) if t.size else 1.0
    for name, x in zip(result.wheel_names, result.wheel_positions, strict=True):
        ax.axvline(x, color="0.7", lw=0.8)
        ax.text(x, top * 1.02, name, rotation=90, va="bottom", ha="right", fontsize=8, color="0.3")
    ax.set_xlabel("position along the chain from the head exit [m]")
    ax.set_ylabel(f"tension [{unit}]")
    ax.set_ylim(bottom=min(0.0, float(np.min(t))), top=top * 1.25)
    ax.legend(loc="lower right", fontsize=8)
    ax.set_title("Chain pull along the conveyor")
    fig.tight_layout()
    return fig


def startup_plot(result: StartUp, *, ax: tuple[Axes, Axes] | None = None) -> Figure:
    """Start-up: head speed and drive torque over time; peak-tension envelope along the chain.

    Parameters
    ----------
    result : chaindrive.simulation.conveyor.StartUp
    ax : two matplotlib Axes, optional

    Returns
    -------
    matplotlib.figure.Figure
    """
    import matplotlib.pyplot as plt

    from ..display import DISPLAY

    unit, k = DISPLAY["N"]

    if ax is None:
        fig, (a1, a2) = plt.subplots(2, 1, figsize=(8, 6.5))
    else:
        a1, a2 = ax
        fig = figure_of(a1)
    a1.plot(result.time, result.chain_speed, color="C0", label="chain speed at the head [m/s]")
    a1.set_xlabel("time [s]")
    a1.set_ylabel("chain speed [m/s]")
    b = a1.twinx()
    b.plot(result.time, k * np.asarray(result.tight_tension), color="C3", lw=1,
           label=f"tension arriving at the head [{unit}]")
    b.plot(result.time, k * np.asarray(result.slack_tension), color="C2", lw=1,
           label=f"tension leaving the head [{unit}]")
    b.set_ylabel(f"tension [{unit}]")
    h1, l1 = a1.get_legend_handles_labels()
    h2, l2 = b.get_legend_handles_labels()
    a1.legend(h1 + h2, l1 + l2, fontsize=7, loc="lower center", bbox_to_anchor=(0.5, 1.0), ncol=3,
              frameon=False)
    fig.suptitle("Start-up: the head's chain speed and tensions")
    a2.plot(result.envelope_position, k * np.asarray(result.envelope_peak), color="C3",
            label="peak over the start-up")
    a2.plot(result.envelope_position, k * np.asarray(result.envelope_low), color="C2",
            label="lowest over the start-up")
    a2.plot(result.envelope_position, k * np.asarray(result.steady_tension), color="0.4", ls="--",
            label="at the end of the run")
    a2.set_xlabel("position along the path from the head exit [m]")
    a2.set_ylabel(f"tension [{unit}]")
    a2.legend(fontsize=8)
    a2.set_title("Peak-tension envelope along the chain path")
    fig.tight_layout()
    return fig
