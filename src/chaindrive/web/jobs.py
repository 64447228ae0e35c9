"""Long work off the event loop: jobs in worker processes with a concurrency and a time cap.

A job (a full report with figures, a PDF, a simulation) runs in its own process, forked
from a ``forkserver`` that has chaindrive already imported, so it starts in milliseconds
and can be killed when it overruns its time cap. At most ``max_jobs`` jobs are admitted
at a time (running or waiting for a CPU); one more is refused at once with
:class:`Busy` (the app answers 503 with the message), never queued without bound.

Work that is quick but not free (the live analysis of the studio) goes through
:class:`Gate`: a small pool of worker processes with a bounded number of waiting requests.
"""

from __future__ import annotations

import asyncio
import contextlib
import gc
import multiprocessing
import os
import shutil
import sys
import tempfile
import threading
import time
import uuid
from collections import OrderedDict
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..errors import ChainDriveError
from .workers import worker_setup

__all__ = ["Busy", "Job", "JobManager", "Gate"]


class Busy(ChainDriveError):
    """The server has no room for more work now (answered with 503)."""


@dataclass
class Job:
    """One job: its state, progress in [0, 1], message, files written, errors."""

    id: str
    kind: str
    folder: Path
    state: str = "queued"  # queued | running | done | failed | timeout
    progress: float = 0.0
    message: str = "waiting for a worker"
    files: dict[str, str] = field(default_factory=dict)
    result: dict[str, Any] = field(default_factory=dict)
    error: str = ""
    started: float = field(default_factory=time.monotonic)
    finished: threading.Event = field(default_factory=threading.Event)

    def public(self) -> dict[str, Any]:
        """JSON-ready view (no paths)."""
        return {"id": self.id, "kind": self.kind, "state": self.state,
                "progress": round(self.progress, 4), "message": self.message,
                "files": sorted(self.files), "result": self.result, "error": self.error,
                "elapsed": round(time.monotonic() - self.started, 2)}


def _context():
    try:
        ctx = multiprocessing.get_context("forkserver")
    except ValueError:  # pragma: no cover - platforms without forkserver
        return multiprocessing.get_context("spawn")
    ctx.set_forkserver_preload(["chaindrive.web.tasks", "chaindrive.web.studio", "chaindrive.web.api"])
    # start the server without the main script: a script run as a file would be
    # imported again in the server (and run its top level) otherwise
    import multiprocessing.forkserver as forkserver

    main = sys.modules.get("__main__")
    saved = main.__dict__.pop("__file__", None) if main is not None else None
    try:
        forkserver.ensure_running()
    finally:
        if saved is not None:
            main.__file__ = saved
    return ctx


