"""A way out of a failed span-vibration check: the nearest design that passes, over what a designer can change.

Searched (the stated ranges, :data:`REMEDY_RANGES`): the tensioner's position along the
slack span (its wheel moved parallel to the chord of the span between its neighbours),
the pretension (the tensioner force), the tensioner's mass and its stiffness. Each
candidate's layout and loads are recomputed (the spans, angles and the slack tension
follow the change) and its forced response to every excitation is computed; it passes
with the criterion of the verdict itself
(:func:`chaindrive.analysis.vibration.vibration_checks`): every excitation amplified at
most :data:`~chaindrive.vibration.excitation.AMPLIFICATION_LIMIT` times, here with the
reserve :data:`REQUIRED_MARGIN`. The candidates are rounded as a designer writes them
(:data:`SIGNIFICANT_DIGITS`, positions to the millimetre) before they are judged, and the
nearest passing one (distance: each change relative to its range, root of the sum of
squares) is verified by the full analysis of the changed drive: it must pass the
vibration check and fail no check the design passed. Only then is it returned as found
(``analyze -o DIR`` writes it to ``DIR/proposal.toml``). When none passes, the best
candidate is returned with the reason and the bounds of the search that stop it.

Guides or supports in the span (which shorten the free length) are not searched.

The declared part ``remedy`` (needs ``vibration``; about a second when the check fails,
so a per-keystroke caller may ``exclude=["remedy"]``) is shown in the vibration section.
"""

from __future__ import annotations

import dataclasses
import math
from typing import TYPE_CHECKING, Any

import numpy as np

from .._finite import finite_guard
from .._results import Result, quantity
from ..drive.model import Drive
from ..errors import ChainDriveError
from ..vibration import TensionerSpan
from ..vibration.excitation import AMPLIFICATION_LIMIT
from .parts import Part, PartContext, register_part

if TYPE_CHECKING:
    from .vibration import DriveVibration

__all__ = ["REMEDY_RANGES", "REQUIRED_MARGIN", "SIGNIFICANT_DIGITS", "Remedy", "round_significant", "search_remedy"]

#: What the search may change, relative to the design: mass and stiffness factors,
#: tensioner-force factor, shift of the tensioner wheel along the span's chord as a
#: fraction of the chord (a designer's practical range: a tensioner of 1/4 to 4 times the
#: mass, springs of 1/10 to 10 times the rate, half to twice the pretension, within
#: the outer thirds of the span).
REMEDY_RANGES = {"mass": (0.25, 4.0), "stiffness": (0.1, 10.0), "force": (0.5, 2.0), "shift": (-0.3, 0.3)}
#: Reserve of a proposal below the amplification limit (5 %: robust to tolerances and to
#: the rounding of the written values).
REQUIRED_MARGIN = 0.05
#: Significant digits of a proposed mass, stiffness and force (positions: to 1 mm).
SIGNIFICANT_DIGITS = 3
_GRID = {"mass": 9, "stiffness": 9, "force": 5, "shift": 7}
#: Candidates passing the fast criterion that are verified by the full analysis, at most.
_VERIFIED = 8


@dataclasses.dataclass(frozen=True)
class Remedy(Result):
    """The nearest design that passes the span-vibration check, or the best one found.

    Attributes
    ----------
    found : bool
        A candidate within :data:`REMEDY_RANGES` passes, verified by the full analysis.
    drive : Drive
        The proposed (or the best) design.
    changes : tuple of str
        What changed, in words with the old and new values.
    margin : float
        Worst margin of the tensioner paper's band of the proposal [-] (information).
    amplification : float
        Largest amplification of the proposal's forced response over every excitation [-]
        (the verdict's number; at most the limit when found).
    distance : float
        Size of the change (each change over its range, root sum of squares) [-].
    reason : str
        Why nothing passes (empty when found).
    ranges : str
        The ranges searched, in words.
    bounds : tuple of str
        The bounds of the searched ranges at which the best candidate sits (what stops the
        search; empty when found).
    """

    found: bool
    drive: Drive
    changes: tuple[str, ...]
    margin: float = quantity("1")
    amplification: float = quantity("1")
    distance: float = quantity("1")
    reason: str = ""
    ranges: str = ""
    bounds: tuple[str, ...] = ()


