r"""Compiled hot loop stepping many variants of a drive together, linearly implicit
(internal).

:func:`integrate_implicit_lanes` advances ``V`` variants ("lanes") of one drive layout
(the same number of pins, wheels and guides; any masses, stiffnesses, profiles, speeds,
loads and time steps) with the linearly implicit step of
:func:`._implicit.integrate_implicit`, each lane exactly as that kernel advances it
alone: the same operations in the same order, so the results are equal to the last bit
(``tests/test_simulation_batched_implicit.py``).

Layout: the lanes go in blocks of :data:`._lane_passes.BLOCK` (32); each step runs a
block through all its passes before the next block, on the link system's work arrays
``(N, BLOCK)`` shared by the blocks (a block's working set stays in the core's L2
cache; the pins' state is kept blocked ``(blocks, N, BLOCK)`` during a call, copied back
to the ``(N, V)`` arrays of :class:`Lanes` at its end), the lanes the inner, contiguous
dimension, so that the link forces,
the pins' 2 x 2 inverses, the Woodbury passes, the cyclic tridiagonal factorisation and
substitutions (:func:`._banded._factor_solve4`'s arithmetic with every recurrence carried
per lane) and the pins' update run as vector instructions across the lanes
(:mod:`._lane_passes`), as does the span damping, its force and slope, each lane its own
(:mod:`._lane_span`); the contact candidates listed with the pins read across the
lanes; the wheel contacts a candidate slot at a time across the lanes, their law
branch-free (:mod:`._lane_contacts`); the guides, the wheels' bordered (Schur
complement) rows, the active set of the contacts (a lane solved again alone by
``_implicit._solve`` on its columns) and the wheels' update per lane.

Lanes run segments. A segment is one call of the single kernel: ``nsteps`` steps from
time ``t0`` with a record every ``every`` steps, the contact candidates and the seats'
cache fresh at its start (:func:`start_lane`). Each lane has its own segment and step
count; a lane without a segment is idle (its state untouched). A call returns when one
lane or more has finished its segment (``step == nsteps``), so the caller can read its
records and start its next segment while the others go on where they stopped.
Divisions by zero give inf instead of raising (``error_model="numpy"``, so that the
loops vectorise; the values are the same).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from . import _contact as C
from . import _kernel as K
from ._banded import _apply_inverse, _small_solve
from ._batched import LANES, NQ, _wheel_constants
from ._implicit import (
    C_BETA,
    C_DN,
    C_DT,
    C_FN0,
    C_FT0,
    C_L,
    C_LT,
    C_NX,
    C_NY,
    C_S,
    _pin_inverse,
    _solve,
)
from ._kernel import advance_motor, speed_factor, wheel_drive_torque
from ._lane_contacts import NO, _add_pin, wheel_contacts
from ._lane_passes import (
    BLOCK,
    _back,
    _entries,
    _factor_solve,
    _links,
    _pin_forces,
    _pin_inverses,
    _rhs,
    _update,
)
from ._lane_span import span_damping_implicit

__all__ = ["Lanes", "integrate_implicit_lanes", "start_lane"]

_OPTS = {"cache": True, "fastmath": False, "error_model": "numpy"}


#: the attributes of :class:`Lanes` with the lanes as their second dimension
_PIN_ARRAYS = frozenset({"x", "y", "vx", "vy"})


class Lanes:
    """The state and the work arrays of ``V`` lanes of one layout (``n`` pins, ``nw``
    wheels, ``ng`` guides, seat tables of ``smax`` seats), ``R`` records per segment.

    Pins ``x``, ``y``, ``vx``, ``vy`` ``(N, V)``; wheels ``ws`` ``(V, W, NWS)``, ``wp``
    ``(V, W, NWP)``; guides ``gd`` ``(V, G, NGD)``; seat tables ``tab`` ``(V, W, smax, 6)``;
    parameters ``par`` ``(V, NPAR)``; per lane its segment: ``t0``, ``nsteps``, ``every``,
    ``step``, ``nrec``, ``active``; records ``rec_t`` ``(V, R)``, ``rec_tension``
    ``(V, R, N)``, ``rec_ws`` ``(V, R, W, NWS)``, ``rec_pos`` ``(V, R, N, 2)``.
    """

    def __init__(self, v: int, n: int, nw: int, ng: int, smax: int, records: int):
        f = np.zeros
        self.x, self.y, self.vx, self.vy = (f((n, v)) for _ in range(4))
        self.ws = f((v, nw, K.NWS))
        self.wp = f((v, nw, K.NWP))
        self.gd = f((v, ng, K.NGD))
        self.tab = f((v, nw, smax, 6))
        self.par = np.ones((v, K.NPAR))
        self.t0 = f(v)
        self.nsteps = np.zeros(v, np.int64)
        self.every = np.ones(v, np.int64)
        self.step = np.zeros(v, np.int64)
        self.nrec = np.zeros(v, np.int64)
        self.active = np.zeros(v, np.bool_)
        self.countdown = np.zeros(v, np.int64)
        self.vmax_s = f(v)
        self.cand = np.zeros((v, nw, n), np.int64)
        self.gcache = np.full((v, nw, n), -1, np.int64)
        self.ncand = np.zeros((v, nw), np.int64)
        self.gcand = np.zeros((v, ng, n), np.int64)
        self.ngcand = np.zeros((v, ng), np.int64)
        self.rec_t = f((v, records))
        self.rec_tension = f((v, records, n))
        self.rec_ws = f((v, records, nw, K.NWS))
        self.rec_pos = f((v, records, n, 2))

    def arrays(self) -> tuple:
        """The arguments of :func:`integrate_implicit_lanes`, in order."""
        return (self.x, self.y, self.vx, self.vy, self.ws, self.wp, self.gd, self.tab, self.par,
                self.t0, self.nsteps, self.every, self.step, self.nrec, self.active,
                self.countdown, self.vmax_s, self.cand, self.gcache, self.ncand, self.gcand,
                self.ngcand, self.rec_t, self.rec_tension, self.rec_ws, self.rec_pos)

    def take(self, keep: np.ndarray) -> Lanes:
        """A new :class:`Lanes` of the lanes ``keep`` (in that order), each where it stands
        (mid-segment included)."""
        new = object.__new__(Lanes)
        for name, value in vars(self).items():
            setattr(new, name, value[:, keep].copy() if name in _PIN_ARRAYS else value[keep].copy())
        return new

    def load(self, v: int, pos: np.ndarray, vel: np.ndarray, ws: np.ndarray, wp: np.ndarray,
             gd: np.ndarray, tab: np.ndarray, par: np.ndarray, t0: float, nsteps: int,
             every: int) -> None:
        """Start a segment of lane ``v`` from the given state (as one call of the single
        kernel with these arguments)."""
        self.x[:, v] = pos[:, 0]
        self.y[:, v] = pos[:, 1]
        self.vx[:, v] = vel[:, 0]
        self.vy[:, v] = vel[:, 1]
        self.ws[v] = ws
        self.wp[v] = wp
        self.gd[v] = gd
        self.tab[v] = 0.0
        self.tab[v, :, :tab.shape[1]] = tab
        self.par[v] = par
        start_lane(v, t0, nsteps, every, self.t0, self.nsteps, self.every, self.step, self.nrec,
                   self.active, self.countdown, self.vmax_s, self.gcache, self.ncand,
                   self.ngcand)

    def state(self, v: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``(pos, vel, ws)`` of lane ``v`` (copies)."""
        pos = np.column_stack([self.x[:, v], self.y[:, v]])
        vel = np.column_stack([self.vx[:, v], self.vy[:, v]])
        return pos, vel, self.ws[v].copy()


