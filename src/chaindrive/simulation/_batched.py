"""Compiled hot loop stepping many variants of a drive together (internal).

:func:`integrate_batch` advances ``V`` variants of one drive layout (the same number of
pins, wheels and guides; any masses, stiffnesses, profiles, speeds, loads and time
steps) by the same number of symplectic Euler steps, each variant exactly as
:func:`._kernel.integrate` advances it alone: the same operations in the same order,
so the results are equal to the last bit (``tests/test_simulation_batched.py``).

Layout: the pins' coordinates, velocities, forces and link tensions as ``(N, V)``
arrays, the variants the inner, contiguous dimension, so that the link forces and the
pins' update (the bulk of a step) run as vector instructions across the variants, as
they run across the links of one long chain; the contacts (a few dozen pins per
variant near the wheels) per variant, with the contact routines of :mod:`._contact`
shared with the single-drive kernels. Wheels, guides and seat tables: ``(V, W, ...)``,
``(V, G, NGD)``, ``(V, W, smax, 6)`` (a table padded to the largest seat count).
Records, per variant contiguous: time ``(V, R)``, link tensions ``(V, R, N)``, wheel
states ``(V, R, W, NWS)``, pin positions ``(V, R, N, 2)``.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from . import _contact as C
from . import _layout as L
from ._kernel import _carry, advance_wheels

__all__ = ["empty_batch_records", "integrate_batch", "stack_tables"]


@njit(cache=True, fastmath=False, inline="always")
def _contacts(v, x, y, vx, vy, fx, fy, wsv, wpv, gdv, tabv, gcache, cand, ncand, gcand, ngcand,
              extra, rebuild, par):
    """Contact forces of variant ``v`` (columns ``v`` of the pin arrays, rows ``v`` of the
    candidate lists; ``wsv`` ... ``tabv`` its own wheel, guide and seat arrays) as
    :func:`._kernel.integrate` computes them; True if a pin carries material. (Indexed
    rather than sliced: a view per variant and step would cost more than its contacts.)"""
    rr = par[v, L.P_RROLLER]
    kc = par[v, L.P_KC]
    cc = par[v, L.P_CC]
    mu = par[v, L.P_MU]
    veps = par[v, L.P_VEPS]
    gx = par[v, L.P_GX]
    gy = par[v, L.P_GY]
    kg = par[v, L.P_KG]
    cg = par[v, L.P_CG]
    dtref = par[v, L.P_DTREF]
    inv_m = 1.0 / par[v, L.P_MASS]
    margin = 0.25 * rr
    carrying = False
    for w in range(wsv.shape[0]):
        geo = C.wheel_geometry(wpv, wsv, w, rr)
        cx = geo[0]
        cy = geo[1]
        om = wsv[w, L.S_OMEGA]
        sd = wsv[w, L.S_SDOT]
        dxw = wpv[w, L.W_DX]
        dyw = wpv[w, L.W_DY]
        tq = 0.0
        fwx = 0.0
        fwy = 0.0
        if rebuild:
            rc = geo[10] + margin
            C.wheel_candidates(x[:, v], y[:, v], cx, cy, rc * rc, cand[v], gcache[v], ncand[v], w)
        for ic in range(ncand[v, w]):
            i = cand[v, w, ic]
            qx = x[i, v] - cx
            qy = y[i, v] - cy
            r2 = qx * qx + qy * qy
            if r2 > geo[8] or r2 < geo[9]:
                continue
            if geo[5]:
                pen, nx, ny, _curv = C.rim_gap(qx, qy, r2, geo[4], 0.0)
            else:
                g, ex, ey = C.nearest_seat(tabv, w, gcache[v, w, i], geo[6],
                                         qx * geo[2] + qy * geo[3], -qx * geo[3] + qy * geo[2],
                                         geo[7])
                gcache[v, w, i] = g
                pen, nx, ny, _curv = C.seat_normal(qx, qy, ex, ey, geo, rr, 0.0)
            if pen <= 0.0:
                continue
            _fn, cfx, cfy = C.penalty_contact(kc, cc, mu, dtref, inv_m, veps, pen, nx, ny,
                                            vx[i, v] - (-om * qy + sd * dxw),
                                            vy[i, v] - (om * qx + sd * dyw))
            fx[i, v] += cfx
            fy[i, v] += cfy
            tq -= qx * cfy - qy * cfx
            fwx -= cfx
            fwy -= cfy
        wsv[w, L.S_TORQUE] = tq
        wsv[w, L.S_SFORCE] = fwx * dxw + fwy * dyw
    for g in range(gdv.shape[0]):
        if rebuild:
            C.guide_candidates(x[:, v], y[:, v], gdv, g, rr + margin, gcand[v], ngcand[v])
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


@njit(cache=True, fastmath=False)
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
        # links, vectorised across the variants
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
        # contacts, one variant at a time
        for v in range(nv):
            wsv = ws[v]
            rebuild = countdown[v] <= 0
            if rebuild:
                countdown[v], vmax_s[v] = C.rebuild_every(vx[:, v], vy[:, v], wsv,
                                                        0.25 * par[v, L.P_RROLLER], dt[v], vmax_s[v])
            countdown[v] -= 1
            if _contacts(v, x, y, vx, vy, fx, fy, wsv, wp[v], gd[v], tab[v], gcache, cand, ncand,
                         gcand, ngcand, extra, rebuild, par):
                carrying[v] = True
        # records (state at time t) and the pins' update, as the single kernel does them
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
