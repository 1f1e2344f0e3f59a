"""Checks: a claim of the paper, tested against computed data, with its residual and verdict.

A check never decides by construction: it evaluates the claim on the vertices that were
computed and compares the residual with a tolerance that fits the precision. Where the printed
formula is wrong, the check tests the corrected one and carries an ``Erratum`` whose
``printed_residual`` is the printed formula evaluated on the same data.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from decimal import ROUND_CEILING, Context, Decimal
from typing import Any

import flint
import numpy as np

from app.geometry import arb_loops
from app.geometry.ball_arithmetic import (
    BOUND_DIGITS,
    RESIDUAL_BITS,
    all_balls,
    decimal_ball,
    decimal_bound,
    decimal_tolerance,
)
from app.geometry.compiled import largest_of_magnitudes
from app.geometry.precision import Arithmetic, Array
from app.geometry.tolerances import MPMATH_FLOAT_DIGITS

ERRATA_DOCUMENT = "docs/errata.md"
#: Where the service serves each entry of ERRATA_DOCUMENT (GET /errata/{id}).
ERRATA_PAGE = "/errata"


@dataclass(frozen=True)
class Statement:
    """A checkable statement of the paper: its id, where it is, and what it claims."""

    id: str
    reference: str
    claim: str
    conditions: tuple[str, ...] = ()
    """Hypotheses the text leaves implicit or states needlessly, in words (docs/errata.md)."""
    defaults: tuple[tuple[str, str], ...] = ()
    """Parameters (name, value) under which the statement applies, used when a request to
    /theorems/{id} does not set them (e.g. Remark 13 is about ``sequence=remark-13``)."""
    errata: tuple[str, ...] = ()
    """Errata (``E<n>`` of docs/errata.md) whose printed formula the check carries at the
    default parameters: the print is wrong and the check tests the correction."""


@dataclass(frozen=True)
class Erratum:
    """A printed formula that is wrong, its correction, and the printed one's residual."""

    id: str
    """Anchor in docs/errata.md, e.g. ``"E3"``."""
    printed: str
    corrected: str
    printed_residual: float | Decimal | None
    """On balls a decimal rounded down: a rigorous lower bound (``printed_residual``)."""

    def __init__(
        self, id: str, printed: str, corrected: str, printed_residual: float | Decimal | None
    ) -> None:
        # written out as ``Check.__init__`` is (several errata a request)
        fields = self.__dict__
        fields["id"], fields["printed"], fields["corrected"] = id, printed, corrected
        fields["printed_residual"] = printed_residual

    @property
    def link(self) -> str:
        return f"{ERRATA_PAGE}/{self.id}"


@dataclass(frozen=True)
class PerIndex:
    """Residual of a check at each index where it is evaluated."""

    indices: np.ndarray[Any, np.dtype[np.int64]]
    residuals: np.ndarray[Any, np.dtype[np.float64]] | list[Decimal | None]
    """Floats; on balls decimals rounded up (``decimal_uppers``: rigorous upper bounds, which
    leave the float range from 324 digits on), ``None`` where a residual is not finite."""


@dataclass(frozen=True)
class Check:
    """The outcome of testing one statement on one computed polygon."""

    id: str
    reference: str
    claim: str
    residual: float | Decimal | None
    """On balls a decimal rounded up: a rigorous upper bound of the largest residual."""
    tolerance: float | Decimal
    """On balls a decimal (``decimal_tolerance``): they leave the float range from 324 digits
    on."""
    holds: bool | None
    """``None`` when the statement is not applicable (e.g. too few vertices)."""
    per_index: PerIndex | None = None
    erratum: Erratum | None = None
    note: str | None = None

    def __init__(
        self,
        id: str,
        reference: str,
        claim: str,
        residual: float | Decimal | None,
        tolerance: float | Decimal,
        holds: bool | None,
        per_index: PerIndex | None = None,
        erratum: Erratum | None = None,
        note: str | None = None,
    ) -> None:
        # written out: the generated __init__ of a frozen dataclass sets each field through
        # object.__setattr__ (about 4 µs for these nine); a 100-vertex D4b makes 21 checks
        fields = self.__dict__
        fields["id"], fields["reference"], fields["claim"] = id, reference, claim
        fields["residual"], fields["tolerance"], fields["holds"] = residual, tolerance, holds
        fields["per_index"], fields["erratum"], fields["note"] = per_index, erratum, note


