"""The crawler drive's guide reaction and the check of the cam-force assumptions.

Independent references (no value copied from the implementation):
* statics of the hinge on the guide solved as a 2x2 linear system from positions found
  on the pitch polygon by root finding (not from eq. 6.15);
* the elastic loop solved by minimising its elastic energy over the tensioning
  sprocket's angle (scipy minimize_scalar), instead of the library's moment balance;
* the limit of a rigid return span, where the loop must reduce to the closed form
  cam_force (the rebuilt formula of the crawler drive text).
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.optimize import brentq, minimize_scalar

from chaindrive.errors import InputError
from chaindrive.kinematics.crawler import (
    cam_force,
    cam_pushing_off_force,
    elastic_loop,
    free_span_displacement,
    guide_link_angle,
    guide_reaction,
    guided_displacement,
    leaving_displacement,
)

T, Z = 0.1, 8
G = np.pi / Z
R = T / (2 * np.sin(G))


def hinge_statics(theta, tension):
    """Hinge G on the guide line: positions from the polygon, forces from a linear solve."""
    alpha = np.mod(theta + 2 * G * np.arange(Z), 2 * np.pi)
    a = alpha.min()
    sx, sy = -R * np.sin(a), R * np.cos(a)
    gx = brentq(lambda x: (x - sx) ** 2 + (R - sy) ** 2 - T**2, sx, sx + T, xtol=1e-15)
    ex, ey = (sx - gx) / T, (sy - R) / T  # unit vector G -> S
    # unknowns: link tension T1 and guide force N (along +y); the span pulls +x with `tension`
    M = np.array([[ex, 0.0], [ey, 1.0]])
    t1, n = np.linalg.solve(M, [-tension, 0.0])
    return t1, n


@pytest.mark.parametrize("theta", [0.05, 0.2, 0.5, 0.7, 2 * G * (1 - 1e-9)])
def test_guide_reaction_against_statics(theta):
    _, n = hinge_statics(theta, 12e3)
    assert float(guide_reaction(12e3, guide_link_angle(theta, T, Z))) == pytest.approx(n, rel=1e-9)


def test_guide_reaction_limits_and_errors():
    # largest just before seating: T tan(pi/z); zero when the link lies on the guide
    assert float(guide_reaction(1e3, guide_link_angle(2 * G * (1 - 1e-12), T, Z))) == pytest.approx(
        1e3 * np.tan(G), rel=1e-5)
    assert float(guide_reaction(1e3, 0.0)) == 0.0
    np.testing.assert_allclose(guide_reaction([1.0, 2.0], [0.1, 0.1]), np.tan(0.1) * np.array([1, 2]))
    with pytest.raises(InputError, match="tension must be finite and >= 0"):
        guide_reaction(-1.0, 0.1)
    with pytest.raises(InputError, match=r"link_angle must lie in \[0, pi/2\)"):
        guide_reaction(1.0, np.pi / 2)


def test_pushing_off_force():
    # contact normal at alpha to the chain axis: along-chain component P, across P tan(alpha)
    alpha = np.radians(25)
    normal = 10e3 / np.cos(alpha)
    assert float(cam_pushing_off_force(10e3, alpha)) == pytest.approx(normal * np.sin(alpha))
    assert float(cam_pushing_off_force(-10e3, alpha)) == pytest.approx(normal * np.sin(alpha))
    assert float(cam_pushing_off_force(10e3, 0.0)) == 0.0
    with pytest.raises(InputError, match="face_angle must lie in"):
        cam_pushing_off_force(1.0, -0.1)
    with pytest.raises(InputError, match="cam_force must be finite"):
        cam_pushing_off_force(np.inf, 0.1)


# ----------------------------------------------------------------------------- elastic loop


def loop_energy_force(psi, up, E, A, l, T0, Ec, guide="tangent"):
    """Force on the cam from the loop's energy minimum over the tensioning sprocket angle."""
    on = guided_displacement if guide == "tangent" else free_span_displacement

    def stretches(theta):
        sa = up - float(leaving_displacement(theta, T, Z, guide))
        sb = float(on(psi, T, Z)) - up
        sc = float(free_span_displacement(theta, T, Z)) - float(free_span_displacement(psi, T, Z))
        return sa, sb, sc

    def energy(theta):
        sa, sb, sc = stretches(theta)
        # pretension T0 in every span: work T0 * stretch plus the elastic energy
        return (T0 * (sa + sb + sc) + 0.5 * E / l * sa**2 + 0.5 * E / (A - l) * sb**2
                + 0.5 * Ec / A * sc**2)

    opt = minimize_scalar(energy, bounds=(psi - 0.4 * G, psi + 0.4 * G), method="bounded",
                          options={"xatol": 1e-13})
    sa, sb, _ = stretches(opt.x)
    return (T0 + E / (A - l) * sb) - (T0 + E / l * sa), opt.x - psi


