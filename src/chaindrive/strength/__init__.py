"""Strength and life of wheels and chains: contact, skew, fretting, track wheel teeth, bolts.

Modules
-------
hertz
    Hertz line contact (two materials) and Garshniev & Maksymovych form ``0.418 sqrt(Q E/(L ρ))``.
skew
    Roller–tooth contact with skew of the roller axis (Garshniev & Maksymovych, paper 2), life vs skew.
fretting
    Fretting latent period (Vikulov, Penza) and the multi-row pin as a beam.
track_tooth
    Tooth of a track drive wheel in bending and contact (Sharipov).
bolts
    Bolts of the toothed rim: fitted bolts in shear, friction joints (VDI 2230).

Models, sources and decisions: ``docs/strength.md``.

Examples
--------
>>> from chaindrive import strength
>>> round(strength.skew_paper_contact_coefficient(0.3), 3)
0.418
"""

from .._deprecation import renamed_attributes as _renamed_attributes
from .bolts import (
    FittedBoltResult,
    FrictionBoltResult,
    bolt_force_from_torque,
    bolt_stress_area,
    fitted_bolt_check,
    friction_bolt_preload,
)
from .fretting import (
    END_FIXITIES,
    BeamSolution,
    FrettingComparison,
    MultiRowPin,
    PinBendingResult,
    beam_solve,
    fretting_comparison,
    fretting_latent_period,
)
from .hertz import (
    CONTACT_KINDS,
    STEEL_ELASTIC_MODULUS,
    STEEL_POISSON_RATIO,
    effective_modulus,
    hertz_line_half_width,
    hertz_line_pressure,
    reduced_radius,
    skew_paper_contact_coefficient,
    skew_paper_contact_stress,
)
from .skew import (
    ARCMIN,
    GAMMA_INTERPOLATIONS,
    GAMMA_TABLE_PITCH,
    GAMMA_TABLE_VALUE,
    LIFE_MODELS,
    MEASURED_SKEW_RANGE,
    WEAR_FACTOR_RANGE,
    RollerContactResult,
    RollerToothContact,
    design_skew,
    relative_life,
    roller_contact_stress,
    skew_from_measurement,
    skew_gamma,
    skew_load_factor,
)
from .track_tooth import (
    DESIGN_WEIGHT_SHARE,
    HARDNESS_RANGE,
    TrackToothResult,
    check_hardness,
    pin_tooth_contact_stress,
    tooth_bending_stress,
    track_design_force,
    track_tooth_check,
    track_tooth_section,
)

__all__ = [
    "FittedBoltResult", "FrictionBoltResult", "bolt_force_from_torque", "bolt_stress_area",
    "fitted_bolt_check", "friction_bolt_preload",
    "END_FIXITIES", "BeamSolution", "FrettingComparison", "MultiRowPin", "PinBendingResult",
    "beam_solve", "fretting_comparison", "fretting_latent_period",
    "CONTACT_KINDS", "STEEL_ELASTIC_MODULUS", "STEEL_POISSON_RATIO", "effective_modulus",
    "hertz_line_half_width", "hertz_line_pressure", "reduced_radius", "skew_paper_contact_coefficient",
    "skew_paper_contact_stress",
    "ARCMIN", "GAMMA_INTERPOLATIONS", "GAMMA_TABLE_PITCH", "GAMMA_TABLE_VALUE", "LIFE_MODELS",
    "MEASURED_SKEW_RANGE", "WEAR_FACTOR_RANGE", "RollerContactResult", "RollerToothContact",
    "design_skew", "relative_life", "roller_contact_stress", "skew_from_measurement", "skew_gamma",
    "skew_load_factor",
    "DESIGN_WEIGHT_SHARE", "HARDNESS_RANGE", "TrackToothResult", "check_hardness",
    "pin_tooth_contact_stress", "tooth_bending_stress", "track_design_force", "track_tooth_check",
    "track_tooth_section",
]


# former public names (renamed; deprecated, removed in the next release: chaindrive._deprecation)
__getattr__ = _renamed_attributes(
    "chaindrive.strength",
    {"seed_contact_stress": "skew_paper_contact_stress",
     "seed_contact_coefficient": "skew_paper_contact_coefficient"})
