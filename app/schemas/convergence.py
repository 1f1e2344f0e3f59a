"""Parameters and response of GET /convergence/{id}, the refinement studies of Section 6."""

from __future__ import annotations

from typing import Any, Literal

from pydantic import BaseModel, Field

from app.schemas.catalog import ParameterInfo
from app.schemas.common import StrictModel
from app.schemas.curve import CheckModel, ParameterValue, PrecisionInfo


class StudyQuery(StrictModel):
    """Parameters every study accepts; subclasses add the study's own."""

    precision: Literal["float64", "mp"] = Field(
        "float64",
        description="`float64` (numpy) or `mp` (mpmath with `digits` digits). Errors and orders "
        "are numbers in both.",
    )
    digits: int = Field(
        30,
        ge=1,
        le=100_000,
        description="Significant digits for precision=mp (at most DCOSH_MAX_DIGITS; the mp work "
        "of the whole study is bounded by DCOSH_MAX_MP_WORK). Ignored in float64.",
    )
    format: Literal["json", "csv", "svg"] = Field(
        "json",
        description="`json` (default), `csv` (columns level,d,measure,error,resolved) or `svg` "
        "(log-log plot of every measure's sup error against the step, with fitted orders).",
    )

    def core_arguments(self) -> dict[str, Any]:
        """The keyword arguments of the study's run function."""
        return self.model_dump(exclude={"precision", "digits", "format"})


class TractrixStudyQuery(StudyQuery):
    """Theorems 14 and 15: refinement of (D4b) with vertical first stick; the paper's h."""

    h: float = Field(
        1.0,
        ge=1e-50,
        le=1e50,
        description="Stick length h (> 0): the limits are h cosh(x/h) and the tractrix of h.",
        json_schema_extra={"x-domain": "h > 0"},
    )
    d0: float = Field(
        0.2,
        gt=0,
        le=1e50,
        description="Coarsest step: level k uses d = d0/2^k. 0 < d0 < h.",
        json_schema_extra={"x-domain": "0 < d0 < h"},
    )
    levels: int = Field(
        8,
        ge=2,
        le=64,
        description="Number of refinement levels (at most DCOSH_MAX_CONVERGENCE_LEVELS).",
        json_schema_extra={"x-domain": "2 <= levels"},
    )
    x_max: float = Field(
        2.0,
        gt=0,
        le=1e52,
        description="The compact set is |x| <= x_max (x: the curves' parameter); "
        "d0 <= x_max <= 20h.",
        json_schema_extra={"x-domain": "d0 <= x_max <= 20h"},
    )
    samples: int = Field(
        401,
        ge=2,
        le=10_000_000,
        description="Points of a uniform grid of [−x_max, x_max] where the smooth interpolating "
        "curve is measured, per level (at most DCOSH_MAX_CONVERGENCE_SAMPLES).",
        json_schema_extra={"x-domain": "samples >= 2"},
    )


class CatenoidStudyQuery(StudyQuery):
    """Theorem 11: refinement of (D2b) for the sequences of Example 12 and Remark 13."""

    j0: int = Field(
        4,
        ge=1,
        le=1_000_000,
        description="Coarsest j: level k uses j = j0·2^k (s_i^j of Example 12 and Remark 13).",
        json_schema_extra={"x-domain": "j0 >= 1"},
    )
    levels: int = Field(
        7,
        ge=2,
        le=64,
        description="Number of refinement levels (at most DCOSH_MAX_CONVERGENCE_LEVELS).",
        json_schema_extra={"x-domain": "2 <= levels"},
    )
    i_min: int = Field(
        -1,
        ge=-1_000_000,
        le=1_000_000,
        description="Start of the compact set in indices of level 0: t = i/j from i_min/j0 "
        "(level k uses 2^k i_min). Example 12 uses its part i >= 0.",
        json_schema_extra={"x-domain": "−j0/2 < i_min < i_max (Remark 13: i > −j/2)"},
    )
    i_max: int = Field(
        8,
        ge=1,  # Example 12 is defined for i >= 0 (the study's own check, in the schema too)
        le=1_000_000,
        description="End of the compact set in indices of level 0: t = i/j up to i_max/j0.",
        json_schema_extra={"x-domain": "i_max >= 1"},
    )


class MeasureModel(BaseModel):
    id: str = Field(description="Measure id, a key of each level's `errors`.")
    description: str = Field(description="What is compared with what, on which points.")
    expected_order: float | None = Field(description="The order the analysis predicts.")
    observed_order: float | None = Field(
        description="Least-squares slope of ln(error) against ln(step) over `levels_used`; "
        "null with fewer than two resolved levels."
    )
    constant: float | None = Field(description="C in error ≈ C·step^order.")
    levels_used: list[int] = Field(description="Levels in the fit (errors above resolution).")
    local_orders: list[float | None] = Field(
        description="ln(e_k/e_{k+1})/ln 2 for consecutive levels (null where unresolved)."
    )


class LevelModel(BaseModel):
    level: int = Field(description="k, the refinement level.")
    step: float = Field(description="The step of this level, e.g. d = d0/2^k.")
    vertices: int = Field(description="Constructed vertices on the compact set.")
    samples: int = Field(description="Sample points of the interpolating curve.")
    errors: dict[str, float | None] = Field(description="Sup error of each measure.")
    resolved: dict[str, bool] = Field(
        description="Whether the error is above the rounding resolution of the level."
    )


