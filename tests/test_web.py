"""The web app without a browser: studio payloads, downloads, projects, limits, errors, escaping.

The browser tests (Playwright + Debian chromium) are in test_web_browser.py; the load
test (50 parallel requests against a real server) in test_web_load.py.
"""

import io
import json
import math
import re

import pytest

pytest.importorskip("fastapi")
from fastapi.testclient import TestClient  # noqa: E402
from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

from chaindrive.errors import InputError  # noqa: E402
from chaindrive.web import create_app  # noqa: E402
from chaindrive.web.design import (  # noqa: E402
    DEFAULTS,
    MINING_EXAMPLE,
    design_from_state,
    normalise_state,
    service_factor_table,
    state_from_project,
)
from chaindrive.web.display import show  # noqa: E402
from chaindrive.web.fields import FieldError, FieldSpec, parse_field, parse_integer  # noqa: E402
from chaindrive.web.studio import state_query, studio_payload  # noqa: E402


@pytest.fixture(scope="module")
def client():
    return TestClient(create_app(max_jobs=2, job_time_limit=120.0))


def _query(state):
    return state_query(normalise_state(state))


# --------------------------------------------------------------------------- fields


@pytest.mark.parametrize("text, expected", [
    ("500 mm", 0.5), ("0.5 m", 0.5), ("19.685 in", 0.5 * 0.999998),
])
def test_length_field_parses_units(text, expected):
    assert parse_field("centre_distance", text, FieldSpec("m", 0.0, 50.0)) == pytest.approx(expected, rel=1e-5)


@pytest.mark.parametrize("text, match", [
    ("500", "give a unit"), ("", "required"), ("5 kg", "centre_distance"), ("-3 mm", "outside the valid range"),
    ("60 m", "outside the valid range"), ("x" * 300, "at most"),
])
def test_length_field_errors_name_the_field(text, match):
    with pytest.raises(FieldError, match=match) as info:
        parse_field("centre_distance", text, FieldSpec("m", 0.0, 50.0, example="500 mm"))
    assert info.value.field == "centre_distance"


@pytest.mark.parametrize("text, match", [("2", "outside"), ("19.5", "whole number"), ("", "whole number"),
                                         ("9" * 12, "whole number")])
def test_integer_field_errors(text, match):
    with pytest.raises(FieldError, match=match):
        parse_integer("teeth_driving", text, 6, 150)


@settings(max_examples=40, deadline=None)
@given(st.floats(min_value=1e-3, max_value=40.0))
def test_length_field_round_trip(metres):
    # property: a length written in mm and read back is the same length
    assert parse_field("centre_distance", f"{metres * 1e3!r} mm", FieldSpec("m", 0.0, 50.0)) == pytest.approx(metres)


def test_display_conversion_is_display_only():
    # 1 in = 25.4 mm, 1 hp = 745.69987 W, 1 lbf = 4.4482216 N (NIST SP 811, appendix B)
    assert show(0.0254, "m", "imperial") == ("1", "in")
    assert show(745.69987158227022, "W", "imperial") == ("1", "hp")
    assert show(4.4482216152605, "N", "imperial") == ("1", "lbf")
    assert show(7500.0, "W") == ("7.5", "kW")
    assert show(3.0, "pairs", "imperial") == ("3", "pairs")


# --------------------------------------------------------------------------- service factors


def test_service_factor_table_is_the_published_one():
    # U.S. Tsubaki, The Complete Guide to Chain, Table 4.2 (= Shigley 9th ed. Table 17-15):
    # smooth 1.0/1.0/1.2, some impact 1.3/1.2/1.4, high impact 1.5/1.4/1.7
    t = service_factor_table()
    f = t["factors"]
    assert [f[c]["electric_motor"] for c in ("smooth", "moderate", "heavy")] == [1.0, 1.3, 1.5]
    assert [f[c]["ic_hydraulic"] for c in ("smooth", "moderate", "heavy")] == [1.0, 1.2, 1.4]
    assert [f[c]["ic_mechanical"] for c in ("smooth", "moderate", "heavy")] == [1.2, 1.4, 1.7]
    assert "Tsubaki" in t["source"] and "Table 4.2" in t["source"]
    from chaindrive.loads import service_factor

    # the same numbers as the library's ACA table
    for character in ("smooth", "moderate", "heavy"):
        for driver in ("electric_motor", "ic_hydraulic", "ic_mechanical"):
            assert f[character][driver] == service_factor(character, driver)


