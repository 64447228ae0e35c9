r"""The drive description: :class:`Drive` with its :class:`Wheel`, :class:`Tensioner`,
:class:`Guide`, :class:`Load`, :class:`ContactSpec` and :class:`TrackSpec`.

Every object here is an immutable (frozen) dataclass in SI units: a drive cannot be
changed in place, so nothing computed from it can go stale. Editing means making a
changed copy, with :func:`dataclasses.replace` or :meth:`Drive.with_wheel`::

    faster = dataclasses.replace(drive, speed=2 * drive.speed)
    bigger = drive.with_wheel("fan", teeth=60)

A drive holds only what describes it, plus the quantities that follow from it
directly (pitch radii, mean speeds, torque and power). Its analysis (layout, loads,
rating, entry kinematics, span vibration, contact, wear, checks) is
:func:`chaindrive.analysis.analyze_drive`. The project-file loader
(:func:`chaindrive.drive.project.load_project`) builds a drive; the simulation
(:func:`chaindrive.simulation.model_from_drive`), the command line, the web page and
design studies start from one.
"""

from __future__ import annotations

import dataclasses
import functools
import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Literal

import numpy as np

from .. import layout as L
from .. import loads as F
from .._presenters import view
from ..errors import InputError
from ..layout.wheels import cached_pitch_radius
from ..loads import mean_chain_speed, sides_per_turn
from ._fields import _direction, _finite, _whole
from .specs import (  # noqa: F401 - the optional tables, importable from here as before
    RETURN_STRANDS,
    ContactSpec,
    Conveyor,
    CrawlerSpec,
    FrettingSpec,
    RimBoltsSpec,
    TrackSpec,
    _spec,
)

if TYPE_CHECKING:
    from ..chains import Chain

__all__ = ["WHEEL_KINDS", "TENSIONER_PARTS", "sides_per_turn", "Wheel", "Tensioner", "Adjustable", "Guide", "Load",
           "Drive"]
# the optional tables (ContactSpec, TrackSpec, RimBoltsSpec, CrawlerSpec, FrettingSpec, Conveyor,
# RETURN_STRANDS) are defined in chaindrive.drive.specs and importable from here as before

WHEEL_KINDS = ("sprocket", "pocket_wheel", "track_wheel", "idler")
TENSIONER_KINDS = ("spring", "weight", "screw", "hydraulic")
#: The parts of a tensioner described by its mechanism (:meth:`Tensioner.from_parts`), with their SI units.
TENSIONER_PARTS: dict[str, dict[str, str]] = {
    "lever": {"arm_length": "m", "arm_inertia": "kg*m**2", "arm_mass": "kg", "wheel_mass": "kg",
              "spring_stiffness": "N/m", "spring_lever": "m", "spring_angle": "rad", "torsion_stiffness": "N*m/rad"},
    "sliding": {"carriage_mass": "kg", "wheel_mass": "kg", "spring_stiffness": "N/m", "spring_mass": "kg",
                "spring_angle": "rad"},
}
GUIDE_KINDS = ("tangential", "chordal", "guided")


# The drive's derived quantities, kept by value (an analysis asks for the chain speed, the wheel speeds
# and the torque a dozen times): the same numbers as the formulas give, emptied by
# chaindrive.analysis._memo.clear with the analysis' other stores.
@functools.lru_cache(maxsize=256)
def _sides_per_turn(teeth: int, link_chain: bool) -> int:
    return sides_per_turn(teeth, link_chain)


@functools.lru_cache(maxsize=256)
def _mean_chain_speed(sides: int, pitch: float, speed: float) -> float:
    return float(mean_chain_speed(sides, pitch, speed))


@functools.lru_cache(maxsize=256)
def _torque_from_power(power: float, speed: float) -> float:
    return float(F.torque_from_power(power, speed))


@functools.lru_cache(maxsize=256)
def _power_from_torque(torque: float, speed: float) -> float:
    return float(F.power_from_torque(torque, speed))


