"""What Section 4.1 proves about (D2a): the formulas of the proofs of Theorems 1–3, (8)–(11).

These are the *theorems*; ``christoffel`` is the *definition*. Nothing here calls the
construction, so comparing the two is a real test. Each function takes the parameter line's
values f_{i−1}, f_i (quad) or the parameters a, b, λ and the indices (hexagonal) and returns the
printed quantity; where the transcription is wrong, the corrected form is implemented and the
printed one sits beside it with the suffix ``_printed`` (docs/errata.md, E40–E44).

Quad mesh, proof of Theorem 1 (f_{i−1} = ``f_prev``, f_i = ``f_cur``, all ``(m,)``):
    Δφ_{i−1} = −2(f_{i−1} − f_i)/((f_{i−1}² + 1)(f_i² + 1)) · (f_{i−1} + f_i, 1 − f_{i−1}f_i),
    ‖Δφ_{i−1}‖² = 4(f_{i−1} − f_i)²/((f_{i−1}² + 1)(f_i² + 1)),
    Δp_{i−1} = −1/(2(f_{i−1} − f_i)) · (f_{i−1} + f_i, 1 − f_{i−1}f_i),
    d = (f_{i−1} + f_i)/(2(f_i − f_{i−1})),   Δ²p_{i−1} = (0, −(f_i² + 1)/(2f_i))   [E41],
    (5) p_{i−1}^y = −(f_i + f_{i−1}²f_i)/(2(f_{i−1} − f_i)²), p_i^y, p_{i+1}^y, A_{i−1} + A_i,
    c = 4(f_i − f_{i−1})³/(f_{i−1} + f_i)³ > 0   [E42].
Hexagonal mesh, Theorem 3 (8), (9) [E43], the constants (11) and the start height r of the proof
of Theorem 2 [E44]. With s = b/a the printed powers a^{i/2}, b^{i/2}, (ab)^{−i/2} combine to
s^{±i/2}, which is how (8) and (9) are evaluated (the literal printed powers overflow in float64
long before the values do); the ``_printed`` functions keep the literal form.
"""

from __future__ import annotations

from app.geometry.precision import Arithmetic, Array, Scalar, stack_points

# ---------------------------------------------------------------------------------------------
# Quad mesh: the proof of Theorem 1


def quad_gauss_edge(f_prev: Array, f_cur: Array) -> Array:
    """Proof of Theorem 1: Δφ_{i−1} as printed (verified); ``(m,), (m,) -> (m, 2)``."""
    factor = -2 * (f_prev - f_cur) / ((f_prev * f_prev + 1) * (f_cur * f_cur + 1))
    return stack_points(factor * (f_prev + f_cur), factor * (1 - f_prev * f_cur))


def quad_gauss_edge_norm_squared(f_prev: Array, f_cur: Array) -> Array:
    """Proof of Theorem 1: ‖Δφ_{i−1}‖² = 4(f_{i−1} − f_i)²/((f_{i−1}² + 1)(f_i² + 1))."""
    g = f_prev - f_cur
    return 4 * g * g / ((f_prev * f_prev + 1) * (f_cur * f_cur + 1))


def quad_dual_edge(f_prev: Array, f_cur: Array) -> Array:
    """Proof of Theorem 1: Δp_{i−1} = −(f_{i−1} + f_i, 1 − f_{i−1}f_i)/(2(f_{i−1} − f_i))."""
    factor = -1 / (2 * (f_prev - f_cur))
    return stack_points(factor * (f_prev + f_cur), factor * (1 - f_prev * f_cur))


def quad_x_step(f_prev: Array, f_cur: Array) -> Array:
    """Proof of Theorem 1: the x-step d = (f_{i−1} + f_i)/(2(f_i − f_{i−1})) (corrected, E40)."""
    return (f_prev + f_cur) / (2 * (f_cur - f_prev))


def quad_x_step_printed(f_prev: Array, f_cur: Array) -> Array:
    """The shifted x-step as printed: (f_{i−1+j} + f_{i+j})/(2(f_{i−1+j} − f_{i+j})) (E40)."""
    return (f_prev + f_cur) / (2 * (f_prev - f_cur))


def quad_second_difference(f_cur: Array) -> Array:
    """Proof of Theorem 1: Δ²p_{i−1} = (0, −(f_i² + 1)/(2f_i)) (corrected sign, E41)."""
    return stack_points(0 * f_cur, -(f_cur * f_cur + 1) / (2 * f_cur))


