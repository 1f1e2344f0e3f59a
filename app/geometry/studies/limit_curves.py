"""Theorems 14 and 15: smooth curves through the vertices of (14) and (16), and their limits.

These are *theorems*: formulas the paper proves. The discrete curves themselves come from the
construction (D4b) in ``kinematic_tractrix``; nothing here calls it, so comparing the two tests
the theorems.

Theorem 14 interpolates the discrete hyperbolic cosine (14) by
  c(x) = (x, (h−d)^{(x+d)/(2d)} / (2(h+d)^{(x−d)/(2d)})
             + (h+d)^{(x+d)/(2d)} / (2(h−d)^{(x−d)/(2d)})),
which passes through p_i at x = (2i − 1)d. With a = artanh(d/h)/d (so 2ad = ln((h+d)/(h−d)))
it is c(x) = (x, √(h² − d²) cosh(a x)), and as d → 0 it tends to the catenary (x, h cosh(x/h)).

Theorem 15 interpolates the discrete tractrix (16) by
  c(x) = (h((h−d)^t − (h+d)^t)/((h−d)^t + (h+d)^t) + x + d, 2h(h² − d²)^{t/2}/((h−d)^t + (h+d)^t))
with t = (x + d)/d; it passes through d_i at x = (2i − 1)d, is
c(x) = (x + d − h tanh(a(x + d)), h / cosh(a(x + d))), and tends to the tractrix
T(x) = (x − h tanh(x/h), h / cosh(x/h)) of (S4), whose tangent at T(x) meets the x-axis at (x, 0).

The ``*_printed`` functions evaluate the formulas as printed, powers included (in float64 they
overflow for large exponents; the callers drop those points and say so). The other forms are
the algebraically equal ones in cosh and tanh, accurate for every representable value; the
refinement studies (``convergence``) use those.
"""

from __future__ import annotations

from app.geometry.precision import Arithmetic, Array, Scalar, stack_points


def rate(ar: Arithmetic, h: Scalar, d: Scalar) -> Scalar:
    """a = artanh(d/h)/d = ln((h+d)/(h−d))/(2d), the exponent rate of (14) and (16) per unit x."""
    return ar.atanh(d / h) / d


def catenary(ar: Arithmetic, h: Scalar, x: Array) -> Array:
    """(S1), the limit of Theorem 14: x ↦ (x, h cosh(x/h)); ``(n,) -> (n, 2)``."""
    return stack_points(x, h * ar.cosh(x / h))


def tractrix(ar: Arithmetic, h: Scalar, s: Array) -> Array:
    """(S4), the limit of Theorem 15: s ↦ (s − h tanh(s/h), h / cosh(s/h)); ``(n, 2)``."""
    return stack_points(s - h * ar.tanh(s / h), h / ar.cosh(s / h))


def theorem_14_curve(ar: Arithmetic, h: Scalar, d: Scalar, x: Array) -> Array:
    """Theorem 14's curve c(x) in the form (x, √(h² − d²) cosh(a x)); ``(n,) -> (n, 2)``."""
    return stack_points(x, ar.sqrt((h - d) * (h + d)) * ar.cosh(rate(ar, h, d) * x))


def theorem_14_curve_printed(ar: Arithmetic, h: Scalar, d: Scalar, x: Array) -> Array:
    """Theorem 14's c(x) as printed, with the powers (h ± d)^{(x ± d)/(2d)}; ``(n, 2)``."""
    up, down = (x + d) / (2 * d), (x - d) / (2 * d)
    pw = ar.power
    y = pw(h - d, up) / (2 * pw(h + d, down)) + pw(h + d, up) / (2 * pw(h - d, down))
    return stack_points(x, y)


