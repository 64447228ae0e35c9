r"""The design procedure of a roller chain drive, once: duty -> chain -> drive -> checks -> advice.

:func:`design_drive` is the one function the Python API, ``chaindrive select``, the
design studio and studies call. The steps and the source of each (docs/design.md):

1. **duty -> service factor** (:func:`chaindrive.design.duty.duty_factors`; ACA / U.S.
   Tsubaki table); the design power ``K_s P``.
2. **tooth-count policy** per chain (:mod:`chaindrive.design.policy`): 19 teeth (ISO
   10823 basis), at least the minimum for the chain speed's lubrication region (Diamond
   Chain), odd, the large wheel at most 120 teeth (U.S. Tsubaki).
3. **rating by the method of the chain's family** (:func:`chaindrive.rating.chain_rating`,
   ``method=`` registry; tooth and strand factors of that method); the chain is adequate
   when its rating carries the design power.
4. **layout**: the wanted centre distance (default 40 pitches, ISO 10823: 30-50) gives the
   chain length rounded up to an even number of links (Shigley eq. (17-34),
   :func:`chaindrive.layout.even_links`); the exact polygon centre distance for those
   links (:func:`chaindrive.layout.centre_distance_polygon`, taut).
5. **the drive is written as a project file and analysed** (layout, loads, rating:
   :func:`chaindrive.analysis.analyze_drive`): the static safety is the analysis's one
   definition (:func:`chaindrive.analysis.loads.static_safety_check`) against the required
   safety of the drive; chains below it are dropped.
6. **ranking**: outside the galling region first, fewer strands, smaller pitch, larger
   static safety; per proportion series (ISO B; ISO A = ANSI) and strand count only the
   smallest adequate pitch unless ``all_sizes``.
7. **advice** (:mod:`chaindrive.design.advice`) for every candidate.
"""

from __future__ import annotations

import functools
import math
import warnings
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from .._results import Result, quantity
from ..analysis._memo import memo
from ..analysis.checks import Check
from ..errors import (
    ChainDriveError,
    InfeasibleError,
    InputError,
    ValidityRangeWarning,
)
from ..loads import mean_chain_speed
from ..selection import ChainChoice
from ..units import angular_velocity_to_rpm
from .duty import Duty, Factor, design_power, duty_factors
from .policy import DEFAULT_CENTRE_PITCHES, default_centre_distance
from .request import DesignRequest

if TYPE_CHECKING:
    from ..chains import Chain
    from ..drive.model import Drive

__all__ = ["DesignCandidate", "DesignResult", "NearMiss", "design_drive", "project_text", "two_sprocket_drive",
           "DEFAULT_CENTRE_PITCHES", "NEAR_MISS_BAND"]



@dataclass(frozen=True)
class DesignCandidate(ChainChoice):
    """One chain that carries the duty, laid out and analysed (a row of :func:`design_drive`):
    the fields of :class:`~chaindrive.selection.ChainChoice` and the layout, the checks and the
    advice."""

    method: str
    limited_by: str
    driving_teeth: int = quantity("1")
    driven_teeth: int = quantity("1")
    links: int = quantity("1")
    centre_distance: float = quantity("m", display="mm")
    lubrication: str = ""
    lubrication_method: str = ""
    static_safety: float | None = quantity("1", default=None)
    required_static_safety: float = quantity("1", default=6.0)
    static_tension: float = quantity("N", default=0.0)
    dynamic_tension: float = quantity("N", default=0.0)
    peak_tension: float = quantity("N", default=0.0)
    peak_tension_limit: float | None = quantity("N", default=None)
    teeth_rule: str = ""
    factors: tuple[Factor, ...] = ()
    checks: tuple[Any, ...] = ()
    advice: tuple[Any, ...] = ()
    notes: tuple[str, ...] = ()
    project_text: str = field(default="", repr=False)
    built: Drive | None = field(default=None, repr=False, compare=False)

    def summary(self) -> dict[str, Any]:
        """The row as JSON data in SI units (the shape of ``select --json``)."""
        return {
            "chain": self.chain, "names": list(self.names), "strands": self.strands, "pitch": self.pitch,
            "driving_teeth": self.driving_teeth, "driven_teeth": self.driven_teeth, "links": self.links,
            "centre_distance": self.centre_distance, "service_factor": self.service_factor,
            "rated_power": self.rated_power, "design_power": self.design_power,
            "power_margin": self.power_margin, "method": self.method, "limited_by": self.limited_by,
            "chain_speed": self.chain_speed, "lubrication": self.lubrication,
            "static_safety": self.static_safety, "required_static_safety": self.required_static_safety,
            "static_tension": self.static_tension, "dynamic_tension": self.dynamic_tension,
            "peak_tension": self.peak_tension, "peak_tension_limit": self.peak_tension_limit,
            "teeth_rule": self.teeth_rule,
            "factors": [f.to_dict() for f in self.factors],
            "advice": [a.to_dict() for a in self.advice], "notes": list(self.notes),
        }

    def drive(self) -> Drive:
        """The candidate's drive (built in code; parsed from its project file when only that is given)."""
        if self.built is not None:
            return self.built
        from ..drive.project import parse_project

        return parse_project(self.project_text, filename="design.toml")


