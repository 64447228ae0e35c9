"""Pocket wheel for a round link chain: pitch radius, central angles, pocket positions, outline.

The hinge centres of the chain (where a horizontal and a vertical link interlock) lie on
a bi-regular polygon with sides ``t + d`` (horizontal link, seated flat in a pocket) and
``t - d`` (vertical link, standing in the central slot); its circumradius is the pitch
radius of Dolipiński et al. eq. (6), computed by :mod:`chaindrive.geometry.polygon`.

The drawn outline is a *basic* face view of the wheel rim for drawings (not a
manufacturing profile; compare GOST 13561-89 or DIN 22252's wheel annex for those):

* a flat pocket floor under each horizontal link, at ``R cos(δ1/2) − d/2 − c`` from the
  axis, ending in arcs of radius ``d/2 + c`` round the hinge centres;
* pocket walls parallel to the pocket axis up to the tip circle;
* teeth between the pockets (where the vertical links stand), topped by the tip circle;
* the central slot for the vertical links as a reference circle (layer ``SLOT``) at the
  groove bottom ``R cos(δ2/2) − (b + 2d)/2 − c`` (``b`` the inner width of a link).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from .._docs import Fragments
from .._finite import finite_guard
from .._results import Result, quantity
from .._validation import check_nonnegative, check_positive, check_teeth
from ..errors import InfeasibleError, InputError
from ._files import WheelFiles
from .outline import Arc, Line, Outline, Primitive, _drop_short, _repeat
from .polygon import link_chain_central_angles, link_chain_pitch_radius

if TYPE_CHECKING:

    from ..chains import Chain

__all__ = ["PocketWheel", "PocketWheelDimensions", "pocket_angles", "DEFAULT_INNER_WIDTH_RATIO"]

#: Inner width of a round link as a multiple of the bar diameter when the chain gives
#: none: 21 mm / 18 mm from DIN 22252 for the 18x64 chain (inner width min 21 mm).
DEFAULT_INNER_WIDTH_RATIO = 21.0 / 18.0


#: The round link chain's dimensions, described once (:mod:`chaindrive._docs`).
_DOCS = Fragments(pitch_bar="""
    pitch : float
        Inner link length ``t`` [m].
    bar_diameter : float
        Bar diameter ``d`` [m].
