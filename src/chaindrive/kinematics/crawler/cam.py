r"""Crawler drive unit of a conveyor: the elastic drive chain, the force on the cam and the
guide reaction (the crawler drive text, text after eq. (6.16); the formula is lost in the OCR
and rebuilt here).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from ..._typing import FloatOrArray
from ..._validation import as_float_array, check_positive
from ...errors import InputError
from .laws import _out

__all__ = ["cam_force", "cam_hinge_distance", "cam_stiffness"]


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
    Equilibrium of the cam hinge between the two segments: segment ``A - l`` is
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


