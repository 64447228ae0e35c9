"""The web app's one door into the analysis: everything it asks of a Drive goes through here.

:func:`light_analysis` is the per-keystroke analysis: :func:`chaindrive.analysis.analyze_drive`
(no figures). :func:`full_report` is the report with figures
(:func:`chaindrive.workflows.analyze.analyze`, run as a job). Names, units and values of checks come from the result objects, never re-listed here.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from ..analysis.checks import Check
    from ..analysis.layout import DriveLayout
    from ..analysis.vibration import _Excitation
    from ..drive.model import Drive
    from ..vibration import TensionerSpan
    from ..workflows.report import Table

__all__ = ["LightAnalysis", "light_analysis", "layout_summary", "full_report", "tensioner_span",
           "loads_table"]


@dataclass
class LightAnalysis:
    """Checks, warnings and the key numbers of one drive (SI units)."""

    checks: list[dict[str, Any]]
    warnings: list[str]
    passed: bool
    analysis: Any = None
    layout: Any = None

    def results(self) -> dict[str, Any]:
        """Every number of the analysis, JSON-ready (SI units)."""
        return {} if self.analysis is None else self.analysis.to_dict()


def _finite(x: Any) -> Any:
    if isinstance(x, float) and not math.isfinite(x):
        return None
    return x


def _check_dict(group: str, c: Check) -> dict[str, Any]:
    """A check of the analysis as the page's data: its own fields, its verdict and its numeric margin
    (:attr:`chaindrive.analysis.checks.Check.margin`; never parsed from a text)."""
    value = _finite(c.value) if isinstance(c.value, float) else c.value
    return {"group": group, "name": c.name, "value": value, "limit": c.limit, "relation": c.relation,
            "unit": c.unit, "display": c.display, "passed": c.passed, "verdict": c.verdict,
            "margin": _finite(c.margin), "source": c.source, "note": c.note}


def light_analysis(drive: Drive) -> LightAnalysis:
    """Every check of ``drive`` without figures (the live update of the studio).

    Parameters
    ----------
    drive : chaindrive.drive.Drive

    Returns
    -------
    LightAnalysis

    Examples
    --------
    >>> from chaindrive.drive.project import parse_project, template
    >>> a = light_analysis(parse_project(template("roller")))
    >>> any(c["name"].startswith("static safety") for c in a.checks)
    True
    """
    from ..analysis import analyze_drive  # the typed analysis layer

    res = analyze_drive(drive, exclude=["remedy"])  # the remedy search (~1.5 s) belongs to the full report
    checks = [_check_dict(_group(c), c) for c in res.checks]
    return LightAnalysis(checks=checks, warnings=[str(w) for w in res.warnings],
                         passed=bool(res.passed), analysis=res, layout=res.layout)


def _group(check: Any) -> str:
    return str(getattr(check, "group", "") or "")


def loads_table(analysis: LightAnalysis) -> Table | None:
    """The chain-tension table of the report's "Loads" section (names, values, units and
    basis as the report gives them), or ``None`` when the analysis has no loads."""
    from ..analysis.parts import get_part
    from ..workflows.sections import Figures, section_function

    if analysis.analysis is None or getattr(analysis.analysis, "loads", None) is None:
        return None
    sec = section_function(get_part("loads"))(analysis.analysis, Figures(False))  # that section only
    return None if sec is None or not sec.tables else sec.tables[0]


def _layout(drive: Any):
    try:
        from ..analysis.layout import drive_layout
    except ImportError:  # the Drive methods before the analysis layer
        return drive.layout()
    return drive_layout(drive)


def layout_summary(drive: Drive, layout: DriveLayout | None = None) -> dict[str, Any]:
    """Links, exact centre distance, wheel circles and spans of ``drive`` (SI units).

    ``layout`` is the drive's ``DriveLayout`` when already computed (by the analysis).

    Examples
    --------
    >>> from chaindrive.drive.project import parse_project, template
    >>> s = layout_summary(parse_project(template("roller")))
    >>> s["links"], len(s["wheels"])
    (122, 2)
    """
    lay = _layout(drive) if layout is None else layout
    w = lay.wrap
    names = list(lay.wheel_names)
    wheels = []
    by_name = {wh.name: wh for wh in drive.wheels}
    for i, name in enumerate(names):
        wh = by_name[name]
        wheels.append({"name": name, "kind": wh.kind, "teeth": wh.teeth,
                       "centre": [float(w.centres[i][0]), float(w.centres[i][1])],
                       "radius": float(w.radii[i]), "side": int(w.sides[i]),
                       "driving": bool(wh.driving), "wrap": float(w.wrap_angle[i])})
    spans = [{"start": [float(a) for a in w.span_start[i]], "end": [float(a) for a in w.span_end[i]],
              "length": float(w.span_length[i]),
              "role": "tight" if i == lay.tight_span else ("slack" if i == lay.slack_span else "")}
             for i in range(len(names))]
    cdl = lay.centre_distance_for_links
    speed = getattr(lay, "chain_speed", None)
    return {
        "links": int(lay.links),
        "links_required": float(lay.links_required),
        "chain_length": float(lay.links * drive.chain.pitch),
        "centre_distance": None if lay.centre_distance is None else float(lay.centre_distance),
        "centre_distance_for_links": None if cdl is None else float(cdl.taut),
        "chain_speed": float(speed if speed is not None else drive.chain_speed()),
        "wheels": wheels,
        "spans": spans,
        "travel": drive.travel,
    }


def tensioner_span(drive: Drive) -> tuple[TensionerSpan, _Excitation] | None:
    """The slack span with its tensioner (``TensionerSpan``) and the excitation keywords.

    Returns
    -------
    (TensionerSpan, dict) or None
        ``None`` without a tensioner. The dict holds ``ratio``, ``teeth``, ``link_chain``
        of :func:`chaindrive.vibration.excitation_multipliers`.
    """
    if drive.tensioner is None:
        return None
    from ..analysis.loads import drive_loads
    from ..analysis.vibration import excitation_kwargs
    from ..analysis.vibration import tensioner_span as _span

    lay = _layout(drive)
    span = _span(drive, lay, drive_loads(drive, lay))
    if span is None:
        return None
    return span, excitation_kwargs(drive)


def full_report(drive: Drive, output: str | Path, *, pdf: bool = False) -> dict[str, str]:
    """The full report with figures written to ``output`` (run inside a job).

    Returns
    -------
    dict
        File kind -> path written (``html``, ``json``, ``pdf``).
    """
    from ..workflows.analyze import analyze

    outcome = analyze(drive, output, pdf=pdf)
    return {k: str(v) for k, v in outcome.files.items() if k in ("html", "json", "pdf")}
