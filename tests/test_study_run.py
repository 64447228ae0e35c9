"""Design studies on a real dask cluster: LocalCluster with 2 worker processes, a rerun that adds
nothing, a failing variant, and a `dask scheduler` + `dask worker` started as separate processes."""

from __future__ import annotations

import socket
import subprocess
import sys
import time
from pathlib import Path

import pytest

pytest.importorskip("distributed")
pa = pytest.importorskip("pyarrow")

from _shared import EXAMPLES, free_port  # noqa: E402
from chaindrive.cli import main  # noqa: E402
from chaindrive.errors import InfeasibleError, InputError  # noqa: E402
from chaindrive.study.run import evaluate_variant, existing_keys, read_results, run_study  # noqa: E402
from chaindrive.study.spec import load_study  # noqa: E402

# 6 variants: 2 skews x 3 tooth counts of the driving sprocket; teeth = 2 is refused by
# the project schema (whole number >= 3), so 2 variants fail and record their error
STUDY = f"""
[study]
name = "small skew study"
base = "{(EXAMPLES / 'roller_industrial.toml').as_posix()}"
remove = ["contact.skew_height_difference", "contact.skew_base"]
outputs = ["contact.stress", "loads.maximum", "passed", "checks.static safety.value"]

[plan]
kind = "grid"

[[vary]]
path = "contact.skew"
unit = "arcmin"
values = [42, 206]

[[vary]]
path = "wheels.0.teeth"
values = [19, 2, 23]
"""

COMPARE = ["key", "variant", "contact.skew", "wheels.0.teeth", "contact.stress", "loads.maximum",
           "passed", "checks.static safety.value", "error"]


def _rows(table) -> list[dict]:
    return [{k: r[k] for k in COMPARE} for r in table.to_pylist()]


@pytest.fixture(scope="module")
def study_file(tmp_path_factory) -> Path:
    f = tmp_path_factory.mktemp("study") / "small.toml"
    f.write_text(STUDY, encoding="utf-8")
    return f


@pytest.fixture(scope="module")
def local_run(study_file, tmp_path_factory):
    """The study on a LocalCluster with 2 worker processes (one per core)."""
    out = tmp_path_factory.mktemp("local")
    run = run_study(load_study(study_file), out, workers=2, batch_size=2, progress=False)
    return out, run


def test_local_cluster_two_workers(local_run, study_file):
    out, run = local_run
    assert (run.variants, run.skipped, run.computed, run.failed, run.workers) == (6, 0, 6, 2, 2)
    assert len(run.files) == 3  # batches of 2 -> three part files
    table = read_results(out)
    assert table.num_rows == 6
    assert table.schema.field("contact.skew").metadata == {b"unit": b"arcmin"}
    rows = table.to_pylist()
    assert [r["variant"] for r in rows] == list(range(6))
    # independent: the same variants evaluated in this process, without dask
    study = load_study(study_file)
    for r, values in zip(rows, study.rows(), strict=True):
        ref = evaluate_variant(study.base, study.variant_inputs(values), study.outputs, parts=study.parts)
        assert r["error"] == ref["error"]
        for o in study.outputs:
            assert r[o] == ref[o]
    failed = [r for r in rows if r["error"]]
    assert [r["wheels.0.teeth"] for r in failed] == [2, 2]
    assert all("wheels[0].teeth" in r["error"] and r["contact.stress"] is None for r in failed)
    ok = [r for r in rows if not r["error"]]
    # passed counts every check: at 206' the life with skew (about 1900 h) falls below the life at the
    # rated power (18 300 h), the service-life check fails (issue 19: passed ignored the skew)
    assert all(r["contact.stress"] > 0 and r["passed"] is (r["contact.skew"] < 100) for r in ok)
    # more skew, more stress (Garshniev & Maksymovych eq. (2)); the 206' rows come after the 42' rows
    assert ok[-1]["contact.stress"] > 2 * ok[0]["contact.stress"]
    assert len({r["worker"] for r in rows}) >= 1


def test_rerun_adds_nothing(local_run, study_file, capsys):
    out, _ = local_run
    before = sorted((out / "results").glob("part-*.parquet"))
    keys = existing_keys(out)
    # through the command line: nothing pending, so no cluster is started
    assert main(["study", str(study_file), "-o", str(out)]) == 0
    text = capsys.readouterr().out
    assert "0 variants computed (0 failed), 6 already in" in text
    assert sorted((out / "results").glob("part-*.parquet")) == before
    assert existing_keys(out) == keys and len(keys) == 6




