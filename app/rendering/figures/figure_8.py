"""Figure 8: n^j and p^j for the first j, then p^j for every j with an ε-band about cosh."""

from __future__ import annotations

from typing import TYPE_CHECKING
from urllib.parse import urlencode

import numpy as np

from app.geometry.precision import Float64
from app.geometry.smooth import curves as smooth, references as smooth_curves
from app.rendering.curves import drawable
from app.rendering.figures.common import (
    GAUSS_COLOUR,
    P_COLOUR,
    CurveSource,
    panel,
    source_url,
    unit_circle_series,
)
from app.rendering.svg import Panels, Series

if TYPE_CHECKING:  # the request models are read, not imported at run time
    from app.schemas.figures import Figure8Query


def draw(query: Figure8Query, curves: CurveSource) -> Panels:
    """Figure 8: n^j and p^j for the first j, then p^j for every j with an ε-band about cosh."""
    computed = [curves("d2b", sequence=query.sequence, j=j) for j in query.j]
    first = computed[0]
    polygons = [drawable(c, "p", c.polygon) for c in computed]
    low = min(float(np.min(p[:, 0])) for p in polygons)
    high = max(float(np.max(p[:, 0])) for p in polygons)
    catenary = smooth_curves.compute_catenary(Float64(), h=1.0, x_min=low, x_max=high, count=201)
    c_points = drawable(catenary, "catenary", catenary.polygon)
    ar = Float64()
    upper, lower = smooth.catenary_offsets(ar, 1.0, c_points[:, 0], query.eps)
    sources = "; ".join(
        source_url("d2b", {"sequence": query.sequence, "j": j})[len("/discretizations/") :]
        for j in query.j
    )
    figures = Panels(
        title=f"Figure 8: Theorem 11, the sequence (p^j) of {query.sequence} converging to cosh",
        subtitle=f"j = {', '.join(str(j) for j in query.j)}; ε = {query.eps:g}",
        footnote=f"Data: GET /discretizations/{sources}; C: GET /smooth/catenary?"
        + urlencode({"x_min": low, "x_max": high, "count": 201}),
    )
    j1 = query.j[0]
    left = panel(f"Gauss image n^{j1} (inscribed)")
    left.add(unit_circle_series())
    left.add(
        Series(
            "gauss_image",
            f"n^{j1}",
            drawable(first, "gauss_image", first.companions["gauss_image"]),
            color=GAUSS_COLOUR,
            width=2,
            description="n_i = (s_i, √(1 − s_i²))",
        )
    )
    figures.add("left", left)
    centre = panel(f"p^{j1}: edges parallel to those of n^{j1}")
    centre.add(
        Series(
            "p",
            f"p^{j1}",
            polygons[0],
            color=P_COLOUR,
            width=2,
            description="the discrete hyperbolic cosine (D2b)",
        )
    )
    figures.add("centre", centre)
    right = panel("(p^j) and the ε-neighbourhood of C = {(x, cosh x)}")
    right.add(
        Series(
            "band",
            f"|q − C| < {query.eps:g}",
            np.concatenate([upper, lower[::-1]]),
            kind="area",
            color="#56B4E9",
            width=0.5,
            description="bounded by the parallel curves of C at distance ε",
        )
    )
    right.add(
        Series(
            "catenary",
            "C",
            c_points,
            color="#555555",
            markers=False,
            dashed=True,
            width=1,
            description="(x, cosh x)",
        )
    )
    palette = ("#D55E00", "#009E73", "#0072B2", "#CC79A7", "#E69F00", "#000000")
    for k, (j, p) in enumerate(zip(query.j, polygons, strict=True)):
        right.add(
            Series(
                f"p-{j}",
                f"p^{j}",
                p,
                color=palette[k % len(palette)],
                width=1.5,
                description=f"{len(p)} vertices",
            )
        )
    figures.add("right", right)
    return figures
