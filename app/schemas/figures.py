"""Request models of the figures (GET /figures/{id}.svg)."""

from __future__ import annotations

import math

from pydantic import Field

from app.schemas.common import StrictModel
from app.schemas.d4b import HalfStep, Index, StickAngle, StickLength


class FigureQuery(StrictModel):
    """Parameters of a figure; subclasses add the paper's parameters."""

    def vertex_range(self) -> tuple[int, int]:
        """The index range drawn (for the picture size limit)."""
        i_min: int = getattr(self, "i_min", 0)
        i_max: int = getattr(self, "i_max", 0)
        return i_min, i_max


class Figure4Query(FigureQuery):
    """Parameters of Figure 4 (left): those of (D4b) on a short index range."""

    h: StickLength = 1.0
    d: HalfStep = 0.2
    beta0: StickAngle = math.pi / 2
    i_min: Index = Field(-4, description="First index i drawn.")
    i_max: Index = Field(4, description="Last index i drawn.")
