"""(D3) the area–length polygon, with (D1), eq. (2) and the closed form checked on it.

The polygon comes from the area–length condition (``area_length``) by default, or from its
closed form (``area_length_closed_forms``) with ``method="closed-form"``. With constant spacing
a (D3) polygon that never folds back is a sampled catenary without offset, so it also satisfies
(D1) with delta/(2c) and eq. (2) with delta/(2c²): (D3) implies (D1), while (D1) implies (D3)
only for offset 0 (see the d1 discretization).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Literal

import numpy as np

from app.geometry import properties
from app.geometry.catalog import section3, section4
from app.geometry.catalog.section3 import (
    D3_CLOSED_FORM as CLOSED_FORM,
)
from app.geometry.checks import (
    Check,
    Statement,
    check_residuals,
    not_applicable,
    relative_point_difference,
)
from app.geometry.curve import EVERYTHING, Curve, DiscretizationInfo, Selection, require_range
from app.geometry.d3 import closed_forms
from app.geometry.d3.construction import Branch, construct, validate
from app.geometry.errors import NotRepresentableError
from app.geometry.precision import Arithmetic, Array, Scalar
from app.geometry.tolerances import FLOAT64_COORDINATE_LIMIT, LOCAL_STEPS, NOT_CONSTRUCTED

Method = Literal["construction", "closed-form"]


STATEMENTS: tuple[Statement, ...] = (
    section3.D3,
    section3.D1,
    section4.EQUATION_2,
    section3.HANGING_STICKS,
    CLOSED_FORM,
)

INFO = DiscretizationInfo(
    id="d3",
    title="Area equals c times length: the area–length polygon (D3)",
    reference="Section 3 (D3)",
    summary=(
        "The polygon with constant x-spacing delta in which the area under every edge is c "
        "times the edge's length, from the height y0 of p_0; branch chooses the first step "
        "(each step solves a quadratic whose two roots are the two directions along a "
        "catenary)."
    ),
    default_range=(-10, 10),
    methods=("construction", "closed-form"),
    companions={},
    constants={
        "d3": "c of (D3), A_i = c l_i; equals the parameter c",
        "d1": "c of (D1), Δ²p_i^y = c(l_i + l_{i+1}); equals delta/(2c)",
        "eq2": "c of eq. (2), Δ²p_i^y = c(A_i + A_{i+1}); equals delta/(2c²)",
        "equilibrium": "c of the hanging-sticks equilibrium; equals 1/(2c)",
    },
    statements=STATEMENTS,
)


@dataclass(frozen=True)
class D3Polygons:
    """One (D3) computation on i_min .. i_max: the polygon and its closed form, ``(n, 2)``."""

    i_min: int
    p: Array
    closed: Array
    constructed: bool
    start: float = math.inf
    """y0: the walk (and the closed form's arcosh(y0/a)) starts there even when index 0 is not
    in the range shown."""


def polygons(
    ar: Arithmetic,
    c: float,
    delta: float,
    y0: float,
    branch: Branch,
    i_min: int,
    i_max: int,
    method: Method = "construction",
) -> D3Polygons:
    """The construction (Section 3) and the closed form on i_min .. i_max."""
    validate(c, delta, y0, branch)
    i = ar.indices(i_min, i_max)
    closed = closed_forms.hyperbolic_cosine(
        ar, ar.scalar(c), ar.scalar(delta), ar.scalar(y0), branch == "up", i
    )
    if method == "construction":
        p = construct(ar, c, delta, y0, branch, i_min, i_max).vertices
    else:
        p = closed
    return D3Polygons(i_min, p, closed, constructed=method == "construction", start=y0)


def evaluate(
    ar: Arithmetic,
    c: float,
    delta: float,
    data: D3Polygons,
    detail: bool = False,
) -> tuple[dict[str, Scalar], list[Check]]:
    """Fitted constants and every check of ``STATEMENTS`` on the given polygons."""
    n = len(data.p)
    ctx = properties.Context(ar, np.arange(data.i_min, data.i_min + n, dtype=np.int64), detail)
    found = properties.fits(ar, data.p)
    expected = {
        "d3": f"(D3) holds with c = {c!r}",
        "d1": f"(D3) implies (D1) here, with delta/(2c) = {delta / (2 * c):.12g}",
        "equation-2": f"holds with delta/(2c²) = {delta / (2 * c * c):.12g}",
        "hanging-sticks": f"constant x-spacing: holds with 1/(2c) = {1 / (2 * c):.12g}",
    }
    by_id = {check.id: check for check in properties.checks(ctx, found, expected)}
    checks = [by_id[statement.id] for statement in STATEMENTS if statement.id in by_id]
    steps = max(abs(data.i_min), abs(data.i_min + n - 1)) + 1
    checks.append(_closed_form(ctx, c, delta, data, steps))
    return properties.constants(found), checks


def compute(
    ar: Arithmetic,
    c: float = 1.0,
    delta: float = 0.2,
    y0: float = 1.0,
    branch: Branch = "up",
    i_min: int = -10,
    i_max: int = 10,
    method: Method = "construction",
    detail: bool = False,
    selection: Selection = EVERYTHING,
) -> Curve:
    """(D3) on i_min .. i_max with its constants and checks."""
    validate(c, delta, y0, branch)
    require_range(i_min, i_max)
    if ar.mode == "float64":
        _require_float64_representable(c, delta, y0, i_min, i_max)
    data = polygons(ar, c, delta, y0, branch, i_min, i_max, method)
    constants, checks = evaluate(ar, c, delta, data, detail)
    parameters: dict[str, Any] = {
        "c": c,
        "delta": delta,
        "y0": y0,
        "branch": branch,
        "i_min": i_min,
        "i_max": i_max,
        "method": method,
    }
    return INFO.curve(
        ar, parameters, data.p, constants=constants, checks=checks, selection=selection
    )


def _closed_form(
    ctx: properties.Context, c: float, delta: float, data: D3Polygons, steps: int
) -> Check:
    """Construction against closed form.

    Rounding grows along the construction (``steps``), and where the polygon passes close to
    its lowest point a (argument v of the catenary near 0) both the step and the closed form's
    arcosh(y_0/a) turn a rounding error into about 1/v of them: the tolerance allows
    steps · max(1, 1/v_min), v_min = arcosh(min(y_0, min y_i) / a) (at least √eps).
    """
    ar = ctx.ar
    a = closed_forms.amplitude(ar, ar.scalar(c), ar.scalar(delta))
    ratio = min(np.min(data.p[:, 1]), ar.scalar(data.start)) / a
    v_min = ar.to_float(ar.acosh(ratio)) if ratio > 1 else 0.0
    amplification = math.ceil(1 / max(v_min, math.sqrt(ar.eps), 1e-300))
    amplification = max(1, amplification)
    tolerance = ar.tolerance(max(steps, LOCAL_STEPS) * amplification)
    note = (
        f"the polygon passes within v = {v_min:.3g} of its lowest point (argument of the "
        f"catenary), where rounding grows about 1/v times; the tolerance allows it"
        if amplification > 1
        else None
    )
    if not data.constructed:
        return not_applicable(CLOSED_FORM, tolerance, NOT_CONSTRUCTED)
    residuals = relative_point_difference(ar, data.p, data.closed)
    return check_residuals(
        CLOSED_FORM, ar, ctx.indices, residuals, tolerance, ctx.detail, note=note
    )


def _require_float64_representable(
    c: float, delta: float, y0: float, i_min: int, i_max: int
) -> None:
    """Refuse, before computing, ranges whose heights would leave the float64 limits.

    y_i = a cosh(v_0 ± 2iD) <= a e^{v_0} e^{2D|i|} <= 2 y0 e^{2D|i|}.
    """
    D = math.atanh(delta / (2 * c))
    budget = math.log(FLOAT64_COORDINATE_LIMIT) - math.log(2 * y0)  # y0 >= a > 0
    largest = math.floor(budget / (2 * D)) if D > 0 else 10**9
    for name, value in (("i_max", i_max), ("i_min", i_min)):
        if abs(value) > largest:
            raise NotRepresentableError(
                name,
                f"|{name}| <= {largest} in float64",
                value,
                f"beyond it the heights exceed {FLOAT64_COORDINATE_LIMIT:g}; use precision=mp",
            )
