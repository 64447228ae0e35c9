"""Published measurements kept as data (tests/data/published/*.csv) and the model they check.

Each CSV carries its provenance in its ``#`` header (source, table or sentence read, conditions,
what is derived and what is assumed); docs/validation_sources.md records what was searched and
what was not readable. Here the articulation-friction efficiency model
(:mod:`chaindrive.life.efficiency`) meets the bicycle-chain measurements found so far, and the
tests keep both where the model agrees and by how much it does not, so that a change of the model
or of its calibration shows.
"""

from __future__ import annotations

import csv
import math
from pathlib import Path

import numpy as np
import pytest

from chaindrive.life import (
    articulation_power_loss,
    full_tension_rig_loss,
    transmission_efficiency,
    two_wheel_power_loss,
)

DATA = Path(__file__).parent / "data" / "published"


def _read(name: str) -> list[dict[str, str]]:
    """Rows of a published-data CSV (the ``#`` provenance header skipped)."""
    with (DATA / name).open(encoding="utf-8") as fh:
        return list(csv.DictReader(line for line in fh if not line.startswith("#")))


def _bicycle(power: float, cadence_rpm: float, front: int, rear: int) -> tuple[float, float, float]:
    """Tight tension [N], loss [W] and efficiency of a 1/2-inch bicycle chain (pin 3.6 mm) by the
    model, slack side unloaded (the rigs below run without a loaded slack side)."""
    pitch = 0.0127
    omega = cadence_rpm * math.pi / 30
    radius = pitch / (2 * math.sin(math.pi / front))
    tension = power / omega / radius
    loss = float(articulation_power_loss(omega * radius, pitch, 0.0036, [front, rear],
                                         [tension, 0.0], [0.0, tension]))
    return tension, loss, float(transmission_efficiency(power, loss))


def _rig(power: float, cadence_rpm: float, front: int, rear: int) -> tuple[float, float]:
    """Loss [W] and "efficiency" ``1 - loss/power`` of Friction Facts' Full Tension Test by the model: no power
    transmitted, the whole loop at the tension of ``power`` (both spans, four articulations)."""
    speed = cadence_rpm * math.pi / 30 * 0.0127 / (2 * math.sin(math.pi / front))
    loss = float(full_tension_rig_loss(speed, 0.0127, 0.0036, [front, rear], power / speed))
    return loss, 1 - loss / power


def test_every_dataset_states_its_source():
    files = sorted(DATA.glob("*.csv"))
    assert len(files) >= 4
    for path in files:
        header = [line for line in path.read_text(encoding="utf-8").splitlines() if line.startswith("#")]
        text = " ".join(header)
        assert "source" in text or "original" in text, path.name
        assert "used by" in text, path.name
        assert _read(path.name), path.name  # and data below the header


# --------------------------------------------------------------------------- Friction Facts, run time
def _runtime() -> dict[str, dict[float, float]]:
    out: dict[str, dict[float, float]] = {}
    for row in _read("friction_facts_chain_runtime.csv"):
        out.setdefault(row["chain"], {})[float(row["run_time_h"])] = float(row["loss_W"])
    return out


def test_friction_facts_running_in_is_small():
    # The calibration uses the losses after 8 h of running-in; the running-in itself (the model has
    # none) moves each chain by 0.26-0.61 W at 250 W, i.e. at most 0.25 percentage point.
    for chain, series in _runtime().items():
        drop = series[0.0] - series[8.0]
        assert 0.2 < drop < 0.65, chain
        assert drop / 250.0 < 0.0025, chain
        assert series[8.0] == min(series.values()), chain  # the loss falls over the run time


def test_friction_facts_chains_against_the_model():
    loss, eta = _rig(250.0, 95.0, 53, 11)
    series = _runtime()
    # chain A (Campagnolo) after 8 h is the calibration point of ARTICULATION_FRICTION, on the Full Tension Test
    # (both spans at 234 N); a drive transmitting the 250 W with its slack side unloaded loses half that
    assert loss == pytest.approx(series["A"][8.0], abs=0.02)
    assert _bicycle(250.0, 95.0, 53, 11)[1] == pytest.approx(loss / 2, rel=1e-12)
    # chain B (Shimano CN-7901): within the 0.5 point aim of issue 32 (-0.09 point)
    assert abs(eta - (1 - series["B"][8.0] / 250.0)) < 0.005
    # chain C (SRAM PC-1091R, factory lube) loses 34 % more on the same rig: the one effective
    # coefficient of the model cannot hold it; the model is 0.90 point above it (kept, not hidden)
    gap_c = eta - (1 - series["C"][8.0] / 250.0)
    assert gap_c == pytest.approx(0.0090, abs=0.0005)


