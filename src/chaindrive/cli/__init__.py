"""Command-line interface ``chaindrive``.

Each topic registers its subcommands in its own module (``cli/<topic>.py``) through
:func:`chaindrive.cli.app.register`; this keeps the topics independent.
Errors of the package (:class:`~chaindrive.errors.ChainDriveError`) and file errors are
printed as one line on stderr with exit code 2, never as a traceback; anything else is
an internal error, printed as one line with exit code 3 (``--debug`` shows the
traceback).
"""

from __future__ import annotations

import importlib
import sys

from ..errors import ChainDriveError
from .app import app

__all__ = ["main", "TOPICS"]

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
    "study",
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


#: Longest error message printed (lines); the rest is summarised.
MAX_ERROR_LINES = 25


def _one_line(text: object) -> str:
    lines = [ln for ln in str(text).splitlines() if ln.strip()]
    return lines[0] if lines else ""


def _cap(text: object, limit: int = MAX_ERROR_LINES) -> str:
    lines = str(text).splitlines() or [""]
    if len(lines) <= limit:
        return "\n".join(lines)
    return "\n".join(lines[:limit] + [f"... and {len(lines) - limit} more"])


def _split_debug(argv: list[str]) -> tuple[list[str], bool]:
    """Remove the global ``--debug`` flag (anywhere before a ``--``) from ``argv``."""
    out, debug, rest = [], False, False
    for a in argv:
        if not rest and a == "--debug":
            debug = True
            continue
        rest = rest or a == "--"
        out.append(a)
    return out, debug


def main(argv: list[str] | None = None) -> int:
    """Entry point of the ``chaindrive`` command; returns the exit code.

    Exit codes: 0 success, 1 a check failed, 2 bad input (one line ``error: ...`` on
    stderr: an invalid value, a missing, unreadable or unwritable file, an existing
    output without ``--force``), 3 an internal error (one line; ``--debug`` prints the
    traceback).
    """
    import os
    import traceback
    import warnings

    argv = list(sys.argv[1:] if argv is None else argv)
    argv, debug = _split_debug(argv)
    debug = debug or os.environ.get("CHAINDRIVE_DEBUG", "") not in ("", "0")
    warnings.showwarning = _show_warning
    try:
        rv = app(args=argv, prog_name="chaindrive", standalone_mode=False)
    except ChainDriveError as exc:
        print(f"error: {_cap(exc)}", file=sys.stderr)
        return 2
    except SystemExit as exc:  # typer/click exits
        code = exc.code
        if code is None:
            return 0
        if isinstance(code, int):
            return code
        print(f"error: {code}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:  # e.g. `chaindrive chains | head`
        try:
            sys.stdout = open(os.devnull, "w")  # noqa: SIM115 - silence the flush at exit
        except OSError:
            pass
        return 1
    except OverflowError as exc:  # a value too large for double precision somewhere in a formula
        print(f"error: a number overflows ({_one_line(exc) or 'too large'}); check the inputs' "
              "magnitudes and units", file=sys.stderr)
        return 2
    except OSError as exc:  # a file or folder the command was given
        where = f": {exc.filename!r}" if getattr(exc, "filename", None) else ""
        print(f"error: {exc.strerror or _one_line(exc) or type(exc).__name__}{where}", file=sys.stderr)
        return 2
    except Exception as exc:  # click usage errors in non-standalone mode, and the unexpected
        if hasattr(exc, "show") and hasattr(exc, "exit_code"):  # click.ClickException
            exc.show()
            return 2
        if type(exc).__name__ == "Abort":
            return 1
        if debug:
            traceback.print_exc()
        text = _one_line(exc)
        notes = "; ".join(getattr(exc, "__notes__", []) or [])
        print(f"internal error: {type(exc).__name__}{': ' + text if text else ''}"
              f"{'; ' + notes if notes else ''}"
              f"{'' if debug else '; run with --debug for the traceback'}", file=sys.stderr)
        return 3
    return rv if isinstance(rv, int) else 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
