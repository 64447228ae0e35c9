"""A study folder belongs to one plan (internal to :mod:`chaindrive.study.run`).

``chaindrive study STUDY.toml -o DIR`` writes ``DIR/study.json`` (the plan, with its
*fingerprint*) and ``DIR/results/part-*.parquet`` (each part carries the fingerprint in
its metadata). The policy:

* a rerun of the same plan (same fingerprint) resumes: the variants already in the folder
  are skipped;
* a run of another plan (the study file's variables, plan, samples, seed, outputs or
  simulation changed, or the base project's content) is refused with the remedy: a new
  folder, or ``--force`` to start over; ``--force`` removes only what a study wrote
  (``study.json``, the part files, the summary's page and figures);
* the summary and :func:`~chaindrive.study.run.read_results` read only the parts of the
  folder's plan;
* a part file that cannot be read (truncated, empty, corrupt: a killed disk write) is
  moved aside as ``part-*.parquet.damaged`` and its variants are computed again, named in
  one warning line; temporary files of killed runs (``results/.part-*.tmp``) are removed.

The fingerprint is the SHA-256 of the canonical JSON of what decides the rows: the base
project as parsed (``[set]`` and ``remove`` applied: comments and layout of either file do
not count), the variables, the plan, samples, seed, outputs and simulation options.
"""

from __future__ import annotations

import contextlib
import json
import os
import warnings
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .._folders import show_path
from .._io import atomic_write_text
from ..errors import ChainDriveWarning, InputError
from .spec import canonical_hash

if TYPE_CHECKING:
    from .spec import Study

__all__ = ["STUDY_FILE", "fingerprint", "prepare_folder", "plan_parts", "read_part", "folder_fingerprint",
           "part_fingerprint"]

#: The plan file of a study folder.
STUDY_FILE = "study.json"

#: Key of the study's JSON in a part file's Parquet metadata.
META_KEY = b"chaindrive.study"


def fingerprint(study: Study) -> str:
    """SHA-256 of what decides a study's rows (see the module notes).

    Examples
    --------
    >>> import pathlib
    >>> from chaindrive.study.spec import load_study
    >>> s = load_study(pathlib.Path(__file__).parents[3] / "examples" / "skew_study.toml")
    >>> len(fingerprint(s))
    64
    """
    described = study.describe()
    return canonical_hash({"base": study.base_hash, "variables": described["variables"],
                           "plan": study.plan, "samples": study.samples, "seed": study.seed,
                           "outputs": list(study.outputs), "simulation": study.simulation})


def _parquet():
    try:
        import pyarrow as pa
        import pyarrow.parquet as pq
    except ImportError:  # pragma: no cover - depends on install
        raise InputError("design studies need pyarrow: pip install 'chaindrive[study]'") from None
    return pa, pq


def _parts(directory: Path) -> list[Path]:
    return sorted((Path(directory) / "results").glob("part-*.parquet"))


