r"""Service life of the chain with skew against the life its rating promises.

The ANSI/ACA power ratings are set for 15 000 h of life with at most 3 % elongation
(:data:`chaindrive.life.wear.RATING_LIFE_HOURS`; Shigley, 10th ed., §17-5): a drive loaded at
its rated power reaches the life the wear part computes for ``P = P_r`` (its link count,
wheels and elongation limit included). The wear part gives the hours to the elongation
limit at the design power without skew; the contact part the life with skew relative to
none (Garshniev & Maksymovych, wear law). Their product is the life of the skewed drive:

.. math:: t = t_{lim}(P)\,\frac{L_\varphi}{L_0} \ \ge\ t_{lim}(P_r)

For a roller chain rated by the ANSI/ACA method this is a verdict: a drive whose skew
eats more life than its power margin gives fails (a study's ``passed`` then counts it).
For other chains (the Archard wear model) the life is reported for information. Without a
skew (no contact part) the part does not apply: the rating check covers the life.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from .._results import Result, quantity
from ..life import wear as W
from .checks import Check
from .parts import Part, PartContext, register_part

__all__ = ["ServiceLife"]


@dataclass(frozen=True)
class ServiceLife(Result):
    """Hours to the elongation limit with the skew's relative life."""

    hours_without_skew: float = quantity("h")
    relative_life: float = quantity("1")
    hours: float = quantity("h")
    required: float | None = quantity("h", default=None)
    model: str = ""


def _part(ctx: PartContext) -> ServiceLife | None:
    life = ctx["wear"]
    contact = ctx["contact"]
    if life is None or contact is None:  # no skew given: the rating check covers the life
        return None
    rel = float(contact.result.relative_life_wear)
    hours = float(life.hours_to_limit)
    required = None
    rating = ctx["rating"]
    if life.model == "rating" and rating is not None:
        drive = ctx.drive
        rated = rating.rating.rated_power
        required = float(W.wear_life("rating", rated_power=rated, power=rated, links=ctx["layout"].links,
                                     elongation_limit=drive.elongation_limit,
                                     wheels=len(drive.wheels)).hours_to_limit)
    return ServiceLife(hours_without_skew=hours, relative_life=rel, hours=hours * rel, required=required,
                       model=life.model)


def _checks(ctx: PartContext, result: ServiceLife) -> list[Check]:
    source = ("ANSI/ACA rating basis 15 000 h at the rated power (Shigley, 10th ed., §17-5); skew: "
              "Garshniev & Maksymovych (wear law)")
    note = f"{result.hours_without_skew:.0f} h without skew × relative life {result.relative_life:.3g}"
    if result.required is None:
        return [Check("service life with skew", result.hours, None, "h", None, source, note=note, relation="info")]
    return [Check("service life with skew >= life at the rated power", result.hours, result.required, "h",
                  bool(result.hours >= result.required), source, note=note)]



# --------------------------------------------------------------------------- many variants
def _batch(contexts: Sequence[PartContext]) -> list[ServiceLife | None] | None:
    """:func:`_part` for many variants that share the wear, rating and layout results, the
    elongation limit and the number of wheels (their contacts differ): the life at the
    rated power is computed once, its warnings replayed for each variant."""
    import warnings

    first = contexts[0]
    life, rating, layout = first["wear"], first["rating"], first["layout"]
    drive = first.drive
    for ctx in contexts:
        d = ctx.drive
        if (ctx["wear"] is not life or ctx["rating"] is not rating or ctx["layout"] is not layout
                or d.elongation_limit != drive.elongation_limit or len(d.wheels) != len(drive.wheels)):
            return None
    if life is None:
        return [None] * len(contexts)
    hours = float(life.hours_to_limit)
    required = None
    messages: list[str] = []
    if life.model == "rating" and rating is not None:
        rated = rating.rating.rated_power
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            required = float(W.wear_life("rating", rated_power=rated, power=rated, links=layout.links,
                                         elongation_limit=drive.elongation_limit,
                                         wheels=len(drive.wheels)).hours_to_limit)
        messages = [str(w.message) for w in caught]
    out: list[ServiceLife | None] = []
    for ctx in contexts:
        contact = ctx["contact"]
        if contact is None:
            out.append(None)
            continue
        rel = float(contact.result.relative_life_wear)
        for m in messages:
            ctx.warn(m)
        out.append(ServiceLife(hours_without_skew=hours, relative_life=rel, hours=hours * rel, required=required,
                               model=life.model))
    return out


register_part(Part("service_life", "Service life with skew", _part, needs=("layout", "rating", "wear", "contact"),
                   checks=_checks, order=95, batch=_batch))
