"""
Pocket wheel for a round link chain
===================================

Dolipiński et al., eq. 6: the hinge centres of a round link chain on its pocket wheel form
a bi-regular polygon with sides ``t + d`` and ``t − d``; pitch radius
``R = ½·sqrt((t / sin(π/2z))² + (d / cos(π/2z))²)``. Chain Ø18×64 on 8 pockets, the
paper's worked case.
"""

from chaindrive.geometry.pocket_wheel import PocketWheel
from chaindrive.plotting.geometry import geometry_plot

wheel = PocketWheel(pitch=0.064, bar_diameter=0.018, teeth=8)
fig = geometry_plot(wheel)
print(f"pitch radius R = {wheel.dimensions().pitch_radius * 1e3:.2f} mm")
