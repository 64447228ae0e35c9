"""No NaN or inf in, no NaN or inf out (internal).

:func:`finite_guard` wraps a public formula function so that

* a NaN or infinite number among its numeric arguments is refused with
  :class:`~chaindrive.errors.InputError` naming the parameter;
* a NaN or infinite number in its result (a formula evaluated outside its domain, or a
  product that overflows double precision for extreme but finite inputs) is raised as
  :class:`~chaindrive.errors.InfeasibleError` naming the function and the result field,
  instead of being returned;
* numerical failures of the libraries underneath (a singular or non-definite matrix, a
  degenerate convex hull, an overflow, arrays of incompatible shapes) become
  :class:`~chaindrive.errors.ConvergenceError` or :class:`~chaindrive.errors.InputError`
  with one clear line.

Errors of chaindrive itself pass unchanged. The wrapper keeps the function's name,
signature and docstring (``functools.wraps``); its cost is a few microseconds a call.
"""

from __future__ import annotations

import dataclasses
import functools
import inspect
import math
import sys
import threading
from collections.abc import Callable
from typing import Any, TypeVar, cast, overload

import numpy as np

from .errors import ChainDriveError, ConvergenceError, InfeasibleError, InputError

__all__ = ["finite_guard", "first_nonfinite", "check_finite_fields", "finite_fields", "guard_public", "guard_scope",
           "refuse_nonfinite_result"]

F = TypeVar("F", bound=Callable[..., Any])

_NUMERIC_SKIP = (str, bytes, bool, type(None))


class _GuardState(threading.local):
    depth = 0  # guarded calls on this thread's stack (numpy's error state is set by the outermost)


_GUARD = _GuardState()


# exact types that hold no NaN/inf, and the float types, looked up before the isinstance
# chains below (the checks run on every guarded call: these are the common arguments)
_PLAIN = frozenset({str, bytes, bool, type(None), int, np.int64, np.intp})
_FLOATS = frozenset({float, np.float64})
_FIELDS: dict[type, tuple[str, ...]] = {}  # dataclass type -> its field names


def _field_names(cls: type) -> tuple[str, ...]:
    names = _FIELDS.get(cls)
    if names is None:
        names = _FIELDS[cls] = tuple(f.name for f in dataclasses.fields(cls))
    return names


_FLOAT64 = np.dtype(np.float64)  # the native double's dtype (numpy hands out this one object)


def _all_finite(a: np.ndarray) -> bool:
    """Whether the float or complex array ``a`` holds no NaN and no infinity."""
    if a.size <= 16 and a.dtype.kind == "f":  # a short array: faster in Python than a ufunc and a reduction
        return all(map(math.isfinite, a.ravel().tolist()))
    if a.dtype is _FLOAT64 and _GUARD.depth:
        # inside a guard numpy's floating-point errors are ignored: a finite sum of squares has
        # finite terms only (a NaN or an infinity makes it NaN or infinite); one that overflows
        # is looked at term by term
        flat = a.ravel()
        if math.isfinite(flat.dot(flat)):
            return True
    return bool(np.isfinite(a).all())


def _nonfinite_number(value: Any) -> bool:
    """Whether ``value`` is a number or numeric array holding a NaN or an infinity."""
    t = type(value)
    if t in _FLOATS:
        return not math.isfinite(value)
    if t is np.ndarray:
        return value.dtype.kind in "fc" and not _all_finite(value)
    if t in _PLAIN:
        return False
    if isinstance(value, _NUMERIC_SKIP):
        return False
    if isinstance(value, float):
        return not math.isfinite(value)
    if isinstance(value, (np.floating, np.complexfloating, complex)):
        return not np.isfinite(value)
    if isinstance(value, np.ndarray):
        return value.dtype.kind in "fc" and not bool(np.all(np.isfinite(value)))
    if isinstance(value, (list, tuple)) and len(value) <= 10_000:
        for v in value:  # any(_nonfinite_number(v) for v in value), the common members without a call
            tv = type(v)
            if tv in _FLOATS:
                if not math.isfinite(v):
                    return True
            elif tv not in _PLAIN and _nonfinite_number(v):
                return True
        return False
    if not issubclass(t, _LOOKED_AT):
        _OPAQUE.add(t)  # never a number nor a sequence of them: the guard passes it at a glance
    return False


