"""Plots of strength results: contact stress and life against skew, pin bending.

matplotlib is imported inside the functions (optional extra).
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import TYPE_CHECKING

import numpy as np

from ._axes import figure_of, subplots

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from ..strength.fretting import PinBendingResult
    from ..strength.skew import RollerContactResult

__all__ = ["skew_plot", "pin_bending_plot"]


def skew_plot(result: RollerContactResult, *, ax: Axes | None = None) -> Figure:
    """Contact stress and relative life against the roller skew (Garshniev & Maksymovych).

    Parameters
    ----------
    result : RollerContactResult
        From :func:`chaindrive.strength.roller_contact_stress` with an array of
        ``max_skew``.
    ax : matplotlib Axes, optional
        Axes for the stress; the life goes on a twin axis.

    Returns
    -------
    matplotlib.figure.Figure

    Examples
    --------
    >>> import numpy as np
    >>> from chaindrive.strength import ARCMIN, roller_contact_stress
    >>> r = roller_contact_stress(5e3, 15.88e-3, 68.7e-3, 17e-3, contact="convex",
    ...                           pitch=0.0254, max_skew=np.linspace(0, 200, 41) * ARCMIN)
    >>> fig = skew_plot(r)
    >>> len(fig.axes)
    2
    """

    from ..strength.skew import ARCMIN, MEASURED_SKEW_RANGE

    own = ax is None
    if ax is None:
        # fixed margins [in] (what the tight layout found for the report's examples, with room
        # for a longer tick label): no layout pass measuring every text at each draw
        fig, ax = subplots(figsize=(7.5, 5.5), layout="tight")
        fig.set_layout_engine("none")  # an inert engine: a report keeps these margins
        width, height = fig.get_size_inches()
        fig.subplots_adjust(left=0.78 / width, right=1 - 0.78 / width, bottom=1.34 / height, top=1 - 0.37 / height)
    else:
        fig = figure_of(ax)
    skew = np.atleast_1d(result.max_skew) / ARCMIN
    stress = np.atleast_1d(result.stress) / 1e6
    ax.axvspan(MEASURED_SKEW_RANGE[0] / ARCMIN, MEASURED_SKEW_RANGE[1] / ARCMIN, color="0.92",
               label="measured skews 0°42′…3°26′ (Garshniev & Maksymovych)")
    ax.plot(skew, stress, color="C3", lw=2, label="contact stress σ (Garshniev & Maksymovych eq. 1–2)")
    ax.axhline(float(np.atleast_1d(result.stress_unskewed)[0]) / 1e6, color="C3", ls=":", lw=1,
               label="σ without skew (Hertz)")
    ax.axvline(50, color="k", ls="--", lw=0.8)
    ax.set_xlabel("largest skew φ_p,max [arcmin]")
    ax.set_ylabel("contact stress σ [MPa]")
    ax2 = ax.twinx()
    ax2.semilogy(skew, np.atleast_1d(result.relative_life_wear), color="C0", lw=2,
                 label="life L/L0, wear (∝ 1/Q_n, Archard)")
    ax2.semilogy(skew, np.atleast_1d(result.relative_life_fatigue), color="C2", lw=2,
                 label="life L/L0, rolling fatigue (∝ Q_n^-10/3, ISO 281)")
    ax2.vlines(50, 1 / 3, 1 / 2, color="k", lw=6, alpha=0.6, label="Garshniev & Maksymovych claim: 0→50′ cuts life 2…3 times")
    ax2.set_ylabel("relative life L/L0 [-]")
    h1, l1 = ax.get_legend_handles_labels()
    h2, l2 = ax2.get_legend_handles_labels()
    ax.legend(h1 + h2, l1 + l2, fontsize=7.5, loc="upper center", bbox_to_anchor=(0.5, -0.15), ncol=2)
    g = float(np.atleast_1d(result.gamma)[0])
    ax.set_title(f"Roller–tooth contact with skew (γ = {g:.5f}/arcmin², "
                 f"K_φ = {float(np.atleast_1d(result.design_skew)[-1] / np.atleast_1d(result.max_skew)[-1]):.2f})")
    ax.grid(True, alpha=0.3)
    if not own:  # a caller's figure: laid out now
        fig.tight_layout()
    return fig


def pin_bending_plot(result: Iterable[PinBendingResult], *, ax: Axes | None = None) -> Figure:
    """Deflection of a multi-row chain pin with and without working intermediate plates.

    Parameters
    ----------
    result : sequence of PinBendingResult
        E.g. ``(pin.bending(F, intermediate_plates=False), pin.bending(F, intermediate_plates=True))``.
    ax : matplotlib Axes, optional

    Returns
    -------
    matplotlib.figure.Figure
        The pin deflection along the pin, one panel per result.

    Examples
    --------
    >>> from chaindrive.strength import MultiRowPin
    >>> pin = MultiRowPin(8.28e-3, 31.88e-3, 3, 17.02e-3)
    >>> fig = pin_bending_plot([pin.bending(5e3, intermediate_plates=b) for b in (False, True)])
    >>> len(fig.axes)
    2
    """

    results = list(result)
    axes: list[Axes]
    if ax is None:
        fig, grid = subplots(len(results), 1, figsize=(7.5, 2.6 * len(results) + 0.6), sharex=True,
                                 squeeze=False)
        axes = list(grid[:, 0])
    else:
        fig, axes = figure_of(ax), [ax] * len(results)
    load = 0.0
    for i, (r, a) in enumerate(zip(results, axes, strict=True)):
        load = float(np.atleast_1d(r.load)[0])
        b = r.beam
        lab = "with intermediate plates" if r.intermediate_plates else "without (intermediate plates idle)"
        (line,) = a.plot(b.x * 1e3, b.deflection * load * 1e6, lw=2, color=f"C{i}",
                         label=f"{lab}: slip A = {float(np.atleast_1d(r.slip_amplitude)[0]) * 1e6:.2f} µm, "
                               f"σ_max = {float(np.atleast_1d(r.max_stress)[0]) / 1e6:.0f} MPa")
        a.plot(b.supports * 1e3, np.zeros_like(b.supports), "^", ms=9, color=line.get_color(),
               label="plate supports" if i == 0 else None)
        if not a.yaxis_inverted():
            a.invert_yaxis()
        a.set_ylabel("deflection [µm]")
        a.legend(fontsize=8, loc="best")
        a.grid(True, alpha=0.3)
    axes[-1].set_xlabel("position along the pin [mm] (row centres at 0, pt, 2pt …)")
    axes[0].set_title(f"Multi-row chain pin under {load / 1e3:g} kN (Euler–Bernoulli beam, Vikulov)")
    fig.tight_layout()
    return fig
