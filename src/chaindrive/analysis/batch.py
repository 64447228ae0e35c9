r"""Many variants of one drive analysed together: what does not change is computed once.

Design studies ask for thousands to millions of variants of one drive that differ in a
few inputs (a skew, a wear factor, a tensioner's mass). :func:`analyze_variants` takes
the base :class:`~chaindrive.drive.Drive` and, per variant, the fields that change; it
finds which declared parts read those fields (by recording, on the base drive, which
fields each part's compute and checks functions read) and computes every other part
once for all variants. A part that reads a changed field, or needs one that does, is
computed per variant, or for all variants in one vectorised call where the part
declares one (``Part.batch``).

The recording is sound for pure parts: the variants differ only in the changed fields,
so a part that never read them on the base drive takes the same branches, reads the
same values and returns the same result for every variant. The results equal those of
:func:`~chaindrive.analysis.analyze_drive` variant by variant (tests compare them to
1e-12).

Examples
--------
>>> from chaindrive.drive.project import load_project
>>> drive = load_project("examples/roller_industrial.toml")
>>> changes = [{("contact", "wear_factor"): k} for k in (0.6, 0.65, 0.7)]
>>> out = analyze_variants(drive, changes, include=["contact", "loads"])
>>> [round(a.contact.result.stress / 1e6, 1) for a in out]
[104.4, 108.4, 112.5]
>>> out.shared
('layout', 'entry', 'conveyor', 'loads')
"""

from __future__ import annotations

import contextvars
import dataclasses
from collections.abc import Iterable, Mapping, Sequence
from typing import Any

from ..drive.model import Drive
from ..errors import ChainDriveError, InputError
from ..limits import check_size
from .checks import Check
from .parts import Part, _Computed, compute_parts, resolve

__all__ = ["analyze_variants", "VariantAnalyses", "replace_path", "replace_paths", "MAXIMUM_VARIANTS_PER_CALL"]

#: Largest number of variants in one call (the study runner sends batches).
MAXIMUM_VARIANTS_PER_CALL = 1_000_000

FieldPath = tuple[str | int, ...]

_READS: contextvars.ContextVar[set[str] | None] = contextvars.ContextVar("chaindrive_drive_reads", default=None)
_RECORDING_CLASSES: dict[type, type] = {}


def _recording_getattribute(self: Any, name: str) -> Any:
    reads = _READS.get()
    if reads is not None and name in type(self).__dataclass_fields__:
        reads.add(name)
    return object.__getattribute__(self, name)


def _recording(drive: Any) -> Any:
    """``drive`` (any dataclass instance) as an instance of a subclass that records the fields read (while a
    recording set is active)."""
    cls = type(drive)
    sub = _RECORDING_CLASSES.get(cls)
    if sub is None:
        sub = type(f"Recording{cls.__name__}", (cls,), {"__getattribute__": _recording_getattribute,
                                                         "__module__": cls.__module__})
        _RECORDING_CLASSES[cls] = sub
    obj: Drive = object.__new__(sub)
    obj.__dict__.update(drive.__dict__)
    return obj


def replace_paths(obj: Any, changes: Mapping[FieldPath, Any]) -> Any:
    """A copy of ``obj`` with every field of ``changes`` replaced, each object along the
    paths replaced (and validated) once.

    >>> from chaindrive.drive.project import load_project
    >>> d = load_project("examples/roller_industrial.toml")
    >>> e = replace_paths(d, {("wheels", 0, "teeth"): 21, ("wheels", 1, "teeth"): 63})
    >>> e.wheels[0].teeth, e.wheels[1].teeth
    (21, 63)
    """
    if () in changes:
        return changes[()]
    groups: dict[str | int, dict[FieldPath, Any]] = {}
    for path, value in changes.items():
        groups.setdefault(path[0], {})[tuple(path[1:])] = value
    if isinstance(obj, tuple):
        items = list(obj)
        for head, sub in groups.items():
            if not isinstance(head, int) or not -len(obj) <= head < len(obj):
                raise InputError(f"no item {head} in {type(obj).__name__}", field=str(head))
            items[head] = replace_paths(items[head], sub)
        return tuple(items)
    if not dataclasses.is_dataclass(obj):
        raise InputError(f"{type(obj).__name__} has no fields to replace", field=str(next(iter(groups))))
    names = {f.name for f in dataclasses.fields(obj)}
    for head in groups:
        if head not in names:
            raise InputError(f"{type(obj).__name__} has no field {head!r}", field=str(head))
    return dataclasses.replace(obj, **{str(h): replace_paths(getattr(obj, str(h)), sub)  # type: ignore[type-var]
                                       for h, sub in groups.items()})


