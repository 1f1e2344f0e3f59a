"""(D4b): the checks of Sections 3 and 4.2 on given polygons, each evaluated on demand.

``evaluate`` runs the selected statements of ``STATEMENTS`` (``discretization``) on any polygons
(computed ones, or perturbed ones in the tests); each check reads only the polygons and shared
quantities (``_Context``: fits, tolerances) it needs. The Gauss images of Section 5 and Theorems
7, 8 are checked in ``curvature``. Errata of the proof of Theorem 4 are carried on the checks.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from concurrent.futures import Future, ThreadPoolExecutor
from dataclasses import replace
from functools import cached_property
from typing import TYPE_CHECKING, Any

import numpy as np

from app.geometry import conditions, darboux, nikolaides
from app.geometry.catalog.section3 import (
    D4B_DARBOUX as DARBOUX,
    D4B_DARBOUX_DISTANCE as DARBOUX_DISTANCE,
    D4B_NIKOLAIDES as NIKOLAIDES,
)
from app.geometry.catalog.section4 import (
    D4B_HYPOTHESIS as HYPOTHESIS,
    D4B_RECURSION_13 as RECURSION_13,
    D4B_ROTATION_ANGLE as ROTATION_ANGLE,
    D4B_THEOREM_4_I as THEOREM_4_I,
    D4B_THEOREM_4_II as THEOREM_4_II,
    D4B_THEOREM_4_III as THEOREM_4_III,
    D4B_THEOREM_5 as THEOREM_5,
    D4B_THEOREM_6 as THEOREM_6,
    D4B_TWO_STEP as TWO_STEP,
)
from app.geometry.catalog.section5 import (
    D4B_EQUATION_18,
    D4B_EQUATION_19,
    D4B_EQUATION_20,
)
from app.geometry.checks import (
    Check,
    Erratum,
    IndexRange,
    Largest,
    Statement,
    check_residuals,
    not_applicable,
    printed_residual,
    relative_difference,
    relative_to,
)
from app.geometry.compiled import largest_of_magnitudes
from app.geometry.curve import EVERYTHING, Selection
from app.geometry.d4b import (
    arb_checks,
    closed_forms as kinematic_closed_forms,
    curvature as d4b_curvature,
    fused_checks,
    residual_kernels,
)
from app.geometry.d4b.residual_kernels import point_distance, relative_point_difference
from app.geometry.precision import Arithmetic, Array, Scalar
from app.geometry.tolerances import (
    LOCAL_STEPS,
    NOT_CONSTRUCTED,
)

if TYPE_CHECKING:
    from app.geometry.d4b.discretization import D4bPolygons

ERRATUM_ANGLE = (
    "E1",
    "α_i is the angle at p_i between the lines to (x_i, 0) and (x_{i+1}, 0)",
    "α_i is the angle at p_i between the lines to x_{i−1} and x_i (Theorem 5's indexing, "
    "p_i^x = (2i−1)d)",
)
ERRATUM_RATIO = (
    "E2",
    "Δ²p_i^{y2}/(l_i + l_{i+1}) = Δ²p_{i+1}^{y2}/(l_{i+1} + l_{i+2}) with the proof's "
    "l_i = √(4d² + (p_i^y − p_{i−1}^y)²)",
    "Δ²p_i^y/(l_i + l_{i+1}) = Δ²p_{i+1}^y/(l_{i+1} + l_{i+2}) with l_i = |p_{i+1} − p_i| as in "
    "(D1)",
)
ERRATUM_TWO_STEP = (
    "E3",
    "d⁴(2p_i^{y3} + 2p_{i−1}^y + 3p_i^y) in the numerator of p_{i+2}^y",
    "d⁴(2p_{i−1}^y + 3p_i^y)",
)


#: The statements that compare with a closed form (``fused_checks.fill_closed_forms``).
_CLOSED_FORMS = (THEOREM_5, THEOREM_6, D4B_EQUATION_18, D4B_EQUATION_19, D4B_EQUATION_20)
#: The statements that read the fits of (D1), (D3) and eq. (2).
_FITTED = (THEOREM_4_I, THEOREM_4_II, THEOREM_4_III)
#: The statements whose float64 numbers come from one call when all are selected
#: (``_Context.section_numbers``).
_SECTION = (
    HYPOTHESIS,
    *_FITTED,
    ROTATION_ANGLE,
    RECURSION_13,
    TWO_STEP,
    DARBOUX,
    DARBOUX_DISTANCE,
    NIKOLAIDES,
)
#: From this many indices a float64 computation that checks a fit computes the fits on a second
#: thread, from the start of the checks to where they are first read (≈ 30 ms at 10^6 here;
#: a thread costs ≈ 0.1 ms), as ``curvature`` does with its two rings.
FITS_THREADED_FROM = 100_000


def conditioning(h: float, d: float) -> float:
    """κ = h²/(h² − d²): how much one step of (D4b) amplifies rounding.

    Both the construction (h − d·cos β cancels for a steep stick) and the recursion (13) (its
    denominator p_{i−1}^y p_i^y − d² can be as small as h² − d²) lose log10(κ) digits as d → h;
    the local tolerances are multiplied by κ (1.01 for d = h/10, 50 for d = 0.99h).
    """
    ratio = float(d) / float(h)
    return 1 / ((1 - ratio) * (1 + ratio))


def evaluate(
    ar: Arithmetic,
    h: float,
    d: float,
    data: D4bPolygons,
    detail: bool = False,
    beta0: float | None = None,
    selection: Selection = EVERYTHING,
) -> tuple[dict[str, Scalar], list[Check]]:
    """Fitted constants and the selected checks of ``STATEMENTS`` on the given polygons.

    Each check computes only the polygons and shared quantities it needs (``_Context``); the
    constants of (D1), (D3) and (2) come with the checks that fit them (Theorem 4 (i)–(iii)),
    as ``Selection.constants`` has it: a selection without those checks computes no fit.
    """
    ctx = _Context(ar, ar.scalar(h), ar.scalar(d), data, detail, selection)
    ctx.start_fits()
    if ar.mode == "float64" and any(selection.wants_check(s.id) for s in _CLOSED_FORMS):
        # Theorems 5, 6 without detail compare block by block (``closed_largest``): no arrays
        kinematic = detail and any(selection.wants_check(s.id) for s in _CLOSED_FORMS[:2])
        # (18)-(20) on constructed images without detail compare block by block (``curvature``)
        images = (detail or not data.constructed) and any(
            selection.wants_check(s.id) for s in _CLOSED_FORMS[2:]
        )
        # the closed forms the selected statements compare with, in a few calls a block
        fused_checks.fill_closed_forms(data, images, kinematic)
    found: dict[int, Check] = {}
    later = []  # with the fits on their thread: their checks after the others, in their place
    for position, (statement, evaluator) in enumerate(_EVALUATORS):
        if selection.wants_check(statement.id):
            if ctx.fits_threaded and statement in _FITTED:
                later.append(position)
                continue
            ar.check_time()  # the compiled ball passes read no clock: one check per statement
            found[position] = evaluator(ctx)
    for position in later:
        ar.check_time()
        found[position] = _EVALUATORS[position][1](ctx)
    checks = [found[position] for position in sorted(found)]
    if any(selection.wants_check(s.id) for s in d4b_curvature.STATEMENTS):
        n = ctx.n
        shift = kinematic_closed_forms.tilt_shift(ar, ctx.h, ctx.d, beta0)
        checks += d4b_curvature.evaluate(
            ar,
            ctx.h,
            data.p,
            data.tractrix,
            data.gauss,
            d4b_curvature.printed_forms(ar, ctx.h, ctx.d, shift, data.i_min, data.i_min + n - 1),
            ctx.indices,
            n,
            ctx.tolerance,
            ctx.construction_tolerance,
            detail,
            selection.wants_check,
        )
    constants: dict[str, Scalar] = {}
    if "fit_constants" in vars(ctx):  # the fitted constants come with the checks that fit them
        constants = {k: c for k, c in ctx.fit_constants.items() if c is not None}
    return constants, checks


def tolerances(ar: Arithmetic, h: float, d: float, data: D4bPolygons) -> tuple[float, float, int]:
    """(local tolerance, construction tolerance, construction steps) of one computation.

    Local: a check on a few neighbouring vertices, times the conditioning κ (and the closed
    forms' own rounding when the polygons are the closed forms). Construction: comparisons
    along the whole recursion from stick 0.
    """
    n = data.vertices - 1
    rounding = 4 * math.ceil(data.exponent)  # steps' worth of the closed forms' own rounding
    kappa = conditioning(h, d)
    local = kappa * ar.tolerance(LOCAL_STEPS + (0 if data.constructed else rounding))
    steps = max(abs(data.i_min - 1), abs(data.i_min + n)) + 1 + rounding
    return local, ar.tolerance(max(steps, LOCAL_STEPS)), steps


class _Context:
    """What the checks of one computation share, each part computed when first needed."""

    def __init__(
        self,
        ar: Arithmetic,
        h: Scalar,
        d: Scalar,
        data: D4bPolygons,
        detail: bool,
        selection: Selection = EVERYTHING,
    ) -> None:
        self.ar, self.h, self.d, self.data, self.detail = ar, h, d, data, detail
        self.selection = selection
        self.n = data.vertices - 1
        self.indices = IndexRange(data.i_min, self.n + 1)  # an array only when shown
        self._pending_fits: Future[Any] | None = None

    @property
    def fits_threaded(self) -> bool:
        """Whether the fits run on a second thread (``start_fits``)."""
        return self._pending_fits is not None

    def start_fits(self) -> None:
        """Float64 from ``FITS_THREADED_FROM`` indices, when a fit is checked: the fits' kernel
        (a pure function of p that releases the GIL) on a second thread, joined where the fits
        are first read (``fused_fits``): ``evaluate`` takes Theorem 4 (i)–(iii) after the other
        checks of Sections 3 and 4.2 (before Section 5's rings, which take a second thread of
        their own), so that the fits run beside them."""
        wanted = any(self.selection.wants_check(s.id) for s in _FITTED)
        if self.ar.mode != "float64" or self.n < FITS_THREADED_FROM or not wanted:
            return
        kernel = fused_checks.fits_arrays if self.detail else fused_checks.fits_summary
        pool = ThreadPoolExecutor(max_workers=1, thread_name_prefix="fits")
        self._pending_fits = pool.submit(kernel, self.data.p[: self.n])
        pool.shutdown(wait=False)  # the thread ends with its one task

    @cached_property
    def _tolerances(self) -> tuple[float, float, int]:
        return tolerances(self.ar, self.h, self.d, self.data)

    @property
    def tolerance(self) -> float:
        """The local tolerance: a check on a few neighbouring vertices."""
        return self._tolerances[0]

    @property
    def construction_tolerance(self) -> float:
        """Comparisons along the whole recursion from stick 0."""
        return self._tolerances[1]

    @property
    def steps(self) -> int:
        """Construction steps from stick 0 to the farthest index (plus the closed forms')."""
        return self._tolerances[2]

    @cached_property
    def section_numbers(self) -> fused_checks.SectionNumbers | None:
        """Float64 without ``detail``, when every statement of ``_SECTION`` is selected and n is
        below ``fused_checks.SECTION_BELOW``: their numbers from one compiled call (the same
        bits as each check's own pass; ``fused_checks.section_numbers``), else None (each check
        calls its own: beyond a few hundred vertices the calls cost nothing to speak of)."""
        if self.ar.mode != "float64" or self.detail or self.n >= fused_checks.SECTION_BELOW:
            return None
        wanted = self.selection.wants_check
        if not all(wanted(statement.id) for statement in _SECTION):
            return None
        data = self.data
        return fused_checks.section_numbers(
            data.p, data.axis, data.darboux, data.tractrix, self.n, self.d, self.h
        )

    @cached_property
    def compiled_recursion(self) -> tuple[Array | Largest, Array | Largest]:
        """Float64 residuals of (13) and of its two-step form, both from one compiled pass (their
        largest values alone without ``detail``)."""
        if not self.detail:
            numbers = self.section_numbers
            found = None if numbers is None else numbers.recursion
            return residual_kernels.recursion_largest(self.d, self.data.p[:, 1], found)
        return residual_kernels.recursion_residuals(self.d, self.data.p[:, 1])

    @cached_property
    def closed_largest(self) -> tuple[float, float]:
        """Float64: the largest residuals of Theorems 5 and 6 (those selected), from one
        compiled pass."""
        wanted = self.selection.wants_check
        theorem_5, theorem_6 = wanted(THEOREM_5.id), wanted(THEOREM_6.id)
        given = {"closed_p", "closed_tractrix"} & vars(self.data).keys()
        if self.data.constructed and not given:  # each closed point compared as it is made
            found = fused_checks.closed_kinematic_comparisons(
                self.data, self.n, theorem_5, theorem_6
            )
            if found is not None:
                return found
        return fused_checks.closed_comparisons(self.data, self.n, theorem_5, theorem_6)

    @cached_property
    def fused_fits(self) -> fused_checks.Fits:
        """Float64: the fits of (D1), (D3) and eq. (2) on p_{i_min} .. p_{i_max}, eq. (2)'s misfit
        and each check's largest residual, from one compiled call (the residuals themselves
        with ``detail``; on a second thread from ``FITS_THREADED_FROM``, ``start_fits``)."""
        p = self.data.p[: self.n]
        if self._pending_fits is not None:
            return fused_checks.Fits(p, self._pending_fits.result())
        if self.detail:
            return fused_checks.Fits(p, fused_checks.fits_arrays(p))
        numbers = self.section_numbers
        return fused_checks.Fits(p, None if numbers is None else numbers.fits)

    @cached_property
    def fit_constants(self) -> dict[str, Scalar | None]:
        """The fitted constants of (D1), (D3) and (2) (``None`` where there is none)."""
        if self.ar.mode == "float64":  # without the residuals unless ``detail`` asks
            return dict(self.fused_fits.constants)
        return {key: fit.constant for key, fit in self.fits.items()}

    @cached_property
    def fits(self) -> dict[str, conditions.ConditionFit]:
        """Least-squares fits of (D1), (D3) and (2) on p_{i_min} .. p_{i_max}."""
        if self.ar.mode == "float64":  # the three from one set of columns, in one call
            return self.fused_fits.fits
        p = self.data.p[: self.n]
        ball_columns = self.ball_columns
        if ball_columns is not None:  # the same balls from one set of columns, compiled
            return {
                name: conditions.ConditionFit(*ball_columns.fit(kind, self.n))
                for name, kind in (
                    ("d1", arb_checks.D1),
                    ("d3", arb_checks.D3),
                    ("eq2", arb_checks.EQUATION_2),
                )
            }
        return {
            "d1": conditions.d1(self.ar, p),
            "d3": conditions.d3(self.ar, p),
            "eq2": conditions.equation_2(self.ar, p),
        }

    @cached_property
    def ball_columns(self) -> arb_checks.Columns | None:
        """Balls: the columns of (D1), (D3) and (2) on the whole polygon, for the compiled
        fits, misfits and the proof's ratio (None where ``arb_checks`` does not apply)."""
        if not self.ar.certified or not arb_checks.balls(self.data.p):
            return None
        return arb_checks.Columns(self.data.p, _tiny(self.ar))

    def fitted_residuals(self, key: str, residuals: Callable[[], Array]) -> Array | Largest:
        """A fit's residuals as a check takes them: float64 without ``detail`` the largest
        alone (``fused_fits``; ``key`` ``"eq2"`` stands for eq. (2) with its misfit), the
        residuals computed only if the check asks for them."""
        if self.ar.mode == "float64" and not self.detail:
            fits = self.fused_fits
            return Largest(fits.largest[key], fits.counts[key], residuals)
        return residuals()

    def check(
        self,
        statement: Statement,
        first: int,
        residuals: Array | Largest,
        erratum: Erratum | None = None,
        factor: int = 1,
        note: str | None = None,
    ) -> Check:
        """A check whose k-th residual belongs to index ``indices[first + k]``.

        ``factor`` widens the local tolerance for formulas with several times the usual number
        of operations and vertices.
        """
        idx = self.indices[first : first + len(residuals)]
        tolerance = self.tolerance * factor
        return check_residuals(
            statement, self.ar, idx, residuals, tolerance, self.detail, erratum, note
        )


def _hypothesis(ctx: _Context, p: Array) -> Check:
    if ctx.ar.mode == "float64" and not ctx.detail and ctx.n >= 2:  # one compiled pass
        numbers = ctx.section_numbers if p is ctx.data.p else None
        found = None if numbers is None else numbers.hypothesis
        largest, smallest = residual_kernels.hypothesis_largest(p, ctx.n, ctx.d, found)
        note = f"smallest p_(i-1)^y p_i^y / d² = {smallest:.6g}"
        if math.isfinite(largest.value):  # the note is the check's only one
            return ctx.check(HYPOTHESIS, 1, largest, note=note)
        return replace(ctx.check(HYPOTHESIS, 1, largest), note=note)
    y = p[: ctx.n, 1]
    if ctx.ar.certified and arb_checks.balls(y):  # the same balls, compiled
        violation, ratios = arb_checks.hypothesis(ctx.d, y)
        check = ctx.check(HYPOTHESIS, 1, violation)
        if len(ratios):
            smallest = ctx.ar.to_float(np.min(ratios))
            return replace(check, note=f"smallest p_(i-1)^y p_i^y / d² = {smallest:.6g}")
        return check
    d2 = ctx.d * ctx.d
    products = y[:-1] * y[1:]
    violation = ctx.ar.maximum(d2 - products, ctx.ar.scalar(0)) / d2
    check = ctx.check(HYPOTHESIS, 1, violation)
    if len(products):
        smallest = ctx.ar.to_float(np.min(products / d2))
        return replace(check, note=f"smallest p_(i-1)^y p_i^y / d² = {smallest:.6g}")
    return check


def _fitted(
    ctx: _Context,
    statement: Statement,
    key: str,
    erratum: Erratum | None = None,
    residuals: Callable[[], Array] | None = None,
) -> Check:
    """The check of the fit ``key``: its residuals (``ctx.fits[key]``'s unless given)."""
    if residuals is None:
        residuals = lambda: ctx.fits[key].residuals  # noqa: E731
    check = ctx.check(statement, 0, ctx.fitted_residuals(key, residuals), erratum)
    constant = ctx.fit_constants[key]
    if constant is not None and not constant > 0 and check.holds:
        return replace(check, holds=False, note="the fitted constant is not > 0")
    return check


def _equation_2(ctx: _Context, p: Array) -> Check:
    """(2) with the fitted c and with c = c_(D1)/c_(D3), both residuals measured alike.

    Comparing the constants themselves would ask more than the data resolve: a constant fitted
    to second differences is known only to eps·|y|/|Δ²y| relative, about eps·(h/d)², while the
    equation's residual stays relative to the magnitude of the numbers it is computed from.
    """
    if ctx.ar.mode == "float64":  # p is ctx.data.p[: n]: both in the fits' one call
        return _fitted(ctx, THEOREM_4_III, "eq2", residuals=lambda: ctx.fused_fits.equation_2)
    fits = ctx.fits
    c1, c2 = fits["d1"].constant, fits["d3"].constant
    residuals = fits["eq2"].residuals
    if c1 is not None and c2 is not None and c2 != 0 and len(residuals):
        if ctx.ball_columns is not None and len(p) == ctx.n:  # compiled, the same balls
            misfit = ctx.ball_columns.misfit(arb_checks.EQUATION_2, ctx.n, c1 / c2)
        else:
            misfit = conditions.equation_2_misfit(ctx.ar, p, c1 / c2)
        residuals = ctx.ar.maximum(residuals, misfit)
    return _fitted(ctx, THEOREM_4_III, "eq2", residuals=lambda: residuals)


def _ratio_erratum(ctx: _Context, p: Array) -> Erratum | None:
    """The proof's ratio with its own l_i = |p_i − p_{i−1}|: not constant along the polygon."""
    ar = ctx.ar
    if ar.mode == "float64":  # the same numbers in compiled passes, the ratios' array alone
        numbers = ctx.section_numbers if p is ctx.data.p else None
        found = None if numbers is None else numbers.ratio
        return Erratum(*ERRATUM_RATIO, printed_residual=residual_kernels.ratio_spread(p, found))
    if p is ctx.data.p and ctx.ball_columns is not None:  # the same balls, compiled
        spread = ctx.ball_columns.ratio_spread()
        worst = None if spread is None else printed_residual(ar, spread)
        return Erratum(*ERRATUM_RATIO, printed_residual=worst)
    y = p[:, 1]
    lengths = ar.hypot(p[1:, 0] - p[:-1, 0], y[1:] - y[:-1])  # lengths[k] = |p_{k+1} − p_k|
    # printed: Δ²p_i^y / (l'_i + l'_{i+1}) with l'_i = |p_i − p_{i−1}|, for i with p_{i−1} known
    ratio = (y[3:] - 2 * y[2:-1] + y[1:-2]) / (lengths[:-2] + lengths[1:-1])
    if len(ratio) < 2:
        return Erratum(*ERRATUM_RATIO, printed_residual=None)
    spread = relative_difference(ar, ratio, np.full_like(ratio, np.sum(ratio) / len(ratio)))
    return Erratum(*ERRATUM_RATIO, printed_residual=printed_residual(ar, spread))


def _rotation_angle(ctx: _Context, p: Array, axis: Array) -> Check:
    ar, n = ctx.ar, ctx.n
    if ar.mode == "float64" and not ctx.detail:  # the largest residuals in one compiled pass
        numbers = ctx.section_numbers if p is ctx.data.p and axis is ctx.data.axis else None
        found = None if numbers is None else numbers.rotation
        largest, worst = residual_kernels.rotation_angle_largest(ctx.d, p, axis, n, found)
        return ctx.check(ROTATION_ANGLE, 1, largest, Erratum(*ERRATUM_ANGLE, worst))
    if ar.mode == "float64":  # the same residuals in one compiled pass
        corrected, printed_angles = residual_kernels.rotation_angles(ctx.d, p, axis, n)
        erratum = Erratum(*ERRATUM_ANGLE, printed_residual=printed_residual(ar, printed_angles))
        return ctx.check(ROTATION_ANGLE, 1, corrected, erratum)
    if ar.certified and arb_checks.balls(p[: n + 1], axis[: n + 1]):  # the same balls, compiled
        corrected, printed_angles = arb_checks.rotation_angle(ctx.d, p, axis, n)
        erratum = Erratum(*ERRATUM_ANGLE, printed_residual=printed_residual(ar, printed_angles))
        return ctx.check(ROTATION_ANGLE, 1, corrected, erratum)
    a = axis[: n - 1] - p[1:n]  # x_{i−1} − p_i
    b = axis[1:n] - p[1:n]  # x_i − p_i
    angle = _signed_angle(ar, a, b)
    formula = 2 * ar.atan2(ctx.d, p[1:n, 1])
    # printed indexing: the angle at p_i between x_i and x_{i+1}
    printed = _signed_angle(ar, axis[1:n] - p[1:n], axis[2 : n + 1] - p[1:n])
    erratum = Erratum(*ERRATUM_ANGLE, printed_residual=printed_residual(ar, abs(printed - formula)))
    return ctx.check(ROTATION_ANGLE, 1, abs(angle - formula), erratum)


def _signed_angle(ar: Arithmetic, a: Array, b: Array) -> Array:
    """The angle turning vector a_k into b_k, in (−π, π]; ``(n, 2) -> (n,)``."""
    cross = a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]
    return ar.atan2(cross, a[:, 0] * b[:, 0] + a[:, 1] * b[:, 1])


def _recursion(ctx: _Context, p: Array) -> Check:
    y = p[:, 1]
    if ctx.ar.mode == "float64" and p is ctx.data.p:  # the same residuals, compiled
        return ctx.check(RECURSION_13, 1, ctx.compiled_recursion[0])
    if ctx.ar.certified and arb_checks.balls(y):  # the same balls, compiled
        return ctx.check(RECURSION_13, 1, arb_checks.recursion_13(ctx.d, y, _tiny(ctx.ar)))
    predicted = kinematic_closed_forms.recursion_13(ctx.d, y[:-2], y[1:-1])
    return ctx.check(RECURSION_13, 1, relative_difference(ctx.ar, y[2:], predicted))


def _two_step(ctx: _Context, p: Array) -> Check:
    y = p[:, 1]
    ar = ctx.ar
    if ar.certified and arb_checks.balls(y):  # the same balls as below, compiled
        corrected, printed = arb_checks.two_step(ctx.d, y, _tiny(ar))
        erratum = Erratum(*ERRATUM_TWO_STEP, printed_residual=printed_residual(ar, printed))
        return ctx.check(TWO_STEP, 1, corrected, erratum, factor=3)
    # the printed form has 7th powers: its residual only where they stay finite (max |y| as
    # np.max(abs(y)), NaN included, by one compiled pass in float64)
    numbers = ctx.section_numbers if p is ctx.data.p else None
    if ar.mode != "float64":
        small = True
    elif numbers is not None:
        small = numbers.height < 1e60
    else:
        small = float(largest_of_magnitudes(y)) < 1e60
    if ar.mode == "float64" and small:  # the same, compiled
        found = None if numbers is None else numbers.two_step_printed
        worst = residual_kernels.largest_two_step_printed_residual(ctx.d, y, found)
        erratum = Erratum(*ERRATUM_TWO_STEP, printed_residual=worst)
    elif ar.mode == "mp":
        printed = kinematic_closed_forms.two_step_printed(ctx.d, y[:-3], y[1:-2])
        erratum = Erratum(
            *ERRATUM_TWO_STEP,
            printed_residual=printed_residual(ar, relative_difference(ar, y[3:], printed)),
        )
    else:
        erratum = Erratum(*ERRATUM_TWO_STEP, printed_residual=None)
    # (13) twice: three vertices and about three times the operations of a local check
    if ar.mode == "float64" and p is ctx.data.p:  # the same residuals, compiled
        residuals = ctx.compiled_recursion[1]
    else:
        corrected = kinematic_closed_forms.two_step(ctx.d, y[:-3], y[1:-2])
        residuals = relative_difference(ar, y[3:], corrected)
    return ctx.check(TWO_STEP, 1, residuals, erratum, factor=3)


def _tiny(ar: Arithmetic) -> Scalar:
    """The floor of ``checks.relative_difference``'s scale, as it makes it."""
    return ar.scalar(np.finfo(np.float64).tiny)


def _closed_form(
    ctx: _Context,
    statement: Statement,
    constructed: bool,
    computed: Array,
    closed_form: Callable[[], Array],
    steps: int,
    polygon: str,
    scale: Callable[[], Array] | None = None,
) -> Check:
    """Construction against closed form; the construction's rounding grows with its steps.

    ``scale`` (per vertex) replaces |closed form| as the magnitude the difference is measured
    against where the vertex is a difference of larger terms: d_i = x_i + h·u_i is computed to
    a few units of |x_i| + h, and its x-coordinate vanishes (|d_i| → 0) near β0 → 0 or π, where
    a difference relative to |d_i| reported errors of 1e-7 for points right to 1e-16 (issue 15).
    ``polygon`` names ``computed`` in ``ctx.data`` (``"p"``, ``"tractrix"``): in float64
    without ``detail`` both theorems' largest residuals come from one compiled pass.
    """
    tolerance = conditioning(ctx.h, ctx.d) * ctx.ar.tolerance(max(steps, LOCAL_STEPS))
    if not constructed:
        return not_applicable(statement, tolerance, NOT_CONSTRUCTED)
    n = ctx.n

    def separate() -> Array:
        closed = closed_form()
        if scale is None:
            return relative_point_difference(ctx.ar, computed[:n], closed[:n])
        scales = scale()[:n]
        if ctx.ar.certified and arb_checks.balls(computed[:n], closed[:n], scales):
            # the same balls, compiled
            return arb_checks.relative_distances(computed[:n], closed[:n], scales, _tiny(ctx.ar))
        difference = point_distance(ctx.ar, computed[:n], closed[:n])
        return relative_to(ctx.ar, difference, scales)

    residuals: Array | Largest
    if ctx.ar.mode == "float64" and not ctx.detail and computed is getattr(ctx.data, polygon):
        # Theorems 5 and 6 from one compiled pass, the largest alone
        largest = ctx.closed_largest[("p", "tractrix").index(polygon)]
        residuals = Largest(largest, len(computed[:n]), separate)
    else:
        residuals = separate()
    return check_residuals(statement, ctx.ar, ctx.indices[:n], residuals, tolerance, ctx.detail)


def _nikolaides(ctx: _Context, p: Array, tractrix: Array, axis: Array) -> Check:
    n = ctx.n
    if ctx.ar.mode == "float64":  # the same residuals in one compiled pass
        if not ctx.detail:  # the largest alone
            same = p is ctx.data.p and tractrix is ctx.data.tractrix and axis is ctx.data.axis
            numbers = ctx.section_numbers if same else None
            found = None if numbers is None else numbers.right_angles
            return ctx.check(
                NIKOLAIDES, 0, residual_kernels.right_angle_largest(tractrix, axis, p, n, found)
            )
        return ctx.check(
            NIKOLAIDES, 0, residual_kernels.right_angle_residuals(tractrix, axis, p, n)
        )
    if ctx.ar.certified and arb_checks.balls(tractrix[:n], axis[:n], p[: n + 1]):  # compiled
        return ctx.check(NIKOLAIDES, 0, arb_checks.nikolaides(tractrix, axis, p, n))
    at_p = nikolaides.right_angle_residuals(tractrix[:n], axis[:n], p[:n])
    at_next = nikolaides.right_angle_residuals(tractrix[:n], axis[:n], p[1 : n + 1])
    return ctx.check(NIKOLAIDES, 0, ctx.ar.maximum(at_p, at_next))


def _darboux(ctx: _Context) -> Check:
    n, axis, e = ctx.n, ctx.data.axis, ctx.data.darboux
    if ctx.ar.certified and arb_checks.balls(axis[:n], e[:n]):  # the same balls, compiled
        return ctx.check(DARBOUX, 0, arb_checks.darboux_edges(axis[:n], e[:n]))
    if ctx.ar.mode == "float64" and not ctx.detail:  # the largest alone, in one compiled pass
        numbers = ctx.section_numbers
        found = None if numbers is None else numbers.darboux_edges
        return ctx.check(DARBOUX, 0, darboux.edge_length_largest(axis[:n], e[:n], found))
    return ctx.check(DARBOUX, 0, darboux.edge_length_residuals(ctx.ar, axis[:n], e[:n]))


def _darboux_distance(ctx: _Context) -> Check:
    n, axis, e = ctx.n, ctx.data.axis, ctx.data.darboux
    if ctx.ar.certified and arb_checks.balls(axis[:n], e[:n]):  # the same balls, compiled
        residuals = arb_checks.darboux_distances(axis[:n], e[:n], 2 * ctx.h)
    elif ctx.ar.mode == "float64" and not ctx.detail:  # the largest alone, in one compiled pass
        numbers = ctx.section_numbers
        found = None if numbers is None else numbers.darboux_distances
        largest = darboux.distance_largest(axis[:n], e[:n], 2 * ctx.h, found)
        return ctx.check(DARBOUX_DISTANCE, 0, largest)
    else:
        residuals = darboux.distance_residuals(ctx.ar, axis[:n], e[:n], 2 * ctx.h)
    return ctx.check(DARBOUX_DISTANCE, 0, residuals)


#: Each statement of Section 3 and 4.2 about (D4b) and the function that evaluates it, in the
#: order of the response; each reads only the polygons and fits it needs.
_EVALUATORS: tuple[tuple[Statement, Callable[[_Context], Check]], ...] = (
    (HYPOTHESIS, lambda c: _hypothesis(c, c.data.p)),
    (
        THEOREM_4_I,
        lambda c: _fitted(c, THEOREM_4_I, "d1", _ratio_erratum(c, c.data.p)),
    ),
    (THEOREM_4_II, lambda c: _fitted(c, THEOREM_4_II, "d3")),
    (THEOREM_4_III, lambda c: _equation_2(c, c.data.p[: c.n])),
    (ROTATION_ANGLE, lambda c: _rotation_angle(c, c.data.p, c.data.axis)),
    (RECURSION_13, lambda c: _recursion(c, c.data.p)),
    (TWO_STEP, lambda c: _two_step(c, c.data.p)),
    (
        THEOREM_5,
        lambda c: _closed_form(
            c, THEOREM_5, c.data.constructed, c.data.p, lambda: c.data.closed_p, c.steps, "p"
        ),
    ),
    (
        THEOREM_6,
        lambda c: _closed_form(
            c,
            THEOREM_6,
            c.data.constructed,
            c.data.tractrix,
            lambda: c.data.closed_tractrix,
            c.steps,
            "tractrix",
            lambda: abs(c.data.axis[:, 0]) + c.h,  # d_i = x_i + h u_i: the terms' magnitude
        ),
    ),
    (DARBOUX, _darboux),
    (DARBOUX_DISTANCE, _darboux_distance),
    (NIKOLAIDES, lambda c: _nikolaides(c, c.data.p, c.data.tractrix, c.data.axis)),
)
