r"""Advice of the design procedure: what a careful engineer would say about a drive.

Each advice is a :class:`~chaindrive.analysis.checks.Check` with relation ``"info"``: the
value that triggers it, the published limit, the source and, in ``note``, what to do:

* **teeth below the minimum for the chain speed** (Diamond Chain FAQ: 12 drip, 17 oil
  bath, 25 pumped lubrication) -- more teeth;
* **the roller–bushing (impact) limit governs** (ACA, Shigley eq. (17-33): the impact
  limit falls as ``n^-1.5 p^0.8``) -- more teeth, or a smaller pitch in several strands;
* **the galling region** (Shigley §17-5, Table 17-20 type C') -- a smaller pitch in
  several strands, or submit to the chain maker;
* **lubrication** -- the lubrication the rating assumes at this chain speed (McGuire
  Bearing Co. table; Shigley Table 17-20), above what the site provides;
* **a dusty or abrasive environment** -- the ratings assume clean, lubricated chains
  (ISO 10823:2004; ACA): enclosed drive or a larger service margin;
* **the centre distance in pitches** outside 30 ... 80 (ISO 10823:2004, 10.1: 30-50
  pitches; clause 8: at most 80 pitches without support) -- above: a guide or idler under
  the long span, or a larger pitch; below: fewer teeth in mesh and more articulations per
  metre: a longer centre distance or a smaller pitch;
* **rating basis** -- the wear life (15 000 h, ACA) the ratings assume; the drive's own life is the wear check.
"""

from __future__ import annotations

from ..analysis.checks import Check
from ..rating import ChainRating
from .duty import Duty
from .policy import MINIMUM_TEETH_BY_REGION, TEETH_SOURCES

__all__ = ["drive_advice", "RATING_LIFE_HOURS", "CENTRE_PITCHES"]

#: Rating life of the ANSI/ACA and ISO 10823 power ratings [h].
RATING_LIFE_HOURS = 15000.0
#: Centre distance range without advice [pitches] (ISO 10823:2004, 10.1: 30-50; clause 8: at most 80).
CENTRE_PITCHES = (30.0, 80.0)
_CENTRE_SOURCE = "ISO 10823:2004, 10.1 (30-50 pitches) and clause 8 (maximum centre distance, 80 pitches)"
_LUBRICATION_ORDER = {"A": 0, "B": 1, "C": 2, "C'": 2}
_LUBRICATION_SOURCE = ("McGuire Bearing Co. lubrication table by chain speed; Shigley, 10th ed., "
                       "Table 17-20 (types A, B, C)")


def _info(name: str, value: float | None, limit: float | None, unit: str, source: str, note: str) -> Check:
    return Check(name=name, value=value, limit=limit, unit=unit, passed=None, source=source, note=note,
                 relation="info")


def drive_advice(duty: Duty, rating: ChainRating, *, smaller_pitch: str | None = None,
                 centre_pitches: float | None = None) -> tuple[Check, ...]:
    """Advice for one rated chain under ``duty`` (information checks with sources).

    Parameters
    ----------
    duty : Duty
    rating : ChainRating
        The rating of the chain on the small sprocket at the design power.
    smaller_pitch : str, optional
        A smaller-pitch multi-strand chain that carries the duty (named in the advice).
    centre_pitches : float, optional
        The drive's centre distance in pitches [-] (advice outside :data:`CENTRE_PITCHES`).

    Returns
    -------
    tuple of Check

    Examples
    --------
    >>> import math
    >>> from chaindrive.rating import chain_rating
    >>> d = Duty(11e3, 1460 * math.pi / 30, ratio=3.0, load_character="moderate")
    >>> r = chain_rating("16B-1", 17, d.speed, power=14.3e3)
    >>> [a.name for a in drive_advice(d, r)][:1]
    ['teeth below the minimum for the chain speed']
    """
    out: list[Check] = []
    region = rating.lubrication
    need = MINIMUM_TEETH_BY_REGION[region]
    if rating.teeth < need:
        out.append(_info("teeth below the minimum for the chain speed", float(rating.teeth), float(need), "1",
                         TEETH_SOURCES["region"],
                         f"{rating.chain_speed:.3g} m/s is lubrication region {region}: use at least {need} "
                         "teeth on the small sprocket (odd), or hardened teeth if the space forbids more"))
    multi = f" (e.g. {smaller_pitch})" if smaller_pitch else ""
    if rating.governing_limit == "roller_bushing":
        out.append(_info("roller-bushing impact limit governs", rating.roller_bushing, None, "W",
                         "ACA; Shigley, 10th ed., eq. (17-33): impact limit ~ z^1.5 p^0.8 / n^1.5",
                         "the impact of the rollers on the teeth limits the rating: more teeth or a smaller "
                         f"pitch in several strands{multi}"))
    if rating.galling_exceeded:
        out.append(_info("galling region", rating.angular_velocity, rating.galling_speed, "rad/s",
                         "Shigley, 10th ed., §17-5 and Table 17-20 (type C')",
                         f"the joints gall at this speed and tension: a smaller pitch in several strands{multi}, "
                         "or submit the design to the chain maker"))
    if duty.lubrication is not None and _LUBRICATION_ORDER[region] > _LUBRICATION_ORDER[duty.lubrication]:
        out.append(_info("lubrication the rating needs", rating.chain_speed, None, "m/s", _LUBRICATION_SOURCE,
                         f"the rating at {rating.chain_speed:.3g} m/s assumes type {region} "
                         f"({rating.lubrication_method}); the site provides type {duty.lubrication}: provide "
                         f"type {region} or choose a slower chain (more teeth on a smaller pitch)"))
    else:
        out.append(_info("lubrication", rating.chain_speed, None, "m/s", _LUBRICATION_SOURCE,
                         f"type {region}: {rating.lubrication_method}"))
    if duty.environment != "clean":
        out.append(_info("environment", None, None, "-",
                         "ISO 10823:2004 and ACA ratings: clean, properly lubricated chains",
                         f"a {duty.environment} environment shortens the wear life the rating assumes: "
                         "enclose and lubricate the drive or choose a larger margin"))
    low, high = CENTRE_PITCHES
    if centre_pitches is not None and centre_pitches > high:
        out.append(_info("centre distance above 80 pitches", centre_pitches, high, "1", _CENTRE_SOURCE,
                         f"{centre_pitches:.0f} pitches: support the long span on a guide or an idler, or choose "
                         "a larger pitch"))
    elif centre_pitches is not None and centre_pitches < low:
        out.append(_info("centre distance below 30 pitches", centre_pitches, low, "1", _CENTRE_SOURCE,
                         f"{centre_pitches:.0f} pitches: each link articulates often and the wrap on the small "
                         "sprocket shrinks: a longer centre distance or a smaller pitch"))
    # one life per drive: the ratings' basis is stated in hours, the drive's own life (in
    # years at the duty's hours) is the wear check of the analysis (issue 30)
    out.append(_info("rating basis: wear life the ratings assume", RATING_LIFE_HOURS * 3600.0, None, "s",
                     "ACA and ISO 10823:2004 ratings: 15 000 h",
                     "the ratings assume 15 000 h of wear life; this drive's own wear life is the wear "
                     "check of the analysis (hours to the elongation limit)"))
    return tuple(out)


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
