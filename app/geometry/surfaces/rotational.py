"""A discrete surface of revolution with its Gauss image: meshes (15), per-face K, H, checks.

Given a meridian polygon and a parallel Gauss image meridian (both ``(n, 2)``), this builds the
two rotational meshes of ``surfaces``, computes on *every* face the mixed-area curvatures of
``curvature`` and the planarity of both meshes, and checks:

- ``face-planarity``: every face of both meshes is planar (the paper's meshes are polyhedral);
- ``face-parallelity``: corresponding faces are parallel (what the curvature theory requires);
- ``equation-17``: the per-face K and H equal (17) from the radii (0/0 faces skipped);
- the surface's own claim: K constant (Theorem 7) or H = 0 (Theorem 8, (D2b), any catenoid).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Literal

import numpy as np

from app.geometry.catalog.section5 import (
    D4B_THEOREM_7 as THEOREM_7,
    RING_EQUATION_17 as EQUATION_17_FACES,
    SURFACE_MINIMAL as MINIMAL,
    SURFACE_PARALLELITY as PARALLELITY,
    SURFACE_PLANARITY as PLANARITY,
)
from app.geometry.checks import Check, Statement, check_residuals, not_applicable
from app.geometry.curvature import FaceCurvatures, face_curvatures, planarity
from app.geometry.precision import Arithmetic, Array
from app.geometry.surfaces.mesh import MeshLayout, face_vertices, layout, revolve
from app.geometry.surfaces.revolution_formulas import face_residuals
from app.geometry.tolerances import LOCAL_STEPS

Claim = Literal["minimal", "constant-curvature"]

#: What ``build`` checks the meshes of a rotational surface for, by the claim it is built with.
STATEMENTS: dict[str, tuple[Statement, ...]] = {
    "minimal": (PLANARITY, PARALLELITY, EQUATION_17_FACES, MINIMAL),
    "constant-curvature": (PLANARITY, PARALLELITY, EQUATION_17_FACES, THEOREM_7),
}


@dataclass(frozen=True)
class RotationalSurface:
    """Both meshes and everything computed on their faces."""

    arithmetic: Arithmetic
    layout: MeshLayout
    surface: Array
    """``(rows·columns, 3)`` vertices of the surface."""
    gauss_image: Array
    """``(rows·columns, 3)`` vertices of the Gauss image (same layout)."""
    curvature: FaceCurvatures
    surface_planarity: Array
    gauss_planarity: Array
    checks: list[Check]


def build(
    ar: Arithmetic,
    meridian: Array,
    gauss: Array,
    m: int,
    steps: int,
    claim: Claim,
    K: Any = None,
    tolerance: float | None = None,
) -> RotationalSurface:
    """Meshes (15) of a meridian and its Gauss image, per-face K, H, planarity, and checks.

    ``claim`` is the surface's statement: H = 0 (``minimal``) or K = ``K`` on every face
    (``constant-curvature``). ``tolerance`` defaults to the local one; callers whose meridians
    come from long recursions pass a larger one (``Arithmetic.tolerance(steps)``).
    """
    mesh = layout(len(meridian), m, steps)
    surface = revolve(ar, meridian, mesh)
    image = revolve(ar, gauss, mesh)
    f = face_vertices(surface, mesh)
    g = face_vertices(image, mesh)
    curvature = face_curvatures(ar, f, g)
    flat_f, flat_g = planarity(ar, f), planarity(ar, g)
    tol = tolerance if tolerance is not None else ar.tolerance(LOCAL_STEPS)
    face_numbers = np.arange(len(mesh.faces), dtype=np.int64)

    def check(statement: Statement, residuals: Array, note: str | None = None) -> Check:
        return check_residuals(statement, ar, face_numbers, residuals, tol, False, note=note)

    row = np.repeat(np.arange(len(meridian) - 1), mesh.steps)  # meridian edge of each face
    p_y, n_y = meridian[:, 1], gauss[:, 1]
    k17, h17, defined = face_residuals(
        ar, p_y[:-1][row], p_y[1:][row], n_y[:-1][row], n_y[1:][row], curvature
    )
    eq17 = np.where(defined, np.maximum(ar.to_floats(k17), ar.to_floats(h17)), 0.0)
    skipped = int(np.count_nonzero(~defined))
    eq17_check = (
        not_applicable(EQUATION_17_FACES, tol, "(17) is 0/0 on every face")
        if skipped == len(eq17)
        else check(
            EQUATION_17_FACES,
            eq17,
            f"(17) is 0/0 on {skipped} face(s) (meridian edges parallel to the axis); the "
            "mixed-area values are reported there"
            if skipped
            else None,
        )
    )
    checks = [
        check(PLANARITY, np.maximum(ar.to_floats(flat_f), ar.to_floats(flat_g))),
        check(PARALLELITY, curvature.parallel),
        eq17_check,
    ]
    if claim == "minimal":
        checks.append(check(MINIMAL, abs(curvature.mixed_area) / curvature.mixed_area_magnitude))
    else:
        scale = curvature.gauss_area_magnitude + abs(K) * curvature.area_magnitude
        checks.append(check(THEOREM_7, abs(curvature.gauss_area - K * curvature.area) / scale))
    return RotationalSurface(ar, mesh, surface, image, curvature, flat_f, flat_g, checks)
