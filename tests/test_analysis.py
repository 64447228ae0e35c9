"""Tests of the analysis layer: one drive description in, one typed DriveAnalysis out."""

from __future__ import annotations

import bisect
import dataclasses
import json
import math
import re
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from _shared import EXAMPLES, roller_drive
from chaindrive.analysis import PARTS, Check, DriveAnalysis, analyze_drive
from chaindrive.chains import get
from chaindrive.drive import Drive, Load, Wheel, load_project
from chaindrive.errors import InputError
from chaindrive.workflows.analyze import analyze

BASELINE = Path(__file__).resolve().parent / "data" / "analysis_regression"
NAMES = ["mining_conveyor", "roller_industrial", "tractor_track"]


def _leaves(x, path=""):
    if isinstance(x, dict):
        for k, v in x.items():
            yield from _leaves(v, f"{path}.{k}")
    elif isinstance(x, list):
        for i, v in enumerate(x):
            yield from _leaves(v, f"{path}[{i}]")
    elif isinstance(x, (int, float)) and not isinstance(x, bool):
        yield path, float(x)


#: Numbers of the earlier results.json that moved on purpose (closing note of the
#: analysis-layer issue): the wrap check is now in SI (rad, not degrees). The resonance
#: check's pairs (issue 20): the band is applied to the tensioner paper's three excitations
#: only, so a round link chain's "link passing" 2 z1 ω1 pairs left the band table (it is
#: judged by its forced response, docs/vibration.md §6); the Campbell lines and the free
#: spans' information pairs follow the same excitations (a roller chain's meshing left them,
#: its unequal links z1 ω1/2 came in). The roller-bushing limit of a B-series chain (issue
#: 19): rated by its family's method, ISO 10823, whose B-series roller constant is 21.85 on the
#: standard's 19-tooth basis and tooth factor (19/z1)^1.08, not the ANSI 17 (docs/rating.md); the rated
#: power (link plate) is unchanged.
#: The dynamic load (issue 19): a roller chain's dynamic tension is the spring-mass model's, so the
#: roller example's dynamic load, F_max, dynamic factor, moving mass and static safety moved
#: (docs/design.md, "The dynamic load and the simulation").
MOVED = ("safety.checks", "Loads and safety.tensions.dynamic", "Loads and safety.tensions.maximum",
         "Loads and safety.tensions.moving_mass", "Loads and safety.safety.static_safety",
         "Span vibration and resonance check.tensioner.check",
         "Span vibration and resonance check.check", "Span vibration and resonance check.tensioner.campbell",
         "Span vibration and resonance check.free_spans.check", "Loads and safety.rating.roller_bushing",
         # the B-series link-plate constant 0.00434 (docs/rating.md, "ISO 10823"): the 16B-1 rating of
         # roller_industrial and the wear life that scales with it rise by 0.00434/0.004
         "Loads and safety.rating.link_plate", "Loads and safety.rating.rated_power",
         "Loads and safety.safety.rated_power", "Wear life.life.hours",
         # the required static safety of roller chains 7 -> 6 (Diamond Chain's 1/6 rule on F_max,
         # docs/design.md "One static safety"); the roller example's project file states it
         "Input data.inputs.required_static_safety", "Loads and safety.safety.required_static_safety",
         # issue 29: the static safety by Chernavsky et al. eq. (7.40), without the dynamic tension,
         # against Table 7.19's required value (the roller example no longer states 6)
         "Loads and safety.safety.required_static_safety")
#: Issue 33: the exact model's entry extremes are its true ones (one-sided limits at the seatings,
#: the derivative's roots), not the largest of a 4,000-angle grid, so they and the peak acceleration
#: taken from them moved by 1e-9 to 1e-7 (docs/kinematics.md; tests/test_kinematics.py checks them
#: against 400,000 angles).
MOVED_PATTERNS = (r"^\.Kinematics of the chain entering the wheels \(polygonal effect\)\.[^.]+"
                  r"\.(v_min|v_max|nonuniformity|a_min|a_max|a_abs_max)$",
                  r"^\.Loads and safety\.tensions\.acceleration_peak$")


