"""results.json holds each number once (issue 31): every number of the analysis under
``analysis``; a report section holds only presentation and references into ``analysis`` by
path (``"analysis.layout"``, ``"analysis.checks[3]"``), which resolve."""

import json

import pytest

from _shared import EXAMPLES
from chaindrive.drive.project import load_project
from chaindrive.workflows.analyze import analyze
from chaindrive.workflows.report import RESULTS_VERSION, Report, resolve

NAMES = ("roller_industrial", "mining_conveyor", "tractor_track", "self_regulating", "crawler_conveyor")


def _leaves(value, path=""):
    if isinstance(value, dict):
        for k, v in value.items():
            yield from _leaves(v, f"{path}.{k}" if path else str(k))
    elif isinstance(value, list):
        for i, v in enumerate(value):
            yield from _leaves(v, f"{path}[{i}]")
    else:
        yield path, value


def _number(value):
    return isinstance(value, (int, float)) and not isinstance(value, bool)


@pytest.fixture(scope="module", params=NAMES)
def results(request, tmp_path_factory):
    folder = tmp_path_factory.mktemp(request.param)
    outcome = analyze(load_project(EXAMPLES / f"{request.param}.toml"), folder, figures=False)
    return json.loads(outcome.files["json"].read_text(encoding="utf-8"))


def test_each_number_stored_once(results):
    # walk the whole document: a number is stored under `analysis` (the results, SI),
    # `timings_s` (the run's own measurement) or `version` (the layout's), nowhere else; so no number of the analysis is
    # stored at a second path outside it (sections, title, verdict hold none)
    assert results["version"] == RESULTS_VERSION == 2
    outside = [(p, v) for p, v in _leaves(results) if _number(v) and p.split(".")[0] not in ("analysis", "timings_s", "version")]
    assert outside == []
    # the analysis' own numbers: each part's values once per part (a check's value is the
    # checked part's result, named by the check: docs/analysis.md "results.json")
    analysis_paths = {p for p, v in _leaves(results["analysis"]) if _number(v)}
    assert analysis_paths


def test_sections_reference_the_analysis(results):
    refs = 0
    for title, sec in results["sections"].items():
        for key, ref in sec["results"].items():
            assert ref == f"analysis.{key}", title
            assert resolve(results, ref) is not None or key in results["analysis"]
            refs += 1
        for ref in sec["checks"]:
            assert isinstance(ref, str) and ref.startswith("analysis.checks["), title
            check = resolve(results, ref)
            assert check["passed"] in (True, False, None)
            refs += 1
    assert refs > 5


def test_resolve_errors():
    data = {"analysis": {"checks": [{"value": 2.0}]}}
    assert resolve(data, "analysis.checks[0]") == {"value": 2.0}
    with pytest.raises(KeyError, match="layout"):
        resolve(data, "analysis.layout")
    with pytest.raises(IndexError, match="out of range"):
        resolve(data, "analysis.checks[3]")


def test_report_without_analysis_keeps_its_checks():
    # a report built by hand (no analysis to point at) stores its sections' checks themselves
    from chaindrive.analysis.checks import Check
    from chaindrive.workflows.report import Section

    check = Check(name="x", value=1.0, limit=2.0, unit="m", passed=True, source="s")
    d = Report(title="t", sections=[Section("S", checks=[check])]).to_dict()
    assert d["sections"]["S"]["checks"][0]["value"] == 1.0
