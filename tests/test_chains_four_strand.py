"""Four-strand roller chains (issue 30, item 5): the catalogue lists what the makers publish,
with provenance, and the selection finds them (Mott's worked example, No. 40-4)."""

from __future__ import annotations

import pytest

from chaindrive.chains import get
from chaindrive.chains._catalogue import catalogue, equivalent_names
from chaindrive.cli import main

LBF = 4.4482216152605

# provenance: Renold transmission chain catalogue (Russian edition), Section 1, "Renold
# Multiplex, ANSI standard - multi-strand", p. 32: mass [kg/m] and transverse pitch [mm] of
# the 4-strand rows 40-4 ... 200-4 (text copy in github.com/ArtemFilin1990/Mar)
RENOLD_4 = {"40": (2.50, 14.38), "50": (4.20, 18.11), "60": (6.20, 22.78), "80": (11.20, 29.29),
            "100": (16.80, 35.76), "120": (22.92, 45.44), "140": (30.21, 48.87), "160": (38.90, 58.55),
            "200": (68.24, 71.55)}


@pytest.mark.parametrize("number", sorted(RENOLD_4, key=int))
def test_four_strand_rows_against_renold_and_the_b29_rule(number):
    c, twin = get(f"ANSI {number}-4"), get(f"ANSI {number}-1")
    iso = get(equivalent_names(c)[0])
    mass, pt = RENOLD_4[number]
    assert c.strands == 4 and c.pitch == twin.pitch and c.roller_diameter == twin.roller_diameter
    assert c.mass_per_length == pytest.approx(mass) and c.transverse_pitch == pytest.approx(pt * 1e-3)
    # ANSI B29.1: the minimum tensile strength of a multiple strand chain is strands x simplex
    assert c.breaking_force == pytest.approx(4 * twin.breaking_force, rel=1e-6)
    assert iso.strands == 4 and "Renold" in iso.source and iso.mass_per_length == c.mass_per_length


def test_every_four_strand_row_has_its_source():
    rows = [c for c in catalogue() if c.strands == 4]
    assert {c.name for c in rows} >= {f"ANSI {n}-4" for n in RENOLD_4}
    for c in rows:
        assert c.breaking_force > 0 and c.mass_per_length and c.transverse_pitch and c.source
        assert "4 x" in c.source or "4 strands" in c.source


def test_mott_worked_example_finds_a_four_strand_chain(capsys):
    # Mott, Machine Elements in Mechanical Design, 4th ed., Example Problem 7-3: 15 hp to a coal
    # conveyor, 900 rpm, output 230-240 rpm (ratio 3.83), design power 21.0 hp (service factor
    # 1.4), a four-strand chain (factor 3.3): "a no. 40 chain with a 17-tooth sprocket", 65
    # teeth, type B lubrication. Before the 4-strand rows the selection answered "no catalogue
    # roller chain ... try more strands" for lack of any 4-strand chain.
    assert get("ANSI 40-4").strands == 4  # Mott's answer is in the catalogue
    code = main(["select", "-P", "15 hp", "-n", "900 rpm", "-i", "3.83", "-K", "1.4", "--strands", "4",
                 "-z", "17", "-f", "ansi", "-a", "15 in"])
    out = capsys.readouterr()
    assert code == 0, out.err
    assert "try more strands" not in out.out + out.err
    assert "-4" in out.out.split("Recommended:", 1)[1].splitlines()[0]


def test_cli_lists_four_strand_chains(capsys):
    assert main(["chain", "ANSI 40-4"]) == 0
    out = capsys.readouterr().out
    assert "ANSI 40-4" in out and "Renold" in out
