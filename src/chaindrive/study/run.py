"""Running a design study on ``dask.distributed``.

Variants go to the workers in batches (one task per batch, :func:`run_batch_columns`); each
finished batch is appended to the output folder as a new Parquet part file
(``results/part-*.parquet``, written to a temporary name and renamed, so a part is
either whole or absent). A row is keyed by the SHA-256 of the canonical JSON of the
variant's inputs (with the base project, the outputs and the simulation options), so
a rerun skips the variants already in the folder. A variant that fails records its
error message in its row (outputs null) and the study goes on.

The same code runs on a :class:`distributed.LocalCluster` (default: one worker process
per core, one thread each) or on an existing cluster (``scheduler="tcp://host:port"``).
"""

from __future__ import annotations

import json
import logging
import math
import os
import socket
import time
import uuid
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .._io import atomic_write_bytes, folder_lock
from ..errors import InfeasibleError, InputError
from ._columns import array as _array
from ._columns import column_type as _column_type
from .folder import META_KEY as _META_KEY
from .folder import fingerprint, plan_parts, prepare_folder, read_part
from .progress import LONG_STUDY, QuietProgress, progress_bar
from .spec import MAXIMUM_BATCH_SIZE, Study
from .variant import analysis_result, evaluate_variant, lookup
from .variant import one_line as _one_line

if TYPE_CHECKING:
    import pandas as pd
    import pyarrow as pa


__all__ = ["analysis_result", "lookup", "evaluate_variant", "run_batch", "run_batch_columns", "run_study", "read_dataframe",
           "read_results", "existing_keys", "StudyRun", "DEFAULT_BATCH_SIZE"]

#: Largest default batch: a batch is the unit of progress and of what a lost worker loses, and
#: its variants are evaluated together (chaindrive.study.batch: the fixed cost of a batch is a
#: few project reads and one analysis of the base drive, about 20 ms).
DEFAULT_BATCH_SIZE = 5000

#: Error prefix of the rows of a batch lost on the cluster (computed again on a rerun).
CLUSTER_FAILURE = "batch failed on the cluster"


# --------------------------------------------------------------------------- one variant


def design_outputs(duty: Any, **options: Any) -> dict[str, Any]:
    """The design procedure's recommended drive for a duty, as a study row (SI units).

    A study over duties (power, speed, driven machine, ...) evaluates each through
    :func:`chaindrive.design.design_drive`, the function ``chaindrive select`` and the
    studio call, so a study gives the same chain, teeth, links and centre distance.

    Examples
    --------
    >>> import math
    >>> from chaindrive.design import Duty
    >>> row = design_outputs(Duty(11e3, 1460 * math.pi / 30, driven_speed=480 * math.pi / 30,
    ...                           driven_machine="varying_conveyor", centre_distance=0.6))
    >>> row["chain"], row["links"]
    ('12A-1', 104)
    """
    from ..design import design_drive

    return design_drive(duty, **options).recommended.summary()


def warm_up() -> str:
    """Import the analysis on a worker (run once per worker before the clock starts)."""
    from ..analysis import analyze_drive  # noqa: F401
    from ..drive.project import project_from_mapping  # noqa: F401

    return f"{socket.gethostname()}:{os.getpid()}"