#: Types whose values :func:`_nonfinite_number` looks into; any other type it passes, and once
#: seen it is kept in :data:`_OPAQUE` for the guard's first glance.
_LOOKED_AT = (float, complex, np.number, np.ndarray, list, tuple, str, bytes, bool, type(None), int)
_OPAQUE: set[type] = set()


def first_nonfinite(obj: Any, _depth: int = 0) -> str | None:
    """Where the first NaN/inf of a result is (``''`` for the object itself), else ``None``.

    Walks numbers, numpy arrays, dataclasses, mappings and sequences.

    Examples
    --------
    >>> first_nonfinite({"a": [1.0, float("nan")]})
    "['a'][1]"
    >>> first_nonfinite((1.0, np.array([2.0]))) is None
    True
    """
    t = type(obj)
    if _depth > 12 or t in _PLAIN:
        return None
    if t in _FLOATS:
        return None if math.isfinite(obj) else ""
    if t is np.ndarray:
        if obj.dtype.kind in "fc" and obj.size and not _all_finite(obj):
            return f"[{int(np.flatnonzero(~np.isfinite(obj.ravel()))[0])}]"
        return None
    names = _FIELDS.get(t)
    if names is None and hasattr(t, "__dataclass_fields__") and dataclasses.is_dataclass(t):
        names = _field_names(t)
    if names is not None:
        for name in names:
            where = first_nonfinite(getattr(obj, name, None), _depth + 1)
            if where is not None:
                return f".{name}{where}"
        return None
    if t is tuple or t is list:
        for i, v in enumerate(obj):
            where = first_nonfinite(v, _depth + 1)
            if where is not None:
                return f"[{i}]{where}"
        return None
    if isinstance(obj, _NUMERIC_SKIP) or isinstance(obj, (int, np.integer)):
        return None
    if isinstance(obj, (float, np.floating)):
        return None if math.isfinite(obj) else ""
    if isinstance(obj, (complex, np.complexfloating)):
        return None if np.isfinite(obj) else ""
    if isinstance(obj, np.ndarray):
        if obj.dtype.kind in "fc" and obj.size and not np.all(np.isfinite(obj)):
            return f"[{int(np.flatnonzero(~np.isfinite(obj.ravel()))[0])}]"
        return None
    if dataclasses.is_dataclass(obj) and not isinstance(obj, type):
        for f in dataclasses.fields(obj):
            where = first_nonfinite(getattr(obj, f.name, None), _depth + 1)
            if where is not None:
                return f".{f.name}{where}"
        return None
    if isinstance(obj, dict):
        for k, v in obj.items():
            where = first_nonfinite(v, _depth + 1)
            if where is not None:
                return f"[{k!r}]{where}"
        return None
    if isinstance(obj, (list, tuple)):
        for i, v in enumerate(obj):
            where = first_nonfinite(v, _depth + 1)
            if where is not None:
                return f"[{i}]{where}"
        return None
    return None


def _finite_tree(obj: Any, _depth: int = 0) -> bool:
    """``first_nonfinite(obj) is None``, answered faster: no path built, the common members
    (plain values, floats, arrays) of dataclasses and sequences checked without a call."""
    t = type(obj)
    if t in _PLAIN or _depth > 12:
        return True
    if t in _FLOATS:
        return math.isfinite(obj)
    if t is np.ndarray:
        return obj.dtype.kind not in "fc" or not obj.size or _all_finite(obj)
    names = _FIELDS.get(t)
    if names is None and hasattr(t, "__dataclass_fields__") and dataclasses.is_dataclass(t):
        names = _field_names(t)
    if names is not None:
        values: Any = [getattr(obj, name, None) for name in names]
    elif t is tuple or t is list:
        values = obj
    elif t is dict:  # first_nonfinite walks a mapping's values the same way
        values = obj.values()
    else:
        return first_nonfinite(obj, _depth) is None
    if _depth >= 12:  # first_nonfinite looks no deeper
        return True
    for v in values:
        tv = type(v)
        if tv in _PLAIN:
            continue
        if tv in _FLOATS:
            if not math.isfinite(v):
                return False
        elif tv is np.ndarray:  # _finite_tree(v) of an array, without the call
            if v.dtype.kind in "fc" and v.size and not _all_finite(v):
                return False
        elif (tv is tuple or tv is list) and _depth < 11:  # one of plain numbers, without the call
            for x in v:
                tx = type(x)
                if tx in _FLOATS:
                    if not math.isfinite(x):
                        return False
                elif tx not in _PLAIN and not _finite_tree(x, _depth + 2):
                    return False
        elif not _finite_tree(v, _depth + 1):
            return False
    return True


