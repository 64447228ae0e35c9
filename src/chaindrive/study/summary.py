"""Summary of a study folder: statistics, figures and a short HTML page.

``chaindrive study --summary DIR`` reads every Parquet part of the folder
(:func:`chaindrive.study.run.read_results`) and writes ``DIR/summary/``: one PNG per
numeric output (histogram and empirical CDF), a scatter matrix of the inputs and
outputs, the feasible region of two inputs (e.g. tensioner mass × stiffness that are
resonance-free over a speed range) and ``index.html`` with the statistics, the errors of
the failed variants and the figures.
"""

from __future__ import annotations

import base64
import io
import json
import re
from collections import Counter
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from .._io import atomic_write_bytes, atomic_write_text
from ..errors import InputError
from .outputs import output_display, output_unit

__all__ = ["summarize", "StudySummary", "output_unit", "output_display", "column_statistics"]


_TEMPLATE = """<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>{{ name }}: study summary</title>
<style>
body { font-family: system-ui, sans-serif; max-width: 1100px; margin: 2em auto; color: #222; }
table { border-collapse: collapse; margin: 1em 0; font-size: 0.9em; }
th, td { border: 1px solid #ccc; padding: 0.25em 0.6em; text-align: right; }
th:first-child, td:first-child { text-align: left; }
img { max-width: 100%; border: 1px solid #eee; margin: 0.5em 0; }
.small { color: #666; font-size: 0.85em; }
</style></head><body>
<h1>{{ name }}</h1>
<p>{{ description }}</p>
<p>Plan: <b>{{ plan }}</b>{% if seed is not none %}, seed {{ seed }}{% endif %};
{{ rows }} variants in the folder ({{ planned }} planned), {{ failed }} failed.
Base project: <code>{{ base }}</code>.</p>
<h2>Inputs</h2>
<table><tr><th>path</th><th>unit</th><th>varied as</th><th>min</th><th>max</th></tr>
{% for v in inputs %}<tr><td><code>{{ v.path }}</code></td><td>{{ v.unit or "-" }}</td>
<td>{{ v.how }}</td><td>{{ v.min }}</td><td>{{ v.max }}</td></tr>{% endfor %}
</table>
<h2>Outputs</h2>
<table><tr><th>output</th><th>unit</th><th>n</th><th>mean</th><th>std</th><th>min</th>
<th>5 %</th><th>50 %</th><th>95 %</th><th>max</th></tr>
{% for s in stats %}<tr><td><code>{{ s.name }}</code></td><td>{{ s.unit }}</td><td>{{ s.n }}</td>
{% if s.kind == "number" %}<td>{{ s.mean }}</td><td>{{ s.std }}</td><td>{{ s.min }}</td>
<td>{{ s.p05 }}</td><td>{{ s.p50 }}</td><td>{{ s.p95 }}</td><td>{{ s.max }}</td>
{% elif s.kind == "yes/no" %}<td colspan="7">true in {{ s.true }} of {{ s.n }} ({{ s.fraction }})</td>
{% else %}<td colspan="7">{{ s.distinct }} distinct values</td>{% endif %}</tr>{% endfor %}
</table>
{% if warned %}<h2>Warnings</h2>
<table><tr><th>warning (numbers of the first variant that gave it)</th><th>variants</th></tr>
{% for w, n in warned %}<tr><td>{{ w }}</td><td>{{ n }}</td></tr>{% endfor %}</table>{% endif %}
{% if errors %}<h2>Failed variants</h2>
<table><tr><th>error</th><th>variants</th></tr>
{% for e, n in errors %}<tr><td>{{ e }}</td><td>{{ n }}</td></tr>{% endfor %}</table>{% endif %}
<h2>Figures</h2>
{% for f in figures %}<figure><img src="{{ f.src }}" alt="{{ f.caption }}">
<figcaption class="small">{{ f.caption }}</figcaption></figure>{% endfor %}
<p class="small">Results: <code>results/part-*.parquet</code> (one row per variant, outputs in
SI units, inputs in the units of the study file). Written by chaindrive.</p>
</body></html>
"""


@dataclass
class StudySummary:
    """What :func:`summarize` wrote.

    Attributes
    ----------
    html : pathlib.Path
    figures : list of pathlib.Path
    statistics : list of dict
    rows, failed : int
    """

    html: Path
    figures: list = field(default_factory=list)
    statistics: list = field(default_factory=list)
    rows: int = 0
    failed: int = 0


def _fmt(x: float) -> str:
    return f"{x:.4g}"


