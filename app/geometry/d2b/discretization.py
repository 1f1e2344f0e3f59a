"""(D2b) the meridian of a discrete catenoid with vanishing mean curvature; Lemma 10, Theorem 11.

The polygon comes from its definition (``vanishing_mean_curvature``: parallel edges, H = 0 in the
mixed-area sense, p_0 = (0, 1)) for a Gauss image meridian n_i = (s_i, √(1 − s_i²)); the checks
test (17), the proof of Theorem 11 (p^y = 1/n^y and the x-recursion), Lemma 10's closed form
and, for the named sequences, the convergence to the catenary.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from functools import cached_property
from typing import Any

import numpy as np

from app.geometry.catalog.section3 import (
    D2B_MEAN_CURVATURE as MEAN_CURVATURE,
    D2B_PARALLEL as PARALLEL,
)
from app.geometry.catalog.section5 import RING_EQUATION_17 as EQUATION_17
from app.geometry.catalog.section6 import (
    D2B_EXAMPLE_12 as EXAMPLE_12,
    D2B_LEMMA_10 as LEMMA_10,
    D2B_RADII as RADII,
    D2B_RECURSION as RECURSION,
    D2B_REMARK_13 as REMARK_13,
    D2B_THEOREM_11 as THEOREM_11,
)
from app.geometry.checks import (
    Check,
    Erratum,
    Statement,
    check_residuals,
    not_applicable,
    point_distance,
    printed_residual,
    relative_difference,
    relative_point_difference,
)
from app.geometry.curvature import FaceCurvatures
from app.geometry.curve import EVERYTHING, Curve, DiscretizationInfo, Selection
from app.geometry.d2b import (
    closed_forms as catenoid_convergence,
    construction as vanishing_mean_curvature,
)
from app.geometry.d2b.construction import GaussSequence, SequenceName
from app.geometry.errors import DomainError
from app.geometry.on_demand import Evaluators, OnDemand
from app.geometry.precision import Arithmetic, Array
from app.geometry.surfaces.ring_curvature import (
    edge_parallel_residuals,
    equation_17_check,
    minimal_residuals,
    ring_curvatures,
)
from app.geometry.tolerances import LOCAL_STEPS

#: theorem-11 holds when doubling j shrinks the distance to the catenary (ratio below 1).
CONVERGENCE_TOLERANCE = 1.0

S = Statement

STATEMENTS: tuple[Statement, ...] = (
    MEAN_CURVATURE,
    PARALLEL,
    EQUATION_17,
    RADII,
    RECURSION,
    LEMMA_10,
    THEOREM_11,
    EXAMPLE_12,
    REMARK_13,
)

DEFAULT_J = 5

INFO = DiscretizationInfo(
    id="d2b",
    title="Meridian of a discrete catenoid with vanishing mean curvature (D2b)",
    reference="Section 3 (D2b); Section 5, eq. (17); Section 6, Lemma 10, Theorem 11, "
    "Example 12, Remark 13",
    summary=(
        "A Gauss image meridian n_i = (s_i, √(1 − s_i²)) on the unit circle, from a strictly "
        "increasing sequence with s_0 = 0, and the catenoid meridian p_i with p_0 = (0, 1), edges "
        "parallel to n and vanishing discrete mean curvature on every face."
    ),
    default_range=(0, 2 * DEFAULT_J),
    methods=("construction",),
    companions={
        "gauss_image": "n_i = (s_i, √(1 − s_i²)), the Gauss image meridian (inscribed in the unit "
        "circle), same indices as p",
    },
    constants={},
    statements=STATEMENTS,
)

ERRATUM_LEMMA_10 = (
    "E64",
    "for i < 1 the indices k in the sum Σ_{k=0}^{i−1} go from k = i − 1 to 0",
    "for i < 0 the sum is −Σ_{k=i}^{−1} (and 0 for i = 0), the usual convention "
    "Σ_{k=0}^{i−1} = −Σ_{k=i}^{−1}",
)


def default_range(sequence: SequenceName, j: int) -> tuple[int, int]:
    """Default i_min, i_max of a named sequence: t = i/j from max(start, −¼) to 2."""
    return max(vanishing_mean_curvature.domain_start(sequence, j), -j // 4), 2 * j


def resolve_range(
    sequence: SequenceName,
    j: int | None,
    s: list[float] | None,
    i_min: int | None,
    i_max: int | None,
) -> tuple[int, int]:
    """The effective i_min, i_max: given ones, else the defaults (custom: i_min = 0 and the
    length of s)."""
    if sequence == "custom":
        first = 0 if i_min is None else i_min
        last = first + (len(s) if s is not None else 1) - 1 if i_max is None else i_max
        return first, last
    lo, hi = default_range(sequence, j if j is not None else DEFAULT_J)
    return (lo if i_min is None else i_min), (hi if i_max is None else i_max)


@dataclass(frozen=True)
class D2bPolygons(OnDemand):
    """One (D2b) computation on the hull of 0 and i_min .. i_max; ``first`` is i_min's entry."""

    ar: Arithmetic
    sequence_name: SequenceName
    j: int | None
    sequence: GaussSequence
    n: Array
    p: Array
    first: int
    count: int

    @cached_property
    def refined(self) -> tuple[GaussSequence, Array, Array] | None:
        """The same family at 2j on 2i_min .. 2i_max (hull of 0): sequence, n, p; named only,
        computed when first read (Theorem 11's convergence)."""
        if self.sequence_name == "custom" or self.j is None:
            return None
        i_min = self.sequence.i_min + self.first
        i_max = i_min + self.count - 1
        fine = vanishing_mean_curvature.named_sequence(
            self.ar, self.sequence_name, 2 * self.j, min(0, 2 * i_min), max(0, 2 * i_max)
        )
        return (fine, *_build(self.ar, fine))


