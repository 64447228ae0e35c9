"""The report's figures: drawn once on the Agg canvas (the same pixels as savefig), and the
same report whether one process draws them or a forked helper shares them."""

from __future__ import annotations

import io
import sys
import warnings

import numpy as np
import pytest

from _shared import EXAMPLES
from chaindrive.drive import load_project
from chaindrive.workflows import _figures
from chaindrive.workflows.analyze import report_from_analysis

pytest.importorskip("matplotlib")


def _pixels(png: bytes) -> np.ndarray:
    from PIL import Image

    return np.asarray(Image.open(io.BytesIO(png)))


def test_direct_agg_png_has_the_pixels_of_savefig():
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure as MplFigure

    from chaindrive.workflows.report import Figure

    def make():
        fig = MplFigure(figsize=(4, 3), layout="constrained")
        FigureCanvasAgg(fig)
        ax = fig.subplots()
        ax.plot([0, 1, 2], [1e-3, 3e-3, 2e-3], label="a line")
        ax.set_title("a title")
        ax.legend()
        return fig

    fig = make()
    ours = Figure.from_matplotlib(fig, "c", "x.png").png
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=100)
    assert np.array_equal(_pixels(ours), _pixels(buf.getvalue()))


def test_offset_text_keeps_matplotlibs_title_placement():
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure as MplFigure

    from chaindrive.workflows.report import _fixed_titles

    fig = MplFigure()
    FigureCanvasAgg(fig)
    plain, shifted = fig.subplots(2, 1)
    plain.plot([0, 1], [0, 1])
    shifted.plot([0, 1], [1e6, 1e6 + 1])  # an offset text beside the title
    for ax in (plain, shifted):
        ax.set_title("t")
    _fixed_titles(fig)
    assert plain._autotitlepos is False
    assert shifted._autotitlepos is True


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="the helper is forked (Linux)")
def test_a_forked_helper_gives_the_same_report(monkeypatch):
    from chaindrive.analysis import analyze_drive

    analysis = analyze_drive(load_project(EXAMPLES / "roller_industrial.toml"))
    serial, _ = report_from_analysis(analysis)
    monkeypatch.setattr(_figures.FigureShare, "available", staticmethod(lambda: True))
    shared, timings = report_from_analysis(analysis, parallel_figures=True)
    assert "figures of the helper process" in timings
    figures = [(f.filename, f.caption) for s in serial.sections for f in s.figures]
    assert figures == [(f.filename, f.caption) for s in shared.sections for f in s.figures]
    for a, b in zip((f for s in serial.sections for f in s.figures), (f for s in shared.sections for f in s.figures),
                    strict=True):
        assert np.array_equal(_pixels(a.png), _pixels(b.png)), a.filename
    assert serial.warnings == shared.warnings


def test_a_figure_the_helper_cannot_draw_is_drawn_here(monkeypatch):
    from chaindrive.workflows.report import Section

    monkeypatch.setattr(_figures.FigureShare, "collect", lambda self: {})  # a helper that sent nothing

    def run(share):  # the helper claims every figure and draws none
        for i in range(3):
            share.claim(i)

    share = _figures.FigureShare(run)
    share._process.join()
    figures = _figures.Figures(True, share)
    section = Section("s")

    def make():
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure as MplFigure

        warnings.warn("drawn", UserWarning, stacklevel=1)
        fig = MplFigure(figsize=(2, 2))
        FigureCanvasAgg(fig)
        fig.subplots().plot([0, 1])
        return fig

    figures(section, make, "c", "a.png")
    assert section.figures[0].png == b""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        figures.finish()
    assert section.figures[0].png.startswith(b"\x89PNG")
    assert [str(w.message) for w in caught] == ["drawn"]
