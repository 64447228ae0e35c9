"""Moved to :mod:`chaindrive.display` (deprecated alias, removed in the next release): the
display units sit in the bottom layer beside :mod:`chaindrive.units`, so that every
presenter, the plots included, reads one table."""

from .._deprecation import moved_module

__getattr__ = moved_module("chaindrive.workflows.display", "chaindrive.display")
