"""The constant-fill fluid coupling (chaindrive.drivetrain.coupling) and the start-up through it in
the simulation: the formula against its defining points and the similarity law, the
motor-coupling-load system against an independent integration (scipy solve_ivp of the
two-inertia system), the stiff-coupling limit (direct drive), the error paths."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from chaindrive.drivetrain.coupling import FluidCoupling, coupling_torque, slip_shape
from chaindrive.drivetrain.motor import Motor
from chaindrive.errors import InputError
from chaindrive.simulation import SimWheel, simulate
from chaindrive.simulation.conveyor import with_drive_profile
from chaindrive.simulation.examples import roller_example


# ------------------------------------------------------------------ the formula
@pytest.mark.parametrize("s_n, k", [(0.03, 1.5), (0.02, 2.5), (0.06, 3.0), (0.005, 1.1)])
def test_slip_shape_through_its_catalogue_points(s_n, k):
    assert float(slip_shape(0.0, s_n, k)) == 0.0
    assert float(slip_shape(s_n, s_n, k)) == pytest.approx(1.0, rel=1e-12)
    assert float(slip_shape(1.0, s_n, k)) == pytest.approx(k, rel=1e-12)
    s = np.linspace(-1.0, 1.0, 2001)
    phi = slip_shape(s, s_n, k)
    assert np.all(np.diff(phi) > 0)                                   # monotonic
    np.testing.assert_allclose(phi, -phi[::-1], atol=1e-12)           # odd
    # linear at small slip: slope (1 + c)/s_n by central differences
    c = (1 - k * s_n) / (k - 1)
    h = 1e-7 * s_n
    slope = (float(slip_shape(h, s_n, k)) - float(slip_shape(-h, s_n, k))) / (2 * h)
    assert slope == pytest.approx((1 + c) / s_n, rel=1e-6)


@settings(max_examples=60, deadline=None)
@given(wp=st.floats(0.1, 400.0), s=st.floats(-1.0, 1.0), s_n=st.floats(0.01, 0.1), k=st.floats(1.2, 4.0),
       scale=st.floats(0.2, 5.0))
def test_coupling_torque_is_the_similarity_law(wp, s, s_n, k, scale):
    # T = T_n (w_p/w_n)^2 phi(s): the regular form equals it, and at a fixed slip the
    # torque goes with the primary speed squared (Foettinger's similarity law)
    tn, wn = 250.0, 150.0
    wt = wp * (1 - s)
    t = float(coupling_torque(wp, wt, tn, wn, s_n, k))
    assert t == pytest.approx(tn * (wp / wn) ** 2 * float(slip_shape((wp - wt) / wp, s_n, k)), rel=1e-9,
                              abs=1e-9 * tn)
    t2 = float(coupling_torque(scale * wp, scale * wp * (1 - s), tn, wn, s_n, k))
    assert t2 == pytest.approx(scale**2 * t, rel=1e-9, abs=1e-9 * tn)


def test_coupling_torque_limits():
    # the primary at rest transmits nothing, whatever the secondary does
    assert float(coupling_torque(0.0, 5.0, 100.0, 20.0, 0.03, 2.0)) == 0.0
    assert float(coupling_torque(0.0, 0.0, 100.0, 20.0, 0.03, 2.0)) == 0.0
    # nominal point and stall at the nominal primary speed
    assert float(coupling_torque(20.0, 19.4, 100.0, 20.0, 0.03, 2.0)) == pytest.approx(100.0, rel=1e-12)
    assert float(coupling_torque(20.0, 0.0, 100.0, 20.0, 0.03, 2.0)) == pytest.approx(200.0, rel=1e-12)
    c = FluidCoupling.sized(100.0, 20.0, nominal_slip=0.03, stall_ratio=2.0)
    assert float(c.torque(20.0, 19.4)) == pytest.approx(100.0, rel=1e-12)
    k, s_n, cc = c.kernel_constants()
    assert (s_n, cc) == (0.03, c.shape_constant)
    assert k == pytest.approx(100.0 * (1 + cc) / 400.0, rel=1e-12)


@pytest.mark.parametrize("call, match", [
    (lambda: slip_shape(0.1, 0.001, 2.0), "nominal_slip"),
    (lambda: slip_shape(0.1, 0.03, 1.0), "stall_ratio"),
    (lambda: slip_shape(0.1, 0.2, 5.5), "stall_ratio times nominal_slip"),
    (lambda: coupling_torque(1.0, 0.5, 0.0, 20.0, 0.03, 2.0), "nominal_torque"),
    (lambda: coupling_torque(1.0, 0.5, 10.0, -1.0, 0.03, 2.0), "nominal_speed"),
    (lambda: FluidCoupling(100.0, 20.0, 0.5, 2.0), "nominal_slip"),
    (lambda: FluidCoupling(100.0, 20.0, 0.03, 7.0), "stall_ratio"),
    (lambda: SimWheel(SimWheel.at((0.0, 0.0), 17).wheel, coupling=FluidCoupling(100.0, 20.0, 0.03, 2.0)),
     "coupling needs a motor"),
    (lambda: SimWheel(SimWheel.at((0.0, 0.0), 17).wheel, mode="motor", motor=Motor.rated(2e3, 20.0),
                      coupling=FluidCoupling(100.0, 20.0, 0.03, 2.0)), "motor_inertia"),
    (lambda: with_drive_profile(roller_example(), coupling=FluidCoupling(100.0, 20.0, 0.03, 2.0)),
     "needs a motor"),
    (lambda: with_drive_profile(roller_example(), motor=Motor.rated(2e3, 20.0), secondary_inertia=1.0),
     "secondary_inertia"),
])
def test_coupling_errors(call, match):
    with pytest.raises(InputError, match=match):
        call()


# ------------------------------------------------------------------ in the simulation
W0, JM, JD, DAMP = 20.0, 0.5, 2.0, 4.0
MOTOR = Motor.rated(2000.0, W0, rated_slip=0.05, breakdown_ratio=2.5)


def _two_wheels(coupling, *, links=40, motor_inertia=JM):
    """16B on two 17-tooth sprockets without gravity; the driven wheel's load is its
    bearing damping D w (no load at rest: nothing turns it back at switch-on)."""
    m = roller_example(gravity=False, links=links)
    driven = dataclasses.replace(m.wheels[1], torque=0.0, damping=DAMP, inertia=JD)
    m = dataclasses.replace(m, wheels=[m.wheels[0], driven])
    return with_drive_profile(m, motor=MOTOR, motor_inertia=motor_inertia, coupling=coupling)


def _rigid(coupling, model, times):
    """Independent: motor + coupling + rigid chain and wheels (equal sprockets), solve_ivp."""
    from scipy.integrate import solve_ivp

    radius = float(model.pitch_radii()[0])
    jeq = model.wheels[0].inertia + JD + model.links * model.link_mass * radius**2

    def rhs(_t, y):
        wm, w = y
        tc = float(coupling.torque(wm, w))
        return [(float(MOTOR.torque(wm)) - tc) / JM, (tc - DAMP * w) / jeq]

    return solve_ivp(rhs, (0.0, float(times[-1])), [0.0, 0.0], t_eval=times, method="LSODA",
                     rtol=1e-10, atol=1e-10).y


def test_start_through_a_coupling_agrees_with_the_two_inertia_system():
    coupling = FluidCoupling.sized(100.0, W0, nominal_slip=0.04, stall_ratio=2.0)
    model = _two_wheels(coupling)
    r = simulate(model, 0.45, samples=90)
    wm, w = _rigid(coupling, model, r.time)
    # the motor runs up almost unloaded (T_c ~ w_m^2), the load follows through the slip
    assert np.max(np.abs(r.motor_speed[:, 0] - wm)) < 0.01 * W0
    assert np.max(np.abs(r.wheel_speed[:, 1] - w)) < 0.015 * W0
    assert float(w[-1]) > 0.9 * W0
    # the kernel's coupling torque (start_up's record) is the formula's at the recorded speeds
    from chaindrive.simulation.conveyor import start_up_of

    su = start_up_of(r, model)
    np.testing.assert_allclose(su.drive_torque, coupling.torque(r.motor_speed[:, 0], r.wheel_speed[:, 0]))
    np.testing.assert_array_equal(su.motor_speed, r.motor_speed[:, 0])


def test_a_stiff_coupling_is_a_direct_drive():
    # a coupling a thousand times the motor's size (slip ~ 1e-3 of nominal at any torque
    # once the primary turns) locks the motor to the wheel: the run equals the direct drive
    # with the motor inertia added to the wheel's
    stiff = FluidCoupling.sized(1e5, W0, nominal_slip=0.01, stall_ratio=1.5)
    r_c = simulate(_two_wheels(stiff), 0.3, samples=60)
    direct = _two_wheels(None)
    r_d = simulate(direct, 0.3, samples=60)
    assert direct.wheels[0].inertia == pytest.approx(_two_wheels(stiff).wheels[0].inertia + JM)
    assert np.max(np.abs(r_c.wheel_speed[:, 1] - r_d.wheel_speed[:, 1])) < 0.02 * W0
    assert np.max(np.abs(r_c.motor_speed[:, 0] - r_c.wheel_speed[:, 0])[r_c.time > 0.05]) < 0.05 * W0
    assert np.all(r_d.motor_speed == 0.0)          # no coupling: no motor degree of freedom


def test_cli_coupling_errors(tmp_path, capsys):
    from chaindrive.cli import main

    proj = "examples/scraper_conveyor.toml"
    cases = [
        (["--coupling"], "--coupling needs --motor"),
        (["--motor", "--coupling"], "--coupling needs --motor-inertia"),
        (["--motor", "--coupling", "--motor-inertia", "10 kg*m**2", "--coupling-slip", "0.5"],
         r"--coupling-slip must lie in \[0.005, 0.2\]"),
        (["--motor", "--coupling", "--motor-inertia", "10 kg*m**2", "--coupling-stall", "9"],
         r"--coupling-stall must lie in \[1.1, 6\]"),
        (["--motor", "--secondary-inertia", "10 kg*m**2"], "--secondary-inertia needs --coupling"),
        (["--motor", "--coupling", "--motor-inertia", "0 kg*m**2"], "motor_inertia"),
        (["--motor", "--coupling", "--motor-inertia", "10 kg*m**2", "--secondary-inertia", "-1 kg*m**2"],
         "secondary_inertia"),
    ]
    for i, (args, match) in enumerate(cases):
        assert main(["simulate", proj, *args, "-o", str(tmp_path / f"o{i}")]) == 2
        err = capsys.readouterr().err
        assert len([ln for ln in err.splitlines() if "rror" in ln]) == 1
        assert pytest.importorskip("re").search(match, err), err
    assert main(["simulate", "--example", "roller", "--coupling", "-o", str(tmp_path / "x")]) == 2
    assert "apply to project files" in capsys.readouterr().err


def test_the_documented_coupling_is_softer_than_the_motor_direct():
    # docs/conveyor.md: the coupling's stall torque at the motor's rated speed is 1.5 T_N,
    # while the high-slip motor direct on line starts with T(s = 1) = 1.41 T_N; the coupling
    # starts from zero torque and rises with the motor's speed squared
    motor = Motor.rated(40e3, 4.0, rated_slip=0.05, breakdown_ratio=2.8)
    cpl = FluidCoupling.sized(40e3 / 4.0, 4.0, nominal_slip=0.03, stall_ratio=1.5)
    assert float(motor.torque(0.0)) / 1e4 == pytest.approx(1.413, abs=1e-3)
    assert float(cpl.torque(4.0, 0.0)) / 1e4 == pytest.approx(1.5, rel=1e-12)
    assert float(cpl.torque(2.0, 0.0)) == pytest.approx(0.25 * float(cpl.torque(4.0, 0.0)), rel=1e-12)
    assert math.isclose(float(cpl.torque(0.0, 0.0)), 0.0)


def test_start_through_a_coupling_with_the_implicit_integrator():
    # the linearly implicit integrator (simulate(method="implicit")) drives the wheel
    # through the same coupling step: the same two-inertia solution
    coupling = FluidCoupling.sized(100.0, W0, nominal_slip=0.04, stall_ratio=2.0)
    model = _two_wheels(coupling)
    r = simulate(model, 0.45, samples=90, method="implicit")
    wm, w = _rigid(coupling, model, r.time)
    assert np.max(np.abs(r.motor_speed[:, 0] - wm)) < 0.01 * W0
    assert np.max(np.abs(r.wheel_speed[:, 1] - w)) < 0.015 * W0


def test_conveyor_start_up_through_a_coupling_runs_at_the_couplings_slip():
    # start_up(..., coupling=...) on an 8 m conveyor: at the end the coupling carries the
    # head's pull (T = F R) with the motor ahead of the head by the coupling's slip
    from chaindrive.analysis.conveyor import conveyor_pull
    from chaindrive.simulation.startup import start_up
    from test_simulation_conveyor import _short

    d = _short(length=8.0)
    motor = Motor.rated(30e3, 5.0, rated_slip=0.05, breakdown_ratio=2.8)
    cpl = FluidCoupling.sized(30e3 / 5.0, 5.0, nominal_slip=0.03, stall_ratio=1.5)
    su, res, model = start_up(d, 1.5, motor=motor, motor_inertia=40.0, coupling=cpl, secondary_inertia=10.0,
                              samples=600)
    assert model.wheels[0].coupling is cpl and model.wheels[0].motor_inertia == 40.0
    pull = conveyor_pull(d)
    radius = float(model.pitch_radii()[0])
    tail = su.time > 1.0
    torque = float(np.mean(su.drive_torque[tail]))
    assert torque == pytest.approx(pull.head_force * radius, rel=0.1)
    head = res.wheel_speed[tail, 0]
    slip = 1.0 - float(np.mean(head)) / float(np.mean(su.motor_speed[tail]))
    # the slip the coupling's characteristic gives for that torque at that primary speed
    wm = float(np.mean(su.motor_speed[tail]))
    phi = torque / (cpl.nominal_torque * (wm / cpl.nominal_speed) ** 2)
    c = cpl.shape_constant
    s_expected = cpl.nominal_slip * phi / (1 + c - c * phi)
    assert slip == pytest.approx(s_expected, rel=0.15)
    assert 0.0 < slip < cpl.nominal_slip
