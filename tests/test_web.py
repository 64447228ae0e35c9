"""The web page: index, catalogue API, kinematics page and API, bad input."""

import pytest

pytest.importorskip("fastapi")
from fastapi.testclient import TestClient  # noqa: E402

from chaindrive.web import create_app  # noqa: E402


@pytest.fixture(scope="module")
def client():
    return TestClient(create_app())


def test_index(client):
    r = client.get("/")
    assert r.status_code == 200 and "Chain entry kinematics" in r.text


def test_chains_api(client):
    r = client.get("/api/chains", params={"family": "din22252"})
    assert r.status_code == 200
    names = [c["name"] for c in r.json()]
    assert "18x64" in names


def test_kinematics_api_parses_units_once(client):
    r = client.get("/api/kinematics", params={"chain": "18x64", "teeth": 8, "speed": "5 rad/s",
                                               "entry": "tangential", "guide_end": "256 mm"})
    assert r.status_code == 200
    d = r.json()
    assert set(d) == {"phi", "x", "velocity", "acceleration", "summary"}
    r2 = client.get("/api/kinematics", params={"chain": "18x64", "teeth": 8, "speed": "47.746 rpm",
                                                "entry": "tangential", "guide_end": "0.256"})
    assert r2.json()["summary"]["v_mean"] == pytest.approx(d["summary"]["v_mean"], rel=1e-4)


def test_kinematics_page_has_plot(client):
    r = client.get("/kinematics", params={"chain": "18x64", "teeth": 8, "speed": "5 rad/s",
                                          "guide_end": "256 mm"})
    assert r.status_code == 200 and "data:image/png;base64," in r.text


@pytest.mark.parametrize("params, match", [
    ({"chain": "18x65", "teeth": 8, "speed": "5 rad/s"}, "18x64"),
    ({"chain": "18x64", "teeth": 2, "speed": "5 rad/s"}, "teeth"),
    ({"chain": "18x64", "teeth": 8, "speed": "5 kg"}, "speed"),
])
def test_bad_input_is_422_with_message(client, params, match):
    r = client.get("/api/kinematics", params=params)
    assert r.status_code == 422
    assert match in r.json()["error"]


def test_analyze_page_returns_report(client):
    from pathlib import Path

    text = (Path(__file__).parents[1] / "examples" / "roller_industrial.toml").read_text()
    r = client.post("/analyze", data={"project": text})
    assert r.status_code == 200 and "Overall verdict" in r.text
    r = client.post("/api/analyze", data={"project": text})
    assert r.status_code == 200 and r.json()["passed"] is True


def test_analyze_bad_project_names_field_and_line(client):
    r = client.post("/api/analyze", data={"project": '[drive]\nspeed = "5 kg"\n'})
    assert r.status_code == 422
    assert "drive.toml:2" in r.json()["error"] and "speed" in r.json()["error"]
