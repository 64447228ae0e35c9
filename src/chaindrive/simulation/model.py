r"""Self-contained model description of a planar chain-drive simulation.

:class:`SimulationModel` holds everything the integrator needs in SI units: the chain
(pitch, link mass, axial stiffness and damping, roller radius, number of links), the
wheels (centre, teeth, inertia, how each is driven or loaded, tooth profile), an
optional tensioner (a wheel on a slide with mass, spring and damper), straight guides,
the contact law and gravity.

The tooth gap is the ISO 606 profile reduced to its two working features: a seating
arc of radius ``r_s`` centred on the pitch circle, spanning ``±ψ_s`` about the radial
direction with ``ψ_s = 70° − 45°/z`` (half the maximum ISO 606 roller seating angle
``α_max = 140° − 90°/z``), continued by straight flanks tangent to the arc up to the
tip height ``h_a`` above the pitch circle. In the gap's frame (``a`` radial offset from
the seat centre, ``b`` tangential) the penetration of a roller of radius ``r`` is

.. math::
    g = \begin{cases} \sqrt{a^2+b^2} - (r_s - r), & |b|\cos ψ_s + a \sin ψ_s \le 0\\
        -a\cos ψ_s + |b|\sin ψ_s - (r_s - r), & \text{otherwise}\end{cases}

continuous with a continuous normal across the arc/flank boundary; contact acts only for
``a < h_a``. Force: ``F_n = max(0, k_c g + c_c \dot g)``, friction
``F_t = −μ F_n \tanh(v_t / v_ε)`` (regularised Coulomb).

References
----------
ISO 606:2015, clause 8.3 (tooth form: seating radius ``r_i = 0.505 d_1``, roller
seating angle ``α = 140° − 90°/z`` max, tip diameter range).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .._validation import check_positive
from ..errors import InputError

__all__ = ["SimWheel", "SimTensioner", "SimGuide", "SimulationModel", "roller_example",
           "AXIAL_STIFFNESS_16B"]

#: Axial stiffness ``EA`` [N] of an ISO 606 16B roller-chain link, order-of-magnitude
#: value: plate steel alone gives ``E A_plates = 2.1e11 * 2 * (h - d_pin) t ≈ 2e8 N``
#: (16B: plate height 21.1 mm, pin 8.3 mm, plates 4 mm thick); pin-bush-plate contact
#: compliance roughly halves it. NOT checked against a published measurement (the
#: model follows Pedersen, Hansen & Ambrósio, Multibody Syst. Dyn. 12 (2004) 285-301:
#: rollers as mass particles, links as spring-dampers). Pass ``axial_stiffness=`` to
#: use a measured value.
AXIAL_STIFFNESS_16B = 1.0e8

_MODES = ("speed", "torque", "free")


@dataclass
class SimWheel:
    """A sprocket of the simulated drive.

    Parameters
    ----------
    centre : (float, float)
        Centre [m].
    teeth : int
        Number of teeth ``z >= 3``.
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
    name : str
    """

    centre: tuple[float, float]
    teeth: int
    inertia: float = 0.05
    mode: str = "free"
    angular_velocity: float = 0.0
    ramp_time: float = 0.0
    torque: float = 0.0
    damping: float = 0.0
    name: str = ""

    def __post_init__(self):
        if self.mode not in _MODES:
            raise InputError(f"wheel mode must be one of {', '.join(_MODES)}, got {self.mode!r}")
        if int(self.teeth) != self.teeth or self.teeth < 3:
            raise InputError(f"wheel teeth must be a whole number >= 3, got {self.teeth!r}")
        check_positive("inertia", self.inertia)
        self.centre = (float(self.centre[0]), float(self.centre[1]))

    def pitch_radius(self, pitch: float) -> float:
        """``R = p / (2 sin(π/z))`` [m]."""
        return pitch / (2.0 * math.sin(math.pi / self.teeth))


@dataclass
class SimTensioner:
    """A wheel carried on a straight slide by a spring and damper.

    Parameters
    ----------
    wheel : int
        Index of the wheel it carries (in ``SimulationModel.wheels``).
    direction : (float, float)
        Direction of the slide (normalised), the way the wheel moves to take up slack.
    mass : float
        Mass moving with the slide [kg].
    stiffness : float
        Spring stiffness [N/m].
    damping : float
        Damper [N s/m].
    preload : float
        Spring force at the assembly position [N] (pushes along ``direction``).
    """

    wheel: int
    direction: tuple[float, float]
    mass: float
    stiffness: float
    damping: float = 0.0
    preload: float = 0.0


@dataclass
class SimGuide:
    """A straight guide (line segment); the chain runs on its left side (start → end).

    Parameters
    ----------
    start, end : (float, float)
        End points [m] of the guide line on which the roller *surfaces* slide.
    """

    start: tuple[float, float]
    end: tuple[float, float]


@dataclass
class SimulationModel:
    """Planar chain drive for :func:`chaindrive.simulation.simulate`.

    The chain is a closed loop of ``links`` point-mass pins (hinge centres, each
    carrying one link's mass ``link_mass``) joined by axial spring-dampers; wheels in
    the order the chain passes them, counter-clockwise around the loop.

    Parameters
    ----------
    pitch : float
        Chain pitch [m].
    links : int
        Number of links (pins) in the closed loop.
    link_mass : float
        Mass of one link (``q p``) [kg].
    axial_stiffness : float
        ``EA`` of the chain [N]; a link's spring is ``k = EA / p``.
    link_damping_ratio : float
        Damping ratio of one link's axial oscillator (``c = 2ζ sqrt(k m)``).
    roller_radius : float
        Roller (or bearing pin) radius [m].
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
        Tooth seating radius [m]; default ISO 606 ``0.505 d_1``.
    tip_height : float or None
        Tooth tip above the pitch circle [m]; default the middle of the ISO 606 range.
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

    def __post_init__(self):
        for name in ("pitch", "link_mass", "axial_stiffness", "roller_radius",
                     "contact_stiffness"):
            check_positive(name, getattr(self, name))
        if int(self.links) != self.links or self.links < 4:
            raise InputError(f"links must be a whole number >= 4, got {self.links!r}")
        if len(self.wheels) < 2:
            raise InputError(f"a drive needs at least 2 wheels, got {len(self.wheels)}")
        if self.roller_radius >= 0.5 * self.pitch:
            raise InputError(f"roller_radius must be < pitch/2 = {0.5 * self.pitch:g} m, "
                             f"got {self.roller_radius:g}")
        if not 0.0 <= self.prestrain < 0.01:
            raise InputError(f"prestrain must be in [0, 0.01), got {self.prestrain!r}")
        if self.tensioner is not None and not 0 <= self.tensioner.wheel < len(self.wheels):
            raise InputError(f"tensioner.wheel must be in 0..{len(self.wheels) - 1}")

    # derived quantities -------------------------------------------------------------
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
        """Seating radius ``r_s`` [m] (ISO 606: ``0.505 d_1``)."""
        return self.seat_radius if self.seat_radius is not None else 1.01 * self.roller_radius

    def tip(self, teeth: int) -> float:
        """Tip height above the pitch circle [m] (mid ISO 606 range: ``(p(1.125 − 0.8/z) − d_1)/2``)."""
        if self.tip_height is not None:
            return self.tip_height
        return 0.5 * (self.pitch * (1.125 - 0.8 / teeth) - 2.0 * self.roller_radius)

    def pitch_radii(self) -> np.ndarray:
        """Pitch radii of the wheels [m]."""
        return np.array([w.pitch_radius(self.pitch) for w in self.wheels])

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


def roller_example(*, chain: str = "16B", teeth: int = 17, links: int = 100,
                   angular_velocity: float = 20.0, load_torque: float = 200.0,
                   ramp_time: float = 0.2, gravity: bool = True,
                   **kwargs) -> SimulationModel:
    """Two equal sprockets, the driver (wheel 0) on the left at prescribed speed.

    The centre distance is the exact polygon one for ``links`` (``(N − z)/2 · p`` for
    equal wheels); the tight span is the upper one.

    Examples
    --------
    >>> m = roller_example()
    >>> m.links, m.wheels[0].teeth, round(m.wheels[1].centre[0], 4)
    (100, 17, 1.0541)
    """
    from .. import chains

    ch = chains.get(chain)
    p = ch.pitch
    a = 0.5 * (links - teeth) * p
    r_w = p / (2 * math.sin(math.pi / teeth))
    inertia = 0.5 * 7800 * math.pi * r_w**4 * 0.02  # steel disc, 20 mm thick
    wheels = [
        SimWheel((0.0, 0.0), teeth, inertia, "speed", angular_velocity, ramp_time, name="driver"),
        SimWheel((a, 0.0), teeth, inertia, "free", torque=-load_torque, name="driven"),
    ]
    opts = dict(pitch=p, links=links, link_mass=ch.mass_per_length * p,
                axial_stiffness=AXIAL_STIFFNESS_16B * (p / 0.0254) ** 2,
                roller_radius=0.5 * ch.roller_diameter, wheels=wheels,
                gravity=(0.0, -9.81) if gravity else (0.0, 0.0))
    opts.update(kwargs)
    return SimulationModel(**opts)
