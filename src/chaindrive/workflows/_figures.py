"""Drawing the report's figures, in this process or shared with one forked helper (internal).

A report's sections call :class:`Figures` for each figure they show, in a fixed order. Serial
(the default), each figure is drawn when asked. Shared (``chaindrive analyze`` on a machine
with two or more processors, where the ``fork`` start method exists), a helper process
forked from this one runs the same sections on the same analysis and the two processes
claim the figures one by one from a shared table: each figure is drawn once, by whichever
process reaches it first; the helper sends its PNGs back. A figure the helper could not
draw (an error, a helper that died or took too long) is drawn here, so the report is the
same either way.

The warnings a figure raises are replayed after all the figures, in figure order, by
either process: the report's list of warnings does not depend on who drew what.
"""

from __future__ import annotations

import os
import sys
import warnings
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from .report import Figure, Section

if TYPE_CHECKING:
    from matplotlib.figure import Figure as MatplotlibFigure

__all__ = ["Figures", "FigureShare"]

#: Figures a shared report can split (later ones are drawn here).
SLOTS = 256
#: Seconds this process waits for the helper's figures before drawing them itself.
HELPER_TIMEOUT = 120.0

_HERE, _HELPER = 2, 1  # owners in the claim table (0: not claimed yet)

Replay = list[tuple[type[Warning], str]]


def _draw(make: Callable[[], MatplotlibFigure], caption: str, filename: str) -> tuple[Figure, Replay]:
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        figure = Figure.from_matplotlib(make(), caption, filename)
    return figure, [(w.category, str(w.message)) for w in caught]


class FigureShare:
    """One forked helper process that draws part of a report's figures (see the module)."""

    def __init__(self, run: Callable[[FigureShare], None]) -> None:
        import multiprocessing as mp

        ctx = mp.get_context("fork")
        self.owner = _HERE
        self.drawn: dict[int, tuple[bytes, Replay] | None] = {}  # in the helper: its figures (None: failed)
        self._claims = ctx.Array("b", SLOTS)
        self._receive, send = ctx.Pipe(duplex=False)
        for stream in (sys.stdout, sys.stderr):  # the helper must not write this process' buffered output again
            stream.flush()

        def helper() -> None:
            self.owner = _HELPER
            try:
                run(self)
            finally:
                send.send(self.drawn)
                send.close()

        self._process = ctx.Process(target=helper, daemon=True)
        self._process.start()
        send.close()

    @staticmethod
    def available() -> bool:
        """Whether a helper can be forked here and would have a processor of its own."""
        import multiprocessing as mp

        try:
            cpus = len(os.sched_getaffinity(0))
        except (AttributeError, OSError):  # pragma: no cover - not Linux
            cpus = os.cpu_count() or 1
        # a processor idle on average over the last minute. Measured on 2 cores (chaindrive
        # analyze of the roller example, 15 pairs against drawing alone): wall 0.92x at load
        # 1.4-1.7 (CPU +6 %), 0.86x at load 0.5; at load 3.3 no gain (1.03-1.07x)
        idle = os.getloadavg()[0] < cpus
        return (cpus >= 2 and idle and "fork" in mp.get_all_start_methods() and not mp.current_process().daemon
                and sys.platform.startswith("linux"))

    def claim(self, index: int) -> bool:
        """Whether this process draws figure ``index`` (claimed now, or by no one yet)."""
        if index >= SLOTS:
            return self.owner == _HERE
        with self._claims.get_lock():
            if self._claims[index] == 0:
                self._claims[index] = self.owner
            return bool(self._claims[index] == self.owner)

    def collect(self) -> dict[int, tuple[bytes, Replay] | None]:
        """The helper's figures (empty when it failed or timed out); the helper ends."""
        drawn: dict[int, tuple[bytes, Replay] | None] = {}
        try:
            if self._receive.poll(HELPER_TIMEOUT):
                drawn = self._receive.recv()
        except (EOFError, OSError):  # the helper died: its figures are drawn here
            drawn = {}
        finally:
            self._receive.close()
            self._process.join(timeout=5.0)
            if self._process.is_alive():  # pragma: no cover - a stuck helper
                self._process.kill()
                self._process.join()
        return drawn


class Figures:
    """What a report section calls to show a figure: ``fig(section, make, caption, filename)``.

    Draws unless switched off; with a :class:`FigureShare`, only the figures this process
    claims (the others are filled in by :meth:`finish`).
    """

    def __init__(self, enabled: bool, share: FigureShare | None = None, browser: bool = False) -> None:
        self.enabled = enabled
        self.share = share
        self.browser = browser
        self._count = 0
        self._pending: list[tuple[int, Figure, Callable[[], MatplotlibFigure]]] = []
        self._replay: dict[int, Replay] = {}

    def __call__(self, section: Section, make: Callable[[], MatplotlibFigure], caption: str, filename: str,
                 chart: Callable[[], dict[str, Any]] | None = None) -> None:
        """Show a figure: with ``browser`` and a ``chart`` (plotly data, :mod:`chaindrive.workflows.charts`), as that
        chart, drawn by the browser; otherwise ``make()`` drawn as PNG."""
        if not self.enabled:
            return
        if self.browser and chart is not None:
            if self.share is None or self.share.owner == _HERE:
                section.figures.append(Figure(caption=caption, png=b"", filename=filename, chart=chart()))
            return
        index = self._count
        self._count += 1
        share = self.share
        if share is not None and share.owner == _HELPER:
            if share.claim(index):
                try:
                    figure, replay = _draw(make, caption, filename)
                    share.drawn[index] = (figure.png, replay)
                except Exception:  # noqa: BLE001 - drawn again (and raised) by the report's own process
                    share.drawn[index] = None
            return
        if share is not None and not share.claim(index):  # the helper draws it
            figure = Figure(caption=caption, png=b"", filename=filename)
            self._pending.append((index, figure, make))
        else:
            figure, self._replay[index] = _draw(make, caption, filename)
        section.figures.append(figure)

    def finish(self) -> None:
        """The helper's figures filled in (or drawn here), then every figure's warnings in order."""
        if self.share is not None and self.share.owner == _HELPER:
            return
        if self.share is not None:
            drawn = self.share.collect()
            for index, figure, make in self._pending:
                got = drawn.get(index)
                if got is None:
                    again, self._replay[index] = _draw(make, figure.caption, figure.filename)
                    figure.png = again.png
                else:
                    figure.png, self._replay[index] = got
            self._pending.clear()
        for index in sorted(self._replay):
            for category, text in self._replay[index]:
                warnings.warn(text, category, stacklevel=2)
        self._replay.clear()

