"""The dynamic tension of the running chain, behind one function (:func:`dynamic_tension`).

The peak tight-span tension of the running drive is the static tight-side tension plus the
dynamic tension ``F_d`` this module gives. It is its own check in the analysis
(:func:`chaindrive.analysis.loads.peak_tension_check`), never part of the static safety.
Every caller (the loads part, the design procedure through it, the studio, studies) reaches
the model through :func:`dynamic_tension` only, so that a better model (a reduced model
calibrated against the validated simulation) replaces it here and nowhere else.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .. import loads as F
from .._results import Result, quantity
from ..drive.model import Drive
from ._wheels import wheel_teeth
from .layout import DriveLayout

__all__ = ["DynamicTension", "dynamic_tension", "polygonal_spring_mass", "SPRING_MASS_VALIDITY", "RIGID_VALIDITY",
           "RUNNING_VALIDITY"]

#: What the spring–mass model is worth, said where its number is shown (docs/design.md, "The
#: dynamic load and the simulation").
SPRING_MASS_VALIDITY = ("not validated against measurement: within 5-12 % of the simulated peak on the three "
                        "drives it was accepted on, -37 % to +161 % elsewhere (docs/design.md, 'The dynamic load "
                        "and the simulation'); EA, the wheel inertia and the damping ratio are assumed")
#: What the reduced running-tension model is worth outside its validated range (docs/design.md,
#: "The running peak tension").
RUNNING_VALIDITY = ("reduced model calibrated against the simulation (its spans damped with the resonance check's "
                    "zeta = 0.02 at the tooth frequency, an assumption), outside its validated range (the sweep's "
                    "input ranges, chain speed <= 12 m/s): extrapolated; over the 64-drive sweep out of sample worst "
                    "22 % (rms 8 %); the simulation itself is not validated against measurement (docs/design.md, "
                    "'The running peak tension')")
#: What the rigid-chain estimate is worth.
RIGID_VALIDITY = ("rigid-chain inertia force: a lower bound of the polygonal action's peak (no elastic "
                  "response, no seating impact); not validated against measurement")


@dataclass(frozen=True)
class DynamicTension(Result):
    """The dynamic tension of the running chain (see :func:`dynamic_tension`).

    Attributes
    ----------
    value : float
        Peak dynamic tension ``F_d`` added to the static tight-side tension [N].
    moving_mass : float
        Mass the model accelerates, reduced to the chain [kg].
    stiffness : float or None
        Stiffness holding that mass [N/m] (spring–mass model only).
    model : str
        Which model gave ``value`` and its inputs.
    validity : str
        How far the model is checked.
    """

    value: float = quantity("N")
    moving_mass: float = quantity("kg")
    stiffness: float | None = quantity("N/m", default=None)
    model: str = ""
    validity: str = ""


def dynamic_tension(drive: Drive, layout: DriveLayout, acceleration_peak: float, *,
                    moving_mass: float | None = None, tight: float | None = None) -> DynamicTension:
    r"""Peak dynamic tension of the running chain's tight span: the one entry of the model.

    .. math:: F_{peak} = F_{tight} + F_d

    Where it applies (free entry on a roller-chain sprocket that drives a load taken off at the
    wheel the tight span leaves) and the tight-side tension ``tight`` is given (the loads part
    gives it): the reduced model of the running peak tension,
    ``F_d = running_peak_tension(F_t, ω, p, z₁, q, k_c) − F_t``
    (:func:`chaindrive.vibration.running_tension.running_peak_tension`: the seating impact of
    a link on its seat, calibrated against the simulation over a sweep of 64 drives;
    docs/design.md, "The running peak tension"), with a ``ValidityRangeWarning`` outside the
    sweep; without ``tight``, the periodic response of the driven side on its spans
    (:func:`polygonal_spring_mass`, :func:`chaindrive.loads.polygonal_dynamic_tension`). Else
    ``F_d = m a_max`` with the whole chain moved rigidly (or ``moving_mass`` when given).

    Parameters
    ----------
    drive : Drive
    layout : DriveLayout
    acceleration_peak : float
        Peak chain acceleration of the entry [m/s²] (the rigid estimate uses it).
    moving_mass : float, optional
        Mass moved rigidly [kg]: then ``F_d = m a_max``.
    tight : float, optional
        Tight-side tension ``F_t = K_s T/R + S + q v²`` [N]: then the reduced model.

    Returns
    -------
    DynamicTension

    References
    ----------
    Dolipiński et al., eqs (1)–(13) (polygonal speed of free entry); S. S. Rao, Mechanical
    Vibrations, 5th ed., §§2.6, 3.6, 4.2; docs/design.md, "The dynamic load and the simulation"
    and "The running peak tension".

    Examples
    --------
    >>> from chaindrive.drive.project import load_project
    >>> from chaindrive.analysis.layout import drive_layout
    >>> d = load_project("examples/roller_industrial.toml")
    >>> round(dynamic_tension(d, drive_layout(d), 127.0).value)
    3934
    >>> round(dynamic_tension(d, drive_layout(d), 127.0, tight=2254.09).value)
    2472
    """
    sm = None if moving_mass is not None else polygonal_spring_mass(drive, layout)
    if sm is None:
        m = float(moving_mass) if moving_mass is not None else drive.mass_per_length * layout.links * drive.pitch
        return DynamicTension(value=float(F.dynamic_tension(m, acceleration_peak)), moving_mass=m, stiffness=None,
                              model="m a_max, the whole chain moved rigidly", validity=RIGID_VALIDITY)
    j, m, k = sm
    if tight is not None and drive.chain.inner_width is not None and drive.chain.breaking_force is not None:
        return _running_tension(drive, layout, tight, j, m, float(drive.chain.inner_width),
                                float(drive.chain.breaking_force))
    R = float(layout.pitch_radii[drive.driving_index])
    Fd = float(F.polygonal_dynamic_tension(drive.speed, R, math.pi / wheel_teeth(drive.driving_wheel, "the driving wheel"),
                                           k, m))
    return DynamicTension(
        value=Fd, moving_mass=m, stiffness=k,
        model=(f"wheel {drive.wheels[j].name!r} as a mass on its spans, driven by the polygonal speed "
               f"(periodic response, ζ = {F.POLYGONAL_DAMPING_RATIO:g})"),
        validity=SPRING_MASS_VALIDITY)


def _running_tension(drive: Drive, layout: DriveLayout, tight: float, j: int, m: float, width: float,
                     breaking_force: float) -> DynamicTension:
    """``F_d = F_peak − F_t`` of :func:`chaindrive.vibration.running_tension.running_peak_tension`
    (the seats at :func:`~chaindrive.vibration.running_tension.seat_contact_stiffness`, each of
    ``n`` strands a simplex chain at ``F_t / n``); a ``ValidityRangeWarning`` outside its
    calibration sweep's input ranges. The steady state of the simulation
    (:func:`chaindrive.simulation.running_tension.simulated_dynamic_tension`) is not taken there instead: on the three drives outside
    the ranges checked against a run from rest its per-period peak was −16.8, −3.9 and −9.4 % off,
    the reduced model −13.8, −21.2 and −2.7 % (``benchmarks/_dynamic_sweep.py --outside``, the damped
    simulation), at 0.1–2 s of
    CPU a drive against microseconds (docs/design.md, 'The running peak tension')."""
    import warnings

    from ..errors import ValidityRangeWarning
    from ..vibration import running_tension as RT

    n = drive.chain.strands
    z0 = wheel_teeth(drive.driving_wheel, "the driving wheel")
    kc = n * float(RT.seat_contact_stiffness(tight / n, width))
    R = float(layout.pitch_radii[drive.driving_index])
    inputs: dict[str, float] = dict(
        pitch=drive.pitch, teeth=z0, teeth_driven=wheel_teeth(drive.wheels[j], "the driven wheel"),
        angular_velocity=drive.speed, centre_distance=float(layout.wrap.span_length[layout.tight_span]),
        pull=float(drive.torque()) / R, breaking_force=breaking_force)
    RT.check_running_tension_range(**inputs, wheels=len(drive.wheels), stacklevel=5)
    swept = not RT.running_tension_range_violations(**inputs, wheels=len(drive.wheels))
    peak = float(RT.running_peak_tension(tight, drive.speed, drive.pitch, z0, drive.mass_per_length, kc))
    c = RT.calibration()
    v = c.validated
    ratio = float(RT.tooth_frequency_ratio(drive.speed, z0, drive.pitch, tight, drive.mass_per_length,
                                           float(layout.wrap.span_length[layout.tight_span])))
    why = RT.validated_range_violations(drive.speed * z0 * drive.pitch / (2 * math.pi), ratio)
    if swept and not why:
        clear = (f", the tooth frequency clear of the tight span's first {v['resonance_modes']:.0f} transverse natural "
                 f"frequencies by {100 * v['resonance_band']:g} %, here z w / w1 = {ratio:.3g}"
                 if v["resonance_band"] > 0 else "")
        chosen = (f" ({100 * v['nested_worst']:.1f} % with the range chosen without them)"
                  if abs(v["nested_worst"] - v["worst"]) > 5e-4 else "")
        validity = (f"reduced model calibrated against the simulation (its spans damped with the resonance check's "
                    f"zeta = 0.02 at the tooth frequency, an assumption), in its validated range (chain speed <= "
                    f"{v['chain_speed_max']:g} m/s{clear}): {v['drives']:.0f} drives of the sweep within "
                    f"{100 * v['worst']:.1f} % out of sample, rms {100 * v['rms']:.1f} %{chosen}; the simulation itself "
                    f"is not validated against measurement (docs/design.md, 'The running peak tension')")
    else:
        validity = RUNNING_VALIDITY
    if why:
        warnings.warn(f"the dynamic tension's reduced model is outside its validated range ({'; '.join(why)}), where "
                      f"it agrees with the simulation within {100 * v['worst']:.1f} %: here up to "
                      f"{100 * max(c.loo_worst, v['outside_worst']):.0f} % off (docs/design.md, 'The running peak "
                      f"tension')", ValidityRangeWarning, stacklevel=5)
    return DynamicTension(
        value=peak - tight, moving_mass=m, stiffness=kc, validity=validity,
        model=(f"seating impact of a link on its seat (k_c = {kc:.3g} N/m, Palmgren), reduced model calibrated "
               f"against the simulation (running_peak_tension)"))



def polygonal_spring_mass(drive: Drive, layout: DriveLayout) -> tuple[int, float, float] | None:
    r"""The driven side of the tight span as a mass on the chain's spans: ``(wheel, m, k)``.

    The tight span joins the driving wheel to wheel ``j``; that wheel (its inertia
    :func:`chaindrive.loads.disc_inertia` at the pitch radius, as the torsional critical
    speed and the simulation assume), the chain wrapped on it and a third of each of its two
    spans (the consistent mass of a uniform spring) form the mass, its two spans
    ``Σ EA/l`` the stiffness (as :mod:`chaindrive.analysis.critical_speeds`):

    .. math:: m = \frac{J_j}{R_j^2} + q R_j θ_j + \frac{q (l_{j-1} + l_j)}{3}, \qquad
              k = EA \left(\frac{1}{l_{j-1}} + \frac{1}{l_j}\right)

    Known limits (measured against the simulation, docs/design.md, "The dynamic load and the
    simulation"): the slack span sags and holds the wheel with Ernst's stiffness
    ``12 T³/(w² l³)`` (1e4–1e5 N/m in the examples), not ``EA/l``; the tight span's sag (statically) and
    the seats (dynamically) soften it further, so the simulation's driven side is 2.5–3.2 times
    softer than ``k`` dynamically (natural frequency 1.6–1.8 times lower). ``k`` is kept as it is: the
    spring–mass ``F_d`` agrees with the simulated peaks on the acceptance drives through
    this stiffness, and a softer spring alone does not make it agree elsewhere.

    ``None`` where the model does not apply (then ``m a_max`` with the whole chain): round
    link chains and conveyors, a guide on the driving wheel (not free entry), a chain
    without mass per length, a load not taken off at the wheel the tight span leaves (an
    idler, the tensioner's wheel, a track's road wheel, a crawler drive's cams).

    >>> from chaindrive.drive.project import load_project
    >>> from chaindrive.analysis.layout import drive_layout
    >>> d = load_project("examples/roller_industrial.toml")
    >>> j, m, k = polygonal_spring_mass(d, drive_layout(d))
    >>> j, round(m, 2), round(k / 1e8, 3)
    (1, 16.9, 1.925)
    """
    from ..chains.stiffness import chain_axial_stiffness

    chain = drive.chain
    k0 = drive.driving_index
    if (chain.bar_diameter is not None or drive.conveyor is not None or chain.mass_per_length is None
            or drive.driving_wheel.teeth is None or any(g.wheel == drive.driving_wheel.name for g in drive.guides)):
        return None
    n = len(drive.wheels)
    t = layout.tight_span
    j = t if (t + 1) % n == k0 else (t + 1) % n
    far = drive.wheels[j]
    tensioner = drive.tensioner.wheel if drive.tensioner is not None else None
    if (far.teeth is None or far.kind == "idler" or far.name == tensioner or drive.track is not None
            or drive.crawler is not None):
        return None  # the load is not on the wheel the tight span leaves (idler, tensioner, track, crawler's cams)
    spans = layout.wrap.span_length
    l_in, l_out = float(spans[(j - 1) % n]), float(spans[j])
    R = float(layout.pitch_radii[j])
    q = float(drive.mass_per_length)
    m = float(F.disc_inertia(R)) / R**2 + q * R * float(layout.wrap.wrap_angle[j]) + q * (l_in + l_out) / 3.0
    ea = chain_axial_stiffness(chain) * chain.strands
    return j, m, ea * (1.0 / l_in + 1.0 / l_out)

