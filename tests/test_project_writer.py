"""The one project writer (chaindrive.drive.writer): a Drive written to TOML reads back equal.

Independent check: parse_project, the loader every user file goes through, reads the text.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

pytest.importorskip("pydantic")

from chaindrive.chains import get  # noqa: E402
from chaindrive.drive import Drive, Guide, Load, Tensioner, Wheel  # noqa: E402
from chaindrive.drive.project import load_project, parse_project  # noqa: E402
from chaindrive.drive.writer import candidate_drive, drive_to_toml, project_text  # noqa: E402

positive = st.floats(1e-3, 1e4, allow_nan=False, allow_infinity=False)
coordinate = st.floats(-20.0, 20.0, allow_nan=False, allow_infinity=False)
# names: any text but brackets (the loader bounds the nesting depth by counting them)
words = st.text(st.characters(blacklist_characters="[]", blacklist_categories=("Cs",)), max_size=60)


@st.composite
def drives(draw: st.DrawFn) -> Drive:
    chain = get(draw(st.sampled_from(["16B", "10A-1", "ANSI 40", "12B-2"])))
    x = draw(st.floats(1.5, 5.0))  # wheels apart (the reader refuses overlapping wheels)
    wheels = [Wheel("motor", "sprocket", draw(st.integers(9, 40)), (0.0, 0.0), driving=True),
              Wheel("fan", "sprocket", draw(st.integers(9, 120)), (x, draw(st.floats(-0.2, 0.2))))]
    tensioner = None
    guides: tuple[Guide, ...] = ()
    if draw(st.booleans()):
        wheels.insert(1, Wheel("idler", "idler", 17, (x / 2, -0.4 - draw(st.floats(0.0, 0.3)))))
        tensioner = Tensioner("idler", mass=draw(positive), stiffness=draw(positive) * 1e3,
                              direction=(0.0, -1.0), force=draw(st.one_of(st.none(), positive)))
    if draw(st.booleans()):
        guides = (Guide("motor", end_distance=draw(st.floats(0.05, 0.5)), kind="tangential"),)
    power = draw(st.booleans())
    load = (Load(power=draw(positive) * 100.0, service_factor=draw(st.floats(1.0, 3.0))) if power
            else Load(torque=draw(positive), service_factor=1.0))
    return Drive(chain=chain, speed=draw(st.floats(1.0, 300.0)), load=load, wheels=tuple(wheels),
                 tensioner=tensioner, guides=guides, links=draw(st.one_of(st.none(), st.integers(20, 400))),
                 slack_sag_ratio=draw(st.floats(0.005, 0.2)), required_static_safety=draw(st.floats(1.5, 20.0)),
                 elongation_limit=draw(st.floats(0.005, 0.1)), name=draw(words.filter(bool)),
                 description=draw(words), travel=draw(st.sampled_from(["ccw", "cw"])))


@settings(max_examples=60, deadline=None)
@given(drives())
def test_round_trip_is_exact(drive: Drive) -> None:
    assert parse_project(project_text(drive)) == drive


@pytest.mark.parametrize("name", ["roller_industrial", "mining_conveyor", "tractor_track", "long_conveyor"])
def test_examples_round_trip(examples_dir, name: str) -> None:
    drive = load_project(examples_dir / f"{name}.toml")
    assert parse_project(project_text(drive)) == drive


def test_custom_chain_and_comments() -> None:
    chain = dataclasses.replace(get("16B"), mass_per_length=3.1)
    d = Drive(chain=chain, speed=50.0, load=Load(torque=200.0),
              wheels=(Wheel("a", "sprocket", 19, (0.0, 0.0), driving=True), Wheel("b", "sprocket", 38, (0.8, 0.0))))
    text = project_text(d, header="my drive", comments={"chain.mass_per_length": "weighed"})
    assert text.startswith("# my drive") and 'mass_per_length = "3.1 kg/m"  # weighed' in text
    assert parse_project(text) == d


def test_candidate_drive_is_the_selected_row() -> None:
    from chaindrive.drive.writer import candidate_project_text as candidate_project
    from chaindrive.selection import select

    row = select(7.5e3, 1450 * np.pi / 30, 3.0)[0]
    d = candidate_drive(row)
    assert parse_project(candidate_project(row)) == d
    assert d.links == row.links and d.wheels[1].position[0] == row.centre_distance


def test_self_regulating_round_trip(examples_dir) -> None:
    drive = load_project(examples_dir / "self_regulating.toml")
    assert parse_project(drive_to_toml(drive)) == drive


def test_control_characters_in_names_round_trip(roller_drive) -> None:
    # found by the round-trip property: DEL (U+007F) must be escaped in a TOML string
    d = roller_drive(name="fan\x7f drive", description="tab\there")
    assert parse_project(project_text(d)) == d
