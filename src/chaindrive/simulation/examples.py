"""Ready-made simulation models: two-sprocket roller drive, two-pocket-wheel link drive."""

from __future__ import annotations

import math
from typing import Any

from .._validation import check_nonnegative
from ..errors import InputError
from .model import SimulationModel, SimWheel, _mass_per_length, _required
from .profiles import AXIAL_STIFFNESS_16B, link_chain_axial_stiffness

__all__ = ["roller_example", "link_example"]


def roller_example(*, chain: str = "16B", teeth: int = 17, links: int = 100,
                   angular_velocity: float = 20.0, load_torque: float = 200.0,
                   ramp_time: float = 0.2, gravity: bool = True,
                   **kwargs: Any) -> SimulationModel:
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

    # the examples run counter-clockwise with the tight span on top; a reversed drive
    # is a project with travel = "cw"
    check_nonnegative("angular_velocity", angular_velocity, "rad/s")
    check_nonnegative("load_torque", load_torque, "N m")
    ch = chains.get(chain)
    p = ch.pitch
    a = 0.5 * (links - teeth) * p
    r_w = p / (2 * math.sin(math.pi / teeth))
    inertia = 0.5 * 7800 * math.pi * r_w**4 * 0.02  # steel disc, 20 mm thick
    wheels = [
        SimWheel.at((0.0, 0.0), teeth, inertia, "speed", angular_velocity, ramp_time, name="driver"),
        SimWheel.at((a, 0.0), teeth, inertia, "free", torque=-load_torque, name="driven"),
    ]
    opts: dict[str, Any] = dict(pitch=p, links=links, link_mass=_mass_per_length(ch) * p,
                axial_stiffness=AXIAL_STIFFNESS_16B * (p / 0.0254) ** 2,
                roller_radius=0.5 * _required(ch.roller_diameter, ch.name, "roller_diameter"), wheels=wheels,
                gravity=(0.0, -9.81) if gravity else (0.0, 0.0))
    opts.update(kwargs)
    return SimulationModel(**opts)


def link_example(*, chain: str = "18x64", teeth: int = 8, links: int = 60,
                 angular_velocity: float = 5.0, load_torque: float = 2000.0,
                 ramp_time: float = 0.2, gravity: bool = True,
                 **kwargs: Any) -> SimulationModel:
    """Round link chain on two equal pocket wheels, the driver (wheel 0) on the left.

    The chain is a DIN 22252 round link chain from :func:`chaindrive.chains.get`
    (inner link length ``t`` as ``pitch``, bar diameter ``d``); each wheel has ``teeth``
    pockets (pitch radius of Dolipiński et al. eq. (6)). The wheels' centre distance starts at
    ``(N − 2z)/2 · t`` (a half wrap holds ``z`` links) and is adjusted by the assembly
    so that the loop of ``links`` links closes; the tight span is the upper one.
    Wheel inertia: steel discs at the pitch radius, ``5 d`` thick. ``EA`` from
    :func:`link_chain_axial_stiffness`; pretension 1 kN unless given.

    Parameters
    ----------
    chain : str
        Catalogue name of a round link chain (``family == "din22252"``).
    teeth : int
        Pockets per wheel ``z >= 3``.
    links : int
        Number of links (even).
    angular_velocity : float
        Driver speed [rad/s] (reached after ``ramp_time`` [s]).
    load_torque : float
        Load on the driven wheel [N m].
    gravity : bool
    **kwargs
        Other :class:`SimulationModel` fields.

    Examples
    --------
    >>> m = link_example()
    >>> m.links, m.link_lengths, m.wheels[1].teeth
    (60, (0.082, 0.046), 8)
    >>> round(float(m.pitch_radii()[0]), 6)   # Dolipiński et al. eq. (6): 18x64, z = 8
    0.164283
    """
    from .. import chains

    # the examples run counter-clockwise with the tight span on top; a reversed drive
    # is a project with travel = "cw"
    check_nonnegative("angular_velocity", angular_velocity, "rad/s")
    check_nonnegative("load_torque", load_torque, "N m")
    ch = chains.get(chain)
    if not getattr(ch, "is_link_chain", False) or ch.bar_diameter is None:
        raise InputError(f"link_example needs a round link chain (DIN 22252, e.g. '18x64'), "
                         f"got {chain!r} ({ch.family})")
    t, d = float(ch.pitch), float(ch.bar_diameter)
    from ..geometry.polygon import link_chain_pitch_radius

    r_w = float(link_chain_pitch_radius(t, d, teeth))
    a = 0.5 * (links - 2 * teeth) * t
    inertia = 0.5 * 7800 * math.pi * r_w**4 * 5 * d
    wheels = [
        SimWheel.at((0.0, 0.0), teeth, inertia, "speed", angular_velocity, ramp_time, name="driver"),
        SimWheel.at((a, 0.0), teeth, inertia, "free", torque=-load_torque, name="driven"),
    ]
    opts: dict[str, Any] = dict(pitch=t, links=links, link_mass=_mass_per_length(ch) * t,
                axial_stiffness=link_chain_axial_stiffness(d), roller_radius=0.5 * d,
                bar_diameter=d, wheels=wheels, pretension=1000.0,
                gravity=(0.0, -9.81) if gravity else (0.0, 0.0))
    opts.update(kwargs)
    return SimulationModel(**opts)


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
