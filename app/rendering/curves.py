"""``format=svg`` of every curve endpoint: the polygon p and each companion, from a ``Curve``."""

from __future__ import annotations

import numpy as np

from app.geometry.curve import Curve, Polyline
from app.geometry.errors import NotRepresentableError
from app.rendering.svg import Plot, Series, describe_parameters
from app.responses import ensure_finite

SVG_MEDIA_TYPE = "image/svg+xml"

#: Shown in the legend for the polygon itself.
P_DESCRIPTION = "the discrete hyperbolic cosine p_i"


def drawable(curve: Curve, name: str, polyline: Polyline) -> np.ndarray:
    """A polyline's vertices as float64 for drawing; 422 if they leave the float64 range."""
    points = curve.arithmetic.to_floats(polyline.vertices.reshape(-1)).reshape(-1, 2)
    if not np.all(np.isfinite(points)):
        raise NotRepresentableError(
            "format",
            "coordinates within the float64 range to draw (format=svg)",
            "svg",
            f"the polygon {name!r} has coordinates beyond float64; use format=json or csv",
        )
    return points


def curve_plot(curve: Curve) -> Plot:
    """The plot of one curve response: p first, then the companions in response order."""
    checks = [c for c in curve.checks if c.holds is not None]
    held = sum(1 for c in checks if c.holds)
    plot = Plot(
        title=curve.title,
        subtitle=f"{curve.reference}; {describe_parameters(curve.parameters)}",
        footnote=f"GET /discretizations/{curve.id}: {held} of {len(checks)} checks hold "
        f"({curve.arithmetic.mode}). Equal scales on both axes.",
    )
    plot.add(Series("p", "p", drawable(curve, "p", curve.polygon), description=P_DESCRIPTION))
    for name, polyline in curve.companions.items():
        plot.add(
            Series(
                name,
                name,
                drawable(curve, name, polyline),
                width=1.2,
                description=polyline.description,
            )
        )
    return plot


def curve_svg(curve: Curve) -> bytes:
    """The curve as a self-contained SVG document."""
    ensure_finite(curve)
    return curve_plot(curve).render().encode()
