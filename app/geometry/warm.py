"""Compile every float64 kernel into numba's cache: ``python -m app.geometry.warm``.

``make run``, ``make test`` and the service image run it once after installing, so that no
process compiles a kernel later: the service loads them from the cache when it imports the
geometry (app/geometry/compiled.py), before its first request. Importing the modules is enough,
since every kernel is declared with its signature; ``warm`` returns their names.
"""

from __future__ import annotations

import importlib

from app.geometry.compiled import KERNELS

#: The modules that declare kernels.
MODULES = (
    "app.geometry.arb_program",
    "app.geometry.companion_kernels",
    "app.geometry.conditions",
    "app.geometry.d1.construction",
    "app.geometry.d3.construction",
    "app.geometry.d4a.construction",
    "app.geometry.d4b.arb_checks",
    "app.geometry.d4b.closed_forms",
    "app.geometry.d4b.construction",
    "app.geometry.d4b.fused_checks",
    "app.geometry.d4b.residual_kernels",
    "app.geometry.darboux",
    "app.geometry.elementary",
    "app.geometry.surfaces.equation_17_kernel",
    "app.geometry.surfaces.ring_kernel",
)


def warm() -> list[str]:
    """Import every module with kernels (compiling what the cache lacks); their names."""
    for module in MODULES:
        importlib.import_module(module)
    return sorted(KERNELS)


if __name__ == "__main__":
    warm()
