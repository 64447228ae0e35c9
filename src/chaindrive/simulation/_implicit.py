r"""Compiled hot loop of the linearly implicit integrator (internal).

:func:`integrate_implicit` has the signature of :func:`._kernel.integrate` (the same
state, parameter, wheel, guide and record arrays) and advances the same model with the
stiff parts of the force treated implicitly, so that the step is set by accuracy and
not by the stability of the link springs (derivation in ``docs/simulation.md``,
"Integrator"):

* link springs and dampers (``k``, ``c``) and, per pin, the normal contact springs and
  dampers of the wheels and guides and the sticking slope of the regularised friction:
  linearised about the state at the start of the step (one linearly implicit Euler
  step, ``(M/h + D + h K) Δv = F + h K v``);
* the system matrix is ``W⁻¹ + Gᵀ a G`` with ``W⁻¹`` block diagonal (2 x 2 per pin)
  and ``G`` the link directions (one row per link, nonzero at its two pins): by the
  Woodbury identity the solve reduces to the symmetric *cyclic tridiagonal* system of
  the link force increments ``(1/a + G W Gᵀ) λ = G W F`` (``a = h k + c``), solved by
  :func:`cyclic_tridiagonal_solve`, linear in the number of links;
* the wheels' rotations and slides after the pins (Gauss–Seidel): implicit in their
  own contact stiffness, with the pins' new velocities;
* the optional transverse span damping ``−α m v_⊥`` (``P_CSPAN`` > 0, a study): linear in
  the pin's own velocity, it adds ``θ α m n nᵀ`` to the pin's 2 x 2 block (``n`` the unit
  normal to its neighbours' chord, frozen at the start of the step) and its value at
  the start of the step to the force (:func:`._kernel.span_damping_forces`), as the link
  dampers.

Layout: positions and velocities in separate ``x``/``y`` arrays inside the kernel, the
link rest lengths in one array (no odd/even branch).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from . import _contact as C
from . import _kernel as K
from ._banded import (  # noqa: F401 - the cyclic solver is part of this module's interface
    _apply_inverse,
    _factor_solve4,
    _link_back,
    _link_entries,
    _link_rhs,
    _small_solve,
    cyclic_tridiagonal_factor,
    cyclic_tridiagonal_solve,
    cyclic_tridiagonal_substitute,
)
from ._kernel import advance_motor, speed_factor, wheel_drive_torque

# per-contact columns kept for the wheels' implicit update after the pins
C_BETA, C_S, C_NX, C_NY, C_L, C_LT, C_DN, C_DT, C_FN0, C_FT0, C_FN = range(11)


@njit(cache=True, fastmath=False, inline="always")
def _add_pin_matrix(mxx, mxy, myy, i, coef, ax, ay):
    """``M_i += coef (a aᵀ)``."""
    mxx[i] += coef * ax * ax
    mxy[i] += coef * ax * ay
    myy[i] += coef * ay * ay


@njit(cache=True, fastmath=False)
def _span_damping_matrix(x, y, mxx, mxy, myy, coef):
    """``M_i += coef n nᵀ`` for the span damping: ``n`` the unit normal to the chord of
    pin ``i``'s neighbours (``coef = θ α m`` [N s/m]; the implicit part of
    :func:`._kernel.span_damping_forces`)."""
    for i in range(x.shape[0]):
        tx, ty, inv = K.neighbour_chord(x, y, i)
        ci = coef * inv
        mxx[i] += ci * ty * ty
        mxy[i] -= ci * tx * ty
        myy[i] += ci * tx * tx


@njit(cache=True, fastmath=False, inline="always")
def _pin_inverse(i, mh, mxx, mxy, myy, wxx, wxy, wyy):
    """``W_i = (M_i/h + contact terms)⁻¹`` (2 x 2)."""
    axx = mh + mxx[i]
    axy = mxy[i]
    ayy = mh + myy[i]
    idet = 1.0 / (axx * ayy - axy * axy)
    wxx[i] = ayy * idet
    wxy[i] = -axy * idet
    wyy[i] = axx * idet


@njit(cache=True, fastmath=False)
def _drop_tensile(cinfo, ncand, cand, qrot, qsl, dq, dvx, dvy, yx, yy, mxx, mxy, myy, wtq, wsf,
                  contact):
    """Drop the wheel contacts whose linearised normal force at the end of the step is
    tensile (take their terms out of the pins' forces and matrices); True if any."""
    changed = False
    for w in range(cinfo.shape[0]):
        dom = dq[qrot[w]] if qrot[w] >= 0 else 0.0
        dsd = dq[qsl[w]] if qsl[w] >= 0 else 0.0
        for ic in range(ncand[w]):
            be = cinfo[w, ic, C_BETA]
            if be == 0.0:
                continue
            i = cand[w, ic]
            nx = cinfo[w, ic, C_NX]
            ny = cinfo[w, ic, C_NY]
            dvn = nx * dvx[i] + ny * dvy[i] - dom * cinfo[w, ic, C_L] - dsd * cinfo[w, ic, C_DN]
            fn0 = cinfo[w, ic, C_FN0]
            if fn0 + be * dvn >= 0.0:
                continue
            changed = True
            ft0 = cinfo[w, ic, C_FT0]
            s = cinfo[w, ic, C_S]
            yx[i] += fn0 * nx + ft0 * ny
            yy[i] += fn0 * ny - ft0 * nx
            _add_pin_matrix(mxx, mxy, myy, i, -be, nx, ny)
            _add_pin_matrix(mxx, mxy, myy, i, -s, -ny, nx)
            wtq[w] -= fn0 * cinfo[w, ic, C_L] - ft0 * cinfo[w, ic, C_LT]
            wsf[w] -= fn0 * cinfo[w, ic, C_DN] - ft0 * cinfo[w, ic, C_DT]
            contact[i] -= cinfo[w, ic, C_FN]
            cinfo[w, ic, C_BETA] = 0.0
            cinfo[w, ic, C_S] = 0.0
    return changed


@njit(cache=True, fastmath=False)
def _solve(n, nw, yx, yy, wxx, wxy, wyy, ux, uy, dg, of, dd, ff, lam, lamq, inv_ak, dvx, dvy, ws,
           wp, ncand, cand, cinfo, qrot, qsl, bx, by, zx, zy, sq, fq, wtq, wsf, h, t, gx, gy):
    """Velocity changes of the pins (``dvx``, ``dvy``) and of the wheels' rotations and
    slides in contact (``fq[qrot[w]]``, ``fq[qsl[w]]``) of one linearly implicit step."""
    # links: P = W⁻¹ + Gᵀ a G; by Woodbury P⁻¹ g = W g − W Gᵀ λ with
    # (1/a + G W Gᵀ) λ = G W g, a cyclic tridiagonal system factored once per step
    for li in range(n - 1):
        _link_entries(dg, of, wxx, wxy, wyy, ux, uy, inv_ak, li, li + 1)
    _link_entries(dg, of, wxx, wxy, wyy, ux, uy, inv_ak, n - 1, 0)
    # the wheels' rotations and slides in contact with pins: bordered system
    # [[P, B], [Bᵀ, Q]] [Δv, Δq] = [F, F_q], solved by its Schur complement
    nq = 0
    for w in range(nw):
        mode = wp[w, K.W_MODE]
        qrot[w] = -1
        qsl[w] = -1
        if (mode == K.MODE_FREE or mode == K.MODE_MOTOR) and ncand[w] > 0:
            qrot[w] = nq
            nq += 1
        if wp[w, K.W_SLIDE] > 0.0 and ncand[w] > 0:
            qsl[w] = nq
            nq += 1
    # the rows of B are zero off their wheel's pins (cleared after use below)
    for q in range(nq):
        for q2 in range(nq):
            sq[q, q2] = 0.0
        fq[q] = 0.0
    for w in range(nw):
        om = ws[w, K.S_OMEGA]
        qr = qrot[w]
        qs = qsl[w]
        if qr >= 0:
            sq[qr, qr] = wp[w, K.W_INERTIA] / h
            fq[qr] = wtq[w] + wp[w, K.W_TORQUE] - wp[w, K.W_DAMP] * om
            if wp[w, K.W_MODE] == K.MODE_MOTOR:
                fq[qr] += wheel_drive_torque(wp, ws, w, om, t, fq[qr], h)
        if qs >= 0:
            sq[qs, qs] = wp[w, K.W_SMASS] / h
            fq[qs] = wsf[w] + wp[w, K.W_SF] - wp[w, K.W_SK] * ws[w, K.S_S] \
                - wp[w, K.W_SC] * ws[w, K.S_SDOT] \
                + wp[w, K.W_SMASS] * (gx * wp[w, K.W_DX] + gy * wp[w, K.W_DY])
        if qr < 0 and qs < 0:
            continue
        for ic in range(ncand[w]):
            be = cinfo[w, ic, C_BETA]
            if be == 0.0:
                continue
            s = cinfo[w, ic, C_S]
            i = cand[w, ic]
            nx = cinfo[w, ic, C_NX]
            ny = cinfo[w, ic, C_NY]
            lev = cinfo[w, ic, C_L]
            levt = cinfo[w, ic, C_LT]
            dn = cinfo[w, ic, C_DN]
            dtt = cinfo[w, ic, C_DT]
            # contact rows J_n = [nᵀ, −L, −d·n], J_t = [tᵀ, −L_t, −d·t]: β J_nᵀJ_n + s J_tᵀJ_t
            if qr >= 0:
                bx[qr, i] -= be * lev * nx - s * levt * ny
                by[qr, i] -= be * lev * ny + s * levt * nx
                sq[qr, qr] += be * lev * lev + s * levt * levt
            if qs >= 0:
                bx[qs, i] -= be * dn * nx - s * dtt * ny
                by[qs, i] -= be * dn * ny + s * dtt * nx
                sq[qs, qs] += be * dn * dn + s * dtt * dtt
            if qr >= 0 and qs >= 0:
                sq[qr, qs] += be * lev * dn + s * levt * dtt
                sq[qs, qr] += be * lev * dn + s * levt * dtt
    # P⁻¹ F and P⁻¹ B_0 (up to B_2) with the factorisation in one pass, further border
    # columns after
    _link_rhs(yx, yy, dvx, dvy, wxx, wxy, wyy, ux, uy, lam)
    fused = min(nq, 3)
    for q in range(fused):
        _link_rhs(bx[q], by[q], zx[q], zy[q], wxx, wxy, wyy, ux, uy, lamq[q])
    if nq > 1:
        for q in range(fused, 3):
            lamq[q, :] = 0.0   # an unused right-hand side: zeros stay zeros
    dlast = _factor_solve4(dg, of, dd, ff, lam, lamq[0], lamq[1], lamq[2], nq > 1)
    _link_back(dvx, dvy, wxx, wxy, wyy, ux, uy, lam)
    if nq > 0:
        for q in range(fused):
            _link_back(zx[q], zy[q], wxx, wxy, wyy, ux, uy, lamq[q])
        for q in range(fused, nq):
            _apply_inverse(bx[q], by[q], zx[q], zy[q], wxx, wxy, wyy, ux, uy, of, dd, ff,
                           dlast, lamq[0])
        # Schur complement S = Q − Bᵀ P⁻¹ B, right-hand side F_q − Bᵀ P⁻¹ F; B is
        # sparse (its rows live on their wheel's candidate pins)
        for w in range(nw):
            for q in (qrot[w], qsl[w]):
                if q < 0:
                    continue
                for ic in range(ncand[w]):
                    i = cand[w, ic]
                    bxq = bx[q, i]
                    byq = by[q, i]
                    if bxq == 0.0 and byq == 0.0:
                        continue
                    fq[q] -= bxq * dvx[i] + byq * dvy[i]
                    for q2 in range(nq):
                        sq[q, q2] -= bxq * zx[q2, i] + byq * zy[q2, i]
                    bx[q, i] = 0.0
                    by[q, i] = 0.0
        _small_solve(sq, fq, nq)
        for q in range(nq):
            dq = fq[q]
            for i in range(n):
                dvx[i] -= zx[q, i] * dq
                dvy[i] -= zy[q, i] * dq
    return nq


@njit(cache=True, fastmath=False)
def integrate_implicit(pos: np.ndarray, vel: np.ndarray, force: np.ndarray, work: np.ndarray,
                       tension: np.ndarray, contact: np.ndarray, ws: np.ndarray, wp: np.ndarray,
                       gd: np.ndarray, tab: np.ndarray, par: np.ndarray, t0: float, nsteps: int,
                       record_every: int, probes: np.ndarray, rec_t: np.ndarray,
                       rec_probe: np.ndarray, rec_tension: np.ndarray, rec_contact: np.ndarray,
                       rec_ws: np.ndarray, rec_pos: np.ndarray, rec_energy: np.ndarray,
                       rec_start: int) -> int:
    """Advance ``nsteps`` linearly implicit steps from ``t0``; return the records written.

    Same arguments as :func:`._kernel.integrate` (``force`` and ``work`` unused).
    """
    n = pos.shape[0]
    nw = ws.shape[0]
    ng = gd.shape[0]
    npr = probes.shape[0]
    m = par[K.P_MASS]
    k = par[K.P_K]
    c = par[K.P_C]
    rr = par[K.P_RROLLER]
    kc = par[K.P_KC]
    cc = par[K.P_CC]
    mu = par[K.P_MU]
    veps = par[K.P_VEPS]
    gx = par[K.P_GX]
    gy = par[K.P_GY]
    h = par[K.P_DT]
    cglob = par[K.P_CGLOB]
    kg = par[K.P_KG]
    cg = par[K.P_CG]
    dtref = par[K.P_DTREF]
    inv_m = 1.0 / m
    mh = m / h
    th = par[K.P_THETA]
    cspan = par[K.P_CSPAN] * m
    ak = th * (h * k + c)
    inv_ak = 1.0 / ak
    betac = th * (h * kc + cc)
    betag = th * (h * kg + cg)
    thh = th * h
    margin = 0.25 * rr
    # separate coordinate arrays; rest lengths per link (no odd/even branch)
    x, y, vx, vy, rest = K.pin_arrays(pos, vel, par[K.P_PITCH], par[K.P_PITCH2])
    ux = np.empty(n)
    uy = np.empty(n)
    tstar = np.empty(n)
    fx = np.zeros(n)
    fy = np.zeros(n)
    mxx = np.zeros(n)
    mxy = np.zeros(n)
    myy = np.zeros(n)
    wxx = np.empty(n)
    wxy = np.empty(n)
    wyy = np.empty(n)
    yx = np.empty(n)
    yy = np.empty(n)
    dg = np.empty(n)
    of = np.empty(n)
    lam = np.empty(n)
    lamq = np.zeros((3, n))
    dd = np.empty(n)
    ff = np.empty(n)
    dvx = np.empty(n)
    dvy = np.empty(n)
    qrot = np.empty(nw, np.int64)
    qsl = np.empty(nw, np.int64)
    bx = np.zeros((2 * nw, n))
    by = np.zeros((2 * nw, n))
    zx = np.zeros((2 * nw, n))
    zy = np.zeros((2 * nw, n))
    sq = np.zeros((2 * nw, 2 * nw))
    fq = np.zeros(2 * nw)
    cand, gcache, ncand, gcand, ngcand = K.candidate_arrays(nw, ng, n)
    cinfo = np.zeros((nw, n, 11))
    wtq = np.zeros(nw)
    wsf = np.zeros(nw)
    omu = np.zeros(nw)
    countdown = 0
    vmax_s = 0.0
    fgx = m * gx
    fgy = m * gy
    cm = cglob * m
    nrec = rec_start
    for step in range(nsteps):
        t = t0 + step * h
        tn = t + h
        epot = 0.0
        # links: tension at the start of the step, and its linearised value at the end
        # without the implicit increment, T* = T + h k l̇
        for i in range(n - 1):
            tt, ex, ey, ldot = C.link_force(x[i + 1] - x[i], y[i + 1] - y[i], vx[i + 1] - vx[i],
                                            vy[i + 1] - vy[i], k, c, rest[i])
            tension[i] = tt
            tstar[i] = tt + thh * k * ldot
            ux[i] = ex
            uy[i] = ey
        dx = x[0] - x[n - 1]
        dy = y[0] - y[n - 1]
        ll = math.sqrt(dx * dx + dy * dy)
        ex = dx / ll
        ey = dy / ll
        ldot = (vx[0] - vx[n - 1]) * ex + (vy[0] - vy[n - 1]) * ey
        tt = k * (ll - rest[n - 1]) + c * ldot
        tension[n - 1] = tt
        tstar[n - 1] = tt + thh * k * ldot
        ux[n - 1] = ex
        uy[n - 1] = ey
        if cspan > 0.0:
            # span damping: its force at the start of the step, its slope implicit
            K.span_damping_forces(x, y, vx, vy, fx, fy, cspan)
            _span_damping_matrix(x, y, mxx, mxy, myy, th * cspan)
        # wheel speeds used in the contacts: the prescribed ones at the end of the step
        # (known), the free ones at its start (updated after the pins)
        for w in range(nw):
            mode = wp[w, K.W_MODE]
            if mode == K.MODE_SPEED:
                omu[w] = wp[w, K.W_OMEGA0] * speed_factor(wp, w, tn)
            elif mode == K.MODE_LOCKED:
                omu[w] = 0.0
            else:
                omu[w] = ws[w, K.S_OMEGA]
        rebuild = countdown <= 0
        if rebuild:
            countdown, vmax_s = C.rebuild_every(vx, vy, ws, margin, h, vmax_s)
        countdown -= 1
        for w in range(nw):
            geo = C.wheel_geometry(wp, ws, w, rr)
            cx = geo[0]
            cy = geo[1]
            om = omu[w]
            sd = ws[w, K.S_SDOT]
            ddx = wp[w, K.W_DX]
            ddy = wp[w, K.W_DY]
            tq = 0.0
            fsl = 0.0
            if rebuild:
                rc = geo[10] + margin
                C.wheel_candidates(x, y, cx, cy, rc * rc, cand, gcache, ncand, w)
            for ic in range(ncand[w]):
                cinfo[w, ic, C_BETA] = 0.0
                cinfo[w, ic, C_S] = 0.0
                i = cand[w, ic]
                pen, nx, ny, curv, qx, qy, g = C.pin_contact(x[i], y[i], cx, cy, geo, tab, w, gcache[w, i],
                                                             rr, margin)
                gcache[w, i] = g
                if pen <= -margin:
                    continue
                rvx = vx[i] - (-om * qy + sd * ddx)
                rvy = vy[i] - (om * qx + sd * ddy)
                vn = rvx * nx + rvy * ny
                # linearised normal force at the end of the step without the implicit
                # increment: a contact that opens within the step carries no force, a
                # gap that closes within it (pen < 0) is a contact of this step
                fn0 = kc * (pen + thh * vn) + cc * vn
                if fn0 <= 0.0 and pen <= 0.0:
                    continue
                fn = kc * pen + cc * vn if pen > 0.0 else 0.0
                if fn < 0.0:
                    fn = 0.0
                if pen > 0.0:
                    epot += 0.5 * kc * pen * pen
                vt = -rvx * ny + rvy * nx
                ft0, ve = C.friction(mu, fn, vt, dtref, inv_m, veps)
                s = mu * fn / ve if abs(vt) < ve else 0.0
                if curv > 0.0:
                    # concave seat: the normal turns with the roller, a tangential
                    # stiffness fn/d (d = distance from the seat's centre, ~r_s - r):
                    # implicit like the sticking friction (Δx_t = h Δv_t)
                    kt = fn * curv
                    ft0 -= thh * kt * vt
                    s += h * kt
                s *= th
                # force on the pin: -(fn0 + β Δvn) n + (ft0 - s Δvt) t, t = (-ny, nx)
                fx[i] += -fn0 * nx - ft0 * ny
                fy[i] += -fn0 * ny + ft0 * nx
                _add_pin_matrix(mxx, mxy, myy, i, betac, nx, ny)
                _add_pin_matrix(mxx, mxy, myy, i, s, -ny, nx)
                contact[i] += fn
                lev = qx * ny - qy * nx
                levt = qx * nx + qy * ny
                tq += fn0 * lev - ft0 * levt
                dn = nx * ddx + ny * ddy
                dtt = -ny * ddx + nx * ddy
                fsl += fn0 * dn - ft0 * dtt
                cinfo[w, ic, C_BETA] = betac
                cinfo[w, ic, C_S] = s
                cinfo[w, ic, C_NX] = nx
                cinfo[w, ic, C_NY] = ny
                cinfo[w, ic, C_L] = lev
                cinfo[w, ic, C_LT] = levt
                cinfo[w, ic, C_DN] = dn
                cinfo[w, ic, C_DT] = dtt
                cinfo[w, ic, C_FN0] = fn0
                cinfo[w, ic, C_FT0] = ft0
                cinfo[w, ic, C_FN] = fn
            wtq[w] = tq
            wsf[w] = fsl
            ws[w, K.S_TORQUE] = tq
            ws[w, K.S_SFORCE] = fsl
        # guides (fixed): the same linearisation
        for g in range(ng):
            if rebuild:
                C.guide_candidates(x, y, gd, g, rr + margin, gcand, ngcand)
            for ic in range(ngcand[g]):
                i = gcand[g, ic]
                pen, mx, my = C.guide_penetration(x[i], y[i], gd, g, rr, margin)
                if pen <= -margin:
                    continue
                vn = vx[i] * mx + vy[i] * my
                fn0 = kg * (pen - thh * vn) - cg * vn
                if fn0 <= 0.0:
                    continue
                fn = kg * pen - cg * vn if pen > 0.0 else 0.0
                if fn < 0.0:
                    fn = 0.0
                if pen > 0.0:
                    epot += 0.5 * kg * pen * pen
                vt = vx[i] * my - vy[i] * mx
                mug = C.guide_mu(gd, g, mu)
                ft0, ve = C.friction(mug, fn, vt, dtref, inv_m, veps)
                s = mug * fn / ve if abs(vt) < ve else 0.0
                mmat = gd[g, K.G_MM]
                if mmat > 0.0:
                    # material scraped along the pan (material_drag), its mass in the
                    # pin's matrix
                    fdrag, fm, vem = C.material_drag(gd, g, gx, gy, mx, my, vt, dtref, inv_m, veps)
                    ft0 += fdrag
                    if abs(vt) < vem:
                        s += fm / vem
                    _add_pin_matrix(mxx, mxy, myy, i, mmat / h, my, -mx)
                s *= th
                fx[i] += fn0 * mx + ft0 * my
                fy[i] += fn0 * my - ft0 * mx
                _add_pin_matrix(mxx, mxy, myy, i, betag, mx, my)
                _add_pin_matrix(mxx, mxy, myy, i, s, my, -mx)
                contact[i] += fn
        # record (state at time t)
        if step % record_every == 0 and nrec < rec_t.shape[0]:
            epot, ekin, egrav = K.record_pins(x, y, vx, vy, fx, fy, 0.0, rest, k, m, gx, gy, epot,
                                              tension, contact, rec_tension, rec_contact,
                                              rec_pos, nrec)
            for w in range(nw):
                om = ws[w, K.S_OMEGA]
                ekin += 0.5 * wp[w, K.W_INERTIA] * om * om
                if wp[w, K.W_SLIDE] > 0.0:
                    sv = ws[w, K.S_SDOT]
                    ekin += 0.5 * wp[w, K.W_SMASS] * sv * sv
                    epot += 0.5 * wp[w, K.W_SK] * ws[w, K.S_S] ** 2 - wp[w, K.W_SF] * ws[w, K.S_S]
                    egrav -= wp[w, K.W_SMASS] * (gx * wp[w, K.W_DX] + gy * wp[w, K.W_DY]) \
                        * ws[w, K.S_S]
                for col in range(ws.shape[1]):
                    rec_ws[nrec, w, col] = ws[w, col]
            rec_energy[nrec] = ekin + epot + egrav
            rec_t[nrec] = t
            for q in range(npr):
                ib = C.nearest_pin(x, y, probes[q, 0], probes[q, 1])
                rec_probe[nrec, q] = vx[ib] * probes[q, 2] + vy[ib] * probes[q, 3]
            nrec += 1
        # pins: forces F_i (explicit forces, gravity and the links' T*) and the
        # inverse W_i of the 2 x 2 matrix M_i/h + contact terms
        yx[0] = fx[0] + fgx - cm * vx[0] + tstar[0] * ux[0] - tstar[n - 1] * ux[n - 1]
        yy[0] = fy[0] + fgy - cm * vy[0] + tstar[0] * uy[0] - tstar[n - 1] * uy[n - 1]
        for i in range(1, n):
            yx[i] = fx[i] + fgx - cm * vx[i] + tstar[i] * ux[i] - tstar[i - 1] * ux[i - 1]
            yy[i] = fy[i] + fgy - cm * vy[i] + tstar[i] * uy[i] - tstar[i - 1] * uy[i - 1]
        for i in range(n):
            _pin_inverse(i, mh, mxx, mxy, myy, wxx, wxy, wyy)
        # active set of the wheel contacts: a contact whose normal force at the end of
        # the step comes out tensile is dropped and the step solved again
        for it in range(4):
            _solve(n, nw, yx, yy, wxx, wxy, wyy, ux, uy, dg, of, dd, ff, lam, lamq, inv_ak, dvx,
                   dvy, ws, wp, ncand, cand, cinfo, qrot, qsl, bx, by, zx, zy, sq, fq, wtq, wsf, h,
                   t, gx, gy)
            if it == 3 or not _drop_tensile(cinfo, ncand, cand, qrot, qsl, fq, dvx, dvy, yx, yy,
                                            mxx, mxy, myy, wtq, wsf, contact):
                break
            for i in range(n):
                _pin_inverse(i, mh, mxx, mxy, myy, wxx, wxy, wyy)
        for i in range(n):
            fx[i] = 0.0
            fy[i] = 0.0
            mxx[i] = 0.0
            mxy[i] = 0.0
            myy[i] = 0.0
            contact[i] = 0.0
        for i in range(n):
            vx[i] += dvx[i]
            vy[i] += dvy[i]
            x[i] += h * vx[i]
            y[i] += h * vy[i]
        for w in range(nw):
            if wp[w, K.W_MODE] == K.MODE_MOTOR and qrot[w] >= 0:
                advance_motor(wp, ws, w, t, h)   # the motor behind a fluid coupling
            if qrot[w] >= 0:
                ws[w, K.S_OMEGA] += fq[qrot[w]]
            elif wp[w, K.W_MODE] == K.MODE_FREE or wp[w, K.W_MODE] == K.MODE_MOTOR:
                # no pin within reach: the wheel on its own
                om = ws[w, K.S_OMEGA]
                tq = wp[w, K.W_TORQUE] - wp[w, K.W_DAMP] * om
                if wp[w, K.W_MODE] == K.MODE_MOTOR:
                    tq += wheel_drive_torque(wp, ws, w, om, t, tq, h)
                    advance_motor(wp, ws, w, t, h)
                ws[w, K.S_OMEGA] = om + h * tq / wp[w, K.W_INERTIA]
            else:
                ws[w, K.S_OMEGA] = omu[w]
            ws[w, K.S_THETA] += ws[w, K.S_OMEGA] * h
            if wp[w, K.W_SLIDE] > 0.0:
                if qsl[w] >= 0:
                    ws[w, K.S_SDOT] += fq[qsl[w]]
                else:
                    dxw = wp[w, K.W_DX]
                    dyw = wp[w, K.W_DY]
                    fs = wp[w, K.W_SF] - wp[w, K.W_SK] * ws[w, K.S_S] \
                        - wp[w, K.W_SC] * ws[w, K.S_SDOT] + wp[w, K.W_SMASS] * (gx * dxw + gy * dyw)
                    ws[w, K.S_SDOT] += h * fs / wp[w, K.W_SMASS]
                ws[w, K.S_S] += ws[w, K.S_SDOT] * h
    K.store_pins(pos, vel, x, y, vx, vy)
    return nrec
