"""The study file: a base project, the inputs to vary, the plan, the outputs wanted.

A study file is TOML, checked with pydantic like a project file (errors name the field
and the line)::

    [study]
    name = "Skew tolerance of the 16B fan drive"
    base = "roller_industrial.toml"       # project file, relative to this study file
    outputs = ["contact.stress", "contact.relative_life_wear", "wear.hours_to_limit", "passed"]
    remove = ["contact.skew_height_difference", "contact.skew_base"]   # optional

    [plan]
    kind = "monte_carlo"                  # "grid", "latin_hypercube" or "monte_carlo"
    samples = 400
    seed = 2026

    [[vary]]
    path = "contact.skew"                 # dotted path into the project file
    unit = "arcmin"
    distribution = "uniform"              # a scipy.stats name, its arguments in `unit`
    parameters = { loc = 42, scale = 164 }

    [set]                                 # optional: fixed changes to the base file
    "contact.wear_factor" = 0.65

    [simulation]                          # optional, for outputs "simulation.*"
    duration = "0.5 s"

An input's values are written into the base project's mapping exactly as a project file
writes them (``"50 arcmin"``) and the variant's :class:`~chaindrive.drive.Drive` is
built by :func:`chaindrive.drive.project.project_from_mapping`: the project file's own
checks apply to every variant. Outputs are dotted paths into the analysis result's
``to_dict()`` (:func:`chaindrive.study.run.analysis_result`), e.g. ``"loads.maximum"``,
``"contact.stress"``, ``"wear.hours_to_limit"``, ``"vibration.tensioner.check.passed"``,
``"checks.<check name>.passed"``, ``"passed"``, and ``"simulation.<summary key>"``.
"""

from __future__ import annotations

import copy
import hashlib
import json
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path
from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field, ValidationError, field_validator

from ..errors import InputError
from .plan import MAXIMUM_VARIANTS, Variable, format_value, plan_rows

__all__ = ["Study", "load_study", "parse_study", "RESULT_KEYS", "result_heads", "MAXIMUM_BATCH_SIZE",
           "MAXIMUM_SIMULATION_DURATION", "set_path", "remove_path", "canonical_hash"]

#: Top-level names of an analysis result that are not analysis parts.
RESULT_KEYS = ("inputs", "checks", "warnings", "passed", "simulation", "dynamics")


def result_heads() -> tuple[str, ...]:
    """Top-level names an output path may start with: every declared analysis part
    (:func:`chaindrive.analysis.parts.part_names`) and :data:`RESULT_KEYS`."""
    from ..analysis.parts import part_names

    return (RESULT_KEYS[0], *part_names(), *RESULT_KEYS[1:])


def __getattr__(name: str) -> Any:
    if name == "RESULT_PARTS":  # kept for callers of the former constant: a live view
        return result_heads()
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")

#: Largest number of variants sent to a worker as one task.
MAXIMUM_BATCH_SIZE = 20_000

#: Longest simulated time per variant for ``simulation.*`` outputs [s].
MAXIMUM_SIMULATION_DURATION = 10.0


