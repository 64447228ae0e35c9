"""Roller–tooth contact stress with skew of the roller axis (Garshniev & Maksymovych, paper 2).

Garshniev & Maksymovych (Garshnev & Maksymovych) raises the compressive force of eq. (1) for a roller
whose axis is skewed against the tooth generatrix:

.. math:: Q_n = Q_{nom} (1 + \\gamma \\varphi_p^2),\\qquad
          \\varphi_p = \\varphi_{p,max} K_\\varphi\\ \\text{[arc minutes]}

with ``γ`` tabulated by chain pitch and ``K_φ = 0.6…0.7`` for the reduction of skew by
wear. The skew is measured as ``φ = atan(Δh / B)``.

Decisions (see ``docs/strength.md``):

* ``γ`` is per arc minute squared, as printed; angles are radians in the API and are
  converted to minutes only inside :func:`skew_load_factor`.
* Between the table's pitches ``γ`` is interpolated piecewise linearly in
  ``log γ`` against ``log p`` (a power law between nodes). The table follows
  ``γ ≈ 0.0303 mm / p`` within 4 %, so outside the table ``γ`` is extrapolated with
  that ``1/p`` law from the nearest end and a :class:`ValidityRangeWarning` is issued
  (``outside="raise"`` raises instead). ``interpolation="linear"`` interpolates
  linearly in pitch.
* A skew above the largest measured value, 3°26′, warns; skews from 0 to the smallest
  measured 42′ do not, because at zero skew the formula is the exact Hertz contact.
* Life against skew: ``L/L0 = (Q_n/Q_nom)^(−k)``, ``k = 1`` for wear (Archard) or
  ``k = 10/3`` for rolling contact fatigue of line contacts (ISO 281 roller-bearing
  exponent); see :data:`LIFE_MODELS`.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike

from .._finite import finite_guard
from .._registry import Registry
from .._results import Result, quantity
from .._typing import FloatOrArray
from .._validation import check_nonnegative, check_positive, check_range, warn_outside
from ..errors import InputError, ValidityRangeWarning
from . import hertz

if TYPE_CHECKING:
    from ..chains import Chain

__all__ = [
    "ARCMIN",
    "GAMMA_TABLE_PITCH",
    "GAMMA_TABLE_VALUE",
    "MEASURED_SKEW_RANGE",
    "WEAR_FACTOR_RANGE",
    "GAMMA_INTERPOLATIONS",
    "LIFE_MODELS",
    "skew_gamma",
    "skew_from_measurement",
    "design_skew",
    "skew_load_factor",
    "relative_life",
    "roller_contact_stress",
    "RollerContactResult",
    "RollerToothContact",
]

#: One arc minute [rad].
ARCMIN = np.pi / (180 * 60)
#: Chain pitches of the γ table of Garshniev & Maksymovych [m].
GAMMA_TABLE_PITCH = np.array([12.7, 15.875, 19.05, 25.4]) * 1e-3
#: γ of Garshniev & Maksymovych [1/arcmin²].
GAMMA_TABLE_VALUE = np.array([0.0023, 0.00195, 0.0016, 0.0012])
#: Measured skews of Garshniev & Maksymovych: 0°42′ … 3°26′ [rad].
MEASURED_SKEW_RANGE = (42 * ARCMIN, 206 * ARCMIN)
#: K_φ of Garshniev & Maksymovych [-].
WEAR_FACTOR_RANGE = (0.6, 0.7)

GAMMA_INTERPOLATIONS = Registry("interpolation")
GAMMA_INTERPOLATIONS.add("log", "piecewise linear in log(gamma) vs log(pitch)")
GAMMA_INTERPOLATIONS.add("linear", "piecewise linear in pitch")

#: Load exponent ``k`` of ``L ∝ Q^(−k)`` (``L ∝ σ^(−2k)`` for a line contact).
LIFE_MODELS = Registry("life model")
LIFE_MODELS.add("wear", 1.0)  # Archard: wear volume ∝ load × sliding distance
LIFE_MODELS.add("rolling-fatigue", 10.0 / 3.0)  # ISO 281:2007 roller bearings, L10=(C/P)^(10/3)


def _out(x: ArrayLike) -> FloatOrArray:
    x = np.asarray(x, dtype=float)
    return float(x) if x.ndim == 0 else x


#: Largest ``γ`` accepted [1/arcmin²]: about four times Garshniev & Maksymovych's largest table value
#: (0.0023 at 12.7 mm), which covers the 1/p extrapolation down to a 3 mm pitch.
GAMMA_MAX = 0.01


def check_gamma(gamma: ArrayLike) -> np.ndarray:
    """Refuse a ``γ`` outside [0, :data:`GAMMA_MAX`] 1/arcmin² (Garshniev & Maksymovych's table: 0.0012...0.0023).

    Examples
    --------
    >>> float(check_gamma(0.0016))
    0.0016
    >>> check_gamma(1e300)
    Traceback (most recent call last):
    ...
    chaindrive.errors.InputError: gamma must lie in [0, 0.01] 1/arcmin^2 (Garshniev & Maksymovych's table: 0.0012...0.0023), got 1e+300
    """
    return check_range("gamma", gamma, 0.0, GAMMA_MAX, unit="1/arcmin^2 (Garshniev & Maksymovych's table: 0.0012...0.0023)")


@finite_guard
def skew_gamma(pitch: ArrayLike, *, interpolation: str = "log", outside: str = "warn") -> FloatOrArray:
    r"""Coefficient ``γ`` of Garshniev & Maksymovych eq. (2) for a chain pitch [1/arcmin²].

    .. math:: \gamma(p):\ 12.7, 15.875, 19.05, 25.4\ \text{mm} \to
              0.0023, 0.00195, 0.0016, 0.0012

    Parameters
    ----------
    pitch : float or array_like
        Chain pitch ``t`` [m].
    interpolation : {"log", "linear"}
        Between table pitches: power law between the nodes (``"log"``, default) or
        linear in pitch.
    outside : {"warn", "raise"}
        Outside 12.7…25.4 mm: extrapolate ``γ = γ_end p_end / p`` with a
        :class:`ValidityRangeWarning` (default) or raise :class:`InputError`.

    Returns
    -------
    float or ndarray
        ``γ`` [1/arcmin²].

    Notes
    -----
    The table is close to ``γ = 0.0303 mm / p`` (largest deviation 4 % at 12.7 mm);
    that trend is used for extrapolation. Exact at the four table pitches.

    References
    ----------
    Garshniev & Maksymovych, paper 2, text after eq. (2).

    Examples
    --------
    >>> skew_gamma(0.01905)
    0.0016
    >>> round(skew_gamma(0.022225), 6)
    0.001371
    >>> round(skew_gamma(0.022225, interpolation="linear"), 6)
    0.0014
    """
    kind = GAMMA_INTERPOLATIONS.get(interpolation)
    del kind
    if outside not in ("warn", "raise"):
        raise InputError(f"outside must be 'warn' or 'raise', got {outside!r}")
    p = check_positive("pitch", pitch, "m")
    lo, hi = GAMMA_TABLE_PITCH[0], GAMMA_TABLE_PITCH[-1]
    tol = 1e-9
    out_lo = p < lo * (1 - tol)
    out_hi = p > hi * (1 + tol)
    if np.any(out_lo | out_hi):
        msg = (
            f"pitch = {np.round(p * 1e3, 4).tolist()} mm is outside the gamma table of Garshniev & Maksymovych "
            f"(12.7 ... 25.4 mm)"
        )
        if outside == "raise":
            raise InputError(msg)
        warnings.warn(msg + "; gamma extrapolated as gamma_end * p_end / p", ValidityRangeWarning, stacklevel=2)
    pc = np.clip(p, lo, hi)
    if interpolation == "log":
        g = np.exp(np.interp(np.log(pc), np.log(GAMMA_TABLE_PITCH), np.log(GAMMA_TABLE_VALUE)))
    else:
        g = np.interp(pc, GAMMA_TABLE_PITCH, GAMMA_TABLE_VALUE)
    # snap exact table values (avoid exp/log round-off at the nodes)
    for pt, gt in zip(GAMMA_TABLE_PITCH, GAMMA_TABLE_VALUE, strict=True):
        g = np.where(np.abs(pc - pt) <= 1e-12 * abs(pt), gt, g)  # np.isclose(pc, pt, rtol=1e-12, atol=0)
    g = np.where(out_lo, GAMMA_TABLE_VALUE[0] * lo / p, g)
    g = np.where(out_hi, GAMMA_TABLE_VALUE[-1] * hi / p, g)
    return _out(g)


@finite_guard
def skew_from_measurement(height_difference: ArrayLike, base: ArrayLike) -> FloatOrArray:
    r"""Skew angle from the two probe depths of Garshniev & Maksymovych measuring device.

    .. math:: \varphi = \arctan\frac{|\Delta h|}{B}

    Parameters
    ----------
    height_difference : float or array_like
        Difference ``Δh`` of the depths of the two probe plates [m] (its sign only
        tells the direction of skew and is dropped).
    base : float or array_like
        Distance ``B`` between the probe plates (≈ roller length) [m].

    Returns
    -------
    float or ndarray
        ``φ`` [rad].

    References
    ----------
    Garshniev & Maksymovych, paper 2, formula under Fig. 1.

    Examples
    --------
    >>> round(skew_from_measurement(0.185e-3, 12.7e-3) / ARCMIN, 1)
    50.1
    """
    dh = np.abs(np.asarray(check_range("height_difference", height_difference), dtype=float))
    if np.any(~np.isfinite(dh)):
        raise InputError("height_difference must be finite (-inf < height_difference < inf m)")
    b = check_positive("base", base, "m")
    return _out(np.arctan(dh / b))


@finite_guard
def design_skew(max_skew: ArrayLike, wear_factor: ArrayLike = 0.65) -> FloatOrArray:
    r"""Design skew ``φ_p = φ_p,max K_φ`` of Garshniev & Maksymovych.

    .. math:: \varphi_p = \varphi_{p,max} K_\varphi

    Parameters
    ----------
    max_skew : float or array_like
        Largest skew ``φ_p,max`` [rad], ``0 <= φ < π/2``; above 3°26′ (the largest
        measured skew) a :class:`ValidityRangeWarning` is issued.
    wear_factor : float or array_like
        ``K_φ`` [-], ``0 < K_φ <= 1``; outside 0.6…0.7 (the paper's range) a warning.

    Returns
    -------
    float or ndarray
        Design skew ``φ_p`` [rad].

    References
    ----------
    Garshniev & Maksymovych, paper 2, text after eq. (2).

    Examples
    --------
    >>> round(design_skew(50 * ARCMIN, 0.65) / ARCMIN, 2)
    32.5
    """
    phi = check_range("max_skew", max_skew, 0.0, np.pi / 2, high_inclusive=False, unit="rad")
    k = check_range("wear_factor", wear_factor, 0.0, 1.0, low_inclusive=False)
    warn_outside("max_skew", phi, 0.0, MEASURED_SKEW_RANGE[1], "Garshniev & Maksymovych (measured skews up to 3°26′ = 0.05992 rad)")
    warn_outside("wear_factor", k, *WEAR_FACTOR_RANGE, "Garshniev & Maksymovych (K_phi = 0.6...0.7)")
    return _out(phi * k)


@finite_guard
def skew_load_factor(skew: ArrayLike, gamma: ArrayLike) -> FloatOrArray:
    r"""Load factor ``Q_n / Q_nom = 1 + γ φ_p²`` of Garshniev & Maksymovych eq. (2).

    .. math:: \frac{Q_n}{Q_{nom}} = 1 + \gamma\,\varphi_p^2,\quad \varphi_p\ \text{in arc minutes}

    Parameters
    ----------
    skew : float or array_like
        Design skew ``φ_p`` [rad] (:func:`design_skew`).
    gamma : float or array_like
        ``γ`` [1/arcmin²] (:func:`skew_gamma`).

    Returns
    -------
    float or ndarray
        ``1 + γ φ_p²`` [-].

    References
    ----------
    Garshniev & Maksymovych, paper 2, eq. (2).

    Examples
    --------
    >>> round(skew_load_factor(32.5 * ARCMIN, 0.0016), 3)
    2.69
    """
    phi = check_nonnegative("skew", skew, "rad")
    g = check_gamma(gamma)
    return _out(1.0 + g * (phi / ARCMIN) ** 2)


@finite_guard
def relative_life(load_factor: ArrayLike, model: str = "wear", *, exponent: float | None = None) -> FloatOrArray:
    r"""Life relative to the unskewed contact, ``L / L0 = (Q_n / Q_nom)^(−k)``.

    .. math:: \frac{L}{L_0} = \left(\frac{Q_n}{Q_{nom}}\right)^{-k}
              = \left(\frac{\sigma}{\sigma_0}\right)^{-2k}

    Parameters
    ----------
    load_factor : float or array_like
        ``Q_n / Q_nom >= 1`` [-] (:func:`skew_load_factor`).
    model : {"wear", "rolling-fatigue"}
        ``k = 1`` (Archard wear: wear per cycle ∝ load, life to a wear limit ∝ 1/load)
        or ``k = 10/3`` (ISO 281 roller bearings, rolling contact fatigue of a line
        contact). Ignored when ``exponent`` is given.
    exponent : float, optional
        A user load exponent ``k > 0``.

    Returns
    -------
    float or ndarray
        ``L / L0`` [-].

    References
    ----------
    J. F. Archard, "Contact and rubbing of flat surfaces", J. Appl. Phys. 24 (1953)
    981–988; ISO 281:2007, clause 6 (``L10 = (C/P)^p``, ``p = 10/3`` roller bearings).

    Examples
    --------
    >>> round(relative_life(2.69, "wear"), 3)
    0.372
    >>> round(relative_life(2.69, "rolling-fatigue"), 4)
    0.0369
    """
    k = LIFE_MODELS.get(model) if exponent is None else float(check_positive("exponent", exponent))
    f = check_range("load_factor", load_factor, 1.0, np.inf, high_inclusive=False)
    return _out(f ** (-k))


@dataclass(frozen=True)
class RollerContactResult(Result):
    """Roller–tooth contact with skew (Garshniev & Maksymovych); all fields in SI units.

    Fields: ``nominal_load`` Q_nom [N], ``max_skew`` φ_p,max [rad], ``design_skew`` φ_p
    [rad], ``gamma`` [1/arcmin²], ``load_factor`` Q_n/Q_nom [-], ``equivalent_load`` Q_n
    [N], ``reduced_radius`` ρ [m], ``effective_modulus`` E* [Pa], ``stress_unskewed`` σ
    at zero skew [Pa], ``stress`` σ with skew [Pa], ``stress_ratio`` [-],
    ``half_width`` of the contact strip at Q_n [m], ``relative_life_wear`` and
    ``relative_life_fatigue`` L/L0 [-], ``contact`` "convex"/"concave".
    """

    nominal_load: np.ndarray | float = quantity("N")
    max_skew: np.ndarray | float = quantity("rad")
    design_skew: np.ndarray | float = quantity("rad")
    gamma: np.ndarray | float = quantity("1/arcmin^2")
    load_factor: np.ndarray | float = quantity("1")
    equivalent_load: np.ndarray | float = quantity("N")
    reduced_radius: np.ndarray | float = quantity("m")
    effective_modulus: np.ndarray | float = quantity("Pa", display="GPa")
    stress_unskewed: np.ndarray | float = quantity("Pa")
    stress: np.ndarray | float = quantity("Pa")
    stress_ratio: np.ndarray | float = quantity("1")
    half_width: np.ndarray | float = quantity("m")
    relative_life_wear: np.ndarray | float = quantity("1")
    relative_life_fatigue: np.ndarray | float = quantity("1")
    contact: str


@finite_guard
def roller_contact_stress(
    load: ArrayLike,
    roller_diameter: ArrayLike,
    seat_radius: ArrayLike,
    length: ArrayLike,
    *,
    contact: str = "concave",
    max_skew: ArrayLike = 0.0,
    wear_factor: ArrayLike = 0.65,
    pitch: float | None = None,
    gamma: float | None = None,
    elastic_modulus: float = hertz.STEEL_ELASTIC_MODULUS,
    poisson_ratio: float = hertz.STEEL_POISSON_RATIO,
    tooth_elastic_modulus: float | None = None,
    tooth_poisson_ratio: float | None = None,
    interpolation: str = "log",
    outside: str = "warn",
) -> RollerContactResult:
    r"""Contact stress between a chain roller and a sprocket tooth, with skew (Garshniev & Maksymovych).

    .. math:: \sigma = \sqrt{\frac{Q_n E^*}{\pi L_p \rho}},\quad
              Q_n = Q_{nom}(1+\gamma\varphi_p^2),\quad
              \frac{1}{\rho} = \frac{2}{D_p} \pm \frac{1}{r_1}

    For equal steels (``ν = 0.3``) this is Garshniev & Maksymovych eq. (1), ``0.418 sqrt(Q_n E/(L_p ρ))``.

    Parameters
    ----------
    load : float or array_like
        Nominal compressive force on the roller ``Q_nom`` [N].
    roller_diameter : float or array_like
        ``D_p`` [m].
    seat_radius : float or array_like
        Tooth profile radius in the contact zone ``r1`` [m] (seat radius for
        ``contact="concave"``, flank radius for ``"convex"``).
    length : float or array_like
        Roller (contact) length ``L_p`` [m].
    contact : {"concave", "convex"}
        Roller in the concave seat (default) or on a convex flank.
    max_skew : float or array_like
        Largest measured skew ``φ_p,max`` [rad] (:func:`skew_from_measurement`).
    wear_factor : float or array_like
        ``K_φ`` [-], the paper's range 0.6…0.7.
    pitch : float, optional
        Chain pitch [m], used for ``γ`` (:func:`skew_gamma`) when ``gamma`` is None.
    gamma : float, optional
        ``γ`` [1/arcmin²] given directly.
    elastic_modulus, poisson_ratio : float
        Roller material [Pa, -].
    tooth_elastic_modulus, tooth_poisson_ratio : float, optional
        Tooth material (default: as the roller).
    interpolation, outside : str
        Passed to :func:`skew_gamma`.

    Returns
    -------
    RollerContactResult

    Raises
    ------
    InputError
        Non-positive load/dimensions, negative skew, missing pitch and gamma with a
        non-zero skew.
    InfeasibleError
        Concave seat not larger than the roller.

    Notes
    -----
    Garshniev & Maksymovych's range: pitches 12.7…25.4 mm, skews up to 3°26′, ``K_φ = 0.6…0.7``.
    A roller in a seat barely larger than itself (ISO 606 ``r_i``) is a conforming
    contact: when the Hertz half-width exceeds 0.1 of the roller radius a
    :class:`ValidityRangeWarning` says so (the Hertz value is then an upper estimate).

    References
    ----------
    Garshniev & Maksymovych, paper 2, eqs. (1)–(3); Johnson 1985 §4.3 eq. (4.45).

    Examples
    --------
    Roller of a 16B chain on a convex flank of radius 68.7 mm (ISO 606 ``r_e,max``, z = 19):

    >>> r = roller_contact_stress(5e3, 15.88e-3, 68.7e-3, 17e-3, contact="convex",
    ...                           pitch=25.4e-3, max_skew=50 * ARCMIN)
    >>> round(r.stress_unskewed / 1e6), round(r.stress / 1e6), round(r.load_factor, 3)
    (1232, 1855, 2.268)
    """
    q = check_positive("load", load, "N")
    d = check_positive("roller_diameter", roller_diameter, "m")
    ln = check_positive("length", length, "m")
    rho = hertz.reduced_radius(d / 2, seat_radius, contact)
    es = hertz.effective_modulus(elastic_modulus, poisson_ratio, tooth_elastic_modulus, tooth_poisson_ratio)
    phi_p = design_skew(max_skew, wear_factor)
    g: FloatOrArray
    if gamma is None:
        if pitch is None:
            if np.any(np.asarray(phi_p) > 0):
                raise InputError("pitch (12.7 ... 25.4 mm) or gamma (> 0) is needed when max_skew > 0")
            g = 0.0
        else:
            g = skew_gamma(pitch, interpolation=interpolation, outside=outside)
    else:
        g = check_gamma(gamma)
    factor = skew_load_factor(phi_p, g)
    qn = q * factor
    s0 = hertz.hertz_line_pressure(q, ln, rho, es)
    s = hertz.hertz_line_pressure(qn, ln, rho, es)
    b = hertz.hertz_line_half_width(qn, ln, rho, es)
    hertz.warn_conformal(b, d / 2, "roller-tooth contact")
    return RollerContactResult(
        nominal_load=_out(q),
        max_skew=_out(np.asarray(max_skew, dtype=float)),
        design_skew=phi_p,
        gamma=_out(g),
        load_factor=factor,
        equivalent_load=_out(qn),
        reduced_radius=rho,
        effective_modulus=es,
        stress_unskewed=s0,
        stress=s,
        stress_ratio=_out(np.asarray(s) / np.asarray(s0)),
        half_width=b,
        relative_life_wear=relative_life(factor, "wear"),
        relative_life_fatigue=relative_life(factor, "rolling-fatigue"),
        contact=contact,
    )


@dataclass(frozen=True)
class RollerToothContact:
    """A roller on a sprocket tooth: geometry and materials, SI units.

    Parameters
    ----------
    pitch : float
        Chain pitch [m].
    roller_diameter : float
        ``D_p`` [m].
    seat_radius : float
        Tooth profile radius ``r1`` in the contact zone [m].
    length : float
        Roller length ``L_p`` [m].
    contact : str
        ``"concave"`` (seat) or ``"convex"`` (flank).
    elastic_modulus, poisson_ratio : float
        Steel by default [Pa, -].

    Examples
    --------
    >>> c = RollerToothContact(0.0254, 15.88e-3, 68.7e-3, 17e-3, contact="convex")
    >>> round(c.stress(5e3, max_skew=50 * ARCMIN).stress / 1e6)
    1855
    """

    pitch: float
    roller_diameter: float
    seat_radius: float
    length: float
    contact: str = "concave"
    elastic_modulus: float = hertz.STEEL_ELASTIC_MODULUS
    poisson_ratio: float = hertz.STEEL_POISSON_RATIO

    def __post_init__(self) -> None:
        from .._finite import check_finite_fields

        check_finite_fields(self)  # NaN/inf refused here, not carried into a result

    @classmethod
    def from_chain(cls, chain: Chain | str, *, seat_radius: float | None = None, length: float | None = None,
                   contact: str = "concave") -> RollerToothContact:
        """From a catalogue chain (``chaindrive.chains.get``) or a Chain-like object.

        ``seat_radius`` defaults to ISO 606 ``r_i,min = 0.505 d1`` (clause 5.4.2), the
        length to the width between inner plates ``b1`` (the roller is a little
        shorter; pass ``length`` for the real value).
        """
        if isinstance(chain, str):
            from .. import chains

            chain = chains.get(chain)
        d1 = getattr(chain, "roller_diameter", None)
        if d1 is None:
            raise InputError(f"chain {getattr(chain, 'name', chain)!r} has no roller diameter (a roller chain is needed)")
        if seat_radius is None:
            seat_radius = 0.505 * d1
        if length is None:
            length = getattr(chain, "inner_width", None)
            if length is None:
                raise InputError("length (roller length > 0 m) is needed: the chain has no inner width")
        return cls(chain.pitch, d1, seat_radius, length, contact)

    def stress(self, load: ArrayLike, *, max_skew: ArrayLike = 0.0, wear_factor: ArrayLike = 0.65,
               outside: str = "warn") -> RollerContactResult:
        """Contact stress for ``load`` [N] and ``max_skew`` [rad]; see :func:`roller_contact_stress`."""
        return roller_contact_stress(
            load,
            self.roller_diameter,
            self.seat_radius,
            self.length,
            contact=self.contact,
            max_skew=max_skew,
            wear_factor=wear_factor,
            pitch=self.pitch,
            elastic_modulus=self.elastic_modulus,
            poisson_ratio=self.poisson_ratio,
            outside=outside,
        )
