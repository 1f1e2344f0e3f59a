"""The properties every stick-and-chain polygon is tested for: (D1), (D3), eq. (2), hanging sticks.

The paper says the discretizations are not equivalent; these checks say, for one computed
polygon, which of the conditions it satisfies, with the best (least-squares) constant for each,
whether it holds or not. A failing check is an answer: ``holds`` is false and the residual
measures by how much the polygon misses the condition. The statement ids are shared by every
discretization that reports them (``/theorems/d3?discretization=d1`` checks (D3) on a (D1)
polygon).
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping
from dataclasses import replace
from functools import cached_property
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
from app.geometry.on_demand import Evaluators, OnDemand
from app.geometry.precision import Arithmetic, Array, Scalar
from app.geometry.tolerances import LOCAL_STEPS

PROPERTIES: tuple[Statement, ...] = (D1, D3, EQUATION_2, HANGING_STICKS)

#: Constant names in responses, per property statement.
CONSTANT_NAMES = {"d1": "d1", "d3": "d3", "equation-2": "eq2", "hanging-sticks": "equilibrium"}


class Context(OnDemand):
    """What the checks of one computation share: precision, indices, detail, and the property
    fits of its polygon, each computed when a selected check first needs it.

    ``polygon`` is what the properties are fitted on; ``property_tolerance`` replaces the local
    tolerance of the property checks when the polygon is resolved worse than its rounding (D4a's
    p). Discretizations extend it with their own shared quantities.
    """

    def __init__(
        self,
        ar: Arithmetic,
        indices: np.ndarray[Any, np.dtype[np.int64]],
        detail: bool,
        polygon: Array | None = None,
        property_tolerance: float | None = None,
    ) -> None:
        self.ar, self.indices, self.detail = ar, indices, detail
        self.polygon, self.property_tolerance = polygon, property_tolerance

    @property
    def tolerance(self) -> float:
        return self.ar.tolerance(LOCAL_STEPS)

    @cached_property
    def fits(self) -> Fits:
        """The property fits of ``polygon``, each when first read."""
        if self.polygon is None:
            raise ValueError("no polygon to fit the properties on")
        return Fits(self.ar, self.polygon)

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

    def property_check(self, statement: Statement, expected: str | None = None) -> Check:
        """The check of one of ``PROPERTIES`` from its fit; ``expected`` adds to the note."""
        fit = self.fits[statement.id]
        note = (
            _constant_note(self.ar, fit.constant, expected)
            if len(fit.residuals)
            else None  # not applicable: the check says why
        )
        tolerance = self.property_tolerance
        found = self.check(statement, 0, fit.residuals, note=note, tolerance=tolerance)
        if fit.constant is not None and not fit.constant > 0 and found.holds:
            found = replace(found, holds=False, note=f"{note}; the best constant is not > 0")
        return found


def fit_property(ar: Arithmetic, statement_id: str, p: Array) -> conditions.ConditionFit:
    """The property ``statement_id`` fitted on the polygon ``p`` (``(n, 2)``)."""
    fitter: dict[str, Callable[[Arithmetic, Array], conditions.ConditionFit]] = {
        D1.id: conditions.d1,
        D3.id: conditions.d3,
        EQUATION_2.id: conditions.equation_2,
        HANGING_STICKS.id: conditions.equilibrium,
    }
    return fitter[statement_id](ar, p)


class Fits(Mapping[str, conditions.ConditionFit]):
    """The four conditions fitted on the polygon ``p``, each when first read (at most once)."""

    def __init__(self, ar: Arithmetic, p: Array) -> None:
        self._ar, self._p = ar, p
        self._found: dict[str, conditions.ConditionFit] = {}

    def __getitem__(self, key: str) -> conditions.ConditionFit:
        if key not in self._found:
            self._found[key] = fit_property(self._ar, key, self._p)
        return self._found[key]

    def __iter__(self) -> Iterator[str]:
        return iter(CONSTANT_NAMES)

    def __len__(self) -> int:
        return len(CONSTANT_NAMES)

    def constants(self) -> dict[str, Scalar]:
        """The constants of the fits computed so far, under their response names, in
        ``PROPERTIES`` order (absent when undetermined)."""
        found = {key: self._found[key] for key in CONSTANT_NAMES if key in self._found}
        return constants(found)


def constants(found: Mapping[str, conditions.ConditionFit]) -> dict[str, Scalar]:
    """The fitted constants under their response names (absent when undetermined)."""
    return {
        CONSTANT_NAMES[key]: fit.constant for key, fit in found.items() if fit.constant is not None
    }


def _evaluator(statement: Statement) -> Callable[[Context], Check]:
    return lambda x: x.property_check(statement)


#: The property checks with no note beyond the fitted constant, in ``PROPERTIES`` order.
EVALUATORS: Evaluators[Context] = tuple((s, _evaluator(s)) for s in PROPERTIES)


def _constant_note(ar: Arithmetic, constant: Scalar | None, expected: str | None) -> str:
    text = (
        "no constant: every right-hand side vanishes"
        if constant is None
        else f"best constant {ar.to_float(constant):.12g}"
    )
    return f"{text}; {expected}" if expected else text
