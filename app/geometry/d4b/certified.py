"""(D4b) on rigorous balls: the prototype of issue 15's certified verdicts for precision=mp.

The construction of Section 3 (``construction.construct``) and the closed forms (14), (16) of
Theorems 5 and 6 run unchanged on python-flint ``arb`` balls (``precision.Ball``); every value
is a midpoint and a radius that contains the exact value for the exact inputs (``h``, ``d``,
``beta0`` as the decimals written). From them:

- coordinates: decimal midpoints with ``digits`` significant digits, plus the largest radius;
- the residual of a statement (theorem-4-hypothesis, theorem-4-rotation-angle, recursion-13
  and its two-step form, theorem-5, theorem-6, darboux-d4b, darboux-d4b-distance,
  nikolaides-d4b; measured as in the float checks, docs/checks.md): a rigorous upper bound of
  the largest residual, so
  ``holds`` (bound <= tolerance) is a proof that the computed polygon satisfies the statement to
  that tolerance;
- the residual of a printed formula (erratum E3, the two-step formula of the proof of Theorem 4):
  a rigorous lower bound, so a positive bound *certifies* that the printed formula is false on
  this polygon.

The recursion carries the ball's dependency problem: the radius of sin β_i grows about like
e^{2|i|L}·ulp while sin β_i decays like e^{−|i|L} (L = ln((h+d)/(h−d))), a pessimism of the
balls, not an error of the construction. Precision is raised in advance by that many digits
and, if the radii still exceed 10^−digits of the values, doubled until they do not: never a
guess. mpmath is not used here; its only remaining uses are the float-to-decimal reading of
``MultiPrecision`` and the printing of mp numbers there.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from typing import Any

import flint
import numpy as np

from app.geometry import darboux, nikolaides
from app.geometry.d4b import closed_forms
from app.geometry.d4b.construction import construct, validate
from app.geometry.errors import NotRepresentableError
from app.geometry.precision import Array, Ball

#: Local statements allow this many units of 10^−digits (as ``Arithmetic.tolerance``).
LOCAL_STEPS = 16

#: Give up raising the precision past this many extra digits (the request is then refused).
MAX_EXTRA_DIGITS = 20_000


@dataclass(frozen=True)
class Verdict:
    """One certified statement: a rigorous bound and what it proves."""

    id: str
    residual: float
    """Upper bound (statements) or lower bound (printed formulas) of the largest residual."""
    tolerance: float
    holds: bool | None
    """Statements: bound <= tolerance. Printed formulas: False when certified false, else None
    (undecided: the ball still contains 0)."""
    certified_false: bool = False


@dataclass(frozen=True)
class CertifiedD4b:
    """A (D4b) polygon on balls with its certified verdicts."""

    indices: np.ndarray[Any, np.dtype[np.int64]]
    p: Array
    tractrix: Array
    digits: int
    extra_digits: int
    """Digits carried beyond ``digits`` (plus guard digits) to keep the radii small enough."""
    radius: float
    """Largest radius of a coordinate of p and the tractrix (rounded up)."""
    verdicts: tuple[Verdict, ...]

    def coordinates(self, points: Array) -> list[list[str]]:
        """Decimal midpoints with ``digits`` significant digits."""
        digits = self.digits
        return [[v.mid().str(digits, radius=False) for v in row] for row in points]


def extra_digits_needed(h: float, d: float, i_min: int, i_max: int) -> int:
    """The digits the balls lose over the recursion: about 2·max|i|·L/ln 10 (see above)."""
    L = math.log1p(2 * d / (h - d))
    return math.ceil(2 * max(abs(i_min - 1), abs(i_max + 2), 1) * L / math.log(10)) + 5


def _resolved(points: Array, digits: int) -> bool:
    """Whether every radius is below 10^−(digits+1) of its point's largest coordinate."""
    limit = flint.arb(10) ** (-digits - 1)
    for x, y in points:
        size = abs(x).lower().max(abs(y).lower())
        if not (size > 0 and x.rad().max(y.rad()) < limit * size):
            return False
    return True


