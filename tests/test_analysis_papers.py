"""The source papers' items as analysis parts: the conveyor crawler drive, fretting of a
multi-strand chain, the track drive wheel's rim bolts and worn-chain tip radius.

References (independent of the parts' code):
* the crawler part's kinematics against crawler_drive's closed forms and the mean speed
  z t ω / 2π; its cam force mean against the loads part's effective pull; its guide
  reaction against T tan(π/z) (statics of the hinge, tests/test_crawler_forces.py);
* the fretting part against MultiRowPin directly (the pin beam is checked in
  tests/test_strength_fretting.py against textbook beams);
* the rim bolts against F = T / (n R_b), τ = 4F / (π d²) by hand.
"""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import numpy as np
import pytest

from chaindrive import chains
from chaindrive.analysis import analyze_drive
from chaindrive.drive import load_project
from chaindrive.drive.model import CrawlerSpec, FrettingSpec, RimBoltsSpec
from chaindrive.errors import InputError
from chaindrive.strength import MultiRowPin

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


@pytest.fixture(scope="module")
def crawler():
    return load_project(EXAMPLES / "crawler_conveyor.toml")


@pytest.fixture(scope="module")
def crawler_analysis(crawler):
    return analyze_drive(crawler, include=["crawler_conveyor"])


def test_crawler_part_kinematics_and_forces(crawler, crawler_analysis):
    r = crawler_analysis.crawler_conveyor
    loads = analyze_drive(crawler, include=["loads"]).loads
    t, z, w = 0.0635, 10, 50 * math.pi / 30
    assert r.sprocket_distance == pytest.approx(32 * t) and r.cam_distance == pytest.approx(0.381 + 1.016)
    assert r.mean_speed == pytest.approx(z * t * w / (2 * math.pi), rel=1e-12)
    assert r.transverse_throw == 0.0 and r.guide == "tangent"
    # the mean cam force is the traction force: the effective pull of the loads part
    assert r.traction_force == pytest.approx(loads.effective_pull, rel=1e-12)
    assert r.cam_force_min < r.traction_force < r.cam_force_max
    assert r.cam_force_max - r.cam_force_min == pytest.approx(r.cam_force_range, rel=1e-3)
    # the guide reaction at the driving end: the driving-side tension times tan(π/z) at most
    assert r.guide_reaction_driving <= r.driving_side_tension_max * math.tan(math.pi / z) * (1 + 1e-9)
    # ... and at least the smallest driving-side tension times tan(π/z) near the seating
    assert r.guide_reaction_driving > 0.5 * (loads.slack + loads.effective_pull) * math.tan(math.pi / z)
    assert r.cam_pushing_off == pytest.approx(r.cam_force_max * math.tan(math.radians(15)), rel=1e-9)
    # regression (examples/crawler_conveyor.toml, computed with this code)
    assert r.cam_force_range == pytest.approx(9827.94, rel=1e-5)
    assert r.cam_force_range_elastic == pytest.approx(9069.6, rel=1e-4)
    assert r.guide_reaction_driving == pytest.approx(7318.29, rel=1e-5)


@pytest.mark.slow
def test_crawler_part_checks_and_report(crawler_analysis, tmp_path):
    checks = {c.name: c for c in crawler_analysis.checks}
    assert checks["cam stays on the traction-chain hinge (smallest cam force)"].passed is True
    assert checks["tensioning-side segment stays taut (smallest tension)"].passed is True
    ratio = checks["cam force fluctuation, elastic return span / rigid (the formula's assumption)"].value
    assert 0.5 < ratio < 1.0
    data = crawler_analysis.to_dict()["crawler_conveyor"]
    assert data["guide_reaction_driving"] > 0 and data["cam_force_max"] > 0
    from chaindrive.workflows.analyze import analyze

    out = analyze(crawler_analysis.drive, tmp_path, figures=True)
    html = out.files["html"].read_text(encoding="utf-8")
    assert "Conveyor crawler drive: cam force and guide reaction" in html
    assert "guide reaction at the driving sprocket end, T tan φ1" in html and "cam force, largest" in html
    assert "pushing-off force at the cam, P tan α" in html and "m/s²" in html
    assert (tmp_path / "crawler.png").exists() or "crawler.png" in html


def test_crawler_part_without_guide_and_errors(crawler):
    free = dataclasses.replace(crawler, crawler=dataclasses.replace(crawler.crawler, guide="none"))
    a = analyze_drive(free, include=["crawler_conveyor"])
    assert a.crawler_conveyor.guide_reaction_driving is None
    assert a.crawler_conveyor.transverse_throw > 0
    assert any("no guide" in w for w in a.warnings)
    moved = crawler.with_wheel("driving sprocket", position=(2.05, 0.0))
    with pytest.raises(InputError, match="whole number of pitches"):
        analyze_drive(moved, include=["crawler_conveyor"])
    far = dataclasses.replace(crawler, crawler=CrawlerSpec(stiffness=2e7, cam_distance=3.0))
    with pytest.raises(InputError, match="crawler.cam_distance must lie in"):
        analyze_drive(far, include=["crawler_conveyor"])
    with pytest.raises(InputError, match="crawler: give cam_distance"):
        CrawlerSpec(stiffness=2e7)
    with pytest.raises(InputError, match="crawler.cam_face_angle must lie in"):
        CrawlerSpec(stiffness=2e7, cam_distance=1.0, cam_face_angle=2.0)
    roller = load_project(EXAMPLES / "roller_industrial.toml")
    assert analyze_drive(roller, include=["crawler_conveyor"]).crawler_conveyor is None