# --------------------------------------------------------------------------- the design


def test_acceptance_roller_design():
    d, errors = design_from_state(normalise_state({}))
    assert errors == {}
    assert d.service_factor == 1.0 and d.load_character == "smooth"
    assert d.teeth_driving == 19 and d.teeth_driven == 57
    assert d.links % 2 == 0
    # independent: the approximate chain length of a two-sprocket drive (Shigley 9th ed.,
    # eq. (17-34)): L/p = 2C/p + (z1+z2)/2 + (z2-z1)^2 / (4 pi^2 C/p)
    p, c = d.chain.pitch, 0.5
    approx = 2 * c / p + (19 + 57) / 2 + (57 - 19) ** 2 / (4 * math.pi**2 * c / p)
    assert d.links == pytest.approx(approx, abs=2.5)
    # the exact centre distance for the even link count lies within a pitch of the one asked
    assert abs(d.exact_centre_distance - 0.5) < p
    c_exact = d.exact_centre_distance
    approx_exact = 2 * c_exact / p + 38 + 38**2 / (4 * math.pi**2 * c_exact / p)
    assert approx_exact == pytest.approx(d.links, abs=0.05)
    # the candidates carry the design power (rating margin >= 1)
    assert d.candidates and all(cand["margin"] >= 1 for cand in d.candidates)
    assert d.chain.name == d.candidates[0]["chain"]


def test_imperial_units_are_display_only():
    metric = studio_payload(normalise_state({}))
    imperial = studio_payload(normalise_state({"units": "imperial"}))
    assert tuple(imperial["duty"]["power"]) == ("10.06", "hp")  # 7.5 kW / 745.7 W/hp
    assert imperial["layout"]["links"] == metric["layout"]["links"]
    assert imperial["layout"]["chain_length"].endswith(" in")
    assert [c["value"] for c in imperial["checks"]] == [c["value"] for c in metric["checks"]]


def test_mining_design_has_tensioner_and_resonance_check():
    p = studio_payload(normalise_state(MINING_EXAMPLE))
    assert p["errors"] == {}
    assert p["has_tensioner"] and p["chain"]["name"] == "18x64"
    names = [c["name"] for c in p["checks"]]
    assert any("forced response" in n for n in names) and any("band 0.7" in n for n in names)  # verdict, information
    assert all(c["source"] for c in p["checks"])
    assert "<svg" in p["drawing"] and "tensioner" in p["drawing"]


@pytest.mark.parametrize("change, field, match", [
    ({"power": "7.5"}, "power", "give a unit"),
    ({"centre_distance": "500"}, "centre_distance", "give a unit"),
    ({"centre_distance": "50 mm"}, "centre_distance", "too short"),
    ({"teeth_driving": "2"}, "teeth_driving", "outside"),
    ({"speed": "5 kg"}, "speed", "rad/s"),
    ({"chain": "nonsense"}, "chain", "nonsense"),
    ({"ratio": "0"}, "ratio", "outside"),
])
def test_errors_at_the_field(change, field, match):
    p = studio_payload(normalise_state({**DEFAULTS, **change}))
    assert field in p["errors"] and re.search(match, p["errors"][field])


def test_state_in_the_url_round_trip():
    state = normalise_state({"power": "10 kW", "centre_distance": "600 mm", "evil": "<x>"})
    q = state_query(state)
    assert "evil" not in q
    from urllib.parse import parse_qsl

    assert normalise_state(dict(parse_qsl(q))) == state


@settings(max_examples=15, deadline=None)
@given(st.sampled_from(["roller", "link"]), st.floats(min_value=0.7, max_value=1.4))
def test_every_design_reproduces_from_its_query(kind, factor):
    # property: the query of a design rebuilds the same project file
    base = normalise_state({"kind": kind})
    c = float(base["centre_distance"].split()[0]) * factor
    state = normalise_state({**base, "centre_distance": f"{c:.4g} {base['centre_distance'].split()[1]}"})
    d1, e1 = design_from_state(state)
    from urllib.parse import parse_qsl

    d2, e2 = design_from_state(normalise_state(dict(parse_qsl(state_query(state)))))
    assert e1 == e2
    if d1 is not None:
        assert d1.project_text == d2.project_text