class JobManager:
    """Admits, runs and times out jobs.

    Parameters
    ----------
    max_jobs : int
        Jobs admitted at a time (running plus waiting for a CPU).
    workers : int
        Jobs running at a time (processes).
    time_limit : float
        Wall time a job may run before it is killed [s].
    keep : int
        Finished jobs kept (their folders are deleted after that).

    Examples
    --------
    >>> m = JobManager(max_jobs=1, workers=1, time_limit=5.0)
    >>> m.admitted
    0
    """

    def __init__(self, max_jobs: int = 4, workers: int = 2, time_limit: float = 90.0, keep: int = 40) -> None:
        self.max_jobs = int(max_jobs)
        self.time_limit = float(time_limit)
        self.keep = int(keep)
        self._slots = threading.BoundedSemaphore(int(workers))
        self._lock = threading.Lock()
        self._jobs: OrderedDict[str, Job] = OrderedDict()
        self._root = Path(tempfile.mkdtemp(prefix="chaindrive-web-"))
        self._ctx: Any = None  # the multiprocessing context, made on the first job
        self._procs: set = set()

    @property
    def admitted(self) -> int:
        """Jobs queued or running now."""
        with self._lock:
            return sum(1 for j in self._jobs.values() if j.state in ("queued", "running"))

    def submit(self, kind: str, payload: dict[str, Any], *, time_limit: float | None = None) -> Job:
        """Start a job of ``kind`` (a function of :mod:`chaindrive.web.tasks`).

        Raises
        ------
        Busy
            ``max_jobs`` jobs are already admitted.
        """
        with self._lock:
            active = sum(1 for j in self._jobs.values() if j.state in ("queued", "running"))
            if active >= self.max_jobs:
                raise Busy(f"the server is busy: {active} long jobs (reports, simulations) are running "
                           f"or waiting, the limit is {self.max_jobs}; try again in a minute")
            job_id = uuid.uuid4().hex
            folder = self._root / job_id
            folder.mkdir()
            job = Job(id=job_id, kind=kind, folder=folder)
            self._jobs[job_id] = job
            self._prune()
        limit = self.time_limit if time_limit is None else float(time_limit)
        threading.Thread(target=self._run, args=(job, payload, limit), daemon=True).start()
        return job

    def get(self, job_id: str) -> Job | None:
        """The job with this id (``None`` when unknown or pruned)."""
        with self._lock:
            return self._jobs.get(job_id)

    async def wait(self, job: Job, timeout: float | None = None) -> Job:
        """Wait (without blocking the event loop) until ``job`` has finished."""
        loop = asyncio.get_running_loop()
        await loop.run_in_executor(None, job.finished.wait, timeout or self.time_limit + 30)
        return job

    def _prune(self) -> None:
        done = [j for j in self._jobs.values() if j.finished.is_set()]
        for j in done[: max(0, len(done) - self.keep)]:
            self._jobs.pop(j.id, None)
            shutil.rmtree(j.folder, ignore_errors=True)

    def _run(self, job: Job, payload: dict[str, Any], limit: float) -> None:
        try:
            with self._slots:
                self._execute(job, payload, limit)
        except Exception as exc:  # noqa: BLE001 - a job's failure is reported, never raised
            job.state, job.error = "failed", f"{type(exc).__name__}: {exc}"
        finally:
            job.finished.set()

    def _execute(self, job: Job, payload: dict[str, Any], limit: float) -> None:
        if self._ctx is None:
            self._ctx = _context()
        recv, send = self._ctx.Pipe(duplex=False)
        from .tasks import run_task  # imported on first use: it preloads matplotlib and the report

        proc = self._ctx.Process(target=run_task, args=(send, job.kind, payload, str(job.folder), os.getpid()),
                                 daemon=True)
        self._procs.add(proc)
        job.state, job.message, job.started = "running", "starting", time.monotonic()
        proc.start()
        send.close()
        deadline = time.monotonic() + limit
        try:
            while True:
                left = deadline - time.monotonic()
                if left <= 0:
                    proc.kill()
                    job.state = "timeout"
                    job.error = (f"stopped after the time cap of {limit:g} s; shorten the job "
                                 "(e.g. a shorter simulated time)")
                    return
                if recv.poll(min(left, 0.5)):
                    try:
                        kind, *rest = recv.recv()
                    except EOFError:
                        job.state = "failed"
                        job.error = "the worker stopped without a result"
                        return
                    if kind == "progress":
                        job.progress, job.message = float(rest[0]), str(rest[1])
                    elif kind == "done":
                        files, result = rest
                        job.files = {k: v for k, v in files.items()
                                     if Path(v).resolve().parent == job.folder.resolve()}
                        job.result = result
                        job.state, job.progress, job.message = "done", 1.0, "done"
                        return
                    elif kind == "error":
                        job.state, job.error, job.message = "failed", str(rest[0]), "failed"
                        return
                elif not proc.is_alive() and not recv.poll(0):
                    job.state, job.error = "failed", f"the worker exited (code {proc.exitcode})"
                    return
        finally:
            recv.close()
            proc.join(timeout=5)
            if proc.is_alive():  # pragma: no cover - kill did not take
                proc.kill()
            self._procs.discard(proc)

    def close(self) -> None:
        """Stop the running jobs and delete the job folders."""
        for proc in list(self._procs):
            try:
                proc.kill()
            except (AttributeError, OSError, ValueError):  # not started yet, or gone
                pass
        shutil.rmtree(self._root, ignore_errors=True)


