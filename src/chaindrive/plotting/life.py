"""Plots of the drive over its life (:class:`chaindrive.analysis.life.DriveLife`)."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from ..display import convert
from ._axes import subplots

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from ..analysis.life import DriveLife

__all__ = ["life_plot"]


def _shown(values, unit, shown=None):
    """An SI array in its display unit, and that unit (:func:`chaindrive.workflows.display.convert`)."""
    factor, name = convert(1.0, unit, shown)
    return np.asarray(values, float) * float(factor or 0.0), name


def _pct(values):
    return _shown(values, "1", "%")[0]


def life_plot(result: DriveLife) -> Figure:
    """Four panels: elongation over hours (with the limit and the lives); the jump-over margin
    of every loaded sprocket, the tensioner's travel and the spans' first frequencies over
    the elongation, new to the limit.

    Parameters
    ----------
    result : chaindrive.analysis.life.DriveLife

    Returns
    -------
    matplotlib.figure.Figure
    """
    fig, axes = subplots(2, 2, figsize=(11, 7.5))
    ax1, ax2, ax3, ax4 = axes.ravel()
    e_grid = _pct(result.elongations)
    ax1.plot(result.hours, _pct(result.elongation), label="wear elongation")
    ax1.axhline(float(_pct(result.elongation_limit)), color="tab:red", ls="--",
                label=f"drive's limit {float(_pct(result.elongation_limit)):.3g} %")
    if result.replacement_limit is not None:
        ax1.axhline(float(_pct(result.replacement_limit)), color="tab:orange", ls=":",
                    label=f"makers' limit {float(_pct(result.replacement_limit)):.3g} %")
    ax1.axvline(result.replacement_hours, color="0.4", ls=":", label=f"{result.replacement_hours:,.0f} h (wear)")
    if result.fatigue_life_hours is not None and result.fatigue_life_hours < 2 * result.replacement_hours:
        ax1.axvline(result.fatigue_life_hours, color="tab:purple", ls="-.",
                    label=f"{result.fatigue_life_hours:,.0f} h (fatigue)")
    ax1.set_xlabel("operating time [h]")
    ax1.set_ylabel("chain elongation [%]")
    ax1.set_title(f"Elongation over the life (governed by {result.governing})")
    ax1.legend(fontsize=8)
    if result.jump_over_margins is not None:
        for name, curve in zip(result.wheel_names, result.jump_over_margins, strict=True):
            if np.all(np.isnan(curve)):
                continue
            ax2.semilogy(e_grid, curve, marker="o", ms=3, label=f"{name}")
        ax2.axhline(1.0, color="tab:red", ls="--", label="jump-over")
        ax2.legend(fontsize=8)
    else:
        ax2.text(0.5, 0.5, "no ISO 606 sprocket:\njump-over not modelled", ha="center", va="center",
                 transform=ax2.transAxes)
    ax2.set_xlabel("chain elongation [%]")
    ax2.set_ylabel("load ratio at jump-over / running T1/T2 [-]")
    ax2.set_title("Jump-over margin")
    if result.take_up is not None:
        tu, unit = _shown(result.take_up, "m")
        ax3.plot(e_grid, tu, marker="o", ms=3)
        ax3.set_ylabel(f"tensioner travel / take-up [{unit}]")
    else:
        ax3.text(0.5, 0.5, "fixed centres: no take-up", ha="center", va="center", transform=ax3.transAxes)
    ax3.set_xlabel("chain elongation [%]")
    ax3.set_title("Take-up of the elongation")
    if result.span_frequencies is not None:
        f, unit = _shown(result.span_frequencies, "rad/s", "Hz")
        names = result.wheel_names
        for j, row in enumerate(np.atleast_2d(f)):
            ax4.plot(e_grid, row, marker="o", ms=3, label=f"{names[j]} → {names[(j + 1) % len(names)]}")
        ax4.set_ylabel(f"first span frequency [{unit}]")
        ax4.legend(fontsize=8)
    ax4.set_xlabel("chain elongation [%]")
    ax4.set_title("Span frequencies of the worn chain")
    for ax in (ax1, ax2, ax3, ax4):
        ax.grid(True, lw=0.3)
    fig.tight_layout()
    return fig
