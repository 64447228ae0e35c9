"""The vectorised ``batch=`` functions of the analysis parts equal the parts' own compute,
variant by variant (to 1e-12), warnings, checks and errors included; the variants' drives
built by analyze_variants equal those of replace_paths."""

from __future__ import annotations

import dataclasses
import json
import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from chaindrive.analysis import analyze_drive
from chaindrive.analysis.batch import analyze_variants, replace_paths
from chaindrive.analysis.parts import get_part, temporary_part
from chaindrive.drive.project import load_project
from chaindrive.errors import ChainDriveError, InputError
from test_study_batch import _same

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
ARCMIN = math.pi / 180 / 60


def _roller(skew: float = 60 * ARCMIN):
    d = load_project(EXAMPLES / "roller_industrial.toml")
    return dataclasses.replace(d, contact=dataclasses.replace(d.contact, skew=skew, skew_height_difference=None,
                                                              skew_base=None))


def _equal_to_analyze_drive(drive, changes, **kwargs) -> list:
    out = analyze_variants(drive, changes, errors="return", **kwargs)
    assert len(out) == len(changes)
    for got, change in zip(out, changes, strict=True):
        try:
            ref = analyze_drive(replace_paths(drive, change), **kwargs)
        except ChainDriveError as exc:
            assert isinstance(got, type(exc)) and str(got) == str(exc)
            continue
        assert not isinstance(got, BaseException), got
        assert _same(json.loads(json.dumps(ref.to_dict())), json.loads(json.dumps(got.to_dict())))
        assert got.warnings == ref.warnings
        assert got.checks == ref.checks
    return out


@pytest.fixture
def no_compute():
    """The contact and service-life parts with a compute that fails for every drive but
    the base one (60'): only their batch functions can give the variants' results."""
    contact, life = get_part("contact"), get_part("service_life")

    def only_base(part):
        def compute(ctx):
            if ctx.drive.contact.skew != 60 * ARCMIN:
                raise AssertionError("computed one by one")
            return part.compute(ctx)
        return compute

    with temporary_part(dataclasses.replace(contact, compute=only_base(contact))), \
            temporary_part(dataclasses.replace(life, compute=only_base(life))):
        yield


def test_contact_and_service_life_batches_are_used(no_compute):
    drive = _roller()
    changes = [{("contact", "skew"): s * ARCMIN, ("contact", "wear_factor"): k}
               for s, k in ((42, 0.6), (100, 0.65), (206, 0.7), (150, 0.62))]
    out = analyze_variants(drive, changes)
    assert out.per_variant == ("contact", "service_life", "life")  # the life reads the service life
    assert [round(a.contact.skew / ARCMIN) for a in out] == [42, 100, 206, 150]
    assert all(a.service_life.relative_life == a.contact.result.relative_life_wear for a in out)


def test_contact_batch_equals_compute_with_each_variants_warnings():
    # inside the measured ranges, above the largest measured skew (3°26'), wear factors
    # outside the paper's 0.6...0.7: each variant warns as its own analysis does
    changes = [{("contact", "skew"): s * ARCMIN, ("contact", "wear_factor"): k}
               for s, k in ((42, 0.6), (100, 0.65), (206, 0.7), (300, 0.65), (80, 0.5), (0.0, 0.9),
                            (250, 0.95), (120, 0.64))]
    out = _equal_to_analyze_drive(_roller(), changes)
    assert len({a.warnings for a in out}) > 2


def test_contact_batch_errors_fall_back_to_each_variants_message():
    changes = [{("contact", "skew"): 60 * ARCMIN, ("contact", "wear_factor"): k} for k in (0.65, 1.5, 0.7)]
    out = _equal_to_analyze_drive(_roller(), changes)
    assert isinstance(out[1], InputError) and "wear_factor" in str(out[1])
    with pytest.raises(InputError, match="wear_factor"):
        analyze_variants(_roller(), changes)


def test_service_life_batch_over_power_and_skew():
    # power changes the loads, the rating margin, the wear life: every part is per variant
    # and the batch functions see different wear results (they decline, compute runs)
    changes = [{("contact", "skew"): s * ARCMIN, ("load", "power"): p}
               for s, p in ((60, 5e3), (120, 15e3), (200, 25e3))]
    out = _equal_to_analyze_drive(_roller(), changes)
    assert "service_life" in out.per_variant


