"""Section 4 as a matrix: which discretization satisfies which property.

Rows are computed curves (any discretization), columns are the properties of the paper's
Sections 3-5 that a polygon of the plane can have: (D1), (D3), eq. (2), eq. (7), vanishing mean
curvature H and constant Gaussian curvature K of the surface of revolution. Each cell fits the
property's constant(s) on the curve's polygon (``conditions``), reports the residual and the
verdict, with the curve's own local tolerance (``Curve.local_tolerance``).

H = 0 and K constant are tested on surfaces of revolution (15) with the mixed-area curvatures
of [3] (``curvature``, on one ring of three-dimensional faces, ``curvature_checks``), never with
(17). Which surface and which Gauss image (``surface_pair``):

- H = 0: the row's meridian p with its own ``gauss_image`` companion where it has one (D2a: φ,
  the sphere its Christoffel dual is built on; D2b: the inscribed n of its definition; D4b: the
  circumscribed m of Theorem 8), else with the circumscribed Gauss image built from p (edges
  tangent to the unit circle, parallel to p's; as in Theorem 8 and ``GET /surfaces``), on the
  interior vertices of p.
- K constant: the row's tractrix with its ``tractrix_gauss_image`` (the discrete pseudosphere of
  Theorem 7). A row without a tractrix generates a catenoid, whose Gaussian curvature is not
  constant even in the smooth case, and a row whose tractrix has no Gauss image in the paper
  (D4a) has no surface the claim is about: both are "not applicable" with the reason.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from decimal import Decimal
from typing import Any

import numpy as np

from app.geometry import conditions, gauss_image
from app.geometry.ball_arithmetic import decimal_bound, decimal_tolerance
from app.geometry.curvature import FaceCurvatures
from app.geometry.curve import Curve
from app.geometry.errors import DomainError
from app.geometry.polygon import magnitude
from app.geometry.precision import Arithmetic, Array, Scalar
from app.geometry.surfaces.ring_curvature import (
    constant_curvature_residuals,
    minimal_residuals,
    ring_curvatures,
)
from app.geometry.tolerances import LOCAL_STEPS


@dataclass(frozen=True)
class Cell:
    """One property tested on one polygon."""

    property: str
    residual: float | Decimal | None
    """On balls a decimal rounded up (a rigorous upper bound of the largest residual)."""
    tolerance: float | Decimal
    """On balls a decimal rounded down."""
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


def tolerance_of(curve: Curve) -> Any:
    """The tolerance of a local condition on this curve's polygon (on balls a decimal)."""
    if curve.local_tolerance is not None:
        return _shown(curve.arithmetic, curve.local_tolerance)
    return _shown(curve.arithmetic, curve.arithmetic.tolerance(LOCAL_STEPS))


def _shown(ar: Arithmetic, tolerance: Any) -> Any:
    """A tolerance as a cell holds it: on balls a decimal (``decimal_tolerance``: from 324
    digits on a float tolerance is 0), compared with residuals rounded up; else as is."""
    return decimal_tolerance(tolerance) if ar.certified else tolerance


def _residual(ar: Arithmetic, residuals: Array) -> Any:
    """The largest residual; a residual that is not a number counts as the largest float. On
    balls a decimal >= its rigorous upper bound (``decimal_bound``)."""
    values = ar.to_floats(residuals)
    if not len(values):
        return None
    if ar.certified and bool(np.all(np.isfinite(values))):
        return decimal_bound(ar.largest_upper(residuals), upward=True)  # type: ignore[attr-defined]
    values = np.where(np.isfinite(values), values, np.finfo(np.float64).max)
    worst = float(np.max(values))
    return decimal_bound(worst, upward=True) if ar.certified else worst


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


@dataclass(frozen=True)
class SurfacePair:
    """A meridian and the Gauss image meridian its surface of revolution is paired with."""

    meridian: Array
    gauss: Array
    description: str
    tolerance: float
    resolution: Array | None = None
    """Per face, for a Gauss image built here from the meridian's edge directions: the worst
    resolution |e| / (|p_k| + |p_{k+1}|) of the edges it uses; residuals are multiplied by it
    (docs/checks.md). ``None``: the Gauss image is the discretization's own."""