def _show(value: Any) -> str:
    if isinstance(value, np.ndarray):
        bad = value[~np.isfinite(value)] if value.dtype.kind in "fc" else value
        return f"an array holding {float(bad.ravel()[0])!r}" if bad.size else "an array"
    return repr(value)


def check_finite_fields(obj: Any, names: tuple[str, ...] | None = None,
                        allow_infinite: tuple[str, ...] = ()) -> None:
    """Refuse NaN/inf in the numeric fields of a dataclass (for ``__post_init__``).

    Examples
    --------
    >>> @dataclasses.dataclass
    ... class P:
    ...     pitch: float
    >>> check_finite_fields(P(float("inf")))
    Traceback (most recent call last):
    ...
    chaindrive.errors.InputError: pitch must be finite (a number, not NaN or inf), got inf
    """
    for name in _field_names(type(obj)):
        if names is not None and name not in names:
            continue
        value = getattr(obj, name, None)
        if _nonfinite_number(value):
            if name in allow_infinite and not _has_nan(value):
                continue
            raise InputError(f"{name} must be finite (a number, not NaN or inf), got {_show(value)}")


@overload
def finite_guard(function: F, *, check_result: bool = ..., allow_infinite: tuple[str, ...] = ...) -> F: ...


@overload
def finite_guard(function: None = None, *, check_result: bool = ...,
                 allow_infinite: tuple[str, ...] = ...) -> Callable[[F], F]: ...


