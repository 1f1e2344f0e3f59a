"""Section 6: convergence (Lemma 10, Theorem 11, Example 12, Remark 13, Theorems 14, 15).

Each statement of the paper is defined here once; see ``app.geometry.catalog``.
"""

from __future__ import annotations

from app.geometry.catalog.conditions import (
    _REFINEMENT,
    _VERTICAL,
    D2B__EXAMPLE_DOMAIN,
    D2B__REMARK_DOMAIN,
    D2B_LEMMA_HYPOTHESES,
    D2B_RECURSION_DIVIDES,
    D2B_START,
    ORDER_21,
    PROOF_SUBSTITUTION,
    T11__REFINEMENT,
    T11_PROOF_PARAMETERS,
)
from app.geometry.checks import Statement

D2B_RADII = Statement(
    "theorem-11-radii",
    "Proof of Theorem 11",
    "H = 0 in (17) telescopes to p_i^y = 1/n_i^y = (1 − s_i²)^{−1/2} (p_0^y = n_0^y = 1). "
    "Residual: largest |p_i^y − 1/n_i^y| / (1/n_i^y).",
    conditions=(D2B_START,),
)

D2B_RECURSION = Statement(
    "theorem-11-recursion",
    "Proof of Theorem 11",
    "p_i^x = p_{i−1}^x + Δp_{i−1}^y Δn_{i−1}^x / Δn_{i−1}^y. Residual: largest "
    "|(p_i^x − p_{i−1}^x) Δn_{i−1}^y − Δp_{i−1}^y Δn_{i−1}^x| (the recursion multiplied out, "
    "which stays defined where Δn^y rounds to 0) relative to the magnitude of its terms.",
    conditions=(D2B_RECURSION_DIVIDES,),
)

D2B_LEMMA_10 = Statement(
    "lemma-10",
    "Lemma 10",
    "p_i = (Σ_{k=0}^{i−1} (s_k − s_{k+1})/((1 − s_k²)^{1/2}(1 − s_{k+1}²)^{1/2}), "
    "(1 − s_i²)^{−1/2}) is the constructed (D2b) meridian, with Σ_{k=0}^{i−1} = −Σ_{k=i}^{−1} "
    "for i < 0 (corrected convention; see erratum). Residual: largest |p_i − closed form| / "
    "|closed form|, on a curve over its range, on /convergence/theorem-11 over every vertex of "
    "every level of both sequences.",
    conditions=D2B_LEMMA_HYPOTHESES,
    errata=("E64",),
)

D2B_THEOREM_11 = Statement(
    "theorem-11",
    "Theorem 11 (with Example 12 / Remark 13)",
    "The meridians p^j converge to the catenary C = {(x, cosh x)} uniformly on compact sets as "
    "j → ∞, measured by max_i |p_i^j − c(i/j)| with the points c(t) = (−artanh g(t), cosh "
    "artanh g(t)) of C (and by the distance to C). On the refinement study "
    "/convergence/theorem-11 (the default): both named sequences at j = j0·2^k over the same "
    "parameter interval; holds when every doubling of j shrinks each sup error by at least "
    "2^(−1/2) (observed order about 2). On a d2b curve (named sequences only): residual = the "
    "ratio of the distances at 2j and at j over the same parameter interval (indices 2i_min .. "
    "2i_max), which must not exceed 1; the note gives both distances and the observed order.",
    conditions=(
        "Theorem 11 takes p_0^j = (0, 1, 0) and n_0^j = (0, 1) (s_0 = 0), and sequences with "
        "the hypotheses of Lemma 10 on the indices used: Example 12 on i >= 0, Remark 13 on "
        "i > −j/2 (see example-12, remark-13).",
        "'Compact sets' are sets of the parameter t = i/j (equivalently of x on C). The error "
        "is horizontal (p_i^y = c^y(i/j) exactly) and about (1/(6j²))|∫_0^t u'³| with "
        "u = artanh g: order 2, and uniform on any set where ∫|u'|³ is finite, which a bounded "
        "g' does not ensure (remark-13-uniform, E66).",
    ),
)

D2B_EXAMPLE_12 = Statement(
    "example-12",
    "Example 12",
    "n_i^x = s_i = 4i²/(j² + 4i²) = g(i/j) with g(x) = 4x²/(1 + 4x²), strictly increasing with "
    "|s_i| < 1 and n_0 = (0, 1) on i >= 0, as Lemma 10 requires. Residual: the largest of "
    "|n_i^x − g(i/j)|, the monotonicity and bound violations and |n_0 − (0, 1)|, on a curve "
    "over its range, on /convergence/theorem-11 over every level.",
    conditions=(D2B__EXAMPLE_DOMAIN,),
)