class IndexRange:
    """The indices first, first + 1, …, first + count − 1 of the vertices a check reads, as
    ``check_residuals`` takes them: an array (``np.asarray``) only when a response shows them
    per index (``detail``) or a residual is not finite. A float64 check of a 10^6-vertex
    polygon otherwise made and filled 8 MB it never read (issue 13, session 30)."""

    __slots__ = ("count", "first")

    def __init__(self, first: int, count: int) -> None:
        self.first, self.count = first, max(count, 0)

    def __len__(self) -> int:
        return self.count

    def __getitem__(self, rows: slice) -> IndexRange:
        """The indices of rows ``rows`` (a slice with step 1), as ``np.arange(…)[rows]``."""
        start, stop, step = rows.indices(self.count)
        if step != 1:
            raise ValueError("an IndexRange takes slices with step 1")
        return IndexRange(self.first + start, stop - start)

    def __array__(self, dtype: Any = None, copy: Any = None) -> np.ndarray[Any, Any]:
        return np.arange(self.first, self.first + self.count, dtype=dtype or np.int64)


Indices = np.ndarray[Any, np.dtype[np.int64]] | IndexRange


@dataclass(frozen=True)
class Largest:
    """The largest of a check's ``count`` float64 residuals, found by a compiled pass that did
    not store them (a response without ``detail`` shows the largest alone).

    ``value`` is what ``largest_magnitude`` would give for the array (NaN if one is NaN);
    ``residuals`` computes the array itself, which ``check_residuals`` asks for only when the
    largest is not finite (its note counts the residuals that are not).
    """

    value: float
    count: int
    residuals: Callable[[], Array]

    def __init__(self, value: float, count: int, residuals: Callable[[], Array]) -> None:
        # written out as ``Check.__init__`` is: a 100-vertex D4b makes about twenty of these
        fields = self.__dict__
        fields["value"], fields["count"], fields["residuals"] = value, count, residuals

    def __len__(self) -> int:
        return self.count


def check_residuals(
    statement: Statement,
    ar: Arithmetic,
    indices: Indices,
    residuals: Array | Largest,
    tolerance: Any,
    detail: bool,
    erratum: Erratum | None = None,
    note: str | None = None,
) -> Check:
    """A check whose residual is the largest of the per-index ``residuals`` (all >= 0).

    ``tolerance`` is a float, or on balls (``ar.certified``) a ball or a float: there the
    residual is a rigorous upper bound, ``holds`` is true when it is <= the tolerance, false
    when a rigorous lower bound exceeds the tolerance, and ``None`` (undecided, with a note) in
    between (``_certified``).
    """
    if (
        not detail
        and ar.mode == "float64"
        and type(residuals) is np.ndarray
        and residuals.dtype == np.float64
    ):
        # float64 without detail: the largest alone, by one compiled pass, when it is finite
        worst = largest_magnitude(residuals) if len(residuals) else math.nan
        if math.isfinite(worst):
            return Check(
                statement.id,
                statement.reference,
                statement.claim,
                worst,
                tolerance,
                worst <= tolerance,
                None,
                erratum,
                note,
            )
    elif isinstance(residuals, Largest):
        if residuals.count and math.isfinite(residuals.value) and not detail:
            return Check(
                id=statement.id,
                reference=statement.reference,
                claim=statement.claim,
                residual=residuals.value,
                tolerance=tolerance,
                holds=residuals.value <= tolerance,
                erratum=erratum,
                note=note,
            )
        residuals = residuals.residuals()
    if len(residuals) == 0:
        return not_applicable(
            statement, tolerance, note or "not enough vertices in the range to evaluate it"
        )
    if ar.mode == "mp" and not ar.certified and ar.digits > MPMATH_FLOAT_DIGITS:
        # mpmath's residuals are reported as floats: 10^-digits is 0 there, and a residual
        # of 0 <= a tolerance of 0 would be a verdict without content
        beyond = (
            f"undecided: computed with mpmath, whose residuals and tolerance are floats; beyond "
            f"{MPMATH_FLOAT_DIGITS} digits they leave the float range (use at most "
            f"{MPMATH_FLOAT_DIGITS} digits here; the discretizations are certified at any digits)"
        )
        return not_applicable(statement, float(tolerance), f"{note}; {beyond}" if note else beyond)
    if ar.certified and not detail and residuals.dtype == object:
        # balls: the largest upper bound alone (floats of every residual are for per_index)
        upper = ar.largest_upper(residuals)  # type: ignore[attr-defined]
        if upper.is_finite():
            return _certified(
                statement, ar, indices, residuals, upper, None, tolerance, erratum, note
            )
    floats = ar.to_floats(residuals)
    holds: bool | None
    worst = largest_magnitude(floats)
    residual: float | Decimal | None = worst
    values = np.abs(floats) if detail else floats  # |values| only where they are shown
    if math.isfinite(worst) and ar.certified:
        upper = ar.largest_upper(residuals)  # type: ignore[attr-defined]
        shown = decimal_uppers(residuals) if detail else None
        return _certified(statement, ar, indices, residuals, upper, shown, tolerance, erratum, note)
    if math.isfinite(worst):  # the largest is finite only when every value is
        holds = worst <= tolerance
    else:
        values = np.abs(floats)
        finite = np.isfinite(values)
        # A residual that cannot be computed (an overflow, 0/0) tests nothing: the check fails
        # if a computed residual already exceeds the tolerance, and is otherwise not applicable
        # (never passed). NaN/Infinity stay out of the response.
        computed = values[finite]
        worst = float(np.max(computed)) if len(computed) else np.finfo(np.float64).max
        holds = False if worst > tolerance else None
        residual = worst if holds is not None else None
        if ar.certified:
            tolerance = decimal_tolerance(tolerance)
            residual = None if residual is None else decimal_bound(residual, upward=True)
        missing = f"{int(np.count_nonzero(~finite))} of {len(values)} residuals could not be "
        missing += "computed (not finite)"
        note = f"{note}; {missing}" if note else missing
        values = np.where(finite, values, np.finfo(np.float64).max)
        if ar.certified and detail:
            # on balls per index the decimal upper bound of each finite residual, None for the
            # others (float64 shows the largest float there)
            values = decimal_uppers(residuals, finite)
    return Check(
        id=statement.id,
        reference=statement.reference,
        claim=statement.claim,
        residual=residual,
        tolerance=tolerance,
        holds=holds,
        per_index=PerIndex(np.asarray(indices, dtype=np.int64), values) if detail else None,
        erratum=erratum,
        note=note,
    )


