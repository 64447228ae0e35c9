"""The running peak tension of a roller drive (chaindrive.vibration.running_tension): the seat
stiffness against a second published contact formula, the impact terms against independent
computations, the reduced model against its calibration sweep (cached) and, slow, against
fresh simulations of a subset of the sweep (docs/design.md, "The running peak tension")."""

from __future__ import annotations

import math
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from chaindrive.errors import InputError, ValidityRangeWarning
from chaindrive.vibration import running_tension as RT

ROOT = Path(__file__).resolve().parents[1]


def _roark_cylinder_between_plates(load, length, diameter, e=2.07e11, nu=0.3):
    """Independent: the decrease of diameter of a steel cylinder pressed between two flat steel
    plates (two line contacts), Föppl's elastic solution as printed by Roark (W. C. Young,
    R. G. Budynas, Roark's Formulas for Stress and Strain, 7th ed., Table 14.1, cylinder
    between two flat plates): Δd = 4 w (1 − ν²)/(π E) (1/3 + ln(2D/b)), b = 1.6 √(w D C_E),
    C_E = 2 (1 − ν²)/E, w the load per length."""
    w = load / length
    b = 1.6 * math.sqrt(w * diameter * 2 * (1 - nu**2) / e)
    return 4 * w * (1 - nu**2) / (math.pi * e) * (1 / 3 + math.log(2 * diameter / b))


def test_palmgren_in_si():
    # δ = 3.84e-5 Q^0.9 / l^0.8 in mm, N, mm: 2.5 kN on 17.02 mm (16B) by hand in those units
    delta_mm = 3.84e-5 * 2500**0.9 / 17.02**0.8
    k = float(RT.seat_contact_stiffness(2500.0, 0.01702))
    assert k == pytest.approx(2500.0 / (2 * delta_mm * 1e-3), rel=1e-12)
    assert float(RT.seat_contact_stiffness(2500.0, 0.01702, contacts=1)) == pytest.approx(2 * k)


@pytest.mark.parametrize("load", [500.0, 2500.0, 20e3])
@pytest.mark.parametrize(("width", "diameter"), [(0.00775, 0.00851), (0.01702, 0.01588), (0.0296, 0.0191)])
def test_seat_stiffness_against_roark(load, width, diameter):
    # Palmgren's empirical roller deflection is 2.06-2.25 times Föppl/Roark's elastic one over
    # 0.5-20 kN on 08B…20B rollers: the bracket of the seat stiffness stated in docs/design.md
    two = load / float(RT.seat_contact_stiffness(load, width))   # both contacts
    assert 1.9 < two / _roark_cylinder_between_plates(load, width, diameter) < 2.4


def test_impact_velocity_kinematics():
    # independent: the free roller of a link pivoting about a seated roller, in the wheel's frame;
    # the span keeps its direction in space, so the link turns at -ω relative to the wheel
    w, p, dt = 100.0, 0.0254, 1e-7
    ang = np.array([0.3, 0.3 - w * dt])
    pos = p * np.column_stack([np.cos(ang), np.sin(ang)])
    speed = float(np.hypot(*(pos[1] - pos[0]))) / dt
    assert float(RT.seating_impact_velocity(w, p)) == pytest.approx(speed, rel=1e-6)


def test_impact_force_against_integration():
    # independent: m x'' = -k x from x = 0, x' = v (scipy), the largest k x
    from scipy.integrate import solve_ivp

    v, k, m = 1.7, 3e8, 0.066
    sol = solve_ivp(lambda t, y: [y[1], -k / m * y[0]], (0, 2 * math.pi * math.sqrt(m / k)), [0.0, v],
                    max_step=1e-7, rtol=1e-10, atol=1e-14)
    assert float(RT.seating_impact_force(v, k, m)) == pytest.approx(k * sol.y[0].max(), rel=1e-4)
    assert float(RT.seating_impact_force(0.0, k, m)) == 0.0


def test_model_regression_and_terms():
    c = RT.calibration()
    ft, w, p, z, q, kc = 2254.0, 100.531, 0.0254, 19, 2.612, 2.75e8
    x = w * p * math.sqrt(kc * q * p) / ft
    expected = ft * (1 + c.coefficient * x**c.impact_exponent * (z / 19) ** c.teeth_exponent)
    assert float(RT.running_peak_tension(ft, w, p, z, q, kc)) == pytest.approx(expected, rel=1e-12)
    # vectorised
    out = RT.running_peak_tension(ft, np.array([10.0, 50.0, 100.0]), p, z, q, kc)
    assert out.shape == (3,) and np.all(np.diff(out) > 0)


