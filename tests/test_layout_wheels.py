"""Every wheel checked (issue 30, item 4): impossible layouts refused with the wheel
named, wrap and teeth in mesh on every power sprocket with advice, a wheel placed for a
requested wrap (``chaindrive layout --place``)."""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from chaindrive import layout as L
from chaindrive.analysis import analyze_drive
from chaindrive.analysis.placement import place_wheel
from chaindrive.drive.project import load_project
from chaindrive.errors import InputError

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "multi_wheel.toml"


@pytest.fixture(scope="module")
def multi():
    return load_project(EXAMPLE)


def _layout(drive):
    return analyze_drive(drive, include=("layout",))


# ------------------------------------------------------------------ reproducers, refused
def test_driven_wheel_on_the_motor_centre_is_refused(multi):
    with pytest.raises(InputError, match=r"'motor' and 'machine B' have the same centre") as exc:
        _layout(multi.with_wheel("machine B", position=(0.0, 0.0)))
    assert exc.value.field == "wheels[3].position"


def test_overlapping_sprockets_are_refused(multi):
    # centres 150 mm apart, pitch radii 153.8 + 121.5 = 275.3 mm (16B: 38 and 30 teeth)
    with pytest.raises(InputError, match=r"'machine A' and 'machine B' overlap: centres 150.0 mm apart, "
                                         r"pitch radii 153.8 \+ 121.5 = 275.3 mm") as exc:
        _layout(multi.with_wheel("machine B", position=(1.15, -0.05)))
    assert exc.value.field == "wheels[3].position"


def test_chain_crossing_a_wheel_is_refused(multi):
    # the 30-tooth machine B on the top strand of this 150 mm deep drive: the bottom strand
    # (idler to machine A) runs through it
    with pytest.raises(InputError, match=r"the chain from 'take-up idler' to 'machine A' runs through "
                                         r"wheel 'machine B'") as exc:
        _layout(multi.with_wheel("take-up idler", position=(0.25, -0.08)).with_wheel("machine B",
                                                                                       position=(0.6, 0.0)))
    assert exc.value.field == "wheels[3].position"


def test_refusal_at_the_cli_names_the_wheel(tmp_path, capsys):
    from chaindrive.cli import main

    text = EXAMPLE.read_text(encoding="utf-8").replace('position = ["800 mm", "800 mm"]',
                                                        'position = ["0 mm", "0 mm"]')
    f = tmp_path / "d.toml"
    f.write_text(text, encoding="utf-8")
    assert main(["analyze", str(f), "-o", str(tmp_path / "out")]) == 2
    # refused where the file is read, with its line
    assert "d.toml:53: wheels 'motor' and 'machine B' have the same centre" in capsys.readouterr().err


# ------------------------------------------------------------------ reproducer, fails
def _little_wrap(multi):
    # a 12-tooth machine B taking 40 % of the power, just touching the top strand
    return multi.with_wheel("machine B", teeth=12, position=(0.7, 0.052))


def test_driven_wheel_with_no_wrap_fails_with_advice(multi):
    a = _layout(_little_wrap(multi))
    assert math.degrees(a.layout.wrap.wrap_angle[3]) == pytest.approx(1.43, abs=0.01)
    assert a.layout.teeth_in_mesh[3] == 0
    checks = {c.name: c for c in a.checks}
    wrap = checks["wrap on driven wheel 'machine B'"]
    mesh = checks["teeth in mesh on driven wheel 'machine B'"]
    assert wrap.passed is False and mesh.passed is False and not a.passed
    assert wrap.limit == pytest.approx(math.radians(120.0))
    assert mesh.limit == 3.0
    assert "ISO 10823" in wrap.source and "Diamond Chain" in wrap.source
    # the advice is computed: move the wheel to the printed position, and it passes
    m = re.search(r'position = \["(-?\d+) mm", "(-?\d+) mm"\]', wrap.note)
    assert m, wrap.note
    moved = _little_wrap(multi).with_wheel("machine B", position=(int(m[1]) / 1e3, int(m[2]) / 1e3))
    b = _layout(moved)
    assert b.passed
    assert math.degrees(b.layout.wrap.wrap_angle[3]) >= 120.0


