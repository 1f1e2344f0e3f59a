"""The float64 elementary functions, from the C library on every machine.

numpy picks an implementation of its transcendental ufuncs by the processor it finds: with
AVX-512 (``X86_V4``) its float64 ``sin``, ``cos``, ``arctan2``, ``cosh``, ``sinh``, ``power``,
``expm1``, ``log1p`` and the inverse hyperbolic functions come from Intel's SVML, ``exp`` and
``log`` from its own AVX-512 code; without it they call the C library (libm), and ``tanh`` has a
SIMD polynomial of numpy's own in either case. The answers differ in their last bits, and an
error measure or a near cancellation turns those into visibly different numbers: the golden
answers recorded on an AVX-512 host differed on one without it by up to 256 ulp in the smooth
tractrix's vertices (the cancellation in x − h tanh(x/h) of (S4)) and by up to 3.4e-10
relative in Theorem 14's convergence errors (docs/performance.md, issue 13, session 28).

A reference service should give the same bytes for the same request on every replica, and a
strong ETag promises it. So the float64 arithmetic (``precision.Float64``) and every float64
path that called numpy's transcendental ufuncs call these instead: each is a numpy ufunc (so
broadcasting, ``out=`` and floating-point warnings behave as numpy's) whose loop calls the C
library's function through numba, as the compiled kernels' ``math.*`` calls already do. libm
is correctly rounded or within one ulp for these functions and picks no variant that changes
its results between x86-64 processors with FMA. The service runs on one C library, glibc 2.36
(Debian 12, on the hosts and in the image's ``python:3.11-slim-bookworm``); another release
could round some values differently. Where numpy called libm already (every function but
``tanh`` on a host without AVX-512) the bits are the same as before.

Signatures: each takes and returns float64 elementwise, ``(...) -> (...)``.

Two of them have a second, faster form for whole arrays: ``exp_into`` computes e^x with glibc's
own algorithm, written out here, so that the compiler vectorizes it (a call to libm per element
cannot be), and ``cosh_into`` glibc's cosh on top of it: the same bits as ``exp`` and ``cosh``,
about 3.5× and 2.5–4× faster (docs/performance.md, issue 13, session 29). ``exp_array`` and
``cosh_array`` (what ``Float64`` calls) take them for float64 arrays and keep the ufuncs'
warnings.
"""

from __future__ import annotations

import math
from typing import Any

import mpmath
import numba
import numpy as np

from app.geometry.compiled import bits_float, compiled_ufunc, float_bits, fma, kernel

_UNARY = "float64(float64)"
_BINARY = "float64(float64, float64)"


@compiled_ufunc(_UNARY)
def exp(x: float) -> float:
    """e^x."""
    return math.exp(x)


@compiled_ufunc(_UNARY)
def expm1(x: float) -> float:
    """e^x − 1."""
    return math.expm1(x)


@compiled_ufunc(_UNARY)
def log(x: float) -> float:
    """The natural logarithm."""
    return math.log(x)


@compiled_ufunc(_UNARY)
def log1p(x: float) -> float:
    """log(1 + x)."""
    return math.log1p(x)


@compiled_ufunc(_UNARY)
def cos(x: float) -> float:
    """The cosine."""
    return math.cos(x)


@compiled_ufunc(_UNARY)
def sin(x: float) -> float:
    """The sine."""
    return math.sin(x)


@compiled_ufunc(_UNARY)
def cosh(x: float) -> float:
    """The hyperbolic cosine."""
    return math.cosh(x)


@compiled_ufunc(_UNARY)
def sinh(x: float) -> float:
    """The hyperbolic sine."""
    return math.sinh(x)


@compiled_ufunc(_UNARY)
def tanh(x: float) -> float:
    """The hyperbolic tangent."""
    return math.tanh(x)


@compiled_ufunc(_UNARY)
def atanh(x: float) -> float:
    """The inverse hyperbolic tangent."""
    return math.atanh(x)


