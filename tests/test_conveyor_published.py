"""The chain pull of the `conveyor` analysis part against the chain makers' published
method, applied exactly (formula by formula), through ``analyze``.

Provenance
----------
e-uparts machine handbook (e-uparts.com, *kikaibinran*), sheet 20-3, "Calculation formula
of tension acting on the chain (inclined transport)",
https://e-uparts.com/up2/en/kikaibinran/keisan/keisan20-3.htm (stored copy read for this
test): with ``M`` the chain [kgf/m], ``W`` the material [kgf/m], ``L`` and ``H`` the
horizontal and vertical sprocket centre distance [m], ``f1`` chain on guide, ``f``
material (accumulating/scraped) friction:

    T1 = M (L f1 - H)                       (return run, going down; T1 < 0 -> T2 = 0)
    T2 = 1.1 T1                              (sprocket at the tail)
    TMAX = W (L f + H) + M (L f1 + H) + T2   [kgf]
    kW = TMAX V alpha / (102 x 60 eta)       (V in m/min, alpha motor safety factor)

and Tsubakimoto Chain Co., *Technical data: large size conveyor chain, selection*, 9.
"Calculate chain load" (tt-net.tsubakimoto.co.jp/tecs/engd/clc/engd_clc_sen_ksn.asp):
``W = 16.7 Q / V`` for bulk material (``Q`` t/h, ``V`` m/min; "16.7 = 1000/60").

Neither page prints a numeric worked example (the sheets are calculators with empty
result fields), so the inputs below are chosen here and the test applies the published
formulas to them exactly. Two documented differences of chaindrive's loop walk
(docs/conveyor.md), stated and reproduced here rather than hidden in a tolerance:

1. the sheet multiplies the return run by a sprocket factor 1.1 at the tail; chaindrive
   has no sprocket losses (factor 1.0);
2. the sheet puts the friction and the material on the whole centre distance ``L``;
   chaindrive's pans stop ``pan_end_clearance`` short of each wheel (the chain ends hang
   free: their weight, no friction, no material), so the friction acts on the pans'
   horizontal projection ``L_p`` and the material is lifted by ``H_p = L_p tan α``.

With ``L -> L_p``, the material's ``H -> H_p`` and 1.1 -> 1.0 the sheet's numbers are
reproduced to floating-point precision; with the sheet's own ``L``, ``H`` and 1.1 the
differences are exactly those terms.
"""

from __future__ import annotations

import math

import pytest

from chaindrive import chains
from chaindrive import conveyor as C
from chaindrive.analysis import analyze_drive
from chaindrive.drive.model import Conveyor, Drive, Load, Wheel
from chaindrive.geometry.polygon import link_chain_pitch_radius
from chaindrive.layout import GRAVITY

CHORD = 20.0                   # sprocket centre distance along the incline [m]
RISE = 4.0                     # head above the tail [m]
F1, F = 0.4, 0.6               # chain on pans, scraped coal on pans
Q_TPH = 200.0                  # capacity [t/h]
POCKETS = 8


def _drive(minimum=0.0):
    alpha = math.asin(RISE / CHORD)
    wheels = (Wheel("head", "pocket_wheel", POCKETS, (0.0, 0.0), driving=True),
              Wheel("tail", "pocket_wheel", POCKETS, (CHORD, 0.0)))
    conv = Conveyor(chain_friction=F1, material_friction=F, capacity=Q_TPH / 3.6, inclination=alpha,
                    return_strand="supported", minimum_tension=minimum, efficiency=0.85)
    return Drive(chain=chains.get("18x64"), wheels=wheels, speed=5.0, load=Load(power=30e3), conveyor=conv)


def _sheet(M, W, L, H, sprocket=1.1, material_rise=None):
    """e-uparts sheet 20-3, verbatim (kgf); ``material_rise`` replaces ``H`` in the
    material's term (default ``H``, as printed)."""
    hm = H if material_rise is None else material_rise
    t1 = M * (L * F1 - H)
    t2 = sprocket * t1 if t1 > 0 else 0.0
    tmax = W * (L * F + hm) + M * (L * F1 + H) + t2
    return t1, t2, tmax


