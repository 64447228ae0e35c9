r"""Assembly in static equilibrium and time integration of a :class:`SimulationModel`.

The placement of the chain (steps 1-2 below) is :mod:`chaindrive.simulation.placement`,
the result of a run :mod:`chaindrive.simulation.results`.

Assembly
--------
1. The loop path: pitch circles joined by their outer common tangents (wheels in
   counter-clockwise chain order). Measured in pitches — a wrap of angle ``γ`` on a
   ``z``-tooth wheel holds ``γ z / 2π`` links, a span of length ``L`` holds ``L/p`` — the
   path must hold exactly ``N`` links; the centre of the adjusting wheel (the tensioner's
   wheel, else the last wheel, moved along the line from wheel 0) is solved for that
   (Brent's method).
2. Pins are placed link by link at their exact lengths (seated pins on the polygons,
   free pins on the tangents; the adjusting offset refined so that the loop closes).
3. Static equilibrium (default ``method="newton"``, :mod:`chaindrive.simulation.statics`):
   the minimum of the model's potential energy by a pseudo-transient Newton iteration
   with a bordered banded solve, cost linear in the number of links; continuation from
   the prestrained chain without gravity, then gravity and the adjusting wheel on a
   slide pushed by ``2 × pretension`` (or the tensioner on its spring), then the loads
   (at once, or by angle control of the loaded wheel when a sagging span must be
   straightened through the polygon's cogging). ``method="relaxation"``: the earlier dynamic relaxation (the same
   equations with mass-proportional damping until the kinetic energy is negligible).
   The measured run starts from this state at rest.

Integration
-----------
``method="explicit"`` (default): semi-implicit (symplectic) Euler, ``v ← v + Δt F/m``,
``x ← x + Δt v``: one force evaluation per step, no energy drift for the conservative
part (it conserves a shadow Hamiltonian), stable for ``Δt < 2/ω_max``
(:meth:`SimulationModel.stable_time_step`, ~3 µs for a 16B chain: the step is set by the
stiff links, not by accuracy).

``method="implicit"``: the linearly implicit step of :mod:`._implicit` (link springs,
contact springs, sticking friction implicit; a cyclic tridiagonal solve per step, linear
in the links), at a step set by accuracy (:meth:`SimulationModel.accurate_time_step`,
first order: check it against its half). docs/simulation.md, "Integrator".
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable

import numpy as np
from numpy.typing import ArrayLike

from ..errors import ConvergenceError, InputError, UnknownNameError
from . import _kernel as K
from ._implicit import integrate_implicit
from .model import SimulationModel, iso_flank
from .placement import _path, _place, _tangent  # noqa: F401 - _path, _tangent: also imported from here
from .results import (
    SUMMARY_QUANTITIES,
    SimulationResult,
    State,
    _summary,
    default_probes,
    slack_span,
    tight_span,
)

__all__ = ["SimulationResult", "SUMMARY_QUANTITIES", "assemble", "simulate", "kernel_arrays", "State", "conservative",
           "step_for_accuracy"]


# ---------------------------------------------------------------------------- kernel data
def kernel_arrays(model: SimulationModel, dt: float | None = None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Parameter vector and wheel/guide tables for the kernel (fresh arrays)."""
    dt = model.stable_time_step() if dt is None else dt
    par = np.zeros(K.NPAR)
    par[K.P_MASS] = model.link_mass
    par[K.P_K] = model.link_stiffness
    par[K.P_C] = model.link_damping
    lengths = model.link_lengths
    par[K.P_PITCH] = lengths[0] / (1.0 + model.prestrain)
    par[K.P_PITCH2] = lengths[1] / (1.0 + model.prestrain)
    par[K.P_RROLLER] = model.roller_radius
    par[K.P_KC] = model.contact_stiffness
    par[K.P_CC] = model.contact_damping
    par[K.P_MU] = model.friction
    par[K.P_VEPS] = model.friction_velocity
    par[K.P_GX], par[K.P_GY] = model.gravity
    par[K.P_DT] = dt
    par[K.P_THETA] = 1.0
    par[K.P_CSPAN] = model.span_damping_rate()
    # friction slope cap m / dt_ref (see the kernel), dt_ref = 2 dt_stable: the cap
    # m / dt makes the friction dead-beat on its own, and with the link springs and
    # large seat forces the alternating mode of the seated pins then grows (period 2:
    # the mining conveyor at 12 kN and a 16B roller drive at 12 kN pretension did not
    # assemble with dt_ref = dt_stable). Half that slope keeps it stable, for every chain.
    par[K.P_DTREF] = 2.0 * model.stable_time_step()
    par[K.P_KG] = model.guide_stiffness
    par[K.P_CG] = 2.0 * model.contact_damping_ratio * math.sqrt(model.guide_stiffness * model.link_mass)
    nw = len(model.wheels)
    wp = np.zeros((nw, K.NWP))
    radii = model.seat_radii()  # the wheels' own pitch (a worn chain: model.wheel_pitch)
    for i, w in enumerate(model.wheels):
        psi = model.seat_angle(w.teeth)
        wp[i, K.W_CX], wp[i, K.W_CY] = w.centre
        wp[i, K.W_R] = radii[i]
        wp[i, K.W_Z] = w.teeth
        wp[i, K.W_NSEAT] = model.seats_per_turn(w.teeth)
        wp[i, K.W_DA], wp[i, K.W_DB] = model.central_angles(w.teeth)
        wp[i, K.W_RS] = model.seat
        wp[i, K.W_CPSI] = math.cos(psi)
        wp[i, K.W_SPSI] = math.sin(psi)
        wp[i, K.W_HTIP] = model.tip(w.teeth)
        wp[i, K.W_INERTIA] = w.inertia
        if w.plain_radius is None and not model.is_link_chain and model.tooth_flank == "arc":
            # ISO 606 convex flank arc (sprockets of roller chains)
            (wp[i, K.W_RE], wp[i, K.W_CEA], wp[i, K.W_CEB], wp[i, K.W_TCA], wp[i, K.W_TCB],
             wp[i, K.W_DTA], wp[i, K.W_DTB]) = iso_flank(model.tooth_pitch, w.teeth, model.roller_radius,
                                                         model.seat, psi, model.tip(w.teeth))
        if w.plain_radius is not None:
            # toothless idler: penalty contact with its running circle, no seats
            wp[i, K.W_PLAIN] = 1.0
            wp[i, K.W_HTIP] = 0.0
            wp[i, K.W_NSEAT] = 3
            wp[i, K.W_Z] = 0  # reported as teeth = 0 (toothless)
        wp[i, K.W_MODE] = {"speed": K.MODE_SPEED, "motor": K.MODE_MOTOR}.get(w.mode, K.MODE_FREE)
        if w.motor is not None:
            wp[i, K.W_MSYNC] = w.motor.synchronous_speed
            wp[i, K.W_MTK] = w.motor.breakdown_torque
            wp[i, K.W_MSK] = w.motor.breakdown_slip
        if w.coupling is not None:
            wp[i, K.W_FCK], wp[i, K.W_FCSN], wp[i, K.W_FCC] = w.coupling.kernel_constants()
            wp[i, K.W_FCJ] = w.motor_inertia
        wp[i, K.W_RIPA] = w.ripple
        wp[i, K.W_RIPW] = w.ripple_frequency
        wp[i, K.W_TSTOP] = w.stop_time
        wp[i, K.W_TDOWN] = w.stop_ramp
        wp[i, K.W_OMEGA0] = w.angular_velocity
        wp[i, K.W_RAMP] = w.ramp_time
        wp[i, K.W_TORQUE] = w.torque
        wp[i, K.W_DAMP] = w.damping
    t = model.tensioner
    if t is not None:
        d = np.asarray(t.direction, float)
        d = d / np.hypot(*d)
        wp[t.wheel, K.W_SLIDE] = 1.0
        wp[t.wheel, K.W_DX], wp[t.wheel, K.W_DY] = d
        wp[t.wheel, K.W_SMASS] = t.mass
        wp[t.wheel, K.W_SK] = t.stiffness
        wp[t.wheel, K.W_SC] = t.damping
        wp[t.wheel, K.W_SF] = t.preload
    gd = np.zeros((len(model.guides), K.NGD))
    for g, gu in enumerate(model.guides):
        a = np.asarray(gu.start, float)
        b = np.asarray(gu.end, float)
        length = float(np.hypot(*(b - a)))
        u = (b - a) / length
        gd[g] = [a[0], a[1], u[0], u[1], -u[1], u[0], length,
                 -1.0 if gu.friction is None else gu.friction, gu.material_mass, gu.material_friction]
    return par, wp, gd


