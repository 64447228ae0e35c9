"""The built-in demo job (``make demo``).

1. Dolipiński et al.'s worked case: chain 18x64 on an 8-pocket wheel, ω = 5 rad/s, guide end
   l = 0.256 m: velocity and acceleration of free, chordal and tangential entry under
   both models (exact and the paper's corrected closed forms), as a plot and JSON.
2. When the analysis pipeline is available: ``chaindrive analyze`` of the mining
   conveyor example (``examples/mining_conveyor.toml``), with its report.
"""

from __future__ import annotations

import json
from pathlib import Path

from .._results import jsonable


def run_demo(output: Path, *, analysis: bool = True, shown: Path | None = None) -> dict:
    """Run the demo and write its files into ``output``; returns the summary.

    ``shown`` is the folder named in the messages (the final folder when ``output`` is
    the temporary one it is moved to).
    """
    shown = Path(output) if shown is None else Path(shown)
    output = Path(output)
    output.mkdir(parents=True, exist_ok=True)
    from ..kinematics import dolipinski_worked_case
    from ..plotting.kinematics import kinematics_plot

    summary: dict = {"case": "Dolipiński et al.: chain 18x64, z = 8, omega = 5 rad/s, l = 0.256 m"}
    files = []
    for model in ("exact", "paper"):
        cases = dolipinski_worked_case(model=model)
        summary[model] = {entry: res.summary for entry, res in cases.items()}
        fig = kinematics_plot(cases)
        png = output / f"kinematics_dolipinski_{model}.png"
        fig.savefig(png, dpi=120, bbox_inches="tight")
        import matplotlib.pyplot as plt

        plt.close(fig)
        files.append(png)
        data = {entry: res.to_dict() for entry, res in cases.items()}
        js = output / f"kinematics_dolipinski_{model}.json"
        js.write_text(json.dumps(jsonable(data), indent=1))
        files.append(js)
    (output / "summary.json").write_text(json.dumps(jsonable(summary), indent=2))
    files.append(output / "summary.json")
    print("chaindrive demo: Dolipiński et al. chain entry kinematics (18x64, z = 8, ω = 5 rad/s, l = 0.256 m)")
    for model in ("exact", "paper"):
        for entry, s in summary[model].items():
            print(
                f"  {model:5s} {entry:10s} v = {s['v_min']:.4f}..{s['v_max']:.4f} m/s, "
                f"non-uniformity {100 * s['nonuniformity']:.3g} %, a = {s['a_min']:+.3f}..{s['a_max']:+.3f} m/s²"
            )
    if analysis:
        _maybe_analysis(output, files, shown)
    record = " (report.html is the calculation record)" if any(f.name == "report.html" for f in files) else ""
    print(f"chaindrive demo: results written to {shown.resolve()}/{record}")
    for f in files:
        print(f"  {f.name}")
    return summary


def _maybe_analysis(output: Path, files: list, shown: Path) -> None:
    from .._examples import example_path

    example = example_path("mining_conveyor.toml")
    try:
        from ..drive.project import load_project
        from .analyze import analyze
    except ImportError as exc:  # an install without the project extra: say so, do not hide it
        print(f"chaindrive demo: analysis of {example.name} skipped ({exc.name} is not installed; "
              "pip install 'chaindrive[all]')")
        return
    if not example.exists():
        print(f"chaindrive demo: analysis skipped ({example} not found)")
        return
    drive = load_project(example)
    outcome = analyze(drive, output, subtitle=f"Project file: {example.name}")
    from ..display import verdict_text

    words = verdict_text(len(outcome.analysis.failed), len(outcome.report.warnings))
    verdict = (words if outcome.passed else
               f"{words}, as intended: the report says which and why "
               f"(`chaindrive analyze {example.name}` exits 1 for it; the demo itself exits 0)")
    print(f"chaindrive demo: analysis of {example.name}: {verdict}; report: {shown / 'report.html'}")
    files.extend(outcome.files.values())
