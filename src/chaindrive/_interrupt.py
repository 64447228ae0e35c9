"""Ctrl-C while the ``chaindrive`` command is still starting (internal).

Until :func:`chaindrive.cli.main` installs its own handler (which says what is kept), a
SIGINT ends the command with one line ``interrupted`` and exit code 130, never a
traceback of an import. Only builtin modules are used, so the handler is in place a few
microseconds after ``import chaindrive`` begins.
"""

from __future__ import annotations

import _signal
import os
import sys

__all__ = ["install_early", "restore"]


def _exit_130(signum, frame):  # noqa: ARG001
    try:
        os.write(2, b"interrupted\n")
    finally:
        os._exit(130)


def install_early() -> object | None:
    """Install the start-up handler in the main thread when SIGINT has Python's default
    handler; returns the previous handler (None: nothing installed)."""
    try:
        if _signal.getsignal(_signal.SIGINT) is not _signal.default_int_handler:
            return None
        return _signal.signal(_signal.SIGINT, _exit_130)
    except (ValueError, OSError):  # not the main thread
        return None


def restore(previous: object | None) -> None:
    """Put back the handler :func:`install_early` replaced (if it is still ours)."""
    if previous is None:
        return
    try:
        if _signal.getsignal(_signal.SIGINT) is _exit_130:
            _signal.signal(_signal.SIGINT, previous)
    except (ValueError, OSError):
        pass


def is_command() -> bool:
    """Whether this process is the ``chaindrive`` command (its script name)."""
    name = os.path.basename(sys.argv[0]) if sys.argv and sys.argv[0] else ""
    return name in ("chaindrive", "chaindrive.exe", "__main__.py")