def finite_guard(function: F | None = None, *, check_result: bool = True,
                 allow_infinite: tuple[str, ...] = ()) -> F | Callable[[F], F]:
    """Decorate a public formula: NaN/inf arguments refused, NaN/inf results raised.

    Parameters
    ----------
    function : callable
        The function (the decorator may be used bare or called).
    check_result : bool
        Also check the returned value (numbers, arrays, dataclasses, mappings).
    allow_infinite : tuple of str
        Parameters that may be ``+inf`` by their documented meaning (e.g. the stiffness
        of a fixed tensioner); the function checks them itself.

    Examples
    --------
    >>> @finite_guard
    ... def ratio(a, b):
    ...     return a / b
    >>> ratio(1.0, np.array([2.0]))
    array([0.5])
    >>> ratio(float("nan"), 1.0)
    Traceback (most recent call last):
    ...
    chaindrive.errors.InputError: a must not be NaN (a finite number is needed), got nan
    >>> ratio(1e300, 1e-300)
    Traceback (most recent call last):
    ...
    chaindrive.errors.InfeasibleError: ratio: the result is not a finite number (inf) for these inputs: they lie outside the range where the formula is defined, or the numbers overflow double precision
    """
    if function is None:

        def decorate(inner: F) -> F:
            return finite_guard(inner, check_result=check_result, allow_infinite=allow_infinite)

        return decorate
    label = function.__name__

    @functools.lru_cache(maxsize=1)
    def parameter_names() -> list[str]:  # read when an argument is refused, not at import
        try:
            return list(inspect.signature(function).parameters)
        except (TypeError, ValueError):  # pragma: no cover - builtins
            return []

    if getattr(function, "_finite_guarded", False):  # guarded already
        return function

    @functools.wraps(function)
    def wrapper(*args, **kwargs):
        for i, value in enumerate(args):
            t = type(value)  # the common arguments answered here, without a call
            if (math.isfinite(value) if t in _FLOATS else (t in _PLAIN or t in _OPAQUE)) \
                    or not _nonfinite_number(value):
                continue
            names = parameter_names()
            name = names[i] if i < len(names) else f"argument {i + 1}"
            _refuse(name, value, allow_infinite)
        for name, value in kwargs.items():
            t = type(value)
            if (math.isfinite(value) if t in _FLOATS else (t in _PLAIN or t in _OPAQUE)) \
                    or not _nonfinite_number(value):
                continue
            _refuse(name, value, allow_infinite)
        try:
            if _GUARD.depth:  # an outer guard has set numpy's error state already
                _GUARD.depth += 1
                try:
                    result = function(*args, **kwargs)
                finally:
                    _GUARD.depth -= 1
            else:
                _GUARD.depth = 1
                try:
                    with np.errstate(all="ignore"):
                        result = function(*args, **kwargs)
                finally:
                    _GUARD.depth = 0
        except ChainDriveError:
            raise
        except np.linalg.LinAlgError as exc:
            raise ConvergenceError(f"{label}: the linear algebra failed for these inputs ({exc}); they "
                                   "are probably outside the physically meaningful range") from None
        except (OverflowError, ZeroDivisionError, FloatingPointError) as exc:
            raise InfeasibleError(f"{label}: the numbers overflow or divide by zero for these inputs "
                                  f"({exc}); check they are in SI units and physically plausible") from None
        except ValueError as exc:
            text = str(exc)
            if "broadcast" in text or "dimension" in text or "shape" in text:
                raise InputError(f"{label}: array arguments of incompatible shapes ({text.strip()}); give "
                                 "scalars or arrays that broadcast together") from None
            if "negative dimensions" in text:
                raise InputError(f"{label}: a count argument is negative ({text}); counts must be >= 1") from None
            # numpy/scipy refusing a value the function did not check itself (e.g. a
            # negative sample count, an empty range): an input outside its range
            raise InputError(f"{label}: an input is outside its valid range ({text.strip()})") from None
        except IndexError as exc:  # an index or a count argument outside the arrays it indexes
            raise InputError(f"{label}: an index or count argument is out of range for the other "
                             f"arguments ({str(exc).strip()})") from None
        except RuntimeError as exc:  # e.g. scipy's QhullError: a degenerate geometry
            if type(exc).__name__ in ("QhullError",):
                raise InfeasibleError(f"{label}: the geometry is degenerate for these inputs (the points are "
                                      "collinear or the numbers overflow); check the dimensions") from None
            raise
        if check_result and not _finite_tree(result):
            refuse_nonfinite_result(label, result)
        return result

    wrapper._finite_guarded = True  # type: ignore[attr-defined]
    return cast(F, wrapper)  # functools.wraps keeps the signature


def refuse_nonfinite_result(label: str, result: Any) -> None:
    """Raise :class:`~chaindrive.errors.InfeasibleError` naming ``label`` and the place of the first
    NaN/inf in ``result`` (what :func:`finite_guard` raises); nothing when it holds none. For a
    function guarded with ``check_result=False`` that checks a result it computes afresh itself."""
    if _finite_tree(result):
        return
    where = first_nonfinite(result)
    if where is not None:
        raise InfeasibleError(
            f"{label}: the result{' ' + where.lstrip('.') if where else ''} is not a finite number "
            f"({_bad_value(result, where)}) for these inputs: they lie outside the range where the "
            "formula is defined, or the numbers overflow double precision")


class guard_scope:  # noqa: N801 - used like a function (``with guard_scope():``)
    """Context for many guarded calls: numpy's error state is set once, on entry, instead
    of by each outermost guarded call (each call still checks its arguments and result).

    Examples
    --------
    >>> @finite_guard
    ... def ratio(a, b):
    ...     return a / b
    >>> with guard_scope():
    ...     ratio(1.0, np.array([2.0]))
    array([0.5])
    """

    __slots__ = ("_state",)

    def __enter__(self) -> guard_scope:
        self._state = None
        if not _GUARD.depth:
            self._state = np.errstate(all="ignore")
            self._state.__enter__()
        _GUARD.depth += 1
        return self

    def __exit__(self, *exc: Any) -> None:
        _GUARD.depth -= 1
        if self._state is not None:
            self._state.__exit__(*exc)


