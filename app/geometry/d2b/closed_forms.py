"""What Section 6 proves about (D2b): Theorem 11's proof, Lemma 10 and the limit curve.

These are the *theorems*; ``vanishing_mean_curvature`` is the *definition*:

- proof of Theorem 11: H = 0 in (17) telescopes to p_i^y = 1/n_i^y (p_0^y = n_0^y = 1), and
  parallel edges give p_i^x = p_{i−1}^x + Δp_{i−1}^y Δn_{i−1}^x / Δn_{i−1}^y;
- Lemma 10: p_i = (Σ_{k=0}^{i−1} t_k, (1 − s_i²)^{−1/2}) with
  t_k = (s_k − s_{k+1}) / ((1 − s_k²)^{1/2} (1 − s_{k+1}²)^{1/2}), the sum read with the usual
  convention Σ_{k=0}^{i−1} = −Σ_{k=i}^{−1} for i < 0 (the printed convention is wrong, E64);
- the limit: p_i^j is close to c(i/j), c(t) = (−artanh g(t), (1 − g(t)²)^{−1/2}), a point of
  the catenary C = {(x, cosh x)}; for the named sequences artanh g has the closed forms
  ½ ln(1 + 8t²) (Example 12, g(t) = 4t²/(1 + 4t²)) and ½ ln(1 + 2t) (Remark 13, g(t) = t/(1 + t)).
"""

from __future__ import annotations

import numpy as np

from app.geometry.precision import Arithmetic, Array, stack_points


def radii(ar: Arithmetic, n_y: Array) -> Array:
    """Proof of Theorem 11: p_i^y = 1/n_i^y (telescoping p_{i+1}^y n_{i+1}^y = p_i^y n_i^y)."""
    return 1 / n_y


def recursion_x_defect(p: Array, n: Array) -> Array:
    """Proof of Theorem 11, p_i^x = p_{i−1}^x + Δp_{i−1}^y Δn_{i−1}^x / Δn_{i−1}^y, multiplied
    by Δn_{i−1}^y: (p_i^x − p_{i−1}^x) Δn_{i−1}^y − Δp_{i−1}^y Δn_{i−1}^x, 0 when it holds.

    Multiplied out because Δn^y can vanish in float64 (s_1 ≈ 4/j² for Example 12); ``(N−1,)``.
    """
    dp = p[1:] - p[:-1]
    dn = n[1:] - n[:-1]
    return dp[:, 0] * dn[:, 1] - dp[:, 1] * dn[:, 0]


def lemma_10_terms(ar: Arithmetic, s: Array, one_minus_s2: Array) -> Array:
    """t_k = (s_k − s_{k+1}) / ((1 − s_k²)^{1/2}(1 − s_{k+1}²)^{1/2}) of Lemma 10; ``(N−1,)``."""
    root = ar.sqrt(one_minus_s2)
    return (s[:-1] - s[1:]) / (root[:-1] * root[1:])


def lemma_10(ar: Arithmetic, s: Array, one_minus_s2: Array, start: int) -> Array:
    """Lemma 10, with Σ_{k=0}^{i−1} = −Σ_{k=i}^{−1} for i < 0; ``start`` is the local index of 0.

    The heights and the terms t_k are elementwise (``Arithmetic``'s blocks); the partial sums
    are written in place into the x column.
    """
    p = ar.points(lambda rest: (rest, 1 / ar.sqrt(rest)), one_minus_s2)
    x = p[:, 0]
    x[start] = ar.scalar(0)

    def term(s0: Array, s1: Array, y0: Array, y1: Array) -> Array:
        return (s0 - s1) * (y0 * y1)  # t_k, with 1/√(1 − s²) = p^y

    y = p[:, 1]
    t = ar.values(term, s[:-1], s[1:], y[:-1], y[1:])
    if start < len(s) - 1:
        np.cumsum(t[start:], out=x[start + 1 :])
    if start > 0:
        np.cumsum(t[start - 1 :: -1], out=x[start - 1 :: -1])
        np.negative(x[:start], out=x[:start])
    return p


