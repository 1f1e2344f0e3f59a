"""Section 4: how the discretizations relate.

4.1 Christoffel duals of conformal meshes (Theorems 1–3, eq. (2)); 4.2 the kinematic
construction (Theorems 4–6, eqs. (13), (14), (16)).

Each statement of the paper is defined here once; see ``app.geometry.catalog``.
"""

from __future__ import annotations

from app.geometry.catalog.conditions import (
    D2A_NOT_FOR_D2A,
    D4B_HYPOTHESIS_ALWAYS,
    D4B_HYPOTHESIS_NEEDLESS,
    D4B_LOCAL_NUMBERING,
    D4B_RECURSION_DENOMINATOR,
    D4B_VERTICAL_START,
    EQUATION_2_SOURCE,
    HEX_ONLY_AT_R_STAR,
    HEX_R_ANY,
    HEX_RANGE,
    QUAD_CONVENTIONS,
    QUAD_ONLY_AT_R_STAR,
    QUAD_SPECIAL_R,
)
from app.geometry.checks import Statement

EQUATION_2 = Statement(
    "equation-2",
    "Section 4.1, eq. (2)",
    "Δ²p_i^y = c (A_i + A_{i+1}) with one constant c > 0 (least-squares fit: constants.eq2, or "
    "the check's note where the discretization reports no such constant). "
    "Residual: largest |Δ²p_i^y − c(A_i + A_{i+1})|, relative to the magnitude of the "
    "coordinates (docs/checks.md).",
    conditions=(EQUATION_2_SOURCE, D2A_NOT_FOR_D2A),
)

D4B_HYPOTHESIS = Statement(
    "theorem-4-hypothesis",
    "Theorem 4, hypothesis",
    "d² < p_{i−1}^y p_i^y for every i. Residual: largest max(0, d² − p_{i−1}^y p_i^y)/d². "
    "Every (D4b) polygon satisfies it, since p_{i−1}^y p_i^y ≥ h² > d² (see docs/errata.md).",
    conditions=(D4B_HYPOTHESIS_NEEDLESS,),
)

D4B_THEOREM_4_I = Statement(
    "theorem-4-i",
    "Theorem 4 (i), (D1)",
    "Δ²p_i^y = c (l_i + l_{i+1}) with one constant c > 0 (constants.d1, least-squares fit). "
    "Residual: largest |Δ²p_i^y − c(l_i + l_{i+1})|, relative to the magnitude of the "
    "coordinates it is computed from (docs/checks.md).",
    conditions=(D4B_HYPOTHESIS_ALWAYS,),
    errata=("E2",),
)

D4B_THEOREM_4_II = Statement(
    "theorem-4-ii",
    "Theorem 4 (ii), (D3)",
    "A_i = c l_i with one constant c > 0 (constants.d3, least-squares fit). Residual: largest "
    "|A_i − c l_i|, relative to the magnitude of the coordinates (docs/checks.md).",
    conditions=(D4B_HYPOTHESIS_ALWAYS,),
)

D4B_THEOREM_4_III = Statement(
    "theorem-4-iii",
    "Theorem 4 (iii), eq. (2)",
    "Δ²p_i^y = c (A_i + A_{i+1}) with one constant c > 0 (constants.eq2) and c = c_(D1)/c_(D3). "
    "Residual: the larger of the residuals of (2) with the fitted c and with c = c_(D1)/c_(D3), "
    "each as in theorem-4-i (a difference of the constants themselves would exceed what the "
    "data resolve for small d/h).",
    conditions=(D4B_HYPOTHESIS_ALWAYS,),
)

D4B_ROTATION_ANGLE = Statement(
    "theorem-4-rotation-angle",
    "Proof of Theorem 4",
    "The rotation about p_i, which takes x_{i−1} to x_i, turns by α_i = 2 arctan(d/p_i^y). "
    "Residual: largest |angle(x_{i−1} − p_i, x_i − p_i) − 2 arctan(d/p_i^y)|.",
    conditions=(D4B_LOCAL_NUMBERING,),
    errata=("E1",),
)

D4B_RECURSION_13 = Statement(
    "recursion-13",
    "Proof of Theorem 4, eq. (13)",
    "p_{i+1}^y = (p_i^y³ + 2d²p_i^y + d²p_{i−1}^y) / (p_i^y p_{i−1}^y − d²). "
    "Residual: largest relative difference from the polygon's p_{i+1}^y.",
    conditions=(D4B_RECURSION_DENOMINATOR,),
)

D4B_TWO_STEP = Statement(
    "recursion-13-two-step",
    "Proof of Theorem 4 (i), formula for p_{i+2}^y",
    "p_{i+2}^y = (p_i⁵ + d²(p_{i−1}³ + 2p_{i−1}²p_i + 3p_{i−1}p_i² + 4p_i³) + d⁴(2p_{i−1} + 3p_i))"
    " / (d² − p_{i−1}p_i)² (all heights p^y). Residual: largest relative difference.",
    conditions=(D4B_RECURSION_DENOMINATOR,),
    errata=("E3",),
)

