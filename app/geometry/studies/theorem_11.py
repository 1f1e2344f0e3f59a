"""Refinement study of Theorem 11: the (D2b) catenoid meridians approach the catenary.

Level k uses j = j0·2^k and the indices 2^k i_min .. 2^k i_max, so that every level covers the
same parameter interval t = i/j ∈ [i_min/j0, i_max/j0] (Example 12 its part t ≥ 0: the
sequence is defined for i ≥ 0 only). At each level both named sequences are built from the
definition of (D2b) (``vanishing_mean_curvature``: Gauss image n_i = (s_i, √(1 − s_i²)),
meridian with parallel edges and H = 0 in the mixed-area sense, p_0 = (0, 1)) and compared with
the points c(i/j) = (−artanh g(i/j), cosh artanh g(i/j)) of the catenary C = {(x, cosh x)}
that Lemma 10 pairs them with (``catenoid_convergence``, the theorem side).

Why the order is 2. With u = artanh s, Lemma 10's terms are (s_k − s_{k+1}) /
(√(1 − s_k²) √(1 − s_{k+1}²)) = −sinh(u_{k+1} − u_k), so p_i^x = −Σ sinh Δu_k exactly, while
c^x(i/j) = −u_i = −Σ Δu_k and p_i^y = cosh u_i = c^y(i/j). The error is horizontal and equals
Σ (sinh Δu_k − Δu_k) ≈ Σ Δu_k³/6 ≈ (1/(6j²)) ∫ u'(τ)³ dτ over [0, i/j]: order 2 on every set
where u' = g'/(1 − g²) is bounded, and uniform on a non-compact set exactly where ∫ |u'|³ is
finite there. Remark 13's sequence on its whole domain i > −j/2 is not such a set (u' = 1/(1 + 2t)
blows up at t = −½): the measure ``remark-13-domain`` stays near 0.0095 (E66).

The proof of Lemma 10 approximates c^x(t) = ∫_0^t g'/(g² − 1) by Riemann sums; with g evaluated
at the parameters t_k = k/j (not at the values s_k, as printed: E65) they converge with order 1.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable
from dataclasses import replace

import numpy as np

from app.geometry.catalog import section6
from app.geometry.catalog.section6 import (
    T11_LEMMA_10_PROOF as LEMMA_10_PROOF,
    T11_REMARK_13_UNIFORM as REMARK_13_UNIFORM,
)
from app.geometry.checks import (
    Check,
    Erratum,
    Statement,
    check_residuals,
    point_distance,
    printed_residual,
    relative_point_difference,
)
from app.geometry.d2b import closed_forms as cc, construction as vmc, discretization as d2b
from app.geometry.errors import DomainError
from app.geometry.precision import Arithmetic, Array
from app.geometry.smooth.distance import distance_to_catenary
from app.geometry.studies.common import (
    SAMPLE_COST,
    WORK_CAP,
    Level,
    Measure,
    OrderFit,
    Study,
    StudyInfo,
    converges,
    observed_order,
)
from app.geometry.tolerances import LOCAL_STEPS

Meridian = Callable[[Arithmetic, Array, int], Array]
"""The (D2b) construction the study measures (tests pass a perturbed one)."""

S = Statement

ERRATUM_REMARK_13 = (
    "E66",
    "if g' is bounded on its domain then the polygons (p_i^j)_j uniformly converge to C; e.g. "
    "s_i^j = i/(i + j), g(x) = x/(1 + x)",
    "the convergence is uniform on a set of parameters where ∫|u'|³ < ∞, u = artanh g (the "
    "error is ≈ (1/(6j²))|∫_0^t u'³|): for s_i = i/(i + j) on every t >= t_0 > −½ and on all "
    "i >= 0, not on the whole domain i > −j/2",
)
ERRATUM_RIEMANN = (
    "E65",
    "Σ_{k=0}^{i−1} g'(s_k^j)/(1 − g(s_k^j)²)(s_k^j − s_{k+1}^j) and "
    "Σ_{k=0}^{i−1} (g(s_k^j) − g(s_{k+1}^j))/(1 − g(s_k^j)²)",
    "Σ_{k=0}^{i−1} g'(t_k)/(1 − g(t_k)²)(t_k − t_{k+1}) and Σ_{k=0}^{i−1} (s_k − s_{k+1})/"
    "(1 − s_k²), t_k = k/j",
)

MEASURES = (
    Measure(
        "example-12",
        "Example 12 (s_i = 4i²/(j² + 4i²)): max over the vertices with i/j in the compact set "
        "(and i >= 0) of |p_i^j − c(i/j)|, c(t) = (−artanh g(t), cosh artanh g(t)) the point of "
        "C that Lemma 10 pairs with p_i (absolute; the error is horizontal: p_i^y = c^y(i/j))",
        2,
    ),
    Measure(
        "example-12-distance",
        "Example 12: max over the same vertices of their distance to the catenary C (nearest "
        "point; absolute)",
        2,
    ),
    Measure(
        "remark-13",
        "Remark 13 (s_i = i/(i + j)): max over the vertices with i/j in the compact set of "
        "|p_i^j − c(i/j)| (absolute)",
        2,
    ),
    Measure(
        "remark-13-distance",
        "Remark 13: max over the same vertices of their distance to C (absolute)",
        2,
    ),
    Measure(
        "remark-13-domain",
        "Remark 13 on its whole domain: max of |p_i^j − c(i/j)| over every vertex −j/2 < i <= "
        "2^k i_max; it does not tend to 0 (about 0.0095 at the vertex next to i = −j/2, E66)",
        0,
    ),
    Measure(
        "riemann-sum",
        "Example 12, proof of Lemma 10: max over the vertices of |Σ_{k<i} g'(t_k)/(1 − g(t_k)²)"
        "(t_k − t_{k+1}) − c^x(i/j)|, t_k = k/j (a left Riemann sum of ∫ g'/(g² − 1))",
        1,
    ),
    Measure(
        "difference-sum",
        "Example 12, proof of Lemma 10: max over the vertices of |Σ_{k<i} (s_k − s_{k+1})/"
        "(1 − s_k²) − c^x(i/j)| (g' replaced by its difference quotient)",
        1,
    ),
)

THEOREM_11_INFO = StudyInfo(
    id="theorem-11",
    title="Theorem 11: (D2b) catenoid meridians converge to the catenary",
    reference="Section 6, Lemma 10, Theorem 11, Example 12, Remark 13; (D2b)",
    summary=(
        "The meridians p^j of discrete catenoids with vanishing mean curvature and inscribed "
        "Gauss images n_i^j = (s_i^j, √(1 − s_i^j²)), for the sequences of Example 12 and Remark "
        "13 with j = j0·2^k, against the catenary C = {(x, cosh x)} on the parameter interval "
        "t = i/j ∈ [i_min/j0, i_max/j0]. Every measure on the compact set has order 2; Remark "
        "13's sequence does not converge uniformly on its whole domain."
    ),
    refinement="j_k = j0·2^k, k = 0 .. levels − 1; indices 2^k i_min .. 2^k i_max "
    "(t = i/j ∈ [i_min/j0, i_max/j0]; Example 12: i >= 0)",
    step_name="1/j",
    measures=MEASURES,
    statements=(
        section6.D2B_THEOREM_11,
        section6.D2B_LEMMA_10,
        section6.D2B_EXAMPLE_12,
        section6.D2B_REMARK_13,
        REMARK_13_UNIFORM,
        LEMMA_10_PROOF,
    ),
)

CONVERGENT = ("example-12", "example-12-distance", "remark-13", "remark-13-distance")


def validate(j0: int, levels: int, i_min: int, i_max: int) -> None:
    """Raise ``DomainError`` unless j0 >= 1, levels >= 2, −j0/2 < i_min < i_max, i_max >= 1."""
    if j0 < 1:
        raise DomainError("j0", "j0 >= 1", j0)
    if levels < 2:
        raise DomainError("levels", "levels >= 2 (an order needs two levels)", levels)
    if i_max < 1:
        raise DomainError("i_max", "i_max >= 1 (Example 12 is defined for i >= 0)", i_max)
    if i_min >= i_max:
        raise DomainError("i_min", "i_min < i_max", i_min, f"i_max = {i_max}")
    if 2 * i_min <= -j0:
        raise DomainError(
            "i_min",
            "i_min > −j0/2 (Remark 13's domain: s_i = i/(i + j) has |s_i| < 1 only for i > −j/2)",
            i_min,
            f"j0 = {j0}",
        )


def _level_ranges(j0: int, k: int, i_min: int, i_max: int) -> tuple[int, int, int, int]:
    """(j, lo, hi, domain start) of level k."""
    factor = 2**k
    j = j0 * factor
    return j, factor * i_min, factor * i_max, vmc.domain_start("remark-13", j)


def work(j0: int, levels: int, i_min: int, i_max: int) -> tuple[int, int]:
    """(constructed vertices, measured vertices) over all levels, before any work (validates)."""
    validate(j0, levels, i_min, i_max)
    built = measured = 0
    for k in range(levels):
        if k > 60:  # 2^k alone is beyond any budget
            return WORK_CAP, WORK_CAP
        _, lo, hi, start = _level_ranges(j0, k, i_min, i_max)
        built += (hi + 1) + (hi - min(start, 0) + 1)
        measured += (hi - max(lo, 0) + 1) + (hi - lo + 1)
        if built > WORK_CAP:
            return WORK_CAP, min(measured, WORK_CAP)
    return built, measured


def mp_work(j0: int, levels: int, i_min: int, i_max: int) -> int:
    """The work of the study in construction steps, for the mp budget."""
    built, measured = work(j0, levels, i_min, i_max)
    return min(built + SAMPLE_COST * measured, WORK_CAP)


def _sup(ar: Arithmetic, values: Array) -> float | None:
    if not len(values):
        return None
    worst = float(np.max(ar.to_floats(values)))
    return worst if math.isfinite(worst) else None


def _size(ar: Arithmetic, points: Array) -> float:
    """The largest |x| + |y| of the points: the size of the numbers an error is taken from."""
    return float(np.max(ar.to_floats(abs(points[:, 0]) + abs(points[:, 1]))))


def _limit(ar: Arithmetic, name: vmc.SequenceName, j: int, i_min: int, count: int) -> Array:
    t = ar.indices(i_min, i_min + count - 1) / ar.scalar(j)
    artanh = cc.artanh_example_12(ar, t) if name == "example-12" else cc.artanh_remark_13(ar, t)
    return cc.limit_points(ar, artanh)


class _Collected:
    """Residuals of an identity over every level, with the printed form's where there is one."""

    def __init__(self) -> None:
        self.residuals: list[float] = []
        self.printed: list[float] = []
        self.steps = LOCAL_STEPS

    def add(self, ar: Arithmetic, residuals: Array, steps: int = LOCAL_STEPS) -> None:
        self.residuals.extend(ar.to_floats(residuals).tolist())
        self.steps = max(self.steps, steps)

    def check(
        self, ar: Arithmetic, statement: Statement, note: str, erratum: Erratum | None = None
    ) -> Check:
        values = np.array(self.residuals)
        return check_residuals(
            statement,
            ar,
            np.arange(len(values), dtype=np.int64),
            values,
            ar.tolerance(self.steps),
            False,
            erratum,
            note=note,
        )


