"""Long chains in the simulation: the 100 m conveyor, the static sag of its return strand,
the longitudinal wave speed and the string frequency of a span of 1,000+ links.

References used (provenance of every expected value):
* catenary: ``chaindrive.layout.catenary_sag`` / ``tension_for_sag`` (Irvine, Cable
  Structures, 1981, ch. 1), an independent closed form of the continuous inextensible chain;
* longitudinal waves of a lumped chain: ``ω = 2 sqrt(k/m) sin(κ a/2)`` (Brillouin, Wave
  Propagation in Periodic Structures, 1946, ch. 1), long-wave speed ``c = sqrt(EA/q)``,
  group velocity ``c cos(κ a/2)``;
* taut string: ``f = (1/2L) sqrt(S/q)`` (Rayleigh, Theory of Sound, §124) through
  ``chaindrive.vibration.moving_string_frequencies`` at chain speed 0.
"""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import numpy as np
import pytest

from chaindrive.layout import catenary_sag, tension_for_sag
from chaindrive.simulation import (
    SimulationModel,
    SimWheel,
    assemble,
    conveyor_drive,
    conveyor_example,
    model_from_drive,
    simulate,
)
from chaindrive.simulation import _kernel as K

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "long_conveyor.toml"


@pytest.fixture(scope="module")
def conveyor():
    m = conveyor_example()
    return m, assemble(m)


def test_project_file_is_the_example_drive():
    import dataclasses

    from chaindrive.drive.project import load_project

    # the file without its [conveyor] table (pans, material: tests/test_simulation_conveyor.py)
    a = model_from_drive(dataclasses.replace(load_project(EXAMPLE), conveyor=None), ramp_time=2.0)
    b = conveyor_example()
    assert a.links == b.links == 2194
    assert [w.centre for w in a.wheels] == [w.centre for w in b.wheels]
    assert a.tensioner == b.tensioner
    assert a.pretension == pytest.approx(b.pretension, rel=1e-12)
    assert [w.torque for w in a.wheels] == [w.torque for w in b.wheels]


def test_conveyor_assembles_and_runs(conveyor):
    m, st = conveyor
    # loaded static state: the tight (upper) span carries the slack tension + T/R
    r = simulate(m, 0.05, state=st, samples=20)
    assert np.all(np.isfinite(r.tension)) and np.all(np.isfinite(r.positions))
    radius = float(m.pitch_radii()[2])
    tight0 = float(r.tight_side_tension()[0])
    slack0 = float(r.slack_side_tension()[0])
    # tight - slack = T/R at the tail within the polygon's lever-arm change (the span
    # leaves a 7-pocket wheel at R cos(δ/2) ... R from its axis) and the tension change
    # q g Δy along a sagging span: measured -3.4 %
    assert tight0 - slack0 == pytest.approx(-m.wheels[2].torque / radius, rel=0.06)
    # exact statics of the tail with its seated hinges: the moments of the two boundary
    # links' forces, of the seated hinges' weight and the load torque add up to zero
    pos, ten, con = r.positions[0], r.tension[0], r.contact_force[0]
    c = r.wheel_centres[2]
    seated = np.where((np.hypot(*(pos - c).T) < radius + 0.02) & (con > 0))[0]
    b, e = int(seated.min()), int(seated.max())
    assert e - b + 1 == seated.size  # one run of hinges

    def force(i):
        u = pos[(i + 1) % m.links] - pos[i]
        return ten[i] * u / np.hypot(*u)

    def moment(point, f):
        return float((point[0] - c[0]) * f[1] - (point[1] - c[1]) * f[0])

    weight = np.array([0.0, -9.81 * m.link_mass])
    total = moment(pos[b], -force(b - 1)) + moment(pos[e], force(e)) \
        + sum(moment(pos[k], weight) for k in seated) + m.wheels[2].torque
    assert abs(total) < 1e-3 * abs(m.wheels[2].torque)
    # on the 2 s ramp: the mean over the summary's window 0.025...0.05 s
    assert r.summary["wheel_speed_mean"][0] == pytest.approx(
        m.wheels[0].angular_velocity * 0.0375 / 2.0, rel=0.05)