@dataclass(frozen=True)
class DesignResult(Result):
    """The result of :func:`design_drive`: the duty, its factors, the recommended drive and the candidates."""

    duty: Duty
    factors: tuple[Factor, ...]
    recommended: DesignCandidate
    candidates: tuple[DesignCandidate, ...]
    near_misses: tuple[Any, ...] = ()
    request: DesignRequest | None = field(default=None, repr=False, compare=False)

    def drive(self) -> Drive:
        """The recommended drive (:class:`~chaindrive.drive.model.Drive`, built in code)."""
        return self.recommended.drive()

    @property
    def design_power(self) -> float:
        """The design power ``K_s P`` [W] (:func:`chaindrive.design.duty.design_power`)."""
        return design_power(self.duty.power, self.factors[0])

    @property
    def advice(self) -> tuple[Check, ...]:
        """The advice for the recommended drive."""
        return tuple(self.recommended.advice)

    def to_dict(self) -> dict[str, Any]:
        return {"duty": self.duty.to_dict(), "request": None if self.request is None else self.request.to_dict(),
                "factors": [f.to_dict() for f in self.factors],
                "recommended": self.recommended.summary(),
                "candidates": [c.summary() for c in self.candidates],
                "near_misses": [m.summary() for m in self.near_misses]}


def two_sprocket_drive(chain: str | Chain, teeth: tuple[int, int], centre_distance: float, links: int,
                       speed: float, power: float, service_factor: float, *, name: str = "",
                       description: str = "", required_static_safety: float | None = None) -> Drive:
    """The two-sprocket :class:`~chaindrive.drive.model.Drive` of a design, built in code: the
    driving sprocket at the origin, the driven one on the x axis at ``centre_distance`` [m].

    Examples
    --------
    >>> d = two_sprocket_drive("16B-1", (19, 58), 0.6, 84, 152.89, 11e3, 1.3)
    >>> d.links, d.wheels[1].position, d.load.service_factor
    (84, (0.6, 0.0), 1.3)
    """
    from ..chains import get
    from ..drive.model import Drive, Load, Wheel

    c = get(chain) if isinstance(chain, str) else chain
    return Drive(
        chain=c, speed=float(speed), links=int(links),
        load=Load(power=float(power), service_factor=float(service_factor)),
        wheels=(Wheel("driving", "sprocket", int(teeth[0]), (0.0, 0.0), driving=True),
                Wheel("driven", "sprocket", int(teeth[1]), (float(centre_distance), 0.0))),
        name=name or f"{c.name} chain drive, {teeth[0]}/{teeth[1]} teeth", description=description,
        required_static_safety=required_static_safety)


def project_text(chain: str, teeth: tuple[int, int], centre_distance: float, links: int, speed: float,
                 power: float, service_factor: float, *, name: str = "", description: str = "",
                 required_static_safety: float | None = None) -> str:
    """A complete project file (TOML) for a two-sprocket drive on a horizontal line: the
    :func:`two_sprocket_drive` written by :func:`chaindrive.drive.writer.project_text`.

    Examples
    --------
    >>> text = project_text("16B-1", (19, 58), 0.6, 84, 152.89, 11e3, 1.3)
    >>> "links = 84" in text and 'position = ["0.6 m", "0.0 m"]' in text
    True
    """
    return _written(two_sprocket_drive(chain, teeth, centre_distance, links, speed, power, service_factor,
                                       name=name, description=description,
                                       required_static_safety=required_static_safety))


def _written(drive: Drive) -> str:
    """The project file of a designed drive, with its comments."""
    from ..drive.writer import project_text as write

    return write(drive, header="chaindrive project file written by the design procedure (TOML). Quantities "
                               "carry units;\na bare number is refused for them. Check it with:  chaindrive "
                               "analyze <this file>",
                 comments={"drive.speed": "driving (small) sprocket", "drive.links": "even number of pitches",
                           "wheels.1.position": f"exact centre distance for {drive.links} links"})


