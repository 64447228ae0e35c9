"""Design help on the tensioner paper's resonance check: the Campbell diagram, the resonance
map over (mass, stiffness), the nearest safe tensioner and :func:`span_vibration` (one design's
frequencies, rod force, check and Campbell data)."""

from __future__ import annotations

import dataclasses
import math
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike

from .._finite import finite_guard
from .._presenters import view
from .._results import Result, quantity
from .._validation import check_nonnegative, check_positive, check_range
from ..errors import InfeasibleError, InputError
from .resonance import (
    BAND,
    ResonanceCheck,
    TensionerSpan,
    excitation_multipliers,
    resonance_margin,
)

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

__all__ = [
    "CampbellResult",
    "ResonanceMapResult",
    "SafeTensioner",
    "SpanVibration",
    "span_vibration",
    "campbell",
    "resonance_map",
    "propose_safe_tensioner",
]


# --------------------------------------------------------------------------- results
@dataclasses.dataclass(frozen=True)
class CampbellResult(Result):
    """Natural and exciting frequencies against driving speed (rad/s)."""

    speed: np.ndarray = quantity("rad/s")
    natural_frequencies: np.ndarray = quantity("rad/s", display="Hz")  # (speeds, modes)
    excitation_names: list
    excitation_multipliers: np.ndarray = quantity("1")
    band: tuple[float, float] = quantity("1")
    design_speed: float | None = quantity("rad/s")
    min_margin: np.ndarray = quantity("1")  # (speeds,)

    def plot(self, *, ax: Axes | None = None) -> Figure:
        """Campbell diagram (:func:`chaindrive.plotting.vibration.campbell_plot`)."""
        return view("plot", self, ax=ax)


@dataclasses.dataclass(frozen=True)
class ResonanceMapResult(Result):
    """Smallest margin to the forbidden band over a speed range, on an (m, C) grid."""

    mass: np.ndarray = quantity("kg")
    stiffness: np.ndarray = quantity("N/m")
    min_margin: np.ndarray = quantity("1")  # (masses, stiffnesses)
    safe: np.ndarray = quantity("1")
    speed_range: tuple[float, float] = quantity("rad/s")
    speeds: int = quantity("1")
    excitation_names: list
    design: tuple | None = None
    proposal: tuple | None = None

    def plot(self, *, ax: Axes | None = None) -> Figure:
        """Resonance map (:func:`chaindrive.plotting.vibration.resonance_map_plot`)."""
        return view("plot", self, ax=ax)


@dataclasses.dataclass(frozen=True)
class SafeTensioner(Result):
    """Nearest safe tensioner to a design (the tensioner paper check over the speed range)."""

    mass: float = quantity("kg")
    stiffness: float = quantity("N/m")
    margin: float = quantity("1")
    distance: float = quantity("1")
    design_mass: float = quantity("kg")
    design_stiffness: float = quantity("N/m")
    design_margin: float = quantity("1")
    changed: bool


@dataclasses.dataclass(frozen=True)
class SpanVibration(Result):
    """Everything the tensioner paper check gives for one design (SI units); ``.plot()`` = Campbell."""

    frequencies_rad_s: np.ndarray = quantity("rad/s", display="Hz")
    frequencies_hz: np.ndarray = quantity("Hz")
    static_rod_force: float = quantity("N")
    heavy_tensioner_frequency: float | None = quantity("rad/s", display="Hz")
    check: ResonanceCheck | None
    campbell: CampbellResult | None

    @property
    def passed(self) -> bool | None:
        """Verdict of the check (None without a speed)."""
        return None if self.check is None else self.check.passed

    def plot(self, *, ax: Axes | None = None) -> Figure:
        """Campbell diagram (needs a speed range)."""
        if self.campbell is None:
            raise InputError("no Campbell data: give speed (rad/s) or speed_range to span_vibration")
        return self.campbell.plot(ax=ax)


