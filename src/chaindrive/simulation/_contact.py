"""Contact routines shared by the simulation kernels (internal).

The explicit kernel (:func:`._kernel.integrate`), the linearly implicit one
(:func:`._implicit.integrate_implicit`) and the batched one
(:func:`._batched.integrate_batch`) find their contacts with the same compiled
functions (inlined into each kernel, so the shared code costs nothing):

* :func:`rebuild_every`, :func:`wheel_candidates`, :func:`guide_candidates`: the pins near
  each wheel and guide, listed again every few steps (often enough that no pin covers
  the margin in between);
* :func:`wheel_geometry`, :func:`nearest_seat`, :func:`seat_normal` and :func:`rim_gap`:
  a pin's penetration into its nearest seat (or the rim of a toothless idler) and the
  contact normal, :func:`seat_penetration` and :func:`guide_penetration` the profiles;
* :func:`friction` and :func:`material_drag`: the regularised Coulomb law and the
  material scraped along a pan; :func:`penalty_contact`: the explicit kernels' contact
  force; :func:`nearest_pin`: the pin a velocity probe reads.
"""

from __future__ import annotations

import math

from numba import njit

from . import _layout as L

__all__ = ["friction", "guide_candidates", "link_force", "guide_penetration", "material_drag", "nearest_pin",
           "nearest_seat", "penalty_contact", "rim_gap", "seat_normal", "rebuild_every", "seat_penetration",
           "wheel_candidates", "wheel_geometry", "wheel_profile"]


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
    delta = wp[w, L.W_RS] - rr
    cps = wp[w, L.W_CPSI]
    sps = wp[w, L.W_SPSI]
    htip = wp[w, L.W_HTIP]
    re = wp[w, L.W_RE]
    arcflank = re > 0.0
    cea = wp[w, L.W_CEA]
    ceb = wp[w, L.W_CEB]
    dta = wp[w, L.W_DTA]
    dtb = wp[w, L.W_DTB]
    if arcflank:
        tca = wp[w, L.W_TCA]
        tcb = wp[w, L.W_TCB]
        stip = 0.0
    else:
        # straight flank: the tooth corner (a, |b|) where the roller centre riding
        # on the flank reaches the tip height
        stip = (htip + delta * cps) / sps
        tca = -delta * cps + stip * sps - rr * cps
        tcb = delta * sps + stip * cps + rr * sps
    return delta, cps, sps, re, arcflank, cea, ceb, dta, dtb, tca, tcb, stip


@njit(cache=True, fastmath=False, inline="always")
def nearest_seat(tab, w, g, iz, qxw, qyw, pitch_angle=0.0):
    """Seat of wheel ``w`` nearest to the point ``(qxw, qyw)`` (wheel frame), from seat ``g``.

    Moves by whole seats while the point lies beyond the boundary half-way to the next
    (previous) seat, at the half central angle ``h``: ``b cos h > a sin h``. Returns the
    seat and its unit direction ``(ex, ey)``. ``g < 0`` (a pin fresh on the wheel): the
    walk starts from a cheap atan2 at the mean seat spacing ``pitch_angle`` [rad] (the
    walk corrects it on a bi-regular wheel).
    """
    if g < 0:
        g = int(math.floor(_fast_atan2(qyw, qxw) / pitch_angle + 0.5))
        if g < 0:
            g += iz
        if g >= iz:
            g -= iz
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
def rebuild_every(vx, vy, ws, margin, dt, vmax_s):
    """Steps until the candidate lists are built again, and the largest slide speed so far.

    Often enough that no pin covers ``margin`` [m] in between: 4 x the fastest pin speed
    plus the fastest slide speed seen (``vmax_s`` [m/s], kept by the caller), 1 to 200
    steps. Returns ``(countdown, vmax_s)``.
    """
    vmax = 0.0
    for i in range(vx.shape[0]):
        v2 = vx[i] * vx[i] + vy[i] * vy[i]
        if v2 > vmax:
            vmax = v2
    vmax = math.sqrt(vmax)
    for w in range(ws.shape[0]):
        vmax_w = abs(ws[w, L.S_SDOT])
        if vmax_w > vmax_s:
            vmax_s = vmax_w
    cnt = margin / (4.0 * (vmax + vmax_s + 1e-12) * dt)
    return (1 if cnt < 1.0 else (200 if cnt > 200.0 else int(cnt))), vmax_s