ASSEMBLY_METHODS = ("newton", "relaxation")
#: time integrators of :func:`simulate` (same arguments, same records)
INTEGRATORS = {"explicit": K.integrate, "implicit": integrate_implicit}


def assemble(model: SimulationModel, *, dt: float | None = None, method: str = "newton",
             tolerance: float = 1e-7, max_time: float = 3.0) -> State:
    """Chain placed on the wheels and brought to static equilibrium (see module notes).

    Parameters
    ----------
    model : SimulationModel
    dt : float, optional
        Time step of the state's run [s]; default the model's stable step.
    method : {"newton", "relaxation"}
        ``"newton"`` (default): the static equilibrium solved directly
        (:func:`chaindrive.simulation.statics.solve_static`, cost linear in the number of
        links); ``"relaxation"``: dynamic relaxation with the explicit kernel (the
        earlier method; its cost grows with the slowest span period).
    tolerance : float
        Relaxation only: kinetic energy per pin [J] below which the state counts as static.
    max_time : float
        Relaxation only: simulated relaxation time allowed [s].

    Returns
    -------
    State
        The state at rest (driver held, loads on, the tensioner's spring loaded).

    Raises
    ------
    UnknownNameError
        ``method`` not one of ``newton``, ``relaxation``.
    ConvergenceError
        No static state reached.

    Examples
    --------
    >>> from chaindrive.simulation import roller_example, assemble
    >>> st = assemble(roller_example(links=40, teeth=12, gravity=False))
    >>> st.pos.shape
    (40, 2)
    """
    if method not in ASSEMBLY_METHODS:
        raise UnknownNameError(f"assembly method must be one of {', '.join(ASSEMBLY_METHODS)}, "
                               f"got {method!r}")
    pos, theta, centres, adj, d, s0, pieces = _place(model, exact=method == "newton")
    par, wp, gd = kernel_arrays(model, dt)
    dt = par[K.P_DT]
    nw = len(model.wheels)
    wp[:, K.W_CX] = centres[:, 0]
    wp[:, K.W_CY] = centres[:, 1]
    ws = np.zeros((nw, K.NWS))
    ws[:, K.S_THETA] = theta
    run_wp = wp.copy()
    spans = [x[2] for x in pieces if x[0] == "span"]
    if method == "newton":
        # one BLAS thread: the Newton iteration's products are of 2N-vectors, for which a
        # threaded BLAS only adds start-up cost (32 % of a 5,000-link assembly measured)
        with _one_blas_thread():
            return _assemble_newton(model, pos, ws, wp, run_wp, gd, par, adj, d, pieces, s0)
    # relaxation set-up
    lspan = max(min(spans), 5 * model.pitch)
    kspan = model.axial_stiffness / lspan
    q = model.link_mass / model.pitch
    # slowest transverse mode expected: string with pretension
    s_pre = max(model.pretension, 1.0)
    om_low = math.pi / max(spans) * math.sqrt(s_pre / q)
    par[K.P_CGLOB] = 2.0 * om_low
    for i, w in enumerate(model.wheels):
        r = wp[i, K.W_R]
        wp[i, K.W_DAMP] = w.damping + 2.0 * math.sqrt(2 * kspan * r * r * w.inertia)
        if w.mode in ("speed", "motor"):
            wp[i, K.W_MODE] = K.MODE_LOCKED
    if model.tensioner is None:
        wp[adj, K.W_SLIDE] = 1.0
        wp[adj, K.W_DX], wp[adj, K.W_DY] = d
        # temporary slide mass: the links seated on a full turn of the wheel, at least
        # 1 kg (heavy pins with stiff, damped contacts would make a light slide unstable)
        smass = _slide_mass(model, adj)
        wp[adj, K.W_SMASS] = smass
        wp[adj, K.W_SK] = 0.0
        wp[adj, K.W_SF] = 2.0 * model.pretension
        wp[adj, K.W_SC] = 2.0 * math.sqrt(2 * kspan * smass)
    else:
        # critical damping of the slide on its own spring plus the pins' relaxation
        # damping rate (a slack chain must not make the slide creep)
        wp[adj, K.W_SC] = model.tensioner.damping + 2.0 * math.sqrt(
            model.tensioner.stiffness * model.tensioner.mass) \
            + 2.0 * par[K.P_CGLOB] * model.tensioner.mass
    vel = np.zeros_like(pos)
    force = np.zeros_like(pos)
    tension = np.zeros(model.links)
    contact = np.zeros(model.links)
    recs = K.empty_records(1, model.links, nw, 0)
    probes = np.zeros((0, 4))
    chunk = max(int(0.01 / dt), 100)
    t = 0.0
    steps = 0
    # phase 1: no load, the adjusting wheel finds the centre distance for the pretension;
    # phase 2 (drives without tensioner): that wheel fixed, loads applied.
    loads = wp[:, K.W_TORQUE].copy()
    wp[:, K.W_TORQUE] = 0.0
    for phase in (1, 2):
        if phase == 2:
            wp[:, K.W_TORQUE] = loads
            if model.tensioner is None:
                wp[adj, K.W_CX] += ws[adj, K.S_S] * d[0]
                wp[adj, K.W_CY] += ws[adj, K.S_S] * d[1]
                run_wp[adj, K.W_CX], run_wp[adj, K.W_CY] = wp[adj, K.W_CX], wp[adj, K.W_CY]
                ws[adj, K.S_S] = 0.0
                ws[adj, K.S_SDOT] = 0.0
                wp[adj, K.W_SLIDE] = 0.0
        t_phase = 0.0
        converged = False
        vtol = math.sqrt(2.0 * tolerance / model.link_mass)
        while t_phase < max_time:
            K.integrate(pos, vel, force, np.zeros_like(pos), tension, contact, ws, wp, gd, K.seat_table(wp), par, 0.0, chunk,
                        chunk + 1, probes, *recs, 0)
            t_phase += chunk * dt
            steps += chunk
            ek = 0.5 * model.link_mass * float(np.mean(np.sum(vel * vel, axis=1)))
            if ek < tolerance and t_phase > 5.0 / par[K.P_CGLOB] \
                    and np.all(np.abs(ws[:, K.S_OMEGA]) * wp[:, K.W_R] < vtol) \
                    and np.all(np.abs(ws[:, K.S_SDOT]) < vtol):
                converged = True
                break
        t += t_phase
        if not converged:
            raise ConvergenceError(
                f"static assembly (phase {phase}) did not settle within max_time = {max_time:g} s"
                f" (kinetic energy per pin {ek:.3g} J, tolerance {tolerance:g} J; wheel rim "
                f"speeds {np.abs(ws[:, K.S_OMEGA]) * wp[:, K.W_R]} m/s, slide speeds "
                f"{np.abs(ws[:, K.S_SDOT])} m/s, limit {vtol:.3g} m/s)")
    # freeze: adjusting wheel fixed at its found centre unless it is the tensioner
    if model.tensioner is not None:
        # re-centre the slide coordinate: s measured from the assembled position,
        # spring force there = preload + the static spring force found
        s_eq = ws[adj, K.S_S]
        run_wp[adj, K.W_CX] += s_eq * d[0]
        run_wp[adj, K.W_CY] += s_eq * d[1]
        run_wp[adj, K.W_SF] = model.tensioner.preload - model.tensioner.stiffness * s_eq
        ws[adj, K.S_S] = 0.0
    ws[:, K.S_OMEGA] = 0.0
    ws[:, K.S_SDOT] = 0.0
    vel[:] = 0.0
    par[K.P_CGLOB] = 0.0
    st = State(pos, vel, ws, run_wp, gd, par, t, steps)
    return st


