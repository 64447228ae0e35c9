"""Benchmark of chaindrive.simulation against MuJoCo on the same chain drive.

Drive: ISO 606 16B simplex chain, 100 links, two 17-tooth sprockets, centre distance
(100 - 17)/2 p = 1.054 m; driver ramped to 20 rad/s in 0.1 s, 200 N m load on the
driven wheel (tight side ~3.1 kN), gravity. Both start from the same statically
assembled state (chaindrive's static solve).

chaindrive: point-mass pins, axial spring-dampers (EA = 1e8 N), penalty contact of each
roller with the ISO 606 seat/flank profile; two integrators: symplectic Euler at its
largest stable step (``method="explicit"``, 3 µs) and the linearly implicit step
(``method="implicit"``: link springs, contact springs, sticking friction implicit; a
cyclic tridiagonal solve per step) on the ladder 200, 100, 50, 25 µs.

MuJoCo (the peer), the same model:

* the same 100 rollers as point bodies (two slide joints each, x-z plane) with sphere
  geoms of the roller radius and the link mass;
* links as spatial tendons between consecutive rollers with the same ``k = EA/p``,
  damping ``c`` and rest length ``p``;
* teeth with chaindrive's working profile, built from boxes: in every gap the seating
  arc (radius ``r_s = 0.505 d1``, ``±ψ_s``, ``ψ_s = 70° − 45°/z``) is replaced by
  ``FACES − 1`` flat faces tangent to it, and each ISO 606 convex flank arc (``r_e``,
  tangent to the seat at ``±ψ_s``, up to the tooth corner on the tip circle; see
  ``chaindrive.simulation.model.iso_flank``) by ``FLANK_FACES`` flat faces tangent to
  it (a roller touching the kernel's flank lies within 5 µm of them; with
  ``tooth_flank="straight"`` one box face per straight flank). Because ``r_s − r`` is only
  80 µm, the roller centre's free region in this polygonal seat differs from the
  circular one by ``(r_s − r)(1/cos(Δ/2) − 1)`` < 4 µm; a roller beyond the flank
  meets the box edge at the tooth corner, as in chaindrive. (A whole tooth is not
  convex, the seating arcs are concave, so one convex mesh per tooth would fill the
  seats; boxes also get MuJoCo's analytic sphere-box collider instead of the general
  convex one);
* contacts: friction 0.1 on both geoms (MuJoCo takes the larger of the two), elliptic
  cone so that the in-plane Coulomb limit is exactly μ F_n whatever the orientation of
  the contact frame's tangent axes, ``condim = 3``; normal law in MuJoCo's direct form
  ``solref = (−k_c/m, −c_c/m)`` = chaindrive's contact stiffness and damping per unit
  roller mass, ``solimp`` with ``d_min = d_max = 0.95``: the free contact oscillation
  then has chaindrive's frequency ``sqrt(k_c/m)`` and damping ratio 0.2, while the
  static penetration is ``(1 − d)`` of the penalty one (≤ 1 µm instead of ~15 µm;
  both negligible against the profile);
* wheels: hinges with the same inertias; the driver by a velocity servo (``kv = 1e5``
  N m s, steady speed error 200/1e5 = 0.002 rad/s = 0.01 %) following the same ramp, the
  driven wheel loaded by the same torque through ``qfrc_applied``; gravity;
* integrator ``implicitfast`` (tendon damping and the servo's velocity gain implicit;
  tendon stiffness explicit, which sets MuJoCo's stable step to ~2/sqrt(4k/m), as the
  link stiffness does for chaindrive).

MuJoCo with rigid links (``rigid=True``): the same bodies, geoms and wheels, the links as
spatial tendons whose length is held by an equality constraint (``<equality><tendon>``,
the length at the assembled state); contacts and length constraints soft with MuJoCo's
standard ``solref = (2e-4 s, 1)`` and ``solimp`` 0.99 (the direct contact stiffness of the
stiff model is unstable above ~5 µs); its ladder 100, 50, 25 µs (``timeconst >= 2 dt``).
The link tension is read from the equality constraint's force.

MuJoCo first settles from chaindrive's assembled state with the driver held and the load
on (velocities quenched, 0.02 s, not timed), then runs the same duration. Its step is the
largest of a ladder at which the run stays finite, raises no divergence warning and the
driven wheel follows the driver; then half and quarter of it for a convergence check
(from the same settled state). chaindrive runs at its default step, half and quarter.

"Equal accuracy": each engine is timed at the largest step whose results are converged
against its own halved step (mean tight-side tension within 1 %, mean chain speed within
0.5 %) and within 1 % of the reference (chaindrive's explicit run, mean speed and mean
tight-side tension); the report prints, per engine, that step, its CPU time per simulated
second and the differences, then ``vs MuJoCo rigid links: R x`` and ``vs MuJoCo stiff
links: R x`` (MuJoCo's CPU time per simulated second over chaindrive's implicit one). CPU
times (``time.process_time``; MuJoCo's Python sampling excluded, chaindrive timed in a
second run without records): the machine is shared, the load average is printed.

MuJoCo settings used (mujoco.readthedocs.io):
  direct solref (-stiffness, -damping), scaled by the impedance:
    https://mujoco.readthedocs.io/en/stable/modeling.html#solver-parameters
    https://mujoco.readthedocs.io/en/stable/modeling.html#restitution
  soft-constraint dynamics a1 + d (b v + k r) = (1 - d) a0, solimp d(r):
    https://mujoco.readthedocs.io/en/stable/computation/index.html#soft-constraints
  friction combination (max of the two geoms) and condim:
    https://mujoco.readthedocs.io/en/stable/modeling.html#contact-parameters
  cone="elliptic", integrator="implicitfast":
    https://mujoco.readthedocs.io/en/stable/XMLreference.html#option
  spatial tendon stiffness/damping/springlength:
    https://mujoco.readthedocs.io/en/stable/XMLreference.html#tendon-spatial

Scaling (``--scaling``): the same drive with N = 100, 500, 1000, 2000, 5000 links (the
centre distance grows with N; the pretension is that of a 2 % sag of the span, at least
200 N, so that the long spans are drives and not hanging ropes), one line per length:
assembly CPU time, link-steps/s of both integrators and their CPU time per simulated
second (the implicit one at its default step); and the plain compiled point-mass chain (the
same closed loop of springs and masses in the vectorised layout, separate x/y arrays,
symplectic Euler, no contacts, no records) as the ceiling of a link-steps/s figure on this
machine.

Steady state (``--steady``, also in the default run): ``steady_state`` of the same drive
from nothing against an ensemble of four explicit runs measured 8 s, 8 s after the warm start
(benchmarks/_steady.py; also the early reference 0.5-8.5 s and the exact integrator over the
steady state's own window), printing
``steady state, 16B 100 links: X s CPU, within Y % of the reference``.

Batched (``--batched``, also after the scaling): the batched kernel
(``chaindrive.simulation._batched``, variants as the inner, vectorised dimension) on 64
variants of the 100-link drive (speed and load drawn at random), printing ``batched, N
variants: R link-steps/s per core, F of the ceiling`` (and of the ceiling compiled with
``error_model="numpy"``, whose link loop runs as vector instructions; the batched kernel is
compiled so); then the batched implicit kernel (``chaindrive.simulation._batched_implicit``,
each variant bit-equal to the single implicit kernel) on the same 64 variants at their
accurate implicit step: ``batched implicit, N variants: R link-steps/s per core, F of the
ceiling`` and its ratio to the single implicit kernel on the same variants in the same run.
With ``--batched`` alone, each kernel also with the span damping (each variant its own
default ``α = 2 ζ z ω``, ``ζ = 0.02`` at its tooth frequency), both rates in the same run;
the other runs measure the drives without it.

Exudyn (``--exudyn``): the same drive, benchmarks/peers/exudyn_drive.py (its docstring).

Run:  .venv/bin/python benchmarks/simulate.py [--mujoco] [--duration 0.3] [--no-mujoco]
                                              [--quick] [--no-scaling] [--steady] [--exudyn]
      .venv/bin/python benchmarks/simulate.py --scaling        (the scaling only)
"""