@njit(cache=True, fastmath=False, inline="always")
def wheel_geometry(wp, ws, w, rr):
    """Constants of wheel ``w`` for one step: ``(cx, cy, cth, sth, rad, plain, iz, pitch
    angle, rout2, rin2, rout, profile)``, its centre [m] (on its slide), the cos/sin of its
    angle, its radius [m], toothless or not, seats per turn, the outer and inner radii of
    the ring where a roller of radius ``rr`` can touch it (squared) and
    :func:`wheel_profile`."""
    cx = wp[w, L.W_CX] + ws[w, L.S_S] * wp[w, L.W_DX]
    cy = wp[w, L.W_CY] + ws[w, L.S_S] * wp[w, L.W_DY]
    theta = ws[w, L.S_THETA]
    rad = wp[w, L.W_R]
    plain = wp[w, L.W_PLAIN] > 0.5
    nseat = wp[w, L.W_NSEAT]
    prof = wheel_profile(wp, w, rr)
    rout = rad + wp[w, L.W_HTIP] + rr
    rin = rad - wp[w, L.W_RS] - rr
    if rin < 0.0:
        rin = 0.0
    return (cx, cy, math.cos(theta), math.sin(theta), rad, plain, int(nseat),
            2.0 * math.pi / nseat, rout * rout, rin * rin, rout, prof)


@njit(cache=True, fastmath=False, inline="always")
def wheel_candidates(x, y, cx, cy, rc2, cand, gcache, ncand, w):
    """List the pins within ``sqrt(rc2)`` of wheel ``w``'s centre in ``cand[w]``
    (``ncand[w]`` of them) and forget the seats cached for the former list."""
    for ic in range(ncand[w]):
        gcache[w, cand[w, ic]] = -1
    nc = 0
    for i in range(x.shape[0]):
        qx = x[i] - cx
        qy = y[i] - cy
        if qx * qx + qy * qy <= rc2:
            cand[w, nc] = i
            nc += 1
    ncand[w] = nc


@njit(cache=True, fastmath=False, inline="always")
def friction(mu, fn, vt, dtref, inv_m, veps):
    """Regularised Coulomb force ``−μ fn sat(vt/v_e)`` [N] and ``v_e`` [m/s].

    The slope ``μ fn / v_e`` is capped at ``m / dt_ref`` so that the explicit step stays
    stable, with the model's reference step, not the actual one, so that the law does
    not change when ``dt`` is refined; ``v_e >= veps``.
    """
    ve = mu * fn * dtref * inv_m
    if ve < veps:
        ve = veps
    return -mu * fn * _sat(vt / ve), ve


@njit(cache=True, fastmath=False, inline="always")
def material_drag(gd, g, gx, gy, mx, my, vt, dtref, inv_m, veps):
    """Material scraped along pan ``g`` by a pin moving at ``vt`` along it: its weight
    along the pan and its friction on the pan (regularised like the chain's). Returns
    ``(force along the tangent (my, −mx) [N], friction force scale fm [N], v_e [m/s])``."""
    mmat = gd[g, L.G_MM]
    gt = gx * my - gy * mx
    gn = abs(gx * mx + gy * my)
    fm = mmat * gd[g, L.G_MMU] * gn
    vem = fm * dtref * inv_m
    if vem < veps:
        vem = veps
    return mmat * gt - fm * _sat(vt / vem), fm, vem


@njit(cache=True, fastmath=False, inline="always")
def guide_mu(gd, g, mu):
    """Friction coefficient of guide ``g`` (its own, else the model's ``mu``)."""
    return gd[g, L.G_MU] if gd[g, L.G_MU] >= 0.0 else mu


@njit(cache=True, fastmath=False, inline="always")
def penalty_contact(kc, cc, mu, dtref, inv_m, veps, pen, nx, ny, rvx, rvy):
    """Explicit penalty contact of a roller (relative velocity ``(rvx, rvy)``) pressed
    ``pen`` into a wheel along ``−n``: ``(fn, fx, fy)``, the normal force (``kc pen +
    cc v_n``, never tensile) and the force on the roller [N]."""
    vn = rvx * nx + rvy * ny
    fn = kc * pen + cc * vn
    if fn < 0.0:
        fn = 0.0
    vt = -rvx * ny + rvy * nx
    ft, _ = friction(mu, fn, vt, dtref, inv_m, veps)
    return fn, -fn * nx - ft * ny, -fn * ny + ft * nx


