"""Dimensions and solids of chain links for the drive assembly (roller and round link chains).

Roller chains (ISO 606 / ASME B29.1): an inner link is two inner plates pressed on two
bushings carrying two rollers; an outer link is two outer plates riveted on two pins.
From the catalogue (:mod:`chaindrive.chains`, ``chains/data``) come the pitch ``p``, the
roller diameter ``d1``, the width between inner plates ``b1``, the pin diameter ``d2``,
the inner plate depth ``h2`` and the transverse pitch ``pt`` of multi-strand chains.
What the catalogue does not give is a drawing choice, stated with each dimension in
:attr:`RollerLinkDimensions.sources`: the plate thickness ``p/8`` (the standard-series
proportion of the ACA *Standard Handbook of Chains*, 2nd ed., table "roller chain
proportions": plate thickness about 0.125 p), the bushing diameter midway between pin
and roller, the outer plate as deep as the inner one. The plates are drawn as stadium
(slot) shapes round the two joint centres, the plates' usual straight-sided form.

Round link chains (DIN 22252): a link is a bar of diameter ``d`` bent to a stadium of
inner length ``t`` (the pitch) and inner width ``b``; its centre line is a stadium of
straight length ``t − b`` and end radius ``(b + d)/2``. On a pocket wheel the
horizontal links lie flat on the pocket floors (their plane holds the chain's direction
and the wheel axis) and the vertical links stand in the central groove (in the wheel
plane); the hinge points of the simulation (the corners of the bi-regular polygon of
Dolipiński et al. eq. (6)) are the centres of the horizontal links' end bars, ``t + d``
apart along a horizontal link and ``t − d`` along a vertical one.

The solids are built with build123d (extra ``cad3d``), in millimetres, each in its own
frame: x along the link from its first joint to its second, z the wheel axis, the link's
middle plane at z = 0. :mod:`chaindrive.cad.assembly` places copies of them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

from .._results import Result, quantity
from ..errors import InputError

__all__ = ["RollerLinkDimensions", "RoundLinkDimensions", "roller_link_dimensions", "round_link_dimensions",
           "roller_chain_parts_layout", "roller_chain_solids", "round_link_solid", "round_link_volume", "round_link_face_outline",
           "PLATE_THICKNESS_RATIO"]

_MM = 1e3
#: Plate thickness over pitch of a standard-series roller chain (ACA, Standard Handbook of
#: Chains, 2nd ed., roller chain proportions: about 1/8 of the pitch).
PLATE_THICKNESS_RATIO = 0.125


@dataclass(frozen=True)
class RollerLinkDimensions(Result):
    """Dimensions of a roller chain's parts [m] (see the module notes for their sources).

    Examples
    --------
    >>> d = roller_link_dimensions("16B")
    >>> round(d.plate_thickness * 1e3, 3), round(d.bushing_diameter * 1e3, 2)
    (3.175, 12.08)
    """

    pitch: float = quantity("m")
    roller_diameter: float = quantity("m")
    bushing_diameter: float = quantity("m")
    pin_diameter: float = quantity("m")
    inner_width: float = quantity("m")
    plate_height: float = quantity("m")
    outer_plate_height: float = quantity("m")
    plate_thickness: float = quantity("m")
    strands: int = quantity("1")
    transverse_pitch: float = quantity("m")
    sources: dict = field(default_factory=dict)

    @property
    def strand_offsets(self) -> list[float]:
        """Axial position of each strand's middle plane [m], the chain centred on z = 0."""
        n = self.strands
        return [(k - (n - 1) / 2) * self.transverse_pitch for k in range(n)]

    @property
    def width(self) -> float:
        """Axial width over the outer plates [m]."""
        return (self.strands - 1) * self.transverse_pitch + self.inner_width + 4 * self.plate_thickness


@dataclass(frozen=True)
class RoundLinkDimensions(Result):
    """Dimensions of a round steel link [m]: pitch ``t`` (inner length), bar ``d``, inner width ``b``.

    Examples
    --------
    >>> d = round_link_dimensions("18x64")
    >>> round(d.inner_width * 1e3, 1), round(d.horizontal_chord * 1e3), round(d.vertical_chord * 1e3)
    (21.0, 82, 46)
    """

    pitch: float = quantity("m")
    bar_diameter: float = quantity("m")
    inner_width: float = quantity("m")
    sources: dict = field(default_factory=dict)

    @property
    def horizontal_chord(self) -> float:
        """Hinge-to-hinge distance along a horizontal link, ``t + d`` [m]."""
        return self.pitch + self.bar_diameter

    @property
    def vertical_chord(self) -> float:
        """Hinge-to-hinge distance along a vertical link, ``t − d`` [m]."""
        return self.pitch - self.bar_diameter

    @property
    def outer_width(self) -> float:
        """``b + 2d`` [m]."""
        return self.inner_width + 2 * self.bar_diameter


