r"""Critical speeds of a chain drive beside the transverse one: longitudinal and torsional.

The polygonal action excites the drive at the tooth frequency ``z1 ω1`` of the driving
wheel. Two resonances besides the transverse span vibration (:mod:`chaindrive.analysis.vibration`):

* **longitudinal (wave-type)**: the tight span as an elastic rod between its wheels,
  ``ω_L = π/l sqrt(EA/q)`` (:func:`chaindrive.vibration.critical.longitudinal_frequency`);
* **torsional (spring-type)**: every wheel but the driving one (held by its motor) on the
  spans that hold it, ``ω_t = R sqrt(Σ EA/l_i / J)``
  (:func:`chaindrive.vibration.critical.torsional_frequency`).

Each is compared with the tooth frequency through the forbidden band of the tensioner
paper, ``0.7 <= ω/(z1 ω1) <= 1.4`` (:data:`chaindrive.vibration.resonance.BAND`), as the
transverse check. The chain's axial stiffness ``EA`` is the simulation's estimate
(:data:`chaindrive.chains.stiffness.AXIAL_STIFFNESS_16B` scaled with pitch², or
:func:`~chaindrive.chains.stiffness.link_chain_axial_stiffness`), an order of magnitude,
and the wheels' inertia is not part of the drive description: a steel disc 20 mm thick at
the pitch radius is assumed, as in the simulation. Both checks are therefore reported for
information (relation ``"info"``), with the verdict in words in the note.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .._results import Result, quantity
from ..drive.model import Drive
from .checks import Check
from .layout import DriveLayout
from .parts import Part, PartContext, register_part

__all__ = ["CriticalSpeeds", "critical_speeds", "ASSUMED_DISC_THICKNESS"]

#: Thickness of the steel disc assumed for a wheel's inertia [m] (as the simulation).
ASSUMED_DISC_THICKNESS = 0.02


@dataclass(frozen=True)
class CriticalSpeeds(Result):
    """Longitudinal and torsional natural frequencies against the tooth frequency."""

    tooth_frequency: float = quantity("rad/s", display="Hz")
    axial_stiffness: float = quantity("N")
    longitudinal: float = quantity("rad/s", display="Hz")
    longitudinal_ratio: float = quantity("1")
    torsional: np.ndarray = quantity("rad/s", display="Hz")
    torsional_ratio: np.ndarray = quantity("1")
    wheel_names: tuple[str, ...] = ()
    assumed_inertia: np.ndarray = quantity("kg*m**2", default_factory=lambda: np.zeros(0))


def _axial_stiffness(drive: Drive) -> float:
    from ..chains.stiffness import AXIAL_STIFFNESS_16B, link_chain_axial_stiffness

    if drive.chain.bar_diameter is not None:
        return float(link_chain_axial_stiffness(drive.chain.bar_diameter))
    return AXIAL_STIFFNESS_16B * (drive.pitch / 0.0254) ** 2 * drive.chain.strands


def critical_speeds(drive: Drive, layout: DriveLayout) -> CriticalSpeeds:
    """Longitudinal frequency of the tight span and torsional frequencies of the driven wheels.

    >>> from chaindrive.drive.project import load_project
    >>> from chaindrive.analysis.layout import drive_layout
    >>> d = load_project("examples/roller_industrial.toml")
    >>> c = critical_speeds(d, drive_layout(d))
    >>> round(c.longitudinal_ratio, 1), [round(float(r), 2) for r in c.torsional_ratio]
    (9.8, [2.01])
    """
    from ..loads import disc_inertia
    from ..vibration.critical import longitudinal_frequency, torsional_frequency

    q = drive.mass_per_length
    ea = _axial_stiffness(drive)
    driving = drive.driving_wheel
    teeth = driving.sides_per_turn(drive.chain) if driving.teeth is not None else 1
    tooth = float(drive.speed) * teeth
    spans = layout.wrap.span_length
    lt = float(spans[layout.tight_span])
    wl = float(longitudinal_frequency(lt, ea, q))
    n = len(drive.wheels)
    names, freqs, inertias = [], [], []
    for i, w in enumerate(drive.wheels):
        if w.driving or w.teeth is None:
            continue
        r = float(layout.pitch_radii[i])
        j = float(disc_inertia(r, ASSUMED_DISC_THICKNESS))  # the one assumed wheel inertia
        k = ea / float(spans[(i - 1) % n]) + ea / float(spans[i])
        names.append(w.name)
        inertias.append(j)
        freqs.append(float(torsional_frequency(j, r, k)))
    ft = np.asarray(freqs, dtype=float)
    return CriticalSpeeds(tooth_frequency=tooth, axial_stiffness=ea, longitudinal=wl, longitudinal_ratio=wl / tooth,
                          torsional=ft, torsional_ratio=ft / tooth, wheel_names=tuple(names),
                          assumed_inertia=np.asarray(inertias, dtype=float))


def _verdict(ratio: float) -> str:
    from ..vibration.resonance import BAND

    inside = BAND[0] <= ratio <= BAND[1]
    return (f"ω / (z1 ω1) = {ratio:.3g}: " + ("INSIDE" if inside else "outside")
            + f" the forbidden band {BAND[0]}…{BAND[1]}")


def critical_speed_checks(result: CriticalSpeeds) -> list[Check]:
    """Information checks: each natural frequency against the tooth frequency."""
    # a frequency is stated in Hz (f = ω/2π, SI), its angular frequency in the note (issue 30)
    wl = result.longitudinal
    out = [Check("longitudinal (wave-type) natural frequency of the tight span", wl / (2 * math.pi), None,
                 "Hz", None, "S. S. Rao, Mechanical Vibrations, 5th ed., §8.3 (bar fixed at both ends); "
                 "band: the tensioner paper",
                 note=f"{wl:.4g} rad/s; " + _verdict(result.longitudinal_ratio) + "; EA estimated", relation="info")]
    for name, f, r in zip(result.wheel_names, result.torsional, result.torsional_ratio, strict=True):
        out.append(Check(f"torsional (spring-type) natural frequency of wheel {name!r}", float(f) / (2 * math.pi),
                         None, "Hz", None,
                         "S. S. Rao, Mechanical Vibrations, 5th ed., §2.2 (one-degree-of-freedom torsion)",
                         note=f"{float(f):.4g} rad/s; " + _verdict(float(r))
                         + "; EA estimated, inertia of a 20 mm steel disc assumed", relation="info"))
    return out


def _part(ctx: PartContext) -> CriticalSpeeds | None:
    drive = ctx.drive
    if drive.chain.mass_per_length is None or drive.driving_wheel.teeth is None:
        return None
    return critical_speeds(drive, ctx["layout"])


register_part(Part("critical_speeds", "Longitudinal and torsional critical speeds", _part, needs=("layout",),
                   checks=lambda ctx, result: critical_speed_checks(result), order=55))
