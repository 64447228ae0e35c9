"""The studio keeps a project's [conveyor] table and shows the chain pull (non-browser)."""

from __future__ import annotations

from chaindrive.web.design import design_from_state, normalise_state, state_from_project
from chaindrive.web.studio import studio_payload


def test_opened_conveyor_keeps_its_table_and_shows_the_chain_pull():
    state = normalise_state(state_from_project(open("examples/scraper_conveyor.toml").read()))
    assert "material_load=100.0 kg/m" in state["conveyor"]
    design, errors = design_from_state(state)
    assert not errors and design is not None and design.drive.conveyor.return_strand == "free"
    rows = studio_payload(state)["loads"]["rows"]
    names = [r[0] for r in rows]
    assert "conveyor: tight tension" in names and "conveyor: drive power" in names
    power = next(r for r in rows if r[0] == "conveyor: drive power")
    assert power[2] == "kW"


def test_plain_drive_has_no_conveyor_rows():
    rows = studio_payload(normalise_state({}))["loads"]["rows"]
    assert not any(r[0].startswith("conveyor") for r in rows)
