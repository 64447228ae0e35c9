"""Take-up for wear elongation: centre-distance increase and tensioner travel."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from .._finite import finite_guard
from .._validation import as_float_array, check_nonnegative, check_positive
from ..errors import InfeasibleError, InputError
from .two_wheels import _belt_length
from .wheels import pitch_radius
from .wrap import MATH_TRIG, _loop_length, _loop_lengths, _span_scalar, wrap_layout


@finite_guard
def centre_distance_travel(
    pitch: float,
    teeth_1: int,
    teeth_2: int,
    centre_distance: float,
    elongation: ArrayLike,
    *,
    bar_diameter: float | None = None,
) -> np.ndarray:
    r"""Increase of centre distance that takes up a chain elongation (two wheels).

    .. math:: L_c(a + \Delta a) = (1 + e)\, L_c(a)

    Parameters
    ----------
    pitch : float
        [m].
    teeth_1, teeth_2 : int
        [-].
    centre_distance : float
        Initial centre distance [m] (chain taut on the pitch circles).
    elongation : float or array_like
        Relative elongation ``e`` of the chain (0.03 for 3 %) [-].
    bar_diameter : float, optional
        [m].

    Returns
    -------
    ndarray
        ``Δa`` [m], same shape as ``elongation``; about ``e L / 2``.

    Notes
    -----
    Uses the pitch-circle model with the worn pitch ``p(1+e)``: the worn chain rides
    higher on the teeth, which this neglects (conservative: it overstates travel by
    the radius growth, ``≈ e R`` per wheel).

    References
    ----------
    Belt model of :func:`chain_length_circles`.

    Examples
    --------
    >>> round(float(centre_distance_travel(0.0254, 19, 57, 1.05, 0.03)), 4)
    0.0468
    """
    from .._roots import brentq

    e = check_nonnegative("elongation", elongation)
    a0 = float(check_positive("centre_distance", centre_distance, "m"))
    p = float(pitch)
    r1 = float(pitch_radius(p, teeth_1, bar_diameter))
    r2 = float(pitch_radius(p, teeth_2, bar_diameter))
    L0 = float(_belt_length(a0, r1, r2))
    out = np.empty(e.shape).ravel()
    for i, ei in enumerate(e.ravel()):
        if ei == 0:
            out[i] = 0.0
            continue
        target = L0 * (1 + ei)
        out[i] = brentq(lambda a, t=target: _belt_length(a, r1, r2) - t, a0, a0 + target) - a0
    return out.reshape(e.shape)


@finite_guard
def tensioner_travel(
    centres: ArrayLike,
    radii: ArrayLike,
    sides: ArrayLike | None,
    index: int,
    direction: ArrayLike,
    elongation: ArrayLike,
    *,
    chain_length: float | None = None,
    extra_length: float = 0.0,
) -> np.ndarray:
    r"""Travel of a tensioner wheel that takes up a chain elongation (any layout).

    .. math:: L(c_k + s\,\mathbf{u}) = L(c_k) + \Delta L_0 + e\,L_{chain}

    Parameters
    ----------
    centres, radii, sides
        The layout as for :func:`wrap_layout`.
    index : int
        Index of the tensioner wheel (it moves; the others stay).
    direction : array_like, shape (2,)
        Direction of the tensioner's travel (normalised here); it must lengthen the
        chain path (e.g. pushing into the slack span).
    elongation : float or array_like
        Relative elongation ``e`` [-] (0.01, 0.02, 0.03).
    chain_length : float, optional
        Length of the new chain ``L_chain`` [m]; default the path length ``L(c_k)``.
    extra_length : float
        Slack ``ΔL_0 >= 0`` of the new chain over the path at the given position [m]
        (a chain rounded up to whole links), taken up first.

    Returns
    -------
    ndarray
        Travel ``s`` [m] from the given position for each elongation.

    Raises
    ------
    InfeasibleError
        If moving along ``direction`` does not lengthen the path enough (the
        tensioner runs out of the loop geometry).

    Notes
    -----
    Pitch-circle model (:func:`wrap_layout`); root by Brent's method.

    References
    ----------
    Layout model of this package (docs/drive.md).

    Examples
    --------
    >>> c = [[0, 0], [1, -0.2], [2, 0]]  # back-side idler under the lower span
    >>> s = tensioner_travel(c, [0.2, 0.05, 0.2], [1, -1, 1], 1, [0, 1], [0.01, 0.03])
    >>> np.round(s, 4)
    array([0.184 , 0.3517])
    """
    from .._roots import brentq

    c = as_float_array("centres", centres)
    lay0 = wrap_layout(c, radii, sides)
    u = as_float_array("direction", direction)
    if u.shape != (2,) or not np.hypot(*u) > 0:
        raise InputError(f"direction must be a non-zero 2-vector, got {direction!r}")
    u = u / np.hypot(*u)
    k = int(index)
    if not 0 <= k < c.shape[0]:
        raise InputError(f"index must lie in [0, {c.shape[0] - 1}], got {index}")
    e = check_nonnegative("elongation", elongation)
    extra = float(check_nonnegative("extra_length", extra_length, "m"))
    Lch = lay0.length if chain_length is None else float(check_positive("chain_length", chain_length, "m"))

    r, sd = lay0.radii, lay0.sides

    def positions(s):  # centres with the tensioner moved by s (array of travels)
        cc = np.broadcast_to(c, np.shape(s) + c.shape).copy()
        cc[..., k, :] = c[k] + np.asarray(s)[..., None] * u
        return cc

    small = c.shape[0] <= 7
    if small:  # Python floats for a few wheels (_loop_length, the math module's trigonometry)
        xs, ys, rl, sl = c[:, 0].tolist(), c[:, 1].tolist(), r.tolist(), sd.tolist()
        ck, uk = c[k].tolist(), u.tolist()
        n = len(xs)
        rho = [a * b for a, b in zip(sl, rl, strict=True)]
        # the spans that do not touch the moving wheel, once
        fixed = [None if i in ((k - 1) % n, k) else _span_scalar(xs, ys, rho, i, MATH_TRIG) for i in range(n)]

        def length(s):
            xs[k], ys[k] = ck[0] + s * uk[0], ck[1] + s * uk[1]
            return _loop_length(xs, ys, rl, sl, fixed, MATH_TRIG)
    else:
        def length(s):
            return float(_loop_lengths(positions(np.array([s])), r, sd)[0])

    out = np.empty(e.size)
    smax = float(np.max(np.hypot(*(c - c[k]).T))) + float(np.max(lay0.radii)) * 4
    grid = np.linspace(0, smax, 120)
    vals = None if small else _loop_lengths(positions(grid), r, sd)  # bracket the roots once for all e
    steps = grid.tolist()
    seen: dict[int, float] = {}  # a few wheels: the grid's lengths walked from s = 0 as far as a root needs

    def first_reaching(target: float) -> int | None:
        if vals is not None:
            idx = np.nonzero(vals >= target)[0]
            return int(idx[0]) if idx.size else None
        for j in range(1, len(steps)):
            if j not in seen:
                seen[j] = length(steps[j])
            if seen[j] >= target:
                return j
        return None

    for i, ei in enumerate(e.ravel()):
        target = lay0.length + extra + ei * Lch
        if target <= lay0.length:
            out[i] = 0.0
            continue
        j = first_reaching(target)
        if j is None:
            vals = _loop_lengths(positions(grid), r, sd)
            raise InfeasibleError(
                f"the tensioner cannot take up an elongation of {ei:g} (plus {extra:g} m of "
                f"initial slack): moving it along "
                f"{u.tolist()} lengthens the chain path by at most "
                f"{(np.max(vals[np.isfinite(vals)]) / lay0.length - 1):.4g}"
            )
        try:
            out[i] = brentq(lambda s, t=target: length(s) - t, grid[j - 1], grid[j])
        except ValueError:  # the bracket's ends of one sign within a rounding of the grid's: the grid's own numbers
            out[i] = brentq(lambda s, t=target: float(_loop_lengths(positions(np.array([s])), r, sd)[0]) - t,
                            grid[j - 1], grid[j])
    return out.reshape(e.shape)
