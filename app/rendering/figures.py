"""The paper's figures, redrawn from computed data (``GET /figures/{id}.svg``).

Each figure is one ``Figure`` entry in ``FIGURES``: an id, the paper reference, a request model
with the figure's adjustable parameters, and a ``draw`` function that computes the data through
the discretization registry (the same code as the curve endpoints) and returns a ``Plot``.
Adding a figure means writing its request model and ``draw``, and one entry in ``_FIGURES``.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any
from urllib.parse import urlencode

import numpy as np

from app.geometry.curve import Curve
from app.geometry.precision import Float64
from app.registry import DISCRETIZATIONS
from app.rendering.curves import drawable
from app.rendering.svg import Plot, Series, describe_parameters, segments
from app.schemas.d4b import stick_angle
from app.schemas.figures import Figure4Query, FigureQuery


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


def draw_figure_4(query: Figure4Query) -> Plot:
    """Figure 4 (left): sticks x_i d_i, tractrix d_i, Darboux transform e_i, centres p_i."""
    arguments = {
        "h": query.h,
        "d": query.d,
        "beta0": stick_angle(query.beta0),
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
