r"""Scraper conveyors in the simulation: pans under the strands, the steady state, the
peak-tension envelope.

A pan is a :class:`~chaindrive.simulation.model.SimGuide` along a span's tangent line
(the pin line; the bar surfaces slide on it), on the side of gravity, stopping
:func:`chaindrive.conveyor.pan_end_clearance` short of each wheel's tangent point (clear
of the tip circle), as the analysis assumes.
The contact is unilateral (penalty) with regularised Coulomb friction (the kernel's
law, ``F_t = −μ F_n sat(v_t/v_ε)``); the carrying strand's pan also gets the material
each pin in contact scrapes along it (its weight along the pan, its friction and its
inertia: :func:`chaindrive.simulation._kernel.integrate`).
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from .._results import Result, quantity
from .._validation import check_nonnegative
from ..conveyor import pan_end_clearance
from ..errors import InputError, ValidityRangeWarning
from .model import SimGuide, SimulationModel

if TYPE_CHECKING:
    from ..analysis.conveyor import ConveyorPull
    from ..drive.model import Drive
    from ..drivetrain.coupling import FluidCoupling
    from ..drivetrain.motor import Motor
    from .run import SimulationResult

#: Clearance of a pan below the tangent line of its span, in bar (roller) radii.
PAN_GAP = 0.1

__all__ = ["conveyor_pans", "SteadyState", "steady_state", "peak_tension_envelope", "span_kinds", "StartUp",
           "start_up_of", "with_drive_profile", "path_envelope", "compare"]


def span_kinds(model: SimulationModel, drive: Drive) -> list[str]:
    """Kind of each simulated span ``i`` (wheel ``i`` to ``i + 1``): ``"carrying"``,
    ``"pans"`` (return on the bottom pans) or ``"free"`` (the analysis' rule:
    :data:`chaindrive.analysis.conveyor.RETURN_SPAN_FRACTION`)."""
    from ..analysis.conveyor import RETURN_SPAN_FRACTION
    from .run import _tangent

    conv = drive.conveyor
    if conv is None:
        raise InputError("the drive has no [conveyor] table", field="conveyor")
    nw = len(model.wheels)
    radii = model.signed_radii()
    lengths = []
    for i in range(nw):
        j = (i + 1) % nw
        p1, p2, _, _ = _tangent(model.wheels[i].centre, radii[i], model.wheels[j].centre, radii[j])
        lengths.append(float(np.hypot(*(p2 - p1))))
    carry = lengths[nw - 1]   # wheel 0 is the head: the last span arrives at it
    kinds = []
    for i in range(nw):
        if i == nw - 1:
            kinds.append("carrying")
        elif conv.return_on_pans and lengths[i] >= RETURN_SPAN_FRACTION * carry:
            kinds.append("pans")
        else:
            kinds.append("free")
    return kinds


def conveyor_pans(model: SimulationModel, drive: Drive, gravity: tuple[float, float]) -> list[SimGuide]:
    """Pans under the carrying strand (with the material) and, when the return strand is
    supported, under the long return spans (module notes).

    Parameters
    ----------
    model : SimulationModel
        Wheel 0 the head, chain order counter-clockwise (as :func:`model_from_drive`).
    drive : chaindrive.drive.Drive
        With its :class:`~chaindrive.drive.Conveyor`.
    gravity : (float, float)
        Gravity vector in the model's frame [m/s²].

    Returns
    -------
    list of SimGuide
    """
    from .run import _tangent

    conv = drive.conveyor
    if conv is None:
        raise InputError("the drive has no [conveyor] table", field="conveyor")
    g = np.asarray(gravity, float)
    ghat = g / max(float(np.hypot(*g)), 1e-300)
    nw = len(model.wheels)
    radii = model.signed_radii()
    speed = drive.chain_speed()
    qm = conv.material_mass_per_length(speed)
    pans = []
    for i, kind in enumerate(span_kinds(model, drive)):
        if kind == "free":
            continue
        j = (i + 1) % nw
        p1, p2, u, _ = _tangent(model.wheels[i].centre, radii[i], model.wheels[j].centre, radii[j])
        length = float(np.hypot(*(p2 - p1)))
        m1 = float(pan_end_clearance(abs(radii[i]), model.tip(model.wheels[i].teeth), model.pitch))
        m2 = float(pan_end_clearance(abs(radii[j]), model.tip(model.wheels[j].teeth), model.pitch))
        if length - m1 - m2 < 2.0 * model.pitch:
            continue
        a = p1 + m1 * u
        b = p2 - m2 * u
        left = np.array([-u[1], u[0]])
        if left @ ghat > 0:          # the chain lies on the pan's left: against gravity
            a, b = b, a
            left = -left
        # the pan surface a little (PAN_GAP bar radii) below the tangent line: the
        # static assembly starts with the pins just clear of it, not on the contact's edge
        drop = (1.0 + PAN_GAP) * model.roller_radius
        a = a - drop * left
        b = b - drop * left
        if kind == "carrying":
            pans.append(SimGuide((float(a[0]), float(a[1])), (float(b[0]), float(b[1])),
                                 friction=conv.chain_friction, material_mass=qm * model.pitch,
                                 material_friction=conv.material_friction))
        else:
            pans.append(SimGuide((float(a[0]), float(a[1])), (float(b[0]), float(b[1])),
                                 friction=conv.return_pan_friction))
    return pans


@dataclass(frozen=True)
class SteadyState(Result):
    """Time means of a conveyor simulation over its steady window (:func:`steady_state`)."""

    slack_tension: float = quantity("N")
    tight_tension: float = quantity("N")
    return_sag: float = quantity("m", display="mm")
    slack_tension_std: float = quantity("N")
    tight_tension_std: float = quantity("N")
    return_sag_std: float = quantity("m", display="mm")
    start: float = quantity("s")
    tensioner_force: float | None = quantity("N", default=None)


def _link_nearest(pos: np.ndarray, point: np.ndarray) -> np.ndarray:
    """Index of the link (mid-point of pins i, i+1) nearest ``point`` in every record."""
    mid = 0.5 * (pos + np.roll(pos, -1, axis=1))
    return np.argmin(np.sum((mid - point) ** 2, axis=2), axis=1)


def steady_state(result: SimulationResult, model: SimulationModel, drive: Drive, *,
                 start: float | None = None, offset_links: float = 6.0) -> SteadyState:
    """Slack and tight tension at the head and the sag of the return strand, as time means.

    The slack (tight) tension is that of the link ``offset_links`` link lengths after
    (before) the head's tangent point along the span leaving (arriving at) it; the sag
    is the largest vertical distance of the pins below the chord of the longest free
    return span (0 when every return span lies on pans).

    Parameters
    ----------
    result : SimulationResult
    model : SimulationModel
    drive : chaindrive.drive.Drive
    start : float, optional
        Start of the window [s]; default the second half of the run.
    offset_links : float

    Returns
    -------
    SteadyState
    """
    from .run import _tangent

    t = result.time
    t0 = float(t[0] + 0.5 * (t[-1] - t[0])) if start is None else float(start)
    sel = t >= t0
    if not np.any(sel):
        raise InputError(f"steady_state: no record after start = {t0:g} s", field="start")
    pos = result.positions[sel]
    ten = result.tension[sel]
    c = result.wheel_centres
    radii = model.signed_radii()
    nw = len(model.wheels)
    p_out, _, u_out, _ = _tangent(c[0], radii[0], c[1], radii[1])
    _, p_in, u_in, _ = _tangent(c[nw - 1], radii[nw - 1], c[0], radii[0])
    step = offset_links * model.pitch
    rows = np.arange(pos.shape[0])
    slack = ten[rows, _link_nearest(pos, p_out + step * u_out)]
    tight = ten[rows, _link_nearest(pos, p_in - step * u_in)]
    kinds = span_kinds(model, drive)
    free = [i for i, k in enumerate(kinds) if k == "free"]
    sag = np.zeros(pos.shape[0])
    if free:
        lengths = []
        for i in free:
            a, b, _, _ = _tangent(c[i], radii[i], c[(i + 1) % nw], radii[(i + 1) % nw])
            lengths.append((float(np.hypot(*(b - a))), a, b))
        _, a, b = max(lengths, key=lambda x: x[0])
        lo, hi = min(a[0], b[0]), max(a[0], b[0])
        x = pos[:, :, 0]
        y = pos[:, :, 1]
        inside = (x > lo + 0.05 * (hi - lo)) & (x < hi - 0.05 * (hi - lo))
        chord = a[1] + (b[1] - a[1]) * (x - a[0]) / (b[0] - a[0]) if b[0] != a[0] else np.full_like(x, a[1])
        # the pins of this span: inside its x range and below the chord by less than the
        # span itself (the carrying strand lies above)
        below = np.where(inside & (y < chord + 1e-3) & (chord - y < 0.5 * (hi - lo)), chord - y, 0.0)
        sag = np.max(below, axis=1)
    force = None
    if model.tensioner is not None:
        force = _chain_on_tensioner(pos, ten, c, radii, model, step=1.5 * model.pitch)
    return SteadyState(float(np.mean(slack)), float(np.mean(tight)), float(np.mean(sag)),
                       float(np.std(slack)), float(np.std(tight)), float(np.std(sag)), t0, force)


def _chain_on_tensioner(pos: np.ndarray, ten: np.ndarray, c: np.ndarray, radii: np.ndarray,
                        model: SimulationModel, step: float) -> float:
    """Time mean of the chain's force on the tensioner wheel against its travel [N]:
    ``(T_in u_in − T_out u_out)·d`` with the tension and the direction of the simulated
    links ``step`` before and after the wheel's tangent points (the chain's own end
    tangents, not the chords)."""
    from .run import _tangent

    assert model.tensioner is not None
    j = model.tensioner.wheel
    nw = len(model.wheels)
    d = np.asarray(model.tensioner.direction, float)
    d = d / np.hypot(*d)
    _, p_in, u_in, _ = _tangent(c[(j - 1) % nw], radii[(j - 1) % nw], c[j], radii[j])
    p_out, _, u_out, _ = _tangent(c[j], radii[j], c[(j + 1) % nw], radii[(j + 1) % nw])
    rows = np.arange(pos.shape[0])
    total = np.zeros(pos.shape[0])
    for point, chord, sign in ((p_in - step * u_in, u_in, 1.0), (p_out + step * u_out, u_out, -1.0)):
        i = _link_nearest(pos, point)
        link = pos[rows, (i + 1) % pos.shape[1]] - pos[rows, i]
        link /= np.hypot(link[:, 0], link[:, 1])[:, None]
        link *= np.sign(link @ chord)[:, None]       # in the direction of travel
        total += sign * ten[rows, i] * (link @ d)
    return float(np.mean(total))


def peak_tension_envelope(result: SimulationResult) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Largest and smallest tension each link saw over the run, by position along the chain.

    Returns
    -------
    position : ndarray (N,)
        Link index times the mean link length [m] (along the chain from link 0).
    peak, low : ndarray (N,)
        [N].
    """
    n = result.tension.shape[1]
    return np.arange(n) * result.pitch, np.max(result.tension, axis=0), np.min(result.tension, axis=0)


