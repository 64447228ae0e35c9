"""Tests of chaindrive.selection against published ANSI rating tables."""

from __future__ import annotations

import json
import math
import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from chaindrive import selection as S
from chaindrive.drive.writer import candidate_project_text
from chaindrive.errors import InfeasibleError, InputError, UnknownNameError, ValidityRangeWarning

RPM = 2 * math.pi / 60
HP = S.HP

# Published rating table of ANSI No. 40 single-strand roller chain [hp], rows small
# sprocket teeth 11…18, columns rpm 50…1800. Source: Engineers Edge, "Single Strand
# Roller Chain Number 40 Horsepower Ratings Table" (ANSI/ACA ratings),
# https://www.engineersedge.com/hardware/single_strand_roller_chain_number_40_13897.htm
# The 1800-rpm column is in the roller-bushing regime, the others link-plate.
RPM_40 = [50, 100, 200, 300, 400, 500, 700, 900, 1000, 1200, 1400, 1600, 1800]
TABLE_40 = {
    11: [0.23, 0.43, 0.80, 1.16, 1.50, 1.83, 2.48, 3.11, 3.42, 4.03, 4.63, 5.22, 4.66],
    12: [0.25, 0.47, 0.88, 1.27, 1.65, 2.01, 2.73, 3.42, 3.76, 4.43, 5.09, 5.74, 5.31],
    13: [0.28, 0.52, 0.96, 1.39, 1.80, 2.20, 2.97, 3.73, 4.10, 4.83, 5.55, 6.26, 5.99],
    14: [0.30, 0.56, 1.04, 1.50, 1.95, 2.38, 3.22, 4.04, 4.44, 5.23, 6.01, 6.78, 6.70],
    15: [0.32, 0.60, 1.12, 1.62, 2.10, 2.56, 3.47, 4.35, 4.78, 5.64, 6.47, 7.30, 7.43],
    16: [0.35, 0.65, 1.20, 1.74, 2.25, 2.75, 3.72, 4.66, 5.13, 6.04, 6.94, 7.83, 8.18],
    17: [0.37, 0.69, 1.29, 1.85, 2.40, 2.93, 3.97, 4.98, 5.48, 6.45, 7.41, 8.36, 8.96],
    18: [0.39, 0.73, 1.37, 1.97, 2.55, 3.12, 4.22, 5.30, 5.82, 6.86, 7.88, 8.89, 9.76],
}

# ANSI No. 41 (K_p = 0.0022, K_r = 3.4), 17 teeth, rpm 10…1400. Source: Engineers Edge,
# "Roller Chain No 41 Horsepower and Speed Ratings".
RPM_41 = [10, 25, 50, 100, 200, 300, 400, 500, 700, 900, 1000, 1200, 1400]
ROW_41_17 = [0.05, 0.11, 0.20, 0.38, 0.71, 1.02, 1.32, 1.61, 2.18, 2.74, 3.01, 3.29, 2.61]


@pytest.mark.parametrize("teeth", sorted(TABLE_40))
def test_ansi_40_table_whole_speed_range(teeth):
    n = np.array(RPM_40, dtype=float)
    got = S.ansi_rated_power(0.0127, teeth, n * RPM) / HP
    # the table is printed to 0.01 hp: rounding allows ±0.005; 0.006 for float noise
    assert np.allclose(got, TABLE_40[teeth], atol=0.006, rtol=0)


def test_ansi_41_table():
    kp, kr = S.ansi_constants("ANSI 41")
    got = S.ansi_rated_power(0.0127, 17, np.array(RPM_41) * RPM, plate_constant=kp,
                             roller_constant=kr) / HP
    assert np.allclose(got, ROW_41_17, atol=0.006, rtol=0)


def test_limits_cross_and_regimes():
    # link plate grows with n^0.9, roller-bushing falls with n^-1.5
    n = np.array([100, 3000]) * RPM
    h1 = S.ansi_link_plate_power(17, n, 0.0127)
    h2 = S.ansi_roller_bushing_power(17, n, 0.0127)
    assert h1[0] < h2[0] and h1[1] > h2[1]
    assert h1[1] / h1[0] == pytest.approx(30**0.9)
    assert h2[0] / h2[1] == pytest.approx(30**1.5)


