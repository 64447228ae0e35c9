"""Rich display in notebooks: HTML tables with units for drives, analyses and results.

Jupyter shows an object through its ``_repr_html_``. :class:`chaindrive.drive.Drive`,
:class:`chaindrive.analysis.DriveAnalysis` and every result object
(:class:`chaindrive._results.Result`) hand themselves to :func:`html_of`, which only
formats: each numeric field in its display unit (:mod:`chaindrive.workflows.display`,
from the unit the field declares), arrays as their range, nested results folded, the
checks of an analysis with value, limit, verdict and source, and the drive drawn to
scale as inline SVG.

Examples
--------
>>> from chaindrive.vibration import TensionerSpan
>>> html = html_of(TensionerSpan(2000.0, 2.6, 0.8, 0.8, 0.35, 0.35, 3.0, 5e4))
>>> "<td>800</td><td>mm</td>" in html
True
"""

from __future__ import annotations

import dataclasses
import io
import math
from html import escape
from typing import Any

import numpy as np

from .._presenters import register_view
from ..display import check_limit_text, check_value_text, convert, fmt

__all__ = ["html_of", "drive_html", "analysis_html", "result_html", "drawing_svg", "tidy"]

_STYLE = ("<style>.cd-table{border-collapse:collapse;font-size:0.9em;margin:0.3em 0}"
          ".cd-table td,.cd-table th{border-bottom:1px solid #ddd;padding:2px 8px;text-align:left}"
          ".cd-table td:nth-child(2),.cd-table td:nth-child(3){text-align:right;font-variant-numeric:tabular-nums;white-space:nowrap}"
          ".cd-fail{color:#b03a2e;font-weight:bold}.cd-pass{color:#1e8449}"
          ".cd-drawing svg{max-width:560px;height:auto}</style>")

#: Below this fraction of the largest value shown with it, a number is rounding noise: 0.
NOISE = 1e-9


def tidy(value: float, scale: float | None = None) -> float:
    """``value`` with rounding noise removed: 0 when ``|value| <= NOISE * scale``.

    ``scale`` is the magnitude of the quantity it is compared with (the largest value of
    its array, for example); a lone value is compared with itself and kept.

    Examples
    --------
    >>> tidy(7.694e-12, 0.82), tidy(-0.0, None), tidy(0.5, 0.82)
    (0.0, 0.0, 0.5)
    """
    v = float(value)
    if v == 0.0 or (scale is not None and math.isfinite(scale) and abs(v) <= NOISE * abs(scale)):
        return 0.0
    return v


def _label(name: str) -> str:
    return name.replace("_", " ")


def _number_cells(value: Any, unit: str | None, shown: str | None) -> tuple[str, str]:
    """The value and unit cells of one field."""
    si = unit or "1"
    if isinstance(value, (bool, np.bool_)):
        return fmt(bool(value)), ""
    if isinstance(value, np.ndarray) or (isinstance(value, (list, tuple)) and value
                                         and all(isinstance(v, (int, float, np.number)) for v in value)):
        array = np.asarray(value, dtype=float)
        if array.size == 0:
            return "—", ""
        finite = array[np.isfinite(array)]
        if finite.size == 0:
            return "—", ""
        lo, unit_text = convert(float(finite.min()), si, shown)
        hi, _ = convert(float(finite.max()), si, shown)
        scale = max(abs(lo or 0.0), abs(hi or 0.0))
        lo, hi = tidy(lo or 0.0, scale), tidy(hi or 0.0, scale)
        text = fmt(lo) if lo == hi else f"{fmt(lo)} … {fmt(hi)}"
        return f"{text} ({array.size} values)", "" if unit_text == "1" else unit_text
    if isinstance(value, (int, np.integer)):
        return str(int(value)), "" if si in ("1", "-") else si
    if isinstance(value, (float, np.floating)):
        shown_value, unit_text = convert(float(value), si, shown)
        return fmt(shown_value), "" if unit_text in ("1", "-") else unit_text
    if isinstance(value, (tuple, list)):
        return escape(", ".join(str(v) for v in value)), ""
    return escape(str(value)), ""


def result_html(result: Any, *, title: str | None = None) -> str:
    """A result object as an HTML table: field, value in its display unit, unit.

    Nested results (and tuples of them) are folded under their field's name.
    """
    cls = type(result)
    rows: list[str] = []
    nested: list[str] = []
    for f in dataclasses.fields(result):
        value = getattr(result, f.name)
        if f.name.startswith("_") or value is None:
            continue
        if dataclasses.is_dataclass(value) and not isinstance(value, type):
            nested.append(_fold(_label(f.name), result_html(value)))
            continue
        if isinstance(value, (tuple, list)) and value and dataclasses.is_dataclass(value[0]):
            inner = "".join(result_html(v, title=getattr(v, "name", None)) for v in value)
            nested.append(_fold(f"{_label(f.name)} ({len(value)})", inner))
            continue
        if isinstance(value, dict):
            continue
        unit = f.metadata.get("unit")
        shown = f.metadata.get("display")
        if isinstance(value, str) and not value:
            continue
        cell, unit_text = _number_cells(value, unit, shown)
        rows.append(f"<tr><td>{escape(_label(f.name))}</td><td>{cell}</td><td>{escape(unit_text)}</td></tr>")
    head = f"<b>{escape(title or cls.__name__)}</b>"
    table = ("<table class='cd-table'><tr><th>quantity</th><th>value</th><th>unit</th></tr>"
             + "".join(rows) + "</table>") if rows else ""
    return f"<div>{head}{table}{''.join(nested)}</div>"


