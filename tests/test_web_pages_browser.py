"""Every studio page in engineering units, looked at in Chromium (issue 22).

Each page (the guided studio and the expert pages) is opened with its defaults: it shows
its results at once, its tables carry a unit for every number and no library attribute
name (``v_mean``, ``a_end_left``, ``sign_change_at_period_end``); a zero is 0, never a
rounding residue like 7.694e-12. An invalid input marks the results on screen as stale.
Screenshots go to tests/artifacts/pages/ to be looked at.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from test_web_browser import ARTIFACTS as _WEB_ARTIFACTS  # noqa: F401 - skips the module without chromium
from test_web_browser import _live, browser, page, server  # noqa: F401, F811 - shared fixtures

pytestmark = pytest.mark.browser
# ruff: noqa: F811 - the fixtures imported above are the test parameters
SHOTS = Path(__file__).parent / "artifacts" / "pages"
ATTRIBUTE = re.compile(r"\b[a-z]+_[a-z0-9_]+\b")          # a snake_case library name
RESIDUE = re.compile(r"\d\.\d+e-(?:0[7-9]|[1-9]\d)")     # 7.694e-12: rounding noise shown as a number
NUMBER = re.compile(r"^[−+-]?\d[\d.,]*(?:e[+-]?\d+)?(?: … [−+-]?\d[\d.,]*)?$")


def _shot(pg, name: str) -> None:
    SHOTS.mkdir(parents=True, exist_ok=True)
    pg.screenshot(path=str(SHOTS / f"{name}.png"), full_page=True)


def _table_text(pg, selector: str) -> list[list[str]]:
    return pg.eval_on_selector_all(f"{selector} tr", "rows => rows.map(r => [...r.cells].map(c => c.innerText.trim()))")


@pytest.mark.parametrize("name", ["kinematics", "crawler"])
def test_motion_pages_show_labelled_quantities_with_units(page, name):
    page.goto(page.base + f"/expert/{name}")
    rows = _table_text(page, "#summary")
    assert len(rows) > 8                                    # computed when the page opens
    header, body = rows[0], rows[1:]
    assert header[:2] == ["quantity", "unit"]
    text = page.inner_text("#result")
    assert not ATTRIBUTE.search(text.split("chain velocity")[0]) and not RESIDUE.search(text)
    for label, unit, *cells in body:
        numeric = [c for c in cells if NUMBER.match(c)]
        assert unit or not numeric or "non-uniformity" in label or "jumps" in label, label
    _shot(page, name)


@pytest.mark.parametrize("name", ["pocket-wheel", "track-wheel"])
def test_wheel_pages_show_dimensions_with_units(page, name):
    page.goto(page.base + f"/expert/{name}")
    rows = _table_text(page, "#dimensions")[1:]
    assert len(rows) > 10
    text = page.inner_text("#dimensions")
    assert not ATTRIBUTE.search(text) and not RESIDUE.search(text)
    for label, value, unit in rows:
        if NUMBER.match(value) and not any(w in label for w in ("teeth", "factor")):
            assert unit in ("mm", "°", "%"), (label, value, unit)
    _shot(page, name)


def test_expert_page_marks_a_stale_result_and_refuses_a_bare_number(page):
    page.goto(page.base + "/expert/kinematics")
    page.fill("#speed", "5")
    assert page.is_visible("#stale") and "stale" in page.get_attribute("#result", "class")
    _shot(page, "kinematics-stale")
    page.click("#run")
    page.wait_for_selector("#no-result")
    assert "give a unit" in page.inner_text("#err-speed")
    page.fill("#speed", "0.8 m/s")                           # a chain speed, as at the command line
    page.click("#run")
    page.wait_for_selector("#summary")
    assert "0.8" in page.inner_text("#summary")


def test_studio_marks_results_stale_after_an_invalid_input(page):
    page.goto(page.base + "/")
    _live(page)
    _shot(page, "studio")
    text = page.inner_text("#step-checks")
    assert not RESIDUE.search(text)
    page.fill("#power", "7.5")                               # a bare number: refused
    page.wait_for_selector("#stale-banner:not([hidden])")
    assert "stale" in page.inner_text("#overall")
    _shot(page, "studio-stale")


def test_simulation_page_summary_in_engineering_units(page):
    page.goto(page.base + "/expert/simulation?example=roller&duration=0.1+s&frames=0")
    page.click("#run")
    page.wait_for_selector("body[data-job=done]", timeout=240_000)
    rows = _table_text(page, "#sim-summary")
    assert len(rows) > 8
    text = page.inner_text("#sim-summary")
    assert not ATTRIBUTE.search(text)
    for label, _value, unit in rows:
        assert unit or label in ("time steps", "computing seconds per simulated second"), label
    _shot(page, "simulation")
    page.goto(page.base + "/about")
    _shot(page, "about")
