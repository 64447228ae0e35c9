"""The remedy of a failed resonance check (issue 20, item 4c): a design that passes, or why none does."""

from __future__ import annotations

from pathlib import Path

import pytest

from chaindrive.analysis import analyze_drive
from chaindrive.analysis import vibration_remedy as vr
from chaindrive.analysis.layout import drive_layout
from chaindrive.analysis.loads import drive_loads
from chaindrive.analysis.vibration import drive_vibration
from chaindrive.drive.project import load_project
from chaindrive.workflows.analyze import analyze

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


@pytest.fixture(scope="module")
def mining(tmp_path_factory):
    out = tmp_path_factory.mktemp("mining")
    outcome = analyze(load_project(EXAMPLES / "mining_conveyor.toml"), out, figures=False)
    return outcome, out


def test_mining_conveyor_fails_and_gets_a_passing_proposal(mining):
    outcome, out = mining
    vib, remedy = outcome.analysis.vibration, outcome.analysis.remedy
    assert vib.passed is False and remedy is not None and remedy.found
    assert (out / "proposal.toml").exists()
    proposal = load_project(out / "proposal.toml")
    again = analyze_drive(proposal, include=["vibration"])
    assert again.vibration.passed is True
    assert all(c.verdict == "pass" for c in again.checks if c.part == "vibration")
    text = (out / "proposal.toml").read_text()
    assert "# chaindrive proposal" in text and "tensioner mass" in text


def test_report_shows_severity_and_the_changes(mining):
    outcome, _ = mining
    sec = next(s for s in outcome.report.sections if s.title.startswith("Span vibration"))
    captions = [t.caption for t in sec.tables]
    assert any(c.startswith("Severity") for c in captions) and "Proposed changes" in captions
    check = next(t for t in sec.tables if t.caption.startswith("Resonance check"))
    assert check.headers[-1] == "forced response [mm]"
    assert sec.results["remedy"]["found"] is True and sec.results["remedy"]["changes"]


def test_no_remedy_within_the_ranges_says_why(monkeypatch):
    drive = load_project(EXAMPLES / "mining_conveyor.toml")
    monkeypatch.setattr(vr, "REMEDY_RANGES", {"mass": (0.9, 1.1), "stiffness": (0.9, 1.1), "force": (0.95, 1.05),
                                              "shift": (-0.01, 0.01)})
    layout = drive_layout(drive)
    vib = drive_vibration(drive, layout, drive_loads(drive, layout))
    remedy = vr.search_remedy(drive, vib)
    assert remedy is not None and not remedy.found
    assert "mode 1" in remedy.reason and "link pair" in remedy.reason
    a = analyze_drive(drive, include=["remedy"])
    assert any("no design within the searched ranges" in w for w in a.warnings)


def test_passing_drive_has_no_remedy_and_the_part_can_be_left_out():
    a = analyze_drive(load_project(EXAMPLES / "roller_industrial.toml"), include=["remedy"])
    assert a.remedy is None
    b = analyze_drive(load_project(EXAMPLES / "mining_conveyor.toml"), exclude=["remedy"])
    assert b.vibration.passed is False and b.remedy is None
