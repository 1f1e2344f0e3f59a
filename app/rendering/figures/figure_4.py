"""Figure 4 (left): sticks x_i d_i, tractrix d_i, Darboux transform e_i, centres p_i."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from app.rendering.curves import drawable
from app.rendering.figures.common import (
    CurveSource,
    source_url,
)
from app.rendering.svg import Plot, Series, describe_parameters, segments

if TYPE_CHECKING:  # the request models are read, not imported at run time
    from app.schemas.figures import Figure4Query


def draw(query: Figure4Query, curves: CurveSource) -> Plot:
    """Figure 4 (left): sticks x_i d_i, tractrix d_i, Darboux transform e_i, centres p_i."""
    arguments = {
        "h": query.h,
        "d": query.d,
        "beta0": query.beta0,
        "i_min": query.i_min,
        "i_max": query.i_max,
    }
    curve = curves("d4b", **arguments)
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
