"""The self-regulating drive as a declared analysis part: the model of
:mod:`chaindrive.self_regulating` for a :class:`chaindrive.drive.Drive` with a
``[self_regulating]`` table (carrier statics over load and wear), and its checks."""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

import numpy as np

from .. import layout as L
from ..drive.carrier import SelfRegulatingSpec
from ..errors import InputError
from ..self_regulating.grid import SelfRegulatingDriveResult, self_regulating_drive
from .checks import Check
from .parts import Part, PartContext, register_part

if TYPE_CHECKING:
    from ..drive.model import Drive

__all__ = ["self_regulating_analysis", "self_regulating_checks"]


def _drive_inputs(drive: Any, spec: SelfRegulatingSpec) -> dict:
    """Read what the model needs from a :class:`chaindrive.drive.Drive` (attributes only).

    The one place that knows the Drive: attribute names shared by the mutable Drive
    and the frozen dataclass that replaces it; nothing is written to the drive.
    """
    wheels = list(drive.wheels)
    if len(wheels) != 2 or any(w.teeth is None or w.kind == "idler" for w in wheels):
        raise InputError(
            "self_regulating: the model covers two-wheel drives of toothed wheels (got "
            f"{len(wheels)} wheels: {', '.join(w.name for w in wheels)})")
    names = [w.name for w in wheels]
    if spec.wheel not in names:
        raise InputError(f"self_regulating.wheel: no wheel named {spec.wheel!r}; wheels: {', '.join(names)}")
    carrier = wheels[names.index(spec.wheel)]
    fixed = wheels[1 - names.index(spec.wheel)]
    chain = drive.chain
    bar = chain.bar_diameter if chain.is_link_chain else None
    if chain.mass_per_length is None:
        raise InputError(f"chain {chain.name!r} has no mass_per_length; give it in the [chain] table")
    load = drive.load
    speed = float(drive.speed)
    torque = float(load.torque) if load.torque is not None else float(load.power) / speed
    links = drive.links
    if links is None:  # the rule of chaindrive.analysis.drive_layout: polygon length, even
        a0 = float(np.hypot(*np.subtract(wheels[1].position, wheels[0].position)))
        req = L.chain_length_polygon(chain.pitch, wheels[0].teeth, wheels[1].teeth, a0,
                                     bar_diameter=bar, phases=8).links_max
        links = int(L.even_links(req))
    return dict(pitch=float(chain.pitch), bar_diameter=bar, teeth_carrier=int(carrier.teeth),
                teeth_fixed=int(fixed.teeth), carrier_centre=tuple(carrier.position),
                fixed_centre=tuple(fixed.position), links=int(links), torque=torque,
                carrier_driving=bool(carrier.driving), mass_per_length=float(chain.mass_per_length),
                travel=str(drive.travel), elongation_limit=float(drive.elongation_limit),
                speed=speed,
                sag_ratio=float(drive.slack_sag_ratio), wheel=carrier.name)


