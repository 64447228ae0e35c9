"""No NaN/inf out of the public API, no foreign exception: the fixes the API fuzzing found,
and a bounded sweep with the generators of scripts/fuzz.py (``make fuzz`` runs 10,000)."""

from __future__ import annotations

import math
import random

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from _fuzz_loader import load_fuzz
from chaindrive._finite import check_finite_fields, finite_guard, first_nonfinite
from chaindrive.errors import ConvergenceError, InfeasibleError, InputError

pytestmark = pytest.mark.fuzz

fuzz = load_fuzz()


# --------------------------------------------------------------------------- the guard itself


def test_guard_refuses_nonfinite_arguments_by_name():
    @finite_guard
    def f(pitch, teeth=3):
        return pitch * teeth

    with pytest.raises(InputError, match="pitch must not be NaN .* got nan"):
        f(float("nan"))
    with pytest.raises(InputError, match="teeth must be finite .* got inf"):
        f(1.0, teeth=np.inf)
    with pytest.raises(InputError, match="pitch must be finite .* an array holding -inf"):
        f(np.array([1.0, -np.inf]))
    assert f(2.0) == 6.0
    assert f.__name__ == "f" and "pitch" in str(__import__("inspect").signature(f))


def test_guard_raises_nonfinite_results_with_where():
    @finite_guard
    def g(x):
        return {"a": [1.0, x * 1e300]}

    with pytest.raises(InfeasibleError, match=r"g: the result \['a'\]\[1\] is not a finite number \(inf\)"):
        g(1e10)
    assert g(1.0) == {"a": [1.0, 1e300]}


def test_guard_maps_numerical_failures():
    @finite_guard
    def singular():
        return np.linalg.solve(np.zeros((2, 2)), np.ones(2))

    @finite_guard
    def shapes(a, b):
        return np.asarray(a) + np.asarray(b)

    with pytest.raises(ConvergenceError, match="singular: the linear algebra failed"):
        singular()
    with pytest.raises(InputError, match="shapes: array arguments of incompatible shapes"):
        shapes(np.ones(3), np.ones(7))


def test_guard_allow_infinite_leaves_the_check_to_the_function():
    @finite_guard(allow_infinite=("stiffness",))
    def k(stiffness):
        return 1.0 if np.isinf(stiffness) else float(stiffness)

    assert k(np.inf) == 1.0


def test_first_nonfinite_and_fields():
    assert first_nonfinite([1.0, {"x": np.array([1.0, np.nan])}]) == "[1]['x'][1]"
    assert first_nonfinite(None) is None and first_nonfinite("nan") is None
    from chaindrive.geometry import Sprocket

    with pytest.raises(InputError, match="inner_width must be finite .* got inf"):
        Sprocket(pitch=0.0254, teeth=19, roller_diameter=0.01588, inner_width=np.inf)
    with pytest.raises(InputError, match="pitch must be finite"):
        Sprocket(np.inf, 19, 0.01588)
    import dataclasses

    @dataclasses.dataclass
    class Q:
        a: float
        b: str = "x"

    check_finite_fields(Q(1.0))
    with pytest.raises(InputError, match="a must be finite"):
        check_finite_fields(Q(-np.inf))


# --------------------------------------------------------------------------- each fix found by fuzzing
# Each input below is a reproducer printed by `python scripts/fuzz.py --surface api`
# before the fix (finite inputs, NaN/inf or a foreign exception out).


def test_gamma_range_cli_reproducer():
    # issue: `contact --chain 16B --load "5 kN" --skew "50 arcmin" --gamma 1e300` printed inf MPa
    from chaindrive.strength import roller_contact_stress, skew_load_factor

    with pytest.raises(InputError, match=r"gamma must lie in \[0, 0.01\] 1/arcmin\^2"):
        roller_contact_stress(5e3, 15.88e-3, 8.02e-3, 17e-3, max_skew=50 * math.pi / 180 / 60, gamma=1e300)
    with pytest.raises(InputError, match=r"gamma must lie in \[0, 0.01\]"):
        skew_load_factor(0.01, 0.5)
    # Garshniev & Maksymovych's table values stay inside the range
    assert skew_load_factor(0.0, 0.0023) == pytest.approx(1.0)