@compiled_ufunc(_UNARY)
def asinh(x: float) -> float:
    """The inverse hyperbolic sine."""
    return math.asinh(x)


@compiled_ufunc(_UNARY)
def acosh(x: float) -> float:
    """The inverse hyperbolic cosine."""
    return math.acosh(x)


@compiled_ufunc(_BINARY)
def atan2(y: float, x: float) -> float:
    """The argument of (x, y), in [−π, π]."""
    return math.atan2(y, x)


@compiled_ufunc(_BINARY)
def power(x: float, y: float) -> float:
    """x^y."""
    return x**y


# --- e^x a block at a time: glibc's algorithm, written out (``exp_into``) ---
#
# glibc 2.36's exp (the one of Szabolcs Nagy, from Arm's optimized routines) splits
# x = k·ln2/N + r with N = 128 and |r| ≤ ln2/(2N), so that e^x = 2^(k/N) · e^r: 2^(k/N) is
# 2^⌊k/N⌋ times one of N tabulated values, and e^r − 1 a polynomial of degree 5. On x86-64 with
# FMA (every host and image of the service: ``x86-64-v3``) the C library takes the variant
# compiled with fused multiply-adds; its machine code (``objdump -d`` of Debian's libm.so.6)
# fuses exactly the operations fused below, and these constants are the bits of its data.

#: N/ln 2, the shift 1.5·2^52 that rounds k to an integer in the low bits, −ln2/N in two parts.
EXP_INV_LN2_N = float.fromhex("0x1.71547652b82fep7")
EXP_SHIFT = float.fromhex("0x1.8p52")
EXP_NEG_LN2_HI_N = float.fromhex("-0x1.62e42fefa0000p-8")
EXP_NEG_LN2_LO_N = float.fromhex("-0x1.cf79abc9e3b3ap-47")
#: The polynomial's coefficients of r², r³, r⁴, r⁵ (1 and r are exact).
EXP_C2 = float.fromhex("0x1.ffffffffffdbdp-2")
EXP_C3 = float.fromhex("0x1.555555555543cp-3")
EXP_C4 = float.fromhex("0x1.55555cf172b91p-5")
EXP_C5 = float.fromhex("0x1.1111167a4d017p-7")
#: The exponent fields (biased) of 2^-54 and 512: between them (the usual range) no
#: overflow, underflow or tiny argument needs care; outside it ``exp_into`` calls libm. From
#: 512 on exp may overflow (or has an infinite or NaN argument), which only the ufunc reports
#: as numpy does (``exp_array``).
EXP_TOP_LOW, EXP_TOP_HUGE = 0x3C9, 0x408
#: Elements ``exp_into`` looks at together: all usual, the block goes to the vector loop.
EXP_CHUNK = 512


def _exp_table() -> Any:
    """glibc's table of 2^(k/128), k = 0..127, as ((256,) uint64) bit patterns: at 2k the tail
    t_k, at 2k + 1 the scale s_k less k·2^45 (the exponent k/128 adds back), where s_k is the
    double nearest 2^(k/128) and t_k the double nearest 2^(k/128)/s_k − 1; computed here at
    300 bits (mpmath) and the same bits as the C library's data (tests/geometry/test_elementary.py
    compares the results)."""
    table = np.empty(256, dtype=np.uint64)
    with mpmath.workprec(300):
        for k in range(128):
            exact = mpmath.mpf(2) ** (mpmath.mpf(k) / 128)
            scale = float(exact)
            table[2 * k] = np.float64(float(exact / scale - 1)).view(np.uint64)
            table[2 * k + 1] = np.float64(scale).view(np.uint64) - np.uint64(k << 45)
    return table


EXP_TABLE = _exp_table()


@numba.njit(cache=True, inline="always", error_model="numpy")
def _exponent_field(x: float) -> Any:
    """The biased exponent of x (uint64; 0x7FF for inf and NaN)."""
    return (float_bits(x) >> np.uint64(52)) & np.uint64(0x7FF)