def self_regulating_analysis(drive: Drive, spec: SelfRegulatingSpec | Mapping[str, Any] | None = None
                             ) -> SelfRegulatingDriveResult:
    """The self-regulating drive model for a :class:`chaindrive.drive.Drive` and its spec.

    Parameters
    ----------
    drive : chaindrive.drive.Drive
        A two-wheel drive; read only (never modified).
    spec : SelfRegulatingSpec or mapping, optional
        The carrier; a mapping is read by :meth:`SelfRegulatingSpec.from_table`;
        default the drive's ``self_regulating``.

    Returns
    -------
    SelfRegulatingDriveResult
        Over load factors ``0 … spec.load_max_factor`` (nominal: the drive's load
        without service factor) and elongations ``0 … drive.elongation_limit``.

    Raises
    ------
    InputError, InfeasibleError
        See :func:`self_regulating_drive`.

    References
    ----------
    See :func:`self_regulating_drive`.

    Examples
    --------
    >>> from chaindrive.chains import get
    >>> from chaindrive.drive import Drive, Load, Wheel
    >>> d = Drive(chain=get("16B"), speed=100.0, load=Load(torque=300.0),
    ...           wheels=[Wheel("motor", "sprocket", 19, (0.6, 0.0), driving=True),
    ...                   Wheel("fan", "sprocket", 38, (0.0, 0.0))], links=76)
    >>> spec = SelfRegulatingSpec(wheel="motor", pivot=(0.66, -0.045), weight=400.0,
    ...                           weight_offset=(0.08, 0.0), numerical=False)
    >>> r = self_regulating_analysis(d, spec)
    >>> r.centre_distance.shape, r.links
    ((7, 4), 76)
    """
    if spec is None:
        spec = getattr(drive, "self_regulating", None)
        if spec is None:
            raise InputError("self_regulating: the drive has no [self_regulating] table (carrier spec)")
    if isinstance(spec, Mapping):
        spec = SelfRegulatingSpec.from_table(spec)
    if not isinstance(spec, SelfRegulatingSpec):
        raise InputError(f"spec must be a SelfRegulatingSpec or a table, got {type(spec).__name__}")
    inp = _drive_inputs(drive, spec)
    lam = np.linspace(0.0, float(spec.load_max_factor), int(spec.load_steps))
    e = np.linspace(0.0, inp.pop("elongation_limit"), int(spec.elongation_steps))
    sag = inp.pop("sag_ratio") if spec.sag_allowance is None else float(spec.sag_allowance)
    axial = spec.axial_stiffness
    if axial is None and inp["bar_diameter"] is not None:
        # studless chain: EA = 0.854e8 d² kN with d in m (OrcaFlex, "Chain: axial and
        # bending stiffness", from catalogue data)
        axial = 0.854e11 * inp["bar_diameter"] ** 2
    return self_regulating_drive(
        **inp, kind=spec.kind, pivot=spec.pivot, direction=spec.direction,
        torque_reaction=spec.torque_reaction, weight=float(spec.weight),
        weight_offset=spec.weight_offset, stiffness=float(spec.stiffness),
        preload=float(spec.preload), load_factors=lam, elongations=e, sag_allowance=sag,
        psi_tolerance=float(spec.psi_tolerance), numerical=bool(spec.numerical),
        inertia=spec.inertia, axial_stiffness=axial)


def self_regulating_checks(result: SelfRegulatingDriveResult) -> tuple[Any, ...]:
    """The result's checks as :class:`chaindrive.analysis.Check` verdicts.

    Parameters
    ----------
    result : SelfRegulatingDriveResult

    Returns
    -------
    tuple of chaindrive.analysis.Check
        Sag at the rated load within the allowance over the wear range; ``S2/F_t`` at the
        rated load within ``(1 + tolerance) ψ*``; the carrier statically stable; its
        natural frequency outside the tensioner paper's band (when the speed and an inertia
        or weight are known); closed form against the numerical equilibrium (when it was
        run).

    References
    ----------
    docs/self_regulating.md ("The rational ψ").

    Examples
    --------
    >>> from chaindrive.self_regulating import example_drive
    >>> r = example_drive()  # self_regulating_drive's example, closed forms only
    >>> [c.verdict for c in self_regulating_checks(r)]
    ['pass', 'FAIL', 'pass']
    """
    if not isinstance(result, SelfRegulatingDriveResult):
        raise InputError(f"result must be a SelfRegulatingDriveResult, got {type(result).__name__}")
    return tuple(Check(**c) for c in result.checks)


def _self_regulating_part(ctx: PartContext) -> SelfRegulatingDriveResult | None:
    if ctx.drive.self_regulating is None:
        return None
    sr = self_regulating_analysis(ctx.drive, ctx.drive.self_regulating)
    for text in sr.warnings:
        ctx.note(text)
    return sr


def _self_regulating_checks(ctx: PartContext, sr: SelfRegulatingDriveResult) -> tuple[Check, ...]:
    return self_regulating_checks(sr)


register_part(Part("self_regulating", "Self-regulating drive", _self_regulating_part, checks=_self_regulating_checks,
                   order=100, section="chaindrive.workflows.sections:self_regulating_section"))
