"""Deprecated: moved to :mod:`chaindrive.life.wear` (the formulas are apart from the drive
description); this alias warns and is removed in the next release."""

from .._deprecation import moved_module

__getattr__ = moved_module("chaindrive.drive.wear", "chaindrive.life.wear")