@given(st.floats(5.0, 190.0), st.floats(1.05, 3.0))
def test_peak_grows_with_speed_and_exceeds_the_static_tension(w, f):
    a = float(RT.running_peak_tension(1500.0, w, 0.01905, 19, 1.244, 2e8))
    b = float(RT.running_peak_tension(1500.0, w * f, 0.01905, 19, 1.244, 2e8))
    assert 1500.0 < a < b and math.isfinite(b)


def test_calibration_is_data_with_provenance():
    c = RT.calibration()
    assert "Halton" in c.provenance and "benchmarks/_dynamic_sweep.py" in c.provenance
    assert c.reference == "long" and "six 0.25 s windows" in c.provenance
    assert set(c.ranges) == {"pitch", "teeth", "ratio", "rpm", "chain_speed", "centre_pitches", "pull_ratio", "wheels"}
    assert 0 < c.calibration_rms <= c.calibration_worst < 1
    assert {"chain_speed_max", "resonance_band", "resonance_modes", "drives", "worst", "nested_worst"} <= set(c.validated)


def _module(folder, name):
    """A module of benchmarks/ or scripts/ (not part of the package)."""
    import importlib

    sys.path.insert(0, str(ROOT / folder))
    return importlib.import_module(name)


def _sweep():
    return _module("benchmarks", "_dynamic_sweep")


def test_model_against_the_cached_sweep():
    # the stored in-sample accuracy is the model's against the long reference of the drives inside
    # the validated range (fitted to them), and outside it: recomputed through the package's
    # functions (the range by validated_range_violations), not the script's
    sw = _sweep()
    rows = sw.read_cache()
    long = {r["name"]: r["long_peak"] for r in sw.read_cache(sw.LONG_CACHE)}
    assert len(rows) == len(long) == 64
    c = RT.calibration()
    err, inside = [], []
    for r in rows:
        w = r["rpm"] * math.pi / 30
        f = RT.running_peak_tension(r["tight"], w, r["pitch"], r["teeth_driving"], r["mass_per_length"],
                                    r["contact_stiffness"])
        err.append(float(f) / long[r["name"]] - 1)
        ratio = RT.tooth_frequency_ratio(w, r["teeth_driving"], r["pitch"], r["tight"], r["mass_per_length"],
                                         r["tight_span"])
        inside.append(not RT.validated_range_violations(w * r["teeth_driving"] * r["pitch"] / (2 * math.pi),
                                                        float(ratio)))
    err, inside = np.abs(np.array(err)), np.array(inside)
    assert int(inside.sum()) == c.validated["drives"] == 63
    assert err[inside].max() == pytest.approx(c.calibration_worst, abs=1e-3)
    assert err[~inside].max() == pytest.approx(c.validated["outside_worst"], abs=1e-3)


@pytest.mark.slow
@pytest.mark.parametrize("name", ["S04", "S27", "S45"])
def test_sweep_subset_simulated_again(name):
    # three drives of the sweep (10B 19/30 at 1273 rpm, 16B 27/82 at 182 rpm, 20B 26/32 at 467 rpm
    # and 11.5 % F_B) simulated afresh: the cache is reproduced, and the model is within its
    # stated calibration accuracy of the simulation
    sw = _sweep()
    drive = next(d for d in sw.sweep_drives(64) if d.name == name)
    row = sw.simulate_row(drive)
    cached = next(r for r in sw.read_cache() if r["name"] == name)
    assert row.sim_peak == pytest.approx(cached["sim_peak"], rel=0.02)
    # the model within its stated out-of-sample accuracy of each (the damped sweep; the three sat on
    # span modes 9, 8 and 10, outside the undamped calibration's range)
    f = float(RT.running_peak_tension(row.tight, row.rpm * math.pi / 30, row.pitch, row.teeth_driving,
                                      row.mass_per_length, row.contact_stiffness))
    c = RT.calibration()
    assert abs(f / row.sim_peak - 1) <= max(c.loo_worst, c.validated["outside_worst"]) + 0.02


