"""--force deletes only what chaindrive wrote and what is unchanged since; the final swap is
atomic (issue 34, items 2 and 7)."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from _shared import EXAMPLES
from chaindrive import _folders
from chaindrive._folders import RUN_MARKER, atomic_output_dir, exchange
from chaindrive.cli import main
from chaindrive.errors import InputError

SRC = Path(__file__).resolve().parents[1] / "src"


def _run(folder: Path, files: dict[str, str], force: bool = False, **kw) -> None:
    with atomic_output_dir(folder, force=force, **kw) as tmp:
        for name, text in files.items():
            (tmp / name).parent.mkdir(parents=True, exist_ok=True)
            (tmp / name).write_text(text)


def test_marker_holds_the_content_hashes(tmp_path):
    _run(tmp_path / "r", {"a.txt": "one", "sub/b.txt": "two"})
    marker = json.loads((tmp_path / "r" / RUN_MARKER).read_text())
    assert marker["files"] == ["a.txt", "sub/b.txt"]
    # sha256("one"), computed independently with hashlib's reference implementation
    assert marker["sha256"]["a.txt"] == "7692c3ad3540bb803c020b3aee66cd8887123234ea0c6e7143c0add73ff431ed"


def test_force_refuses_an_edited_file(tmp_path):
    # reproducer: text appended to a file chaindrive wrote was deleted silently by --force
    out = tmp_path / "r"
    _run(out, {"proposal.toml": "x = 1\n", "report.html": "<html>"})
    with open(out / "proposal.toml", "a") as fh:
        fh.write("# my edit\n")
    with pytest.raises(InputError, match=r"files changed since chaindrive wrote them \(proposal.toml\); "
                                         r"chaindrive does not delete them"):
        _run(out, {"report.html": "new"}, force=True)
    assert (out / "proposal.toml").read_text() == "x = 1\n# my edit\n"
    assert (out / "report.html").read_text() == "<html>"


def test_force_replaces_an_unchanged_run(tmp_path):
    out = tmp_path / "r"
    _run(out, {"a.txt": "one"})
    _run(out, {"b.txt": "two"}, force=True)
    assert sorted(p.name for p in out.iterdir()) == [RUN_MARKER, "b.txt"]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["r"]  # nothing left beside


def test_force_never_deletes_the_input(tmp_path, capsys):
    # reproducer: `analyze pr/proposal.toml -o pr --force` deleted pr/proposal.toml, its input
    out = tmp_path / "pr"
    # a run folder holding a project file chaindrive wrote (as analyze writes proposal.toml)
    _run(out, {"proposal.toml": (EXAMPLES / "mining_conveyor.toml").read_text(encoding="utf-8")})
    proposal = out / "proposal.toml"
    before = proposal.read_bytes()
    assert main(["analyze", str(proposal), "-o", str(out), "--force", "-q", "--no-figures"]) == 2
    err = capsys.readouterr().err
    assert f"holds the input file {str(proposal)!r}" in err
    assert sum(ln.startswith(("error", "internal error")) for ln in err.splitlines()) == 1
    assert proposal.read_bytes() == before
    # an input outside the folder: --force works
    assert main(["analyze", str(EXAMPLES / "mining_conveyor.toml"), "-o", str(out), "--force", "-q",
                 "--no-figures"]) in (0, 1)


def test_input_protected_at_the_library_level(tmp_path):
    out = tmp_path / "r"
    _run(out, {"in.toml": "a"})
    with pytest.raises(InputError, match="holds the input file"):
        _run(out, {"x": "y"}, force=True, inputs=(out / "in.toml",))


def test_swap_without_the_atomic_exchange(tmp_path, monkeypatch):
    monkeypatch.setattr(_folders, "exchange", lambda a, b: False)
    out = tmp_path / "r"
    _run(out, {"a.txt": "one"})
    _run(out, {"b.txt": "two"}, force=True)
    assert sorted(p.name for p in out.iterdir()) == [RUN_MARKER, "b.txt"]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["r"]


def test_exchange_swaps_two_folders(tmp_path):
    a, b = tmp_path / "a", tmp_path / "b"
    a.mkdir()
    b.mkdir()
    (a / "x").write_text("a")
    (b / "y").write_text("b")
    if not exchange(a, b):
        pytest.skip("no renameat2(RENAME_EXCHANGE) here")
    assert (a / "y").exists() and (b / "x").exists()


KILLER = textwrap.dedent("""
    import os, signal, sys
    from chaindrive import _folders
    point, folder, atomic = sys.argv[1], sys.argv[2], sys.argv[3] == "1"
    if not atomic:
        _folders.exchange = lambda a, b: False
    def die(*args, **kwargs):
        os.kill(os.getpid(), signal.SIGKILL)
    real_rename = os.rename
    if point == "before-swap":
        _folders.exchange = die
        if not atomic:
            _folders.os.rename = lambda a, b: die() if str(a) == os.path.realpath(folder) else real_rename(a, b)
    elif point == "after-swap":
        _folders._remove_run = die
    elif point == "between-renames":
        _folders.os.rename = lambda a, b: die() if str(a).endswith(".partial") else real_rename(a, b)
    with _folders.atomic_output_dir(folder, force=True) as tmp:
        (tmp / "new.txt").write_text("new")
""")


def _complete(folder: Path) -> str:
    names = sorted(p.name for p in folder.iterdir())
    assert RUN_MARKER in names
    listed = json.loads((folder / RUN_MARKER).read_text())["files"]
    assert sorted(listed) == sorted(n for n in names if n != RUN_MARKER)
    return "old" if "old.txt" in names else "new"


@pytest.mark.parametrize(("point", "atomic"), [("before-swap", True), ("after-swap", True),
                                               ("before-swap", False), ("between-renames", False),
                                               ("after-swap", False)])
def test_sigkill_in_the_swap_leaves_a_complete_folder(tmp_path, point, atomic):
    # reproducer: SIGKILL inside the final folder swap left no DIR until the next run
    out = tmp_path / "r"
    _run(out, {"old.txt": "old"})
    env = {**os.environ, "PYTHONPATH": f"{SRC}{os.pathsep}{os.environ.get('PYTHONPATH', '')}"}
    proc = subprocess.run([sys.executable, "-c", KILLER, point, str(out), "1" if atomic else "0"],
                          env=env, capture_output=True, text=True, timeout=120)
    assert proc.returncode == -signal.SIGKILL, proc.stderr
    if point != "between-renames":  # the atomic exchange: DIR complete at once
        assert _complete(out) == ("old" if point == "before-swap" else "new")
    else:  # the fallback's window: DIR renamed aside; a reader recovers it at once
        from chaindrive._io import read_text_file

        assert read_text_file(out / "old.txt", what="file") == "old"
        assert _complete(out) == "old"
    _run(out, {"third.txt": "3"}, force=True)  # the next run cleans what the killed one left
    assert sorted(p.name for p in tmp_path.iterdir()) == ["r"]
    assert _complete(out) == "new" or (out / "third.txt").exists()
