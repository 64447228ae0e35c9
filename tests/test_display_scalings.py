"""Display units in one module (issue 31, item 3): the command line and the web pages scale no SI
value by hand; a length is shown in mm, a force in kN, a power in kW through chaindrive.display."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from chaindrive.display import CONVERSIONS, kn, kn_per_m, kw, mm, mpa, ms, scaled, um

SRC = Path(__file__).parents[1] / "src" / "chaindrive"
# a product or quotient of an SI value by a power of ten written by hand (not a bound or a unit definition)
SCALING = re.compile(r"[*/]\s*1e[36]\b(?!\s*/)|[*/]\s*1e-[36]\b")
# every command-line module is covered
NOT_YET: set[str] = set()


@pytest.mark.parametrize("folder", ["cli", "web"])
def test_no_hand_written_display_scaling(folder):
    found = []
    for path in sorted((SRC / folder).rglob("*.py")):
        rel = path.relative_to(SRC).as_posix()
        if rel in NOT_YET:
            continue
        for n, line in enumerate(path.read_text("utf-8").splitlines(), 1):
            code = line.split("#", 1)[0]
            if SCALING.search(code) and "IMPERIAL" not in code and ": (" not in code:
                found.append(f"{rel}:{n}: {line.strip()}")
    assert found == []


def test_scaled_is_the_one_table():
    # the conversions are the definitions of the prefixes (SI brochure, 9th ed., Table 7)
    assert mm(0.0254) == 25.4 and um(2.5e-6) == pytest.approx(2.5) and ms(0.5) == 500.0
    # a kilo unit divides exactly as written by hand: 12345.678 / 1e3, not * 1e-3 (the last digit may differ)
    for x in (12345.678, 4906.3, 0.1 + 0.2, 7.5e3):
        assert kn(x) == x / 1e3 and kw(x) == x / 1e3 and kn_per_m(x) == x / 1e3 and mpa(x * 1e3) == x * 1e3 / 1e6
    with pytest.raises(KeyError):
        scaled(1.0, "m", "furlong")
    assert CONVERSIONS[("N", "kN")] == 1e-3


def test_margin_is_the_checks_number(capsys, tmp_path):
    """The studio, `layout` and `analyze` show a check's margin from its own number (Check.margin),
    never from its limit text (web.engine._margin is gone)."""
    import chaindrive.web.engine as engine
    from chaindrive.analysis import analyze_drive
    from chaindrive.cli import main
    from chaindrive.display import check_margin_text
    from chaindrive.drive.project import parse_project, template

    assert not hasattr(engine, "_margin")
    drive = parse_project(template("roller"))
    checks = analyze_drive(drive, exclude=["remedy"]).checks
    page = engine.light_analysis(drive).checks
    assert [c["margin"] for c in page] == [c.margin for c in checks]
    static = next(c for c in checks if c.name.startswith("static safety"))
    # margin = value / limit - 1 for a lower bound (">=")
    assert static.margin == pytest.approx(static.value / static.limit - 1.0, rel=1e-15)
    f = tmp_path / "roller.toml"
    f.write_text(template("roller"))
    main(["layout", str(f)])
    out = capsys.readouterr().out
    assert f"margin {check_margin_text(static)}" in " ".join(out.split())
