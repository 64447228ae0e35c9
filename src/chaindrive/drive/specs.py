"""The optional tables of a drive description: contact with skew, track wheel strength and
its rim bolts, the conveyor crawler drive, fretting of multi-strand chains, the scraper
conveyor (frozen dataclasses, SI units). :class:`chaindrive.drive.model.Drive` holds them;
they are re-exported there."""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from ..errors import InputError
from ._fields import _finite, _whole

__all__ = ["ContactSpec", "RimBoltsSpec", "TrackSpec", "CrawlerSpec", "FrettingSpec", "RETURN_STRANDS", "Conveyor"]


@dataclass(frozen=True)
class ContactSpec:
    """Roller–tooth contact with skew (Garshniev & Maksymovych), for roller chains.

    Parameters
    ----------
    skew : float, optional
        Largest measured skew ``φ_p,max`` [rad]; or give the measurement below.
    skew_height_difference, skew_base : float, optional
        Measured height difference ``Δh`` over the base ``B`` [m]: ``φ = atan(Δh/B)``.
    wear_factor : float
        ``K_φ`` [-] (Garshniev & Maksymovych: 0.6…0.7).
    seat_radius, contact_length : float, optional
        Tooth seat radius and contact length [m] (default from ISO 606 and the chain).
    """

    skew: float | None = None
    skew_height_difference: float | None = None
    skew_base: float | None = None
    wear_factor: float = 0.65
    seat_radius: float | None = None
    contact_length: float | None = None

    def __post_init__(self) -> None:
        from .schema import check_rules

        check_rules(self, "contact")  # the rules declared for the reader too (chaindrive.drive.tables)


@dataclass(frozen=True)
class RimBoltsSpec:
    """Bolts fastening a toothed rim to the hub (Sharipov, Fig. 14), ``[track.bolts]``.

    Parameters
    ----------
    count : int
        Bolts per rim ``n``.
    circle_radius : float
        Bolt circle radius ``R_b`` [m].
    diameter : float
        Fitted shank diameter ``d`` (``joint = "fitted"``) or nominal thread diameter
        (``joint = "friction"``) [m].
    joint : {"fitted", "friction"}
        Fitted bolts in shear, or a friction (slip-resistant) joint.
    shear_planes : int
        Shear planes ``m`` of a fitted bolt.
    plate_thickness : float, optional
        Thinnest clamped part for the bearing check [m].
    allowable_shear, allowable_bearing : float, optional
        [Pa] (fitted joint).
    friction : float
        Friction coefficient ``μ`` (friction joint).
    friction_faces : int
        Friction interfaces ``q``.
    slip_safety : float
        ``S >= 1`` (friction joint).
    thread_pitch : float, optional
        Thread pitch [m] for the stress area (friction joint).
    yield_strength : float, optional
        ``R_p0.2`` [Pa] (friction joint).
    """

    count: int
    circle_radius: float
    diameter: float
    joint: str = "fitted"
    shear_planes: int = 1
    plate_thickness: float | None = None
    allowable_shear: float | None = None
    allowable_bearing: float | None = None
    friction: float = 0.15
    friction_faces: int = 1
    slip_safety: float = 1.25
    thread_pitch: float | None = None
    yield_strength: float | None = None

    def __post_init__(self) -> None:
        if self.joint not in ("fitted", "friction"):
            raise InputError(f"track.bolts.joint must be 'fitted' or 'friction', got {self.joint!r}",
                             field="track.bolts.joint")
        _whole(self.count, "track.bolts.count", 1, 1000)
        from .schema import check_declared

        check_declared(self, "track.bolts", ("circle_radius", "diameter", "plate_thickness", "allowable_shear",
                                             "allowable_bearing", "friction", "slip_safety", "thread_pitch",
                                             "yield_strength"))  # declared once (chaindrive.drive.tables)


