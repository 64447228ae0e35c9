"""Deprecated: moved to :mod:`chaindrive.drivetrain.coupling`; this alias warns and is removed in
the next release."""

from ._deprecation import moved_module

__getattr__ = moved_module("chaindrive.coupling", "chaindrive.drivetrain.coupling")
