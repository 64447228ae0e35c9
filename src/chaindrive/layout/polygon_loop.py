r"""Any number of wheels on the pitch *polygons*: exact chain length and the position of
one adjustable wheel for a whole number of links.

The chain seated on a toothed wheel has its hinges on the wheel's pitch circle at the
vertices of its pitch polygon (the phase ``φ`` of the wheel fixes where they are);
between wheels it runs straight. Each span is therefore a common *supporting line* of
two wheels (polygon or, for a toothless idler, circle) on the sides the chain passes
them, and the wrap on a toothed wheel is a run of whole polygon sides. For two wheels
inside the loop this path is the boundary of the convex hull of the two polygons, the
model of :func:`chaindrive.layout.chain_length_polygon`, which it reproduces.

Derivation (this module)
------------------------
A span travelling along ``t = (cos α, sin α)`` with left normal ``n = (-sin α, cos α)``
touches a wheel on side ``s`` (+1: the wheel on the chain's left, inside the loop; -1:
on its right, an idler on the back of the chain) at the point that minimises ``s v·n``
over the wheel: for a polygon the vertex ``argmin_k s sin(a_k - α)``, for a circle the
point at polar angle ``α - s π/2``. The span is the line on which both wheels' support
points lie; starting from the pitch-circle tangent (:func:`chaindrive.layout.wrap_layout`)
the direction is updated to the tangent between the two current support points (a
vertex is a circle of radius 0) until the support points no longer change (a fixed
point of the rotating-calipers construction).

The chain turns by ``θ_i`` on wheel ``i`` on the circles; on the polygon it leaves at a
vertex of polar angle ``β_out`` and arrives at ``β_in`` with both within a tooth of the
circle tangent points, so its wrap runs over the sides between them, with the angle
swept ``θ_i + s_i (e_out - e_in)`` (``e``: the vertex's angle from the circle tangent
point). Writing ``A_i(v)`` for the arc position of vertex ``v`` along the polygon's
perimeter (unwrapped next to the circle tangent point), the wrap length is
``s_i (A_i(out) - A_i(in))`` and

.. math::
    L(\varphi_1, \dots, \varphi_N) = \sum_i \Bigl[\ell_i(\varphi_i, \varphi_{i+1})
        + s_i A_i(\mathrm{out}_i) - s_{i+1} A_{i+1}(\mathrm{in}_{i+1})\Bigr]

a cyclic sum of terms of two neighbouring phases each. Its largest (smallest) value over
independent phases of every toothed wheel is the largest (smallest) diagonal entry of
the max-plus (min-plus) product of the ``N`` span matrices, so the envelope over a grid
of ``n`` phases per wheel costs ``N n³`` operations instead of ``n^N`` evaluations (for
two wheels the same grid as :func:`chaindrive.layout.chain_length_polygon`).

Where the polygons of two wheels overlap so that no common supporting line exists, or
a wrap would be negative (an idler the chain barely touches), the pitch circles stand
in with a :class:`~chaindrive.errors.ValidityRangeWarning`.
"""

from __future__ import annotations

import functools
import math
import warnings
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from .._results import Result, quantity
from .._validation import as_float_array, check_positive
from ..errors import InfeasibleError, InputError, ValidityRangeWarning
from .two_wheels import MAX_PHASE_GRID, _check_phases
from .wheels import _radius_and_offsets
from .wrap import wrap_layout

__all__ = ["LoopLength", "LoopAdjustment", "loop_length_at_phases", "chain_length_loop", "adjust_loop"]

_MAX_ITERATIONS = 60


@dataclass(frozen=True)
class _Wheel:
    centre: np.ndarray
    side: int
    radius: float
    offsets: np.ndarray | None  # vertex angles from the first vertex; None: a circle
    cumulative: np.ndarray | None  # arc position of each vertex from vertex 0 [m]
    perimeter: float
    period: float  # phase period [rad]


