"""The paper's figures, redrawn from computed data (``GET /figures/{id}.svg``).

Each figure is one ``Figure`` entry in ``FIGURES``: an id, the paper reference, a request model
with the figure's adjustable parameters, the discretizations it draws, and a ``draw`` function
that computes the data through the discretization registry (the same code as the curve
endpoints; the smooth references and the planar meshes through the core's functions) and returns
a ``Plot`` or, for a figure in several parts, ``Panels``. Nothing here computes geometry beyond
averaging two points for a marker; the unit circle of the Gauss images is a drawing aid.
Adding a figure means writing its request model and ``draw``, and one entry in ``_FIGURES``.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any
from urllib.parse import urlencode

import numpy as np

from app.geometry.curve import Curve
from app.geometry.d2a import construction as christoffel
from app.geometry.precision import Float64
from app.geometry.smooth import curves as smooth, references as smooth_curves
from app.registry import DISCRETIZATIONS
from app.rendering.curves import drawable
from app.rendering.svg import Panels, Plot, Series, describe_parameters, segments
from app.schemas.d4b import stick_angle
from app.schemas.figures import (
    Figure2Query,
    Figure3Query,
    Figure4Query,
    Figure5Query,
    Figure6Query,
    Figure7Query,
    Figure8Query,
    FigureQuery,
)

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


@dataclass(frozen=True)
class Figure:
    """One of the paper's figures as the API serves it."""

    id: str
    title: str
    reference: str
    description: str
    query: type[FigureQuery]
    draw: Callable[[Any], Plot | Panels]
    """Takes a validated ``query`` instance; returns the picture."""
    discretizations: tuple[str, ...] = ()
    """The discretizations whose data it draws (the explorer lists it with them)."""


def curve_of(identifier: str, **arguments: Any) -> Curve:
    """A curve computed in float64 by the registered discretization (the curve endpoints' code)."""
    return DISCRETIZATIONS[identifier].compute(Float64(), **arguments)


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
    return np.stack([np.cos(t), np.sin(t)], axis=1)


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


# --- Figure 2 (right): the smooth tractrix and its evolute, (S4) ---------------------------------


def triangle_samples(x: np.ndarray, count: int) -> np.ndarray:
    """``count`` sample numbers spread evenly over the samples, skipping the cusp x = 0."""
    if count == 0:
        return np.zeros(0, dtype=np.int64)
    chosen = np.unique(np.round(np.linspace(0, len(x) - 1, count + 2)[1:-1]).astype(np.int64))
    kept: np.ndarray = chosen[x[chosen] != 0]
    return kept


def draw_figure_2(query: Figure2Query) -> Plot:
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


# --- Figure 3: (D4a), Sauer's discrete tractrix --------------------------------------------------


