"""Tests of the Drive objects, TOML project files (errors with field and line), CLI."""

from __future__ import annotations

import dataclasses
import json
import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from _shared import EXAMPLES, roller_drive
from chaindrive.analysis import (
    analyze_drive,
    drive_entry,
    drive_layout,
    drive_loads,
    drive_rating,
    entry_cases,
    slack_span_sag,
    tensioner_span,
)
from chaindrive.analysis.entry import EntryCase
from chaindrive.analysis.loads import free_entry_acceleration
from chaindrive.chains import get
from chaindrive.cli import main
from chaindrive.drive import Drive, Guide, Load, Tensioner, Wheel, load_project
from chaindrive.drive.project import line_index, parse_project, template
from chaindrive.errors import InputError, UnknownNameError

RPM = 2 * math.pi / 60


def _roller():
    return roller_drive(speed=960 * RPM)


# ---------------------------------------------------------------- objects
def test_drive_roller_numbers():
    d = _roller()
    a = analyze_drive(d)
    lay = a.layout
    assert lay.links == 122 and lay.links_required == pytest.approx(121.5654, abs=1e-3)
    assert lay.centre_distance_for_links.taut == pytest.approx(1.05558, abs=1e-5)
    assert lay.tight_span == 1 and lay.slack_span == 0
    t = drive_loads(d)
    # hand: T = 15e3/(100.531) = 149.208 N·m; R = 77.159 mm; pull = 1933.8 N
    assert t.effective_pull == pytest.approx(149.208 / 0.0771589, rel=1e-4)
    assert t.centrifugal == pytest.approx(2.612 * (19 * 0.0254 * 16) ** 2, rel=1e-9)
    # free entry: a = ω² p / 2 = 100.531² · 0.0127
    assert t.acceleration_peak == pytest.approx((960 * RPM) ** 2 * 0.0127, rel=1e-9)
    assert t.maximum == pytest.approx(t.effective_pull + t.slack + t.centrifugal + t.dynamic)
    # the slack span hangs 2 % of its length (default)
    j = lay.slack_span
    assert slack_span_sag(d, lay, t.slack) == pytest.approx(0.02 * lay.wrap.span_length[j], rel=1e-6)
    # shaft loads: both shafts carry the same resultant (only span tensions act)
    assert t.shaft_loads[0] == pytest.approx(t.shaft_loads[1])
    assert t.shaft_loads[0] == pytest.approx(t.effective_pull + 2 * t.slack, rel=0.01)
    safety = next(c for c in a.checks if c.name.startswith("static safety"))
    assert a.passed and safety.value == pytest.approx(60e3 / a.loads.tight)  # Chernavsky et al. eq. (7.40)
    assert a.rating.rating.teeth == 19 and a.rating.rating.rated_power > 15e3
    assert a.wear.model == "rating" and a.wear.hours_to_limit > 15000
    summary = json.loads(json.dumps(a.to_dict()))
    assert summary["inputs"]["wheels"][1]["teeth"] == 57
    assert summary["inputs"]["chain"]["name"] == "16B-1"


def test_drive_given_acceleration_and_entry_cases():
    d = _roller()
    t = drive_loads(d, acceleration_peak=10.0, moving_mass=2.0)
    assert t.dynamic == 20.0 and "given" in t.acceleration_source
    assert entry_cases(d) == (EntryCase("motor", 0.0254, 19, 960 * RPM, None, "free"),)


def test_free_entry_closed_form_matches_kinematics_module():
    # independent: the kinematics module's general solver for free entry
    for path in ("roller_industrial", "mining_conveyor"):
        d = dataclasses.replace(load_project(EXAMPLES / f"{path}.toml"), guides=())  # free entry
        a_free = free_entry_acceleration(d)
        e = drive_entry(d)
        assert e.driving.case.entry == "free"
        assert e.acceleration_peak == pytest.approx(a_free, rel=1e-6)
    a = analyze_drive(load_project(EXAMPLES / "mining_conveyor.toml"), include=["loads"])
    assert "tangential" in a.loads.acceleration_source