@dataclass(frozen=True)
class TrackSpec:
    """Track drive wheel strength inputs (Sharipov, p. 34).

    Parameters
    ----------
    tractor_weight : float
        ``G_T`` [N].
    tooth_width : float
        [m].
    pin_radius : float
        Track pin radius ``r_ц`` [m].
    adhesion : float
        ``φ`` [-].
    rims : {1, 2}
        Toothed rims ``i``.
    link : {"built-up", "cast"}
    hardness : float, optional
        Surface hardness [HRC].
    allowable_bending, allowable_contact : float, optional
        [Pa].
    bolts : RimBoltsSpec, optional
        The rim's bolts (Sharipov, Fig. 14); a mapping of its fields is accepted.
    """

    tractor_weight: float
    tooth_width: float
    pin_radius: float
    adhesion: float = 1.0
    rims: int = 1
    link: str = "cast"
    hardness: float | None = None
    allowable_bending: float | None = None
    allowable_contact: float | None = None
    bolts: RimBoltsSpec | None = None

    def __post_init__(self) -> None:
        object.__setattr__(self, "bolts", _spec(self.bolts, RimBoltsSpec, "track.bolts"))


@dataclass(frozen=True)
class CrawlerSpec:
    """The conveyor crawler drive (the crawler drive text), ``[crawler]``.

    The drive's two toothed wheels are the driving and the tensioning sprocket of the drive
    chain (same tooth count, a whole number of pitches apart); the cams on the drive chain
    push the hinges of the conveyor's traction chain.

    Parameters
    ----------
    stiffness : float
        Reduced stiffness ``E_П`` of the drive chain as axial rigidity ``EA`` [N].
    guide : {"tangent", "none"}
        Guide holding the chain axis tangent to the pitch circles, or none.
    cam_distance : float, optional
        Distance ``l`` of the engaged cam's hinge from the tensioning sprocket [m]; or give
        ``engagement_distance`` (``l1``), ``cam_pitch`` (``t_K``) and ``cam_index`` (``k``):
        ``l = l1 + k t_K``.
    cam_face_angle : float
        Pressure angle ``α`` of the cam's working face [rad] (the pushing-off force
        ``P tan α`` on the guide); ``0 <= α < π/2``.
    return_guide : {"none", "tangent"}
        Guide of the return span (for the elastic-loop check).
    """

    stiffness: float
    guide: str = "tangent"
    cam_distance: float | None = None
    engagement_distance: float | None = None
    cam_pitch: float | None = None
    cam_index: int = 0
    cam_face_angle: float = 0.0
    return_guide: str = "none"

    def __post_init__(self) -> None:
        from .schema import check_declared

        check_declared(self, "crawler", ("stiffness",))  # declared once (chaindrive.drive.tables)
        for name in ("guide", "return_guide"):
            if getattr(self, name) not in ("tangent", "none"):
                raise InputError(f"crawler.{name} must be 'tangent' or 'none', got {getattr(self, name)!r}",
                                 field=f"crawler.{name}")
        if self.cam_distance is None:
            if self.engagement_distance is None:
                raise InputError("crawler: give cam_distance (l > 0 m), or engagement_distance (l1 > 0 m) with "
                                 "cam_pitch and cam_index (l = l1 + k t_K)", field="crawler.cam_distance")
            l1 = _finite(self.engagement_distance, "crawler.engagement_distance", positive=True)
            k = self.cam_index
            _whole(k, "crawler.cam_index", 0)
            tk = 0.0 if k == 0 else _finite(self.cam_pitch, "crawler.cam_pitch", positive=True)
            object.__setattr__(self, "cam_distance", l1 + int(k) * tk)
        object.__setattr__(self, "cam_distance", _finite(self.cam_distance, "crawler.cam_distance", positive=True))
        a = _finite(self.cam_face_angle, "crawler.cam_face_angle", nonnegative=True)
        if not a < math.pi / 2:
            raise InputError(f"crawler.cam_face_angle must lie in [0, 90) deg, got {math.degrees(a):g} deg",
                             field="crawler.cam_face_angle")


@dataclass(frozen=True)
class FrettingSpec:
    """Fretting of a multi-strand roller chain (Vikulov), ``[fretting]``.

    Parameters
    ----------
    roughness : float
        ``Ra`` of the pin and bushing surfaces [m].
    latent_coefficient : float
        ``K1`` of ``τ = K1 Ra exp(−k2 A N f / Ra)`` [s/m].
    decay_coefficient : float
        ``k2 = −K2 > 0`` [s/N].
    frequency : float, optional
        Load frequency ``f`` [Hz]; default the tooth frequency of the driving wheel.
    """

    roughness: float
    latent_coefficient: float
    decay_coefficient: float
    frequency: float | None = None


