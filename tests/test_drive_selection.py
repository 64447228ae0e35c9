"""Tests of chaindrive.drive.selection against published ANSI rating tables."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from chaindrive.drive import selection as S
from chaindrive.errors import InfeasibleError, InputError, UnknownNameError, ValidityRangeWarning

RPM = 2 * math.pi / 60
HP = S.HP

# Published rating table of ANSI No. 40 single-strand roller chain [hp], rows small
# sprocket teeth 11…18, columns rpm 50…1800. Source: Engineers Edge, "Single Strand
# Roller Chain Number 40 Horsepower Ratings Table" (ANSI/ACA ratings),
# https://www.engineersedge.com/hardware/single_strand_roller_chain_number_40_13897.htm
# The 1800-rpm column is in the roller-bushing regime, the others link-plate.
RPM_40 = [50, 100, 200, 300, 400, 500, 700, 900, 1000, 1200, 1400, 1600, 1800]
TABLE_40 = {
    11: [0.23, 0.43, 0.80, 1.16, 1.50, 1.83, 2.48, 3.11, 3.42, 4.03, 4.63, 5.22, 4.66],
    12: [0.25, 0.47, 0.88, 1.27, 1.65, 2.01, 2.73, 3.42, 3.76, 4.43, 5.09, 5.74, 5.31],
    13: [0.28, 0.52, 0.96, 1.39, 1.80, 2.20, 2.97, 3.73, 4.10, 4.83, 5.55, 6.26, 5.99],
    14: [0.30, 0.56, 1.04, 1.50, 1.95, 2.38, 3.22, 4.04, 4.44, 5.23, 6.01, 6.78, 6.70],
    15: [0.32, 0.60, 1.12, 1.62, 2.10, 2.56, 3.47, 4.35, 4.78, 5.64, 6.47, 7.30, 7.43],
    16: [0.35, 0.65, 1.20, 1.74, 2.25, 2.75, 3.72, 4.66, 5.13, 6.04, 6.94, 7.83, 8.18],
    17: [0.37, 0.69, 1.29, 1.85, 2.40, 2.93, 3.97, 4.98, 5.48, 6.45, 7.41, 8.36, 8.96],
    18: [0.39, 0.73, 1.37, 1.97, 2.55, 3.12, 4.22, 5.30, 5.82, 6.86, 7.88, 8.89, 9.76],
}

# ANSI No. 41 (K_p = 0.0022, K_r = 3.4), 17 teeth, rpm 10…1400. Source: Engineers Edge,
# "Roller Chain No 41 Horsepower and Speed Ratings".
RPM_41 = [10, 25, 50, 100, 200, 300, 400, 500, 700, 900, 1000, 1200, 1400]
ROW_41_17 = [0.05, 0.11, 0.20, 0.38, 0.71, 1.02, 1.32, 1.61, 2.18, 2.74, 3.01, 3.29, 2.61]


@pytest.mark.parametrize("teeth", sorted(TABLE_40))
def test_ansi_40_table_whole_speed_range(teeth):
    n = np.array(RPM_40, dtype=float)
    got = S.ansi_rated_power(0.0127, teeth, n * RPM) / HP
    # the table is printed to 0.01 hp: rounding allows ±0.005; 0.006 for float noise
    assert np.allclose(got, TABLE_40[teeth], atol=0.006, rtol=0)


def test_ansi_41_table():
    kp, kr = S.ansi_constants("ANSI 41")
    got = S.ansi_rated_power(0.0127, 17, np.array(RPM_41) * RPM, plate_constant=kp,
                             roller_constant=kr) / HP
    assert np.allclose(got, ROW_41_17, atol=0.006, rtol=0)


def test_limits_cross_and_regimes():
    # link plate grows with n^0.9, roller-bushing falls with n^-1.5
    n = np.array([100, 3000]) * RPM
    h1 = S.ansi_link_plate_power(17, n, 0.0127)
    h2 = S.ansi_roller_bushing_power(17, n, 0.0127)
    assert h1[0] < h2[0] and h1[1] > h2[1]
    assert h1[1] / h1[0] == pytest.approx(30**0.9)
    assert h2[0] / h2[1] == pytest.approx(30**1.5)


def test_multi_strand_and_tooth_factor():
    one = float(S.ansi_rated_power(0.0254, 17, 500 * RPM))
    assert float(S.ansi_rated_power(0.0254, 17, 500 * RPM, strands=3)) == pytest.approx(2.5 * one)
    assert [S.multi_strand_factor(k) for k in (1, 2, 3, 4)] == [1.0, 1.7, 2.5, 3.3]
    with pytest.raises(InputError, match=r"strands must be a whole number in \[1, 4\]"):
        S.multi_strand_factor(5)
    # K1 converts the 17-tooth value to z teeth (Shigley Table 17-22)
    for z in (11, 19, 25):
        h17 = float(S.ansi_link_plate_power(17, 300 * RPM, 0.0254))
        hz = float(S.ansi_link_plate_power(z, 300 * RPM, 0.0254))
        assert hz == pytest.approx(h17 * float(S.tooth_correction_factor(z)))
        r17 = float(S.ansi_roller_bushing_power(17, 3000 * RPM, 0.0254))
        rz = float(S.ansi_roller_bushing_power(z, 3000 * RPM, 0.0254))
        assert rz == pytest.approx(r17 * float(S.tooth_correction_factor(z, "roller_bushing")))
    with pytest.raises(UnknownNameError, match="unknown regime"):
        S.tooth_correction_factor(17, "galling")


def test_constants_by_name():
    assert S.ansi_constants("ANSI 25-1") == (0.004, 29.0)
    assert S.ansi_constants("06C-2") == (0.004, 29.0)
    assert S.ansi_constants("41") == (0.0022, 3.4)
    assert S.ansi_constants("ANSI 240-3") == (0.004, 17.0)


def test_rating_warns_outside_tooth_range():
    with pytest.warns(ValidityRangeWarning, match="teeth = 60"):
        S.ansi_link_plate_power(60, 100, 0.0254)


def test_lubrication_type():
    # McGuire Bearing table, ANSI 80 (1 in): type A up to 170 ft/min (0.8636 m/s),
    # type B up to 1500 ft/min (7.62 m/s)
    v = np.array([0.86, 0.87, 7.6, 7.7])
    assert list(S.lubrication_type(v, 0.0254)) == ["I", "II", "II", "III"]
    with pytest.warns(ValidityRangeWarning, match="outside the lubrication table"):
        S.lubrication_type(1.0, 0.00635)


def test_select_smallest_first_and_consistent():
    w = 960 * RPM
    found = S.select(15e3, w, 3.0, service_factor=1.3, teeth_driving=19)
    pitches = [c.pitch for c in found]
    assert pitches == sorted(pitches)
    for c in found:
        assert c.rated_power >= c.design_power == pytest.approx(19.5e3)
        assert c.teeth_driven == 57
        assert c.static_safety is None or c.static_safety >= 6.0
        assert c.lubrication in ("I", "II", "III")
    best = found[0]
    # the best is the smallest pitch whose rating carries 19.5 kW: check one smaller
    # pitch fails for every strand count
    smaller = [c for c in found if c.pitch < best.pitch]
    assert not smaller
    assert float(S.ansi_rated_power(0.0127, 19, w, strands=3)) < 19.5e3
    assert S.select(15e3, w, 3.0, limit=2).__len__() == 2


def test_select_errors():
    with pytest.raises(InputError, match="ratio must be >= 1"):
        S.select(1e3, 100, 0.5)
    with pytest.raises(InputError, match="service_factor must be >= 1"):
        S.select(1e3, 100, 2, service_factor=0.8)
    with pytest.raises(InputError, match="power must be positive"):
        S.select(-1, 100, 2)
    with pytest.raises(UnknownNameError, match="unknown roller-chain family 'din22252'"):
        S.select(1e3, 100, 2, family="din22252")
    with pytest.raises(InfeasibleError, match="no catalogue roller chain carries"):
        S.select(5e6, 3000 * RPM, 2)


def test_select_no_warning_leak():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        S.select(2e3, 300 * RPM, 2, teeth_driving=50)
