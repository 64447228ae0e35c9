"""Compiled hot loop stepping many variants of a drive together (internal).

:func:`integrate_batch` advances ``V`` variants of one drive layout (the same number of
pins, wheels and guides; any masses, stiffnesses, profiles, speeds, loads and time
steps) by the same number of symplectic Euler steps, each variant exactly as
:func:`._kernel.integrate` advances it alone: the same operations in the same order,
so the results are equal to the last bit (``tests/test_simulation_batched.py``).

Layout: the pins' coordinates, velocities, forces and link tensions as ``(N, V)``
arrays, the variants the inner, contiguous dimension, so that the link forces and the
pins' update (the bulk of a step; one pass outside the record steps) run as vector
instructions across the variants. The roller-seat contacts (about a dozen candidate pins
per wheel) one candidate slot at a time across the variants: gathered per variant (the
pin, its offset, its seat: the last one kept when the pin is still within it, else the
walk of :func:`._contact.nearest_seat`), the forces of all lanes in one branch-free loop
(:func:`_seat_lane`, :func:`_slot_forces`: every case of the seat profile evaluated, the
one that applies selected, so the loop compiles to vector instructions), scattered back
per variant. Guides per variant. The span damping (``P_CSPAN``, each variant its own)
across the variants before the contacts (:mod:`._lane_span`). Divisions by zero give inf
instead of raising (``error_model="numpy"``, so that the loops vectorise; the values are
the same). Wheels,
guides and seat tables: ``(V, W, ...)``, ``(V, G, NGD)``, ``(V, W, smax, 6)`` (a table
padded to the largest seat count). Records, per variant contiguous: time ``(V, R)``,
link tensions ``(V, R, N)``, wheel states ``(V, R, W, NWS)``, pin positions
``(V, R, N, 2)``.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from . import _contact as C
from . import _layout as L
from ._kernel import _carry, advance_wheels
from ._lane_span import span_damping_forces

__all__ = ["empty_batch_records", "integrate_batch", "stack_tables"]


@njit(cache=True, fastmath=False, inline="always", error_model="numpy")
def _seat_lane(qx, qy, ex, ey, cth, sth, rad, rr, delta, cps, sps, re, arcflank, cea, ceb, dta,
               dtb, tca, tcb, stip):
    """:func:`._contact.seat_normal` (``reach`` 0) without branches: every case of
    :func:`._contact.seat_penetration` evaluated with the same operations, the one that
    applies selected (one square root, two divisions), so that the variants' loop runs
    as vector instructions and each lane's result equals the scalar one to the last bit.
    Returns ``(pen, nx, ny, ds)``; the normal is meaningless where ``pen <= 0``; ``ds`` the
    distance from the seating arc's centre where the roller is in the seat (−1 elsewhere:
    the seat's curvature is ``1/ds``)."""
    erx = ex * cth - ey * sth
    ery = ex * sth + ey * cth
    a = qx * erx + qy * ery - rad
    b = -qx * ery + qy * erx
    ab = abs(b)
    sb = 1.0 if b >= 0.0 else -1.0
    va = a - cea
    vb = ab - ceb
    onarc = ab * cps + a * sps > 0.0
    pa = onarc and va * dtb - vb * dta < 0.0
    ps = (a + delta * cps) * sps + (ab - delta * sps) * cps > stip
    past = pa if arcflank else ps
    seat = not past and not onarc
    flank = not past and onarc
    ta = a - tca
    tb = ab - tcb
    # the distance of the applicable case: tooth corner, seating arc, flank arc
    d2 = ta * ta + tb * tb if past else (a * a + b * b if seat else va * va + vb * vb)
    d = math.sqrt(d2)
    straight = flank and not arcflank
    pen = rr - d if past else (d - delta if seat else (re + rr - d if not straight
                                                      else -a * cps + ab * sps - delta))
    # normal (numerator over d; the straight flank's over 1)
    nan_ = -ta if past else (a if seat else (-va if not straight else -cps))
    nbn = -sb * tb if past else (b if seat else (-sb * vb if not straight else sb * sps))
    den = 1.0 if straight else d
    na = nan_ / den
    nb = nbn / den
    return pen, na * erx - nb * ery, na * ery + nb * erx, d if seat else -1.0


