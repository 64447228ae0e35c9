"""Safe output files and folders, and the project-file reader (chaindrive._io)."""

from __future__ import annotations

import os
import stat
import sys

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from chaindrive._io import (
    RUN_MARKER,
    atomic_output_dir,
    atomic_write_bytes,
    atomic_write_text,
    cap_lines,
    check_output_dir,
    check_output_path,
    load_toml_text,
    read_text_file,
    save_figure,
    toml_nesting,
)
from chaindrive.errors import InputError

root_only = pytest.mark.skipif(
    sys.platform == "win32" or (hasattr(os, "geteuid") and os.geteuid() == 0),
    reason="permission bits do not bind root (or Windows)",
)


# --------------------------------------------------------------------------- single files


def test_atomic_write_creates_and_refuses_existing(tmp_path):
    f = tmp_path / "a.txt"
    assert atomic_write_text(f, "one").read_text() == "one"
    with pytest.raises(InputError, match=r"--x: .*a\.txt' exists; use --force"):
        atomic_write_text(f, "two", option="--x")
    assert f.read_text() == "one"
    atomic_write_text(f, "two", force=True)
    assert f.read_text() == "two"
    # no temporary files left behind
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.txt"]


def test_atomic_write_keeps_mode_of_replaced_file(tmp_path):
    f = tmp_path / "a.txt"
    f.write_text("x")
    os.chmod(f, 0o640)
    atomic_write_bytes(f, b"y", force=True)
    assert stat.S_IMODE(f.stat().st_mode) == 0o640


def test_atomic_write_new_file_follows_umask(tmp_path):
    mask = os.umask(0o022)
    try:
        f = atomic_write_bytes(tmp_path / "b.bin", b"1")
    finally:
        os.umask(mask)
    assert stat.S_IMODE(f.stat().st_mode) == 0o644


@pytest.mark.parametrize(
    ("name", "pattern"),
    [
        ("", "empty file name"),
        ("sub/", "is a folder"),
        ("missing/a.svg", "does not exist"),
        ("a.dxf", r"unsupported file type '\.dxf' of 'a\.dxf'; use one of \.png, \.svg"),
        ("noext", "file name without an extension"),
    ],
)
def test_check_output_path_errors(tmp_path, name, pattern):
    (tmp_path / "sub").mkdir()
    path = "" if name == "" else str(tmp_path / name) + ("/" if name.endswith("/") else "")
    with pytest.raises(InputError, match=pattern):
        check_output_path(path, (".png", ".svg"), option="--plot")


def test_check_output_path_directory_and_parent_file(tmp_path):
    with pytest.raises(InputError, match="--svg: .* is a folder"):
        check_output_path(tmp_path, (".svg",), option="--svg")
    (tmp_path / "f").write_text("x")
    with pytest.raises(InputError, match="is not a folder"):
        check_output_path(tmp_path / "f" / "a.svg", (".svg",), option="--svg")
    assert check_output_path(tmp_path / "A.SVG", (".svg",), option="--svg").name == "A.SVG"


def test_check_output_path_existing_needs_force(tmp_path):
    f = tmp_path / "a.png"
    f.write_bytes(b"x")
    with pytest.raises(InputError, match="exists; use --force"):
        check_output_path(f, (".png",), force=False)
    assert check_output_path(f, (".png",), force=True) == f


@root_only
def test_unwritable_folder(tmp_path):
    ro = tmp_path / "ro"
    ro.mkdir()
    os.chmod(ro, 0o500)
    try:
        with pytest.raises(InputError, match="no permission to write"):
            atomic_write_text(ro / "a.txt", "x")
        with pytest.raises(InputError, match="no permission"):
            check_output_dir(ro / "run", force=False)
    finally:
        os.chmod(ro, 0o700)


