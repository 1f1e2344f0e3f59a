"""Two precisions behind one interface, so every construction is written once.

``Float64`` computes with numpy float64 arrays; ``MultiPrecision`` computes with numpy
object arrays holding mpmath numbers of one private mpmath context (so concurrent requests with
different ``digits`` never share the global ``mpmath.mp``). Geometry code takes an
``Arithmetic`` and uses only ``+ - * /``, comparisons and the functions below, so the float64
and the mp path run the same lines of mathematics.

Conventions:
- an *array* is a 1-d numpy array: ``(n,)`` float64, or ``(n,)`` object holding ``mpf``;
- literal constants in geometry code are integers or exact binary fractions (``2``, ``0.5``),
  so that they mean the same number in both precisions;
- tolerances come from ``Arithmetic.tolerance`` and nowhere else.

A parameter written by the client is an ``ExactReal`` (``app.geometry.exact``); mpmath's
functions apply to object arrays through ``app.geometry.mp_elementwise``.
"""

from __future__ import annotations

import operator
import time
from collections.abc import Callable, Iterable, Iterator
from contextlib import contextmanager
from functools import partial
from typing import Any, Literal

import mpmath
import numpy as np

from app.geometry import elementary
from app.geometry.compiled import all_finite_vector, hypot_arrays
from app.geometry.errors import DomainError, TimeLimitError
from app.geometry.exact import ExactReal as ExactReal
from app.geometry.mp_elementwise import array_aware_npconvert, elementwise

#: The elementary functions of one argument every arithmetic offers (float64, mpmath, balls).
UNARY_FUNCTIONS = (
    "exp",
    "expm1",
    "log",
    "log1p",
    "sqrt",
    "cos",
    "sin",
    "cosh",
    "sinh",
    "tanh",
    "atanh",
    "asinh",
    "acosh",
)

Array = np.ndarray[Any, np.dtype[Any]]
"""``(n,)`` float64 array in float64 mode, ``(n,)`` object array of ``mpf`` in mp mode."""

Scalar = Any
"""``float`` in float64 mode, ``mpf`` in mp mode."""

PrecisionMode = Literal["float64", "mp"]

#: How many units of the working precision a residual may use per elementary step before a
#: check calls it a failure. One constant for the whole core.
TOLERANCE_SAFETY = 64

#: Sequential loops call ``Arithmetic.check_time`` once per this many steps.
CLOCK_STEPS = 4096

#: Extra decimal digits carried by the mp context beyond the requested ``digits``.
GUARD_DIGITS = 10

#: Float64 evaluates elementwise formulas over long arrays in blocks of this many entries
#: (``Arithmetic.points`` and ``Arithmetic.values``): every temporary of a block (64 KiB) stays
#: in the L2 cache and below glibc's mmap threshold (128 KiB in ``make run``), so a formula of k
#: numpy passes costs k passes over the cache instead of k passes over memory, each into a fresh
#: allocation (about 2× faster at 10^6 vertices; bench/kernels.py, docs/performance.md).
BLOCK_SIZE = 8192


class UndecidedError(ArithmeticError):
    """A comparison that the balls cannot decide (``Arithmetic.exceeds``): the exact values are
    closer than the radii. ``balls.serve`` computes again with more digits."""

    def __init__(self, parameter: str, what: str) -> None:
        super().__init__(f"{what}: undecided at this precision")
        self.parameter, self.what = parameter, what


Kernel = Callable[..., Any]
"""An elementwise formula: arrays aligned entry by entry in, an array (or a pair) out."""


