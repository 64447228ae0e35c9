"""The full nonlinear equilibrium of a self-regulating carrier (:func:`solve_equilibrium`,
exact polygon chain length, catenary spans) and the rational pivot (:func:`rational_pivot`)."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from .. import layout as L
from .._validation import check_nonnegative, check_range
from ..errors import ConvergenceError, InfeasibleError, InputError
from .sag import _catenary_excess, pivot_offset_for_coefficient, sag_length_excess, sag_stiffness
from .statics import (
    _GRAVITY_DIRECTION,
    _cross,
    _perp,
    _sides_per_turn,
    _slide_direction,
    carrier_position,
    regulation_coefficient,
    restoring_force,
    slack_tension,
    span_arms,
    worn_centre_distance,
)

__all__ = [
    "CarrierGeometry",
    "solve_equilibrium",
    "rational_pivot",
]

@dataclass(frozen=True)
class CarrierGeometry:
    """Everything fixed about one self-regulating drive (SI units), shared by both solvers.

    Built by :func:`self_regulating_drive` from its arguments (same names; ``pivot``,
    ``direction``, the centres and ``weight_offset`` as float arrays, ``direction``
    normalised). ``radii(e)`` gives the worn pitch radii of the carrier and fixed wheel
    [m]; ``tight_side`` the side of the centre line (``+1`` left of ``n = (C - F)/a``)
    on which the tight span runs; ``axial_stiffness`` the chain's ``EA`` [N] (``None``:
    inextensible); ``stretch(S1, S2, chord, e)`` its elastic elongation [m].
    """

    pitch: float
    bar_diameter: float | None
    teeth_carrier: int
    teeth_fixed: int
    carrier_centre: np.ndarray
    fixed_centre: np.ndarray
    links: int
    carrier_driving: bool
    travel: str
    kind: str
    pivot: np.ndarray | None
    direction: np.ndarray | None
    torque_reaction: str
    weight: float
    weight_offset: np.ndarray
    stiffness: float
    preload: float
    mass_per_length: float
    axial_stiffness: float | None = None

    def radii(self, elongation: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
        pw = self.pitch * (1.0 + np.asarray(elongation, dtype=float))
        rc = L.pitch_radius(pw, self.teeth_carrier, self.bar_diameter)
        rf = L.pitch_radius(pw, self.teeth_fixed, self.bar_diameter)
        return np.asarray(rc, dtype=float), np.asarray(rf, dtype=float)

    @property
    def tight_side(self) -> int:
        # ccw travel: the span into the carrier runs on the right of n = (C - F)/a
        into_carrier = -1 if self.travel == "ccw" else 1
        return into_carrier if self.carrier_driving else -into_carrier

    def stretch(self, tight_tension: ArrayLike, slack_tension: ArrayLike, chord: ArrayLike,
                elongation: ArrayLike) -> np.ndarray:
        """Elastic elongation of the whole chain: spans at S1 and S2, wraps at the mean [m]."""
        if self.axial_stiffness is None:
            return np.zeros(np.broadcast(tight_tension, slack_tension, chord).shape)
        S1 = np.asarray(tight_tension, dtype=float)
        S2 = np.asarray(slack_tension, dtype=float)
        ell = np.asarray(chord, dtype=float)
        length = self.links * self.pitch * (1.0 + np.asarray(elongation, dtype=float))
        return (S1 * ell + S2 * ell + 0.5 * (S1 + S2) * (length - 2.0 * ell)) / self.axial_stiffness

    @classmethod
    def example(cls) -> CarrierGeometry:
        """The example drive of the doctests: 25.4 mm pitch, 19/38 teeth,
        76 links, carrier 0.6 m from the fixed wheel on a pivot at (0.66, -0.045) m,
        400 N carrier weight 80 mm off its centre, 2.7 kg/m chain.

        Examples
        --------
        >>> CarrierGeometry.example().links
        76
        """
        return cls(pitch=0.0254, bar_diameter=None, teeth_carrier=19, teeth_fixed=38,
                   carrier_centre=np.array([0.6, 0.0]), fixed_centre=np.zeros(2), links=76,
                   carrier_driving=True, travel="ccw", kind="pivot",
                   pivot=np.array([0.66, -0.045]), direction=None,
                   torque_reaction="carrier", weight=400.0,
                   weight_offset=np.array([0.08, 0.0]), stiffness=0.0, preload=0.0,
                   mass_per_length=2.7)

    def carrier_kw(self) -> dict[str, Any]:
        return dict(kind=self.kind, pivot=None if self.pivot is None else tuple(self.pivot),
                    direction=None if self.direction is None else tuple(self.direction))


def _closed_form_state(geo: CarrierGeometry, effective_pull, elongation, centre_distance,
                       strict: bool = True):
    """Tensions and geometry at a given centre distance (closed forms).

    ``strict=False`` returns ``S2 <= 0`` instead of raising (used inside the root search).
    """
    kw = geo.carrier_kw()
    q, C = carrier_position(centre_distance, geo.fixed_centre, geo.carrier_centre, **kw)
    rc, rf = geo.radii(elongation)
    g1, g2 = span_arms(C, geo.fixed_centre, rc, rf, tight_side=geo.tight_side,
                       reference_centre=geo.carrier_centre, torque_reaction=geo.torque_reaction,
                       **kw)
    Q = restoring_force(q, C, geo.fixed_centre, reference_centre=geo.carrier_centre,
                        weight=geo.weight, weight_offset=geo.weight_offset,
                        stiffness=geo.stiffness, preload=geo.preload, **kw)
    psi = regulation_coefficient(g1, g2)
    if strict:
        S2 = slack_tension(effective_pull, g1, g2, Q)
    else:
        S2 = psi * effective_pull - Q / (g1 + g2)
    a = np.hypot(C[..., 0] - geo.fixed_centre[0], C[..., 1] - geo.fixed_centre[1])
    n = (C - geo.fixed_centre) / a[..., None]
    m = _perp(n)
    sb = (rc - rf) / a
    cb = np.sqrt(1.0 - sb**2)
    sig = geo.tight_side
    u_t = -cb[..., None] * n - sig * sb[..., None] * m
    u_s = -cb[..., None] * n + sig * sb[..., None] * m
    chord = a * cb
    return dict(q=q, C=C, g1=g1, g2=g2, Q=Q, S2=S2, psi=psi, S0=S2 - psi * effective_pull,
                u_t=u_t, u_s=u_s, chord=chord, incl_t=_inclination(u_t), incl_s=_inclination(u_s))


def _inclination(u):
    """Chord angle above the horizontal in [-π/2, π/2] of a direction vector."""
    return np.arctan2(u[..., 1] * np.sign(np.where(u[..., 0] == 0, 1.0, u[..., 0])),
                      np.abs(u[..., 0]))


def _reach(geo: CarrierGeometry) -> float:
    """Smallest centre distance the carrier reaches [m]."""
    F, C0 = geo.fixed_centre, geo.carrier_centre
    if geo.kind == "pivot":
        return abs(float(np.hypot(*(geo.pivot - F))) - float(np.hypot(*(C0 - geo.pivot))))
    b = float(np.dot(_slide_direction(geo), C0 - F))
    return math.sqrt(max(float(np.dot(C0 - F, C0 - F)) - b * b, 0.0))


def _closed_form(geo: CarrierGeometry, effective_pull, elongation):
    """Closed-form model: taut length (ISO form), carrier statics and parabolic sag; the
    compatibility ``L_taut(a) + Δ1 + Δ2 = N p'`` solved for ``a`` by vectorised bisection."""
    e = np.asarray(elongation, dtype=float)
    shape = np.broadcast(effective_pull, e).shape
    Ft = np.broadcast_to(effective_pull, shape)
    pw = geo.pitch * (1.0 + e)
    r1 = _sides_per_turn(geo.teeth_carrier, geo.bar_diameter) * pw / (2.0 * np.pi)
    r2 = _sides_per_turn(geo.teeth_fixed, geo.bar_diameter) * pw / (2.0 * np.pi)
    qm = geo.mass_per_length

    def mismatch(a):
        st = _closed_form_state(geo, Ft, e, a, strict=False)
        ok = st["S2"] > 0
        S2 = np.where(ok, st["S2"], 1.0)
        sag = (sag_length_excess(st["chord"], st["incl_t"], S2 + Ft, qm)
               + sag_length_excess(st["chord"], st["incl_s"], S2, qm))
        taut = 2.0 * a + np.pi * (r1 + r2) + (r2 - r1) ** 2 / a  # ISO 10823 form
        stretch = geo.stretch(S2 + Ft, S2, st["chord"], e)
        return np.where(ok, taut + sag - geo.links * pw - stretch, np.inf)

    hi = np.broadcast_to(worn_centre_distance(geo.links, geo.pitch, geo.teeth_carrier,
                                              geo.teeth_fixed, e, bar_diameter=geo.bar_diameter),
                         shape).copy()
    carrier_position(hi, geo.fixed_centre, geo.carrier_centre, **geo.carrier_kw())  # reach check
    if geo.axial_stiffness is not None:  # the stretch may exceed the sag: root above a_taut
        step = np.full(shape, 1e-4) * hi
        for _ in range(60):
            short = mismatch(hi) < 0
            if not np.any(short):
                break
            hi = np.where(short, hi + step, hi)
            step = np.where(short, 2.0 * step, step)
        carrier_position(hi, geo.fixed_centre, geo.carrier_centre, **geo.carrier_kw())
    floor = _reach(geo) * (1.0 + 1e-12) + 1e-12
    delta = np.full(shape, 1e-4) * hi
    lo = np.maximum(hi - delta, floor)
    for _ in range(60):
        need = mismatch(lo) >= 0
        if not np.any(need) or np.all(lo[need] <= floor):
            break
        delta = np.where(need, 2.0 * delta, delta)
        lo = np.where(need, np.maximum(hi - delta, floor), lo)
    bad = mismatch(lo) >= 0
    if np.any(bad):
        raise InfeasibleError(
            "no equilibrium with a taut chain for F_t in "
            f"[{np.min(Ft[bad]):g}, {np.max(Ft[bad]):g}] N, e in [{np.min(np.broadcast_to(e, shape)[bad]):g}, "
            f"{np.max(np.broadcast_to(e, shape)[bad]):g}]: the slack tension S2 = ψ F_t + S0 "
            "falls to zero, or the sag takes more chain than the carrier's travel gives; "
            "more weight or spring preload, or a pivot that gives ψ >= 0")
    for _ in range(48):  # the bracket is at most a few cm wide: 2⁻⁴⁸ of it is below 1e-15 m
        mid = 0.5 * (lo + hi)
        low = mismatch(mid) < 0
        lo = np.where(low, mid, lo)
        hi = np.where(low, hi, mid)
    a = 0.5 * (lo + hi)
    st = _closed_form_state(geo, Ft, e, a)
    st["a"] = a
    return st


