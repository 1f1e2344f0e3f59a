"""Parameters of (D4a), Sauer's discrete tractrix."""

from __future__ import annotations

import math
from typing import Annotated, Any, Literal

from pydantic import Field

from app.geometry.precision import ExactReal
from app.schemas.common import CurveQuery
from app.schemas.d4b import Index, StickAngle

D4A_DESCRIPTION = """\
Sauer's discrete tractrix (D4a): a stick of length `h` has one end x_i on the x-axis and its
other end d_i on the neighbouring stick, `s` away from that stick's end, so |d_{i+1} − d_i| = s
(a tractrix parametrized by arc length). The symmetry lines (perpendicular bisectors) of
consecutive tractrix edges meet in the discrete hyperbolic cosine p_i, the centre of the
rotation taking stick i to stick i+1. Companions: the tractrix d_i, the axis points x_i and the
Darboux transform e_i (x_i reflected in the midpoint of the tractrix edge on stick i).

Conventions: x_0 = (0, 0), stick 0 at angle `beta0` (radians from the positive x-axis; π/2 is
vertical with d_0 = (0, h)). The pursuit runs away from the cusp stick c — the stick whose end
is higher than h − s, so that no stick can carry it — on both sides: for i ≥ c, d_{i+1} lies on
stick i and the leader moves ahead; for i < c, d_{i−1} lies on stick i (the mirror image). The
paper's "d_i on the previous stick for all i" is impossible (docs/errata.md, E20). For the
vertical start c = 0 and the polygon is symmetric: p_{−1} and p_0 = (∓w/2, h − s/2) with
w = √(s(2h − s)), and p_{−1−i} mirrors p_i. p_i^x = (x_i + x_{i+1})/2: the x-spacing of p is not
constant, and p satisfies none of (D1), (D3), eq. (2) (the checks report the best constants and
by how much they miss).

`method=construction` (default) builds the sticks one after the other and compares with the
explicit form (sin β_i = sin β_c (1 − s/h)^{|i−c|}, x_i as partial sums); `method=closed-form`
evaluates the explicit form (vectorized). p is where nearly parallel lines meet and is resolved
to about h/s units of rounding: float64 needs s/h ≥ 0.001 and p_i^y below 1e150 (beyond, use
precision=mp); mp needs s/h ≥ 10^−⌊digits/2⌋, which keeps half of the digits.
"""


SauerStickLength = Annotated[
    float,
    Field(
        gt=0,
        le=1e100,
        description="Stick length h (> 0).",
        json_schema_extra={"x-domain": "h > 0"},
    ),
]
SauerStep = Annotated[
    float,
    Field(
        gt=0,
        le=1e100,
        description="Distance of consecutive tractrix points, |d_{i+1} − d_i| = s; 0 < s < h.",
        json_schema_extra={"x-domain": "0 < s < h"},
    ),
]


class D4aQuery(CurveQuery):
    """(D4a) parameters: h, s, beta0 (= β0)."""

    h: SauerStickLength = 1.0
    s: SauerStep = 0.1
    beta0: StickAngle = math.pi / 2
    i_min: Index = Field(-10, description="First index i (inclusive).")
    i_max: Index = Field(
        10,
        description="Last index i (inclusive), >= i_min.",
        json_schema_extra={"x-domain": "i_min <= i_max"},
    )
    method: Literal["construction", "closed-form"] = Field(
        "construction",
        description="`construction`: stick by stick (compared with the explicit form). "
        "`closed-form`: the explicit form, for very long ranges.",
    )

    def core_arguments(self) -> dict[str, Any]:
        arguments = super().core_arguments()
        if arguments["beta0"] == math.pi / 2 and not isinstance(arguments["beta0"], ExactReal):
            arguments["beta0"] = None  # exactly vertical, in every precision
        return arguments