@njit(cache=True, fastmath=False)
def start_lane(v, t0, nsteps, every, t0s, nstepss, everys, step, nrec, active, countdown, vmax_s,
               gcache, ncand, ngcand):
    """Lane ``v`` begins a segment: the per-call state of the single kernel set fresh."""
    t0s[v] = t0
    nstepss[v] = nsteps
    everys[v] = every
    step[v] = 0
    nrec[v] = 0
    active[v] = nsteps > 0
    countdown[v] = 0
    vmax_s[v] = 0.0
    gcache[v, :, :] = -1
    ncand[v, :] = 0
    ngcand[v, :] = 0


@njit(**_OPTS)
def _lane_guides(v, b, x, y, vx, vy, fx, fy, mxx, mxy, myy, gd, par, gcand, ngcand, rebuild,
                 margin):
    """The guide contacts of lane ``v`` (forces and 2 x 2 matrix terms on its pins, the
    block's column ``b``), as the single kernel."""
    ng = gd.shape[1]
    h = par[v, K.P_DT]
    th = par[v, K.P_THETA]
    thh = th * h
    rr = par[v, K.P_RROLLER]
    mu = par[v, K.P_MU]
    veps = par[v, K.P_VEPS]
    dtref = par[v, K.P_DTREF]
    inv_m = 1.0 / par[v, K.P_MASS]
    kg = par[v, K.P_KG]
    cg = par[v, K.P_CG]
    gx = par[v, K.P_GX]
    gy = par[v, K.P_GY]
    betag = th * (h * kg + cg)
    gdv = gd[v]
    for g in range(ng):
        if rebuild:
            C.guide_candidates(x[:, b], y[:, b], gdv, g, rr + margin, gcand[v], ngcand[v])
        for ic in range(ngcand[v, g]):
            i = gcand[v, g, ic]
            pen, mx, my = C.guide_penetration(x[i, b], y[i, b], gdv, g, rr, margin)
            if pen <= -margin:
                continue
            vn = vx[i, b] * mx + vy[i, b] * my
            fn0 = kg * (pen - thh * vn) - cg * vn
            if fn0 <= 0.0:
                continue
            fn = kg * pen - cg * vn if pen > 0.0 else 0.0
            if fn < 0.0:
                fn = 0.0
            vt = vx[i, b] * my - vy[i, b] * mx
            mug = C.guide_mu(gdv, g, mu)
            ft0, ve = C.friction(mug, fn, vt, dtref, inv_m, veps)
            s = mug * fn / ve if abs(vt) < ve else 0.0
            mmat = gdv[g, K.G_MM]
            if mmat > 0.0:
                fdrag, fm, vem = C.material_drag(gdv, g, gx, gy, mx, my, vt, dtref, inv_m, veps)
                ft0 += fdrag
                if abs(vt) < vem:
                    s += fm / vem
                _add_pin(mxx, mxy, myy, i, b, mmat / h, my, -mx)
            s *= th
            fx[i, b] += fn0 * mx + ft0 * my
            fy[i, b] += fn0 * my - ft0 * mx
            _add_pin(mxx, mxy, myy, i, b, betag, mx, my)
            _add_pin(mxx, mxy, myy, i, b, s, my, -mx)


