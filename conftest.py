"""Test set-up shared by the test suite (tests/) and the doctests (src/chaindrive/)."""

import sys

import matplotlib
import pytest

matplotlib.use("Agg")


@pytest.fixture(autouse=True)
def _close_figures():
    """Close the figures a test or doctest opened.

    Plot functions return their figure and never close it (the caller owns it); without
    this, a worker that runs more than 20 plotting tests gets matplotlib's
    "More than 20 figures" RuntimeWarning, which the suite turns into an error.
    """
    yield
    if "matplotlib.pyplot" in sys.modules:
        sys.modules["matplotlib.pyplot"].close("all")