def draw_figure_3(query: Figure3Query) -> Plot:
    """Figure 3: sticks x_i d_i, tractrix d_i, midpoints, Darboux transform e_i and p_i."""
    curve = curve_of(
        "d4a",
        h=query.h,
        s=query.s,
        beta0=stick_angle(query.beta0),
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


# --- Figures 5 and 6: (D2a), Christoffel duals of conformal meshes --------------------------------


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


def draw_figure_5(query: Figure5Query) -> Panels:
    """Figure 5: the planar conformal quad mesh, its Gauss image meridian and p (D2a, quad)."""
    curve = curve_of(
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


def draw_figure_6(query: Figure6Query) -> Panels:
    """Figure 6: a conformal hexagonal mesh, its Gauss image meridian and p (D2a, hexagonal)."""
    curve = curve_of(
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


# --- Figure 7: Theorems 7 and 8, Gauss images of the (D4b) tractrix and catenoid ------------------


def draw_figure_7(query: Figure7Query) -> Panels:
    """Figure 7: tractrix d_i, inscribed n_i (18), circumscribed m_i (20) with contact points."""
    curve = curve_of("d4b", h=query.h, d=query.d, i_min=query.i_min, i_max=query.i_max)
    tractrix = drawable(curve, "tractrix", curve.companions["tractrix"])
    axis = drawable(curve, "axis_points", curve.companions["axis_points"])
    inscribed = drawable(curve, "tractrix_gauss_image", curve.companions["tractrix_gauss_image"])
    contact = drawable(curve, "contact_points", curve.companions["contact_points"])
    circumscribed = drawable(curve, "gauss_image", curve.companions["gauss_image"])
    shown = shown_parameters(curve)
    figures = Panels(
        title="Figure 7: Gauss images of the discrete pseudosphere and catenoid (D4b)",
        subtitle=describe_parameters(shown),
        footnote=f"Data: GET {source_url('d4b', shown)} (tractrix, tractrix_gauss_image, "
        "contact_points, gauss_image)",
    )
    left = panel("Discrete tractrix d_i (Theorem 6)")
    left.add(
        Series(
            "sticks",
            "sticks",
            segments(axis, tractrix),
            kind="segments",
            color=STICK_COLOUR,
            width=1,
            description="x_i d_i, of length h",
        )
    )
    left.add(
        Series("tractrix", "d_i", tractrix, color=TRACTRIX_COLOUR, width=2, description="(16)")
    )
    figures.add("left", left)
    centre = panel("Inscribed Gauss image n_i (Theorem 7)")
    centre.add(unit_circle_series())
    centre.add(
        Series(
            "tractrix_gauss_image",
            "n_i",
            inscribed,
            color=GAUSS_COLOUR,
            width=2,
            description="(18): on the unit circle, edges parallel to d_i",
        )
    )
    figures.add("centre", centre)
    right = panel("Circumscribed Gauss image m_i (Theorem 8)")
    right.add(unit_circle_series())
    right.add(
        Series(
            "chords",
            "ñ_{i−1} ñ_i",
            segments(contact[:-1], contact[1:]),
            kind="segments",
            color=GUIDE_COLOUR,
            width=1,
            description="m_i is the midpoint of this chord reflected in the circle",
        )
    )
    right.add(
        Series(
            "contact_points",
            "ñ_i",
            contact,
            kind="points",
            color="#000000",
            description="(19): where the edges touch the circle",
        )
    )
    right.add(
        Series(
            "gauss_image",
            "m_i",
            circumscribed,
            color=GAUSS_COLOUR,
            width=2,
            description="(20): edges tangent to the circle, parallel to p",
        )
    )
    figures.add("right", right)
    return figures


# --- Figure 8: Theorem 11 with the sequences of Example 12 ---------------------------------------


def draw_figure_8(query: Figure8Query) -> Panels:
    """Figure 8: n^j and p^j for the first j, then p^j for every j with an ε-band about cosh."""
    curves = [curve_of("d2b", sequence=query.sequence, j=j) for j in query.j]
    first = curves[0]
    polygons = [drawable(c, "p", c.polygon) for c in curves]
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


_FIGURES = (
    Figure(
        id="figure-2",
        title="Figure 2 (right): a tractrix and its evolute, the hyperbolic cosine",
        reference="Section 2, (S4); Figure 2 (right)",
        description="The smooth tractrix d with stick h, its evolute p (the centres of "
        "curvature, computed from d's derivatives) on the catenary h·cosh(x/h), and Nikolaides' "
        "triangles (x, 0), p(x), d(x), right-angled at d(x). The data are those of GET "
        "/smooth/tractrix with the same parameters.",
        query=Figure2Query,
        draw=draw_figure_2,
    ),
    Figure(
        id="figure-3",
        title="Figure 3: Sauer's discrete tractrix, its Darboux transform and p",
        reference="Section 3, (D4a); Figure 3",
        description="Sauer's discrete tractrix (D4a): the sticks x_i d_i of length h, the "
        "tractrix d_i with |d_{i+1} − d_i| = s, the midpoints of consecutive tractrix points, "
        "the Darboux transform e_i (x_i reflected in those midpoints) and the discrete "
        "hyperbolic cosine p_i on the symmetry lines of the tractrix edges. The data are those "
        "of GET /discretizations/d4a with the same parameters.",
        query=Figure3Query,
        draw=draw_figure_3,
        discretizations=("d4a",),
    ),
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
        discretizations=("d4b",),
    ),
    Figure(
        id="figure-5",
        title="Figure 5: a planar conformal quad mesh and its Christoffel dual meridian",
        reference="Section 4.1, Theorem 1; Figure 5",
        description="Left: the rotationally symmetric conformal quad mesh of the yz-plane through "
        "f_i = f_0 (f_1/f_0)^i (eq. (3)): vertices f_i e^{ijv}, every quad with a a'/(b b') = "
        "−1, which fixes sin(v/2) = (f_1 − f_0)/(2√(f_0 f_1)) (so f_1/f_0 < 3 + 2√2). Centre: "
        "the stereographic images φ_i on the unit circle. Right: the Christoffel dual p_i "
        "(eq. (4)). p and φ are those of GET /discretizations/d2a-quad with the same parameters; "
        "the mesh's column 0 is its `conformal` companion.",
        query=Figure5Query,
        draw=draw_figure_5,
        discretizations=("d2a-quad",),
    ),
    Figure(
        id="figure-6",
        title="Figure 6: a conformal hexagonal mesh and its Christoffel dual meridian",
        reference="Section 4.1, Theorems 2, 3; Figure 6",
        description="Left: a rotationally symmetric hexagonal mesh of the yz-plane whose ray 0 "
        "carries f_i (even: f_i = f_{i−2} b/a; odd: f_i = λ f_{i+1} + (1 − λ) f_{i−1}); the "
        "meridian runs alternately along an edge and across a hexagon, and every hexagon has "
        "multi-ratio −1 ([10]'s conformality) whatever the angle π/m between the rays. Centre: "
        "the stereographic images φ_i. Right: the Christoffel dual p_i with the factors 3 and 2 "
        "of eq. (6). p and φ are those of GET /discretizations/d2a-hex with the same parameters; "
        "the mesh's ray 0 is its `conformal` companion.",
        query=Figure6Query,
        draw=draw_figure_6,
        discretizations=("d2a-hex",),
    ),
    Figure(
        id="figure-7",
        title="Figure 7: the discrete tractrix and the Gauss images n (inscribed), m "
        "(circumscribed)",
        reference="Section 5, Theorems 6-8, eqs. (16), (18)-(20); Figure 7",
        description="Left: the discrete tractrix d_i of (D4b) (Theorem 6; stick 0 vertical). "
        "Centre: the inscribed Gauss image n_i of the pseudosphere (18), edges parallel to the "
        "tractrix (Theorem 7). Right: the circumscribed Gauss image m_i of the catenoid (20), "
        "its edges tangent to the unit circle at the contact points ñ_i (19); m_i is the midpoint "
        "of the chord ñ_{i−1} ñ_i reflected in the circle (Theorem 8). The data are those of GET "
        "/discretizations/d4b with the same parameters.",
        query=Figure7Query,
        draw=draw_figure_7,
        discretizations=("d4b",),
    ),
    Figure(
        id="figure-8",
        title="Figure 8: Theorem 11, discrete catenoids converging to the catenoid",
        reference="Section 6, Theorem 11, Example 12; Figure 8",
        description="Left: the Gauss image meridian n^j inscribed in the unit circle for the "
        "first j; centre: the discrete hyperbolic cosine p^j with edges parallel to n^j (D2b); "
        "right: p^j for every j with the ε-neighbourhood of C = {(x, cosh x)} (bounded by the "
        "parallel curves of C at distance ε). The polygons are those of GET "
        "/discretizations/d2b?sequence=…&j=… with the default ranges; C is GET "
        "/smooth/catenary over their x-range.",
        query=Figure8Query,
        draw=draw_figure_8,
        discretizations=("d2b",),
    ),
)

FIGURES: dict[str, Figure] = {figure.id: figure for figure in _FIGURES}