#: The stores above (for chaindrive.analysis._memo.clear).
DERIVED_CACHES = (_sides_per_turn, _mean_chain_speed, _torque_from_power, _power_from_torque)


@dataclass(frozen=True)
class Wheel:
    """A wheel of the drive.

    Parameters
    ----------
    name : str
        Unique name (used by guides and the tensioner).
    kind : {"sprocket", "pocket_wheel", "track_wheel", "idler"}
    teeth : int or None
        Teeth (pockets of a pocket wheel); ``None`` for a toothless idler, which then
        needs ``diameter``.
    position : (float, float)
        Centre [m].
    driving : bool
        The one driving wheel of the drive.
    diameter : float, optional
        Pitch (running) diameter of a toothless idler [m].
    side : {+1, -1}
        +1 inside the chain loop; -1 an idler on the outside (back) of the chain.
    power_share : float, optional
        Share of the transmitted power taken off at this driven wheel, in (0, 1]; the
        shares of a drive sum to 1. ``None``: the wheel takes no power (an idler), or,
        when no wheel of the drive has a share, the one driven wheel takes it all.
    """

    name: str
    kind: str
    teeth: int | None
    position: tuple[float, float]
    driving: bool = False
    diameter: float | None = None
    side: int = 1
    power_share: float | None = None

    def __post_init__(self) -> None:
        what = f"wheel {self.name!r}"
        if self.kind not in WHEEL_KINDS:
            raise InputError(f"{what}: kind must be one of {', '.join(WHEEL_KINDS)}, got {self.kind!r}",
                             field="kind")
        if self.teeth is None and self.kind != "idler":
            raise InputError(f"{what}: a {self.kind} needs teeth (a whole number >= 3)", field="teeth")
        if self.teeth is None and self.diameter is None:
            raise InputError(f"{what}: give teeth or (for a toothless idler) diameter", field="teeth")
        if self.teeth is not None:
            object.__setattr__(self, "teeth", _whole(self.teeth, f"{what}: teeth", 3, field="teeth"))
        if self.diameter is not None:
            object.__setattr__(self, "diameter", _finite(self.diameter, f"{what}: diameter", positive=True))
        if self.side not in (1, -1):
            raise InputError(f"{what}: side must be +1 or -1, got {self.side!r}", field="side")
        pos = tuple(self.position)
        if len(pos) != 2:
            raise InputError(f"{what}: position must be (x, y) [m], got {self.position!r}", field="position")
        object.__setattr__(self, "position", (_finite(pos[0], f"{what}: position x"),
                                              _finite(pos[1], f"{what}: position y")))
        object.__setattr__(self, "driving", bool(self.driving))
        if self.power_share is not None:
            share = _finite(self.power_share, f"{what}: power_share")
            if not 0 < share <= 1:
                raise InputError(f"{what}: power_share must lie in (0, 1], got {share:g}", field="power_share")
            if self.driving or self.kind == "idler" or self.teeth is None:
                raise InputError(f"{what}: power_share is for a driven wheel with teeth (not the driving wheel "
                                 "or an idler)", field="power_share")
            object.__setattr__(self, "power_share", share)

    def pitch_radius(self, chain: Chain) -> float:
        """Pitch radius on ``chain`` [m] (pocket wheels: Dolipiński et al., eq. (6))."""
        if self.teeth is None:
            if self.diameter is None:  # refused by __post_init__; the check narrows the type
                raise InputError(f"wheel {self.name!r}: give teeth or (for a toothless idler) diameter",
                                 field="teeth")
            return 0.5 * float(self.diameter)
        bar = chain.bar_diameter if chain.is_link_chain else None
        try:
            return cached_pitch_radius(chain.pitch, self.teeth, bar)  # the same number, kept
        except TypeError:  # an argument that cannot be hashed
            return float(L.pitch_radius(chain.pitch, self.teeth, bar))

    def sides_per_turn(self, chain: Chain) -> int:
        """Chain links seated per turn (:func:`sides_per_turn`); 0 for a toothless idler."""
        if self.teeth is None:
            return 0
        try:
            return _sides_per_turn(self.teeth, bool(chain.is_link_chain))  # the same number, kept
        except TypeError:  # an argument that cannot be hashed
            return sides_per_turn(self.teeth, bool(chain.is_link_chain))


