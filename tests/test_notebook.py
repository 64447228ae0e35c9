"""Notebook display: drives, analyses and results as HTML tables with units."""

from __future__ import annotations

from html import escape as html_escape
from pathlib import Path

import pytest

from chaindrive.analysis import analyze_drive
from chaindrive.drive.project import load_project
from chaindrive.workflows.notebook import html_of, tidy

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


@pytest.fixture(scope="module")
def mining():
    drive = load_project(EXAMPLES / "mining_conveyor.toml")
    return drive, analyze_drive(drive)


def test_analysis_repr_html_shows_checks_units_drawing_and_parts(mining):
    _, a = mining
    html = a._repr_html_()
    assert "passes" in html and "all checks pass" not in html  # the verdict in words (issue 30)
    for c in a.checks:
        assert html_escape(c.name) in html or c.name.replace("&", "&amp;") in html or c.name[:20] in html
    assert "<svg" in html                                      # the drive drawn to scale, inline
    assert "<td>kN</td>" in html and "<td>mm</td>" in html     # display units of declared fields
    assert "Layout" in html and "Wear life" in html            # each part folded under its title
    assert "Traceback" not in html and ">nan<" not in html.lower() and ">inf<" not in html.lower()


def test_drive_and_result_repr_html(mining):
    drive, a = mining
    html = drive._repr_html_()
    assert "18x64" in html and "rpm" in html and "<svg" in html
    layout = a.layout._repr_html_()
    assert "<b>DriveLayout</b>" in layout and "chain length" in layout and "<td>mm</td>" in layout
    assert html_of(a.layout) == layout


def test_tidy_rounding_noise_is_zero():
    assert tidy(7.694e-12, 1.025) == 0.0          # the 7.694e-12 next to accelerations of 1 m/s²
    assert tidy(-1e-17, 0.8) == 0.0 and tidy(0.5, 0.8) == 0.5
    assert tidy(2e-16, None) == 2e-16              # a lone small value (a wear coefficient) is kept
