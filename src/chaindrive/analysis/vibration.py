"""Span vibration of a drive and the resonance check (tensioner paper; Wickert & Mote 1990)."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TypedDict

import numpy as np

from .._results import Result, quantity
from ..drive.model import Drive
from ..errors import ChainDriveError
from ..vibration import (
    ResonanceCheck,
    SafeTensioner,
    SpanVibration,
    TensionerSpan,
    excitation_frequencies,
    moving_string_frequencies,
    resonance_check,
    span_vibration,
)
from ..vibration.excitation import (
    AMPLIFICATION_LIMIT,
    DAMPING_RATIO,
    ExcitationResponse,
    span_excitations,
)
from ._memo import memo
from .checks import Check
from .layout import DriveLayout, span_inclination
from .loads import DriveLoads
from .parts import Part, PartContext, register_part

__all__ = ["RESPONSE_SOURCE", "worst_response", "COUPLING_LIMIT_ANGLE", "CAMPBELL_RANGE", "PROPOSAL_RANGE", "excitation_kwargs", "FreeSpans", "DriveVibration", "tensioner_span", "drive_vibration"]

#: Largest inclination of a span part to the normal of the tensioner's axis for which the
#: tensioner paper's coupling is used [rad]. Beyond it the tensioner moves almost along the
#: chain, its coupling to the transverse motion (∝ sin β) dominates the string, and the
#: spans are analysed as free strings instead.
COUPLING_LIMIT_ANGLE = math.radians(60.0)
#: Speed range of the Campbell diagram, relative to the driving speed.
CAMPBELL_RANGE = (0.5, 1.5)
#: Speed range over which a proposed tensioner must be free of resonance, relative.
PROPOSAL_RANGE = (0.9, 1.1)
MODES = 3


@dataclass(frozen=True)
class FreeSpans(Result):
    """Tight and slack spans as axially moving strings (no tensioner coupling).

    Attributes
    ----------
    names : tuple of str
        ``"tight span mode 1"``, ...
    lengths, running_tensions : dict
        Per span role [m], [N].
    frequencies : ndarray
        Natural frequencies in the order of ``names`` [rad/s].
    check : ResonanceCheck
        The 0.7…1.4 band applied to them (information).
    """

    names: tuple[str, ...]
    lengths: dict[str, float] = quantity("m")
    running_tensions: dict[str, float] = quantity("N")
    frequencies: np.ndarray = quantity("rad/s", display="Hz")
    check: ResonanceCheck

    @property
    def pairs_in_band(self) -> list[dict]:
        return [r for r in self.check.rows() if not r["ok"]]


@dataclass(frozen=True)
class DriveVibration(Result):
    """Span vibration of a drive.

    Exactly one of ``tensioner`` (the slack span with its tensioner, the tensioner
    paper's check) and ``free_spans`` (spans as free strings, information) is set.
    ``severity``: every excitation of the slack span with its amplitude and forced
    response (with a tensioner); the verdict ``passed`` is that every response is amplified
    at most :data:`~chaindrive.vibration.excitation.AMPLIFICATION_LIMIT` times (the band
    check ``tensioner.check`` is information). The nearest design that passes when the
    check fails is the part ``remedy`` (:mod:`chaindrive.analysis.vibration_remedy`).
    """

    excitations: dict[str, float] = quantity("rad/s", display="Hz")
    span: TensionerSpan | None
    tensioner: SpanVibration | None
    proposal: SafeTensioner | None
    free_spans: FreeSpans | None
    notes: tuple[str, ...]
    severity: tuple[ExcitationResponse, ...] = ()

    @property
    def passed(self) -> bool | None:
        if self.tensioner is None:
            return None
        return all(s.passed is not False for s in self.severity)


def tensioner_span(drive: Drive, layout: DriveLayout, loads: DriveLoads) -> TensionerSpan | None:
    r"""The slack span split by the tensioner, in the tensioner paper's terms (SI).

    ``length_1, length_2``: the span parts before and after the tensioner wheel;
    ``angle_1, angle_2``: their inclinations β to the line across the tensioner axis
    (normal to its direction of travel); ``tension``: S2, the component of the chain
    tension T across that axis, :math:`S_2 = T \cos\beta`, with the mean ``cos β`` of the
    two parts when they differ (the paper carries one S2 and tension ``S2 / cos β_i`` in
    part i; the real chain has the same T in both).

    ``None`` when the drive has no tensioner.
    """
    if drive.tensioner is None:
        return None
    n = len(drive.wheels)
    idx = drive.wheel_index(drive.tensioner.wheel)
    s_in, s_out = (idx - 1) % n, idx
    d = np.asarray(drive.tensioner.direction, dtype=float)
    d = d / float(np.hypot(*d))
    betas = []
    for j in (s_in, s_out):
        a = layout.wrap.span_angle[j]
        betas.append(float(math.asin(min(1.0, abs(math.cos(a) * d[0] + math.sin(a) * d[1])))))
    T = float(loads.slack)
    S2 = T * 0.5 * (math.cos(betas[0]) + math.cos(betas[1]))
    return TensionerSpan(S2, drive.mass_per_length, float(layout.wrap.span_length[s_in]),
                         float(layout.wrap.span_length[s_out]), betas[0], betas[1],
                         float(drive.tensioner.mass), float(drive.tensioner.stiffness))


class _Excitation(TypedDict):
    """The excitation arguments of :func:`~chaindrive.vibration.excitation_frequencies`."""

    ratio: float
    teeth: int | None
    link_chain: bool


def excitation_kwargs(drive: Drive) -> _Excitation:
    """The excitation arguments of a drive: speed ratio, driving teeth, link chain or not.

    >>> from chaindrive.drive.project import parse_project, template
    >>> excitation_kwargs(parse_project(template("roller")))["teeth"]
    19
    """
    return _Excitation(ratio=drive.speed_ratio(), teeth=drive.driving_wheel.teeth,
                       link_chain=bool(drive.chain.is_link_chain))


#: Old private name of :func:`excitation_kwargs`.
_excitation_kwargs = excitation_kwargs


def _severity(drive: Drive, layout: DriveLayout, span: TensionerSpan) -> tuple[ExcitationResponse, ...]:
    """Every excitation of the slack span with its amplitude and forced response."""
    i = drive.driving_index
    driven = [(j, w) for j, w in enumerate(drive.wheels) if w.teeth is not None and w.kind != "idler" and not w.driving]
    j, wd = max(driven, key=lambda jw: jw[1].teeth or 0) if driven else (i, drive.driving_wheel)
    radii = layout.pitch_radii
    return _span_excitations(span, float(drive.speed), ratio=drive.speed_ratio(),
                             teeth_driving=int(drive.driving_wheel.teeth or 0), teeth_driven=int(wd.teeth or 0),
                             radius_driving=float(radii[i]), radius_driven=float(radii[j]), pitch=drive.pitch,
                             bar_diameter=drive.chain.bar_diameter if drive.chain.is_link_chain else None,
                             damping_ratio=DAMPING_RATIO)


# the tensioner paper's frequencies and the forced responses of a slack span, kept for reuse by
# their inputs (chaindrive.analysis._memo): an edit of another field gives the same span
_span_vibration = memo(maxsize=64)(span_vibration)
_span_excitations = memo(maxsize=64)(span_excitations)


def drive_vibration(drive: Drive, layout: DriveLayout, loads: DriveLoads) -> DriveVibration:
    r"""The tensioner paper's check on the slack span with its tensioner; free spans otherwise.

    With a tensioner whose span parts lie within :data:`COUPLING_LIMIT_ANGLE` of the
    normal to its axis: natural frequencies of the re-derived frequency equation
    (tensioner paper eqs (1)–(12), docs/vibration.md), the paper's band
    :math:`0.7 \le P_i/\omega_j \le 1.4` against its three excitations (driving wheel,
    driven wheel, unequal link lengths; information), the forced response to every
    excitation with its published amplitude (``severity``; the verdict: each amplified at
    most :data:`~chaindrive.vibration.excitation.AMPLIFICATION_LIMIT` times), the Campbell data
    over 0.5…1.5 of the speed (the nearest design that passes is the separate part
    ``remedy``, :func:`~chaindrive.analysis.vibration_remedy.search_remedy`).

    Otherwise the tight and the slack span are axially moving strings (Wickert & Mote 1990)
    with the running tension: the tight tension (which holds ``q v²``) and the slack
    tension plus ``q v²``, projected across the chord by ``cos β`` of the span's
    inclination; their pairs inside the band are reported for information (a sag-controlled
    span's harmonics cover most of a factor-2 band, so a verdict would fail nearly every
    drive).
    """
    omega = float(drive.speed)
    kw = excitation_kwargs(drive)
    exc = excitation_frequencies(omega, **kw)
    notes: list[str] = []
    span = tensioner_span(drive, layout, loads)
    if span is not None and max(span.angle_1, span.angle_2) > COUPLING_LIMIT_ANGLE:
        notes.append(
            "the tensioner moves almost along the chain (span inclination to the normal of its axis "
            f"{math.degrees(max(span.angle_1, span.angle_2)):.0f}° > {math.degrees(COUPLING_LIMIT_ANGLE):.0f}°): "
            "the tensioner paper's coupling does not apply; the spans are analysed as free strings")
        span = None
    if span is not None:
        res = _span_vibration(span, omega, modes=MODES,
                             speed_range=(CAMPBELL_RANGE[0] * omega, CAMPBELL_RANGE[1] * omega), **kw)
        return DriveVibration(exc, span, res, None, None, tuple(notes), _severity(drive, layout, span))
    q = drive.mass_per_length
    v = loads.chain_speed
    names: list[str] = []
    freqs = []
    lengths: dict[str, float] = {}
    running: dict[str, float] = {}
    for j, role, T in ((layout.tight_span, "tight", loads.tight), (layout.slack_span, "slack", loads.slack + loads.centrifugal)):
        L = float(layout.wrap.span_length[j])
        beta = abs(span_inclination(layout.wrap.span_angle[j]))
        try:
            f = np.asarray(moving_string_frequencies(T * math.cos(beta), q, L, chain_speed=v,
                                                     inclination=beta, modes=MODES))
        except ChainDriveError as exc_:  # e.g. chain speed at or above the wave speed
            notes.append(f"{role} span: {exc_}")
            continue
        lengths[role], running[role] = L, float(T)
        freqs.append(f)
        names += [f"{role} span mode {i + 1}" for i in range(len(f))]
    if not freqs:
        return DriveVibration(exc, None, None, None, None, tuple(notes))
    allf = np.concatenate(freqs)
    free = FreeSpans(tuple(names), lengths, running, allf, resonance_check(allf, exc))
    for r in free.pairs_in_band:
        p, w = r["natural_frequency"], r["exciting_frequency"]
        notes.append(f"{names[r['mode'] - 1]} ({p / (2 * math.pi):.4g} Hz, {p:.4g} rad/s) lies in the band "
                     f"0.7…1.4 of the {r['excitation']} excitation ({w / (2 * math.pi):.4g} Hz, {w:.4g} rad/s)")
    return DriveVibration(exc, None, None, None, free, tuple(notes))


#: The basis of the span-vibration verdict, as the report prints it.
RESPONSE_SOURCE = ("forced response of the slack span with its tensioner (string model of the tensioner paper's "
                   f"frequency equation, structural damping ζ = {DAMPING_RATIO:g} assumed; docs/vibration.md §6a); "
                   "limit: the tensioner paper's band edge P/ω = 1.4 as the amplification of one undamped mode, "
                   "1/(1 − 1/1.4²)")


def worst_response(vib: DriveVibration) -> ExcitationResponse | None:
    """The excitation whose forced response is amplified most (None without a judged one)."""
    judged = [s for s in vib.severity if s.passed is not None]
    return max(judged, key=lambda s: s.amplification) if judged else None


def vibration_checks(vib: DriveVibration) -> tuple[Check, ...]:
    """The span-vibration verdict (with a tensioner) and the paper's band as information.

    The verdict answers "does the span vibrate harmfully?" with the largest amplification
    of the slack span's forced response over every excitation, against
    :data:`~chaindrive.vibration.excitation.AMPLIFICATION_LIMIT`; the search for a remedy
    (:mod:`chaindrive.analysis.vibration_remedy`) uses the same criterion. The tensioner
    paper's band 0.7 ≤ P/ω ≤ 1.4 and, without a tensioner, the free-span pairs inside it
    are information.
    """
    if vib.tensioner is not None and vib.tensioner.check is not None:
        out = []
        worst = worst_response(vib)
        if worst is not None:
            out.append(Check("largest amplification of the slack span's forced response, worst excitation",
                             worst.amplification, AMPLIFICATION_LIMIT, "-", worst.passed, RESPONSE_SOURCE,
                             f"{worst.name} excitation at {worst.frequency / (2 * math.pi):.4g} Hz "
                             f"({worst.frequency:.4g} rad/s): span-end amplitude {worst.end_amplitude * 1e3:.3g} mm "
                             f"→ largest span amplitude {worst.response * 1e3:.3g} mm", relation="<="))
        rows = vib.tensioner.check.rows()
        band = min(rows, key=lambda r: r["margin"])
        out.append(Check("band 0.7 ≤ P/ω ≤ 1.4 of the tensioner paper, worst pair margin (information)", band["margin"],
                         None, "-", None,
                         "tensioner paper, band 0.7 ≤ P/ω ≤ 1.4 for its three excitations; "
                         "margin = max(r/1.4 − 1, 1 − r/0.7); the verdict is the forced response above",
                         f"mode {band['mode']} vs {band['excitation']}: P/ω = {band['ratio']:.3f}", relation="info"))
        return tuple(out)
    if vib.free_spans is not None:
        return (Check("free-span pairs inside the band 0.7 ≤ P/ω ≤ 1.4", float(len(vib.free_spans.pairs_in_band)),
                      None, "pairs", None, "tensioner paper criterion applied to free spans (information)",
                      relation="info"),)
    return ()


# --------------------------------------------------------------------------- declared parts
def _vibration_part(ctx: PartContext) -> DriveVibration:
    vib = drive_vibration(ctx.drive, ctx["layout"], ctx["loads"])
    for text in vib.notes:
        ctx.note(text)
    return vib


register_part(Part("vibration", "Span vibration and the resonance check", _vibration_part, needs=("layout", "loads"),
                   checks=lambda ctx, vib: vibration_checks(vib), order=50,
                   section="chaindrive.workflows.sections:vibration_section"))