@pytest.mark.parametrize("guide", ["tangent", "none"])
def test_elastic_loop_against_energy_minimum(guide):
    E, A, l, T0 = 5e6, 2.0, 0.7, 4e3
    psi = np.linspace(0.02, 2 * G - 0.02, 7)
    up = Z * T / (2 * np.pi) * psi - 1e-3
    r = elastic_loop(psi, T, Z, E, A, l, up, pretension=T0, guide=guide)
    for i, p in enumerate(psi):
        force, lag = loop_energy_force(p, up[i], E, A, l, T0, E, guide)
        assert r.force[i] == pytest.approx(force, rel=1e-6, abs=1e-3)
        assert r.lag[i] == pytest.approx(lag, abs=1e-8)


def test_rigid_return_span_gives_the_closed_form():
    # the closed form's assumptions: rigid return span (no guide on it) -> tensioning sprocket in
    # phase -> cam_force with the running-off law. The difference shrinks like 1/E_c.
    E, A, l = 5e6, 2.0, 0.7
    psi = np.linspace(0.0, 2 * G, 9)
    up = Z * T / (2 * np.pi) * psi - 2e-3
    rigid = cam_force(E, A, l, guided_displacement(psi, T, Z), up, leaving_displacement(psi, T, Z))
    diffs = []
    for Ec in (5e9, 5e12, 5e15):
        r = elastic_loop(psi, T, Z, E, A, l, up, pretension=5e3, return_stiffness=Ec)
        np.testing.assert_allclose(r.rigid_force, rigid, rtol=1e-14)
        diffs.append(np.max(np.abs(r.force - rigid)))
    assert diffs[2] < 1e-7 * np.max(np.abs(rigid))
    assert diffs[0] / diffs[1] == pytest.approx(1e3, rel=0.01)


def test_elastic_return_span_lowers_the_fluctuation():
    # regression: t = 100 mm, z = 8, E = 5 MN, A = 2 m, l = 0.7 m, T0 = 2 kN, E_c = E.
    # The free tensioning sprocket follows the working span and relieves it: the closed form
    # (rigid return span) overstates the fluctuation of the cam force (5.55 kN against 3.14 kN).
    E, A, l = 5e6, 2.0, 0.7
    psi = np.linspace(0.0, 2 * G, 9)
    up = Z * T / (2 * np.pi) * psi - 2e-3
    r = elastic_loop(psi, T, Z, E, A, l, up, pretension=2e3)
    assert np.ptp(r.rigid_force) == pytest.approx(5554.4904181550155, rel=1e-9)
    assert np.ptp(r.force) == pytest.approx(3136.96, rel=1e-4)
    assert np.ptp(r.force) < np.ptp(r.rigid_force)


def test_elastic_loop_errors():
    with pytest.raises(InputError, match="pretension must be positive"):
        elastic_loop([0.1], T, Z, 5e6, 2.0, 0.7, [0.0], pretension=0.0)
    with pytest.raises(InputError, match="cam_distance must lie in"):
        elastic_loop([0.1], T, Z, 5e6, 2.0, 2.5, [0.0], pretension=1e3)
    with pytest.raises(InputError, match="psi must not be NaN"):
        elastic_loop([np.nan], T, Z, 5e6, 2.0, 0.7, [0.0], pretension=1e3)


