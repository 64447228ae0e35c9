"""Deprecated: the self-regulating drive moved apart along the layers: the formulas to
:mod:`chaindrive.self_regulating`, the ``[self_regulating]`` table to
:mod:`chaindrive.drive.carrier`, the drive-level analysis to
:mod:`chaindrive.analysis.self_regulating`. This alias warns and is removed in the next release."""

from .._deprecation import moved_module

__getattr__ = moved_module("chaindrive.drive.self_regulating", "chaindrive.self_regulating",
                           "chaindrive.drive.carrier", "chaindrive.analysis.self_regulating")
