r"""Chain pull along a scraper conveyor: the tension round the whole loop.

The loop is walked in the direction of travel from the head's exit (the driving
wheel): each span is either on the pans (:func:`chaindrive.conveyor.strand_resistance`,
the carrying strand with the material, the return strand on the bottom pans) or hanging
free (:func:`chaindrive.conveyor.free_strand`, a catenary); the head drive takes
``head_share`` of the total pull where the chain wraps it, a tail drive the rest. The
running tension is ``T(s) = S_0 + τ(s)`` with ``S_0`` the tension leaving the head,
set (in this order) by

1. a spring tensioner: its force ``F_0 − k s`` holds the tensioner wheel against the
   chain, whose length is fixed: ``g s = ∮ T ds / EA − Σ X_free`` (the stretch of the
   running chain is taken up by the slide travel ``s`` and the extra length ``X`` of the
   free strands' catenaries; ``g = (u_in − u_out)·d`` is the path lengthening per unit
   travel, ``F_0`` the tensioner force when the chain just fits unstretched);
2. a weight or hydraulic tensioner: a constant force, ``T_w g = F``;
3. the drive's ``slack_tension``;
4. else the stated minimum: the lowest tension at a sprocket exit is ``minimum_tension``.

The *pretension* reported is the standstill tension of a rigidly tensioned loop that
gives ``minimum_tension`` at every sprocket exit when running
(:func:`chaindrive.conveyor.pretension_for_minimum`).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np

from .. import conveyor as C
from .._results import Result, quantity
from .._roots import brentq
from ..drive.model import Drive
from ..errors import InfeasibleError, InputError
from ..layout import GRAVITY, tensioner_travel
from .checks import Check
from .layout import DriveLayout, drive_layout
from .parts import Part, PartContext, register_part

__all__ = ["TensionProfile", "ConveyorPull", "conveyor_pull", "conveyor_checks", "gravity_direction",
           "RETURN_SPAN_FRACTION"]

#: A drive with a span longer than this [m] and no [conveyor] table gets a note (it may be
#: a conveyor described without its pans).
LONG_SPAN = 10.0

#: A return span lies on the bottom pans when longer than this fraction of the
#: carrying strand (shorter spans, round a tensioner, hang free).
RETURN_SPAN_FRACTION = 0.25


@dataclass(frozen=True)
class TensionProfile(Result):
    """Tension along the loop from the head's exit, in the direction of travel."""

    position: np.ndarray = quantity("m")
    tension: np.ndarray = quantity("N")


