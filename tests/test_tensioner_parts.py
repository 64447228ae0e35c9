"""A tensioner described by its parts in the project file, reduced to its axis by the energy balance."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from chaindrive.analysis import analyze_drive
from chaindrive.drive.model import Tensioner
from chaindrive.drive.project import TEMPLATES, parse_project
from chaindrive.drive.writer import drive_to_toml
from chaindrive.errors import InputError

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"

LEVER = '''[tensioner]
wheel = "tensioner"
kind = "spring"
direction = [0, -1]
force = "5 kN"
mechanism = "lever"
arm_length = "400 mm"
arm_mass = "30 kg"
wheel_mass = "40 kg"
spring_stiffness = "600 kN/m"
spring_lever = "250 mm"
spring_angle = "10 deg"
'''

SLIDING = '''[tensioner]
wheel = "tensioner"
direction = [0, -1]
force = "5 kN"
mechanism = "sliding"
carriage_mass = "25 kg"
wheel_mass = "40 kg"
spring_stiffness = "300 kN/m"
spring_mass = "6 kg"
spring_angle = "20 deg"
'''


def _with(block: str) -> str:
    t = TEMPLATES["mining"]
    i = t.index("[tensioner]")
    j = t.index("\n[", i + 3)
    return t[:i] + block + t[j:]


def _lever_energy(length, inertia, wheel_mass, k, lever, gamma, torsion=0.0, theta=1e-6):
    """Independent: rotate the arm by θ, measure the wheel's travel along its axis (the normal
    to the arm) and the spring's length change from the geometry; m = 2T/u̇², C = 2V/u²."""
    pivot = np.zeros(2)
    attach0 = pivot + lever * np.array([1.0, 0.0])           # arm along x, axis of the wheel: y
    spring_dir = np.array([math.sin(gamma), math.cos(gamma)])  # at γ to the normal of the arm
    anchor = attach0 + 0.5 * spring_dir                        # spring 0.5 m long
    rot = np.array([[math.cos(theta), -math.sin(theta)], [math.sin(theta), math.cos(theta)]])
    attach = rot @ attach0
    stretch = np.linalg.norm(anchor - attach) - 0.5
    u = length * math.sin(theta)
    V = 0.5 * k * stretch**2 + 0.5 * torsion * theta**2
    T_per_rate = 0.5 * (inertia + wheel_mass * length**2)      # T / θ̇²
    return 2 * T_per_rate * (theta / u) ** 2, 2 * V / u**2


def test_lever_parts_reduced_as_the_energy_balance_says():
    d = parse_project(_with(LEVER))
    m_ref, c_ref = _lever_energy(0.4, 30.0 * 0.4**2 / 3, 40.0, 600e3, 0.25, math.radians(10))
    assert d.tensioner.mechanism == "lever"
    assert d.tensioner.mass == pytest.approx(m_ref, rel=1e-6)      # 40 + 30/3 = 50 kg
    assert d.tensioner.stiffness == pytest.approx(c_ref, rel=1e-4)
    assert d.tensioner.mass == pytest.approx(50.0)


def test_lever_with_inertia_and_torsion_spring():
    t = Tensioner.from_parts("w", "lever", {"arm_length": 0.3, "arm_inertia": 0.8, "wheel_mass": 5.0,
                                            "spring_stiffness": 1e5, "spring_lever": 0.2,
                                            "spring_angle": math.radians(30), "torsion_stiffness": 500.0})
    m_ref, c_ref = _lever_energy(0.3, 0.8, 5.0, 1e5, 0.2, math.radians(30), torsion=500.0)
    assert t.mass == pytest.approx(m_ref, rel=1e-6) and t.stiffness == pytest.approx(c_ref, rel=1e-4)


