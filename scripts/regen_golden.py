"""Regenerate the golden results of the examples (tests/data/golden/) and print what changed,
path by path.

Usage::

    PYTHONPATH=src python scripts/regen_golden.py            # show the differences only
    PYTHONPATH=src python scripts/regen_golden.py --write    # and store the new results

Review every line before --write: a changed number is a behaviour change to explain in the
closing note (a correction), a new path may need a pattern in tests/_golden.ALLOWED_ADDED.
"""

from __future__ import annotations

import argparse
import json
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

from _golden import GOLDEN, NAMES, VOLATILE, differences, results_of  # noqa: E402


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--write", action="store_true", help="store the new results in tests/data/golden/")
    parser.add_argument("names", nargs="*", default=list(NAMES), help="examples (default: all)")
    args = parser.parse_args(argv)
    changed = 0
    for name in args.names:
        with tempfile.TemporaryDirectory() as folder:
            new = results_of(name, Path(folder))
        path = GOLDEN / f"{name}.json"
        old = json.loads(path.read_text(encoding="utf-8")) if path.exists() else {}
        diff = differences(old, new)
        changed += bool(diff)
        print(f"{name}: {len(diff)} difference(s)" if diff else f"{name}: unchanged")
        for line in diff:
            print("  " + line)
        if args.write and diff:
            GOLDEN.mkdir(parents=True, exist_ok=True)
            stored = {k: v for k, v in new.items() if k not in VOLATILE}
            path.write_text(json.dumps(stored, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")
            print(f"  wrote {path}")
    return 1 if changed and not args.write else 0


if __name__ == "__main__":
    raise SystemExit(main())