# --------------------------------------------------------------------------- Friction Facts, ring size
def test_ring_size_difference():
    # 39-11 against 53-15 (same ratio, chain coplanar): measured 1.5 W more at (assumed) 250 W.
    (row,) = _read("friction_facts_ring_size.csv")
    power = float(row["power_W_assumed"])
    small = [int(z) for z in row["small_pair"].split("-")]
    large = [int(z) for z in row["large_pair"].split("-")]
    extra = _rig(power, 95.0, *small)[0] - _rig(power, 95.0, *large)[0]
    # the model on Friction Facts' Full Tension Test (their method of measurement; this report's not readable):
    # 1.88 W (its loss fraction ~ 1/z1 + 1/z2), +0.38 W = +0.15 point of 250 W; in a drive with its slack side
    # unloaded it would be half, 0.94 W (-0.22 point): within the aim either way
    assert extra == pytest.approx(1.885, abs=0.01)
    assert abs(extra - float(row["extra_loss_of_small_pair_W"])) / power < 0.005
    assert abs(_bicycle(power, 95.0, *small)[1] - _bicycle(power, 95.0, *large)[1] - 1.5) / power < 0.005
    # independent of the cadence, as the measurement's "same speed" needs
    assert _rig(power, 60.0, *small)[0] - _rig(power, 60.0, *large)[0] == pytest.approx(extra, rel=1e-9)


# --------------------------------------------------------------------------- Spicer et al., cadence
def _spicer() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    rows = _read("spicer2001_efficiency_cadence.csv")
    cadence = np.array([float(r["cadence_rpm"]) for r in rows])
    measured = np.array([float(r["measured_efficiency_percent"]) for r in rows]) / 100
    tension = np.array([_bicycle(float(r["power_W"]), float(r["cadence_rpm"]), int(r["chainring"]),
                                 int(r["sprocket"]))[0] for r in rows])
    return cadence, tension, measured


def test_spicer_cadence_series_is_the_published_form():
    # Spicer et al. fit their data as eta = eta_inf - alpha / T; the secondary reading does too,
    # with the >100 % intercept that Connelly and Allen pointed out (so the reading is consistent
    # with what was said of the original)
    _c, tension, measured = _spicer()
    design = np.vstack([np.ones_like(tension), 1 / tension]).T
    (eta_inf, slope), *_ = np.linalg.lstsq(design, measured, rcond=None)
    fit = design @ np.array([eta_inf, slope])
    r2 = 1 - ((measured - fit) ** 2).sum() / ((measured - measured.mean()) ** 2).sum()
    assert r2 > 0.99
    assert eta_inf == pytest.approx(1.039, abs=0.002) and slope < 0


def test_spicer_cadence_series_against_the_model():
    # The model (articulation friction, slack side unloaded) gives 99.19 % at every cadence of
    # this series. At the highest tension (227 N, 40 rpm) it is 1.39 points above the measurement;
    # the gap grows as 1/T to 9.3 points at 101 N (90 rpm). Spicer et al. found the same:
    # friction does not account for the low-tension losses. NOT matchable: the rig's slack-side tension
    # and the bearings between its torque sensors are not stated, and the series extrapolates above 100 %.
    _c, tension, measured = _spicer()
    model = np.array([_bicycle(100.0, c, 52, 21)[2] for c in _c])
    assert np.ptp(model) < 1e-12 and model[0] == pytest.approx(0.9919, abs=5e-5)
    gap = model - measured
    assert gap[np.argmax(tension)] == pytest.approx(0.0139, abs=5e-4)
    assert np.all(np.diff(gap[np.argsort(-tension)]) > 0)  # the gap grows as the tension falls
    assert gap.max() == pytest.approx(0.0929, abs=5e-4)


def test_spicer_sprocket_effect():
    # Spicer: 52-11 loses 2-5 points more than 52-21. The model's friction gives 0.53 point, below
    # the measured range by a factor 4-10 (while Friction Facts' 39-11 against 53-15 agrees with it,
    # test_ring_size_difference): the two sources disagree; the model follows the later one.
    (row,) = _read("spicer2000_sprocket_effect.csv")
    front, small, large = int(row["chainring"]), int(row["small_sprocket"]), int(row["large_sprocket"])
    diff = 100 * (_bicycle(200.0, 80.0, front, large)[2] - _bicycle(200.0, 80.0, front, small)[2])
    assert diff == pytest.approx(0.526, abs=0.005)
    assert diff < float(row["loss_difference_min_percent"])