@numba.njit(cache=True, inline="always", error_model="numpy")
def _usual(x: float) -> bool:
    """Whether 2^-54 ≤ |x| < 512 (``EXP_TOP_*``), where ``_exp_usual`` is libm's exp."""
    span = np.uint64(EXP_TOP_HUGE - EXP_TOP_LOW)
    return bool((_exponent_field(x) - np.uint64(EXP_TOP_LOW)) < span)


@numba.njit(cache=True, inline="always", error_model="numpy")
def _exp_usual(x: float) -> float:
    """e^x as glibc's exp computes it (FMA variant) for 2^-54 ≤ |x| < 512, bit for bit."""
    shifted = fma(x, EXP_INV_LN2_N, EXP_SHIFT)  # k in the low bits, rounded to nearest
    k_bits = float_bits(shifted)
    k = shifted - EXP_SHIFT
    r = fma(k, EXP_NEG_LN2_LO_N, fma(k, EXP_NEG_LN2_HI_N, x))  # x − k·ln2/N
    at = np.uint64(2) * (k_bits & np.uint64(127))
    tail = bits_float(EXP_TABLE[at])
    scale = bits_float(EXP_TABLE[at + np.uint64(1)] + (k_bits << np.uint64(45)))
    r2 = r * r
    low = fma(fma(r, EXP_C3, EXP_C2), r2, tail + r)
    result = fma(r2 * r2, fma(r, EXP_C5, EXP_C4), low)  # tail + e^r − 1
    return fma(scale, result, scale)


@numba.njit(cache=True, inline="always", error_model="numpy")
def _exp_huge(x: float) -> bool:
    """Whether |x| ≥ 512, inf or NaN (``EXP_TOP_HUGE``)."""
    return bool(_exponent_field(x) >= np.uint64(EXP_TOP_HUGE))


@numba.njit(cache=True, error_model="numpy")
def _libm_exp(x: float) -> float:
    """libm's exp (the call the ufunc ``exp`` makes)."""
    return math.exp(x)


@numba.njit(cache=True, inline="always", error_model="numpy")
def _in_chunks(x: Any, out: Any, usual: Any, value: Any, libm: Any, huge_of: Any) -> bool:
    """out = f(x) for float64 vectors, chunk by chunk (``EXP_CHUNK``): a chunk whose arguments
    are all ``usual`` takes ``value`` in a loop the compiler vectorizes; another takes it too,
    then ``libm`` (the C library's f) replaces the unusual entries (read from a copy, so ``out``
    may be ``x``). Returns whether an unusual argument was ``huge_of`` (one whose result numpy
    may warn about, which no kernel does)."""
    huge = False
    held = np.empty(EXP_CHUNK)
    n = x.shape[0]
    for start in range(0, n, EXP_CHUNK):
        xs = x[start : min(start + EXP_CHUNK, n)]
        os = out[start : min(start + EXP_CHUNK, n)]
        outside = 0
        for i in range(xs.shape[0]):
            outside += 0 if usual(xs[i]) else 1
        if outside == 0:
            for i in range(xs.shape[0]):
                os[i] = value(xs[i])
            continue
        kept = held[: xs.shape[0]]
        kept[:] = xs
        for i in range(kept.shape[0]):  # every entry in the vector loop, then the exceptions
            os[i] = value(kept[i])
        for i in range(kept.shape[0]):
            argument = kept[i]
            if not usual(argument):
                os[i] = libm(argument)
                huge = huge or huge_of(argument)
    return huge


@kernel("boolean(float64[::1], float64[::1])")
def exp_into(x: Any, out: Any) -> bool:
    """out = e^x for float64 vectors ((n,) → (n,)), the same bits as ``exp`` (libm's exp with
    FMA); ``out`` may be ``x`` (``_in_chunks``: ``_exp_usual`` where 2^-54 ≤ |x| < 512, libm's
    exp for 0, a tiny, a huge, inf or NaN). Returns whether an argument was huge, infinite or
    NaN: the one kind whose result numpy may warn about (overflow; ``exp_array``)."""
    return _in_chunks(x, out, _usual, _exp_usual, _libm_exp, _exp_huge)


