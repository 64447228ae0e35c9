"""Manufacturing description of a wheel (sprocket or pocket wheel) for drawings and solids.

A :class:`WheelPart` gathers what a workshop needs beyond the face outline: the plate or
rim width, the tooth side chamfer of a sprocket (ISO 606:2015 clause 5.6), the central
groove of a pocket wheel for the vertical links (DIN 22252 link sizes), and the bore, hub
and DIN 6885-1 keyway (:mod:`chaindrive.geometry.hub`). It is frozen: build a new one to
change it. :mod:`chaindrive.geometry.drawing` draws it (DXF), :mod:`chaindrive.geometry.solid`
models it (STEP), and :func:`part_volume` gives its volume in closed form, against which
the solid is checked.

Tooth side chamfer (our reading of ISO 606:2015 clause 5.6, figure "rim profile"): in an
axial section the tooth side is rounded by an arc of the tooth side radius ``rx`` tangent
to the side face, which meets the tip circle the tooth side relief ``ba`` inside the face.
Its tangent point lies ``h = sqrt(2 rx ba − ba²)`` below the tip circle.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from .._results import Result, quantity
from .._typing import FloatOrArray
from .._validation import as_float_array, check_positive
from ..errors import InfeasibleError, InputError
from ..limits import MAX_ARC_POINTS, MAX_SOLID_TEETH, MAX_TEETH, check_size
from .hub import Hub, design_hub, keyway_area
from .outline import Arc, Outline, check_outline_size
from .pocket_wheel import DEFAULT_INNER_WIDTH_RATIO, PocketWheel
from .sprocket import Sprocket

__all__ = [
    "DEFAULT_MATERIAL",
    "ToothChamfer",
    "Groove",
    "Rim",
    "WheelPart",
    "side_chamfer_thickness",
    "side_chamfer_moment",
    "plate_volume",
    "part_volume",
    "sprocket_part",
    "pocket_wheel_part",
]

_MM = 1e-3

#: Default material / heat-treatment note of the title block (to be replaced by the designer).
DEFAULT_MATERIAL = "C45 (1.0503), teeth induction hardened 45...55 HRC"


@dataclass(frozen=True)
class ToothChamfer:
    """Tooth side chamfer of a sprocket (m), ISO 606:2015 clause 5.6.

    Attributes
    ----------
    tip_radius : float
        Tip radius of the teeth [m].
    side_radius : float
        Tooth side radius ``rx`` [m] (nominal ``p``).
    side_relief : float
        Tooth side relief ``ba`` [m] (``0.10...0.15 p``).
    """

    tip_radius: float
    side_radius: float
    side_relief: float

    @property
    def depth(self) -> float:
        """Radial depth ``h = sqrt(2 rx ba − ba²)`` of the chamfer below the tip circle [m]."""
        rx, ba = self.side_radius, self.side_relief
        return float(np.sqrt(2.0 * rx * ba - ba * ba))

    @property
    def start_radius(self) -> float:
        """Radius where the chamfer arc leaves the side face [m]."""
        return self.tip_radius - self.depth


@dataclass(frozen=True)
class Groove:
    """Central groove of a pocket wheel for the vertical links (m).

    Attributes
    ----------
    width : float
        Axial width ``d + 2c`` [m] (bar diameter plus play).
    bottom_radius : float
        Groove bottom radius ``R cos(δ2/2) − (b + 2d)/2 − c`` [m].
    """

    width: float
    bottom_radius: float


@dataclass(frozen=True)
class Rim:
    """Rim of a multi-strand sprocket (m): ``strands`` tooth plates ``pt`` apart on a web.

    Attributes
    ----------
    strands : int
        Tooth plates (chain strands), >= 2.
    transverse_pitch : float
        Distance ``pt`` between the plates' middle planes [m] (the chain's).
    web_radius : float
        Radius of the web joining the plates [m]: ISO 606's ``dg/2``, below which the
        chain's plates never come.
    """

    strands: int
    transverse_pitch: float
    web_radius: float

    def offsets(self) -> list[float]:
        """Axial position of each plate's middle plane [m], the rim centred on z = 0."""
        n = self.strands
        return [(k - (n - 1) / 2) * self.transverse_pitch for k in range(n)]


