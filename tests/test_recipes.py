"""The CONTRIBUTING recipes hold: a new chain family is its CSV plus its rating method, nothing else.

The family is added at run time through the documented extension point
(:func:`chaindrive.chains.register_family`, the same reader as a CSV file dropped into
``chaindrive/chains/data``) and rated by a method registered under its name.
"""

import pytest

from chaindrive import chains
from chaindrive.design import Duty, design_drive
from chaindrive.errors import InputError, UnknownNameError
from chaindrive.rating import RATING_METHODS, _rate, chain_rating, default_method
from chaindrive.selection import select

# A made-up family: the dimensions of ISO 606 16B-1 and 20B-1 under other names.
_CSV = """# test family (made up): the dimensions of 16B-1 and 20B-1
name,strands,pitch_mm,roller_diameter_mm,inner_width_mm,pin_diameter_mm,plate_height_mm,transverse_pitch_mm,breaking_force_kN,mass_per_length_kg_m,source
ACME 16,1,25.4,15.88,17.02,8.28,21.08,,60,2.7,made up
ACME 20,1,31.75,19.05,19.56,10.19,26.42,,95,3.6,made up
"""


@pytest.fixture
def acme():
    """The family and its rating method (the ACA form with the ANSI 80 constants), removed after.

    A family's rating module inside the package (``chaindrive/rating/<family>.py``) would
    register the same function at import.
    """
    def rating(chain, teeth, angular_velocity, *, power=None):
        return _rate(chain, teeth, angular_velocity, power, constants=lambda name: (0.004, 17.0),
                     method="acme", source="test family: ACA form, K_p = 0.004, K_r = 17", notes=[])

    chains.register_family("acme", _CSV)
    RATING_METHODS.add("acme", rating)
    yield
    chains.unregister_family("acme")
    RATING_METHODS._items.pop("acme", None)  # the registry has no public removal


def test_family_csv_and_rating_method_are_enough(acme) -> None:
    ch = chains.get("acme 16")
    assert ch.family == "acme" and ch.pitch == 0.0254 and ch.is_roller_chain
    assert [c.name for c in chains.catalogue("acme")] == ["ACME 16", "ACME 20"]
    assert "acme" in chains.families()
    assert default_method(ch) == "acme"
    # the same dimensions and constants as 16B-1 rated by the ANSI/ACA method (K_p = 0.004, K_r = 17)
    twin = chain_rating("16B-1", 17, 100.0, method="ansi")
    own = chain_rating(ch, 17, 100.0)
    assert own.method == "acme" and own.rated_power == pytest.approx(twin.rated_power, rel=1e-12)
    with pytest.warns(FutureWarning):
        rows = select(20e3, 100.0, 2.0, family="acme")
    assert rows and {r.chain for r in rows} <= {"ACME 16", "ACME 20"}
    with pytest.warns(FutureWarning):
        assert any(r.family == "acme" for r in select(20e3, 100.0, 2.0))
    found = design_drive(Duty(power=20e3, speed=100.0, ratio=2.0, load_character="smooth"), family="acme")
    assert found.candidates and {c.chain for c in found.candidates} <= {"ACME 16", "ACME 20"}


def test_catalogue_is_back_after_removal(acme) -> None:
    chains.unregister_family("acme")
    with pytest.raises(UnknownNameError, match="unknown chain"):
        chains.get("ACME 16")
    with pytest.raises(UnknownNameError, match="unknown roller-chain family"):
        design_drive(Duty(power=20e3, speed=100.0, ratio=2.0, load_character="smooth"), family="acme")


def test_bad_family_is_refused() -> None:
    with pytest.raises(InputError, match="new lower-case identifier"):
        chains.register_family("iso606", _CSV)
    with pytest.raises(InputError, match="already in the catalogue"):
        chains.register_family("dup", "name,pitch_mm,roller_diameter_mm,source\n16B-1,25.4,15.88,x\n")
    with pytest.raises(InputError, match="needs name, pitch_mm and source"):
        chains.register_family("nopitch", "name,source\nX 1,x\n")
    assert "dup" not in chains.families() and "nopitch" not in chains.families()