def test_fretting_part_multi_strand():
    base = load_project(EXAMPLES / "roller_industrial.toml")
    assert analyze_drive(base, include=["fretting"]).fretting is None  # simplex: no fretting part
    duplex = dataclasses.replace(base, chain=chains.get("16B-2"))
    a = analyze_drive(duplex, include=["fretting", "loads"])
    r = a.fretting
    swing = a.loads.tight - a.loads.slack
    pin = MultiRowPin.from_chain(chains.get("16B-2"))
    assert r.load_swing == pytest.approx(swing)
    assert r.slip_without_plates == pytest.approx(float(pin.bending(swing, intermediate_plates=False).slip_amplitude))
    assert r.slip_with_plates == pytest.approx(float(pin.bending(swing, intermediate_plates=True).slip_amplitude))
    assert r.slip_ratio > 1  # Vikulov: intermediate plates reduce the slip
    assert r.frequency == pytest.approx(19 * 960 / 60)  # tooth frequency of the driving wheel
    assert r.latent_period_with_plates is None  # no [fretting] constants
    spec = FrettingSpec(roughness=0.8e-6, latent_coefficient=1e9, decay_coefficient=1e-6)
    a = analyze_drive(dataclasses.replace(duplex, fretting=spec), include=["fretting"])
    r = a.fretting
    k1, k2, ra = 1e9, 1e-6, 0.8e-6
    tau = k1 * ra * np.exp(-k2 * r.slip_with_plates * r.normal_load * r.frequency / ra)
    assert r.latent_period_with_plates == pytest.approx(tau, rel=1e-12)
    assert r.life_ratio > 1
    assert any(c.name.startswith("fretting latent period") for c in a.checks)


def test_rim_bolts_friction_joint():
    d = load_project(EXAMPLES / "tractor_track.toml")
    bolts = RimBoltsSpec(count=16, circle_radius=0.25, diameter=0.016, joint="friction", friction=0.15,
                         slip_safety=1.25, thread_pitch=0.002, yield_strength=640e6)
    a = analyze_drive(dataclasses.replace(d, track=dataclasses.replace(d.track, bolts=bolts)),
                      include=["rim_bolts"])
    r = a.rim_bolts
    torque = 22750.0 * 0.17 / (2 * math.sin(math.pi / 13))
    # VDI 2230-1 step R2: F_V = S T / (μ q n R_b)
    assert r.required_preload == pytest.approx(1.25 * torque / (0.15 * 16 * 0.25), rel=1e-12)
    assert r.yield_safety is not None and any(c.name.startswith("rim bolt preload") for c in a.checks)
    with pytest.raises(InputError, match="track.bolts.joint must be"):
        RimBoltsSpec(count=4, circle_radius=0.2, diameter=0.02, joint="welded")


def test_worn_tip_check_fails_for_a_short_tooth():
    d = load_project(EXAMPLES / "tractor_track.toml")
    worn = dataclasses.replace(d, elongation_limit=0.1)  # 10 %: pins ride above R_0 + 1.2 r
    a = analyze_drive(worn, include=["track_tooth"])
    check = next(c for c in a.checks if c.name.startswith("tip radius holds the worn chain"))
    r0 = 0.17 / (2 * math.sin(math.pi / 13))
    assert check.limit == pytest.approx(1.1 * r0, rel=1e-12) and check.passed is False


def test_studio_shows_the_fretting_table_for_a_multi_strand_chain():
    from chaindrive.web.design import normalise_state
    from chaindrive.web.studio import studio_payload

    p = studio_payload(normalise_state({"chain": "16B-2"}))
    assert p["errors"] == {} and p["chain"]["name"] == "16B-2"
    rows = {name: (value, unit) for name, value, unit in p["fretting"]["rows"]}
    assert rows["strands"] == ("2", "") and rows["slip without plates"][1] == "mm"
    assert float(rows["slip ratio"][0]) > 1
    assert "fretting" not in studio_payload(normalise_state({"chain": "16B-1"}))


def test_expert_track_wheel_page_shows_the_worn_chain_tip():
    from chaindrive.web.expert import DEFAULTS, wheel_result
    from chaindrive.web.fields import FieldError

    rows = {label: (value, unit) for label, value, unit in wheel_result("track-wheel", DEFAULTS["track-wheel"])
            ["dimensions"]}
    r0 = 0.17 / (2 * math.sin(math.pi / 13))
    assert float(rows["worn tip radius"][0]) == pytest.approx(1.03 * r0 * 1e3, abs=0.05)
    with pytest.raises(FieldError, match="elongation_limit"):
        wheel_result("track-wheel", dict(DEFAULTS["track-wheel"], elongation_limit="0.5"))