def test_paper_entry_out_of_domain_is_infeasible():
    from chaindrive.kinematics import paper_tangential_entry, paper_tangential_limit_angles

    with pytest.raises(InfeasibleError, match="paper_tangential_limit_angles: the result"):
        paper_tangential_limit_angles(0.3650286412646147, 2.5750604517450464, 1.1331275071200295,
                                      0.03830073988608602, 21.684126794929714, 0.019840941107573503)
    # a roller chain has no second limit angle: None, not inf
    r = paper_tangential_entry([0.0, 0.1], 0.0254, 0.0, 0.0779, 0.3307, 0.3307, 0.4, 10.0, roller=True)
    assert r["limit_angles"][1] is None and np.all(np.isfinite(r["velocity"]))


def test_contact_stress_overflow_and_thin_roller():
    from chaindrive.strength import hertz_line_pressure, skew_paper_contact_stress

    with pytest.raises(InfeasibleError, match="skew_paper_contact_stress: the result is not a finite number"):
        skew_paper_contact_stress(1e300, 0.021349419330858824, 0.7899145785353765, 28118836998.933548)
    with pytest.raises((InputError, InfeasibleError)):
        hertz_line_pressure(189558.36878085506, 5e-324, 0.9276711673667009, 483469726.91903085)


def test_layout_formulas():
    from chaindrive.layout import catenary_sag, centre_distance_polygon, chain_length_polygon

    with pytest.raises((InputError, InfeasibleError)):
        catenary_sag(0.001722578859797774, 0.01, 82875.31416437284, 5e-324)
    with pytest.raises((InputError, InfeasibleError)):
        chain_length_polygon(1.9360150601300858, 40, 25, 1e300, phases=151)  # was scipy's QhullError
    with pytest.raises(InputError):
        centre_distance_polygon(0.052120950958763075, 40, 8, 100, phases=-1)  # was numpy's ValueError


def test_vibration_numerical_failures():
    from chaindrive.vibration import excitation_frequencies, fe_tensioner_frequencies, wave_speed

    # was numpy.linalg.LinAlgError (B not positive definite) out of scipy's eigh
    with pytest.raises((ConvergenceError, InputError, InfeasibleError)):
        fe_tensioner_frequencies(586.5084961719964, 1e-300, 2.922091722669689, 1e-300, 5e-324,
                                 1.0064139753338366, 34.761356744402036, 268.4429547623053, elements=151)
    with pytest.raises(InputError, match=r"elements must be a whole number in \[2, 400\]"):
        fe_tensioner_frequencies(2000.0, 2.6, 0.8, 0.8, 0.3, 0.3, 3.0, 5e4, elements=1000)
    with pytest.raises(InfeasibleError, match="wave_speed"):
        wave_speed(1e12, 1e-300)
    with pytest.raises(InfeasibleError, match="excitation_multipliers: the result"):
        excitation_frequencies(6.699108107210665, ratio=5e-324)


def test_strength_numerical_failures():
    from chaindrive.strength import (
        MultiRowPin,
        beam_solve,
        fretting_comparison,
        tooth_bending_stress,
    )

    with pytest.raises((ConvergenceError, InputError, InfeasibleError)):
        beam_solve([0.2, 0.9], [], 5e-324, elements_per_span=151)  # was LinAlgError: singular matrix
    with pytest.raises(InfeasibleError, match="tooth_bending_stress"):
        tooth_bending_stress(67.57657413109692, 0.5220353118571855, 1e-300, 5e-324)
    pin = MultiRowPin(8.28e-3, 31.88e-3, 3, 17.02e-3)
    with pytest.raises((InputError, InfeasibleError)):
        fretting_comparison(pin, 89770.7313651492, 0.012442854154622192, 0.15205225168292338, 1e-300,
                            1.0712552792028844)


# --------------------------------------------------------------------------- bounded sweep

FUNCTIONS = fuzz.api_functions()


