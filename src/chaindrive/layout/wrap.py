"""Two or more wheels on the pitch circles: spans, wraps and length (the belt problem)."""

from __future__ import annotations

import contextlib
import math
from collections import OrderedDict
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from .._finite import finite_guard, refuse_nonfinite_result
from .._results import Result, quantity
from .._validation import as_float_array, check_nonnegative, check_positive, check_teeth
from ..errors import InfeasibleError, InputError


@dataclass(frozen=True)
class WrapLayout(Result):
    """Chain path around two or more wheels (pitch circles, exact tangents).

    Attributes
    ----------
    centres : ndarray, shape (n, 2)
        Wheel centres, in the order the chain passes them [m].
    radii : ndarray, shape (n,)
        Pitch radii [m].
    sides : ndarray, shape (n,)
        +1: the chain turns counter-clockwise around the wheel (wheel inside the
        loop); -1: clockwise (idler on the back of the chain).
    span_start, span_end : ndarray, shape (n, 2)
        Tangent points of span ``i`` from wheel ``i`` to wheel ``i+1`` [m].
    span_length : ndarray, shape (n,)
        [m].
    span_angle : ndarray, shape (n,)
        Direction of travel of span ``i`` from the x axis [rad].
    wrap_angle : ndarray, shape (n,)
        Angle of wrap on each wheel [rad].
    wrap_length : ndarray, shape (n,)
        Arc length on each pitch circle [m].
    length : float
        Total chain length on the pitch circles [m].
    """

    centres: np.ndarray = quantity("m")
    radii: np.ndarray = quantity("m")
    sides: np.ndarray = quantity("1")
    span_start: np.ndarray = quantity("m")
    span_end: np.ndarray = quantity("m")
    span_length: np.ndarray = quantity("m")
    span_angle: np.ndarray = quantity("rad")
    wrap_angle: np.ndarray = quantity("rad")
    wrap_length: np.ndarray = quantity("m")
    length: float = quantity("m")


@finite_guard(check_result=False)  # a result computed afresh is checked below; a kept one was
def wrap_layout(centres: ArrayLike, radii: ArrayLike, sides: ArrayLike | None = None) -> WrapLayout:
    r"""Spans, wrap angles and length of a chain around wheels at given positions.

    .. math::
        \alpha_i = \delta_i - \arcsin\frac{\rho_{i+1} - \rho_i}{D_i},\qquad
        \ell_i = \sqrt{D_i^2 - (\rho_{i+1} - \rho_i)^2},\qquad
        L = \sum \ell_i + \sum R_i \theta_i

    with ``ρ = s R`` the signed radius, ``D_i, δ_i`` length and angle of the line of
    centres from wheel ``i`` to ``i+1``.

    Parameters
    ----------
    centres : array_like, shape (n, 2)
        Wheel centres in the order of chain travel, counter-clockwise around the
        loop [m], ``n >= 2``.
    radii : array_like, shape (n,)
        Pitch radii [m] (> 0).
    sides : array_like of {+1, -1}, optional
        +1 for a wheel inside the loop (default), -1 for an idler pressing on the
        outside of the chain.

    Returns
    -------
    WrapLayout

    Raises
    ------
    InputError
        Shapes, radii <= 0, sides not ±1.
    InfeasibleError
        Two consecutive wheels overlap so that no common tangent exists.

    Notes
    -----
    Derivation: a chain moving along the unit vector ``t`` that turns left around a
    wheel has the centre at ``P + R n`` with ``n = (-t_y, t_x)``; the span from wheel
    ``i`` to ``i+1`` satisfies ``c_{i+1} - c_i - (ρ_{i+1} - ρ_i) n = ℓ t``. Its
    components along ``n`` and ``t`` give the formulas above. The wrap angle is the
    turn of ``t`` between the incoming and outgoing span (mod 2π, left turns for
    ``s = +1``, right turns for ``s = -1``); for a simple loop ``Σ s θ = 2π``.
    The pitch circles stand for the polygons (belt model): the teeth in mesh follow
    from :func:`teeth_in_mesh`.

    References
    ----------
    Tangent lines between circles (the belt problem); two-wheel case: Shigley, 9th ed.,
    eq. (17-1). Tested against the two-wheel formula and an equilateral three-wheel
    loop ``L = 3s + 2πR``.

    Examples
    --------
    >>> lay = wrap_layout([[0, 0], [1, 0], [0.5, 0.8660254037844386]], [0.1, 0.1, 0.1])
    >>> round(lay.length, 6), round(float(lay.wrap_angle[0]), 6)
    (3.628319, 2.094395)
    """
    c = as_float_array("centres", centres)
    if c.ndim != 2 or c.shape[1] != 2 or c.shape[0] < 2:
        raise InputError(f"centres must have shape (n, 2) with n >= 2, got shape {c.shape}")
    n = c.shape[0]
    r = check_positive("radii", radii, "m")
    if r.shape != (n,):
        raise InputError(f"radii must have shape ({n},) like centres, got {r.shape}")
    s = np.ones(n) if sides is None else as_float_array("sides", sides)
    if s.shape != (n,) or not all(x in (1.0, -1.0) for x in s.tolist()):
        raise InputError(f"sides must be +1 or -1 for each of the {n} wheels, got {sides!r}")
    key = (c.tobytes(), r.tobytes(), s.tobytes())
    kept = _KEPT.get(key)
    if kept is not None:  # the same wheels asked for again (an analysis draws its layout several times)
        with contextlib.suppress(KeyError):  # another thread may have dropped it meanwhile
            _KEPT.move_to_end(key)
        fields: dict[str, Any] = {name: (v.copy() if type(v) is np.ndarray else v) for name, v in kept.items()}
        return WrapLayout(**fields)
    lay = _wrap_layout(c, r, s)
    refuse_nonfinite_result("wrap_layout", lay)
    _KEPT[key] = {name: (v.copy() if type(v) is np.ndarray else v) for name, v in lay.__dict__.items()}
    if len(_KEPT) > 64:
        with contextlib.suppress(KeyError):
            _KEPT.popitem(last=False)
    return lay


