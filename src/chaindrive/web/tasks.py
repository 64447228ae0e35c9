"""What a job does, inside its worker process (see :mod:`chaindrive.web.jobs`).

Each task gets its payload (plain JSON-like data: the project text, options) and a folder
of its own; it sends ``("progress", fraction, text)`` messages and ends with
``("done", files, result)`` or ``("error", message)``. Files are named by the task, never
by the user.
"""

from __future__ import annotations

import json
import os
from pathlib import Path
from typing import Any

os.environ.setdefault("MPLBACKEND", "Agg")

import matplotlib  # noqa: E402  (preloaded in the forkserver: jobs start warm)

matplotlib.use("Agg")

from .. import workflows  # noqa: E402,F401
from ..drive.project import parse_project  # noqa: E402
from ..workflows import analyze as _analyze  # noqa: E402,F401

__all__ = ["run_task", "TASKS"]

from .expert import simulation_rows  # noqa: E402
from .workers import worker_setup  # noqa: E402


def _report(send: Any, payload: dict[str, Any], folder: Path) -> tuple[dict, dict]:
    from .engine import full_report

    drive = parse_project(payload["project"], filename="studio.toml")
    send.send(("progress", 0.1, "analysing"))
    files = full_report(drive, folder, pdf=bool(payload.get("pdf")))
    return files, {}


def _simulate(send: Any, payload: dict[str, Any], folder: Path) -> tuple[dict, dict]:
    import matplotlib.pyplot as plt

    from .._results import jsonable
    from ..plotting.simulation import drive_frame_plot, simulation_animation, simulation_plot
    from ..simulation import link_example, model_from_drive, roller_example, simulate

    duration = float(payload["duration"])
    frames = int(payload.get("frames", 30))
    example = payload.get("example")
    if example:
        build = {"roller": roller_example, "link": link_example}[example]
        model = build(angular_velocity=float(payload["speed"]), load_torque=float(payload["load"]),
                      ramp_time=float(payload.get("ramp", 0.1)))
    else:
        model = model_from_drive(parse_project(payload["project"], filename="project.toml"),
                                 ramp_time=float(payload.get("ramp", 0.1)))
        # the studio's drive runs at its own speed and load (the project file's)
    send.send(("progress", 0.0, "simulating"))
    res = simulate(model, duration,
                   progress=lambda done, total: send.send(("progress", 0.8 * done / total, "simulating")))
    files = {}
    send.send(("progress", 0.82, "drawing the plots"))
    fig = simulation_plot(res)
    fig.savefig(folder / "simulation.png", dpi=90)
    plt.close(fig)
    files["simulation.png"] = str(folder / "simulation.png")
    fig = drive_frame_plot(res)
    fig.savefig(folder / "frame.png", dpi=90)
    plt.close(fig)
    files["frame.png"] = str(folder / "frame.png")
    if frames > 0:
        send.send(("progress", 0.9, "drawing the animation"))
        simulation_animation(res, folder / "simulation.gif", frames=frames)
        files["simulation.gif"] = str(folder / "simulation.gif")
    summary = jsonable(res.summary)
    (folder / "simulation.json").write_text(json.dumps(summary, indent=2), encoding="utf-8")
    files["simulation.json"] = str(folder / "simulation.json")
    return files, {"summary": summary, "rows": simulation_rows(summary)}


TASKS = {"report": _report, "simulate": _simulate}


def run_task(send: Any, kind: str, payload: dict[str, Any], folder: str, server_pid: int | None = None) -> None:
    """Entry point of a worker process: run task ``kind`` and report through ``send``."""
    worker_setup(server_pid)
    try:
        files, result = TASKS[kind](send, payload, Path(folder))
        send.send(("done", files, result))
    except Exception as exc:  # noqa: BLE001 - every failure goes back as a message
        send.send(("error", f"{exc}" if getattr(exc, "__module__", "").startswith("chaindrive")
                   or type(exc).__module__.startswith("chaindrive") else f"{type(exc).__name__}: {exc}"))
    finally:
        send.close()
