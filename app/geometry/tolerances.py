"""One place for the tolerances and limits every check and representability guard shares.

Tolerances are multiples of the working precision (``Arithmetic.tolerance(steps)``, with the
safety factor ``precision.TOLERANCE_SAFETY`` per step); what differs between checks is how many
rounding steps a residual accumulates, and the constants here say how many.
"""

from __future__ import annotations

import math
from decimal import Context, Decimal
from fractions import Fraction
from typing import Any

from app.geometry.exact import ExactReal
from app.geometry.precision import GUARD_DIGITS, Arithmetic, Scalar

LOCAL_STEPS = 16
"""A local check combines a handful of neighbouring values: its tolerance allows this many
rounding steps (``ar.tolerance(LOCAL_STEPS)``)."""

FLOAT64_COORDINATE_LIMIT = 1e150
"""Float64 results keep every coordinate below this size, so that the checks, which multiply two
coordinates (areas, dot products), stay finite; beyond it a request is refused before any work
(use precision=mp)."""

RESOLUTION_MARGIN = 100
"""A second difference Δ²p^y of relative size r is resolved when r exceeds the working precision
by this factor squared (D4b: Δ²p^y/p^y ≈ (2d/h)², so d/h >= 100·√eps in float64)."""

MPMATH_FLOAT_DIGITS = 300
"""Most digits at which a check computed with mpmath (surfaces and smooth references in mp:
``MultiPrecision``, not balls) can decide: its residuals and tolerance are floats, and beyond
this their sizes (about 10^−(digits+10)) leave the float range; such a check is undecided."""

NOT_CONSTRUCTED = "method=closed-form: the construction was not run to compare"
"""The note of a construction-against-closed-form check when the closed form is all there is."""


# --- the unit of the precision, exact at any digits -------------------------------------------
# ``Arithmetic.eps`` and ``working_eps`` are floats: in mp 10^−digits is 0 from 324 digits on
# (its square from about 162), so a tolerance or guard built from them compares with 0 there.
# Guards and thresholds of the mp path use the numbers below instead; float64 keeps its floats
# (the same bits).

#: Decimal arithmetic for thresholds shown in messages: exponents beyond any working precision.
_SHOWN = Context(prec=2, Emin=-(10**9), Emax=10**9)


def unit(ar: Arithmetic) -> Scalar:
    """The unit of the requested precision as a number of ``ar``: float64's eps (2^−52) in
    float64; in mp 10^−digits at the working precision (a ball on balls), never 0."""
    if ar.mode == "float64":
        return ar.eps
    return ar.scalar(10) ** (-ar.digits)


def working_unit(ar: Arithmetic) -> Scalar:
    """As ``unit`` for the precision computed with (mp carries ``GUARD_DIGITS`` more)."""
    if ar.mode == "float64":
        return ar.working_eps
    return ar.scalar(10) ** (-(ar.digits + GUARD_DIGITS))


def log2_working_unit(ar: Arithmetic) -> float:
    """log2 of ``working_unit`` as a float (finite at any digits)."""
    if ar.working_eps > 0:
        return math.log2(ar.working_eps)
    return -(ar.digits + GUARD_DIGITS) * math.log2(10)


def exact(value: Any) -> Fraction:
    """A parameter as the exact rational mp computes with: the decimal the client wrote
    (``ExactReal``), a float's shortest decimal (as ``MultiPrecision.scalar`` reads it), an
    integer as itself."""
    if isinstance(value, ExactReal):
        return Fraction(value.text)
    if isinstance(value, float):
        return Fraction(repr(float(value)))  # numpy floats print their type in repr
    return Fraction(value)


def below_root_working_unit(ar: Arithmetic, ratio: Fraction, factor: int = 1) -> bool:
    """Whether ``ratio`` < factor·√(working unit), decided exactly (mp: 10^−(digits+guard))."""
    if ratio < 0:
        return True
    return ratio * ratio < Fraction(factor * factor, 10 ** (ar.digits + GUARD_DIGITS))


def root_working_unit_text(ar: Arithmetic, factor: int = 1) -> str:
    """factor·√(working unit) with two significant digits, as a message shows it (``1e-255``)."""
    root = (Decimal(factor * factor) * Decimal(10) ** -(ar.digits + GUARD_DIGITS)).sqrt(_SHOWN)
    return format(_SHOWN.normalize(root), ".2g")


def power_of_ten_text(exponent: int) -> str:
    """10^exponent as a message shows it (``1e-500``, ``0.1``, ``1``), at any exponent."""
    return format(Decimal(10) ** exponent, ".2g")
