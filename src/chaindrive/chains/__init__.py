"""Chain catalogue: ISO 606 roller chains, ANSI B29.1 numbers, DIN 22252 link chains.

The data live in CSV files inside the package (``chaindrive/chains/data``, one file per
family, in mm/kN/kg/m with the source of every row) and are converted to SI units when
loaded. Sources, coverage and gaps: ``docs/chains.md``.

Examples
--------
>>> from chaindrive import chains
>>> chains.get("16B").pitch
0.0254
>>> chains.get("ANSI 40").inner_width, chains.get("08A").inner_width   # ANSI 5/16 in; ISO twin
(0.0079375, 0.00792)
>>> chains.equivalent_names("08A")
('ANSI 40-1',)
>>> chains.get("18x64").breaking_force
410000.0
"""

from ._catalogue import (
    FAMILIES,
    Chain,
    catalogue,
    check_roller_family,
    equivalent_names,
    estimated_fields,
    families,
    get,
    names,
    normalize_name,
    register_family,
    roller_families,
    unregister_family,
)

__all__ = ["Chain", "FAMILIES", "get", "catalogue", "names", "normalize_name", "estimated_fields",
           "equivalent_names", "families", "roller_families", "check_roller_family", "register_family",
           "unregister_family"]
