"""The drive as an assembly of named, placed parts (no CAD kernel needed here).

:func:`drive_assembly` places every part of a project's drive: each wheel (its
manufacturing part, :mod:`chaindrive.geometry.part`), each link of the chain (the parts of
:mod:`chaindrive.cad.links`), the guides and the tensioner's slide. The chain lies where
the static assembly of the simulation puts it (:func:`chaindrive.simulation.assemble`:
the chain's potential energy with gravity, the wheels' seats, the loads and the
tensioner at its minimum), so the slack span hangs with its sag; :func:`frame_assembly`
does the same for an instant of a simulation run. The result holds only numbers (4 × 4
placement matrices in metres, the shapes to build as descriptions);
:mod:`chaindrive.cad.build` turns it into OpenCascade shapes, building each distinct
shape once and placing copies.

Frames: the wheels turn in the x-y plane of the project, z is their axis, the chain's
middle plane is z = 0; a wheel's hub points to +z.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..errors import InputError
from ..limits import MAX_CAD_PARTS
from .links import (
    RollerLinkDimensions,
    RoundLinkDimensions,
    roller_link_dimensions,
    round_link_dimensions,
)

__all__ = ["Pose", "PartPlacement", "ShapeSpec", "DriveAssembly", "drive_assembly", "frame_assembly",
           "static_pose", "frame_pose", "placement_matrix", "pocket_play"]

#: Play round a round link in the pocket and the groove of the modelled pocket wheels, as a
#: fraction of the bar diameter (a drawing choice: a pocket made to the link's nominal size
#: would touch it everywhere, and a link entering at an angle needs room; 10 % of d is
#: 1.8 mm on an 18 mm chain).
POCKET_PLAY_RATIO = 0.10

#: Gap [m] left at each contact of the static pose once the penalty penetration is removed
#: (:func:`static_pose`): the parts touch to within it, and a CAD system's interference
#: check (OpenCascade's linear tolerance 1e-7 mm) reads them as clear.
CONTACT_GAP = 1e-6


@dataclass(frozen=True)
class Pose:
    """Where the chain and the wheels are, in the project's frame [m, rad].

    Attributes
    ----------
    pins : ndarray (N, 2)
        Joint centres (roller chains) or hinge points (round link chains) [m].
    centres : ndarray (W, 2)
        Wheel centres [m], in the order of :attr:`wheels`.
    angles : ndarray (W,)
        Polar angle [rad] of each wheel's tooth gap 0 (sprocket) or pocket 0 (pocket wheel).
    wheels : tuple
        The project's :class:`~chaindrive.drive.Wheel` of each entry.
    tensions : ndarray (N,)
        Force in each link [N] (link i joins pins i and i + 1).
    guides : ndarray (G, 2, 2)
        Start and end of each guide's running surface [m]; the chain runs on its left.
    time : float or None
        Instant of a simulation frame [s]; None for the static assembly.
    shift : ndarray (N,) or None
        Distance [m] each pin was moved out of the seat or guide it pressed into (the
        instant's penalty penetration plus :data:`CONTACT_GAP`).
    """

    pins: np.ndarray
    centres: np.ndarray
    angles: np.ndarray
    wheels: tuple
    tensions: np.ndarray
    guides: np.ndarray
    time: float | None = None
    shift: np.ndarray | None = None


@dataclass(frozen=True)
class ShapeSpec:
    """A shape to build once: ``kind`` (``wheel``, ``chain part``, ``round link``, ``box``) and its data."""

    kind: str
    data: Any


@dataclass(frozen=True)
class PartPlacement:
    """One part of the assembly: its name, group, shape key, placement and numbers.

    ``matrix`` is the 4 × 4 homogeneous placement of the shape's own frame [m]; ``info``
    holds the numbers shown for the part (SI units, keys with the unit in brackets).
    """

    name: str
    group: str
    shape: str
    matrix: np.ndarray
    info: dict = field(default_factory=dict)


@dataclass(frozen=True)
class DriveAssembly:
    """The drive's parts and the distinct shapes they are copies of.

    Attributes
    ----------
    title : str
    parts : tuple of PartPlacement
    shapes : dict
        Shape key -> :class:`ShapeSpec`.
    links, first_link : int
        Links modelled and the index of the first (a section of the chain exports fewer).
    total_links : int
        Links of the layout.
    pitch : float
        Chain pitch [m].
    pose : Pose
    link_chain : bool
    pocket_play : float or None
        Play round the links in the drawn pockets and groove [m] (:func:`pocket_play`;
        None for a roller chain).
    """

    title: str
    parts: tuple
    shapes: dict
    links: int
    first_link: int
    total_links: int
    pitch: float
    pose: Pose
    link_chain: bool
    pocket_play: float | None = None

    @property
    def part_count(self) -> int:
        """Number of parts (solids) of the assembly."""
        return len(self.parts)

    def chain_length(self) -> float:
        """Sum of the modelled links' joint-to-joint distances at the pose [m] (all links: the
        closed loop's length, to compare with the layout's ``links × pitch``)."""
        pins = self.pose.pins
        return float(np.sum(np.hypot(*(np.roll(pins, -1, axis=0) - pins).T)))

    def summary(self) -> dict:
        """Counts and the chain's numbers (SI units)."""
        groups: dict[str, int] = {}
        shift = 0.0 if self.pose.shift is None else float(np.max(self.pose.shift, initial=0.0))
        for part in self.parts:
            groups[part.group] = groups.get(part.group, 0) + 1
        return {"title": self.title, "parts": self.part_count, "distinct_shapes": len(self.shapes),
                "groups": groups, "links": self.links, "first_link": self.first_link,
                "total_links": self.total_links, "pitch": self.pitch,
                "chain_length": self.chain_length(), "layout_length": self.total_links * self.pitch,
                "time": self.pose.time, "contact_shift_max": shift, "contact_gap": CONTACT_GAP,
                "pocket_play": self.pocket_play}