class _Model(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class StudySection(_Model):
    """``[study]``."""

    name: str = "design study"
    description: str = ""
    base: str
    outputs: list[str] = Field(min_length=1)
    remove: list[str] = []
    batch_size: int | None = Field(default=None, ge=1, le=MAXIMUM_BATCH_SIZE)

    @field_validator("outputs")
    @classmethod
    def _outputs(cls, value: list[str]) -> list[str]:
        for out in value:
            head = out.split(".", 1)[0]
            heads = result_heads()
            if head not in heads:
                raise ValueError(f"output {out!r} must start with one of {', '.join(heads)}")
        if len(set(value)) != len(value):
            raise ValueError("outputs must not repeat a path")
        return value


class PlanSection(_Model):
    """``[plan]``."""

    kind: Literal["grid", "latin_hypercube", "monte_carlo"] = "grid"
    samples: int | None = Field(default=None, ge=1, le=MAXIMUM_VARIANTS)
    seed: int = 0


class VarySpec(_Model):
    """``[[vary]]``."""

    path: str = Field(min_length=1)
    unit: str = ""
    values: list[float | int | str] | None = None
    low: float | None = None
    high: float | None = None
    count: int | None = None
    scale: Literal["linear", "log"] = "linear"
    distribution: str | None = None
    parameters: dict[str, float] = {}
    integer: bool = False


class SimulationSection(_Model):
    """``[simulation]``."""

    duration: float | str = "0.5 s"
    samples: int = Field(default=400, ge=10, le=5000)


class SummarySection(_Model):
    """``[summary]``: what ``chaindrive study --summary`` draws as the feasible region."""

    feasible: str | None = None
    axes: list[str] | None = Field(default=None, min_length=2, max_length=2)


class StudyFile(_Model):
    """The whole study file."""

    study: StudySection
    plan: PlanSection = PlanSection()
    vary: list[VarySpec] = Field(min_length=1)
    set: dict[str, Any] = {}
    simulation: SimulationSection | None = None
    summary: SummarySection = SummarySection()


# --------------------------------------------------------------------------- paths


def _split(path: str) -> list[str | int]:
    parts: list[str | int] = []
    for p in path.split("."):
        if not p:
            raise InputError(f"path {path!r}: empty part (write it like 'contact.skew' or "
                             "'wheels.1.teeth')")
        parts.append(int(p) if p.isdigit() else p)
    return parts


def _walk(data: dict, path: str, *, create: bool) -> tuple[Any, str | int]:
    parts = _split(path)
    node: Any = data
    for i, part in enumerate(parts[:-1]):
        here = ".".join(str(p) for p in parts[: i + 1])
        if isinstance(part, int):
            if not isinstance(node, list) or not 0 <= part < len(node):
                size = len(node) if isinstance(node, list) else 0
                raise InputError(f"path {path!r}: {here} is not an entry of the base project "
                                 f"(valid indices 0...{size - 1})" if size else
                                 f"path {path!r}: {here}: no list there in the base project")
            node = node[part]
            continue
        if not isinstance(node, dict):
            raise InputError(f"path {path!r}: {here}: no table there in the base project")
        if part not in node:
            if not create:
                raise InputError(f"path {path!r}: the base project has no {here!r}")
            node[part] = {}
        node = node[part]
    last = parts[-1]
    if isinstance(last, int):
        if not isinstance(node, list) or not 0 <= last < len(node):
            raise InputError(f"path {path!r}: index {last} is outside the base project's list")
    elif not isinstance(node, dict):
        raise InputError(f"path {path!r}: no table to hold {last!r} in the base project")
    return node, last


def set_path(data: dict, path: str, value: Any) -> None:
    """Set ``value`` at the dotted ``path`` of a project mapping (tables created as needed).

    Examples
    --------
    >>> d = {"wheels": [{"teeth": 19}, {"teeth": 57}]}
    >>> set_path(d, "wheels.1.teeth", 38); set_path(d, "contact.skew", "50 arcmin"); d
    {'wheels': [{'teeth': 19}, {'teeth': 38}], 'contact': {'skew': '50 arcmin'}}
    """
    node, last = _walk(data, path, create=True)
    node[last] = value


def remove_path(data: dict, path: str) -> None:
    """Remove the entry at the dotted ``path`` of a project mapping (it must exist).

    Examples
    --------
    >>> d = {"contact": {"skew_base": 0.02, "wear_factor": 0.65}}
    >>> remove_path(d, "contact.skew_base"); d
    {'contact': {'wear_factor': 0.65}}
    """
    node, last = _walk(data, path, create=False)
    if isinstance(last, int) or last not in node:
        raise InputError(f"study.remove: {path!r} is not in the base project")
    del node[last]


def _flatten(table: dict, prefix: str = "") -> list[tuple[str, Any]]:
    """``{"contact": {"skew": x}}`` (TOML ``contact.skew = x``) as ``[("contact.skew", x)]``."""
    out: list[tuple[str, Any]] = []
    for key, value in table.items():
        path = f"{prefix}.{key}" if prefix else str(key)
        if isinstance(value, dict) and value:
            out.extend(_flatten(value, path))
        else:
            out.append((path, value))
    return out


def canonical_hash(obj: Any) -> str:
    """SHA-256 (hex) of the canonical JSON of ``obj`` (sorted keys, no spaces).

    Examples
    --------
    >>> canonical_hash({"b": 1, "a": [1.5, "x"]}) == canonical_hash({"a": [1.5, "x"], "b": 1})
    True
    """
    text = json.dumps(obj, sort_keys=True, separators=(",", ":"), ensure_ascii=False, default=str)
    return hashlib.sha256(text.encode("utf-8")).hexdigest()


# --------------------------------------------------------------------------- the study


@dataclass(frozen=True)
class Study:
    """A validated study: base mapping, variables, plan, outputs.

    Attributes
    ----------
    name, description : str
    source : str
        Study file name (for messages).
    base_path : pathlib.Path
        Base project file.
    base : dict
        Base project mapping with ``[set]`` and ``remove`` applied.
    variables : tuple of Variable
    plan : str
        ``"grid"``, ``"latin_hypercube"`` or ``"monte_carlo"``.
    samples : int or None
    seed : int
    outputs : tuple of str
    batch_size : int or None
    simulation : dict or None
        ``{"duration": [s], "samples": int}`` when an output starts with ``simulation.``.
    feasible : str or None
        Yes/no output that marks a feasible variant (summary map).
    axes : tuple of str or None
        Two varied paths for the feasible-region map.
    """

    name: str
    description: str
    source: str
    base_path: Path
    base: dict
    variables: tuple[Variable, ...]
    plan: str
    samples: int | None
    seed: int
    outputs: tuple[str, ...]
    batch_size: int | None = None
    simulation: dict | None = None
    feasible: str | None = None
    axes: tuple[str, ...] | None = None
    _rows: list = field(default_factory=list, repr=False, compare=False)

    @property
    def parts(self) -> tuple[str, ...]:
        """Top-level parts of the analysis result the outputs need."""
        return tuple(dict.fromkeys(o.split(".", 1)[0] for o in self.outputs))

    def rows(self) -> list[tuple]:
        """Values of every variant, in each variable's unit (computed once)."""
        if not self._rows:
            self._rows.extend(plan_rows(self.plan, self.variables, samples=self.samples,
                                        seed=self.seed))
        return self._rows

    def variant_inputs(self, row: tuple) -> dict[str, Any]:
        """``{path: value as a project file writes it}`` of one plan row."""
        return {v.path: format_value(x, v.unit) for v, x in zip(self.variables, row, strict=True)}

    @cached_property
    def base_hash(self) -> str:
        """SHA-256 of the canonical JSON of the base mapping ([set] and remove applied)."""
        return canonical_hash(self.base)

    def key(self, inputs: dict[str, Any]) -> str:
        """Identity of a variant: hash of the base, its inputs, the outputs and options
        (:func:`canonical_hash` of ``{"base", "inputs", "outputs", "simulation"}``; the
        canonical text around the inputs is made once per study)."""
        before, after = self._key_text
        text = before + json.dumps(inputs, sort_keys=True, separators=(",", ":"), ensure_ascii=False,
                                   default=str) + after
        return hashlib.sha256(text.encode("utf-8")).hexdigest()

    @cached_property
    def _key_text(self) -> tuple[str, str]:
        """The canonical JSON of a variant's key with a gap where its inputs go."""
        mark = "\x00inputs\x00"
        text = json.dumps({"base": self.base_hash, "inputs": mark, "outputs": list(self.outputs),
                           "simulation": self.simulation}, sort_keys=True, separators=(",", ":"),
                          ensure_ascii=False, default=str)
        before, after = text.split(json.dumps(mark, ensure_ascii=False))
        return before, after

    def variant_mapping(self, inputs: dict[str, Any]) -> dict:
        """The base project mapping with the variant's inputs set (a copy)."""
        data = copy.deepcopy(self.base)
        for path, value in inputs.items():
            set_path(data, path, value)
        return data

    def describe(self) -> dict[str, Any]:
        """JSON-ready description (written to ``study.json`` of the output folder)."""
        return {
            "name": self.name, "description": self.description, "source": self.source,
            "base": str(self.base_path), "plan": self.plan, "samples": self.samples,
            "seed": self.seed, "variants": len(self.rows()), "outputs": list(self.outputs),
            "variables": [{"path": v.path, "unit": v.unit, "values": v.values, "low": v.low,
                           "high": v.high, "count": v.count, "scale": v.scale,
                           "distribution": v.distribution, "parameters": dict(v.parameters),
                           "integer": v.integer} for v in self.variables],
            "simulation": self.simulation, "feasible": self.feasible,
            "axes": None if self.axes is None else list(self.axes),
        }


def _check_unit(unit: str, where: str) -> None:
    if not unit:
        return
    from ..units import parse_quantity

    try:
        parse_quantity(f"1 {unit}", unit, field=where)
    except InputError as exc:
        raise InputError(f"{where}: unknown unit {unit!r} ({exc})") from None


def parse_study(text: str, *, filename: str = "<study>", folder: Path | str = ".") -> Study:
    """Validate a study text and return its :class:`Study`.

    Parameters
    ----------
    text : str
        TOML text of the study file.
    filename : str
        Name used in error messages.
    folder : path
        Folder the ``base`` path is relative to.

    Raises
    ------
    InputError
        TOML syntax, unknown or missing field, bad path, unit, plan or base project;
        the message names the field (and its line).

    Examples
    --------
    >>> import pathlib
    >>> study = parse_study('''
    ... [study]
    ... base = "roller_industrial.toml"
    ... outputs = ["loads.maximum"]
    ... [plan]
    ... kind = "grid"
    ... [[vary]]
    ... path = "drive.speed"
    ... unit = "rpm"
    ... low = 500
    ... high = 1500
    ... count = 3
    ... ''', folder=pathlib.Path(__file__).parents[3] / "examples")
    >>> [study.variant_inputs(r) for r in study.rows()][0]
    {'drive.speed': '500 rpm'}
    """
    from .._io import load_toml_text, read_text_file
    from ..drive.project import _format_errors, line_index, project_from_mapping

    data = load_toml_text(text, filename)
    index = line_index(text)
    try:
        spec = StudyFile.model_validate(data)
    except ValidationError as exc:
        raise InputError(_format_errors(exc, index, filename)) from None

    base_path = (Path(folder) / spec.study.base).resolve()
    try:
        base = load_toml_text(read_text_file(base_path, what="project file"), base_path.name)
    except InputError as exc:
        raise InputError(f"{filename}: study.base: {exc}") from None
    for path in spec.study.remove:
        try:
            remove_path(base, path)
        except InputError as exc:
            raise InputError(f"{filename}: study.remove: {exc}") from None
    for path, value in _flatten(spec.set):
        try:
            set_path(base, path, value)
        except InputError as exc:
            raise InputError(f"{filename}: set: {exc}") from None

    variables = []
    seen: set[str] = set()
    for i, v in enumerate(spec.vary):
        where = f"{filename}: vary[{i}]"
        if v.path in seen:
            raise InputError(f"{where}.path: {v.path!r} is varied twice")
        seen.add(v.path)
        _check_unit(v.unit, f"{where}.unit")
        try:
            set_path(copy.deepcopy(base), v.path, 0)
            variables.append(Variable(
                path=v.path, unit=v.unit, values=None if v.values is None else tuple(v.values),
                low=v.low, high=v.high, count=v.count, scale=v.scale,
                distribution=v.distribution, parameters=dict(v.parameters), integer=v.integer))
        except InputError as exc:
            raise InputError(f"{where}: {exc}") from None
    clash = seen & set(spec.study.outputs)
    if clash:
        raise InputError(f"{filename}: study.outputs: {sorted(clash)} also varied; an output names "
                         "a result of the analysis, not an input")

    if spec.summary.feasible is not None and spec.summary.feasible not in spec.study.outputs:
        raise InputError(f"{filename}: summary.feasible: {spec.summary.feasible!r} must be one of "
                         f"the outputs ({', '.join(spec.study.outputs)})")
    if spec.summary.axes is not None:
        bad = [a for a in spec.summary.axes if a not in seen]
        if bad or spec.summary.axes[0] == spec.summary.axes[1]:
            raise InputError(f"{filename}: summary.axes: give two different varied paths "
                             f"({', '.join(sorted(seen))}), got {spec.summary.axes}")

    simulation = None
    if any(o.startswith("simulation.") for o in spec.study.outputs):
        from ..units import parse_quantity

        sim = spec.simulation or SimulationSection()
        duration = parse_quantity(sim.duration, "s", field="simulation.duration")
        if not 0 < duration <= MAXIMUM_SIMULATION_DURATION:
            raise InputError(f"{filename}: simulation.duration must lie in "
                             f"(0, {MAXIMUM_SIMULATION_DURATION:g}] s, got {duration:g} s")
        simulation = {"duration": duration, "samples": sim.samples}

    study = Study(
        name=spec.study.name, description=spec.study.description, source=filename,
        base_path=base_path, base=base, variables=tuple(variables), plan=spec.plan.kind,
        samples=spec.plan.samples, seed=spec.plan.seed, outputs=tuple(spec.study.outputs),
        batch_size=spec.study.batch_size, simulation=simulation,
        feasible=spec.summary.feasible,
        axes=None if spec.summary.axes is None else tuple(spec.summary.axes),
    )
    try:
        rows = study.rows()
    except InputError as exc:
        raise InputError(f"{filename}: {exc}") from None
    if not rows:
        raise InputError(f"{filename}: the plan has no variants")
    # the first variant must be a valid project: a typo in the base would fail them all
    first = study.variant_inputs(rows[0])
    try:
        project_from_mapping(study.variant_mapping(first), filename=base_path.name)
    except InputError as exc:
        raise InputError(f"{filename}: the first variant {first} is not a valid project: {exc}") from None
    return study


def load_study(path: str | Path) -> Study:
    """Read a study file (``base`` relative to its folder) and return its :class:`Study`.

    Raises
    ------
    InputError
        File missing or invalid (field and line named).

    Examples
    --------
    >>> import pathlib
    >>> s = load_study(pathlib.Path(__file__).parents[3] / "examples" / "skew_study.toml")
    >>> s.plan, len(s.rows())
    ('monte_carlo', 400)
    """
    from .._io import read_text_file

    p = Path(path)
    text = read_text_file(p, what="study file")
    return parse_study(text, filename=p.name, folder=p.parent)
