"""The self-regulating drive as a declared analysis part (carrier statics, its checks)."""

from __future__ import annotations

from typing import Any

from .parts import Part, PartContext, register_part

__all__: list[str] = []


def _self_regulating_part(ctx: PartContext) -> Any:
    from ..drive.self_regulating import self_regulating_analysis

    if ctx.drive.self_regulating is None:
        return None
    sr = self_regulating_analysis(ctx.drive, ctx.drive.self_regulating)
    for text in sr.warnings:
        ctx.note(text)
    return sr


def _self_regulating_checks(ctx: PartContext, sr: Any) -> Any:
    from ..drive.self_regulating import self_regulating_checks

    return self_regulating_checks(sr)


register_part(Part("self_regulating", "Self-regulating drive", _self_regulating_part, checks=_self_regulating_checks,
                   order=100, section="chaindrive.workflows.sections:self_regulating_section"))
