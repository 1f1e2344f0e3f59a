"""Figure 6: a conformal hexagonal mesh, its Gauss image meridian and p (D2a, hexagonal)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from app.geometry.d2a import construction as christoffel
from app.geometry.precision import Float64
from app.rendering.figures.common import (
    CurveSource,
    christoffel_figure,
)
from app.rendering.svg import Panels

if TYPE_CHECKING:  # the request models are read, not imported at run time
    from app.schemas.figures import Figure6Query


def draw(query: Figure6Query, curves: CurveSource) -> Panels:
    """Figure 6: a conformal hexagonal mesh, its Gauss image meridian and p (D2a, hexagonal)."""
    curve = curves(
        "d2a-hex",
        a=query.a,
        b=query.b,
        lam=query.lam,
        r=query.r,
        i_min=query.i_min,
        i_max=query.i_max,
    )
    m = query.rays()
    mesh = christoffel.conformal_hexagonal_mesh(
        Float64(), query.a, query.b, query.lam, query.i_min, query.i_max, m
    )
    return christoffel_figure(
        curve,
        "Figure 6: Christoffel dual of a conformal hexagonal mesh (D2a)",
        f"mesh with 2m = {2 * m} rays",
        "f_i on ray 0",
        ("Conformal hexagonal mesh (yz-plane)", "hexagonal mesh", mesh),
        "even: f_i = f_{i−2} b/a; odd: λ f_{i+1} + (1 − λ) f_{i−1}",
    )
