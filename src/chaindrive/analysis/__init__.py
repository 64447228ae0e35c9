r"""The analysis of a drive: one function from a :class:`~chaindrive.drive.Drive` to a
:class:`DriveAnalysis`, with no plots and no report.

:func:`analyze_drive` computes each declared part (:mod:`chaindrive.analysis.parts`)
once, after the parts it needs: the layout, the loads (with the peak acceleration of the
driving wheel's entry) and the slack-span sag, the rating, the entry kinematics of the
driving and the guided wheels, the span vibration and resonance check, the wheel
geometry, the contact with skew, the track wheel teeth, the wear life, the
self-regulating drive and every part declared by another module of this package, and
the list of :class:`Check` verdicts with their values, limits, units, sources and parts.
Every engineering decision of the analysis lives in this package, documented where it is
made; the report, the command line, the web page and design studies only present a
:class:`DriveAnalysis`, iterating the declarations.

Select parts with ``include=`` or ``exclude=`` (names in :func:`part_names`): the parts
a selected part needs are computed but not returned.

Examples
--------
>>> from chaindrive.drive.project import load_project
>>> a = analyze_drive(load_project("examples/roller_industrial.toml"))
>>> a.layout.links, a.passed
(122, True)
>>> [(c.part, c.verdict) for c in a.checks][:3]
[('layout', 'pass'), ('layout', 'pass'), ('layout', 'pass')]
>>> analyze_drive(load_project("examples/roller_industrial.toml"), include=["loads"]).rating is None
True
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any

from .._finite import guard_scope
from .._results import Result
from ..drive.model import Drive
from ..errors import InputError
from .checks import Check
from .entry import DriveEntry, drive_entry, entry_cases
from .geometry import WheelGeometry, drive_geometry
from .layout import DriveLayout, drive_layout, slack_span_sag
from .loads import DriveLoads, drive_loads
from .parts import (
    Part,
    PartContext,
    all_parts,
    compute_parts,
    get_part,
    part_names,
    register_part,
    temporary_part,
)
from .rating import DriveRating, drive_rating
from .strength import ContactAnalysis, drive_contact
from .vibration import DriveVibration, drive_vibration, tensioner_span

__all__ = ["Check", "DriveAnalysis", "analyze_drive", "DriveLayout", "DriveLoads", "DriveRating",
           "DriveEntry", "DriveVibration", "ContactAnalysis", "WheelGeometry", "drive_layout", "drive_loads",
           "drive_rating", "drive_entry", "drive_vibration", "drive_contact", "drive_geometry",
           "entry_cases", "tensioner_span", "slack_span_sag",
           "Part", "PartContext", "register_part", "temporary_part", "get_part", "all_parts", "part_names"]


def __getattr__(name: str) -> Any:
    if name == "PARTS":  # the declared parts' names, in report order (a live view of the registry)
        return part_names()
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


@dataclass(frozen=True)
class DriveAnalysis(Result):
    """The complete analysis of one drive (SI units).

    The result of each declared part (:mod:`chaindrive.analysis.parts`) is an attribute
    of that name (``a.layout``, ``a.loads``, ``a.vibration``, ...) and an item
    (``a["layout"]``); parts not asked for, or that do not apply to the drive, are ``None``.

    Attributes
    ----------
    drive : Drive
    results : mapping of str to object
        The result of each returned part, by part name.
    checks : tuple of Check
        The verdicts of the returned parts, in report order (each knows its ``part``).
    warnings : tuple of str
        Everything the analysis warned about, each once.
    parts : tuple of str
        The names of the returned parts, in report order.
    """

    drive: Drive
    results: Mapping[str, Any] = field(default_factory=dict)
    checks: tuple[Check, ...] = ()
    warnings: tuple[str, ...] = ()
    parts: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        object.__setattr__(self, "results", MappingProxyType(dict(self.results)))

    def __getattr__(self, name: str) -> Any:
        if name.startswith("_"):
            raise AttributeError(name)
        try:
            results = object.__getattribute__(self, "results")
        except AttributeError:
            raise AttributeError(name) from None
        if name in results:
            return results[name]
        if name in part_names():
            return None
        raise AttributeError(f"{type(self).__name__!r} has no attribute or analysis part {name!r}")

    def __getitem__(self, name: str) -> Any:
        get_part(name)  # an unknown name is an InputError naming the valid parts
        return self.results.get(name)

    def __reduce__(self) -> Any:  # results is a mapping proxy: pickle a plain dict
        return (_rebuild_analysis, (self.drive, dict(self.results), self.checks, self.warnings, self.parts))

    @property
    def passed(self) -> bool:
        """No check failed (information and unknown values do not fail)."""
        return all(c.passed is not False for c in self.checks)

    @property
    def failed(self) -> tuple[Check, ...]:
        return tuple(c for c in self.checks if c.passed is False)

    def checks_of(self, *parts: str) -> tuple[Check, ...]:
        """The checks made by the named parts."""
        return tuple(c for c in self.checks if c.part in parts)

    def to_dict(self) -> dict[str, Any]:
        """Everything as JSON-ready data (SI units): inputs, every declared part (``None`` when
        not computed), checks, warnings, verdict."""
        out: dict[str, Any] = {"inputs": self.drive.inputs(), "passed": self.passed}
        for part in all_parts():
            out[part.name] = part.to_json(self.results.get(part.name))
        out["checks"] = [c.to_dict() for c in self.checks]
        out["warnings"] = list(self.warnings)
        return out


def _rebuild_analysis(drive: Drive, results: dict[str, Any], checks: tuple[Check, ...], warnings: tuple[str, ...],
                      parts: tuple[str, ...]) -> DriveAnalysis:
    return DriveAnalysis(drive, results, checks, warnings, parts)


def _parts(include: Iterable[str] | None, exclude: Iterable[str] | None) -> tuple[str, ...]:
    names = part_names()

    def check(given: Iterable[str], what: str) -> list[str]:
        given = [given] if isinstance(given, str) else list(given)
        bad = [n for n in given if n not in names]
        if bad:
            raise InputError(f"{what}: unknown part(s) {', '.join(map(repr, bad))}; valid: {', '.join(names)}",
                             field=what)
        return given

    chosen = check(include, "include") if include is not None else list(names)
    dropped = set(check(exclude, "exclude")) if exclude is not None else set()
    return tuple(p for p in names if p in chosen and p not in dropped)


def analyze_drive(drive: Drive, *, include: Iterable[str] | None = None,
                  exclude: Iterable[str] | None = None, entry_points: int = 361) -> DriveAnalysis:
    """The complete analysis of ``drive`` (no figures, no files).

    Each declared part (:func:`~chaindrive.analysis.parts.all_parts`) is computed once,
    after the parts it needs; its checks and warnings are collected.

    Parameters
    ----------
    drive : Drive
    include, exclude : iterable of str, optional
        Parts to return (names in :func:`~chaindrive.analysis.parts.part_names`); default
        all. The parts they need are computed but not returned. The checks are those of
        the returned parts.
    entry_points : int
        Wheel angles per tooth period of the entry kinematics (bounded by
        :func:`chaindrive.kinematics.chain_entry`).

    Returns
    -------
    DriveAnalysis

    Raises
    ------
    InputError
        The drive lacks data a part needs (e.g. the chain's mass per length), or an
        unknown part name.
    """
    if not isinstance(drive, Drive):
        raise InputError(f"drive must be a chaindrive.drive.Drive, got {type(drive).__name__}", field="drive")
    parts = _parts(include, exclude)
    with guard_scope():  # numpy's error state set once for the formula functions' guards
        results, checks, notes = compute_parts(drive, parts, {"entry_points": entry_points})
    return DriveAnalysis(drive=drive, results=results, checks=tuple(checks), warnings=tuple(dict.fromkeys(notes)),
                         parts=parts)