@pytest.mark.slow
def test_long_reference_simulated_again():
    # sweep drive S06 (08B 25/54 at 162 rpm, 14 s of CPU) run on to 4 s afresh: the long cache is
    # reproduced (benchmarks/_dynamic_sweep.py 64 --long)
    sw = _sweep()
    drive = next(d for d in sw.sweep_drives(64) if d.name == "S06")
    row = sw.long_row(drive)
    cached = next(r for r in sw.read_cache(sw.LONG_CACHE) if r["name"] == "S06")
    assert row.long_peak == pytest.approx(cached["long_peak"], rel=0.02)
    assert row.long_mean == pytest.approx(cached["long_mean"], rel=0.02)


def test_range_warnings():
    args = dict(pitch=0.0254, teeth=19, teeth_driven=57, angular_velocity=100.5, centre_distance=1.05,
                pull=1940.0, breaking_force=60e3)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        RT.check_running_tension_range(**args)
    for change, match in [(dict(teeth=9), "teeth"), (dict(teeth_driven=95), "ratio"),
                          (dict(angular_velocity=300.0), "rpm"), (dict(centre_distance=2.5), "centre_pitches"),
                          (dict(pull=12e3), "pull_ratio"), (dict(pitch=0.0508), "pitch"), (dict(wheels=3), "wheels")]:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            RT.check_running_tension_range(**{**args, **change})
        assert any(issubclass(w.category, ValidityRangeWarning) and match in str(w.message) for w in caught)


@pytest.mark.parametrize(("call", "match"), [
    (lambda: RT.seat_contact_stiffness(0.0, 0.017), "load"),
    (lambda: RT.seat_contact_stiffness(1e3, float("nan")), "width"),
    (lambda: RT.seat_contact_stiffness(1e3, 0.017, contacts=0), "contacts"),
    (lambda: RT.seating_impact_velocity(-1.0, 0.0254), "angular_velocity"),
    (lambda: RT.seating_impact_velocity(10.0, 0.0), "pitch"),
    (lambda: RT.seating_impact_force(-1.0, 1e8, 0.05), "velocity"),
    (lambda: RT.seating_impact_force(1.0, float("inf"), 0.05), "stiffness"),
    (lambda: RT.seating_impact_force(1.0, 1e8, 0.0), "mass"),
    (lambda: RT.running_peak_tension(0.0, 100.0, 0.0254, 19, 2.6, 2e8), "tight_tension"),
    (lambda: RT.running_peak_tension(2e3, 100.0, 0.0254, 0, 2.6, 2e8), "teeth"),
    (lambda: RT.running_peak_tension(2e3, 100.0, 0.0254, 19, float("nan"), 2e8), "mass_per_length"),
    (lambda: RT.running_peak_tension(2e3, 100.0, 0.0254, 19, 2.6, -2e8), "stiffness"),
    (lambda: RT.seating_impact_force("fast", 1e8, 0.05), "velocity"),
    (lambda: RT.check_running_tension_range(pitch="x", teeth=19, teeth_driven=57, angular_velocity=100.0,
                                            centre_distance=1.0, pull=1e3, breaking_force=6e4), "pitch"),
    (lambda: RT.check_running_tension_range(pitch=0.0254, teeth=19, teeth_driven=57, angular_velocity=100.0,
                                            centre_distance=1.0, pull=0.0, breaking_force=6e4), "pull"),
])
def test_errors(call, match):
    with pytest.raises(InputError, match=match):
        call()


def _calibration_script():
    return _module("scripts", "calibrate_running_tension")


def test_cross_validation_stored_and_recomputed():
    # issue 29.4: the constants fitted on three folds of the cached sweep predict the fourth;
    # the stored out-of-fold accuracy is recomputed here (the fold of drive i is i mod 4)
    cs = _calibration_script()
    a = cs.load("long")
    err = cs.crossvalidate(a)
    c = RT.calibration()
    assert len(err) == 64
    assert np.abs(err).max() == pytest.approx(c.crossval_worst, abs=1e-3)
    assert np.sqrt(np.mean(err**2)) == pytest.approx(c.crossval_rms, abs=1e-3)
    short = cs.crossvalidate(cs.load())
    assert np.abs(short).max() == pytest.approx(c.short_crossval_worst, abs=1e-3)
    # regression of the finding (docs/design.md, "The running peak tension", the damped sweep): over
    # the whole sweep the aim of 15 % worst is not met against either reference (22.3 % long, 25.5 %
    # short), the rms is about 8 % (undamped spans, before 2026-11-29: 33.5 % and 35.6 %, rms 11 %)
    assert 0.20 < c.crossval_worst < 0.25 and 0.07 < c.crossval_rms < 0.09
    assert 0.23 < c.short_crossval_worst < 0.28