#: Decimals of ``BOUND_DIGITS`` significant digits, rounded up (per-index bounds on balls).
_UPWARD = Context(prec=BOUND_DIGITS, rounding=ROUND_CEILING, Emin=-(10**9), Emax=10**9)


def decimal_uppers(
    residuals: Array, finite: np.ndarray[Any, np.dtype[np.bool_]] | None = None
) -> list[Decimal | None]:
    """Per entry the smallest decimal of ``BOUND_DIGITS`` significant digits >= every |v| in
    the ball (an exact dyadic upper bound m·2^e turned into m·5^−e·10^e and rounded up once:
    about 5 µs an entry, a third of ``decimal_bound``'s search, and never above it, so no
    per-index bound exceeds the check's ``residual``); ``None`` where ``finite`` is false or a
    ball is unbounded. Float entries (bounds converted already) are read exactly."""
    out: list[Decimal | None] = []
    flat = residuals.reshape(-1)
    for k, value in enumerate(flat):
        if (finite is not None and not finite[k]) or not _is_finite(value):
            out.append(None)
            continue
        if not isinstance(value, flint.arb):
            out.append(_UPWARD.create_decimal(abs(float(value))))
            continue
        mantissa, exponent = value.abs_upper().man_exp()
        m, e = int(mantissa), int(exponent)
        if e >= 0:
            out.append(_UPWARD.create_decimal(m << e))
        else:
            out.append(_UPWARD.create_decimal(m * 5**-e).scaleb(e, _UPWARD))
    return out


def _is_finite(value: Any) -> bool:
    if isinstance(value, flint.arb):
        return bool(value.is_finite())
    return math.isfinite(float(value))


def _certified(
    statement: Statement,
    ar: Arithmetic,
    indices: Indices,
    residuals: Array,
    upper: Any,
    values: list[Decimal | None] | None,
    tolerance: Any,
    erratum: Erratum | None,
    note: str | None,
) -> Check:
    """``check_residuals`` on balls: the verdict from the decimals shown, exactly.

    The residual is a decimal >= the exact upper bound of the largest residual, the tolerance
    the decimal nearest to it (``decimal_bound``, ``decimal_tolerance``: decimal strings in the
    response, since both leave the float range from 324 digits on); ``holds`` is true when
    the one is <= the other, false when a rigorous lower bound of the largest residual
    exceeds the tolerance, and ``None`` (undecided, with a note) in between: more digits
    narrow the bounds, and ``balls.serve`` computes such a curve again with every digit.
    """
    shown_tolerance = decimal_tolerance(tolerance)
    residual = decimal_bound(upper, upward=True)
    holds: bool | None = residual <= shown_tolerance
    lower = None if holds else ar.largest_lower(residuals)  # type: ignore[attr-defined]
    if not holds and not lower > decimal_ball(shown_tolerance):
        holds = None
        ar.undecided += 1
        undecided = (
            "undecided: the residual's rigorous bounds enclose the tolerance "
            "(more digits narrow them)"
        )
        note = f"{note}; {undecided}" if note else undecided
    return Check(
        id=statement.id,
        reference=statement.reference,
        claim=statement.claim,
        residual=residual,
        tolerance=shown_tolerance,
        holds=holds,
        per_index=None if values is None else PerIndex(np.asarray(indices, dtype=np.int64), values),
        erratum=erratum,
        note=note,
    )


