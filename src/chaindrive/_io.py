"""Safe output files and folders (internal): nothing half-written, nothing lost.

Every file chaindrive writes goes first to a temporary file in the same folder, is
flushed to disk (``fsync``) and then renamed over its final name (``os.replace``, atomic
on POSIX and Windows). A reader therefore sees either the earlier file or the complete
new one, never a half-written file.

Output folders (run folders) are built aside and moved into place under a lock: see
:mod:`chaindrive._folders` (re-exported here).

Problems with a path (missing folder, a directory where a file is expected, no write
permission, an unsupported file extension, an existing file) raise
:class:`~chaindrive.errors.InputError` naming the option, before any work is done.
"""

from __future__ import annotations

import contextlib
import os
import tempfile
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import TYPE_CHECKING, Any, TypeVar

from ._folders import (
    RUN_MARKER,
    atomic_output_dir,
    check_output_dir,
    claim_output_dir,
    earlier_run_note,
    folder_lock,
    recover_output_dir,
    show_path,
)
from .errors import ChainDriveError, InputError

if TYPE_CHECKING:
    from ezdxf.document import Drawing
    from matplotlib.figure import Figure

#: A decorated function (its signature is kept).
F = TypeVar("F", bound=Callable[..., Any])

__all__ = [
    "RUN_MARKER",
    "atomic_write_bytes",
    "atomic_write_text",
    "check_output_path",
    "check_output_dir",
    "atomic_output_dir",
    "claim_output_dir",
    "folder_lock",
    "show_path",
    "earlier_run_note",
    "FIGURE_SUFFIXES",
    "save_figure",
    "save_dxf",
    "note_earlier_run",
]

def _reason(exc: OSError) -> str:
    return exc.strerror or type(exc).__name__


def _check_parent(path: Path, option: str) -> None:
    parent = path.parent if str(path.parent) else Path(".")
    if not parent.exists():
        raise InputError(f"{option}: the folder {str(parent)!r} of {str(path)!r} does not exist "
                         "(create it first, or give a path in an existing folder)")
    if not parent.is_dir():
        raise InputError(f"{option}: {str(parent)!r} is not a folder, so {str(path)!r} cannot be written")
    if not os.access(parent, os.W_OK | os.X_OK):
        raise InputError(f"{option}: no permission to write in the folder {str(parent)!r}")


def _file_mode(path: Path) -> int:
    """Mode of a new file: the existing file's mode, else 0o666 less the umask."""
    try:
        return path.stat().st_mode & 0o7777
    except OSError:
        mask = os.umask(0)
        os.umask(mask)
        return 0o666 & ~mask


def check_output_path(
    path: str | os.PathLike,
    allowed_suffixes: Iterable[str] | None = None,
    *,
    option: str = "output",
    force: bool = True,
) -> Path:
    """Check, before any work is done, that a single output file can be written.

    Parameters
    ----------
    path : str or os.PathLike
        The file the user asked for.
    allowed_suffixes : iterable of str, optional
        Accepted extensions with the dot, e.g. ``(".png", ".svg")`` (case-insensitive);
        ``None`` accepts any.
    option : str
        The option or field the path came from (named in every message), e.g. ``"--svg"``.
    force : bool
        Whether an existing file may be replaced.

    Returns
    -------
    pathlib.Path
        The path.

    Raises
    ------
    InputError
        Empty path, unsupported extension (the allowed ones are listed), a folder, a
        missing or read-only parent folder, or an existing file without ``force``.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> d = pathlib.Path(tempfile.mkdtemp())
    >>> check_output_path(d / "k.png", (".png", ".svg"), option="--plot").name
    'k.png'
    >>> check_output_path(d / "k.dxf", (".png", ".svg"), option="--plot")
    Traceback (most recent call last):
    ...
    chaindrive.errors.InputError: --plot: unsupported file type '.dxf' of 'k.dxf'; use one of .png, .svg
    """
    text = os.fspath(path)
    if not str(text).strip():
        raise InputError(f"{option}: empty file name; give a file path")
    try:
        return _check_output_path(text, allowed_suffixes, option, force)
    except OSError as exc:  # a name too long, a loop of links, ...
        raise InputError(f"{option}: cannot write {show_path(text)}: {_reason(exc)}") from None