@dataclass(frozen=True)
class Tensioner:
    """A tensioner acting on the slack span.

    Parameters
    ----------
    wheel : str
        Name of the idler wheel it carries.
    mass : float
        Mass reduced to the tensioner axis [kg] (tensioner paper, eq. (7)).
    stiffness : float
        Stiffness reduced to the axis [N/m] (tensioner paper, eq. (7)).
    kind : {"spring", "weight", "screw", "hydraulic"}
    direction : (float, float)
        Direction in which the tensioner travels to take up slack (non-zero).
    force : float, optional
        Force of the tensioner on the chain [N]; sets the slack tension.
    mechanism : {"lever", "sliding"}, optional
        The tensioner described by its parts (:meth:`from_parts`); ``mass`` and
        ``stiffness`` are then its reduction to the axis.
    parts : tuple of (str, float)
        The parts' values in SI units (:data:`TENSIONER_PARTS`), with ``mechanism``.
    """

    wheel: str
    mass: float
    stiffness: float
    kind: str = "spring"
    direction: tuple[float, float] = (0.0, 1.0)
    force: float | None = None
    mechanism: str | None = None
    parts: tuple[tuple[str, float], ...] = ()

    @classmethod
    def from_parts(cls, wheel: str, mechanism: str, parts: Mapping[str, float], **options: Any) -> Tensioner:
        """A tensioner described by its parts, reduced to its axis by the energy balance.

        Parameters
        ----------
        wheel : str
            The idler it carries.
        mechanism : {"lever", "sliding"}
            Pivoted arm or straight slide.
        parts : mapping
            SI values of :data:`TENSIONER_PARTS` ``[mechanism]``; ``lever``: arm_length [m],
            arm_inertia [kg m²] about the pivot (or arm_mass [kg] of a uniform arm, J = m L²/3),
            wheel_mass [kg], spring_stiffness [N/m], spring_lever [m], spring_angle [rad],
            torsion_stiffness [N m/rad]; ``sliding``: carriage_mass [kg], wheel_mass [kg],
            spring_stiffness [N/m], spring_mass [kg], spring_angle [rad].
        **options
            kind, direction, force as for the class.

        Returns
        -------
        Tensioner
            ``mass`` and ``stiffness`` from :func:`chaindrive.vibration.reduced_tensioner`.

        Examples
        --------
        >>> t = Tensioner.from_parts("idler", "lever", {"arm_length": 0.25, "arm_inertia": 0.05,
        ...     "wheel_mass": 2.0, "spring_stiffness": 2e5, "spring_lever": 0.1})
        >>> round(t.mass, 3), round(t.stiffness, 1)
        (2.8, 32000.0)
        """
        from ..vibration import reduced_tensioner

        if mechanism not in TENSIONER_PARTS:
            raise InputError(f"tensioner.mechanism must be one of {', '.join(TENSIONER_PARTS)}, got {mechanism!r}",
                             field="tensioner.mechanism")
        allowed = TENSIONER_PARTS[mechanism]
        values = {k: _finite(v, f"tensioner.{k}", nonnegative=True) for k, v in parts.items()}
        for k in values:
            if k not in allowed:
                raise InputError(f"tensioner.{k} is not a part of a {mechanism} tensioner (parts: "
                                 f"{', '.join(allowed)})", field=f"tensioner.{k}")
        if mechanism == "lever":
            if "arm_inertia" in values and "arm_mass" in values:
                raise InputError("tensioner: give arm_inertia or arm_mass (a uniform arm), not both",
                                 field="tensioner.arm_mass")
            for k in ("arm_length", "spring_stiffness", "spring_lever"):
                if k not in values:
                    raise InputError(f"tensioner.{k} is required for a lever tensioner", field=f"tensioner.{k}")
            length = values["arm_length"]
            inertia = values.get("arm_inertia", values.get("arm_mass", 0.0) * length**2 / 3.0)
            r = reduced_tensioner("pivot_arm", arm_inertia=inertia, sprocket_mass=values.get("wheel_mass", 0.0),
                                  arm_length=length, spring_stiffness=values["spring_stiffness"],
                                  spring_lever=values["spring_lever"], spring_angle=values.get("spring_angle", 0.0),
                                  torsion_stiffness=values.get("torsion_stiffness", 0.0))
        else:
            if "spring_stiffness" not in values:
                raise InputError("tensioner.spring_stiffness is required for a sliding tensioner",
                                 field="tensioner.spring_stiffness")
            r = reduced_tensioner("sliding", carriage_mass=values.get("carriage_mass", 0.0),
                                  sprocket_mass=values.get("wheel_mass", 0.0),
                                  spring_stiffness=values["spring_stiffness"],
                                  spring_mass=values.get("spring_mass", 0.0),
                                  spring_angle=values.get("spring_angle", 0.0))
        return cls(wheel, r.mass, r.stiffness, mechanism=mechanism, parts=tuple(sorted(values.items())), **options)

    def __post_init__(self) -> None:
        object.__setattr__(self, "mass", _finite(self.mass, "tensioner.mass", nonnegative=True))
        object.__setattr__(self, "stiffness", _finite(self.stiffness, "tensioner.stiffness", nonnegative=True))
        if self.kind not in TENSIONER_KINDS:
            raise InputError(f"tensioner.kind must be one of {', '.join(TENSIONER_KINDS)}, got {self.kind!r}",
                             field="tensioner.kind")
        object.__setattr__(self, "direction", _direction(self.direction, "tensioner.direction"))
        if self.force is not None:
            object.__setattr__(self, "force", _finite(self.force, "tensioner.force", nonnegative=True))


