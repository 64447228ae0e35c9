r"""Wear life of a chain: elongation over hours, hours to an elongation limit.

Two models (``model=`` of :func:`wear_life`):

``"rating"`` (roller chains, default)
    The ANSI/ACA power ratings are set for a life of 15 000 h with at most 3 %
    elongation, on two 17-tooth sprockets with a chain of 100 pitches (Shigley, 9th
    ed., §17-5, conditions of Table 17-20). Wear of a joint follows Archard's law:
    its wear per articulation is proportional to the bearing pressure (so to the
    load), and each joint articulates twice per wheel per lap, i.e.
    ``2 n_w v / (X p)`` times per second. Scaling the rating basis:

    .. math:: t_{lim} = 15000\,\mathrm h\;\frac{e_{lim}}{0.03}
              \left(\frac{P_{rated}}{P}\right)^{m}\frac{X}{100}\,\frac{2}{n_w}

    with ``m = 1`` (Archard; wear linear in pressure). Elongation grows linearly
    in time (steady wear after running-in).

``"archard"`` (any chain, user coefficient)
    Pin–bush (or link–link) wear depth ``h = k p_b s``, with bearing pressure
    ``p_b = F / A``, sliding distance per articulation ``s = r θ`` (joint radius ``r``,
    articulation angle ``θ = 2π/z``) and the articulations per hour as above. A worn
    joint lengthens its pitch by about ``2h`` (both sides of the joint clearance), so
    ``e = 2 h / p``. The wear coefficient ``k`` [m²/N] must be supplied (from tests;
    typical dimensional Archard coefficients of lubricated steel pairs are
    1e-17…1e-15 m²/N).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from .._registry import Registry
from .._results import Result, quantity
from .._typing import FloatOrArray
from .._validation import check_nonnegative, check_positive, check_range
from ..errors import InputError

__all__ = [
    "RATING_LIFE_HOURS",
    "RATING_ELONGATION",
    "RATING_LINKS",
    "articulations_per_hour",
    "hours_to_elongation_rating",
    "elongation_rate_archard",
    "WearLife",
    "wear_life",
    "WEAR_MODELS",
]

#: Life [h] behind the ANSI/ACA ratings (Shigley, 9th ed., §17-5).
RATING_LIFE_HOURS = 15000.0
#: Elongation [-] admitted at the end of the rating life (3 %).
RATING_ELONGATION = 0.03
#: Chain length [pitches] of the rating basis.
RATING_LINKS = 100.0


def articulations_per_hour(chain_speed: ArrayLike, links: ArrayLike, pitch: ArrayLike, wheels: int=2) -> FloatOrArray:
    r"""How often one joint articulates per hour.

    .. math:: f = \frac{2\,n_w\,v}{X\,p}\cdot 3600

    Parameters
    ----------
    chain_speed : float or array_like
        [m/s].
    links : float or array_like
        Chain length ``X`` [pitches].
    pitch : float or array_like
        [m].
    wheels : int
        Wheels the chain wraps ``n_w`` (each gives an entry and an exit articulation).

    Returns
    -------
    ndarray
        [1/h].

    Examples
    --------
    >>> float(articulations_per_hour(1.0, 100, 0.0254, 2)) == 2 * 2 * 1.0 / 2.54 * 3600
    True
    """
    v = check_nonnegative("chain_speed", chain_speed, "m/s")
    X = check_positive("links", links)
    p = check_positive("pitch", pitch, "m")
    nw = check_positive("wheels", wheels)
    return 2.0 * nw * v / (X * p) * 3600.0


def hours_to_elongation_rating(rated_power: ArrayLike, power: ArrayLike, links: ArrayLike, *, elongation_limit: float=0.03, wheels: int=2,
                               load_exponent: float=1.0) -> FloatOrArray:
    r"""Hours until the elongation limit, scaled from the ANSI/ACA rating basis.

    .. math:: t_{lim} = 15000\,\mathrm h\;\frac{e_{lim}}{0.03}
              \left(\frac{P_{rated}}{P}\right)^{m}\frac{X}{100}\,\frac{2}{n_w}

    Parameters
    ----------
    rated_power : float or array_like
        ANSI/ACA rating of the chain at the operating speed and teeth [W].
    power : float or array_like
        Design power (with service factor) [W].
    links : float or array_like
        Chain length [pitches].
    elongation_limit : float
        Admitted elongation, ``0 < e <= 0.1`` (3 % usual; 2 % for drives with
        large sprockets, > 60 teeth) [-].
    wheels : int
        Number of wheels the chain wraps.
    load_exponent : float
        ``m`` (1 = Archard).

    Returns
    -------
    ndarray
        [h].

    Notes
    -----
    A model (see module notes), not a published life equation: it reproduces the
    rating basis exactly (15 000 h at rated power, 100 pitches, two wheels, 3 %) and
    scales with load and articulation frequency by Archard's law. Rated powers
    include the chain speed and sprocket size through the ANSI formulas.

    References
    ----------
    Shigley, 9th ed., §17-5 (rating basis: 15 000 h, 3 % elongation, 100 pitches,
    two 17-tooth sprockets); Archard, J. F., J. Appl. Phys. 24 (1953) 981.

    Examples
    --------
    >>> round(float(hours_to_elongation_rating(10e3, 5e3, 120)))
    36000
    """
    Pr = check_positive("rated_power", rated_power, "W")
    P = check_positive("power", power, "W")
    X = check_positive("links", links)
    e = check_range("elongation_limit", elongation_limit, 0.0, 0.1, low_inclusive=False)
    nw = check_positive("wheels", wheels)
    m = check_positive("load_exponent", load_exponent)
    return RATING_LIFE_HOURS * (e / RATING_ELONGATION) * (Pr / P) ** m * (X / RATING_LINKS) * (2.0 / nw)


def elongation_rate_archard(tension: ArrayLike, bearing_area: ArrayLike, joint_radius: ArrayLike, teeth: ArrayLike, chain_speed: ArrayLike, links: ArrayLike, pitch: ArrayLike,
                            wear_coefficient: float, wheels: int=2) -> FloatOrArray:
    r"""Elongation per hour by Archard's wear law in the chain joints.

    .. math:: \dot e = \frac{2}{p}\,k\,\frac{F}{A}\,r\,\frac{2\pi}{z}\,f

    Parameters
    ----------
    tension : float or array_like
        Mean joint load (tight-side tension) [N].
    bearing_area : float or array_like
        Projected bearing area of a joint ``A`` [m²] (pin diameter × bush length for
        a roller chain; ``d²`` order for a round link chain).
    joint_radius : float or array_like
        Radius at which the joint slides ``r`` [m] (pin radius; ``d/2`` for links).
    teeth : int or array_like
        Teeth of the (smallest) wheel: articulation angle ``2π/z`` [-].
    chain_speed : float or array_like
        [m/s].
    links, pitch
        Chain length [pitches], pitch [m].
    wear_coefficient : float
        Dimensional Archard coefficient ``k`` [m²/N] (volume per load per distance).
    wheels : int
        Wheels wrapped.

    Returns
    -------
    ndarray
        [1/h].

    References
    ----------
    Archard, J. F., "Contact and rubbing of flat surfaces", J. Appl. Phys. 24 (1953)
    981–988.

    Examples
    --------
    >>> r = elongation_rate_archard(2000, 1e-4, 0.004, 19, 5.0, 120, 0.0254, 1e-16)
    >>> f"{float(r):.3e}"
    '4.921e-06'
    """
    F = check_nonnegative("tension", tension, "N")
    A = check_positive("bearing_area", bearing_area, "m^2")
    r = check_positive("joint_radius", joint_radius, "m")
    z = check_positive("teeth", teeth)
    k = check_positive("wear_coefficient", wear_coefficient, "m^2/N")
    f = articulations_per_hour(chain_speed, links, pitch, wheels)
    p = check_positive("pitch", pitch, "m")
    return 2.0 / p * k * F / A * r * (2 * np.pi / z) * f


@dataclass(frozen=True)
class WearLife(Result):
    """Elongation over time and the hours to the limit.

    Attributes
    ----------
    model : str
    hours : ndarray
        Time points [h].
    elongation : ndarray
        Relative elongation at ``hours`` [-].
    elongation_limit : float
        [-].
    hours_to_limit : float
        [h].
    """

    model: str
    hours: np.ndarray = quantity("h")
    elongation: np.ndarray = quantity("1")
    elongation_limit: float = quantity("1")
    hours_to_limit: float = quantity("h")


WEAR_MODELS = Registry("wear model")


@WEAR_MODELS.register("rating")
def _rating(*, rated_power, power, links, elongation_limit, wheels, load_exponent=1.0, **_):
    return float(hours_to_elongation_rating(rated_power, power, links, elongation_limit=elongation_limit,
                                            wheels=wheels, load_exponent=load_exponent))


@WEAR_MODELS.register("archard")
def _archard(*, tension, bearing_area, joint_radius, teeth, chain_speed, links, pitch,
             wear_coefficient, elongation_limit, wheels, **_):
    rate = float(elongation_rate_archard(tension, bearing_area, joint_radius, teeth, chain_speed,
                                         links, pitch, wear_coefficient, wheels))
    if rate <= 0:
        return float("inf")
    return elongation_limit / rate


def wear_life(model: str = "rating", *, elongation_limit: float=0.03, wheels: int=2, hours: ArrayLike | None=None,
              **parameters: ArrayLike | None) -> WearLife:
    r"""Chain elongation over hours and hours until the elongation limit.

    .. math:: e(t) = e_{lim}\,\frac{t}{t_{lim}}

    Parameters
    ----------
    model : {"rating", "archard"}
        See the module notes.
    elongation_limit : float
        [-], in (0, 0.1].
    wheels : int
        Wheels wrapped.
    hours : array_like, optional
        Time points [h]; default 0…1.5 ``t_lim`` (51 points).
    **parameters
        ``"rating"``: ``rated_power`` [W], ``power`` [W], ``links``.
        ``"archard"``: ``tension``, ``bearing_area``, ``joint_radius``, ``teeth``,
        ``chain_speed``, ``links``, ``pitch``, ``wear_coefficient``.

    Returns
    -------
    WearLife

    Raises
    ------
    UnknownNameError
        Unknown model.
    InputError
        A parameter of the model is missing (named in the message).

    References
    ----------
    See :func:`hours_to_elongation_rating` and :func:`elongation_rate_archard`.

    Examples
    --------
    >>> w = wear_life("rating", rated_power=10e3, power=5e3, links=120)
    >>> round(w.hours_to_limit)
    36000
    """
    fn = WEAR_MODELS.get(model)
    need = {"rating": ("rated_power", "power", "links"),
            "archard": ("tension", "bearing_area", "joint_radius", "teeth", "chain_speed", "links",
                        "pitch", "wear_coefficient")}[model]
    missing = [k for k in need if parameters.get(k) is None]
    if missing:
        raise InputError(f"wear model {model!r} needs {', '.join(missing)}")
    e = float(check_range("elongation_limit", elongation_limit, 0.0, 0.1, low_inclusive=False))
    t_lim = fn(elongation_limit=e, wheels=wheels, **parameters)
    t = (np.linspace(0.0, 1.5 * t_lim, 51) if hours is None
         else check_nonnegative("hours", hours, "h"))
    return WearLife(model=model, hours=t, elongation=e * t / t_lim, elongation_limit=e,
                    hours_to_limit=float(t_lim))


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
