"""The free strand's end tangents and the forces they put on the wheels (issue 30, item 3).

Reference: an independent numerical catenary. The strand is integrated along its arc
length from the equilibrium of an element (Irvine, H. M., *Cable Structures*, MIT Press
1981, ch. 1, eq. (1.1)–(1.3): the tension acts along the tangent, its horizontal
component is constant, its vertical component grows by the weight ``w ds``; an elastic
cable stretches each element by ``T/EA``), with scipy's ``solve_ivp``, and the start
angle and unstretched length are shot (scipy ``root``) so that the strand ends at the
other wheel's tangent point. Nothing of :mod:`chaindrive.conveyor` is used.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import root

from chaindrive import conveyor as C
from chaindrive.analysis.conveyor import conveyor_pull
from chaindrive.drive.project import load_project
from chaindrive.errors import InputError
from chaindrive.layout import GRAVITY


def shoot_catenary(span: float, rise: float, start_tension: float, weight: float,
                   axial_stiffness: float = math.inf) -> tuple[float, float, float]:
    """Start angle, end angle [rad] and end tension [N] of a catenary from (0, 0) to
    (span, rise) with ``start_tension`` at its start (the taut branch), by shooting."""

    def end_point(phi0: float, length: float) -> np.ndarray:
        H, V0 = start_tension * math.cos(phi0), start_tension * math.sin(phi0)

        def rhs(s, y):
            V = V0 + weight * s                      # dV/ds = w (Irvine eq. 1.2)
            T = math.hypot(H, V)
            stretch = 1.0 + T / axial_stiffness      # elastic: ds_stretched = (1 + T/EA) ds
            return [stretch * H / T, stretch * V / T]

        sol = solve_ivp(rhs, (0.0, length), [0.0, 0.0], rtol=1e-12, atol=1e-12)
        return sol.y[:, -1]

    chord = math.hypot(span, rise)
    guess = [math.atan2(rise, span) - 0.5 * weight * chord / start_tension, chord]
    res = root(lambda z: end_point(z[0], z[1]) - [span, rise], guess, tol=1e-13)
    assert res.success
    phi0, length = res.x
    H, V1 = start_tension * math.cos(phi0), start_tension * math.sin(phi0) + weight * length
    return float(phi0), math.atan2(V1, H), math.hypot(H, V1)


@pytest.mark.parametrize("chord, incl, t0, q", [
    (28.8, 0.0125, 11.4e3, 15.4),    # the 30 m scraper conveyor's free return strand
    (28.8, 0.0, 3.5e3, 15.4),        # deep sag (3.28 kN is the least that holds it)
    (1.26, -0.29, 11.4e3, 15.4),     # the short strand down to its tensioner
    (50.0, 0.3, 20e3, 6.7),          # rising
    (50.0, -0.3, 20e3, 6.7),         # falling
])
def test_end_tangents_against_a_shot_catenary(chord, incl, t0, q):
    s = C.free_strand(chord, incl, t0, q)
    phi0, phi1, t1 = shoot_catenary(chord * math.cos(incl), chord * math.sin(incl), t0, q * GRAVITY)
    assert s.start_angle == pytest.approx(phi0, abs=1e-8)
    assert s.end_angle == pytest.approx(phi1, abs=1e-8)
    assert s.end_tension == pytest.approx(t1, rel=1e-9)
    # T cos φ = H at both ends
    assert s.start_tension * math.cos(s.start_angle) == pytest.approx(s.horizontal_tension, rel=1e-10)
    assert s.end_tension * math.cos(s.end_angle) == pytest.approx(s.horizontal_tension, rel=1e-10)


def test_elastic_stretch_changes_the_tangents_little():
    # 18x64 link chain: EA = 0.854e11 d² ≈ 27.7 MN; at 11 kN the tangent moves < 0.01°
    # (0.05 N of force on a wheel), so the inextensible catenary is the analysis' strand
    # (Irvine ch. 1: the elastic term T/EA ≈ 4e-4)
    phi_e, _, _ = shoot_catenary(28.8, 0.36, 11.4e3, 15.4 * GRAVITY, axial_stiffness=27.7e6)
    phi_i, _, _ = shoot_catenary(28.8, 0.36, 11.4e3, 15.4 * GRAVITY)
    assert abs(math.degrees(phi_e - phi_i)) < 1e-2


def _tangent(chord_angle: float, phi: float) -> np.ndarray:
    # level conveyor: the drive's frame is the world's, y up
    del chord_angle
    return np.array([math.cos(phi), math.sin(phi)])


def test_scraper_tensioner_force_from_the_end_tangents():
    # issue 30 item 3: the force on the tensioner is recomputed here from the shot
    # catenaries of the two free strands round it, at the analysis' running tensions, with
    # the wheel where the chain of 956 links puts it
    import dataclasses

    from chaindrive.analysis.layout import drive_layout

    d = load_project("examples/scraper_conveyor.toml")
    r = conveyor_pull(d)
    lay = drive_layout(d)
    # 956 links for a polygon path of 954.37: 104 mm of chain taken up by the tensioner;
    # running, the simulation's wheel sits 0.2682 m below its drawn position (assembled
    # 0.27039 m, then 2.15 mm back up under the running load; benchmarks/conveyor.py model)
    assert r.tensioner_offset + r.tensioner_travel == pytest.approx(0.2682, abs=1.5e-3)
    moved = dataclasses.replace(d.with_wheel("tensioner", position=(1.2, -0.4 - r.tensioner_offset)),
                                links=lay.links)
    wrap = drive_layout(moved).wrap
    q = float(d.chain.mass_per_length)
    w = q * GRAVITY
    # span 0: head -> tensioner (starts at the head's exit tension), span 1: tensioner -> tail
    L0, a0 = float(wrap.span_length[0]), float(wrap.span_angle[0])
    L1, a1 = float(wrap.span_length[1]), float(wrap.span_angle[1])
    _, phi_in, t_in = shoot_catenary(L0 * math.cos(a0), L0 * math.sin(a0), r.slack_tension, w)
    t_out = r.wheel_tension_out[1]
    phi_out, _, _ = shoot_catenary(L1 * math.cos(a1), L1 * math.sin(a1), t_out, w)
    assert t_in == pytest.approx(r.wheel_tension_in[1], rel=1e-5)
    direction = np.array([0.0, -1.0])
    force = float((t_in * _tangent(a0, phi_in) - t_out * _tangent(a1, phi_out)) @ direction)
    assert r.tensioner_force == pytest.approx(force, rel=1e-5)
    # the chord directions would be wrong by the strand's sag angle (about 4.7° at the
    # tensioner): the force from the chords is over 20 % higher
    chord_force = float((t_in * _tangent(a0, a0) - t_out * _tangent(a1, a1)) @ direction)
    assert chord_force > 1.2 * force
    # the spring's force at its travel equals the chain's: one equilibrium
    assert float(d.tensioner.force) - float(d.tensioner.stiffness) * r.tensioner_travel == pytest.approx(
        r.tensioner_force, rel=1e-6)
    # the project's simulation (benchmarks/conveyor.py, 5 s run): slack tension 11,454 N,
    # chain force on the tensioner 4,579 N (link tensions and directions next to the wheel)
    assert r.slack_tension == pytest.approx(11_454, rel=0.05)
    assert r.tensioner_force == pytest.approx(4_579, rel=0.05)


def test_shaft_loads_are_the_chain_pull_tensions_of_one_run():
    d = load_project("examples/scraper_conveyor.toml")
    r = conveyor_pull(d)
    names = [w.name for w in d.wheels]
    head, tail = names.index("drive"), names.index("tail")
    # the head: the tight tension arrives, the slack tension leaves
    assert r.wheel_tension_in[head] == pytest.approx(r.tight_tension, rel=1e-12)
    assert r.wheel_tension_out[head] == pytest.approx(r.slack_tension, rel=1e-12)
    # the idle tail: no drive force, the tension passes round it unchanged
    assert r.tail_force == 0.0
    assert r.wheel_tension_out[tail] == pytest.approx(r.wheel_tension_in[tail], rel=1e-12)
    # two nearly opposite, nearly equal tensions at the tail and the head: |F| ≈ T_in + T_out
    assert r.shaft_loads[tail] == pytest.approx(2 * r.wheel_tension_in[tail], rel=0.01)
    # the head: the slack strand leaves it downwards to the tensioner (about 26°)
    assert 0.95 * (r.tight_tension + r.slack_tension) < r.shaft_loads[head] < r.tight_tension + r.slack_tension
    # the report's loads part shows the same run, with the label of its formula
    from chaindrive.analysis import analyze_drive

    loads = analyze_drive(d, include=("loads",)).loads
    np.testing.assert_allclose(loads.shaft_loads, r.shaft_loads, rtol=1e-12)
    np.testing.assert_allclose(loads.tension_in, r.wheel_tension_in, rtol=1e-12)
    assert loads.effective_pull_formula == "K_s F_head"
    assert loads.effective_pull == pytest.approx(d.load.service_factor * r.head_force, rel=1e-12)
    assert loads.tight == pytest.approx(loads.slack + loads.effective_pull + loads.centrifugal, rel=1e-12)


def test_roller_drive_label_matches_its_formula(roller_drive):
    from chaindrive.analysis import analyze_drive

    roller_drive = roller_drive()
    loads = analyze_drive(roller_drive, include=("loads",)).loads
    R = float(analyze_drive(roller_drive, include=("layout",)).layout.pitch_radii[roller_drive.driving_index])
    assert loads.effective_pull_formula == "K_s T / R"
    assert loads.effective_pull == pytest.approx(roller_drive.load.service_factor * roller_drive.torque() / R,
                                                 rel=1e-12)


def test_free_strand_too_slack_is_refused():
    with pytest.raises(InputError, match="start_tension .* too low"):
        C.free_strand(28.8, 0.0, 100.0, 15.4)


@pytest.mark.slow
def test_conveyor_template_report_labels_match_their_formulas(tmp_path):
    # issue 30 item 3: the template's loads section said "K_s T / R = 27.41 kN" (1.5 × the
    # conveyor pull; T / R would be 73 kN) and drew the idle tail as a driven wheel
    from chaindrive.cli import main

    f = tmp_path / "c.toml"
    assert main(["new", str(f), "--kind", "conveyor"]) == 0
    main(["analyze", str(f), "-o", str(tmp_path / "out")])
    html = (tmp_path / "out" / "report.html").read_text(encoding="utf-8")
    assert "effective pull K_s F_head" in html and "K_s T / R" not in html
    assert "running tensions of the chain pull" in html
    d = load_project(f)
    r = conveyor_pull(d)
    assert r.tail_force == 0.0
    tail = [w.name for w in d.wheels].index("tail")
    assert r.wheel_tension_in[tail] == pytest.approx(r.wheel_tension_out[tail], rel=1e-12)