from __future__ import annotations

import argparse
import math
import time

import numpy as np

from chaindrive.simulation import _kernel as K
from chaindrive.simulation import assemble, roller_example, simulate
from chaindrive.simulation.model import iso_flank

#: convergence tolerances against the halved step (relative)
TOL_TENSION = 0.01
TOL_SPEED = 0.005
#: equal accuracy: mean speed and mean tight-side tension within this of the reference
#: (chaindrive's explicit integrator at its converged step)
TOL_REF = 0.01
#: flat faces replacing each seating arc (FACES - 1 inner faces plus the two flanks)
FLANK_FACES = 6  # flat faces per ISO flank arc (tangent polygon, < 5 µm from the arc)
FACES = 4
#: sampling interval of chain speed and tension, the same for both engines [s]
SAMPLE = 1.5e-4
#: start of the steady window [s] (ramp ends at 0.1 s)
STEADY = 0.15
#: time constant [s] of MuJoCo's soft constraints in the rigid-link model (contacts and
#: link lengths): 2 x the largest step of its ladder
RIGID_TC = 2.0e-4
#: step ladders [s]: chaindrive's implicit integrator, MuJoCo's rigid-link model
IMPLICIT_LADDER = (2.0e-4, 1.0e-4, 5.0e-5, 2.5e-5)
RIGID_LADDER = (1.0e-4, 5.0e-5, 2.5e-5)


def build():
    # the peers (MuJoCo, Exudyn) model no span damping: the same drive with none
    # (span_damping = 0; chaindrive's default is zeta = 0.02 at the tooth frequency)
    model = roller_example(links=100, teeth=17, angular_velocity=20.0, load_torque=200.0,
                           ramp_time=0.1, span_damping=0.0)
    state = assemble(model)
    return model, state


def run_chaindrive(model, state, duration, dt=None, method="explicit"):
    """One chaindrive run (results) and its CPU time per simulated second (a second run
    with two records, so that the sampling and the summary are not timed)."""
    simulate(model, 0.002, state=state, dt=dt, method=method)  # compile / warm the cache
    r = simulate(model, duration, state=state, settle=STEADY, dt=dt, method=method,
                 samples=max(int(round(duration / SAMPLE)), 2))
    t0 = time.process_time()
    rt = simulate(model, duration, state=state, settle=STEADY, dt=dt, method=method, samples=2)
    cpu = time.process_time() - t0
    s = r.summary
    return {
        "name": f"chaindrive {method[:4]}",
        "dt": r.dt,
        "steps": r.steps,
        "wall": cpu,
        "link_steps_per_s": rt.steps * model.links / cpu,
        "wall_per_sim_s": cpu / (rt.steps * rt.dt),
        "v_mean": s["chain_velocity_mean"][0],
        "v_peak": s["chain_velocity_max"][0],
        "tight_mean": s["tight_side_tension_mean"],
        "tight_max": s["tight_side_tension_max"],
        "wheel1": s["wheel_speed_mean"][1],
    }, r


# --- MuJoCo model ---------------------------------------------------------------------

def _box(origin, p_ab, t_ab, n_ab, e_a, e_b, half_len, half_thick):
    """MJCF box whose face (centre p, direction t; gap frame at ``origin``) bounds material on
    the side n."""
    c = p_ab + half_thick * n_ab
    cx, cz = origin + c[0] * e_a + c[1] * e_b
    tx, tz = t_ab[0] * e_a + t_ab[1] * e_b
    al = math.atan2(tz, tx)
    # rotation by al about -y turns local x into (cos al, 0, sin al): counter-clockwise in
    # the x-z plane, like the wheel hinges (axis -y)
    return (f'<geom type="box" size="{half_len:.9g} 0.01 {half_thick:.9g}" '
            f'pos="{cx:.10g} 0 {cz:.10g}" quat="{math.cos(al / 2):.12g} 0 {-math.sin(al / 2):.12g} 0"/>')


