"""chaindrive._docs: shared docstring fragments filled in at import (help() shows the whole text)."""

import inspect

import pytest

from chaindrive._docs import Fragments
from chaindrive.geometry import iso606
from chaindrive.kinematics.crawler import laws
from chaindrive.rating import ansi
from chaindrive.vibration import tensioner

_F = Fragments(a="""
    a : float
        The first [m].
""", b="""
    %(a)s
    b : int
        The second [-].
""")
_F.section("ab_parameters", "b")


def test_fill_indents_and_nests() -> None:
    @_F
    def f(a, b):
        """Summary.

        %(ab_parameters)s
        """
    lines = f.__doc__.splitlines()
    assert lines[2:8] == ["        Parameters", "        ----------", "        a : float",
                          "            The first [m].", "        b : int", "            The second [-]."]


def test_unknown_fragment_fails_at_import() -> None:
    with pytest.raises(KeyError, match="nope"):
        @_F
        def g():
            """%(nope)s"""


def test_no_docstring_is_left_alone() -> None:  # python -OO strips docstrings
    def h():
        pass
    assert _F(h).__doc__ is None


@pytest.mark.parametrize("func", [laws.guided_velocity, ansi.galling_power, tensioner.heavy_tensioner_validity,
                                  iso606.root_diameter])
def test_public_docstrings_are_complete(func) -> None:
    """No placeholder survives; every parameter of the signature is described."""
    doc = inspect.getdoc(func)
    assert "%(" not in doc
    for name in inspect.signature(func).parameters:
        assert f"{name} :" in doc or f"{name}," in doc or f", {name}" in doc, name