def _outside_diameter(pitch: float, teeth: int) -> float:
    # ANSI B29.1 sprocket outside diameter, OD = p (0.6 + cot(180°/N))
    return pitch * (0.6 + 1.0 / math.tan(math.pi / teeth))


@memo(maxsize=1024, key=lambda chain, duty, given: (chain.pitch, duty.character, duty.speed_ratio, duty.speed,
                                                     given))
def _teeth_for(chain: Chain, duty: Duty, given: int | None) -> tuple[int, str]:
    """Small-sprocket teeth of a chain for the duty, and why (pure in the pitch, the shock class, the
    ratio, the speed and the given teeth: kept for the chains of equal pitch and the next edit)."""
    from ..rating.ansi import lubrication_region
    from .policy import driving_teeth

    z, why = driving_teeth("A", duty.character, duty.speed_ratio, given=given)
    for _ in range(3):  # the region depends on the teeth through the chain speed
        v = float(mean_chain_speed(z, chain.pitch, duty.speed))
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ValidityRangeWarning)
            region = str(lubrication_region(v, chain.pitch))
        z_new, why = driving_teeth(region, duty.character, duty.speed_ratio, given=given)
        if z_new == z:
            break
        z = z_new
    return z, why


@dataclass(frozen=True)
class _Rated:
    """A chain past steps 2-3 (teeth, rating, room between the sprockets): the rest of
    :func:`_candidate` is its layout and loads."""

    chain: Chain
    twins: tuple[str, ...]
    z1: int
    z2: int
    why: str
    rating: Any
    centre: float


def _candidate(chain: Chain, twins: tuple[str, ...], duty: Duty, factors: tuple[Factor, ...], ks: float,
               given_teeth: int | None, method: str | None, required: float | None) -> DesignCandidate | str | None:
    """One chain through steps 2-5 (``None``: does not carry the load; a string: why it was left out)."""
    rated = _rated(chain, twins, duty, ks, given_teeth, method)
    if rated is None or isinstance(rated, str):
        return rated
    return _laid_out(rated, duty, factors, ks, required)


def _rated(chain: Chain, twins: tuple[str, ...], duty: Duty, ks: float, given_teeth: int | None,
           method: str | None, teeth: tuple[int, str] | None = None,
           short: list[tuple[_Rated, float]] | None = None, centre: float | None = None) -> _Rated | str | None:
    """Steps 2-3 of :func:`_candidate`: teeth (``teeth`` when already chosen), rating, room
    (``None``: does not carry the load; then, when its rating lies within :data:`NEAR_MISS_BAND`
    of the design power, it is appended to ``short`` with its rating ratio). ``centre``: the wanted
    centre distance [m] (default the duty's, else :data:`DEFAULT_CENTRE_PITCHES` pitches)."""
    from .policy import driven_teeth

    z1, why = _teeth_for(chain, duty, given_teeth) if teeth is None else teeth
    z2 = driven_teeth(z1, duty.speed_ratio)
    design = duty.power * ks
    if centre is not None:
        a = centre
    else:
        a = default_centre_distance(chain.pitch) if duty.centre_distance is None else duty.centre_distance
    r = _rating(chain, z1, duty.speed, design, method)
    if r.rated_power < design:
        if short is not None and r.rated_power >= (1.0 - NEAR_MISS_BAND) * design:
            short.append((_Rated(chain, twins, z1, z2, why, r, a), r.rated_power / design))
        return None
    clearance = (_outside_diameter(chain.pitch, z1) + _outside_diameter(chain.pitch, z2)) / 2
    if a <= clearance:
        return f"{chain.name} (needs > {clearance * 1e3:.0f} mm)"
    return _Rated(chain, twins, z1, z2, why, r, a)


@memo(maxsize=2048)
def _rating(chain: Chain, teeth: int, speed: float, power: float, method: str | None) -> Any:
    """:func:`chaindrive.rating.chain_rating` of a chain on ``teeth`` at ``speed`` [rad/s] for the design
    power [W] (its validity-range notes in ``warnings``): pure, kept for the near misses and the next edit."""
    from ..rating import chain_rating

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityRangeWarning)
        return chain_rating(chain, teeth, speed, power=power, method=method)


