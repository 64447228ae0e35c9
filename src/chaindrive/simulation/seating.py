"""Penalty penetration of a state of the simulation model, for presenters.

The model's contacts are penalty contacts: a roller (a round link's hinge) pressed into a
seat with the force ``F`` lies ``F / k_c`` inside the seat's profile, and a pin on a guide
``F / k_g`` inside the guide. :func:`contact_penetration` returns, for every pin, the
penetration vector of those contacts (depth times the direction in which it grows), from
the same energy the static solver minimises (:func:`chaindrive.simulation._statics.static_system`
with unit contact stiffnesses and no links, gravity or torques: its gradient is then the
sum of ``g n`` over the pin's contacts). A presenter that draws the parts (the CAD
assembly) moves each pin by minus that vector to show the parts touching instead of
overlapping; the simulation itself is not changed.
"""

from __future__ import annotations

import numpy as np

from ..errors import InputError
from . import _kernel as K
from . import _statics as S

__all__ = ["contact_penetration"]


def contact_penetration(pos: np.ndarray, wp: np.ndarray, theta: np.ndarray, slide: np.ndarray,
                        gd: np.ndarray, par: np.ndarray) -> np.ndarray:
    """Penetration vector [m] of every pin into the wheels' seats and the guides.

    Parameters
    ----------
    pos : ndarray (N, 2)
        Pin positions [m].
    wp, gd, par : ndarray
        Kernel tables of the model (:func:`chaindrive.simulation.run.kernel_arrays`, or a
        :class:`~chaindrive.simulation.State`'s ``wp``, ``gd``, ``par``).
    theta, slide : ndarray (W,)
        Wheel angles [rad] and slide positions [m] (a State's ``ws[:, S_THETA]``,
        ``ws[:, S_S]``).

    Returns
    -------
    ndarray (N, 2)
        ``Σ g n`` over each pin's contacts: the penetration ``g > 0`` [m] times the unit
        direction in which it grows (the contact force on the pin is ``−k g n``); zero for
        a pin out of contact. ``pos − result`` puts every singly-touching pin on the
        profile it pressed into.

    Raises
    ------
    InputError
        ``pos`` not ``(N, 2)``, ``theta`` or ``slide`` not one value per wheel, a NaN or
        infinite number.

    References
    ----------
    P. Wriggers, *Computational Contact Mechanics*, 2nd ed., Springer 2006, the penalty
    method (a contact force ``k g`` exists only with the penetration ``g`` it acts on).

    Examples
    --------
    >>> from chaindrive.simulation import assemble, roller_example
    >>> st = assemble(roller_example(links=30, teeth=11))
    >>> v = contact_penetration(st.pos, st.wp, st.ws[:, K.S_THETA], st.ws[:, K.S_S], st.gd, st.par)
    >>> bool(0.0 < np.hypot(*v.T).max() < 1e-4)      # micrometres under load
    True
    """
    pos = np.ascontiguousarray(pos, dtype=float)
    wp = np.asarray(wp, dtype=float)
    if pos.ndim != 2 or pos.shape[1] != 2 or len(pos) < 2:
        raise InputError(f"pos must be an (N, 2) array of pin positions in m with N >= 2, got shape {pos.shape}",
                         field="pos")
    n = len(pos)
    nw = len(wp)
    for name, value in (("theta", theta), ("slide", slide)):
        if np.shape(value) != (nw,):
            raise InputError(f"{name} must hold one value per wheel ({nw}, the rows of wp), got shape "
                             f"{np.shape(value)}", field=name)
    parc = np.array(par, dtype=float)
    parc[[K.P_K, K.P_MASS, K.P_GX, K.P_GY]] = 0.0   # no links, no gravity: contacts only
    parc[[K.P_KC, K.P_KG]] = 1.0                     # unit stiffness: gradient = g n
    parc[K.P_PITCH2] = parc[K.P_PITCH] = 1.0
    wpc = np.array(wp, dtype=float)
    wpc[:, K.W_TORQUE] = 0.0
    wpc[:, K.W_SK] = 0.0
    grad = np.zeros(2 * n)
    none = np.full(nw, -1, np.int64)
    empty = np.zeros(0, np.int64)
    S.static_system(pos.ravel().copy(), n, wpc, np.asarray(theta, float), np.asarray(slide, float), none, none,
                    np.asarray(gd, float), K.seat_table(wpc), parc, np.zeros(nw), np.zeros(nw), grad, empty, empty,
                    np.zeros(0), False, 0.0)
    return grad.reshape(n, 2)


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