def quad_second_difference_printed(f_cur: Array) -> Array:
    """Δ²p_{i−1} = (0, (f_i² + 1)/(2f_i)) as printed (E41)."""
    return stack_points(0 * f_cur, (f_cur * f_cur + 1) / (2 * f_cur))


def quad_equation_5(f_prev: Array, f_cur: Array) -> Array:
    """Eq. (5): p_{i−1}^y = −(f_i + f_{i−1}²f_i)/(2(f_{i−1} − f_i)²) (verified)."""
    g = f_prev - f_cur
    return -(f_cur + f_prev * f_prev * f_cur) / (2 * g * g)


def quad_height_next(f_prev: Array, f_cur: Array) -> Array:
    """Proof of Theorem 1: p_i^y = −(f_{i−1} + f_{i−1}f_i²)/(2(f_{i−1} − f_i)²) (verified)."""
    g = f_prev - f_cur
    return -(f_prev + f_prev * f_cur * f_cur) / (2 * g * g)


def quad_height_after(f_prev: Array, f_cur: Array) -> Array:
    """Proof of Theorem 1: p_{i+1}^y = −(f_{i−1}² + f_i⁴)/(2f_i(f_{i−1} − f_i)²) (verified)."""
    g = f_prev - f_cur
    square = f_cur * f_cur
    return -(f_prev * f_prev + square * square) / (2 * f_cur * g * g)


def quad_area_sum(f_prev: Array, f_cur: Array) -> Array:
    """Proof of Theorem 1: A_{i−1} + A_i = (f_{i−1}+f_i)³(1+f_i²)/(8f_i(f_{i−1}−f_i)³)."""
    s, g = f_prev + f_cur, f_prev - f_cur
    return s * s * s * (1 + f_cur * f_cur) / (8 * f_cur * g * g * g)


def theorem_1_constant(f0: Scalar, f1: Scalar) -> Scalar:
    """Theorem 1: c of eq. (2), 4(f_1 − f_0)³/(f_0 + f_1)³ > 0 (corrected sign, E42)."""
    g = (f1 - f0) / (f0 + f1)
    return 4 * g * g * g


def theorem_1_constant_printed(f0: Scalar, f1: Scalar) -> Scalar:
    """c = 4(f_{i−1} − f_i)³/(f_{i−1} + f_i)³ as printed (negative; E42)."""
    g = (f0 - f1) / (f0 + f1)
    return 4 * g * g * g


def theorem_1_radius(f0: Scalar, f1: Scalar) -> Scalar:
    """Theorem 1 holds for p_0^y = r* = −f_1(1 + f_0²)/(2(f_1 − f_0)²), eq. (5) at i = 1."""
    g = f1 - f0
    return -f1 * (1 + f0 * f0) / (2 * g * g)


# ---------------------------------------------------------------------------------------------
# Hexagonal mesh: Theorems 2 and 3


def _hex_denominator(a: Scalar, b: Scalar, lam: Scalar) -> Scalar:
    """2λ(a − b)²(λ − 1), the denominator of (8), (9) and of the start height r."""
    return 2 * lam * (a - b) * (a - b) * (lam - 1)


def _hex_constant(a: Scalar, b: Scalar, lam: Scalar) -> Scalar:
    """−3a³(λ−1)² + 5a²b(λ−1)λ − 2ab²λ² + b(λ−3), the constant term of (9)'s numerator."""
    m = lam - 1
    return (
        -3 * a * a * a * m * m + 5 * a * a * b * m * lam - 2 * a * b * b * lam * lam + b * (lam - 3)
    )


def theorem_3_x(a: Scalar, b: Scalar, lam: Scalar, i: Array, odd: bool) -> Array:
    """Theorem 3: p_i^x of (8) (i even) or (9) (i odd), as printed (verified)."""
    denominator = 4 * lam * (a - b) * (lam - 1)
    if odd:
        numerator = b * lam * (1 + 5 * i - lam * (5 + i)) + a * (lam - 1) * (
            lam * (5 + i) - 6 * (1 + i)
        )
        return numerator / denominator
    return i * (a * (lam - 6) * (lam - 1) - b * (lam - 5) * lam) / denominator