def _check_output_path(text: str, allowed_suffixes: Iterable[str] | None, option: str, force: bool) -> Path:
    p = Path(text)
    if len(os.fsencode(p.name)) > 250:
        raise InputError(f"{option}: the file name {show_path(p.name)} is {len(os.fsencode(p.name))} "
                         "bytes long; file names have at most 250 bytes")
    if p.is_dir() or str(text).endswith(("/", os.sep)):
        raise InputError(f"{option}: {show_path(text)} is a folder; give a file name"
                         + (f" ending in {', '.join(allowed_suffixes)}" if allowed_suffixes else ""))
    if allowed_suffixes is not None:
        allowed = tuple(s.lower() for s in allowed_suffixes)
        if p.suffix.lower() not in allowed:
            what = f"file type {p.suffix!r}" if p.suffix else "file name without an extension"
            raise InputError(f"{option}: unsupported {what} of {p.name!r}; use one of {', '.join(allowed)}")
    _check_parent(p, option)
    if p.exists() or p.is_symlink():
        if not p.is_file():
            raise InputError(f"{option}: {show_path(text)} exists and is not a regular file")
        if not force:
            raise InputError(f"{option}: {show_path(text)} exists; use --force to overwrite it")
        if not os.access(p, os.W_OK):
            raise InputError(f"{option}: {show_path(text)} exists and is read-only")
    return p


def atomic_write_bytes(path: str | os.PathLike, data: bytes, *, force: bool = False,
                       option: str = "output") -> Path:
    """Write ``data`` to ``path`` atomically (temporary file, fsync, rename).

    Parameters
    ----------
    path : str or os.PathLike
        Destination file; its folder must exist.
    data : bytes
        The content.
    force : bool
        Replace an existing file (otherwise refused).
    option : str
        Name of the option or field the path came from, used in messages.

    Returns
    -------
    pathlib.Path
        The path written.

    Raises
    ------
    InputError
        The path is a folder, its folder is missing or not writable, the file exists
        and ``force`` is false, or the operating system refuses the write.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> f = pathlib.Path(tempfile.mkdtemp()) / "a.txt"
    >>> atomic_write_bytes(f, b"one").read_bytes()
    b'one'
    >>> atomic_write_bytes(f, b"two")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    chaindrive.errors.InputError: output: '...a.txt' exists; use --force to overwrite it
    >>> atomic_write_bytes(f, b"two", force=True).read_bytes()
    b'two'
    """
    p = check_output_path(path, None, option=option, force=force)
    folder = p.parent if str(p.parent) else Path(".")
    fd = None
    tmp = None
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{p.name[:200]}.", suffix=".tmp", dir=folder)
        with os.fdopen(fd, "wb") as fh:
            fd = None
            fh.write(data)
            fh.flush()
            os.fsync(fh.fileno())
        os.chmod(tmp, _file_mode(p))
        if not force and p.exists():  # appeared meanwhile
            raise InputError(f"{option}: {str(p)!r} exists; use --force to overwrite it")
        os.replace(tmp, p)
        tmp = None
    except OSError as exc:  # disk full, quota, read-only: say what is kept
        kept = (f"{show_path(p)} was left unchanged" if p.exists() else "nothing was written")
        raise InputError(f"{option}: cannot write {show_path(p)}: {_reason(exc)}; {kept}") from None
    finally:
        if fd is not None:
            os.close(fd)
        if tmp is not None:
            with contextlib.suppress(OSError):
                os.unlink(tmp)
    return p


def atomic_write_text(path: str | os.PathLike, text: str, *, force: bool = False,
                      option: str = "output", encoding: str = "utf-8") -> Path:
    """Write ``text`` to ``path`` atomically; see :func:`atomic_write_bytes`.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> f = pathlib.Path(tempfile.mkdtemp()) / "a.toml"
    >>> atomic_write_text(f, "x = 1\\n").read_text()
    'x = 1\\n'
    """
    return atomic_write_bytes(path, text.encode(encoding), force=force, option=option)


#: File types a figure can be saved as (matplotlib back ends always present).
FIGURE_SUFFIXES = (".png", ".svg", ".pdf")


def save_figure(figure: Figure, path: str | os.PathLike, *, option: str = "--plot", dpi: int = 120,
                force: bool = True, **savefig_options: Any) -> Path:
    """Render a matplotlib figure in memory and write it atomically.

    The format comes from the extension (one of :data:`FIGURE_SUFFIXES`). Existing
    files named explicitly by the user are replaced (``force=True``), atomically.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> import matplotlib; matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> fig, ax = plt.subplots()
    >>> p = save_figure(fig, pathlib.Path(tempfile.mkdtemp()) / "a.png")
    >>> p.read_bytes()[:4]
    b'\\x89PNG'
    >>> plt.close(fig)
    """
    import io

    p = check_output_path(path, FIGURE_SUFFIXES, option=option, force=force)
    buf = io.BytesIO()
    figure.savefig(buf, format=p.suffix.lower().lstrip("."), dpi=dpi, **savefig_options)
    return atomic_write_bytes(p, buf.getvalue(), force=force, option=option)


