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

# wheel parameter columns
W_CX, W_CY, W_R, W_Z, W_RS, W_CPSI, W_SPSI, W_HTIP, W_INERTIA, W_MODE, W_OMEGA0, W_RAMP, \
    W_TORQUE, W_DAMP, W_SLIDE, W_DX, W_DY, W_SMASS, W_SK, W_SC, W_SF, W_NSEAT, W_DA, W_DB, \
    W_PLAIN, W_RE, W_CEA, W_CEB, W_TCA, W_TCB, W_DTA, W_DTB, W_MSYNC, W_MTK, W_MSK, W_RIPA, W_RIPW, \
    W_TSTOP, W_TDOWN, W_FCK, W_FCSN, W_FCC, W_FCJ = range(43)
NWP = 43
# time-varying drive: W_MSYNC, W_MTK, W_MSK synchronous speed [rad/s], breakdown torque [N m]
# and breakdown slip of a motor on the Kloss curve (MODE_MOTOR, reduced to the wheel);
# W_RIPA, W_RIPW relative amplitude and angular frequency [rad/s] of a torque ripple;
# W_TSTOP, W_TDOWN: from W_TSTOP [s] the motor is off (MODE_MOTOR) or the prescribed
# speed falls linearly to 0 over W_TDOWN [s] (MODE_SPEED); W_TSTOP <= 0: never
# W_FCJ > 0: the motor drives through a constant-fill fluid coupling (chaindrive.coupling):
# the motor rotor and coupling primary (inertia W_FCJ [kg m²], speed S_MOTOR) are their own
# degree of freedom; W_FCK = T_n (1 + c)/ω_n², W_FCSN = s_n, W_FCC = c (coupling_torque)
# W_RE > 0: ISO 606 convex flank arc of radius r_e (sprockets): its centre (W_CEA, W_CEB)
# and the tooth corner (W_TCA, W_TCB) in gap coordinates (a, |b|), the unit direction
# (W_DTA, W_DTB) from the flank centre to the corner; W_RE = 0: straight flank (pockets)
# W_PLAIN: 1 for a toothless idler (roller centres on the circle of radius W_R)
# W_NSEAT: number of seats per turn (z for a sprocket, 2z for a pocket wheel); W_DA, W_DB:
# central angles [rad] spanned by an even link (pins 2k, 2k+1) and an odd link when seated
# wheel state columns
S_THETA, S_OMEGA, S_S, S_SDOT, S_TORQUE, S_SFORCE, S_MOTOR, S_COUPLING = range(8)
NWS = 8
# S_MOTOR: speed of the motor behind a fluid coupling; S_COUPLING: the coupling's torque
# on the wheel in the last step (both 0 without a coupling)
# parameter vector
P_MASS, P_K, P_C, P_PITCH, P_RROLLER, P_KC, P_CC, P_MU, P_VEPS, P_GX, P_GY, P_DT, P_CGLOB, \
    P_KG, P_CG, P_DTREF, P_PITCH2, P_THETA = range(18)
NPAR = 18
# P_THETA: implicitness θ of the linearly implicit integrator (forces evaluated at
# x + θ h v⁺); unused by the explicit kernel
# P_PITCH: rest length of the even links (i = 0, 2, ...); P_PITCH2: of the odd links
# (equal for a roller chain; t + d and t - d for a round link chain)
# wheel modes
MODE_SPEED, MODE_FREE, MODE_LOCKED, MODE_MOTOR = 0, 1, 2, 3
# guide table columns: ax, ay, ux, uy, nx, ny, length, friction (< 0: the model's), material
# mass per pin [kg] scraped along the guide, its friction coefficient
G_MU, G_MM, G_MMU = 7, 8, 9
NGD = 10


