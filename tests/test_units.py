"""The strict quantity parser, the chain-speed conversion and the size limits."""

import math
import warnings

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from chaindrive.errors import InputError, ValidityRangeWarning
from chaindrive.kinematics.speed import chain_speed_to_angular_velocity, parse_wheel_speed
from chaindrive.limits import (
    MAX_POINTS,
    check_duration,
    check_size,
    warn_implausible,
)
from chaindrive.units import (
    MAX_TEXT_LENGTH,
    parse_quantity,
    to_si,
)

# Reference factors: SI brochure 9th ed. (2019) and the definitions of the units
# (1 rpm = 2π/60 rad/s, 1 deg = π/180 rad, 1 arcmin = π/10800 rad, 1 kN = 1000 N).
CASES = [
    ("64 mm", "m", 0.064),
    ("300 rpm", "rad/s", 10 * math.pi),
    ("5 rad/s", "rad/s", 5.0),
    ("10 1/s", "Hz", 10.0),
    ("600 rpm", "Hz", 10.0),
    ("2 rev/s", "rad/s", 4 * math.pi),
    ("5 Hz", "rad/s", 10 * math.pi),  # five turns per second
    ("300 rpm", "Hz", 5.0),
    ("10 Hz", "Hz", 10.0),
    ("2 kN", "N", 2000.0),
    ("20 deg", "rad", math.pi / 9),
    ("50 arcmin", "rad", 50 * math.pi / 10800),
    ("50 kN/m", "N/m", 5e4),
    ("7 kN*m", "N*m", 7000.0),
    ("7 kN·m", "N*m", 7000.0),
    ("7 N m", "N*m", 7.0),
    ("2e-16 m**2/N", "m**2/N", 2e-16),
    ("2e-16 m^2/N", "m**2/N", 2e-16),
    ("1 mm²", "m**2", 1e-6),
    ("0.8 um", "m", 8e-7),
    ("0.8 µm", "m", 8e-7),
    ("2.6 kg/m", "kg/m", 2.6),
    ("210 GPa", "Pa", 2.1e11),
    ("500 ms", "s", 0.5),
    ("15 kW", "W", 15000.0),
    ("-5 mm", "m", -0.005),
    ("+.5 m", "m", 0.5),
    ("3", "", 3.0),
    ("3", "dimensionless", 3.0),
    ("2 %", "", 0.02),
    (5, "rad/s", 5.0),      # a Python number is SI (the API path)
    (2.5, "m", 2.5),
]


@pytest.mark.parametrize("text, unit, expected", CASES)
def test_parse_quantity_values(text, unit, expected):
    assert parse_quantity(text, unit, field="f") == pytest.approx(expected, rel=1e-12)


def test_negative_zero_is_zero():
    v = parse_quantity("-0 mm", "m", field="inner-width")
    assert v == 0.0 and math.copysign(1.0, v) == 1.0


@pytest.mark.parametrize(
    "text, unit, match",
    [
        ("1450", "rad/s", r'speed: give a unit, e\.g\. "1450 rpm" or "1450 rad/s"'),
        ("7.5", "W", r'speed: give a unit, e\.g\. "7\.5 W" or "7\.5 kW"'),
        ("20", "rad", r'give a unit, e\.g\. "20 deg" or "20 rad"'),
        ("20 %", "rad", r"give an angle unit"),
        ("9**9**9", "m", r"cannot read '9\*\*9\*\*9' as a quantity.*no arithmetic"),
        ("10**10**10 mm", "m", r"no arithmetic, no powers of powers"),
        ("2**1000", "m", r"no arithmetic"),
        ("1+1 m", "m", r"no arithmetic"),
        ("5 (m)", "m", r"cannot read"),
        ("5 m**22", "m", r"cannot read"),
        ("nan m", "m", r"cannot read"),
        ("inf", "m", r"cannot read"),
        ("1e400 m", "m", r"too large"),
        ("1e308 km", "m", r"overflows"),
        ("1,5 m", "m", r"decimal point as '\.'.*\"1\.5 mm\""),
        ("5 foo", "m", r"unknown unit 'foo'"),
        ("3 kg", "m", r"'3 kg' has units of \[mass\], expected a quantity convertible to 'm'"),
        ("20 deg", "", r"is an angle"),
        ("300 rpm", "1/s", r"is an angle"),
        ("5 1/s", "rad/s", r"'5 1/s' is ambiguous for an angular quantity.*\"5 rpm\" or \"5 rad/s\""),
        ("1450 1/min", "rad/s", r"is ambiguous"),
        ("", "m", r"expected a number with a unit"),
        ("   ", "m", r"expected a number with a unit"),
        (None, "m", r"expected a number with a unit"),
        (True, "m", r"expected a number with a unit"),
        (float("nan"), "m", r"finite"),
        (float("inf"), "m", r"finite"),
        ("1" * (MAX_TEXT_LENGTH + 1), "m", r"at most 64 characters"),
        ("1 " + "m*" * 40 + "m", "m", r"at most 64 characters"),
    ],
)
def test_parse_quantity_refuses(text, unit, match):
    with pytest.raises(InputError, match=match):
        parse_quantity(text, unit, field="speed")