@dataclass(frozen=True)
class WheelPart(Result):
    """A wheel as a part to make: outline, width, chamfer or groove, hub, bore, keyway (m).

    Attributes
    ----------
    kind : str
        ``"sprocket"`` or ``"pocket wheel"``.
    title : str
        Part name for the title block.
    chain : str
        Chain designation.
    teeth : int
        Teeth or pockets.
    outline : Outline
        Face outline (gap or pocket 0 on +y).
    width : float
        Plate (tooth width ``bf1``) or rim width [m]; the plate spans ``z ∈ [−w/2, w/2]``.
    hub : Hub
        Bore, hub (on the +z side) and keyway (towards +y).
    chamfer : ToothChamfer or None
        Sprocket tooth side chamfer.
    groove : Groove or None
        Pocket wheel groove for the vertical links.
    material : str
        Material and heat-treatment note.
    dimensions : Any
        :class:`SprocketDimensions` or :class:`PocketWheelDimensions`.
    form : str or None
        ISO 606 tooth gap form of the outline.
    sources : dict
        Source of each dimension.
    rim : Rim or None
        Multi-strand sprocket: the plates and their web (``width`` is then one plate's).
    """

    kind: str
    title: str
    chain: str
    teeth: int = quantity("1")
    outline: Outline
    width: float = quantity("m")
    hub: Hub
    chamfer: ToothChamfer | None
    groove: Groove | None
    material: str
    dimensions: Any
    form: str | None = None
    sources: dict = field(default_factory=dict)
    rim: Rim | None = None

    @property
    def rim_width(self) -> float:
        """Axial width of the rim [m]: ``(n − 1) pt + bf1`` for ``n`` strands, else ``width``."""
        if self.rim is None:
            return self.width
        return (self.rim.strands - 1) * self.rim.transverse_pitch + self.width

    @property
    def tip_radius(self) -> float:
        """Outer radius of the outline [m]."""
        return float(self.outline.circles["TIP"])

    @property
    def total_width(self) -> float:
        """Plate or rim width plus hub projection [m]."""
        return self.rim_width + self.hub.hub_length

    def to_dict(self) -> dict:
        """Numbers of the part in SI units (the outline is summarised)."""
        out = {k: v for k, v in super().to_dict().items() if k != "outline"}
        out["tip_radius"] = self.tip_radius
        out["total_width"] = self.total_width
        out["volume"] = float(part_volume(self))
        return out


# --------------------------------------------------------------------------- layer 1
def side_chamfer_thickness(radius: ArrayLike, width: float, tip_radius: float, side_radius: float,
                           side_relief: float) -> FloatOrArray:
    r"""Axial thickness of a chamfered tooth at a radius, ISO 606:2015 clause 5.6 (our reading).

    .. math:: t(r) = w - 2\left(r_x - \sqrt{r_x^2 - (r - r_t)^2}\right)\ (r > r_t),\qquad
              t(r) = w\ (r \le r_t),\qquad r_t = r_a - \sqrt{2 r_x b_a - b_a^2}

    Parameters
    ----------
    radius : float or array_like
        Radius [m], at most ``r_t + r_x``.
    width : float
        Tooth width ``bf1`` [m].
    tip_radius : float
        Tip radius ``r_a`` [m].
    side_radius : float
        Tooth side radius ``rx`` [m].
    side_relief : float
        Tooth side relief ``ba`` [m], ``< rx`` and ``< w/2``.

    Returns
    -------
    ndarray
        ``t`` [m]; ``t(r_a) = w − 2 ba``.

    References
    ----------
    ISO 606:2015, clause 5.6.2 (``rx``, ``ba``); the arc construction is described in the
    module docstring.

    Examples
    --------
    >>> round(float(side_chamfer_thickness(0.08509, 0.016169, 0.08509, 0.0254, 0.00254)) * 1e3, 3)
    11.089
    """
    r, w, rx, rt, u = _chamfer_arc(radius, width, tip_radius, side_radius, side_relief)
    return w - 2.0 * (rx - np.sqrt(rx * rx - u * u))


def _chamfer_args(width, side_radius, side_relief):
    w = float(check_positive("width", width, "m"))
    rx = float(check_positive("side_radius", side_radius, "m"))
    ba = float(check_positive("side_relief", side_relief, "m"))
    if ba >= rx or 2 * ba >= w:
        raise InputError(
            f"side_relief must lie in (0, {min(rx, w / 2) * 1e3:.3f}) mm (below the side radius and half "
            f"the tooth width), got {ba * 1e3:.3f} mm"
        )
    return w, rx, ba