def _ranges_text() -> str:
    r = REMEDY_RANGES
    return (f"tensioner mass ×{r['mass'][0]:g}…×{r['mass'][1]:g}, stiffness ×{r['stiffness'][0]:g}…×"
            f"{r['stiffness'][1]:g}, force (pretension) ×{r['force'][0]:g}…×{r['force'][1]:g}, position along "
            f"the span ±{100 * r['shift'][1]:.0f} % of its chord")


@finite_guard  # NaN/inf and out-of-range arguments refused (chaindrive._finite)
def round_significant(x: float, digits: int = SIGNIFICANT_DIGITS) -> float:
    """``x`` rounded to ``digits`` significant digits, as a designer writes it.

    >>> round_significant(112468.26503806982), round_significant(3535.533905932738)
    (112000.0, 3540.0)
    """
    if x == 0 or not math.isfinite(x):
        return float(x)
    return float(round(x, digits - 1 - int(math.floor(math.log10(abs(x))))))


def _moved(drive: Drive, shift: float, force_factor: float) -> Drive:
    """The drive with the tensioner wheel moved along the chord (to the mm) and its force scaled (rounded)."""
    t = drive.tensioner
    assert t is not None
    n = len(drive.wheels)
    i = drive.wheel_index(t.wheel)
    a, b = np.asarray(drive.wheels[(i - 1) % n].position), np.asarray(drive.wheels[(i + 1) % n].position)
    pos = np.asarray(drive.wheels[i].position) + shift * (b - a)
    wheels = list(drive.wheels)
    if shift != 0.0:
        wheels[i] = dataclasses.replace(wheels[i], position=(round(float(pos[0]), 3) + 0.0, round(float(pos[1]), 3) + 0.0))
    force = None if t.force is None else (t.force if force_factor == 1.0 else round_significant(t.force * force_factor))
    return dataclasses.replace(drive, wheels=tuple(wheels), tensioner=dataclasses.replace(t, force=force))


def _span(drive: Drive) -> TensionerSpan | None:
    """The slack span of a moved drive, as the analysis computes it (its layout, the conveyor's
    pull, its loads); None where the tensioner paper's coupling does not apply or the layout fails."""
    from . import analyze_drive

    try:
        vib = analyze_drive(drive, include=["vibration"])["vibration"]
    except ChainDriveError:
        return None
    return None if vib is None or vib.tensioner is None else vib.span


def _amplifications(span: TensionerSpan, excitations: list[tuple[float, float]], omega: float,
                    mass: np.ndarray, stiffness: np.ndarray) -> np.ndarray:
    """Largest amplification over the excitations (frequency [rad/s], end amplitude [m]) for K
    tensioners at once (the criterion of :func:`~chaindrive.analysis.vibration.vibration_checks`)."""
    from ..vibration.excitation import DAMPING_RATIO, _span_response

    out = np.zeros(mass.size)
    for freq, amp in excitations:  # each with its amplitude, as span_excitations
        w, _ = _span_response(span, np.array([freq, 1e-6 * omega]), amp, amp, DAMPING_RATIO, 101, mass, stiffness)
        out = np.maximum(out, w[:, 0] / w[:, 1])
    return out


def _failed_names(analysis: Any) -> set[tuple[str, str]]:
    return {(c.part, c.name) for c in analysis.checks if c.passed is False}


def _verify(new: Drive, failed_before: set[tuple[str, str]]) -> tuple[bool, Any, str]:
    """The full analysis of a candidate: (passes the vibration check and fails nothing new, analysis, why not)."""
    from . import analyze_drive

    try:
        a = analyze_drive(new, exclude=["remedy"])
    except ChainDriveError as exc:
        return False, None, str(exc)
    vib = a["vibration"]
    if vib is None or vib.tensioner is None:
        return False, a, "the tensioner paper's coupling does not apply to it"
    new_failures = [c for c in a.checks if c.passed is False and (c.part, c.name) not in failed_before]
    if any(c.part == "vibration" for c in new_failures) or vib.passed is not True:
        w = worst_of(vib)
        return False, a, (f"its re-analysis amplifies the {w.name} excitation {w.amplification:.3g}× "
                          f"(limit {AMPLIFICATION_LIMIT:.3g}×)" if w is not None else "its re-analysis fails")
    if new_failures:
        return False, a, "it fails " + "; ".join(f"{c.name} ({c.part})" for c in new_failures)
    return True, a, ""