def test_bare_number_allowed_when_asked():
    assert parse_quantity("5", "m", require_unit=False) == 5.0
    with pytest.raises(InputError, match="unknown quantity kind"):
        to_si("1", "colour")
    assert to_si("2.6 kg/m", "mass_per_length") == pytest.approx(2.6)
    with pytest.raises(InputError, match=r'mass-per-length: give a unit, e\.g\. "2\.6 kg/m"'):
        to_si("2.6", "mass_per_length", field="mass-per-length")


def test_arithmetic_is_refused_unread():
    # the issue: pint evaluates '9**9**9' for minutes; the grammar refuses it unread
    for text in ("9**9**9", "10**10**10 mm", "9**9**9**9 m", "(" * 60, "1e9**1e9 m"):
        with pytest.raises(InputError):
            parse_quantity(text, "m", field="pitch")


@settings(max_examples=300, deadline=None)
@given(st.one_of(st.text(max_size=80),
                 st.text(alphabet="0123456789.eE+- mkMNgsrpad/*^²·%°µHzil1", max_size=30)))
def test_any_text_is_a_value_or_an_input_error(text):
    # property: never another exception, never a non-finite value
    for unit in ("m", "rad/s", ""):
        try:
            v = parse_quantity(text, unit, field="f")
        except InputError:
            continue
        assert math.isfinite(v)


@settings(max_examples=100, deadline=None)
@given(st.floats(min_value=-1e300, max_value=1e300, allow_nan=False))
def test_round_trip_mm(x):
    # property: '<x> mm' is x / 1000 m, exactly as float division gives it
    assert parse_quantity(f"{x!r} mm", "m") == pytest.approx(x * 1e-3, rel=1e-15, abs=1e-320)


# -------------------------------------------------------------------------- chain speed


def test_chain_speed_against_the_kinematics_mean_speed():
    # independent: the mean speed of the entry kinematics (Dolipiński et al. worked case
    # 18x64, z = 8, ω = 5 rad/s, and a 19-tooth 16B sprocket) over one tooth period
    from chaindrive.kinematics import chain_entry

    r = chain_entry(0.064, 8, 5.0, bar_diameter=0.018)
    w = chain_speed_to_angular_velocity(r.summary["v_mean"], 0.064, 8, link_chain=True)
    assert w == pytest.approx(5.0, rel=1e-12)
    r = chain_entry(0.0254, 19, 3.0)
    assert chain_speed_to_angular_velocity(r.summary["v_mean"], 0.0254, 19) == pytest.approx(3.0, rel=1e-12)


def test_parse_wheel_speed():
    # scraper conveyor: 1.2 m/s on an 8-pocket wheel, 18x64: ω = 2π 1.2 / (16 × 0.064)
    assert parse_wheel_speed("1.2 m/s", pitch=0.064, teeth=8, link_chain=True) == pytest.approx(
        2 * math.pi * 1.2 / (16 * 0.064), rel=1e-12)
    assert parse_wheel_speed("72 m/min", pitch=0.064, teeth=8, link_chain=True) == pytest.approx(
        2 * math.pi * 1.2 / (16 * 0.064), rel=1e-12)
    assert parse_wheel_speed("48 rpm", pitch=0.064, teeth=8) == pytest.approx(48 * math.pi / 30)
    assert parse_wheel_speed(5.0, pitch=0.064, teeth=8) == 5.0
    with pytest.raises(InputError, match=r'give a unit.*chain speed such as "1\.2 m/s"'):
        parse_wheel_speed("1450", pitch=0.0254, teeth=19)
    with pytest.raises(InputError, match=r"has units of \[mass\].*chain speed"):
        parse_wheel_speed("3 kg", pitch=0.0254, teeth=19)
    with pytest.raises(InputError, match=r"pitch must be positive"):
        chain_speed_to_angular_velocity(1.0, -0.01, 19)
    with pytest.raises(InputError, match=r"teeth must be a whole number >= 2"):
        chain_speed_to_angular_velocity(1.0, 0.01, 1)
    with pytest.raises(InputError, match=r"chain_speed (must be a finite|must not be NaN)"):
        chain_speed_to_angular_velocity(float("nan"), 0.01, 19)


