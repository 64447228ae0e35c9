"""A conveyor's (or any drive's) start-up and stop in the simulation: the model built from
the drive (:func:`chaindrive.simulation.from_drive.model_from_drive`), a time-varying head
drive (:func:`chaindrive.simulation.conveyor.with_drive_profile`), the run and its
start-up record (:func:`chaindrive.simulation.conveyor.start_up_of`)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from .conveyor import StartUp, start_up_of, with_drive_profile
from .from_drive import model_from_drive
from .run import simulate

if TYPE_CHECKING:
    from ..drive.model import Drive
    from ..drivetrain.coupling import FluidCoupling
    from ..drivetrain.motor import Motor
    from .model import SimulationModel
    from .results import SimulationResult

__all__ = ["start_up"]


def start_up(drive: Drive, duration: float, *, motor: Motor | None = None, motor_inertia: float = 0.0,
             ramp_time: float = 0.0, stop_time: float = 0.0, stop_ramp: float = 0.0, ripple: float = 0.0,
             ripple_frequency: float = 0.0, samples: int = 1500, coupling: FluidCoupling | None = None,
             secondary_inertia: float = 0.0) -> tuple[StartUp, SimulationResult, SimulationModel]:
    r"""Start (and optionally stop) a conveyor from rest with a time-varying head drive.

    With ``motor`` the head wheel is driven by it (Kloss curve, switched on at ``t = 0``,
    off at ``stop_time``; ``motor_inertia`` [kg m²] is the motor's rotor and coupling
    reduced to the head shaft, added to the wheel's); without, the head follows a
    prescribed speed: a linear ramp over ``ramp_time`` [s], down to 0 over ``stop_ramp``
    from ``stop_time``. ``ripple`` (relative amplitude) and ``ripple_frequency`` [rad/s]
    modulate the motor torque (or the prescribed speed).

    With ``coupling`` (a :class:`chaindrive.drivetrain.coupling.FluidCoupling` reduced to the head)
    the motor drives the head through it: the motor rotor and coupling primary, of
    inertia ``motor_inertia`` (> 0), turn at their own speed ``ω_m``; the coupling's
    secondary and the gearbox (``secondary_inertia`` [kg m²], reduced) turn with the head,

    .. math::
        J_m \dot ω_m = T_{Kloss}(ω_m) − T_c(ω_m, ω), \qquad
        J \dot ω = T_c(ω_m, ω) + T_{chain}

    with the coupling torque ``T_c`` of :func:`chaindrive.drivetrain.coupling.coupling_torque`
    (implicit in the slip in each time step: the coupling is a stiff damper).

    Parameters
    ----------
    drive : chaindrive.drive.Drive
        A conveyor (with ``[conveyor]``), or any drive.
    duration : float
        Simulated time [s].
    motor, motor_inertia, ramp_time, stop_time, stop_ramp, ripple, ripple_frequency, coupling, secondary_inertia
        As above.
    samples : int
        Records kept.

    Returns
    -------
    (StartUp, SimulationResult, SimulationModel)
    """
    model = with_drive_profile(model_from_drive(drive, ramp_time=ramp_time), motor=motor,
                               motor_inertia=motor_inertia, stop_time=stop_time, stop_ramp=stop_ramp,
                               ripple=ripple, ripple_frequency=ripple_frequency, coupling=coupling,
                               secondary_inertia=secondary_inertia)
    result = simulate(model, duration, samples=samples)
    return start_up_of(result, model), result, model