class Arithmetic:
    """Elementwise arithmetic in one precision; see the module docstring."""

    mode: PrecisionMode
    digits: int
    eps: float
    """Unit of the *requested* precision: 2**-52 in float64, 10**-digits in mp."""
    working_eps: float
    """Unit of the precision actually computed with (mp carries guard digits)."""
    may_overflow: bool
    """Whether a result can overflow to ±inf (float64's exponent range ends near 1.8e308;
    mpmath's exponents are unbounded). Formulas with an overflow-free fallback test it to take
    the direct, cheaper form where it cannot matter."""

    def scalar(self, value: float | int | str) -> Scalar:
        """One number in this precision; floats are read as their shortest decimal."""
        raise NotImplementedError

    def array(self, values: Iterable[Any]) -> Array:
        """An ``(n,)`` array of the given numbers in this precision."""
        raise NotImplementedError

    def empty(self, n: int) -> Array:
        """An ``(n,)`` array to be filled."""
        raise NotImplementedError

    def indices(self, i_min: int, i_max: int) -> Array:
        """The integers ``i_min .. i_max`` (inclusive) as numbers of this precision."""
        return self.array(range(i_min, i_max + 1))

    def zeros(self, n: int) -> Array:
        """An ``(n,)`` array of zeros."""
        return self.array([0] * n)

    def points(self, kernel: Kernel, *arrays: Array) -> Array:
        """``(n, 2)`` points with ``(x, y) = kernel(a, b, …)`` of the aligned ``(n,)`` arrays.

        The kernel must be elementwise (entry k of its results depends on entry k of its
        arguments only): float64 evaluates it block by block, mp at once, with the same code.
        """
        return self.columns(kernel, 2, *arrays)

    def columns(self, kernel: Kernel, width: int, *arrays: Array) -> Array:
        """``(n, width)``: column j is the j-th result of the elementwise ``kernel``."""
        return np.stack(kernel(*arrays), axis=1)

    def values(self, kernel: Kernel, *arrays: Array) -> Array:
        """``(n,)`` values ``kernel(a, b, …)`` of the aligned ``(n,)`` arrays (elementwise)."""
        result: Array = kernel(*arrays)
        return result

    # elementwise functions (scalars or arrays)
    exp: Callable[[Any], Any]
    expm1: Callable[[Any], Any]
    log: Callable[[Any], Any]
    log1p: Callable[[Any], Any]
    sqrt: Callable[[Any], Any]
    cos: Callable[[Any], Any]
    sin: Callable[[Any], Any]
    cosh: Callable[[Any], Any]
    sinh: Callable[[Any], Any]
    tanh: Callable[[Any], Any]
    atanh: Callable[[Any], Any]
    asinh: Callable[[Any], Any]
    acosh: Callable[[Any], Any]
    atan2: Callable[[Any, Any], Any]
    hypot: Callable[[Any, Any], Any]
    #: x^y elementwise (an array exponent: the printed forms of (14), (16), (21), Theorems 14, 15)
    power: Callable[[Any, Any], Any] = staticmethod(operator.pow)

    @property
    def pi(self) -> Scalar:
        raise NotImplementedError

    def to_float(self, value: Any) -> float:
        """A scalar as a Python float (for residuals, which are always reported as numbers)."""
        return float(value)

    def to_floats(self, values: Array) -> np.ndarray[Any, np.dtype[np.float64]]:
        """An array as float64 (for residuals and plots)."""
        return np.asarray(values, dtype=np.float64)

    def all_finite(self, values: Array) -> bool:
        """Whether every entry is a finite number."""
        raise NotImplementedError

    certified: bool = False
    """Whether numbers are rigorous balls (``Ball``): then ``to_floats`` of a residual is an
    upper bound of its absolute value and ``lower_floats`` a lower bound."""

    def lower_floats(self, values: Array) -> np.ndarray[Any, np.dtype[np.float64]]:
        """Lower bounds of ``|values|`` as float64 (here: the values themselves)."""
        return np.abs(self.to_floats(values))

    def maximum(self, a: Any, b: Any) -> Any:
        """The larger of a and b entry by entry (for balls: a ball holding the exact maximum)."""
        return np.maximum(a, b)

    def exceeds(self, a: Scalar, b: Scalar, parameter: str, what: str) -> bool:
        """Whether a > b, for a discrete choice of a construction (which branch, which side).

        Balls answer only what they prove; an undecided comparison raises ``UndecidedError``
        (naming ``parameter`` and ``what`` is chosen) so that the computation is redone with
        more digits, never guessed.
        """
        return bool(a > b)

    def at_least_or(self, x: Scalar, y: Scalar, a: Scalar, b: Scalar) -> Scalar:
        """``a`` if x >= y else ``b`` (for balls, undecided: a ball holding both)."""
        return a if x >= y else b

    def nonnegative(self, x: Scalar) -> Scalar:
        """x where it is >= 0, else 0 (a value >= 0 in exact arithmetic, below by rounding)."""
        return x if not x < 0 else self.scalar(0)

    def truncate(self, x: Scalar) -> int:
        """x truncated to an integer (a starting guess of a search that decides exactly)."""
        return int(x)

    deadline: float | None = None
    """``time.monotonic()`` after which ``check_time`` stops the computation (None: no limit)."""
    limit: tuple[str, float] = ("i_max", 0.0)

    def start_clock(self, seconds: float, parameter: str) -> None:
        """Allow ``seconds`` from now; past them ``check_time`` raises, naming ``parameter``."""
        self.deadline = time.monotonic() + seconds
        self.limit = (parameter, seconds)

    def check_time(self) -> None:
        """Raise ``TimeLimitError`` once the deadline has passed (cheap: one clock read).

        Called by the sequential construction loops every few thousand steps and by every
        elementwise mp operation: the paths whose cost grows fastest with the request.
        """
        if self.deadline is not None and time.monotonic() > self.deadline:
            parameter, seconds = self.limit
            raise TimeLimitError(
                parameter,
                f"the computation finishes within {seconds:g} s (DCOSH_TIME_LIMIT)",
                "over the limit",
                "use a shorter range or fewer digits",
            )

    undecided: int = 0
    """Checks left undecided on balls (``checks.check_residuals`` counts them on ``Ball``)."""

    @contextmanager
    def recursion(self) -> Iterator[None]:
        """Around a sequential construction (a recursion along the range): on balls, computed
        with the extra digits its growing radii need (``Ball.recursion``); here nothing."""
        yield

    @contextmanager
    def residual_precision(self) -> Iterator[None]:
        """Around the last operations of a residual (its differences already taken): a residual
        is reported as a float, so on balls these run at ``RESIDUAL_BITS`` (rigorous all the
        same, and about twice as fast for a square root); here nothing."""
        yield

    def tolerance(self, steps: int = 1) -> float:
        """The tolerance for a residual built from ``steps`` elementary operations in sequence."""
        return TOLERANCE_SAFETY * self.eps * max(1, steps)

    def describe(self) -> dict[str, Any]:
        """``{"mode": ..., "digits": ...}`` as in the response's ``precision`` field."""
        return {"mode": self.mode, "digits": self.digits}


