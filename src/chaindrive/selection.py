r"""Selection of roller chains from the catalogue (ANSI/ACA rating), and the rating re-exported.

:func:`select` ranks the catalogue chains that carry a power (the older door; the design
procedure :func:`chaindrive.design.design_drive` is the one the command line, the studio
and studies call). The rating itself lives in :mod:`chaindrive.rating`
(:mod:`chaindrive.rating.ansi`); its names are re-exported here for existing callers.
Sources: ``docs/rating.md``, ``docs/design.md``.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Protocol, TypeVar

from ._finite import finite_guard
from ._results import Result, quantity
from ._validation import check_positive, check_teeth
from .errors import InfeasibleError, InputError, ValidityRangeWarning
from .rating import ChainRating, _scalar, chain_rating
from .rating import ansi as _ansi
from .rating.ansi import *  # noqa: F403 - re-exported for existing callers
from .units import angular_velocity_to_rpm

if TYPE_CHECKING:
    from .chains import Chain

__all__ = [
    "ChainRating",
    "chain_rating",
    "Candidate",
    "ChainChoice",
    "select",
]
# the rating's names, re-exported for existing callers (one list: chaindrive.rating.ansi's)
__all__ += _ansi.__all__


# --------------------------------------------------------------------------- selection

#: Default centre distance of :func:`select` [pitches] (ISO 10823: 30 … 50 pitches).
DEFAULT_CENTRE_PITCHES = 40


def _outside_diameter(pitch: float, teeth: int) -> float:
    # ANSI B29.1 sprocket outside diameter, OD = p (0.6 + cot(180°/N))
    return pitch * (0.6 + 1.0 / math.tan(math.pi / teeth))


@dataclass(frozen=True)
class ChainChoice(Result):
    """A catalogue chain that carries a duty, with the duty and the chain's rated power: what
    a row of :func:`select` (:class:`Candidate`) and of :func:`chaindrive.design.design_drive`
    (:class:`~chaindrive.design.DesignCandidate`) have in common.

    Attributes
    ----------
    chain : str
        Chain name (the ISO 606 name when the chain also has an ANSI number).
    names : tuple of str
        Every catalogue name of this chain, e.g. ``("10A-1", "ANSI 50-1")``.
    family : str
        Catalogue family of ``chain``.
    pitch : float
        [m].
    strands : int
    speed : float
        Small (driving) sprocket speed [rad/s].
    power : float
        Transmitted power [W].
    service_factor : float
    design_power : float
        Power times service factor [W].
    rated_power : float
        Rating of the chain (all strands) [W].
    power_margin : float
        ``rated_power / design_power`` [-] (>= 1 for a chain that carries the duty).
    chain_speed : float
        [m/s].
    """

    chain: str
    names: tuple[str, ...]
    family: str
    pitch: float = quantity("m", display="mm")
    strands: int = quantity("1")
    speed: float = quantity("rad/s", display="rpm")
    power: float = quantity("W")
    service_factor: float = quantity("1")
    design_power: float = quantity("W")
    rated_power: float = quantity("W")
    power_margin: float = quantity("1")
    chain_speed: float = quantity("m/s")


@dataclass(frozen=True)
class Candidate(ChainChoice):
    """One chain that carries the load (a row of :func:`select`): the fields of
    :class:`ChainChoice` (``rated_power``: the ANSI/ACA rating, galling included) and these.

    Attributes
    ----------
    teeth_driving, teeth_driven : int
    governing_limit : str
        ``"link_plate"``, ``"roller_bushing"`` or ``"galling"``.
    working_tension : float
        Design pull plus centrifugal tension [N].
    static_safety : float or None
        Breaking force / working tension [-] (``None``: breaking force unknown).
    galling_speed : float
        Small-sprocket speed at which galling starts at the design tension [rad/s].
    lubrication : str
        ANSI lubrication region ``"A"``, ``"B"``, ``"C"``, or ``"C'"`` (galling region:
        the design needs the manufacturer's evaluation; such rows rank last).
    lubrication_method : str
    centre_distance : float
        Centre distance for ``links`` (ISO 10823 approximation) [m].
    links : int
        Chain length [pitches], even.
    notes : tuple of str
    """

    teeth_driving: int = quantity("1")
    teeth_driven: int = quantity("1")
    governing_limit: str
    working_tension: float = quantity("N")
    static_safety: float | None = quantity("1")
    galling_speed: float = quantity("rad/s")
    lubrication: str
    lubrication_method: str
    centre_distance: float = quantity("m")
    links: int = quantity("1")
    notes: tuple[str, ...]


def _series(chain: Chain) -> str:
    """Proportion series: ``"B"`` (ISO B) or ``"A"`` (ISO A/C = ANSI numbers)."""
    return "B" if chain.family == "iso606" and "B" in chain.name else "A"


class _SizedRow(Protocol):
    """What :func:`_smallest_per_series` reads of a row (a :class:`Candidate`, a design candidate)."""

    @property
    def chain(self) -> str: ...
    @property
    def strands(self) -> int: ...
    @property
    def lubrication(self) -> str: ...
    @property
    def pitch(self) -> float: ...


_Row = TypeVar("_Row", bound=_SizedRow)


def _smallest_per_series(rows: list[_Row]) -> list[_Row]:
    """Of ``rows`` (sorted outside the galling region first, then by pitch), per proportion
    series and strand count: the smallest adequate pitch outside the galling region, or, when
    every adequate chain of the group galls, the smallest (shared by :func:`select_chains` and
    :func:`chaindrive.design.design_drive`)."""
    from .chains import get

    def key(c: _Row) -> tuple[str, int]:
        return _series(get(c.chain)), c.strands

    smallest: dict[tuple[str, int], tuple[bool, float]] = {}
    for c in rows:
        smallest.setdefault(key(c), (c.lubrication == "C'", c.pitch))
    return [c for c in rows if smallest[key(c)] == (c.lubrication == "C'", c.pitch)]


@finite_guard
def select(power: float, speed: float, ratio: float, *, service_factor: float = 1.0,
           teeth_driving: int = 17, centre_distance: float | None = None, family: str | None = None,
           strands: tuple[int, ...] = (1, 2, 3), min_static_safety: float = 6.0,
           all_sizes: bool = False, limit: int | None = None) -> list[Candidate]:
    r"""Roller chains that carry a power with the required safety, simplex first (deprecated).

    .. deprecated:: 0.2
        Use :func:`chaindrive.design.design_drive`, the design procedure that ``chaindrive
        select``, the studio and studies run: this older screen takes ``K_s = 1`` and 17
        teeth unless told, and its static safety ``F_B / (K_s P / v + q v²)`` is not the
        analysis's (which adds the slack-side and the polygonal dynamic tension), so it can
        rank and pass another chain than the one design procedure. It warns
        (``FutureWarning``) and is removed in the next release.

    .. math:: K_2 \min(H_1, H_2, H_3) \ge K_s P,\qquad
              \frac{F_B}{K_s P / v + q v^2} \ge S_{min},\qquad
              X = 2\left\lceil \tfrac{1}{2}\left(\tfrac{2a}{p} + \tfrac{z_1+z_2}{2}
              + \left(\tfrac{z_2-z_1}{2\pi}\right)^2\tfrac{p}{a}\right)\right\rceil

    Parameters
    ----------
    power : float
        Transmitted power ``P > 0`` [W].
    speed : float
        Speed of the driving (small) sprocket [rad/s].
    ratio : float
        Speed ratio ``n1/n2 >= 1``; the driven wheel gets ``round(z1 · ratio)`` teeth.
    service_factor : float
        ``K_s >= 1`` (see :func:`chaindrive.loads.service_factor`).
    teeth_driving : int
        Small-sprocket teeth (the ANSI tables are built on 17).
    centre_distance : float, optional
        Wanted centre distance [m]; default 40 pitches of each chain (ISO 10823:
        30 … 50). Chains whose sprockets would overlap there are left out.
    family : {None, "ansi", "iso606"} or str
        Catalogue family; ``None`` takes every roller-chain family (an ANSI chain and
        its ISO 606 twin being one row with both names), a further family
        (:func:`chaindrive.chains.register_family`) by its name.
    strands : tuple of int
        Strand counts admitted (1 … 4).
    min_static_safety : float
        Required ``F_B / F`` (Diamond Chain: working load <= 1/6 of the breaking force).
    all_sizes : bool
        ``False`` (default): per proportion series (ISO B; ISO A = ANSI) and strand
        count only the smallest adequate pitch outside the galling region (the
        smallest galling one when none is outside). ``True``: every adequate chain.
    limit : int, optional
        Return at most this many candidates.

    Returns
    -------
    list of Candidate
        Ranked: rows outside the galling region first; then simplex before duplex
        before triplex; within a strand count by pitch (smallest first), then by
        static safety (largest first).

    Raises
    ------
    InputError
        Non-positive or non-finite power/speed/centre distance/minimum static safety,
        ratio < 1, service factor < 1, a strand count outside 1 … 4.
    UnknownNameError
        Unknown family.
    InfeasibleError
        No catalogue chain carries the load.

    Notes
    -----
    Only roller chains. The galling limit (Shigley §17-5) is checked at the design
    tension; a chain in the galling region (type C') stays in the list, last, as the
    ANSI tables keep it with "submit the design to the manufacturer". Chains without a
    mass per length are checked with the centrifugal tension omitted and without a
    breaking force with the static check omitted (both noted). The chain length is the
    ISO 10823 approximation rounded up to an even number of links; the centre distance
    is that of the rounded length (``chaindrive layout`` gives the exact polygon value).

    References
    ----------
    ACA and ISO 10823 rating methods, each chain by its family's (:func:`chain_rating`);
    Shigley, 10th ed., §17-5 (selection
    procedure, eqs (17-34), (17-35)); ISO 10823:2004 (centre distance 30 … 50 pitches,
    chain length); ANSI B29.1 sprocket outside diameter ``p (0.6 + cot(180°/z))``.

    Examples
    --------
    >>> import warnings
    >>> with warnings.catch_warnings():
    ...     warnings.simplefilter("ignore", FutureWarning)
    ...     rows = select(7.5e3, 1450 * math.pi / 30, 3.0)
    >>> [(c.chain, c.strands, round(c.power_margin, 2)) for c in rows][:3]
    [('10B-1', 1, 1.61), ('10A-1', 1, 1.47), ('08B-2', 2, 1.4)]
    >>> rows[1].names, rows[1].links, rows[1].lubrication
    (('10A-1', 'ANSI 50-1'), 116, 'B')
    """
    warnings.warn("chaindrive.selection.select is deprecated and will be removed: use "
                  "chaindrive.design.design_drive (the one design procedure of select, the studio and "
                  "studies; the service factor from a duty class, the analysis's static safety)",
                  FutureWarning, stacklevel=2)
    from .chains import catalogue, check_roller_family, equivalent_names
    from .layout import centre_distance_approx, chain_length_approx, even_links

    P = _scalar("power", power, check_positive, "W")
    w = _scalar("speed", speed, check_positive, "rad/s")
    i = _scalar("ratio", ratio, check_positive, "-")
    if i < 1:
        raise InputError(f"ratio must be >= 1 (n_driving / n_driven), got {i:g}")
    ks = _scalar("service_factor", service_factor, check_positive, "-")
    if ks < 1:
        raise InputError(f"service_factor must be >= 1, got {ks:g}")
    z1 = int(_scalar("teeth_driving", teeth_driving, lambda n, v, u: check_teeth(n, v), "whole number >= 3"))
    z2 = int(round(z1 * i))
    a_wanted = None if centre_distance is None else _scalar("centre_distance", centre_distance, check_positive, "m")
    s_min = _scalar("min_static_safety", min_static_safety, check_positive, "-")
    fams = check_roller_family(family)
    allowed = tuple(strands)
    if not allowed or any(isinstance(k, bool) or k not in (1, 2, 3, 4) for k in allowed):
        raise InputError(f"strands must be a non-empty selection of 1, 2, 3, 4, got {strands!r}")
    design = P * ks
    found: dict[str, Candidate] = {}
    too_close: list[str] = []
    for fam in fams:
        for ch in catalogue(fam):
            if ch.strands not in allowed:
                continue
            twins = equivalent_names(ch)
            if family is None and ch.family == "ansi" and twins:
                continue  # one row per chain: the ISO 606 twin carries both names
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", ValidityRangeWarning)
                r = chain_rating(ch, z1, w, power=design)
            if r.rated_power < design:
                continue
            v = r.chain_speed
            notes = ["ISO B series rated with the ANSI A-series constants (approximation)"
                     for n in r.warnings if "B-series" in n]
            if not 9 <= z1 <= 45:
                notes.append(f"{z1} teeth: outside the 9-45 teeth of the ANSI/ACA tables")
            if r.galling_exceeded:
                notes.append(f"galling region above {angular_velocity_to_rpm(r.galling_speed):.4g} rpm: submit to the "
                             "chain manufacturer")
            fc = 0.0
            if ch.mass_per_length is None:
                notes.append("mass per length unknown: centrifugal tension omitted")
            else:
                fc = ch.mass_per_length * v**2
            F = design / v + fc
            sf = None if ch.breaking_force is None else ch.breaking_force / F
            if sf is not None and sf < s_min:
                continue
            if sf is None:
                notes.append("breaking force unknown: static safety not checked")
            a = DEFAULT_CENTRE_PITCHES * ch.pitch if a_wanted is None else a_wanted
            clearance = (_outside_diameter(ch.pitch, z1) + _outside_diameter(ch.pitch, z2)) / 2
            if a <= clearance:
                too_close.append(f"{ch.name} (needs > {clearance * 1e3:.0f} mm)")
                continue
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", ValidityRangeWarning)
                links = int(even_links(chain_length_approx(ch.pitch, z1, z2, a)))
                a_links = float(centre_distance_approx(ch.pitch, z1, z2, links))
            if a_wanted is not None and not 30 <= a / ch.pitch <= 80:
                notes.append(f"centre distance {a / ch.pitch:.0f} pitches (ISO 10823: 30-50, at most 80)")
            if z2 > 120:
                notes.append(f"{z2} teeth on the driven wheel (Shigley §17-5: standard sprockets up to 120)")
            found[ch.name] = Candidate(
                chain=ch.name, names=(ch.name, *twins), family=ch.family, pitch=ch.pitch,
                strands=ch.strands, teeth_driving=z1, teeth_driven=z2, speed=w, power=P,
                service_factor=ks, chain_speed=v, rated_power=r.rated_power, design_power=design,
                power_margin=r.rated_power / design, governing_limit=r.governing_limit,
                working_tension=F, static_safety=sf, galling_speed=r.galling_speed,
                lubrication=r.lubrication, lubrication_method=r.lubrication_method,
                centre_distance=a_links, links=links, notes=tuple(notes),
            )
    if not found:
        extra = f"; sprockets too large for the centre distance: {', '.join(too_close[:4])}" if too_close else ""
        raise InfeasibleError(
            f"no catalogue roller chain carries {design / 1e3:g} kW (design power) at "
            f"{angular_velocity_to_rpm(w):g} rpm with {z1} teeth{extra}; try more teeth, more strands, a lower "
            "speed or a longer centre distance"
        )
    rows = sorted(found.values(), key=lambda c: (c.lubrication == "C'", c.strands, c.pitch,
                                                 -(c.static_safety or 0.0), c.chain))
    if not all_sizes:
        rows = _smallest_per_series(rows)
    return rows[:limit] if limit else rows


def _toml_string(text: str) -> str:
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def __getattr__(name: str) -> Any:
    """``candidate_project``, moved to :func:`chaindrive.drive.writer.candidate_project_text` (the
    writer of project files belongs to the drive description, above this formula module):
    a deprecated alias, removed in the next release."""
    if name == "candidate_project":
        import importlib

        from ._deprecation import alias

        function = importlib.import_module("chaindrive.drive.writer").candidate_project_text
        return alias(function, "chaindrive.selection.candidate_project")
    raise AttributeError(f"module 'chaindrive.selection' has no attribute {name!r}")
