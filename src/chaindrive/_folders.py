"""Run folders (internal): built aside, moved into place under a lock, nothing of the user's lost.

Output folders (``chaindrive analyze -o DIR``, ``chaindrive simulate -o DIR``,
``chaindrive demo -o DIR``) are built in a hidden sibling folder ``.DIR.XXXXXXXX.partial``
and moved into place when complete. The policy, also described in README "Using it" and
in the commands' help:

* a new or empty ``DIR`` is simply filled;
* a ``DIR`` that holds an earlier run (it has the marker file ``.chaindrive-run``, which
  lists the files of that run with the SHA-256 of each) is replaced only with ``--force``;
  without it the command stops before any work;
* a ``DIR`` that holds files chaindrive did not write (no marker, or files the marker does
  not list) or files changed since chaindrive wrote them (their content no longer matches
  the marker's hash) is never replaced, not even with ``--force``: chaindrive deletes only
  files it wrote and that are unchanged since; the message names the files;
* a ``DIR`` that holds the command's own input (``chaindrive analyze DIR/proposal.toml -o
  DIR --force``) is never replaced: refused with the file's name;
* one run at a time per folder: the run holds an advisory lock (``fcntl.flock`` on the
  file ``.DIR.lock`` beside the folder) from its start to the move; a second run into a
  folder in use is refused at once with one line;
* the rules are checked again at the moment of the move: when files appeared in ``DIR``
  during the run, nothing there is touched and the new results are kept in a sibling
  folder (``DIR.new``, ``DIR.new-2``, ...) named in the message;
* a symbolic link ``DIR`` is followed: the run goes where it points (the link is kept);
  a link loop is refused;
* when a run fails or is interrupted, the earlier results are left untouched and the
  message says so; the half-built folder is removed. What a killed run left behind
  (``.DIR.*.partial``, ``.DIR.*.old``) is cleaned by the next run into that place; an
  earlier run moved aside and not yet replaced is put back first;
* the final swap exchanges the new folder and ``DIR`` in one atomic step where the system
  offers it (Linux ``renameat2(RENAME_EXCHANGE)``), so a reader always finds a complete
  ``DIR``, even when the run is killed in the middle; elsewhere ``DIR`` is renamed aside
  (``.DIR.*.old``) and the new folder renamed to ``DIR``, and :func:`recover_output_dir`
  (called by the next run, and by readers) puts a complete run back at once.
"""

from __future__ import annotations

import contextlib
import errno
import hashlib
import json
import os
import re
import shutil
import tempfile
import warnings
from collections.abc import Iterable, Iterator
from pathlib import Path
from typing import Any

from .errors import ChainDriveError, ChainDriveWarning, InputError

try:  # POSIX; elsewhere runs are not locked
    import fcntl
except ImportError:  # pragma: no cover - Windows
    fcntl = None  # type: ignore[assignment]

__all__ = [
    "RUN_MARKER",
    "check_output_dir",
    "claim_output_dir",
    "folder_lock",
    "atomic_output_dir",
    "earlier_run_note",
    "resolve_output_dir",
    "show_path",
    "recover_output_dir",
    "run_marker",
    "protect_inputs",
]

#: Marker file that identifies a folder written by chaindrive (a "run folder").
RUN_MARKER = ".chaindrive-run"
_COMPLETED: list[str] = []  #: run folders this process moved into place (for completed_note)


def completed_note() -> str:
    """What a Ctrl-C after the last run folder was moved into place keeps: its results
    are complete ("" when this process has completed none).

    Examples
    --------
    >>> _COMPLETED.append("out"); completed_note()
    "the results in 'out' were complete before the interrupt"
    >>> _COMPLETED.clear(); completed_note()
    ''
    """
    if not _COMPLETED:
        return ""
    return f"the results in {show_path(_COMPLETED[-1])} were complete before the interrupt"

#: Longest path shown in a message [characters]; longer ones are shortened in the middle.
SHOWN_PATH = 100


def show_path(path: str | os.PathLike) -> str:
    """A path quoted for a message, shortened in the middle when very long.

    Examples
    --------
    >>> show_path("out/run")
    "'out/run'"
    >>> len(show_path("a" * 300 + ".png")) < 110
    True
    """
    text = os.fspath(path)
    if len(text) > SHOWN_PATH:
        text = f"{text[:60]}...{text[-(SHOWN_PATH - 63):]}"
    return repr(text)


