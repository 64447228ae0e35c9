"""The design layer owns design (issue 31, item 2): one :class:`DesignRequest`, one answer at every door.

The Python API (``design_drive(DesignRequest)``), the web API (``/api/design``, the studio's form
mapped to a request) and ``chaindrive select --json`` give the same chain, teeth, links and exact
centre distance for the same duty; the studio's page holds no service-factor table lookup, no
design-power formula and no bound of its own (every bound from ``chaindrive.limits``); a request's
``InputError`` is shown at the form field it names.
"""

from __future__ import annotations

import ast
import json
import math
import re
from pathlib import Path
from urllib.parse import urlencode

import pytest

from chaindrive.cli import main
from chaindrive.design import DesignRequest, Duty, design_drive
from chaindrive.design.duty import design_power, service_factor_of
from chaindrive.errors import InputError, UnknownNameError
from chaindrive.limits import DUTY_RANGES, MAX_TEETH, MIN_TEETH

pytest.importorskip("fastapi")
from fastapi.testclient import TestClient  # noqa: E402

from chaindrive.web.app import create_app  # noqa: E402
from chaindrive.web.design import FIELDS, TEETH_RANGE, design_request, normalise_state  # noqa: E402

RPM = math.pi / 30
WEB = Path(__file__).parents[1] / "src" / "chaindrive" / "web" / "design.py"

# (power kW, speed rpm, ratio, driven machine, driver, teeth, centre distance): duties of the design tests
# (issue 19's conveyor; a smooth fan-like duty; a heavy one on an IC engine with given teeth; a blank centre)
DUTIES = [
    (11.0, 1460, 3.0417, "varying_conveyor", "electric_motor", "", "600 mm"),
    (7.5, 1450, 3.0, "uniform_conveyor", "electric_motor", "", "500 mm"),
    (3.65, 480, 4.5, "uniform_conveyor", "ic_mechanical", "25", "800 mm"),
    (30.64, 1800, 3.8, "varying_conveyor", "ic_hydraulic", "", ""),
]


@pytest.fixture(scope="module")
def client():
    return TestClient(create_app(max_jobs=1, job_time_limit=60.0))


def _state(power, rpm, ratio, machine, driver, teeth, centre) -> dict[str, str]:
    return {"power": f"{power} kW", "speed": f"{rpm} rpm", "ratio": f"{ratio}", "driven_speed": "",
            "driven": machine, "driver": driver, "teeth_driving": teeth, "centre_distance": centre,
            "hours_per_day": "8"}


def _request(power, rpm, ratio, machine, driver, teeth, centre) -> DesignRequest:
    # built by hand from the duty, as a Python user would (SI units)
    return DesignRequest.of(power=power * 1e3, speed=rpm * RPM, ratio=ratio, driven_machine=machine, driver=driver,
                            hours_per_day=8.0, teeth_driving=int(teeth) if teeth else None,
                            centre_distance=float(centre.split()[0]) * 1e-3 if centre else None, limit=8)


@pytest.mark.parametrize("duty", DUTIES)
def test_one_request_one_answer_at_every_door(duty, client, capsys):
    request = _request(*duty)
    api = design_drive(request).recommended
    # the studio's form maps to exactly this request
    mapped, errors = design_request(normalise_state(_state(*duty)))
    assert errors == {} and mapped == request
    # the web API
    payload = client.get("/api/design?" + urlencode(normalise_state(_state(*duty)))).json()
    assert payload["errors"] == {}
    first = payload["candidates"][0]
    assert (first["chain"], first["teeth_driving"], first["teeth_driven"], first["links"]) == (
        api.chain, api.driving_teeth, api.driven_teeth, api.links)
    assert first["centre_distance"] == pytest.approx(api.centre_distance, abs=1e-12)
    assert first["design_power"] == pytest.approx(api.design_power, rel=1e-15)
    # select --json
    power, rpm, ratio, machine, driver, teeth, centre = duty
    args = ["select", "--power", f"{power} kW", "--speed", f"{rpm} rpm", "--ratio", str(ratio), "--driven-machine",
            machine, "--driver", driver, "--json", "--limit", "8"]
    args += ["--teeth", teeth] if teeth else []
    args += ["--centre-distance", centre] if centre else []
    assert main(args) == 0
    rec = json.loads(capsys.readouterr().out)["recommended"]
    assert (rec["chain"], rec["driving_teeth"], rec["driven_teeth"], rec["links"]) == (
        api.chain, api.driving_teeth, api.driven_teeth, api.links)
    assert rec["centre_distance"] == pytest.approx(api.centre_distance, abs=1e-12)


