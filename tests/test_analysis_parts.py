"""The declared analysis parts: a toy part added here, in this test module only, is seen by
analyze_drive, to_dict, the report and a study's outputs (issue: one decision in one place)."""

from __future__ import annotations

import json
import tomllib
from dataclasses import dataclass

import pytest

from _shared import EXAMPLES
from chaindrive._results import Result, quantity
from chaindrive.analysis import Check, analyze_drive
from chaindrive.analysis.parts import (
    Part,
    get_part,
    part_names,
    register_part,
    resolve,
    temporary_part,
)
from chaindrive.drive.project import load_project
from chaindrive.errors import ChainDriveError, InputError


@dataclass(frozen=True)
class ChainMass(Result):
    """The toy part's result: the mass of the whole chain."""

    mass: float = quantity("kg")
    links: int = quantity("1")
    note: str = ""


def _chain_mass(ctx):
    lay = ctx["layout"]
    if ctx.drive.chain.mass_per_length is None:
        return None
    ctx.note("toy part: chain mass from the layout's chain length")
    return ChainMass(ctx.drive.chain.mass_per_length * lay.chain_length, lay.links)


def _chain_mass_checks(ctx, res):
    return [Check("toy: chain mass below 100 kg", res.mass, 100.0, "kg", res.mass <= 100.0, "test", relation="<=")]


TOY = Part("chain_mass", "Toy: mass of the chain", _chain_mass, needs=("layout",), checks=_chain_mass_checks,
           order=15)


@pytest.fixture
def toy():
    with temporary_part(TOY) as part:
        yield part
    assert "chain_mass" not in part_names()


def test_toy_part_in_analysis_and_to_dict(toy):
    drive = load_project(EXAMPLES / "roller_industrial.toml")
    a = analyze_drive(drive)
    assert "chain_mass" in a.parts and a.chain_mass is a["chain_mass"]
    # independent: 122 links of 25.4 mm at 2.6 kg/m... computed from the chain data directly
    expected = drive.chain.mass_per_length * a.layout.links * drive.chain.pitch
    assert a.chain_mass.mass == pytest.approx(expected, rel=1e-12)
    check = next(c for c in a.checks if c.part == "chain_mass")
    assert check.verdict == "pass" and check.unit == "kg"
    assert "toy part: chain mass from the layout's chain length" in a.warnings
    d = json.loads(json.dumps(a.to_dict()))
    assert d["chain_mass"]["mass"] == pytest.approx(expected) and d["chain_mass"]["links"] == a.layout.links
    # asked alone: its need is computed, not returned
    only = analyze_drive(drive, include=["chain_mass"])
    assert only.parts == ("chain_mass",) and only.layout is None and only.chain_mass.mass == pytest.approx(expected)
    assert [c.part for c in only.checks] == ["chain_mass"]


def test_toy_part_in_the_report(toy, tmp_path):
    from chaindrive.workflows.sections import build_sections, report_sections

    assert "chain_mass" in [key for key, _, _ in report_sections()]
    a = analyze_drive(load_project(EXAMPLES / "roller_industrial.toml"))
    sections, _ = build_sections(a, figures=False)
    sec = next(s for s in sections if s.title == "Toy: mass of the chain")
    rows = {r[0]: r for r in sec.tables[0].rows}
    assert rows["mass"][2] == "kg" and rows["mass"][1] == pytest.approx(a.chain_mass.mass)
    assert rows["links"][1] == a.layout.links and rows["links"][2] == ""
    assert [c.name for c in sec.checks] == ["toy: chain mass below 100 kg"]
    from chaindrive.workflows.analyze import analyze

    analyze(load_project(EXAMPLES / "roller_industrial.toml"), tmp_path / "run", figures=False)
    html = (tmp_path / "run" / "report.html").read_text()
    assert "Toy: mass of the chain" in html and "toy: chain mass below 100 kg" in html


def test_toy_part_as_a_study_output(toy):
    from chaindrive.drive.project import template
    from chaindrive.study.run import evaluate_variant
    from chaindrive.study.spec import parse_study

    base = tomllib.loads(template("roller"))
    row = evaluate_variant(base, {"drive.speed": "1450 rpm"}, ["chain_mass.mass", "chain_mass.links"])
    assert row["error"] is None and row["chain_mass.mass"] > 0 and row["chain_mass.links"] % 2 == 0
    text = f'''[study]
base = "{(EXAMPLES / 'roller_industrial.toml').as_posix()}"
outputs = ["chain_mass.mass"]
[plan]
kind = "grid"
[[vary]]
path = "drive.speed"
unit = "rpm"
low = 960
high = 1450
count = 2
'''
    study = parse_study(text)
    assert list(study.outputs) == ["chain_mass.mass"]