def test_multi_strand_and_tooth_factor():
    one = float(S.ansi_rated_power(0.0254, 17, 500 * RPM))
    assert float(S.ansi_rated_power(0.0254, 17, 500 * RPM, strands=3)) == pytest.approx(2.5 * one)
    assert [S.multi_strand_factor(k) for k in (1, 2, 3, 4)] == [1.0, 1.7, 2.5, 3.3]
    with pytest.raises(InputError, match=r"strands must be a whole number in \[1, 4\]"):
        S.multi_strand_factor(5)
    # K1 converts the 17-tooth value to z teeth (Shigley Table 17-22)
    for z in (11, 19, 25):
        h17 = float(S.ansi_link_plate_power(17, 300 * RPM, 0.0254))
        hz = float(S.ansi_link_plate_power(z, 300 * RPM, 0.0254))
        assert hz == pytest.approx(h17 * float(S.tooth_correction_factor(z)))
        r17 = float(S.ansi_roller_bushing_power(17, 3000 * RPM, 0.0254))
        rz = float(S.ansi_roller_bushing_power(z, 3000 * RPM, 0.0254))
        assert rz == pytest.approx(r17 * float(S.tooth_correction_factor(z, "roller_bushing")))
    with pytest.raises(UnknownNameError, match="unknown regime"):
        S.tooth_correction_factor(17, "galling")


def test_constants_by_name():
    assert S.ansi_constants("ANSI 25-1") == (0.004, 29.0)
    assert S.ansi_constants("06C-2") == (0.004, 29.0)
    assert S.ansi_constants("41") == (0.0022, 3.4)
    assert S.ansi_constants("ANSI 240-3") == (0.004, 17.0)


def test_rating_warns_outside_tooth_range():
    with pytest.warns(ValidityRangeWarning, match="teeth = 60"):
        S.ansi_link_plate_power(60, 100, 0.0254)


def test_lubrication_type():
    # McGuire Bearing table, ANSI 80 (1 in): type A up to 170 ft/min (0.8636 m/s),
    # type B up to 1500 ft/min (7.62 m/s)
    v = np.array([0.86, 0.87, 7.6, 7.7])
    assert list(S.lubrication_type(v, 0.0254)) == ["I", "II", "II", "III"]
    with pytest.warns(ValidityRangeWarning, match="outside the lubrication table"):
        S.lubrication_type(1.0, 0.00635)


def test_select_ranking_and_consistency():
    w = 960 * RPM
    found = S.select(15e3, w, 3.0, service_factor=1.3, teeth_driving=19)
    keys = [(c.lubrication == "C'", c.strands, c.pitch) for c in found]
    assert keys == sorted(keys)  # simplex first, then by pitch
    for c in found:
        assert c.rated_power >= c.design_power == pytest.approx(19.5e3)
        assert c.power_margin == pytest.approx(c.rated_power / c.design_power) and c.power_margin >= 1
        assert c.teeth_driven == 57 and c.links % 2 == 0
        assert c.static_safety is None or c.static_safety >= 6.0
        assert c.lubrication in ("A", "B", "C", "C'")
    # per series and strand count only the smallest adequate pitch: one size smaller fails
    for c in found:
        smaller = [x for x in get_catalogue_pitches() if x < c.pitch]
        if smaller:
            p = max(smaller)
            assert float(S.ansi_rated_power(p, 19, w, strands=c.strands)) < 19.5e3
    assert len(S.select(15e3, w, 3.0, limit=2)) == 2


def test_select_and_design_rows_share_one_chain_choice():
    # the fields a select row and a design_drive row have in common are declared once
    # (selection.ChainChoice, #31): same names, units and display in both
    import dataclasses

    from chaindrive.design import DesignCandidate

    shared = [f.name for f in dataclasses.fields(S.ChainChoice)]
    assert shared[:3] == ["chain", "names", "family"] and "rated_power" in shared
    for cls in (S.Candidate, DesignCandidate):
        assert issubclass(cls, S.ChainChoice)
        assert [f.name for f in dataclasses.fields(cls)][:len(shared)] == shared
        assert cls.unit_of("speed") == "rad/s" and cls.unit_of("pitch") == "m"
    c = S.select(15e3, 960 * RPM, 3.0, teeth_driving=19, limit=1)[0]
    assert list(c.to_dict())[:len(shared)] == shared and c.pitch > 0 and c.teeth_driving == 19


def get_catalogue_pitches():
    from chaindrive.chains import catalogue

    return sorted({c.pitch for c in catalogue("iso606")})


