"""Validation of the chain-drive simulation (chaindrive.simulation).

Small models, short runs: each case is a few seconds at most (numba cache=True).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from chaindrive.errors import InputError
from chaindrive.simulation import (
    SimulationModel,
    SimWheel,
    assemble,
    roller_example,
    simulate,
)
from chaindrive.simulation.run import conservative


def _free_entry_law(result, teeth):
    """Rigid free-entry (chordal) law v = ωR cos(φ − π/z), φ ∈ [0, 2π/z).

    φ − π/z is the angle of the seated pin that holds the span, measured from the
    normal to the span (the top of the driver: the tight span enters there).
    Provenance: elementary kinematics of a rigid polygon, Dolipiński et al. eqs (1)-(4) for a
    regular polygon (d = 0); cross-checked against chaindrive.kinematics below.
    """
    radius = result.pitch_radii[0]
    th = result.wheel_angle[:, 0]
    ph = np.mod(th - np.pi / 2 + np.pi / teeth, 2 * np.pi / teeth) - np.pi / teeth
    return result.wheel_speed[:, 0] * radius * np.cos(ph), ph


def test_rigid_limit_free_entry_chordal_speed():
    teeth, omega = 12, 2.0
    m = roller_example(links=40, teeth=teeth, angular_velocity=omega, load_torque=20.0,
                       ramp_time=0.05, gravity=False)
    r = simulate(m, 0.6, samples=3000)
    law, ph = _free_entry_law(r, teeth)
    sel = r.time > 0.15
    # the seating impact (a few ms after each seating instant φ = ±π/z) is not part of
    # the rigid law: leave out 5 % of the period on either side of it
    away = np.abs(np.abs(ph) - np.pi / teeth) > 0.05 * 2 * np.pi / teeth
    sel &= away
    v = r.chain_velocity[sel, 0]
    mean = float(np.mean(law[sel]))
    assert np.max(np.abs(v - law[sel])) / mean < 0.01
    # the chordal ripple is reproduced (over the same samples)
    ripple = (v.max() - v.min()) / v.max()
    ripple_law = (law[sel].max() - law[sel].min()) / law[sel].max()
    assert ripple == pytest.approx(ripple_law, rel=0.1)


def test_free_entry_law_matches_kinematics_module():
    kin = pytest.importorskip("chaindrive.kinematics")
    k = kin.chain_entry(0.0254, 12, 2.0, entry="free")
    radius = 0.0254 / (2 * math.sin(math.pi / 12))
    # extremes of the rigid law used above: ωR and ωR cos(π/z)
    assert np.max(k.velocity) == pytest.approx(2.0 * radius, rel=1e-6)
    assert np.min(k.velocity) == pytest.approx(2.0 * radius * math.cos(math.pi / 12), rel=1e-6)


def test_plucked_span_string_frequency():
    m = roller_example(links=60, teeth=16, angular_velocity=0.0, load_torque=0.0,
                       gravity=False, pretension=500.0)
    st = assemble(m)
    r0 = simulate(m, 1e-4, state=st, samples=2)
    tension = float(np.mean(r0.tight_side_tension()))
    p1, p2 = r0.tight_span
    length = float(np.hypot(*(p2 - p1)))
    pos = st.pos
    x0 = min(p1[0], p2[0])
    on = (np.abs(pos[:, 1] - p1[1]) < 1e-4) & (pos[:, 0] > x0 + 1e-4) \
        & (pos[:, 0] < max(p1[0], p2[0]) - 1e-4)
    assert on.sum() == 21
    # 20 µm half-sine: small enough that the stretch adds < 0.1 % to the tension
    st.pos[on, 1] += 2e-5 * np.sin(np.pi * (pos[on, 0] - x0) / length)
    mid = np.where(on)[0][np.argmin(np.abs(pos[on, 0] - x0 - length / 2))]
    r = simulate(m, 0.5, state=st, samples=5000)
    y = r.positions[:, mid, 1] - p1[1]
    y = y - y.mean()
    s = np.sign(y)
    i = np.where(s[:-1] * s[1:] < 0)[0]
    tc = r.time[i] - y[i] * (r.time[i + 1] - r.time[i]) / (y[i + 1] - y[i])
    f_sim = 1.0 / (2 * np.mean(np.diff(tc)))
    q = m.link_mass / m.pitch
    # string: f = (1/2L) sqrt(S/q) (taut string, fixed ends; Rayleigh, Theory of Sound §124)
    f_string = math.sqrt(tension / q) / (2 * length)
    assert f_sim == pytest.approx(f_string, rel=0.02)
    # regression (measured 12.352 Hz vs 12.376 Hz, -0.19 %)
    assert f_sim == pytest.approx(12.352, rel=2e-3)


def test_energy_conserved_without_damping():
    # a soft (EA = 1e7 N) small drive so that 10 revolutions stay fast; flywheels keep
    # the drive turning while impacts feed the chain's vibration
    w = 60.0
    m = roller_example(links=20, teeth=8, angular_velocity=w, load_torque=0.0,
                       pretension=300.0, ramp_time=0.03, axial_stiffness=1e7,
                       contact_stiffness=2e7, span_damping=0.0)
    for wheel in m.wheels:
        wheel.inertia *= 1000.0
    dt = 0.25 * m.stable_time_step()
    r0 = simulate(m, 0.06, samples=10, dt=dt)
    st = conservative(r0.final_state)
    r = simulate(m, 11 * 2 * np.pi / w, state=st, samples=2000, dt=dt)
    turns = (r.wheel_angle[-1, 0] - r.wheel_angle[0, 0]) / (2 * np.pi)
    assert turns >= 10.0
    e = r.energy
    # measured 6.3e-4 (range / mean over the run)
    assert (e.max() - e.min()) / e.mean() < 0.002


def test_time_step_halving_changes_mean_tension_little():
    # friction, link and contact damping on; a speed away from span resonances
    w, teeth, dur = 10.0, 16, 0.3
    m = roller_example(links=40, teeth=teeth, angular_velocity=w, load_torque=100.0,
                       pretension=2000.0, ramp_time=0.05)
    means = []
    period = 2 * np.pi / teeth / w
    for factor in (1.0, 0.5):
        r = simulate(m, dur, dt=factor * m.stable_time_step())
        sel = r.time >= dur - 4 * period  # four whole tooth periods
        means.append(float(np.mean(r.tight_side_tension()[sel])))
    assert means[1] == pytest.approx(means[0], rel=0.005)


def test_static_tension_equals_load_over_pitch_radius():
    load = 100.0
    m = roller_example(links=40, teeth=16, angular_velocity=0.0, load_torque=load,
                       gravity=False, pretension=200.0)
    r = simulate(m, 1e-4, samples=2)
    radius = r.pitch_radii[1]
    tight = float(np.mean(r.tight_side_tension()))
    slack = float(np.mean(r.slack_side_tension()))
    # tight - slack = T / R (moment balance of the driven wheel; the slack side keeps
    # part of the pretension)
    assert tight - slack == pytest.approx(load / radius, rel=0.005)


def test_model_errors():
    w = [SimWheel.at((0, 0), 12), SimWheel.at((0.3, 0), 12)]
    with pytest.raises(InputError, match="links"):
        SimulationModel(pitch=0.0254, links=3, link_mass=0.07, axial_stiffness=1e8,
                        roller_radius=0.008, wheels=w)
    with pytest.raises(InputError, match="roller_radius"):
        SimulationModel(pitch=0.0254, links=40, link_mass=0.07, axial_stiffness=1e8,
                        roller_radius=0.02, wheels=w)
    with pytest.raises(InputError, match="mode"):
        SimWheel.at((0, 0), 12, mode="fast")
    with pytest.raises(InputError, match="teeth"):
        SimWheel.at((0, 0), 2)
    with pytest.raises(InputError, match="duration"):
        simulate(roller_example(links=30, teeth=11), -1.0)


def test_result_arrays_and_npz(tmp_path):
    m = roller_example(links=30, teeth=11, angular_velocity=5.0, ramp_time=0.005)
    r = simulate(m, 0.01, samples=20)
    assert r.tension.shape == (len(r.time), 30)
    assert r.positions.shape == (len(r.time), 30, 2)
    r.save_npz(tmp_path / "s.npz")
    data = np.load(tmp_path / "s.npz")  # no pickled object (the final state) in it
    assert data["tension"].shape == r.tension.shape
    assert "final_state" not in data.files and "summary" not in data.files
    assert all(data[k].dtype != object for k in data.files)
    r.save_npz(tmp_path / "c.npz", compressed=True)
    np.testing.assert_array_equal(np.load(tmp_path / "c.npz")["positions"], r.positions)
    d = r.to_dict()
    assert "wheel_speed" in d and "summary" in d


def _tensioner_model(**kw):
    from chaindrive.simulation import SimTensioner

    p, q = 0.0254, 2.612
    wheels = [SimWheel.at((0, 0), 17, 0.01, "speed", 10.0, 0.05, name="driver"),
              SimWheel.at((0.5, -0.12), 11, 0.002, "free", name="tensioner"),
              SimWheel.at((1.0, 0), 17, 0.01, "free", torque=-100.0, name="driven")]
    opts = dict(pitch=p, links=100, link_mass=q * p, axial_stiffness=1e8,
                roller_radius=0.00794, wheels=wheels,
                tensioner=SimTensioner.at(1, (0, -1), 1.0, 2e4, 50.0, preload=300.0))
    opts.update(kw)
    return SimulationModel(**opts)


def test_tensioner_static_force_balance():
    from chaindrive.simulation.run import _tangent

    m = _tensioner_model(gravity=(0.0, 0.0))
    for w in m.wheels:
        w.torque = 0.0
    st = assemble(m)
    r = simulate(m, 1e-4, state=st, samples=2)
    c = r.wheel_centres
    radii = r.pitch_radii
    spans = [_tangent(c[0], radii[0], c[1], radii[1]), _tangent(c[1], radii[1], c[2], radii[2])]
    d = np.array([0.0, -1.0])
    force = 0.0
    for p1, p2, u, _ in spans:
        pos = r.positions[0]
        mid = 0.5 * (p1 + p2)
        lm = 0.5 * (pos + np.roll(pos, -1, axis=0))
        s = r.tension[0, np.argmin(np.sum((lm - mid) ** 2, axis=1))]
        # each span pulls the tensioner wheel along itself, away from the wheel
        # (the tensioner paper eq. (8): F = S (sin β1 + sin β2), β from the slide normal)
        sign = -1.0 if np.allclose(p2, _tangent(c[0], radii[0], c[1], radii[1])[1]) else 1.0
        force += s * sign * float(np.dot(u, d))
    from chaindrive.simulation import _kernel as K

    spring = st.wp[1, K.W_SF]  # spring force at the assembled position (preload - k s)
    # the spring force is balanced by the two span tensions along the slide
    assert -force == pytest.approx(spring, rel=0.01)
    # and the tensioner is at rest
    assert np.max(np.abs(r.tensioner_position)) < 1e-6


def test_tensioner_drive_runs():
    m = _tensioner_model()
    r = simulate(m, 0.1, settle=0.06)
    # the tensioner idler turns at the chain speed: ω z_driver / z_idler
    assert r.summary["wheel_speed_mean"][1] == pytest.approx(10.0 * 17 / 11, rel=0.02)
    assert np.all(np.isfinite(r.tensioner_position))


def test_continued_run_keeps_time_and_driver_speed():
    # a run continued from a final_state goes on at its end time: the driver's speed
    # ramp does not restart
    m = roller_example(links=30, teeth=11, angular_velocity=5.0, ramp_time=0.01,
                       gravity=False)
    r0 = simulate(m, 0.02, samples=20)
    assert r0.final_state.time == pytest.approx(r0.steps * r0.dt)
    r1 = simulate(m, 0.01, state=r0.final_state, samples=20)
    assert r1.time[0] == pytest.approx(r0.final_state.time)
    assert np.all(r1.wheel_speed[:, 0] == pytest.approx(5.0))
    assert r1.summary["duration"] == pytest.approx(0.01, rel=1e-3)


def test_tooth_form_equals_geometry_module():
    # the simulation's ISO 606 seat radius, half seating angle and mid tip height are the
    # geometry module's (ISO 606:2015 clause 8.3), for every tooth count it covers
    from chaindrive.geometry import sprocket as g

    m = roller_example()
    d1 = 2 * m.roller_radius
    for z in range(9, 151):
        assert m.seat == pytest.approx(float(g.seating_radius_limits(d1)[0]), rel=1e-12)
        assert m.seat_angle(z) == pytest.approx(0.5 * float(g.seating_angle_limits(z)[1]), rel=1e-12)
        lo, hi = g.tip_diameter_limits(m.pitch, z, d1)
        tip = 0.25 * float(lo + hi) - 0.5 * float(g.pitch_diameter(m.pitch, z))
        assert m.tip(z) == pytest.approx(tip, rel=1e-9)


def test_example_builders_reject_negative_speed_and_load():
    with pytest.raises(InputError, match=r"angular_velocity must be non-negative .*rad/s\), got -1"):
        roller_example(angular_velocity=-1.0)
    with pytest.raises(InputError, match=r"load_torque must be non-negative .*N m\), got -5"):
        roller_example(load_torque=-5.0)


def test_iso_flank_is_the_geometry_modules_flank():
    # the simulation's sprocket flank is the ISO 606 minimum tooth form's convex arc of
    # chaindrive.geometry.sprocket.sprocket_outline (r_i,min, α_max, r_e,max), up to the
    # tip circle in the middle of the d_a range. iso_flank builds it with the geometry
    # module's half gap, so the centre match checks the frame change and r_e (the
    # outline takes r_e from flank_radius_limits); tangency to the seat and the corner on
    # the tip circle are checked from first principles
    from chaindrive.geometry.sprocket import sprocket_outline, tip_diameter_limits
    from chaindrive.simulation.model import iso_flank

    m = roller_example()
    d1 = 2 * m.roller_radius
    for z in (9, 12, 17, 25, 40):
        radius = m.pitch / (2 * math.sin(math.pi / z))
        psi = m.seat_angle(z)
        re, ca, cb, ta, tb, da, db = iso_flank(m.pitch, z, m.roller_radius, m.seat, psi, m.tip(z))
        lo, hi = tip_diameter_limits(m.pitch, z, d1)
        outline = sprocket_outline(m.pitch, z, d1, form="min", tip_diameter=0.5 * (lo + hi))
        flank = min((a for a in outline.primitives if abs(a.radius - re) < 1e-12 and a.center[0] > 0),
                    key=lambda a: abs(a.center[0] - cb))
        # gap 0 of the outline is centred on +y: a = y − R, b = x
        assert (flank.center[1] - radius, flank.center[0]) == pytest.approx((ca, cb), abs=1e-12)
        # tangent to the seat: the ray point at r_i − r lies r_e + r from the flank centre
        q = (m.seat - m.roller_radius) * np.array([-math.cos(psi), math.sin(psi)])
        assert math.hypot(q[0] - ca, q[1] - cb) == pytest.approx(re + m.roller_radius, rel=1e-12)
        # the corner on the flank circle and on the tip circle (about the axis at a = −R)
        assert math.hypot(ta - ca, tb - cb) == pytest.approx(re, rel=1e-12)
        assert math.hypot(ta + radius, tb) == pytest.approx(radius + m.tip(z), rel=1e-12)
        assert (da, db) == pytest.approx(((ta - ca) / re, (tb - cb) / re), abs=1e-12)
    with pytest.raises(InputError, match="tooth_flank must be one of arc, straight, got 'iso'"):
        roller_example(tooth_flank="iso")


def test_highly_tensioned_roller_drive_assembles():
    # 12 kN pretension on a 16B drive: with the friction slope capped at m/Δt (dead-beat
    # on its own) the seated pins' alternating mode grew and the static assembly never
    # settled; the cap m/(2Δt) of every chain keeps it stable
    m = roller_example(links=60, teeth=17, angular_velocity=5.0, load_torque=2000.0,
                       pretension=12000.0, ramp_time=0.05)
    st = assemble(m)
    r = simulate(m, 1e-4, state=st, samples=2)
    # the loop carries the pretension: slack span near 12 kN, tight span T/R more
    radius = m.pitch_radii()[0]
    tight = float(np.mean(r.tight_side_tension()))
    slack = float(np.mean(r.slack_side_tension()))
    assert tight - slack == pytest.approx(2000.0 / radius, rel=0.01)
