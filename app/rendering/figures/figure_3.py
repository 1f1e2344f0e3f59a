"""Figure 3: sticks x_i d_i, tractrix d_i, midpoints, Darboux transform e_i and p_i."""

from __future__ import annotations

from typing import TYPE_CHECKING

from app.rendering.curves import drawable
from app.rendering.figures.common import (
    DARBOUX_COLOUR,
    GUIDE_COLOUR,
    P_COLOUR,
    STICK_COLOUR,
    TRACTRIX_COLOUR,
    CurveSource,
    shown_parameters,
    source_url,
)
from app.rendering.svg import Plot, Series, describe_parameters, segments

if TYPE_CHECKING:  # the request models are read, not imported at run time
    from app.schemas.figures import Figure3Query


def draw(query: Figure3Query, curves: CurveSource) -> Plot:
    """Figure 3: sticks x_i d_i, tractrix d_i, midpoints, Darboux transform e_i and p_i."""
    curve = curves(
        "d4a",
        h=query.h,
        s=query.s,
        beta0=query.beta0,
        i_min=query.i_min,
        i_max=query.i_max,
    )
    p = drawable(curve, "p", curve.polygon)
    tractrix = drawable(curve, "tractrix", curve.companions["tractrix"])
    axis = drawable(curve, "axis_points", curve.companions["axis_points"])
    darboux = drawable(curve, "darboux", curve.companions["darboux"])
    midpoints = (axis + darboux) / 2  # e_i is x_i reflected in this point
    shown = shown_parameters(curve)
    plot = Plot(
        title="Figure 3: Sauer's discrete tractrix (D4a), its Darboux transform and p",
        subtitle=describe_parameters(shown),
        footnote=f"Data: GET {source_url('d4a', shown)}",
    )
    plot.add(
        Series(
            "reflections",
            "x_i to e_i",
            segments(axis, darboux),
            kind="segments",
            color=GUIDE_COLOUR,
            width=0.8,
            description="e_i is x_i reflected in the midpoint of a tractrix edge",
        )
    )
    plot.add(
        Series(
            "sticks",
            "sticks",
            segments(axis, tractrix),
            kind="segments",
            color=STICK_COLOUR,
            width=1.2,
            description="x_i d_i, of length h",
        )
    )
    plot.add(Series("axis_points", "x_i", axis, kind="points", color="#000000"))
    plot.add(
        Series(
            "tractrix",
            "d_i",
            tractrix,
            color=TRACTRIX_COLOUR,
            description="discrete tractrix: |d_{i+1} − d_i| = s",
        )
    )
    plot.add(
        Series(
            "midpoints",
            "midpoints",
            midpoints,
            kind="points",
            color="#000000",
            description="of consecutive tractrix points (the black points)",
        )
    )
    plot.add(
        Series(
            "darboux",
            "e_i",
            darboux,
            color=DARBOUX_COLOUR,
            dashed=True,
            description="Darboux transform of (x_i)",
        )
    )
    plot.add(
        Series(
            "p",
            "p_i",
            p,
            color=P_COLOUR,
            width=2,
            description="on the symmetry lines of the tractrix edges: the discrete hyperbolic "
            "cosine",
        )
    )
    return plot