def _largest_ratio(errors: list[float]) -> float | None:
    """The largest e_{k+1}/e_k (the printed claims' residual under refinement)."""
    ratios = [b / a for a, b in itertools.pairwise(errors) if a > 0]
    return max(ratios) if ratios else None


def theorem_11(
    ar: Arithmetic,
    j0: int = 4,
    levels: int = 7,
    i_min: int = -1,
    i_max: int = 8,
    meridian: Meridian = vmc.catenoid_meridian,
) -> Study:
    """Refinement study of Theorem 11 with Example 12 and Remark 13 (see the module doc).

    Levels are sequential (a Python loop over at most ``levels`` refinements, each vectorized).
    """
    validate(j0, levels, i_min, i_max)
    one = ar.scalar(1)
    result: list[Level] = []
    lemma, example, remark = _Collected(), _Collected(), _Collected()
    lemma_printed: list[float] = []
    domain_errors: list[float] = []
    printed_sums: list[float] = []
    for k in range(levels):
        j, lo, hi, start = _level_ranges(j0, k, i_min, i_max)
        errors: dict[str, float | None] = {}
        resolution: dict[str, float] = {}
        measured = 0
        built_total = 0
        sequences: tuple[tuple[vmc.SequenceName, int, int], ...] = (
            ("example-12", max(lo, 0), 0),
            ("remark-13", lo, min(start, 0)),
        )
        for name, first, hull_start in sequences:
            seq = vmc.named_sequence(ar, name, j, hull_start, hi)
            n = vmc.gauss_image(ar, seq)
            p = meridian(ar, n, -seq.i_min)
            built_total += len(p)
            c = _limit(ar, name, j, seq.i_min, len(p))
            window = slice(first - seq.i_min, hi - seq.i_min + 1)
            gap = point_distance(ar, p, c)
            steps = LOCAL_STEPS + len(p)
            noise = ar.tolerance(steps) * _size(ar, c[window])
            errors[name] = _sup(ar, gap[window])
            errors[f"{name}-distance"] = _sup(ar, distance_to_catenary(ar, one, p[window]))
            resolution[name] = resolution[f"{name}-distance"] = noise
            measured += window.stop - window.start
            indices = np.arange(seq.i_min, seq.i_max + 1, dtype=np.int64)
            closed = cc.lemma_10(ar, seq.s, seq.one_minus_s2, -seq.i_min)
            lemma.add(ar, relative_point_difference(ar, p[window], closed[window]), steps)
            where, printed = cc.lemma_10_printed(ar, seq.s, seq.one_minus_s2, -seq.i_min)
            shown = indices[where]
            negative = shown < 0
            if bool(np.any(negative)):
                printed_points = closed[where].copy()
                printed_points[:, 0] = printed
                worst = printed_residual(
                    ar,
                    relative_point_difference(ar, p[where][negative], printed_points[negative]),
                )
                if worst is not None:
                    lemma_printed.append(float(worst))  # mpmath here: a float already
            hypotheses = d2b.hypothesis_residuals(ar, name, j, indices, n)
            if name == "example-12":
                example.add(ar, hypotheses)
                _riemann(ar, j, seq, c, window, errors, resolution, printed_sums, steps)
            else:
                remark.add(ar, hypotheses)
                errors["remark-13-domain"] = _sup(ar, gap[: window.stop])
                resolution["remark-13-domain"] = ar.tolerance(steps) * _size(ar, c[: window.stop])
                value = errors["remark-13-domain"]
                if value is not None:
                    domain_errors.append(value)
        result.append(Level(1 / j, built_total, measured, errors, resolution))
    parameters = {"j0": j0, "levels": levels, "i_min": i_min, "i_max": i_max}

    def checks(fits: dict[str, OrderFit]) -> list[Check]:
        uniform = converges(
            REMARK_13_UNIFORM, result, ("remark-13", "remark-13-distance"), fits, "1/j"
        )
        proof = converges(LEMMA_10_PROOF, result, ("riemann-sum", "difference-sum"), fits, "1/j")
        lemma_erratum = Erratum(
            *d2b.ERRATUM_LEMMA_10, printed_residual=max(lemma_printed) if lemma_printed else None
        )
        return [
            converges(section6.D2B_THEOREM_11, result, CONVERGENT, fits, "1/j"),
            lemma.check(
                ar,
                section6.D2B_LEMMA_10,
                "every vertex of every level, both sequences",
                lemma_erratum,
            ),
            example.check(ar, section6.D2B_EXAMPLE_12, "every vertex i >= 0 of every level"),
            remark.check(
                ar, section6.D2B_REMARK_13, "every vertex −j/2 < i <= 2^k i_max of every level"
            ),
            _with_erratum(uniform, ERRATUM_REMARK_13, _largest_ratio(domain_errors)),
            _with_erratum(proof, ERRATUM_RIEMANN, _largest_ratio(printed_sums)),
        ]

    fits = {m.id: observed_order(result, m.id) for m in THEOREM_11_INFO.measures}
    return Study(THEOREM_11_INFO, parameters, ar, result, fits, checks(fits))