def _laid_out(rated: _Rated, duty: Duty, factors: tuple[Factor, ...], ks: float,
              required: float | None, dropped: list[tuple[float, str]] | None = None) -> DesignCandidate | None:
    """Steps 4-5 of :func:`_candidate`: links, exact centre distance, loads, static safety."""
    from ..analysis import analyze_drive
    from ..analysis.loads import static_safety_check
    from ..layout import (
        centre_distance_approx,
        centre_distance_polygon,
        chain_length_approx,
        even_links,
    )
    from .advice import drive_advice

    chain, twins, z1, z2, why, r, a = (rated.chain, rated.twins, rated.z1, rated.z2, rated.why, rated.rating,
                                       rated.centre)
    design = duty.power * ks
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityRangeWarning)
        links = int(even_links(chain_length_approx(chain.pitch, z1, z2, a)))
        try:
            exact = float(centre_distance_polygon(chain.pitch, z1, z2, links).taut)
        except InputError:
            exact = float(centre_distance_approx(chain.pitch, z1, z2, links))
    from ..drive.tables import warn_implausible_inputs

    drive = two_sprocket_drive(chain, (z1, z2), exact, links, duty.speed, duty.power, ks,
                               description=f"{chain.name}: rated {r.rated_power / 1e3:.4g} kW ({r.method}) for a "
                                           f"design power of {design / 1e3:.4g} kW", required_static_safety=required)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        warn_implausible_inputs(drive)   # e.g. an implausible chain speed: a note of the row
    text = _written(drive)
    notes = list(dict.fromkeys([*r.warnings, *(str(w.message) for w in caught)]))
    checks: tuple[Check, ...] = ()
    static_value, tensions, peak_limit = None, (0.0, 0.0, 0.0), None
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        try:
            analysis = analyze_drive(drive, include=["layout", "loads", "rating"])
        except ChainDriveError as exc:  # e.g. a chain without a mass per length: no loads
            notes.append(f"static safety not computed: {exc}")
        else:
            loads = analysis.loads
            assert loads is not None
            static = static_safety_check(drive, loads)
            if static.value is not None and static.passed is False:
                if dropped is not None:
                    dropped.append((static.value / drive.static_safety_required,
                                    f"{chain.name} ({z1}/{z2} teeth) has a static safety of {static.value:.3g} "
                                    f"< {static.limit:.4g} required (Chernavsky et al. Table 7.19)"))
                return None
            static_value, checks = static.value, analysis.checks
            tensions = (loads.tight, loads.dynamic, loads.maximum)
            peak_limit = next((float(c.limit) for c in checks
                               if c.name == "peak tension" and isinstance(c.limit, (int, float))), None)
    from ..rating.ansi import multi_strand_factor

    cand_factors = factors + (
        Factor("multi-strand factor", "K_2", multi_strand_factor(chain.strands),
               "ACA; Shigley, 10th ed., Table 17-23 (ISO 10823:2004: the same 1, 1.7, 2.5)"),
        _tooth_factor(r.method, r.governing_limit, z1, why),
    )
    return DesignCandidate(
        chain=chain.name, names=(chain.name, *twins), family=chain.family, pitch=chain.pitch,
        strands=chain.strands, driving_teeth=z1, driven_teeth=z2, links=links, centre_distance=exact,
        speed=duty.speed, power=duty.power, service_factor=ks, design_power=design, rated_power=r.rated_power,
        power_margin=r.rated_power / design, method=r.method, limited_by=r.limited_by,
        chain_speed=r.chain_speed, lubrication=r.lubrication, lubrication_method=r.lubrication_method,
        static_safety=static_value, required_static_safety=drive.static_safety_required,
        static_tension=tensions[0], dynamic_tension=tensions[1], peak_tension=tensions[2],
        peak_tension_limit=peak_limit, teeth_rule=why, factors=cand_factors,
        checks=checks, advice=drive_advice(duty, r, centre_pitches=exact / chain.pitch), notes=tuple(notes), project_text=text,
        built=drive)


_MESSAGE_UNITS = {"rad/s": (1.0 / angular_velocity_to_rpm(1.0), "rpm"), "W": (1e3, "kW"), "N": (1e3, "kN"),
                  "Pa": (1e6, "MPa"), "rad": (math.pi / 180, "°")}


def _failed(candidate: DesignCandidate) -> list[str]:
    """The checks a candidate fails, as ``name: value (limit ...)`` texts (empty: it passes every check)."""
    def text(x: float, unit: str) -> str:
        scale, shown = _MESSAGE_UNITS.get(unit, (1.0, "" if unit in ("1", "-", "") else unit))
        return f"{x / scale:.4g} {shown}".strip()

    out = []
    if not candidate.checks:   # the analysis could not run (e.g. no mass per length): nothing is verified
        if candidate.lubrication == "C'":
            out.append("speed below the galling limit (galling region, type C')")
        out.append("static safety: not computed (" + "; ".join(
            n.removeprefix("static safety not computed: ") for n in candidate.notes
            if n.startswith("static safety not computed")) + ")")
    for c in candidate.checks:
        if c.passed is not False:
            continue
        value = "not computed" if c.value is None else text(c.value, c.unit)
        if isinstance(c.limit, tuple):
            limit = f"{text(c.limit[0], c.unit)} … {text(c.limit[1], c.unit)}"
        else:
            limit = "" if c.limit is None else f"{c.relation} {text(c.limit, c.unit)}"
        out.append(f"{c.name}: {value}" + (f" (limit {limit})" if limit else ""))
    return out