# --------------------------------------------------------------------------- Wilson, Bicycling Science
def test_wilson_derailleur_table():
    rows = _read("wilson2004_derailleur_efficiency.csv")
    table = {(float(r["power_W"]), int(r["cog_teeth"])): float(r["efficiency_percent"]) / 100 for r in rows}
    cogs = sorted({cog for _p, cog in table})
    powers = sorted({p for p, _cog in table})
    # the measured loss fraction falls with the power for every cog (a load-independent loss: pulleys,
    # bearings, the slack side's tension); the model with its slack side unloaded has none, its efficiency does
    # not depend on power (test_wilson_table_with_the_derailleur_tension adds the derailleur's)
    for cog in cogs:
        series = [table[(p, cog)] for p in powers]
        assert np.all(np.diff(series) > 0), cog
    # at the highest power (400 W) the bare drive is 0.65-1.2 points above for every cog, whatever the
    # (unstated) chainring of a road bicycle, 39 to 53 teeth: the derailleur is missing
    for front in (39, 42, 46, 50, 52, 53):
        for cog in cogs:
            gap = _bicycle(400.0, 80.0, front, cog)[2] - table[(400.0, cog)]
            assert 0.006 < gap < 0.012, (front, cog)
    # at 50 W it is 5-7 points above: the measured losses there are not the chain's articulation
    gaps = [_bicycle(50.0, 80.0, 52, cog)[2] - table[(50.0, cog)] for cog in cogs]
    assert 0.05 < min(gaps) and max(gaps) < 0.07


# --------------------------------------------------------------------------- the slack side of a derailleur drive
def _spring_tension(bicycle: str = "road") -> float:
    """The derailleur's chain tension T_2 [N] of derailleur_spring_tension.csv (a road Campagnolo: 11.6 N)."""
    return {r["bicycle"]: float(r["force_N"]) for r in _read("derailleur_spring_tension.csv")}[bicycle]


def _derailleur(power: float, cadence_rpm: float, front: int, rear: int, slack: float,
                jockeys: tuple[int, int] = (11, 11)) -> float:
    """Efficiency of a derailleur drive by the model: the lower span and both jockey wheels at ``slack``."""
    omega = cadence_rpm * math.pi / 30
    speed = omega * 0.0127 / (2 * math.sin(math.pi / front))
    loss = two_wheel_power_loss(power, speed, 0.0127, 0.0036, [front, rear], slack_tension=slack, idler_teeth=jockeys)
    return float(transmission_efficiency(power, float(loss)))


def test_spring_tension_is_a_tenth_of_the_racing_load():
    forces = [float(r["force_N"]) for r in _read("derailleur_spring_tension.csv")]
    assert 10.0 < min(forces) and max(forces) < 13.5  # 2.3-3.0 lbf
    # against a tight side of 230-450 N at racing loads: 2-5 %, at 50 W (57 N at 80 rpm on 52T) 20 %
    assert _bicycle(50.0, 80.0, 52, 19)[0] == pytest.approx(56.7, abs=0.1)


def test_pulley_size_implies_the_derailleur_tension():
    # Friction Facts' pulley test at an (assumed) 1.07 m/s: the model's jockey term is 2 T_2 mu r (2 pi v / p) / z per
    # pulley; the slack tension that would reproduce each measured difference by articulation alone is a consequence,
    # not a fit: 28.4 N (10T vs 15T) and 19.9 N (11T vs 15T), above the measured spring tensions 10.2-13.3 N: at the
    # spring's tension the articulation leaves 0.29 and 0.10 W of the measured differences to something else (a
    # bearing torque of the small pulleys, or a cage tension the report does not state): -0.12 and -0.04 point of
    # 250 W, within the aim.
    speed = 95 * math.pi / 30 * 0.0127 / (2 * math.sin(math.pi / 53))

    def per_newton(small: int, large: int) -> float:
        loss = [float(two_wheel_power_loss(250.0, speed, 0.0127, 0.0036, [53, 11], slack_tension=1.0,
                                           idler_teeth=[z, z])) for z in (small, large)]
        return loss[0] - loss[1]

    implied = {int(r["small_pulley_teeth"]): float(r["extra_loss_of_small_W"])
               / per_newton(int(r["small_pulley_teeth"]), int(r["large_pulley_teeth"]))
               for r in _read("friction_facts_pulley_size.csv")}
    assert implied[10] == pytest.approx(28.35, abs=0.05)
    assert implied[11] == pytest.approx(19.89, abs=0.05)
    assert min(implied.values()) > 1.4 * _spring_tension("mountain")
    for r in _read("friction_facts_pulley_size.csv"):
        small, large = int(r["small_pulley_teeth"]), int(r["large_pulley_teeth"])
        assert abs(per_newton(small, large) * _spring_tension() - float(r["extra_loss_of_small_W"])) / 250 < 0.005
    # the ratio of the two differences is the model's (1/10 - 1/15)/(1/11 - 1/15) = 1.375; measured 1.96
    assert per_newton(10, 15) / per_newton(11, 15) == pytest.approx(1.375, abs=1e-3)


