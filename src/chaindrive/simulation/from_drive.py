"""Build a :class:`SimulationModel` from a project :class:`chaindrive.drive.Drive`."""

from __future__ import annotations

import dataclasses
import itertools
import math
import warnings
from typing import TYPE_CHECKING, Any

from .._validation import check_positive, check_range
from ..errors import ChainDriveError, ChainDriveWarning, InputError

if TYPE_CHECKING:
    from ..drive.model import Drive
from .model import (
    AXIAL_STIFFNESS_16B,
    SimGuide,
    SimTensioner,
    SimulationModel,
    SimWheel,
    _required,
    link_chain_axial_stiffness,
)

__all__ = ["model_from_drive", "guide_channel", "channel_guides", "conveyor_drive",
           "conveyor_example"]


def _teeth(wheel: Any) -> int:
    if wheel.teeth is None:
        raise InputError(f"simulation: wheel {wheel.name!r} carries the load but has no teeth")
    return int(wheel.teeth)


def _disc_inertia(radius: float) -> float:
    """``J = ½ ρ π r⁴ b`` of a 20 mm steel disc at the pitch radius [kg m²]
    (:func:`chaindrive.loads.disc_inertia`, the one definition)."""
    from ..loads import disc_inertia

    return float(disc_inertia(radius))