@pytest.mark.parametrize("name", NAMES)
def test_results_json_numbers_unchanged(name, tmp_path):
    # provenance: tests/data/analysis_regression/*.json are the results.json that
    # `chaindrive analyze` wrote for the three examples before the analysis layer
    # (commit 0e69f60); every number of their sections' results must still be there.
    old = json.loads((BASELINE / f"{name}.json").read_text(encoding="utf-8"))
    drive = load_project(EXAMPLES / f"{name}.toml")
    if name == "tractor_track":
        # the example's torque moved on purpose from 8.08 to 16.16 kN·m (Sharipov's i is the
        # number of toothed rims of the drive wheel, not the number of tracks: docs/strength.md);
        # with the baseline's torque every number of the baseline must still be there
        drive = dataclasses.replace(drive, load=dataclasses.replace(drive.load, torque=8080.0))
    outcome = analyze(drive, tmp_path, figures=False)
    new = json.loads(outcome.files["json"].read_text(encoding="utf-8"))
    values = sorted(v for _, v in _leaves(new))
    missing = []
    for path, v in _leaves({k: s["results"] for k, s in old["sections"].items()}):
        if any(m in path for m in MOVED) or any(re.search(m, path) for m in MOVED_PATTERNS):
            continue
        tol = abs(v) * 1e-9 + 1e-12
        i = bisect.bisect_left(values, v - tol)
        if not (i < len(values) and abs(values[i] - v) <= tol):
            missing.append((path, v))
    assert not missing
    # the mining conveyor's verdict moved on purpose (issue 30): its slack span's forced response
    # is amplified 1.9 times (limit 2.04); the band the baseline failed on is information now
    assert new["passed"] is (True if name == "mining_conveyor" else old["passed"])


def _roller(**changes):
    return roller_drive(speed=100.53, **changes)


def test_drive_cannot_be_changed_in_place():
    d = _roller()
    with pytest.raises(dataclasses.FrozenInstanceError):
        d.speed = 1.0
    with pytest.raises(dataclasses.FrozenInstanceError):
        d.wheels[0].teeth = 21
    with pytest.raises(dataclasses.FrozenInstanceError):
        d.load.power = 1.0
    with pytest.raises(AttributeError):
        d.wheels.append(Wheel("x", "sprocket", 19, (2, 0)))
    # lists given by a caller are copied into tuples
    wheels = [Wheel("a", "sprocket", 19, (0, 0), driving=True), Wheel("b", "sprocket", 19, (1, 0))]
    d2 = Drive(chain=get("16B"), speed=10.0, load=Load(power=1e3), wheels=wheels)
    wheels.pop()
    assert len(d2.wheels) == 2


def _flat(a: DriveAnalysis, part: str):
    return json.dumps(a.to_dict()[part], sort_keys=True)


def test_edited_copy_changes_where_it_should_and_nowhere_else():
    d = _roller()
    a = analyze_drive(d)
    # a stricter required safety changes only the static safety check's limit and verdict
    b = analyze_drive(dataclasses.replace(d, required_static_safety=30.0))
    for part in ("layout", "loads", "rating", "entry", "vibration", "geometry", "wear"):
        assert _flat(a, part) == _flat(b, part), part
    sa = next(c for c in a.checks if c.name.startswith("static safety"))
    sb = next(c for c in b.checks if c.name.startswith("static safety"))
    assert sa.value == sb.value and sb.limit == 30.0 and sa.passed and not sb.passed
    assert a.passed and not b.passed
    # more teeth on the driven wheel: layout and loads change, the entry of the driving wheel not
    c = analyze_drive(d.with_wheel("fan", teeth=60))
    assert c.layout.links != a.layout.links
    assert _flat(a, "entry") == _flat(c, "entry")
    assert c.drive.wheels[1].teeth == 60 and d.wheels[1].teeth == 57


