"""Result classes of the entry mechanisms (:mod:`chaindrive.kinematics.solver`) and of the
paper's closed forms (:mod:`chaindrive.kinematics.paper`): the chain's position, velocity
and acceleration over the wheel angles asked for, SI units.

They read as attributes (``r.velocity``) and, for the code written when these functions
returned dicts, as items (``r["velocity"]``).
"""

from __future__ import annotations

import dataclasses
from typing import Any

import numpy as np

from .._results import Result, quantity

__all__ = ["EntryHistory", "PaperEntry", "TautEntry", "RodEntry", "PeriodMotion"]


@dataclasses.dataclass(frozen=True)
class PeriodMotion(Result):
    """The motion of a chain driven by a wheel over one tooth period, what every such result
    has (:class:`~chaindrive.kinematics.EntryKinematics`,
    :class:`~chaindrive.kinematics.crawler.CrawlerKinematics`).

    Attributes
    ----------
    velocity, acceleration : ndarray
        Chain velocity [m/s] and acceleration [m/s²] over the wheel angles.
    summary : dict
        ``v_mean``, ``v_min``, ``v_max`` [m/s], ``nonuniformity`` = (v_max - v_min)/v_mean
        [-], ``a_min``, ``a_max`` [m/s²], ``sign_change_at_period_end`` (bool),
        ``transverse_throw`` [m], and what the subclass adds.
    pitch, radius : float
        Chain pitch ``t`` (``p``) and the wheel's pitch radius ``R`` [m].
    teeth : int
        ``z``.
    angular_velocity : float
        ``ω`` [rad/s].
    period : float
        ``2π/z`` [rad].
    """

    velocity: np.ndarray = quantity("m/s")
    acceleration: np.ndarray = quantity("m/s^2")
    summary: dict
    pitch: float = quantity("m")
    radius: float = quantity("m")
    teeth: int = quantity("1")
    angular_velocity: float = quantity("rad/s")
    period: float = quantity("rad")


@dataclasses.dataclass(frozen=True)
class EntryHistory(Result):
    """Chain displacement ``x`` [m], velocity [m/s] and acceleration [m/s²] over the wheel angles."""

    x: np.ndarray = quantity("m")
    velocity: np.ndarray = quantity("m/s")
    acceleration: np.ndarray = quantity("m/s^2")

    def __getitem__(self, name: str) -> Any:
        """``r["velocity"]`` is ``r.velocity`` (these results were dicts before)."""
        if name not in self.keys():
            raise KeyError(name)
        return getattr(self, name)

    def __contains__(self, name: object) -> bool:
        """A field that holds a value (the dicts held only the keys that applied)."""
        return isinstance(name, str) and name in self.keys() and getattr(self, name) is not None

    def get(self, name: str, default: Any = None) -> Any:
        return getattr(self, name, default) if name in self.keys() else default

    def keys(self) -> tuple[str, ...]:
        return tuple(f.name for f in dataclasses.fields(self))


@dataclasses.dataclass(frozen=True)
class PaperEntry(EntryHistory):
    """One of the paper's closed forms (Dolipiński et al.): :class:`EntryHistory` and

    ``advance`` chain advance per period [m]; free entry: ``y``, ``vy``, ``ay`` the
    transverse position [m], velocity [m/s] and acceleration [m/s²]; chordal entry:
    ``x_printed`` the printed (uncorrected) displacement [m]; tangential entry:
    ``limit_angles`` ``(φ_g1, φ_g2)`` [rad] (``φ_g2`` None for a roller chain); ``seats``
    the seating angles in the period [rad] (set by the entry model).
    """

    advance: float = quantity("m", default=0.0)
    y: np.ndarray | None = quantity("m", default=None)
    vy: np.ndarray | None = quantity("m/s", default=None)
    ay: np.ndarray | None = quantity("m/s^2", default=None)
    x_printed: np.ndarray | None = quantity("m", default=None)
    limit_angles: tuple[float, float | None] | None = quantity("rad", default=None)
    seats: np.ndarray | None = quantity("rad", default=None)


@dataclasses.dataclass(frozen=True)
class TautEntry(EntryHistory):
    """The taut-span mechanism (:func:`~chaindrive.kinematics.solver.taut_entry`): :class:`EntryHistory` and

    ``span`` free span length [m] (guided entry; None for free entry); ``y``, ``vy``,
    ``ay`` height of the seating point [m], its velocity [m/s] and acceleration [m/s²];
    ``k`` the seated vertex at each angle; ``seats`` the seating angles [rad];
    ``advance`` chain advance per period [m] (set by the entry model).
    """

    span: np.ndarray | None = quantity("m", default=None)
    y: np.ndarray | None = quantity("m", default=None)
    vy: np.ndarray | None = quantity("m/s", default=None)
    ay: np.ndarray | None = quantity("m/s^2", default=None)
    k: np.ndarray | None = quantity("1", default=None)
    seats: np.ndarray | None = quantity("rad", default=None)
    advance: float | None = quantity("m", default=None)


@dataclasses.dataclass(frozen=True)
class RodEntry(EntryHistory):
    """The rod (guided) mechanism (:func:`~chaindrive.kinematics.solver.rod_entry`): :class:`EntryHistory` and

    ``advance`` chain advance per period [m]; ``k`` the seated vertex of each interval.
    """

    advance: float = quantity("m", default=0.0)
    k: np.ndarray | None = quantity("1", default=None)