def tooth_geoms(model, teeth, faces=FACES):
    """Box geoms (wheel frame) of chaindrive's tooth-gap profile, see the module docstring."""
    rad = model.pitch / (2 * math.sin(math.pi / teeth))
    rs = model.seat
    rr = model.roller_radius
    psi = model.seat_angle(teeth)
    cps, sps = math.cos(psi), math.sin(psi)
    delta = rs - rr
    # the flank as in the kernel: the ISO 606 convex arc r_e (model.tooth_flank == "arc")
    # up to the tooth corner, or the straight flank truncated where the roller centre
    # reaches h_a
    arc = model.tooth_flank == "arc"
    if arc:
        re, cea, ceb, _, _, dta, dtb = iso_flank(model.pitch, teeth, rr, rs, psi, model.tip(teeth))
        th_e = math.atan2(-sps, cps)
        sweep = math.atan2(cps * dtb + sps * dta, cps * dta - sps * dtb)
        dth = sweep / FLANK_FACES
        hf = re * math.tan(0.5 * dth)
    stip = (model.tip(teeth) + delta * cps) / sps
    dphi = 2 * psi / faces
    hl = rs * math.tan(0.5 * dphi)  # half length of an arc face (tangent polygon)
    out = []
    for g in range(teeth):
        be = 2 * math.pi * g / teeth
        e_a = np.array([math.cos(be), math.sin(be)])
        e_b = np.array([-math.sin(be), math.cos(be)])
        seat_c = rad * e_a
        for k in range(1, faces):
            phi = -psi + k * dphi
            n = np.array([-math.cos(phi), math.sin(phi)])  # into the material
            t = np.array([math.sin(phi), math.cos(phi)])
            out.append(_box(seat_c, rs * n, t, n, e_a, e_b, hl, 1.0e-3))
        for s in (-1.0, 1.0):
            n = np.array([-cps, s * sps])
            t = np.array([sps, s * cps])  # outwards along the flank
            p0 = rs * n
            if not arc:
                mid = p0 + 0.5 * (stip - hl) * t
                out.append(_box(seat_c, mid, t, n, e_a, e_b, 0.5 * (stip + hl), 0.75e-3))
                continue
            # convex flank arc: FLANK_FACES faces tangent to it (tangent polygon), the first
            # one extended back over the seat's last half face
            for k in range(FLANK_FACES):
                th = th_e + (k + 0.5) * dth
                u = np.array([math.cos(th), s * math.sin(th)])
                centre = np.array([cea, s * ceb]) + re * u
                tf = np.array([-math.sin(th), s * math.cos(th)])
                out.append(_box(seat_c, centre, tf, -u, e_a, e_b, hf, 0.75e-3))
    return out


def mujoco_xml(model, state, dt, dmax=0.95, kv=1.0e5, faces=FACES, rigid=False):
    """MJCF of the drive (x-z plane, gravity -z); ``rigid``: links as length constraints
    (tendon equalities) instead of stiff tendons."""
    p = model.pitch
    rr = model.roller_radius
    m = model.link_mass
    mu = model.friction
    # direct form: (-stiffness, -damping) per unit mass of the roller
    solref = f"{-model.contact_stiffness / m:.9g} {-model.contact_damping / m:.9g}"
    solimp = f"{dmax} {dmax} 0.001 0.5 2"
    if rigid:
        # MuJoCo's rigid limit: contacts and link lengths as soft constraints with the
        # time constant RIGID_TC, the same on every step of the ladder (>= 2 dt, MuJoCo's
        # advice), critically damped, impedance 0.99 (with 0.95 and 4e-4 s the mean speed
        # came out 3 % high: the rollers sank into the soft seats)
        solref = f"{RIGID_TC:.6g} 1"
        solimp = "0.99 0.99 0.001 0.5 2"
    wl = []
    for j, w in enumerate(model.wheels):
        cx, cy = state.wp[j, K.W_CX], state.wp[j, K.W_CY]
        teeth = "".join(tooth_geoms(model, w.teeth, faces))
        wl.append(f'<body name="wheel{j}" pos="{cx:.12g} 0 {cy:.12g}" childclass="tooth">'
                  f'<joint name="w{j}" type="hinge" axis="0 -1 0"/>'
                  f'<inertial pos="0 0 0" mass="1" diaginertia="{w.inertia:.9g} {w.inertia:.9g} '
                  f'{w.inertia:.9g}"/>'
                  f'{teeth}</body>')
    pins = []
    for i, (x, z) in enumerate(state.pos):
        pins.append(f'<body name="p{i}" pos="{x:.12g} 0 {z:.12g}">'
                    f'<joint name="px{i}" type="slide" axis="1 0 0"/>'
                    f'<joint name="pz{i}" type="slide" axis="0 0 1"/>'
                    f'<geom class="roller" size="{rr:.9g}" mass="{m:.9g}"/>'
                    f'<site name="s{i}"/></body>')
    tendons = []
    n = len(state.pos)
    equality = []
    for i in range(n):
        j = (i + 1) % n
        if rigid:
            # length held at its assembled value (qpos0 = the assembled state) by a soft
            # equality constraint (MuJoCo's rigid limit)
            tendons.append(f'<spatial name="t{i}"><site site="s{i}"/><site site="s{j}"/></spatial>')
            equality.append(f'<tendon tendon1="t{i}" solref="{RIGID_TC:.6g} 1" '
                            f'solimp="{solimp}"/>')
            continue
        tendons.append(f'<spatial stiffness="{model.link_stiffness:.12g}" '
                       f'damping="{model.link_damping:.9g}" springlength="{p:.12g}">'
                       f'<site site="s{i}"/><site site="s{j}"/></spatial>')
    return f"""<mujoco model="chain drive">
  <option timestep="{dt:.6g}" gravity="0 0 -9.81" integrator="implicitfast" cone="elliptic"/>
  <default>
    <geom solref="{solref}" solimp="{solimp}" condim="{3 if mu > 0 else 1}" friction="{max(mu, 1e-5)} 0 0"/>
    <default class="roller"><geom type="sphere" contype="1" conaffinity="2"/></default>
    <default class="tooth"><geom type="box" contype="2" conaffinity="1" mass="0"/></default>
  </default>
  <worldbody>{''.join(wl)}{''.join(pins)}</worldbody>
  <tendon>{''.join(tendons)}</tendon>
  <equality>{''.join(equality)}</equality>
  <actuator><velocity joint="w0" kv="{kv:.6g}"/></actuator>
</mujoco>"""