#: lanes of a block: the branch-free contact loop runs over the variants of one block, its
#: work arrays 1-D with rows ``LANES`` apart (a constant stride, so that the compiler
#: proves the rows apart and vectorises without a run-time check per row)
LANES = 64

#: per-wheel constants of a variant (rows of ``gc``, :func:`_wheel_constants`): radius,
#: seats per turn, pitch angle, the contact annulus' outer and inner radii squared, the
#: candidates' reach squared, the slide direction, toothless or not, then the profile of
#: :func:`._contact.wheel_profile` (``arcflank`` as 0/1)
G_RAD, G_IZ, G_PA, G_ROUT2, G_RIN2, G_RC2, G_DX, G_DY, G_PLAIN, G_DELTA, G_CPS, G_SPS, G_RE, \
    G_ARC, G_CEA, G_CEB, G_DTA, G_DTB, G_TCA, G_TCB, G_STIP = range(21)
NGC = 21
#: rows of the gathered slot ``sq``: offset from the wheel centre, seat direction (or a
#: toothless idler's normal), pin velocity, state (0 none, 1 seat, 2 rim), rim
#: penetration, cos/sin of the wheel angle, wheel centre, wheel speed and slide speed
Q_QX, Q_QY, Q_EX, Q_EY, Q_VX, Q_VY, Q_ON, Q_PEN, Q_CTH, Q_STH, Q_CX, Q_CY, Q_OM, Q_SD = range(14)
NQ = 14
#: rows of the slot's results ``so``: contact force, in contact or not, the wheel's
#: torque and force sums
O_FX, O_FY, O_ON, O_TQ, O_WX, O_WY = range(6)
NO = 6


@njit(cache=True, fastmath=False)
def _wheel_constants(wp, par):
    """``(gc, pt)``: the per-wheel constants of every variant (``G_*``) at
    ``((block W + w) NGC + row) LANES + lane`` and the parameters (``P_*``) at
    ``(block NPAR + row) LANES + lane``."""
    nv = wp.shape[0]
    nw = wp.shape[1]
    nblk = (nv + LANES - 1) // LANES
    gc = np.zeros(nblk * nw * NGC * LANES)
    pt = np.ones(nblk * L.NPAR * LANES)
    ws0 = np.zeros((nw, L.NWS))
    for v in range(nv):
        blk = v // LANES
        lane = v - blk * LANES
        rr = par[v, L.P_RROLLER]
        for p in range(L.NPAR):
            pt[(blk * L.NPAR + p) * LANES + lane] = par[v, p]
        for w in range(nw):
            geo = C.wheel_geometry(wp[v], ws0, w, rr)
            rc = geo[10] + 0.25 * rr
            prof = geo[11]
            row = (blk * nw + w) * NGC
            vals = (geo[4], float(geo[6]), geo[7], geo[8], geo[9], rc * rc, wp[v, w, L.W_DX],
                    wp[v, w, L.W_DY], 1.0 if geo[5] else 0.0, prof[0], prof[1], prof[2],
                    prof[3], 1.0 if prof[4] else 0.0, prof[5], prof[6], prof[7], prof[8],
                    prof[9], prof[10], prof[11])
            for r in range(NGC):
                gc[(row + r) * LANES + lane] = vals[r]
    return gc, pt


