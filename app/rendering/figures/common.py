"""What the redrawn figures share: panel sizes, colours, drawing aids, data links."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any
from urllib.parse import urlencode

import numpy as np

from app.geometry import elementary
from app.geometry.curve import Curve
from app.rendering.curves import drawable
from app.rendering.svg import Panels, Plot, Series, describe_parameters, segments

#: Size of one panel of a figure in several parts.
PANEL_WIDTH = 560
PANEL_HEIGHT = 500

#: Colours (Okabe–Ito) by role, the same in every figure.
P_COLOUR = "#0072B2"
TRACTRIX_COLOUR = "#D55E00"
DARBOUX_COLOUR = "#009E73"
GAUSS_COLOUR = "#CC79A7"
MESH_COLOUR = "#555555"
GUIDE_COLOUR = "#bbbbbb"
STICK_COLOUR = "#666666"


def source_url(identifier: str, parameters: dict[str, Any]) -> str:
    """The curve request that returns the figure's data as JSON."""
    return f"/discretizations/{identifier}?{urlencode(parameters)}"


def shown_parameters(curve: Curve) -> dict[str, Any]:
    """The curve's effective parameters without ``method`` (for subtitles and data links)."""
    return {k: v for k, v in curve.parameters.items() if k != "method" and v is not None}


def panel(title: str, x_label: str = "x", y_label: str = "y") -> Plot:
    """An empty panel of a figure in several parts (equal scales)."""
    return Plot(
        title=title, x_label=x_label, y_label=y_label, width=PANEL_WIDTH, height=PANEL_HEIGHT
    )


def unit_circle(count: int = 241) -> np.ndarray:
    """The unit circle as a closed polyline (a drawing aid for the Gauss images)."""
    t = np.linspace(0, 2 * np.pi, count)
    return np.stack([elementary.cos(t), elementary.sin(t)], axis=1)


def unit_circle_series() -> Series:
    return Series(
        "unit_circle",
        "unit circle",
        unit_circle(),
        color=GUIDE_COLOUR,
        markers=False,
        width=1,
        description="the meridian of the unit sphere",
    )


def mesh_series(name: str, label: str, vertices: np.ndarray, edges: np.ndarray) -> Series:
    """Every edge of a planar mesh as one segments series."""
    return Series(
        name,
        label,
        segments(vertices[edges[:, 0]], vertices[edges[:, 1]]),
        kind="segments",
        color=MESH_COLOUR,
        width=0.8,
        description=f"{len(edges)} edges",
    )


def gauss_and_dual_panels(curve: Curve, figures: Panels) -> None:
    """The centre and right panels of Figures 5 and 6: φ_i on the unit circle, and p_i."""
    gauss = drawable(curve, "gauss_image", curve.companions["gauss_image"])
    p = drawable(curve, "p", curve.polygon)
    centre = panel("Gauss image meridian φ_i = Φ(f_i)")
    centre.add(unit_circle_series())
    centre.add(
        Series(
            "gauss_image",
            "φ_i",
            gauss,
            color=GAUSS_COLOUR,
            description="stereographic images of the f_i",
        )
    )
    figures.add("centre", centre)
    right = panel("Christoffel dual p_i")
    right.add(
        Series("p", "p_i", p, color=P_COLOUR, width=2, description="the discrete hyperbolic cosine")
    )
    figures.add("right", right)


def christoffel_figure(
    curve: Curve,
    title: str,
    mesh_note: str,
    data_note: str,
    mesh: tuple[str, str, Any],
    conformal_description: str,
) -> Panels:
    """Figures 5 and 6: the planar conformal mesh with the f_i on it, the Gauss image and p.

    ``mesh`` is (panel title, series label, mesh with ``vertices`` and ``edges``).
    """
    shown = shown_parameters(curve)
    figures = Panels(
        title=title,
        subtitle=f"{describe_parameters(shown)}; {mesh_note}",
        footnote=f"Data: GET {source_url(curve.id, shown)} (p, φ_i; {data_note})",
    )
    panel_title, label, grid = mesh
    left = panel(panel_title, "y", "z")
    left.add(mesh_series("mesh", label, grid.vertices, grid.edges))
    left.add(
        Series(
            "conformal",
            "f_i",
            drawable(curve, "conformal", curve.companions["conformal"]),
            kind="points",
            color=P_COLOUR,
            description=conformal_description,
        )
    )
    figures.add("left", left)
    gauss_and_dual_panels(curve, figures)
    return figures


CurveSource = Callable[..., Curve]
"""``curves(identifier, **parameters) -> Curve``: a discretization's curve, computed by the service
(the same code as the curve endpoints) and handed to the drawing."""
