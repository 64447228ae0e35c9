"""The result of a simulation run: :class:`SimulationResult` and its summary."""

from __future__ import annotations

import os
from collections.abc import Sequence
from dataclasses import dataclass, field, fields
from typing import TYPE_CHECKING

import numpy as np

from .._finite import finite_fields, finite_guard
from .._presenters import view
from .._results import Result, quantity
from . import _kernel as K
from .model import SimulationModel
from .placement import _tangent

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure


__all__ = ["SimulationResult", "State", "SUMMARY_QUANTITIES", "default_probes", "tight_span", "slack_span", "span_tension"]


@finite_fields
@dataclass
class State:
    """Mutable simulation state (pins and wheels).

    ``relax_time`` and ``relax_steps`` are the relaxation's simulated time [s] and steps,
    or 0 and the accepted Newton steps of the static solver.
    """

    pos: np.ndarray
    vel: np.ndarray
    ws: np.ndarray
    wp: np.ndarray
    gd: np.ndarray
    par: np.ndarray
    relax_time: float = 0.0
    relax_steps: int = 0
    #: time [s] of this state: 0 after assembly, the end time of the run for a
    #: ``final_state`` (so that a continued run does not restart the driver's ramp)
    time: float = 0.0



@dataclass(frozen=True)
class SimulationResult(Result):
    """Time histories of a simulation (SI units), sampled every ``record_every`` steps.

    Attributes
    ----------
    time : ndarray (R,)
        [s].
    probe_points : ndarray (P, 4)
        Probe point (x, y) [m] and direction (unit vector) at which the chain speed is
        taken (velocity component of the pin nearest the point).
    chain_velocity : ndarray (R, P)
        Chain speed at the probes [m/s].
    tension : ndarray (R, N)
        Force in each link [N] (link i joins pins i and i+1).
    contact_force : ndarray (R, N)
        Total normal contact force on each roller [N].
    wheel_angle, wheel_speed, wheel_torque : ndarray (R, W)
        Angle [rad], speed [rad/s] and torque of the chain on each wheel [N m] (for the
        driver, minus the driving torque).
    tensioner_position : ndarray (R, W)
        Slide displacement of each wheel from its assembled position [m] (0 if fixed).
    positions : ndarray (R, N, 2)
        Pin positions [m].
    energy : ndarray (R,)
        Mechanical energy (kinetic + elastic + contact + gravity) [J].
    wheel_centres : ndarray (W, 2), pitch_radii : ndarray (W,), teeth : ndarray (W,)
    tight_span : ndarray (2, 2)
        End points of the tight span (entering the driver) [m].
    slack_span : ndarray (2, 2)
        End points of the span leaving the driver [m].
    dt : float
        Time step [s].
    steps : int
    wall_time : float
        Wall-clock time of the integration [s] (excluding assembly).
    assembly_time : float
        Simulated relaxation time of the assembly [s].
    guide_segments : ndarray (G, 2, 2)
        Start and end points of the guides' roller surfaces [m].
    motor_speed : ndarray (R, W)
        Speed of the motor behind a wheel's fluid coupling, reduced to the wheel
        [rad/s] (0 for a wheel without one).
    """

    time: np.ndarray = quantity("s")
    probe_points: np.ndarray = quantity("m")
    chain_velocity: np.ndarray = quantity("m/s")
    tension: np.ndarray = quantity("N")
    contact_force: np.ndarray = quantity("N")
    wheel_angle: np.ndarray = quantity("rad")
    wheel_speed: np.ndarray = quantity("rad/s")
    wheel_torque: np.ndarray = quantity("N*m")
    tensioner_position: np.ndarray = quantity("m")
    positions: np.ndarray = quantity("m")
    energy: np.ndarray = quantity("J")
    wheel_centres: np.ndarray = quantity("m")
    pitch_radii: np.ndarray = quantity("m")
    teeth: np.ndarray = quantity("1")
    tight_span: np.ndarray = quantity("m")
    slack_span: np.ndarray = quantity("m")
    pitch: float = quantity("m")
    roller_radius: float = quantity("m")
    dt: float = quantity("s")
    steps: int = quantity("1")
    wall_time: float = quantity("s")
    assembly_time: float = quantity("s")
    guide_segments: np.ndarray = quantity("m", default_factory=lambda: np.zeros((0, 2, 2)))
    motor_speed: np.ndarray = quantity("rad/s", default_factory=lambda: np.zeros((0, 0)))
    summary: dict = field(default_factory=dict)
    if TYPE_CHECKING:  # set by simulate(); at run time not a dataclass field (not saved)
        final_state: State = field(init=False)

    def tight_side_tension(self) -> np.ndarray:
        """Tension of the link nearest the middle of the tight span, over time [N]."""
        return self._span_tension(self.tight_span)

    def slack_side_tension(self) -> np.ndarray:
        """Tension of the link nearest the middle of the span leaving the driver [N]."""
        return self._span_tension(self.slack_span)

    def _span_tension(self, span) -> np.ndarray:
        other = self.slack_span if span is self.tight_span else self.tight_span
        return span_tension(self.positions, self.tension, span, other)

    def save_npz(self, path: str | os.PathLike[str], *, compressed: bool = False) -> None:
        """Write every array (and scalars) to a ``.npz`` file (``numpy.load`` reads it
        without ``allow_pickle``): the dataclass fields but the summary; not the
        ``final_state``.

        Uncompressed by default: the recorded floats compress by a quarter at most
        (6.6 MB to 4.9 MB for the 0.5 s roller example) and the compression costs 0.2 s;
        ``compressed=True`` for a smaller file."""
        data = {f.name: getattr(self, f.name) for f in fields(self) if f.name != "summary"}
        (np.savez_compressed if compressed else np.savez)(path, **data)

    def plot(self, *, ax: Sequence[Axes] | None = None) -> Figure:
        """Standard views (see :func:`chaindrive.plotting.simulation.simulation_plot`)."""
        return view("plot", self, ax=ax)


