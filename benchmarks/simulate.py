"""Benchmark of chaindrive.simulation against MuJoCo on the same chain drive.

Drive: ISO 606 16B simplex chain, 100 links, two 17-tooth sprockets, centre distance
(100 - 17)/2 p = 1.054 m; driver ramped to 20 rad/s in 0.1 s, 200 N m load on the
driven wheel (tight side ~3.1 kN), gravity. Both start from the same statically
assembled state (chaindrive's static solve).

chaindrive: point-mass pins, axial spring-dampers (EA = 1e8 N), penalty contact of each
roller with the ISO 606 seat/flank profile, symplectic Euler at its largest stable step.

MuJoCo (the peer): the same 100 rollers as point bodies on two slide joints (x-z plane)
with sphere geoms, links as spatial tendons with the same stiffness and damping,
teeth as cylinder collision geoms placed so that a roller between two of them
sits on the pitch circle (resting on a root cylinder R - r_s, held tangentially by the
teeth with chaindrive's seat clearance); driver hinge with a stiff velocity servo, driven hinge with
the same inertia and load torque. Its time step is the largest of a ladder of steps
at which the run stays finite and the chain stays on the wheels.

Prints link-steps/s and wall seconds per simulated second of both, their ratio, and
the differences in mean/peak chain speed and mean tight-side tension.

Run:  .venv/bin/python benchmarks/simulate.py [--duration 0.3] [--no-mujoco]
"""

from __future__ import annotations

import argparse
import math
import time

import numpy as np

from chaindrive.simulation import _kernel as K
from chaindrive.simulation import assemble, roller_example, simulate


def build(duration):
    model = roller_example(links=100, teeth=17, angular_velocity=20.0, load_torque=200.0,
                           ramp_time=0.1)
    state = assemble(model)
    return model, state


def run_chaindrive(model, state, duration):
    simulate(model, 0.002, state=state)  # compile / warm the cache
    t0 = time.perf_counter()
    r = simulate(model, duration, state=state, settle=0.15)
    wall = time.perf_counter() - t0
    s = r.summary
    return {
        "name": "chaindrive",
        "dt": r.dt,
        "steps": r.steps,
        "wall": wall,
        "kernel_wall": r.wall_time,
        "link_steps_per_s": r.steps * model.links / r.wall_time,
        "wall_per_sim_s": r.wall_time / (r.steps * r.dt),
        "v_mean": s["chain_velocity_mean"][0],
        "v_peak": s["chain_velocity_max"][0],
        "tight_mean": s["tight_side_tension_mean"],
        "tight_max": s["tight_side_tension_max"],
    }, r