def _remedies(failed: list[str], four_strands: bool) -> str:
    """What to try when the nearest candidate fails these checks (texts of :func:`_failed`)."""
    out = []
    if any(f.startswith("speed below the galling limit") for f in failed):
        out.append(("" if four_strands else "more strands (up to 4), ") + "a lower speed, or submit the duty to "
                   "the chain maker (beyond the galling limit the ACA and ISO 10823 ratings do not apply: "
                   "Shigley §17-5, type C')")
    if any(f.startswith("wrap") for f in failed):
        out.append("a longer centre distance, a smaller ratio per stage or an idler for at least 120° of wrap "
                   "on the small sprocket (ISO 10823:2004 guidance)")
    if any("not computed" in f for f in failed):
        out.append("a chain whose catalogue entry has its mass per length (the static safety needs it)")
    if not out:
        out.append("more strands, a lower speed or a longer centre distance")
    return "; or ".join(out)


def _tooth_factor(method: str, governing: str, teeth: int, why: str) -> Factor:
    """The tooth factor of the candidate's rating method, as the rating applied it."""
    if method == "iso10823":
        return Factor("tooth factor", "1/f_2", (teeth / 19.0) ** 1.08,
                      "ISO 10823:2004, 4.2: f_2 = (19/z_1)^1.08 on the 19-tooth chart (one factor for both branches)",
                      note=f"{teeth} teeth: {why}")
    return Factor("tooth factor", "K_1", (teeth / 17.0) ** (1.5 if governing == "roller_bushing" else 1.08),
                  "Shigley, 10th ed., Table 17-22 (relative to the 17-tooth column of the ANSI tables)",
                  note=f"{teeth} teeth: {why}")


#: A chain whose rating falls short of the design power by at most this fraction is a near miss:
#: ``select`` names it with the smallest change that makes it pass (issue 30, item 5).
NEAR_MISS_BAND = 0.05
#: The most teeth a near miss's remedy adds to its small sprocket.
NEAR_MISS_MAX_EXTRA_TEETH = 4


@dataclass(frozen=True)
class NearMiss(Result):
    """A chain whose rating misses the design power by a few per cent, and the smallest change that
    makes it pass every check (re-analysed: ``remedy_candidate`` is the drive with the change)."""

    chain: str
    names: tuple[str, ...]
    driving_teeth: int = quantity("1")
    rating_ratio: float = quantity("1")
    remedy: str = ""
    remedy_candidate: DesignCandidate | None = None

    def summary(self) -> dict[str, Any]:
        """JSON data in SI units (``select --json``, ``near_misses``)."""
        c = self.remedy_candidate
        return {"chain": self.chain, "names": list(self.names), "driving_teeth": self.driving_teeth,
                "rating_ratio": self.rating_ratio, "remedy": self.remedy,
                "remedy_drive": None if c is None else {
                    "driving_teeth": c.driving_teeth, "driven_teeth": c.driven_teeth, "links": c.links,
                    "centre_distance": c.centre_distance, "rated_power": c.rated_power,
                    "power_margin": c.power_margin, "static_safety": c.static_safety,
                    "required_static_safety": c.required_static_safety, "peak_tension": c.peak_tension,
                    "peak_tension_limit": c.peak_tension_limit}}


