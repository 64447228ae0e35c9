"""The efficiency model's two constants against published data: the articulation friction read off
Friction Facts' Full Tension Test, and the derailleur cage's load-independent drag.

Provenance: tests/data/published/friction_facts_chain_runtime.csv (Friction Facts / CeramicSpeed, "Chain
Efficiency vs. Run Time", Table 1: 53T/11T, 95 rpm, "250 W", chain A 6.67 W after 8 h, read by the Full Tension
Test while the running-in ran by the Full Load Test "at 250W actual rotational load"),
wilson2004_derailleur_efficiency.csv (D. G. Wilson, *Bicycling Science*, 3rd ed., MIT Press, 2004, p. 343, as
quoted by D. Connelly, 2010: efficiency of a 6-speed derailleur drive against power for three cogs; the chainring
and cadence are not stated: 52T and 80 rpm ASSUMED, as in tests/test_published_data.py),
derailleur_spring_tension.csv (the road derailleur's 11.6 N, measured), friction_facts_pulley_size.csv (Friction
Facts: 10T/11T against 15T jockey wheels, the same bearings moved) and friction_facts_derailleur_cage.csv (Friction
Facts / CeramicSpeed: a stock Dura-Ace cage 3.25-3.80 W). The friction is FITTED on chain A alone, the drag on
Wilson's three 50 W points alone; both are CHECKED on his nine 100-400 W points and on the measured cage.
"""

from __future__ import annotations

import csv
import math
from pathlib import Path

import numpy as np
import pytest

from chaindrive.errors import InputError
from chaindrive.life import (
    ARTICULATION_FRICTION,
    DERAILLEUR_DRAG,
    articulation_power_loss,
    full_tension_rig_loss,
    transmission_efficiency,
    two_wheel_power_loss,
)

DATA = Path(__file__).parent / "data" / "published"
PITCH, PIN, JOCKEYS = 0.0127, 0.0036, (11, 11)  # 1/2-inch bicycle chain, pin 3.6 mm; 11T jockey wheels (assumed)


def _read(name):
    with (DATA / name).open(encoding="utf-8") as fh:
        return list(csv.DictReader(line for line in fh if not line.startswith("#")))


def _speed(cadence_rpm, front):
    return cadence_rpm * math.pi / 30 * PITCH / (2 * math.sin(math.pi / front))


def _spring():
    return {r["bicycle"]: float(r["force_N"]) for r in _read("derailleur_spring_tension.csv")}["road"]


# --------------------------------------------------------------------------- the articulation friction
def test_friction_is_chain_a_on_the_full_tension_rig():
    # Friction Facts' Full Tension Test transmits no power: the loop is tensioned to the 234 N of 250 W at 95 rpm on
    # 53T, both spans, and all four articulations carry it. mu is what makes the model lose chain A's 6.67 W there.
    (row,) = [r for r in _read("friction_facts_chain_runtime.csv") if r["chain"] == "A" and r["run_time_h"] == "8"]
    v = _speed(95.0, 53)
    per_mu = float(full_tension_rig_loss(v, PITCH, PIN, [53, 11], 250.0 / v, friction=1.0))
    assert ARTICULATION_FRICTION == pytest.approx(float(row["loss_W"]) / per_mu, abs=5e-4)  # 0.13646, stored 0.1365
    # as a sum over the articulations: each wheel's entry and exit at the loop's tension
    by_wheel = articulation_power_loss(v, PITCH, PIN, [53, 11], [250.0 / v] * 2, [250.0 / v] * 2)
    assert float(full_tension_rig_loss(v, PITCH, PIN, [53, 11], 250.0 / v)) == pytest.approx(float(by_wheel), rel=1e-12)


def test_full_tension_rig_loses_twice_the_drive_with_an_unloaded_slack_side():
    # the drive transmitting P = T v: two articulations at T (leaving the driver, entering the driven wheel), two at
    # zero; the rig: four at T. Exactly twice, at any speed, tension and teeth (closed form 2 mu r (2 pi/p) v T sum 1/z)
    for v, t, teeth in ((1.07, 234.4, [53, 11]), (0.5, 80.0, [39, 25]), (3.0, 1500.0, [19, 57])):
        rig = float(full_tension_rig_loss(v, PITCH, PIN, teeth, t))
        drive = float(two_wheel_power_loss(t * v, v, PITCH, PIN, teeth))
        assert rig == pytest.approx(2 * drive, rel=1e-12)
        closed = 2 * ARTICULATION_FRICTION * PIN / 2 * 2 * math.pi / PITCH * v * t * sum(1 / z for z in teeth)
        assert rig == pytest.approx(closed, rel=1e-12)
    arr = full_tension_rig_loss(1.0, PITCH, PIN, [53, 11], np.array([100.0, 200.0]))
    assert arr.shape == (2,) and arr[1] == pytest.approx(2 * arr[0], rel=1e-12)


