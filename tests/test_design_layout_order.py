"""design_drive lays out only the chains it can keep (per series and strand count, the
smallest adequate pitch outside the galling region): the same candidates as laying out
every adequate chain and keeping those afterwards."""

from __future__ import annotations

import math
import warnings

import pytest

from chaindrive.chains import get
from chaindrive.design import Duty, design_drive
from chaindrive.selection import _series


@pytest.mark.parametrize(("power", "rpm", "centre"), [(11e3, 1460, 0.6), (3e3, 960, None), (40e3, 300, 1.2),
                                                      (150e3, 960, None), (11e3, 3000, None), (0.5e3, 100, 0.3),
                                                      (30e3, 2000, None), (60e3, 1460, None)])
def test_candidates_equal_those_of_every_chain_laid_out(power, rpm, centre):
    duty = Duty(power, rpm * math.pi / 30, ratio=3.0, driven_machine="varying_conveyor", centre_distance=centre)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        every = design_drive(duty, all_sizes=True).candidates
        kept = design_drive(duty).candidates
    smallest: dict = {}
    for c in every:
        smallest.setdefault((_series(get(c.chain)), c.strands), (c.lubrication == "C'", c.pitch))
    expected = [c for c in every if smallest[(_series(get(c.chain)), c.strands)] == (c.lubrication == "C'", c.pitch)]
    def rows(cands):  # (a candidate may hold NaN, which == does not match)
        return [(c.chain, c.driving_teeth, c.driven_teeth, c.links, c.centre_distance, c.static_safety, c.lubrication,
                 repr(c.peak_tension), c.notes, [x.name for x in c.checks]) for c in cands]

    assert rows(kept) == rows(expected) and kept


@pytest.mark.parametrize(("power", "rpm"), [(11e3, 1460), (3e3, 960), (60e3, 300)])
def test_the_catalogue_screen_passes_every_chain_the_one_chain_rating_passes(power, rpm):
    from chaindrive.chains import catalogue
    from chaindrive.design.procedure import _may_carry
    from chaindrive.rating import chain_rating

    speed = rpm * math.pi / 30
    chains = [(ch, 19) for ch in catalogue("ansi") if ch.strands <= 4]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        one_by_one = [chain_rating(ch, z, speed, power=power).rated_power >= power for ch, z in chains]
    screened = _may_carry(chains, speed, power, "ansi")
    assert screened == one_by_one
    assert 0 < sum(screened) < len(screened)


@pytest.mark.parametrize(("power", "rpm"), [(11e3, 1460), (3e3, 960), (60e3, 300)])
def test_the_screen_of_every_method_passes_every_chain_the_one_chain_rating_passes(power, rpm):
    # each chain by its family's method (the ISO 606 B series by ISO 10823), as design_drive rates it
    from chaindrive.chains import catalogue
    from chaindrive.design.procedure import _may_carry, _screened
    from chaindrive.rating import chain_rating

    speed = rpm * math.pi / 30
    chains = [(ch, z) for ch in catalogue("iso606") if ch.strands <= 4 for z in (17, 25)]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        exact = [chain_rating(ch, z, speed, power=power).rated_power for ch, z in chains]
    screened = _screened(chains, speed, None)
    assert all(s == pytest.approx(r, rel=1e-12) for s, r in zip(screened, exact, strict=True))
    assert _may_carry(chains, speed, power, None) == [r >= power for r in exact]