def mujoco_xml(model, state, dt, solref=None):
    """MJCF of the drive (x-z plane, gravity -z)."""
    p = model.pitch
    rr = model.roller_radius
    if solref is None:
        # contact time constant 1/ω_c of chaindrive's roller contact, at least 2 dt
        solref = f"{max(math.sqrt(model.link_mass / model.contact_stiffness), 2 * dt):.6g} 1"
    k = model.link_stiffness
    c = model.link_damping
    wl = []
    for j, w in enumerate(model.wheels):
        cx, cy = state.wp[j, K.W_CX], state.wp[j, K.W_CY]
        rad = w.pitch_radius(p)
        # teeth: cylinders whose centres lie on the line through two neighbouring seat
        # points' tangents (radius R / cos(π/z)), sized so that a roller on the pitch
        # circle has the same clearance r_s - r as chaindrive's seat on either side; the
        # roller rests radially on the root cylinder (radius R - r_s, the bottom of chaindrive's seat): it can leave the gap
        # radially, as on a real sprocket
        clear = model.seat - rr
        rho = rad / math.cos(math.pi / w.teeth)
        rt = rho * math.sin(math.pi / w.teeth) - rr - clear
        teeth = [f'<geom type="cylinder" size="{rad - rr - clear:.9g} 0.01" zaxis="0 1 0" '
                 f'contype="2" conaffinity="1" mass="0"/>']
        for g in range(w.teeth):
            a = (g + 0.5) * 2 * math.pi / w.teeth
            x, z = rho * math.cos(a), rho * math.sin(a)
            teeth.append(f'<geom type="cylinder" size="{rt:.6g} 0.01" pos="{x:.9g} 0 {z:.9g}" '
                         f'zaxis="0 1 0" contype="2" conaffinity="1" mass="0"/>')
        joint = (f'<joint name="w{j}" type="hinge" axis="0 -1 0"/>')
        wl.append(f'<body name="wheel{j}" pos="{cx:.9g} 0 {cy:.9g}">{joint}'
                  f'<inertial pos="0 0 0" mass="1" diaginertia="{w.inertia:.6g} {w.inertia:.6g} '
                  f'{w.inertia:.6g}"/>' + "".join(teeth) + "</body>")
    pins = []
    for i, (x, z) in enumerate(state.pos):
        pins.append(f'<body name="p{i}" pos="{x:.12g} 0 {z:.12g}">'
                    f'<joint name="px{i}" type="slide" axis="1 0 0"/>'
                    f'<joint name="pz{i}" type="slide" axis="0 0 1"/>'
                    f'<geom type="sphere" size="{rr:.6g}" mass="{model.link_mass:.6g}" '
                    f'contype="1" conaffinity="2" friction="{model.friction} 0 0"/>'
                    f'<site name="s{i}"/></body>')
    tendons = []
    n = len(state.pos)
    for i in range(n):
        j = (i + 1) % n
        tendons.append(f'<spatial stiffness="{k:.9g}" damping="{c:.6g}" springlength="{p:.12g}">'
                       f'<site site="s{i}"/><site site="s{j}"/></spatial>')
    return f"""<mujoco model="chain drive">
  <option timestep="{dt:.6g}" gravity="0 0 -9.81" integrator="implicitfast" cone="pyramidal"/>
  <default><geom solref="{solref}" solimp="0.9 0.95 0.001"/></default>
  <worldbody>{''.join(wl)}{''.join(pins)}</worldbody>
  <tendon>{''.join(tendons)}</tendon>
  <actuator><velocity joint="w0" kv="2000"/></actuator>
</mujoco>"""


