"""CLI ``chaindrive kinematics``."""

from __future__ import annotations

import json

import numpy as np
import pytest

from chaindrive.cli import main

SEED = ["kinematics", "--chain", "18x64", "--teeth", "8", "--speed", "5 rad/s",
        "--guide-end", "256 mm"]


def _json(capsys, argv):
    assert main(argv) == 0
    return json.loads(capsys.readouterr().out)


def test_json_seed_case(capsys):
    d = _json(capsys, SEED + ["--entry", "tangential", "--json", "--points", "9"])
    assert set(d) == {"phi", "x", "velocity", "acceleration", "summary"}
    assert len(d["phi"]) == 9
    assert d["phi"][-1] == pytest.approx(np.pi / 4)
    s = d["summary"]
    for key in ("v_mean", "v_min", "v_max", "nonuniformity", "a_min", "a_max",
                "sign_change_at_period_end", "transverse_throw"):
        assert key in s
    # mean speed = 2t z ω / 2π = 0.128 * 8 * 5 / 2π (Dolipiński et al.'s case)
    assert s["v_mean"] == pytest.approx(0.128 * 8 * 5 / (2 * np.pi), rel=1e-12)
    assert s["sign_change_at_period_end"] is False


def test_rpm_and_custom_chain_equal_catalogue(capsys):
    a = _json(capsys, SEED + ["--entry", "chordal", "--json", "--points", "5"])
    b = _json(capsys, ["kinematics", "--pitch", "64 mm", "--bar-diameter", "18 mm", "--teeth", "8",
                       "--speed", f"{5 * 60 / (2 * np.pi)} rpm", "--guide-end", "0.256 m",
                       "--entry", "chordal", "--json", "--points", "5"])
    np.testing.assert_allclose(a["velocity"], b["velocity"], rtol=1e-12)


def test_roller_and_paper_and_height(capsys):
    d = _json(capsys, ["kinematics", "--chain", "16B", "--teeth", "12", "--speed", "100 rpm",
                       "--json", "--points", "3"])
    assert d["summary"]["v_min"] / d["summary"]["v_max"] == pytest.approx(np.cos(np.pi / 12))
    d = _json(capsys, SEED + ["--entry", "tangential", "--model", "paper", "--json"])
    assert d["summary"]["a_max"] == pytest.approx(1.223309, abs=2e-6)  # regression
    d = _json(capsys, SEED + ["--guide-height", "150 mm", "--json", "--points", "3"])
    assert d["summary"]["transverse_throw"] == 0.0


def test_text_output_and_plot(capsys, tmp_path):
    png = tmp_path / "k.png"
    assert main(SEED + ["--entry", "tangential", "--plot", str(png)]) == 0
    out = capsys.readouterr().out
    assert "non-uniformity" in out and "wrote" in out
    assert png.stat().st_size > 10_000


@pytest.mark.parametrize(
    "extra, match",
    [
        (["--teeth", "2"], "teeth must be a whole number >= 3"),
        (["--teeth", "10000000000"], "teeth must be a whole number in [3, 10000]"),
        (["--points", "100000000"], "points must be a whole number in [2, 1000000]"),
        (["--speed", "1450"], 'give a unit, e.g. "1450 rpm" or "1450 rad/s"'),
        (["--speed", "9**9**9"], "no arithmetic"),
        (["--speed", "-5 rad/s"], "angular_velocity must be positive"),
        (["--speed", "5 m"], "--speed: '5 m' has units of"),
        (["--entry", "tangential", "--guide-end", "10 mm"], "guide_end_distance = 0.01 m is too close"),
        (["--entry", "sideways"], "unknown entry 'sideways'"),
        (["--model", "nope"], "unknown model 'nope'"),
        (["--guide-height", "-1 mm"], "--guide-height must be non-negative"),
    ],
)
def test_bad_input_exit_2_one_line(capsys, extra, match):
    argv = SEED + extra
    # later options override earlier ones in click
    assert main(argv) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("error: ") and match in err
    assert "\n" not in err and "Traceback" not in err


def test_custom_chain_errors(capsys):
    assert main(["kinematics", "--teeth", "8", "--speed", "5 rad/s"]) == 2
    assert "give --chain" in capsys.readouterr().err
    assert main(["kinematics", "--pitch", "64 mm", "--teeth", "8", "--speed", "5 rad/s"]) == 2
    assert "exactly one of --bar-diameter" in capsys.readouterr().err
    assert main(["kinematics", "--pitch", "0 mm", "--roller", "--teeth", "8", "--speed", "5 rad/s"]) == 2
    assert "pitch must be positive" in capsys.readouterr().err
    assert main(["kinematics", "--chain", "18x64", "--teeth", "8", "--speed", "5 rad/s",
                 "--plot", "x.png"]) == 2
    assert "--guide-end" in capsys.readouterr().err


def test_speed_as_chain_speed(capsys):
    # the mean chain speed of Dolipiński et al.'s case is 2 t z ω / 2π = 0.128 · 8 · 5 / 2π m/s;
    # giving it as --speed must reproduce ω = 5 rad/s
    v = 0.128 * 8 * 5 / (2 * np.pi)
    d = _json(capsys, ["kinematics", "--chain", "18x64", "--teeth", "8", "--speed", f"{v!r} m/s",
                       "--json", "--points", "5"])
    assert d["summary"]["v_mean"] == pytest.approx(v, rel=1e-12)
    d = _json(capsys, ["kinematics", "--chain", "16B", "--teeth", "19", "--speed", "60 m/min",
                       "--json", "--points", "5"])
    assert d["summary"]["v_mean"] == pytest.approx(1.0, rel=1e-12)


def test_implausible_speed_warns(capsys):
    assert main(["kinematics", "--chain", "16B", "--teeth", "19", "--speed", "1450 rad/s",
                 "--points", "5"]) == 0
    assert "warning: --speed = 13846 rpm is implausible" in capsys.readouterr().err
