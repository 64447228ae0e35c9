"""
Forced entry of a round link chain onto a pocket wheel
======================================================

Dolipiński et al., Figs 2 and 3: the chain's velocity and acceleration over one pocket
period for free entry, chordal entry (guide at ``H = R cos(δ1/2)``) and tangential entry
(guide at ``H = R``). Worked case of the paper: chain Ø18×64, ``z = 8``,
``ω = 5 rad/s`` (47.7 rpm), guide end ``l = 0.256 m`` from the wheel axis.

The curves come from the corrected closed forms (eqs 14–43), which the test suite checks
against an independent solver of the same mechanism; tangential entry has no sign change
of the acceleration at the end of the period and the smallest extreme accelerations, as
the paper concludes.
"""

from chaindrive.kinematics import dolipinski_worked_case
from chaindrive.plotting.kinematics import kinematics_plot

cases = dolipinski_worked_case(points=361)
fig = kinematics_plot(cases)

for name, result in cases.items():
    print(f"{name:>12}: acceleration from {result.acceleration.min():7.3f} "
          f"to {result.acceleration.max():7.3f} m/s²")
