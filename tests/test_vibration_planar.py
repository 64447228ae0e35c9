"""The planar bead model of the slack span with a tensioner settles the coupling (issue 20, item 5)."""

from __future__ import annotations

import importlib.util
import math
from pathlib import Path

import numpy as np
import pytest

from chaindrive.errors import InputError
from chaindrive.vibration import tensioner_frequencies
from chaindrive.vibration.planar import planar_tensioner_frequencies

CASE = dict(tension=2000.0, mass_per_length=2.6, length_1=0.8, length_2=1.1, mass=3.0, stiffness=5e4)


def _bench():
    path = Path(__file__).resolve().parents[1] / "benchmarks" / "tensioner_coupling.py"
    spec = importlib.util.spec_from_file_location("tensioner_coupling", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


@pytest.mark.slow
def test_planar_model_converges_to_projected_and_not_to_as_printed():
    # independent reference: the planar bead chain (no coupling factor assumed), 100 and 200
    # links per part extrapolated; at 50° the printed eq. (7) is 6 % off, the derived one 1e-4
    b = math.radians(50)
    sim = 2 * planar_tensioner_frequencies(angle_1=b, angle_2=b, elements=200, **CASE) - \
        planar_tensioner_frequencies(angle_1=b, angle_2=b, elements=100, **CASE)
    projected = tensioner_frequencies(angle_1=b, angle_2=b, model="projected", **CASE)
    printed = tensioner_frequencies(angle_1=b, angle_2=b, model="as_printed", **CASE)
    assert np.allclose(projected, sim, rtol=2e-4)
    assert abs(printed[0] / sim[0] - 1) > 0.05
    # regression (planar model at 200 links per part)
    assert planar_tensioner_frequencies(angle_1=b, angle_2=b, elements=200, **CASE)[0] == pytest.approx(93.689, abs=2e-3)


def test_beta_zero_both_models_and_planar_coincide():
    p = planar_tensioner_frequencies(angle_1=0.0, angle_2=0.0, elements=200, **CASE)
    for model in ("projected", "as_printed"):
        assert np.allclose(tensioner_frequencies(angle_1=0.0, angle_2=0.0, model=model, **CASE), p, rtol=1e-4)


def test_paper_claim_larger_beta1_raises_all_frequencies_is_not_general():
    # a heavy, soft tensioner: its mode is set by a_1 = S2 cos β1 (falls with β1) -> the
    # first frequency falls although the paper says all rise; the planar model agrees
    case = dict(CASE, mass=30.0, stiffness=1e3)
    lo, hi = (planar_tensioner_frequencies(angle_1=math.radians(d), angle_2=math.radians(20), elements=100, **case)
              for d in (20, 35))
    assert hi[0] < lo[0]
    assert hi[1] > lo[1]  # string modes do rise with the part's tension S2/cos β1
    printed = [tensioner_frequencies(angle_1=math.radians(d), angle_2=math.radians(20), model="as_printed", **case)
               for d in (20, 35)]
    assert printed[1][0] > printed[0][0]  # the printed coupling would have confirmed the claim


def test_locked_chain_length_tends_to_two_fixed_strings():
    # E A -> large with fixed ends: the tensioner cannot move (the length change u(sin β1 + sin β2)
    # is refused), so the parts become fixed-fixed strings: π c_i / ℓ_i
    b = math.radians(30)
    p = planar_tensioner_frequencies(angle_1=b, angle_2=b, elements=200, axial_stiffness=1e9, **CASE)
    c = math.sqrt(CASE["tension"] / math.cos(b) / CASE["mass_per_length"])
    assert p[0] == pytest.approx(math.pi * c / 1.1, rel=2e-3)
    assert p[1] == pytest.approx(math.pi * c / 0.8, rel=2e-3)


def test_errors():
    with pytest.raises(InputError, match="stiffness must be finite"):
        planar_tensioner_frequencies(angle_1=0.1, angle_2=0.1, **dict(CASE, stiffness=math.inf))
    with pytest.raises(InputError, match="axial_stiffness"):
        planar_tensioner_frequencies(angle_1=0.1, angle_2=0.1, axial_stiffness=-1.0, **CASE)
    with pytest.raises(InputError, match="elements"):
        planar_tensioner_frequencies(angle_1=0.1, angle_2=0.1, elements=1, **CASE)
    with pytest.raises(InputError, match="angle_1"):
        planar_tensioner_frequencies(angle_1=2.0, angle_2=0.1, **CASE)


@pytest.mark.slow
def test_benchmark_default_within_one_percent_at_every_angle():
    bench = _bench()
    rows = bench.compare()
    assert [r["beta"] for r in rows] == [0.0, 20.0, 35.0, 50.0]
    for r in rows:
        assert np.max(np.abs(r[f"d_{bench.DEFAULT}"])) < 0.01
    assert np.max(np.abs(rows[-1]["d_as_printed"])) > 0.05