@pytest.mark.slow
def test_save_figure_formats(tmp_path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots()
    ax.plot([0, 1], [0, 1])
    try:
        assert save_figure(fig, tmp_path / "a.png").read_bytes()[:4] == b"\x89PNG"
        assert b"<svg" in save_figure(fig, tmp_path / "a.svg").read_bytes()[:400]
        assert save_figure(fig, tmp_path / "a.pdf").read_bytes()[:4] == b"%PDF"
        with pytest.raises(InputError, match=r"--plot: unsupported file type '\.dxf'"):
            save_figure(fig, tmp_path / "a.dxf")
    finally:
        plt.close(fig)


# --------------------------------------------------------------------------- run folders


def test_output_dir_new_then_force(tmp_path):
    out = tmp_path / "run"
    with atomic_output_dir(out) as tmp:
        assert tmp != out and tmp.parent == out.resolve().parent
        (tmp / "report.html").write_text("first")
    assert (out / RUN_MARKER).exists() and (out / "report.html").read_text() == "first"
    with pytest.raises(InputError, match="holds an earlier run; use --force"):
        check_output_dir(out, force=False)
    with pytest.raises(InputError, match="holds an earlier run"), atomic_output_dir(out):
        pass  # pragma: no cover - refused before the body
    with atomic_output_dir(out, force=True) as tmp:
        (tmp / "results.json").write_text("{}")
    # the earlier run is replaced as a whole: no stale report.html
    assert sorted(p.name for p in out.iterdir()) == [RUN_MARKER, "results.json"]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["run"]  # no partial/old folders left


def test_output_dir_failure_keeps_earlier_run_and_says_so(tmp_path):
    out = tmp_path / "run"
    with atomic_output_dir(out) as tmp:
        (tmp / "report.html").write_text("first")
    with pytest.raises(InputError, match=r"bad value; nothing was written; the files in .* are from an earlier run"):
        with atomic_output_dir(out, force=True) as tmp:
            (tmp / "report.html").write_text("half")
            raise InputError("bad value")
    assert (out / "report.html").read_text() == "first"
    with pytest.raises(ZeroDivisionError) as info:
        with atomic_output_dir(out, force=True):
            1 / 0  # noqa: B018
    assert "earlier run" in " ".join(info.value.__notes__)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["run"]


def test_output_dir_failure_without_earlier_run_leaves_nothing(tmp_path):
    out = tmp_path / "new"
    with pytest.raises(InputError, match="^oops$"), atomic_output_dir(out):
        raise InputError("oops")
    assert not out.exists() and list(tmp_path.iterdir()) == []


def test_output_dir_refuses_foreign_folder_and_file(tmp_path):
    (tmp_path / "mine.txt").write_text("keep")
    with pytest.raises(InputError, match="not written by chaindrive"):
        check_output_dir(tmp_path, force=True)
    f = tmp_path / "mine.txt"
    with pytest.raises(InputError, match="is a file; give a folder"):
        check_output_dir(f, force=True)
    with pytest.raises(InputError, match="empty folder name"):
        check_output_dir("", force=True)
    with pytest.raises(InputError, match="is a file, so the folder"):
        check_output_dir(f / "sub" / "run", force=False)
    assert f.read_text() == "keep"


def test_output_dir_empty_existing_and_nested_parent(tmp_path):
    (tmp_path / "empty").mkdir()
    with atomic_output_dir(tmp_path / "empty") as tmp:
        (tmp / "a.json").write_text("{}")
    assert (tmp_path / "empty" / "a.json").exists()
    with atomic_output_dir(tmp_path / "x" / "y" / "run") as tmp:
        (tmp / "a.json").write_text("{}")
    assert (tmp_path / "x" / "y" / "run" / "a.json").exists()


# --------------------------------------------------------------------------- reading


@pytest.mark.parametrize(
    ("content", "pattern"),
    [
        (b"\x89PNG\r\n\x1a\n\x00\x00\x00", "is a binary file"),
        (b"name = \"caf\xe9\"\n", r"is not UTF-8 text \(byte 0xe9 at offset 11\)"),
        (b"x" * (1 << 20) + b"y", "larger than 1024 KiB"),
    ],
)
def test_read_text_file_refusals(tmp_path, content, pattern):
    f = tmp_path / "p.toml"
    f.write_bytes(content)
    with pytest.raises(InputError, match=pattern):
        read_text_file(f)


def test_read_text_file_missing_folder_bom(tmp_path):
    with pytest.raises(InputError, match="project file .* does not exist"):
        read_text_file(tmp_path / "nope.toml")
    with pytest.raises(InputError, match="is a folder; give a TOML file"):
        read_text_file(tmp_path)
    with pytest.raises(InputError, match="empty file name"):
        read_text_file("")
    f = tmp_path / "bom.toml"
    f.write_bytes("\ufeffa = 1\n".encode())
    assert read_text_file(f) == "a = 1\n"


def test_deep_nesting_refused_before_parsing():
    # 5,000-deep array: tomllib alone raises RecursionError (the reported crash)
    with pytest.raises(InputError, match="nested 5000 deep; a project file nests at most 32"):
        load_toml_text("a = " + "[" * 5000 + "]" * 5000)
    with pytest.raises(InputError, match="nested 40 deep"):
        load_toml_text("a = " + "{b = " * 40 + "1" + "}" * 40)
    with pytest.raises(InputError, match="nested more than 32 deep"):
        load_toml_text("a" + ".a" * 60 + " = 1")
    data = load_toml_text("a = " + "[" * 32 + "]" * 32)  # the limit itself is accepted
    depth, x = 0, data["a"]
    while isinstance(x, list) and x:
        depth, x = depth + 1, x[0]
    assert depth == 31  # the innermost array is empty


def test_syntax_error_is_one_line():
    with pytest.raises(InputError, match=r"f\.toml: TOML syntax error: .*line 1"):
        load_toml_text("a = = 1", "f.toml")


def test_brackets_in_strings_and_comments_do_not_count():
    assert toml_nesting('a = "[[[[" # ]]]]\nb = \'{{{\'\nc = """\n[[[\n"""') == 0
    assert toml_nesting("") == 0


@settings(max_examples=60, deadline=None)
@given(st.integers(1, 60))
def test_nesting_scan_matches_structure(depth):
    text = "a = " + "[" * depth + "]" * depth
    assert toml_nesting(text) == depth
    if depth <= 32:
        load_toml_text(text)
    else:
        with pytest.raises(InputError, match=f"nested {depth} deep"):
            load_toml_text(text)


def test_cap_lines():
    assert cap_lines(["a"] * 3, 20) == ["a"] * 3
    capped = cap_lines([str(i) for i in range(50_000)], 20)
    assert len(capped) == 21 and capped[-1] == "... and 49980 more"


def test_run_folder_mode_follows_umask(tmp_path):
    mask = os.umask(0o022)
    try:
        with atomic_output_dir(tmp_path / "run") as tmp:
            (tmp / "a.json").write_text("{}")
    finally:
        os.umask(mask)
    assert stat.S_IMODE((tmp_path / "run").stat().st_mode) == 0o755
