"""Deprecation policy: a renamed or moved public name keeps an alias that warns
(FutureWarning) for one release and gives the same results (chaindrive._deprecation)."""

from __future__ import annotations

import importlib

import pytest

from chaindrive.kinematics import dolipinski_worked_case
from chaindrive.strength import skew_paper_contact_coefficient, skew_paper_contact_stress


@pytest.mark.parametrize("module, old, new, args", [
    ("chaindrive.strength", "seed_contact_stress", skew_paper_contact_stress, (10e3, 0.02, 0.005)),
    ("chaindrive.strength.hertz", "seed_contact_stress", skew_paper_contact_stress, (10e3, 0.02, 0.005)),
    ("chaindrive.strength", "seed_contact_coefficient", skew_paper_contact_coefficient, (0.3,)),
    ("chaindrive.strength.hertz", "seed_contact_coefficient", skew_paper_contact_coefficient, (0.3,)),
])
def test_renamed_functions_warn_and_work(module, old, new, args):
    alias = getattr(importlib.import_module(module), old)
    with pytest.warns(FutureWarning, match=rf"{module}\.{old} is deprecated and will be removed in the "
                                           rf"next release; use chaindrive\.strength\.hertz\.{new.__name__}"):
        value = alias(*args)
    assert value == new(*args)
    assert "Deprecated alias" in alias.__doc__ and "seed" not in alias.__doc__


def test_renamed_worked_case_warns_and_works():
    from chaindrive import kinematics

    with pytest.warns(FutureWarning, match="seed002_case is deprecated .* use chaindrive.kinematics.entry."
                                           "dolipinski_worked_case"):
        old = kinematics.seed002_case(points=11)
    new = dolipinski_worked_case(points=11)
    assert old.keys() == new.keys()
    assert all(type(old[k]) is type(new[k]) for k in new)


def test_from_import_of_a_former_name_works():
    with pytest.warns(FutureWarning):
        from chaindrive.strength import seed_contact_stress

        seed_contact_stress(10e3, 0.02, 0.005)


@pytest.mark.parametrize("old, new, name", [
    ("chaindrive.drive.layout", "chaindrive.layout", "chain_length_links"),
    ("chaindrive.drive.loads", "chaindrive.loads", None),
    ("chaindrive.drive.selection", "chaindrive.selection", "select"),
    ("chaindrive.drive.wear", "chaindrive.life.wear", None),
    ("chaindrive.wear", "chaindrive.life.wear", "wear_life"),
    ("chaindrive.static_safety", "chaindrive.loads.safety", "static_safety"),
    ("chaindrive.motor", "chaindrive.drivetrain.motor", "Motor"),
    ("chaindrive.coupling", "chaindrive.drivetrain.coupling", "FluidCoupling"),
    ("chaindrive.drive.self_regulating", "chaindrive.self_regulating", "self_regulating_drive"),
    ("chaindrive.drive.self_regulating", "chaindrive.drive.carrier", "SelfRegulatingSpec"),
    ("chaindrive.drive.self_regulating", "chaindrive.analysis.self_regulating", "self_regulating_analysis"),
])
def test_moved_modules_warn_and_forward(old, new, name):
    target = importlib.import_module(new)
    name = name or next(n for n in getattr(target, "__all__", dir(target)) if not n.startswith("_"))
    if not hasattr(target, name):
        name = next(n for n in getattr(target, "__all__", dir(target)) if not n.startswith("_"))
    moved = importlib.import_module(old)
    with pytest.warns(FutureWarning, match=rf"{old}\.{name} is deprecated .* use {new}\.{name}"):
        value = getattr(moved, name)
    assert value is getattr(target, name)


def test_unknown_names_still_raise():
    import chaindrive.kinematics
    import chaindrive.strength

    with pytest.raises(AttributeError, match="has no attribute 'nothing_here'"):
        chaindrive.strength.nothing_here  # noqa: B018
    with pytest.raises(AttributeError):
        chaindrive.kinematics.nothing_here  # noqa: B018


def test_split_modules_keep_their_names():
    # vibration.resonance and geometry.sprocket were split by topic; every name still imports
    from chaindrive.geometry import sprocket, tooth_form
    from chaindrive.vibration import resonance, tensioner_design

    assert resonance.campbell is tensioner_design.campbell
    assert sprocket.sprocket_outline is tooth_form.sprocket_outline


def test_selection_select_is_deprecated_for_the_design_procedure():
    """`chaindrive.selection.select` (K_s = 1 and 17 teeth unless told, its own static safety) gave another
    answer than the one design procedure: it warns and names `design_drive`."""
    import math

    from chaindrive.selection import select

    with pytest.warns(FutureWarning, match=r"chaindrive\.selection\.select is deprecated and will be removed: "
                                           r"use chaindrive\.design\.design_drive"):
        rows = select(7.5e3, 1450 * math.pi / 30, 3.0)
    assert rows
