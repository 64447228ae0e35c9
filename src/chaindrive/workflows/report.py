"""Calculation report: sections of tables, checks and figures, rendered to HTML or PDF.

The HTML carries its CSS inline and its figures either embedded as base64 PNG or as chart
data that the browser draws with plotly.js, written beside the HTML (:data:`PLOTLY_JS`,
offline): the folder is the calculation record. PDF is rendered from the HTML of PNG
figures with WeasyPrint.
"""

from __future__ import annotations

import base64
import dataclasses
import datetime as _dt
import io
import sys
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .. import display as _display
from .._results import Result, jsonable
from ..analysis.checks import Check

if TYPE_CHECKING:
    from matplotlib.figure import Figure as MatplotlibFigure

__all__ = ["Table", "Figure", "Section", "Report", "RESULTS_VERSION", "resolve"]

#: The file name of plotly.js beside report.html (copied from the installed plotly package).
PLOTLY_JS = "plotly.min.js"


def plotly_js_path() -> Path | None:
    """The installed plotly package's plotly.min.js, found without importing plotly."""
    import importlib.util

    spec = importlib.util.find_spec("plotly")
    if spec is None or not spec.submodule_search_locations:
        return None
    path = Path(next(iter(spec.submodule_search_locations))) / "package_data" / PLOTLY_JS
    return path if path.exists() else None


#: The layout of results.json: 2 holds each number once (sections reference ``analysis`` by
#: path); 1 (before) repeated the analysis' numbers in each section's ``results`` and ``checks``.
RESULTS_VERSION = 2


def resolve(data: dict[str, Any], path: str) -> Any:
    """The value at ``path`` (``"analysis.layout.links"``, ``"analysis.checks[3]"``) of a results.json
    document ``data``: how a reader follows a section's references.

    >>> resolve({"analysis": {"checks": [{"value": 2.0}]}}, "analysis.checks[0].value")
    2.0
    """
    value: Any = data
    for key in path.replace("[", ".[").split("."):
        value = value[int(key[1:-1])] if key.startswith("[") else value[key]
    return value


@dataclasses.dataclass(frozen=True)
class Table(Result):
    """A table with a caption, headers and rows of plain values."""

    caption: str
    headers: list[str]
    rows: list[list[Any]]


#: Margins of a plain plot [in]: left (y tick labels and label), right, bottom (x tick
#: labels and label), top (a title), and the gap between stacked axes with titles.
_MARGINS = {"left": 0.95, "right": 0.2, "bottom": 0.6, "top": 0.42, "gap": 0.5}


def _fixed_margins(fig: MatplotlibFigure) -> bool:
    """Place the axes of a plain plot (one column of axes, legends inside them, no twin
    axes or colorbars) with fixed margins, without measuring the text (no layout pass).
    Returns False, changing nothing, for any other figure."""
    axes = fig.axes
    if not axes or fig.legends or any(ax.get_aspect() != "auto" for ax in axes):
        return False
    for ax in axes:
        spec = ax.get_subplotspec()
        if spec is None or spec.get_gridspec().ncols != 1 or ax.yaxis.get_label_position() != "left":
            return False  # not a grid axes, several columns, a twin or a colorbar axes
        legend = ax.get_legend()
        if legend is not None and legend.get_bbox_to_anchor() is not ax.bbox:
            return False  # a legend placed outside its axes
    if len({spec.get_gridspec() for ax in axes if (spec := ax.get_subplotspec()) is not None}) != 1:
        return False
    width, height = fig.get_size_inches()
    rows = len(axes)
    m = _MARGINS
    top = m["top"] if axes[0].get_title() else m["right"]
    free = height - m["bottom"] - top - (rows - 1) * m["gap"]
    if free <= 1.0 or width <= m["left"] + m["right"] + 1.0:
        return False
    fig.set_layout_engine("none")
    fig.subplots_adjust(left=m["left"] / width, right=1 - m["right"] / width, bottom=m["bottom"] / height,
                        top=1 - top / height, hspace=m["gap"] / (free / rows))
    return True


