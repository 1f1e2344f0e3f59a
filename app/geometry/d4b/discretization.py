"""(D4b) Wunderlich's discrete hyperbolic cosine, with Theorems 4–8 checked on it.

The polygon comes from the construction (``kinematic_tractrix``) by default, or from the closed
forms (``kinematic_closed_forms``) with ``method="closed-form"``; the checks compare the two and
test the properties that Section 4.2 proves. The Gauss images of Section 5 and Theorems 7, 8 are
assembled in ``d4b_curvature``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Any, Literal

import numpy as np

from app.geometry import conditions, darboux, nikolaides
from app.geometry.checks import (
    Check,
    Erratum,
    Statement,
    check_residuals,
    not_applicable,
    point_distance,
    printed_residual,
    relative_difference,
    relative_point_difference,
    relative_to,
)
from app.geometry.curve import Curve, DiscretizationInfo, require_range
from app.geometry.d4b import closed_forms as kinematic_closed_forms
from app.geometry.d4b import curvature as d4b_curvature
from app.geometry.d4b.construction import construct, validate
from app.geometry.errors import NotRepresentableError
from app.geometry.precision import Arithmetic, Array, Scalar, stack_points

Method = Literal["construction", "closed-form"]

#: Local checks combine a handful of neighbouring values; their tolerance allows this many
#: rounding steps.
LOCAL_STEPS = 16

#: Float64 results keep every coordinate below this size, so that the checks, which multiply
#: two coordinates (areas, dot products), stay finite.
FLOAT64_COORDINATE_LIMIT = 1e150

#: Δ²p^y/p^y is about (2d/h)²; the constants of (D1), (2) are resolved when that exceeds the
#: working precision by this factor squared (float64: d/h >= 1.5e-6).
RESOLUTION_MARGIN = 100

S = Statement
HYPOTHESIS_NEEDLESS = (
    "Stated needlessly for (D4b): every (D4b) polygon has p_{i−1}^y p_i^y >= h² > d², for every "
    "0 < d < h and every first stick; the condition matters only for sequences that merely "
    "satisfy (13) (docs/errata.md, Section 3, implicit conditions)."
)
HYPOTHESIS_ALWAYS = (
    "Theorem 4's hypothesis d² < p_{i−1}^y p_i^y always holds for (D4b) (theorem-4-hypothesis), "
    "so the statement holds for every 0 < d < h."
)
VERTICAL_START = (
    "Assumes a vertical first stick (d_0^y = p_1^y = h). For a first stick at angle beta0 the "
    "construction is the vertical one shifted by the index τ = ln(tan(β0/2))/L, and the service "
    "checks the formula at i + τ (an extension; docs/errata.md, Section 3)."
)
LOCAL_NUMBERING = (
    "The proof numbers the axis points locally, shifted by one against Section 3 and Theorem 5: "
    "with Theorem 5's indexing (p_i^x = (2i − 1)d) α_i is the angle at p_i between the lines to "
    "x_{i−1} and x_i (E1)."
)
RECURSION_DENOMINATOR = (
    "For (D4b) polygons the denominator p_{i−1}^y p_i^y − d² is always >= h² − d² > 0; for "
    "sequences that merely satisfy (13) it must not vanish (Theorem 4's hypothesis)."
)
CENTRE_INDEX = (
    "Index convention (Theorem 5): p_i is the centre of the rotation from stick i − 1 to stick "
    "i, over the midpoint of x_{i−1} and x_i, so the reflection axis of x_{i−1} and x_i passes "
    "through p_i."
)
POINT_REFLECTION = (
    "Here x_i is reflected in the tractrix point d_i itself (e_i = 2d_i − x_i, so |x_i − e_i| = "
    "2h), not in an edge midpoint as in (D4a); the edges of e and x are equal because the "
    "polygon is symmetric about the reflection axis of each tractrix edge, for every first "
    "stick."
)
HYPOTHESIS = S(
    "theorem-4-hypothesis",
    "Theorem 4, hypothesis",
    "d² < p_{i−1}^y p_i^y for every i. Residual: largest max(0, d² − p_{i−1}^y p_i^y)/d². "
    "Every (D4b) polygon satisfies it, since p_{i−1}^y p_i^y ≥ h² > d² (see docs/errata.md).",
    conditions=(HYPOTHESIS_NEEDLESS,),
)
THEOREM_4_I = S(
    "theorem-4-i",
    "Theorem 4 (i), (D1)",
    "Δ²p_i^y = c (l_i + l_{i+1}) with one constant c > 0 (constants.d1, least-squares fit). "
    "Residual: largest |Δ²p_i^y − c(l_i + l_{i+1})|, relative to the magnitude of the "
    "coordinates it is computed from (docs/checks.md).",
    conditions=(HYPOTHESIS_ALWAYS,),
)
THEOREM_4_II = S(
    "theorem-4-ii",
    "Theorem 4 (ii), (D3)",
    "A_i = c l_i with one constant c > 0 (constants.d3, least-squares fit). Residual: largest "
    "|A_i − c l_i|, relative to the magnitude of the coordinates (docs/checks.md).",
    conditions=(HYPOTHESIS_ALWAYS,),
)
THEOREM_4_III = S(
    "theorem-4-iii",
    "Theorem 4 (iii), eq. (2)",
    "Δ²p_i^y = c (A_i + A_{i+1}) with one constant c > 0 (constants.eq2) and c = c_(D1)/c_(D3). "
    "Residual: the larger of the residuals of (2) with the fitted c and with c = c_(D1)/c_(D3), "
    "each as in theorem-4-i (a difference of the constants themselves would exceed what the "
    "data resolve for small d/h).",
    conditions=(HYPOTHESIS_ALWAYS,),
)
ROTATION_ANGLE = S(
    "theorem-4-rotation-angle",
    "Proof of Theorem 4",
    "The rotation about p_i, which takes x_{i−1} to x_i, turns by α_i = 2 arctan(d/p_i^y). "
    "Residual: largest |angle(x_{i−1} − p_i, x_i − p_i) − 2 arctan(d/p_i^y)|.",
    conditions=(LOCAL_NUMBERING,),
)
RECURSION_13 = S(
    "recursion-13",
    "Proof of Theorem 4, eq. (13)",
    "p_{i+1}^y = (p_i^y³ + 2d²p_i^y + d²p_{i−1}^y) / (p_i^y p_{i−1}^y − d²). "
    "Residual: largest relative difference from the polygon's p_{i+1}^y.",
    conditions=(RECURSION_DENOMINATOR,),
)
TWO_STEP = S(
    "recursion-13-two-step",
    "Proof of Theorem 4 (i), formula for p_{i+2}^y",
    "p_{i+2}^y = (p_i⁵ + d²(p_{i−1}³ + 2p_{i−1}²p_i + 3p_{i−1}p_i² + 4p_i³) + d⁴(2p_{i−1} + 3p_i))"
    " / (d² − p_{i−1}p_i)² (all heights p^y). Residual: largest relative difference.",
    conditions=(RECURSION_DENOMINATOR,),
)
THEOREM_5 = S(
    "theorem-5",
    "Theorem 5, eq. (14)",
    "The closed form p_i = ((2i−1)d, (h−d)^i/(2(h+d)^{i−1}) + (h+d)^i/(2(h−d)^{i−1})) equals the "
    "constructed centres (for a tilted first stick: at the shifted index i + τ, see the "
    "kinematic_closed_forms module). Residual: largest |p_i − closed form| / |closed form|.",
    conditions=(VERTICAL_START,),
)
THEOREM_6 = S(
    "theorem-6",
    "Theorem 6, eq. (16)",
    "The closed form (16) of the tractrix equals the constructed stick ends d_i. "
    "Residual: largest |d_i − closed form| / |closed form|.",
    conditions=(VERTICAL_START,),
)
DARBOUX = S(
    "darboux-d4b",
    "Section 3, (D4b): Darboux transform",
    "e_i, the reflection of x_i in d_i, has |e_{i+1} − e_i| = |x_{i+1} − x_i| = 2d. "
    "Residual: largest difference of the edge lengths, relative to the magnitude of the four "
    "points (docs/checks.md).",
    conditions=(POINT_REFLECTION,),
)
DARBOUX_DISTANCE = S(
    "darboux-d4b-distance",
    "Section 3, (D4b): Darboux transform",
    "|x_i − e_i| is the same for every i, namely 2h. Residual: largest | |x_i − e_i| − 2h |, "
    "relative to the magnitude of x_i and e_i (docs/checks.md).",
    conditions=(POINT_REFLECTION,),
)
NIKOLAIDES = S(
    "nikolaides-d4b",
    "Section 3, (D4b) and (S4): construction of Nikolaides",
    "The triangles x_i d_i p_i and x_i d_i p_{i+1} have a right angle at d_i: the edge p_i p_{i+1}"
    " is the tractrix normal at d_i. Residual: largest |cos| of the angles at d_i, with the "
    "vectors measured against the magnitude of their end points (docs/checks.md).",
    conditions=(CENTRE_INDEX,),
)

STATEMENTS: tuple[Statement, ...] = (
    HYPOTHESIS,
    THEOREM_4_I,
    THEOREM_4_II,
    THEOREM_4_III,
    ROTATION_ANGLE,
    RECURSION_13,
    TWO_STEP,
    THEOREM_5,
    THEOREM_6,
    DARBOUX,
    DARBOUX_DISTANCE,
    NIKOLAIDES,
    *d4b_curvature.STATEMENTS,
)

INFO = DiscretizationInfo(
    id="d4b",
    title="Wunderlich's kinematic discrete hyperbolic cosine (D4b)",
    reference="Section 3 (D4b); Section 4.2, Theorems 4-6; Section 5, Theorems 7, 8",
    summary=(
        "A stick of length h slides with one end along the x-axis in steps of 2d; each step is a "
        "rotation, and the rotation centres p_i form the discrete hyperbolic cosine. The other end "
        "of the stick traces the discrete tractrix d_i."
    ),
    default_range=(-10, 10),
    methods=("construction", "closed-form"),
    companions={
        "tractrix": "d_i, the free end of stick i (the discrete tractrix), same indices as p",
        "axis_points": "x_i = (2di, 0), the end of stick i on the x-axis",
        "darboux": "e_i = 2d_i − x_i, the reflection of x_i in d_i (a Darboux transform of x)",
        **d4b_curvature.COMPANIONS,
    },
    constants={
        "d1": "c of (D1), Δ²p_i^y = c(l_i + l_{i+1}); equals d/h",
        "d3": "c of (D3), A_i = c l_i; equals h",
        "eq2": "c of eq. (2), Δ²p_i^y = c(A_i + A_{i+1}); equals d/h²",
    },
    statements=STATEMENTS,
)

ERRATUM_ANGLE = (
    "E1",
    "α_i is the angle at p_i between the lines to (x_i, 0) and (x_{i+1}, 0)",
    "α_i is the angle at p_i between the lines to x_{i−1} and x_i (Theorem 5's indexing, "
    "p_i^x = (2i−1)d)",
)
ERRATUM_RATIO = (
    "E2",
    "Δ²p_i^{y2}/(l_i + l_{i+1}) = Δ²p_{i+1}^{y2}/(l_{i+1} + l_{i+2}) with the proof's "
    "l_i = √(4d² + (p_i^y − p_{i−1}^y)²)",
    "Δ²p_i^y/(l_i + l_{i+1}) = Δ²p_{i+1}^y/(l_{i+1} + l_{i+2}) with l_i = |p_{i+1} − p_i| as in "
    "(D1)",
)
ERRATUM_TWO_STEP = (
    "E3",
    "d⁴(2p_i^{y3} + 2p_{i−1}^y + 3p_i^y) in the numerator of p_{i+2}^y",
    "d⁴(2p_{i−1}^y + 3p_i^y)",
)


@dataclass(frozen=True)
class D4bPolygons:
    """The polygons of one (D4b) computation, ``(n + 1, 2)`` each, on i_min .. i_max + 1.

    The extra last index only feeds checks (d_i needs p_{i+1}); responses show i_min .. i_max.
    ``p`` and ``tractrix`` come from the construction or, for ``method="closed-form"``, are the
    closed forms themselves (then ``constructed`` is false and Theorems 5, 6 are not compared).
    """

    i_min: int
    p: Array
    tractrix: Array
    axis: Array
    darboux: Array
    closed_p: Array
    closed_tractrix: Array
    constructed: bool
    gauss: d4b_curvature.GaussImages
    """Section 5: n_i, ñ_i, m_i (see ``d4b_curvature.GaussImages`` for their alignment)."""
    exponent: float = 0.0
    """Largest |(i + τ)L| of the closed forms: each closed-form vertex carries a relative error of
    about eps·exponent from rounding that argument. The comparisons with the construction allow
    for it, and so do the local checks when the polygons *are* the closed forms."""


def polygons(
    ar: Arithmetic,
    h: float,
    d: float,
    beta0: float | None,
    i_min: int,
    i_max: int,
    method: Method = "construction",
) -> D4bPolygons:
    """Construction (Section 3) and closed forms (14), (16) on i_min .. i_max + 1.

    The construction runs on the hull of 0 and i_min − 1 .. i_max + 2 (it starts at stick 0
    anyway): the Gauss image n starts at index 0, and m_i needs p_{i−1} .. p_{i+1}.
    """
    hh, dd = ar.scalar(h), ar.scalar(d)
    shift = kinematic_closed_forms.tilt_shift(ar, hh, dd, beta0)
    i = ar.indices(i_min, i_max + 1)
    closed_p = kinematic_closed_forms.hyperbolic_cosine(ar, hh, dd, i, shift)
    closed_d = kinematic_closed_forms.tractrix(ar, hh, dd, i, shift)
    if method == "construction":
        lo, hi = min(0, i_min - 1), max(0, i_max + 2)
        built = construct(ar, h, d, beta0, lo, hi)
        window = slice(i_min - lo, i_max + 2 - lo)
        p, tractrix, axis = built.centres[window], built.tractrix[window], built.axis_points[window]
        u0 = built.directions[0 - lo]
        gauss = d4b_curvature.build(
            ar,
            hh,
            dd,
            shift,
            i_min,
            i_max,
            lo,
            built.tractrix,
            (u0[0], u0[1]),
            built.centres[i_min - 1 - lo : i_max + 3 - lo],
            built.directions,
        )
    else:
        p, tractrix = closed_p, closed_d
        axis = stack_points(2 * dd * i, ar.zeros(len(i)))
        gauss = d4b_curvature.build(ar, hh, dd, shift, i_min, i_max, 0, None, None, None)
    e = darboux.reflect_in_points(axis, tractrix)
    constructed = method == "construction"
    exponent = ar.to_float(np.max(abs((i + shift) * kinematic_closed_forms.log_ratio(ar, hh, dd))))
    return D4bPolygons(
        i_min, p, tractrix, axis, e, closed_p, closed_d, constructed, gauss, exponent
    )


def conditioning(h: float, d: float) -> float:
    """κ = h²/(h² − d²): how much one step of (D4b) amplifies rounding.

    Both the construction (h − d·cos β cancels for a steep stick) and the recursion (13) (its
    denominator p_{i−1}^y p_i^y − d² can be as small as h² − d²) lose log10(κ) digits as d → h;
    the local tolerances are multiplied by κ (1.01 for d = h/10, 50 for d = 0.99h).
    """
    ratio = float(d) / float(h)
    return 1 / ((1 - ratio) * (1 + ratio))


def evaluate(
    ar: Arithmetic,
    h: float,
    d: float,
    data: D4bPolygons,
    detail: bool = False,
    beta0: float | None = None,
) -> tuple[dict[str, Scalar], list[Check]]:
    """Fitted constants and every check of ``STATEMENTS`` on the given polygons."""
    hh, dd = ar.scalar(h), ar.scalar(d)
    n = len(data.p) - 1
    indices = np.arange(data.i_min, data.i_min + n + 1, dtype=np.int64)
    p, tractrix, axis, e = data.p, data.tractrix, data.axis, data.darboux
    fits = {
        "d1": conditions.d1(ar, p[:n]),
        "d3": conditions.d3(ar, p[:n]),
        "eq2": conditions.equation_2(ar, p[:n]),
    }
    constants = {k: f.constant for k, f in fits.items() if f.constant is not None}
    local, construction, steps = tolerances(ar, h, d, data)
    ctx = _Context(ar, hh, dd, indices, n, local, detail)
    checks = [
        _hypothesis(ctx, p),
        _fitted(ctx, THEOREM_4_I, fits["d1"], _ratio_erratum(ctx, p)),
        _fitted(ctx, THEOREM_4_II, fits["d3"]),
        _equation_2(ctx, fits, p[:n]),
        _rotation_angle(ctx, p, axis),
        _recursion(ctx, p),
        _two_step(ctx, p),
        _closed_form(ctx, THEOREM_5, data.constructed, p, data.closed_p, steps),
        _closed_form(
            ctx,
            THEOREM_6,
            data.constructed,
            tractrix,
            data.closed_tractrix,
            steps,
            abs(axis[:, 0]) + hh,  # d_i = x_i + h u_i: the terms' magnitude
        ),
        ctx.check(DARBOUX, 0, darboux.edge_length_residuals(ar, axis[:n], e[:n])),
        ctx.check(DARBOUX_DISTANCE, 0, darboux.distance_residuals(ar, axis[:n], e[:n], 2 * hh)),
        _nikolaides(ctx, p, tractrix, axis),
    ]
    shift = kinematic_closed_forms.tilt_shift(ar, hh, dd, beta0)
    checks += d4b_curvature.evaluate(
        ar,
        hh,
        p,
        tractrix,
        data.gauss,
        d4b_curvature.printed_forms(ar, hh, dd, shift, data.i_min, data.i_min + n - 1),
        indices,
        n,
        ctx.tolerance,
        construction,
        detail,
    )
    return constants, checks


def tolerances(ar: Arithmetic, h: float, d: float, data: D4bPolygons) -> tuple[float, float, int]:
    """(local tolerance, construction tolerance, construction steps) of one computation.

    Local: a check on a few neighbouring vertices, times the conditioning κ (and the closed
    forms' own rounding when the polygons are the closed forms). Construction: comparisons
    along the whole recursion from stick 0.
    """
    n = len(data.p) - 1
    rounding = 4 * math.ceil(data.exponent)  # steps' worth of the closed forms' own rounding
    kappa = conditioning(h, d)
    local = kappa * ar.tolerance(LOCAL_STEPS + (0 if data.constructed else rounding))
    steps = max(abs(data.i_min - 1), abs(data.i_min + n)) + 1 + rounding
    return local, ar.tolerance(max(steps, LOCAL_STEPS)), steps


def compute(
    ar: Arithmetic,
    h: float = 1.0,
    d: float = 0.1,
    beta0: float | None = None,
    i_min: int = -10,
    i_max: int = 10,
    method: Method = "construction",
    detail: bool = False,
) -> Curve:
    """(D4b) on i_min .. i_max with its companions, constants and checks."""
    validate(h, d, beta0)
    require_range(i_min, i_max)
    _require_resolvable(ar, h, d)
    if ar.mode == "float64":
        _require_float64_representable(h, d, beta0, i_min, i_max)
    data = polygons(ar, h, d, beta0, i_min, i_max, method)
    constants, checks = evaluate(ar, h, d, data, detail, beta0)
    local, construction, _ = tolerances(ar, h, d, data)
    parameters: dict[str, Any] = {
        "h": h,
        "d": d,
        "beta0": math.pi / 2 if beta0 is None else beta0,
        "i_min": i_min,
        "i_max": i_max,
        "method": method,
    }

    companions = {
        "tractrix": data.tractrix,
        "axis_points": data.axis,
        "darboux": data.darboux,
        "tractrix_gauss_image": data.gauss.tractrix_gauss,
        "contact_points": data.gauss.contact[1:],
        "gauss_image": data.gauss.gauss,
    }
    return INFO.curve(
        ar,
        parameters,
        data.p,
        companions,
        constants=constants,
        checks=checks,
        local_tolerance=local,
        companion_tolerances=d4b_curvature.companion_tolerances(ar, data.gauss, construction),
    )


class _Context:
    """What every check of one computation shares."""

    def __init__(
        self,
        ar: Arithmetic,
        h: Scalar,
        d: Scalar,
        indices: np.ndarray[Any, np.dtype[np.int64]],
        n: int,
        tolerance: float,
        detail: bool,
    ) -> None:
        self.ar, self.h, self.d = ar, h, d
        self.indices, self.n = indices, n
        self.tolerance, self.detail = tolerance, detail

    def check(
        self,
        statement: Statement,
        first: int,
        residuals: Array,
        erratum: Erratum | None = None,
        factor: int = 1,
    ) -> Check:
        """A check whose k-th residual belongs to index ``indices[first + k]``.

        ``factor`` widens the local tolerance for formulas with several times the usual number
        of operations and vertices.
        """
        idx = self.indices[first : first + len(residuals)]
        tolerance = self.tolerance * factor
        return check_residuals(statement, self.ar, idx, residuals, tolerance, self.detail, erratum)


def _hypothesis(ctx: _Context, p: Array) -> Check:
    y = p[: ctx.n, 1]
    d2 = ctx.d * ctx.d
    products = y[:-1] * y[1:]
    violation = np.maximum(d2 - products, ctx.ar.scalar(0)) / d2
    check = ctx.check(HYPOTHESIS, 1, violation)
    if len(products):
        smallest = ctx.ar.to_float(np.min(products / d2))
        return replace(check, note=f"smallest p_(i-1)^y p_i^y / d² = {smallest:.6g}")
    return check


def _fitted(
    ctx: _Context,
    statement: Statement,
    fit: conditions.ConditionFit,
    erratum: Erratum | None = None,
) -> Check:
    check = ctx.check(statement, 0, fit.residuals, erratum)
    if fit.constant is not None and not fit.constant > 0 and check.holds:
        return replace(check, holds=False, note="the fitted constant is not > 0")
    return check


def _equation_2(ctx: _Context, fits: dict[str, conditions.ConditionFit], p: Array) -> Check:
    """(2) with the fitted c and with c = c_(D1)/c_(D3), both residuals measured alike.

    Comparing the constants themselves would ask more than the data resolve: a constant fitted
    to second differences is known only to eps·|y|/|Δ²y| relative, about eps·(h/d)², while the
    equation's residual stays relative to the magnitude of the numbers it is computed from.
    """
    c, c1, c2 = (fits[k].constant for k in ("eq2", "d1", "d3"))
    residuals = fits["eq2"].residuals
    if c1 is not None and c2 is not None and c2 != 0 and len(residuals):
        residuals = np.maximum(residuals, conditions.equation_2_misfit(ctx.ar, p, c1 / c2))
    return _fitted(ctx, THEOREM_4_III, conditions.ConditionFit(c, residuals))


def _ratio_erratum(ctx: _Context, p: Array) -> Erratum | None:
    """The proof's ratio with its own l_i = |p_i − p_{i−1}|: not constant along the polygon."""
    y = p[:, 1]
    ar = ctx.ar
    lengths = ar.hypot(p[1:, 0] - p[:-1, 0], y[1:] - y[:-1])  # lengths[k] = |p_{k+1} − p_k|
    # printed: Δ²p_i^y / (l'_i + l'_{i+1}) with l'_i = |p_i − p_{i−1}|, for i with p_{i−1} known
    ratio = (y[3:] - 2 * y[2:-1] + y[1:-2]) / (lengths[:-2] + lengths[1:-1])
    if len(ratio) < 2:
        return Erratum(*ERRATUM_RATIO, printed_residual=None)
    spread = relative_difference(ar, ratio, np.full_like(ratio, np.sum(ratio) / len(ratio)))
    return Erratum(*ERRATUM_RATIO, printed_residual=printed_residual(ar, spread))


def _rotation_angle(ctx: _Context, p: Array, axis: Array) -> Check:
    ar, n = ctx.ar, ctx.n
    a = axis[: n - 1] - p[1:n]  # x_{i−1} − p_i
    b = axis[1:n] - p[1:n]  # x_i − p_i
    angle = _signed_angle(ar, a, b)
    formula = 2 * ar.atan2(ctx.d, p[1:n, 1])
    # printed indexing: the angle at p_i between x_i and x_{i+1}
    printed = _signed_angle(ar, axis[1:n] - p[1:n], axis[2 : n + 1] - p[1:n])
    erratum = Erratum(*ERRATUM_ANGLE, printed_residual=printed_residual(ar, abs(printed - formula)))
    return ctx.check(ROTATION_ANGLE, 1, abs(angle - formula), erratum)


def _signed_angle(ar: Arithmetic, a: Array, b: Array) -> Array:
    """The angle turning vector a_k into b_k, in (−π, π]; ``(n, 2) -> (n,)``."""
    cross = a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]
    return ar.atan2(cross, a[:, 0] * b[:, 0] + a[:, 1] * b[:, 1])