def test_drive_object_errors():
    w = [Wheel("a", "sprocket", 19, (0, 0), driving=True), Wheel("b", "sprocket", 19, (1, 0))]
    with pytest.raises(InputError, match="exactly one wheel must have driving"):
        Drive(chain=get("16B"), speed=10, load=Load(power=1e3),
              wheels=[Wheel("a", "sprocket", 19, (0, 0)), Wheel("b", "sprocket", 19, (1, 0))])
    with pytest.raises(InputError, match="at least 2 wheels"):
        Drive(chain=get("16B"), speed=10, load=Load(power=1e3), wheels=w[:1])
    with pytest.raises(InputError, match="speed must be positive"):
        Drive(chain=get("16B"), speed=0, load=Load(power=1e3), wheels=w)
    with pytest.raises(InputError, match="speed must be finite"):
        Drive(chain=get("16B"), speed=float("inf"), load=Load(power=1e3), wheels=w)
    with pytest.raises(InputError, match=r"guides\[0\].wheel: no wheel named 'c'"):
        Drive(chain=get("16B"), speed=1, load=Load(power=1e3), wheels=w, guides=[Guide("c", 0.1)])
    with pytest.raises(InputError, match="tensioner.wheel: no wheel named 'x'"):
        Drive(chain=get("16B"), speed=1, load=Load(power=1e3), wheels=w, tensioner=Tensioner("x", 1, 1))
    with pytest.raises(InputError, match="kind must be one of"):
        Wheel("a", "gear", 19, (0, 0))
    with pytest.raises(InputError, match="needs teeth"):
        Wheel("a", "sprocket", None, (0, 0), diameter=0.1)
    with pytest.raises(InputError, match="teeth must be a whole number >= 3"):
        Wheel("a", "sprocket", 2, (0, 0))
    # the one whole-number field check (drive._fields._whole): a non-number, a fraction, a bool
    for bad in ("19x", 19.5, True, float("nan"), float("inf")):
        with pytest.raises(InputError, match=r"wheel 'a': teeth must be a whole number >= 3, got") as exc:
            Wheel("a", "sprocket", bad, (0, 0))
        assert exc.value.field == "teeth"
    assert Wheel("a", "sprocket", 19.0, (0, 0)).teeth == 19
    with pytest.raises(InputError, match="exactly one of power and torque"):
        Load()
    with pytest.raises(InputError, match="service_factor must be >= 1"):
        Load(power=1.0, service_factor=0.5)
    with pytest.raises(InputError, match="tensioner.direction must be a non-zero vector"):
        Tensioner("b", 1, 1, direction=(0, 0))
    with pytest.raises(InputError, match="guide.end_distance must be positive"):
        Guide("a", -1.0)
    with pytest.raises(InputError, match="contact: unknown field"):
        Drive(chain=get("16B"), speed=1, load=Load(power=1e3), wheels=w, contact={"skw": 0.01})
    with pytest.raises(InputError, match="slack_sag_ratio must lie in"):
        Drive(chain=get("16B"), speed=1, load=Load(power=1e3), wheels=w, slack_sag_ratio=0.5)


# ---------------------------------------------------------------- examples
@pytest.mark.parametrize("name", ["mining_conveyor", "roller_industrial", "tractor_track"])
def test_examples_load_and_validate(name):
    d = load_project(EXAMPLES / f"{name}.toml")
    a = analyze_drive(d, include=["layout", "loads", "rating"])
    assert a.layout.links >= a.layout.links_required - 1e-9
    assert a.loads.maximum > a.loads.effective_pull > 0
    assert a.passed
    json.dumps(a.to_dict())


