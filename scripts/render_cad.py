"""Render the pictures of docs/cad.md: each example's 3-D assembly as a PNG (docs/img/cad_*.png).

Run: ``PYTHONPATH=src python scripts/render_cad.py [example.toml ...]`` (needs the extra cad3d).
"""

from __future__ import annotations

import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

from chaindrive._examples import example_path  # noqa: E402
from chaindrive.cad.assembly import drive_assembly  # noqa: E402
from chaindrive.cad.mesh import tessellate  # noqa: E402
from chaindrive.drive.project import load_project  # noqa: E402
from chaindrive.plotting.cad import assembly_plot  # noqa: E402

OUT = Path(__file__).resolve().parents[1] / "docs" / "img"
VIEWS = {"roller_industrial.toml": (30, -75), "multi_wheel.toml": (40, -70), "mining_conveyor.toml": (30, -65)}
#: Close-ups: (example, wheel, radius round its centre [m], elevation, azimuth).
DETAILS = [("mining_conveyor.toml", "tensioner", 0.24, 35, -100), ("roller_industrial.toml", "motor", 0.17, 40, -110)]


def detail(name: str, wheel: str, radius: float, elev: float, azim: float) -> Path:
    """Picture of the parts within ``radius`` of a wheel's centre (the wheel and its chain)."""
    import dataclasses

    import numpy as np

    a = drive_assembly(load_project(example_path(name)))
    centre = next(p.matrix[:2, 3] for p in a.parts if p.name == f"wheel {wheel}")
    parts = tuple(p for p in a.parts if p.group in ("wheels", "chain")
                  and float(np.hypot(*(p.matrix[:2, 3] - centre))) < radius)
    keys = {p.shape for p in parts}
    sub = dataclasses.replace(a, parts=parts, shapes={k: v for k, v in a.shapes.items() if k in keys},
                              title=f"{a.title}: wheel {wheel}")
    fig = assembly_plot(sub, tessellate(sub), elevation=elev, azimuth=azim)
    path = OUT / f"cad_{Path(name).stem}_{wheel}.png"
    fig.savefig(path, dpi=110, bbox_inches="tight")
    return path


def main(names: list[str]) -> None:
    OUT.mkdir(parents=True, exist_ok=True)
    for name in names or list(VIEWS):
        a = drive_assembly(load_project(example_path(name)))
        elev, azim = VIEWS.get(name, (30, -70))
        fig = assembly_plot(a, tessellate(a), elevation=elev, azimuth=azim)
        path = OUT / f"cad_{Path(name).stem}.png"
        fig.savefig(path, dpi=110, bbox_inches="tight")
        print("wrote", path)
    for name, wheel, radius, elev, azim in DETAILS:
        if not names or name in names:
            print("wrote", detail(name, wheel, radius, elev, azim))


if __name__ == "__main__":
    main(sys.argv[1:])