def _build(ar: Arithmetic, sequence: GaussSequence) -> tuple[Array, Array]:
    n = vanishing_mean_curvature.gauss_image(ar, sequence)
    p = vanishing_mean_curvature.catenoid_meridian(ar, n, -sequence.i_min)
    return n, p


def polygons(
    ar: Arithmetic,
    sequence: SequenceName,
    j: int | None,
    s: list[float] | None,
    i_min: int,
    i_max: int,
) -> D2bPolygons:
    """Gauss image and meridian (the definition); the refinement at 2j when first read."""
    if sequence == "custom":
        if s is None:
            raise DomainError("s", "required for sequence=custom", None)
        data = vanishing_mean_curvature.custom_sequence(ar, s, i_min)
        if data.i_max != i_max:
            raise DomainError(
                "i_max",
                "i_max = i_min + len(s) − 1 for sequence=custom",
                i_max,
                f"len(s) = {len(s)}",
            )
        name_j = None
    else:
        if j is None:
            raise DomainError("j", "required for sequence=" + sequence, None)
        vanishing_mean_curvature.named_sequence(ar, sequence, j, i_min, i_max)  # validates
        data = vanishing_mean_curvature.named_sequence(
            ar, sequence, j, min(0, i_min), max(0, i_max)
        )
        name_j = j
    n, p = _build(ar, data)
    return D2bPolygons(ar, sequence, name_j, data, n, p, i_min - data.i_min, i_max - i_min + 1)


def construction_tolerance(ar: Arithmetic, data: D2bPolygons) -> float:
    """Tolerance of statements on p, which the definition builds by cumulative products and sums
    from i = 0 (one rounding step per vertex)."""
    return ar.tolerance(max(len(data.p) + 1, LOCAL_STEPS))


def _lemma_10_note(check: Check) -> Check:
    """Say why E64's printed residual is null: the printed convention differs only for i < 1.

    At i = 0 it needs s_{−1}, outside a list starting at 0 (Example 12's domain starts there,
    and its g is even, so Σ_{k=−1}^{0} t_k = 0 would agree anyway); for i >= 1 it is the
    usual sum. Ranges with i < 0 (Remark 13's default, sequence=remark-13) show it.
    """
    if check.erratum is None or check.erratum.printed_residual is not None or check.note:
        return check
    return replace(
        check,
        note="printed_residual is null: E64's printed convention differs from the corrected "
        "one only for i < 1, where it needs s_{i−1}, which this sequence does not have (an "
        "even g such as Example 12's would even agree at i = 0); sequence=remark-13 shows it",
    )


class _Context(OnDemand):
    """What the checks of one (D2b) computation share, each part computed when first needed."""

    def __init__(self, ar: Arithmetic, data: D2bPolygons, detail: bool) -> None:
        self.ar, self.data, self.detail = ar, data, detail
        self.window = slice(data.first, data.first + data.count)
        self.p, self.n = data.p[self.window], data.n[self.window]
        i_min = data.sequence.i_min + data.first
        self.indices = np.arange(i_min, i_min + data.count, dtype=np.int64)
        self.tolerance = construction_tolerance(ar, data)
        self.local = ar.tolerance(LOCAL_STEPS)

    def check(
        self, statement: Statement, first: int, residuals: Array, erratum: Erratum | None = None
    ) -> Check:
        """A check on p (construction tolerance) whose k-th residual is at indices[first + k]."""
        idx = self.indices[first : first + len(residuals)]
        return check_residuals(
            statement, self.ar, idx, residuals, self.tolerance, self.detail, erratum
        )

    @cached_property
    def ring(self) -> FaceCurvatures | None:
        """The mixed-area curvatures of the faces (Section 5), ``None`` without a face."""
        return ring_curvatures(self.ar, self.p, self.n) if self.data.count > 1 else None


