"""The units read without pint (chaindrive.units._TABLE) are pint's own definitions, exactly:
the same factor to the root units, dimensionality, radian exponent and Hz flag, so a
project parses to the same SI numbers with or without the table."""

import pytest

from chaindrive import units
from chaindrive.units import _TABLE, _pint_unit_info, _unit_info, parse_quantity


@pytest.mark.parametrize("unit", sorted(_TABLE))
def test_table_equals_pint(unit):
    # independent reference: pint's registry (the SI brochure's definitions), asked directly
    _, factor, dims, radians, hertz = _pint_unit_info(unit)
    t_factor, t_items, t_text, t_radians, t_hertz = _TABLE[unit]
    assert t_factor == factor  # exactly, not approximately
    assert t_items == dims.items and t_text == str(dims)
    assert (t_radians, t_hertz) == (radians, hertz)


def test_fast_and_pint_units_compare():
    # a table unit against a pint-only unit (inch is not in the table): same dimension
    assert "in" not in _TABLE
    assert parse_quantity("1 in", "mm") == pytest.approx(25.4, rel=1e-15)
    assert _unit_info("in")[2] == _unit_info("mm")[2]
    assert str(_unit_info("kg")[2]) == "[mass]"


def test_wrong_dimension_still_named():
    with pytest.raises(units.InputError, match=r"has units of \[mass\]"):
        parse_quantity("3 kg", "m", field="pitch")
    with pytest.raises(units.InputError, match="unknown unit"):
        parse_quantity("3 furlongz", "m", field="pitch")


def test_a_project_needs_no_pint():
    # the examples' quantities all come from the table: pint is not loaded for them
    import subprocess
    import sys

    code = ("import sys; from chaindrive.drive.project import load_project; "
            "load_project('examples/roller_industrial.toml'); print('pint' in sys.modules)")
    from _shared import EXAMPLES

    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=EXAMPLES.parent,
                         check=True)
    assert out.stdout.strip() == "False"
