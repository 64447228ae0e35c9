r"""Static equilibrium of the simulation model by a damped Newton iteration.

The assembly's static state is the minimum of the model's potential energy (links,
penalty contacts with the seats and guides, gravity, applied wheel torques, slide
springs and forces; :mod:`chaindrive.simulation._statics`) over the pin positions, the
angles of the free wheels and the positions of the wheels on slides. It is found by
*pseudo-transient continuation* (Kelley & Keyes 1998): each iteration solves

.. math::
    \left(H + \frac{D}{τ^2}\right) Δx = -∇Π

with the positive semi-definite part ``H`` of the Hessian (sparse: each pin couples to
its two neighbours and to the wheels it touches), the diagonal of the masses and wheel
inertias ``D`` and a pseudo time step ``τ``: a backward-Euler step of the model's own
dynamics from rest, strongly damped. ``τ`` grows after each step that lowers the energy
(Armijo) and shrinks otherwise, so the iteration moves like a damped dynamic relaxation
while the chain is slack or out of contact and becomes Newton's method (quadratic
convergence) as it approaches the equilibrium. Each iteration costs one sparse
factorisation of a matrix of about ``2N`` unknowns with a band of a few pins: the cost
grows linearly with the number of links, where the explicit dynamic relaxation needs a
number of steps that grows with the slowest span period over the stable step.

References
----------
C. T. Kelley and D. E. Keyes, "Convergence analysis of pseudo-transient continuation",
SIAM J. Numer. Anal. 35 (1998) 508-523 (the iteration and its step-size rule).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import ConvergenceError
from . import _statics as S

__all__ = ["StaticSolution", "solve_static"]


@dataclass
class StaticSolution:
    """Result of :func:`solve_static`.

    Attributes
    ----------
    x : ndarray
        Unknowns at the equilibrium (pin coordinates, then wheel angles and slides).
    iterations : int
        Accepted Newton steps.
    residual : float
        Largest residual force [N] (moments divided by the wheel's pitch radius).
    energy : float
        Potential energy [J].
    factorisations : int
        Sparse factorisations (accepted and rejected steps).
    """

    x: np.ndarray
    iterations: int
    residual: float
    energy: float
    factorisations: int = 0


class _System:
    """The static system with preallocated buffers."""

    def __init__(self, npins, wp, theta, slide, th_idx, s_idx, gd, tab, par, th_spring=None,
                 th_target=None):
        nw = wp.shape[0]
        th_spring = np.zeros(nw) if th_spring is None else np.asarray(th_spring, float)
        th_target = np.zeros(nw) if th_target is None else np.asarray(th_target, float)
        self.args = (npins, wp, theta, slide, th_idx, s_idx, gd, tab, par, th_spring,
                     th_target)
        self.nx = 2 * npins + int(np.sum(th_idx >= 0)) + int(np.sum(s_idx >= 0))
        self.grad = np.zeros(self.nx)
        cap = 16 * npins + 32 * npins + 64
        self.rows = np.zeros(cap, np.int64)
        self.cols = np.zeros(cap, np.int64)
        self.vals = np.zeros(cap)

    def energy(self, x: np.ndarray) -> float:
        e, _ = S.static_system(x, *self.args, self.grad, self.rows[:0], self.cols[:0],
                               self.vals[:0], False, 0.0)
        return e

    def evaluate(self, x: np.ndarray, tension_floor: float = 0.0
                 ) -> tuple[float, np.ndarray, tuple[np.ndarray, np.ndarray, np.ndarray]]:
        """Energy, gradient (a copy) and the Hessian as triplets (rows, cols, values)."""
        while True:
            e, nnz = S.static_system(x, *self.args, self.grad, self.rows, self.cols,
                                     self.vals, True, tension_floor)
            if nnz <= self.rows.shape[0]:
                break
            cap = 2 * nnz
            self.rows = np.zeros(cap, np.int64)
            self.cols = np.zeros(cap, np.int64)
            self.vals = np.zeros(cap)
        return e, self.grad.copy(), (self.rows[:nnz].copy(), self.cols[:nnz].copy(),
                                     self.vals[:nnz].copy())


def _bordered_solve(nx, npins, hessian, diagonal, rhs):
    """Solve ``(H + diag) y = rhs`` for the chain's bordered band structure.

    Pins 1 … N−1 (unknowns 2 … 2N−1) couple only to their neighbours: a band of half
    width 3, solved by banded LU (LAPACK ``gbsv``, as ``scipy.linalg.solve_banded`` calls
    it); pin 0 (which closes the loop) and the wheel unknowns form a small border,
    eliminated through its Schur complement. The cost is linear in the number of pins.
    Entries outside that structure (none in this model) fall back to a general sparse
    LU. The triplets are summed in their order (``np.bincount``, as ``np.add.at`` would).
    """
    rows, cols, vals = hessian
    lo, hi = 2, 2 * npins
    nin = hi - lo
    inner_r = (rows >= lo) & (rows < hi)
    inner_c = (cols >= lo) & (cols < hi)
    both = inner_r & inner_c
    band = rows[both] - cols[both] + 3
    if np.any((band < 0) | (band > 6)):
        from scipy.sparse import csc_matrix, diags
        from scipy.sparse.linalg import splu

        a = csc_matrix((vals, (rows, cols)), shape=(nx, nx)) + diags(diagonal)
        return splu(a.tocsc(), permc_spec="MMD_AT_PLUS_A").solve(rhs)
    # LAPACK's band storage: 3 rows for the LU's fill-in above the 7 diagonals
    ab = np.zeros((10, nin))
    ab[3:] = np.bincount(band * nin + (cols[both] - lo), vals[both], 7 * nin).reshape(7, nin)
    ab[6] += diagonal[lo:hi]
    border = np.r_[0:lo, hi:nx]
    where = np.full(nx, -1)
    where[border] = np.arange(border.size)
    nb = border.size
    b = np.empty((nb + 1, nin))     # the right-hand sides, column-major for LAPACK
    b[0] = rhs[lo:hi]
    sel = inner_r & ~inner_c        # rows inner, columns border
    b[1:] = np.bincount(where[cols[sel]] * nin + (rows[sel] - lo), vals[sel],
                        nb * nin).reshape(nb, nin)
    sel = ~inner_r & inner_c        # rows border, columns inner
    e_out = np.bincount(where[rows[sel]] * nin + (cols[sel] - lo), vals[sel],
                        nb * nin).reshape(nb, nin)
    sel = ~inner_r & ~inner_c
    f = np.bincount(where[rows[sel]] * nb + where[cols[sel]], vals[sel], nb * nb).reshape(nb, nb)
    f[np.arange(nb), np.arange(nb)] += diagonal[border]
    _, _, z, info = _gbsv()(3, 3, ab, b.T, overwrite_ab=True, overwrite_b=True)
    if info > 0:
        raise np.linalg.LinAlgError("singular matrix")
    schur = f - e_out @ z[:, 1:]
    v = np.linalg.solve(schur, rhs[border] - e_out @ z[:, 0])
    y = np.empty(nx)
    y[lo:hi] = z[:, 0] - z[:, 1:] @ v
    y[border] = v
    return y


def _gbsv():
    """LAPACK's ``dgbsv`` (the routine ``scipy.linalg.solve_banded`` uses for a band)."""
    from scipy.linalg import get_lapack_funcs

    return get_lapack_funcs(("gbsv",), (np.zeros((1, 1)),))[0]


def solve_static(x0: np.ndarray, npins: int, wp: np.ndarray, theta: np.ndarray,
                 slide: np.ndarray, th_idx: np.ndarray, s_idx: np.ndarray, gd: np.ndarray,
                 tab: np.ndarray, par: np.ndarray, masses: np.ndarray, scale: np.ndarray, *,
                 pseudo_time: float, force_tolerance: float, tension_floor: float = 0.0,
                 max_step: float = np.inf, capped: np.ndarray | None = None,
                 angle_spring: np.ndarray | None = None, angle_target: np.ndarray | None = None,
                 max_iterations: int = 400) -> StaticSolution:
    r"""Minimise the model's potential energy from ``x0`` (pseudo-transient Newton).

    .. math:: \left(H + \frac{D}{τ^2}\right) Δx = -∇Π,\qquad
              τ \to 4τ\ \text{(energy lowered)},\quad τ \to τ/4\ \text{(not)}

    Parameters
    ----------
    x0 : ndarray
        Start: pin coordinates ``(x0, y0, x1, ...)`` [m], then the wheel unknowns.
    npins : int
        Number of pins ``N``.
    wp, theta, slide, th_idx, s_idx, gd, tab, par
        Kernel tables (:func:`chaindrive.simulation.run.kernel_arrays`), the fixed wheel
        angles [rad] and slide positions [m], and the index of each wheel's angle and
        slide unknown in ``x`` (``-1``: fixed).
    masses : ndarray
        Mass [kg] (inertia [kg m²]) of each unknown: the ``D`` of the iteration.
    scale : ndarray
        Lever [m] of each unknown: 1 for a coordinate, the pitch radius for an angle;
        the residual moment of an angle is compared as a force, moment / lever.
    pseudo_time : float
        First pseudo time step ``τ₀`` [s] (about the inverse of the slowest span mode).
    force_tolerance : float
        Largest residual force [N] of the converged state.
    tension_floor : float
        Tension [N] the links' geometric stiffness takes at least while the residual is
        above ``1e-3`` of it (a slack chain is a mechanism; this gives its spans the
        transverse stiffness of a string at that tension); then exact Newton.
    max_step : float
        Largest motion [m] of a pin (of a wheel's rim for an angle) in one iteration.
    capped : ndarray, optional
        Lever [m] with which each unknown's step counts against ``max_step`` (0: not
        limited, e.g. pins far from any wheel); default ``scale``.
    angle_spring, angle_target : ndarray, optional
        Torsion spring [N m/rad] tying each free wheel's angle to a target [rad] (0: none).
    max_iterations : int
        Limit of the iterations (accepted and rejected).

    Returns
    -------
    StaticSolution

    Raises
    ------
    ConvergenceError
        The residual does not fall below ``force_tolerance`` within ``max_iterations``.

    Notes
    -----
    Friction and damping do no work at rest: the equilibrium found is frictionless (a
    valid static state of the model with friction, the one a slow assembly reaches).

    References
    ----------
    Kelley & Keyes, SIAM J. Numer. Anal. 35 (1998) 508-523.

    Examples
    --------
    >>> from chaindrive.simulation import roller_example, assemble
    >>> st = assemble(roller_example(links=30, teeth=11))
    >>> bool(st.relax_steps < 100)
    True
    """
    system = _System(npins, wp, theta, slide, th_idx, s_idx, gd, tab, par, angle_spring,
                     angle_target)
    capped = scale if capped is None else capped
    x = np.array(x0, dtype=float)
    floor = float(tension_floor)
    e, g, h = system.evaluate(x, floor)
    tau = float(pseudo_time)
    tau_max = 1e6 * tau

    def residual(grad):
        return float(np.max(np.abs(grad) / scale)) if grad.size else 0.0

    res = residual(g)
    accepted = 0
    nfac = 0
    for _ in range(max_iterations):
        if res <= force_tolerance:
            return StaticSolution(x, accepted, res, e, nfac)
        nfac += 1
        try:
            dx = _bordered_solve(system.nx, npins, h, masses / tau**2, -g)
        except (RuntimeError, np.linalg.LinAlgError):
            # exactly singular: a shorter pseudo step regularises it
            tau *= 0.25
            continue
        # at most `max_step` [m] of motion per iteration (scaled by each unknown's lever: a
        # wheel turns by at most max_step / R), so that no roller is carried over a tooth
        # in one step
        big = float(np.max(np.abs(dx) * capped)) if dx.size else 0.0
        cap = min(1.0, max_step / big) if big > 0 else 1.0
        dx *= cap
        slope = float(g @ dx)
        # backtracking along the direction (the contacts make the energy only piecewise
        # quadratic), then a shorter pseudo step
        for alpha in (1.0, 0.5, 0.25):
            x_try = x + alpha * dx
            e_try = system.energy(x_try)
            ok = np.isfinite(e_try) and e_try - e <= 1e-4 * alpha * slope
            if not ok and np.isfinite(e_try) and \
                    abs(e_try - e) <= 1e-12 * max(abs(e), abs(e_try)):
                # at the resolution of the energy: accept if the residual falls
                _, g_try, _ = system.evaluate(x_try)
                ok = residual(g_try) < res
            if ok:
                break
        if ok:
            x = x_try
            e, g, h = system.evaluate(x, floor)
            res = residual(g)
            if floor > 0.0 and res < 1e-3 * floor:
                floor = 0.0
                e, g, h = system.evaluate(x, floor)
            accepted += 1
            if alpha == 1.0 and cap == 1.0:
                tau = min(4.0 * tau, tau_max)
        else:
            tau *= 0.25
    if res <= force_tolerance:
        return StaticSolution(x, accepted, res, e, nfac)
    raise ConvergenceError(
        f"static assembly: the Newton iteration did not reach equilibrium within "
        f"{max_iterations} iterations (largest residual force {res:.3g} N, tolerance "
        f"{force_tolerance:.3g} N); a drive whose chain can hang off a wheel or whose wheels "
        f"have no seated roller has no single static state")


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