@finite_guard
def span_vibration(span: TensionerSpan, speed: float | None = None, *, ratio: float = 1.0,
                   teeth: int | None = None, link_chain: bool = False, modes: int = 3,
                   speed_range: tuple[float, float] | None = None) -> SpanVibration:
    r"""Natural frequencies, rod force and the resonance check of one design.

    Parameters
    ----------
    span : TensionerSpan
        The slack span with its tensioner.
    speed : float, optional
        Driving sprocket speed ω1 [rad/s]; without it no check is made.
    ratio, teeth, link_chain
        Excitations, see :func:`excitation_multipliers`.
    modes : int
        Natural frequencies (the tensioner paper: three).
    speed_range : (float, float), optional
        Range of the Campbell diagram [rad/s]; default 0.8…1.2 × speed.

    Returns
    -------
    SpanVibration
        ``frequencies_rad_s``, ``frequencies_hz``, ``static_rod_force`` [N],
        ``heavy_tensioner_frequency`` [rad/s] (None for m = 0), ``check``, ``campbell``.

    .. math:: 0.7 \le P_i/\omega_j \le 1.4 \ \text{forbidden}

    Notes
    -----
    Stationary span (the tensioner paper).

    Examples
    --------
    >>> s = TensionerSpan(2000.0, 2.6, 0.8, 0.8, np.radians(20), np.radians(20), 3.0, 5e4)
    >>> r = span_vibration(s, 31.4159, ratio=2.5, teeth=17)
    >>> r.passed, round(r.static_rod_force, 1)
    (True, 1455.9)

    References
    ----------
    the tensioner paper, eqs (1)-(13) and the resonance condition.
    """
    p = span.frequencies(modes)
    heavy = float(span.heavy_tensioner_frequency()) if span.mass > 0 and math.isfinite(span.stiffness) else None
    chk = cb = None
    if speed is not None:
        chk = span.check(speed, ratio=ratio, teeth=teeth, link_chain=link_chain, modes=modes)
        if speed_range is None:
            speed_range = (0.8 * float(speed), 1.2 * float(speed))
    if speed_range is not None:
        cb = campbell(span, speed_range, ratio=ratio, teeth=teeth, link_chain=link_chain,
                      modes=modes, design_speed=speed)
    return SpanVibration(frequencies_rad_s=p, frequencies_hz=p / (2 * np.pi),
                         static_rod_force=float(span.static_rod_force()),
                         heavy_tensioner_frequency=heavy, check=chk, campbell=cb)


# --------------------------------------------------------------------------- design help
def _speed_grid(speed_range: tuple[float, float], speeds: int) -> np.ndarray:
    lo, hi = (float(v) for v in speed_range)
    check_positive("speed_range", [lo, hi], "rad/s")
    if hi < lo:
        raise InputError(f"speed_range must be (low, high) with low <= high, got ({lo:g}, {hi:g}) rad/s")
    from ..limits import MAX_GRID, check_size

    return np.linspace(lo, hi, check_size("speeds", speeds, MAX_GRID))


def _min_margin(p: np.ndarray, mult: list[float], w: np.ndarray) -> np.ndarray:
    """min over modes, excitations and speeds of the margin; p (..., modes), w (speeds,).

    The margin max(r/1.4 - 1, 1 - r/0.7) with r = P/(k ω) is a convex piecewise-linear
    function of x = 1/ω, smallest at x* = 2k / (P (1/1.4 + 1/0.7)); over the sampled
    speeds its minimum is at one of the two samples around x* (exact, no loop over speeds).
    """
    lo, hi = BAND
    x = np.sort(1.0 / np.asarray(w, dtype=float))
    out = np.full(p.shape[:-1], np.inf)
    for k in mult:
        xs = 2.0 * k / (p * (1.0 / hi + 1.0 / lo))
        j = np.searchsorted(x, xs)
        for jj in (np.clip(j - 1, 0, x.size - 1), np.clip(j, 0, x.size - 1)):
            r = p * x[jj] / k
            mu = np.maximum(r * (1.0 / hi) - 1.0, 1.0 - r * (1.0 / lo))
            np.minimum(out, mu.min(axis=-1), out=out)
    return out


