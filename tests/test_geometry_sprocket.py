"""Tests of ISO 606 / ANSI sprocket dimensions and tooth outlines (chaindrive.geometry.sprocket)."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from chaindrive.errors import InfeasibleError, InputError, UnknownNameError, ValidityRangeWarning
from chaindrive.geometry import sprocket as S
from chaindrive.geometry.outline import Arc, Line
from chaindrive.geometry.sprocket import (
    Sprocket,
    ansi_tooth_form,
    flank_radius_limits,
    max_hub_diameter,
    measurement_over_pins,
    pitch_diameter,
    root_diameter,
    seating_angle_limits,
    seating_radius_limits,
    sprocket_outline,
    tip_diameter_limits,
    tooth_height_limits,
    tooth_side_relief_limits,
    tooth_width,
)

IN = 0.0254
MM = 1e-3
# 16B-1 (ISO 606 table 1): p = 25.4 mm, d1 = 15.88 mm, b1 = 17.02 mm, h2 = 21.08 mm
P16B, D16B, B16B, H16B = 25.4 * MM, 15.88 * MM, 17.02 * MM, 21.08 * MM


# ----------------------------------------------------------------- published values
def test_pitch_and_root_diameter_din8196_worked_example():
    # Worked example for DIN 8196 sprockets (simsonforum.net thread "neuer Kettensatz fällig",
    # post 1120956): z = 34, p = 12.7 mm, d1 = 7.75 mm -> d = 137.64 mm, df = 129.89 mm;
    # with d1 = 8.51 mm (TGL 086 chain) df = 129.13 mm.
    assert pitch_diameter(12.7 * MM, 34) / MM == pytest.approx(137.64, abs=0.005)
    assert root_diameter(12.7 * MM, 34, 7.75 * MM) / MM == pytest.approx(129.89, abs=0.005)
    assert root_diameter(12.7 * MM, 34, 8.51 * MM) / MM == pytest.approx(129.13, abs=0.005)


def test_pitch_diameter_catalogue_example():
    # Sprocket maker's worked example (Hebei Ever-Power "Standard sprocket size calculation",
    # wheelsprocket.xyz, 2015): No. 120 (p = 38.1 mm), 25 teeth: pitch diameter factor 7.9789,
    # PCD = 303.99 mm; outer diameter factor 8.516, OD = 324.46 mm. (1/sin(7.2°) = 7.97870: the
    # printed factor is 2.5e-5 high, inside the catalogue's rounding of PCD to 0.01 mm.)
    assert pitch_diameter(38.1 * MM, 25) / MM == pytest.approx(303.99, abs=0.01)
    assert pitch_diameter(1.0, 25) == pytest.approx(7.9789, rel=5e-5)
    f = ansi_tooth_form(38.1 * MM, 25, 22.23 * MM)
    assert float(f.outside_diameter_turned) / MM == pytest.approx(324.46, abs=0.05)


def test_ansi_outside_diameter_published_table():
    # Published OD table (pegaswitch.com "What is sprocket diameter?", inches):
    # #80 (1 in): 36 T 12.030, 37 T 12.349, 38 T 12.668; #25 (1/4 in): 3.008, 3.087, 3.167;
    # #40 (1/2 in), 60 T: 9.841. These are ASME B29.1 turned ODs P (0.6 + cot(180°/N)).
    for pitch_in, z, od in [(1, 36, 12.030), (1, 37, 12.349), (1, 38, 12.668), (0.25, 36, 3.008),
                            (0.25, 37, 3.087), (0.25, 38, 3.167), (0.5, 60, 9.841)]:
        roller = {1: 0.625, 0.25: 0.130, 0.5: 0.312}[pitch_in] * IN
        f = ansi_tooth_form(pitch_in * IN, z, roller)
        assert float(f.outside_diameter_turned) / IN == pytest.approx(od, abs=6e-4)


def test_pitch_diameter_equals_polygon_circumcircle():
    # independent: circumradius of a regular z-gon of side p from the chord relation,
    # solved numerically
    from scipy.optimize import brentq

    for z in (9, 19, 64):
        r = brentq(lambda r, z=z: 2 * r * math.sin(math.pi / z) - P16B, P16B / 2, 100 * P16B)
        assert float(pitch_diameter(P16B, z)) == pytest.approx(2 * r, rel=1e-12)


def test_iso_16b_19_regression_and_hand_values():
    # hand calculation with the ISO 606:2015 clause 5 formulas (mm):
    d = 25.4 / math.sin(math.pi / 19)
    lo, hi = tip_diameter_limits(P16B, 19, D16B)
    assert hi / MM == pytest.approx(d + 1.25 * 25.4 - 15.88, rel=1e-12)
    assert lo / MM == pytest.approx(d + 25.4 * (1 - 1.6 / 19) - 15.88, rel=1e-12)
    assert float(hi) == pytest.approx(0.17018855905274619, rel=1e-12)  # regression
    ri = seating_radius_limits(D16B)
    assert ri[0] / MM == pytest.approx(0.505 * 15.88)
    assert ri[1] / MM == pytest.approx(0.505 * 15.88 + 0.069 * 15.88 ** (1 / 3))
    a = seating_angle_limits(19)
    assert np.degrees(a) == pytest.approx([120 - 90 / 19, 140 - 90 / 19])
    re = flank_radius_limits(D16B, 19)
    assert np.array(re) / MM == pytest.approx([0.12 * 15.88 * 21, 0.008 * 15.88 * (361 + 180)])
    ha = tooth_height_limits(P16B, 19, D16B)
    assert np.array(ha) / MM == pytest.approx([0.5 * (25.4 - 15.88), 0.625 * 25.4 - 0.5 * 15.88 + 0.8 * 25.4 / 19])
    assert max_hub_diameter(P16B, 19, H16B) / MM == pytest.approx(
        25.4 / math.tan(math.pi / 19) - 1.04 * 21.08 - 0.76
    )
    assert np.array(tooth_side_relief_limits(P16B)) / MM == pytest.approx([2.54, 3.81])


def test_tooth_width_factors():
    # ISO 606 / DIN 8196 face width table as summarised on tandwiel.info ("Roller chain wheels"):
    # simplex 0.93 b1 (p <= 12.7) / 0.95 b1; duplex, triplex 0.91 / 0.93; quadruple 0.88 / 0.93.
    # A textbook worked example (Scilab solution 14.5 of a machine design text) uses 0.95 b1, p > 12.7.
    assert tooth_width(P16B, B16B) == pytest.approx(0.95 * B16B)
    assert tooth_width(12.7 * MM, 7.85 * MM) == pytest.approx(0.93 * 7.85 * MM)
    assert tooth_width(P16B, B16B, strands=2) == pytest.approx(0.93 * B16B)
    assert tooth_width(12.7 * MM, B16B, strands=4) == pytest.approx(0.88 * B16B)
    assert tooth_width(P16B, B16B, strands=3) == pytest.approx(0.93 * B16B)
    assert tooth_width(12.7 * MM, B16B, strands=3) == pytest.approx(0.91 * B16B)


def test_ansi_tooth_form_against_worked_sheet():
    # "Equations for the Design of Standard Sprocket Teeth" (GEARS-IDS sheet, after the ACA
    # handbook / Machinery's Handbook): P = 1 in, N = 28, Dr = 0.625 in gives
    # PD 8.9314, Ds 0.6311, R 0.3156, A 37.1429, B 16.0000, ac 0.5000, M 0.3986, T 0.3019,
    # E 0.8156, xy 0.2270, yz 0.0844, ab 0.8750, W 0.8695, V 0.0980, F 0.5114, H 0.3477, S 0.5358
    f = ansi_tooth_form(IN, 28, 0.625 * IN)
    got = {k: float(v) / IN for k, v in f.to_dict().items()}
    expected = {"seating_curve_diameter": 0.6311, "seating_radius": 0.3156, "ac": 0.5, "m": 0.3986,
                "t": 0.3019, "working_radius": 0.8156, "chord_xy": 0.2270, "line_yz": 0.0844,
                "ab": 0.8750, "w": 0.8695, "v": 0.0980, "topping_radius": 0.5114, "h": 0.3477,
                "s": 0.5358}
    for k, v in expected.items():
        assert got[k] == pytest.approx(v, abs=6e-5), k
    assert np.degrees(float(f.angle_a)) == pytest.approx(37.1429, abs=6e-5)
    assert np.degrees(float(f.angle_b)) == pytest.approx(16.0, abs=6e-5)
    assert pitch_diameter(IN, 28) / IN == pytest.approx(8.9314, abs=6e-5)


def test_measurement_over_pins_vs_asme_caliper_and_geometry():
    # ASME B29.1 caliper diameter (amesweb summary): even z -> PD − Dr, odd -> PD cos(90°/N) − Dr.
    # Measurement over pins of diameter Dr = caliper + 2 Dr.
    for z in (18, 19):
        d = float(pitch_diameter(P16B, z))
        caliper = d - D16B if z % 2 == 0 else d * math.cos(math.pi / (2 * z)) - D16B
        assert measurement_over_pins(P16B, z, D16B) == pytest.approx(caliper + 2 * D16B, rel=1e-12)
        # independent: the largest distance between two roller seat centres of the outline
        c = sprocket_outline(P16B, z, D16B).centres
        dist = np.max(np.hypot(*(c[:, None, :] - c[None, :, :]).transpose(2, 0, 1)))
        assert measurement_over_pins(P16B, z, D16B) == pytest.approx(dist + D16B, rel=1e-12)


# ----------------------------------------------------------------- scalar vs array
def test_scalar_vs_array():
    z = np.array([9, 10, 19, 20, 150])
    arr = measurement_over_pins(P16B, z, D16B)
    assert arr.shape == (5,)
    for zi, v in zip(z, arr, strict=True):
        assert float(measurement_over_pins(P16B, int(zi), D16B)) == v
    lo, hi = tip_diameter_limits(np.array([P16B, 2 * P16B]), 19, np.array([D16B, 2 * D16B]))
    assert lo.shape == hi.shape == (2,)
    assert hi[1] == pytest.approx(2 * hi[0])  # all ISO lengths scale with the chain
    assert np.ndim(pitch_diameter(P16B, 19)) == 0


# ----------------------------------------------------------------- outlines
def _seat_arcs(outline, radius):
    return [p for p in outline.primitives if isinstance(p, Arc) and abs(p.radius - radius) < 1e-12]


@pytest.mark.parametrize("z", [9, 10, 19, 20, 57])
@pytest.mark.parametrize("method,form", [("iso606", "min"), ("iso606", "max"), ("ansi", None)])
def test_outline_closes_has_z_teeth_seats_on_pitch_circle(z, method, form):
    o = sprocket_outline(P16B, z, D16B, method=method, form=form)
    rp = float(pitch_diameter(P16B, z)) / 2
    assert o.closure_gap() < 1e-12
    assert o.area() > 0  # counter-clockwise
    if method == "iso606":
        ri = float(seating_radius_limits(D16B)[0 if form == "min" else 1])
    else:
        ri = float(ansi_tooth_form(P16B, z, D16B).seating_radius)
    seats = _seat_arcs(o, ri)
    assert len(seats) == 2 * z  # each seat is two half arcs (mirror halves)
    centres = {tuple(np.round(a.center, 12)) for a in seats}
    assert len(centres) == z
    for c in centres:
        assert abs(math.hypot(*c) - rp) < 1e-6  # within 1 µm of the pitch circle
    assert np.all(np.abs(np.hypot(*o.centres.T) - rp) < 1e-6)
    # z teeth: z local maxima of the radius along the contour
    poly = o.polyline(32)[:-1]
    r = np.hypot(poly[:, 0], poly[:, 1])
    ang = np.unwrap(np.arctan2(poly[:, 1], poly[:, 0]))
    assert np.all(np.diff(ang) > -1e-9)  # star-shaped: angle never runs back
    bins = np.floor(((ang - np.pi / 2 - np.pi / z) % (2 * np.pi)) / (2 * np.pi / z)).astype(int)
    assert len(set(bins)) == z
    # bottom of the seat at rp − ri, tip inside the ISO limits
    assert r.min() == pytest.approx(rp - ri, abs=1e-9)
    if method == "iso606":
        lo, hi = (float(v) / 2 for v in tip_diameter_limits(P16B, z, D16B))
        assert r.max() <= hi + 1e-9
        assert r.max() == pytest.approx(o.circles["TIP"], abs=1e-9)


def _tangent(prim, at_end):
    if isinstance(prim, Line):
        v = np.subtract(prim.end, prim.start)
        return v / np.hypot(*v)
    a = prim.end_angle if at_end else prim.start_angle
    t = np.array([-math.sin(a), math.cos(a)]) * np.sign(prim.sweep)
    return t


@pytest.mark.parametrize("method", ["iso606", "ansi"])
def test_outline_tangent_continuity_between_seat_flank(method):
    # seat -> flank (ISO) and seat -> working -> line -> topping (ANSI) join without a kink;
    # only the tooth tip corners may be sharp
    o = sprocket_outline(P16B, 19, D16B, method=method)
    prims = o.primitives
    kinks = 0
    for a, b in zip(prims, prims[1:] + prims[:1], strict=True):
        ta, tb = _tangent(a, True), _tangent(b, False)
        if np.dot(ta, tb) < 1 - 1e-9:
            kinks += 1
    assert kinks == 2 * 19  # two tip corners per tooth


def test_ansi_line_yz_is_common_tangent_of_printed_length():
    # derivation check: the straight part computed as the common tangent of the working
    # circle E and the topping circle F has the printed length yz and touches both circles
    for z in (9, 19, 28, 60):
        prims, pointed, zpt, y = S._ansi_half_gap(IN, z, 0.625 * IN, 10 * IN)
        f = ansi_tooth_form(IN, z, 0.625 * IN)
        assert math.dist(zpt, y) == pytest.approx(float(f.line_yz), abs=1e-12)
        top = prims[-4]
        assert math.dist(top.center, zpt) == pytest.approx(float(f.topping_radius), abs=1e-12)


def test_ansi_pointed_od_differs_from_printed_by_seat_clearance():
    # documented discrepancy: our pointed tip lies at rp cos(π/N) + H; the printed pointed OD
    # adds cos(180°/N)(Ds − Dr)
    z = 28
    f = ansi_tooth_form(IN, z, 0.625 * IN)
    prims, pointed, _, _ = S._ansi_half_gap(IN, z, 0.625 * IN, 10 * IN)
    assert pointed
    ours = 2 * math.hypot(*prims[0].start)
    diff = float(f.outside_diameter_pointed) - ours
    assert diff == pytest.approx(math.cos(math.pi / z) * float(f.seating_curve_diameter - 0.625 * IN), abs=1e-12)


def test_tip_diameter_option_and_pointed_teeth():
    lo, hi = (float(v) for v in tip_diameter_limits(P16B, 19, D16B))
    o = sprocket_outline(P16B, 19, D16B, form="max", tip_diameter=hi)
    assert o.circles["TIP"] <= hi / 2 + 1e-12
    # 9 teeth, maximum gap, da max: the flanks meet below da max -> pointed teeth, no tip arc
    o9 = sprocket_outline(P16B, 9, D16B, form="max", tip_diameter=float(tip_diameter_limits(P16B, 9, D16B)[1]))
    assert o9.closure_gap() < 1e-12


# ----------------------------------------------------------------- objects
def test_sprocket_object_from_chain_like_and_dict():
    class FakeChain:
        name = "16B-1"
        pitch = P16B
        roller_diameter = D16B
        inner_width = B16B
        plate_height = H16B
        strands = 1

    s = Sprocket.from_chain(FakeChain(), 19)
    d = s.to_dict()
    assert d["pitch_diameter"] == pytest.approx(float(pitch_diameter(P16B, 19)))
    assert d["tooth_width"] == pytest.approx(0.95 * B16B)
    assert d["max_hub_diameter"] == pytest.approx(float(max_hub_diameter(P16B, 19, H16B)))
    s2 = Sprocket.from_chain({"pitch": P16B, "roller_diameter": D16B}, 19, method="ansi")
    assert s2.to_dict()["ansi"]["topping_radius"] > 0
    assert "ASME" in s2.label()


def test_sprocket_from_catalogue_name():
    chains = pytest.importorskip("chaindrive.chains")
    if not hasattr(chains, "get"):
        pytest.skip("chain catalogue not available")
    s = Sprocket.from_chain("16B", 19)
    assert s.pitch == pytest.approx(P16B)
    assert s.roller_diameter == pytest.approx(D16B)


# ----------------------------------------------------------------- errors
def test_errors():
    with pytest.raises(InputError, match=r"teeth must be a whole number >= 9 .*Annex A"):
        pitch_diameter(P16B, 8)
    with pytest.raises(InputError, match="teeth must be a whole number >= 9"):
        pitch_diameter(P16B, 19.5)
    with pytest.raises(InputError, match=r"pitch must be positive"):
        pitch_diameter(-P16B, 19)
    with pytest.raises(InputError, match=r"roller_diameter must be smaller than pitch"):
        root_diameter(P16B, 19, P16B)
    with pytest.raises(InputError, match=r"form must be 'min' .* or 'max'"):
        sprocket_outline(P16B, 19, D16B, form="mid")
    with pytest.raises(InputError, match=r"ASME B29.1 gives one tooth form"):
        sprocket_outline(P16B, 19, D16B, method="ansi", form="min")
    with pytest.raises(InputError, match=r"tip_diameter must lie in \[161\.700, 170\.189\] mm"):
        sprocket_outline(P16B, 19, D16B, tip_diameter=0.2)
    with pytest.raises(UnknownNameError, match=r"unknown method 'din'; valid: 'iso606', 'ansi'"):
        sprocket_outline(P16B, 19, D16B, method="din")
    with pytest.raises(UnknownNameError):
        Sprocket(P16B, 19, D16B, method="iso")
    with pytest.raises(InputError, match="no roller_diameter: not a roller chain"):
        Sprocket.from_chain({"name": "18x64", "pitch": 0.064, "roller_diameter": None}, 8)
    with pytest.raises(InputError, match="strands must be a whole number >= 1"):
        tooth_width(P16B, B16B, strands=0)
    with pytest.raises(InfeasibleError, match="no hub fits"):
        max_hub_diameter(P16B, 9, 0.1)
    with pytest.raises(InputError, match="must be scalars"):
        sprocket_outline(P16B, [19, 20], D16B)
    with pytest.raises(InfeasibleError, match="topping radius"):
        ansi_tooth_form(P16B, 19, 0.2 * P16B)


def test_warning_above_annex_a():
    with pytest.warns(ValidityRangeWarning, match="outside ISO 606:2015 Annex A"):
        pitch_diameter(P16B, 151)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        pitch_diameter(P16B, 150)


# ----------------------------------------------------------------- properties
@settings(max_examples=25, deadline=None)
@given(
    z=st.integers(min_value=9, max_value=150),
    ratio=st.floats(min_value=0.5, max_value=0.7),
    form=st.sampled_from(["min", "max"]),
)
def test_property_iso_outline(z, ratio, form):
    p = 0.0254
    d1 = ratio * p
    o = sprocket_outline(p, z, d1, form=form)
    rp = p / (2 * math.sin(math.pi / z))
    assert o.closure_gap() < 1e-12
    r = np.hypot(*o.polyline(8).T)
    lo, hi = (float(v) / 2 for v in tip_diameter_limits(p, z, d1))
    ri = float(seating_radius_limits(d1)[0 if form == "min" else 1])
    assert r.min() >= rp - ri - 1e-12
    assert r.max() <= hi + 1e-12
    assert np.all(np.abs(np.hypot(*o.centres.T) - rp) < 1e-9)


@settings(max_examples=40, deadline=None)
@given(z=st.integers(min_value=9, max_value=150), d1=st.floats(min_value=1e-3, max_value=0.1))
def test_property_iso_limits_ordered(z, d1):
    a = seating_angle_limits(z)
    re = flank_radius_limits(d1, z)
    ri = seating_radius_limits(d1)
    assert a[0] < a[1] and re[0] < re[1] and ri[0] < ri[1]


@pytest.mark.parametrize("z", [9, 19, 60])
def test_minimum_gap_form_removes_less_material(z):
    # independent check of the ISO pairing (ri min, α max, re max) = minimum tooth gap form:
    # with the same tip diameter its gaps are smaller, so the wheel's area is larger
    lo, hi = (float(v) for v in tip_diameter_limits(P16B, z, D16B))
    da = 0.5 * (lo + hi)
    a_min = sprocket_outline(P16B, z, D16B, form="min", tip_diameter=da).area()
    a_max = sprocket_outline(P16B, z, D16B, form="max", tip_diameter=da).area()
    assert a_min > a_max
    # and the brief's swapped pairing (ri min, α min, re min) would not be the tightest gap
    rp = float(pitch_diameter(P16B, z)) / 2
    ri = float(seating_radius_limits(D16B)[0])
    al, ah = (float(v) for v in seating_angle_limits(z))
    rl, rh = (float(v) for v in flank_radius_limits(D16B, z))
    from chaindrive.geometry.outline import Outline
    from chaindrive.geometry.sprocket import _full_from_half, _iso_half_gap

    def area(alpha, re):
        half, _ = _iso_half_gap(rp, z, ri, alpha, re, da / 2)
        return Outline(_full_from_half(half, z), rp, np.zeros((0, 2))).area()

    assert area(ah, rh) == max(area(al, rl), area(ah, rl), area(al, rh), area(ah, rh))


@given(st.floats(-1.0, 1.0), st.floats(-1.0, 1.0), st.floats(0.05, 1.0), st.floats(-1.0, 1.0),
       st.floats(-1.0, 1.0), st.floats(0.05, 1.0))
@settings(max_examples=200, deadline=None)
def test_circle_intersections_lie_on_both_circles(x1, y1, r1, x2, y2, r2):
    # independent check of the shared helper (tooth outline, worn-chain seat): each point is at
    # r1 from c1 and r2 from c2; none exactly when the circles are apart, nested or concentric
    from chaindrive.geometry.outline import circle_intersections

    d = math.hypot(x2 - x1, y2 - y1)
    hit = circle_intersections((x1, y1), r1, (x2, y2), r2)
    if d > r1 + r2 or d < abs(r1 - r2) or d == 0:
        assert hit is None
        return
    assert hit is not None
    for p in hit:
        assert math.hypot(p[0] - x1, p[1] - y1) == pytest.approx(r1, abs=1e-9 / min(1.0, d))
        assert math.hypot(p[0] - x2, p[1] - y2) == pytest.approx(r2, abs=1e-9 / min(1.0, d))
    # the first lies to the left of c1 -> c2
    assert (x2 - x1) * (hit[0][1] - y1) - (y2 - y1) * (hit[0][0] - x1) >= -1e-12
