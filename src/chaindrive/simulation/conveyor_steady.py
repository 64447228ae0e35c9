r"""A conveyor's running steady state, measured from its warm start: :func:`running_steady_state`.

Kept apart from :mod:`chaindrive.simulation.conveyor` (the pans, which the drive's
simulation model takes) so that the steady state's module, which builds that model from a
drive, imports no module that imports it back.
"""

from __future__ import annotations

from typing import Any

from .steady import SteadyState, steady_state

__all__ = ["running_steady_state"]


def running_steady_state(drive_or_model: Any, *, min_settle_time: float = 0.0, window: int = 1,
                         **options: Any) -> SteadyState:
    r"""Tight-span tension of a running conveyor from nothing, measured from its warm start.

    :func:`chaindrive.simulation.steady.steady_state` (warm start, settling detected,
    the implicit step checked against its half, ``periods`` tooth periods measured) with
    no minimum settling time and the settling compared over single tooth periods: the
    long free spans of a conveyor vibrate without damping of their own, so the settling
    that waits two periods of their first transverse mode (``2L/\sqrt{S/q}``, Irvine,
    *Cable Structures*, MIT Press 1981, ch. 3; 2.26 s on the 100 m conveyor) waits for a
    state that never comes: the tight-span tension of ``conveyor_example()`` beats over
    20–30 s (12 tooth periods measured anywhere in a 60 s run lie up to 3.4 % from the
    whole run's statistics), and the periods right after the warm start are as close to
    that as any (0.9–1.0 % measured from the warm start, 1.8 % after the 4.6 s of
    settling; docs/simulation.md, "Steady state").

    Parameters
    ----------
    drive_or_model : chaindrive.drive.Drive or SimulationModel
        As :func:`~chaindrive.simulation.steady.steady_state`.
    min_settle_time : float
        Simulated time [s] before the settling test may pass.
    window : int
        Tooth periods compared with those before them to detect the settling.
    **options
        Other arguments of :func:`~chaindrive.simulation.steady.steady_state`.

    Returns
    -------
    chaindrive.simulation.steady.SteadyState

    Examples
    --------
    A short two-sprocket drive stands in for a conveyor here (the 100 m one takes 0.7 s):

    >>> from chaindrive.simulation import roller_example
    >>> drive = roller_example(links=44, teeth=11, angular_velocity=8.0, gravity=False)
    >>> s = running_steady_state(drive, periods=3, bins=8)
    >>> bool(s.max_tension >= s.peak_tension >= s.mean_tension > 0), len(s.phase)
    (True, 8)

    References
    ----------
    Irvine, H. M. *Cable Structures*, MIT Press 1981, ch. 3 (the span's transverse modes).
    """
    return steady_state(drive_or_model, min_settle_time=min_settle_time, window=window, **options)