@finite_guard
def campbell(span: TensionerSpan, speed_range: tuple[float, float], *, ratio: float = 1.0,
             teeth: int | None = None, link_chain: bool = False, modes: int = 3, speeds: int = 200,
             chain_speed_per_speed: float = 0.0, design_speed: float | None = None) -> CampbellResult:
    r"""Campbell diagram data: natural and exciting frequencies against ω1.

    Parameters
    ----------
    span : TensionerSpan
        The slack span with its tensioner.
    speed_range : (float, float)
        Driving sprocket speed range [rad/s].
    ratio, teeth, link_chain
        Excitations, see :func:`excitation_multipliers`.
    modes : int
        Natural frequencies drawn.
    speeds : int
        Samples of the speed range.
    chain_speed_per_speed : float
        Chain speed per unit ω1 [m/rad] (z1 p / 2π for a roller chain, the pitch radius
        in general): the natural frequencies then fall with speed (moving-string
        correction); 0 keeps them constant (the tensioner paper's stationary model).
    design_speed : float, optional
        Marked on the plot [rad/s].

    Returns
    -------
    CampbellResult

    .. math:: P_i(\omega_1), \quad \omega_j = k_j\omega_1, \quad 0.7 k_j\omega_1 \le P \le 1.4 k_j\omega_1

    Notes
    -----
    ``min_margin`` per speed is the smallest :func:`resonance_margin` over all pairs.

    Examples
    --------
    >>> s = TensionerSpan(2000.0, 2.6, 0.8, 0.8, 0.35, 0.35, 3.0, 5e4)
    >>> r = campbell(s, (5.0, 60.0), ratio=2.5, teeth=17, speeds=12)
    >>> r.natural_frequencies.shape
    (12, 3)

    References
    ----------
    the tensioner paper (resonance condition); Mote 1965 (speed correction).
    """
    w = _speed_grid(speed_range, speeds)
    ks = excitation_multipliers(ratio, teeth, link_chain=link_chain)
    v = check_nonnegative("chain_speed_per_speed", chain_speed_per_speed, "m/rad") * w
    p = span.frequencies(modes, chain_speed=v[:, None]) if np.any(v > 0) else np.broadcast_to(
        span.frequencies(modes), (w.size, modes)).copy()
    p = p.reshape(w.size, modes)
    mult = np.array(list(ks.values()))
    mm = np.min(np.asarray(resonance_margin(p[:, :, None] / (mult[None, None, :] * w[:, None, None]))),
                axis=(1, 2))
    return CampbellResult(speed=w, natural_frequencies=p, excitation_names=list(ks),
                          excitation_multipliers=mult, band=BAND, design_speed=design_speed,
                          min_margin=mm)


