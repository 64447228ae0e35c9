"""Wide command-line tables wrap their cells instead of cutting words ("roller-bus…")."""

from __future__ import annotations


def test_select_table_never_truncates_a_word(capsys, monkeypatch):
    from rich.console import Console

    import chaindrive.cli.drive as drive_cli
    from chaindrive.cli import main

    monkeypatch.setattr(drive_cli, "_console", lambda: Console(width=100))
    assert main(["select", "--power", "7.5 kW", "--speed", "1450 rpm", "--ratio", "3",
                 "--centre-distance", "500 mm", "--service-factor", "1.0"]) == 0
    out = capsys.readouterr().out
    assert "…" not in out
    assert "link-plate" in out                          # the governing limit, whole