D2B_REMARK_13 = Statement(
    "remark-13",
    "Remark 13",
    "n_i^x = s_i = i/(i + j) = g(i/j) with g(x) = x/(1 + x), strictly increasing with |s_i| < 1 "
    "and n_0 = (0, 1) on i > −j/2, where g' = 1/(1 + x)² is bounded. Residual: as for "
    "example-12 (on /convergence/theorem-11: every vertex −j/2 < i of every level). The "
    "remark's conclusion, uniform convergence, is remark-13-uniform.",
    defaults=(("sequence", "remark-13"),),
    conditions=(D2B__REMARK_DOMAIN,),
)

T11_REMARK_13_UNIFORM = Statement(
    "remark-13-uniform",
    "Remark 13 (with Theorem 11)",
    "Remark 13 says that a bounded g' makes the convergence uniform, not only on compact sets. "
    "Corrected (E66): what decides is ∫|u'|³ with u = artanh g, u' = g'/(1 − g²); for "
    "s_i = i/(i + j) the convergence is uniform on every t >= t_0 > −½, in particular on i >= 0, "
    "but not on the whole domain i > −j/2. Measures: `remark-13` and `remark-13-distance` on "
    "the compact set (the corrected claim); the erratum's printed residual is the same ratio "
    "for `remark-13-domain` (all vertices i > −j/2 up to 2^k i_max), about 1. " + T11__REFINEMENT,
    conditions=(
        "A bounded g' is not enough in general: g = tanh (g' <= 1, g(0) = 0, g' > 0) gives "
        "u' = 1 and an error (i/j)/(6j²) that grows without bound in i for fixed j.",
    ),
    errata=("E66",),
)

T11_LEMMA_10_PROOF = Statement(
    "lemma-10-proof",
    "Proof of Lemma 10, the Riemann sums",
    "For Example 12, the sums of the proof tend to the first component of c(t) = "
    "(−artanh g(t), …) = ∫_0^t g'/(g² − 1): Σ_{k<i} g'(t_k)/(1 − g(t_k)²)(t_k − t_{k+1}) and "
    "Σ_{k<i} (s_k − s_{k+1})/(1 − s_k²), with t_k = k/j (printed with g and g' evaluated at "
    "s_k, E65). Measures `riemann-sum`, `difference-sum` (order 1). " + T11__REFINEMENT,
    conditions=(T11_PROOF_PARAMETERS,),
    errata=("E65",),
)

THEOREM_14 = Statement(
    "theorem-14",
    "Theorem 14",
    "The smooth curve c(x) through the vertices of (14) tends to the catenary x ↦ "
    "(x, h cosh(x/h)) as d → 0, uniformly on compact sets. Measure: sup |c(x) − (x, h "
    "cosh(x/h))| (`parametric`; observed order 2). " + _REFINEMENT,
    conditions=(
        "The proof shows convergence for each x (via (21)); uniformity on compact sets follows "
        "from c(x) = (x, √(h² − d²) cosh(a x)) with a = artanh(d/h)/d = 1/h + O(d²), and on all "
        "of R it fails: for fixed d the error grows without bound as |x| → ∞, so 'on compact "
        "sets' is needed (docs/errata.md, Section 6).",
        _VERTICAL,
    ),
)

INTERPOLATION_14 = Statement(
    "theorem-14-interpolation",
    "Theorem 14",
    "Theorem 14's c(x), as printed and in the form (x, √(h² − d²) cosh(a x)), passes through "
    "the constructed (D4b) centres: c((2i − 1)d) = p_i at every level. Residual: largest "
    "|c((2i − 1)d) − p_i| / |p_i|.",
    conditions=(_VERTICAL,),
)

REARRANGEMENT_14 = Statement(
    "theorem-14-rearrangement",
    "Proof of Theorem 14",
    "The rearranged c^y(x) = h(1 − d/h)^{(x+d)/(2d)}/(2(1 + d/h)^{(x−d)/(2d)}) + "
    "h(1 + d/h)^{(x+d)/(2d)}/(2(1 − d/h)^{(x−d)/(2d)}) equals the printed c^y(x). Residual: "
    "largest relative difference at the sample points of every level.",
    conditions=(_VERTICAL,),
)

SUBSTITUTION_21 = Statement(
    "equation-21-substitution",
    "Proof of Theorem 14, eq. (21)",
    "With d = x/D (x ≠ 0): (1 − d/h)^{(x+d)/(2d)} = (1 − x/(hD))^{D/2} (1 − x/(hD))^{1/2}. "
    "Residual: largest relative difference at the sample points x ≠ 0 of every level.",
    conditions=(
        "The substitution needs x ≠ 0, and D = x/d → −∞ for x < 0; the limit is the same "
        "(e^{−x/(2h)} at x = 0 too).",
    ),
)

