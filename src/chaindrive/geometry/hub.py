"""Bore, hub and parallel-key keyway of a wheel (DIN 6885-1 / ISO 773), for drawings and solids.

Layer 1: :func:`parallel_key` (the DIN 6885-1 table, shipped as a CSV with its source),
:func:`keyway_area` (the hub keyway's cross-section beyond the bore, closed form) and
:func:`bore_limits`; layer 2: :func:`design_hub`, which fills in drawing defaults and
refuses a bore or hub that leaves too thin a wall (the message names the field and the
range). Everything is in SI units (m); the table is in millimetres and converted here.

Wall rule (a drawing rule of this package, not a clause of a standard): the material
left between the bottom of the hub keyway (radius ``d/2 + t2``) and the hub surface (or,
for a wheel without a hub, the innermost rim circle: the sprocket's root seat circle or
the pocket wheel's groove bottom) must be at least one key height ``h``. A key presses on
the hub keyway flank over ``h − t1``; a wall of ``h`` keeps the hub's section over the
keyway at least as deep as the key itself.
"""

from __future__ import annotations

import csv
import math
from dataclasses import dataclass
from functools import lru_cache
from importlib import resources

import numpy as np
from numpy.typing import ArrayLike

from .._results import Result, quantity
from .._typing import FloatOrArray
from .._validation import as_float_array, check_nonnegative, check_positive
from ..errors import InputError

__all__ = [
    "KEYWAY_SOURCE",
    "ParallelKey",
    "Hub",
    "parallel_key",
    "parallel_key_table",
    "keyway_area",
    "bore_limits",
    "design_hub",
]

_MM = 1e-3

#: Citation of the keyway table.
KEYWAY_SOURCE = "DIN 6885-1:1968 table 1 (parallel keys, high form; same sections as ISO 773)"

#: Default ratio hub diameter / bore when only one of them is given (drawing default).
HUB_TO_BORE = 1.8


@dataclass(frozen=True)
class ParallelKey(Result):
    """One row of the DIN 6885-1 parallel-key table, in metres.

    Attributes
    ----------
    shaft_over, shaft_up_to : float
        Shaft diameter band ``(over, up to and including]`` [m].
    width, height : float
        Key width ``b`` and height ``h`` [m].
    shaft_depth, hub_depth : float
        Keyway depth in the shaft ``t1`` and in the hub ``t2`` [m].
    source : str
        Table citation.
    """

    shaft_over: float = quantity("m")
    shaft_up_to: float = quantity("m")
    width: float = quantity("m")
    height: float = quantity("m")
    shaft_depth: float = quantity("m")
    hub_depth: float = quantity("m")
    source: str = KEYWAY_SOURCE

    def label(self) -> str:
        """``"16 x 10"`` (b x h in mm)."""
        return f"{self.width / _MM:g} x {self.height / _MM:g}"


@lru_cache(maxsize=1)
def parallel_key_table() -> tuple[ParallelKey, ...]:
    """The DIN 6885-1 table as :class:`ParallelKey` rows (m), smallest shaft first.

    Examples
    --------
    >>> rows = parallel_key_table()
    >>> rows[0].shaft_over * 1e3, rows[-1].shaft_up_to * 1e3
    (6.0, 230.0)
    """
    text = resources.files("chaindrive.geometry").joinpath("data/din6885_parallel_keys.csv").read_text("utf-8")
    lines = [ln for ln in text.splitlines() if ln.strip() and not ln.lstrip().startswith("#")]
    rows = []
    for rec in csv.DictReader(lines):
        rows.append(
            ParallelKey(
                shaft_over=float(rec["shaft_over_mm"]) * _MM,
                shaft_up_to=float(rec["shaft_up_to_mm"]) * _MM,
                width=float(rec["width_mm"]) * _MM,
                height=float(rec["height_mm"]) * _MM,
                shaft_depth=float(rec["shaft_depth_mm"]) * _MM,
                hub_depth=float(rec["hub_depth_mm"]) * _MM,
            )
        )
    return tuple(rows)