def _has_nan(value: Any) -> bool:
    if isinstance(value, (list, tuple)):
        return any(_has_nan(v) for v in value)
    try:
        return bool(np.any(np.isnan(np.asarray(value))))
    except (TypeError, ValueError):
        return False


def _refuse(name: str, value: Any, allow_infinite: tuple[str, ...]) -> None:
    if name in allow_infinite:  # the function checks these itself (its range includes +inf)
        return
    if _has_nan(value):
        raise InputError(f"{name} must not be NaN (a finite number is needed), got {_show(value)}")
    raise InputError(f"{name} must be finite (a number, not NaN or inf), got {_show(value)}")


def _bad_value(result: Any, where: str) -> str:
    try:
        text = repr(_walk(result, where))
    except Exception:  # noqa: BLE001 - only for the message
        return "NaN or inf"
    return text.removeprefix("np.float64(").removesuffix(")")


def _walk(obj: Any, where: str) -> Any:
    import ast
    import re

    for part in re.findall(r"\.([A-Za-z_]\w*)|\[([^\]]+)\]", where):
        attr, key = part
        if attr:
            obj = getattr(obj, attr)
        else:
            if isinstance(obj, dict):
                obj = obj[ast.literal_eval(key)]
            else:
                obj = np.asarray(obj).ravel()[int(key)] if isinstance(obj, np.ndarray) else obj[int(key)]
    return obj


C = TypeVar("C", bound=type)


def finite_fields(cls: C | None = None, *, allow_infinite: tuple[str, ...] = ()) -> Any:
    """Class decorator (above ``@dataclass``, or applied after it): the constructor refuses
    NaN/inf in any numeric field with :class:`~chaindrive.errors.InputError` naming the field.

    Parameters
    ----------
    cls : type
        A dataclass.
    allow_infinite : tuple of str
        Fields that may be ``+inf`` or ``-inf`` by their documented meaning (never NaN).

    Examples
    --------
    >>> @finite_fields
    ... @dataclasses.dataclass(frozen=True)
    ... class Span:
    ...     length: float
    >>> Span(float("nan"))
    Traceback (most recent call last):
    ...
    chaindrive.errors.InputError: length must be finite (a number, not NaN or inf), got nan
    """
    if cls is None:
        return lambda inner: finite_fields(inner, allow_infinite=allow_infinite)
    if getattr(cls, "_finite_fields", False) is cls:  # applied already
        return cls
    init = cls.__init__  # type: ignore[misc]

    @functools.wraps(init)
    def __init__(self, *args, **kwargs):
        init(self, *args, **kwargs)
        check_finite_fields(self, allow_infinite=allow_infinite)

    cls.__init__ = __init__  # type: ignore[misc]
    cls._finite_fields = cls  # type: ignore[attr-defined]
    return cls


def guard_public(module: str, *, skip: tuple[str, ...] = (), allow_infinite: tuple[str, ...] = ()) -> None:
    """Guard every public function and dataclass of ``module`` (its ``__all__``, or without
    one the public names defined there) at once.

    Call it as the last line of a formula module (``guard_public(__name__)``): each public
    function defined there gets :func:`finite_guard` (NaN/inf arguments refused by name,
    NaN/inf results and numerical failures raised as chaindrive errors), each public
    dataclass :func:`finite_fields`. Names already guarded are left as they are; ``skip``
    names the exceptions (say why beside the call).

    Parameters
    ----------
    module : str
        The module's ``__name__``.
    skip : tuple of str
        Public names left unguarded.
    allow_infinite : tuple of str
        Parameters and fields that may be infinite by their documented meaning.
    """
    mod = sys.modules[module]
    names = getattr(mod, "__all__", None)
    if names is None:  # no __all__: the public names defined in the module
        names = [n for n in list(vars(mod)) if not n.startswith("_")]
    for name in names:
        if name in skip:
            continue
        obj = getattr(mod, name, None)
        if getattr(obj, "__module__", None) != module:
            continue
        if inspect.isfunction(obj):
            setattr(mod, name, finite_guard(obj, allow_infinite=allow_infinite))
        elif inspect.isclass(obj) and dataclasses.is_dataclass(obj):
            finite_fields(obj, allow_infinite=allow_infinite)
