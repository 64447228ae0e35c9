"""Deprecation policy (internal): a renamed or moved public name keeps an alias that warns
with :class:`FutureWarning` for one release, and CHANGELOG.md lists it.

:func:`moved_module` makes a module forward every attribute to its new home;
:func:`alias` makes a renamed function that warns and calls the new one;
:func:`renamed_attributes` gives a module the former names of its renamed functions.

Renamed in this release (removed in the next):

==============================================  ==================================================
former name                                     new name
==============================================  ==================================================
``chaindrive.drive.layout/loads/selection/wear``  ``chaindrive.layout/loads/selection/wear``
``chaindrive.strength.seed_contact_stress``     ``chaindrive.strength.skew_paper_contact_stress``
``chaindrive.strength.seed_contact_coefficient``  ``chaindrive.strength.skew_paper_contact_coefficient``
``chaindrive.kinematics.seed002_case``          ``chaindrive.kinematics.dolipinski_worked_case``
``chaindrive.static_safety``                    ``chaindrive.loads.safety`` (all names also in ``chaindrive.loads``)
``chaindrive.motor``, ``chaindrive.coupling``   ``chaindrive.drivetrain.motor``, ``chaindrive.drivetrain.coupling``
``chaindrive.wear``, ``chaindrive.drive.wear``  ``chaindrive.life.wear``
==============================================  ==================================================
"""

from __future__ import annotations

import functools
import importlib
import warnings
from collections.abc import Callable
from typing import Any, TypeVar

__all__ = ["alias", "moved_module", "renamed_attributes", "warn_renamed"]

F = TypeVar("F", bound=Callable[..., Any])


def warn_renamed(old: str, new: str, *, stacklevel: int = 3) -> None:
    """Warn once per call site that ``old`` is now ``new`` (removed in the next release)."""
    warnings.warn(f"{old} is deprecated and will be removed in the next release; use {new}",
                  FutureWarning, stacklevel=stacklevel)


def alias(function: F, old: str) -> F:
    """``function`` under its former public name ``old``, warning at each call."""
    new = f"{function.__module__}.{function.__qualname__}"

    @functools.wraps(function)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        warn_renamed(old, new)
        return function(*args, **kwargs)

    wrapper.__doc__ = f"Deprecated alias of :func:`{new}` (removed in the next release)."
    return wrapper  # type: ignore[return-value]


def moved_module(old: str, new: str, *more: str) -> Callable[[str], Any]:
    """A module ``__getattr__`` forwarding every attribute of the moved module ``old`` to ``new``
    (or, for a module split in parts, to the first of ``new, *more`` that has it)."""

    def __getattr__(name: str) -> Any:
        if not name.startswith("__"):
            for home in (new, *more):
                module = importlib.import_module(home)
                if hasattr(module, name):
                    warn_renamed(f"{old}.{name}", f"{home}.{name}")
                    return getattr(module, name)
        raise AttributeError(f"module {old!r} has no attribute {name!r}")

    return __getattr__


def renamed_attributes(module: str, renamed: dict[str, str]) -> Callable[[str], Any]:
    """A module ``__getattr__`` giving each former name in ``renamed`` (old -> new name in
    the same module) as a warning :func:`alias` of the new function.

    Examples
    --------
    >>> import warnings
    >>> getter = renamed_attributes("chaindrive.strength", {"old_stress": "skew_paper_contact_stress"})
    >>> with warnings.catch_warnings(record=True) as caught:
    ...     warnings.simplefilter("always")
    ...     value = round(getter("old_stress")(10e3, 0.02, 0.005) / 1e6, 1)
    >>> value, caught[0].category.__name__
    (1915.5, 'FutureWarning')
    """

    def __getattr__(name: str) -> Any:
        if name not in renamed:
            raise AttributeError(f"module {module!r} has no attribute {name!r}")
        function = getattr(importlib.import_module(module), renamed[name])
        return alias(function, f"{module}.{name}")

    return __getattr__
