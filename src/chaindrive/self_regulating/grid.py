"""The self-regulating drive over a grid of loads and wear elongations
(:func:`self_regulating_drive`, :class:`SelfRegulatingDriveResult`)."""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from .. import layout as L
from .._results import Result, quantity
from .._validation import as_float_array, check_nonnegative, check_positive, check_range
from ..errors import ConvergenceError, InfeasibleError, InputError, ValidityRangeWarning
from .equilibrium import (
    CarrierGeometry,
    _carrier_stiffness,
    _closed_form,
    rational_pivot,
    solve_equilibrium,
)
from .sag import carrier_natural_frequency
from .statics import _SOURCE, GRAVITY, _cross, _kind, _point, _reaction, _unit

# --------------------------------------------------------------------------- the drive

__all__ = [
    "SelfRegulatingDriveResult",
    "self_regulating_drive",
    "example_drive",
]

@dataclass(frozen=True)
class SelfRegulatingDriveResult(Result):
    """Slack tension, centre distance and ψ of a self-regulating drive over load and wear.

    Arrays of shape ``(loads, elongations)`` unless said otherwise; SI units.

    Attributes
    ----------
    wheel : str
        The wheel on the carrier.
    kind : {"pivot", "slide"}
    torque_reaction : {"carrier", "frame"}
    carrier_driving : bool
        The carrier wheel is the driving wheel.
    links : int
        Chain length [pitches].
    nominal_torque : float
        Torque on the driving wheel at load factor 1 [N·m].
    load_factor : ndarray, shape (loads,)
        Torque / nominal torque [-] (contains 1).
    elongation : ndarray, shape (elongations,)
        Wear elongation ``e`` [-].
    effective_pull : ndarray
        ``F_t`` [N].
    centre_distance : ndarray
        ``a`` [m] (closed form).
    carrier_coordinate : ndarray
        Swing [rad] (pivot) or travel [m] (slide) from the given position, growing with ``a``.
    coordinate_unit : str
    slack_tension, tight_tension : ndarray
        Static span tensions ``S2``, ``S1 = S2 + F_t`` [N] (closed form).
    base_tension : ndarray
        ``S0``, the part of ``S2`` set by weight and spring [N].
    psi : ndarray
        Regulation coefficient ψ [-].
    sag_ratio : ndarray
        Slack-span catenary sag / chord [-].
    shaft_load : ndarray
        Resultant of the span tensions on the carrier wheel [N].
    centre_distance_range : tuple of float
        Smallest and largest ``a`` over the grid [m].
    carrier_travel : float
        Range of the carrier coordinate [rad] or [m].
    rated_ratio : ndarray, shape (elongations,)
        ``S2 / F_t`` at load factor 1 [-].
    psi_rational : float
        ``S2* / F_t`` at load factor 1 for the least worn chain of the grid, ``S2*`` the
        smallest slack tension that keeps the sag within ``sag_allowance`` [-].
    slack_tension_rational : float
        ``S2*`` [N].
    sag_allowance : float
        [-].
    pivot_offset : float or None
        The given pivot's offset from the centre line toward the tight span [m] (pivot
        with the torque reacted on the carrier).
    pivot_rational : tuple of float or None
        A pivot (x, y) [m] that makes ψ equal ``psi_rational`` for the new and for the
        most worn chain (:func:`rational_pivot`), same carrier wheel position.
    pivot_rational_deviation : float or None
        Largest ``|ψ - psi_rational|`` over the wear range with that pivot [-].
    carrier_stiffness : ndarray
        ``K`` of the carrier at equilibrium [N·m/rad] or [N/m] (sag of the spans, arms,
        weight and spring).
    carrier_inertia : float or None
        [kg·m²] or [kg].
    carrier_frequency : ndarray or None
        ``sqrt(K/J)`` [rad/s].
    excitations : dict or None
        Exciting frequencies [rad/s] (driving, driven, meshing).
    resonance_margin : ndarray or None
        Smallest distance of ``P_c/ω_j`` to the band 0.7…1.4 over the excitations [-]
        (> 0 outside).
    numerical_centre_distance, numerical_slack_tension : ndarray or None
        Full nonlinear equilibrium (:func:`solve_equilibrium`) [m], [N].
    centre_distance_difference : float or None
        Largest ``|a - a_numerical|`` [m].
    slack_tension_difference : float or None
        Largest ``|S2 - S2_numerical| / S2_numerical`` [-].
    checks : tuple of dict
        ``name, value, limit, unit, passed, source, note, relation`` of each check
        (the fields of :class:`chaindrive.analysis.Check`; see
        :func:`self_regulating_checks`).
    warnings : tuple of str
    """

    wheel: str
    kind: str
    torque_reaction: str
    carrier_driving: bool
    links: int = quantity("1")
    nominal_torque: float = quantity("N*m")
    load_factor: np.ndarray = quantity("1")
    elongation: np.ndarray = quantity("1")
    effective_pull: np.ndarray = quantity("N")
    centre_distance: np.ndarray = quantity("m")
    carrier_coordinate: np.ndarray
    coordinate_unit: str
    slack_tension: np.ndarray = quantity("N")
    tight_tension: np.ndarray = quantity("N")
    base_tension: np.ndarray = quantity("N")
    psi: np.ndarray = quantity("1")
    sag_ratio: np.ndarray = quantity("1")
    shaft_load: np.ndarray = quantity("N")
    centre_distance_range: tuple[float, float] = quantity("m")
    carrier_travel: float
    rated_ratio: np.ndarray = quantity("1")
    psi_rational: float = quantity("1")
    slack_tension_rational: float = quantity("N")
    sag_allowance: float = quantity("1")
    pivot_offset: float | None = quantity("m")
    pivot_rational: tuple[float, float] | None = quantity("m")
    pivot_rational_deviation: float | None = quantity("1")
    carrier_stiffness: np.ndarray = quantity("N*m/rad|N/m")
    carrier_inertia: float | None = quantity("kg*m^2|kg")
    carrier_frequency: np.ndarray | None = quantity("rad/s", display="Hz")
    excitations: dict[str, float] | None = quantity("rad/s", display="Hz")
    resonance_margin: np.ndarray | None = quantity("1")
    numerical_centre_distance: np.ndarray | None = quantity("m")
    numerical_slack_tension: np.ndarray | None = quantity("N")
    centre_distance_difference: float | None = quantity("m")
    slack_tension_difference: float | None = quantity("1")
    checks: tuple
    warnings: tuple

    @property
    def passed(self) -> bool:
        """All checks passed (checks without a verdict do not count)."""
        return all(c["passed"] is not False for c in self.checks)


