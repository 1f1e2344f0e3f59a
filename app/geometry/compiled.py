"""Float64 kernels compiled to machine code (numba), and the list of them for the warm-up.

The recursive constructions (D1), (D3), (D4a), (D4b) need the previous vertex for the next one,
so numpy cannot vectorize them; a Python loop costs 0.4–1.5 µs per vertex. Each of them has one
float64 implementation, a kernel compiled here and written in its own ``construction.py`` from
the paper's definition, step for step as the mp path (which keeps its Python loop over mpmath
numbers). The hot float64 checks of (D4b) are kernels too (``d4b/residual_kernels.py``).

Every kernel is declared with its signature, so it is compiled (or loaded from numba's on-disk
cache) when its module is imported, never on a first request; ``python -m app.geometry.warm``
imports all of them once, so that ``make run`` and ``make test`` find the cache filled
(``NUMBA_CACHE_DIR``, docs/performance.md).

The cache (``NUMBA_CACHE_DIR``, set by the Makefile to ``.numba-cache/``) may be read-only, as
in the service image: numba's own locator refuses a directory it cannot write to, so
``ReadableCacheLocator`` comes first and loads from it anyway. Should a kernel still need
compiling there (another CPU than the one that filled the cache), saving fails and the kernel is
compiled in memory instead, at import as before: the service starts, only more slowly.

Kernels are compiled without fast-math: IEEE operations in the order they are written, no
contraction into fused multiply-adds, so a kernel returns the same bits as the same formula
evaluated by numpy or Python floats (tests/geometry/*/test_construction.py compare them).
"""

from __future__ import annotations

import contextlib
import math
from collections.abc import Callable
from typing import Any, TypeVar, cast

import numba
import numpy as np
from numba.core import caching, types
from numba.extending import intrinsic

F = TypeVar("F", bound=Callable[..., Any])


class ReadableCacheLocator(caching.UserProvidedCacheLocator):
    """``NUMBA_CACHE_DIR``, used when it can be read even if it cannot be written."""

    def ensure_cache_path(self) -> None:
        # read-only: loading works; a save fails, and ``kernel`` compiles in memory instead
        with contextlib.suppress(OSError):
            super().ensure_cache_path()  # type: ignore[no-untyped-call]


caching.CacheImpl._locator_classes = [
    ReadableCacheLocator,
    *caching.CacheImpl._locator_classes,
]

#: Every compiled kernel, by qualified name (``python -m app.geometry.warm`` lists them).
KERNELS: dict[str, Any] = {}


def kernel(signature: str) -> Callable[[F], F]:
    """Compile a float64 kernel with this numba signature, cached on disk, at import time.

    ``error_model="numpy"``: a division by zero gives inf or NaN as in numpy instead of raising;
    ``nogil``: a kernel releases the GIL, so other requests' threads go on meanwhile.
    """

    def compile_(function: F) -> F:
        options: dict[str, Any] = {"nogil": True, "error_model": "numpy"}
        try:
            compiled = numba.njit(signature, cache=True, **options)(function)
        except (OSError, RuntimeError):  # no cache to read or write: compile in memory
            compiled = numba.njit(signature, cache=False, **options)(function)
        KERNELS[f"{function.__module__}.{function.__qualname__}"] = compiled
        return cast(F, compiled)

    return compile_


def compiled_ufunc(signature: str) -> Callable[[Callable[..., float]], np.ufunc]:
    """Compile a scalar float64 function with this numba signature into a numpy ufunc, cached
    on disk, at import time: the ufunc's loop calls the compiled function on each element
    (broadcasting, ``out=`` and scalars as any ufunc; numpy's floating-point warnings too)."""

    def compile_(function: Callable[..., float]) -> np.ufunc:
        try:
            compiled = numba.vectorize([signature], cache=True, nopython=True)(function)  # type: ignore[no-untyped-call]
        except (OSError, RuntimeError):  # no cache to read or write: compile in memory
            compiled = numba.vectorize([signature], cache=False, nopython=True)(function)  # type: ignore[no-untyped-call]
        ufunc: np.ufunc = compiled.ufunc  # the plain ufunc: no Python layer per call
        KERNELS[f"{function.__module__}.{function.__qualname__}"] = ufunc
        return ufunc

    return compile_


#: glibc's bounds for its unscaled hypot: the larger |argument| at most 2^511, the smaller at
#: least 2^-459 and more than 2^-54 times the larger (``hypot``); outside them it scales by 2^±600.
HYPOT_LARGE, HYPOT_TINY, HYPOT_EPS, HYPOT_SCALE = 2.0**511, 2.0**-459, 2.0**-54, 2.0**-600


