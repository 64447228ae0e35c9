"""Command-line interface ``chaindrive``.

Each topic registers its subcommands in its own module (``cli/<topic>.py``) through
:func:`chaindrive.cli.app.register`; this keeps the topics independent.
Errors of the package (:class:`~chaindrive.errors.ChainDriveError`) are printed as one
line on stderr with exit code 2, never as a traceback.
"""

from __future__ import annotations

import importlib
import sys

from ..errors import ChainDriveError
from .app import app

#: Topic modules that add subcommands; a missing optional one is skipped.
TOPICS = (
    "demo",
    "chains",
    "kinematics",
    "vibration",
    "geometry",
    "strength",
    "drive",
    "simulate",
    "web",
    "analyze",
    "crawler",
)

for _topic in TOPICS:
    try:
        importlib.import_module(f"{__name__}.{_topic}")
    except ModuleNotFoundError as exc:  # a topic module not written yet
        if exc.name != f"{__name__}.{_topic}":
            raise


def _show_warning(message, category, filename, lineno, file=None, line=None):  # noqa: ARG001
    """Print a warning as one line ``warning: ...`` on stderr (no source line)."""
    print(f"warning: {message}", file=sys.stderr if file is None else file)


def main(argv: list[str] | None = None) -> int:
    """Entry point of the ``chaindrive`` command; returns the exit code."""
    import warnings

    warnings.showwarning = _show_warning
    try:
        rv = app(args=argv, prog_name="chaindrive", standalone_mode=False)
    except ChainDriveError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    except SystemExit as exc:  # typer/click exits
        return int(exc.code or 0)
    except Exception as exc:  # click usage errors in non-standalone mode
        if hasattr(exc, "show") and hasattr(exc, "exit_code"):  # click.ClickException
            exc.show()
            return 2
        if type(exc).__name__ == "Abort":
            return 1
        raise
    return rv if isinstance(rv, int) else 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
