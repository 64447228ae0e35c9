"""The package's layers, read from its source (AST): every import between the package's
own modules, those written inside functions included (a lazy import is still a
dependency); only imports under ``if TYPE_CHECKING:`` (annotations) are not counted.

* no import circle between modules;
* no upward import: each module belongs to a layer (the longest matching prefix of
  :data:`LAYERS`, every module of the package has one) and imports only from its own
  layer or below;
* no source module over 800 lines (the numba kernel aside);
* rpm <-> rad/s is converted only in :mod:`chaindrive.units`.

A deprecated alias that forwards a moved name (``chaindrive._deprecation``,
``importlib.import_module`` by name) and the presenter registry (``chaindrive._presenters``:
results ask for their views by kind) are no imports: the lower module names no module
above it in code.
"""

from __future__ import annotations

import ast
import functools
import re
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parents[1] / "src"
PACKAGE = SRC / "chaindrive"

#: The layers, lowest first; a module belongs to the layer of its longest matching prefix.
LAYERS: tuple[tuple[str, tuple[str, ...]], ...] = (
    ("foundation", ("chaindrive.errors", "chaindrive._typing", "chaindrive._deprecation", "chaindrive._roots",
                    "chaindrive._registry", "chaindrive._presenters", "chaindrive._examples", "chaindrive.units",
                    "chaindrive.limits", "chaindrive._validation", "chaindrive._finite", "chaindrive._results",
                    "chaindrive._io", "chaindrive._folders", "chaindrive.display", "chaindrive._interrupt",
                    "chaindrive._docs")),
    ("formulas", ("chaindrive.kinematics", "chaindrive.vibration", "chaindrive.strength", "chaindrive.geometry",
                  "chaindrive.layout", "chaindrive.loads", "chaindrive.selection", "chaindrive.wear",
                  "chaindrive.chains", "chaindrive.self_regulating", "chaindrive.rating", "chaindrive.motor",
                  "chaindrive.coupling", "chaindrive.conveyor", "chaindrive.life", "chaindrive.static_safety",
                  "chaindrive.drivetrain")),
    ("description", ("chaindrive.drive",)),
    ("analysis", ("chaindrive.analysis",)),
    ("simulation", ("chaindrive.simulation",)),
    ("design", ("chaindrive.design",)),
    ("plots", ("chaindrive.plotting", "chaindrive.cad")),
    ("workflows", ("chaindrive.workflows",)),
    ("studies", ("chaindrive.study",)),
    ("web", ("chaindrive.web",)),
    ("command line", ("chaindrive.cli",)),
    ("package face", ("chaindrive",)),
)

#: Circles still to be taken apart (a ratchet: a new circle fails, and so does an entry
#: here that no longer exists; the list only shrinks).
KNOWN_CIRCLES: list[list[str]] = []

MAX_LINES = 800
#: Modules allowed over MAX_LINES: the numba kernel (one jitted unit) only.
OVERSIZE_ALLOWED = {
    "chaindrive.simulation._kernel",  # one jitted unit (689 lines today: under the limit too)
}


def _module_name(path: Path) -> str:
    rel = path.relative_to(SRC).with_suffix("")
    parts = list(rel.parts)
    if parts[-1] == "__init__":
        parts = parts[:-1]
    return ".".join(parts)


MODULES = {_module_name(p): p for p in sorted(PACKAGE.rglob("*.py"))}


