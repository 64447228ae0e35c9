"""Workshop drawings (DXF) of wheel parts; the hub / keyway table; closed-form part volumes."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from chaindrive.cli import main
from chaindrive.errors import InfeasibleError, InputError
from chaindrive.geometry import PocketWheel, Sprocket
from chaindrive.geometry.hub import (
    bore_limits,
    design_hub,
    keyway_area,
    parallel_key,
    parallel_key_table,
)
from chaindrive.geometry.part import (
    ToothChamfer,
    part_volume,
    plate_volume,
    pocket_wheel_part,
    side_chamfer_moment,
    side_chamfer_thickness,
    sprocket_part,
)

ezdxf = pytest.importorskip("ezdxf")

from chaindrive.geometry.drawing import choose_sheet, part_drawing, render_png, write_drawing  # noqa: E402

MM = 1e-3


@pytest.fixture(scope="module")
def sprocket16b():
    return sprocket_part(Sprocket.from_chain("16B", 19))


@pytest.fixture(scope="module")
def pocket18x64():
    return pocket_wheel_part(PocketWheel.from_chain("18x64", 8))


# --------------------------------------------------------------------------- keyway table
# Reference rows: Siemens Flender catalogue MD 31.1 (2016) p. 7/3 reprints DIN 6885-1:
# 38-44: 12x8, t1 5, d + 3.3; 50-58: 16x10, t1 6, d + 4.3; 95-110: 28x16, t1 10, d + 6.4;
# 200-230: 50x28, t1 17, d + 11.4.
@pytest.mark.parametrize(
    "bore_mm,label,t1,t2",
    [(40, "12 x 8", 5.0, 3.3), (55, "16 x 10", 6.0, 4.3), (100, "28 x 16", 10.0, 6.4), (230, "50 x 28", 17.0, 11.4)],
)
def test_parallel_key_published_rows(bore_mm, label, t1, t2):
    k = parallel_key(bore_mm * MM)
    assert k.label() == label
    assert k.shaft_depth == pytest.approx(t1 * MM) and k.hub_depth == pytest.approx(t2 * MM)
    assert "DIN 6885-1" in k.source


def test_parallel_key_band_edges_and_table_is_contiguous():
    # a band is (over, up to and including]: 30 mm takes 8 x 7, 30.5 mm the 10 x 8 key
    assert parallel_key(30 * MM).label() == "8 x 7"
    assert parallel_key(30.5 * MM).label() == "10 x 8"
    rows = parallel_key_table()
    for a, b in zip(rows, rows[1:], strict=False):
        assert a.shaft_up_to == pytest.approx(b.shaft_over)
        assert b.width >= a.width and b.height >= a.height and b.hub_depth >= a.hub_depth
        assert a.hub_depth < a.height and a.shaft_depth < a.height  # key protrudes from the shaft


@pytest.mark.parametrize("bore", [5 * MM, 6 * MM, 231 * MM])
def test_parallel_key_outside_table(bore):
    with pytest.raises(InputError, match=r"bore must lie in \(6, 230\] mm"):
        parallel_key(bore)


def test_keyway_area_against_pixel_count():
    # independent: count grid points in the strip |x| <= b/2, 0 <= y <= R + t2 outside the bore
    d, b, t2 = 40 * MM, 12 * MM, 3.3 * MM
    n = 2001
    x = np.linspace(-b / 2, b / 2, n)
    y = np.linspace(0, d / 2 + t2, n)
    xx, yy = np.meshgrid(x, y)
    outside = (xx**2 + yy**2 > (d / 2) ** 2).mean() * b * (d / 2 + t2)
    assert float(keyway_area(d, b, t2)) == pytest.approx(outside, rel=2e-3)
    assert float(keyway_area(d, b, t2)) == pytest.approx(43.2502e-6, rel=1e-5)  # regression


def test_keyway_area_errors():
    with pytest.raises(InputError, match="key_width must be smaller than the bore"):
        keyway_area(0.01, 0.012, 0.002)
    with pytest.raises(InputError, match="hub_depth"):
        keyway_area(0.04, 0.012, -0.002)


def test_bore_limits_regression_and_wall():
    lo, hi = bore_limits(0.100)
    assert (lo, hi) == (pytest.approx(6 * MM), pytest.approx(66.2 * MM))
    k = parallel_key(hi)
    assert 0.100 / 2 - (hi / 2 + k.hub_depth) == pytest.approx(k.height)  # the wall is exactly h
    lo, hi = bore_limits(0.100, keyway=False)
    assert hi == pytest.approx(0.08)


@settings(max_examples=60, deadline=None)
@given(outer=st.floats(0.03, 0.45))
def test_bore_limits_property_wall_at_least_one_key_height(outer):
    lo, hi = bore_limits(outer)
    if hi <= lo:
        return
    for bore in np.linspace(lo + 1e-6, hi, 7):
        k = parallel_key(bore)
        assert outer / 2 - (bore / 2 + k.hub_depth) >= k.height - 1e-12


def test_design_hub_defaults_and_choices():
    h = design_hub(max_hub_diameter=0.1295, rim_diameter=0.1383, plate_width=0.0162)
    assert (h.bore, h.hub_diameter) == (pytest.approx(0.055), pytest.approx(0.100))
    assert h.hub_length + 0.0162 == pytest.approx(0.070)  # 1.2 d = 66 -> 70 mm overall
    assert h.keyway_dimension == pytest.approx(0.0593)
    h = design_hub(max_hub_diameter=0.1295, rim_diameter=0.1383, plate_width=0.0162, bore=0.040)
    assert h.hub_diameter == pytest.approx(0.075)  # 1.8 x 40 = 72 -> 75 mm
    h = design_hub(max_hub_diameter=0.1295, rim_diameter=0.1383, plate_width=0.0162, bore=0.040, hub_length=0)
    assert h.hub_diameter == pytest.approx(0.1383) and h.hub_length == 0
    h = design_hub(max_hub_diameter=0.1295, rim_diameter=0.1383, plate_width=0.0162, bore=0.030, keyway=False)
    assert h.key is None and h.keyway_dimension is None


@pytest.mark.parametrize(
    "kw,message",
    [
        ({"bore": 0.080, "hub_diameter": 0.100}, r"bore must lie in \(6.000, 66.200\] mm for the hub diameter 100.000 mm"),
        ({"hub_diameter": 0.140}, r"hub_diameter must be at most 129.500 mm \(dg\)"),
        ({"hub_diameter": 0.010}, r"hub_diameter must be at least"),
        ({"hub_length": -0.01}, "hub_length must be"),
        ({"hub_length": 0.0, "hub_diameter": 0.1}, "hub_diameter has no meaning with hub_length = 0"),
        ({"bore": 0.300}, r"bore must lie in \(6.000, "),
        ({"bore": -0.01}, "bore must be positive"),
        ({"bore": 0.120, "hub_length": 0.0}, r"bore must lie in .* for the rim \(no hub\)"),
    ],
)
def test_design_hub_errors(kw, message):
    with pytest.raises(InputError, match=message):
        design_hub(max_hub_diameter=0.1295, rim_diameter=0.1383, plate_width=0.0162, limit_name="dg", **kw)


# --------------------------------------------------------------------------- chamfer and volume
def test_side_chamfer_thickness_ends():
    w, ra, rx, ba = 0.016169, 0.08509, 0.0254, 0.00254
    rt = ra - math.sqrt(2 * rx * ba - ba * ba)
    t = side_chamfer_thickness([0.0, rt, ra], w, ra, rx, ba)
    assert t == pytest.approx([w, w, w - 2 * ba], rel=1e-12)
    with pytest.raises(InputError, match="side_relief must lie in"):
        side_chamfer_thickness(0.05, 0.004, ra, rx, 0.003)
    with pytest.raises(InputError, match="radius must stay below"):
        side_chamfer_thickness(ra + rx, w, ra, rx, ba)


def test_side_chamfer_moment_against_quadrature():
    from scipy.integrate import quad

    w, ra, rx, ba = 0.016169, 0.08509, 0.0254, 0.00381
    for r in (0.03, 0.075, 0.080, 0.08509, 0.086):
        ref, _ = quad(lambda s: float(side_chamfer_thickness(s, w, ra, rx, ba)) * s, 0, r, points=[ra - 0.0127],
                      epsabs=1e-16, epsrel=1e-12)
        assert float(side_chamfer_moment(r, w, ra, rx, ba)) == pytest.approx(ref, rel=1e-10)
    g = side_chamfer_moment(np.array([0.01, 0.02]), w, ra, rx, ba)
    assert g.shape == (2,)


@pytest.mark.parametrize("chain,teeth,method", [("16B", 19, "iso606"), ("80", 17, "ansi")])
def test_plate_volume_against_ray_integration(chain, teeth, method):
    # independent of the closed form G and of Green's theorem: the outline is star-shaped, so
    # V = ∫ dθ ∫_0^ρ(θ) t(r) r dr with ρ(θ) read off the sampled outline and the inner
    # integral done by the trapezoid rule on a fine radial grid; the ANSI outline has straight
    # flank lines crossing the chamfer zone
    part = sprocket_part(Sprocket.from_chain(chain, teeth, method=method))
    o = part.outline
    ch = part.chamfer
    p = o.polyline(400)
    ang = np.unwrap(np.arctan2(p[:, 1], p[:, 0]))
    rho = np.hypot(p[:, 0], p[:, 1])
    theta = np.linspace(ang[0], ang[0] + 2 * np.pi, 200001)
    rho_t = np.interp(theta, ang, rho)
    r = np.linspace(0, part.tip_radius, 40001)
    f = side_chamfer_thickness(r, part.width, ch.tip_radius, ch.side_radius, ch.side_relief) * r
    inner = np.concatenate([[0.0], np.cumsum(0.5 * (f[1:] + f[:-1]) * np.diff(r))])
    outer = np.interp(rho_t, r, inner)
    ref = float(np.sum(0.5 * (outer[1:] + outer[:-1]) * np.diff(theta)))
    got = plate_volume(o, part.width, ch)
    assert got == pytest.approx(ref, rel=2e-5)
    assert got < plate_volume(o, part.width)  # the chamfer removes material
    assert plate_volume(o, part.width) == pytest.approx(o.area() * part.width, rel=1e-6)


def test_part_volume_regression(sprocket16b, pocket18x64):
    assert part_volume(sprocket16b) == pytest.approx(535.5133e-6, rel=1e-5)
    assert part_volume(pocket18x64) == pytest.approx(5200.944e-6, rel=1e-5)
    d = sprocket16b.to_dict()
    assert d["volume"] == pytest.approx(part_volume(sprocket16b)) and "outline" not in d


def test_sprocket_part_values(sprocket16b):
    p = sprocket16b
    assert p.width == pytest.approx(0.95 * 0.01702)  # ISO 606 bf1 = 0.95 b1 (p > 12.7 mm)
    assert p.chamfer.side_radius == pytest.approx(0.0254) and p.chamfer.side_relief == pytest.approx(0.00254)
    assert 2 * p.tip_radius == pytest.approx(0.17018855905274619, rel=1e-12)
    assert p.total_width == pytest.approx(0.070)
    assert p.form == "min" and p.kind == "sprocket"
    q = sprocket_part(Sprocket.from_chain("16B", 19), tooth_side_relief=0.0038, bore=0.04, hub_length=0.0)
    assert q.chamfer.side_relief == pytest.approx(0.0038) and q.hub.hub_length == 0


@pytest.mark.parametrize(
    "make,kw,err,message",
    [
        (lambda: Sprocket(0.0254, 19, 0.01588), {}, InputError, r"inner_width \(b1\) is needed"),
        (lambda: Sprocket(0.0254, 19, 0.01588, inner_width=0.017, strands=2), {}, InputError, "strands must be 1"),
        (lambda: Sprocket.from_chain("16B", 19), {"tooth_side_relief": 0.001}, InputError,
         r"tooth_side_relief must lie in \[2.540, 3.810\] mm"),
        (lambda: Sprocket.from_chain("16B", 19), {"bore": 0.095}, InputError, "bore must lie in"),
        (lambda: Sprocket.from_chain("16B", 19), {"hub_diameter": 0.135}, InputError,
         "hub_diameter must be at most 129.531 mm"),
    ],
)
def test_sprocket_part_errors(make, kw, err, message):
    with pytest.raises(err, match=message):
        sprocket_part(make(), **kw)


def test_sprocket_part_without_plate_height_limits_hub_to_075_d():
    s = Sprocket(0.0254, 19, 0.01588, inner_width=0.01702)
    p = sprocket_part(s)
    assert p.hub.hub_diameter_range[1] == pytest.approx(0.75 * 0.0254 / math.sin(math.pi / 19))


def test_pocket_wheel_part_values_and_errors(pocket18x64):
    p = pocket18x64
    d = p.dimensions
    assert p.width == pytest.approx(0.021 + 2 * 0.018)  # b + 2d, DIN 22252 18x64 inner width 21 mm
    assert p.groove.width == pytest.approx(0.018)
    assert p.groove.bottom_radius == pytest.approx(d.slot_radius)
    assert p.hub.hub_diameter <= 2 * p.groove.bottom_radius
    with pytest.raises(InputError, match="hub_diameter must be at most 268.330 mm"):
        pocket_wheel_part(PocketWheel.from_chain("18x64", 8), hub_diameter=0.3)
    # a wide link on a small wheel: the groove would reach the pocket floor
    with pytest.raises((InfeasibleError, InputError)):
        pocket_wheel_part(PocketWheel(0.064, 0.018, 5, inner_width=0.2))


def test_tooth_chamfer_properties():
    c = ToothChamfer(tip_radius=0.085, side_radius=0.0254, side_relief=0.00254)
    assert c.depth == pytest.approx(math.sqrt(2 * 0.0254 * 0.00254 - 0.00254**2))
    assert c.start_radius == pytest.approx(0.085 - c.depth)


# --------------------------------------------------------------------------- drawings
def _measurements(doc):
    return [round(d.get_measurement(), 3) for d in doc.modelspace().query("DIMENSION")]


def test_sprocket_drawing_dimensions_and_title_block(sprocket16b):
    doc = part_drawing(sprocket16b, date="2026-11-24")
    auditor = doc.audit()
    assert not auditor.has_errors, [str(e) for e in auditor.errors]
    assert doc.units == ezdxf.units.MM
    m = _measurements(doc)
    dims = sprocket16b.dimensions
    for value in (2 * sprocket16b.tip_radius, dims.root_diameter, dims.pitch_diameter, dims.measurement_over_pins,
                  sprocket16b.width, sprocket16b.chamfer.side_relief, 0.055, 0.100, 0.0593, 0.016, 0.070):
        assert round(value * 1e3, 3) in m, value
    texts = " | ".join(e.dxf.text for e in doc.modelspace().query("TEXT"))
    for needle in ("Sprocket 16B-1 z = 19", "16B-1", "z = 19", "C45", "1:1", "mm", "2026-11-24", "chaindrive 0.1",
                   "Measurement over pins MR", "169.671 mm", "h11", "h14", "rx = 25.4", "16 x 10",
                   "ISO 606 minimum tooth gap form", "A-A"):
        assert needle in texts, needle
    layers = {e.dxf.layer for e in doc.modelspace()}
    assert {"OUTLINE", "CENTER", "DIMENSIONS", "HATCH", "PINS", "TITLE", "FRAME"} <= layers
    assert len(doc.modelspace().query("HATCH")) == 2


def test_pocket_wheel_drawing(pocket18x64):
    doc = part_drawing(pocket18x64, date="2026-11-24")
    assert not doc.audit().has_errors
    m = _measurements(doc)
    for value in (2 * pocket18x64.tip_radius, 2 * pocket18x64.groove.bottom_radius, pocket18x64.groove.width,
                  pocket18x64.width, 2 * pocket18x64.dimensions.pitch_radius, 0.110, 0.200, 0.028):
        assert round(value * 1e3, 3) in m, value
    texts = " | ".join(e.dxf.text for e in doc.modelspace().query("TEXT"))
    assert "Pocket wheel 18x64 z = 8" in texts and "1:2" in texts and "42CrMo4" in texts
    assert "Groove width d + 2c" in texts


def test_choose_sheet(sprocket16b, pocket18x64):
    assert (choose_sheet(sprocket16b).name, choose_sheet(sprocket16b).scale) == ("A2", 1.0)
    s = choose_sheet(pocket18x64)
    assert (s.name, s.scale_label) == ("A2", "1:2")
    big = pocket_wheel_part(PocketWheel(0.064, 0.018, 40))
    assert choose_sheet(big).scale <= 0.2


def test_write_drawing_paths(tmp_path, pocket18x64):
    f = tmp_path / "p.dxf"
    write_drawing(pocket18x64, f, date="2026-11-24")
    assert not ezdxf.readfile(f).audit().has_errors
    before = f.read_bytes()
    with pytest.raises(InputError, match="exists; use --force"):
        write_drawing(pocket18x64, f)
    assert f.read_bytes() == before
    write_drawing(pocket18x64, f, force=True, date="2026-11-25")
    assert f.read_bytes() != before
    with pytest.raises(InputError, match="is a folder"):
        write_drawing(pocket18x64, tmp_path)
    with pytest.raises(InputError, match="does not exist"):
        write_drawing(pocket18x64, tmp_path / "missing" / "p.dxf")
    with pytest.raises(InputError, match="unsupported file type '.dwg'"):
        write_drawing(pocket18x64, tmp_path / "p.dwg")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["p.dxf"]  # no temporary files left


def test_render_png(tmp_path, pocket18x64):
    pytest.importorskip("matplotlib")
    png = tmp_path / "p.png"
    render_png(part_drawing(pocket18x64, date="2026-11-24"), png, dpi=30)
    assert png.read_bytes()[:4] == b"\x89PNG"


# --------------------------------------------------------------------------- CLI
def test_cli_sprocket_dxf_drawing(tmp_path, capsys):
    dxf = tmp_path / "s.dxf"
    assert main(["sprocket", "--chain", "16B", "--teeth", "19", "--dxf", str(dxf), "--bore", "40 mm",
                 "--material", "C45, induction hardened"]) == 0
    out = capsys.readouterr().out
    assert "bore d (H7)" in out and "40.000 mm" in out and "12 x 8 mm" in out and f"wrote {dxf}" in out
    doc = ezdxf.readfile(dxf)
    assert not doc.audit().has_errors
    assert 40.0 in _measurements(doc)
    assert "C45, induction hardened" in [e.dxf.text for e in doc.modelspace().query("TEXT")]
    assert main(["sprocket", "--chain", "16B", "--teeth", "19", "--dxf", str(dxf)]) == 2
    assert "exists; use --force" in capsys.readouterr().err
    assert main(["sprocket", "--chain", "16B", "--teeth", "19", "--dxf", str(dxf), "--force", "--json"]) == 0
    assert capsys.readouterr().out.count('"bore": 0.055') == 1


def test_cli_svg_is_not_overwritten_without_force(tmp_path, capsys):
    svg = tmp_path / "s.svg"
    svg.write_text("keep")
    assert main(["sprocket", "--chain", "16B", "--teeth", "19", "--svg", str(svg)]) == 2
    assert "exists; use --force" in capsys.readouterr().err and svg.read_text() == "keep"
    assert main(["pocket-wheel", "--chain", "18x64", "--teeth", "8", "--svg", str(svg), "--force"]) == 0
    assert svg.read_text().startswith("<?xml")


def test_cli_pocket_wheel_dxf(tmp_path, capsys):
    dxf = tmp_path / "p.dxf"
    assert main(["pocket-wheel", "--chain", "18x64", "--teeth", "8", "--dxf", str(dxf), "--hub-length", "0 mm",
                 "--bore", "100 mm"]) == 0
    assert "28 x 16 mm" in capsys.readouterr().out
    assert not ezdxf.readfile(dxf).audit().has_errors


@pytest.mark.parametrize(
    "argv,message",
    [
        (["sprocket", "--chain", "16B", "--teeth", "19", "--dxf", "{tmp}/s.dxf", "--bore", "80 mm",
          "--hub-diameter", "100 mm"], "bore must lie in (6.000, 66.200] mm"),
        (["sprocket", "--chain", "16B", "--teeth", "19", "--dxf", "{tmp}/s.dxf", "--hub-diameter", "140 mm"],
         "--hub-diameter must be at most 129.531 mm"),
        (["sprocket", "--pitch", "25.4 mm", "--roller-diameter", "15.88 mm", "--teeth", "19", "--dxf", "{tmp}/s.dxf"],
         "--inner-width (b1) is needed"),
        (["sprocket", "--chain", "16B", "--teeth", "19", "--dxf", "{tmp}"], "is a folder"),
        (["sprocket", "--chain", "16B", "--teeth", "19", "--dxf", "{tmp}/no/s.dxf"], "does not exist"),
        (["sprocket", "--chain", "16B", "--teeth", "19", "--dxf", "{tmp}/s.pdf"], "unsupported file type '.pdf'"),
        (["sprocket", "--chain", "16B", "--teeth", "19", "--step", "{tmp}/s.stl"], "unsupported file type '.stl'"),
        (["pocket-wheel", "--chain", "18x64", "--teeth", "8", "--dxf", "{tmp}/p.dxf", "--bore", "150 mm",
          "--hub-diameter", "200 mm"],
         "bore must lie in (6.000, 143.200] mm"),
        (["pocket-wheel", "--chain", "18x64", "--teeth", "8", "--dxf", "{tmp}/p.dxf", "--bore", "3 kg"], "--bore"),
    ],
)
def test_cli_errors(tmp_path, capsys, argv, message):
    argv = [a.replace("{tmp}", str(tmp_path)) for a in argv]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert message in err and "Traceback" not in err and err.count("\n") == 1
    assert list(tmp_path.iterdir()) == []  # nothing written


# --------------------------------------------------------------------------- properties
@settings(max_examples=80, deadline=None)
@given(
    width=st.floats(0.004, 0.05),
    pitch=st.floats(0.008, 0.08),
    fraction=st.floats(0.10, 0.15),
    u=st.floats(0.0, 1.0),
)
def test_chamfer_thickness_property_bounded_and_monotone(width, pitch, fraction, u):
    ba = fraction * pitch
    if 2 * ba >= width:
        return
    ra = 0.2
    r = np.linspace(ra - 0.6 * pitch, ra, 50) * (1 - 1e-12)
    t = side_chamfer_thickness(r, width, ra, pitch, ba)
    assert np.all(t <= width + 1e-15) and np.all(t >= width - 2 * ba - 1e-12)
    assert np.all(np.diff(t) <= 1e-15)  # the chamfer only removes material outwards
    g0, g1 = side_chamfer_moment(np.array([ra * u, ra]), width, ra, pitch, ba)
    # to rounding: at u -> 1 both ends are the same radius (hypothesis found g0 one ulp above g1)
    assert g0 <= g1 * (1 + 1e-12) and g1 <= width * ra * ra / 2 + 1e-18


@settings(max_examples=80, deadline=None)
@given(bore=st.floats(0.0061, 0.23))
def test_keyway_area_property_between_rectangles(bore):
    k = parallel_key(bore)
    r, half = bore / 2, k.width / 2
    a = float(keyway_area(bore, k.width, k.hub_depth))
    assert k.width * k.hub_depth <= a <= k.width * (k.hub_depth + r - math.sqrt(r * r - half * half)) + 1e-15
