r"""General vectorised solver of a chain running onto a polygonal wheel.

Geometry (all cases; sketch)::

                 y
                 ^        guide line y = H         guide end G = (l, H)
                 |   S_prev  S   free span  N        |
                 |     o-----o-------------o--------*====o====o====  chain in the guide
                 |    /       \_  (taut, straight)  |        <- chain moves towards -x
                 |   /  wheel   \                   |
            -----O-----------------------------------+-------> x
                 |  axis, turning counter-clockwise   l
                 |  (top moves to -x) at ω = dφ/dt

* The wheel axis is the origin O; the chain arrives from ``+x`` and moves towards
  ``-x``; the wheel turns counter-clockwise (its top moves towards ``-x``).
* A hinge centre seated on the wheel is a vertex of the pitch polygon (radius ``R``).
  Its position is ``(R sin β, R cos β)``, ``β`` being its angle from the top measured
  towards the incoming chain; ``β = β0 - φ``.
* Vertex ``k`` (any integer) and vertex ``k + 1`` are joined by a link; the link
  lengths and central angles repeat with the period ``2π/z`` (two links, ``t + d`` and
  ``t - d``, for a round link chain; one link ``p`` for a roller chain).
* The guide line is ``y = H``; the guide end is the point ``G = (l, H)``: ``l`` is the
  distance of the guide end from the wheel axis measured along the guide line (from the
  foot of the perpendicular dropped from the axis onto the guide line).

Two mechanisms are solved:

``taut`` (the exact model)
    The free span is a straight segment from the last seated hinge ``S`` to the guide
    end ``G``; the unseated hinges lie on it at their link distances from ``S``; the
    chain wraps over the guide end (a corner of negligible radius) and lies on the guide
    line beyond it. The chain position is the material coordinate of the chain point
    at ``G``: ``x = c_k + |G - S_k|`` (``c_k`` = chain length from hinge 0 to hinge
    ``k``). Hinge ``k + 1`` seats when it reaches the span, i.e. when the chord
    ``S_k → V_{k+1}`` becomes collinear with ``S_k → G``; at that instant the span
    shortens by exactly the seated link, so ``x`` and (rigid-body property of the
    wheel) ``dx/dφ`` are continuous. ``G`` at infinity in direction ``+x`` gives the
    free entry (the span keeps its direction, Dolipiński et al. eqs 1-13).

``rod`` (the paper's simplified model)
    The free span from the seated hinge ``S_k`` to a slider ``P = (X, H)`` on the guide
    line is a rigid rod of given length ``L``; ``x = l - X`` (+ a constant making ``x``
    continuous). The rod length and the hinge it starts from change either at a seating
    event (rod collinear with the next chord; then ``L`` shrinks by that link) or at
    prescribed angles (the paper's chordal case).

Velocity and acceleration follow analytically (implicit differentiation of the
closure), never by numerical differencing.

References
----------
Dolipiński et al. (Dolipiński, Reich, Adamowicz, Ziegler, "Wymuszone nabieganie łańcucha
ogniwowego na koło gniazdowe"), Figs 1, 4, 5 and eqs (1)-(43).
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, cast

import numpy as np
from numpy.typing import ArrayLike

from .._roots import brentq  # scipy.optimize.brentq, bit for bit, without importing scipy.optimize
from .._typing import FloatOrArray
from ..errors import InfeasibleError
from .histories import RodEntry, TautEntry

__all__ = [
    "GuideEnd",
    "RodSchedule",
    "WheelPolygon",
    "taut_seating_angles",
    "taut_entry",
    "rod_entry",
    "rod_seating_schedule",
]

#: Guide end ``G = (l, H)`` [m]: distance along the guide line and height of the guide line.
GuideEnd = tuple[float, float]
#: Rod schedule: ``(φ_start [rad], seated vertex k, rod length L [m])`` per interval.
RodSchedule = list[tuple[float, int, float]]


@dataclass(frozen=True)
class WheelPolygon:
    """Pitch polygon of a chain seated on a wheel, with its phase.

    Parameters
    ----------
    radius : float
        Pitch radius ``R`` [m].
    links : tuple of float
        Lengths of the links following vertex 0 towards the incoming chain, one
        period (``(t - d, t + d)`` or ``(t + d, t - d)``, or ``(p,)``) [m].
    angles : tuple of float
        Central angles of those links [rad]; they sum to ``2π/z``.
    phase : float
        Angle ``β0`` of vertex 0 from the top (towards the incoming chain) at ``φ = 0``
        [rad].

    Notes
    -----
    Vertex ``k = q n + r`` (``n`` links per period) is at
    ``β_k = β0 + q·2π/z + Σ_{j<r} δ_j`` and at chain coordinate
    ``c_k = q·Σ links + Σ_{j<r} links_j``:

    .. math:: β_k(φ) = β_k(0) - φ

    References
    ----------
    Dolipiński et al., Fig. 1 and eqs (6)-(9) (bi-regular polygon).

    Examples
    --------
    >>> poly = WheelPolygon(1.0, (0.5, 0.3), (0.5, 0.3), 0.25)
    >>> [round(float(b), 6) for b in poly.vertex([0, 1, 2, -1])[0]]
    [0.25, 0.75, 1.05, -0.05]
    >>> round(poly.period, 6), round(poly.advance, 6)
    (0.8, 0.8)
    """

    radius: float
    links: tuple[float, ...]
    angles: tuple[float, ...]
    phase: float

    @functools.cached_property
    def period(self) -> float:
        """Angular period ``2π/z`` [rad] (kept on the polygon: its fields are frozen)."""
        return float(sum(self.angles))

    @functools.cached_property
    def advance(self) -> float:
        """Chain length per period (``2t`` or ``p``) [m] (kept on the polygon)."""
        return float(sum(self.links))

    def _cum(self) -> tuple[np.ndarray, np.ndarray]:
        try:
            return _cumulative(self.angles, self.links)
        except TypeError:  # links or angles given as a list: not kept
            return _cumulative.__wrapped__(self.angles, self.links)

    def vertex(self, k: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
        """Angle ``β_k`` at ``φ = 0`` [rad] and material coordinate ``c_k`` [m] of vertex ``k``."""
        n = len(self.links)
        q, r = np.divmod(np.asarray(k), n)
        ca, cl = self._cum()
        return self.phase + q * self.period + ca[r], q * self.advance + cl[r]

    def link_after(self, k: int) -> float:
        """Length of the link from vertex ``k`` to vertex ``k + 1`` [m]."""
        return self.links[k % len(self.links)]

    def angle_after(self, k: int) -> float:
        """Central angle of the link from vertex ``k`` to ``k + 1`` [rad]."""
        return self.angles[k % len(self.angles)]


@functools.lru_cache(maxsize=64)
def _cumulative(angles: tuple[float, ...], links: tuple[float, ...]) -> tuple[np.ndarray, np.ndarray]:
    # WheelPolygon._cum: the cumulative angles and links from vertex 0, once per polygon (read only)
    ca = np.concatenate(([0.0], np.cumsum(angles)))
    cl = np.concatenate(([0.0], np.cumsum(links)))
    ca.flags.writeable = cl.flags.writeable = False
    return ca, cl


def _pos(radius: float, beta: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    return radius * np.sin(beta), radius * np.cos(beta)


def _taut_gap(poly: WheelPolygon, k: int, phi: np.ndarray, guide: GuideEnd | None,
              angles: tuple[Any, Any] | None = None) -> np.ndarray:
    """Cross product (N - S) x (G - S): > 0 while vertex k+1 is inside the span line;
    ``angles``: ``poly.vertex(k)[0], poly.vertex(k + 1)[0]`` when the caller has them."""
    b0, b1 = (poly.vertex(k)[0], poly.vertex(k + 1)[0]) if angles is None else angles
    if type(phi) is float:  # a root search's point: Python floats (math.sin and cos round as numpy's)
        return _taut_gap_float(float(poly.radius), float(b0) - phi, float(b1) - phi, guide)  # type: ignore[return-value]
    sx, sy = _pos(poly.radius, b0 - phi)
    nx, ny = _pos(poly.radius, b1 - phi)
    wx: FloatOrArray
    wy: FloatOrArray
    if guide is None:  # free entry: span direction +x
        wx, wy = 1.0, 0.0
    else:
        wx, wy = guide[0] - sx, guide[1] - sy
    return (nx - sx) * wy - (ny - sy) * wx


def _taut_gap_float(R: float, a0: float, a1: float, guide: GuideEnd | None) -> float:
    """:func:`_taut_gap` at one angle in Python floats (the same operations), ``a0``, ``a1`` the
    angles of the two vertices at it."""
    sx, sy, nx, ny = R * math.sin(a0), R * math.cos(a0), R * math.sin(a1), R * math.cos(a1)
    if guide is None:
        return (nx - sx) * 0.0 - (ny - sy) * 1.0
    return (nx - sx) * (guide[1] - sy) - (ny - sy) * (guide[0] - sx)


def _find_crossing(fun: Callable[[Any], Any], estimate: float, what: str) -> float:
    """Root of ``fun`` where it goes from + to -, nearest to ``estimate``.

    Bracketed on a 1441-point scan of ``estimate ± π/2``; the scan starts with the
    points about the estimate (``2 w + 1`` of them, ``w`` in :data:`_SCAN_WINDOWS`) and
    widens only when a crossing outside them could be as near (``fun`` is pointwise: the
    same values, the same bracket)."""
    grid = estimate + _SCAN
    centre = 720
    for window in _SCAN_WINDOWS:
        lo, hi = centre - window, centre + window + 1
        g = fun(grid[lo:hi])
        idx = ((g[:-1] > 0) & (g[1:] <= 0)).nonzero()[0] + lo
        if idx.size:
            dist = np.abs(grid[idx] - estimate)
            k = int(np.argmin(dist))
            # a crossing not seen starts at index lo - 1 or below, or hi - 1 or above
            if dist[k] < min(abs(grid[lo - 1] - estimate), abs(grid[hi - 1] - estimate)):
                i = int(idx[k])
                if g[i + 1 - lo] == 0.0:
                    return float(grid[i + 1])
                return float(brentq(fun, grid[i], grid[i + 1], xtol=1e-15, rtol=1e-15, maxiter=200))
    g = fun(grid)
    idx = ((g[:-1] > 0) & (g[1:] <= 0)).nonzero()[0]
    if idx.size == 0:
        raise InfeasibleError(f"no seating of {what} found: the span never reaches the next hinge")
    i = idx[np.argmin(np.abs(grid[idx] - estimate))]
    if g[i + 1] == 0.0:
        return float(grid[i + 1])
    return float(brentq(fun, grid[i], grid[i + 1], xtol=1e-15, rtol=1e-15, maxiter=200))


#: Points either side of the estimate that :func:`_find_crossing` scans first, then next (of 720).
_SCAN_WINDOWS = (24, 180)
#: The offsets of :func:`_find_crossing`'s scan from its estimate [rad] (read only).
_SCAN = np.linspace(-0.5 * np.pi, 0.5 * np.pi, 1441)
_SCAN.flags.writeable = False


def taut_seating_angles(poly: WheelPolygon, guide: GuideEnd | None = None) -> np.ndarray:
    """Wheel angles at which vertices 0..n seat (taut span to ``guide``, or free entry).

    Parameters
    ----------
    poly : WheelPolygon
        Pitch polygon and phase.
    guide : tuple (l, H) or None
        Guide end ``G`` [m]; ``None`` for free entry (span direction ``+x``).

    Returns
    -------
    ndarray, shape (n + 1,)
        ``φ_k`` [rad]; vertex ``k`` is the last seated hinge for ``φ_k <= φ < φ_{k+1}``;
        ``φ_n = φ_0 + 2π/z``.

    Raises
    ------
    InfeasibleError
        Guide end inside the pitch circle, no seating found, or seatings out of order.

    Notes
    -----
    Root of ``g(φ) = (V_{k+1} - S_k) × (G - S_k)`` where it changes from + (hinge
    outside the span line) to -, bracketed on a 1441-point scan of ``±π/2`` around the
    estimate "link symmetric about the tangent point seen from ``G``", refined by
    Brent's method to ``1e-15`` rad. Valid for ``|G| > R``. Free entry: the estimate
    itself (the link level).

    .. math:: (V_{k+1} - S_k) \times (G - S_k) = 0

    References
    ----------
    Dolipiński et al., eqs (27)-(29) and (32)-(34) (the same condition for the rod mechanism).

    Examples
    --------
    Free entry of a roller chain: a hinge seats when the link before it is horizontal.

    >>> poly = WheelPolygon(1.0, (2 * np.sin(np.pi / 8),), (np.pi / 4,), np.pi / 8)
    >>> np.round(taut_seating_angles(poly), 12)
    array([0.      , 0.785398])
    """
    n = len(poly.links)
    out = np.empty(n + 1)
    if guide is None:
        beta_t = 0.0  # free entry: the span touches the circle at the top
    else:
        rho = float(np.hypot(guide[0], guide[1]))
        if rho <= poly.radius:
            raise InfeasibleError("the guide end lies inside the pitch circle")
        # tangent point of the span seen from G (chain wrapping counter-clockwise)
        beta_t = float(np.arctan2(guide[0], guide[1]) - np.arccos(poly.radius / rho))
    for j in range(n):
        b_prev, _ = poly.vertex(j - 1)
        b_j, _ = poly.vertex(j)
        # estimate: link (j-1, j) symmetric about the tangent point
        est = float(0.5 * (b_j + b_prev) - beta_t)

        def gap(p: np.ndarray, j: int = j, angles: tuple[Any, Any] = (b_prev, b_j)) -> np.ndarray:
            return _taut_gap(poly, j - 1, p, guide, angles)

        # free entry: the seating is the estimate itself (the link (j-1, j) level, its ends at
        # equal heights R cos(±(b_j - b_prev)/2): the root of the gap in closed form)
        out[j] = est if guide is None else _find_crossing(gap, est, f"hinge {j}")
    out[n] = out[0] + poly.period
    if any(b <= a for a, b in zip(out.tolist(), out[1:].tolist(), strict=False)):  # np.any(np.diff(out) <= 0)
        raise InfeasibleError("seating angles are not increasing: the span cuts the wheel")
    return out


def _locate(poly: WheelPolygon, seats: np.ndarray, phi: np.ndarray,
            index: bool = True) -> tuple[np.ndarray | None, np.ndarray, np.ndarray]:
    """Index k of the last seated vertex and its β at φ = 0 and c_k (vectorised); ``index=False``:
    ``None`` for k (β and c alone).

    ``k = q n + j`` with ``0 <= j < n``, so ``poly.vertex(k)`` is ``(β0 + q T + Σδ_{<j}, q a + Σlinks_{<j})``
    from ``q`` and ``j`` directly (the same operations: ``q`` is a whole number as a float)."""
    n = len(poly.links)
    T = poly.period
    q = np.floor((phi - seats[0]) / T)
    r = phi - q * T
    if n > 1:
        j = np.minimum(np.maximum(seats[:n].searchsorted(r, side="right") - 1, 0), n - 1)  # np.clip(j, 0, n - 1)
    else:  # one link a period: always the first
        j = np.zeros(np.shape(r), dtype=np.intp)
    ca, cl = poly._cum()
    beta0 = poly.phase + q * T + ca[j]
    c = q * poly.advance + cl[j]
    return ((q * n + j).astype(np.int64) if index else None), beta0, c


def taut_entry(
    poly: WheelPolygon,
    phi: ArrayLike,
    angular_velocity: float,
    guide: GuideEnd | None = None,
    seats: np.ndarray | None = None,
) -> TautEntry:
    r"""Position, velocity and acceleration of the chain for the taut-span mechanism.

    .. math::
        x = c_k + |G - S_k(φ)| - x_0,\quad
        \frac{dx}{dφ} = -u\cdot S_φ,\quad
        \frac{d^2x}{dφ^2} = \frac{R^2 - (u\cdot S_φ)^2}{|G - S|} + u\cdot S

    with ``u = (G - S)/|G - S|``, ``S_φ = dS/dφ``, ``S_φφ = -S``; for free entry
    (``guide=None``) ``u = (1, 0)`` and the first term vanishes.

    Parameters
    ----------
    poly : WheelPolygon
        Pitch polygon and phase.
    phi : array_like
        Wheel angles ``φ`` [rad].
    angular_velocity : float
        ``ω`` [rad/s].
    guide : tuple (l, H) or None
        Guide end [m]; ``None`` = free entry.
    seats : ndarray, optional
        Seating angles from :func:`taut_seating_angles` (computed if omitted).

    Returns
    -------
    dict
        ``x`` [m], ``velocity`` [m/s], ``acceleration`` [m/s²] (along the chain, positive
        towards the wheel), ``y``, ``vy``, ``ay`` (transverse motion of the last seated
        hinge, [m], [m/s], [m/s²]), ``k`` (last seated vertex), ``seats``.

    Examples
    --------
    >>> poly = WheelPolygon(1.0, (2 * np.sin(np.pi / 8),), (np.pi / 4,), np.pi / 8)
    >>> r = taut_entry(poly, [0.0, np.pi / 8], 1.0)
    >>> np.round(r["velocity"], 6)
    array([0.92388, 1.     ])
    """
    phi = np.asarray(phi, dtype=float)
    if seats is None:
        seats = taut_seating_angles(poly, guide)
    R = poly.radius
    w = angular_velocity
    # the angles asked for and φ = 0 (the origin of x) in one pass (a pointwise computation:
    # the same numbers as two)
    both = np.append(phi, 0.0)
    k_or_none, b0, c = _locate(poly, seats, both)
    k = cast(np.ndarray, k_or_none)
    beta = b0 - both
    sb, cb = np.sin(beta), np.cos(beta)
    sx, sy = R * sb, R * cb
    shape = phi.shape
    if guide is None:
        m0 = float(c[-1] - sx[-1])
        m = c[:-1] - sx[:-1]
        dm = R * cb[:-1]  # -dS_x/dφ
        ddm = sx[:-1]
        span = None
    else:
        gx, gy = guide
        wx, wy = gx - sx, gy - sy
        D = np.hypot(wx, wy)
        m0 = float(c[-1] + D[-1])
        sx, sy, sb, cb, wx, wy, D = sx[:-1], sy[:-1], sb[:-1], cb[:-1], wx[:-1], wy[:-1], D[:-1]
        ux, uy = wx / D, wy / D
        us = ux * (-R * cb) + uy * (R * sb)  # u · dS/dφ
        m = c[:-1] + D
        dm = -us
        ddm = (R * R - us * us) / D + (ux * sx + uy * sy)
        span = D.reshape(shape)
    sy = sy[:-1] if guide is None else sy
    return TautEntry(x=(m - m0).reshape(shape), velocity=(w * dm).reshape(shape),
                     acceleration=(w * w * ddm).reshape(shape), span=span, y=sy.reshape(shape),
                     vy=(w * (R * sb[:-1] if guide is None else R * sb)).reshape(shape),
                     ay=(-w * w * sy).reshape(shape), k=k[:-1].reshape(shape), seats=seats)


def _taut_rates(poly: WheelPolygon, phi: np.ndarray, angular_velocity: float, guide: GuideEnd | None,
                seats: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``velocity``, ``acceleration`` and ``y`` of :func:`taut_entry` alone (the same operations,
    pointwise: the same numbers) at the wheel angles ``phi`` (a 1-d array), for the summary's
    extremes over its period grid."""
    _, b0, c = _locate(poly, seats, phi, index=False)
    beta = b0 - phi
    R = poly.radius
    w = angular_velocity
    sb, cb = np.sin(beta), np.cos(beta)
    sx, sy = R * sb, R * cb
    if guide is None:
        dm = R * cb
        ddm = sx
    else:
        gx, gy = guide
        wx, wy = gx - sx, gy - sy
        D = np.hypot(wx, wy)
        ux, uy = wx / D, wy / D
        us = ux * (-R * cb) + uy * (R * sb)
        dm = -us
        ddm = (R * R - us * us) / D + (ux * sx + uy * sy)
    return w * dm, w * w * ddm, sy


