"""Plots and animation of a chain-drive simulation (:mod:`chaindrive.simulation`)."""

from __future__ import annotations

import os
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from .._presenters import register_view
from ..simulation.run import SimulationResult
from ._axes import figure_of

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.collections import PathCollection
    from matplotlib.figure import Figure


__all__ = ["simulation_plot", "drive_frame_plot", "simulation_animation"]


@register_view("plot", SimulationResult)
def simulation_plot(result: SimulationResult, *, ax: Sequence[Axes] | None = None) -> Figure:
    """Standard views: chain speed, tight/slack tension, wheel speeds, contact forces.

    Parameters
    ----------
    result : SimulationResult
    ax : sequence of four matplotlib Axes, optional
        A new 2 × 2 figure if omitted.

    Returns
    -------
    matplotlib.figure.Figure
        The four views against time [s] on a 2 × 2 grid.

    Examples
    --------
    >>> from chaindrive.simulation import roller_example, simulate
    >>> r = simulate(roller_example(links=30, teeth=11, ramp_time=0.005), 0.01, samples=20)
    >>> fig = simulation_plot(r)
    >>> len(fig.axes)
    4
    """
    import matplotlib.pyplot as plt

    if ax is None:
        fig, axes = plt.subplots(2, 2, figsize=(11, 7), sharex=True)
        axes = axes.ravel()
    else:
        axes = list(ax)
        fig = figure_of(axes[0])
    t = result.time
    a = axes[0]
    for j in range(result.chain_velocity.shape[1]):
        a.plot(t, result.chain_velocity[:, j], lw=0.8, label=f"probe {j}")
    a.set_ylabel("chain speed [m/s]")
    a.set_title("Chain speed at the probes (tight span)")
    a.legend(fontsize=8)
    a = axes[1]
    a.plot(t, result.tight_side_tension() / 1e3, lw=0.8, label="tight span")
    a.plot(t, result.slack_side_tension() / 1e3, lw=0.8, label="slack span")
    a.set_ylabel("link tension [kN]")
    a.set_title("Span tension (link at mid-span)")
    a.legend(fontsize=8)
    a = axes[2]
    for j in range(result.wheel_speed.shape[1]):
        a.plot(t, result.wheel_speed[:, j], lw=0.8, label=f"wheel {j} (z = {result.teeth[j]})" if result.teeth[j] else f"wheel {j} (toothless)")
    a.set_ylabel("wheel speed [rad/s]")
    a.set_xlabel("time [s]")
    a.set_title("Wheel speeds")
    a.legend(fontsize=8)
    a = axes[3]
    lines = a.plot(t, np.max(result.contact_force, axis=1) / 1e3, lw=0.8,
                   label="largest contact force on a roller (hinge)")
    moving = [j for j in range(result.tensioner_position.shape[1])
              if np.any(result.tensioner_position[:, j])]
    if moving:
        # only the wheels on a slide (the others' column is zero throughout)
        b = a.twinx()
        for j in moving:
            lines += b.plot(t, result.tensioner_position[:, j] * 1e3, "k--", lw=0.8,
                            label=f"slide of wheel {j} (right axis)")
        b.set_ylabel("tensioner slide position [mm]")
    a.set_ylabel("contact force [kN]")
    a.set_xlabel("time [s]")
    a.set_title("Contact forces (roller–tooth or hinge–pocket)")
    # the legend on the top axes, so that no curve is drawn over it
    (b if moving else a).legend(lines, [ln.get_label() for ln in lines], fontsize=8,
                                loc="lower left", framealpha=0.9)
    fig.tight_layout()
    return fig


def _draw_drive(ax: Axes, result: SimulationResult, k: int) -> PathCollection:
    return _draw_drive_parts(ax, result, k)[0]


def _draw_drive_parts(ax: Axes, result: SimulationResult, k: int) -> tuple[PathCollection, list, Any]:
    """Draw record ``k``; return the pins, each wheel's seat marks and radius (in wheel
    order; a toothless idler has no marks) and the chain's line."""
    import matplotlib.patches as mp

    ax.clear()
    pos = result.positions[k]
    marks = []
    for j, (c, rad, z) in enumerate(zip(result.wheel_centres, result.pitch_radii, result.teeth,
                                        strict=True)):
        cx = c[0]
        cy = c[1]
        ax.add_patch(mp.Circle((cx, cy), rad, fill=False, color="0.6", lw=0.8))
        # seats (a toothless idler, z = 0: none) and a radius turning with the wheel
        th = result.wheel_angle[k, j] + 2 * np.pi * np.arange(max(z, 1)) / max(z, 1)
        if z > 0:
            marks += ax.plot(cx + rad * np.cos(th), cy + rad * np.sin(th), "+", color="0.4", ms=4)
        marks += ax.plot([cx, cx + rad * np.cos(th[0])], [cy, cy + rad * np.sin(th[0])], "-", color="0.4")
    for seg in result.guide_segments:
        ax.plot(seg[:, 0], seg[:, 1], "-", color="tab:brown", lw=1.5)
    closed = np.vstack([pos, pos[:1]])
    ten = result.tension[k]
    (chain,) = ax.plot(closed[:, 0], closed[:, 1], "-", color="k", lw=0.8)
    sc = ax.scatter(pos[:, 0], pos[:, 1], c=ten / 1e3, s=12, cmap="viridis",
                    vmin=np.min(result.tension) / 1e3, vmax=np.max(result.tension) / 1e3)
    ax.set_aspect("equal")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_title(f"t = {result.time[k]:.4f} s")
    return sc, marks, chain


