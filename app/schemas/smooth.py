"""Parameters of the smooth references GET /smooth/catenary and GET /smooth/tractrix."""

from __future__ import annotations

from typing import Annotated

from pydantic import Field

from app.schemas.common import CurveQuery

CATENARY_DESCRIPTION = """\
The smooth catenary (S1)–(S3), x ↦ (x, h·cosh(x/h)), sampled at `count` equally spaced x in
[`x_min`, `x_max`] (both included), for overlays, convergence studies and figures. `indices`
numbers the samples 0 … count − 1. In float64, |x|/h is limited so that h·cosh(x/h) < 1e150;
in precision=mp, to |x|/h <= 1e10 (beyond, cosh(x/h) is not resolved to the requested digits).
"""

TRACTRIX_DESCRIPTION = """\
The smooth tractrix (S4) with stick h, x ↦ d(x) = (x − h·tanh(x/h), h/cosh(x/h)), where (x, 0)
is the leader on the x-axis, sampled at `count` equally spaced x in [`x_min`, `x_max`].
Companions: `evolute`, the centres of curvature computed from the tractrix's own derivatives;
`catenary`, (x, h·cosh(x/h)); `axis_points`, (x, 0).

Checks: `tractrix-s4` (|d − (x, 0)| = h and the tangent points at the leader), `evolute-s4`
(the evolute is the catenary) and `nikolaides-s4` (right angle at d(x) in the triangle
(x, 0), q(x), d(x)); the cusp x = 0, where d'(x) = 0, is skipped.
"""


Scale = Annotated[
    float,
    Field(
        gt=0,
        le=1e100,
        description="Scale h: the catenary h·cosh(x/h), the tractrix with stick length h.",
        json_schema_extra={"x-domain": "h > 0"},
    ),
]
SampleStart = Annotated[
    float,
    Field(ge=-1e100, le=1e100, description="First sample abscissa (the leader's position)."),
]
SampleEnd = Annotated[
    float,
    Field(
        ge=-1e100,
        le=1e100,
        description="Last sample abscissa, > x_min.",
        json_schema_extra={"x-domain": "x_min < x_max"},
    ),
]
SampleCount = Annotated[
    int,
    Field(
        ge=2,
        le=10_000_000,
        description="Number of samples, >= 2 (at most DCOSH_MAX_VERTICES).",
    ),
]


class SmoothQuery(CurveQuery):
    """Parameters of a smooth reference: h and the sampling."""

    h: Scale = 1.0
    x_min: SampleStart = -3.0
    x_max: SampleEnd = 3.0
    count: SampleCount = 121
