"""
Crawler drive chain with and without the tangent guide
======================================================

The crawler drive text, Fig. 6.9 c: speed of the drive chain's straight span over one
tooth period, without a guide (curve 2, the usual chordal action) and with a guide that
holds the chain tangent to the pitch circles (curve 1, eq. 6.15–6.16). The guide halves
the speed non-uniformity. Pitch 0.1 m, 8 teeth, 2 rad/s (19.1 rpm).
"""

from chaindrive.kinematics.crawler import crawler_drive, crawler_nonuniformity
from chaindrive.plotting.crawler import crawler_plot

results = [crawler_drive(0.1, 8, 2.0, guide=guide, points=361) for guide in ("tangent", "none")]
fig = crawler_plot(results)

for guide in ("tangent", "none"):
    print(f"speed non-uniformity, guide {guide!r}: {crawler_nonuniformity(8, guide=guide):.4f}")
