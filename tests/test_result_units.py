"""Every public result class is frozen and declares the unit of every numeric field.

The classes are discovered by walking the package for subclasses of
:class:`chaindrive._results.Result`; a numeric field is one annotated as a float, an int,
a numpy array or a sequence of numbers (optionally ``| None``). A unit written
``"a|b"`` is ``a`` or ``b`` by the kind of the object (a pivot's N·m/rad, a slide's N/m).
"""

from __future__ import annotations

import dataclasses
import importlib
import pkgutil
import re

import pytest

import chaindrive
from chaindrive._results import Result

_SKIP_MODULES = ("chaindrive.web", "chaindrive.cli", "chaindrive.__main__")


def _modules() -> list[str]:
    names = ["chaindrive"]
    for info in pkgutil.walk_packages(chaindrive.__path__, "chaindrive."):
        if info.name.startswith(_SKIP_MODULES):
            continue
        names.append(info.name)
    return names


def _result_classes() -> list[type]:
    import warnings

    found: dict[str, type] = {}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for name in _modules():
            try:
                module = importlib.import_module(name)
            except ImportError:  # an optional extra not installed
                continue
            for obj in vars(module).values():
                if (isinstance(obj, type) and issubclass(obj, Result) and obj is not Result
                        and obj.__module__.startswith("chaindrive") and not obj.__name__.startswith("_")
                        and not obj.__module__.startswith(_SKIP_MODULES)):
                    found[f"{obj.__module__}.{obj.__qualname__}"] = obj
    return [found[k] for k in sorted(found)]


CLASSES = _result_classes()

#: Fields whose unit is held by another field of the instance: (class, field) -> that field.
_UNIT_FROM_FIELD = {
    ("Check", "value"): "unit",
    ("Check", "limit"): "unit",
    ("SelfRegulatingDriveResult", "carrier_coordinate"): "coordinate_unit",
    ("SelfRegulatingDriveResult", "carrier_travel"): "coordinate_unit",
}


_NUMERIC = re.compile(r"\b(float|int|np\.ndarray|ndarray|NDArray|FloatOrArray|ArrayLike|complex)\b")


def _numeric(annotation: str) -> bool:
    """A float, int, array or a sequence of numbers (``bool`` and ``str`` are not numbers)."""
    text = annotation.replace("numpy.", "np.")
    return bool(_NUMERIC.search(text))


def test_classes_found() -> None:
    assert len(CLASSES) >= 45, [c.__name__ for c in CLASSES]


@pytest.mark.parametrize("cls", CLASSES, ids=lambda c: f"{c.__module__}.{c.__name__}")
def test_result_class_is_frozen(cls: type) -> None:
    assert dataclasses.is_dataclass(cls)
    assert cls.__dataclass_params__.frozen, f"{cls.__name__} is not frozen"  # type: ignore[attr-defined]


@pytest.mark.parametrize("cls", CLASSES, ids=lambda c: f"{c.__module__}.{c.__name__}")
def test_every_numeric_field_has_a_unit(cls: type) -> None:
    missing = []
    for f in dataclasses.fields(cls):
        annotation = f.type if isinstance(f.type, str) else getattr(f.type, "__name__", str(f.type))
        if (cls.__name__, f.name) in _UNIT_FROM_FIELD:
            assert _UNIT_FROM_FIELD[cls.__name__, f.name] in {g.name for g in dataclasses.fields(cls)}
            continue
        if _numeric(annotation) and cls.unit_of(f.name) is None:
            missing.append(f"{f.name}: {annotation}")
    assert not missing, f"{cls.__name__}: no unit for " + ", ".join(missing)


def test_units_are_known_to_the_display_table() -> None:
    """Every declared SI unit is one :mod:`chaindrive.display` can show."""
    from chaindrive.display import convert

    for cls in CLASSES:
        for name, unit in cls.field_units().items():
            convert(1.0, unit, cls.display_unit_of(name))  # raises KeyError for an unknown pair