def test_return_strand_hangs_as_the_catenary(conveyor):
    """The static return strand (tensioner idler → tail, 98.5 m, 1,072 links) against the
    catenary of the layout module: sag from the horizontal tension, and the tension from
    the sag."""
    m, st = conveyor
    r = simulate(m, 1e-5, state=st, samples=2)
    pos, ten, con = r.positions[0], r.tension[0], r.contact_force[0]
    c_idler, c_tail = r.wheel_centres[1], r.wheel_centres[2]
    near_idler = np.hypot(*(pos - c_idler).T) < m.pitch_radii()[1] + 0.02
    near_tail = np.hypot(*(pos - c_tail).T) < m.pitch_radii()[2] + 0.02
    # the pins run idler -> tail with increasing index (counter-clockwise loop)
    a = int(np.max(np.where(near_idler & (con > 0))[0]))
    b = int(np.min(np.where(near_tail & (con > 0) & (np.arange(m.links) > a))[0]))
    span = pos[a:b + 1]
    assert b - a > 1000
    chord_vec = span[-1] - span[0]
    chord = float(np.hypot(*chord_vec))
    incl = math.atan2(chord_vec[1], chord_vec[0])
    # horizontal tension component: constant along a catenary (checked), its mean
    d = np.diff(span, axis=0)
    h = ten[a:b] * d[:, 0] / np.hypot(*d.T)
    assert np.ptp(h) / np.mean(h) < 1e-3
    horizontal = float(np.mean(h))
    q = m.link_mass / m.pitch
    chord_y = span[0, 1] + (span[:, 0] - span[0, 0]) * math.tan(incl)
    sag = float(np.max(chord_y - span[:, 1]))
    expected = float(catenary_sag(chord, incl, horizontal, q, gravity=9.81))
    # measured 2.7591 m vs 2.7619 m (-0.10 %) and H 58,722 N vs 58,663 N (+0.10 %): the
    # stretch T/EA = 1.0e-3 lengthens the chain without adding weight; with the stretched
    # chain's weight per length q/(1 + T/EA) the two agree to 2e-6 (the lumped chain's
    # hinges lie on a discrete catenary)
    assert sag == pytest.approx(expected, rel=2e-3)
    assert float(tension_for_sag(chord, incl, sag, q, gravity=9.81)) == pytest.approx(
        horizontal, rel=2e-3)
    stretched = q / (1.0 + horizontal / m.axial_stiffness)
    assert sag == pytest.approx(float(catenary_sag(chord, incl, horizontal, stretched,
                                                   gravity=9.81)), rel=1e-4)


def _straight_drive(links, *, tension, axial_stiffness=None):
    """26x92 on two locked 7-pocket wheels, no gravity, no friction, no damping: a straight
    span of about ``links/2`` links each side, pretension ``tension``."""
    from chaindrive import chains
    from chaindrive.geometry.polygon import link_chain_pitch_radius

    ch = chains.get("26x92")
    t, d = ch.pitch, ch.bar_diameter
    r_w = float(link_chain_pitch_radius(t, d, 7))
    wheels = [SimWheel.at((0.0, 0.0), 7, 1.0, "speed", 0.0, name="A"),
              SimWheel.at((0.5 * (links - 14) * t, 0.0), 7, 1.0, "free", name="B")]
    opts = dict(pitch=t, links=links, link_mass=ch.mass_per_length * t,
                axial_stiffness=axial_stiffness or 0.854e11 * d * d, roller_radius=0.5 * d,
                bar_diameter=d, wheels=wheels, gravity=(0.0, 0.0), friction=0.0,
                link_damping_ratio=0.0, pretension=tension)
    return SimulationModel(**opts), r_w


def test_longitudinal_wave_speed_is_sqrt_ea_over_q():
    m, _ = _straight_drive(1200, tension=20e3)
    st = assemble(m)
    q = m.link_mass / m.pitch
    c = math.sqrt(m.axial_stiffness / q)
    top = np.where(np.abs(st.pos[:, 1] - st.pos[:, 1].max()) < 1e-3)[0]
    x = st.pos[:, 0]
    x0 = float(np.min(x[top])) + 8.0
    # a right-going Gaussian pulse of the axial displacement u(x - c t), σ = 1 m (11
    # links): its group velocity is c cos(κa/2) with κa <= 0.1 over the pulse's
    # spectrum, within 0.1 % of c
    sigma, amp = 1.0, 2e-5
    s1 = dataclasses.replace(st, pos=st.pos.copy(), vel=st.vel.copy())
    u = amp * np.exp(-0.5 * ((x[top] - x0) / sigma) ** 2)
    s1.pos[top, 0] += u
    s1.vel[top, 0] += c * u * (x[top] - x0) / sigma**2
    duration = 36.0 / c
    r = simulate(m, duration, state=s1, samples=1500)
    # travel time between two links 25 m apart along the top span (5 σ and 30 m ahead of
    # the pulse): the lag that best aligns their tension histories (cross-correlation,
    # refined by a parabola through its peak)
    xs = 0.5 * (r.positions[0, :, 0] + np.roll(r.positions[0, :, 0], -1))
    on_top = np.isin(np.arange(m.links), top[:-1])
    ia, ib = (int(np.argmin(np.where(on_top, np.abs(xs - xp), np.inf)))
              for xp in (x0 + 5.0, x0 + 30.0))
    ya = r.tension[:, ia] - r.tension[0, ia]
    yb = r.tension[:, ib] - r.tension[0, ib]
    corr = np.correlate(yb, ya, mode="full")
    k = int(np.argmax(corr))
    frac = 0.5 * (corr[k - 1] - corr[k + 1]) / (corr[k - 1] - 2 * corr[k] + corr[k + 1])
    lag = (k - (len(ya) - 1) + frac) * (r.time[1] - r.time[0])
    speed = (xs[ib] - xs[ia]) / lag
    # measured 2063.5 m/s vs sqrt(EA/q) = 2060.3 m/s (+0.15 %: the stretch T/EA = 3.5e-4
    # lengthens the span the wave crosses, the rest is the sampling of the lag)
    assert speed == pytest.approx(c, rel=5e-3)