def column_statistics(name: str, values: list) -> dict[str, Any]:
    """Count, mean, standard deviation, extremes and 5/50/95 % quantiles of a column, in the
    display unit of the output (:func:`output_display`).

    Examples
    --------
    >>> s = column_statistics("loads.maximum", [1000.0, 2000.0, 3000.0, None])  # N, shown in kN
    >>> s["n"], s["mean"], s["p50"], s["unit"]
    (3, '2', '2', 'kN')
    >>> column_statistics("passed", [True, False, True])["fraction"]
    '67 %'
    """
    present = [v for v in values if v is not None]
    factor, unit = output_display(name)
    if present and all(isinstance(v, bool) for v in present):
        t = sum(present)
        return {"name": name, "unit": "-", "kind": "yes/no", "n": len(present), "true": t,
                "fraction": f"{t / len(present):.0%}".replace("%", " %")}
    if present and all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in present):
        x = np.asarray(present, dtype=float) * factor
        q = np.quantile(x, [0.05, 0.5, 0.95])
        return {"name": name, "unit": unit or "-", "kind": "number", "n": int(x.size),
                "mean": _fmt(x.mean()), "std": _fmt(x.std(ddof=1)) if x.size > 1 else "-",
                "min": _fmt(x.min()), "p05": _fmt(q[0]), "p50": _fmt(q[1]), "p95": _fmt(q[2]),
                "max": _fmt(x.max())}
    return {"name": name, "unit": unit or "-", "kind": "other", "n": len(present),
            "distinct": len({json.dumps(v, default=str) for v in present})}


def _png(fig) -> bytes:
    import matplotlib.pyplot as plt

    buf = io.BytesIO()
    if fig.get_layout_engine() is None:
        fig.set_layout_engine("constrained")
    fig.savefig(buf, format="png", dpi=100)
    plt.close(fig)
    return buf.getvalue()


def _warning_counts(column: list, limit: int = 10) -> list[tuple[str, int]]:
    """Warnings grouped with their numbers masked: ``[(first message, variants), ...]``.

    Examples
    --------
    >>> _warning_counts(["ratio 0.2 > 0.1 | x", "ratio 0.3 > 0.1", None])
    [('ratio 0.2 > 0.1', 2), ('x', 1)]
    """
    first: dict[str, str] = {}
    count: Counter = Counter()
    for cell in column:
        for message in dict.fromkeys((cell or "").split(" | ")):
            if not message:
                continue
            shape = re.sub(r"[-+]?\d+(\.\d+)?([eE][-+]?\d+)?", "#", message)
            first.setdefault(shape, message)
            count[shape] += 1
    return [(first[s], n) for s, n in count.most_common(limit)]


def _slug(name: str) -> str:
    return re.sub(r"[^A-Za-z0-9]+", "_", name).strip("_")[:60] or "output"


