"""Command-line interface ``chaindrive``.

Each topic registers its subcommands in its own module (``cli/<topic>.py``) through
:func:`chaindrive.cli.app.register`; this keeps the topics independent.
Errors of the package (:class:`~chaindrive.errors.ChainDriveError`) and file errors are
printed as one line on stderr with exit code 2, never as a traceback; anything else is
an internal error, printed as one line with exit code 3 (``--debug`` shows the
traceback).
"""

from __future__ import annotations

from .. import _interrupt

# Ctrl-C during the imports below (a few hundred ms) ends the command with one line, not a
# traceback; main() installs its own handler, and a library import gets the previous one back
_BEFORE = _interrupt.install_early()

import importlib  # noqa: E402
import sys  # noqa: E402

from ..errors import ChainDriveError  # noqa: E402
from .app import app  # noqa: E402

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
    "life",
    "cad",
)

for _topic in TOPICS:
    try:
        importlib.import_module(f"{__name__}.{_topic}")
    except ModuleNotFoundError as exc:  # a topic module not written yet
        if exc.name != f"{__name__}.{_topic}":
            raise
if not _interrupt.is_command():
    _interrupt.restore(_BEFORE)


#: Warnings printed by the current command (each text once, whatever the place it comes from).
_SHOWN: set[str] = set()


def _show_warning(message, category, filename, lineno, file=None, line=None):  # noqa: ARG001
    """Print a warning as one line ``warning: ...`` on stderr (no source line), each text once."""
    text = str(message)
    if text in _SHOWN:
        return
    _SHOWN.add(text)
    print(f"warning: {text}", file=sys.stderr if file is None else file)


#: Longest error message printed (lines); the rest is summarised.
MAX_ERROR_LINES = 25


def _one_line(text: object) -> str:
    lines = [ln for ln in str(text).splitlines() if ln.strip()]
    return lines[0] if lines else ""


_LONG_NUMBER = None


def shorten_numbers(text: str) -> str:
    """Numbers of more than 15 digits in a message written with 6 significant digits.

    Examples
    --------
    >>> shorten_numbers("ratio must lie in (0, 10], got " + "1" + "0" * 300 + ".0")
    'ratio must lie in (0, 10], got 1e+300'
    >>> shorten_numbers("teeth 1000000")
    'teeth 1000000'
    """
    import re

    global _LONG_NUMBER
    if _LONG_NUMBER is None:
        _LONG_NUMBER = re.compile(r"(?<![\w.])-?\d{16,}(?:\.\d*)?(?:[eE][-+]?\d+)?(?![\w.])")
    return _LONG_NUMBER.sub(lambda m: f"{float(m.group()):.6g}", text)


def _notes(exc: BaseException | None) -> str:
    notes = []
    while exc is not None:
        notes += [n for n in getattr(exc, "__notes__", []) or [] if n not in notes]
        exc = exc.__cause__ or exc.__context__
    return "".join(f"; {n}" for n in notes)


def _completed() -> str:
    """For an interrupt without a note (it came after the command's run folder was moved
    into place, while its last lines were printed): the folder's results are complete."""
    from .._folders import completed_note

    note = completed_note()
    return f"; {note}" if note else ""


def _cap(text: object, limit: int = MAX_ERROR_LINES) -> str:
    lines = shorten_numbers(str(text)).splitlines() or [""]
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


class Interrupted(BaseException):
    """Ctrl-C (SIGINT) during a command; raised instead of KeyboardInterrupt so that typer
    does not swallow it, and the message can say what is kept."""


def _on_interrupt(signum: int, frame: object) -> None:  # noqa: ARG001
    raise Interrupted


def main(argv: list[str] | None = None) -> int:
    """Entry point of the ``chaindrive`` command; returns the exit code.

    Exit codes: 0 success, 1 a check failed, 2 bad input (one line ``error: ...`` on
    stderr: an invalid value, a missing, unreadable or unwritable file, an existing
    output without ``--force``), 3 an internal error (one line; ``--debug`` prints the
    traceback).
    """
    import os
    import warnings

    argv = list(sys.argv[1:] if argv is None else argv)
    argv, debug = _split_debug(argv)
    debug = debug or os.environ.get("CHAINDRIVE_DEBUG", "") not in ("", "0")
    import signal
    import threading

    warnings.showwarning = _show_warning
    _SHOWN.clear()
    previous = None
    if threading.current_thread() is threading.main_thread():
        previous = signal.signal(signal.SIGINT, _on_interrupt)
    try:
        return _main(argv, debug)
    finally:
        if previous is not None:
            signal.signal(signal.SIGINT, previous)


def _main(argv: list[str], debug: bool) -> int:
    import os
    import traceback

    try:
        rv = app(args=argv, prog_name="chaindrive", standalone_mode=False)
    except ChainDriveError as exc:  # named by the option the user typed, not the formula's parameter
        from .app import command_options, name_options

        try:
            text = name_options(str(exc), *command_options(argv))
        except Exception:  # noqa: BLE001 - the message as raised is still an answer
            text = str(exc)
        print(f"error: {_cap(text)}", file=sys.stderr)
        return 2
    except SystemExit as exc:  # typer/click exits
        code = exc.code
        if code is None:
            return 0
        if isinstance(code, int):
            return code
        print(f"error: {code}", file=sys.stderr)
        return 2
    except (KeyboardInterrupt, Interrupted) as exc:  # the note says what is kept
        print(f"interrupted{_notes(exc) or _completed()}", file=sys.stderr)
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
        from .._io import show_path

        where = f": {show_path(exc.filename)}" if getattr(exc, "filename", None) else ""
        print(f"error: {exc.strerror or _one_line(exc) or type(exc).__name__}{where}{_notes(exc)}",
              file=sys.stderr)
        return 2
    except Exception as exc:  # click usage errors in non-standalone mode, and the unexpected
        if hasattr(exc, "show") and hasattr(exc, "exit_code"):  # click.ClickException
            exc.show()
            return 2
        if type(exc).__name__ == "Abort":  # click's answer to Ctrl-C (or EOF at a prompt)
            if isinstance(exc.__context__, KeyboardInterrupt):
                print(f"interrupted{_notes(exc.__context__) or _completed()}", file=sys.stderr)
                return 130
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
