r"""Perimeter of the convex hull of two separated convex polygons by their two bridges
(internal; the fast path of :func:`chaindrive.layout.two_wheels._hull_perimeters`).

For two convex counter-clockwise polygons ``P1`` (left) and ``P2`` (right) whose
circumscribed circles do not meet, the boundary of ``hull(P1 ∪ P2)`` is: the upper
bridge (a segment from a vertex of ``P2`` to a vertex of ``P1``, both on one supporting
line), the edges of ``P1`` from that vertex round its far side to the lower bridge's
vertex, the lower bridge, and the edges of ``P2`` back to the upper bridge. So

.. math:: L = \sum_{P_1\ \text{arc}} |e| + |b_l| + \sum_{P_2\ \text{arc}} |e| + |b_u|

which is the same number as Cauchy's support-function integral of
:func:`~chaindrive.layout.two_wheels._hull_perimeters` up to rounding (tested to
1e-13 against it and against Qhull). Each bridge is found by a fixed-point iteration on
its outward normal ``ν``: the vertices of both polygons extreme in the direction ``ν``
(the first estimate: the normal of the common tangent of the circumscribed circles,
``cos ν = (R1 - R2)/a``) give a segment; its normal is the next ``ν``; the iteration
stops when both extreme vertices stay the same, which makes the segment a common
supporting line of both polygons, i.e. a bridge. Pairs that did not settle in a few
steps are returned as NaN (the caller computes them by the integral).

References
----------
Preparata, F. P. & Shamos, M. I., Computational Geometry: An Introduction (Springer
1985), section 3.3.5 (merging two convex hulls by their two bridges, the "upper and
lower supporting lines").
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

__all__ = ["bridge_perimeters", "edge_sums", "pair_root"]

#: Fixed-point steps allowed per bridge (two or three settle it for chain wheels).
MAX_STEPS = 8


def edge_sums(vertices: np.ndarray) -> np.ndarray:
    """Cumulative edge lengths of each polygon: (rows, n, 2) -> (rows, n + 1), from vertex 0 [m]."""
    d = np.concatenate([vertices[:, 1:, :], vertices[:, :1, :]], axis=1) - vertices
    out = np.zeros((vertices.shape[0], vertices.shape[1] + 1))
    np.cumsum(np.hypot(d[..., 0], d[..., 1]), axis=1, out=out[:, 1:])
    return out


def bridge_perimeters(v1: np.ndarray, v2: np.ndarray, cum1: np.ndarray, cum2: np.ndarray,
                      r1: float, r2: float, a: float, *, vertices: bool = False,
                      regular: tuple[np.ndarray, int, np.ndarray, int] | None = None) -> Any:
    """Hull perimeter of every pair: ``v1`` (A, n1, 2) round the origin, ``v2`` (B, n2, 2)
    round ``(a, 0)``, ``cum1``, ``cum2`` their :func:`edge_sums`, ``r1``, ``r2`` the largest
    vertex radii, ``a > r1 + r2``. Returns (A, B) [m]; NaN where a bridge did not settle.
    With ``vertices``: also the bridges' vertices, ``k1``, ``k2`` of shape (2, A, B)
    (upper, lower). ``regular``: ``(phases_1, z1, phases_2, z2)`` when both are regular
    polygons with vertex ``k`` at ``phase + 2πk/z`` on their circles: the vertex extreme in a
    direction is then the one whose angle is nearest (no search over the vertices)."""
    A, n1 = v1.shape[:2]
    B, n2 = v2.shape[:2]
    x1, y1 = v1[..., 0], v1[..., 1]               # (A, n1)
    x2, y2 = v2[..., 0], v2[..., 1]               # (B, n2)
    nu0 = math.acos((r1 - r2) / a)
    # both bridges at once: index 0 upper (normal in (0, π)), 1 lower; shape (2, A, B)
    nu = np.empty((2, A, B))
    nu[0], nu[1] = nu0, -nu0
    rows1 = np.arange(A)[None, :, None]
    rows2 = np.arange(B)[None, None, :]
    # the vertices gathered by flat indices (row r, vertex k at r n + k: the same elements as x[rows, k])
    x1f, y1f, x2f, y2f = x1.ravel(), y1.ravel(), x2.ravel(), y2.ravel()
    base1, base2 = rows1 * n1, rows2 * n2
    k1: Any = None
    k2: Any = None
    settled = np.zeros((2, A, B), dtype=bool)
    if regular is not None:
        ph1, z1, ph2, z2 = regular
        f1, f2 = z1 / (2 * math.pi), z2 / (2 * math.pi)
        ph1, ph2 = np.asarray(ph1, dtype=float)[None, :, None], np.asarray(ph2, dtype=float)[None, None, :]
    for _ in range(MAX_STEPS):
        if regular is not None:
            n_k1 = np.rint((nu - ph1) * f1).astype(np.intp) % z1
            n_k2 = np.rint((nu - ph2) * f2).astype(np.intp) % z2
        else:
            c, s = np.cos(nu), np.sin(nu)
            n_k1 = np.argmax(x1[None, :, None, :] * c[..., None] + y1[None, :, None, :] * s[..., None], axis=-1)
            n_k2 = np.argmax(x2[None, None, :, :] * c[..., None] + y2[None, None, :, :] * s[..., None], axis=-1)
        if k1 is not None:
            settled = (n_k1 == k1) & (n_k2 == k2)
            if settled.all():
                break
        k1, k2 = n_k1, n_k2
        i1, i2 = base1 + k1, base2 + k2
        wx = x2f[i2] - x1f[i1]
        wy = y2f[i2] - y1f[i1]
        # outward normal: the upper bridge runs from P2 to P1 (-w), the lower from P1 to P2 (w)
        nu = np.empty(wx.shape)
        nu[0] = np.arctan2(wx[0], -wy[0])
        nu[1] = np.arctan2(-wx[1], wy[1])
    bridges = np.hypot(wx, wy).sum(axis=0)
    own1 = cum1[:, -1][:, None]
    own2 = cum2[:, -1][None, :]
    # P1 from the upper bridge's vertex on to the lower's, P2 from the lower's on to the upper's
    arc1 = cum1[rows1[0], k1[1]] - cum1[rows1[0], k1[0]]
    arc1 = np.where(arc1 < 0, arc1 + own1, arc1)
    arc2 = cum2[rows2[0], k2[0]] - cum2[rows2[0], k2[1]]
    arc2 = np.where(arc2 < 0, arc2 + own2, arc2)
    out = arc1 + arc2 + bridges
    out = np.where(settled.all(axis=0), out, np.nan)
    return (out, k1, k2) if vertices else out


def pair_root(cum1: np.ndarray, cum2: np.ndarray, v1: np.ndarray, v2: np.ndarray, k1: tuple[int, int],
              k2: tuple[int, int], length: float, a: float) -> float:
    r"""Centre distance at which one pair's hull perimeter is ``length``, its bridges' vertices
    held: ``v1`` (n1, 2) round the origin, ``v2`` (n2, 2) round *its own* centre, ``cum1``,
    ``cum2`` their :func:`edge_sums`, ``k1``, ``k2`` the (upper, lower) bridge vertices,
    ``a`` the start [m].

    With the vertices held, :math:`L(a) = C + |w_u(a)| + |w_l(a)|`, ``C`` the two arcs and
    :math:`w(a) = (a + \Delta x, \Delta y)`: increasing and convex in ``a``, so Newton's
    method with the exact slope :math:`\sum (a + \Delta x)/|w|` converges (quadratically)
    to its root. The caller checks that the vertices are still the bridges' at the root.
    """
    own1, own2 = float(cum1[-1]), float(cum2[-1])
    arc1 = float(cum1[k1[1]] - cum1[k1[0]])
    arc2 = float(cum2[k2[0]] - cum2[k2[1]])
    c = (arc1 + own1 if arc1 < 0 else arc1) + (arc2 + own2 if arc2 < 0 else arc2)
    dxu, dyu = float(v2[k2[0], 0] - v1[k1[0], 0]), float(v2[k2[0], 1] - v1[k1[0], 1])
    dxl, dyl = float(v2[k2[1], 0] - v1[k1[1], 0]), float(v2[k2[1], 1] - v1[k1[1], 1])
    for _ in range(60):
        hu, hl = math.hypot(a + dxu, dyu), math.hypot(a + dxl, dyl)
        step = (c + hu + hl - length) / ((a + dxu) / hu + (a + dxl) / hl)
        a -= step
        if abs(step) <= 4e-16 * abs(a):
            break
    return a