class ConvergenceResponse(BaseModel):
    """One refinement study: errors per level, observed orders, checks of the statements."""

    id: str
    title: str
    reference: str
    summary: str
    refinement: str = Field(description="How the levels refine and the compact set.")
    step_name: str = Field(description="The refinement parameter (the fit's abscissa).")
    parameters: dict[str, ParameterValue] = Field(
        description="Effective parameters, defaults filled in."
    )
    precision: PrecisionInfo
    levels: list[LevelModel]
    measures: list[MeasureModel]
    checks: list[CheckModel] = Field(description="The paper's statements checked on the study.")


class MeasureInfo(BaseModel):
    id: str = Field(description="Measure id.")
    description: str = Field(description="What is compared with what, on which points.")
    expected_order: float | None = Field(description="The order the analysis predicts.")


class StudyEntry(BaseModel):
    id: str = Field(description="Id used in /convergence/{id}.")
    title: str
    reference: str
    summary: str
    url: str = Field(description="Path of the study (default parameters).")
    refinement: str = Field(description="How the levels refine and the compact set.")
    parameters: list[ParameterInfo] = Field(description="Parameters with domains and defaults.")
    measures: list[MeasureInfo] = Field(description="The error measures of every level.")
    statements: list[str] = Field(description="Ids of the statements checked (GET /theorems).")


_STUDY_CONVENTIONS = """\
Levels k = 0 .. levels − 1 halve the step: d_k = d0/2^k. At each level the (D4b) polygon with a
vertical first stick (the hypothesis of Theorems 5 and 6, which (14) and (16) need) is built from
its definition on the indices with |(2i − 1)d| <= x_max, and the theorem's smooth curve c(x) is
evaluated on `samples` points of [−x_max, x_max]. Every error is an absolute sup (maximum) over
those points; `levels[k].errors` holds one per measure. The observed order is the least-squares
slope of ln(error) against ln(d) over the levels whose error lies above the rounding resolution
of that level (`resolved`). `checks` test the paper's statements of this section on the same
data: limit claims by refinement (every halving of d must shrink the sup error by at least
2^(−1/2)), identities by their residuals, with errata where the print is wrong (docs/errata.md).
In precision=mp the study costs about (digits + 200) × (construction steps + 30 × samples ×
levels), bounded by DCOSH_MAX_MP_WORK: use few levels and samples there.
"""

THEOREM_14_DESCRIPTION = (
    """\
Theorem 14: the smooth curve c(x) through the vertices of the discrete hyperbolic cosine (14)
tends to the catenary x ↦ (x, h cosh(x/h)), uniformly on compact sets. Measures: `parametric`
(|c(x) − (x, h cosh(x/h))|), `distance` (from c(x) to the catenary), `vertices` and
`vertices-distance` (the same for the constructed centres p_i), `equation-21` (the limit (21)).
All have order 2 except (21), which has order 1: its error cancels in the symmetric c(x).

"""
    + _STUDY_CONVENTIONS
)

THEOREM_15_DESCRIPTION = (
    """\
Theorem 15: the smooth curve c(x) through the vertices of the discrete tractrix (16) tends to
the tractrix T(x) = (x − h tanh(x/h), h / cosh(x/h)), uniformly. Measures: `parametric`
(|c(x) − T(x)|, order 1), `distance` (from c(x) to the tractrix, order 2), `vertices` and
`vertices-distance` (the same for the constructed d_i), `natural` (|d_i − T(2di)|, order 2) and
the two quantities of (22). The orders differ because c passes through d_i at x = (2i − 1)d
while d_i is within O(d²) of T(2di), the tractrix point whose tangent meets the x-axis at the
foot (2di, 0) of stick i: c(x) ≈ T(x + d) lies O(d²) from the curve but d·|tanh(x/h)| from T(x).

"""
    + _STUDY_CONVENTIONS
)

THEOREM_11_DESCRIPTION = """\
Theorem 11 with the sequences of Example 12 (s_i = 4i²/(j² + 4i²), i >= 0) and Remark 13
(s_i = i/(i + j), i > −j/2): the meridians p^j of discrete catenoids with vanishing mean curvature
and inscribed Gauss images n_i = (s_i, √(1 − s_i²)), built from the definition of (D2b) (GET
/discretizations/d2b), converge to the catenary C = {(x, cosh x)}. Level k uses j = j0·2^k and the
indices 2^k i_min .. 2^k i_max: the same parameter interval t = i/j ∈ [i_min/j0, i_max/j0] at every
level (Example 12: its part t >= 0). The step of the fit is 1/j.

Measures (absolute sup errors over the vertices): `example-12`, `remark-13`: |p_i^j − c(i/j)| with
c(t) = (−artanh g(t), cosh artanh g(t)), the point of C that Lemma 10 pairs with p_i (the error is
horizontal: p_i^y = c^y(i/j) exactly); `example-12-distance`, `remark-13-distance`: the distance of
p_i^j to C. All four have order 2: with u = artanh s, p_i^x = −Σ sinh Δu_k while c^x = −Σ Δu_k,
so the error is about (1/(6j²))∫ u'³. `remark-13-domain`: Remark 13 on its whole domain (every
vertex −j/2 < i); it tends to about 0.0095, not 0: the convergence is not uniform there (E66).
`riemann-sum`, `difference-sum`: the two sums of the proof of Lemma 10 for Example 12, with g at the
parameters t_k = k/j (E65), against c^x (order 1).

Checks: `theorem-11` (the four compact-set measures), `lemma-10` (the closed form at every vertex
of every level), `example-12` and `remark-13` (the sequences' hypotheses at every level),
`remark-13-uniform` (E66) and `lemma-10-proof` (E65). Limit claims hold when every doubling of j
shrinks the sup error by at least 2^(−1/2). In precision=mp the study costs about
(digits + 200) × (constructed vertices + 30 × measured vertices): use levels <= 3 there.
"""