@finite_guard
def resonance_map(span: TensionerSpan, masses: ArrayLike, stiffnesses: ArrayLike,
                  speed_range: tuple[float, float], *, ratio: float = 1.0, teeth: int | None = None,
                  link_chain: bool = False, modes: int = 3, speeds: int = 50,
                  required_margin: float = 0.0) -> ResonanceMapResult:
    r"""Smallest margin to the forbidden band over a speed range, on a grid of (m, C).

    Parameters
    ----------
    span : TensionerSpan
        Chain, span geometry and tension (its own mass and stiffness are the design).
    masses : array_like
        Tensioner masses m [kg] (1-D, >= 0).
    stiffnesses : array_like
        Tensioner stiffnesses C [N/m] (1-D, >= 0).
    speed_range : (float, float)
        Driving sprocket speed range [rad/s].
    ratio, teeth, link_chain
        Excitations, see :func:`excitation_multipliers`.
    modes : int
        Natural frequencies checked (the tensioner paper: the first three).
    speeds : int
        Samples of the speed range.
    required_margin : float
        A grid point is safe when its smallest margin exceeds this.

    Returns
    -------
    ResonanceMapResult
        ``min_margin`` of shape (len(masses), len(stiffnesses)).

    .. math:: \mu(m, C) = \min_{i,j,\omega_1} \max(P_i/(1.4\omega_j) - 1,\ 1 - P_i/(0.7\omega_j))

    Notes
    -----
    All roots of the grid are found at once (:func:`tensioner_frequencies` is
    vectorised); stationary span (the tensioner paper).

    Examples
    --------
    >>> s = TensionerSpan(2000.0, 2.6, 0.8, 0.8, 0.35, 0.35, 3.0, 5e4)
    >>> r = resonance_map(s, np.geomspace(0.3, 30, 5), np.geomspace(5e3, 5e5, 4), (20, 40),
    ...                   ratio=2.5, teeth=17)
    >>> r.min_margin.shape
    (5, 4)

    References
    ----------
    the tensioner paper (resonance condition, m and C reduced to the tensioner axis).
    """
    m = check_nonnegative("masses", masses, "kg").ravel()
    c = check_nonnegative("stiffnesses", stiffnesses, "N/m").ravel()
    w = _speed_grid(speed_range, speeds)
    ks = excitation_multipliers(ratio, teeth, link_chain=link_chain)
    p = span.frequencies(modes, mass=m[:, None], stiffness=c[None, :])
    mu = _min_margin(p, list(ks.values()), w)
    return ResonanceMapResult(mass=m, stiffness=c, min_margin=mu, safe=mu > required_margin,
                              speed_range=(float(w[0]), float(w[-1])), speeds=int(speeds),
                              excitation_names=list(ks), design=(span.mass, span.stiffness))