NO_TRACTRIX = (
    "not applicable: this discretization has no tractrix; its surface of revolution is a "
    "catenoid, whose Gaussian curvature is not constant even in the smooth case (K constant is "
    "Theorem 7's claim about the pseudosphere)"
)
NO_TRACTRIX_GAUSS_IMAGE = (
    "not applicable: the paper pairs a Gauss image with a discrete tractrix only for (D4b) "
    "(Theorem 7, eq. (18)); for this tractrix it defines none, and the inscribed parallel "
    "polygons are a one-parameter family none of which is singled out (docs/errata.md, Section 5)"
)


def surface_pair(curve: Curve, claim: str) -> SurfacePair | str:
    """The surface a curvature column tests on this row, or the reason there is none.

    ``claim`` is ``"minimal"`` (H = 0: p with its Gauss image) or ``"constant-curvature"`` (K
    constant: the tractrix with its Gauss image).
    """
    ar = curve.arithmetic
    local = tolerance_of(curve)
    if claim == "constant-curvature":
        if "tractrix" not in curve.companions:
            return NO_TRACTRIX
        if "tractrix_gauss_image" not in curve.companions:
            return NO_TRACTRIX_GAUSS_IMAGE
        return SurfacePair(
            curve.companions["tractrix"].vertices,
            curve.companions["tractrix_gauss_image"].vertices,
            "the tractrix with its Gauss image tractrix_gauss_image (Theorem 7)",
            max(local, _shown(ar, curve.companion_tolerances.get("tractrix_gauss_image", local))),
        )
    p = curve.polygon.vertices
    if "gauss_image" in curve.companions:
        return SurfacePair(
            p,
            curve.companions["gauss_image"].vertices,
            "p with its own Gauss image (companion gauss_image)",
            max(local, _shown(ar, curve.companion_tolerances.get("gauss_image", local))),
        )
    if len(p) < 4:
        return "needs 4 vertices (the circumscribed Gauss image uses the interior vertices)"
    edges = p[1:] - p[:-1]
    resolution = ar.hypot(edges[:, 0], edges[:, 1]) / magnitude(p[:-1], p[1:])
    # face k of the interior meridian p_{k+1} .. p_{k+2} uses the edges k, k + 1, k + 2 of p
    worst = np.minimum(np.minimum(resolution[:-2], resolution[1:-1]), resolution[2:])
    return SurfacePair(
        p[1:-1],
        gauss_image.circumscribed(ar, p),
        "p (interior vertices) with the circumscribed Gauss image built from p",
        local,
        worst,
    )


def _curvatures(pair: SurfacePair, ar: Arithmetic) -> FaceCurvatures:
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        return ring_curvatures(ar, pair.meridian, pair.gauss)


def _scaled(ar: Arithmetic, pair: SurfacePair, *residuals: Array) -> Array:
    """The largest of the residuals per face, times the pair's resolution where it has one (on
    balls as balls: floats of their bounds underflow from 324 digits on)."""
    if ar.certified:
        largest = residuals[0]
        for more in residuals[1:]:
            largest = ar.maximum(largest, more)
        return largest if pair.resolution is None else largest * pair.resolution
    worst = ar.to_floats(residuals[0])
    for more in residuals[1:]:
        worst = np.maximum(worst, ar.to_floats(more))
    if pair.resolution is not None:
        worst = worst * ar.to_floats(pair.resolution)
    return worst


def _surface_faces(curve: Curve, key: str, claim: str) -> tuple[SurfacePair, FaceCurvatures] | Cell:
    """The row's surface for ``claim`` and its face curvatures, or the cell saying why not."""
    try:
        pair = surface_pair(curve, claim)
    except DomainError as error:
        return Cell(key, None, tolerance_of(curve), None, note=f"not evaluable: {error}")
    if isinstance(pair, str):
        return Cell(key, None, tolerance_of(curve), None, note=pair)
    if len(pair.meridian) < 2:
        return Cell(key, None, pair.tolerance, None, note="needs a face (two vertices)")
    try:
        return pair, _curvatures(pair, curve.arithmetic)
    except DomainError as error:
        return Cell(key, None, pair.tolerance, None, note=f"not evaluable: {error}")


