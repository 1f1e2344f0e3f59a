"""Figure 5: the planar conformal quad mesh, its Gauss image meridian and p (D2a, quad)."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from app.geometry.d2a import construction as christoffel
from app.geometry.precision import Float64
from app.rendering.figures.common import (
    CurveSource,
    christoffel_figure,
)
from app.rendering.svg import Panels

if TYPE_CHECKING:  # the request models are read, not imported at run time
    from app.schemas.figures import Figure5Query


def draw(query: Figure5Query, curves: CurveSource) -> Panels:
    """Figure 5: the planar conformal quad mesh, its Gauss image meridian and p (D2a, quad)."""
    curve = curves(
        "d2a-quad", f0=query.f0, f1=query.f1, r=query.r, i_min=query.i_min, i_max=query.i_max
    )
    ar = Float64()
    angle = ar.to_float(christoffel.conformal_quad_angle(ar, query.f0, query.f1))
    columns = query.columns or max(1, min(120, math.floor(2 * math.pi / angle + 1e-9)))
    mesh = christoffel.conformal_quad_mesh(
        ar, query.f0, query.f1, query.i_min, query.i_max, columns
    )
    return christoffel_figure(
        curve,
        "Figure 5: Christoffel dual of a conformal quad mesh (D2a)",
        f"{columns} quads around, v = {math.degrees(angle):.4g}°",
        "f_i on column 0",
        ("Planar conformal quad mesh (yz-plane)", "quad mesh", mesh),
        "f_i = f_0 (f_1/f_0)^i on the y-axis",
    )