def _stop(proc: subprocess.Popen) -> None:
    if proc.poll() is None:
        proc.terminate()
        try:
            proc.wait(timeout=15)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait(timeout=5)


@pytest.mark.slow
def test_separate_scheduler_and_worker_give_the_same_rows(local_run, study_file, tmp_path):
    port = free_port()
    address = f"tcp://127.0.0.1:{port}"
    procs = []
    try:
        procs.append(subprocess.Popen(
            [sys.executable, "-m", "distributed.cli.dask_scheduler", "--host", "127.0.0.1",
             "--port", str(port), "--no-dashboard"],
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL))
        deadline = time.monotonic() + 30
        while time.monotonic() < deadline:
            with socket.socket() as s:
                if s.connect_ex(("127.0.0.1", port)) == 0:
                    break
            time.sleep(0.2)
        # a scheduler without workers: refused after the wait, nothing written
        with pytest.raises(InfeasibleError, match="no dask worker joined the scheduler within 1 s"):
            run_study(load_study(study_file), tmp_path / "empty", scheduler=address, progress=False,
                      wait_for_workers=1)
        assert not list((tmp_path / "empty").glob("results/part-*.parquet"))
        procs.append(subprocess.Popen(
            [sys.executable, "-m", "distributed.cli.dask_worker", address, "--nworkers", "1",
             "--nthreads", "1", "--no-dashboard", "--host", "127.0.0.1"],
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL))
        remote = tmp_path / "remote"
        run = run_study(load_study(study_file), remote, scheduler=address, progress=False,
                        wait_for_workers=60)
        assert (run.computed, run.failed, run.workers) == (6, 2, 1)
        assert _rows(read_results(remote)) == _rows(read_results(local_run[0]))
    finally:
        for p in reversed(procs):
            _stop(p)


@pytest.mark.slow
def test_summary_page(local_run, capsys):
    pytest.importorskip("matplotlib")
    out, _ = local_run
    assert main(["study", "--summary", str(out)]) == 0
    assert "6 variants (2 failed)" in capsys.readouterr().out
    html = (out / "summary" / "index.html").read_text(encoding="utf-8")
    assert "small skew study" in html and "data:image/png;base64," in html
    assert "wheels[0].teeth" in html  # the failed variants' error, counted
    assert "<h2>Warnings</h2>" in html  # the analysis warnings, grouped and counted
    assert (out / "summary" / "distribution_contact_stress.png").stat().st_size > 1000


def test_study_cli_errors(study_file, tmp_path, capsys):
    assert main(["study"]) == 2
    assert "give a study file" in capsys.readouterr().err
    assert main(["study", str(study_file)]) == 2
    assert "--output" in capsys.readouterr().err
    assert main(["study", str(study_file), "-o", str(tmp_path), "--summary", str(tmp_path)]) == 2
    assert "either STUDY" in capsys.readouterr().err
    assert main(["study", str(study_file), "-o", str(tmp_path / "x"), "--scheduler", "127.0.0.1:8786"]) == 2
    assert "tcp://HOST:PORT" in capsys.readouterr().err
    assert main(["study", "--summary", str(tmp_path)]) == 2
    assert "not a study folder" in capsys.readouterr().err
    assert main(["study", str(tmp_path / "none.toml"), "-o", str(tmp_path / "y")]) == 2
    assert "does not exist" in capsys.readouterr().err


def test_run_errors(study_file, tmp_path, local_run):
    study = load_study(study_file)
    with pytest.raises(InputError, match=r"batch_size must lie in \[1, 20000\], got 0"):
        run_study(study, tmp_path / "a", batch_size=0, progress=False)
    with pytest.raises(InputError, match=r"workers must lie in \[1, 256\], got 0"):
        run_study(study, tmp_path / "a", workers=0, progress=False)
    (tmp_path / "file").write_text("x")
    with pytest.raises(InputError, match="is a file; give a folder"):
        run_study(study, tmp_path / "file", progress=False)
    with pytest.raises(InputError, match="holds no results"):
        read_results(tmp_path)
    # nobody listens on a fresh port: refused with the address named
    with pytest.raises(InputError, match=r"--scheduler: cannot reach the scheduler at 'tcp://127.0.0.1:\d+'"):
        run_study(study, tmp_path / "b", scheduler=f"tcp://127.0.0.1:{free_port()}", progress=False,
                  wait_for_workers=1)
    other = load_study(EXAMPLES / "skew_study.toml")
    with pytest.raises(InputError, match="holds the results of another plan"):
        run_study(other, local_run[0], progress=False)