@numba.njit(cache=True, inline="always", error_model="numpy")
def _hypot_kernel(a: float, b: float) -> float:
    """glibc's √(a² + b²) for a ≥ b ≥ 0 in its unscaled range, corrected by one Newton step on
    the rounding errors of the squares (Borges' algorithm, without FMA)."""
    h = math.sqrt(a * a + b * b)
    if h <= 2.0 * b:
        delta = h - b
        t1 = a * (2.0 * delta - a)
        t2 = (delta - 2.0 * (a - b)) * delta
    else:
        delta = h - a
        t1 = 2.0 * delta * (a - 2.0 * b)
        t2 = (4.0 * delta - b) * b + delta * delta
    return h - (t1 + t2) / (2.0 * h)


@numba.njit(cache=True, inline="always", error_model="numpy")
def hypot(x: float, y: float) -> float:
    """libm's hypot(x, y), bit for bit, without the call (glibc 2.36, x86-64 without FMA).

    glibc computes h = √(a² + b²) for a = max(|x|, |y|), b = min(|x|, |y|) and corrects it by
    one Newton step on the rounding errors of the squares (``_hypot_kernel``); a > 2^511 is
    scaled by 2^-600 first, b < 2^-459 by 2^600 (the scalings are exact), and a b too small to
    matter (b ≤ 2^-54 a) gives a + b. All of that is done here, inline; only inf and NaN call
    libm. Earlier sessions measured 50–90 ns for the call; on this host in session 17 the call
    and the inline form both cost 5–8 ns a call in a loop (two per face of a long ring, whose
    far faces are mostly in the scaled ranges). tests/geometry/test_compiled.py compares it
    with ``np.hypot`` on millions of arguments.
    """
    a, b = abs(x), abs(y)
    if a < b:
        a, b = b, a
    if a <= HYPOT_LARGE and b >= HYPOT_TINY and b > a * HYPOT_EPS:
        return _hypot_kernel(a, b)
    if not (a <= 1.7976931348623157e308 and b <= a):  # inf or NaN: libm's rules
        return math.hypot(x, y)
    if a > HYPOT_LARGE:
        if b <= a * HYPOT_EPS:
            return a + b
        return _hypot_kernel(a * HYPOT_SCALE, b * HYPOT_SCALE) / HYPOT_SCALE
    if b < HYPOT_TINY:
        if a >= b / HYPOT_EPS:
            return a + b
        return _hypot_kernel(a / HYPOT_SCALE, b / HYPOT_SCALE) * HYPOT_SCALE
    return a + b  # b <= 2^-54 a


def _fma(typingctx: Any, a: Any, b: Any, c: Any) -> Any:
    signature = types.float64(types.float64, types.float64, types.float64)

    def codegen(context: Any, builder: Any, sig: Any, args: Any) -> Any:
        return builder.fma(*args)

    return signature, codegen


def _float_bits(typingctx: Any, x: Any) -> Any:
    signature = types.uint64(types.float64)

    def codegen(context: Any, builder: Any, sig: Any, args: Any) -> Any:
        return builder.bitcast(args[0], context.get_value_type(types.uint64))

    return signature, codegen


def _bits_float(typingctx: Any, bits: Any) -> Any:
    signature = types.float64(types.uint64)

    def codegen(context: Any, builder: Any, sig: Any, args: Any) -> Any:
        return builder.bitcast(args[0], context.get_value_type(types.float64))

    return signature, codegen


#: a·b + c rounded once (LLVM's ``llvm.fma.f64``), in compiled code: one instruction with FMA,
#: the C library's ``fma`` without it, the same bits either way. The kernels compile without
#: contraction, so a fused multiply-add happens only where a kernel asks for it by name.
fma = cast(Callable[[float, float, float], float], intrinsic(_fma))
#: The bit pattern of a float64 as an unsigned 64-bit integer, in compiled code (free).
float_bits = cast(Callable[[float], int], intrinsic(_float_bits))
#: The float64 with this unsigned 64-bit pattern, in compiled code (``float_bits`` undone).
bits_float = cast(Callable[[Any], float], intrinsic(_bits_float))


#: Magnitudes between which a sum of squares neither overflows nor underflows past its last bits.
SQUARES_LOW, SQUARES_HIGH = 2.0**-480, 2.0**480


@numba.njit(cache=True, inline="always", error_model="numpy")
def length(x: float, y: float) -> float:
    """|(x, y)| for residuals: √(x² + y²) for moderate magnitudes, libm's hypot outside them.

    libm's hypot costs 50–90 ns here (glibc 2.36); the square root of the sum of squares is
    within 2 units in the last place of it wherever neither square overflows or underflows,
    which a residual at rounding level may differ by (tests/test_golden.py); outside, libm's
    hypot inline (``hypot``). Coordinates that responses show keep hypot.
    """
    big = max(abs(x), abs(y))
    if SQUARES_LOW < big < SQUARES_HIGH:
        return math.sqrt(x * x + y * y)
    return hypot(x, y)


