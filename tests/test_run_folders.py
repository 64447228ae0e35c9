"""Run folders under races, links, kills and full disks (chaindrive._folders).

The reproducers of issue "Nothing lost under races, links, kills and stalled clients":
two processes racing into one folder, a file dropped into the folder mid-run, a link to
an earlier run, SIGKILL at random points then a rerun, a full disk, Ctrl-C. Each must end
refused or kept, with one clear line, nothing of the user's deleted, nothing stale.
"""

from __future__ import annotations

import errno
import json
import os
import random
import signal
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import pytest

from chaindrive._folders import (
    RUN_MARKER,
    atomic_output_dir,
    check_output_dir,
    claim_output_dir,
    clean_leftovers,
    folder_lock,
    show_path,
)
from chaindrive.cli import main
from chaindrive.errors import InputError

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "examples" / "roller_industrial.toml"
SRC = str(ROOT / "src")

posix_only = pytest.mark.skipif(sys.platform == "win32", reason="flock and SIGKILL are POSIX")


def _run(folder: Path, files: dict[str, str], force: bool = True) -> None:
    with atomic_output_dir(folder, force=force) as tmp:
        for name, text in files.items():
            (tmp / name).parent.mkdir(parents=True, exist_ok=True)
            (tmp / name).write_text(text)


def _listing(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.iterdir())


def _holder(folder: Path, what: str = "run") -> subprocess.Popen:
    """A second process holding the lock of ``folder`` until its stdin closes."""
    code = textwrap.dedent(f"""
        import sys
        from chaindrive._folders import folder_lock
        with folder_lock({str(folder)!r}, what={what!r}):
            print("held", flush=True)
            sys.stdin.read()
    """)
    env = dict(os.environ, PYTHONPATH=SRC)
    proc = subprocess.Popen([sys.executable, "-c", code], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                            env=env, text=True)
    assert proc.stdout is not None and proc.stdout.readline().strip() == "held"
    return proc


def _stop(proc: subprocess.Popen) -> None:
    assert proc.stdin is not None
    proc.stdin.close()
    proc.wait(timeout=30)


# --------------------------------------------------------------------------- races


@posix_only
def test_second_run_into_a_folder_in_use_is_refused(tmp_path, capsys):
    out = tmp_path / "run"
    proc = _holder(out)
    try:
        with pytest.raises(InputError, match=r"--output: the folder '.*run' is in use by another "
                                             r"chaindrive run \(process \d+\); wait until it finishes"):
            _run(out, {"a.txt": "x"})
        # the command line: refused at once, one line, exit 2
        assert main(["analyze", str(EXAMPLE), "-o", str(out), "-q"]) == 2
        err = capsys.readouterr().err.strip()
        assert len(err.splitlines()) == 1 and "is in use by another chaindrive run" in err
    finally:
        _stop(proc)
    assert not out.exists()  # the refused runs wrote nothing
    _run(out, {"a.txt": "x"})  # free again
    assert _listing(tmp_path) == ["run"]  # no lock file left


@posix_only
def test_lock_is_reentrant_in_one_process_and_removed(tmp_path):
    out = tmp_path / "sub" / "run"
    with folder_lock(out) as real, claim_output_dir(out, force=False):
        assert (real.parent / ".run.lock").is_file()
        _run(out, {"a.txt": "1"})
    assert _listing(tmp_path / "sub") == ["run"]
    with folder_lock(tmp_path / "new" / "deeper" / "run"):
        pass
    assert not (tmp_path / "new").exists()  # parents made for the lock alone are removed