def model_from_drive(drive: Drive, *, ramp_time: float = 0.2, axial_stiffness: float | None = None,
                     **kwargs: Any) -> SimulationModel:
    """Simulation model of a project drive (roller or round link chain, toothed wheels).

    Roller chains run on sprockets; a round link chain (DIN 22252, ``bar_diameter`` in
    the catalogue) on pocket wheels (every toothed wheel of the drive is then a pocket
    wheel with ``teeth`` pockets; pitch radius Dolipiński et al. eq. (6); ``EA`` from
    :func:`~chaindrive.simulation.model.link_chain_axial_stiffness`). Each guide of the
    drive becomes a channel (:func:`guide_channel`, with lead-ins) on the span entering
    its wheel; guided entry is validated against the kinematics module for roller and
    round link chains (docs/simulation.md).
    The driving wheel becomes wheel 0 at the drive's speed (ramped over ``ramp_time``
    [s]); the load torque ``T z_j / z_0`` acts on the first other wheel that is neither an
    idler nor the tensioner;
    wheel inertias are 20 mm steel discs at the pitch radius; the slack tension of
    :meth:`Drive.tensions` is the assembly pretension. A drive with ``travel = "cw"``
    is simulated as its mirror image (``y → −y``, wheel order reversed).

    Parameters
    ----------
    drive : chaindrive.drive.Drive
    ramp_time : float
        Speed ramp of the driver [s].
    axial_stiffness : float, optional
        ``EA`` [N]; default :data:`AXIAL_STIFFNESS_16B` scaled with pitch².
    **kwargs
        Other :class:`SimulationModel` fields (contact_stiffness, friction, ...).

    Examples
    --------
    >>> from chaindrive.drive.project import parse_project, template
    >>> m = model_from_drive(parse_project(template("roller")))
    >>> m.wheels[0].mode
    'speed'

    Raises
    ------
    InputError
        A sprocket on a link chain, an odd number of round links, toothless or outside
        idlers with a link chain, no driven wheel to carry the load (a track drive), a
        guide whose end lies inside the pitch circle or beyond the span.
    """
    from ..analysis.layout import drive_layout
    from ..analysis.loads import drive_loads

    chain = drive.chain
    # every chain has exactly one of bar_diameter (round link chain) and roller_diameter
    # (roller chain): chains.Chain refuses anything else
    link = bool(chain.is_link_chain)
    p = float(chain.pitch)
    bar = _required(chain.bar_diameter, chain.name, "bar_diameter") if link else 0.0
    wheels = list(drive.wheels)
    for w in wheels:
        if link and w.teeth is not None and w.kind == "sprocket":
            raise InputError(f"simulation: wheel {w.name!r} is a sprocket but the chain "
                             f"{chain.name!r} is a round link chain (use kind = "
                             "\"pocket_wheel\" or a pocket idler)")
        if w.teeth is None and link:
            raise InputError(f"simulation: wheel {w.name!r} has no teeth; toothless idlers are "
                             "supported with roller chains only")
        if w.side != 1 and link:
            raise InputError(f"simulation: wheel {w.name!r} has side = -1 (outside idler); "
                             "supported with roller chains only")
    sign = 1.0
    if drive.travel == "cw":
        wheels = wheels[::-1]
        sign = -1.0
    i0 = next(i for i, w in enumerate(wheels) if w.driving)
    wheels = wheels[i0:] + wheels[:i0]
    torque = float(drive.torque())
    tail_torque = 0.0
    if drive.conveyor is not None:
        # a conveyor's load is the friction on its pans (and the material), not a torque
        # on the tail; a tail drive takes its share of the pull there
        from ..analysis.conveyor import conveyor_pull

        pull = conveyor_pull(drive)
        tail_force = 0.0 if pull is None else pull.tail_force
        torque = 0.0
        tail_torque = tail_force
    tens_name = drive.tensioner.wheel if drive.tensioner is not None else None
    # the load goes to the first driven wheel that is neither an idler nor the tensioner
    load_idx = next((i for i, w in enumerate(wheels)
                     if i > 0 and w.name != tens_name and w.kind != "idler"), None)
    if drive.conveyor is not None:
        load_idx = len(wheels) - 1   # the tail: the carrying strand leaves it towards the head
    if load_idx is None:
        raise InputError("simulation: the drive has no driven wheel (besides the driver, only "
                         "idlers and the tensioner) to carry the load; a track drive's load, "
                         "the ground traction on its road wheels, is not simulated")
    sim_wheels = []
    for i, w in enumerate(wheels):
        # the drive's own pitch radius: sprocket, pocket wheel (Dolipiński et al. eq. 6) or the
        # running radius of a toothless idler
        r = float(w.pitch_radius(chain))
        centre = (w.position[0], sign * w.position[1])
        # the drive's own wheel, in the simulation's frame (mirrored for clockwise travel)
        body = dataclasses.replace(w, position=centre, driving=False)
        if i == 0:
            sw = SimWheel(body, _disc_inertia(r), "speed", float(drive.speed), ramp_time)
        else:
            # power balance at the mean speeds: T_j = T_0 ω_0/ω_j = T_0 z_j/z_0
            load = -torque * _teeth(w) / _teeth(wheels[0]) if i == load_idx else 0.0
            if drive.conveyor is not None and i == load_idx:
                load = tail_torque * r
            sw = SimWheel(body, _disc_inertia(r), "free", torque=load)
        sim_wheels.append(sw)
    tens = None
    if drive.tensioner is not None:
        t = drive.tensioner
        j = next(i for i, w in enumerate(wheels) if w.name == t.wheel)
        d = (t.direction[0], sign * t.direction[1])
        tens = SimTensioner(dataclasses.replace(t, direction=d), j,
                            damping=0.2 * 2 * math.sqrt(float(t.stiffness) * float(t.mass)),
                            preload=float(t.force or 0.0))
    links = drive.links if drive.links is not None else drive_layout(drive).links
    if link and int(links) % 2:
        raise InputError(f"simulation: a round link chain needs an even number of links, the "
                         f"drive has {int(links)} (set links = {int(links) + 1} in the project)")
    try:
        # only the slack tension, as the assembly's pretension guess: the loads part's other
        # numbers (and their validity warnings: the running tension's, ...) are not this run's
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ChainDriveWarning)
            slack = float(drive_loads(drive).slack)
    except ChainDriveError:  # a drive the loads part refuses: a pretension guess is enough for the assembly
        slack = 200.0
    if axial_stiffness is not None:
        ea = axial_stiffness
    elif link:
        ea = link_chain_axial_stiffness(bar)
    else:
        ea = AXIAL_STIFFNESS_16B * (p / 0.0254) ** 2
    radius = 0.5 * bar if link else 0.5 * _required(chain.roller_diameter, chain.name, "roller_diameter")
    opts: dict[str, Any] = dict(pitch=p, links=int(links),
                                link_mass=_required(chain.mass_per_length, chain.name, "mass_per_length") * p,
                                axial_stiffness=ea, roller_radius=radius, bar_diameter=bar if link else None,
                wheels=sim_wheels, tensioner=tens, pretension=max(slack, 1.0))
    if drive.conveyor is not None and "gravity" not in kwargs:
        from ..analysis.conveyor import gravity_direction

        gdir = gravity_direction(drive) * 9.81
        opts["gravity"] = (float(gdir[0]), float(sign * gdir[1]))
    opts.update(kwargs)
    model = SimulationModel(**opts)
    if drive.conveyor is not None and "guides" not in kwargs:
        from .conveyor import conveyor_pans

        model.guides.extend(conveyor_pans(model, drive, model.gravity))
    if "guides" not in kwargs:
        names = [w.name for w in wheels]
        for g in drive.guides:
            j = names.index(g.wheel)
            radius_j = model.pitch_radii()[j]
            if g.kind == "tangential" or (g.kind != "chordal" and g.height is None):
                height = radius_j
            elif g.kind == "chordal":
                height = radius_j * math.cos(0.5 * model.central_angles(model.wheels[j].teeth)[0])
            elif g.height is not None:  # kind "guided" has a height (Guide)
                height = float(g.height)
            else:  # excluded by the first condition; the check narrows the type
                raise InputError(f"guide of wheel {g.wheel!r}: give its height (>= 0 m) or kind "
                                 "tangential/chordal", field="guides")
            model.guides.extend(guide_channel(model, j, height, float(g.end_distance)))
    return model