class Gate:
    """Worker processes for quick work (the live analysis), refusing when too many wait.

    The work runs in processes forked from the forkserver (chaindrive already imported),
    never in the server's process: a burst of analyses cannot slow the event loop, which
    keeps answering light pages. The functions and their arguments must be picklable
    (module-level functions of plain data). Each request goes to the first idle worker (the
    least busy when none is idle), so that one user's edits and the charts that follow each
    edit meet the results that worker keeps (the design of the form, the ratings).

    Parameters
    ----------
    workers : int
        Processes.
    max_waiting : int
        Requests admitted at a time (running plus waiting); more raise :class:`Busy`.
    time_limit : float
        Longest wait for one result [s]; then :class:`Busy` (the worker is replaced).
    """

    def __init__(self, workers: int = 2, max_waiting: int = 8, time_limit: float = 60.0) -> None:
        self.workers = int(workers)
        self.max_waiting = int(max_waiting)
        self.time_limit = float(time_limit)
        self._lock = threading.Lock()
        self._count = 0
        self._pools: list[Any] = [None] * max(1, self.workers)
        self._busy = [0] * len(self._pools)

    def _executor(self, slot: int):
        from concurrent.futures import ProcessPoolExecutor

        if self._pools[slot] is None:
            self._pools[slot] = ProcessPoolExecutor(max_workers=1, mp_context=_context(),
                                                    initializer=worker_setup, initargs=(os.getpid(),))
        return self._pools[slot]

    async def run(self, fn: Callable[..., Any], *args: Any) -> Any:
        """Run ``fn(*args)`` in a worker; :class:`Busy` when ``max_waiting`` are admitted."""
        from concurrent.futures.process import BrokenProcessPool

        with self._lock:
            if self._count >= self.max_waiting:
                raise Busy(f"the server is busy ({self._count} analyses waiting, the limit is "
                           f"{self.max_waiting}); the page retries by itself")
            self._count += 1
            slot = min(range(len(self._busy)), key=lambda i: (self._busy[i], i))
            self._busy[slot] += 1
        try:
            loop = asyncio.get_running_loop()
            try:
                future = loop.run_in_executor(self._executor(slot), fn, *args)
                return await asyncio.wait_for(future, self.time_limit)
            except (TimeoutError, BrokenProcessPool):
                pool, self._pools[slot] = self._pools[slot], None
                if pool is not None:
                    pool.shutdown(wait=False, cancel_futures=True)
                    for proc in list(getattr(pool, "_processes", {}).values()):
                        proc.kill()
                raise Busy(f"the analysis did not finish within {self.time_limit:g} s; "
                           "try again or simplify the input") from None
        finally:
            with self._lock:
                self._count -= 1
                self._busy[slot] -= 1

    def close(self) -> None:
        """Stop the worker processes and release the pools' queues (their semaphores are
        unlinked now, not reported as leaked by multiprocessing's resource tracker at exit)."""
        pools = [p for p in self._pools if p is not None]
        self._pools = [None] * len(self._pools)
        for pool in pools:
            _stop_pool(pool)
        del pools
        gc.collect()


def _stop_pool(pool: Any) -> None:
    """Kill the processes of a pool, join them and shut the pool down."""
    procs = list(getattr(pool, "_processes", {}).values())
    pool.shutdown(wait=False, cancel_futures=True)
    for proc in procs:
        try:
            proc.kill()
        except (AttributeError, OSError, ValueError):  # gone already
            pass
    for proc in procs:
        with contextlib.suppress(AttributeError, OSError, ValueError, AssertionError):
            proc.join(timeout=5)
    with contextlib.suppress(Exception):  # the manager thread notices the killed workers
        pool.shutdown(wait=True, cancel_futures=True)