def drive_frame_plot(result: SimulationResult, frame: int = -1, *, ax: Axes | None = None) -> Figure:
    """The drive at one recorded instant: wheels, pins coloured by link tension.

    Parameters
    ----------
    result : SimulationResult
    frame : int
        Record index.
    ax : matplotlib Axes, optional

    Returns
    -------
    matplotlib.figure.Figure
        The drive in its plane at record ``frame``, pins coloured by link tension.

    Examples
    --------
    >>> from chaindrive.simulation import roller_example, simulate
    >>> r = simulate(roller_example(links=30, teeth=11, ramp_time=0.005), 0.01, samples=20)
    >>> fig = drive_frame_plot(r)
    >>> fig.axes[0].get_xlabel()
    'x [m]'
    """
    import matplotlib.pyplot as plt

    if ax is None:
        fig, ax = plt.subplots(figsize=(10, 4))
    else:
        fig = figure_of(ax)
    sc = _draw_drive(ax, result, frame if frame >= 0 else len(result.time) + frame)
    fig.colorbar(sc, ax=ax, label="link tension [kN]")
    return fig


def simulation_animation(result: SimulationResult, path: str | os.PathLike[str], *, frames: int = 60,
                         fps: int = 15) -> str:
    """Write a GIF of the drive in motion (matplotlib's Agg canvas, Pillow's GIF writer).

    The wheels, guides, axes and colour bar are drawn once; each frame redraws only what
    moves (the chain, its pins coloured by link tension, the seats and the radius of each
    wheel, the time) over that background (blitting), at the limits of the first frame.

    Parameters
    ----------
    result : SimulationResult
    path : str or Path
        Output ``.gif``.
    frames : int
        Number of frames (evenly over the records).
    fps : int
        Frames per second of the GIF.

    Returns
    -------
    str
        The path written.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> from chaindrive.simulation import roller_example, simulate
    >>> r = simulate(roller_example(links=30, teeth=11, ramp_time=0.005), 0.01, samples=20)
    >>> with tempfile.TemporaryDirectory() as d:
    ...     out = simulation_animation(r, pathlib.Path(d) / "a.gif", frames=5)
    ...     from PIL import Image
    ...     Image.open(out).n_frames
    5
    """
    import matplotlib.pyplot as plt
    from PIL import Image

    n = len(result.time)
    idx = np.unique(np.linspace(0, n - 1, min(frames, n)).astype(int))
    fig, ax = plt.subplots(figsize=(10, 4))
    sc, marks, chain = _draw_drive_parts(ax, result, idx[0])
    fig.colorbar(sc, ax=ax, label="link tension [kN]")
    # what moves, in the drawing order of _draw_drive: each wheel's seat marks and
    # radius, the chain's line, its pins, the time in the title
    moving = [*marks, chain, sc, ax.title]
    for a in moving:
        a.set_animated(True)
    ax.set_autoscale_on(False)
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    canvas = FigureCanvasAgg(fig)  # whatever the backend: copy_from_bbox, buffer_rgba
    canvas.draw()
    background = canvas.copy_from_bbox(fig.bbox)

    def render(k: int) -> Image.Image:
        canvas.restore_region(background)
        pos = result.positions[k]
        closed = np.vstack([pos, pos[:1]])
        chain.set_data(closed[:, 0], closed[:, 1])
        sc.set_offsets(pos)
        sc.set_array(result.tension[k] / 1e3)
        _turn_marks(marks, result, k)
        ax.title.set_text(f"t = {result.time[k]:.4f} s")
        for a in moving:
            ax.draw_artist(a)
        return Image.frombuffer("RGBA", canvas.get_width_height(), canvas.buffer_rgba(), "raw",
                                "RGBA", 0, 1).convert("RGB")

    # one palette for every frame, from the first, middle and last frames together (the
    # tension colours change over the run), each frame mapped to it without dithering as
    # it is drawn (a palette per frame, by median cut, took most of the time; frames kept
    # in colour, most of the memory)
    first = render(idx[0])
    w, h = first.size
    probe = Image.new("RGB", (w, 3 * h))
    for j, im in enumerate((first, render(idx[len(idx) // 2]), render(idx[-1]))):
        probe.paste(im, (0, j * h))
    palette = probe.quantize(colors=255, method=Image.Quantize.FASTOCTREE)
    frames_p = [render(k).quantize(palette=palette, dither=Image.Dither.NONE) for k in idx]
    plt.close(fig)
    frames_p[0].save(str(path), save_all=True, append_images=frames_p[1:],
                     duration=int(1000 / fps), loop=0)
    return str(path)


def _turn_marks(marks: list, result: SimulationResult, k: int) -> None:
    """Seat marks and radius of each wheel at record ``k`` (the lines of :func:`_draw_drive`
    in its order: a toothed wheel's marks, then its radius; a toothless idler's radius)."""
    it = iter(marks)
    for j, (c, rad, z) in enumerate(zip(result.wheel_centres, result.pitch_radii, result.teeth,
                                        strict=True)):
        th = result.wheel_angle[k, j] + 2 * np.pi * np.arange(max(z, 1)) / max(z, 1)
        if z > 0:
            next(it).set_data(c[0] + rad * np.cos(th), c[1] + rad * np.sin(th))
        next(it).set_data([c[0], c[0] + rad * np.cos(th[0])], [c[1], c[1] + rad * np.sin(th[0])])