def channel_guides(end: float, far: float, height: float, roller_radius: float, *,
                   lead_in: float = 0.0, segments: int = 10, lead_in_angle: float = 0.15,
                   both_ends: bool = True) -> list[SimGuide]:
    """Guides of a straight channel in its own frame (``x`` along it, ``y`` across).

    The pin line is ``y = height`` from ``x = end`` (the guide end ``G`` of Dolipiński et al.,
    where the chain leaves the channel towards the wheel) to ``x = far``; the roller
    (bar) *surfaces* slide on two guides at ``height ∓ roller_radius``. With
    ``lead_in > 0`` each guide's end opens on an arc of that radius over
    ``lead_in_angle`` [rad], as real guides have a lead-in (a polyline of ``segments``
    pieces: the kernel treats segment ends as corners, so the surface has no gaps or
    steps); ``both_ends`` puts one at the far end too.

    Parameters
    ----------
    end, far : float
        ``x`` of the channel's ends [m], ``far > end``.
    height : float
        ``y`` of the pin line [m].
    roller_radius : float
        [m].
    lead_in : float
        Radius of the lead-in arcs [m]; 0 for plain ends.
    segments : int
    lead_in_angle : float
    both_ends : bool

    Returns
    -------
    list of SimGuide
        The two straight guides first, then the lead-in pieces.

    Examples
    --------
    >>> g = channel_guides(0.1, 0.5, 0.05, 0.008, lead_in=0.1, segments=4)
    >>> len(g), g[0].start, g[1].end
    (18, (0.1, 0.042), (0.1, 0.058))
    """
    import numpy as np

    if not far > end:
        raise InputError(f"channel far end must lie beyond its end (far > {end:g} m), got {far:g}")
    guides = [SimGuide((end, height - roller_radius), (far, height - roller_radius)),
              SimGuide((far, height + roller_radius), (end, height + roller_radius))]
    if lead_in > 0:
        angles = np.linspace(0.0, lead_in_angle, int(segments) + 1)
        for side in (-1, 1):  # the guide below (-1) and above (+1) the pin line
            yc = height + side * (roller_radius + lead_in)
            pts = [(end - lead_in * math.sin(a), yc - side * lead_in * math.cos(a)) for a in angles]
            for q0, q1 in itertools.pairwise(pts):
                # the chain on the left of start -> end
                guides.append(SimGuide(q1, q0) if side < 0 else SimGuide(q0, q1))
        if both_ends:
            # mirror image x -> end + far - x (which reverses each segment's direction)
            guides += [SimGuide((end + far - g.end[0], g.end[1]), (end + far - g.start[0], g.start[1]))
                       for g in guides[2:]]
    return [SimGuide((float(g.start[0]), float(g.start[1])), (float(g.end[0]), float(g.end[1])))
            for g in guides]