@pytest.mark.slow
def test_plucked_span_of_a_thousand_links_rings_at_the_string_frequency():
    from chaindrive.vibration import moving_string_frequencies

    m, _ = _straight_drive(2030, tension=100e3)
    st = assemble(m)
    r0 = simulate(m, 1e-5, state=st, samples=2)
    p1, p2 = r0.tight_span
    pos = st.pos
    top = np.where((np.abs(pos[:, 1] - p1[1]) < 2e-3) & (pos[:, 0] > p1[0] + 1e-3)
                   & (pos[:, 0] < p2[0] - 1e-3))[0] if p1[0] < p2[0] else \
        np.where((np.abs(pos[:, 1] - p1[1]) < 2e-3) & (pos[:, 0] < p1[0] - 1e-3)
                 & (pos[:, 0] > p2[0] + 1e-3))[0]
    assert top.size > 1000
    # the span between its end hinges (the last pins seated on either wheel)
    ends = [int(top.min()) - 1, int(top.max()) + 1]
    xa, xb = sorted(pos[ends, 0])
    length = xb - xa
    tension = float(np.mean(r0.tension[0, top.min():top.max()]))
    q = m.link_mass * (top.size + 1) / length  # the stretched span's mass per length
    s1 = dataclasses.replace(st, pos=st.pos.copy(), vel=st.vel.copy())
    # 5 mm half-sine over 92 m: the stretch it adds is 7e-9 of the span
    s1.pos[top, 1] += 5e-3 * np.sin(np.pi * (pos[top, 0] - xa) / length)
    mid = top[np.argmin(np.abs(pos[top, 0] - 0.5 * (xa + xb)))]
    f_string = float(moving_string_frequencies(tension, q, length, modes=1)[0]) / (2 * np.pi)
    r = simulate(m, 1.6 / f_string, state=s1, samples=3000)
    y = r.positions[:, mid, 1] - p1[1]
    s = np.sign(y)
    i = np.where(s[:-1] * s[1:] < 0)[0]
    tc = r.time[i] - y[i] * (r.time[i + 1] - r.time[i]) / (y[i + 1] - y[i])
    assert tc.size >= 3
    f_sim = 1.0 / (2 * np.mean(np.diff(tc)))
    # measured 0.46268 Hz vs 0.46219 Hz (+0.11 %; discretisation of the lumped string
    # (π/n)²/24 ~ 1e-7, so this is the zero-crossing estimate over 1.6 periods)
    assert f_sim == pytest.approx(f_string, rel=5e-3)


def test_conveyor_errors():
    from chaindrive.errors import InputError

    with pytest.raises(InputError, match=r"length must lie in \[10, inf\] m, got 5"):
        conveyor_drive(length=5.0)
    with pytest.raises(InputError, match="power"):
        conveyor_drive(power=0.0)
    with pytest.raises(InputError, match="angular_velocity"):
        conveyor_drive(angular_velocity=-1.0)
    with pytest.raises(InputError, match="tensioner_force"):
        conveyor_drive(tensioner_force=0.0)


def test_assembly_methods():
    from chaindrive.errors import UnknownNameError

    m, _ = _straight_drive(60, tension=5e3)
    with pytest.raises(UnknownNameError, match="assembly method must be one of newton, "
                                               "relaxation, got 'implicit'"):
        assemble(m, method="implicit")
    a = assemble(m)
    assert a.wp[1, K.W_CX] > 0
