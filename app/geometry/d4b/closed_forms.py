"""Closed forms and recursions that Section 4.2 proves for (D4b): eq. (13), (14) and (16).

These are the *theorems*; ``kinematic_tractrix`` is the *definition*. Nothing here calls the
construction, so comparing the two is a real test of Theorems 5 and 6.

Stable forms. With L = ln((h+d)/(h−d)) = 2 artanh(d/h), the printed power forms are
  (14)  p_i^y = (h−d)^i / (2(h+d)^{i−1}) + (h+d)^i / (2(h−d)^{i−1}) = √(h²−d²) cosh((i − ½)L),
  (16)  d_i   = (−h tanh(iL) + 2di,  h / cosh(iL)).
The powers overflow or underflow in float64 long before the values do (e.g. (h+d)^i for h = 100
overflows at i ≈ 154 while p_i^y ≈ 100·1.02^i), so the functions below evaluate a·cosh(u) and
a/cosh(u) with cosh of the exponent (finite for |u| < 710), falling back to
exp(ln(a/2) + |u|)·(1 + e^{−2|u|}) and exp(ln(2a) − |u|)/(1 + e^{−2|u|}) beyond: accurate for
every index whose value is representable.

Tilted start (an extension, not in the paper): for a first stick at angle β0 the construction is
the vertical one advanced by the non-integer index τ = ln(tan(β0/2))/L, so p_i and d_i are
(14) and (16) at i + τ, translated back by 2dτ along the x-axis. τ = 0 for β0 = π/2.
"""

from __future__ import annotations

from typing import Any

import flint
import numba
import numpy as np

from app.geometry.compiled import kernel
from app.geometry.d4b import arb_checks
from app.geometry.precision import Arithmetic, Array, Scalar, stack_points


def log_ratio(ar: Arithmetic, h: Scalar, d: Scalar) -> Scalar:
    """L = ln((h+d)/(h−d)) = 2 artanh(d/h), the growth exponent of (14) and (16).

    Evaluated as log1p(2d/(h − d)): accurate for small d/h (where ln of a ratio near 1 is not)
    and for d near h (where artanh of the rounded d/h is off by κ·eps, κ = h²/(h² − d²);
    h − d is exact there).
    """
    return ar.log1p(2 * d / (h - d))


def tilt_shift(ar: Arithmetic, h: Scalar, d: Scalar, beta0: float | None) -> Scalar:
    """τ = artanh(−cos β0)/L = ln(tan(β0/2))/L, the index shift of a tilted first stick.

    0 for the vertical stick. The logarithmic form stays finite for β0 within an ulp of 0 or π,
    where −cos β0 rounds to ±1.
    """
    if beta0 is None:
        return ar.scalar(0)
    half = ar.scalar(beta0) / 2
    return ar.log(ar.sin(half) / ar.cos(half)) / log_ratio(ar, h, d)


def amplitude_cosh(ar: Arithmetic, a: Scalar, u: Array) -> Array:
    """a·cosh(u) for a > 0 (scalar or array), finite whenever the value is representable.

    Directly (one cosh, one product) wherever cosh(u) is finite: always in mp, and for
    |u| < 710 in float64, which covers every float64 range the service accepts (coordinates stay
    below 1e150). Otherwise through E = (a/2)·e^{|u|} = exp(ln(a/2) + |u|):
    a·cosh(u) = E + (a/2)·((a/2)/E), finite while the value is.
    """
    if not ar.may_overflow:
        return a * ar.cosh(u)
    with np.errstate(over="ignore"):
        c = ar.cosh(u)
    if ar.all_finite(c):
        return a * c
    half = a / 2
    e = ar.exp(abs(u) + ar.log(half))
    return e + half * (half / e)


def amplitude_sech(ar: Arithmetic, a: Scalar, u: Array) -> Array:
    """a / cosh(u) for a > 0, without overflow of cosh and with gradual underflow.

    Directly where cosh(u) is finite; otherwise as exp(ln(2a) − |u|)/(1 + e^{−2|u|}).
    """
    if not ar.may_overflow:
        return a / ar.cosh(u)
    with np.errstate(over="ignore"):
        c = ar.cosh(u)
    if ar.all_finite(c):
        return a / c
    v = abs(u)
    return ar.exp(ar.log(2 * a) - v) / (1 + ar.exp(-2 * v))