def run_batch(batch: Sequence[tuple[int, str, dict]], *, base: dict, outputs: Sequence[str],
              parts: Sequence[str] = (), simulation: dict | None = None) -> list[dict]:
    """Evaluate a batch of ``(variant number, key, inputs)`` on a worker; one row each.

    Examples
    --------
    >>> import tomllib
    >>> from chaindrive.drive.project import template
    >>> rows = run_batch([(0, "k0", {"drive.speed": "1450 rpm"}), (1, "k1", {"drive.speed": "0 rpm"})],
    ...                  base=tomllib.loads(template("roller")), outputs=["loads.chain_speed"])
    >>> [(r["variant"], r["key"], r["error"] is None) for r in rows]
    [(0, 'k0', True), (1, 'k1', False)]
    """
    worker = f"{socket.gethostname()}:{os.getpid()}"
    if simulation is None:  # the analysis parts of many variants together (chaindrive.study.batch)
        from .batch import evaluate_batch

        rows = evaluate_batch(base, [inputs for _, _, inputs in batch], outputs, parts=parts)
        for (number, key, _), row in zip(batch, rows, strict=True):
            row.update(key=key, variant=number, worker=worker)
        return rows
    rows = []
    for number, key, inputs in batch:
        row = evaluate_variant(base, inputs, outputs, parts=parts, simulation=simulation)
        row.update(key=key, variant=number, worker=worker)
        rows.append(row)
    return rows


def run_batch_columns(batch: Sequence[tuple[int, str, dict]], *, base: dict, outputs: Sequence[str],
                      parts: Sequence[str] = (), simulation: dict | None = None) -> dict[str, list]:
    """:func:`run_batch` as columns (``{"key": [...], "variant": [...], output: [...], ...}``):
    what the study runner's tasks return and its Parquet part files store.

    Examples
    --------
    >>> import tomllib
    >>> from chaindrive.drive.project import template
    >>> cols = run_batch_columns([(0, "k0", {"drive.speed": "1450 rpm"}), (1, "k1", {"drive.speed": "0 rpm"})],
    ...                          base=tomllib.loads(template("roller")), outputs=["loads.chain_speed"])
    >>> cols["key"], [e is None for e in cols["error"]]
    (['k0', 'k1'], [True, False])
    """
    worker = f"{socket.gethostname()}:{os.getpid()}"
    if simulation is None:
        from .batch import evaluate_columns

        columns = evaluate_columns(base, [inputs for _, _, inputs in batch], outputs, parts=parts)
    else:
        rows = run_batch(batch, base=base, outputs=outputs, parts=parts, simulation=simulation)
        columns = {name: [r.get(name) for r in rows] for name in rows[0]} if rows else {}
    columns["key"] = [key for _, key, _ in batch]
    columns["variant"] = [number for number, _, _ in batch]
    columns["worker"] = [worker] * len(batch)
    return columns


# --------------------------------------------------------------------------- Parquet


def _parquet():
    try:
        import pyarrow as pa
        import pyarrow.parquet as pq
    except ImportError:  # pragma: no cover - depends on install
        raise InputError("design studies need pyarrow: pip install 'chaindrive[study]'") from None
    return pa, pq


def existing_keys(directory: str | Path) -> set[str]:
    """Keys of the variants done in a study folder.

    A row of a batch lost on the cluster (error ``"batch failed on the cluster: ..."``)
    does not count: a rerun computes that variant again.
    """
    _parquet()
    keys: set[str] = set()
    for f in plan_parts(Path(directory)):
        table = read_part(f, ["key", "error"])
        if table is None:
            continue
        part = table.to_pydict()
        keys.update(k for k, e in zip(part["key"], part["error"], strict=True)
                    if not (e or "").startswith(CLUSTER_FAILURE))
    return keys