def parallel_key(shaft_diameter: float) -> ParallelKey:
    """Parallel key and keyway for a shaft (bore) diameter, DIN 6885-1 table 1.

    Parameters
    ----------
    shaft_diameter : float
        Shaft (bore) diameter ``d`` [m], 6 mm < d <= 230 mm.

    Returns
    -------
    ParallelKey
        Key ``b x h`` and keyway depths ``t1`` (shaft), ``t2`` (hub) [m].

    Notes
    -----
    A band covers diameters *over* its lower end *up to and including* its upper end
    (a 30 mm shaft takes the 8 x 7 key, a 30.5 mm shaft the 10 x 8 key).

    References
    ----------
    DIN 6885-1:1968, table 1; ISO 773:1969 (same sections). Rows 38...230 mm as reprinted
    in the Siemens Flender catalogue MD 31.1 (2016), p. 7/3.

    Examples
    --------
    >>> k = parallel_key(0.040)
    >>> k.label(), round(k.shaft_depth * 1e3, 1), round(k.hub_depth * 1e3, 1)
    ('12 x 8', 5.0, 3.3)
    """
    d = float(as_float_array("bore", shaft_diameter))
    rows = parallel_key_table()
    lo, hi = rows[0].shaft_over, rows[-1].shaft_up_to
    if not (lo < d <= hi + 1e-12):
        raise InputError(
            f"bore must lie in ({lo / _MM:g}, {hi / _MM:g}] mm (the range of the {KEYWAY_SOURCE}), "
            f"got {d / _MM:.6g} mm"
        )
    for row in rows:
        if d <= row.shaft_up_to + 1e-12:
            return row
    raise AssertionError("unreachable")  # pragma: no cover


def keyway_area(bore: ArrayLike, key_width: ArrayLike, hub_depth: ArrayLike) -> FloatOrArray:
    r"""Cross-section of a hub keyway beyond the bore [m²].

    The keyway is the strip ``|x| <= b/2``, ``0 <= y <= R + t2`` (``R = d/2``); the part
    inside the bore circle is already empty, so

    .. math:: A_k = b\,(R + t_2) - \left[x\sqrt{R^2 - x^2} + R^2\arcsin\frac{x}{R}\right]_{x = b/2}

    Parameters
    ----------
    bore : float or array_like
        Bore diameter ``d`` [m].
    key_width : float or array_like
        Keyway width ``b`` [m], ``b < d``.
    hub_depth : float or array_like
        Hub keyway depth ``t2`` above the bore surface at the keyway's centre [m].

    Returns
    -------
    ndarray
        ``A_k`` [m²].

    Notes
    -----
    The bracket is the area of the bore circle between the lines ``x = ±b/2`` above the
    x axis, ``∫ sqrt(R² − x²) dx`` over ``[−b/2, b/2]``. Tested against a pixel count.

    Examples
    --------
    >>> round(float(keyway_area(0.040, 0.012, 0.0033)) * 1e6, 4)   # [mm²]
    43.2502
    """
    d = check_positive("bore", bore, "m")
    b = check_positive("key_width", key_width, "m")
    t2 = check_positive("hub_depth", hub_depth, "m")
    if np.any(b >= d):
        raise InputError("key_width must be smaller than the bore (0 < b < d)")
    r = d / 2.0
    x = b / 2.0
    inside = x * np.sqrt(r * r - x * x) + r * r * np.arcsin(x / r)
    return b * (r + t2) - inside


def _floor_to(value: float, step: float) -> float:
    return math.floor(value / step + 1e-9) * step


def _ceil_to(value: float, step: float) -> float:
    return math.ceil(value / step - 1e-9) * step