@dataclass(frozen=True)
class ConveyorPull(Result):
    """The chain pull of a scraper conveyor (:func:`conveyor_pull`).

    Attributes
    ----------
    tension_profile : TensionProfile
        Running tension along the loop [m, N].
    wheel_positions : ndarray
        Where each wheel's wrap begins along the profile [m] (chain order from the head).
    wheel_names : tuple of str
    slack_tension, tight_tension : float
        Leaving and arriving at the head [N].
    minimum_tension : float
        Lowest running tension [N] and ``minimum_position`` where [m].
    required_minimum : float
        Stated minimum at every sprocket exit [N].
    pretension : float
        Standstill tension of a rigidly tensioned loop that gives ``required_minimum``
        at every sprocket exit when running [N].
    mean_tension : float
        Mean running tension of the loop as computed [N].
    carrying_resistance, return_resistance : float
        Tension gained along the carrying and the return strand [N].
    drive_force, head_force, tail_force : float
        Total pull and the shares of head and tail drive [N].
    drive_power, head_power, tail_power : float
        At the motors (drive efficiency included) [W].
    material_load : float
        [kg/m].
    return_sag : float
        Largest sag of a free span of the return strand [m] (0 when all on pans).
    tensioner_force, tensioner_travel : float or None
        Spring tensioner: force on its wheel [N] and slide travel from the position
        where the unstretched chain just fits [m].
    tensioner_offset : float
        Where the unstretched chain of the layout's (even) number of links just fits:
        the tensioner wheel's distance from its drawn position along its travel [m]; the
        running state (spans, wraps, forces) is computed with the wheel there.
    chain_speed : float
        [m/s].
    source : str
        What sets the tension leaving the head.
    wheel_tension_in, wheel_tension_out : ndarray
        Running tension arriving at and leaving each wheel [N] (the drive's wheel order).
    shaft_loads, shaft_load_angles : ndarray
        Force of the chain on each wheel's shaft [N] and its direction [rad]: the two
        spans' tensions of this running state, each along its end tangent (a free
        strand's catenary tangent, a strand on pans its chord).
    """

    tension_profile: TensionProfile
    wheel_positions: np.ndarray = quantity("m")
    wheel_names: tuple[str, ...] = ()
    slack_tension: float = quantity("N", default=0.0)
    tight_tension: float = quantity("N", default=0.0)
    minimum_tension: float = quantity("N", default=0.0)
    minimum_position: float = quantity("m", display="m", default=0.0)
    required_minimum: float = quantity("N", default=0.0)
    pretension: float = quantity("N", default=0.0)
    mean_tension: float = quantity("N", default=0.0)
    carrying_resistance: float = quantity("N", default=0.0)
    return_resistance: float = quantity("N", default=0.0)
    drive_force: float = quantity("N", default=0.0)
    head_force: float = quantity("N", default=0.0)
    tail_force: float = quantity("N", default=0.0)
    drive_power: float = quantity("W", default=0.0)
    head_power: float = quantity("W", default=0.0)
    tail_power: float = quantity("W", default=0.0)
    material_load: float = quantity("kg/m", default=0.0)
    return_sag: float = quantity("m", display="mm", default=0.0)
    tensioner_force: float | None = quantity("N", default=None)
    tensioner_travel: float | None = quantity("m", display="mm", default=None)
    tensioner_offset: float = quantity("m", display="mm", default=0.0)
    chain_speed: float = quantity("m/s", default=0.0)
    source: str = ""
    wheel_tension_in: np.ndarray | None = quantity("N", default=None)
    wheel_tension_out: np.ndarray | None = quantity("N", default=None)
    shaft_loads: np.ndarray | None = quantity("N", default=None)
    shaft_load_angles: np.ndarray | None = quantity("rad", default=None)


def gravity_direction(drive: Drive) -> np.ndarray:
    """Unit vector of gravity in the drive's frame with the conveyor's inclination.

    The frame's ``y`` is up for a level conveyor; an inclination ``α > 0`` (head higher)
    tilts gravity towards the tail: ``ĝ = −(cos α e_up + sin α u_c)`` with ``u_c`` the
    unit vector from the tail to the head and ``e_up`` the normal to ``u_c`` pointing
    to positive ``y``.
    """
    conv = drive.conveyor
    alpha = 0.0 if conv is None else conv.inclination
    head, tail = _head_tail(drive)
    u = np.asarray(drive.wheels[head].position, float) - np.asarray(drive.wheels[tail].position, float)
    norm = float(np.hypot(*u))
    if not norm > 0:
        raise InputError("conveyor: the head and the tail wheel are at the same place", field="wheels")
    u = u / norm
    up = np.array([-u[1], u[0]])
    if up[1] < 0 or (up[1] == 0 and up[0] < 0):
        up = -up
    return -(math.cos(alpha) * up + math.sin(alpha) * u)


def _head_tail(drive: Drive) -> tuple[int, int]:
    """Index of the head (driving wheel) and the tail (where the carrying strand starts)."""
    n = len(drive.wheels)
    head = next(i for i, w in enumerate(drive.wheels) if w.driving)
    tail = (head - 1) % n if drive.travel == "ccw" else (head + 1) % n
    return head, tail