def test_full_tension_rig_refuses_bad_input():
    with pytest.raises(InputError, match="tension"):
        full_tension_rig_loss(1.0, PITCH, PIN, [53, 11], -1.0)
    with pytest.raises(InputError, match="tension"):
        full_tension_rig_loss(1.0, PITCH, PIN, [53, 11], math.nan)
    with pytest.raises(InputError, match="teeth must be >= 2"):
        full_tension_rig_loss(1.0, PITCH, PIN, [1, 11], 100.0)
    with pytest.raises(InputError, match="pin_diameter must be smaller than the pitch"):
        full_tension_rig_loss(1.0, PITCH, 0.02, [53, 11], 100.0)


# --------------------------------------------------------------------------- the derailleur cage's drag
def _wilson():
    """{(power, cog): (measured efficiency, the model's loss without the cage drag [W])} at 52T, 80 rpm."""
    v = _speed(80.0, 52)
    out = {}
    for r in _read("wilson2004_derailleur_efficiency.csv"):
        p, cog = float(r["power_W"]), int(r["cog_teeth"])
        loss = float(two_wheel_power_loss(p, v, PITCH, PIN, [52, cog], slack_tension=_spring(), idler_teeth=JOCKEYS))
        out[(p, cog)] = (float(r["efficiency_percent"]) / 100, loss)
    return out, v


def _gaps(drag):
    """Model minus measured [points] at every Wilson point with the cage drag ``drag`` [N]."""
    table, v = _wilson()
    return {k: 100 * (float(transmission_efficiency(k[0], loss + drag * v)) - m) for k, (m, loss) in table.items()}


def test_drag_is_the_least_squares_fit_on_wilsons_50_w_points():
    # the watts the model lacks at 50 W, averaged (least squares of a constant), over the chain speed
    table, v = _wilson()
    lacking = [(1 - m) * p - loss for (p, _cog), (m, loss) in table.items() if p == 50.0]
    assert len(lacking) == 3
    assert DERAILLEUR_DRAG == pytest.approx(float(np.mean(lacking)) / v, abs=0.005)  # 2.4552 N, stored rounded


def test_drag_checked_on_wilsons_100_to_400_w_points():
    # the nine points not fitted: none within 0.5 point without the drag (the slack side's tension alone: +0.57 ...
    # +3.24), 7 of 9 with it; the largest gap 3.24 -> 1.08 point (the 13T at 100 W: that cog loses ~1 point more
    # than the model at 50 and 100 W, a cog-specific, load-independent loss such as a chain-line offset, which
    # Wilson's table does not let one model), the mean |gap| 1.62 -> 0.38
    before = {k: g for k, g in _gaps(0.0).items() if k[0] > 50.0}
    after = {k: g for k, g in _gaps(DERAILLEUR_DRAG).items() if k[0] > 50.0}
    assert len(after) == 9
    assert sum(abs(g) <= 0.5 for g in before.values()) == 0
    assert sum(abs(g) <= 0.5 for g in after.values()) == 7
    assert max(map(abs, before.values())) == pytest.approx(3.24, abs=0.01)
    assert max(map(abs, after.values())) == pytest.approx(1.08, abs=0.01)
    assert max(after, key=lambda k: abs(after[k])) == (100.0, 13)
    assert np.mean(np.abs(list(after.values()))) < 0.38 < 1.6 < np.mean(np.abs(list(before.values())))
    # at 400 W (the load-proportional articulation dominates) all three within 0.5 point: +0.47, +0.03, +0.32
    assert all(abs(g) < 0.5 for (p, _c), g in after.items() if p == 400.0)
    # and at 50 W (the fit) the gaps fall from 3.8-5.4 to -0.55 ... +1.03
    fit = [g for k, g in _gaps(DERAILLEUR_DRAG).items() if k[0] == 50.0]
    assert -0.6 < min(fit) and max(fit) < 1.05


