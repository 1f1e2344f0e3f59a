"""The hanging chain of sticks (D1), Section 3, built from its difference equation.

The polygon has constant horizontal spacing δ, p_i = (iδ, y_i), starts at p_0 = (0, y0) and
p_1 = (δ, y1), and satisfies (D1) at every index:

    Δ²y_i = y_{i+2} − 2y_{i+1} + y_i = c (l_i + l_{i+1}),    l_i = |p_{i+1} − p_i|.

With constant spacing this is also the equilibrium of homogeneous sticks hanging from hinges
(force balance at each hinge with constant horizontal tension T and weight w per length gives
T(k_{i+1} − k_i) = (w/2)(l_i + l_{i+1}) for the slopes k_i; see ``conditions.equilibrium``).

**One step.** With the slopes m_i = (y_{i+1} − y_i)/δ, (D1) divided by δ reads

    m_{i+1} − m_i = c (√(1 + m_i²) + √(1 + m_{i+1}²)).

Put κ = m_i + c√(1 + m_i²). Then m_{i+1} − κ = c√(1 + m_{i+1}²), and squaring gives the quadratic

    (1 − c²) m² − 2κ m + κ² − c² = 0,    m± = (κ ± c√(κ² + 1 − c²)) / (1 − c²).

The admissible root is m+: the unsquared equation needs m − κ ≥ 0, and since
√(κ² + 1 − c²) > |κ| ≥ c|κ|, m+ − κ = c(cκ + √(κ² + 1 − c²))/(1 − c²) > 0 while m− − κ < 0.
The root m− solves m − κ = −c√(1 + m²): it is the step of the chain with −c, an arch standing
upside down, brought in by the squaring.

**Domain of c.** For 0 < c < 1 the root m+ is real for every slope (κ² + 1 − c² > 0), so every
start (y0, y1) continues for ever in both directions. For c ≥ 1 no next vertex exists at all:
|m_{i+1} − m_i| ≤ |m_i| + |m_{i+1}| < c(√(1 + m_i²) + √(1 + m_{i+1}²)). c = 0 is a straight
line and c < 0 the arch; (D1) asks for c > 0. Hence 0 < c < 1, delta > 0, any finite y0, y1.

**Backwards.** Reversing the indices maps (D1) to itself with the slopes negated, so the step
from edge i+1 back to edge i is m_i = −F(−m_{i+1}), F the forward step. Any index range works.

**Numerics.** F is evaluated without cancellation: for m < 0, κ = ((1 − c²)m² − c²)/(m − c√(1+m²))
and for κ < 0, m+ = (κ − c)(κ + c)/(κ − c√(κ² + 1 − c²)) (both are the product of the two roots
divided by the other one). The slopes are sequential (each step needs the previous slope), so
they are computed in a scalar loop: in float64 the compiled kernel ``_chain`` (its forward
and backward chains side by side, one step of each per turn; ≈ 25 ns a vertex at 10^5, 1.8 µs
a step as a Python loop), in mp the loop of ``construct`` over mpmath numbers, the same step
in both, except that the kernel takes √(1 + m_{i+1}²) from the step's own numbers instead of a
second hypot (``_step``: within 4 units in the last place of the previous kernel on
tests/geometry/previous_constructions.json); the heights are then partial sums (numpy cumsum).
The step
is a hyperbolic rotation of (√(1 + m²), m), so vectorizing it means solving the recursion: that
is the closed form (``hanging_chain_closed_forms``), a theorem the checks compare with this
construction, so it is not used here; ``method=closed-form`` serves long ranges from it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from app.geometry.compiled import hypot, kernel
from app.geometry.errors import DomainError
from app.geometry.precision import CLOCK_STEPS, Arithmetic, Array, Scalar, stack_points


@dataclass(frozen=True)
class HangingChain:
    """(D1) on the indices i_min .. i_max: vertices ``(n, 2)`` and edge slopes ``(n − 1,)``."""

    first: int
    """The first index, i_min."""
    vertices: Array
    slopes: Array
    """m_i = (y_{i+1} − y_i)/δ for i = i_min .. i_max − 1, as the recursion computed them."""

    @property
    def indices(self) -> np.ndarray[Any, np.dtype[np.int64]]:
        """The indices i_min .. i_max (made when read: no computation needs them)."""
        return np.arange(self.first, self.first + len(self.vertices), dtype=np.int64)


def validate(c: float, delta: float, y0: float, y1: float) -> None:
    """Raise ``DomainError`` unless 0 < c < 1, delta > 0 and y0, y1 are finite."""
    if not np.isfinite(c) or not 0 < c < 1:
        raise DomainError(
            "c",
            "0 < c < 1",
            c,
            "for c >= 1 no polygon satisfies (D1) with constant spacing (no real next vertex)",
        )
    if not np.isfinite(delta) or delta <= 0:
        raise DomainError("delta", "delta > 0", delta)
    for name, value in (("y0", y0), ("y1", y1)):
        if not np.isfinite(value):
            raise DomainError(name, f"{name} is a finite number", value)


@dataclass(frozen=True)
class StepConstants:
    """c, 1 − c² and √(1 − c²), the numbers every step uses."""

    c: Scalar
    one_minus_c2: Scalar
    root: Scalar

    @classmethod
    def of(cls, ar: Arithmetic, c: Scalar) -> StepConstants:
        one_minus_c2 = (1 - c) * (1 + c)
        return cls(c, one_minus_c2, ar.sqrt(one_minus_c2))


def forward_slope(ar: Arithmetic, k: StepConstants, m: Scalar) -> Scalar:
    """(D1) solved for m_{i+1} given m_i: the admissible root m+ of the step's quadratic."""
    c = k.c
    r = ar.hypot(1, m)
    kappa = m + c * r if m >= 0 else (k.one_minus_c2 * m * m - c * c) / (m - c * r)
    root = ar.hypot(kappa, k.root)
    if kappa >= 0:
        return (kappa + c * root) / k.one_minus_c2
    return (kappa - c) * (kappa + c) / (kappa - c * root)