def tanh_and_sech(ar: Arithmetic, t: Array) -> tuple[Array, Array]:
    """(tanh t, 1/cosh t): sinh(t)·(1/cosh t) and 1/cosh t where cosh t is finite (one cosh,
    one sinh, one division: cheaper than tanh), else tanh and ``amplitude_sech``.

    Both forms are accurate to a few units of the precision for every t (sinh keeps small |t|
    relative, and the quotient tends to ±1 for large |t|).
    """
    if ar.may_overflow:
        with np.errstate(over="ignore"):
            c = ar.cosh(t)
        if not ar.all_finite(c):
            return ar.tanh(t), amplitude_sech(ar, ar.scalar(1), t)
    else:
        c = ar.cosh(t)
    sech = 1 / c
    return ar.sinh(t) * sech, sech


def hyperbolic_cosine(ar: Arithmetic, h: Scalar, d: Scalar, i: Array, shift: Scalar) -> Array:
    """Theorem 5, eq. (14): p_i = ((2i−1)d, √(h²−d²) cosh((i − ½ + τ)L)); ``(n,) -> (n, 2)``.

    Elementwise in i (``Arithmetic.points``: float64 runs it in cache-sized blocks).
    """
    L = log_ratio(ar, h, d)
    amplitude = ar.sqrt((h - d) * (h + d))
    offset = (shift - 0.5) * L
    step = 2 * d

    def kernel(i: Array) -> tuple[Array, Array]:
        u = i * L
        u += offset
        x = i * step
        x -= d
        return x, amplitude_cosh(ar, amplitude, u)

    return ar.points(kernel, i)


def tractrix(ar: Arithmetic, h: Scalar, d: Scalar, i: Array, shift: Scalar) -> Array:
    """Theorem 6, eq. (16): d_i = (−h tanh((i+τ)L) + 2di, h / cosh((i+τ)L)); ``(n, 2)``.

    tanh and 1/cosh from one cosh and one sinh (``tanh_and_sech``), accurate for small and large
    |t| alike and without overflow. Elementwise in i (``Arithmetic.points``).
    """
    L = log_ratio(ar, h, d)
    offset = shift * L
    step = 2 * d

    def kernel(i: Array) -> tuple[Array, Array]:
        t = i * L
        t += offset
        tanh, sech = tanh_and_sech(ar, t)
        x = i * step
        x -= h * tanh
        return x, h * sech

    return ar.points(kernel, i)


def kinematic_balls(
    ar: Arithmetic, h: Scalar, d: Scalar, i: Array, shift: Scalar
) -> tuple[Array, Array] | None:
    """Theorems 5 and 6 together on balls: (``hyperbolic_cosine``, ``tractrix``) at ``i`` from
    one exponential per index, in one compiled pass (``arb_checks.closed_kinematics``); None
    off balls (the two functions above then run apart).

    With E = e^t, t = (i + τ)L: tanh t = 1 − 2/(E² + 1) and sech t = 2/(E + 1/E) (the forms
    Section 5's Gauss images take, ``curvature._BallHyperbolic``: no difference of close
    numbers, so the radii stay near those of a tanh and a 1/cosh), and e^u = E·√((h−d)/(h+d))
    for u = t − L/2, so cosh u = (e^u + 1/e^u)/2. Rigorous balls of the same numbers as the two
    functions' cosh and sinh, one exponential in place of three functions (about 2.5 ms less
    for 1001 indices at 50 digits); not the same bits (their radii differ in the last units).
    """
    if not (
        ar.certified
        and not ar.may_overflow
        and type(h) is flint.arb
        and type(d) is flint.arb
        and type(shift) is flint.arb
        and isinstance(i, np.ndarray)
        and i.ndim == 1
        and arb_checks.balls(i)
    ):
        return None
    L = log_ratio(ar, h, d)
    constants = [
        L,
        shift * L,
        ar.sqrt((h - d) / (h + d)),  # e^{−L/2}
        2 * d,
        d,
        h,
        ar.sqrt((h - d) * (h + d)),
        flint.arb(1),
        flint.arb(2),
        flint.arb(0.5),
    ]
    ar.check_time()  # where the elementwise functions read the clock
    return arb_checks.closed_kinematics(i, constants)


