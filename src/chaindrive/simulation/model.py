r"""Self-contained model description of a planar chain-drive simulation.

:class:`SimulationModel` holds everything the integrator needs in SI units: the chain
(pitch, link mass, axial stiffness and damping, roller radius, number of links), the
wheels (centre, teeth, inertia, how each is driven or loaded, tooth profile), an
optional tensioner (a wheel on a slide with mass, spring and damper), straight guides,
the contact law and gravity.

The tooth gap of a sprocket is ISO 606's minimum tooth form: a seating arc of radius
``r_s`` centred on the pitch circle, spanning ``±ψ_s`` about the radial direction with
``ψ_s = 70° − 45°/z`` (half the maximum roller seating angle ``α_max = 140° − 90°/z``),
continued tangentially by the convex flank arc ``r_e,max = 0.008 d_1 (z² + 180)``
(:func:`iso_flank`) up to the tip circle ``R + h_a`` (middle of the tip-diameter range),
ending in the tooth corner ``T``. In the gap's frame (``a`` radial offset from the seat
centre, ``b`` tangential) the penetration of a roller of radius ``r`` is

.. math::
    g = \begin{cases} \sqrt{a^2+b^2} - (r_s - r), & |b|\cos ψ_s + a \sin ψ_s \le 0\\
        (r_e + r) - |q - C_e|, & \text{on the flank}\\
        r - |q - T|, & \text{past the flank}\end{cases}

continuous with a continuous normal across the seat/flank boundary
(``tooth_flank="straight"``: the earlier straight flank, truncated where the roller
centre reaches ``h_a``; pocket wheels use it). Force: ``F_n = max(0, k_c g + c_c \dot g)``,
friction ``F_t = −μ F_n sat(v_t / v_ε)`` (regularised Coulomb).

Round link chains (``bar_diameter`` given) on pocket wheels: the pins are the hinge
points (centre of the horizontal link's end bar, where it interlocks with the vertical
link); the links alternate the rest lengths ``t + d`` (even links, horizontal, lying in
a pocket) and ``t − d`` (odd links, vertical); seated, the hinges are the vertices of
the bi-regular polygon of Dolipiński et al. eq. (6) (pitch radius ``R``, central angles ``δ1``,
``δ2``, ``δ1 + δ2 = 2π/z`` for ``z`` pockets). Each hinge has a seat of the same
arc-and-flank form: arc ``r_s = 0.505 d`` round the hinge (the pocket's end arc of
radius ``d/2 + c`` in :mod:`chaindrive.geometry.pocket_wheel`, ``c = 0.005 d``), flanks
at ``ψ_s = 90° − max(δ1/2 + h_a/(2(t+d)), δ2/2 + h_a/(2(t−d)))`` up to
``h_a = d/2`` (the tip circle ``R + d/2`` of :class:`~chaindrive.geometry.PocketWheel`).
See :func:`link_seat_profile` for the reasoning and the simplifications.

References
----------
ISO 606:2015, clause 8.3 (tooth form: seating radius ``r_i = 0.505 d_1``, roller
seating angle ``α = 140° − 90°/z`` max, tip diameter range).
Dolipiński et al., eqs (6)-(9) (bi-regular polygon of a round link chain on a pocket wheel).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from .._validation import check_nonnegative, check_positive
from ..drive.model import Tensioner, Wheel, sides_per_turn
from ..errors import InputError

if TYPE_CHECKING:
    from ..drivetrain.coupling import FluidCoupling
    from ..drivetrain.motor import Motor
    from ..geometry.sprocket import IsoToothForm

from .profiles import (  # noqa: F401 - re-exported: chaindrive.simulation.model is where they were
    AXIAL_STIFFNESS_16B,
    AXIAL_STIFFNESS_LINK_PER_D2,
    iso_flank,
    link_chain_axial_stiffness,
    link_seat_profile,
)

__all__ = ["SimWheel", "SimTensioner", "SimGuide", "SimulationModel", "iso_flank", "link_seat_profile",
           "link_chain_axial_stiffness", "AXIAL_STIFFNESS_16B"]


def __getattr__(name: str) -> Any:
    """``roller_example`` and ``link_example`` live in :mod:`chaindrive.simulation.examples`:
    deprecated aliases here (removed in the next release)."""
    if name in ("roller_example", "link_example"):
        import importlib

        from .._deprecation import warn_renamed

        warn_renamed(f"{__name__}.{name}", f"chaindrive.simulation.{name}")
        return getattr(importlib.import_module("chaindrive.simulation"), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")

_MODES = ("speed", "torque", "free", "motor")


@dataclass
class SimWheel:
    """A wheel of the simulated drive: the drive's own description plus its dynamics.

    The geometry (name, teeth, centre, side, running diameter of a toothless idler) is the
    :class:`chaindrive.drive.Wheel` it simulates, defined once there; this class adds only
    what the simulation needs. Build one from coordinates with :meth:`at`.

    Parameters
    ----------
    wheel : chaindrive.drive.Wheel
        The wheel's description (``position`` is the centre in the simulation's frame [m]).
    inertia : float
        Moment of inertia about the axis [kg m²].
    mode : {"speed", "torque", "free"}
        ``"speed"``: angular velocity prescribed (``angular_velocity``, ramped linearly
        from 0 over ``ramp_time``); ``"torque"``/``"free"``: free rotation under the
        chain and the applied ``torque``.
    angular_velocity : float
        Prescribed speed [rad/s] (mode ``"speed"``); positive counter-clockwise.
    ramp_time : float
        Ramp of the prescribed speed [s]; 0 starts at full speed.
    torque : float
        Applied torque [N m] (counter-clockwise positive): a load is negative.
    damping : float
        Viscous bearing damping [N m s/rad].
    motor : chaindrive.drivetrain.motor.Motor, optional
        Mode ``"motor"``: the wheel is driven by this motor (Kloss curve, reduced to the
        wheel; add the motor's reduced inertia to ``inertia``).
    stop_time : float
        From this time [s] the motor is off (mode ``"motor"``) or the prescribed speed
        falls linearly to 0 over ``stop_ramp`` [s] (mode ``"speed"``); 0: never.
    stop_ramp : float
        [s].
    ripple : float
        Relative amplitude of a torque (mode ``"motor"``) or speed (mode ``"speed"``)
        ripple ``1 + a sin(Ω t)``, ``|a| < 1``.
    ripple_frequency : float
        ``Ω`` [rad/s].
    coupling : chaindrive.drivetrain.coupling.FluidCoupling, optional
        Mode ``"motor"``: the motor drives the wheel through this constant-fill fluid
        coupling (reduced to the wheel); the motor rotor and the coupling's primary are
        then their own degree of freedom of inertia ``motor_inertia`` (not in
        ``inertia``).
    motor_inertia : float
        With ``coupling``: motor rotor and coupling primary reduced to the wheel [kg m²], > 0.

    Notes
    -----
    A toothless idler (roller chains) is a drive wheel without teeth whose ``diameter`` is
    the circle on which the roller centres run (the rim diameter plus the roller
    diameter); the roller rests on the rim by penalty contact with friction (no seats).
    An idler with ``side = -1`` runs on the back of the chain (wrapped clockwise).
    """

    wheel: Wheel
    inertia: float = 0.05
    mode: str = "free"
    angular_velocity: float = 0.0
    ramp_time: float = 0.0
    torque: float = 0.0
    damping: float = 0.0
    motor: Motor | None = None
    stop_time: float = 0.0
    stop_ramp: float = 0.0
    ripple: float = 0.0
    ripple_frequency: float = 0.0
    coupling: FluidCoupling | None = None
    motor_inertia: float = 0.0

    def __post_init__(self) -> None:
        if (self.mode == "motor") != (self.motor is not None):
            raise InputError("a wheel in mode 'motor' needs its motor (and a motor needs mode 'motor')",
                             field="motor")
        if self.coupling is not None:
            if self.motor is None:
                raise InputError("a fluid coupling needs a motor (mode 'motor') in front of it", field="coupling")
            check_positive("motor_inertia", self.motor_inertia, "kg m^2")
        else:
            check_nonnegative("motor_inertia", self.motor_inertia, "kg m^2")
        check_nonnegative("stop_time", self.stop_time, "s")
        check_nonnegative("stop_ramp", self.stop_ramp, "s")
        if not abs(float(self.ripple)) < 1:
            raise InputError(f"ripple must lie in (-1, 1), got {self.ripple!r}", field="ripple")
        check_nonnegative("ripple_frequency", self.ripple_frequency, "rad/s")
        if not isinstance(self.wheel, Wheel):
            raise InputError(f"SimWheel.wheel must be a chaindrive.drive.Wheel, got {type(self.wheel).__name__}")
        if self.mode not in _MODES:
            raise InputError(f"wheel mode must be one of {', '.join(_MODES)}, got {self.mode!r}")
        check_positive("inertia", self.inertia)

    @classmethod
    def at(cls, centre: tuple[float, float], teeth: int, inertia: float = 0.05, mode: str = "free",
           angular_velocity: float = 0.0, ramp_time: float = 0.0, torque: float = 0.0, damping: float = 0.0,
           name: str = "", plain_radius: float | None = None, side: int = 1,
           kind: str | None = None) -> SimWheel:
        """A simulated wheel at ``centre`` [m] with ``teeth`` (or a toothless idler of
        running radius ``plain_radius`` [m], ``teeth`` then ignored); the rest as the class."""
        if side not in (1, -1):
            raise InputError(f"wheel side must be 1 (inside the loop) or -1 (outside idler), got {side!r}")
        if plain_radius is not None:
            check_positive("plain_radius", plain_radius)
            wheel = Wheel(name, kind or "idler", None, (float(centre[0]), float(centre[1])),
                          diameter=2.0 * float(plain_radius), side=side)
        else:
            if int(teeth) != teeth or teeth < 3:
                raise InputError(f"wheel teeth must be a whole number >= 3, got {teeth!r}")
            wheel = Wheel(name, kind or "sprocket", int(teeth), (float(centre[0]), float(centre[1])), side=side)
        return cls(wheel, inertia, mode, angular_velocity, ramp_time, torque, damping)

    @property
    def name(self) -> str:
        return self.wheel.name

    @property
    def centre(self) -> tuple[float, float]:
        """Centre [m] (the wheel's position)."""
        return self.wheel.position

    @property
    def teeth(self) -> int:
        """Teeth; 3 for a toothless idler (not used: its path uses :meth:`path_teeth`)."""
        return 3 if self.wheel.teeth is None else int(self.wheel.teeth)

    @property
    def side(self) -> int:
        return int(self.wheel.side)

    @property
    def plain_radius(self) -> float | None:
        """Running radius of a toothless idler [m] (``None`` with teeth)."""
        if self.wheel.teeth is not None:
            return None
        if self.wheel.diameter is None:  # Wheel() refuses this; the check narrows the type
            raise InputError(f"wheel {self.wheel.name!r}: a toothless idler needs its diameter (> 0 m)",
                             field="diameter")
        return 0.5 * float(self.wheel.diameter)

    def moved(self, centre: tuple[float, float]) -> SimWheel:
        """A copy at another centre [m]."""
        return dataclasses.replace(self, wheel=dataclasses.replace(self.wheel, position=(float(centre[0]),
                                                                                     float(centre[1]))))

    def pitch_radius(self, pitch: float) -> float:
        """``R = p / (2 sin(π/z))`` [m]; a toothless idler: ``plain_radius``."""
        if self.plain_radius is not None:
            return float(self.plain_radius)
        return pitch / (2.0 * math.sin(math.pi / self.teeth))

    def path_teeth(self, pitch: float) -> float:
        """Links per turn on the pitch circle: ``z``, or ``π / asin(p / 2R)`` (toothless).

        A toothless idler holds the rollers at chord ``p`` on its running circle, so each
        link spans ``2 asin(p / 2R)``; the assembly treats it as a wheel of that many
        (non-integer) teeth.
        """
        if self.plain_radius is None:
            return float(self.teeth)
        return math.pi / math.asin(pitch / (2.0 * self.plain_radius))


@dataclass
class SimTensioner:
    """A wheel carried on a straight slide by a spring and damper.

    The tensioner itself (mass and stiffness reduced to its axis, direction of travel) is
    the drive's :class:`chaindrive.drive.Tensioner`; this class adds the index of the
    simulated wheel it carries and what only the simulation needs. Build one from numbers
    with :meth:`at`.

    Parameters
    ----------
    tensioner : chaindrive.drive.Tensioner
        Its description: ``mass`` [kg], ``stiffness`` [N/m], ``direction`` (the way the
        wheel moves to take up slack).
    wheel : int
        Index of the wheel it carries (in ``SimulationModel.wheels``).
    damping : float
        Damper [N s/m].
    preload : float
        Spring force at the assembly position [N] (pushes along ``direction``).
    """

    tensioner: Tensioner
    wheel: int
    damping: float = 0.0
    preload: float = 0.0

    @classmethod
    def at(cls, wheel: int, direction: tuple[float, float], mass: float, stiffness: float,
           damping: float = 0.0, preload: float = 0.0, name: str = "") -> SimTensioner:
        """A slide carrying wheel ``wheel`` (index), moving along ``direction``."""
        return cls(Tensioner(name, mass, stiffness, direction=(float(direction[0]), float(direction[1]))), int(wheel),
                   damping, preload)

    @property
    def direction(self) -> tuple[float, float]:
        return self.tensioner.direction

    @property
    def mass(self) -> float:
        return float(self.tensioner.mass)

    @property
    def stiffness(self) -> float:
        return float(self.tensioner.stiffness)


def _required(value: float | None, chain: str, field: str) -> float:
    if value is None:
        raise InputError(f"chain {chain!r} has no {field}; the simulation needs it (give it in the [chain] table)")
    return float(value)


def _mass_per_length(chain: Any) -> float:
    return _required(chain.mass_per_length, chain.name, "mass_per_length")


@dataclass
class SimGuide:
    """A straight guide (line segment); the chain runs on its left side (start → end).

    A conveyor's pan is a guide under a strand with its own ``friction`` and,
    under the carrying strand, the material each pin scrapes along it.

    Parameters
    ----------
    start, end : (float, float)
        End points [m] of the guide line on which the roller *surfaces* slide.
    friction : float, optional
        Coulomb coefficient chain–guide; default the model's ``friction``.
    material_mass : float
        Material pushed along the guide by each pin in contact [kg] (``q_m`` times
        the mean link length); its weight component along the guide, its friction
        (``material_friction`` times its weight normal to the guide) and its inertia
        act on that pin.
    material_friction : float
    """

    start: tuple[float, float]
    end: tuple[float, float]
    friction: float | None = None
    material_mass: float = 0.0
    material_friction: float = 0.0


@dataclass
class SimulationModel:
    """Planar chain drive for :func:`chaindrive.simulation.simulate`.

    The chain is a closed loop of ``links`` point-mass pins (hinge centres, each
    carrying one link's mass ``link_mass``) joined by axial spring-dampers; wheels in
    the order the chain passes them, counter-clockwise around the loop. A roller chain
    by default; a round link chain on pocket wheels when ``bar_diameter`` is given
    (links alternate the rest lengths ``t + d``, ``t − d``; seats at the vertices of the
    bi-regular polygon of Dolipiński et al. eq. (6)).

    Parameters
    ----------
    pitch : float
        Chain pitch [m]; for a round link chain the inner link length ``t``.
    links : int
        Number of links (pins) in the closed loop; even for a round link chain.
    link_mass : float
        Mass of one link (``q p``, round link chain ``q t``) [kg].
    axial_stiffness : float
        ``EA`` of the chain [N]; a link's spring is ``k = EA / p`` (round link chain:
        ``EA / t`` for both kinds of link — each segment is one physical link).
    link_damping_ratio : float
        Damping ratio of one link's axial oscillator (``c = 2ζ sqrt(k m)``).
    roller_radius : float
        Roller (or bearing pin) radius [m]; for a round link chain the bar radius
        ``d/2`` (the horizontal link's end bar seated round the hinge).
    wheels : list of SimWheel
    contact_stiffness : float
        Roller-tooth penalty stiffness [N/m].
    contact_damping_ratio : float
        Damping ratio of the roller-tooth contact (``c_c = 2ζ sqrt(k_c m)``).
    friction : float
        Coulomb friction coefficient roller-tooth and roller-guide.
    friction_velocity : float
        Regularisation velocity ``v_ε`` of the friction law [m/s].
    seat_radius : float or None
        Tooth seating radius [m]; default ISO 606 ``0.505 d_1`` (round link chain:
        ``0.505 d``, the pocket's end arc with a clearance of ``0.005 d``).
    tip_height : float or None
        Tooth tip above the pitch circle [m]; default the middle of the ISO 606 range
        (round link chain: ``d/2``, see :func:`link_seat_profile`).
    tensioner : SimTensioner or None
    guides : list of SimGuide
    guide_stiffness : float
        Roller-guide penalty stiffness [N/m].
    gravity : (float, float)
        [m/s²].
    pretension : float
        Slack-side tension the assembly aims at when it adjusts the last wheel's centre
        (drives without tensioner) [N].
    prestrain : float
        Strain of the links as placed on the path (their rest length is
        ``pitch / (1 + prestrain)``): pretensions a chain between locked wheels by
        ``EA · prestrain`` without moving any wheel (used for anchored spans), 0 <= ε < 0.01.
    tooth_flank : {"arc", "straight"}
        Sprocket tooth flank: ``"arc"`` the ISO 606 convex flank arc ``r_e,max`` up to the
        tip circle (:func:`iso_flank`); ``"straight"`` a straight flank tangent to the seat,
        truncated where the roller centre reaches the tip height (the earlier model).
    bar_diameter : float or None
        Round link chain: bar diameter ``d`` [m], ``0 < d < t/2`` (``None``: roller
        chain). The wheels are then pocket wheels with ``teeth`` pockets.
    wheel_pitch : float or None
        Pitch the sprockets are cut for [m] (roller chains; ``None``: ``pitch``). A worn
        chain is ``pitch = p (1 + e)`` on wheels of ``wheel_pitch = p``: the chain is placed on
        its own pitch polygons (the rollers ridden out to ``R (1 + e)``), the tooth gaps are
        the wheels' (docs/life.md). ``pitch / 1.3 <= wheel_pitch <= pitch``.
    span_damping : float or None
        Transverse span damping rate ``α`` [1/s], ``>= 0`` (docs/simulation.md, "Span
        damping"): each pin feels ``−α m v_⊥``, ``v_⊥`` its velocity normal to the chord of
        its neighbours, so a span's transverse mode of angular frequency ``ω_n`` has the
        damping ratio ``α / (2 ω_n)``. ``None`` (default): ``α = 2 ζ Ω`` with the span
        damping ratio ``ζ`` = :data:`chaindrive.vibration.excitation.DAMPING_RATIO` of
        the resonance check at the drive's tooth frequency ``Ω`` (:meth:`tooth_frequency`),
        so a span mode in resonance with the teeth has the damping the analysis assumes
        (:meth:`span_damping_rate`); ``0``: undamped spans.
    """

    pitch: float
    links: int
    link_mass: float
    axial_stiffness: float
    roller_radius: float
    wheels: list[SimWheel]
    link_damping_ratio: float = 0.05
    contact_stiffness: float = 2.0e8
    contact_damping_ratio: float = 0.2
    friction: float = 0.1
    friction_velocity: float = 1.0e-3
    seat_radius: float | None = None
    tip_height: float | None = None
    tensioner: SimTensioner | None = None
    guides: list[SimGuide] = field(default_factory=list)
    guide_stiffness: float = 2.0e8
    gravity: tuple[float, float] = (0.0, -9.81)
    pretension: float = 200.0
    prestrain: float = 0.0
    tooth_flank: str = "arc"
    bar_diameter: float | None = None
    wheel_pitch: float | None = None
    span_damping: float | None = None

    def __post_init__(self):
        for name in ("pitch", "link_mass", "axial_stiffness", "roller_radius",
                     "contact_stiffness"):
            check_positive(name, getattr(self, name))
        from ..limits import MAX_LINKS

        if self.span_damping is not None:
            check_nonnegative("span_damping", self.span_damping, "1/s")

        if int(self.links) != self.links or not 4 <= self.links <= MAX_LINKS:
            raise InputError(f"links must be a whole number in [4, {MAX_LINKS}], got {self.links!r}")
        if len(self.wheels) < 2:
            raise InputError(f"a drive needs at least 2 wheels, got {len(self.wheels)}")
        if self.roller_radius >= 0.5 * self.pitch:
            raise InputError(f"roller_radius must be < pitch/2 = {0.5 * self.pitch:g} m, "
                             f"got {self.roller_radius:g}")
        if self.bar_diameter is not None:
            check_positive("bar_diameter", self.bar_diameter)
            if self.bar_diameter >= 0.5 * self.pitch:
                raise InputError("bar_diameter must lie in (0, pitch/2) = "
                                 f"(0, {0.5 * self.pitch:g}) m for a round link chain, got "
                                 f"{self.bar_diameter:g}")
            if self.links % 2:
                raise InputError("a round link chain needs an even number of links "
                                 f"(horizontal and vertical alternate), got links = {self.links}")
            if self.roller_radius >= 0.5 * (self.pitch - self.bar_diameter):
                raise InputError("roller_radius (contact radius of a hinge) must be < (t - d)/2 "
                                 f"= {0.5 * (self.pitch - self.bar_diameter):g} m, got "
                                 f"{self.roller_radius:g}")
        if self.wheels[0].side != 1:
            raise InputError("wheel 0 (the driver) must lie inside the chain loop (side = 1)")
        for i, w in enumerate(self.wheels):
            if w.side != 1 and self.bar_diameter is not None:
                raise InputError(f"wheel {w.name or i!r}: outside idlers (side = -1) are "
                                 "supported for roller chains only")
            if w.plain_radius is None:
                continue
            if self.bar_diameter is not None:
                raise InputError(f"wheel {w.name or i!r}: toothless idlers (plain_radius) are "
                                 "supported for roller chains only")
            if w.plain_radius <= 0.5 * self.pitch + self.roller_radius:
                raise InputError(f"wheel {w.name or i!r}: plain_radius must exceed pitch/2 + "
                                 f"roller radius = {0.5 * self.pitch + self.roller_radius:g} m, "
                                 f"got {w.plain_radius:g}")
        if self.tooth_flank not in ("arc", "straight"):
            raise InputError(f"tooth_flank must be one of arc, straight, got {self.tooth_flank!r}")
        if self.wheel_pitch is not None:
            if self.bar_diameter is not None:
                raise InputError("wheel_pitch (a worn chain on its wheels) is for roller chains only",
                                 field="wheel_pitch")
            if not self.pitch / 1.3 <= self.wheel_pitch <= self.pitch:
                raise InputError(f"wheel_pitch must lie in [pitch/1.3, pitch] = [{self.pitch / 1.3:g}, "
                                 f"{self.pitch:g}] m (a chain worn by at most 30 %), got {self.wheel_pitch!r}",
                                 field="wheel_pitch")
        if not 0.0 <= self.prestrain < 0.01:
            raise InputError(f"prestrain must be in [0, 0.01), got {self.prestrain!r}")
        if self.tensioner is not None and not 0 <= self.tensioner.wheel < len(self.wheels):
            raise InputError(f"tensioner.wheel must be in 0..{len(self.wheels) - 1}")

    # derived quantities -------------------------------------------------------------
    def tooth_frequency(self) -> float:
        """Nominal tooth frequency ``Ω`` [rad/s]: seats passing per second times ``2π`` on the
        fastest driven wheel (a ``"speed"`` wheel's prescribed ``ω``, a ``"motor"`` wheel's
        synchronous speed), ``Ω = n_s ω`` with ``n_s`` the seats per turn; 0 when no wheel
        has a nominal speed."""
        best = 0.0
        for w in self.wheels:
            if w.teeth is None or w.plain_radius is not None:
                continue
            if w.mode == "speed":
                omega = abs(float(w.angular_velocity))
            elif w.mode == "motor" and w.motor is not None:
                omega = abs(float(w.motor.synchronous_speed))
            else:
                continue
            best = max(best, self.seats_per_turn(int(w.teeth)) * omega)
        return best

    def span_damping_rate(self) -> float:
        """The span damping rate ``α`` [1/s] the integrators use: ``span_damping`` when given,
        else ``2 ζ Ω`` (:func:`chaindrive.vibration.excitation.span_damping_rate` at
        :meth:`tooth_frequency`)."""
        if self.span_damping is not None:
            return float(self.span_damping)
        from ..vibration.excitation import span_damping_rate

        return span_damping_rate(self.tooth_frequency())

    @property
    def is_link_chain(self) -> bool:
        """True for a round link chain on pocket wheels (``bar_diameter`` given)."""
        return self.bar_diameter is not None

    @property
    def link_lengths(self) -> tuple[float, float]:
        """Rest lengths [m] of the even and the odd links as placed: ``(p, p)`` or ``(t + d, t − d)``."""
        if self.bar_diameter is None:
            return self.pitch, self.pitch
        return self.pitch + self.bar_diameter, self.pitch - self.bar_diameter

    def seats_per_turn(self, teeth: int) -> int:
        """Seated links per turn of a wheel (:func:`chaindrive.drive.model.sides_per_turn`)."""
        return sides_per_turn(teeth, self.is_link_chain)

    def central_angles(self, teeth: int) -> tuple[float, float]:
        """Central angles [rad] of a seated even and odd link: ``2π/z`` each, or ``δ1``, ``δ2``.

        Round link chain: Dolipiński et al. eqs (7)-(9), ``δ1 + δ2 = 2π/z``.
        """
        if self.bar_diameter is None:
            a = 2.0 * math.pi / teeth
            return a, a
        from ..geometry.polygon import link_chain_central_angles

        d1, d2 = link_chain_central_angles(self.pitch, self.bar_diameter, teeth)
        return float(d1), float(d2)

    def seat_angle(self, teeth: int) -> float:
        """Half seating angle ``ψ_s`` [rad] of the seat/flank profile.

        Sprocket: ``α_max / 2 = 70° − 45°/z`` of ISO 606's minimum tooth gap
        (:func:`chaindrive.geometry.sprocket.iso_tooth_form`); pocket wheel:
        :func:`link_seat_profile`.
        """
        if self.bar_diameter is None:
            return 0.5 * self.tooth_form(teeth).seat_angle
        return link_seat_profile(self.pitch, self.bar_diameter, teeth, self.tip(teeth))[0]

    def tooth_form(self, teeth: int) -> IsoToothForm:
        """ISO 606 minimum tooth gap of a ``teeth``-tooth sprocket of this chain (roller chains).

        :func:`chaindrive.geometry.sprocket.iso_tooth_form` (the one ISO 606 tooth form of
        the package, the sprocket outline's too) with the model's seat radius and the tip
        circle in the middle of ISO 606's tip-diameter range (or ``tip_height``).
        """
        from ..geometry.sprocket import iso_tooth_form, tip_diameter_limits

        d1 = 2.0 * self.roller_radius
        p = self.tooth_pitch
        if self.tip_height is not None:
            tip = p / math.sin(math.pi / teeth) + 2.0 * self.tip_height
        elif teeth >= 9:
            tip = 0.5 * float(sum(tip_diameter_limits(p, teeth, d1)))
        else:  # below ISO 606 Annex A: the same clause 5.5 formula, extrapolated
            tip = p / math.sin(math.pi / teeth) + p * (1.125 - 0.8 / teeth) - d1
        return iso_tooth_form(p, teeth, d1, seat_radius=self.seat, tip_diameter=tip)

    @property
    def tooth_pitch(self) -> float:
        """Pitch the sprockets are cut for [m]: ``wheel_pitch``, else the chain's ``pitch``."""
        return self.pitch if self.wheel_pitch is None else float(self.wheel_pitch)

    def seat_radii(self) -> np.ndarray:
        """Radius of every wheel's seat centres [m]: the pitch radius of the wheel's own pitch
        (:attr:`tooth_pitch`; :meth:`pitch_radii` is the chain's polygon)."""
        radii = self.pitch_radii()
        if self.wheel_pitch is None:
            return radii
        return np.array([w.pitch_radius(self.tooth_pitch) if w.plain_radius is None else r
                         for w, r in zip(self.wheels, radii, strict=True)])

    @property
    def link_stiffness(self) -> float:
        """``k = EA / p`` [N/m]."""
        return self.axial_stiffness / self.pitch

    @property
    def link_damping(self) -> float:
        """``c = 2ζ sqrt(k m)`` [N s/m]."""
        return 2.0 * self.link_damping_ratio * math.sqrt(self.link_stiffness * self.link_mass)

    @property
    def contact_damping(self) -> float:
        """``c_c = 2ζ_c sqrt(k_c m)`` [N s/m]."""
        return 2.0 * self.contact_damping_ratio * math.sqrt(self.contact_stiffness * self.link_mass)

    @property
    def seat(self) -> float:
        """Seating radius ``r_s`` [m] (ISO 606: ``r_i,min = 0.505 d_1``; a pocket's end arc).

        From :func:`chaindrive.geometry.sprocket.seating_radius_limits` unless
        ``seat_radius`` is given.
        """
        if self.seat_radius is not None:
            return self.seat_radius
        from ..geometry.sprocket import seating_radius_limits

        return float(seating_radius_limits(2.0 * self.roller_radius)[0])

    def tip(self, teeth: int) -> float:
        """Tip height above the pitch circle [m].

        Sprocket: the middle of ISO 606's tip-diameter range,
        ``(p(1.125 − 0.8/z) − d_1)/2`` (:meth:`tooth_form`); pocket wheel ``d/2``.
        """
        if self.tip_height is not None:
            return self.tip_height
        if self.bar_diameter is not None:
            return 0.5 * self.bar_diameter
        form = self.tooth_form(teeth)
        return form.tip_radius - form.pitch_radius

    def pitch_radii(self) -> np.ndarray:
        """Pitch radii of the wheels [m] (pocket wheels: Dolipiński et al. eq. (6))."""
        if self.bar_diameter is None:
            return np.array([w.pitch_radius(self.pitch) for w in self.wheels])
        from ..geometry.polygon import link_chain_pitch_radius

        return np.array([float(link_chain_pitch_radius(self.pitch, self.bar_diameter, w.teeth))
                         for w in self.wheels])

    def signed_radii(self) -> np.ndarray:
        """Pitch radii [m] with the sign of the wrap: negative for outside idlers."""
        return self.pitch_radii() * np.array([float(w.side) for w in self.wheels])

    def omega_max(self) -> float:
        """Highest natural frequency of a pin [rad/s]: ``sqrt((4k + k_c)/m)``."""
        kc = max(self.contact_stiffness, self.guide_stiffness if self.guides else 0.0)
        return math.sqrt((4.0 * self.link_stiffness + kc) / self.link_mass)

    def stable_time_step(self, safety: float = 0.9) -> float:
        """Largest stable step of semi-implicit Euler [s].

        .. math:: Δt = s\\,\\frac{2}{ω_{max}}\\left(\\sqrt{1+ζ^2} - ζ\\right)

        with the damping ratio ``ζ`` of the stiffest oscillator.
        """
        om = self.omega_max()
        zeta = max(self.link_damping_ratio, self.contact_damping_ratio)
        return safety * 2.0 / om * (math.sqrt(1.0 + zeta * zeta) - zeta)

    def accurate_time_step(self, per_seat: int = 200, stable_steps: float = 15.0) -> float:
        """Default step of the linearly implicit integrator [s] (``method="implicit"``).

        .. math:: Δt = \\min\\left(\\frac{2π}{n_{per}\\, s\\, ω},\\; n_s Δt_{stable}\\right)

        ``per_seat`` steps per seat period ``2π/(s ω)`` (``s`` seats per turn of a driving
        wheel, ``ω`` its prescribed speed or its motor's synchronous speed): the seating
        of each roller, which sets the accuracy of the mean tension and speed, spread
        over ``per_seat`` steps; at most ``stable_steps`` explicit stable steps
        (:meth:`stable_time_step`), which keeps the explicit parts (the links' transverse
        stiffness ``S/p``, the bearings) inside their own stability limit. The rule is
        empirical: on the benchmark drive (16B, z = 17, 20 rad/s) the seat rule alone
        gives 92 µs, where the mean tight-side tension changes by 0.7 % against the halved
        step; the 100 m conveyor (108 kN) runs within 0.1 % of the explicit integrator
        at 500 µs (16 stable steps) and is off by 15 % at 1 ms (32), where the transverse
        stiffness of its links reaches its explicit limit ``2/ω``.

        Examples
        --------
        >>> from chaindrive.simulation import roller_example
        >>> m = roller_example(links=100, teeth=17, angular_velocity=20.0)
        >>> round(m.accurate_time_step() / m.stable_time_step(), 6)
        15.0
        """
        rates = [self.seats_per_turn(w.teeth) * abs(w.angular_velocity) for w in self.wheels
                 if w.mode == "speed" and w.plain_radius is None]
        rates += [self.seats_per_turn(w.teeth) * abs(w.motor.synchronous_speed) for w in self.wheels
                  if w.mode == "motor" and w.motor is not None and w.plain_radius is None]
        dt = stable_steps * self.stable_time_step()
        rate = max(rates, default=0.0)
        if rate > 0.0:
            dt = min(dt, 2.0 * math.pi / (per_seat * rate))
        return dt


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
