"""The report's charts drawn by the browser (issue 33 item 4): ``chaindrive analyze`` writes
the figures that have a chart (chaindrive.workflows.charts) as plotly data in report.html,
plotly.min.js beside it (offline), no PNG for them; ``--png`` and ``--pdf`` draw PNGs."""

import json
import os
import re
import shutil
from pathlib import Path

import pytest

from _shared import EXAMPLES
from chaindrive.cli import main
from chaindrive.drive.project import load_project
from chaindrive.workflows import charts
from chaindrive.workflows.analyze import analyze
from chaindrive.workflows.report import PLOTLY_JS

ROLLER = EXAMPLES / "roller_industrial.toml"


def _charts(html: str) -> list[dict]:
    blocks = re.findall(r'<script type="application/json" class="chart-data"[^>]*>(.*?)</script>', html, re.S)
    return [json.loads(b) for b in blocks]


@pytest.fixture(scope="module")
def both(tmp_path_factory):
    drive = load_project(ROLLER)
    png = analyze(drive, tmp_path_factory.mktemp("png"), figures=True)
    web = analyze(drive, tmp_path_factory.mktemp("web"), figures=True, browser_charts=True)
    return png, web


def test_every_figure_still_there(both):
    png, web = both
    # the same figures, in the same order, with the same captions
    assert [(f.caption, f.filename) for s in png.report.sections for f in s.figures] == \
        [(f.caption, f.filename) for s in web.report.sections for f in s.figures]
    charted = [f for s in web.report.sections for f in s.figures if f.chart is not None]
    assert len(charted) == 7  # layout, rating, kinematics, wheel, skew, wear, life
    folder = web.files["html"].parent
    html = web.files["html"].read_text(encoding="utf-8")
    assert len(_charts(html)) == 7
    assert (folder / PLOTLY_JS).stat().st_size > 1_000_000
    assert f'<script src="{PLOTLY_JS}"></script>' in html
    assert not any((folder / f.filename).exists() for f in charted)  # no PNG for a chart
    data = json.loads(web.files["json"].read_text(encoding="utf-8"))
    assert all(not f for f in (s["figures"] for s in data["sections"].values()))


def test_charts_have_units_on_their_axes(both):
    _, web = both
    for chart in _charts(web.files["html"].read_text(encoding="utf-8")):
        axes = {k: v for k, v in chart["layout"].items() if k.startswith(("xaxis", "yaxis"))}
        assert axes
        for name, axis in axes.items():
            assert re.search(r"\[.+\]$", axis["title"]["text"]), (name, axis["title"]["text"])
        assert chart["data"]


def test_charts_are_offline(both):
    # nothing from the internet: the page loads plotly.js from its own folder only
    _, web = both
    html = web.files["html"].read_text(encoding="utf-8")
    assert not re.search(r"<script[^>]+src=\"https?:", html)
    assert not re.search(r"<link[^>]+href=\"https?:", html)


def test_chart_data_equal_the_analysis(both):
    # the wear chart's points are the analysis' wear curve (rounded to 7 digits)
    _, web = both
    wear = web.analysis.wear
    chart = charts.wear_chart(wear)
    assert chart["data"][0]["y"][-1] == pytest.approx(100 * wear.elongation[-1], rel=1e-6)
    assert chart["layout"]["shapes"][0]["y0"] == pytest.approx(100 * wear.elongation_limit)


def test_color_names():
    assert charts.color("tab:red") == "#d62728"
    assert charts.color("C0") == "#1f77b4"
    assert charts.color("0.4") == "rgb(102,102,102)"
    assert charts.color("k") == "black"
    assert charts.color(None) is None


def test_cli_png_draws_pngs(tmp_path):
    assert main(["analyze", str(ROLLER), "-o", str(tmp_path / "a"), "-q", "--png"]) == 0
    assert (tmp_path / "a" / "layout.png").exists()
    assert not (tmp_path / "a" / PLOTLY_JS).exists()
    assert main(["analyze", str(ROLLER), "-o", str(tmp_path / "b"), "-q"]) == 0
    assert not (tmp_path / "b" / "layout.png").exists()
    assert (tmp_path / "b" / PLOTLY_JS).exists()


CHROMIUM = next((p for p in (os.environ.get("CHROMIUM"), shutil.which("chromium"), "/usr/bin/chromium")
                 if p and Path(p).exists()), None)


@pytest.mark.browser
def test_charts_drawn_in_chromium(both, tmp_path):
    if CHROMIUM is None:
        pytest.skip("no chromium found (apt-get install chromium)")
    sync = pytest.importorskip("playwright.sync_api")
    _, web = both
    errors: list[str] = []
    with sync.sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=["--no-sandbox", "--disable-gpu"])
        page = browser.new_page()
        page.on("pageerror", lambda e: errors.append(str(e)))
        page.goto(web.files["html"].as_uri())
        page.wait_for_function("document.querySelectorAll('.chart .main-svg').length >= 7", timeout=60_000)
        drawn = page.evaluate("Array.from(document.querySelectorAll('.chart')).filter("
                              "c => c.querySelector('.main-svg') && c.getBoundingClientRect().height > 150).length")
        titles = page.evaluate("Array.from(document.querySelectorAll('.chart .xtitle')).map(t => t.textContent)")
        browser.close()
    assert not errors
    assert drawn == 7
    assert all(re.search(r"\[.+\]$", t) for t in titles)


@pytest.mark.parametrize("name", ["roller_industrial", "mining_conveyor", "long_conveyor", "crawler_conveyor",
                                  "self_regulating", "tractor_track"])
def test_a_run_loads_neither_matplotlib_nor_pint(name, tmp_path):
    # every figure of the examples has a chart and every unit of their files is in the
    # units table: `chaindrive analyze` imports neither (measured with python -X importtime)
    import subprocess
    import sys

    code = ("import sys; from chaindrive.cli import main; "
            f"code = main(['analyze', {str(EXAMPLES / (name + '.toml'))!r}, '-o', {str(tmp_path / 'out')!r}, '-q']); "
            "print(code, 'matplotlib' in sys.modules, 'pint' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.split()[1:] == ["False", "False"], out.stdout + out.stderr
    assert not list((tmp_path / "out").glob("*.png"))
