r"""Fretting and pin slip of a multi-strand roller chain as an analysis part (Vikulov).

Vikulov (Penza): in multi-row drive chains the pins fret against the intermediate plates;
intermediate plates that carry load reduce the bending of the pin, hence the micro-slip,
and so raise the latent period of fretting ``τ = K1 Ra exp(−k2 A N f / Ra)``. For every
drive whose chain has two or more strands (and the pin diameter, transverse pitch and
inner width the pin model needs) the part computes, once per drive:

* the pin as a beam across the rows (:class:`~chaindrive.strength.MultiRowPin`), with
  and without working intermediate plates, under the load swing of one pass round the
  loop (tight minus slack tension): the bending stress and the slip amplitude ``A``;
* with the empirical constants of a ``[fretting]`` table: the latent periods and their
  ratio (without the table: ``None``; the paper gives no values of ``K1``, ``K2``).

Decisions made here (one place): the slip follows the load *swing* ``F_tight − F_slack``;
the normal load in a joint is the tight-side tension of one row, ``F_tight / n``; the
frequency is the tooth frequency of the driving wheel ``z ω / 2π`` unless given.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .._results import Result, quantity
from ..errors import InputError
from ..strength.fretting import MultiRowPin, fretting_comparison
from .checks import Check
from .parts import Part, PartContext, register_part

__all__ = ["FrettingAnalysis", "drive_fretting"]

SOURCE = "Vikulov (Penza), eq. (1) and conclusions; docs/strength.md §3"


@dataclass(frozen=True)
class FrettingAnalysis(Result):
    """Pin bending, slip and fretting latent period of a multi-strand chain (SI units)."""

    strands: int = quantity("1")
    load_swing: float = quantity("N")
    normal_load: float = quantity("N")
    frequency: float = quantity("Hz")
    pin_stress_without_plates: float = quantity("Pa")
    pin_stress_with_plates: float = quantity("Pa")
    slip_without_plates: float = quantity("m", display="mm")
    slip_with_plates: float = quantity("m", display="mm")
    slip_ratio: float = quantity("1")
    latent_period_without_plates: float | None = quantity("s", default=None)
    latent_period_with_plates: float | None = quantity("s", default=None)
    life_ratio: float | None = quantity("1", default=None)


def drive_fretting(ctx: PartContext) -> FrettingAnalysis | None:
    """The part's compute function (``None`` for a single-strand or link chain)."""
    drive = ctx.drive
    chain = drive.chain
    if not chain.is_roller_chain or int(chain.strands) < 2:
        return None
    try:
        pin = MultiRowPin.from_chain(chain)
    except InputError as exc:
        ctx.note(f"fretting: not computed: {exc}")
        return None
    loads = ctx["loads"]
    swing = float(loads.tight - loads.slack)
    if not swing > 0:
        return None
    normal = float(loads.tight) / pin.strands
    spec = drive.fretting
    teeth = drive.driving_wheel.teeth or 0
    frequency = float(spec.frequency) if spec is not None and spec.frequency is not None else (
        teeth * float(drive.speed) / (2 * math.pi))
    without = pin.bending(swing, intermediate_plates=False)
    with_ = pin.bending(swing, intermediate_plates=True)
    latent_without = latent_with = life = None
    if spec is not None:
        cmp = fretting_comparison(pin, swing, spec.roughness, frequency, spec.latent_coefficient,
                                  spec.decay_coefficient, normal_load=normal)
        latent_without, latent_with = float(cmp.latent_without), float(cmp.latent_with)
        life = float(cmp.life_ratio)
    return FrettingAnalysis(
        strands=pin.strands, load_swing=swing, normal_load=normal, frequency=frequency,
        pin_stress_without_plates=float(without.max_stress), pin_stress_with_plates=float(with_.max_stress),
        slip_without_plates=float(without.slip_amplitude), slip_with_plates=float(with_.slip_amplitude),
        slip_ratio=float(without.slip_amplitude) / float(with_.slip_amplitude),
        latent_period_without_plates=latent_without, latent_period_with_plates=latent_with, life_ratio=life,
    )


def fretting_checks(ctx: PartContext, r: FrettingAnalysis) -> list[Check]:
    out = [Check("pin slip without / with intermediate plates", r.slip_ratio, None, "-", None, SOURCE,
                 f"{r.strands}-strand chain, load swing tight − slack", relation="info")]
    if r.life_ratio is not None:
        out.append(Check("fretting latent period with / without intermediate plates", r.life_ratio, None, "-",
                         None, SOURCE, "τ = K1 Ra exp(−k2 A N f / Ra) with the [fretting] constants",
                         relation="info"))
    return out


register_part(Part("fretting", "Fretting and pin slip of a multi-strand chain (Vikulov)", drive_fretting,
                   needs=("loads",), checks=fretting_checks, order=75))
