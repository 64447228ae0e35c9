"""The peak tight-span tension of a running roller-chain drive: the seats' contact
stiffness and a reduced model calibrated against the simulation (issue 29).

One formula per function, SI units, vectorised:

* :func:`seat_contact_stiffness`: a roller's seat as two steel line contacts in series
  (tooth–roller and roller–bushing), Palmgren's roller–raceway deformation, secant
  stiffness at the load;
* :func:`seating_impact_velocity`: the velocity of an engaging roller relative to its
  seat, ``ω p`` (the link pivoting about the last seated roller);
* :func:`seating_impact_force`: the peak force of that link's mass striking the seat
  spring, ``v √(k m)``;
* :func:`running_peak_tension`: the reduced model ``F_peak = F_tight (1 + a x^b (z/19)^c)``,
  ``x`` the impact force over the tight-side tension, with the constants ``a, b, c``
  calibrated over a sweep of simulated drives (:func:`calibration`, stored with their
  provenance in ``vibration/data/running_tension.json``), its validity range checked by
  :func:`check_running_tension_range`.

The derivations, the sweep and the accuracy are in docs/design.md, "The running peak
tension".
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from functools import cache
from pathlib import Path

import numpy as np

from .._typing import ArrayLike
from .._validation import check_nonnegative, check_positive, warn_outside
from ..units import angular_velocity_to_rpm

__all__ = ["PALMGREN_LINE_CONTACT", "RunningTensionCalibration", "calibration", "seat_contact_stiffness",
           "seating_impact_velocity", "seating_impact_force", "running_peak_tension",
           "running_tension_range_violations", "check_running_tension_range", "tooth_frequency_ratio",
           "span_resonance_mode", "validated_range_violations"]

#: Palmgren's roller–raceway (steel on steel line contact) deformation
#: ``δ = 3.84e-5 Q^0.9 / l^0.8`` (δ in mm, Q in N, l in mm); in SI
#: ``δ = 1.529e-10 Q^0.9 l^−0.8`` [m] with Q in N and l in m (A. Palmgren, *Ball and
#: Roller Bearing Engineering*, 3rd ed., Burbank 1959; T. A. Harris & M. N. Kotzalas,
#: *Rolling Bearing Analysis*, 5th ed., CRC 2007, "Essential Concepts", ch. 6).
PALMGREN_LINE_CONTACT = 3.84e-5 * 1e-3 * 1e3**-0.8

_DATA = Path(__file__).with_name("data") / "running_tension.json"


def seat_contact_stiffness(load: ArrayLike, width: ArrayLike, contacts: int = 2) -> np.ndarray:
    """Secant stiffness of a roller's seat: ``contacts`` steel line contacts in series [N/m].

    .. math:: k = \\frac{Q}{n\\,\\delta(Q)},\\qquad \\delta = 1.529\\times10^{-10}\\,Q^{0.9} l^{-0.8}

    Palmgren's roller–raceway deformation (``δ = 3.84e-5 Q^0.9 / l^0.8`` in mm, N, mm)
    for each of the ``n`` line contacts a seating roller carries in series: the tooth's
    seat on the roller and the roller on its bushing (``n = 2``); the plates and the pin
    are the chain's ``EA``. The simulation's seat spring is linear, so the law is taken
    as its secant through the working load ``Q`` (the tight-span tension, carried by the
    first seated roller).

    Parameters
    ----------
    load : array_like
        Roller load ``Q`` [N], > 0.
    width : array_like
        Contact length ``l`` [m] (the chain's inner width ``b1``, the roller's length), > 0.
    contacts : int
        Line contacts in series (default 2).

    Returns
    -------
    numpy.ndarray
        Stiffness [N/m].

    Notes
    -----
    Palmgren's formula is empirical for hardened bearing-steel rollers on raceways; a
    roller's seat is a nearly conforming concave arc (``r_i = 0.505 d₁``), for which the
    Hertzian line-contact approach depends on the radii only logarithmically. Tested
    against Roark's cylinder between two flat plates (within 25 % over 0.5…20 kN on
    17 mm). Clearances, oil films and the pin–bushing contact are not counted.

    References
    ----------
    A. Palmgren, Ball and Roller Bearing Engineering, 3rd ed., S. H. Burbank, 1959;
    T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis (Essential Concepts of Bearing
    Technology), 5th ed., CRC 2007, ch. 6.

    Examples
    --------
    >>> round(float(seat_contact_stiffness(2500.0, 0.01702)) / 1e8, 2)   # 16B at 2.5 kN
    2.75
    """
    q = check_positive("load", load, "N")
    w = check_positive("width", width, "m")
    check_positive("contacts", contacts)
    delta = PALMGREN_LINE_CONTACT * q**0.9 * w**-0.8
    return np.asarray(q / (contacts * delta))


def seating_impact_velocity(angular_velocity: ArrayLike, pitch: ArrayLike) -> np.ndarray:
    """Velocity of an engaging roller relative to its seat, ``v = ω p`` [m/s].

    .. math:: v_i = \\omega\\, p

    In the wheel's frame the last free link pivots about the last seated roller while the
    span it belongs to keeps its direction in space: relative to the wheel it turns at
    ``−ω``, so its free roller, a pitch ``p`` from the pivot, arrives at its seat with
    the speed ``ω p`` normal to the link (within ``cos(π/z)`` of the seat's normal):
    the impact velocity of Binder & Covert's engagement analysis.

    Parameters
    ----------
    angular_velocity : array_like
        Wheel speed ``ω`` [rad/s], > 0.
    pitch : array_like
        Chain pitch ``p`` [m], > 0.

    Returns
    -------
    numpy.ndarray
        ``v_i`` [m/s].

    References
    ----------
    R. C. Binder, W. V. Covert, Impact between chain roller and sprocket in a chain drive,
    J. Franklin Inst. 245 (1948) 319–329.

    Examples
    --------
    >>> round(float(seating_impact_velocity(100.531, 0.0254)), 3)   # 16B at 960 rpm
    2.553
    """
    w = check_positive("angular_velocity", angular_velocity, "rad/s")
    p = check_positive("pitch", pitch, "m")
    return np.asarray(w * p)


def seating_impact_force(velocity: ArrayLike, stiffness: ArrayLike, mass: ArrayLike) -> np.ndarray:
    """Peak force of a mass striking a linear spring, ``F = v √(k m)`` [N].

    .. math:: F_i = v\\,\\sqrt{k\\,m}

    Energy balance of the undamped impact, ``½ m v² = ½ k δ²``, and ``F = k δ``: here the
    engaging link's mass ``m = q p`` at the seating velocity
    (:func:`seating_impact_velocity`) on the seat's contact stiffness
    (:func:`seat_contact_stiffness`).

    Parameters
    ----------
    velocity : array_like
        Impact velocity [m/s], >= 0.
    stiffness : array_like
        Contact stiffness ``k`` [N/m], > 0.
    mass : array_like
        Striking mass ``m`` [kg], > 0.

    Returns
    -------
    numpy.ndarray
        ``F_i`` [N].

    References
    ----------
    W. Goldsmith, Impact: The Theory and Physical Behaviour of Colliding Solids, Arnold
    1960, ch. 4 (the linear-spring limit of Hertz's impact).

    Examples
    --------
    >>> round(float(seating_impact_force(2.0, 2e8, 0.05)))
    6325
    """
    v = check_nonnegative("velocity", velocity, "m/s")
    k = check_positive("stiffness", stiffness, "N/m")
    m = check_positive("mass", mass, "kg")
    return np.asarray(v * np.sqrt(k * m))


@dataclass(frozen=True)
class RunningTensionCalibration:
    """The reduced model's constants, validity and validated ranges, with their provenance.

    Attributes
    ----------
    coefficient, impact_exponent, teeth_exponent : float
        ``a``, ``b``, ``c`` of ``F_peak = F_tight (1 + a x^b (z/z_ref)^c)``.
    reference_teeth : float
        ``z_ref``.
    ranges : dict
        Validity range of each input, ``name -> (low, high)``, the sweep's span.
    provenance : str
        How the constants were obtained (the sweep, the reference, the fit, the accuracy).
    reference : str
        The simulated reference the constants are fitted to: ``"long"``, the median of all the
        per-tooth-period peaks of six 0.25 s windows after 2.5 s of settling.
    calibration_worst, calibration_rms : float
        In-sample relative errors over the drives the constants are fitted to (the validated
        range's) [1].
    crossval_worst, crossval_rms : float
        Over the whole sweep, out of sample: four-fold cross-validation (each fold predicted by
        the constants fitted on the other three), against the long reference [1].
    loo_worst, loo_rms : float
        The same by leave-one-out [1].
    short_crossval_worst, short_crossval_rms : float
        The four-fold cross-validation against the short reference (one window), refitted [1].
    validated : dict
        The validated range (:func:`validated_range_violations`): ``chain_speed_max`` [m/s],
        ``resonance_band`` and ``resonance_modes`` (:func:`span_resonance_mode`), the sweep's
        ``drives`` inside it, their out-of-sample ``worst`` and ``rms`` (the larger of four-fold
        and leave-one-out; long reference), ``short_worst``, ``short_rms`` (short reference),
        the check of the range's choice (``nested_drives``, ``nested_worst``, ``nested_rms``:
        the range chosen again inside each fold, the held-out drives inside it) and the
        stored model's ``outside_worst`` on the drives outside it.
    """
    coefficient: float
    impact_exponent: float
    teeth_exponent: float
    reference_teeth: float
    ranges: dict[str, tuple[float, float]]
    provenance: str
    reference: str
    calibration_worst: float
    calibration_rms: float
    crossval_worst: float
    crossval_rms: float
    loo_worst: float
    loo_rms: float
    short_crossval_worst: float
    short_crossval_rms: float
    validated: dict[str, float]


@cache
def calibration() -> RunningTensionCalibration:
    """The stored calibration (``vibration/data/running_tension.json``, written by
    ``scripts/calibrate_running_tension.py`` from ``benchmarks/data/dynamic_sweep*.csv``).

    >>> 0 < calibration().coefficient < 5
    True
    """
    raw = json.loads(_DATA.read_text())
    return RunningTensionCalibration(
        coefficient=float(raw["coefficient"]), impact_exponent=float(raw["impact_exponent"]),
        teeth_exponent=float(raw["teeth_exponent"]), reference_teeth=float(raw["reference_teeth"]),
        ranges={k: (float(v[0]), float(v[1])) for k, v in raw["ranges"].items()},
        provenance=str(raw["provenance"]), reference=str(raw["reference"]),
        calibration_worst=float(raw["calibration_worst"]), calibration_rms=float(raw["calibration_rms"]),
        crossval_worst=float(raw["crossval_worst"]), crossval_rms=float(raw["crossval_rms"]),
        loo_worst=float(raw["loo_worst"]), loo_rms=float(raw["loo_rms"]),
        short_crossval_worst=float(raw["short_crossval_worst"]), short_crossval_rms=float(raw["short_crossval_rms"]),
        validated={k: float(v) for k, v in raw["validated"].items()})


def running_peak_tension(tight_tension: ArrayLike, angular_velocity: ArrayLike, pitch: ArrayLike,
                         teeth: ArrayLike, mass_per_length: ArrayLike, contact_stiffness: ArrayLike) -> np.ndarray:
    """Peak tight-span tension of a running roller drive, the reduced model [N].

    .. math::

        F_{peak} = F_t \\left(1 + a\\, x^{b} \\left(\\frac{z_1}{19}\\right)^{c}\\right),\\qquad
        x = \\frac{\\omega p \\sqrt{k_c\\, q\\, p}}{F_t}

    ``F_t = T/R + S_slack + q v²`` is the quasi-static tight-side tension; ``x`` the
    seating impact force of one link (:func:`seating_impact_force` of
    :func:`seating_impact_velocity`, mass ``q p``, seat stiffness ``k_c``) over it. The
    impact is what the simulation shows to govern the peaks (docs/design.md: they scale
    with ``√k_c``, hardly with the driven wheel's inertia); ``(z/19)^c`` carries the
    polygon's share (fewer teeth, harder engagement). The constants ``a, b, c`` are not
    derived: they are fitted to the median per-tooth-period peak of the simulated
    tight-span tension over a sweep of two-sprocket drives (:func:`calibration`, its
    provenance; docs/design.md, "The running peak tension"), with the simulation's seats
    at :func:`seat_contact_stiffness`.

    Parameters
    ----------
    tight_tension : array_like
        ``F_t`` [N], > 0.
    angular_velocity : array_like
        Driving wheel speed ``ω`` [rad/s], > 0.
    pitch : array_like
        Chain pitch ``p`` [m], > 0.
    teeth : array_like
        Driving wheel teeth ``z₁``, > 0.
    mass_per_length : array_like
        Chain mass per length ``q`` [kg/m], > 0 (all strands).
    contact_stiffness : array_like
        Seat stiffness ``k_c`` [N/m], > 0 (all strands:
        ``strands * seat_contact_stiffness(F_t / strands, b1)``).

    Returns
    -------
    numpy.ndarray
        ``F_peak`` [N].

    Notes
    -----
    Validity range (the sweep's; :func:`check_running_tension_range` warns outside it):
    ISO 606 B simplex chains 08B…20B, ``z₁`` 13…27, ratio 1…3.5, 100…1800 rpm, chain
    speed ≤ 12 m/s, centre distance 25…60 pitches, pull 2…12 % of ``F_B``, two
    sprockets, free entry, no guides, idlers or tensioner. Multi-strand chains by the
    scaling ``x`` is invariant under (each strand a simplex chain at ``F_t / n``), not
    simulated. Accuracy against the simulation: ``calibration()`` (calibration and
    hold-out drives). The simulation itself is not validated against a measurement
    (docs/design.md).

    References
    ----------
    R. C. Binder, W. V. Covert, J. Franklin Inst. 245 (1948) 319–329 (seating impact);
    A. Palmgren, Ball and Roller Bearing Engineering, 1959 (seat stiffness); the
    calibration sweep: benchmarks/_dynamic_sweep.py, scripts/calibrate_running_tension.py.

    Examples
    --------
    >>> f = running_peak_tension(2254.0, 100.531, 0.0254, 19, 2.612, 2.5e8)
    >>> 1.5 < float(f) / 2254.0 < 4.0
    True
    """
    ft = check_positive("tight_tension", tight_tension, "N")
    z = check_positive("teeth", teeth)
    q = check_positive("mass_per_length", mass_per_length, "kg/m")
    p = check_positive("pitch", pitch, "m")
    force = seating_impact_force(seating_impact_velocity(angular_velocity, p), contact_stiffness, q * p)
    c = calibration()
    x = force / ft
    return np.asarray(ft * (1.0 + c.coefficient * x**c.impact_exponent * (z / c.reference_teeth) ** c.teeth_exponent))


def tooth_frequency_ratio(angular_velocity: ArrayLike, teeth: ArrayLike, pitch: ArrayLike, tight_tension: ArrayLike,
                          mass_per_length: ArrayLike, span_length: ArrayLike) -> np.ndarray:
    """Tooth frequency over the tight span's first transverse natural frequency, ``z ω / ω₁`` [1].

    .. math:: \\frac{z\\omega}{\\omega_1},\\qquad \\omega_1 = \\frac{\\pi}{l}\\sqrt{\\frac{F_t}{q}}
              \\left(1 - \\frac{v^2}{c^2}\\right),\\quad v = \\frac{z\\omega p}{2\\pi}

    The tight span as an axially moving string at the tight-side tension
    (:func:`chaindrive.vibration.string.moving_string_frequencies`), its ``n``-th natural
    frequency ``n ω₁``; the polygon drives it at the tooth frequency ``z ω``. A whole number ``n``
    is a span resonance of mode ``n`` (:func:`span_resonance_mode`).

    Parameters
    ----------
    angular_velocity : array_like
        Driving wheel ``ω`` [rad/s], > 0.
    teeth : array_like
        Driving wheel teeth ``z``, > 0.
    pitch : array_like
        [m], > 0.
    tight_tension : array_like
        ``F_t`` [N], > 0.
    mass_per_length : array_like
        ``q`` [kg/m], > 0.
    span_length : array_like
        Tight span ``l`` [m], > 0.

    Returns
    -------
    numpy.ndarray

    References
    ----------
    J. A. Wickert, C. D. Mote, Classical vibration analysis of axially moving continua,
    J. Appl. Mech. 57 (1990) 738-744, eq. (29).

    Examples
    --------
    >>> round(float(tooth_frequency_ratio(15.95, 18, 0.03175, 4246.0, 3.802, 1.4335)), 2)   # sweep drive S13
    3.93
    """
    from .string import moving_string_frequencies

    w = check_positive("angular_velocity", angular_velocity, "rad/s")
    z = check_positive("teeth", teeth)
    p = check_positive("pitch", pitch, "m")
    zw = z * w
    omega = moving_string_frequencies(check_positive("tight_tension", tight_tension, "N"),
                                      check_positive("mass_per_length", mass_per_length, "kg/m"),
                                      check_positive("span_length", span_length, "m"),
                                      chain_speed=zw * p / (2 * math.pi), modes=1)
    return np.asarray(zw / omega[..., 0])


def span_resonance_mode(frequency_ratio: ArrayLike, band: float | None = None, modes: int | None = None) -> np.ndarray:
    """The transverse mode ``n`` of the tight span the tooth frequency is in resonance with, 0 for none.

    .. math:: n:\\ \\left|\\frac{z\\omega}{n\\,\\omega_1} - 1\\right| < \\delta,\\qquad 1 \\le n \\le N

    Parameters
    ----------
    frequency_ratio : array_like
        ``z ω / ω₁`` (:func:`tooth_frequency_ratio`), > 0.
    band : float, optional
        ``δ``, the relative half-width of the resonance band (default the calibration's).
    modes : int, optional
        ``N``, the modes checked (default the calibration's).

    Returns
    -------
    numpy.ndarray of int

    Notes
    -----
    The band and the modes are not derived: they are the validated range's
    (:func:`calibration`, ``validated``), chosen on the calibration sweep (docs/design.md,
    "The running peak tension"). With the simulation's spans damped (since 2026-11-29) the
    drives on a mode are those the model over-predicts, so the stored range excludes none
    (band 0); the undamped calibration excluded ±5 % of modes 1–20, where its two worst
    drives were (``n`` = 4 at ``z ω / ω₁`` 3.93, ``n`` = 6 at 5.99).

    Examples
    --------
    >>> span_resonance_mode([3.93, 4.5, 5.99, 25.0], band=0.05, modes=20).tolist()
    [4, 0, 6, 0]
    """
    r = check_positive("frequency_ratio", frequency_ratio)
    d = float(calibration().validated["resonance_band"] if band is None else check_nonnegative("band", band))
    top = int(calibration().validated["resonance_modes"] if modes is None else check_nonnegative("modes", modes))
    # the modes either side of r (the band is relative: either may hold it); above the last mode, the last
    low = np.clip(np.floor(r), 1.0, max(top, 1))
    out = np.zeros(np.shape(r), dtype=int)
    best = np.full(np.shape(r), np.inf)
    for n in (low, np.minimum(low + 1, max(top, 1))):
        off = np.abs(r / n - 1)
        hit = (off < d) & (n <= top) & (off < best)
        out = np.where(hit, n.astype(int), out)
        best = np.where(hit, off, best)
    return np.asarray(out)


def validated_range_violations(chain_speed: float, frequency_ratio: float) -> tuple[str, ...]:
    """Why a drive lies outside the reduced model's validated range (empty inside).

    The validated range (:func:`calibration`, ``validated``): chain speed at most ``v_max``
    (12 m/s, the sweep's whole range) and, when the calibration has a band ``δ > 0``, the
    tooth frequency not within ``±δ`` of any of the tight span's first ``N`` transverse
    natural frequencies (:func:`span_resonance_mode`; the stored calibration has none).
    Inside it, over the sweep's drives, the model is within ``validated["worst"]`` of the
    simulation out of sample (docs/design.md, "The running peak tension").

    Parameters
    ----------
    chain_speed : float
        Mean chain speed ``v`` [m/s], > 0.
    frequency_ratio : float
        ``z ω / ω₁`` (:func:`tooth_frequency_ratio`), > 0.

    Returns
    -------
    tuple of str

    Examples
    --------
    >>> validated_range_violations(1.45, 4.5)
    ()
    >>> for why in validated_range_violations(13.0, 3.93):
    ...     print(why)
    chain speed 13 m/s is above 12 m/s
    """
    v = float(check_positive("chain_speed", chain_speed, "m/s"))
    r = float(check_positive("frequency_ratio", frequency_ratio))
    c = calibration().validated
    out = []
    if v > float(c["chain_speed_max"]):
        out.append(f"chain speed {v:.3g} m/s is above {float(c['chain_speed_max']):g} m/s")
    n = int(span_resonance_mode(r))
    if n:
        out.append(f"the tooth frequency is within {100 * float(c['resonance_band']):g} % of the tight span's "
                   f"transverse mode {n} (z w / w1 = {r:.3g})")
    return tuple(out)


def running_tension_range_violations(*, pitch: float, teeth: float, teeth_driven: float, angular_velocity: float,
                                     centre_distance: float, pull: float, breaking_force: float,
                                     wheels: int = 2) -> tuple[tuple[str, float, float, float], ...]:
    """The inputs of :func:`running_peak_tension` outside the calibration sweep's range.

    Parameters
    ----------
    pitch : float
        [m].
    teeth, teeth_driven : float
        Driving and driven wheel teeth.
    angular_velocity : float
        Driving wheel [rad/s].
    centre_distance : float
        [m].
    pull : float
        ``T/R`` [N].
    breaking_force : float
        Chain's ``F_B`` [N] (all strands).
    wheels : int
        Wheels of the drive (the sweep's drives have two).

    Returns
    -------
    tuple of (name, value, low, high)
        One entry per quantity outside its range (``calibration().ranges``); empty inside.

    Examples
    --------
    >>> running_tension_range_violations(pitch=0.0254, teeth=19, teeth_driven=57, angular_velocity=100.5,
    ...                                  centre_distance=1.05, pull=1940.0, breaking_force=60e3)
    ()
    >>> [v[0] for v in running_tension_range_violations(pitch=0.0254, teeth=19, teeth_driven=57,
    ...     angular_velocity=100.5, centre_distance=1.05, pull=1940.0, breaking_force=60e3, wheels=3)]
    ['wheels']
    """
    given = {"pitch": pitch, "teeth": teeth, "teeth_driven": teeth_driven, "angular_velocity": angular_velocity,
             "centre_distance": centre_distance, "pull": pull, "breaking_force": breaking_force}
    pitch, teeth, teeth_driven, angular_velocity, centre_distance, pull, breaking_force = (
        float(check_positive(name, value)) for name, value in given.items())
    r = calibration().ranges
    values = {"pitch": pitch, "teeth": teeth, "ratio": teeth_driven / teeth, "rpm": float(angular_velocity_to_rpm(angular_velocity)),
              "chain_speed": angular_velocity * teeth * pitch / (2 * math.pi), "centre_pitches": centre_distance / pitch,
              "pull_ratio": pull / breaking_force, "wheels": float(wheels)}
    return tuple((name, value, *r[name]) for name, value in values.items()
                 if not r[name][0] <= value <= r[name][1])


def check_running_tension_range(*, pitch: float, teeth: float, teeth_driven: float, angular_velocity: float,
                                centre_distance: float, pull: float, breaking_force: float, wheels: int = 2,
                                stacklevel: int = 3) -> None:
    """Warn (:class:`chaindrive.errors.ValidityRangeWarning`) for each input of
    :func:`running_peak_tension` outside the calibration sweep's range
    (:func:`running_tension_range_violations`).

    Parameters
    ----------
    pitch, teeth, teeth_driven, angular_velocity, centre_distance, pull, breaking_force, wheels
        As :func:`running_tension_range_violations`.
    stacklevel : int
        For the warning.

    Examples
    --------
    >>> import warnings
    >>> with warnings.catch_warnings(record=True) as w:
    ...     warnings.simplefilter("always")
    ...     check_running_tension_range(pitch=0.0254, teeth=19, teeth_driven=57, angular_velocity=100.5,
    ...                                 centre_distance=1.05, pull=1940.0, breaking_force=60e3)
    >>> len(w)
    0
    """
    source = "the running peak tension model (its calibration sweep)"
    for name, value, low, high in running_tension_range_violations(
            pitch=pitch, teeth=teeth, teeth_driven=teeth_driven, angular_velocity=angular_velocity,
            centre_distance=centre_distance, pull=pull, breaking_force=breaking_force, wheels=wheels):
        warn_outside(name, value, low, high, source, stacklevel=stacklevel + 1)


from .._finite import guard_public  # noqa: E402 - last: it wraps what this module defined

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