@njit(**_OPTS)
def _drop_tensile(v, b, cinfo, ncand, cand, qrot, qsl, dq, dvx, dvy, yx, yy, mxx, mxy, myy, wtq,
                  wsf):
    """:func:`._implicit._drop_tensile` for lane ``v`` (the block's column ``b``; without
    the contact record)."""
    changed = False
    for w in range(qrot.shape[1]):
        dom = dq[v, qrot[v, w]] if qrot[v, w] >= 0 else 0.0
        dsd = dq[v, qsl[v, w]] if qsl[v, w] >= 0 else 0.0
        for ic in range(ncand[v, w]):
            be = cinfo[v, w, ic, C_BETA]
            if be == 0.0:
                continue
            i = cand[v, w, ic]
            nx = cinfo[v, w, ic, C_NX]
            ny = cinfo[v, w, ic, C_NY]
            dvn = nx * dvx[i, b] + ny * dvy[i, b] - dom * cinfo[v, w, ic, C_L] - dsd * cinfo[v, w, ic, C_DN]
            fn0 = cinfo[v, w, ic, C_FN0]
            if fn0 + be * dvn >= 0.0:
                continue
            changed = True
            ft0 = cinfo[v, w, ic, C_FT0]
            s = cinfo[v, w, ic, C_S]
            yx[i, b] += fn0 * nx + ft0 * ny
            yy[i, b] += fn0 * ny - ft0 * nx
            _add_pin(mxx, mxy, myy, i, b, -be, nx, ny)
            _add_pin(mxx, mxy, myy, i, b, -s, -ny, nx)
            wtq[v, w] -= fn0 * cinfo[v, w, ic, C_L] - ft0 * cinfo[v, w, ic, C_LT]
            wsf[v, w] -= fn0 * cinfo[v, w, ic, C_DN] - ft0 * cinfo[v, w, ic, C_DT]
            cinfo[v, w, ic, C_BETA] = 0.0
            cinfo[v, w, ic, C_S] = 0.0
    return changed



@njit(**_OPTS)
def _border_rows(v, b, ws, wp, par, ncand, cand, cinfo, qrot, qsl, bx, by, sq, fq, wtq, wsf, t):
    """The wheels' rows of lane ``v``'s bordered system ``[[P, B], [Bᵀ, Q]]`` (as
    ``_implicit._solve``): ``qrot``, ``qsl``, ``Q`` in ``sq[v]``, ``F_q`` in ``fq[v]``,
    ``B`` in ``bx``, ``by`` ``(2W, N, block)`` column ``b``; returns their number ``nq``."""
    nw = ws.shape[1]
    h = par[v, K.P_DT]
    gx = par[v, K.P_GX]
    gy = par[v, K.P_GY]
    wsv = ws[v]
    wpv = wp[v]
    nq = 0
    for w in range(nw):
        mode = wpv[w, K.W_MODE]
        qrot[v, w] = -1
        qsl[v, w] = -1
        if (mode == K.MODE_FREE or mode == K.MODE_MOTOR) and ncand[v, w] > 0:
            qrot[v, w] = nq
            nq += 1
        if wpv[w, K.W_SLIDE] > 0.0 and ncand[v, w] > 0:
            qsl[v, w] = nq
            nq += 1
    for q in range(nq):
        for q2 in range(nq):
            sq[v, q, q2] = 0.0
        fq[v, q] = 0.0
    for w in range(nw):
        om = wsv[w, K.S_OMEGA]
        qr = qrot[v, w]
        qs = qsl[v, w]
        if qr >= 0:
            sq[v, qr, qr] = wpv[w, K.W_INERTIA] / h
            fq[v, qr] = wtq[v, w] + wpv[w, K.W_TORQUE] - wpv[w, K.W_DAMP] * om
            if wpv[w, K.W_MODE] == K.MODE_MOTOR:
                fq[v, qr] += wheel_drive_torque(wpv, wsv, w, om, t, fq[v, qr], h)
        if qs >= 0:
            sq[v, qs, qs] = wpv[w, K.W_SMASS] / h
            fq[v, qs] = wsf[v, w] + wpv[w, K.W_SF] - wpv[w, K.W_SK] * wsv[w, K.S_S] \
                - wpv[w, K.W_SC] * wsv[w, K.S_SDOT] \
                + wpv[w, K.W_SMASS] * (gx * wpv[w, K.W_DX] + gy * wpv[w, K.W_DY])
        if qr < 0 and qs < 0:
            continue
        for ic in range(ncand[v, w]):
            be = cinfo[v, w, ic, C_BETA]
            if be == 0.0:
                continue
            s = cinfo[v, w, ic, C_S]
            i = cand[v, w, ic]
            nx = cinfo[v, w, ic, C_NX]
            ny = cinfo[v, w, ic, C_NY]
            lev = cinfo[v, w, ic, C_L]
            levt = cinfo[v, w, ic, C_LT]
            dn = cinfo[v, w, ic, C_DN]
            dtt = cinfo[v, w, ic, C_DT]
            if qr >= 0:
                bx[qr, i, b] -= be * lev * nx - s * levt * ny
                by[qr, i, b] -= be * lev * ny + s * levt * nx
                sq[v, qr, qr] += be * lev * lev + s * levt * levt
            if qs >= 0:
                bx[qs, i, b] -= be * dn * nx - s * dtt * ny
                by[qs, i, b] -= be * dn * ny + s * dtt * nx
                sq[v, qs, qs] += be * dn * dn + s * dtt * dtt
            if qr >= 0 and qs >= 0:
                sq[v, qr, qs] += be * lev * dn + s * levt * dtt
                sq[v, qs, qr] += be * lev * dn + s * levt * dtt
    return nq


