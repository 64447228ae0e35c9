"""Plots of design studies: distributions, scatter matrices, feasible regions.

Each function takes plain arrays (a study's columns, see
:func:`chaindrive.study.run.read_results`) and returns the matplotlib Figure.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike

from ._axes import figure_of

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

__all__ = ["distribution_plot", "scatter_matrix_plot", "feasible_region_plot", "axis_label"]

_PASS = "#2b8a3e"
_FAIL = "#c92a2a"


def axis_label(name: str, unit: str) -> str:
    """``"name [unit]"`` (``[-]`` for a bare number)."""
    return f"{name} [{unit or '-'}]"


def _short(name: str, width: int = 26) -> str:
    """The last parts of a long dotted name (``...tensioner.frequencies_rad_s.0``)."""
    if len(name) <= width:
        return name
    parts = name.split(".")
    out = parts[-1]
    for p in reversed(parts[:-1]):
        if len(p) + len(out) + 1 > width:
            break
        out = f"{p}.{out}"
    return "…" + out


def _finite(values: Any) -> np.ndarray:
    x = np.asarray(values, dtype=float)
    return x[np.isfinite(x)]


def distribution_plot(values: Sequence[float], *, name: str, unit: str = "",
                      ax: Sequence[Axes] | None = None) -> Figure:
    """Histogram and empirical cumulative distribution of one output.

    Parameters
    ----------
    values : sequence of float
        The output over the variants (``None``/NaN rows, failed variants, are left out).
    name : str
        Output path, for the labels.
    unit : str
        Its unit.
    ax : pair of matplotlib Axes, optional
        Axes for the histogram and the CDF; default a new figure.

    Returns
    -------
    matplotlib.figure.Figure

    Notes
    -----
    The empirical CDF is the step function :math:`F_n(x) = \\#\\{x_i \\le x\\} / n`
    (Wasserman, *All of Statistics*, 2004, §7.1), drawn with its 5 %, 50 % and 95 %
    quantiles.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> fig = distribution_plot([1.0, 2.0, 2.5, 4.0], name="contact.stress", unit="Pa")
    >>> len(fig.axes)
    2
    """
    import matplotlib.pyplot as plt

    x = np.sort(_finite(values))
    if ax is None:
        fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(9.0, 3.4), layout="constrained")
    else:
        ax1, ax2 = ax
        fig = figure_of(ax1)
    label = axis_label(name, unit)
    if x.size:
        bins = int(np.clip(np.sqrt(x.size), 5, 50)) if np.ptp(x) > 0 else 1
        ax1.hist(x, bins=bins, color="#4263eb", alpha=0.85, edgecolor="white")
        ax2.step(x, np.arange(1, x.size + 1) / x.size, where="post", color="#4263eb",
                 label="empirical CDF")
        for q, style in ((0.05, ":"), (0.5, "--"), (0.95, ":")):
            v = float(np.quantile(x, q))
            ax2.axvline(v, color="0.4", ls=style, lw=0.9, label=f"{q:.0%} quantile: {v:.4g}")
        ax2.legend(fontsize=7, loc="lower right")
    else:
        ax1.text(0.5, 0.5, "no values", ha="center", va="center", transform=ax1.transAxes)
    ax1.set_xlabel(label)
    ax1.set_ylabel("variants")
    ax1.set_title(f"{_short(name, 40)}: histogram (n = {x.size})", fontsize=9)
    ax2.set_xlabel(label)
    ax2.set_ylabel("fraction of variants ≤ x [-]")
    ax2.set_ylim(0, 1.02)
    ax2.set_title(f"{_short(name, 40)}: empirical CDF", fontsize=9)
    ax2.grid(alpha=0.3)
    return fig


def scatter_matrix_plot(columns: dict[str, Sequence[float]], *, units: dict[str, str] | None = None,
                        passed: Sequence[bool | None] | None = None, passed_name: str = "passed",
                        log: Sequence[str] = (), ax: ArrayLike | None = None) -> Figure:
    """Scatter matrix of inputs and outputs: histograms on the diagonal, pairs elsewhere.

    Parameters
    ----------
    columns : dict of name -> sequence of float
        Equal-length columns (at most 8).
    units : dict of name -> str, optional
    passed : sequence of bool or None, optional
        Colours the points: green passed, red failed, grey unknown.
    passed_name : str
        Name of that yes/no output (legend).
    log : sequence of str
        Columns drawn on logarithmic axes.
    ax : 2-D array of Axes, optional

    Returns
    -------
    matplotlib.figure.Figure
        Histograms on the diagonal, one scatter panel per pair of columns elsewhere.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> fig = scatter_matrix_plot({"a": [1, 2, 3], "b": [3, 1, 2]}, passed=[True, False, None])
    >>> len(fig.axes)
    4
    """
    import matplotlib.pyplot as plt

    names = list(columns)[:8]
    units = units or {}
    n = len(names)
    if ax is None:
        size = min(2.2 * n, 14.0)
        fig, axes = plt.subplots(n, n, figsize=(size, size), squeeze=False, layout="constrained")
    else:
        axes = np.atleast_2d(ax)
        fig = figure_of(axes[0, 0])
    data = {k: np.asarray(columns[k], dtype=float) for k in names}
    if passed is None:
        colour = np.full(len(data[names[0]]) if names else 0, "#4263eb", dtype=object)
    else:
        colour = np.array([_PASS if p is True else _FAIL if p is False else "0.6" for p in passed],
                          dtype=object)
    for i, yn in enumerate(names):
        for j, xn in enumerate(names):
            a = axes[i, j]
            if i == j:
                x = _finite(data[xn])
                if x.size:
                    bins: Any = int(np.clip(np.sqrt(x.size), 5, 30)) if np.ptp(x) > 0 else 1
                    if xn in log and x.min() > 0 and np.ptp(x) > 0:
                        bins = np.geomspace(x.min(), x.max(), bins + 1)
                    a.hist(x, bins=bins, color="#4263eb", alpha=0.8)
            else:
                ok = np.isfinite(data[xn]) & np.isfinite(data[yn])
                a.scatter(data[xn][ok], data[yn][ok], s=6, c=list(colour[ok]), linewidths=0)
            if xn in log and np.nanmin(data[xn], initial=np.inf) > 0:
                a.set_xscale("log")
            if i != j and yn in log and np.nanmin(data[yn], initial=np.inf) > 0:
                a.set_yscale("log")
            if i == n - 1:
                a.set_xlabel(axis_label(_short(xn), units.get(xn, "")), fontsize=7)
            else:
                a.set_xticklabels([])
            if j == 0 and i != 0:
                a.set_ylabel(axis_label(_short(yn), units.get(yn, "")), fontsize=7)
            elif j != 0:
                a.set_yticklabels([])
            a.tick_params(labelsize=6)
    if passed is not None and n:
        from matplotlib.lines import Line2D

        handles = [Line2D([], [], marker="o", ls="", color=_PASS, label=f"{passed_name}: yes"),
                   Line2D([], [], marker="o", ls="", color=_FAIL, label=f"{passed_name}: no")]
        fig.legend(handles=handles, loc="upper right", fontsize=8)
    fig.suptitle("Scatter matrix of the variants", fontsize=10)
    return fig


def feasible_region_plot(x: Sequence[float], y: Sequence[float], feasible: Sequence[bool | None], *,
                         xname: str, yname: str, xunit: str = "", yunit: str = "",
                         feasible_name: str = "passed", over: str = "the other inputs",
                         log_x: bool = False, log_y: bool = False, ax: Axes | None = None) -> Figure:
    """Feasible region of two inputs: the fraction of variants that pass at each point.

    On a grid (repeated ``(x, y)`` pairs, the other inputs varying) each cell is coloured
    by the fraction of its variants with ``feasible`` true, and the cells where all pass
    are outlined: e.g. tensioner mass × stiffness that are resonance-free at every speed
    of a range. Scattered samples are drawn as green (feasible) and red points.

    Parameters
    ----------
    x, y : sequence of float
        The two inputs of every variant.
    feasible : sequence of bool or None
        The yes/no output (``None``: failed variant, left out).
    xname, yname, xunit, yunit : str
        Labels.
    feasible_name : str
        Name of the yes/no output (title).
    over : str
        What varies at each point (colour bar label), e.g. ``"drive.speed"``.
    log_x, log_y : bool
        Logarithmic axes.
    ax : matplotlib Axes, optional

    Returns
    -------
    matplotlib.figure.Figure
        The grid cells coloured by their fraction of passing variants (or the points, for
        scattered samples), with the colour bar.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> fig = feasible_region_plot([1, 1, 2, 2], [1, 2, 1, 2], [True, False, True, True],
    ...                            xname="m", yname="C")
    >>> fig.axes[0].get_title()
    'passed: feasible (green) and not (red)'
    """
    import matplotlib.pyplot as plt

    xs = np.asarray(x, dtype=float)
    ys = np.asarray(y, dtype=float)
    ok = np.array([f is not None for f in feasible]) & np.isfinite(xs) & np.isfinite(ys)
    val = np.array([bool(f) if f is not None else False for f in feasible])
    xs, ys, val = xs[ok], ys[ok], val[ok]
    if ax is None:
        fig, ax = plt.subplots(figsize=(6.4, 5.0), layout="constrained")
    else:
        fig = figure_of(ax)
    ux, uy = np.unique(xs), np.unique(ys)
    grid = xs.size > 0 and ux.size * uy.size < xs.size and ux.size > 1 and uy.size > 1
    if grid:
        ix, iy = np.searchsorted(ux, xs), np.searchsorted(uy, ys)
        count = np.zeros((uy.size, ux.size))
        good = np.zeros((uy.size, ux.size))
        np.add.at(count, (iy, ix), 1.0)
        np.add.at(good, (iy, ix), val.astype(float))
        with np.errstate(invalid="ignore", divide="ignore"):
            frac = np.where(count > 0, good / np.maximum(count, 1), np.nan)

        def edges(u: np.ndarray, log: bool) -> np.ndarray:
            v = np.log(u) if log else u
            mid = 0.5 * (v[1:] + v[:-1])
            e = np.concatenate([[v[0] - (mid[0] - v[0])], mid, [v[-1] + (v[-1] - mid[-1])]])
            return np.exp(e) if log else e

        ex, ey = edges(ux, log_x), edges(uy, log_y)
        mesh = ax.pcolormesh(ex, ey, np.ma.masked_invalid(frac), cmap="RdYlGn", vmin=0, vmax=1,
                             shading="flat")
        fig.colorbar(mesh, ax=ax, label=f"fraction feasible over {over} [-]")
        allok = np.nan_to_num(frac) >= 1.0
        for r, c in zip(*np.nonzero(allok), strict=True):
            ax.add_patch(plt.Rectangle((ex[c], ey[r]), ex[c + 1] - ex[c], ey[r + 1] - ey[r],
                                       fill=False, ec="k", lw=1.2))
        from matplotlib.patches import Patch

        ax.legend(handles=[Patch(fill=False, ec="k", lw=1.2, label="feasible for all")],
                  loc="upper right", fontsize=8)
    else:
        ax.scatter(xs[val], ys[val], s=10, c=_PASS, label="feasible")
        ax.scatter(xs[~val], ys[~val], s=10, c=_FAIL, label="not feasible")
        ax.legend(fontsize=8)
    if log_x:
        ax.set_xscale("log")
    if log_y:
        ax.set_yscale("log")
    ax.set_xlabel(axis_label(xname, xunit))
    ax.set_ylabel(axis_label(yname, yunit))
    ax.set_title(f"{feasible_name}: fraction of variants feasible" if grid else
                 f"{feasible_name}: feasible (green) and not (red)", fontsize=9)
    return fig
