r"""The declared parts of a drive analysis: one declaration per part, read by every door.

A part is declared once, in its own module of :mod:`chaindrive.analysis`, with
:func:`register_part`: its name, the parts it needs, its compute function, its checks,
its report section and its place in the report. :func:`~chaindrive.analysis.analyze_drive`
resolves the needs from the declarations; :meth:`DriveAnalysis.to_dict`, the report,
the command line, the web page and the study outputs iterate the declarations. Every
module of the :mod:`chaindrive.analysis` package is imported when the parts are first
needed, so adding a part is its module, (optionally) its report section and its test.

Examples
--------
A part that reads the layout and reports the chain's mass:

>>> from dataclasses import dataclass
>>> from chaindrive._results import Result, quantity
>>> @dataclass(frozen=True)
... class ChainMass(Result):
...     mass: float = quantity("kg")
>>> def chain_mass(ctx):
...     return ChainMass(ctx.drive.chain.mass_per_length * ctx["layout"].chain_length)
>>> with temporary_part(Part("chain_mass", "Chain mass", chain_mass, needs=("layout",), order=15)):
...     from chaindrive.drive.project import load_project
...     from chaindrive.analysis import analyze_drive
...     a = analyze_drive(load_project("examples/roller_industrial.toml"), include=["chain_mass"])
...     round(a.chain_mass.mass, 2), a.parts
(8.09, ('chain_mass',))
"""

from __future__ import annotations

import contextlib
import importlib
import pkgutil
from collections.abc import Callable, Iterable, Iterator, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from ..errors import ChainDriveError, InputError

if TYPE_CHECKING:
    from ..drive.model import Drive
    from .checks import Check

__all__ = ["Part", "PartContext", "register_part", "unregister_part", "temporary_part", "get_part",
           "all_parts", "part_names", "resolve"]


@dataclass(frozen=True)
class Part:
    """The declaration of one analysis part.

    Parameters
    ----------
    name : str
        The key of the part: ``DriveAnalysis.<name>``, ``to_dict()[name]``, study output
        paths ``name.field``, ``include=[name]``.
    title : str
        What the part computes, in words (report heading, web, CLI).
    compute : callable
        ``compute(context) -> result or None``: the part's result object (a frozen
        :class:`~chaindrive._results.Result` whose numeric fields declare their units), or
        ``None`` where the part does not apply to the drive.
    needs : tuple of str
        The parts ``compute`` and ``checks`` read through ``context[name]``; they are
        computed first (and not returned unless asked for).
    checks : callable, optional
        ``checks(context, result) -> iterable of Check``: the verdicts of this part.
    order : float
        Place in the report, in ``to_dict`` and in the list of checks (ascending).
    section : str, optional
        ``"module:function"`` of the report section that presents the part
        (``function(analysis, figures) -> Section``; several parts may share one section);
        ``None``: the generic section (a table of the result's fields with their units,
        and the part's checks).
    unit : str, optional
        The SI unit of a part whose result is a plain number (e.g. the slack-span sag [m]).
    json : callable, optional
        ``json(result) -> JSON-ready data`` where the result's ``to_dict()`` is not the form
        to publish.
    batch : callable, optional
        ``batch(contexts) -> list of results, or None``: the part for many variants of a
        drive in one vectorised call (:func:`chaindrive.analysis.batch.analyze_variants`);
        each result must equal ``compute`` of that variant. ``None`` (or a warning or an
        error in the call) makes the variants computed one by one.
    """

    name: str
    title: str
    compute: Callable[[PartContext], Any]
    needs: tuple[str, ...] = ()
    checks: Callable[[PartContext, Any], Iterable[Check]] | None = None
    order: float = 1000.0
    section: str | None = None
    unit: str | None = None
    json: Callable[[Any], Any] | None = None
    batch: Callable[[Sequence[PartContext]], Sequence[Any] | None] | None = None

    def __post_init__(self) -> None:
        if not self.name.isidentifier() or self.name.startswith("_"):
            raise InputError(f"part name must be a Python identifier not starting with '_', got {self.name!r}",
                             field="name")
        if self.name in _RESERVED:
            raise InputError(f"part name {self.name!r} is reserved ({', '.join(sorted(_RESERVED))})", field="name")
        object.__setattr__(self, "needs", tuple(self.needs))

    def to_json(self, result: Any) -> Any:
        """The part's result as JSON-ready data (SI units)."""
        from .._results import jsonable

        if result is None:
            return None
        return self.json(result) if self.json is not None else jsonable(result)


