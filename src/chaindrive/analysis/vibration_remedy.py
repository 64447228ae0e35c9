"""A way out of a failed resonance check: the nearest design that passes, over what a designer can change.

Searched (the stated ranges, :data:`REMEDY_RANGES`): the tensioner's position along the
slack span (its wheel moved parallel to the chord of the span between its neighbours),
the pretension (the tensioner force), the tensioner's mass and its stiffness. Each
candidate's layout and loads are recomputed (the spans, angles and the slack tension
follow the change), its natural frequencies come from the frequency equation, and it
passes when the tensioner paper's band check holds with the margin
:data:`REQUIRED_MARGIN` and the polygon's forced response stays within
:data:`~chaindrive.vibration.excitation.AMPLIFICATION_LIMIT`. The nearest passing
candidate (distance: each change relative to its range, root of the sum of squares) is
verified by the full vibration analysis of the changed drive and returned as a
:class:`~chaindrive.drive.model.Drive`; ``analyze -o DIR`` writes it to
``DIR/proposal.toml``. When none passes, the candidate with the best margin is returned
with the reason.

Guides or supports in the span (which shorten the free length) are not searched.

The declared part ``remedy`` (needs ``vibration``; about 1.5 s when the check fails, so a
per-keystroke caller may ``exclude=["remedy"]``) is shown in the vibration section.
"""

from __future__ import annotations

import dataclasses
import math
from typing import TYPE_CHECKING, Any

import numpy as np

from .._results import Result, quantity
from ..drive.model import Drive
from ..errors import ChainDriveError
from ..vibration import TensionerSpan, excitation_multipliers, tensioner_frequencies
from ..vibration.excitation import AMPLIFICATION_LIMIT
from .parts import Part, PartContext, register_part

if TYPE_CHECKING:
    from .vibration import DriveVibration

__all__ = ["REMEDY_RANGES", "REQUIRED_MARGIN", "Remedy", "search_remedy"]

#: What the search may change, relative to the design: mass and stiffness factors,
#: tensioner-force factor, shift of the tensioner wheel along the span's chord as a
#: fraction of the chord (a designer's practical range: a tensioner of 1/4 to 4 times the
#: mass, springs of 1/10 to 10 times the rate, half to twice the pretension, within
#: the outer thirds of the span).
REMEDY_RANGES = {"mass": (0.25, 4.0), "stiffness": (0.1, 10.0), "force": (0.5, 2.0), "shift": (-0.3, 0.3)}
#: Smallest band margin of a proposal (5 %: away from the band edge, robust to tolerances).
REQUIRED_MARGIN = 0.05
_GRID = {"mass": 9, "stiffness": 9, "force": 5, "shift": 7}


@dataclasses.dataclass(frozen=True)
class Remedy(Result):
    """The nearest design that passes the resonance check, or the nearest one found.

    Attributes
    ----------
    found : bool
        A candidate within :data:`REMEDY_RANGES` passes.
    drive : Drive
        The proposed (or the nearest) design.
    changes : tuple of str
        What changed, in words with the old and new values.
    margin : float
        Worst band margin of the proposal [-] (> 0 outside the band).
    amplification : float
        Largest amplification of the polygon's forced response of the proposal [-].
    distance : float
        Size of the change (each change over its range, root sum of squares) [-].
    reason : str
        Why nothing passes (empty when found).
    ranges : str
        The ranges searched, in words.
    """

    found: bool
    drive: Drive
    changes: tuple[str, ...]
    margin: float = quantity("1")
    amplification: float = quantity("1")
    distance: float = quantity("1")
    reason: str = ""
    ranges: str = ""


def _ranges_text() -> str:
    r = REMEDY_RANGES
    return (f"tensioner mass ×{r['mass'][0]:g}…×{r['mass'][1]:g}, stiffness ×{r['stiffness'][0]:g}…×"
            f"{r['stiffness'][1]:g}, force (pretension) ×{r['force'][0]:g}…×{r['force'][1]:g}, position along "
            f"the span ±{100 * r['shift'][1]:.0f} % of its chord")


def _moved(drive: Drive, shift: float, force_factor: float) -> Drive:
    """The drive with the tensioner wheel moved along the chord and its force scaled."""
    t = drive.tensioner
    assert t is not None
    n = len(drive.wheels)
    i = drive.wheel_index(t.wheel)
    a, b = np.asarray(drive.wheels[(i - 1) % n].position), np.asarray(drive.wheels[(i + 1) % n].position)
    pos = np.asarray(drive.wheels[i].position) + shift * (b - a)
    wheels = list(drive.wheels)
    wheels[i] = dataclasses.replace(wheels[i], position=(float(pos[0]), float(pos[1])))
    force = None if t.force is None else t.force * force_factor
    return dataclasses.replace(drive, wheels=tuple(wheels), tensioner=dataclasses.replace(t, force=force))


def _span(drive: Drive, layout_cache: dict[float, Any], shift: float) -> TensionerSpan | None:
    """The slack span of a moved drive (its layout cached by shift; None where the tensioner
    paper's coupling does not apply or the layout fails)."""
    from .layout import drive_layout
    from .loads import drive_loads
    from .vibration import COUPLING_LIMIT_ANGLE, tensioner_span

    try:
        if shift not in layout_cache:
            layout_cache[shift] = drive_layout(drive)
        layout = layout_cache[shift]
        span = tensioner_span(drive, layout, drive_loads(drive, layout))
    except ChainDriveError:
        return None
    if span is None or max(span.angle_1, span.angle_2) > COUPLING_LIMIT_ANGLE:
        return None
    return span