@settings(max_examples=120, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(seed=st.integers(0, 2**32 - 1))
def test_api_sweep_no_nonfinite_no_foreign_exception(seed):
    rnd = random.Random(seed)
    tally = fuzz.Tally("api")
    name, obj = rnd.choice(FUNCTIONS)
    fuzz.run_api(name, obj, tally, rnd)
    # timing is measured by `make fuzz` (calls over 30 s), never asserted in tests
    assert not (tally.tracebacks or tally.bad_exit or tally.nonfinite), tally.examples


def test_api_surface_is_discovered():
    names = {n.rsplit(".", 1)[1] for n, _ in FUNCTIONS}
    assert {"chain_entry", "tensioner_frequencies", "roller_contact_stress", "chain_length_polygon",
            "pocket_angles"} <= names


def test_second_fuzz_round_reproducers():
    # reproducers of the first full `make fuzz` run (finite inputs; foreign exception or inf out)
    from chaindrive import chains
    from chaindrive.geometry import TrackDriveWheel, tooth_width
    from chaindrive.kinematics import chain_entry_for
    from chaindrive.kinematics.crawler import crawler_drive
    from chaindrive.layout import centre_distance_polygon
    from chaindrive.selection import select
    from chaindrive.vibration import TensionerSpan, propose_safe_tensioner

    with pytest.raises(InfeasibleError, match="chain_entry: the result acceleration"):
        chain_entry_for(chains.get("18x64"), 8, 1e300)  # ω² overflows
    # (one line either way; which guard trips first depends on the catalogue rows rated)
    with pytest.raises(InfeasibleError, match=r"select: (the numbers overflow or divide by zero|the result "
                                              r"\[0\]\.power_margin is not a finite number)"):
        select(5e-324, 19.80946939381021, 1.6830019764695077, centre_distance=0.0729603197769288)
    span = TensionerSpan(2000.0, 2.6, 0.8, 0.8, 0.35, 0.35, 3.0, 5e4)
    with pytest.raises(InputError):
        propose_safe_tensioner(span, (6.2, 6.2), points=-1)  # was numpy's ValueError
    with pytest.raises(InputError, match="phases must be a whole number >= 1"):
        centre_distance_polygon(1e12, 9, 8, 19, phases=0)  # was argmax of an empty sequence
    with pytest.raises(InputError, match="incompatible shapes"):
        tooth_width(np.array([0.0318, 0.0023, 0.5173]), np.ones(7) * 0.01)
    with pytest.raises(InfeasibleError, match="dimensions: the numbers overflow"):
        TrackDriveWheel(pitch=1e300, teeth=40, pin_radius=0.256).dimensions()  # was OverflowError
    with pytest.raises(InfeasibleError, match=r"(crawler_drive: the numbers overflow|guided_acceleration: the result)"):
        crawler_drive(chains.get("08A").pitch, 150, 1e300 * 2 * math.pi / 60, sprocket_distance=0.064)


def test_third_fuzz_round_reproducers():
    # second full `make fuzz` run: points=0 gave an IndexError out of an empty grid
    from chaindrive.vibration import TensionerSpan, propose_safe_tensioner

    span = TensionerSpan(2000.0, 2.6, 0.8, 0.8, 0.35, 0.35, 3.0, 5e4)
    with pytest.raises(InputError, match=r"points must be a whole number in \[2, "):
        propose_safe_tensioner(span, (20.6, 20.6), modes=25, points=0)
    with pytest.raises(InputError, match=r"decades must lie in \(0, 10\]"):
        propose_safe_tensioner(span, (0.24, 0.24), decades=-1.0)


def test_fourth_fuzz_round_reproducer():
    # `make fuzz` with --seed 7: a NaN plate constant came out as a NaN rating
    from chaindrive.selection import ansi_rated_power

    with pytest.raises(InputError, match="plate_constant must not be NaN"):
        ansi_rated_power(0.830273602335735, 19, 1e-300, plate_constant=float("nan"))


def test_fifth_fuzz_round_reproducers():
    # `scripts/fuzz.py --surface api --seed 8/9`: a 15 GiB phase grid (MemoryError) and an
    # infinite tip radius carried into a pocket wheel
    from chaindrive.geometry import PocketWheel
    from chaindrive.layout import chain_length_polygon

    with pytest.raises(InputError, match=r"phases must be a whole number in \[1, 131\] for 1000 \+ 150 teeth"):
        chain_length_polygon(0.0068, 1000, 150, 3.0, phases=1000)
    with pytest.raises(InputError, match="tip_radius must be finite"):
        PocketWheel(pitch=3.0, bar_diameter=1.0, teeth=25, tip_radius=float("inf"))
