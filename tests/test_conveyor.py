"""Chain pull of scraper conveyors: formulas (chaindrive.conveyor), the motor curve
(chaindrive.drivetrain.motor), the Conveyor spec and the [conveyor] table, the chain pull along the
loop (chaindrive.analysis.conveyor)."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from chaindrive import conveyor as C
from chaindrive.analysis.conveyor import conveyor_checks, conveyor_pull
from chaindrive.drive import Conveyor
from chaindrive.drive.project import load_project, parse_project
from chaindrive.drivetrain.motor import Motor, breakdown_slip, kloss_torque
from chaindrive.errors import InputError
from chaindrive.layout import GRAVITY, catenary_sag
from chaindrive.simulation.from_drive import conveyor_drive

G = GRAVITY


# ------------------------------------------------------------------ formulas
def test_strand_resistance_inclined_transport_sheet():
    # e-uparts machine handbook, sheet 20-3 "Calculation formula of tension acting on the
    # chain (inclined transport)": T_MAX = W (L f + H) + M (L f1 + H) [kgf] with L the
    # horizontal and H the vertical centre distance. Numbers chosen here: M = 10 kgf/m
    # chain, W = 50 kgf/m material, L = 20 m, H = 5 m, f1 = 0.3, f = 0.6:
    # T = 50 (12 + 5) + 10 (6 + 5) = 960 kgf (by hand).
    length = math.hypot(20.0, 5.0)
    alpha = math.atan2(5.0, 20.0)
    t = C.strand_resistance(length, 10.0, 0.3, alpha, 50.0, 0.6)
    assert float(t) == pytest.approx(960.0 * G, rel=1e-12)
    # the return run going down, sheet 20-3: T1 = M (L f1 - H) = 10 (6 - 5) = 10 kgf
    assert float(C.strand_resistance(length, 10.0, 0.3, -alpha)) == pytest.approx(10.0 * G, rel=1e-12)


def test_strand_resistance_horizontal_tsubaki_table3():
    # Tsubakimoto, Large size conveyor chain selection, Table 3, horizontal conveyor with
    # the material scraped (f = f2/f1): T = (W f2 + M f1) L g with M the chain and W
    # the material per metre: 100 m, M = 14.3 kg/m, f1 = 0.4, W = 100 kg/m, f2 = 0.6
    t = C.strand_resistance(100.0, 14.3, 0.4, 0.0, 100.0, 0.6)
    assert float(t) == pytest.approx((100.0 * 0.6 + 14.3 * 0.4) * 100.0 * G, rel=1e-12)
    assert float(t) == pytest.approx(64449.3, abs=0.1)   # regression


def test_material_and_power():
    # Tsubakimoto 9.1: W = 16.7 Q / V (Q t/h, V m/min): 600 t/h at 60 m/min -> 167 kg/m
    assert float(C.material_mass_per_length(600 / 3.6, 1.0)) == pytest.approx(16.7 * 600 / 60, rel=2e-3)
    # kW = T V / (60 eta): 50 kN at 48 m/min, eta 0.8 -> 50 kW
    assert float(C.drive_power(50e3, 0.8, 0.8)) == pytest.approx(50e3, rel=1e-12)


@pytest.mark.parametrize("call, match", [
    (lambda: C.strand_resistance(0.0, 1.0, 0.3), "length"),
    (lambda: C.strand_resistance(10.0, 1.0, 2.0), "friction"),
    (lambda: C.strand_resistance(10.0, 1.0, 0.3, 2.0), "inclination"),
    (lambda: C.strand_resistance(10.0, 1.0, 0.3, 0.0, -1.0), "material_mass_per_length"),
    (lambda: C.material_mass_per_length(1.0, 0.0), "chain_speed"),
    (lambda: C.drive_power(1.0, 1.0, 0.0), "efficiency"),
    (lambda: C.drive_power(-1.0, 1.0), "force"),
    (lambda: C.mean_tension([0.0, 1.0], [1.0]), "same length"),
    (lambda: C.mean_tension([1.0, 0.0], [1.0, 1.0]), "increase"),
    (lambda: C.free_strand(30.0, 0.0, 100.0, 10.0), "too low"),
    (lambda: C.free_strand(30.0, 2.0, 1e4, 10.0), "inclination"),
    (lambda: C.pretension_for_minimum(-1.0, 0.0, 0.0), "minimum"),
])
def test_formula_errors(call, match):
    with pytest.raises(InputError, match=match):
        call()


def test_mean_tension_is_the_integral():
    s = np.linspace(0.0, 200.0, 41)
    t = 1e4 + 50.0 * s
    assert C.mean_tension(s, t) == pytest.approx(1e4 + 50.0 * 100.0, rel=1e-12)


def test_free_strand_limits_and_balance():
    # small sag: the parabola f = w l^2 / (8 H) and the extra length 8 f^2 / (3 l)
    s = C.free_strand(30.0, 0.0, 50e3, 6.6)
    f = 6.6 * G * 30.0**2 / (8 * s.horizontal_tension)
    assert s.sag == pytest.approx(f, rel=1e-3)
    assert s.excess_length == pytest.approx(8 * f**2 / (3 * 30.0), rel=2e-3)
    # the sag agrees with chaindrive.layout.catenary_sag at the same horizontal tension
    assert s.sag == pytest.approx(float(catenary_sag(30.0, 0.0, s.horizontal_tension, 6.6)), rel=1e-12)
    assert s.sag == pytest.approx(0.14566, rel=1e-4)         # regression


@settings(max_examples=40, deadline=None)
@given(chord=st.floats(2.0, 200.0), incl=st.floats(-0.6, 0.6), q=st.floats(1.0, 30.0),
       factor=st.floats(1.2, 50.0))
def test_free_strand_end_tension_is_start_plus_weight_of_rise(chord, incl, q, factor):
    t0 = factor * C.free_strand_minimum_tension(chord, incl, q)
    s = C.free_strand(chord, incl, t0, q)
    # exact catenary property: T_end - T_start = q g (y_end - y_start)
    assert s.end_tension - s.start_tension == pytest.approx(q * G * chord * math.sin(incl),
                                                            rel=1e-6, abs=1e-6 * t0)
    assert s.horizontal_tension <= min(s.start_tension, s.end_tension) * (1 + 1e-12)
    assert s.excess_length >= 0


# ------------------------------------------------------------------ motor
def test_kloss_curve():
    # at s = s_k the breakdown torque, and it is the maximum (finite differences)
    assert float(kloss_torque(0.15, 800.0, 0.15)) == pytest.approx(800.0, rel=1e-12)
    h = 1e-6
    slope = (float(kloss_torque(0.15 + h, 800.0, 0.15)) - float(kloss_torque(0.15 - h, 800.0, 0.15))) / (2 * h)
    assert abs(slope) < 1e-3
    # through the rated point: T(s_N) = T_k / m
    sk = float(breakdown_slip(0.03, 2.2))
    assert float(kloss_torque(0.03, 2.2, sk)) == pytest.approx(1.0, rel=1e-12)
    m = Motor.rated(40e3, 4.0, rated_slip=0.03, breakdown_ratio=2.2)
    assert float(m.torque(4.0)) == pytest.approx(40e3 / 4.0, rel=1e-9)


@pytest.mark.parametrize("call, match", [
    (lambda: kloss_torque(0.1, 100.0, 1.0), "breakdown_slip"),
    (lambda: kloss_torque(2.5, 100.0, 0.1), "slip"),
    (lambda: breakdown_slip(0.02, 0.9), "breakdown_ratio"),
    (lambda: Motor(4.0, 100.0, 0.0), "breakdown_slip"),
])
def test_motor_errors(call, match):
    with pytest.raises(InputError, match=match):
        call()


# ------------------------------------------------------------------ spec and project
@pytest.mark.parametrize("kwargs, match", [
    (dict(inclination=1.0), "inclination"),
    (dict(material_load=1.0, capacity=1.0), "not both"),
    (dict(head_share=0.0), "head_share"),
    (dict(return_strand="floor"), "return_strand"),
    (dict(chain_friction=2.0), "chain_friction"),
    (dict(efficiency=1.5), "efficiency"),
])
def test_conveyor_spec_errors(kwargs, match):
    with pytest.raises(InputError, match=match):
        Conveyor(**kwargs)


def test_project_conveyor_table(tmp_path):
    d = load_project("examples/scraper_conveyor.toml")
    assert d.conveyor is not None and d.conveyor.material_load == 100.0
    text = open("examples/scraper_conveyor.toml").read().replace('material_load = "100 kg/m"',
                                                                 'capacity = "300 t/h"')
    d2 = parse_project(text)
    assert d2.conveyor.capacity == pytest.approx(300 / 3.6)
    bad = text.replace('inclination = "0 deg"', "inclination = 3")
    with pytest.raises(InputError, match="inclination"):
        parse_project(bad, filename="c.toml")


# ------------------------------------------------------------------ the loop
def _drive(**conv):
    return dataclasses.replace(conveyor_drive(), conveyor=Conveyor(**conv))


def test_pull_balances_round_the_loop():
    r = conveyor_pull(_drive(return_strand="free", material_load=50.0))
    prof = r.tension_profile
    assert prof.tension[0] == pytest.approx(prof.tension[-1], abs=1e-6)
    assert r.tight_tension - r.slack_tension == pytest.approx(r.head_force, rel=1e-12)
    assert r.drive_force == pytest.approx(r.carrying_resistance + r.return_resistance, rel=1e-12)
    # the free return is level end to end: no resistance; the carrying strand: Table 3
    assert abs(r.return_resistance) < 1e-6 * r.drive_force
    length = r.carrying_resistance / ((13.6 * 0.4 + 50 * 0.6) * G)
    assert 97.0 < length < 100.0
    assert r.drive_power == pytest.approx(r.drive_force * r.chain_speed, rel=1e-12)


def test_pull_stated_minimum_and_pretension_without_tensioner():
    d = dataclasses.replace(_drive(return_strand="supported", material_load=50.0, minimum_tension=5e3,
                                   head_share=0.6), tensioner=None,
                            wheels=conveyor_drive().wheels[::2])
    r = conveyor_pull(d)
    assert r.source.startswith("stated minimum")
    # the lowest exit tension (head or tail) is the stated minimum
    assert min(r.slack_tension, r.tight_tension - r.carrying_resistance) == pytest.approx(5e3, rel=1e-9)
    assert r.tail_force == pytest.approx(0.4 * r.drive_force, rel=1e-12)
    # pretension: the loop's mean running tension (rigid take-up)
    assert r.pretension == pytest.approx(C.mean_tension(r.tension_profile.position, r.tension_profile.tension))
    checks = conveyor_checks(d, r)
    assert checks[0].passed and checks[1].passed


def test_pull_weight_tensioner_holds_its_force():
    base = conveyor_drive()
    d = dataclasses.replace(_drive(return_strand="free"),
                            tensioner=dataclasses.replace(base.tensioner, kind="weight"))
    r = conveyor_pull(d)
    assert r.tensioner_force == pytest.approx(base.tensioner.force, rel=1e-6)


def test_pull_spring_tensioner_regression():
    r = conveyor_pull(load_project("examples/long_conveyor.toml"))
    # regression values (this implementation); the simulation agrees within 5 %
    # (benchmarks/conveyor.py, tests/test_simulation_conveyor.py)
    # (issue 30: the tensioner wheel where the 2,194 links put it, the spans' end
    # tangents; before, 57,526 N and 2.838 m from the chords at the drawn position)
    assert r.slack_tension == pytest.approx(58102, rel=1e-3)
    assert r.return_sag == pytest.approx(2.810, rel=1e-3)
    assert r.tensioner_force < base_force() and r.tensioner_travel > 0


def base_force():
    return 45e3


def test_no_conveyor_no_pull():
    assert conveyor_pull(conveyor_drive()) is None


@settings(max_examples=15, deadline=None)
@given(mu=st.floats(0.1, 0.8), mum=st.floats(0.2, 0.9), qm=st.floats(0.0, 150.0),
       incl=st.floats(-0.15, 0.15), share=st.floats(0.3, 1.0),
       ret=st.sampled_from(["supported", "free"]))
def test_pull_properties(mu, mum, qm, incl, share, ret):
    # the profile closes round the loop, the drives take the whole pull in their shares,
    # the pretension lifts the lowest sprocket exit to the stated minimum
    d = dataclasses.replace(load_project("examples/scraper_conveyor.toml"),
                            conveyor=Conveyor(chain_friction=mu, material_friction=mum, material_load=qm,
                                              inclination=incl, head_share=share, return_strand=ret))
    try:
        r = conveyor_pull(d)
    except InputError as exc:               # a tensioner too weak for a steep free return
        assert "tensioner" in str(exc) or "slack" in str(exc)
        return
    prof = r.tension_profile
    assert prof.tension[-1] == pytest.approx(prof.tension[0], abs=1e-6 * r.tight_tension)
    assert r.head_force + r.tail_force == pytest.approx(r.drive_force, rel=1e-12, abs=1e-9)
    assert r.head_force == pytest.approx(share * r.drive_force, rel=1e-12, abs=1e-9)
    assert np.all(np.diff(prof.position) >= 0)
    assert r.minimum_tension == pytest.approx(float(np.min(prof.tension)))


def test_long_drive_without_conveyor_table_gets_a_note():
    from chaindrive.analysis import analyze_drive

    d = dataclasses.replace(load_project("examples/long_conveyor.toml"), conveyor=None)
    a = analyze_drive(d, include=["conveyor"])
    assert a.conveyor is None
    assert any("[conveyor] table" in w for w in a.warnings)
    assert not analyze_drive(load_project("examples/roller_industrial.toml"), include=["conveyor"]).warnings


def test_analysis_part_in_results_json():
    from chaindrive.analysis import analyze_drive

    a = analyze_drive(load_project("examples/scraper_conveyor.toml"), include=["conveyor", "loads", "slack_sag"])
    data = a.to_dict()["conveyor"]
    assert set(data["tension_profile"]) == {"position", "tension"}
    for key in ("minimum_tension", "pretension", "drive_power"):
        assert isinstance(data[key], float)
    # the conveyor feeds the loads: slack = tension leaving the head; the sag = the return's
    assert a.loads.slack == pytest.approx(a.conveyor.slack_tension)
    assert a.slack_sag == pytest.approx(a.conveyor.return_sag)
    assert [c.part for c in a.checks if c.part == "conveyor"]