def theorem_14_curve_rearranged(ar: Arithmetic, h: Scalar, d: Scalar, x: Array) -> Array:
    """The proof of Theorem 14: c(x) with the factors h(1 ∓ d/h)^{(x+d)/(2d)} / (2(1 ± d/h)^…)."""
    up, down = (x + d) / (2 * d), (x - d) / (2 * d)
    minus, plus = 1 - d / h, 1 + d / h
    pw = ar.power
    y = h * pw(minus, up) / (2 * pw(plus, down)) + h * pw(plus, up) / (2 * pw(minus, down))
    return stack_points(x, y)


def power_21(ar: Arithmetic, h: Scalar, d: Scalar, x: Array) -> Array:
    """The left side of (21) before the limit: (1 − d/h)^{(x+d)/(2d)}."""
    return ar.power(1 - d / h, (x + d) / (2 * d))


def power_21_substituted(ar: Arithmetic, h: Scalar, d: Scalar, x: Array) -> Array:
    """(21) after replacing d by x/D: (1 − x/(hD))^{D/2} (1 − x/(hD))^{1/2}; x ≠ 0."""
    big_d = x / d
    base = 1 - x / (h * big_d)
    return ar.power(base, big_d / 2) * base**0.5


def limit_21(ar: Arithmetic, h: Scalar, x: Array) -> Array:
    """The right side of (21): e^{−x/(2h)}."""
    return ar.exp(-x / (2 * h))


def theorem_15_curve(ar: Arithmetic, h: Scalar, d: Scalar, x: Array) -> Array:
    """Theorem 15's curve c(x) = (x + d − h tanh(a(x+d)), h / cosh(a(x+d))); ``(n, 2)``."""
    u = rate(ar, h, d) * (x + d)
    return stack_points(x + d - h * ar.tanh(u), h / ar.cosh(u))


def theorem_15_curve_printed(ar: Arithmetic, h: Scalar, d: Scalar, x: Array) -> Array:
    """Theorem 15's c(x) as printed, with the powers (h ± d)^{(x+d)/d}; ``(n, 2)``."""
    t = (x + d) / d
    minus, plus = ar.power(h - d, t), ar.power(h + d, t)
    first = h * (minus - plus) / (minus + plus) + x + d
    second = 2 * h * ar.power(h * h - d * d, t / 2) / (minus + plus)
    return stack_points(first, second)


def substitution_15_y(
    ar: Arithmetic, h: Scalar, d: Scalar, x: Array, printed: bool = False
) -> tuple[Array, Array]:
    """(f(d), g(d)) of the proof of Theorem 15 for the y-component, where 2h/(f + g) = c^y(x).

    Corrected (E80): f(d) = ((1 − d/h)/(1 + d/h))^{(x+d)/(2d)} and g(d) = 1/f(d). Printed:
    f(d) = (1 − d/h)/(1 + d/h), g(d) = 1/f(d) (constants, without the exponent).
    """
    ratio = (1 - d / h) / (1 + d / h)
    f = ratio + 0 * x if printed else ratio ** ((x + d) / (2 * d))
    return f, 1 / f


def substitution_15_x(
    ar: Arithmetic, h: Scalar, d: Scalar, x: Array, printed: bool = False
) -> tuple[Array, Array]:
    """(f(d), g(d)) of the proof of Theorem 15 for the x-component, (g − f)/(g + f) = ….

    Corrected (E81): f(d) = (1 − d/h)^{(x+d)/d}, g(d) = (1 + d/h)^{(x+d)/d}, so that
    h(g − f)/(g + f) = x + d − c^x(x). Printed: f(d) = 1 − d/h, g(d) = 1 + d/h.
    """
    zero = 0 * x
    if printed:
        return 1 - d / h + zero, 1 + d / h + zero
    t = (x + d) / d
    return (1 - d / h) ** t, (1 + d / h) ** t


def limits_15(ar: Arithmetic, h: Scalar, x: Array) -> tuple[Array, Array]:
    """The limits (f, g) = (e^{−x/h}, e^{x/h}) of both substitutions as d → 0 (by (21))."""
    return ar.exp(-x / h), ar.exp(x / h)