def replace_path(obj: Any, path: FieldPath, value: Any) -> Any:
    """A copy of the frozen dataclass ``obj`` with the field at ``path`` replaced (through
    nested dataclasses and tuples); each replaced object validates itself again.

    >>> from chaindrive.drive.project import load_project
    >>> d = load_project("examples/roller_industrial.toml")
    >>> replace_path(d, ("wheels", 0, "teeth"), 21).wheels[0].teeth
    21
    """
    if not path:
        return value
    head, rest = path[0], path[1:]
    if isinstance(head, int):
        if not isinstance(obj, tuple) or not -len(obj) <= head < len(obj):
            raise InputError(f"no item {head} in {type(obj).__name__}", field=str(head))
        items = list(obj)
        items[head] = replace_path(items[head], rest, value)
        return tuple(items)
    if not dataclasses.is_dataclass(obj) or head not in {f.name for f in dataclasses.fields(obj)}:
        raise InputError(f"{type(obj).__name__} has no field {head!r}", field=str(head))
    return dataclasses.replace(obj, **{head: replace_path(getattr(obj, head), rest, value)})  # type: ignore[type-var]


class VariantAnalyses(list):  # type: ignore[type-arg]
    """The analyses of the variants, in order (a list of
    :class:`~chaindrive.analysis.DriveAnalysis`, or of the exception a variant raised);
    ``shared`` names the parts computed once, ``per_variant`` those computed per variant."""

    shared: tuple[str, ...] = ()
    per_variant: tuple[str, ...] = ()


def _affected(plan: Sequence[Part], reads: Mapping[str, set[str]], changed: set[str]) -> set[str]:
    out: set[str] = set()
    for part in plan:  # needs come first in a resolved plan
        if reads[part.name] & changed or any(n in out for n in part.needs):
            out.add(part.name)
    return out


