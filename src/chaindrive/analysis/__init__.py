r"""The analysis of a drive: one function from a :class:`~chaindrive.drive.Drive` to a
:class:`DriveAnalysis`, with no plots and no report.

:func:`analyze_drive` computes, in this order and each once: the layout, the entry
kinematics of the driving and the guided wheels, the loads (with the peak acceleration of
the driving wheel's entry), the ANSI/ACA rating, the span vibration and resonance check,
the wheel geometry, the contact with skew, the track wheel teeth and the wear life, and
the list of :class:`Check` verdicts with their values, limits, units and sources. Every
engineering decision of the analysis lives in this package, documented where it is made;
the report, the command line, the web page and design studies only present a
:class:`DriveAnalysis`.

Select parts with ``include=`` or ``exclude=`` (names in :data:`PARTS`): the parts a
selected part needs are computed but not returned.

Examples
--------
>>> from chaindrive.drive.project import load_project
>>> a = analyze_drive(load_project("examples/roller_industrial.toml"))
>>> a.layout.links, a.passed
(122, True)
>>> [c.verdict for c in a.checks][:3]
['pass', 'pass', 'pass']
>>> analyze_drive(load_project("examples/roller_industrial.toml"), include=["loads"]).rating is None
True
"""

from __future__ import annotations

import warnings
from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import Any

from .._results import Result, jsonable, quantity
from ..drive.model import Drive
from ..errors import ChainDriveError, InputError
from ..wear import WearLife
from .checks import Check
from .entry import DriveEntry, drive_entry, entry_cases, entry_checks
from .geometry import WheelGeometry, drive_geometry
from .layout import DriveLayout, drive_layout, slack_span_sag
from .loads import DriveLoads, drive_loads, static_safety_check, wrap_check
from .rating import DriveRating, drive_rating, rating_checks
from .strength import (
    ContactAnalysis,
    contact_checks,
    drive_contact,
    drive_track_tooth,
    track_tooth_checks,
)
from .vibration import DriveVibration, drive_vibration, tensioner_span, vibration_checks
from .wear import drive_wear

__all__ = ["PARTS", "Check", "DriveAnalysis", "analyze_drive", "DriveLayout", "DriveLoads", "DriveRating",
           "DriveEntry", "DriveVibration", "ContactAnalysis", "WheelGeometry", "drive_layout", "drive_loads",
           "drive_rating", "drive_entry", "drive_vibration", "drive_contact", "drive_geometry",
           "entry_cases", "tensioner_span", "slack_span_sag"]

#: The parts of an analysis, in report order.
PARTS = ("layout", "loads", "rating", "entry", "vibration", "geometry", "contact", "track_tooth", "wear",
         "self_regulating")


@dataclass(frozen=True)
class DriveAnalysis(Result):
    """The complete analysis of one drive (SI units). Parts not asked for are ``None``.

    Attributes
    ----------
    drive : Drive
    layout : DriveLayout
    loads : DriveLoads
    slack_sag : float or None
        Catenary sag of the slack span at the slack tension [m].
    rating : DriveRating or None
        ANSI/ACA rating (standard roller chains).
    entry : DriveEntry
        Entry kinematics of the driving and the guided wheels.
    vibration : DriveVibration
    geometry : tuple of WheelGeometry
    contact : ContactAnalysis or None
    track_tooth : TrackToothCheck or None
    wear : WearLife or None
    self_regulating : object or None
    checks : tuple of Check
    warnings : tuple of str
        Everything the analysis warned about, each once.
    """

    drive: Drive
    layout: DriveLayout | None = None
    loads: DriveLoads | None = None
    slack_sag: float | None = quantity("m", default=None)
    rating: DriveRating | None = None
    entry: DriveEntry | None = None
    vibration: DriveVibration | None = None
    geometry: tuple[WheelGeometry, ...] | None = None
    contact: ContactAnalysis | None = None
    track_tooth: Any = None
    wear: WearLife | None = None
    self_regulating: Any = None
    checks: tuple[Check, ...] = ()
    warnings: tuple[str, ...] = ()
    parts: tuple[str, ...] = field(default=PARTS)

    @property
    def passed(self) -> bool:
        """No check failed (information and unknown values do not fail)."""
        return all(c.passed is not False for c in self.checks)

    @property
    def failed(self) -> tuple[Check, ...]:
        return tuple(c for c in self.checks if c.passed is False)

    def to_dict(self) -> dict[str, Any]:
        """Everything as JSON-ready data (SI units): inputs, parts, checks, warnings, verdict."""
        out: dict[str, Any] = {"inputs": self.drive.inputs(), "passed": self.passed}
        for name in ("layout", "loads", "slack_sag", "rating", "entry", "vibration", "contact",
                     "track_tooth", "wear", "self_regulating"):
            out[name] = jsonable(getattr(self, name))
        out["geometry"] = None if self.geometry is None else {g.wheel: g.to_dict() for g in self.geometry}
        out["checks"] = [c.to_dict() for c in self.checks]
        out["warnings"] = list(self.warnings)
        return out