@finite_guard
def propose_safe_tensioner(span: TensionerSpan, speed_range: tuple[float, float], *, ratio: float = 1.0,
                           teeth: int | None = None, link_chain: bool = False, modes: int = 3,
                           speeds: int = 50, required_margin: float = 0.05, decades: float = 1.5,
                           points: int = 241) -> SafeTensioner:
    r"""Nearest safe (m, C) to the span's tensioner in a normalized log metric.

    Parameters
    ----------
    span : TensionerSpan
        The design; its ``mass`` and ``stiffness`` must be > 0.
    speed_range : (float, float)
        Driving sprocket speed range [rad/s].
    ratio, teeth, link_chain, modes, speeds
        As in :func:`resonance_map`.
    required_margin : float
        Smallest acceptable margin (:func:`resonance_margin`) over the range.
    decades : float
        Search m and C within ± this many decades of the design.
    points : int
        Grid points per axis.

    Returns
    -------
    SafeTensioner
        The safe grid point nearest to the design, distance
        d = sqrt(log10(m/m0)² + log10(C/C0)²) in decades.

    .. math:: d = \sqrt{\log_{10}^2(m/m_0) + \log_{10}^2(C/C_0)}

    Notes
    -----
    The metric treats a factor 2 on the mass like a factor 2 on the stiffness.
    Resolution is the grid step (2·decades/(points−1) decades). Raises
    :class:`~chaindrive.errors.InfeasibleError` when nothing in the window is safe.

    Examples
    --------
    >>> s = TensionerSpan(2000.0, 2.6, 0.8, 0.8, 0.35, 0.35, 3.0, 5e4)
    >>> r = propose_safe_tensioner(s, (20.0, 40.0), ratio=1.0, teeth=None, points=61)
    >>> r.changed
    False

    References
    ----------
    the tensioner paper (resonance condition).
    """
    m0 = float(check_positive("span.mass", span.mass, "kg"))
    c0 = float(check_positive("span.stiffness", span.stiffness, "N/m"))
    if not math.isfinite(c0):
        raise InputError("span.stiffness must be finite (0 < C < inf N/m) to propose a change")
    from ..limits import MAX_GRID, check_size

    decades = float(check_range("decades", decades, 0.0, 10.0, low_inclusive=False))
    f = np.linspace(-decades, decades, check_size("points", points, MAX_GRID, minimum=2))
    mm = m0 * 10.0**f
    cc = c0 * 10.0**f
    # the corners of the map: the same argument checks (and errors) as the whole map
    corners = [0, -1] if mm.size else []
    resonance_map(span, mm[corners], cc[corners], speed_range, ratio=ratio, teeth=teeth, link_chain=link_chain,
                  modes=modes, speeds=speeds, required_margin=required_margin)
    w = _speed_grid(speed_range, speeds)
    mult = list(excitation_multipliers(ratio, teeth, link_chain=link_chain).values())
    p0 = span.frequencies(modes)
    mu0 = float(_min_margin(p0, mult, w))
    if mu0 > required_margin:
        return SafeTensioner(m0, c0, mu0, 0.0, m0, c0, mu0, False)
    # margins of the (m, C) grid, skipping the blocks whose every point is proven unsafe
    # (see _margin_grid); the points left are evaluated exactly, as by resonance_map
    margin = _margin_grid(span, mm, cc, mult, w, modes, required_margin) if mm.size else np.empty((0, 0))
    d = np.hypot(f[:, None], f[None, :])
    d = np.where(margin > required_margin, d, np.inf)
    if not np.isfinite(d).any():
        raise InfeasibleError(
            f"no safe tensioner within ±{decades:g} decades of m = {m0:g} kg, C = {c0:g} N/m "
            f"(required margin {required_margin:g}); widen decades or change the span")
    i, j = np.unravel_index(np.argmin(d), d.shape)
    if np.isposinf(margin[i, j]):  # proven safe without solving: its margin, as resonance_map has it
        mu = _min_margin(span.frequencies(modes, mass=mm[[i]], stiffness=cc[[j]]), mult, w)[0]
        if not mu > required_margin:  # pragma: no cover - the proof holds with room for rounding
            raise InfeasibleError(f"propose_safe_tensioner: the margin bound failed at m = {mm[i]:g} kg, "
                                  f"C = {cc[j]:g} N/m; please report this case")
        margin[i, j] = mu
    return SafeTensioner(float(mm[i]), float(cc[j]), float(margin[i, j]), float(d[i, j]),
                         m0, c0, mu0, True)


def _unsafe_frequencies(mult: list[float], w: np.ndarray, required_margin: float, *,
                        widen: bool = False) -> tuple[np.ndarray, np.ndarray]:
    """Natural frequencies with a margin <= ``required_margin`` at some sampled speed.

    The margin of P against ``k ω`` is ``<= μ`` exactly for ``0.7(1 - μ) k ω <= P <=
    1.4(1 + μ) k ω``; the union of these intervals over excitations and speeds, merged
    into disjoint (start, end) components. ``μ`` is lowered by 1e-9 so that the set is
    strictly inside the true one (proofs of unsafety made with it hold after rounding).
    ``widen=True`` raises ``μ`` by 1e-9 instead: a set strictly containing the true one
    (proofs of safety).
    """
    lo, hi = BAND
    mu = required_margin + (1e-9 if widen else -1e-9) * (1.0 + abs(required_margin))
    kw = (np.asarray(mult, dtype=float)[:, None] * np.asarray(w, dtype=float)[None, :]).ravel()
    start, end = kw * lo * (1.0 - mu), kw * hi * (1.0 + mu)
    keep = start <= end
    order = np.argsort(start[keep], kind="stable")
    start, end = start[keep][order], end[keep][order]
    if start.size == 0:
        return start, end
    reach = np.maximum.accumulate(end)
    new = np.concatenate([[True], start[1:] > reach[:-1]])
    return start[new], np.maximum.reduceat(end, np.flatnonzero(new))