def test_duty_and_options_is_the_same_request():
    duty = Duty(11e3, 1460 * RPM, driven_speed=480 * RPM, driven_machine="varying_conveyor", centre_distance=0.6)
    a = design_drive(duty, strands=(1,), limit=3)
    b = design_drive(DesignRequest(duty, strands=(1,), limit=3))
    assert a.recommended == b.recommended and a.request == b.request
    assert b.drive().links == b.recommended.links == 104
    assert b.design_power == pytest.approx(14.3e3) == b.recommended.design_power


def test_service_factor_and_design_power_come_from_the_design_layer():
    # U.S. Tsubaki Table 4.2 / ACA (Shigley 9th ed. Table 17-15): moderate shock, IC engine mechanical drive: 1.4
    f = service_factor_of("ic_mechanical", driven_machine="varying_conveyor")
    assert f.value == 1.4 and "Tsubaki" in f.source
    assert service_factor_of("electric_motor", load_character="heavy", given=1.1).value == 1.1
    assert design_power(10e3, f) == pytest.approx(14e3)
    duty = Duty(10e3, 150.0, ratio=3.0, driver="ic_mechanical", driven_machine="varying_conveyor")
    assert design_drive(duty).design_power == pytest.approx(14e3)


@pytest.mark.parametrize(("kwargs", "error", "match", "field"), [
    ({"teeth_driving": 2}, InputError, r"teeth_driving must be a whole number in \[3, 10000\]", "teeth_driving"),
    ({"teeth_driving": 10_001}, InputError, r"teeth_driving must be a whole number in \[3, 10000\]", "teeth_driving"),
    ({"strands": (5,)}, InputError, r"strands must be a non-empty selection of whole numbers in \[1, 4\]", "strands"),
    ({"strands": ()}, InputError, "strands must be a non-empty selection", "strands"),
    ({"required_static_safety": 0.5}, InputError, r"required_static_safety must be a number in \[1, 50\]",
     "required_static_safety"),
    ({"required_static_safety": float("nan")}, InputError, "required_static_safety", "required_static_safety"),
    ({"limit": 0}, InputError, r"limit must be a whole number in \[1, ", "limit"),
    ({"all_sizes": "yes"}, InputError, "all_sizes must be True or False", "all_sizes"),
    ({"family": "zz"}, UnknownNameError, "unknown roller-chain family 'zz'", None),
    ({"method": "nope"}, UnknownNameError, "rating method", None),
])
def test_request_errors_name_the_field(kwargs, error, match, field):
    duty = Duty(11e3, 150.0, ratio=3.0, service_factor=1.3)
    with pytest.raises(error, match=match) as err:
        DesignRequest(duty, **kwargs)
    if field is not None:
        assert err.value.field == field


@pytest.mark.parametrize(("values", "match", "field"), [
    ({"power": 2e8}, r"power must be a finite number in \(0, 1e\+08\] W", "power"),
    ({"speed": -1.0}, r"speed must be a finite number in \(0, 10000\] rad/s", "speed"),
    ({"hours_per_day": 25.0}, r"hours_per_day must be a finite number in \(0, 24\] h", "hours_per_day"),
    ({"service_factor": 6.0}, r"service_factor must be a finite number in \(0, 5\]", "service_factor"),
    ({"colour": "red"}, "unknown design request field 'colour'", "colour"),
])
def test_request_of_refuses_with_the_limits(values, match, field):
    base = {"power": 11e3, "speed": 150.0, "ratio": 3.0, "load_character": "smooth"}
    with pytest.raises(InputError, match=match) as err:
        DesignRequest.of(**{**base, **values})
    assert err.value.field == field


def test_design_drive_refuses_other_arguments():
    duty = Duty(11e3, 150.0, ratio=3.0, service_factor=1.3)
    with pytest.raises(InputError, match="request must be a chaindrive.design.DesignRequest"):
        design_drive({"power": 1.0})
    with pytest.raises(InputError, match="give the options in the DesignRequest"):
        design_drive(DesignRequest(duty), limit=3)
    with pytest.raises(InputError, match="duty must be a chaindrive.design.Duty"):
        DesignRequest("11 kW")