def _through(kernel_into: Any, ufunc: np.ufunc, x: Any) -> Any:
    """``ufunc(x)`` by ``kernel_into`` where it can: a float64 array (any shape) whose arguments
    the kernel reports none of that may warn; anything else (scalars, other types, such an
    argument) by the ufunc itself, so numpy's warnings (errors in the service) are as before."""
    if type(x) is np.ndarray and x.dtype == np.float64 and x.size > 1:
        flat = np.ascontiguousarray(x).reshape(-1)
        out = np.empty(flat.shape[0])
        if not kernel_into(flat, out):
            return out.reshape(x.shape)
    return ufunc(x)


def exp_array(x: Any) -> Any:
    """e^x elementwise with ``exp``'s bits and warnings (any shape → the same shape), through
    ``exp_into``'s vector loop for a float64 array with no argument of 512 or more."""
    return _through(exp_into, exp, x)


# --- cosh a block at a time: glibc's cosh on ``_exp_usual`` (``cosh_into``) ---
#
# glibc's cosh (``e_cosh.c``, compiled without FMA: ``objdump -d`` shows mulsd, divsd, addsd)
# branches on |x|: up to ≈ ½ln2 it takes expm1 (libm's call here), below 22 it returns
# ½·t + ½/t with t = exp(|x|) (the FMA variant above: the same ifunc), from 22 on ½·t.

#: The least |x| of glibc's ½·t + ½/t branch (its high word 0x3FD62E43, the first above ½ln2's).
COSH_EXP_LEAST = float(np.array([0x3FD62E43 << 32], dtype=np.uint64).view(np.float64)[0])
#: Where glibc's cosh turns to ½·e^|x|; and the end of ``_exp_usual``'s range.
COSH_HALF_FROM, COSH_USUAL_BELOW = 22.0, 512.0


@numba.njit(cache=True, inline="always", error_model="numpy")
def _cosh_usual(x: float) -> float:
    """cosh x as glibc computes it for COSH_EXP_LEAST ≤ |x| < 512, bit for bit."""
    a = abs(x)
    t = _exp_usual(a)
    return 0.5 * t + 0.5 / t if a < COSH_HALF_FROM else 0.5 * t


@numba.njit(cache=True, inline="always", error_model="numpy")
def _cosh_in_range(x: float) -> bool:
    """Whether COSH_EXP_LEAST ≤ |x| < 512, where ``_cosh_usual`` is libm's cosh."""
    a = abs(x)
    return bool((a >= COSH_EXP_LEAST) & (a < COSH_USUAL_BELOW))


@numba.njit(cache=True, inline="always", error_model="numpy")
def _cosh_huge(x: float) -> bool:
    """Whether |x| ≥ 512, inf or NaN."""
    return not abs(x) < COSH_USUAL_BELOW


@numba.njit(cache=True, error_model="numpy")
def _libm_cosh(x: float) -> float:
    """libm's cosh (the call the ufunc ``cosh`` makes)."""
    return math.cosh(x)


@kernel("boolean(float64[::1], float64[::1])")
def cosh_into(x: Any, out: Any) -> bool:
    """out = cosh x for float64 vectors ((n,) → (n,)), the same bits as ``cosh``; ``out`` may be
    ``x`` (``_in_chunks``: ``_cosh_usual`` where COSH_EXP_LEAST ≤ |x| < 512, libm's cosh for
    the others). Returns whether an |x| was 512 or more, infinite or NaN (what numpy may warn
    about: ``cosh_array``)."""
    return _in_chunks(x, out, _cosh_in_range, _cosh_usual, _libm_cosh, _cosh_huge)


def cosh_array(x: Any) -> Any:
    """cosh x elementwise with ``cosh``'s bits and warnings (any shape → the same shape), through
    ``cosh_into``'s vector loop for a float64 array with no |argument| of 512 or more."""
    return _through(cosh_into, cosh, x)