class Float64(Arithmetic):
    """IEEE double precision with numpy; vectorized everywhere a formula allows it."""

    mode: PrecisionMode = "float64"
    digits = 16
    eps = float(np.finfo(np.float64).eps)
    working_eps = eps
    may_overflow = True

    # the C library's functions on every machine (``elementary``), not numpy's, whose
    # float64 ufuncs take other implementations on a processor with AVX-512
    exp = staticmethod(elementary.exp_array)  # the same bits, vectorized for arrays
    expm1 = staticmethod(elementary.expm1)
    log = staticmethod(elementary.log)
    log1p = staticmethod(elementary.log1p)
    sqrt = staticmethod(np.sqrt)  # correctly rounded on every machine (IEEE 754)
    cos = staticmethod(elementary.cos)
    sin = staticmethod(elementary.sin)
    cosh = staticmethod(elementary.cosh_array)  # the same bits, vectorized for arrays
    sinh = staticmethod(elementary.sinh)
    tanh = staticmethod(elementary.tanh)
    atanh = staticmethod(elementary.atanh)
    asinh = staticmethod(elementary.asinh)
    acosh = staticmethod(elementary.acosh)
    atan2 = staticmethod(elementary.atan2)
    power = staticmethod(elementary.power)
    hypot = staticmethod(hypot_arrays)  # np.hypot's bits, compiled for aligned vectors

    def scalar(self, value: float | int | str) -> float:
        return float(value)  # an ExactReal's nearest double

    def array(self, values: Iterable[Any]) -> Array:
        return (
            np.fromiter(values, dtype=np.float64)
            if not isinstance(values, np.ndarray)
            else values.astype(np.float64, copy=False)
        )

    def empty(self, n: int) -> Array:
        return np.empty(n, dtype=np.float64)

    def indices(self, i_min: int, i_max: int) -> Array:
        return np.arange(i_min, i_max + 1, dtype=np.float64)

    def zeros(self, n: int) -> Array:
        return np.zeros(n, dtype=np.float64)

    def columns(self, kernel: Kernel, width: int, *arrays: Array) -> Array:
        n = len(arrays[0]) if arrays else 0
        if n <= BLOCK_SIZE:
            return super().columns(kernel, width, *arrays)
        out = np.empty((n, width), dtype=np.float64)
        for start in range(0, n, BLOCK_SIZE):
            block = slice(start, start + BLOCK_SIZE)
            for column, value in enumerate(kernel(*(a[block] for a in arrays))):
                out[block, column] = value
        return out

    def values(self, kernel: Kernel, *arrays: Array) -> Array:
        n = len(arrays[0]) if arrays else 0
        if n <= BLOCK_SIZE:
            return super().values(kernel, *arrays)
        out = np.empty(n, dtype=np.float64)
        for start in range(0, n, BLOCK_SIZE):
            block = slice(start, start + BLOCK_SIZE)
            out[block] = kernel(*(a[block] for a in arrays))
        return out

    @property
    def pi(self) -> float:
        return float(np.pi)

    def all_finite(self, values: Array) -> bool:
        if isinstance(values, np.ndarray) and values.ndim == 1 and values.dtype == np.float64:
            return bool(all_finite_vector(values))  # one compiled pass
        return bool(np.all(np.isfinite(values)))


