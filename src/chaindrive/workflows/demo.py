"""The built-in demo job (``make demo``)."""

from __future__ import annotations

import json
from pathlib import Path

from .._results import jsonable


def run_demo(output: Path) -> dict:
    """Run the demo and write its files into ``output``; returns the summary."""
    output = Path(output)
    output.mkdir(parents=True, exist_ok=True)
    from ..geometry import link_chain_central_angles, link_chain_pitch_radius

    summary = {
        "case": "seed 002: chain 18x64, z = 8, omega = 5 rad/s, l = 0.256 m",
        "pitch_radius_m": link_chain_pitch_radius(0.064, 0.018, 8),
        "central_angles_rad": link_chain_central_angles(0.064, 0.018, 8),
    }
    (output / "demo.json").write_text(json.dumps(jsonable(summary), indent=2))
    print(f"chaindrive demo: results written to {output.resolve()}/")
    return summary