def _near_misses(short: list[tuple[_Rated, float]], best: DesignCandidate, duty: Duty,
                 factors: tuple[Factor, ...], ks: float, method: str | None,
                 required: float | None) -> tuple[NearMiss, ...]:
    """The near misses lighter than the recommended drive (smaller pitch, or the same pitch in fewer
    strands), each with the smallest remedy that passes every check after re-analysis: one more
    small-sprocket tooth, then two, ... up to :data:`NEAR_MISS_MAX_EXTRA_TEETH` (the large wheel at
    most 120 teeth). A lower service factor is never offered: the duty's shock is what it is; nor a
    lubrication type: the ACA and ISO 10823 ratings do not rise with it (the type is what the
    rating requires)."""
    from .policy import MAXIMUM_DRIVEN_TEETH, driven_teeth

    out = []
    for rated, ratio in sorted(short, key=lambda x: -x[1]):
        ch = rated.chain
        if not (ch.pitch < best.pitch - 1e-12 or (abs(ch.pitch - best.pitch) <= 1e-12 and ch.strands < best.strands)):
            continue
        remedy, found, why = f"no change of up to {NEAR_MISS_MAX_EXTRA_TEETH} more small-sprocket teeth passes", None, ""
        for extra in range(1, NEAR_MISS_MAX_EXTRA_TEETH + 1):
            z = rated.z1 + extra
            if driven_teeth(z, duty.speed_ratio) > MAXIMUM_DRIVEN_TEETH:
                break
            got = _rated(ch, rated.twins, duty, ks, z, method, centre=rated.centre,
                         teeth=(z, f"near-miss remedy: {extra} more "
                                                                         f"tooth{'' if extra == 1 else ' teeth'}"))
            if not isinstance(got, _Rated):
                continue
            cand = _laid_out(got, duty, factors, ks, required)
            if cand is None:
                why = f"with {z} teeth: static safety below the required value"
                continue
            if _failed(cand):
                why = f"with {z} teeth: " + "; ".join(_failed(cand))
                continue
            if not _failed(cand):
                found = cand
                remedy = (f"{z} teeth on the small sprocket instead of {rated.z1} "
                          f"({extra} more), {cand.driven_teeth} on the large: rated {cand.rated_power / 1e3:.4g} kW "
                          f"for {cand.design_power / 1e3:.4g} kW, every check passes")
                break
        if found is None and why:
            remedy += f" ({why})"
        out.append(NearMiss(chain=ch.name, names=(ch.name, *rated.twins), driving_teeth=rated.z1,
                            rating_ratio=float(ratio), remedy=remedy, remedy_candidate=found))
    return tuple(out)


#: Relative margin of the catalogue screen: a chain whose screened rating lies within it
#: below the design power is rated one by one (the screen's vectorised powers may differ
#: from the one-chain rating in the last digits).
SCREEN_MARGIN = 1e-9


def _screened(chains: list[tuple[Chain, int]], speed: float, method: str | None) -> list[float | None]:
    """The rated power [W] of each (chain, teeth) at ``speed`` [rad/s] by the catalogue screen
    (``None``: a chain the screen does not rate): ``K_2 min(H_1, H_2)`` of the ANSI/ACA and ISO 10823
    methods (:func:`chaindrive.rating.branch_powers`: ISO 10823 on its 19-tooth basis times the tooth
    factor) of the whole catalogue in one vectorised call per method. It may differ from the one-chain
    rating (:func:`chaindrive.rating.chain_rating`) in the last digits (:data:`SCREEN_MARGIN`)."""
    from ..rating import branch_powers, default_method
    from ..rating.iso10823 import REFERENCE_TEETH

    basis = {"ansi": None, "iso10823": REFERENCE_TEETH}
    how = [method or default_method(ch) for ch, _ in chains]
    out: list[float | None] = [None] * len(chains)
    import numpy as np

    for name, zb in basis.items():
        at = [i for i, ((ch, _), m) in enumerate(zip(chains, how, strict=True))
              if m == name and ch.is_roller_chain and ch.strands <= 4 and not (zb and ch.family == "custom")]
        if not at:
            continue
        z = np.array([chains[i][1] for i in at], dtype=float)
        p = np.array([chains[i][0].pitch for i in at])
        kp, kr, k2 = np.array([_screen_constants(chains[i][0].name, chains[i][0].strands, name) for i in at]).T
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ValidityRangeWarning)
            h1, h2 = branch_powers(p, z, speed, plate_constant=kp, roller_constant=kr, basis_teeth=zb)
        for i, rated in zip(at, np.minimum(k2 * h1, k2 * h2), strict=True):
            out[i] = float(rated)
    return out


@functools.lru_cache(maxsize=1024)
def _screen_constants(name: str, strands: int, method: str) -> tuple[float, float, float]:
    """``(K_p, K_r, K_2)`` of a catalogue chain by a method (:func:`chaindrive.rating.rating_constants`,
    :func:`chaindrive.rating.ansi.multi_strand_factor`), for :func:`_screened`."""
    from ..rating import rating_constants
    from ..rating.ansi import multi_strand_factor

    return (*rating_constants(name, method), float(multi_strand_factor(strands)))


