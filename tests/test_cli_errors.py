"""The command line's front doors: every reproducer of the tracebacks issue gives one clear
line and exit code 2; internal errors are one line and exit code 3 (--debug shows the
traceback); run folders are never overwritten silently or left looking current."""

from __future__ import annotations

import pytest

from _shared import EXAMPLES
from chaindrive.cli import main

ROLLER = EXAMPLES / "roller_industrial.toml"


PROGRESS = ("warning:", "assembling the model", "compiling the kernel")


def _error_lines(err: str) -> list[str]:
    return [ln for ln in err.splitlines() if ln.strip() and not ln.startswith(PROGRESS)]


def run(capsys, argv):
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


def one_line(capsys, argv, pattern: str, code: int = 2) -> str:
    got, out, err = run(capsys, argv)
    lines = _error_lines(err)
    assert got == code, (argv, got, err)
    assert "Traceback" not in err and "Traceback" not in out
    assert len(lines) == 1, lines
    import re

    assert re.search(pattern, lines[0]), lines[0]
    return lines[0]


# --------------------------------------------------------------------------- output paths


def test_svg_to_a_directory(capsys, tmp_path):
    one_line(capsys, ["sprocket", "--chain", "16B", "--teeth", "19", "--svg", "/"],
             r"^error: --svg: '/' is a folder; give a file name ending in \.svg$")


def test_plot_with_unsupported_extension_refused_before_work(capsys, tmp_path):
    one_line(capsys, ["crawler", "--pitch", "100 mm", "--teeth", "8", "--speed", "30 rpm", "--plot",
                      tmp_path / "out.dxf"], r"--plot: unsupported file type '\.dxf' .* use one of \.png, \.svg, \.pdf")
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(("option", "name", "pattern"), [
    ("--dxf", "missing/s.dxf", "does not exist"),
    ("--svg", "s.png", r"unsupported file type '\.png'"),
    ("--dxf", "", "is a folder"),  # typer reads an empty path as "."
])
def test_geometry_output_paths(capsys, tmp_path, option, name, pattern):
    path = tmp_path / name if name else ""
    one_line(capsys, ["pocket-wheel", "--chain", "18x64", "--teeth", "8", option, path], pattern)


def test_geometry_outputs_written_atomically(capsys, tmp_path):
    dxf, svg = tmp_path / "s.dxf", tmp_path / "s.svg"
    code, out, _ = run(capsys, ["sprocket", "--chain", "16B", "--teeth", "19", "--dxf", dxf, "--svg", svg])
    assert code == 0 and f"wrote {dxf}" in out
    assert svg.read_text().startswith("<?xml") and b"SECTION" in dxf.read_bytes()[:100]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["s.dxf", "s.svg"]  # no temporary files left


def test_analyze_output_is_a_file(capsys, tmp_path):
    f = tmp_path / "f"
    f.write_text("mine")
    one_line(capsys, ["analyze", ROLLER, "-o", f, "--no-figures", "-q"], r"--output: .* is a file; give a folder")
    assert f.read_text() == "mine"


def test_new_refuses_a_directory_and_an_existing_file(capsys, tmp_path):
    d = tmp_path / "SOME_DIR"
    d.mkdir()
    one_line(capsys, ["new", d, "--force"], r"FILE: .*SOME_DIR' is a folder")
    f = tmp_path / "drive.toml"
    assert run(capsys, ["new", f])[0] == 0
    text = f.read_text()
    one_line(capsys, ["new", f, "--kind", "mining"], r"FILE: .*drive\.toml' exists; use --force to overwrite it")
    assert f.read_text() == text
    assert run(capsys, ["new", f, "--kind", "mining", "--force"])[0] == 0
    assert f.read_text() != text


# --------------------------------------------------------------------------- project files


@pytest.mark.parametrize("command", ["layout", "analyze", "simulate"])
def test_binary_project(capsys, tmp_path, command):
    f = tmp_path / "p.toml"
    f.write_bytes(bytes(range(256)) * 4)
    extra = ["-o", tmp_path / "o"] if command in ("analyze", "simulate") else []
    one_line(capsys, [command, f, *extra], r"project file .* is a binary file, not a TOML text file")


@pytest.mark.parametrize("command", ["layout", "analyze", "simulate"])
def test_deeply_nested_project(capsys, tmp_path, command):
    f = tmp_path / "deep.toml"
    f.write_text("a = " + "[" * 5000 + "]" * 5000 + "\n")  # tomllib alone: RecursionError
    extra = ["-o", tmp_path / "o"] if command in ("analyze", "simulate") else []
    one_line(capsys, [command, f, *extra], r"nested 5000 deep; a project file nests at most 32 deep")


def test_not_utf8_missing_and_directory(capsys, tmp_path):
    f = tmp_path / "latin1.toml"
    f.write_bytes('[drive]\nname = "Förderer"\n'.encode("latin-1"))
    one_line(capsys, ["layout", f], r"is not UTF-8 text \(byte 0xf6 at offset \d+\); save it as UTF-8")
    one_line(capsys, ["layout", tmp_path / "nope.toml"], r"project file .*nope\.toml' does not exist")
    one_line(capsys, ["layout", tmp_path], r"is a folder; give a TOML file")


def test_too_many_errors_capped(capsys, tmp_path):
    from chaindrive.drive.project import template

    f = tmp_path / "many.toml"
    f.write_text(template("roller") + "\n[[wheels]]\nteeth = -1\n" * 40_000)  # < 1 MiB
    code, out, err = run(capsys, ["layout", f])
    assert code == 2 and "Traceback" not in err
    lines = _error_lines(err)
    assert len(lines) <= 22, len(lines)  # 20 errors, "... and N more" (was 150,000 lines)
    assert lines[-1].startswith("... and ") and lines[-1].endswith(" more")