def _fold(summary: str, body: str) -> str:
    return f"<details><summary>{escape(summary)}</summary>{body}</details>"


def drawing_svg(subject: Any) -> str:
    """The drive of ``subject`` (a Drive or a DriveAnalysis) drawn to scale, as inline SVG."""
    import matplotlib.pyplot as plt

    from ..plotting.drive import layout_plot

    fig = layout_plot(subject)
    fig.set_size_inches(6.0, 4.0)
    buffer = io.StringIO()
    fig.savefig(buffer, format="svg", bbox_inches="tight")
    plt.close(fig)
    svg = buffer.getvalue()
    return svg[svg.find("<svg"):]


def _checks_html(checks: Any) -> str:
    rows = []
    for c in checks:
        verdict = {True: "<span class='cd-pass'>pass</span>", False: "<span class='cd-fail'>FAIL</span>",
                   None: "info"}[c.passed]
        rows.append(f"<tr><td>{escape(c.name)}</td><td>{escape(check_value_text(c))}</td>"
                    f"<td>{escape(check_limit_text(c))}</td><td>{verdict}</td><td>{escape(c.source)}</td></tr>")
    return ("<table class='cd-table'><tr><th>check</th><th>value</th><th>limit</th><th>verdict</th>"
            "<th>source</th></tr>" + "".join(rows) + "</table>")


def _drive_rows(drive: Any) -> str:
    chain = drive.chain
    rows = [("name", escape(drive.name), ""),
            ("chain", escape(str(getattr(chain, "name", chain))), ""),
            ("pitch", fmt(convert(chain.pitch, "m")[0]), "mm")]
    speed, _ = convert(drive.speed, "rad/s")
    rows.append(("driving wheel speed", f"{fmt(drive.speed)} rad/s", f"{fmt(speed)} rpm"))
    try:
        power, unit = convert(drive.design_power(), "W")
        rows.append(("design power", fmt(power), unit))
    except Exception:  # noqa: BLE001 - a drive given by its torque alone may have no power yet
        pass
    from .sections import wheel_description

    for w in drive.wheels:
        teeth = "plain" if w.teeth is None else f"{w.teeth} teeth"
        x, _ = convert(w.position[0], "m")
        y, _ = convert(w.position[1], "m")
        rows.append((f"wheel {escape(w.name)}", f"{escape(wheel_description(drive, w.name))}, {teeth}, "
                                                 f"at ({fmt(x)}, {fmt(y)})", "mm"))
    body = "".join(f"<tr><td>{a}</td><td>{b}</td><td>{c}</td></tr>" for a, b, c in rows)
    return "<table class='cd-table'><tr><th>quantity</th><th>value</th><th>unit</th></tr>" + body + "</table>"


def drive_html(drive: Any) -> str:
    """A drive: its data with units and its drawing to scale."""
    try:
        svg = f"<div class='cd-drawing'>{drawing_svg(drive)}</div>"
    except Exception as exc:  # noqa: BLE001 - a drive that cannot be laid out still shows its data
        svg = f"<p>(no drawing: {escape(str(exc))})</p>"
    return f"{_STYLE}<div><b>Drive</b>{_drive_rows(drive)}{svg}</div>"


def analysis_html(analysis: Any) -> str:
    """An analysis: verdict, every check with its value, limit and source, the drawing,
    and each part folded as its table."""
    from ..display import verdict_text

    words = escape(verdict_text(len(analysis.failed), len(analysis.warnings)))
    verdict = (f"<span class='cd-pass'>{words}</span>" if analysis.passed
               else f"<span class='cd-fail'>{words}</span>")
    from ..analysis.parts import get_part

    parts = []
    for name, value in analysis.results.items():
        if value is None:
            continue
        try:
            title = f"{get_part(name).title} ({name})"
        except Exception:  # noqa: BLE001 - a result stored under a name no part declares
            title = name
        if isinstance(value, tuple):
            inner = "".join(result_html(v, title=getattr(v, "name", None)) for v in value
                            if dataclasses.is_dataclass(v))
        elif dataclasses.is_dataclass(value):
            inner = result_html(value)
        else:
            cell, unit = _number_cells(value, None, None)
            inner = f"<p>{cell} {escape(unit)}</p>"
        parts.append(_fold(title, inner))
    warnings = "".join(f"<li>{escape(w)}</li>" for w in analysis.warnings)
    try:
        svg = f"<div class='cd-drawing'>{drawing_svg(analysis)}</div>"
    except Exception as exc:  # noqa: BLE001
        svg = f"<p>(no drawing: {escape(str(exc))})</p>"
    return (f"{_STYLE}<div><b>Analysis of {escape(analysis.drive.name)}</b>: {verdict}"
            f"{_checks_html(analysis.checks)}{svg}"
            + (f"<details><summary>warnings ({len(analysis.warnings)})</summary><ul>{warnings}</ul></details>"
               if warnings else "")
            + "".join(parts) + "</div>")


@register_view("html", object)
def html_of(subject: Any) -> str:
    """The notebook HTML of a drive, an analysis or a result object."""
    from ..analysis import DriveAnalysis
    from ..drive.model import Drive

    if isinstance(subject, DriveAnalysis):
        return analysis_html(subject)
    if isinstance(subject, Drive):
        return drive_html(subject)
    return _STYLE + result_html(subject)
