"""Calculation report: sections of tables, checks and figures, rendered to HTML or PDF.

The HTML is self-contained (figures embedded as base64 PNG, CSS inline) so that one file
is the calculation record. PDF is rendered from the same HTML with WeasyPrint.
"""

from __future__ import annotations

import base64
import dataclasses
import datetime as _dt
import io
import sys
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .._results import Result, jsonable
from ..analysis.checks import Check
from . import display as _display

if TYPE_CHECKING:
    from matplotlib.figure import Figure as MatplotlibFigure

__all__ = ["Table", "Figure", "Section", "Report"]


@dataclasses.dataclass(frozen=True)
class Table(Result):
    """A table with a caption, headers and rows of plain values."""

    caption: str
    headers: list[str]
    rows: list[list[Any]]


@dataclasses.dataclass
class Figure:
    """A figure: caption plus PNG bytes (and the file name it is saved under)."""

    caption: str
    png: bytes
    filename: str

    @classmethod
    def from_matplotlib(cls, fig: MatplotlibFigure, caption: str, filename: str, dpi: int = 100) -> Figure:
        buf = io.BytesIO()
        if fig.get_layout_engine() is None:
            # one pass of the tight layout inside savefig's single draw (constrained layout
            # iterates and bbox_inches="tight" draws twice); a plot that needs another
            # engine (a legend outside its axes) sets it where it is made
            fig.set_layout_engine("tight", pad=0.6)
        fig.savefig(buf, format="png", dpi=dpi)
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
    def checks(self) -> list[tuple[str, Check]]:
        return [(s.title, c) for s in self.sections for c in s.checks]

    @property
    def passed(self) -> bool:
        if self.analysis is not None:
            return bool(self.analysis.passed)
        return all(s.passed for s in self.sections)

    def to_dict(self) -> dict[str, Any]:
        return {
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
                    "checks": [c.to_dict() for c in s.checks],
                    "warnings": list(s.warnings),
                    "results": jsonable(s.results),
                    "figures": [f.filename for f in s.figures],
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
        return env.get_template("report.html").render(report=self, version=__version__)

    def write_html(self, path: str | Path) -> Path:
        path = Path(path)
        path.write_text(self.to_html(), encoding="utf-8")
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
                p = folder / f.filename
                p.write_bytes(f.png)
                out.append(p)
        return out