def test_implausible_speed_warns():
    with pytest.warns(ValidityRangeWarning, match=r"speed = 13846 rpm is implausible"):
        parse_wheel_speed("1450 rad/s", pitch=0.0254, teeth=19)
    with pytest.warns(ValidityRangeWarning) as record:
        parse_wheel_speed("100 m/s", pitch=0.0254, teeth=19)
    assert [str(w.message).split(" is ")[0] for w in record] == ["speed (chain speed) = 100 m/s",
                                                                "speed = 12433 rpm"]
    # the issue: 7.5 W at 13,800 rpm; and a plausible 3000 rpm on a 100-tooth 16B wheel
    # drives the chain at 100 · 25.4 mm · 50 /s = 127 m/s
    with pytest.warns(ValidityRangeWarning, match=r"speed \(chain speed n p omega / 2 pi\) = 127 m/s"):
        parse_wheel_speed("3000 rpm", pitch=0.0254, teeth=100)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        parse_wheel_speed("1450 rpm", pitch=0.0254, teeth=19)
        assert not warn_implausible("power", 15e3, "power")
        assert not warn_implausible("x", 1e9, "no such kind")
    with pytest.warns(ValidityRangeWarning, match=r"power = 0.0005 kW is implausible"):
        warn_implausible("power", 0.5, "power")


# -------------------------------------------------------------------------- limits


def test_check_size():
    assert check_size("points", 361, MAX_POINTS, minimum=2) == 361
    assert check_size("points", 361.0, MAX_POINTS, minimum=2) == 361
    for bad in (1, 10**8, 2.5, True, "7", float("nan"), None):
        with pytest.raises(InputError, match=r"points must be a whole number in \[2, 1000000\]"):
            check_size("points", bad, MAX_POINTS, minimum=2)


def test_check_duration():
    assert check_duration("duration", 2.0) == 2.0
    for bad in (0.0, -1.0, 61.0, float("inf"), float("nan")):
        with pytest.raises(InputError, match=r"duration must lie in \(0, 60\] s"):
            check_duration("duration", bad)
    with pytest.raises(InputError, match=r"duration must be a number of seconds"):
        check_duration("duration", "x")


def test_api_refuses_sizes_before_allocating():
    # the issue: --points 100000000 took 43 s, --teeth 10000000000 asked for 74.5 GiB
    from chaindrive.geometry.track_wheel import TrackDriveWheel
    from chaindrive.kinematics import chain_entry
    from chaindrive.kinematics.crawler import crawler_drive
    from chaindrive.vibration import TensionerSpan

    with pytest.raises(InputError, match=r"points must be a whole number in \[2, 1000000\], got 100000000"):
        chain_entry(0.064, 8, 5.0, bar_diameter=0.018, points=10**8)
    with pytest.raises(InputError, match=r"points must be a whole number in \[2, 1000000\]"):
        crawler_drive(0.1, 8, 3.0, points=10**8)
    with pytest.raises(InputError, match=r"teeth must be a whole number in \[3, 10000\], got 1e\+10"):
        TrackDriveWheel(pitch=0.17, teeth=10**10, pin_radius=0.025)
    with pytest.raises(InputError, match=r"teeth must be a whole number in \[3, 10000\]"):
        chain_entry(0.064, 10**10, 5.0, bar_diameter=0.018)
    span = TensionerSpan(2000.0, 2.6, 0.8, 0.8, 0.35, 0.35, 3.0, 5e4)
    with pytest.raises(InputError, match=r"modes must be a whole number in \[1, 100\]"):
        span.frequencies(10**6)


def test_simulation_bounds():
    from chaindrive.simulation import roller_example

    with pytest.raises(InputError, match=r"links must be a whole number in \[4, 10000\]"):
        roller_example(links=10**6)
    from chaindrive.simulation import simulate

    model = roller_example()
    with pytest.raises(InputError, match=r"duration must lie in \(0, 60\] s, got 3600 s"):
        simulate(model, 3600.0)


