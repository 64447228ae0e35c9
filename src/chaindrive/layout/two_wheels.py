"""Two wheels: chain length and centre distance, continuous approximation, pitch circles and
pitch polygons (convex hull of the two polygons, over the phases of the wheels)."""

from __future__ import annotations

import functools
import math
import threading
from dataclasses import dataclass, replace

import numpy as np
from numpy.typing import ArrayLike

from .._finite import finite_guard
from .._results import Result, quantity
from .._typing import FloatOrArray
from .._validation import as_float_array, check_positive, check_teeth
from ..errors import ConvergenceError, InfeasibleError, InputError
from ._bridges import bridge_perimeters, edge_sums, pair_root
from .wheels import _radius_and_offsets, cached_pitch_radius, pitch_radius


@finite_guard
def chain_length_approx(
    pitch: ArrayLike, teeth_1: ArrayLike, teeth_2: ArrayLike, centre_distance: ArrayLike
) -> FloatOrArray:
    r"""Chain length in pitches, continuous approximation (ISO 10823 / textbook).

    .. math::
        X = \frac{2a}{p} + \frac{z_1 + z_2}{2}
            + \left(\frac{z_2 - z_1}{2\pi}\right)^2 \frac{p}{a}

    Parameters
    ----------
    pitch : float or array_like
        Chain pitch ``p`` [m].
    teeth_1, teeth_2 : int or array_like
        Tooth counts of the two wheels [-] (order does not matter).
    centre_distance : float or array_like
        Centre distance ``a`` [m].

    Returns
    -------
    ndarray
        Chain length ``X`` [pitches] (not rounded).

    Notes
    -----
    Derivation: belt on the pitch circles approximated by ``R ≈ z p / (2π)`` and
    ``asin β ≈ β``, ``cos β ≈ 1 - β²/2`` for the span angle ``β = (R2 - R1)/a``;
    the error against :func:`chain_length_circles` is below 0.1 pitch for
    ``a >= 30 p`` and ratios up to 7 (tested). The centre distance should exceed
    ``R1 + R2``; ISO 10823 recommends 30…50 pitches.

    References
    ----------
    ISO 10823:2004, Guidance on the selection of roller chain drives (chain length
    formula); Shigley's Mechanical Engineering Design, 9th ed., eq. (17-34); Ramsey
    Chain, "Chain length calculations" (same formula with a tabulated ``T`` term).

    Examples
    --------
    >>> round(float(chain_length_approx(0.0254, 19, 57, 1.05)), 3)   # [pitches]
    121.562
    """
    p = check_positive("pitch", pitch, "m")
    z1 = check_teeth("teeth_1", teeth_1)
    z2 = check_teeth("teeth_2", teeth_2)
    a = check_positive("centre_distance", centre_distance, "m")
    return 2.0 * a / p + (z1 + z2) / 2.0 + ((z2 - z1) / (2.0 * np.pi)) ** 2 * p / a


@finite_guard
def centre_distance_approx(pitch: ArrayLike, teeth_1: ArrayLike, teeth_2: ArrayLike, links: ArrayLike) -> FloatOrArray:
    r"""Centre distance for a chain of ``links`` pitches, inverse of the approximation.

    .. math::
        a = \frac{p}{8}\left[2X - z_1 - z_2
            + \sqrt{(2X - z_1 - z_2)^2 - \frac{8}{\pi^2}(z_2 - z_1)^2}\right]

    Parameters
    ----------
    pitch : float or array_like
        Chain pitch [m].
    teeth_1, teeth_2 : int or array_like
        Tooth counts [-].
    links : float or array_like
        Chain length ``X`` [pitches].

    Returns
    -------
    ndarray
        Centre distance [m].

    Raises
    ------
    InfeasibleError
        If the chain is too short for the two wheels (negative discriminant).

    Notes
    -----
    The larger root of ``2c² - (X - S)c + D²/(4π²) = 0`` with ``c = a/p``,
    ``S = (z1+z2)/2``, ``D = z2 - z1`` (derived here; the handbook form writes
    ``8/π² ≈ 0.810``). Exact inverse of :func:`chain_length_approx` (tested). Written
    as ``a = p (2X - z1 - z2) F`` it has the form of ISO 10823 (factor ``F`` tabulated
    there) with ``F = [1 + √(1 - (8/π²)(D/(2X - z1 - z2))²)] / 8``.

    References
    ----------
    ISO 10823:2004 (centre distance formula); Shigley, 9th ed., eq. (17-35); Autodesk
    Inventor help, "Calculating roller chain length" (``C = F p [2X - (z1 + z2)]``);
    U. C. Jindal, Machine Design, Example 30-1 (round trip, tested).

    Examples
    --------
    >>> round(float(centre_distance_approx(0.0254, 19, 57, 122)), 4)   # [m], 122 links
    1.0556
    """
    p = check_positive("pitch", pitch, "m")
    z1 = check_teeth("teeth_1", teeth_1)
    z2 = check_teeth("teeth_2", teeth_2)
    X = check_positive("links", links)
    b = 2.0 * X - z1 - z2
    disc = b**2 - 8.0 / np.pi**2 * (z2 - z1) ** 2
    if np.asarray(b <= 0).any() or np.asarray(disc < 0).any():
        raise InfeasibleError(
            f"links = {X} is too short for wheels of {z1} and {z2} teeth: need "
            "2X - z1 - z2 > sqrt(8/pi^2) |z2 - z1| (links must exceed about (z1+z2)/2 + 0.45|z2-z1|)"
        )
    return p / 8.0 * (b + np.sqrt(disc))