@njit(cache=True, fastmath=False, inline="always")
def guide_candidates(x, y, gd, g, reach, gcand, ngcand):
    """List the pins within ``reach`` of guide ``g``'s segment in ``gcand[g]``."""
    ax = gd[g, 0]
    ay = gd[g, 1]
    length = gd[g, 6]
    nc = 0
    for i in range(x.shape[0]):
        h, s = _segment_frame(x[i] - ax, y[i] - ay, gd[g, 2], gd[g, 3], gd[g, 4], gd[g, 5])
        if h < -reach or h >= reach or s < -reach or s > length + reach:
            continue
        gcand[g, nc] = i
        nc += 1
    ngcand[g] = nc


@njit(cache=True, fastmath=False, inline="always")
def nearest_pin(x, y, px, py):
    """Index of the pin nearest to ``(px, py)`` (a velocity probe)."""
    best = 1e300
    ib = 0
    for i in range(x.shape[0]):
        ddx = x[i] - px
        ddy = y[i] - py
        dd = ddx * ddx + ddy * ddy
        if dd < best:
            best = dd
            ib = i
    return ib


@njit(cache=True, fastmath=False, inline="always")
def rim_gap(qx, qy, r2, rad, reach):
    """Penetration and outward normal ``(pen, nx, ny, curvature)`` of a roller at
    ``(qx, qy)`` from the centre of a toothless idler (``r2 = qx² + qy²``): the roller
    centre stays outside the running circle of radius ``rad`` (rim plus roller radius);
    no contact when ``pen <= −reach`` (the normal then 0)."""
    dq = math.sqrt(r2)
    pen = rad - dq
    if pen <= -reach:
        return pen, 0.0, 0.0, 0.0
    return pen, -qx / dq, -qy / dq, 0.0


@njit(cache=True, fastmath=False, inline="always")
def seat_normal(qx, qy, ex, ey, geo, rr, reach):
    """Penetration and outward normal ``(pen, nx, ny, curvature)`` of a roller of radius
    ``rr`` at ``(qx, qy)`` from the centre of a toothed wheel (``geo`` from
    :func:`wheel_geometry`) in its seat of unit direction ``(ex, ey)`` (wheel frame, from
    :func:`nearest_seat`): :func:`seat_penetration` in the seat's frame; no contact when
    ``pen <= −reach`` (the normal then 0).

    Scalars only: an array passed to an inlined function costs a reference count per call.
    """
    cth = geo[2]
    sth = geo[3]
    erx = ex * cth - ey * sth
    ery = ex * sth + ey * cth
    a = qx * erx + qy * ery - geo[4]
    b = -qx * ery + qy * erx
    delta, cps, sps, re, arcflank, cea, ceb, dta, dtb, tca, tcb, stip = geo[11]
    pen, na, nb, curv = seat_penetration(a, b, rr, delta, cps, sps, re, arcflank, cea, ceb,
                                         dta, dtb, tca, tcb, stip, reach)
    if pen <= -reach:
        return pen, 0.0, 0.0, 0.0
    return pen, na * erx - nb * ery, na * ery + nb * erx, curv


@njit(cache=True, fastmath=False, inline="always")
def link_force(dx, dy, dvx, dvy, k, c, rest):
    """Axial spring-damper link from its end-to-end vector ``(dx, dy)`` [m] and the
    relative velocity of its ends ``(dvx, dvy)`` [m/s]: ``(T, ux, uy, l̇)``, the tension
    ``k (l − rest) + c l̇`` [N], the unit direction and the rate of extension [m/s].
    Scalars only (the link loops stay vectorised)."""
    ll = math.sqrt(dx * dx + dy * dy)
    il = 1.0 / ll
    ux = dx * il
    uy = dy * il
    ldot = dvx * ux + dvy * uy
    return k * (ll - rest) + c * ldot, ux, uy, ldot
