"""Where the example project files are (internal).

The files of ``examples/`` in the source tree are shipped inside the wheel as
``chaindrive/examples/``; :func:`examples_directory` finds them in either place, so the
demo and the studio use the same files an installed user can open.
"""

from __future__ import annotations

from pathlib import Path

__all__ = ["examples_directory", "example_path"]


def examples_directory() -> Path:
    """The folder holding the example project files (``mining_conveyor.toml``, ...).

    Examples
    --------
    >>> (examples_directory() / "mining_conveyor.toml").is_file()
    True
    """
    packaged = Path(__file__).resolve().parent / "examples"
    if packaged.is_dir():
        return packaged
    return Path(__file__).resolve().parents[2] / "examples"  # a source checkout


def example_path(name: str) -> Path:
    """The example file ``name`` (``"mining_conveyor.toml"``)."""
    return examples_directory() / name