def analyze_variants(drive: Drive, changes: Sequence[Mapping[FieldPath, Any]], *,
                     include: Iterable[str] | None = None, exclude: Iterable[str] | None = None,
                     entry_points: int = 361, errors: str = "raise") -> VariantAnalyses:
    """Analyse the variants of ``drive`` given by ``changes`` (one mapping per variant from
    a field path such as ``("contact", "skew")`` or ``("wheels", 0, "teeth")`` to its new
    value, SI units).

    Parameters
    ----------
    drive : Drive
        The base drive.
    changes : sequence of mapping
        Per variant, the fields that differ from ``drive`` (at most
        :data:`MAXIMUM_VARIANTS_PER_CALL` variants).
    include, exclude, entry_points
        As for :func:`~chaindrive.analysis.analyze_drive`.
    errors : {"raise", "return"}
        A variant whose drive or analysis fails: raise, or put the exception in its place.

    Returns
    -------
    VariantAnalyses
        One :class:`~chaindrive.analysis.DriveAnalysis` per variant, equal to
        ``analyze_drive(variant)``.

    Raises
    ------
    InputError
        Bad arguments, or (``errors="raise"``) a variant's drive is invalid.
    """
    from . import _parts

    if not isinstance(drive, Drive):
        raise InputError(f"drive must be a chaindrive.drive.Drive, got {type(drive).__name__}", field="drive")
    if errors not in ("raise", "return"):
        raise InputError(f"errors must be 'raise' or 'return', got {errors!r}", field="errors")
    check_size("variants", len(changes), MAXIMUM_VARIANTS_PER_CALL)
    parts = _parts(include, exclude)
    options = {"entry_points": entry_points}
    plan = resolve(parts)
    changed = {str(path[0]) for change in changes for path in change}
    out = VariantAnalyses()

    # 1. the base drive once, recording the fields each part reads (compute and checks)
    reads: dict[str, set[str]] = {p.name: set() for p in plan}
    recorder = _recording(drive)
    computed: dict[str, _Computed] = {}
    base_checks: dict[str, list[Check]] = {}
    failed = False
    for part in plan:
        token = _READS.set(reads[part.name])
        try:
            _, checks, _ = compute_parts(recorder, (part.name,), options, computed=computed)
            base_checks[part.name] = checks
        except ChainDriveError:
            failed = True  # the base drive fails here: every part is computed per variant
            break
        finally:
            _READS.reset(token)
    affected = {p.name for p in plan} if failed else _affected(plan, reads, changed)
    shared = {name: computed[name] for name in computed if name not in affected}
    shared_checks = {name: base_checks[name] for name in shared if name in parts}
    out.shared = tuple(p.name for p in plan if p.name in shared)
    out.per_variant = tuple(p.name for p in plan if p.name in affected)

    # 2. the variants' drives; then each affected part for all of them (vectorised where
    # the part declares it), then their checks
    n = len(changes)
    failures: list[BaseException | None] = [None] * n
    drives = _variant_drives(drive, changes, failures, errors)
    computed_v = [dict(shared) for _ in range(n)]
    for part in plan:
        if part.name in shared:
            continue
        live = [i for i in range(n) if failures[i] is None]
        _compute_for_variants(part, live, drives, computed_v, failures, options, errors)
    _assemble(out, plan, parts, drives, computed_v, failures, shared, shared_checks, options, errors)
    return out


def _variant_drives(drive: Drive, changes: Sequence[Mapping[FieldPath, Any]], failures: list[BaseException | None],
                    errors: str) -> list[Drive | None]:
    """The variants' drives, as :func:`replace_paths` builds them; variants that change
    the same paths as the first rebuild the objects along those paths from keyword
    arguments read once (the same constructor calls, so the same validation)."""
    n = len(changes)
    drives: list[Drive | None] = [None] * n
    plans: dict[tuple[FieldPath, ...], Any] = {}
    for i, change in enumerate(changes):
        try:
            if not change:
                drives[i] = drive
                continue
            paths = tuple(tuple(p) for p in change)
            if paths not in plans or plans[paths] is None:  # the first variant of these paths: the checked way
                drives[i] = replace_paths(drive, dict(zip(paths, change.values(), strict=True)))
                if paths not in plans:
                    plans[paths] = _shell(drive, _rebuild_plan(drive, paths))
                continue
            drives[i] = _rebuild(plans[paths], iter(change.values()))
        except Exception as exc:
            if errors == "raise":
                raise
            failures[i] = exc
    return drives


def _rebuild_plan(obj: Any, paths: Sequence[FieldPath]) -> Any:
    """How to rebuild ``obj`` with new values at ``paths`` (given in that order):
    ``("value", index)``, ``("tuple", items, {position: plan})`` or
    ``("object", class, keyword arguments, {name: plan})``."""
    if len(paths) == 1 and paths[0] == ():
        return ("value",)
    if any(not p for p in paths):  # a path and one inside it: replace_paths decides
        return None
    groups: dict[str | int, list[FieldPath]] = {}
    for path in paths:
        groups.setdefault(path[0], []).append(tuple(path[1:]))
    init: Any
    if isinstance(obj, tuple):
        subs = {h: _rebuild_plan(obj[h], sub) for h, sub in groups.items()}  # type: ignore[index]
        kind, init = "tuple", list(obj)
    else:
        subs = {h: _rebuild_plan(getattr(obj, str(h)), sub) for h, sub in groups.items()}
        kind, init = "object", {f.name: getattr(obj, f.name) for f in dataclasses.fields(obj) if f.init}
    if any(sub is None for sub in subs.values()):
        return None
    return (kind, type(obj), init, subs, _order(paths))


