"""Browser tests of the web studio: Playwright for Python driving Debian's chromium.

The app runs in a subprocess on 127.0.0.1 with a free port. Every request the pages make
to anything but that server is aborted and recorded; each test asserts there was none.
Screenshots go to tests/artifacts/web/. Skipped only when no chromium is found and CI is
not set; in CI a missing chromium is a failure.
"""

from __future__ import annotations

import io
import json
import re
from pathlib import Path

import pytest

import _shared

pytestmark = pytest.mark.browser

ARTIFACTS = Path(__file__).parent / "artifacts" / "web"
CHROMIUM = _shared.chromium_or_skip()
playwright = pytest.importorskip("playwright.sync_api")
expect = playwright.expect
pytest.importorskip("fastapi")

ARGS = ["--no-sandbox", "--disable-gpu", "--disable-background-networking", "--disable-component-update",
        "--disable-sync", "--no-first-run", "--disable-dev-shm-usage"]
TIMEOUT = 90_000  # generous: CI runs these beside the rest of the suite on 2 cores


@pytest.fixture(scope="module")
def server(web_server):
    # the workers at the suite's priority: niced below a busy test suite on 2 cores they
    # can take tens of seconds for their first (import-heavy) request
    with web_server("job_time_limit=120", env={"CHAINDRIVE_WEB_NICENESS": "0"}, log_level="warning",
                    stop_timeout=10) as base:
        yield base


@pytest.fixture(scope="module")
def browser():
    with playwright.sync_playwright() as p:
        b = p.chromium.launch(executable_path=CHROMIUM, args=ARGS)
        yield b
        b.close()


@pytest.fixture
def page(browser, server):
    ARTIFACTS.mkdir(parents=True, exist_ok=True)
    context = browser.new_context(viewport={"width": 1400, "height": 1000}, accept_downloads=True)
    outside: list[str] = []
    errors: list[str] = []

    def route(r):
        if r.request.url.startswith(server + "/") or r.request.url == server:
            r.continue_()
        else:
            outside.append(r.request.url)
            r.abort()

    context.route("**/*", route)
    pg = context.new_page()
    pg.set_default_timeout(TIMEOUT)
    pg.on("pageerror", lambda e: errors.append(str(e)))
    pg.outside, pg.errors, pg.base = outside, errors, server
    yield pg
    context.close()
    assert outside == [], f"requests outside the app: {outside}"
    assert errors == [], f"JavaScript errors: {errors}"


def _live(pg):
    pg.wait_for_selector("body[data-ready=live]")
    pg.wait_for_selector("body[data-charts=ready]")


def _download(pg, name: str) -> bytes:
    with pg.expect_download(timeout=120_000) as info:
        pg.click(f'#downloads a[data-name="{name}"]')
    path = info.value.path()
    data = Path(path).read_bytes()
    (ARTIFACTS / f"{pg.shot_prefix}-{name}").write_bytes(data)
    return data


def _check_downloads(pg, tmp_path):
    """The five downloads open: TOML with `chaindrive layout`, HTML, PDF, JSON, DXF (audit), SVG."""
    from chaindrive.cli import main

    toml = _download(pg, "project.toml")
    path = tmp_path / "drive.toml"
    path.write_bytes(toml)
    assert main(["layout", str(path)]) == 0
    results = json.loads(_download(pg, "results.json"))
    assert results["checks"] and "passed" in results
    dxf = _download(pg, "wheel.dxf")
    import ezdxf

    doc = ezdxf.read(io.StringIO(dxf.decode()))
    assert not doc.audit().has_errors
    svg = _download(pg, "wheel.svg")
    assert b"<svg" in svg
    html = _download(pg, "report.html")
    assert b"<html" in html.lower() and b"static safety" in html
    pdf = _download(pg, "report.pdf")
    assert pdf.startswith(b"%PDF")
    from pypdf import PdfReader

    reader = PdfReader(io.BytesIO(pdf))
    assert len(reader.pages) >= 2 and "static safety" in "".join(p.extract_text() for p in reader.pages[:3])
    return toml