def folder_fingerprint(directory: Path) -> str | None:
    """The fingerprint stored in ``DIR/study.json`` (None: none, or no readable file)."""
    try:
        data = json.loads((Path(directory) / STUDY_FILE).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    value = data.get("fingerprint") if isinstance(data, dict) else None
    return value if isinstance(value, str) else None


def read_part(path: Path, columns: list[str] | None = None) -> Any:
    """A part file as a :class:`pyarrow.Table`, or None when it cannot be read (damaged)."""
    pa, pq = _parquet()
    try:
        return pq.read_table(path, columns=columns)
    except (pa.ArrowException, OSError, ValueError, KeyError):
        return None


def part_fingerprint(path: Path) -> str | None:
    """The fingerprint in a part file's metadata (None: none, or the file is damaged)."""
    pa, pq = _parquet()
    try:
        meta = pq.read_schema(path).metadata or {}
        value = json.loads(meta.get(META_KEY, b"{}").decode("utf-8")).get("fingerprint")
    except (pa.ArrowException, OSError, ValueError, AttributeError):
        return None
    return value if isinstance(value, str) else None


def plan_parts(directory: Path, *, on_damaged: str = "skip") -> list[Path]:
    """The readable part files of the folder's plan, in time order.

    A part written for another plan (a folder of an earlier chaindrive that mixed plans)
    is left out. A damaged part is moved aside (``on_damaged="recompute"``: its variants
    are computed again by the run) or skipped (``"skip"``: the summary), with one warning
    line naming it.
    """
    directory = Path(directory)
    wanted = folder_fingerprint(directory)
    kept = []
    for f in _parts(directory):
        _, pq = _parquet()
        try:
            pq.read_metadata(f)
            found = part_fingerprint(f)
        except Exception:  # noqa: BLE001 - any reader error: the file is damaged
            found, damaged = None, True
        else:
            damaged = False
        if damaged or (found is None and read_part(f, ["key"]) is None):
            _damaged(f, recompute=on_damaged == "recompute")
            continue
        if wanted is not None and found is not None and found != wanted:
            continue
        kept.append(f)
    return kept


def _damaged(path: Path, *, recompute: bool) -> None:
    shown = show_path(Path(path.parent.name) / path.name)
    if recompute:
        with contextlib.suppress(OSError):
            os.replace(path, path.with_name(path.name + ".damaged"))
        warnings.warn(f"the part file {shown} is damaged (truncated, empty or corrupt: a stopped "
                      "write); it was moved aside (.damaged) and its variants are computed again",
                      ChainDriveWarning, stacklevel=3)
    else:
        warnings.warn(f"the part file {shown} is damaged (truncated, empty or corrupt: a stopped "
                      "write) and was left out; run the study again to compute its variants",
                      ChainDriveWarning, stacklevel=3)


def clean_temporary(directory: Path) -> None:
    """Remove the temporary files of killed runs (call with the folder's lock held)."""
    for folder in (Path(directory), Path(directory) / "results"):
        with contextlib.suppress(OSError):
            for name in os.listdir(folder):
                if name.startswith((".part-", f".{STUDY_FILE}.")) and name.endswith(".tmp"):
                    with contextlib.suppress(OSError):
                        os.unlink(folder / name)


def _remove_study(directory: Path) -> None:
    """``--force``: delete what a study wrote in ``directory`` (nothing else)."""
    results = directory / "results"
    doomed = [directory / STUDY_FILE]
    with contextlib.suppress(OSError):
        doomed += [results / n for n in os.listdir(results)
                   if n.startswith("part-") and n.endswith((".parquet", ".parquet.damaged"))]
    summary = directory / "summary"
    with contextlib.suppress(OSError):
        doomed += [summary / n for n in os.listdir(summary) if n == "index.html" or n.endswith(".png")]
    for f in doomed:
        with contextlib.suppress(FileNotFoundError):
            os.unlink(f)
    for folder in (results, summary):
        with contextlib.suppress(OSError):
            folder.rmdir()


def prepare_folder(directory: Path, study: Study, *, force: bool = False) -> str:
    """Create the folder or check it belongs to ``study``'s plan; write ``study.json``.

    Returns the fingerprint. Call with the folder's lock held.

    Raises
    ------
    InputError
        ``directory`` is a file, or holds the results of another plan (without ``force``).
    """
    from .._results import jsonable

    directory = Path(directory)
    shown = show_path(directory)
    if directory.exists() and not directory.is_dir():
        raise InputError(f"--output: {shown} is a file; give a folder")
    try:
        directory.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise InputError(f"--output: cannot create the folder {shown}: {exc.strerror or exc}") from None
    clean_temporary(directory)
    mine = fingerprint(study)
    stored = folder_fingerprint(directory)
    if (stored is not None and stored != mine) or (stored is None and _parts(directory)):
        if not force:
            why = ("its study file or base project differs from this one" if stored is not None else
                   "it was written without a plan fingerprint (an earlier chaindrive) or not by a study")
            raise InputError(f"--output: the study folder {shown} holds the results of another plan "
                             f"({why}); give a new folder, or use --force to start over (it deletes "
                             "the results there)")
        _remove_study(directory)
        directory.mkdir(parents=True, exist_ok=True)
    described = jsonable(study.describe())
    described["fingerprint"] = mine
    atomic_write_text(directory / STUDY_FILE, json.dumps(described, indent=2), force=True, option="--output")
    return mine
