"""The studio edits drives with further wheels: machine sprockets with a power share, idlers."""

from __future__ import annotations

import pytest

pytest.importorskip("fastapi")

from fastapi.testclient import TestClient  # noqa: E402

from chaindrive.drive.project import parse_project  # noqa: E402
from chaindrive.web import create_app  # noqa: E402
from chaindrive.web.design import design_from_state, normalise_state  # noqa: E402
from chaindrive.web.studio import state_query, studio_payload  # noqa: E402
from chaindrive.web.wheels import MAX_EXTRA_WHEELS, extra_wheels  # noqa: E402

#: A motor sprocket, the driven conveyor (60 %), a second machine above (40 %) and a back-side
#: idler on the span returning to the motor.
THREE_SPROCKETS = {"extra_wheels": "2", "wheel0_share": "0.4", "wheel0_x": "300 mm", "wheel0_y": "450 mm",
                   "wheel1_kind": "idler", "wheel1_teeth": "17", "wheel1_x": "100 mm", "wheel1_y": "200 mm",
                   "wheel1_side": "-1"}


@pytest.fixture(scope="module")
def client():
    return TestClient(create_app(max_jobs=2, job_time_limit=120.0))


def test_design_with_further_wheels_builds_the_drive():
    design, errors = design_from_state(normalise_state(THREE_SPROCKETS))
    assert errors == {}
    drive = parse_project(design.project_text)
    assert [w.name for w in drive.wheels] == ["driving", "driven", "machine 1", "idler 2"]
    assert drive.power_shares().tolist() == pytest.approx([0, 0.6, 0.4, 0])
    assert drive.wheel("idler 2").side == -1
    assert drive.adjustable is not None and drive.adjustable.wheel == "driven"  # no tensioner: it moves


def test_payload_of_a_multi_wheel_design():
    p = studio_payload(normalise_state(THREE_SPROCKETS))
    assert p["errors"] == {}
    assert p["layout"]["links"] % 2 == 0
    assert p["layout"]["centre_distance_exact"] is not None  # where the driven wheel was moved to
    assert p["drawing"].count("<circle") >= 4 or "machine 1" in p["drawing"]


def test_a_single_further_sprocket_without_share_leaves_the_power_on_the_driven_wheel():
    design, errors = design_from_state(normalise_state({"extra_wheels": "1", "wheel0_kind": "idler",
                                                        "wheel0_x": "250 mm", "wheel0_y": "300 mm"}))
    assert errors == {}
    assert parse_project(design.project_text).power_shares().tolist() == pytest.approx([0, 1, 0])


@pytest.mark.parametrize("change, field, match", [
    ({"wheel0_y": "400"}, "wheel0_y", "give a unit"),
    ({"wheel0_teeth": "2"}, "wheel0_teeth", "outside the valid range"),
    ({"wheel0_share": "1.2"}, "wheel0_share", "outside the valid range"),
    ({"wheel0_share": "0.7", "wheel1_kind": "sprocket", "wheel1_share": "0.5"}, "wheel1_share",
     "must stay below 1"),
    ({"wheel0_x": "90 m"}, "wheel0_x", "outside the valid range"),
])
def test_errors_at_the_wheel_field(change, field, match):
    errors: dict[str, str] = {}
    state = normalise_state({**THREE_SPROCKETS, **change})
    extra_wheels(state, errors)
    assert field in errors and match in errors[field]
    assert field in studio_payload(state)["errors"]


def test_count_and_choices_are_bounded():
    state = normalise_state({"extra_wheels": str(MAX_EXTRA_WHEELS + 1), "wheel0_kind": "crane", "wheel0_side": "2"})
    assert state["extra_wheels"] == "0" and state["wheel0_kind"] == "sprocket" and state["wheel0_side"] == "1"


def test_page_shows_the_rows_and_the_add_remove_buttons(client):
    r = client.get("/?" + state_query(normalise_state(THREE_SPROCKETS)))
    assert r.status_code == 200
    assert 'id="wheel-row-0"' in r.text and 'id="wheel-row-1"' in r.text and 'id="wheel-row-2"' not in r.text
    assert 'id="add-wheel"' in r.text and 'id="remove-wheel"' in r.text
    r = client.get("/")
    assert 'id="wheel-row-0"' not in r.text and 'id="add-wheel"' in r.text and 'id="remove-wheel"' not in r.text


def test_download_project_of_a_multi_wheel_design_analyzes(client):
    r = client.get("/download/project.toml?" + state_query(normalise_state(THREE_SPROCKETS)))
    assert r.status_code == 200
    drive = parse_project(r.text)
    assert len(drive.wheels) == 4 and "power_share = 0.4" in r.text and "[adjustable]" in r.text
    r = client.get("/api/design?" + state_query(normalise_state({**THREE_SPROCKETS, "wheel0_y": "400"})))
    assert r.status_code == 200 and "wheel0_y" in r.json()["errors"]