def read_results(directory: str | Path) -> pa.Table:
    """All rows of a study folder as one :class:`pyarrow.Table` (each key once).

    Only the parts of the folder's plan are read (:mod:`chaindrive.study.folder`); a damaged
    part is left out with a warning. Part files written by different runs are unified (a
    column missing from a part is null there). A key written more than once (a variant of a
    lost batch computed again) keeps its newest row. Rows are sorted by variant number.

    Raises
    ------
    InputError
        No results in the folder.
    """
    pa, _ = _parquet()
    tables = [t for t in (read_part(f) for f in plan_parts(Path(directory))) if t is not None]
    if not tables:
        raise InputError(f"study folder {str(directory)!r} holds no results (results/part-*.parquet)")
    schema = pa.unify_schemas([t.schema for t in tables], promote_options="permissive")
    columns: dict[str, list] = {f.name: [] for f in schema}
    for t in tables:
        for f in schema:
            if f.name in t.column_names:
                columns[f.name].append(t.column(f.name).cast(f.type))
            else:
                columns[f.name].append(pa.nulls(t.num_rows, type=f.type))
    table = pa.table({name: pa.chunked_array(parts, type=schema.field(name).type)
                      for name, parts in columns.items()}, schema=schema)
    keys = table.column("key").to_pylist()
    last = {k: i for i, k in enumerate(keys)}  # parts are named in time order: newest last
    if len(last) < len(keys):
        table = table.take(sorted(last.values()))
    import pyarrow.compute as pc

    return table.take(pc.sort_indices(table, sort_keys=[("variant", "ascending")]))


class _PartWriter:
    """Writes each finished batch as one Parquet part file (atomic rename)."""

    def __init__(self, directory: Path, study: Study):
        self.pa, self.pq = _parquet()
        pa = self.pa
        self.folder = Path(directory) / "results"
        self.folder.mkdir(parents=True, exist_ok=True)
        now = time.time()  # part names sort in time order (to the microsecond)
        self.run = (f"{time.strftime('%Y%m%dT%H%M%S', time.gmtime(now))}.{int(now % 1 * 1e6):06d}"
                    f"-{uuid.uuid4().hex[:8]}")
        self.count = 0
        self.study = study
        self.input_types = {}
        for v in study.variables:
            if v.values is not None and any(isinstance(x, str) for x in v.values):
                self.input_types[v.path] = pa.string()
            elif v.integer or (v.values is not None and all(isinstance(x, int) for x in v.values)):
                self.input_types[v.path] = pa.int64()
            else:
                self.input_types[v.path] = pa.float64()
        self.output_types: dict[str, Any] = {}
        for f in plan_parts(Path(directory)):
            schema = self.pq.read_schema(f)
            for name in study.outputs:
                if name in schema.names and not pa.types.is_null(schema.field(name).type):
                    self.output_types.setdefault(name, schema.field(name).type)
        meta = {"name": study.name, "units": {v.path: v.unit for v in study.variables},
                "inputs": [v.path for v in study.variables], "outputs": list(study.outputs),
                "fingerprint": fingerprint(study)}
        self.metadata = {_META_KEY: json.dumps(meta).encode("utf-8")}

    def write(self, columns: dict[str, list], values: dict[str, tuple]) -> Path:
        """One part file of a finished batch (``columns`` as :func:`run_batch_columns` gives
        them; a column missing is null)."""
        pa, pq = self.pa, self.pq
        keys = list(columns["key"])
        n = len(keys)
        fields = [pa.field("key", pa.string()), pa.field("variant", pa.int64())]
        data: dict[str, Any] = {"key": keys, "variant": [int(v) for v in columns["variant"]]}
        for j, v in enumerate(self.study.variables):
            t = self.input_types[v.path]
            fields.append(pa.field(v.path, t, metadata={b"unit": v.unit.encode()}))
            data[v.path] = _array([values[k][j] for k in keys], t, pa)
        for name in self.study.outputs:
            col = columns.get(name) or [None] * n
            t = _column_type(col, self.output_types.get(name), pa)
            if not pa.types.is_null(t):
                self.output_types[name] = t
            fields.append(pa.field(name, t))
            data[name] = _array(col, t, pa)
        for name, t in (("error", pa.string()), ("warnings", pa.string()), ("seconds", pa.float64()),
                        ("cpu_seconds", pa.float64()), ("worker", pa.string())):
            fields.append(pa.field(name, t))
            data[name] = _array(columns.get(name) or [None] * n, t, pa)
        schema = pa.schema(fields, metadata=self.metadata)
        table = pa.table(data, schema=schema)
        self.count += 1
        final = self.folder / f"part-{self.run}-{self.count:05d}.parquet"
        buffer = pa.BufferOutputStream()
        pq.write_table(table, buffer)
        return atomic_write_bytes(final, buffer.getvalue().to_pybytes(), option="--output")