def lemma_10_printed(
    ar: Arithmetic, s: Array, one_minus_s2: Array, start: int
) -> tuple[slice, Array]:
    """Lemma 10's x-component with the printed convention "for i < 1 the k go from i − 1 to 0".

    For i < 1 that is Σ_{k=i−1}^{0} t_k, which needs s_{i−1} and s_1; for i >= 1 it is the usual
    sum. Returns the local indices where it can be evaluated (a slice) and the values there.
    """
    t = lemma_10_terms(ar, s, one_minus_s2)
    total = np.concatenate([ar.zeros(1), np.cumsum(t)])  # total[r] = t_0 + … + t_{r−1} (local)
    correct = total - total[start]
    if start > len(s) - 2:  # no s_1: the printed sums for i < 1 cannot be formed
        return slice(start + 1, len(s)), correct[start + 1 :]
    x = correct.copy()
    r = np.arange(1, start + 1)
    x[1 : start + 1] = total[start + 1] - total[r - 1]  # t_{r−1} + … + t_start (local indices)
    return slice(1, len(s)), x[1:]


def limit_points(ar: Arithmetic, artanh_g: Array) -> Array:
    """c(t) = (−artanh g(t), cosh(artanh g(t))), the point of C that Lemma 10 pairs with p_i."""
    return stack_points(-artanh_g, ar.exp(artanh_g) / 2 + ar.exp(-artanh_g) / 2)


def artanh_example_12(ar: Arithmetic, t: Array) -> Array:
    """artanh g(t) for Example 12, g(t) = 4t²/(1 + 4t²): ½ ln(1 + 8t²)."""
    return ar.log(1 + 8 * t * t) / 2


def artanh_remark_13(ar: Arithmetic, t: Array) -> Array:
    """artanh g(t) for Remark 13, g(t) = t/(1 + t), t > −½: ½ ln(1 + 2t)."""
    return ar.log(1 + 2 * t) / 2


def example_12_g(t: Array) -> Array:
    """g(t) = 4t²/(1 + 4t²) of Example 12."""
    return 4 * t * t / (1 + 4 * t * t)


def remark_13_g(t: Array) -> Array:
    """g(t) = t/(1 + t) of Remark 13."""
    return t / (1 + t)


def example_12_g_prime(t: Array) -> Array:
    """g'(t) = 8t/(1 + 4t²)² of Example 12."""
    q = 1 + 4 * t * t
    return 8 * t / (q * q)


def remark_13_g_prime(t: Array) -> Array:
    """g'(t) = 1/(1 + t)² of Remark 13."""
    return 1 / ((1 + t) * (1 + t))


def _partial_sums(ar: Arithmetic, terms: Array) -> Array:
    """0, t_0, t_0 + t_1, …: the sums Σ_{k=0}^{i−1} for i = 0 .. len(terms)."""
    return np.concatenate([ar.zeros(1), np.cumsum(terms)])


def riemann_sums(ar: Arithmetic, g: Array, g_prime: Array, t: Array) -> Array:
    """Proof of Lemma 10: Σ_{k=0}^{i−1} g'(t_k)/(1 − g(t_k)²)(t_k − t_{k+1}), i = 0 .. N.

    ``t`` are the parameters t_0 = 0, t_1, … (k/j), ``g``, ``g_prime`` g and g' there. The
    printed sum evaluates g and g' at s_k = g(t_k) instead (E65): pass those values for it.
    """
    return _partial_sums(ar, g_prime[:-1] / (1 - g[:-1] * g[:-1]) * (t[:-1] - t[1:]))


def difference_sums(ar: Arithmetic, s: Array, one_minus_s2: Array) -> Array:
    """Proof of Lemma 10: Σ_{k=0}^{i−1} (s_k − s_{k+1})/(1 − s_k²), i = 0 .. N (g' by its
    difference quotient)."""
    return _partial_sums(ar, (s[:-1] - s[1:]) / one_minus_s2[:-1])


def difference_sums_printed(ar: Arithmetic, g_of_s: Array) -> Array:
    """The printed Σ_{k=0}^{i−1} (g(s_k) − g(s_{k+1}))/(1 − g(s_k)²) (g of the values s_k, E65)."""
    return _partial_sums(ar, (g_of_s[:-1] - g_of_s[1:]) / (1 - g_of_s[:-1] * g_of_s[:-1]))
