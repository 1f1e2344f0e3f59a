"""Closed form of the hanging chain (D1) with constant spacing (a theorem; not in the paper).

Write the slope of edge i as m_i = sinh u_i. Since sinh a − sinh b = 2 cosh((a+b)/2) sinh((a−b)/2)
and cosh a + cosh b = 2 cosh((a+b)/2) cosh((a−b)/2), (D1) divided by δ,
m_{i+1} − m_i = c(cosh u_i + cosh u_{i+1}), becomes

    tanh((u_{i+1} − u_i)/2) = c,    so    u_i = u_0 + iE  with  E = 2 artanh c.

Summing the slopes,
Σ_{k=0}^{i−1} sinh(u_0 + kE) = (cosh(u_0 + (i − ½)E) − cosh(u_0 − E/2)) / (2 sinh(E/2)),
and sinh(E/2) = c/√(1 − c²), so every (D1) polygon is a sampled, vertically shifted catenary:

    y_i = C + a cosh(u_0 + (i − ½)E),   a = δ√(1 − c²)/(2c),   C = y_0 − a cosh(u_0 − E/2),

with u_0 = arsinh((y_1 − y_0)/δ). The offset C is free: (D1) only sees differences of heights.
Evaluated as written, C + a cosh(…) cancels badly when a ≫ |y| (small c: a nearly straight
chain), so the service uses the equivalent product form of the same sum,

    y_i = y_0 + 2a sinh(iE/2) sinh(u_0 + (i − 1)E/2),

with the product of the sinh taken through logarithms (no overflow where y_i is representable).
A (D1) polygon satisfies (D3) exactly when C = 0 (then A_i = (δ/(2c)) l_i, see
``area_length_closed_forms``), and eq. (2) then holds with 2c²/δ.

Nothing here calls the construction (``hanging_chain``): comparing the two tests this theorem.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from app.geometry.d4b.closed_forms import amplitude_cosh
from app.geometry.precision import Arithmetic, Array, Scalar


@dataclass(frozen=True)
class ChainParameters:
    """The constants of the closed form for given c, δ, y_0, y_1."""

    step: Scalar
    """E = 2 artanh c, the growth of the hyperbolic angle per edge."""
    amplitude: Scalar
    """a = δ√(1 − c²)/(2c)."""
    angle: Scalar
    """u_0 = arsinh((y_1 − y_0)/δ), the hyperbolic angle of edge 0."""
    offset: Scalar
    """C = y_0 − a cosh(u_0 − E/2); (D3) holds exactly when C = 0."""


def parameters(ar: Arithmetic, c: Scalar, delta: Scalar, y0: Scalar, y1: Scalar) -> ChainParameters:
    """E, a, u_0 and C of the closed form."""
    step = 2 * ar.atanh(c)
    amplitude = delta * ar.sqrt((1 - c) * (1 + c)) / (2 * c)
    angle = ar.asinh((y1 - y0) / delta)
    offset = y0 - amplitude_cosh(ar, amplitude, angle - step / 2)
    return ChainParameters(step, amplitude, angle, offset)


def hyperbolic_cosine(
    ar: Arithmetic, c: Scalar, delta: Scalar, y0: Scalar, y1: Scalar, i: Array
) -> tuple[Array, Array]:
    """p_i = (iδ, y_0 + 2a sinh(iE/2) sinh(u_0 + (i − 1)E/2)) and the size of its terms.

    ``(n, 2)`` and ``(n,)``; the size |iδ| + |y_0| + |2a sinh(…) sinh(…)| adds up the numbers
    the value is computed from. Elementwise in i (``Arithmetic.columns``).
    """
    k = parameters(ar, c, delta, y0, y1)
    half = k.step / 2
    factor = 2 * k.amplitude
    start = k.angle - half

    def kernel(i: Array) -> tuple[Array, Array, Array]:
        rise = sinh_product(ar, factor, half * i, start + half * i)
        x = delta * i
        return x, y0 + rise, abs(x) + abs(y0) + abs(rise)

    table = ar.columns(kernel, 3, i)
    return table[:, :2], table[:, 2]


def sinh_product(ar: Arithmetic, factor: Scalar, a: Array, b: Array) -> Array:
    """factor · sinh(a) · sinh(b) for factor > 0, finite whenever the value is representable.

    Directly where that is finite (always in mp); otherwise through log|sinh|:
    log|sinh x| = |x| − ln 2 + ln(−expm1(−2|x|)), accurate for every x (expm1 keeps small |x|
    exact to rounding, and −expm1 → 1 without overflow for large |x|; x = 0 gives −∞, so 0).
    """
    if not ar.may_overflow:
        return factor * ar.sinh(a) * ar.sinh(b)
    with np.errstate(over="ignore", invalid="ignore"):
        direct = factor * ar.sinh(a) * ar.sinh(b)
    if ar.all_finite(direct):
        return direct
    with np.errstate(divide="ignore"):
        logs = _log_abs_sinh_plus_ln2(ar, a) + _log_abs_sinh_plus_ln2(ar, b)
        logs += ar.log(factor / 4)
        return _sign(a) * _sign(b) * ar.exp(logs)


def _log_abs_sinh_plus_ln2(ar: Arithmetic, x: Array) -> Array:
    """log|sinh x| + ln 2 = |x| + ln(−expm1(−2|x|)), one expm1 and one log per entry."""
    v = abs(x)
    return v + ar.log(-ar.expm1(-2 * v))


def _sign(x: Array) -> np.ndarray[Any, np.dtype[np.int64]]:
    return np.asarray(x > 0, dtype=np.int64) - np.asarray(x < 0, dtype=np.int64)