def save_dxf(document: Drawing, path: str | os.PathLike, *, option: str = "--dxf", force: bool = True) -> Path:
    """Write an ezdxf document atomically (text DXF, in the document's encoding)."""
    import io

    p = check_output_path(path, (".dxf",), option=option, force=force)
    stream = io.StringIO()
    document.write(stream)
    encoding = getattr(document, "output_encoding", "utf-8") or "utf-8"
    return atomic_write_bytes(p, stream.getvalue().encode(encoding, errors="replace"),
                              force=force, option=option)


# --------------------------------------------------------------------------- reading

#: Largest project file read [bytes] (1 MiB; the templates are about 2 KiB).
MAX_PROJECT_BYTES = 1 << 20
#: Deepest nesting of arrays and tables accepted in a project file.
MAX_NESTING = 32

_TOML_SKIP = None


def read_text_file(path: str | os.PathLike, *, what: str = "project file",
                   max_bytes: int = MAX_PROJECT_BYTES) -> str:
    """Read a UTF-8 text file given by the user, refusing with one clear line what is not one.

    Parameters
    ----------
    path : str or os.PathLike
        The file.
    what : str
        What the file is, for messages (``"project file"``).
    max_bytes : int
        Largest size accepted [bytes].

    Returns
    -------
    str
        The text (a leading UTF-8 byte-order mark removed).

    Raises
    ------
    InputError
        Missing, a folder, unreadable, larger than ``max_bytes``, binary (NUL bytes),
        or not UTF-8 (the offset of the first bad byte is named).

    Examples
    --------
    >>> import tempfile, pathlib
    >>> f = pathlib.Path(tempfile.mkdtemp()) / "bin.toml"
    >>> _ = f.write_bytes(b"\\x89PNG\\r\\n\\x1a\\n\\x00\\x00")
    >>> read_text_file(f)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    chaindrive.errors.InputError: project file '...bin.toml' is a binary file, not a TOML text file
    """
    text = os.fspath(path)
    if not str(text).strip():
        raise InputError(f"{what}: empty file name; give the path of a TOML file")
    with contextlib.suppress(OSError, ValueError):
        if not os.path.exists(text):  # a run folder swapped out by a killed run: put back
            recover_output_dir(os.path.dirname(os.path.abspath(text)))
    p = Path(text)
    try:
        if p.is_dir():
            raise InputError(f"{what} {text!r} is a folder; give a TOML file")
        with open(p, "rb") as fh:
            data = fh.read(max_bytes + 1)
    except InputError:
        raise
    except FileNotFoundError:
        raise InputError(f"{what} {text!r} does not exist") from None
    except OSError as exc:
        raise InputError(f"cannot read {what} {text!r}: {_reason(exc)}") from None
    if len(data) > max_bytes:
        raise InputError(f"{what} {text!r} is larger than {max_bytes // 1024} KiB; a project file is "
                         "a few KiB of text (is it the right file?)")
    if b"\x00" in data[:65536]:
        raise InputError(f"{what} {text!r} is a binary file, not a TOML text file")
    try:
        decoded = data.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise InputError(f"{what} {text!r} is not UTF-8 text (byte 0x{data[exc.start]:02x} at offset "
                         f"{exc.start}); save it as UTF-8") from None
    return decoded.removeprefix("\ufeff")


def _strip_toml_strings(text: str) -> str:
    import re

    global _TOML_SKIP
    if _TOML_SKIP is None:
        _TOML_SKIP = re.compile(
            r'"""[\s\S]*?"""|\'\'\'[\s\S]*?\'\'\'|"(?:[^"\\\n]|\\.)*"|\'[^\'\n]*\'|#[^\n]*')
    return _TOML_SKIP.sub("", text)


def toml_nesting(text: str) -> int:
    """Deepest bracket/brace nesting of a TOML text outside strings and comments.

    Examples
    --------
    >>> toml_nesting('a = [[1, 2], {b = "[[["}]  # ]]]')
    2
    """
    import numpy as np

    code = _strip_toml_strings(text).encode("utf-8", errors="replace")
    if not code:
        return 0
    b = np.frombuffer(code, dtype=np.uint8)
    step = ((b == 91) | (b == 123)).astype(np.int64) - ((b == 93) | (b == 125))
    return int(max(0, np.cumsum(step).max()))