def settle_mujoco(model, state, dt, settle=0.02, **opts):
    """MuJoCo model and data settled from chaindrive's assembled state (driver held)."""
    import mujoco

    m = mujoco.MjModel.from_xml_string(mujoco_xml(model, state, dt, **opts))
    d = mujoco.MjData(m)
    d.qpos[0] = state.ws[0, K.S_THETA]
    d.qpos[1] = state.ws[1, K.S_THETA]
    load = model.wheels[1].torque
    d.ctrl[0] = 0.0
    nq = int(settle / dt)
    for s in range(nq):
        d.qfrc_applied[1] = load
        mujoco.mj_step(m, d)
        if s % 500 == 0 and s < nq - 1000:
            d.qvel[:] = 0.0
        if not np.all(np.isfinite(d.qpos)):
            return m, None
    if d.warning[mujoco.mjtWarning.mjWARN_BADQACC].number > 0:
        return m, None
    d.qvel[:] = 0.0
    d.time = 0.0
    return m, d


def run_mujoco(model, state, duration, dt, probe, tight_mid, start=None, **opts):
    """One timed MuJoCo run; ``start``: qpos of a settled state to start from; ``opts`` go to
    :func:`mujoco_xml`."""
    import mujoco

    m, d = settle_mujoco(model, state, dt, settle=0.0 if start is not None else 0.02, **opts)
    if d is None:
        print(f"    mujoco dt = {dt:g}: diverged while settling")
        return None
    if start is not None:
        d.qpos[:] = start
        d.qvel[:] = 0.0
    settled = d.qpos.copy()
    w0 = model.wheels[0]
    load = model.wheels[1].torque
    nsteps = int(round(duration / dt))
    every = max(int(round(SAMPLE / dt)), 1)
    n = model.links
    pin_adr = np.array([m.jnt_qposadr[m.joint(f"px{i}").id] for i in range(n)])
    vel_adr = np.array([m.jnt_dofadr[m.joint(f"px{i}").id] for i in range(n)])
    k, c, p = model.link_stiffness, model.link_damping, model.pitch
    times, v, ten, w1 = [], [], [], []
    ramp_t = w0.ramp_time
    om0 = w0.angular_velocity
    step = mujoco.mj_step
    qfrc = d.qfrc_applied
    ctrl = d.ctrl
    rigid = opts.get("rigid", False)
    eq_rows = np.zeros(n, int)
    sampling = 0.0
    t0 = time.process_time()
    for s in range(nsteps):
        t = s * dt
        # chaindrive sets the driver speed at the end of the step, t + dt
        ctrl[0] = om0 * min(1.0, (t + dt) / ramp_t) if ramp_t > 0 else om0
        qfrc[1] = load
        step(m, d)
        if s % every == 0:
            ts = time.process_time()
            xz = state.pos + np.column_stack([d.qpos[pin_adr], d.qpos[pin_adr + 1]])
            if not np.all(np.isfinite(xz)):
                print(f"    mujoco dt = {dt:g}: non-finite state at t = {t:.4f} s")
                return None
            ib = np.argmin(np.sum((xz - probe[:2]) ** 2, axis=1))
            v.append(d.qvel[vel_adr[ib]] * probe[2] + d.qvel[vel_adr[ib] + 1] * probe[3])
            mid = 0.5 * (xz + np.roll(xz, -1, axis=0))
            il = np.argmin(np.sum((mid - tight_mid) ** 2, axis=1))
            if rigid:
                # the equality constraint's force (tension: the length's force negative)
                rows = np.nonzero(d.efc_type[:d.nefc] == mujoco.mjtConstraint.mjCNSTR_EQUALITY)[0]
                eq_rows[d.efc_id[rows]] = rows
                ten.append(-d.efc_force[eq_rows[il]])
            else:
                # link force as chaindrive records it: spring + damper
                ten.append(k * (d.ten_length[il] - p) + c * d.ten_velocity[il])
            w1.append(d.qvel[1])
            times.append(t)
            sampling += time.process_time() - ts
    # CPU time of the steps alone (the Python sampling above excluded)
    wall = time.process_time() - t0 - sampling
    if d.warning[mujoco.mjtWarning.mjWARN_BADQACC].number > 0:
        print(f"    mujoco dt = {dt:g}: divergence warning (bad qacc)")
        return None
    times, v, ten, w1 = map(np.asarray, (times, v, ten, w1))
    sel = times >= STEADY
    res = {
        "name": "mujoco rigid" if rigid else "mujoco stiff",
        "dt": dt,
        "steps": nsteps,
        "wall": wall,
        "link_steps_per_s": nsteps * n / wall,
        "wall_per_sim_s": wall / (nsteps * dt),
        "v_mean": float(np.mean(v[sel])),
        "v_peak": float(np.max(v[sel])),
        "tight_mean": float(np.mean(ten[sel])),
        "tight_max": float(np.max(ten[sel])),
        "wheel1": float(np.mean(w1[sel])),
        "settled": settled,
    }
    # the chain must still run on the wheels: the driven wheel follows the driver
    if not abs(res["wheel1"] / om0 - 1.0) < 0.05:
        print(f"    mujoco dt = {dt:g}: driven wheel at {res['wheel1']:.3f} rad/s, chain off")
        return None
    return res


# --- report ---------------------------------------------------------------------------

def _rel(a, b, key):
    return a[key] / b[key] - 1.0


