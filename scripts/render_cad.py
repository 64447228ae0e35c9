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
VIEWS = {"roller_industrial.toml": (30, -75), "multi_wheel.toml": (40, -70), "mining_conveyor.toml": (65, -90)}


def main(names: list[str]) -> None:
    OUT.mkdir(parents=True, exist_ok=True)
    for name in names or list(VIEWS):
        a = drive_assembly(load_project(example_path(name)))
        elev, azim = VIEWS.get(name, (30, -70))
        fig = assembly_plot(a, tessellate(a), elevation=elev, azimuth=azim)
        path = OUT / f"cad_{Path(name).stem}.png"
        fig.savefig(path, dpi=110, bbox_inches="tight")
        print("wrote", path)


if __name__ == "__main__":
    main(sys.argv[1:])