@dataclass(frozen=True)
class Adjustable:
    """The wheel moved to fit a whole number of links (take-up, movable sprocket).

    Parameters
    ----------
    wheel : str
        Name of the wheel; its ``position`` is the nominal one.
    direction : (float, float)
        Direction along which it moves (non-zero).
    """

    wheel: str
    direction: tuple[float, float] = (1.0, 0.0)

    def __post_init__(self) -> None:
        object.__setattr__(self, "direction", _direction(self.direction, "adjustable.direction"))


@dataclass(frozen=True)
class Guide:
    """A straight guide at the entry of a wheel (Dolipiński et al.).

    Parameters
    ----------
    wheel : str
        Name of the wheel.
    end_distance : float
        Distance ``l`` of the guide end from the wheel axis [m].
    height : float, optional
        Height ``H`` of the guide line above the axis [m]; ``None`` with
        ``kind="tangential"`` (``H = R``) or ``"chordal"`` (``H = R cos(δ1/2)``).
    kind : {"tangential", "chordal", "guided"}
    """

    wheel: str
    end_distance: float
    height: float | None = None
    kind: str = "tangential"

    def __post_init__(self) -> None:
        object.__setattr__(self, "end_distance", _finite(self.end_distance, "guide.end_distance", positive=True))
        if self.height is not None:
            object.__setattr__(self, "height", _finite(self.height, "guide.height", nonnegative=True))
        if self.kind not in GUIDE_KINDS:
            raise InputError(f"guide.kind must be one of {', '.join(GUIDE_KINDS)}, got {self.kind!r}",
                             field="guide.kind")


@dataclass(frozen=True)
class Load:
    """The transmitted load: power or torque (on the driving wheel), service factor.

    Parameters
    ----------
    power : float, optional
        [W].
    torque : float, optional
        [N·m].
    service_factor : float
        ``K_s >= 1``.
    """

    power: float | None = None
    torque: float | None = None
    service_factor: float = 1.0

    def __post_init__(self) -> None:
        from .schema import check_declared, check_rules

        # the rules and bounds declared for the reader too (chaindrive.drive.tables)
        check_rules(self, "load")
        check_declared(self, "load", ("power", "torque", "service_factor"))


