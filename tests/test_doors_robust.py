"""The reproducers of issue 34 at the command line and in project files: tiny speeds, the
documented limits at every door, Ctrl-C at any moment, and the messages."""

from __future__ import annotations

import math
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from _shared import EXAMPLES
from chaindrive.cli import main
from chaindrive.errors import ChainDriveError, InputError

SRC = Path(__file__).resolve().parents[1] / "src"


def _errors(capsys) -> list[str]:
    return [ln for ln in capsys.readouterr().err.splitlines() if ln.startswith(("error", "internal error"))]


# --------------------------------------------------------------------------- tiny values


def test_rating_at_tiny_speeds_is_one_line(capsys):
    # reproducers: 5e-324 rad/s gave `internal error: ZeroDivisionError`, exit 3; 1e-300 rpm
    # printed "roller-bushing inf kW", exit 0
    assert main(["rating", "--chain", "ANSI 80", "--teeth", "120", "--speed", "5e-324 rad/s"]) == 2
    assert len(_errors(capsys)) == 1
    assert main(["rating", "--chain", "08B-1", "--teeth", "19", "--speed", "1e-300 rpm"]) == 2
    out = capsys.readouterr()
    assert "inf" not in out.out and out.err.count("error:") == 1


def test_api_reproducers_refused():
    from chaindrive.conveyor import free_strand_minimum_tension
    from chaindrive.rating import chain_rating

    with pytest.raises(ChainDriveError, match="not a finite number"):
        chain_rating("16B", 50, 1e-300, power=0.09)  # was roller_bushing=inf
    with pytest.raises(InputError, match="free_strand_minimum_tension"):
        free_strand_minimum_tension(5e-324, 1.1, 1.1)  # was a raw ValueError of numpy
    with pytest.raises(InputError, match="inclination must not be NaN"):
        free_strand_minimum_tension(1.0, math.nan, 1.0)  # was inf
    # an ordinary case is unchanged (Shigley's 16B at 50 teeth: a finite rating)
    assert math.isfinite(chain_rating("16B", 50, 100.0).rated_power)


def test_fuzz_found_nonfinite_outputs():
    # first run of the enumerated API surface: NaN/inf passed through or came out
    from chaindrive.geometry.hub import bore_limits
    from chaindrive.kinematics.crawler import cam_force
    from chaindrive.simulation import SimGuide

    assert bore_limits(0.001) == (bore_limits(0.001)[0], 0.0)  # nothing fits: 0, not -inf
    with pytest.raises(InputError, match="must not be NaN|must be finite"):
        SimGuide(start=(math.nan, 0.0), end=(1.0, 0.0))
    with pytest.raises(ChainDriveError, match="cam_(force|stiffness): the result is not a finite number"):
        cam_force(245128.85438129873, 1.0, 5e-324, 22.556520920767674, 0.06950025862533617)


# --------------------------------------------------------------------------- limits


@pytest.mark.parametrize("command", ["layout", "analyze"])
def test_layout_link_limit_at_every_door(tmp_path, capsys, command):
    # reproducer: a 1e6 m centre distance (78,740,196 links) was accepted by layout and analyze
    text = (EXAMPLES / "roller_industrial.toml").read_text(encoding="utf-8")
    big = tmp_path / "big.toml"
    big.write_text(text.replace('position = ["1050 mm", "0 mm"]', 'position = ["1e6 m", "0 mm"]'), encoding="utf-8")
    argv = [command, str(big)] + (["-o", str(tmp_path / "out"), "-q", "--no-figures"] if command == "analyze" else [])
    assert main(argv) == 2
    err = _errors(capsys)
    assert len(err) == 1 and "needs 78,740,19" in err[0] and "at most 10,000" in err[0]
    assert not (tmp_path / "out").exists()


# --------------------------------------------------------------------------- messages


def _sr(tmp_path: Path, line: str) -> Path:
    text = (EXAMPLES / "self_regulating.toml").read_text(encoding="utf-8")
    assert 'weight = "30 N"' in text
    f = tmp_path / "sr.toml"
    f.write_text(text.replace('weight = "30 N"', line), encoding="utf-8")
    return f


@pytest.mark.parametrize(("line", "message"), [
    # reproducer: `sr.toml:41: sr.toml:41: ... e.g. weight = "5 mm" or "5 N"`
    ("weight = 30", r'^error: sr.toml:\d+: self_regulating.weight: give a unit, e.g. weight = "30 N" \(see'),
    ('weight = "30"', r"^error: sr.toml:\d+: self_regulating.weight: give a unit"),
])
def test_location_once_and_the_fields_own_unit(tmp_path, capsys, line, message):
    import re

    f = _sr(tmp_path, line)
    assert main(["analyze", str(f), "-o", str(tmp_path / "o"), "-q"]) == 2
    err = capsys.readouterr().err.strip()
    assert re.match(message, err), err
    assert err.count("sr.toml:") == 1 and " mm" not in err
    row = next(i for i, t in enumerate(f.read_text().splitlines(), 1) if t.startswith("weight ="))
    assert f"sr.toml:{row}:" in err


def test_tooth_strength_names_its_option(capsys):
    # reproducer: `tooth-strength --kt 0.5` said stress_concentration
    assert main(["tooth-strength", "--weight", "60 kN", "--pitch", "170 mm", "--teeth", "12", "--pin-radius",
                 "25 mm", "--tooth-width", "60 mm", "--hardness", "52", "--kt", "0.5"]) == 2
    err = capsys.readouterr().err
    assert "--kt must lie in [1, inf), got 0.5" in err and "stress_concentration" not in err