EQUATION_21 = Statement(
    "equation-21",
    "Proof of Theorem 14, eq. (21)",
    "(1 − d/h)^{(x+d)/(2d)} → e^{−x/(2h)} as d → 0. Measure: its sup error on the compact set "
    "(`equation-21`; observed order 1, while the symmetric combination in c(x) converges with "
    "order 2). " + _REFINEMENT,
    conditions=(ORDER_21,),
)

THEOREM_15 = Statement(
    "theorem-15",
    "Theorem 15",
    "The smooth curve c(x) through the vertices of (16) tends to the tractrix x ↦ "
    "(x − h tanh(x/h), h / cosh(x/h)) as d → 0, uniformly on all of R. Measure: sup |c(x) − "
    "T(x)| at the same x (`parametric`, order 1; the distance from c(x) to the tractrix has "
    "order 2, see the study). " + _REFINEMENT,
    conditions=(
        "The proof, via (22), shows convergence for each x; uniformity needs a bound "
        "independent of x, which holds: c(x) − T(x) = (d − h(tanh(a(x+d)) − tanh(x/h)), "
        "h/cosh(a(x+d)) − h/cosh(x/h)) with a = 1/h + O(d²) tends to (d, 0) as |x| → ∞, so "
        "the global sup error is about d (order 1) (docs/errata.md, Section 6).",
        "c passes through d_i at x = (2i − 1)d, while the stick of d_i meets the x-axis at "
        "2di: c(x) ≈ T(x + d). So the same-parameter error has order 1 and the distance to the "
        "curve order 2 (GET /convergence/theorem-15).",
        _VERTICAL,
    ),
)

INTERPOLATION_15 = Statement(
    "theorem-15-interpolation",
    "Theorem 15",
    "Theorem 15's c(x), as printed and in the form (x + d − h tanh(a(x+d)), h / cosh(a(x+d))), "
    "passes through the constructed (D4b) tractrix: c((2i − 1)d) = d_i at every level. "
    "Residual: largest |c((2i − 1)d) − d_i| / |d_i|.",
    conditions=(_VERTICAL,),
)

PROOF_15_Y = Statement(
    "theorem-15-proof-y",
    "Proof of Theorem 15, the y-component",
    "2h/(f(d) + g(d)) = 2h(h² − d²)^{(x+d)/(2d)}/((h−d)^{(x+d)/d} + (h+d)^{(x+d)/d}) = c^y(x) "
    "with f(d) = ((1 − d/h)/(1 + d/h))^{(x+d)/(2d)} and g(d) = 1/f(d) (printed without the "
    "exponent, E80); then f(d) → e^{−x/h}, g(d) → e^{x/h} by (21) and (22) applies. Residual: "
    "largest relative difference at the sample points of every level.",
    conditions=(PROOF_SUBSTITUTION,),
    errata=("E80",),
)

PROOF_15_X = Statement(
    "theorem-15-proof-x",
    "Proof of Theorem 15, the x-component",
    "(g(d) − f(d))/(g(d) + f(d)) = (x + d − c^x(x))/h with f(d) = (1 − d/h)^{(x+d)/d} and "
    "g(d) = (1 + d/h)^{(x+d)/d} (printed without the exponent, E81); then f(d) → e^{−x/h}, "
    "g(d) → e^{x/h} and (22) gives c^x(x) → x − h tanh(x/h). Residual: largest absolute "
    "difference (both sides lie in [−1, 1]) at the sample points of every level.",
    conditions=(PROOF_SUBSTITUTION,),
    errata=("E81",),
)

INEQUALITY_22 = Statement(
    "inequality-22",
    "Proof of Theorem 15, (22)",
    "For f(d), g(d) > 0 with limits f, g > 0: 1/(f(d) + g(d)) → 1/(f + g) and (f(d) − g(d))/"
    "(f(d) + g(d)) → (f − g)/(f + g), applied to the proof's f(d), g(d) (corrected, E80, E81) "
    "with f = e^{−x/h}, g = e^{x/h}. Measures: the sup of both differences on the compact set "
    "(`inequality-22-y`, `inequality-22-x`; order 1). " + _REFINEMENT,
    conditions=(
        "(22) holds for each x 'for sufficiently small d'; the smallness depends on x, so (22) "
        "alone gives pointwise convergence, not the uniform convergence Theorem 15 states.",
    ),
)