# --------------------------------------------------------------------------- matrices
def placement_matrix(origin: tuple[float, float, float], angle: float = 0.0, *, upright: bool = False) -> np.ndarray:
    """4 × 4 placement: rotation ``angle`` [rad] about z (after a quarter turn about x if
    ``upright``), then translation to ``origin`` [m].

    Examples
    --------
    >>> placement_matrix((1.0, 0.0, 0.0), math.pi / 2)[:3, 0].round(12).tolist()
    [0.0, 1.0, 0.0]
    """
    c, s = math.cos(angle), math.sin(angle)
    rz = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    if upright:
        rz = rz @ np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])
    m = np.eye(4)
    m[:3, :3] = rz
    m[:3, 3] = origin
    return m


# --------------------------------------------------------------------------- poses
def _model_pose(model: Any, pins: np.ndarray, centres: np.ndarray, theta: np.ndarray, tensions: np.ndarray,
                mirrored: bool, time: float | None, shift: np.ndarray | None = None) -> Pose:
    """Pose in the project's frame from the simulation's (mirrored back for clockwise travel)."""
    angles = []
    for k, w in enumerate(model.wheels):
        a = float(theta[k])
        if model.is_link_chain and w.teeth:
            a += 0.5 * model.central_angles(w.teeth)[0]  # pocket 0 between seats 0 and 1
        angles.append(a)
    ang = np.asarray(angles)
    guides = np.array([[g.start, g.end] for g in model.guides], float).reshape(-1, 2, 2)
    pins = np.array(pins, float)
    centres = np.array(centres, float)
    if mirrored:
        pins = pins[::-1].copy()
        pins[:, 1] *= -1
        shift = None if shift is None else shift[::-1].copy()
        tensions = np.roll(tensions[::-1], -1)
        centres[:, 1] *= -1
        ang = -ang
        guides = guides[:, ::-1, :].copy()
        guides[..., 1] *= -1
    return Pose(pins=pins, centres=centres, angles=ang, wheels=tuple(w.wheel for w in model.wheels),
                tensions=np.asarray(tensions, float), guides=guides, time=time, shift=shift)


