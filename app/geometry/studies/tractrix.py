"""What the refinement studies of Theorems 14 and 15 share: (D4b) levels, samples, budgets.

A study refines a discretization by halving its step (d_k = d0/2^k, k = 0 .. levels − 1) and
measures at each level the sup error of one or more *measures* on a compact set. The observed
order is the slope of the least-squares line through (ln d_k, ln e_k); a limit claim of the
paper is checked by refinement (``converges``): every halving must shrink the error by at least
``CONVERGENCE_RATIO``.

Studies (registered in ``app.registry``):
- ``theorem-14``: the curve of Theorem 14 through the vertices of (14), and the constructed
  (D4b) centres p_i, against the catenary x ↦ (x, h cosh(x/h)); plus the limit (21).
- ``theorem-15``: the curve of Theorem 15 through the vertices of (16), and the constructed
  (D4b) tractrix d_i, against the tractrix x ↦ (x − h tanh(x/h), h / cosh(x/h)); plus (22).
- ``theorem-11`` (module ``catenoid_refinement``): the (D2b) meridians of Example 12 and Remark
  13 against the catenary, built from the same pieces.

The vertices come from the construction (``kinematic_tractrix``); the interpolating curves and
limits are the theorems (``limit_curves``); distances to the smooth curves from
``curve_distance``. A study is a ``StudyInfo`` and a ``run`` function built from ``Level``,
``observed_order`` and ``converges``.

Why the tractrix has two orders. Theorem 15's curve passes through d_i at x = (2i − 1)d, the
x-coordinate of p_i; but the stick of d_i meets the x-axis at x_i = 2di, and the tractrix point
with that property is T(2di). Indeed d_i = T(2di) + O(d²), so c(x) = T(x + d) + O(d²): the points
lie within O(d²) of the curve (``distance``, ``natural``: order 2), while the same-parameter
error |c(x) − T(x)| ≈ d·|T'(x)| = d·|tanh(x/h)| is of order 1 (``parametric``, ``vertices``). For
Theorem 14 the parameter x is the x-coordinate itself, and every measure has order 2.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from app.geometry.checks import (
    Check,
    Erratum,
    Statement,
    check_residuals,
    not_applicable,
)
from app.geometry.d4b.construction import KinematicTractrix
from app.geometry.errors import DomainError
from app.geometry.precision import Arithmetic, Array, Scalar
from app.geometry.studies.common import (
    MAX_SPAN,
    SAMPLE_COST,
    WORK_CAP,
    Level,
    OrderFit,
    Study,
    StudyInfo,
    observed_order,
)
from app.geometry.tolerances import LOCAL_STEPS

Builder = Callable[[Arithmetic, float, float, float | None, int, int], KinematicTractrix]
"""The (D4b) construction a study measures (tests pass a perturbed one)."""


def validate(h: float, d0: float, levels: int, x_max: float, samples: int) -> None:
    """Raise ``DomainError`` unless 0 < d0 < h, levels >= 2, d0 <= x_max <= 20h, samples >= 2."""
    if not math.isfinite(h) or h <= 0:
        raise DomainError("h", "h > 0", h)
    if not math.isfinite(d0) or d0 <= 0 or d0 >= h:
        raise DomainError("d0", "0 < d0 < h", d0, f"the stick length is h = {h!r}")
    if levels < 2:
        raise DomainError("levels", "levels >= 2 (an order needs two levels)", levels)
    if not math.isfinite(x_max) or x_max < d0:
        raise DomainError(
            "x_max", "d0 <= x_max (each level then has vertices on the compact set)", x_max
        )
    if x_max > MAX_SPAN * h:
        raise DomainError("x_max", f"x_max <= {MAX_SPAN}·h", x_max, f"h = {h!r}")
    if samples < 2:
        raise DomainError("samples", "samples >= 2", samples)


def index_range(d: float, x_max: float) -> tuple[int, int]:
    """The indices i with |(2i − 1)d| <= x_max: the vertices on the compact set."""
    ratio = x_max / d
    return math.ceil((1 - ratio) / 2), math.floor((1 + ratio) / 2)


def steps(d0: float, levels: int) -> list[float]:
    """d_k = d0/2^k for k = 0 .. levels − 1 (exact in binary)."""
    return [d0 / 2**k for k in range(levels)]


def work(h: float, d0: float, levels: int, x_max: float, samples: int) -> tuple[int, int]:
    """(construction steps, sample points) of a study, summed over its levels, before any work."""
    validate(h, d0, levels, x_max, samples)
    total = 0
    for d in steps(d0, levels):
        if not (d > 0 and x_max / d < WORK_CAP):  # a step below any budget (or underflowed)
            return WORK_CAP, samples * levels
        i_min, i_max = index_range(d, x_max)
        total += max(1 - i_min, 0) + max(i_max, 0) + 1
    return min(total, WORK_CAP), samples * levels


def mp_work(h: float, d0: float, levels: int, x_max: float, samples: int) -> int:
    """The work of a study in construction steps, for the mp budget."""
    built, sampled = work(h, d0, levels, x_max, samples)
    return built + SAMPLE_COST * sampled


# --- statements --------------------------------------------------------------------------------


@dataclass
class Identity:
    """Residuals of an identity collected over the levels (float64 overflow points dropped)."""

    residuals: list[float] = field(default_factory=list)
    printed: list[float] = field(default_factory=list)
    dropped: int = 0
    steps: int = LOCAL_STEPS

    def add(
        self,
        ar: Arithmetic,
        residuals: Array,
        steps: int,
        printed: Array | None = None,
        keep: np.ndarray[Any, np.dtype[np.bool_]] | None = None,
    ) -> None:
        """Residuals of the points in ``keep`` (all if None) whose values are finite."""
        values = ar.to_floats(residuals)
        usable = np.isfinite(values) if keep is None else np.isfinite(values) & keep
        self.dropped += int(np.count_nonzero(~usable))
        self.residuals.extend(values[usable].tolist())
        if printed is not None:
            p = ar.to_floats(printed)
            self.printed.extend(p[usable & np.isfinite(p)].tolist())
        self.steps = max(self.steps, steps)

    def check(self, ar: Arithmetic, statement: Statement, erratum: tuple[str, ...] = ()) -> Check:
        tolerance = ar.tolerance(self.steps)
        note = None
        if self.dropped:
            note = (
                f"{self.dropped} points left out: a printed power (h ± d)^t leaves the normal "
                "float64 range there; precision=mp evaluates them all"
            )
        if not self.residuals:
            return not_applicable(statement, tolerance, note or "no points to evaluate")
        attached = None
        if erratum:
            worst = max(self.printed) if self.printed else None
            attached = Erratum(erratum[0], erratum[1], erratum[2], printed_residual=worst)
        values = np.array(self.residuals)
        return check_residuals(
            statement,
            ar,
            np.arange(len(values), dtype=np.int64),
            values,
            tolerance,
            False,
            attached,
            note,
        )


def sample_points(ar: Arithmetic, x_max: float, samples: int) -> Array:
    """x_j = x_max (2j/(samples − 1) − 1), j = 0 .. samples − 1: uniform on [−x_max, x_max]."""
    j = ar.indices(0, samples - 1)
    return ar.scalar(x_max) * (2 * j / (samples - 1) - 1)


def power_steps(ar: Arithmetic, h: Scalar, d: Scalar, x_max: float) -> int:
    """Rounding steps of a printed power (h ± d)^t: its exponent t ~ x/d times (1 + |ln(h ± d)|)."""
    exponent = (x_max + ar.to_float(d)) / ar.to_float(d)
    logs = max(abs(math.log(ar.to_float(h + d))), abs(math.log(ar.to_float(h - d))))
    return LOCAL_STEPS + math.ceil(2 * exponent * (1 + logs))


def unit_power_steps(ar: Arithmetic, h: Scalar, d: Scalar, x_max: float) -> int:
    """Rounding steps of a power (1 ± d/h)^t with t ~ x/d (the proofs' dimensionless forms)."""
    return LOCAL_STEPS + math.ceil(2 * (x_max + ar.to_float(d)) / ar.to_float(d))


#: In float64 a printed power whose natural logarithm exceeds this in size overflows or falls
#: into the subnormal range (where it loses digits): such points are left out of identities.
FLOAT64_LOG_LIMIT = 700


def printable(
    ar: Arithmetic, h: Scalar, d: Scalar, x: Array, per_step: float
) -> np.ndarray[Any, np.dtype[np.bool_]]:
    """The points where every printed power (h ± d)^t, |t| <= per_step·(|x| + d)/d, and its
    products with h stay normal float64 numbers (all points in mp)."""
    if ar.mode == "mp":
        return np.ones(len(x), dtype=bool)
    hf, df = ar.to_float(h), ar.to_float(d)
    logs = max(abs(math.log(hf + df)), abs(math.log(hf - df)))
    exponent = per_step * (np.abs(ar.to_floats(x)) + df) / df
    return np.asarray(logs * (exponent + 2) < FLOAT64_LOG_LIMIT, dtype=bool)


def largest(ar: Arithmetic, values: Array) -> float | None:
    """The sup of ``values`` as a float (``None`` when there are none or it is not finite)."""
    if not len(values):
        return None
    worst = float(np.max(ar.to_floats(values)))
    return worst if math.isfinite(worst) else None


def finish(
    info: StudyInfo,
    ar: Arithmetic,
    parameters: dict[str, Any],
    levels: list[Level],
    checks: Callable[[dict[str, OrderFit]], list[Check]],
) -> Study:
    """The study of ``levels``: an observed order per measure, then its checks on those fits."""
    fits = {m.id: observed_order(levels, m.id) for m in info.measures}
    return Study(info, parameters, ar, levels, fits, checks(fits))