#: Names a part cannot take (the other keys of an analysis' dict and its attributes).
_RESERVED = frozenset({"inputs", "passed", "checks", "warnings", "drive", "parts", "results", "failed",
                       "simulation", "to_dict", "to_json"})

_REGISTRY: dict[str, Part] = {}
_DISCOVERED = False
_PLANS: dict[tuple[str, ...], tuple[Part, ...]] = {}  # resolved plans, cleared when a declaration changes


def _discover() -> None:
    """Import every module of the chaindrive.analysis package (each registers its parts)."""
    global _DISCOVERED
    if _DISCOVERED:
        return
    _DISCOVERED = True
    package = importlib.import_module("chaindrive.analysis")
    for info in pkgutil.iter_modules(package.__path__):
        if not info.name.startswith("_") and info.name != "parts":
            importlib.import_module(f"chaindrive.analysis.{info.name}")


def register_part(part: Part, *, replace: bool = False) -> Part:
    """Declare ``part`` (at import time of its module). Returns it.

    Raises
    ------
    InputError
        A part of that name exists (pass ``replace=True`` to redeclare it).
    """
    if not isinstance(part, Part):
        raise InputError(f"register_part takes a Part, got {type(part).__name__}", field="part")
    if part.name in _REGISTRY and not replace and _REGISTRY[part.name] is not part:
        raise InputError(f"an analysis part named {part.name!r} is already declared "
                         f"(by {_REGISTRY[part.name].compute.__module__}); pass replace=True", field="name")
    _REGISTRY[part.name] = part
    _PLANS.clear()
    return part


def unregister_part(name: str) -> None:
    """Remove the part ``name`` (tests and plug-ins)."""
    _REGISTRY.pop(name, None)
    _PLANS.clear()


@contextlib.contextmanager
def temporary_part(part: Part) -> Iterator[Part]:
    """Declare ``part`` for the duration of a ``with`` block (tests, notebooks)."""
    _discover()
    previous = _REGISTRY.get(part.name)
    register_part(part, replace=True)
    try:
        yield part
    finally:
        if previous is None:
            unregister_part(part.name)
        else:
            _REGISTRY[part.name] = previous
            _PLANS.clear()


def all_parts() -> tuple[Part, ...]:
    """Every declared part, in report order."""
    _discover()
    return tuple(sorted(_REGISTRY.values(), key=lambda p: (p.order, p.name)))


def part_names() -> tuple[str, ...]:
    """The names of every declared part, in report order."""
    return tuple(p.name for p in all_parts())


def get_part(name: str) -> Part:
    """The declaration of part ``name``."""
    _discover()
    if name not in _REGISTRY:
        import difflib

        close = difflib.get_close_matches(str(name), list(_REGISTRY), n=1)
        hint = f" (did you mean {close[0]!r}?)" if close else ""
        raise InputError(f"unknown analysis part {name!r}{hint}; valid: {', '.join(part_names())}", field="part")
    return _REGISTRY[name]


def resolve(names: Iterable[str]) -> tuple[Part, ...]:
    """``names`` and every part they need, directly or not, in an order that computes
    each part after its needs (report order where the needs allow).

    Raises
    ------
    InputError
        An unknown part, or needs that form a circle.
    """
    names = tuple(names)
    _discover()
    plan = _PLANS.get(names)
    if plan is not None:
        return plan
    order: list[Part] = []
    state: dict[str, int] = {}  # 1: on the path, 2: done

    def visit(name: str, path: tuple[str, ...]) -> None:
        if state.get(name) == 2:
            return
        if state.get(name) == 1:
            raise InputError(f"analysis parts need each other in a circle: {' -> '.join((*path, name))}",
                             field="needs")
        part = get_part(name)
        state[name] = 1
        for need in part.needs:
            visit(need, (*path, name))
        state[name] = 2
        order.append(part)

    for name in sorted(set(names), key=lambda n: (get_part(n).order, n)):
        visit(name, ())
    _PLANS[names] = plan = tuple(order)
    return plan


