"""Write the table of every project-file input into docs/drive.md (from the declarations).

Usage: ``python scripts/input_docs.py`` (tests/test_input_tables.py checks the table is current).
"""

from __future__ import annotations

import re
from pathlib import Path

DOC = Path(__file__).resolve().parents[1] / "docs" / "drive.md"
BLOCK = re.compile(r"(<!-- input-table: begin[^\n]*-->\n)(.*?)(<!-- input-table: end -->)", re.S)


def current(text: str) -> str:
    """The generated block of ``text`` (docs/drive.md)."""
    m = BLOCK.search(text)
    if m is None:
        raise SystemExit("docs/drive.md has no input-table block")
    return m.group(2)


def main() -> None:
    from chaindrive.drive.schema import docs_table, load_providers

    load_providers()
    text = DOC.read_text(encoding="utf-8")
    DOC.write_text(BLOCK.sub(lambda m: m.group(1) + docs_table() + m.group(3), text), encoding="utf-8")


if __name__ == "__main__":
    main()