@njit(**_OPTS)
def _schur(v, b, nq, ncand, cand, qrot, qsl, bx, by, zx, zy, dvx, dvy, sq, fq):
    """Lane ``v``'s Schur complement ``S = Q − Bᵀ P⁻¹ B`` and right-hand side
    ``F_q − Bᵀ P⁻¹ F`` (``B`` cleared after use), solved in place in ``fq[v]``."""
    for w in range(qrot.shape[1]):
        for q in (qrot[v, w], qsl[v, w]):
            if q < 0:
                continue
            for ic in range(ncand[v, w]):
                i = cand[v, w, ic]
                bxq = bx[q, i, b]
                byq = by[q, i, b]
                if bxq == 0.0 and byq == 0.0:
                    continue
                fq[v, q] -= bxq * dvx[i, b] + byq * dvy[i, b]
                for q2 in range(nq):
                    sq[v, q, q2] -= bxq * zx[q2, i, b] + byq * zy[q2, i, b]
                bx[q, i, b] = 0.0
                by[q, i, b] = 0.0
    _small_solve(sq[v], fq[v], nq)


@njit(**_OPTS)
def _wheels(v, ws, wp, par, qrot, qsl, fq, omu, t):
    """Lane ``v``'s wheels after its pins (as the single kernel)."""
    h = par[v, K.P_DT]
    gx = par[v, K.P_GX]
    gy = par[v, K.P_GY]
    wsv = ws[v]
    wpv = wp[v]
    for w in range(wsv.shape[0]):
        qr = qrot[v, w]
        if wpv[w, K.W_MODE] == K.MODE_MOTOR and qr >= 0:
            advance_motor(wpv, wsv, w, t, h)
        if qr >= 0:
            wsv[w, K.S_OMEGA] += fq[v, qr]
        elif wpv[w, K.W_MODE] == K.MODE_FREE or wpv[w, K.W_MODE] == K.MODE_MOTOR:
            om = wsv[w, K.S_OMEGA]
            tq = wpv[w, K.W_TORQUE] - wpv[w, K.W_DAMP] * om
            if wpv[w, K.W_MODE] == K.MODE_MOTOR:
                tq += wheel_drive_torque(wpv, wsv, w, om, t, tq, h)
                advance_motor(wpv, wsv, w, t, h)
            wsv[w, K.S_OMEGA] = om + h * tq / wpv[w, K.W_INERTIA]
        else:
            wsv[w, K.S_OMEGA] = omu[v, w]
        wsv[w, K.S_THETA] += wsv[w, K.S_OMEGA] * h
        if wpv[w, K.W_SLIDE] > 0.0:
            if qsl[v, w] >= 0:
                wsv[w, K.S_SDOT] += fq[v, qsl[v, w]]
            else:
                dxw = wpv[w, K.W_DX]
                dyw = wpv[w, K.W_DY]
                fs = wpv[w, K.W_SF] - wpv[w, K.W_SK] * wsv[w, K.S_S] \
                    - wpv[w, K.W_SC] * wsv[w, K.S_SDOT] + wpv[w, K.W_SMASS] * (gx * dxw + gy * dyw)
                wsv[w, K.S_SDOT] += h * fs / wpv[w, K.W_SMASS]
            wsv[w, K.S_S] += wsv[w, K.S_SDOT] * h


