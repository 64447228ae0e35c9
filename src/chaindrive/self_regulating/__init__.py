r"""The self-regulating chain drive: slack tension set by the load and the wear through
the centre distance, with the regulation coefficient ψ.

One wheel of a two-wheel drive sits on a *carrier*: a plate that swings about a pivot
(``kind="pivot"``, the pivoted or "reactive-torque" motor base) or runs along a straight
slide (``kind="slide"``). The chain length (whole links, lengthened by wear) fixes the
centre distance ``a`` and so the carrier position; the balance of the carrier under the
two span tensions, its weight and an optional spring fixes the tensions:

.. math::
    S_2 = \psi\,F_t + S_0,\qquad
    \psi = -\frac{g_1}{g_1 + g_2},\qquad S_0 = -\frac{Q_r}{g_1 + g_2}

with ``F_t`` the effective pull, ``g_1, g_2`` the generalized lever arms of the tight
and slack spans (virtual work of a unit span tension per unit carrier coordinate) and
``Q_r`` the generalized force of weight and spring. When the wheel's torque is reacted
on the carrier (the motor or gear unit sits on it), ``ψ`` is positive for a pivot placed
between the spans nearer the tight one: the slack tension grows with the load. As the
chain wears the carrier moves, the arms change, and so does ψ; the range of ``a`` the
wear covers must keep ψ near its rational value.

What is whose
-------------
The self-regulating drive paper survives only in its conclusions: a sprocket design
that regulates the chain tightening with the useful load, the influence of the
geometric parameters of sprocket and transmission on the regulation, and a coefficient
ψ that stays close to its most rational value over the limits of change of the centre
distance ``a`` caused by chain wear. Everything else here is derived in this package
(``docs/self_regulating.md``): the carrier statics, the definition of ψ as the
load-proportional part ``∂S2/∂F_t`` (a reconstruction), the wear and sag coupling, and
the rational ψ (the smallest slack tension that keeps the slack span's sag within the
allowance at the rated load). The closed forms are checked against a full numerical
equilibrium (:func:`solve_equilibrium`: exact polygon chain length, catenary spans,
moments from the tangent points, Brent's method).

Layers: pure vectorised closed forms (:func:`worn_centre_distance`,
:func:`carrier_position`, :func:`span_arms`, :func:`regulation_coefficient`,
:func:`slack_tension`, :func:`restoring_force`, :func:`sag_length_excess`,
:func:`pivot_offset_for_coefficient`, :func:`sag_stiffness`,
:func:`carrier_natural_frequency`); the full equilibrium :func:`solve_equilibrium`
and the design helper :func:`rational_pivot` on a :class:`CarrierGeometry`; the grid
solver :func:`self_regulating_drive` returning :class:`SelfRegulatingDriveResult`;
:class:`chaindrive.drive.carrier.SelfRegulatingSpec` (the ``[self_regulating]`` table of a
project) and :func:`chaindrive.analysis.self_regulating.self_regulating_analysis` for a
:class:`chaindrive.drive.Drive`. Plot: :func:`chaindrive.plotting.self_regulating.self_regulating_plot`.

Modules: :mod:`~chaindrive.self_regulating.statics` (the carrier statics),
:mod:`~chaindrive.self_regulating.sag` (sag coupling, stiffness, frequency),
:mod:`~chaindrive.self_regulating.equilibrium` (numerical equilibrium, rational pivot),
:mod:`~chaindrive.self_regulating.grid` (the load and wear grid).

References
----------
Self-regulating drive paper (conclusions). E. J. Bees, "Motor base how-to", *Power
Transmission Design* (Overly Hautz Motor Base Co.): spring-loaded and reactive-torque
(pivoted) motor bases that change the centre distance with the load. ISO 10823:2004
(chain length and centre distance). Irvine, H. M., *Cable Structures*, MIT Press 1981,
ch. 1 (catenary and the parabolic length excess).
"""

from . import statics as _statics
from .equilibrium import CarrierGeometry, rational_pivot, solve_equilibrium
from .grid import SelfRegulatingDriveResult, self_regulating_drive
from .sag import (
    carrier_natural_frequency,
    pivot_offset_for_coefficient,
    sag_length_excess,
    sag_stiffness,
)
from .statics import *  # noqa: F403 - the carrier statics, named once in statics.__all__

__all__ = [
    *_statics.__all__,
    "sag_length_excess",
    "pivot_offset_for_coefficient",
    "sag_stiffness",
    "carrier_natural_frequency",
    "CarrierGeometry",
    "solve_equilibrium",
    "rational_pivot",
    "self_regulating_drive",
    "SelfRegulatingDriveResult",
]
