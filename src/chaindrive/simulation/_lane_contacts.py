"""The wheel contacts of :mod:`._batched_implicit`, a candidate slot across the lanes (internal).

The roller-seat and rim contacts of one wheel in every lane, a block of ``LANES`` lanes
and one candidate slot at a time, as :mod:`._batched` does them for the explicit step:
gathered per lane (the pin, its offset from the wheel centre, its seat: the last one kept
when the pin is still within it, else the walk of :func:`._contact.nearest_seat`; a
toothless idler's rim by :func:`._contact.rim_gap`), the contact law linearised for the
implicit step (``_implicit.integrate_implicit``: the normal force at the end of the step
without the implicit increment, the regularised friction and its sticking slope, the
concave seat's tangential stiffness) for all lanes of the block in one branch-free loop
(:func:`_slot_law`, every case evaluated and the one that applies selected, so that it
compiles to vector instructions: in a lane-per-lane loop the cases' branches, different
in every lane, are mispredicted), then scattered per lane with the single kernel's
arithmetic (forces, the pins' matrix terms, the wheel's torque and slide force in
candidate order, the contact's row for the wheels' border and the active set). Each
lane's result equals the single kernel's to the last bit.
"""

from __future__ import annotations

import math

from numba import njit

from . import _contact as C
from . import _layout as L
from ._batched import (
    G_ARC,
    G_CEA,
    G_CEB,
    G_CPS,
    G_DELTA,
    G_DTA,
    G_DTB,
    G_DX,
    G_DY,
    G_IZ,
    G_PA,
    G_PLAIN,
    G_RAD,
    G_RE,
    G_RIN2,
    G_ROUT2,
    G_SPS,
    G_STIP,
    G_TCA,
    G_TCB,
    LANES,
    NGC,
    Q_CTH,
    Q_CX,
    Q_CY,
    Q_EX,
    Q_EY,
    Q_OM,
    Q_ON,
    Q_PEN,
    Q_QX,
    Q_QY,
    Q_SD,
    Q_STH,
    Q_VX,
    Q_VY,
    _seat_lane,
)
from ._implicit import C_BETA, C_DN, C_DT, C_FN0, C_FT0, C_L, C_LT, C_NX, C_NY, C_S
from ._lane_passes import _NoAlias

__all__ = ["wheel_contacts"]

_OPTS = {"cache": True, "fastmath": False, "error_model": "numpy"}
#: the slot's law's arrays never overlap: vectorised without run-time overlap checks
_NOALIAS = {**_OPTS, "pipeline_class": _NoAlias}

#: rows of the slot's law ``so``: in contact, normal, force at the end of the step
#: without the implicit increment, friction, sticking slope
O_ON, O_NX, O_NY, O_FN0, O_FT0, O_S = range(6)
NO = 6


@njit(**_NOALIAS)
def _slot_law(sq, so, gc, g0, pt, p0, nb):
    """The linearised contact law of one candidate slot in the ``nb`` lanes of a block,
    branch-free (see the module notes); each lane's operations those of the single
    implicit kernel."""
    gb = gc[g0:]
    pb = pt[p0:]
    for v in range(nb):
        qx = sq[Q_QX * LANES + v]
        qy = sq[Q_QY * LANES + v]
        rr = pb[L.P_RROLLER * LANES + v]
        pen, nx, ny, ds = _seat_lane(qx, qy, sq[Q_EX * LANES + v], sq[Q_EY * LANES + v],
                                     sq[Q_CTH * LANES + v], sq[Q_STH * LANES + v],
                                     gb[G_RAD * LANES + v], rr, gb[G_DELTA * LANES + v],
                                     gb[G_CPS * LANES + v], gb[G_SPS * LANES + v],
                                     gb[G_RE * LANES + v], gb[G_ARC * LANES + v] > 0.5,
                                     gb[G_CEA * LANES + v], gb[G_CEB * LANES + v],
                                     gb[G_DTA * LANES + v], gb[G_DTB * LANES + v],
                                     gb[G_TCA * LANES + v], gb[G_TCB * LANES + v],
                                     gb[G_STIP * LANES + v])
        on = sq[Q_ON * LANES + v]
        rim = on == 2.0
        centre = ds == 0.0   # the roller on the seat's centre: no normal (as the scalar)
        pen = sq[Q_PEN * LANES + v] if rim else pen
        nx = sq[Q_EX * LANES + v] if rim else (0.0 if centre else nx)
        ny = sq[Q_EY * LANES + v] if rim else (0.0 if centre else ny)
        curv = 1.0 / ds if ds > 0.0 and not rim else 0.0
        om = sq[Q_OM * LANES + v]
        sd = sq[Q_SD * LANES + v]
        h = pb[L.P_DT * LANES + v]
        th = pb[L.P_THETA * LANES + v]
        thh = th * h
        kc = pb[L.P_KC * LANES + v]
        cc = pb[L.P_CC * LANES + v]
        mu = pb[L.P_MU * LANES + v]
        margin = 0.25 * rr
        rvx = sq[Q_VX * LANES + v] - (-om * qy + sd * gb[G_DX * LANES + v])
        rvy = sq[Q_VY * LANES + v] - (om * qx + sd * gb[G_DY * LANES + v])
        vn = rvx * nx + rvy * ny
        fn0 = kc * (pen + thh * vn) + cc * vn
        act = on > 0.0 and pen > -margin and not (fn0 <= 0.0 and pen <= 0.0)
        fn = kc * pen + cc * vn if pen > 0.0 else 0.0
        fn = 0.0 if fn < 0.0 else fn
        vt = -rvx * ny + rvy * nx
        ve = mu * fn * pb[L.P_DTREF * LANES + v] * (1.0 / pb[L.P_MASS * LANES + v])
        veps = pb[L.P_VEPS * LANES + v]
        ve = veps if ve < veps else ve
        x = vt / ve
        x = 1.0 if x > 1.0 else (-1.0 if x < -1.0 else x)
        ft0 = -mu * fn * x
        s = mu * fn / ve if abs(vt) < ve else 0.0
        kt = fn * curv
        ft0 = ft0 - thh * kt * vt if curv > 0.0 else ft0
        s = s + h * kt if curv > 0.0 else s
        so[O_ON * LANES + v] = 1.0 if act else 0.0
        so[O_NX * LANES + v] = nx
        so[O_NY * LANES + v] = ny
        so[O_FN0 * LANES + v] = fn0
        so[O_FT0 * LANES + v] = ft0
        so[O_S * LANES + v] = s * th