def _belt_length(a: FloatOrArray, r1: FloatOrArray, r2: FloatOrArray) -> FloatOrArray:
    """Open-belt length on two circles (exact tangents)."""
    if type(a) is float and type(r1) is float and type(r2) is float:
        # Python floats (the root searches): numpy's arc sine, the correctly rounded square root,
        # the same products and sums as below, bit for bit
        b = float(np.arcsin((r2 - r1) / a))
        return 2.0 * math.sqrt(a**2 - (r2 - r1) ** 2) + r1 * (math.pi - 2 * b) + r2 * (math.pi + 2 * b)
    beta = np.arcsin((r2 - r1) / a)
    return 2.0 * np.sqrt(a**2 - (r2 - r1) ** 2) + r1 * (np.pi - 2 * beta) + r2 * (np.pi + 2 * beta)


@finite_guard
def chain_length_circles(
    pitch: ArrayLike,
    teeth_1: ArrayLike,
    teeth_2: ArrayLike,
    centre_distance: ArrayLike,
    bar_diameter: float | None = None,
) -> FloatOrArray:
    r"""Chain length in pitches on the pitch *circles*, exact tangents (belt formula).

    .. math::
        L = 2\sqrt{a^2 - (R_2 - R_1)^2} + R_1(\pi - 2\beta) + R_2(\pi + 2\beta),
        \quad \beta = \arcsin\frac{R_2 - R_1}{a},\qquad X = L/p

    Parameters
    ----------
    pitch : float or array_like
        Chain pitch (inner link length) [m].
    teeth_1, teeth_2 : int or array_like
        Teeth / pockets [-].
    centre_distance : float or array_like
        Centre distance ``a > |R2 - R1|`` [m].
    bar_diameter : float, optional
        Bar diameter of a round link chain [m].

    Returns
    -------
    ndarray
        Chain length [pitches].

    Notes
    -----
    The chain is replaced by a belt on the pitch circles: the wrapped parts are arcs,
    not polygon sides, so this over-estimates the polygonal length (a side is shorter
    than its arc) and is the limit of :func:`chain_length_polygon` for many teeth.

    References
    ----------
    Open-belt length, e.g. Shigley, 9th ed., eq. (17-1) for flat belts.

    Examples
    --------
    >>> round(float(chain_length_circles(0.0254, 19, 19, 1.0)), 3)
    97.827
    """
    p = check_positive("pitch", pitch, "m")
    a = check_positive("centre_distance", centre_distance, "m")
    r1 = pitch_radius(p, teeth_1, bar_diameter)
    r2 = pitch_radius(p, teeth_2, bar_diameter)
    if np.any(a <= np.abs(r2 - r1)):
        raise InfeasibleError(
            "centre_distance must exceed |R2 - R1| (one wheel inside the other), "
            f"got a = {a} m, |R2 - R1| = {np.abs(r2 - r1)} m"
        )
    return _belt_length(a, r1, r2) / p


def _hull_perimeter(points: np.ndarray) -> float:
    """Perimeter of the convex hull of ``points`` by Qhull (reference for the fast path)."""
    from scipy.spatial import ConvexHull

    hull = ConvexHull(points)
    v = points[hull.vertices]
    return float(np.sum(np.hypot(*(np.roll(v, -1, axis=0) - v).T)))


def _next_vertices(vertices: np.ndarray) -> np.ndarray:
    """Vertex ``k + 1`` in place of vertex ``k`` (``np.roll(vertices, -1, axis=-2)``, without its overhead)."""
    return np.concatenate([vertices[..., 1:, :], vertices[..., :1, :]], axis=-2)