def _reason(exc: OSError) -> str:
    return exc.strerror or type(exc).__name__


def _entries(folder: Path) -> list[str]:
    try:
        return sorted(os.listdir(folder))
    except OSError as exc:
        raise InputError(f"cannot read the folder {show_path(folder)}: {_reason(exc)}") from None


def _listed_files(folder: Path) -> set[str] | None:
    """The files the run marker of ``folder`` lists as chaindrive's (None: no usable list)."""
    try:
        data = json.loads((folder / RUN_MARKER).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    files = data.get("files") if isinstance(data, dict) else None
    if not isinstance(files, list) or not all(isinstance(f, str) for f in files):
        return None
    return {f for f in files if f and not os.path.isabs(f) and ".." not in Path(f).parts}


def _hashes(folder: Path) -> dict[str, str] | None:
    """``{file: sha256}`` of the marker of ``folder`` (None: an earlier marker without hashes)."""
    try:
        data = json.loads((folder / RUN_MARKER).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    found = data.get("sha256") if isinstance(data, dict) else None
    if not isinstance(found, dict):
        return None
    return {k: v for k, v in found.items() if isinstance(k, str) and isinstance(v, str)}


def _sha256(path: Path) -> str | None:
    digest = hashlib.sha256()
    try:
        with open(path, "rb") as fh:
            for block in iter(lambda: fh.read(1 << 20), b""):
                digest.update(block)
    except OSError:
        return None
    return digest.hexdigest()


def _edited(folder: Path) -> list[str]:
    """Files the marker of ``folder`` lists whose content changed since chaindrive wrote them."""
    hashes = _hashes(folder)
    if not hashes:
        return []
    return sorted(f for f, h in hashes.items()
                  if (folder / f).is_file() and not (folder / f).is_symlink() and _sha256(folder / f) != h
                  and ".." not in Path(f).parts and not os.path.isabs(f))


def run_marker(folder: Path) -> str:
    """The text of the marker of a run built in ``folder``: its files and their SHA-256."""
    files = sorted(str(q.relative_to(folder)) for q in folder.rglob("*")
                   if q.is_file() and q.name != RUN_MARKER)
    return json.dumps({"files": files, "sha256": {f: _sha256(folder / f) for f in files}}, indent=1) + "\n"


def protect_inputs(real: Path, inputs: Iterable[str | os.PathLike[str]] | None, option: str, shown: str) -> None:
    """Refuse a run folder that holds one of the command's input files."""
    for given in inputs or ():
        try:
            where = Path(os.path.realpath(given))
        except (OSError, ValueError):
            continue
        if where == real or real in where.parents:
            raise InputError(
                f"{option}: the folder {shown} holds the input file {show_path(given)}; chaindrive "
                "does not replace a folder holding its own input: copy the file elsewhere, or give "
                "another folder")


def _foreign(folder: Path) -> list[str]:
    """Entries of ``folder`` that chaindrive did not write (relative paths, sorted).

    Everything is foreign in a folder without the run marker; in a run folder, what the
    marker does not list (and is not a folder holding listed files).
    """
    entries = _entries(folder)
    if RUN_MARKER not in entries:
        return entries
    listed = _listed_files(folder)
    if listed is None:  # a marker without a list: its top-level entries count as the run
        return []
    ours = set(listed) | {RUN_MARKER}
    for f in listed:
        ours.update(str(p) for p in Path(f).parents if str(p) != ".")
    found = []
    for root, dirs, files in os.walk(folder, followlinks=False):
        rel = Path(root).relative_to(folder)
        for name in dirs + files:
            r = str(rel / name) if str(rel) != "." else name
            if r not in ours:
                found.append(r)
        dirs[:] = [d for d in dirs if (str(rel / d) if str(rel) != "." else d) in ours]
    return sorted(found)


def _names(entries: list[str], limit: int = 3) -> str:
    shown = ", ".join(entries[:limit])
    return shown + (f" and {len(entries) - limit} more" if len(entries) > limit else "")


def resolve_output_dir(path: str | os.PathLike, option: str = "--output") -> Path:
    """The folder a run really goes to: symbolic links followed, ``.`` and ``..`` resolved.

    Raises
    ------
    InputError
        An empty name, a link loop, or a path without a folder name (``/``).
    """
    text = os.fspath(path)
    if not str(text).strip():
        raise InputError(f"{option}: empty folder name; give a folder path")
    try:
        real = Path(os.path.realpath(text))
        Path(real).exists()
    except OSError as exc:
        raise InputError(f"{option}: {show_path(text)}: {_reason(exc)}") from None
    if Path(text).is_symlink() and not real.exists() and real.is_symlink():
        raise InputError(f"{option}: {show_path(text)} is a symbolic link loop; give a folder")
    if not real.name:
        raise InputError(f"{option}: {show_path(text)} is the root folder; give a folder for the run")
    return real


def check_output_dir(path: str | os.PathLike, *, force: bool, option: str = "--output",
                     inputs: tuple = ()) -> Path:
    """Check, before any work, that a run folder may be (re)written; see the module policy.

    Parameters
    ----------
    path : str or os.PathLike
        The folder (a symbolic link is followed).
    force : bool
        Replace an earlier run found there.
    option : str
        Option named in messages.
    inputs : tuple of path
        The command's input files: a folder holding one is refused.

    Returns
    -------
    pathlib.Path
        The folder as given.

    Raises
    ------
    InputError
        The path is a file; it holds an earlier run and ``force`` is false; it holds
        files chaindrive did not write, files changed since it wrote them, or an input
        of the command; the parent cannot be created or written.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> d = pathlib.Path(tempfile.mkdtemp())
    >>> check_output_dir(d / "new", force=False).name
    'new'
    """
    text = os.fspath(path)
    real = resolve_output_dir(text, option)
    shown = show_path(text)
    try:
        if real.exists():
            if not real.is_dir():
                raise InputError(f"{option}: {shown} is a file; give a folder (new, empty, or an earlier "
                                 "chaindrive run with --force)")
            entries = _entries(real)
            if entries:
                protect_inputs(real, inputs, option, shown)
                if RUN_MARKER not in entries:
                    raise InputError(
                        f"{option}: the folder {shown} is not empty and was not written by chaindrive "
                        f"(no {RUN_MARKER} file); chaindrive does not replace other files: give a new "
                        "or empty folder")
                foreign = _foreign(real)
                if foreign:
                    raise InputError(
                        f"{option}: the folder {shown} holds an earlier run and files chaindrive did not "
                        f"write ({_names(foreign)}); chaindrive does not delete them: move them away or "
                        "give another folder")
                edited = _edited(real)
                if edited:
                    raise InputError(
                        f"{option}: the folder {shown} holds an earlier run with files changed since "
                        f"chaindrive wrote them ({_names(edited)}); chaindrive does not delete them: "
                        "move them away or give another folder")
                if not force:
                    raise InputError(f"{option}: the folder {shown} holds an earlier run; use --force to "
                                     "replace it, or give another folder")
            if not os.access(real, os.W_OK | os.X_OK):
                raise InputError(f"{option}: no permission to write in the folder {shown}")
        probe = real.parent
        while not probe.exists():
            probe = probe.parent
        if not probe.is_dir():
            raise InputError(f"{option}: {show_path(probe)} is a file, so the folder {shown} cannot be "
                             "created")
        if not os.access(probe, os.W_OK | os.X_OK):
            raise InputError(f"{option}: no permission to create the folder {shown} in {show_path(probe)}")
    except OSError as exc:
        raise InputError(f"{option}: {shown}: {_reason(exc)}") from None
    return Path(text)


def earlier_run_note(path: str | os.PathLike) -> str:
    """The sentence added to an error when a run fails in front of an earlier run."""
    return (f"nothing was written; the files in {show_path(path)} are from an earlier run "
            "and were left unchanged")


def _nothing_note(path: str | os.PathLike, had_run: bool) -> str:
    return earlier_run_note(path) if had_run else f"nothing was written to {show_path(path)}"


def _is_run(folder: Path) -> bool:
    try:
        return (folder / RUN_MARKER).is_file()
    except OSError:
        return False


# --------------------------------------------------------------------------- locks

#: Locks held by this process: lock file -> [descriptor or None, holders, folders created].
_HELD: dict[str, list] = {}


def _lock_path(real: Path) -> Path:
    return real.parent / f".{real.name[:200]}.lock"


def _holder(fd: int) -> tuple[str, str]:
    """(what, pid) written in a held lock file, e.g. ``("study", "1234")``."""
    try:
        words = os.pread(fd, 64, 0).decode("ascii", "replace").split()
    except OSError:
        return "run", ""
    pid = words[0] if words and words[0].isdigit() else ""
    what = words[1] if len(words) > 1 and words[1].isalpha() else "run"
    return what, pid


def _acquire(lock: Path, message: str, what: str = "run") -> int | None:
    """Take the exclusive lock on ``lock`` (created when missing) or raise ``InputError(message)``."""
    if fcntl is None:  # pragma: no cover - Windows
        return None
    while True:
        try:
            fd = os.open(lock, os.O_RDWR | os.O_CREAT | getattr(os, "O_CLOEXEC", 0), 0o644)
        except OSError:  # a read-only place: the write itself will say so
            return None
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError as exc:
            kind, pid = _holder(fd)
            os.close(fd)
            if exc.errno in (errno.EWOULDBLOCK, errno.EAGAIN, errno.EACCES):
                raise InputError(message.format(what=kind, who=f" (process {pid})" if pid else "")) from None
            return None  # locks not supported on this file system
        try:  # the holder before us may have removed the file: lock the current one
            same = os.stat(lock).st_ino == os.fstat(fd).st_ino
        except OSError:
            same = False
        if same:
            with contextlib.suppress(OSError):
                os.ftruncate(fd, 0)
                os.pwrite(fd, f"{os.getpid()} {what}\n".encode(), 0)
            return fd
        os.close(fd)


def _release(lock: Path, fd: int | None) -> None:
    if fd is None:
        return
    with contextlib.suppress(OSError):
        os.unlink(lock)  # while still held: a waiting process sees the inode change and retries
    os.close(fd)


def _make_parents(folder: Path) -> list[Path]:
    """Create the missing parents of ``folder``; return those created (deepest first)."""
    made = []
    probe = folder
    while not probe.exists():
        made.append(probe)
        probe = probe.parent
    for p in reversed(made):
        try:
            p.mkdir()
        except FileExistsError:
            pass
        except OSError:
            return [q for q in made if q.exists()]
    return made


@contextlib.contextmanager
def folder_lock(path: str | os.PathLike, *, option: str = "--output", what: str = "run") -> Iterator[Path]:
    """Hold the advisory lock of an output folder (re-entrant within a process).

    The lock file ``.NAME.lock`` lies beside the folder (in its real place when ``path``
    is a symbolic link) and is removed on release.

    Yields
    ------
    pathlib.Path
        The real folder (symbolic links resolved).

    Raises
    ------
    InputError
        Another process holds the lock: one line naming the folder.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> d = pathlib.Path(tempfile.mkdtemp()) / "run"
    >>> with folder_lock(d) as real:
    ...     sorted(p.name for p in real.parent.iterdir())
    ['.run.lock']
    >>> sorted(p.name for p in d.parent.iterdir())
    []
    """
    real = resolve_output_dir(path, option)
    lock = _lock_path(real)
    key = str(lock)
    held = _HELD.get(key)
    if held is None:
        made = _make_parents(real.parent)
        message = (f"{option}: the folder {show_path(path)} is in use by another chaindrive "
                   "{what}{who}; wait until it finishes, or give another folder")
        try:
            fd = _acquire(lock, message, what)
        except BaseException:
            _remove_empty(made)
            raise
        held = _HELD[key] = [fd, 0, made]
    held[1] += 1
    try:
        yield real
    finally:
        held[1] -= 1
        if held[1] == 0:
            del _HELD[key]
            _release(lock, held[0])
            _remove_empty(held[2])


def _remove_empty(folders: list[Path]) -> None:
    for p in folders:  # deepest first
        with contextlib.suppress(OSError):
            p.rmdir()


# --------------------------------------------------------------------------- leftovers


def _leftover_pattern(real: Path) -> re.Pattern[str]:
    return re.compile(rf"^\.{re.escape(real.name[:200])}\.[a-z0-9_]{{8}}\.(partial|old)$")


def _remove_run(folder: Path) -> list[str]:
    """Delete the files the marker of ``folder`` lists, then the emptied folders.

    Returns what is left (files chaindrive did not write, or changed since); the folder
    itself is removed when empty.
    """
    listed = _listed_files(folder)
    if listed is None:
        listed = {e for e in _entries(folder) if (folder / e).is_file()}
    hashes = _hashes(folder)
    for f in sorted(listed, key=lambda s: -len(Path(s).parts)):
        with contextlib.suppress(OSError):
            if (folder / f).is_dir():
                continue
            if hashes is not None and (folder / f).is_file() and _sha256(folder / f) != hashes.get(f):
                continue  # edited since chaindrive wrote it: kept (then foreign: no marker)
            (folder / f).unlink()
    with contextlib.suppress(OSError):
        (folder / RUN_MARKER).unlink()
    for root, _dirs, _files in sorted(os.walk(folder, topdown=False), key=lambda t: -len(t[0])):
        if Path(root) != folder:
            with contextlib.suppress(OSError):
                os.rmdir(root)
    left = _foreign(folder) if folder.exists() else []
    if not left:
        with contextlib.suppress(OSError):
            os.rmdir(folder)
    return left


def _keep_aside(folder: Path, real: Path, word: str) -> Path:
    """Rename ``folder`` to a free visible sibling ``REAL.WORD`` (``REAL.WORD-2``, ...)."""
    for n in range(1, 1000):
        target = real.parent / (f"{real.name}.{word}" if n == 1 else f"{real.name}.{word}-{n}")
        if target.exists() or target.is_symlink():
            continue
        try:
            os.rename(folder, target)
            return target
        except OSError as exc:
            if exc.errno in (errno.ENOTEMPTY, errno.EEXIST):
                continue
            raise
    raise InputError(f"no free name beside {show_path(real)} to keep {show_path(folder)}")


def clean_leftovers(real: Path) -> None:
    """Remove what killed runs into ``real`` left beside it (call with the lock held).

    An earlier run moved aside (``.old``) while ``real`` is missing is put back first.
    """
    pattern = _leftover_pattern(real)
    try:
        names = sorted(n for n in os.listdir(real.parent) if pattern.match(n))
    except OSError:
        return
    olds = [n for n in names if n.endswith(".old")]
    if olds and not (real.exists() or real.is_symlink()):
        with contextlib.suppress(OSError):
            os.rename(real.parent / olds[0], real)
            names.remove(olds[0])
    for n in names:
        p = real.parent / n
        if n.endswith(".partial") and not _is_run(p):  # a half-built run
            shutil.rmtree(p, ignore_errors=True)
        elif _remove_run(p):  # an earlier run moved aside, or swapped out by an exchange  # files of the user in an old run: kept, visible
            with contextlib.suppress(OSError, InputError):
                kept = _keep_aside(p, real, "kept")
                warnings.warn(f"files chaindrive did not write were found in an earlier run of "
                              f"{show_path(real)} left by a stopped run; they are kept in "
                              f"{show_path(kept)}", ChainDriveWarning, stacklevel=3)


@contextlib.contextmanager
def claim_output_dir(path: str | os.PathLike, *, force: bool, option: str = "--output",
                     inputs: tuple = ()) -> Iterator[Path]:
    """Lock the run folder, clean leftovers of killed runs, check the policy; for a whole command.

    Hold it around everything a command does, so that a second run into the same folder
    is refused at once. An interrupt (Ctrl-C) inside gets a note saying what is kept.
    ``inputs``: the command's input files (a folder holding one is refused).

    Yields
    ------
    pathlib.Path
        The folder as given.
    """
    with folder_lock(path, option=option) as real:
        clean_leftovers(real)
        check_output_dir(path, force=force, option=option, inputs=inputs)
        had_run = _is_run(real)
        try:
            yield Path(os.fspath(path))
        except BaseException as exc:  # Ctrl-C (KeyboardInterrupt or the command line's own)
            if not isinstance(exc, (Exception, SystemExit, GeneratorExit)):
                notes = getattr(exc, "__notes__", [])
                if not any("nothing was written" in n for n in notes):
                    exc.add_note(_nothing_note(path, had_run))
            raise


def _map_filename(exc: OSError, tmp: Path, text: str) -> str:
    name = getattr(exc, "filename", None)
    if not name:
        return f"the results into {show_path(text)}"
    with contextlib.suppress(ValueError, TypeError):
        return show_path(Path(text) / Path(os.fspath(name)).relative_to(tmp))
    return show_path(os.fspath(name))


@contextlib.contextmanager
def atomic_output_dir(path: str | os.PathLike, *, force: bool = False,
                      option: str = "--output", inputs: tuple = ()) -> Iterator[Path]:
    """Build a run folder in a hidden sibling folder and move it into place when complete.

    Parameters
    ----------
    path : str or os.PathLike
        The final folder (created with its parents when missing; a symbolic link is
        followed).
    force : bool
        Replace an earlier chaindrive run in ``path``.
    option : str
        Option named in messages.
    inputs : tuple of path
        The command's input files: a folder holding one is never replaced.

    Yields
    ------
    pathlib.Path
        The temporary folder to write into.

    Raises
    ------
    InputError
        See :func:`check_output_dir` and :func:`folder_lock`; raised before the body
        runs. At the move: files appeared in the folder during the run (the new results
        are kept in a sibling folder named in the message). A file error in the body
        (disk full) is turned into one line naming the file and saying what is kept.
        Other errors propagate unchanged in type; when an earlier run is present their
        message says that those files are from the earlier run.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> d = pathlib.Path(tempfile.mkdtemp()) / "run"
    >>> with atomic_output_dir(d) as tmp:
    ...     _ = (tmp / "a.json").write_text("{}")
    >>> sorted(p.name for p in d.parent.iterdir()), sorted(p.name for p in d.iterdir())
    (['run'], ['.chaindrive-run', 'a.json'])
    """
    text = os.fspath(path)
    with claim_output_dir(path, force=force, option=option, inputs=inputs):
        real = resolve_output_dir(text, option)
        had_run = _is_run(real)
        try:
            real.parent.mkdir(parents=True, exist_ok=True)
            tmp = Path(tempfile.mkdtemp(prefix=f".{real.name[:200]}.", suffix=".partial", dir=real.parent))
            mask = os.umask(0)
            os.umask(mask)
            os.chmod(tmp, 0o777 & ~mask)  # mkdtemp makes 0o700; a run folder is an ordinary folder
        except OSError as exc:
            raise InputError(f"{option}: cannot create the folder {show_path(text)}: {_reason(exc)}") from None
        moved = False
        try:
            try:
                yield tmp
                (tmp / RUN_MARKER).write_text(run_marker(tmp), encoding="utf-8")
            except ChainDriveError as exc:
                if had_run and "earlier run" not in str(exc):
                    raise type(exc)(f"{exc}; {earlier_run_note(text)}") from None
                raise
            except OSError as exc:  # disk full, quota, a file system gone read-only
                raise InputError(f"{option}: cannot write {_map_filename(exc, tmp, text)}: {_reason(exc)}; "
                                 f"{_nothing_note(text, had_run)}") from None
            except BaseException as exc:
                notes = getattr(exc, "__notes__", [])
                if not isinstance(exc, (SystemExit, GeneratorExit)) and not any(
                        "nothing was written" in n for n in notes):
                    exc.add_note(_nothing_note(text, had_run))
                raise
            moved = _move_into_place(tmp, real, text, force=force, option=option, inputs=inputs)
            _COMPLETED.append(text)
        finally:
            if not moved:
                shutil.rmtree(tmp, ignore_errors=True)


def _as_given(sibling: Path, text: str) -> Path:
    """``sibling`` (beside the real folder) written relative to the path the user gave, when
    that is not a link."""
    given = Path(text)
    try:
        if not given.is_symlink() and given.absolute().parent.resolve() == sibling.parent:
            return given.parent / sibling.name
    except OSError:
        pass
    return sibling


def _renameat2():
    """libc's ``renameat2`` (Linux, glibc >= 2.28), or None."""
    global _RENAMEAT2
    if _RENAMEAT2 is None:
        _RENAMEAT2 = False
        try:
            import ctypes

            function = ctypes.CDLL(None, use_errno=True).renameat2
            function.argtypes = [ctypes.c_int, ctypes.c_char_p, ctypes.c_int, ctypes.c_char_p, ctypes.c_uint]
            function.restype = ctypes.c_int
            _RENAMEAT2 = function
        except (OSError, AttributeError, ImportError):
            pass
    return _RENAMEAT2 or None


_RENAMEAT2: Any = None


def exchange(a: Path, b: Path) -> bool:
    """Swap two folders in one atomic step (``renameat2(RENAME_EXCHANGE)``); False where the
    system or the file system does not offer it (nothing is changed then)."""
    function = _renameat2()
    if function is None:
        return False
    import ctypes

    at_fdcwd, rename_exchange = -100, 2
    if function(at_fdcwd, os.fsencode(a), at_fdcwd, os.fsencode(b), rename_exchange) == 0:
        return True
    err = ctypes.get_errno()
    if err in (errno.ENOSYS, errno.EINVAL, errno.EOPNOTSUPP, errno.ENOTSUP, errno.EPERM):
        return False
    raise OSError(err, os.strerror(err), os.fspath(b))


def recover_output_dir(path: str | os.PathLike) -> None:
    """Put back an earlier run moved aside by a run killed in the middle of its final swap
    (only where the atomic exchange is not available); nothing to do otherwise."""
    try:
        real = Path(os.path.realpath(path))
        if real.exists() or real.is_symlink() or not real.parent.is_dir():
            return
        pattern = _leftover_pattern(real)
        olds = sorted(n for n in os.listdir(real.parent) if pattern.match(n) and n.endswith(".old"))
        if olds:
            os.rename(real.parent / olds[0], real)
    except OSError:
        pass


def _drop_earlier(old: Path, real: Path, text: str) -> None:
    """Delete the earlier run swapped out to ``old``; files of the user are kept aside."""
    left = _remove_run(old)
    if left:
        kept = _keep_aside(old, real, "kept")
        warnings.warn(f"files chaindrive did not write were in the earlier run of {show_path(text)} "
                      f"({_names(left)}); they are kept in {show_path(_as_given(kept, text))}",
                      ChainDriveWarning, stacklevel=5)


def _move_into_place(tmp: Path, real: Path, text: str, *, force: bool, option: str,
                     inputs: tuple = ()) -> bool:
    """Check the rules again and move ``tmp`` to ``real``; returns True (or raises).

    With an earlier run in ``real``, the two folders are exchanged atomically where the
    system can (:func:`exchange`): ``real`` is a complete run at every instant; ``tmp``
    then holds the earlier run, whose files are deleted (the user's are kept aside).
    """
    shown = show_path(text)

    def keep(reason: str) -> None:
        kept = _keep_aside(tmp, real, "new")
        raise InputError(f"{option}: {reason}; nothing there was changed; the new results are in "
                         f"{show_path(_as_given(kept, text))}")

    try:
        if real.is_symlink() or (real.exists() and not real.is_dir()):
            keep(f"{shown} was replaced by a file or link during the run")
        if real.exists():
            foreign = _foreign(real)
            if foreign:
                keep(f"files chaindrive did not write appeared in {shown} during the run ({_names(foreign)})")
            edited = _edited(real)
            if edited:
                keep(f"files of the earlier run in {shown} were changed during the run ({_names(edited)})")
            try:
                protect_inputs(real, inputs, option, shown)
            except InputError:
                keep(f"{shown} holds an input file of the command")
            if _is_run(real) and not force:
                keep(f"an earlier run appeared in {shown} during the run (use --force to replace one)")
        old = None
        if real.exists() and _entries(real):
            if exchange(tmp, real):  # atomic: DIR is the new run, tmp the earlier one
                _drop_earlier(tmp, real, text)
                return True
            old = Path(tempfile.mkdtemp(prefix=f".{real.name[:200]}.", suffix=".old", dir=real.parent))
            os.rmdir(old)
            os.rename(real, old)
            late = _foreign(old)
            if late:  # a file arrived between the check and the move: put everything back
                os.rename(old, real)
                keep(f"files chaindrive did not write appeared in {shown} during the run ({_names(late)})")
        try:
            os.rename(tmp, real)
        except OSError as exc:
            if old is not None:
                with contextlib.suppress(OSError):
                    os.rename(old, real)
                    old = None
            if exc.errno in (errno.ENOTEMPTY, errno.EEXIST):
                keep(f"files appeared in {shown} during the run")
            raise
        if old is not None:
            _drop_earlier(old, real, text)
    except OSError as exc:
        raise InputError(f"{option}: cannot move the results into {shown}: {_reason(exc)}") from None
    return True
