"""Refinement studies of Section 6: the framework every study is built from.

A study refines a discretization by halving its step (d_k = d0/2^k, k = 0 .. levels − 1) and
measures at each level the sup error of one or more *measures* on a compact set. The observed
order is the slope of the least-squares line through (ln d_k, ln e_k); a limit claim of the
paper is checked by refinement (``converges``): every halving must shrink the error by at least
``CONVERGENCE_RATIO``.

Studies (registered in ``app.registry``), one module each: ``theorem_11`` (the (D2b) meridians
against the catenary), ``theorem_14`` (the curve of Theorem 14 and the (D4b) centres against the
catenary), ``theorem_15`` (the curve of Theorem 15 and the (D4b) tractrix against the tractrix);
what the last two share is in ``tractrix``.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from app.geometry import elementary
from app.geometry.checks import (
    Check,
    Statement,
    not_applicable,
)
from app.geometry.precision import Arithmetic

#: A limit claim holds under refinement when every halving of the step multiplies the sup
#: error by at most this factor: a local order of at least 1/2 at every level.
CONVERGENCE_RATIO = 2**-0.5


#: The compact set is |x| <= x_max with x_max <= MAX_SPAN·h (cosh(x/h) stays far from overflow).
MAX_SPAN = 20

#: Work counts are capped here: more than any budget allows, and still an exact integer.
WORK_CAP = 10**15

#: mp work of one sample point in units of one construction step (both distance brackets, the
#: curves and the proofs' forms; measured against ``construct``).
SAMPLE_COST = 30

S = Statement


@dataclass(frozen=True)
class Measure:
    """One error measure of a study: what is compared with what, and on which points."""

    id: str
    description: str
    expected_order: float | None = None
    """The order the analysis in the docs predicts (``None`` where there is none)."""


@dataclass(frozen=True)
class StudyInfo:
    """Catalog facts of one study."""

    id: str
    title: str
    reference: str
    summary: str
    refinement: str
    """How the levels refine, e.g. ``d_k = d0/2^k``."""
    step_name: str
    """The refinement parameter of the fit, e.g. ``d``."""
    measures: tuple[Measure, ...]
    statements: tuple[Statement, ...]


@dataclass(frozen=True)
class Level:
    """One refinement level: its step, its size and the sup error of every measure."""

    step: float
    vertices: int
    """Constructed vertices measured on the compact set."""
    samples: int
    """Points of the smooth interpolating curve measured."""
    errors: dict[str, float | None]
    resolution: dict[str, float]
    """Per measure: the error below which rounding could matter (the level's tolerance times the
    size of the numbers compared); a level whose error is not above it is left out of fits."""

    def resolved(self, measure: str) -> bool:
        """Whether the error of ``measure`` is a number above its rounding resolution."""
        error = self.errors.get(measure)
        return error is not None and error > self.resolution.get(measure, 0.0)


@dataclass(frozen=True)
class OrderFit:
    """The observed order of one measure: slope of ln e against ln(step) by least squares."""

    order: float | None
    constant: float | None
    """C in e ≈ C·step^order."""
    levels: tuple[int, ...]
    """The level numbers k used (resolved, positive errors)."""
    local_orders: tuple[float | None, ...]
    """ln(e_k/e_{k+1}) / ln(step_k/step_{k+1}) for consecutive levels (None if unresolved)."""


@dataclass(frozen=True)
class Study:
    """A refinement study with its levels, fitted orders and checks."""

    info: StudyInfo
    parameters: dict[str, Any]
    arithmetic: Arithmetic
    levels: list[Level]
    fits: dict[str, OrderFit]
    checks: list[Check] = field(default_factory=list)


def observed_order(levels: list[Level], measure: str) -> OrderFit:
    """Least-squares slope of ln e_k against ln step_k over the resolved levels of ``measure``."""
    used = [k for k, level in enumerate(levels) if level.resolved(measure)]
    local: list[float | None] = []
    for k in range(len(levels) - 1):
        a, b = levels[k], levels[k + 1]
        if k in used and k + 1 in used:
            ea, eb = a.errors[measure], b.errors[measure]
            assert ea is not None and eb is not None
            local.append(math.log(ea / eb) / math.log(a.step / b.step))
        else:
            local.append(None)
    if len(used) < 2:
        return OrderFit(None, None, tuple(used), tuple(local))
    x = elementary.log(np.array([levels[k].step for k in used]))
    y = elementary.log(np.array([levels[k].errors[measure] for k in used], dtype=np.float64))
    xm, ym = float(np.mean(x)), float(np.mean(y))
    slope = float(np.sum((x - xm) * (y - ym)) / np.sum((x - xm) ** 2))
    log_constant = ym - slope * xm
    constant = math.exp(log_constant) if abs(log_constant) < 700 else None  # JSON-safe
    return OrderFit(slope, constant, tuple(used), tuple(local))


def converges(
    statement: Statement,
    levels: list[Level],
    measures: tuple[str, ...],
    fits: dict[str, OrderFit],
    step_name: str = "d",
) -> Check:
    """A limit claim checked by refinement on the given measures (``step_name``: for the note).

    Residual: the largest ratio e_{k+1}/e_k of consecutive resolved levels over the measures;
    holds when it is at most ``CONVERGENCE_RATIO``. The note gives each observed order.
    """
    ratios: list[float] = []
    for measure in measures:
        for a, b in itertools.pairwise(levels):
            if a.resolved(measure) and b.resolved(measure):
                ea, eb = a.errors[measure], b.errors[measure]
                assert ea is not None and eb is not None
                ratios.append(eb / ea)
    orders = ", ".join(
        f"{m}: {fits[m].order:.4f}" if fits[m].order is not None else f"{m}: none" for m in measures
    )
    finest = levels[-1]
    errors = ", ".join(
        f"{m}: {finest.errors[m]:.3g}" for m in measures if finest.errors[m] is not None
    )
    note = f"observed order {orders}; sup error at {step_name} = {finest.step:.6g}: {errors}"
    if not ratios:
        return not_applicable(
            statement,
            CONVERGENCE_RATIO,
            "fewer than two consecutive levels above the rounding resolution; use fewer levels "
            "or precision=mp",
        )
    worst = max(ratios)
    return Check(
        id=statement.id,
        reference=statement.reference,
        claim=statement.claim,
        residual=worst,
        tolerance=CONVERGENCE_RATIO,
        holds=worst <= CONVERGENCE_RATIO,
        note=note,
    )