def _walk(drive: Drive, layout: DriveLayout) -> list[tuple[str, int]]:
    """The loop in the direction of travel from the head's exit: ("span", j) and ("wheel", i),
    ending with the head's wrap."""
    n = len(drive.wheels)
    head, _ = _head_tail(drive)
    out: list[tuple[str, int]] = []
    for step in range(n):
        if drive.travel == "ccw":
            w = (head + step) % n
            out += [("wheel", w), ("span", w)]
        else:
            w = (head - step) % n
            out += [("wheel", w), ("span", (w - 1) % n)]
    return out[1:] + out[:1]   # from the head's exit round to the head's wrap


def _axial_stiffness(drive: Drive) -> float:
    """``EA`` [N] of the chain, the simulation's value (round link chains: 0.854e11 d²)."""
    from ..chains.stiffness import AXIAL_STIFFNESS_16B, link_chain_axial_stiffness

    if drive.chain.bar_diameter is not None:
        return float(link_chain_axial_stiffness(float(drive.chain.bar_diameter)))
    return AXIAL_STIFFNESS_16B * (float(drive.chain.pitch) / 0.0254) ** 2


def conveyor_pull(drive: Drive, layout: DriveLayout | None = None, *, fit_tensioner: bool = True
                  ) -> ConveyorPull | None:
    """Tension along the loop of a scraper conveyor (module notes); ``None`` without ``[conveyor]``.

    Parameters
    ----------
    drive : chaindrive.drive.Drive
        With a :class:`~chaindrive.drive.Conveyor`.
    layout : DriveLayout, optional
    fit_tensioner : bool
        Move a force tensioner's wheel first to where the unstretched chain of the
        layout's links just fits (``tensioner_offset``); False: the wheel as drawn.

    Returns
    -------
    ConveyorPull or None

    Raises
    ------
    InputError
        The chain has no mass per length; the head and tail coincide; no tension
        leaving the head keeps every free strand off the ground.

    Examples
    --------
    >>> from chaindrive.simulation.from_drive import conveyor_drive
    >>> import dataclasses
    >>> from chaindrive.drive import Conveyor
    >>> d = dataclasses.replace(conveyor_drive(), conveyor=Conveyor(return_strand="free"))
    >>> r = conveyor_pull(d)
    >>> round(r.carrying_resistance)     # 0.4 x 13.6 kg/m x g x 99.67 m of pans
    5317
    """
    conv = drive.conveyor
    if conv is None:
        return None
    if layout is None:
        layout = drive_layout(drive)
    fitted = _fitted_tensioner(drive, layout) if fit_tensioner else None
    if fitted is not None:
        moved, offset = fitted
        pull = conveyor_pull(moved, drive_layout(moved), fit_tensioner=False)
        assert pull is not None
        return dataclasses.replace(pull, tensioner_offset=offset)
    q = drive.chain.mass_per_length
    if q is None:
        raise InputError(f"conveyor: chain {drive.chain.name!r} has no mass_per_length (give it in [chain])",
                         field="chain.mass_per_length")
    q = float(q)
    wrap = layout.wrap
    n = len(drive.wheels)
    head, tail = _head_tail(drive)
    sign = 1.0 if drive.travel == "ccw" else -1.0
    speed = float(layout.chain_speed)
    qm = conv.material_mass_per_length(speed)
    ghat = gravity_direction(drive)
    walk = _walk(drive, layout)
    carrying = layout.tight_span
    carry_len = float(wrap.span_length[carrying])

    # fixed part of every span: kind, length, world inclination in the direction of travel
    spans: dict[int, tuple[str, float, float, float]] = {}
    chords: dict[int, np.ndarray] = {}
    for kind, j in walk:
        if kind != "span":
            continue
        length = float(wrap.span_length[j])
        ang = float(wrap.span_angle[j]) + (0.0 if sign > 0 else math.pi)
        u = np.array([math.cos(ang), math.sin(ang)])
        chords[j] = u
        beta = math.asin(max(-1.0, min(1.0, -float(u @ ghat))))
        # the pan stops short of each wheel (pan_end_clearance): the ends hang free
        ends = _pan_ends(drive, layout, j)
        pan = max(length - ends, 1e-9)
        free_ends = q * GRAVITY * (length - pan) * math.sin(beta)
        if j == carrying:
            spans[j] = ("carrying", length, beta, float(C.strand_resistance(
                pan, q, conv.chain_friction, beta, qm, conv.material_friction)) + free_ends)
        elif conv.return_on_pans and length >= RETURN_SPAN_FRACTION * carry_len:
            spans[j] = ("pans", length, beta,
                        float(C.strand_resistance(pan, q, conv.return_pan_friction, beta)) + free_ends)
        else:
            spans[j] = ("free", length, beta, q * GRAVITY * length * math.sin(beta))
    total = sum(v[3] for v in spans.values())
    head_force = conv.head_share * total
    tail_force = total - head_force

    def profile(s0: float) -> _Run:
        """Positions, tensions, wheel starts, extra length of the free strands, largest free
        return sag, and each span's end directions and tensions."""
        pos, ten, starts = [0.0], [s0], []
        t = s0
        s = 0.0
        excess = 0.0
        sag = 0.0
        ends: dict[int, tuple[np.ndarray, np.ndarray, float, float]] = {}
        for kind, j in walk:
            if kind == "wheel":
                starts.append(s)
                s += float(wrap.wrap_length[j])
                if j == head:
                    t -= head_force
                elif j == tail:
                    t -= tail_force
                pos.append(s)
                ten.append(t)
                continue
            what, length, beta, dt = spans[j]
            u_start = u_end = chords[j]
            if what == "free":
                if not t > 0:
                    raise InputError("conveyor: the chain goes slack (tension <= 0) on a free span",
                                     field="conveyor")
                strand = C.free_strand(length, beta, t, q)
                excess += strand.excess_length
                if j != carrying:
                    sag = max(sag, strand.sag)
                u_start = _tangent(chords[j], ghat, strand.start_angle)
                u_end = _tangent(chords[j], ghat, strand.end_angle)
            ends[j] = (u_start, u_end, t, t + dt)
            t += dt
            s += length
            pos.append(s)
            ten.append(t)
        return _Run(np.array(pos), np.array(ten), starts, excess, sag, ends)

    # the head's exit tension
    exits = _exit_offsets(walk, spans, head, tail, head_force, tail_force)
    lowest_offset = min(exits)
    required_s0 = conv.minimum_tension - lowest_offset
    t_force: float | None = None
    t_travel: float | None = None
    tens = drive.tensioner
    lower = _lowest_feasible(walk, spans, q)
    if tens is not None and tens.force is not None and tens.kind in ("spring", "weight", "hydraulic"):
        iw = drive.wheel_index(tens.wheel)
        # unit vectors of the spans' chords arriving at and leaving the wheel, in the
        # direction of travel: the path lengthens by (u_in − u_out)·d per unit travel
        u_in = _span_unit(wrap, (iw - 1) % n)
        u_out = _span_unit(wrap, iw)
        if drive.travel == "cw":
            u_in, u_out = -u_out, -u_in
        d = np.asarray(tens.direction, float)
        d = d / np.hypot(*d)
        gproj = float((u_in - u_out) @ d)
        if not gproj > 1e-9:
            raise InputError("tensioner: moving its wheel along direction does not take up slack "
                             "(the chain runs straight past it)", field="tensioner.direction")
        ea = _axial_stiffness(drive)
        k = float(tens.stiffness) if tens.kind == "spring" else 0.0
        force0 = float(tens.force)
        around = _around(walk)[iw]

        def residual(s0: float) -> float:
            run = profile(s0)
            travel = (run.stretch(ea) - run.excess) / gproj
            return force0 - k * travel - _chain_on_slide(run, around, d)

        lo = lower
        tau_in, tau_out = _offsets_round_wheel(walk, spans, iw, head, tail, head_force, tail_force)
        hi = max(2.0 * lo + 1.0, force0 / gproj * 4.0 + abs(tau_in) + abs(tau_out) + 1.0)
        for _ in range(60):
            if residual(hi) < 0:
                break
            hi *= 2.0
        if residual(lo) <= 0:
            raise InputError("conveyor: the tensioner cannot hold the chain off the ground "
                             "(raise tensioner.force)", field="tensioner.force")
        s0 = brentq(residual, lo, hi, xtol=1e-6, rtol=1e-12)
        run = profile(s0)
        t_travel = (run.stretch(ea) - run.excess) / gproj
        t_force = _chain_on_slide(run, around, d)
        source = (f"{tens.kind} tensioner on wheel {tens.wheel!r} with the chain's length fixed"
                  if k > 0 else f"{tens.kind} tensioner force on wheel {tens.wheel!r}")
    elif drive.slack_tension is not None:
        s0 = float(drive.slack_tension)
        source = "given slack tension"
    else:
        s0 = max(required_s0, lower)
        source = "stated minimum tension at every sprocket exit"
    run = profile(s0)
    pos, ten, starts, sag = run.position, run.tension, run.starts, run.sag
    i_min = int(np.argmin(ten))
    req = profile(max(required_s0, lower))
    pre = C.mean_tension(req.position, req.tension)
    t_in, t_out, shaft = _wheel_forces(run, _around(walk), n)
    carrying_res = spans[carrying][3]
    return ConveyorPull(
        tension_profile=TensionProfile(pos, ten),
        wheel_positions=np.array(starts), wheel_names=tuple(drive.wheels[j].name for k_, j in walk if k_ == "wheel"),
        slack_tension=float(s0), tight_tension=float(s0 + head_force),
        minimum_tension=float(ten[i_min]), minimum_position=float(pos[i_min]),
        required_minimum=float(conv.minimum_tension), pretension=float(pre),
        mean_tension=C.mean_tension(pos, ten),
        carrying_resistance=float(carrying_res), return_resistance=float(total - carrying_res),
        drive_force=float(total), head_force=float(head_force), tail_force=float(tail_force),
        drive_power=_power(total, speed, conv.efficiency), head_power=_power(head_force, speed, conv.efficiency),
        tail_power=_power(tail_force, speed, conv.efficiency), material_load=float(qm),
        return_sag=float(sag), tensioner_force=t_force, tensioner_travel=t_travel,
        chain_speed=speed, source=source, wheel_tension_in=t_in, wheel_tension_out=t_out,
        shaft_loads=np.hypot(shaft[:, 0], shaft[:, 1]), shaft_load_angles=np.arctan2(shaft[:, 1], shaft[:, 0]))