def test_chordal_rise_fundamental_against_quadrature():
    # independent: the first Fourier coefficient of the entering roller's height R cos(theta/z)
    # over one tooth period, by numerical quadrature; and its large-z limit 2 R / z^2
    from scipy.integrate import quad

    cs = _calibration_script()
    for p, z in [(0.0254, 13), (0.03175, 18), (0.0127, 27)]:
        r = p / (2 * math.sin(math.pi / z))
        ref = quad(lambda t, r=r, z=z: r * math.cos(t / z) * math.cos(t), -math.pi, math.pi)[0] / math.pi
        assert float(cs.chordal_rise_fundamental(np.array(p), np.array(z))) == pytest.approx(abs(ref), rel=1e-9)
        assert abs(ref) == pytest.approx(2 * r / z**2, rel=0.02)


def test_span_resonance_term_does_not_explain_the_sweep():
    # the span-resonance term with its derived coefficient (1) makes the model worse over the
    # sweep at every damping ratio tried (docs/design.md): the reason it is not in the package;
    # a regression of that finding, on the damped sweep as on the undamped one
    cs = _calibration_script()
    a = cs.load()
    cal = a["index"] < cs.CALIBRATION_DRIVES
    base = cs.model(cs.fit(a, cal), a) / a["sim_peak"] - 1
    for zeta in (0.02, 0.05, 0.1, 0.2):
        extra = cs.span_resonance_tension(a, zeta)

        def f(c, s, extra=extra):
            return cs.model(c, s) + extra[np.searchsorted(a["index"], s["index"])]

        err = f(cs.fit(a, cal, f), a) / a["sim_peak"] - 1
        # worse on the calibration drives' worst and on the held-out drives (S48-S63) at every zeta
        # (damped sweep, measured: base 17.3 % / 26.4 %; zeta 0.2: 18.8 % / 30.2 %, 0.02: 265 % / 119 %)
        assert np.abs(err[cal]).max() > np.abs(base[cal]).max()
        assert np.abs(err[~cal]).max() > np.abs(base[~cal]).max()


@pytest.mark.slow
def test_undamped_spans_reproduce_the_former_sweep():
    # sweep drive S13 (20B 18/53 at 152 rpm, its tooth frequency 0.94 of the tight span's fourth
    # transverse mode) with span_damping = 0 reproduces the undamped sweep of the sessions before
    # 2026-11-29 (median per-period peak 9065 N, mean 4676 N: the cache then); with the default
    # damping (zeta = 0.02 at the tooth frequency) the cached 5350 N: the undamped resonance raised
    # the peak by 69 % (docs/simulation.md, "Span damping"; docs/design.md, "The damped sweep")
    sw = _sweep()
    s = next(d for d in sw.sweep_drives(64) if d.name == "S13")
    cached = next(r for r in sw.read_cache() if r["name"] == "S13")
    d = sw.drive_of(s)
    periods, settle = sw.periods_and_settle(d)
    t, ts = sw.settled_run(d, periods, settle, contact_stiffness=cached["contact_stiffness"], span_damping=0.0)
    assert float(np.median(sw.tooth_peaks(d, t, ts))) == pytest.approx(9065.0, rel=0.03)
    assert float(ts.mean()) == pytest.approx(4676.0, rel=0.03)
    assert cached["sim_peak"] == pytest.approx(5350.0, rel=0.01)


_RANGE_ARGS = dict(pitch=0.0254, teeth=19, teeth_driven=57, angular_velocity=100.5, centre_distance=1.05,
                   pull=1940.0, breaking_force=60e3)


@pytest.mark.parametrize(("change", "name", "value"), [
    (dict(teeth=29), "teeth", 29.0), (dict(wheels=3), "wheels", 3.0),
    (dict(centre_distance=2.5), "centre_pitches", 2.5 / 0.0254), (dict(pull=12e3), "pull_ratio", 0.2)])
