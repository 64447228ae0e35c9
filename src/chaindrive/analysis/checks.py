"""The one :class:`Check` of chaindrive: a verdict with its value, limit, unit and source."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from .._results import Result
from ..errors import InputError

__all__ = ["Check", "RELATIONS"]

#: How a check's value is compared with its limit.
RELATIONS = (">=", "<=", "within", "info")


@dataclass(frozen=True)
class Check(Result):
    """One verdict of the analysis, in SI units.

    Parameters
    ----------
    name : str
        What is checked, in words.
    value : float or None
        The computed value [``unit``]; ``None`` when it cannot be computed (then
        ``note`` says why).
    limit : float, (float, float) or None
        The limit [``unit``]: a bound for ``">="``/``"<="``, a ``(low, high)`` range for
        ``"within"``, ``None`` for ``"info"``.
    unit : str
        SI unit of ``value`` and ``limit`` (``"N"``, ``"W"``, ``"Pa"``, ``"rad"``,
        ``"h"``, ``"-"``).
    passed : bool or None
        ``True``/``False`` for a verdict, ``None`` for information or unknown value.
    source : str
        The publication and equation, standard and clause, or book and page.
    note : str
        Detail for the reader.
    relation : {">=", "<=", "within", "info"}
    display : str
        The unit the value is shown in when not the default display unit of ``unit``
        (``"%"`` for a ratio, :data:`chaindrive.workflows.display.CONVERSIONS`); empty: the default.
    part : str
        The analysis part that made the check (set by :func:`~chaindrive.analysis.analyze_drive`
        from the part's declaration, :mod:`chaindrive.analysis.parts`).

    Examples
    --------
    >>> c = Check("static safety F_B / F_max", 9.1, 7.0, "-", True, "ISO 10823:2004")
    >>> c.verdict, round(c.margin, 3)
    ('pass', 0.3)
    """

    name: str
    value: float | None
    limit: float | tuple[float, float] | None
    unit: str
    passed: bool | None
    source: str
    note: str = ""
    relation: Literal[">=", "<=", "within", "info"] = ">="
    part: str = ""
    display: str = ""

    @property
    def verdict(self) -> str:
        """``"pass"``, ``"FAIL"``, ``"info"`` or ``"unknown"``."""
        if self.relation == "info":
            return "info"
        if self.passed is None:
            return "unknown"
        return "pass" if self.passed else "FAIL"

    @property
    def margin(self) -> float | None:
        """Relative margin to the limit (positive: on the safe side) [-]."""
        if self.value is None or self.limit is None or self.relation == "info":
            return None
        limit = self.limit
        if self.relation == "within":
            if not isinstance(limit, tuple):
                raise InputError(f"check {self.name!r}: a 'within' limit must be (low, high), got {limit!r}",
                                 field="limit")
            lo, hi = limit
            return float(min(self.value - lo, hi - self.value) / max(abs(hi - lo), 1e-300))
        if isinstance(limit, tuple):
            raise InputError(f"check {self.name!r}: a {self.relation!r} limit must be one number, got {limit!r}",
                             field="limit")
        lim = float(limit)
        if lim == 0:
            return float(self.value) if self.relation == ">=" else -float(self.value)
        r = float(self.value) / lim - 1.0
        return r if self.relation == ">=" else -r

    def to_dict(self) -> dict:
        d = super().to_dict()
        d["verdict"] = self.verdict
        d["margin"] = self.margin
        return d