def _chamfer_arc(radius, width, tip_radius, side_radius, side_relief):
    """Radius ``r``, width ``w``, side radius ``rx``, arc start ``r_t`` and ``u = max(r − r_t, 0)``
    of the chamfer arc, the radius checked to stay on the arc."""
    r = as_float_array("radius", radius)
    w, rx, ba = _chamfer_args(width, side_radius, side_relief)
    rt = float(tip_radius) - np.sqrt(2 * rx * ba - ba * ba)
    u = np.clip(r - rt, 0.0, None)
    if np.any(u > rx):
        raise InputError(f"radius must stay below r_t + rx = {(rt + rx) * 1e3:.3f} mm for the chamfer arc")
    return r, w, rx, rt, u


def side_chamfer_moment(radius: ArrayLike, width: float, tip_radius: float, side_radius: float,
                        side_relief: float) -> FloatOrArray:
    r"""Radial moment ``G(r) = ∫₀ʳ t(s) s ds`` of the chamfered thickness (closed form) [m³].

    With ``u = r − r_t`` (``r > r_t``):

    .. math:: G = \frac{w r^2}{2} - 2\left[r_x\left(\frac{u^2}{2} + r_t u\right)
              + \frac{(r_x^2 - u^2)^{3/2} - r_x^3}{3}
              - r_t\left(\frac{u\sqrt{r_x^2 - u^2}}{2} + \frac{r_x^2}{2}\arcsin\frac{u}{r_x}\right)\right]

    Parameters
    ----------
    radius : float or array_like
        As in :func:`side_chamfer_thickness` [m].
    width, tip_radius, side_radius, side_relief : float
        As in :func:`side_chamfer_thickness` [m].

    Returns
    -------
    ndarray
        ``G(r)`` [m³]. By the divergence theorem the volume of a chamfered plate over a
        region Ω is ``∬_Ω t dA = ∮ G(r)/r² (x dy − y dx)`` (:func:`plate_volume`).

    Notes
    -----
    Integrated by hand (``∫ √(a² − u²) u du = −(a² − u²)^{3/2}/3``, ``∫ √(a² − u²) du``
    the circular segment); tested against numerical quadrature.

    Examples
    --------
    >>> g = side_chamfer_moment(0.0, 0.016, 0.085, 0.0254, 0.00254)
    >>> float(g)
    0.0
    """
    r, w, rx, rt, u = _chamfer_arc(radius, width, tip_radius, side_radius, side_relief)
    root = np.sqrt(rx * rx - u * u)
    removed = rx * (u * u / 2 + rt * u) + (root**3 - rx**3) / 3.0 - rt * (u * root / 2 + rx * rx / 2 * np.arcsin(u / rx))
    return w * r * r / 2.0 - 2.0 * removed


def check_part_size(part: WheelPart, maximum: int = MAX_TEETH, *, what: str = "a drawing") -> None:
    """Refuse a part with more teeth than ``maximum`` (one of :mod:`chaindrive.limits`), or
    an outline larger than :data:`chaindrive.limits.MAX_PRIMITIVES`, before it is drawn.

    Examples
    --------
    >>> from chaindrive.geometry.sprocket import Sprocket
    >>> check_part_size(sprocket_part(Sprocket.from_chain("16B", 160)), MAX_SOLID_TEETH, what="a 3-D solid")
    Traceback (most recent call last):
    ...
    chaindrive.errors.InputError: teeth: a 3-D solid is built for at most 150 teeth (chaindrive.limits.MAX_SOLID_TEETH), got 160
    """
    teeth = getattr(part, "teeth", None)
    if isinstance(teeth, (int, np.integer)) and teeth > maximum:
        name = "MAX_SOLID_TEETH" if maximum == MAX_SOLID_TEETH else "MAX_TEETH"
        raise InputError(f"teeth: {what} is built for at most {maximum} teeth (chaindrive.limits.{name}), "
                         f"got {teeth}", field="teeth")
    check_outline_size(part.outline)


