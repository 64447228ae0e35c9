"""Banded linear algebra of the linearly implicit integrator (internal).

The symmetric cyclic tridiagonal solve of the link force increments
(:func:`cyclic_tridiagonal_factor`, :func:`cyclic_tridiagonal_substitute`), the Woodbury
passes around it (``P⁻¹ g = W g − W Gᵀ λ`` for ``P = W⁻¹ + Gᵀ a G``) and the small dense
solve of the wheels' Schur complement; used by :mod:`._implicit`.
"""

from __future__ import annotations

import numpy as np
from numba import njit


@njit(cache=True, fastmath=False)
def cyclic_tridiagonal_factor(d: np.ndarray, e: np.ndarray, idd: np.ndarray, ff: np.ndarray) -> float:
    """Factor the symmetric cyclic tridiagonal matrix ``A`` (n >= 3); return the last pivot.

    ``A[l, l] = d[l]``, ``A[l, l+1] = A[l+1, l] = e[l]`` (``l + 1`` modulo n: ``e[n-1]``
    couples rows ``n-1`` and 0). Gaussian elimination without pivoting (stable for the
    symmetric positive definite matrices of the integrator) carrying the fill-in of the
    last column: ``idd`` the inverse pivots of rows ``0 … n-2``, ``ff`` the fill-in
    (``ff[n-2]`` includes ``e[n-2]``). Cost linear in n.
    """
    n = d.shape[0]
    dcur = d[0]
    ff[0] = e[n - 1]
    dlast = d[n - 1]
    for ll in range(n - 2):
        ip = 1.0 / dcur
        idd[ll] = ip
        dcur = d[ll + 1] - e[ll] * e[ll] * ip
        ff[ll + 1] = -e[ll] * ip * ff[ll]
        dlast -= ff[ll] * ff[ll] * ip
    idd[n - 2] = 1.0 / dcur
    ff[n - 2] += e[n - 2]
    return dlast - ff[n - 2] * ff[n - 2] * idd[n - 2]


@njit(cache=True, fastmath=False)
def cyclic_tridiagonal_substitute(e: np.ndarray, idd: np.ndarray, ff: np.ndarray, dlast: float,
                                  b: np.ndarray, x: np.ndarray) -> None:
    """Solve ``A x = b`` with the factors of :func:`cyclic_tridiagonal_factor` (``x`` may be ``b``)."""
    n = b.shape[0]
    # forward: x holds the eliminated right-hand side
    blast = b[n - 1]
    prev = b[0]
    x[0] = prev
    for ll in range(n - 2):
        q = prev * idd[ll]
        blast -= ff[ll] * q
        prev = b[ll + 1] - e[ll] * q
        x[ll + 1] = prev
    blast -= ff[n - 2] * prev * idd[n - 2]
    xl = blast / dlast
    x[n - 1] = xl
    nxt = (prev - ff[n - 2] * xl) * idd[n - 2]
    x[n - 2] = nxt
    for ll in range(n - 3, -1, -1):
        nxt = (x[ll] - e[ll] * nxt - ff[ll] * xl) * idd[ll]
        x[ll] = nxt


@njit(cache=True, fastmath=False)
def cyclic_tridiagonal_solve(d: np.ndarray, e: np.ndarray, b: np.ndarray, x: np.ndarray) -> None:
    """``A x = b`` for the symmetric cyclic tridiagonal ``A`` (:func:`cyclic_tridiagonal_factor`)."""
    n = d.shape[0]
    idd = np.empty(n)
    ff = np.empty(n)
    dlast = cyclic_tridiagonal_factor(d, e, idd, ff)
    cyclic_tridiagonal_substitute(e, idd, ff, dlast, b, x)


@njit(cache=True, fastmath=False)
def _link_rhs(gx, gy, ox, oy, wxx, wxy, wyy, ux, uy, lam):
    """``o = W g`` and the link system's right-hand side ``λ = G o``."""
    n = gx.shape[0]
    for i in range(n):
        ox[i] = wxx[i] * gx[i] + wxy[i] * gy[i]
        oy[i] = wxy[i] * gx[i] + wyy[i] * gy[i]
    for li in range(n - 1):
        lam[li] = ux[li] * (ox[li + 1] - ox[li]) + uy[li] * (oy[li + 1] - oy[li])
    lam[n - 1] = ux[n - 1] * (ox[0] - ox[n - 1]) + uy[n - 1] * (oy[0] - oy[n - 1])


@njit(cache=True, fastmath=False)
def _link_back(ox, oy, wxx, wxy, wyy, ux, uy, lam):
    """``o ← o − W Gᵀ λ``, ``(Gᵀ λ)_i = λ_{i−1} u_{i−1} − λ_i u_i``."""
    n = ox.shape[0]
    _link_back_pin(ox, oy, wxx, wxy, wyy, ux, uy, lam, 0, n - 1)
    for i in range(1, n):
        _link_back_pin(ox, oy, wxx, wxy, wyy, ux, uy, lam, i, i - 1)


@njit(cache=True, fastmath=False, inline="always")
def _link_back_pin(ox, oy, wxx, wxy, wyy, ux, uy, lam, i, im):
    gtx = lam[im] * ux[im] - lam[i] * ux[i]
    gty = lam[im] * uy[im] - lam[i] * uy[i]
    ox[i] -= wxx[i] * gtx + wxy[i] * gty
    oy[i] -= wxy[i] * gtx + wyy[i] * gty


