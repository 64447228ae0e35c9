"""Smoke tests of chaindrive.plotting.drive (figures returned, labelled, no show())."""

from __future__ import annotations

import pytest

from chaindrive.analysis import analyze_drive, drive_layout

pytest.importorskip("matplotlib")

from _shared import EXAMPLES
from chaindrive.drive import load_project  # noqa: E402
from chaindrive.plotting.drive import layout_plot, rating_plot, wear_plot  # noqa: E402


@pytest.mark.parametrize("name", ["mining_conveyor", "roller_industrial", "tractor_track"])
def test_layout_plot(name, tmp_path):
    import matplotlib.pyplot as plt

    d = load_project(EXAMPLES / f"{name}.toml")
    fig = layout_plot(d)
    ax = fig.axes[0]
    assert ax.get_xlabel() == "x [mm]" and ax.get_ylabel() == "y [mm]"
    assert "links" in ax.get_title()
    fig.savefig(tmp_path / "layout.png", dpi=50)
    plt.close(fig)
    fig = layout_plot(drive_layout(d))  # a result alone: geometry only
    plt.close(fig)


def test_wear_and_rating_plots():
    import matplotlib.pyplot as plt

    d = load_project(EXAMPLES / "roller_industrial.toml")
    fig = wear_plot(analyze_drive(d, include=['wear']).wear)
    assert fig.axes[0].get_ylabel() == "chain elongation [%]"
    plt.close(fig)
    fig = rating_plot(0.0254, 19, name="16B-1", operating=(d.speed, d.design_power()))
    assert fig.axes[0].get_xlabel() == "small-sprocket speed [rpm]"
    assert {"rated power", "operating point", "galling line (Shigley §17-5)"} <= {
        t.get_text() for t in fig.axes[0].get_legend().get_texts()}
    plt.close(fig)


def test_rating_plot_draws_the_ratings_own_branches():
    """The rating chart draws the branches of the rating it is given: an ISO 10823 rating of a B-series
    chain off 19 teeth (25) takes the standard's tooth factor in both branches, so its 'rated power' line
    passes through the rating's own value at the operating speed (it drew the ACA z^1.5 roller branch)."""
    import matplotlib.pyplot as plt
    import numpy as np

    from chaindrive.rating import chain_rating

    w = 1460 * np.pi / 30
    r = chain_rating("12B-1", 25, w)
    assert r.method == "iso10823" and r.governing_limit == "roller_bushing"
    fig = rating_plot(r)
    line = next(ln for ln in fig.axes[0].get_lines() if ln.get_label() == "rated power")
    x, y = line.get_data()
    at = float(np.interp(np.log(1460.0), np.log(x), np.log(y)))
    assert np.exp(at) == pytest.approx(r.rated_power / 1e3, rel=2e-3)
    assert "ISO 10823" in fig.axes[0].get_title()
    plt.close(fig)
