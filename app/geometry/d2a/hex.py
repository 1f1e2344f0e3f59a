"""(D2a) on conformal hexagonal meshes: Theorems 2 and 3 checked on the Christoffel dual.

The polygon comes from the construction (``christoffel.hexagonal``: the sequence of Section 4.1
and eq. (6)); the checks compare it with Theorem 3's explicit forms (8), (9), with (10), (11)
and the start height of the proof of Theorem 2, and test (7), (2), (D1), (D3) on it. Theorem 2
holds for exactly one start height r* (the default).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property
from typing import Any, cast

import numpy as np

from app.geometry import conditions
from app.geometry.catalog.section4 import (
    HEX_EQUATION_10 as EQUATION_10,
    HEX_START_HEIGHT as START_HEIGHT,
    HEX_THEOREM_2 as THEOREM_2,
    HEX_THEOREM_3_EVEN as THEOREM_3_EVEN,
    HEX_THEOREM_3_ODD as THEOREM_3_ODD,
)
from app.geometry.checks import Check, Statement, not_applicable, relative_to
from app.geometry.curve import EVERYTHING, Curve, DiscretizationInfo, Selection, require_range
from app.geometry.d2a import closed_forms as cf, construction as christoffel
from app.geometry.d2a.common import (
    FLOAT64_MIN_GAP,
    SHARED_D1,
    SHARED_D3,
    SHARED_EQUATION_2,
    Context,
    at_r_star,
    companions,
    fitted_condition,
    local_tolerance,
    not_enough,
    off_r_star_note,
    require_f_range,
    require_mp_gap,
    scaled_point_difference,
    shifted,
)
from app.geometry.errors import NotRepresentableError
from app.geometry.on_demand import Constants, Evaluators
from app.geometry.polygon import area_magnitude, second_difference, signed_areas
from app.geometry.precision import Arithmetic, Array, ExactReal, Scalar, stack_points
from app.geometry.tolerances import exact

S = Statement

STATEMENTS: tuple[Statement, ...] = (
    THEOREM_2,
    START_HEIGHT,
    EQUATION_10,
    THEOREM_3_EVEN,
    THEOREM_3_ODD,
    SHARED_EQUATION_2,
    SHARED_D1,
    SHARED_D3,
)

INFO = DiscretizationInfo(
    id="d2a-hex",
    title="Christoffel dual of a conformal hexagonal mesh (D2a)",
    reference="Section 3 (D2a); Section 4.1, Theorems 2 and 3, eqs. (6)-(11)",
    summary=(
        "The parameter line of a conformal hexagonal mesh (f_{2k} = a (b/a)^k, odd points the "
        "convex combinations λ f_{i+1} + (1 − λ) f_{i−1}) is projected stereographically to the "
        "unit circle, and its Christoffel dual with the hexagonal factors 3 (even steps) and 2 "
        "(odd steps), eq. (6), with p_0 = (0, r), is the discrete hyperbolic cosine. Theorem 2 "
        "(eq. (7), two constants) holds for one r; Theorem 3 gives the vertices explicitly."
    ),
    default_range=(-10, 10),
    methods=("construction",),
    companions={
        "conformal": "the conformal points f_i on the y-axis of the yz-plane, as (y, z) = (f_i, 0)",
        "gauss_image": "φ_i = Φ(f_i) = ((f_i² − 1)/(f_i² + 1), 2f_i/(f_i² + 1)) on the unit circle",
    },
    constants={
        "c1": "c_1 of eq. (7), least-squares fit (with c2); equals c1_eq11 when r = r_theorem_2",
        "c2": "c_2 of eq. (7), least-squares fit (with c1); equals c2_eq11 when r = r_theorem_2",
        "c1_eq11": "c_1 of eq. (11); its sign depends on a, b, λ",
        "c2_eq11": "c_2 of eq. (11); its sign depends on a, b, λ",
        "r_theorem_2": "r*, the start height for which Theorem 2 holds (proof of Theorem 2)",
        "x_step_even": "p_{i+1}^x − p_i^x for even i",
        "x_step_odd": "p_{i+1}^x − p_i^x for odd i",
    },
    statements=STATEMENTS,
)

ERRATUM_EQUATION_2 = (
    "E45",
    "Section 4.1: '(2) is fulfilled by polygons constructed in (D2a) with the Christoffel "
    "duality. This is the content of Theorems 1 and 2'; Figure 6: 'Theorem 2 states that this "
    "type of discretization also fulfills a modified version of (D3)'; before the proof of "
    "Theorem 2: 'we can show the analog of (D3)'",
    "(2) holds for the quad polygons (Theorem 1, at r = r*); the hexagonal polygons satisfy "
    "the modified (2), eq. (7), with two constants c_1 ≠ c_2 (Theorem 2), and neither (2) nor "
    "(D3), not even with alternating constants",
)
ERRATUM_EVEN = (
    "E43",
    "p_i^y = (b^{−i/2} − a^{−i/2})(a^{i/2}b(λ−3) + ab^{i/2}(3a(λ−1) − 2bλ)(a(λ−1) − bλ)) / "
    "(2λ(a−b)²(λ−1)) + r  (i even)",
    "p_i^y = (a^{−i/2} − b^{−i/2})(a^{i/2}b(λ−3) + ab^{i/2}(3a(λ−1) − 2bλ)(a(λ−1) − bλ)) / "
    "(2λ(a−b)²(λ−1)) + r  (i even)",
)
ERRATUM_START_HEIGHT = (
    "E44",
    "r = [3a³(λ−1)² − 5a²b(λ−1)λ + 2ab²λ² − b(λ−3)] / [2λ(λ−1)a − b]²",
    "r = [3a³(λ−1)² − 5a²b(λ−1)λ + 2ab²λ² − b(λ−3)] / [2λ(λ−1)(a − b)²]",
)


@dataclass(frozen=True)
class HexPolygons:
    """One (D2a) hexagonal computation on i_min .. i_max."""

    i_min: int
    a: Scalar
    b: Scalar
    lam: Scalar
    r: Scalar
    f: Array
    gauss: Array
    p: Array


def start_height(ar: Arithmetic, a: float, b: float, lam: float) -> Scalar:
    """r* of Theorem 2 in this precision (corrected form, E44)."""
    return cf.theorem_2_radius(ar.scalar(a), ar.scalar(b), ar.scalar(lam))


def polygons(
    ar: Arithmetic, a: float, b: float, lam: float, r: float | None, i_min: int, i_max: int
) -> HexPolygons:
    """The construction (Section 4.1, eq. (6)) on i_min .. i_max; r = None means r = r*."""
    rr = start_height(ar, a, b, lam) if r is None else ar.scalar(r)
    built = christoffel.hexagonal(ar, a, b, lam, rr, i_min, i_max)
    return HexPolygons(
        i_min, ar.scalar(a), ar.scalar(b), ar.scalar(lam), rr, built.f, built.gauss, built.p
    )


class _Context(Context):
    """What the checks of one hexagonal computation share, each part computed when first
    needed."""

    def __init__(self, ar: Arithmetic, data: HexPolygons, detail: bool) -> None:
        n = len(data.p)
        indices = np.arange(data.i_min, data.i_min + n, dtype=np.int64)
        steps = max(abs(data.i_min), abs(data.i_min + n - 1)) + 1
        super().__init__(ar, indices, steps, detail, smallest_gap(data.a, data.b, data.lam))
        self.data = data

    @cached_property
    def c11(self) -> tuple[Scalar, Scalar]:
        """c_1, c_2 of eq. (11)."""
        return cf.theorem_2_constants(self.data.a, self.data.b, self.data.lam)

    @cached_property
    def r_star(self) -> Scalar:
        """r*, the start height for which Theorem 2 holds."""
        return cf.theorem_2_radius(self.data.a, self.data.b, self.data.lam)

    @cached_property
    def fit(self) -> conditions.TwoConstantFit:
        """Eq. (7) fitted on p (two constants)."""
        return conditions.equation_7(self.ar, self.data.p, self.data.i_min)

    @cached_property
    def fit_2(self) -> conditions.ConditionFit:
        """Eq. (2) fitted on p (one constant)."""
        return conditions.equation_2(self.ar, self.data.p)

    @cached_property
    def x_steps(self) -> tuple[Scalar, Scalar]:
        """p_{i+1}^x − p_i^x for even and odd i, from Theorem 3 (p_0^x = 0)."""
        ar, a, b, lam = self.ar, self.data.a, self.data.b, self.data.lam
        x1 = cf.theorem_3_x(a, b, lam, ar.array([1]), odd=True)[0]  # p_1^x
        x2 = cf.theorem_3_x(a, b, lam, ar.array([2]), odd=False)[0]
        return x1, x2 - x1


def evaluate(
    ar: Arithmetic, data: HexPolygons, detail: bool = False, selection: Selection = EVERYTHING
) -> tuple[dict[str, Scalar], list[Check]]:
    """Constants and the selected checks of ``STATEMENTS`` on the given polygons.

    Each check computes only what it needs; a constant comes with the statements it belongs to.
    """
    ctx = _Context(ar, data, detail)
    return selection.constants(ctx, _CONSTANTS), selection.evaluate(ctx, _EVALUATORS)


def compute(
    ar: Arithmetic,
    a: float = 1.0,
    b: float = 2.5,
    lam: float = 0.5,
    r: float | None = None,
    i_min: int = -10,
    i_max: int = 10,
    detail: bool = False,
    selection: Selection = EVERYTHING,
) -> Curve:
    """(D2a) hexagonal on i_min .. i_max with companions, constants and checks (r = None: r*)."""
    christoffel.validate_hex(a, b, lam, r)
    require_range(i_min, i_max)
    if ar.mode == "float64":
        _require_float64_representable(a, b, lam, i_min, i_max)
    else:
        exact_a, exact_b, exact_lam = exact(a), exact(b), exact(lam)
        require_mp_gap(ar, "b", "(b − a)/b", b, (exact_b - exact_a) / exact_b)
        require_mp_gap(
            ar,
            "lambda",
            "λ(b − a)/f_1 and (1 − λ)(b − a)/b",
            lam,
            smallest_gap(exact_a, exact_b, exact_lam),
        )
    data = polygons(ar, a, b, lam, r, i_min, i_max)
    constants, checks = evaluate(ar, data, detail, selection)
    parameters: dict[str, Any] = {
        "a": a,
        "b": b,
        "lambda": lam,
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
        local_tolerance=local_tolerance(ar, smallest_gap(data.a, data.b, data.lam)),
        selection=selection,
    )


def equation_7_residuals(ar: Arithmetic, p: Array, i_min: int, c1: Scalar, c2: Scalar) -> Array:
    """(7) with given constants: |Δ²p_i^y − (c_1 u_i + c_2 v_i)| relative to the magnitudes."""
    y = p[:, 1]
    areas, sizes = signed_areas(p), area_magnitude(p)
    lhs = second_difference(y)
    even = (np.arange(i_min, i_min + len(lhs)) % 2) == 0
    first = cast(Array, np.where(even, c1, c2))  # multiplies A_i
    second = cast(Array, np.where(even, c2, c1))  # multiplies A_{i+1}
    a = abs(y)
    scale = a[2:] + 2 * a[1:-1] + a[:-2] + abs(first) * sizes[:-1] + abs(second) * sizes[1:]
    return relative_to(ar, lhs - first * areas[:-1] - second * areas[1:], scale)


def _theorem_2(ctx: _Context) -> Check:
    ar, data, fit = ctx.ar, ctx.data, ctx.fit
    if fit.constants is None:
        return not_applicable(THEOREM_2, ctx.summed, "needs five vertices (two equations)")
    with_11 = equation_7_residuals(ar, data.p, data.i_min, *ctx.c11)
    erratum = ctx.erratum(ERRATUM_EQUATION_2, ctx.fit_2.residuals)  # what Section 4.1 says
    note = None
    if not at_r_star(ar, data.r, ctx.r_star):
        note = off_r_star_note(ar, data.r, ctx.r_star)
    return ctx.check(THEOREM_2, 0, np.maximum(fit.residuals, with_11), erratum, note=note)


def _start_height(ctx: _Context) -> Check:
    ar, data = ctx.ar, ctx.data
    if len(data.p) < 3:
        return not_enough(ctx, START_HEIGHT, "three vertices")
    moved = shifted(data.p, ctx.r_star - data.r)
    residuals = equation_7_residuals(ar, moved, data.i_min, *ctx.c11)
    printed_r = cf.theorem_2_radius_printed(data.a, data.b, data.lam)
    printed = equation_7_residuals(ar, shifted(data.p, printed_r - data.r), data.i_min, *ctx.c11)
    return ctx.check(START_HEIGHT, 0, residuals, ctx.erratum(ERRATUM_START_HEIGHT, printed))


def _equation_10(ctx: _Context) -> Check:
    data = ctx.data
    if len(data.p) < 4:
        return not_enough(ctx, EQUATION_10, "four vertices")
    p = data.p
    y = p[:, 1]
    a = abs(y)
    third = y[3:] - 3 * y[2:-1] + 3 * y[1:-2] - y[:-3]
    areas, sizes = signed_areas(p), area_magnitude(p)
    even = (np.arange(data.i_min, data.i_min + len(third)) % 2) == 0
    c = cast(Array, np.where(even, ctx.c11[0], ctx.c11[1]))
    scale = a[3:] + 3 * a[2:-1] + 3 * a[1:-2] + a[:-3] + abs(c) * (sizes[2:] + sizes[:-2])
    residuals = relative_to(ctx.ar, third - c * (areas[2:] - areas[:-2]), scale)
    return ctx.check(EQUATION_10, 0, residuals)


def _theorem_3(ctx: _Context, statement: Statement) -> Check:
    """Theorem 3's explicit p_i at the even (``THEOREM_3_EVEN``) or odd indices."""
    ar, p = ctx.ar, ctx.data.p
    a, b, lam, r = ctx.data.a, ctx.data.b, ctx.data.lam, ctx.data.r
    is_odd = statement is THEOREM_3_ODD
    mask = (ctx.indices % 2) == (1 if is_odd else 0)
    at = ctx.indices[mask]
    if len(at) == 0:
        return not_enough(ctx, statement, "an index of this parity")
    i = ar.array(at)
    x = cf.theorem_3_x(a, b, lam, i, odd=is_odd)
    if is_odd:
        y = cf.theorem_3_y_odd(ar, a, b, lam, r, i)
    else:
        y = cf.theorem_3_y_even(ar, a, b, lam, r, i)
    zero = ar.zeros(len(at))
    residuals = scaled_point_difference(ar, p[mask], stack_points(x, y), zero)
    erratum = None
    if not is_odd:
        # the literal powers may overflow in float64: the printed residual is then not a
        # number, and the erratum says so (printed_residual None)
        with np.errstate(all="ignore"):
            printed_y = cf.theorem_3_y_even_printed(a, b, lam, r, i)
            printed = scaled_point_difference(ar, p[mask], stack_points(x, printed_y), zero)
        erratum = ctx.erratum(ERRATUM_EVEN, printed)
    return ctx.check(statement, 0, residuals, erratum, summed=True, at=at)


