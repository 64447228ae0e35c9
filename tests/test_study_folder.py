"""A study folder belongs to one plan (issue 34, items 1 and 5): another plan refused (or
started over with --force), the same plan resumed, the summary reading only the plan's rows,
damaged part files computed again, temporary files of killed runs removed."""

from __future__ import annotations

import io
import json
import warnings
from pathlib import Path

import pytest

pytest.importorskip("distributed")
pytest.importorskip("pyarrow")

from _shared import EXAMPLES  # noqa: E402
from chaindrive.cli import main  # noqa: E402
from chaindrive.errors import ChainDriveWarning, InputError  # noqa: E402
from chaindrive.study.folder import fingerprint, plan_parts, prepare_folder  # noqa: E402
from chaindrive.study.progress import QuietProgress  # noqa: E402
from chaindrive.study.run import _PartWriter, existing_keys, read_results, run_batch_columns  # noqa: E402
from chaindrive.study.spec import parse_study  # noqa: E402


def _study(folder: Path, power: str = "15 kW", samples: int = 4, text: str = ""):
    base = (EXAMPLES / "roller_industrial.toml").read_text(encoding="utf-8")
    assert 'power = "15 kW"' in base
    (folder / "base.toml").write_text(base.replace('power = "15 kW"', f'power = "{power}"'), encoding="utf-8")
    return parse_study(f"""{text}
[study]
name = "skew"
base = "base.toml"
remove = ["contact.skew_height_difference", "contact.skew_base"]
outputs = ["loads.maximum"]
[plan]
kind = "monte_carlo"
samples = {samples}
seed = 1
[[vary]]
path = "contact.skew"
unit = "arcmin"
distribution = "uniform"
parameters = {{ loc = 42, scale = 164 }}
""", filename="s.toml", folder=folder)


def _fill(out: Path, study, *, parts: int = 2) -> None:
    """Compute the study in this process and write it as ``parts`` part files (no cluster)."""
    prepare_folder(out, study)
    rows = study.rows()
    batch = [(i, study.key(study.variant_inputs(r)), study.variant_inputs(r)) for i, r in enumerate(rows)]
    values = {k: r for (_, k, _), r in zip(batch, rows, strict=True)}
    writer = _PartWriter(out, study)
    step = -(-len(batch) // parts)
    for i in range(0, len(batch), step):
        writer.write(run_batch_columns(batch[i:i + step], base=study.base, outputs=study.outputs,
                                       parts=study.parts), values)


def test_another_plan_is_refused_and_force_starts_over(tmp_path):
    # reproducer: the same study file with the base power 15 -> 30 kW into the same folder
    # gave twice the rows, each variant number twice, and a summary of both designs
    out = tmp_path / "out"
    first = _study(tmp_path)
    _fill(out, first)
    assert read_results(out).num_rows == 4
    second = _study(tmp_path, power="30 kW")
    assert fingerprint(second) != fingerprint(first)
    with pytest.raises(InputError, match=r"holds the results of another plan .*give a new folder, or use "
                                         r"--force to start over"):
        prepare_folder(out, second)
    (out / "notes.txt").write_text("mine")  # a file of the user: --force keeps it
    (out / "summary").mkdir()
    (out / "summary" / "index.html").write_text("<html>")
    prepare_folder(out, second, force=True)
    assert not list((out / "results").glob("part-*")) if (out / "results").exists() else True
    assert (out / "notes.txt").read_text() == "mine"
    assert not (out / "summary").exists()
    assert json.loads((out / "study.json").read_text())["fingerprint"] == fingerprint(second)


def test_same_plan_resumes_and_comments_do_not_count(tmp_path):
    out = tmp_path / "out"
    study = _study(tmp_path)
    _fill(out, study)
    again = _study(tmp_path, text="# a comment and another name do not change the rows")
    prepare_folder(out, again)  # accepted: same plan
    assert len(existing_keys(out)) == 4


def test_smaller_plan_refused_summary_reads_only_the_plan(tmp_path):
    # reproducer: a 1,000-sample study into a 2,000-row folder left the summary at 2,000 rows
    out = tmp_path / "out"
    _fill(out, _study(tmp_path, samples=4))
    smaller = _study(tmp_path, samples=2)
    with pytest.raises(InputError, match="another plan"):
        prepare_folder(out, smaller)
    # a folder of an earlier chaindrive that mixed two plans: only the stored plan's parts count
    other = _study(tmp_path, power="30 kW", samples=3)
    _fill(tmp_path / "o", other, parts=1)
    (out / "results" / "part-99999999T000000.000000-ffffffff-00001.parquet").write_bytes(
        next((tmp_path / "o" / "results").glob("part-*.parquet")).read_bytes())
    assert read_results(out).num_rows == 4
    assert main(["study", "--summary", str(out), "-q"]) == 0


def test_old_folder_without_fingerprint_is_refused(tmp_path):
    out = tmp_path / "out"
    study = _study(tmp_path)
    _fill(out, study)
    described = json.loads((out / "study.json").read_text())
    del described["fingerprint"]
    (out / "study.json").write_text(json.dumps(described))
    with pytest.raises(InputError, match="without a plan fingerprint"):
        prepare_folder(out, study)


@pytest.mark.parametrize("damage", ["truncated", "empty", "garbage"])
def test_damaged_part_is_recomputed_named_in_one_line(tmp_path, damage, capsys):
    # reproducer: a truncated or empty part file gave `internal error: ArrowInvalid`, exit 3,
    # on a rerun and on --summary
    out = tmp_path / "out"
    study = _study(tmp_path)
    _fill(out, study)
    part = sorted((out / "results").glob("part-*.parquet"))[0]
    data = part.read_bytes()
    part.write_bytes({"truncated": data[: len(data) // 2], "empty": b"", "garbage": b"PAR1" + b"x" * 200}[damage])
    assert main(["study", "--summary", str(out), "-q"]) == 0
    err = capsys.readouterr().err
    assert err.count("warning:") == 1 and part.name in err and "left out" in err
    assert "ArrowInvalid" not in err
    with pytest.warns(ChainDriveWarning, match=rf"{part.name}.* is damaged .*computed again"):
        kept = plan_parts(out, on_damaged="recompute")
    assert part not in kept and part.with_name(part.name + ".damaged").exists()
    assert len(existing_keys(out)) == 2  # the damaged part's two variants are computed again


def test_temporary_files_of_killed_runs_are_removed(tmp_path):
    out = tmp_path / "out"
    study = _study(tmp_path)
    _fill(out, study)
    leftover = out / "results" / ".part-20260101T000000.000000-abcdef12-00001.parquet.k2j3h4.tmp"
    leftover.write_bytes(b"half")
    (out / ".study.json.x1y2.tmp").write_text("{")
    prepare_folder(out, study)
    assert not leftover.exists() and not (out / ".study.json.x1y2.tmp").exists()


def test_quiet_progress_line_for_long_studies():
    stream = io.StringIO()
    p = QuietProgress(1_999_396, stream=stream, every=3600)
    p.update(10, 100.0)  # within the interval: nothing
    p.update(1_000_000, 500.0, force=True)
    lines = stream.getvalue().splitlines()
    assert lines[0].startswith("study: 1,999,396 variants to compute")
    assert lines[1] == "study: 1,000,000 of 1,999,396 variants computed (500.0 variants/s, about 33 min 19 s left)"
    assert len(lines) == 2


def test_study_cli_force_option(tmp_path, capsys):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        assert main(["study", "--help"]) == 0
    assert "--force" in capsys.readouterr().out
