"""Drop the cached kernels that a change to app/geometry has made stale.

    python scripts/stale_kernels.py FILE ...   (the Makefile's warm-up passes the changed files)

numba checks the freshness of a cached kernel against one file only: the source file of the
function it compiled. A kernel that calls a function of another module (``compiled.hypot``,
``construction._sticks``) or reads another module's constant (a tolerance, a block size) has that
code and those values compiled into its own machine code, so when only the other module changes,
numba loads the old machine code. On a machine that keeps ``.numba-cache`` across a ``git pull``,
such a kernel would go on computing what the previous commit computed.

Given the changed files, this script removes the cache entries of every module of app/geometry
that imports one of them, directly or through other modules of app/geometry (its own entries
numba finds stale by itself). ``python -m app.geometry.warm`` then compiles those kernels again.
It prints what it removed.
"""

from __future__ import annotations

import ast
import os
import sys
from pathlib import Path

from numba.core.caching import _CacheLocator

ROOT = Path(__file__).resolve().parents[1]
GEOMETRY = ROOT / "app" / "geometry"


def module_file(name: str) -> Path | None:
    """The file of module ``name`` of app.geometry (a package's ``__init__.py``), if any."""
    base = ROOT.joinpath(*name.split("."))
    for candidate in (base.with_suffix(".py"), base / "__init__.py"):
        if candidate.is_file() and GEOMETRY in candidate.parents:
            return candidate
    return None


def imports(path: Path) -> set[Path]:
    """The files of app/geometry that ``path`` imports (``from app.geometry.x import y`` names
    module x, and y too when y is a module)."""
    found: set[Path] = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        names: list[str] = []
        if isinstance(node, ast.Import):
            names = [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            names = [node.module] + [f"{node.module}.{alias.name}" for alias in node.names]
        for name in names:
            if name.startswith("app.geometry") and (file := module_file(name)) is not None:
                found.add(file)
    found.discard(path)
    return found


def dependents(changed: set[Path]) -> set[Path]:
    """Every file of app/geometry that imports a changed file, directly or not."""
    graph = {path: imports(path) for path in GEOMETRY.rglob("*.py")}
    stale: set[Path] = set()
    grew = True
    while grew:
        grew = False
        for path, uses in graph.items():
            if path not in stale and uses & (changed | stale):
                stale.add(path)
                grew = True
    return stale


def cache_entries(path: Path, cache: Path) -> list[Path]:
    """The index and data files numba keeps in ``cache`` for the kernels of ``path``."""
    subpath = _CacheLocator.get_suitable_cache_subpath(str(path))  # type: ignore[no-untyped-call]
    directory = cache / subpath
    if not directory.is_dir():
        return []
    return sorted(directory.glob(f"{path.stem}.*.nb[ic]"))


def main(arguments: list[str]) -> None:
    cache = Path(os.environ.get("NUMBA_CACHE_DIR", ROOT / ".numba-cache"))
    changed = {
        Path(a).resolve() for a in arguments if a.endswith(".py") and Path(a).resolve().is_file()
    }
    changed = {path for path in changed if GEOMETRY in path.parents}
    for path in sorted(dependents(changed)):
        entries = cache_entries(path, cache)
        for entry in entries:
            entry.unlink()
        if entries:
            print(f"stale kernels: {path.relative_to(ROOT)} ({len(entries)} cache files)")


if __name__ == "__main__":
    main(sys.argv[1:])