# --------------------------------------------------------------------------- NaN/inf


def test_gamma_1e300_refused_with_its_range(capsys):
    one_line(capsys, ["contact", "--chain", "16B", "--load", "5 kN", "--skew", "50 arcmin", "--gamma", "1e300"],
             r"gamma must lie in \[0, 0\.01\] 1/arcmin\^2")


# --------------------------------------------------------------------------- run folders


def test_analyze_run_folder_policy(capsys, tmp_path):
    out = tmp_path / "run"
    assert run(capsys, ["analyze", ROLLER, "-o", out, "--no-figures", "-q"])[0] == 0
    first = (out / "results.json").read_text()
    assert (out / ".chaindrive-run").exists() and (out / "report.html").exists()
    # an earlier run is not overwritten without --force (refused before any work)
    one_line(capsys, ["analyze", ROLLER, "-o", out, "--no-figures", "-q"],
             r"--output: .* holds an earlier run; use --force to replace it")
    # a failed run leaves the earlier results, and says they are from the earlier run
    from chaindrive.drive.project import template

    bad = tmp_path / "bad.toml"
    text = template("roller")
    line = next(ln for ln in text.splitlines() if ln.startswith("speed"))
    bad.write_text(text.replace(line, 'speed = "-5 rpm"'))
    line = one_line(capsys, ["analyze", bad, "-o", out, "--force", "--no-figures", "-q"], "error")
    assert (out / "results.json").read_text() == first
    assert "speed must be positive" in line and "are from an earlier run and were left unchanged" in line
    # with --force a good run replaces the whole folder
    assert run(capsys, ["analyze", ROLLER, "-o", out, "--force", "--no-figures", "-q"])[0] == 0
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad.toml", "run"]  # no partial folders


def test_analyze_failure_inside_the_run_keeps_earlier_results(capsys, tmp_path, monkeypatch):
    out = tmp_path / "run"
    assert run(capsys, ["analyze", ROLLER, "-o", out, "--no-figures", "-q"])[0] == 0
    before = sorted(p.name for p in out.iterdir())
    import chaindrive.workflows.analyze as wa

    def broken(*args, **kwargs):
        from chaindrive.errors import InfeasibleError

        raise InfeasibleError("the drive cannot be analysed")

    monkeypatch.setattr(wa, "analyze", broken)
    line = one_line(capsys, ["analyze", ROLLER, "-o", out, "--force", "--no-figures", "-q"],
                    r"the drive cannot be analysed; nothing was written; the files in .* are from an earlier run")
    assert "earlier run" in line
    assert sorted(p.name for p in out.iterdir()) == before


def test_analyze_refuses_a_folder_of_other_files(capsys, tmp_path):
    (tmp_path / "photo.png").write_bytes(b"x")
    one_line(capsys, ["analyze", ROLLER, "-o", tmp_path, "--force", "--no-figures", "-q"],
             r"not empty and was not written by chaindrive")
    assert (tmp_path / "photo.png").exists()


def test_simulate_speaks_in_its_first_second(capsys, tmp_path):
    code, out, err = run(capsys, ["simulate", "--example", "bike", "-o", tmp_path / "s"])
    assert code == 2
    assert err.splitlines()[0] == "assembling the model..."


# --------------------------------------------------------------------------- internal errors


def test_internal_error_one_line_exit_3(capsys, monkeypatch):
    import chaindrive.geometry.sprocket as sp

    def boom(*args, **kwargs):
        raise ZeroDivisionError("float division by zero")

    monkeypatch.setattr(sp.Sprocket, "dimensions", boom)
    line = one_line(capsys, ["sprocket", "--chain", "16B", "--teeth", "19"],
                    r"^internal error: ZeroDivisionError: float division by zero; run with --debug for the traceback$",
                    code=3)
    assert line
    code, out, err = run(capsys, ["--debug", "sprocket", "--chain", "16B", "--teeth", "19"])
    assert code == 3 and "Traceback (most recent call last)" in err
    code, out, err = run(capsys, ["sprocket", "--chain", "16B", "--teeth", "19", "--debug"])
    assert code == 3 and "Traceback (most recent call last)" in err


def test_debug_is_accepted_and_harmless(capsys):
    code, out, err = run(capsys, ["--debug", "version"])
    assert code == 0 and out.strip()


def test_os_error_on_input_is_exit_2(capsys, monkeypatch):
    import chaindrive.geometry.sprocket as sp

    def denied(*args, **kwargs):
        raise PermissionError(13, "Permission denied", "/root/x")

    monkeypatch.setattr(sp.Sprocket, "dimensions", denied)
    one_line(capsys, ["sprocket", "--chain", "16B", "--teeth", "19"], r"^error: Permission denied: '/root/x'$")


def test_simulate_error_names_the_earlier_run(capsys, tmp_path):
    out = tmp_path / "sim"
    out.mkdir()
    (out / ".chaindrive-run").write_text("{}")
    (out / "simulation.json").write_text("{}")
    line = one_line(capsys, ["simulate", "--example", "roller", "--speed", "-5 rad/s", "-o", out, "--force"],
                    r"are from an earlier run and were left unchanged")
    assert "speed" in line and (out / "simulation.json").read_text() == "{}"


@pytest.mark.parametrize("argv", [
    ["track-wheel", "--pitch", "1e300 m", "--teeth", "40", "--pin-radius", "256 mm", "--json"],
    ["crawler", "--teeth", "150", "--speed", "1e300 rpm", "--chain", "08A", "--sprocket-distance", "64 mm"],
])
def test_overflow_is_one_line_exit_2(capsys, argv):
    # first full `make fuzz` run: these gave "internal error: OverflowError" (exit 3)
    one_line(capsys, argv, r"^error: .*overflow")