def converged(rows):
    """Mark each row's change against the next (halved-step) row; return the first converged."""
    pick = None
    for a, b in zip(rows, rows[1:], strict=False):
        a["d_v"] = _rel(a, b, "v_mean")
        a["d_vp"] = _rel(a, b, "v_peak")
        a["d_s"] = _rel(a, b, "tight_mean")
        a["conv"] = abs(a["d_v"]) <= TOL_SPEED and abs(a["d_s"]) <= TOL_TENSION
        if pick is None and a["conv"]:
            pick = a
    return pick


def print_table(rows):
    hdr = (f"{'engine':<14}{'dt [us]':>8}{'link-steps/s':>13}{'wall s/sim s':>13}"
           f"{'v mean':>8}{'v peak':>8}{'S tight':>9}{'S max':>9}"
           f"{'dv/v':>8}{'dvpk':>8}{'dS/S':>8}  conv")
    print(hdr)
    for x in rows:
        ch = "" if "d_v" not in x else (f"{100 * x['d_v']:>+7.2f}%{100 * x['d_vp']:>+7.2f}%"
                                        f"{100 * x['d_s']:>+7.2f}%  {'yes' if x['conv'] else 'no'}")
        print(f"{x['name']:<14}{1e6 * x['dt']:>8.3g}{x['link_steps_per_s']:>13.3g}"
              f"{x['wall_per_sim_s']:>13.4g}{x['v_mean']:>8.4f}{x['v_peak']:>8.4f}"
              f"{x['tight_mean']:>9.1f}{x['tight_max']:>9.1f}{ch}")


def plain_chain_rate(links=5000, steps=4000, error_model="python"):
    """Link-steps per second of a plain compiled point-mass chain (the ceiling): the
    vectorised layout (separate x/y arrays, no branch in the loops), symplectic Euler, no
    contacts, no records. (With numba's default ``error_model="python"`` the division's
    zero check keeps the link loop scalar; ``"numpy"`` lets it run as vector
    instructions, the same values.)"""
    from numba import njit

    @njit(cache=False, fastmath=False, error_model=error_model)
    def run(x, y, vx, vy, k, p, m, dt, nsteps):
        n = x.shape[0]
        fx = np.zeros(n + 1)
        fy = np.zeros(n + 1)
        for _ in range(nsteps):
            for i in range(n - 1):
                dx = x[i + 1] - x[i]
                dy = y[i + 1] - y[i]
                ll = math.sqrt(dx * dx + dy * dy)
                f = k * (ll - p) / ll
                fx[i + 1] = f * dx
                fy[i + 1] = f * dy
            dx = x[0] - x[n - 1]
            dy = y[0] - y[n - 1]
            ll = math.sqrt(dx * dx + dy * dy)
            f = k * (ll - p) / ll
            fx[n] = f * dx
            fy[n] = f * dy
            fx[0] = fx[n]
            fy[0] = fy[n]
            for i in range(n):
                vx[i] += (fx[i + 1] - fx[i]) * dt / m
                vy[i] += (fy[i + 1] - fy[i]) * dt / m
                x[i] += vx[i] * dt
                y[i] += vy[i] * dt

    a = 2 * np.pi * np.arange(links) / links
    radius = 0.0254 / (2 * math.sin(math.pi / links))
    x, y = radius * np.cos(a), radius * np.sin(a)
    vx, vy = np.zeros(links), np.zeros(links)
    run(x.copy(), y.copy(), vx.copy(), vy.copy(), 3.9e9, 0.0254, 0.066, 3e-6, 10)
    best = 0.0
    for _ in range(3):
        t0 = time.process_time()
        run(x, y, vx, vy, 3.9e9, 0.0254, 0.066, 3e-6, steps)
        best = max(best, links * steps / (time.process_time() - t0))
    return best


def batched_models(variants, links, damped):
    """``variants`` variants of the benchmark drive (driver speed 15...25 rad/s and load
    100...300 N m drawn at random), without span damping or (``damped``) each with its own
    default ``α = 2 ζ z ω`` (``SimulationModel.span_damping_rate``: ``ζ`` the resonance
    check's at the tooth frequency ``z ω``)."""
    rng = np.random.default_rng(1)
    return [roller_example(links=links, teeth=17, ramp_time=0.1,
                           angular_velocity=float(rng.uniform(15.0, 25.0)),
                           load_torque=float(rng.uniform(100.0, 300.0)),
                           span_damping=None if damped else 0.0)
            for _ in range(variants)]


def _span_label(damped):
    from chaindrive.vibration.excitation import DAMPING_RATIO

    return f"span damping ζ = {DAMPING_RATIO} at the tooth frequency" if damped else \
        "no span damping"


def batched_rate(variants=64, links=100, steps=3000, damped=False, plain=None):
    """Link-steps per second (CPU time) of the batched kernel on ``variants`` variants of
    the benchmark drive (:func:`batched_models`, each at its own stable step, from its warm
    start), and its fraction of the point-mass ceiling (:func:`plain_chain_rate`)."""
    from chaindrive.simulation._batched import empty_batch_records, integrate_batch, stack_tables
    from chaindrive.simulation.steady import warm_start

    states = [warm_start(m) for m in batched_models(variants, links, damped)]
    par = np.stack([s.par for s in states])
    args = [np.stack([getattr(s, a) for s in states]) for a in ("pos", "vel", "ws", "wp", "gd")]
    args += [stack_tables([K.seat_table(s.wp) for s in states]), par,
             np.array([s.time for s in states])]
    recs = empty_batch_records(variants, 1, links, 2)
    integrate_batch(*[a.copy() for a in args], 10, steps, *recs)  # compile / warm the cache
    best = 0.0
    for _ in range(3):
        run = [a.copy() for a in args]
        t0 = time.process_time()
        integrate_batch(*run, steps, steps, *recs)
        best = max(best, variants * links * steps / (time.process_time() - t0))
    plain = plain_chain_rate() if plain is None else plain
    simd = plain_chain_rate(error_model="numpy")
    print(f"batched, {variants} variants: {best:.3g} link-steps/s per core, "
          f"{best / plain:.2f} of the ceiling ({1e9 / best:.2f} ns per link-step; the "
          f"point-mass ceiling {plain:.3g}, {best / simd:.2f} of its vector-instruction "
          f"form {simd:.3g}; {links}-link 16B drives, {_span_label(damped)}, explicit, CPU time, "
          f"load average {__import__('os').getloadavg()[0]:.1f})", flush=True)
    return best, plain