def _data_depth(data) -> int:
    """Nesting depth of parsed data, walked without recursion."""
    deepest, stack = 0, [(data, 0)]  # the document's own table is level 0
    while stack:
        obj, depth = stack.pop()
        children: Iterable[Any]
        if isinstance(obj, dict):
            children = obj.values()
        elif isinstance(obj, list):
            children = obj
        else:
            continue
        deepest = max(deepest, depth)
        if deepest > MAX_NESTING:
            return deepest
        stack.extend((c, depth + 1) for c in children)
    return deepest


def load_toml_text(text: str, filename: str = "<project>", *, max_nesting: int = MAX_NESTING) -> dict:
    """Parse TOML text with the limits of a project file; errors are one line.

    Parameters
    ----------
    text : str
        The TOML text.
    filename : str
        Name used in messages.
    max_nesting : int
        Deepest nesting of arrays/tables accepted (checked before parsing).

    Returns
    -------
    dict
        The parsed tables.

    Raises
    ------
    InputError
        Syntax error (with line and column), nesting deeper than ``max_nesting``,
        a text too large for the parser.

    Examples
    --------
    >>> load_toml_text("a = [[1]]")
    {'a': [[1]]}
    >>> load_toml_text("a = " + "[" * 40 + "]" * 40)
    Traceback (most recent call last):
    ...
    chaindrive.errors.InputError: <project>: arrays or tables nested 40 deep; a project file nests at most 32 deep
    """
    import tomllib

    if len(text) > MAX_PROJECT_BYTES:
        raise InputError(f"{filename}: text larger than {MAX_PROJECT_BYTES // 1024} KiB; a project "
                         "file is a few KiB")
    depth = toml_nesting(text)
    if depth > max_nesting:
        raise InputError(f"{filename}: arrays or tables nested {depth} deep; a project file nests "
                         f"at most {max_nesting} deep")
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputError(f"{filename}: TOML syntax error: {exc}") from None
    except RecursionError:
        raise InputError(f"{filename}: arrays or tables nested too deep; a project file nests at "
                         f"most {max_nesting} deep") from None
    depth = _data_depth(data)
    if depth > max_nesting:
        raise InputError(f"{filename}: keys or tables nested more than {max_nesting} deep; a project "
                         f"file nests at most {max_nesting} deep")
    return data


def cap_lines(lines: list[str], limit: int = 20) -> list[str]:
    """The first ``limit`` lines, then ``... and N more``.

    Examples
    --------
    >>> cap_lines([str(i) for i in range(5)], 2)
    ['0', '1', '... and 3 more']
    """
    if len(lines) <= limit:
        return list(lines)
    return list(lines[:limit]) + [f"... and {len(lines) - limit} more"]


def note_earlier_run(parameter: str = "output") -> Callable[[F], F]:
    """Decorate a command writing a run folder: a chaindrive error raised anywhere in it
    (bad input found late, a failed computation) says that the results already in the
    folder are from an earlier run, when there is one.

    The wrapped function keeps its signature (``functools.wraps``), so typer sees the
    same options.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> d = pathlib.Path(tempfile.mkdtemp())
    >>> _ = (d / RUN_MARKER).write_text("{}")
    >>> @note_earlier_run()
    ... def command(output):
    ...     raise InputError("speed must be positive")
    >>> command(output=d)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    chaindrive.errors.InputError: speed must be positive; nothing was written; the files in '...' are from an earlier run and were left unchanged
    """
    import functools
    import inspect

    def decorate(function):
        names = list(inspect.signature(function).parameters)

        @functools.wraps(function)
        def wrapper(*args, **kwargs):
            try:
                return function(*args, **kwargs)
            except ChainDriveError as exc:
                folder = kwargs.get(parameter)
                if folder is None and parameter in names and names.index(parameter) < len(args):
                    folder = args[names.index(parameter)]
                if folder is None or "earlier run" in str(exc):
                    raise
                try:
                    earlier = (Path(folder) / RUN_MARKER).is_file()
                except (OSError, TypeError, ValueError):
                    earlier = False
                if not earlier:
                    raise
                raise type(exc)(f"{exc}; {earlier_run_note(folder)}") from None

        return wrapper

    return decorate
