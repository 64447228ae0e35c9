"""Entry kinematics of a drive: the chain entering its guided wheels and its driving wheel."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from .._finite import finite_guard
from .._results import Result
from ..drive.model import Drive
from ..kinematics import EntryKinematics, chain_entry
from ._memo import memo
from ._wheels import wheel_teeth
from .checks import Check
from .parts import Part, PartContext, register_part

__all__ = ["EntryCase", "EntryAnalysis", "DriveEntry", "entry_cases", "drive_entry"]


@dataclass(frozen=True)
class EntryCase:
    """The inputs of :func:`chaindrive.kinematics.chain_entry` for one wheel entry (SI)."""

    wheel: str
    pitch: float
    teeth: int
    angular_velocity: float
    bar_diameter: float | None
    entry: str
    guide_end_distance: float | None = None
    guide_height: float | None = None

    def solve(self, *, points: int = 361, free: bool = False) -> EntryKinematics:
        """The entry kinematics (exact rigid-link model); ``free=True``: the same wheel without guide.

        Kept for reuse by its case (:mod:`chaindrive.analysis._memo`): a drive whose other
        fields changed has the same entries."""
        return _solve(self, int(points), bool(free or self.entry == "free"))

    def _solve(self, points: int, free: bool) -> EntryKinematics:
        if free:
            return chain_entry(self.pitch, self.teeth, self.angular_velocity, bar_diameter=self.bar_diameter,
                               entry="free", points=points)
        return chain_entry(self.pitch, self.teeth, self.angular_velocity, bar_diameter=self.bar_diameter,
                           entry=self.entry, guide_end_distance=self.guide_end_distance,
                           guide_height=self.guide_height, points=points)


@memo(maxsize=64)
def _solve(case: EntryCase, points: int, free: bool) -> EntryKinematics:
    return case._solve(points, free)


@dataclass(frozen=True)
class EntryAnalysis(Result):
    """One wheel entry: its case, its kinematics and (guided entries) free entry for comparison."""

    case: EntryCase
    result: EntryKinematics
    free: EntryKinematics | None

    @property
    def label(self) -> str:
        return f"{self.case.wheel}: {self.case.entry}"

    def to_dict(self) -> dict:
        return {"wheel": self.case.wheel, "entry": self.case.entry, "summary": self.result.summary,
                "free_summary": None if self.free is None else self.free.summary}


@dataclass(frozen=True)
class DriveEntry(Result):
    """Entry kinematics of every guided wheel and of the driving wheel."""

    cases: tuple[EntryAnalysis, ...]
    driving_wheel: str

    @property
    def driving(self) -> EntryAnalysis:
        """The driving wheel's entry (its guide if it has one, else free entry)."""
        return next(c for c in self.cases if c.case.wheel == self.driving_wheel)

    @property
    def acceleration_peak(self) -> float:
        """Largest chain acceleration at the driving wheel's entry [m/s²]."""
        return float(self.driving.result.summary["a_abs_max"])

    def to_dict(self) -> dict:
        return {"driving_wheel": self.driving_wheel, "cases": [c.to_dict() for c in self.cases]}


def entry_cases(drive: Drive) -> tuple[EntryCase, ...]:
    """One case per guided wheel (its guide) and free entry of the driving wheel if unguided.

    >>> from chaindrive.drive.project import load_project
    >>> [c.entry for c in entry_cases(load_project("examples/mining_conveyor.toml"))]
    ['tangential']
    """
    om = drive.angular_velocities()
    out = []
    guided = set()
    for g in drive.guides:
        i = drive.wheel_index(g.wheel)
        w = drive.wheels[i]
        guided.add(w.name)
        entry, height = ("guided", g.height) if g.height is not None else (g.kind, None)
        out.append(EntryCase(w.name, drive.pitch, wheel_teeth(w, "a guided entry"), float(om[i]), drive.bar_diameter,
                             entry, g.end_distance, height))
    w = drive.driving_wheel
    if w.name not in guided:
        out.append(EntryCase(w.name, drive.pitch, wheel_teeth(w, "the driving wheel"), float(drive.speed),
                             drive.bar_diameter,
                             "free"))
    return tuple(out)


# the result is not walked again: its cases were checked when built (EntryCase refuses NaN/inf
# fields) and its kinematics by chain_entry's own guard
@finite_guard(check_result=False)
def drive_entry(drive: Drive, *, points: int = 361) -> DriveEntry:
    """Entry kinematics (exact rigid-link model, Dolipiński et al. eqs (1)–(43) corrected).

    Guided entries come with free entry of the same wheel for comparison.
    """
    cases = []
    for c in entry_cases(drive):
        res = c.solve(points=points)
        free = c.solve(points=points, free=True) if c.entry != "free" else None
        cases.append(EntryAnalysis(c, res, free))
    return DriveEntry(tuple(cases), drive.driving_wheel.name)


def entry_checks(entry: DriveEntry) -> tuple[Check, ...]:
    """Speed non-uniformity of every entry (information)."""
    return tuple(Check(f"speed non-uniformity, {c.label}", float(c.result.summary["nonuniformity"]), None, "-",
                       None, "Dolipiński et al.; exact rigid-link model", relation="info", display="%")
                 for c in entry.cases)


# --------------------------------------------------------------------------- declared parts
def _entry_part(ctx: PartContext) -> DriveEntry:
    return drive_entry(ctx.drive, points=ctx.options.get("entry_points", 361))


def _entry_batch(contexts: Sequence[PartContext]) -> list[DriveEntry]:
    """The entry kinematics of many variants, solved once per distinct set of entry cases
    (:func:`drive_entry` reads nothing else of a drive: wheels whose positions differ share
    it); each variant gets that result and its warnings."""
    import warnings

    solved: dict[tuple[Any, ...], tuple[DriveEntry, list[str]]] = {}
    out = []
    for ctx in contexts:
        points = ctx.options.get("entry_points", 361)
        key = (entry_cases(ctx.drive), ctx.drive.driving_wheel.name, points)
        hit = solved.get(key)
        if hit is None:
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always")
                result = drive_entry(ctx.drive, points=points)
            hit = solved[key] = (result, [str(w.message) for w in caught])
        for text in hit[1]:
            ctx.warn(text)
        out.append(hit[0])
    return out


register_part(Part("entry", "Entry kinematics of the driving and the guided wheels", _entry_part,
                   checks=lambda ctx, entry: entry_checks(entry), order=40,
                   section="chaindrive.workflows.sections:entry_section", batch=_entry_batch))


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