#: Each statement about the (D2a) hexagonal polygon and the function that checks it, in the
#: order of the response.
_EVALUATORS: Evaluators[_Context] = (
    (THEOREM_2, _theorem_2),
    (START_HEIGHT, _start_height),
    (EQUATION_10, _equation_10),
    (THEOREM_3_EVEN, lambda x: _theorem_3(x, THEOREM_3_EVEN)),
    (THEOREM_3_ODD, lambda x: _theorem_3(x, THEOREM_3_ODD)),
    (
        SHARED_EQUATION_2,
        lambda x: fitted_condition(
            x,
            SHARED_EQUATION_2,
            x.fit_2,
            "(2) holds",
            "(2) with one constant fails; Theorem 2 replaces it by (7)",
        ),
    ),
    (
        SHARED_D1,
        lambda x: fitted_condition(
            x,
            SHARED_D1,
            conditions.d1(x.ar, x.data.p),
            "(D1) holds",
            "(D1) fails: the (D2a) hexagonal polygon is not a (D1) polygon",
        ),
    ),
    (
        SHARED_D3,
        lambda x: fitted_condition(
            x,
            SHARED_D3,
            conditions.d3(x.ar, x.data.p),
            "(D3) holds",
            "(D3) fails: the (D2a) hexagonal polygon is not a (D3) polygon",
        ),
    ),
)


