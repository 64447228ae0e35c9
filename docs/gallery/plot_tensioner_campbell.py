"""
Resonance-free slack span with a tensioner
==========================================

The tensioner paper: the slack span is split by the tensioner sprocket into two parts;
its natural frequencies P1, P2, P3 (frequency equation (11)/(12)) must stay out of the
band ``0.7 ≤ P/ω ≤ 1.4`` of each exciting frequency (driving sprocket, driven sprocket,
meshing). The Campbell diagram shows the frequencies against the driving sprocket's
speed; the resonance map shows which tensioner masses and stiffnesses are safe over the
whole speed range.
"""

import dataclasses
import math

import numpy as np

from chaindrive.plotting.vibration import campbell_plot, resonance_map_plot
from chaindrive.vibration import TensionerSpan, campbell, propose_safe_tensioner, resonance_map

span = TensionerSpan(tension=2000.0, mass_per_length=2.6, length_1=0.8, length_2=0.8,
                     angle_1=math.radians(20), angle_2=math.radians(20),
                     mass=30.0, stiffness=2e4)
speed_range = (25.0, 38.0)  # rad/s of the driving sprocket (239–363 rpm)

diagram = campbell(span, (10.0, 100.0), ratio=2.5, teeth=17, speeds=120, design_speed=31.4)
fig = campbell_plot(diagram)

# %%
# Which tensioners are safe over the whole speed range, and the nearest safe one:
proposal = propose_safe_tensioner(span, speed_range, ratio=2.5, teeth=17, points=81)
chart = resonance_map(span, np.geomspace(1, 300, 60), np.geomspace(1e3, 1e6, 60), speed_range,
                      ratio=2.5, teeth=17)
chart = dataclasses.replace(chart, proposal=(proposal.mass, proposal.stiffness))
fig2 = resonance_map_plot(chart)
print(f"nearest safe tensioner: {proposal.mass:.1f} kg, {proposal.stiffness / 1e3:.1f} kN/m")
