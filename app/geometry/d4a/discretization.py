"""(D4a) Sauer's discrete tractrix and its discrete hyperbolic cosine, with Section 3's claims.

The sticks, the tractrix and p come from the construction (``sauer_tractrix``) by default, or
from the explicit form (``sauer_closed_forms``) with ``method="closed-form"``. The checks test
what Section 3 says about (D4a) — the Darboux transform, p_i as the centre of the rotation from
stick i to stick i+1, the construction of Nikolaides — and whether p satisfies (D1), (D3),
eq. (2): it satisfies none of them (its x-spacing is not constant), and the checks say by how
much it misses.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from fractions import Fraction
from functools import cached_property
from typing import Any, Literal

import numpy as np

from app.geometry import darboux, properties
from app.geometry.catalog.section3 import (
    D4A_ARC_LENGTH as ARC_LENGTH,
    D4A_CLOSED_FORM as CLOSED_FORM,
    D4A_DARBOUX as DARBOUX,
    D4A_DARBOUX_DISTANCE as DARBOUX_DISTANCE,
    D4A_NIKOLAIDES as NIKOLAIDES,
    D4A_ROTATION as ROTATION,
    D4A_STICKS as STICKS,
)
from app.geometry.checks import (
    Check,
    Erratum,
    Statement,
    check_residuals,
    not_applicable,
    point_distance,
    printed_residual,
    relative_point_difference,
)
from app.geometry.curve import EVERYTHING, Curve, DiscretizationInfo, Selection, require_range
from app.geometry.d4a import closed_forms as sauer_closed_forms, construction as sauer_tractrix
from app.geometry.d4a.closed_forms import ExplicitTractrix
from app.geometry.d4a.construction import SauerSticks
from app.geometry.errors import NotRepresentableError
from app.geometry.on_demand import Evaluators, OnDemand
from app.geometry.polygon import magnitude
from app.geometry.precision import Arithmetic, Array, Scalar
from app.geometry.tolerances import (
    FLOAT64_COORDINATE_LIMIT,
    LOCAL_STEPS,
    NOT_CONSTRUCTED,
    exact,
    power_of_ten_text,
)

Method = Literal["construction", "closed-form"]


#: Below this step ratio s/h the symmetry lines of consecutive tractrix edges meet at angles
#: too small for float64 (p loses about log10(h/s) digits; see docs/errata.md, D4a numerics).
FLOAT64_MIN_STEP_RATIO = 1e-3

S = Statement

STATEMENTS: tuple[Statement, ...] = (
    STICKS,
    ARC_LENGTH,
    DARBOUX,
    DARBOUX_DISTANCE,
    ROTATION,
    NIKOLAIDES,
    CLOSED_FORM,
    *properties.PROPERTIES,
)

INFO = DiscretizationInfo(
    id="d4a",
    title="Sauer's discrete tractrix and its hyperbolic cosine (D4a)",
    reference="Section 3 (D4a), Figure 3",
    summary=(
        "A stick of length h with one end x_i on the x-axis; its other end d_i lies on the "
        "neighbouring stick, s away from that stick's end (a discrete tractrix parametrized by "
        "arc length). The symmetry lines of consecutive tractrix edges meet in the discrete "
        "hyperbolic cosine p_i, the centre of the rotation from stick i to stick i+1."
    ),
    default_range=(-10, 10),
    methods=("construction", "closed-form"),
    companions={
        "tractrix": "d_i, the free end of stick i (the discrete tractrix), same indices as p",
        "axis_points": "x_i, the end of stick i on the x-axis",
        "darboux": "e_i, the reflection of x_i in the midpoint of the tractrix edge on stick i "
        "(a Darboux transform of x)",
    },
    constants={
        "d1": "best c of (D1), Δ²p_i^y = c(l_i + l_{i+1}) (does not hold for D4a)",
        "d3": "best c of (D3), A_i = c l_i (does not hold for D4a)",
        "eq2": "best c of eq. (2), Δ²p_i^y = c(A_i + A_{i+1}) (does not hold for D4a)",
        "equilibrium": "best c of the hanging-sticks equilibrium (does not hold for D4a)",
    },
    statements=STATEMENTS,
)

ERRATUM_STICKS = (
    "E20",
    "for all i ∈ ℤ, d_i lies on the previous stick (i − 1), s away from d_{i−1}",
    "d_i lies on stick i − 1 for i > c and on stick i + 1 for i < c, c the cusp stick (whose "
    "end is higher than h − s): for all i the literal rule would need sin β_i = (1 − s/h)^i "
    "sin β_0 <= 1",
)
ERRATUM_DARBOUX = (
    "E21",
    "e_i is the reflection of x_i in the midpoint of d_i and d_{i+1}",
    "e_i is the reflection of x_i in the midpoint of the tractrix edge on stick i: d_i d_{i+1} "
    "for i ≥ c, d_{i−1} d_i for i < c (before the cusp stick c the pursuit runs the other way)",
)


@dataclass(frozen=True)
class D4aPolygons(OnDemand):
    """The polygons of one (D4a) computation, ``(n + 1, 2)`` each, on i_min .. i_max + 1.

    The extra last index only feeds checks (p_i needs stick i+1); responses show i_min .. i_max.
    p, the tractrix, the axis points and the sides come with the construction (or the explicit
    form); the Darboux transform, the explicit form and what only the checks read are computed
    when first read. ``replaced`` gives a copy with some polygons swapped.
    """

    ar: Arithmetic
    parameters: tuple[float, float, float | None]
    """h, s, beta0."""
    i_min: int
    p: Array
    tractrix: Array
    axis: Array
    side: np.ndarray[Any, np.dtype[np.int64]]
    sticks: SauerSticks | ExplicitTractrix
    """Every stick lo .. hi (lo = min(0, i_min − 1), hi = max(0, i_max + 3)): the construction
    or, for ``method="closed-form"``, the explicit form."""
    lo: int
    hull_side: np.ndarray[Any, np.dtype[np.int64]]
    constructed: bool

    def window(self, points: Array, first: int) -> Array:
        """i_min .. i_max + 1 of a hull array whose entry 0 belongs to stick lo + first."""
        start = self.i_min - self.lo - first
        return points[start : start + len(self.p)]

    @cached_property
    def darboux(self) -> Array:
        """e_i, the reflection of x_i in the midpoint of the tractrix edge on stick i."""
        if isinstance(self.sticks, ExplicitTractrix):
            return self.window(self.sticks.darboux, 0)
        return self.window(sauer_tractrix.darboux(self.sticks), 1)

    @cached_property
    def carried_far(self) -> Array:
        """The far end of the tractrix edge on each stick (d_{i+1} or d_{i−1})."""
        tractrix = self.sticks.tractrix
        before = (self.hull_side < sauer_tractrix.CUSP)[1:-1, None]
        far = np.where(before, tractrix[:-2], tractrix[2:])  # sticks lo + 1 .. hi − 1
        return self.window(far, 1)

    @cached_property
    def printed_darboux(self) -> Array:
        """d_i + d_{i+1} − x_i, the reflection the paper prints, on i_min .. i_max + 1."""
        tractrix, axis = self.sticks.tractrix, self.sticks.axis_points
        return self.window(tractrix[:-1] + tractrix[1:] - axis[:-1], 0)

    @cached_property
    def explicit(self) -> ExplicitTractrix:
        """The explicit form on the sticks lo .. hi."""
        if isinstance(self.sticks, ExplicitTractrix):
            return self.sticks
        ar, (h, s, beta0) = self.ar, self.parameters
        hi = self.lo + len(self.hull_side) - 1
        return sauer_closed_forms.tractrix(ar, ar.scalar(h), ar.scalar(s), beta0, self.lo, hi)

    @property
    def explicit_p(self) -> Array:
        """p_i of the explicit form on i_min .. i_max + 1."""
        return self.window(self.explicit.hyperbolic_cosine, 0)

    @property
    def explicit_tractrix(self) -> Array:
        """d_i of the explicit form on i_min .. i_max + 1."""
        return self.window(self.explicit.tractrix, 0)

    @property
    def cusp(self) -> int:
        """The cusp stick c."""
        return self.explicit.cusp.index


def polygons(
    ar: Arithmetic,
    h: float,
    s: float,
    beta0: float | None,
    i_min: int,
    i_max: int,
    method: Method = "construction",
) -> D4aPolygons:
    """Construction (Section 3) or explicit form on i_min .. i_max + 1."""
    sauer_tractrix.validate(h, s, beta0)
    hh, ss = ar.scalar(h), ar.scalar(s)
    lo, hi = min(0, i_min - 1), max(0, i_max + 3)
    sticks: SauerSticks | ExplicitTractrix
    if method == "construction":
        sticks = sauer_tractrix.construct_sticks(ar, h, s, beta0, lo, hi)
        side, p, first = sticks.side, sauer_tractrix.hyperbolic_cosine(ar, sticks), 1
    else:
        sticks = sauer_closed_forms.tractrix(ar, hh, ss, beta0, lo, hi)
        cusp = sticks.cusp.index
        # the cusp may lie ~10^(digits/2) sticks away: only its side of the range matters
        side = np.sign(np.arange(lo, hi + 1) - min(max(cusp, lo - 1), hi + 1)).astype(np.int64)
        p, first = sticks.hyperbolic_cosine, 0
    start = i_min - lo
    count = i_max - i_min + 2
    return D4aPolygons(
        ar=ar,
        parameters=(h, s, beta0),
        i_min=i_min,
        p=p[start - first : start - first + count],
        tractrix=sticks.tractrix[start : start + count],
        axis=sticks.axis_points[start : start + count],
        side=side[start : start + count],
        sticks=sticks,
        lo=lo,
        hull_side=side,
        constructed=method == "construction",
    )


class _Context(properties.Context):
    """What the checks of one (D4a) computation share, each part computed when first needed.

    p_i is where nearly parallel lines meet: resolved to about h/s + (sticks walked) units of
    rounding (docs/checks.md); every check that reads p allows that (``p_tolerance``).
    """

    def __init__(self, ar: Arithmetic, data: D4aPolygons, detail: bool) -> None:
        h, s, _ = data.parameters
        n = len(data.p) - 1
        indices = np.arange(data.i_min, data.i_min + n + 1, dtype=np.int64)
        steps = max(abs(data.i_min - 1), abs(data.i_min + n + 2)) + 1
        self.p_tolerance = ar.tolerance(LOCAL_STEPS + steps + math.ceil(h / s))
        super().__init__(ar, indices, detail, data.p[:n], self.p_tolerance)
        self.data, self.n = data, n
        self.h, self.s = ar.scalar(h), ar.scalar(s)


def evaluate(
    ar: Arithmetic, data: D4aPolygons, detail: bool = False, selection: Selection = EVERYTHING
) -> tuple[dict[str, Scalar], list[Check]]:
    """Fitted constants and the selected checks of ``STATEMENTS`` on the given polygons.

    Each check computes only the polygons and fits it needs; the constants are those of the
    fits computed.
    """
    ctx = _Context(ar, data, detail)
    checks = selection.evaluate(ctx, _EVALUATORS)
    return ctx.fits.constants() if ctx.computed("fits") else {}, checks


def compute(
    ar: Arithmetic,
    h: float = 1.0,
    s: float = 0.1,
    beta0: float | None = None,
    i_min: int = -10,
    i_max: int = 10,
    method: Method = "construction",
    detail: bool = False,
    selection: Selection = EVERYTHING,
) -> Curve:
    """(D4a) on i_min .. i_max with its companions, constants and checks."""
    sauer_tractrix.validate(h, s, beta0)
    require_range(i_min, i_max)
    if ar.mode == "float64":
        _require_float64_representable(h, s, beta0, i_min, i_max)
    elif exact(s) / exact(h) < Fraction(1, 10 ** (ar.digits // 2)):
        # p is resolved to about h/s units of rounding: keep at least half of the digits
        # (exact: a float 10^−(digits//2) is 0 from 648 digits on)
        raise NotRepresentableError(
            "s",
            f"s/h >= {power_of_ten_text(-(ar.digits // 2))} with digits={ar.digits}",
            s,
            "p is resolved to about h/s units of rounding; use more digits",
        )
    data = polygons(ar, h, s, beta0, i_min, i_max, method)
    constants, checks = evaluate(ar, data, detail, selection)
    parameters: dict[str, Any] = {
        "h": h,
        "s": s,
        "beta0": math.pi / 2 if beta0 is None else beta0,
        "i_min": i_min,
        "i_max": i_max,
        "method": method,
    }
    companions: dict[str, Array | Callable[[], Array]] = {
        "tractrix": data.tractrix,
        "axis_points": data.axis,
        "darboux": lambda: data.darboux,
    }
    return INFO.curve(
        ar, parameters, data.p, companions, constants=constants, checks=checks, selection=selection
    )


def _sticks(ctx: _Context) -> Check:
    """Stick lengths, axis ends, and the carried tractrix point at distance h − s."""
    ar, data, h, s, n = ctx.ar, ctx.data, ctx.h, ctx.s, ctx.n
    x, d, far = data.axis, data.tractrix, data.carried_far
    length = point_distance(ar, d, x)
    carried = x + (h - s) * (d - x) / length[:, None]  # the point s below d on the stick
    residuals = np.maximum(
        np.maximum(abs(length[:n] - h), abs(x[:n, 1])) / magnitude(x[:n], d[:n]),
        point_distance(ar, far[:n], carried[:n]) / magnitude(x[:n], d[:n], far[:n]),
    )
    # printed: d_i on the previous stick, for every i
    printed = point_distance(ar, d[1 : n + 1], carried[:n]) / magnitude(x[:n], d[:n], d[1 : n + 1])
    erratum = Erratum(*ERRATUM_STICKS, printed_residual=printed_residual(ar, printed))
    return ctx.check(STICKS, 0, residuals, erratum)


def _arc_length_residuals(ar: Arithmetic, s: Scalar, d: Array) -> Array:
    return abs(point_distance(ar, d[1:], d[:-1]) - s) / magnitude(d[1:], d[:-1])


def _darboux_edges(ctx: _Context) -> Check:
    ar, data = ctx.ar, ctx.data
    residuals = darboux.edge_length_residuals(ar, data.axis, data.darboux)
    printed = darboux.edge_length_residuals(ar, data.axis, data.printed_darboux)
    erratum = Erratum(*ERRATUM_DARBOUX, printed_residual=printed_residual(ar, printed))
    return ctx.check(DARBOUX, 0, residuals, erratum)


def _darboux_distance(ctx: _Context) -> Check:
    ar, data, n = ctx.ar, ctx.data, ctx.n
    expected = 2 * ctx.h - ctx.s
    x = data.axis[:n]
    residuals = darboux.distance_residuals(ar, x, data.darboux[:n], expected)
    printed = darboux.distance_residuals(ar, x, data.printed_darboux[:n], expected)
    erratum = Erratum(*ERRATUM_DARBOUX, printed_residual=printed_residual(ar, printed))
    return ctx.check(DARBOUX_DISTANCE, 0, residuals, erratum)


def _signed_angle(ar: Arithmetic, a: Array, b: Array) -> Array:
    """The angle turning vector a_k into b_k, in (−π, π]; ``(n, 2) -> (n,)``."""
    cross = a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]
    return ar.atan2(cross, a[:, 0] * b[:, 0] + a[:, 1] * b[:, 1])


def _rotation_residuals(ar: Arithmetic, p: Array, x: Array, d: Array) -> Array:
    """p_i against sticks i, i+1: equal distances and equal turning angles; ``(n,)``."""
    x0, x1, d0, d1 = x[:-1], x[1:], d[:-1], d[1:]
    axis_gap = abs(point_distance(ar, p, x0) - point_distance(ar, p, x1)) / magnitude(p, x0, x1)
    end_gap = abs(point_distance(ar, p, d0) - point_distance(ar, p, d1)) / magnitude(p, d0, d1)
    turn = abs(_signed_angle(ar, x0 - p, x1 - p) - _signed_angle(ar, d0 - p, d1 - p))
    return np.maximum(np.maximum(axis_gap, end_gap), turn)


def _nikolaides_residuals(p: Array, x: Array) -> Array:
    """|p_i^x − (x_i^x + x_{i+1}^x)/2| relative to the points' magnitude; ``(n,)``."""
    x0, x1 = x[:-1], x[1:]
    return abs(p[:, 0] - (x0[:, 0] + x1[:, 0]) / 2) / magnitude(p, x0, x1)