def _riemann(
    ar: Arithmetic,
    j: int,
    seq: vmc.GaussSequence,
    c: Array,
    window: slice,
    errors: dict[str, float | None],
    resolution: dict[str, float],
    printed_sums: list[float],
    steps: int,
) -> None:
    """The Riemann sums of Lemma 10's proof for Example 12 (``seq`` starts at i = 0)."""
    t = ar.indices(seq.i_min, seq.i_max) / ar.scalar(j)
    target = c[:, 0]
    riemann = cc.riemann_sums(ar, cc.example_12_g(t), cc.example_12_g_prime(t), t)
    difference = cc.difference_sums(ar, seq.s, seq.one_minus_s2)
    s = seq.s
    printed_riemann = cc.riemann_sums(ar, cc.example_12_g(s), cc.example_12_g_prime(s), s)
    printed_difference = cc.difference_sums_printed(ar, cc.example_12_g(s))
    noise = ar.tolerance(steps) * float(np.max(ar.to_floats(abs(target[window]))))
    errors["riemann-sum"] = _sup(ar, abs(riemann - target)[window])
    errors["difference-sum"] = _sup(ar, abs(difference - target)[window])
    resolution["riemann-sum"] = resolution["difference-sum"] = noise
    worst = _sup(
        ar,
        np.maximum(
            ar.to_floats(abs(printed_riemann - target)[window]),
            ar.to_floats(abs(printed_difference - target)[window]),
        ),
    )
    if worst is not None:
        printed_sums.append(worst)


def _with_erratum(check: Check, erratum: tuple[str, str, str], printed: float | None) -> Check:
    if check.holds is None:
        return check
    return replace(check, erratum=Erratum(*erratum, printed_residual=printed))
