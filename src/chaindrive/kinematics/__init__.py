"""Kinematics of a chain entering (or leaving) a wheel: the polygonal effect.

Public API:

* :func:`chain_entry` - free, chordal, tangential or custom-height guided entry of a
  round link chain (bi-regular polygon) or a roller chain (regular polygon), with
  ``model="exact"`` (general rigid-link solver), ``model="paper"`` (Dolipiński et al.'s rod
  mechanism, the same for both guides) or ``model="as_printed"`` (the chordal rod switched at
  ``π/z`` as printed; Dolipiński et al.'s
  corrected closed forms); returns :class:`EntryKinematics`.
* :func:`dolipinski_worked_case` - the three entries of Dolipiński et al.'s worked case.
* :mod:`.paper` - the closed forms, :mod:`.solver` - the general vectorised solver; both
  return :mod:`.histories` result classes (:class:`PaperEntry`, :class:`TautEntry`, :class:`RodEntry`).

See ``docs/kinematics.md``.
"""

from .._deprecation import renamed_attributes as _renamed_attributes
from .entry import (
    ENTRIES,
    MODELS,
    SUMMARY_KEYS,
    EntryKinematics,
    chain_entry,
    chain_entry_for,
    dolipinski_worked_case,
)
from .histories import EntryHistory, PaperEntry, RodEntry, TautEntry
from .paper import (
    paper_chordal_entry,
    paper_free_entry,
    paper_tangential_entry,
    paper_tangential_limit_angles,
)
from .solver import WheelPolygon, rod_entry, rod_seating_schedule, taut_entry, taut_seating_angles

__all__ = [
    "ENTRIES",
    "MODELS",
    "SUMMARY_KEYS",
    "EntryKinematics",
    "EntryHistory",
    "PaperEntry",
    "RodEntry",
    "TautEntry",
    "WheelPolygon",
    "chain_entry",
    "chain_entry_for",
    "paper_chordal_entry",
    "paper_free_entry",
    "paper_tangential_entry",
    "paper_tangential_limit_angles",
    "rod_entry",
    "rod_seating_schedule",
    "dolipinski_worked_case",
    "taut_entry",
    "taut_seating_angles",
]


# former public names (renamed; deprecated, removed in the next release: chaindrive._deprecation)
__getattr__ = _renamed_attributes(
    "chaindrive.kinematics",
    {"seed002_case": "dolipinski_worked_case"})
