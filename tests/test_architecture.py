"""The core imports numpy, mpmath, numba, python-flint and the standard library only (pure core)."""

from __future__ import annotations

import ast
import sys
from pathlib import Path

CORE = Path(__file__).resolve().parents[1] / "app" / "geometry"
ALLOWED = {"numpy", "mpmath", "numba", "flint", "app"}


def imported_modules(path: Path) -> set[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    names: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            names.add(node.module)
    return names


def test_core_imports_only_numpy_mpmath_and_the_standard_library() -> None:
    files = sorted(CORE.rglob("*.py"))
    assert files
    for path in files:
        for name in imported_modules(path):
            top = name.split(".")[0]
            if top == "app":
                assert name.startswith("app.geometry"), f"{path.name} imports {name}"
            else:
                assert top in ALLOWED or top in sys.stdlib_module_names, f"{path.name}: {name}"


IO_MODULES = {
    "os",
    "io",
    "pathlib",
    "logging",
    "sys",
    "socket",
    "subprocess",
    "shutil",
    "tempfile",
    "urllib",
    "http",
    "json",
    "pickle",
}
IO_CALLS = {"open", "print", "input", "eval", "exec"}


def test_core_does_no_io_and_evaluates_nothing() -> None:
    for path in CORE.rglob("*.py"):
        assert not {m.split(".")[0] for m in imported_modules(path)} & IO_MODULES, path.name
        tree = ast.parse(path.read_text(encoding="utf-8"))
        calls = {
            node.func.id
            for node in ast.walk(tree)
            if isinstance(node, ast.Call) and isinstance(node.func, ast.Name)
        }
        assert not calls & IO_CALLS, f"{path.name} calls {calls & IO_CALLS}"


APP = CORE.parent
NEVER = {"eval", "exec", "compile", "__import__"}


def test_nothing_from_a_request_is_evaluated_or_written() -> None:
    """No module of the service evaluates code or starts processes; only the OpenAPI export
    (a command-line tool, not a route) writes a file, and only the launcher (app/server.py,
    which the app never imports) starts the worker processes."""
    for path in APP.rglob("*.py"):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        calls = [node.func for node in ast.walk(tree) if isinstance(node, ast.Call)]
        builtins = {f.id for f in calls if isinstance(f, ast.Name)}  # eval(...), not re.compile
        methods = {f.attr for f in calls if isinstance(f, ast.Attribute)}
        assert not builtins & NEVER, f"{path.name} calls {builtins & NEVER}"
        if path.name != "server.py":
            assert "subprocess" not in {m.split(".")[0] for m in imported_modules(path)}, path.name
        writes = methods & {"write_text", "write_bytes"}
        assert not writes or path.name == "openapi_export.py", f"{path.name} writes files"


APP = CORE.parent
WEB_MODULES = {"main.py", "errors.py"}
"""Besides the routers, only these import FastAPI (the app factory and the error handlers)."""
HTTP_PLUMBING = {
    "admission.py",
    "bounded_io.py",
    "compression.py",
    "fast_lane.py",
    "negotiation.py",
    "problem_types.py",
    "response_cache.py",
    "security.py",
}
"""ASGI middlewares: they speak HTTP through Starlette's types, never FastAPI's."""


def test_only_routers_main_and_errors_import_fastapi() -> None:
    for path in sorted(APP.rglob("*.py")):
        relative = path.relative_to(APP)
        tops = {name.split(".")[0] for name in imported_modules(path)}
        if relative.parts[0] == "routers" or relative.name in WEB_MODULES:
            continue
        assert "fastapi" not in tops, f"{relative} imports fastapi"
        if relative.parts[0] in ("geometry", "services", "rendering", "schemas"):
            assert "starlette" not in tops, f"{relative} imports starlette"
        elif "starlette" in tops:
            assert relative.name in HTTP_PLUMBING, f"{relative} imports starlette"
