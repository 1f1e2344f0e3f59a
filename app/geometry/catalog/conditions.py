"""Implicit hypotheses and conventions of the statements, in words (docs/errata.md)."""

from __future__ import annotations

S4_LEADER = (
    "The tractrix is parametrized by the leader's position x on the axis: d(x) = (x − h "
    "tanh(x/h), h/cosh(x/h)), two branches meeting at the cusp d(0) = (0, h)."
)

S4_CUSP = (
    "At the cusp x = 0 the tangent vanishes (d'(0) = 0) and the centre of curvature is a "
    "limit, (0, h): the check skips that point."
)

SPACING = (
    "(D1) and (D3) say nothing about the x-coordinates ((D1) constrains heights only, (D3) "
    "leaves one degree of freedom per vertex); the service's (D1) and (D3) polygons have a "
    "constant spacing δ, p_i = (iδ, y_i). The constant is then not the smooth one: h cosh(x/h) "
    "solves (S1) with c = 1/h, while a polygon sampling it has c_(D1) = δ/(2h)."
)

D1_RANGE = (
    "(D1) needs 0 < c < 1: for c >= 1 no next vertex exists. For 0 < c < 1 every (D1) polygon "
    "with spacing δ is y_i = C + a cosh(u_0 + (i − ½)E), E = 2 artanh c, a = δ√(1 − c²)/(2c), "
    "with an offset C that (D1) cannot see; it satisfies (D3) and eq. (2) exactly when C = 0."
)

D3_RANGE = (
    "(D3) with spacing δ needs 0 < δ < 2c and y0 >= √(c² − δ²/4): otherwise the step's "
    "quadratic has no real root, or only one admissible root and the polygon zig-zags across "
    "the axis."
)

D3_FOLDS = (
    "Each step has two admissible roots, the two directions along one catenary a cosh(v ± 2D) "
    "(tanh D = δ/(2c)); one of them is the previous vertex, and taking it folds the polygon "
    "back: such zig-zags satisfy (D3) but not (D1). 'Not contained in a line' excludes the "
    "horizontal line y = c, which has A_i = c l_i. A (D3) polygon that does not fold back "
    "satisfies (D1) (c = δ/(2c)), eq. (2) and the hanging-sticks equilibrium."
)

EQUATION_2_SOURCE = (
    "(D1) and (D3) imply (2) with c = c_(D1)/c_(D3) (proof of Theorem 4 (iii)); the converse "
    "fails: the (D2a) quad polygon satisfies (2) but neither (D1) nor (D3). Section 4.1's "
    "'(2) is fulfilled by polygons constructed in (D2a) … Theorems 1 and 2' holds for the quad "
    "polygons only; the hexagonal ones satisfy the modified (7), not (2) (E45)."
)

EQUILIBRIUM_SPACING = (
    "'(D1) implies a position of equilibrium' holds only for a constant horizontal spacing: "
    "force and moment balance of homogeneous sticks on weightless hinges give "
    "T(k_{i+1} − k_i) = (w/2)(l_i + l_{i+1}) for the slopes k_i, which is (D1) divided by δ "
    "when the spacing is δ; sticks of unequal extents in equilibrium miss (D1)."
)

D1_CLOSED_FORM_RANGE = (
    "Derived here (not in the paper) for 0 < c < 1 and a constant spacing δ; it is evaluated as "
    "y_0 + 2a sinh(iE/2) sinh(u_0 + (i − 1)E/2), which does not cancel for small c (a >> |y|)."
)

D3_CLOSED_FORM_RANGE = (
    "Derived here (not in the paper) for a polygon that does not fold back, with spacing "
    "0 < δ < 2c and y0 >= a = √(c² − δ²/4). Next to the lowest point (v near 0) the step is "
    "ill-conditioned by nature (dw/dy = sinh(v ± 2D)/sinh v): the tolerance allows 1/v_min."
)

D4A_CUSP = (
    "'d_i on the previous stick for all i ∈ Z' is impossible (E20): sin β_i = (1 − s/h)^i "
    "sin β_0 would exceed 1. The pursuit runs away from a cusp stick c on both sides: d_i lies "
    "on stick i − 1 for i > c and on stick i + 1 for i < c, and the tractrix folds back there "
    "(d_{c−1} = d_{c+1}); for a vertical stick 0, c = 0."
)

