"""The properties every stick-and-chain polygon is tested for: (D1), (D3), eq. (2), hanging sticks.

The paper says the discretizations are not equivalent; these checks say, for one computed
polygon, which of the conditions it satisfies, with the best (least-squares) constant for each,
whether it holds or not. A failing check is an answer: ``holds`` is false and the residual
measures by how much the polygon misses the condition. The statement ids are shared by every
discretization that reports them (``/theorems/d3?discretization=d1`` checks (D3) on a (D1)
polygon).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from app.geometry import conditions
from app.geometry.checks import Check, Erratum, Statement, check_residuals
from app.geometry.precision import Arithmetic, Array, Scalar

#: Local checks combine a handful of neighbouring values; their tolerance allows this many
#: rounding steps (as for D4b).
LOCAL_STEPS = 16

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
D1 = Statement(
    "d1",
    "Section 3, (D1)",
    "Δ²p_i^y = c (l_i + l_{i+1}) with one constant c > 0 (constants.d1, least-squares fit). "
    "Residual: largest |Δ²p_i^y − c(l_i + l_{i+1})|, relative to the magnitude of the "
    "coordinates it is computed from (docs/checks.md). On a polygon that does not satisfy (D1) "
    "the check fails and the residual says by how much.",
    conditions=(SPACING, D1_RANGE),
)
D3 = Statement(
    "d3",
    "Section 3, (D3)",
    "A_i = c l_i with one constant c > 0 (constants.d3, least-squares fit): the area under each "
    "edge is c times its length. Residual: largest |A_i − c l_i|, relative to the magnitude of "
    "the coordinates (docs/checks.md).",
    conditions=(SPACING, D3_RANGE, D3_FOLDS),
)
EQUATION_2 = Statement(
    "equation-2",
    "Section 4.1, eq. (2)",
    "Δ²p_i^y = c (A_i + A_{i+1}) with one constant c > 0 (constants.eq2, least-squares fit). "
    "Residual: largest |Δ²p_i^y − c(A_i + A_{i+1})|, relative to the magnitude of the "
    "coordinates (docs/checks.md).",
    conditions=(EQUATION_2_SOURCE,),
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

PROPERTIES: tuple[Statement, ...] = (D1, D3, EQUATION_2, HANGING_STICKS)

#: Constant names in responses, per property statement.
CONSTANT_NAMES = {"d1": "d1", "d3": "d3", "equation-2": "eq2", "hanging-sticks": "equilibrium"}


@dataclass(frozen=True)
class Context:
    """What the checks of one computation share: precision, indices, tolerance, detail."""

    ar: Arithmetic
    indices: np.ndarray[Any, np.dtype[np.int64]]
    detail: bool

    @property
    def tolerance(self) -> float:
        return self.ar.tolerance(LOCAL_STEPS)

    def check(
        self,
        statement: Statement,
        first: int,
        residuals: Array,
        erratum: Erratum | None = None,
        note: str | None = None,
        tolerance: float | None = None,
    ) -> Check:
        """A check whose k-th residual belongs to index ``indices[first + k]``."""
        idx = self.indices[first : first + len(residuals)]
        return check_residuals(
            statement,
            self.ar,
            idx,
            residuals,
            self.tolerance if tolerance is None else tolerance,
            self.detail,
            erratum,
            note,
        )


def fits(ar: Arithmetic, p: Array) -> dict[str, conditions.ConditionFit]:
    """The four conditions fitted on the polygon ``p`` (``(n, 2)``), keyed by statement id."""
    return {
        D1.id: conditions.d1(ar, p),
        D3.id: conditions.d3(ar, p),
        EQUATION_2.id: conditions.equation_2(ar, p),
        HANGING_STICKS.id: conditions.equilibrium(ar, p),
    }


def constants(found: dict[str, conditions.ConditionFit]) -> dict[str, Scalar]:
    """The fitted constants under their response names (absent when undetermined)."""
    return {
        CONSTANT_NAMES[key]: fit.constant for key, fit in found.items() if fit.constant is not None
    }


def checks(
    ctx: Context,
    found: dict[str, conditions.ConditionFit],
    expected: dict[str, str] | None = None,
    tolerance: float | None = None,
) -> list[Check]:
    """One check per property, in ``PROPERTIES`` order; ``expected`` adds a note per id.

    ``tolerance`` replaces the local one when the polygon is resolved worse than its rounding
    (D4a's p).
    """
    out = []
    for statement in PROPERTIES:
        fit = found[statement.id]
        note = (
            _constant_note(ctx.ar, fit.constant, (expected or {}).get(statement.id))
            if len(fit.residuals)
            else None  # not applicable: the check says why
        )
        check = ctx.check(statement, 0, fit.residuals, note=note, tolerance=tolerance)
        if fit.constant is not None and not fit.constant > 0 and check.holds:
            check = replace(check, holds=False, note=f"{note}; the best constant is not > 0")
        out.append(check)
    return out


def _constant_note(ar: Arithmetic, constant: Scalar | None, expected: str | None) -> str:
    text = (
        "no constant: every right-hand side vanishes"
        if constant is None
        else f"best constant {ar.to_float(constant):.12g}"
    )
    return f"{text}; {expected}" if expected else text
