"""Deprecated: moved to :mod:`chaindrive.loads.safety` (every name is also importable from
:mod:`chaindrive.loads`); this alias warns and is removed in the next release."""

from ._deprecation import moved_module

__getattr__ = moved_module("chaindrive.static_safety", "chaindrive.loads.safety")