def test_web_design_holds_no_design_procedure():
    """web/design.py: no service-factor table lookup, no design-power product, no teeth formula, no
    numeric bound of its own (the duty's ranges are those of chaindrive.limits)."""
    text = WEB.read_text("utf-8")
    tree = ast.parse(text)
    keys = {n.slice.value for n in ast.walk(tree) if isinstance(n, ast.Subscript)
            and isinstance(n.slice, ast.Constant) and isinstance(n.slice.value, str)}
    assert "factors" not in keys  # service_factor_table()["factors"][character][driver]
    products = [ast.unparse(n) for n in ast.walk(tree) if isinstance(n, ast.BinOp) and isinstance(n.op, ast.Mult)
                and {"power", "ks"} & {getattr(x, "id", "") for x in (n.left, n.right)}]
    assert products == []
    assert "round(z1 * ratio)" not in text and "0.05 <= ratio" not in text and "5.0, example" not in text
    from chaindrive.drive.schema import get_table

    teeth = get_table("wheels").field("teeth")
    assert TEETH_RANGE == (MIN_TEETH, MAX_TEETH) == (teeth.minimum, teeth.maximum)
    for name in ("power", "speed", "ratio", "driven_speed", "service_factor", "hours_per_day", "centre_distance"):
        assert FIELDS[name].maximum == DUTY_RANGES[name][1], name


@pytest.mark.parametrize(("change", "field", "match"), [
    ({"hours_per_day": "30"}, "hours_per_day", r"outside the valid range 0 < hours_per_day <= 24"),
    ({"driven_speed": "10 rpm"}, "driven_speed", r"ratio must be a finite number in \(0, 20\], got 145"),
    ({"service_factor": "6"}, "service_factor", r"outside the valid range 1 <= service_factor <= 5"),
    ({"teeth_driving": "2"}, "teeth_driving", r"outside the valid range 3 <= teeth_driving <= 10000"),
])
def test_web_api_shows_the_error_at_the_field(change, field, match, client):
    payload = client.get("/api/design?" + urlencode(normalise_state({"speed": "1450 rpm", **change}))).json()
    assert list(payload["errors"]) == [field]
    assert re.search(match, payload["errors"][field])


@pytest.mark.parametrize(("change", "field", "match"), [
    ({"ratio": "0.5"}, "ratio", "the drive must reduce the speed"),
    ({"ratio": "", "driven_speed": "2000 rpm"}, "driven_speed", "the drive must reduce the speed"),
    ({"driven": "rocket"}, "driven", "unknown driven machine 'rocket'"),
])
def test_request_errors_at_the_form_field(change, field, match):
    """A request's InputError (its ``field`` a request field) lands on the form field that maps to it."""
    state = {**normalise_state({"speed": "1450 rpm"}), **change}
    request, errors = design_request(state)
    assert request is None and list(errors) == [field]
    assert match in errors[field]


def test_centre_distance_bounds():
    """Without a wanted centre distance each chain is laid out at 40 pitches moved into the bounds; a
    range of one value is that centre distance; the exact centre distance of the even link count
    lies within a pitch of the wanted one (Shigley eq. (17-34), links rounded up)."""
    duty = Duty(11e3, 1460 * RPM, driven_speed=480 * RPM, driven_machine="varying_conveyor")
    fixed = design_drive(Duty(11e3, 1460 * RPM, driven_speed=480 * RPM, driven_machine="varying_conveyor",
                              centre_distance=0.6)).recommended
    one = design_drive(DesignRequest(duty, centre_distance_range=(0.6, 0.6))).recommended
    assert (one.chain, one.driving_teeth, one.driven_teeth, one.links, one.centre_distance) == (
        fixed.chain, fixed.driving_teeth, fixed.driven_teeth, fixed.links, fixed.centre_distance)
    result = design_drive(DesignRequest(duty, centre_distance_range=(0.3, 0.4), all_sizes=True))
    for c in result.candidates:
        wanted = result.request.wanted_centre(c.pitch)
        assert 0.3 <= wanted <= 0.4 and wanted <= c.centre_distance < wanted + c.pitch


@pytest.mark.parametrize(("bounds", "centre", "match"), [
    ((0.5, 0.4), None, r"centre_distance_range must be \(low, high\) in m with 0 <= low <= high <= 50 m"),
    ((-0.1, 0.4), None, "centre_distance_range must be"),
    ((0.1, 60.0), None, "centre_distance_range must be"),
    (("a", "b"), None, "centre_distance_range must be"),
    ((0.1, 0.4), 0.6, "give the centre distance or its bounds"),
])
def test_centre_distance_bounds_errors(bounds, centre, match):
    duty = Duty(11e3, 150.0, ratio=3.0, service_factor=1.3, centre_distance=centre)
    with pytest.raises(InputError, match=match) as err:
        DesignRequest(duty, centre_distance_range=bounds)
    assert err.value.field == "centre_distance_range"