# --------------------------------------------------------------------------- projects


def test_project_round_trip_through_the_studio():
    from chaindrive.drive.project import parse_project, template

    state = state_from_project(template("mining"))
    assert state["kind"] == "link" and state["tensioner"] == "on" and state["guide"] == "tangential"
    d, errors = design_from_state(normalise_state(state))
    assert errors == {}
    drive = parse_project(d.project_text)
    # tensioner idler where the template has it: (1.2 m, -0.4 m)
    idler = drive.wheel("tensioner")
    assert idler.position[0] == pytest.approx(1.2, abs=1e-3) and idler.position[1] == pytest.approx(-0.4, abs=1e-3)
    assert drive.tensioner.mass == 60.0 and drive.tensioner.stiffness == 2e5


def test_project_with_more_wheels_is_refused_with_a_reason():
    from chaindrive.drive.project import template

    with pytest.raises(InputError, match="two sprockets or pocket wheels"):
        state_from_project(template("track"))


def test_open_upload_and_bad_upload(client):
    from chaindrive.drive.project import template

    r = client.post("/open", files={"file": ("../../etc/passwd", template("roller").encode(), "text/plain")},
                    headers={"Accept": "application/json"})
    assert r.status_code == 200 and "chain=16B" in r.json()["query"]
    r = client.post("/open", files={"file": ("x.toml", b'[drive]\nspeed = "5 kg"\n', "text/plain")},
                    headers={"Accept": "application/json"})
    assert r.status_code == 422 and "speed" in r.json()["error"]
    r = client.post("/open", files={"file": ("x.toml", b"\xff\xfe", "text/plain")}, headers={"Accept": "application/json"})
    assert r.status_code == 422 and "UTF-8" in r.json()["error"]
    r = client.post("/open", files={"file": ("x.toml", b"", "text/plain")}, follow_redirects=False)
    assert r.status_code == 303 and "open_error" in r.headers["location"]


# --------------------------------------------------------------------------- pages and API


def test_studio_page_escapes_echoed_values(client):
    evil = '"><script>alert(1)</script>'
    r = client.get("/", params={"name": evil, "power": evil})
    assert r.status_code == 200
    assert "<script>alert(1)" not in r.text and "&lt;script&gt;" in r.text


def test_security_headers_and_offline(client):
    r = client.get("/")
    csp = r.headers["content-security-policy"]
    assert "default-src 'self'" in csp and "script-src 'self'" in csp
    assert r.headers["x-content-type-options"] == "nosniff"
    # no page refers to anything outside the app
    for path in ("/", "/expert/kinematics", "/expert/simulation", "/about"):
        text = client.get(path).text
        assert not re.search(r'(src|href)="(https?:)?//', text), path
    assert "seed" not in r.text.lower()
    js = client.get("/static/plotly.min.js")
    assert js.status_code == 200 and len(js.content) > 1_000_000


def test_docs_are_absent_not_blank(client):
    assert client.get("/docs").status_code == 404
    assert client.get("/redoc").status_code == 404
    assert client.get("/openapi.json").status_code == 200


def test_api_design_and_charts(client):
    r = client.get("/api/design?" + _query({}))
    assert r.status_code == 200
    d = r.json()
    assert d["layout"]["links"] % 2 == 0 and d["checks"] and "<svg" in d["drawing"]
    r = client.get("/api/design/charts?" + _query(MINING_EXAMPLE))
    charts = r.json()
    assert charts["rating"]["data"] and charts["campbell"]["data"] and charts["resonance_map"]["data"]


def test_api_design_body_is_the_studio_payload(client):
    # the worker writes the JSON body (studio_json): the answer is studio_payload's, as FastAPI wrote it
    from chaindrive.web.studio import charts_payload

    for state in ({}, MINING_EXAMPLE, {"power": "not a power"}):
        r = client.get("/api/design?" + _query(state))
        assert r.status_code == 200 and r.headers["content-type"] == "application/json"
        got, want = r.json(), studio_payload(normalise_state(state))
        for timing in ("elapsed_ms", "cpu_ms"):
            assert isinstance(got.pop(timing, 0.0), float) == isinstance(want.pop(timing, 0.0), float)
        assert got == json.loads(json.dumps(want))
    charts = client.get("/api/design/charts?" + _query(MINING_EXAMPLE))
    assert charts.json() == json.loads(json.dumps(charts_payload(normalise_state(MINING_EXAMPLE))))