def test_service_life_batch_without_wear_part():
    out = _equal_to_analyze_drive(_roller(), [{("contact", "skew"): s * ARCMIN} for s in (50, 90)],
                                  include=["contact", "loads"])
    assert out[0].service_life is None


def test_variant_drives_equal_replace_paths():
    drive = _roller()
    changes = [{("wheels", 0, "teeth"): z, ("wheels", 1, "teeth"): 3 * z, ("contact", "skew"): 0.01 * z}
               for z in (17, 19, 21)]
    changes.append({("wheels", 0, "teeth"): 2, ("wheels", 1, "teeth"): 57, ("contact", "skew"): 0.02})
    out = analyze_variants(drive, changes, include=["layout"], errors="return")
    for got, change in zip(out[:3], changes[:3], strict=True):
        assert got.drive == replace_paths(drive, change)
    with pytest.raises(InputError) as ref:
        replace_paths(drive, changes[3])
    assert isinstance(out[3], InputError) and str(out[3]) == str(ref.value)
    # a path and one inside it: replace_paths decides for every variant
    whole = [{("contact",): dataclasses.replace(drive.contact, skew=s), ("contact", "skew"): s} for s in (0.01, 0.02)]
    assert [a.drive for a in analyze_variants(drive, whole, include=["layout"])] == \
        [replace_paths(drive, c) for c in whole]


@pytest.mark.slow
@settings(max_examples=8, deadline=None)
@given(st.lists(st.tuples(st.floats(0.0, 0.08), st.floats(0.3, 1.2)), min_size=2, max_size=8))
def test_batched_contact_and_service_life_equal_analyze_drive(variants):
    changes = [{("contact", "skew"): s, ("contact", "wear_factor"): k} for s, k in variants]
    _equal_to_analyze_drive(_roller(), changes)


def test_entry_batch_solves_each_distinct_entry_once():
    # positions change the layout, not the entry kinematics: one solution per tooth count
    drive = _roller()
    changes = [{("wheels", 0, "teeth"): z, ("wheels", 1, "position"): (x, 0.0)}
               for z in (19, 21) for x in (0.95, 1.0, 1.1)]
    out = _equal_to_analyze_drive(drive, changes)
    assert "entry" in out.per_variant
    assert out[0].entry is out[1].entry is out[2].entry and out[3].entry is out[5].entry
    assert out[0].entry is not out[3].entry
    # a conveyor with a guided (tangential) entry on its driving wheel
    mining = load_project(EXAMPLES / "mining_conveyor.toml")
    x, y = mining.wheels[1].position
    _equal_to_analyze_drive(mining, [{("wheels", 1, "position"): (x * f, y)} for f in (0.98, 1.0, 1.02)],
                            include=["entry", "loads"])


def test_entry_batch_errors_fall_back_to_each_variant():
    drive = _roller()
    out = _equal_to_analyze_drive(drive, [{("wheels", 0, "teeth"): z} for z in (19, 2, 21)], include=["entry"])
    assert isinstance(out[1], InputError)


def test_variant_drives_inside_a_field_skip_only_the_drives_own_checks():
    from chaindrive.analysis.batch import _rebuild_plan, _shell

    drive = _roller()
    paths = [("contact", "skew"), ("contact", "wear_factor"), ("load", "power")]
    # the drive's __post_init__ reads none of the contact's and load's fields: the variants'
    # drives are the base's fields with their own (checked) contact and load
    assert _shell(drive, _rebuild_plan(drive, paths))[0] == "shell"
    assert _shell(drive, _rebuild_plan(drive, [("wheels", 0, "teeth")]))[0] == "object"
    changes = [dict(zip(paths, v, strict=True)) for v in ((0.01, 0.6, 5e3), (0.02, 0.7, 20e3), (0.03, 0.65, -1.0))]
    changes.append({("contact", "skew"): 0.01, ("contact", "skew_height_difference"): 1e-3})
    out = analyze_variants(drive, changes[:3], include=["loads"], errors="return")
    assert [a.drive for a in out[:2]] == [replace_paths(drive, c) for c in changes[:2]]
    with pytest.raises(InputError) as ref:
        replace_paths(drive, changes[2])
    assert isinstance(out[2], InputError) and str(out[2]) == str(ref.value)
    twice = analyze_variants(drive, [changes[3], changes[3]], include=["loads"], errors="return")
    with pytest.raises(InputError, match="not both"):
        replace_paths(drive, changes[3])
    assert all(isinstance(e, InputError) and "not both" in str(e) for e in twice)