def _fitted_tensioner(drive: Drive, layout: DriveLayout) -> tuple[Drive, float] | None:
    """The drive with its tensioner wheel where the unstretched chain of ``layout.links``
    just fits the path (the links rounded up to an even number leave chain to take up),
    and that offset along the travel [m]; ``None`` where no wheel moves (no force
    tensioner, or the chain fits as drawn)."""
    tens = drive.tensioner
    if tens is None or tens.force is None or tens.kind not in ("spring", "weight", "hydraulic"):
        return None
    # the chain over the path: the exact polygon length where the layout has it (the length
    # that set the link count; the simulation's assembly fits the same), else the circles'
    loop = layout.loop
    needed = float(loop.links_max) if loop is not None and loop.exact else float(layout.links_required)
    extra = (float(layout.links) - needed) * drive.pitch
    if not extra > 1e-6 * drive.pitch:
        return None
    iw = drive.wheel_index(tens.wheel)
    positions = np.array([w.position for w in drive.wheels], dtype=float)
    try:
        offset = float(tensioner_travel(positions, layout.pitch_radii, [w.side for w in drive.wheels], iw,
                                        tens.direction, [0.0], chain_length=layout.links * drive.pitch,
                                        extra_length=extra)[0])
    except InfeasibleError as exc:
        raise InputError(f"conveyor: the tensioner cannot take up the chain of {layout.links} links "
                         f"({extra * 1e3:.1f} mm longer than the path): {exc}", field="tensioner.direction") from exc
    d = np.asarray(tens.direction, float) / float(np.hypot(*tens.direction))
    at = positions[iw] + offset * d
    moved = dataclasses.replace(drive.with_wheel(tens.wheel, position=(float(at[0]), float(at[1]))),
                                links=int(layout.links))
    return moved, offset


