"""The drive description: the immutable :class:`Drive` and its parts, and project files.

The formulas live in their topic modules (:mod:`chaindrive.layout`, :mod:`chaindrive.loads`,
:mod:`chaindrive.selection`, :mod:`chaindrive.life.wear`); the thin objects
(:class:`Drive`, :class:`Wheel`, :class:`Tensioner`, :class:`Guide`, :class:`Load`), immutable, in
:mod:`~chaindrive.drive.model`; their analysis in :mod:`chaindrive.analysis`; TOML project files in :mod:`~chaindrive.drive.project`.
Models and sources: ``docs/drive.md``.

Examples
--------
>>> from chaindrive.drive import Drive, Wheel, Load
>>> from chaindrive.chains import get
>>> d = Drive(chain=get("16B"), speed=100.53, load=Load(power=15e3, service_factor=1.0),
...           wheels=[Wheel("motor", "sprocket", 19, (0, 0), driving=True),
...                   Wheel("fan", "sprocket", 57, (1.05, 0))])
>>> from chaindrive.analysis import drive_layout
>>> drive_layout(d).links
122
"""

from typing import Any

from . import tables as _tables  # noqa: F401 - declares the input tables
from .model import (
    Adjustable,
    ContactSpec,
    Conveyor,
    CrawlerSpec,
    Drive,
    FrettingSpec,
    Guide,
    Load,
    RimBoltsSpec,
    Tensioner,
    TrackSpec,
    Wheel,
)

__all__ = [
    "Drive", "Wheel", "Tensioner", "Adjustable", "Guide", "Load", "ContactSpec", "TrackSpec", "CrawlerSpec",
    "FrettingSpec", "RimBoltsSpec", "Conveyor",
    "load_project", "Project",
]

#: Formula names that lived here before they moved to their topic modules (deprecated aliases).
_MOVED = {
    "chain_length_approx": "layout", "centre_distance_approx": "layout", "chain_length_circles": "layout",
    "chain_length_polygon": "layout", "centre_distance_polygon": "layout", "even_links": "layout",
    "wrap_layout": "layout", "catenary_sag": "layout", "parabolic_sag": "layout", "tension_for_sag": "layout",
    "tensioner_travel": "layout", "ansi_rated_power": "selection", "lubrication_type": "selection",
    "select": "selection", "wear_life": "wear",
    "layout": None, "loads": None, "selection": None, "wear": None,
}


def __getattr__(name: str) -> Any:  # project files need pydantic (optional extra): import lazily
    import importlib

    if name in ("load_project", "Project", "project"):
        project = importlib.import_module(f"{__name__}.project")
        return project if name == "project" else getattr(project, name)
    if name in _MOVED:
        from .._deprecation import warn_renamed

        home = _MOVED[name]
        if home is None:
            warn_renamed(f"chaindrive.drive.{name}", f"chaindrive.{name}")
            return importlib.import_module(f"chaindrive.{name}")
        warn_renamed(f"chaindrive.drive.{name}", f"chaindrive.{home}.{name}")
        return getattr(importlib.import_module(f"chaindrive.{home}"), name)
    raise AttributeError(name)
