"""The NaN/inf guard's fast paths (chaindrive._finite): the same answers as the general walk.

Reference: the definition itself (IEEE 754 finite numbers, ``math.isfinite`` /
``np.isfinite``), applied element by element to every kind of value the guards see.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from chaindrive._finite import (
    _finite_tree,
    _nonfinite_number,
    finite_guard,
    first_nonfinite,
    guard_scope,
)
from chaindrive.errors import InfeasibleError, InputError


@dataclasses.dataclass(frozen=True)
class _Inner:
    values: tuple
    scale: float


@dataclasses.dataclass(frozen=True)
class _Outer:
    inner: _Inner
    table: np.ndarray
    count: int


@pytest.mark.parametrize("bad", [math.nan, math.inf, -math.inf])
@pytest.mark.parametrize("size", [1, 3, 16, 17, 4001])
def test_arrays_short_and_long_found_at_their_index(bad, size):
    a = np.linspace(0.0, 1.0, size)
    assert first_nonfinite(a) is None and not _nonfinite_number(a)
    a[size // 2] = bad
    assert first_nonfinite(a) == f"[{size // 2}]"
    assert _nonfinite_number(a)
    assert _nonfinite_number(a.reshape(1, -1)) and first_nonfinite(a.reshape(1, -1)) == f"[{size // 2}]"


@pytest.mark.parametrize("value", [np.float64("nan"), float("inf"), np.float32("nan"), complex(0, math.inf)])
def test_scalars_of_every_float_type_refused(value):
    assert _nonfinite_number(value)
    assert first_nonfinite(value) == ""


def test_nested_dataclasses_tuples_and_lists_name_the_place():
    ok = _Outer(_Inner((1.0, [2.0, np.array([3.0])]), 4.0), np.ones((2, 2)), 5)
    assert first_nonfinite(ok) is None
    bad = dataclasses.replace(ok, inner=_Inner((1.0, [2.0, np.array([3.0, math.nan])]), 4.0))
    assert first_nonfinite(bad) == ".inner.values[1][1][1]"
    assert first_nonfinite({"a": (1, True, None, "x", math.inf)}) == "['a'][4]"


def test_guard_scope_sets_the_error_state_once_and_restores_it():
    @finite_guard
    def ratio(a, b):
        return a / b

    before = np.geterr()
    with guard_scope():
        assert np.geterr()["divide"] == "ignore"
        with pytest.raises(InfeasibleError, match=r"ratio: the result \[0\] is not a finite number \(inf\)"):
            ratio(np.array([1.0]), np.array([0.0]))
        with pytest.raises(InputError, match="a must not be NaN"):
            ratio(math.nan, 1.0)
        assert ratio(1.0, 4.0) == 0.25
    assert np.geterr() == before


# ------------------------------------------------- the guard's fast result check (no path built)
@dataclasses.dataclass(frozen=True)
class _Holder:
    a: object = None
    b: object = None


_LEAVES = st.one_of(st.floats(allow_nan=True, allow_infinity=True), st.integers(-5, 5), st.none(), st.text(max_size=2),
                    st.booleans(), st.lists(st.floats(allow_nan=True, allow_infinity=True), max_size=20).map(np.array),
                    st.floats(allow_nan=True, allow_infinity=True).map(np.float64))


@settings(max_examples=300, deadline=None)
@given(st.recursive(_LEAVES, lambda kids: st.one_of(st.lists(kids, max_size=4), st.tuples(kids, kids),
                                                    st.builds(_Holder, kids, kids),
                                                    st.dictionaries(st.text(max_size=2), kids, max_size=3)),
                    max_leaves=30))
def test_fast_result_check_agrees_with_first_nonfinite(obj):
    assert _finite_tree(obj) == (first_nonfinite(obj) is None)


def test_fast_result_check_looks_as_deep_as_first_nonfinite():
    deep: object = float("nan")
    for depth in range(16):
        deep = [deep] if depth % 2 else _Holder(deep)
        assert _finite_tree(deep) == (first_nonfinite(deep) is None)


_ELEMENT = st.sampled_from([0.0, -0.0, 1.0, -2.5, 1e-300, 1e308, -1e308, math.inf, -math.inf, math.nan])


@settings(max_examples=300, deadline=None)
@given(st.lists(_ELEMENT, min_size=0, max_size=40))
def test_array_fast_paths_equal_the_elementwise_definitions(values):
    # _all_finite (a short array in Python floats; inside a guard a long one by its dot product), the checks'
    # NaN test and their range test (short arrays in Python floats, longer by min and max)
    from chaindrive._finite import _all_finite
    from chaindrive._validation import _has_nan, _within

    arr = np.array(values, dtype=float)
    assert _all_finite(arr) == bool(np.isfinite(arr).all())
    with guard_scope():  # inside a guard: a long array by its sum of squares first (1e308² overflows)
        assert _all_finite(arr) == bool(np.isfinite(arr).all())
    assert _has_nan(arr) == bool(np.isnan(arr).any())
    import warnings

    from chaindrive._validation import warn_outside

    with warnings.catch_warnings(record=True) as caught:  # warn_outside: NaN outside neither bound
        warnings.simplefilter("always")
        warn_outside("x", arr, -1.0, 2.0, "a test")
    assert bool(caught) == bool(((arr < -1.0) | (arr > 2.0)).any())
    if not np.isnan(arr).any():
        from chaindrive._validation import check_range

        for inclusive in (True, False):
            try:
                check_range("x", arr, -1.0, 1.0, low_inclusive=inclusive, high_inclusive=inclusive)
                passed = True
            except InputError:
                passed = False
            inside = (arr >= -1.0) & (arr <= 1.0) if inclusive else (arr > -1.0) & (arr < 1.0)
            assert passed == bool(inside.all())
        assert _within(arr, 0.0, True) == (not ((arr <= 0).any() or not np.isfinite(arr).all()))
        assert _within(arr, 0.0, False) == (not ((arr < 0).any() or not np.isfinite(arr).all()))


def test_an_opaque_argument_type_is_passed_at_a_glance_once_seen():
    from chaindrive._finite import _OPAQUE

    class Thing:
        pass

    @finite_guard
    def f(x, y):
        return y

    assert f(Thing(), 1.0) == 1.0 and Thing in _OPAQUE
    with pytest.raises(InputError, match="y must not be NaN"):
        f(Thing(), math.nan)
