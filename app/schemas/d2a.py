"""Parameters of (D2a), the Christoffel duals of conformal quad and hexagonal meshes."""

from __future__ import annotations

from typing import Annotated

from pydantic import Field

from app.schemas.common import CurveQuery
from app.schemas.d4b import Index

_CONVENTIONS = """\
Conventions: the conformal points f_i lie on the y-axis of the yz-plane; the stereographic
projection from (1, 0, 0), Φ(f) = (f² − 1, 2f, 0)/(f² + 1), maps them to the unit circle in the
plane of the first two coordinates. The first coordinate (the symmetry axis) is x, the second
(the distance from the axis) is y, for the Gauss image φ_i and for p alike; Δφ_i = φ_{i+1} − φ_i,
p_0 = (0, r). With these choices the x-steps of p are constant (quad) or 2-periodic (hexagonal),
and the polygon of the theorem lies *below* the x-axis (p_i^y < 0, as eq. (5) prints it): the
signed areas A_i are negative and Δ²p_i^y < 0. Δ²y_i = y_{i+2} − 2y_{i+1} + y_i;
l_i = |p_{i+1} − p_i|; A_i is the signed trapezoid area under the edge p_i p_{i+1}.
Only `method=construction` exists: vertices are cumulative sums of the dual edges from p_0, so a
range far from 0 costs max(|i_min|, |i_max|) edges. In float64, every f_i and 1/f_i must stay
below 1e50, and consecutive f_i must differ by a relative 1e-4: (f1 − f0)/f1, (b − a)/b,
λ(b − a)/f_1 and (1 − λ)(b − a)/b at least 1e-4 (float64 error grows like
1e-16·f_i/(f_{i+1} − f_i)); beyond, use precision=mp, where these gaps must be at least √ε of the
digits asked (the 422 gives the bound).
"""

D2A_QUAD_DESCRIPTION = (
    """\
(D2a) on a conformal quad mesh (Theorem 1): f_i = f_0 (f_1/f_0)^i (eq. (3)), φ_i = Φ(f_i), and
the Christoffel dual p_i = p_{i−1} + Δφ_{i−1}/‖Δφ_{i−1}‖² (eq. (4)). Companions: `conformal`
(the points f_i as (f_i, 0)) and `gauss_image` (the φ_i). Theorem 1 (eq. (2)) holds for exactly
one start height, r* = −f_1(1 + f_0²)/(2(f_1 − f_0)²), the default of `r`; its constant is
c = 4(f_1 − f_0)³/(f_0 + f_1)³ > 0. For any other `r` the check `theorem-1` reports
`holds: false`. The quad polygon satisfies neither (D1) nor (D3) (checks `d1`, `d3`).

"""
    + _CONVENTIONS
)

D2A_HEX_DESCRIPTION = (
    """\
(D2a) on a conformal hexagonal mesh (Theorems 2, 3): f_{2k} = a (b/a)^k, odd
f_i = λ f_{i+1} + (1 − λ) f_{i−1}, φ_i = Φ(f_i), and the Christoffel dual with the hexagonal
factors, p_{i+1} = p_i + 3Δφ_i/‖Δφ_i‖² (i even) or + 2Δφ_i/‖Δφ_i‖² (i odd) (eq. (6)).
Companions: `conformal` and `gauss_image` as for d2a-quad. Theorem 2 (eq. (7), constants c_1, c_2
of (11)) holds for exactly one start height r* (proof of Theorem 2, denominator corrected), the
default of `r`; c_1 > 0 iff (b/a)(7λ − 3) < 3(1 − λ) and c_2 > 0 iff (b/a)λ > 3 − 4λ, so either
may be negative or zero. Theorem 3 ((8), (9)) is compared vertex by vertex (the printed (8) has a
sign error, docs/errata.md E43). Eq. (2) with one constant, (D1) and (D3) fail (checks).

"""
    + _CONVENTIONS
)


ConformalStart = Annotated[
    float,
    Field(
        gt=0,
        le=1e50,
        description="f_0, the conformal point of index 0 on the y-axis; 0 < f0 < f1.",
        json_schema_extra={"x-domain": "0 < f0 < f1"},
    ),
]
ConformalNext = Annotated[
    float,
    Field(
        gt=0,
        le=1e50,
        description="f_1, the next conformal point; f_i = f_0 (f_1/f_0)^i. 0 < f0 < f1.",
        json_schema_extra={"x-domain": "0 < f0 < f1"},
    ),
]
QuadStartHeight = Annotated[
    float | None,
    Field(
        ge=-1e100,
        le=1e100,
        description="Start height: p_0 = (0, r). Default (absent): r* = −f_1(1 + f_0²)/(2(f_1 − "
        "f_0)²), the only value for which Theorem 1 holds.",
        json_schema_extra={"x-domain": "any real; Theorem 1 holds only at r*"},
    ),
]
HexStart = Annotated[
    float,
    Field(
        gt=0,
        le=1e50,
        description="a = f_0, the even conformal point of index 0; 0 < a < b.",
        json_schema_extra={"x-domain": "0 < a < b"},
    ),
]
HexNext = Annotated[
    float,
    Field(
        gt=0,
        le=1e50,
        description="b = f_2; the even points are f_{2k} = a (b/a)^k. 0 < a < b.",
        json_schema_extra={"x-domain": "0 < a < b"},
    ),
]
HexWeight = Annotated[
    float,
    Field(
        alias="lambda",
        gt=0,
        lt=1,
        description="λ of the odd points f_i = λ f_{i+1} + (1 − λ) f_{i−1}; 0 < lambda < 1.",
        json_schema_extra={"x-domain": "0 < lambda < 1"},
    ),
]
HexStartHeight = Annotated[
    float | None,
    Field(
        ge=-1e100,
        le=1e100,
        description="Start height: p_0 = (0, r). Default (absent): r* of the proof of Theorem 2, "
        "the only value for which Theorem 2 holds.",
        json_schema_extra={"x-domain": "any real; Theorem 2 holds only at r*"},
    ),
]


class D2aQuadQuery(CurveQuery):
    """(D2a) quad parameters; the paper's symbols f0, f1 (= f_0, f_1) and r."""

    f0: ConformalStart = 1.0
    f1: ConformalNext = 1.5
    r: QuadStartHeight = None
    i_min: Index = Field(-10, description="First index i (inclusive).")
    i_max: Index = Field(
        10,
        description="Last index i (inclusive), >= i_min.",
        json_schema_extra={"x-domain": "i_min <= i_max"},
    )


class D2aHexQuery(CurveQuery):
    """(D2a) hexagonal parameters; the paper's symbols a, b, λ and r.

    λ is the query parameter and JSON field `lambda` (a Python keyword): the field is named
    `lam` with the alias `lambda`, so ``core_arguments`` (which dumps by field name) hands the
    core the keyword ``lam``.
    """

    a: HexStart = 1.0
    b: HexNext = 2.5
    lam: HexWeight = 0.5
    r: HexStartHeight = None
    i_min: Index = Field(-10, description="First index i (inclusive).")
    i_max: Index = Field(
        10,
        description="Last index i (inclusive), >= i_min.",
        json_schema_extra={"x-domain": "i_min <= i_max"},
    )