def test_wilson_table_with_the_derailleur_tension():
    # The load-independent loss the 50 W points show: the lower span and the two jockey wheels (11T, ASSUMED) at the
    # measured spring tension of a road derailleur (11.6 N, derailleur_spring_tension.csv, not fitted), 52T chainring
    # and 80 rpm (ASSUMED: Wilson's table states neither). The 50 W gaps fall from 5.0-6.7 to 3.7-5.4 points; none of
    # the 12 points is within 0.5 point yet (the cage's own drag: tests/test_life_efficiency.py); at 400 W +0.57 ... +1.01.
    rows = _read("wilson2004_derailleur_efficiency.csv")
    slack = _spring_tension("road")
    gaps = {(float(r["power_W"]), int(r["cog_teeth"])):
            100 * _derailleur(float(r["power_W"]), 80.0, 52, int(r["cog_teeth"]), slack) - float(r["efficiency_percent"])
            for r in rows}
    bare = {k: 100 * _bicycle(k[0], 80.0, 52, k[1])[2] - float(r["efficiency_percent"])
            for k, r in zip(gaps, rows, strict=True)}
    assert sum(abs(g) <= 0.5 for g in gaps.values()) == 0
    assert sum(abs(g) <= 0.5 for g in bare.values()) == 0
    low = [g for (p, _c), g in gaps.items() if p == 50.0]
    assert 3.7 < min(low) and max(low) < 5.4  # still above: pulley bearings, seals are not articulation
    assert all(0.5 < g < 1.05 for (p, _c), g in gaps.items() if p == 400.0)
    assert all(gaps[k] < bare[k] for k in gaps)  # the slack side only adds loss


def test_spicer_highest_tension_with_a_derailleur():
    # Spicer's rig is not described in what could be read; IF it held the slack side like a road derailleur (11.6 N over
    # two 11T pulleys, no cage drag), the model is 1.08 points above the 227 N point and 8.6 above the 101 N one.
    assert 100 * _derailleur(100.0, 40.0, 52, 21, _spring_tension()) - 97.8 == pytest.approx(1.08, abs=0.01)
    assert 100 * _derailleur(100.0, 90.0, 52, 21, _spring_tension()) - 89.9 == pytest.approx(8.59, abs=0.01)


def test_industrial_statements_bound_the_model():
    """Single-speed (industrial) roller drives: only statements without conditions are readable
    (industrial_efficiency_statements.csv: Lanaspeze et al., Mechanics & Industry 23 (2022) 27, introduction,
    "about 99% for single speed transmissions" after Lodge & Burgess 2002 and Kidd; "98.4% by the National Physical
    Laboratory"; "as high as 99%"). Over the makers' usual envelope (ISO 606 08B-24B, 17-25 teeth, ratios 1-4, the
    slack side unloaded) the model's median is 99.0 %, the NPL figure lies inside its range and its highest value
    (large sprockets) exceeds the "as high as 99%" by 0.36 point. Nothing here is fitted: mu comes from the bicycle
    rig (Friction Facts chain A)."""
    from chaindrive import chains

    etas = np.array([1 - float(two_wheel_power_loss(1.0, 1.0, c.pitch, c.pin_diameter, [z, i * z]))
                     for c in (chains.get(f"{n}B-1") for n in ("08", "10", "12", "16", "20", "24"))
                     for z in range(17, 26, 2) for i in range(1, 5)]) * 100
    rows = {r["source"]: r for r in _read("industrial_efficiency_statements.csv")}
    about = rows["lanaspeze2022"]
    assert float(about["efficiency_low_percent"]) <= np.median(etas) <= float(about["efficiency_high_percent"])
    assert etas.min() <= float(rows["npl"]["efficiency_high_percent"]) <= etas.max()
    assert etas.max() - float(rows["darling"]["efficiency_high_percent"]) == pytest.approx(0.36, abs=0.01)
    assert rows["burgess_lodge2004"]["kind"] == "model"  # another model's estimate: a record, not a check
    # regression of the envelope (slack side unloaded: independent of load and speed)
    assert (etas.min(), np.median(etas), etas.max()) == pytest.approx((98.06, 99.00, 99.36), abs=0.01)