def _fixed_titles(fig: MatplotlibFigure) -> None:
    """Leave each axes title at its default height where matplotlib's automatic placement
    would not move it (no x ticks or label on top, no offset text beside the title):
    that placement measures every y tick label at each draw, a third of a plain figure's
    drawing time. The picture is the same."""
    axes: list[Any] = list(fig.axes)  # matplotlib's own (private) title state is read and set
    for ax in axes:
        if not getattr(ax, "_autotitlepos", False) or not any(
                t.get_text() for t in (ax.title, ax._left_title, ax._right_title)):
            continue
        if ax.xaxis.get_ticks_position() in ("top", "unknown") or ax.xaxis.get_label_position() == "top":
            continue
        if ax.child_axes or len(ax._twinned_axes.get_siblings(ax)) > 1:
            continue
        if ax.yaxis.offsetText.get_visible() and _offset_text(ax.yaxis):
            continue
        ax._autotitlepos = False


def _offset_text(axis: Any) -> str:
    """The offset text (``1e6``, ``+7.7``) the axis will show, found without drawing it."""
    formatter = axis.get_major_formatter()
    if not hasattr(formatter, "get_offset"):
        return ""
    try:
        formatter.set_locs(axis.get_majorticklocs())
        return str(formatter.get_offset())
    except Exception:  # noqa: BLE001 - any doubt: keep matplotlib's own placement
        return "?"


def _save_png(fig: MatplotlibFigure, buf: io.BytesIO, dpi: int) -> None:
    """The figure as PNG, zlib level 3 (a quarter less encoding time than the default 6,
    files ~8 % larger). On the Agg canvas at the figure's own resolution with the default
    savefig settings: one draw and the encoding, the same bytes as ``savefig`` (which
    draws a figure twice when it has a layout engine, even the inert one of fixed
    margins); otherwise ``savefig``."""
    import matplotlib as mpl
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    pil_kwargs = {"compress_level": 3}
    rc = mpl.rcParams
    canvas = fig.canvas
    direct = (isinstance(canvas, FigureCanvasAgg) and fig.dpi == dpi and rc["savefig.bbox"] is None
              and rc["savefig.facecolor"] == "auto" and rc["savefig.edgecolor"] == "auto"
              and not rc["savefig.transparent"] and getattr(fig.canvas, "_device_pixel_ratio", 1) == 1)
    if not direct or not isinstance(canvas, FigureCanvasAgg):
        fig.savefig(buf, format="png", dpi=dpi, pil_kwargs=pil_kwargs)
        return
    FigureCanvasAgg.draw(canvas)
    mpl.image.imsave(buf, canvas.buffer_rgba(), format="png", origin="upper", dpi=fig.dpi,
                     pil_kwargs=pil_kwargs)


@dataclasses.dataclass
class Figure:
    """A figure: caption plus PNG bytes (and the file name it is saved under), or a chart
    the browser draws (plotly data, :mod:`chaindrive.workflows.charts`; then ``png`` is empty)."""

    caption: str
    png: bytes
    filename: str
    chart: dict[str, Any] | None = None

    @classmethod
    def from_matplotlib(cls, fig: MatplotlibFigure, caption: str, filename: str, dpi: int = 100) -> Figure:
        buf = io.BytesIO()
        from matplotlib.layout_engine import TightLayoutEngine

        engine = fig.get_layout_engine()
        # a plain plot: fixed margins (no layout pass); else one pass of the tight layout
        # inside savefig's single draw (constrained layout iterates and bbox_inches="tight"
        # draws twice); a plot that needs another engine (a legend outside the figure's
        # axes) sets it where it is made
        if (engine is None or isinstance(engine, TightLayoutEngine)) and not _fixed_margins(fig) and engine is None:
            fig.set_layout_engine("tight", pad=0.6)
        _fixed_titles(fig)
        _save_png(fig, buf, dpi)
        plt = sys.modules.get("matplotlib.pyplot")  # imported only by a program that uses it
        if plt is not None:
            plt.close(fig)
        return cls(caption=caption, png=buf.getvalue(), filename=filename)

    @property
    def data_uri(self) -> str:
        return "data:image/png;base64," + base64.b64encode(self.png).decode("ascii")


@dataclasses.dataclass
class Section:
    """A report section: text paragraphs, tables, checks, figures and warnings."""

    title: str
    paragraphs: list[str] = dataclasses.field(default_factory=list)
    tables: list[Table] = dataclasses.field(default_factory=list)
    checks: list[Check] = dataclasses.field(default_factory=list)
    figures: list[Figure] = dataclasses.field(default_factory=list)
    warnings: list[str] = dataclasses.field(default_factory=list)
    results: dict[str, Any] = dataclasses.field(default_factory=dict)
    skipped: str | None = None

    @property
    def passed(self) -> bool:
        return all(c.passed is not False for c in self.checks)


