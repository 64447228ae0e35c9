r"""Crawler drive unit of a conveyor: the elastic drive chain, the force on the cam and the
guide reaction (the crawler drive text, text after eq. (6.16); the formula is lost in the OCR
and rebuilt here).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from ..._results import Result, quantity
from ..._typing import FloatOrArray
from ..._validation import as_float_array, check_positive, check_teeth
from ...errors import InputError
from .laws import (
    GUIDES,
    _out,
    free_span_displacement,
    free_span_velocity,
    guided_displacement,
    guided_velocity,
    leaving_displacement,
)

__all__ = ["ElasticLoop", "cam_force", "cam_hinge_distance", "cam_pushing_off_force", "cam_stiffness",
           "elastic_loop", "guide_reaction"]


def cam_stiffness(stiffness: ArrayLike, sprocket_distance: ArrayLike, cam_distance: ArrayLike) -> FloatOrArray:
    r"""Stiffness of the drive chain at the cam hinge, two segments in parallel [N/m].

    .. math:: k = \frac{E_П}{l} + \frac{E_П}{A - l} = \frac{E_П\,A}{l\,(A - l)}

    Parameters
    ----------
    stiffness : float or array_like
        Reduced stiffness ``E_П`` of the drive chain, as axial rigidity ``EA`` [N]
        (force per unit strain; a segment of length ``L`` has stiffness ``E_П/L``).
    sprocket_distance : float or array_like
        Centre distance ``A`` between the sprockets [m].
    cam_distance : float or array_like
        Distance ``l`` of the cam hinge from the tensioning sprocket, ``0 < l < A`` [m].

    Returns
    -------
    ndarray or float
        ``k`` [N/m]; smallest, ``4E_П/A``, at ``l = A/2``; ``k -> inf`` as ``l -> 0``
        or ``l -> A`` (the cam sits on a sprocket).

    Notes
    -----
    The cam hinge splits the working span into a segment ``l`` to the tensioning
    sprocket and ``A - l`` to the driving sprocket. Both sprocket ends impose
    displacements on the chain and the cam hinge is displaced against both, so the
    segments act in **parallel** (same displacement difference, forces add), not in
    series. Linear elastic chain, massless, tension always positive (pre-tension),
    no friction on the guide.

    References
    ----------
    the crawler drive text, text after eq. (6.16) (formula lost in the OCR; rebuilt).

    Examples
    --------
    >>> float(cam_stiffness(1e6, 2.0, 1.0))   # 4 E/A
    2000000.0
    """
    E = check_positive("stiffness", stiffness, "N")
    A = check_positive("sprocket_distance", sprocket_distance, "m")
    l = as_float_array("cam_distance", cam_distance)
    if np.any(~(l > 0)) or np.any(~(l < A)) or np.any(~np.isfinite(l)):
        raise InputError(
            f"cam_distance must lie in (0, sprocket_distance) = (0, A) m, got l = {l} with A = {A}"
        )
    return _out(E * A / (l * (A - l)))


def cam_force(stiffness: ArrayLike, sprocket_distance: ArrayLike, cam_distance: ArrayLike, sprocket_displacement: ArrayLike,
              cam_displacement: ArrayLike, tensioning_displacement: ArrayLike | None=None) -> FloatOrArray:
    r"""Force of the elastic drive chain on the cam hinge [N].

    .. math::
        P = E_П\left[\frac{u_З - u_П}{A - l} + \frac{u_1 - u_П}{l}\right]
        \;\overset{u_1 = u_З}{=}\; \frac{E_П\,A}{l\,(A - l)}\,(u_З - u_П)

    Parameters
    ----------
    stiffness : float or array_like
        ``E_П`` = ``EA`` of the drive chain [N].
    sprocket_distance : float or array_like
        ``A`` [m].
    cam_distance : float or array_like
        ``l`` from the tensioning sprocket, ``0 < l < A`` [m]; ``l = l1 + k t_K``
        (:func:`cam_hinge_distance`).
    sprocket_displacement : float or array_like
        ``u_З``: displacement of the drive chain at the driving sprocket [m].
    cam_displacement : float or array_like
        ``u_П``: displacement of the cam hinge (imposed by the traction chain) [m].
    tensioning_displacement : float or array_like, optional
        ``u_1``: displacement of the drive chain at the tensioning sprocket [m];
        default ``u_З`` (sprockets in phase with the same law: exact without a guide).

    Returns
    -------
    ndarray or float
        ``P`` [N], positive in the direction of motion (the chain pulls the cam ahead).

    Notes
    -----
    Assumptions (stated; the text's formula is lost): (1) the return span is rigid, so
    (2) the tensioning sprocket turns in phase with the driving one and *imposes its own
    displacement* ``u_1`` on the working span (its axis fixed). :func:`elastic_loop` drops
    both (elastic return span, free tensioning sprocket) and tends to this formula as the
    return span's stiffness grows (tested; docs/crawler.md §2a): with a return span as
    stiff as the working span the fluctuation of ``P`` is smaller, so the formula errs on
    the safe side for the cam's strength. Equilibrium of the cam hinge between the two segments: segment ``A - l`` is
    stretched by ``u_З - u_П`` (force ``E_П (u_З - u_П)/(A - l)``), segment ``l`` by
    ``u_1 - u_П``; the forces add (parallel). With a common end law the paper's
    quantities ``E_П, A, l, u_З, u_П`` give the closed form above. Forces are changes
    about the static pre-tension. Limits: ``l -> 0`` gives ``E_П (u_1 - u_П)/l`` (the
    near segment dominates); ``E_П -> inf`` at fixed force forces ``u_П -> u_З``.

    References
    ----------
    the crawler drive text, text after eq. (6.16) (formula lost in the OCR; rebuilt).

    Examples
    --------
    >>> float(cam_force(1e6, 2.0, 0.5, 1e-3, 0.0))   # 1e6*2/(0.5*1.5) * 1e-3
    2666.6666666666665
    """
    E = check_positive("stiffness", stiffness, "N")
    A = check_positive("sprocket_distance", sprocket_distance, "m")
    cam_stiffness(E, A, cam_distance)  # validates l
    l = as_float_array("cam_distance", cam_distance)
    u2 = as_float_array("sprocket_displacement", sprocket_displacement)
    up = as_float_array("cam_displacement", cam_displacement)
    u1 = u2 if tensioning_displacement is None else as_float_array(
        "tensioning_displacement", tensioning_displacement)
    for name, arr in (("sprocket_displacement", u2), ("cam_displacement", up),
                      ("tensioning_displacement", u1)):
        if np.any(~np.isfinite(arr)):
            raise InputError(f"{name} must be finite (-inf < u < inf m)")
    return _out(E * ((u2 - up) / (A - l) + (u1 - up) / l))


def cam_hinge_distance(engagement_distance: float, cam_pitch: float, index: ArrayLike) -> FloatOrArray:
    r"""Distance ``l = l1 + k t_K`` of the k-th cam hinge from the tensioning sprocket [m].

    .. math:: l = l_1 + k\,t_K

    Parameters
    ----------
    engagement_distance : float
        ``l1``: value of ``l`` at which a cam engages a hinge of the traction chain [m].
    cam_pitch : float
        Cam pitch ``t_K`` [m].
    index : int or array_like
        ``k = 0, 1, 2, ...`` [-].

    Returns
    -------
    ndarray or float
        ``l`` [m].

    Notes
    -----
    Pure bookkeeping; check ``0 < l < A`` with :func:`cam_stiffness`.

    References
    ----------
    the crawler drive text, last line.

    Examples
    --------
    >>> float(cam_hinge_distance(0.3, 0.4, 2))
    1.1
    """
    l1 = check_positive("engagement_distance", engagement_distance, "m")
    tk = check_positive("cam_pitch", cam_pitch, "m")
    k = as_float_array("index", index)
    if np.any(k < 0) or np.any(k != np.round(k)):
        raise InputError(f"index must be a whole number >= 0, got {k}")
    return _out(l1 + k * tk)




# ----------------------------------------------------------------------------- guide reaction


def guide_reaction(tension: ArrayLike, link_angle: ArrayLike) -> FloatOrArray:
    r"""Force the guide takes at the first hinge on it, where the chain leaves the polygon [N].

    .. math:: N = T\,\tan φ_1

    Parameters
    ----------
    tension : float or array_like
        Tension ``T`` of the span on the guide at that end [N], ``T >= 0``.
    link_angle : float or array_like
        Inclination ``φ1`` of the link between the seated hinge and the hinge on the
        guide (eq. 6.15, :func:`~chaindrive.kinematics.crawler.guide_link_angle`),
        ``0 <= φ1 < π/2`` [rad]; at most ``γ = π/z``.

    Returns
    -------
    ndarray or float
        ``N`` [N], directed from the guide line towards the sprocket axis (the inclined
        link pulls the hinge off the guide; the guide, embracing the chain, holds it).

    Notes
    -----
    Statics of the massless hinge ``G`` on the guide line: the link ``SG`` pulls it
    with ``T_1`` at ``φ1`` below the guide, the next link along the guide with
    ``T``; frictionless guide, force ``N`` normal to it. Along the guide
    ``T_1 cos φ1 = T``; across it ``N = T_1 sin φ1 = T tan φ1``. Largest,
    ``T tan(π/z)``, just before the hinge seats. These are, with the cam's own
    :func:`cam_pushing_off_force`, the "pushing-off forces" the guide receives
    (the crawler drive text: «направляющую, охватывающую цепь, которая воспринимает
    отжимающие усилия, действующие на кулак»); without a guide the same forces move
    the span sideways (the transverse throw).

    References
    ----------
    the crawler drive text, text to Fig. 6.9 b and eq. (6.15); statics derived here.

    Examples
    --------
    >>> import numpy as np
    >>> round(float(guide_reaction(10e3, np.pi / 8)), 3)   # T tan(pi/z), z = 8
    4142.136
    """
    T = as_float_array("tension", tension)
    phi = as_float_array("link_angle", link_angle)
    if np.any(~np.isfinite(T)) or np.any(T < 0):
        raise InputError(f"tension must be finite and >= 0 N (0 <= T < inf), got {T}", field="tension")
    if np.any(~np.isfinite(phi)) or np.any(phi < 0) or np.any(phi >= np.pi / 2):
        raise InputError(f"link_angle must lie in [0, pi/2) rad, got {phi}", field="link_angle")
    return _out(T * np.tan(phi))


def cam_pushing_off_force(cam_force: ArrayLike, face_angle: ArrayLike) -> FloatOrArray:
    r"""Force pushing the cam off the traction chain, taken by the guide [N].

    .. math:: N_K = |P|\,\tan α

    Parameters
    ----------
    cam_force : float or array_like
        Force ``P`` along the chain between the cam and the traction-chain hinge [N].
    face_angle : float or array_like
        Pressure angle ``α`` of the cam's working face: the angle between the contact
        normal and the chain axis, ``0 <= α < π/2`` [rad] (``0``: a face square to the
        chain, no pushing-off force).

    Returns
    -------
    ndarray or float
        ``N_K`` [N], across the chain, away from the traction chain.

    Notes
    -----
    The contact force between the cam face and the traction-chain hinge is normal to
    the face (frictionless); its component along the chain is ``P``, across it
    ``P tan α``. The guide embracing the drive chain takes this force (the crawler
    drive text: the guide «воспринимает отжимающие усилия, действующие на кулак»).
    Friction on the face (coefficient ``μ``) would turn ``α`` into ``α ± atan μ``
    depending on the sliding direction; not included.

    References
    ----------
    the crawler drive text, text to Fig. 6.9 b; statics derived here.

    Examples
    --------
    >>> import numpy as np
    >>> round(float(cam_pushing_off_force(20e3, np.radians(20))), 3)
    7279.404
    """
    P = as_float_array("cam_force", cam_force)
    a = as_float_array("face_angle", face_angle)
    if np.any(~np.isfinite(P)):
        raise InputError("cam_force must be finite (-inf < P < inf N)", field="cam_force")
    if np.any(~np.isfinite(a)) or np.any(a < 0) or np.any(a >= np.pi / 2):
        raise InputError(f"face_angle must lie in [0, pi/2) rad (0...90 deg), got {a}", field="face_angle")
    return _out(np.abs(P) * np.tan(a))


# ----------------------------------------------------------------------------- the elastic loop


@dataclass(frozen=True)
class ElasticLoop(Result):
    """The drive-chain loop with an elastic return span and a free tensioning sprocket.

    Attributes
    ----------
    psi : ndarray
        Driving-sprocket angle ``ψ`` [rad].
    force : ndarray
        Force on the cam ``P = T_b - T_a`` [N] (total, not about its mean).
    rigid_force : ndarray
        The same from :func:`cam_force` with the tensioning sprocket in phase
        (``θ = ψ``: rigid return span) [N].
    lag : ndarray
        ``θ - ψ``: how far the tensioning sprocket runs ahead of the in-phase position [rad].
    tension_tensioning_side, tension_driving_side, tension_return : ndarray
        Total tensions of the segment tensioning sprocket–cam ``T_a``, cam–driving
        sprocket ``T_b`` and of the return span ``T_c`` [N].
    """

    psi: np.ndarray = quantity("rad")
    force: np.ndarray = quantity("N")
    rigid_force: np.ndarray = quantity("N")
    lag: np.ndarray = quantity("rad")
    tension_tensioning_side: np.ndarray = quantity("N")
    tension_driving_side: np.ndarray = quantity("N")
    tension_return: np.ndarray = quantity("N")


def _running_on(angle, t, z, kind):
    return guided_displacement(angle, t, z) if kind == "tangent" else free_span_displacement(angle, t, z)


def _running_on_rate(angle, t, z, kind):
    """du/dψ of the running-on law (velocity at ω = 1)."""
    return guided_velocity(angle, t, z, 1.0) if kind == "tangent" else free_span_velocity(angle, t, z, 1.0)


def _leaving_rate(angle, t, z, kind):
    """du_1/dψ of the running-off law: the running-on rate at the mirrored phase."""
    gamma = np.pi / z
    s = np.mod(angle, 2 * gamma)
    return _running_on_rate(2 * gamma - s, t, z, kind) if kind == "tangent" else _running_on_rate(angle, t, z, kind)


def elastic_loop(psi: ArrayLike, pitch: float, teeth: int, stiffness: float, sprocket_distance: float,
                 cam_distance: float, cam_displacement: ArrayLike, *, pretension: float,
                 guide: str = "tangent", return_guide: str = "none",
                 return_stiffness: float | None = None) -> ElasticLoop:
    r"""Force on the cam with an elastic return span and a free tensioning sprocket [N].

    The check of the two assumptions of :func:`cam_force` (rigid return span, tensioning
    sprocket in phase with the driving one, imposing its own displacement): here the
    tensioning sprocket is free (massless, frictionless bearing) and turns to the angle
    ``θ`` at which its two spans balance,

    .. math::
        T_a\,\frac{du_1}{dθ}(θ) = T_c\,\frac{du_r}{dθ}(θ),\qquad
        T_a = T_0 + \frac{E_П}{l}(u_П - u_1(θ)),\quad
        T_b = T_0 + \frac{E_П}{A - l}(u_З(ψ) - u_П),\quad
        T_c = T_0 + \frac{E_c}{A}(u_r(θ) - u_{r2}(ψ)),

    and the force on the cam is ``P = T_b - T_a``. ``u_1`` is the running-off law of the
    working span at the tensioning sprocket, ``u_r`` the running-on law of the return
    span there, ``u_{r2}`` its running-off law at the driving sprocket.

    Parameters
    ----------
    psi : array_like
        Driving-sprocket angles ``ψ`` [rad].
    pitch : float
        ``t`` [m].
    teeth : int
        ``z`` of both sprockets.
    stiffness : float
        ``E_П`` = ``EA`` of the drive chain [N].
    sprocket_distance : float
        ``A`` [m] (the return span is as long as the working span).
    cam_distance : float
        ``l`` from the tensioning sprocket [m], ``0 < l < A``.
    cam_displacement : array_like
        ``u_П`` at each ``ψ`` [m] (imposed by the traction chain).
    pretension : float
        ``T_0`` [N], the tension of every span with the chain at rest (``> 0``).
    guide, return_guide : {"tangent", "none"}
        Guide of the working span and of the return span.
    return_stiffness : float, optional
        ``E_c`` = ``EA`` of the return span [N]; default ``E_П``.

    Returns
    -------
    ElasticLoop

    Notes
    -----
    Quasi-static, massless chain and sprocket; the balance is solved for ``θ`` near ``ψ``
    by bracketing root finding. As ``E_c -> inf`` the return span becomes rigid,
    ``θ -> ψ`` (for the same law on both ends of the return span) and ``P`` tends to
    :func:`cam_force` with ``u_1`` the running-off law: the closed form's limit
    (tested). With ``E_c = E_П`` the difference measures what the assumptions cost.

    References
    ----------
    the crawler drive text, text after eq. (6.16) (formula lost in the OCR); model built here.

    Examples
    --------
    >>> import numpy as np
    >>> psi = np.array([0.1])
    >>> u_cam = 8 * 0.1 / (2 * np.pi) * psi          # the cam at the mean speed
    >>> r = elastic_loop(psi, 0.1, 8, 5e6, 2.0, 0.7, u_cam, pretension=5e3)
    >>> round(float(r.rigid_force[0]), 1), round(float(r.force[0]), 1)
    (2008.5, 1458.2)
    """
    from scipy.optimize import brentq

    t = float(check_positive("pitch", pitch, "m"))
    z = int(check_teeth("teeth", teeth))
    E = float(check_positive("stiffness", stiffness, "N"))
    A = float(check_positive("sprocket_distance", sprocket_distance, "m"))
    Ec = E if return_stiffness is None else float(check_positive("return_stiffness", return_stiffness, "N"))
    T0 = float(check_positive("pretension", pretension, "N"))
    l = float(cam_distance)
    cam_stiffness(E, A, l)  # validates l
    kind, rkind = GUIDES.get(guide), GUIDES.get(return_guide)
    p = np.atleast_1d(as_float_array("psi", psi))
    up = np.broadcast_to(as_float_array("cam_displacement", cam_displacement), p.shape)
    if np.any(~np.isfinite(p)) or np.any(~np.isfinite(up)):
        raise InputError("psi and cam_displacement must be finite", field="psi")
    gamma = np.pi / z

    def tensions(theta, psi_, up_):
        u1 = float(leaving_displacement(theta, t, z, kind))
        ur = float(_running_on(theta, t, z, rkind))
        ur2 = float(leaving_displacement(psi_, t, z, rkind))
        Ta = T0 + E / l * (up_ - u1)
        Tc = T0 + Ec / A * (ur - ur2)
        return Ta, Tc

    def balance(theta, psi_, up_):
        Ta, Tc = tensions(theta, psi_, up_)
        return Ta * float(_leaving_rate(theta, t, z, kind)) - Tc * float(_running_on_rate(theta, t, z, rkind))

    theta = np.empty_like(p)
    for i, (ps, u) in enumerate(zip(p, up, strict=True)):
        lo, hi = ps - 0.5 * gamma, ps + 0.5 * gamma
        if balance(lo, ps, u) * balance(hi, ps, u) > 0:
            raise InputError("elastic_loop: the tensioning sprocket finds no balance within half a tooth "
                             "period; the pretension is too small for this stiffness and displacement",
                             field="pretension")
        theta[i] = brentq(balance, lo, hi, args=(ps, u), xtol=1e-15, rtol=1e-15)
    Ta = np.empty_like(p)
    Tc = np.empty_like(p)
    for i, (th, ps, u) in enumerate(zip(theta, p, up, strict=True)):
        Ta[i], Tc[i] = tensions(th, ps, u)
    uz = _running_on(p, t, z, kind)
    Tb = T0 + E / (A - l) * (uz - up)
    rigid = cam_force(E, A, l, uz, up, leaving_displacement(p, t, z, kind))
    return ElasticLoop(psi=p, force=Tb - Ta, rigid_force=np.asarray(rigid), lag=theta - p,
                       tension_tensioning_side=Ta, tension_driving_side=Tb, tension_return=Tc)


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
