"""``count`` sample numbers spread evenly over the samples, skipping the cusp x = 0."""

from __future__ import annotations

from typing import TYPE_CHECKING
from urllib.parse import urlencode

import numpy as np

from app.geometry.precision import Float64
from app.geometry.smooth import references as smooth_curves
from app.rendering.curves import drawable
from app.rendering.figures.common import (
    GUIDE_COLOUR,
    P_COLOUR,
    TRACTRIX_COLOUR,
    CurveSource,
)
from app.rendering.svg import Plot, Series, describe_parameters, segments

if TYPE_CHECKING:  # the request models are read, not imported at run time
    from app.schemas.figures import Figure2Query


def triangle_samples(x: np.ndarray, count: int) -> np.ndarray:
    """``count`` sample numbers spread evenly over the samples, skipping the cusp x = 0."""
    if count == 0:
        return np.zeros(0, dtype=np.int64)
    chosen = np.unique(np.round(np.linspace(0, len(x) - 1, count + 2)[1:-1]).astype(np.int64))
    kept: np.ndarray = chosen[x[chosen] != 0]
    return kept


def draw(query: Figure2Query, curves: CurveSource) -> Plot:
    """Figure 2 (right): tractrix d, its evolute p (a hyperbolic cosine) and Nikolaides' angles."""
    curve = smooth_curves.compute_tractrix(
        Float64(), h=query.h, x_min=query.x_min, x_max=query.x_max, count=query.count
    )
    d = drawable(curve, "d", curve.polygon)
    evolute = drawable(curve, "evolute", curve.companions["evolute"])
    catenary = drawable(curve, "catenary", curve.companions["catenary"])
    axis = drawable(curve, "axis_points", curve.companions["axis_points"])
    parameters: dict[str, object] = {
        "h": query.h,
        "x_min": query.x_min,
        "x_max": query.x_max,
        "count": query.count,
    }
    plot = Plot(
        title="Figure 2 (right): a tractrix d and its evolute p, a hyperbolic cosine (S4)",
        subtitle=describe_parameters(parameters) + f"; {query.triangles} Nikolaides triangles",
        footnote=f"Data: GET /smooth/tractrix?{urlencode(parameters)}",
    )
    chosen = triangle_samples(axis[:, 0], query.triangles)
    plot.add(
        Series(
            "triangles",
            "(x, 0), p(x), d(x)",
            segments(
                np.concatenate([axis[chosen], evolute[chosen], d[chosen]]),
                np.concatenate([evolute[chosen], d[chosen], axis[chosen]]),
            ),
            kind="segments",
            color=GUIDE_COLOUR,
            width=1,
            description="Nikolaides: the right angle is at d(x)",
        )
    )
    plot.add(
        Series(
            "axis_points",
            "(x, 0)",
            axis[chosen],
            kind="points",
            color="#000000",
            description="the leader on the x-axis",
        )
    )
    plot.add(
        Series(
            "catenary",
            "h·cosh(x/h)",
            catenary,
            color="#555555",
            markers=False,
            dashed=True,
            width=1,
            description="the hyperbolic cosine",
        )
    )
    plot.add(
        Series(
            "evolute",
            "p",
            evolute,
            color=P_COLOUR,
            markers=False,
            width=2,
            description="evolute of d: centres of curvature from d's derivatives",
        )
    )
    plot.add(
        Series(
            "tractrix",
            "d",
            d,
            color=TRACTRIX_COLOUR,
            markers=False,
            width=2,
            description="tractrix with stick h, (x − h tanh(x/h), h/cosh(x/h))",
        )
    )
    return plot
