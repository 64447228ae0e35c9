r"""Tooth-count policy of the design procedure: how many teeth the small sprocket gets.

The rules, each from a chain maker's published guidance:

* **start at 19 teeth** -- the basis of the ISO 10823:2004 power-rating charts (tooth
  factor 1) and an odd count;
* **minimum by chain speed** -- Diamond Chain, "What is the smallest suggested sprocket
  size to minimize the effects of chordal action?": slow drives (drip lubrication,
  region A) 12 teeth, medium speed (oil bath, region B) 17, high speed (pumped
  lubrication, region C) 25;
* **shock** -- no published minimum tooth count by shock class was found; shock enters
  through the service factor (:mod:`chaindrive.design.duty`) and the advice on impact;
* **odd counts preferred** -- with an even link count every roller then meets every tooth
  (Shigley, 10th ed., §17-5: "an odd number of teeth on the driving sprocket");
* **at least 15, the large wheel at most 120 teeth** -- U.S. Tsubaki, RS roller chain
  catalogue, selection steps 4 and 5 (small sprocket at least 15 teeth, the large one
  not above 120; if it would be, fewer small-sprocket teeth, not below 13).

:func:`driving_teeth` applies them for one chain speed region.
"""

from __future__ import annotations

from .._validation import check_teeth
from ..errors import InputError

__all__ = ["BASE_TEETH", "MINIMUM_TEETH_BY_REGION", "MAXIMUM_DRIVEN_TEETH",
           "ABSOLUTE_MINIMUM_TEETH", "TEETH_SOURCES", "DEFAULT_CENTRE_PITCHES", "default_centre_distance",
           "driving_teeth", "driven_teeth"]

#: Small-sprocket teeth the procedure starts with (ISO 10823:2004 rating basis).
BASE_TEETH = 19
#: Default centre distance [pitches] (ISO 10823:2004: 30 ... 50 pitches).
DEFAULT_CENTRE_PITCHES = 40
#: Minimum small-sprocket teeth by ANSI lubrication region (Diamond Chain FAQ).
MINIMUM_TEETH_BY_REGION = {"A": 12, "B": 17, "C": 25, "C'": 25}
#: The large wheel's teeth at most (U.S. Tsubaki RS catalogue, selection step 5).
MAXIMUM_DRIVEN_TEETH = 120
#: The small sprocket's teeth never below (U.S. Tsubaki RS catalogue: "more than 13").
ABSOLUTE_MINIMUM_TEETH = 13
TEETH_SOURCES = {
    "base": "ISO 10823:2004 rating charts: 19-tooth driving sprocket",
    "region": "Diamond Chain, FAQ 'smallest suggested sprocket size ... chordal action': 12 (drip), "
              "17 (oil bath), 25 (pumped lubrication) teeth",
    "odd": "Shigley, 10th ed., §17-5: odd number of teeth on the driving sprocket",
    "driven": "U.S. Tsubaki RS roller chain catalogue, selection steps 4-5: small sprocket >= 15 "
              "(not below 13), large sprocket <= 120 teeth",
}


def _odd_up(z: int) -> int:
    return z if z % 2 else z + 1


def driving_teeth(region: str, character: str | None, ratio: float, *, given: int | None = None) -> tuple[int, str]:
    """Small-sprocket teeth for a lubrication region and shock class, and why.

    Parameters
    ----------
    region : {"A", "B", "C", "C'"}
        ANSI lubrication region at the chain speed.
    character : {"smooth", "moderate", "heavy"} or None
        Load character (no published tooth minimum by shock class was found; kept for
        the advice).
    ratio : float
        Speed ratio ``>= 1`` (the large wheel stays at or below 120 teeth).
    given : int, optional
        Teeth the user asked for (kept; the advice says when they are below the policy).

    Returns
    -------
    (int, str)
        The teeth and the rule that set them.

    Examples
    --------
    >>> driving_teeth("B", "moderate", 3.0)
    (19, 'ISO 10823:2004 rating charts: 19-tooth driving sprocket')
    >>> driving_teeth("C", "moderate", 2.0)[0]
    25
    >>> driving_teeth("B", None, 7.5)[0]     # 120 / 7.5 = 16 -> 15, odd
    15
    """
    if region not in MINIMUM_TEETH_BY_REGION:
        raise InputError(f"unknown lubrication region {region!r}; valid: A, B, C, C'", field="region")
    if given is not None:
        return int(check_teeth("teeth_driving", given)), "given"
    z, why = BASE_TEETH, TEETH_SOURCES["base"]
    need_region = MINIMUM_TEETH_BY_REGION[region]
    if need_region > z:
        z, why = _odd_up(need_region), TEETH_SOURCES["region"]
    top = int(MAXIMUM_DRIVEN_TEETH // ratio)
    if round(z * ratio) > MAXIMUM_DRIVEN_TEETH:
        z = top if top % 2 else top - 1
        z = max(z, ABSOLUTE_MINIMUM_TEETH)
        why = TEETH_SOURCES["driven"]
    return z, why


def default_centre_distance(pitch: float) -> float:
    """The centre distance [m] a chain of ``pitch`` [m] is laid out at when none is wanted:
    :data:`DEFAULT_CENTRE_PITCHES` pitches (ISO 10823:2004: 30 ... 50 pitches).

    >>> round(default_centre_distance(0.01905), 4)
    0.762
    """
    return DEFAULT_CENTRE_PITCHES * float(pitch)


def driven_teeth(teeth_driving: int, ratio: float) -> int:
    """Teeth of the driven wheel, ``round(z1 · i)`` [-].

    >>> driven_teeth(19, 3.0417)
    58
    """
    return int(round(teeth_driving * ratio))


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