def bore_limits(outer_diameter: float, *, keyway: bool = True) -> tuple[float, float]:
    """Smallest and largest bore whose keyway leaves a wall of one key height to ``outer_diameter``.

    Parameters
    ----------
    outer_diameter : float
        Diameter of the material round the bore: the hub diameter, or for a wheel
        without hub the root seat / groove bottom diameter [m].
    keyway : bool
        With a DIN 6885-1 keyway (wall rule ``D/2 − (d/2 + t2) >= h``); without one the
        wall rule is ``D/2 − d/2 >= 0.1 D``.

    Returns
    -------
    bore_min, bore_max : float
        [m]; ``bore_max < bore_min`` (0) when nothing fits.

    Notes
    -----
    The key grows with the bore in steps, so the largest bore is the largest over the
    table's bands of ``min(band upper end, 2 (D/2 − t2 − h))``.

    References
    ----------
    DIN 6885-1:1968 table 1 for ``t2`` and ``h``; the wall rule is this package's
    drawing rule (module docstring).

    Examples
    --------
    >>> lo, hi = bore_limits(0.100)
    >>> round(lo * 1e3, 3), round(hi * 1e3, 3)
    (6.0, 66.2)
    """
    big_d = float(check_positive("outer_diameter", outer_diameter, "m"))
    rows = parallel_key_table()
    lo = rows[0].shaft_over
    if not keyway:
        return lo, 0.8 * big_d
    best = -math.inf
    for row in rows:
        fit = 2.0 * (big_d / 2.0 - row.hub_depth - row.height)
        cand = min(row.shaft_up_to, fit)
        if cand > row.shaft_over:
            best = max(best, cand)
    return lo, best if math.isfinite(best) else 0.0  # nothing fits: 0 < bore_min, never -inf


@dataclass(frozen=True)
class Hub(Result):
    """Bore, hub and keyway of a wheel (m).

    Attributes
    ----------
    bore : float
        Bore diameter ``d`` [m] (tolerance H7 on the drawing).
    hub_diameter : float
        Hub diameter [m]; equals the plate's inner rim diameter when ``hub_length = 0``.
    hub_length : float
        Projection of the hub beyond one face of the plate or rim [m]; 0: no hub.
    key : ParallelKey or None
        DIN 6885-1 key of the keyway, None for a plain bore.
    bore_range : tuple of float
        Bores the wall rule allows for this hub [m].
    hub_diameter_range : tuple of float
        Hub diameters allowed for this bore [m].
    """

    bore: float = quantity("m")
    hub_diameter: float = quantity("m")
    hub_length: float = quantity("m")
    key: ParallelKey | None
    bore_range: tuple[float, float] = quantity("m")
    hub_diameter_range: tuple[float, float] = quantity("m")

    @property
    def keyway_dimension(self) -> float | None:
        """Drawing dimension ``d + t2`` from the opposite bore edge to the keyway bottom [m]."""
        return None if self.key is None else self.bore + self.key.hub_depth


def _min_hub_for(bore: float, keyway: bool) -> float:
    if not keyway:
        return bore / 0.8
    k = parallel_key(bore)
    return bore + 2.0 * (k.hub_depth + k.height)