def _link_tensions(model: Any, pins: np.ndarray) -> np.ndarray:
    """Force in each link from its stretch [N]: ``k (|chord| − L0)``, ``k`` the link stiffness."""
    chords = np.hypot(*(np.roll(pins, -1, axis=0) - pins).T)
    if model.is_link_chain:
        a, b = model.link_lengths
        rest = np.where(np.arange(len(chords)) % 2 == 0, a, b)
    else:
        rest = np.full(len(chords), model.pitch)
    return float(model.link_stiffness) * (chords - rest)


def _out_of_contact(pos: np.ndarray, wp: np.ndarray, theta: np.ndarray, slide: np.ndarray, gd: np.ndarray,
                    par: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Pins moved out of the seats and guides they press into, and each one's shift [m].

    The model's contacts are penalty contacts: a roller pressed with ``F`` lies ``F / k_c``
    inside its seat (micrometres), which drawn solids would show as an overlap. Each pin
    in contact moves out along the contact's normal by its penetration
    (:func:`chaindrive.simulation.seating.contact_penetration`) plus :data:`CONTACT_GAP`.
    """
    from ..simulation.seating import contact_penetration

    pen = contact_penetration(pos, wp, theta, slide, gd, par)
    depth = np.hypot(*pen.T)
    touching = depth > 0.0
    scale = 1.0 + CONTACT_GAP / np.where(touching, depth, 1.0) * touching
    return pos - pen * scale[:, None], depth + CONTACT_GAP * touching


def static_pose(drive: Any) -> tuple[Pose, Any]:
    """The static assembly of a project drive (:func:`chaindrive.simulation.assemble`) as a
    :class:`Pose`; returns ``(pose, simulation model)``.

    The pose is the static assembly with the penalty penetration removed: each pin pressed
    into a seat or a guide moves out by its penetration plus :data:`CONTACT_GAP` (at most
    7 um on the roller examples, 0.12 mm on the mining conveyor's loaded pockets);
    the link tensions are the assembly's.

    Examples
    --------
    >>> from chaindrive.drive.project import parse_project, template
    >>> pose, model = static_pose(parse_project(template("roller")))  # doctest: +SKIP
    >>> pose.pins.shape[1]  # doctest: +SKIP
    2
    """
    from ..simulation import _kernel as K
    from ..simulation import assemble, model_from_drive

    model = model_from_drive(drive)
    state = assemble(model)
    centres = state.wp[:, [K.W_CX, K.W_CY]] + state.ws[:, [K.S_S]] * state.wp[:, [K.W_DX, K.W_DY]]
    pins, shift = _out_of_contact(state.pos, state.wp, state.ws[:, K.S_THETA], state.ws[:, K.S_S], state.gd,
                                  state.par)
    pose = _model_pose(model, pins, centres, state.ws[:, K.S_THETA], _link_tensions(model, state.pos),
                       drive.travel == "cw", None, shift=shift)
    return pose, model


def frame_pose(result: Any, model: Any, time: float, *, mirrored: bool = False) -> Pose:
    """The instant of a simulation run nearest ``time`` [s] as a :class:`Pose`, the pins moved
    out of the contacts they press into as in :func:`static_pose`.

    Raises
    ------
    InputError
        ``time`` outside the run.
    """
    times = np.asarray(result.time)
    t = float(time)
    if not (math.isfinite(t) and times[0] - 1e-12 <= t <= times[-1] + 1e-12):
        raise InputError(f"--cad-frame must lie in [{times[0]:g}, {times[-1]:g}] s (the simulated time), got {t:g} s",
                         field="cad-frame")
    k = int(np.argmin(np.abs(times - t)))
    direction = np.zeros((len(model.wheels), 2))
    if model.tensioner is not None:
        d = np.asarray(model.tensioner.direction, float)
        direction[model.tensioner.wheel] = d / np.hypot(*d)
    centres = np.asarray(result.wheel_centres) + np.asarray(result.tensioner_position)[k][:, None] * direction
    from ..simulation import _kernel as K
    from ..simulation.run import kernel_arrays

    par, wp, gd = kernel_arrays(model)
    wp[:, K.W_CX], wp[:, K.W_CY] = centres[:, 0], centres[:, 1]
    theta = np.asarray(result.wheel_angle)[k]
    pins, shift = _out_of_contact(np.asarray(result.positions)[k], wp, theta, np.zeros(len(centres)), gd, par)
    return _model_pose(model, pins, centres, theta, np.asarray(result.tension)[k], mirrored, float(times[k]),
                       shift=shift)


# --------------------------------------------------------------------------- parts
def _wheel_part(wheel: Any, chain: Any, link: RoundLinkDimensions | None,
                play: float = 0.0) -> tuple[str, ShapeSpec, dict]:
    """Shape key, spec and numbers of a wheel."""
    from ..geometry import PocketWheel, Sprocket
    from ..geometry.part import pocket_wheel_part, sprocket_part

    if wheel.kind == "track_wheel":
        raise InputError(f"wheel {wheel.name!r}: track wheels are not modelled in 3-D", field="wheels")
    if wheel.teeth is None:  # toothless idler of a roller chain: a plain disc under the rollers
        d1 = float(chain.roller_diameter or 0.0)
        diameter = float(wheel.diameter) - d1
        width = 0.9 * float(chain.inner_width or d1)
        key = f"disc {diameter * 1e3:.3f} x {width * 1e3:.3f}"
        return key, ShapeSpec("disc", (diameter, width)), {
            "kind": "toothless idler", "rim diameter [m]": diameter, "width [m]": width}
    z = int(wheel.teeth)
    if link is not None:
        pw = PocketWheel.from_chain(chain, z, clearance=play)
        part = pocket_wheel_part(pw)
        pdims = pw.dimensions()
        info = {"kind": "pocket wheel", "pockets": z, "pitch radius [m]": float(pdims.pitch_radius),
                "tip radius [m]": float(pdims.tip_radius), "play in pocket and groove [m]": pw.clearance}
    else:
        sp = Sprocket.from_chain(chain, z)
        part = sprocket_part(sp, transverse_pitch=chain.transverse_pitch if sp.strands > 1 else None)
        dims = sp.dimensions()
        info = {"kind": "sprocket", "teeth": z, "pitch diameter [m]": float(dims.pitch_diameter),
                "tip diameter [m]": 2 * part.tip_radius, "tooth width bf1 [m]": part.width,
                "strands": sp.strands, "rim width [m]": part.rim_width}
    info.update({"bore [m]": part.hub.bore, "hub diameter [m]": part.hub.hub_diameter,
                 "hub length [m]": part.hub.hub_length, "material": part.material})
    key = f"{part.kind} {part.chain} z{z}" + (f" play {play * 1e3:.2f} mm" if link is not None else "")
    return key, ShapeSpec("wheel", part), info


def _inside(points: np.ndarray, polygon: np.ndarray) -> np.ndarray:
    """Which ``points`` (K, 2) lie inside the closed ``polygon`` (M, 2) (even-odd rule)."""
    a, b = polygon, np.roll(polygon, -1, axis=0)
    px, py = points[:, :1], points[:, 1:]
    cross = (a[:, 1] > py) != (b[:, 1] > py)
    with np.errstate(divide="ignore", invalid="ignore"):
        x = a[:, 0] + (py - a[:, 1]) * (b[:, 0] - a[:, 0]) / (b[:, 1] - a[:, 1])
    return np.count_nonzero(cross & (px < x), axis=1) % 2 == 1


def _boundary_distance(points: np.ndarray, polygon: np.ndarray) -> np.ndarray:
    """Distance [m] of each point to the boundary of the closed polygon."""
    a, b = polygon, np.roll(polygon, -1, axis=0)
    ab = b - a
    length2 = np.maximum(np.sum(ab * ab, axis=1), 1e-30)
    rel = points[:, None, :] - a[None]
    t = np.clip(np.sum(rel * ab[None], axis=2) / length2, 0.0, 1.0)
    return np.min(np.hypot(*(rel - t[..., None] * ab[None]).transpose(2, 0, 1)), axis=1)


def _overlap_depth(p: np.ndarray, q: np.ndarray) -> float:
    """Largest depth [m] of a vertex of one closed polygon inside the other (0: apart)."""
    depth = 0.0
    for u, v in ((p, q), (q, p)):
        inside = _inside(u, v)
        if inside.any():
            depth = max(depth, float(_boundary_distance(u[inside], v).max()))
    return depth


def _pocket_overlap(pose: Pose, chain: Any, dims: RoundLinkDimensions, play: float) -> float:
    """Largest overlap [m] of a horizontal link beside the groove with a pocket wheel's drawn
    rim (face view, :func:`chaindrive.cad.links.round_link_face_outline`) at ``play``."""
    from ..geometry import PocketWheel
    from .links import round_link_face_outline

    link = round_link_face_outline(dims, dims.bar_diameter / 2 + play)
    pins = pose.pins
    u = np.roll(pins, -1, axis=0) - pins
    chords = np.hypot(*u.T)
    horizontal = np.abs(chords - dims.horizontal_chord) < np.abs(chords - dims.vertical_chord)
    depth = 0.0
    for k, wheel in enumerate(pose.wheels):
        if not wheel.teeth:
            continue
        pw = PocketWheel.from_chain(chain, int(wheel.teeth), clearance=play)
        rim = pw.outline().polyline(12)[:-1]
        c, s = math.cos(pose.angles[k] - math.pi / 2), math.sin(pose.angles[k] - math.pi / 2)
        rim = rim @ np.array([[c, s], [-s, c]]) + pose.centres[k]
        mid = pins + 0.5 * u
        near = horizontal & (np.hypot(*(mid - pose.centres[k]).T) < pw.dimensions().tip_radius + dims.pitch)
        for i in np.flatnonzero(near):
            e = u[i] / chords[i]
            placed = mid[i] + link[:, :1] * e + link[:, 1:] * np.array([-e[1], e[0]])
            depth = max(depth, _overlap_depth(placed, rim))
    return depth


def pocket_play(pose: Pose, chain: Any, dims: RoundLinkDimensions) -> float:
    """Play [m] round the links in the drawn pockets and groove: ``POCKET_PLAY_RATIO · d``, or
    more where a link of ``pose`` entering or leaving a pocket needs it.

    The simulation's hinge seats are symmetric arc-and-flank seats
    (:func:`chaindrive.simulation.profiles.link_seat_profile`, flanks about 18° to 22°
    from the hinge's radius) and its links have no shape: a hinge lifted in its seat may
    lie nearer the drawn pocket wall (parallel to the pocket axis, i.e. leaning over the
    hinge by half the pocket's central angle) than the link's end bend allows. The play
    is then the smallest, to 0.05 mm, at which no horizontal link beside the groove
    overlaps the drawn rim (face view; bisection), if the pockets stay apart.

    Returns
    -------
    float
        The play [m] (``POCKET_PLAY_RATIO · d`` if no link overlaps or none can be cleared).

    References
    ----------
    Dolipiński et al., eqs (6)-(9) (the pocket wheel's pitch radius and central angles);
    DIN 22252 (the link's inner width); :class:`chaindrive.geometry.PocketWheel` (the
    drawn outline).

    Examples
    --------
    >>> # pocket_play(drive_assembly(drive).pose, drive.chain, round_link_dimensions(drive.chain))
    """
    from ..errors import InfeasibleError

    def overlap(play: float) -> float:
        try:
            return _pocket_overlap(pose, chain, dims, play)
        except (InfeasibleError, InputError):  # the pockets would overlap
            return math.inf

    step = 5e-5
    lo = POCKET_PLAY_RATIO * dims.bar_diameter
    depth = overlap(lo)
    if depth <= 0.0:
        return lo
    hi = lo + depth + step
    for _ in range(4):
        if overlap(hi) <= 0.0:
            break
        hi += depth
    else:
        return lo  # no play clears it: the clearance check reports the overlap
    while hi - lo > step:
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if overlap(mid) > 0.0 else (lo, mid)
    return math.ceil(hi / step - 1e-9) * step


def _check_parts(count: int, links: int) -> None:
    if count > MAX_CAD_PARTS:
        per_link = max(count // max(links, 1), 1)
        raise InputError(
            f"the assembly would have {count} parts, more than chaindrive.limits.MAX_CAD_PARTS = {MAX_CAD_PARTS}; "
            f"export a section of the chain (--links FIRST:COUNT, e.g. --links 0:{max(MAX_CAD_PARTS // per_link - 20, 1)})",
            field="links")


def _section(section: tuple[int, int] | None, total: int) -> tuple[int, int]:
    if section is None:
        return 0, total
    first, count = (int(v) for v in section)
    if not (0 <= first < total and 1 <= count <= total):
        raise InputError(f"--links FIRST:COUNT must have 0 <= FIRST < {total} and 1 <= COUNT <= {total} "
                         f"(the chain's links), got {first}:{count}", field="links")
    return first, count


def _roller_chain_parts(pose: Pose, dims: RollerLinkDimensions, first: int, count: int) -> list[PartPlacement]:
    from .links import roller_chain_parts_layout

    pins = pose.pins
    n = len(pins)
    layout = roller_chain_parts_layout(dims)
    out = []
    for i in (first + j for j in range(count)):
        k = i % n
        a, b = pins[k], pins[(k + 1) % n]
        u = b - a
        angle = math.atan2(u[1], u[0])
        mid = 0.5 * (a + b)
        inner = k % 2 == 0 and not (n % 2 and k == n - 1)
        kind = "inner" if inner else "outer"
        start = mid - 0.5 * dims.pitch * u / np.hypot(*u)
        info = {"link": k, "kind": f"{kind} link", "tension [N]": float(pose.tensions[k]),
                "pitch [m]": dims.pitch}
        for shape, (x, z), label in layout[kind]:
            if shape.endswith("plate"):
                m = placement_matrix((start[0], start[1], z), angle)
            else:
                c = a if x == 0.0 else b
                m = placement_matrix((c[0], c[1], z), angle)
            out.append(PartPlacement(f"link {k:04d} {kind}/{label}", "chain", shape, m, info))
    return out


def _round_chain_parts(pose: Pose, dims: RoundLinkDimensions, first: int, count: int) -> list[PartPlacement]:
    pins = pose.pins
    n = len(pins)
    out = []
    for i in (first + j for j in range(count)):
        k = i % n
        a, b = pins[k], pins[(k + 1) % n]
        u = b - a
        chord = float(np.hypot(*u))
        horizontal = abs(chord - dims.horizontal_chord) < abs(chord - dims.vertical_chord)
        mid = 0.5 * (a + b)
        m = placement_matrix((mid[0], mid[1], 0.0), math.atan2(u[1], u[0]), upright=horizontal)
        kind = "horizontal" if horizontal else "vertical"
        out.append(PartPlacement(f"link {k:04d} {kind}", "chain", "round link", m,
                                 {"link": k, "kind": f"{kind} link", "tension [N]": float(pose.tensions[k]),
                                  "pitch [m]": dims.pitch, "bar diameter [m]": dims.bar_diameter}))
    return out


def _assembly(drive: Any, pose: Pose, section: tuple[int, int] | None, chain_width: float | None = None) -> DriveAssembly:
    chain = drive.chain
    link_chain = chain.is_link_chain
    n = len(pose.pins)
    first, count = _section(section, n)
    if link_chain:
        rdims = round_link_dimensions(chain)
        play = pocket_play(pose, chain, rdims)
        per_link, width, thickness = 1, rdims.outer_width, rdims.bar_diameter
        dims: Any = rdims
    else:
        from .links import roller_chain_parts_layout

        dims = roller_link_dimensions(chain)
        lay = roller_chain_parts_layout(dims)
        per_link = (len(lay["inner"]) + len(lay["outer"]) + 1) // 2
        width, thickness = dims.width, 0.5 * dims.roller_diameter
    _check_parts(count * per_link + len(pose.wheels) + len(pose.guides) + 1, count)
    shapes: dict[str, ShapeSpec] = {}
    parts: list[PartPlacement] = []
    tens = drive.tensioner
    for k, wheel in enumerate(pose.wheels):
        key, spec, info = _wheel_part(wheel, chain, rdims if link_chain else None, play if link_chain else 0.0)
        shapes.setdefault(key, spec)
        c = pose.centres[k]
        info = {"wheel": wheel.name, **info, "centre x [m]": float(c[0]), "centre y [m]": float(c[1]),
                "driving": bool(wheel.driving)}
        parts.append(PartPlacement(f"wheel {wheel.name}", "wheels", key,
                                   placement_matrix((c[0], c[1], 0.0), float(pose.angles[k]) - math.pi / 2), info))
        if tens is not None and tens.wheel == wheel.name:
            parts.append(_tensioner_slide(tens, c, wheel, shapes, width))
    for g, (a, b) in enumerate(pose.guides):
        u = b - a
        length = float(np.hypot(*u))
        key = f"guide rail {length * 1e3:.1f} mm"
        shapes.setdefault(key, ShapeSpec("box", (length, thickness, 1.2 * width, 0.0, -thickness)))
        parts.append(PartPlacement(f"guide {g}", "guides", key,
                                   placement_matrix((a[0], a[1], 0.0), math.atan2(u[1], u[0])),
                                   {"guide": g, "length [m]": length, "start x [m]": float(a[0]),
                                    "start y [m]": float(a[1]), "end x [m]": float(b[0]), "end y [m]": float(b[1])}))
    if link_chain:
        shapes["round link"] = ShapeSpec("round link", rdims)
        parts += _round_chain_parts(pose, rdims, first, count)
    else:
        for name in ("roller", "bushing", "inner plate", "pin", "outer plate", "middle plate"):
            if name != "middle plate" or dims.strands > 1:
                shapes[name] = ShapeSpec("chain part", (dims, name))
        parts += _roller_chain_parts(pose, dims, first, count)
    _check_parts(len(parts), count)
    title = drive.name or "chain drive"
    if pose.time is not None:
        title += f" at t = {pose.time:.4g} s"
    return DriveAssembly(title=title, parts=tuple(parts), shapes=shapes, links=count, first_link=first,
                         total_links=n, pitch=float(chain.pitch), pose=pose, link_chain=link_chain,
                         pocket_play=play if link_chain else None)


def _tensioner_slide(tens: Any, centre: np.ndarray, wheel: Any, shapes: dict, width: float) -> PartPlacement:
    """The tensioner's slide: a block along its travel behind the wheel (−z side)."""
    d = np.asarray(tens.direction, float)
    d = d / np.hypot(*d)
    length = 0.25
    key = "tensioner slide"
    shapes.setdefault(key, ShapeSpec("box", (length, 0.04, 0.04, -0.5 * length, -0.02)))
    z = -(0.5 * width + 0.05)
    m = placement_matrix((centre[0], centre[1], z), math.atan2(d[1], d[0]))
    return PartPlacement("tensioner slide", "tensioner", key, m,
                         {"tensioner": wheel.name, "kind": tens.kind, "mass [kg]": tens.mass,
                          "stiffness [N/m]": tens.stiffness, "force [N]": tens.force,
                          "direction": [float(d[0]), float(d[1])]})


def drive_assembly(drive: Any, *, section: tuple[int, int] | None = None) -> DriveAssembly:
    """The drive's parts at the static assembly (the slack span with its sag).

    Parameters
    ----------
    drive : chaindrive.drive.Drive
        A roller chain on sprockets (toothed or toothless idlers) or a round link chain on
        pocket wheels.
    section : (int, int), optional
        ``(first link, number of links)``: model only these links of the chain (all wheels).

    Returns
    -------
    DriveAssembly

    Raises
    ------
    InputError
        More parts than :data:`chaindrive.limits.MAX_CAD_PARTS` (the message gives the
        section to export instead), a track wheel, a chain without the dimensions.

    Examples
    --------
    >>> from chaindrive.drive.project import parse_project, template
    >>> a = drive_assembly(parse_project(template("roller")))  # doctest: +SKIP
    >>> a.summary()["groups"]["wheels"]  # doctest: +SKIP
    2
    """
    pose, _ = static_pose(drive)
    return _assembly(drive, pose, section)


def frame_assembly(drive: Any, result: Any, model: Any, time: float, *,
                   section: tuple[int, int] | None = None) -> DriveAssembly:
    """The drive's parts at an instant of a simulation run of ``drive`` (nearest record to ``time`` [s]).

    Examples
    --------
    >>> # frame_assembly(drive, result, model, 0.4)  (see chaindrive simulate --cad-frame)
    """
    pose = frame_pose(result, model, time, mirrored=drive.travel == "cw")
    return _assembly(drive, pose, section)