D4A_DARBOUX_SIDES = (
    "e_i reflects x_i in the midpoint of the tractrix edge that lies on stick i: d_i d_{i+1} "
    "after the cusp, d_{i−1} d_i before it (E21); the constant |x_i − e_i| = 2h − s is not "
    "printed."
)

D4A_INDEXING = (
    "Index convention: p_i is the centre of the rotation from stick i to stick i + 1 (the "
    "symmetry lines of the tractrix edges on sticks i and i + 1 meet there); it lies over the "
    "midpoint of x_i x_{i+1}, so the x-spacing of p is not constant, unlike (D4b)'s."
)

D4A_RESOLUTION = (
    "Consecutive symmetry lines meet at an angle of about (s/h) sin β, so p is resolved to "
    "about ⌈h/s⌉ + (sticks walked) units of rounding: float64 requests need s/h >= 10⁻³ (use "
    "precision=mp below)."
)

D4B_HYPOTHESIS_NEEDLESS = (
    "Stated needlessly for (D4b): every (D4b) polygon has p_{i−1}^y p_i^y >= h² > d², for every "
    "0 < d < h and every first stick; the condition matters only for sequences that merely "
    "satisfy (13) (docs/errata.md, Section 3, implicit conditions)."
)

D4B_HYPOTHESIS_ALWAYS = (
    "Theorem 4's hypothesis d² < p_{i−1}^y p_i^y always holds for (D4b) (theorem-4-hypothesis), "
    "so the statement holds for every 0 < d < h."
)

D4B_LOCAL_NUMBERING = (
    "The proof numbers the axis points locally, shifted by one against Section 3 and Theorem 5: "
    "with Theorem 5's indexing (p_i^x = (2i − 1)d) α_i is the angle at p_i between the lines to "
    "x_{i−1} and x_i (E1)."
)

D4B_RECURSION_DENOMINATOR = (
    "For (D4b) polygons the denominator p_{i−1}^y p_i^y − d² is always >= h² − d² > 0; for "
    "sequences that merely satisfy (13) it must not vanish (Theorem 4's hypothesis)."
)

D4B_VERTICAL_START = (
    "Assumes a vertical first stick (d_0^y = p_1^y = h). For a first stick at angle beta0 the "
    "construction is the vertical one shifted by the index τ = ln(tan(β0/2))/L, and the service "
    "checks the formula at i + τ (an extension; docs/errata.md, Section 3)."
)

D4B_POINT_REFLECTION = (
    "Here x_i is reflected in the tractrix point d_i itself (e_i = 2d_i − x_i, so |x_i − e_i| = "
    "2h), not in an edge midpoint as in (D4a); the edges of e and x are equal because the "
    "polygon is symmetric about the reflection axis of each tractrix edge, for every first "
    "stick."
)

D4B_CENTRE_INDEX = (
    "Index convention (Theorem 5): p_i is the centre of the rotation from stick i − 1 to stick "
    "i, over the midpoint of x_{i−1} and x_i, so the reflection axis of x_{i−1} and x_i passes "
    "through p_i."
)

D4B_FIRST_NORMAL = (
    "The inscribed Gauss images parallel to the tractrix are a one-parameter family (the "
    "choice of n_0); Theorem 7 needs n_0 = (±1, 0), the normal of the vertical stick 0 "
    "(another n_0 zig-zags and K is not constant). For a tilted first stick (an extension) "
    "the service starts at the unit normal of stick 0, and Theorem 7 holds for every β0."
)

D4B_VERTICAL_STICK = (
    "The closed forms (18)–(20) assume a vertical first stick (d_0^y = p_1^y = h), as (14) and "
    "(16) do; for a tilted one the service evaluates them at the shifted index i + τ."
)

D4B_SLOPE_SIGN = (
    "k_{i+1} = (p_{i+1}^y − p_i^y)/2d is the slope of the edge p_i p_{i+1} (12); n_i has its "
    "sign, which the printed square roots drop (E61)."
)

D4B_CONTACT_SIDE = (
    "ñ_i is the unit normal of the edge p_i p_{i+1} on the side away from the axis; the "
    "rotation by 90° relates the corrected (18) and (19) (E60, E62)."
)

