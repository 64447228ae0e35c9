r"""The compliant wrap's jump-over onset at the analysis' cost: a reduced model of :func:`wrap_jump_ratio`.

:func:`chaindrive.life.wrap_jump_ratio` (the compliant load distribution of the worn wrap,
after Marshek & Naji, *Mech. Mach. Theory* 18 (1983) 349; checked against the simulation's
quasi-static onset within 10 % on ten cases, ``benchmarks/life.py``) takes seconds per wheel. Its
onset is tabulated here as a correction to the rigid, uniformly seated model of
:mod:`chaindrive.life.jump_over`:

.. math::
    ρ_{jump} = c(z, s, λ, \text{loading})\;β(e)^{-n},\qquad s = \frac{e}{e_{hold}},\qquad
    λ = \frac{F}{EA}

- ``ρ_jump`` the onset's load ratio ``M/(R_e T_2)`` (with the span tensions held: the
  tension ratio ``T_1/T_2``), ``β`` of :func:`chaindrive.life.tension_ratio`, ``n`` the
  rollers in mesh (:func:`chaindrive.layout.teeth_in_mesh`),
- ``s`` the elongation over the tooth form's holding limit
  (:func:`chaindrive.life.holding_limit`),
- ``λ`` the span tensions' sum ``F`` (one strand) over the chain's axial stiffness ``EA``
  (:func:`chaindrive.chains.stiffness.chain_axial_stiffness`; the contact stiffness scaled
  with the size like it, ``k_c p = 2 EA``, as the simulation's 16B),
- the loading: ``"torque"`` (the wheel's torque and ``T_1 + T_2`` held: a loaded wheel on
  a slide) or ``"tensions"`` (the span tensions held: a back tension set by a tensioner on
  the slack span or by its sag).

``c`` is stored in ``life/data/wrap_jump.json`` (written by ``scripts/tabulate_wrap_jump.py``
from :func:`wrap_jump_ratio`, provenance in the file) on ``z × s`` at ``λ = 3·10⁻⁵`` (torque) or
``3·10⁻⁴`` (tensions) with a coarse factor for ``λ``; it is interpolated linearly in ``ln c`` over ``ln z``, ``s`` and
``ln λ``. The table is for the half wrap (180°) of ISO 606 16B proportions
(``d_1/p = 0.625``) and the tip diameter ``d_a max`` of the tooth form of
:func:`~chaindrive.life.holding_limit`, so that ``s`` runs up to the holding limit (0.999 of it);
``n`` carries the wheel's own wrap into ``β^-n``, ``c`` is the half wrap's. Outside the table's
range (:func:`wrap_jump_range`) the nearest edge is used and a
:class:`~chaindrive.errors.ValidityRangeWarning` says so.

References
----------
K. M. Marshek and M. R. Naji, "Analysis of sprocket load distribution", Mech. Mach. Theory
18 (1983) 349-356; docs/life.md, "Jump-over".
"""

from __future__ import annotations

import bisect
import functools
import json
import math
import warnings
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import ArrayLike

from .._results import Result, quantity
from .._validation import check_nonnegative, check_positive
from ..errors import InputError, ValidityRangeWarning
from .jump_over import holding_limit, tension_ratio

__all__ = ["JumpOnset", "LOADINGS", "jump_onset", "wrap_jump_range"]

#: The loadings of the table (see the module notes).
LOADINGS = ("torque", "tensions")
_DATA = Path(__file__).with_name("data") / "wrap_jump.json"
#: Axial stiffness of a 16B strand [N] the table's ``λ`` is scaled by when none is given
#: (:data:`chaindrive.chains.stiffness.AXIAL_STIFFNESS_16B`, scaled with the pitch squared).
_EA_16B = 1.0e8


@functools.cache
def _table() -> dict:
    raw = json.loads(_DATA.read_text())
    out = {"teeth": np.log(np.asarray(raw["teeth"], float)), "fraction": np.asarray(raw["fraction"], float),
           "side_teeth": np.log(np.asarray(raw["side_teeth"], float)),
           "side_fraction": np.asarray(raw["side_fraction"], float), "provenance": raw["provenance"]}
    for ld in LOADINGS:
        lams = [float(raw[ld]["load_stiffness"]), *map(float, raw[ld]["side_load_stiffness"])]
        order = np.argsort(lams)
        out[ld + "_lambda"] = np.log(np.asarray(lams))[order]
        out[ld] = np.log(np.asarray(raw[ld]["correction"], float))
        side = np.log(np.asarray(raw[ld]["load_factor"], float))  # teeth × fraction × (the side λ)
        full = np.concatenate([np.zeros(side.shape[:2] + (1,)), side], axis=2)
        out[ld + "_side"] = full[:, :, order]
    return out


