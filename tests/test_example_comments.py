"""The comments of the examples and of the ``chaindrive new`` templates say what the reader
does (issue 30, item 5): a bare number where a unit is needed is refused, not read in SI."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from chaindrive.drive.project import TEMPLATES, parse_project, template
from chaindrive.errors import InputError

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
TEXTS = {**{p.name: p.read_text(encoding="utf-8") for p in sorted(EXAMPLES.glob("*.toml"))},
         **{f"template {k}": template(k) for k in TEMPLATES}}


@pytest.mark.parametrize("name", sorted(TEXTS))
def test_no_comment_says_a_bare_number_is_read(name):
    comments = " ".join(line.split("#", 1)[1] for line in TEXTS[name].splitlines() if "#" in line)
    comments = re.sub(r"\s+", " ", comments)
    assert "bare number is read" not in comments and "read in SI" not in comments
    if "bare number" in comments:
        assert "bare number is refused" in comments


def test_what_the_comments_say_is_what_the_reader_does():
    text = template("roller")
    bare = text.replace('speed = "960 rpm"', "speed = 100.5")
    with pytest.raises(InputError, match="speed"):
        parse_project(bare)
    assert parse_project(text).load.service_factor == 1.0  # a ratio stays a bare number
