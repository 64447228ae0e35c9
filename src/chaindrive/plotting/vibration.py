"""Plots of the slack-span/tensioner vibration check (the tensioner paper): Campbell diagram, resonance map."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from .._presenters import register_view
from ..units import angular_velocity_to_rpm, rpm_to_angular_velocity
from ..vibration.tensioner_design import CampbellResult, ResonanceMapResult
from ._axes import figure_of

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure


__all__ = ["campbell_plot", "resonance_map_plot"]



def _runs(mask: np.ndarray) -> list[tuple[int, int]]:
    """(first, last) indices of the runs of True in a 1-D mask."""
    m = np.concatenate(([False], np.asarray(mask, dtype=bool), [False]))
    edges = np.flatnonzero(np.diff(m.astype(int)))
    return [(int(a), int(b) - 1) for a, b in zip(edges[::2], edges[1::2], strict=True)]


@register_view("plot", CampbellResult)
def campbell_plot(result: CampbellResult, *, ax: Axes | None = None) -> Figure:
    """Campbell diagram: natural frequencies and excitation lines against sprocket speed.

    Parameters
    ----------
    result : CampbellResult
        The speeds, natural frequencies and excitation orders, from
        :func:`chaindrive.vibration.campbell`.
    ax : matplotlib Axes, optional
        Axes to draw on (secondary axes in rpm above and Hz beside are added to it); a
        new figure if omitted.

    Returns
    -------
    matplotlib.figure.Figure
        The driving sprocket's speed ω₁ in rad/s on the horizontal axis (rpm on a second
        axis above), the frequencies in rad/s on the vertical one, so that an excitation
        ``k·ω₁`` is a line of slope ``k`` and the check compares the numbers plotted (the
        tensioner paper states its criterion P/ω in rad/s). The plot is fitted to the
        natural frequencies (30 % headroom; an excitation band lying wholly above is named
        in the legend with its range); the forbidden band 0.7 ω_j <= P <= 1.4 ω_j of every
        excitation lightly shaded in the excitation's colour; the speeds where a natural
        frequency lies in a band tinted red over the whole height (named in the legend);
        each natural frequency labelled with its value, or its range when it varies with
        speed; the legend outside the data, right of the axes.

    Examples
    --------
    >>> from chaindrive.vibration import TensionerSpan, campbell
    >>> s = TensionerSpan(2000.0, 2.6, 0.8, 0.8, 0.35, 0.35, 3.0, 5e4)
    >>> fig = campbell_plot(campbell(s, (5.0, 60.0), ratio=2.5, teeth=17, speeds=50))
    >>> fig.axes[0].get_xlabel(), fig.axes[0].get_ylabel()
    ('driving sprocket speed ω₁ [rad/s]', 'frequency [rad/s]')
    >>> bool(fig.axes[0].get_ylim()[1] < 250.0)  # fitted to P1...P3 (94-145 rad/s), not the meshing band
    True

    References
    ----------
    the tensioner paper (condition 0.7 <= P_i/ω_j <= 1.4).
    """
    import matplotlib.pyplot as plt

    if ax is None:
        fig, ax = plt.subplots(figsize=(10.5, 5.5), layout="constrained")
    else:
        fig = figure_of(ax)
    w = np.asarray(result.speed, dtype=float)
    x = w
    p = np.asarray(result.natural_frequencies, dtype=float)
    if p.ndim == 1:
        p = p[:, None]
    from ..display import CONVERSIONS

    per_hz = CONVERSIONS[("rad/s", "Hz")]  # the display table's factor

    def hz(omega: Any) -> Any:  # [rad/s] -> [Hz]
        return np.asarray(omega) * per_hz

    def rad_s(frequency: Any) -> Any:  # [Hz] -> [rad/s]
        return np.asarray(frequency) / per_hz

    lo, hi = result.band
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    ymax = 1.3 * float(np.max(p))
    for j, (name, k) in enumerate(zip(result.excitation_names, result.excitation_multipliers, strict=True)):
        col = colors[(1, 4, 5, 9, 8, 6)[j % 6] % len(colors)]  # red is kept for the forbidden speeds
        f = k * w
        above = lo * float(f.min()) > ymax
        where = f" (above the plot: {lo * f.min():.3g}–{hi * f.max():.3g} rad/s)" if above else ""
        ax.fill_between(x, lo * f, hi * f, color=col, alpha=0.12, lw=0)
        ax.plot(x, f, color=col, lw=1.4, ls="--", label=f"excitation {name}: {k:g}·ω₁{where}")
    mode_colors = ["black", "navy", "darkgreen", "purple", "saddlebrown", "teal"]
    for i in range(p.shape[1]):
        col = mode_colors[i % len(mode_colors)]
        low, high = float(np.min(p[:, i])), float(np.max(p[:, i]))
        value = (f"{hz(low):.3g} Hz ({low:.3g} rad/s)" if high - low <= 1e-3 * high
                 else f"{hz(low):.3g}…{hz(high):.3g} Hz ({low:.3g}…{high:.3g} rad/s) over the speeds")
        ax.plot(x, p[:, i], color=col, lw=2.0, ls=["-", "-.", ":"][i] if i < 3 else "-",
                label=f"natural frequency P{i + 1} = {value}")
    bad = np.asarray(result.min_margin) <= 0
    step = float(x[1] - x[0]) if x.size > 1 else 0.0
    for n, (a, b) in enumerate(_runs(bad)):
        x0, x1 = max(x[0], x[a] - step / 2), min(x[-1], x[b] + step / 2)
        ax.axvspan(x0, x1, facecolor="red", alpha=0.07, lw=0, zorder=0,
                   label="speeds with a P_i inside the paper's band" if n == 0 else None)
    if result.design_speed is not None:
        ax.axvline(result.design_speed, color="0.3", lw=1, ls=":",
                   label=f"design speed {result.design_speed:.3g} rad/s "
                         f"({angular_velocity_to_rpm(result.design_speed):.0f} rpm)")
    ax.set_xlim(x[0], x[-1])
    ax.set_ylim(0, ymax)
    ax.set_xlabel("driving sprocket speed ω₁ [rad/s]")
    ax.set_ylabel("frequency [rad/s]")
    top = ax.secondary_xaxis("top", functions=(angular_velocity_to_rpm, rpm_to_angular_velocity))
    top.set_xlabel("n₁ [rpm]")
    right = ax.secondary_yaxis("right", functions=(hz, rad_s))  # the frequencies in Hz beside
    right.set_ylabel("frequency [Hz]")
    ax.set_title("Campbell diagram: slack span with tensioner (the tensioner paper)\n"
                 f"shaded round each excitation: the paper's band {lo:g} ≤ P/ω ≤ {hi:g} (information)", fontsize=10)
    ax.grid(True, alpha=0.3)
    ax.legend(loc="upper left", bbox_to_anchor=(1.12, 1.0), borderaxespad=0.0, fontsize=8, framealpha=0.9)
    if fig.get_layout_engine() is None:
        fig.tight_layout()
    return fig


@register_view("plot", ResonanceMapResult)
def resonance_map_plot(result: ResonanceMapResult, *, ax: Axes | None = None) -> Figure:
    """Resonance map: smallest margin to the forbidden band over (tensioner mass, stiffness).

    Parameters
    ----------
    result : ResonanceMapResult
        The smallest margins over the (mass, stiffness) grid, from
        :func:`chaindrive.vibration.resonance_map`.
    ax : matplotlib Axes, optional
        Axes to draw on (the colour bar of the margin is added beside it); a new figure
        if omitted.

    Returns
    -------
    matplotlib.figure.Figure
        Log axes mass [kg] and stiffness [kN/m]; colour = smallest margin over the
        speed range (green safe, red resonant), black contour = margin 0, unsafe
        region hatched, design (and proposal, if any) marked.

    Examples
    --------
    >>> from chaindrive.vibration import TensionerSpan, resonance_map
    >>> s = TensionerSpan(2000.0, 2.6, 0.8, 0.8, 0.35, 0.35, 3.0, 5e4)
    >>> r = resonance_map(s, np.geomspace(0.3, 30, 20), np.geomspace(5e3, 5e5, 20), (20, 40))
    >>> resonance_map_plot(r).axes[0].get_xscale()
    'log'
    """
    import matplotlib.pyplot as plt
    from matplotlib.colors import TwoSlopeNorm

    if ax is None:
        fig, ax = plt.subplots(figsize=(8.0, 6.0))
    else:
        fig = figure_of(ax)
    m = np.asarray(result.mass)
    c = np.asarray(result.stiffness) / 1e3
    mu = np.asarray(result.min_margin)
    vmax = max(float(np.nanmax(mu)), 0.05)
    vmin = min(float(np.nanmin(mu)), -0.05)
    mesh = ax.pcolormesh(c, m, mu, cmap="RdYlGn", norm=TwoSlopeNorm(0.0, vmin, vmax),
                         shading="nearest")
    cb = fig.colorbar(mesh, ax=ax)
    cb.set_label("smallest margin to the band 0.7 ≤ P/ω ≤ 1.4 [-]\n(> 0 safe, ≤ 0 resonant)")
    if mu.min() < 0 < mu.max():
        ax.contour(c, m, mu, levels=[0.0], colors="k", linewidths=1.6)
    ax.contourf(c, m, (mu <= 0).astype(float), levels=[0.5, 1.5], colors="none", hatches=["//"])
    if result.design is not None:
        ax.plot(result.design[1] / 1e3, result.design[0], marker="o", ms=9, mfc="white",
                mec="k", ls="none", label=f"design: m = {result.design[0]:g} kg, "
                                           f"C = {result.design[1] / 1e3:g} kN/m")
    if result.proposal is not None:
        ax.plot(result.proposal[1] / 1e3, result.proposal[0], marker="*", ms=14, mfc="gold",
                mec="k", ls="none", label=f"nearest safe: m = {result.proposal[0]:.3g} kg, "
                                            f"C = {result.proposal[1] / 1e3:.3g} kN/m")
    ax.plot([], [], color="k", lw=1.6, label="safe boundary (margin 0); hatched: resonant")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("tensioner stiffness C reduced to its axis [kN/m]")
    ax.set_ylabel("tensioner mass m reduced to its axis [kg]")
    lo, hi = result.speed_range
    ax.set_title("Resonance map (the tensioner paper)\n"
                 f"natural frequencies against {len(result.excitation_names)} excitations over "
                 f"ω₁ = {lo:.3g}…{hi:.3g} rad/s ({angular_velocity_to_rpm(lo):.0f}…"
                 f"{angular_velocity_to_rpm(hi):.0f} rpm, {result.speeds} speeds)", fontsize=10)
    ax.legend(loc="lower left", fontsize=8, framealpha=0.9)
    fig.tight_layout()
    return fig
