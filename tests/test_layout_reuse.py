"""What the analysis computes once and reuses gives the numbers of computing it again."""

from __future__ import annotations

import numpy as np
import pytest

from _shared import EXAMPLES
from chaindrive.drive.clearance import clearance_error
from chaindrive.drive.project import load_project
from chaindrive.errors import InputError
from chaindrive.layout import centre_distance_polygon, chain_length_polygon, wrap_layout


def test_clearance_error_returns_the_wrap_layout_it_drew():
    d = load_project(EXAMPLES / "tractor_track.toml")
    c = np.array([w.position for w in d.wheels], dtype=float)
    drawn = clearance_error(d, c)
    ref = wrap_layout(c, d.pitch_radii(), [w.side for w in d.wheels])
    assert drawn is not None
    for name in ("span_length", "span_angle", "wrap_angle", "span_start", "span_end"):
        assert np.array_equal(getattr(drawn, name), getattr(ref, name))
    assert drawn.length == ref.length


def test_centre_distance_from_a_kept_grid_equals_a_fresh_search():
    # after chain_length_polygon the root search starts from its grid; the root is the same
    from chaindrive.analysis import _memo

    _memo.clear()
    fresh = centre_distance_polygon(0.0254, 21, 63, 130, phases=8)
    _memo.clear()
    chain_length_polygon(0.0254, 21, 63, 1.2, phases=8)
    hinted = centre_distance_polygon(0.0254, 21, 63, 130, phases=8)
    assert abs(hinted.taut - fresh.taut) <= 1e-14 * fresh.taut
    assert abs(hinted.loose - fresh.loose) <= 1e-14 * fresh.loose


@pytest.mark.parametrize("centres", [[0.0489, np.inf], [[0.0, 0.0], [1.0, 0.0]], [[0.0, 0.0]] * 3 + [[np.inf, 0.0]]])
def test_clearance_error_refuses_centres_not_one_finite_point_per_wheel(centres):
    # found by the API fuzz: a 1-D array reached the clearance check and raised an IndexError
    drive = load_project(EXAMPLES / "multi_wheel.toml")
    with pytest.raises(InputError, match=rf"centres must have shape \({len(drive.wheels)}, 2\)"):
        clearance_error(drive, np.array(centres, float))