@dataclass
class _Computed:
    result: Any = None
    notes: list[str] = field(default_factory=list)
    caught: list[str] = field(default_factory=list)  # Python warnings raised while computing the part


class PartContext:
    """What a part's compute and checks functions see: the drive, the analysis options,
    the results of the parts they declared in ``needs``, and :meth:`note`."""

    def __init__(self, drive: Drive, part: Part, computed: dict[str, _Computed], options: dict[str, Any]) -> None:
        self.drive = drive
        self.part = part
        self.options = options
        self._computed = computed

    def __getitem__(self, name: str) -> Any:
        if name not in self.part.needs:
            # a programming error of the part's author, not of the user's input
            raise ChainDriveError(f"analysis part {self.part.name!r} reads {name!r} without declaring it in needs")
        if name not in self._computed:
            raise ChainDriveError(f"analysis part {name!r} was not computed before {self.part.name!r}")
        return self._computed[name].result

    def note(self, text: str) -> None:
        """A warning for the reader of the analysis (reported once, if the part is returned)."""
        self._computed[self.part.name].notes.append(str(text))

    def warn(self, text: str) -> None:
        """Record a formula's warning for this variant as if the part had raised it (a
        ``batch`` function replays each variant's warnings this way)."""
        self._computed[self.part.name].caught.append(str(text))


def _with_part(check: Check, name: str) -> Check:
    """``dataclasses.replace(check, part=name)`` (a copy of the frozen check with its part; the
    same fields, without running the generated ``__init__`` again)."""
    if check.part == name:
        return check
    new = object.__new__(type(check))
    new.__dict__.update(check.__dict__)
    object.__setattr__(new, "part", name)
    return new


def compute_parts(drive: Drive, wanted: tuple[str, ...], options: dict[str, Any], *,
                  computed: dict[str, _Computed] | None = None,
                  shared_checks: dict[str, list[Check]] | None = None,
                  ) -> tuple[dict[str, Any], list[Check], list[str]]:
    """Compute ``wanted`` and their needs; return (results of the wanted parts, their
    checks in report order, their notes and then every warning raised while computing,
    in order). Internal to analyze_drive and analyze_variants: ``computed`` holds parts
    already computed (reused, not recomputed), ``shared_checks`` their checks."""
    import warnings

    computed = {} if computed is None else computed
    plan = resolve(wanted)
    results: dict[str, Any] = {}
    checks: list[Check] = []
    notes: list[str] = []
    # one recording context for the whole analysis (each part's warnings are the records it
    # added); a part that changed the filters has them put back before the next part
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        filters = list(warnings.filters)

        def recorded(start: int) -> list[str]:
            if warnings.filters != filters:
                warnings.resetwarnings()  # marks the filters changed for the warnings module's caches
                warnings.filters[:] = filters  # type: ignore[index]  # a list at run time
            return [str(w.message) for w in caught[start:]]

        for part in plan:
            if part.name in computed:
                continue
            entry = computed[part.name] = _Computed()
            start = len(caught)
            entry.result = part.compute(PartContext(drive, part, computed, options))
            entry.caught = recorded(start)
        for part in sorted((p for p in plan if p.name in wanted), key=lambda p: (p.order, p.name)):
            res = computed[part.name].result
            results[part.name] = res
            if shared_checks is not None and part.name in shared_checks:
                checks.extend(shared_checks[part.name])
            elif res is not None and part.checks is not None:
                start = len(caught)
                checks.extend(_with_part(c, part.name) for c in part.checks(PartContext(drive, part, computed, options),
                                                                            res))
                computed[part.name].caught.extend(recorded(start))
            notes.extend(computed[part.name].notes)
    for part in plan:
        notes.extend(computed[part.name].caught)
    return results, checks, notes
