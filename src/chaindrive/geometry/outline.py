"""Closed 2-D outlines made of lines and circular arcs (the drawing layer of the wheels).

An :class:`Outline` is an ordered list of primitives (:class:`Line`, :class:`Arc`) whose
end points chain up into one closed contour, plus a dense polyline sampled from them
for plotting. All lengths are in metres; angles in radians, counter-clockwise from +x.
Exports (DXF, SVG) live in :mod:`chaindrive.geometry.export`.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from .._finite import finite_guard
from ..errors import InputError
from ..limits import MAX_ARC_POINTS, MAX_PRIMITIVES, MAX_TEETH, check_size

__all__ = ["Line", "Arc", "Outline", "Primitive", "rotate_points", "check_outline_size"]


@finite_guard  # NaN/inf and out-of-range arguments refused (chaindrive._finite)
def rotate_points(points: ArrayLike, angle: float) -> np.ndarray:
    """Rotate ``(..., 2)`` points counter-clockwise about the origin by ``angle`` [rad].

    Examples
    --------
    >>> np.round(rotate_points([1.0, 0.0], np.pi / 2), 12) + 0.0
    array([0., 1.])
    """
    p = np.asarray(points, dtype=float)
    c, s = np.cos(angle), np.sin(angle)
    return np.stack([c * p[..., 0] - s * p[..., 1], s * p[..., 0] + c * p[..., 1]], axis=-1)


def circle_intersections(c1: ArrayLike, r1: float, c2: ArrayLike, r2: float) -> tuple[np.ndarray, np.ndarray] | None:
    """Both points where two circles meet (centres ``c1``, ``c2`` [m], radii [m]); ``None`` if
    they do not meet (or are concentric). The first lies to the left of ``c1 → c2``.

    Internal (no input checks): the tooth outline and the worn-chain seat
    (:mod:`chaindrive.life.jump_over`) share it.

    Examples
    --------
    >>> p, q = circle_intersections((0.0, 0.0), 5.0, (6.0, 0.0), 5.0)
    >>> p.tolist(), q.tolist()
    ([3.0, 4.0], [3.0, -4.0])
    >>> circle_intersections((0.0, 0.0), 1.0, (3.0, 0.0), 1.0) is None
    True
    """
    c1 = np.asarray(c1, float)
    c2 = np.asarray(c2, float)
    d = float(np.hypot(*(c2 - c1)))
    if d > r1 + r2 or d < abs(r1 - r2) or d == 0:
        return None
    a = (r1**2 - r2**2 + d**2) / (2 * d)
    h = np.sqrt(max(r1**2 - a**2, 0.0))
    u = (c2 - c1) / d
    m = c1 + a * u
    nrm = np.array([-u[1], u[0]])
    return m + h * nrm, m - h * nrm


@dataclass(frozen=True)
class Line:
    """Straight segment from ``start`` to ``end`` [m]."""

    start: tuple[float, float]
    end: tuple[float, float]

    @property
    def length(self) -> float:
        return float(np.hypot(self.end[0] - self.start[0], self.end[1] - self.start[1]))

    def sample(self, n: int = 2) -> np.ndarray:
        check_size("points", n, MAX_ARC_POINTS, minimum=0)
        t = np.linspace(0.0, 1.0, max(n, 2))[:, None]
        return (1 - t) * np.asarray(self.start) + t * np.asarray(self.end)

    def rotated(self, angle: float) -> Line:
        return Line(_pair(rotate_points(self.start, angle)), _pair(rotate_points(self.end, angle)))

    def mirrored_x(self) -> Line:
        """Mirror about the y axis (x -> -x) and reverse the direction."""
        return Line((-self.end[0], self.end[1]), (-self.start[0], self.start[1]))

    def reversed(self) -> Line:
        return Line(self.end, self.start)

    @property
    def bulge(self) -> float:
        return 0.0

    def to_dict(self) -> dict[str, Any]:
        return {"type": "line", "start": list(self.start), "end": list(self.end)}


@dataclass(frozen=True)
class Arc:
    """Circular arc: ``center`` [m], ``radius`` [m], from ``start_angle`` sweeping ``sweep`` [rad].

    ``sweep > 0`` runs counter-clockwise, ``sweep < 0`` clockwise.
    """

    center: tuple[float, float]
    radius: float
    start_angle: float
    sweep: float

    @property
    def end_angle(self) -> float:
        return self.start_angle + self.sweep

    @property
    def start(self) -> tuple[float, float]:
        return self._point(self.start_angle)

    @property
    def end(self) -> tuple[float, float]:
        return self._point(self.end_angle)

    def _point(self, a: float) -> tuple[float, float]:
        return (
            float(self.center[0] + self.radius * np.cos(a)),
            float(self.center[1] + self.radius * np.sin(a)),
        )

    @property
    def length(self) -> float:
        return abs(self.sweep) * self.radius

    def sample(self, n: int = 16) -> np.ndarray:
        check_size("points", n, MAX_ARC_POINTS, minimum=0)
        a = np.linspace(self.start_angle, self.end_angle, max(n, 2))
        return np.stack(
            [self.center[0] + self.radius * np.cos(a), self.center[1] + self.radius * np.sin(a)],
            axis=-1,
        )

    def rotated(self, angle: float) -> Arc:
        return Arc(_pair(rotate_points(self.center, angle)), self.radius, self.start_angle + angle, self.sweep)

    def mirrored_x(self) -> Arc:
        """Mirror about the y axis (x -> -x) and reverse the direction."""
        return Arc((-self.center[0], self.center[1]), self.radius, float(np.pi - self.end_angle), self.sweep)

    def reversed(self) -> Arc:
        return Arc(self.center, self.radius, self.end_angle, -self.sweep)

    @property
    def bulge(self) -> float:
        """DXF bulge ``tan(sweep/4)`` (positive counter-clockwise)."""
        return float(np.tan(self.sweep / 4.0))

    def to_dict(self) -> dict[str, Any]:
        return {
            "type": "arc",
            "center": list(self.center),
            "radius": self.radius,
            "start_angle": self.start_angle,
            "sweep": self.sweep,
        }


#: One piece of an outline.
Primitive = Line | Arc


def _pair(point: np.ndarray) -> tuple[float, float]:
    """A point ``(2,)`` as a tuple of two floats (internal)."""
    return float(point[0]), float(point[1])


@dataclass
class Outline:
    """A closed contour of lines and arcs plus reference geometry for drawings.

    Attributes
    ----------
    primitives : list of Line or Arc
        The contour, each primitive starting where the previous one ends [m].
    pitch_radius : float
        Radius of the pitch circle [m] (drawn on layer PITCH_CIRCLE).
    centres : ndarray, shape (n, 2)
        Reference centres [m]: roller seats, pins or pocket centres (layer CENTRES).
    circles : dict
        Further reference circles by layer name -> radius [m] (e.g. ``{"SLOT": r}``).
    """

    primitives: list[Primitive]
    pitch_radius: float
    centres: np.ndarray
    circles: dict[str, float] = field(default_factory=dict)

    def __post_init__(self) -> None:
        check_outline_size(self)

    def polyline(self, points_per_arc: int = 24) -> np.ndarray:
        """Dense closed polyline ``(n, 2)`` [m]; the first point is repeated at the end."""
        check_size("points_per_arc", points_per_arc, MAX_ARC_POINTS, minimum=2)
        check_outline_size(self)
        pts = [self.primitives[0].sample(2)[:1]]
        for prim in self.primitives:
            n = 2 if isinstance(prim, Line) else points_per_arc
            pts.append(prim.sample(n)[1:])
        return np.concatenate(pts, axis=0)

    def closure_gap(self) -> float:
        """Largest distance between the end of one primitive and the start of the next [m]."""
        gaps = [
            np.hypot(a.end[0] - b.start[0], a.end[1] - b.start[1])
            for a, b in zip(self.primitives, self.primitives[1:] + self.primitives[:1], strict=True)
        ]
        return float(max(gaps))

    def extents(self) -> tuple[float, float, float, float]:
        """``(xmin, ymin, xmax, ymax)`` of the contour [m] from a dense sampling."""
        p = self.polyline(180)
        return float(p[:, 0].min()), float(p[:, 1].min()), float(p[:, 0].max()), float(p[:, 1].max())

    def area(self) -> float:
        """Enclosed area [m²] (shoelace formula on the dense polyline; positive if CCW)."""
        p = self.polyline(180)
        return 0.5 * float(np.sum(p[:-1, 0] * p[1:, 1] - p[1:, 0] * p[:-1, 1]))

    def to_dict(self) -> dict[str, Any]:
        return {
            "primitives": [p.to_dict() for p in self.primitives],
            "pitch_radius": self.pitch_radius,
            "centres": np.asarray(self.centres).tolist(),
            "circles": dict(self.circles),
        }


def check_outline_size(outline: Outline, name: str = "outline") -> None:
    """Refuse an outline with more than :data:`chaindrive.limits.MAX_PRIMITIVES` lines and
    arcs, or more reference centres than :data:`chaindrive.limits.MAX_TEETH` (before it is
    sampled, drawn or exported).

    Examples
    --------
    >>> check_outline_size(Outline([Line((0.0, 0.0), (1.0, 0.0))] * 3, 1.0, np.zeros((0, 2))))
    >>> Outline([Line((0.0, 0.0), (1.0, 0.0))] * 300_000, 1.0, np.zeros((0, 2)))
    Traceback (most recent call last):
    ...
    chaindrive.errors.InputError: outline has 300000 lines and arcs; at most 200000 (chaindrive.limits.MAX_PRIMITIVES)
    """
    count = len(outline.primitives)
    if count > MAX_PRIMITIVES:
        raise InputError(f"{name} has {count} lines and arcs; at most {MAX_PRIMITIVES} "
                         "(chaindrive.limits.MAX_PRIMITIVES)", field=name)
    centres = int(np.size(outline.centres)) // 2
    if centres > MAX_TEETH:
        raise InputError(f"{name} has {centres} reference centres; at most {MAX_TEETH} "
                         "(chaindrive.limits.MAX_TEETH)", field=name)


def _repeat(tooth: list[Primitive], count: int) -> list[Primitive]:
    """Copies of one period's primitives rotated by ``2π k / count`` (internal)."""
    check_size("teeth", count, MAX_TEETH)
    if len(tooth) * count > MAX_PRIMITIVES:
        raise InputError(f"an outline of {count} teeth of {len(tooth)} lines and arcs each has more than "
                         f"{MAX_PRIMITIVES} (chaindrive.limits.MAX_PRIMITIVES)", field="teeth")
    out: list[Primitive] = []
    for k in range(count):
        ang = 2.0 * np.pi * k / count
        out.extend(p.rotated(ang) for p in tooth)
    return out


def _drop_short(prims: list[Primitive], tol: float = 1e-12) -> list[Primitive]:
    """Remove zero-length primitives (internal)."""
    return [p for p in prims if p.length > tol]
