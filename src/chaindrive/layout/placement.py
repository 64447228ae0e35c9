"""Where wheels may sit: clearance between wheels and spans, and a wheel placed for a wrap.

Pure geometry on the pitch circles (:func:`chaindrive.layout.wrap_layout`): the drive's
checks (:mod:`chaindrive.analysis.layout`) and the ``chaindrive layout --place``
command use these.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike

from .._validation import as_float_array
from ..errors import InfeasibleError, InputError
from .wrap import wrap_layout

__all__ = ["clearance_problems", "place_for_wrap"]


def clearance_problems(centres: ArrayLike, radii: ArrayLike, sides: ArrayLike | None = None,
                       ) -> list[tuple[str, int, int, float]]:
    r"""Wheels that overlap and spans that cross a wheel, on the pitch circles.

    Two wheels ``i, j`` overlap when ``|c_i − c_j| < R_i + R_j`` (coincident centres
    included); span ``j`` (wheel ``j`` to ``j+1``) crosses wheel ``k`` (any other) when
    the segment between its tangent points comes nearer the centre than ``R_k``:

    .. math:: \min_{0≤t≤1} |P_j + t (Q_j − P_j) − c_k| < R_k

    Parameters
    ----------
    centres : array_like, shape (n, 2)
        [m].
    radii : array_like, shape (n,)
        Pitch radii [m].
    sides : array_like, optional
        ±1 per wheel as :func:`~chaindrive.layout.wrap_layout`.

    Returns
    -------
    list of (kind, i, j, distance)
        ``("overlap", i, j, centre distance)`` and ``("crossing", span, wheel,
        distance of the span from the wheel's centre)`` [m]; empty when the layout is
        clear.

    References
    ----------
    Plane geometry (distance of a point from a segment).

    Examples
    --------
    >>> clearance_problems([[0, 0], [0.15, 0], [1, 0.5]], [0.15, 0.125, 0.1])
    [('overlap', 0, 1, 0.15)]
    """
    return _clearance(as_float_array("centres", centres), as_float_array("radii", radii), sides)[0]


def _clearance(c: np.ndarray, r: np.ndarray, sides: ArrayLike | None):
    """(:func:`clearance_problems`, the wrap layout or ``None`` where there is none)."""
    n = len(c)
    out: list[tuple[str, int, int, float]] = []
    diff = c[:, None, :] - c[None, :, :]
    dist = np.hypot(diff[..., 0], diff[..., 1])
    close = dist < (r[:, None] + r[None, :]) * (1 - 1e-9)
    # each wheel is close to itself: only more than n close pairs name an overlap
    for i, j in (zip(*np.nonzero(np.triu(close, 1)), strict=True) if np.count_nonzero(close) > n else ()):
        out.append(("overlap", int(i), int(j), float(dist[i, j])))
    if out:
        return out, None
    try:
        wrap = wrap_layout(c, r, sides)
    except InfeasibleError:
        return out, None
    if n <= 2:  # every centre is an end of both spans: none to check
        return out, wrap
    a, b = np.asarray(wrap.span_start), np.asarray(wrap.span_end)
    ab = b - a
    den = np.maximum(np.sum(ab * ab, axis=1), 1e-300)
    # distance of every centre k from every span j: (j, k)
    rel = c[None, :, :] - a[:, None, :]
    # the dot product over the two coordinates, clipped to the span (np.einsum and np.clip written out)
    t = np.minimum(np.maximum((rel[..., 0] * ab[:, None, 0] + rel[..., 1] * ab[:, None, 1]) / den[:, None], 0.0), 1.0)
    near = a[:, None, :] + t[..., None] * ab[:, None, :] - c[None, :, :]
    gap = np.hypot(near[..., 0], near[..., 1]).tolist()
    reach = [float(rk) * (1 - 1e-9) for rk in r.tolist()]
    for j in range(n):
        for k in range(n):
            if k not in (j, (j + 1) % n) and gap[j][k] < reach[k]:
                out.append(("crossing", j, k, gap[j][k]))
    return out, wrap


def place_for_wrap(centres: ArrayLike, radii: ArrayLike, sides: ArrayLike | None, index: int,
                   direction: ArrayLike, wrap: float, *, target: int | None = None,
                   reach: float | None = None, steps: int = 200, tolerance: float = 1e-13) -> float:
    r"""Distance [m] to move wheel ``index`` along ``direction`` so that wheel ``target``
    has the chain wrapped over ``wrap`` [rad].

    Solves :math:`θ_{target}(c_{index} + s\,\hat d) = θ_{req}` for the smallest move
    ``|s|`` (a scan in ``steps`` steps each way over ``[−reach, reach]`` from ``s = 0``,
    then bisection on the first sign change, to ``tolerance``; the edge of a clear layout found
    by bisection too), where the layout stays clear (:func:`clearance_problems`).

    Parameters
    ----------
    centres, radii, sides
        The layout as for :func:`~chaindrive.layout.wrap_layout`.
    index : int
        The wheel moved.
    direction : array_like, shape (2,)
        Its line of travel (normalised here).
    wrap : float
        Requested wrap on ``target``, ``0 < wrap < 2π`` [rad].
    target : int, optional
        The wheel whose wrap is set (default ``index``).
    reach : float, optional
        Longest move searched [m]; default twice the layout's largest extent.
    steps : int
        Scan steps each way.
    tolerance : float
        Width [m] to which the root and a clear layout's edge are bisected.

    Returns
    -------
    float
        ``s`` [m] (negative: against ``direction``).

    Raises
    ------
    InputError
        No position along the line within ``reach`` gives that wrap with the layout
        clear (field ``wrap``), or a bad argument.

    References
    ----------
    Wrap angles of :func:`~chaindrive.layout.wrap_layout` (the belt problem).

    Examples
    --------
    >>> c = [[0, 0], [0.5, -0.1], [1, 0]]     # a corner wheel under the chord, moved down
    >>> s = place_for_wrap(c, [0.1, 0.05, 0.1], None, 1, [0, -1], math.radians(60))
    >>> round(float(np.degrees(wrap_layout(np.array(c) + [[0, 0], [0, -s], [0, 0]],
    ...     [0.1, 0.05, 0.1]).wrap_angle[1])), 6)
    60.0
    """
    c = as_float_array("centres", centres).copy()
    n = len(c)
    if not 0 <= int(index) < n:
        raise InputError(f"index must be in 0..{n - 1}, got {index}", field="wheel")
    tgt = int(index) if target is None else int(target)
    if not 0 <= tgt < n:
        raise InputError(f"target must be in 0..{n - 1}, got {target}", field="target")
    d = as_float_array("direction", direction)
    if d.shape != (2,) or not float(np.hypot(*d)) > 0:
        raise InputError(f"direction must be a non-zero 2-vector, got {direction!r}", field="direction")
    d = d / float(np.hypot(*d))
    if not 0 < float(wrap) < 2 * math.pi:
        raise InputError(f"wrap must lie in (0°, 360°), got {math.degrees(float(wrap)):.6g}°", field="wrap")
    span = float(np.max(np.ptp(c, axis=0)))
    reach = 2.0 * max(span, 1e-3) if reach is None else float(reach)
    if not 0 < reach <= 1e4:
        raise InputError(f"reach must lie in (0, 10000] m, got {reach:g}", field="reach")
    if not 0 < float(tolerance) <= reach:
        raise InputError(f"tolerance must lie in (0, reach = {reach:g}] m, got {float(tolerance):g}",
                         field="tolerance")
    if isinstance(steps, bool) or not 2 <= int(steps) <= 10_000 or int(steps) != steps:
        raise InputError(f"steps must be a whole number in [2, 10000], got {steps!r}", field="steps")
    base = c[int(index)].copy()

    r = as_float_array("radii", radii)

    def theta(s: float) -> float:
        c[int(index)] = base + s * d
        problems, lay = _clearance(c, r, sides)
        if problems or lay is None:      # not clear, or no simple loop there
            return math.nan
        return float(lay.wrap_angle[tgt]) - float(wrap)

    def edge(good: float, bad: float) -> float:
        """The last clear position between a clear ``good`` and an unclear ``bad`` (bisection)."""
        for _ in range(200):  # halving 2 reach down to tolerance: far fewer steps
            if abs(good - bad) <= tolerance:
                break
            mid = 0.5 * (good + bad)
            if math.isnan(theta(mid)):
                bad = mid
            else:
                good = mid
        return good

    def bisect(a: float, va: float, b: float) -> float | None:
        """Root between ``a`` (value ``va``) and ``b`` of opposite signs; ``None`` where the
        layout stops being clear inside (no continuous wrap there)."""
        for _ in range(80):
            mid = 0.5 * (a + b)
            vm = theta(mid)
            if math.isnan(vm):
                return None
            if vm == 0 or abs(b - a) < tolerance:
                return mid
            if (vm < 0) == (va < 0):
                a, va = mid, vm
            else:
                b = mid
        return 0.5 * (a + b)

    def scan(sign: float) -> float | None:
        grid = sign * np.linspace(0.0, reach, int(steps) + 1)
        prev_s, prev_v = 0.0, math.nan
        for i, s in enumerate(grid):
            a, b, v = prev_s, float(s), theta(float(s))
            vb = v
            if i == 0:
                prev_s, prev_v = b, vb
                continue
            if math.isnan(v) != math.isnan(prev_v):
                # the layout becomes (or stops being) clear inside this step: test up to its edge
                if math.isnan(v):
                    b = edge(a, b)
                    v = theta(b)
                else:
                    a = edge(b, a)
                    prev_v = theta(a)
            if not math.isnan(v) and not math.isnan(prev_v) and prev_v * v <= 0:
                if v == 0:
                    return b
                if prev_v == 0:
                    return a
                root = bisect(a, prev_v, b)
                if root is not None:
                    return root
            prev_s, prev_v = float(s), vb
        return None

    found = [x for x in (scan(1.0), scan(-1.0)) if x is not None]
    if found:
        return min(found, key=abs)
    raise InputError(f"no position within ±{reach:.6g} m along ({d[0]:.6g}, {d[1]:.6g}) gives wheel {tgt} a wrap "
                     f"of {math.degrees(float(wrap)):.6g}° with the wheels and spans clear of each other",
                     field="wrap")


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function: NaN/inf in or out refused, numerical failures one line