def _chain(chain: Any) -> Any:
    if isinstance(chain, str):
        from .. import chains

        return chains.get(chain)
    return chain


def roller_link_dimensions(chain: Any) -> RollerLinkDimensions:
    """The part dimensions of a catalogue roller chain (name or :class:`~chaindrive.chains.Chain`).

    Raises
    ------
    InputError
        A dimension the solids need (``d1``, ``b1``, ``d2``, ``h2``; ``pt`` of a
        multi-strand chain) is missing from the chain.

    Examples
    --------
    >>> roller_link_dimensions("16B").strands
    1
    """
    ch = _chain(chain)
    missing = [n for n in ("roller_diameter", "inner_width", "pin_diameter", "plate_height")
               if getattr(ch, n, None) is None]
    strands = int(getattr(ch, "strands", 1) or 1)
    if strands > 1 and ch.transverse_pitch is None:
        missing.append("transverse_pitch")
    if missing:
        raise InputError(f"chain {ch.name}: the 3-D model needs {', '.join(missing)} (give a catalogue chain "
                         "or these dimensions)", field="chain")
    p, d1, d2 = float(ch.pitch), float(ch.roller_diameter), float(ch.pin_diameter)
    h2 = float(ch.plate_height)
    if not (d2 < d1 < h2 < p):
        raise InputError(f"chain {ch.name}: the 3-D model needs pin < roller < plate depth < pitch, got "
                         f"d2 = {d2 * _MM:g}, d1 = {d1 * _MM:g}, h2 = {h2 * _MM:g}, p = {p * _MM:g} mm", field="chain")
    catalogue = f"chain catalogue ({ch.source})"
    return RollerLinkDimensions(
        pitch=p, roller_diameter=d1, bushing_diameter=0.5 * (d1 + d2), pin_diameter=d2,
        inner_width=float(ch.inner_width), plate_height=h2, outer_plate_height=h2,
        plate_thickness=PLATE_THICKNESS_RATIO * p, strands=strands,
        transverse_pitch=float(ch.transverse_pitch or 0.0),
        sources={"pitch": catalogue, "roller_diameter": catalogue, "inner_width": catalogue,
                 "pin_diameter": catalogue, "plate_height": catalogue, "transverse_pitch": catalogue,
                 "plate_thickness": "p/8: ACA Standard Handbook of Chains (2nd ed.), roller chain proportions",
                 "bushing_diameter": "(d1 + d2)/2: drawing choice (ISO 606 does not dimension the bushing)",
                 "outer_plate_height": "h2: drawing choice (the catalogue gives the inner plate depth)"})


def round_link_dimensions(chain: Any) -> RoundLinkDimensions:
    """The dimensions of a catalogue round link chain (DIN 22252).

    Examples
    --------
    >>> round(round_link_dimensions("18x64").bar_diameter * 1e3)
    18
    """
    from ..geometry.pocket_wheel import DEFAULT_INNER_WIDTH_RATIO

    ch = _chain(chain)
    if ch.bar_diameter is None:
        raise InputError(f"chain {ch.name}: a round link chain needs its bar diameter", field="chain")
    d = float(ch.bar_diameter)
    b = float(ch.inner_width) if ch.inner_width is not None else DEFAULT_INNER_WIDTH_RATIO * d
    return RoundLinkDimensions(
        pitch=float(ch.pitch), bar_diameter=d, inner_width=b,
        sources={"pitch": f"chain catalogue ({ch.source})", "bar_diameter": f"chain catalogue ({ch.source})",
                 "inner_width": "catalogue" if ch.inner_width is not None
                 else "21/18 d (DIN 22252 18x64: inner width min 21 mm)"})


# --------------------------------------------------------------------------- solids (mm)
def _bd() -> Any:
    from ..geometry.solid import _bd as bd

    return bd()