def _verdict(drive: Drive, layout: Any, span: TensionerSpan) -> tuple[bool, float, float, str]:
    """(passes, worst band margin, worst polygon amplification, why not) of one design."""
    from .vibration import MODES, _severity, excitation_kwargs

    check = span.check(float(drive.speed), modes=MODES, **excitation_kwargs(drive))
    severity = _severity(drive, layout, span)
    margin = float(np.min(check.margin))
    amp = max((s.amplification for s in severity if s.criterion == "response"), default=0.0)
    ok = margin > REQUIRED_MARGIN and all(s.passed is not False for s in severity)
    why = []
    worst = min(check.rows(), key=lambda r: r["margin"])
    if worst["margin"] <= REQUIRED_MARGIN:
        why.append(f"mode {worst['mode']} ({worst['natural_frequency']:.4g} rad/s) stays within "
                   f"{100 * REQUIRED_MARGIN:.0f} % of the band of the {worst['excitation']} excitation "
                   f"({worst['exciting_frequency']:.4g} rad/s, P/ω = {worst['ratio']:.3f})")
    for s in severity:
        if s.passed is False:
            why.append(f"the {s.name} excitation ({s.frequency:.4g} rad/s) is amplified {s.amplification:.3g}× "
                       f"(limit {AMPLIFICATION_LIMIT:.3g}×)")
    return ok, margin, amp, "; ".join(why)


def search_remedy(drive: Drive, vib: DriveVibration) -> Remedy | None:
    r"""The nearest design within :data:`REMEDY_RANGES` that passes the resonance check.

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
    Grid: 9 masses × 9 stiffnesses (geometric) × 5 forces × 7 positions. Frequencies of
    every (mass, stiffness) at once for each (force, position) from its own layout and
    loads; candidates are then taken in order of distance and the first one whose full
    vibration analysis passes (band margin > :data:`REQUIRED_MARGIN`, polygon within its
    amplification limit) is returned.
    """
    if drive.tensioner is None or vib.span is None:
        return None
    from .vibration import MODES, excitation_kwargs

    t0 = drive.tensioner
    m0, c0 = float(t0.mass), float(t0.stiffness)
    rng = REMEDY_RANGES
    fm = np.geomspace(*rng["mass"], _GRID["mass"]) if m0 > 0 else np.array([1.0])
    fc = np.geomspace(*rng["stiffness"], _GRID["stiffness"]) if 0 < c0 < math.inf else np.array([1.0])
    ff = np.geomspace(*rng["force"], _GRID["force"]) if t0.force else np.array([1.0])
    fs = np.linspace(*rng["shift"], _GRID["shift"])
    kw = excitation_kwargs(drive)
    mult = np.array(list(excitation_multipliers(kw["ratio"], kw["teeth"], link_chain=kw["link_chain"]).values()))
    omega = float(drive.speed)
    lo, hi = 0.7, 1.4
    layouts: dict[float, Any] = {}
    spans: dict[tuple[float, float], TensionerSpan] = {}
    candidates = []
    for force in ff:
        for shift in fs:
            sp = _span(_moved(drive, float(shift), float(force)), layouts, float(shift))
            if sp is None:
                continue
            spans[float(force), float(shift)] = sp
            p = tensioner_frequencies(sp.tension, sp.mass_per_length, sp.length_1, sp.length_2, sp.angle_1,
                                      sp.angle_2, m0 * fm[:, None], c0 * fc[None, :], modes=MODES, model=sp.model)
            r = p[..., None] / (mult * omega)
            margin = np.min(np.maximum(r / hi - 1.0, 1.0 - r / lo), axis=(-1, -2))
            for i, a in enumerate(fm):
                for j, c in enumerate(fc):
                    d = math.sqrt((math.log(a) / math.log(rng["mass"][1])) ** 2
                                  + (math.log(c) / math.log(rng["stiffness"][1])) ** 2
                                  + (math.log(force) / math.log(rng["force"][1])) ** 2
                                  + (shift / rng["shift"][1]) ** 2)
                    candidates.append((d, float(margin[i, j]), float(a), float(c), float(force), float(shift)))
    if not candidates:
        return None

    def design(cand: tuple) -> tuple[Drive, TensionerSpan]:
        _, _, a, c, force, shift = cand
        new = _moved(drive, shift, force)
        assert new.tensioner is not None
        new = dataclasses.replace(new, tensioner=dataclasses.replace(new.tensioner, mass=m0 * a, stiffness=c0 * c))
        return new, dataclasses.replace(spans[force, shift], mass=m0 * a, stiffness=c0 * c)

    best: tuple | None = None
    best_score = -math.inf
    tried = 0
    for cand in sorted(candidates, key=lambda x: x[0]):
        if cand[1] <= REQUIRED_MARGIN or tried >= 40:
            continue
        tried += 1
        new, span = design(cand)
        ok, mg, amp, why = _verdict(new, layouts[cand[5]], span)
        if ok:
            return Remedy(True, new, _changes(drive, new, cand[5]), mg, amp, cand[0], "", _ranges_text())
        score = min(mg, 1.0 - amp / 2.0)
        if score > best_score:
            best, best_score = (cand, new, mg, amp, why), score
    if best is None:  # nothing even clears the band: the candidate with the best band margin
        cand = max(candidates, key=lambda x: x[1])
        new, span = design(cand)
        ok, mg, amp, why = _verdict(new, layouts[cand[5]], span)
        best = (cand, new, mg, amp, why)
    cand, new, mg, amp, why = best
    return Remedy(False, new, _changes(drive, new, cand[5]), mg, amp, cand[0], why or "no candidate could be analysed",
                  _ranges_text())


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
        ctx.note(f"no design within the searched ranges ({found.ranges}) passes the resonance check: {found.reason}")
    return found


register_part(Part("remedy", "A design that passes the resonance check", _remedy_part, needs=("vibration",),
                   order=51, section="chaindrive.workflows.sections:vibration_section"))