def hyperbolic_cosine_printed(ar: Arithmetic, h: Scalar, d: Scalar, i: Array) -> Array:
    """Eq. (14) exactly as printed, with powers (overflows early in float64; see module doc)."""
    pw = ar.power
    y = pw(h - d, i) / (2 * pw(h + d, i - 1)) + pw(h + d, i) / (2 * pw(h - d, i - 1))
    return stack_points((2 * i - 1) * d, y)


def tractrix_printed(ar: Arithmetic, h: Scalar, d: Scalar, i: Array) -> Array:
    """Eq. (16) exactly as printed, with powers (overflows early in float64)."""
    a, b = ar.power(h - d, 2 * i), ar.power(h + d, 2 * i)
    return stack_points(
        h * (a - b) / (a + b) + 2 * d * i, 2 * h * ar.power(h * h - d * d, i) / (a + b)
    )


def recursion_13(d: Scalar, before: Array, current: Array) -> Array:
    """Eq. (13): p_{i+1}^y from p_{i−1}^y and p_i^y.

    (p_i³ + 2d²p_i + d²p_{i−1}) / (p_i p_{i−1} − d²), numerator and denominator divided by
    p_i p_{i−1} so that no cube overflows.
    """
    a, b = before, current
    return (b * (b / a) + 2 * d * (d / a) + d * (d / b)) / (1 - (d / a) * (d / b))


def two_step(d: Scalar, before: Array, current: Array) -> Array:
    """p_{i+2}^y from p_{i−1}^y, p_i^y: eq. (13) applied twice, simplified (corrected form).

    (b⁵ + d²(a³ + 2a²b + 3ab² + 4b³) + d⁴(2a + 3b)) / (ab − d²)² with a = p_{i−1}^y, b = p_i^y;
    evaluated divided by (ab)² against overflow.
    """
    a, b = before, current
    e = d / a
    f = d / b
    numerator = b * (b / a) * (b / a) + (d * f) * (a / b + 2 + 3 * (b / a) + 4 * (b / a) * (b / a))
    numerator = numerator + (d * e) * (e * f) * (2 * (a / b) + 3)
    return numerator / ((1 - e * f) * (1 - e * f))


def two_step_printed(d: Scalar, before: Array, current: Array) -> Array:
    """p_{i+2}^y as printed in the proof of Theorem 4 (with the spurious 2p_i^{y3} term)."""
    a, b = before, current
    numerator = (
        b**5
        + d**2 * (a**3 + 2 * a**2 * b + 3 * a * b**2 + 4 * b**3)
        + d**4 * (2 * b**3 + 2 * a + 3 * b)
    )
    return numerator / (d**2 - a * b) ** 2


# Section 5: the Gauss images of the pseudosphere and of the catenoid, eqs. (18)–(20).
# With t = (i + τ)L, the power forms reduce to hyperbolic functions: ((h+d)/(h−d))^i = e^{iL}, so
# 2(h−d)^i(h+d)^i / ((h−d)^{2i} + (h+d)^{2i}) = sech(t) and
# ((h+d)^{2i} − (h−d)^{2i}) / ((h−d)^{2i} + (h+d)^{2i}) = tanh(t). The functions below evaluate
# these exact rewritings (no overflow); the tests compare them with the literal power forms.


def tractrix_gauss_image(ar: Arithmetic, h: Scalar, d: Scalar, i: Array, shift: Scalar) -> Array:
    """(18) corrected: n_i = (sech t, tanh t), t = (i+τ)L, the unit normal of stick i."""
    t = (i + shift) * log_ratio(ar, h, d)
    one = ar.scalar(1)
    return stack_points(amplitude_sech(ar, one, t), ar.tanh(t))


def tractrix_gauss_image_printed(
    ar: Arithmetic, h: Scalar, d: Scalar, i: Array, shift: Scalar
) -> Array:
    """(18) as printed: (2(h−d)^i(h+d)^i, (h−d)^{2i} − (h+d)^{2i}) / B = (sech t, −tanh t)."""
    t = (i + shift) * log_ratio(ar, h, d)
    one = ar.scalar(1)
    return stack_points(amplitude_sech(ar, one, t), -ar.tanh(t))