def test_guided_flow_roller_acceptance(page, tmp_path):
    # 7.5 kW, 1450 rpm, ratio 3, about 500 mm, electric motor driving a uniformly loaded conveyor
    page.shot_prefix = "roller"
    page.goto(page.base + "/")
    _live(page)
    assert page.input_value("#power") == "7.5 kW" and page.input_value("#speed") == "1450 rpm"
    assert page.input_value("#driven") == "uniform_conveyor"
    assert "K_s = 1" in page.inner_text("#ks-source") and "Tsubaki" in page.inner_text("#ks-source")
    chosen = page.inner_text("#candidates tr.chosen")
    assert "✓" in chosen and "%" in chosen
    assert page.locator("#plot-rating .main-svg").count() >= 1
    layout = page.inner_text("#layout-out")
    links = int(re.search(r"(\d+) links", layout).group(1))
    assert links % 2 == 0 and "exact centre distance" in layout
    assert page.locator("#drawing svg .wheel").count() == 2
    rows = page.locator("#checks tbody tr")
    assert rows.count() >= 4
    verdicts = page.locator("#checks .verdict-cell").all_inner_texts()
    assert any("pass" in v for v in verdicts)
    assert all(page.locator("#checks tbody tr td.source").all_inner_texts())
    page.screenshot(path=str(ARTIFACTS / "roller-flow.png"), full_page=True)
    # live: an edit redraws and rechecks, the URL carries the state
    page.fill("#centre_distance", "650 mm")
    page.wait_for_url(re.compile(r".*centre_distance=650.*"))
    expect(page.locator("#layout-out")).to_contain_text("650 mm")
    new_links = int(re.search(r"(\d+) links", page.inner_text("#layout-out")).group(1))
    assert new_links > links
    page.fill("#centre_distance", "500 mm")
    page.wait_for_url(re.compile(r"^[^?]*(\?(?!.*centre_distance).*)?$"))
    expect(page.locator("#layout-out")).to_contain_text("500 mm")
    # contact with skew (Garshniev & Maksymovych) joins the checks when a skew is given
    page.fill("#skew", "50 arcmin")
    expect(page.locator("#checks")).to_contain_text("skew")
    assert "contact" in page.inner_text("#checks").lower()
    _check_downloads(page, tmp_path)


def test_guided_flow_mining_with_tensioner_sliders(page, tmp_path):
    from chaindrive.web.design import MINING_EXAMPLE, normalise_state
    from chaindrive.web.studio import state_query

    page.shot_prefix = "mining"
    page.goto(page.base + "/?" + state_query(normalise_state(MINING_EXAMPLE)))
    _live(page)
    assert "18x64" in page.inner_text("#candidates tr.chosen")
    assert page.locator("#drawing svg .tensioner").count() == 1
    assert page.locator("#drawing svg .guide").count() == 1
    resonance = page.locator("#checks tbody tr", has_text="resonance")
    assert resonance.count() == 1
    assert page.locator("#plot-campbell .main-svg").count() >= 1
    assert page.locator("#plot-map .main-svg").count() >= 1
    assert page.is_visible("#slider-mass") and page.is_visible("#slider-stiffness")
    before = page.inner_text("#checks")
    page.fill("#slider-mass", "-1")
    expect(page.locator("#tensioner_mass")).to_have_value("6.00 kg")
    page.wait_for_url(re.compile(r".*tensioner_mass=6\.00.*"))
    expect(page.locator("#checks")).not_to_have_text(before)
    page.screenshot(path=str(ARTIFACTS / "mining-flow.png"), full_page=True)
    toml = _check_downloads(page, tmp_path)
    assert b'mass = "6.00 kg"' in toml and b"pocket_wheel" in toml


def test_upload_edit_download_round_trip(page, tmp_path):
    from chaindrive.drive.project import parse_project, template

    page.shot_prefix = "roundtrip"
    page.goto(page.base + "/")
    _live(page)
    src = tmp_path / "fan.toml"
    src.write_text(template("roller"), encoding="utf-8")
    page.set_input_files("#project-file", str(src))
    page.wait_for_url(re.compile(r".*chain=16B.*"))
    _live(page)
    assert page.input_value("#teeth_driving") == "19" and page.input_value("#centre_distance") == "1050 mm"
    page.fill("#teeth_driving", "21")
    page.wait_for_url(re.compile(r".*teeth_driving=21.*"))
    expect(page.locator("#layout-out")).to_contain_text("21 / 57")
    toml = _download(page, "project.toml")
    drive = parse_project(toml.decode())
    assert drive.chain.name.startswith("16B") and drive.driving_wheel.teeth == 21
    assert drive.wheels[-1].teeth == 57