def plate_volume(outline: Outline, width: float, chamfer: ToothChamfer | None = None, *,
                 points_per_arc: int = 720) -> float:
    r"""Volume of the outline extruded over ``width``, less the tooth side chamfer [m³].

    .. math:: V = \oint_{\partial\Omega} \frac{G(r)}{r^2}\,(x\,dy - y\,dx),\qquad G(r) = \int_0^r t(s)\,s\,ds

    (divergence theorem for the radial field ``G(r) r̂ / r``, whose divergence is ``t(r)``);
    without chamfer ``G = w r²/2`` and this is the shoelace area times ``w``.

    Parameters
    ----------
    outline : Outline
        Closed counter-clockwise face outline [m].
    width : float
        Plate width [m].
    chamfer : ToothChamfer, optional
        Tooth side chamfer.
    points_per_arc : int
        Sampling of each arc (midpoint rule on the chords; relative error about 1e-7 at 720).

    Returns
    -------
    float
        Volume of the extruded plate less the chamfer [m³].

    Examples
    --------
    >>> from chaindrive.geometry.sprocket import sprocket_outline
    >>> o = sprocket_outline(0.0254, 19, 0.01588)
    >>> round(plate_volume(o, 0.016169) / (o.area() * 0.016169), 6)
    1.0
    """
    w = float(check_positive("width", width, "m"))
    # lines are subdivided too: G(r)/r² varies along a line that crosses the chamfer zone
    check_outline_size(outline)
    check_size("points_per_arc", points_per_arc, MAX_ARC_POINTS, minimum=2)
    pieces = [prim.sample(points_per_arc if isinstance(prim, Arc) else 64) for prim in outline.primitives]
    a = np.concatenate([q[:-1] for q in pieces])
    b = np.concatenate([q[1:] for q in pieces])
    cross = a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]
    if chamfer is None:
        return 0.5 * w * float(np.sum(cross))
    mid = 0.5 * (a + b)
    r = np.hypot(mid[:, 0], mid[:, 1])
    g = side_chamfer_moment(r, w, chamfer.tip_radius, chamfer.side_radius, chamfer.side_relief)
    return float(np.sum(g / (r * r) * cross))


def part_volume(part: WheelPart) -> float:
    r"""Volume of a wheel part in closed form [m³].

    .. math:: V = V_{plate} - g\,(A - \pi r_g^2) - (\pi R_b^2 + A_k)\,w
              + \left(\pi (R_h^2 - R_b^2) - A_k\right) L_h

    ``V_plate`` from :func:`plate_volume` (outline area ``A`` times width ``w`` less the
    chamfers), the groove (width ``g``, bottom radius ``r_g``, pocket wheels), the bore
    ``R_b`` and keyway ``A_k`` (:func:`~chaindrive.geometry.hub.keyway_area`) through plate
    and hub, the hub ``R_h`` of projection ``L_h``. A multi-strand rim of ``n`` plates
    ``pt`` apart counts ``n V_plate + π r_w² (W − n w)`` (web radius ``r_w``, rim width
    ``W = (n − 1) pt + w``) for ``V_plate`` and ``W`` for ``w`` in the bore term.

    Parameters
    ----------
    part : WheelPart
        The part.

    Returns
    -------
    float
        Volume of the part: rim plates and hub, less groove, bore and keyway [m³].

    Examples
    --------
    >>> from chaindrive.geometry import Sprocket
    >>> p = sprocket_part(Sprocket.from_chain("16B", 19))
    >>> round(part_volume(p) * 1e6, 1)
    535.5
    """
    hub = part.hub
    vol = plate_volume(part.outline, part.width, part.chamfer)
    if part.rim is not None:  # n plates and the web between them (the plates overlap it below r_w)
        n, rw = part.rim.strands, part.rim.web_radius
        vol = n * vol + np.pi * rw * rw * (part.rim_width - n * part.width)
    if part.groove is not None:
        area = plate_volume(part.outline, 1.0)
        vol -= part.groove.width * (area - np.pi * part.groove.bottom_radius**2)
    rb = hub.bore / 2
    ak = 0.0 if hub.key is None else float(keyway_area(hub.bore, hub.key.width, hub.key.hub_depth))
    vol -= (np.pi * rb * rb + ak) * part.rim_width
    vol += (np.pi * ((hub.hub_diameter / 2) ** 2 - rb * rb) - ak) * hub.hub_length
    return float(vol)