def test_mining_example_is_dolipinski_worked_case():
    d = load_project(EXAMPLES / "mining_conveyor.toml")
    assert d.chain.name == "18x64" and d.speed == 5.0
    assert [w.teeth for w in d.wheels if w.kind == "pocket_wheel"] == [8, 8]
    (case,) = entry_cases(d)
    assert case.entry == "tangential"
    assert case.guide_end_distance == pytest.approx(0.256)
    assert case.bar_diameter == pytest.approx(0.018)
    lay = drive_layout(d)
    loads = drive_loads(d, lay)
    span = tensioner_span(d, lay, loads)
    assert span.mass == 60 and span.stiffness == 2e5
    # the tensioner force balances the slack tension over the wrap of the idler
    i = lay.wheel_names.index("tensioner")
    assert loads.slack * 2 * math.sin(lay.wrap.wrap_angle[i] / 2) == pytest.approx(5e3)
    assert lay.take_up is not None and np.all(np.diff(lay.take_up) > 0)
    assert analyze_drive(d, include=["wear"]).wear.model == "archard"


def test_tractor_example_sharipov_load():
    d = load_project(EXAMPLES / "tractor_track.toml")
    # Sharipov p. 34: P = 0.65 G_T φ = 45.5 kN, the whole track's adhesion force, on the track's
    # drive wheel at the pitch radius of 13 teeth, 170 mm; i = 2 rims share it per tooth
    # (P_P = 22.75 kN), they do not halve the wheel's torque (the example read i as the
    # number of tracks until this release: 8.08 kN·m)
    R = 0.170 / (2 * math.sin(math.pi / 13))
    assert drive_loads(d).effective_pull == pytest.approx(16160 / R, rel=1e-9)
    assert 16160 / R == pytest.approx(0.65 * 70e3 * 1.0, rel=0.001)
    assert d.track.rims == 2 and d.track.bolts.count == 12
    assert drive_rating(d) is None  # custom chain: no ANSI rating


def _with(text: str, old: str, new: str) -> str:
    assert old in text
    return text.replace(old, new, 1)


def _line_of(text: str, needle: str) -> int:
    return next(i for i, line in enumerate(text.splitlines(), 1) if needle in line)


def test_error_wrong_unit_names_field_and_line():
    text = _with(template("roller"), 'speed = "960 rpm"', 'speed = "960 kg"')
    with pytest.raises(InputError) as exc:
        parse_project(text, "drive.toml")
    n = _line_of(text, 'speed = "960 kg"')
    assert str(exc.value).startswith(f"drive.toml:{n}: drive.speed: ")
    assert "[mass]" in str(exc.value) and "rad/s" in str(exc.value)


def test_error_missing_field_names_field_and_table_line():
    text = _with(template("roller"), "teeth = 57\n", "")
    with pytest.raises(InputError) as exc:
        parse_project(text, "drive.toml")
    # the second [[wheels]] table
    n = [i for i, line in enumerate(text.splitlines(), 1) if line.strip() == "[[wheels]]"][1]
    assert str(exc.value) == f"drive.toml:{n}: wheel 'fan': a sprocket needs teeth (a whole number >= 3)"


def test_error_missing_required_key():
    text = _with(template("roller"), 'speed = "960 rpm"', "")
    with pytest.raises(InputError, match=r"drive.toml:\d+: drive.speed: required field is missing \(add it to the \[drive\] table\)"):
        parse_project(text, "drive.toml")
    text = template("roller").split("[load]")[0] + "[[wheels]]" + template("roller").split("[[wheels]]", 1)[1]
    with pytest.raises(InputError, match=r"drive.toml: load: required field is missing \(add a \[load\] table\)"):
        parse_project(text, "drive.toml")


def test_error_negative_value():
    text = _with(template("mining"), 'end_distance = "0.256 m"', 'end_distance = "-0.256 m"')
    with pytest.raises(InputError) as exc:
        parse_project(text, "m.toml")
    n = _line_of(text, 'end_distance = "-0.256 m"')
    assert str(exc.value) == (f"m.toml:{n}: guides[0].end_distance: end_distance must be positive "
                              "(0 < end_distance < inf m), got -0.256")


