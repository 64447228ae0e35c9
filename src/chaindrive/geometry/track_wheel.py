"""Drive wheel (sprocket) of a tracked vehicle engaging the lantern pins of the track links.

Sharipov (Sharipov, *Design of tractor running systems*, p. 34) gives:

* root radius ``R_В = R_о − r_цо`` with the pin-seat arc radius ``r_цо = (1.1…1.3) r_ц``;
* tip radius ``R_Г = R_о + (0.2…0.5) r_ц`` for built-up (composite) links and
  ``R_Г = R_о + (0.8…1.2) r_ц`` for cast one-piece links,

with ``R_о`` the pitch radius and ``r_ц`` the pin radius. The pitch radius is not printed
on the page; for pins at the vertices of a regular ``z``-gon of side ``t`` (the track
pitch) it is ``R_о = t / (2 sin(π/z))``, the same as a roller-chain sprocket.

The paper gives no flank shape. The outline drawn here uses the classical construction
for pin-gear (lantern) wheels: the flank is a circle of radius ``t − r_цо`` centred on
the *neighbouring* pin, i.e. the path of a pin that swings about its neighbour as the
link leaves the wheel, offset by the seat radius. It meets the seat arc tangentially on
the line joining the two pins.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike

from .._finite import finite_guard, refuse_nonfinite_result
from .._registry import Registry
from .._results import Result, quantity
from .._typing import FloatOrArray
from .._validation import check_positive, check_range, check_teeth
from ..errors import InfeasibleError, InputError
from ._files import WheelFiles
from .outline import Arc, Outline, Primitive, _drop_short, _pair, _repeat
from .polygon import roller_chain_pitch_radius
from .tooth_form import _convex_flank_to_tip, _tip_half

if TYPE_CHECKING:
    pass

__all__ = [
    "PIN_SEAT_FACTOR_RANGE",
    "TIP_FACTOR_RANGES",
    "track_wheel_pitch_radius",
    "pin_seat_radius_range",
    "root_radius",
    "root_radius_range",
    "tip_radius_range",
    "tip_radius",
    "worn_tip_radius",
    "TrackDriveWheel",
    "TrackDriveWheelDimensions",
]

#: ``r_цо / r_ц`` range, Sharipov.
PIN_SEAT_FACTOR_RANGE: tuple[float, float] = (1.1, 1.3)
#: ``(R_Г − R_о) / r_ц`` ranges by link type, Sharipov.
TIP_FACTOR_RANGES = Registry("link")
TIP_FACTOR_RANGES.add("built-up", (0.2, 0.5))
TIP_FACTOR_RANGES.add("cast", (0.8, 1.2))


@finite_guard
def track_wheel_pitch_radius(pitch: ArrayLike, teeth: ArrayLike) -> FloatOrArray:
    r"""Pitch radius ``R_о`` of a track drive wheel with pins on a regular polygon.

    .. math:: R_о = \frac{t}{2\sin(\pi/z)}

    Parameters
    ----------
    pitch : float or array_like
        Track pitch ``t`` (pin centre distance) [m].
    teeth : int or array_like
        Number of teeth ``z >= 3`` [-].

    Returns
    -------
    ndarray
        [m].

    References
    ----------
    Sharipov (R_о named, not printed); same geometry as ISO 606:2015 5.3.2.

    Examples
    --------
    >>> round(float(track_wheel_pitch_radius(0.17, 13)) * 1e3, 3)
    355.179
    """
    return roller_chain_pitch_radius(pitch, teeth)


@finite_guard
def pin_seat_radius_range(pin_radius: ArrayLike) -> tuple[FloatOrArray, FloatOrArray]:
    r"""Allowed pin-seat arc radius ``r_цо = (1.1…1.3) r_ц`` (Sharipov).

    .. math:: r_{цо} = (1.1 \dots 1.3)\, r_ц

    Parameters
    ----------
    pin_radius : float or array_like
        Pin (lantern) radius ``r_ц`` [m].

    Returns
    -------
    low, high : ndarray
        [m].

    Examples
    --------
    >>> [round(float(v), 6) for v in pin_seat_radius_range(0.025)]
    [0.0275, 0.0325]
    """
    r = check_positive("pin_radius", pin_radius, "m")
    return PIN_SEAT_FACTOR_RANGE[0] * r, PIN_SEAT_FACTOR_RANGE[1] * r


@finite_guard
def root_radius(pitch_radius: ArrayLike, pin_seat_radius: ArrayLike) -> FloatOrArray:
    r"""Root radius ``R_В = R_о − r_цо`` (Sharipov).

    .. math:: R_В = R_о - r_{цо}

    Parameters
    ----------
    pitch_radius : float or array_like
        ``R_о`` [m].
    pin_seat_radius : float or array_like
        ``r_цо`` [m].

    Returns
    -------
    ndarray
        Root radius ``R_В`` [m].

    Examples
    --------
    >>> round(float(root_radius(0.355, 0.03)), 6)   # R_о − r_цо
    0.325
    """
    r0 = check_positive("pitch_radius", pitch_radius, "m")
    rs = check_positive("pin_seat_radius", pin_seat_radius, "m")
    if np.any(rs >= r0):
        raise InputError("pin_seat_radius must be smaller than pitch_radius")
    return r0 - rs


@finite_guard
def root_radius_range(pitch_radius: ArrayLike, pin_radius: ArrayLike) -> tuple[FloatOrArray, FloatOrArray]:
    r"""Range of ``R_В = R_о − (1.1…1.3) r_ц`` (Sharipov); returns ``(low, high)``.

    .. math:: R_В \in [R_о - 1.3 r_ц,\ R_о - 1.1 r_ц]

    Examples
    --------
    >>> [round(float(v), 6) for v in root_radius_range(0.355, 0.025)]
    [0.3225, 0.3275]
    """
    lo, hi = pin_seat_radius_range(pin_radius)
    return root_radius(pitch_radius, hi), root_radius(pitch_radius, lo)


@finite_guard
def tip_radius_range(
    pitch_radius: ArrayLike, pin_radius: ArrayLike, link: str = "built-up"
) -> tuple[FloatOrArray, FloatOrArray]:
    r"""Range of the tip radius ``R_Г = R_о + k r_ц`` (Sharipov).

    .. math:: R_Г = R_о + (0.2 \dots 0.5)\,r_ц\ \text{(built-up links)},\quad
              R_Г = R_о + (0.8 \dots 1.2)\,r_ц\ \text{(cast links)}

    Parameters
    ----------
    pitch_radius : float or array_like
        Pitch radius ``R_о`` of the wheel [m].
    pin_radius : float or array_like
        Pin radius ``r_ц`` of the track links [m].
    link : {"built-up", "cast"}
        Track link construction.

    Returns
    -------
    low, high : ndarray
        [m].

    References
    ----------
    Sharipov (Sharipov, p. 34).

    Examples
    --------
    >>> [round(float(v), 6) for v in tip_radius_range(0.355, 0.025, "cast")]
    [0.375, 0.385]
    """
    k_lo, k_hi = TIP_FACTOR_RANGES.get(link)
    r0 = check_positive("pitch_radius", pitch_radius, "m")
    r = check_positive("pin_radius", pin_radius, "m")
    return r0 + k_lo * r, r0 + k_hi * r


@finite_guard
def tip_radius(
    pitch_radius: ArrayLike, pin_radius: ArrayLike, tip_factor: ArrayLike, link: str = "built-up"
) -> FloatOrArray:
    r"""Tip radius ``R_Г = R_о + k r_ц`` with ``k`` validated inside the paper's range.

    .. math:: R_Г = R_о + k\, r_ц

    Parameters
    ----------
    pitch_radius, pin_radius : float or array_like
        ``R_о``, ``r_ц`` [m].
    tip_factor : float or array_like
        ``k``: 0.2…0.5 for built-up links, 0.8…1.2 for cast links [-].
    link : {"built-up", "cast"}

    Returns
    -------
    ndarray
        [m].

    Raises
    ------
    InputError
        ``k`` outside the range for ``link``.

    Examples
    --------
    >>> round(float(tip_radius(0.355, 0.025, 0.35)), 6)
    0.36375
    >>> tip_radius(0.355, 0.025, 0.7)
    Traceback (most recent call last):
    ...
    chaindrive.errors.InputError: tip_factor must lie in [0.2, 0.5] for built-up links (Sharipov: R_Г = R_о + (0.2...0.5) r_ц), got 0.7
    """
    k_lo, k_hi = TIP_FACTOR_RANGES.get(link)
    k = _factor("tip_factor", tip_factor, k_lo, k_hi, f"{link} links (Sharipov: R_Г = R_о + ({k_lo}...{k_hi}) r_ц)")
    r0 = check_positive("pitch_radius", pitch_radius, "m")
    r = check_positive("pin_radius", pin_radius, "m")
    return r0 + k * r


@finite_guard
def worn_tip_radius(pitch: ArrayLike, teeth: ArrayLike, elongation_limit: ArrayLike) -> FloatOrArray:
    r"""Smallest tip radius that still holds the pins of the chain at its largest allowed pitch [m].

    .. math:: R_{Г,min} = \frac{t\,(1 + Δ)}{2\sin(π/z)} = R_о\,(1 + Δ),\qquad
              k_{min} = \frac{R_{Г,min} - R_о}{r_ц} = \frac{Δ\,R_о}{r_ц}

    Parameters
    ----------
    pitch : float or array_like
        New track pitch ``t`` [m].
    teeth : int or array_like
        ``z >= 3``.
    elongation_limit : float or array_like
        Largest allowed wear elongation of the pitch ``Δ``, ``0 < Δ <= 0.1`` [-]
        (the drive's ``elongation_limit``).

    Returns
    -------
    ndarray or float
        ``R_Г,min`` [m].

    Notes
    -----
    Sharipov: «Исходя из допустимого максимального шага цепи при изнашивании шарниров,
    определяют радиус R_Г окружности головок зубьев» (the tip radius follows from the
    largest allowed pitch of the chain with worn joints); the page prints only the
    resulting ranges ``R_Г = R_о + (0.2…0.5) r_ц`` (built-up links) and ``(0.8…1.2) r_ц``
    (cast links). Derivation: a worn chain of pitch ``t (1 + Δ)`` wraps the wheel with
    its pins on the circle on which that pitch is the side of a regular ``z``-gon,
    radius ``R_о (1 + Δ)``; a pin whose centre rises above the tooth tip is no longer
    pushed along the chain by the flank and the chain jumps the teeth, so the tips must
    reach at least that circle. With ``R_о = 355 mm, r_ц = 22.5 mm`` the printed
    built-up range ``0.2…0.5`` corresponds to ``Δ = 1.3…3.2 %``, the cast range
    ``0.8…1.2`` to ``Δ = 5…7.6 %``.

    References
    ----------
    Sharipov, *Design of tractor running systems*, p. 34 (the rule; the formula derived here).

    Examples
    --------
    >>> round(float(worn_tip_radius(0.17, 13, 0.03)), 6)
    0.365835
    """
    t = check_positive("pitch", pitch, "m")
    z = check_teeth("teeth", teeth)
    d = np.asarray(elongation_limit, dtype=float)
    if np.any(~np.isfinite(d)) or np.any(d <= 0) or np.any(d > 0.1):
        raise InputError(f"elongation_limit must lie in (0, 0.1], got {d}", field="elongation_limit")
    return roller_chain_pitch_radius(t * (1.0 + d), z)


def _factor(name: str, value: ArrayLike, lo: float, hi: float, what: str) -> np.ndarray:
    try:
        return check_range(name, value, lo, hi)
    except InputError:
        v = np.asarray(value, dtype=float)
        got = f"{float(v):g}" if v.ndim == 0 else str(v.tolist())
        raise InputError(f"{name} must lie in [{lo:g}, {hi:g}] for {what}, got {got}") from None


def _floats(pair: tuple[FloatOrArray, FloatOrArray]) -> tuple[float, float]:
    """Two scalar results as plain floats (internal)."""
    return float(pair[0]), float(pair[1])


@dataclass(frozen=True)
class TrackDriveWheelDimensions(Result):
    """Computed track drive wheel dimensions (m) with the paper's allowed ranges."""

    pitch: float = quantity("m")
    teeth: int = quantity("1")
    pin_radius: float = quantity("m")
    link: str
    pitch_radius: float = quantity("m")
    root_factor: float = quantity("1")
    root_factor_range: tuple[float, float] = quantity("1")
    pin_seat_radius: float = quantity("m")
    pin_seat_radius_range: tuple[float, float] = quantity("m")
    root_radius: float = quantity("m")
    root_radius_range: tuple[float, float] = quantity("m")
    tip_factor: float = quantity("1")
    tip_factor_range: tuple[float, float] = quantity("1")
    tip_radius: float = quantity("m")
    tip_radius_range: tuple[float, float] = quantity("m")
    flank_radius: float = quantity("m")
    pointed_tip_radius: float = quantity("m")
    tooth_pointed: bool
    sources: dict[str, str]
    elongation_limit: float | None = quantity("1", display="%", default=None)
    worn_tip_radius: float | None = quantity("m", default=None)
    worn_tip_factor: float | None = quantity("1", default=None)


@dataclass
class TrackDriveWheel(WheelFiles):
    """Drive wheel of a tracked vehicle engaging lantern pins (thin object, Sharipov).

    Parameters
    ----------
    pitch : float
        Track pitch (pin centre distance) ``t`` [m].
    teeth : int
        Number of teeth ``z >= 3``.
    pin_radius : float
        Pin radius ``r_ц`` [m].
    link : {"built-up", "cast"}
        Track link construction (selects the tip-factor range).
    root_factor : float, optional
        ``r_цо / r_ц`` in [1.1, 1.3]; default the middle, 1.2.
    tip_factor : float, optional
        ``(R_Г − R_о) / r_ц`` inside the range for ``link``; default its middle.
    elongation_limit : float, optional
        Largest allowed wear elongation ``Δ`` of the track pitch [-]; adds the smallest
        tip radius that holds the worn chain (:func:`worn_tip_radius`) to the dimensions.

    Examples
    --------
    >>> w = TrackDriveWheel(pitch=0.17, teeth=13, pin_radius=0.025, link="cast")
    >>> d = w.dimensions()
    >>> round(d.root_radius * 1e3, 3), round(d.tip_radius * 1e3, 3)
    (325.179, 380.179)
    """

    pitch: float
    teeth: int
    pin_radius: float
    link: str = "built-up"
    root_factor: float | None = None
    tip_factor: float | None = None
    name: str = ""
    elongation_limit: float | None = None

    def __post_init__(self) -> None:
        check_positive("pitch", self.pitch, "m")
        check_positive("pin_radius", self.pin_radius, "m")
        self.teeth = int(check_teeth("teeth", self.teeth))
        if self.elongation_limit is not None:  # as worn_tip_radius checks it (a NaN or inf is refused)
            self.elongation_limit = float(check_range("elongation_limit", self.elongation_limit, 0.0, 0.1,
                                                      low_inclusive=False))
        k_lo, k_hi = TIP_FACTOR_RANGES.get(self.link)
        if self.root_factor is None:
            self.root_factor = 0.5 * sum(PIN_SEAT_FACTOR_RANGE)
        self.root_factor = float(_factor("root_factor", self.root_factor, *PIN_SEAT_FACTOR_RANGE,
                                         "the pin seat (Sharipov: r_цо = (1.1...1.3) r_ц)"))
        if self.tip_factor is None:
            self.tip_factor = 0.5 * (k_lo + k_hi)
        self.tip_factor = float(_factor("tip_factor", self.tip_factor, k_lo, k_hi,
                                        f"{self.link} links (Sharipov: R_Г = R_о + ({k_lo}...{k_hi}) r_ц)"))
        if self.root_factor * self.pin_radius >= self.pitch / 2:
            raise InfeasibleError(
                f"pin seat radius {self.root_factor * self.pin_radius:.6g} m must be < pitch/2 = "
                f"{self.pitch / 2:.6g} m: neighbouring seats would overlap"
            )

    def _factors(self) -> tuple[float, float]:
        """``(root_factor, tip_factor)`` as numbers (set by ``__post_init__``)."""
        if self.root_factor is None or self.tip_factor is None:
            raise InputError(
                "root_factor and tip_factor must be numbers (root_factor in [1.1, 1.3], tip_factor "
                "inside the range of the link type); None is only allowed when constructing the wheel"
            )
        return float(self.root_factor), float(self.tip_factor)

    @finite_guard(check_result=False)  # a result computed afresh is checked below; a kept one was
    def dimensions(self) -> TrackDriveWheelDimensions:
        """Pitch, root and tip radii with their ranges from Sharipov, and the drawn flank."""
        # kept with the fields it was computed from (the tooth check and the worn-tip check of
        # one analysis ask for it in turn; a changed field computes it again), its warnings replayed
        fields = (self.pitch, self.teeth, self.pin_radius, self.link, self.root_factor, self.tip_factor,
                  self.elongation_limit)
        kept = self.__dict__.get("_dimensions_kept")
        if kept is not None and kept[0] == fields:
            for category, text in kept[2]:
                warnings.warn(text, category, stacklevel=2)
            return kept[1]
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            dims = self._dimensions()
        refuse_nonfinite_result("dimensions", dims)
        replay = tuple((w.category, str(w.message)) for w in caught)
        for category, text in replay:
            warnings.warn(text, category, stacklevel=2)
        self.__dict__["_dimensions_kept"] = (fields, dims, replay)
        return dims

    def _dimensions(self) -> TrackDriveWheelDimensions:
        t, z, r = self.pitch, self.teeth, self.pin_radius
        root_factor, tip_factor = self._factors()
        r0 = float(track_wheel_pitch_radius(t, z))
        rs = root_factor * r
        rb_lo, rb_hi = (float(v) for v in root_radius_range(r0, r))
        rt_lo, rt_hi = (float(v) for v in tip_radius_range(r0, r, self.link))
        rf = t - rs
        pointed_r = r0 * np.cos(np.pi / z) + np.sqrt(max(rf**2 - (t / 2) ** 2, 0.0))
        tip = float(tip_radius(r0, r, tip_factor, self.link))
        worn = None if self.elongation_limit is None else float(worn_tip_radius(t, z, self.elongation_limit))
        return TrackDriveWheelDimensions(
            pitch=t, teeth=z, pin_radius=r, link=self.link, pitch_radius=r0,
            root_factor=root_factor, root_factor_range=PIN_SEAT_FACTOR_RANGE,
            pin_seat_radius=rs, pin_seat_radius_range=_floats(pin_seat_radius_range(r)),
            root_radius=float(root_radius(r0, rs)), root_radius_range=(rb_lo, rb_hi),
            tip_factor=tip_factor, tip_factor_range=TIP_FACTOR_RANGES.get(self.link),
            tip_radius=tip, tip_radius_range=(rt_lo, rt_hi),
            flank_radius=rf, pointed_tip_radius=float(pointed_r), tooth_pointed=bool(pointed_r < tip),
            sources={
                "pitch_radius": "R_о = t / (2 sin(π/z)) (regular pin polygon; R_о named in Sharipov)",
                "root_radius": "Sharipov: R_В = R_о − r_цо, r_цо = (1.1...1.3) r_ц",
                "tip_radius": "Sharipov: R_Г = R_о + (0.2...0.5) r_ц built-up, (0.8...1.2) r_ц cast links",
                "flank_radius": "drawing construction: circle of radius t − r_цо about the neighbouring pin",
                "worn_tip_radius": "R_Г,min = t (1 + Δ) / (2 sin(π/z)): pins of the worn chain (Sharipov's rule)",
            },
            elongation_limit=None if self.elongation_limit is None else float(self.elongation_limit),
            worn_tip_radius=worn, worn_tip_factor=None if worn is None else (worn - r0) / r,
        )

    def outline(self, form: str | None = None) -> Outline:
        """Closed outline: seat arcs round each pin, convex flanks, tip arcs at ``R_Г``.

        Examples
        --------
        >>> o = TrackDriveWheel(0.17, 13, 0.025).outline()
        >>> sorted(o.circles), len(o.centres), o.closure_gap() < 1e-12   # a pin centre per tooth
        (['ROOT', 'TIP'], 13, True)
        """
        d = self.dimensions()
        z, t, rs, r0 = self.teeth, self.pitch, d.pin_seat_radius, d.pitch_radius
        half = np.pi / z
        p0 = np.array([0.0, r0])
        u = np.array([np.cos(half), -np.sin(half)])
        q = p0 + t * u
        phi_s = np.pi - half
        phi_t, tip, pointed = _convex_flank_to_tip(q, t - rs, phi_s, d.tip_radius, half)
        right: list[Primitive] = _tip_half(tip, half, pointed)
        right.append(Arc(_pair(q), t - rs, phi_t, phi_s - phi_t))
        right.append(Arc(_pair(p0), rs, -half, -(np.pi / 2 - half)))
        right = _drop_short(right)
        left = [p.mirrored_x() for p in reversed(right)]
        ang = np.pi / 2 + 2 * np.pi * np.arange(z) / z
        centres = np.stack([r0 * np.cos(ang), r0 * np.sin(ang)], axis=-1)
        return Outline(_repeat(right + left, z), r0, centres, {"ROOT": d.root_radius, "TIP": d.tip_radius})

    def label(self) -> str:
        return f"Track drive wheel z = {self.teeth}, {self.link} links (Sharipov)"
