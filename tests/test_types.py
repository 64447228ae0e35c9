"""Every public function and method of chaindrive carries type hints (``make lint`` runs mypy).

A function is public when its name does not start with ``_`` (at module level or in a
class); it is typed when every parameter but ``self``/``cls`` and its return value are
annotated. The numba kernels are typed by numba (their arguments are arrays whose
dtypes numba infers) and are left out, as in the mypy configuration of pyproject.toml.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

import chaindrive

ROOT = Path(chaindrive.__file__).parent
#: Modules compiled by numba (``@njit``): typed by numba, not by annotations.
NUMBA_KERNELS = {"simulation/_kernel.py", "simulation/_statics.py", "simulation/_implicit.py",
                 "simulation/_batched.py", "simulation/_contact.py",
                 "simulation/_batched_implicit.py", "simulation/_lane_contacts.py",
                 "simulation/_lane_passes.py", "simulation/_lane_span.py"}


def _public_functions(tree: ast.Module) -> list[tuple[str, ast.FunctionDef | ast.AsyncFunctionDef, bool]]:
    """(qualified name, node, is_method) of the public functions of a module."""
    out = []

    def visit(body: list[ast.stmt], owner: str | None) -> None:
        for node in body:
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                if not node.name.startswith("_"):
                    out.append((f"{owner}.{node.name}" if owner else node.name, node, owner is not None))
            elif isinstance(node, ast.ClassDef) and owner is None:
                visit(node.body, node.name)
            elif isinstance(node, (ast.If, ast.Try)):
                visit(node.body, owner)

    visit(tree.body, None)
    return out


def _untyped(node: ast.FunctionDef | ast.AsyncFunctionDef, is_method: bool) -> list[str]:
    """Names of the parameters (and ``return``) of ``node`` without an annotation."""
    args = node.args
    params = args.posonlyargs + args.args + args.kwonlyargs
    static = any(isinstance(d, ast.Name) and d.id == "staticmethod" for d in node.decorator_list)
    if is_method and params and not static and params[0].arg in ("self", "cls"):
        params = params[1:]
    params += [a for a in (args.vararg, args.kwarg) if a is not None]
    missing = [p.arg for p in params if p.annotation is None]
    if node.returns is None:
        missing.append("return")
    return missing


def _scan() -> tuple[int, list[str]]:
    total, untyped = 0, []
    for path in sorted(ROOT.rglob("*.py")):
        rel = path.relative_to(ROOT).as_posix()
        if rel in NUMBA_KERNELS:
            continue
        for name, node, is_method in _public_functions(ast.parse(path.read_text(encoding="utf-8"))):
            total += 1
            missing = _untyped(node, is_method)
            if missing:
                untyped.append(f"{rel}:{node.lineno} {name} (no annotation: {', '.join(missing)})")
    return total, untyped


def test_every_public_function_is_typed():
    total, untyped = _scan()
    assert total > 500  # the scan found the package
    assert not untyped, "public functions without type hints:\n" + "\n".join(untyped)


def test_scan_sees_missing_annotations():
    # the checker itself: an unannotated parameter, a missing return and a method's self
    tree = ast.parse(
        "def f(a, b: int) -> int: ...\n"
        "def g(a: int): ...\n"
        "class C:\n"
        "    def m(self, x: int) -> None: ...\n"
        "    def _hidden(self, y): ...\n"
        "def _private(z): ...\n"
    )
    found = {name: _untyped(node, is_method) for name, node, is_method in _public_functions(tree)}
    assert found == {"f": ["a"], "g": ["return"], "C.m": []}


@pytest.mark.parametrize("kernel", sorted(NUMBA_KERNELS))
def test_numba_kernels_exist(kernel):
    # the exemption names real files (a renamed kernel must be typed or exempted again)
    assert (ROOT / kernel).is_file()