def _tube(bd: Any, outer: float, inner: float, length: float) -> Any:
    """Tube along z centred on z = 0 (mm)."""
    solid = bd.Solid.make_cylinder(outer / 2, length)
    if inner > 0:
        solid = solid - bd.Solid.make_cylinder(inner / 2, length)
    return solid.moved(bd.Location((0, 0, -length / 2)))


def _plate(bd: Any, pitch: float, height: float, hole: float, thickness: float) -> Any:
    """Stadium plate round joints at x = 0 and x = pitch, holes ``hole``, centred on z = 0 (mm)."""
    r = height / 2
    sketch = bd.Solid.make_box(pitch, height, thickness).moved(bd.Location((0, -r, 0)))
    sketch = sketch + bd.Solid.make_cylinder(r, thickness) + bd.Solid.make_cylinder(r, thickness).moved(
        bd.Location((pitch, 0, 0)))
    for x in (0.0, pitch):
        sketch = sketch - bd.Solid.make_cylinder(hole / 2, thickness).moved(bd.Location((x, 0, 0)))
    return _one(sketch).moved(bd.Location((0, 0, -thickness / 2)))


def _one(shape: Any) -> Any:
    solids = shape.solids() if hasattr(shape, "solids") else [shape]
    if len(solids) != 1:  # pragma: no cover - the sizes are checked before
        raise InputError(f"a chain part fell apart into {len(solids)} pieces; check the chain's dimensions")
    return solids[0]


def roller_chain_parts_layout(dims: RollerLinkDimensions) -> dict[str, list[tuple[str, tuple[float, float], str]]]:
    """Which parts make an inner and an outer link, and where [m] in the link's frame.

    Returns
    -------
    dict
        ``"inner"`` and ``"outer"``: lists of ``(shape, (x, z), label)``; ``x`` is 0 (the
        link's first joint) or ``p`` (its second) for the round parts, 0 for the plates
        (which run from x = 0 to x = p); ``z`` the axial position of the part's middle.

    Examples
    --------
    >>> lay = roller_chain_parts_layout(roller_link_dimensions("16B"))
    >>> len(lay["inner"]), len(lay["outer"])
    (6, 4)
    """
    p, t, b1 = dims.pitch, dims.plate_thickness, dims.inner_width
    offsets = dims.strand_offsets
    inner = []
    for k, z in enumerate(offsets):
        strand = f" strand {k + 1}" if dims.strands > 1 else ""
        for j, x in enumerate((0.0, p)):
            inner.append(("roller", (x, z), f"roller {j + 1}{strand}"))
            inner.append(("bushing", (x, z), f"bushing {j + 1}{strand}"))
        for j, s in enumerate((-1, 1)):
            inner.append(("inner plate", (0.0, z + s * (b1 + t) / 2), f"inner plate {j + 1}{strand}"))
    outer = [("pin", (x, 0.0), f"pin {j + 1}") for j, x in enumerate((0.0, p))]
    outer += [("outer plate", (0.0, s * (dims.width - t) / 2), f"outer plate {j + 1}") for j, s in enumerate((-1, 1))]
    outer += [("middle plate", (0.0, 0.5 * (offsets[k] + offsets[k + 1])), f"middle plate {k + 1}")
              for k in range(dims.strands - 1)]
    return {"inner": inner, "outer": outer}


def roller_chain_solids(dims: RollerLinkDimensions) -> dict[str, Any]:
    """The distinct solids of a roller chain (build123d, mm), each in its own frame.

    Plates run from joint x = 0 to x = p; round parts (roller, bushing, pin) lie on the
    z axis; every part is centred on z = 0 (:func:`roller_chain_parts_layout` places them).

    Examples
    --------
    >>> parts = roller_chain_solids(roller_link_dimensions("16B"))  # doctest: +SKIP
    >>> sorted(parts)  # doctest: +SKIP
    ['bushing', 'inner plate', 'outer plate', 'pin', 'roller']
    """
    bd = _bd()
    p, t = dims.pitch * _MM, dims.plate_thickness * _MM
    b1, pt = dims.inner_width * _MM, dims.transverse_pitch * _MM
    d1, db, d2 = dims.roller_diameter * _MM, dims.bushing_diameter * _MM, dims.pin_diameter * _MM
    out = {
        "roller": _tube(bd, d1, db, b1),
        "bushing": _tube(bd, db, d2, b1 + 2 * t),
        "inner plate": _plate(bd, p, dims.plate_height * _MM, db, t),
        "pin": _tube(bd, d2, 0.0, dims.width * _MM + t),
        "outer plate": _plate(bd, p, dims.outer_plate_height * _MM, d2, t),
    }
    if dims.strands > 1:
        out["middle plate"] = _plate(bd, p, dims.outer_plate_height * _MM, d2, pt - b1 - 2 * t)
    return out