def _carrier_stiffness(geo: CarrierGeometry, effective_pull, elongation, st) -> np.ndarray:
    """Full stiffness of the carrier at the closed-form equilibrium ``st`` (sag spring, arms,
    weight and spring; the last two by central differences of the closed forms)."""
    e = np.asarray(elongation, dtype=float)
    kw = geo.carrier_kw()
    a = st["a"]
    h = 1e-6 * a
    S2 = st["S2"]
    S1 = S2 + effective_pull
    rc, rf = geo.radii(e)

    def fixed_tension_force(aa):
        q, C = carrier_position(aa, geo.fixed_centre, geo.carrier_centre, **kw)
        g1, g2 = span_arms(C, geo.fixed_centre, rc, rf, tight_side=geo.tight_side,
                           reference_centre=geo.carrier_centre,
                           torque_reaction=geo.torque_reaction, **kw)
        Q = restoring_force(q, C, geo.fixed_centre, reference_centre=geo.carrier_centre,
                            weight=geo.weight, weight_offset=geo.weight_offset,
                            stiffness=geo.stiffness, preload=geo.preload, **kw)
        return q, S1 * g1 + S2 * g2 + Q

    qp, Qp = fixed_tension_force(a + h)
    qm, Qm = fixed_tension_force(a - h)
    dq = qp - qm
    pw = geo.pitch * (1.0 + e)
    r1 = _sides_per_turn(geo.teeth_carrier, geo.bar_diameter) * pw / (2.0 * np.pi)
    r2 = _sides_per_turn(geo.teeth_fixed, geo.bar_diameter) * pw / (2.0 * np.pi)
    qm_ = geo.mass_per_length
    d1 = sag_length_excess(st["chord"], st["incl_t"], S1, qm_)
    d2 = sag_length_excess(st["chord"], st["incl_s"], S2, qm_)
    elastic = 0.0 if geo.axial_stiffness is None else geo.links * pw / (2.0 * geo.axial_stiffness)
    Ks = sag_stiffness(2.0 * h / dq, 2.0 - (r2 - r1) ** 2 / a**2, np.arcsin((rc - rf) / a),
                       d1, S1, d2, S2, elastic)
    return Ks - (Qp - Qm) / dq


