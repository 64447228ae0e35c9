"""mypy plugin: ``chaindrive._results.quantity(...)`` is a dataclass field specifier.

mypy's dataclass support knows only ``dataclasses.field``; without this plugin it reads
``x: float = quantity("m")`` as a field *with a default*, and reports every field without
one that follows it. The plugin makes mypy read ``quantity`` like ``field`` (its ``default``
and ``default_factory`` keywords decide whether the field has a default; the unit, given
positionally, is skipped) in the result classes, those that inherit ``Result``.
"""

from __future__ import annotations

from collections.abc import Callable

from mypy.nodes import DataclassTransformSpec
from mypy.plugin import ClassDefContext, Plugin
from mypy.plugins import dataclasses as mypy_dataclasses

_SPEC = DataclassTransformSpec(
    eq_default=True, order_default=False, kw_only_default=False, frozen_default=False,
    field_specifiers=(*mypy_dataclasses.DATACLASS_FIELD_SPECIFIERS, "chaindrive._results.quantity"),
)


def _result_dataclass(ctx: ClassDefContext) -> bool:
    if not ctx.cls.info.has_base("chaindrive._results.Result"):
        return mypy_dataclasses.dataclass_class_maker_callback(ctx)
    return mypy_dataclasses.DataclassTransformer(ctx.cls, ctx.reason, _SPEC, ctx.api).transform()


class _QuantityPlugin(Plugin):
    def get_class_decorator_hook_2(self, fullname: str) -> Callable[[ClassDefContext], bool] | None:
        if fullname in mypy_dataclasses.dataclass_makers:
            return _result_dataclass
        return None


def plugin(version: str) -> type[Plugin]:
    return _QuantityPlugin