def batched_implicit_rate(variants=64, links=100, steps=1200, plain=None, damped=False):
    """Link-steps per second (CPU time) of the batched implicit kernel
    (``chaindrive.simulation._batched_implicit``, each lane bit-equal to the single
    implicit kernel) on ``variants`` variants of the benchmark drive (as
    :func:`batched_rate`, each at its accurate implicit step), against the single implicit
    kernel on the same variants in the same run, and its fraction of the point-mass
    ceiling (:func:`plain_chain_rate`)."""
    from chaindrive.simulation._batched_implicit import Lanes, integrate_implicit_lanes
    from chaindrive.simulation._implicit import integrate_implicit
    from chaindrive.simulation.steady import warm_start

    models = batched_models(variants, links, damped)
    states = [warm_start(m) for m in models]
    tabs = [K.seat_table(s.wp) for s in states]
    pars = []
    for m, s in zip(models, states, strict=True):
        par = s.par.copy()
        par[K.P_DT] = m.accurate_time_step()
        pars.append(par)

    def batch(nsteps):
        lanes = Lanes(variants, links, states[0].ws.shape[0], states[0].gd.shape[0],
                      max(t.shape[1] for t in tabs), 1)
        for v, s in enumerate(states):
            lanes.load(v, s.pos, s.vel, s.ws, s.wp, s.gd, tabs[v], pars[v], s.time, nsteps,
                       nsteps)
        t0 = time.process_time()
        integrate_implicit_lanes(*lanes.arrays(), nsteps)
        return time.process_time() - t0

    def single(nsteps):
        spent = 0.0
        for v, s in enumerate(states):
            pos, vel, ws = s.pos.copy(), s.vel.copy(), s.ws.copy()
            recs = K.empty_records(1, links, ws.shape[0], 1)
            t0 = time.process_time()
            integrate_implicit(pos, vel, np.zeros_like(pos), np.zeros_like(pos), np.zeros(links),
                               np.zeros(links), ws, s.wp, s.gd, tabs[v], pars[v], s.time, nsteps,
                               nsteps, np.zeros((1, 4)), *recs, 0)
            spent += time.process_time() - t0
        return spent

    batch(5)
    single(5)  # compile / warm the cache
    best_b = variants * links * steps / min(batch(steps) for _ in range(3))
    best_s = variants * links * steps / min(single(steps) for _ in range(2))
    plain = plain_chain_rate() if plain is None else plain
    print(f"batched implicit, {variants} variants: {best_b:.3g} link-steps/s per core, "
          f"{best_b / plain:.2f} of the ceiling ({1e9 / best_b:.1f} ns per link-step; the "
          f"single implicit kernel on the same variants {best_s:.3g}, {1e9 / best_s:.1f} ns: "
          f"{best_b / best_s:.2f}x; the point-mass ceiling {plain:.3g}; {links}-link 16B "
          f"drives, {_span_label(damped)}, at their accurate implicit step, CPU time, load average "
          f"{__import__('os').getloadavg()[0]:.1f})", flush=True)
    return best_b, best_s


def scaling(lengths=(100, 500, 1000, 2000, 5000), link_steps=1.5e8):
    """One line per chain length: assembly time and kernel link-steps/s (CPU time) of both
    integrators, and the implicit one's CPU time per simulated second."""
    print("scaling (16B on two 17-tooth sprockets, 20 rad/s, 200 N m; pretension of a 2 % "
          "sag, >= 200 N; CPU time, machine shared):", flush=True)
    rates = {}
    for n in lengths:
        span = 0.5 * (n - 17) * 0.0254
        weight = 9.81 * 2.6  # 16B: q ≈ 2.6 kg/m
        pretension = max(200.0, weight * span / (8 * 0.02))
        model = roller_example(links=n, teeth=17, angular_velocity=20.0, load_torque=200.0,
                               ramp_time=0.1, pretension=pretension)
        t0 = time.process_time()
        state = assemble(model)
        t_asm = time.process_time() - t0
        line = f"links {n}: assemble {t_asm:.2f} s"
        for method, dt in (("explicit", model.stable_time_step()),
                           ("implicit", model.accurate_time_step())):
            duration = max(link_steps / n / (10 if method == "implicit" else 1), 2000) * dt
            simulate(model, 20 * dt, state=state, samples=2, method=method)  # warm
            best = 0.0
            for _ in range(3 if n <= 1000 else 2):
                t0 = time.process_time()
                r = simulate(model, duration, state=state, samples=2, method=method)
                best = max(best, r.steps * n / (time.process_time() - t0))
            rates[n, method] = best
            line += (f", {method} link-steps/s {best:.3g} ({1e9 / best:.1f} ns, "
                     f"{n / (best * dt):.3g} s/sim s at {1e6 * dt:.3g} us)")
        print(line, flush=True)
    from chaindrive.simulation import conveyor_example

    conveyor = conveyor_example()
    t0 = time.process_time()
    state = assemble(conveyor)
    t_asm = time.process_time() - t0
    line = f"conveyor (26x92, 100 m, tensioner) links {conveyor.links}: assemble {t_asm:.2f} s"
    for method in ("explicit", "implicit"):
        t0 = time.process_time()
        r = simulate(conveyor, 0.3, state=state, samples=20, method=method)
        cpu = time.process_time() - t0
        line += f", {method} {cpu / 0.3:.3g} s/sim s at {1e6 * r.dt:.3g} us"
    print(line, flush=True)
    plain = plain_chain_rate()
    top, low = max(lengths), min(lengths)
    print(f"vectorised point-mass chain (5000 links, separate x/y, no contacts): link-steps/s "
          f"{plain:.3g} ({1e9 / plain:.2f} ns)")
    for method in ("explicit", "implicit"):
        print(f"{method}: kernel at {top} links / at {low} links: "
              f"{rates[top, method] / rates[low, method]:.2f}; per link-step at {top} links / "
              f"point-mass ceiling: {rates[top, method] / plain:.2f}")
    return rates, plain