def test_range_violations_name_each_input_outside(change, name, value):
    assert RT.running_tension_range_violations(**_RANGE_ARGS) == ()
    out = RT.running_tension_range_violations(**{**_RANGE_ARGS, **change})
    assert [v[0] for v in out] == [name]
    assert out[0][1] == pytest.approx(value) and tuple(out[0][2:]) == RT.calibration().ranges[name]


def test_leave_one_out_regression():
    # issue 29.4, out of sample over the whole sweep: each of the 64 drives predicted by the constants
    # fitted on the 63 others (the damped sweep, measured: short reference worst 24.0 % (S63), rms
    # 8.0 %, 6 drives beyond 15 %; long reference 21.1 % (S63), rms 7.8 %, 6 beyond 15 %; the undamped
    # sweep had 36.5 % and 34.4 % (S13), 10 and 11 beyond 15 %); a regression
    cs = _calibration_script()
    for ref, many, top in (("short", 6, 0.26), ("long", 6, 0.23)):
        a = cs.load(ref)
        err = np.abs(cs.leave_one_out(a))
        assert len(err) == 64 and a["index"][np.argmax(err)] == 63
        assert 0.19 < err.max() < top and 0.07 < np.sqrt(np.mean(err**2)) < 0.09
        assert int((err > 0.15).sum()) == many
    assert RT.calibration().loo_worst == pytest.approx(np.abs(cs.leave_one_out(cs.load("long"))).max(), abs=1e-3)


def test_steady_state_against_the_sweep_cached():
    # the steady state of the simulation (warm start, settling detected, the implicit step;
    # benchmarks/_dynamic_sweep.py --steady) against the sweep's runs from rest (the damped sweep):
    # its MEAN tension within 1.2 % of the long reference's on every drive, its per-period peak low
    # on average (measured -6.7 %, worst -37.0 % on S21, rms 9.2 %: the implicit step's numerical
    # damping of the seating impacts, docs/simulation.md "Integrator"): not a better stand-in for the
    # peak than the reduced model (docs/design.md, "The running peak tension")
    sw = _sweep()
    ref = {r["name"]: r for r in sw.read_cache()}
    long = {r["name"]: r for r in sw.read_cache(sw.LONG_CACHE)}
    rows = sw.read_cache(sw.STEADY_CACHE)
    e = {r["name"]: float(r["pp"]) / ref[r["name"]]["sim_peak"] - 1 for r in rows}
    err = np.array(list(e.values()))
    assert len(err) == 64
    assert min(e, key=e.get) == "S21" and -0.40 < err.min() < -0.33
    assert -0.09 < err.mean() < -0.05 and 0.08 < np.sqrt(np.mean(err**2)) < 0.11
    mean = np.array([float(r["mean"]) / long[r["name"]]["long_mean"] - 1 for r in rows])
    assert np.abs(mean).max() < 0.013


@pytest.mark.slow
def test_simulated_dynamic_tension_is_the_cached_steady_state():
    # analysis.dynamic_tension.simulated_dynamic_tension on sweep drive S01 (20B 22/45 at 107 rpm,
    # nominal torque) reproduces the cached steady state (same seats, EA, drive): F_t + F_d = pp
    from chaindrive.simulation.running_tension import SIMULATED_VALIDITY, simulated_dynamic_tension

    sw = _sweep()
    s = next(d for d in sw.sweep_drives(64) if d.name == "S01")
    row = next(r for r in sw.read_cache() if r["name"] == "S01")
    steady = next(r for r in sw.read_cache(sw.STEADY_CACHE) if r["name"] == "S01")
    dyn = simulated_dynamic_tension(sw.drive_of(s), row["tight"])
    assert dyn.value + row["tight"] == pytest.approx(steady["pp"], rel=1e-6)
    assert dyn.stiffness == pytest.approx(row["contact_stiffness"], rel=1e-12)
    assert dyn.validity == SIMULATED_VALIDITY and "steady-state simulation" in dyn.model


def test_simulated_dynamic_tension_refuses_a_chain_without_width():
    import dataclasses

    from chaindrive.simulation.running_tension import simulated_dynamic_tension

    sw = _sweep()
    d = sw.drive_of(sw.sweep_drives(64)[1])
    bare = d.replace(chain=dataclasses.replace(d.chain, inner_width=None))
    with pytest.raises(InputError, match="inner width"):
        simulated_dynamic_tension(bare, 4000.0)


