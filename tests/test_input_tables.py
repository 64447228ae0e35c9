"""The input tables declared once (chaindrive.drive.schema, chaindrive.drive.tables): the reader,
the writer and the docs table follow the declarations; a part's own table needs no other file."""

from __future__ import annotations

import importlib.util
import tomllib
from dataclasses import dataclass
from pathlib import Path

import pytest

from chaindrive.drive.project import TEMPLATES, parse_project, template
from chaindrive.drive.schema import (
    REQUIRED,
    Input,
    InputTable,
    all_tables,
    docs_table,
    get_table,
    register_table,
    unregister_table,
)
from chaindrive.drive.writer import mapping_text, project_text
from chaindrive.errors import InputError

ROOT = Path(__file__).resolve().parents[1]


def _script():
    spec = importlib.util.spec_from_file_location("input_docs", ROOT / "scripts" / "input_docs.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_docs_table_is_current():
    from chaindrive.drive.schema import load_providers

    load_providers()
    text = (ROOT / "docs" / "drive.md").read_text(encoding="utf-8")
    assert _script().current(text) == docs_table(), "run: python scripts/input_docs.py"


@pytest.mark.parametrize("kind", sorted(TEMPLATES))
def test_every_template_key_is_declared(kind):
    # the templates of `chaindrive new` use only declared tables and fields
    data = tomllib.loads(TEMPLATES[kind])
    for name, table in data.items():
        decl = get_table(name)
        if decl.extra.get("mapping"):
            continue
        for entry in table if isinstance(table, list) else [table]:
            for key, value in entry.items():
                if isinstance(value, dict):
                    assert get_table(f"{name}.{key}")
                else:
                    decl.field(key)


def test_declared_bounds_give_the_messages():
    # generated from the declaration: (0, 0.2] for the sag ratio, >= 1 for the service factor
    text = template("roller").replace("slack_sag_ratio = 0.02", "slack_sag_ratio = 0.3")
    with pytest.raises(InputError, match=r"drive.slack_sag_ratio: slack_sag_ratio must lie in \(0, 0.2\], got 0.3"):
        parse_project(text, "d.toml")
    assert get_table("load").field("service_factor").range_text() == ">= 1"
    assert get_table("wheels").field("teeth").range_text() == "[3, 10000]"


def test_every_table_is_written_and_read_back():
    names = {t.name for t in all_tables()}
    assert {"drive", "chain", "load", "wheels", "tensioner", "guides", "contact", "track", "track.bolts",
            "crawler", "fretting", "conveyor", "self_regulating", "adjustable"} <= names


@dataclass(frozen=True)
class _Brake:
    torque: float
    pads: int = 2


def test_a_part_declares_its_own_table():
    # what an analysis part with a new input table does in its own module: declare the table
    table = InputTable("brake", (Input("torque", "quantity", unit="N*m", default=REQUIRED, minimum=0.0,
                                       open_minimum=True, help="holding torque"),
                                 Input("pads", "integer", default=2, minimum=1, maximum=8, help="pads")),
                       help="a brake on the driving shaft", target=_Brake, order=50)
    register_table(table)
    try:
        text = template("roller") + '\n[brake]\ntorque = "1.5 kN*m"\npads = 4\n'
        d = parse_project(text)
        assert d.input("brake") == _Brake(1500.0, 4)
        written = project_text(d)
        assert '[brake]\ntorque = "1500.0 N*m"\npads = 4' in written
        assert parse_project(written) == d
        with pytest.raises(InputError, match=r"d.toml:\d+: brake.torque: torque must be positive"):
            parse_project(text.replace("1.5 kN*m", "-1 N*m"), "d.toml")
        assert "`brake.torque`" in docs_table()
    finally:
        unregister_table("brake")
    with pytest.raises(InputError, match=r"brake: unknown field"):
        parse_project(text, "d.toml")


def test_mapping_text_reads_back_as_the_mapping():
    data = tomllib.loads(template("mining"))
    assert tomllib.loads(mapping_text(data)) == data


def test_designed_drives_are_built_in_code_and_written_exactly():
    # the design procedure builds its drives (no TOML text parsed back); the file it writes
    # reads back to the same drive
    from chaindrive.design import Duty, design_drive

    result = design_drive(Duty(7.5e3, 1450 * 3.141592653589793 / 30, ratio=3.0, service_factor=1.3), limit=2)
    for c in result.candidates:
        assert c.built is not None and parse_project(c.project_text) == c.drive()


def test_studio_file_reads_back_as_its_drive():
    from chaindrive.web.design import design_from_state, normalise_state, state_from_project

    for state in (normalise_state({}), normalise_state(state_from_project(template("mining")))):
        d, errors = design_from_state(state)
        assert errors == {} and parse_project(d.project_text) == d.drive


@pytest.mark.parametrize("table, cls", [
    ("contact", "ContactSpec"), ("track", "TrackSpec"), ("track.bolts", "RimBoltsSpec"), ("crawler", "CrawlerSpec"),
    ("fretting", "FrettingSpec"), ("conveyor", "Conveyor"), ("load", "Load"), ("guides", "Guide"),
    ("adjustable", "Adjustable"), ("wheels", "Wheel"),
])
def test_declarations_match_the_drive_objects(table, cls):
    # the objects a table becomes have the declared fields and defaults (no drift between them)
    import dataclasses

    from chaindrive.drive import model

    fields = {f.name: f for f in dataclasses.fields(getattr(model, cls))}
    decl = get_table(table)
    for f in decl.fields:
        assert f.name in fields, f"{table}.{f.name} is no field of {cls}"
        default = fields[f.name].default
        if f.required:
            assert default is dataclasses.MISSING, f"{table}.{f.name}"
        elif default is not dataclasses.MISSING:  # (a positional argument in code may be None in a file)
            assert default == f.default, f"{table}.{f.name}: {cls} default {default!r}, declared {f.default!r}"
    nested = {c.name.rsplit(".", 1)[1] for c in all_tables() if c.name.startswith(table + ".")}
    assert set(fields) - {f.name for f in decl.fields} <= nested
