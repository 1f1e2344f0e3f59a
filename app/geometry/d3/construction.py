"""The area–length polygon (D3), Section 3, built from its defining condition.

The polygon has constant horizontal spacing δ, p_i = (iδ, y_i), starts at p_0 = (0, y0) and
satisfies (D3) on every edge: the area under the edge equals c times its length,

    A_i = δ (y_i + y_{i+1}) / 2 = c √(δ² + (y_{i+1} − y_i)²).

**One step.** Given the height y of one end, squaring the condition gives a quadratic for the
height w of the other end (the condition is symmetric in y and w):

    (4c² − δ²)(w² + y²) − 2(4c² + δ²) y w + 4c²δ² = 0,
    w± = ((4c² + δ²) y ± 4cδ √(y² − a²)) / (4c² − δ²),    a = √(c² − δ²/4).

The squaring brings in nothing spurious when y > 0: both roots are positive (their sum and
product are), so y + w > 0 and both satisfy the unsquared condition.

**What the two roots mean.** Both are edges with area = c · length, and they are mirror images
in the vertical line through p_i. Writing y = a cosh v (v ≥ 0), the roots are a cosh(v ± 2D) with
tanh D = δ/(2c) (``area_length_closed_forms``): the two directions along one catenary. Because the
condition is symmetric in its two heights, one root of the step at p_i is always the previous
height y_{i−1}; choosing it would fold the polygon back onto its previous edge (a zig-zag that
satisfies (D3) but is no discrete catenary). So the construction takes, at p_0, the root named by
``branch`` (``up``: w+, ``down``: w−) for p_1 and the other one for p_{−1}; at every later step it
takes the root that is not the previous vertex (the one farther from it), forwards and backwards.

**Domain.** c > 0 and 0 < δ < 2c (for δ ≥ 2c the quadratic's leading coefficient vanishes or
changes sign, only one root is admissible, and the polygon zig-zags across the x-axis), and
y0 ≥ a: for |y0| < a the roots are complex — no edge from p_0 reaches area/length = c, since the
largest area/length of an edge from height y0 over the width δ is √(y0² + δ²/4) — and for
y0 ≤ −a both roots satisfy A = −c l instead (the polygon reflected in the x-axis). Every height
of a (D3) polygon is at least a, the lowest point of its catenary.

**Numerics.** w+ is computed as written (no cancellation for y > 0) and w− as the product of the
roots divided by w+; √(y² − a²) as √((y − a)(y + a)). Next to the lowest point (y ≈ a) the step is
ill-conditioned by nature: dw/dy = sinh(v ± 2D)/sinh v grows without bound as v → 0, so a vertex
within a relative ε of the bottom can cost up to log10(1/ε)/2 digits in the vertex after it
(measured in float64: 2 digits for ε = 1e-10, 5 for ε = 1e-14). Each step needs the
previous height, so the construction is a scalar loop over max(|i_min|, |i_max|) steps: in
float64 the compiled kernel ``_vertices`` (app/geometry/compiled.py; ≈ 10 ns per step, 1.1 µs as
a Python loop), in mp the loop of ``construct`` over mpmath numbers, the same step in both.
Vectorizing it means solving the recursion, which is the closed form the checks compare with
(served by ``method=closed-form``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Literal

import numpy as np

from app.geometry.compiled import kernel
from app.geometry.errors import DomainError
from app.geometry.precision import CLOCK_STEPS, Arithmetic, Array, Scalar, stack_points

Branch = Literal["up", "down"]


@dataclass(frozen=True)
class AreaLengthPolygon:
    """(D3) on the indices i_min .. i_max: vertices ``(n, 2)``."""

    first: int
    """The first index, i_min."""
    vertices: Array

    @property
    def indices(self) -> np.ndarray[Any, np.dtype[np.int64]]:
        """The indices i_min .. i_max (made when read: no computation needs them)."""
        return np.arange(self.first, self.first + len(self.vertices), dtype=np.int64)


@dataclass(frozen=True)
class StepQuadratic:
    """Coefficients of the step's quadratic, in the form its roots need."""

    sum_factor: Scalar
    """(4c² + δ²)/(4c² − δ²): the roots add up to 2·sum_factor·y."""
    root_factor: Scalar
    """4cδ/(4c² − δ²): the roots differ by 2·root_factor·√(y² − a²)."""
    product_term: Scalar
    """4c²δ²/(4c² − δ²): the roots multiply to y² + product_term."""
    lowest: Scalar
    """a = √(c² − δ²/4), below which the roots are complex."""