def test_json_bytes_refuses_what_is_not_json():
    import numpy as np

    from chaindrive.web.studio import json_bytes

    assert json.loads(json_bytes({"a": np.float64(1.5), "b": np.int64(2), "c": np.arange(2)})) == {
        "a": 1.5, "b": 2, "c": [0, 1]}
    with pytest.raises(ValueError, match="Out of range float values"):
        json_bytes({"a": float("nan")})
    with pytest.raises(TypeError, match="object is not JSON serialisable"):
        json_bytes({"a": object()})


def test_kinematics_api_bounds(client):
    base = {"chain": "18x64", "teeth": 8, "speed": "5 rad/s", "entry": "tangential", "guide_end": "256 mm"}
    r = client.get("/api/kinematics", params=base)
    assert r.status_code == 200
    r2 = client.get("/api/kinematics", params={**base, "speed": "47.746 rpm"})
    assert r2.json()["summary"]["v_mean"] == pytest.approx(r.json()["summary"]["v_mean"], rel=1e-4)
    for bad, match in (({"points": 20_000_000}, "points"), ({"teeth": 10**9}, "teeth"),
                       ({"guide_end": "0.256"}, "give a unit"), ({"chain": "18x65"}, "18x64")):
        r = client.get("/api/kinematics", params={**base, **bad})
        assert r.status_code == 422 and match in r.json()["error"]


def test_request_size_limits(client):
    r = client.post("/api/analyze", data={"project": "x" * 1_100_000})
    assert r.status_code == 413
    r = client.get("/?" + "a=" + "b" * 9000)
    assert r.status_code == 414


def test_api_analyze(client):
    from chaindrive.drive.project import template

    r = client.post("/api/analyze", data={"project": template("roller")})
    assert r.status_code == 200 and r.json()["checks"]
    r = client.post("/api/analyze", data={"project": '[drive]\nspeed = "5 kg"\n'})
    assert r.status_code == 422 and "speed" in r.json()["error"]


@pytest.mark.parametrize("path, params, field", [
    ("/expert/kinematics", {"teeth": "2"}, "teeth"),
    ("/expert/crawler", {"speed": "30"}, "speed"),
    ("/expert/pocket-wheel", {"chain": "16B"}, "chain"),
    ("/expert/track-wheel", {"pin_radius": "25"}, "pin_radius"),
])
def test_expert_page_error_at_the_field_keeps_values(client, path, params, field):
    r = client.get(path, params=params)
    assert r.status_code == 422
    m = re.search(rf'id="err-{field}" role="alert">([^<]+)<', r.text)
    assert m and m.group(1).strip()
    assert f'value="{params[field]}"' in r.text or f'value="{params[field]}" ' in r.text or params[field] in r.text


@pytest.mark.parametrize("path", ["/expert/kinematics", "/expert/crawler", "/expert/pocket-wheel",
                                  "/expert/track-wheel"])
def test_expert_pages_compute(client, path):
    from chaindrive.web.expert import DEFAULTS as EXPERT

    r = client.get(path, params=EXPERT[path.rsplit("/", 1)[1]])
    assert r.status_code == 200 and 'id="result"' in r.text


# --------------------------------------------------------------------------- downloads


def test_small_downloads_open(client, tmp_path):
    q = _query({})
    toml = client.get("/download/project.toml?" + q)
    assert toml.status_code == 200
    from chaindrive.cli import main

    path = tmp_path / "drive.toml"
    path.write_bytes(toml.content)
    assert main(["layout", str(path)]) == 0
    res = client.get("/download/results.json?" + q)
    assert res.status_code == 200 and json.loads(res.content)["checks"]
    dxf = client.get("/download/wheel.dxf?" + q)
    import ezdxf

    doc = ezdxf.read(io.StringIO(dxf.content.decode()))
    assert not doc.audit().has_errors
    svg = client.get("/download/wheel.svg?" + q)
    assert svg.content.startswith(b"<?xml") and b"<svg" in svg.content
    assert client.get("/download/nothing?" + q).status_code == 404
    bad = client.get("/download/project.toml?" + _query({"power": "7.5"}))
    assert bad.status_code == 422 and "power" in bad.json()["error"]


# --------------------------------------------------------------------------- jobs and caps