def compare(pull: ConveyorPull, state: SteadyState) -> dict[str, tuple[float, float, float]]:
    """Analysis, simulation and their difference [%] of slack, tight tension, sag and the
    tensioner force (where both have a tensioner)."""
    out = {}
    rows = [("slack tension", pull.slack_tension, state.slack_tension),
            ("tight tension", pull.tight_tension, state.tight_tension),
            ("sag", pull.return_sag, state.return_sag)]
    if pull.tensioner_force is not None and state.tensioner_force is not None:
        rows.append(("tensioner force", pull.tensioner_force, state.tensioner_force))
    for name, a, s in rows:
        out[name] = (float(a), float(s), 100.0 * (s - a) / a if a else math.nan)
    return out


@dataclass(frozen=True)
class StartUp(Result):
    """A conveyor's start-up (or stop) in the simulation (:func:`chaindrive.simulation.startup.start_up`).

    Attributes
    ----------
    time : ndarray
        [s].
    chain_speed : ndarray
        Mean chain speed at the head, ``n t ω / 2π`` [m/s].
    drive_torque : ndarray
        Torque driving the head: the motor's (Kloss curve), through a fluid coupling the
        coupling's, at prescribed speed that of the chain on the head, reversed [N m].
    tight_tension, slack_tension : ndarray
        Arriving at and leaving the head [N].
    envelope_position : ndarray
        Position along the path from the head's exit [m].
    envelope_peak, envelope_low : ndarray
        Highest and lowest tension seen at that path position [N].
    steady_tension : ndarray
        Tension along the path at the end of the run [N].
    peak_tension, peak_position, peak_time : float
        The highest tension [N], where along the path [m] and when [s].
    motor_speed : ndarray
        The motor's speed reduced to the head [rad/s]: behind a fluid coupling its own,
        else the head's (empty at prescribed speed).
    """

    time: np.ndarray = quantity("s")
    chain_speed: np.ndarray = quantity("m/s")
    drive_torque: np.ndarray = quantity("N*m")
    tight_tension: np.ndarray = quantity("N")
    slack_tension: np.ndarray = quantity("N")
    envelope_position: np.ndarray = quantity("m")
    envelope_peak: np.ndarray = quantity("N")
    envelope_low: np.ndarray = quantity("N")
    steady_tension: np.ndarray = quantity("N")
    peak_tension: float = quantity("N")
    peak_position: float = quantity("m", display="m")
    peak_time: float = quantity("s")
    motor_speed: np.ndarray = quantity("rad/s", default_factory=lambda: np.zeros(0))


