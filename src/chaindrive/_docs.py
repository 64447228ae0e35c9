"""Shared docstring fragments: a parameter described once, filled into every docstring at import.

Where many functions take the same parameters with the same meaning, their numpydoc
entries are written once in a :class:`Fragments` set and a line ``%(name)s`` in the
docstring stands for one of them. The decorator replaces that line when the module is
imported, at the line's indentation, so ``help()``, the API reference and the doctests
see the whole text (the mechanism of matplotlib's ``_docstring.interpd``).

Examples
--------
>>> speed = Fragments(pitch_teeth='''
...     pitch : float
...         Chain pitch [m].
...     teeth : int
...         Sprocket teeth [-].
... ''')
>>> @speed
... def f(pitch, teeth):
...     '''Something.
...
...     Parameters
...     ----------
...     %(pitch_teeth)s
...     '''
>>> print(f.__doc__.splitlines()[4])
    pitch : float
"""

from __future__ import annotations

import re
import textwrap
from typing import TypeVar

__all__ = ["Fragments"]

_T = TypeVar("_T")
_LINE = re.compile(r"^([ \t]*)%\((\w+)\)s[ \t]*$", re.MULTILINE)


class Fragments:
    """A named set of docstring fragments and the decorator that fills them in.

    Parameters
    ----------
    **fragments : str
        Name -> numpydoc text (dedented; leading and trailing blank lines dropped); a
        fragment may itself hold ``%(name)s`` lines naming the fragments before it.

    Raises
    ------
    KeyError
        At import, when a docstring names a fragment the set does not hold.
    """

    def __init__(self, **fragments: str) -> None:
        self._texts: dict[str, str] = {}
        for k, v in fragments.items():  # a fragment may use the ones before it
            self._texts[k] = self.fill(textwrap.dedent(v).strip("\n"))

    def __call__(self, obj: _T) -> _T:
        doc = getattr(obj, "__doc__", None)
        if doc:  # None under python -OO
            obj.__doc__ = self.fill(doc)
        return obj

    def fill(self, doc: str) -> str:
        """``doc`` with every line ``%(name)s`` replaced by that fragment, indented alike."""
        def one(m: re.Match[str]) -> str:
            return textwrap.indent(self._texts[m.group(2)], m.group(1))
        return _LINE.sub(one, doc)

    def section(self, name: str, *parts: str, title: str = "Parameters") -> None:
        """Add fragment ``name``: a numpydoc section ``title`` made of the fragments ``parts``."""
        body = "\n".join(self._texts[p] for p in parts)
        self._texts[name] = f"{title}\n{'-' * len(title)}\n{body}"

    def extended(self, **fragments: str) -> Fragments:
        """A new set with these fragments added to this one's."""
        out = Fragments()
        out._texts = dict(self._texts)
        for k, v in fragments.items():
            out._texts[k] = out.fill(textwrap.dedent(v).strip("\n"))
        return out