def _pan_ends(drive: Drive, layout: DriveLayout, span: int) -> float:
    """Length [m] of span ``span`` (wheel ``span`` to ``span + 1``) without pan at its two ends."""
    n = len(drive.wheels)
    chain = drive.chain
    if chain.bar_diameter is not None:
        tip = 0.5 * float(chain.bar_diameter)
    else:
        tip = 0.5 * float(chain.roller_diameter or 0.0)
    return sum(float(C.pan_end_clearance(float(layout.pitch_radii[w]), tip, drive.pitch))
               for w in (span, (span + 1) % n))


def _power(force: float, speed: float, efficiency: float) -> float:
    """Motor power [W]; a braking drive (negative force) returns power through its efficiency."""
    if force >= 0:
        return float(C.drive_power(force, speed, efficiency))
    return -float(C.drive_power(-force, speed, 1.0)) * efficiency


def _span_unit(wrap, j: int) -> np.ndarray:
    a = float(wrap.span_angle[j])
    return np.array([math.cos(a), math.sin(a)])


def _offsets(walk, spans, head, tail, head_force, tail_force):
    """``τ`` after each element of the walk (tension minus the head's exit tension)."""
    t = 0.0
    out = []
    for kind, j in walk:
        if kind == "wheel":
            if j == head:
                t -= head_force
            elif j == tail:
                t -= tail_force
        else:
            t += spans[j][3]
        out.append((kind, j, t))
    return out