def guide_channel(model: SimulationModel, wheel: int, height: float, end_distance: float,
                  *, length: float | None = None, lead_in: float | None = None,
                  margin_links: float = 2.0) -> list[SimGuide]:
    """Channel guides for the chain entering ``wheel`` (Dolipiński et al.'s guide).

    In the frame of docs/kinematics.md for that wheel (origin at its axis, ``x`` against
    the chain's travel along the incoming span, ``y`` from the axis towards the span) the
    pin line is ``y = H`` (``height``) from its end ``G = (l, H)`` (``end_distance``) back
    along the span for ``length`` (default: to ``margin_links`` pitches before the
    previous wheel's tangent point); the roller (bar) *surfaces* slide on the guides, at
    ``H − r`` and ``H + r``, with lead-in arcs at both ends (:func:`channel_guides`).

    Parameters
    ----------
    model : SimulationModel
    wheel : int
        Index of the wheel the guide feeds (the span from wheel ``wheel − 1``).
    height : float
        ``H`` [m], ``0 < H``.
    end_distance : float
        ``l`` [m], greater than the pitch radius.
    length : float, optional
        Length of the channel [m].
    lead_in : float, optional
        Radius of the lead-in arcs [m]; default 5 pitches; 0 for plain ends (a round
        link chain's bar then drops off the corner: docs/simulation.md).
    margin_links : float
        Clearance of the channel's far end from the previous wheel [pitches].

    Returns
    -------
    list of SimGuide

    Raises
    ------
    InputError
        ``l`` not beyond the pitch circle, or the channel would be shorter than one pitch.

    Examples
    --------
    >>> from chaindrive.simulation import roller_example
    >>> m = roller_example(links=40, teeth=12)
    >>> g = guide_channel(m, 0, m.pitch_radii()[0], 0.1, lead_in=0)
    >>> [round(float(v), 4) for v in g[0].start], [round(float(v), 4) for v in g[0].end]
    ([0.1, 0.0411], [0.3048, 0.0411])
    """
    from .run import _tangent

    nw = len(model.wheels)
    radii = model.signed_radii()
    j, i = wheel, (wheel - 1) % nw
    if not height > 0:
        raise InputError(f"guide height must be positive (0 < H), got {height:g} m")
    if not end_distance > abs(radii[j]):
        raise InputError(f"guide end_distance must exceed the pitch radius {abs(radii[j]):.6g} m of "
                         f"wheel {model.wheels[j].name or j!r}, got {end_distance:g} m")
    c_i = model.wheels[i].centre
    c_j = model.wheels[j].centre
    p1, _p2, u, n = _tangent(c_i, radii[i], c_j, radii[j])
    ex = (-u[0], -u[1])          # x: against the travel
    ey = (-n[0], -n[1])          # y: from the axis towards the span
    far = (p1[0] - c_j[0]) * ex[0] + (p1[1] - c_j[1]) * ex[1] - margin_links * model.pitch
    if far - end_distance < model.pitch:
        raise InputError(f"guide end_distance {end_distance:g} m leaves no room for a guide on "
                         f"the span entering wheel {model.wheels[j].name or j!r} (at most "
                         f"{far - model.pitch:.4g} m)")
    if length is not None:
        if not model.pitch <= length <= far - end_distance:
            raise InputError(f"guide length must lie in [{model.pitch:.4g}, "
                             f"{far - end_distance:.4g}] m, got {length:g}")
        far = end_distance + length
    lead = 5.0 * model.pitch if lead_in is None else float(lead_in)
    local = channel_guides(end_distance, far, height, model.roller_radius, lead_in=lead)

    def point(q):
        return (c_j[0] + q[0] * ex[0] + q[1] * ey[0], c_j[1] + q[0] * ex[1] + q[1] * ey[1])

    return [SimGuide(point(g.start), point(g.end)) for g in local]


