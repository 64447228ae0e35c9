"""drive_to_toml: a drive written as a project file reads back equal."""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import pytest

from chaindrive.drive.project import TEMPLATES, load_project, parse_project
from chaindrive.drive.writer import drive_to_toml
from chaindrive.errors import InputError

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


@pytest.mark.parametrize("name", ["long_conveyor", "mining_conveyor", "roller_industrial", "tractor_track"])
def test_examples_round_trip(name):
    d = load_project(EXAMPLES / f"{name}.toml")
    assert parse_project(drive_to_toml(d)) == d


@pytest.mark.parametrize("kind", sorted(TEMPLATES))
def test_templates_round_trip(kind):
    d = parse_project(TEMPLATES[kind])
    assert parse_project(drive_to_toml(d, header="written by a test\nsecond line")) == d


def test_changed_tensioner_and_custom_chain_are_written():
    d = load_project(EXAMPLES / "mining_conveyor.toml")
    t = dataclasses.replace(d.tensioner, mass=12.5, stiffness=3.25e5, force=7e3)
    chain = dataclasses.replace(d.chain, mass_per_length=7.0)  # no longer the catalogue chain
    d2 = dataclasses.replace(d, tensioner=t, chain=chain)
    text = drive_to_toml(d2)
    assert 'mass = "12.5 kg"' in text and 'mass_per_length = "7.0 kg/m"' in text
    assert parse_project(text) == d2


def test_self_regulating_round_trips_and_non_finite_refused():
    d = load_project(EXAMPLES / "self_regulating.toml")
    assert parse_project(drive_to_toml(d)) == d
    with pytest.raises(InputError, match="non-finite"):
        from chaindrive.drive.writer import quantity_text

        quantity_text(math.nan, "m")


def test_crawler_fretting_and_rim_bolts_tables_are_written():
    from chaindrive.drive.model import FrettingSpec

    d = load_project(EXAMPLES / "crawler_conveyor.toml")
    d2 = dataclasses.replace(d, fretting=FrettingSpec(roughness=0.8e-6, latent_coefficient=1e9,
                                                      decay_coefficient=1e-6, frequency=12.5))
    text = drive_to_toml(d2)
    assert "[crawler]" in text and 'stiffness = "20000000.0 N"' in text and "[fretting]" in text
    assert parse_project(text) == d2
    t = drive_to_toml(load_project(EXAMPLES / "tractor_track.toml"))
    assert "[track.bolts]" in t and 'circle_radius = "0.26 m"' in t