@pytest.mark.parametrize("value", ["1e300", "1e30", "-1e300", "19.5", "100000", "2"])
def test_teeth_bound_message(tmp_path, capsys, value):
    # reproducer: `teeth = 1e300` showed pydantic's "exceeded maximum size"
    text = (EXAMPLES / "roller_industrial.toml").read_text(encoding="utf-8").replace("teeth = 19", f"teeth = {value}", 1)
    f = tmp_path / "t.toml"
    f.write_text(text, encoding="utf-8")
    assert main(["layout", str(f)]) == 2
    err = capsys.readouterr().err.strip()
    assert err.endswith(f"wheels[0].teeth: must be a whole number in [3, 10000], got {float(value):g}"
                        if "." in value or "e" in value else
                        f"wheels[0].teeth: must be a whole number in [3, 10000], got {value}"), err
    assert "exceeded" not in err and len(err.splitlines()) == 1


def test_sprocket_warning_once(capsys):
    # reproducer: `sprocket --teeth 10000` printed one warning four times
    assert main(["sprocket", "--chain", "16B", "--teeth", "10000"]) == 0
    err = capsys.readouterr().err
    assert err.count("teeth above 150") == 1


# --------------------------------------------------------------------------- Ctrl-C


def _interrupt(argv: list[str], delay: float, tmp_path: Path) -> tuple[int, str]:
    env = {**os.environ, "PYTHONPATH": f"{SRC}{os.pathsep}{os.environ.get('PYTHONPATH', '')}", "MPLBACKEND": "Agg"}
    proc = subprocess.Popen([sys.executable, "-c", "import sys; sys.argv[0] = 'chaindrive'; "
                             "from chaindrive.cli import main; sys.exit(main())", *argv],
                            env=env, cwd=tmp_path, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    time.sleep(delay)
    proc.send_signal(signal.SIGINT)
    err = proc.communicate(timeout=120)[1]
    return proc.returncode, err


def _judge(code: int, err: str, delay: float) -> None:
    assert "Traceback" not in err, err
    if code == -signal.SIGINT:  # before the interpreter had started its own handling: no output at all
        assert delay < 0.3 and not err.strip(), (code, err)
        return
    assert code in (130, 0, 1), (code, err)
    if code == 130:
        last = [ln for ln in err.splitlines() if ln.strip()][-1]
        assert last.startswith("interrupted"), err
        assert sum(ln.startswith(("interrupted", "error", "internal")) for ln in err.splitlines()) == 1


def test_ctrl_c_during_analyze_one_line(tmp_path):
    # reproducer: Ctrl-C within ~0.2 s of starting `analyze` printed a traceback
    code, err = _interrupt(["analyze", str(EXAMPLES / "mining_conveyor.toml"), "-o", "out"], 0.5, tmp_path)
    _judge(code, err, 0.5)


@pytest.mark.slow
@pytest.mark.parametrize("delay", [0.1, 0.2, 0.35, 0.7, 1.2, 2.0, 3.5])
def test_ctrl_c_at_any_moment(tmp_path, delay):
    code, err = _interrupt(["analyze", str(EXAMPLES / "mining_conveyor.toml"), "-o", "out"], delay, tmp_path)
    done = (tmp_path / "out" / "results.json").is_file() and (tmp_path / "out" / ".chaindrive-run").is_file()
    if code == -signal.SIGINT and done:
        # the run had finished (its folder complete, moved into place) and the signal came while the
        # interpreter was exiting, after main() gave the handler back (seen on a loaded machine at 3.5 s)
        assert "Traceback" not in err, err
        return
    _judge(code, err, delay)
    if code == 130 and done:
        # the signal came after the folder was moved into place, while the last lines were
        # printed (seen in CI at 0.7 s): the one line says the results are complete
        assert "were complete before the interrupt" in err, err
        return
    assert not (tmp_path / "out").exists() or code in (0, 1)
    assert not [p for p in tmp_path.iterdir() if p.name.startswith(".out.")]  # no half-built folder left


@pytest.mark.slow
@pytest.mark.parametrize("delay", [0.5, 2.0, 4.0])
def test_ctrl_c_during_simulate(tmp_path, delay):
    code, err = _interrupt(["simulate", "--example", "roller", "--duration", "0.2 s", "-o", "out"], delay, tmp_path)
    lines = [ln for ln in err.splitlines() if ln.strip()]
    if code == -signal.SIGINT and lines and lines[-1].startswith("compiling the kernel"):
        # seen once, in a fresh clone's CI on a loaded machine (4 s, numba compiling the kernels
        # into an empty cache): the process ended by the signal itself, without a word and
        # without a traceback; not reproduced with a cold cache at 1-8 s. What must hold then:
        # nothing written, no half-built folder left
        assert "Traceback" not in err, err
        assert not (tmp_path / "out").exists()
        assert not [p for p in tmp_path.iterdir() if p.name.startswith(".out.")]
        return
    _judge(code, err, delay)


def test_interrupt_after_the_folder_was_moved_says_it_is_complete(monkeypatch, capsys):
    # a Ctrl-C while the command prints its last lines, after its run folder was moved into
    # place: the one line says the results there are complete (not "nothing was written")
    import chaindrive.cli as cli
    from chaindrive import _folders

    def interrupted_app(**kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr(_folders, "_COMPLETED", ["out"])
    monkeypatch.setattr(cli, "app", interrupted_app)
    assert cli._main(["analyze", "x.toml", "-o", "out"], False) == 130
    assert capsys.readouterr().err.strip() == "interrupted; the results in 'out' were complete before the interrupt"
    monkeypatch.setattr(_folders, "_COMPLETED", [])
    assert cli._main(["analyze", "x.toml", "-o", "out"], False) == 130
    assert capsys.readouterr().err.strip() == "interrupted"