def _is_type_checking(node: ast.If) -> bool:
    test = node.test
    return (isinstance(test, ast.Name) and test.id == "TYPE_CHECKING") or (
        isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING")


def _imports(tree: ast.Module) -> list[ast.Import | ast.ImportFrom]:
    """Every import statement, at any depth, but those under ``if TYPE_CHECKING:``."""
    out: list[ast.Import | ast.ImportFrom] = []

    def visit(node: ast.AST) -> None:
        for child in ast.iter_child_nodes(node):
            if isinstance(child, (ast.Import, ast.ImportFrom)):
                out.append(child)
            elif isinstance(child, ast.If) and _is_type_checking(child):
                for other in child.orelse:
                    visit(other)
            else:
                visit(child)

    visit(tree)
    return out


def _resolve(module: str, node: ast.ImportFrom) -> str:
    is_package = MODULES[module].name == "__init__.py"
    base = module.split(".") if is_package else module.split(".")[:-1]
    if node.level:
        base = base[: len(base) - (node.level - 1)]
        return ".".join(base + ([node.module] if node.module else []))
    return node.module or ""


def _edges(module: str) -> set[str]:
    """The chaindrive modules ``module`` imports, anywhere in its code."""
    tree = ast.parse(MODULES[module].read_text(encoding="utf-8"))
    out: set[str] = set()
    for node in _imports(tree):
        if isinstance(node, ast.Import):
            targets = [a.name for a in node.names]
        else:
            target = _resolve(module, node)
            targets = [f"{target}.{a.name}" if f"{target}.{a.name}" in MODULES else target for a in node.names]
        for t in targets:
            while t and t not in MODULES:
                t = t.rpartition(".")[0]
            # importing a submodule imports its packages: that is no edge back to them
            if t.startswith("chaindrive") and t != module and not module.startswith(t + "."):
                out.add(t)
    return out


@functools.cache
def graph() -> dict[str, set[str]]:
    """Every chaindrive module's imports (parsed when a test first asks, not at collection)."""
    return {m: _edges(m) for m in MODULES}


def _layer(module: str) -> int | None:
    best: tuple[int, int] | None = None
    for level, (_, prefixes) in enumerate(LAYERS):
        for prefix in prefixes:
            if (module == prefix or module.startswith(prefix + ".")) and (best is None or len(prefix) > best[1]):
                best = (level, len(prefix))
    return None if best is None else best[0]


def test_the_graph_was_read() -> None:
    assert len(MODULES) > 100 and graph()["chaindrive.analysis.layout"]


def test_no_import_circle() -> None:
    """Tarjan's strongly connected components of the module-level import graph."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on: set[str] = set()
    circles: list[list[str]] = []
    counter = [0]

    def strong(v: str) -> None:
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in graph()[v]:
            if w not in index:
                strong(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                circles.append(sorted(comp))

    import sys

    sys.setrecursionlimit(max(sys.getrecursionlimit(), 5000))
    for v in graph():
        if v not in index:
            strong(v)
    new = [c for c in circles if c not in KNOWN_CIRCLES]
    assert not new, f"import circles: {new}"
    gone = [c for c in KNOWN_CIRCLES if c not in circles]
    assert not gone, f"no longer circles, remove from KNOWN_CIRCLES: {gone}"


def test_every_module_has_a_layer() -> None:
    assert not [m for m in MODULES if _layer(m) is None]


def test_imports_inside_functions_are_counted() -> None:
    """A lazy import is an edge: chaindrive.analysis.conveyor imports the conveyor formulas
    (module level) and the sag solver inside a function."""
    tree = ast.parse("def f():\n    from .x import y\nif TYPE_CHECKING:\n    from .z import w\n")
    assert [n.module for n in _imports(tree)] == ["x"]


def test_no_upward_import() -> None:
    bad = []
    for module, targets in graph().items():
        here = _layer(module)
        for t in targets:
            there = _layer(t)
            if here is not None and there is not None and there > here:
                bad.append(f"{module} ({LAYERS[here][0]}) -> {t} ({LAYERS[there][0]})")
    assert not bad, "upward imports:\n" + "\n".join(sorted(bad))


@pytest.mark.parametrize("module", sorted(MODULES))
def test_module_size(module: str) -> None:
    lines = MODULES[module].read_text(encoding="utf-8").count("\n")
    if module in OVERSIZE_ALLOWED and lines > MAX_LINES:
        pytest.skip(f"{module}: {lines} lines, allowed (one jitted unit)")
    assert lines <= MAX_LINES, f"{module} has {lines} lines (> {MAX_LINES}): split it by topic"


_RPM = re.compile(r"\bRPM\b\s*=|\b(?:30|60)(?:\.0)?\s*/\s*\(?\s*(?:2(?:\.0)?\s*\*\s*)?(?:np|math)\.pi"
                  r"|(?:np|math)\.pi\s*/\s*(?:30|60)\b|2(?:\.0)?\s*\*\s*(?:np|math)\.pi\s*/\s*60\b|/ \(2 \* 3\.14159")


def _code_without_docstrings(path: Path) -> str:
    """The source with docstrings blanked (doctests may show a conversion: they are examples)."""
    text = path.read_text(encoding="utf-8")
    lines = text.splitlines()
    for node in ast.walk(ast.parse(text)):
        body = getattr(node, "body", None)
        if isinstance(body, list) and body and isinstance(body[0], ast.Expr) and isinstance(
                getattr(body[0], "value", None), ast.Constant) and isinstance(body[0].value.value, str):
            d = body[0]
            for i in range(d.lineno - 1, (d.end_lineno or d.lineno)):
                lines[i] = ""
    return "\n".join(lines)


def test_rpm_conversion_only_in_units() -> None:
    found = []
    for module, path in MODULES.items():
        if module == "chaindrive.units":
            continue
        for i, line in enumerate(_code_without_docstrings(path).splitlines(), 1):
            if _RPM.search(line.split("#", 1)[0]):
                found.append(f"{module}:{i}: {line.strip()}")
    assert not found, "rpm <-> rad/s outside chaindrive.units:\n" + "\n".join(found)


def test_the_rpm_pattern_finds_the_old_spellings() -> None:
    for text in ("RPM = 2.0 * math.pi / 60.0", "x * 60 / (2 * np.pi)", "w * 30 / np.pi", "n * np.pi / 30",
                 "_RPM = 60.0 / (2.0 * np.pi)"):
        assert _RPM.search(text), text
