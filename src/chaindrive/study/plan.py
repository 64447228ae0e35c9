r"""Sampling plans of a design study: full grid, Latin hypercube, Monte Carlo.

A plan turns the study's varied inputs (:class:`Variable`) into rows of values, one row
per variant. Every plan works in two steps:

1. points ``u`` in the unit hypercube :math:`[0, 1)^d`: the grid's level indices, a
   Latin hypercube (:func:`latin_hypercube`, McKay, Beckman & Conover 1979) or
   independent uniform numbers (:func:`monte_carlo`), all from one seeded
   :class:`numpy.random.Generator`;
2. each column mapped to its variable (:func:`transform`): ``low + u (high - low)``
   (or the logarithmic form), or the inverse CDF of a named :mod:`scipy.stats`
   distribution, :math:`x = F^{-1}(u)`.

Step 2 with independent uniform ``u`` is inverse-transform sampling (Devroye 1986,
§II.2.1, theorem 2.1): :math:`F^{-1}(U)` has the distribution ``F`` for
:math:`U \sim \mathcal U(0, 1)`. With Latin-hypercube ``u`` each of the ``n`` equal
probability strata of every variable receives exactly one sample.

References
----------
M. D. McKay, R. J. Beckman, W. J. Conover, A comparison of three methods for selecting
values of input variables in the analysis of output from a computer code,
*Technometrics* 21 (1979) 239–245.
L. Devroye, *Non-Uniform Random Variate Generation*, Springer, 1986, §II.2.1.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from .._registry import Registry
from ..errors import InputError, UnknownNameError

if TYPE_CHECKING:
    from scipy.stats._distn_infrastructure import rv_frozen

__all__ = ["Variable", "PLANS", "MAXIMUM_VARIANTS", "full_grid", "latin_hypercube",
           "monte_carlo", "transform", "frozen_distribution", "plan_rows", "format_value"]

#: Largest number of variants one study may have (a bigger design space is split into
#: several studies, each with its own output folder).
MAXIMUM_VARIANTS = 2_000_000

#: Plan kinds, by name.
PLANS = Registry("plan")

# keeps the inverse CDF of unbounded distributions finite (u = 0 has probability
# 2**-53 per draw for a Generator's random())
_U_EDGE = 1e-15


@dataclass(frozen=True)
class Variable:
    """One varied input of a study.

    Parameters
    ----------
    path : str
        Dotted path into the base project file, e.g. ``"contact.skew"``,
        ``"tensioner.mass"``, ``"wheels.1.teeth"`` (list entries by 0-based index).
    unit : str
        Unit the values are written in, as a project file writes it (``"arcmin"``,
        ``"kg"``, ``"kN/m"``, ``"rpm"``); ``""`` for a bare number.
    values : tuple, optional
        Explicit grid levels (numbers, or strings such as ``"16B"`` or ``"50 arcmin"``).
    low, high : float, optional
        Range in ``unit``: grid levels (with ``count``) or uniform sampling.
    count : int, optional
        Grid levels from ``low`` to ``high``.
    scale : {"linear", "log"}
        Spacing of grid levels and of uniform samples between ``low`` and ``high``.
    distribution : str, optional
        Name of a :mod:`scipy.stats` distribution for Latin-hypercube and Monte Carlo
        plans (``"norm"``, ``"uniform"``, ``"lognorm"``, ``"truncnorm"``, ``"triang"``,
        ...), with its arguments in ``parameters`` (in ``unit``).
    parameters : mapping
        Keyword arguments of the distribution (``loc``, ``scale`` and its shapes).
    integer : bool
        Round sampled values to whole numbers (teeth, links).
    """

    path: str
    unit: str = ""
    values: tuple | None = None
    low: float | None = None
    high: float | None = None
    count: int | None = None
    scale: str = "linear"
    distribution: str | None = None
    parameters: Mapping[str, float] = field(default_factory=dict)
    integer: bool = False

    def __post_init__(self) -> None:
        where = f"variable {self.path!r}"
        if self.scale not in ("linear", "log"):
            raise InputError(f"{where}: scale must be 'linear' or 'log', got {self.scale!r}")
        given = [self.values is not None, self.low is not None or self.high is not None,
                 self.distribution is not None]
        if sum(given) != 1:
            raise InputError(f"{where}: give exactly one of values, (low, high) or distribution")
        if self.values is not None and len(self.values) == 0:
            raise InputError(f"{where}: values must hold at least 1 value, got none")
        if given[1]:
            if self.low is None or self.high is None:
                raise InputError(f"{where}: give both low and high")
            if not (math.isfinite(self.low) and math.isfinite(self.high) and self.low <= self.high):
                raise InputError(f"{where}: need finite low <= high, got low = {self.low:g}, "
                                 f"high = {self.high:g}")
            if self.scale == "log" and not self.low > 0:
                raise InputError(f"{where}: scale = 'log' needs 0 < low <= high, got low = {self.low:g}")
        if self.count is not None and not (given[1] and 1 <= self.count <= MAXIMUM_VARIANTS):
            raise InputError(f"{where}: count needs low and high and must lie in "
                             f"[1, {MAXIMUM_VARIANTS}], got {self.count}")
        if self.distribution is not None:
            frozen_distribution(self.distribution, self.parameters, where=where)

    def levels(self) -> list:
        """Grid levels of this variable (``values``, or ``count`` points from low to high)."""
        if self.values is not None:
            return list(self.values)
        if self.count is None:
            raise InputError(f"variable {self.path!r}: a grid needs values, or low, high and count")
        u = np.linspace(0.0, 1.0, self.count) if self.count > 1 else np.array([0.0])
        return [_round(float(x), self.integer) for x in self._from_unit(u)]

    def _from_unit(self, u: np.ndarray) -> np.ndarray:
        if self.distribution is not None:
            dist = frozen_distribution(self.distribution, self.parameters,
                                       where=f"variable {self.path!r}")
            with np.errstate(over="ignore"):  # an overflow is refused as non-finite below
                return np.asarray(dist.ppf(np.clip(u, _U_EDGE, 1.0 - _U_EDGE)), dtype=float)
        if self.low is None or self.high is None:
            raise InputError(f"variable {self.path!r}: Latin-hypercube and Monte Carlo plans "
                             "need (low, high) or a distribution, not a list of values")
        if self.scale == "log":
            x = np.exp(math.log(self.low) + u * (math.log(self.high) - math.log(self.low)))
        else:
            x = self.low + u * (self.high - self.low)
        # the ends exactly (exp(log(x)) is not x)
        return np.where(u == 0.0, self.low, np.where(u == 1.0, self.high, x))


def _round(x: float, integer: bool) -> float | int:
    # 12 significant digits: the value a variant's project receives (format_value)
    return int(round(x)) if integer else float(f"{x:.12g}")


def frozen_distribution(name: str, parameters: Mapping[str, float], *, where: str = "distribution") -> rv_frozen:
    """A frozen :mod:`scipy.stats` distribution from its name and keyword arguments.

    Raises
    ------
    UnknownNameError
        ``name`` is not a scipy.stats distribution.
    InputError
        Arguments the distribution does not take, or outside its domain.

    Examples
    --------
    >>> d = frozen_distribution("norm", {"loc": 50.0, "scale": 10.0})
    >>> round(float(d.ppf(0.975)), 3)
    69.6
    """
    import scipy.stats as st

    dist = getattr(st, str(name), None)
    if not isinstance(dist, (st.rv_continuous, st.rv_discrete)):
        common = "norm, uniform, lognorm, truncnorm, triang, beta, gamma, weibull_min, loguniform, randint"
        raise UnknownNameError(f"{where}: unknown distribution {name!r}; use the name of a "
                               f"scipy.stats distribution, e.g. {common}")
    shapes = [s.strip() for s in (dist.shapes or "").split(",") if s.strip()]
    args = ", ".join(shapes + ["loc", "scale"] if isinstance(dist, st.rv_continuous) else shapes + ["loc"])
    try:
        params = {str(k): float(v) for k, v in dict(parameters).items()}
        frozen = dist(**params)
        probe = frozen.ppf(np.array([0.25, 0.5, 0.75]))
    except (TypeError, ValueError) as exc:
        raise InputError(f"{where}: distribution {name!r} takes the parameters ({args}); "
                         f"got {dict(parameters)} ({exc})") from None
    if not np.all(np.isfinite(probe)):
        raise InputError(f"{where}: parameters {dict(parameters)} lie outside the domain of "
                         f"{name!r} (its parameters: {args})")
    return frozen


def full_grid(levels: Sequence[Sequence[Any]]) -> list[tuple]:
    """Every combination of the levels (full factorial design), last variable fastest.

    Parameters
    ----------
    levels : sequence of sequences
        Levels of each variable.

    Returns
    -------
    list of tuple
        ``prod(len(l) for l in levels)`` rows.

    Examples
    --------
    >>> full_grid([[1, 2], ["a", "b", "c"]])[:4]
    [(1, 'a'), (1, 'b'), (1, 'c'), (2, 'a')]
    """
    size = math.prod(len(x) for x in levels)
    if size > MAXIMUM_VARIANTS:
        raise InputError(f"plan: the full grid has {size} variants; at most {MAXIMUM_VARIANTS} "
                         "per study (fewer levels, or a Latin hypercube)")
    return list(itertools.product(*levels))


def _check_samples(samples: int) -> int:
    if isinstance(samples, bool) or int(samples) != samples or not 1 <= samples <= MAXIMUM_VARIANTS:
        raise InputError(f"plan.samples must be a whole number in [1, {MAXIMUM_VARIANTS}], got {samples!r}")
    return int(samples)


def latin_hypercube(samples: int, dimensions: int, seed: int) -> np.ndarray:
    """Latin hypercube in :math:`[0, 1)^d`: each of ``samples`` strata hit once per axis.

    Parameters
    ----------
    samples : int
        Number of points ``n``.
    dimensions : int
        Number of variables ``d``.
    seed : int
        Seed of the random generator (same seed, same points).

    Returns
    -------
    ndarray, shape (n, d)

    References
    ----------
    McKay, Beckman & Conover 1979; scipy.stats.qmc.LatinHypercube.

    Examples
    --------
    >>> u = latin_hypercube(4, 2, seed=1)
    >>> sorted((u[:, 0] * 4).astype(int).tolist())
    [0, 1, 2, 3]
    """
    from scipy.stats import qmc

    n = _check_samples(samples)
    return qmc.LatinHypercube(d=int(dimensions), rng=np.random.default_rng(seed)).random(n)


def monte_carlo(samples: int, dimensions: int, seed: int) -> np.ndarray:
    """Independent uniform points in :math:`[0, 1)^d` (simple random sampling).

    Examples
    --------
    >>> bool(np.all(monte_carlo(3, 2, seed=7) == monte_carlo(3, 2, seed=7)))
    True
    """
    n = _check_samples(samples)
    return np.random.default_rng(seed).random((n, int(dimensions)))


PLANS.add("latin_hypercube", latin_hypercube)
PLANS.add("monte_carlo", monte_carlo)
PLANS.add("grid", full_grid)


def transform(u: np.ndarray, variable: Variable) -> np.ndarray:
    r"""Map unit-interval points to a variable's values.

    .. math:: x = F^{-1}(u) \quad\text{or}\quad x = x_{low} + u (x_{high} - x_{low})

    (logarithmic: :math:`\ln x = \ln x_{low} + u \ln(x_{high}/x_{low})`).

    Parameters
    ----------
    u : ndarray
        Points in [0, 1).
    variable : Variable

    Returns
    -------
    ndarray
        Values in the variable's unit.

    References
    ----------
    Devroye 1986, §II.2.1 (inversion method).

    Examples
    --------
    >>> v = Variable("tensioner.mass", "kg", low=10.0, high=1000.0, scale="log")
    >>> transform(np.array([0.0, 0.5]), v).round(6).tolist()
    [10.0, 100.0]
    """
    x = variable._from_unit(np.asarray(u, dtype=float))
    if not np.all(np.isfinite(x)):
        raise InputError(f"variable {variable.path!r}: the distribution gives non-finite values; "
                         "give a distribution with finite quantiles")
    return np.rint(x) if variable.integer else x


def format_value(value: Any, unit: str) -> Any:
    """A value as a project file writes it: ``"50 arcmin"``; a bare number without unit.

    Numbers are written with 12 significant digits (a relative change below 1e-12).

    Examples
    --------
    >>> format_value(50.0, "arcmin"), format_value(19, ""), format_value("16B", "")
    ('50 arcmin', 19, '16B')
    >>> format_value(31.697863849222262, "kN/m"), format_value(0.1 + 0.2, "")
    ('31.6978638492 kN/m', 0.3)
    """
    if isinstance(value, (bool, str)):
        return value
    if isinstance(value, (int, np.integer)):
        return f"{int(value)} {unit}" if unit else int(value)
    text = f"{float(value):.12g}"
    return f"{text} {unit}" if unit else float(text)


def plan_rows(kind: str, variables: Sequence[Variable], *, samples: int | None = None,
              seed: int = 0) -> list[tuple]:
    """Rows of values (in each variable's unit) of a plan.

    Parameters
    ----------
    kind : {"grid", "latin_hypercube", "monte_carlo"}
    variables : sequence of Variable
    samples : int, optional
        Number of variants of a Latin hypercube or Monte Carlo plan.
    seed : int
        Seed of the random generator.

    Returns
    -------
    list of tuple
        One tuple of values per variant (ints for integer variables).

    Examples
    --------
    >>> vs = [Variable("drive.speed", "rpm", low=500.0, high=1500.0, count=3),
    ...       Variable("wheels.0.teeth", values=(17, 19))]
    >>> plan_rows("grid", vs)[:3]
    [(500.0, 17), (500.0, 19), (1000.0, 17)]
    """
    PLANS.get(kind)
    if not variables:
        raise InputError("plan: vary at least 1 input (a [[vary]] table), got none")
    if kind == "grid":
        return full_grid([v.levels() for v in variables])
    if samples is None:
        raise InputError(f"plan.samples: a {kind} plan needs the number of samples, "
                         f"a whole number in [1, {MAXIMUM_VARIANTS}]")
    u = PLANS.get(kind)(samples, len(variables), seed)
    columns = [transform(u[:, j], v) for j, v in enumerate(variables)]
    return [tuple(_round(float(c[i]), v.integer) for c, v in zip(columns, variables, strict=True))
            for i in range(u.shape[0])]


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