@settings(max_examples=40, deadline=None)
@given(z=st.integers(3, 60), pitch_mm=st.floats(5.0, 200.0), omega=st.floats(0.05, 200.0),
       link=st.booleans())
def test_chain_speed_round_trip_against_the_polygon(z, pitch_mm, omega, link):
    # property: the mean speed of the chain over one tooth period, computed independently by
    # the entry kinematics (a polygon of z or 2z sides), converts back to omega
    from chaindrive.kinematics import chain_entry

    p = pitch_mm * 1e-3
    bar = 0.25 * p if link else None
    v = chain_entry(p, z, omega, bar_diameter=bar, points=33).summary["v_mean"]
    assert chain_speed_to_angular_velocity(v, p, z, link_chain=link) == pytest.approx(omega, rel=1e-9)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityRangeWarning)  # fast corners of the range
        w = parse_wheel_speed(f"{v!r} m/s", pitch=p, teeth=z, link_chain=link)
    assert w == pytest.approx(omega, rel=1e-9)


# ------------------------------------------------------- spellings engineers type (issue 22)
@pytest.mark.parametrize("text,unit,expected", [
    ("1450 RPM", "rad/s", 1450 * math.pi / 30),      # 1 rpm = 2π/60 rad/s
    ("1450 Rpm", "rad/s", 1450 * math.pi / 30),
    ("1450 rev/min", "rad/s", 1450 * math.pi / 30),
    ("1450 r/min", "rad/s", 1450 * math.pi / 30),
    ("1450 U/min", "rad/s", 1450 * math.pi / 30),
    ("2 r/s", "rad/s", 4 * math.pi),
    ("7.5 kw", "W", 7500.0),
    ("7.5 KW", "W", 7500.0),
    ("7.5 Kw", "W", 7500.0),
    ("2 KN", "N", 2000.0),
    ("50 KN/m", "N/m", 50000.0),
    ("40 Nm", "N*m", 40.0),
    ("1.2 kNm", "N*m", 1200.0),
    ("3 KG", "kg", 3.0),
    ("64 MM", "m", 0.064),
    ("210 GPA", "Pa", 210e9),
    ("10 HP", "W", 10 * 745.69987158227022),        # mechanical horsepower, 550 ft·lbf/s
])
def test_engineering_spellings_accepted(text, unit, expected):
    from chaindrive.units import parse_quantity

    assert parse_quantity(text, unit, field="x") == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize("text,unit,match", [
    ("5 mw", "W", r"power: unit 'mw' in '5 mw' is ambiguous: write 'mW' \(milliwatt\) or 'MW' \(megawatt\)"),
    ("5 mpa", "Pa", r"'MPa' \(megapascal\) or 'mPa' \(millipascal\)"),
    ("3 kn", "N", r"'kN' \(kilonewton\) or 'knot'"),
    ("3 kn/m", "N/m", r"unit 'kn' in '3 kn/m' is ambiguous"),
])
def test_ambiguous_spellings_refused_with_both_readings(text, unit, match):
    from chaindrive.units import parse_quantity

    with pytest.raises(InputError, match=match) as info:
        parse_quantity(text, unit, field="power")
    assert info.value.field == "power"


def test_spellings_keep_pint_units_and_cli_accepts_rpm_in_capitals():
    from chaindrive.cli import main
    from chaindrive.units import parse_quantity

    assert parse_quantity("5 MW", "W") == 5e6 and parse_quantity("5 mW", "W") == pytest.approx(5e-3)
    assert parse_quantity("500 nm", "m") == pytest.approx(5e-7)      # a nanometre stays one
    assert main(["kinematics", "--chain", "18x64", "--teeth", "8", "--speed", "48 RPM", "--points", "7"]) == 0


def test_moved_speed_functions_warn_from_units():
    """The former home chaindrive.units keeps the two wheel-speed functions as deprecated aliases."""
    import chaindrive.units as units

    with pytest.warns(FutureWarning, match="chaindrive.kinematics.speed.parse_wheel_speed"):
        f = units.parse_wheel_speed
    assert f is parse_wheel_speed
    with pytest.raises(AttributeError, match="no attribute 'nothing'"):
        units.nothing  # noqa: B018