def wrap_jump_range(loading: str = "torque") -> dict[str, tuple[float, float]]:
    """The table's range for ``loading``: ``teeth``, ``fraction`` (``e/e_hold``), ``load_stiffness`` (``F/EA``).

    >>> r = wrap_jump_range()
    >>> r["teeth"], r["fraction"]
    ((9.0, 57.0), (0.0, 0.999))
    """
    if loading not in LOADINGS:
        raise InputError(f"loading must be one of {', '.join(LOADINGS)}, got {loading!r}", field="loading")
    return dict(_range(loading))  # a new dict of the kept (immutable) pairs


@functools.cache
def _range(loading: str) -> tuple[tuple[str, tuple[float, float]], ...]:
    # wrap_jump_range's items for a checked loading, read from the table once
    t = _table()
    lam = t[loading + "_lambda"]
    return (("teeth", (float(round(math.exp(t["teeth"][0]))), float(round(math.exp(t["teeth"][-1]))))),
            ("fraction", (float(t["fraction"][0]), float(t["fraction"][-1]))),
            ("load_stiffness", (float(math.exp(lam[0])), float(math.exp(lam[-1])))))


def _interp(x: float, xp: list[float], fp: list[float]) -> float:
    """``numpy.interp(x, xp, fp)`` for a scalar in Python floats (the same formula: ``fp`` at the
    ends and at a node, else ``slope (x - xp[j]) + fp[j]``); the tables are short."""
    if x <= xp[0]:
        return fp[0]
    if x >= xp[-1]:
        return fp[-1]
    j = bisect.bisect_right(xp, x) - 1
    if xp[j] == x:
        return fp[j]
    return (fp[j + 1] - fp[j]) / (xp[j + 1] - xp[j]) * (x - xp[j]) + fp[j]


def _along(x: float, axis: np.ndarray, values: np.ndarray) -> np.ndarray:
    """``values`` (first axis along ``axis``) interpolated linearly at the scalar ``x`` (clipped)."""
    x = min(max(x, float(axis[0])), float(axis[-1]))
    j = min(max(int(np.searchsorted(axis, x)) - 1, 0), len(axis) - 2)
    w = (x - float(axis[j])) / float(axis[j + 1] - axis[j])
    return (1.0 - w) * values[j] + w * values[j + 1]


@functools.lru_cache(maxsize=1024)
def _rows(loading: str, log_z: float) -> tuple[list[float], tuple[list[float], ...], list[float], list[float],
                                               list[float]]:
    """At ``z``: ``ln c`` at ``λ0`` over the fractions, the side table's ``ln`` factor over ``ln λ`` at each
    side fraction, and the axes (fractions, ``ln λ``, side fractions), as lists of floats."""
    t = _table()
    side = _along(log_z, t["side_teeth"], t[loading + "_side"])
    return (_along(log_z, t["teeth"], t[loading]).tolist(), tuple(row.tolist() for row in side),
            t["fraction"].tolist(), t[loading + "_lambda"].tolist(), t["side_fraction"].tolist())


def _fraction_terms(loading: str, z: float, s: list[float]) -> tuple[list[float], list[tuple]]:
    """What ``ln c`` takes from ``z`` and each ``s`` (:func:`_log_correction`): the ``ln λ`` axis, and per
    point the two side rows about ``s``, the weight of the second and ``ln c`` at ``λ0``."""
    main, side, fraction, axis, sf = _rows(loading, math.log(z))
    last = len(sf) - 2
    terms = []
    for si in s:
        j = min(max(bisect.bisect_left(sf, si) - 1, 0), last)
        w = min(max((si - sf[j]) / (sf[j + 1] - sf[j]), 0.0), 1.0)
        terms.append((side[j], side[j + 1], w, _interp(si, fraction, main)))
    return axis, terms