@dataclass(frozen=True)
class Drive:
    """A chain drive: chain, wheels, tensioner, guides, speed, load (immutable).

    Parameters
    ----------
    chain : chaindrive.chains.Chain
    wheels : sequence of Wheel
        In the order the chain passes them, counter-clockwise around the loop.
    speed : float
        Angular velocity of the driving wheel [rad/s].
    load : Load
    tensioner : Tensioner, optional
    guides : sequence of Guide
    links : int, optional
        Chain length [pitches]; default: the required length rounded up to even.
    slack_tension : float, optional
        Slack-side tension [N]; else from the tensioner force, else from
        ``slack_sag_ratio`` of the slack span.
    slack_sag_ratio : float
        Sag / span length used when nothing else sets the slack tension (ISO 10823
        and chain makers: about 2 %), ``0 < ratio <= 0.2``.
    required_static_safety : float
        Required ``F_B / F_max``.
    elongation_limit : float
        Wear elongation limit [-], ``0 < limit <= 0.1``.
    wear_coefficient : float, optional
        Archard coefficient [m²/N] for the ``"archard"`` wear model (link chains).
    name, description : str
        For reports.
    travel : {"ccw", "cw"}
        Direction the chain runs relative to the listed (counter-clockwise) wheel
        order. The driving wheel pulls the span arriving at it (the tight span).
    contact : ContactSpec, optional
        Roller–tooth contact with skew (a mapping of its fields is accepted).
    track : TrackSpec, optional
        Track drive wheel strength (a mapping of its fields is accepted).
    crawler : CrawlerSpec, optional
        The conveyor crawler drive: cams, guide and drive-chain stiffness.
    fretting : FrettingSpec, optional
        Empirical constants of the fretting latent period (multi-strand chains).
    self_regulating : object, optional
        Self-regulating drive inputs
        (:class:`chaindrive.drive.carrier.SelfRegulatingSpec`).
    conveyor : Conveyor, optional
        Scraper conveyor: pans, material, drives (a mapping of its fields is accepted).
    adjustable : Adjustable, optional
        The wheel moved to fit the link count (a mapping of its fields is accepted).
    extra_inputs : tuple of (str, object)
        Further input tables declared by analysis parts (:func:`chaindrive.drive.schema.register_table`),
        ``(("table", value), ...)``; read with :meth:`input`.

    Examples
    --------
    >>> from chaindrive.chains import get
    >>> d = Drive(chain=get("18x64"), speed=5.0, load=Load(power=25e3, service_factor=1.5),
    ...           wheels=[Wheel("drive", "pocket_wheel", 8, (0, 0), driving=True),
    ...                   Wheel("return", "pocket_wheel", 8, (4.0, 0))])
    >>> round(d.chain_speed(), 4), round(d.torque(), 1)
    (0.8149, 5000.0)
    >>> d.speed = 6.0
    Traceback (most recent call last):
    ...
    dataclasses.FrozenInstanceError: cannot assign to field 'speed'
    >>> d.with_wheel("return", teeth=10).wheels[1].teeth
    10
    """

    chain: Chain
    wheels: tuple[Wheel, ...]
    speed: float
    load: Load
    tensioner: Tensioner | None = None
    guides: tuple[Guide, ...] = ()
    links: int | None = None
    slack_tension: float | None = None
    slack_sag_ratio: float = 0.02
    required_static_safety: float | None = None
    elongation_limit: float = 0.03
    wear_coefficient: float | None = None
    name: str = "chain drive"
    description: str = ""
    travel: Literal["ccw", "cw"] = "ccw"
    contact: ContactSpec | None = None
    track: TrackSpec | None = None
    self_regulating: Any = field(default=None)
    crawler: CrawlerSpec | None = None
    fretting: FrettingSpec | None = None
    conveyor: Conveyor | None = None
    adjustable: Adjustable | None = None
    extra_inputs: tuple[tuple[str, Any], ...] = field(default=(), metadata={"omit_empty": True})

    def __post_init__(self) -> None:
        object.__setattr__(self, "wheels", tuple(self.wheels))
        object.__setattr__(self, "extra_inputs", tuple(sorted(dict(self.extra_inputs).items())))
        object.__setattr__(self, "conveyor", _spec(self.conveyor, Conveyor, "conveyor"))
        object.__setattr__(self, "adjustable", _spec(self.adjustable, Adjustable, "adjustable"))
        object.__setattr__(self, "guides", tuple(self.guides))
        object.__setattr__(self, "contact", _spec(self.contact, ContactSpec, "contact"))
        object.__setattr__(self, "track", _spec(self.track, TrackSpec, "track"))
        object.__setattr__(self, "crawler", _spec(self.crawler, CrawlerSpec, "crawler"))
        object.__setattr__(self, "fretting", _spec(self.fretting, FrettingSpec, "fretting"))
        if self.travel not in ("ccw", "cw"):
            raise InputError(f"travel must be 'ccw' or 'cw', got {self.travel!r}", field="drive.travel")
        if len(self.wheels) < 2:
            raise InputError(f"wheels: a drive needs at least 2 wheels, got {len(self.wheels)}", field="wheels")
        if not all(isinstance(w, Wheel) for w in self.wheels):
            raise InputError("wheels must be Wheel objects", field="wheels")
        names = [w.name for w in self.wheels]
        if len(set(names)) != len(names):
            raise InputError(f"wheels: wheel names must be unique, got {names}", field="wheels")
        n_drv = sum(1 for w in self.wheels if w.driving)
        if n_drv != 1:
            raise InputError(f"wheels: exactly one wheel must have driving = true, got {n_drv}", field="wheels")
        if self.driving_wheel.teeth is None:
            raise InputError("wheels: the driving wheel needs teeth", field="wheels")
        object.__setattr__(self, "speed", _finite(self.speed, "drive.speed", positive=True))
        for i, g in enumerate(self.guides):
            self.wheel(g.wheel, what=f"guides[{i}].wheel")
        if self.tensioner is not None:
            self.wheel(self.tensioner.wheel, what="tensioner.wheel")
        if self.adjustable is not None:
            self.wheel(self.adjustable.wheel, what="adjustable.wheel")
        shares = [w.power_share for w in self.wheels if w.power_share is not None]
        if shares and abs(math.fsum(shares) - 1.0) > 1e-9:
            raise InputError("wheels: the power_share of the driven wheels must sum to 1, got "
                             f"{' + '.join(f'{x:g}' for x in shares)} = {math.fsum(shares):.12g}", field="wheels")
        if self.links is not None:
            object.__setattr__(self, "links", _whole(self.links, "drive.links", 3))
        if self.slack_tension is not None:
            object.__setattr__(self, "slack_tension",
                               _finite(self.slack_tension, "drive.slack_tension", positive=True))
        ratio = _finite(self.slack_sag_ratio, "drive.slack_sag_ratio")
        if not 0 < ratio <= 0.2:
            raise InputError(f"drive.slack_sag_ratio must lie in (0, 0.2], got {ratio:g}",
                             field="drive.slack_sag_ratio")
        limit = _finite(self.elongation_limit, "drive.elongation_limit")
        if not 0 < limit <= 0.1:
            raise InputError(f"drive.elongation_limit must lie in (0, 0.1], got {limit:g}",
                             field="drive.elongation_limit")
        if self.required_static_safety is not None:
            _finite(self.required_static_safety, "drive.required_static_safety", positive=True)
        if self.wear_coefficient is not None:
            _finite(self.wear_coefficient, "drive.wear_coefficient", positive=True)

    # ------------------------------------------------------------------ editing

    def input(self, table: str) -> Any:
        """The value of a further input table ``[table]`` (one an analysis part declared with
        :func:`chaindrive.drive.schema.register_table`), or ``None`` when the drive has none."""
        return dict(self.extra_inputs).get(table)
    def with_wheel(self, name: str, **changes: Any) -> Drive:
        """A copy of the drive with the wheel ``name`` changed (``teeth=21``, ...)."""
        w = self.wheel(name)
        new = dataclasses.replace(w, **changes)
        return dataclasses.replace(self, wheels=tuple(new if x is w else x for x in self.wheels))

    def replace(self, **changes: Any) -> Drive:
        """A copy of the drive with ``changes`` (same as :func:`dataclasses.replace`)."""
        return dataclasses.replace(self, **changes)

    # ------------------------------------------------------------------ direct quantities
    def wheel(self, name: str, what: str = "wheel") -> Wheel:
        """The wheel called ``name``."""
        for w in self.wheels:
            if w.name == name:
                return w
        raise InputError(f"{what}: no wheel named {name!r}; wheels: {', '.join(w.name for w in self.wheels)}",
                         field=what)

    def wheel_index(self, name: str) -> int:
        """Index of the wheel called ``name`` in chain order."""
        return self.wheels.index(self.wheel(name))

    @property
    def wheel_names(self) -> tuple[str, ...]:
        return tuple(w.name for w in self.wheels)

    @property
    def driving_index(self) -> int:
        return next(i for i, w in enumerate(self.wheels) if w.driving)

    @property
    def driving_wheel(self) -> Wheel:
        return self.wheels[self.driving_index]

    @property
    def pitch(self) -> float:
        """Chain pitch [m]."""
        return float(self.chain.pitch)

    @property
    def bar_diameter(self) -> float | None:
        """Bar diameter of a round link chain [m]; ``None`` for roller chains."""
        return self.chain.bar_diameter if self.chain.is_link_chain else None

    @property
    def mass_per_length(self) -> float:
        """Chain mass per length [kg/m]; :class:`InputError` when the chain has none."""
        q = self.chain.mass_per_length
        if q is None:
            raise InputError(f"chain {self.chain.name!r} has no mass_per_length; give it in the "
                             "[chain] table of the project", field="chain.mass_per_length")
        return float(q)

    def small_sprocket_speed(self) -> float:
        """Speed of the fastest toothed wheel [rad/s]: ``ω z_driving / z_min`` (the small sprocket of a
        two-sprocket drive; the driving wheel's speed when wheels have no teeth)."""
        z0 = self.driving_wheel.teeth
        teeth = [w.teeth for w in self.wheels if w.teeth is not None]
        if z0 is None or not teeth:
            return float(self.speed)
        return float(self.speed) * z0 / min(teeth)

    @property
    def static_safety_required(self) -> float:
        """Required static safety ``[s]`` (:func:`chaindrive.loads.static_safety`): the drive's
        ``required_static_safety``, else 3.5 for a round link chain and, for a roller chain,
        Chernavsky et al.'s Table 7.19 at the chain's pitch and the small sprocket's speed
        (:func:`chaindrive.loads.required_static_safety_table`; docs/design.md, "One static safety")."""
        if self.required_static_safety is not None:
            return float(self.required_static_safety)
        from ..loads import required_static_safety_for

        return required_static_safety_for(self.chain.is_link_chain, self.pitch, self.small_sprocket_speed())

    def pitch_radii(self) -> np.ndarray:
        """Pitch radius of every wheel in chain order [m]."""
        return np.array([w.pitch_radius(self.chain) for w in self.wheels])

    def chain_speed(self) -> float:
        """Mean chain speed [m/s]: sides per turn × pitch × ω / 2π."""
        w = self.driving_wheel
        return _mean_chain_speed(w.sides_per_turn(self.chain), self.pitch, self.speed)

    def angular_velocities(self) -> np.ndarray:
        """Mean angular velocity of every wheel [rad/s]."""
        v = self.chain_speed()
        out = []
        for w in self.wheels:
            n = w.sides_per_turn(self.chain)
            out.append(2 * math.pi * v / (n * self.pitch) if n else v / w.pitch_radius(self.chain))
        return np.array(out)

    def speed_ratio(self) -> float:
        """Driving over slowest driven (toothed, non-idler) wheel speed [-]; 1 without one."""
        om = self.angular_velocities()
        others = [float(o) for w, o in zip(self.wheels, om, strict=True)
                  if w.teeth is not None and w.kind != "idler" and not w.driving]
        return float(self.speed) / min(others) if others else 1.0

    def torque(self) -> float:
        """Torque on the driving wheel without service factor [N·m]."""
        return self._torque_and_power()[0]

    def power(self) -> float:
        """Transmitted power without service factor [W]."""
        return self._torque_and_power()[1]

    def _torque_and_power(self) -> tuple[float, float]:
        """(torque [N·m], power [W]) on the driving wheel: the one the load gives, the other at the drive's speed."""
        torque, power = self.load.torque, self.load.power
        if torque is not None:
            return float(torque), _power_from_torque(float(torque), self.speed)
        if power is None:  # refused by Load(); the check narrows the type
            raise InputError("load: give exactly one of power and torque", field="load")
        return _torque_from_power(float(power), self.speed), float(power)

    def design_power(self) -> float:
        """Power times service factor [W]."""
        return self.power() * self.load.service_factor

    def power_shares(self) -> np.ndarray:
        """Share of the power taken off at every wheel, in chain order [-] (sum 1).

        The given ``power_share`` of each wheel; when none is given, all of it at the wheel
        the tight span leaves (the driven wheel of a two-wheel drive).
        """
        if any(w.power_share is not None for w in self.wheels):
            return np.array([w.power_share or 0.0 for w in self.wheels])
        k, n = self.driving_index, len(self.wheels)
        out = np.zeros(n)
        out[(k - 1) % n if self.travel == "ccw" else (k + 1) % n] = 1.0
        return out

    def _repr_html_(self) -> str:
        """Notebook display: the drive's data with units and its drawing to scale
        (formatted by :func:`chaindrive.workflows.notebook.html_of`)."""
        return view("html", self)

    def is_two_wheel(self) -> bool:
        """Two toothed wheels and nothing else (the two-wheel hull model and its centre distance for the
        links apply; more wheels: :func:`chaindrive.layout.chain_length_loop`)."""
        return len(self.wheels) == 2 and all(w.teeth is not None for w in self.wheels)

    def inputs(self) -> dict[str, Any]:
        """The drive's inputs, JSON-ready, SI units (for reports and results files)."""
        from .._results import jsonable

        return {
            "name": self.name,
            "description": self.description,
            "chain": self.chain.to_dict() if hasattr(self.chain, "to_dict") else str(self.chain),
            "speed": float(self.speed),
            "travel": self.travel,
            "load": dataclasses.asdict(self.load),
            "wheels": [jsonable(dataclasses.asdict(w)) for w in self.wheels],
            "tensioner": None if self.tensioner is None else jsonable(dataclasses.asdict(self.tensioner)),
            "guides": [dataclasses.asdict(g) for g in self.guides],
            "links": self.links,
            "slack_tension": self.slack_tension,
            "slack_sag_ratio": self.slack_sag_ratio,
            "required_static_safety": self.static_safety_required,
            "elongation_limit": self.elongation_limit,
            "wear_coefficient": self.wear_coefficient,
            "contact": None if self.contact is None else dataclasses.asdict(self.contact),
            "track": None if self.track is None else dataclasses.asdict(self.track),
            "crawler": None if self.crawler is None else dataclasses.asdict(self.crawler),
            "fretting": None if self.fretting is None else dataclasses.asdict(self.fretting),
            "self_regulating": (None if self.self_regulating is None
                                else jsonable(self.self_regulating)),
            "conveyor": None if self.conveyor is None else dataclasses.asdict(self.conveyor),
            "adjustable": None if self.adjustable is None else dataclasses.asdict(self.adjustable),
        }



from chaindrive._finite import guard_public  # noqa: E402

# every public function and dataclass: NaN/inf in or out refused; a Drive is built from parts
# checked here, its own numbers by its __post_init__ (a study builds millions: no second pass)
guard_public(__name__, skip=("Drive",))