def test_inclined_scraper_conveyor_follows_the_published_sheet():
    d = _drive()
    a = analyze_drive(d, include=["conveyor"])
    r = a.conveyor
    chain = d.chain
    M = float(chain.mass_per_length)
    v = r.chain_speed
    # Tsubaki 9.1: W = 16.7 Q / V (Q t/h, V m/min); chaindrive uses 1000/60 exactly
    w_tsubaki = 16.7 * Q_TPH / (v * 60.0)
    W = float(C.material_mass_per_length(Q_TPH / 3.6, v))
    assert r.material_load == pytest.approx(W, rel=1e-12)
    assert W == pytest.approx(w_tsubaki, rel=2.1e-3)          # 16.7 vs 16.667: 0.2 %
    alpha = math.asin(RISE / CHORD)
    L, H = CHORD * math.cos(alpha), RISE
    # the pans: centre distance less the free ends at both wheels (independently here)
    radius = float(link_chain_pitch_radius(chain.pitch, chain.bar_diameter, POCKETS))
    ends = 2 * float(C.pan_end_clearance(radius, 0.5 * chain.bar_diameter, chain.pitch))
    Lp = (CHORD - ends) * math.cos(alpha)

    # 1. the published formulas with L_p, H_p and no sprocket factor: chaindrive to rounding
    Hp = Lp * math.tan(alpha)
    t1, t2, tmax = _sheet(M, W, Lp, H, sprocket=1.0, material_rise=Hp)
    s0 = r.slack_tension        # the sheet's zero at the head's exit; chaindrive's floor 1 N
    assert s0 == pytest.approx(1.0, abs=1e-9)
    assert r.return_resistance == pytest.approx(t1 * GRAVITY, rel=1e-9)            # T1
    assert r.tight_tension - s0 == pytest.approx(tmax * GRAVITY, rel=1e-9)         # TMAX
    assert r.carrying_resistance == pytest.approx((tmax - t2) * GRAVITY, rel=1e-9)
    # drive power, kW = TMAX V alpha / (102 x 60 eta) with alpha = 1 (102 kgf m/s = 1 kW)
    kw = tmax * (v * 60.0) * 1.0 / (102.0 * 60.0 * 0.85)
    assert r.drive_force == pytest.approx(r.tight_tension - s0, rel=1e-12)
    assert r.drive_power / 1e3 == pytest.approx(kw, rel=2e-3)   # 102 vs 1000/g = 101.97: 0.03 %

    # 2. the sheet as printed (whole L, 1.1 at the tail): larger by exactly the two terms
    p1, p2, pmax = _sheet(M, W, L, H)
    on_free_ends = (W * F + 2 * M * F1) * (L - Lp) + W * (H - Hp)
    assert (pmax - tmax) == pytest.approx(on_free_ends + 0.1 * p1, rel=1e-9)
    assert p1 - t1 == pytest.approx(M * F1 * (L - Lp), rel=1e-9)
    # the differences are small: the pan ends 0.5 % of L, the sprocket factor 1.3 % of TMAX
    assert 0.0 < (pmax - tmax) / pmax < 0.02


def test_the_sheets_zero_clamp_of_a_steep_return():
    # T1 < 0 (the return run pulls itself down the incline): the sheet sets T2 = 0, the
    # zero tension at the tail's exit; chaindrive puts its stated minimum there (the lowest
    # sprocket exit), so TMAX is the sheet's plus the minimum, and the head's exit carries
    # minimum - T1
    steep = math.asin(0.5)
    d = _drive(minimum=1000.0)
    import dataclasses

    d = dataclasses.replace(d, conveyor=dataclasses.replace(d.conveyor, inclination=steep))
    r = analyze_drive(d, include=["conveyor"]).conveyor
    M = float(d.chain.mass_per_length)
    assert r.return_resistance < 0
    assert r.slack_tension == pytest.approx(1000.0 - r.return_resistance, rel=1e-9)
    radius = float(link_chain_pitch_radius(d.chain.pitch, d.chain.bar_diameter, POCKETS))
    ends = 2 * float(C.pan_end_clearance(radius, 0.5 * d.chain.bar_diameter, d.chain.pitch))
    Lp, H = (CHORD - ends) * math.cos(steep), CHORD * math.sin(steep)
    W = r.material_load
    t1, t2, tmax = _sheet(M, W, Lp, H, material_rise=Lp * math.tan(steep))
    assert t1 < 0 and t2 == 0.0
    assert r.return_resistance == pytest.approx(t1 * GRAVITY, rel=1e-9)
    assert r.tight_tension - 1000.0 == pytest.approx(tmax * GRAVITY, rel=1e-9)
    assert r.minimum_tension == pytest.approx(1000.0, rel=1e-9)
