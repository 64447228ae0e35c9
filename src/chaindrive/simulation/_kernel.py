"""Compiled hot loop of the chain-drive simulation (internal).

One function, :func:`integrate`, advances the state by ``nsteps`` steps of the
symplectic (semi-implicit) Euler scheme and writes samples every ``record_every``
steps. Everything is preallocated by the caller: no allocation inside the loop.

Layout
------
pos, vel : (N, 2) pin (hinge-centre) positions [m] and velocities [m/s].
force, work : (N, 2) work arrays.
tension : (N,) link forces of the last step [N] (link i joins pin i and i+1).
contact : (N,) total normal contact force on each pin of the last step [N].
ws : (W, 7) wheel state: theta, omega, slide s, slide sdot, contact torque, slide force,
    speed of the motor behind a fluid coupling (0 without one).
wp : (W, NWP) wheel parameters (column indices ``W_*`` below).
gd : (G, 7) guides: ax, ay, ux, uy, nx, ny, length.
tab : (W, smax, 6) seat (gap) directions in the wheel frame and the cos/sin of the half
    angles to the next and to the previous seat (:func:`seat_table`).
par : parameter vector (indices ``P_*`` below).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from ._contact import (
    friction,
    guide_candidates,
    guide_mu,
    guide_penetration,
    link_force,
    material_drag,
    nearest_pin,
    penalty_contact,
    pin_contact,
    rebuild_every,
    wheel_candidates,
    wheel_geometry,
)
from ._layout import (  # noqa: F401 - the layout is part of this module's interface
    G_MM,
    G_MMU,
    G_MU,
    MODE_FREE,
    MODE_LOCKED,
    MODE_MOTOR,
    MODE_SPEED,
    NGD,
    NPAR,
    NWP,
    NWS,
    P_C,
    P_CC,
    P_CG,
    P_CGLOB,
    P_CSPAN,
    P_DT,
    P_DTREF,
    P_GX,
    P_GY,
    P_K,
    P_KC,
    P_KG,
    P_MASS,
    P_MU,
    P_PITCH,
    P_PITCH2,
    P_RROLLER,
    P_THETA,
    P_VEPS,
    S_COUPLING,
    S_MOTOR,
    S_OMEGA,
    S_S,
    S_SDOT,
    S_SFORCE,
    S_THETA,
    S_TORQUE,
    W_CEA,
    W_CEB,
    W_CPSI,
    W_CX,
    W_CY,
    W_DA,
    W_DAMP,
    W_DB,
    W_DTA,
    W_DTB,
    W_DX,
    W_DY,
    W_FCC,
    W_FCJ,
    W_FCK,
    W_FCSN,
    W_HTIP,
    W_INERTIA,
    W_MODE,
    W_MSK,
    W_MSYNC,
    W_MTK,
    W_NSEAT,
    W_OMEGA0,
    W_PLAIN,
    W_R,
    W_RAMP,
    W_RE,
    W_RIPA,
    W_RIPW,
    W_RS,
    W_SC,
    W_SF,
    W_SK,
    W_SLIDE,
    W_SMASS,
    W_SPSI,
    W_TCA,
    W_TCB,
    W_TDOWN,
    W_TORQUE,
    W_TSTOP,
    W_Z,
)


@njit(cache=True, fastmath=False, inline="always")
def drive_torque(wp, w, om, t):
    """Torque [N m] of a motor on the Kloss curve at wheel speed ``om`` and time ``t``.

    ``T = 2 T_k s s_k / (s² + s_k²)`` with the slip ``s = (ω_s − ω)/ω_s`` (Kloss), times
    ``1 + a sin(Ω t)`` (ripple); 0 once the motor is switched off.
    """
    tstop = wp[w, W_TSTOP]
    if tstop > 0.0 and t >= tstop:
        return 0.0
    ws_ = wp[w, W_MSYNC]
    sk = wp[w, W_MSK]
    s = (ws_ - om) / ws_
    tq = 2.0 * wp[w, W_MTK] * s * sk / (s * s + sk * sk)
    if wp[w, W_RIPA] != 0.0:
        tq *= 1.0 + wp[w, W_RIPA] * math.sin(wp[w, W_RIPW] * t)
    return tq


@njit(cache=True, fastmath=False, inline="always")
def fluid_coupling_torque(wp, w, om_p, om_t):
    """Torque [N m] of a constant-fill fluid coupling, primary at ``om_p``, secondary at
    ``om_t`` (:func:`chaindrive.coupling.coupling_torque`, its regular form), and its
    slope ``∂T/∂(om_p − om_t)`` [N m s] at constant ``om_p``."""
    d = om_p - om_t
    sp = wp[w, W_FCSN] * abs(om_p)
    den = sp + wp[w, W_FCC] * abs(d)
    if den <= 0.0:
        return 0.0, 0.0
    k = wp[w, W_FCK] * om_p * om_p
    return k * d / den, k * sp / (den * den)


@njit(cache=True, fastmath=False, inline="always")
def fluid_coupling_step(wp, w, om_m, om, t, tload, dt):
    """Coupling torque [N m] for the step ``t -> t + dt``: implicit in the slip.

    The coupling is a stiff damper between the motor (inertia ``J_m``) and the wheel
    (``J``); with its slope ``b`` the slip rate of the step solves
    ``δ = dt [(T_m − T_c − b δ)/J_m − (T_load + T_c + b δ)/J]``, and ``T_c + b δ`` is
    returned (backward Euler of the linearised coupling: stable for any ``dt``).
    """
    tc, b = fluid_coupling_torque(wp, w, om_m, om)
    jm = wp[w, W_FCJ]
    jw = wp[w, W_INERTIA]
    tm = drive_torque(wp, w, om_m, t)
    delta = dt * ((tm - tc) / jm - (tload + tc) / jw) / (1.0 + dt * b * (1.0 / jm + 1.0 / jw))
    return tc + b * delta


@njit(cache=True, fastmath=False, inline="always")
def wheel_drive_torque(wp, ws, w, om, t, tload, dt):
    """Torque [N m] driving wheel ``w`` (mode motor) in the step from ``t``: the motor's
    at the wheel's speed ``om``, or through a fluid coupling the coupling's
    (:func:`fluid_coupling_step`, kept in ``ws[w, S_COUPLING]`` for
    :func:`advance_motor`); ``tload`` the other torques on the wheel."""
    if wp[w, W_FCJ] > 0.0:
        tc = fluid_coupling_step(wp, w, ws[w, S_MOTOR], om, t, tload, dt)
        ws[w, S_COUPLING] = tc
        return tc
    return drive_torque(wp, w, om, t)


@njit(cache=True, fastmath=False, inline="always")
def advance_motor(wp, ws, w, t, dt):
    """The motor behind a fluid coupling over the step: ``J_m ω̇_m = T_m(ω_m) − T_c`` with
    the coupling torque of :func:`wheel_drive_torque` (once per step, after it)."""
    if wp[w, W_FCJ] > 0.0:
        om_m = ws[w, S_MOTOR]
        ws[w, S_MOTOR] = om_m + (drive_torque(wp, w, om_m, t) - ws[w, S_COUPLING]) / wp[w, W_FCJ] * dt


@njit(cache=True, fastmath=False, inline="always")
def speed_factor(wp, w, t):
    """Prescribed speed over its target: linear ramp up, hold, linear ramp down to 0."""
    ramp = wp[w, W_RAMP]
    f = 1.0
    if ramp > 0.0 and t < ramp:
        f = t / ramp
    tstop = wp[w, W_TSTOP]
    if tstop > 0.0 and t >= tstop:
        down = wp[w, W_TDOWN]
        g = 0.0 if down <= 0.0 else 1.0 - (t - tstop) / down
        if g < 0.0:
            g = 0.0
        if g < f:
            f = g
    if wp[w, W_RIPA] != 0.0:
        f *= 1.0 + wp[w, W_RIPA] * math.sin(wp[w, W_RIPW] * t)
    return f


@njit(cache=True, fastmath=False, inline="always")
def advance_wheels(wp, ws, t, dt, gx, gy):
    """The wheels over the explicit step ``t -> t + dt``: prescribed speeds, motors (and
    the motor behind a fluid coupling), free wheels under their contact torques, slides
    under their springs, dampers, contact forces and gravity (``gx``, ``gy`` [m/s²])."""
    tn = t + dt
    for w in range(ws.shape[0]):
        mode = wp[w, W_MODE]
        if mode == MODE_SPEED:
            ws[w, S_OMEGA] = wp[w, W_OMEGA0] * speed_factor(wp, w, tn)
        elif mode == MODE_MOTOR:
            tload = ws[w, S_TORQUE] + wp[w, W_TORQUE] - wp[w, W_DAMP] * ws[w, S_OMEGA]
            tc = wheel_drive_torque(wp, ws, w, ws[w, S_OMEGA], t, tload, dt)
            advance_motor(wp, ws, w, t, dt)
            ws[w, S_OMEGA] += (tload + tc) / wp[w, W_INERTIA] * dt
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


@njit(cache=True, fastmath=False)
def record_pins(x, y, vx, vy, fx, fy, hm, rest, k, m, gx, gy, epot, tension, contact,
                rec_tension, rec_contact, rec_pos, nrec):
    """Record ``nrec`` of the pins (link tensions, contact forces, positions) and their
    energies: ``(epot, ekin, egrav)``, the potential energy ``epot`` [J] plus the links'
    strain energy, the kinetic energy at the velocities ``v + hm f`` (``hm = 0``: ``v``)
    and the potential energy of gravity [J]. Shared by both single-drive kernels."""
    n = x.shape[0]
    ekin = 0.0
    egrav = 0.0
    for i in range(n):
        j = i + 1 if i + 1 < n else 0
        ddx = x[j] - x[i]
        ddy = y[j] - y[i]
        dl = math.sqrt(ddx * ddx + ddy * ddy) - rest[i]
        epot += 0.5 * k * dl * dl
        hvx = vx[i] + hm * fx[i]
        hvy = vy[i] + hm * fy[i]
        ekin += 0.5 * m * (hvx * hvx + hvy * hvy)
        egrav -= m * (gx * x[i] + gy * y[i])
        rec_tension[nrec, i] = tension[i]
        rec_contact[nrec, i] = contact[i]
        rec_pos[nrec, i, 0] = x[i]
        rec_pos[nrec, i, 1] = y[i]
    return epot, ekin, egrav


@njit(cache=True, fastmath=False, inline="always")
def pin_arrays(pos, vel, p, p2):
    """``(x, y, vx, vy, rest)``: the caller's (N, 2) positions and velocities copied into
    separate coordinate arrays, and the rest length of each link (``p`` from an even pin,
    ``p2`` from an odd one) — the state layout of both integrators."""
    n = pos.shape[0]
    rest = np.empty(n)
    for i in range(n):
        rest[i] = p if i % 2 == 0 else p2
    return pos[:, 0].copy(), pos[:, 1].copy(), vel[:, 0].copy(), vel[:, 1].copy(), rest


@njit(cache=True, fastmath=False, inline="always")
def store_pins(pos, vel, x, y, vx, vy):
    """Copy the coordinate arrays of :func:`pin_arrays` back into the caller's (N, 2) arrays."""
    for i in range(pos.shape[0]):
        pos[i, 0] = x[i]
        pos[i, 1] = y[i]
        vel[i, 0] = vx[i]
        vel[i, 1] = vy[i]


