"""Exact chain length and the adjustable wheel for any number of wheels (chaindrive.layout.polygon_loop)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from chaindrive import layout as L
from chaindrive.errors import InfeasibleError, InputError, ValidityRangeWarning
from chaindrive.layout.polygon_loop import adjust_loop, chain_length_loop, loop_length_at_phases

P = 0.0254


# ---------------------------------------------------------------- the two-wheel special case


@pytest.mark.parametrize("z1, z2, a, pitch, bar", [
    (19, 57, 1.05, P, None), (9, 25, 0.4, P, None), (6, 11, 0.3, P, None), (8, 8, 4.0, 0.064, 0.018),
    (17, 17, 0.5, P, None),
])
def test_two_wheels_reproduce_the_hull_model(z1, z2, a, pitch, bar):
    # reference: chain_length_polygon / centre_distance_polygon (convex hull of the two
    # polygons over the same phase grid, Cauchy's formula, itself tested against Qhull)
    hull = L.chain_length_polygon(pitch, z1, z2, a, bar_diameter=bar, phases=6)
    loop = chain_length_loop(pitch, [[0, 0], [a, 0]], [z1, z2], bar_diameter=bar, phases=6)
    assert loop.exact
    assert loop.links_min == pytest.approx(hull.links_min, abs=1e-9)
    assert loop.links_max == pytest.approx(hull.links_max, abs=1e-9)
    assert loop.links_mean == pytest.approx(hull.links_mean, abs=1e-9)
    links = int(L.even_links(hull.links_max))
    cd = L.centre_distance_polygon(pitch, z1, z2, links, bar_diameter=bar, phases=6)
    moved = adjust_loop(pitch, [[0, 0], [a, 0]], [z1, z2], links, 1, [1, 0], bar_diameter=bar, phases=6)
    assert a + moved.taut == pytest.approx(cd.taut, abs=1e-9)
    assert a + moved.loose == pytest.approx(cd.loose, abs=1e-9)
    assert a + moved.circles == pytest.approx(cd.circles, abs=1e-9)


def test_equal_wheels_in_equal_phase():
    # exact special case: the hull is the polygon swept along the centre line, X = z + 2a/p
    length = loop_length_at_phases(P, [[0, 0], [1, 0]], [19, 19], [0.3, 0.3])
    assert length / P == pytest.approx(19 + 2 / P, abs=1e-9)


# ---------------------------------------------------------------- independent computations


@pytest.mark.parametrize("teeth", [9, 19, 30])
def test_equal_wheels_in_equal_phase_at_the_corners_of_a_convex_polygon(teeth):
    # exact closed form: the hull of translates of one convex polygon P to the corners of a
    # convex polygon C is the Minkowski sum P ⊕ C, and perimeters add under Minkowski sums
    # (Cauchy's formula: support functions add), so L = z p + perimeter(C)
    centres = np.array([[0, 0], [1.2, -0.1], [1.6, 0.5], [0.9, 1.1], [-0.2, 0.7]])
    perimeter = float(np.sum(np.hypot(*(np.roll(centres, -1, axis=0) - centres).T)))
    length = loop_length_at_phases(P, centres, [teeth] * 5, [0.37] * 5)
    assert length == pytest.approx(teeth * P + perimeter, abs=1e-12)



def _qhull_length(centres, teeth, phases, pitch=P):
    vertices = np.vstack([L.pitch_polygon_vertices(pitch, z, f, centre=c) for z, f, c in zip(teeth, phases, centres, strict=True)])
    return L._hull_perimeter(vertices)


@settings(max_examples=30, deadline=None)
@given(st.lists(st.floats(0, 2 * math.pi), min_size=4, max_size=4), st.floats(-0.3, 0.3),
       st.lists(st.integers(6, 40), min_size=4, max_size=4))
def test_wheels_inside_the_loop_equal_the_convex_hull(phases, shift, teeth):
    # independent: with every wheel inside the loop and on the hull, the taut chain is the
    # boundary of the convex hull of all seated hinges; its perimeter by Qhull
    centres = np.array([[0, 0], [1.0, 0.1 + shift], [0.6, 0.7], [-0.2, 0.5]])
    assert loop_length_at_phases(P, centres, teeth, phases) == pytest.approx(
        _qhull_length(centres, teeth, phases), abs=1e-12)


def _brute_force_length(centres, teeth, sides, phases, pitch=P):
    """Chain length by exhaustive search: every vertex pair tried as a span, the supporting
    one kept (all hinges of both wheels on the side the chain passes them), then the
    polygon sides walked hinge by hinge from the entry to the exit hinge of each wheel."""
    n = len(teeth)
    polys = [L.pitch_polygon_vertices(pitch, z, f, centre=c) for z, f, c in zip(teeth, phases, centres, strict=True)]
    radii = [float(L.pitch_radius(pitch, z)) for z in teeth]
    circle = L.wrap_layout(centres, radii, sides)
    spans = []
    for i in range(n):
        j = (i + 1) % n
        A, B = polys[i], polys[j]
        t = B[None, :, :] - A[:, None, :]  # every pair (a, b)

        def side_of(points, t=t, A=A):
            rel = points[None, None, :, :] - A[:, None, None, :]
            return t[..., None, 0] * rel[..., 1] - t[..., None, 1] * rel[..., 0]

        supporting = (np.all(sides[i] * side_of(A) >= -1e-12, axis=-1)
                      & np.all(sides[j] * side_of(B) >= -1e-12, axis=-1))
        ang = np.arctan2(t[..., 1], t[..., 0])
        off = np.abs(np.angle(np.exp(1j * (ang - circle.span_angle[i]))))
        a, b = np.unravel_index(np.argmin(np.where(supporting, off, np.inf)), off.shape)
        spans.append((int(a), int(b), float(np.hypot(*t[a, b]))))  # the supporting line next to the circles'
    total = sum(s[2] for s in spans)
    for i in range(n):
        k_in, k_out, z = spans[(i - 1) % n][1], spans[i][0], teeth[i]
        steps = ((k_out - k_in) * sides[i]) % z
        # whole turns: the wrap on the polygon is within a tooth of the circle's wrap
        steps += z * round((circle.wrap_angle[i] * z / (2 * math.pi) - steps) / z)
        k = k_in
        for _ in range(steps):
            nxt = (k + sides[i]) % z
            total += np.hypot(*(polys[i][nxt] - polys[i][k]))
            k = nxt
    return total


@pytest.mark.parametrize("seed", range(6))
def test_idler_on_the_back_matches_brute_force(seed):
    # a motor sprocket, a back-side idler pressing the lower span up, two machine sprockets
    rng = np.random.default_rng(seed)
    centres = np.array([[0, 0], [0.45, 0.03], [0.9, 0], [0.5, 0.6]])
    teeth, sides = [19, 13, 25, 17], [1, -1, 1, 1]
    phases = rng.uniform(0, 2 * math.pi, 4)
    assert loop_length_at_phases(P, centres, teeth, phases, sides) == pytest.approx(
        _brute_force_length(centres, teeth, sides, phases), abs=1e-12)


def test_many_teeth_tend_to_the_pitch_circles():
    # limiting case: the polygon tends to its circle (error ~ 1/z²)
    centres = [[0, 0], [0.45, 0.03], [0.9, 0], [0.5, 0.6]]
    sides = [1, -1, 1, 1]
    errors = []
    for scale in (1, 4):
        teeth = [19 * scale, 13 * scale, 25 * scale, 17 * scale]
        pitch = P / scale
        r = chain_length_loop(pitch, centres, teeth, sides, phases=4)
        errors.append(abs(r.links_mean - r.links_circles) * pitch)
    assert errors[1] < errors[0] / 10


def test_toothless_idler_on_circles():
    # a toothless idler is a circle: with every wheel toothless... the sprockets as polygons,
    # the idler's wrap on its circle; many teeth -> the circle model
    centres = [[0, 0], [0.45, 0.03], [0.9, 0]]
    r = chain_length_loop(P / 8, centres, [19 * 8, None, 25 * 8], [1, -1, 1], diameters=[None, 0.1, None], phases=3)
    circles = L.wrap_layout(centres, [float(L.pitch_radius(P / 8, 19 * 8)), 0.05, float(L.pitch_radius(P / 8, 25 * 8))],
                            [1, -1, 1]).length / (P / 8)
    assert r.exact
    assert r.links_mean == pytest.approx(circles, abs=0.05)


def test_regression_three_wheels():
    # regression (this implementation, 2026-11-25)
    r = chain_length_loop(P, [[0, 0], [1, 0], [0.5, 0.6]], [19, 19, 19], phases=4)
    assert (r.links_min, r.links_max) == pytest.approx((119.86525, 119.87099), abs=1e-4)


# ---------------------------------------------------------------- the adjustable wheel


def test_adjustable_idler_fits_the_links():
    centres = np.array([[0, 0], [0.5, -0.02], [1.0, 0]])
    teeth, sides = [19, 15, 25], [1, -1, 1]
    r = adjust_loop(P, centres, teeth, 104, 1, [0, 1], sides, phases=6)
    assert r.exact
    moved = centres.copy()
    moved[1] = r.position
    assert chain_length_loop(P, moved, teeth, sides, phases=6).links_max == pytest.approx(104, abs=1e-9)
    assert r.loose > r.taut  # the loosest phase needs the idler further in


def test_adjustable_wheel_errors():
    with pytest.raises(InputError, match="links must be a whole number"):
        adjust_loop(P, [[0, 0], [1, 0]], [19, 19], 98.5, 1, [1, 0])
    with pytest.raises(InputError, match="wheel must be an index"):
        adjust_loop(P, [[0, 0], [1, 0]], [19, 19], 98, 2, [1, 0])
    with pytest.raises(InputError, match="direction must be a non-zero"):
        adjust_loop(P, [[0, 0], [1, 0]], [19, 19], 98, 1, [0, 0])
    with pytest.raises(InfeasibleError, match="no chain path"):
        adjust_loop(P, [[0, 0], [0.5, -0.02], [1.0, 0]], [19, 15, 25], 60, 1, [0, 1], [1, -1, 1])


def test_input_errors():
    with pytest.raises(InputError, match="centres must have shape"):
        chain_length_loop(P, [[0, 0]], [19])
    with pytest.raises(InputError, match="teeth must give one entry per wheel"):
        chain_length_loop(P, [[0, 0], [1, 0]], [19])
    with pytest.raises(InputError, match="sides must be"):
        chain_length_loop(P, [[0, 0], [1, 0]], [19, 19], [1, 0])
    with pytest.raises(InputError, match="toothless wheel needs a diameter"):
        chain_length_loop(P, [[0, 0], [1, 0], [0.5, 0.5]], [19, 19, None])
    with pytest.raises(InputError, match="phases must be a whole number"):
        chain_length_loop(P, [[0, 0], [1, 0]], [19, 19], phases=0)
    with pytest.raises(InputError, match="phases must give one angle per wheel"):
        loop_length_at_phases(P, [[0, 0], [1, 0]], [19, 19], [0.0])


def test_grazed_idler_falls_back_to_circles_with_a_warning():
    # a back-side idler that reaches 0.1 mm past the pitch circles' common tangent: the
    # chain on the polygons (spans up to R (1 - cos(π/z)) higher) does not touch it
    R = float(L.pitch_radius(P, 19))
    centres = [[0, 0], [0.5, -R - 0.025 + 1e-4], [1.0, 0]]
    with pytest.warns(ValidityRangeWarning, match="pitch circles"):
        r = chain_length_loop(P, centres, [19, None, 19], [1, -1, 1], diameters=[None, 0.05, None], phases=4)
    assert not r.exact
    assert r.links_max == r.links_circles
    with pytest.raises(InfeasibleError, match="no polygon path at these phases"):
        loop_length_at_phases(P, centres, [19, None, 19], [0.0, 0.0, 0.0], [1, -1, 1], diameters=[None, 0.05, None])


# ---------------------------------------------------------------- the multi-wheel example


def test_multi_wheel_example_length_matches_brute_force():
    # acceptance: examples/multi_wheel.toml (motor sprocket, back-side take-up idler, two
    # machine sprockets) analyzes, and its exact length at the adjusted idler position equals
    # the exhaustive-search computation above over every phase combination of a 3-phase grid
    import itertools

    from chaindrive.analysis import analyze_drive
    from chaindrive.drive import load_project

    drive = load_project(Path(__file__).resolve().parents[1] / "examples" / "multi_wheel.toml")
    a = analyze_drive(drive)
    lay = a.layout
    assert lay.loop.exact and lay.adjustment.exact
    # (150 links since machine B sits at 121.9° of wrap, issue 30: 144 before, at 117.8°;
    # (764, 791) mm gave 120.5° but a static assembly that did not converge)
    assert lay.links == 150
    assert lay.loop.links_max == pytest.approx(150, abs=1e-9)  # the idler set so that 150 links are taut
    teeth = [w.teeth for w in drive.wheels]
    sides = [w.side for w in drive.wheels]
    centres = lay.wrap.centres
    pitch = drive.pitch
    grids = [np.arange(3) * (2 * math.pi / z) / 3 for z in teeth]
    brute = [_brute_force_length(centres, teeth, sides, np.array(f), pitch) / pitch
             for f in itertools.product(*grids)]
    exact = chain_length_loop(pitch, centres, teeth, sides, phases=3)
    assert exact.links_max == pytest.approx(max(brute), abs=1e-9)
    assert exact.links_min == pytest.approx(min(brute), abs=1e-9)
    assert exact.links_mean == pytest.approx(np.mean(brute), abs=1e-9)
    # cross-check: the pitch circles with each wrap counted in seated links (a different
    # approximation) lies within the polygonal play
    assert abs(lay.links_required - lay.loop.links_mean) < 2e-3
    # the power split: the tension rises by 60 % and 40 % of the effective pull
    t = a.loads
    k = drive.driving_index
    assert t.span_tensions[k] == pytest.approx(t.slack)
    assert t.span_tensions[2] - t.span_tensions[1] == pytest.approx(0.6 * t.effective_pull)
    assert t.span_tensions[3] - t.span_tensions[2] == pytest.approx(0.4 * t.effective_pull)
    assert t.tight == pytest.approx(max(t.span_tensions) + t.centrifugal)


def test_toothless_wheels_only_give_the_pitch_circle_length():
    # independent: with no toothed wheel the path is the belt on the circles (wrap_layout,
    # closed-form tangents), whatever the sides
    centres = [[0, 0], [0.45, 0.03], [0.9, 0], [0.5, 0.6]]
    diameters = [0.2, 0.08, 0.3, 0.15]
    sides = [1, -1, 1, 1]
    r = chain_length_loop(P, centres, [None] * 4, sides, diameters=diameters)
    circles = L.wrap_layout(centres, [d / 2 for d in diameters], sides).length / P
    assert r.exact
    assert (r.links_min, r.links_max, r.links_mean) == pytest.approx((circles,) * 3, abs=1e-12)


def test_phases_bounded_by_the_max_plus_product():
    """The API fuzz at 10,000 inputs (seed 20261129): drive_layout(phases=1000) on a loop asked
    for a 1000³ array (7.45 GiB); the loop's phases are bounded by the cube root of the grid limit."""
    with pytest.raises(InputError, match=r"phases must be a whole number in \[1, 271\] for a loop"):
        chain_length_loop(0.0127, [[0.0, 0.0], [0.3, 0.0], [0.15, 0.2]], [9, 9, 9], phases=272)
