r"""Crawler drive unit of a conveyor: the whole-period workflow :func:`crawler_drive`
(kinematics with or without the guide, and the cam force) and the speed non-uniformity.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from ..._finite import finite_guard
from ..._registry import Registry
from ..._results import quantity
from ..._typing import FloatOrArray
from ..._validation import as_float_array, check_nonnegative, check_positive, check_teeth
from ...errors import InfeasibleError, InputError
from ...loads import mean_chain_speed
from ..histories import PeriodMotion
from .cam import cam_force, cam_pushing_off_force, cam_stiffness, guide_reaction
from .laws import (
    GUIDES,
    _geometry,
    _guided_parts,
    _omega,
    _out,
    free_span_acceleration,
    free_span_displacement,
    free_span_height,
    free_span_velocity,
    guide_link_angle,
    guided_acceleration,
    guided_displacement,
    guided_velocity,
    leaving_displacement,
)

__all__ = ["MEASURES", "SUMMARY_KEYS", "CrawlerKinematics", "crawler_drive", "crawler_nonuniformity"]

# ----------------------------------------------------------------------------- workflow

#: Keys of :attr:`CrawlerKinematics.summary` always present.
SUMMARY_KEYS = (
    "v_mean", "v_min", "v_max", "nonuniformity", "a_min", "a_max",
    "sign_change_at_period_end", "transverse_throw",
)


@dataclass(frozen=True)
class CrawlerKinematics(PeriodMotion):
    """Kinematics (and optionally the cam force) of the crawler drive over ``psi`` (the fields
    of :class:`~chaindrive.kinematics.histories.PeriodMotion` first).

    Attributes
    ----------
    psi : ndarray
        Sprocket angles ``ψ`` [rad] (default one period ``0 ... 2π/z``).
    displacement, velocity, acceleration : ndarray
        ``u`` [m], ``v`` [m/s], ``a`` [m/s²] of the drive chain at the driving sprocket
        (right-continuous at the period ends).
    transverse_position : ndarray
        Height of the chain above the sprocket axes [m] (``R`` with the guide).
    link_angle : ndarray or None
        ``φ1`` of eq. (6.15) [rad] (tangent guide only).
    force : ndarray or None
        Force on the cam [N] (:func:`cam_force`) with the cam driven at the mean speed
        (``u_П = v_mean t``), minus its mean over a period (the mean is the transmitted
        load, not a kinematic quantity); ``None`` without ``stiffness``.
    summary : dict
        The keys of :attr:`PeriodMotion.summary <chaindrive.kinematics.histories.PeriodMotion>`,
        plus ``a_end_left``, ``a_end_right``, ``a_jump_at_period_end`` [m/s²], ``psi_v_min``
        [rad], ``peak_deviation`` = max|v - v_mean| [m/s]; with stiffness ``cam_stiffness``
        [N/m], ``force_min``, ``force_max``, ``force_range`` [N]. Exact over a whole period
        (the minimum of the guided speed is found by root finding), not on ``psi``.
    guide : str
        ``"none"`` or ``"tangent"``.
    pitch, radius, teeth, angular_velocity, period
        ``t``, ``R`` [m], ``z``, ``ω`` [rad/s], ``2π/z`` [rad] (:class:`PeriodMotion`).
    stiffness, sprocket_distance, cam_distance : float or None
        ``E_П`` [N], ``A`` [m], ``l`` [m].
    """

    psi: np.ndarray = quantity("rad")
    displacement: np.ndarray = quantity("m")
    transverse_position: np.ndarray = quantity("m")
    link_angle: np.ndarray | None = quantity("rad")
    force: np.ndarray | None = quantity("N")
    guide: str
    stiffness: float | None = quantity("N", default=None)
    sprocket_distance: float | None = quantity("m", default=None)
    cam_distance: float | None = quantity("m", default=None)


def _guided_vmin_angle(t, R, gamma):
    """Angle of the guided speed minimum: root of a(ψ) in (0, 2γ), vectorised bisection."""
    t, R, gamma = np.broadcast_arrays(np.asarray(t, float), np.asarray(R, float),
                                      np.asarray(gamma, float))
    lo = 1e-6 * gamma
    hi = 2.0 * gamma * (1.0 - 1e-12)

    def acc(s):
        sp, cp = _guided_parts(s, t, R)
        return -np.sin(s) + np.cos(s) * sp / cp + R * np.sin(s) ** 2 / (t * cp**3)

    for _ in range(80):
        mid = 0.5 * (lo + hi)
        neg = acc(mid) < 0
        lo = np.where(neg, mid, lo)
        hi = np.where(neg, hi, mid)
    return 0.5 * (lo + hi)


#: Measures of speed non-uniformity for :func:`crawler_nonuniformity`.
MEASURES = Registry("measure")
MEASURES.add("range", "range")
MEASURES.add("peak_deviation", "peak_deviation")


def crawler_nonuniformity(teeth: ArrayLike, guide: str="tangent", measure: str="range") -> FloatOrArray:
    r"""Speed non-uniformity ``(v_max - v_min)/v_mean`` of the crawler drive chain [-].

    .. math::
        δ_{none} = (1 - \cos γ)\,\frac{γ}{\sin γ},\qquad
        δ_{tangent} = \left(1 - \frac{\cos(ψ^* - φ^*)}{\cos φ^*}\right)\frac{γ}{\sin γ}

    Parameters
    ----------
    teeth : int or array_like
        ``z >= 3`` [-] (vectorised).
    guide : {"tangent", "none"}
        Guide type.
    measure : {"range", "peak_deviation"}
        ``"range"``: ``(v_max - v_min)/v_mean`` (the usual coefficient);
        ``"peak_deviation"``: ``max|v - v_mean| / v_mean``.

    Returns
    -------
    ndarray or float
        Non-uniformity, independent of pitch and speed [-].

    Notes
    -----
    ``v_max = ωR`` in both cases and ``v_mean = zωt/2π = ωR sin γ / γ``. With the guide
    ``ψ*`` is the root of ``a(ψ) = 0`` in ``(0, 2γ)`` (≈ ``4γ/3``). For small ``γ``:
    ``δ_none ≈ γ²/2``, ``δ_tangent ≈ 8γ²/27``; the ratio tends to ``16/27 ≈ 0.593``
    (the crawler drive text claims "almost 2 times"; it is a factor of about 1.69). The peak
    deviation from the mean, ``max|v - v_mean|``, is halved: free ``v_mean - v_min ≈
    ωRγ²/3``, guided ``v_max - v_mean ≈ ωRγ²/6``.

    References
    ----------
    the crawler drive text, eqs (6.7), (6.14)-(6.16) and the text to Fig. 6.9 c.

    Examples
    --------
    >>> r = crawler_nonuniformity(8, "tangent") / crawler_nonuniformity(8, "none")
    >>> round(float(r), 4)
    0.5923
    """
    kind = GUIDES.get(guide)
    how = MEASURES.get(measure)
    z = check_teeth("teeth", teeth)
    gamma = np.pi / z
    vmean = np.sin(gamma) / gamma  # in units of ωR
    if kind == "none":
        vmin = np.cos(gamma)
    else:
        t = 1.0
        R = 0.5 / np.sin(gamma)
        s = _guided_vmin_angle(t, R, gamma)
        sp, cp = _guided_parts(s, t, R)
        vmin = np.cos(s) + np.sin(s) * sp / cp
    if how == "range":
        return _out((1.0 - vmin) / vmean)
    return _out(np.maximum(1.0 - vmean, vmean - vmin) / vmean)


@finite_guard
def crawler_drive(pitch: float, teeth: int, angular_velocity: float, *, guide: str="tangent", with_guide: bool | None=None,
                  points: int=361, psi: ArrayLike | None=None, stiffness: float | None=None, sprocket_distance: float | None=None,
                  cam_distance: float | None=None, tension: float | None = None,
                  traction_force: float = 0.0, cam_face_angle: float = 0.0) -> CrawlerKinematics:
    r"""Kinematics of the crawler drive chain with or without the tangent guide (the crawler drive text).

    .. math:: v_{none} = ωR\cos(ψ - γ),\qquad
              v_{tangent} = ωR\,\frac{\cos(ψ_1 - φ_1)}{\cos φ_1},\ \
              R = R\cos ψ_1 + t\sin φ_1

    Parameters
    ----------
    pitch : float
        Drive-chain pitch ``t`` [m].
    teeth : int
        Tooth count ``z >= 3`` of both sprockets [-].
    angular_velocity : float
        Sprocket angular velocity ``ω > 0`` [rad/s].
    guide : {"tangent", "none"}
        Tangent guide (chain axis tangent to the pitch circles) or no guide.
    with_guide : bool, optional
        Alternative to ``guide``: ``True`` -> ``"tangent"``, ``False`` -> ``"none"``.
    points : int
        Samples over one period when ``psi`` is not given (``>= 2``).
    psi : array_like, optional
        Sprocket angles [rad] to evaluate at instead of one period.
    stiffness : float, optional
        ``E_П`` = ``EA`` of the drive chain [N]; with ``sprocket_distance`` and
        ``cam_distance`` adds the cam force.
    sprocket_distance : float, optional
        ``A`` [m], a whole number of pitches (sprockets in phase).
    cam_distance : float, optional
        ``l`` from the tensioning sprocket, ``0 < l < A`` [m].
    tension : float, optional
        Tension ``T`` of the span on the guide [N]; with the tangent guide adds the
        largest guide reaction ``T tan φ1`` (:func:`guide_reaction`) to the summary.
    traction_force : float
        Mean force on the cam (the traction force it passes to the conveyor) [N],
        ``>= 0``; added to the cam force's fluctuation for ``cam_force_max`` and the
        pushing-off force.
    cam_face_angle : float
        Pressure angle ``α`` of the cam face [rad], ``0 <= α < π/2``; with the cam force
        adds the pushing-off force ``P tan α`` (:func:`cam_pushing_off_force`).

    Returns
    -------
    CrawlerKinematics

    Notes
    -----
    The cam force assumes the traction chain moves the cam at the mean speed
    (``u_П = v_mean t``, a heavy conveyor) and, with the guide, takes the running-off
    law at the tensioning sprocket (:func:`leaving_displacement`). Valid for constant
    ``ω``, rigid sprockets, in-phase sprockets with equal ``z``.

    References
    ----------
    the crawler drive text, eqs (6.7), (6.14)-(6.16), Fig. 6.9; cam force rebuilt (see :func:`cam_force`).

    Examples
    --------
    >>> r = crawler_drive(0.1, 8, 3.0, guide="tangent", points=5)
    >>> round(r.summary["v_mean"], 9) == round(8 * 0.1 * 3.0 / (2 * np.pi), 9)
    True
    >>> round(r.summary["nonuniformity"], 5)
    0.04627
    """
    if with_guide is not None:
        if not isinstance(with_guide, (bool, np.bool_)):
            raise InputError(f"with_guide must be True or False, got {with_guide!r}")
        kind = "tangent" if with_guide else "none"
    else:
        kind = GUIDES.get(guide)
    t, z, gamma, R = _geometry(pitch, teeth)
    if t.ndim or z.ndim:
        raise InputError("pitch and teeth must be scalars in crawler_drive (vectorise over psi)")
    t, z, R = float(t), int(z), float(R)
    w = _omega(angular_velocity)
    if w.ndim:
        raise InputError("angular_velocity must be a scalar in crawler_drive")
    w = float(w)
    period = 2.0 * gamma
    if psi is None:
        from ...limits import MAX_POINTS, check_size

        psi = np.linspace(0.0, period, check_size("points", points, MAX_POINTS, minimum=2))
    psi = np.atleast_1d(as_float_array("psi", psi))
    if kind == "none":
        u = free_span_displacement(psi, t, z)
        v = free_span_velocity(psi, t, z, w)
        a = free_span_acceleration(psi, t, z, w)
        y = free_span_height(psi, t, z)
        link = None
    else:
        u = guided_displacement(psi, t, z)
        v = guided_velocity(psi, t, z, w)
        a = guided_acceleration(psi, t, z, w)
        y = np.full_like(psi, R)
        link = guide_link_angle(psi, t, z)
    # right-continuous at the end of the period: keep the value at exactly 2γ left-sided
    # when psi is the default grid so that the curves close the period
    end = np.isclose(psi, period, rtol=0, atol=1e-12 * period)
    if np.any(end):
        left = period * (1.0 - 1e-13)
        if kind == "none":
            a = np.where(end, free_span_acceleration(left, t, z, w), a)
        else:
            a = np.where(end, guided_acceleration(left, t, z, w), a)
    v_mean = mean_chain_speed(z, t, w)
    v_max = w * R
    if kind == "none":
        psi_min = 0.0
        v_min = w * R * np.cos(gamma)
        a_left, a_right = -(w**2) * R * np.sin(gamma), w**2 * R * np.sin(gamma)
        a_min, a_max = a_left, a_right
        throw = R * (1.0 - np.cos(gamma))
    else:
        psi_min = float(_guided_vmin_angle(t, R, gamma))
        v_min = float(guided_velocity(psi_min, t, z, w))
        a_left, a_right = w**2 * R * np.tan(gamma), 0.0
        grid = np.linspace(0.0, period * (1.0 - 1e-13), 4001)
        ag = guided_acceleration(grid, t, z, w)
        i = int(np.argmin(ag))
        from scipy.optimize import minimize_scalar

        opt = minimize_scalar(lambda p: float(guided_acceleration(p, t, z, w)),
                              bounds=(grid[max(i - 1, 0)], grid[min(i + 1, grid.size - 1)]),
                              method="bounded", options={"xatol": 1e-14 * period})
        a_min = min(float(np.min(ag)), float(opt.fun))
        a_max = max(float(np.max(ag)), a_left)
        throw = 0.0
    summary = {
        "v_mean": v_mean,
        "v_min": float(v_min),
        "v_max": float(v_max),
        "nonuniformity": float((v_max - v_min) / v_mean),
        "a_min": float(a_min),
        "a_max": float(a_max),
        "sign_change_at_period_end": bool(a_left * a_right < 0),
        "transverse_throw": float(throw),
        "a_end_left": float(a_left),
        "a_end_right": float(a_right),
        "a_jump_at_period_end": float(a_right - a_left),
        "psi_v_min": float(psi_min),
        "peak_deviation": float(max(v_max - v_mean, v_mean - v_min)),
    }
    force = None
    given = [x is not None for x in (stiffness, sprocket_distance, cam_distance)]
    if any(given) and not all(given):
        raise InputError("the cam force needs all of stiffness (E_П > 0 N), "
                         "sprocket_distance (A > 0 m) and cam_distance (0 < l < A m)")
    if stiffness is not None and sprocket_distance is not None and cam_distance is not None:
        if any(np.ndim(x) for x in (stiffness, sprocket_distance, cam_distance)):
            raise InputError("stiffness, sprocket_distance and cam_distance must be scalars in "
                             "crawler_drive (use cam_force for arrays)")
        E = float(check_positive("stiffness", stiffness, "N"))
        A = float(check_positive("sprocket_distance", sprocket_distance, "m"))
        ratio = A / t
        if abs(ratio - round(ratio)) > 1e-9 * max(ratio, 1.0) or round(ratio) < 1:
            lo_, hi_ = max(np.floor(ratio), 1.0) * t, np.ceil(ratio) * t
            raise InfeasibleError(
                f"sprocket_distance must be a whole number of pitches (in-phase sprockets): "
                f"A = {A:g} m is {ratio:g} t; nearest valid {lo_:g} m or {hi_:g} m")
        k = float(cam_stiffness(E, A, cam_distance))
        l = float(cam_distance)

        def _force(p):
            u2 = guided_displacement(p, t, z) if kind == "tangent" else free_span_displacement(p, t, z)
            u1 = leaving_displacement(p, t, z, kind)
            return cam_force(E, A, l, u2, v_mean * p / w, u1)

        fine = np.linspace(0.0, period, 4001)
        ff = _force(fine)
        mean = float(np.trapezoid(ff, fine) / period)
        force = _force(psi) - mean
        summary.update({
            "cam_stiffness": k,
            "force_min": float(ff.min() - mean),
            "force_max": float(ff.max() - mean),
            "force_range": float(ff.max() - ff.min()),
        })
        F = float(check_nonnegative("traction_force", traction_force, "N"))
        peak = max(abs(F + summary["force_min"]), abs(F + summary["force_max"]))
        summary["cam_force_max"] = F + summary["force_max"]
        summary["cam_pushing_off_max"] = float(cam_pushing_off_force(peak, cam_face_angle))
    if tension is not None and kind == "tangent":
        # largest where the hinge on the guide is about to seat: phi1 -> gamma
        near_seat = period * (1.0 - 1e-13)
        summary["guide_reaction_max"] = float(guide_reaction(tension, guide_link_angle(near_seat, t, z)))
    return CrawlerKinematics(
        psi=psi, displacement=np.asarray(u), velocity=np.asarray(v),
        acceleration=np.asarray(a), transverse_position=np.asarray(y),
        link_angle=None if link is None else np.asarray(link), force=force,
        summary=summary, guide=kind, pitch=t, radius=R, teeth=z, angular_velocity=w,
        period=period,
        stiffness=None if stiffness is None else float(stiffness),
        sprocket_distance=None if sprocket_distance is None else float(sprocket_distance),
        cam_distance=None if cam_distance is None else float(cam_distance),
    )