#: The last layouts computed, by the bytes of their checked inputs (chaindrive.analysis._memo.clear
#: empties it); a kept layout is handed out as copies, so no caller shares its arrays.
_KEPT: OrderedDict[tuple[bytes, bytes, bytes], dict] = OrderedDict()


def _wrap_layout(c: np.ndarray, r: np.ndarray, s: np.ndarray) -> WrapLayout:
    """:func:`wrap_layout` of checked inputs."""
    n = c.shape[0]
    rho = s * r
    # wheel i + 1 beside wheel i (np.roll(..., -1) without its overhead: the same values)
    c_next = np.concatenate((c[1:], c[:1]))
    rho_next = np.concatenate((rho[1:], rho[:1]))
    d = c_next - c
    D = np.hypot(d[:, 0], d[:, 1])
    drho = rho_next - rho
    if (D <= np.abs(drho)).any():
        bad = int(np.argmax(D <= np.abs(drho)))
        raise InfeasibleError(
            f"wheels {bad} and {(bad + 1) % n} overlap so that the chain has no common "
            f"tangent: centre distance {D[bad]:g} m must exceed |±R1 ∓ R2| = {abs(drho[bad]):g} m"
        )
    delta = np.arctan2(d[:, 1], d[:, 0])
    alpha = delta - np.arcsin(drho / D)
    ell = np.sqrt(D**2 - drho**2)
    # the normal (-sin, cos) of each span filled in (np.column_stack of the same columns)
    nrm = np.empty((n, 2))
    nrm[:, 0], nrm[:, 1] = -np.sin(alpha), np.cos(alpha)
    start = c - rho[:, None] * nrm
    end = c_next - rho_next[:, None] * nrm
    alpha_in = np.concatenate((alpha[-1:], alpha[:-1]))
    turn = np.mod(s * (alpha - alpha_in), 2 * np.pi)
    wrap = np.where(np.abs(turn) <= 1e-12, 0.0, turn)  # np.isclose(turn, 0, atol=1e-12) written out
    total_turn = float(np.add.reduce(s * wrap))  # np.sum
    if not abs(total_turn - 2 * np.pi) <= 1e-6 + 1e-5 * 2 * np.pi:  # np.isclose(.., 2π, atol=1e-6)
        raise InfeasibleError(
            "the wheels do not form a simple counter-clockwise loop in the given order "
            f"(total turning {total_turn:.4f} rad, expected 2π); list the wheels in the "
            "order of chain travel, counter-clockwise, and mark back-side idlers with side -1"
        )
    arc = r * wrap
    return WrapLayout(centres=c, radii=r, sides=s, span_start=start, span_end=end,
                      span_length=ell, span_angle=alpha, wrap_angle=wrap, wrap_length=arc,
                      length=float(np.add.reduce(ell) + np.add.reduce(arc)))  # ell.sum() + arc.sum()


