"""What the two (D2a) discretizations share: residual measures, check context, float64 limits."""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import replace
from decimal import Decimal
from fractions import Fraction
from typing import Any

import numpy as np

from app.geometry import conditions
from app.geometry.catalog.section3 import D1 as SHARED_D1, D3 as SHARED_D3
from app.geometry.catalog.section4 import EQUATION_2 as SHARED_EQUATION_2
from app.geometry.checks import (
    Check,
    Erratum,
    Statement,
    check_residuals,
    not_applicable,
    printed_residual,
)
from app.geometry.errors import NotRepresentableError
from app.geometry.on_demand import OnDemand
from app.geometry.polygon import magnitude
from app.geometry.precision import Arithmetic, Array, Scalar, stack_points
from app.geometry.tolerances import (
    LOCAL_STEPS,
    below_root_working_unit,
    root_working_unit_text,
    unit,
)

#: In float64 every f_i and 1/f_i stays below this bound, so that the printed formulas (which
#: hold f⁴) and the areas (products of coordinates) stay finite.
FLOAT64_F_LIMIT = 1e50

#: Below this relative gap between consecutive f_i the Gauss image edges are differences of
#: nearly equal points and float64 loses most digits (error about 1e-16/gap); use precision=mp.
FLOAT64_MIN_GAP = 1e-4


def require_mp_gap(ar: Arithmetic, parameter: str, what: str, value: float, gap: Fraction) -> None:
    """In mp, refuse relative gaps below √(working unit): their Gauss image edges vanish.

    ``gap`` is exact (of the parameters as written, ``tolerances.exact``) and so is the
    comparison: a float √(10^−(digits+guard)) is 0 from 314 digits on.
    """
    if below_root_working_unit(ar, gap):
        raise NotRepresentableError(
            parameter,
            f"{what} >= {root_working_unit_text(ar)} in mp with {ar.digits} digits",
            value,
            "nearly equal f_i give Gauss image edges below the working precision; use more digits",
        )


def local_tolerance(ar: Arithmetic, gap: Scalar) -> Any:
    """Tolerance of a local check: ``Arithmetic.tolerance(16)`` times the conditioning 1/gap
    (on balls a ball: 1/gap leaves the float range where the gap is below 1e-308, which the
    digits allow from 606 on)."""
    if not ar.certified:
        return ar.tolerance(LOCAL_STEPS) * max(1.0, 1 / ar.to_float(gap))
    return ar.tolerance(LOCAL_STEPS) * ar.maximum(ar.scalar(1), 1 / gap)


def at_r_star(ar: Arithmetic, r: Scalar, r_star: Scalar) -> bool:
    """Whether the start height r is r* to within 4 units of the requested precision, relative
    (Theorems 1 and 2 hold only there). In mp the unit is a number of ``ar`` (``unit``): a float
    10^−digits is 0 from 324 digits on, where only an exactly equal r would have counted."""
    return bool(abs(r - r_star) <= 4 * unit(ar) * abs(r_star))


def off_r_star_note(ar: Arithmetic, r: Scalar, r_star: Scalar) -> str:
    """The note of a check that holds only for r = r*, on a polygon starting elsewhere; in mp
    with r − r* too (r and r* agree as floats when they differ beyond the 17th digit)."""
    note = (
        f"holds only for r = r* = {ar.to_float(r_star):.17g}; this polygon starts at "
        f"r = {ar.to_float(r):.17g}"
    )
    if ar.mode == "float64":
        return note
    difference = ar.to_strings(np.array([r - r_star], dtype=object))[0]  # type: ignore[attr-defined]
    return f"{note} (r − r* = {format(Decimal(difference), '.3g')})"


