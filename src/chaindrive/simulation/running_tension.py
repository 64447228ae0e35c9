"""The dynamic tension of a drive from the steady state of its simulation: the model the
analysis's reduced running-tension model is calibrated against, for a drive of one's own
(:func:`simulated_dynamic_tension`)."""

from __future__ import annotations

import dataclasses
import functools
import math
import warnings

from ..analysis.dynamic_tension import DynamicTension
from ..chains.stiffness import chain_axial_stiffness
from ..drive.model import Drive
from ..errors import InputError
from ..vibration import running_tension as RT
from .from_drive import model_from_drive
from .steady import steady_state

__all__ = ["SIMULATED_VALIDITY", "simulated_dynamic_tension"]

#: What the steady-state simulation's peak is worth (docs/design.md, "The running peak tension").
SIMULATED_VALIDITY = ("steady-state simulation (warm start, settling detected): its peaks differ from a 2.5 s run from rest by up to -35 % on the calibration "
                      "sweep (rms 13 %, lower on average), the peaks "
                      "move 8-22 % with the unvalidated roller-tooth friction, and the simulation itself is not "
                      "validated against measurement (docs/design.md, 'The running peak tension')")


def simulated_dynamic_tension(drive: Drive, tight: float) -> DynamicTension:
    r"""The dynamic tension from the steady state of the simulation.

    .. math:: F_d = \max(F_{peak} − F_t, 0)

    ``F_peak`` is the mean per-tooth-period peak of the simulated tight-span tension in the
    steady state (:func:`chaindrive.simulation.steady.steady_state`) of ``drive`` at its design
    torque ``K_s T`` (as ``F_t``), the seats at the stiffness the reduced model assumes
    (:func:`chaindrive.vibration.running_tension.seat_contact_stiffness` at ``F_t / n`` for
    each of ``n`` strands), ``EA`` of all strands: the model the reduced running-tension model
    is calibrated against, for a drive outside its calibration range.

    The analysis does not take it (:func:`chaindrive.analysis.dynamic_tension.dynamic_tension`
    keeps the reduced model, warned, outside its input ranges): on the 64 drives of the
    calibration sweep its peaks are 8.6 % lower on average than a 2.5 s run from rest, worst
    -35 %, and on three drives outside the ranges no closer than the model (docs/design.md,
    "The running peak tension"); about 0.2-0.7 s of CPU on the roller examples.

    Parameters
    ----------
    drive : Drive
        A roller-chain drive the simulation takes (:func:`chaindrive.simulation.model_from_drive`).
    tight : float
        Tight-side tension ``F_t = K_s T/R + S + q v²`` [N] (:class:`~chaindrive.analysis.loads.DriveLoads` ``.tight``).

    Returns
    -------
    DynamicTension

    Raises
    ------
    InputError
        A chain without inner width or mass per length, or a drive the simulation cannot assemble.

    References
    ----------
    docs/simulation.md, "Steady state"; docs/design.md, "The running peak tension".
    """
    return _simulated(drive, float(tight))


@functools.lru_cache(maxsize=64)
def _simulated(drive: Drive, tight: float) -> DynamicTension:
    """:func:`simulated_dynamic_tension`, remembered for the last 64 drives (a drive is
    immutable; the design procedure and the studio ask again for the same one)."""
    chain = drive.chain
    if chain.inner_width is None or chain.mass_per_length is None:
        raise InputError(f"chain {chain.name!r} has no inner width or mass per length: no seat stiffness",
                         field="chain")
    n = chain.strands
    kc = n * float(RT.seat_contact_stiffness(tight / n, float(chain.inner_width)))
    load = drive.load
    ks = load.service_factor
    design = drive.replace(load=dataclasses.replace(
        load, power=None if load.power is None else load.power * ks,
        torque=None if load.torque is None else load.torque * ks, service_factor=1.0))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        state = steady_state(model_from_drive(design, axial_stiffness=chain_axial_stiffness(chain) * n,
                                              contact_stiffness=kc))
    peak = float(state.period_peak_tension)
    if not math.isfinite(peak):
        raise InputError(f"the steady-state simulation of the drive gave no finite peak tension ({peak})",
                         field="drive")
    return DynamicTension(
        value=max(peak - tight, 0.0), moving_mass=drive.mass_per_length * drive.pitch, stiffness=kc,
        validity=SIMULATED_VALIDITY,
        model=(f"steady-state simulation: mean per-tooth-period peak {peak:.4g} N over {state.measured_time:.3g} s "
               f"({state.method}), seats k_c = {kc:.3g} N/m (Palmgren)"))
