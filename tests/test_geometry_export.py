"""DXF/SVG export round trips and the geometry plot."""

from __future__ import annotations

import xml.etree.ElementTree as ET

import numpy as np
import pytest

from chaindrive.geometry import PocketWheel, Sprocket, TrackDriveWheel
from chaindrive.geometry.export import outline_to_dxf, svg_text

ezdxf = pytest.importorskip("ezdxf")

WHEELS = {
    "sprocket-16B-19": lambda: Sprocket(0.0254, 19, 0.01588, name="16B"),
    "sprocket-ansi": lambda: Sprocket(0.0254, 19, 0.01588, method="ansi"),
    "pocket-18x64-8": lambda: PocketWheel(0.064, 0.018, 8, name="18x64"),
    "track": lambda: TrackDriveWheel(0.17, 13, 0.025, link="cast"),
}


@pytest.mark.parametrize("key", list(WHEELS))
def test_dxf_round_trip(tmp_path, key):
    wheel = WHEELS[key]()
    path = tmp_path / f"{key}.dxf"
    wheel.to_dxf(path)
    o = wheel.outline()
    doc = ezdxf.readfile(path)
    auditor = doc.audit()
    assert not auditor.has_errors, [str(e) for e in auditor.errors]
    assert doc.units == ezdxf.units.MM
    msp = doc.modelspace()
    kinds = [e.dxftype() for e in msp]
    assert kinds.count("LWPOLYLINE") == 1
    assert kinds.count("CIRCLE") == 1 + len(o.circles)
    assert kinds.count("POINT") == len(o.centres)
    assert kinds.count("TEXT") == 1
    layers = {e.dxf.layer for e in msp}
    assert {"OUTLINE", "PITCH_CIRCLE", "CENTRES", "TEXT", *o.circles} == layers
    pl = msp.query("LWPOLYLINE").first
    assert pl.closed and len(pl) == len(o.primitives)
    # extents of the polyline (exact arcs, via ezdxf's bbox) equal the outline's extents in mm
    from ezdxf import bbox

    box = bbox.extents([pl], fast=False)
    xmin, ymin, xmax, ymax = (v * 1e3 for v in o.extents())
    assert box.extmin.x == pytest.approx(xmin, abs=2e-3)
    assert box.extmin.y == pytest.approx(ymin, abs=2e-3)
    assert box.extmax.x == pytest.approx(xmax, abs=2e-3)
    assert box.extmax.y == pytest.approx(ymax, abs=2e-3)
    pitch = msp.query('CIRCLE[layer=="PITCH_CIRCLE"]').first
    assert pitch.dxf.radius == pytest.approx(o.pitch_radius * 1e3, rel=1e-12)
    # bulges reproduce each arc: vertex-to-vertex distances equal the primitives' chords
    pts = np.array([(x, y) for x, y, *_ in pl.get_points("xy")]) / 1e3
    starts = np.array([p.start for p in o.primitives])
    assert pts == pytest.approx(starts, abs=1e-9)


def test_outline_to_dxf_returns_document(tmp_path):
    o = Sprocket(0.0254, 19, 0.01588).outline(form="max")
    doc = outline_to_dxf(o, tmp_path / "x.dxf")
    assert len(doc.modelspace().query("TEXT")) == 0  # no title given


@pytest.mark.parametrize("key", list(WHEELS))
def test_svg(tmp_path, key):
    wheel = WHEELS[key]()
    path = tmp_path / f"{key}.svg"
    text = wheel.to_svg(path)
    assert path.read_text(encoding="utf-8") == text
    root = ET.fromstring(text)
    ns = {"s": "http://www.w3.org/2000/svg"}
    vb = [float(v) for v in root.get("viewBox").split()]
    assert root.get("width").endswith("mm")
    o = wheel.outline()
    rmax = max(abs(v) for v in o.extents()) * 1e3
    assert vb[0] < -rmax and vb[0] + vb[2] > rmax  # the drawing fits, in mm
    d = root.find("s:g[@id='OUTLINE']/s:path", ns).get("d")
    n_arcs = sum(1 for p in o.primitives if hasattr(p, "radius"))
    assert d.count("A ") == n_arcs
    assert d.strip().endswith("Z")
    assert len(root.findall("s:g[@id='CENTRES']/s:circle", ns)) == len(o.centres)


def test_svg_escapes_title():
    o = PocketWheel(0.064, 0.018, 8).outline()
    assert "&lt;b&gt;" in svg_text(o, "<b>")


def test_geometry_plot(tmp_path):
    pytest.importorskip("matplotlib")
    from chaindrive.plotting.geometry import geometry_plot

    for key, make in WHEELS.items():
        fig = geometry_plot(make(), detail=key.startswith("sprocket"))
        ax = fig.axes[0]
        assert "mm" in ax.get_xlabel() and ax.get_title()
        fig.savefig(tmp_path / f"{key}.png", dpi=40)
    fig = geometry_plot(Sprocket(0.0254, 19, 0.01588).outline())
    assert fig.axes[0].get_title() == "Outline"


def test_geometry_plot_chain_overlay():
    pytest.importorskip("matplotlib")
    from chaindrive.plotting.geometry import geometry_plot

    labels = lambda fig: [t.get_text() for t in fig.axes[0].get_legend().get_texts()]  # noqa: E731
    assert "rollers" in labels(geometry_plot(WHEELS["sprocket-16B-19"]()))
    assert "rollers" not in labels(geometry_plot(WHEELS["sprocket-16B-19"](), chain=False))
    assert "vertical links (in plane)" in labels(geometry_plot(WHEELS["pocket-18x64-8"]()))
    assert "pins" in labels(geometry_plot(WHEELS["track"](), form="min"))
