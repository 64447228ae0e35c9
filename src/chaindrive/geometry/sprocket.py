"""Roller-chain sprockets (the :class:`Sprocket` object and its dimensions; the formulas in
:mod:`.iso606`, the tooth forms in :mod:`.tooth_form`, all importable from here): ISO 606:2015 clause 5 dimensions and tooth forms, ANSI B29.1 tooth form.

Layer 1 holds one published formula per function (vectorised, SI units); the tooth
outline builders and the thin :class:`Sprocket` object sit on top of them.

Sources (see docs/geometry.md for the full discussion)
------------------------------------------------------
* ISO 606:2015, *Short-pitch transmission precision roller and bush chains, attachments
  and associated chain sprockets*, clause 5 "Chain sprockets": 5.3 diametral dimensions,
  5.4 tooth gap forms, 5.5 tooth heights and tip diameters, 5.6 rim profiles
  (DIN 8196 and GB/T 1243 carry the same formulas).
* ASME B29.1 tooth form as printed in Machinery's Handbook ("Sprocket tooth form") and
  the American Chain Association, *Chains for Power Transmission and Material Handling*.

Correction of the task's list: ISO 606 pairs the *minimum tooth gap form* with
``ri min = 0.505 d1``, ``α max = 140° − 90°/z`` and ``re max = 0.008 d1 (z² + 180)``;
the *maximum tooth gap form* with ``ri max``, ``α min = 120° − 90°/z`` and
``re min = 0.12 d1 (z + 2)``. (The brief had α and re min/max swapped: 140° − 90°/z
cannot be the minimum of a range whose other end is 120° − 90°/z.)
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from .._results import Result, quantity
from ..errors import InputError
from ._files import WheelFiles
from .iso606 import (  # noqa: F401 - importable from here as before
    MAX_TEETH_TABULATED,
    MIN_TEETH,
    _roller,
    _teeth,
    flank_radius_limits,
    max_hub_diameter,
    measurement_over_pins,
    pitch_diameter,
    root_diameter,
    seating_angle_limits,
    seating_radius_limits,
    tip_diameter_limits,
    tooth_height_limits,
    tooth_side_radius,
    tooth_side_relief_limits,
    tooth_width,
)
from .outline import Outline
from .tooth_form import _DOCS as _TOOTH_DOCS
from .tooth_form import (  # noqa: F401 - the private helpers for the tests and track_wheel
    TOOTH_FORMS,
    AnsiToothForm,
    IsoToothForm,
    _ansi_half_gap,
    _convex_flank_to_tip,
    _full_from_half,
    _iso_half_gap,
    _tip_half,
    ansi_tooth_form,
    iso_tooth_form,
    sprocket_outline,
)

if TYPE_CHECKING:

    from ..chains import Chain

# the formulas (iso606) and tooth forms (tooth_form) import from here as before; this
# module documents only its own objects
__all__ = [
    "SprocketDimensions",
    "Sprocket",
]


# --------------------------------------------------------------------------- objects
@dataclass(frozen=True)
class SprocketDimensions(Result):
    """Every computed sprocket dimension in SI units (m, rad)."""

    method: str
    teeth: int = quantity("1")
    pitch: float = quantity("m")
    roller_diameter: float = quantity("m")
    pitch_diameter: float = quantity("m")
    root_diameter: float = quantity("m")
    tip_diameter_min: float = quantity("m")
    tip_diameter_max: float = quantity("m")
    seating_radius_min: float = quantity("m")
    seating_radius_max: float = quantity("m")
    seating_angle_min: float = quantity("rad")
    seating_angle_max: float = quantity("rad")
    flank_radius_min: float = quantity("m")
    flank_radius_max: float = quantity("m")
    tooth_height_min: float = quantity("m")
    tooth_height_max: float = quantity("m")
    measurement_over_pins: float = quantity("m")
    tooth_side_radius: float = quantity("m")
    tooth_side_relief_min: float = quantity("m")
    tooth_side_relief_max: float = quantity("m")
    tooth_width: float | None = quantity("m", default=None)
    max_hub_diameter: float | None = quantity("m", default=None)
    ansi: dict | None = None
    sources: dict = field(default_factory=dict)


_SOURCES = {
    "pitch_diameter": "ISO 606:2015 5.3.2, d = p / sin(180°/z)",
    "root_diameter": "ISO 606:2015 5.3.2, df = d − d1",
    "tip_diameter": "ISO 606:2015 5.5.2, da max = d + 1.25p − d1, da min = d + p(1 − 1.6/z) − d1",
    "seating_radius": "ISO 606:2015 5.4.2, ri min = 0.505 d1, ri max = 0.505 d1 + 0.069 d1^(1/3) [mm]",
    "seating_angle": "ISO 606:2015 5.4.2, α min = 120° − 90°/z, α max = 140° − 90°/z",
    "flank_radius": "ISO 606:2015 5.4.2, re min = 0.12 d1 (z + 2), re max = 0.008 d1 (z² + 180)",
    "tooth_height": "ISO 606:2015 5.5.2, ha min = 0.5(p − d1), ha max = 0.625p − 0.5d1 + 0.8p/z",
    "measurement_over_pins": "ISO 606:2015 5.3.2, MR = d + d1 (z even), d cos(90°/z) + d1 (z odd)",
    "tooth_width": "ISO 606:2015 5.6.2, bf1 = 0.93 b1 (p <= 12.7 mm) / 0.95 b1 (simplex)",
    "tooth_side": "ISO 606:2015 5.6.2, rx = p, ba = 0.1...0.15 p",
    "max_hub_diameter": "ISO 606:2015 5.6.2, dg = p cot(180°/z) − 1.04 h2 − 0.76 mm",
    "ansi": "ASME B29.1 tooth form, Machinery's Handbook 'Sprocket tooth form'",
}


def _get(obj, name, default=None):
    return getattr(obj, name, default) if not isinstance(obj, dict) else obj.get(name, default)


@_TOOTH_DOCS
@dataclass
class Sprocket(WheelFiles):
    """A roller-chain sprocket: chain dimensions + tooth count (thin object).

    Parameters
    ----------
    %(sprocket_chain)s
    inner_width : float, optional
        Width between inner plates ``b1`` [m] (for the tooth width).
    plate_height : float, optional
        Inner plate depth ``h2`` [m] (for the max hub diameter).
    strands : int
        Number of chain strands.
    method : {"iso606", "ansi"}
        Tooth form standard.
    name : str
        Chain designation, for labels.

    Examples
    --------
    >>> s = Sprocket(pitch=0.0254, teeth=19, roller_diameter=0.01588)
    >>> round(s.dimensions().pitch_diameter * 1e3, 3)
    154.32
    """

    pitch: float
    teeth: int
    roller_diameter: float
    inner_width: float | None = None
    plate_height: float | None = None
    strands: int = 1
    method: str = "iso606"
    name: str = ""

    def __post_init__(self):
        from .._finite import check_finite_fields

        check_finite_fields(self)  # e.g. inner_width = inf: refused here, not carried into a result
        TOOTH_FORMS.get(self.method)
        _roller(self.pitch, self.roller_diameter)
        self.teeth = int(_teeth(self.teeth))

    @classmethod
    def from_chain(cls, chain: Chain | str | Mapping[str, Any], teeth: int, *, method: str = "iso606") -> Sprocket:
        """Build from a chain object (``chaindrive.chains.get(name)``), a name, or a dict."""
        if isinstance(chain, str):
            from .. import chains as _chains

            if not hasattr(_chains, "get"):
                raise InputError("the chain catalogue is not available yet; give pitch and roller_diameter")
            chain = _chains.get(chain)
        d1 = _get(chain, "roller_diameter")
        if d1 is None:
            raise InputError(f"chain {_get(chain, 'name', '?')!r} has no roller_diameter: not a roller chain")
        return cls(
            pitch=float(_get(chain, "pitch")),
            teeth=teeth,
            roller_diameter=float(d1),
            inner_width=_get(chain, "inner_width"),
            plate_height=_get(chain, "plate_height"),
            strands=int(_get(chain, "strands", 1) or 1),
            method=method,
            name=str(_get(chain, "name", "") or ""),
        )

    def dimensions(self) -> SprocketDimensions:
        """All ISO 606 dimensions (and the ANSI constants when ``method='ansi'``)."""
        p, z, d1 = self.pitch, self.teeth, self.roller_diameter

        def f(v):
            return float(v)

        da = tip_diameter_limits(p, z, d1)
        ri = seating_radius_limits(d1)
        al = seating_angle_limits(z)
        re = flank_radius_limits(d1, z)
        ha = tooth_height_limits(p, z, d1)
        ba = tooth_side_relief_limits(p)
        return SprocketDimensions(
            method=self.method,
            teeth=z,
            pitch=f(p),
            roller_diameter=f(d1),
            pitch_diameter=f(pitch_diameter(p, z)),
            root_diameter=f(root_diameter(p, z, d1)),
            tip_diameter_min=f(da[0]),
            tip_diameter_max=f(da[1]),
            seating_radius_min=f(ri[0]),
            seating_radius_max=f(ri[1]),
            seating_angle_min=f(al[0]),
            seating_angle_max=f(al[1]),
            flank_radius_min=f(re[0]),
            flank_radius_max=f(re[1]),
            tooth_height_min=f(ha[0]),
            tooth_height_max=f(ha[1]),
            measurement_over_pins=f(measurement_over_pins(p, z, d1)),
            tooth_side_radius=f(tooth_side_radius(p)),
            tooth_side_relief_min=f(ba[0]),
            tooth_side_relief_max=f(ba[1]),
            tooth_width=None if self.inner_width is None else f(tooth_width(p, self.inner_width, self.strands)),
            max_hub_diameter=None if self.plate_height is None else f(max_hub_diameter(p, z, self.plate_height)),
            ansi=ansi_tooth_form(p, z, d1).to_dict() if self.method == "ansi" else None,
            sources=dict(_SOURCES),
        )

    def outline(self, form: str | None = None, tip_diameter: float | None = None) -> Outline:
        """Closed tooth outline; see :func:`sprocket_outline`."""
        return sprocket_outline(
            self.pitch, self.teeth, self.roller_diameter, method=self.method, form=form, tip_diameter=tip_diameter
        )

    def to_dict(self) -> dict[str, Any]:
        """Inputs and every computed dimension, SI units."""
        return {"name": self.name, "strands": self.strands, **self.dimensions().to_dict()}

    def label(self) -> str:
        std = "ISO 606" if self.method == "iso606" else "ASME B29.1"
        return f"Sprocket {self.name + ' ' if self.name else ''}z = {self.teeth} ({std})"