def _order(paths: Sequence[FieldPath]) -> list[tuple[str | int, int]]:
    """For each value in turn (paths in the given order): its head and its place
    among the values of that head."""
    seen: dict[str | int, int] = {}
    out = []
    for path in paths:
        out.append((path[0], seen.get(path[0], 0)))
        seen[path[0]] = seen.get(path[0], 0) + 1
    return out


def _rebuild(plan: Any, values: Any) -> Any:
    if plan[0] == "value":
        return next(values)
    kind, base, init, subs, order = plan
    per_head: dict[str | int, list[Any]] = {}
    for head, _ in order:
        per_head.setdefault(head, []).append(next(values))
    if kind == "tuple":
        items = list(init)
        for head, sub in subs.items():
            items[head] = _rebuild(sub, iter(per_head[head]))
        return tuple(items)
    kwargs = dict(init)
    for head, sub in subs.items():
        kwargs[head] = _rebuild(sub, iter(per_head[head]))
    if kind == "shell":  # the fields as validated on the base; the changed objects built by their classes
        new = object.__new__(base)
        new.__dict__.update(kwargs)
        return new
    return base(**kwargs)


def _shell(drive: Drive, plan: Any) -> Any:
    """``plan`` with the drive's own construction skipped where that is exact: every change
    lies inside a dataclass field of the drive, and the drive's ``__post_init__``, run on
    the base with those objects recording, reads none of their fields and keeps them as
    they are (its checks then pass and normalise alike for every variant; the changed
    objects are still built, and checked, by their own classes)."""
    if plan is None or plan[0] != "object" or any(isinstance(h, int) for h in plan[3]):
        return plan
    cls = type(drive)
    post = getattr(cls, "__post_init__", None)
    reads: set[str] = set()
    recorders = {}
    token = _READS.set(reads)
    try:
        probe = object.__new__(cls)
        probe.__dict__.update(drive.__dict__)
        for head in plan[3]:
            value = drive.__dict__.get(str(head))
            if value is None or not dataclasses.is_dataclass(value) or isinstance(value, type) \
                    or plan[3][head][0] != "object":
                return plan
            recorders[head] = probe.__dict__[head] = _recording(value)
        if post is not None:
            post(probe)
    except Exception:  # noqa: BLE001 - not a plain dataclass, or the base is refused: construct each variant
        return plan
    finally:
        _READS.reset(token)
    if reads or any(probe.__dict__[h] is not r for h, r in recorders.items()):
        return plan
    kind, base, _, subs, order = plan
    return ("shell", base, dict(drive.__dict__), subs, order)


def _with_part(check: Check, name: str) -> Check:
    """``dataclasses.replace(check, part=name)`` (Check has no __post_init__)."""
    if check.part == name:
        return check
    new = object.__new__(type(check))
    new.__dict__.update(check.__dict__)
    new.__dict__["part"] = name
    return new


