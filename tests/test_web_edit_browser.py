"""The studio's live update in Chromium: after a sequence of edits the page shows exactly what a
fresh page of the same design shows (the page redraws only the parts an edit changed, reusing
the rows of its tables: this checks that nothing of an earlier answer stays behind).

Skipped without Debian's chromium (outside CI), like tests/test_web_browser.py.
"""

from __future__ import annotations

import pytest

import _shared

pytestmark = [pytest.mark.browser, pytest.mark.slow]

CHROMIUM = _shared.chromium_or_skip()
sync_api = pytest.importorskip("playwright.sync_api")
pytest.importorskip("fastapi")

#: the parts of the page an answer fills (their HTML, hidden flags and classes)
SHOWN = """() => {
  const parts = ["duty-out", "ks-source", "candidates", "candidate-note", "layout-out", "drawing", "loads",
                 "fretting", "checks", "warnings", "overall"];
  const out = Object.fromEntries(parts.map((id) => {
    const el = document.getElementById(id);
    return [id, [el.innerHTML, el.hidden, el.className]];
  }));
  out.resonance = document.getElementById("resonance").hidden;  // its charts come later, by themselves
  return out;
}"""

#: (field, value) edits in turn from the roller example and from the mining conveyor example;
#: "not a power" is invalid (the page keeps the last valid answer, marked stale)
EDITS = {"roller": [("centre_distance", "650 mm"), ("chain", "16B-2"), ("power", "not a power"),
                    ("power", "12 kW"), ("chain", ""), ("tensioner", "on"), ("tensioner_mass", "5 kg"),
                    ("tensioner", ""), ("units", "imperial")],
         "mining": [("tensioner_mass", "90 kg"), ("power", "40 kW"), ("guide", ""), ("tensioner", "")]}


def _updated(page, count: int) -> int:
    page.wait_for_selector(f"body[data-updates='{count + 1}']")
    return count + 1


@pytest.mark.parametrize("example", sorted(EDITS))
def test_edits_show_what_a_fresh_page_shows(web_server, example):
    from chaindrive.web.design import MINING_EXAMPLE, normalise_state
    from chaindrive.web.studio import state_query

    start = "/" if example == "roller" else "/?" + state_query(normalise_state(MINING_EXAMPLE))
    with web_server(env={"CHAINDRIVE_WEB_NICENESS": "0"}, log_level="warning") as base, \
            sync_api.sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=["--no-sandbox", "--disable-gpu"])
        errors: list[str] = []
        page = browser.new_page(viewport={"width": 1400, "height": 1000})
        page.set_default_timeout(90_000)
        page.on("pageerror", lambda e: errors.append(str(e)))
        page.goto(base + start)
        count = _updated(page, 0)
        for field, value in EDITS[example]:
            if page.get_attribute(f"#{field}", "type") is None:  # a select
                page.select_option(f"#{field}", value)
            else:
                page.fill(f"#{field}", value)
            count = _updated(page, count)
            if page.get_attribute("body", "class") and "has-errors" in page.get_attribute("body", "class"):
                assert field == "power" and page.inner_text("#err-power")
                continue  # stale: the results of the last valid inputs stay (tests/test_web_browser.py)
            fresh = browser.new_page(viewport={"width": 1400, "height": 1000})
            fresh.set_default_timeout(90_000)
            fresh.goto(page.url)
            _updated(fresh, 0)
            assert page.evaluate(SHOWN) == fresh.evaluate(SHOWN), f"after {field} = {value!r}"
            fresh.close()
        browser.close()
        assert errors == []