def design_hub(
    *,
    max_hub_diameter: float,
    rim_diameter: float,
    plate_width: float,
    bore: float | None = None,
    hub_diameter: float | None = None,
    hub_length: float | None = None,
    keyway: bool = True,
    limit_name: str = "the largest hub diameter",
) -> Hub:
    """Bore, hub diameter and length with drawing defaults, checked against the wall rule.

    Parameters
    ----------
    max_hub_diameter : float
        Largest hub diameter the chain allows [m] (sprocket: ISO 606 ``dg``; pocket
        wheel: the groove bottom diameter).
    rim_diameter : float
        Innermost rim circle [m] (sprocket: root seat circle ``d − 2 ri``; pocket wheel:
        groove bottom): for a wheel without hub the keyway must keep its wall to it.
    plate_width : float
        Width of the plate or rim [m] (for the default hub length).
    bore : float, optional
        Bore diameter [m]; default ``hub_diameter / 1.8`` rounded down to 5 mm.
    hub_diameter : float, optional
        Hub diameter [m]; default ``1.8 bore`` rounded up to 5 mm when a bore is given,
        else ``min(0.95 max_hub_diameter, 0.75 rim_diameter)`` rounded down to 5 mm.
    hub_length : float, optional
        Hub projection beyond the plate [m]; 0 for a plain plate wheel; default
        ``1.2 bore − plate_width`` rounded up to 5 mm overall (key length about 1.2 d).
    keyway : bool
        Cut a DIN 6885-1 keyway.
    limit_name : str
        Name of ``max_hub_diameter`` in messages.

    Returns
    -------
    Hub

    Raises
    ------
    InputError
        A bore outside ``(6, 230]`` mm or one whose keyway leaves less than one key
        height of wall (message: field ``bore`` and the allowed range in mm); a hub
        diameter outside ``[d + 2 (t2 + h), max_hub_diameter]``; a negative hub length.

    Examples
    --------
    >>> h = design_hub(max_hub_diameter=0.1295, rim_diameter=0.1383, plate_width=0.0162)
    >>> round(h.bore * 1e3), round(h.hub_diameter * 1e3), h.key.label()
    (55, 100, '16 x 10')
    """
    dmax = float(check_positive("max_hub_diameter", max_hub_diameter, "m"))
    rim = float(check_positive("rim_diameter", rim_diameter, "m"))
    width = float(check_positive("plate_width", plate_width, "m"))
    step = 5 * _MM
    if bore is not None:
        bore = float(check_positive("bore", bore, "m"))
    if hub_length is not None:
        hub_length = float(check_nonnegative("hub_length", hub_length, "m"))
    plain = hub_length is not None and hub_length == 0.0
    if plain:
        if hub_diameter is not None:
            raise InputError("hub_diameter has no meaning with hub_length = 0 (a plate wheel without hub)")
        outer = rim
    elif hub_diameter is not None:
        outer = float(check_positive("hub_diameter", hub_diameter, "m"))
        if outer > dmax * (1 + 1e-12):
            raise InputError(
                f"hub_diameter must be at most {dmax / _MM:.3f} mm ({limit_name}), got {outer / _MM:.3f} mm"
            )
    elif bore is not None:
        outer = min(max(_ceil_to(HUB_TO_BORE * bore, step), _min_hub_for(bore, keyway) if bore <= 0.230 else 0.0),
                    _floor_to(dmax, _MM))
    else:
        outer = _floor_to(min(0.95 * dmax, 0.75 * rim), step)
    lo, hi = bore_limits(outer, keyway=keyway)
    where = "the rim (no hub)" if plain else f"the hub diameter {outer / _MM:.3f} mm"
    if hi < lo:
        raise InputError(
            f"hub_diameter must be at least {_min_hub_for(lo * 1.001, keyway) / _MM:.3f} mm for the smallest "
            f"DIN 6885-1 bore; {where} leaves no room for a bore and keyway"
        )
    if bore is None:
        bore = max(min(_floor_to(outer / HUB_TO_BORE, step), _floor_to(hi, _MM)), _ceil_to(lo + 1e-9, _MM))
    if not (lo < bore <= hi + 1e-12):
        raise InputError(
            f"bore must lie in ({lo / _MM:.3f}, {hi / _MM:.3f}] mm for {where}: a DIN 6885-1 keyway needs "
            f"a wall of at least one key height beyond its bottom (d/2 + t2); got {bore / _MM:.3f} mm"
        )
    key = parallel_key(bore) if keyway else None
    if hub_length is None:
        hub_length = max(_ceil_to(1.2 * bore, step) - width, 0.5 * bore)
    hub_min = _min_hub_for(bore, keyway)
    return Hub(
        bore=bore,
        hub_diameter=outer,
        hub_length=hub_length,
        key=key,
        bore_range=(lo, hi),
        hub_diameter_range=(hub_min, rim if plain else dmax),
    )


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
