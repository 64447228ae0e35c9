"""Compiled static system of the chain-drive model (internal): energy, gradient, Hessian.

The static equilibrium of the simulation model (without friction and damping) is the
minimum of its potential energy

.. math::
    Π = \\sum_{links} \\tfrac12 k (l_i - L_i)^2 + \\sum_{contacts} \\tfrac12 k_c g^2
        - \\sum_{pins} m\\,\\mathbf g\\cdot\\mathbf x_i - \\sum_{wheels} τ_w θ_w
        + \\sum_{slides} (\\tfrac12 k_s s^2 - F_s s - m_s\\,\\mathbf g\\cdot\\mathbf d\\,s)

over the pin positions, the angles of the free wheels and the positions of the wheels on
slides: the same terms as the forces of :func:`chaindrive.simulation._kernel.integrate`
(the contact penetration ``g`` from the kernel's own inline functions), so that the
static state is an equilibrium of the dynamic model. The Hessian returned is the
positive semi-definite part used by the Newton iteration: each link's
``k u uᵀ + max(T, 0)/l (I − u uᵀ)`` (a compressed link's negative geometric stiffness is
left out), each contact's ``k_c (J Jᵀ + g κ⁺ T Tᵀ)`` (Gauss–Newton plus the seat arc's
positive curvature ``κ = 1/d``, which is what holds a pressed roller in its seat
tangentially; the convex flanks' and corners' negative curvature left out), each guide
contact's ``k_g J Jᵀ``.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from . import _layout as L
from ._contact import guide_penetration, nearest_seat, seat_penetration, wheel_profile


@njit(cache=True, inline="always")
def _put(rows, cols, vals, nnz, r, c, v):
    if nnz < rows.shape[0]:
        rows[nnz] = r
        cols[nnz] = c
        vals[nnz] = v
    return nnz + 1


@njit(cache=True)
def static_system(x, npins, wp, theta, slide, th_idx, s_idx, gd, tab, par, th_spring,
                  th_target, grad, rows, cols, vals, want_hessian, tension_floor):
    """Potential energy [J] at ``x``; fills ``grad`` and the Hessian triplets.

    ``x`` holds the pin coordinates ``(x0, y0, x1, y1, ...)`` and then the wheel
    unknowns: wheel ``w``'s angle is ``x[th_idx[w]]`` if ``th_idx[w] >= 0`` (else the
    fixed ``theta[w]``), its slide position ``x[s_idx[w]]`` if ``s_idx[w] >= 0`` (else
    ``slide[w]``). A free wheel's angle may be tied to ``th_target[w]`` by a torsion
    spring ``th_spring[w]`` [N m/rad] (the assembly's angle control). The links' geometric stiffness in the Hessian takes at least the
    tension ``tension_floor`` [N] (a slack chain is otherwise a mechanism).
    Returns ``(energy, number of triplets)``; more triplets than
    ``rows.shape[0]`` means the buffers were too short (the call must be repeated).
    """
    n = npins
    nw = wp.shape[0]
    ng = gd.shape[0]
    m = par[L.P_MASS]
    k = par[L.P_K]
    p = par[L.P_PITCH]
    p2 = par[L.P_PITCH2]
    rr = par[L.P_RROLLER]
    kc = par[L.P_KC]
    kg = par[L.P_KG]
    gx = par[L.P_GX]
    gy = par[L.P_GY]
    twopi = 2.0 * math.pi
    for i in range(grad.shape[0]):
        grad[i] = 0.0
    nnz = 0
    energy = 0.0
    # gravity
    for i in range(n):
        energy -= m * (gx * x[2 * i] + gy * x[2 * i + 1])
        grad[2 * i] -= m * gx
        grad[2 * i + 1] -= m * gy
    # links
    for i in range(n):
        j = i + 1
        if j == n:
            j = 0
        dx = x[2 * j] - x[2 * i]
        dy = x[2 * j + 1] - x[2 * i + 1]
        ll = math.sqrt(dx * dx + dy * dy)
        ux = dx / ll
        uy = dy / ll
        dl = ll - (p if (i & 1) == 0 else p2)
        tt = k * dl
        energy += 0.5 * k * dl * dl
        grad[2 * j] += tt * ux
        grad[2 * j + 1] += tt * uy
        grad[2 * i] -= tt * ux
        grad[2 * i + 1] -= tt * uy
        if want_hessian:
            geo = (tt if tt > tension_floor else tension_floor) / ll
            kxx = k * ux * ux + geo * (1.0 - ux * ux)
            kxy = k * ux * uy - geo * ux * uy
            kyy = k * uy * uy + geo * (1.0 - uy * uy)
            # the link's 16 triplets written directly (25 times faster than through
            # _put: 3.3 ms to 0.13 ms for 2,194 links), in _put's order
            if nnz + 16 <= rows.shape[0]:
                i0 = 2 * i
                j0 = 2 * j
                q = nnz
                for a in range(2):
                    for b in range(2):
                        v = kxx if a + b == 0 else (kyy if a + b == 2 else kxy)
                        rows[q] = i0 + a
                        cols[q] = i0 + b
                        vals[q] = v
                        rows[q + 1] = j0 + a
                        cols[q + 1] = j0 + b
                        vals[q + 1] = v
                        rows[q + 2] = i0 + a
                        cols[q + 2] = j0 + b
                        vals[q + 2] = -v
                        rows[q + 3] = j0 + a
                        cols[q + 3] = i0 + b
                        vals[q + 3] = -v
                        q += 4
            nnz += 16
    # wheels: applied torque, slide, contacts
    jv = np.zeros(4)
    tv = np.zeros(4)
    idx = np.zeros(4, np.int64)
    for w in range(nw):
        th = x[th_idx[w]] if th_idx[w] >= 0 else theta[w]
        s = x[s_idx[w]] if s_idx[w] >= 0 else slide[w]
        if th_idx[w] >= 0:
            energy -= wp[w, L.W_TORQUE] * th
            grad[th_idx[w]] -= wp[w, L.W_TORQUE]
            if th_spring[w] > 0.0:
                dth = th - th_target[w]
                energy += 0.5 * th_spring[w] * dth * dth
                grad[th_idx[w]] += th_spring[w] * dth
                if want_hessian:
                    nnz = _put(rows, cols, vals, nnz, th_idx[w], th_idx[w], th_spring[w])
        dxw = wp[w, L.W_DX]
        dyw = wp[w, L.W_DY]
        if s_idx[w] >= 0:
            fext = wp[w, L.W_SF] + wp[w, L.W_SMASS] * (gx * dxw + gy * dyw)
            energy += 0.5 * wp[w, L.W_SK] * s * s - fext * s
            grad[s_idx[w]] += wp[w, L.W_SK] * s - fext
            if want_hessian:
                nnz = _put(rows, cols, vals, nnz, s_idx[w], s_idx[w], wp[w, L.W_SK])
        cx = wp[w, L.W_CX] + s * dxw
        cy = wp[w, L.W_CY] + s * dyw
        rad = wp[w, L.W_R]
        plain = wp[w, L.W_PLAIN] > 0.5
        iz = int(wp[w, L.W_NSEAT])
        pitch_angle = twopi / iz
        delta, cps, sps, re, arcflank, cea, ceb, dta, dtb, tca, tcb, stip = \
            wheel_profile(wp, w, rr)
        rout = rad + wp[w, L.W_HTIP] + rr
        rin = rad - wp[w, L.W_RS] - rr
        if rin < 0.0:
            rin = 0.0
        cth = math.cos(th)
        sth = math.sin(th)
        for i in range(n):
            qx = x[2 * i] - cx
            qy = x[2 * i + 1] - cy
            r2 = qx * qx + qy * qy
            if r2 > rout * rout or r2 < rin * rin:
                continue
            if plain:
                dq = math.sqrt(r2)
                pen = rad - dq
                if pen <= 0.0:
                    continue
                nx = -qx / dq
                ny = -qy / dq
                curv = 0.0
            else:
                qxw = qx * cth + qy * sth
                qyw = -qx * sth + qy * cth
                g = int(math.floor(math.atan2(qyw, qxw) / pitch_angle + 0.5)) % iz
                g, ex, ey = nearest_seat(tab, w, g, iz, qxw, qyw)
                erx = ex * cth - ey * sth
                ery = ex * sth + ey * cth
                a = qx * erx + qy * ery - rad
                b = -qx * ery + qy * erx
                pen, na, nb, curv = seat_penetration(a, b, rr, delta, cps, sps, re, arcflank,
                                                     cea, ceb, dta, dtb, tca, tcb, stip)
                if pen <= 0.0:
                    continue
                nx = na * erx - nb * ery
                ny = na * ery + nb * erx
            energy += 0.5 * kc * pen * pen
            # derivatives of pen: along the normal for the pin, the pin's motion relative
            # to the wheel for the wheel's angle (-e_z x q) and slide (-d)
            tx = -ny
            ty = nx
            jv[0] = nx
            jv[1] = ny
            jv[2] = qy * nx - qx * ny
            jv[3] = -(nx * dxw + ny * dyw)
            tv[0] = tx
            tv[1] = ty
            tv[2] = qy * tx - qx * ty
            tv[3] = -(tx * dxw + ty * dyw)
            idx[0] = 2 * i
            idx[1] = 2 * i + 1
            idx[2] = th_idx[w]
            idx[3] = s_idx[w]
            f = kc * pen
            ck = f * curv if curv > 0.0 else 0.0
            for a in range(4):
                if idx[a] >= 0:
                    grad[idx[a]] += f * jv[a]
            if want_hessian:
                for a in range(4):
                    if idx[a] < 0:
                        continue
                    for b in range(4):
                        if idx[b] < 0:
                            continue
                        nnz = _put(rows, cols, vals, nnz, idx[a], idx[b],
                                   kc * jv[a] * jv[b] + ck * tv[a] * tv[b])
    # guides
    for g in range(ng):
        for i in range(n):
            pen, mx, my = guide_penetration(x[2 * i], x[2 * i + 1], gd, g, rr)
            if pen <= 0.0:
                continue
            energy += 0.5 * kg * pen * pen
            grad[2 * i] -= kg * pen * mx
            grad[2 * i + 1] -= kg * pen * my
            if want_hessian:
                nnz = _put(rows, cols, vals, nnz, 2 * i, 2 * i, kg * mx * mx)
                nnz = _put(rows, cols, vals, nnz, 2 * i, 2 * i + 1, kg * mx * my)
                nnz = _put(rows, cols, vals, nnz, 2 * i + 1, 2 * i, kg * mx * my)
                nnz = _put(rows, cols, vals, nnz, 2 * i + 1, 2 * i + 1, kg * my * my)
    return energy, nnz