@njit(cache=True, fastmath=False, inline="always")
def _fast_atan2(y, x):
    """atan2 to about 1e-5 rad (polynomial on [0, 1]), in (-π, π]."""
    ax = abs(x)
    ay = abs(y)
    mx = ax if ax > ay else ay
    mn = ay if ax > ay else ax
    if mx == 0.0:
        return 0.0
    t = mn / mx
    s = t * t
    r = ((-0.0464964749 * s + 0.15931422) * s - 0.327622764) * s * t + t
    if ay > ax:
        r = 1.5707963267948966 - r
    if x < 0.0:
        r = 3.141592653589793 - r
    if y < 0.0:
        r = -r
    return r


@njit(cache=True, fastmath=False, inline="always")
def _sat(x):
    """Saturation ``clip(x, -1, 1)``: the regularised Coulomb law (linear below v_ε)."""
    if x > 1.0:
        return 1.0
    if x < -1.0:
        return -1.0
    return x


@njit(cache=True, fastmath=False, inline="always")
def _segment_frame(rx, ry, ux, uy, nx, ny):
    """Offset ``h`` along the normal and position ``s`` along a segment of ``(rx, ry)``."""
    return rx * nx + ry * ny, rx * ux + ry * uy


@njit(cache=True, fastmath=False, inline="always")
def wheel_profile(wp, w, rr):
    """Constants of wheel ``w``'s seat profile for a roller (bar) of radius ``rr``.

    Returns ``(delta, cps, sps, re, arcflank, cea, ceb, dta, dtb, tca, tcb, stip)``:
    seat clearance ``r_s − r``, cos/sin of the half seating angle, flank arc radius (0:
    straight flank) and centre, the unit direction from the flank centre to the tooth
    corner, the corner ``(a, |b|)`` and (straight flank) the corner's position along the
    flank.
    """
    delta = wp[w, W_RS] - rr
    cps = wp[w, W_CPSI]
    sps = wp[w, W_SPSI]
    htip = wp[w, W_HTIP]
    re = wp[w, W_RE]
    arcflank = re > 0.0
    cea = wp[w, W_CEA]
    ceb = wp[w, W_CEB]
    dta = wp[w, W_DTA]
    dtb = wp[w, W_DTB]
    if arcflank:
        tca = wp[w, W_TCA]
        tcb = wp[w, W_TCB]
        stip = 0.0
    else:
        # straight flank: the tooth corner (a, |b|) where the roller centre riding
        # on the flank reaches the tip height
        stip = (htip + delta * cps) / sps
        tca = -delta * cps + stip * sps - rr * cps
        tcb = delta * sps + stip * cps + rr * sps
    return delta, cps, sps, re, arcflank, cea, ceb, dta, dtb, tca, tcb, stip


@njit(cache=True, fastmath=False, inline="always")
def nearest_seat(tab, w, g, iz, qxw, qyw):
    """Seat of wheel ``w`` nearest to the point ``(qxw, qyw)`` (wheel frame), from seat ``g``.

    Moves by whole seats while the point lies beyond the boundary half-way to the next
    (previous) seat, at the half central angle ``h``: ``b cos h > a sin h``. Returns the
    seat and its unit direction ``(ex, ey)``.
    """
    ex = tab[w, g, 0]
    ey = tab[w, g, 1]
    for _it in range(iz):
        ex = tab[w, g, 0]
        ey = tab[w, g, 1]
        ar = qxw * ex + qyw * ey
        bt = -qxw * ey + qyw * ex
        if bt * tab[w, g, 2] > ar * tab[w, g, 3]:
            g = g + 1 if g + 1 < iz else 0
        elif -bt * tab[w, g, 4] > ar * tab[w, g, 5]:
            g = g - 1 if g > 0 else iz - 1
        else:
            break
    return g, ex, ey


