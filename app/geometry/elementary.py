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
"""

from __future__ import annotations

import math

from app.geometry.compiled import compiled_ufunc

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