def _closed_form(ctx: _Context) -> Check:
    """Construction against the explicit form, with the tolerance of p's resolution.

    p_i is compared relative to its size, d_i relative to the magnitude of d_i and x_i (d_i^x
    is a difference x_i + h cos β_i that may nearly cancel).
    """
    ar, data, n, tolerance = ctx.ar, ctx.data, ctx.n, ctx.p_tolerance
    if not data.constructed:
        return not_applicable(CLOSED_FORM, tolerance, NOT_CONSTRUCTED)
    ends = data.explicit_tractrix[:n]
    residuals = np.maximum(
        relative_point_difference(ar, data.p[:n], data.explicit_p[:n]),
        point_distance(ar, data.tractrix[:n], ends) / magnitude(ends, data.axis[:n]),
    )
    return check_residuals(
        CLOSED_FORM,
        ar,
        ctx.indices[:n],
        residuals,
        tolerance,
        ctx.detail,
        note=f"cusp stick c = {data.cusp}",
    )


#: Each statement about (D4a) and the function that checks it, in the order of the response.
_EVALUATORS: Evaluators[_Context] = (
    (STICKS, _sticks),
    (
        ARC_LENGTH,
        lambda x: x.check(ARC_LENGTH, 0, _arc_length_residuals(x.ar, x.s, x.data.tractrix)),
    ),
    (DARBOUX, _darboux_edges),
    (DARBOUX_DISTANCE, _darboux_distance),
    (
        ROTATION,
        lambda x: x.check(
            ROTATION,
            0,
            _rotation_residuals(x.ar, x.data.p[: x.n], x.data.axis, x.data.tractrix),
            tolerance=x.p_tolerance,
        ),
    ),
    (
        NIKOLAIDES,
        lambda x: x.check(
            NIKOLAIDES,
            0,
            _nikolaides_residuals(x.data.p[: x.n], x.data.axis),
            tolerance=x.p_tolerance,
        ),
    ),
    (CLOSED_FORM, _closed_form),
    *properties.EVALUATORS,
)