def theorem_3_y_even(
    ar: Arithmetic, a: Scalar, b: Scalar, lam: Scalar, r: Scalar, i: Array
) -> Array:
    """Theorem 3, (8) corrected (E43): p_i^y = r − (b^{−i/2} − a^{−i/2})(…)/D.

    The bracket is a^{i/2}b(λ−3) + a b^{i/2}W, W = (3a(λ−1) − 2bλ)(a(λ−1) − bλ),
    D = 2λ(a−b)²(λ−1); expanded with s = b/a as
    r + (C − s^{−i/2} b(λ−3) + s^{i/2} aW)/D, C the constant of (9).
    """
    w = (3 * a * (lam - 1) - 2 * b * lam) * (a * (lam - 1) - b * lam)
    log_s = ar.log(b / a)
    constant, denominator = _hex_constant(a, b, lam), _hex_denominator(a, b, lam)
    low, high = b * (lam - 3), a * w

    def kernel(i: Array) -> Array:
        half = i / 2
        numerator = constant - ar.exp(-half * log_s) * low
        numerator = numerator + ar.exp(half * log_s) * high
        return r + numerator / denominator

    return ar.values(kernel, i)


def theorem_3_y_even_printed(a: Scalar, b: Scalar, lam: Scalar, r: Scalar, i: Array) -> Array:
    """(8) for p_i^y exactly as printed, with literal powers (E43: the fraction's sign is wrong)."""
    h = i / 2
    w = (3 * a * (lam - 1) - 2 * b * lam) * (a * (lam - 1) - b * lam)
    numerator = (b ** (-h) - a ** (-h)) * (a**h * b * (lam - 3) + a * b**h * w)
    return numerator / _hex_denominator(a, b, lam) + r


def theorem_3_y_odd(
    ar: Arithmetic, a: Scalar, b: Scalar, lam: Scalar, r: Scalar, i: Array
) -> Array:
    """Theorem 3, (9) (verified): p_i^y = r + (C + s^{(1−i)/2}(2bλ − 3a(λ−1))
    + s^{(1+i)/2} a²(λ−3)(a(λ−1) − bλ))/D, the printed powers combined with s = b/a."""
    log_s = ar.log(b / a)
    constant, denominator = _hex_constant(a, b, lam), _hex_denominator(a, b, lam)
    low = 2 * b * lam - 3 * a * (lam - 1)
    high = a * a * (lam - 3) * (a * (lam - 1) - b * lam)

    def kernel(i: Array) -> Array:
        numerator = constant + ar.exp((1 - i) / 2 * log_s) * low
        numerator = numerator + ar.exp((1 + i) / 2 * log_s) * high
        return r + numerator / denominator

    return ar.values(kernel, i)


def theorem_3_y_odd_printed(
    ar: Arithmetic, a: Scalar, b: Scalar, lam: Scalar, r: Scalar, i: Array
) -> Array:
    """(9) for p_i^y exactly as printed, with literal powers (b/a)^{1/2}(ab)^{−i/2}a^i, b^i."""
    m = lam - 1
    factor = ar.sqrt(b / a) * (a * b) ** (-i / 2)
    bracket = a**i * (2 * b * lam - 3 * a * m) + a * a * (lam - 3) * b**i * (a * m - b * lam)
    numerator = _hex_constant(a, b, lam) + factor * bracket
    return numerator / _hex_denominator(a, b, lam) + r


def theorem_2_constants(a: Scalar, b: Scalar, lam: Scalar) -> tuple[Scalar, Scalar]:
    """Eq. (11): c_1 and c_2 of (7) (verified against (10) on the construction)."""
    c1 = (4 * lam * (a - b) * (3 * a * (lam - 1) + b * (7 * lam - 3))) / (
        3 * (a * (lam - 2) - b * lam) * (3 * a * (lam - 1) - b * (lam + 3))
    )
    c2 = (2 * (1 - lam) * (a - b) * (a * (4 * lam - 3) + b * lam)) / (
        (-a * lam + a + b * lam + b) * (a * (2 * lam - 3) - b * lam)
    )
    return c1, c2


def theorem_2_radius(a: Scalar, b: Scalar, lam: Scalar) -> Scalar:
    """Proof of Theorem 2: the start height r for which (7) holds, −C/(2λ(λ−1)(a−b)²) (E44)."""
    return -_hex_constant(a, b, lam) / _hex_denominator(a, b, lam)


def theorem_2_radius_printed(a: Scalar, b: Scalar, lam: Scalar) -> Scalar:
    """The start height as printed: [3a³(λ−1)² − … − b(λ−3)] / [2λ(λ−1)a − b]² (E44)."""
    denominator = 2 * lam * (lam - 1) * a - b
    return -_hex_constant(a, b, lam) / (denominator * denominator)