def evaluate(
    ar: Arithmetic, data: D2bPolygons, detail: bool = False, selection: Selection = EVERYTHING
) -> list[Check]:
    """The selected checks of ``STATEMENTS`` on the given polygons (shown range i_min .. i_max);
    each computes only what it needs."""
    return selection.evaluate(_Context(ar, data, detail), _EVALUATORS)


def _equation_17(ctx: _Context) -> Check:
    if ctx.ring is None:
        return not_applicable(EQUATION_17, ctx.tolerance, "a face needs two vertices")
    return equation_17_check(
        ctx.ar, ctx.indices, [(ctx.p, ctx.n)], ctx.tolerance, ctx.detail, [ctx.ring]
    )


def _recursion(ctx: _Context) -> Check:
    p, n = ctx.p, ctx.n
    size = (abs(p[1:, 0]) + abs(p[:-1, 0])) * (abs(n[1:, 1]) + abs(n[:-1, 1])) + (
        abs(p[1:, 1]) + abs(p[:-1, 1])
    ) * (abs(n[1:, 0]) + abs(n[:-1, 0]))
    recursion = abs(catenoid_convergence.recursion_x_defect(p, n)) / size
    return ctx.check(RECURSION, 1, recursion)


def _lemma_10(ctx: _Context) -> Check:
    ar, data = ctx.ar, ctx.data
    full = data.sequence
    zero = -full.i_min
    closed = catenoid_convergence.lemma_10(ar, full.s, full.one_minus_s2, zero)
    where, printed = catenoid_convergence.lemma_10_printed(ar, full.s, full.one_minus_s2, zero)
    printed_points = closed[where].copy()
    printed_points[:, 0] = printed
    shown = np.arange(len(full.s))[where]
    keep = (shown >= data.first) & (shown < data.first + data.count)
    lemma_erratum = Erratum(
        *ERRATUM_LEMMA_10,
        printed_residual=printed_residual(
            ar,
            relative_point_difference(ar, data.p[where][keep], printed_points[keep]),
        )
        if bool(np.any(keep & (shown <= zero)))
        else None,
    )
    residuals = relative_point_difference(ar, ctx.p, closed[ctx.window])
    return _lemma_10_note(ctx.check(LEMMA_10, 0, residuals, erratum=lemma_erratum))


#: Each statement about (D2b) and the function that checks it, in the order of the response.
_EVALUATORS: Evaluators[_Context] = (
    (
        MEAN_CURVATURE,
        lambda x: x.check(
            MEAN_CURVATURE, 0, minimal_residuals(x.ring) if x.ring else x.ar.zeros(0)
        ),
    ),
    (PARALLEL, lambda x: x.check(PARALLEL, 0, edge_parallel_residuals(x.p, x.n))),
    (EQUATION_17, _equation_17),
    (
        RADII,
        lambda x: x.check(
            RADII,
            0,
            relative_difference(x.ar, x.p[:, 1], catenoid_convergence.radii(x.ar, x.n[:, 1])),
        ),
    ),
    (RECURSION, _recursion),
    (LEMMA_10, _lemma_10),
    (THEOREM_11, lambda x: _convergence(x.ar, x.data, x.p, x.indices, x.local)),
    (
        EXAMPLE_12,
        lambda x: _example(
            x.ar, x.data, EXAMPLE_12, "example-12", x.n, x.indices, x.local, x.detail
        ),
    ),
    (
        REMARK_13,
        lambda x: _example(x.ar, x.data, REMARK_13, "remark-13", x.n, x.indices, x.local, x.detail),
    ),
)


def _limit_points(ar: Arithmetic, name: SequenceName, j: int, i: Array) -> Array:
    t = i / ar.scalar(j)
    if name == "example-12":
        return catenoid_convergence.limit_points(ar, catenoid_convergence.artanh_example_12(ar, t))
    return catenoid_convergence.limit_points(ar, catenoid_convergence.artanh_remark_13(ar, t))


def distance_to_limit(ar: Arithmetic, name: SequenceName, j: int, p: Array, i_min: int) -> float:
    """max_i |p_i − c(i/j)| over the given points (indices i_min, i_min + 1, …)."""
    i = ar.indices(i_min, i_min + len(p) - 1)
    return float(np.max(ar.to_floats(point_distance(ar, p, _limit_points(ar, name, j, i)))))