D4B_THEOREM_5 = Statement(
    "theorem-5",
    "Theorem 5, eq. (14)",
    "The closed form p_i = ((2i−1)d, (h−d)^i/(2(h+d)^{i−1}) + (h+d)^i/(2(h−d)^{i−1})) equals the "
    "constructed centres (for a tilted first stick: at the shifted index i + τ, see the "
    "kinematic_closed_forms module). Residual: largest |p_i − closed form| / |closed form|.",
    conditions=(D4B_VERTICAL_START,),
)

D4B_THEOREM_6 = Statement(
    "theorem-6",
    "Theorem 6, eq. (16)",
    "The closed form (16) of the tractrix equals the constructed stick ends d_i. "
    "Residual: largest |d_i − closed form| / (|x_i| + h): d_i = x_i + h u_i is computed to a few "
    "units of that size, and |d_i| itself vanishes for a first stick near the axis.",
    conditions=(D4B_VERTICAL_START,),
)

QUAD_THEOREM_1 = Statement(
    "theorem-1",
    "Theorem 1, eq. (2)",
    "Δ²p_i^y = c (A_i + A_{i+1}) with one constant c (constants.eq2, least squares) equal to "
    "4(f_1 − f_0)³/(f_0 + f_1)³ > 0 (constants.c_theorem_1; the printed c has the wrong sign, "
    "E42). True exactly for r = r* (constants.r_theorem_1): for any other r the polygon is the "
    "same one moved vertically, and (2) fails. Residual: the larger of the residuals of (2) with "
    "the fitted c and with c_theorem_1, each relative to the magnitude of the coordinates it is "
    "computed from (docs/checks.md).",
    conditions=(QUAD_ONLY_AT_R_STAR,),
    errata=("E42",),
)

QUAD_START_HEIGHT = Statement(
    "theorem-1-start-height",
    "Proof of Theorem 1, eq. (5) at i = 1",
    "r* = −f_1(1 + f_0²)/(2(f_1 − f_0)²) is the start height p_0^y for which (2) holds: the "
    "polygon moved vertically by r* − r satisfies (2) with c = 4(f_1 − f_0)³/(f_0 + f_1)³. "
    "Holds for every r. Residual: as for theorem-1's fit, on the moved polygon.",
    conditions=(QUAD_SPECIAL_R,),
)

QUAD_GAUSS_EDGE = Statement(
    "theorem-1-gauss-edge",
    "Proof of Theorem 1, Δφ_{i−1}",
    "φ_i − φ_{i−1} = −2(f_{i−1} − f_i)/((f_{i−1}² + 1)(f_i² + 1)) · (f_{i−1} + f_i, "
    "1 − f_{i−1}f_i), with φ_i = Φ(f_i) (x: symmetry axis, y: distance from it). Residual: "
    "largest |Δφ − formula| / |formula|.",
    conditions=(QUAD_CONVENTIONS,),
)

QUAD_GAUSS_NORM = Statement(
    "theorem-1-gauss-edge-norm",
    "Proof of Theorem 1, ‖Δφ_{i−1}‖²",
    "‖φ_i − φ_{i−1}‖² = 4(f_{i−1} − f_i)²/((f_{i−1}² + 1)(f_i² + 1)). Residual: largest "
    "relative difference.",
    conditions=(QUAD_CONVENTIONS,),
)

QUAD_DUAL_EDGE = Statement(
    "theorem-1-dual-edge",
    "Proof of Theorem 1, Δp_{i−1}",
    "p_i − p_{i−1} = −(f_{i−1} + f_i, 1 − f_{i−1}f_i)/(2(f_{i−1} − f_i)). Residual: largest "
    "|Δp − formula| relative to the magnitude of p_{i−1}, p_i (docs/checks.md).",
    conditions=(QUAD_CONVENTIONS,),
)

QUAD_X_STEP = Statement(
    "theorem-1-x-step",
    "Proof of Theorem 1, the x-step d",
    "p_i^x − p_{i−1}^x = d = (f_{i−1} + f_i)/(2(f_i − f_{i−1})) = (f_0 + f_1)/(2(f_1 − f_0)) for "
    "every i (constants.x_step). Residual: largest |Δp^x − d| relative to the magnitude of "
    "p_{i−1}, p_i.",
    conditions=(QUAD_CONVENTIONS,),
    errata=("E40",),
)

