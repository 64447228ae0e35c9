r"""Fatigue of the link plates from the running tension: rainflow counting, S–N curve, Miner's rule.

A link's tension runs through one cycle per lap (tight span → wheel → slack span), plus
whatever the dynamics add. Rainflow counting (ASTM E1049-85, the ``rainflow`` package)
turns a tension history into cycles of range ``ΔF`` and mean; each is made equivalent to a
pulsating cycle (``R = 0``, the way chains are tested and rated) by the Smith–Watson–Topper
parameter, ``ΔF_0 = sqrt(F_max ΔF)``. The S–N curve of the link plates is a Basquin line

.. math:: N(ΔF_0) = N_D \left(\frac{ΔF_e}{ΔF_0}\right)^{k}\quad (ΔF_0 > ΔF_e),\qquad
          N = \infty \text{ below}

whose endurance ``ΔF_e`` is tied to the rating basis: the ANSI/ACA link-plate line is the
plates' fatigue limit (Tsubaki, *The Complete Guide to Chain*, 1997, §2.2.3, Fig. 2.19:
"line O-A … the fatigue limit", no finite life), so the tight-side tension at the
link-plate-limited power, ``ΔF_e = P_{plate} / v`` (slack side ≈ 0), is the endurance
range. ``N_D = 10^6`` and ``k = 5`` are the FKM guideline's component S–N curve for normal
stress in steel (FKM, *Analytical strength assessment*, 6th ed., 2012, §4.4.3). Miner's
rule sums the damage: ``D = Σ n_i / N_i`` and the life is ``1/D`` laps.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from .._results import Result, quantity
from .._validation import as_float_array, check_positive
from ..errors import InputError

__all__ = ["KNEE_CYCLES", "SN_EXPONENT", "FatigueCycles", "rainflow_cycles", "equivalent_range",
           "cycles_to_failure", "miner_damage"]

#: Knee of the S–N curve [cycles] (FKM guideline, steel, normal stress).
KNEE_CYCLES = 1.0e6
#: Basquin exponent ``k`` of the S–N curve (FKM guideline, components, normal stress).
SN_EXPONENT = 5.0


@dataclass(frozen=True)
class FatigueCycles(Result):
    """Rainflow cycles of a tension history: ranges, means and counts (0.5 or 1)."""

    ranges: np.ndarray = quantity("N")
    means: np.ndarray = quantity("N")
    counts: np.ndarray = quantity("1")


def rainflow_cycles(tension: ArrayLike) -> FatigueCycles:
    r"""Rainflow cycles of a tension history (ASTM E1049-85, by the ``rainflow`` package).

    Parameters
    ----------
    tension : array_like
        Tension of one link over time (or along its lap) [N], at least 2 samples.

    Returns
    -------
    FatigueCycles

    Raises
    ------
    InputError
        Fewer than 2 samples, NaN or inf.

    References
    ----------
    ASTM E1049-85 (2017), *Standard practices for cycle counting in fatigue analysis*,
    §5.4.4 (rainflow counting); package ``rainflow`` (Janiszewski), ``extract_cycles``.

    Examples
    --------
    >>> c = rainflow_cycles([0.0, 5000.0, 200.0, 5000.0, 0.0])
    >>> [float(r) for r in c.ranges], [float(n) for n in c.counts]
    ([4800.0, 5000.0, 5000.0], [1.0, 0.5, 0.5])
    """
    import rainflow

    x = as_float_array("tension", tension).ravel()
    if x.size < 2 or not np.all(np.isfinite(x)):
        raise InputError("tension must hold at least 2 finite samples [N]", field="tension")
    rows = list(rainflow.extract_cycles(x))
    if not rows:
        z = np.zeros(0)
        return FatigueCycles(z, z, z)
    arr = np.asarray([(r, m, c) for r, m, c, _i, _j in rows], dtype=float)
    order = np.argsort(arr[:, 0], kind="stable")
    arr = arr[order]
    return FatigueCycles(arr[:, 0], arr[:, 1], arr[:, 2])


def equivalent_range(ranges: ArrayLike, means: ArrayLike) -> np.ndarray:
    r"""Pulsating (``R = 0``) range equivalent to a cycle by Smith, Watson & Topper.

    .. math:: ΔF_0 = \sqrt{F_{max}\,ΔF},\qquad F_{max} = F_m + ΔF/2

    Parameters
    ----------
    ranges, means : array_like
        ``ΔF`` and ``F_m`` [N].

    Returns
    -------
    ndarray
        [N]; ``ΔF_0 = ΔF`` for a pulsating cycle.

    References
    ----------
    Smith, Watson & Topper, "A stress-strain function for the fatigue of metals",
    J. Materials 5 (1970) 767–778.

    Examples
    --------
    >>> float(equivalent_range(4000.0, 2000.0)), round(float(equivalent_range(1000.0, 3000.0)), 1)
    (4000.0, 1870.8)
    """
    d = as_float_array("ranges", ranges)
    m = as_float_array("means", means)
    fmax = np.maximum(m + 0.5 * d, 0.0)
    return np.sqrt(fmax * np.maximum(d, 0.0))


def cycles_to_failure(equivalent: ArrayLike, endurance_range: float, *, knee: float = KNEE_CYCLES,
                      exponent: float = SN_EXPONENT) -> np.ndarray:
    r"""Cycles to failure of the link plates at an equivalent pulsating range.

    .. math:: N = N_D\,(ΔF_e / ΔF_0)^{k} \text{ for } ΔF_0 > ΔF_e, \text{ else } \infty

    Parameters
    ----------
    equivalent : array_like
        ``ΔF_0`` [N].
    endurance_range : float
        ``ΔF_e`` [N] (tied to the rating: see the module notes).
    knee, exponent : float
        ``N_D``, ``k``.

    Returns
    -------
    ndarray
        [cycles]; ``inf`` below the endurance.

    References
    ----------
    FKM guideline, 6th ed. (2012), §4.4.3 (``k = 5``, ``N_D = 10^6`` for steel components
    in normal stress); Tsubaki (1997), Fig. 2.19 (link-plate line = fatigue limit).

    Examples
    --------
    >>> float(cycles_to_failure(2000.0, 1000.0))
    31250.0
    """
    s = as_float_array("equivalent", equivalent)
    se = float(check_positive("endurance_range", endurance_range, "N"))
    nd = float(check_positive("knee", knee))
    k = float(check_positive("exponent", exponent))
    with np.errstate(divide="ignore"):
        n = nd * (se / np.maximum(s, 1e-300)) ** k
    return np.where(s > se, n, math.inf)


def miner_damage(cycles: FatigueCycles, endurance_range: float, *, knee: float = KNEE_CYCLES,
                 exponent: float = SN_EXPONENT) -> float:
    r"""Miner's damage of one pass of a history: ``D = Σ n_i / N_i``.

    Parameters
    ----------
    cycles : FatigueCycles
        From :func:`rainflow_cycles`.
    endurance_range, knee, exponent
        As in :func:`cycles_to_failure`.

    Returns
    -------
    float
        [-]; the history repeats ``1/D`` times before failure.

    References
    ----------
    Miner, M. A., "Cumulative damage in fatigue", J. Appl. Mech. 12 (1945) A159–A164.

    Examples
    --------
    >>> c = rainflow_cycles([0.0, 2000.0, 0.0])
    >>> miner_damage(c, 1000.0)
    3.2e-05
    """
    eq = equivalent_range(cycles.ranges, cycles.means)
    n = cycles_to_failure(eq, endurance_range, knee=knee, exponent=exponent)
    return float(np.sum(np.where(np.isfinite(n), cycles.counts / n, 0.0)))


from chaindrive._finite import guard_public  # noqa: E402

# every public function and dataclass: NaN/inf in or out refused; cycles_to_failure is +inf
# below the endurance range by its documented meaning; rainflow_cycles checks its samples itself
guard_public(__name__, skip=("cycles_to_failure", "rainflow_cycles"))
