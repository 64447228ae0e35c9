"""``chaindrive analyze`` and ``chaindrive report``: every analysis of a project file."""

from __future__ import annotations

from pathlib import Path

import typer

from .._io import note_earlier_run
from .app import app


def _run(project: Path, output: Path, pdf: bool, figures: bool, quiet: bool, force: bool = False,
         png: bool = False) -> int:

    from .._io import claim_output_dir

    # before any work: the folder locked (a second run into it is refused), an earlier run
    # needs --force, a folder with other files is refused
    with claim_output_dir(output, force=force, inputs=(project,)):
        return _run_claimed(project, output, pdf, figures, quiet, force, png)


def _run_claimed(project: Path, output: Path, pdf: bool, figures: bool, quiet: bool, force: bool,
                 png: bool = False) -> int:
    from rich.console import Console
    from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn

    from .._io import atomic_output_dir
    from ..drive.project import load_project
    from ..workflows.analyze import analyze

    console = Console(stderr=True, quiet=quiet)
    drive = load_project(project)
    try:
        source: str | None = project.read_text(encoding="utf-8")
    except (OSError, UnicodeError):
        source = None
    with Progress(TextColumn("[bold]{task.description}"), BarColumn(), TextColumn("{task.completed}/{task.total}"),
                  TimeElapsedColumn(), console=console, transient=True, disable=quiet) as prog:
        task = prog.add_task("analysing", total=None)

        def progress(title: str, i: int, n: int) -> None:
            prog.update(task, description=title, completed=i, total=n)

        with atomic_output_dir(output, force=force, inputs=(project,)) as partial:  # moved into place when complete
            outcome = analyze(drive, partial, subtitle=f"Project file: {project}", pdf=pdf, figures=figures,
                              progress=progress, parallel_figures=True, source=source, browser_charts=not png)
        outcome.files = {k: output / Path(v).relative_to(partial) for k, v in outcome.files.items()}
    from ..display import check_limit_text, check_margin_text, check_value_text, verdict_text

    out = Console(quiet=quiet, highlight=False)
    for title, c in outcome.report.checks:
        if c.relation == "info":
            continue
        mark = {"pass": "[green]pass[/green]", "FAIL": "[bold red]FAIL[/bold red]"}.get(c.verdict, c.verdict)
        margin = check_margin_text(c)
        out.print(f"  {mark}  {title}: {c.name} = {check_value_text(c)} (limit {check_limit_text(c)}"
                  + (f", margin {margin})" if margin else ")"), markup=True)
    warns = outcome.report.warnings
    words = verdict_text(len(outcome.analysis.failed), len(warns))
    verdict = f"[green]{words}[/green]" if outcome.passed else f"[bold red]{words}[/bold red]"
    out.print(f"{drive.name}: {verdict}" + (":" if warns else ""))
    for w in warns:
        out.print(f"  warning: {w}", markup=False)
    out.print(f"report: {outcome.files['html']}")
    out.print(f"results: {outcome.files['json']}")
    if "proposal" in outcome.files:
        out.print(f"proposal (a design that passes the span-vibration check): {outcome.files['proposal']}")
    if "pdf" in outcome.files:
        out.print(f"pdf: {outcome.files['pdf']}")
    return outcome.exit_code


@app.command("analyze")
@note_earlier_run("output")  # an error says the files already in OUTPUT are from an earlier run
def analyze_cmd(
    project: Path = typer.Argument(..., help="TOML project file (see `chaindrive new`)."),
    output: Path = typer.Option(Path("out"), "--output", "-o", help="Folder for report.html, results.json (SI units) and the PNG plots."),
    pdf: bool = typer.Option(False, "--pdf", help="Also write report.pdf (WeasyPrint)."),
    figures: bool = typer.Option(True, "--figures/--no-figures", help="Draw the plots."),
    quiet: bool = typer.Option(False, "--quiet", "-q", help="Print nothing; use the exit code."),
    force: bool = typer.Option(False, "--force", help="Replace an earlier run in the output folder (without it an earlier run is refused before any work; a folder with other files is never replaced)."),
    png: bool = typer.Option(False, "--png", help="Every figure as a PNG file (matplotlib), embedded in report.html; without it the report's charts are drawn by the browser from their data (plotly.min.js written beside report.html, offline). --pdf implies it."),
) -> None:
    """Run every applicable analysis of a drive and write a calculation report.

    Layout (ISO 10823 / exact polygon), loads and static safety (catalogue breaking
    force), power rating (ANSI/ACA; ISO 10823 for B-series chains), entry kinematics (Dolipiński et al.), span and tensioner vibration
    with the resonance check (the tensioner paper), wheel geometry (ISO 606, Dolipiński et al., Sharipov),
    contact with skew (Garshniev & Maksymovych), track wheel teeth (Sharipov), wear life.
    Exit code 0 when every check passes, 1 when a check fails, 2 on bad input.
    The results are built in a temporary folder and moved into OUTPUT when complete;
    an earlier run there is replaced only with --force, and a failed run leaves it
    unchanged (the error says so).
    """
    raise typer.Exit(_run(project, output, pdf, figures, quiet, force, png))


@app.command("report")
@note_earlier_run("output")
def report_cmd(
    project: Path = typer.Argument(..., help="TOML project file."),
    output: Path = typer.Option(Path("out"), "--output", "-o", help="Folder for the report."),
    pdf: bool = typer.Option(True, "--pdf/--no-pdf", help="Write report.pdf (default) besides report.html."),
    force: bool = typer.Option(False, "--force", help="Replace an earlier run in the output folder."),
) -> None:
    """Write the calculation report of a drive (HTML and PDF); same as `analyze --pdf`."""
    raise typer.Exit(_run(project, output, pdf, True, False, force))