def path_envelope(result: SimulationResult, model: SimulationModel
                  ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, int, int]:
    """Tension by position along the path (space-fixed), from the head's exit.

    In every record the link nearest the head's exit tangent point is path position 0
    and link ``k + j`` sits at ``j`` mean link lengths along the path.

    Returns
    -------
    position, peak, low, last : ndarray (N,)
        [m], [N], [N], [N]; plus the record index and path index of the peak.
    """
    from .run import _tangent

    c = result.wheel_centres
    radii = model.signed_radii()
    p_out, _, u_out, _ = _tangent(c[0], radii[0], c[1], radii[1])
    k = _link_nearest(result.positions, p_out + 0.5 * model.pitch * u_out)
    n = result.tension.shape[1]
    idx = (k[:, None] + np.arange(n)[None, :]) % n
    along = np.take_along_axis(result.tension, idx, axis=1)
    peak_at = np.unravel_index(int(np.argmax(along)), along.shape)
    return (np.arange(n) * model.pitch, np.max(along, axis=0), np.min(along, axis=0), along[-1],
            int(peak_at[0]), int(peak_at[1]))


def with_drive_profile(model: SimulationModel, *, motor: Motor | None = None, motor_inertia: float = 0.0,
                       stop_time: float = 0.0, stop_ramp: float = 0.0, ripple: float = 0.0,
                       ripple_frequency: float = 0.0, coupling: FluidCoupling | None = None,
                       secondary_inertia: float = 0.0) -> SimulationModel:
    """``model`` with its driving wheel (wheel 0) given a time-varying drive (:func:`chaindrive.simulation.startup.start_up`)."""
    import dataclasses

    check_nonnegative("motor_inertia", motor_inertia, "kg m^2")
    check_nonnegative("secondary_inertia", secondary_inertia, "kg m^2")
    head = model.wheels[0]
    if secondary_inertia and coupling is None:
        raise InputError("secondary_inertia is the coupling's secondary side: it needs a coupling",
                         field="secondary_inertia")
    if coupling is not None and motor is None:
        raise InputError("a fluid coupling needs a motor in front of it", field="coupling")
    if motor is not None and coupling is not None:
        # the motor (rotor and coupling primary) is its own degree of freedom
        head = dataclasses.replace(head, mode="motor", motor=motor, coupling=coupling, motor_inertia=motor_inertia,
                                   inertia=head.inertia + secondary_inertia, stop_time=stop_time, ripple=ripple,
                                   ripple_frequency=ripple_frequency)
    elif motor is not None:
        head = dataclasses.replace(head, mode="motor", motor=motor, inertia=head.inertia + motor_inertia,
                                   stop_time=stop_time, ripple=ripple, ripple_frequency=ripple_frequency)
    else:
        head = dataclasses.replace(head, stop_time=stop_time, stop_ramp=stop_ramp, ripple=ripple,
                                   ripple_frequency=ripple_frequency)
    return dataclasses.replace(model, wheels=[head, *model.wheels[1:]], guides=list(model.guides))