def pick_converged(rows, ref=None):
    """The largest step whose run is converged against its halved step and (``ref``) within
    ``TOL_REF`` of the reference in mean speed and mean tight-side tension; else the
    largest converged one, else the finest. Returns (row, converged, within the reference)."""
    converged(rows)
    conv = [x for x in rows if x.get("conv")]
    for x in conv:
        if ref is None or (abs(_rel(x, ref, "v_mean")) <= TOL_REF
                           and abs(_rel(x, ref, "tight_mean")) <= TOL_REF):
            return x, True, True
    return (conv[0], True, False) if conv else (rows[-1], False, False)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--duration", type=float, default=0.3)
    ap.add_argument("--mujoco", action="store_true",
                    help="compare with MuJoCo (stiff links and rigid links); the default "
                         "when mujoco is installed")
    ap.add_argument("--no-mujoco", action="store_true")
    ap.add_argument("--exudyn", action="store_true",
                    help="also the Exudyn peer (benchmarks/peers/exudyn_drive.py; ~10 min CPU)")
    ap.add_argument("--quick", action="store_true",
                    help="MuJoCo stiff links at its largest stable step and half only")
    ap.add_argument("--diagnose", action="store_true",
                    help="also run the variants behind the stated diagnosis (MuJoCo at 4 us: "
                         "impedance d, seat faces, servo gain; both engines without friction)")
    ap.add_argument("--scaling", action="store_true",
                    help="only the scaling: assembly time and link-steps/s for 100...5000 "
                         "links, and the plain point-mass chain")
    ap.add_argument("--no-scaling", action="store_true",
                    help="only the comparison (the default runs both, `make bench`)")
    ap.add_argument("--batched", action="store_true",
                    help="only the batched kernels' rates (explicit, implicit) on 64 variants "
                         "of the drive")
    ap.add_argument("--steady", action="store_true",
                    help="only the steady state against its long reference run "
                         "(benchmarks/_steady.py; also part of the default run)")
    args = ap.parse_args()
    if args.scaling:
        scaling()
        return
    if args.batched:
        _, plain = batched_rate()
        batched_rate(damped=True, plain=plain)
        batched_implicit_rate(plain=plain)
        batched_implicit_rate(plain=plain, damped=True)
        return
    import sys
    from pathlib import Path

    sys.path.insert(0, str(Path(__file__).parent))
    from _steady import steady_lines

    if args.steady:
        steady_lines()
        return
    import os

    print(f"load average {os.getloadavg()[0]:.2f} {os.getloadavg()[1]:.2f} (2 cores shared); "
          "times are CPU times", flush=True)
    model, state = build()
    dt0 = model.stable_time_step()
    own, r = run_chaindrive(model, state, args.duration)
    exp_rows = [own, run_chaindrive(model, state, args.duration, dt=dt0 / 2)[0]]
    imp_rows = [run_chaindrive(model, state, args.duration, dt=dt, method="implicit")[0]
                for dt in IMPLICIT_LADDER]
    stiff_rows, rigid_rows = [], []
    if not args.no_mujoco:
        try:
            import mujoco
        except ImportError:
            print("mujoco not installed (.venv/bin/pip install mujoco, or the bench extra); "
                  "peer skipped")
        else:
            # divergence is read from MjData.warning; silence MuJoCo's own message (stdout and
            # MUJOCO_LOG.TXT in the working directory) for the unstable steps of the ladder
            previous = mujoco.get_mju_user_warning()
            mujoco.set_mju_user_warning(lambda msg: None)
            probe = r.probe_points[0]
            tight_mid = 0.5 * (r.tight_span[0] + r.tight_span[1])
            base = None
            for dt in (1e-5, 8e-6, 6e-6, 5e-6, 4e-6, 3e-6, 2e-6):
                res = run_mujoco(model, state, args.duration, dt, probe, tight_mid)
                print(f"  mujoco stiff links dt = {dt:g} s: "
                      f"{'stable' if res is not None else 'unstable'}", flush=True)
                if res is not None:
                    base = res
                    break
            # each ladder stops at its first step converged against its half (the finer
            # steps would not change the pick; --quick: at most one halving)
            if base is not None:
                stiff_rows.append(base)
                for f in ((2,) if args.quick else (2, 4)):
                    res = run_mujoco(model, state, args.duration, base["dt"] / f, probe, tight_mid,
                                     start=base["settled"])
                    if res is None:
                        break
                    stiff_rows.append(res)
                    if converged(stiff_rows) is not None:
                        break
            for dt in RIGID_LADDER:
                res = run_mujoco(model, state, args.duration, dt, probe, tight_mid, rigid=True)
                print(f"  mujoco rigid links dt = {dt:g} s: "
                      f"{'ran' if res is not None else 'failed'}", flush=True)
                if res is not None:
                    rigid_rows.append(res)
                    if len(rigid_rows) > 1 and converged(rigid_rows) is not None:
                        break
            mujoco.set_mju_user_warning(previous)
    exudyn_rows = []
    if args.exudyn:
        sys.path.insert(0, str(Path(__file__).parent / "peers"))
        import exudyn_drive

        exudyn_rows = exudyn_drive.ladder(model, state, args.duration, r.probe_points[0],
                                          0.5 * (r.tight_span[0] + r.tight_span[1]), SAMPLE,
                                          STEADY, converged)
    print(f"\n16B chain, {model.links} links, 2 x z = 17, centre distance "
          f"{state.wp[1, K.W_CX]:.4f} m, {args.duration:g} s simulated, steady window "
          f"t >= {STEADY:g} s, samples every {1e6 * SAMPLE:g} us")
    print("dv/v, dvpk, dS/S: change of mean speed, peak speed, mean tight-side tension against "
          "the next (halved) step; conv: |dv/v| <= "
          f"{100 * TOL_SPEED:g} % and |dS/S| <= {100 * TOL_TENSION:g} %")
    groups = [g for g in (exp_rows, imp_rows, stiff_rows, rigid_rows, exudyn_rows) if g]
    ref, _, _ = pick_converged(exp_rows)
    picks = {g[0]["name"]: pick_converged(g, ref) for g in groups}
    print_table([x for g in groups for x in g])
    print(f"static reference: T/R = {200 / model.pitch_radii()[1]:.1f} N (+ slack-side tension)")
    print(f"\nreference: chaindrive explicit at {1e6 * ref['dt']:.3g} us (mean speed "
          f"{ref['v_mean']:.4f} m/s, mean tight-side tension {ref['tight_mean']:.1f} N)")
    print(f"equal accuracy: each engine at its largest step converged against its halved step "
          f"and within {100 * TOL_REF:g} % of the reference (mean speed, mean tight-side tension):")
    for name, (x, ok, near) in picks.items():
        state_ = "equal accuracy" if near else ("converged, NOT within the reference" if ok
                                                else "NOT converged")
        print(f"  {name:<16} {1e6 * x['dt']:>6.3g} us {state_}, {x['wall_per_sim_s']:.3g} s CPU "
              f"per simulated s; against the reference: mean speed "
              f"{100 * _rel(x, ref, 'v_mean'):+.2f} %, mean tension "
              f"{100 * _rel(x, ref, 'tight_mean'):+.2f} %, peak speed "
              f"{100 * _rel(x, ref, 'v_peak'):+.2f} %")
    imp, _, imp_near = picks["chaindrive impl"]
    print(f"chaindrive implicit vs explicit (per simulated second): "
          f"{ref['wall_per_sim_s'] / imp['wall_per_sim_s']:.3g} x")
    for label, key in (("MuJoCo rigid links", "mujoco rigid"), ("MuJoCo stiff links", "mujoco stiff"),
                       ("Exudyn stiff links, VelocityVerlet", "exudyn stiff")):
        if key in picks:
            x, ok, near = picks[key]
            print(f"vs {label}: {x['wall_per_sim_s'] / imp['wall_per_sim_s']:.3g} x"
                  f"{'' if near and imp_near else '  (not at equal accuracy: see the lines above)'}")
            if key.startswith("exudyn") and ok:
                _at_peer_accuracy(label, x, ref, imp_rows)
    if args.diagnose and stiff_rows:
        diagnose(model, state, args.duration, stiff_rows[0]["dt"], own)
    print()
    steady_lines()
    if not args.no_scaling:
        print()
        scaling()
        _, plain = batched_rate()
        batched_implicit_rate(plain=plain)


