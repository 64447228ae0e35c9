"""The drive over its life: wear elongation, jump-over, fatigue and efficiency (formulas).

One module per topic, each a set of pure vectorised functions in SI units:

- :mod:`~chaindrive.life.elongation`: the elongation over running hours (the steady wear
  law of :mod:`chaindrive.wear`, calibrated to the ANSI/ACA rating basis) and the makers'
  replacement limit by tooth count.
- :mod:`~chaindrive.life.jump_over`: where the rollers of a worn chain seat on the ISO 606
  tooth form, the tension ratio a seated roller carries, the tight-side tension at which
  the chain rides over the teeth, and the elongation the tooth form can hold at all.
- :mod:`~chaindrive.life.fatigue`: rainflow counting of a link's tension history, a link
  plate S–N curve tied to the rating basis, Miner's rule.
- :mod:`~chaindrive.life.efficiency`: the power lost by articulation friction at the
  engagement and disengagement of every joint.

The drive-level decisions are the analysis part :mod:`chaindrive.analysis.life`.
"""

from . import efficiency, elongation, fatigue, jump_over, jump_table, wrap_statics
from .efficiency import *  # noqa: F403
from .elongation import *  # noqa: F403
from .fatigue import *  # noqa: F403
from .jump_over import *  # noqa: F403
from .jump_table import *  # noqa: F403
from .wrap_statics import *  # noqa: F403

__all__ = [*elongation.__all__, *jump_over.__all__, *jump_table.__all__, *fatigue.__all__, *efficiency.__all__,
           *wrap_statics.__all__]