def backward_slope(ar: Arithmetic, k: StepConstants, m: Scalar) -> Scalar:
    """(D1) solved for m_i given m_{i+1}: the forward step of the reversed chain, negated."""
    return -forward_slope(ar, k, -m)


@kernel("UniTuple(float64, 2)(float64, float64, float64, float64, float64)")
def _step(c: float, one_minus_c2: float, root: float, m: float, r: float) -> tuple[float, float]:
    """``forward_slope`` carrying r = √(1 + m²) along: (m_{i+1}, √(1 + m_{i+1}²)) from (m_i, r_i).

    The next r needs no second hypot: m_{i+1} − κ = c√(1 + m_{i+1}²) gives
    √(1 + m_{i+1}²) = (cκ + √(κ² + 1 − c²))/(1 − c²) for κ ≥ 0 and, with the product of the
    conjugates, (κ² + 1)/(√(κ² + 1 − c²) − cκ) for κ < 0: sums of positive terms, a few units
    in the last place of hypot(1, m_{i+1}) (one hypot a step instead of two).
    """
    kappa = m + c * r if m >= 0 else (one_minus_c2 * m * m - c * c) / (m - c * r)
    big = hypot(kappa, root)  # libm's, bit for bit (inline)
    if kappa >= 0:
        return (kappa + c * big) / one_minus_c2, (c * kappa + big) / one_minus_c2
    following = (kappa - c) * (kappa + c) / (kappa - c * big)
    if kappa < -1e150:  # κ² would overflow
        return following, hypot(1.0, following)
    return following, (kappa * kappa + 1) / (big - c * kappa)