def test_job_manager_caps_and_time_limit():
    import asyncio

    from chaindrive.web.jobs import Busy, JobManager

    m = JobManager(max_jobs=1, workers=1, time_limit=1.0)
    try:
        job = m.submit("simulate", {"example": "link", "speed": 5.0, "load": 2000.0, "duration": 3.0,
                                    "frames": 0})
        with pytest.raises(Busy, match="busy"):
            m.submit("report", {"project": ""})
        asyncio.run(m.wait(job, timeout=60))
        assert job.state == "timeout" and "time cap" in job.error
    finally:
        m.close()


def test_gate_refuses_when_full():
    import asyncio

    from chaindrive.web.jobs import Busy, Gate

    g = Gate(workers=1, max_waiting=0)
    with pytest.raises(Busy, match="busy"):
        asyncio.run(g.run(lambda: 1))


@pytest.mark.slow
def test_simulation_job_of_the_studio_design(client):
    import time

    r = client.post("/api/jobs/simulate", data={"example": "studio", "design": _query(MINING_EXAMPLE),
                                                "duration": "0.1 s", "frames": "0", "speed": "5 rad/s",
                                                "load": "0 N*m"})
    assert r.status_code == 200
    job = r.json()["job"]
    deadline = time.monotonic() + 120
    while True:
        j = client.get(f"/api/jobs/{job}").json()
        if j["state"] not in ("queued", "running") or time.monotonic() > deadline:
            break
        time.sleep(0.5)
    assert j["state"] == "done", j
    assert "simulation.png" in j["files"] and j["result"]["summary"]["duration"] == pytest.approx(0.1, rel=1e-3)
    png = client.get(f"/api/jobs/{job}/files/simulation.png")
    assert png.status_code == 200 and png.content.startswith(b"\x89PNG")
    assert client.get(f"/api/jobs/{job}/files/..%2F..%2Fetc%2Fpasswd").status_code == 404
    bad = client.post("/api/jobs/simulate", data={"example": "link", "duration": "30 s", "frames": "0",
                                                  "speed": "5 rad/s", "load": "0 N*m"})
    assert bad.status_code == 422 and "duration" in bad.json()["errors"]


@pytest.mark.parametrize("page", ["pocket-wheel", "track-wheel"])
def test_expert_wheel_outline_downloads(client, page):
    import ezdxf

    from chaindrive.web.expert import DEFAULTS as EXPERT

    r = client.get(f"/expert/{page}/outline.dxf", params=EXPERT[page])
    assert r.status_code == 200
    assert not ezdxf.read(io.StringIO(r.content.decode())).audit().has_errors
    r = client.get(f"/expert/{page}/outline.svg", params=EXPERT[page])
    assert r.status_code == 200 and b"<svg" in r.content
    assert client.get(f"/expert/{page}/outline.exe").status_code == 404
    bad = client.get(f"/expert/{page}/outline.dxf", params={**EXPERT[page], "teeth": "1"})
    assert bad.status_code == 422 and "teeth" in bad.json()["error"]


@pytest.mark.slow
@settings(max_examples=12, deadline=None)
@given(st.integers(min_value=9, max_value=40), st.floats(min_value=1.0, max_value=4.0),
       st.floats(min_value=0.3, max_value=2.0), st.sampled_from(["", "on"]))
def test_drawing_is_well_formed_and_to_scale(teeth, ratio, centre, tensioner):
    # property: the drawing parses as XML, has one wheel per wheel of the drive, and its
    # centre-distance text equals the layout's centre distance
    import xml.etree.ElementTree as ET

    state = normalise_state({"teeth_driving": str(teeth), "ratio": f"{ratio:.3f}",
                             "centre_distance": f"{centre:.4f} m", "tensioner": tensioner})
    p = studio_payload(state)
    if p["errors"]:
        return
    root = ET.fromstring(p["drawing"])
    wheels = [e for e in root.iter() if e.get("class") == "wheel"]
    assert len(wheels) == (3 if tensioner else 2)
    text = next(e for e in root.iter() if e.get("class") == "centre-distance").text
    c_mm = float(re.search(r"C = ([0-9.]+) mm", text).group(1))
    expected = p["layout"]["centre_distance_exact"] or p["layout"]["centre_distance_given"]
    assert c_mm == pytest.approx(float(expected.split()[0]), rel=6e-4)  # 4 significant digits shown