def _require_float64_representable(
    h: float, s: float, beta0: float | None, i_min: int, i_max: int
) -> None:
    """Refuse, before computing, what float64 cannot resolve or represent.

    p_i^y is about h / sin β_i and sin β changes by the factor k = 1 − s/h per stick, so
    sin β_i >= sin β_0 k^{|i|+3} over the constructed sticks.
    """
    if s / h < FLOAT64_MIN_STEP_RATIO:
        raise NotRepresentableError(
            "s",
            f"s/h >= {FLOAT64_MIN_STEP_RATIO:g} in float64",
            s,
            "the symmetry lines of consecutive tractrix edges meet at angles float64 cannot "
            "resolve; use precision=mp",
        )
    sin0 = 1.0 if beta0 is None else math.sin(beta0)
    budget = math.log(FLOAT64_COORDINATE_LIMIT) - math.log(2 * h) + math.log(sin0)
    per_stick = -math.log1p(-s / h)
    largest = math.floor(budget / per_stick) - 4
    if largest < 0:
        raise NotRepresentableError(
            "beta0",
            "sin(beta0) large enough for p_0^y ≈ h / sin(beta0) to stay below 1e150 in float64",
            beta0,
            "use precision=mp",
        )
    for name, value in (("i_max", i_max), ("i_min", i_min)):
        if abs(value) > largest:
            raise NotRepresentableError(
                name,
                f"|{name}| <= {largest} in float64",
                value,
                f"beyond it p_i^y may exceed {FLOAT64_COORDINATE_LIMIT:g}; use precision=mp",
            )
