"""Plots of chaindrive.plotting.strength render and save."""

from __future__ import annotations

import numpy as np

from chaindrive.plotting.strength import pin_bending_plot, skew_plot
from chaindrive.strength import ARCMIN, MultiRowPin, roller_contact_stress


def test_skew_plot_saves_png(tmp_path):
    r = roller_contact_stress(5e3, 15.88e-3, 68.7e-3, 17e-3, contact="convex", pitch=0.01905,
                              max_skew=np.linspace(0, 120, 25) * ARCMIN)
    fig = skew_plot(r)
    ax = fig.axes[0]
    assert "MPa" in ax.get_ylabel() and "arcmin" in ax.get_xlabel()
    assert "L/L0" in fig.axes[1].get_ylabel()
    path = tmp_path / "skew.png"
    fig.savefig(path)
    assert path.stat().st_size > 10_000


def test_pin_bending_plot_saves_png(tmp_path):
    import matplotlib.pyplot as plt

    pin = MultiRowPin.from_chain("16B-3")
    res = [pin.bending(5e3, intermediate_plates=b) for b in (False, True)]
    fig = pin_bending_plot(res)
    assert len(fig.axes) == 2 and "µm" in fig.axes[0].get_ylabel()
    fig.savefig(tmp_path / "pin.png")
    _, ax = plt.subplots()
    assert pin_bending_plot(res, ax=ax) is ax.figure