@njit(cache=True, fastmath=False, inline="always")
def seat_penetration(a, b, rr, delta, cps, sps, re, arcflank, cea, ceb, dta, dtb, tca, tcb,
                     stip, reach=0.0):
    """Penetration ``pen`` [m] of a roller at ``(a, b)`` in its gap frame, outward normal.

    Returns ``(pen, na, nb, curvature)``; no contact when ``pen <= 0`` (the other values
    are then 0). The normal ``(na, nb)`` is the direction in which ``pen`` grows (the
    force on the roller is ``−k_c pen n``); ``curvature`` [1/m] is that of the gap
    function along the tangent (``+1/d`` on the concave seat arc, ``−1/d`` on the convex
    flank arc and the tooth corner, 0 on a straight flank), for the static solver.
    ``reach`` > 0: the normal also for a gap ``0 <= −pen < reach`` (the implicit
    integrator's contacts that close within a step).
    """
    ab = abs(b)
    sb = 1.0 if b >= 0.0 else -1.0
    # past the flank: the roller against the tooth corner
    va = a - cea
    vb = ab - ceb
    if arcflank:
        past = ab * cps + a * sps > 0.0 and va * dtb - vb * dta < 0.0
    else:
        # position along the flank from the end of the seating arc
        past = (a + delta * cps) * sps + (ab - delta * sps) * cps > stip
    if past:
        # beyond the tooth tip: roller against the rounded tooth corner
        ta = a - tca
        tb = ab - tcb
        d = math.sqrt(ta * ta + tb * tb)
        pen = rr - d
        if pen <= -reach:
            return pen, 0.0, 0.0, 0.0
        return pen, -ta / d, -sb * tb / d, -1.0 / d
    if ab * cps + a * sps <= 0.0:
        d = math.sqrt(a * a + b * b)
        pen = d - delta
        if pen <= -reach or d == 0.0:
            return pen, 0.0, 0.0, 0.0
        return pen, a / d, b / d, 1.0 / d
    if arcflank:
        # outside the convex ISO flank arc (radius r_e about C_e)
        dv = math.sqrt(va * va + vb * vb)
        pen = re + rr - dv
        if pen <= -reach:
            return pen, 0.0, 0.0, 0.0
        return pen, -va / dv, -sb * vb / dv, -1.0 / dv
    pen = -a * cps + ab * sps - delta
    if pen <= -reach:
        return pen, 0.0, 0.0, 0.0
    return pen, -cps, sb * sps, 0.0


