r"""Quasi-static load distribution of a worn chain on a wheel, with compliant contacts.

The rigid analysis of :mod:`chaindrive.life.jump_over` seats every roller alike; a worn
chain does not seat alike, and near the onset of jump-over the ratio the wrap holds is
very sensitive to where each roller sits. This module computes the seating instead, as
the minimum of the potential energy of the wrap (the load-distribution model of Naji &
Marshek, *Mech. Mach. Theory* 18 (1983) 349, extended from their seated rollers to rollers
that slide on the worn seat and the flank):

.. math::
    Π(\mathbf x) = \sum_i \tfrac12 k_l\,(|\mathbf x_{i+1}-\mathbf x_i| - p(1+e))^2
    + \sum_i \tfrac12 k_c\,\langle δ_i(\mathbf x_i)\rangle^2
    - T_1\,\mathbf e_1\!\cdot\mathbf x_0 - T_2\,\mathbf e_2\!\cdot\mathbf x_{m}

- ``x_i`` the roller centres of a stretch of chain (a few links of each span and the
  wrap), ``k_l = EA / (p(1+e))`` the link's axial stiffness (chain elasticity),
- ``δ_i`` the penetration of roller ``i`` into the ISO 606 tooth gap nearest to it (seating
  arc, convex flank arc, tooth corner; :func:`chaindrive.geometry.tooth_form.iso_tooth_form`)
  and ``k_c`` the contact stiffness (a linear spring per roller, the dynamic simulation's
  penalty law; the Palmgren line-contact law of
  :func:`chaindrive.vibration.running_tension.seat_contact_stiffness` gives
  1.2·10⁸…3.6·10⁸ N/m for 16B over 0.5…20 kN),
- the span tensions ``T_1`` (tight) and ``T_2`` (slack) applied along the two spans'
  fixed directions (the spans are long: their direction does not follow the rollers).

The wheel is held at an angle ``θ``; frictionless. The minimum is found by Newton's method
with a line search (the Hessian shifted to be positive definite where it is not; banded, so
each step is a banded Cholesky solve), each wheel position started from the previous one
turned with the wheel.

**Loading.** A drive does not impose the span tensions but the wheel's torque ``M`` and,
through the take-up (a wheel on a slide pulled by ``F``, or the pretension), their sum
``T_1 + T_2 = F``. The chain's moment balance about the wheel centre (frictionless: the
tooth forces pass ``M`` on) with the spans' heights ``y_1``, ``y_2`` at the wheel gives
``T_1 = (M + F|y_2|)/(y_1 + |y_2|)``. The heights change over a tooth pitch (the polygonal
action, and the worn chain's uneven seating), so at constant ``M`` the slack span's tension
dips once per tooth, and near the onset it dips to almost nothing: the chain jumps at the
weakest phase, at a mean ratio far below the one the same seating holds at fixed ``T_1/T_2``.

**Jump-over.** ``M = F ρ/(1+ρ) R(1+e)`` (``ρ`` the nominal ratio); the wheel is turned
through one tooth pitch in steps (40 by default: the dip of the slack span's tension is
narrow) and the equilibrium followed; the chain has jumped when a
roller of the wrap has moved to another tooth gap (or no equilibrium is found).
:func:`wrap_jump_ratio` bisects ``ρ`` and reports the mean span tensions' ratio at the
onset.

References
----------
K. M. Marshek and M. R. Naji, "Analysis of sprocket load distribution", Mech. Mach. Theory
18 (1983) 349-356 (the load distribution of the seated rollers from the chain's and the
teeth's compliance); M. R. Naji and K. M. Marshek, "Experimental determination of the
roller chain load distribution", J. Mech. Transm. Autom. Des. 105 (1983) 331-338 (measured
on a 20-tooth sprocket: largely independent of the elastic properties).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np
from scipy.linalg.lapack import dpbtrf, dpbtrs

from .._results import Result, quantity
from .._validation import check_nonnegative, check_positive
from ..errors import InputError
from ..geometry.tooth_form import iso_tooth_form

__all__ = ["WrapModel", "WrapJump", "wrap_jump_ratio"]


@dataclass(frozen=True)
class WrapModel:
    """A worn chain on one wheel (fixed at the origin), its spans along ``+x``.

    The tight span leaves the top of the wheel, the slack span the bottom, both towards
    ``+x`` (a 180° wrap, two equal wheels). ``pitch`` is the wheel's (nominal) pitch [m],
    the chain's is ``pitch (1 + elongation)``. ``tip_diameter`` [m] default: the middle of
    ISO 606's range (as the dynamic simulation); seat radius ``0.505 d_1``.

    Examples
    --------
    >>> m = WrapModel(0.0254, 17, 0.01588, 0.0)
    >>> m.start(0.0).shape  # 8 rollers in the half wrap and 3 links of each span
    (14, 2)
    >>> x, ok = m.equilibrium(m.start(0.0).ravel(), 0.0, 2000.0, 200.0)
    >>> ok
    True
    """

    pitch: float
    teeth: int
    roller_diameter: float
    elongation: float
    axial_stiffness: float = 1.0e8
    contact_stiffness: float = 2.0e8
    span_links: int = 3
    tip_diameter: float | None = None

    def __post_init__(self) -> None:
        check_positive("pitch", self.pitch, "m")
        check_positive("roller_diameter", self.roller_diameter, "m")
        check_nonnegative("elongation", self.elongation)
        check_positive("axial_stiffness", self.axial_stiffness, "N")
        check_positive("contact_stiffness", self.contact_stiffness, "N/m")
        check_positive("span_links", self.span_links)
        f, r, _psi, ce, corner, _d_t = self._const  # validates teeth, pitch and roller (ISO 606 form)
        tip = ce + (f.flank_radius + r) * (corner - ce) / float(np.hypot(*(corner - ce)))
        limit = float(np.hypot(tip[0] + f.pitch_radius, tip[1])) / f.pitch_radius - 1.0
        if not float(self.elongation) < limit:
            raise InputError(f"elongation {float(self.elongation):.4g} is more than the ISO 606 tooth form of a "
                             f"{f.teeth}-tooth wheel can hold ({limit:.4g}): the rollers would ride over the "
                             "tooth corner", field="elongation")

    # ------------------------------------------------------------------ geometry
    @functools.cached_property
    def _const(self):
        from ..geometry.sprocket import tip_diameter_limits

        d1 = float(self.roller_diameter)
        tip = (0.5 * float(sum(tip_diameter_limits(self.pitch, self.teeth, d1)))
               if self.tip_diameter is None else float(self.tip_diameter))
        f = iso_tooth_form(self.pitch, self.teeth, d1, seat_radius=0.505 * d1, tip_diameter=tip)
        psi = 0.5 * f.seat_angle
        ce = np.asarray(f.flank_centre, float)
        corner = np.asarray(f.tooth_corner, float)
        d_t = (corner - ce) / float(np.hypot(*(corner - ce)))
        return f, 0.5 * d1, psi, ce, corner, d_t

    def start(self, theta: float) -> np.ndarray:
        """Roller centres of the uniformly ridden-out chain (radius ``R (1 + e)``) and its spans."""
        f = self._const[0]
        step = 2 * math.pi / self.teeth
        r_e = f.pitch_radius * (1 + self.elongation)
        k = math.ceil((0.5 * math.pi - theta) / step - 1e-9)
        angles = []
        while theta + k * step <= 1.5 * math.pi + 1e-9:
            angles.append(theta + k * step)
            k += 1
        wrap = [r_e * np.array([math.cos(a), math.sin(a)]) for a in angles]
        link = self.pitch * (1 + self.elongation)
        tight = [wrap[0] + np.array([link * (j + 1), 0.0]) for j in range(self.span_links)][::-1]
        slack = [wrap[-1] + np.array([link * (j + 1), 0.0]) for j in range(self.span_links)]
        return np.array(tight + wrap + slack)

    # ------------------------------------------------------------------ energy
    def energy(self, x: np.ndarray, theta: float, t1: float, t2: float, *,
               banded: bool = False) -> tuple[float, np.ndarray, np.ndarray]:
        """Potential energy [J], its gradient [N] and Hessian [N/m] at the roller centres ``x`` (flat).

        ``banded``: the Hessian in LAPACK's upper banded storage (as
        :func:`scipy.linalg.cholesky_banded`; 3 superdiagonals: a chain of 2-D points couples
        only its neighbours) instead of the full matrix.
        """
        f, r, psi, ce, corner, d_t = self._const
        xx = x.reshape(-1, 2)
        n = len(xx)
        grad = np.zeros((n, 2))
        # links
        rest = self.pitch * (1 + self.elongation)
        kl = self.axial_stiffness / rest
        d = xx[1:] - xx[:-1]
        length = np.hypot(d[:, 0], d[:, 1])
        u = d / length[:, None]
        ext = length - rest
        energy = 0.5 * kl * float(ext @ ext)
        fl = (kl * ext)[:, None] * u
        grad[:-1] -= fl
        grad[1:] += fl
        uu = u[:, :, None] * u[:, None, :]
        blocks = kl * uu + (kl * ext / length)[:, None, None] * (np.eye(2) - uu)
        diag = np.zeros((n, 2, 2))
        diag[1:] += blocks
        diag[:-1] += blocks
        # contacts
        pen, nrm, curv = _penetrations(xx, theta, f, r, psi, ce, corner, d_t)
        kc = self.contact_stiffness
        energy += float(np.sum(0.5 * kc * pen * pen))
        grad += (kc * pen)[:, None] * nrm
        tan = np.stack([-nrm[:, 1], nrm[:, 0]], axis=1)
        diag += kc * (nrm[:, :, None] * nrm[:, None, :] + (pen * curv)[:, None, None] * (tan[:, :, None] * tan[:, None, :]))
        energy -= t1 * xx[0, 0] + t2 * xx[-1, 0]
        grad[0, 0] -= t1
        grad[-1, 0] -= t2
        # upper banded storage: row 3 - k holds the k-th superdiagonal
        band = np.zeros((4, 2 * n))
        band[3, 0::2], band[3, 1::2] = diag[:, 0, 0], diag[:, 1, 1]
        band[2, 1::2] = diag[:, 0, 1]
        band[2, 2::2] = -blocks[:, 1, 0]
        band[1, 2::2], band[1, 3::2] = -blocks[:, 0, 0], -blocks[:, 1, 1]
        band[0, 3::2] = -blocks[:, 0, 1]
        return energy, grad.ravel(), (band if banded else _dense(band))

    def _energy_value(self, x: np.ndarray, theta: float, t1: float, t2: float) -> float:
        """:meth:`energy`'s value alone (the same operations: the same number to the last bit)."""
        xx = x.reshape(-1, 2)
        rest = self.pitch * (1 + self.elongation)
        kl = self.axial_stiffness / rest
        d = xx[1:] - xx[:-1]
        ext = np.hypot(d[:, 0], d[:, 1]) - rest
        energy = 0.5 * kl * float(ext @ ext)
        f, r, psi, ce, corner, d_t = self._const
        pen = _penetrations(xx, theta, f, r, psi, ce, corner, d_t, normals=False)[0]
        energy += float(np.sum(0.5 * self.contact_stiffness * pen * pen))
        return energy - (t1 * xx[0, 0] + t2 * xx[-1, 0])

    def equilibrium(self, x: np.ndarray, theta: float, t1: float, t2: float, *, tol: float = 1e-7,
                    max_iter: int = 200) -> tuple[np.ndarray, bool]:
        """The equilibrium nearest ``x`` (Newton, line search on ``Π``); (positions, converged)."""
        energy, grad, hess = self.energy(x, theta, t1, t2, banded=True)
        scale = max(t1, t2, 1.0)
        for _ in range(max_iter):
            if float(np.max(np.abs(grad))) < tol * scale:
                return x, True
            dx = _descent(hess, grad)
            big = float(np.max(np.abs(dx)))
            if big > 0.08 * self.pitch:
                dx *= 0.08 * self.pitch / big
            t = 1.0
            while True:  # the trial points' energy alone; the gradient and Hessian at the accepted one
                if self._energy_value(x + t * dx, theta, t1, t2) <= energy + 1e-4 * t * float(grad @ dx) or t < 1e-6:
                    break
                t *= 0.5
            x = x + t * dx
            energy, grad, hess = self.energy(x, theta, t1, t2, banded=True)
        return x, False

    def tensions(self, x: np.ndarray, theta: float, torque: float, load: float, t1: float, *,
                 iterations: int = 30) -> tuple[np.ndarray, float, bool]:
        """The equilibrium under the wheel torque ``M`` and the span tensions' sum ``F``.

        The span forces are horizontal and act at the heights ``y_1`` (tight span, top) and
        ``y_2 < 0`` (slack span) of the chain's ends, so the chain's moment balance about the
        wheel centre (frictionless: the teeth's forces pass the torque ``M`` on) and
        ``T_1 + T_2 = F`` give

        .. math:: T_1 = \\frac{M + F\\,|y_2|}{y_1 + |y_2|}

        which is iterated with the equilibrium (the heights depend on the seating).
        Returns (positions, ``T_1`` [N], converged).
        """
        def update(t):
            xs, ok = self.equilibrium(x, theta, t, load - t)
            xx = xs.reshape(-1, 2)
            y1, y2 = float(xx[0, 1]), -float(xx[-1, 1])
            return xs, ok, min(max((torque + load * y2) / (y1 + y2), 0.0), load) - t

        # secant iteration on T_1 - f(T_1) = 0 (f: the moment balance at the seating under T_1)
        xs, ok, res = update(t1)
        prev_t: float | None = None
        prev_r: float | None = None
        for _ in range(iterations):
            if not ok:
                return xs, t1, False
            if abs(res) < 1e-6 * load:
                return xs, t1, True
            x = xs
            if prev_t is None or prev_r is None or res == prev_r:
                step = res
            else:
                step = -res * (t1 - prev_t) / (res - prev_r)
                step = max(min(step, 0.05 * load), -0.05 * load)
            prev_t, prev_r = t1, res
            t1 = min(max(t1 + step, 0.0), load)
            xs, ok, res = update(t1)
        return xs, t1, False

    def holds(self, load: float, ratio: float, *, phases: int = 40, ramp: int = 12, sense: int = 1,
              loading: str = "torque") -> tuple[bool, float]:
        """Whether the wrap holds the torque ``M = F ρ/(1+ρ) R (1+e)`` while the wheel turns one pitch.

        ``F`` (``load``) is the sum of the span tensions (the slide force of a wheel on a
        slide), ``ρ`` (``ratio``) the nominal ratio ``T_1/T_2`` the torque would give at the
        radius ``R (1 + e)`` of the uniformly ridden-out chain; the spans' actual tensions
        follow the seating. Returns (held, the ratio of the mean span tensions over the
        pitch ``mean T_1 / mean T_2``). ``loading="tensions"``: the span tensions held at
        ``T_1 = F ρ/(1+ρ)``, ``T_2 = F/(1+ρ)`` instead (a back tension set by the slack span's
        sag); ``sense``: the way the wheel turns (+1 counter-clockwise).
        """
        if loading not in ("torque", "tensions"):
            raise InputError(f"loading must be 'torque' or 'tensions', got {loading!r}", field="loading")
        fixed = loading == "tensions"
        theta = 0.0
        x = self.start(theta).ravel()
        radius = self._const[0].pitch_radius * (1 + self.elongation)
        t1 = load * ratio / (1 + ratio)
        for rho in np.geomspace(1.5, max(ratio, 1.5), ramp):
            if fixed:
                x, _ok = self.equilibrium(x, theta, load * rho / (1 + rho), load / (1 + rho))
            else:
                x, t1, _ok = self.tensions(x, theta, load * rho / (1 + rho) * radius, load, t1)
        t1 = load * ratio / (1 + ratio) if fixed else t1
        torque = load * ratio / (1 + ratio) * radius
        mid = len(x) // 4
        step = 2 * math.pi / self.teeth

        def seat(xv, th):
            q = xv.reshape(-1, 2)[mid]
            return (math.atan2(q[1], q[0]) - th) / step

        k0 = seat(x, theta)
        tight = []
        for theta in np.linspace(0.0, sense * step, phases + 1)[1:]:
            x, t1, ok = self._advance(x, float(theta) - sense * step / phases, float(theta), t1, torque, load,
                                      fixed)
            moved = (seat(x, float(theta)) - k0 + 0.5 * self.teeth) % self.teeth - 0.5 * self.teeth
            if not ok or abs(moved) > 0.5:
                return False, math.nan
            tight.append(t1)
        mean = float(np.mean(tight))
        return True, mean / max(load - mean, 1e-12)


    def _advance(self, x, start, end, t1, torque, load, fixed, depth=3):
        """The equilibrium at the wheel angle ``end`` followed from ``start`` (halving the step
        where the iteration does not converge, down to 1/8 of it), started from ``x`` turned with
        the wheel."""
        c, s = math.cos(end - start), math.sin(end - start)
        guess = (x.reshape(-1, 2) @ np.array([[c, s], [-s, c]])).ravel()
        if fixed:
            xs, ok = self.equilibrium(guess, end, t1, load - t1)
            ts = t1
        else:
            xs, ts, ok = self.tensions(guess, end, torque, load, t1)
        if ok or depth == 0:
            return xs, ts, ok
        mid = 0.5 * (start + end)
        xm, tm, okm = self._advance(x, start, mid, t1, torque, load, fixed, depth - 1)
        if not okm:
            return xm, tm, False
        return self._advance(xm, mid, end, tm, torque, load, fixed, depth - 1)