def run_mujoco(model, state, duration, dt, probe, tight_mid, record_every=20):
    import mujoco

    m = mujoco.MjModel.from_xml_string(mujoco_xml(model, state, dt))
    d = mujoco.MjData(m)
    # wheel angles: teeth were placed relative to angle 0; MuJoCo's hinge axis is -y so
    # that positive angles turn counter-clockwise in the x-z plane
    d.qpos[0] = state.ws[0, K.S_THETA]
    d.qpos[1] = state.ws[1, K.S_THETA]
    w0 = model.wheels[0]
    load = model.wheels[1].torque
    nsteps = int(round(duration / dt))
    n = model.links
    pin_adr = np.array([m.jnt_qposadr[m.joint(f"px{i}").id] for i in range(n)])
    vel_adr = np.array([m.jnt_dofadr[m.joint(f"px{i}").id] for i in range(n)])
    # MuJoCo's own static equilibrium first (its cylinder teeth differ from chaindrive's
    # flank profile near the tangent points): driver held, load on, velocities quenched
    # every 200 steps (kinetic-energy damping) for 0.03 s simulated; not timed
    d.ctrl[0] = 0.0
    for s in range(int(0.03 / dt)):
        d.qfrc_applied[1] = load
        mujoco.mj_step(m, d)
        if s % 200 == 0:
            d.qvel[:] = 0.0
    d.qvel[:] = 0.0
    d.time = 0.0
    if d.warning[mujoco.mjtWarning.mjWARN_BADQACC].number > 0:
        print("    (diverged while settling)")
        return None
    times, v, ten = [], [], []
    t0 = time.perf_counter()
    mujoco.set_mjcb_control(None)
    for s in range(nsteps):
        t = s * dt
        ramp = min(1.0, (t + dt) / w0.ramp_time) if w0.ramp_time > 0 else 1.0
        d.ctrl[0] = w0.angular_velocity * ramp
        d.qfrc_applied[1] = load
        mujoco.mj_step(m, d)
        if d.warning[mujoco.mjtWarning.mjWARN_BADQACC].number > 0:
            print(f"    (diverged at t = {t:.4f} s)")
            return None  # MuJoCo detected divergence (and reset itself)
        if s % record_every == 0:
            xz = state.pos + np.column_stack([d.qpos[pin_adr], d.qpos[pin_adr + 1]])
            if not np.all(np.isfinite(xz)):
                return None
            ib = np.argmin(np.sum((xz - probe[:2]) ** 2, axis=1))
            v.append(d.qvel[vel_adr[ib]] * probe[2] + d.qvel[vel_adr[ib] + 1] * probe[3])
            mid = 0.5 * (xz + np.roll(xz, -1, axis=0))
            il = np.argmin(np.sum((mid - tight_mid) ** 2, axis=1))
            ten.append(model.link_stiffness * (d.ten_length[il] - model.pitch))
            times.append(t)
    wall = time.perf_counter() - t0
    times, v, ten = map(np.asarray, (times, v, ten))
    # the chain must still run on the wheels: wheel 1 turning with it
    sel = times >= min(0.15, 0.5 * duration)
    if not (np.all(np.isfinite(v)) and np.all(np.isfinite(ten))):
        return None
    return {
        "name": f"mujoco {mujoco.__version__}",
        "dt": dt,
        "steps": nsteps,
        "wall": wall,
        "kernel_wall": wall,
        "link_steps_per_s": nsteps * n / wall,
        "wall_per_sim_s": wall / (nsteps * dt),
        "v_mean": float(np.mean(v[sel])),
        "v_peak": float(np.max(v[sel])),
        "tight_mean": float(np.mean(ten[sel])),
        "tight_max": float(np.max(ten[sel])),
        "wheel1_speed": float(d.qvel[1]),
    }


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--duration", type=float, default=0.3)
    ap.add_argument("--no-mujoco", action="store_true")
    args = ap.parse_args()
    model, state = build(args.duration)
    own, r = run_chaindrive(model, state, args.duration)
    rows = [own]
    if not args.no_mujoco:
        try:
            import mujoco  # noqa: F401
        except ImportError:
            print("mujoco not installed (.venv/bin/pip install mujoco); peer skipped")
        else:
            probe = r.probe_points[0]
            tight_mid = 0.5 * (r.tight_span[0] + r.tight_span[1])
            # largest stable step: the full run stays finite without MuJoCo's divergence
            # warning (link forces are reported, not limited)
            for dt in (1e-4, 3e-5, 1e-5, 6e-6, 5e-6, 4e-6, 3e-6, 2e-6, 1e-6):
                res = run_mujoco(model, state, args.duration, dt, probe, tight_mid)
                print(f"  mujoco dt = {dt:g} s: {'stable' if res is not None else 'unstable'}")
                if res is not None:
                    rows.append(res)
                    break
    print(f"\n16B chain, {model.links} links, 2 x z = 17, centre distance "
          f"{state.wp[1, K.W_CX]:.4f} m, {args.duration:g} s simulated")
    hdr = f"{'engine':<16}{'dt [s]':>10}{'link-steps/s':>14}{'wall s / sim s':>16}" \
          f"{'v mean':>9}{'v peak':>9}{'S tight':>10}{'S max':>10}"
    print(hdr)
    for x in rows:
        print(f"{x['name']:<16}{x['dt']:>10.3g}{x['link_steps_per_s']:>14.3g}"
              f"{x['wall_per_sim_s']:>16.4g}{x['v_mean']:>9.4f}{x['v_peak']:>9.4f}"
              f"{x['tight_mean']:>10.1f}{x['tight_max']:>10.1f}")
    if len(rows) == 2:
        a, b = rows
        print(f"\nwall time per simulated second, mujoco / chaindrive: "
              f"{b['wall_per_sim_s'] / a['wall_per_sim_s']:.3g}")
        print(f"difference (mujoco - chaindrive): mean speed "
              f"{100 * (b['v_mean'] / a['v_mean'] - 1):+.2f} %, peak speed "
              f"{100 * (b['v_peak'] / a['v_peak'] - 1):+.2f} %, mean tight-side tension "
              f"{100 * (b['tight_mean'] / a['tight_mean'] - 1):+.2f} %")
    print(f"static reference: T/R + slack = {200 / model.pitch_radii()[1]:.1f} N + slack")


if __name__ == "__main__":
    main()