def conveyor_drive(*, length: float = 100.0, chain: str = "26x92", teeth: int = 7,
                   angular_velocity: float = 4.0, power: float = 40e3,
                   tensioner_force: float = 45e3) -> Drive:
    """The long scraper conveyor of ``examples/long_conveyor.toml`` as a drive description.

    A DIN 22252 round link chain on two pocket wheels ``length`` apart (the head, driving,
    at the origin; the tail at ``(length, 0)``), with a pocket idler on a spring slide
    (150 kg, 400 kN/m, travelling down) pressing the return strand down 1.5 m behind the
    head (a wrap of about 45°: two hinges seated; a barely touching idler loses the chain).

    Parameters
    ----------
    length : float
        Distance between the head and the tail wheel [m], at least 10 m.
    chain : str
        Catalogue name of a round link chain (DIN 22252).
    teeth : int
        Pockets of each wheel (the idler too).
    angular_velocity : float
        Head wheel speed [rad/s], positive.
    power : float
        Transmitted power [W], positive.
    tensioner_force : float
        Force of the tensioner on the chain [N], positive.

    Returns
    -------
    chaindrive.drive.Drive

    Examples
    --------
    >>> d = conveyor_drive()
    >>> d.chain.name, [w.teeth for w in d.wheels], d.wheels[2].position
    ('26x92', [7, 7, 7], (100.0, 0.0))
    """
    from .. import chains
    from ..drive.model import Drive, Load, Tensioner, Wheel

    check_range("length", length, 10.0, math.inf, unit="m")
    check_positive("angular_velocity", angular_velocity, "rad/s")
    check_positive("power", power, "W")
    check_positive("tensioner_force", tensioner_force, "N")
    wheels = (Wheel("drive", "pocket_wheel", teeth, (0.0, 0.0), driving=True),
              Wheel("tensioner", "idler", teeth, (1.5, -1.2)),
              Wheel("tail", "pocket_wheel", teeth, (float(length), 0.0)))
    return Drive(chain=chains.get(chain), wheels=wheels, speed=float(angular_velocity),
                 load=Load(power=float(power)),
                 tensioner=Tensioner("tensioner", 150.0, 400e3, "spring", (0.0, -1.0),
                                     float(tensioner_force)),
                 required_static_safety=3.5, elongation_limit=0.02,
                 name=f"Long scraper conveyor, {length:g} m")


def conveyor_example(*, ramp_time: float = 2.0, **kwargs: Any) -> SimulationModel:
    """Simulation model of the long scraper conveyor (:func:`conveyor_drive`).

    The head wheel is ramped to speed over ``ramp_time`` [s] (a 100 m chain of 2,194 links
    started within 0.2 s runs into longitudinal shocks near its breaking force).

    Parameters
    ----------
    ramp_time : float
        Speed ramp of the head wheel [s].
    **kwargs
        Arguments of :func:`conveyor_drive` (length, chain, teeth, angular_velocity,
        power, tensioner_force).

    Returns
    -------
    SimulationModel

    Examples
    --------
    >>> m = conveyor_example()
    >>> m.links, m.is_link_chain, m.tensioner.wheel
    (2194, True, 1)
    """
    return model_from_drive(conveyor_drive(**kwargs), ramp_time=ramp_time)


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
