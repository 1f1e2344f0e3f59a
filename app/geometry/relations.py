"""Section 4 as a matrix: which discretization satisfies which property.

Rows are computed curves (any discretization), columns are the properties of the paper's
Sections 3-5 that a polygon of the plane can have: (D1), (D3), eq. (2), eq. (7), vanishing mean
curvature H and constant Gaussian curvature K of the surface of revolution. Each cell fits the
property's constant(s) on the curve's polygon (``conditions``), reports the residual and the
verdict, with the curve's own local tolerance (``Curve.local_tolerance``).

H and K need a Gauss image and the discrete curvatures (17) of Section 5; until a curvature
module exists their cells are "not applicable" with a note. Adding them means writing one
``Property`` whose ``evaluate`` reads the curve's Gauss image companion and computes (17).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from app.geometry import conditions
from app.geometry.curve import Curve
from app.geometry.precision import Arithmetic, Array, Scalar

#: Local conditions combine a handful of neighbouring values (as in the discretizations' checks).
LOCAL_STEPS = 16


@dataclass(frozen=True)
class Cell:
    """One property tested on one polygon."""

    property: str
    residual: float | None
    tolerance: float
    holds: bool | None
    """``None``: not applicable (too few vertices, or no way to evaluate it yet)."""
    constants: dict[str, Scalar] = field(default_factory=dict)
    note: str | None = None


@dataclass(frozen=True)
class Property:
    """A column of the matrix: a property and how to test it on a computed curve."""

    id: str
    title: str
    reference: str
    claim: str
    evaluate: Callable[[Curve], Cell]


def tolerance_of(curve: Curve) -> float:
    """The tolerance of a local condition on this curve's polygon."""
    if curve.local_tolerance is not None:
        return curve.local_tolerance
    return curve.arithmetic.tolerance(LOCAL_STEPS)


def _residual(ar: Arithmetic, residuals: Array) -> float | None:
    """The largest residual; a residual that is not a number counts as the largest float."""
    values = ar.to_floats(residuals)
    if not len(values):
        return None
    values = np.where(np.isfinite(values), values, np.finfo(np.float64).max)
    return float(np.max(values))


def _one_constant(
    property_id: str, fit: Callable[[Arithmetic, Array], conditions.ConditionFit], needs: int
) -> Callable[[Curve], Cell]:
    """A cell for lhs_i = c·rhs_i with one constant c > 0 ((D1), (D3), (2))."""

    def evaluate(curve: Curve) -> Cell:
        ar, p = curve.arithmetic, curve.polygon.vertices
        tolerance = tolerance_of(curve)
        if len(p) < needs:
            return Cell(property_id, None, tolerance, None, note=f"needs {needs} vertices")
        result = fit(ar, p)
        residual = _residual(ar, result.residuals)
        if result.constant is None or residual is None:
            return Cell(property_id, residual, tolerance, False, note="no constant fits")
        constants = {"c": result.constant}
        if residual > tolerance:
            return Cell(property_id, residual, tolerance, False, constants)
        if not result.constant > 0:
            return Cell(
                property_id, residual, tolerance, False, constants, "the fitted c is not > 0"
            )
        return Cell(property_id, residual, tolerance, True, constants)

    return evaluate


def _equation_7(curve: Curve) -> Cell:
    """Eq. (7) with two constants c_1, c_2 (any signs: Theorem 2 only says they exist)."""
    ar, p = curve.arithmetic, curve.polygon.vertices
    tolerance = tolerance_of(curve)
    if len(p) < 4:
        return Cell("equation-7", None, tolerance, None, note="needs 4 vertices")
    result = conditions.equation_7(ar, p, int(curve.polygon.indices[0]))
    residual = _residual(ar, result.residuals)
    if result.constants is None or residual is None:
        return Cell("equation-7", residual, tolerance, False, note="c_1, c_2 are not determined")
    c1, c2 = result.constants
    return Cell("equation-7", residual, tolerance, residual <= tolerance, {"c1": c1, "c2": c2})


CURVATURE_NOTE = (
    "not evaluated yet: needs the discrete curvatures (17) of Section 5 and a Gauss image for "
    "this discretization (curvature module not merged); the column is part of the matrix design"
)


def _not_yet(property_id: str) -> Callable[[Curve], Cell]:
    def evaluate(curve: Curve) -> Cell:
        return Cell(property_id, None, tolerance_of(curve), None, note=CURVATURE_NOTE)

    return evaluate


PROPERTIES: tuple[Property, ...] = (
    Property(
        "d1",
        "(D1)",
        "Section 3, (D1)",
        "Δ²p_i^y = c (l_i + l_{i+1}) with one constant c > 0 (least-squares c). Residual: "
        "largest |Δ²p_i^y − c(l_i + l_{i+1})| relative to the magnitude of the numbers it is "
        "computed from (docs/checks.md).",
        _one_constant("d1", conditions.d1, 3),
    ),
    Property(
        "d3",
        "(D3)",
        "Section 3, (D3)",
        "A_i = c l_i with one constant c > 0 (least-squares c). Residual: largest |A_i − c l_i| "
        "relative to the magnitude of the coordinates.",
        _one_constant("d3", conditions.d3, 2),
    ),
    Property(
        "equation-2",
        "eq. (2)",
        "Section 4.1, eq. (2)",
        "Δ²p_i^y = c (A_i + A_{i+1}) with one constant c > 0 (least-squares c). Residual: as for "
        "(D1).",
        _one_constant("equation-2", conditions.equation_2, 3),
    ),
    Property(
        "equation-7",
        "eq. (7)",
        "Section 4.1, Theorem 2, eq. (7)",
        "Δ²p_i^y = c_1 A_i + c_2 A_{i+1} (i even), c_2 A_i + c_1 A_{i+1} (i odd) with constants "
        "c_1, c_2 of any sign (least squares; the paper's indices decide the parity). Residual: "
        "largest misfit relative to the magnitude of the numbers it is computed from.",
        _equation_7,
    ),
    Property(
        "mean-curvature-zero",
        "H = 0",
        "Section 5, eq. (17); (D2b)",
        "The surface of revolution of p has vanishing discrete mean curvature H of (17) with "
        "respect to a Gauss image of the discretization.",
        _not_yet("mean-curvature-zero"),
    ),
    Property(
        "gaussian-curvature-constant",
        "K constant",
        "Section 5, eq. (17), Theorem 7",
        "The discrete Gaussian curvature K of (17) is the same for every face (for the "
        "discretization's own pair of meridian and Gauss image).",
        _not_yet("gaussian-curvature-constant"),
    ),
)


def row(curve: Curve) -> list[Cell]:
    """Every property tested on one computed curve, in the order of ``PROPERTIES``."""
    return [prop.evaluate(curve) for prop in PROPERTIES]
