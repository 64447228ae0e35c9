"""Every command's rendered --help shows each option's unit and an example; bounds at the CLI."""

from __future__ import annotations

import re

import pytest
import typer

from chaindrive.cli import app, main

#: Text options that are names or choices, not quantities.
NOT_QUANTITIES = {
    "chain", "entry", "model", "method", "form", "link", "contact", "gamma_outside", "outside",
    "end_fixity", "joint", "family", "example", "kind", "host", "name", "file", "project",
    "output", "plan", "format", "study", "summary", "template", "sections", "include",
    "exclude", "material", "bore_standard", "keyway", "units", "preset", "scheduler", "write", "strands",
    "driver", "driven_machine", "load_character", "environment", "lubrication",
    "place", "along", "of",  # layout --place: a wheel name, a direction, a wheel name
    "links",  # cad --links FIRST:COUNT: a section of the chain by link indices
}


def _commands() -> dict:
    group = typer.main.get_command(app)
    return dict(group.commands)


def _context(command, name):
    try:  # typer >= 0.20 carries its own copy of click
        from typer._click.core import Context
    except ImportError:  # pragma: no cover - older typer on plain click
        from click import Context
    return Context(command, info_name=name)


def _bare_type(param) -> str:
    bare = getattr(param, "bare_type", None)
    if callable(bare):
        return str(bare())
    return {"STRING": "str", "INT": "int", "FLOAT": "float"}.get(str(param.type), str(param.type))


COMMANDS = sorted(_commands())


def _render(capsys, name: str) -> str:
    assert main([name, "--help"]) == 0
    return " ".join(capsys.readouterr().out.split())


@pytest.mark.parametrize("name", COMMANDS)
def test_help_shows_units_and_examples(capsys, name):
    command = _commands()[name]
    params = command.get_params(_context(command, name))
    assert params, f"{name}: no parameters found (typer internals changed?)"
    text = _render(capsys, name)
    assert "seed" not in text.lower()
    assert not re.search("[\u0400-\u04ff]", text), "Cyrillic symbols in --help: use Latin letters"
    for param in params:
        if getattr(param, "param_type_name", "") != "option" or param.hidden or param.is_flag \
                or param.name == "help":
            continue
        kind = _bare_type(param)
        help_text = " ".join((param.help or "").split())
        assert help_text, f"{name} {param.opts[0]}: no help"
        # the help is printed as typed: nothing eaten as markup
        squeezed = "".join(text.split())  # click wraps lines, also after hyphens
        assert "".join(help_text.split()) in squeezed, f"{name} {param.opts[0]}: help not shown verbatim"
        if kind == "str" and param.name not in NOT_QUANTITIES:
            assert re.search(r"Unit .+?, e\.g\. '[-+.\deE]+ [^']+'", help_text), \
                f"{name} {param.opts[0]}: a quantity option must show its unit and an example"
        if kind in ("int", "float") and name not in ("select", "study", "web"):  # others' option sets
            assert re.search(r"dimensionless|count|bare number|\[-\]|HRC|1/arcmin|unit s\b|\d\.\.\.\d", help_text), \
                f"{name} {param.opts[0]}: a number option must say it is dimensionless (or its unit)"


def test_root_help_says_units_are_required(capsys):
    assert main(["--help"]) == 0
    text = " ".join(capsys.readouterr().out.split())
    assert "a bare number is refused" in text


def test_brackets_survive_in_help(capsys):
    # rich markup used to eat '[m, or ...]'; the help is plain text now
    assert main(["vibration", "--help"]) == 0
    assert "P [rad/s]" not in capsys.readouterr().out  # (not in help) but units are:
    text = _render(capsys, "vibration")
    assert "Unit N/m, e.g. '50 kN/m'." in text and "Unit kg/m, e.g. '2.6 kg/m'." in text


@pytest.mark.parametrize(
    "argv, message",
    [
        (["simulate", "--example", "roller", "-t", "1 h"], "--duration must lie in (0, 60] s, got 3600 s"),
        (["simulate", "--example", "roller", "-t", "2"], '--duration: give a unit, e.g. "2 s" or "2 ms"'),
        (["simulate", "--example", "roller", "--frames", "100000"], "--frames must be a whole number in [0, 1000]"),
        (["crawler", "--pitch", "100 mm", "--teeth", "8", "--speed", "30 rpm", "--points", "100000000"],
         "points must be a whole number in [2, 1000000]"),
        (["vibration", "--tension", "2 kN", "--mass-per-length", "2.6 kg/m", "--span1", "0.8 m",
          "--span2", "0.8 m", "--angle1", "20", "--angle2", "20 deg", "--tensioner-mass", "3 kg",
          "--tensioner-stiffness", "50 kN/m"], '--angle1: give a unit, e.g. "20 deg" or "20 rad"'),
        (["vibration", "--tension", "2 kN", "--mass-per-length", "2.6 kg/m", "--span1", "0.8 m",
          "--span2", "0.8 m", "--angle1", "20 deg", "--angle2", "20 deg", "--tensioner-mass", "3 kg",
          "--tensioner-stiffness", "50 kN/m", "--modes", "1000000"], "modes must be"),
        (["fretting", "--load", "5 kN", "--pin-diameter", "8 mm", "--transverse-pitch", "30 mm",
          "--strands", "1000000000", "--inner-width", "17 mm"], "strands must be a whole number in [1, 100]"),
        (["contact", "--chain", "16B", "--load", "10**10**10 N"], "no arithmetic, no powers of powers"),
        (["contact", "--chain", "16B", "--load", "5 kN", "--skew", "50"],
         '--skew: give a unit, e.g. "50 arcmin" or "50 deg"'),
        (["simulate", "--example", "link", "--speed", "5"], 'a chain speed such as "1.2 m/s" is accepted too'),
        (["simulate", "--example", "link", "--speed", "-1 m/s"], "--speed must be non-negative"),
    ],
)
def test_bounds_and_units_at_the_cli(capsys, argv, message):
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert message in err and "Traceback" not in err


def test_plausibility_warnings_at_the_cli(capsys):
    # a tension above any chain's breaking force warns; an axial rigidity EA in N does not
    assert main(["crawler", "--pitch", "100 mm", "--teeth", "8", "--speed", "30 rpm", "--stiffness", "500 MN",
                 "--sprocket-distance", "2 m", "--cam-distance", "0.7 m", "--points", "5"]) == 0
    assert "warning" not in capsys.readouterr().err
    main(["vibration", "--tension", "50 MN", "--mass-per-length", "2.6 kg/m", "--span1", "0.8 m",
          "--span2", "0.8 m", "--angle1", "20 deg", "--angle2", "20 deg", "--tensioner-mass", "3 kg",
          "--tensioner-stiffness", "50 kN/m"])
    assert "warning: --tension = 50000 kN is implausible" in capsys.readouterr().err
    assert main(["crawler", "--pitch", "2 mm", "--teeth", "8", "--speed", "30 rpm", "--points", "5"]) == 0
    assert "warning: --pitch = 2 mm is implausible" in capsys.readouterr().err
