"""The calculation report renders to self-contained HTML and to PDF."""

import json

import matplotlib.pyplot as plt
import pytest

from chaindrive.analysis import Check
from chaindrive.workflows.report import Figure, Report, Section, Table


def _report(passed=True):
    fig, ax = plt.subplots()
    ax.plot([0, 1], [0, 1])
    s = Section(
        "Layout",
        paragraphs=["Two wheels."],
        tables=[Table("Spans", ["span", "length [m]"], [["tight", 1.05]])],
        checks=[Check("static safety", 7.2, 7.0, "-", passed, "ISO 10823 cl. 6"),
                Check("chain speed", 3.1, None, "m/s", None, "", relation="info")],
        figures=[Figure.from_matplotlib(fig, "A line", "line.png")],
        warnings=["something to look at"],
    )
    return Report("Drive X", "demo", inputs=Table("Inputs", ["name", "value"], [["pitch", 0.0254]]), sections=[s])


def test_html_is_self_contained_and_has_verdicts():
    html = _report().to_html()
    assert "data:image/png;base64," in html
    # a warning beside passing checks: "passes, 1 warning", never "all checks pass" (issue 30)
    assert "the drive passes, 1 warning" in html and "ALL CHECKS PASS" not in html and "ISO 10823 cl. 6" in html
    assert "Warning: something to look at" in html
    assert "&gt;= 7" in html and "pass" in html
    assert "<script" not in html and "src=\"http" not in html


def test_failed_check_is_shown_and_counted():
    r = _report(passed=False)
    assert not r.passed
    assert "the drive fails: 1 check fails" in r.to_html()
    d = r.to_dict()
    json.dumps(d)
    assert d["sections"]["Layout"]["checks"][0]["passed"] is False


def test_pdf(tmp_path):
    pytest.importorskip("weasyprint")
    p = _report().write_pdf(tmp_path / "r.pdf")
    assert p.read_bytes()[:4] == b"%PDF"
