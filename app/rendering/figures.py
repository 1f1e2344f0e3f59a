"""The paper's figures, redrawn from computed data (``GET /figures/{id}.svg``).

Each figure is one ``Figure`` entry in ``FIGURES``: an id, the paper reference, a request model
with the figure's adjustable parameters, and a ``draw`` function that computes the data through
the discretization registry (the same code as the curve endpoints) and returns a ``Plot``.
Adding a figure means writing its request model and ``draw``, and one entry in ``_FIGURES``.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any
from urllib.parse import urlencode

import numpy as np
from pydantic import Field

from app.geometry.curve import Curve
from app.geometry.precision import Float64
from app.registry import DISCRETIZATIONS
from app.rendering.curves import drawable
from app.rendering.svg import Plot, Series, describe_parameters, segments
from app.schemas.common import StrictModel


class FigureQuery(StrictModel):
    """Parameters of a figure; subclasses add the paper's parameters."""

    def vertex_range(self) -> tuple[int, int]:
        """The index range drawn (for the picture size limit)."""
        i_min: int = getattr(self, "i_min", 0)
        i_max: int = getattr(self, "i_max", 0)
        return i_min, i_max


@dataclass(frozen=True)
class Figure:
    """One of the paper's figures as the API serves it."""

    id: str
    title: str
    reference: str
    description: str
    query: type[FigureQuery]
    draw: Callable[[Any], Plot]
    """Takes a validated ``query`` instance; returns the plot."""


def curve_of(identifier: str, **arguments: Any) -> Curve:
    """A curve computed in float64 by the registered discretization (the curve endpoints' code)."""
    return DISCRETIZATIONS[identifier].compute(Float64(), **arguments)


def source_url(identifier: str, parameters: dict[str, Any]) -> str:
    """The curve request that returns the figure's data as JSON."""
    return f"/discretizations/{identifier}?{urlencode(parameters)}"


# --- Figure 4 (left): (D4b), the kinematic discrete tractrix -------------------------------------


class Figure4Query(FigureQuery):
    """Parameters of Figure 4 (left): those of (D4b) on a short index range."""

    h: float = Field(
        1.0,
        gt=0,
        le=1e100,
        description="Stick length h (> 0).",
        json_schema_extra={"domain": "h > 0"},
    )
    d: float = Field(
        0.2,
        gt=0,
        le=1e100,
        description="Half the step of the stick's end on the x-axis (x_i = (2di, 0)); 0 < d < h.",
        json_schema_extra={"domain": "0 < d < h"},
    )
    beta0: float = Field(
        math.pi / 2,
        gt=0,
        lt=math.pi,
        description="Angle of stick 0 with the positive x-axis, radians (default π/2: vertical).",
        json_schema_extra={"domain": "0 < beta0 < π"},
    )
    i_min: int = Field(-4, ge=-10_000_000, le=10_000_000, description="First index i drawn.")
    i_max: int = Field(4, ge=-10_000_000, le=10_000_000, description="Last index i drawn.")


def draw_figure_4(query: Figure4Query) -> Plot:
    """Figure 4 (left): sticks x_i d_i, tractrix d_i, Darboux transform e_i, centres p_i."""
    arguments = {
        "h": query.h,
        "d": query.d,
        "beta0": None if query.beta0 == math.pi / 2 else query.beta0,
        "i_min": query.i_min,
        "i_max": query.i_max,
    }
    curve = curve_of("d4b", **arguments)
    p = drawable(curve, "p", curve.polygon)
    tractrix = drawable(curve, "tractrix", curve.companions["tractrix"])
    axis = drawable(curve, "axis_points", curve.companions["axis_points"])
    darboux = drawable(curve, "darboux", curve.companions["darboux"])
    shown = {k: v for k, v in curve.parameters.items() if k != "method"}
    plot = Plot(
        title="Figure 4 (left): the kinematic discrete tractrix (D4b)",
        subtitle=describe_parameters(shown),
        footnote=f"Data: GET {source_url('d4b', shown)}",
    )
    # the rotation about p_i takes x_{i−1} to x_i: both lines from p_i (the angle α_i)
    plot.add(
        Series(
            "rotations",
            "rotation lines",
            segments(
                np.repeat(p[1:], 2, axis=0), np.stack([axis[:-1], axis[1:]], 1).reshape(-1, 2)
            ),
            kind="segments",
            color="#bbbbbb",
            width=0.8,
            description="p_i to x_{i−1} and to x_i: the rotation by α_i about p_i",
        )
    )
    plot.add(
        Series(
            "sticks",
            "sticks",
            segments(axis, tractrix),
            kind="segments",
            color="#666666",
            width=1.2,
            description="x_i d_i, of length h",
        )
    )
    plot.add(Series("axis_points", "x_i", axis, kind="points", color="#000000"))
    plot.add(Series("tractrix", "d_i", tractrix, color="#D55E00", description="discrete tractrix"))
    plot.add(
        Series(
            "darboux",
            "e_i",
            darboux,
            color="#009E73",
            dashed=True,
            description="Darboux transform of (x_i)",
        )
    )
    plot.add(
        Series(
            "p",
            "p_i",
            p,
            color="#0072B2",
            width=2,
            description="centres of rotation: the discrete hyperbolic cosine",
        )
    )
    return plot


_FIGURES = (
    Figure(
        id="figure-4",
        title="Figure 4 (left): discrete tractrix, Darboux transform and centres of rotation",
        reference="Section 3, (D4b); Figure 4 (left)",
        description="Wunderlich's discrete tractrix (D4b): the sticks x_i d_i of length h, the "
        "tractrix d_i, its Darboux transform e_i and the rotation centres p_i (the discrete "
        "hyperbolic cosine), with the rotation lines from p_i to x_{i−1} and x_i. The data are "
        "those of GET /discretizations/d4b with the same parameters.",
        query=Figure4Query,
        draw=draw_figure_4,
    ),
)

FIGURES: dict[str, Figure] = {figure.id: figure for figure in _FIGURES}