def _parts(include: Iterable[str] | None, exclude: Iterable[str] | None) -> tuple[str, ...]:
    def check(names: Iterable[str], what: str) -> list[str]:
        names = [names] if isinstance(names, str) else list(names)
        bad = [n for n in names if n not in PARTS]
        if bad:
            raise InputError(f"{what}: unknown part(s) {', '.join(map(repr, bad))}; valid: {', '.join(PARTS)}",
                             field=what)
        return names

    chosen = check(include, "include") if include is not None else list(PARTS)
    dropped = set(check(exclude, "exclude")) if exclude is not None else set()
    return tuple(p for p in PARTS if p in chosen and p not in dropped)


def analyze_drive(drive: Drive, *, include: Iterable[str] | None = None,
                  exclude: Iterable[str] | None = None, entry_points: int = 361) -> DriveAnalysis:
    """The complete analysis of ``drive`` (no figures, no files).

    Parameters
    ----------
    drive : Drive
    include, exclude : iterable of str, optional
        Parts to return (names in :data:`PARTS`); default all that apply. The checks are
        those of the returned parts.
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
    want = set(parts)
    need_loads = want & {"loads", "vibration", "contact", "wear"}
    need_rating = want & {"rating", "wear"}
    notes: list[str] = []
    checks: list[Check] = []
    out: dict[str, Any] = {}
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        lay = drive_layout(drive)
        if "layout" in want:
            out["layout"] = lay
        entry = None
        if "entry" in want or need_loads:
            entry = drive_entry(drive, points=entry_points)
            if "entry" in want:
                out["entry"] = entry
        loads = None
        if need_loads and entry is not None:  # the entry is computed whenever loads are needed
            driving = entry.driving
            loads = drive_loads(drive, lay, acceleration_peak=entry.acceleration_peak,
                                acceleration_source=f"chaindrive.kinematics.chain_entry ({driving.case.entry} entry)")
            if "loads" in want:
                out["loads"] = loads
                checks.append(static_safety_check(drive, loads))
                try:
                    out["slack_sag"] = slack_span_sag(drive, lay, loads.slack)
                except ChainDriveError as exc:
                    notes.append(f"sag not computed: {exc}")
        rating = drive_rating(drive) if need_rating else None
        if "rating" in want and rating is not None:
            out["rating"] = rating
            checks.extend(rating_checks(drive, rating))
            notes.extend(rating.rating.warnings)
        if "layout" in want:
            checks.append(wrap_check(drive, lay))
            if lay.take_up is None:
                notes.append(f"take-up: {lay.take_up_kind}")
        if "entry" in want and entry is not None:
            checks.extend(entry_checks(entry))
        # vibration, contact and wear are in need_loads: loads is not None for them
        if "vibration" in want and loads is not None:
            vib = drive_vibration(drive, lay, loads)
            out["vibration"] = vib
            checks.extend(vibration_checks(vib))
            notes.extend(vib.notes)
        geometry = drive_geometry(drive) if want & {"geometry", "track_tooth"} else None
        if "geometry" in want:
            out["geometry"] = geometry
        if "contact" in want and loads is not None:
            con = drive_contact(drive, loads)
            if con is not None:
                out["contact"] = con
                checks.extend(contact_checks(con))
        if "track_tooth" in want and drive.track is not None:
            from ..geometry.track_wheel import TrackDriveWheel

            tw = next((g.object for g in geometry or () if isinstance(g.object, TrackDriveWheel)), None)
            tt = drive_track_tooth(drive, tw)
            if tt is not None:
                out["track_tooth"] = tt
                checks.extend(track_tooth_checks(drive, tt))
        if "wear" in want and loads is not None:
            life = drive_wear(drive, lay, loads, rating)
            out["wear"] = life
            if life is not None:
                checks.append(Check("hours to the elongation limit", float(life.hours_to_limit), None, "h", None,
                                    "ANSI/ACA 15 000 h basis" if life.model == "rating" else "Archard wear of the joints",
                                    relation="info"))
            else:
                notes.append("wear life: no wear model applies (a link chain needs wear_coefficient in [drive])")
        if "self_regulating" in want and drive.self_regulating is not None:
            from ..drive.self_regulating import self_regulating_analysis, self_regulating_checks

            sr = self_regulating_analysis(drive, drive.self_regulating)
            out["self_regulating"] = sr
            checks.extend(self_regulating_checks(sr))
            notes.extend(sr.warnings)
    seen = dict.fromkeys(notes)
    for w in caught:
        seen.setdefault(str(w.message))
    return DriveAnalysis(drive=drive, checks=tuple(checks), warnings=tuple(seen), parts=parts, **out)



