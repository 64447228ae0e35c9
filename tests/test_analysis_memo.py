"""The analysis keeps results of pure sub-computations for reuse (chaindrive.analysis._memo):
the same results and warnings whether a result is reused or computed, frozen arrays, errors
not kept."""

from __future__ import annotations

import dataclasses
import json
import warnings

import numpy as np
import pytest

from _shared import EXAMPLES
from chaindrive._results import jsonable
from chaindrive.analysis import _memo, analyze_drive
from chaindrive.drive import load_project
from chaindrive.errors import InputError, ValidityRangeWarning


def _json(analysis):
    return json.dumps(jsonable(analysis.to_dict()), sort_keys=True)


@pytest.mark.parametrize("name", ["roller_industrial", "mining_conveyor", "tractor_track"])
def test_reused_results_equal_computed_ones(name):
    drive = load_project(EXAMPLES / f"{name}.toml")
    _memo.clear()
    computed = analyze_drive(drive, exclude=["remedy"])
    reused = analyze_drive(drive, exclude=["remedy"])
    assert _json(computed) == _json(reused)
    assert computed.warnings == reused.warnings
    assert [(c.name, c.value) for c in computed.checks] == [(c.name, c.value) for c in reused.checks]


def test_an_edit_of_the_speed_or_load_gives_what_a_fresh_analysis_gives():
    drive = load_project(EXAMPLES / "roller_industrial.toml")
    analyze_drive(drive, exclude=["remedy"])  # the stores hold this drive's parts
    for edited in (dataclasses.replace(drive, speed=drive.speed * 0.8),
                   dataclasses.replace(drive, load=dataclasses.replace(drive.load, power=drive.load.power * 1.3))):
        reused = analyze_drive(edited, exclude=["remedy"])
        _memo.clear()
        fresh = analyze_drive(edited, exclude=["remedy"])
        assert _json(reused) == _json(fresh)
        assert reused.layout.chain_speed == pytest.approx(edited.chain_speed(), rel=1e-15)


def test_kept_arrays_are_read_only():
    drive = load_project(EXAMPLES / "roller_industrial.toml")
    lay = analyze_drive(drive, include=["layout"]).layout
    with pytest.raises(ValueError, match="read-only"):
        lay.pitch_radii[0] = 1.0


@pytest.mark.filterwarnings("ignore::chaindrive.errors.ValidityRangeWarning")
def test_memo_replays_warnings_keeps_no_error_and_computes_unhashable_arguments():
    calls = []

    @_memo.memo(maxsize=2)
    def f(x):
        calls.append(x)
        if isinstance(x, list):
            return np.array(x, dtype=float)
        if x < 0:
            raise InputError("x must be >= 0")
        warnings.warn(f"x = {x} is large", ValidityRangeWarning, stacklevel=2)
        return np.array([x], dtype=float)

    for _ in range(2):
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            out = f(5.0)
        assert [str(w.message) for w in caught] == ["x = 5.0 is large"]
        assert caught[0].category is ValidityRangeWarning
        assert not out.flags.writeable
    assert calls == [5.0]
    for _ in range(2):
        with pytest.raises(InputError, match="x must be >= 0"):
            f(-1.0)
    assert calls == [5.0, -1.0, -1.0]
    assert f([1.0, 2.0]).tolist() == [1.0, 2.0] and f([1.0, 2.0]).flags.writeable  # not kept
    f(6.0)
    f(7.0)  # the store holds two: 5.0 is dropped
    f(5.0)
    assert calls.count(5.0) == 2
    _memo.clear()
    f(7.0)
    assert calls.count(7.0) == 2