def _margin_grid(span: TensionerSpan, masses: np.ndarray, stiffnesses: np.ndarray, mult: list[float],
                 w: np.ndarray, modes: int, required_margin: float) -> np.ndarray:
    r"""``resonance_map(...).min_margin``: ``-inf`` where proven <= ``required_margin``, ``+inf`` where proven above.

    Branch and bound on blocks of the (monotonic) grid: every natural frequency rises with
    the stiffness and falls with the mass (the frequency equation
    :math:`G(p) = \sum a_i k_i\cot k_i\ell_i + C - m p^2` decreases in ``p`` between its
    poles, so :math:`\partial p/\partial C = -1/G_p > 0` and
    :math:`\partial p/\partial m = p^2/G_p < 0`), hence over a block each ``P_i`` lies
    between its values at the (heaviest, softest) and (lightest, stiffest) corners. A
    block where one mode's whole range lies in the unsafe set
    (:func:`_unsafe_frequencies`, widened by 1e-9 for rounding) holds no safe point; a
    block where no mode's range meets the (widened) unsafe set holds only safe points;
    other blocks are split, and the points of small blocks are solved exactly, element
    by element as in :func:`resonance_map` (the same values).
    """
    starts, ends = _unsafe_frequencies(mult, w, required_margin)
    starts_wide, ends_wide = _unsafe_frequencies(mult, w, required_margin, widen=True)
    out = np.full((masses.size, stiffnesses.size), -np.inf)
    blocks = np.array([[0, masses.size, 0, stiffnesses.size]])
    exact: list[np.ndarray] = []
    while blocks.size:
        small = (blocks[:, 1] - blocks[:, 0]) * (blocks[:, 3] - blocks[:, 2]) <= 16
        exact.append(blocks[small])
        blocks = blocks[~small]
        if not blocks.size or not starts.size:
            exact.append(blocks)
            break
        m_ends = masses[blocks[:, 0]], masses[blocks[:, 1] - 1]  # a monotonic axis: extremes at the ends
        c_ends = stiffnesses[blocks[:, 2]], stiffnesses[blocks[:, 3] - 1]
        m_corner = np.concatenate([np.maximum(*m_ends), np.minimum(*m_ends)])
        c_corner = np.concatenate([np.minimum(*c_ends), np.maximum(*c_ends)])
        p = span.frequencies(modes, mass=m_corner, stiffness=c_corner)
        low, high = p[: len(blocks)] * (1.0 - 1e-9), p[len(blocks):] * (1.0 + 1e-9)
        k = np.clip(np.searchsorted(starts, low, side="right") - 1, 0, None)
        covered = (starts[k] <= low) & (high <= ends[k])
        k = np.searchsorted(starts_wide, high, side="left") - 1  # the last component starting below high
        clear = (k < 0) | (ends_wide[np.clip(k, 0, None)] < low)
        for i0, i1, j0, j1 in blocks[clear.all(axis=1) & ~covered.any(axis=1)]:
            out[i0:i1, j0:j1] = np.inf
        open_ = blocks[~covered.any(axis=1) & ~clear.all(axis=1)]
        if not open_.size:
            break
        i0, i1, j0, j1 = open_.T
        im, jm = (i0 + i1 + 1) // 2, (j0 + j1 + 1) // 2
        quarters = np.concatenate([np.column_stack(q) for q in ((i0, im, j0, jm), (i0, im, jm, j1),
                                                                (im, i1, j0, jm), (im, i1, jm, j1))])
        blocks = quarters[(quarters[:, 1] > quarters[:, 0]) & (quarters[:, 3] > quarters[:, 2])]
    rows, cols = [], []
    for i0, i1, j0, j1 in (b for part in exact for b in part):
        ii, jj = np.meshgrid(np.arange(i0, i1), np.arange(j0, j1), indexing="ij")
        rows.append(ii.ravel())
        cols.append(jj.ravel())
    if rows:
        ii, jj = np.concatenate(rows), np.concatenate(cols)
        p = span.frequencies(modes, mass=masses[ii], stiffness=stiffnesses[jj])
        out[ii, jj] = _min_margin(p, mult, w)
    return out