@posix_only
def test_two_cli_runs_racing_into_one_folder(tmp_path):
    """Two `analyze` runs into one new folder at once: one runs, the other is refused."""
    env = dict(os.environ, PYTHONPATH=SRC, MPLBACKEND="Agg")
    cmd = [sys.executable, "-c", "import sys; from chaindrive.cli import main; sys.exit(main())", "analyze", str(EXAMPLE), "-o", str(tmp_path / "run"),
           "-q", "--no-figures"]
    first = subprocess.Popen(cmd, env=env, stderr=subprocess.PIPE, text=True)
    time.sleep(0.3)
    second = subprocess.run(cmd, env=env, stderr=subprocess.PIPE, text=True, timeout=300)
    first_err = first.communicate(timeout=300)[1]
    codes = sorted([first.returncode, second.returncode])
    refused = second.stderr if second.returncode == 2 else first_err
    assert codes in ([0, 2], [1, 2]), (codes, first_err, second.stderr)
    assert "is in use by another chaindrive run" in refused or "holds an earlier run" in refused
    assert _listing(tmp_path) == ["run"]
    assert (tmp_path / "run" / "results.json").is_file()


@posix_only
def test_second_study_into_a_folder_in_use_is_refused(tmp_path):
    from chaindrive.study.run import run_study
    from chaindrive.study.spec import load_study

    out = tmp_path / "study"
    proc = _holder(out, what="study")
    try:
        with pytest.raises(InputError, match=r"--output: the folder '.*study' is in use by another "
                                             r"chaindrive study \(process \d+\)"):
            run_study(load_study(ROOT / "examples" / "skew_study.toml"), out, workers=1, progress=False)
    finally:
        _stop(proc)
    assert not out.exists()


# --------------------------------------------------------------------------- the user's files


def test_file_dropped_into_the_folder_mid_run_is_kept(tmp_path):
    out = tmp_path / "run"
    with pytest.raises(InputError, match=r"--output: files chaindrive did not write appeared in '.*run' "
                                         r"during the run \(NOTES.txt\); nothing there was changed; the "
                                         r"new results are in '.*run.new'"):
        with atomic_output_dir(out) as tmp:
            (tmp / "results.json").write_text("{}")
            out.mkdir()
            (out / "NOTES.txt").write_text("n")  # the user, meanwhile
    assert _listing(out) == ["NOTES.txt"] and (out / "NOTES.txt").read_text() == "n"
    assert _listing(tmp_path / "run.new") == [RUN_MARKER, "results.json"]
    assert _listing(tmp_path) == ["run", "run.new"]  # nothing hidden left


def test_file_dropped_into_an_earlier_run_mid_run_is_kept(tmp_path):
    out = tmp_path / "run"
    _run(out, {"a.txt": "old"})
    with pytest.raises(InputError, match=r"files chaindrive did not write appeared .*\(mine.txt\).*"
                                         r"run.new'"):
        with atomic_output_dir(out, force=True) as tmp:
            (tmp / "a.txt").write_text("new")
            (out / "mine.txt").write_text("keep me")
    assert (out / "mine.txt").read_text() == "keep me" and (out / "a.txt").read_text() == "old"
    assert (tmp_path / "run.new" / "a.txt").read_text() == "new"
    # and from now on a --force run into it is refused before any work
    with pytest.raises(InputError, match=r"holds an earlier run and files chaindrive did not write "
                                         r"\(mine.txt\); chaindrive does not delete them"):
        check_output_dir(out, force=True)


def test_run_appearing_without_force_is_not_overwritten(tmp_path):
    out = tmp_path / "run"
    with pytest.raises(InputError, match="an earlier run appeared .*run.new'"):
        with atomic_output_dir(out) as tmp:
            (tmp / "b.txt").write_text("second")
            out.mkdir()
            (out / "a.txt").write_text("first")
            (out / RUN_MARKER).write_text(json.dumps({"files": ["a.txt"]}))
    assert (out / "a.txt").read_text() == "first"


def test_only_listed_files_are_replaced(tmp_path):
    out = tmp_path / "run"
    _run(out, {"a.txt": "1", "sub/b.txt": "2"})
    _run(out, {"c.txt": "3"})
    assert _listing(out) == [RUN_MARKER, "c.txt"]
    assert _listing(tmp_path) == ["run"]


# --------------------------------------------------------------------------- links


