"""Compiled hot loop of the chain-drive simulation (internal).

One function, :func:`integrate`, advances the state by ``nsteps`` steps of the
symplectic (semi-implicit) Euler scheme and writes samples every ``record_every``
steps. Everything is preallocated by the caller: no allocation inside the loop.

Layout
------
pos, vel : (N, 2) pin (hinge-centre) positions [m] and velocities [m/s].
force : (N, 2) work array.
tension : (N,) link forces of the last step [N] (link i joins pin i and i+1).
contact : (N,) total normal contact force on each pin of the last step [N].
ws : (W, 6) wheel state: theta, omega, slide s, slide sdot, contact torque, slide force.
wp : (W, NWP) wheel parameters (column indices ``W_*`` below).
gd : (G, 7) guides: ax, ay, ux, uy, nx, ny, length.
par : parameter vector (indices ``P_*`` below).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

# wheel parameter columns
W_CX, W_CY, W_R, W_Z, W_RS, W_CPSI, W_SPSI, W_HTIP, W_INERTIA, W_MODE, W_OMEGA0, W_RAMP, \
    W_TORQUE, W_DAMP, W_SLIDE, W_DX, W_DY, W_SMASS, W_SK, W_SC, W_SF = range(21)
NWP = 21
# wheel state columns
S_THETA, S_OMEGA, S_S, S_SDOT, S_TORQUE, S_SFORCE = range(6)
# parameter vector
P_MASS, P_K, P_C, P_PITCH, P_RROLLER, P_KC, P_CC, P_MU, P_VEPS, P_GX, P_GY, P_DT, P_CGLOB, \
    P_KG, P_CG, P_DTREF = range(16)
NPAR = 16
# wheel modes
MODE_SPEED, MODE_FREE, MODE_LOCKED = 0, 1, 2


@njit(cache=True, fastmath=False)
def integrate(pos, vel, force, tension, contact, ws, wp, gd, par, t0, nsteps, record_every,
              probes, rec_t, rec_probe, rec_tension, rec_contact, rec_ws, rec_pos, rec_energy,
              rec_start):
    """Advance ``nsteps`` steps from time ``t0``; return the number of records written."""
    n = pos.shape[0]
    nw = ws.shape[0]
    ng = gd.shape[0]
    npr = probes.shape[0]
    m = par[P_MASS]
    k = par[P_K]
    c = par[P_C]
    p = par[P_PITCH]
    rr = par[P_RROLLER]
    kc = par[P_KC]
    cc = par[P_CC]
    mu = par[P_MU]
    veps = par[P_VEPS]
    gx = par[P_GX]
    gy = par[P_GY]
    dt = par[P_DT]
    cglob = par[P_CGLOB]
    kg = par[P_KG]
    cg = par[P_CG]
    dtref = par[P_DTREF]
    twopi = 2.0 * math.pi
    inv_m = 1.0 / m
    nrec = rec_start
    for step in range(nsteps):
        t = t0 + step * dt
        epot = 0.0
        for i in range(n):
            force[i, 0] = m * gx - cglob * m * vel[i, 0]
            force[i, 1] = m * gy - cglob * m * vel[i, 1]
            contact[i] = 0.0
        # links: axial spring-damper between consecutive pins (closed loop)
        for i in range(n):
            j = i + 1
            if j == n:
                j = 0
            dx = pos[j, 0] - pos[i, 0]
            dy = pos[j, 1] - pos[i, 1]
            ll = math.sqrt(dx * dx + dy * dy)
            ux = dx / ll
            uy = dy / ll
            dl = ll - p
            ldot = (vel[j, 0] - vel[i, 0]) * ux + (vel[j, 1] - vel[i, 1]) * uy
            tt = k * dl + c * ldot
            tension[i] = tt
            epot += 0.5 * k * dl * dl
            force[i, 0] += tt * ux
            force[i, 1] += tt * uy
            force[j, 0] -= tt * ux
            force[j, 1] -= tt * uy
        # wheels: penalty contact of each roller with the nearest tooth gap
        for w in range(nw):
            cx = wp[w, W_CX] + ws[w, S_S] * wp[w, W_DX]
            cy = wp[w, W_CY] + ws[w, S_S] * wp[w, W_DY]
            theta = ws[w, S_THETA]
            om = ws[w, S_OMEGA]
            sd = ws[w, S_SDOT]
            rad = wp[w, W_R]
            z = wp[w, W_Z]
            delta = wp[w, W_RS] - rr
            cps = wp[w, W_CPSI]
            sps = wp[w, W_SPSI]
            htip = wp[w, W_HTIP]
            rout = rad + htip + rr
            rin = rad - wp[w, W_RS] - rr
            if rin < 0.0:
                rin = 0.0
            rout2 = rout * rout
            rin2 = rin * rin
            pitch_angle = twopi / z
            # tooth corner (in roller-centre coordinates a, |b|): end of the flank at the
            # tip height plus one roller radius along the flank normal
            stip = (htip + delta * cps) / sps
            tca = -delta * cps + stip * sps - rr * cps
            tcb = delta * sps + stip * cps + rr * sps
            tq = 0.0
            fwx = 0.0
            fwy = 0.0
            for i in range(n):
                qx = pos[i, 0] - cx
                qy = pos[i, 1] - cy
                r2 = qx * qx + qy * qy
                if r2 > rout2 or r2 < rin2:
                    continue
                ang = math.atan2(qy, qx) - theta
                gap = math.floor(ang / pitch_angle + 0.5)
                beta = theta + gap * pitch_angle
                erx = math.cos(beta)
                ery = math.sin(beta)
                a = qx * erx + qy * ery - rad
                b = -qx * ery + qy * erx
                ab = abs(b)
                sb = 1.0 if b >= 0.0 else -1.0
                # position along the flank from the end of the seating arc
                sf = (a + delta * cps) * sps + (ab - delta * sps) * cps
                if sf > stip:
                    # beyond the tooth tip: roller against the rounded tooth corner
                    ta = a - tca
                    tb = ab - tcb
                    d = math.sqrt(ta * ta + tb * tb)
                    pen = rr - d
                    if pen <= 0.0:
                        continue
                    na = -ta / d
                    nb = -sb * tb / d
                elif ab * cps + a * sps <= 0.0:
                    d = math.sqrt(a * a + b * b)
                    pen = d - delta
                    if pen <= 0.0:
                        continue
                    na = a / d
                    nb = b / d
                else:
                    pen = -a * cps + ab * sps - delta
                    if pen <= 0.0:
                        continue
                    na = -cps
                    nb = sb * sps
                nx = na * erx - nb * ery
                ny = na * ery + nb * erx
                rvx = vel[i, 0] - (-om * qy + sd * wp[w, W_DX])
                rvy = vel[i, 1] - (om * qx + sd * wp[w, W_DY])
                vn = rvx * nx + rvy * ny
                fn = kc * pen + cc * vn
                if fn < 0.0:
                    fn = 0.0
                epot += 0.5 * kc * pen * pen
                vt = -rvx * ny + rvy * nx
                # regularised Coulomb; the slope mu fn / ve is capped at m / dt so that the
                # explicit step stays stable; capped with the model's reference step, not the
                # actual one, so that the law does not change when dt is refined
                ve = mu * fn * dtref * inv_m
                if ve < veps:
                    ve = veps
                ft = -mu * fn * math.tanh(vt / ve)
                fx = -fn * nx - ft * ny
                fy = -fn * ny + ft * nx
                force[i, 0] += fx
                force[i, 1] += fy
                contact[i] += fn
                tq -= qx * fy - qy * fx
                fwx -= fx
                fwy -= fy
            ws[w, S_TORQUE] = tq
            ws[w, S_SFORCE] = fwx * wp[w, W_DX] + fwy * wp[w, W_DY]
        # guides: one-sided penalty contact of the roller with a line segment
        for g in range(ng):
            ax = gd[g, 0]
            ay = gd[g, 1]
            ux = gd[g, 2]
            uy = gd[g, 3]
            nx = gd[g, 4]
            ny = gd[g, 5]
            length = gd[g, 6]
            for i in range(n):
                rx = pos[i, 0] - ax
                ry = pos[i, 1] - ay
                s = rx * ux + ry * uy
                if s < 0.0 or s > length:
                    continue
                h = rx * nx + ry * ny
                pen = rr - h
                if pen <= 0.0 or h < -rr:
                    continue
                vn = vel[i, 0] * nx + vel[i, 1] * ny
                fn = kg * pen - cg * vn
                if fn < 0.0:
                    fn = 0.0
                epot += 0.5 * kg * pen * pen
                vt = vel[i, 0] * ux + vel[i, 1] * uy
                ve = mu * fn * dtref * inv_m
                if ve < veps:
                    ve = veps
                ft = -mu * fn * math.tanh(vt / ve)
                force[i, 0] += fn * nx + ft * ux
                force[i, 1] += fn * ny + ft * uy
                contact[i] += fn
        # record (state at time t, forces of this step)
        if step % record_every == 0 and nrec < rec_t.shape[0]:
            # velocities at time t (mid-point of the two half-step velocities), so that
            # the energy estimate is second order
            hm = 0.5 * dt / m
            ekin = 0.0
            egrav = 0.0
            for i in range(n):
                vx = vel[i, 0] + hm * force[i, 0]
                vy = vel[i, 1] + hm * force[i, 1]
                ekin += 0.5 * m * (vx * vx + vy * vy)
                egrav -= m * (gx * pos[i, 0] + gy * pos[i, 1])
                rec_tension[nrec, i] = tension[i]
                rec_contact[nrec, i] = contact[i]
                rec_pos[nrec, i, 0] = pos[i, 0]
                rec_pos[nrec, i, 1] = pos[i, 1]
            for w in range(nw):
                om = ws[w, S_OMEGA]
                if wp[w, W_MODE] == MODE_FREE:
                    om += 0.5 * dt * (ws[w, S_TORQUE] + wp[w, W_TORQUE]
                                      - wp[w, W_DAMP] * ws[w, S_OMEGA]) / wp[w, W_INERTIA]
                ekin += 0.5 * wp[w, W_INERTIA] * om * om
                if wp[w, W_SLIDE] > 0.0:
                    dxw = wp[w, W_DX]
                    dyw = wp[w, W_DY]
                    fs = ws[w, S_SFORCE] + wp[w, W_SF] - wp[w, W_SK] * ws[w, S_S] \
                        - wp[w, W_SC] * ws[w, S_SDOT] + wp[w, W_SMASS] * (gx * dxw + gy * dyw)
                    sv = ws[w, S_SDOT] + 0.5 * dt * fs / wp[w, W_SMASS]
                    ekin += 0.5 * wp[w, W_SMASS] * sv * sv
                    epot += 0.5 * wp[w, W_SK] * ws[w, S_S] ** 2 - wp[w, W_SF] * ws[w, S_S]
                    egrav -= wp[w, W_SMASS] * (gx * dxw + gy * dyw) * ws[w, S_S]
                for col in range(6):
                    rec_ws[nrec, w, col] = ws[w, col]
            rec_energy[nrec] = ekin + epot + egrav
            rec_t[nrec] = t
            for q in range(npr):
                best = 1e300
                ib = 0
                for i in range(n):
                    ddx = pos[i, 0] - probes[q, 0]
                    ddy = pos[i, 1] - probes[q, 1]
                    dd = ddx * ddx + ddy * ddy
                    if dd < best:
                        best = dd
                        ib = i
                rec_probe[nrec, q] = (vel[ib, 0] + hm * force[ib, 0]) * probes[q, 2] \
                    + (vel[ib, 1] + hm * force[ib, 1]) * probes[q, 3]
            nrec += 1
        # integrate pins: semi-implicit (symplectic) Euler
        for i in range(n):
            vel[i, 0] += force[i, 0] * inv_m * dt
            vel[i, 1] += force[i, 1] * inv_m * dt
            pos[i, 0] += vel[i, 0] * dt
            pos[i, 1] += vel[i, 1] * dt
        # wheels
        tn = t + dt
        for w in range(nw):
            mode = wp[w, W_MODE]
            if mode == MODE_SPEED:
                ramp = wp[w, W_RAMP]
                f = 1.0
                if ramp > 0.0 and tn < ramp:
                    f = tn / ramp
                ws[w, S_OMEGA] = wp[w, W_OMEGA0] * f
            elif mode == MODE_FREE:
                acc = (ws[w, S_TORQUE] + wp[w, W_TORQUE] - wp[w, W_DAMP] * ws[w, S_OMEGA]) \
                    / wp[w, W_INERTIA]
                ws[w, S_OMEGA] += acc * dt
            else:
                ws[w, S_OMEGA] = 0.0
            ws[w, S_THETA] += ws[w, S_OMEGA] * dt
            if wp[w, W_SLIDE] > 0.0:
                dxw = wp[w, W_DX]
                dyw = wp[w, W_DY]
                fs = ws[w, S_SFORCE] + wp[w, W_SF] - wp[w, W_SK] * ws[w, S_S] \
                    - wp[w, W_SC] * ws[w, S_SDOT] + wp[w, W_SMASS] * (gx * dxw + gy * dyw)
                ws[w, S_SDOT] += fs / wp[w, W_SMASS] * dt
                ws[w, S_S] += ws[w, S_SDOT] * dt
    return nrec


def empty_records(n_records, n_pins, n_wheels, n_probes):
    """Preallocated record arrays for :func:`integrate`."""
    return (np.zeros(n_records), np.zeros((n_records, n_probes)), np.zeros((n_records, n_pins)),
            np.zeros((n_records, n_pins)), np.zeros((n_records, n_wheels, 6)),
            np.zeros((n_records, n_pins, 2)), np.zeros(n_records))
