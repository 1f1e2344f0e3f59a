"""Section 3: the definitions (D1)–(D4b) and the facts the text states about each.

Each statement of the paper is defined here once; see ``app.geometry.catalog``.
"""

from __future__ import annotations

from app.geometry.catalog.conditions import (
    D1_CLOSED_FORM_RANGE,
    D1_RANGE,
    D2A_NOT_FOR_D2A,
    D2B_GAUSS_IMAGE_CHOICE,
    D3_CLOSED_FORM_RANGE,
    D3_FOLDS,
    D3_RANGE,
    D4A_CUSP,
    D4A_DARBOUX_SIDES,
    D4A_INDEXING,
    D4A_RESOLUTION,
    D4B_CENTRE_INDEX,
    D4B_POINT_REFLECTION,
    EQUILIBRIUM_SPACING,
    SPACING,
)
from app.geometry.checks import Statement

D1 = Statement(
    "d1",
    "Section 3, (D1)",
    "Δ²p_i^y = c (l_i + l_{i+1}) with one constant c > 0 (least-squares fit: constants.d1, or "
    "the check's note where the discretization reports no such constant). "
    "Residual: largest |Δ²p_i^y − c(l_i + l_{i+1})|, relative to the magnitude of the "
    "coordinates it is computed from (docs/checks.md). On a polygon that does not satisfy (D1) "
    "the check fails and the residual says by how much.",
    conditions=(SPACING, D1_RANGE, D2A_NOT_FOR_D2A),
)

D3 = Statement(
    "d3",
    "Section 3, (D3)",
    "A_i = c l_i with one constant c > 0 (least-squares fit: constants.d3, or the check's note "
    "where the discretization reports no such constant): the area under each edge is c times "
    "its length. Residual: largest |A_i − c l_i|, relative to the magnitude of the coordinates "
    "(docs/checks.md).",
    conditions=(SPACING, D3_RANGE, D3_FOLDS, D2A_NOT_FOR_D2A),
)

HANGING_STICKS = Statement(
    "hanging-sticks",
    "Section 3, after (D1): sticks hanging from hinges",
    "Homogeneous sticks on the edges, joined by weightless hinges, hang in equilibrium: with a "
    "constant horizontal tension the edge slopes k_i satisfy k_{i+1} − k_i = c (l_i + l_{i+1}) "
    "(constants.equilibrium = weight per length / (2 · horizontal tension)). With constant "
    "x-spacing δ this is (D1) divided by δ; otherwise it is a different condition (see "
    "docs/errata.md). Residual: as for (D1), with the magnitudes of the slopes.",
    conditions=(EQUILIBRIUM_SPACING,),
)

D1_CLOSED_FORM = Statement(
    "d1-closed-form",
    "Section 3, (D1) with constant spacing: closed form (derived here, not in the paper)",
    "p_i = (iδ, C + a cosh(u_0 + (i − ½)E)) with E = 2 artanh c, a = δ√(1 − c²)/(2c), "
    "u_0 = arsinh((y_1 − y_0)/δ), C = y_0 − a cosh(u_0 − E/2): the slope angles advance by E "
    "per edge, tanh((u_{i+1} − u_i)/2) = c. Evaluated as y_0 + 2a sinh(iE/2) sinh(u_0 + "
    "(i − 1)E/2) (no cancellation). Residual: largest |p_i − closed form| divided by "
    "|iδ| + |y_0| + |2a sinh(…) sinh(…)|, the size of the closed form's terms.",
    conditions=(D1_CLOSED_FORM_RANGE,),
)

D3_CLOSED_FORM = Statement(
    "d3-closed-form",
    "Section 3, (D3) with constant spacing: closed form (derived here, not in the paper)",
    "p_i = (iδ, a cosh(v_0 ± 2iD)) with tanh D = δ/(2c), a = √(c² − δ²/4), cosh v_0 = y_0/a "
    "(v_0 ≥ 0), + for branch=up and − for branch=down: the catenary of amplitude a sampled every "
    "2D of its argument. Residual: largest |p_i − closed form| / |closed form|; near the "
    "lowest point (argument v_min) rounding grows like 1/v_min and the tolerance allows it.",
    conditions=(D3_CLOSED_FORM_RANGE,),
)

D4A_STICKS = Statement(
    "d4a-sticks",
    "Section 3, (D4a) and Figure 3",
    "Every stick has length h and its end x_i on the x-axis, and the tractrix edge it carries "
    "lies on it with its far end at distance h − s from x_i: d_{i+1} on stick i for i ≥ c, "
    "d_{i−1} on stick i for i < c (c the cusp stick; see the d4a description). Residual: "
    "largest of | |d_i − x_i| − h |, |x_i^y| and the distance of the far end from "
    "x_i + (h − s)(d_i − x_i)/|d_i − x_i|, relative to the magnitude of the points.",
    conditions=(D4A_CUSP,),
    errata=("E20",),
)

D4A_ARC_LENGTH = Statement(
    "d4a-arc-length",
    "Section 3, (D4a) and Figure 3: discrete arc length",
    "|d_{i+1} − d_i| = s for every i: the tractrix is parametrized by arc length. Residual: "
    "largest | |d_{i+1} − d_i| − s |, relative to the magnitude of the two points.",
    conditions=(D4A_CUSP,),
)

