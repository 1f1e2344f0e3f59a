"""Refinement studies of Section 6: how fast the discrete curves approach the smooth ones.

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

import itertools
import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from app.geometry.catalog.section6 import (
    EQUATION_21,
    INEQUALITY_22,
    INTERPOLATION_14,
    INTERPOLATION_15,
    PROOF_15_X,
    PROOF_15_Y,
    REARRANGEMENT_14,
    SUBSTITUTION_21,
    THEOREM_14,
    THEOREM_15,
)
from app.geometry.checks import (
    Check,
    Erratum,
    Statement,
    check_residuals,
    not_applicable,
    point_distance,
    relative_point_difference,
)
from app.geometry.d4b.construction import KinematicTractrix, construct
from app.geometry.errors import DomainError
from app.geometry.precision import Arithmetic, Array, Scalar
from app.geometry.smooth.distance import distance_to_catenary, distance_to_tractrix
from app.geometry.studies import limit_curves as lc
from app.geometry.tolerances import LOCAL_STEPS

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

Builder = Callable[[Arithmetic, float, float, float | None, int, int], KinematicTractrix]
"""The (D4b) construction a study measures (tests pass a perturbed one)."""


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
    x = np.log(np.array([levels[k].step for k in used]))
    y = np.log(np.array([levels[k].errors[measure] for k in used], dtype=np.float64))
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


ERRATUM_PROOF_Y = (
    "E80",
    "f(d) = (1 − d/h)/(1 + d/h) and g(d) = 1/f(d)",
    "f(d) = ((1 − d/h)/(1 + d/h))^{(x+d)/(2d)} and g(d) = 1/f(d)",
)
ERRATUM_PROOF_X = (
    "E81",
    "f(d) = 1 − d/h and g(d) = 1 + d/h",
    "f(d) = (1 − d/h)^{(x+d)/d} and g(d) = (1 + d/h)^{(x+d)/d}",
)

CATENARY_MEASURES = (
    Measure(
        "parametric",
        "sup over the sample points x of |c(x) − (x, h cosh(x/h))|: Theorem 14's curve against "
        "the catenary at the same x (absolute; both first coordinates are x, so this is the "
        "vertical gap)",
        2,
    ),
    Measure(
        "distance",
        "sup over the sample points x of the distance from c(x) to the catenary (nearest "
        "point; absolute)",
        2,
    ),
    Measure(
        "vertices",
        "max over the constructed (D4b) centres p_i with |p_i^x| <= x_max of |p_i − (p_i^x, "
        "h cosh(p_i^x/h))| (absolute)",
        2,
    ),
    Measure(
        "vertices-distance",
        "max over the same p_i of their distance to the catenary (absolute)",
        2,
    ),
    Measure(
        "equation-21",
        "sup over the sample points x of |(1 − d/h)^{(x+d)/(2d)} − e^{−x/(2h)}|, the limit (21)",
        1,
    ),
)

TRACTRIX_MEASURES = (
    Measure(
        "parametric",
        "sup over the sample points x of |c(x) − T(x)|: Theorem 15's curve against the tractrix "
        "T(x) = (x − h tanh(x/h), h / cosh(x/h)) at the same parameter x (absolute)",
        1,
    ),
    Measure(
        "distance",
        "sup over the sample points x of the distance from c(x) to the tractrix (nearest point; "
        "absolute)",
        2,
    ),
    Measure(
        "vertices",
        "max over the constructed (D4b) tractrix points d_i with |(2i − 1)d| <= x_max of "
        "|d_i − T((2i − 1)d)|, the theorem's parametrization (absolute)",
        1,
    ),
    Measure(
        "vertices-distance",
        "max over the same d_i of their distance to the tractrix (absolute)",
        2,
    ),
    Measure(
        "natural",
        "max over the same d_i of |d_i − T(2di)|: T(2di) is the tractrix point whose tangent "
        "meets the x-axis at the foot x_i = (2di, 0) of stick i (absolute)",
        2,
    ),
    Measure(
        "inequality-22-y",
        "sup over the sample points x of |1/(f(d) + g(d)) − 1/(e^{−x/h} + e^{x/h})| with the "
        "proof's f(d) = ((1 − d/h)/(1 + d/h))^{(x+d)/(2d)}, g(d) = 1/f(d)",
        1,
    ),
    Measure(
        "inequality-22-x",
        "sup over the sample points x of |(f(d) − g(d))/(f(d) + g(d)) + tanh(x/h)| with the "
        "proof's f(d) = (1 − d/h)^{(x+d)/d}, g(d) = (1 + d/h)^{(x+d)/d}",
        1,
    ),
)

THEOREM_14_INFO = StudyInfo(
    id="theorem-14",
    title="Theorem 14: the discrete hyperbolic cosine (14) converges to the catenary",
    reference="Section 6, Theorem 14, eq. (21); (D4b), eq. (14)",
    summary=(
        "The (D4b) discrete hyperbolic cosine with vertical first stick and its interpolating "
        "curve c(x) of Theorem 14, against the catenary x ↦ (x, h cosh(x/h)), for d = d0/2^k. "
        "Every measure has order 2."
    ),
    refinement="d_k = d0/2^k, k = 0 .. levels − 1; compact set |x| <= x_max",
    step_name="d",
    measures=CATENARY_MEASURES,
    statements=(THEOREM_14, INTERPOLATION_14, REARRANGEMENT_14, SUBSTITUTION_21, EQUATION_21),
)

THEOREM_15_INFO = StudyInfo(
    id="theorem-15",
    title="Theorem 15: the discrete tractrix (16) converges to the tractrix",
    reference="Section 6, Theorem 15, (22); (D4b), eq. (16)",
    summary=(
        "The (D4b) discrete tractrix with vertical first stick and its interpolating curve c(x) "
        "of Theorem 15, against the tractrix T(x) = (x − h tanh(x/h), h / cosh(x/h)), for "
        "d = d0/2^k. The same-parameter error has order 1, the distance to the curve order 2: "
        "c(x) ≈ T(x + d)."
    ),
    refinement="d_k = d0/2^k, k = 0 .. levels − 1; compact set |x| <= x_max",
    step_name="d",
    measures=TRACTRIX_MEASURES,
    statements=(THEOREM_15, INTERPOLATION_15, PROOF_15_Y, PROOF_15_X, INEQUALITY_22),
)


# --- the two studies ---------------------------------------------------------------------------


@dataclass
class _Identity:
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


def _samples(ar: Arithmetic, x_max: float, samples: int) -> Array:
    """x_j = x_max (2j/(samples − 1) − 1), j = 0 .. samples − 1: uniform on [−x_max, x_max]."""
    j = ar.indices(0, samples - 1)
    return ar.scalar(x_max) * (2 * j / (samples - 1) - 1)


def _power_steps(ar: Arithmetic, h: Scalar, d: Scalar, x_max: float) -> int:
    """Rounding steps of a printed power (h ± d)^t: its exponent t ~ x/d times (1 + |ln(h ± d)|)."""
    exponent = (x_max + ar.to_float(d)) / ar.to_float(d)
    logs = max(abs(math.log(ar.to_float(h + d))), abs(math.log(ar.to_float(h - d))))
    return LOCAL_STEPS + math.ceil(2 * exponent * (1 + logs))


def _unit_power_steps(ar: Arithmetic, h: Scalar, d: Scalar, x_max: float) -> int:
    """Rounding steps of a power (1 ± d/h)^t with t ~ x/d (the proofs' dimensionless forms)."""
    return LOCAL_STEPS + math.ceil(2 * (x_max + ar.to_float(d)) / ar.to_float(d))


#: In float64 a printed power whose natural logarithm exceeds this in size overflows or falls
#: into the subnormal range (where it loses digits): such points are left out of identities.
FLOAT64_LOG_LIMIT = 700


def _printable(
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


def _sup(ar: Arithmetic, values: Array) -> float | None:
    if not len(values):
        return None
    worst = float(np.max(ar.to_floats(values)))
    return worst if math.isfinite(worst) else None


def _relative(ar: Arithmetic, computed: Array, expected: Array) -> Array:
    tiny = ar.scalar(np.finfo(np.float64).tiny)
    scale = np.where(abs(expected) > tiny, abs(expected), tiny)
    return abs(computed - expected) / scale


def _finish(
    info: StudyInfo,
    ar: Arithmetic,
    parameters: dict[str, Any],
    levels: list[Level],
    checks: Callable[[dict[str, OrderFit]], list[Check]],
) -> Study:
    fits = {m.id: observed_order(levels, m.id) for m in info.measures}
    return Study(info, parameters, ar, levels, fits, checks(fits))


def theorem_14(
    ar: Arithmetic,
    h: float = 1.0,
    d0: float = 0.2,
    levels: int = 8,
    x_max: float = 2.0,
    samples: int = 401,
    build: Builder = construct,
) -> Study:
    """Refinement study of Theorem 14 and (21) on the (D4b) construction (see module doc).

    Levels are sequential (a Python loop over at most ``levels`` refinements, each vectorized).
    """
    validate(h, d0, levels, x_max, samples)
    hh = ar.scalar(h)
    x = _samples(ar, x_max, samples)
    nonzero = np.asarray(x != 0, dtype=bool)
    result: list[Level] = []
    interpolation, rearrangement, substitution = _Identity(), _Identity(), _Identity()
    for d in steps(d0, levels):
        dd = ar.scalar(d)
        i_min, i_max = index_range(d, x_max)
        built = build(ar, h, d, None, i_min, i_max)
        p = built.centres
        size = max(abs(i_min), abs(i_max)) + 1
        powers = _power_steps(ar, hh, dd, x_max)
        c = lc.theorem_14_curve(ar, hh, dd, x)
        smooth = lc.catenary(ar, hh, x)
        at_vertices = lc.catenary(ar, hh, p[:, 0])
        power = lc.power_21(ar, hh, dd, x)
        scale = ar.to_float(hh * ar.cosh(ar.scalar(x_max) / hh))
        noise = ar.tolerance(LOCAL_STEPS + size) * scale
        result.append(
            Level(
                step=d,
                vertices=len(p),
                samples=samples,
                errors={
                    "parametric": _sup(ar, point_distance(ar, c, smooth)),
                    "distance": _sup(ar, distance_to_catenary(ar, hh, c)),
                    "vertices": _sup(ar, point_distance(ar, p, at_vertices)),
                    "vertices-distance": _sup(ar, distance_to_catenary(ar, hh, p)),
                    "equation-21": _sup(ar, abs(power - lc.limit_21(ar, hh, x))),
                },
                resolution={
                    "parametric": ar.tolerance(LOCAL_STEPS) * scale,
                    "distance": ar.tolerance(LOCAL_STEPS) * scale,
                    "vertices": noise,
                    "vertices-distance": noise,
                    "equation-21": ar.tolerance(_unit_power_steps(ar, hh, dd, x_max)),
                },
            )
        )
        with np.errstate(over="ignore", under="ignore", invalid="ignore", divide="ignore"):
            printed = lc.theorem_14_curve_printed(ar, hh, dd, p[:, 0])
            interpolation.add(
                ar,
                np.maximum(
                    relative_point_difference(ar, printed, p),
                    relative_point_difference(ar, lc.theorem_14_curve(ar, hh, dd, p[:, 0]), p),
                ),
                2 * size + powers,
                keep=_printable(ar, hh, dd, p[:, 0], 0.5),
            )
            rearrangement.add(
                ar,
                _relative(
                    ar,
                    lc.theorem_14_curve_rearranged(ar, hh, dd, x)[:, 1],
                    lc.theorem_14_curve_printed(ar, hh, dd, x)[:, 1],
                ),
                powers,
                keep=_printable(ar, hh, dd, x, 0.5),
            )
            xs = x[nonzero]
            substitution.add(
                ar,
                _relative(ar, lc.power_21_substituted(ar, hh, dd, xs), lc.power_21(ar, hh, dd, xs)),
                _unit_power_steps(ar, hh, dd, x_max),
            )
    parameters = {"h": h, "d0": d0, "levels": levels, "x_max": x_max, "samples": samples}

    def checks(fits: dict[str, OrderFit]) -> list[Check]:
        return [
            converges(THEOREM_14, result, ("parametric",), fits),
            interpolation.check(ar, INTERPOLATION_14),
            rearrangement.check(ar, REARRANGEMENT_14),
            substitution.check(ar, SUBSTITUTION_21),
            converges(EQUATION_21, result, ("equation-21",), fits),
        ]

    return _finish(THEOREM_14_INFO, ar, parameters, result, checks)


def theorem_15(
    ar: Arithmetic,
    h: float = 1.0,
    d0: float = 0.2,
    levels: int = 8,
    x_max: float = 2.0,
    samples: int = 401,
    build: Builder = construct,
) -> Study:
    """Refinement study of Theorem 15 and (22) on the (D4b) construction (see module doc).

    Levels are sequential (a Python loop over at most ``levels`` refinements, each vectorized).
    """
    validate(h, d0, levels, x_max, samples)
    hh = ar.scalar(h)
    x = _samples(ar, x_max, samples)
    result: list[Level] = []
    interpolation, proof_y, proof_x = _Identity(), _Identity(), _Identity()
    for d in steps(d0, levels):
        dd = ar.scalar(d)
        i_min, i_max = index_range(d, x_max)
        built = build(ar, h, d, None, i_min, i_max)
        tip, parameter = built.tractrix, built.centres[:, 0]  # (2i − 1)d
        size = max(abs(i_min), abs(i_max)) + 1
        powers = _power_steps(ar, hh, dd, x_max)
        c = lc.theorem_15_curve(ar, hh, dd, x)
        f_y, g_y = lc.substitution_15_y(ar, hh, dd, x)
        f_x, g_x = lc.substitution_15_x(ar, hh, dd, x)
        f, g = lc.limits_15(ar, hh, x)
        scale = ar.to_float(hh) + x_max
        local = ar.tolerance(LOCAL_STEPS) * scale
        noise = ar.tolerance(LOCAL_STEPS + size) * scale
        result.append(
            Level(
                step=d,
                vertices=len(tip),
                samples=samples,
                errors={
                    "parametric": _sup(ar, point_distance(ar, c, lc.tractrix(ar, hh, x))),
                    "distance": _sup(ar, distance_to_tractrix(ar, hh, c)),
                    "vertices": _sup(ar, point_distance(ar, tip, lc.tractrix(ar, hh, parameter))),
                    "vertices-distance": _sup(ar, distance_to_tractrix(ar, hh, tip)),
                    "natural": _sup(
                        ar, point_distance(ar, tip, lc.tractrix(ar, hh, built.axis_points[:, 0]))
                    ),
                    "inequality-22-y": _sup(ar, abs(1 / (f_y + g_y) - 1 / (f + g))),
                    "inequality-22-x": _sup(ar, abs((f_x - g_x) / (f_x + g_x) - (f - g) / (f + g))),
                },
                resolution={
                    "parametric": local,
                    "distance": local,
                    "vertices": noise,
                    "vertices-distance": noise,
                    "natural": noise,
                    "inequality-22-y": ar.tolerance(_unit_power_steps(ar, hh, dd, x_max)),
                    "inequality-22-x": ar.tolerance(_unit_power_steps(ar, hh, dd, x_max)),
                },
            )
        )
        with np.errstate(over="ignore", under="ignore", invalid="ignore", divide="ignore"):
            printed = lc.theorem_15_curve_printed(ar, hh, dd, parameter)
            interpolation.add(
                ar,
                np.maximum(
                    relative_point_difference(ar, printed, tip),
                    relative_point_difference(ar, lc.theorem_15_curve(ar, hh, dd, parameter), tip),
                ),
                2 * size + powers,
                keep=_printable(ar, hh, dd, parameter, 1.0),
            )
            curve = lc.theorem_15_curve_printed(ar, hh, dd, x)
            keep = _printable(ar, hh, dd, x, 1.0)
            pf, pg = lc.substitution_15_y(ar, hh, dd, x, printed=True)
            proof_y.add(
                ar,
                _relative(ar, 2 * hh / (f_y + g_y), curve[:, 1]),
                powers,
                _relative(ar, 2 * hh / (pf + pg), curve[:, 1]),
                keep,
            )
            fraction = (x + dd - curve[:, 0]) / hh
            qf, qg = lc.substitution_15_x(ar, hh, dd, x, printed=True)
            proof_x.add(
                ar,
                abs((g_x - f_x) / (g_x + f_x) - fraction),
                powers,
                abs((qg - qf) / (qg + qf) - fraction),
                keep,
            )
    parameters = {"h": h, "d0": d0, "levels": levels, "x_max": x_max, "samples": samples}

    def checks(fits: dict[str, OrderFit]) -> list[Check]:
        return [
            converges(THEOREM_15, result, ("parametric",), fits),
            interpolation.check(ar, INTERPOLATION_15),
            proof_y.check(ar, PROOF_15_Y, ERRATUM_PROOF_Y),
            proof_x.check(ar, PROOF_15_X, ERRATUM_PROOF_X),
            converges(INEQUALITY_22, result, ("inequality-22-y", "inequality-22-x"), fits),
        ]

    return _finish(THEOREM_15_INFO, ar, parameters, result, checks)