def test_validated_range_stored_and_recomputed():
    # issue 29.4: the validated range chosen on the (damped) sweep: no candidate meets the 15 % aim, so
    # the sweep's whole range (chain speed <= 12 m/s: 63 of the 64 drives; measured out of sample worst
    # 22.6 %, rms 8.3 %), no resonance band (the drives on a transverse mode are over-predicted now, the
    # safe side: S63, S18, S00, S02, S11); recomputed from the cached sweep
    cs = _calibration_script()
    a = cs.load("long")
    v = RT.calibration().validated
    assert cs.choose_range(a, np.ones(64, bool)) is None
    assert (v["chain_speed_max"], v["resonance_band"], v["resonance_modes"], v["drives"]) == (12.0, 0.0, 0, 63)
    inside = cs.in_range(a, 12.0, 0.0, 0)
    assert int(inside.sum()) == 63
    err = cs.out_of_sample(cs.subset(a, inside))
    assert np.abs(err).max() == pytest.approx(v["worst"], abs=1e-3) and 0.20 < v["worst"] < 0.25
    assert np.sqrt(np.mean(err**2)) == pytest.approx(v["rms"], abs=1e-3)
    short = cs.out_of_sample(cs.subset(cs.load(), inside))
    assert np.abs(short).max() == pytest.approx(v["short_worst"], abs=1e-3)
    idx, nested = cs.nested_check(a)
    assert len(idx) == v["nested_drives"] == 63
    assert np.abs(nested).max() == pytest.approx(v["nested_worst"], abs=1e-3)
    # the resonance-band candidates of the undamped calibration would not meet the aim either
    assert cs.choose_range(a, np.ones(64, bool), bands=cs.FORMER_BANDS) is None


def test_analysis_states_the_validated_range_or_warns():
    # the roller example (16B 19/57 at 960 rpm) is inside the validated range: its validity says so,
    # with the simulation's span-damping assumption; the self-regulating example (a 23.4-pitch span,
    # outside the sweep's 25-60) says it is outside; a drive above 12 m/s is warned
    from chaindrive.analysis import analyze_drive
    from chaindrive.drive.project import load_project

    a = analyze_drive(load_project(ROOT / "examples" / "roller_industrial.toml"), include=["loads"])
    assert not any("validated range" in str(w) for w in a.warnings)
    assert "in its validated range" in a.loads.dynamic_validity and "22.6 %" in a.loads.dynamic_validity
    assert "zeta = 0.02" in a.loads.dynamic_validity
    b = analyze_drive(load_project(ROOT / "examples" / "self_regulating.toml"), include=["loads"])
    assert "outside its validated range" in b.loads.dynamic_validity
    assert RT.validated_range_violations(12.5, 7.0) == ("chain speed 12.5 m/s is above 12 m/s",)


def test_tooth_frequency_ratio_against_the_string_by_hand():
    # independent: ω1 = (π/l) √(F/q) (1 − v²/c²) by hand (Wickert & Mote 1990, eq. 29), S13's inputs
    w, z, p, f, q, l = 15.949, 18, 0.03175, 4246.0, 3.802, 1.4335
    v = z * w * p / (2 * math.pi)
    c = math.sqrt(f / q)
    w1 = math.pi / l * c * (1 - v**2 / c**2)
    assert float(RT.tooth_frequency_ratio(w, z, p, f, q, l)) == pytest.approx(z * w / w1, rel=1e-12)


@given(st.floats(0.2, 30.0), st.floats(0.0, 0.3), st.integers(0, 20))
def test_span_resonance_mode_is_a_mode_within_the_band(r, band, modes):
    # independent: every mode 1..N checked one by one
    n = int(RT.span_resonance_mode(r, band=band, modes=modes))
    within = [k for k in range(1, modes + 1) if abs(r / k - 1) < band]
    if within:
        assert n == min(within, key=lambda k: abs(r / k - 1))
    else:
        assert n == 0


def test_span_resonance_mode_either_side():
    # the band is relative: 16.495 is nearer 16 but within 3 % of 17 only
    assert int(RT.span_resonance_mode(16.495, band=0.03, modes=20)) == 17
    assert int(RT.span_resonance_mode(12.55, band=0.05, modes=12)) == 12
    assert int(RT.span_resonance_mode(11.5, band=0.3, modes=9)) == 9   # above the last mode


