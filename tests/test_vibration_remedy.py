"""The remedy of a failed span-vibration check (issue 20, item 4c; issue 30, item 2): a design
that passes, verified by its own analysis, or why none does and which bound stops the search."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from chaindrive.analysis import analyze_drive
from chaindrive.analysis import vibration_remedy as vr
from chaindrive.analysis.layout import drive_layout
from chaindrive.analysis.loads import drive_loads
from chaindrive.analysis.vibration import drive_vibration
from chaindrive.drive.project import load_project
from chaindrive.vibration.excitation import AMPLIFICATION_LIMIT
from chaindrive.workflows.analyze import analyze
from chaindrive.workflows.report import resolve

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


@pytest.fixture(scope="module")
def long(tmp_path_factory):
    out = tmp_path_factory.mktemp("long")
    path = EXAMPLES / "long_conveyor.toml"
    outcome = analyze(load_project(path), out, figures=False, source=path.read_text(encoding="utf-8"))
    return outcome, out


def test_long_conveyor_fails_and_gets_a_passing_proposal(long):
    outcome, out = long
    vib, remedy = outcome.analysis.vibration, outcome.analysis.remedy
    assert vib.passed is False and remedy is not None and remedy.found
    assert remedy.amplification <= AMPLIFICATION_LIMIT * (1 - vr.REQUIRED_MARGIN)
    proposal = load_project(out / "proposal.toml")
    again = analyze_drive(proposal)
    assert again.passed and again.vibration.passed is True and again.remedy is None  # the loop ends
    assert all(c.verdict == "pass" for c in again.checks if c.part == "vibration" and c.relation != "info")


def test_proposal_is_the_users_file_with_only_the_changes(long):
    _, out = long
    text = (out / "proposal.toml").read_text()
    original = (EXAMPLES / "long_conveyor.toml").read_text()
    assert text.startswith("# chaindrive proposal")
    body = text.split("\n\n", 1)[1]
    changed = [(a, b) for a, b in zip(original.splitlines(), body.splitlines(), strict=True) if a != b]
    assert changed and all(a.split("=")[0] == b.split("=")[0] for a, b in changed)  # same keys, same order
    for a, b in changed:  # the user's comment stays on its line
        assert ("#" in a) == ("#" in b) and (a.split("#", 1)[1:] == b.split("#", 1)[1:])
    assert "99999" not in text and "00000001" not in text  # numbers rounded


def test_report_shows_severity_and_the_changes(long):
    outcome, out = long
    sec = next(s for s in outcome.report.sections if s.title.startswith("Span vibration"))
    captions = [t.caption for t in sec.tables]
    assert any(c.startswith("Severity") for c in captions) and "Proposed changes" in captions
    # results.json version 2: the section points into the analysis, where the remedy's numbers are
    data = json.loads((out / "results.json").read_text(encoding="utf-8"))
    remedy = resolve(data, sec.results["remedy"])
    assert remedy["found"] is True and remedy["changes"]


def test_no_remedy_within_the_ranges_says_why_and_which_bound(monkeypatch):
    drive = load_project(EXAMPLES / "long_conveyor.toml")
    monkeypatch.setattr(vr, "REMEDY_RANGES", {"mass": (0.98, 1.02), "stiffness": (0.98, 1.02), "force": (0.98, 1.02),
                                              "shift": (-0.001, 0.001)})
    layout = drive_layout(drive)
    vib = drive_vibration(drive, layout, drive_loads(drive, layout))
    remedy = vr.search_remedy(drive, vib)
    assert remedy is not None and not remedy.found
    assert remedy.amplification > AMPLIFICATION_LIMIT
    assert "still amplifies the response" in remedy.reason and remedy.bounds
    assert "bound" in remedy.reason and remedy.bounds[0] in remedy.reason
    a = analyze_drive(drive, include=["remedy"])
    assert any("no design within the searched ranges" in w for w in a.warnings)


def test_passing_drive_has_no_remedy_and_the_part_can_be_left_out():
    a = analyze_drive(load_project(EXAMPLES / "roller_industrial.toml"), include=["remedy"])
    assert a.remedy is None
    b = analyze_drive(load_project(EXAMPLES / "long_conveyor.toml"), exclude=["remedy"])
    assert b.vibration.passed is False and b.remedy is None


def test_round_significant():
    assert vr.round_significant(4.199999999999999) == 4.2
    assert vr.round_significant(112468.26503806982) == 112000.0
    assert vr.round_significant(0.0) == 0.0 and vr.round_significant(-0.012345) == -0.0123