def test_every_example_wheel_passes_or_is_an_idler():
    root = EXAMPLE.parent
    for f in sorted(root.glob("*.toml")):
        try:
            d = load_project(f)
        except InputError:          # study files, not drives
            continue
        a = _layout(d)
        for c in a.checks:
            if "wrap" in c.name or "mesh" in c.name:
                assert c.passed is not False or c.name.startswith("teeth in mesh on driving wheel 'drive'"), (f, c)


def test_idlers_and_link_chain_pockets_are_information():
    a = _layout(load_project(EXAMPLE.parent / "long_conveyor.toml"))
    checks = {c.name: c for c in a.checks}
    assert checks["wrap on idler 'tensioner'"].relation == "info"
    # a 7-pocket wheel under a round link chain: the roller chain's 3-teeth rule does not apply
    assert checks["pockets in mesh on driving wheel 'drive'"].passed is None


# ------------------------------------------------------------------ placement
@pytest.mark.parametrize("wrap_deg", [120.0, 125.0, 140.0])
def test_place_wheel_gives_the_requested_wrap(multi, wrap_deg):
    p = place_wheel(multi, "machine B", math.radians(wrap_deg))
    # independent re-check: the drive's own layout with the wheel moved (links re-fitted)
    a = _layout(p.drive)
    assert math.degrees(a.layout.wrap.wrap_angle[3]) == pytest.approx(wrap_deg, abs=1e-6)
    assert math.degrees(p.wrap) == pytest.approx(wrap_deg, abs=1e-9)
    assert p.distance >= 0


def test_place_wheel_along_a_line_and_for_another_wheel(multi):
    # move machine A to the right until machine B has 125°
    p = place_wheel(multi, "machine A", math.radians(125.0), along=(1.0, 0.0), target="machine B")
    assert abs(p.direction[0]) == pytest.approx(1.0) and p.direction[1] == pytest.approx(0.0, abs=1e-12)
    assert p.position[1] == pytest.approx(-0.05)
    assert math.degrees(float(L.wrap_layout(
        np.array(_layout(p.drive).layout.wrap.centres), multi.pitch_radii(),
        [w.side for w in multi.wheels]).wrap_angle[3])) == pytest.approx(125.0, abs=1e-6)


@pytest.mark.parametrize("kwargs, field, match", [
    (dict(wheel="machine C", wrap=2.0), "wheel", "not in the drive"),
    (dict(wheel="machine B", wrap=2.0, target="nope"), "target", "not in the drive"),
    (dict(wheel="machine B", wrap=math.radians(359.0)), "wrap", "no position within"),
    (dict(wheel="machine B", wrap=0.0), "wrap", r"must lie in \(0°, 360°\)"),
    (dict(wheel="machine B", wrap=2.0, along=(0.0, 0.0)), "direction", "non-zero"),
])
def test_place_wheel_errors(multi, kwargs, field, match):
    wheel = kwargs.pop("wheel")
    wrap = kwargs.pop("wrap")
    with pytest.raises(InputError, match=match) as exc:
        place_wheel(multi, wheel, wrap, **kwargs)
    assert exc.value.field == field


def test_layout_place_cli(capsys):
    from chaindrive.cli import main

    assert main(["layout", str(EXAMPLE), "--place", "machine B", "--wrap", "130 deg"]) == 0
    out = capsys.readouterr().out
    assert "wrap on 'machine B' there 130.00°" in out and "position = [" in out
    assert main(["layout", str(EXAMPLE), "--place", "machine B", "--wrap", "130"]) == 2
    assert "give a unit" in capsys.readouterr().err
    assert main(["layout", str(EXAMPLE), "--wrap", "130 deg"]) == 2
    assert "--place and --wrap go together" in capsys.readouterr().err
    assert main(["layout", str(EXAMPLE), "--place", "machine B", "--wrap", "130 deg", "--along", "1,x"]) == 2
    assert "--along must be two numbers" in capsys.readouterr().err


