"""The rating of one roller chain at one speed, as the design procedure rates its candidates.

:func:`rate_chain` is what the ``chaindrive rating`` door asks for: the chain by name,
the small sprocket's teeth and speed, the rating method of the chain's family unless one
is named (:func:`chaindrive.rating.chain_rating`), and the galling check at a design power.
"""

from __future__ import annotations

from ..rating import ChainRating, chain_rating

__all__ = ["rate_chain"]


def rate_chain(chain: str, teeth: int, angular_velocity: float, *, power: float | None = None,
               method: str | None = None) -> ChainRating:
    """The rated power of ``chain`` on a ``teeth``-tooth sprocket at ``angular_velocity`` [rad/s].

    Parameters
    ----------
    chain : str
        Catalogue name of a roller chain (``"16B-1"``, ``"ANSI 40"``).
    teeth : int
        Teeth of the small sprocket.
    angular_velocity : float
        Speed of the small sprocket [rad/s].
    power : float, optional
        Design power [W], for the galling check.
    method : str, optional
        Rating method; default the method of the chain's family.

    Returns
    -------
    ChainRating

    References
    ----------
    ANSI/ACA rating formulas as in Shigley's Mechanical Engineering Design, §17-5; ISO 10823:2004 (B series;
    docs/rating.md).

    Examples
    --------
    >>> r = rate_chain("ANSI 40", 17, 1000 * 3.141592653589793 / 30)
    >>> r.limited_by in ("link_plate", "roller_bushing"), r.rated_power > 0
    (True, True)
    """
    return chain_rating(chain, teeth, angular_velocity, power=power, method=method)
