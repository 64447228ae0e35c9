"""Deprecated: moved to :mod:`chaindrive.drivetrain.motor`; this alias warns and is removed in
the next release."""

from ._deprecation import moved_module

__getattr__ = moved_module("chaindrive.motor", "chaindrive.drivetrain.motor")