class MultiPrecision(Arithmetic):
    """mpmath numbers with ``digits`` significant decimal digits (plus guard digits)."""

    mode: PrecisionMode = "mp"
    may_overflow = False

    def __init__(self, digits: int) -> None:
        if digits < 1:
            raise DomainError("digits", "digits >= 1", digits)
        self.digits = digits
        self.eps = 10.0 ** (-digits)
        self.working_eps = 10.0 ** (-digits - GUARD_DIGITS)

    # The mpmath context and its functions are made when first used: an mp request served on
    # balls (``balls.serve``) reads only ``digits`` and the clock of this object, and a new
    # MPContext costs about 3 ms (a quarter of a 1000-vertex recursion at 50 digits).
    _LAZY = frozenset((*UNARY_FUNCTIONS, "ctx", "atan2", "hypot", "_isfinite"))

    def __getattr__(self, name: str) -> Any:
        # only called for names not set yet: the lazy ones are set all at once by _build
        if name in MultiPrecision._LAZY and "ctx" not in self.__dict__:
            self._build()
            return getattr(self, name)
        raise AttributeError(name)

    def _build(self) -> None:
        """The private mpmath context at ``digits`` + guard digits, and its functions."""
        ctx = mpmath.MPContext()
        ctx.dps = self.digits + GUARD_DIGITS
        ctx.npconvert = array_aware_npconvert(ctx.npconvert)
        elementwise_ = partial(elementwise, clock=self.check_time)
        for name in UNARY_FUNCTIONS:
            setattr(self, name, elementwise_(getattr(ctx, name)))
        self.atan2 = elementwise_(ctx.atan2, 2)
        self.hypot = elementwise_(ctx.hypot, 2)
        self._isfinite = np.frompyfunc(ctx.isfinite, 1, 1)
        self.ctx = ctx

    def scalar(self, value: float | int | str) -> Any:
        # An ExactReal is read as the decimal the client wrote; any other float through repr(),
        # the shortest decimal that round-trips it: d=0.3 means 3/10 here, not the binary
        # neighbour 0.29999999999999998889...
        if isinstance(value, ExactReal):
            return self.ctx.mpf(value.text)
        return self.ctx.mpf(repr(float(value)) if isinstance(value, float) else value)

    def array(self, values: Iterable[Any]) -> Array:
        items = [v if isinstance(v, self.ctx.mpf) else self.scalar(v) for v in values]
        out = np.empty(len(items), dtype=object)
        out[:] = items
        return out

    def empty(self, n: int) -> Array:
        return np.empty(n, dtype=object)

    @property
    def pi(self) -> Any:
        return +self.ctx.pi

    def to_float(self, value: Any) -> float:
        return float(value)

    def to_floats(self, values: Array) -> np.ndarray[Any, np.dtype[np.float64]]:
        return np.fromiter((float(v) for v in values), dtype=np.float64, count=len(values))

    def all_finite(self, values: Array) -> bool:
        return bool(np.all(self._isfinite(values))) if len(values) else True

    def to_strings(self, values: Array) -> list[str]:
        """Decimal strings with ``digits`` significant digits."""
        nstr = self.ctx.nstr
        digits = self.digits
        return [nstr(v, digits) for v in values]


def arithmetic(mode: PrecisionMode, digits: int | None = None) -> Arithmetic:
    """The ``Arithmetic`` for a precision mode (``digits`` is used in mp mode only)."""
    if mode == "float64":
        return Float64()
    if mode == "mp":
        return MultiPrecision(digits if digits is not None else 30)
    raise DomainError("precision", "precision is 'float64' or 'mp'", mode)


def stack_points(x: Array, y: Array) -> Array:
    """Two ``(n,)`` coordinate arrays as one ``(n, 2)`` array of points.

    Filled column by column (``np.stack`` took 7× as long for float64 at 10^6 points).
    """
    x, y = np.asarray(x), np.asarray(y)
    if x.shape != y.shape or x.ndim != 1:
        return np.stack([x, y], axis=1)  # its error for arrays that do not pair up
    points = np.empty((len(x), 2), dtype=np.result_type(x, y))
    points[:, 0] = x
    points[:, 1] = y
    return points