def _dense(band: np.ndarray) -> np.ndarray:
    """The symmetric matrix of the upper banded storage ``band`` (see :meth:`WrapModel.energy`)."""
    m, size = band.shape
    out = np.zeros((size, size))
    for k in range(m):
        i = np.arange(size - k)
        out[i, i + k] = out[i + k, i] = band[m - 1 - k, k:]
    return out


def _descent(band: np.ndarray, grad: np.ndarray) -> np.ndarray:
    """Newton step ``-(H + λI)^-1 g`` with the smallest shift ``λ >= 0`` that makes it positive definite
    (``H`` in upper banded storage: a banded Cholesky factorisation)."""
    shift = 0.0
    dmax = max(float(np.max(np.abs(band[-1]))), 1.0)
    while True:  # LAPACK's banded Cholesky (dpbtrf; info > 0: not positive definite)
        shifted = band.copy()
        shifted[-1] += shift
        low, info = dpbtrf(shifted)
        if info == 0:
            break
        shift = max(2 * shift, 1e-8 * dmax)
    step, info = dpbtrs(low, grad)
    return -step


def _penetrations(xx, theta, f, r, psi, ce, corner, d_t, normals=True):
    """Penetration [m] of each roller of ``xx`` into its nearest tooth gap (0 without contact),
    the unit normal in which it grows and the curvature of the gap function along the tangent
    (arc of the seat, flank arc, tooth corner; ISO 606)."""
    step = 2 * math.pi / f.teeth
    px, py = xx[:, 0], xx[:, 1]
    gap = theta + np.round((np.arctan2(py, px) - theta) / step) * step
    cg, sg = np.cos(gap), np.sin(gap)
    a = (px * cg + py * sg) - f.pitch_radius  # along the gap's radius (e_r)
    b = (px * (-sg) + py * cg)  # across it (e_t)
    sign = np.where(b >= 0, 1.0, -1.0)
    b = np.abs(b)
    on_seat = b * math.cos(psi) + a * math.sin(psi) <= 0.0
    vx, vy = a - ce[0], b - ce[1]
    at_corner = ~on_seat & (vx * d_t[1] - vy * d_t[0] < 0.0)
    rx = np.where(at_corner, a - corner[0], np.where(on_seat, a, vx))
    ry = np.where(at_corner, b - corner[1], np.where(on_seat, b, vy))
    dist = np.hypot(rx, ry)
    safe = np.where(dist == 0.0, 1.0, dist)
    pen = np.where(at_corner, r - dist, np.where(on_seat, dist - (f.seat_radius - r), f.flank_radius + r - dist))
    out = np.where(on_seat, 1.0, -1.0) / safe  # the seat is concave, the flank and the corner convex
    na, nb = out * rx, sign * (out * ry)
    touch = (pen > 0.0) & (dist > 0.0)
    pen = np.where(touch, pen, 0.0)
    if not normals:
        return pen, None, None
    nrm = np.empty_like(xx)
    nrm[:, 0] = np.where(touch, na * cg - nb * sg, 0.0)
    nrm[:, 1] = np.where(touch, na * sg + nb * cg, 0.0)
    return pen, nrm, out