def _log_correction(axis: list[float], terms: list[tuple], lam: list[float]) -> list[float]:
    """``ln c`` at each point of :func:`_fraction_terms` and its ``λ``: linear in ``s`` and ``ln λ``
    (clipped to the table); the two side rows interpolated over ``ln λ`` as ``numpy.interp`` does."""
    lo, hi = axis[0], axis[-1]
    out = []
    for (row_a, row_b, w, at_lam0), li in zip(terms, lam, strict=True):
        x = math.log(li)
        if x <= lo:
            a, b = row_a[0], row_b[0]
        elif x >= hi:
            a, b = row_a[-1], row_b[-1]
        else:
            k = bisect.bisect_right(axis, x) - 1
            if axis[k] == x:
                a, b = row_a[k], row_b[k]
            else:
                d, dx = x - axis[k], axis[k + 1] - axis[k]
                a = (row_a[k + 1] - row_a[k]) / dx * d + row_a[k]
                b = (row_b[k + 1] - row_b[k]) / dx * d + row_b[k]
        out.append(at_lam0 + ((1.0 - w) * a + w * b))
    return out


def _outside(loading: str, z: float, s: list[float], lam: list[float]) -> tuple[str, ...]:
    """The inputs outside the table's range, in words (``s`` and ``λ`` of the points asked for)."""
    rng = wrap_jump_range(loading)
    outside = []
    for name, lo_v, hi_v, what in (("teeth", z, z, "teeth"), ("fraction", min(s), max(s), "e/e_hold"),
                                   ("load_stiffness", min(lam), max(lam), "F/EA")):
        low, high = rng[name]
        if lo_v < low * (1 - 1e-9) or hi_v > high * (1 + 1e-9):
            shown = f"{lo_v:.4g}" if lo_v == hi_v else f"{lo_v:.4g}…{hi_v:.4g}"
            outside.append(f"{what} = {shown} outside [{low:g}, {high:g}]")
    return tuple(outside)


@dataclass(frozen=True)
class JumpOnset(Result):
    """Onset of jump-over of a worn wrap from the reduced compliant model (see :func:`jump_onset`)."""

    load_ratio: np.ndarray | float = quantity("1")
    tight_tension: np.ndarray | float = quantity("N")
    loading: str = "torque"
    rigid_ratio: np.ndarray | float = quantity("1", default=math.nan)
    correction: np.ndarray | float = quantity("1", default=math.nan)
    outside: tuple[str, ...] = ()
    fraction: np.ndarray | float = quantity("1", default=math.nan)
    load_stiffness: np.ndarray | float = quantity("1", default=math.nan)


