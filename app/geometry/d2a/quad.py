"""(D2a) on conformal quad meshes: the Christoffel dual of Theorem 1, with its proof checked.

The polygon comes from the construction (``christoffel.quad``, eqs. (3), (4)); the checks
compare it with the formulas of the proof of Theorem 1 (``christoffel_closed_forms``) and test
eq. (2), (D1) and (D3) on it. Theorem 1 holds for exactly one start height r = p_0^y,
r* = −f_1(1 + f_0²)/(2(f_1 − f_0)²) (eq. (5) at i = 1), which is the default.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property
from typing import Any

import numpy as np

from app.geometry import conditions
from app.geometry.catalog.section4 import (
    QUAD_AREA_SUM as AREA_SUM,
    QUAD_DUAL_EDGE as DUAL_EDGE,
    QUAD_EQUATION_5 as EQUATION_5,
    QUAD_GAUSS_EDGE as GAUSS_EDGE,
    QUAD_GAUSS_NORM as GAUSS_NORM,
    QUAD_HEIGHTS as HEIGHTS,
    QUAD_SECOND_DIFFERENCE as SECOND_DIFFERENCE,
    QUAD_START_HEIGHT as START_HEIGHT,
    QUAD_THEOREM_1 as THEOREM_1,
    QUAD_X_STEP as X_STEP,
)
from app.geometry.checks import Check, Statement, relative_to
from app.geometry.curve import EVERYTHING, Curve, DiscretizationInfo, Selection, require_range
from app.geometry.d2a import closed_forms as cf, construction as christoffel
from app.geometry.d2a.common import (
    FLOAT64_MIN_GAP,
    SHARED_D1,
    SHARED_D3,
    Context,
    at_r_star,
    companions,
    fitted_condition,
    local_tolerance,
    not_enough,
    off_r_star_note,
    require_f_range,
    require_mp_gap,
    scaled_difference,
    scaled_point_difference,
    shifted,
    vertex_magnitude,
)
from app.geometry.errors import NotRepresentableError
from app.geometry.on_demand import Constants, Evaluators
from app.geometry.polygon import area_magnitude, second_difference, signed_areas
from app.geometry.precision import Arithmetic, Array, ExactReal, Scalar
from app.geometry.tolerances import exact

S = Statement

STATEMENTS: tuple[Statement, ...] = (
    THEOREM_1,
    START_HEIGHT,
    GAUSS_EDGE,
    GAUSS_NORM,
    DUAL_EDGE,
    X_STEP,
    SECOND_DIFFERENCE,
    EQUATION_5,
    HEIGHTS,
    AREA_SUM,
    SHARED_D1,
    SHARED_D3,
)

INFO = DiscretizationInfo(
    id="d2a-quad",
    title="Christoffel dual of a conformal quad mesh (D2a)",
    reference="Section 3 (D2a); Section 4.1, Theorem 1, eqs. (2)-(5)",
    summary=(
        "The points f_i = f_0 (f_1/f_0)^i of a conformal quad mesh's parameter line are projected "
        "stereographically to the unit circle (the meridian of a discrete Gaussian image); the "
        "Christoffel dual of that polygon, p_i = p_{i−1} + Δφ_{i−1}/‖Δφ_{i−1}‖² with "
        "p_0 = (0, r), is the discrete hyperbolic cosine. Theorem 1 (eq. (2)) holds for one r."
    ),
    default_range=(-10, 10),
    methods=("construction",),
    companions={
        "conformal": "the conformal points f_i on the y-axis of the yz-plane, as (y, z) = (f_i, 0)",
        "gauss_image": "φ_i = Φ(f_i) = ((f_i² − 1)/(f_i² + 1), 2f_i/(f_i² + 1)) on the unit circle",
    },
    constants={
        "eq2": "c of eq. (2), least-squares fit; equals c_theorem_1 when r = r_theorem_1",
        "c_theorem_1": "4(f_1 − f_0)³/(f_0 + f_1)³ (> 0), the c of Theorem 1 (sign corrected)",
        "r_theorem_1": "r* = −f_1(1 + f_0²)/(2(f_1 − f_0)²), the start height for Theorem 1",
        "x_step": "d = (f_0 + f_1)/(2(f_1 − f_0)), the constant x-step of p",
    },
    statements=STATEMENTS,
)

ERRATUM_X_STEP = (
    "E40",
    "(Δp_{i−1+j})^x = (f_{i−1+j} + f_{i+j})/(2(f_{i−1+j} − f_{i+j}))",
    "(Δp_{i−1+j})^x = (f_{i−1+j} + f_{i+j})/(2(f_{i+j} − f_{i−1+j})) = d > 0",
)
ERRATUM_SECOND_DIFFERENCE = (
    "E41",
    "Δ²p_{i−1} = (0, (f_i² + 1)/(2f_i))",
    "Δ²p_{i−1} = (0, −(f_i² + 1)/(2f_i))",
)
ERRATUM_CONSTANT = (
    "E42",
    "c = 4(f_{i−1} − f_i)³/(f_{i−1} + f_i)³",
    "c = 4(f_i − f_{i−1})³/(f_{i−1} + f_i)³ = 4(f_1 − f_0)³/(f_0 + f_1)³ > 0",
)


@dataclass(frozen=True)
class QuadPolygons:
    """One (D2a) quad computation on i_min .. i_max (``(n,)`` and ``(n, 2)`` arrays)."""

    i_min: int
    f0: Scalar
    f1: Scalar
    r: Scalar
    f: Array
    gauss: Array
    gauss_edges: Array
    p: Array


def start_height(ar: Arithmetic, f0: float, f1: float) -> Scalar:
    """r* of Theorem 1 in this precision (eq. (5) at i = 1)."""
    return cf.theorem_1_radius(ar.scalar(f0), ar.scalar(f1))


def polygons(
    ar: Arithmetic, f0: float, f1: float, r: float | None, i_min: int, i_max: int
) -> QuadPolygons:
    """The construction (3), (4) on i_min .. i_max; r = None means r = r*."""
    rr = start_height(ar, f0, f1) if r is None else ar.scalar(r)
    built = christoffel.quad(ar, f0, f1, rr, i_min, i_max)
    return QuadPolygons(
        i_min, ar.scalar(f0), ar.scalar(f1), rr, built.f, built.gauss, built.gauss_edges, built.p
    )


class _Context(Context):
    """What the checks of one quad computation share, each part computed when first needed."""

    def __init__(self, ar: Arithmetic, data: QuadPolygons, detail: bool) -> None:
        n = len(data.p)
        indices = np.arange(data.i_min, data.i_min + n, dtype=np.int64)
        steps = max(abs(data.i_min), abs(data.i_min + n - 1)) + 1
        super().__init__(ar, indices, steps, detail, (data.f1 - data.f0) / data.f1)
        self.data = data

    @cached_property
    def c_proof(self) -> Scalar:
        """c = 4(f_1 − f_0)³/(f_0 + f_1)³ of Theorem 1 (sign corrected)."""
        return cf.theorem_1_constant(self.data.f0, self.data.f1)

    @cached_property
    def r_star(self) -> Scalar:
        """r*, the start height for which Theorem 1 holds."""
        return cf.theorem_1_radius(self.data.f0, self.data.f1)

    @cached_property
    def x_step(self) -> Scalar:
        """d = (f_0 + f_1)/(2(f_1 − f_0)), the constant x-step the proof names d."""
        return cf.quad_x_step(self.data.f0, self.data.f1)

    @cached_property
    def fit(self) -> conditions.ConditionFit:
        """Eq. (2) fitted on p."""
        return conditions.equation_2(self.ar, self.data.p)

    @cached_property
    def special_note(self) -> str | None:
        """Why a check that holds only for r = r* fails here (``None`` when r = r*)."""
        ar, r = self.ar, self.data.r
        return None if at_r_star(ar, r, self.r_star) else off_r_star_note(ar, r, self.r_star)


def evaluate(
    ar: Arithmetic, data: QuadPolygons, detail: bool = False, selection: Selection = EVERYTHING
) -> tuple[dict[str, Scalar], list[Check]]:
    """Constants and the selected checks of ``STATEMENTS`` on the given polygons.

    Each check computes only what it needs; a constant comes with the statements it belongs to.
    """
    ctx = _Context(ar, data, detail)
    return selection.constants(ctx, _CONSTANTS), selection.evaluate(ctx, _EVALUATORS)


def compute(
    ar: Arithmetic,
    f0: float = 1.0,
    f1: float = 1.5,
    r: float | None = None,
    i_min: int = -10,
    i_max: int = 10,
    detail: bool = False,
    selection: Selection = EVERYTHING,
) -> Curve:
    """(D2a) quad on i_min .. i_max with companions, constants and checks (r = None: r*)."""
    christoffel.validate_quad(f0, f1, r)
    require_range(i_min, i_max)
    if ar.mode == "float64":
        _require_float64_representable(f0, f1, i_min, i_max)
    else:
        require_mp_gap(ar, "f1", "(f1 − f0)/f1", f1, (exact(f1) - exact(f0)) / exact(f1))
    data = polygons(ar, f0, f1, r, i_min, i_max)
    constants, checks = evaluate(ar, data, detail, selection)
    parameters: dict[str, Any] = {
        "f0": f0,
        "f1": f1,
        "r": r if isinstance(r, ExactReal) else ar.to_float(data.r),  # as written (mp)
        "i_min": i_min,
        "i_max": i_max,
    }
    return INFO.curve(
        ar,
        parameters,
        data.p,
        companions(ar, data.f, data.gauss),
        constants=constants,
        checks=checks,
        local_tolerance=local_tolerance(ar, (data.f1 - data.f0) / data.f1),
        selection=selection,
    )


def _theorem_1(ctx: _Context) -> Check:
    """(2) with a fitted c; it must also hold with the proof's c (so a short range cannot fit)."""
    ar, data = ctx.ar, ctx.data
    if len(data.p) < 3:
        return not_enough(ctx, THEOREM_1, "three vertices")
    residuals = np.maximum(ctx.fit.residuals, _equation_2_residuals(ar, data.p, ctx.c_proof))
    printed_c = cf.theorem_1_constant_printed(data.f0, data.f1)
    printed = np.maximum(ctx.fit.residuals, _equation_2_residuals(ar, data.p, printed_c))
    erratum = ctx.erratum(ERRATUM_CONSTANT, printed)
    return ctx.check(THEOREM_1, 0, residuals, erratum, note=ctx.special_note)