#: How the return strand of a conveyor runs: on the bottom pans or hanging free.
RETURN_STRANDS = ("supported", "free")


@dataclass(frozen=True)
class Conveyor:
    """A scraper (drag) chain conveyor: the pans, the conveyed material, the drives.

    The carrying strand is the span arriving at the driving wheel (the head); it lies
    on the pans with the material scraped along them. The tail is the wheel it comes
    from. The other spans are the return strand: on the bottom pans
    (``return_strand = "supported"``: every return span longer than a quarter of the
    carrying strand; the short spans round a tensioner hang free) or hanging free.

    Parameters
    ----------
    chain_friction : float
        Friction coefficient of the chain on the pans ``μ`` (0 … 1.5).
    material_friction : float
        Friction coefficient of the material on the pans ``μ_m`` (0 … 1.5).
    material_load : float, optional
        Material per metre on the carrying strand ``q_m`` [kg/m]; or give ``capacity``.
    capacity : float, optional
        Mass flow [kg/s] (``q_m = Q / v``).
    inclination : float
        Inclination of the conveyor [rad], positive when the head is higher
        (conveying uphill), ``|α| <= 45°``.
    return_strand : {"supported", "free"}
    return_friction : float, optional
        ``μ`` of the return strand on the bottom pans; default ``chain_friction``.
    head_share : float
        Share of the drive force taken by the head drive, ``0 < share <= 1``; below 1
        the tail wheel drives too and takes the rest.
    minimum_tension : float
        Smallest tension wanted at every sprocket exit [N] (>= 0).
    efficiency : float
        Efficiency of each drive between motor and sprocket, ``0 < η <= 1``.
    """

    chain_friction: float = 0.4
    material_friction: float = 0.6
    material_load: float | None = None
    capacity: float | None = None
    inclination: float = 0.0
    return_strand: str = "supported"
    return_friction: float | None = None
    head_share: float = 1.0
    minimum_tension: float = 2000.0
    efficiency: float = 1.0

    def __post_init__(self) -> None:
        from .schema import check_declared

        if self.material_load is not None and self.capacity is not None:
            raise InputError("conveyor: give material_load or capacity, not both", field="conveyor.capacity")
        # bounds declared once, for the reader too (chaindrive.drive.tables)
        check_declared(self, "conveyor", ("chain_friction", "material_friction", "return_friction", "material_load",
                                          "capacity", "head_share", "minimum_tension", "efficiency"))
        a = _finite(self.inclination, "conveyor.inclination")
        if abs(a) > math.pi / 4:
            raise InputError(f"conveyor.inclination must lie in [-45°, 45°], got {math.degrees(a):.4g}°",
                             field="conveyor.inclination")
        object.__setattr__(self, "inclination", a)
        if self.return_strand not in RETURN_STRANDS:
            raise InputError(f"conveyor.return_strand must be one of {', '.join(RETURN_STRANDS)}, got "
                             f"{self.return_strand!r}", field="conveyor.return_strand")

    @property
    def return_on_pans(self) -> bool:
        """True when the return strand lies on the bottom pans."""
        return self.return_strand == "supported"

    @property
    def return_pan_friction(self) -> float:
        """``μ`` of the return strand on the bottom pans."""
        return self.chain_friction if self.return_friction is None else float(self.return_friction)

    def material_mass_per_length(self, chain_speed: float) -> float:
        """``q_m`` [kg/m]: given, or ``capacity / chain_speed``."""
        if self.material_load is not None:
            return float(self.material_load)
        if self.capacity is not None:
            from ..conveyor import material_mass_per_length

            return float(material_mass_per_length(self.capacity, chain_speed))
        return 0.0


def _spec(value: Any, cls: type, what: str) -> Any:
    if value is None or isinstance(value, cls):
        return value
    if isinstance(value, Mapping):
        names = {f.name for f in dataclasses.fields(cls)}
        unknown = sorted(set(value) - names)
        if unknown:
            raise InputError(f"{what}: unknown field(s) {', '.join(unknown)}; valid: {', '.join(sorted(names))}",
                             field=what)
        return cls(**value)
    raise InputError(f"{what} must be a {cls.__name__}, got {type(value).__name__}", field=what)


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
