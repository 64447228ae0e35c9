"""Deprecated: moved to :mod:`chaindrive.life.wear`; this alias warns and is removed in the
next release."""

from ._deprecation import moved_module

__getattr__ = moved_module("chaindrive.wear", "chaindrive.life.wear")