@njit(cache=True, fastmath=False, inline="always")
def _add_pin(mxx, mxy, myy, i, v, coef, ax, ay):
    """``M_i += coef (a aᵀ)`` of lane ``v``."""
    mxx[i, v] += coef * ax * ax
    mxy[i, v] += coef * ax * ay
    myy[i, v] += coef * ay * ay


@njit(**_OPTS)
def wheel_contacts(w, v0, nb, act, x, y, vx, vy, fx, fy, mxx, mxy, myy, ws, wp, par, omu, tab2,
                   gc, pt, cand, gcache, ncand, cinfo, wtq, wsf, sq, so, si):
    """The contacts of wheel ``w`` in the stepping lanes ``act`` of the block of ``nb``
    lanes from lane ``v0`` (see the module notes): forces and matrix terms on the pins
    (the block's ``(N, nb…)`` arrays, column ``v - v0``), ``wtq``, ``wsf`` and the wheel
    state's torque and slide force, the contacts' rows ``cinfo``. ``gc``, ``pt`` from
    :func:`._batched._wheel_constants` (``v0 % LANES + nb <= LANES``); ``tab2`` the seat
    tables ``(V W, smax, 6)``; ``sq`` ``(NQ LANES,)``, ``so`` ``(NO LANES,)``, ``si``
    ``(LANES,)`` work arrays."""
    nw = ws.shape[1]
    if nb > 0:
        blk = v0 // LANES
        off = v0 - blk * LANES
        g0 = (blk * nw + w) * NGC * LANES + off
        p0 = blk * L.NPAR * LANES + off
        maxc = 0
        for b in range(nb):
            v = v0 + b
            wtq[v, w] = 0.0
            wsf[v, w] = 0.0
            if not act[v]:
                continue
            if ncand[v, w] > maxc:
                maxc = ncand[v, w]
            th = ws[v, w, L.S_THETA]
            sq[Q_CTH * LANES + b] = math.cos(th)
            sq[Q_STH * LANES + b] = math.sin(th)
            sq[Q_CX * LANES + b] = wp[v, w, L.W_CX] + ws[v, w, L.S_S] * wp[v, w, L.W_DX]
            sq[Q_CY * LANES + b] = wp[v, w, L.W_CY] + ws[v, w, L.S_S] * wp[v, w, L.W_DY]
            sq[Q_OM * LANES + b] = omu[v, w]
            sq[Q_SD * LANES + b] = ws[v, w, L.S_SDOT]
        for ic in range(maxc):
            for b in range(nb):
                v = v0 + b
                sq[Q_ON * LANES + b] = 0.0
                sq[Q_EX * LANES + b] = 1.0
                sq[Q_EY * LANES + b] = 0.0
                sq[Q_QX * LANES + b] = 0.0
                sq[Q_QY * LANES + b] = 0.0
                sq[Q_VX * LANES + b] = 0.0
                sq[Q_VY * LANES + b] = 0.0
                if not act[v] or ic >= ncand[v, w]:
                    continue
                cinfo[v, w, ic, C_BETA] = 0.0
                cinfo[v, w, ic, C_S] = 0.0
                i = cand[v, w, ic]
                si[b] = i
                # the gather of _batched._wheel_contacts (an inlined function taking the
                # arrays would cost their reference counts per call), the rim with reach
                qx = x[i, b] - sq[Q_CX * LANES + b]
                qy = y[i, b] - sq[Q_CY * LANES + b]
                sq[Q_QX * LANES + b] = qx
                sq[Q_QY * LANES + b] = qy
                sq[Q_VX * LANES + b] = vx[i, b]
                sq[Q_VY * LANES + b] = vy[i, b]
                r2 = qx * qx + qy * qy
                if r2 > gc[g0 + G_ROUT2 * LANES + b] or r2 < gc[g0 + G_RIN2 * LANES + b]:
                    continue
                if gc[g0 + G_PLAIN * LANES + b] > 0.5:
                    pen, nx, ny, _ = C.rim_gap(qx, qy, r2, gc[g0 + G_RAD * LANES + b],
                                               0.25 * par[v, L.P_RROLLER])
                    sq[Q_ON * LANES + b] = 2.0
                    sq[Q_PEN * LANES + b] = pen
                    sq[Q_EX * LANES + b] = nx
                    sq[Q_EY * LANES + b] = ny
                    continue
                cth = sq[Q_CTH * LANES + b]
                sth = sq[Q_STH * LANES + b]
                qxw = qx * cth + qy * sth
                qyw = -qx * sth + qy * cth
                g = gcache[v, w, i]
                wv = v * nw + w
                kept = False
                ex = 1.0
                ey = 0.0
                if g >= 0:
                    ex = tab2[wv, g, 0]
                    ey = tab2[wv, g, 1]
                    ar = qxw * ex + qyw * ey
                    bt = -qxw * ey + qyw * ex
                    kept = not bt * tab2[wv, g, 2] > ar * tab2[wv, g, 3] \
                        and not -bt * tab2[wv, g, 4] > ar * tab2[wv, g, 5]
                if not kept:
                    g, ex, ey = C.nearest_seat(tab2, wv, g, int(gc[g0 + G_IZ * LANES + b]), qxw,
                                               qyw, gc[g0 + G_PA * LANES + b])
                gcache[v, w, i] = g
                sq[Q_ON * LANES + b] = 1.0
                sq[Q_EX * LANES + b] = ex
                sq[Q_EY * LANES + b] = ey
            _slot_law(sq, so, gc, g0, pt, p0, nb)
            for b in range(nb):
                if so[O_ON * LANES + b] == 0.0:
                    continue
                v = v0 + b
                i = si[b]
                # one contact on its pin, wheel and row (the single kernel's arithmetic)
                qx = sq[Q_QX * LANES + b]
                qy = sq[Q_QY * LANES + b]
                nx = so[O_NX * LANES + b]
                ny = so[O_NY * LANES + b]
                fn0 = so[O_FN0 * LANES + b]
                ft0 = so[O_FT0 * LANES + b]
                s = so[O_S * LANES + b]
                th = par[v, L.P_THETA]
                betac = th * (par[v, L.P_DT] * par[v, L.P_KC] + par[v, L.P_CC])
                ddx = wp[v, w, L.W_DX]
                ddy = wp[v, w, L.W_DY]
                fx[i, b] += -fn0 * nx - ft0 * ny
                fy[i, b] += -fn0 * ny + ft0 * nx
                mxx[i, b] += betac * nx * nx
                mxy[i, b] += betac * nx * ny
                myy[i, b] += betac * ny * ny
                mxx[i, b] += s * -ny * -ny
                mxy[i, b] += s * -ny * nx
                myy[i, b] += s * nx * nx
                lev = qx * ny - qy * nx
                levt = qx * nx + qy * ny
                wtq[v, w] += fn0 * lev - ft0 * levt
                dn = nx * ddx + ny * ddy
                dtt = -ny * ddx + nx * ddy
                wsf[v, w] += fn0 * dn - ft0 * dtt
                cinfo[v, w, ic, C_BETA] = betac
                cinfo[v, w, ic, C_S] = s
                cinfo[v, w, ic, C_NX] = nx
                cinfo[v, w, ic, C_NY] = ny
                cinfo[v, w, ic, C_L] = lev
                cinfo[v, w, ic, C_LT] = levt
                cinfo[v, w, ic, C_DN] = dn
                cinfo[v, w, ic, C_DT] = dtt
                cinfo[v, w, ic, C_FN0] = fn0
                cinfo[v, w, ic, C_FT0] = ft0
        for b in range(nb):
            v = v0 + b
            if act[v]:
                ws[v, w, L.S_TORQUE] = wtq[v, w]
                ws[v, w, L.S_SFORCE] = wsf[v, w]