def test_lost_batch_is_computed_again(study_file, tmp_path):
    # no cluster: the part writer directly. A batch lost on the cluster leaves rows with
    # the cluster-failure error; they do not count as done, and the newer row wins.
    from chaindrive.study.run import CLUSTER_FAILURE, _PartWriter

    study = load_study(study_file)
    rows = study.rows()[:2]
    keys = [study.key(study.variant_inputs(r)) for r in rows]
    values = dict(zip(keys, rows, strict=True))
    writer = _PartWriter(tmp_path, study)
    writer.write({"key": keys, "variant": [0, 1], "error": [f"{CLUSTER_FAILURE}: KilledWorker"] * 2}, values)
    assert existing_keys(tmp_path) == set()
    time.sleep(0.01)  # part names carry the microsecond: the retry's part sorts after
    retry = _PartWriter(tmp_path, study)
    retry.write({"key": keys[:1], "variant": [0], "contact.stress": [1.0e8], "error": [None]}, values)
    assert existing_keys(tmp_path) == {keys[0]}
    table = read_results(tmp_path)
    assert table.num_rows == 2
    first, second = table.to_pylist()
    assert (first["contact.stress"], first["error"]) == (1.0e8, None)
    assert second["error"].startswith(CLUSTER_FAILURE)


def test_drive_family_with_named_chains(tmp_path):
    # a family over catalogue chains (text values) and tooth counts: text and whole-number
    # input columns; evaluated in this process, written by the part writer
    from chaindrive.study.run import _PartWriter, run_batch_columns
    from chaindrive.study.spec import parse_study

    study = parse_study(f"""
[study]
base = "{(EXAMPLES / 'roller_industrial.toml').as_posix()}"
outputs = ["loads.maximum", "rating.rated_power"]
[[vary]]
path = "chain.name"
values = ["12B", "16B", "20B"]
[[vary]]
path = "wheels.0.teeth"
values = [17, 21]
""", filename="family.toml")
    rows = study.rows()
    batch = [(i, study.key(study.variant_inputs(r)), study.variant_inputs(r)) for i, r in enumerate(rows)]
    out = run_batch_columns(batch, base=study.base, outputs=study.outputs, parts=study.parts)
    _PartWriter(tmp_path, study).write(out, {k: r for (_, k, _), r in zip(batch, rows, strict=True)})
    table = read_results(tmp_path)
    assert table.schema.field("chain.name").type == pa.string()
    assert table.schema.field("wheels.0.teeth").type == pa.int64()
    got = table.to_pylist()
    assert [(r["chain.name"], r["wheels.0.teeth"]) for r in got] == list(rows)
    assert all(r["error"] is None for r in got)
    # a bigger chain carries more power (ANSI/ACA rating grows with pitch, Shigley eq. (17-32))
    power = {(r["chain.name"], r["wheels.0.teeth"]): r["rating.rated_power"] for r in got}
    assert power[("12B", 17)] < power[("16B", 17)] < power[("20B", 17)]


def test_results_as_dataframe_with_units(local_run):
    pytest.importorskip("pandas")
    from chaindrive.study import read_dataframe

    out, _ = local_run
    df = read_dataframe(out)
    assert len(df) == 6 and list(df["variant"]) == list(range(6))
    units = df.attrs["units"]
    assert units["contact.skew"] == "arcmin"          # an input: the study file's unit
    assert units["contact.stress"] == "Pa" and units["loads.maximum"] == "N"   # outputs: SI
    assert units["seconds"] == "s" and units["passed"] == "" and set(units) == set(df.columns)
    assert df.attrs["study"]["inputs"] == ["contact.skew", "wheels.0.teeth"]
    with pytest.raises(InputError, match="holds no results"):
        read_dataframe(out / "nothing")