def _start_height(ctx: _Context) -> Check:
    data = ctx.data
    if len(data.p) < 3:
        return not_enough(ctx, START_HEIGHT, "three vertices")
    moved = shifted(data.p, ctx.r_star - data.r)
    residuals = _equation_2_residuals(ctx.ar, moved, ctx.c_proof)
    return ctx.check(START_HEIGHT, 0, residuals)


def _equation_2_residuals(ar: Arithmetic, p: Array, c: Scalar) -> Array:
    """|Δ²p_i^y − c(A_i + A_{i+1})| relative to the magnitudes, for a given c."""
    y = p[:, 1]
    areas = signed_areas(p)
    sizes = area_magnitude(p)
    lhs = second_difference(y)
    a = abs(y)
    scale = a[2:] + 2 * a[1:-1] + a[:-2] + abs(c) * (sizes[:-1] + sizes[1:])
    return relative_to(ar, lhs - c * (areas[:-1] + areas[1:]), scale)


def _gauss_edge(ctx: _Context) -> Check:
    data = ctx.data
    if len(data.f) < 2:
        return not_enough(ctx, GAUSS_EDGE, "two vertices")
    formula = cf.quad_gauss_edge(data.f[:-1], data.f[1:])
    zero = ctx.ar.zeros(len(data.f) - 1)
    residuals = scaled_point_difference(ctx.ar, data.gauss_edges, formula, zero)
    return ctx.check(GAUSS_EDGE, 1, residuals)