def jump_onset(pitch: float, teeth: int, roller_diameter: float, elongation: ArrayLike, *,
               load: float | None = None, back_tension: float | None = None, seated: int | None = None,
               axial_stiffness: float | None = None, warn: bool = True) -> JumpOnset:
    r"""The load ratio at which a worn wrap lets the chain jump, from the table of the compliant model.

    .. math:: ρ_{jump} = c(z,\ e/e_{hold},\ F/EA)\;β(e)^{-n}

    Give ``load`` for a wheel whose torque and span tensions' sum ``F`` are held (a loaded
    wheel on a slide: the ``torque`` loading; ``ρ = M/(R_e T_2)`` with ``T_2 = F - M/R_e``), or
    ``back_tension`` for one whose back tension ``T_2`` is held (the ``tensions`` loading,
    ``ρ = T_1/T_2``; ``F = T_2 (1 + ρ_jump)`` at the onset, found by two substitutions).

    Parameters
    ----------
    pitch : float
        Wheel (nominal chain) pitch ``p`` [m].
    teeth : int
        ``z``.
    roller_diameter : float
        ``d_1`` [m].
    elongation : float or array_like
        ``0 <= e`` up to the tooth form's holding limit [-].
    load : float, optional
        ``F = T_1 + T_2`` of one strand, held [N], > 0.
    back_tension : float, optional
        ``T_2`` of one strand, held [N], > 0.
    seated : int, optional
        Rollers in mesh ``n`` (default the half wrap's, ``teeth_in_mesh(π, z) = ⌊z/2⌋``).
    axial_stiffness : float, optional
        ``EA`` of one strand [N]; default 16B's ``1e8 N`` scaled with the pitch squared
        (:func:`chaindrive.chains.stiffness.chain_axial_stiffness`).
    warn : bool
        Warn (:class:`~chaindrive.errors.ValidityRangeWarning`) for inputs outside the
        table's range; they are in ``outside`` either way.

    Returns
    -------
    JumpOnset
        ``load_ratio`` ``ρ_jump`` [-] (the shape of ``elongation``), ``tight_tension`` the
        tight-side tooth load at the onset (``F ρ/(1 + ρ)``, or ``T_2 ρ``) [N],
        ``rigid_ratio`` ``β^-n``, ``correction`` ``c``, ``fraction`` ``e/e_hold``,
        ``load_stiffness`` ``F/EA``, ``loading``, ``outside`` the inputs outside the
        table's range, in words.

    Raises
    ------
    InputError
        An elongation the tooth form cannot hold (:func:`chaindrive.life.tension_ratio`),
        not exactly one of ``load`` and ``back_tension``, or bad input.

    References
    ----------
    Marshek and Naji, Mech. Mach. Theory 18 (1983) 349 (compliant load distribution);
    :func:`chaindrive.life.wrap_jump_ratio`, tabulated by ``scripts/tabulate_wrap_jump.py``.

    Examples
    --------
    >>> r = jump_onset(0.0254, 17, 0.01588, 0.1, load=3000.0)
    >>> 45 < r.load_ratio < 60  # wrap_jump_ratio: 52.0; the simulation, quasi-static: 50.9
    True
    """
    if (load is None) == (back_tension is None):
        raise InputError("give exactly one of load (T1 + T2 held, e.g. 3000 N) and back_tension (T2 held)",
                         field="load")
    p = float(check_positive("pitch", pitch, "m"))
    z = float(check_positive("teeth", teeth))
    if z != round(z) or z < 3:
        raise InputError(f"teeth must be a whole number >= 3, got {z:g}", field="teeth")
    ea = _EA_16B * (p / 0.0254) ** 2 if axial_stiffness is None else float(
        check_positive("axial_stiffness", axial_stiffness, "N"))
    n = int(z) // 2 if seated is None else int(check_positive("seated", seated))
    if seated is not None and n != seated:
        raise InputError(f"seated must be a whole number of rollers, got {seated}", field="seated")
    e = np.asarray(check_nonnegative("elongation", elongation), float)
    flat = e.ravel()
    beta = np.atleast_1d(np.asarray(tension_ratio(p, int(z), roller_diameter, flat), float)).tolist()  # refuses e > e_hold
    hold = holding_limit(p, int(z), roller_diameter)
    # point by point in Python floats (an analysis asks for 7 … 17 points: numpy's per-call cost would dominate)
    s_l = [x / hold for x in flat.tolist()]
    rigid_l = [b ** (-float(n)) if b > 0 else math.inf for b in beta]
    f = t2 = 0.0
    if load is not None:
        loading, f = "torque", float(check_positive("load", load, "N"))
        lam_l = [f / ea] * len(s_l)
        axis, terms = _fraction_terms(loading, z, s_l)
        c_l = list(map(math.exp, _log_correction(axis, terms, lam_l)))
    else:
        loading, t2 = "tensions", float(check_positive("back_tension", float(back_tension or 0.0), "N"))
        c_l = [1.6] * len(s_l)  # the simulated cases' c (docs/life.md); two substitutions of F
        axis, terms = _fraction_terms(loading, z, s_l)
        for _ in range(2):
            lam_l = [t2 * (1.0 + min(ci * ri, 1e12)) / ea for ci, ri in zip(c_l, rigid_l, strict=True)]
            c_l = list(map(math.exp, _log_correction(axis, terms, lam_l)))
    rho_l = [ci * ri for ci, ri in zip(c_l, rigid_l, strict=True)]
    tight_l = [f * r / (1.0 + r) for r in rho_l] if loading == "torque" else [t2 * r for r in rho_l]
    outside = _outside(loading, z, s_l, lam_l)
    if warn and outside:
        warnings.warn(f"jump-over onset (the compliant wrap's table, scripts/tabulate_wrap_jump.py): "
                      f"{'; '.join(outside)}; the nearest edge of the table is used", ValidityRangeWarning,
                      stacklevel=2)

    def shaped(v):
        return float(v[0]) if e.ndim == 0 else np.array(v, float).reshape(e.shape)

    return JumpOnset(shaped(rho_l), shaped(tight_l), loading, shaped(rigid_l), shaped(c_l), outside, shaped(s_l),
                     shaped(lam_l))
