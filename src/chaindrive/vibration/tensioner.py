"""Slack span split by a tensioner: frequency equation, roots, checks (the tensioner paper).

Model (derived in docs/vibration.md): two strings, part i of length ℓ_i inclined at
β_i to the line perpendicular to the tensioner axis, tension T_i = S2 / cos β_i along
it (S2 its perpendicular component, eq. (8)), wave speed c_i = sqrt(T_i / q) (eqs
(1)-(3)), far ends fixed (eqs (4)-(5)), the near ends attached to the tensioner
sprocket that moves by u along its axis with mass m and stiffness C. The normal
displacement of part i at the tensioner is w_i = g_i u with g_i = cos β_i
(``model="projected"``, derived) or g_i = 1 (``model="as_printed"``, eq. (7) as printed).
The frequency equation is

    G(p) = Σ_i a_i k_i cot(k_i ℓ_i) + C − m p² = 0,   k_i = p / c_i,  a_i = T_i g_i²,

G strictly decreasing between the poles p = jπ c_i / ℓ_i, so exactly one root lies
between consecutive distinct poles, and a pole shared by both parts is itself a root
(a mode with a node at the tensioner). The solver uses that interlacing.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike

from .._docs import Fragments
from .._finite import finite_guard
from .._registry import Registry
from .._typing import FloatOrArray
from .._validation import check_nonnegative, check_positive, check_range
from ..errors import InfeasibleError, InputError
from ..limits import MAX_MODES
from .string import transverse_wave_speed

__all__ = [
    "COUPLING_MODELS",
    "span_parameters",
    "frequency_function",
    "pole_free_function",
    "tensioner_frequencies",
    "fe_tensioner_frequencies",
    "static_rod_force",
    "heavy_tensioner_frequency",
    "heavy_tensioner_validity",
]

#: How the normal displacement of each part follows the tensioner motion u.
COUPLING_MODELS = Registry("model")
COUPLING_MODELS.add("projected", lambda beta: np.cos(beta))
COUPLING_MODELS.add("as_printed", lambda beta: np.ones_like(beta))

#: The parameters of the slack span and tensioner, described once (:mod:`chaindrive._docs`).
_SPAN = """
    tension : {t}
        S2, slack-span tension perpendicular to the tensioner axis [N], > 0.
    mass_per_length : {t}
        Chain mass per length q [kg/m], > 0.
    length_1, length_2 : {t}
        Lengths ℓ1, ℓ2 of the parts left and right of the tensioner [m], > 0.
    angle_1, angle_2 : {t}
        Inclinations β1, β2 of the parts [rad], 0 <= β < π/2.
    mass : {t}
        Tensioner mass reduced to its axis m [kg], >= 0.
    stiffness : {t}
        Tensioner stiffness reduced to its axis C [N/m], >= 0; {inf}.