def _gauss_norm(ctx: _Context) -> Check:
    data = ctx.data
    if len(data.f) < 2:
        return not_enough(ctx, GAUSS_NORM, "two vertices")
    edges = data.gauss_edges
    norm = edges[:, 0] * edges[:, 0] + edges[:, 1] * edges[:, 1]
    expected = cf.quad_gauss_edge_norm_squared(data.f[:-1], data.f[1:])
    zero = ctx.ar.zeros(len(data.f) - 1)
    return ctx.check(GAUSS_NORM, 1, scaled_difference(ctx.ar, norm, expected, zero))


def _dual_edge(ctx: _Context) -> Check:
    data = ctx.data
    if len(data.p) < 2:
        return not_enough(ctx, DUAL_EDGE, "two vertices")
    p = data.p
    formula = cf.quad_dual_edge(data.f[:-1], data.f[1:])
    residuals = scaled_point_difference(
        ctx.ar, p[1:] - p[:-1], formula, vertex_magnitude(p[:-1], p[1:])
    )
    return ctx.check(DUAL_EDGE, 1, residuals)


def _x_step(ctx: _Context) -> Check:
    data = ctx.data
    if len(data.p) < 2:
        return not_enough(ctx, X_STEP, "two vertices")
    ar, p = ctx.ar, data.p
    steps = p[1:, 0] - p[:-1, 0]
    size = vertex_magnitude(p[:-1], p[1:])
    f_prev, f_cur = data.f[:-1], data.f[1:]
    per_edge = cf.quad_x_step(f_prev, f_cur)
    residuals = np.maximum(
        scaled_difference(ar, steps, per_edge, size),
        scaled_difference(ar, steps, np.full_like(steps, ctx.x_step), size),
    )
    printed = scaled_difference(ar, steps, cf.quad_x_step_printed(f_prev, f_cur), size)
    return ctx.check(X_STEP, 1, residuals, ctx.erratum(ERRATUM_X_STEP, printed))


