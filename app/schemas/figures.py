"""Request models of the figures (GET /figures/{id}.svg).

Each figure takes the parameters of the discretization it draws, with the same types (domains,
bounds and descriptions) as the curve endpoints, on a shorter default index range, plus what the
picture alone needs (a number of Nikolaides triangles, the mesh's rays, ε of a neighbourhood).
"""

from __future__ import annotations

import math
from typing import Annotated, Any, Literal

from pydantic import BeforeValidator, Field

from app.schemas.common import StrictModel
from app.schemas.d2a import (
    ConformalNext,
    ConformalStart,
    HexNext,
    HexStart,
    HexStartHeight,
    HexWeight,
    QuadStartHeight,
)
from app.schemas.d2b import Refinement
from app.schemas.d4a import SauerStep, SauerStickLength
from app.schemas.d4b import HalfStep, Index, StickAngle, StickLength
from app.schemas.smooth import SampleCount, SampleEnd, SampleStart, Scale

#: Index range of the mesh figures (5 and 6): the mesh has (range) × (columns or rays) vertices.
MeshIndex = Annotated[int, Field(ge=-60, le=60)]


class FigureQuery(StrictModel):
    """Parameters of a figure; subclasses add the paper's parameters."""

    def vertex_range(self) -> tuple[int, int]:
        """The index range drawn (for the picture size limit)."""
        i_min: int = getattr(self, "i_min", 0)
        i_max: int = getattr(self, "i_max", 0)
        return i_min, i_max


class Figure2Query(FigureQuery):
    """Figure 2 (right): the smooth tractrix, its evolute and Nikolaides' right angles (S4)."""

    h: Scale = 1.0
    x_min: SampleStart = -2.0
    x_max: SampleEnd = 2.0
    count: SampleCount = Field(101, le=20_001)
    triangles: int = Field(
        6,
        ge=0,
        le=50,
        description="Number of Nikolaides triangles (x, 0), p(x), d(x) drawn, at samples "
        "spread evenly over the range (the cusp x = 0 skipped).",
        json_schema_extra={"x-domain": "0 <= triangles <= 50"},
    )

    def vertex_range(self) -> tuple[int, int]:
        return 0, self.count - 1


class Figure3Query(FigureQuery):
    """Figure 3: (D4a), Sauer's discrete tractrix, its Darboux transform and p."""

    h: SauerStickLength = 1.0
    s: SauerStep = 0.3
    beta0: StickAngle = math.pi / 2
    i_min: Index = Field(-4, description="First index i drawn.")
    i_max: Index = Field(
        3,
        description="Last index i drawn (p_{−1−i} mirrors p_i for the vertical start).",
        json_schema_extra={"x-domain": "i_min <= i_max"},
    )


class Figure4Query(FigureQuery):
    """Parameters of Figure 4 (left): those of (D4b) on a short index range."""

    h: StickLength = 1.0
    d: HalfStep = 0.2
    beta0: StickAngle = math.pi / 2
    i_min: Index = Field(-4, description="First index i drawn.")
    i_max: Index = Field(
        4,
        description="Last index i drawn.",
        json_schema_extra={"x-domain": "i_min <= i_max"},
    )


class Figure5Query(FigureQuery):
    """Figure 5: the planar conformal quad mesh and the (D2a) quad polygon p."""

    f0: ConformalStart = 1.0
    f1: ConformalNext = 1.5
    r: QuadStartHeight = None
    i_min: MeshIndex = Field(-4, description="First index i drawn (mesh rings and p).")
    i_max: MeshIndex = Field(
        4,
        description="Last index i drawn (mesh rings and p).",
        json_schema_extra={"x-domain": "i_min <= i_max"},
    )
    columns: int | None = Field(
        None,
        ge=1,
        le=120,
        description="Quads drawn around the centre (default: as many as fit in one turn, at "
        "most 120). Their angle v is fixed by conformality: sin(v/2) = (f1 − f0)/(2√(f0·f1)).",
        json_schema_extra={"x-domain": "1 <= columns <= 120, columns·v <= 2π"},
    )


class Figure6Query(FigureQuery):
    """Figure 6: a conformal hexagonal mesh and the (D2a) hexagonal polygon p."""

    a: HexStart = 1.0
    b: HexNext = 2.5
    lam: HexWeight = 0.5
    r: HexStartHeight = None
    i_min: MeshIndex = Field(-4, description="First index i drawn (mesh and p).")
    i_max: MeshIndex = Field(
        4,
        description="Last index i drawn (mesh and p).",
        json_schema_extra={"x-domain": "i_min <= i_max"},
    )
    m: int | None = Field(
        None,
        ge=2,
        le=60,
        description="The mesh has 2m rays, π/m apart (every m gives hexagons of multi-ratio −1; "
        "the paper does not state it). Default: the m for which the hexagons are closest to "
        "regular, round(2√3·π/log(b/a)), within 2 .. 60.",
        json_schema_extra={"x-domain": "2 <= m <= 60"},
    )

    def rays(self) -> int:
        """m as drawn: the given one, or the default of the description."""
        if self.m is not None:
            return self.m
        estimate = 2 * math.sqrt(3) * math.pi / math.log(self.b / self.a) if self.b > self.a else 2
        return min(60, max(2, round(estimate)))


class Figure7Query(FigureQuery):
    """Figure 7: the (D4b) tractrix with its inscribed Gauss image n and the circumscribed m."""

    h: StickLength = 1.0
    d: HalfStep = 0.2
    i_min: Index = Field(-4, description="First index i drawn.")
    i_max: Index = Field(
        4,
        description="Last index i drawn.",
        json_schema_extra={"x-domain": "i_min <= i_max"},
    )


def _integers(value: Any) -> Any:
    """Accept ``j`` as a list, or as one comma-separated string (a GET query)."""
    if isinstance(value, str):
        return [part.strip() for part in value.split(",") if part.strip()]
    if isinstance(value, list) and len(value) == 1 and isinstance(value[0], str):
        return [part.strip() for part in value[0].split(",") if part.strip()]
    return value


class Figure8Query(FigureQuery):
    """Figure 8: Theorem 11 with the sequences of Example 12 (or Remark 13)."""

    sequence: Literal["example-12", "remark-13"] = Field(
        "example-12",
        description="`example-12` (s_i = 4i²/(j² + 4i²)) or `remark-13` (s_i = i/(i + j)).",
        json_schema_extra={"x-domain": "example-12 | remark-13"},
    )
    j: Annotated[list[Annotated[Refinement, Field(le=1000)]], BeforeValidator(_integers)] = Field(
        [1, 2, 5],
        min_length=1,
        max_length=6,
        description="Refinements j drawn on the right, comma-separated (1 to 6 of them, each "
        "1 .. 1000); the left panels show the first. Each polygon has its default range, "
        "t = i/j from the start of the domain to 2.",
        json_schema_extra={"x-domain": "1 to 6 integers, 1 <= j <= 1000"},
    )
    eps: float = Field(
        0.1,
        gt=0,
        lt=1,
        description="Half-width ε of the neighbourhood drawn around C = {(x, cosh x)}.",
        json_schema_extra={"x-domain": "0 < eps < 1"},
    )

    def vertex_range(self) -> tuple[int, int]:
        # the default range of refinement j has about 2j + j/4 + 1 vertices
        return 0, 3 * max(self.j)