@dataclass(frozen=True)
class WrapJump(Result):
    """Onset of jump-over of a compliant worn wrap (see :func:`wrap_jump_ratio`)."""

    load_ratio: float = quantity("1")
    tension_ratio: float = quantity("1")
    tight_tension: float = quantity("N")


def wrap_jump_ratio(pitch: float, teeth: int, roller_diameter: float, elongation: float, load: float, *,
                    axial_stiffness: float = 1.0e8, contact_stiffness: float = 2.0e8, phases: int = 40,
                    low: float = 2.0, high: float = 3000.0, rtol: float = 0.03,
                    loading: str = "torque", tip_diameter: float | None = None) -> WrapJump:
    r"""The span-tension ratio at which a compliant worn wrap under a torque lets the chain jump (quasi-static).

    The wheel carries ``M = F ρ/(1+ρ) R (1+e)`` with the span tensions' sum ``F``
    (``load``); the largest ``ρ`` for which the equilibrium of :class:`WrapModel` is
    followed through one tooth pitch without a roller changing its gap, bisected
    geometrically in ``[low, high]``.

    Parameters
    ----------
    pitch : float
        Wheel (nominal chain) pitch ``p`` [m].
    teeth : int
        ``z``; 180° wrap.
    roller_diameter : float
        ``d_1`` [m].
    elongation : float
        ``e >= 0`` [-].
    load : float
        ``F = T_1 + T_2`` [N], > 0.
    axial_stiffness : float
        Chain ``EA`` [N] (16B: 1e8, the simulation's).
    contact_stiffness : float
        Roller–tooth spring [N/m] (the simulation's 2e8).
    phases : int
        Wheel positions per tooth pitch. With the torque held the slack span's tension dips to
        its least over a small part of the pitch, and a wheel position that misses the dip
        over-states the onset: 17 teeth at 10 %, 3 kN: 56.8 at 10 positions, 54.4 at 20, 52.2
        at 40 and at 80; 11 teeth at 10 %: 25.9 at 10, 23.5 at 40 (the simulation driven ever
        slower: 51.3 and 23.0; docs/life.md, "Jump-over"). Default 40.
    low, high : float
        Bracket of ``ρ`` (``low`` held, ``high`` not).
    rtol : float
        Relative width of the final bracket.
    loading : {"torque", "tensions"}
        The wheel's torque with ``T_1 + T_2 = F`` held (a wheel on a slide; default), or the
        span tensions held (a back tension set by the slack span's sag): :meth:`WrapModel.holds`.
    tip_diameter : float, optional
        The wheel's ``d_a`` [m]; default the middle of ISO 606's range (:class:`WrapModel`).

    Returns
    -------
    WrapJump
        ``load_ratio`` ``ρ`` (the held end of the final bracket; ``high`` if that holds),
        ``tension_ratio`` the mean ``T_1`` over the mean ``T_2`` over the pitch at it [-],
        ``tight_tension`` that mean ``T_1`` [N].

    Raises
    ------
    InputError
        The wrap does not hold even ``ρ = low`` (the tooth form cannot hold the worn chain
        under this load), or bad input.

    References
    ----------
    Marshek and Naji, Mech. Mach. Theory 18 (1983) 349 (compliant load distribution).

    Examples
    --------
    >>> r = wrap_jump_ratio(0.0254, 17, 0.01588, 0.1, 3000.0, phases=4, rtol=0.5)  # doctest: +SKIP
    """
    check_positive("load", load, "N")
    z = float(check_positive("teeth", teeth))
    if z != round(z):
        raise InputError(f"teeth must be a whole number, got {z:g}", field="teeth")
    if not 1 <= phases <= 100 or phases != int(phases):
        raise InputError(f"phases must be a whole number in [1, 100], got {phases}", field="phases")
    lo, hi = float(check_positive("low", low)), float(check_positive("high", high))
    if not lo < hi <= 1e9:
        raise InputError(f"the bracket must be 0 < low < high <= 1e9, got [{lo:g}, {hi:g}]", field="high")
    if not 1e-3 <= float(rtol) <= 10.0:
        raise InputError(f"rtol must lie in [0.001, 10], got {rtol}", field="rtol")
    model = WrapModel(pitch, int(z), roller_diameter, elongation, axial_stiffness, contact_stiffness,
                      tip_diameter=tip_diameter)
    held, measured = model.holds(load, lo, phases=int(phases), loading=loading)
    if not held:
        raise InputError(f"the worn wrap ({teeth} teeth, elongation {elongation:g}) does not hold even "
                         f"T1/T2 = {low:g} under {load:g} N: the tooth form cannot hold the worn chain",
                         field="elongation")
    held, got = model.holds(load, hi, phases=int(phases), loading=loading)
    if held:
        lo, measured = hi, got
    while not held and hi / lo > 1.0 + rtol:
        mid = math.sqrt(lo * hi)
        ok, got = model.holds(load, mid, phases=int(phases), loading=loading)
        if ok:
            lo, measured = mid, got
        else:
            hi = mid
    return WrapJump(lo, measured, load * measured / (1.0 + measured))
