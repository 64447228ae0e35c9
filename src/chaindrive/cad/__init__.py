"""The drive as a 3-D assembly: STEP (named parts, placed copies), glTF, DXF and an interactive view.

>>> from chaindrive.cad import drive_assembly, write_step_assembly, write_gltf, figure  # doctest: +SKIP
>>> a = drive_assembly(load_project("examples/mining_conveyor.toml"))                  # doctest: +SKIP
>>> write_step_assembly(a, "drive.step"); write_gltf(a, "drive.glb"); figure(a)        # doctest: +SKIP

See ``docs/cad.md``. Needs build123d (extra ``cad3d``); the placements
(:mod:`chaindrive.cad.assembly`) need only numpy.
"""

from __future__ import annotations

from typing import Any

__all__ = ["drive_assembly", "frame_assembly", "write_step_assembly", "read_assembly", "clearances",
           "write_gltf", "write_dxf", "figure"]

_WHERE = {"drive_assembly": "assembly", "frame_assembly": "assembly", "write_step_assembly": "build",
          "read_assembly": "build", "clearances": "build", "write_gltf": "mesh", "figure": "mesh",
          "write_dxf": "drawing"}


def __getattr__(name: str) -> Any:
    """The public names, imported on first use (OpenCascade loads only when needed)."""
    if name in _WHERE:
        import importlib

        return getattr(importlib.import_module(f"{__name__}.{_WHERE[name]}"), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
