"""The paper's figures as the API serves them (``GET /figures/{id}.svg``).

Each figure is one ``Figure`` entry in ``FIGURES``: an id, the paper reference, a request model
with the figure's adjustable parameters, the discretizations it draws, and the ``draw`` function
of its module in ``app/rendering/figures/``. The drawing is handed the curves it shows
(``curve``: the registered discretization, validated by its request model and computed in
float64 — the curve endpoints' own code) and returns a ``Plot`` or, for a figure in several
parts, ``Panels``.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from app.geometry.curve import Curve
from app.geometry.precision import Float64
from app.registry import DISCRETIZATIONS
from app.rendering.figures import (
    CurveSource,
    figure_2,
    figure_3,
    figure_4,
    figure_5,
    figure_6,
    figure_7,
    figure_8,
)
from app.rendering.svg import Panels, Plot
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


@dataclass(frozen=True)
class Figure:
    """One of the paper's figures as the API serves it."""

    id: str
    title: str
    reference: str
    description: str
    query: type[FigureQuery]
    draw: Callable[[Any, CurveSource], Plot | Panels]
    """Takes a validated ``query`` instance and the curve source; returns the picture."""
    discretizations: tuple[str, ...] = ()
    """The discretizations whose data it draws (the explorer lists it with them)."""


def curve(identifier: str, **parameters: Any) -> Curve:
    """The curve of a registered discretization for the given request parameters, in float64."""
    entry = DISCRETIZATIONS[identifier]
    query = entry.query.model_validate(parameters, by_name=True)
    return entry.compute(Float64(), **query.core_arguments())


def render(figure: Figure, query: FigureQuery) -> bytes:
    """The figure drawn for ``query`` as SVG bytes."""
    return figure.draw(query, curve).render().encode()


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
        draw=figure_2.draw,
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
        draw=figure_3.draw,
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
        draw=figure_4.draw,
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
        draw=figure_5.draw,
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
        draw=figure_6.draw,
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
        draw=figure_7.draw,
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
        draw=figure_8.draw,
        discretizations=("d2b",),
    ),
)

FIGURES: dict[str, Figure] = {figure.id: figure for figure in _FIGURES}
