"""Manufacturing CAD: time to build the drawing (DXF) and the solid (STEP) of a few wheels,
and the agreement of OpenCascade's volume with the closed form; then the whole drive as a
STEP assembly (``chaindrive cad``) of each example: parts, export time and file size.
Prints figures; no asserts.

Run: ``.venv/bin/python benchmarks/cad.py`` (needs the extras cad and cad3d);
``--drives-only`` skips the single wheels.
"""

from __future__ import annotations

import tempfile
import time
from pathlib import Path

from chaindrive.geometry import PocketWheel, Sprocket
from chaindrive.geometry.drawing import part_drawing
from chaindrive.geometry.part import part_volume, pocket_wheel_part, sprocket_part

CASES = [
    ("sprocket 16B z = 19", lambda: sprocket_part(Sprocket.from_chain("16B", 19))),
    ("sprocket 08B z = 11 (max gap form)", lambda: sprocket_part(Sprocket.from_chain("08B", 11), form="max")),
    ("sprocket ANSI 80 z = 17", lambda: sprocket_part(Sprocket.from_chain("80", 17, method="ansi"))),
    ("pocket wheel 18x64 z = 8", lambda: pocket_wheel_part(PocketWheel.from_chain("18x64", 8))),
]


def main() -> None:
    try:
        from chaindrive.geometry.solid import have_build123d, read_step, write_step
    except ImportError:  # pragma: no cover
        have_build123d = None
    solids = bool(have_build123d and have_build123d())
    print(f"{'case':36s} {'drawing CPU s':>14s} {'solid+STEP CPU s':>17s} {'V closed form cm3':>18s} "
          f"{'V OpenCascade / closed - 1':>27s}")
    with tempfile.TemporaryDirectory() as folder:
        for name, make in CASES:
            part = make()
            t0 = time.process_time()
            part_drawing(part, date="2026-01-01")
            t_draw = time.process_time() - t0
            volume = part_volume(part)
            if solids:
                path = Path(folder) / "part.step"
                t0 = time.process_time()
                write_step(part, path, force=True)
                t_solid = time.process_time() - t0
                ratio = read_step(path).volume / volume - 1.0
                print(f"{name:36s} {t_draw:14.2f} {t_solid:17.2f} {volume * 1e6:18.3f} {ratio:27.2e}")
            else:
                print(f"{name:36s} {t_draw:14.2f} {'(no build123d)':>17s} {volume * 1e6:18.3f}")
    print("CPU seconds (process time): the wall time on a shared machine is longer.")


#: Examples exported as assemblies (the 2,194-link conveyor of ``simulate --example conveyor`` last).
DRIVES = ["roller_industrial.toml", "multi_wheel.toml", "mining_conveyor.toml", "scraper_conveyor.toml",
          "long_conveyor.toml"]


def drives() -> None:
    """Export time (placement, solids, STEP) and size of each example's assembly."""
    from chaindrive._examples import example_path
    from chaindrive.cad.assembly import drive_assembly
    from chaindrive.cad.build import build_shapes, step_bytes
    from chaindrive.drive.project import load_project

    print(f"{'example':26s} {'links':>6s} {'parts':>6s} {'solids':>6s} {'place s':>8s} {'solids s':>9s} "
          f"{'STEP s':>7s} {'total s':>8s} {'STEP MB':>8s}")
    for name in DRIVES:
        drive = load_project(example_path(name))
        t0 = time.perf_counter()
        a = drive_assembly(drive)
        t1 = time.perf_counter()
        shapes = build_shapes(a)
        t2 = time.perf_counter()
        data = step_bytes(a, shapes)
        t3 = time.perf_counter()
        print(f"{name:26s} {a.total_links:6d} {a.part_count:6d} {len(shapes):6d} {t1 - t0:8.2f} {t2 - t1:9.2f} "
              f"{t3 - t2:7.2f} {t3 - t0:8.2f} {len(data) / 1e6:8.2f}")
    print("wall seconds (each distinct solid built once, the parts placed copies).")


if __name__ == "__main__":
    import sys

    if "--drives-only" not in sys.argv:
        main()
    drives()