def round_link_solid(dims: RoundLinkDimensions) -> Any:
    """One round steel link (mm): its centre at the origin, its length along x, lying in the x-y plane.

    The bar's centre line is a stadium of straight length ``t − b`` and end radius
    ``(b + d)/2``; the circle of diameter ``d`` swept along it.

    Examples
    --------
    >>> s = round_link_solid(round_link_dimensions("18x64"))  # doctest: +SKIP
    >>> round(s.volume)  # doctest: +SKIP
    53062
    """
    bd = _bd()
    d, b, t = dims.bar_diameter * _MM, dims.inner_width * _MM, dims.pitch * _MM
    rc = (b + d) / 2
    half = (t - b) / 2
    if half <= 0:
        raise InputError(f"a round link needs its inner length above its inner width, got t = {t:g} mm, "
                         f"b = {b:g} mm", field="chain")
    pieces = [
        bd.Solid.make_cylinder(d / 2, 2 * half, bd.Plane((-half, s * rc, 0), x_dir=(0, 0, 1), z_dir=(1, 0, 0)))
        for s in (-1, 1)
    ]
    for s in (-1, 1):
        ring = bd.Solid.make_torus(rc, d / 2).moved(bd.Location((s * half, 0, 0)))
        cut = bd.Solid.make_box(rc + d, 2 * (rc + d), 2 * d).moved(
            bd.Location((s * half - (rc + d) if s < 0 else s * half, -(rc + d), -d)))
        pieces.append(ring & cut)
    link = pieces[0]
    for piece in pieces[1:]:
        link = link + piece
    return _one(link.clean() if hasattr(link, "clean") else link)


def round_link_volume(dims: RoundLinkDimensions) -> float:
    r"""Volume of a round link [m³]: the bar's cross-section times its centre-line length
    (Pappus), :math:`V = \frac{\pi d^2}{4}\,\left(2 (t - b) + \pi (b + d)\right)`.

    Examples
    --------
    >>> round(round_link_volume(round_link_dimensions("18x64")) * 1e9)
    53062
    """
    d, b, t = dims.bar_diameter, dims.inner_width, dims.pitch
    return math.pi * d * d / 4 * (2 * (t - b) + math.pi * (b + d))


def round_link_face_outline(dims: RoundLinkDimensions, groove_half_width: float, points: int = 25) -> Any:
    """Face view (along the wheel axis) of a horizontal link's parts beside a pocket wheel's groove [m].

    A horizontal link lies with its width along the wheel axis ``z``; the wheel's rim
    beside the central groove (``|z| >= w``) meets only the link's material there. At a
    distance ``s`` from the link's middle plane the bar reaches ``ρ = (b + d)/2 +
    sqrt(d²/4 − s²)`` from the end bend's centre, so beside the groove it ends at
    ``x = (t − b)/2 + sqrt(ρ² − w²)`` along the link (the torus of the end bend cut by
    the plane ``z = w``).

    Returns
    -------
    ndarray (M, 2)
        Closed polygon ``(x, s)`` [m]: ``x`` along the link from its middle, ``s`` across
        (in the wheel plane), the first point not repeated.

    Examples
    --------
    >>> o = round_link_face_outline(round_link_dimensions("18x64"), 0.0108)
    >>> round(float(o[:, 0].max()) * 1e3, 2), round(float(o[:, 1].max()) * 1e3, 1)
    (47.87, 9.0)
    """
    import numpy as np

    r = dims.bar_diameter / 2
    rc = (dims.inner_width + dims.bar_diameter) / 2
    half = (dims.pitch - dims.inner_width) / 2
    s = r * np.sin(np.linspace(-np.pi / 2, np.pi / 2, points))
    rho = rc + np.sqrt(np.maximum(r * r - s * s, 0.0))
    x = half + np.sqrt(np.maximum(rho * rho - groove_half_width ** 2, 0.0))
    return np.concatenate([np.column_stack([x, s]), np.column_stack([-x, -s])])