# --------------------------------------------------------------------------- the runner


def read_dataframe(directory: str | Path) -> pd.DataFrame:
    """All rows of a study folder as a :class:`pandas.DataFrame` with the unit of each column.

    ``df.attrs["units"]`` maps each column to its unit: the inputs in the units of the
    study file (as stored with the column), the analysis outputs in SI units
    (:func:`chaindrive.study.outputs.output_unit`), the timings in seconds; ``""`` for a
    count, a ratio, a flag or text. ``df.attrs["study"]`` holds the study's name, inputs
    and outputs.

    Raises
    ------
    InputError
        No results in the folder.
    """
    import pandas

    from .outputs import output_unit

    table = read_results(directory)
    frame = table.to_pandas()
    units: dict[str, str] = {}
    meta = json.loads((table.schema.metadata or {}).get(_META_KEY, b"{}").decode("utf-8"))
    for f in table.schema:
        stored = (f.metadata or {}).get(b"unit")
        if stored is not None:
            units[f.name] = stored.decode("utf-8")
        elif f.name in ("seconds", "cpu_seconds"):
            units[f.name] = "s"
        elif f.name in meta.get("outputs", ()):
            units[f.name] = output_unit(f.name)
        else:
            units[f.name] = ""
    frame.attrs["units"] = units
    frame.attrs["study"] = {k: meta[k] for k in ("name", "inputs", "outputs") if k in meta}
    assert isinstance(frame, pandas.DataFrame)
    return frame


@dataclass
class StudyRun:
    """What a run did.

    Attributes
    ----------
    directory : pathlib.Path
    variants : int
        Variants of the plan.
    skipped : int
        Already in the folder (not computed again).
    computed : int
        Computed by this run.
    failed : int
        Of those, rows with an error.
    seconds : float
        Wall time of the run (cluster start included) [s].
    compute_seconds : float
        From the first submitted batch to the last result [s].
    workers : int
    files : list of pathlib.Path
        Part files written.
    """

    directory: Path
    variants: int
    skipped: int
    computed: int
    failed: int
    seconds: float
    compute_seconds: float
    workers: int
    files: list = field(default_factory=list)

    @property
    def rate(self) -> float:
        """Variants per second of compute time [1/s]."""
        return self.computed / self.compute_seconds if self.compute_seconds > 0 else 0.0


def _check_address(scheduler: str) -> None:
    if not scheduler.startswith(("tcp://", "tls://", "inproc://", "ucx://", "ws://", "wss://")):
        raise InputError(f"--scheduler: give the address as tcp://HOST:PORT, got {scheduler!r}")


def _client(scheduler: str | None, workers: int | None, timeout: float = 10.0):
    try:
        from distributed import Client, LocalCluster
    except ImportError:  # pragma: no cover - depends on install
        raise InputError("design studies need dask.distributed: pip install 'chaindrive[study]'") from None
    if scheduler:
        _check_address(scheduler)
        try:
            client = Client(scheduler, timeout=f"{timeout:g}s")
        except (OSError, TimeoutError) as exc:
            raise InputError(f"--scheduler: cannot reach the scheduler at {scheduler!r} ({exc})") from None
        return client, None
    n = workers if workers is not None else (os.cpu_count() or 1)
    if not 1 <= n <= 256:
        raise InputError(f"workers must lie in [1, 256], got {n}")
    # the scheduler's HTTP server on a free local port: no clash (and no warning) when
    # another cluster holds the default 8787. Its processes log only CRITICAL: on a loaded
    # machine a worker's heartbeat can race the scheduler's close and log an ERROR with a
    # traceback after every result is in; a task's own failure reaches the client through
    # its future (reported per variant) and a lost worker fails its batch (recorded), so nothing is hidden
    try:
        cluster = LocalCluster(n_workers=n, threads_per_worker=1, processes=True,
                               dashboard_address="127.0.0.1:0", silence_logs=logging.CRITICAL)
    except (OSError, TimeoutError) as exc:
        raise InfeasibleError(f"the local dask cluster of {n} workers did not start: "
                              f"{_one_line(exc)}") from None
    return Client(cluster), cluster