""")


@finite_guard
@_DOCS
def pocket_angles(pitch: float, bar_diameter: float, teeth: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    r"""Polar angles of pocket centres, hinge centres and vertical-link centres.

    Pocket ``k`` (horizontal link ``k``) is centred at ``θ_k = π/2 + 2πk/z``; its hinges
    at ``θ_k ± δ1/2`` and the vertical link that follows at ``θ_k + π/z``.

    .. math:: \theta_k = \frac{\pi}{2} + \frac{2\pi k}{z},\quad
              \theta_k \pm \frac{\delta_1}{2},\quad \theta_k + \frac{\pi}{z}

    Parameters
    ----------
    %(pitch_bar)s
    teeth : int
        Number of pockets ``z`` [-].

    Returns
    -------
    pockets, hinges, vertical : ndarray
        Angles in [0, 2π) [rad]; ``hinges`` has ``2z`` entries in counter-clockwise
        order starting with the first hinge of pocket 0.

    References
    ----------
    Dolipiński et al., eqs (6)-(9) (central angles δ1, δ2).

    Examples
    --------
    >>> pk, hg, vt = pocket_angles(0.064, 0.018, 8)
    >>> round(float(hg[1] - hg[0]), 6), round(float(hg[2] - hg[1]), 6)
    (0.504471, 0.280927)
    """
    z = int(check_teeth("teeth", teeth))
    d1, d2 = (float(v) for v in link_chain_central_angles(pitch, bar_diameter, z))
    pockets = np.pi / 2 + 2 * np.pi * np.arange(z) / z
    hinges = np.empty(2 * z)
    hinges[0::2] = pockets - d1 / 2
    hinges[1::2] = pockets + d1 / 2
    two_pi = 2 * np.pi
    return np.mod(pockets, two_pi), np.mod(hinges, two_pi), np.mod(pockets + np.pi / z, two_pi)


@dataclass(frozen=True)
class PocketWheelDimensions(Result):
    """Computed pocket wheel dimensions (m, rad)."""

    pitch: float = quantity("m")
    bar_diameter: float = quantity("m")
    teeth: int = quantity("1")
    pitch_radius: float = quantity("m")
    central_angle_horizontal: float = quantity("rad")
    central_angle_vertical: float = quantity("rad")
    pocket_angles: np.ndarray = quantity("rad")
    hinge_angles: np.ndarray = quantity("rad")
    vertical_link_angles: np.ndarray = quantity("rad")
    pocket_floor_distance: float = quantity("m")
    pocket_length: float = quantity("m")
    horizontal_link_centre_distance: float = quantity("m")
    vertical_link_centre_distance: float = quantity("m")
    slot_radius: float = quantity("m")
    slot_width: float = quantity("m")
    tip_radius: float = quantity("m")
    clearance: float = quantity("m")
    sources: dict[str, str]


@_DOCS
@dataclass
class PocketWheel(WheelFiles):
    """Pocket wheel for a round link chain ``d x t`` with ``teeth`` pockets (thin object).

    Parameters
    ----------
    %(pitch_bar)s
    teeth : int
        Number of pockets (horizontal links per turn), ``>= 3``.
    inner_width : float, optional
        Inner width of a link ``b`` [m]; default ``21/18 d`` (DIN 22252, 18x64).
    clearance : float
        Radial/axial play added round the link in pockets and slot [m].
    tip_radius : float, optional
        Outer radius of the teeth [m]; default ``R + d/2`` (flush with the top of the bar
        at the hinge).
    name : str
        Chain designation for labels.

    Examples
    --------
    >>> w = PocketWheel(pitch=0.064, bar_diameter=0.018, teeth=8)
    >>> round(w.dimensions().pitch_radius, 6)
    0.164283
    """

    pitch: float
    bar_diameter: float
    teeth: int
    inner_width: float | None = None
    clearance: float = 0.0
    tip_radius: float | None = None
    name: str = ""

    def __post_init__(self) -> None:
        from .._finite import check_finite_fields

        check_finite_fields(self)  # e.g. tip_radius = inf: refused here, not carried into a result
        check_positive("pitch", self.pitch, "m")
        check_positive("bar_diameter", self.bar_diameter, "m")
        check_nonnegative("clearance", self.clearance, "m")
        self.teeth = int(check_teeth("teeth", self.teeth))
        if self.bar_diameter >= self.pitch:
            raise InputError("bar_diameter must be smaller than pitch (0 < d < t)")
        if self.inner_width is not None:
            check_positive("inner_width", self.inner_width, "m")

    @classmethod
    def from_chain(cls, chain: Chain | str | Mapping[str, Any], teeth: int, **kw: Any) -> PocketWheel:
        """Build from a chain object (``chaindrive.chains.get("18x64")``), a name or a dict."""
        if isinstance(chain, str):
            from .. import chains as _chains

            if not hasattr(_chains, "get"):
                raise InputError("the chain catalogue is not available yet; give pitch and bar_diameter")
            chain = _chains.get(chain)
        source = chain

        def g(n: str, default: Any = None) -> Any:
            return source.get(n, default) if isinstance(source, Mapping) else getattr(source, n, default)

        d = g("bar_diameter")
        if d is None:
            raise InputError(f"chain {g('name', '?')!r} has no bar_diameter: not a round link chain")
        return cls(pitch=float(g("pitch")), bar_diameter=float(d), teeth=teeth,
                   inner_width=g("inner_width"), name=str(g("name", "") or ""), **kw)

    # ------------------------------------------------------------------ numbers
    def _core(self) -> tuple[float, float, int, float, float, float, float, float, float, float]:
        t, d, z, c = self.pitch, self.bar_diameter, self.teeth, self.clearance
        r = float(link_chain_pitch_radius(t, d, z))
        d1, d2 = (float(v) for v in link_chain_central_angles(t, d, z))
        b = self.inner_width if self.inner_width is not None else DEFAULT_INNER_WIDTH_RATIO * d
        outer_width = b + 2 * d
        slot_r = r * np.cos(d2 / 2) - outer_width / 2 - c
        tip = self.tip_radius if self.tip_radius is not None else r + d / 2
        return t, d, z, c, r, d1, d2, b, slot_r, tip

    def dimensions(self) -> PocketWheelDimensions:
        """Pitch radius (Dolipiński et al. eq. 6), central angles, pocket positions and drawing sizes."""
        t, d, z, c, r, d1, d2, b, slot_r, tip = self._core()
        pk, hg, vt = pocket_angles(t, d, z)
        return PocketWheelDimensions(
            pitch=t, bar_diameter=d, teeth=z, pitch_radius=r,
            central_angle_horizontal=d1, central_angle_vertical=d2,
            pocket_angles=pk, hinge_angles=hg, vertical_link_angles=vt,
            pocket_floor_distance=r * np.cos(d1 / 2) - d / 2 - c,
            pocket_length=t + 2 * d + 2 * c,
            horizontal_link_centre_distance=r * np.cos(d1 / 2),
            vertical_link_centre_distance=r * np.cos(d2 / 2),
            slot_radius=slot_r, slot_width=d + 2 * c, tip_radius=tip, clearance=c,
            sources={
                "pitch_radius": "Dolipiński et al. eq. (6): R = ½ sqrt((t/sin(π/2z))² + (d/cos(π/2z))²)",
                "central_angles": "Dolipiński et al. eqs (7)-(9): δ1 = 2 asin((t+d)/2R), δ2 = 2 asin((t−d)/2R)",
                "pocket_floor_distance": "R cos(δ1/2) − d/2 − c (chord of the horizontal link minus half a bar)",
                "slot_radius": "R cos(δ2/2) − (b + 2d)/2 − c (half the outer width of a vertical link)",
                "tip_radius": "drawing choice R + d/2 unless given",
            },
        )

    def outline(self, form: str | None = None) -> Outline:
        """Basic closed rim outline (face view); ``centres`` are the ``2z`` hinge centres.

        Examples
        --------
        >>> o = PocketWheel(0.064, 0.018, 8).outline()
        >>> o.closure_gap() < 1e-12, len(o.centres)
        (True, 16)
        """
        t, d, z, c, r, d1, d2, b, slot_r, tip = self._core()
        rho = d / 2 + c
        hx, hy = r * np.sin(d1 / 2), r * np.cos(d1 / 2)
        xw = hx + rho
        if np.arctan2(xw, hy) >= np.pi / z:
            raise InfeasibleError(
                "pockets overlap: the pocket wall at the hinge reaches past the tooth centreline "
                f"(increase teeth or reduce clearance); z = {z}"
            )
        if tip <= np.hypot(xw, hy):
            raise InputError(
                f"tip_radius must exceed {np.hypot(xw, hy):.6g} m (top of the pocket end arcs), got {tip:.6g} m"
            )
        if slot_r <= 0:
            raise InfeasibleError("slot bottom radius <= 0: wheel too small for the link width")
        ytop = np.sqrt(tip**2 - xw**2)
        start = np.pi / 2 - np.pi / z
        th = np.arctan2(ytop, xw)
        right: list[Primitive] = [
            Arc((0.0, 0.0), tip, start, th - start),
            Line((xw, ytop), (xw, hy)),
            Arc((hx, hy), rho, 0.0, -np.pi / 2),
            Line((hx, hy - rho), (0.0, hy - rho)),
        ]
        right = _drop_short(right)
        left = [p.mirrored_x() for p in reversed(right)]
        prims = _repeat(right + left, z)
        pk, hg, vt = pocket_angles(t, d, z)
        centres = np.stack([r * np.cos(hg), r * np.sin(hg)], axis=-1)
        return Outline(prims, r, centres, {"SLOT": slot_r, "TIP": tip})

    def label(self) -> str:
        return f"Pocket wheel {self.name + ' ' if self.name else ''}z = {self.teeth} (Dolipiński et al. eq. 6)"