def _mean_curvature_zero(curve: Curve) -> Cell:
    """H = 0 on every face of the row's surface of revolution (mixed areas, [3])."""
    key, ar = "mean-curvature-zero", curve.arithmetic
    found = _surface_faces(curve, key, "minimal")
    if isinstance(found, Cell):
        return found
    pair, faces = found
    residual = _residual(ar, _scaled(ar, pair, minimal_residuals(faces), faces.parallel))
    product = pair.meridian[:, 1] * pair.gauss[:, 1]
    constants = {}
    if bool(np.all(product != 0)):  # a vertex on the axis would take all the weight
        fit = conditions.fit(ar, product, 1 + 0 * product, abs(product), 0 * product)
        if fit.constant is not None:
            constants["a"] = fit.constant
    holds = residual is not None and residual <= pair.tolerance
    return Cell(key, residual, pair.tolerance, holds, constants, pair.description)


def _gaussian_curvature_constant(curve: Curve) -> Cell:
    """K = A(n)/A(f) the same on every face of the row's pseudosphere (mixed areas, [3])."""
    key, ar = "gaussian-curvature-constant", curve.arithmetic
    found = _surface_faces(curve, key, "constant-curvature")
    if isinstance(found, Cell):
        return found
    pair, faces = found
    fit = conditions.fit(
        ar, faces.gauss_area, faces.area, faces.gauss_area_magnitude, faces.area_magnitude
    )
    if fit.constant is None:
        return Cell(key, None, pair.tolerance, False, note="every face has zero area")
    misfit = constant_curvature_residuals(faces, fit.constant)
    residual = _residual(ar, _scaled(ar, pair, misfit, faces.parallel))
    holds = residual is not None and residual <= pair.tolerance
    return Cell(key, residual, pair.tolerance, holds, {"K": fit.constant}, pair.description)


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
        "Section 5, Theorem 8; (D2b); Section 1 (Christoffel duals)",
        "The surface of revolution (15) of p is a discrete minimal surface: H = −A(f,n)/A(f) = 0 "
        "on every face (mixed areas of [3] on three-dimensional faces, not (17)) with respect to "
        "the row's Gauss image: its own gauss_image companion where it has one (d2a: φ = Φ(f_i), "
        "the sphere of its Christoffel dual; d2b: the inscribed n of its definition; d4b: the "
        "circumscribed m of Theorem 8), else the circumscribed Gauss image built from p (edges "
        "tangent to the unit circle and parallel to p's, m_i the pole of the chord of the "
        "contact points; on the interior vertices). Residual: largest of |A(f, n)| and the "
        "faces' parallelism defect, relative to the magnitudes (for the circumscribed image, "
        "built from edge directions, times the edges' resolution; docs/checks.md). Constant a: "
        "the least-squares value of p_i^y n_i^y, which (17) makes constant exactly when H = 0 "
        "(h for d4b, 1 for d2b).",
        _mean_curvature_zero,
    ),
    Property(
        "gaussian-curvature-constant",
        "K constant",
        "Section 5, Theorem 7",
        "The discrete pseudosphere has constant Gaussian curvature: the row's tractrix, rotated "
        "about the x-axis, has the same K = A(n)/A(f) on every face (mixed areas of [3] on "
        "three-dimensional faces) with respect to the Gauss image of Theorem 7 (the row's "
        "tractrix_gauss_image: inscribed in the unit circle, edges parallel to the tractrix). "
        "Constant K: the least-squares fit of A(n) = K A(f) (−1/h² for d4b). Residual: largest "
        "of |A(n) − K A(f)| and the parallelism defect, relative to the magnitudes. Not "
        "applicable to rows without a tractrix (catenoids) or without a Gauss image for it.",
        _gaussian_curvature_constant,
    ),
)


def row(curve: Curve) -> list[Cell]:
    """Every property tested on one computed curve, in the order of ``PROPERTIES``."""
    return [prop.evaluate(curve) for prop in PROPERTIES]