def test_a_study_output_of_an_undeclared_part_is_refused():
    from chaindrive.study.spec import parse_study

    text = f'''[study]
base = "{(EXAMPLES / 'roller_industrial.toml').as_posix()}"
outputs = ["chain_mass.mass"]
[plan]
kind = "grid"
[[vary]]
path = "drive.speed"
unit = "rpm"
low = 960
high = 1450
count = 2
'''
    with pytest.raises(InputError, match="must start with one of inputs, layout"):
        parse_study(text)


def test_declaration_errors():
    with pytest.raises(InputError, match="part name must be a Python identifier"):
        Part("chain mass", "x", _chain_mass)
    with pytest.raises(InputError, match="part name 'checks' is reserved"):
        Part("checks", "x", _chain_mass)
    with pytest.raises(InputError, match="an analysis part named 'layout' is already declared"):
        register_part(Part("layout", "x", _chain_mass))
    with pytest.raises(InputError, match="unknown analysis part 'layuot' \\(did you mean 'layout'\\?\\)"):
        get_part("layuot")
    with pytest.raises(InputError, match="include: unknown part\\(s\\) 'nope'"):
        analyze_drive(load_project(EXAMPLES / "roller_industrial.toml"), include=["nope"])


def test_circular_and_undeclared_needs():
    a = Part("toy_a", "a", lambda ctx: 1.0, needs=("toy_b",))
    b = Part("toy_b", "b", lambda ctx: 1.0, needs=("toy_a",))
    with temporary_part(a), temporary_part(b):
        with pytest.raises(InputError, match="in a circle: toy_a -> toy_b -> toy_a"):
            resolve(["toy_a"])
    sneaky = Part("toy_c", "c", lambda ctx: ctx["loads"], needs=("layout",))
    with temporary_part(sneaky):
        with pytest.raises(ChainDriveError, match="reads 'loads' without declaring it in needs"):
            analyze_drive(load_project(EXAMPLES / "roller_industrial.toml"), include=["toy_c"])


def test_needs_come_first_and_every_builtin_part_is_declared():
    names = part_names()
    for expected in ("layout", "loads", "slack_sag", "rating", "entry", "vibration", "geometry", "contact",
                     "track_tooth", "wear", "self_regulating"):
        assert expected in names
    plan = [p.name for p in resolve(["wear"])]
    assert plan.index("layout") < plan.index("loads") < plan.index("wear")
    assert plan.index("entry") < plan.index("loads") and plan.index("rating") < plan.index("wear")


def test_every_check_knows_its_part():
    for example in ("roller_industrial.toml", "mining_conveyor.toml", "tractor_track.toml"):
        a = analyze_drive(load_project(EXAMPLES / example))
        assert all(c.part in a.parts for c in a.checks), example


def test_each_parts_warnings_are_its_own_and_a_filter_change_does_not_leak():
    """The analysis records warnings in one context: each part gets the warnings it raised
    (compute and checks), in order, and a part that silences warnings (a filter left behind)
    does not silence the next part's."""
    import warnings as W

    def loud(ctx):
        W.warn("toy_loud: computed", UserWarning, stacklevel=2)
        return 1.0

    def silencer(ctx):
        W.simplefilter("ignore")  # left behind on purpose
        W.warn("toy_silencer: not recorded", UserWarning, stacklevel=2)
        return 2.0

    def after(ctx):
        W.warn("toy_after: computed", UserWarning, stacklevel=2)
        return 3.0

    def after_checks(ctx, res):
        W.warn("toy_after: checked", UserWarning, stacklevel=2)
        return []

    parts = [Part("toy_loud", "l", loud, order=1), Part("toy_silencer", "s", silencer, needs=("toy_loud",), order=2),
             Part("toy_after", "a", after, needs=("toy_silencer",), checks=after_checks, order=3)]
    with temporary_part(parts[0]), temporary_part(parts[1]), temporary_part(parts[2]):
        filters = list(W.filters)
        a = analyze_drive(load_project(EXAMPLES / "roller_industrial.toml"), include=["toy_after"])
        assert list(W.filters) == filters  # the caller's filters untouched
    got = [w for w in a.warnings if w.startswith("toy_")]
    assert got == ["toy_loud: computed", "toy_after: computed", "toy_after: checked"]