@numba.njit(cache=True, inline="always", error_model="numpy")
def length3(x: float, y: float, z: float) -> float:
    """|(x, y, z)| for residuals, as ``length`` (hypot(hypot(x, y), z) outside)."""
    big = max(abs(x), abs(y), abs(z))
    if SQUARES_LOW < big < SQUARES_HIGH:
        return math.sqrt(x * x + y * y + z * z)
    return hypot(hypot(x, y), z)


#: All bits of a float64 but its sign, and the pattern of +inf. For non-negative floats the
#: patterns as integers order as the numbers do (a NaN's pattern is above ``INF_BITS``), so the
#: largest magnitude of a block is an integer maximum, which the compiler vectorizes without
#: fast-math (a float maximum it does not: ``max`` is not associative once NaN is involved).
MAGNITUDE_BITS = 0x7FFF_FFFF_FFFF_FFFF
INF_BITS = 0x7FF0_0000_0000_0000


@numba.njit(cache=True, inline="always", error_model="numpy")
def largest_bits(values: Any, count: int) -> int:
    """The largest magnitude's bit pattern of float64 ``values[:count]`` (0 for none; above
    ``INF_BITS`` if one is NaN), as an integer maximum the compiler vectorizes."""
    bits = values.view(np.int64)
    top = 0
    for j in range(count):
        pattern = bits[j] & MAGNITUDE_BITS
        top = pattern if pattern > top else top
    return top


@numba.njit(cache=True, inline="always", error_model="numpy")
def bits_value(bits: int) -> float:
    """The float64 whose bit pattern is ``bits``, a signed 64-bit integer (e.g. ``largest_bits``'
    result as a number): ``bits_float`` of the same 64 bits, no array a call."""
    return bits_float(np.uint64(bits))


@numba.njit(cache=True, inline="always", error_model="numpy")
def flat_rows(points: Any, start: int, count: int) -> Any:
    """Rows start .. start + count − 1 of a C-contiguous (m, 2) array (or of its flat entries,
    (2m,)) as (2·count,) flat entries: x of row start + j at 2j, y at 2j + 1.

    A loop over a block reads its rows this way so that the compiler vectorizes it: indexing
    ``rows[j, 0]`` of a two-dimensional slice kept the Darboux passes and the rotation angle's
    blocks scalar (issue 13, session 30: the same loops 2–4× faster read flat, the same bits).
    """
    return points.reshape(-1)[2 * start : 2 * (start + count)]


@numba.njit(cache=True, inline="always", error_model="numpy")
def fast_length(x: float, y: float) -> tuple[float, bool]:
    """``length`` on its square-root branch without a branch: (√(x² + y²), whether ``length``
    takes that branch or gives the same number: the larger magnitude inside its moderate
    range, or both zero, where hypot is 0 too). A NaN argument makes a NaN length."""
    ax, ay = abs(x), abs(y)
    big = ax if ax > ay else ay
    usual = ((big > SQUARES_LOW) & (big < SQUARES_HIGH)) | (big == 0.0)
    return math.sqrt(x * x + y * y), usual


@numba.njit(cache=True, inline="always", error_model="numpy")
def running_largest(value: float, largest: float) -> float:
    """One step of the largest |value| of a sequence, NaN once one is NaN (as ``np.max`` of the
    magnitudes): start from 0.0, feed each value."""
    if largest != largest:
        return largest
    magnitude = abs(value)
    return magnitude if not magnitude <= largest else largest


@kernel("float64(float64[:])")
def largest_of_magnitudes(values: Any) -> float:
    """max |v| of a float64 vector, NaN if one is NaN (``np.abs(values).max()``, exactly: no
    rounding is involved), in one compiled pass: at 20–1000 entries a third of the two numpy
    reductions ``checks.largest_magnitude`` took (each check of every answer takes one)."""
    largest = 0.0
    for k in range(values.shape[0]):
        largest = running_largest(values[k], largest)
    return largest


@kernel("boolean(float64[:])")
def all_finite_vector(values: Any) -> bool:
    """Whether every entry of a float64 vector is finite (``np.all(np.isfinite(v))`` in one
    compiled pass, stopping at the first that is not)."""
    for k in range(values.shape[0]):  # noqa: SIM110 (a loop numba compiles)
        if not math.isfinite(values[k]):
            return False
    return True