def worst_of(vib: Any) -> Any:
    from .vibration import worst_response

    return worst_response(vib)


def search_remedy(drive: Drive, vib: DriveVibration) -> Remedy | None:
    r"""The nearest design within :data:`REMEDY_RANGES` that passes the span-vibration check.

    Parameters
    ----------
    drive : Drive
        The design, with a tensioner.
    vib : DriveVibration
        Its vibration analysis (failed).

    Returns
    -------
    Remedy or None
        None when the drive has no tensioner span to change.

    .. math:: d = \sqrt{\sum_k (\log(x_k/x_{k,0}) / \log r_k)^2 + (s/s_{max})^2}

    Notes
    -----
    Grid: 9 masses × 9 stiffnesses (geometric) × 5 forces × 7 positions, each value
    rounded (:func:`round_significant`, positions to 1 mm). For each (force, position) its
    own layout and loads, then the forced response to every excitation for every (mass,
    stiffness) at once; a candidate passes the fast criterion when every excitation is
    amplified at most :data:`~chaindrive.vibration.excitation.AMPLIFICATION_LIMIT`
    × (1 − :data:`REQUIRED_MARGIN`). In order of distance, the first such candidate whose
    full analysis passes the vibration check and fails no check the design passed is
    returned as found.
    """
    if drive.tensioner is None or vib.span is None:
        return None
    from . import analyze_drive

    t0 = drive.tensioner
    m0, c0 = float(t0.mass), float(t0.stiffness)
    rng = REMEDY_RANGES
    fm = np.geomspace(*rng["mass"], _GRID["mass"]) if m0 > 0 else np.array([1.0])
    fc = np.geomspace(*rng["stiffness"], _GRID["stiffness"]) if 0 < c0 < math.inf else np.array([1.0])
    ff = np.geomspace(*rng["force"], _GRID["force"]) if t0.force else np.array([1.0])
    fs = np.linspace(*rng["shift"], _GRID["shift"])
    masses = np.array([m0 if a == 1.0 else round_significant(m0 * a) for a in fm])
    stiffs = np.array([c0 if c == 1.0 else round_significant(c0 * c) for c in fc])
    mm, cc = (x.ravel() for x in np.meshgrid(masses, stiffs, indexing="ij"))
    omega = float(drive.speed)
    excitations = [(s.frequency, s.end_amplitude) for s in vib.severity if s.end_amplitude > 0]
    target = AMPLIFICATION_LIMIT * (1.0 - REQUIRED_MARGIN)
    candidates = []
    for force in ff:
        for shift in fs:
            key = (float(force), float(shift))
            sp = _span(_moved(drive, float(shift), float(force)))
            if sp is None:
                continue
            amp = _amplifications(sp, excitations, omega, mm, cc)
            for k, (i, j) in enumerate(np.ndindex(fm.size, fc.size)):
                d = math.sqrt((math.log(fm[i]) / math.log(rng["mass"][1])) ** 2
                              + (math.log(fc[j]) / math.log(rng["stiffness"][1])) ** 2
                              + (math.log(force) / math.log(rng["force"][1])) ** 2
                              + (shift / rng["shift"][1]) ** 2)
                candidates.append((d, float(amp[k]), int(i), int(j), key))
    if not candidates:
        return None

    def design(cand: tuple) -> Drive:
        _, _, i, j, key = cand
        new = _moved(drive, key[1], key[0])
        assert new.tensioner is not None
        t = new.tensioner
        if masses[i] == t.mass and stiffs[j] == t.stiffness:
            return new
        # a new mass or stiffness replaces the description by parts (it is their reduction)
        return dataclasses.replace(new, tensioner=dataclasses.replace(t, mass=float(masses[i]), stiffness=float(stiffs[j]),
                                                                      mechanism=None, parts=()))

    def result(found: bool, cand: tuple, a: Any, why: str, bounds: tuple[str, ...] = ()) -> Remedy:
        new = a.drive if a is not None else design(cand)
        v = a["vibration"] if a is not None else None
        margin = float(np.min(v.tensioner.check.margin)) if v is not None and v.tensioner is not None else math.nan
        w = worst_of(v) if v is not None else None
        amp = float(w.amplification) if w is not None else cand[1]
        return Remedy(found, new, _changes(drive, new, cand[4][1]), margin, amp, cand[0], why, _ranges_text(), bounds)

    failed_before = _failed_names(analyze_drive(drive, exclude=["remedy"]))
    rejected: list[str] = []
    for cand in sorted((c for c in candidates if c[1] <= target), key=lambda x: x[0])[:_VERIFIED]:
        ok, a, why = _verify(design(cand), failed_before)
        if ok:
            return result(True, cand, a, "")
        rejected.append(why)
    best = min(candidates, key=lambda x: (x[1], x[0]))
    _, _, i, j, (force, shift) = best
    bounds = tuple(text for text, at in (
        (f"tensioner mass at ×{rng['mass'][0]:g}", m0 > 0 and i == 0),
        (f"tensioner mass at ×{rng['mass'][1]:g}", m0 > 0 and i == fm.size - 1),
        (f"stiffness at ×{rng['stiffness'][0]:g}", fc.size > 1 and j == 0),
        (f"stiffness at ×{rng['stiffness'][1]:g}", fc.size > 1 and j == fc.size - 1),
        (f"force at ×{rng['force'][0]:g}", ff.size > 1 and force == ff[0]),
        (f"force at ×{rng['force'][1]:g}", ff.size > 1 and force == ff[-1]),
        (f"position at {100 * rng['shift'][0]:+.0f} % of the chord", shift == fs[0]),
        (f"position at {100 * rng['shift'][1]:+.0f} % of the chord", shift == fs[-1])) if at)
    ok, a, why = _verify(design(best), failed_before)
    reason = (f"the best candidate still amplifies the response {best[1]:.3g}× (limit {target:.3g}× with the "
              f"{100 * REQUIRED_MARGIN:.0f} % reserve)" if best[1] > target else
              f"the {len(rejected)} nearest candidates that meet the amplification limit fail their verification by "
              "the full analysis: " + "; ".join(dict.fromkeys(rejected[:3])))
    if bounds:
        reason += "; it sits at the bound" + ("s" if len(bounds) > 1 else "") + " of the search: " + ", ".join(bounds)
    return result(False, best, a, reason, bounds)