@pytest.mark.parametrize("args, match", [(["--port", "0"], "port"), (["--max-jobs", "0"], "max-jobs"),
                                         (["--job-time-limit", "0.5"], "job-time-limit")])
def test_cli_web_refuses_bad_options(capsys, args, match):
    from chaindrive.cli import main

    assert main(["web", *args]) == 2
    assert match in capsys.readouterr().err


def test_loads_shown_with_units_from_the_report_table():
    p = studio_payload(normalise_state({}))
    names = [r[0] for r in p["loads"]["rows"]]
    assert any("tight" in n for n in names) and any("peak tension" in n for n in names) and any("dynamic tension" in n for n in names)
    units = {r[2] for r in p["loads"]["rows"]}
    assert "kN" in units
    imperial = studio_payload(normalise_state({"units": "imperial"}))
    assert "lbf" in {r[2] for r in imperial["loads"]["rows"]}


@pytest.mark.slow
def test_dxf_downloads_are_the_workshop_drawing_and_the_mining_example_is_the_file(client):
    """The studio's and the pocket-wheel page's DXF is the workshop drawing that
    ``chaindrive sprocket --dxf`` / ``pocket-wheel --dxf`` write (views, title block), not an
    outline; the studio's mining example is examples/mining_conveyor.toml."""
    import ezdxf

    from chaindrive.geometry import Sprocket
    from chaindrive.geometry.drawing import part_drawing
    from chaindrive.geometry.part import sprocket_part
    from chaindrive.web.design import design_from_state

    res = client.get("/download/wheel.dxf?" + _query({}))
    doc = ezdxf.read(io.StringIO(res.content.decode()))
    design = design_from_state(normalise_state({}))[0]
    reference = part_drawing(sprocket_part(Sprocket.from_chain(design.chain, design.teeth_driving)))
    assert {layer.dxf.name for layer in doc.layers} == {layer.dxf.name for layer in reference.layers}
    assert len(doc.modelspace()) == len(reference.modelspace()) > 50
    pocket = client.get("/expert/pocket-wheel/outline.dxf?chain=18x64&teeth=8")
    doc = ezdxf.read(io.StringIO(pocket.content.decode()))
    assert len(doc.modelspace()) > 50 and not doc.audit().has_errors
    page = client.get("/").text
    from chaindrive._examples import example_path
    from chaindrive.web.design import state_from_project

    state = state_from_project(example_path("mining_conveyor.toml").read_text(encoding="utf-8"))
    assert f"idler_offset={state['idler_offset'].replace(' ', '+')}" in page.replace("%20", "+")



def test_rating_chart_names_each_chains_method():
    """The studio's rating chart rates each candidate by its family's method (B series: ISO 10823) and
    says so: in the title and, when the methods differ, on each curve (it read "ANSI/ACA" for all)."""
    import numpy as np

    from chaindrive.rating import rated_power_curve
    from chaindrive.units import rpm_to_angular_velocity
    from chaindrive.web.charts import rating_chart
    from chaindrive.web.design import design_from_state, normalise_state

    d, errors = design_from_state(normalise_state({"power": "30.64 kW", "speed": "1800 rpm",
                                                   "driven_speed": "473 rpm", "driven": "varying_conveyor",
                                                   "centre_distance": ""}))
    assert errors == {}
    fig = rating_chart(d)
    assert fig["layout"]["title"]["text"] == "Rated power by each chain's method (ISO 10823, ANSI/ACA), z1 = 25"
    by_name = {t["name"]: t for t in fig["data"]}
    assert "16B-2 (ISO 10823)" in by_name and "12A-3 (ANSI/ACA)" in by_name  # 16A-3 left with the Table 7.19 safety (issue 29)
    t = by_name["16B-2 (ISO 10823)"]
    w = rpm_to_angular_velocity(np.asarray(t["x"]))
    kw = rated_power_curve("16B-2", 25, w, method="iso10823") / 1e3
    assert np.allclose(t["y"], kw, rtol=1e-4)
    link, _ = design_from_state(normalise_state({"kind": "link", "chain": "18x64", "teeth_driving": "8",
                                                 "teeth_driven": "8", "centre_distance": "4.05 m"}))
    if link is not None:
        assert rating_chart(link)["layout"]["title"]["text"] == "Power at the required static safety, F_B v / S"