def test_derailleur_checked_on_the_measured_cage():
    # Friction Facts / CeramicSpeed: a stock Dura-Ace cage costs 3.25 W (low speed) to 3.80 W (high speed); the chain
    # speed, power and cage tension are not readable: 53/11, 95 rpm, 250 W (1.07 m/s) and the road spring's 11.6 N
    # assumed. The model's derailleur (the slack span at T_2 over the sprockets and two 11T pulleys, and the drag):
    # 3.49 W, within the measured range; without the drag 0.87 W, far below (the articulation is not the cage's loss).
    (row,) = [r for r in _read("friction_facts_derailleur_cage.csv") if "Dura-Ace" in r["cage"]]
    v = _speed(95.0, 53)

    def derailleur(drag):
        with_cage = float(two_wheel_power_loss(250.0, v, PITCH, PIN, [53, 11], slack_tension=_spring(),
                                               idler_teeth=JOCKEYS, drag_force=drag))
        return with_cage - float(two_wheel_power_loss(250.0, v, PITCH, PIN, [53, 11]))

    assert derailleur(DERAILLEUR_DRAG) == pytest.approx(3.49, abs=0.01)
    assert float(row["loss_low_W"]) < derailleur(DERAILLEUR_DRAG) < float(row["loss_high_W"])
    assert derailleur(0.0) < 0.3 * float(row["loss_low_W"])


def test_drag_leaves_the_pulley_size_differences_alone():
    # Friction Facts moved the same bearings between the pulleys: the measured differences (0.49 W 10T vs 15T,
    # 0.25 W 11T vs 15T); the model's articulation at the road spring's 11.6 N gives 0.20 and 0.15 W (the rest, 0.29
    # and 0.10 W, is not readable from the report: a higher cage tension, or a pulley bearing torque of ~1/3 of the
    # drag). The drag, per cage, cancels from the difference; as a bearing torque (power ~ 1/R) the whole fitted drag
    # would add 0.94 and 0.68 W to them, more than the measured differences themselves: it is mostly per cage.
    v = _speed(95.0, 53)
    for r in _read("friction_facts_pulley_size.csv"):
        small, large = int(r["small_pulley_teeth"]), int(r["large_pulley_teeth"])

        def loss(z, drag):
            return float(two_wheel_power_loss(250.0, v, PITCH, PIN, [53, 11], slack_tension=_spring(),
                                              idler_teeth=[z, z], drag_force=drag))

        with_drag = loss(small, DERAILLEUR_DRAG) - loss(large, DERAILLEUR_DRAG)
        assert with_drag == pytest.approx(loss(small, 0.0) - loss(large, 0.0), abs=1e-12)
        measured = float(r["extra_loss_of_small_W"])
        assert 0.0 < measured - with_drag < 0.3
        radius = [PITCH / (2 * math.sin(math.pi / z)) for z in (11, small, large)]
        torque = DERAILLEUR_DRAG * _speed(80.0, 52) / (2 * _speed(80.0, 52) / radius[0])  # the same watts as a torque
        as_torque = 2 * torque * v * (1 / radius[1] - 1 / radius[2])
        assert as_torque > 0.6 and with_drag + as_torque > 1.5 * measured


def test_drag_adds_its_force_times_the_speed():
    # independent of the load, the teeth and the slack side: F_d v on top of the articulation
    for power, teeth, slack in ((50.0, [52, 13], 0.0), (400.0, [39, 24], 11.6)):
        base = float(two_wheel_power_loss(power, 0.9, PITCH, PIN, teeth, slack_tension=slack, idler_teeth=JOCKEYS))
        got = float(two_wheel_power_loss(power, 0.9, PITCH, PIN, teeth, slack_tension=slack, idler_teeth=JOCKEYS,
                                         drag_force=DERAILLEUR_DRAG))
        assert got - base == pytest.approx(DERAILLEUR_DRAG * 0.9, rel=1e-12)
    arr = two_wheel_power_loss(np.array([50.0, 100.0]), 0.9, PITCH, PIN, [52, 13], drag_force=np.array([0.0, 1.0]))
    assert arr.shape == (2,)
    # regression (the docstring's example)
    assert float(two_wheel_power_loss(250.0, 1.0664, PITCH, PIN, [53, 11], slack_tension=11.6, idler_teeth=[11, 11],
                                      drag_force=DERAILLEUR_DRAG)) == pytest.approx(6.8310, abs=5e-4)


def test_drag_force_refuses_bad_input():
    with pytest.raises(InputError, match="drag_force"):
        two_wheel_power_loss(100.0, 0.9, PITCH, PIN, [52, 13], drag_force=-1.0)
    with pytest.raises(InputError, match="drag_force"):
        two_wheel_power_loss(100.0, 0.9, PITCH, PIN, [52, 13], drag_force=math.nan)