def self_regulating_drive(*, pitch: float, teeth_carrier: int, teeth_fixed: int,
                          carrier_centre: ArrayLike, fixed_centre: ArrayLike, links: int,
                          torque: float,
                          carrier_driving: bool, mass_per_length: float, kind: str = "pivot",
                          pivot: ArrayLike | None = None, direction: ArrayLike | None = None,
                          torque_reaction: str = "carrier", weight: float = 0.0,
                          weight_offset: ArrayLike = (0.0, 0.0), stiffness: float = 0.0,
                          preload: float = 0.0, travel: str = "ccw", bar_diameter: float | None = None,
                          load_factors: ArrayLike | None = None,
                          elongations: ArrayLike | None = None, sag_allowance: float = 0.02,
                          psi_tolerance: float = 1.0, numerical: bool = True, phases: int = 4,
                          wheel: str = "carrier", speed: float | None = None,
                          inertia: float | None = None,
                          axial_stiffness: float | None = None) -> SelfRegulatingDriveResult:
    r"""Slack tension, centre distance and ψ of a self-regulating drive over load and wear.

    .. math::
        S_2(F_t, e) = \psi(a)\,F_t + S_0(a),\qquad a = a(e, S_1, S_2)\ \text{from}\
        L_{taut}(a) + \Delta_1 + \Delta_2 = N p (1 + e)

    Parameters
    ----------
    pitch : float
        Chain pitch (inner link length) [m].
    teeth_carrier, teeth_fixed : int
        Teeth (pockets) of the carrier wheel and the fixed wheel [-].
    carrier_centre, fixed_centre : (float, float)
        Wheel centres [m]; the carrier wheel's is its reference (given) position.
    links : int
        Chain length [pitches].
    torque : float
        Nominal torque on the driving wheel ``T > 0`` [N·m] (load factor 1).
    carrier_driving : bool
        The carrier wheel drives (a motor on a pivoted base) or is driven.
    mass_per_length : float
        Chain mass per length [kg/m].
    kind : {"pivot", "slide"}
    pivot, direction
        Pivot [m] or slide direction; see :func:`carrier_position`.
    torque_reaction : {"carrier", "frame"}
        See :func:`span_arms`.
    weight, weight_offset, stiffness, preload
        See :func:`restoring_force`.
    travel : {"ccw", "cw"}
        Direction the chain circulates.
    bar_diameter : float, optional
        Round link chain [m].
    load_factors : array_like, optional
        Torque / nominal torque, ``>= 0``; default 7 steps over ``[0, 1.5]``; 1 is
        always added.
    elongations : array_like, optional
        Wear elongations ``0 <= e < 0.1``; default ``0, 0.01, 0.02, 0.03``.
    sag_allowance : float
        Largest acceptable slack-span sag / chord at the rated load (0.02 for the
        usual horizontal drives: ISO 10823 guidance and chain makers) [-].
    psi_tolerance : float
        Accepted excess of ``S2/F_t`` at the rated load over the rational value, as a
        fraction [-] (design choice of this package; 1.0: at most twice).
    numerical : bool
        Also solve the full equilibrium (:func:`solve_equilibrium`) at every grid point.
    phases : int
        Phases per wheel of the polygon length in the numerical solution.
    wheel : str
        Name of the carrier wheel (for reports).
    speed : float, optional
        Angular velocity of the driving wheel [rad/s]: the exciting frequencies of the
        carrier resonance check (:func:`chaindrive.vibration.excitation_frequencies`).
    inertia : float, optional
        Moment of inertia of the carrier about the pivot [kg·m²] (pivot) or its mass [kg]
        (slide); default the weight as a point mass at its centre of gravity,
        ``J = (W/g) |G - O|²`` (a lower bound) or ``W/g``.
    axial_stiffness : float, optional
        Axial stiffness ``EA`` of the chain [N]: its elastic stretch joins the length
        compatibility and the carrier stiffness. ``None``: inextensible; the carrier
        stiffness at high load is then an upper bound (the sag spring stiffens without
        limit as the tension rises).

    Returns
    -------
    SelfRegulatingDriveResult

    Raises
    ------
    InputError
        A parameter outside its range (the message names it).
    InfeasibleError
        The carrier cannot reach the centre distance a worn chain needs, or cannot keep
        the chain taut at some load (``S2 <= 0``), or equal tensions do not pull it in.

    Notes
    -----
    Closed-form model (docs/self_regulating.md): at a centre distance ``a`` the carrier
    position (:func:`carrier_position`), the arms and ψ (:func:`span_arms`,
    :func:`regulation_coefficient`) and the tensions (:func:`slack_tension`) are
    explicit; the chain length ``N p'`` equals the taut length in ISO 10823's form
    (:func:`worn_centre_distance`) plus the length the two spans' sag takes
    (:func:`sag_length_excess`), one scalar equation in ``a`` solved by vectorised
    bisection (48 halvings) below the taut value. The numerical solution differs from
    it by the polygon length (ISO approximation vs exact phase mean), the pitch-circle
    tangent points and the parabolic sag length; the result reports both and their
    largest difference. Valid while the slack span's sag ratio stays below about 0.1
    (warned) and the carrier stays clear of its dead point.

    References
    ----------
    Self-regulating drive paper (conclusions: ψ near its rational value over the wear range of
    ``a``); carrier statics and the rest derived in docs/self_regulating.md; ISO 10823:2004
    (chain length, sag guidance).

    Examples
    --------
    >>> r = self_regulating_drive(pitch=0.0254, teeth_carrier=19, teeth_fixed=38,
    ...     carrier_centre=(0.6, 0.0), fixed_centre=(0.0, 0.0), links=76, torque=300.0,
    ...     carrier_driving=True, mass_per_length=2.7, pivot=(0.66, -0.045), weight=400.0,
    ...     weight_offset=(0.08, 0.0), numerical=False)
    >>> r.psi.shape, r.psi[r.load_factor == 1][0].round(3).tolist()
    ((7, 4), [0.323, 0.205, 0.141, 0.103])
    """
    p = float(check_positive("pitch", pitch, "m"))
    from .._validation import check_teeth

    zc = int(check_teeth("teeth_carrier", teeth_carrier, minimum=3 if not bar_diameter else 2))
    zf = int(check_teeth("teeth_fixed", teeth_fixed, minimum=3 if not bar_diameter else 2))
    N = as_float_array("links", links)
    if N.ndim or N != np.round(N) or N <= 0:
        raise InputError(f"links must be a whole number > 0, got {links!r}")
    T = float(check_positive("torque", torque, "N·m"))
    qm = float(check_positive("mass_per_length", mass_per_length, "kg/m"))
    if travel not in ("ccw", "cw"):
        raise InputError(f"travel must be 'ccw' or 'cw', got {travel!r}")
    _kind(kind)
    _reaction(torque_reaction)
    if bar_diameter is not None:
        check_positive("bar_diameter", bar_diameter, "m")
    lam = np.linspace(0.0, 1.5, 7) if load_factors is None else check_nonnegative(
        "load_factors", load_factors)
    lam = np.unique(np.concatenate([np.ravel(lam), [1.0]]))
    e = np.array([0.0, 0.01, 0.02, 0.03]) if elongations is None else np.unique(np.ravel(
        check_range("elongations", elongations, 0.0, 0.1, high_inclusive=False)))
    sag_allow = float(check_range("sag_allowance", sag_allowance, 0.0, 0.5, low_inclusive=False))
    tol = float(check_nonnegative("psi_tolerance", psi_tolerance))
    if int(phases) < 1:
        raise InputError(f"phases must be a whole number >= 1, got {phases}")
    geo = CarrierGeometry(
        pitch=p, bar_diameter=bar_diameter, teeth_carrier=zc, teeth_fixed=zf,
        carrier_centre=_point("carrier_centre", carrier_centre),
        fixed_centre=_point("fixed_centre", fixed_centre), links=int(N),
        carrier_driving=bool(carrier_driving), travel=travel, kind=kind,
        pivot=None if pivot is None else _point("pivot", pivot),
        direction=None if direction is None else _unit("direction", direction),
        torque_reaction=torque_reaction, weight=float(check_nonnegative("weight", weight, "N")),
        weight_offset=_point("weight_offset", weight_offset),
        stiffness=float(check_nonnegative("stiffness", stiffness)),
        preload=float(as_float_array("preload", preload)), mass_per_length=qm,
        axial_stiffness=None if axial_stiffness is None else float(
            check_positive("axial_stiffness", axial_stiffness, "N")),
    )
    if kind == "pivot" and geo.pivot is None:
        raise InputError("pivot: a pivoted carrier needs the pivot position (x, y) in m")
    if kind == "slide" and geo.direction is None:
        raise InputError("direction: a sliding carrier needs the slide direction (x, y)")
    if not math.isfinite(geo.preload):
        raise InputError(f"preload must be a finite number, got {preload!r}")

    rc, rf = geo.radii(e)
    r_drive = rc if geo.carrier_driving else rf
    Ft = lam[:, None] * T / r_drive[None, :]
    EE = np.broadcast_to(e[None, :], Ft.shape)
    st = _closed_form(geo, Ft, EE)
    a, S2 = st["a"], st["S2"]
    S1 = S2 + Ft
    shaft = np.hypot(*(S1[..., None] * st["u_t"] + S2[..., None] * st["u_s"]).transpose(2, 0, 1))
    sag = _sag_ratio(st["chord"], st["incl_s"], S2, qm)
    notes = []
    K = _carrier_stiffness(geo, Ft, EE, st)
    J = None
    if inertia is not None:
        J = float(check_positive("inertia", inertia, "kg·m² or kg"))
    elif geo.weight > 0:
        mass = geo.weight / GRAVITY
        J = mass if kind == "slide" else mass * float(
            np.sum((geo.carrier_centre + geo.weight_offset - geo.pivot) ** 2))
    freq: Any = None
    margin: Any = None
    excitations: Any = None
    if J is not None and J > 0 and np.all(K > 0):
        freq = carrier_natural_frequency(K, J)
        if speed is not None:
            from ..vibration.resonance import excitation_frequencies, resonance_margin

            z_drive = zc if geo.carrier_driving else zf
            z_driven = zf if geo.carrier_driving else zc
            excitations = excitation_frequencies(float(check_positive("speed", speed, "rad/s")),
                                                 z_driven / z_drive, z_drive,
                                                 link_chain=bool(bar_diameter))
            margins: list[Any] = [resonance_margin(freq / w) for w in excitations.values()]
            margin = np.min(np.asarray(margins), axis=0)
    elif J is None:
        notes.append("carrier natural frequency not computed: give the carrier's weight or inertia")
    if geo.axial_stiffness is None:
        notes.append("inextensible chain (no axial_stiffness): the carrier stiffness and frequency "
                     "at high load are upper bounds")
    if np.any(sag > 0.1):
        msg = (f"the slack span sags up to {float(np.max(sag)):.3g} of its chord (at low load): "
               "the parabolic sag length of the closed form is outside its range (sag ratio <= "
               "0.1); the numerical equilibrium stays exact")
        warnings.warn(msg, ValidityRangeWarning, stacklevel=2)
        notes.append(msg)

    # the rational ψ: the smallest slack tension that keeps the sag within the allowance
    i1 = int(np.nonzero(lam == 1.0)[0][0])
    chord0, incl0 = float(st["chord"][i1, 0]), float(st["incl_s"][i1, 0])
    if abs(incl0) > math.radians(80):
        S2_star = qm * GRAVITY * chord0
    else:
        S2_star = float(L.tension_for_sag(chord0, incl0, sag_allow * chord0, qm)) / math.cos(incl0)
    psi_star = S2_star / float(Ft[i1, 0])
    rated_ratio = S2[i1] / Ft[i1]
    offset: Any = None
    pivot_star: Any = None
    pivot_dev: Any = None
    if kind == "pivot" and torque_reaction == "carrier":
        C = geo.carrier_centre
        n = (C - geo.fixed_centre) / float(np.hypot(*(C - geo.fixed_centre)))
        offset = float(geo.tight_side * _cross(n, geo.pivot - C))  # + toward the tight span
        try:
            pivot_star, pivot_dev = rational_pivot(geo, psi_star, (float(e[0]), float(e[-1])))
            pivot_star = (float(pivot_star[0]), float(pivot_star[1]))
        except (ConvergenceError, InfeasibleError) as exc:
            notes.append(f"no rational pivot found: {exc}")

    a_num = S2_num = None
    da: Any = None
    dS: Any = None
    if numerical:
        a_num = np.empty_like(a)
        S2_num = np.empty_like(a)
        for i in range(a.shape[0]):
            for j in range(a.shape[1]):
                _, a_num[i, j], S2_num[i, j] = solve_equilibrium(
                    geo, float(Ft[i, j]), float(e[j]), phases=int(phases), guess=float(st["q"][i, j]))
        da = float(np.max(np.abs(a - a_num)))
        dS = float(np.max(np.abs(S2 - S2_num) / S2_num))

    checks = [
        dict(name="slack-span sag at the rated load within the allowance over the wear range",
             value=float(np.max(sag[i1])), limit=sag_allow, unit="-",
             passed=bool(np.max(sag[i1]) <= sag_allow * (1 + 1e-9)), relation="<=",
             source="ISO 10823:2004 guidance (sag about 2 % of the span); " + _SOURCE,
             note="the self-regulating carrier must keep S2 >= S2* at the rated load as the chain wears"),
        dict(name="slack tension at the rated load near the rational value (S2/F_t <= (1 + tolerance) ψ*)",
             value=float(np.max(rated_ratio) / psi_star), limit=1.0 + tol, unit="-",
             passed=bool(np.max(rated_ratio) / psi_star <= 1.0 + tol), relation="<=",
             source=_SOURCE,
             note=f"ψ* = {psi_star:.4g} (S2* = {S2_star:.4g} N); S2/F_t over wear "
                  f"{float(np.min(rated_ratio)):.4g}…{float(np.max(rated_ratio)):.4g}; tolerance is "
                  "a design choice of this package"),
    ]
    k_unit = "N·m/rad" if kind == "pivot" else "N/m"
    checks.append(dict(
        name="carrier equilibrium statically stable (stiffness > 0) over load and wear",
        value=float(np.min(K)), limit=0.0, unit=k_unit, passed=bool(np.min(K) > 0), relation=">=",
        source=_SOURCE, note="stiffness of the sag of both spans, the arms, weight and spring"))
    if margin is not None:
        worst = np.unravel_index(int(np.argmin(margin)), margin.shape)
        checks.append(dict(
            name="carrier natural frequency outside 0.7…1.4 × every exciting frequency",
            value=float(np.min(margin)), limit=0.0, unit="-", passed=bool(np.min(margin) > 0),
            relation=">=",
            source="the tensioner paper (0.7 <= P/ω <= 1.4 forbidden); carrier stiffness derived "
                   "in docs/self_regulating.md",
            note=f"margin (distance to the band); carrier {float(np.min(freq)):.4g}…"
                 f"{float(np.max(freq)):.4g} rad/s, worst at load factor {lam[worst[0]]:g}, "
                 f"e = {e[worst[1]]:g}"))
    if dS is not None:
        checks.append(dict(
            name="closed form agrees with the numerical equilibrium (slack tension)",
            value=dS, limit=0.02, unit="-", passed=bool(dS <= 0.02), relation="<=", source=_SOURCE,
            note=f"largest centre-distance difference {da * 1e3:.3g} mm"))
    return SelfRegulatingDriveResult(
        wheel=str(wheel), kind=kind, torque_reaction=torque_reaction,
        carrier_driving=geo.carrier_driving, links=geo.links, nominal_torque=T,
        load_factor=lam, elongation=e, effective_pull=Ft, centre_distance=a,
        carrier_coordinate=st["q"], coordinate_unit="rad" if kind == "pivot" else "m",
        slack_tension=S2, tight_tension=S1, base_tension=st["S0"], psi=st["psi"],
        sag_ratio=sag, shaft_load=shaft,
        centre_distance_range=(float(np.min(a)), float(np.max(a))),
        carrier_travel=float(np.ptp(st["q"])), rated_ratio=rated_ratio,
        psi_rational=float(psi_star), slack_tension_rational=float(S2_star),
        sag_allowance=sag_allow, pivot_offset=offset, pivot_rational=pivot_star,
        pivot_rational_deviation=pivot_dev,
        carrier_stiffness=K, carrier_inertia=J, carrier_frequency=freq, excitations=excitations,
        resonance_margin=margin,
        numerical_centre_distance=a_num, numerical_slack_tension=S2_num,
        centre_distance_difference=da, slack_tension_difference=dS,
        checks=tuple(checks), warnings=tuple(notes),
    )


