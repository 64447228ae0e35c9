"""The ``[self_regulating]`` table of a project: the carrier of one wheel (the description;
the model is :mod:`chaindrive.self_regulating`, its analysis :mod:`chaindrive.analysis.self_regulating`)."""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from .._validation import check_nonnegative, check_positive, check_range
from ..errors import InputError
from ..self_regulating.statics import _kind, _point, _reaction

# --------------------------------------------------------------------------- spec and Drive

__all__ = [
    "SelfRegulatingSpec",
]

def _pair(name: str, value) -> tuple[float, float] | None:
    if value is None:
        return None
    arr = _point(name, value)
    return (float(arr[0]), float(arr[1]))


@dataclass(frozen=True)
class SelfRegulatingSpec:
    """The ``[self_regulating]`` table of a project: the carrier of one wheel (SI units).

    Parameters
    ----------
    wheel : str
        Name of the wheel on the carrier (one of the two wheels of the drive).
    kind : {"pivot", "slide"}
        Swinging carrier (pivoted base) or straight slide.
    pivot : (float, float), optional
        Pivot position in the drive's coordinates [m] (``kind="pivot"``).
    direction : (float, float), optional
        Slide direction (``kind="slide"``) [-].
    torque_reaction : {"carrier", "frame"}
        Where the wheel's torque is reacted: on the carrier (motor or gear unit on it,
        the self-regulating arrangement) or on the frame (only the bearing force acts).
    weight : float
        Weight of the carrier and all it carries [N].
    weight_offset : (float, float)
        Its centre of gravity relative to the wheel centre at the given position [m].
    stiffness : float
        Spring stiffness [N·m/rad] (pivot) or [N/m] (slide).
    preload : float
        Spring force at the given position, positive outward [N·m] (pivot) or [N] (slide).
    load_max_factor : float
        Largest torque / nominal torque of the load grid (> 0).
    load_steps : int
        Load steps over ``[0, load_max_factor]`` (>= 2; 1 is added).
    elongation_steps : int
        Elongation steps over ``[0, elongation_limit]`` of the drive (>= 2).
    sag_allowance : float, optional
        Sag / chord allowed at the rated load; default the drive's ``slack_sag_ratio``.
    psi_tolerance : float
        Accepted excess of ``S2/F_t`` over the rational ψ at the rated load [-].
    numerical : bool
        Cross-check every grid point with the full equilibrium.
    inertia : float, optional
        Carrier's moment of inertia about the pivot [kg·m²] (pivot) or mass [kg]
        (slide), for its natural frequency; default from ``weight`` as a point mass.
    axial_stiffness : float, optional
        Chain axial stiffness ``EA`` [N]; default: for a round link chain
        ``EA = 0.854e11 d²`` N (studless chain, OrcaFlex documentation), for a roller
        chain none (inextensible).

    Examples
    --------
    >>> SelfRegulatingSpec(wheel="motor", pivot=(0.66, -0.045), weight=400.0).kind
    'pivot'
    """

    wheel: str
    kind: str = "pivot"
    pivot: tuple[float, float] | None = None
    direction: tuple[float, float] | None = None
    torque_reaction: str = "carrier"
    weight: float = 0.0
    weight_offset: tuple[float, float] = (0.0, 0.0)
    stiffness: float = 0.0
    preload: float = 0.0
    load_max_factor: float = 1.5
    load_steps: int = 7
    elongation_steps: int = 4
    sag_allowance: float | None = None
    psi_tolerance: float = 1.0
    numerical: bool = True
    inertia: float | None = None
    axial_stiffness: float | None = None

    @classmethod
    def from_table(cls, table: Mapping[str, Any]) -> SelfRegulatingSpec:
        """Build the spec from a project file's ``[self_regulating]`` table, parsing units.

        Parameters
        ----------
        table : mapping
            Keys as the fields; quantities as numbers (SI) or strings with units
            (``"660 mm"``, ``"400 N"``, ``"50 N*m/rad"``, ``"5 kN/m"``); ``pivot``,
            ``direction`` and ``weight_offset`` as pairs.

        Returns
        -------
        SelfRegulatingSpec

        Raises
        ------
        InputError
            An unknown key (the message lists the valid ones), a value that is not a
            number with a unit of the right dimension, or a field out of its range.

        Examples
        --------
        >>> spec = SelfRegulatingSpec.from_table({"wheel": "motor", "pivot": ["660 mm", "-45 mm"],
        ...     "weight": "0.4 kN", "weight_offset": ["80 mm", 0], "stiffness": "50 N*m/rad"})
        >>> spec.pivot, spec.weight, spec.stiffness
        ((0.66, -0.045), 400.0, 50.0)
        """
        from ..units import parse_quantity

        try:
            items = dict(table)
        except (TypeError, ValueError) as exc:
            raise InputError(f"self_regulating must be a table, got {table!r}") from exc
        names = [f.name for f in dataclasses.fields(cls)]
        unknown = sorted(set(items) - set(names))
        if unknown:
            raise InputError(f"self_regulating: unknown key(s) {', '.join(unknown)}; valid keys: "
                             f"{', '.join(names)}")
        pivot = items.get("kind", "pivot") == "pivot"
        units = {"weight": "N", "stiffness": "N*m/rad" if pivot else "N/m",
                 "preload": "N*m" if pivot else "N", "load_max_factor": "",
                 "sag_allowance": "", "psi_tolerance": "",
                 "inertia": "kg*m^2" if pivot else "kg", "axial_stiffness": "N"}
        pairs = {"pivot": "m", "weight_offset": "m", "direction": ""}
        out: dict[str, Any] = {}
        for key, value in items.items():
            field = f"self_regulating.{key}"
            if key in units and value is not None:
                out[key] = parse_quantity(value, units[key], field=field)
            elif key in pairs and value is not None:
                if not isinstance(value, (list, tuple)) or len(value) != 2:
                    raise InputError(f"{field} must be a pair (x, y), got {value!r}")
                out[key] = tuple(parse_quantity(v, pairs[key], field=field) for v in value)
            else:
                out[key] = value
        missing = [f.name for f in dataclasses.fields(cls)
                   if f.default is dataclasses.MISSING and f.default_factory is dataclasses.MISSING
                   and f.name not in out]
        if missing:
            raise InputError(f"self_regulating: required key(s) missing: {', '.join(missing)}")
        return cls(**out)

    def __post_init__(self):
        _kind(self.kind)
        _reaction(self.torque_reaction)
        if self.kind == "pivot" and self.pivot is None:
            raise InputError("self_regulating.pivot: a pivoted carrier needs the pivot (x, y) in m")
        if self.kind == "slide" and self.direction is None:
            raise InputError("self_regulating.direction: a sliding carrier needs the slide direction (x, y)")
        object.__setattr__(self, "pivot", _pair("self_regulating.pivot", self.pivot))
        object.__setattr__(self, "direction", _pair("self_regulating.direction", self.direction))
        if self.direction is not None and not np.hypot(*self.direction) > 0:
            raise InputError("self_regulating.direction must be a non-zero 2-vector")
        object.__setattr__(self, "weight_offset", _pair("self_regulating.weight_offset", self.weight_offset))
        check_nonnegative("self_regulating.weight", self.weight, "N")
        check_nonnegative("self_regulating.stiffness", self.stiffness)
        check_range("self_regulating.preload", self.preload)
        if not math.isfinite(float(self.preload)):
            raise InputError(f"self_regulating.preload must be finite, got {self.preload!r}")
        check_positive("self_regulating.load_max_factor", self.load_max_factor)
        for name in ("load_steps", "elongation_steps"):
            v = getattr(self, name)
            if isinstance(v, bool) or not isinstance(v, (int, np.integer)) or v < 2:
                raise InputError(f"self_regulating.{name} must be a whole number >= 2, got {v!r}")
        if self.sag_allowance is not None:
            check_range("self_regulating.sag_allowance", self.sag_allowance, 0.0, 0.5,
                        low_inclusive=False)
        check_nonnegative("self_regulating.psi_tolerance", self.psi_tolerance)
        if self.inertia is not None:
            check_positive("self_regulating.inertia", self.inertia, "kg·m² or kg")
        if self.axial_stiffness is not None:
            check_positive("self_regulating.axial_stiffness", self.axial_stiffness, "N")