@njit(**_OPTS)
def _rebuild(v0, nb, due, x, y, vx, vy, ws, wp, par, margin, h, countdown, vmax_s, cand, gcache,
             ncand, vm, rc2):
    """The contact candidates of the lanes ``due`` of the block of ``nb`` lanes from lane
    ``v0``, as the single kernel lists them (:func:`._contact.rebuild_every`,
    :func:`._contact.wheel_candidates`: the same pins in the same order, the same
    countdown), the pins read across the block's lanes (contiguous)."""
    n = x.shape[0]
    nw = ws.shape[1]
    for b in range(nb):
        vm[b] = 0.0
    for i in range(n):
        for b in range(nb):
            v2 = vx[i, b] * vx[i, b] + vy[i, b] * vy[i, b]
            vm[b] = v2 if v2 > vm[b] else vm[b]
    for b in range(nb):
        v = v0 + b
        if not due[v]:
            continue
        vmax = math.sqrt(vm[b])
        vs = vmax_s[v]
        for w in range(nw):
            vmax_w = abs(ws[v, w, K.S_SDOT])
            if vmax_w > vs:
                vs = vmax_w
        vmax_s[v] = vs
        cnt = margin[v] / (4.0 * (vmax + vs + 1e-12) * h[v])
        countdown[v] = 1 if cnt < 1.0 else (200 if cnt > 200.0 else int(cnt))
        rr = par[v, K.P_RROLLER]
        for w in range(nw):
            geo = C.wheel_geometry(wp[v], ws[v], w, rr)
            rc = geo[10] + margin[v]
            rc2[b, w, 0] = geo[0]
            rc2[b, w, 1] = geo[1]
            rc2[b, w, 2] = rc * rc
            for ic in range(ncand[v, w]):
                gcache[v, w, cand[v, w, ic]] = -1
            ncand[v, w] = 0
    for w in range(nw):
        for i in range(n):
            for b in range(nb):
                v = v0 + b
                if due[v]:
                    qx = x[i, b] - rc2[b, w, 0]
                    qy = y[i, b] - rc2[b, w, 1]
                    if qx * qx + qy * qy <= rc2[b, w, 2]:
                        cand[v, w, ncand[v, w]] = i
                        ncand[v, w] += 1


@njit(**_OPTS)
def _solve_all(v0, nb, act, nq, ws, wp, par, ncand, cand, cinfo, qrot, qsl, bx, by, zx, zy, sq,
               fq, wtq, wsf, tl, yx, yy, wxx, wxy, wyy, ux, uy, dg, of, dd, ff, dlast, bl, dcur,
               lams, inv_ak, dvx, dvy):
    """``_implicit._solve`` of every stepping lane of the block of ``nb`` lanes from lane
    ``v0``: the link system's passes across the block's lanes, the wheels' border per
    lane."""
    n = yx.shape[0]
    _entries(dg, of, wxx, wxy, wyy, ux, uy, inv_ak)
    maxnq = 0
    for b in range(nb):
        v = v0 + b
        nq[v] = 0
        if act[v]:
            nq[v] = _border_rows(v, b, ws, wp, par, ncand, cand, cinfo, qrot, qsl, bx, by, sq,
                                 fq, wtq, wsf, tl[v])
            maxnq = max(maxnq, nq[v])
    _rhs(yx, yy, dvx, dvy, wxx, wxy, wyy, ux, uy, lams[0])
    fused = min(maxnq, 3)
    for q in range(fused):
        _rhs(bx[q], by[q], zx[q], zy[q], wxx, wxy, wyy, ux, uy, lams[q + 1])
    if maxnq > 1:
        for q in range(fused, 3):
            lams[q + 1, :, :] = 0.0
    _factor_solve(dg, of, dd, ff, dlast, bl, lams, 4 if maxnq > 1 else 2, dcur)
    _back(dvx, dvy, wxx, wxy, wyy, ux, uy, lams[0])
    if maxnq == 0:
        return
    for q in range(fused):
        _back(zx[q], zy[q], wxx, wxy, wyy, ux, uy, lams[q + 1])
    for b in range(nb):
        v = v0 + b
        if nq[v] == 0:
            continue
        for q in range(min(nq[v], 3), nq[v]):
            _apply_inverse(bx[q, :, b], by[q, :, b], zx[q, :, b], zy[q, :, b], wxx[:, b],
                           wxy[:, b], wyy[:, b], ux[:, b], uy[:, b], of[:, b], dd[:, b],
                           ff[:, b], dlast[b], lams[1, :, b])
        _schur(v, b, nq[v], ncand, cand, qrot, qsl, bx, by, zx, zy, dvx, dvy, sq, fq)
    for q in range(maxnq):
        for i in range(n):
            for b in range(nb):
                v = v0 + b
                dvx[i, b] = dvx[i, b] - zx[q, i, b] * fq[v, q] if q < nq[v] else dvx[i, b]
                dvy[i, b] = dvy[i, b] - zy[q, i, b] * fq[v, q] if q < nq[v] else dvy[i, b]