def example_drive(**changes: Any) -> SelfRegulatingDriveResult:
    """The example drive of :func:`self_regulating_drive`'s docstring (closed forms only).

    Parameters
    ----------
    **changes
        Arguments of :func:`self_regulating_drive` that replace the example's.

    Returns
    -------
    SelfRegulatingDriveResult

    References
    ----------
    As :func:`self_regulating_drive`.

    Examples
    --------
    >>> example_drive().psi.shape
    (7, 4)
    """
    kwargs: dict[str, Any] = dict(
        pitch=0.0254, teeth_carrier=19, teeth_fixed=38, carrier_centre=(0.6, 0.0),
        fixed_centre=(0.0, 0.0), links=76, torque=300.0, carrier_driving=True,
        mass_per_length=2.7, pivot=(0.66, -0.045), weight=400.0, weight_offset=(0.08, 0.0),
        numerical=False)
    kwargs.update(changes)
    return self_regulating_drive(**kwargs)


def _sag_ratio(chord, inclination, tension, mass_per_length):
    """Catenary sag / chord of the slack span (0 for a near-vertical span)."""
    chord = np.asarray(chord, dtype=float)
    incl = np.asarray(inclination, dtype=float)
    steep = np.abs(incl) > math.radians(80)
    safe = np.where(steep, 0.0, incl)
    H = np.asarray(tension, dtype=float) * np.cos(safe)
    f = L.catenary_sag(chord, safe, H, mass_per_length)
    return np.where(steep, 0.0, f / chord)