@settings(max_examples=8, deadline=None)
@given(x=st.floats(-0.3, 0.3), y=st.floats(0.4, 1.2), want=st.floats(60.0, 170.0))
def test_place_for_wrap_property(x, y, want):
    # three wheels: wherever the third starts, a placement found gives exactly the wrap
    c = np.array([[0.0, 0.0], [1.0, 0.0], [0.5 + x, y]])
    r = [0.1, 0.08, 0.06]
    try:
        s = L.place_for_wrap(c, r, None, 2, [0.0, 1.0], math.radians(want))
    except InputError:
        return
    c[2, 1] += s
    assert math.degrees(float(L.wrap_layout(c, r).wrap_angle[2])) == pytest.approx(want, abs=1e-6)
    assert not L.clearance_problems(c, r)


def test_clearance_problems_crossing():
    # a span passing through a fourth wheel listed out of the chain's order
    c = [[0, 0], [1, 0], [1, 1], [0, 1], [0.5, 0.5]]
    out = L.clearance_problems([[0, 0], [1, 0], [0.5, 0.9]], [0.1, 0.1, 0.1])
    assert out == []
    out = L.clearance_problems(c[:4], [0.1] * 4)
    assert out == []
    assert L.clearance_problems([[0, 0], [1, 0], [0.5, -0.05]], [0.1, 0.1, 0.08], [1, 1, -1])


def test_both_advices_pass_when_followed(multi):
    # the example as it was (machine B at 117.8° of wrap): move it, or add an idler
    import dataclasses

    from chaindrive.drive import Wheel

    old = multi.with_wheel("machine B", position=(0.75, 0.75))
    a = _layout(old)
    wrap = {c.name: c for c in a.checks}["wrap on driven wheel 'machine B'"]
    assert wrap.passed is False and math.degrees(wrap.value) == pytest.approx(117.8, abs=0.05)
    pos = r'position = \["(-?\d+) mm", "(-?\d+) mm"\]'
    moves = re.findall(pos, wrap.note)
    assert len(moves) == 2, wrap.note
    (mx, my), (ix, iy) = ((int(x) / 1e3, int(y) / 1e3) for x, y in moves)
    moved = _layout(old.with_wheel("machine B", position=(mx, my)))
    assert moved.passed and math.degrees(moved.layout.wrap.wrap_angle[3]) >= 120.0
    m = re.search(r"on the back of the span '(.+?)' → '(.+?)'", wrap.note)
    assert m and m[1] == "machine A" and m[2] == "machine B"
    wheels = list(old.wheels)
    wheels.insert(3, Wheel("advised idler", "idler", 17, (ix, iy), side=-1))
    with_idler = _layout(dataclasses.replace(old, wheels=wheels, links=None))
    checks = {c.name: c for c in with_idler.checks}
    assert checks["wrap on driven wheel 'machine B'"].passed
    assert math.degrees(with_idler.layout.wrap.wrap_angle[4]) >= 120.0
    assert with_idler.passed


def test_place_for_wrap_refuses_a_search_without_bounds():
    # found by scripts/fuzz.py at 10,000 API inputs: reach = -1e300, tolerance = -0.01 never ended
    from chaindrive.layout import place_for_wrap

    c, r = [[0, 0], [0.5, -0.1], [1, 0]], [0.1, 0.05, 0.1]
    with pytest.raises(InputError, match=r"reach must lie in \(0, 10000\] m"):
        place_for_wrap(c, r, None, 1, [0, -1], math.radians(60), reach=-1e300)
    with pytest.raises(InputError, match=r"tolerance must lie in \(0, reach"):
        place_for_wrap(c, r, None, 1, [0, -1], math.radians(60), tolerance=-0.01)
    with pytest.raises(InputError, match=r"steps must be a whole number in \[2, 10000\]"):
        place_for_wrap(c, r, None, 1, [0, -1], math.radians(60), steps=10**9)
