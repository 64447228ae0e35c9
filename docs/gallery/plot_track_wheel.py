"""
Drive wheel of a tracked tractor
================================

Sharipov, *Design of tractor running systems*, p. 34: the drive wheel engages the pins of
the track links; root radius ``R_В = R_о − r_цо`` with the pin-seat radius
``r_цо = (1.1…1.3) r_ц``, tip radius ``R_Г = R_о + (0.8…1.2) r_ц`` for cast one-piece
links. Track pitch 170 mm, 13 teeth, pin radius 25 mm.
"""

from chaindrive.geometry.track_wheel import TrackDriveWheel
from chaindrive.plotting.geometry import geometry_plot

wheel = TrackDriveWheel(pitch=0.17, teeth=13, pin_radius=0.025, link="cast")
fig = geometry_plot(wheel)
d = wheel.dimensions()
print(f"pitch Ø{2e3 * d.pitch_radius:.1f} mm, root Ø{2e3 * d.root_radius:.1f} mm, "
      f"tip Ø{2e3 * d.tip_radius:.1f} mm")