def _one_blas_thread():
    """Context limiting BLAS to one thread (``threadpoolctl``; no-op without it)."""
    try:
        from threadpoolctl import threadpool_limits
    except ImportError:  # pragma: no cover - threadpoolctl ships with the fast extra
        from contextlib import nullcontext

        return nullcontext()
    return threadpool_limits(limits=1, user_api="blas")


def _slide_mass(model: SimulationModel, adj: int) -> float:
    """Mass [kg] of the assembly's temporary slide: the links seated on a full turn of the
    adjusting wheel, at least 1 kg (a light slide with heavy, stiffly seated pins made the
    relaxation unstable)."""
    return max(1.0, model.seats_per_turn(model.wheels[adj].teeth) * model.link_mass)


def _assemble_newton(model, pos, ws, wp, run_wp, gd, par, adj, d, pieces, s_metric):
    """Static state by the Newton iteration of :mod:`chaindrive.simulation.statics`.

    Phase 1: no loads, the adjusting wheel on a slide (pushed by ``2 × pretension``, or
    the tensioner on its spring); phase 2 (no tensioner): that wheel fixed where phase 1
    left it, the loads applied (at once, else by :func:`_lead_the_loaded_wheel`). The
    driver is held; free toothed wheels turn.
    """
    from .statics import solve_static

    n = model.links
    nw = len(model.wheels)
    tab = K.seat_table(wp)
    m = model.link_mass
    q = m / model.pitch
    spans = [x[2] for x in pieces if x[0] == "span"]
    om_low = math.pi / max(spans) * math.sqrt(max(model.pretension, 1.0) / q)
    free = [w for w in range(nw) if wp[w, K.W_MODE] == K.MODE_FREE and wp[w, K.W_PLAIN] < 0.5]
    radii = wp[:, K.W_R]
    loads = wp[:, K.W_TORQUE].copy()
    gmag = math.hypot(par[K.P_GX], par[K.P_GY])
    # converged: residual forces below 1e-5 of the chain's tension (pretension, the load's
    # tension, the prestrain's tension), or at the rounding floor of the link forces
    fscale = max(model.pretension, float(np.max(np.abs(loads) / radii)), m * gmag,
                 model.prestrain * model.axial_stiffness)
    xscale = float(np.max(np.abs(pos))) + model.pitch
    ftol = max(1e-5 * fscale, 20.0 * par[K.P_K] * xscale * np.finfo(float).eps)
    wp1 = wp.copy()
    wp1[:, K.W_TORQUE] = 0.0
    if model.tensioner is None:
        wp1[adj, K.W_SLIDE] = 1.0
        wp1[adj, K.W_DX], wp1[adj, K.W_DY] = d
        wp1[adj, K.W_SMASS] = _slide_mass(model, adj)
        wp1[adj, K.W_SK] = 0.0
        wp1[adj, K.W_SF] = 2.0 * model.pretension
    theta = ws[:, K.S_THETA].copy()
    slide = np.zeros(nw)
    iterations = 0
    if model.tensioner is not None:
        # the tensioner's spring preload acts at the metric path's position (as in the
        # relaxation); the exact placement starts it a little off that, on its slide
        shift = float(np.dot(np.subtract((wp[adj, K.W_CX], wp[adj, K.W_CY]),
                                         model.wheels[adj].centre), d)) - s_metric
        for arr in (wp, wp1, run_wp):
            arr[adj, K.W_CX] -= shift * d[0]
            arr[adj, K.W_CY] -= shift * d[1]
        slide[adj] = shift

    def solve(wpx, with_slide, floor, parx=par, max_iterations=400, spring=None, target=None):
        nonlocal iterations
        th_idx = np.full(nw, -1, np.int64)
        s_idx = np.full(nw, -1, np.int64)
        th_idx[free] = 2 * n + np.arange(len(free))
        extra = [theta[free]]
        masses = [np.full(2 * n, m), wpx[free, K.W_INERTIA]]
        scale = [np.ones(2 * n), radii[free]]
        if with_slide:
            s_idx[adj] = 2 * n + len(free)
            extra.append([slide[adj]])
            masses.append([wpx[adj, K.W_SMASS]])
            scale.append([1.0])
        x0 = np.concatenate([pos.ravel()] + [np.asarray(e, float) for e in extra])
        # the step limit applies to the pins near a wheel (or a guide) and to the wheels
        near = np.zeros(n, bool)
        for w in range(nw):
            c = np.array([wpx[w, K.W_CX], wpx[w, K.W_CY]]) + slide[w] * np.asarray(
                [wpx[w, K.W_DX], wpx[w, K.W_DY]])
            near |= np.hypot(*(pos - c).T) < radii[w] + 3.0 * model.pitch
        for g in gd:
            rel = pos - g[:2]
            along = rel @ g[2:4]
            near |= (np.abs(rel @ g[4:6]) < 3.0 * model.pitch) & (along > -3.0 * model.pitch) \
                & (along < g[6] + 3.0 * model.pitch)
        capped = np.concatenate([np.repeat(near, 2).astype(float)] + scale[1:])
        sol = solve_static(x0, n, wpx, theta, slide, th_idx, s_idx, gd, tab, parx,
                           np.concatenate(masses), np.concatenate(scale),
                           pseudo_time=1.0 / om_low, force_tolerance=ftol,
                           tension_floor=floor, max_iterations=max_iterations,
                           max_step=0.25 * model.pitch, capped=capped,
                           angle_spring=spring, angle_target=target)
        pos[:] = sol.x[:2 * n].reshape(n, 2)
        theta[free] = sol.x[th_idx[free]]
        if with_slide:
            slide[adj] = sol.x[s_idx[adj]]
        iterations += sol.iterations

    # 1a: no gravity, every wheel where the placement put it, the links shortened by the
    # pretension strain and the seats' clearance (a slack chain is a mechanism, and a
    # chain whose rollers float in their seats leaves a slide unresisted); 1b: gravity,
    # the links at their length, the wheel on its slide (or the tensioner's spring) sets
    # the pretension
    per_turn = [model.seats_per_turn(w.teeth) if model.is_link_chain else w.path_teeth(model.pitch)
                for w in model.wheels]
    length = n * model.pitch
    wrap = sum(x[2] / model.pitch * 2 * math.pi / per_turn[x[1][0]] for x in pieces
               if x[0] == "arc" and wp[x[1][0], K.W_PLAIN] < 0.5)
    take_up = 2.0 * wrap * max(model.seat - model.roller_radius, 0.0)
    shorten = 1.0 + model.pretension / model.axial_stiffness + take_up / length
    par0 = par.copy()
    par0[K.P_GX] = par0[K.P_GY] = 0.0
    par0[K.P_PITCH] /= shorten
    par0[K.P_PITCH2] /= shorten
    solve(wp1, False, model.pretension, par0)
    solve(wp1, True, model.pretension)
    wp2 = wp1.copy()
    with_slide = model.tensioner is not None
    if not with_slide:
        for arr in (wp2, run_wp):
            arr[adj, K.W_CX] += slide[adj] * d[0]
            arr[adj, K.W_CY] += slide[adj] * d[1]
        wp2[adj, K.W_SLIDE] = 0.0
        slide[adj] = 0.0
    # 2: the loads. A load that straightens a sagging span turns the free wheels with
    # their seated rollers through the polygon's cogging, a large motion a Newton step
    # cannot take at once: then the loaded wheel's angle is led there (angle control).
    wp2[:, K.W_TORQUE] = loads
    saved = pos.copy(), theta.copy(), slide.copy(), iterations
    loaded = [w for w in free if loads[w] != 0.0]
    try:
        solve(wp2, with_slide, 0.0, max_iterations=80)
    except ConvergenceError:
        pos[:], theta[:], slide[:], iterations = saved
        if len(loaded) != 1:
            raise
        _lead_the_loaded_wheel(model, loaded[0], loads[loaded[0]], wp2, theta,
                               lambda wpx, **kw: solve(wpx, with_slide, 0.0, **kw))
        solve(wp2, with_slide, 0.0)
    if with_slide:
        # re-centre the slide coordinate: s from the assembled position, spring force
        # there = preload + the static spring force found
        s_eq = slide[adj]
        run_wp[adj, K.W_CX] += s_eq * d[0]
        run_wp[adj, K.W_CY] += s_eq * d[1]
        run_wp[adj, K.W_SF] = model.tensioner.preload - model.tensioner.stiffness * s_eq
    ws = ws.copy()
    ws[:, K.S_THETA] = theta
    ws[:, K.S_OMEGA] = 0.0
    ws[:, K.S_S] = 0.0
    ws[:, K.S_SDOT] = 0.0
    par = par.copy()
    par[K.P_CGLOB] = 0.0
    return State(pos, np.zeros_like(pos), ws, run_wp, gd, par, 0.0, iterations)


