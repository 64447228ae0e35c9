"""Progress of a study run on stderr (internal): the rich bar, or under ``--quiet`` a line now
and then for a long study (so that a study of hours never runs silent)."""

from __future__ import annotations

import sys
import time
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from rich.progress import Progress

__all__ = ["LONG_STUDY", "progress_bar", "QuietProgress"]

#: A study of at least this many variants to compute is "long": under ``--quiet`` it still
#: prints a line at the start and one a minute (about 1 min of compute on 2 cores).
LONG_STUDY = 10_000

#: Seconds between two lines of :class:`QuietProgress`.
LINE_EVERY = 60.0


def progress_bar(enabled: bool) -> Progress | None:
    """The rich progress bar with ETA on stderr (None when disabled)."""
    if not enabled:
        return None
    from rich.console import Console
    from rich.progress import (
        BarColumn,
        MofNCompleteColumn,
        Progress,
        TextColumn,
        TimeElapsedColumn,
        TimeRemainingColumn,
    )

    return Progress(TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(),
                    TextColumn("{task.fields[rate]}"), TimeElapsedColumn(),
                    TextColumn("ETA"), TimeRemainingColumn(),
                    console=Console(stderr=True), refresh_per_second=4)


class QuietProgress:
    """One line at the start and one every :data:`LINE_EVERY` s, for a long study under ``-q``.

    Examples
    --------
    >>> import io
    >>> out = io.StringIO()
    >>> p = QuietProgress(20_000, stream=out)
    >>> p.update(5_000, 100.0, force=True)
    >>> out.getvalue().splitlines()[-1]
    'study: 5,000 of 20,000 variants computed (100.0 variants/s, about 2 min 30 s left)'
    """

    def __init__(self, total: int, *, stream=None, every: float = LINE_EVERY):
        self.total = total
        self.stream = stream if stream is not None else sys.stderr
        self.every = every
        self.last = time.monotonic()
        self._write(f"study: {total:,} variants to compute; a long run (Ctrl-C stops it, a rerun "
                    "into the same folder resumes); a progress line every minute")

    def _write(self, text: str) -> None:
        try:
            self.stream.write(text + "\n")
            self.stream.flush()
        except (OSError, ValueError):  # a closed stderr: the study goes on
            pass

    def update(self, done: int, rate: float, *, force: bool = False) -> None:
        now = time.monotonic()
        if not force and now - self.last < self.every:
            return
        self.last = now
        left = (self.total - done) / rate if rate > 0 else None
        eta = "" if left is None else f", about {_duration(left)} left"
        self._write(f"study: {done:,} of {self.total:,} variants computed ({rate:.1f} variants/s{eta})")


def _duration(seconds: float) -> str:
    s = int(round(seconds))
    if s >= 3600:
        return f"{s // 3600} h {s % 3600 // 60} min"
    if s >= 60:
        return f"{s // 60} min {s % 60} s"
    return f"{s} s"