def run_study(study: Study, directory: str | Path, *, scheduler: str | None = None,
              workers: int | None = None, batch_size: int | None = None,
              progress: bool = True, wait_for_workers: float = 60.0, force: bool = False) -> StudyRun:
    """Run every variant of ``study`` not yet in ``directory`` on a dask cluster.

    Parameters
    ----------
    study : Study
    directory : path
        Output folder: ``study.json`` and ``results/part-*.parquet``.
    scheduler : str, optional
        Address of a running ``dask scheduler`` (``tcp://HOST:PORT``); default a
        :class:`~distributed.LocalCluster` started for this run.
    workers : int, optional
        Worker processes of the local cluster (default one per core).
    batch_size : int, optional
        Variants per task (default: the study's, else about eight tasks per worker, at
        most :data:`DEFAULT_BATCH_SIZE`; at most :data:`~chaindrive.study.spec.MAXIMUM_BATCH_SIZE`).
    progress : bool
        Progress bar with ETA on stderr.
    wait_for_workers : float
        How long to wait for the first worker of an existing cluster [s] (and, within
        3...10 s, for the scheduler to answer).
    force : bool
        Start over in a folder holding the results of another plan (they are deleted);
        without it such a folder is refused (:mod:`chaindrive.study.folder`).

    Returns
    -------
    StudyRun

    Raises
    ------
    InputError
        Bad batch size, worker count or scheduler address; the folder holds another plan.
    InfeasibleError
        No worker joined the scheduler in time.

    Examples
    --------
    A cluster takes seconds to start, so this is not run as a doctest (the tests run it):

    >>> from chaindrive.study import load_study
    >>> run = run_study(load_study("examples/skew_study.toml"), "skew", workers=2)  # doctest: +SKIP
    >>> run.computed, run.failed, run.workers  # doctest: +SKIP
    (400, 0, 2)
    """
    t_start = time.perf_counter()
    directory = Path(directory)
    # one study at a time per folder: a second one into it is refused at once (it would
    # compute every variant again); the lock is the run folders' (.NAME.lock beside it)
    with folder_lock(directory, option="--output", what="study"):
        return _run_study(study, directory, t_start, scheduler=scheduler, workers=workers,
                          batch_size=batch_size, progress=progress, wait_for_workers=wait_for_workers,
                          force=force)