def _lead_the_loaded_wheel(model, wheel, torque, wp, theta, solve):
    """Turn the loaded free wheel by angle control until the chain holds its load.

    The wheel's angle is tied to a target by a stiff torsion spring (100 times the load
    per pitch angle) and the target moves in eighths of a pitch angle in the sense of the
    load, each step solved from the last; it stops once the spring carries the load
    (the chain's torque, read from the spring, reaches it), where the free Newton
    iteration with the load on takes over. Angle control follows the torque-angle curve
    through the polygon's cogging, which load increments cannot.
    """
    nw = wp.shape[0]
    pitch_angle = 2.0 * math.pi / wp[wheel, K.W_NSEAT]
    stiffness = 100.0 * abs(torque) / pitch_angle
    spring = np.zeros(nw)
    spring[wheel] = stiffness
    target = theta.copy()
    wpc = wp.copy()
    wpc[wheel, K.W_TORQUE] = 0.0
    sense = math.copysign(1.0, torque)
    for _ in range(4000):
        target[wheel] += sense * pitch_angle / 8.0
        solve(wpc, spring=spring, target=target, max_iterations=200)
        # the spring's torque k (θ − θ_t) holds the chain's; the load would be −τ
        if sense * (stiffness * (theta[wheel] - target[wheel]) + torque) <= 0.0:
            return
    raise ConvergenceError(f"static assembly: wheel {wheel} turned 500 pitches without the "
                           f"chain holding its load {torque:g} N m")