def test_select_front_door_example():
    # The example: 7.5 kW at 1450 rpm, ratio 3. The ANSI/ACA limits (Engineers Edge No. 50
    # table, 17 teeth: 14.4 hp at 1400, 12.8 hp at 1600 rpm) give about 14.8 hp = 11.05 kW for a
    # 5/8 in simplex chain at 1450 rpm, and 13.0 hp = 9.70 kW for 1/2 in duplex (1.7 x 7.64 hp).
    rows = S.select(7.5e3, 1450 * RPM, 3.0)
    names = [c.chain for c in rows]
    assert names == ["10B-1", "10A-1", "08B-2", "08A-2", "08B-3", "08A-3"]
    assert rows[1].names == ("10A-1", "ANSI 50-1")  # one row, both names
    assert names.index("10B-1") < names.index("08B-3")  # simplex above triplex
    assert rows[1].rated_power / 1e3 == pytest.approx(11.05, abs=0.01)
    # 10B-1 and 08B-2 are rated by their family's method, ISO 10823 (docs/rating.md): the link-plate
    # branch governs with the B-series plate constant 0.00434 (Bhandari Table 14.2), 8.5 % above the ACA
    # 0.004: 11.10 -> 12.04 kW and 9.70 -> 10.52 kW
    assert rows[0].rated_power / 1e3 == pytest.approx(12.04, abs=0.01)
    assert rows[2].rated_power / 1e3 == pytest.approx(10.52, abs=0.01)
    assert rows[3].rated_power / 1e3 == pytest.approx(9.70, abs=0.01)
    assert [round(c.power_margin, 2) for c in rows] == [1.61, 1.47, 1.4, 1.29, 2.06, 1.9]
    # links for the default 40 pitches: X = 80 + 34 + (34 / 2 pi)^2 / 40 = 114.7 -> 116;
    # the centre distance is the inverse of the same formula (layout.centre_distance_approx)
    from chaindrive.layout import centre_distance_approx

    assert {c.links for c in rows} == {116}
    assert rows[0].centre_distance == pytest.approx(float(centre_distance_approx(0.015875, 17, 51, 116)))
    every = S.select(7.5e3, 1450 * RPM, 3.0, all_sizes=True)
    assert len(every) > len(rows) and {c.chain for c in rows} <= {c.chain for c in every}
    assert len({c.chain for c in every}) == len(every)
    assert not any(n.startswith("ANSI") for c in every for n in c.names[:1])  # ISO name first


def test_select_centre_distance_and_families():
    rows = S.select(7.5e3, 1450 * RPM, 3.0, centre_distance=0.6)
    for c in rows:
        assert abs(c.centre_distance - 0.6) < c.pitch  # within a pitch of the wish (even links)
    ansi = S.select(7.5e3, 1450 * RPM, 3.0, family="ansi")
    assert ansi[0].chain == "ANSI 50-1" and ansi[0].names == ("ANSI 50-1", "10A-1")
    assert all(c.family == "ansi" for c in ansi)
    duplex = S.select(7.5e3, 1450 * RPM, 3.0, strands=(2,))
    assert {c.strands for c in duplex} == {2}
    # too short a centre distance for the sprockets: refused with the reason
    with pytest.raises(InfeasibleError, match="sprockets too large for the centre distance"):
        S.select(7.5e3, 1450 * RPM, 3.0, centre_distance=0.05)
    # a galling-region-only case is listed last with type C'
    heavy = S.select(200e3, 300 * RPM, 2.0)
    assert heavy[-1].lubrication == "C'" and "galling region" in " ".join(heavy[-1].notes)
    assert heavy[0].lubrication != "C'"


def test_candidate_project_loads_and_lays_out(tmp_path):
    pytest.importorskip("pydantic")
    from chaindrive.drive.project import load_project

    row = S.select(7.5e3, 1450 * RPM, 3.0)[1]
    f = tmp_path / "drive.toml"
    f.write_text(candidate_project_text(row), encoding="utf-8")
    drive = load_project(f)
    assert drive.chain.name == "10A-1" and drive.links == 116
    assert drive.speed == pytest.approx(1450 * RPM) and [w.teeth for w in drive.wheels] == [17, 51]
    from chaindrive.analysis import drive_layout

    lay = drive_layout(drive)
    assert lay.links == 116
    assert lay.centre_distance_for_links.taut == pytest.approx(row.centre_distance, abs=0.5e-3)