def not_applicable(statement: Statement, tolerance: Any, note: str) -> Check:
    """A check that could not be evaluated, with the reason (on balls the tolerance is shown as
    a decimal, as ``check_residuals`` shows it)."""
    if not isinstance(tolerance, float | int):
        tolerance = decimal_tolerance(tolerance)
    return Check(
        id=statement.id,
        reference=statement.reference,
        claim=statement.claim,
        residual=None,
        tolerance=tolerance,
        holds=None,
        note=note,
    )


def relative_to(ar: Arithmetic, difference: Array, scale: Array) -> Array:
    """|difference| / scale entry by entry, the scale floored at the smallest normal float.

    Scales are data magnitudes; they vanish only for degenerate data (all zeros), where the
    floor keeps 0/0 from becoming NaN (float64) or an exception (mp).
    """
    tiny = ar.scalar(np.finfo(np.float64).tiny)
    return abs(difference) / np.where(scale > tiny, scale, tiny)


def relative_difference(ar: Arithmetic, computed: Array, expected: Array) -> Array:
    """``|computed - expected| / max(|expected|, tiny)`` entry by entry."""
    scale = np.abs(expected)
    tiny = ar.scalar(np.finfo(np.float64).tiny)
    scale = np.where(scale > tiny, scale, tiny)
    return np.abs(computed - expected) / scale


def point_distance(ar: Arithmetic, a: Array, b: Array) -> Array:
    """``|a_i - b_i|`` for two ``(n, 2)`` point arrays."""
    return ar.hypot(a[:, 0] - b[:, 0], a[:, 1] - b[:, 1])


def relative_point_difference(ar: Arithmetic, computed: Array, expected: Array) -> Array:
    """``|computed_i - expected_i| / max(|expected_i|, tiny)`` for ``(n, 2)`` point arrays.

    The differences at the working precision; on balls the lengths and the quotient, which
    only round a result reported as a float, at ``Arithmetic.residual_precision`` (in one
    compiled pass, ``arb_loops.relative_point_difference``: the same balls).
    """
    if _compiled_balls(ar, computed, expected):  # one pass
        low = min(flint.ctx.prec, RESIDUAL_BITS)
        with ar.residual_precision():  # the floor's ball as below
            tiny = ar.scalar(np.finfo(np.float64).tiny)
        return arb_loops.relative_point_difference(computed, expected, tiny, low)
    dx, dy = computed[:, 0] - expected[:, 0], computed[:, 1] - expected[:, 1]
    with ar.residual_precision():
        scale = ar.hypot(expected[:, 0], expected[:, 1])
        tiny = ar.scalar(np.finfo(np.float64).tiny)
        scale = np.where(scale > tiny, scale, tiny)
        return ar.hypot(dx, dy) / scale


def _compiled_balls(ar: Arithmetic, computed: Array, expected: Array) -> bool:
    """Whether two ``(n, 2)`` arrays are balls for ``arb_loops``' compiled pass."""
    return (
        ar.certified
        and arb_loops.AVAILABLE
        and len(computed) == len(expected) > 0
        and all_balls(computed)
        and all_balls(expected)
    )


def printed_residual(ar: Arithmetic, residuals: Array) -> float | Decimal | None:
    """The largest printed-formula residual as a float (``None`` if it is not a number); on
    balls (``ar.certified``) a rigorous lower bound of it, a decimal rounded down (``None`` if
    a ball is unbounded)."""
    if len(residuals) == 0:
        return None
    # on balls, a rigorous lower bound: positive certifies that the printed formula is false
    if ar.certified:
        if not ar.largest_upper(residuals).is_finite():  # type: ignore[attr-defined]
            return None
        return decimal_bound(ar.largest_lower(residuals), upward=False)  # type: ignore[attr-defined]
    else:
        worst = largest_magnitude(ar.to_floats(residuals))
    return worst if math.isfinite(worst) else None


def largest_magnitude(values: np.ndarray[Any, np.dtype[np.float64]]) -> float:
    """max |v| of a non-empty float64 array, as ``np.abs(values).max()`` (NaN if one is NaN)
    but without the array of absolute values: one compiled pass over a float64 vector
    (``compiled.largest_of_magnitudes``), else the larger of max v and −min v."""
    if values.ndim == 1 and values.dtype == np.float64 and len(values):
        return float(largest_of_magnitudes(values))
    return abs(max(float(values.max()), -float(values.min())))