@njit(**_OPTS)
def _lane_solve(v, b, mh, mxx, mxy, myy, wxx, wxy, wyy, yx, yy, ux, uy, dg, of, dd, ff, lams,
                inv_ak, dvx, dvy, ws, wp, par, ncand, cand, cinfo, qrot, qsl, bx, by, zx, zy, sq,
                fq, wtq, wsf, t):
    """Lane ``v`` (the block's column ``b``) solved again after a dropped contact: its
    pins' inverses and ``_implicit._solve`` itself on the lane's columns."""
    n = yx.shape[0]
    for i in range(n):
        _pin_inverse(i, mh[b], mxx[:, b], mxy[:, b], myy[:, b], wxx[:, b], wxy[:, b], wyy[:, b])
    _solve(n, ws.shape[1], yx[:, b], yy[:, b], wxx[:, b], wxy[:, b], wyy[:, b], ux[:, b],
           uy[:, b], dg[:, b], of[:, b], dd[:, b], ff[:, b], lams[0, :, b], lams[1:, :, b],
           inv_ak[b], dvx[:, b], dvy[:, b], ws[v], wp[v], ncand[v], cand[v], cinfo[v], qrot[v],
           qsl[v], bx[:, :, b], by[:, :, b], zx[:, :, b], zy[:, :, b], sq[v], fq[v], wtq[v],
           wsf[v], par[v, K.P_DT], t, par[v, K.P_GX], par[v, K.P_GY])


@njit(**_OPTS)
def _blocked(a, nblk):
    """``(N, V)`` as ``(blocks, N, BLOCK)``, the last block padded with the last lane."""
    n, nv = a.shape
    out = np.empty((nblk, n, BLOCK))
    for blk in range(nblk):
        for i in range(n):
            for b in range(BLOCK):
                out[blk, i, b] = a[i, min(blk * BLOCK + b, nv - 1)]
    return out