@njit(cache=True, fastmath=False, inline="always")
def candidate_arrays(nw, ng, n):
    """``(cand, gcache, ncand, gcand, ngcand)``: the pins near each wheel (with their last
    seat, -1 none yet) and near each guide, filled at the candidate rebuilds."""
    return (np.empty((nw, n), np.int64), np.full((nw, n), -1, np.int64), np.zeros(nw, np.int64),
            np.empty((ng, n), np.int64), np.zeros(ng, np.int64))


@njit(cache=True, fastmath=False)
def integrate(pos, vel, force, work, tension, contact, ws, wp, gd, tab, par, t0, nsteps, record_every,
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
    p2 = par[P_PITCH2]
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
    cspan = par[P_CSPAN] * m
    inv_m = 1.0 / m
    nrec = rec_start
    margin = 0.25 * rr
    # pins near each wheel and each guide, listed at the same rebuilds
    cand, gcache, ncand, gcand, ngcand = candidate_arrays(nw, ng, n)
    # material carried by a pin this step: mass [kg] and the pan's unit tangent
    extra = np.zeros((n, 5))
    countdown = 0
    vmax_s = 0.0
    fgx = m * gx
    fgy = m * gy
    cm = cglob * m
    # separate coordinate arrays (the caller's (N, 2) arrays copied in and out), rest
    # lengths per link; (fx, fy) hold the contact forces only (zero between steps); link,
    # gravity and damping forces are added in the update loop; `force`, `work` unused
    x, y, vx, vy, rest = pin_arrays(pos, vel, p, p2)
    fx = np.zeros(n)
    fy = np.zeros(n)
    wkx = np.zeros(n + 1)
    wky = np.zeros(n + 1)
    carrying = False
    for i in range(n):
        contact[i] = 0.0
    for step in range(nsteps):
        t = t0 + step * dt
        epot = 0.0
        # links: axial spring-damper between consecutive pins (closed loop); first the
        # link forces (independent iterations, vectorised: separate x/y arrays, rest
        # lengths per link), then the pin forces
        for i in range(n - 1):
            tt, ux, uy, _ = link_force(x[i + 1] - x[i], y[i + 1] - y[i], vx[i + 1] - vx[i],
                                       vy[i + 1] - vy[i], k, c, rest[i])
            tension[i] = tt
            wkx[i + 1] = tt * ux
            wky[i + 1] = tt * uy
        tt, ux, uy, _ = link_force(x[0] - x[n - 1], y[0] - y[n - 1], vx[0] - vx[n - 1],
                                   vy[0] - vy[n - 1], k, c, rest[n - 1])
        tension[n - 1] = tt
        wkx[n] = tt * ux
        wky[n] = tt * uy
        wkx[0] = wkx[n]
        wky[0] = wky[n]
        if cspan > 0.0:
            span_damping_forces(x, y, vx, vy, fx, fy, cspan)
        # wheels: penalty contact of each roller with the nearest tooth gap; the pins
        # near each wheel are listed every `countdown` steps, often enough that no pin
        # can cover the margin in between (4 x the fastest relative speed)
        rebuild = countdown <= 0
        if rebuild:
            countdown, vmax_s = rebuild_every(vx, vy, ws, margin, dt, vmax_s)
        countdown -= 1
        for w in range(nw):
            geo = wheel_geometry(wp, ws, w, rr)
            cx = geo[0]
            cy = geo[1]
            om = ws[w, S_OMEGA]
            sd = ws[w, S_SDOT]
            tq = 0.0
            fwx = 0.0
            fwy = 0.0
            if rebuild:
                # candidate pins: those that can come within reach before the next rebuild
                rc = geo[10] + margin
                wheel_candidates(x, y, cx, cy, rc * rc, cand, gcache, ncand, w)
            for ic in range(ncand[w]):
                i = cand[w, ic]
                pen, nx, ny, _curv, qx, qy, g = pin_contact(x[i], y[i], cx, cy, geo, tab, w, gcache[w, i],
                                                            rr, 0.0)
                gcache[w, i] = g
                if pen <= 0.0:
                    continue
                fn, cfx, cfy = penalty_contact(kc, cc, mu, dtref, inv_m, veps, pen, nx, ny,
                                               vx[i] - (-om * qy + sd * wp[w, W_DX]),
                                               vy[i] - (om * qx + sd * wp[w, W_DY]))
                epot += 0.5 * kc * pen * pen
                fx[i] += cfx
                fy[i] += cfy
                contact[i] += fn
                tq -= qx * cfy - qy * cfx
                fwx -= cfx
                fwy -= cfy
            ws[w, S_TORQUE] = tq
            ws[w, S_SFORCE] = fwx * wp[w, W_DX] + fwy * wp[w, W_DY]
        # guides: one-sided penalty contact of the roller with a line segment whose end
        # points act as corners (distance to the segment, clamped to its ends): a roller
        # rolls round a guide's end instead of dropping off it, and a polyline of
        # segments bent away from the chain is a continuous surface
        for g in range(ng):
            if rebuild:
                # candidates: pins within reach of the segment (distance < r + margin)
                guide_candidates(x, y, gd, g, rr + margin, gcand, ngcand)
            for ic in range(ngcand[g]):
                i = gcand[g, ic]
                pen, mx, my = guide_penetration(x[i], y[i], gd, g, rr)
                if pen <= 0.0:
                    continue
                vn = vx[i] * mx + vy[i] * my
                fn = kg * pen - cg * vn
                if fn < 0.0:
                    fn = 0.0
                epot += 0.5 * kg * pen * pen
                # tangent (my, -mx): the segment direction on its face
                vt = vx[i] * my - vy[i] * mx
                ft, _ = friction(guide_mu(gd, g, mu), fn, vt, dtref, inv_m, veps)
                if gd[g, G_MM] > 0.0:
                    # material scraped along a pan by this pin (material_drag); its
                    # inertia in the pin's update (extra mass along the pan)
                    ft += material_drag(gd, g, gx, gy, mx, my, vt, dtref, inv_m, veps)[0]
                    extra[i, 0] = gd[g, G_MM]
                    extra[i, 3] = vx[i]
                    extra[i, 4] = vy[i]
                    carrying = True
                    extra[i, 1] = my
                    extra[i, 2] = -mx
                fx[i] += fn * mx + ft * my
                fy[i] += fn * my - ft * mx
                contact[i] += fn
        # record (state at time t, forces of this step)
        assembled = False
        if step % record_every == 0 and nrec < rec_t.shape[0]:
            assembled = True
            for i in range(n):
                fx[i] += fgx - cm * vx[i] + wkx[i + 1] - wkx[i]
                fy[i] += fgy - cm * vy[i] + wky[i + 1] - wky[i]
            # velocities at time t (mid-point of the two half-step velocities), so that
            # the energy estimate is second order
            hm = 0.5 * dt / m
            epot, ekin, egrav = record_pins(x, y, vx, vy, fx, fy, hm, rest, k, m, gx, gy, epot,
                                            tension, contact, rec_tension, rec_contact, rec_pos,
                                            nrec)
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
                for col in range(ws.shape[1]):
                    rec_ws[nrec, w, col] = ws[w, col]
            rec_energy[nrec] = ekin + epot + egrav
            rec_t[nrec] = t
            for q in range(npr):
                ib = nearest_pin(x, y, probes[q, 0], probes[q, 1])
                rec_probe[nrec, q] = (vx[ib] + hm * fx[ib]) * probes[q, 2] \
                    + (vy[ib] + hm * fy[ib]) * probes[q, 3]
            nrec += 1
        # integrate pins: semi-implicit (symplectic) Euler; the force of link i is
        # (wkx, wky)[i + 1] (index 0 repeats the closing link's), so pin i gets
        # wk[i + 1] - wk[i] without a branch; the material's inertia in a second pass
        hdt = inv_m * dt
        if assembled:
            for i in range(n):
                vx[i] += fx[i] * hdt
                vy[i] += fy[i] * hdt
        else:
            for i in range(n):
                vx[i] += (fx[i] + fgx - cm * vx[i] + wkx[i + 1] - wkx[i]) * hdt
                vy[i] += (fy[i] + fgy - cm * vy[i] + wky[i + 1] - wky[i]) * hdt
        if carrying:
            for i in range(n):
                if extra[i, 0] > 0.0:
                    _carry(vx, vy, extra, i, m)
            carrying = False
        for i in range(n):
            x[i] += vx[i] * dt
            y[i] += vy[i] * dt
            fx[i] = 0.0
            fy[i] = 0.0
            contact[i] = 0.0
        advance_wheels(wp, ws, t, dt, gx, gy)
    store_pins(pos, vel, x, y, vx, vy)
    return nrec


@njit(cache=True, fastmath=False, inline="always")
def neighbour_chord(x, y, i):
    """``(tx, ty, 1/|t|²)``: the chord ``t`` from pin ``i``'s previous neighbour to its next
    (closed loop)."""
    n = x.shape[0]
    a = i - 1 if i > 0 else n - 1
    b = i + 1 if i < n - 1 else 0
    tx = x[b] - x[a]
    ty = y[b] - y[a]
    return tx, ty, 1.0 / (tx * tx + ty * ty)


@njit(cache=True, fastmath=False)
def span_damping_forces(x, y, vx, vy, fx, fy, cspan):
    """Add the transverse span damping ``−α m v_⊥`` to ``(fx, fy)``: ``v_⊥`` the pin's
    velocity normal to the chord of its two neighbours (``cspan = α m`` [N s/m]).

    On an axially moving string the velocity normal to the local tangent is, to first
    order, the Eulerian transverse velocity ``∂y/∂t`` (the material velocity is
    ``(V, ∂y/∂t + V ∂y/∂x)``, the tangent ``(1, ∂y/∂x)``): the force is the viscous term
    ``−c ∂y/∂t`` of the damped travelling string (Mahalingam 1957, eq. (1) with its
    damping coefficient ``c``; Wickert & Mote 1990). A pin seated on a rotating wheel
    moves along that chord (zero force), so does a straight span's axial motion. Each
    transverse mode ``n`` of a span gets the damping ratio ``ζ_n = α / (2 ω_n)``.
    """
    for i in range(x.shape[0]):
        tx, ty, inv = neighbour_chord(x, y, i)
        vn = (vx[i] * ty - vy[i] * tx)
        # v_perp = vn * (ty, -tx) / |t|^2
        fx[i] -= cspan * vn * ty * inv
        fy[i] += cspan * vn * tx * inv


@njit(cache=True, fastmath=False, inline="always")
def _carry(vx, vy, extra, i, m):
    """Pin ``i`` carries material of mass ``extra[i, 0]`` along the pan tangent
    ``extra[i, 1:3]``: its velocity change along the pan this step is that of
    ``m + m_material`` (``extra[i, 3:5]``: its velocity before the step)."""
    tx = extra[i, 1]
    ty = extra[i, 2]
    dvt = (vx[i] - extra[i, 3]) * tx + (vy[i] - extra[i, 4]) * ty
    corr = dvt * extra[i, 0] / (m + extra[i, 0])
    vx[i] -= corr * tx
    vy[i] -= corr * ty
    extra[i, 0] = 0.0


def seat_table(wp):
    """(W, smax, 6) seat table of each wheel, in the wheel frame.

    Columns: unit vector of seat ``g`` (tooth-gap or pocket-hinge centre direction),
    then ``cos h``, ``sin h`` of the half central angle to seat ``g + 1`` and to seat
    ``g - 1``. Seat 0 lies at angle 0; seat ``g`` is followed by the central angle
    ``W_DA`` (``g`` even) or ``W_DB`` (``g`` odd). A sprocket (``W_DA = W_DB = 2π/z``)
    has the regular spacing ``2πg/z`` and half angles ``π/z``; a pocket wheel the
    bi-regular vertices of Dolipiński et al. eq. (6) (``δ1``, ``δ2`` alternating).
    """
    ns = wp[:, W_NSEAT].astype(np.int64)
    tab = np.zeros((len(ns), int(ns.max()), 6))
    for w, n in enumerate(ns):
        da, db = float(wp[w, W_DA]), float(wp[w, W_DB])
        if da == db:
            a = 2 * np.pi * np.arange(n) / n
            hn = hp = np.full(n, math.pi / n)
        else:
            steps = np.where(np.arange(n) % 2 == 0, da, db)
            a = np.concatenate([[0.0], np.cumsum(steps[:-1])])
            hn = 0.5 * steps
            hp = 0.5 * np.roll(steps, 1)
        tab[w, :n, 0] = np.cos(a)
        tab[w, :n, 1] = np.sin(a)
        # scalar math.cos/sin: the same values the kernel computed inline before
        tab[w, :n, 2] = [math.cos(h) for h in hn]
        tab[w, :n, 3] = [math.sin(h) for h in hn]
        tab[w, :n, 4] = [math.cos(h) for h in hp]
        tab[w, :n, 5] = [math.sin(h) for h in hp]
    return tab


def empty_records(n_records, n_pins, n_wheels, n_probes):
    """Preallocated record arrays for :func:`integrate`."""
    return (np.zeros(n_records), np.zeros((n_records, n_probes)), np.zeros((n_records, n_pins)),
            np.zeros((n_records, n_pins)), np.zeros((n_records, n_wheels, NWS)),
            np.zeros((n_records, n_pins, 2)), np.zeros(n_records))