def lowest_height(c: float, delta: float) -> float:
    """a = √(c² − δ²/4) = c√(1 − ρ²), ρ = δ/(2c), in float64: the smallest admissible y0."""
    rho = delta / (2 * c)
    return float(c * np.sqrt((1 - rho) * (1 + rho)))


def validate(c: float, delta: float, y0: float, branch: str) -> None:
    """Raise ``DomainError`` unless c > 0, 0 < delta < 2c, y0 ≥ √(c² − δ²/4), branch up/down."""
    if not np.isfinite(c) or c <= 0:
        raise DomainError("c", "c > 0", c)
    if not np.isfinite(delta) or delta <= 0:
        raise DomainError("delta", "0 < delta < 2c", delta)
    if delta >= 2 * c:
        raise DomainError(
            "delta",
            "0 < delta < 2c",
            delta,
            f"c = {c!r}; for delta >= 2c the (D3) polygon zig-zags across the x-axis",
        )
    if not np.isfinite(y0):
        raise DomainError("y0", "y0 is a finite number", y0)
    a = lowest_height(c, delta)
    if y0 < a:
        raise DomainError(
            "y0",
            "y0 >= √(c² − delta²/4)",
            y0,
            f"√(c² − delta²/4) = {a!r}: no edge from a lower p_0 has area = c · length",
        )
    if branch not in ("up", "down"):
        raise DomainError("branch", "branch is 'up' or 'down'", branch)


def quadratic(ar: Arithmetic, c: Scalar, delta: Scalar) -> StepQuadratic:
    """The coefficients of the step's quadratic for given c and δ.

    Written with ρ = δ/(2c) (no squares of c or δ, which would overflow or underflow first):
    (4c² + δ²)/(4c² − δ²) = (1 + ρ²)/(1 − ρ²), 4cδ/(4c² − δ²) = 2ρ/(1 − ρ²),
    4c²δ²/(4c² − δ²) = δ²/(1 − ρ²), √(c² − δ²/4) = c√(1 − ρ²).
    """
    rho = delta / (2 * c)
    gap = (1 - rho) * (1 + rho)
    return StepQuadratic(
        sum_factor=(1 + rho * rho) / gap,
        root_factor=2 * rho / gap,
        product_term=delta * (delta / gap),
        lowest=c * ar.sqrt(gap),
    )


def step_roots(ar: Arithmetic, q: StepQuadratic, y: Scalar) -> tuple[Scalar, Scalar]:
    """(D3) solved for the other height w of an edge from height y: the roots (w+, w−)."""
    # >= 0 but for rounding, next to the lowest point: the double root
    excess = ar.nonnegative(y - q.lowest)
    big = q.sum_factor * y + q.root_factor * ar.sqrt(excess * (y + q.lowest))
    return big, (y * y + q.product_term) / big


def _other(ar: Arithmetic, near: Scalar, roots: tuple[Scalar, Scalar]) -> Scalar:
    """The root that is not the previous vertex's height ``near`` (the one farther from it;
    on balls that cannot tell, a ball holding both)."""
    big, small = roots
    return ar.at_least_or(abs(big - near), abs(small - near), big, small)


@kernel("UniTuple(float64, 2)(float64, float64, float64, float64, float64)")
def _roots(
    sum_factor: float, root_factor: float, product_term: float, lowest: float, y: float
) -> tuple[float, float]:
    """``step_roots`` in float64, for the compiled loop: (w+, w−) for an edge from height y."""
    excess = y - lowest
    if excess < 0:  # only by rounding, next to the lowest point: the double root
        excess = 0.0
    big = sum_factor * y + root_factor * math.sqrt(excess * (y + lowest))
    return big, (y * y + product_term) / big


