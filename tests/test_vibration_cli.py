"""CLI ``chaindrive vibration`` (the tensioner paper)."""

from __future__ import annotations

import json

import numpy as np
import pytest

from chaindrive.cli import main
from chaindrive.vibration import static_rod_force, tensioner_frequencies

BASE = ["vibration", "--tension", "2 kN", "--mass-per-length", "2.6 kg/m", "--span1", "0.8 m",
        "--span2", "0.8 m", "--angle1", "20 deg", "--angle2", "20 deg",
        "--tensioner-mass", "3 kg", "--tensioner-stiffness", "50 kN/m"]


def _replace(args, opt, value):
    out = list(args)
    out[out.index(opt) + 1] = value
    return out


def test_json_output(capsys):
    assert main(BASE + ["--modes", "3", "--speed", "300 rpm", "--ratio", "2.5", "--teeth", "17", "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert set(d) == {"frequencies_rad_s", "frequencies_hz", "static_rod_force_n", "resonance"}
    b = np.radians(20)
    np.testing.assert_allclose(d["frequencies_rad_s"], tensioner_frequencies(2000, 2.6, 0.8, 0.8, b, b, 3, 5e4))
    np.testing.assert_allclose(np.array(d["frequencies_hz"]) * 2 * np.pi, d["frequencies_rad_s"])
    assert d["static_rod_force_n"] == pytest.approx(static_rod_force(2000, b, b))
    assert len(d["resonance"]) == 9  # 3 modes x (driving, driven, unequal links)
    assert set(d["resonance"][0]) == {"mode", "excitation", "ratio", "ok"}
    assert all(r["ok"] for r in d["resonance"])
    unequal = [r for r in d["resonance"] if r["excitation"] == "unequal links (inner/outer)"]
    assert unequal[0]["ratio"] == pytest.approx(d["frequencies_rad_s"][0] / (8.5 * 10 * np.pi))


def test_text_output_and_failed_check(capsys):
    assert main(BASE) == 0
    out = capsys.readouterr().out
    assert "natural frequency P1" in out and "rad/s" in out and "static rod force" in out
    # 900 rpm: P1 ≈ 94.7 rad/s ≈ ω1 -> resonance, exit code 1
    assert main(BASE + ["--speed", "900 rpm", "--ratio", "2.5", "--teeth", "17"]) == 1
    out = capsys.readouterr().out
    assert "RESONANCE RISK" in out and " NO" in out


def test_json_without_speed_has_empty_table(capsys):
    assert main(BASE + ["--json", "--model", "as_printed", "--modes", "2"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["resonance"] == [] and len(d["frequencies_rad_s"]) == 2


def test_link_chain_excitations(capsys):
    assert main(BASE + ["--speed", "20 rpm", "--teeth", "8", "--link-chain", "--json"]) == 0
    names = {r["excitation"] for r in json.loads(capsys.readouterr().out)["resonance"]}
    assert names == {"driving sprocket", "driven sprocket", "link pair (t ± d)"}  # the paper's three


def test_plots(tmp_path, capsys):
    cam, mp = tmp_path / "c.png", tmp_path / "m.png"
    args = _replace(_replace(BASE, "--tensioner-mass", "30 kg"), "--tensioner-stiffness", "20 kN/m")
    rc = main(args + ["--speed", "300 rpm", "--ratio", "2.5", "--teeth", "17", "--campbell", str(cam), "--map", str(mp)])
    assert rc == 1  # this design resonates (P1 ≈ 31 rad/s ≈ ω1)
    assert cam.stat().st_size > 10000 and mp.stat().st_size > 10000
    assert "wrote" in capsys.readouterr().out


@pytest.mark.parametrize("opt,value,match", [
    ("--tension", "0 N", "tension must be positive and finite (0 < tension < inf N)"),
    ("--tension", "-2 kN", "tension must be positive"),
    ("--mass-per-length", "0 kg/m", "mass-per-length must be positive"),
    ("--span1", "0 m", "span1 must be positive"),
    ("--span2", "-1 m", "span2 must be positive"),
    ("--angle1", "90 deg", "angle1 must lie in [0, 90) deg"),
    ("--angle2", "120 deg", "angle2 must lie in [0, 90) deg"),
    ("--angle2", "-5 deg", "angle2 must lie in [0, 90) deg"),
    ("--tensioner-mass", "-1 kg", "tensioner-mass must be non-negative"),
    ("--tensioner-stiffness", "-5 N/m", "tensioner-stiffness must be non-negative"),
    ("--tension", "2 kg", "tension"),
])
def test_bad_input_exit_2(opt, value, match, capsys):
    assert main(_replace(BASE, opt, value)) == 2
    err = capsys.readouterr().err
    assert match in err
    assert err.count("\n") == 1 and err.startswith("error: ")


@pytest.mark.parametrize("extra,match", [
    (["--modes", "0"], "modes must be >= 1"),
    (["--speed", "0 rpm"], "speed must be positive"),
    (["--speed", "300 rpm", "--ratio", "0"], "ratio must be positive"),
    (["--speed", "300 rpm", "--teeth", "2"], "teeth must be a whole number >= 3"),
    (["--campbell", "x.png"], "need a speed range"),
    (["--speed", "300 rpm", "--speed-min", "500 rpm", "--campbell", "x.png"], "speed-max must exceed"),
    (["--model", "exact"], "unknown model 'exact'"),
])
def test_bad_options_exit_2(extra, match, capsys):
    assert main(BASE + extra) == 2
    assert match in capsys.readouterr().err