# --------------------------------------------------------------------------- layer 2
def sprocket_part(sprocket: Sprocket, *, form: str | None = None, tip_diameter: float | None = None,
                  bore: float | None = None, hub_diameter: float | None = None,
                  hub_length: float | None = None, tooth_side_relief: float | None = None,
                  material: str = DEFAULT_MATERIAL, transverse_pitch: float | None = None) -> WheelPart:
    """A sprocket as a part: ISO 606 teeth, chamfer, hub (type B), bore and keyway.

    Parameters
    ----------
    sprocket : Sprocket
        The sprocket (needs ``inner_width`` for the tooth width ``bf1``).
    form : {"min", "max"}, optional
        ISO 606 tooth gap form of the outline (default "min").
    tip_diameter : float, optional
        Tip diameter [m] inside ISO 606's ``[da min, da max]``.
    bore, hub_diameter, hub_length : float, optional
        See :func:`~chaindrive.geometry.hub.design_hub`; the hub may not exceed ISO 606's
        ``dg`` (needs ``plate_height``), else ``0.75`` of the pitch diameter.
    tooth_side_relief : float, optional
        ``ba`` [m], inside ISO 606's ``0.10...0.15 p``; default ``0.10 p``.
    material : str
        Material / heat-treatment note.
    transverse_pitch : float, optional
        The chain's transverse pitch ``pt`` [m]: with it a multi-strand sprocket becomes a
        part (its :class:`Rim`: one tooth plate per strand, ``pt`` apart, joined by a web
        of radius ``dg/2``), for solids; the workshop drawing is of simplex sprockets only.

    Returns
    -------
    WheelPart

    References
    ----------
    ISO 606:2015 clauses 5.3-5.6 (dimensions, tooth width ``bf1``, ``rx = p``, ``ba``,
    ``dg``); DIN 6885-1 (keyway).

    Examples
    --------
    >>> p = sprocket_part(Sprocket.from_chain("16B", 19))
    >>> round(p.width * 1e3, 3), round(p.hub.bore * 1e3), round(p.chamfer.side_relief * 1e3, 2)
    (16.169, 55, 2.54)
    """
    if sprocket.inner_width is None:
        raise InputError("inner_width (b1) is needed for the tooth width bf1 of the drawing and solid "
                         "(ISO 606:2015 5.6); give it or use a catalogue chain")
    if sprocket.strands != 1 and transverse_pitch is None:
        raise InputError(f"strands must be 1 for drawings and solids without the transverse pitch (a multi-strand "
                         f"rim is a solid only, give transverse_pitch), got {sprocket.strands}")
    outline = sprocket.outline(form=form, tip_diameter=tip_diameter)
    dims = sprocket.dimensions()
    p = sprocket.pitch
    ba_lo, ba_hi = 0.10 * p, 0.15 * p
    if tooth_side_relief is None:
        ba = ba_lo
    else:
        ba = float(check_positive("tooth_side_relief", tooth_side_relief, "m"))
        if not (ba_lo * (1 - 1e-9) <= ba <= ba_hi * (1 + 1e-9)):
            raise InputError(
                f"tooth_side_relief must lie in [{ba_lo / _MM:.3f}, {ba_hi / _MM:.3f}] mm (ISO 606:2015 5.6.2, "
                f"ba = 0.10...0.15 p), got {ba / _MM:.3f} mm"
            )
    if dims.tooth_width is None:  # set whenever inner_width is known (checked above)
        raise InputError("inner_width (b1) is needed for the tooth width bf1 (ISO 606:2015 5.6)")
    width = float(dims.tooth_width)
    chamfer = ToothChamfer(tip_radius=float(outline.circles["TIP"]), side_radius=float(dims.tooth_side_radius),
                           side_relief=ba)
    _chamfer_args(width, chamfer.side_radius, ba)
    seat_bottom = 2.0 * float(outline.circles["ROOT"])
    if chamfer.start_radius <= outline.circles["ROOT"]:
        raise InfeasibleError("the tooth side chamfer reaches below the root seat circle; use a smaller "
                              "tooth_side_relief")
    if dims.max_hub_diameter is not None:
        hub_limit, limit_name = float(dims.max_hub_diameter), "ISO 606:2015 5.6.2 dg, chain plate clearance"
    else:
        hub_limit, limit_name = 0.75 * dims.pitch_diameter, "0.75 d without plate_height"
    rim = None
    if sprocket.strands != 1 and transverse_pitch is not None:  # refused above without it
        pt = float(check_positive("transverse_pitch", transverse_pitch, "m"))
        if pt <= width:
            raise InputError(f"transverse_pitch must exceed the tooth width bf1 = {width / _MM:.3f} mm, got "
                             f"{pt / _MM:.3f} mm", field="transverse_pitch")
        rim = Rim(strands=int(sprocket.strands), transverse_pitch=pt, web_radius=0.5 * min(hub_limit, seat_bottom))
    rim_width = width if rim is None else (rim.strands - 1) * rim.transverse_pitch + width
    hub = design_hub(max_hub_diameter=min(hub_limit, seat_bottom), rim_diameter=seat_bottom, plate_width=rim_width,
                     bore=bore, hub_diameter=hub_diameter, hub_length=hub_length, limit_name=limit_name)
    chain = sprocket.name or f"p = {p / _MM:g} mm, d1 = {sprocket.roller_diameter / _MM:g} mm"
    return WheelPart(
        kind="sprocket", title=f"Sprocket {sprocket.name} z = {sprocket.teeth}".replace("  ", " "),
        chain=chain, teeth=sprocket.teeth, outline=outline, width=width, hub=hub, chamfer=chamfer,
        groove=None, material=material, dimensions=dims,
        form=(form or "min") if sprocket.method == "iso606" else None, rim=rim,
        sources={
            **dims.sources,
            **({"rim": "one tooth plate bf1 per strand, pt apart (ISO 606:2015 5.6), on a web of radius dg/2"}
               if rim is not None else {}),
            "tooth_chamfer": "ISO 606:2015 5.6.2, rx = p, ba = 0.10...0.15 p (arc tangent to the side face)",
            "keyway": "DIN 6885-1:1968 table 1",
        },
    )


