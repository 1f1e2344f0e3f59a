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
from functools import cached_property
from typing import Any, Literal

import numpy as np

from app.geometry import properties
from app.geometry.catalog.section3 import (
    D1,
    D3,
    D3_CLOSED_FORM as CLOSED_FORM,
    HANGING_STICKS,
)
from app.geometry.catalog.section4 import EQUATION_2
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
from app.geometry.on_demand import Evaluators, OnDemand
from app.geometry.precision import Arithmetic, Array, Scalar
from app.geometry.tolerances import (
    FLOAT64_COORDINATE_LIMIT,
    LOCAL_STEPS,
    NOT_CONSTRUCTED,
    unit,
)

Method = Literal["construction", "closed-form"]


STATEMENTS: tuple[Statement, ...] = (
    D3,
    D1,
    EQUATION_2,
    HANGING_STICKS,
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
class D3Polygons(OnDemand):
    """One (D3) computation on i_min .. i_max: the polygon ``(n, 2)``, and its closed form when
    first read."""

    ar: Arithmetic
    parameters: tuple[float, float, float, Branch]
    """c, delta, y0, branch: the walk (and the closed form's arcosh(y0/a)) starts at y0 even
    when index 0 is not in the range shown."""
    i_min: int
    p: Array
    constructed: bool

    @property
    def start(self) -> float:
        """y0."""
        return self.parameters[2]

    @cached_property
    def closed(self) -> Array:
        """The closed form p_i of (D3) (Section 3)."""
        return _explicit(self.ar, *self.parameters, self.i_min, self.i_min + len(self.p) - 1)


def _explicit(
    ar: Arithmetic, c: float, delta: float, y0: float, branch: Branch, i_min: int, i_max: int
) -> Array:
    i = ar.indices(i_min, i_max)
    return closed_forms.hyperbolic_cosine(
        ar, ar.scalar(c), ar.scalar(delta), ar.scalar(y0), branch == "up", i
    )


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
    """The construction (Section 3), or the closed form, on i_min .. i_max."""
    validate(c, delta, y0, branch)
    parameters = (c, delta, y0, branch)
    if method == "construction":
        p = construct(ar, c, delta, y0, branch, i_min, i_max).vertices
    else:
        p = _explicit(ar, *parameters, i_min, i_max)
    return D3Polygons(ar, parameters, i_min, p, constructed=method == "construction")


class _Context(properties.Context):
    """What the checks of one (D3) computation share, each part computed when first needed."""

    def __init__(self, ar: Arithmetic, data: D3Polygons, detail: bool) -> None:
        indices = np.arange(data.i_min, data.i_min + len(data.p), dtype=np.int64)
        super().__init__(ar, indices, detail, data.p)
        self.data = data
        self.c, self.delta = data.parameters[:2]


def evaluate(
    ar: Arithmetic,
    data: D3Polygons,
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
    constants, checks = evaluate(ar, data, detail, selection)
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


def _closed_form(ctx: _Context) -> Check:
    """Construction against closed form.

    Rounding grows along the construction (``steps``), and where the polygon passes close to
    its lowest point a (argument v of the catenary near 0) both the step and the closed form's
    arcosh(y_0/a) turn a rounding error into about 1/v of them: the tolerance allows
    steps · max(1, 1/v_min), v_min = arcosh(min(y_0, min y_i) / a) (at least √eps).
    """
    ar, data = ctx.ar, ctx.data
    steps = max(abs(data.i_min), abs(data.i_min + len(data.p) - 1)) + 1
    a = closed_forms.amplitude(ar, ar.scalar(ctx.c), ar.scalar(ctx.delta))
    ratio = min(np.min(data.p[:, 1]), ar.scalar(data.start)) / a
    v = ar.acosh(ratio) if ratio > 1 else ar.scalar(0)
    v_min = ar.to_float(v)
    amplification = math.ceil(1 / max(v_min, math.sqrt(ar.eps), 1e-300))
    if ar.mode != "float64" and v_min < 1e-300:
        # 1/v beyond the float range (digits > 600): 1/max(v, √unit) in ``ar`` (a float √eps
        # is 0 from 324 digits on, and the floor 1e-300 would cut the amplification short)
        amplification = ar.truncate(1 / ar.maximum(v, ar.sqrt(unit(ar)))) + 1
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


#: Each statement about (D3) and the function that checks it, in the order of the response.
_EVALUATORS: Evaluators[_Context] = (
    (D3, lambda x: x.property_check(D3, f"(D3) holds with c = {x.c!r}")),
    (
        D1,
        lambda x: x.property_check(
            D1, f"(D3) implies (D1) here, with delta/(2c) = {x.delta / (2 * x.c):.12g}"
        ),
    ),
    (
        EQUATION_2,
        lambda x: x.property_check(
            EQUATION_2, f"holds with delta/(2c²) = {x.delta / (2 * x.c * x.c):.12g}"
        ),
    ),
    (
        HANGING_STICKS,
        lambda x: x.property_check(
            HANGING_STICKS, f"constant x-spacing: holds with 1/(2c) = {1 / (2 * x.c):.12g}"
        ),
    ),
    (CLOSED_FORM, _closed_form),
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
