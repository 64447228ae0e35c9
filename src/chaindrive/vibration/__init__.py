"""Transverse vibration of chain spans and the resonance check of the tensioner paper.

* :func:`moving_string_frequencies`: a free span as an axially moving string.
* :func:`tensioner_frequencies`: the slack span split by a tensioner (the tensioner paper,
  eqs (1)-(12), frequency equation re-derived), vectorised and robust for every
  m >= 0, 0 <= C <= inf; :func:`fe_tensioner_frequencies` is the independent check.
* :func:`static_rod_force` (eq. 8), :func:`heavy_tensioner_frequency` (eq. 13 fixed).
* :func:`reduced_tensioner`: mass and stiffness reduced to the tensioner axis.
* :func:`resonance_check`, :func:`campbell`, :func:`resonance_map`,
  :func:`propose_safe_tensioner`: the 0.7 <= P/ω <= 1.4 check and design help;
  :func:`span_vibration` bundles one design's results (``.to_dict()``, ``.plot()``).

Derivations and figures: docs/vibration.md.
"""

from .resonance import (
    BAND,
    TENSIONER_REDUCTIONS,
    ReducedTensioner,
    ResonanceCheck,
    TensionerSpan,
    excitation_frequencies,
    excitation_multipliers,
    reduced_tensioner,
    resonance_check,
    resonance_margin,
)
from .string import moving_string_frequencies, wave_speed
from .tensioner import (
    COUPLING_MODELS,
    fe_tensioner_frequencies,
    frequency_function,
    heavy_tensioner_frequency,
    heavy_tensioner_validity,
    pole_free_function,
    span_parameters,
    static_rod_force,
    tensioner_frequencies,
)
from .tensioner_design import (
    CampbellResult,
    ResonanceMapResult,
    SafeTensioner,
    SpanVibration,
    campbell,
    propose_safe_tensioner,
    resonance_map,
    span_vibration,
)

__all__ = [
    "BAND",
    "COUPLING_MODELS",
    "TENSIONER_REDUCTIONS",
    "CampbellResult",
    "ReducedTensioner",
    "ResonanceCheck",
    "ResonanceMapResult",
    "SafeTensioner",
    "SpanVibration",
    "TensionerSpan",
    "campbell",
    "excitation_frequencies",
    "excitation_multipliers",
    "fe_tensioner_frequencies",
    "frequency_function",
    "heavy_tensioner_frequency",
    "heavy_tensioner_validity",
    "moving_string_frequencies",
    "pole_free_function",
    "propose_safe_tensioner",
    "reduced_tensioner",
    "resonance_check",
    "resonance_map",
    "resonance_margin",
    "span_parameters",
    "span_vibration",
    "static_rod_force",
    "tensioner_frequencies",
    "wave_speed",
]
