"""The calculation report of a drive: ``analyze(drive, output)`` behind ``chaindrive analyze``.

The analysis itself is :func:`chaindrive.analysis.analyze_drive`; this module only
presents it: the report sections (:mod:`chaindrive.workflows.sections`, a fixed ordered
list), ``report.html``, ``results.json`` (every number of the analysis once, SI units), the
figures as PNG or as charts the browser draws (``browser_charts``) and, on request,
``report.pdf``.
"""

from __future__ import annotations

import dataclasses
import json
import time
import warnings
from collections.abc import Callable, Iterable
from pathlib import Path

from .._results import jsonable
from ..analysis import DriveAnalysis, analyze_drive
from ..drive.model import Drive
from .report import Report
from .sections import build_sections

__all__ = ["AnalysisOutcome", "analyze", "report_from_analysis"]


@dataclasses.dataclass
class AnalysisOutcome:
    """The analysis, its report and the paths written."""

    analysis: DriveAnalysis
    report: Report
    files: dict[str, Path]
    timings: dict[str, float]

    @property
    def passed(self) -> bool:
        return self.analysis.passed

    @property
    def exit_code(self) -> int:
        return 0 if self.passed else 1


def report_from_analysis(analysis: DriveAnalysis, *, title: str | None = None, subtitle: str = "",
                         figures: bool = True,
                         progress: Callable[[str, int, int], None] | None = None,
                         parallel_figures: bool = False, browser_charts: bool = False) -> tuple[Report, dict[str, float]]:
    """The :class:`Report` of ``analysis`` (sections in a fixed order, figures when asked;
    ``parallel_figures``, ``browser_charts``: see :func:`analyze`)."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        sections, timings = build_sections(analysis, figures=figures, progress=progress, parallel=parallel_figures,
                                           browser=browser_charts)
    extra = [str(w.message) for w in caught]
    report = Report(title=title or analysis.drive.name or "Chain drive", subtitle=subtitle, sections=sections,
                    warnings=list(dict.fromkeys([*analysis.warnings, *extra])), analysis=analysis)
    return report, timings


def _proposal_text(analysis: DriveAnalysis, source: str | None = None) -> str | None:
    """The project file of the analysis' passing remedy (None when there is none): the user's
    file ``source`` with only the changed values edited (comments and order kept), or the
    whole drive written when there is no file."""
    remedy = analysis["remedy"]
    if remedy is None or not remedy.found:
        return None
    from ..drive.writer import drive_to_toml, edit_project_text
    from ..errors import InputError

    header = ("chaindrive proposal: the nearest design that passes the span-vibration check (largest\n"
              f"amplification of the slack span's forced response {remedy.amplification:.3g}), for "
              f"{analysis.drive.name!r}. Changes:\n" + "\n".join(f"  - {c}" for c in remedy.changes))
    if source is not None:
        try:
            return edit_project_text(source, analysis.drive, remedy.drive, header=header)
        except (InputError, KeyError, StopIteration):  # e.g. a file of another shape: the whole drive below
            pass
    try:
        return drive_to_toml(remedy.drive, header=header)
    except InputError:  # a drive the writer cannot write yet (e.g. [self_regulating]): the report has the changes
        return None


def analyze(
    drive: Drive,
    output: str | Path | None = None,
    *,
    title: str | None = None,
    subtitle: str = "",
    pdf: bool = False,
    figures: bool = True,
    progress: Callable[[str, int, int], None] | None = None,
    include: Iterable[str] | None = None,
    parallel_figures: bool = False,
    source: str | None = None,
    browser_charts: bool = False,
) -> AnalysisOutcome:
    """Analyse ``drive`` and write its calculation report.

    Parameters
    ----------
    drive : chaindrive.drive.Drive
    output : path, optional
        Folder for ``report.html``, ``results.json``, PNG figures (and ``report.pdf``),
        and ``proposal.toml`` when the span-vibration check fails and a design within the
        searched ranges passes, verified by its own analysis (:mod:`chaindrive.analysis.vibration_remedy`);
        nothing is written when ``None``. The caller chooses the folder: the command line
        builds it in a temporary folder and moves it into place when complete.
    pdf : bool
        Also write ``report.pdf`` (WeasyPrint).
    figures : bool
        Draw the figures.
    progress : callable, optional
        Called as ``progress(title, index, total)`` before each step.
    include : iterable of str, optional
        Parts of the analysis (:data:`chaindrive.analysis.PARTS`).
    parallel_figures : bool
        Share the figures with one helper process forked from this one when the machine
        has two processors or more (Linux) and, on average, one of them idle; the report is
        the same, the process about a tenth faster. For a program of its own (``chaindrive
        analyze`` sets it), not for one that runs threads or a server.
    source : str, optional
        The text of the project file ``drive`` was read from: ``proposal.toml`` is then
        that file with only the changed values edited.
    browser_charts : bool
        The figures that have a chart (:mod:`chaindrive.workflows.charts`) drawn by the
        browser from their data in ``report.html`` (plotly.js written beside it, offline)
        instead of PNG; matplotlib is then not imported for them. Ignored with ``pdf``
        (WeasyPrint runs no script). ``chaindrive analyze`` sets it unless ``--pdf`` or ``--png``.

    Returns
    -------
    AnalysisOutcome
    """
    t0 = time.perf_counter()
    if progress is not None:
        progress("analysis", 0, 1)
    analysis = analyze_drive(drive, include=include)
    t_analysis = time.perf_counter() - t0
    report, timings = report_from_analysis(analysis, title=title, subtitle=subtitle, figures=figures,
                                           progress=progress, parallel_figures=parallel_figures,
                                           browser_charts=browser_charts and not pdf)
    timings = {"analysis": t_analysis, **timings}
    if progress is not None:
        progress("done", 1, 1)
    files: dict[str, Path] = {}
    if output is not None:
        out = Path(output)
        out.mkdir(parents=True, exist_ok=True)
        files["html"] = report.write_html(out / "report.html")
        data = report.to_dict()
        data["timings_s"] = timings
        files["json"] = out / "results.json"
        files["json"].write_text(json.dumps(jsonable(data), indent=2), encoding="utf-8")
        for p in report.write_figures(out):
            files[p.name] = p
        proposal = _proposal_text(analysis, source)
        if proposal is not None:
            files["proposal"] = out / "proposal.toml"
            files["proposal"].write_text(proposal, encoding="utf-8")
        if pdf:
            files["pdf"] = report.write_pdf(out / "report.pdf")
    return AnalysisOutcome(analysis=analysis, report=report, files=files, timings=timings)