def test_cli_select_write_then_layout(tmp_path, capsys):
    from chaindrive.cli import main

    f = tmp_path / "drive.toml"
    duty = ["select", "--power", "7.5 kW", "--speed", "1450 rpm", "--ratio", "3", "--load-character", "smooth"]
    assert main([*duty, "--write", str(f), "--choose", "2"]) == 0
    out = capsys.readouterr().out
    assert "service factor K_s = 1" in out and f"wrote {f}" in out and "margin" in out
    assert main(["layout", str(f)]) == 0
    assert "chain" in capsys.readouterr().out
    # the file exists now: --force needed
    assert main([*duty, "--write", str(f)]) == 2
    g = tmp_path / "other.toml"
    assert main([*duty, "--json", "--write", str(g)]) == 0
    captured = capsys.readouterr()
    data = json.loads(captured.out)
    assert data["recommended"] == data["candidates"][0] and data["recommended"]["links"] % 2 == 0
    assert f"wrote {g}" in captured.err and g.exists()


@pytest.mark.parametrize(("args", "match"), [
    (["--power", "7500", "--speed", "1450 rpm"], r"--power: give a unit"),
    (["--power", "7.5 kW", "--speed", "1450"], r"--speed: give a unit"),
    (["--power", "7.5 kW", "--speed", "1450 rpm", "--centre-distance", "600"], r"--centre-distance: give a unit"),
    (["--power", "7.5 kW", "--speed", "1450 rpm", "--strands", "1,5"], r"--strands must be whole numbers in \[1, 4\]"),
    (["--power", "7.5 kW", "--speed", "1450 rpm", "--choose", "9"], r"--choose must lie in \[1, \d\]"),
    (["--power", "7.5 kW", "--speed", "1450 rpm", "--limit", "0"], r"--limit must be a whole number in \[1, "),
    (["--power", "7.5 kW", "--speed", "1450 rpm", "--write", "x.txt"], r"--write"),
])
def test_cli_select_errors(args, match, capsys):
    from chaindrive.cli import main

    assert main(["select", "--ratio", "3", "--load-character", "smooth", *args]) == 2
    import re

    assert re.search(match, capsys.readouterr().err)


def test_select_errors():
    with pytest.raises(InputError, match="ratio must be >= 1"):
        S.select(1e3, 100, 0.5)
    with pytest.raises(InputError, match="service_factor must be >= 1"):
        S.select(1e3, 100, 2, service_factor=0.8)
    with pytest.raises(InputError, match="power must be positive"):
        S.select(-1, 100, 2)
    with pytest.raises(UnknownNameError, match="unknown roller-chain family 'din22252'"):
        S.select(1e3, 100, 2, family="din22252")
    with pytest.raises(InfeasibleError, match="no catalogue roller chain carries"):
        S.select(5e6, 3000 * RPM, 2)
    with pytest.raises(InputError, match="centre_distance must be positive"):
        S.select(1e3, 100, 2, centre_distance=-1.0)
    with pytest.raises(InputError, match="strands must be a non-empty selection of 1, 2, 3, 4"):
        S.select(1e3, 100, 2, strands=(0,))
    with pytest.raises(InputError, match=r"speed must be a single number"):
        S.select(1e3, [100, 200], 2)
    with pytest.raises(InputError, match=r"min_static_safety must be positive and finite"):
        S.select(1e3, 100, 2, min_static_safety=-1.0)
    with pytest.raises(InputError, match=r"min_static_safety must not be NaN"):
        S.select(1e3, 100, 2, min_static_safety=float("nan"))
    with pytest.raises(InputError, match=r"ratio must not be NaN"):
        S.select(1e3, 100, float("nan"))


def test_select_no_warning_leak():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        warnings.filterwarnings("ignore", "chaindrive.selection.select is deprecated", FutureWarning)
        rows = S.select(2e3, 300 * RPM, 2, teeth_driving=50)
    assert all("50 teeth: outside the 9-45 teeth" in " ".join(c.notes) for c in rows)


@settings(max_examples=12, deadline=None)
@given(power=st.floats(200.0, 2e5), rpm=st.floats(50.0, 3000.0), ratio=st.floats(1.0, 5.0),
       teeth=st.integers(11, 25))
def test_select_invariants(power, rpm, ratio, teeth):
    try:
        rows = S.select(power, rpm * RPM, ratio, teeth_driving=teeth)
    except InfeasibleError:
        return
    keys = [(c.lubrication == "C'", c.strands, c.pitch) for c in rows]
    assert keys == sorted(keys)
    assert len({c.chain for c in rows}) == len(rows)
    for c in rows:
        assert c.rated_power >= c.design_power and c.links % 2 == 0 and c.links > 0
        assert c.teeth_driven == round(teeth * ratio)
        assert (c.lubrication == "C'") == (c.speed > c.galling_speed)
        assert c.static_safety is None or c.static_safety >= 6.0
        assert all(math.isfinite(x) for x in (c.rated_power, c.centre_distance, c.working_tension))