@finite_guard  # NaN/inf and out-of-range arguments refused (chaindrive._finite)
def span_tension(positions: np.ndarray, tension: np.ndarray, span: np.ndarray,
                 other: np.ndarray) -> np.ndarray:
    """Tension [N] of the link nearest the middle of ``span`` in each record.

    The link nearest the span's mid-point among the links nearer to this span's line
    than to the ``other`` span's (a deeply sagging span lies nearer another span's
    mid-point). ``positions`` (R, N, 2) [m], ``tension`` (R, N) [N], spans (2, 2) [m].
    Computed in blocks of ``_ROWS`` records (the temporaries are a dozen arrays of the
    positions' size: 15 MB for the 0.5 s roller example at once).
    """
    out = np.empty(len(positions), dtype=np.result_type(tension, np.float64))
    for a in range(0, len(positions), _ROWS):
        out[a:a + _ROWS] = _span_tension_rows(positions[a:a + _ROWS], tension[a:a + _ROWS], span, other)
    return out


#: records per block of :func:`span_tension`
_ROWS = 256


def _span_tension_rows(positions, tension, span, other):
    mid = 0.5 * (span[0] + span[1])
    lm = 0.5 * (positions + np.roll(positions, -1, axis=1))

    def to_segment(seg):
        u = seg[1] - seg[0]
        t = np.clip(((lm - seg[0]) @ u) / (u @ u), 0.0, 1.0)
        return np.sum((lm - seg[0] - t[..., None] * u) ** 2, axis=2)

    d = np.sum((lm - mid) ** 2, axis=2)
    d = np.where(to_segment(span) <= to_segment(other), d, np.inf)
    idx = np.argmin(d, axis=1)
    return tension[np.arange(len(idx)), idx]


