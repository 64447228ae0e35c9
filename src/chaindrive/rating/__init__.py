r"""Power rating of roller chains, each family by its own method (``method=`` registry).

* ``"ansi"`` -- the American Chain Association method behind the ANSI horsepower tables
  (:mod:`chaindrive.rating.ansi`): link-plate and roller–bushing limits, galling,
  lubrication regions;
* ``"iso10823"`` -- the ISO 10823 rating of ISO 606 A- and B-series chains
  (:mod:`chaindrive.rating.iso10823`; the default for the B series);
* further methods register themselves in :data:`RATING_METHODS`.

:func:`chain_rating` rates one chain on one small sprocket; :func:`default_method` names
the method of a chain's family. Sources and checks against published tables:
``docs/rating.md``.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike

from .._registry import Registry
from .._results import Result, quantity
from .._validation import check_positive, check_teeth
from ..errors import InputError, ValidityRangeWarning
from ..loads import mean_chain_speed
from ..units import angular_velocity_to_rpm
from .ansi import (
    _LUBRICATION_SOURCE,
    HP,
    LUBRICATION_REGIONS,
    ansi_constants,
    ansi_link_plate_power,
    ansi_roller_bushing_power,
    galling_power,
    galling_speed,
    lubrication_region,
    multi_strand_factor,
)

if TYPE_CHECKING:
    from ..chains import Chain

__all__ = ["ChainRating", "chain_rating", "branch_powers", "RATING_METHODS", "RATING_CURVES", "default_method", "rated_power_curve", "HP",
           "rating_constants"]

# --------------------------------------------------------------------------- one chain

_GOVERNING = ("link_plate", "roller_bushing")


@dataclass(frozen=True)
class ChainRating(Result):
    """Rating of one roller chain on one small sprocket by one method (:func:`chain_rating`).

    Attributes
    ----------
    chain : str
        Chain name.
    pitch : float
        [m].
    strands : int
        Number of strands (1 … 4).
    teeth : int
        Teeth of the small sprocket [-].
    angular_velocity : float
        Speed of the small sprocket [rad/s].
    chain_speed : float
        Mean chain speed ``z p ω / (2π)`` [m/s].
    link_plate, roller_bushing : float
        Power limits of link-plate fatigue and roller–bushing impact, strands included
        (multi-strand factor ``K_2``) [W].
    galling : float
        Power at which the joints start to gall at this speed, strands included [W]
        (:func:`galling_power` × ``K_2``); informative, the galling check is
        ``galling_exceeded``.
    rated_power : float
        The smaller of ``link_plate`` and ``roller_bushing`` [W]: the table (chart) value,
        which the ANSI tables also print in the galling region (type C').
    governing_limit : str
        ``"link_plate"`` or ``"roller_bushing"``.
    tension : float
        Strand tension the galling check uses [N]: ``power / (v K_2)`` for a given
        power, else that of the link-plate/roller–bushing rating.
    galling_speed : float
        Small-sprocket speed at which galling starts at ``tension`` [rad/s] (not m/s).
    galling_exceeded : bool
        ``angular_velocity > galling_speed`` (equivalently: power above ``galling``):
        the drive runs in the galling region, lubrication type C'; the ANSI tables
        then ask for the manufacturer's evaluation.
    lubrication : str
        ``"A"``, ``"B"``, ``"C"`` or ``"C'"`` (galling region).
    lubrication_method : str
        Its meaning (:data:`LUBRICATION_REGIONS`).
    lubrication_source : str
        Where the region boundaries come from.
    warnings : tuple of str
        Validity-range and method notes (nothing is emitted as a Python warning).
    method : str
        ``"ansi"`` or ``"iso10823"`` (:data:`RATING_METHODS`).
    source : str
        Where the method's formulas and constants come from.
    """

    chain: str
    pitch: float = quantity("m")
    strands: int = quantity("1")
    teeth: int = quantity("1")
    angular_velocity: float = quantity("rad/s")
    chain_speed: float = quantity("m/s")
    link_plate: float = quantity("W")
    roller_bushing: float = quantity("W")
    galling: float = quantity("W")
    rated_power: float = quantity("W")
    governing_limit: str
    tension: float = quantity("N")
    galling_speed: float = quantity("rad/s")
    galling_exceeded: bool
    lubrication: str
    lubrication_method: str
    lubrication_source: str
    warnings: tuple[str, ...]
    method: str = "ansi"
    source: str = "ACA; Shigley, 10th ed., eqs (17-32), (17-33)"

    @property
    def limited_by(self) -> str:
        """What limits the rating: the governing limit, or ``"galling"`` in the galling region."""
        return "galling" if self.galling_exceeded else self.governing_limit


def _scalar(name: str, value, check, unit: str) -> float:
    arr = check(name, value, unit)
    if arr.ndim:
        raise InputError(f"{name} must be a single number ({unit}), got an array of shape {arr.shape}")
    return float(arr)


def _ansi_rating(chain: Chain | str, teeth: int, angular_velocity: float, *,
                 power: float | None = None) -> ChainRating:
    r"""ANSI/ACA rating of a roller chain on its small sprocket, with galling and lubrication.

    .. math:: P_r = K_2 \min(H_1, H_2),\qquad
              \text{galling if } n_1 > n_g\!\left(\frac{P}{K_2 v}\right)

    Parameters
    ----------
    chain : Chain or str
        A roller chain (catalogue name, or a :class:`~chaindrive.chains.Chain`) with
        1 … 4 strands.
    teeth : int
        Teeth of the small sprocket [-] (the ratings are built for 9 … 45; warns outside).
    angular_velocity : float
        Speed of the small sprocket [rad/s].
    power : float, optional
        Transmitted (design) power [W]; sets the strand tension of the galling check.
        Without it the galling check uses the tension at the link-plate/roller–bushing
        rating.

    Returns
    -------
    ChainRating

    Raises
    ------
    InputError
        For a round link chain or more than 4 strands (outside the ANSI method: this
        function raises rather than returning ``None``; check
        ``chain.is_roller_chain and chain.strands <= 4`` first), and for a bad
        ``teeth``, ``angular_velocity`` or ``power``.
    UnknownNameError
        For an unknown chain name.

    Notes
    -----
    Link-plate and roller–bushing limits: :func:`ansi_link_plate_power`,
    :func:`ansi_roller_bushing_power` with the constants of :func:`ansi_constants`,
    times the multi-strand factor ``K_2``. Galling: :func:`galling_power` per strand
    with the strand tension taken as ``F / K_2`` (the load share the rating assumes).
    ISO 606 B-series chains are rated with the constants of the A series of equal
    pitch (an approximation, noted in ``warnings``); so are custom roller chains.

    References
    ----------
    ACA; Shigley, 10th ed., eqs (17-32), (17-33), the galling limit of §17-5, Table 17-20
    (lubrication types A, B, C, C') and Table 17-23 (multi-strand factors); McGuire
    Bearing Co. (type A/B chain-speed limits).

    Examples
    --------
    >>> r = chain_rating("ANSI 40", 17, 1000 * np.pi / 30)
    >>> round(r.rated_power / HP, 2), r.governing_limit, r.lubrication, r.galling_exceeded
    (5.48, 'link_plate', 'B', False)
    """
    from ..chains import get

    ch = get(chain)
    notes: list[str] = []
    if ch.family == "iso606" and "B" in ch.name:
        notes.append("ANSI/ACA rating applied to an ISO 606 B-series chain with the constants of the "
                     "A series of equal pitch (an approximation; method 'iso10823' rates the B series)")
    if ch.family == "custom":
        notes.append(f"custom chain {ch.name}: ANSI B29.1 proportions assumed by the rating")
    return _rate(ch, teeth, angular_velocity, power, constants=ansi_constants, method="ansi",
                 source="ACA; Shigley, 10th ed., eqs (17-32), (17-33)", notes=notes)


def branch_powers(pitch: ArrayLike, teeth: ArrayLike, angular_velocity: ArrayLike, *, plate_constant: float,
                  roller_constant: float,
                  basis_teeth: int | None = None) -> tuple[np.ndarray, np.ndarray]:
    r"""Link-plate and roller–bushing powers of one strand: the ACA branches, on ``teeth`` or on a basis.

    .. math:: (H_1, H_2)(z_1) = \left(\frac{z_1}{z_b}\right)^{1.08} (H_1, H_2)(z_b)\quad
              (z_b = 19:\ \text{ISO 10823});\qquad (H_1, H_2)(z_1)\quad(\text{ACA})

    Parameters
    ----------
    pitch, teeth, angular_velocity : float or array_like
        Chain pitch [m], small-sprocket teeth [-] and speed [rad/s].
    plate_constant, roller_constant : float
        ``K_p``, ``K_r`` of eqs (17-32), (17-33).
    basis_teeth : int, optional
        Evaluate both branches on this tooth count and scale them by ``(z_1/z_b)^{1.08}``
        (ISO 10823's tooth factor ``1/f_2`` on its 19-tooth basis); ``None``: on ``teeth``.

    Returns
    -------
    tuple of ndarray
        ``H_1``, ``H_2`` [W] per strand.

    References
    ----------
    ACA; Shigley, 10th ed., eqs (17-32), (17-33); ISO 10823:2004, 4.2 (tooth factor).

    Examples
    --------
    >>> h1, h2 = branch_powers(0.01905, 25, 152.89, plate_constant=0.00434, roller_constant=21.85,
    ...                        basis_teeth=19)
    >>> round(float(h1) / 1e3, 2), round(float(h2) / 1e3, 2)
    (31.59, 25.85)
    """
    z = np.asarray(teeth, dtype=float)
    zb = z if basis_teeth is None else basis_teeth
    scale = 1.0 if basis_teeth is None else (z / basis_teeth) ** 1.08
    return (scale * ansi_link_plate_power(zb, angular_velocity, pitch, plate_constant),
            scale * ansi_roller_bushing_power(zb, angular_velocity, pitch, roller_constant))


def _rate(ch: Chain, teeth, angular_velocity, power, *, constants, method: str, source: str,
          notes: list[str], basis_teeth: int | None = None) -> ChainRating:
    """Both fatigue limits, strands, galling and lubrication of one chain (shared by the methods).

    ``basis_teeth``: the branches are evaluated on that tooth count and scaled to ``teeth`` by
    ``(teeth/basis)^1.08`` (ISO 10823's tooth factor); ``None``: on ``teeth`` (ACA)."""
    label = "ANSI/ACA" if method == "ansi" else "ISO 10823"
    if not ch.is_roller_chain:
        raise InputError(f"chain {ch.name} is a round link chain: the {label} rating holds for roller "
                         "chains (ISO 606, ANSI B29.1) with 1 to 4 strands")
    if ch.strands > 4:
        raise InputError(f"chain {ch.name} has {ch.strands} strands: the {label} multi-strand factors "
                         "cover 1 to 4 strands")
    z = int(_scalar("teeth", teeth, lambda n, v, u: check_teeth(n, v), "whole number >= 3"))
    w = _scalar("angular_velocity", angular_velocity, check_positive, "rad/s")
    design = None if power is None else _scalar("power", power, check_positive, "W")
    with warnings.catch_warnings(record=True) as rec:
        warnings.simplefilter("always", ValidityRangeWarning)
        kp, kr = constants(ch.name)
        k2 = multi_strand_factor(ch.strands)
        b1, b2 = branch_powers(ch.pitch, z, w, plate_constant=kp, roller_constant=kr, basis_teeth=basis_teeth)
        h1, h2 = float(b1), float(b2)
        v = mean_chain_speed(z, ch.pitch, w)
        h3 = float(galling_power(ch.pitch, z, w))
        tension = (min(h1, h2) if design is None else design / k2) / v
        n_gall = float(galling_speed(ch.pitch, z, tension))
        region = str(lubrication_region(v, ch.pitch))
    limits = (k2 * h1, k2 * h2)
    i = int(np.argmin(limits))
    exceeded = bool(w > n_gall)
    if exceeded:
        region = "C'"
        notes.append(f"galling region: the joints gall above {angular_velocity_to_rpm(n_gall):.4g} rpm at "
                     f"{tension / 1e3:.3g} kN per strand (Shigley §17-5); submit the design to the "
                     "chain manufacturer")
    return ChainRating(
        chain=ch.name, pitch=ch.pitch, strands=ch.strands, teeth=z, angular_velocity=w, chain_speed=v,
        link_plate=limits[0], roller_bushing=limits[1], galling=k2 * h3, rated_power=limits[i],
        governing_limit=_GOVERNING[i], tension=tension, galling_speed=n_gall, galling_exceeded=exceeded,
        lubrication=region, lubrication_method=LUBRICATION_REGIONS[region],
        lubrication_source=_LUBRICATION_SOURCE,
        warnings=tuple(dict.fromkeys([str(r.message) for r in rec] + notes)),
        method=method, source=source,
    )


def chain_rating(chain: Chain | str, teeth: int, angular_velocity: float, *,
                 power: float | None = None, method: str | None = None) -> ChainRating:
    r"""Rating of a roller chain on its small sprocket by the method of its family (or ``method``).

    .. math:: P_r = K_2 \min(H_1, H_2)\ \text{(ANSI/ACA)},\qquad
              P_r = \frac{K_2}{f_2} \min\big(H_1(19), H_2(19)\big)\ \text{(ISO 10823)}

    Parameters
    ----------
    chain : Chain or str
        A roller chain with 1 … 4 strands.
    teeth : int
        Teeth of the small sprocket [-].
    angular_velocity : float
        Speed of the small sprocket [rad/s].
    power : float, optional
        Transmitted (design) power [W] (sets the tension of the galling check).
    method : str, optional
        A name of :data:`RATING_METHODS`; default :func:`default_method`.

    Returns
    -------
    ChainRating
        By the chosen method; its ``method`` and ``source`` name it.

    Raises
    ------
    InputError
        A round link chain, more than 4 strands, bad teeth, speed or power.
    UnknownNameError
        Unknown chain or method.

    References
    ----------
    See the methods (:mod:`chaindrive.rating.ansi`, :mod:`chaindrive.rating.iso10823`;
    docs/rating.md).

    Examples
    --------
    >>> r = chain_rating("ANSI 40", 17, 1000 * np.pi / 30)
    >>> round(r.rated_power / HP, 2), r.governing_limit, r.lubrication, r.galling_exceeded, r.method
    (5.48, 'link_plate', 'B', False, 'ansi')
    """
    from ..chains import get

    ch = get(chain)
    name = default_method(ch) if method is None else method
    return RATING_METHODS.get(name)(ch, teeth, angular_velocity, power=power)


def _iso10823_rating(chain: Chain | str, teeth: int, angular_velocity: float, *,
                     power: float | None = None) -> ChainRating:
    r"""ISO 10823 rating of an ISO 606 roller chain (A or B series) on its small sprocket.

    .. math:: P_r = \frac{K_2}{f_2} \min\big(P_1(19), P_2(19)\big),\qquad f_2 = (19/z_1)^{1.08},
              \qquad (K_p, K_r)\ \text{of the chain's ISO 606 series}

    Parameters
    ----------
    chain : Chain or str
        An ISO 606 roller chain (A or B series; ANSI names rate as their A-series twins)
        with 1 … 4 strands.
    teeth : int
        Teeth of the small sprocket [-] (9 … 45; warns outside).
    angular_velocity : float
        Speed of the small sprocket [rad/s].
    power : float, optional
        Design power [W] for the galling check.

    Returns
    -------
    ChainRating
        ``method == "iso10823"``; B-series ratings carry the provisional-constants note.

    Raises
    ------
    InputError
        A round link chain, a custom chain (no ISO 606 series), more than 4 strands, bad
        teeth, speed or power.
    UnknownNameError
        Unknown chain name.

    Notes
    -----
    Branch constants :func:`~chaindrive.rating.iso10823.iso10823_constants`, evaluated on
    the charts' 19 teeth and scaled by the standard's tooth factor
    (:func:`~chaindrive.rating.iso10823.iso_tooth_factor`); galling
    check and lubrication regions as in the ANSI method (the ISO charts' own region
    boundaries were not available); docs/rating.md, "ISO 10823".

    References
    ----------
    ISO 10823:2004; Bhandari, *Design of Machine Elements*, Table 14.2; Shigley, 10th
    ed., eqs (17-32), (17-33), §17-5.

    Examples
    --------
    >>> r = chain_rating("12B-1", 17, 1400 * np.pi / 30, method="iso10823")
    >>> round(r.rated_power / 1e3, 2), r.governing_limit, r.method
    (18.15, 'roller_bushing', 'iso10823')
    """
    from ..chains import get
    from .iso10823 import (
        B_SERIES_NOTE,
        ISO10823_SOURCE,
        REFERENCE_TEETH,
        is_b_series,
        iso10823_constants,
    )

    ch = get(chain)
    if ch.family == "custom":
        raise InputError(f"chain {ch.name} is a custom chain: the ISO 10823 rating needs an ISO 606 A- or "
                         "B-series chain (use method='ansi' for custom proportions)")
    notes = [B_SERIES_NOTE] if is_b_series(ch.name) else []
    return _rate(ch, teeth, angular_velocity, power, constants=iso10823_constants, method="iso10823",
                 source=ISO10823_SOURCE, notes=notes, basis_teeth=REFERENCE_TEETH)


#: Rating methods by name: ``f(chain, teeth, angular_velocity, power) -> ChainRating``.
RATING_METHODS = Registry("rating method")
RATING_METHODS.add("ansi", _ansi_rating)
RATING_METHODS.add("iso10823", _iso10823_rating)


def default_method(chain: Chain) -> str:
    """The rating method of a chain's family: its own when registered, ISO 606 B series by ISO 10823, else ANSI/ACA.

    A family beyond the built-in ones (:func:`chaindrive.chains.register_family`, or a
    ``chains/data/<family>.csv``) rates by the method registered under its name in
    :data:`RATING_METHODS`, from the module ``chaindrive/rating/<family>.py`` when there is one.

    >>> from chaindrive.chains import get
    >>> default_method(get("ANSI 40")), default_method(get("12A-1")), default_method(get("12B-1"))
    ('ansi', 'ansi', 'iso10823')
    """
    from .iso10823 import is_b_series

    if chain.family not in _BUILTIN_FAMILIES:  # a further family rates by its own method
        _import_family_method(chain.family)
        if chain.family in RATING_METHODS:
            return chain.family
    if chain.family == "iso606" and is_b_series(chain.name) and "iso10823" in RATING_METHODS:
        return "iso10823"
    return "ansi"


_BUILTIN_FAMILIES = ("iso606", "ansi", "din22252", "custom")


def _import_family_method(family: str) -> None:
    """Import ``chaindrive.rating.<family>`` once if it exists: it registers the family's method."""
    import importlib
    import importlib.util

    name = f"{__name__}.{family}"
    if family not in RATING_METHODS and importlib.util.find_spec(name) is not None:
        importlib.import_module(name)


def rating_constants(name: str, method: str = "ansi") -> tuple[float, float]:
    r"""Branch constants ``(K_p, K_r)`` a method uses for a chain name (both methods share the ACA form).

    .. math:: H_1 \propto K_p,\qquad H_2 \propto K_r

    Parameters
    ----------
    name : str
        Chain name.
    method : str
        ``"ansi"`` or ``"iso10823"``.

    Returns
    -------
    tuple of float

    Raises
    ------
    UnknownNameError
        An unknown method.

    References
    ----------
    :func:`~chaindrive.rating.ansi.ansi_constants`,
    :func:`~chaindrive.rating.iso10823.iso10823_constants`.

    Examples
    --------
    >>> rating_constants("16B-1", "iso10823"), rating_constants("16B-1", "ansi")
    ((0.00434, 21.85), (0.004, 17.0))
    """
    from .iso10823 import iso10823_constants

    RATING_METHODS.get(method)
    return iso10823_constants(name) if method == "iso10823" else ansi_constants(name)


def _ansi_curve(chain: Chain, teeth: int, angular_velocity: np.ndarray) -> np.ndarray:
    from .ansi import ansi_rated_power

    kp, kr = ansi_constants(chain.name)
    return np.asarray(ansi_rated_power(chain.pitch, teeth, angular_velocity, strands=chain.strands,
                                       plate_constant=kp, roller_constant=kr), dtype=float)


def _iso10823_curve(chain: Chain, teeth: int, angular_velocity: np.ndarray) -> np.ndarray:
    from .iso10823 import iso10823_rated_power

    return np.asarray(iso10823_rated_power(chain.name, chain.pitch, teeth, angular_velocity,
                                           strands=chain.strands), dtype=float)


#: Rated power against speed by method: ``f(chain, teeth, angular_velocities) -> ndarray`` [W].
RATING_CURVES = Registry("rating curve")
RATING_CURVES.add("ansi", _ansi_curve)
RATING_CURVES.add("iso10823", _iso10823_curve)


def rated_power_curve(chain: Chain | str, teeth: int, angular_velocity: np.ndarray, *,
                      method: str | None = None) -> np.ndarray:
    r"""Rated power of a chain over small-sprocket speeds, by its family's method (a rating chart's line).

    .. math:: P_r(\omega) = K_2 \min(H_1(\omega), H_2(\omega))\ \text{(ANSI/ACA)}

    Parameters
    ----------
    chain : Chain or str
    teeth : int
        Small-sprocket teeth [-].
    angular_velocity : array_like
        Small-sprocket speeds [rad/s].
    method : str, optional
        Default :func:`default_method`.

    Returns
    -------
    ndarray
        [W], validity-range warnings silenced (the chart marks its own range).

    Examples
    --------
    >>> w = np.array([100.0, 1000.0]) * np.pi / 30
    >>> [round(float(x) / HP, 2) for x in rated_power_curve("ANSI 40", 17, w)]
    [0.69, 5.48]
    """
    from ..chains import get

    ch = get(chain)
    name = default_method(ch) if method is None else method
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityRangeWarning)
        return RATING_CURVES.get(name)(ch, int(teeth), np.asarray(angular_velocity, dtype=float))


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
