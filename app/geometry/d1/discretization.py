"""(D1) the hanging chain of sticks, with (D3), eq. (2) and the closed form checked on it.

The polygon comes from the difference equation (``hanging_chain``) by default, or from its
closed form (``hanging_chain_closed_forms``) with ``method="closed-form"``. A (D1) polygon is a
sampled catenary shifted by an offset C; it satisfies (D3) and eq. (2) exactly when C = 0, so
for most starts those checks come out false, with their best constants and residuals.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Literal

import numpy as np

from app.geometry import properties
from app.geometry.catalog.section3 import (
    D1_CLOSED_FORM as CLOSED_FORM,
)
from app.geometry.checks import Check, Statement, check_residuals, not_applicable, point_distance
from app.geometry.curve import EVERYTHING, Curve, DiscretizationInfo, Selection, require_range
from app.geometry.d1 import closed_forms
from app.geometry.d1.construction import construct, validate
from app.geometry.errors import NotRepresentableError
from app.geometry.precision import Arithmetic, Array, Scalar
from app.geometry.tolerances import FLOAT64_COORDINATE_LIMIT, LOCAL_STEPS, NOT_CONSTRUCTED

Method = Literal["construction", "closed-form"]


STATEMENTS: tuple[Statement, ...] = (*properties.PROPERTIES, CLOSED_FORM)

INFO = DiscretizationInfo(
    id="d1",
    title="Hanging chain of sticks: the difference equation (D1)",
    reference="Section 3 (D1)",
    summary=(
        "The polygon with constant x-spacing delta whose second difference of heights is c times "
        "the sum of its two edge lengths, from the heights y0, y1 of p_0 and p_1: the "
        "equilibrium of homogeneous sticks hanging from hinges. Each step solves a quadratic."
    ),
    default_range=(-10, 10),
    methods=("construction", "closed-form"),
    companions={},
    constants={
        "d1": "c of (D1), Δ²p_i^y = c(l_i + l_{i+1}); equals the parameter c",
        "d3": "best c of (D3), A_i = c l_i; (D3) holds, with delta/(2c), only when the offset "
        "C of the closed form is 0",
        "eq2": "best c of eq. (2), Δ²p_i^y = c(A_i + A_{i+1}); holds, with 2c²/delta, only when "
        "C = 0",
        "equilibrium": "c of the hanging-sticks equilibrium k_{i+1} − k_i = c(l_i + l_{i+1}); "
        "equals c/delta",
    },
    statements=STATEMENTS,
)


@dataclass(frozen=True)
class D1Polygons:
    """One (D1) computation on i_min .. i_max: the polygon and its closed form, ``(n, 2)``."""

    i_min: int
    p: Array
    closed: Array
    closed_size: Array
    """|iδ| + |y_0| + |2a sinh(iE/2) sinh(u_0 + (i − 1)E/2)| per vertex (the terms)."""
    constructed: bool


def polygons(
    ar: Arithmetic,
    c: float,
    delta: float,
    y0: float,
    y1: float,
    i_min: int,
    i_max: int,
    method: Method = "construction",
) -> D1Polygons:
    """The construction (Section 3) and the closed form on i_min .. i_max."""
    validate(c, delta, y0, y1)
    i = ar.indices(i_min, i_max)
    closed, size = closed_forms.hyperbolic_cosine(
        ar, ar.scalar(c), ar.scalar(delta), ar.scalar(y0), ar.scalar(y1), i
    )
    if method == "construction":
        p = construct(ar, c, delta, y0, y1, i_min, i_max).vertices
    else:
        p = closed
    return D1Polygons(i_min, p, closed, size, constructed=method == "construction")


def evaluate(
    ar: Arithmetic,
    c: float,
    delta: float,
    y0: float,
    y1: float,
    data: D1Polygons,
    detail: bool = False,
) -> tuple[dict[str, Scalar], list[Check]]:
    """Fitted constants and every check of ``STATEMENTS`` on the given polygons."""
    n = len(data.p)
    ctx = properties.Context(ar, np.arange(data.i_min, data.i_min + n, dtype=np.int64), detail)
    found = properties.fits(ar, data.p)
    k = closed_forms.parameters(ar, ar.scalar(c), ar.scalar(delta), ar.scalar(y0), ar.scalar(y1))
    offset = ar.to_float(k.offset)
    expected = {
        "d1": f"(D1) holds with c = {c!r}",
        "d3": f"(D3) holds exactly when the offset C = y0 − a cosh(u_0 − E/2) is 0; here "
        f"C = {offset:.12g}",
        "equation-2": f"eq. (2) holds exactly when C = 0; here C = {offset:.12g}",
        "hanging-sticks": f"constant x-spacing: holds with c/delta = {c / delta:.12g}",
    }
    checks = properties.checks(ctx, found, expected)
    steps = max(abs(data.i_min), abs(data.i_min + n - 1)) + 1
    checks.append(_closed_form(ctx, data, steps))
    return properties.constants(found), checks


def compute(
    ar: Arithmetic,
    c: float = 0.1,
    delta: float = 0.2,
    y0: float = 1.0,
    y1: float = 1.0,
    i_min: int = -10,
    i_max: int = 10,
    method: Method = "construction",
    detail: bool = False,
    selection: Selection = EVERYTHING,
) -> Curve:
    """(D1) on i_min .. i_max with its constants and checks."""
    validate(c, delta, y0, y1)
    require_range(i_min, i_max)
    if ar.mode == "float64":
        _require_float64_representable(c, delta, y0, y1, i_min, i_max)
    data = polygons(ar, c, delta, y0, y1, i_min, i_max, method)
    constants, checks = evaluate(ar, c, delta, y0, y1, data, detail)
    parameters: dict[str, Any] = {
        "c": c,
        "delta": delta,
        "y0": y0,
        "y1": y1,
        "i_min": i_min,
        "i_max": i_max,
        "method": method,
    }
    return INFO.curve(
        ar, parameters, data.p, constants=constants, checks=checks, selection=selection
    )


def _closed_form(ctx: properties.Context, data: D1Polygons, steps: int) -> Check:
    """Construction against closed form; the construction's rounding grows with its steps."""
    ar = ctx.ar
    tolerance = ar.tolerance(max(steps, LOCAL_STEPS))
    if not data.constructed:
        return not_applicable(CLOSED_FORM, tolerance, NOT_CONSTRUCTED)
    tiny = ar.scalar(np.finfo(np.float64).tiny)
    size = np.where(data.closed_size > tiny, data.closed_size, tiny)  # p_0 = (0, 0): absolute
    residuals = point_distance(ar, data.p, data.closed) / size
    return check_residuals(CLOSED_FORM, ar, ctx.indices, residuals, tolerance, ctx.detail)


