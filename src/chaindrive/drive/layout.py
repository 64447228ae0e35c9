"""Deprecated: moved to :mod:`chaindrive.layout` (the formulas are apart from the drive
description); this alias warns and is removed in the next release."""

from .._deprecation import moved_module

__getattr__ = moved_module("chaindrive.drive.layout", "chaindrive.layout")