def test_error_teeth_too_few_and_unknown_field():
    text = _with(template("roller"), "teeth = 19", "teeth = 2")
    with pytest.raises(InputError, match=r"drive.toml:\d+: wheels\[0\].teeth: must be a whole number in \[3, 10000\], got 2"):
        parse_project(text, "drive.toml")
    text = _with(template("roller"), "teeth = 19", "teeth = 19\ncolour = 'red'")
    n = _line_of(text, "colour")
    with pytest.raises(InputError, match=rf"drive.toml:{n}: wheels\[0\].colour: unknown field"):
        parse_project(text, "drive.toml")


def test_error_unknown_chain():
    text = _with(template("roller"), 'name = "16B"', 'name = "16X"')
    n = _line_of(text, 'name = "16X"')
    with pytest.raises(UnknownNameError, match=rf"drive.toml:{n}: chain.name: unknown chain '16X'; closest known names: 16B-1"):
        parse_project(text, "drive.toml")


def test_error_toml_syntax_and_missing_file(tmp_path):
    with pytest.raises(InputError, match=r"drive.toml: TOML syntax error: .*line 2"):
        parse_project("[drive]\nspeed = = 3\n", "drive.toml")
    with pytest.raises(InputError, match="does not exist"):
        load_project(tmp_path / "none.toml")


def test_error_two_driving_wheels_and_bad_reference():
    text = _with(template("roller"), 'teeth = 57\n', 'teeth = 57\ndriving = true\n')
    with pytest.raises(InputError, match=r"drive.toml:\d+: wheels: exactly one wheel must have driving = true, got 2"):
        parse_project(text, "drive.toml")
    text = _with(template("mining"), 'wheel = "drive"', 'wheel = "drve"')
    n = _line_of(text, 'wheel = "drve"')
    with pytest.raises(InputError, match=rf"m.toml:{n}: guides\[0\].wheel: no wheel named 'drve'"):
        parse_project(text, "m.toml")


def test_chain_override_and_custom():
    text = _with(template("roller"), 'name = "16B"', 'name = "ANSI 40"\nmass_per_length = "0.62 kg/m"')
    d = parse_project(text)
    assert d.chain.name == "ANSI 40-1" and d.chain.mass_per_length == pytest.approx(0.62)
    d = load_project(EXAMPLES / "tractor_track.toml")
    assert d.chain.family == "custom" and d.chain.pitch == pytest.approx(0.17)


def test_line_index_arrays_and_nesting():
    text = "# c\n[drive]\nspeed = 1\n\n[[wheels]]\nname = 'a'\n[[wheels]]\nname = 'b'\nteeth = 3\n[tensioner]\nmass = 1\n"
    idx = line_index(text)
    assert idx[("drive",)] == 2 and idx[("drive", "speed")] == 3
    assert idx[("wheels", 0)] == 5 and idx[("wheels", 1, "teeth")] == 9
    assert idx[("tensioner", "mass")] == 11


def test_template_unknown_kind():
    with pytest.raises(UnknownNameError, match="unknown template kind 'boat'"):
        template("boat")