def test_sliding_parts_reduced_as_the_energy_balance_says():
    d = parse_project(_with(SLIDING))
    a = math.radians(20)
    # independent: a spring whose free end moves at v cos α has the kinetic energy
    # ∫0^1 ½ (m_s dξ)(ξ v cos α)² (numerical quadrature), its stretch is the projection u cos α
    xi = np.linspace(0, 1, 100001)
    spring_ke = np.trapezoid(0.5 * 6.0 * (xi * math.cos(a)) ** 2, xi)  # per unit u̇²
    assert d.tensioner.mass == pytest.approx(25.0 + 40.0 + 2 * spring_ke, rel=1e-8)
    u = 1e-6
    stretch = np.linalg.norm(np.array([math.sin(a), math.cos(a)]) * 0.5 + np.array([0.0, u])) - 0.5
    assert d.tensioner.stiffness == pytest.approx(2 * 0.5 * 300e3 * stretch**2 / u**2, rel=1e-4)


def test_parts_round_trip_and_reach_the_check():
    d = parse_project(_with(LEVER))
    text = drive_to_toml(d)
    assert 'mechanism = "lever"' in text and "mass =" not in text.split("[tensioner]")[1].split("\n[")[0].replace(
        "arm_mass", "").replace("wheel_mass", "")
    assert parse_project(text) == d
    a = analyze_drive(d, include=["vibration"])
    assert a.vibration.span.mass == pytest.approx(50.0)
    assert a.vibration.span.stiffness == pytest.approx(d.tensioner.stiffness)


@pytest.mark.parametrize(("edit", "match"), [
    (lambda b: b.replace('mechanism = "lever"', 'mechanism = "lever"\nmass = "3 kg"'), "give one or the other"),
    (lambda b: b.replace('mechanism = "lever"\n', 'mass = "3 kg"\nstiffness = "1 kN/m"\n'), "parts need mechanism"),
    (lambda b: b.replace('spring_stiffness = "600 kN/m"\n', ""), "spring_stiffness is required"),
    (lambda b: b.replace('arm_mass = "30 kg"', 'arm_mass = "30 kg"\narm_inertia = "1 kg*m**2"'), "not both"),
    (lambda b: b.replace('arm_mass = "30 kg"', 'carriage_mass = "30 kg"'), "not a part of a lever"),
    (lambda b: b.replace('arm_length = "400 mm"', "arm_length = 0.4"), "give a unit"),
    (lambda b: b.replace('mechanism = "lever"', 'mechanism = "rope"'), "mechanism"),
])
def test_errors_name_the_field(edit, match):
    with pytest.raises(InputError, match=match):
        parse_project(_with(edit(LEVER)))


def test_reduced_mass_and_stiffness_still_accepted():
    d = parse_project(TEMPLATES["mining"])
    assert d.tensioner.mechanism is None and d.tensioner.parts == ()


def test_studio_field_describes_the_tensioner_by_its_parts():
    from chaindrive.web.design import (
        MINING_EXAMPLE,
        design_from_state,
        normalise_state,
        state_from_project,
    )

    state = normalise_state({**MINING_EXAMPLE, "tensioner_mechanism": "lever", "tensioner_arm_length": "400 mm",
                             "tensioner_arm_mass": "30 kg", "tensioner_wheel_mass": "40 kg",
                             "tensioner_spring_stiffness": "600 kN/m", "tensioner_spring_lever": "250 mm",
                             "tensioner_spring_angle": "10 deg"})
    d, errors = design_from_state(state)
    assert errors == {} and d.drive.tensioner.mechanism == "lever"
    assert d.drive.tensioner.mass == pytest.approx(50.0)
    assert d.drive.tensioner.stiffness == pytest.approx(parse_project(_with(LEVER)).tensioner.stiffness)
    assert 'mechanism = "lever"' in d.project_text
    back = state_from_project(d.project_text)
    assert back["tensioner_mechanism"] == "lever" and back["tensioner_arm_length"] == "0.4 m"
    # a missing part is reported on its field
    bad = dict(state, tensioner_spring_stiffness="")
    d, errors = design_from_state(normalise_state(bad))
    assert d is None and "tensioner_spring_stiffness" in errors