def _mod_2pi(x: np.ndarray) -> np.ndarray:
    """``np.mod(x, 2π)`` by the same steps (``fmod``, plus 2π where it is negative, +0 for a zero), a
    third cheaper than numpy's floor-division remainder."""
    r = np.fmod(x, 2 * np.pi)
    r = np.where(r < 0, r + 2 * np.pi, r)
    return np.where(r == 0, 0.0, r)


def _edge_normal_angles(vertices: np.ndarray) -> np.ndarray:
    """Outward normal angles of the edges ``k -> k+1`` of counter-clockwise convex polygons.

    ``vertices`` (rows, n, 2) -> (rows, n), unwrapped so that they increase along a row.
    """
    d = _next_vertices(vertices) - vertices
    return np.unwrap(np.arctan2(-d[..., 0], d[..., 1]), axis=-1)


def _cone_index(normals: np.ndarray, directions: np.ndarray,
                table: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None) -> np.ndarray:
    """Vertex whose normal cone holds each direction: ``normals`` (rows, n), ``directions`` (rows, ...);
    ``table``: ``_cone_table(normals)`` when the caller has it already."""
    rows, n = normals.shape
    first, offsets, flat = _cone_table(normals) if table is None else table
    q = _mod_2pi(directions.reshape(rows, -1) - first) + offsets[:, None]
    k = np.searchsorted(flat, q.ravel(), side="right") - 1
    return ((k.reshape(rows, -1) - n * np.arange(rows)[:, None]) % n).reshape(directions.shape)