D4A_DARBOUX = Statement(
    "darboux-d4a",
    "Section 3, (D4a): Darboux transform",
    "e_i, the reflection of x_i in the midpoint of the tractrix edge on stick i, has "
    "|e_{i+1} − e_i| = |x_{i+1} − x_i|. Residual: largest difference of the edge lengths, "
    "relative to the magnitude of the four points.",
    conditions=(D4A_DARBOUX_SIDES,),
    errata=("E21",),
)

D4A_DARBOUX_DISTANCE = Statement(
    "darboux-d4a-distance",
    "Section 3, (D4a): Darboux transform",
    "|x_i − e_i| is the same for every i, namely 2h − s. Residual: largest | |x_i − e_i| − "
    "(2h − s) |, relative to the magnitude of x_i and e_i.",
    conditions=(D4A_DARBOUX_SIDES,),
    errata=("E21",),
)

D4A_ROTATION = Statement(
    "rotation-centre-d4a",
    "Section 3, (D4a): p_i as a centre of rotation",
    "p_i is the centre of the rotation taking stick i to stick i+1: |p_i − x_i| = "
    "|p_i − x_{i+1}|, |p_i − d_i| = |p_i − d_{i+1}|, and the angle from x_i to x_{i+1} about p_i "
    "equals the angle from d_i to d_{i+1}. Residual: largest of the distance differences "
    "(relative to the magnitude of the points) and the angle difference (radians).",
    conditions=(D4A_INDEXING, D4A_RESOLUTION),
)

D4A_NIKOLAIDES = Statement(
    "nikolaides-d4a",
    "Section 3, (D4a) and (S4): construction of Nikolaides",
    "The symmetry axis of x_i and x_{i+1} passes through p_i: p_i^x = (x_i^x + x_{i+1}^x)/2. "
    "Residual: largest |p_i^x − (x_i^x + x_{i+1}^x)/2|, relative to the magnitude of the points.",
    conditions=(D4A_INDEXING, D4A_RESOLUTION),
)

D4A_CLOSED_FORM = Statement(
    "d4a-closed-form",
    "Section 3, (D4a): explicit form (derived here, not in the paper)",
    "With k = 1 − s/h and the cusp stick c: sin β_i = sin β_c k^{|i − c|}, d_i = x_i + "
    "h(cos β_i, sin β_i), x_{i+1} − x_i = h(k cos β_i − cos β_{i+1}) for i ≥ c and "
    "h(cos β_i − k cos β_{i+1}) for i < c (partial sums from x_0 = 0), and p_i = ((x_i + "
    "x_{i+1})/2, (h − s/2 − (x_{i+1} − x_i) cos β_i / 2)/sin β_i). Residual: largest "
    "|computed − explicit| over p_i (relative to |p_i|) and d_i (relative to the magnitude of "
    "d_i and x_i).",
    conditions=(D4A_RESOLUTION,),
)

D4B_DARBOUX = Statement(
    "darboux-d4b",
    "Section 3, (D4b): Darboux transform",
    "e_i, the reflection of x_i in d_i, has |e_{i+1} − e_i| = |x_{i+1} − x_i| = 2d. "
    "Residual: largest difference of the edge lengths, relative to the magnitude of the four "
    "points (docs/checks.md).",
    conditions=(D4B_POINT_REFLECTION,),
)

D4B_DARBOUX_DISTANCE = Statement(
    "darboux-d4b-distance",
    "Section 3, (D4b): Darboux transform",
    "|x_i − e_i| is the same for every i, namely 2h. Residual: largest | |x_i − e_i| − 2h |, "
    "relative to the magnitude of x_i and e_i (docs/checks.md).",
    conditions=(D4B_POINT_REFLECTION,),
)

D4B_NIKOLAIDES = Statement(
    "nikolaides-d4b",
    "Section 3, (D4b) and (S4): construction of Nikolaides",
    "The triangles x_i d_i p_i and x_i d_i p_{i+1} have a right angle at d_i: the edge p_i p_{i+1}"
    " is the tractrix normal at d_i. Residual: largest |cos| of the angles at d_i, with the "
    "vectors measured against the magnitude of their end points (docs/checks.md).",
    conditions=(D4B_CENTRE_INDEX,),
)

D2B_MEAN_CURVATURE = Statement(
    "d2b-mean-curvature",
    "Section 3, (D2b)",
    "The catenoid generated by p has H = 0 on every face with respect to the Gauss image "
    "generated by n (mixed-area definition [3], three-dimensional faces). Residual: largest "
    "|A(f, n)| relative to the magnitude of the mixed area.",
    conditions=(D2B_GAUSS_IMAGE_CHOICE,),
)

D2B_PARALLEL = Statement(
    "d2b-parallel",
    "Section 3, (D2b); proof of Theorem 11",
    "Corresponding edges of p and n are parallel. Residual: largest |e(p) × e(n)| relative to "
    "the magnitudes of the end points.",
    conditions=(D2B_GAUSS_IMAGE_CHOICE,),
)