@njit(cache=True, fastmath=False, inline="always")
def _guides(v, x, y, vx, vy, fx, fy, gdv, gcand, ngcand, extra, par):
    """Guide contact forces of variant ``v`` (columns ``v`` of the pin arrays) as
    :func:`._kernel.integrate` computes them; True if a pin carries material. (Indexed
    rather than sliced: a view per variant and step would cost more than its contacts.)"""
    rr = par[v, L.P_RROLLER]
    mu = par[v, L.P_MU]
    veps = par[v, L.P_VEPS]
    gx = par[v, L.P_GX]
    gy = par[v, L.P_GY]
    kg = par[v, L.P_KG]
    cg = par[v, L.P_CG]
    dtref = par[v, L.P_DTREF]
    inv_m = 1.0 / par[v, L.P_MASS]
    carrying = False
    for g in range(gdv.shape[0]):
        for ic in range(ngcand[v, g]):
            i = gcand[v, g, ic]
            pen, mx, my = C.guide_penetration(x[i, v], y[i, v], gdv, g, rr)
            if pen <= 0.0:
                continue
            pvx = vx[i, v]
            pvy = vy[i, v]
            fn = kg * pen - cg * (pvx * mx + pvy * my)
            if fn < 0.0:
                fn = 0.0
            vt = pvx * my - pvy * mx
            ft, _ = C.friction(C.guide_mu(gdv, g, mu), fn, vt, dtref, inv_m, veps)
            if gdv[g, L.G_MM] > 0.0:
                ft += C.material_drag(gdv, g, gx, gy, mx, my, vt, dtref, inv_m, veps)[0]
                extra[v, i, 0] = gdv[g, L.G_MM]
                extra[v, i, 1] = my
                extra[v, i, 2] = -mx
                extra[v, i, 3] = pvx
                extra[v, i, 4] = pvy
                carrying = True
            fx[i, v] += fn * mx + ft * my
            fy[i, v] += fn * my - ft * mx
    return carrying


@njit(cache=True, fastmath=False, error_model="numpy")
def _slot_forces(sq, so, gc, g0, pt, p0, nb):
    """The contact forces of one candidate slot of a wheel in the ``nb`` lanes of a block
    (``sq`` gathered by :func:`_wheel_contacts`; the block's wheel constants from ``gc[g0]``,
    its parameters from ``pt[p0]``), branch-free: :func:`_seat_lane` and the penalty law of
    :func:`._contact.penalty_contact` with selects. The forces in ``so`` (``O_FX``,
    ``O_FY``, ``O_ON``), the wheel's torque and force sums added to ``O_TQ``, ``O_WX``,
    ``O_WY``; each lane's operations those of the single kernel."""
    gb = gc[g0:]
    pb = pt[p0:]
    for v in range(nb):
        qx = sq[Q_QX * LANES + v]
        qy = sq[Q_QY * LANES + v]
        pen, nx, ny, _ = _seat_lane(qx, qy, sq[Q_EX * LANES + v], sq[Q_EY * LANES + v],
                                 sq[Q_CTH * LANES + v], sq[Q_STH * LANES + v],
                                 gb[G_RAD * LANES + v], pb[L.P_RROLLER * LANES + v],
                                 gb[G_DELTA * LANES + v], gb[G_CPS * LANES + v],
                                 gb[G_SPS * LANES + v], gb[G_RE * LANES + v],
                                 gb[G_ARC * LANES + v] > 0.5, gb[G_CEA * LANES + v],
                                 gb[G_CEB * LANES + v], gb[G_DTA * LANES + v],
                                 gb[G_DTB * LANES + v], gb[G_TCA * LANES + v],
                                 gb[G_TCB * LANES + v], gb[G_STIP * LANES + v])
        on = sq[Q_ON * LANES + v]
        rim = on == 2.0
        pen = sq[Q_PEN * LANES + v] if rim else pen
        nx = sq[Q_EX * LANES + v] if rim else nx
        ny = sq[Q_EY * LANES + v] if rim else ny
        om = sq[Q_OM * LANES + v]
        sd = sq[Q_SD * LANES + v]
        rvx = sq[Q_VX * LANES + v] - (-om * qy + sd * gb[G_DX * LANES + v])
        rvy = sq[Q_VY * LANES + v] - (om * qx + sd * gb[G_DY * LANES + v])
        mu = pb[L.P_MU * LANES + v]
        fn = pb[L.P_KC * LANES + v] * pen + pb[L.P_CC * LANES + v] * (rvx * nx + rvy * ny)
        fn = 0.0 if fn < 0.0 else fn
        vt = -rvx * ny + rvy * nx
        ve = mu * fn * pb[L.P_DTREF * LANES + v] * (1.0 / pb[L.P_MASS * LANES + v])
        veps = pb[L.P_VEPS * LANES + v]
        ve = veps if ve < veps else ve
        s = vt / ve
        s = 1.0 if s > 1.0 else (-1.0 if s < -1.0 else s)
        ft = -mu * fn * s
        cfx = -fn * nx - ft * ny
        cfy = -fn * ny + ft * nx
        act = on > 0.0 and pen > 0.0
        tq = so[O_TQ * LANES + v]
        wx = so[O_WX * LANES + v]
        wy = so[O_WY * LANES + v]
        so[O_TQ * LANES + v] = tq - (qx * cfy - qy * cfx) if act else tq
        so[O_WX * LANES + v] = wx - cfx if act else wx
        so[O_WY * LANES + v] = wy - cfy if act else wy
        so[O_FX * LANES + v] = cfx
        so[O_FY * LANES + v] = cfy
        so[O_ON * LANES + v] = 1.0 if act else 0.0