def solve_equilibrium(geometry: CarrierGeometry, effective_pull: float, elongation: float, *,
                      phases: int = 4, guess: float | None = None) -> tuple[float, float, float]:
    r"""Full nonlinear equilibrium of the carrier (numerical cross-check of the closed forms).

    .. math::
        \sum_i (P_i - O)\times S_i\mathbf{u}_i + M_W + M_s = 0,\qquad
        p' X_{poly}(a) + \Delta_{cat}(S_1) + \Delta_{cat}(S_2) = N p'

    Parameters
    ----------
    geometry : CarrierGeometry
        The drive.
    effective_pull : float
        ``F_t`` [N].
    elongation : float
        ``e`` [-].
    phases : int
        Phases per wheel for the polygon length (mean over ``phases²`` pairs).
    guess : float, optional
        Carrier coordinate to start the bracket from.

    Returns
    -------
    coordinate, centre_distance, slack_tension : float
        ``q`` [rad or m], ``a`` [m], ``S2`` [N].

    Notes
    -----
    Independent of the closed forms in every part: the tangent points and span
    directions come from :func:`chaindrive.layout.wrap_layout`; the moments are
    the cross products of the span forces about the pivot (or their components along
    the slide); the chain length is the phase mean of the exact polygon length
    (:func:`chaindrive.layout.chain_length_polygon`) of the worn pitch
    ``p(1+e)``; the spans hang as exact catenaries. The balance is linear in ``S2`` at
    a given carrier position; the length compatibility is solved for the coordinate by
    Brent's method.

    References
    ----------
    docs/self_regulating.md ("Numerical check").

    Examples
    --------
    >>> geo = CarrierGeometry.example()
    >>> q, a, S2 = solve_equilibrium(geo, 3000.0, 0.0)
    >>> round(a, 4), round(S2, 1)
    (0.5983, 1056.2)
    """
    from scipy.optimize import brentq

    if not isinstance(geometry, CarrierGeometry):
        raise InputError(f"geometry must be a CarrierGeometry, got {type(geometry).__name__}")
    geo = geometry
    e = float(check_range("elongation", elongation, 0.0, 0.1, high_inclusive=False))
    Ft = float(check_nonnegative("effective_pull", effective_pull, "N"))
    if int(phases) < 1:
        raise InputError(f"phases must be a whole number >= 1, got {phases}")
    pw = geo.pitch * (1.0 + e)
    rc, rf = (float(r) for r in geo.radii(e))
    F = geo.fixed_centre
    C0 = geo.carrier_centre
    qm = geo.mass_per_length
    if geo.kind == "pivot":
        O = geo.pivot
        kappa = 1.0 if _cross(C0 - O, C0 - F) >= 0 else -1.0
    else:
        d = _slide_direction(geo)
        u_sl = d / float(np.hypot(*d))
        kappa = 1.0 if float(np.dot(u_sl, C0 - F)) >= 0 else -1.0
    # tight span index in wrap_layout([F, C]): span 0 runs F -> C, span 1 C -> F (ccw loop)
    tight = 0 if (geo.carrier_driving == (geo.travel == "ccw")) else 1

    def centre(q):
        if geo.kind == "pivot":
            th = kappa * q
            c, s = math.cos(th), math.sin(th)
            r = C0 - O
            return O + np.array([c * r[0] - s * r[1], s * r[0] + c * r[1]]), th
        return C0 + kappa * q * u_sl, 0.0

    def state(q):
        C, th = centre(q)
        lay = L.wrap_layout(np.array([F, C]), [rf, rc])
        t = np.column_stack([np.cos(lay.span_angle), np.sin(lay.span_angle)])
        # pulls on the carrier wheel: span 0 ends on it (pull -t0), span 1 starts on it (+t1)
        pts = [lay.span_end[0], lay.span_start[1]]
        dirs = [-t[0], t[1]]
        if geo.kind == "pivot":
            arm_pts = pts if geo.torque_reaction == "carrier" else [C, C]
            A = [kappa * float(_cross(P - O, u)) for P, u in zip(arm_pts, dirs, strict=True)]
            c, s = math.cos(th), math.sin(th)
            G = C + np.array([c * geo.weight_offset[0] - s * geo.weight_offset[1],
                              s * geo.weight_offset[0] + c * geo.weight_offset[1]])
            QW = kappa * float(_cross(G - O, geo.weight * _GRAVITY_DIRECTION))
        else:
            A = [kappa * float(np.dot(u, u_sl)) for u in dirs]
            QW = kappa * geo.weight * float(np.dot(_GRAVITY_DIRECTION, u_sl))
        Qr = QW + geo.preload - geo.stiffness * q
        A_t, A_s = A[tight], A[1 - tight]
        S2 = -(Ft * A_t + Qr) / (A_t + A_s)
        return C, lay, S2

    def residual(q):
        try:
            C, lay, S2 = state(q)
        except InfeasibleError:
            return -geo.links * pw
        if not S2 > 0:
            return geo.links * pw  # a slack chain would need an infinitely long path
        a = float(np.hypot(*(C - F)))
        X = L.chain_length_polygon(pw, geo.teeth_fixed, geo.teeth_carrier, a,
                                   bar_diameter=geo.bar_diameter, phases=phases).links_mean
        S = np.where(np.arange(2) == tight, S2 + Ft, S2)
        incl = np.arctan(np.tan(lay.span_angle))
        sag = _catenary_excess(lay.span_length, incl, S, qm)
        stretch = 0.0
        if geo.axial_stiffness is not None:  # spans at their tensions, wraps at the mean
            wraps = geo.links * pw - float(np.sum(lay.span_length))
            stretch = (float(np.dot(S, lay.span_length)) + 0.5 * float(np.sum(S)) * wraps) / geo.axial_stiffness
        return X * pw + float(np.sum(sag)) - geo.links * pw - stretch

    q0 = 0.0 if guess is None else float(guess)
    step = 0.02 if geo.kind == "pivot" else 0.002
    lo, hi = q0 - step, q0 + step
    flo, fhi = residual(lo), residual(hi)
    for _ in range(60):
        if flo <= 0 <= fhi:
            break
        if flo > 0:
            lo -= step
            flo = residual(lo)
        if fhi < 0:
            hi += step
            fhi = residual(hi)
        step *= 1.6
    else:
        raise ConvergenceError(
            f"could not bracket the carrier position for F_t = {Ft:g} N, e = {e:g}")
    q = brentq(residual, lo, hi, xtol=1e-13, rtol=1e-13, maxiter=200)
    C, _, S2 = state(q)
    return float(q), float(np.hypot(*(C - F))), float(S2)