def _taut_motion(R: float, beta: Any, guide: GuideEnd | None) -> tuple[Any, Any, Any, Any, Any]:
    r"""The chain's motion per unit wheel speed at the seated hinge's angle ``beta`` (floats, or
    arrays): ``dx/dφ``, ``d²x/dφ²``, ``d³x/dφ³`` [m/rad^k], the hinge's height ``y`` and ``dy/dφ`` [m].

    ``d³x/dφ³`` differentiates :func:`taut_entry`'s ``d²x/dφ²`` once more (``u_φ = (-S_φ + u (u·S_φ))/|G - S|``,
    ``S_φ·S = 0``, ``|S_φ| = R``):

    .. math:: \frac{d^3x}{dφ^3} = (u\cdot S_φ)\Bigl(\frac{2 x''}{|G - S|} + \frac{R^2 - (u\cdot S_φ)^2}{|G - S|^2}
              + \frac{u\cdot S}{|G - S|} + 1\Bigr)

    (free entry: ``-dx/dφ``); tested against finite differences."""
    if isinstance(beta, float):
        sb, cb = math.sin(beta), math.cos(beta)
    else:
        sb, cb = np.sin(beta), np.cos(beta)
    sx, sy = R * sb, R * cb
    if guide is None:
        return R * cb, sx, -R * cb, sy, sx
    wx, wy = guide[0] - sx, guide[1] - sy
    D = math.hypot(wx, wy) if isinstance(beta, float) else np.hypot(wx, wy)
    ux, uy = wx / D, wy / D
    us = ux * (-R * cb) + uy * (R * sb)
    us_s = ux * sx + uy * sy
    ddm = (R * R - us * us) / D + us_s
    return -us, ddm, us * (2.0 * ddm / D + (R * R - us * us) / (D * D) + us_s / D + 1.0), sy, sx