def certify(
    digits: int, h: float, d: float, beta0: float | None, i_min: int, i_max: int
) -> CertifiedD4b:
    """(D4b) on i_min .. i_max at ``digits`` digits on balls, with certified verdicts."""
    validate(h, d, beta0)
    extra = extra_digits_needed(h, d, i_min, i_max)
    while True:
        ar = Ball(digits, extra)
        lo, hi = min(0, i_min - 1), max(0, i_max + 2)
        built = construct(ar, h, d, beta0, lo, hi)
        window = slice(i_min - 1 - lo, i_max + 3 - lo)  # i_min − 1 .. i_max + 2
        p, tractrix, axis = (
            built.centres[window],
            built.tractrix[window],
            built.axis_points[window],
        )
        if _resolved(np.concatenate([p, tractrix]), digits):
            break
        extra *= 2
        if extra > MAX_EXTRA_DIGITS:
            raise NotRepresentableError(
                "i_max",
                "a range the balls resolve",
                i_max,
                "the radii of the certified construction stay too large",
            )
    hh, dd = ar.scalar(h), ar.scalar(d)
    shift = closed_forms.tilt_shift(ar, hh, dd, beta0)
    i = ar.indices(i_min - 1, i_max + 2)
    closed_p = closed_forms.hyperbolic_cosine(ar, hh, dd, i, shift)
    closed_d = closed_forms.tractrix(ar, hh, dd, i, shift)
    local = LOCAL_STEPS * flint.arb(10) ** (-digits)
    shown = slice(1, -2)  # i_min .. i_max
    y = p[:, 1]
    verdicts = (
        _statement("theorem-5", _relative_distance(p[shown], closed_p[shown]), local),
        _statement(
            "theorem-6",
            _distance(tractrix[shown], closed_d[shown]) / (abs(axis[shown, 0]) + hh),
            local,
        ),
        _statement(
            "recursion-13",
            abs(y[2:] - closed_forms.recursion_13(dd, y[:-2], y[1:-1])) / abs(y[2:]),
            local,
        ),
        _statement(
            "recursion-13-two-step",
            abs(y[3:] - closed_forms.two_step(dd, y[:-3], y[1:-2])) / abs(y[3:]),
            3 * local,
        ),
        _statement(
            "theorem-4-hypothesis",
            np.frompyfunc(lambda v: v.nonnegative_part(), 1, 1)(dd * dd - y[:-1] * y[1:])
            / (dd * dd),
            local,
        ),
        _statement(
            "theorem-4-rotation-angle",
            abs(
                _angle(axis[:-1] - p[1:], axis[1:] - p[1:])
                - 2 * ar.atan2(np.full(len(y) - 1, dd, dtype=object), y[1:])
            ),
            local,
        ),
        _statement(
            "darboux-d4b-distance",
            darboux.distance_residuals(ar, axis[shown], 2 * tractrix[shown] - axis[shown], 2 * hh),
            local,
        ),
        _statement(
            "darboux-d4b",
            darboux.edge_length_residuals(ar, axis[1:-1], 2 * tractrix[1:-1] - axis[1:-1]),
            local,
        ),
        _statement(
            "nikolaides-d4b",
            np.concatenate(
                [
                    nikolaides.right_angle_residuals(tractrix[1:-1], axis[1:-1], p[1:-1]),
                    nikolaides.right_angle_residuals(tractrix[1:-1], axis[1:-1], p[2:]),
                ]
            ),
            local,
        ),
        _printed(
            "E3",
            abs(y[3:] - closed_forms.two_step_printed(dd, y[:-3], y[1:-2])) / abs(y[3:]),
            3 * local,
        ),
    )
    return CertifiedD4b(
        indices=np.arange(i_min, i_max + 1, dtype=np.int64),
        p=p[shown],
        tractrix=tractrix[shown],
        digits=digits,
        extra_digits=extra,
        radius=ar.largest_radius(np.concatenate([p[shown], tractrix[shown]])),
        verdicts=verdicts,
    )


def _angle(a: Array, b: Array) -> Array:
    """The angle turning vector a_k into b_k (atan2 of cross and dot products)."""
    cross = a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]
    dot = a[:, 0] * b[:, 0] + a[:, 1] * b[:, 1]
    return np.frompyfunc(flint.arb.atan2, 2, 1)(cross, dot)


def _distance(a: Array, b: Array) -> Array:
    dx, dy = a[:, 0] - b[:, 0], a[:, 1] - b[:, 1]
    # a ball around 0 squared reaches below 0 (sqrt: NaN): keep its part >= 0, which holds the
    # exact square
    return np.frompyfunc(lambda u, v: (u * u + v * v).nonnegative_part().sqrt(), 2, 1)(dx, dy)


def _relative_distance(a: Array, b: Array) -> Array:
    zero = np.full_like(b, flint.arb(0))
    return _distance(a, b) / _distance(b, zero)


def _statement(identifier: str, residuals: Array, tolerance: Any) -> Verdict:
    """Holds when the upper bound of every residual is <= the tolerance (compared as balls,
    so that bounds below the float range still decide)."""
    worst = _largest(abs(v).upper() for v in residuals)
    return Verdict(identifier, _up(worst), _up(tolerance), bool(worst <= tolerance))


def _printed(identifier: str, residuals: Array, tolerance: Any) -> Verdict:
    """Certified false when a residual's ball excludes 0 (its lower bound is > 0)."""
    worst = _largest(abs(v).lower() for v in residuals)
    certain = bool(worst > 0)
    return Verdict(identifier, _down(worst), _up(tolerance), False if certain else None, certain)


def _largest(bounds: Any) -> Any:
    """The largest of exact (radius-0) arb bounds, 0 for none."""
    return functools.reduce(lambda a, b: a.max(b), bounds, flint.arb(0))


def _up(value: Any) -> float:
    """A float >= the exact arb ``value`` (NaN: +inf, nothing is bounded)."""
    nearest = float(value.mid())
    if math.isnan(nearest):
        return math.inf
    if nearest == 0.0 and value.is_zero():
        return 0.0
    return math.nextafter(nearest, math.inf) if math.isfinite(nearest) else nearest


def _down(value: Any) -> float:
    """A float <= the exact arb ``value``, >= 0."""
    nearest = float(value.mid())
    return max(0.0, math.nextafter(nearest, -math.inf)) if math.isfinite(nearest) else 0.0
