"""Closed form of the area–length polygon (D3) with constant spacing (a theorem; not in the paper).

With tanh D = δ/(2c) and a = √(c² − δ²/4) = c / cosh D, the heights y_i = a cosh(v_i) with
v_{i+1} = v_i ± 2D satisfy (D3): y_i + y_{i+1} = 2a cosh(v + D) cosh D and
y_{i+1} − y_i = ±2a sinh(v + D) sinh D (v = min(v_i, v_{i+1})), so

    δ(y_i + y_{i+1})/2 = aδ cosh D cosh(v + D)
    c l_i = c √(δ² + 4a² sinh² D sinh²(v + D)) = c δ cosh(v + D)      (as 2a sinh D = δ),

equal because a cosh D = c. Hence the (D3) polygon from y_0 with branch up / down is

    y_i = a cosh(v_0 ± 2iD),    cosh v_0 = y_0 / a,  v_0 ≥ 0,    x_i = iδ,

the catenary of amplitude a sampled every 2D in its argument. It satisfies (D1) with
c_(D1) = tanh D = δ/(2c) (its amplitude is δ/(2 sinh D) = a, as ``hanging_chain_closed_forms``
requires, and its offset is 0), and eq. (2) with c_(D1)/c = δ/(2c²).

Nothing here calls the construction (``area_length``): comparing the two tests this theorem.
"""

from __future__ import annotations

from app.geometry.d4b.closed_forms import amplitude_cosh
from app.geometry.precision import Arithmetic, Array, Scalar


def half_step(ar: Arithmetic, c: Scalar, delta: Scalar) -> Scalar:
    """D = artanh(δ/(2c)): the argument of the catenary advances by 2D per edge."""
    return ar.atanh(delta / (2 * c))


def amplitude(ar: Arithmetic, c: Scalar, delta: Scalar) -> Scalar:
    """a = √(c² − δ²/4) = c√(1 − ρ²) with ρ = δ/(2c), the lowest height of the catenary."""
    rho = delta / (2 * c)
    return c * ar.sqrt((1 - rho) * (1 + rho))


def hyperbolic_cosine(
    ar: Arithmetic, c: Scalar, delta: Scalar, y0: Scalar, up: bool, i: Array
) -> Array:
    """p_i = (iδ, a cosh(v_0 ± 2iD)), + for branch up; ``(n,) -> (n, 2)``, elementwise in i."""
    a = amplitude(ar, c, delta)
    v0 = ar.acosh(y0 / a) if y0 > a else ar.scalar(0)
    step = 2 * half_step(ar, c, delta)

    def kernel(i: Array) -> tuple[Array, Array]:
        v = v0 + step * i if up else v0 - step * i
        return delta * i, amplitude_cosh(ar, a, v)

    return ar.points(kernel, i)