def span_lengths(centres: np.ndarray, radii: np.ndarray, sides: np.ndarray) -> np.ndarray | None:
    """:attr:`WrapLayout.span_length` for many sets of radii at once: ``radii`` (m, n) on
    checked ``centres`` (n, 2) and ``sides`` (n,) -> (m, n) [m], by the operations of
    :func:`wrap_layout` (the same numbers); ``None`` when a row has no layout (the caller
    asks :func:`wrap_layout` for the error).

    Raises
    ------
    InputError
        ``centres`` not (n, 2) with n >= 2, ``radii`` not positive of shape (m, n), ``sides``
        not +1 or -1 for each wheel, or a value not finite.
    """
    centres = as_float_array("centres", centres)
    if centres.ndim != 2 or centres.shape[1] != 2 or centres.shape[0] < 2 or not np.isfinite(centres).all():
        raise InputError(f"centres must be finite [m] with shape (n, 2), n >= 2, got shape {centres.shape}")
    n = centres.shape[0]
    radii = check_positive("radii", radii, "m")
    if radii.ndim != 2 or radii.shape[1] != n:
        raise InputError(f"radii must have shape (m, {n}): a row of radii for each of the {n} wheels, "
                         f"got {radii.shape}")
    sides = as_float_array("sides", sides)
    if sides.shape != (n,) or not ((sides == 1.0) | (sides == -1.0)).all():
        raise InputError(f"sides must be +1 or -1 for each of the {n} wheels, got shape {sides.shape}")
    rho = sides * radii
    c_next = np.concatenate((centres[1:], centres[:1]))
    rho_next = np.concatenate((rho[:, 1:], rho[:, :1]), axis=1)
    d = c_next - centres
    D = np.hypot(d[:, 0], d[:, 1])
    drho = rho_next - rho
    if (D <= np.abs(drho)).any():  # (the array methods and the ufunc reduction: the same tests and sums)
        return None
    alpha = np.arctan2(d[:, 1], d[:, 0]) - np.arcsin(drho / D)
    turn = np.mod(sides * (alpha - np.concatenate((alpha[:, -1:], alpha[:, :-1]), axis=1)), 2 * np.pi)
    wrap = np.where(np.abs(turn) <= 1e-12, 0.0, turn)
    if not (np.abs(np.add.reduce(sides * wrap, axis=1) - 2 * np.pi) <= 1e-6 + 1e-5 * 2 * np.pi).all():
        return None
    return np.sqrt(D**2 - drho**2)


def _loop_lengths(centres: np.ndarray, radii: np.ndarray, sides: np.ndarray) -> np.ndarray:
    """:attr:`WrapLayout.length` for many layouts at once, ``-inf`` where there is none.

    ``centres`` (m, n, 2) on checked ``radii`` and ``sides`` (n,): the operations of
    :func:`wrap_layout` row by row (its ``isclose`` tests written out), without the
    validation, for the root searches of :func:`tensioner_travel`.
    """
    rho = sides * radii
    d = np.roll(centres, -1, axis=-2) - centres
    D = np.hypot(d[..., 0], d[..., 1])
    drho = np.roll(rho, -1) - rho
    with np.errstate(invalid="ignore", divide="ignore"):
        alpha = np.arctan2(d[..., 1], d[..., 0]) - np.arcsin(drho / D)
        ell = np.sqrt(D**2 - drho**2)
    turn = np.mod(sides * (alpha - np.roll(alpha, 1, axis=-1)), 2 * np.pi)
    wrap = np.where(np.abs(turn) <= 1e-12, 0.0, turn)
    total_turn = np.sum(sides * wrap, axis=-1)
    ok = np.all(D > np.abs(drho), axis=-1) & (np.abs(total_turn - 2 * np.pi) <= 1e-6 + 1e-5 * 2 * np.pi)
    length = np.sum(ell, axis=-1) + np.sum(radii * wrap, axis=-1)
    return np.where(ok, length, -np.inf)