def normal_from_slope(ar: Arithmetic, k: Array) -> Array:
    """(18), first form, corrected: (1, k)/√(1 + k²), the unit vector of slope k = k_{i+1}."""
    q = ar.sqrt(1 + k * k)
    return stack_points(1 / q, k / q)


def normal_from_slope_printed(ar: Arithmetic, k: Array) -> Array:
    """(18), first form, as printed: (√(1/(1 + k²)), √(k²/(1 + k²))), which loses the sign of k."""
    return stack_points(ar.sqrt(1 / (1 + k * k)), ar.sqrt(k * k / (1 + k * k)))


def contact_points(ar: Arithmetic, h: Scalar, d: Scalar, i: Array, shift: Scalar) -> Array:
    """(19) corrected: ñ_i = (−tanh t, sech t), the unit normal of the edge p_i p_{i+1}."""
    t = (i + shift) * log_ratio(ar, h, d)
    one = ar.scalar(1)
    return stack_points(-ar.tanh(t), amplitude_sech(ar, one, t))


def contact_points_printed(ar: Arithmetic, h: Scalar, d: Scalar, i: Array, shift: Scalar) -> Array:
    """(19) as printed: ((h+d)^{2i} − (h−d)^{2i}, 2(h−d)^i(h+d)^i) / B = (tanh t, sech t)."""
    t = (i + shift) * log_ratio(ar, h, d)
    one = ar.scalar(1)
    return stack_points(ar.tanh(t), amplitude_sech(ar, one, t))


def circumscribed_gauss_image(
    ar: Arithmetic, h: Scalar, d: Scalar, i: Array, shift: Scalar
) -> Array:
    """(20) corrected: m_i = (dB − hA, 2h(h²−d²)^i)/(hB − dA) = (−tanh u, h/(a cosh u)).

    u = (i − ½ + τ)L and a = √(h² − d²), so m_i^y = h / p_i^y with p_i^y from (14).
    """
    u = (i - 0.5 + shift) * log_ratio(ar, h, d)
    amplitude = h / ar.sqrt((h - d) * (h + d))
    return stack_points(-ar.tanh(u), amplitude_sech(ar, amplitude, u))


def circumscribed_gauss_image_printed(
    ar: Arithmetic, h: Scalar, d: Scalar, i: Array, shift: Scalar
) -> Array:
    """(20) as printed, read as the column vector (hA − dB, 2h(h²−d²)^i) over dA + hB.

    Divided by B: ((h tanh t − d), h sech t) / (h + d tanh t), t = (i+τ)L.
    """
    t = (i + shift) * log_ratio(ar, h, d)
    tanh = ar.tanh(t)
    one = ar.scalar(1)
    denominator = h + d * tanh
    return stack_points((h * tanh - d) / denominator, h * amplitude_sech(ar, one, t) / denominator)


def pole_by_inversion(before: Array, after: Array) -> Array:
    """(20), first form: 2(ñ_{i−1} + ñ_i)/|ñ_{i−1} + ñ_i|², the midpoint inverted in the circle.

    float64 points in one compiled pass (``_pole_by_inversion``, the same operations), others
    with numpy.
    """
    if before.dtype == np.float64 and after.dtype == np.float64:
        return _pole_by_inversion(before, after)
    total = before + after
    squared = total[:, 0] * total[:, 0] + total[:, 1] * total[:, 1]
    return stack_points(2 * total[:, 0] / squared, 2 * total[:, 1] / squared)


@numba.njit(cache=True, inline="always", error_model="numpy")
def inversion_pole(bx: float, by: float, ax: float, ay: float) -> tuple[float, float]:
    """(20)'s pole of the chord from b to a, in float64: t = b + a, 2t/(t^x t^x + t^y t^y)."""
    tx = bx + ax
    ty = by + ay
    squared = tx * tx + ty * ty
    return 2 * tx / squared, 2 * ty / squared


@kernel("float64[:, :](float64[:, :], float64[:, :])")
def _pole_by_inversion(before: Any, after: Any) -> Any:
    """``pole_by_inversion`` row by row (``inversion_pole``)."""
    out = np.empty((before.shape[0], 2))
    for k in range(before.shape[0]):
        out[k, 0], out[k, 1] = inversion_pole(before[k, 0], before[k, 1], after[k, 0], after[k, 1])
    return out