def _run_study(study: Study, directory: Path, t_start: float, *, scheduler: str | None,
               workers: int | None, batch_size: int | None, progress: bool,
               wait_for_workers: float, force: bool = False) -> StudyRun:
    batch_size = batch_size if batch_size is not None else study.batch_size
    if batch_size is not None and not 1 <= batch_size <= MAXIMUM_BATCH_SIZE:
        raise InputError(f"batch_size must lie in [1, {MAXIMUM_BATCH_SIZE}], got {batch_size}")
    if workers is not None and not 1 <= workers <= 256:
        raise InputError(f"workers must lie in [1, 256], got {workers}")
    if scheduler:
        _check_address(scheduler)
    bar = progress_bar(progress)
    if bar is not None:
        bar.start()
        task = bar.add_task("planning", total=None, rate="")
    client = cluster = None
    try:
        rows = study.rows()
        prepare_folder(directory, study, force=force)
        plan_parts(directory, on_damaged="recompute")  # a damaged part: moved aside, computed again
        done = existing_keys(directory)
        values: dict[str, tuple] = {}

        def pending():  # the variants not yet in the folder, each once (keys made as they go)
            for number, row in enumerate(rows):
                inputs = study.variant_inputs(row)
                key = study.key(inputs)
                if key in done or key in values:
                    continue
                values[key] = row
                yield number, key, inputs

        plan = pending()
        first = next(plan, None)
        run = StudyRun(directory=directory, variants=len(rows), skipped=0, computed=0,
                       failed=0, seconds=0.0, compute_seconds=0.0, workers=0)
        if first is None:
            run.skipped = len(rows)
            if bar is not None:
                bar.update(task, description="nothing to do", total=1, completed=1)
            run.seconds = time.perf_counter() - t_start
            return run
        estimate = len(rows) - len(done)  # at most this many to compute (known when planned)
        quiet = QuietProgress(estimate) if bar is None and estimate >= LONG_STUDY else None
        if bar is not None:
            bar.update(task, description="starting the cluster", total=estimate, completed=0)
        client, cluster = _client(scheduler, workers, timeout=min(10.0, max(3.0, wait_for_workers)))
        try:
            client.wait_for_workers(1, timeout=wait_for_workers)
        except (TimeoutError, OSError) as exc:
            raise InfeasibleError(f"no dask worker joined the scheduler within {wait_for_workers:g} s "
                                  f"({exc}); start one with `dask worker {scheduler}`") from None
        nworkers = len(client.scheduler_info(n_workers=-1).get("workers", {})) or 1
        try:
            client.run(warm_up)  # imports on every worker, outside the timed part
        except Exception:  # noqa: BLE001 - a broken worker shows in the variants' errors
            pass
        run.workers = nworkers
        size = batch_size or max(1, min(DEFAULT_BATCH_SIZE, math.ceil(estimate / (8 * nworkers))))
        writer = _PartWriter(directory, study)
        payload = {"base": study.base, "outputs": list(study.outputs), "parts": list(study.parts),
                   "simulation": study.simulation}
        from distributed import as_completed

        t0 = time.perf_counter()
        if bar is not None:
            bar.update(task, description=f"study, {nworkers} worker{'s' if nworkers != 1 else ''}")
        index: dict[str, list] = {}
        finished = as_completed()

        def collect(future) -> None:
            try:
                result = future.result()
            except Exception as exc:  # noqa: BLE001 - a lost batch is recorded, the study goes on
                msg = f"{CLUSTER_FAILURE}: {_one_line(exc)}"
                lost = index[future.key]
                result = {"key": [k for _, k, _ in lost], "variant": [n for n, _, _ in lost],
                          "error": [msg] * len(lost)}
            future.release()
            del index[future.key]
            run.files.append(writer.write(result, values))
            run.computed += len(result["key"])
            run.failed += sum(1 for e in result.get("error") or () if e)
            run.compute_seconds = time.perf_counter() - t0
            if bar is not None:
                bar.update(task, completed=run.computed, rate=f"{run.rate:.1f} variants/s")
            if quiet is not None:
                quiet.update(run.computed, run.rate)

        # batches go to the cluster as they are planned (the workers start on the first
        # while the client makes the keys of the next); finished ones are written meanwhile
        batch = [first]
        for item in plan:
            batch.append(item)
            if len(batch) == size:
                future = client.submit(run_batch_columns, batch, pure=False, **payload)
                index[future.key] = batch
                finished.add(future)
                batch = []
                while finished.has_ready():
                    collect(next(finished))
        if batch:
            future = client.submit(run_batch_columns, batch, pure=False, **payload)
            index[future.key] = batch
            finished.add(future)
        run.skipped = len(rows) - len(values)
        if bar is not None:
            bar.update(task, total=len(values))
        for future in finished:
            collect(future)
        run.seconds = time.perf_counter() - t_start
        return run
    finally:
        if bar is not None:
            bar.stop()
        if client is not None:
            client.close()
        if cluster is not None:
            cluster.close()
