"""The studio's 3-D view in Chromium (Debian's chromium through Playwright): the mining
example's assembly drawn offline (plotly served by the app), a click shows a part's numbers.
Screenshot: tests/artifacts/web/view3d.png."""

from __future__ import annotations

import importlib.util
import os
import shutil
from pathlib import Path

import numpy as np
import pytest

pytestmark = [pytest.mark.browser, pytest.mark.slow]

ARTIFACTS = Path(__file__).parent / "artifacts" / "web"
CHROMIUM = next((p for p in (os.environ.get("CHROMIUM"), shutil.which("chromium"), "/usr/bin/chromium")
                 if p and Path(p).exists()), None)
if CHROMIUM is None:
    pytest.skip("no chromium found (apt-get install chromium)", allow_module_level=True)
playwright = pytest.importorskip("playwright.sync_api")
if importlib.util.find_spec("build123d") is None:  # not imported here: 3 s per test process
    pytest.skip("could not find 'build123d'", allow_module_level=True)
pytest.importorskip("fastapi")

# software WebGL (SwiftShader) for plotly's mesh3d in a headless browser without GPU
ARGS = ["--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--disable-background-networking",
        "--disable-component-update", "--disable-sync", "--no-first-run", "--disable-dev-shm-usage"]


def test_view3d_draws_the_drive_and_shows_a_part(web_server):
    from chaindrive.web.studio import _example_query

    query = _example_query("mining_conveyor.toml")
    ARTIFACTS.mkdir(parents=True, exist_ok=True)
    outside: list[str] = []
    errors: list[str] = []
    with web_server(log_level="warning") as base, playwright.sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=ARGS)
        context = browser.new_context(viewport={"width": 1300, "height": 1000})

        def route(r):
            if r.request.url.startswith(base + "/"):
                r.continue_()
            else:
                outside.append(r.request.url)
                r.abort()

        context.route("**/*", route)
        page = context.new_page()
        page.set_default_timeout(300_000)  # the wheels' solids of a cold server on a busy machine
        page.on("pageerror", lambda e: errors.append(str(e)))
        page.goto(f"{base}/?{query}")
        href = page.get_attribute("#open-view3d", "href")
        assert href.startswith("/view3d?")
        page.goto(base + href)
        page.wait_for_selector("#view3d[data-ready='1']")
        status = page.inner_text("#view3d-status")
        assert "190 parts" in status and "144 links" in status
        box = page.locator("#view3d").bounding_box()
        # click the plot until a part is hit (the drive spans the middle of the view)
        hit = False
        for fx in (0.5, 0.3, 0.7):
            for fy in np.arange(0.45, 0.8, 0.01):
                x, y = box["x"] + fx * box["width"], box["y"] + fy * box["height"]
                page.mouse.move(x, y)  # plotly picks the WebGL part under the pointer on hover
                page.wait_for_timeout(100)
                # plotly's 3-D scene emits the click from its render loop while the button is
                # down: hold it for a few frames of the software renderer
                page.mouse.down()
                page.wait_for_timeout(600)
                page.mouse.up()
                page.wait_for_timeout(100)
                if page.inner_text("#view3d-part") != "click a part":
                    hit = True
                    break
            if hit:
                break
        page.screenshot(path=str(ARTIFACTS / "view3d.png"), full_page=True)
        text = page.inner_text("#view3d-part")
        browser.close()
    assert outside == [], f"requests outside the app: {outside}"
    assert errors == [], f"JavaScript errors: {errors}"
    assert text != "click a part" and ("link" in text or "wheel" in text or "guide" in text), text