# ---------------------------------------------------------------- CLI
def test_cli_new_layout_select(tmp_path, capsys):
    f = tmp_path / "drive.toml"
    assert main(["new", str(f), "--kind", "roller"]) == 0
    assert main(["new", str(f)]) == 2  # exists
    assert "exists" in capsys.readouterr().err
    assert main(["layout", str(f), "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["layout"]["links"] == 122 and out["passed"] is True
    assert main(["layout", str(f)]) == 0
    assert "centre distance for 122 links" in capsys.readouterr().out
    assert main(["select", "--power", "15 kW", "--speed", "1450 rpm", "--ratio", "3", "-K", "1", "--json"]) == 0
    found = json.loads(capsys.readouterr().out)
    assert found["recommended"]["rated_power"] >= 15e3
    assert main(["select", "--power", "15 kW", "--speed", "1450 rpm", "--ratio", "3", "-K", "1"]) == 0
    assert main(["select", "--power", "15 kg", "--speed", "1450 rpm", "--ratio", "3", "-K", "1"]) == 2
    assert "power" in capsys.readouterr().err


def test_cli_layout_error_exit_code(tmp_path, capsys):
    f = tmp_path / "bad.toml"
    f.write_text(template("roller").replace('power = "15 kW"', 'power = "-15 kW"'))
    assert main(["layout", str(f)]) == 2
    assert "bad.toml:" in capsys.readouterr().err


def test_edited_copy_changes_the_loads():
    d = _roller()
    t1 = drive_loads(d).effective_pull
    d2 = dataclasses.replace(d, load=Load(power=30e3))
    assert drive_loads(d2).effective_pull == pytest.approx(2 * t1)
    assert drive_loads(d).effective_pull == t1  # the original is untouched


@settings(max_examples=12, deadline=None)
@given(z1=st.integers(11, 25), k=st.integers(1, 4), a=st.floats(30, 60))
def test_drive_properties(z1, k, a):
    p = 0.0254
    d = Drive(chain=get("16B"), speed=50.0, load=Load(power=5e3),
              wheels=[Wheel("a", "sprocket", z1, (0, 0), driving=True),
                      Wheel("b", "sprocket", z1 * k, (a * p, 0))])
    lay = drive_layout(d, phases=4)
    # links rounded up to even: the centre distance for them is not shorter than given
    assert lay.links % 2 == 0 and lay.links >= lay.links_required
    assert lay.centre_distance_for_links.taut >= lay.centre_distance - 1e-9
    assert np.all(np.diff(lay.take_up) > 0)
    assert sum(lay.wrap.wrap_angle) == pytest.approx(2 * math.pi)
    t = drive_loads(d, lay)
    assert t.tight > t.effective_pull > 0 and t.dynamic_factor >= 1


def test_vertical_drive_slack_from_weight():
    d = Drive(chain=get("16B"), speed=50.0, load=Load(power=5e3),
              wheels=[Wheel("low", "sprocket", 19, (0, 0), driving=True),
                      Wheel("high", "sprocket", 19, (0, 1.0))])
    t = drive_loads(d)
    assert t.slack == pytest.approx(2.612 * 9.80665 * 1.0)
    assert "vertical" in t.slack_source
    assert drive_layout(d).teeth_in_mesh == (9, 9)


@pytest.mark.parametrize("kind", ["roller", "mining", "track", "crawler-conveyor"])
def test_cli_new_each_kind_loads(kind, tmp_path, capsys):
    f = tmp_path / f"{kind}.toml"
    assert main(["new", str(f), "--kind", kind]) == 0
    assert f"wrote {f}" in capsys.readouterr().out
    d = load_project(f)
    assert analyze_drive(d, include=["loads", "rating", "layout"]).passed
    assert f"chaindrive layout {kind}.toml" in f.read_text()


def test_cli_new_crawler_is_the_former_name_of_track(tmp_path, capsys):
    # `--kind crawler` produced the tractor track; the name belongs to the conveyor crawler
    # drive, so it now warns and still writes the track template
    f = tmp_path / "old.toml"
    assert main(["new", str(f), "--kind", "crawler"]) == 0
    err = capsys.readouterr().err
    assert "'crawler' is deprecated" in err and "'track'" in err and "crawler-conveyor" in err
    assert "[track.bolts]" in f.read_text()
    from chaindrive.drive.project import template

    with pytest.warns(FutureWarning, match="template kind 'crawler' is deprecated"):
        assert template("crawler") == template("track")


def test_cli_new_unknown_kind(tmp_path, capsys):
    assert main(["new", str(tmp_path / "x.toml"), "--kind", "boat"]) == 2
    assert "unknown template kind 'boat'" in capsys.readouterr().err


@pytest.mark.parametrize(
    ("kind", "old", "new", "pattern"),
    [
        ("roller", 'power = "15 kW"', 'power = "15 kW"\ntorque = "100 N*m"',
         r"d.toml:\d+: load: give exactly one of power and torque"),
        ("track", 'pitch = "170 mm"', 'pitch = "170 mm"\nbar_diameter = "10 mm"',
         r"d.toml:\d+: chain: give exactly one of roller_diameter"),
        ("mining", 'wheel = "tensioner"', 'wheel = "tens"',
         r"d.toml:\d+: tensioner.wheel: no wheel named 'tens'"),
        ("roller", 'position = ["0 mm", "0 mm"]', 'position = ["0 mm", "0 kg"]',
         r"d.toml:\d+: wheels\[0\].position\[1\]: '0 kg' has units of \[mass\]"),
        ("roller", "teeth = 19", "teeth = 19.5",
         r"d.toml:\d+: wheels\[0\].teeth: must be a whole number in \[3, 10000\], got 19.5"),
        ("roller", "elongation_limit = 0.03", "elongation_limit = 0.5",
         r"d.toml:\d+: drive.elongation_limit: elongation_limit must lie in \(0, 0.1\]"),
        ("roller", "service_factor = 1.0", "service_factor = 0.5",
         r"d.toml:\d+: load.service_factor: service_factor must be >= 1"),
        ("roller", 'kind = "sprocket"', 'kind = "gear"',
         r"d.toml:\d+: wheels\[0\].kind: Input should be 'sprocket', 'pocket_wheel', 'track_wheel' or 'idler'"),
    ],
)
def test_more_schema_errors(kind, old, new, pattern):
    with pytest.raises(InputError, match=pattern) as exc:
        parse_project(_with(template(kind), old, new), "d.toml")
    line = int(str(exc.value).split(":")[1])
    assert 1 <= line <= len(_with(template(kind), old, new).splitlines())


# ------------------------------------------------------------------ units never guessed


@pytest.mark.parametrize(
    ("kind", "old", "new", "pattern"),
    [
        ("roller", 'speed = "960 rpm"', "speed = 960",
         r'd.toml:\d+: drive.speed: give a unit, e.g. speed = "960 rpm" or "960 rad/s" \(a bare number 960 could be '
         r'read in any unit\); or the mean chain speed, e.g. speed = "1.2 m/s"'),
        ("roller", 'speed = "960 rpm"', 'speed = "960"',
         r'd.toml:\d+: drive.speed: give a unit, e.g. "960 rpm" or "960 rad/s"'),
        ("roller", 'power = "15 kW"', "power = 15000",
         r'd.toml:\d+: load.power: give a unit, e.g. power = "15000 W" or "15000 kW"'),
        ("roller", 'position = ["1050 mm", "0 mm"]', 'position = [1.05, "0 mm"]',
         r'd.toml:\d+: wheels\[1\].position\[0\]: give a unit, e.g. position = "1.05 mm" or "1.05 m"'),
        ("mining", 'end_distance = "0.256 m"', "end_distance = 0.256",
         r'd.toml:\d+: guides\[0\].end_distance: give a unit, e.g. end_distance = "0.256 mm"'),
        ("mining", 'mass = "60 kg"', 'mass = "6**6**6 kg"', r"no arithmetic, no powers of powers"),
        ("mining", 'speed = "5 rad/s"', 'speed = "-1.2 m/s"', r"drive.speed: speed must be positive \(0 < chain speed"),
        ("roller", "teeth = 57", "teeth = 10000000000", r"wheels\[1\].teeth: must be a whole number in \[3, 10000\], got 10000000000"),
        ("roller", "# links = 122 ", "links = 10000000000 ", r"drive.links: must be a whole number in \(0, 10000\], got 10000000000"),
    ],
)
def test_bare_numbers_refused_with_line_and_example(kind, old, new, pattern):
    text = _with(template(kind), old, new)
    with pytest.raises(InputError, match=pattern) as exc:
        parse_project(text, "d.toml")
    n = _line_of(text, new.split("\n")[0])
    assert str(exc.value).startswith(f"d.toml:{n}: ")


def test_dimensionless_numbers_stay_bare():
    d = parse_project(_with(template("roller"), "service_factor = 1.0", "service_factor = 1.3"))
    assert d.load.service_factor == 1.3
    d = parse_project(_with(template("roller"), "slack_sag_ratio = 0.02", 'slack_sag_ratio = "2 %"'))
    assert d.slack_sag_ratio == pytest.approx(0.02)


def test_speed_as_chain_speed_pocket_and_roller():
    # independent: the kinematics module's mean speed for Dolipiński et al.'s case (18x64,
    # z = 8, 5 rad/s) is 2 t z ω / 2π; writing that chain speed must give back 5 rad/s
    from chaindrive.kinematics import chain_entry

    v = chain_entry(0.064, 8, 5.0, bar_diameter=0.018).summary["v_mean"]
    d = parse_project(_with(template("mining"), 'speed = "5 rad/s"', f'speed = "{v!r} m/s"'))
    assert d.speed == pytest.approx(5.0, rel=1e-12)
    # roller: 19 teeth, 16B: v = z p n = 19 · 25.4 mm · 960/60 /s = 7.7216 m/s
    d = parse_project(_with(template("roller"), 'speed = "960 rpm"', 'speed = "7.7216 m/s"'))
    assert d.speed == pytest.approx(960 * math.pi / 30, rel=1e-12)
    d = parse_project(_with(template("mining"), 'speed = "5 rad/s"', 'speed = "72 m/min"'))
    assert d.speed == pytest.approx(2 * math.pi * 1.2 / (16 * 0.064), rel=1e-12)


def test_implausible_project_values_warn():
    from chaindrive.errors import ValidityRangeWarning

    with pytest.warns(ValidityRangeWarning, match=r"speed = 13846 rpm is implausible"):
        parse_project(_with(template("roller"), 'speed = "960 rpm"', 'speed = "1450 rad/s"'))
    with pytest.warns(ValidityRangeWarning, match=r"power = 0.0005 kW is implausible"):
        parse_project(_with(template("roller"), 'power = "15 kW"', 'power = "0.5 W"'))
    with pytest.warns(ValidityRangeWarning, match=r"speed \(chain speed\) = 100 m/s is implausible"):
        parse_project(_with(template("mining"), 'speed = "5 rad/s"', 'speed = "100 m/s"'))


@pytest.mark.parametrize("name", sorted(p.stem for p in (Path(__file__).resolve().parents[1] / "examples")
                                         .glob("*.toml") if not p.stem.endswith("_study")))
def test_examples_write_every_quantity_with_its_unit(name):
    # every dimensional value in the shipped examples is a string with a unit
    import tomllib

    from chaindrive.units import is_dimensional

    root = Path(__file__).resolve().parents[1] / "examples"
    data = tomllib.loads((root / f"{name}.toml").read_text(encoding="utf-8"))
    dimensionless = {"teeth", "service_factor", "slack_sag_ratio", "required_static_safety",
                     "elongation_limit", "links", "strands", "direction", "side", "adhesion",
                     "rims", "hardness", "wear_factor", "cam_index", "count", "shear_planes",
                     "friction", "friction_faces", "slip_safety",
                     "chain_friction", "material_friction", "return_friction", "head_share", "efficiency",
                     "power_share"}
    assert is_dimensional("m") and not is_dimensional("")

    def walk(node, key=""):
        if isinstance(node, dict):
            for k, v in node.items():
                walk(v, k)
        elif isinstance(node, list):
            for v in node:
                walk(v, key)
        elif isinstance(node, (int, float)) and not isinstance(node, bool):
            assert key in dimensionless, f"{name}: {key} = {node} has no unit"

    walk(data)


def test_self_regulating_table_loads_and_refuses_bare_numbers():
    text = (EXAMPLES / "self_regulating.toml").read_text()
    d = parse_project(text, "sr.toml")
    assert d.self_regulating.wheel == "motor"
    assert d.self_regulating.pivot == pytest.approx((0.6251, -0.0711))
    assert d.self_regulating.weight == pytest.approx(30.0)
    a = analyze_drive(d, include=["self_regulating"])
    # the carrier model's closed form against its own numerical equilibrium (docs/self_regulating.md)
    assert a.self_regulating.slack_tension_difference < 1e-3
    assert any(c.name.startswith("closed form agrees") and c.passed for c in a.checks)
    bad = text.replace('weight = "30 N"', "weight = 30")
    with pytest.raises(InputError, match=r"sr.toml:\d+: self_regulating.weight: give a unit"):
        parse_project(bad, "sr.toml")
    bad = text.replace('torque_reaction = "carrier"', 'torque_reaction = "carrier"\nspring = "1 N/m"')
    with pytest.raises(InputError, match=r"sr.toml:\d+: .*unknown key"):
        parse_project(bad, "sr.toml")


# ---------------------------------------------------------------- power split and the adjustable wheel


def _multi(**changes):
    text = (Path(__file__).resolve().parents[1] / "examples" / "multi_wheel.toml").read_text(encoding="utf-8")
    for old, new in changes.items():
        assert old in text
        text = text.replace(old, new)
    return text


def test_power_shares_are_read_and_checked():
    d = parse_project(_multi())
    assert [w.power_share for w in d.wheels] == [None, None, 0.6, 0.4]
    assert d.adjustable is not None and d.adjustable.wheel == "take-up idler"
    assert d.power_shares().tolist() == [0.0, 0.0, 0.6, 0.4]
    with pytest.raises(InputError, match=r"power_share of the driven wheels must sum to 1, got 0.6 \+ 0.3"):
        parse_project(_multi(**{"power_share = 0.4": "power_share = 0.3"}))
    with pytest.raises(InputError, match="power_share"):
        parse_project(_multi(**{"power_share = 0.4": "power_share = 1.5"}))
    with pytest.raises(InputError, match="power_share"):
        parse_project(_multi(**{"power_share = 0.4": "power_share = 0"}))
    with pytest.raises(InputError, match="power_share is for a driven wheel"):
        parse_project(_multi(**{"driving = true": "driving = true\npower_share = 0.5"}))
    with pytest.raises(InputError, match="exactly one wheel must have driving"):
        parse_project(_multi(**{'kind = "idler"': 'kind = "idler"\ndriving = true'}))
    with pytest.raises(InputError, match="adjustable.wheel: no wheel named 'nope'"):
        parse_project(_multi(**{'wheel = "take-up idler"': 'wheel = "nope"'}))
    with pytest.raises(InputError, match="adjustable.direction must be a non-zero vector"):
        parse_project(_multi(**{"direction = [0, 1]": "direction = [0, 0]"}))


def test_shares_sum_within_1e_9():
    from chaindrive.chains import get
    from chaindrive.drive import Drive, Load, Wheel

    def drive(a, b):
        return Drive(chain=get("16B"), speed=100.0, load=Load(power=10e3), wheels=[
            Wheel("m", "sprocket", 19, (0, 0), driving=True), Wheel("a", "sprocket", 38, (1, 0), power_share=a),
            Wheel("b", "sprocket", 30, (0.5, 0.8), power_share=b)])

    assert drive(0.3, 0.7 + 5e-10).power_shares().sum() == pytest.approx(1.0)
    with pytest.raises(InputError, match="must sum to 1"):
        drive(0.3, 0.7 + 2e-9)
