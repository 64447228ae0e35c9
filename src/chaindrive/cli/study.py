"""``chaindrive study``: design studies on dask (many variants of a drive) and their summary."""

from __future__ import annotations

from pathlib import Path

import typer

from .app import app


@app.command("study")
def study_cmd(
    study_file: Path = typer.Argument(None, metavar="STUDY",
                                      help="TOML study file: base project, [[vary]] inputs (dotted "
                                           "paths with units), [plan], outputs (see docs/studies.md)."),
    output: Path = typer.Option(None, "--output", "-o",
                                help="Study folder: study.json and results/part-*.parquet (appended; "
                                     "variants already there are skipped)."),
    summary: Path = typer.Option(None, "--summary",
                                 help="Summarise the study folder DIR instead: DIR/summary/index.html "
                                      "with distributions, scatter matrix, feasible region."),
    scheduler: str = typer.Option(None, "--scheduler",
                                  help="Address tcp://HOST:PORT of a running `dask scheduler`; default a "
                                       "local cluster with one worker process per core."),
    workers: int = typer.Option(None, "--workers", min=1, max=256,
                                help="Worker processes of the local cluster [-] (default: cores)."),
    batch_size: int = typer.Option(None, "--batch-size", min=1, max=20_000,
                                   help="Variants per dask task [-] (at most 20,000; default about 8 "
                                        "tasks per worker, at most 5,000 variants each)."),
    force: bool = typer.Option(False, "--force",
                               help="Start over in a study folder that holds the results of another "
                                    "plan (a changed study file or base project): its results are "
                                    "deleted. Without it such a folder is refused."),
    quiet: bool = typer.Option(False, "--quiet", "-q",
                               help="No progress bar, no summary line (a study of 10,000 variants or "
                                    "more still prints a progress line a minute)."),
) -> None:
    """Run a design study on dask.distributed, or summarise one (--summary DIR).

    Each variant is the base project file with the study's inputs set, analysed like
    `chaindrive analyze` (the papers and standards cited there); the outputs are dotted
    paths into the analysis results (SI units). Results are appended to Parquet as the
    batches finish; a rerun skips the variants already in the folder; a failing variant
    records its error in its row. A study folder belongs to one plan: a changed study
    file or base project is refused there (a new folder, or --force). Exit code 0 when the study ran (failed variants are
    results), 2 on bad input.
    """
    import sys

    if not quiet:  # a first line at once: the study file and the cluster take seconds
        what = f"summarising {summary}" if summary is not None else f"reading {study_file}"
        sys.stderr.write(f"study: {what}\n")
        sys.stderr.flush()
    from rich.console import Console

    out = Console(quiet=quiet, highlight=False)
    if summary is not None:
        if study_file is not None or output is not None:
            raise typer.BadParameter("give either STUDY with --output, or --summary DIR alone")
        from ..study.summary import summarize

        result = summarize(summary)
        out.print(f"{result.rows} variants ({result.failed} failed); "
                  f"{len(result.figures)} figures")
        out.print(f"summary: {result.html}")
        return
    if study_file is None:
        raise typer.BadParameter("give a study file (or --summary DIR)", param_hint="STUDY")
    if output is None:
        raise typer.BadParameter("give the study folder for the results", param_hint="--output")
    from ..study.run import run_study
    from ..study.spec import load_study

    study = load_study(study_file)
    run = run_study(study, output, scheduler=scheduler, workers=workers, batch_size=batch_size,
                    progress=not quiet, force=force)
    out.print(f"{study.name}: {run.computed} variants computed ({run.failed} failed), "
              f"{run.skipped} already in {output}"
              + (f"; {run.rate:.1f} variants/s on {run.workers} worker{'s' if run.workers != 1 else ''}"
                 if run.computed else ""))
    out.print(f"results: {Path(output) / 'results'} (Parquet); summary: chaindrive study --summary {output}")