_UNIT_33 = np.linspace(0.0, 1.0, 33)  # _taut_extremes' default samples of a stretch (read only)
_UNIT_33.flags.writeable = False


def _taut_extremes(poly: WheelPolygon, guide: GuideEnd | None, seats: np.ndarray,
                  points: int = 33) -> tuple[tuple[float, float], ...]:
    r"""Smallest and largest chain speed, acceleration (per unit wheel speed: ``dx/dφ`` [m/rad],
    ``d²x/dφ²`` [m/rad²]) and seated hinge's height ``y`` [m] over one period of :func:`taut_entry`.

    Each stretch between seatings is smooth: its extremes are at its ends (the one-sided
    limits at the seatings) or where its derivative vanishes. The derivative is sampled
    at ``points`` angles per stretch; each sign change that could hold an extreme is refined
    by Brent's method on the analytic derivative (:func:`_taut_motion`) to ``1e-11`` rad (the
    value, flat there, to ~1e-22 of itself).

    .. math:: rac{d}{dφ}rac{dx}{dφ} = 0,\qquad rac{d}{dφ}rac{d^2x}{dφ^2} = 0,\qquad
              rac{dy}{dφ} = R\sin β = 0

    Returns
    -------
    tuple
        ``((v_min, v_max), (a_min, a_max), (y_min, y_max))``, ``v`` per ``ω``, ``a`` per ``ω²``.

    Examples
    --------
    Free entry of a roller chain on 12 teeth: ``R cos(π/z) <= dx/dφ <= R``.

    >>> poly = WheelPolygon(1.0, (2 * np.sin(np.pi / 12),), (np.pi / 6,), np.pi / 12)
    >>> (v_lo, v_hi), _, _ = _taut_extremes(poly, None, taut_seating_angles(poly))
    >>> round(v_lo, 9) == round(math.cos(math.pi / 12), 9), v_hi
    (True, 1.0)
    """
    R = float(poly.radius)
    lo, hi = seats[:-1], seats[1:]
    # each stretch with its own seated hinge (located at its middle), ends included: there the
    # one-sided limits
    _, b0, _ = _locate(poly, seats, 0.5 * (lo + hi), index=False)
    unit = _UNIT_33 if points == 33 else np.linspace(0.0, 1.0, int(points))
    phi = lo[:, None] + (hi - lo)[:, None] * unit[None, :]  # (n, points)
    b0 = b0[:, None] + np.zeros(phi.shape)  # each stretch's (+ 0.0: the same numbers)
    motion = _taut_motion(R, b0 - phi, guide)
    out = []
    for f, g, which in ((motion[0], motion[1], 0), (motion[1], motion[2], 1), (motion[3], motion[4], 3)):
        low, high = float(np.minimum.reduce(f, axis=None)), float(np.maximum.reduce(f, axis=None))
        rows, cols = (g[:, :-1] * g[:, 1:] < 0).nonzero()
        for r, c in zip(rows.tolist(), cols.tolist(), strict=True):
            f0, f1, g0, g1 = float(f[r, c]), float(f[r, c + 1]), float(g[r, c]), float(g[r, c + 1])
            # within the step f moves less than twice the step times the larger |f'| at its ends
            reach = 2.0 * float(phi[r, c + 1] - phi[r, c]) * max(abs(g0), abs(g1))
            if (g0 > 0 and max(f0, f1) + reach < high) or (g0 < 0 and min(f0, f1) - reach > low):
                continue  # a local extreme that cannot be the period's
            beta0 = float(b0[r, c])

            def slope(x: float, beta0: float = beta0, which: int = which) -> float:
                return _taut_motion(R, beta0 - x, guide)[which + 1]

            # at an extreme the value is flat: 1e-11 rad off moves it by ~1e-22 of itself
            x = brentq(slope, float(phi[r, c]), float(phi[r, c + 1]), xtol=1e-11)
            value = float(_taut_motion(R, beta0 - x, guide)[which])
            low, high = min(low, value), max(high, value)
        out.append((low, high))
    return tuple(out)


