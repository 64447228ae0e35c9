"""The calculation report looked at in Chromium (issue 30): the overall verdict with its
warnings, the span-vibration verdict and its number, frequencies in Hz with rad/s beside.
Screenshots go to tests/artifacts/report/."""

from __future__ import annotations

from pathlib import Path

import pytest

import _shared
from chaindrive.drive.project import load_project
from chaindrive.workflows.analyze import analyze

pytestmark = pytest.mark.browser

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
ARTIFACTS = Path(__file__).parent / "artifacts" / "report"
CHROMIUM = _shared.chromium_or_skip()
playwright = pytest.importorskip("playwright.sync_api")

ARGS = ["--no-sandbox", "--disable-gpu", "--disable-background-networking", "--disable-component-update",
        "--disable-sync", "--no-first-run", "--disable-dev-shm-usage"]


@pytest.fixture(scope="module")
def browser():
    with playwright.sync_playwright() as p:
        b = p.chromium.launch(executable_path=CHROMIUM, args=ARGS)
        yield b
        b.close()


@pytest.mark.parametrize("name, verdict", [("long_conveyor", "the drive fails: 1 check fails"),
                                           ("roller_industrial", "the drive passes, ")])
def test_report_verdicts_in_chromium(browser, tmp_path, name, verdict):
    path = EXAMPLES / f"{name}.toml"
    analyze(load_project(path), tmp_path, figures=True, source=path.read_text(encoding="utf-8"))
    ARTIFACTS.mkdir(parents=True, exist_ok=True)
    page = browser.new_page(viewport={"width": 1200, "height": 900})
    page.goto((tmp_path / "report.html").as_uri())
    top = page.locator(".verdict").inner_text()
    assert verdict in top and "ALL CHECKS PASS" not in page.content()
    summary = page.locator("table.summary").inner_text()
    assert "Hz" in summary and "rad/s" in page.content()  # frequencies in Hz, rad/s beside
    if name == "long_conveyor":
        assert "largest amplification of the slack span" in summary and "FAIL" in summary
        assert "band 0.7 ≤ P/ω ≤ 1.4 of the tensioner paper" in summary   # the band, information
        assert "proposal.toml" in page.content()
        box = page.locator("h2", has_text="Span vibration").bounding_box()
        page.screenshot(path=str(ARTIFACTS / f"{name}_vibration.png"), full_page=True,
                        clip={"x": 0, "y": box["y"] - 10, "width": 1200, "height": 1500})
    else:
        assert "warning" in top  # passes beside warnings: said so
        assert "960 rpm" in summary  # a shaft speed in rpm
    page.screenshot(path=str(ARTIFACTS / f"{name}_top.png"))
    page.screenshot(path=str(ARTIFACTS / f"{name}_full.png"), full_page=True)
    page.close()