def test_include_and_exclude():
    d = _roller()
    a = analyze_drive(d, include=["loads"])
    assert a.loads is not None and a.layout is None and a.rating is None and a.entry is None
    assert [c.name for c in a.checks] == ["static safety", "peak tension"]
    b = analyze_drive(d, exclude=["vibration", "geometry"])
    assert b.vibration is None and b.geometry is None and b.rating is not None
    with pytest.raises(InputError, match="include: unknown part.*'lay'.*valid: layout"):
        analyze_drive(d, include=["lay"])
    with pytest.raises(InputError, match="exclude: unknown part"):
        analyze_drive(d, exclude="nothing")
    with pytest.raises(InputError, match="drive must be a chaindrive.drive.Drive"):
        analyze_drive({"chain": "16B"})


def test_every_check_has_unit_source_and_verdict():
    for name in NAMES:
        a = analyze_drive(load_project(EXAMPLES / f"{name}.toml"))
        assert a.checks
        for c in a.checks:
            assert isinstance(c, Check) and c.unit and c.source
            assert c.verdict in ("pass", "FAIL", "info", "unknown")
            assert c.value is None or math.isfinite(c.value)
        json.dumps(a.to_dict(), allow_nan=False)


def test_long_conveyor_fails_the_span_vibration_check_only():
    # issue 30: the verdict is the forced response (amplification 3.5 of the driving wheel's
    # run-out, limit 2.04); the mining conveyor, a mode inside the paper's band but its response
    # amplified 1.9 times, passes
    a = analyze_drive(load_project(EXAMPLES / "long_conveyor.toml"))
    assert [c.name for c in a.failed] == ["largest amplification of the slack span's forced response, worst excitation"]
    assert a.vibration.tensioner is not None and a.vibration.passed is False
    assert a.remedy is not None and a.remedy.found  # a way out (issue 20)
    m = analyze_drive(load_project(EXAMPLES / "mining_conveyor.toml"))
    assert m.passed and m.remedy is None


def test_check_margin_and_verdict():
    # value 9.1 against >= 7: 30 % margin; <= limit; within a range; information
    assert Check("a", 9.1, 7.0, "-", True, "s").margin == pytest.approx(0.3)
    assert Check("a", 80.0, 100.0, "Pa", True, "s", relation="<=").margin == pytest.approx(0.2)
    assert Check("h", 50.0, (48.0, 60.0), "HRC", True, "s", relation="within").margin == pytest.approx(2 / 12)
    info = Check("i", 1.0, None, "-", None, "s", relation="info")
    assert info.verdict == "info" and info.margin is None
    assert Check("u", None, 7.0, "-", None, "s").verdict == "unknown"


@settings(max_examples=15, deadline=None)
@given(power=st.floats(100.0, 30e3), factor=st.floats(1.0, 2.0), teeth=st.integers(11, 40))
def test_properties_of_the_analysis(power, factor, teeth):
    d = _roller(load=Load(power=power, service_factor=factor)).with_wheel("motor", teeth=teeth)
    a = analyze_drive(d, exclude=["geometry", "vibration"])
    # the static safety check is F_B / (K_s F_t + S + q v²) (Chernavsky et al. eq. (7.40), no dynamic
    # tension) and its verdict follows from its value; the peak tension is its own check
    s, peak = a.checks_of("loads")[:2]
    assert s.value == pytest.approx(d.chain.breaking_force / a.loads.tight)
    assert s.passed == (s.value >= d.static_safety_required)
    assert peak.value == a.loads.maximum and peak.limit == pytest.approx(d.chain.breaking_force / 6)
    assert peak.passed == (peak.value <= peak.limit)
    # effective pull scales with the service factor, F_max = tight + dynamic
    assert a.loads.effective_pull == pytest.approx(factor * d.torque() / a.layout.pitch_radii[0])
    assert a.loads.maximum == pytest.approx(a.loads.tight + a.loads.dynamic)
    assert set(a.parts) == set(PARTS) - {"geometry", "vibration"}