def simulate(model: SimulationModel, duration: float, *, dt: float | None = None,
             record_every: int | None = None, samples: int = 2000, probes: ArrayLike | None = None,
             state: State | None = None, settle: float | None = None,
             progress: Callable[[int, int], object] | None = None, chunks: int = 50,
             method: str = "explicit") -> SimulationResult:
    """Assemble ``model`` in static equilibrium and integrate it for ``duration`` [s].

    Parameters
    ----------
    model : SimulationModel
    duration : float
        Simulated time [s].
    dt : float, optional
        Time step [s]; default :meth:`SimulationModel.stable_time_step`.
    record_every : int, optional
        Steps between samples; default so that about ``samples`` samples are stored.
    probes : array (P, 4), optional
        Probe points ``(x, y, ux, uy)``; default the middle of the tight span.
    state : State, optional
        Start state (from :func:`assemble`, or a previous result's ``final_state``:
        the run continues from its time, the driver's speed ramp included); default a
        fresh assembly.
    settle : float, optional
        Start of the steady window of the summary [s] (absolute time); default half way
        through this run.
    progress : callable, optional
        Called as ``progress(done_steps, total_steps)`` between chunks.
    method : {"explicit", "implicit"}
        ``"explicit"`` (default): symplectic Euler, ``dt`` by default the stable step
        :meth:`SimulationModel.stable_time_step`; ``"implicit"``: the linearly implicit
        step (link springs, contact springs and sticking friction implicit), ``dt`` by
        default :meth:`SimulationModel.accurate_time_step` (see docs/simulation.md,
        "Integrator").

    Returns
    -------
    SimulationResult

    Examples
    --------
    >>> from chaindrive.simulation import roller_example, simulate
    >>> m = roller_example(links=30, teeth=11, angular_velocity=5.0, ramp_time=0.005)
    >>> r = simulate(m, 0.01, samples=20)
    >>> r.tension.shape[1], bool(r.summary["tight_side_tension_mean"] > 0)
    (30, True)
    """
    from .._validation import check_positive

    check_positive("duration", duration)
    from ..limits import check_duration

    check_duration("duration", duration)  # at most chaindrive.limits.MAX_DURATION, before any work
    if method not in INTEGRATORS:
        raise UnknownNameError(f"method must be one of {', '.join(INTEGRATORS)}, got {method!r}")
    integrate = INTEGRATORS[method]
    if dt is None and method == "implicit":
        dt = model.accurate_time_step()
    if dt is not None:
        check_positive("dt", dt)
    if state is None:
        state = assemble(model, dt=dt)
    par = state.par.copy()
    par[K.P_CSPAN] = model.span_damping_rate()  # the model's, whatever state it starts from
    if dt is not None:
        par[K.P_DT] = dt
    dt = float(par[K.P_DT])
    nsteps = max(int(round(duration / dt)), 1)
    if record_every is None:
        record_every = max(nsteps // samples, 1)
    nrec = (nsteps + record_every - 1) // record_every
    if probes is None:
        probes = default_probes(model, state)
    probes = np.ascontiguousarray(np.atleast_2d(np.asarray(probes, float)))
    pos = state.pos.copy()
    vel = state.vel.copy()
    ws = state.ws.copy()
    wp = state.wp.copy()
    n = model.links
    nw = len(model.wheels)
    recs = K.empty_records(nrec, n, nw, probes.shape[0])
    force = np.zeros_like(pos)
    tension = np.zeros(n)
    contact = np.zeros(n)
    # chunks that are whole multiples of record_every
    tab = K.seat_table(wp)
    per = max(((nsteps // max(chunks, 1)) // record_every) * record_every, record_every)
    done = 0
    written = 0
    wall = 0.0
    while done < nsteps:
        m = min(per, nsteps - done)
        t0 = time.perf_counter()
        written = integrate(pos, vel, force, np.zeros_like(pos), tension, contact, ws, wp, state.gd, tab, par,
                              state.time + done * dt, m, record_every, probes, *recs, written)
        wall += time.perf_counter() - t0
        done += m
        if progress is not None:
            progress(done, nsteps)
    rt, rprobe, rten, rcon, rws, rpos, ren = (r[:written] for r in recs)
    p1, p2 = tight_span(model, state)
    res = SimulationResult(
        time=rt, probe_points=probes, chain_velocity=rprobe, tension=rten, contact_force=rcon,
        wheel_angle=rws[:, :, K.S_THETA], wheel_speed=rws[:, :, K.S_OMEGA],
        wheel_torque=rws[:, :, K.S_TORQUE], tensioner_position=rws[:, :, K.S_S],
        motor_speed=rws[:, :, K.S_MOTOR],
        positions=rpos, energy=ren,
        wheel_centres=np.column_stack([wp[:, K.W_CX], wp[:, K.W_CY]]),
        pitch_radii=wp[:, K.W_R].copy(), teeth=wp[:, K.W_Z].astype(int),
        tight_span=np.array([p1, p2]), slack_span=np.array(slack_span(model, state)), pitch=model.pitch, roller_radius=model.roller_radius,
        dt=dt, steps=nsteps, wall_time=wall, assembly_time=state.relax_time,
        guide_segments=np.array([[g.start, g.end] for g in model.guides], float).reshape(-1, 2, 2))
    object.__setattr__(res, "summary", _summary(res, state.time + 0.5 * duration if settle is None else settle))  # frozen
    #: state at the end of the run (not a dataclass field: not saved)
    object.__setattr__(res, "final_state", State(pos, vel, ws, wp, state.gd, par, state.relax_time,
                                                 state.relax_steps, state.time + nsteps * dt))  # not a field
    return res


#: Most halvings :func:`step_for_accuracy` tries (a step 1/1024 of the first).
MAX_HALVINGS = 10


def step_for_accuracy(model: SimulationModel, duration: float, *, state: State | None = None,
                      tolerance: float = 0.01, start: float | None = None,
                      method: str = "implicit", max_halvings: int = 6) -> float:
    """Largest step [s] of a halving ladder whose results hold against the halved step.

    Runs ``start``, ``start/2``, … (``start`` default twice
    :meth:`SimulationModel.accurate_time_step` for the implicit integrator, the stable
    step for the explicit one) from the same state and returns the first step whose mean
    chain speed and mean tight-side tension (steady window: the second half of the run)
    differ from those at its half by at most ``tolerance`` (relative).

    Parameters
    ----------
    model : SimulationModel
    duration : float
        Simulated time of each run [s].
    state : State, optional
        Start state; default a fresh assembly.
    tolerance : float
        Relative change allowed against the halved step, 0 < tolerance < 1.
    start : float, optional
        First step of the ladder [s].
    method : {"explicit", "implicit"}
    max_halvings : int
        Halvings tried before giving up, 0 to :data:`MAX_HALVINGS`.

    Returns
    -------
    float
        The step [s].

    Raises
    ------
    InputError
        ``tolerance`` not in [1e-9, 1), ``max_halvings`` not in [0, MAX_HALVINGS].
    ConvergenceError
        No step of the ladder holds.

    Examples
    --------
    >>> from chaindrive.simulation import roller_example
    >>> from chaindrive.simulation.run import step_for_accuracy
    >>> m = roller_example(links=30, teeth=11, angular_velocity=5.0, ramp_time=0.005)
    >>> step_for_accuracy(m, 0.02, tolerance=0.02) >= m.stable_time_step()
    True
    """
    if not 1e-9 <= tolerance < 1.0:
        raise InputError(f"tolerance must be in [1e-9, 1) (relative; below 1e-9 rounding decides), got {tolerance!r}",
                         field="tolerance")
    if isinstance(max_halvings, bool) or not isinstance(max_halvings, int) or not 0 <= max_halvings <= MAX_HALVINGS:
        raise InputError(f"max_halvings must be a whole number in [0, {MAX_HALVINGS}] (each halving doubles the "
                         f"work), got {max_halvings!r}", field="max_halvings")
    if state is None:
        state = assemble(model)
    if start is None:
        start = 2.0 * model.accurate_time_step() if method == "implicit" else model.stable_time_step()

    def means(dt: float) -> tuple[float, float]:
        s = simulate(model, duration, state=state, dt=dt, method=method, samples=400).summary
        return float(s["chain_velocity_mean"][0]), float(s["tight_side_tension_mean"])

    dt = float(start)
    here = means(dt)
    for _ in range(max_halvings):
        half = means(0.5 * dt)
        if all(abs(a - b) <= tolerance * abs(b) for a, b in zip(here, half, strict=True)):
            return dt
        dt, here = 0.5 * dt, half
    raise ConvergenceError(f"no step from {start:.3g} s down to {dt:.3g} s holds its mean chain "
                           f"speed and tight-side tension within {tolerance:g} against the halved step")


def conservative(state: State) -> State:
    """Copy of ``state`` without any dissipation or external work.

    Link, contact and guide damping, friction and bearing damping set to zero, every
    wheel free without applied torque and every slide without damper: the remaining
    system (springs, penalty contacts, inertia, gravity) is conservative, which is what
    the energy check needs.
    """
    par = state.par.copy()
    par[K.P_C] = 0.0
    par[K.P_CC] = 0.0
    par[K.P_CG] = 0.0
    par[K.P_MU] = 0.0
    par[K.P_CGLOB] = 0.0
    wp = state.wp.copy()
    wp[:, K.W_MODE] = K.MODE_FREE
    wp[:, K.W_TORQUE] = 0.0
    wp[:, K.W_DAMP] = 0.0
    wp[:, K.W_SC] = 0.0
    return State(state.pos.copy(), state.vel.copy(), state.ws.copy(), wp, state.gd.copy(), par,
                 state.relax_time, state.relax_steps, state.time)



from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