def pocket_wheel_part(wheel: PocketWheel, *, bore: float | None = None, hub_diameter: float | None = None,
                      hub_length: float | None = None,
                      material: str = "42CrMo4 (1.7225), quenched and tempered, pockets hardened") -> WheelPart:
    """A pocket wheel as a part: pockets for the horizontal links, groove for the vertical links, hub.

    The rim is as wide as a horizontal link lying in its pocket, ``b + 2d + 2c`` (link
    inner width ``b``, bar diameter ``d``, play ``c``); the central groove, ``d + 2c``
    wide, takes the vertical links down to the groove bottom
    ``R cos(δ2/2) − (b + 2d)/2 − c`` (Dolipiński et al. eq. 6 for ``R``; eqs 7-9 for ``δ2``).

    Parameters
    ----------
    wheel : PocketWheel
        The pocket wheel.
    bore, hub_diameter, hub_length : float, optional
        See :func:`~chaindrive.geometry.hub.design_hub`; the hub may not exceed the
        groove bottom diameter.
    material : str
        Material / heat-treatment note.

    Returns
    -------
    WheelPart

    References
    ----------
    Dolipiński et al., eqs (6)-(9); DIN 22252 (link inner width, default ``21/18 d``);
    DIN 6885-1 (keyway).

    Examples
    --------
    >>> p = pocket_wheel_part(PocketWheel.from_chain("18x64", 8))
    >>> round(p.width * 1e3, 1), round(p.groove.width * 1e3, 1)
    (57.0, 18.0)
    """
    outline = wheel.outline()
    dims = wheel.dimensions()
    d, c = wheel.bar_diameter, wheel.clearance
    b = wheel.inner_width if wheel.inner_width is not None else DEFAULT_INNER_WIDTH_RATIO * d
    width = b + 2 * d + 2 * c
    groove = Groove(width=float(dims.slot_width), bottom_radius=float(dims.slot_radius))
    rmin = float(np.min(np.hypot(*outline.polyline(8).T)))
    if groove.bottom_radius >= rmin:
        raise InfeasibleError("the groove bottom must lie below the pocket floor "
                              f"({groove.bottom_radius / _MM:.3f} mm >= {rmin / _MM:.3f} mm)")
    gd = 2 * groove.bottom_radius
    hub = design_hub(max_hub_diameter=gd, rim_diameter=gd, plate_width=width, bore=bore,
                     hub_diameter=hub_diameter, hub_length=hub_length, limit_name="the groove bottom diameter")
    return WheelPart(
        kind="pocket wheel", title=f"Pocket wheel {wheel.name} z = {wheel.teeth}".replace("  ", " "),
        chain=wheel.name or f"{d / _MM:g} x {wheel.pitch / _MM:g}", teeth=wheel.teeth, outline=outline,
        width=float(width), hub=hub, chamfer=None, groove=groove, material=material, dimensions=dims,
        sources={
            **dims.sources,
            "rim_width": "b + 2d + 2c: outer width of a horizontal link (DIN 22252 b; default 21/18 d) plus play",
            "groove": "width d + 2c, bottom R cos(δ2/2) − (b + 2d)/2 − c",
            "keyway": "DIN 6885-1:1968 table 1",
        },
    )


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
