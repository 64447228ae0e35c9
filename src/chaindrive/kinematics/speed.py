"""Wheel speed and chain speed: the one conversion, and the boundary parser of a wheel speed
that may be given as either (``"300 rpm"``, ``"5 rad/s"``, ``"1.2 m/s"``).

The mean chain speed formula itself is :func:`chaindrive.loads.chain_speed` (v = n p omega / 2 pi).
"""

from __future__ import annotations

import math
from typing import Any

from ..errors import InputError
from ..limits import MAX_TEETH, warn_implausible
from ..loads import mean_chain_speed, sides_per_turn
from ..units import parse_quantity, parse_speed_text

__all__ = ["chain_speed_to_angular_velocity", "parse_wheel_speed"]


def chain_speed_to_angular_velocity(chain_speed: float, pitch: float, teeth: int, *,
                                    link_chain: bool = False) -> float:
    """Angular speed of the wheel that drives a chain at a given mean speed [rad/s].

    Parameters
    ----------
    chain_speed : float
        Mean chain speed v [m/s] (how scraper conveyors are specified).
    pitch : float
        Chain pitch p [m]; the inner link length t of a round link chain.
    teeth : int
        Teeth (sprocket, track wheel) or pockets (pocket wheel) z of the driving wheel.
    link_chain : bool
        Round link chain on a pocket wheel: 2z links of length t pass per turn
        (horizontal and vertical links), so the wheel has n = 2z sides; otherwise n = z.

    Returns
    -------
    float
        Angular speed ω [rad/s].

    Notes
    -----
    One turn passes n pitches, so the mean chain speed is v = n p ω / 2π and

    .. math:: \\omega = \\frac{2 \\pi v}{n p}, \\quad n = z \\text{ (sprocket)}, \\; n = 2z
              \\text{ (pocket wheel)}

    (Shigley §17-5, chain velocity V = N p n; for the pocket wheel the bi-regular
    polygon of Dolipiński et al. eq. (6) has 2z sides of lengths t + d and t - d,
    which sum to 2 z t per turn).

    Examples
    --------
    >>> round(chain_speed_to_angular_velocity(0.815, 0.064, 8, link_chain=True), 4)
    5.0008
    >>> round(chain_speed_to_angular_velocity(1.0, 0.0254, 19) * 30 / 3.141592653589793, 2)
    124.33

    References
    ----------
    Shigley, §17-5 (chain velocity). Dolipiński et al., eq. (6).
    """
    if not (isinstance(chain_speed, (int, float)) and math.isfinite(chain_speed)):
        raise InputError(f"chain_speed must be a finite number of m/s, got {chain_speed!r}")
    if not (isinstance(pitch, (int, float)) and math.isfinite(pitch) and pitch > 0):
        raise InputError(f"pitch must be positive and finite (0 < pitch < inf m), got {pitch!r}")
    if isinstance(teeth, bool) or not isinstance(teeth, (int,)) and not float(teeth).is_integer() or teeth < 2:
        raise InputError(f"teeth must be a whole number >= 2, got {teeth!r}")
    return 2 * math.pi * float(chain_speed) / (sides_per_turn(int(teeth), link_chain) * float(pitch))


def parse_wheel_speed(text: Any, *, pitch: float, teeth: int, link_chain: bool = False,
                      field: str = "speed") -> float:
    """Parse a wheel speed given as angular speed or as chain speed; return ω [rad/s].

    ``"300 rpm"``, ``"5 rad/s"`` are angular speeds of the driving wheel; ``"1.2 m/s"``
    or ``"72 m/min"`` is the mean chain speed and is converted with
    :func:`chain_speed_to_angular_velocity`. Implausible values warn
    (:func:`chaindrive.limits.warn_implausible`).

    Parameters
    ----------
    text : str or float
        The speed with its unit (a Python float is ω in rad/s).
    pitch : float
        Chain pitch [m].
    teeth : int
        Teeth or pockets of the driving wheel.
    link_chain : bool
        Round link chain on a pocket wheel (2z sides per turn).
    field : str
        Name of the field in messages.

    Returns
    -------
    float
        ω [rad/s].

    Examples
    --------
    >>> round(parse_wheel_speed("1.2 m/s", pitch=0.064, teeth=8, link_chain=True), 4)
    7.3631
    >>> round(parse_wheel_speed("48 rpm", pitch=0.064, teeth=8), 4)
    5.0265

    References
    ----------
    Shigley, §17-5 (chain velocity). Dolipiński et al., eq. (6).
    """
    if isinstance(text, str):
        v = parse_speed_text(text, field=field)
        if v is not None:
            warn_implausible(f"{field} (chain speed)", v, "chain_speed", stacklevel=3)
            w = chain_speed_to_angular_velocity(v, pitch, teeth, link_chain=link_chain)
            warn_implausible(field, w, "angular_velocity", stacklevel=3)
            return w
        try:
            w = parse_quantity(text, "rad/s", field=field)
        except InputError as exc:
            msg = str(exc)
            if "has units of" in msg or "give a unit" in msg:
                msg += ' (a chain speed such as "1.2 m/s" is accepted too)'
            raise InputError(msg) from None
    else:
        w = parse_quantity(text, "rad/s", field=field)
    valid = isinstance(teeth, int) and 2 <= teeth <= MAX_TEETH and math.isfinite(pitch) and pitch > 0
    if not warn_implausible(field, w, "angular_velocity", stacklevel=3) and w > 0 and valid:
        # a plausible wheel speed may still drive the chain faster than any chain runs
        warn_implausible(f"{field} (chain speed n p omega / 2 pi)",
                         mean_chain_speed(sides_per_turn(int(teeth), link_chain), float(pitch), w),
                         "chain_speed", stacklevel=3)
    return w


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function: NaN/inf in or out refused