def _cone_table(normals: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The cone starts of every row laid end to end (rows 2π apart), for :func:`_cone_index`."""
    rows = normals.shape[0]
    starts = np.concatenate([normals[:, -1:] - 2 * np.pi, normals[:, :-1]], axis=1)  # vertex k: from ν_{k-1}
    offsets = 2 * np.pi * np.arange(rows)
    flat = (starts - starts[:, :1] + offsets[:, None]).ravel()
    return starts[:, :1], offsets, flat


def _abs_cos_primitive(x: np.ndarray, sin_x: np.ndarray | None = None) -> np.ndarray:
    """A primitive of ``|cos x|``: ``2m + (-1)^m sin x``, ``m = floor((x + π/2)/π)`` (continuous);
    ``sin_x``: ``np.sin(x)`` when the caller has it already."""
    m = np.floor((x + np.pi / 2) / np.pi)
    s = np.sin(x) if sin_x is None else sin_x
    # (-1)^m sin x: m is a whole number, so m/2 and 2 floor(m/2) are exact (the same test as m % 2 == 0)
    return 2.0 * m + np.where(np.floor(0.5 * m) * 2.0 == m, s, -s)


def _hull_perimeters(vertices_1: np.ndarray, vertices_2: np.ndarray,
                     first: tuple | None = None) -> np.ndarray:
    r"""Perimeter of hull(P1[a] ∪ P2[b]) for every pair: (A, n1, 2), (B, n2, 2) -> (A, B) [m].

    ``first``: ``_polygon_terms(vertices_1)`` when the caller has them already.

    Cauchy's formula: the perimeter of a convex set is the integral of its support
    function over the directions, :math:`\int_0^{2\pi} h\,d\varphi`, and the support
    function of the hull of a union is :math:`\max(h_1, h_2)`. Hence

    .. math:: L = L_1 + \int_0^{2\pi} \max(0,\ h_2 - h_1)\,d\varphi

    with ``L1`` the perimeter of P1. Between consecutive edge normals of both polygons
    (merged and sorted) each support function is ``v·u(φ)`` for one vertex ``v``, so
    ``h2 - h1 = |w| cos(φ - ψ)`` with ``w = v2 - v1`` and the integral is closed-form
    (a primitive of ``|cos|``). Exact for any two convex counter-clockwise polygons,
    overlapping or not; equal to Qhull (:func:`_hull_perimeter`) within 1e-12 (tests).

    References
    ----------
    Santaló, L. A., Integral Geometry and Geometric Probability (1976), ch. 1, Cauchy's
    formula for the perimeter of a convex set.
    """
    rows_1, rows_2 = vertices_1.shape[0], vertices_2.shape[0]
    n1, n2 = vertices_1.shape[1], vertices_2.shape[1]
    normals_1, own, mod_1, table_1 = _polygon_terms(vertices_1) if first is None else first
    normals_2 = _edge_normal_angles(vertices_2)
    s = np.concatenate([np.broadcast_to(mod_1[:, None, :], (rows_1, rows_2, n1)),
                        np.broadcast_to(_mod_2pi(normals_2)[None, :, :], (rows_1, rows_2, n2))],
                       axis=-1)
    s.sort(axis=-1)
    e = np.concatenate([s[..., 1:], s[..., :1] + 2 * np.pi], axis=-1)
    mid = 0.5 * (s + e)
    k1 = _cone_index(normals_1, mid, table_1)
    k2 = np.swapaxes(_cone_index(normals_2, np.swapaxes(mid, 0, 1)), 0, 1)
    # w = v2[k2] - v1[k1], gathered from the flat x and y columns (the same values, faster than
    # fancy indexing over the rows)
    flat_2 = (k2 + (n2 * np.arange(rows_2))[None, :, None]).ravel()
    flat_1 = (k1 + (n1 * np.arange(rows_1))[:, None, None]).ravel()
    wx = (vertices_2[..., 0].ravel().take(flat_2) - vertices_1[..., 0].ravel().take(flat_1)).reshape(k1.shape)
    wy = (vertices_2[..., 1].ravel().take(flat_2) - vertices_1[..., 1].ravel().take(flat_1)).reshape(k1.shape)
    psi = np.arctan2(wy, wx)
    xs, xe = s - psi, e - psi
    sin_e, sin_s = np.sin(xe), np.sin(xs)  # each sine once (the primitives reuse them)
    extra = 0.5 * np.hypot(wx, wy) * (
        (sin_e - sin_s) + _abs_cos_primitive(xe, sin_e) - _abs_cos_primitive(xs, sin_s))
    return own[:, None] + np.sum(extra, axis=-1)


def _polygon_terms(vertices: np.ndarray) -> tuple:
    """What :func:`_hull_perimeters` needs of its first polygons alone: edge normal angles,
    perimeters, the angles in [0, 2π) and their cone table."""
    own = np.sum(np.hypot(*np.moveaxis(_next_vertices(vertices) - vertices, -1, 0)), axis=-1)
    normals = _edge_normal_angles(vertices)
    return normals, own, _mod_2pi(normals), _cone_table(normals)


@dataclass(frozen=True)
class PolygonLength(Result):
    """Chain length on the pitch polygons over the phases of the two wheels.

    Attributes
    ----------
    links_min, links_max, links_mean : float
        Taut chain length over the sampled phase pairs [pitches].
    links_circles : float
        Length on the pitch circles, for comparison [pitches].
    links_approx : float or None
        The continuous approximation (roller chains only) [pitches].
    phase_1, phase_2 : ndarray
        Sampled phases of wheel 1 and 2 [rad].
    links : ndarray, shape (n1, n2)
        Length for each phase pair [pitches].
    """

    links_min: float = quantity("1")
    links_max: float = quantity("1")
    links_mean: float = quantity("1")
    links_circles: float = quantity("1")
    links_approx: float | None = quantity("1")
    phase_1: np.ndarray = quantity("rad")
    phase_2: np.ndarray = quantity("rad")
    links: np.ndarray = quantity("1")


def _polygon_links(p, z1, z2, a, d, n):
    # period of each polygon: 2π/z (a bi-regular 2z-gon repeats every 2π/z too)
    ph1, ph2 = _phase_grid(z1, n), _phase_grid(z2, n)
    return ph1, ph2, _perimeters(p, z1, z2, a, d, ph1, ph2) / p


def _phase_grid(z, n):
    # the sampled phases of a wheel: n over one tooth period 2π/z (a bi-regular 2z-gon repeats
    # every 2π/z too)
    return np.arange(n) * (2 * np.pi / z) / n


def _perimeters(p, z1, z2, a, d, ph1, ph2, bridges=None):
    # hull perimeters of every phase pair [m]: by the two bridges where the pitch circles are
    # apart (chaindrive.layout._bridges), else (or where a bridge did not settle) by the
    # integral; `bridges`: a dict that receives the bridges' vertices (k1, k2) when found
    v1, v2 = _phase_vertices(p, z1, ph1, d), _phase_vertices(p, z2, ph2, d)
    r1, r2 = _radius(p, z1, d), _radius(p, z2, d)
    v2a = _shifted(v2, a)
    if a > (r1 + r2) * (1.0 + 1e-9):
        out, k1, k2 = bridge_perimeters(v1, v2a, _edge_sums(p, z1, ph1, d), _edge_sums(p, z2, ph2, d),
                                        r1, r2, a, vertices=True, regular=None if d else (ph1, z1, ph2, z2))
        if not np.isnan(out).any():
            if bridges is not None:
                bridges["k"] = (k1, k2)
            return out
    return _hull_perimeters(v1, v2a, _first_terms(p, z1, ph1, d))


def _edge_sums(p, z, phases, d):
    # edge_sums(_phase_vertices(p, z, phases, d)), cached with the vertices
    key = ("sums", *_vertex_key(p, z, phases, d))
    found = _VERTEX_CACHE.get(key)
    if found is None:
        found = edge_sums(_phase_vertices(p, z, phases, d))
        found.flags.writeable = False
        if len(_VERTEX_CACHE) > 256:
            _VERTEX_CACHE.clear()
        _VERTEX_CACHE[key] = found
    return found


def _first_terms(p, z, phases, d):
    # _polygon_terms(_phase_vertices(p, z, phases, d)), cached with the vertices
    key = ("terms", *_vertex_key(p, z, phases, d))
    found = _VERTEX_CACHE.get(key)
    if found is None:
        found = _polygon_terms(_phase_vertices(p, z, phases, d))
        for x in (*found[:3], *found[3]):
            x.flags.writeable = False
        if len(_VERTEX_CACHE) > 256:
            _VERTEX_CACHE.clear()
        _VERTEX_CACHE[key] = found
    return found


def _vertex_key(p, z, phases, d):
    return (float(p), int(z), np.asarray(phases, dtype=float).ravel().tobytes(), None if not d else float(d))


def _phase_vertices(p, z, phases, d):
    # the pitch polygons of a wheel at the origin for each phase, (phases, n, 2); cached
    # because the root searches ask for the same wheels at many centre distances
    phases = np.asarray(phases, dtype=float).ravel()
    key = _vertex_key(p, z, phases, d)
    found = _VERTEX_CACHE.get(key)
    if found is None:
        # pitch_polygon_vertices for every phase at once (the same operations)
        R, offsets = _radius_and_offsets(p, z, d)
        theta = phases[:, None] + offsets[None, :]
        found = np.stack([0.0 + R * np.cos(theta), 0.0 + R * np.sin(theta)], axis=-1)
        found.flags.writeable = False
        if len(_VERTEX_CACHE) > 256:
            _VERTEX_CACHE.clear()
        _VERTEX_CACHE[key] = found
    return found


def _shifted(vertices, a):
    # vertices of a wheel at (a, 0): the same additions as pitch_polygon_vertices(centre=(a, 0))
    out = vertices.copy()
    out[..., 0] = a + vertices[..., 0]
    return out


_VERTEX_CACHE: dict = {}


#: Largest phase grid x vertices handled at once (phases² (z1 + z2) values, 8 bytes each:
#: 2e7 is 160 MB per array).
MAX_PHASE_GRID = 20_000_000


def _check_phases(phases, teeth_1: int, teeth_2: int) -> None:
    """Refuse a phase count below 1, or one whose grid would not fit in memory."""
    if int(phases) < 1:
        raise InputError(f"phases must be a whole number >= 1, got {phases}")
    largest = int(math.isqrt(MAX_PHASE_GRID // (teeth_1 + teeth_2)))
    if int(phases) > largest:
        raise InputError(f"phases must be a whole number in [1, {largest}] for {teeth_1} + {teeth_2} teeth "
                         f"(the phase grid holds phases² (z1 + z2) values), got {phases}")


@finite_guard
def chain_length_polygon(pitch: float, teeth_1: int, teeth_2: int, centre_distance: float, *,
                         bar_diameter: float | None = None, phases: int = 12) -> PolygonLength:
    r"""Exact taut chain length on the pitch *polygons* of two wheels, over their phases.

    .. math::
        X(a, \varphi_1, \varphi_2) = \frac{1}{p}\,
            \operatorname{perimeter}\bigl(\operatorname{hull}(P_1(\varphi_1)
            \cup P_2(a, \varphi_2))\bigr)

    Parameters
    ----------
    pitch : float
        Chain pitch ``p`` (inner link length ``t``) [m].
    teeth_1, teeth_2 : int
        Teeth / pockets [-].
    centre_distance : float
        Centre distance ``a`` [m].
    bar_diameter : float, optional
        Bar diameter of a round link chain [m] (bi-regular polygons).
    phases : int
        Number of phases sampled per wheel over one tooth period ``2π/z`` (the grid
        has ``phases²`` points).

    Returns
    -------
    PolygonLength

    Notes
    -----
    Model (chosen and documented here): the hinges seated on a wheel are the
    vertices of its pitch polygon; a taut chain leaves the last seated hinge along the
    common supporting line of the two polygons, so the taut chain is the boundary of
    the convex hull of both vertex sets: polygon sides (one link each) on the wraps,
    and two straight spans tangent to the *polygons* (not circles). Its length depends
    on the phases ``φ1, φ2`` of the wheels (polygonal effect); the function samples
    a grid of phases over one tooth period each and reports min, max and mean. The
    span length is not forced to a whole number of pitches: a span that is not a
    whole number of links is slightly slack. Exact special case: two equal wheels in
    equal phase give ``X = z + 2a/p`` (the hull is the polygon swept along the centre
    line); for many teeth ``X`` tends to :func:`chain_length_circles` (both tested).

    References
    ----------
    Model of this package (docs/drive.md, "Layout"); polygon from Dolipiński et al., eq. (6).

    Examples
    --------
    >>> r = chain_length_polygon(0.0254, 19, 19, 1.0, phases=4)
    >>> round(r.links_min, 4), round(r.links_max, 4)
    (97.7367, 97.7436)
    """
    p = float(check_positive("pitch", pitch, "m"))
    z1 = int(check_teeth("teeth_1", teeth_1, minimum=2))
    z2 = int(check_teeth("teeth_2", teeth_2, minimum=2))
    a = float(check_positive("centre_distance", centre_distance, "m"))
    _check_phases(phases, z1, z2)
    found = _chain_length_polygon(p, z1, z2, a, None if bar_diameter is None else float(bar_diameter), int(phases))
    # a copy of the cached arrays: the caller may change its own
    return replace(found, phase_1=found.phase_1.copy(), phase_2=found.phase_2.copy(), links=found.links.copy())


def _radius(p: float, z: int, bar_diameter: float | None) -> float:
    # float(pitch_radius(p, z, bar_diameter)) on checked scalars, kept
    return cached_pitch_radius(p, z, bar_diameter)


@functools.lru_cache(maxsize=256)
def _chain_length_polygon(p: float, z1: int, z2: int, a: float, bar_diameter: float | None,
                          phases: int) -> PolygonLength:
    # chain_length_polygon on checked scalars; cached because it depends on them only and
    # an analysis asks for the same pair of wheels again (the results are plain numbers)
    # the grid kept for the root search too (_grid_at: the same numbers as _polygon_links): the
    # centre distance for the links asked next starts from it
    ph1, ph2, X = _grid_at(p, z1, z2, a, bar_diameter, phases)
    r1, r2 = _radius(p, z1, bar_diameter), _radius(p, z2, bar_diameter)
    # chain_length_circles(p, z1, z2, a, bar_diameter) on the checked inputs (a > |R2 - R1|)
    circles = float(_belt_length(a, r1, r2) / p) if a > abs(r2 - r1) else float("nan")
    approx = None if bar_diameter else float(chain_length_approx(p, z1, z2, a))
    return PolygonLength(
        links_min=float(X.min()), links_max=float(X.max()), links_mean=float(X.mean()),
        links_circles=circles, links_approx=approx, phase_1=ph1, phase_2=ph2, links=X,
    )


@dataclass(frozen=True)
class PolygonCentreDistance(Result):
    """Centre distance for a whole number of links on the pitch polygons.

    Attributes
    ----------
    links : int
        Chain length [pitches], as asked.
    taut : float
        Largest centre distance at which the chain fits at *every* sampled phase pair
        (taut at its tightest phase) [m]: the recommended nominal centre distance.
    loose : float
        Centre distance at which the chain is taut only at its loosest phase [m];
        beyond it the chain cannot be fitted. ``loose - taut`` is the polygonal play.
    circles : float
        Centre distance from the pitch-circle (belt) model [m].
    approx : float or None
        From :func:`centre_distance_approx` (roller chains) [m].
    """

    links: int = quantity("1")
    taut: float = quantity("m")
    loose: float = quantity("m")
    circles: float = quantity("m")
    approx: float | None = quantity("m")


def _solve_increasing(fun, target, lo, hi, what):
    from .._roots import brentq

    flo, fhi = fun(lo) - target, fun(hi) - target
    k = 0
    while fhi < 0:
        hi *= 2.0
        fhi = fun(hi) - target
        k += 1
        if k > 60:
            raise ConvergenceError(f"could not bracket the {what}")
    if flo > 0:
        raise InfeasibleError(f"the chain is too short: {what} would be below {lo:g} m")
    return brentq(lambda x: fun(x) - target, lo, hi, xtol=1e-12, rtol=1e-12)


def _newton_fixed_slope(fun, target, a0, r1, r2, p, lo, hi):
    # X(a) grows with slope 2 cos(beta)/p (the two spans); iterate with that slope and
    # fall back to Brent's method if it does not settle
    a = a0
    for _ in range(30):
        slope = 2.0 * np.sqrt(max(1.0 - ((r2 - r1) / a) ** 2, 1e-12)) / p
        step = (fun(a) - target) / slope
        a = a - step
        if abs(step) < 1e-11 * max(a, 1.0):
            return a
    return _solve_increasing(fun, target, lo, hi, "centre distance")


def _pair_links(p, z1, z2, a, d, f1, f2):
    return float(_perimeters(p, z1, z2, a, d, (f1,), (f2,))[0, 0]) / p


#: The phase grids :func:`_extreme_phase_root` evaluated last (the loose root starts where the
#: taut one ended, at a grid already evaluated), per thread.
_GRIDS = threading.local()


def _grid_at(p, z1, z2, a, d, n):
    # _polygon_links(p, z1, z2, a, d, n), the last few kept (read only by the root search),
    # with the bridges' vertices of every pair where the bridges gave it (_grid_bridges)
    grids = getattr(_GRIDS, "grids", None)
    if grids is None:
        grids = _GRIDS.grids = {}
    key = (p, z1, z2, a, d, n)
    found = grids.get(key)
    if found is None:
        if len(grids) >= 4:
            grids.clear()
        ph1, ph2 = _phase_grid(z1, n), _phase_grid(z2, n)
        bridges: dict = {}
        found = grids[key] = (ph1, ph2, _perimeters(p, z1, z2, a, d, ph1, ph2, bridges) / p)
        grids[("bridges", *key)] = bridges.get("k")
    return found


def _grid_bridges(p, z1, z2, a, d, n, i, j):
    # the bridges' vertices ((upper, lower) on wheel 1, on wheel 2) of pair (i, j) of the grid
    # _grid_at evaluated at a, or None
    found = _GRIDS.grids.get(("bridges", p, z1, z2, a, d, n))
    if found is None:
        return None
    k1, k2 = found
    return (int(k1[0, i, j]), int(k1[1, i, j])), (int(k2[0, i, j]), int(k2[1, i, j]))


def _pair_root(p, z1, z2, d, n, i, j, ks, target, a):
    # the centre distance where pair (i, j) of the phase grid is `target` links long, its
    # bridges' vertices `ks` held (chaindrive.layout._bridges.pair_root)
    ph1, ph2 = _phase_grid(z1, n), _phase_grid(z2, n)
    return pair_root(_edge_sums(p, z1, ph1, d)[i], _edge_sums(p, z2, ph2, d)[j], _phase_vertices(p, z1, ph1, d)[i],
                     _phase_vertices(p, z2, ph2, d)[j], ks[0], ks[1], target * p, a)


def _kept_grid_near(p, z1, z2, d, n, lo, hi):
    """The centre distance of the last phase grid :func:`_grid_at` kept for these wheels with its
    bridges (chain_length_polygon's, at the drive's centre distance), or None."""
    grids = getattr(_GRIDS, "grids", None) or {}
    for key in reversed(list(grids)):
        if key[0] != "bridges" and key[:3] == (p, z1, z2) and key[4:] == (d, n) and lo < key[3] < hi \
                and grids.get(("bridges", *key)) is not None:
            return key[3]
    return None


def _extreme_phase_root(pick, p, z1, z2, d, n, target, a0, r1, r2, lo, hi, start=None):
    """Root of max (``pick=np.argmax``) or min over the phase grid of X(a) = target.

    ``start``: a centre distance whose grid is kept already, to choose the first pair from
    instead of ``a0`` (the root is the same: it is checked on the grid there).

    Newton steps run on the phase pair that governs at the current estimate (one hull
    per step instead of n² of them); the whole grid is then evaluated at the root, and if
    another pair governs there the search goes on from it. The result is the root of the
    grid's max (min) itself, as when every step evaluated the whole grid.
    """
    a = a0 if start is None else start
    held = None  # (pair, bridges' vertices) of the last root with the vertices held
    for _ in range(20):
        ph1, ph2, grid = _grid_at(p, z1, z2, a, d, n)
        i, j = np.unravel_index(pick(grid), grid.shape)
        ks = _grid_bridges(p, z1, z2, a, d, n, i, j)
        if held is not None and held == ((i, j), ks):
            return a  # the pair governs at its root, where its bridges are those held
        if abs(grid[i, j] - target) <= 1e-9 and a != a0 and a != start and held is None:
            return a
        f1, f2 = ph1[i], ph2[j]
        if ks is not None and held is None:
            # Newton with the exact slope on the pair, its bridges' vertices held; checked
            # on the grid at the root (the next pass)
            a_new, held = _pair_root(p, z1, z2, d, n, i, j, ks, target, a), ((i, j), ks)
        else:
            held = None
            a_new = _newton_fixed_slope(lambda x, f1=f1, f2=f2: _pair_links(p, z1, z2, x, d, f1, f2),
                                        target, a, r1, r2, p, lo, hi)
        if a_new == a:
            return a
        a = a_new
    fun = (lambda x: _polygon_links(p, z1, z2, x, d, n)[2].max()) if pick is np.argmax else \
          (lambda x: _polygon_links(p, z1, z2, x, d, n)[2].min())
    return _newton_fixed_slope(fun, target, a, r1, r2, p, lo, hi)


@finite_guard
def centre_distance_polygon(pitch: float, teeth_1: int, teeth_2: int, links: int, *,
                            bar_diameter: float | None = None, phases: int = 12) -> PolygonCentreDistance:
    r"""Centre distance for a whole number of links, solving the polygon model.

    .. math:: \max_{\varphi_1,\varphi_2} X(a_{taut}, \varphi_1, \varphi_2) = N,
              \qquad \min_{\varphi_1,\varphi_2} X(a_{loose}, \varphi_1, \varphi_2) = N

    Parameters
    ----------
    pitch : float
        Chain pitch [m].
    teeth_1, teeth_2 : int
        Teeth / pockets [-].
    links : int
        Whole number of links ``N``; an odd number warns nothing but needs an offset
        link (roller chains), see :func:`even_links`.
    bar_diameter : float, optional
        Bar diameter of a round link chain [m].
    phases : int
        Phases sampled per wheel (see :func:`chain_length_polygon`).

    Returns
    -------
    PolygonCentreDistance

    Raises
    ------
    InputError
        ``links`` not a whole number > 0.
    InfeasibleError
        The chain is too short to wrap the two wheels.

    Notes
    -----
    Solved by Newton steps with the span slope ``dX/da = 2 cos β / p`` started from
    the pitch-circle solution (Brent's method as fallback); the taut length grows
    monotonically with ``a``. See :func:`chain_length_polygon` for the model.

    References
    ----------
    Model of this package (docs/drive.md, "Layout").

    Examples
    --------
    >>> r = centre_distance_polygon(0.0254, 19, 19, 98, phases=2)
    >>> round(r.taut, 4)
    1.0033
    """
    p = float(check_positive("pitch", pitch, "m"))
    z1 = int(check_teeth("teeth_1", teeth_1, minimum=2))
    z2 = int(check_teeth("teeth_2", teeth_2, minimum=2))
    links_array = as_float_array("links", links)
    if links_array.ndim or links_array != np.round(links_array) or links_array <= 0:
        raise InputError(f"links must be a whole number > 0, got {links!r}")
    N = int(links_array)
    _check_phases(phases, z1, z2)
    return _centre_distance_polygon(p, z1, z2, N, None if bar_diameter is None else float(bar_diameter), int(phases))


@functools.lru_cache(maxsize=256)
def _centre_distance_polygon(p: float, z1: int, z2: int, N: int, bar_diameter: float | None,
                             n: int) -> PolygonCentreDistance:
    # centre_distance_polygon on checked scalars; cached (a frozen result of plain numbers)
    r1, r2 = _radius(p, z1, bar_diameter), _radius(p, z2, bar_diameter)
    lo = abs(r2 - r1) + 1e-6 * p
    hi = max(N * p / 2.0, 2 * lo)

    def xcirc(a):  # chain_length_circles(p, z1, z2, a, bar_diameter) on the checked inputs
        return float(_belt_length(a, r1, r2) / p)

    circ = _solve_increasing(xcirc, N, lo, hi, "centre distance")
    taut = _extreme_phase_root(np.argmax, p, z1, z2, bar_diameter, n, N, circ, r1, r2, lo, hi,
                               _kept_grid_near(p, z1, z2, bar_diameter, n, lo, hi))
    loose = _extreme_phase_root(np.argmin, p, z1, z2, bar_diameter, n, N, taut, r1, r2, lo, hi)
    approx = None
    if not bar_diameter:
        try:
            approx = float(centre_distance_approx(p, z1, z2, N))
        except InfeasibleError:
            approx = None
    return PolygonCentreDistance(links=N, taut=float(taut), loose=float(loose),
                                 circles=float(circ), approx=approx)


def even_links(links: ArrayLike) -> np.ndarray:
    r"""Round a chain length up to the next even whole number of links.

    .. math:: N = 2\lceil X/2 \rceil

    An even number avoids the offset (cranked) link of a roller chain, which weakens
    the chain (Ramsey Chain, "Chain length calculations").

    Parameters
    ----------
    links : float or array_like
        Chain length [pitches].

    Returns
    -------
    ndarray of int

    Examples
    --------
    >>> int(even_links(121.5)), int(even_links(122.0))
    (122, 122)
    """
    X = check_positive("links", links)
    return (2 * np.ceil(X / 2.0 - 1e-9)).astype(int)
