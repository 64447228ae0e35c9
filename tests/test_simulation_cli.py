"""CLI and plots of the simulation (chaindrive simulate)."""

from __future__ import annotations

import json

import numpy as np
import pytest

from chaindrive.cli import main


@pytest.mark.slow
@pytest.mark.parametrize(("example", "links"), [("roller", 100), ("link", 60)])
def test_cli_example(tmp_path, capsys, example, links):
    out = tmp_path / "out"
    assert main(["simulate", "--example", example, "--duration", "20 ms", "--ramp", "5 ms",
                 "-o", str(out), "--frames", "3", "--plots", "--json"]) == 0
    summary = json.loads(capsys.readouterr().out)
    # the load is carried by the tight span
    assert summary["tight_side_tension_mean"] > summary["slack_side_tension_mean"] > 0
    for name in ("simulation.npz", "simulation.json", "simulation.png", "frame.png",
                 "simulation.gif"):
        assert (out / name).exists()
    assert np.load(out / "simulation.npz")["tension"].shape[1] == links


def test_cli_project_file(tmp_path, capsys):
    pytest.importorskip("chaindrive.drive.project")
    from chaindrive.drive.project import template

    f = tmp_path / "drive.toml"
    f.write_text(template("roller"))
    assert main(["simulate", str(f), "--duration", "5 ms", "--ramp", "2 ms",
                 "-o", str(tmp_path / "o"), "--no-plots"]) == 0
    assert "link-steps/s" in capsys.readouterr().out


def test_cli_errors(tmp_path, capsys):
    assert main(["simulate", "-o", str(tmp_path)]) == 2
    assert "exactly one" in capsys.readouterr().err
    assert main(["simulate", "--example", "bike", "-o", str(tmp_path)]) == 2
    assert "--example must be one of roller, link, conveyor, got 'bike'" in capsys.readouterr().err
    assert main(["simulate", "--example", "roller", "--speed", "-5 rad/s", "-o", str(tmp_path)]) == 2
    assert "--speed must be non-negative (0 <= speed < inf rad/s" in capsys.readouterr().err
    assert main(["simulate", "--example", "link", "--load", "-1 kN*m", "-o", str(tmp_path)]) == 2
    assert "--load must be non-negative (0 <= load < inf N*m" in capsys.readouterr().err


def test_model_from_drive_load_and_speed():
    pytest.importorskip("chaindrive.drive.project")
    from pathlib import Path

    from chaindrive.drive.project import load_project
    from chaindrive.simulation import model_from_drive

    path = Path(__file__).resolve().parents[1] / "examples" / "roller_industrial.toml"
    d = load_project(path)
    m = model_from_drive(d)
    assert m.wheels[0].angular_velocity == pytest.approx(d.speed)
    # load torque on the 57-tooth wheel: T z2/z1 (moment balance through the chain)
    assert m.wheels[1].torque == pytest.approx(-d.torque() * 57 / 19)
    from chaindrive.analysis import drive_layout

    assert m.links == drive_layout(d).links


@pytest.mark.slow
def test_cli_conveyor_example(tmp_path, capsys):
    # the 100 m conveyor (2,194 links): assembled statically by Newton, a short run
    out = tmp_path / "conv"
    assert main(["simulate", "--example", "conveyor", "--duration", "10 ms", "-o", str(out),
                 "--no-plots", "--json"]) == 0
    summary = json.loads(capsys.readouterr().out)
    # at rest on the 2 s ramp: the tight span carries the slack tension + T/R = 48 kN
    assert summary["tight_side_tension_mean"] - summary["slack_side_tension_mean"] == \
        pytest.approx(10e3 / 0.2071, rel=0.06)
    assert np.load(out / "simulation.npz")["tension"].shape[1] == 2194
    assert main(["simulate", "--example", "conveyor", "--speed", "0 rad/s", "-o",
                 str(tmp_path / "bad"), "--no-plots"]) == 2
    assert "conveyor example must be positive" in capsys.readouterr().err


def test_cli_pictures_are_opt_in(tmp_path, capsys):
    """By default the arrays and the summary only; the PNGs with --plots, the animation
    with --gif (or --frames N); --no-plots: no pictures at all."""
    out = tmp_path / "plain"
    assert main(["simulate", "--example", "roller", "--duration", "4 ms", "--ramp", "2 ms",
                 "-o", str(out), "--json"]) == 0
    capsys.readouterr()
    assert {p.name for p in out.iterdir() if not p.name.startswith(".")} == {
        "simulation.npz", "simulation.json"}
    out = tmp_path / "png"
    assert main(["simulate", "--example", "roller", "--duration", "4 ms", "--ramp", "2 ms",
                 "-o", str(out), "--plots", "--json"]) == 0
    capsys.readouterr()
    assert {p.name for p in out.iterdir() if not p.name.startswith(".")} == {
        "simulation.npz", "simulation.json", "simulation.png", "frame.png"}
    out = tmp_path / "gif"
    assert main(["simulate", "--example", "roller", "--duration", "4 ms", "--ramp", "2 ms",
                 "-o", str(out), "--gif", "--no-plots", "--json"]) == 0
    assert not (out / "simulation.gif").exists()  # --no-plots wins: no pictures at all
    out = tmp_path / "gif2"
    assert main(["simulate", "--example", "roller", "--duration", "4 ms", "--ramp", "2 ms",
                 "-o", str(out), "--gif", "--json"]) == 0
    assert {p.name for p in out.iterdir() if not p.name.startswith(".")} == {
        "simulation.npz", "simulation.json", "simulation.gif"}


def test_default_run_loads_no_matplotlib(tmp_path):
    """The footprint of a plain run (#33: `simulate --example roller` < 200 MB): no
    pictures asked, so no matplotlib. A guard on what is imported, not on time."""
    import subprocess
    import sys

    code = ("import sys\n"
            "from chaindrive.cli import main\n"
            f"code = main(['simulate', '--example', 'roller', '--duration', '4 ms', '--ramp', '2 ms', "
            f"'-o', {str(tmp_path / 'o')!r}])\n"
            "loaded = [m for m in ('matplotlib',) if m in sys.modules]\n"
            "print(code, loaded)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert out.stdout.strip().splitlines()[-1] == "0 []", out.stdout[-500:] + out.stderr[-2000:]


def test_bad_option_is_refused_before_any_progress(tmp_path, capsys):
    # the options are read before "assembling the model...": a refused run shows one line only
    assert main(["simulate", "--example", "roller", "--duration", "5", "-o", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err
    assert "assembling" not in err
    assert err.strip().splitlines() == ["error: --duration: give a unit, e.g. \"5 s\" or \"5 ms\" (got '5')"]
    assert not (tmp_path / "out").exists()