def _fitted(x: _Context, k: int) -> Scalar | None:
    return None if x.fit.constants is None else x.fit.constants[k]


#: The constants and the statements they come with.
_CONSTANTS: Constants[_Context] = (
    ("c1", (THEOREM_2,), lambda x: _fitted(x, 0)),
    ("c2", (THEOREM_2,), lambda x: _fitted(x, 1)),
    ("c1_eq11", (THEOREM_2, START_HEIGHT, EQUATION_10), lambda x: x.c11[0]),
    ("c2_eq11", (THEOREM_2, START_HEIGHT, EQUATION_10), lambda x: x.c11[1]),
    ("r_theorem_2", (THEOREM_2, START_HEIGHT), lambda x: x.r_star),
    ("x_step_even", (THEOREM_3_EVEN, THEOREM_3_ODD), lambda x: x.x_steps[0]),
    ("x_step_odd", (THEOREM_3_EVEN, THEOREM_3_ODD), lambda x: x.x_steps[1]),
)


def smallest_gap(a: Scalar, b: Scalar, lam: Scalar) -> Scalar:
    """The smallest relative gap (f_{i+1} − f_i)/f_{i+1} of the hexagonal parameter line."""
    s = b / a
    u = 1 + lam * (s - 1)  # f_{2k+1}/f_{2k}
    return min((u - 1) / u, (s - u) / s)


def _require_float64_representable(a: float, b: float, lam: float, i_min: int, i_max: int) -> None:
    """Refuse, before computing, parameters that float64 cannot resolve or represent."""
    gap = (b - a) / b
    if gap < FLOAT64_MIN_GAP:
        raise NotRepresentableError(
            "b",
            f"(b − a)/b >= {FLOAT64_MIN_GAP:g} in float64",
            b,
            "nearly equal f_i give Gauss image edges below float64 resolution; use precision=mp",
        )
    if smallest_gap(a, b, lam) < FLOAT64_MIN_GAP:
        raise NotRepresentableError(
            "lambda",
            f"λ(b − a)/f_1 >= {FLOAT64_MIN_GAP:g} and (1 − λ)(b − a)/b >= {FLOAT64_MIN_GAP:g} "
            "in float64",
            lam,
            "an odd point nearly coincides with a neighbour; use precision=mp",
        )
    log_a, log_s = math.log(a), math.log(b) - math.log(a)
    for name, value in (("i_max", i_max), ("i_min", i_min)):
        k = math.floor(value / 2)
        require_f_range(name, [log_a + k * log_s, log_a + (k + 1) * log_s, log_a], value)