@posix_only
def test_symlinked_run_folder_goes_where_it_points(tmp_path, capsys):
    first = tmp_path / "first"
    _run(first, {"a.txt": "old"})
    link = tmp_path / "LINK"
    link.symlink_to("first")
    with pytest.raises(InputError, match="'.*LINK' holds an earlier run; use --force"):
        _run(link, {"a.txt": "new"}, force=False)
    _run(link, {"a.txt": "new"}, force=True)
    assert link.is_symlink() and (first / "a.txt").read_text() == "new"
    assert _listing(tmp_path) == ["LINK", "first"]  # no dangling .LINK.*.old, no partial
    dangling = tmp_path / "DANGLING"
    dangling.symlink_to("target")
    _run(dangling, {"x.txt": "x"})
    assert (tmp_path / "target" / "x.txt").read_text() == "x" and dangling.is_symlink()
    loop = tmp_path / "LOOP"
    loop.symlink_to("LOOP")
    with pytest.raises(InputError, match="--output: .*LOOP.* symbolic link loop"):
        _run(loop, {"x.txt": "x"})


# --------------------------------------------------------------------------- kills

_WRITER = textwrap.dedent("""
    import sys, time
    from chaindrive._folders import atomic_output_dir
    with atomic_output_dir(sys.argv[1], force=True) as tmp:
        for i in range(int(sys.argv[2])):
            (tmp / f"f{i}.txt").write_text(sys.argv[3] * 1000)
            time.sleep(0.002)
    print("done", flush=True)
""")


def _consistent(folder: Path) -> str:
    """The content tag of a complete run folder (every listed file there, all the same run)."""
    listed = json.loads((folder / RUN_MARKER).read_text())["files"]
    assert sorted(listed) == sorted(p.name for p in folder.iterdir() if p.name != RUN_MARKER)
    tags = {(folder / f).read_text()[0] for f in listed}
    assert len(tags) == 1
    return tags.pop()


@posix_only
@pytest.mark.parametrize("seed", range(8))
def test_sigkill_at_a_random_point_then_rerun(tmp_path, seed):
    out = tmp_path / "run"
    env = dict(os.environ, PYTHONPATH=SRC)
    subprocess.run([sys.executable, "-c", _WRITER, str(out), "5", "A"], env=env, check=True, timeout=60)
    (tmp_path / "mine.txt").write_text("the user's")
    proc = subprocess.Popen([sys.executable, "-c", _WRITER, str(out), "60", "B"], env=env,
                            stdout=subprocess.PIPE, text=True)
    time.sleep(random.Random(seed).uniform(0.05, 1.0))
    proc.send_signal(signal.SIGKILL)
    proc.wait(timeout=30)
    # killed anywhere: the folder holds one whole run (the earlier or the new one), or,
    # killed between the two renames, the earlier run waits beside it to be put back
    if out.exists():
        assert _consistent(out) in "AB"
    subprocess.run([sys.executable, "-c", _WRITER, str(out), "3", "C"], env=env, check=True, timeout=60)
    assert _consistent(out) == "C"
    assert _listing(tmp_path) == ["mine.txt", "run"]  # no .run.*.partial, .old or .lock left


def test_earlier_run_moved_aside_by_a_killed_run_is_put_back(tmp_path):
    out = tmp_path / "run"
    _run(out, {"a.txt": "A"})
    os.rename(out, tmp_path / ".run.abcd1234.old")  # killed between the two renames
    (tmp_path / ".run.efgh5678.partial").mkdir()
    (tmp_path / ".run.x.abcd1234.partial").mkdir()  # another folder's ("run.x"): not touched
    with folder_lock(out) as real:
        clean_leftovers(real)
    assert _listing(tmp_path) == [".run.x.abcd1234.partial", "run"]
    assert (out / "a.txt").read_text() == "A"
    with pytest.raises(InputError, match="holds an earlier run; use --force"):
        _run(out, {"b.txt": "B"}, force=False)


