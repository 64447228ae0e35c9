r"""The link system's passes of :mod:`._batched_implicit`, across the lanes (internal).

Each pass runs over the pins or links with the lanes (variants) the inner, contiguous
dimension of its ``(N, V)`` arrays, so that it compiles to vector instructions; each
lane's arithmetic is that of the single kernel (:mod:`._implicit`, :mod:`._banded`)
to the last bit: the link forces, the pins' forces and 2 x 2 inverses, the entries and
right-hand sides of the cyclic tridiagonal link system, its factorisation with the
substitutions, the Woodbury back pass and the pins' update.
"""

from __future__ import annotations

import math

from numba import njit
from numba.core.compiler import CompilerBase, DefaultPassBuilder

from . import _contact as C

__all__ = ["BLOCK", "_back", "_entries", "_factor_solve", "_links", "_pin_forces", "_pin_inverses",
           "_rhs", "_update"]



class _NoAlias(CompilerBase):
    """numba's nopython pipeline with the array arguments marked ``noalias`` (no pass
    is called with overlapping arrays), so that the lane loops vectorise without
    run-time overlap checks (too many of them: LLVM would give up)."""

    def define_pipelines(self):
        self.state.flags.noalias = True
        pm = DefaultPassBuilder.define_nopython_pipeline(self.state)
        pm.finalize()
        return [pm]


_OPTS = {"cache": True, "fastmath": False, "error_model": "numpy", "pipeline_class": _NoAlias}

#: lanes per block (a divisor of ``_batched.LANES``): the passes work on a block's
#: ``(N, BLOCK)`` arrays, small enough for the core's L2 cache; not fewer than 32: LLVM's
#: vector loop takes 16 lanes an iteration (blocks of 8 ran scalar, 27 % slower)
BLOCK = 32


@njit(**_OPTS)
def _pin_inverses(mh, mxx, mxy, myy, wxx, wxy, wyy):
    """``W_i = (M_i/h + contact terms)⁻¹`` of every pin and lane."""
    n, nv = mxx.shape
    for i in range(n):
        for v in range(nv):
            axx = mh[v] + mxx[i, v]
            axy = mxy[i, v]
            ayy = mh[v] + myy[i, v]
            idet = 1.0 / (axx * ayy - axy * axy)
            wxx[i, v] = ayy * idet
            wxy[i, v] = -axy * idet
            wyy[i, v] = axx * idet


@njit(**_OPTS)
def _entries(dg, of, wxx, wxy, wyy, ux, uy, inv_ak):
    """Diagonal and off-diagonal of ``1/a + G W Gᵀ`` of every link and lane
    (:func:`._banded._link_entries`)."""
    n, nv = dg.shape
    for li in range(n):
        j = li + 1 if li + 1 < n else 0
        for v in range(nv):
            ex = ux[li, v]
            ey = uy[li, v]
            dg[li, v] = inv_ak[v] + ex * ((wxx[li, v] + wxx[j, v]) * ex + (wxy[li, v] + wxy[j, v]) * ey) \
                + ey * ((wxy[li, v] + wxy[j, v]) * ex + (wyy[li, v] + wyy[j, v]) * ey)
            of[li, v] = -(ex * (wxx[j, v] * ux[j, v] + wxy[j, v] * uy[j, v])
                          + ey * (wxy[j, v] * ux[j, v] + wyy[j, v] * uy[j, v]))


@njit(**_OPTS)
def _rhs(gx, gy, ox, oy, wxx, wxy, wyy, ux, uy, lam):
    """``o = W g`` and ``λ = G o`` of every lane (:func:`._banded._link_rhs`)."""
    n, nv = gx.shape
    for i in range(n):
        for v in range(nv):
            ox[i, v] = wxx[i, v] * gx[i, v] + wxy[i, v] * gy[i, v]
            oy[i, v] = wxy[i, v] * gx[i, v] + wyy[i, v] * gy[i, v]
    for li in range(n):
        j = li + 1 if li + 1 < n else 0
        for v in range(nv):
            lam[li, v] = ux[li, v] * (ox[j, v] - ox[li, v]) + uy[li, v] * (oy[j, v] - oy[li, v])


@njit(**_OPTS)
def _back(ox, oy, wxx, wxy, wyy, ux, uy, lam):
    """``o ← o − W Gᵀ λ`` of every lane (:func:`._banded._link_back`)."""
    n, nv = ox.shape
    for i in range(n):
        im = i - 1 if i > 0 else n - 1
        for v in range(nv):
            gtx = lam[im, v] * ux[im, v] - lam[i, v] * ux[i, v]
            gty = lam[im, v] * uy[im, v] - lam[i, v] * uy[i, v]
            ox[i, v] -= wxx[i, v] * gtx + wxy[i, v] * gty
            oy[i, v] -= wxy[i, v] * gtx + wyy[i, v] * gty