def _may_carry(chains: list[tuple[Chain, int]], speed: float, design: float, method: str | None,
               band: float = 0.0) -> list[bool]:
    """Whether each (chain, teeth) may carry the design power [W] at ``speed`` [rad/s] (or miss it
    by at most the fraction ``band``: the near misses) by the catalogue screen (:func:`_screened`),
    so that only the chains that may carry it are rated one by one (``chain_rating``).
    A chain rated by another method is always passed on."""
    return [s is None or s >= design * (1.0 - band - SCREEN_MARGIN) for s in _screened(chains, speed, method)]


@dataclass(frozen=True)
class _Pending:
    """A chain the screen shows to carry the design power, rated (step 3) only when the layout
    reaches it (:func:`_lay_out`); ``at``: its place in the catalogue."""

    chain: Chain
    twins: tuple[str, ...]
    teeth: tuple[int, str]
    at: int


def _lay_out(rated: list[_Rated | _Pending], duty: Duty, factors: tuple[Factor, ...], ks: float,
             required: float | None, all_sizes: bool, dropped: list[tuple[float, str]] | None = None,
             rate: Callable[[_Pending], _Rated | str | None] | None = None) -> list[DesignCandidate]:
    """The rated chains laid out and loaded (steps 4-5). Unless ``all_sizes``, only the chains
    that can be kept: per series and strand count, design_drive keeps the adequate chains of
    the smallest (galling region, pitch); they are laid out in that order until one passes
    the static safety, and those of its (galling, pitch) with it. A pending chain is rated
    (``rate``) when it is reached: the chains of a group are taken by pitch, those outside the
    galling region laid out at once, those in it kept for when none outside it passes. The
    candidates are those laying out every chain and filtering afterwards would give."""
    if all_sizes:
        return [c for r in rated if isinstance(r, _Rated)
                and (c := _laid_out(r, duty, factors, ks, required, dropped)) is not None]
    from ..selection import _series

    groups: dict[tuple[str, int], list[_Rated | _Pending]] = {}
    for r in rated:
        groups.setdefault((_series(r.chain), r.chain.strands), []).append(r)
    found: list[DesignCandidate] = []
    for group in groups.values():
        kept: tuple[bool, float] | None = None
        galling: list[_Rated] = []
        for e in sorted(group, key=lambda e: e.chain.pitch):
            if kept is not None and e.chain.pitch != kept[1]:
                break
            got = e if isinstance(e, _Rated) or rate is None else rate(e)
            if not isinstance(got, _Rated):
                continue
            r = got
            if r.rating.lubrication == "C'":
                galling.append(r)
                continue
            if (c := _laid_out(r, duty, factors, ks, required, dropped)) is not None:
                found.append(c)
                kept = (False, r.chain.pitch)
        for r in galling if kept is None else ():  # every chain of the group rated: none outside galling passed
            if kept is not None and r.chain.pitch != kept[1]:
                break
            if (c := _laid_out(r, duty, factors, ks, required, dropped)) is not None:
                found.append(c)
                kept = (True, r.chain.pitch)
    return found