def _at_peer_accuracy(label, peer, ref, own_rows):
    """Print the ratio at the peer's own accuracy: chaindrive's implicit integrator at its
    largest step converged against its half and no farther from the reference than the
    peer's converged run (mean tension and mean speed), against the peer's run."""
    tol_s, tol_v = abs(_rel(peer, ref, "tight_mean")), abs(_rel(peer, ref, "v_mean"))
    fits = [x for x in own_rows if x.get("conv") and abs(_rel(x, ref, "tight_mean")) <= tol_s
            and abs(_rel(x, ref, "v_mean")) <= max(tol_v, 1e-4)]
    if not fits:
        print(f"  no chaindrive implicit step as close to the reference as {label}")
        return
    own = fits[0]
    print(f"vs {label} at equal accuracy (both within {100 * tol_s:.2g} % of the reference in mean "
          f"tension, {100 * max(tol_v, 1e-4):.2g} % in mean speed: the peer's error): "
          f"{peer['wall_per_sim_s'] / own['wall_per_sim_s']:.3g} x (peer at {1e6 * peer['dt']:.3g} us, "
          f"{100 * _rel(peer, ref, 'tight_mean'):+.2f} % / {100 * _rel(peer, ref, 'v_mean'):+.2f} %; "
          f"chaindrive implicit at {1e6 * own['dt']:.3g} us, {100 * _rel(own, ref, 'tight_mean'):+.2f} % / "
          f"{100 * _rel(own, ref, 'v_mean'):+.2f} %; both converged against their half step)")


def diagnose(model, state, duration, dt, own):
    """Where the MuJoCo/chaindrive differences come from (results only, not timed)."""
    print(f"\ndiagnosis, MuJoCo at {1e6 * dt:g} us (differences against chaindrive at its default step)")

    def line(label, a, b):
        print(f"  {label:<34} chaindrive S {a['tight_mean']:7.1f} v peak {a['v_peak']:.4f} | "
              f"mujoco S {b['tight_mean']:7.1f} v peak {b['v_peak']:.4f} | "
              f"dS {100 * _rel(b, a, 'tight_mean'):+.2f} %, dv peak {100 * _rel(b, a, 'v_peak'):+.2f} %, "
              f"dv mean {100 * _rel(b, a, 'v_mean'):+.2f} %", flush=True)

    _, r = run_chaindrive(model, state, duration)
    probe = r.probe_points[0]
    tight_mid = 0.5 * (r.tight_span[0] + r.tight_span[1])
    for label, opts in (("impedance d = 0.5", dict(dmax=0.5)), ("impedance d = 0.99", dict(dmax=0.99)),
                        ("8 faces per seat", dict(faces=8)), ("servo kv = 1e4", dict(kv=1.0e4))):
        res = run_mujoco(model, state, duration, dt, probe, tight_mid, **opts)
        if res is not None:
            line(label, own, res)
    m0 = roller_example(links=100, teeth=17, angular_velocity=20.0, load_torque=200.0,
                        ramp_time=0.1, friction=0.0, span_damping=0.0)
    s0 = assemble(m0)
    own0, r0 = run_chaindrive(m0, s0, duration)
    res = run_mujoco(m0, s0, duration, dt, r0.probe_points[0],
                     0.5 * (r0.tight_span[0] + r0.tight_span[1]))
    if res is not None:
        line("no friction (both engines)", own0, res)


if __name__ == "__main__":
    main()