def _exit_offsets(walk, spans, head, tail, head_force, tail_force) -> list[float]:
    """``τ`` where the chain leaves each wheel (the head first).

    Every sprocket exit, not only the driving ones: behind an idle tail at the foot of a
    steep return (which pulls itself down, ``τ`` falling along it) the tail's exit is
    the lowest, as in the chain makers' sheets (e-uparts 20-3: ``T1 < 0 → T2 = 0``)."""
    out = [0.0]
    for kind, _j, t in _offsets(walk, spans, head, tail, head_force, tail_force):
        if kind == "wheel":
            out.append(t)
    return out


def _offsets_round_wheel(walk, spans, wheel, head, tail, head_force, tail_force) -> tuple[float, float]:
    """``τ`` of the chain arriving at and leaving ``wheel``."""
    before = 0.0
    for kind, j, t in _offsets(walk, spans, head, tail, head_force, tail_force):
        if kind == "wheel" and j == wheel:
            return before, t
        before = t
    raise InputError(f"conveyor: wheel {wheel} is not on the loop")


@dataclass(frozen=True)
class _Run:
    """One running state of the loop for a head exit tension: the profile, the extra
    length and largest sag of the free strands, and per span (index in the drive's
    list) its direction of travel at its start and end and its tensions there."""

    position: np.ndarray
    tension: np.ndarray
    starts: list[float]
    excess: float
    sag: float
    ends: dict[int, tuple[np.ndarray, np.ndarray, float, float]]

    def stretch(self, axial_stiffness: float) -> float:
        """Elastic elongation of the loop ``∮ T ds / EA`` [m]."""
        p, t = self.position, self.tension
        return float(np.sum(0.5 * (t[1:] + t[:-1]) * np.diff(p))) / axial_stiffness


def _tangent(chord: np.ndarray, ghat: np.ndarray, angle: float) -> np.ndarray:
    """Unit vector at ``angle`` [rad] above the horizontal in the vertical plane of ``chord``
    (travel direction), ``up = −ĝ``: a catenary's end tangent in the drive's frame."""
    up = -ghat
    h = chord - float(chord @ up) * up
    h = h / float(np.hypot(*h))
    return math.cos(angle) * h + math.sin(angle) * up


def _around(walk) -> dict[int, tuple[int, int]]:
    """For each wheel: the span arriving at it and the span leaving it (in travel)."""
    m = len(walk)
    return {j: (walk[(p - 1) % m][1], walk[(p + 1) % m][1])
            for p, (kind, j) in enumerate(walk) if kind == "wheel"}