def _assemble(out: VariantAnalyses, plan: Sequence[Part], parts: tuple[str, ...], drives: list[Drive | None],
              computed_v: list[dict[str, _Computed]], failures: list[BaseException | None],
              shared: dict[str, _Computed], shared_checks: dict[str, list[Check]], options: dict[str, Any], errors: str) -> None:
    """Each variant's analysis from its computed parts, as
    :func:`~chaindrive.analysis.parts.compute_parts` assembles it: the wanted parts'
    results and checks in report order (shared checks reused, the others computed with
    their warnings), then the notes and the warnings of every part."""
    import warnings

    from . import DriveAnalysis
    from .parts import PartContext

    wanted = sorted((p for p in plan if p.name in parts), key=lambda p: (p.order, p.name))
    names = [p.name for p in plan]
    # what every variant shares is joined once: its results, its checks, and the notes and
    # warnings of runs of shared parts (a variant's own parts are read in their places)
    template = {p.name: shared[p.name].result if p.name in shared else None for p in wanted}
    note_plan: list[Any] = []  # lists of shared notes, or names of parts computed per variant
    check_plan: list[Any] = []  # lists of shared checks, or per-variant parts
    for part in wanted:
        if part.name in shared_checks:
            check_plan.append(list(shared_checks[part.name]))
        else:
            check_plan.append(part)
    notes_of: list[Any] = [("notes", p.name) for p in wanted] + [("caught", name) for name in names]
    for what, name in notes_of:
        if name in shared:
            entry = shared[name]
            note_plan.append(list(entry.notes if what == "notes" else entry.caught))
        else:
            note_plan.append((what, name))
    check_plan = _join_lists(check_plan)
    note_plan = _join_lists(note_plan)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        for i, comp in enumerate(computed_v):
            if failures[i] is not None:
                out.append(failures[i])
                continue
            d = drives[i]
            try:
                if len(comp) < len(names):  # a part not computed: the general way
                    results, checks, notes = compute_parts(d, parts, options, computed=comp,  # type: ignore[arg-type]
                                                           shared_checks=shared_checks)
                else:
                    results = dict(template)
                    checks = []
                    for step in check_plan:
                        if isinstance(step, list):
                            checks.extend(step)
                            continue
                        entry = comp[step.name]
                        res = results[step.name] = entry.result
                        if res is not None and step.checks is not None:
                            k = len(caught)
                            checks.extend(_with_part(c, step.name)
                                          for c in step.checks(PartContext(d, step, comp, options), res))  # type: ignore[arg-type]
                            if len(caught) > k:
                                entry.caught.extend(str(w.message) for w in caught[k:])
                                del caught[k:]
                    notes = []
                    for step in note_plan:
                        if isinstance(step, list):
                            notes.extend(step)
                        else:
                            entry = comp[step[1]]
                            notes.extend(entry.notes if step[0] == "notes" else entry.caught)
                out.append(DriveAnalysis(drive=d, results=results, checks=tuple(checks),  # type: ignore[arg-type]
                                         warnings=tuple(dict.fromkeys(notes)), parts=parts))
            except Exception as exc:
                if errors == "raise":
                    raise
                out.append(exc)
            del caught[:]


def _join_lists(steps: list[Any]) -> list[Any]:
    """Adjacent lists joined into one."""
    out: list[Any] = []
    for step in steps:
        if isinstance(step, list) and out and isinstance(out[-1], list):
            out[-1] = out[-1] + step
        else:
            out.append(step)
    return out


def _compute_for_variants(part: Part, live: list[int], drives: list[Drive | None], computed_v: list[dict[str, _Computed]],
                          failures: list[BaseException | None], options: dict[str, Any], errors: str) -> None:
    """``part`` for the variants ``live``: one vectorised call where the part has one and it
    runs clean (no warning, no error), else one by one (each with its own warnings)."""
    import warnings

    from .parts import PartContext

    entries = {i: _Computed() for i in live}
    for i in live:
        computed_v[i][part.name] = entries[i]
    contexts = [PartContext(drives[i], part, computed_v[i], options) for i in live]  # type: ignore[arg-type]
    if part.batch is not None and len(live) > 1:
        try:
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always")
                results = part.batch(contexts)
        except Exception:  # noqa: BLE001 - a variant is refused: find which, one by one
            results = None
        if results is not None and not caught and len(results) == len(live):
            for i, res in zip(live, results, strict=True):
                entries[i].result = res
            return
        for i in live:  # notes and warnings of the discarded call
            entries[i].notes.clear()
            entries[i].caught.clear()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        for i, ctx in zip(live, contexts, strict=True):
            try:
                entries[i].result = part.compute(ctx)
            except Exception as exc:
                if errors == "raise":
                    raise
                failures[i] = exc
            entries[i].caught = [str(w.message) for w in caught]
            del caught[:]