@functools.lru_cache(maxsize=256)
def _polygon(pitch: float, teeth: int, bar_diameter: float | None) -> tuple[float, np.ndarray, np.ndarray, float]:
    """Pitch radius, vertex angles, arc position of each vertex and perimeter of a wheel's polygon (cached:
    the adjustable wheel's search and the studies ask for the same wheels again and again)."""
    R, off = _radius_and_offsets(pitch, teeth, bar_diameter)
    v = np.column_stack([np.cos(off), np.sin(off)]) * R
    edges = np.hypot(*(np.concatenate((v[1:], v[:1])) - v).T)  # np.roll(v, -1, axis=0): the same rows
    cum = np.concatenate([[0.0], np.cumsum(edges)[:-1]])
    off.flags.writeable = False
    cum.flags.writeable = False
    return float(R), off, cum, float(edges.sum())


def _wheels(pitch: float, centres: np.ndarray, teeth: Sequence[int | None], sides: np.ndarray,
            diameters: Sequence[float | None] | None, bar_diameter: float | None) -> list[_Wheel]:
    out = []
    for i, z in enumerate(teeth):
        if z is None or z == 0:
            d = None if diameters is None else diameters[i]
            if d is None or not float(d) > 0:
                raise InputError(f"wheel {i}: a toothless wheel needs a diameter > 0 [m], got {d!r}",
                                 field="diameters")
            r = 0.5 * float(d)
            out.append(_Wheel(centres[i], int(sides[i]), r, None, None, 2 * math.pi * r, 2 * math.pi))
            continue
        R, off, cum, perimeter = _polygon(float(pitch), int(z), None if not bar_diameter else float(bar_diameter))
        out.append(_Wheel(centres[i], int(sides[i]), R, off, cum, perimeter, 2 * math.pi / int(z)))
    return out


def _check_inputs(pitch, centres, teeth, sides, diameters):
    p = float(check_positive("pitch", pitch, "m"))
    c = as_float_array("centres", centres)
    if c.ndim != 2 or c.shape[1] != 2 or c.shape[0] < 2:
        raise InputError(f"centres must have shape (n, 2) with n >= 2, got shape {c.shape}", field="centres")
    n = c.shape[0]
    teeth = list(teeth)
    if len(teeth) != n:
        raise InputError(f"teeth must give one entry per wheel ({n}), got {len(teeth)}", field="teeth")
    s = np.ones(n) if sides is None else as_float_array("sides", sides)
    if s.shape != (n,) or not all(x in (-1.0, 1.0) for x in s.tolist()):
        raise InputError(f"sides must be +1 or -1 for each of the {n} wheels, got {sides!r}", field="sides")
    if diameters is not None and len(diameters) != n:
        raise InputError(f"diameters must give one entry per wheel ({n}), got {len(diameters)}",
                         field="diameters")
    return p, c, teeth, s


def _phase_grid(w: _Wheel, phases: int) -> np.ndarray:
    if w.offsets is None:
        return np.zeros(1)
    return np.arange(phases) * (w.period / phases)


