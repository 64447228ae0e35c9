"""The CLI's shell: help, demo, error handling."""


import pytest

from chaindrive.cli import main


def test_help_lists_commands(capsys):
    assert main(["--help"]) == 0
    out = capsys.readouterr().out
    assert "demo" in out


@pytest.mark.slow
def test_demo_writes_output(tmp_path, capsys):
    assert main(["demo", "--output", str(tmp_path)]) == 0
    assert "results written to" in capsys.readouterr().out
    assert (tmp_path / "summary.json").exists()
    assert (tmp_path / "kinematics_dolipinski_exact.png").stat().st_size > 10000


def test_unknown_command_is_exit_2(capsys):
    assert main(["no-such-command"]) == 2


def test_warnings_are_one_line_on_stderr(capsys):
    # a skew beyond the measured range of Garshniev & Maksymovych warns; the CLI prints it as one line
    assert main(["contact", "--chain", "16B", "--load", "5 kN", "--skew", "5 deg"]) == 0
    err = capsys.readouterr().err
    assert "warning: max_skew" in err
    assert "Traceback" not in err and ".py:" not in err