def _require_float64_representable(
    c: float, delta: float, y0: float, y1: float, i_min: int, i_max: int
) -> None:
    """Refuse, before computing, ranges whose heights would leave the float64 limits.

    |y_i| <= |y0| + n δ cosh(|u_0| + nE) with n = max(|i_min|, |i_max|) + 1 steps from p_0
    (each slope is sinh of an angle growing by E = 2 artanh c per edge).
    """
    if delta / (2 * c) > FLOAT64_COORDINATE_LIMIT:
        raise NotRepresentableError(
            "c",
            f"delta/(2c) <= {FLOAT64_COORDINATE_LIMIT:g} in float64",
            c,
            "the closed form's amplitude a = delta·√(1 − c²)/(2c) leaves the float64 range; "
            "use precision=mp",
        )
    slope = (y1 - y0) / delta
    if not math.isfinite(slope) or abs(slope) > FLOAT64_COORDINATE_LIMIT:
        raise NotRepresentableError(
            "y1",
            f"|y1 − y0|/delta <= {FLOAT64_COORDINATE_LIMIT:g} in float64",
            y1,
            "the first edge is too steep for float64; use precision=mp",
        )
    E = 2 * math.atanh(c)
    u0 = abs(math.asinh(slope))
    budget = math.log(FLOAT64_COORDINATE_LIMIT)
    largest = _largest_index(delta, u0, E, y0, budget)
    if largest < 1:
        raise NotRepresentableError(
            "y1",
            "a first edge whose chain stays below 1e150 for two steps in float64",
            y1,
            "the heights leave the float64 range at once; use precision=mp",
        )
    for name, value in (("i_max", i_max), ("i_min", i_min)):
        if abs(value) > largest:
            raise NotRepresentableError(
                name,
                f"|{name}| <= {largest} in float64",
                value,
                f"beyond it the heights may exceed {FLOAT64_COORDINATE_LIMIT:g}; use precision=mp",
            )


def _largest_index(delta: float, u0: float, E: float, y0: float, budget: float) -> int:
    """The largest |i| that passes the bound of ``_require_float64_representable``."""
    lo, hi = -1, 10**8
    while lo < hi:
        mid = (lo + hi + 1) // 2
        n = mid + 1
        bound = max(math.log(abs(y0)) if y0 else -math.inf, math.log(n * delta) + u0 + n * E)
        if bound + math.log(2) <= budget:
            lo = mid
        else:
            hi = mid - 1
    return lo