def _geometric_psi(geo: CarrierGeometry, elongation, pivot):
    """ψ of the taut worn chain (no sag) for a trial pivot."""
    e = np.asarray(elongation, dtype=float)
    a = worn_centre_distance(geo.links, geo.pitch, geo.teeth_carrier, geo.teeth_fixed, e,
                             bar_diameter=geo.bar_diameter)
    _, C = carrier_position(a, geo.fixed_centre, geo.carrier_centre, kind="pivot", pivot=pivot)
    rc, rf = geo.radii(e)
    g1, g2 = span_arms(C, geo.fixed_centre, rc, rf, tight_side=geo.tight_side, kind="pivot",
                       pivot=pivot, reference_centre=geo.carrier_centre)
    return regulation_coefficient(g1, g2)


def rational_pivot(geometry: CarrierGeometry, coefficient: float,
                   elongation_range: tuple[float, float] = (0.0, 0.03)) -> tuple[np.ndarray, float]:
    r"""Pivot that keeps ψ at a wanted value at both ends of the wear range.

    .. math:: \psi(e_0; O) - \psi^* = \psi^* - \psi(e_m; O) = \psi(e_1; O) - \psi^* = d,
              \qquad O = C_{mid} + x\,\mathbf n + \sigma_1 y\,\mathbf m

    Parameters
    ----------
    geometry : CarrierGeometry
        The drive; its ``pivot`` is replaced, the carrier wheel's reference position kept.
    coefficient : float
        Wanted ψ*, ``> -1/2`` [-].
    elongation_range : (float, float)
        New and most worn chain, ``0 <= e0 <= e1 < 0.1`` [-].

    Returns
    -------
    pivot : ndarray, shape (2,)
        [m], in the drive's coordinates.
    deviation : float
        Largest ``|ψ - ψ*|`` over 9 elongations in the range [-].

    Raises
    ------
    ConvergenceError
        No such pivot near the centre line (the root search failed).

    Notes
    -----
    Two effects move ψ as the chain wears: the carrier swings, turning the pivot's
    perpendicular offset ``y' = |(C - O) × n|`` (first order in the swing when the pivot
    lies off the normal through the wheel centre, ``dy'/dφ = -(O - C)·n``), and the
    worn chain rides higher on the teeth, ``R_C ∝ 1 + e``, which raises ψ by
    ``ΔR/(2y)``. Solving for both coordinates ``(x, y)`` of the pivot makes the two
    cancel over the range: ψ(e) is then U-shaped, and the pivot ``(x, y)`` and the
    half-width ``d`` are solved so that ψ is ``ψ* + d`` at both ends and ``ψ* - d`` at
    mid-range (equal ripple, close to the smallest largest deviation). ``C_mid`` is the
    carrier wheel centre on the given centre line at the mid-range taut centre distance. Closed forms of the taut
    chain (:func:`worn_centre_distance`, :func:`span_arms`), no sag; root by
    :func:`scipy.optimize.root` (hybrid Powell) from the one-point design
    :func:`pivot_offset_for_coefficient`. For a single elongation only ``y`` is solved,
    with the pivot on the normal (``x = 0``).

    References
    ----------
    Derived here (docs/self_regulating.md, "The rational ψ"); the self-regulating drive
    paper's conclusion that the limits of change of ``a`` with wear can be chosen so
    that ψ stays near its most rational value.

    Examples
    --------
    >>> geo = CarrierGeometry.example()
    >>> pivot, dev = rational_pivot(geo, 0.1, (0.0, 0.03))
    >>> pivot.round(4).tolist(), dev < 0.01
    ([0.621, -0.0627], True)
    """
    from scipy.optimize import root

    if not isinstance(geometry, CarrierGeometry):
        raise InputError(f"geometry must be a CarrierGeometry, got {type(geometry).__name__}")
    geo = geometry
    psi_star = float(check_range("coefficient", coefficient, -0.5, np.inf, low_inclusive=False))
    e0, e1 = (float(x) for x in check_range("elongation_range", elongation_range, 0.0, 0.1,
                                             high_inclusive=False))
    if e1 < e0:
        raise InputError(f"elongation_range must be (new, worn) with new <= worn, got {elongation_range}")
    F, C0 = geo.fixed_centre, geo.carrier_centre
    n0 = (C0 - F) / float(np.hypot(*(C0 - F)))
    m0 = _perp(n0)
    em = 0.5 * (e0 + e1)
    a_mid = float(worn_centre_distance(geo.links, geo.pitch, geo.teeth_carrier, geo.teeth_fixed,
                                       em, bar_diameter=geo.bar_diameter))
    C_mid = F + a_mid * n0
    rc, rf = (float(r) for r in geo.radii(em))
    y0 = float(pivot_offset_for_coefficient(psi_star, rc, math.asin((rc - rf) / a_mid)))

    def pivot_at(v):
        return C_mid + v[1] * n0 + geo.tight_side * v[0] * m0

    def residual(v):
        try:
            return _geometric_psi(geo, [e0, em, e1], pivot_at(v)) - psi_star - v[2] * np.array(
                [1.0, -1.0, 1.0])
        except (InfeasibleError, InputError):
            return np.array([1e3, 1e3, 1e3])

    if e1 - e0 < 1e-12:  # one elongation: ψ(e0) = ψ* with the pivot on the normal (x = 0)
        def fun(v):
            return residual(np.array([v[0], 0.0, 0.0]))[:1]

        sol = root(fun, np.array([y0]), method="hybr", options={"xtol": 1e-12})
        v = np.array([sol.x[0], 0.0, 0.0])
        ok = sol.success and abs(fun(sol.x)[0]) <= 1e-9
    else:
        sol = root(residual, np.array([y0, 0.0, 0.0]), method="hybr", options={"xtol": 1e-12})
        v = sol.x
        ok = sol.success and np.max(np.abs(residual(v))) <= 1e-9
    if not ok:
        raise ConvergenceError(
            f"no pivot found that keeps ψ = {psi_star:g} at e = {e0:g} and e = {e1:g} "
            f"({sol.message})")
    pivot = pivot_at(v)
    dev = float(np.max(np.abs(_geometric_psi(geo, np.linspace(e0, e1, 9), pivot) - psi_star)))
    return pivot, dev


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
