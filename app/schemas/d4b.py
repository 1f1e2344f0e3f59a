"""Parameters of (D4b), Wunderlich's kinematic discrete hyperbolic cosine."""

from __future__ import annotations

import math
from typing import Annotated, Any, Literal

from pydantic import Field

from app.geometry.precision import ExactReal
from app.schemas.common import CurveQuery

D4B_DESCRIPTION = """\
Wunderlich's discrete hyperbolic cosine (D4b): a stick of length `h` moves with one end on the
x-axis in steps of `2d`; each move is a rotation, and the rotation centres p_i are the discrete
hyperbolic cosine. Companions: the tractrix d_i (free end of stick i), the axis points
x_i = (2di, 0), and the Darboux transform e_i = 2d_i − x_i.

Conventions (Theorem 5): stick 0 starts at the origin at angle `beta0` (radians, from the
positive x-axis, counter-clockwise; π/2 is vertical with d_0 = (0, h)); p_i is the centre of the
rotation from stick i−1 to stick i, so p_i^x = (2i − 1)d, p_0 = (−d, h), p_1 = (d, h).
Δ²y_i = y_{i+2} − 2y_{i+1} + y_i; l_i = |p_{i+1} − p_i|; A_i is the signed trapezoid area under
the edge p_i p_{i+1}.

`method=construction` (default) builds the polygon from the definition and compares it with the
closed forms (14) and (16) of Theorems 5 and 6; `method=closed-form` evaluates the closed forms
(in a form that does not overflow early) for very long ranges, and skips that comparison.
In float64, coordinates are kept below 1e150 and d/h ≥ 1.5e-6 (100·√ε, ε = 2.2e-16); beyond,
use precision=mp, where d/h must be at least 100·√ε of the digits asked (the 422 gives it).
"""


StickLength = Annotated[
    float,
    Field(
        gt=0,
        le=1e100,
        description="Stick length h (> 0); also p_1^y when beta0 = π/2.",
        json_schema_extra={"x-domain": "h > 0"},
    ),
]
HalfStep = Annotated[
    float,
    Field(
        gt=0,
        le=1e100,
        description="Half the step of the stick's end along the x-axis (x_i = (2di, 0)); "
        "0 < d < h.",
        json_schema_extra={"x-domain": "0 < d < h"},
    ),
]
StickAngle = Annotated[
    float,
    Field(
        gt=0,
        lt=math.pi,
        description="Angle of stick 0 with the positive x-axis, radians, 0 < beta0 < π. The "
        "default (the double nearest π/2) means exactly vertical, also in precision=mp (where "
        "a written angle is the decimal written).",
        json_schema_extra={"x-domain": "0 < beta0 < π"},
    ),
]
Index = Annotated[int, Field(ge=-10_000_000, le=10_000_000)]


def stick_angle(beta0: float) -> float | None:
    """The core's ``beta0``: ``None`` (exactly vertical in every precision) for the default.

    In precision=mp a written angle is the decimal written (``ExactReal``), never π/2 itself.
    """
    return None if beta0 == math.pi / 2 and not isinstance(beta0, ExactReal) else beta0


class D4bQuery(CurveQuery):
    """(D4b) parameters; the paper's symbols h, d, beta0 (= β0)."""

    h: StickLength = 1.0
    d: HalfStep = 0.1
    beta0: StickAngle = math.pi / 2
    i_min: Index = Field(-10, description="First index i (inclusive).")
    i_max: Index = Field(
        10,
        description="Last index i (inclusive), >= i_min.",
        json_schema_extra={"x-domain": "i_min <= i_max"},
    )
    method: Literal["construction", "closed-form"] = Field(
        "construction",
        description="`construction`: from the definition (compared with Theorems 5, 6). "
        "`closed-form`: from (14) and (16), for very long ranges.",
    )

    def core_arguments(self) -> dict[str, Any]:
        arguments = super().core_arguments()
        arguments["beta0"] = stick_angle(self.beta0)
        return arguments