@settings(max_examples=25, deadline=None)
@given(st.floats(1e3, 1e5), st.floats(0.0, 0.7))
def test_guide_reaction_grows_with_tension(tension, angle):
    a = float(guide_reaction(tension, angle))
    b = float(guide_reaction(2 * tension, angle))
    assert a >= 0 and b == pytest.approx(2 * a)


# ----------------------------------------------------------------------------- doors: CLI and studio


def test_crawler_drive_summary_has_the_guide_reaction_and_pushing_off():
    from chaindrive.kinematics.crawler import crawler_drive

    r = crawler_drive(T, Z, np.pi, stiffness=5e6, sprocket_distance=2.0, cam_distance=0.7, tension=10e3,
                      traction_force=8e3, cam_face_angle=np.radians(15))
    s = r.summary
    assert s["guide_reaction_max"] == pytest.approx(10e3 * np.tan(G), rel=1e-9)
    assert s["cam_force_max"] == pytest.approx(8e3 + s["force_max"])
    peak = max(abs(8e3 + s["force_min"]), abs(8e3 + s["force_max"]))
    assert s["cam_pushing_off_max"] == pytest.approx(peak * np.tan(np.radians(15)))
    free = crawler_drive(T, Z, np.pi, guide="none", tension=10e3)
    assert "guide_reaction_max" not in free.summary  # no guide, no reaction
    with pytest.raises(InputError, match="traction_force must be non-negative"):
        crawler_drive(T, Z, np.pi, stiffness=5e6, sprocket_distance=2.0, cam_distance=0.7, traction_force=-1.0)


def test_cli_crawler_guide_reaction(capsys):
    from chaindrive.cli import main

    assert main(["crawler", "--pitch", "100 mm", "--teeth", "8", "--speed", "30 rpm", "--stiffness", "5 MN",
                 "-A", "2 m", "-l", "0.7 m", "--tension", "10 kN", "--traction-force", "8 kN",
                 "--cam-face-angle", "15 deg"]) == 0
    out = capsys.readouterr().out
    assert "largest guide reaction at the guide end" in out and "4142.14 N" in out
    assert "pushing-off force on the guide at the cam" in out
    assert main(["crawler", "--pitch", "100 mm", "--teeth", "8", "--speed", "30 rpm", "--tension", "10"]) == 2
    assert "--tension: give a unit" in capsys.readouterr().err


def test_studio_crawler_page_cam_force_and_guide_reaction():
    from chaindrive.web.expert import DEFAULTS, crawler_result
    from chaindrive.web.fields import FieldError

    state = dict(DEFAULTS["crawler"], stiffness="5 MN", sprocket_distance="2 m", cam_distance="0.7 m",
                 tension="10 kN", traction_force="8 kN", cam_face_angle="15 deg")
    r = crawler_result(state)
    guided = r["summaries"]["tangent guide"]
    assert guided["guide_reaction_max"] == pytest.approx(10e3 * np.tan(G), rel=1e-9)
    assert guided["force_range"] == pytest.approx(5659.04, rel=1e-5)
    with pytest.raises(FieldError) as exc:
        crawler_result(dict(state, sprocket_distance="2.05 m"))
    assert exc.value.field == "sprocket_distance"


def test_studio_crawler_table_shows_the_guide_reaction():
    from chaindrive.web.expert import DEFAULTS, crawler_result

    state = dict(DEFAULTS["crawler"], stiffness="5 MN", sprocket_distance="2 m", cam_distance="0.7 m",
                 tension="10 kN", traction_force="8 kN", cam_face_angle="15 deg")
    table = crawler_result(state)["table"]
    rows = {label: (unit, cells) for label, unit, cells in table["rows"]}
    unit, cells = rows["largest guide reaction at the guide end, T tan φ1"]
    assert unit == "kN" and cells[table["columns"].index("tangent guide")] == "4.142"
    assert "pushing-off force on the guide at the cam, P tan α" in rows