def _taut_span_length(poly: WheelPolygon, phi: np.ndarray, guide: GuideEnd, seats: np.ndarray) -> np.ndarray:
    """``taut_entry(poly, phi, ω, guide, seats).span`` alone (the same operations): the free span
    length ``|G - S|`` [m] at the wheel angles ``phi`` (a 1-d array)."""
    _, b0, c = _locate(poly, seats, phi, index=False)
    beta = b0 - phi
    R = poly.radius
    return np.hypot(guide[0] - R * np.sin(beta), guide[1] - R * np.cos(beta))


# ----------------------------------------------------------------------------- rod model


def _rod_slider(
    R: float, beta: np.ndarray, H: float, L: FloatOrArray
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    sx, sy = R * np.sin(beta), R * np.cos(beta)
    h = H - sy
    disc = L * L - h * h
    return sx, sy, h, disc


def rod_seating_schedule(poly: WheelPolygon, guide: GuideEnd, n_events: int | None = None) -> RodSchedule:
    """Event-driven rod schedule: the rod starts at vertex 0 with length ``|G - V_0(0)|``.

    At ``φ = 0`` the slider is at the guide end; vertex ``k + 1`` seats when the rod
    from vertex ``k`` is collinear with the chord to it; the rod then shrinks by that
    link. Returns a list of ``(φ_start, k, L)`` covering ``[0, 2π/z)``.

    Parameters
    ----------
    poly : WheelPolygon
        Pitch polygon and phase (vertex 0 is the seated hinge at ``φ = 0``).
    guide : tuple (l, H)
        Guide end [m].
    n_events : int, optional
        Number of seatings in the period (default: one per link).

    Returns
    -------
    list of tuple
        ``(φ_start [rad], vertex k, rod length L [m])``.

    Examples
    --------
    >>> poly = WheelPolygon(1.0, (2 * np.sin(np.pi / 8),), (np.pi / 4,), 0.0)
    >>> [(round(p, 6), k, round(L, 6)) for p, k, L in rod_seating_schedule(poly, (5.0, 1.0))]
    [(0.0, 0, 5.0), (0.409213, 1, 4.234633)]
    """
    R = poly.radius
    gx, gy = guide
    b0, _ = poly.vertex(0)
    L = float(np.hypot(gx - R * np.sin(b0), gy - R * np.cos(b0)))
    sched: RodSchedule = [(0.0, 0, L)]
    n = len(poly.links) if n_events is None else n_events
    start = 0.0
    for k in range(n):
        bk, _ = poly.vertex(k)
        bn, _ = poly.vertex(k + 1)

        def gap(ph: np.ndarray, bk: np.ndarray = bk, bn: np.ndarray = bn, L: float = L) -> np.ndarray:
            sx, sy, h, disc = _rod_slider(R, bk - ph, gy, L)
            px = sx + np.sqrt(np.maximum(disc, 0.0))
            nx, ny = R * np.sin(bn - ph), R * np.cos(bn - ph)
            return (nx - sx) * h - (ny - sy) * (px - sx)

        est = float(bk) + 0.5 * poly.angle_after(k)  # free-entry estimate: chord horizontal
        phe = _find_crossing(gap, est, f"hinge {k + 1}")
        if phe <= start or phe >= poly.period:
            break
        L = float(L - poly.link_after(k))
        if L <= 0:
            raise InfeasibleError("rod length became non-positive: guide end too close")
        sched.append((float(phe), k + 1, L))
        start = phe
    return sched


def rod_entry(
    poly: WheelPolygon,
    phi: ArrayLike,
    angular_velocity: float,
    guide: GuideEnd,
    schedule: RodSchedule,
    continuous: bool = True,
) -> RodEntry:
    r"""Position, velocity and acceleration for the rod (slider) mechanism.

    Closure ``F(X, φ) = (X - S_x)^2 + (H - S_y)^2 - L^2 = 0`` solved for the slider
    abscissa ``X > S_x``; with ``e = X - S_x``, ``h = H - S_y``:

    .. math::
        e\,e_φ = h\,S_{φ,y},\qquad
        e_φφ = \frac{h S_{φφ,y} - S_{φ,y}^2 - e_φ^2}{e},\qquad
        x = l - X,\ \frac{dx}{dφ} = -(S_{φ,x} + e_φ),\
        \frac{d^2x}{dφ^2} = -(S_{φφ,x} + e_φφ)

    Parameters
    ----------
    poly : WheelPolygon
        Pitch polygon and phase.
    phi : array_like
        Wheel angles [rad]; any range (the schedule repeats every period).
    angular_velocity : float
        ``ω`` [rad/s].
    guide : tuple (l, H)
        Guide end [m].
    schedule : list of (φ_start, k, L)
        Intervals of one period ``[0, 2π/z)``; ``k`` the seated vertex, ``L`` the rod.
    continuous : bool
        Add constants so that ``x`` is continuous (the paper's chordal case resets the
        rod, which would otherwise make ``x`` jump).

    Returns
    -------
    dict
        ``x`` [m], ``velocity`` [m/s], ``acceleration`` [m/s²], ``advance`` (chain
        advance per period [m]), ``k``.

    Examples
    --------
    >>> poly = WheelPolygon(1.0, (2 * np.sin(np.pi / 8),), (np.pi / 4,), 0.0)
    >>> r = rod_entry(poly, [0.0], 1.0, (5.0, 1.0), [(0.0, 0, 5.0)])
    >>> round(float(r["velocity"][0]), 12)
    1.0
    """
    phi = np.asarray(phi, dtype=float)
    R = poly.radius
    gx, H = guide
    T = poly.period
    starts = np.array([s[0] for s in schedule])
    ks = np.array([s[1] for s in schedule])
    Ls = np.array([s[2] for s in schedule], dtype=float)
    b0s, _ = poly.vertex(ks)

    def slider(j: int, ph: np.ndarray) -> np.ndarray:
        beta = b0s[j] - ph
        sx, sy, h, disc = _rod_slider(R, beta, H, Ls[j])
        if np.any(disc <= 0):
            raise InfeasibleError(
                "guide_end_distance too small: the rod cannot reach the guide line"
            )
        return sx + np.sqrt(disc)

    # offsets making x continuous at every switch (zero for event-driven switches)
    offs = np.zeros(len(schedule))
    x_start = gx - slider(0, np.array(0.0))
    for j in range(1, len(schedule)):
        p = np.array(starts[j])
        old = gx - slider(j - 1, p) + offs[j - 1]
        new = gx - slider(j, p)
        offs[j] = (old - new) if continuous else 0.0
    advance = float(gx - slider(len(schedule) - 1, np.array(T)) + offs[-1] - x_start)

    q = np.floor(phi / T)
    r = phi - q * T
    interval = np.clip(np.searchsorted(starts, r, side="right") - 1, 0, len(schedule) - 1)
    beta = b0s[interval] - r
    sb, cb = np.sin(beta), np.cos(beta)
    sx, sy = R * sb, R * cb
    spx, spy = -R * cb, R * sb
    sppx, sppy = -sx, -sy
    h = H - sy
    disc = Ls[interval] ** 2 - h * h
    if np.any(disc <= 0):
        raise InfeasibleError("guide_end_distance too small: the rod cannot reach the guide line")
    e = np.sqrt(disc)
    e1 = h * spy / e
    e2 = (h * sppy - spy * spy - e1 * e1) / e
    x = gx - (sx + e) + offs[interval] - x_start + q * advance
    w = angular_velocity
    return RodEntry(x=x, velocity=-w * (spx + e1), acceleration=-w * w * (sppx + e2), advance=advance,
                    k=ks[interval])