def _changes(old: Drive, new: Drive, shift: float) -> tuple[str, ...]:
    t0, t1 = old.tensioner, new.tensioner
    assert t0 is not None and t1 is not None
    out = []
    if not math.isclose(t0.mass, t1.mass):
        out.append(f"tensioner mass {t0.mass:.4g} kg → {t1.mass:.4g} kg")
    if not math.isclose(t0.stiffness, t1.stiffness):
        out.append(f"tensioner stiffness {t0.stiffness / 1e3:.4g} kN/m → {t1.stiffness / 1e3:.4g} kN/m")
    if t0.force is not None and t1.force is not None and not math.isclose(t0.force, t1.force):
        out.append(f"tensioner force (pretension) {t0.force / 1e3:.4g} kN → {t1.force / 1e3:.4g} kN")
    if shift != 0.0:
        i = old.wheel_index(t0.wheel)
        (x0, y0), (x1, y1) = old.wheels[i].position, new.wheels[i].position
        out.append(f"tensioner wheel {t0.wheel!r} moved along the span from ({x0 * 1e3:.0f}, {y0 * 1e3:.0f}) mm "
                   f"to ({x1 * 1e3:.0f}, {y1 * 1e3:.0f}) mm ({100 * shift:+.0f} % of the chord)")
    return tuple(out)


# --------------------------------------------------------------------------- declared part
def _remedy_part(ctx: PartContext) -> Remedy | None:
    vib = ctx["vibration"]
    if vib is None or vib.passed is not False:
        return None
    found = search_remedy(ctx.drive, vib)
    if found is not None and not found.found:
        ctx.note(f"no design within the searched ranges ({found.ranges}) passes the span-vibration check: {found.reason}")
    return found


register_part(Part("remedy", "A design that passes the span-vibration check", _remedy_part, needs=("vibration",),
                   order=51, section="chaindrive.workflows.sections:vibration_section"))