QUAD_SECOND_DIFFERENCE = Statement(
    "theorem-1-second-difference",
    "Proof of Theorem 1, Δ²p_{i−1}",
    "p_{i+1} − 2p_i + p_{i−1} = (0, −(f_i² + 1)/(2f_i)) (printed without the minus sign, E41). "
    "Residual: largest |Δ²p − formula| relative to |p_{i−1}| + 2|p_i| + |p_{i+1}| (coordinates).",
    conditions=(QUAD_CONVENTIONS,),
    errata=("E41",),
)

QUAD_EQUATION_5 = Statement(
    "equation-5",
    "Proof of Theorem 1, eq. (5)",
    "With r = r*, p_{i−1}^y = −(f_i + f_{i−1}²f_i)/(2(f_{i−1} − f_i)²) for every i. Residual: "
    "largest relative difference. Holds only for r = r* (by its definition).",
    conditions=(QUAD_ONLY_AT_R_STAR,),
)

QUAD_HEIGHTS = Statement(
    "theorem-1-heights",
    "Proof of Theorem 1, p_i^y and p_{i+1}^y",
    "With r = r*, p_i^y = −(f_{i−1} + f_{i−1}f_i²)/(2(f_{i−1} − f_i)²) and p_{i+1}^y = "
    "−(f_{i−1}² + f_i⁴)/(2f_i(f_{i−1} − f_i)²) for every i. Residual: largest relative "
    "difference of the two. Holds only for r = r*.",
    conditions=(QUAD_ONLY_AT_R_STAR,),
)

QUAD_AREA_SUM = Statement(
    "theorem-1-area-sum",
    "Proof of Theorem 1, A_{i−1} + A_i",
    "With r = r*, A_{i−1} + A_i = (f_{i−1} + f_i)³(1 + f_i²)/(8f_i(f_{i−1} − f_i)³) (signed "
    "areas; negative, the polygon lies below the x-axis). Residual: largest difference relative "
    "to the magnitude of the areas. Holds only for r = r*.",
    conditions=(QUAD_ONLY_AT_R_STAR,),
)

HEX_THEOREM_2 = Statement(
    "theorem-2",
    "Theorem 2, eq. (7)",
    "Δ²p_i^y = c_1 A_i + c_2 A_{i+1} (i even), c_2 A_i + c_1 A_{i+1} (i odd) with constants "
    "c_1, c_2 (constants.c1, c2: least squares) equal to those of (11) (constants.c1_eq11, "
    "c2_eq11). True exactly for r = r* (constants.r_theorem_2); for any other r (7) fails. "
    "Residual: the larger of the residuals of (7) with the fitted constants and with those of "
    "(11), each relative to the magnitude of the coordinates it is computed from. The "
    "erratum's printed residual is that of (2), which Section 4.1 attributes to Theorem 2.",
    conditions=(HEX_ONLY_AT_R_STAR,),
    errata=("E45",),
)

HEX_START_HEIGHT = Statement(
    "theorem-2-start-height",
    "Proof of Theorem 2, the choice of r",
    "r* = [3a³(λ−1)² − 5a²b(λ−1)λ + 2ab²λ² − b(λ−3)] / [2λ(λ−1)(a−b)²] is the start height for "
    "which (7) holds (printed with the denominator [2λ(λ−1)a − b]², E44): the polygon moved "
    "vertically by r* − r satisfies (7) with c_1, c_2 of (11). Holds for every r. Residual: as "
    "for (7), on the moved polygon.",
    conditions=(HEX_R_ANY,),
    errata=("E44",),
)

HEX_EQUATION_10 = Statement(
    "equation-10",
    "Proof of Theorem 2, eqs. (10) and (11)",
    "Δ³p_i^y = c (A_{i+2} − A_i) with c = c_1 for even i and c = c_2 for odd i, c_1, c_2 from "
    "(11); for every r. Residual: largest |Δ³p_i^y − c(A_{i+2} − A_i)| relative to the magnitude "
    "of the heights and areas it is computed from.",
    conditions=(HEX_R_ANY,),
)

HEX_THEOREM_3_EVEN = Statement(
    "theorem-3-even",
    "Theorem 3, eq. (8)",
    "For even i, p_i = (i(a(λ−6)(λ−1) − b(λ−5)λ)/(4λ(a−b)(λ−1)), r + (a^{−i/2} − b^{−i/2})"
    "(a^{i/2}b(λ−3) + ab^{i/2}(3a(λ−1) − 2bλ)(a(λ−1) − bλ))/(2λ(a−b)²(λ−1))) (the printed "
    "p_i^y has the factor b^{−i/2} − a^{−i/2}, E43). Residual: largest |p_i − closed form| / "
    "|closed form|.",
    conditions=(HEX_RANGE,),
    errata=("E43",),
)

HEX_THEOREM_3_ODD = Statement(
    "theorem-3-odd",
    "Theorem 3, eq. (9)",
    "For odd i, p_i is given by (9) as printed. Residual: largest |p_i − closed form| / "
    "|closed form|.",
    conditions=(HEX_RANGE,),
)
