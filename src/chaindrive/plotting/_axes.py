"""Helpers shared by the plot functions (internal; matplotlib is imported by the callers)."""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from typing import TYPE_CHECKING, Any, Literal, TypeVar

from ..errors import InputError

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

__all__ = ["figure_of", "results_list", "subplots"]

R = TypeVar("R")


def figure_of(ax: Axes) -> Figure:
    """The figure an Axes given by the caller is drawn in (the root figure of a subfigure).

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        An Axes placed in a figure.

    Returns
    -------
    matplotlib.figure.Figure
        Its (root) figure.

    Raises
    ------
    InputError
        The Axes belongs to no figure.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig, ax = plt.subplots()
    >>> figure_of(ax) is fig
    True
    >>> plt.close(fig)
    """
    fig = ax.get_figure(root=True)
    if fig is None:
        raise InputError("ax must be a matplotlib Axes placed in a figure (plt.subplots() gives one)")
    return fig


def results_list(results: R | Mapping[str, R] | Iterable[R], kind: type[R]) -> list[R]:
    """The results a plot function was given, one (an instance of ``kind``), a dict of
    them (its values) or a sequence of them, as a list.

    Examples
    --------
    >>> results_list({"a": 1.0, "b": 2.0}, float), results_list(1.0, float), results_list((1.0,), float)
    ([1.0, 2.0], [1.0], [1.0])
    """
    if isinstance(results, Mapping):
        return list(results.values())
    if isinstance(results, kind):
        return [results]
    return list(results)  # type: ignore[arg-type]


def subplots(nrows: int = 1, ncols: int = 1, *, figsize: tuple[float, float],
             layout: Literal["constrained", "compressed", "tight"] | None = None,
             **kwargs: Any) -> tuple[Figure, Any]:
    """A new figure and its axes, as ``plt.subplots`` gives them.

    Through pyplot when a program has imported it (its figures are then managed and shown
    by ``plt.show()``); otherwise a bare :class:`matplotlib.figure.Figure` on the Agg
    canvas, without importing pyplot and its backend machinery (a report that only writes
    PNGs saves about 0.3 s a process).

    Examples
    --------
    >>> fig, ax = subplots(figsize=(4.0, 3.0))
    >>> fig.get_size_inches().tolist()
    [4.0, 3.0]
    """
    import sys

    plt = sys.modules.get("matplotlib.pyplot")
    if plt is not None:
        return plt.subplots(nrows, ncols, figsize=figsize, layout=layout, **kwargs)
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure as MatplotlibFigure

    fig = MatplotlibFigure(figsize=figsize, layout=layout)
    FigureCanvasAgg(fig)
    return fig, fig.subplots(nrows, ncols, **kwargs)