@njit(**_OPTS)
def _factor_solve(d, e, idd, ff, dlast, bl, bs, nb, dcur):
    """:func:`._banded._factor_solve4` of every lane: the cyclic tridiagonal ``(d, e)``
    factored (inverse pivots ``idd``, fill-in ``ff``, last pivot ``dlast``) and the first
    ``nb`` right-hand sides ``bs[r]`` ``(N, V)`` solved in place, each with the same
    arithmetic as :func:`._banded.cyclic_tridiagonal_substitute`; ``bl`` ``(4, V)`` and
    ``dcur`` ``(V,)`` work."""
    n, nv = d.shape
    for v in range(nv):
        dcur[v] = d[0, v]
        ff[0, v] = e[n - 1, v]
        dlast[v] = d[n - 1, v]
    for r in range(nb):
        for v in range(nv):
            bl[r, v] = bs[r, n - 1, v]
    for ll in range(n - 2):
        for v in range(nv):
            ip = 1.0 / dcur[v]
            idd[ll, v] = ip
            el = e[ll, v]
            fl = ff[ll, v]
            dcur[v] = d[ll + 1, v] - el * el * ip
            ff[ll + 1, v] = -el * ip * fl
            dlast[v] -= fl * fl * ip
        for r in range(nb):
            for v in range(nv):
                # the forward row of the substitution (``p`` is b[ll]; the right-hand
                # sides indexed, not viewed: a view per row would cost its reference count)
                q = bs[r, ll, v] * idd[ll, v]
                bl[r, v] -= ff[ll, v] * q
                bs[r, ll + 1, v] = bs[r, ll + 1, v] - e[ll, v] * q
    for v in range(nv):
        ip = 1.0 / dcur[v]
        idd[n - 2, v] = ip
        fl = ff[n - 2, v] + e[n - 2, v]
        ff[n - 2, v] = fl
        dlast[v] -= fl * fl * ip
    for r in range(nb):
        for v in range(nv):
            ip = idd[n - 2, v]
            fl = ff[n - 2, v]
            p = bs[r, n - 2, v]
            xl = (bl[r, v] - fl * p * ip) / dlast[v]
            bs[r, n - 2, v] = (p - fl * xl) * ip
            bs[r, n - 1, v] = xl
        for ll in range(n - 3, -1, -1):
            for v in range(nv):
                bs[r, ll, v] = (bs[r, ll, v] - e[ll, v] * bs[r, ll + 1, v]
                                - ff[ll, v] * bs[r, n - 1, v]) * idd[ll, v]


@njit(**_OPTS)
def _links(x, y, vx, vy, k, c, thh, rest, tension, tstar, ux, uy):
    """Link tensions at the start of the step, their linearised values without the
    implicit increment ``T* = T + θ h k l̇`` and directions, every lane."""
    n, nv = x.shape
    for i in range(n - 1):
        for v in range(nv):
            tt, ex, ey, ldot = C.link_force(x[i + 1, v] - x[i, v], y[i + 1, v] - y[i, v],
                                            vx[i + 1, v] - vx[i, v], vy[i + 1, v] - vy[i, v],
                                            k[v], c[v], rest[i, v])
            tension[i, v] = tt
            tstar[i, v] = tt + thh[v] * k[v] * ldot
            ux[i, v] = ex
            uy[i, v] = ey
    for v in range(nv):
        dx = x[0, v] - x[n - 1, v]
        dy = y[0, v] - y[n - 1, v]
        ll = math.sqrt(dx * dx + dy * dy)
        ex = dx / ll
        ey = dy / ll
        ldot = (vx[0, v] - vx[n - 1, v]) * ex + (vy[0, v] - vy[n - 1, v]) * ey
        tt = k[v] * (ll - rest[n - 1, v]) + c[v] * ldot
        tension[n - 1, v] = tt
        tstar[n - 1, v] = tt + thh[v] * k[v] * ldot
        ux[n - 1, v] = ex
        uy[n - 1, v] = ey


@njit(**_OPTS)
def _pin_forces(fx, fy, fgx, fgy, cm, vx, vy, tstar, ux, uy, yx, yy):
    """``F_i``: explicit forces, gravity, damping and the links' ``T*``, every lane."""
    n, nv = fx.shape
    for i in range(n):
        im = i - 1 if i > 0 else n - 1
        for v in range(nv):
            yx[i, v] = fx[i, v] + fgx[v] - cm[v] * vx[i, v] + tstar[i, v] * ux[i, v] \
                - tstar[im, v] * ux[im, v]
            yy[i, v] = fy[i, v] + fgy[v] - cm[v] * vy[i, v] + tstar[i, v] * uy[i, v] \
                - tstar[im, v] * uy[im, v]


@njit(**_OPTS)
def _update(act, h, x, y, vx, vy, dvx, dvy, fx, fy, mxx, mxy, myy):
    """The pins of the stepping lanes moved (``v += Δv``, ``x += h v``); the force and
    matrix accumulators cleared."""
    n, nv = x.shape
    for i in range(n):
        for v in range(nv):
            a = act[v]
            nvx = vx[i, v] + dvx[i, v]
            nvy = vy[i, v] + dvy[i, v]
            vx[i, v] = nvx if a else vx[i, v]
            vy[i, v] = nvy if a else vy[i, v]
            x[i, v] = x[i, v] + h[v] * nvx if a else x[i, v]
            y[i, v] = y[i, v] + h[v] * nvy if a else y[i, v]
            fx[i, v] = 0.0
            fy[i, v] = 0.0
            mxx[i, v] = 0.0
            mxy[i, v] = 0.0
            myy[i, v] = 0.0