@kernel("float64[:](float64[:], float64[:])")
def _hypot_arrays(x: Any, y: Any) -> Any:
    """``hypot`` entry by entry of two aligned arrays (any strides)."""
    out = np.empty(x.shape[0])
    for k in range(x.shape[0]):
        out[k] = hypot(x[k], y[k])
    return out


def hypot_arrays(x: Any, y: Any) -> Any:
    """``np.hypot(x, y)`` with the same bits, compiled (≈ 5× faster) for two aligned float64
    vectors; anything else (scalars, broadcasting, other types) goes to ``np.hypot``."""
    if (
        isinstance(x, np.ndarray)
        and isinstance(y, np.ndarray)
        and x.ndim == 1
        and x.shape == y.shape
        and x.dtype == np.float64
        and y.dtype == np.float64
    ):
        return _hypot_arrays(x, y)
    return np.hypot(x, y)


@kernel("boolean(float64[:, :])")
def all_positive_lengths(vectors: Any) -> bool:
    """Whether hypot(v_x, v_y) > 0 for every row (false for a zero or NaN row), as
    ``np.all(np.hypot(…) > 0)`` without the array of lengths."""
    for k in range(vectors.shape[0]):  # noqa: SIM110 (a loop numba compiles)
        if not hypot(vectors[k, 0], vectors[k, 1]) > 0:
            return False
    return True


# --- numpy's pairwise summation written out: sums with the bits of ``np.sum`` ---

#: The most entries numpy sums in one run of eight accumulators (``PW_BLOCKSIZE``): the leaves
#: of its tree.
PAIRWISE_LEAF = 128


@kernel("float64(float64[::1], int64, int64)")
def pairwise_sum(values: Any, start: int, count: int) -> float:
    """numpy's pairwise summation of ``values[start : start + count]`` (``pairwise_sum`` of
    numpy/_core/src/umath/loops_utils.h: eight accumulators up to ``PAIRWISE_LEAF`` entries,
    halves at a multiple of 8 beyond), so that the sum has the bits of ``np.sum``."""
    if count < 8:
        total = 0.0
        for k in range(count):
            total += values[start + k]
        return total
    if count <= PAIRWISE_LEAF:
        r0, r1 = values[start], values[start + 1]
        r2, r3 = values[start + 2], values[start + 3]
        r4, r5 = values[start + 4], values[start + 5]
        r6, r7 = values[start + 6], values[start + 7]
        end = count - count % 8
        k = 8
        while k < end:
            at = start + k
            r0 += values[at]
            r1 += values[at + 1]
            r2 += values[at + 2]
            r3 += values[at + 3]
            r4 += values[at + 4]
            r5 += values[at + 5]
            r6 += values[at + 6]
            r7 += values[at + 7]
            k += 8
        total = ((r0 + r1) + (r2 + r3)) + ((r4 + r5) + (r6 + r7))
        while k < count:
            total += values[start + k]
            k += 1
        return total
    half = count // 2
    half -= half % 8
    return pairwise_sum(values, start, half) + pairwise_sum(values, start + half, count - half)


@kernel("float64(float64[::1])")
def numpy_sum(values: Any) -> float:
    """``np.sum`` of a contiguous float64 vector, bit for bit (0.0 for an empty one; the sum
    starts from +0.0, so that a sum of −0.0 entries is +0.0 as numpy has it)."""
    return 0.0 + pairwise_sum(values, 0, values.shape[0])


@kernel("int64(int64, int64, int64[:, ::1], int64)")
def pairwise_leaves(start: int, count: int, out: Any, at: int) -> int:
    """The leaves of ``pairwise_sum``'s tree on start .. start + count − 1, left to right, as rows
    (first, count) of ``out`` from row ``at``; returns the row after the last."""
    if count <= PAIRWISE_LEAF:
        out[at, 0], out[at, 1] = start, count
        return at + 1
    half = count // 2
    half -= half % 8
    at = pairwise_leaves(start, half, out, at)
    return pairwise_leaves(start + half, count - half, out, at)


@kernel("UniTuple(float64, 2)(int64, float64[:, ::1], int64[::1])")
def leaf_tree(count: int, sums: Any, at: Any) -> tuple[float, float]:
    """``pairwise_sum``'s tree over count terms whose leaves' sums are the rows of ``sums`` from
    row at[0] on (advanced past those it reads)."""
    if count == 0:
        return 0.0, 0.0
    if count <= PAIRWISE_LEAF:
        row = at[0]
        at[0] = row + 1
        return sums[row, 0], sums[row, 1]
    half = count // 2
    half -= half % 8
    a = leaf_tree(half, sums, at)
    b = leaf_tree(count - half, sums, at)
    return a[0] + b[0], a[1] + b[1]
