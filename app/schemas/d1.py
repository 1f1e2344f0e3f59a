"""Parameters of (D1), the hanging chain of sticks."""

from __future__ import annotations

from typing import Literal

from pydantic import Field

from app.schemas.common import CurveQuery

D1_DESCRIPTION = """\
The hanging chain of sticks (D1): the polygon p_i = (i·delta, y_i) with constant x-spacing
`delta` whose second difference of heights is c times the sum of its two edge lengths,
Δ²y_i = c(l_i + l_{i+1}), from p_0 = (0, y0) and p_1 = (delta, y1). Equivalently: homogeneous
sticks hanging from weightless hinges in equilibrium.

Each step solves a quadratic; its admissible root is the one with m_{i+1} − m_i − c√(1 + m_i²) ≥ 0
(the other belongs to the arch with −c). For 0 < c < 1 every start continues for ever in both
directions; for c ≥ 1 no polygon exists. The recursion also runs backwards, so any index range
works.

Checks: (D1) itself, and whether the polygon also satisfies (D3), eq. (2) and the hanging-sticks
equilibrium, each with its best constant (`holds: false` is an answer, not an error), and the
closed form y_i = C + a cosh(u_0 + (i − ½)E) (E = 2 artanh c, a = delta·√(1 − c²)/(2c)). (D3)
and (2) hold exactly when the offset C is 0 — e.g. for the defaults, which give the same polygon
as D4b with h = 1, d = 0.1 shifted by d.

Conventions: Δ²y_i = y_{i+2} − 2y_{i+1} + y_i; l_i = |p_{i+1} − p_i|; A_i is the signed trapezoid
area under the edge p_i p_{i+1}. `method=construction` (default) runs the recursion and compares
it with the closed form; `method=closed-form` evaluates the closed form for long ranges. In
float64 heights are kept below 1e150; beyond, use precision=mp.
"""


class D1Query(CurveQuery):
    """(D1) parameters: c, delta (x-spacing), y0, y1."""

    c: float = Field(
        0.1,
        gt=0,
        lt=1,
        description="The constant c of (D1), 0 < c < 1 (c = delta/(2T)·weight per length for "
        "sticks under horizontal tension T).",
        json_schema_extra={"x-domain": "0 < c < 1"},
    )
    delta: float = Field(
        0.2,
        gt=0,
        le=1e100,
        description="Constant x-spacing of the vertices, p_i^x = i·delta; delta > 0.",
        json_schema_extra={"x-domain": "delta > 0"},
    )
    y0: float = Field(
        1.0,
        ge=-1e100,
        le=1e100,
        description="Height of p_0 = (0, y0).",
        json_schema_extra={"x-domain": "any real number"},
    )
    y1: float = Field(
        1.0,
        ge=-1e100,
        le=1e100,
        description="Height of p_1 = (delta, y1); in float64 |y1 − y0|/delta <= 1e150.",
        json_schema_extra={"x-domain": "any real number (float64: |y1 − y0|/delta <= 1e150)"},
    )
    i_min: int = Field(-10, ge=-10_000_000, le=10_000_000, description="First index i (inclusive).")
    i_max: int = Field(
        10,
        ge=-10_000_000,
        le=10_000_000,
        description="Last index i (inclusive), >= i_min.",
        json_schema_extra={"x-domain": "i_min <= i_max"},
    )
    method: Literal["construction", "closed-form"] = Field(
        "construction",
        description="`construction`: the recursion (compared with the closed form). "
        "`closed-form`: y_i = C + a cosh(u_0 + (i − ½)E), for very long ranges.",
    )