#: Every key of :attr:`SimulationResult.summary`: its label and SI unit ("1": a count or
#: a ratio), for presenters (the studio's simulation page).
SUMMARY_QUANTITIES: dict[str, tuple[str, str]] = {
    "duration": ("simulated time", "s"),
    "dt": ("time step", "s"),
    "steps": ("time steps", "1"),
    "wall_time": ("computing time", "s"),
    "link_steps_per_second": ("link-steps per second of computing", "1/s"),
    "wall_seconds_per_simulated_second": ("computing seconds per simulated second", "1"),
    "steady_from": ("averages taken from", "s"),
    "tight_side_tension_mean": ("tight-side tension, mean", "N"),
    "tight_side_tension_max": ("tight-side tension, maximum", "N"),
    "slack_side_tension_mean": ("slack-side tension, mean", "N"),
    "max_link_tension": ("largest link tension", "N"),
    "max_contact_force": ("largest contact force", "N"),
    "wheel_speed_mean": ("wheel speeds, mean", "rad/s"),
    "chain_velocity_mean": ("chain speed at the probes, mean", "m/s"),
    "chain_velocity_max": ("chain speed at the probes, maximum", "m/s"),
    "chain_velocity_min": ("chain speed at the probes, minimum", "m/s"),
}


def _summary(res: SimulationResult, settle: float) -> dict:
    after = res.time >= settle
    sel: np.ndarray | slice = after if np.any(after) else slice(None)
    v = res.chain_velocity[sel]
    tt = res.tight_side_tension()[sel]
    out = {
        "duration": float(res.steps * res.dt),
        "dt": res.dt,
        "steps": res.steps,
        "wall_time": res.wall_time,
        "link_steps_per_second": res.steps * res.tension.shape[1] / max(res.wall_time, 1e-12),
        "wall_seconds_per_simulated_second": res.wall_time / max(res.steps * res.dt, 1e-300),
        "steady_from": settle,
        "tight_side_tension_mean": float(np.mean(tt)),
        "tight_side_tension_max": float(np.max(tt)),
        "slack_side_tension_mean": float(np.mean(res.slack_side_tension()[sel])),
        "max_link_tension": float(np.max(res.tension[sel])),
        "max_contact_force": float(np.max(res.contact_force[sel])),
        "wheel_speed_mean": np.mean(res.wheel_speed[sel], axis=0).tolist(),
    }
    if v.shape[1]:
        out["chain_velocity_mean"] = np.mean(v, axis=0).tolist()
        out["chain_velocity_max"] = np.max(v, axis=0).tolist()
        out["chain_velocity_min"] = np.min(v, axis=0).tolist()
    return out


def default_probes(model: SimulationModel, state: State) -> np.ndarray:
    """Probe at the middle of the tight span (entering wheel 0), along the chain."""
    p1, p2 = tight_span(model, state)
    u = (p2 - p1) / np.hypot(*(p2 - p1))
    mid = 0.5 * (p1 + p2)
    return np.array([[mid[0], mid[1], u[0], u[1]]])


def tight_span(model: SimulationModel, state: State) -> tuple[np.ndarray, np.ndarray]:
    """(start, end) of the span entering wheel 0 (from the last wheel) [m]."""
    nw = len(model.wheels)
    c = np.column_stack([state.wp[:, K.W_CX], state.wp[:, K.W_CY]])
    radii = model.signed_radii()
    p1, p2, _, _ = _tangent(c[nw - 1], radii[nw - 1], c[0], radii[0])
    return p1, p2


def slack_span(model: SimulationModel, state: State) -> tuple[np.ndarray, np.ndarray]:
    """(start, end) of the span leaving wheel 0 (to wheel 1) [m]."""
    c = np.column_stack([state.wp[:, K.W_CX], state.wp[:, K.W_CY]])
    radii = model.signed_radii()
    p1, p2, _, _ = _tangent(c[0], radii[0], c[1], radii[1])
    return p1, p2
