"""Placement of the chain on the wheels before the static solve (internal to the simulation).

The loop path (pitch circles joined by their common tangents), the centre of the
adjusting wheel for which the path holds exactly ``N`` links, and the pins placed link by
link (:func:`_place`); see :mod:`chaindrive.simulation.run` (Assembly, steps 1-2).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit, types
from numba.extending import intrinsic

from ..errors import InfeasibleError
from .model import SimulationModel


# ---------------------------------------------------------------------------- geometry
def _tangent(c1, r1, c2, r2):
    """Tangent for travel from circle 1 to circle 2: (P1, P2, u, n).

    Radii are signed: positive for a wheel the chain wraps counter-clockwise (inside
    the loop), negative for one it wraps clockwise (an outside idler on the back of the
    chain); the chain touches circle i at ``c_i − r_i n`` (outer tangent for equal
    signs, crossed tangent otherwise).
    """
    d = np.subtract(c2, c1)
    dist = math.hypot(*d)
    if not dist > abs(r2 - r1):
        # also coincident centres (dist = 0), which the assembly's search can pass through
        raise InfeasibleError("wheels overlap: centre distance must exceed the radius "
                              f"difference ({dist:.6g} m <= {abs(r2 - r1):.6g} m)")
    al = math.asin((r2 - r1) / dist)
    dh = d / dist
    ca, sa = math.cos(-al), math.sin(-al)
    u = np.array([ca * dh[0] - sa * dh[1], sa * dh[0] + ca * dh[1]])
    n = np.array([-u[1], u[0]])
    return np.asarray(c1) - r1 * n, np.asarray(c2) - r2 * n, u, n


def _path(centres, radii, teeth, pitch):
    """Path pieces [(kind, data, metric length in m)] starting at wheel 0's exit.

    ``radii`` signed (see :func:`_tangent`); an arc's data is ``(wheel, entry angle,
    sense)``, sense +1 counter-clockwise, −1 clockwise.
    """
    nw = len(centres)
    tans = [_tangent(centres[i], radii[i], centres[(i + 1) % nw], radii[(i + 1) % nw])
            for i in range(nw)]
    pieces = []
    wraps = []
    for i in range(nw):
        p1, p2, u, n = tans[i]
        length = float(np.hypot(*(p2 - p1)))
        pieces.append(("span", (p1, u), length))
        j = (i + 1) % nw
        n_out = tans[j][3]
        sj = 1.0 if radii[j] > 0 else -1.0
        # direction from the centre to the chain: -n (counter-clockwise wrap), +n (clockwise)
        a_in = math.atan2(-sj * n[1], -sj * n[0])
        a_out = math.atan2(-sj * n_out[1], -sj * n_out[0])
        wrap = (sj * (a_out - a_in)) % (2 * math.pi)
        pieces.append(("arc", (j, a_in, sj), wrap * teeth[j] / (2 * math.pi) * pitch))
        wraps.append(sj * wrap)
    if abs(sum(wraps) - 2 * math.pi) > 1e-6:
        # a wheel lies inside the hull of the others (the chain would not touch it), or an
        # outside idler does not press on the chain
        raise InfeasibleError("the wheels do not form a chain loop: the signed wraps add up to "
                              f"{sum(wraps):.4g} rad instead of 2π (a wheel inside the loop "
                              "formed by the others, or an outside idler not pressing on the "
                              "chain); move it")
    return pieces


def _centres(model: SimulationModel, adjust: int, direction, s):
    c = np.array([w.centre for w in model.wheels], dtype=float)
    c[adjust] += s * np.asarray(direction)
    return c


def _adjust(model: SimulationModel):
    if model.tensioner is not None:
        d = np.asarray(model.tensioner.direction, float)
        return model.tensioner.wheel, d / np.hypot(*d)
    last = len(model.wheels) - 1
    d = np.subtract(model.wheels[last].centre, model.wheels[0].centre)
    return last, d / np.hypot(*d)


def _place(model: SimulationModel, exact: bool = False):
    """Pin positions on the path, wheel angles, adjusting offset.

    Round link chains, and roller chains with ``exact``: every link at its exact length
    (:func:`_place_exact`); else (roller chains, the relaxation's start) pins every pitch
    along the metric path (links across a span's tangent point a little short).
    """
    if model.is_link_chain or exact:
        return _place_exact(model)
    p, n = model.pitch, model.links
    radii = model.signed_radii()
    teeth = [w.path_teeth(p) for w in model.wheels]
    adj, d = _adjust(model)

    def excess(s):
        pieces = _path(_centres(model, adj, d, s), radii, teeth, p)
        return sum(x[2] for x in pieces) - n * p

    s0 = _solve_offset(excess, n, p, adj)
    return _place_roller(model, p, n, radii, teeth, adj, d, s0)


def _solve_offset(excess, n, p, adj):
    """Offset of the adjusting wheel along its line that makes ``excess`` zero [m]."""
    from .._roots import brentq

    lo, hi = -0.2 * n * p, 0.2 * n * p
    try:
        s0 = brentq(excess, lo, hi, xtol=1e-12) if excess(lo) * excess(hi) < 0 else None
    except (ValueError, InfeasibleError):
        s0 = None
    if s0 is None:
        # search a bracket near 0: the grid's intervals nearest 0 first (ties: the lower
        # one, as np.argmin over all of them would choose)
        grid = np.linspace(lo, hi, 401)
        known: dict[int, float] = {}
        reasons: dict[int, str] = {}

        def value(k):
            if k not in known:
                try:
                    known[k] = excess(grid[k])
                except InfeasibleError as exc:
                    known[k] = np.nan
                    reasons[k] = str(exc)
            return known[k]

        for k in np.argsort(np.abs(grid[:-1]), kind="stable"):
            a, b = value(k), value(k + 1)
            if np.isfinite(a) and np.isfinite(b) and a * b <= 0:
                return brentq(excess, grid[k], grid[k + 1], xtol=1e-12)
        reason = reasons[max(reasons)] if reasons else ""   # the last one along the grid
        why = f" ({reason})" if not np.any(np.isfinite(list(known.values()))) and reason else ""
        raise InfeasibleError(f"no position of wheel {adj} fits a loop of {n} links{why}")
    return s0


def _place_roller(model, p, n, radii, teeth, adj, d, s0):
    centres = _centres(model, adj, d, s0)
    pieces = _path(centres, radii, teeth, p)
    pos = np.zeros((n, 2))
    theta = np.full(len(teeth), np.nan)
    # wheel 0: a seat at its exit point
    a_exit0 = pieces[-1][1][1] + pieces[-1][2] / p * 2 * math.pi / teeth[0]
    theta[0] = a_exit0
    starts = np.cumsum([0.0] + [x[2] for x in pieces])
    for k in range(n):
        sk = k * p
        i = min(np.searchsorted(starts, sk, side="right") - 1, len(pieces) - 1)
        kind, data, _ = pieces[i]
        local = sk - starts[i]
        if kind == "span":
            pos[k] = data[0] + local * data[1]
        else:
            j, a_in, sj = data
            ang = a_in + sj * local / p * 2 * math.pi / teeth[j]
            if np.isnan(theta[j]):
                theta[j] = ang
            pos[k] = centres[j] + abs(radii[j]) * np.array([math.cos(ang), math.sin(ang)])
    theta = np.where(np.isnan(theta), 0.0, theta)
    return pos, theta, centres, adj, d, s0, pieces


def _hit(piece, centres, radii, wrap, point, length, after):
    """Parameter of the first point of ``piece`` at distance ``length`` from ``point``.

    Span: arc length ``s`` from its start; arc: angle turned from its entry (in the
    sense of the wrap: counter-clockwise, or clockwise round an outside idler). Only
    parameters ``> after`` (and inside the piece) count; ``None`` if there is none.
    """
    kind, data, metric = piece
    tol = 1e-12
    if kind == "span":
        q, u = data
        w = point - q
        b = float(w @ u)
        disc = b * b - (float(w @ w) - length * length)
        if disc < 0.0:
            return None
        s = b + math.sqrt(disc)
        return s if after < s <= metric + tol else None
    j, a_in, sense = data
    c, r = centres[j], abs(radii[j])
    dv = point - c
    dist = math.hypot(*dv)
    cosv = (dist * dist + r * r - length * length) / (2.0 * r * dist)
    if abs(cosv) > 1.0:
        return None
    phi = math.atan2(dv[1], dv[0])
    best = None
    for sign in (1.0, -1.0):
        rel = (sense * (phi + sign * math.acos(cosv) - a_in)) % (2.0 * math.pi)
        if rel > 2.0 * math.pi - 1e-9:
            rel -= 2.0 * math.pi
        if after < rel <= wrap[j] + tol and (best is None or rel < best):
            best = rel
    return best


@intrinsic
def _fma(typingctx, a, b, c):
    """``a b + c`` rounded once (LLVM's ``fma``)."""
    def codegen(context, builder, signature, args):
        return builder.fma(*args)
    return types.float64(types.float64, types.float64, types.float64), codegen


@njit(cache=True, fastmath=False)
def _span_pins(pos, pars, k, n, par, q0, q1, u0, u1, metric, length0, length1):
    """Pins ``k + 1, k + 2, ...`` placed along one span while they fall on it (the span
    case of :func:`_hit`, as numpy rounds it: its two-element dot products ``w·u`` as
    ``fma(w₁, u₁, w₀ u₀)``); returns the last pin placed and its parameter."""
    while k < n:
        length = length0 if k % 2 == 0 else length1
        w0 = pos[k, 0] - q0
        w1 = pos[k, 1] - q1
        b = _fma(w1, u1, w0 * u0)
        disc = b * b - (_fma(w1, w1, w0 * w0) - length * length)
        if disc < 0.0:
            break
        s = b + math.sqrt(disc)
        if not (par + 1e-12 < s <= metric + 1e-12):
            break
        pos[k + 1, 0] = q0 + s * u0
        pos[k + 1, 1] = q1 + s * u1
        pars[k + 1] = s
        par = s
        k += 1
    return k, par


_DOT_IS_FMA: list[bool] = []


def _dot_is_fma() -> bool:
    """Does numpy round a two-element dot product ``w @ u`` as ``fma(w₁, u₁, w₀ u₀)``
    (its BLAS kernel on this machine)? Then :func:`_span_pins` places the pins exactly
    as :func:`_hit` does; else the walk stays in Python."""
    if not _DOT_IS_FMA:
        from fractions import Fraction

        rng = np.random.default_rng(20261129)
        same = True
        for _ in range(64):
            w, u = rng.standard_normal(2) * 10.0, rng.standard_normal(2)
            exact = Fraction(float(w[1])) * Fraction(float(u[1])) + Fraction(float(w[0]) * float(u[0]))
            same &= float(w @ u) == float(exact)
        _DOT_IS_FMA.append(bool(same))
    return _DOT_IS_FMA[0]


def _walk(centres, radii, pieces, wrap, lengths, n):
    """Pins 0..n placed link by link (exact link lengths) along the path from wheel 0's exit.

    Returns the positions (n + 1, 2), the piece index and parameter of each pin and the
    closure: path coordinate of pin ``n`` minus the loop length (0 when it meets pin 0).
    """
    npc = len(pieces)
    starts = np.cumsum([0.0] + [x[2] for x in pieces])
    pos = np.zeros((n + 1, 2))
    where = [(0, 0.0)]
    pos[0] = pieces[0][1][0]
    ip, par = 0, 0.0
    fast = _dot_is_fma()
    pars = np.zeros(n + 1)
    k = 0
    while k < n:
        kind, data, metric = pieces[ip % npc]
        if fast and kind == "span":
            # the pins that follow on this span, compiled
            last, par = _span_pins(pos, pars, k, n, par, data[0][0], data[0][1], data[1][0],
                                   data[1][1], metric, lengths[0], lengths[1])
            where.extend((ip, float(pars[i])) for i in range(k + 1, last + 1))
            k = last
            if k == n:
                break
        length = lengths[k % 2]
        after = par + 1e-12
        for step in range(npc + 1):
            piece = pieces[(ip + step) % npc]
            hit = _hit(piece, centres, radii, wrap, pos[k], length, after if step == 0 else -1e-12)
            if hit is not None:
                ip, par = ip + step, hit
                break
        else:
            raise InfeasibleError("the chain does not fit the path (a link longer than a "
                                  "span and its neighbouring wrap?)")
        kind, data, _ = pieces[ip % npc]
        if kind == "span":
            pos[k + 1] = data[0] + par * data[1]
        else:
            j, a_in, sense = data
            a = a_in + sense * par
            pos[k + 1] = centres[j] + abs(radii[j]) * np.array([math.cos(a), math.sin(a)])
        where.append((ip, par))
        k += 1
    ip, par = where[-1]
    kind, data, metric = pieces[ip % npc]
    frac = par / wrap[data[0]] if kind == "arc" else par / metric
    coord = (ip // npc) * starts[-1] + starts[ip % npc] + frac * metric
    return pos, where, coord - starts[-1]


def _place_exact(model: SimulationModel):
    """Pins on the wheels' polygons and the spans, every link at its exact length.

    The adjusting offset is first found on the metric path (a wrap of angle ``γ`` on a
    wheel of ``z`` seats per turn holds ``γ z/2π`` links of mean length; ``2z`` seats on
    a pocket wheel), then refined so that the chain placed link by link (roller chain:
    every link ``p``; round link chain: ``t + d``, ``t − d`` alternating; seated pins on
    the polygon vertices, free pins on the tangent lines) closes exactly (Brent's method).
    """
    from .._roots import brentq

    t, n = model.pitch, model.links
    radii = model.signed_radii()
    if model.is_link_chain:
        nseat: list[float] = [float(model.seats_per_turn(w.teeth)) for w in model.wheels]
    else:
        nseat = [w.path_teeth(t) for w in model.wheels]
    lengths = model.link_lengths
    adj, d = _adjust(model)

    def excess(s):
        pieces = _path(_centres(model, adj, d, s), radii, nseat, t)
        return sum(x[2] for x in pieces) - n * t

    def layout(s):
        centres = _centres(model, adj, d, s)
        pieces = _path(centres, radii, nseat, t)
        wrap = {x[1][0]: x[2] / t * 2 * math.pi / nseat[x[1][0]] for x in pieces if x[0] == "arc"}
        return centres, pieces, wrap

    walks: dict[float, tuple] = {}

    def walk(s):
        # each offset walked once: Brent's method starts from the bracket's ends, which
        # the bracket search has walked, and its root is one of its own points
        if s not in walks:
            centres, pieces, wrap = layout(s)
            walks[s] = (centres, pieces, wrap, _walk(centres, radii, pieces, wrap, lengths, n))
        return walks[s]

    def closure(s):
        return walk(s)[3][2]

    s0 = _solve_offset(excess, n, t, adj)
    step = 0.25 * t
    f0 = closure(s0)
    s1 = s0
    for _ in range(40):
        # a longer path (larger offset) leaves pin n short of pin 0: closure falls with s
        s1 = s1 - step if f0 < 0 else s1 + step
        try:
            f1 = closure(s1)
        except InfeasibleError:
            break
        if f1 * f0 <= 0:
            break
    else:
        f1 = f0
    if f1 * f0 > 0:
        raise InfeasibleError(f"no position of wheel {adj} closes a loop of {n} links")
    sc = brentq(closure, min(s0, s1), max(s0, s1), xtol=1e-13) if f0 != 0 else s0
    centres, pieces, wrap, (pos, where, _) = walk(sc)
    npc = len(pieces)
    theta = np.full(len(model.wheels), np.nan)
    # wheel 0: pin 0 (even seat 0) at its exit point
    _, a0 = pieces[-1][1][:2]
    theta[0] = a0 + wrap[0]
    for k, (ip, par) in enumerate(where[:n]):
        kind, data, _ = pieces[ip % npc]
        if kind == "arc" and np.isnan(theta[data[0]]):
            j, a_in, sense = data
            # pin k sits on seat k mod 2 (seat 0 at angle 0, seat 1 at the even link's
            # angle); a sprocket's seats are all alike
            da = model.central_angles(model.wheels[j].teeth)[0] if model.is_link_chain else 0.0
            theta[j] = a_in + sense * par - (da if k % 2 else 0.0)
    theta = np.where(np.isnan(theta), 0.0, theta)
    # the offset of the metric path is returned: a tensioner's spring preload is defined
    # at that position, whichever placement is used
    return pos[:n].copy(), theta, centres, adj, d, s0, pieces