def _convergence(
    ar: Arithmetic,
    data: D2bPolygons,
    p: Array,
    indices: np.ndarray[Any, np.dtype[np.int64]],
    tolerance: float,
) -> Check:
    if data.refined is None or data.j is None:
        return not_applicable(
            THEOREM_11, tolerance, "sequence=custom: no family s^j to refine (named sequences only)"
        )
    i_min = int(indices[0])
    coarse = distance_to_limit(ar, data.sequence_name, data.j, p, i_min)
    fine_seq, _, fine_p = data.refined
    first = 2 * i_min - fine_seq.i_min
    fine = distance_to_limit(
        ar,
        data.sequence_name,
        2 * data.j,
        fine_p[first : first + 2 * (data.count - 1) + 1],
        2 * i_min,
    )
    ratio = fine / coarse if coarse > 0 else float("inf")
    order = math.log2(coarse / fine) if coarse > 0 and fine > 0 else float("nan")
    note = f"distance at j = {data.j}: {coarse:.6g}; at 2j = {2 * data.j}: {fine:.6g}" + (
        f"; observed order {order:.3g}" if math.isfinite(order) else ""
    )
    check = check_residuals(
        THEOREM_11, ar, indices[:1], np.array([ratio]), CONVERGENCE_TOLERANCE, False
    )
    return replace(check, note=note)


def _example(
    ar: Arithmetic,
    data: D2bPolygons,
    statement: Statement,
    name: SequenceName,
    n: Array,
    indices: np.ndarray[Any, np.dtype[np.int64]],
    tolerance: float,
    detail: bool,
) -> Check:
    if data.sequence_name != name or data.j is None:
        return not_applicable(statement, tolerance, f"applies to sequence={name} only")
    residual = hypothesis_residuals(ar, name, data.j, indices, n)
    check = check_residuals(statement, ar, indices, residual, tolerance, detail)
    return replace(check, note=hypothesis_note(ar, name, data.j, int(indices[0])))


def hypothesis_residuals(
    ar: Arithmetic,
    name: SequenceName,
    j: int,
    indices: np.ndarray[Any, np.dtype[np.int64]],
    n: Array,
) -> Array:
    """Example 12 / Remark 13 on a Gauss image n (indices given): per index the largest of
    |n_i^x − g(i/j)|, the drop n_i^x − n_{i+1}^x (strictly increasing), |n_i^x| − 1 (bound) and,
    at i = 0, |n_0 − (0, 1)|; 0 where the sequence is what the paper says."""
    x = n[:, 0]
    t = ar.array(indices) / ar.scalar(j)
    g = (
        catenoid_convergence.example_12_g(t)
        if name == "example-12"
        else catenoid_convergence.remark_13_g(t)
    )
    residual = abs(x - g)
    zero = ar.scalar(0)
    if len(x) > 1:
        drops = np.maximum(x[:-1] - x[1:], zero)
        residual[:-1] = np.maximum(residual[:-1], drops)
    residual = np.maximum(residual, np.maximum(abs(x) - 1, zero))
    at_zero = np.flatnonzero(indices == 0)
    if len(at_zero):
        k = int(at_zero[0])
        residual[k] = max(residual[k], abs(n[k, 0]) + abs(n[k, 1] - 1))
    return residual


def hypothesis_note(ar: Arithmetic, name: SequenceName, j: int, i_min: int) -> str:
    """What the hypothesis checks of Example 12 / Remark 13 cannot see (g' on the range)."""
    if name == "remark-13":
        t = ar.scalar(i_min) / ar.scalar(j)
        bound = ar.to_float(1 / ((1 + t) * (1 + t)))
        return f"sup g' on the range = {bound:.6g} (bounded)"
    return "g'(0) = 0 and g is even: Lemma 10's hypothesis g' > 0 holds on t > 0 only"


def compute(
    ar: Arithmetic,
    sequence: SequenceName = "example-12",
    j: int | None = None,
    s: list[float] | None = None,
    i_min: int | None = None,
    i_max: int | None = None,
    detail: bool = False,
    selection: Selection = EVERYTHING,
) -> Curve:
    """(D2b) on i_min .. i_max with its Gauss image and checks (defaults: ``resolve_range``)."""
    if sequence == "custom" and j is not None:
        raise DomainError("j", "j is not used with sequence=custom (give s instead)", j)
    if sequence != "custom" and s is not None:
        raise DomainError("s", "s is only used with sequence=custom", f"{len(s)} numbers")
    if sequence != "custom" and j is None:
        j = DEFAULT_J
    first, last = resolve_range(sequence, j, s, i_min, i_max)
    data = polygons(ar, sequence, j, s, first, last)
    checks = evaluate(ar, data, detail, selection)
    window = slice(data.first, data.first + data.count)
    parameters: dict[str, Any] = {"sequence": sequence, "i_min": first, "i_max": last}
    if sequence == "custom":
        parameters["s"] = s
    else:
        parameters["j"] = j
    return INFO.curve(
        ar,
        parameters,
        data.p[window],
        {"gauss_image": data.n[window]},
        checks=checks,
        companion_tolerances={"gauss_image": construction_tolerance(ar, data)},
        selection=selection,
    )
