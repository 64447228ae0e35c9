r"""Pre-selection of round link chains (DIN 22252) for a scraper-conveyor duty.

A round link chain has no power rating: it is chosen by its static safety. The
pre-selection ranks the catalogue chains by

.. math:: S = \frac{F_B}{K_s P / v + q v^2} \ge S_{req},\qquad v = \frac{2 z p \omega}{2\pi}

(a pocket wheel of ``z`` pockets moves ``2 z`` links per turn), the required safety of the
analysis for link chains (:data:`chaindrive.analysis.loads.REQUIRED_STATIC_SAFETY`). It
omits the slack and dynamic parts the analysis adds once the layout, tensioner and guides
are known: the analysis (:func:`chaindrive.analysis.loads.static_safety_check`) gives the
static safety of the drive.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike

from ..errors import InputError
from ..loads import mean_chain_speed, sides_per_turn

if TYPE_CHECKING:
    from ..chains import Chain

__all__ = ["link_candidates", "power_at_safety"]


def link_candidates(power: float, speed: float, service_factor: float, teeth: int,
                    required: float | None = None, *, limit: int = 8) -> list[dict]:
    """DIN 22252 chains whose pre-selection static safety meets the requirement, smallest pitch first.

    Parameters
    ----------
    power : float
        [W].
    speed : float
        Driving wheel speed [rad/s].
    service_factor : float
        ``K_s`` [-].
    teeth : int
        Pockets of the driving wheel [-].
    required : float, optional
        Required static safety (default the analysis's value for link chains).
    limit : int
        At most this many rows.

    Returns
    -------
    list of dict
        ``chain, strands, pitch, rated_power`` (power at the required safety) ``[W],
        design_power [W], margin, static_safety, lubrication (None), governing_limit, notes``.

    Examples
    --------
    >>> rows = link_candidates(25e3, 5.0, 1.5, 8)
    >>> rows[0]["chain"], rows[0]["static_safety"] >= 3.5
    ('14x50', True)
    """
    from ..analysis.loads import required_static_safety
    from ..chains import catalogue

    out = []
    for ch in catalogue("din22252"):
        if ch.breaking_force is None:
            continue
        need = required_static_safety(ch) if required is None else required
        v = float(mean_chain_speed(sides_per_turn(teeth, True), ch.pitch, speed))
        q = ch.mass_per_length or 0.0
        pull = service_factor * power / v + q * v * v
        safety = ch.breaking_force / pull
        if safety < need:
            continue
        out.append({"chain": ch.name, "strands": ch.strands, "pitch": ch.pitch,
                    "rated_power": ch.breaking_force / need * v, "design_power": service_factor * power,
                    "margin": safety / need, "static_safety": safety, "lubrication": None,
                    "governing_limit": "static safety", "notes": []})
    out.sort(key=lambda c: (c["pitch"], c["rated_power"]))
    return out[:limit]


def power_at_safety(chain: Chain, teeth: int, angular_velocity: ArrayLike,
                    required: float | None = None) -> np.ndarray:
    r"""Power a round link chain carries at the required static safety over speeds, ``F_B v / S``.

    .. math:: P = \frac{F_B}{S_{req}}\,v,\qquad v = \frac{2 z p \omega}{2\pi}

    Parameters
    ----------
    chain : Chain
        A round link chain with a breaking force.
    teeth : int
        Pockets of the driving wheel [-].
    angular_velocity : array_like
        [rad/s].
    required : float, optional
        Default the analysis's required safety for link chains.

    Returns
    -------
    ndarray
        [W] (the centrifugal part omitted: it is small at scraper-conveyor speeds).

    Examples
    --------
    >>> from chaindrive.chains import get
    >>> round(float(power_at_safety(get("18x64"), 8, 5.0)) / 1e3)
    95
    """
    from ..analysis.loads import required_static_safety

    need = required_static_safety(chain) if required is None else required
    if chain.breaking_force is None:
        raise InputError(f"chain {chain.name} has no breaking force", field="chain")
    v = mean_chain_speed(sides_per_turn(teeth, True), chain.pitch, np.asarray(angular_velocity, dtype=float))
    return chain.breaking_force / need * v


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