def _second_difference(ctx: _Context) -> Check:
    data = ctx.data
    if len(data.p) < 3:
        return not_enough(ctx, SECOND_DIFFERENCE, "three vertices")
    ar, p = ctx.ar, data.p
    second = p[2:] - 2 * p[1:-1] + p[:-2]
    size = vertex_magnitude(p[2:], p[1:-1], p[1:-1], p[:-2])
    f_cur = data.f[1:-1]
    residuals = scaled_point_difference(ar, second, cf.quad_second_difference(f_cur), size)
    printed = scaled_point_difference(ar, second, cf.quad_second_difference_printed(f_cur), size)
    erratum = ctx.erratum(ERRATUM_SECOND_DIFFERENCE, printed)
    return ctx.check(SECOND_DIFFERENCE, 1, residuals, erratum)


def _equation_5(ctx: _Context) -> Check:
    ar, y, f = ctx.ar, ctx.data.p[:, 1], ctx.data.f
    if len(f) < 2:
        return not_enough(ctx, EQUATION_5, "two vertices")
    # (5) names p_{i−1}^y; residual k belongs to the vertex i_min + k
    expected = cf.quad_equation_5(f[:-1], f[1:])
    residuals = scaled_difference(ar, y[:-1], expected, 0 * expected)
    return ctx.check(EQUATION_5, 0, residuals, summed=True, note=ctx.special_note)


def _heights(ctx: _Context) -> Check:
    ar, y, f = ctx.ar, ctx.data.p[:, 1], ctx.data.f
    if len(f) < 3:
        return not_enough(ctx, HEIGHTS, "three vertices")
    f_prev, f_cur = f[:-2], f[1:-1]
    current = scaled_difference(ar, y[1:-1], cf.quad_height_next(f_prev, f_cur), 0 * f_cur)
    after = scaled_difference(ar, y[2:], cf.quad_height_after(f_prev, f_cur), 0 * f_cur)
    residuals = np.maximum(current, after)
    return ctx.check(HEIGHTS, 1, residuals, summed=True, note=ctx.special_note)


def _area_sum(ctx: _Context) -> Check:
    if len(ctx.data.p) < 3:
        return not_enough(ctx, AREA_SUM, "three vertices")
    ar, p, f = ctx.ar, ctx.data.p, ctx.data.f
    areas = signed_areas(p)
    sizes = area_magnitude(p)
    expected = cf.quad_area_sum(f[:-2], f[1:-1])
    residuals = scaled_difference(ar, areas[:-1] + areas[1:], expected, sizes[:-1] + sizes[1:])
    return ctx.check(AREA_SUM, 1, residuals, summed=True, note=ctx.special_note)


#: Each statement about the (D2a) quad polygon and the function that checks it, in the order of
#: the response.
_EVALUATORS: Evaluators[_Context] = (
    (THEOREM_1, _theorem_1),
    (START_HEIGHT, _start_height),
    (GAUSS_EDGE, _gauss_edge),
    (GAUSS_NORM, _gauss_norm),
    (DUAL_EDGE, _dual_edge),
    (X_STEP, _x_step),
    (SECOND_DIFFERENCE, _second_difference),
    (EQUATION_5, _equation_5),
    (HEIGHTS, _heights),
    (AREA_SUM, _area_sum),
    (
        SHARED_D1,
        lambda x: fitted_condition(
            x,
            SHARED_D1,
            conditions.d1(x.ar, x.data.p),
            "(D1) holds",
            "(D1) fails: the (D2a) quad polygon is not a (D1) polygon",
        ),
    ),
    (
        SHARED_D3,
        lambda x: fitted_condition(
            x,
            SHARED_D3,
            conditions.d3(x.ar, x.data.p),
            "(D3) holds",
            "(D3) fails: the (D2a) quad polygon is not a (D3) polygon",
        ),
    ),
)

#: The constants and the statements they come with.
_CONSTANTS: Constants[_Context] = (
    ("eq2", (THEOREM_1,), lambda x: x.fit.constant),
    ("c_theorem_1", (THEOREM_1, START_HEIGHT), lambda x: x.c_proof),
    ("r_theorem_1", (THEOREM_1, START_HEIGHT), lambda x: x.r_star),
    ("x_step", (X_STEP,), lambda x: x.x_step),
)


def _require_float64_representable(f0: float, f1: float, i_min: int, i_max: int) -> None:
    """Refuse, before computing, parameters that float64 cannot resolve or represent."""
    if (f1 - f0) / f1 < FLOAT64_MIN_GAP:
        raise NotRepresentableError(
            "f1",
            f"(f1 − f0)/f1 >= {FLOAT64_MIN_GAP:g} in float64",
            f1,
            "nearly equal f_i give Gauss image edges below float64 resolution; use precision=mp",
        )
    log_q = math.log(f1) - math.log(f0)
    log_f0 = math.log(f0)
    for name, value in (("i_max", i_max), ("i_min", i_min)):
        require_f_range(name, [log_f0 + value * log_q, log_f0], value)