@njit(**_OPTS)
def _unblocked(out, a):
    """The lanes of the blocked ``a`` back into ``out`` ``(N, V)``."""
    n, nv = out.shape
    for i in range(n):
        for v in range(nv):
            out[i, v] = a[v // BLOCK, i, v % BLOCK]


@njit(**_OPTS)
def _lane_constants(par, nblk):
    """Per lane (padded to whole blocks, ``(blocks, BLOCK)``): ``k``, ``c``, ``h``,
    ``θ h``, ``m/h``, ``1/a``, the weight, the global damping and the span damping's
    ``α m`` and ``θ α m``."""
    nv = par.shape[0]
    out = np.empty((11, nblk, BLOCK))
    for blk in range(nblk):
        for b in range(BLOCK):
            v = min(blk * BLOCK + b, nv - 1)
            m = par[v, K.P_MASS]
            k = par[v, K.P_K]
            c = par[v, K.P_C]
            h = par[v, K.P_DT]
            th = par[v, K.P_THETA]
            out[0, blk, b] = k
            out[1, blk, b] = c
            out[2, blk, b] = h
            out[3, blk, b] = th * h
            out[4, blk, b] = m / h
            out[5, blk, b] = 1.0 / (th * (h * k + c))
            out[6, blk, b] = m * par[v, K.P_GX]
            out[7, blk, b] = m * par[v, K.P_GY]
            out[8, blk, b] = par[v, K.P_CGLOB] * m
            out[9, blk, b] = par[v, K.P_CSPAN] * m
            out[10, blk, b] = th * out[9, blk, b]
    return out


@njit(**_OPTS)
def _rest_lengths(par, n, nblk):
    """The links' rest lengths ``(blocks, N, BLOCK)`` (padded as :func:`_lane_constants`)."""
    nv = par.shape[0]
    rest = np.empty((nblk, n, BLOCK))
    for blk in range(nblk):
        for i in range(n):
            for b in range(BLOCK):
                v = min(blk * BLOCK + b, nv - 1)
                rest[blk, i, b] = par[v, K.P_PITCH] if i % 2 == 0 else par[v, K.P_PITCH2]
    return rest


@njit(**_OPTS)
def integrate_implicit_lanes(x, y, vx, vy, ws, wp, gd, tab, par, t0, nsteps, every, step, nrec,
                             active, countdown, vmax_s, cand, gcache, ncand, gcand, ngcand,
                             rec_t, rec_tension, rec_ws, rec_pos, max_steps):
    """Step every active lane through its segment (see the module notes) until one or
    more finishes it, at most ``max_steps`` steps; return the steps taken. A finished
    lane is left inactive with its state and ``nrec[v]`` records.

    The lanes go in blocks of ``BLOCK``: each step runs a block through all its passes
    before the next block, on work arrays ``(N, BLOCK)`` shared by the blocks (so that a
    block's working set stays in the core's caches), the pins' state kept blocked
    ``(blocks, N, BLOCK)`` during the call."""
    n, nv = x.shape
    nw = ws.shape[1]
    ng = gd.shape[1]
    nblk = (nv + BLOCK - 1) // BLOCK
    h = par[:, K.P_DT].copy()
    margin = np.empty(nv)
    for v in range(nv):
        margin[v] = 0.25 * par[v, K.P_RROLLER]
    lc = _lane_constants(par, nblk)
    rest = _rest_lengths(par, n, nblk)
    xb, yb, vxb, vyb = _blocked(x, nblk), _blocked(y, nblk), _blocked(vx, nblk), _blocked(vy, nblk)
    f2 = np.zeros
    tension, tstar, ux, uy = f2((n, BLOCK)), f2((n, BLOCK)), f2((n, BLOCK)), f2((n, BLOCK))
    fx, fy, mxx, mxy, myy = (f2((n, BLOCK)), f2((n, BLOCK)), f2((n, BLOCK)), f2((n, BLOCK)),
                             f2((n, BLOCK)))
    wxx, wxy, wyy, yx, yy = (f2((n, BLOCK)), f2((n, BLOCK)), f2((n, BLOCK)), f2((n, BLOCK)),
                             f2((n, BLOCK)))
    dg, of, dd, ff, dvx, dvy = (f2((n, BLOCK)), f2((n, BLOCK)), f2((n, BLOCK)), f2((n, BLOCK)),
                                f2((n, BLOCK)), f2((n, BLOCK)))
    lams = f2((4, n, BLOCK))   # λ, then the border columns' λ_q
    bl = f2((4, BLOCK))
    dlast = f2(BLOCK)
    dcur = f2(BLOCK)
    bx, by = f2((2 * nw, n, BLOCK)), f2((2 * nw, n, BLOCK))
    zx, zy = f2((2 * nw, n, BLOCK)), f2((2 * nw, n, BLOCK))
    sq = f2((nv, 2 * nw, 2 * nw))
    fq = f2((nv, 2 * nw))
    qrot = np.full((nv, nw), -1, np.int64)
    qsl = np.full((nv, nw), -1, np.int64)
    nq = np.zeros(nv, np.int64)
    cinfo = f2((nv, nw, n, 11))
    wtq = f2((nv, nw))
    wsf = f2((nv, nw))
    omu = f2((nv, nw))
    act = np.zeros(nv, np.bool_)
    actb = np.zeros(BLOCK, np.bool_)
    gc, pt = _wheel_constants(wp, par)
    tab2 = tab.reshape((nv * nw, tab.shape[2], tab.shape[3]))
    sqb = f2(NQ * LANES)
    sob = f2(NO * LANES)
    sib = np.zeros(LANES, np.int64)
    due = np.zeros(nv, np.bool_)
    vm = f2(BLOCK)
    rc2 = f2((BLOCK, nw, 3))
    tl = f2(nv)
    nrmax = rec_t.shape[1]
    taken = 0
    while taken < max_steps:
        anyact = False
        for v in range(nv):
            act[v] = active[v]
            anyact = anyact or act[v]
        if not anyact:
            break
        for blk in range(nblk):
            v0 = blk * BLOCK
            nb = min(BLOCK, nv - v0)
            anyb = False
            for b in range(BLOCK):
                actb[b] = b < nb and act[v0 + b]
                anyb = anyb or actb[b]
            if not anyb:
                continue
            _block_step(v0, nb, n, nw, ng, actb, act, due, xb[blk], yb[blk], vxb[blk], vyb[blk],
                        rest[blk], lc[0, blk], lc[1, blk], lc[2, blk], lc[3, blk], lc[4, blk],
                        lc[5, blk], lc[6, blk], lc[7, blk], lc[8, blk], lc[9, blk], lc[10, blk],
                        h, margin, ws, wp, gd,
                        par, t0, step, every, nrec, countdown, vmax_s, cand, gcache, ncand,
                        gcand, ngcand, rec_t, rec_tension, rec_ws, rec_pos, nrmax, tension,
                        tstar, ux, uy, fx, fy, mxx, mxy, myy, wxx, wxy, wyy, yx, yy, dg, of, dd,
                        ff, dvx, dvy, lams, bl, dlast, dcur, bx, by, zx, zy, sq, fq, qrot, qsl,
                        nq, cinfo, wtq, wsf, omu, gc, pt, tab2, sqb, sob, sib, vm, rc2, tl)
        done = False
        for v in range(nv):
            if not act[v]:
                continue
            step[v] += 1
            if step[v] >= nsteps[v]:
                active[v] = False
                done = True
        taken += 1
        if done:
            break
    _unblocked(x, xb)
    _unblocked(y, yb)
    _unblocked(vx, vxb)
    _unblocked(vy, vyb)
    return taken


@njit(**_OPTS)
def _block_step(v0, nb, n, nw, ng, actb, act, due, x, y, vx, vy, rest, k, c, hb, thh, mh, inv_ak,
                fgx, fgy, cm, cspan, cspth, h, margin, ws, wp, gd, par, t0, step, every, nrec, countdown,
                vmax_s, cand, gcache, ncand, gcand, ngcand, rec_t, rec_tension, rec_ws, rec_pos,
                nrmax, tension, tstar, ux, uy, fx, fy, mxx, mxy, myy, wxx, wxy, wyy, yx, yy, dg,
                of, dd, ff, dvx, dvy, lams, bl, dlast, dcur, bx, by, zx, zy, sq, fq, qrot, qsl,
                nq, cinfo, wtq, wsf, omu, gc, pt, tab2, sqb, sob, sib, vm, rc2, tl):
    """One step of the block of ``nb`` lanes from lane ``v0`` (its pins ``x`` ... and
    per-lane constants ``k`` ... ``cspth`` the block's ``(N, BLOCK)``, ``(BLOCK,)`` arrays,
    ``actb`` its stepping lanes), every pass of the single kernel's step in its order."""
    _links(x, y, vx, vy, k, c, thh, rest, tension, tstar, ux, uy)
    # the span damping (its force and slope; nothing in a block without it)
    span_damping_implicit(x, y, vx, vy, fx, fy, mxx, mxy, myy, cspan, cspth)
    anydue = False
    for b in range(nb):
        v = v0 + b
        due[v] = act[v] and countdown[v] <= 0
        anydue = anydue or due[v]
    if anydue:
        _rebuild(v0, nb, due, x, y, vx, vy, ws, wp, par, margin, h, countdown, vmax_s, cand,
                 gcache, ncand, vm, rc2)
    for b in range(nb):
        v = v0 + b
        if not act[v]:
            continue
        t = t0[v] + step[v] * h[v]
        tl[v] = t
        tn = t + h[v]
        for w in range(nw):
            mode = wp[v, w, K.W_MODE]
            if mode == K.MODE_SPEED:
                omu[v, w] = wp[v, w, K.W_OMEGA0] * speed_factor(wp[v], w, tn)
            elif mode == K.MODE_LOCKED:
                omu[v, w] = 0.0
            else:
                omu[v, w] = ws[v, w, K.S_OMEGA]
        countdown[v] -= 1
    for w in range(nw):
        wheel_contacts(w, v0, nb, act, x, y, vx, vy, fx, fy, mxx, mxy, myy, ws, wp, par, omu,
                       tab2, gc, pt, cand, gcache, ncand, cinfo, wtq, wsf, sqb, sob, sib)
    for b in range(nb):
        v = v0 + b
        if not act[v]:
            continue
        if ng > 0:
            _lane_guides(v, b, x, y, vx, vy, fx, fy, mxx, mxy, myy, gd, par, gcand, ngcand,
                         due[v], margin[v])
        t = tl[v]
        r = nrec[v]
        if step[v] % every[v] == 0 and r < nrmax:
            rec_t[v, r] = t
            for i in range(n):
                rec_tension[v, r, i] = tension[i, b]
                rec_pos[v, r, i, 0] = x[i, b]
                rec_pos[v, r, i, 1] = y[i, b]
            for w in range(nw):
                for col in range(ws.shape[2]):
                    rec_ws[v, r, w, col] = ws[v, w, col]
            nrec[v] = r + 1
    _pin_forces(fx, fy, fgx, fgy, cm, vx, vy, tstar, ux, uy, yx, yy)
    _pin_inverses(mh, mxx, mxy, myy, wxx, wxy, wyy)
    _solve_all(v0, nb, act, nq, ws, wp, par, ncand, cand, cinfo, qrot, qsl, bx, by, zx, zy, sq,
               fq, wtq, wsf, tl, yx, yy, wxx, wxy, wyy, ux, uy, dg, of, dd, ff, dlast, bl, dcur,
               lams, inv_ak, dvx, dvy)
    # the active set of the wheel contacts (as the single kernel): a lane whose contact
    # comes out tensile is solved again, alone, by the single kernel's solve
    for b in range(nb):
        v = v0 + b
        if not act[v]:
            continue
        for _ in range(3):
            if not _drop_tensile(v, b, cinfo, ncand, cand, qrot, qsl, fq, dvx, dvy, yx, yy, mxx,
                                 mxy, myy, wtq, wsf):
                break
            _lane_solve(v, b, mh, mxx, mxy, myy, wxx, wxy, wyy, yx, yy, ux, uy, dg, of, dd, ff,
                        lams, inv_ak, dvx, dvy, ws, wp, par, ncand, cand, cinfo, qrot, qsl, bx,
                        by, zx, zy, sq, fq, wtq, wsf, tl[v])
    _update(actb, hb, x, y, vx, vy, dvx, dvy, fx, fy, mxx, mxy, myy)
    for b in range(nb):
        v = v0 + b
        if act[v]:
            _wheels(v, ws, wp, par, qrot, qsl, fq, omu, tl[v])