def _wheel_force(run: _Run, around: tuple[int, int]) -> np.ndarray:
    """Force [N] of the chain on a wheel: ``−T_in u_in + T_out u_out`` with the arriving span's
    tension and direction at its end and the leaving span's at its start (a free span's
    catenary tangents; a span on pans along its chord)."""
    _, u_in, _, t_in = run.ends[around[0]]
    u_out, _, t_out, _ = run.ends[around[1]]
    return -t_in * u_in + t_out * u_out


def _wheel_forces(run: _Run, around: dict[int, tuple[int, int]], n: int
                  ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Tension arriving at and leaving each wheel [N] and the force on each shaft (n, 2) [N]."""
    t_in, t_out, force = np.zeros(n), np.zeros(n), np.zeros((n, 2))
    for i, (a, b) in around.items():
        t_in[i], t_out[i] = run.ends[a][3], run.ends[b][2]
        force[i] = _wheel_force(run, (a, b))
    return t_in, t_out, force


def _chain_on_slide(run: _Run, around: tuple[int, int], d: np.ndarray) -> float:
    """Force [N] the chain puts on a tensioner wheel against its travel ``d``:
    ``(T_in u_in − T_out u_out)·d`` (the spans pull the wheel along ``−u_in`` and ``u_out``,
    each along its end tangent: Irvine, *Cable Structures*, ch. 1, the tension of a
    cable acts along its tangent)."""
    return float(-_wheel_force(run, around) @ d)


def _lowest_feasible(walk, spans, q) -> float:
    """Smallest head exit tension [N] for which every free span hangs as a catenary
    (:func:`chaindrive.conveyor.free_strand_minimum_tension`, 1 % above it), at least 1 N."""
    lo = 1.0
    t = 0.0
    for kind, j in walk:
        if kind == "span":
            what, length, beta, dt = spans[j]
            if what == "free":
                lo = max(lo, 1.01 * C.free_strand_minimum_tension(length, beta, q) - t)
            t += dt
        # (a tail drive's drop is not followed here: the free spans of a conveyor lie on
        # the return, after the head and before the tail)
    return lo


def _conveyor_part(ctx: PartContext) -> ConveyorPull | None:
    drive = ctx.drive
    if drive.conveyor is None:
        spans = ctx["layout"].wrap.span_length
        if float(np.max(spans)) > LONG_SPAN:
            ctx.note(f"a span of {float(np.max(spans)):.3g} m: if this drive is a conveyor, describe its pans "
                     "and material in a [conveyor] table (docs/conveyor.md); without it the slack tension "
                     "comes from the tensioner force or the sag rule alone (no chain length, friction or "
                     "material) and a simulation runs without pans")
        return None
    return conveyor_pull(drive, ctx["layout"])


def conveyor_checks(drive: Drive, result: ConveyorPull) -> list[Check]:
    """Lowest running tension against the stated minimum; drive power against the installed power."""
    src = "Tsubakimoto, Large size conveyor chain selection, Table 3 (chain pull); chaindrive.conveyor"
    checks = [Check("lowest running chain tension", result.minimum_tension, result.required_minimum, "N",
                    bool(result.minimum_tension >= result.required_minimum * (1 - 1e-9)), src,
                    note=f"at {result.minimum_position:.1f} m from the head's exit; tension leaving the head "
                         f"set by the {result.source}")]
    if drive.load.power is not None:
        checks.append(Check("conveyor drive power within the installed power", result.drive_power,
                            float(drive.load.power), "W", bool(result.drive_power <= drive.load.power), src,
                            note="installed power: [load] power", relation="<="))
    return checks


register_part(Part("conveyor", "Chain pull along the conveyor", _conveyor_part, needs=("layout",),
                   checks=lambda ctx, result: conveyor_checks(ctx.drive, result), order=35,
                   section="chaindrive.workflows.sections:conveyor_section"))
