"""Every size-like input bounded at every door, and messages naming what the user typed.

Reproducers of issue "Nothing lost under races, links, kills and stalled clients": a
sprocket of 1,000,000 teeth ran 94 s; `contact --k-phi -1` named the formula's
``wear_factor``; `select --ratio 1e300` printed a 300-digit number.
"""

from __future__ import annotations

import numpy as np
import pytest

from chaindrive.cli import main
from chaindrive.errors import InputError
from chaindrive.geometry.outline import Line, Outline
from chaindrive.geometry.part import check_part_size, plate_volume, sprocket_part
from chaindrive.geometry.sprocket import Sprocket, iso_tooth_form, sprocket_outline
from chaindrive.limits import MAX_PRIMITIVES, MAX_SOLID_TEETH, MAX_TEETH


def _cli(capsys, *argv: str) -> tuple[int, str]:
    code = main(list(argv))
    err = capsys.readouterr().err.strip()
    return code, err


# --------------------------------------------------------------------------- bounds


@pytest.mark.parametrize("call", [
    lambda: sprocket_outline(0.0254, 1_000_000, 0.01588),
    lambda: sprocket_outline(0.0254, 1_000_000, 0.01588, method="ansi"),
    lambda: Sprocket(0.0254, MAX_TEETH + 1, 0.01588),
    lambda: Sprocket.from_chain("16B", 10**9),
])
def test_sprocket_teeth_bounded_in_the_api(call):
    with pytest.raises(InputError, match=rf"teeth must be at most {MAX_TEETH} \(chaindrive.limits.MAX_TEETH"):
        call()


def test_tooth_form_and_outline_bounds():
    with pytest.raises(InputError, match=rf"teeth must be a whole number in \[3, {MAX_TEETH}\]"):
        iso_tooth_form(0.0254, 10**7, 0.01588)
    line = Line((0.0, 0.0), (1.0, 0.0))
    with pytest.raises(InputError, match=rf"outline has {MAX_PRIMITIVES + 1} lines and arcs; at most "
                                         rf"{MAX_PRIMITIVES}"):
        Outline([line] * (MAX_PRIMITIVES + 1), 1.0, np.zeros((0, 2)))
    small = Outline([line, line.reversed()], 1.0, np.zeros((0, 2)))
    with pytest.raises(InputError, match=r"points_per_arc must be a whole number in \[2, 10000\]"):
        small.polyline(10**9)
    with pytest.raises(InputError, match=r"points_per_arc must be a whole number in \[2, 10000\]"):
        plate_volume(small, 0.01, points_per_arc=10**9)
    with pytest.raises(InputError, match=r"points must be a whole number in \[0, 10000\]"):
        line.sample(10**9)


def test_solids_and_drawings_bounded():
    part = sprocket_part(Sprocket.from_chain("16B", MAX_SOLID_TEETH + 1))
    with pytest.raises(InputError, match=rf"teeth: a 3-D solid is built for at most {MAX_SOLID_TEETH} teeth"):
        check_part_size(part, MAX_SOLID_TEETH, what="a 3-D solid")
    from chaindrive.geometry.solid import part_solid, write_step

    for call in (lambda: part_solid(part), lambda: write_step(part, "never.step")):
        with pytest.raises(InputError, match="at most 150 teeth"):
            call()
    check_part_size(part)  # a drawing may have it (the sheet decides)


def test_sprocket_cli_refuses_a_million_teeth_at_once(capsys):
    code, err = _cli(capsys, "sprocket", "--chain", "16B", "--teeth", "1000000", "--json")
    assert code == 2
    assert err == (f"error: --teeth must be at most {MAX_TEETH} (chaindrive.limits.MAX_TEETH; ISO 606:2015 "
                   "Annex A tabulates z = 9...150), got 1e+06")
    code, err = _cli(capsys, "pocket-wheel", "--chain", "18x64", "--teeth", "1000000", "--json")
    assert code == 2 and err.startswith("error: --teeth must be a whole number in [3, 10000]")


# --------------------------------------------------------------------------- messages


@pytest.mark.parametrize("argv, expected", [
    (["contact", "--load", "5 kN", "--chain", "16B", "--k-phi", "-1"],
     "error: --k-phi must lie in (0, 1], got -1"),
    (["contact", "--load", "5 kN", "--chain", "16B", "--seat-radius", "0 mm"],
     "error: --seat-radius must be positive and finite (0 < --seat-radius < inf m), got 0"),
    (["contact", "--load", "5 kN", "--chain", "16B", "--poisson", "0.7"],
     "error: --poisson must lie in [0, 0.5), got 0.7"),
    (["select", "--power", "7 kW", "--speed", "1450 rpm", "--ratio", "1e300", "--load-character", "smooth"],
     "error: --ratio must be a finite number in (0, 20], got 1e+300"),
    (["select", "--power", "7 kW", "--speed", "1450 rpm", "--ratio", "3", "--load-character", "smooth", "--teeth", "1000000"],
     "error: --teeth must be a whole number in [3, 10000], got 1000000"),
])
def test_messages_name_the_option_typed(capsys, argv, expected):
    code, err = _cli(capsys, *argv)
    assert code == 2 and err == expected


def test_long_numbers_shortened_in_messages():
    from chaindrive.cli import shorten_numbers

    assert shorten_numbers("got " + str(10**300)) == "got 1e+300"
    assert shorten_numbers("got 123456789012345678901234.5 m") == "got 1.23457e+23 m"
    assert shorten_numbers("hash abc1234567890123456789") == "hash abc1234567890123456789"


def test_plot_file_name_too_long_names_the_option(tmp_path, capsys):
    name = str(tmp_path / ("k" * 300 + ".png"))
    code, err = _cli(capsys, "kinematics", "--pitch", "64 mm", "--bar-diameter", "18 mm", "--teeth", "8",
                     "--speed", "1 rad/s", "--plot", name)
    assert code == 2 and err.startswith("error: --plot: the file name 'kkkk") and "at most 250 bytes" in err
    assert len(err) < 200