D4B_POLE = (
    "m_i needs the two edges at p_i (ñ_{i−1} and ñ_i): it is defined at interior vertices, so "
    "the service builds p one index beyond each end of the range."
)

D4B_APPROXIMATES_SPHERE = (
    "|m_i|² = 1 + (d²/(h² − d²)) sech²((i − ½)L) > 1: the Gauss image lies outside the sphere "
    "and approaches it as d → 0, as the text says ('approximates a sphere')."
)

D4B_ZERO_OVER_ZERO = (
    "(17) is 0/0 on the ring between p_0 = (−d, h) and p_1 = (d, h) (equal heights); the "
    "mixed-area definition still gives H = 0 there, and the check evaluates every face."
)

QUAD_ONLY_AT_R_STAR = (
    "Holds only for the start height r = r* = −f_1(1 + f_0²)/(2(f_1 − f_0)²), which the proof "
    "calls 'that special r' without writing it out; r* is the default of r (docs/errata.md, "
    "Section 4.1)."
)

QUAD_SPECIAL_R = (
    "r* = −f_1(1 + f_0²)/(2(f_1 − f_0)²) is (5) at i = 1, the proof's 'special r' (never "
    "written out); other r move the polygon vertically, and Theorem 1 then fails."
)

QUAD_CONVENTIONS = (
    "Conventions the proof relies on without stating them: φ_i = Φ(f_i) with Φ(f) = "
    "(f² − 1, 2f)/(f² + 1) (projection from (1, 0, 0) restricted to the y-axis); the first "
    "coordinate is the axis x, the second the distance y; Δφ_i = φ_{i+1} − φ_i; p_0 = (0, r). "
    "With them (4) has constant x-steps and the polygon lies below the axis, as (5) says."
)

HEX_ONLY_AT_R_STAR = (
    "Holds only for the start height r* of the proof of Theorem 2 (with the denominator "
    "corrected, E44), the default of r; and unlike (2), c_1 and c_2 need not be positive "
    "(docs/errata.md, Section 4.1)."
)

HEX_R_ANY = (
    "Holds for every start height r: (10) and the constants of (11) do not depend on r (the "
    "proof says so), while (7) itself needs r = r* (E44)."
)

HEX_RANGE = (
    "0 < a < b and 0 < λ < 1 (at a = b, λ = 0 or 1 two consecutive f_i coincide and the dual "
    "edge is infinite); every r (p_0 = (0, r))."
)

D2A_NOT_FOR_D2A = (
    "A property of other discretizations, tested here to show Section 4's 'not equivalent': "
    "the (D2a) polygons do not satisfy it (quad: (D1), (D3); hexagonal: (D1), (D3), (2)), so the "
    "check reports holds: false on them (GET /relations; docs/errata.md, Section 4.1)."
)

D2B_GAUSS_IMAGE_CHOICE = (
    "(D2b) does not say which Gauss image; Section 6 uses the inscribed n_i = (s_i, "
    "√(1 − s_i²)) with s strictly increasing, |s_i| < 1 and s_0 = 0, and p_0 = (0, 1): what the "
    "service builds (H in the mixed-area sense of [3], with the sign convention of (17))."
)

D2B_START = (
    "The telescoping needs p_0^y = n_0^y = 1 (Theorem 11's p_0 = (0, 1, 0) and s_0 = 0) and "
    "n_i^y > 0 (|s_i| < 1)."
)

D2B_RECURSION_DIVIDES = (
    "The recursion divides by Δn_{i−1}^y, which vanishes where s_i = −s_{i−1} and rounds to 0 "
    "in float64 near s = 0 (Example 12 at small i): the check multiplies it out."
)

D2B__EXAMPLE_DOMAIN = (
    "Example 12 is defined on i >= 0 only: s_i = 4i²/(j² + 4i²) is even in i, hence not "
    "strictly increasing on Z, and g(x) = 4x²/(1 + 4x²) is even with g'(0) = 0, so Lemma 10's "
    "hypotheses (g' > 0 on R) fail on Z; on i >= 0 everything works (the example says i ∈ N). "
    "The meridian then runs towards −x, as Figure 8 shows (C ∩ {x <= 0}); the service refuses "
    "i_min < 0 for this sequence."
)