def _support(w: _Wheel, phase: np.ndarray, alpha: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Support point of ``w`` for span direction ``alpha``: (polar angle [rad], vertex index or -1)."""
    if w.offsets is None:
        none = np.empty(alpha.shape, dtype=int)
        none.fill(-1)  # np.full(alpha.shape, -1)
        return alpha - w.side * math.pi / 2, none
    a = phase[..., None] + w.offsets  # (..., K)
    gap = np.sin(a - alpha[..., None])
    k = (gap if w.side == 1 else w.side * gap).argmin(axis=-1)
    # a at k (np.take_along_axis(a, k[..., None], axis=-1)[..., 0]: the same sums, gathered directly;
    # k has the shape of phase and alpha broadcast)
    return phase + w.offsets[k], k


def _span(wa: _Wheel, wb: _Wheel, pa: np.ndarray, pb: np.ndarray, alpha0: float):
    """Common supporting line of two wheels for every phase pair: (alpha, length, angle_a, k_a, angle_b, k_b, ok)."""
    alpha = np.empty((pa.shape[0], pb.shape[1]))  # np.full(np.broadcast_shapes(pa.shape, pb.shape), alpha0)
    alpha.fill(alpha0)
    ok = np.zeros(alpha.shape, dtype=bool)
    # each support point as a circle: the vertex (radius 0) or the wheel (signed radius); its
    # coordinates one by one (centre + R (cos, sin): the same sums as the stacked pair)
    rho_a = 0.0 if wa.offsets is not None else wa.side * wa.radius
    rho_b = 0.0 if wb.offsets is not None else wb.side * wb.radius
    drho = rho_b - rho_a
    ax, ay = float(wa.centre[0]), float(wa.centre[1])
    bx, by = float(wb.centre[0]), float(wb.centre[1])
    with np.errstate(invalid="ignore", divide="ignore"):
        return _span_iterations(wa, wb, pa, pb, alpha, ok, drho, (ax, ay), (bx, by))


def _span_iterations(wa, wb, pa, pb, alpha, ok, drho, a_xy, b_xy):
    """:func:`_span`'s fixed-point iterations (inside its error state)."""
    ax, ay = a_xy
    bx, by = b_xy
    ka = kb = None
    for _ in range(_MAX_ITERATIONS):
        ang_a, ka_new = _support(wa, pa, alpha)
        ang_b, kb_new = _support(wb, pb, alpha)
        if wa.offsets is not None:
            ax, ay = wa.centre[0] + wa.radius * np.cos(ang_a), wa.centre[1] + wa.radius * np.sin(ang_a)
        if wb.offsets is not None:
            bx, by = wb.centre[0] + wb.radius * np.cos(ang_b), wb.centre[1] + wb.radius * np.sin(ang_b)
        dx, dy = bx - ax, by - ay  # numbers between two circles (the same at every phase pair)
        D = np.hypot(dx, dy)
        new = np.arctan2(dy, dx) - np.arcsin(drho / D)
        turn = np.exp(1j * (new - alpha))
        new = alpha + np.arctan2(turn.imag, turn.real)  # np.angle: stay next to the previous direction
        same = (ka is not None and kb is not None and bool((ka_new == ka).all()) and bool((kb_new == kb).all()))
        ka, kb = ka_new, kb_new
        if same:
            ok = np.isfinite(new) & (D > np.abs(drho))
            length = np.sqrt(np.maximum(D**2 - drho**2, 0.0))
            if np.shape(length) != alpha.shape:  # np.full(alpha.shape, length)
                length, value = np.empty(alpha.shape), length
                length.fill(value)
            return new, length, ang_a, ka, ang_b, kb, ok
        alpha = new
    return alpha, np.full(alpha.shape, np.nan), ang_a, ka, ang_b, kb, ok


def _arc_position(w: _Wheel, angle: np.ndarray, index: np.ndarray, phase: np.ndarray, reference: float) -> np.ndarray:
    """Arc position ``A`` of a support point, its angle unwrapped next to ``reference`` [m]."""
    turns = np.rint((angle - reference) / (2 * math.pi))  # np.round(..): the same rounding, half to even
    unwrapped = angle - 2 * math.pi * turns
    if w.offsets is None or w.cumulative is None:
        return w.radius * unwrapped
    # vertex k at phase + offsets[k] + 2π m: A = m P + cumulative[k]
    m = np.rint((unwrapped - phase - w.offsets[index]) / (2 * math.pi))
    return m * w.perimeter + w.cumulative[index]


def _span_terms(wheels: list[_Wheel], grids: list[np.ndarray], circle) -> tuple[list[np.ndarray], bool]:
    """Span matrices ``M_i[φ_i, φ_{i+1}]`` of the cyclic sum [m], and whether the polygon path exists.

    It does not where a span has no common supporting line (overlapping polygons) or where
    a wrap ``s_i (A_i(out) - A_i(in))`` would be negative at some phases (a grazed wheel).
    """
    n = len(wheels)
    terms, exact = [], True
    outs, ins = [], []
    for i in range(n):
        j = (i + 1) % n
        wa, wb = wheels[i], wheels[j]
        pa, pb = grids[i][:, None], grids[j][None, :]
        alpha0 = float(circle.span_angle[i])
        out_ref = alpha0 - wa.side * math.pi / 2
        in_ref = float(circle.span_angle[j]) - wb.side * math.pi / 2 - wb.side * float(circle.wrap_angle[j])
        alpha, length, ang_a, ka, ang_b, kb, ok = _span(wa, wb, pa, pb, alpha0)
        a_out = _arc_position(wa, ang_a, ka, pa, out_ref)  # the phases broadcast against the angles
        a_in = _arc_position(wb, ang_b, kb, pb, in_ref)
        exact &= bool(ok.all())
        terms.append(length + wa.side * a_out - wb.side * a_in)
        outs.append(wa.side * a_out)  # (φ_i, φ_{i+1}) on wheel i
        ins.append(wb.side * a_in)  # (φ_i, φ_{i+1}) on wheel i+1
    if exact and n > 2:
        for i in range(n):
            # the shortest wrap of wheel i over the phases of its neighbours, at each of its phases
            shortest = np.minimum.reduce(outs[i], axis=1) - np.maximum.reduce(ins[(i - 1) % n], axis=0)
            exact &= bool(np.minimum.reduce(shortest) >= -1e-9)
    return terms, exact


def _max_plus_cycle(terms: list[np.ndarray], pick) -> float:
    reduce = {np.min: np.minimum.reduce, np.max: np.maximum.reduce}.get(pick, pick)  # the same, without the wrapper
    acc = terms[0]
    for m in terms[1:]:
        acc = reduce(acc[:, :, None] + m[None, :, :], axis=1)
    return float(reduce(acc.diagonal(), axis=0))


def loop_length_at_phases(
    pitch: float,
    centres: ArrayLike,
    teeth: Sequence[int | None],
    phases: ArrayLike,
    sides: ArrayLike | None = None,
    *,
    diameters: Sequence[float | None] | None = None,
    bar_diameter: float | None = None,
) -> float:
    r"""Taut chain length on the pitch polygons at given phases of the wheels [m].

    .. math:: L = \sum_i \ell_i + \sum_i s_i \bigl(A_i(\mathrm{out}) - A_i(\mathrm{in})\bigr)

    Parameters
    ----------
    pitch : float
        Chain pitch (inner link length of a round link chain) [m].
    centres : array_like, shape (n, 2)
        Wheel centres in the order of chain travel, counter-clockwise around the loop [m].
    teeth : sequence of int or None
        Teeth (pockets) of each wheel; ``None`` for a toothless idler (give ``diameters``).
    phases : array_like, shape (n,)
        Polar angle of the first hinge seated on each wheel [rad] (ignored for toothless ones).
    sides : array_like of {+1, -1}, optional
        +1 for a wheel inside the loop (default), -1 for one on the back of the chain.
    diameters : sequence of float or None, optional
        Running diameter of each toothless idler [m].
    bar_diameter : float, optional
        Bar diameter of a round link chain [m].

    Returns
    -------
    float
        Chain length [m].

    References
    ----------
    Derivation in the module notes (:mod:`chaindrive.layout.polygon_loop`); two-wheel case:
    :func:`chaindrive.layout.chain_length_polygon`; the polygon: Dolipiński et al., eq. (6).

    Examples
    --------
    >>> L = loop_length_at_phases(0.0254, [[0, 0], [1, 0]], [19, 19], [0.0, 0.0])
    >>> round(L / 0.0254 - 19, 6)  # equal wheels in equal phase: z + 2a/p
    78.740157
    """
    p, c, teeth, s = _check_inputs(pitch, centres, teeth, sides, diameters)
    ph = as_float_array("phases", phases)
    if ph.shape != (c.shape[0],):
        raise InputError(f"phases must give one angle per wheel ({c.shape[0]}), got shape {ph.shape}",
                         field="phases")
    wheels = _wheels(p, c, teeth, s, diameters, bar_diameter)
    circle = wrap_layout(c, [w.radius for w in wheels], s)
    terms, exact = _span_terms(wheels, [np.array([x]) for x in ph], circle)
    if not exact:
        raise InfeasibleError("no polygon path at these phases: the pitch polygons of two neighbouring wheels "
                              "overlap, or the chain only grazes a wheel (use chain_length_loop, which falls back "
                              "to the pitch circles)")
    return float(sum(float(t[0, 0]) for t in terms))


@dataclass(frozen=True)
class LoopLength(Result):
    """Chain length of a drive of any number of wheels on the pitch polygons.

    Attributes
    ----------
    links_min, links_max, links_mean : float
        Taut chain length over independent phases of every toothed wheel [pitches].
    links_circles : float
        Length on the pitch circles [pitches].
    exact : bool
        False when the pitch circles stood in (see the warning).
    """

    links_min: float = quantity("1")
    links_max: float = quantity("1")
    links_mean: float = quantity("1")
    links_circles: float = quantity("1")
    exact: bool


def _loop(p, c, teeth, s, diameters, bar_diameter, n, warn=True) -> LoopLength:
    wheels = _wheels(p, c, teeth, s, diameters, bar_diameter)
    circle = wrap_layout(c, [w.radius for w in wheels], s)
    grids = [_phase_grid(w, n) for w in wheels]
    circles = circle.length / p
    terms, exact = _span_terms(wheels, grids, circle)
    if not exact:
        if warn:
            warnings.warn("no exact polygon path for this layout (the polygons of neighbouring wheels overlap, or "
                          "the chain only grazes a wheel): the chain length is taken on the pitch circles",
                          ValidityRangeWarning, stacklevel=3)
        return LoopLength(links_min=circles, links_max=circles, links_mean=circles, links_circles=circles,
                          exact=False)
    return LoopLength(
        links_min=_max_plus_cycle(terms, np.min) / p, links_max=_max_plus_cycle(terms, np.max) / p,
        # t.mean(): its sum over its count (the same division)
        links_mean=float(sum(np.add.reduce(t, axis=None) / t.size for t in terms)) / p, links_circles=circles,
        exact=True)


def chain_length_loop(
    pitch: float,
    centres: ArrayLike,
    teeth: Sequence[int | None],
    sides: ArrayLike | None = None,
    *,
    diameters: Sequence[float | None] | None = None,
    bar_diameter: float | None = None,
    phases: int = 12,
) -> LoopLength:
    r"""Exact taut chain length around any number of wheels, over their phases.

    .. math:: X_{max} = \frac{1}{p}\max_{\varphi}\ \operatorname{tr}_{\max}
              \bigl(M_1 \otimes M_2 \otimes \dots \otimes M_N\bigr)

    (max-plus product of the span matrices; see the module notes).

    Parameters
    ----------
    pitch : float
        Chain pitch [m].
    centres : array_like, shape (n, 2)
        Wheel centres in chain order, counter-clockwise around the loop [m].
    teeth : sequence of int or None
        Teeth of each wheel; ``None`` for a toothless idler.
    sides : array_like of {+1, -1}, optional
        +1 inside the loop (default), -1 an idler on the back of the chain.
    diameters : sequence of float or None, optional
        Running diameters of the toothless idlers [m].
    bar_diameter : float, optional
        Bar diameter of a round link chain [m].
    phases : int
        Phases sampled per toothed wheel over one tooth period (as
        :func:`chaindrive.layout.chain_length_polygon`).

    Returns
    -------
    LoopLength

    Warns
    -----
    ValidityRangeWarning
        No exact polygon path (overlapping polygons, a grazed idler): pitch circles used.

    Notes
    -----
    For two toothed wheels equal to :func:`chaindrive.layout.chain_length_polygon` on
    the same grid (within 1e-9 pitch, tested); for three or more wheels inside the loop
    equal to the perimeter of the convex hull of all seated hinges (Qhull, tested); for
    many teeth it tends to the pitch-circle length.

    References
    ----------
    Derivation in :mod:`chaindrive.layout.polygon_loop`; Dolipiński et al., eq. (6) (the
    polygon).

    Examples
    --------
    >>> r = chain_length_loop(0.0254, [[0, 0], [1, 0], [0.5, 0.6]], [19, 19, 19], phases=4)
    >>> round(r.links_min, 3), round(r.links_max, 3)
    (119.865, 119.871)
    """
    p, c, teeth, s = _check_inputs(pitch, centres, teeth, sides, diameters)
    toothed = [int(z) for z in teeth if z]
    if int(phases) < 1:
        raise InputError(f"phases must be a whole number >= 1, got {phases}", field="phases")
    if len(toothed) >= 2:
        _check_phases(phases, max(toothed), max(toothed))
        # the max-plus product holds phases³ values at once (_max_plus_cycle)
        largest = round(MAX_PHASE_GRID ** (1 / 3))
        while largest ** 3 > MAX_PHASE_GRID:
            largest -= 1
        if int(phases) > largest:
            raise InputError(f"phases must be a whole number in [1, {largest}] for a loop of {len(toothed)} "
                             f"toothed wheels (the max-plus product holds phases³ values), got {phases}",
                             field="phases")
    return _loop(p, c, teeth, s, diameters, bar_diameter, int(phases))


@dataclass(frozen=True)
class LoopAdjustment(Result):
    """Position of the adjustable wheel for a whole number of links.

    Attributes
    ----------
    links : int
        Chain length [pitches].
    wheel : int
        Index of the adjustable wheel.
    direction : ndarray, shape (2,)
        Unit vector along which it moves.
    taut, loose : float
        Displacement from the given position [m] at which the chain is taut at its tightest
        phase (fits at every phase: the nominal setting) and at its loosest phase.
    circles : float
        Displacement on the pitch-circle model [m].
    position : ndarray, shape (2,)
        Centre of the adjustable wheel at ``taut`` [m].
    exact : bool
        False when the pitch circles stood in.
    """

    links: int = quantity("1")
    wheel: int = quantity("1")
    direction: np.ndarray = quantity("1")
    taut: float = quantity("m")
    loose: float = quantity("m")
    circles: float = quantity("m")
    position: np.ndarray = quantity("m")
    exact: bool


def _root(fun, target, start, step, what):
    """Root of ``fun(x) = target`` bracketed by steps from ``start`` (either slope)."""
    from .._roots import brentq

    def value(x):
        try:
            return fun(x) - target
        except InfeasibleError:
            raise InfeasibleError(f"no chain path with the {what} at {x:+.6g} m from its given position") from None

    f0 = value(start)
    sign = 1.0 if value(start + 1e-3 * step) >= f0 else -1.0  # the length's slope along the direction
    lo = hi = start
    flo = fhi = sign * f0
    k = 0
    while not (flo <= 0 <= fhi):
        k += 1
        if k > 80:
            raise InfeasibleError(f"no position of the {what} fits the chain")
        if fhi < 0:
            lo, flo = hi, fhi
            hi = hi + sign * step
            fhi = sign * value(hi)
        else:
            hi, fhi = lo, flo
            lo = lo - sign * step
            flo = sign * value(lo)
        step *= 2.0
    if flo == 0:
        return lo
    if fhi == 0:
        return hi
    return brentq(value, min(lo, hi), max(lo, hi), xtol=1e-13, rtol=1e-13)


def adjust_loop(
    pitch: float,
    centres: ArrayLike,
    teeth: Sequence[int | None],
    links: int,
    wheel: int,
    direction: ArrayLike,
    sides: ArrayLike | None = None,
    *,
    diameters: Sequence[float | None] | None = None,
    bar_diameter: float | None = None,
    phases: int = 12,
) -> LoopAdjustment:
    r"""Move one wheel along a direction until a chain of ``links`` pitches fits.

    .. math:: X_{max}(c_m + x_{taut} u) = N,\qquad X_{min}(c_m + x_{loose} u) = N

    Parameters
    ----------
    pitch : float
        Chain pitch [m].
    centres : array_like, shape (n, 2)
        Wheel centres (the adjustable one at its nominal position) [m].
    teeth : sequence of int or None
        Teeth of each wheel; ``None`` for a toothless idler.
    links : int
        Whole number of links ``N`` (see :func:`chaindrive.layout.even_links`).
    wheel : int
        Index of the adjustable wheel (take-up, movable sprocket, tensioner).
    direction : array_like, shape (2,)
        Direction in which it moves (non-zero; normalised here).
    sides, diameters, bar_diameter, phases
        As :func:`chain_length_loop`.

    Returns
    -------
    LoopAdjustment

    Raises
    ------
    InputError
        ``links`` not a whole number > 0, ``wheel`` out of range, zero ``direction``.
    InfeasibleError
        No position along the direction fits the chain.

    Notes
    -----
    The pitch-circle solution is found first (bracketed from the given position), then
    the taut and loose polygon solutions by Brent's method from it. With two toothed
    wheels and the second moving along the line of centres, ``taut`` and ``loose`` are
    those of :func:`chaindrive.layout.centre_distance_polygon` (within 1e-9 m, tested).

    References
    ----------
    Derivation in :mod:`chaindrive.layout.polygon_loop`.

    Examples
    --------
    >>> r = adjust_loop(0.0254, [[0, 0], [1, 0]], [19, 19], 98, 1, [1, 0], phases=2)
    >>> round(1 + r.taut, 4)
    1.0033
    """
    p, c, teeth, s = _check_inputs(pitch, centres, teeth, sides, diameters)
    n_links = as_float_array("links", links)
    if n_links.ndim or n_links != np.round(n_links) or n_links <= 0:
        raise InputError(f"links must be a whole number > 0, got {links!r}", field="links")
    N = int(n_links)
    if isinstance(wheel, bool) or int(wheel) != wheel or not 0 <= int(wheel) < c.shape[0]:
        raise InputError(f"wheel must be an index in [0, {c.shape[0] - 1}], got {wheel!r}", field="wheel")
    m = int(wheel)
    u = as_float_array("direction", direction)
    if u.shape != (2,) or not np.hypot(*u) > 0:
        raise InputError(f"direction must be a non-zero vector (x, y), got {direction!r}", field="direction")
    u = u / np.hypot(*u)
    chain_length_loop(p, c, teeth, s, diameters=diameters, bar_diameter=bar_diameter, phases=phases)  # checks
    wheels = _wheels(p, c, teeth, s, diameters, bar_diameter)
    radii = [w.radius for w in wheels]

    def moved(x):
        cc = c.copy()
        cc[m] = c[m] + x * u
        return cc

    def circles(x):
        return wrap_layout(moved(x), radii, s).length / p

    # the length must grow along +u; flip the direction if it shrinks
    x_c = _root(circles, N, 0.0, p, "adjustable wheel")
    exact = True
    cache: dict[float, LoopLength] = {}

    def loop(x):
        if x not in cache:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", ValidityRangeWarning)
                cache[x] = _loop(p, moved(x), teeth, s, diameters, bar_diameter, int(phases), warn=False)
        return cache[x]

    if not loop(x_c).exact:
        warnings.warn("no exact polygon path for this layout: the adjustable wheel is placed on the pitch circles",
                      ValidityRangeWarning, stacklevel=2)
        return LoopAdjustment(links=N, wheel=m, direction=u, taut=x_c, loose=x_c, circles=x_c,
                              position=moved(x_c)[m], exact=False)
    taut = _root(lambda x: loop(x).links_max, N, x_c, 0.5 * p, "adjustable wheel")
    loose = _root(lambda x: loop(x).links_min, N, taut, 0.5 * p, "adjustable wheel")
    exact = loop(taut).exact and loop(loose).exact
    return LoopAdjustment(links=N, wheel=m, direction=u, taut=float(taut), loose=float(loose), circles=float(x_c),
                          position=moved(taut)[m], exact=exact)


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