#: The hypotenuse, arc tangent and arc sine of :func:`_span_scalar`: numpy's own (the same numbers
#: as :func:`_loop_lengths`), or the math module's (faster, within a rounding of them).
NUMPY_TRIG = (np.hypot, np.arctan2, np.arcsin)
MATH_TRIG = (math.hypot, math.atan2, math.asin)


def _span_scalar(xs: list[float], ys: list[float], rho: list[float], i: int,
                 trig: tuple = NUMPY_TRIG) -> tuple[float, float] | None:
    """Direction and length of span ``i`` as :func:`_loop_lengths` has them, or ``None`` where
    the span has no common tangent."""
    hypot, atan2, asin = trig
    j = i + 1 if i + 1 < len(xs) else 0
    dx, dy = xs[j] - xs[i], ys[j] - ys[i]
    D = float(hypot(dx, dy))
    drho = rho[j] - rho[i]
    if not D > abs(drho):
        return None
    return float(atan2(dy, dx)) - float(asin(drho / D)), math.sqrt(D * D - drho * drho)


def _loop_length(xs: list[float], ys: list[float], radii: list[float], sides: list[float],
                 fixed: list[tuple[float, float] | None] | None = None, trig: tuple = NUMPY_TRIG) -> float:
    """:func:`_loop_lengths` of one layout of up to 7 wheels in Python floats (the same
    numbers: the same operations, numpy's own arc tangent and arc sine, the sums in order;
    ``trig=MATH_TRIG``: the math module's, within a rounding), for the scalar root searches;
    ``fixed``: the spans (:func:`_span_scalar`) that do not change between the calls, ``None``
    for those computed each time."""
    n = len(xs)
    rho = [s * r for s, r in zip(sides, radii, strict=True)]
    alpha, ell = [], []
    for i in range(n):
        span = fixed[i] if fixed is not None and fixed[i] is not None else _span_scalar(xs, ys, rho, i, trig)
        if span is None:
            return -math.inf
        alpha.append(span[0])
        ell.append(span[1])
    total = arcs = length = 0.0
    for i in range(n):
        turn = (sides[i] * (alpha[i] - alpha[i - 1])) % (2 * math.pi)
        wrap = 0.0 if abs(turn) <= 1e-12 else turn
        total += sides[i] * wrap
        arcs += radii[i] * wrap
    for v in ell:
        length += v
    return length + arcs if abs(total - 2 * np.pi) <= 1e-6 + 1e-5 * 2 * np.pi else -math.inf


@finite_guard
def teeth_in_mesh(wrap_angle: ArrayLike, teeth: ArrayLike) -> np.ndarray:
    r"""Number of teeth in mesh (hinges seated) for a wrap angle.

    .. math:: z_m = \left\lfloor \frac{\theta z}{2\pi} \right\rfloor

    Parameters
    ----------
    wrap_angle : float or array_like
        Wrap angle ``θ`` [rad], ``0 <= θ <= 2π``.
    teeth : int or array_like
        Tooth count [-].

    Returns
    -------
    ndarray of int
        Whole teeth fully in the wrap (the load-carrying teeth); the fractional
        value is ``θ z / 2π``.

    References
    ----------
    ISO 10823:2004 recommends a wrap of at least 120° on the small sprocket.

    Examples
    --------
    >>> int(teeth_in_mesh(np.pi, 19))
    9
    """
    th = check_nonnegative("wrap_angle", wrap_angle, "rad")
    if np.asarray(th > 2 * np.pi + 1e-12).any():
        raise InputError(f"wrap_angle must lie in [0, 2π] rad, got {th}")
    z = check_teeth("teeth", teeth, minimum=2)
    return np.floor(th * z / (2 * np.pi) + 1e-9).astype(int)
