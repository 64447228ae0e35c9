"""Chain tensions, shaft loads and the static checks of a drive."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from .. import layout as L
from .. import loads as F
from .._finite import finite_guard
from .._results import Result, quantity
from ..chains import Chain
from ..drive.model import Drive
from ..errors import ChainDriveError, InputError
from ..units import angular_velocity_to_rpm, rpm_to_angular_velocity
from ._memo import memo
from ._wheels import wheel_teeth
from .checks import Check
from .dynamic_tension import dynamic_tension, polygonal_spring_mass
from .layout import (
    MINIMUM_WRAP,
    DriveLayout,
    drive_layout,
    slack_span_sag,
    span_inclination,
    wrap_check,
)
from .parts import Part, PartContext, register_part

if TYPE_CHECKING:
    from .conveyor import ConveyorPull

__all__ = ["DriveLoads", "drive_loads", "polygonal_spring_mass", "span_tensions", "free_entry_acceleration",
           "static_safety_check", "peak_tension_check", "wrap_check", "MINIMUM_WRAP", "REQUIRED_STATIC_SAFETY",
           "required_static_safety", "STATIC_SAFETY_SOURCE", "PEAK_TENSION_SOURCE"]

#: Required static safety of round link chains (:data:`chaindrive.loads.REQUIRED_STATIC_SAFETY`);
#: roller chains: :func:`chaindrive.loads.required_static_safety_table`.
REQUIRED_STATIC_SAFETY = F.REQUIRED_STATIC_SAFETY
#: The definition of the static safety and of its required value, as the checks cite it.
STATIC_SAFETY_SOURCE = ("s = F_B / (K_s F_t + S_slack + q v²): Chernavsky et al., Kursovoe proektirovanie detalei "
                        "mashin (1988), eq. (7.40), K_d = the service factor K_s, F_f = the slack-span tension; "
                        "F_B the catalogue minimum breaking force (ISO 606:2015 / ASME B29.1 / DIN 22252)")
#: The limit of the peak tension of the running chain, as the check cites it.
PEAK_TENSION_SOURCE = ("Diamond Chain, 'What is working load ...' (engineering FAQ): chain pull at most 1/6 of "
                       "the ultimate tensile strength (press-fit or non-offset connecting links)")


def required_static_safety(chain: Chain, pitch_speed: float | None = None) -> float:
    """The required static safety for a chain: 3.5 for a round link chain; for a roller chain
    Chernavsky et al.'s Table 7.19 at ``pitch_speed``, the speed of the small sprocket [rad/s]
    (:func:`chaindrive.loads.required_static_safety_table`; ``None``: at 50 rpm, the table's
    lowest value for the pitch).

    >>> from chaindrive.chains import get
    >>> required_static_safety(get("18x64")), required_static_safety(get("16B-1"))
    (3.5, 7.3)
    """
    speed = rpm_to_angular_velocity(50.0) if pitch_speed is None else pitch_speed
    return F.required_static_safety_for(chain.is_link_chain, chain.pitch, speed)


#: A slack span steeper than this hangs in its own weight (no sag to speak of) [rad].
NEAR_VERTICAL = math.radians(80.0)


@dataclass(frozen=True)
class DriveLoads(Result):
    """Chain tensions and shaft loads (see :func:`drive_loads`). Forces in N.

    Attributes
    ----------
    torque : float
        Torque on the driving wheel (without service factor) [N·m].
    design_power : float
        Power times service factor [W].
    chain_speed : float
        [m/s].
    effective_pull : float
        ``K_s T / R`` [N].
    slack : float
        Slack-side tension [N]; how it was set in ``slack_source``.
    centrifugal : float
        ``q v²`` [N].
    tight : float
        ``effective_pull + slack + centrifugal`` [N].
    acceleration_peak : float
        Peak chain acceleration [m/s²]; its origin in ``acceleration_source``.
    moving_mass : float
        Mass accelerated by the polygonal action [kg]: the driven side reduced to the chain
        (:func:`polygonal_spring_mass`), or the whole chain where ``m a_max`` is used.
    dynamic : float
        Peak dynamic tension of the running chain [N] (:func:`chaindrive.analysis.dynamic_tension.dynamic_tension`);
        its model in ``dynamic_source``, how far it is checked in ``dynamic_validity``.
    maximum : float
        Peak tension of the running chain's tight span, ``tight + dynamic`` [N]: the value of
        the peak-tension check (:func:`peak_tension_check`), not of the static safety.
    dynamic_factor : float
        ``maximum / tight`` [-].
    span_tensions : ndarray
        Static tension of each span without centrifugal part [N]: the slack tension on
        the span leaving the driving wheel, rising at each driven wheel by its share of
        the effective pull.
    shaft_loads : ndarray
        Resultant on each wheel [N].
    shaft_load_angles : ndarray
        [rad].
    wheel_names : tuple of str
    power_shares : ndarray
        Share of the power taken off at each wheel [-] (:meth:`Drive.power_shares`).
    wheel_powers : ndarray
        Power at each wheel without service factor [W]: the driving wheel's positive,
        the driven wheels' negative (taken off), idlers 0.
    wheel_torques : ndarray
        Torque on each wheel's shaft without service factor [N·m], signed as the powers.
    dynamic_source : str
        How ``dynamic`` was computed.
    dynamic_stiffness : float or None
        Stiffness of the spans holding the driven side [N/m] (spring–mass model only).
    dynamic_validity : str
        How far the dynamic model is checked.
    tension_in, tension_out : ndarray or None
        Tension arriving at and leaving each wheel [N] where they differ from the span
        tensions (a conveyor: the running tensions of its chain pull).
    effective_pull_formula, effective_pull_basis : str
        How ``effective_pull`` was computed (``K_s T / R``; a conveyor ``K_s F_head``).
    """

    torque: float = quantity("N*m")
    design_power: float = quantity("W")
    chain_speed: float = quantity("m/s")
    effective_pull: float = quantity("N")
    slack: float = quantity("N")
    slack_source: str
    centrifugal: float = quantity("N")
    tight: float = quantity("N")
    acceleration_peak: float = quantity("m/s^2")
    acceleration_source: str
    moving_mass: float = quantity("kg")
    dynamic: float = quantity("N")
    maximum: float = quantity("N")
    dynamic_factor: float = quantity("1")
    span_tensions: np.ndarray = quantity("N")
    shaft_loads: np.ndarray = quantity("N")
    shaft_load_angles: np.ndarray = quantity("rad")
    wheel_names: tuple[str, ...]
    power_shares: np.ndarray | None = quantity("1", default=None)
    wheel_powers: np.ndarray | None = quantity("W", default=None)
    wheel_torques: np.ndarray | None = quantity("N*m", default=None)
    dynamic_source: str = "m a_max"
    dynamic_stiffness: float | None = quantity("N/m", default=None)
    dynamic_validity: str = ""
    tension_in: np.ndarray | None = quantity("N", default=None)
    tension_out: np.ndarray | None = quantity("N", default=None)
    effective_pull_formula: str = "K_s T / R"
    effective_pull_basis: str = "torque over the pitch radius of the driving wheel"


def free_entry_acceleration(drive: Drive) -> float:
    """Peak chain acceleration of free entry on the driving wheel, ``ω² R sin(δ/2)`` [m/s²].

    Dolipiński et al., eqs (1)–(13) (free entry; for a roller chain ``δ = 2π/z``, for a
    round link chain the larger central angle ``δ1`` of eq. (6)).

    >>> from chaindrive.chains import get
    >>> from chaindrive.drive import Drive, Wheel, Load
    >>> d = Drive(chain=get("18x64"), speed=5.0, load=Load(power=25e3),
    ...           wheels=[Wheel("a", "pocket_wheel", 8, (0, 0), driving=True),
    ...                   Wheel("b", "pocket_wheel", 8, (4.0, 0))])
    >>> round(free_entry_acceleration(d), 3)
    1.025
    """
    w = drive.driving_wheel
    R = w.pitch_radius(drive.chain)
    teeth = wheel_teeth(w, "the driving wheel")
    bar_diameter = drive.chain.bar_diameter
    if bar_diameter is not None:  # a round link chain
        from ..geometry.polygon import link_chain_central_angles

        half = float(link_chain_central_angles(drive.pitch, bar_diameter, teeth)[0]) / 2
    else:
        half = math.pi / teeth
    return float(F.free_entry_acceleration_peak(drive.speed, R, half))


def _slack_tension(drive: Drive, layout: DriveLayout) -> tuple[float, str]:
    if drive.slack_tension is not None:
        return float(drive.slack_tension), "given"
    q = drive.mass_per_length
    if drive.tensioner is not None and drive.tensioner.force is not None:
        idx = drive.wheel_index(drive.tensioner.wheel)
        a_in = layout.wrap.span_angle[(idx - 1) % len(drive.wheels)]
        a_out = layout.wrap.span_angle[idx]
        # the wheel is held by the two spans: |S (u_out - u_in)| = force
        spread = float(np.hypot(np.cos(a_out) - np.cos(a_in), np.sin(a_out) - np.sin(a_in)))
        if not spread > 1e-9:
            raise InputError("tensioner.force: the chain runs straight past the tensioner wheel, so its "
                             "force cannot set the slack tension; give drive.slack_tension", field="tensioner.force")
        return float(drive.tensioner.force / spread), f"tensioner force on wheel {drive.tensioner.wheel!r}"
    j = layout.slack_span
    span = float(layout.wrap.span_length[j])
    incl = span_inclination(layout.wrap.span_angle[j])
    if abs(incl) > NEAR_VERTICAL:
        return float(q * L.GRAVITY * span), "weight of the near-vertical slack span, q g l"
    return (_tension_for_sag(span, incl, drive.slack_sag_ratio * span, q),
            f"catenary sag {drive.slack_sag_ratio:.1%} of the slack span")


@memo(maxsize=64)
def _tension_for_sag(span: float, inclination: float, sag: float, mass_per_length: float) -> float:
    # chaindrive.layout.tension_for_sag (a bisection of 100 steps) kept for reuse by its inputs
    return float(L.tension_for_sag(span, inclination, sag, mass_per_length))


@finite_guard  # NaN/inf arguments (acceleration_peak, ...) refused (chaindrive._finite)
def drive_loads(drive: Drive, layout: DriveLayout | None = None, *,
                acceleration_peak: float | None = None, acceleration_source: str = "given",
                moving_mass: float | None = None, conveyor: ConveyorPull | None = None) -> DriveLoads:
    r"""Tight, slack, centrifugal and inertia tensions and the shaft loads of ``drive``.

    .. math::

        F_{tight} = \frac{K_s T}{R} + S_{slack} + q v^2, \qquad F_{peak} = F_{tight} + F_d

    The slack tension is, in this order: given; from the tensioner force (the tensioner
    wheel held by its two spans); the weight of a near-vertical (> 80°) slack span; the
    catenary tension for ``slack_sag_ratio`` of the slack span. The shaft load of each
    wheel is the vector sum of its two span tensions (without the centrifugal part,
    which the chain carries itself, and without the dynamic tension, as the handbook's
    shaft load ``F_t + 2 F_f``: Ivanov, *Detali mashin*, chain drives; here with ``K_s``). The
    dynamic tension ``F_d`` of the running chain comes from the one function
    :func:`chaindrive.analysis.dynamic_tension.dynamic_tension` (docs/design.md, "The dynamic
    load and the simulation"); it enters ``maximum`` (the peak-tension check), not the static
    safety.

    Parameters
    ----------
    drive : Drive
    layout : DriveLayout, optional
        Its layout (computed when not given).
    acceleration_peak : float, optional
        Peak chain acceleration [m/s²]; default the free-entry closed form
        (:func:`free_entry_acceleration`). The analysis passes the entry kinematics'
        value, guides included.
    acceleration_source : str
        Where a given ``acceleration_peak`` comes from (for the report).
    moving_mass : float, optional
        Mass moved rigidly by the polygonal action [kg]: then ``F_d = m a_max``.
    conveyor : ConveyorPull, optional
        A scraper conveyor's chain pull (:func:`chaindrive.analysis.conveyor.conveyor_pull`):
        then the slack tension is the tension leaving the head and the effective pull
        ``K_s`` times the head drive's force (the friction along the loop, not the
        installed power).

    Returns
    -------
    DriveLoads

    References
    ----------
    docs/drive.md; Dolipiński et al. (peak acceleration of the polygonal action);
    ISO 10823:2004 (sag of the slack span about 2 %).

    Examples
    --------
    >>> from chaindrive.drive.project import load_project
    >>> d = load_project("examples/mining_conveyor.toml")  # 18x64 on 8-pocket wheels, 25 kW at 5 rad/s
    >>> round(drive_loads(d).effective_pull / 1e3, 2)  # K_s T / R = 1.5 · 5000 N·m / 0.16428 m
    45.65
    """
    lay = drive_layout(drive) if layout is None else layout
    q = drive.mass_per_length
    k = drive.driving_index
    R = float(lay.pitch_radii[k])
    v = drive.chain_speed()
    Fc = float(F.centrifugal_tension(q, v))
    if conveyor is not None:
        return _conveyor_loads(drive, lay, conveyor, float(conveyor.head_force) * drive.load.service_factor,
                               float(conveyor.slack_tension), f"conveyor chain pull ({conveyor.source})", Fc, v,
                               acceleration_peak, acceleration_source, moving_mass)
    Fe = float(F.tight_side_tension(drive.torque(), R)) * drive.load.service_factor
    Fs, src = _slack_tension(drive, lay)
    shares = drive.power_shares()
    span_T = span_tensions(Fe, Fs, shares, drive.driving_index, drive.travel)
    tight = float(span_T.max()) + Fc  # the largest span tension (Fe + Fs) plus q v²
    if acceleration_peak is None:
        a, asrc = free_entry_acceleration(drive), "free entry on the driving wheel, ω² R sin(δ/2) (Dolipiński et al.)"
    else:
        a, asrc = float(acceleration_peak), acceleration_source
    dyn = dynamic_tension(drive, lay, a, moving_mass=moving_mass, tight=tight)
    m, Fd, dsrc, kd = dyn.moving_mass, dyn.value, dyn.model, dyn.stiffness
    ang = lay.wrap.span_angle
    # wheel i: pulled back along incoming span i-1, forward along outgoing span i
    # (np.column_stack of np.roll(.., 1) and the spans, filled in directly: the same values)
    tens = np.empty((len(span_T), 2))
    tens[0, 0], tens[1:, 0], tens[:, 1] = span_T[-1], span_T[:-1], span_T
    dirs = np.empty((len(ang), 2))
    dirs[0, 0], dirs[1:, 0], dirs[:, 1] = ang[-1] + np.pi, ang[:-1] + np.pi, ang
    mag, th = F.shaft_load(tens, dirs)
    powers = np.where(shares > 0, -shares * drive.power(), 0.0)
    powers[drive.driving_index] = drive.power()
    return DriveLoads(
        torque=drive.torque(), design_power=drive.design_power(), chain_speed=v, effective_pull=Fe, slack=Fs, slack_source=src,
        centrifugal=Fc, tight=tight, acceleration_peak=a, acceleration_source=asrc,
        moving_mass=m, dynamic=Fd, maximum=tight + Fd,
        dynamic_factor=float(F.dynamic_factor(tight, Fd)), span_tensions=span_T,
        shaft_loads=np.asarray(mag, dtype=float), shaft_load_angles=np.asarray(th, dtype=float),
        wheel_names=lay.wheel_names, power_shares=shares, wheel_powers=powers,
        wheel_torques=powers / lay.angular_velocities, dynamic_source=dsrc, dynamic_stiffness=kd,
        dynamic_validity=dyn.validity,
    )


def _conveyor_loads(drive: Drive, lay: DriveLayout, pull: ConveyorPull, Fe: float, Fs: float, src: str,
                    Fc: float, v: float, acceleration_peak: float | None, acceleration_source: str,
                    moving_mass: float | None) -> DriveLoads:
    """A scraper conveyor's loads from its chain pull (one running state): the tensions in
    and out of every wheel and the shaft loads are the chain pull's (no service factor),
    the tight-side tension ``S_0 + K_s F_head + q v²``; the head and a tail drive take
    their forces ``F v`` at the sprocket, no wheel takes power off."""
    tight = Fs + Fe + Fc
    if acceleration_peak is None:
        a, asrc = free_entry_acceleration(drive), "free entry on the driving wheel, ω² R sin(δ/2) (Dolipiński et al.)"
    else:
        a, asrc = float(acceleration_peak), acceleration_source
    dyn = dynamic_tension(drive, lay, a, moving_mass=moving_mass)
    m, Fd = dyn.moving_mass, dyn.value
    n = len(drive.wheels)
    t_in = np.asarray(pull.wheel_tension_in, float)
    t_out = np.asarray(pull.wheel_tension_out, float)
    # span i joins wheel i and i+1 in list order: its tension where it leaves its wheel in travel
    span_T = t_out.copy() if drive.travel == "ccw" else np.roll(t_out, -1)
    powers = np.zeros(n)
    powers[drive.driving_index] = float(pull.head_force) * v
    head = drive.driving_index
    tail = (head - 1) % n if drive.travel == "ccw" else (head + 1) % n
    if tail != head:
        powers[tail] += float(pull.tail_force) * v
    return DriveLoads(
        torque=drive.torque(), design_power=drive.design_power(), chain_speed=v, effective_pull=Fe, slack=Fs,
        slack_source=src, centrifugal=Fc, tight=tight, acceleration_peak=a, acceleration_source=asrc,
        moving_mass=m, dynamic=Fd, maximum=tight + Fd, dynamic_factor=float(F.dynamic_factor(tight, Fd)),
        span_tensions=span_T, shaft_loads=np.asarray(pull.shaft_loads, float),
        shaft_load_angles=np.asarray(pull.shaft_load_angles, float), wheel_names=lay.wheel_names,
        power_shares=None, wheel_powers=powers, wheel_torques=powers / lay.angular_velocities,
        dynamic_source=dyn.model, dynamic_stiffness=dyn.stiffness, dynamic_validity=dyn.validity,
        tension_in=t_in, tension_out=t_out, effective_pull_formula="K_s F_head",
        effective_pull_basis="head drive's force of the conveyor chain pull (its friction and material, not the "
                             "installed torque)")


@finite_guard  # NaN/inf and out-of-range arguments refused (chaindrive._finite)
def span_tensions(effective_pull: float, slack: float, shares: np.ndarray, driving: int,
                  travel: str = "ccw") -> np.ndarray:
    r"""Static tension of every span [N] with the power taken off at several wheels.

    .. math:: S_{j} = S_{slack} + F_e \sum_{i \in \text{path}(k \to j)} \sigma_i

    Following the chain from the slack span (leaving the driving wheel ``k``), each
    driven wheel ``i`` takes its share ``σ_i`` of the torque, so the tension rises across
    it by ``σ_i F_e`` (torque balance of the wheel, friction neglected); the span
    arriving at the driving wheel carries ``S_slack + F_e``.

    Parameters
    ----------
    effective_pull : float
        ``F_e = K_s T / R`` of the driving wheel [N].
    slack : float
        Slack-side tension [N].
    shares : ndarray
        Share of the power of each wheel in chain order (sum 1) [-].
    driving : int
        Index of the driving wheel.
    travel : {"ccw", "cw"}
        Direction of chain travel along the wheel list.

    Returns
    -------
    ndarray
        Tension of span ``i`` (from wheel ``i`` to ``i+1``) [N].

    References
    ----------
    Moment balance of each wheel (statics); two-wheel case: Shigley, 9th ed., sec. 17-5
    (tight side ``F_e + S``, slack side ``S``).

    Examples
    --------
    >>> span_tensions(1000.0, 100.0, np.array([0.0, 0.4, 0.6]), 0)
    array([ 100.,  500., 1100.])
    """
    n = len(shares)
    out = np.empty(n)
    step = 1 if travel == "ccw" else -1
    # ccw: span k leaves wheel k, then wheel k+1 ... ; cw: span k-1 leaves wheel k, then wheel k-1 ...
    span = driving if travel == "ccw" else (driving - 1) % n
    tension = slack
    for _ in range(n):
        out[span] = tension
        wheel = (span + 1) % n if travel == "ccw" else span  # the wheel the chain reaches next
        tension = tension + shares[wheel] * effective_pull
        span = (span + step) % n
    return out


def static_safety_check(drive: Drive, loads: DriveLoads) -> Check:
    """Static safety ``F_B / (K_s F_t + S_slack + q v²)`` against the required ``[s]``
    (:func:`chaindrive.loads.static_safety`, Chernavsky et al. eq. (7.40); the required value
    :attr:`Drive.static_safety_required`: the project's, or Table 7.19 by pitch and
    small-sprocket speed for roller chains, 3.5 for round link chains). The dynamic tension is
    not in it: :func:`peak_tension_check`."""
    fb = drive.chain.breaking_force
    need = drive.static_safety_required
    ks = float(drive.load.service_factor)
    sf = None
    if fb is not None:
        sf = float(F.static_safety(fb, loads.effective_pull / ks, loads.centrifugal, loads.slack, ks))
    if drive.required_static_safety is not None:
        basis = "required value set by the project"
    elif drive.chain.is_link_chain:
        basis = "required 3.5 for round link chains (the Dolipiński et al. example drive; no standard found)"
    else:
        n1 = drive.small_sprocket_speed()
        basis = (f"required [s] from Chernavsky et al. Table 7.19 at p = {drive.pitch * 1e3:.4g} mm, "
                 f"n1 = {angular_velocity_to_rpm(n1):.0f} rpm (small sprocket)")
        if F.outside_required_safety_table(drive.pitch, n1):
            basis += ", outside the printed table: extended linearly (chaindrive.loads.required_static_safety_table)"
    return Check(
        name="static safety", value=sf, limit=need, unit="-",
        passed=None if sf is None else bool(sf >= need),
        source=STATIC_SAFETY_SOURCE,
        note=("breaking force unknown" if fb is None else
              f"K_s F_t = {loads.effective_pull:.4g} N, S_slack = {loads.slack:.4g} N, q v² = {loads.centrifugal:.4g} N; "
              f"{basis}"))


def peak_tension_check(drive: Drive, loads: DriveLoads) -> Check:
    """Peak tension of the running chain's tight span ``F_tight + F_d`` against ``F_B / 6`` for
    roller chains (Diamond Chain's working-load rule, :data:`chaindrive.loads.PEAK_TENSION_RATIO`);
    information for round link chains (no published limit found)."""
    fb = drive.chain.breaking_force
    link = drive.chain.is_link_chain
    limit = None if (fb is None or link) else float(fb) / F.PEAK_TENSION_RATIO
    detail = (f"F_tight = {loads.tight:.4g} N + F_d = {loads.dynamic:.4g} N ({loads.dynamic_source}); "
              f"F_d {loads.dynamic_validity}")
    if link:
        return Check(name="peak tension", value=loads.maximum, limit=None, unit="N", passed=None,
                     source="tight-side tension + dynamic tension of the running chain",
                     note=detail + "; no published peak limit for round link chains was found", relation="info")
    return Check(name="peak tension", value=loads.maximum, limit=limit, unit="N",
                 passed=None if limit is None else bool(loads.maximum <= limit),
                 source=f"F_B / {F.PEAK_TENSION_RATIO:g}: {PEAK_TENSION_SOURCE}",
                 note=detail if fb is not None else "breaking force unknown; " + detail, relation="<=")


# --------------------------------------------------------------------------- declared parts
def _loads_part(ctx: PartContext) -> DriveLoads:
    entry = ctx["entry"]
    return drive_loads(ctx.drive, ctx["layout"], acceleration_peak=entry.acceleration_peak,
                       acceleration_source=f"chaindrive.kinematics.chain_entry ({entry.driving.case.entry} entry)",
                       conveyor=ctx["conveyor"])


def _slack_sag_part(ctx: PartContext) -> float | None:
    pull = ctx["conveyor"]
    if pull is not None:
        # a conveyor: the sag that matters is the free return strand's
        return float(pull.return_sag)
    try:
        return slack_span_sag(ctx.drive, ctx["layout"], ctx["loads"].slack)
    except ChainDriveError as exc:
        ctx.note(f"sag not computed: {exc}")
        return None


def _slack_sag_checks(ctx: PartContext, sag: float) -> list[Check]:
    lay = ctx["layout"]
    pull = ctx["conveyor"]
    if pull is not None:
        return [Check("sag of the free return strand", float(sag), None, "m", None,
                      "catenary of the return strand at the conveyor's running tension (chaindrive.conveyor)",
                      "largest sag of a free span of the return strand", relation="info")]
    span = float(lay.wrap.span_length[lay.slack_span])
    return [Check("sag of the slack span", float(sag), None, "m", None, "catenary, docs/drive.md",
                  f"{sag / span * 100:.2f} % of the span at the slack tension", relation="info")]


register_part(Part("loads", "Loads and safety", _loads_part, needs=("layout", "entry", "conveyor"),
                   checks=lambda ctx, loads: [static_safety_check(ctx.drive, loads), peak_tension_check(ctx.drive, loads)],
                   order=20,
                   section="chaindrive.workflows.sections:loads_section"))
register_part(Part("slack_sag", "Sag of the slack span", _slack_sag_part, needs=("layout", "loads", "conveyor"),
                   checks=_slack_sag_checks, order=21, unit="m",
                   section="chaindrive.workflows.sections:layout_section"))