def start_up_of(result: SimulationResult, model: SimulationModel) -> StartUp:
    """The start-up quantities of a run of ``model`` (:class:`StartUp`)."""
    from .run import _tangent

    head = model.wheels[0]
    seats = model.seats_per_turn(head.teeth)
    omega = result.wheel_speed[:, 0]
    chain_speed = omega * seats * model.pitch / (2 * math.pi)
    motor_speed = np.zeros(0)
    if head.coupling is not None:
        motor_speed = result.motor_speed[:, 0]
        torque = np.asarray(head.coupling.torque(motor_speed, omega), float)
    elif head.motor is not None:
        motor_speed = omega
        on = (head.stop_time <= 0) | (result.time < head.stop_time)
        with warnings.catch_warnings():
            # a loaded start may turn the head back a little at switch-on (slip just above 1)
            warnings.simplefilter("ignore", ValidityRangeWarning)
            torque = np.where(on, head.motor.torque(omega), 0.0)
        if head.ripple:
            torque = torque * (1.0 + head.ripple * np.sin(head.ripple_frequency * result.time))
    else:
        torque = -result.wheel_torque[:, 0]
    c = result.wheel_centres
    radii = model.signed_radii()
    nw = len(model.wheels)
    p_out, _, u_out, _ = _tangent(c[0], radii[0], c[1], radii[1])
    _, p_in, u_in, _ = _tangent(c[nw - 1], radii[nw - 1], c[0], radii[0])
    rows = np.arange(result.time.size)
    step = 6.0 * model.pitch
    slack = result.tension[rows, _link_nearest(result.positions, p_out + step * u_out)]
    tight = result.tension[rows, _link_nearest(result.positions, p_in - step * u_in)]
    pos, peak, low, last, i_t, i_s = path_envelope(result, model)
    return StartUp(result.time, chain_speed, torque, tight, slack, pos, peak, low, last,
                   float(peak[i_s]), float(pos[i_s]), float(result.time[i_t]), motor_speed)


def __getattr__(name: str) -> Any:
    """``start_up`` moved to :mod:`chaindrive.simulation.startup` (it builds the model from a
    drive): a deprecated alias here, removed in the next release."""
    if name == "start_up":
        import importlib

        from .._deprecation import warn_renamed

        warn_renamed(f"{__name__}.start_up", "chaindrive.simulation.start_up")
        return importlib.import_module("chaindrive.simulation").start_up
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