def _recursion(ctx: _Context, p: Array) -> Check:
    y = p[:, 1]
    predicted = kinematic_closed_forms.recursion_13(ctx.d, y[:-2], y[1:-1])
    return ctx.check(RECURSION_13, 1, relative_difference(ctx.ar, y[2:], predicted))


def _two_step(ctx: _Context, p: Array) -> Check:
    y = p[:, 1]
    ar = ctx.ar
    corrected = kinematic_closed_forms.two_step(ctx.d, y[:-3], y[1:-2])
    erratum = None
    if ar.mode == "mp" or float(np.max(abs(y))) < 1e60:  # the printed form has 7th powers
        printed = kinematic_closed_forms.two_step_printed(ctx.d, y[:-3], y[1:-2])
        erratum = Erratum(
            *ERRATUM_TWO_STEP,
            printed_residual=printed_residual(ar, relative_difference(ar, y[3:], printed)),
        )
    else:
        erratum = Erratum(*ERRATUM_TWO_STEP, printed_residual=None)
    # (13) twice: three vertices and about three times the operations of a local check
    return ctx.check(TWO_STEP, 1, relative_difference(ar, y[3:], corrected), erratum, factor=3)


def _closed_form(
    ctx: _Context,
    statement: Statement,
    constructed: bool,
    computed: Array,
    closed: Array,
    steps: int,
    scale: Array | None = None,
) -> Check:
    """Construction against closed form; the construction's rounding grows with its steps.

    ``scale`` (per vertex) replaces |closed form| as the magnitude the difference is measured
    against where the vertex is a difference of larger terms: d_i = x_i + h·u_i is computed to
    a few units of |x_i| + h, and its x-coordinate vanishes (|d_i| → 0) near β0 → 0 or π, where
    a difference relative to |d_i| reported errors of 1e-7 for points right to 1e-16 (issue 15).
    """
    tolerance = conditioning(ctx.h, ctx.d) * ctx.ar.tolerance(max(steps, LOCAL_STEPS))
    if not constructed:
        return not_applicable(
            statement, tolerance, "method=closed-form: the construction was not run to compare"
        )
    if scale is None:
        residuals = relative_point_difference(ctx.ar, computed[: ctx.n], closed[: ctx.n])
    else:
        difference = point_distance(ctx.ar, computed[: ctx.n], closed[: ctx.n])
        residuals = relative_to(ctx.ar, difference, scale[: ctx.n])
    return check_residuals(
        statement, ctx.ar, ctx.indices[: ctx.n], residuals, tolerance, ctx.detail
    )