@dataclasses.dataclass
class Report:
    """The whole calculation record."""

    title: str
    subtitle: str = ""
    inputs: Table | None = None
    sections: list[Section] = dataclasses.field(default_factory=list)
    warnings: list[str] = dataclasses.field(default_factory=list)
    analysis: Any = None
    created: str = dataclasses.field(
        default_factory=lambda: _dt.datetime.now().strftime("%Y-%m-%d %H:%M")
    )

    @property
    def has_charts(self) -> bool:
        """Whether a figure is a chart the browser draws (report.html then loads :data:`PLOTLY_JS`)."""
        return any(f.chart is not None for s in self.sections for f in s.figures)

    @property
    def checks(self) -> list[tuple[str, Check]]:
        return [(s.title, c) for s in self.sections for c in s.checks]

    @property
    def passed(self) -> bool:
        if self.analysis is not None:
            return bool(self.analysis.passed)
        return all(s.passed for s in self.sections)

    @property
    def verdict(self) -> str:
        """The overall verdict in words (``"passes, 3 warnings"``): :func:`~.display.verdict_text`."""
        from ..display import verdict_text

        failed = sum(1 for _, c in self.checks if c.passed is False)
        warnings = dict.fromkeys([*self.warnings, *(w for s in self.sections for w in s.warnings)])
        return verdict_text(failed, len(warnings))

    def to_dict(self) -> dict[str, Any]:
        """The report as JSON-ready data (results.json, :data:`RESULTS_VERSION`): every number once,
        under ``analysis``; a section holds only presentation (its title, verdict, warnings,
        figure files) and references into ``analysis`` by path (``"analysis.layout"``,
        ``"analysis.checks[3]"``). A report without an analysis keeps its sections' own data."""
        checks = [] if self.analysis is None else list(self.analysis.checks)

        def check_ref(c: Check) -> Any:
            index = next((i for i, known in enumerate(checks) if known is c), None)
            if index is None:
                index = next((i for i, known in enumerate(checks) if known == c), None)
            return c.to_dict() if index is None else f"analysis.checks[{index}]"

        return {
            "version": RESULTS_VERSION,
            "title": self.title,
            "subtitle": self.subtitle,
            "created": self.created,
            "passed": self.passed,
            "analysis": None if self.analysis is None else self.analysis.to_dict(),
            "warnings": list(self.warnings),
            "sections": {
                s.title: {
                    "skipped": s.skipped,
                    "passed": s.passed,
                    "checks": [check_ref(c) for c in s.checks],
                    "warnings": list(s.warnings),
                    "results": jsonable(s.results),
                    "figures": [f.filename for f in s.figures if f.chart is None],
                }
                for s in self.sections
            },
        }

    def to_html(self) -> str:
        import jinja2

        from .. import __version__

        env = jinja2.Environment(
            loader=jinja2.FileSystemLoader(str(Path(__file__).parent / "templates")),
            autoescape=jinja2.select_autoescape(["html"]),
        )
        env.filters["fmt"] = _display.fmt
        env.filters["check_value"] = _display.check_value_text
        env.filters["check_limit"] = _display.check_limit_text
        return env.get_template("report.html").render(report=self, version=__version__, plotly_js=PLOTLY_JS)

    def write_html(self, path: str | Path) -> Path:
        """Write report.html and, when it has charts, plotly.js beside it (:data:`PLOTLY_JS`)."""
        path = Path(path)
        path.write_text(self.to_html(), encoding="utf-8")
        if self.has_charts:
            source = plotly_js_path()
            if source is None:  # pragma: no cover - plotly is a dependency
                from ..errors import InputError

                raise InputError("the report's charts need plotly.js (pip install plotly), or give --png",
                                 field="figures")
            import shutil

            shutil.copyfile(source, path.parent / PLOTLY_JS)
        return path

    def write_pdf(self, path: str | Path) -> Path:
        try:
            import weasyprint
        except (ImportError, OSError) as exc:  # pragma: no cover - depends on install
            from ..errors import InputError

            raise InputError(
                f"PDF output needs WeasyPrint (pip install 'chaindrive[pdf]'): {exc}"
            ) from exc
        path = Path(path)
        weasyprint.HTML(string=self.to_html()).write_pdf(str(path))
        return path

    def write_figures(self, folder: str | Path) -> list[Path]:
        folder = Path(folder)
        out = []
        for s in self.sections:
            for f in s.figures:
                if f.chart is not None:
                    continue
                p = folder / f.filename
                p.write_bytes(f.png)
                out.append(p)
        return out

