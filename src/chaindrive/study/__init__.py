"""Design studies: many variants of a drive analysed on a dask cluster.

``chaindrive study study.toml -o DIR`` reads a study file (:mod:`.spec`), makes the
variants of its plan (:mod:`.plan`: full grid, Latin hypercube, Monte Carlo with named
scipy.stats distributions), analyses them on ``dask.distributed`` (:mod:`.run`),
appends the rows to Parquet as they arrive, and ``chaindrive study --summary DIR``
draws the distributions and feasible regions (:mod:`.summary`). See docs/studies.md.
"""

from .plan import MAXIMUM_VARIANTS, Variable, full_grid, latin_hypercube, monte_carlo, plan_rows
from .spec import Study, load_study, parse_study

__all__ = ["MAXIMUM_VARIANTS", "Variable", "full_grid", "latin_hypercube", "monte_carlo",
           "plan_rows", "Study", "load_study", "parse_study", "run_study", "read_results", "read_dataframe",
           "summarize"]


def __getattr__(name: str):
    # the runner and the summary import dask / pyarrow / matplotlib only when used
    if name in ("run_study", "read_results", "read_dataframe"):
        from . import run

        return getattr(run, name)
    if name == "summarize":
        from .summary import summarize

        return summarize
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