def design_drive(request: DesignRequest | Duty, **options: Any) -> DesignResult:
    r"""Design a two-sprocket roller chain drive for a request: the recommended drive and the candidates.

    .. math:: K_2 P_{r,1}(z_1, n_1) \ge K_s P,\qquad
              \frac{F_B}{K_s F_t + S + q v^2} \ge [s],\qquad F_{peak} \le \frac{F_B}{6},\qquad
              X\ \text{even},\ a = a(X)\ \text{exact}

    Parameters
    ----------
    request : DesignRequest or Duty
        The duty and the constraints of the selection (:class:`~chaindrive.design.request.DesignRequest`:
        small-sprocket teeth, family, strands, rating method, required static safety, all sizes,
        limit); a bare :class:`~chaindrive.design.duty.Duty` is the request ``DesignRequest(duty, **options)``.
    **options
        The constraints when ``request`` is a Duty (the fields of ``DesignRequest`` after ``duty``).

    Returns
    -------
    DesignResult
        ``recommended`` (the first candidate), ``candidates`` and ``drive()`` (the recommended
        :class:`~chaindrive.drive.model.Drive`).

    Raises
    ------
    InputError
        No duty class (the table is in the message), bad strands or teeth.
    UnknownNameError
        Unknown family or method.
    InfeasibleError
        No catalogue chain carries the duty.

    References
    ----------
    docs/design.md (the flow and the source of every step).

    Examples
    --------
    >>> duty = Duty(11e3, 1460 * math.pi / 30, driven_speed=480 * math.pi / 30,
    ...             driven_machine="varying_conveyor", centre_distance=0.6)
    >>> r = design_drive(duty)
    >>> c = r.recommended
    >>> c.chain, c.driving_teeth, c.driven_teeth, c.links, round(c.centre_distance * 1e3, 1)
    ('12A-1', 19, 58, 104, 612.4)
    """
    from ..chains import catalogue, check_roller_family, equivalent_names

    if isinstance(request, Duty):
        request = DesignRequest(request, **options)
    elif not isinstance(request, DesignRequest):
        raise InputError(f"request must be a chaindrive.design.DesignRequest, got {type(request).__name__}",
                         field="request")
    elif options:
        raise InputError(f"give the options in the DesignRequest, not beside it: {', '.join(options)}",
                         field=next(iter(options)))
    duty, teeth_driving, family, allowed = request.duty, request.teeth_driving, request.family, request.strands
    method, required_static_safety = request.method, request.required_static_safety
    all_sizes, limit = request.all_sizes, request.limit
    factors = duty_factors(duty)
    ks = float(factors[0].value)
    fams = check_roller_family(family)
    chains = []
    for fam in fams:
        for ch in catalogue(fam):
            if ch.strands not in allowed:
                continue
            twins = tuple(equivalent_names(ch))
            if family is None and ch.family == "ansi" and twins:
                continue  # one row per chain: the ISO 606 twin carries both names
            chains.append((ch, twins, _teeth_for(ch, duty, teeth_driving)))
    design = duty.power * ks
    screened = _screened([(ch, z[0]) for ch, _, z in chains], duty.speed, method)
    rated: list[_Rated | _Pending] = []
    short: list[tuple[_Rated, float]] = []
    too_close: list[tuple[int, str]] = []

    def rate(e: _Pending) -> _Rated | str | None:
        got = _rated(e.chain, e.twins, duty, ks, teeth_driving, method, e.teeth, short=short,
                     centre=request.wanted_centre(e.chain.pitch))
        if isinstance(got, str):
            too_close.append((e.at, got))
        return got

    for at, ((ch, twins, teeth), power) in enumerate(zip(chains, screened, strict=True)):
        if power is not None and power < design * (1.0 - NEAR_MISS_BAND - SCREEN_MARGIN):
            continue  # neither carries the duty nor misses it by the near-miss band
        pending = _Pending(ch, twins, teeth, at)
        if not all_sizes and power is not None and power >= design * (1.0 + SCREEN_MARGIN):
            rated.append(pending)  # carries the duty: rated when the layout reaches it
        elif isinstance(got := rate(pending), _Rated):
            rated.append(got)
    dropped: list[tuple[float, str]] = []
    found = _lay_out(rated, duty, factors, ks, required_static_safety, all_sizes, dropped, rate)
    if not found:
        close = [text for _, text in sorted(too_close)]
        extra = f"; sprockets too large for the centre distance: {', '.join(close[:4])}" if close else ""
        if dropped:
            extra += "; the nearest, " + max(dropped)[1]
        raise InfeasibleError(
            f"no catalogue roller chain carries {duty.power * ks / 1e3:g} kW (design power) at "
            f"{angular_velocity_to_rpm(duty.speed):g} rpm with the required static safety{extra}; try more strands, "
            "a lower speed or a longer centre distance")
    rows = sorted(found, key=lambda c: (c.lubrication == "C'", c.strands, c.pitch, -(c.static_safety or 0.0),
                                        c.chain))
    if not all_sizes:
        from ..selection import _smallest_per_series

        rows = _smallest_per_series(rows)
    # the recommended drive passes every check (rated power, galling, wrap, static safety computed
    # and met): the first such row, moved to the front; none (in practice: every chain that carries
    # the duty runs in the galling region, type C'): no drive the procedure could defend
    passing = [c for c in rows if not _failed(c)]
    if not passing:
        best = rows[0]
        failed = _failed(best)
        raise InfeasibleError(
            f"no catalogue roller chain carries {duty.power * ks / 1e3:g} kW (design power) at "
            f"{angular_velocity_to_rpm(duty.speed):g} rpm and passes every check: the nearest, {best.chain} "
            f"({best.driving_teeth}/{best.driven_teeth} teeth), fails {'; '.join(failed)}; "
            f"try {_remedies(failed, 4 in allowed)}")
    rows = [passing[0], *(c for c in rows if c is not passing[0])]
    rows = rows[:limit] if limit else rows
    near = _near_misses(short, rows[0], duty, factors, ks, method, required_static_safety)
    return DesignResult(duty=duty, factors=factors, recommended=rows[0], candidates=tuple(rows), near_misses=near,
                        request=request)

