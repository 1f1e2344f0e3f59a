"""(D1) the hanging chain of sticks, with (D3), eq. (2) and the closed form checked on it.

The polygon comes from the difference equation (``hanging_chain``) by default, or from its
closed form (``hanging_chain_closed_forms``) with ``method="closed-form"``. A (D1) polygon is a
sampled catenary shifted by an offset C; it satisfies (D3) and eq. (2) exactly when C = 0, so
for most starts those checks come out false, with their best constants and residuals.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property
from typing import Any, Literal

import numpy as np

from app.geometry import properties
from app.geometry.catalog.section3 import (
    D1,
    D1_CLOSED_FORM as CLOSED_FORM,
    D3,
    HANGING_STICKS,
)
from app.geometry.catalog.section4 import EQUATION_2
from app.geometry.checks import Check, Statement, check_residuals, not_applicable, point_distance
from app.geometry.curve import EVERYTHING, Curve, DiscretizationInfo, Selection, require_range
from app.geometry.d1 import closed_forms
from app.geometry.d1.construction import construct, validate
from app.geometry.errors import NotRepresentableError
from app.geometry.on_demand import Evaluators, OnDemand
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
class D1Polygons(OnDemand):
    """One (D1) computation on i_min .. i_max: the polygon ``(n, 2)``, and its closed form when
    first read."""

    ar: Arithmetic
    parameters: tuple[float, float, float, float]
    """c, delta, y0, y1."""
    i_min: int
    p: Array
    constructed: bool

    @cached_property
    def _closed(self) -> tuple[Array, Array]:
        return _explicit(self.ar, self.parameters, self.i_min, self.i_min + len(self.p) - 1)

    @property
    def closed(self) -> Array:
        """The closed form p_i of (D1) (Section 3)."""
        return self._closed[0]

    @property
    def closed_size(self) -> Array:
        """|iδ| + |y_0| + |2a sinh(iE/2) sinh(u_0 + (i − 1)E/2)| per vertex (the terms)."""
        return self._closed[1]


def _explicit(
    ar: Arithmetic, parameters: tuple[float, float, float, float], i_min: int, i_max: int
) -> tuple[Array, Array]:
    c, delta, y0, y1 = (ar.scalar(v) for v in parameters)
    return closed_forms.hyperbolic_cosine(ar, c, delta, y0, y1, ar.indices(i_min, i_max))


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
    """The construction (Section 3), or the closed form, on i_min .. i_max."""
    validate(c, delta, y0, y1)
    parameters = (c, delta, y0, y1)
    if method == "construction":
        p = construct(ar, c, delta, y0, y1, i_min, i_max).vertices
        return D1Polygons(ar, parameters, i_min, p, constructed=True)
    closed = _explicit(ar, parameters, i_min, i_max)
    data = D1Polygons(ar, parameters, i_min, closed[0], constructed=False)
    data.__dict__["_closed"] = closed
    return data


class _Context(properties.Context):
    """What the checks of one (D1) computation share, each part computed when first needed."""

    def __init__(self, ar: Arithmetic, data: D1Polygons, detail: bool) -> None:
        indices = np.arange(data.i_min, data.i_min + len(data.p), dtype=np.int64)
        super().__init__(ar, indices, detail, data.p)
        self.data = data
        self.c, self.delta, self.y0, self.y1 = data.parameters

    @cached_property
    def offset(self) -> float:
        """C = y0 − a cosh(u_0 − E/2), the closed form's offset."""
        ar = self.ar
        c, delta, y0, y1 = (ar.scalar(v) for v in self.data.parameters)
        k = closed_forms.parameters(ar, c, delta, y0, y1)
        return ar.to_float(k.offset)


def evaluate(
    ar: Arithmetic,
    data: D1Polygons,
    detail: bool = False,
    selection: Selection = EVERYTHING,
) -> tuple[dict[str, Scalar], list[Check]]:
    """Fitted constants and the selected checks of ``STATEMENTS`` on the given polygons.

    Each check computes only the fits and closed forms it needs; the constants are those of the
    fits computed.
    """
    ctx = _Context(ar, data, detail)
    checks = selection.evaluate(ctx, _EVALUATORS)
    return ctx.fits.constants() if ctx.computed("fits") else {}, checks


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
    constants, checks = evaluate(ar, data, detail, selection)
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


def _closed_form(ctx: _Context) -> Check:
    """Construction against closed form; the construction's rounding grows with its steps."""
    ar, data = ctx.ar, ctx.data
    steps = max(abs(data.i_min), abs(data.i_min + len(data.p) - 1)) + 1
    tolerance = ar.tolerance(max(steps, LOCAL_STEPS))
    if not data.constructed:
        return not_applicable(CLOSED_FORM, tolerance, NOT_CONSTRUCTED)
    tiny = ar.scalar(np.finfo(np.float64).tiny)
    size = np.where(data.closed_size > tiny, data.closed_size, tiny)  # p_0 = (0, 0): absolute
    residuals = point_distance(ar, data.p, data.closed) / size
    return check_residuals(CLOSED_FORM, ar, ctx.indices, residuals, tolerance, ctx.detail)


#: Each statement about (D1) and the function that checks it, in the order of the response.
_EVALUATORS: Evaluators[_Context] = (
    (D1, lambda x: x.property_check(D1, f"(D1) holds with c = {x.c!r}")),
    (
        D3,
        lambda x: x.property_check(
            D3,
            f"(D3) holds exactly when the offset C = y0 − a cosh(u_0 − E/2) is 0; here "
            f"C = {x.offset:.12g}",
        ),
    ),
    (
        EQUATION_2,
        lambda x: x.property_check(
            EQUATION_2, f"eq. (2) holds exactly when C = 0; here C = {x.offset:.12g}"
        ),
    ),
    (
        HANGING_STICKS,
        lambda x: x.property_check(
            HANGING_STICKS, f"constant x-spacing: holds with c/delta = {x.c / x.delta:.12g}"
        ),
    ),
    (CLOSED_FORM, _closed_form),
)


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