@njit(cache=True, fastmath=False, error_model="numpy")
def _wheel_contacts(w, x, y, vx, vy, fx, fy, ws, wp, tab2, gc, pt, cand, gcache, ncand, sq, so,
                    si):
    """The roller-seat contacts of wheel ``w`` in every variant, a block of ``LANES``
    variants and one candidate slot at a time: gathered per variant (the pin, its offset
    from the centre, the nearest seat by :func:`._contact.nearest_seat`), the forces of
    the block's lanes by :func:`_slot_forces` (vector instructions), scattered back per
    variant; then the wheel's contact torque and slide force. The same operations in the
    same order as the single kernel's, so its results to the last bit. ``tab2`` the seat
    tables ``(V W, smax, 6)``; ``sq`` ``(NQ LANES,)``, ``so`` ``(NO LANES,)``, ``si``
    ``(LANES,)`` work arrays."""
    nv = x.shape[1]
    nw = ws.shape[1]
    for blk in range((nv + LANES - 1) // LANES):
        v0 = blk * LANES
        nb = min(LANES, nv - v0)
        g0 = (blk * nw + w) * NGC * LANES
        p0 = blk * L.NPAR * LANES
        maxc = 0
        for b in range(nb):
            v = v0 + b
            if ncand[v, w] > maxc:
                maxc = ncand[v, w]
            th = ws[v, w, L.S_THETA]
            sq[Q_CTH * LANES + b] = math.cos(th)
            sq[Q_STH * LANES + b] = math.sin(th)
            sq[Q_CX * LANES + b] = wp[v, w, L.W_CX] + ws[v, w, L.S_S] * wp[v, w, L.W_DX]
            sq[Q_CY * LANES + b] = wp[v, w, L.W_CY] + ws[v, w, L.S_S] * wp[v, w, L.W_DY]
            sq[Q_OM * LANES + b] = ws[v, w, L.S_OMEGA]
            sq[Q_SD * LANES + b] = ws[v, w, L.S_SDOT]
            so[O_TQ * LANES + b] = 0.0
            so[O_WX * LANES + b] = 0.0
            so[O_WY * LANES + b] = 0.0
        for ic in range(maxc):
            # gather: the pins of this slot, their offsets, velocities and seats
            for b in range(nb):
                v = v0 + b
                sq[Q_ON * LANES + b] = 0.0
                sq[Q_EX * LANES + b] = 1.0
                sq[Q_EY * LANES + b] = 0.0
                if ic >= ncand[v, w]:
                    sq[Q_QX * LANES + b] = 0.0
                    sq[Q_QY * LANES + b] = 0.0
                    sq[Q_VX * LANES + b] = 0.0
                    sq[Q_VY * LANES + b] = 0.0
                    continue
                i = cand[v, w, ic]
                si[b] = i
                qx = x[i, v] - sq[Q_CX * LANES + b]
                qy = y[i, v] - sq[Q_CY * LANES + b]
                sq[Q_QX * LANES + b] = qx
                sq[Q_QY * LANES + b] = qy
                sq[Q_VX * LANES + b] = vx[i, v]
                sq[Q_VY * LANES + b] = vy[i, v]
                r2 = qx * qx + qy * qy
                if r2 > gc[g0 + G_ROUT2 * LANES + b] or r2 < gc[g0 + G_RIN2 * LANES + b]:
                    continue
                if gc[g0 + G_PLAIN * LANES + b] > 0.5:
                    pen, nx, ny, _ = C.rim_gap(qx, qy, r2, gc[g0 + G_RAD * LANES + b], 0.0)
                    sq[Q_ON * LANES + b] = 2.0
                    sq[Q_PEN * LANES + b] = pen
                    sq[Q_EX * LANES + b] = nx
                    sq[Q_EY * LANES + b] = ny
                    continue
                cth = sq[Q_CTH * LANES + b]
                sth = sq[Q_STH * LANES + b]
                qxw = qx * cth + qy * sth
                qyw = -qx * sth + qy * cth
                # the pin's last seat first (within both half-way boundaries: kept), as
                # the first pass of the walk of nearest_seat; else the walk
                g = gcache[v, w, i]
                wv = v * nw + w
                kept = False
                if g >= 0:
                    ex = tab2[wv, g, 0]
                    ey = tab2[wv, g, 1]
                    ar = qxw * ex + qyw * ey
                    bt = -qxw * ey + qyw * ex
                    kept = not bt * tab2[wv, g, 2] > ar * tab2[wv, g, 3] \
                        and not -bt * tab2[wv, g, 4] > ar * tab2[wv, g, 5]
                if not kept:
                    g, ex, ey = C.nearest_seat(tab2, wv, g, int(gc[g0 + G_IZ * LANES + b]), qxw, qyw,
                                               gc[g0 + G_PA * LANES + b])
                gcache[v, w, i] = g
                sq[Q_ON * LANES + b] = 1.0
                sq[Q_EX * LANES + b] = ex
                sq[Q_EY * LANES + b] = ey
            _slot_forces(sq, so, gc, g0, pt, p0, nb)
            # scatter
            for b in range(nb):
                if so[O_ON * LANES + b] > 0.0:
                    i = si[b]
                    v = v0 + b
                    fx[i, v] += so[O_FX * LANES + b]
                    fy[i, v] += so[O_FY * LANES + b]
        for b in range(nb):
            v = v0 + b
            ws[v, w, L.S_TORQUE] = so[O_TQ * LANES + b]
            ws[v, w, L.S_SFORCE] = so[O_WX * LANES + b] * gc[g0 + G_DX * LANES + b] \
                + so[O_WY * LANES + b] * gc[g0 + G_DY * LANES + b]


@njit(cache=True, fastmath=False, error_model="numpy")
def integrate_batch(pos, vel, ws, wp, gd, tab, par, t0, nsteps, record_every, rec_t,
                    rec_tension, rec_ws, rec_pos):
    """Advance every variant ``nsteps`` steps of its own ``par[v, L.P_DT]`` from its time
    ``t0[v]``; ``pos``, ``vel`` ``(V, N, 2)``, ``ws`` updated in place. Returns the number
    of records written (every ``record_every`` steps, from step 0)."""
    nv = pos.shape[0]
    n = pos.shape[1]
    x = np.empty((n, nv))
    y = np.empty((n, nv))
    vx = np.empty((n, nv))
    vy = np.empty((n, nv))
    rest = np.empty((n, nv))
    for i in range(n):
        for v in range(nv):
            x[i, v] = pos[v, i, 0]
            y[i, v] = pos[v, i, 1]
            vx[i, v] = vel[v, i, 0]
            vy[i, v] = vel[v, i, 1]
            rest[i, v] = par[v, L.P_PITCH] if i % 2 == 0 else par[v, L.P_PITCH2]
    k = par[:, L.P_K].copy()
    c = par[:, L.P_C].copy()
    dt = par[:, L.P_DT].copy()
    fgx = par[:, L.P_MASS] * par[:, L.P_GX]
    fgy = par[:, L.P_MASS] * par[:, L.P_GY]
    cm = par[:, L.P_CGLOB] * par[:, L.P_MASS]
    cspan = par[:, L.P_CSPAN] * par[:, L.P_MASS]
    anyspan = False
    for v in range(nv):
        anyspan = anyspan or cspan[v] > 0.0
    hdt = np.empty(nv)
    for v in range(nv):
        hdt[v] = 1.0 / par[v, L.P_MASS] * dt[v]
    fx = np.zeros((n, nv))
    fy = np.zeros((n, nv))
    wkx = np.zeros((n + 1, nv))
    wky = np.zeros((n + 1, nv))
    tension = np.zeros((n, nv))
    nw = ws.shape[1]
    ng = gd.shape[1]
    gc, pt = _wheel_constants(wp, par)
    tab2 = tab.reshape((nv * nw, tab.shape[2], tab.shape[3]))
    sq = np.zeros(NQ * LANES)
    so = np.zeros(NO * LANES)
    si = np.zeros(LANES, np.int64)
    cand = np.empty((nv, nw, n), np.int64)
    gcache = np.full((nv, nw, n), -1, np.int64)
    ncand = np.zeros((nv, nw), np.int64)
    gcand = np.empty((nv, ng, n), np.int64)
    ngcand = np.zeros((nv, ng), np.int64)
    extra = np.zeros((nv, n, 5))
    carrying = np.zeros(nv, np.bool_)
    countdown = np.zeros(nv, np.int64)
    vmax_s = np.zeros(nv)
    nrec = 0
    for step in range(nsteps):
        # the contact candidates, listed again per variant when it is due
        for v in range(nv):
            if countdown[v] <= 0:
                rr = par[v, L.P_RROLLER]
                rc2 = ((v // LANES) * nw * NGC + G_RC2) * LANES + v % LANES
                countdown[v], vmax_s[v] = C.rebuild_every(vx[:, v], vy[:, v], ws[v], 0.25 * rr,
                                                        dt[v], vmax_s[v])
                for w in range(nw):
                    cx = wp[v, w, L.W_CX] + ws[v, w, L.S_S] * wp[v, w, L.W_DX]
                    cy = wp[v, w, L.W_CY] + ws[v, w, L.S_S] * wp[v, w, L.W_DY]
                    C.wheel_candidates(x[:, v], y[:, v], cx, cy, gc[rc2 + w * NGC * LANES], cand[v],
                                       gcache[v], ncand[v], w)
                for g in range(ng):
                    C.guide_candidates(x[:, v], y[:, v], gd[v], g, rr + 0.25 * rr, gcand[v],
                                       ngcand[v])
            countdown[v] -= 1
        if anyspan:
            # the span damping first, as the single kernel adds it (lanes with α = 0 untouched)
            span_damping_forces(x, y, vx, vy, fx, fy, cspan)
        # contacts: wheels across the variants, guides per variant
        for w in range(nw):
            _wheel_contacts(w, x, y, vx, vy, fx, fy, ws, wp, tab2, gc, pt, cand, gcache, ncand, sq,
                            so, si)
        anycarry = False
        for v in range(nv):
            if ng > 0 and _guides(v, x, y, vx, vy, fx, fy, gd[v], gcand, ngcand, extra, par):
                carrying[v] = True
                anycarry = True
        if step % record_every == 0 and nrec < rec_t.shape[1] or anycarry:
            # links, then records (state at time t) and the pins' update, as the single
            # kernel does them
            for i in range(n):
                j = i + 1 if i + 1 < n else 0
                for v in range(nv):
                    tt, ux, uy, _ = C.link_force(x[j, v] - x[i, v], y[j, v] - y[i, v],
                                                 vx[j, v] - vx[i, v], vy[j, v] - vy[i, v], k[v],
                                                 c[v], rest[i, v])
                    tension[i, v] = tt
                    wkx[i + 1, v] = tt * ux
                    wky[i + 1, v] = tt * uy
            for v in range(nv):
                wkx[0, v] = wkx[n, v]
                wky[0, v] = wky[n, v]
            if step % record_every == 0 and nrec < rec_t.shape[1]:
                for i in range(n):
                    for v in range(nv):
                        fx[i, v] += fgx[v] - cm[v] * vx[i, v] + wkx[i + 1, v] - wkx[i, v]
                        fy[i, v] += fgy[v] - cm[v] * vy[i, v] + wky[i + 1, v] - wky[i, v]
                for v in range(nv):
                    rec_t[v, nrec] = t0[v] + step * dt[v]
                    for i in range(n):
                        rec_tension[v, nrec, i] = tension[i, v]
                        rec_pos[v, nrec, i, 0] = x[i, v]
                        rec_pos[v, nrec, i, 1] = y[i, v]
                    for w in range(nw):
                        for col in range(L.NWS):
                            rec_ws[v, nrec, w, col] = ws[v, w, col]
                nrec += 1
                for i in range(n):
                    for v in range(nv):
                        vx[i, v] += fx[i, v] * hdt[v]
                        vy[i, v] += fy[i, v] * hdt[v]
            else:
                for i in range(n):
                    for v in range(nv):
                        vx[i, v] += (fx[i, v] + fgx[v] - cm[v] * vx[i, v] + wkx[i + 1, v]
                                     - wkx[i, v]) * hdt[v]
                        vy[i, v] += (fy[i, v] + fgy[v] - cm[v] * vy[i, v] + wky[i + 1, v]
                                     - wky[i, v]) * hdt[v]
            for v in range(nv):
                if carrying[v]:
                    m = par[v, L.P_MASS]
                    for i in range(n):
                        if extra[v, i, 0] > 0.0:
                            _carry(vx[:, v], vy[:, v], extra[v], i, m)
                    carrying[v] = False
            for i in range(n):
                for v in range(nv):
                    x[i, v] += vx[i, v] * dt[v]
                    y[i, v] += vy[i, v] * dt[v]
                    fx[i, v] = 0.0
                    fy[i, v] = 0.0
        else:
            # links and the pins' update in one pass (the same operations): link i joins
            # pins i and i + 1, neither moved yet when it is computed; the closing link
            # (pins n - 1 and 0) first
            for v in range(nv):
                tt, ux, uy, _ = C.link_force(x[0, v] - x[n - 1, v], y[0, v] - y[n - 1, v],
                                             vx[0, v] - vx[n - 1, v], vy[0, v] - vy[n - 1, v],
                                             k[v], c[v], rest[n - 1, v])
                wkx[0, v] = tt * ux
                wky[0, v] = tt * uy
            for i in range(n):
                if i < n - 1:
                    for v in range(nv):
                        tt, ux, uy, _ = C.link_force(x[i + 1, v] - x[i, v], y[i + 1, v] - y[i, v],
                                                     vx[i + 1, v] - vx[i, v],
                                                     vy[i + 1, v] - vy[i, v], k[v], c[v],
                                                     rest[i, v])
                        wkx[i + 1, v] = tt * ux
                        wky[i + 1, v] = tt * uy
                else:
                    for v in range(nv):
                        wkx[n, v] = wkx[0, v]
                        wky[n, v] = wky[0, v]
                for v in range(nv):
                    ax = vx[i, v] + (fx[i, v] + fgx[v] - cm[v] * vx[i, v] + wkx[i + 1, v]
                                     - wkx[i, v]) * hdt[v]
                    ay = vy[i, v] + (fy[i, v] + fgy[v] - cm[v] * vy[i, v] + wky[i + 1, v]
                                     - wky[i, v]) * hdt[v]
                    vx[i, v] = ax
                    vy[i, v] = ay
                    x[i, v] += ax * dt[v]
                    y[i, v] += ay * dt[v]
                    fx[i, v] = 0.0
                    fy[i, v] = 0.0
        for v in range(nv):
            advance_wheels(wp[v], ws[v], t0[v] + step * dt[v], dt[v], par[v, L.P_GX], par[v, L.P_GY])
    for v in range(nv):
        for i in range(n):
            pos[v, i, 0] = x[i, v]
            pos[v, i, 1] = y[i, v]
            vel[v, i, 0] = vx[i, v]
            vel[v, i, 1] = vy[i, v]
    return nrec


def stack_tables(tables):
    """The seat tables of the variants (each ``(W, smax, 6)``, :func:`._kernel.seat_table`)
    as one ``(V, W, smax, 6)`` array, padded to the largest ``smax`` (the padding is never
    read: a wheel's seats are counted by its ``W_NSEAT``)."""
    smax = max(t.shape[1] for t in tables)
    out = np.zeros((len(tables), tables[0].shape[0], smax, 6))
    for v, t in enumerate(tables):
        out[v, :, :t.shape[1]] = t
    return out


def empty_batch_records(n_variants, n_records, n_pins, n_wheels):
    """Preallocated record arrays for :func:`integrate_batch`."""
    return (np.zeros((n_variants, n_records)), np.zeros((n_variants, n_records, n_pins)),
            np.zeros((n_variants, n_records, n_wheels, L.NWS)),
            np.zeros((n_variants, n_records, n_pins, 2)))