class Context(OnDemand):
    """What every check of one computation shares; the discretizations add their quantities."""

    def __init__(
        self,
        ar: Arithmetic,
        indices: np.ndarray[Any, np.dtype[np.int64]],
        steps: int,
        detail: bool,
        gap: Scalar,
    ) -> None:
        """``gap``: the smallest relative gap (f_{i+1} − f_i)/f_{i+1} of the parameter line.

        The Gauss image edges are differences of points whose relative distance is about the gap,
        so every quantity derived from them carries rounding of about eps/gap: the local
        tolerance is the core's ``Arithmetic.tolerance(16)`` times this conditioning factor 1/gap.
        Comparisons of vertices with closed forms add ``Arithmetic.tolerance(steps)`` for the
        rounding accumulated along the cumulative sum from p_0.
        """
        self.ar, self.indices, self.detail = ar, indices, detail
        self.local = local_tolerance(ar, gap)
        self.summed = ar.tolerance(steps) + self.local

    def check(
        self,
        statement: Statement,
        first: int,
        residuals: Array,
        erratum: Erratum | None = None,
        summed: bool = False,
        note: str | None = None,
        at: np.ndarray[Any, np.dtype[np.int64]] | None = None,
    ) -> Check:
        """A check whose k-th residual belongs to index ``indices[first + k]`` (or ``at[k]``)."""
        idx = self.indices[first : first + len(residuals)] if at is None else at
        tolerance = self.summed if summed else self.local
        return check_residuals(
            statement, self.ar, idx, residuals, tolerance, self.detail, erratum, note
        )

    def erratum(self, entry: tuple[str, str, str], residuals: Array) -> Erratum:
        """An ``Erratum`` whose printed residual is the largest of ``residuals``."""
        return Erratum(*entry, printed_residual=printed_residual(self.ar, residuals))


def companions(ar: Arithmetic, f: Array, gauss: Array) -> dict[str, Callable[[], Array]]:
    """The conformal points f_i (on the x-axis) and their stereographic images φ_i, eq. (S2),
    each when selected."""
    return {"conformal": lambda: stack_points(f, ar.zeros(len(f))), "gauss_image": lambda: gauss}


def scaled_difference(ar: Arithmetic, computed: Array, expected: Array, size: Array) -> Array:
    """|computed − expected| / max(|expected|, size), entry by entry (size: data magnitude)."""
    tiny = ar.scalar(np.finfo(np.float64).tiny)
    scale = np.maximum(np.maximum(abs(expected), size), tiny)
    return abs(computed - expected) / scale


def scaled_point_difference(ar: Arithmetic, computed: Array, expected: Array, size: Array) -> Array:
    """|computed_i − expected_i| / max(|expected_i|, size_i) for ``(m, 2)`` point arrays."""
    tiny = ar.scalar(np.finfo(np.float64).tiny)
    norm = ar.hypot(expected[:, 0], expected[:, 1])
    scale = np.maximum(np.maximum(norm, size), tiny)
    dx, dy = computed[:, 0] - expected[:, 0], computed[:, 1] - expected[:, 1]
    return ar.hypot(dx, dy) / scale


def vertex_magnitude(*points: Array) -> Array:
    """Sum of the absolute coordinates of the given ``(m, 2)`` vertex arrays."""
    return magnitude(*points)


def fitted_condition(
    ctx: Context,
    statement: Statement,
    fit: conditions.ConditionFit,
    note_holds: str,
    note_fails: str,
) -> Check:
    """A (D1)/(D3)/(2) check with the fitted constant named in the note."""
    check = ctx.check(statement, 0, fit.residuals)
    if check.holds is None:
        return check
    constant = "undetermined" if fit.constant is None else f"{ctx.ar.to_float(fit.constant):.6g}"
    if check.holds and fit.constant is not None and not fit.constant > 0:
        # (D1), (D3) and (2) ask for c > 0: a polygon fitting them with c <= 0 is not one of
        # theirs (as GET /relations answers for the same polygon)
        return replace(
            check, holds=False, note=f"least-squares c = {constant}; {note_fails} (c is not > 0)"
        )
    note = note_holds if check.holds else note_fails
    return replace(check, note=f"least-squares c = {constant}; {note}")


def shifted(p: Array, dy: Scalar) -> Array:
    """The polygon moved vertically by ``dy``."""
    moved = p.copy()
    moved[:, 1] = p[:, 1] + dy
    return moved


def not_enough(ctx: Context, statement: Statement, what: str) -> Check:
    """A check that needs more vertices than the range has."""
    return not_applicable(statement, ctx.summed, f"needs {what}")


def require_f_range(name: str, log_f: list[float], value: int) -> None:
    """Refuse a float64 range whose f_i or 1/f_i would exceed ``FLOAT64_F_LIMIT``."""
    limit = math.log(FLOAT64_F_LIMIT)
    if max(abs(v) for v in log_f) > limit:
        raise NotRepresentableError(
            name,
            f"every f_i and 1/f_i <= {FLOAT64_F_LIMIT:g} in float64",
            value,
            "the conformal points leave the float64 range of the checks; use precision=mp",
        )


__all__ = ["SHARED_D1", "SHARED_D3", "SHARED_EQUATION_2"]
