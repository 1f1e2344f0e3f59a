"""Rigorous ball arithmetic behind the ``Arithmetic`` interface (python-flint's ``arb``).

``Ball`` runs the same geometry code as ``Float64`` and ``MultiPrecision``
(``app.geometry.precision``) on object arrays of ``arb`` balls; ``app.geometry.balls`` serves
precision=mp with it (working precision, raising the digits until every radius is small).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Iterator
from contextlib import contextmanager
from decimal import Context, Decimal
from typing import Any

import flint
import numpy as np
from mpmath.libmp import from_man_exp, to_str
from mpmath.libmp.libmpf import blog2_10

from app.geometry import arb_loops, arb_program
from app.geometry.errors import DomainError
from app.geometry.exact import ExactReal
from app.geometry.precision import (
    GUARD_DIGITS,
    TOLERANCE_SAFETY,
    UNARY_FUNCTIONS,
    Arithmetic,
    Array,
    PrecisionMode,
    Scalar,
    UndecidedError,
)

#: Bits of one decimal digit, for the ball arithmetic's working precision.
BITS_PER_DIGIT = math.log2(10)

#: Significant digits of a residual, tolerance or printed residual reported on balls (decimal
#: strings: from 324 digits on their sizes leave the float range).
BOUND_DIGITS = 10

#: Decimal arithmetic for those bounds: exponents far beyond any working precision.
_BOUNDS = Context(prec=BOUND_DIGITS, Emin=-(10**9), Emax=10**9)

#: Bits of a residual's last operations (``Ball.residual_precision``): more than a float's 53,
#: so that the float it is reported as is the bound, not the rounding.
RESIDUAL_BITS = 64


def _ball_function(name: str, clock: Callable[[], None] | None = None) -> Callable[..., Any]:
    """An arb method (``cos``, ``log1p``, …) on a ball or, entry by entry, on an object array."""

    method = getattr(flint.arb, name)

    def scalar(x: Any) -> Any:
        return method(x if type(x) is flint.arb else flint.arb(x))

    ufunc = np.frompyfunc(method, 1, 1)  # object arrays of Ball hold arb numbers only

    def apply(x: Any) -> Any:
        if isinstance(x, np.ndarray):
            if clock is not None:
                clock()
            return ufunc(x)
        return scalar(x)

    return apply


class Ball(Arithmetic):
    """Rigorous ball arithmetic (python-flint's ``arb``): every number is a midpoint and a radius
    that contains the exact value of the formula on the exact inputs.

    precision=mp of the discretizations served on balls (``app.geometry.balls``): the same
    geometry code runs on object arrays of balls; ``to_floats`` of a residual is a rigorous upper
    bound of its absolute value and ``lower_floats`` a rigorous lower bound (``checks``). flint's
    working precision is process-wide (``flint.ctx.prec``) and this class sets it only inside
    ``recursion``: compute inside ``balls.working_precision(ar.bits)``, which serializes
    computations.

    ``extra_digits`` are for radii that grow along a sequential construction. With
    ``recursions_only``, only the code inside ``recursion()`` (the construction) carries them;
    everything else (closed forms, Gauss images, checks: formulas on a few neighbouring
    vertices, whose radii do not grow along the range) runs at ``digits`` + guard digits, which
    is rigorous all the same (a lower precision only widens the balls) and about 1.5–3× cheaper
    per transcendental function at 50 digits over 1000 vertices (docs/performance.md).
    """

    mode: PrecisionMode = "mp"
    may_overflow = False

    def __init__(self, digits: int, extra_digits: int = 0, recursions_only: bool = False) -> None:
        if digits < 1:
            raise DomainError("digits", "digits >= 1", digits)
        self.digits = digits
        self.eps = 10.0 ** (-digits)
        # the refusals that read it (a step below the resolution) mean the requested digits
        self.working_eps = 10.0 ** (-digits - GUARD_DIGITS)
        self.extra_digits = extra_digits
        """Digits carried beyond ``digits`` and the guard digits, for radii that grow."""
        self.recursion_bits = math.ceil((digits + GUARD_DIGITS + extra_digits) * BITS_PER_DIGIT)
        """Bits of a sequential construction (inside ``recursion()``): with the extra digits."""
        self.recursions_only = recursions_only
        self.bits = (
            math.ceil((digits + GUARD_DIGITS) * BITS_PER_DIGIT)
            if recursions_only
            else self.recursion_bits
        )
        """Bits of everything else (``balls.working_precision(ar.bits)``)."""
        self.undecided = 0
        """Checks left undecided so far (``checks.check_residuals`` counts them)."""
        self.certificate: Any = None
        """What the served curve's balls guarantee (``balls.Certificate``), set by
        ``balls.serve``."""
        for name in UNARY_FUNCTIONS:
            setattr(self, name, _ball_function(name, self.check_time))
        atan2 = np.frompyfunc(flint.arb.atan2, 2, 1)
        self.atan2 = lambda y, x: atan2(y, x)
        # a ball around 0 squared reaches below 0: keep the part >= 0 (it holds the exact value)
        nonnegative = np.frompyfunc(flint.arb.nonnegative_part, 1, 1)
        sqrt = np.frompyfunc(flint.arb.sqrt, 1, 1)

        def hypot(x: Any, y: Any) -> Any:
            if isinstance(x, np.ndarray) or isinstance(y, np.ndarray):
                if _compiled_pair(x, y):
                    return arb_loops.hypot(x, y)  # one pass, the same balls
                return sqrt(nonnegative(x * x + y * y))
            return _ball_hypot(self.scalar(x), self.scalar(y))

        self.hypot = hypot

    @contextmanager
    def recursion(self) -> Iterator[None]:
        """Compute a sequential construction with the extra digits (``recursion_bits``), whose
        balls' radii grow along it; the precision before is restored afterwards."""
        saved = flint.ctx.prec
        flint.ctx.prec = self.recursion_bits
        try:
            yield
        finally:
            flint.ctx.prec = saved

    @contextmanager
    def residual_precision(self) -> Iterator[None]:
        """``RESIDUAL_BITS`` inside (if below the precision before, which is restored): for the
        operations after a residual's differences, whose result is reported as a float."""
        saved = flint.ctx.prec
        flint.ctx.prec = min(saved, RESIDUAL_BITS)
        try:
            yield
        finally:
            flint.ctx.prec = saved

    def tolerance(self, steps: int = 1) -> Any:
        """``Arithmetic.tolerance`` as a ball: 10^−digits leaves the float range from 324 digits
        on (a float tolerance was 0 there, and every check with a nonzero bound undecided).
        Factors multiply it as they multiply a float; ``checks`` compares it through
        ``decimal_bound``."""
        return TOLERANCE_SAFETY * max(1, steps) * flint.arb(10) ** (-self.digits)

    def scalar(self, value: Any) -> Any:
        kind = type(value)
        if kind is flint.arb:
            return value
        if kind is int:
            return flint.arb(value)
        if isinstance(value, np.integer):
            return flint.arb(int(value))
        if isinstance(value, ExactReal):
            return flint.arb(value.text)  # the ball of the decimal written
        if isinstance(value, float):
            return flint.arb(repr(float(value)))  # numpy floats print their type in repr
        return flint.arb(value)

    def array(self, values: Iterable[Any]) -> Array:
        ball = flint.arb
        items = [v if type(v) is ball else self.scalar(v) for v in values]
        out = np.empty(len(items), dtype=object)
        out[:] = items
        return out

    def indices(self, i_min: int, i_max: int) -> Array:
        out = np.empty(i_max - i_min + 1, dtype=object)
        out[:] = [flint.arb(i) for i in range(i_min, i_max + 1)]
        return out

    def zeros(self, n: int) -> Array:
        out = np.empty(n, dtype=object)
        out[:] = [flint.arb(0)] * n  # arb numbers are immutable
        return out

    def empty(self, n: int) -> Array:
        return np.empty(n, dtype=object)

    @property
    def pi(self) -> Any:
        return flint.arb.pi()

    certified = True

    def to_float(self, value: Any) -> float:
        """The float farthest from 0 in the ball, rounded outward: for a residual (>= 0), a
        rigorous upper bound; for anything else the midpoint to within the radius."""
        if type(value) is not flint.arb:
            return float(value)
        return float(self.to_floats(np.array([value], dtype=object))[0])

    def to_floats(self, values: Array) -> np.ndarray[Any, np.dtype[np.float64]]:
        """Entry by entry ``to_float``: ``|result| >= |v|`` for every v in each ball, with the
        sign of the midpoint, so residuals converted here are upper bounds (float arrays, e.g.
        residuals converted already, pass through)."""
        if values.dtype != object:
            return np.asarray(values, dtype=np.float64)
        n = values.size
        flat = values.reshape(-1)
        mids = np.fromiter((float(v) for v in flat), dtype=np.float64, count=n)
        # exact bounds, each converted to its nearest float (numpy's loop: a third faster)
        uppers = _ABS_UPPER(flat).astype(np.float64) if n else np.zeros(0)
        with np.errstate(invalid="ignore"):
            bounds = np.nextafter(uppers, np.inf)  # float() rounds to nearest
        for k in np.flatnonzero(uppers == 0):  # exact zeros stay 0
            if flat[k].is_zero():
                bounds[k] = 0.0
        with np.errstate(invalid="ignore"):
            uppers = bounds
            return np.where(mids < 0, -uppers, uppers)

    def lower_floats(self, values: Array) -> np.ndarray[Any, np.dtype[np.float64]]:
        """Rigorous lower bounds of ``|v|`` (0 where a ball holds 0, or for float entries)."""
        if values.dtype != object:
            return np.zeros(len(values), dtype=np.float64)
        lowers = _ABS_LOWER(values).astype(np.float64) if len(values) else np.zeros(0)
        with np.errstate(invalid="ignore"):
            return np.maximum(np.nextafter(lowers, -np.inf), 0.0)

    def maximum(self, a: Any, b: Any) -> Any:
        """A ball holding max(a, b) entry by entry (numpy's maximum picks one of two overlapping
        balls, which may not contain the maximum)."""
        return _ball_maximum(a, b)

    def exceeds(self, a: Scalar, b: Scalar, parameter: str, what: str) -> bool:
        if a > b:
            return True
        if a <= b:
            return False
        raise UndecidedError(parameter, what)

    def at_least_or(self, x: Scalar, y: Scalar, a: Scalar, b: Scalar) -> Scalar:
        if x >= y:
            return a
        if x < y:
            return b
        return a.union(b)  # the exact choice is one of the two: a ball holding both

    def nonnegative(self, x: Scalar) -> Scalar:
        return x.nonnegative_part()

    def truncate(self, x: Scalar) -> int:
        """The midpoint truncated (a guess only: the search that uses it decides exactly)."""
        mid = x.mid()  # exact, so its floor and ceiling are exact integers
        return int((mid.floor() if mid > 0 else mid.ceil()).unique_fmpz())

    def all_finite(self, values: Array) -> bool:
        return all(v.is_finite() for v in values.reshape(-1))

    def to_strings(self, values: Array) -> list[str]:
        """The midpoints as decimals with ``digits`` significant digits, printed as mpmath
        prints them (``nstr``): the exact binary midpoint, correctly rounded."""
        digits = self.digits
        return [_decimal(v, digits) for v in values]

    def largest_radius(self, values: Array) -> float:
        """The largest radius of the balls, rounded up to a float."""
        radii = [v.rad() for v in values.reshape(-1)]
        return upper_float(max(radii, default=flint.arb(0)))

    def largest_upper(self, values: Array) -> Any:
        """An exact number (radius 0) >= |v| for every v in every ball: a rigorous upper bound of
        the largest |value| (a float array, of bounds converted already: its largest |value|)."""
        if values.dtype != object:
            return flint.arb(float(np.max(np.abs(values))) if len(values) else 0.0)
        found = _largest_abs(values, True)
        if found is not None:
            return found
        return max(_ABS_UPPER(values.reshape(-1)), default=flint.arb(0))

    def largest_lower(self, values: Array) -> Any:
        """An exact number <= the largest |value| (0 for a float array: no lower bounds)."""
        if values.dtype != object:
            return flint.arb(0)
        found = _largest_abs(values, False)
        if found is not None:
            return found
        return max(_ABS_LOWER(values.reshape(-1)), default=flint.arb(0))

    def upper(self, values: Array) -> float:
        """A float >= every number in every ball of ``|values|`` (a rigorous residual bound)."""
        bounds = [abs(v).upper() for v in values.reshape(-1)]
        return upper_float(max(bounds, default=flint.arb(0)))

    def lower(self, values: Array) -> float:
        """A float <= every number in every ball of ``|values|``'s largest entry: a rigorous
        lower bound of the largest |value| (positive: the values certainly are not all 0)."""
        bounds = [abs(v).lower() for v in values.reshape(-1)]
        return lower_float(max(bounds, default=flint.arb(0)))


def decimal_bound(value: Any, upward: bool) -> Decimal:
    """A decimal of ``BOUND_DIGITS`` significant digits >= every number of the ball ``value``
    (``upward``) or <= every one (a float, an int or a Decimal is one exact number).

    Residuals are reported rounded up, printed residuals rounded down; holding is decided on
    the decimals shown (``checks.check_residuals``, with ``decimal_tolerance``), so what is
    shown is what was compared. Exact: each candidate is compared with the bound as a ball.
    """
    if isinstance(value, Decimal):
        value = flint.arb(str(value))
    elif not isinstance(value, flint.arb):
        value = flint.arb(value)  # floats and ints convert exactly
    if not value.is_finite():
        raise ValueError("an unbounded ball has no decimal bound")
    end = value.upper() if upward else value.lower()
    if end.is_zero():
        return Decimal(0)
    candidate = _BOUNDS.create_decimal(end.str(BOUND_DIGITS + 2, radius=False))
    step = _BOUNDS.next_plus if upward else _BOUNDS.next_minus
    while not (flint.arb(str(candidate)) >= end if upward else flint.arb(str(candidate)) <= end):
        candidate = step(candidate)
    return candidate


def decimal_tolerance(value: Any) -> Decimal:
    """A tolerance as checks on balls use and show it: the decimal of ``BOUND_DIGITS``
    significant digits nearest to its midpoint (a tolerance is a chosen threshold, not a
    bound: its ball only carries the rounding of 10^−digits, so 1.024e-27 is shown as such)."""
    if isinstance(value, Decimal):
        return _BOUNDS.plus(value)
    if isinstance(value, float | int):
        return _BOUNDS.create_decimal(repr(value))
    return _BOUNDS.create_decimal(value.mid().str(BOUND_DIGITS + 5, radius=False))


def decimal_ball(value: Decimal) -> Any:
    """The ball of a decimal (exact where it is dyadic), at the working precision."""
    return flint.arb(str(value))


def decimal_text(value: Decimal) -> str:
    """A bound as the response shows it (``6.4e-499``, ``0.5``)."""
    return format(_BOUNDS.normalize(value), "g")


def _decimal(value: Any, digits: int) -> str:
    """A ball's midpoint (exact in binary) with ``digits`` significant digits, as mpmath's
    ``nstr`` prints it (``_nstr``; mpmath's ``to_str`` itself where that does not apply)."""
    if not value.is_finite():
        return "nan"  # refused before encoding (``all_finite``)
    mantissa, exponent = value.mid().man_exp()
    text = _nstr(mantissa, int(exponent), digits)
    if text is not None:
        return text
    return to_str(from_man_exp(int(mantissa), int(exponent)), digits)


#: mpmath's log2(10) for its digit counts (``to_digits_exp``)
_LOG2_10: float = blog2_10


def _nstr(mantissa: Any, exponent: int, dps: int) -> str | None:
    """mantissa·2^exponent (``fmpz`` mantissa) as mpmath's ``to_str(x, dps)`` prints it, the same
    steps on flint integers without its generality (base 10, nearest, default fixed-point
    range): ``to_digits_exp``'s dps + 10 digits rounded toward zero, ``round_digits``'
    rounding to nearest (a 5 followed by zeros goes to the even digit), then the fixed-point or
    exponent layout with trailing zeros stripped. None for what it leaves to mpmath (no digits
    asked, a decimal exponent beyond ±1050, too few digits). About 30 % less time (≈ 3 µs);
    tests/geometry/test_arb_program.py compares it with mpmath's on many kinds of values."""
    if dps < 1:
        return None
    if mantissa == 0:
        return "0.0"
    sign = ""
    if mantissa < 0:
        sign, mantissa = "-", -mantissa
    bits = int(mantissa.bit_length())
    if abs(exponent + bits) > 3500:
        return None
    bitprec = int((dps + 10) * _LOG2_10) + 10
    fixprec = max(bitprec - exponent - bits, 0)
    fixdps = int(fixprec / _LOG2_10 + 0.5)
    offset = exponent + fixprec
    fixed = mantissa << offset if offset >= 0 else mantissa >> -offset
    digits = str((fixed * _power_of_ten(fixdps)) >> fixprec)
    if len(digits) <= dps:
        return None
    point = len(digits) - fixdps - 1
    after = digits[dps]
    if after < "5" or (
        after == "5" and digits[dps - 1] in "02468" and not digits[dps + 1 :].strip("0")
    ):
        digits = digits[:dps]  # down, ties to the even digit
    else:
        kept = digits[:dps].rstrip("9")  # up: ...d99 -> ...(d+1)00
        if kept:
            digits = kept[:-1] + chr(ord(kept[-1]) + 1) + "0" * (dps - len(kept))
        else:
            digits, point = "1" + "0" * (dps - 1), point + 1
    if min(-(dps // 3), -5) < point < dps:
        if point < 0:
            digits, split = "0" * -point + digits, 1
        else:
            split = point + 1
        point = 0
    else:
        split = 1
    digits = (digits[:split] + "." + digits[split:]).rstrip("0")
    if digits[-1] == ".":
        digits += "0"
    return sign + digits if point == 0 else f"{sign}{digits}e{point:+}"


_POWERS_OF_TEN: dict[int, Any] = {}


def _power_of_ten(k: int) -> Any:
    """10^k as a flint integer (kept: a response needs a few k many times)."""
    power = _POWERS_OF_TEN.get(k)
    if power is None:
        if len(_POWERS_OF_TEN) > 4096:
            _POWERS_OF_TEN.clear()
        power = _POWERS_OF_TEN[k] = flint.fmpz(10) ** k
    return power


def _ball_hypot(x: Any, y: Any) -> Any:
    """sqrt(x² + y²) on balls; the sum's part >= 0 (a ball around 0 squared reaches below 0)."""
    return (x * x + y * y).nonnegative_part().sqrt()


_BALL_MAXIMUM: Any = np.frompyfunc(flint.arb.max, 2, 1)
_ANY_MAXIMUM: Any = np.frompyfunc(lambda a, b: flint.arb(a).max(b), 2, 1)


def _ball_maximum(a: Any, b: Any) -> Any:
    """arb's max entry by entry: straight where the first operand's entries are balls (the
    usual case: no copy of each), through a conversion of them otherwise."""
    try:
        return _BALL_MAXIMUM(a, b)
    except TypeError:  # an entry of ``a`` is not an arb
        return _ANY_MAXIMUM(a, b)


_ABS_UPPER: Any = np.frompyfunc(flint.arb.abs_upper, 1, 1)
_ABS_LOWER: Any = np.frompyfunc(flint.arb.abs_lower, 1, 1)


def _compiled_pair(x: Any, y: Any) -> bool:
    """Whether x and y are equal-length 1-d object arrays of balls (``arb_loops``)."""
    return (
        arb_loops.AVAILABLE
        and isinstance(x, np.ndarray)
        and isinstance(y, np.ndarray)
        and x.dtype == object
        and y.dtype == object
        and x.ndim == y.ndim == 1
        and len(x) == len(y) > 0
        and all_balls(x)
        and all_balls(y)
    )


def all_balls(values: Array) -> bool:
    """Whether every entry of an object array is an ``arb`` (what the compiled loops read):
    each entry's type word compared in a compiled loop (``arb_program.all_balls``, with reading
    the addresses about 8 ns an entry), else entry by entry (about 30 ns)."""
    if arb_loops.known_balls(values):
        return True
    if arb_program.AVAILABLE:
        return arb_program.all_balls(arb_loops.addresses(values))
    return arb_loops.all_balls(values)


def _largest_abs(values: Array, upward: bool) -> Any:
    """The largest ``abs_upper`` (``upward``) or ``abs_lower`` of an object array of balls,
    the entry found in a compiled loop (``arb_loops.argmax_abs``, the same bounds compared),
    its bound computed here; None where the loop does not apply (then Python's ``max``)."""
    if not arb_loops.AVAILABLE:
        return None
    # the addresses read once, for the type check and the loop (``all_balls`` reads them too)
    read = arb_loops.addresses(values)
    if not arb_loops.known_balls(values) and not (
        arb_program.all_balls(read) if arb_program.AVAILABLE else arb_loops.all_balls(values)
    ):
        return None
    flat = values.reshape(-1)
    found = arb_loops.argmax_abs(flat, upward, read)
    if found == -1:
        return flint.arb(0)
    if found < 0:
        return None
    return flat[found].abs_upper() if upward else flat[found].abs_lower()


def upper_float(value: Any) -> float:
    """A float >= the (exact, radius-0) arb ``value``."""
    nearest = float(value.mid()) + 0.0
    return math.nextafter(nearest, math.inf) if nearest != math.inf else nearest


def lower_float(value: Any) -> float:
    """A float <= the (exact, radius-0) arb ``value``, and >= 0."""
    nearest = float(value.mid())
    return max(0.0, math.nextafter(nearest, -math.inf))