def _nikolaides(ctx: _Context, p: Array, tractrix: Array, axis: Array) -> Check:
    n = ctx.n
    at_p = nikolaides.right_angle_residuals(tractrix[:n], axis[:n], p[:n])
    at_next = nikolaides.right_angle_residuals(tractrix[:n], axis[:n], p[1 : n + 1])
    return ctx.check(NIKOLAIDES, 0, np.maximum(at_p, at_next))


def _require_resolvable(ar: Arithmetic, h: float, d: float) -> None:
    """Refuse steps so small that Δ²p^y vanishes in the working precision."""
    smallest = RESOLUTION_MARGIN * math.sqrt(ar.working_eps)
    if d / h < smallest:
        more = "use precision=mp" if ar.mode == "float64" else "use more digits"
        raise NotRepresentableError(
            "d",
            f"d/h >= {smallest:.2g} in {ar.mode} with {ar.digits} digits",
            d,
            f"d/h = {d / h:.3g}: the second differences of p^y are below the working "
            f"precision; {more}",
        )


def _require_float64_representable(
    h: float, d: float, beta0: float | None, i_min: int, i_max: int
) -> None:
    """Refuse, before computing, ranges whose coordinates leave the float64 limits."""
    L = math.log1p(2 * d / (h - d))
    tan_half = 1.0 if beta0 is None else math.tan(beta0 / 2)
    if not 0 < tan_half < math.inf:  # β0 within a subnormal of 0
        raise NotRepresentableError(
            "beta0", "a first stick steep enough for float64", beta0, "use precision=mp"
        )
    tau = math.log(tan_half) / L
    budget = math.log(FLOAT64_COORDINATE_LIMIT) - max(0.0, math.log(h))
    largest = math.floor(budget / L - abs(tau) - 1.5)  # |i + 1 − ½ + τ|·L within the budget
    if largest < 0:
        raise NotRepresentableError(
            "beta0",
            "a first stick steep enough for float64",
            beta0,
            f"p_0^y would exceed {FLOAT64_COORDINATE_LIMIT:g}; use precision=mp",
        )
    for name, value in (("i_max", i_max), ("i_min", i_min)):
        if abs(value) > largest:
            raise NotRepresentableError(
                name,
                f"|{name}| <= {largest} in float64",
                value,
                f"beyond it p_i^y exceeds {FLOAT64_COORDINATE_LIMIT:g}; use precision=mp",
            )
