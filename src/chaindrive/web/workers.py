"""The set-up of the web server's worker processes (internal): a lower CPU priority, and an
end when the server is gone. Used by the job manager (:mod:`chaindrive.web.jobs`) for its
pool and by each task process (:mod:`chaindrive.web.tasks`)."""

from __future__ import annotations

import os
import threading
import time

__all__ = ["WORKER_NICENESS", "worker_setup"]


#: Niceness added to worker processes: the server's own process (pages, the event loop)
#: is served first when the CPUs are busy.
WORKER_NICENESS = 10


def _alive(pid: int) -> bool:
    try:
        with open(f"/proc/{pid}/stat", encoding="ascii") as f:
            return f.read().rsplit(")", 1)[1].split()[0] not in ("Z", "X")
    except FileNotFoundError:
        return False
    except OSError:  # pragma: no cover - no /proc: ask the kernel
        try:
            os.kill(pid, 0)
        except ProcessLookupError:
            return False
        return True


def _watch(server_pid: int) -> None:
    while True:
        time.sleep(1.0)
        if not _alive(server_pid):
            os._exit(0)


def worker_setup(server_pid: int | None = None) -> None:
    """Set up a worker process: lower its CPU priority by :data:`WORKER_NICENESS`, and end
    it when the server process ``server_pid`` is gone (a worker forked from the forkserver
    would otherwise outlive a killed server, and keep the forkserver alive with it)."""
    try:
        # CHAINDRIVE_WEB_NICENESS overrides the niceness (the browser tests run the server
        # beside a busy test suite and keep its workers at the suite's priority)
        os.nice(int(os.environ.get("CHAINDRIVE_WEB_NICENESS", WORKER_NICENESS)))
    except (OSError, AttributeError, ValueError):  # pragma: no cover - not permitted, not POSIX, bad value
        pass
    if server_pid is not None:
        threading.Thread(target=_watch, args=(int(server_pid),), daemon=True).start()