def test_validated_range_refuses_bad_input():
    with pytest.raises(InputError, match="chain_speed"):
        RT.validated_range_violations(0.0, 3.0)
    with pytest.raises(InputError, match="frequency_ratio"):
        RT.validated_range_violations(2.0, float("nan"))
    with pytest.raises(InputError, match="span_length"):
        RT.tooth_frequency_ratio(10.0, 19, 0.0254, 2000.0, 2.6, -1.0)
    with pytest.raises(InputError, match="band"):
        RT.span_resonance_mode(4.0, band=-0.1, modes=8)


def test_analysis_keeps_the_reduced_model_outside_the_input_ranges_warned():
    # the self-regulating example's 23.4-pitch tight span is outside the sweep's 25-60 pitches: the
    # reduced model's F_d (2651 N; 4201 N with the undamped calibration), warned; the steady state is
    # not taken instead (on the three drives outside the ranges checked from rest its per-period peak
    # was -16.8, -3.9, -9.4 % off, the model -13.8, -21.2, -2.7 %: benchmarks/data/dynamic_outside*.csv);
    # the analysis imports no simulation
    # (tests/test_architecture.py: the simulation is the floor above)
    from chaindrive.analysis import analyze_drive
    from chaindrive.drive.project import load_project

    a = analyze_drive(load_project(ROOT / "examples" / "self_regulating.toml"), include=["loads"])
    assert "running_peak_tension" in a.loads.dynamic_source
    assert a.loads.dynamic == pytest.approx(2651, rel=0.01)
    assert any("centre_pitches = 23.4286 is outside the validity range [25, 60]" in w for w in a.warnings)


def test_damped_reference_is_settled():
    # all 64 sweep drives run on to 4 s (benchmarks/_dynamic_sweep.py 64 --long) with the spans damped
    # (zeta = 0.02 at the tooth frequency): their six window medians lie 0.01-6.5 % apart (median
    # 0.7 %; undamped 0.6-34.2 %, median 7.4 %), and the one-window reference is within 2.3 % of the
    # long one (undamped -11.1 to +7.9 %): the references are settled; what is left is the model's
    # (docs/design.md, "The damped sweep")
    cs = _calibration_script()
    a, short = cs.load("long"), cs.load()
    assert len(a["index"]) == 64 and (a["index"] == short["index"]).all()
    apart = a["window_peak_high"] / a["window_peak_low"] - 1
    assert apart.max() < 0.07 and np.median(apart) < 0.01
    diff = short["sim_peak"] / a["sim_peak"] - 1
    assert np.abs(diff).max() < 0.025


def test_simulated_dynamic_tension_refuses_a_non_finite_simulation(monkeypatch):
    # a steady state without a finite peak is refused
    import chaindrive.simulation.running_tension as S
    from chaindrive.simulation.running_tension import _simulated

    class _Nan:
        period_peak_tension = float("nan")

    monkeypatch.setattr(S, "steady_state", lambda model, **kw: _Nan())
    sw = _sweep()
    with pytest.raises(InputError, match="no finite peak"):
        _simulated.__wrapped__(sw.drive_of(sw.sweep_drives(64)[1]), 4000.0)


def test_outside_the_ranges_cached():
    # three drives each outside one of the sweep's ranges (benchmarks/_dynamic_sweep.py --outside):
    # the steady state's per-period peak against the run from rest is -16.8, -3.9 and -9.4 %, the
    # reduced model extrapolated -13.8, -21.2 and -2.7 % (docs/design.md): neither is validated
    # there; a regression of that finding (the damped simulation)
    sw = _sweep()
    rest = {r["name"]: r for r in sw.read_cache(sw.OUTSIDE_CACHE)}
    steady = {r["name"]: float(r["pp"]) for r in sw.read_cache(sw.OUTSIDE_STEADY_CACHE)}
    err = {n: steady[n] / rest[n]["sim_peak"] - 1 for n in rest}
    assert sorted(err) == ["X00", "X01", "X02"]
    assert -0.20 < err["X00"] < -0.13 and -0.07 < err["X01"] < -0.01 and -0.13 < err["X02"] < -0.06
    for s in sw.outside_drives():
        r = rest[s.name]
        assert RT.running_tension_range_violations(
            pitch=r["pitch"], teeth=r["teeth_driving"], teeth_driven=r["teeth_driven"],
            angular_velocity=r["rpm"] * math.pi / 30, centre_distance=r["tight_span"], pull=r["pull"],
            breaking_force=r["pull"] / s.pull_ratio)