def summarize(directory: str | Path, *, max_figures: int = 12) -> StudySummary:
    """Write ``DIR/summary/index.html`` and its figures for a study folder.

    Parameters
    ----------
    directory : path
        Folder of ``chaindrive study ... -o DIR``.
    max_figures : int
        Most distribution figures drawn (one per numeric output).

    Returns
    -------
    StudySummary

    Raises
    ------
    InputError
        Not a study folder, or no results in it.
    """
    import matplotlib

    if matplotlib.get_backend().lower() not in ("agg", "pdf", "svg", "cairo"):
        matplotlib.use("Agg")
    from jinja2 import Environment

    from ..plotting.study import distribution_plot, feasible_region_plot, scatter_matrix_plot
    from .run import read_results

    folder = Path(directory)
    try:
        described = json.loads((folder / "study.json").read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise InputError(f"--summary: {str(folder)!r} is not a study folder (no study.json); "
                         "give the folder of `chaindrive study STUDY.toml -o DIR`") from None
    except (OSError, ValueError) as exc:
        raise InputError(f"--summary: cannot read {str(folder / 'study.json')!r} ({exc})") from None
    table = read_results(folder)
    data = {name: table.column(name).to_pylist() for name in table.column_names}
    variables = described.get("variables", [])
    inputs = [v["path"] for v in variables if v["path"] in data]
    units = {v["path"]: v.get("unit", "") for v in variables}
    outputs = [o for o in described.get("outputs", []) if o in data]
    errors = [e for e in data.get("error", []) if e]
    warned = _warning_counts(data.get("warnings", []))
    out = folder / "summary"
    try:
        out.mkdir(exist_ok=True)
    except OSError as exc:
        raise InputError(f"--summary: cannot create {str(out)!r} ({exc.strerror or exc})") from None

    stats = [column_statistics(o, data[o]) for o in outputs]
    numeric_out = [s["name"] for s in stats if s["kind"] == "number"]
    numeric_in = [p for p in inputs
                  if all(v is None or (isinstance(v, (int, float)) and not isinstance(v, bool))
                         for v in data[p])]
    yesno = [s["name"] for s in stats if s["kind"] == "yes/no"]
    feasible = described.get("feasible") or ("passed" if "passed" in yesno else
                                             (yesno[0] if yesno else None))
    figures: list[tuple[Path, str]] = []

    def save(fig, filename: str, caption: str) -> None:
        path = atomic_write_bytes(out / filename, _png(fig), force=True, option="--summary")
        figures.append((path, caption))

    for name in numeric_out[:max_figures]:
        present = np.asarray([v for v in data[name] if v is not None], dtype=float)
        if not present.size or np.ptp(present) <= 1e-12 * np.max(np.abs(present)):
            continue  # a constant output: its statistics say all
        fig = distribution_plot([np.nan if v is None else v for v in data[name]], name=name,
                                unit=output_unit(name))
        save(fig, f"distribution_{_slug(name)}.png",
             f"{name}: histogram and empirical CDF over the variants that ran")
    columns = [c for c in numeric_in + numeric_out
               if np.ptp(np.asarray([v for v in data[c] if v is not None] or [0.0], dtype=float)) > 0]
    if len(columns) >= 2:
        cols: dict[str, Sequence[float]] = {c: [np.nan if v is None else float(v) for v in data[c]]
                                            for c in columns[:8]}
        colour = data.get(feasible) if feasible else None
        fig = scatter_matrix_plot(cols, units={**{c: output_unit(c) for c in numeric_out}, **units},
                                  passed=colour, passed_name=feasible or "passed",
                                  log=[v["path"] for v in variables if v.get("scale") == "log"])
        save(fig, "scatter_matrix.png",
             "Scatter matrix of the varied inputs and the outputs"
             + (f" (green: {feasible} true, red: false)" if colour else ""))
    axes = described.get("axes")
    mixed = feasible is not None and len({v for v in data[feasible] if v is not None}) == 2
    if axes is None and mixed and len(numeric_in) >= 2:
        axes = numeric_in[:2]  # the map is drawn unasked only when some pass and some fail
    if feasible and axes and all(a in data for a in axes):
        scale = {v["path"]: v.get("scale") for v in variables}
        fig = feasible_region_plot(
            [np.nan if v is None else v for v in data[axes[0]]],
            [np.nan if v is None else v for v in data[axes[1]]], data[feasible],
            xname=axes[0], yname=axes[1], xunit=units.get(axes[0], ""), yunit=units.get(axes[1], ""),
            feasible_name=feasible, over=", ".join(p for p in inputs if p not in axes) or "repeats",
            log_x=scale.get(axes[0]) == "log",
            log_y=scale.get(axes[1]) == "log")
        save(fig, "feasible_region.png",
             f"Feasible region ({feasible}) over {axes[0]} and {axes[1]}: fraction of the variants "
             "at each point (over the other inputs) that pass; outlined where all pass")

    def describe_input(v: dict) -> dict:
        vals = [x for x in data.get(v["path"], []) if isinstance(x, (int, float))]
        how = (f"{v['distribution']}({', '.join(f'{k}={p:g}' for k, p in v['parameters'].items())})"
               if v.get("distribution") else
               f"values {v['values']}" if v.get("values") is not None else
               f"{v['low']:g} ... {v['high']:g} ({v.get('scale', 'linear')}"
               + (f", {v['count']} levels)" if v.get("count") else ")"))
        return {"path": v["path"], "unit": v.get("unit", ""), "how": how,
                "min": _fmt(min(vals)) if vals else "-", "max": _fmt(max(vals)) if vals else "-"}

    html = Environment(autoescape=True).from_string(_TEMPLATE).render(
        name=described.get("name", "design study"), description=described.get("description", ""),
        plan=described.get("plan"), seed=described.get("seed") if described.get("plan") != "grid" else None,
        rows=table.num_rows, planned=described.get("variants"), failed=len(errors),
        base=described.get("base"), inputs=[describe_input(v) for v in variables], stats=stats,
        errors=Counter(errors).most_common(10), warned=warned,
        figures=[{"src": "data:image/png;base64," + base64.b64encode(p.read_bytes()).decode("ascii"),
                  "caption": c} for p, c in sorted(figures, key=lambda f: f[0].name != "feasible_region.png")])
    page = atomic_write_text(out / "index.html", html, force=True, option="--summary")
    return StudySummary(html=page, figures=[p for p, _ in figures], statistics=stats,
                        rows=table.num_rows, failed=len(errors))
