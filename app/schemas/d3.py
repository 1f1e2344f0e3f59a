"""Parameters of (D3), the area–length polygon."""

from __future__ import annotations

from typing import Literal

from pydantic import Field

from app.schemas.common import CurveQuery

D3_DESCRIPTION = """\
The area–length polygon (D3): p_i = (i·delta, y_i) with constant x-spacing `delta` in which the
area under every edge is c times its length, A_i = c·l_i, from p_0 = (0, y0).

Each step solves a quadratic. Both roots are edges with area = c·length, mirror images in the
vertical through p_i: writing y_i = a cosh v with a = √(c² − delta²/4), they are a cosh(v ± 2D),
tanh D = delta/(2c) — the two directions along one catenary. `branch` picks the root for p_1
(`up`: the larger, `down`: the smaller); p_{−1} is the other one, and every later step takes the
root that is not the previous vertex (that one would fold the polygon back onto its last edge).

Domain: c > 0, 0 < delta < 2c (for delta ≥ 2c the polygon zig-zags across the x-axis), and
y0 ≥ √(c² − delta²/4): from a lower p_0 no edge reaches area/length = c (the largest
area/length over a step delta from height y0 is √(y0² + delta²/4)); √(c² − delta²/4) is the
lowest height of every (D3) polygon.

With the defaults and `branch=down` the polygon is the d1 default (D4b's with h = 1, d = 0.1,
shifted by d); `up` gives the same catenary one vertex further on.

Checks: (D3) itself; (D1), eq. (2) and the hanging-sticks equilibrium, which (D3) implies here
(constants delta/(2c), delta/(2c²), 1/(2c)); and the closed form y_i = a cosh(v_0 ± 2iD).
Conventions as for D1. Next to the lowest point the step is ill-conditioned by nature: a vertex
within a relative ε of √(c² − delta²/4) can cost up to log10(1/ε)/2 digits in the next one.
"""


class D3Query(CurveQuery):
    """(D3) parameters: c, delta (x-spacing), y0, branch."""

    c: float = Field(
        1.0,
        gt=0,
        le=1e100,
        description="The constant c of (D3): area under each edge = c · its length; c > 0.",
        json_schema_extra={"x-domain": "c > 0"},
    )
    delta: float = Field(
        0.2,
        gt=0,
        le=1e100,
        description="Constant x-spacing of the vertices, p_i^x = i·delta; 0 < delta < 2c.",
        json_schema_extra={"x-domain": "0 < delta < 2c"},
    )
    y0: float = Field(
        1.0,
        ge=-1e100,
        le=1e100,
        description="Height of p_0 = (0, y0); at least √(c² − delta²/4).",
        json_schema_extra={"x-domain": "y0 >= √(c² − delta²/4)"},
    )
    branch: Literal["up", "down"] = Field(
        "up",
        description="Which root of the first step's quadratic gives p_1: `up` the larger "
        "(the catenary's argument grows with i), `down` the smaller.",
        json_schema_extra={"x-domain": "up or down"},
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
        description="`construction`: the area–length recursion (compared with the closed "
        "form). `closed-form`: y_i = a cosh(v_0 ± 2iD), for very long ranges.",
    )
