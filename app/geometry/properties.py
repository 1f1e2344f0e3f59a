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
from app.geometry.catalog.section3 import (
    D1,
    D3,
    HANGING_STICKS,
)
from app.geometry.catalog.section4 import (
    EQUATION_2,
)
from app.geometry.checks import Check, Erratum, Statement, check_residuals
from app.geometry.precision import Arithmetic, Array, Scalar
from app.geometry.tolerances import LOCAL_STEPS

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