@njit(cache=True, fastmath=False)
def _apply_inverse(gx, gy, ox, oy, wxx, wxy, wyy, ux, uy, of, idd, ff, dlast, lam):
    """``o = P⁻¹ g`` for ``P = W⁻¹ + Gᵀ a G`` (Woodbury, factored link system)."""
    _link_rhs(gx, gy, ox, oy, wxx, wxy, wyy, ux, uy, lam)
    cyclic_tridiagonal_substitute(of, idd, ff, dlast, lam, lam)
    _link_back(ox, oy, wxx, wxy, wyy, ux, uy, lam)


@njit(cache=True, fastmath=False, inline="always")
def _forward(p, bl, ip, el, fl, b, ll):
    """One row of :func:`cyclic_tridiagonal_substitute`'s elimination."""
    q = p * ip
    bl -= fl * q
    p = b[ll + 1] - el * q
    b[ll + 1] = p
    return p, bl


@njit(cache=True, fastmath=False, inline="always")
def _last_rows(p, bl, ip, fl, dlast, b):
    """The last two unknowns of :func:`cyclic_tridiagonal_substitute`."""
    n = b.shape[0]
    xl = (bl - fl * p * ip) / dlast
    nxt = (p - fl * xl) * ip
    b[n - 1] = xl
    b[n - 2] = nxt
    return xl, nxt


@njit(cache=True, fastmath=False, inline="always")
def _backward(nxt, xl, ip, el, fl, b, ll):
    """One row of :func:`cyclic_tridiagonal_substitute`'s back substitution."""
    nxt = (b[ll] - el * nxt - fl * xl) * ip
    b[ll] = nxt
    return nxt


@njit(cache=True, fastmath=False)
def _factor_solve4(d, e, idd, ff, b0, b1, b2, b3, wide):
    """:func:`cyclic_tridiagonal_factor` fused with the solution of two right-hand sides
    (``b0``, ``b1``), four if ``wide`` (in place): the division recurrence of the
    factorisation and the substitutions' multiply–add recurrences run in one loop, so
    that they overlap (each the same arithmetic as :func:`cyclic_tridiagonal_substitute`:
    the results are those of the separate solves to the last bit)."""
    n = d.shape[0]
    dcur = d[0]
    ff[0] = e[n - 1]
    dlast = d[n - 1]
    bl0, bl1, bl2, bl3 = b0[n - 1], b1[n - 1], b2[n - 1], b3[n - 1]
    p0, p1, p2, p3 = b0[0], b1[0], b2[0], b3[0]
    for ll in range(n - 2):
        ip = 1.0 / dcur
        idd[ll] = ip
        el = e[ll]
        fl = ff[ll]
        dcur = d[ll + 1] - el * el * ip
        ff[ll + 1] = -el * ip * fl
        dlast -= fl * fl * ip
        p0, bl0 = _forward(p0, bl0, ip, el, fl, b0, ll)
        p1, bl1 = _forward(p1, bl1, ip, el, fl, b1, ll)
        if wide:
            p2, bl2 = _forward(p2, bl2, ip, el, fl, b2, ll)
            p3, bl3 = _forward(p3, bl3, ip, el, fl, b3, ll)
    ip = 1.0 / dcur
    idd[n - 2] = ip
    fl = ff[n - 2] + e[n - 2]
    ff[n - 2] = fl
    dlast -= fl * fl * ip
    xl0, n0 = _last_rows(p0, bl0, ip, fl, dlast, b0)
    xl1, n1 = _last_rows(p1, bl1, ip, fl, dlast, b1)
    xl2, n2, xl3, n3 = 0.0, 0.0, 0.0, 0.0
    if wide:
        xl2, n2 = _last_rows(p2, bl2, ip, fl, dlast, b2)
        xl3, n3 = _last_rows(p3, bl3, ip, fl, dlast, b3)
    for ll in range(n - 3, -1, -1):
        el = e[ll]
        fl = ff[ll]
        ip = idd[ll]
        n0 = _backward(n0, xl0, ip, el, fl, b0, ll)
        n1 = _backward(n1, xl1, ip, el, fl, b1, ll)
        if wide:
            n2 = _backward(n2, xl2, ip, el, fl, b2, ll)
            n3 = _backward(n3, xl3, ip, el, fl, b3, ll)
    return dlast


@njit(cache=True, fastmath=False)
def _small_solve(a, b, nq):
    """``b ← a⁻¹ b`` for the leading ``nq x nq`` block (Gaussian elimination, partial pivoting)."""
    for col in range(nq):
        piv = col
        for r in range(col + 1, nq):
            if abs(a[r, col]) > abs(a[piv, col]):
                piv = r
        if piv != col:
            for cc in range(nq):
                a[col, cc], a[piv, cc] = a[piv, cc], a[col, cc]
            b[col], b[piv] = b[piv], b[col]
        for r in range(col + 1, nq):
            f = a[r, col] / a[col, col]
            for cc in range(col, nq):
                a[r, cc] -= f * a[col, cc]
            b[r] -= f * b[col]
    for r in range(nq - 1, -1, -1):
        acc = b[r]
        for cc in range(r + 1, nq):
            acc -= a[r, cc] * b[cc]
        b[r] = acc / a[r, r]


@njit(cache=True, fastmath=False, inline="always")
def _link_entries(dg, of, wxx, wxy, wyy, ux, uy, inv_ak, li, j):
    """Diagonal and off-diagonal entry of link ``li`` (pins ``li``, ``j``) in ``1/a + G W Gᵀ``."""
    ex = ux[li]
    ey = uy[li]
    dg[li] = inv_ak + ex * ((wxx[li] + wxx[j]) * ex + (wxy[li] + wxy[j]) * ey) \
        + ey * ((wxy[li] + wxy[j]) * ex + (wyy[li] + wyy[j]) * ey)
    of[li] = -(ex * (wxx[j] * ux[j] + wxy[j] * uy[j]) + ey * (wxy[j] * ux[j] + wyy[j] * uy[j]))