@njit(cache=True, fastmath=False, inline="always")
def guide_penetration(px, py, gd, g, rr, reach=0.0):
    """Penetration ``pen`` [m] of a roller at ``(px, py)`` into guide ``g``, and the normal.

    The distance is taken to the segment clamped to its ends (a guide's end is a corner
    the roller rolls round). Returns ``(pen, mx, my)``: the force on the roller is
    ``k_g pen m``; no contact when ``pen <= 0``. ``reach`` > 0: the normal also for a gap
    ``0 <= −pen < reach`` (the implicit integrator).
    """
    h, s = _segment_frame(px - gd[g, 0], py - gd[g, 1], gd[g, 2], gd[g, 3], gd[g, 4], gd[g, 5])
    rmax = rr + reach
    if h < -rr or h >= rmax:
        return -1.0 - reach, 0.0, 0.0
    length = gd[g, 6]
    if s < 0.0 or s > length:
        es = s if s < 0.0 else s - length
        d2 = es * es + h * h
        if d2 >= rmax * rmax or d2 < 1e-24:
            return -1.0 - reach, 0.0, 0.0
        d = math.sqrt(d2)
        return rr - d, (es * gd[g, 2] + h * gd[g, 4]) / d, (es * gd[g, 3] + h * gd[g, 5]) / d
    return rr - h, gd[g, 4], gd[g, 5]


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
    twopi = 2.0 * math.pi
    inv_m = 1.0 / m
    nrec = rec_start
    margin = 0.25 * rr
    cand = np.empty((nw, n), np.int64)
    gcache = np.full((nw, n), -1, np.int64)
    ncand = np.zeros(nw, np.int64)
    # pins near each guide, listed at the same rebuilds as the wheels' candidates
    gcand = np.empty((ng, n), np.int64)
    ngcand = np.zeros(ng, np.int64)
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
    x = pos[:, 0].copy()
    y = pos[:, 1].copy()
    vx = vel[:, 0].copy()
    vy = vel[:, 1].copy()
    rest = np.empty(n)
    for i in range(n):
        rest[i] = p if i % 2 == 0 else p2
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
            dx = x[i + 1] - x[i]
            dy = y[i + 1] - y[i]
            ll = math.sqrt(dx * dx + dy * dy)
            il = 1.0 / ll
            ux = dx * il
            uy = dy * il
            ldot = (vx[i + 1] - vx[i]) * ux + (vy[i + 1] - vy[i]) * uy
            tt = k * (ll - rest[i]) + c * ldot
            tension[i] = tt
            wkx[i + 1] = tt * ux
            wky[i + 1] = tt * uy
        dx = x[0] - x[n - 1]
        dy = y[0] - y[n - 1]
        ll = math.sqrt(dx * dx + dy * dy)
        il = 1.0 / ll
        ux = dx * il
        uy = dy * il
        ldot = (vx[0] - vx[n - 1]) * ux + (vy[0] - vy[n - 1]) * uy
        tt = k * (ll - rest[n - 1]) + c * ldot
        tension[n - 1] = tt
        wkx[n] = tt * ux
        wky[n] = tt * uy
        wkx[0] = wkx[n]
        wky[0] = wky[n]
        # wheels: penalty contact of each roller with the nearest tooth gap; the pins
        # near each wheel are listed every `countdown` steps, often enough that no pin
        # can cover the margin in between (4 x the fastest relative speed)
        rebuild = countdown <= 0
        if rebuild:
            vmax = 0.0
            for i in range(n):
                v2 = vx[i] * vx[i] + vy[i] * vy[i]
                if v2 > vmax:
                    vmax = v2
            vmax = math.sqrt(vmax)
            for w in range(nw):
                vmax_w = abs(ws[w, S_SDOT])
                if vmax_w > vmax_s:
                    vmax_s = vmax_w
            cnt = margin / (4.0 * (vmax + vmax_s + 1e-12) * dt)
            countdown = 1 if cnt < 1.0 else (200 if cnt > 200.0 else int(cnt))
        countdown -= 1
        for w in range(nw):
            cx = wp[w, W_CX] + ws[w, S_S] * wp[w, W_DX]
            cy = wp[w, W_CY] + ws[w, S_S] * wp[w, W_DY]
            theta = ws[w, S_THETA]
            om = ws[w, S_OMEGA]
            sd = ws[w, S_SDOT]
            rad = wp[w, W_R]
            plain = wp[w, W_PLAIN] > 0.5
            nseat = wp[w, W_NSEAT]
            delta, cps, sps, re, arcflank, cea, ceb, dta, dtb, tca, tcb, stip = \
                wheel_profile(wp, w, rr)
            htip = wp[w, W_HTIP]
            rout = rad + htip + rr
            rin = rad - wp[w, W_RS] - rr
            if rin < 0.0:
                rin = 0.0
            rout2 = rout * rout
            rin2 = rin * rin
            pitch_angle = twopi / nseat
            iz = int(nseat)
            cth = math.cos(theta)
            sth = math.sin(theta)
            tq = 0.0
            fwx = 0.0
            fwy = 0.0
            if rebuild:
                # candidate pins: those that can come within reach before the next rebuild
                rc = rout + margin
                rc2 = rc * rc
                nc = 0
                for i in range(n):
                    gcache[w, i] = -1
                for i in range(n):
                    qx = x[i] - cx
                    qy = y[i] - cy
                    if qx * qx + qy * qy <= rc2:
                        cand[w, nc] = i
                        nc += 1
                ncand[w] = nc
            for ic in range(ncand[w]):
                i = cand[w, ic]
                qx = x[i] - cx
                qy = y[i] - cy
                r2 = qx * qx + qy * qy
                if r2 > rout2 or r2 < rin2:
                    continue
                if plain:
                    # toothless idler: the roller centre must stay outside the running
                    # circle of radius R (the rim plus the roller radius)
                    dq = math.sqrt(r2)
                    pen = rad - dq
                    if pen <= 0.0:
                        continue
                    nx = -qx / dq
                    ny = -qy / dq
                else:
                    # wheel frame: rotate by -theta; nearest gap from a cheap atan2 (only
                    # the gap index depends on it), seat direction from the table
                    qxw = qx * cth + qy * sth
                    qyw = -qx * sth + qy * cth
                    # gap of the last step, moved by whole gaps while the pin lies beyond
                    # the boundary half-way to the next (previous) seat, at the half central
                    # angle h: b cos h > a sin h; a fresh pin gets its gap from the cheap
                    # atan2 (mean spacing; the walk corrects it on a bi-regular wheel)
                    g = gcache[w, i]
                    if g < 0:
                        g = int(math.floor(_fast_atan2(qyw, qxw) / pitch_angle + 0.5))
                        if g < 0:
                            g += iz
                        if g >= iz:
                            g -= iz
                    g, ex, ey = nearest_seat(tab, w, g, iz, qxw, qyw)
                    gcache[w, i] = g
                    erx = ex * cth - ey * sth
                    ery = ex * sth + ey * cth
                    a = qx * erx + qy * ery - rad
                    b = -qx * ery + qy * erx
                    pen, na, nb, _curv = seat_penetration(a, b, rr, delta, cps, sps, re,
                                                          arcflank, cea, ceb, dta, dtb,
                                                          tca, tcb, stip)
                    if pen <= 0.0:
                        continue
                    nx = na * erx - nb * ery
                    ny = na * ery + nb * erx
                rvx = vx[i] - (-om * qy + sd * wp[w, W_DX])
                rvy = vy[i] - (om * qx + sd * wp[w, W_DY])
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
                ft = -mu * fn * _sat(vt / ve)
                cfx = -fn * nx - ft * ny
                cfy = -fn * ny + ft * nx
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
            ax = gd[g, 0]
            ay = gd[g, 1]
            ux = gd[g, 2]
            uy = gd[g, 3]
            nx = gd[g, 4]
            ny = gd[g, 5]
            length = gd[g, 6]
            if rebuild:
                # candidates: pins within reach of the segment (distance < r + margin)
                reach = rr + margin
                nc = 0
                for i in range(n):
                    h, s = _segment_frame(x[i] - ax, y[i] - ay, ux, uy, nx, ny)
                    if h < -reach or h >= reach or s < -reach or s > length + reach:
                        continue
                    gcand[g, nc] = i
                    nc += 1
                ngcand[g] = nc
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
                mug = gd[g, G_MU] if gd[g, G_MU] >= 0.0 else mu
                ve = mug * fn * dtref * inv_m
                if ve < veps:
                    ve = veps
                ft = -mug * fn * _sat(vt / ve)
                mmat = gd[g, G_MM]
                if mmat > 0.0:
                    # material scraped along a pan by this pin: its weight along the pan
                    # and its friction on the pan (regularised like the chain's); its
                    # inertia in the pin's update (extra mass along the pan)
                    gt = gx * my - gy * mx
                    gn = abs(gx * mx + gy * my)
                    fm = mmat * gd[g, G_MMU] * gn
                    vem = fm * dtref * inv_m
                    if vem < veps:
                        vem = veps
                    ft += mmat * gt - fm * _sat(vt / vem)
                    extra[i, 0] = mmat
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
                best = 1e300
                ib = 0
                for i in range(n):
                    ddx = x[i] - probes[q, 0]
                    ddy = y[i] - probes[q, 1]
                    dd = ddx * ddx + ddy * ddy
                    if dd < best:
                        best = dd
                        ib = i
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
        # wheels
        tn = t + dt
        for w in range(nw):
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
    for i in range(n):
        pos[i, 0] = x[i]
        pos[i, 1] = y[i]
        vel[i, 0] = vx[i]
        vel[i, 1] = vy[i]
    return nrec


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
