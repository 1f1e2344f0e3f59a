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
A (D1) polygon satisfies (D3) exactly when C = 0 (then A_i = (δ/(2c)) l_i, see
``area_length_closed_forms``), and eq. (2) then holds with 2c²/δ.

Nothing here calls the construction (``hanging_chain``): comparing the two tests this theorem.
"""

from __future__ import annotations

from dataclasses import dataclass

from app.geometry.kinematic_closed_forms import amplitude_cosh
from app.geometry.precision import Arithmetic, Array, Scalar, stack_points


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
    """p_i = (iδ, C + a cosh(u_0 + (i − ½)E)) and the size of its terms; ``(n, 2)``, ``(n,)``.

    The size |iδ| + |C| + a cosh(…) is what the closed form's value is resolved against when C
    and the cosh term nearly cancel.
    """
    k = parameters(ar, c, delta, y0, y1)
    wave = amplitude_cosh(ar, k.amplitude, k.angle + (i - 0.5) * k.step)
    x = delta * i
    return stack_points(x, k.offset + wave), abs(x) + abs(k.offset) + wave