"""
_DOCS = Fragments(
    span=_SPAN.format(t="float or array_like", inf="``np.inf`` fixes the tensioner (two fixed-fixed strings)"),
    span_finite=_SPAN.format(t="float or array_like", inf="finite here"),
    span_scalars=_SPAN.format(t="float", inf="finite"),
    p_span="""
        p : float or array_like
            Trial circular frequency [rad/s], p > 0.
        %(span_finite)s
    """,
)

_HALF_PI = np.pi / 2


def _check_common(tension: ArrayLike, mass_per_length: ArrayLike, length_1: ArrayLike, length_2: ArrayLike,
                  angle_1: ArrayLike, angle_2: ArrayLike, mass: ArrayLike,
                  stiffness: ArrayLike) -> tuple[np.ndarray, ...]:
    s = check_positive("tension", tension, "N")
    q = check_positive("mass_per_length", mass_per_length, "kg/m")
    l1 = check_positive("length_1", length_1, "m")
    l2 = check_positive("length_2", length_2, "m")
    b1 = check_range("angle_1", angle_1, 0.0, _HALF_PI, high_inclusive=False, unit="rad")
    b2 = check_range("angle_2", angle_2, 0.0, _HALF_PI, high_inclusive=False, unit="rad")
    m = check_nonnegative("mass", mass, "kg")
    c = np.asarray(stiffness, dtype=float)
    if np.isnan(c).any() or (c < 0).any():  # c an array
        raise InputError("stiffness must be non-negative (0 <= stiffness <= inf N/m; inf = fixed tensioner)")
    return s, q, l1, l2, b1, b2, m, c


@finite_guard
def span_parameters(
    tension: ArrayLike,
    mass_per_length: ArrayLike,
    angle: ArrayLike,
    *,
    model: str = "projected",
    chain_speed: ArrayLike = 0.0,
) -> tuple[np.ndarray, np.ndarray]:
    r"""Wave speed c_i and coupling coefficient a_i of one part of the slack span.

    Parameters
    ----------
    tension : float or array_like
        S2, the tension component perpendicular to the tensioner axis [N].
    mass_per_length : float or array_like
        q [kg/m].
    angle : float or array_like
        β_i [rad], 0 <= β < π/2.
    model : {"projected", "as_printed"}
        Coupling g_i = cos β_i (derived) or 1 (the tensioner paper eq. (7) as printed).
    chain_speed : float
        Axial chain speed v [m/s]; the wave speed becomes c(1 − v²/c²) (moving-string
        correction, exact for a fixed-fixed part, approximate for the coupling).

    Returns
    -------
    (c, a) : tuple of numpy.ndarray
        Effective wave speed [m/s] and a_i = T_i g_i² [N].

    .. math:: c_i = \sqrt{S_2/(q\cos\beta_i)}, \quad a_i = \frac{S_2}{\cos\beta_i} g_i^2

    Notes
    -----
    Valid for small deflections of a perfectly flexible chain, v < c.

    Examples
    --------
    >>> c, a = span_parameters(2000.0, 2.6, 0.0)
    >>> round(float(c), 3), float(a)
    (27.735, 2000.0)

    References
    ----------
    the tensioner paper, eqs (1)-(3), (7), (8); docs/vibration.md.
    """
    g = COUPLING_MODELS.get(model)
    s = np.asarray(tension, dtype=float)
    q = np.asarray(mass_per_length, dtype=float)
    b = np.asarray(angle, dtype=float)
    t = s / np.cos(b)
    c = transverse_wave_speed(s, q, b)
    v = np.asarray(chain_speed, dtype=float)
    if np.any(v < 0) or np.any(v >= c):
        raise InfeasibleError("chain_speed must satisfy 0 <= v < c = sqrt(S/(q cos β)) m/s")
    return c * (1.0 - v**2 / c**2), t * g(b) ** 2


def _wave_terms(p, tension, mass_per_length, angle_1, angle_2, model,
                chain_speed) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """``p`` as an array, the wave numbers k_i = p/c_i and coefficients a_i of both parts."""
    c1, a1 = span_parameters(tension, mass_per_length, angle_1, model=model, chain_speed=chain_speed)
    c2, a2 = span_parameters(tension, mass_per_length, angle_2, model=model, chain_speed=chain_speed)
    p = np.asarray(p, dtype=float)
    return p, p / c1, p / c2, a1, a2


@finite_guard(allow_infinite=("stiffness",))
@_DOCS
def frequency_function(p: ArrayLike, tension: ArrayLike, mass_per_length: ArrayLike, length_1: ArrayLike,
                       length_2: ArrayLike, angle_1: ArrayLike, angle_2: ArrayLike, mass: ArrayLike,
                       stiffness: ArrayLike, *, model: str = "projected",
                       chain_speed: ArrayLike = 0.0) -> np.ndarray:
    r"""Left side G(p) of the frequency equation of slack span + tensioner [N/m].

    Parameters
    ----------
    p : float or array_like
        Trial circular frequency [rad/s], p > 0.
    %(span)s
    model : {"projected", "as_printed"}
        Coupling model, see :func:`span_parameters`.
    chain_speed : float
        Axial chain speed [m/s].

    Returns
    -------
    numpy.ndarray
        G(p); its zeros are the natural frequencies. Poles at p = jπ c_i / ℓ_i.

    .. math:: G(p) = \sum_{i=1}^{2} a_i k_i \cot(k_i \ell_i) + C - m p^2, \quad k_i = p/c_i

    Notes
    -----
    This is the tensioner paper's eq. (11) corrected (the printed one swaps ℓ1 and ℓ2 and uses
    g_i = 1); with ``model="as_printed"`` and the indices restored it is eq. (11) times S2 p.

    Examples
    --------
    >>> float(frequency_function(1e-9, 2000.0, 2.6, 0.8, 0.8, 0.0, 0.0, 3.0, 5e4)) > 0
    True

    References
    ----------
    the tensioner paper, eqs (7), (9)-(11).
    """
    w, k1, k2, a1, a2 = _wave_terms(p, tension, mass_per_length, angle_1, angle_2, model, chain_speed)
    l1 = np.asarray(length_1, dtype=float)
    l2 = np.asarray(length_2, dtype=float)
    return (a1 * k1 / np.tan(k1 * l1) + a2 * k2 / np.tan(k2 * l2)
            + np.asarray(stiffness, dtype=float) - np.asarray(mass, dtype=float) * w**2)


@finite_guard
@_DOCS
def pole_free_function(p: ArrayLike, tension: ArrayLike, mass_per_length: ArrayLike, length_1: ArrayLike,
                       length_2: ArrayLike, angle_1: ArrayLike, angle_2: ArrayLike, mass: ArrayLike,
                       stiffness: ArrayLike, *, model: str = "projected",
                       chain_speed: ArrayLike = 0.0) -> np.ndarray:
    r"""Pole-free frequency function D(p) = G(p) sin(k1 ℓ1) sin(k2 ℓ2) [N/m].

    Parameters
    ----------
    %(p_span)s
    model : {"projected", "as_printed"}
        Coupling model.
    chain_speed : float
        Axial chain speed [m/s].

    Returns
    -------
    numpy.ndarray
        D(p), continuous in p; zero at every natural frequency, including the modes
        with a node at the tensioner when both parts share a fixed-fixed frequency.

    .. math:: D = a_1 k_1 \cos k_1\ell_1 \sin k_2\ell_2 + a_2 k_2 \cos k_2\ell_2 \sin k_1\ell_1
              + (C - m p^2)\sin k_1\ell_1 \sin k_2\ell_2

    Notes
    -----
    At a pole of one part only, D = a_i k_i cos(k_iℓ_i) sin(k_jℓ_j) ≠ 0, so no pole
    is a root; where both sines vanish D = 0 (a true mode).

    Examples
    --------
    >>> p0 = np.pi * np.sqrt(2000.0 / 2.6) / 0.8  # shared first pole of two equal parts
    >>> abs(float(pole_free_function(p0, 2000.0, 2.6, 0.8, 0.8, 0.0, 0.0, 3.0, 5e4))) < 1e-9
    True

    References
    ----------
    the tensioner paper, eqs (4)-(7), (9)-(11); docs/vibration.md.
    """
    w, k1, k2, a1, a2 = _wave_terms(p, tension, mass_per_length, angle_1, angle_2, model, chain_speed)
    x1 = k1 * np.asarray(length_1, dtype=float)
    x2 = k2 * np.asarray(length_2, dtype=float)
    s1, s2 = np.sin(x1), np.sin(x2)
    return (a1 * k1 * np.cos(x1) * s2 + a2 * k2 * np.cos(x2) * s1
            + (np.asarray(stiffness, dtype=float) - np.asarray(mass, dtype=float) * w**2) * s1 * s2)


def _poles(w1, w2, modes):
    """First ``modes`` merged poles (fixed-fixed frequencies of both parts), sorted."""
    j = np.arange(1, modes + 1)
    p = np.concatenate([w1[..., None] * j, w2[..., None] * j], axis=-1)
    p.sort(axis=-1)
    return p[..., :modes]


#: Up to this many roots, :func:`_solve_interlaced` iterates each in Python floats (the same
#: steps; numpy's per-call cost dominates a handful of roots).
_SCALAR_ROOTS = 16


def _illinois_scalar(xs, idx, lo_f, hi_f, flo_f, fhi_f, pars, iterations, rtol) -> bool:
    """The Illinois steps of :func:`_solve_interlaced` root by root in Python floats, written
    into ``xs[idx]``; ``False`` (nothing kept) where a step leaves the floats (a zero
    division, an infinite argument) or does not converge: the array steps then run."""
    out = []
    try:
        for n in range(idx.size):
            lo, hi, flo, fhi = float(lo_f[n]), float(hi_f[n]), float(flo_f[n]), float(fhi_f[n])
            pb1, pb2, pal1, pal2, pc, pm = (float(v[n]) for v in pars)
            lo0, hi0, side, xn = lo, hi, 0, math.nan
            for _ in range(iterations):
                den = fhi - flo
                xn = (lo * fhi - hi * flo) / den if den != 0 else math.nan
                if not lo < xn < hi:
                    xn = 0.5 * (lo + hi)
                t1, t2 = xn * pb1, xn * pb2
                g = (pal1 * xn * math.cos(t1) / math.sin(t1) + pal2 * xn * math.cos(t2) / math.sin(t2)
                     + pc - pm * xn * xn)
                fx = g * (hi0 - xn) * (xn - lo0 if lo0 > 0 else 1.0)
                if fx > 0:  # H > 0 left of the root: replace the end with the same sign
                    flo, fhi, lo, side = fx, (0.5 * fhi if side == 1 else fhi), xn, 1
                else:
                    flo, fhi, hi, side = (0.5 * flo if side == -1 else flo), fx, xn, -1
                if hi - lo <= rtol * hi or fx == 0:
                    break
            else:
                return False
            if not math.isfinite(xn):
                return False
            out.append(xn)
    except (ValueError, ZeroDivisionError, OverflowError):
        return False
    xs[idx] = out
    return True


def _solve_interlaced(c1, l1, a1, c2, l2, a2, m, c, modes, *, iterations=60, rtol=1e-13):
    """Vectorised root finder: one root of G in each gap between consecutive poles.

    All inputs broadcast; returns shape ``broadcast + (modes,)``. G strictly decreasing,
    so each gap holds exactly one root; a zero-width gap (a pole of both parts) is a root.
    """
    w1 = np.pi * c1 / l1
    w2 = np.pi * c2 / l2
    poles = _poles(np.asarray(w1), np.asarray(w2), modes)
    hi = poles
    lo = np.concatenate([np.zeros(poles.shape[:-1] + (1,)), poles[..., :-1]], axis=-1)
    ex = [np.asarray(x, dtype=float)[..., None] for x in (c1, l1, a1, c2, l2, a2, m, c)]
    c1, l1, a1, c2, l2, a2, m, c = ex
    inf_c = np.isinf(c)
    c_fin = np.where(inf_c, 0.0, c)
    shared = (hi - lo) <= 1e-9 * hi  # a pole of both parts (within 1e-9): a root itself
    done = shared | inf_c
    b1, b2 = l1 / c1, l2 / c2  # ℓ_i / c_i
    al1, al2 = a1 / c1, a2 / c2

    shape = np.broadcast_shapes(lo.shape, m.shape, c.shape, c1.shape, c2.shape, l1.shape, l2.shape)
    lo = np.broadcast_to(lo, shape)
    hi = np.broadcast_to(hi, shape)

    def owns(p, b):  # is p a fixed-fixed frequency jπ c_i/ℓ_i of part i (b = ℓ_i/c_i)?
        r = p * b / np.pi
        return np.abs(r - np.round(r)) <= 1e-9 * np.maximum(r, 1.0)

    # H(p) = G(p) (hi - p) w(p), w = p - lo (lo > 0) or 1 (first gap): G with its poles
    # at the gap ends removed, finite and of opposite signs at the two ends.
    # End values from the residues a_i p_j / ℓ_i of a_i k cot(k ℓ_i) at p_j = jπ c_i/ℓ_i.
    res_lo = (np.where(owns(lo, b1), a1 / l1, 0.0) + np.where(owns(lo, b2), a2 / l2, 0.0)) * lo
    res_hi = (np.where(owns(hi, b1), a1 / l1, 0.0) + np.where(owns(hi, b2), a2 / l2, 0.0)) * hi
    first = lo == 0
    width = hi - lo
    h_lo = np.where(first, (a1 / l1 + a2 / l2 + c_fin) * hi, res_lo * width)
    h_hi = -res_hi * np.where(first, 1.0, width)

    # Illinois (modified regula falsi) on H in every gap at once; converged ones drop out.
    x = 0.5 * (lo + hi)
    idx = np.flatnonzero(~np.broadcast_to(done, shape))
    lo_f, hi_f, flo_f, fhi_f = (np.broadcast_to(v, shape).ravel()[idx]
                                for v in (lo, hi, h_lo, h_hi))
    side_f = np.zeros(idx.size, dtype=np.int8)
    lo0_f = lo_f.copy()
    hi0_f = hi_f.copy()
    xs = x.ravel().copy()
    pars = [np.broadcast_to(v, shape).ravel()[idx] for v in (b1, b2, al1, al2, c_fin, m)]
    if 0 < idx.size <= _SCALAR_ROOTS and _illinois_scalar(xs, idx, lo_f, hi_f, flo_f, fhi_f, pars, iterations, rtol):
        idx = idx[:0]
    for _ in range(iterations):
        if idx.size == 0:
            break
        pb1, pb2, pal1, pal2, pc, pm = pars
        xn = (lo_f * fhi_f - hi_f * flo_f) / (fhi_f - flo_f)
        bad = ~((xn > lo_f) & (xn < hi_f))
        xn = np.where(bad, 0.5 * (lo_f + hi_f), xn)
        t1, t2 = xn * pb1, xn * pb2
        g = (pal1 * xn * np.cos(t1) / np.sin(t1) + pal2 * xn * np.cos(t2) / np.sin(t2)
             + pc - pm * xn * xn)
        fx = g * (hi0_f - xn) * np.where(lo0_f > 0, xn - lo0_f, 1.0)
        same_lo = fx > 0  # H > 0 left of the root
        # replace the end with the same sign; halve the kept end's value if kept twice
        flo_f, fhi_f = (np.where(same_lo, fx, np.where(side_f == -1, 0.5 * flo_f, flo_f)),
                        np.where(same_lo, np.where(side_f == 1, 0.5 * fhi_f, fhi_f), fx))
        lo_f = np.where(same_lo, xn, lo_f)
        hi_f = np.where(same_lo, hi_f, xn)
        side_f = np.where(same_lo, 1, -1).astype(np.int8)
        xs[idx] = xn
        keep = ~((hi_f - lo_f <= rtol * hi_f) | (fx == 0))
        if not keep.all():
            idx = idx[keep]
            lo_f, hi_f, flo_f, fhi_f, side_f, lo0_f, hi0_f = (
                v[keep] for v in (lo_f, hi_f, flo_f, fhi_f, side_f, lo0_f, hi0_f))
            pars = [v[keep] for v in pars]
    else:  # pragma: no cover - Illinois converges well within the limit
        if idx.size:
            from ..errors import ConvergenceError

            raise ConvergenceError(f"tensioner frequency iteration did not converge in {iterations} steps")
    x = xs.reshape(lo.shape)
    return np.where(shared | inf_c, poles, x)


@finite_guard(allow_infinite=("stiffness",))
@_DOCS
def tensioner_frequencies(tension: ArrayLike, mass_per_length: ArrayLike, length_1: ArrayLike,
                          length_2: ArrayLike, angle_1: ArrayLike, angle_2: ArrayLike, mass: ArrayLike,
                          stiffness: ArrayLike, *, modes: int = 3, model: str = "projected",
                          chain_speed: ArrayLike = 0.0) -> np.ndarray:
    r"""First natural frequencies of the slack span with a tensioner [rad/s].

    Parameters
    ----------
    %(span)s
    modes : int
        Number of frequencies wanted (>= 1).
    model : {"projected", "as_printed"}
        Coupling of the parts to the tensioner motion (see :func:`span_parameters`).
    chain_speed : float
        Axial chain speed [m/s] (moving-string correction of the wave speeds).

    Returns
    -------
    numpy.ndarray
        Shape ``broadcast(inputs) + (modes,)``, ascending, > 0 [rad/s].

    .. math:: \sum_i a_i \frac{p}{c_i}\cot\frac{p\ell_i}{c_i} + C - m p^2 = 0

    Notes
    -----
    Exact roots (to ~1e-13 relative) of the corrected frequency equation for every
    m >= 0, C in [0, inf]. The roots interlace the fixed-fixed frequencies jπc_i/ℓ_i
    of the two parts; where both parts share one, it is itself a root (node at the
    tensioner). Fully vectorised: Illinois (modified regula falsi) on G with its
    end poles removed, in every gap at once.

    Examples
    --------
    >>> p = tensioner_frequencies(2000.0, 2.6, 0.8, 0.8, np.radians(20), np.radians(20), 3.0, 5e4)
    >>> np.round(p, 2)
    array([ 94.69, 112.36, 146.02])

    References
    ----------
    the tensioner paper, eqs (1)-(12) (the printed (11)-(12) corrected); docs/vibration.md.
    """
    s, q, l1, l2, b1, b2, m, c = _check_common(tension, mass_per_length, length_1, length_2,
                                              angle_1, angle_2, mass, stiffness)
    if not isinstance(modes, (int, np.integer)) or not 1 <= modes <= MAX_MODES:
        raise InputError(f"modes must be a whole number in [1, {MAX_MODES}], got {modes!r}")
    v = check_nonnegative("chain_speed", chain_speed, "m/s")
    c1, a1 = span_parameters(s, q, b1, model=model, chain_speed=v)
    c2, a2 = span_parameters(s, q, b2, model=model, chain_speed=v)
    return _solve_interlaced(c1, l1, a1, c2, l2, a2, m, c, int(modes))


@finite_guard
@_DOCS
def fe_tensioner_frequencies(tension: float, mass_per_length: float, length_1: float, length_2: float,
                             angle_1: float, angle_2: float, mass: float, stiffness: float, *, modes: int = 3,
                             elements: int = 200, model: str = "projected") -> np.ndarray:
    r"""Independent check: linear finite elements of both parts plus the mass-spring.

    Parameters
    ----------
    %(span_scalars)s
    modes : int
        Number of frequencies returned.
    elements : int
        Elements per part (>= 2).
    model : {"projected", "as_printed"}
        Coupling model.

    Returns
    -------
    numpy.ndarray
        First ``modes`` frequencies [rad/s] of the generalized eigenproblem
        K x = p² M x (scipy.linalg.eigh); converge as O(h²) to the exact roots.

    .. math:: V = \tfrac12\sum_i T_i\int_0^{\ell_i} w_i'^2\,ds + \tfrac12 C u^2, \quad
              T = \tfrac12\sum_i q\int_0^{\ell_i} \dot w_i^2\,ds + \tfrac12 m\dot u^2

    Notes
    -----
    Scalar inputs (one assembled eigenproblem). Part i: nodes 0..N, node 0 fixed, node N
    tied to the tensioner, w = g_i u. Consistent mass matrices. Stationary string (no
    axial speed).

    Examples
    --------
    >>> b = np.radians(20)
    >>> p = fe_tensioner_frequencies(2000.0, 2.6, 0.8, 0.8, b, b, 3.0, 5e4, elements=100)
    >>> np.round(p, 1)
    array([ 94.7, 112.4, 146. ])

    References
    ----------
    the tensioner paper, eqs (1)-(7); docs/vibration.md.
    """
    from scipy.linalg import eigh

    s, q, l1, l2, b1, b2, m, c = (float(x) for x in _check_common(
        tension, mass_per_length, length_1, length_2, angle_1, angle_2, mass, stiffness))
    if not np.isfinite(c):
        raise InputError("stiffness must be finite for the finite-element check (0 <= C < inf N/m)")
    from ..limits import check_size

    # 400 elements per part converge the first modes to 1e-5 (the check uses 100...200);
    # more would only cost minutes for a dense eigenproblem
    n = check_size("elements", elements, 400, minimum=2)
    g = COUPLING_MODELS.get(model)
    ndof = 2 * (n - 1) + 1  # interior nodes of both parts + tensioner u (last)
    K = np.zeros((ndof, ndof))
    M = np.zeros((ndof, ndof))
    ke0 = np.array([[1.0, -1.0], [-1.0, 1.0]])
    me0 = np.array([[2.0, 1.0], [1.0, 2.0]]) / 6.0
    u = ndof - 1
    for part, (ell, beta) in enumerate(((l1, b1), (l2, b2))):
        t = s / np.cos(beta)
        gi = float(g(np.asarray(beta)))
        h = ell / n
        off = part * (n - 1)
        # node j (0..n): 0 fixed, n at the tensioner; part 2 mirrored (same energy)
        for e in range(n):
            dofs: list[int | None] = []
            fac: list[float] = []
            for j in (e, e + 1):
                if j == 0:
                    dofs.append(None)
                    fac.append(0.0)
                elif j == n:
                    dofs.append(u)
                    fac.append(gi)
                else:
                    dofs.append(off + j - 1)
                    fac.append(1.0)
            ke = t / h * ke0
            me = q * h * me0
            for a in range(2):
                for b in range(2):
                    row, col = dofs[a], dofs[b]
                    if row is None or col is None:
                        continue
                    K[row, col] += ke[a, b] * fac[a] * fac[b]
                    M[row, col] += me[a, b] * fac[a] * fac[b]
    K[u, u] += c
    M[u, u] += m
    lam = eigh(K, M, eigvals_only=True, subset_by_index=[0, modes - 1])
    return np.sqrt(lam)


@finite_guard
def static_rod_force(tension: ArrayLike, angle_1: ArrayLike, angle_2: ArrayLike) -> FloatOrArray:
    r"""Static force on the tensioner rod F_n = S2 (tan β1 + tan β2) [N] (the tensioner paper eq. (8)).

    Parameters
    ----------
    tension : float or array_like
        S2, the tension component perpendicular to the tensioner axis [N].
    angle_1, angle_2 : float or array_like
        β1, β2 [rad], 0 <= β < π/2.

    Returns
    -------
    numpy.ndarray or float
        F_n [N].

    .. math:: F_n = S_2(\tan\beta_1 + \tan\beta_2)

    Notes
    -----
    Force balance along the axis: part i pulls with T_i = S2/cos β_i along itself,
    its axial component is T_i sin β_i = S2 tan β_i (checked against (7) at rest).

    Examples
    --------
    >>> round(float(static_rod_force(2000.0, np.radians(20), np.radians(20))), 3)
    1455.881

    References
    ----------
    the tensioner paper, eq. (8).
    """
    s = check_positive("tension", tension, "N")
    b1 = check_range("angle_1", angle_1, 0.0, _HALF_PI, high_inclusive=False, unit="rad")
    b2 = check_range("angle_2", angle_2, 0.0, _HALF_PI, high_inclusive=False, unit="rad")
    out = s * (np.tan(b1) + np.tan(b2))
    return out if out.ndim else float(out)


@finite_guard(allow_infinite=("stiffness",))
@_DOCS
def heavy_tensioner_frequency(tension: ArrayLike, mass_per_length: ArrayLike, length_1: ArrayLike,
                              length_2: ArrayLike, angle_1: ArrayLike, angle_2: ArrayLike, mass: ArrayLike,
                              stiffness: ArrayLike, *, model: str = "projected",
                              chain_mass: bool = False) -> FloatOrArray:
    r"""First frequency of a heavy tensioner on massless spans [rad/s] (the tensioner paper eq. (13), fixed).

    Parameters
    ----------
    %(span)s
    model : {"projected", "as_printed"}
        Coupling model.
    chain_mass : bool
        Add a third of each part's mass (times g_i²) to m (Rayleigh), the next term
        of the expansion of k cot(kℓ).

    Returns
    -------
    numpy.ndarray or float
        P1 [rad/s].

    .. math:: P_1 = \sqrt{\Big(\sum_i \frac{a_i}{\ell_i} + C\Big) \Big/ m}

    Notes
    -----
    As printed, (13) reads P1 = 2S2/(m ℓ1 cos β1) + C/m: that is P1² (dimension
    s⁻²), for ℓ1 = ℓ2, β1 = β2 and the paper coupling. Valid while the parts are
    quasi-static, θ = max_i P1 ℓ_i / c_i small: see :func:`heavy_tensioner_validity`
    (the printed validity condition is garbled and replaced by θ <= 0.5).

    Examples
    --------
    >>> b = np.radians(20)
    >>> round(float(heavy_tensioner_frequency(2000.0, 2.6, 0.8, 0.8, b, b, 30.0, 5e3)), 3)
    17.98

    References
    ----------
    the tensioner paper, eq. (13) (corrected: square root).
    """
    s, q, l1, l2, b1, b2, m, c = _check_common(tension, mass_per_length, length_1, length_2,
                                              angle_1, angle_2, mass, stiffness)
    m = check_positive("mass", m, "kg")
    c = check_nonnegative("stiffness", c, "N/m")
    g = COUPLING_MODELS.get(model)
    a1 = s / np.cos(b1) * g(b1) ** 2
    a2 = s / np.cos(b2) * g(b2) ** 2
    meff = m + ((q * (l1 * g(b1) ** 2 + l2 * g(b2) ** 2) / 3.0) if chain_mass else 0.0)
    out = np.sqrt((a1 / l1 + a2 / l2 + c) / meff)
    return out if out.ndim else float(out)


@finite_guard(allow_infinite=("stiffness",))
@_DOCS
def heavy_tensioner_validity(tension: ArrayLike, mass_per_length: ArrayLike, length_1: ArrayLike,
                             length_2: ArrayLike, angle_1: ArrayLike, angle_2: ArrayLike, mass: ArrayLike,
                             stiffness: ArrayLike, *, model: str = "projected") -> FloatOrArray:
    r"""Validity parameter θ = max_i P1 ℓ_i / c_i of the heavy-tensioner formula.

    Parameters
    ----------
    %(span)s
    model : {"projected", "as_printed"}
        Coupling model.

    Returns
    -------
    numpy.ndarray or float
        θ (dimensionless); the approximation is within ~3 % for θ <= 0.5.

    .. math:: \theta = \max_i P_1 \ell_i / c_i

    Notes
    -----
    The error of (13) is of order θ²·(chain mass)/(3 m_eff): the spans must be short
    against the wave length at P1. Test values in tests/test_vibration.py.

    Examples
    --------
    >>> b = np.radians(20)
    >>> theta = heavy_tensioner_validity(2000.0, 2.6, 0.8, 0.8, b, b, 30.0, 5e3)
    >>> round(float(theta), 3), bool(theta <= 0.5)   # just outside the ~3 % range
    (0.503, False)

    References
    ----------
    the tensioner paper, condition under eq. (13) (garbled in print; replaced).
    """
    p1 = np.asarray(heavy_tensioner_frequency(tension, mass_per_length, length_1, length_2,
                                              angle_1, angle_2, mass, stiffness, model=model))
    c1 = transverse_wave_speed(tension, mass_per_length, angle_1)
    c2 = transverse_wave_speed(tension, mass_per_length, angle_2)
    out = np.maximum(p1 * np.asarray(length_1) / c1, p1 * np.asarray(length_2) / c2)
    return out if out.ndim else float(out)