@kernel(
    "Tuple((float64[:], float64[:, :]))"
    "(float64, float64, float64, float64, float64, float64, int64, int64, int64, int64)"
)
def _chain(
    c: float,
    one_minus_c2: float,
    root: float,
    delta: float,
    y0: float,
    y1: float,
    lo: int,
    hi: int,
    i_min: int,
    i_max: int,
) -> tuple[Array, Array]:
    """The float64 ``construct`` in one pass: (slopes m_j of the edges j = lo .. hi − 1,
    vertices p_i for i = i_min .. i_max).

    m_0 = (y1 − y0)/δ; edge j follows from edge j − 1 by (D1) solved forwards
    (``forward_slope``, as ``_step``), edge j from edge j + 1 by the reversed chain,
    m_j = −F(−m_{j+1}) (``backward_slope``); √(1 + m²) is even in m, so it carries over both
    ways. The heights are the partial sums of the mp path, in its order: y_{j+1} = y1 + Σ δm_k
    (k = 1 .. j) forwards, y_{j−1} = y0 − Σ δm_k (k = j − 1 .. −1) backwards, each sum
    accumulated from index 0 outwards as ``np.cumsum`` does; x_i = δ·i. The vertices are written
    straight into the ``(n, 2)`` result (no height array, no index array, no stacking).
    """
    slopes = np.empty(hi - lo)
    vertices = np.empty((i_max - i_min + 1, 2))
    m0 = (y1 - y0) / delta
    slopes[-lo] = m0
    for i in (0, 1):
        if i_min <= i <= i_max:
            vertices[i - i_min, 0] = delta * float(i)
            vertices[i - i_min, 1] = y0 if i == 0 else y1
    r0 = math.hypot(1.0, m0)
    # The two chains (edges 1 .. hi − 1 forwards, −1 .. lo backwards) depend on nothing but
    # m_0, so they run side by side: one step of each per turn, two independent sequences of
    # divisions and roots that the processor overlaps (each chain's operations and their order
    # are those of running it alone: the same bits, in about half the time).
    m, r, total = m0, r0, 0.0  # forwards
    mb, rb, total_b = -m0, r0, 0.0  # backwards, as the forward step of the reversed chain
    for t in range(max(hi - 1, -lo)):
        if t < hi - 1:  # edge j from edge j − 1; then p_{j+1} = p_j + (δ, δm_j)
            j = t + 1
            m, r = _step(c, one_minus_c2, root, m, r)
            slopes[j - lo] = m
            total = delta * m if j == 1 else total + delta * m
            if i_min <= j + 1 <= i_max:
                vertices[j + 1 - i_min, 0] = delta * float(j + 1)
                vertices[j + 1 - i_min, 1] = y1 + total
        if t < -lo:  # edge j from edge j + 1; then p_j = p_{j+1} − (δ, δm_j)
            j = -1 - t
            mb, rb = _step(c, one_minus_c2, root, mb, rb)
            slopes[j - lo] = -mb
            total_b = delta * -mb if j == -1 else total_b + delta * -mb
            if i_min <= j <= i_max:
                vertices[j - i_min, 0] = delta * float(j)
                vertices[j - i_min, 1] = y0 - total_b
    return slopes, vertices


def construct(
    ar: Arithmetic,
    c: float,
    delta: float,
    y0: float,
    y1: float,
    i_min: int,
    i_max: int,
) -> HangingChain:
    """(D1), Section 3: the polygon with spacing delta from p_0 = (0, y0), p_1 = (delta, y1)."""
    validate(c, delta, y0, y1)
    cc, dd = ar.scalar(c), ar.scalar(delta)
    yy0, yy1 = ar.scalar(y0), ar.scalar(y1)
    k = StepConstants.of(ar, cc)
    lo, hi = min(0, i_min), max(1, i_max)  # vertices lo .. hi, edges lo .. hi − 1
    if ar.mode == "float64":
        m, vertices = _chain(k.c, k.one_minus_c2, k.root, dd, yy0, yy1, lo, hi, i_min, i_max)
        ar.check_time()  # once, after the kernel: ≈ 25 ns per vertex
        return HangingChain(
            first=i_min,
            vertices=vertices,
            slopes=m[i_min - lo : i_max - lo],
        )
    slopes: list[Scalar] = [ar.scalar(0)] * (hi - lo)
    slopes[-lo] = (yy1 - yy0) / dd
    for j in range(1, hi):  # edge j from edge j − 1
        if not j % CLOCK_STEPS:
            ar.check_time()
        slopes[j - lo] = forward_slope(ar, k, slopes[j - 1 - lo])
    for j in range(-1, lo - 1, -1):  # edge j from edge j + 1
        if not j % CLOCK_STEPS:
            ar.check_time()
        slopes[j - lo] = backward_slope(ar, k, slopes[j + 1 - lo])
    m = ar.array(slopes)
    # heights: y_1 = y1 exactly, y_{j+1} = y_j + δ m_j forwards, y_{j−1} = y_j − δ m_{j−1} back
    ahead = np.cumsum(dd * m[1 - lo :]) if hi > 1 else ar.array([])
    behind = np.cumsum(dd * m[-lo - 1 :: -1]) if lo < 0 else ar.array([])
    y = np.concatenate([(yy0 - behind)[::-1], ar.array([yy0, yy1]), yy1 + ahead])
    window = slice(i_min - lo, i_max - lo + 1)
    i = ar.indices(i_min, i_max)
    return HangingChain(
        first=i_min,
        vertices=stack_points(dd * i, y[window]),
        slopes=m[i_min - lo : i_max - lo],
    )