D2B__REMARK_DOMAIN = (
    "Remark 13 is defined on i > −j/2 only: s_i = i/(i + j) has |s_i| < 1 exactly there (s = −1 "
    "at i = −j/2, undefined at i = −j), and g(x) = x/(1 + x) maps (−½, ∞), not R, onto (−1, 1). "
    "There g' = 1/(1 + x)² <= 4 is bounded, as the remark needs; the service refuses "
    "i_min <= −j/2."
)

T11__REFINEMENT = (
    "Checked by refinement (j_k = j0·2^k over the same parameter interval): residual = the "
    "largest ratio e(2j)/e(j) of the sup errors of consecutive levels; holds when every "
    "doubling of j shrinks the error by at least 2^(−1/2). Observed orders in the note."
)

T11_PROOF_PARAMETERS = (
    "The sums need g and g' at the parameters t_k = k/j, not at the values s_k = g(t_k) (E65); "
    "the proof's 'w.l.o.g. i > 0' covers i < 0 through the sum convention of Lemma 10 (E64)."
)

_REFINEMENT = (
    "Checked by refinement (d_k = d0/2^k) on the compact set |x| <= x_max: residual = the "
    "largest ratio e(d/2)/e(d) of the sup errors of consecutive levels; holds when every halving "
    "of d shrinks the error by at least 2^(−1/2) (local order >= 1/2). Observed orders in the "
    "note."
)

_VERTICAL = (
    "Inherited from Theorems 5 and 6: the curve interpolates (14) and (16), which assume a "
    "vertical first stick (d_0^y = p_1^y = h); the studies construct that polygon."
)

ORDER_21 = (
    "(21) converges with order 1: (1 − d/h)^{(x+d)/(2d)} = e^{−x/(2h)}(1 − d/(2h) − xd/(4h²) "
    "+ O(d²)); the first-order terms cancel between the two products of c(x), which converges "
    "with order 2."
)

PROOF_SUBSTITUTION = (
    "The substituted f(d), g(d) must carry the exponents (x + d)/(2d) resp. (x + d)/d (E80, "
    "E81); then f(d), g(d) > 0 with positive limits e^{∓x/h}, as (22) requires."
)

RING_SIGN_CONVENTION = (
    "The curvatures of [3] with K = A(n)/A(f) and H = −A(f,n)/A(f), all areas signed along "
    "the normal of the face of f (the unit sphere with n = f has K = 1, H = −1): the paper does "
    "not state the convention; with H = +A(f,n)/A(f) the H of (17) changes sign."
)

RING_ZERO_OVER_ZERO = (
    "(17) is 0/0 on faces whose meridian edge is parallel to the axis (p_{i+1}^y = p_i^y; the "
    "Gauss image edge is then parallel too); the mixed-area definition still gives K = λ(n_i^y + "
    "n_{i+1}^y)/(p_i^y + p_{i+1}^y) and H = −(λ + (n_i^y + n_{i+1}^y)/(p_i^y + p_{i+1}^y))/2 "
    "there (λ the ratio of the parallel edges); the check skips such faces and counts them."
)

D2B_LEMMA_HYPOTHESES = (
    "Lemma 10 asks for g: R → (−1, 1) of class C¹ with g(0) = 0 and g' > 0; neither named "
    "sequence has such a g on all of R (Example 12: g'(0) = 0, g even; Remark 13: g defined on "
    "(−1, ∞)). On the index sets the service allows (i >= 0; i > −j/2) the conclusions hold.",
    "The closed form needs none of this: with u = artanh s its terms are (s_k − s_{k+1}) / "
    "(√(1 − s_k²)√(1 − s_{k+1}²)) = −sinh(u_{k+1} − u_k), so p_i^x = −Σ sinh Δu_k for every "
    "sequence with |s| < 1 and s_0 = 0, while c^x(i/j) = −u_i. Convergence on compact sets "
    "follows from max |Δu_k| → 0, which (s^j) ↪ g (Definition 9) with g continuous and s "
    "increasing gives; the error Σ (sinh Δu − Δu) ≈ (1/(6j²))∫ u'³ has order 2.",
)