@kernel(
    "float64[:, :](float64, float64, float64, float64, float64, float64, boolean, int64, int64)"
)
def _vertices(
    sum_factor: float,
    root_factor: float,
    product_term: float,
    lowest: float,
    delta: float,
    y0: float,
    up: bool,
    i_min: int,
    i_max: int,
) -> Array:
    """The float64 ``construct`` in one pass: the vertices p_i = (δi, y_i), i = i_min .. i_max.

    Each step solves the quadratic of ``step_roots`` (given by the four ``StepQuadratic``
    numbers) at the last height and keeps the root that is not the height before it (``_other``);
    at p_0 ``up`` sends w+ forwards and w− backwards, and the reverse otherwise. The recursion
    runs from index 0 to i_max and to i_min (at least one step each way, as the mp loop) and
    writes the vertices of the range straight into the ``(n, 2)`` result.
    """
    out = np.empty((i_max - i_min + 1, 2))
    big, small = _roots(sum_factor, root_factor, product_term, lowest, y0)
    ahead, behind = (big, small) if up else (small, big)
    for i, height in ((0, y0), (1, ahead), (-1, behind)):
        if i_min <= i <= i_max:
            out[i - i_min, 0] = delta * float(i)
            out[i - i_min, 1] = height
    # The forward chain (j = 2 .. i_max) and the backward one (j = −2 .. i_min) start from p_0
    # and p_{±1} and never meet, so they run side by side, one step of each per turn: the
    # processor overlaps their roots and divisions, and each chain's operations are those of
    # running it alone (the same bits).
    near, last = y0, ahead  # forwards
    near_b, last_b = y0, behind  # backwards
    for t in range(max(i_max - 1, -i_min - 1)):
        if t < i_max - 1:
            j = t + 2
            big, small = _roots(sum_factor, root_factor, product_term, lowest, last)
            near, last = last, (big if abs(big - near) >= abs(small - near) else small)
            if j >= i_min:
                out[j - i_min, 0] = delta * float(j)
                out[j - i_min, 1] = last
        if t < -i_min - 1:
            j = -t - 2
            big, small = _roots(sum_factor, root_factor, product_term, lowest, last_b)
            near_b, last_b = last_b, (big if abs(big - near_b) >= abs(small - near_b) else small)
            if j <= i_max:
                out[j - i_min, 0] = delta * float(j)
                out[j - i_min, 1] = last_b
    return out


def construct(
    ar: Arithmetic,
    c: float,
    delta: float,
    y0: float,
    branch: Branch,
    i_min: int,
    i_max: int,
) -> AreaLengthPolygon:
    """(D3), Section 3: the polygon with spacing delta from p_0 = (0, y0), first step by branch."""
    validate(c, delta, y0, branch)
    cc, dd, yy0 = ar.scalar(c), ar.scalar(delta), ar.scalar(y0)
    q = quadratic(ar, cc, dd)
    lo, hi = min(-1, i_min), max(1, i_max)
    if ar.mode == "float64":
        vertices = _vertices(
            q.sum_factor,
            q.root_factor,
            q.product_term,
            q.lowest,
            dd,
            yy0,
            branch == "up",
            i_min,
            i_max,
        )
        ar.check_time()  # once, after the kernel: ≈ 15–20 ns per vertex
        return AreaLengthPolygon(first=i_min, vertices=vertices)
    i = ar.indices(i_min, i_max)
    y: list[Scalar] = [yy0] * (hi - lo + 1)
    big, small = step_roots(ar, q, yy0)
    y[1 - lo], y[-1 - lo] = (big, small) if branch == "up" else (small, big)
    for j in range(2, hi + 1):
        if not j % CLOCK_STEPS:
            ar.check_time()
        y[j - lo] = _other(ar, y[j - 2 - lo], step_roots(ar, q, y[j - 1 - lo]))
    for j in range(-2, lo - 1, -1):
        if not j % CLOCK_STEPS:
            ar.check_time()
        y[j - lo] = _other(ar, y[j + 2 - lo], step_roots(ar, q, y[j + 1 - lo]))
    return AreaLengthPolygon(
        first=i_min,
        vertices=stack_points(dd * i, ar.array(y[i_min - lo : i_max - lo + 1])),
    )