def test_select_centre_distance_bounds(capsys):
    args = ["select", "--power", "11 kW", "--speed", "1460 rpm", "--driven-speed", "480 rpm", "--driven-machine",
            "varying_conveyor", "--json"]
    assert main([*args, "--min-centre-distance", "600 mm", "--max-centre-distance", "600 mm"]) == 0
    data = json.loads(capsys.readouterr().out)
    rec = data["recommended"]
    # the request the answer is for, in SI units (select --json)
    assert data["request"]["centre_distance_range"] == [0.6, 0.6] and data["request"]["duty"]["power"] == 11e3
    assert main([*args, "--centre-distance", "600 mm"]) == 0
    assert rec == json.loads(capsys.readouterr().out)["recommended"]
    assert main([*args, "--min-centre-distance", "700 mm", "--max-centre-distance", "600 mm"]) == 2
    assert "--min-centre-distance/--max-centre-distance must be (low, high)" in capsys.readouterr().err


def test_duty_helpers_refuse_unknown_names():
    # found by the API fuzz generators (scripts/fuzz.py): a KeyError before
    from chaindrive.design.duty import check_duty_value, duty_class

    with pytest.raises(UnknownNameError, match="no duty value '5 rad/s'; valid: power, speed"):
        check_duty_value("5 rad/s", 1.0)
    with pytest.raises(InputError, match="unknown driven machine 'fatigue'") as err:
        duty_class("fatigue")
    assert err.value.field == "driven_machine"
    with pytest.raises(InputError, match="unknown load character 'wild'"):
        duty_class(None, "wild")
    with pytest.raises(InputError, match="unknown driver 'steam'") as err:
        service_factor_of("steam", load_character="smooth")
    assert err.value.field == "driver"
    with pytest.raises(InputError, match="no duty class") as err:
        service_factor_of("electric_motor")
    assert err.value.field == "service_factor"
    with pytest.raises(InputError, match="service_factor must be >= 1"):
        service_factor_of("electric_motor", given=0.5)


def test_web_teeth_and_speed_bounds_are_the_limits(client):
    """The JSON API and the expert pages take the teeth and the speed bounds of chaindrive.limits
    (were 3...150 teeth and 1000 rad/s of their own)."""
    from chaindrive.limits import MAX_SPEED
    from chaindrive.web.expert import _SPEED

    assert _SPEED.maximum == MAX_SPEED == DUTY_RANGES["speed"][1]
    base = {"chain": "18x64", "speed": "5 rad/s", "points": "21"}
    assert client.get("/api/kinematics", params={**base, "teeth": "160"}).status_code == 200
    for teeth in (str(MIN_TEETH - 1), str(MAX_TEETH + 1)):
        assert client.get("/api/kinematics", params={**base, "teeth": teeth}).status_code == 422
    r = client.get("/api/kinematics", params={**base, "teeth": "8", "speed": "2e4 rad/s"})
    assert r.status_code == 422 and "speed" in r.text


def test_studio_required_static_safety_reaches_the_design(client):
    """A required static safety typed in the studio is the request's, as `select --required-static-safety`
    (the studio left it out of the roller design before)."""
    state = normalise_state({**_state(*DUTIES[1]), "required_static_safety": "20"})
    request, errors = design_request(state)
    assert errors == {} and request.required_static_safety == 20.0
    api = design_drive(request).recommended
    first = client.get("/api/design?" + urlencode(state)).json()["candidates"][0]
    assert (first["chain"], first["links"], first["required_static_safety"]) == (api.chain, api.links, 20.0)
    assert first["static_safety"] >= 20.0


def test_studio_field_bounds_come_from_limits():
    """Issue 31, item 2: the studio's form takes every bound from chaindrive.limits (DUTY_RANGES,
    FORM_RANGES, MIN_TEETH/MAX_TEETH) or the project schema; web/design.py writes no number as a bound."""
    import re
    from pathlib import Path

    from chaindrive.limits import FORM_RANGES
    from chaindrive.web import design as web_design

    text = Path(web_design.__file__).read_text(encoding="utf-8")
    assert not re.search(r"maximum=\s*[0-9.]", text)
    assert not re.search(r'FieldSpec\("[^"]*",\s*[-0-9.]', text)
    for name, (_low, high, _unit) in FORM_RANGES.items():
        spec = web_design.FIELDS[name]
        assert spec.maximum == high, name
