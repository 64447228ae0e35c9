"""
The example projects
====================

Each project file in ``examples/`` analysed with :func:`chaindrive.analysis.analyze_drive`
and drawn: the layout of the drive (pitch circles, spans, the tight span marked), and for
the roller chain drive its rating curve and wear life.
"""

from pathlib import Path

import chaindrive
from chaindrive.analysis import analyze_drive
from chaindrive.drive.project import load_project
from chaindrive.plotting.drive import layout_plot, rating_plot, wear_plot

root = Path(chaindrive.__file__).resolve().parents[2] / "examples"

# %%
# Mining conveyor: round link chain on pocket wheels with a tensioner
mining = analyze_drive(load_project(root / "mining_conveyor.toml"))
fig = layout_plot(mining)
print(f"verdict: {'pass' if mining.passed else 'fail'}; {len(mining.checks)} checks")

# %%
# Industrial roller chain drive: layout, rating and wear life
roller = analyze_drive(load_project(root / "roller_industrial.toml"))
fig = layout_plot(roller)
# %%
r = roller.rating.rating
fig = rating_plot(r, operating=(r.angular_velocity, roller.drive.design_power()))
# %%
fig = wear_plot(roller.wear)

# %%
# Tractor track
track = analyze_drive(load_project(root / "tractor_track.toml"))
fig = layout_plot(track)
