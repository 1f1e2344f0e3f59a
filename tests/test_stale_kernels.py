"""scripts/stale_kernels.py: the cached kernels of every module that imports a changed file of
app/geometry are removed before the warm-up, the others kept (numba itself checks only the
kernel's own file: a kernel that inlines ``compiled.hypot`` or calls ``construction._sticks``
would keep the old machine code)."""

from __future__ import annotations

import importlib.util
import subprocess
import sys
from pathlib import Path
from types import ModuleType

ROOT = Path(__file__).resolve().parents[1]
GEOMETRY = ROOT / "app" / "geometry"


def _script() -> ModuleType:
    spec = importlib.util.spec_from_file_location(
        "stale_kernels", ROOT / "scripts" / "stale_kernels.py"
    )
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


stale_kernels = _script()


def test_a_module_that_calls_a_changed_kernel_is_stale() -> None:
    changed = {GEOMETRY / "d4b/construction.py"}
    stale = stale_kernels.dependents(changed)
    # d4b_construction calls construction._sticks; D1's construction imports nothing of D4b
    assert GEOMETRY / "companion_kernels.py" in stale
    assert GEOMETRY / "d1/construction.py" not in stale
    assert GEOMETRY / "d4b/construction.py" not in stale  # numba sees its own file change


def test_the_inline_helpers_module_makes_every_construction_stale() -> None:
    stale = stale_kernels.dependents({GEOMETRY / "compiled.py"})
    recursions = (
        "d1/construction.py",
        "d3/construction.py",
        "d4a/construction.py",
        "d4b/construction.py",
    )
    for recursion in recursions:
        assert GEOMETRY / recursion in stale


def test_only_the_dependents_entries_are_removed(tmp_path: Path) -> None:
    def entries(path: Path) -> list[Path]:
        directory = tmp_path / stale_kernels._CacheLocator.get_suitable_cache_subpath(str(path))
        directory.mkdir(parents=True, exist_ok=True)
        files = [
            directory / f"{path.stem}.kernel-10.py311.nbi",
            directory / f"{path.stem}.kernel-10.py311.1.nbc",
        ]
        for file in files:
            file.write_bytes(b"")
        return files

    companion = entries(GEOMETRY / "companion_kernels.py")
    d1 = entries(GEOMETRY / "d1/construction.py")
    script = ROOT / "scripts" / "stale_kernels.py"
    done = subprocess.run(
        [sys.executable, str(script), "app/geometry/d4b/construction.py", "Makefile"],
        cwd=ROOT,
        env={"NUMBA_CACHE_DIR": str(tmp_path), "PATH": "/usr/bin:/bin"},
        capture_output=True,
        text=True,
        check=True,
    )
    assert not any(file.exists() for file in companion)
    assert all(file.exists() for file in d1)
    assert done.stdout == "stale kernels: app/geometry/companion_kernels.py (2 cache files)\n"