# --------------------------------------------------------------------------- full disk, Ctrl-C


def test_disk_full_names_the_file_and_what_is_kept(tmp_path, monkeypatch):
    out = tmp_path / "run"
    _run(out, {"a.txt": "A"})

    def full(*args, **kwargs):
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    with pytest.raises(InputError, match=r"^--output: cannot write '.*run/b.png': No space left on device; "
                                         r"nothing was written; the files in '.*run' are from an earlier "
                                         r"run and were left unchanged$"):
        with atomic_output_dir(out, force=True) as tmp:
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), str(tmp / "b.png"))
    assert (out / "a.txt").read_text() == "A" and _listing(tmp_path) == ["run"]
    from chaindrive._io import atomic_write_bytes

    monkeypatch.setattr(os, "fsync", full)
    with pytest.raises(InputError, match=r"--svg: cannot write '.*a.txt': No space left on device; "
                                         r"'.*a.txt' was left unchanged"):
        atomic_write_bytes(out / "a.txt", b"new", force=True, option="--svg")
    assert (out / "a.txt").read_text() == "A"


def _tiny_tmpfs(path: Path) -> bool:
    if sys.platform != "linux" or os.geteuid() != 0:
        return False
    path.mkdir()
    r = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=256k", "tmpfs", str(path)],
                       capture_output=True, timeout=30)
    return r.returncode == 0


def test_disk_full_on_a_tiny_tmpfs(tmp_path):
    disk = tmp_path / "disk"
    if not _tiny_tmpfs(disk):
        pytest.skip("cannot mount a tmpfs here (not root, or not allowed)")
    try:
        out = disk / "run"
        _run(out, {"a.txt": "A"})
        with pytest.raises(InputError, match=r"^--output: cannot write the results into '.*run': No space "
                                             r"left on device; nothing was written; the files in '.*run' are from "
                                             r"an earlier run and were left unchanged$"):
            with atomic_output_dir(out, force=True) as tmp:
                (tmp / "big.bin").write_bytes(b"\0" * 1_000_000)
        assert (out / "a.txt").read_text() == "A" and _listing(disk) == ["run"]
    finally:
        subprocess.run(["umount", str(disk)], capture_output=True, timeout=30)


def test_ctrl_c_says_what_is_kept(tmp_path, monkeypatch, capsys):
    out = tmp_path / "run"
    _run(out, {"a.txt": "A"})
    import chaindrive.workflows.analyze as workflow

    def interrupted(*args, **kwargs):  # Ctrl-C in the middle of the analysis
        os.kill(os.getpid(), signal.SIGINT)
        time.sleep(5)

    monkeypatch.setattr(workflow, "analyze", interrupted)
    assert main(["analyze", str(EXAMPLE), "-o", str(out), "--force", "-q"]) == 130
    err = capsys.readouterr().err.strip().splitlines()[-1]
    assert err == (f"interrupted; nothing was written; the files in {show_path(out)} are from an "
                   "earlier run and were left unchanged")
    assert main(["analyze", str(EXAMPLE), "-o", str(tmp_path / "new"), "-q"]) == 130
    err = capsys.readouterr().err.strip().splitlines()[-1]
    assert err == f"interrupted; nothing was written to {show_path(tmp_path / 'new')}"
    assert _listing(tmp_path) == ["run"]


def test_long_plot_name_names_the_option(tmp_path, capsys):
    from chaindrive._io import check_output_path

    name = "p" * 300 + ".png"
    with pytest.raises(InputError, match=r"^--plot: the file name 'p{60}\.\.\.p+\.png' is 304 bytes long; "
                                         r"file names have at most 250 bytes$"):
        check_output_path(tmp_path / name, (".png",), option="--plot")
    long_ok = tmp_path / ("q" * 245 + ".png")  # its temporary name is shortened
    from chaindrive._io import atomic_write_bytes

    assert atomic_write_bytes(long_ok, b"x").read_bytes() == b"x"