def test_error_at_the_field_keeps_the_value(page):
    page.shot_prefix = "error"
    page.goto(page.base + "/")
    _live(page)
    page.fill("#centre_distance", "500")
    expect(page.locator("#err-centre_distance")).to_contain_text("give a unit")
    assert page.input_value("#centre_distance") == "500"
    assert page.get_attribute("#centre_distance", "aria-invalid") == "true"
    assert page.inner_text("#err-power") == ""
    page.screenshot(path=str(ARTIFACTS / "field-error.png"))
    page.fill("#centre_distance", "500 mm")
    expect(page.locator("#err-centre_distance")).to_have_text("")
    # a bound of the design request (chaindrive.limits.DUTY_RANGES) at its field: the driven speed's ratio
    page.fill("#driven_speed", "10 rpm")
    expect(page.locator("#err-driven_speed")).to_contain_text("ratio must be a finite number in (0, 20]")
    assert page.input_value("#driven_speed") == "10 rpm" and page.inner_text("#err-ratio") == ""
    page.fill("#driven_speed", "")
    expect(page.locator("#err-driven_speed")).to_have_text("")


def test_expert_pages(page):
    page.shot_prefix = "expert"
    for path, probe in (("/expert/kinematics", "#plot-1 .main-svg"), ("/expert/crawler", "#plot-1 .main-svg"),
                        ("/expert/pocket-wheel", "img.outline"), ("/expert/track-wheel", "img.outline")):
        page.goto(page.base + path)
        page.click("#run")
        page.wait_for_selector(probe)
        assert page.locator("#result").count() == 1
        page.screenshot(path=str(ARTIFACTS / f"{path.rsplit('/', 1)[1]}.png"), full_page=True)
    # an error at the field on an expert page keeps the value
    page.goto(page.base + "/expert/kinematics?chain=18x64&teeth=2&speed=5+rad%2Fs&guide_end=256+mm&model=exact")
    assert page.inner_text("#err-teeth") and page.input_value("#teeth") == "2"
    # the simulation: a background job with progress, then the plots and the animation
    page.goto(page.base + "/expert/simulation")
    page.fill("#duration", "0.2 s")
    page.fill("#frames", "4")
    page.click("#run")
    page.wait_for_selector("body[data-job=done]", timeout=120_000)
    assert page.locator("#job-results img").count() == 3
    assert "done" in page.inner_text("#job-message")
    page.screenshot(path=str(ARTIFACTS / "simulation.png"), full_page=True)


def test_add_and_remove_further_wheels(page):
    # the studio edits a drive with more wheels: a second machine sprocket with 40 % of the
    # power, added and removed with the page's buttons
    page.shot_prefix = "wheels"
    page.goto(page.base + "/")
    _live(page)
    assert page.locator("#wheel-row-0").count() == 0
    with page.expect_navigation():
        page.click("#add-wheel")
    _live(page)
    expect(page.locator("#wheel-row-0")).to_be_visible()
    page.fill("#wheel0_x", "300 mm")
    page.fill("#wheel0_y", "450 mm")
    page.fill("#wheel0_share", "0.4")
    expect(page.locator("#err-wheel0_share")).to_have_text("")
    expect(page).to_have_url(re.compile(r"wheel0_share=0\.4"))
    expect(page.locator("#drawing")).to_contain_text("machine 1")
    page.screenshot(path=str(ARTIFACTS / "further-wheels.png"))
    page.fill("#wheel0_y", "450")
    expect(page.locator("#err-wheel0_y")).to_contain_text("give a unit")
    page.fill("#wheel0_y", "450 mm")
    expect(page.locator("#err-wheel0_y")).to_have_text("")
    with page.expect_navigation():
        page.click("#remove-wheel")
    _live(page)
    assert page.locator("#wheel-row-0").count() == 0
