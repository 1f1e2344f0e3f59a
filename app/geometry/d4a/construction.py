"""Sauer's discrete tractrix (D4a), Section 3, built from its construction with sticks.

A stick of length h has one end x_i on the x-axis and the other end d_i above it; u_i is the unit
vector from x_i to d_i (angle β_i). Consecutive tractrix points are s apart, 0 < s < h, and the
free end of a stick lies on the neighbouring stick: pulled along the stick, the follower moves
by s towards the leader on the axis.

**The two sides of the cusp.** The paper asks that d_i lie on the previous stick for all i ∈ ℤ.
That cannot hold for all i: d_i on stick i−1 at distance s from its end means d_i^y = (h − s)
sin β_{i−1}, so sin β_i = (1 − s/h) sin β_{i−1} and sin β_i = (1 − s/h)^i sin β_0 would exceed 1
for i → −∞. As for the smooth tractrix, whose two branches meet at the cusp where the stick is
vertical, the pursuit runs away from one *cusp stick* c (the stick whose end is higher than
h − s, so that no stick can carry it) on both sides:

- i ≥ c (pursuit side): d_{i+1} lies on stick i, d_{i+1} = d_i − s u_i, and x_{i+1} is the axis
  point at distance h from d_{i+1} ahead (larger x); the sticks lean back (β_i > π/2 for i > c);
- i ≤ c (mirrored side): d_{i−1} lies on stick i, d_{i−1} = d_i − s u_i, and x_{i−1} is the axis
  point at distance h from d_{i−1} behind; the sticks lean forward (β_i < π/2 for i < c).

So d_{c−1} = d_{c+1}: the tractrix folds back at the cusp. Stick 0 starts at x_0 = (0, 0) with
angle ``beta0`` (default π/2: vertical, d_0 = (0, h)); it is the cusp stick when
d_0^y > h − s, otherwise the construction walks to the cusp (behind stick 0 when it leans back,
ahead of it when it leans forward). Every stick i carries one tractrix edge, the one lying on it:
d_i d_{i+1} for i ≥ c, d_{i−1} d_i for i < c (at the cusp both are the same segment).

**The discrete hyperbolic cosine.** The symmetry line of a tractrix edge is its perpendicular
bisector; for the edge carried by stick i it is the normal of the stick at the edge's midpoint.
p_i is where the symmetry lines of the edges carried by sticks i and i+1 meet: on the pursuit
side those are the consecutive edges d_i d_{i+1} and d_{i+1} d_{i+2}. The line of stick i is
taken with the stick's direction u_i, which the construction knows to rounding, rather than with
the difference of the edge's end points, which loses log10(h/s) digits.

**Darboux transform.** e_i is the reflection of x_i in the midpoint of the edge carried by stick
i (the paper's midpoint of d_i and d_{i+1} on the pursuit side).

**Numerics.** Each stick is built from the previous one, so the construction is a scalar loop
over the sticks from 0 to i_min − 1 and i_max + 3: in float64 the compiled kernel ``_sticks``
(app/geometry/compiled.py; ≈ 20 ns per stick, 1.6 µs as a Python loop), in mp the loop of
``construct_sticks`` over mpmath numbers, with the same moves (``_Stepper``). Vectorizing it
would mean solving the recursion first — the heights form a geometric sequence and the axis
points partial sums — which is the explicit form
(``sauer_closed_forms``) the checks compare with, so it is not done here; ``method=closed-form``
serves long ranges from that form, vectorized. The horizontal distance from a new end to its
axis point, √(h² − (d^y)²), is evaluated as √(h² cos²β + s(2h − s) sin²β) (no cancellation next
to the cusp).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numba
import numpy as np

from app.geometry.compiled import kernel
from app.geometry.errors import DomainError
from app.geometry.precision import CLOCK_STEPS, Arithmetic, Array, Scalar, stack_points

#: ``side`` values: the mirrored side (i < c), the cusp stick, the pursuit side (i > c).
MIRRORED, CUSP, PURSUIT = -1, 0, 1


@dataclass(frozen=True)
class SauerSticks:
    """Sticks i_lo .. i_hi of (D4a); every point array is ``(n, 2)``."""

    first: int
    """The first index, i_lo."""
    axis_points: Array
    """x_i on the x-axis."""
    tractrix: Array
    """d_i = x_i + h u_i."""
    directions: Array
    """u_i, the unit vector from x_i to d_i."""
    side: np.ndarray[Any, np.dtype[np.int64]]
    """−1 before the cusp stick, 0 at it, +1 after it."""

    @property
    def indices(self) -> np.ndarray[Any, np.dtype[np.int64]]:
        """The indices i_lo .. i_hi (made when read: no computation needs them)."""
        return np.arange(self.first, self.first + len(self.side), dtype=np.int64)


def validate(h: float, s: float, beta0: float | None) -> None:
    """Raise ``DomainError`` unless h > 0, 0 < s < h and 0 < beta0 < π."""
    if not np.isfinite(h) or h <= 0:
        raise DomainError("h", "h > 0", h)
    if not np.isfinite(s) or s <= 0:
        raise DomainError("s", "0 < s < h", s)
    if s >= h:
        raise DomainError("s", "0 < s < h", s, f"the stick length is h = {h!r}")
    if beta0 is not None and not (0 < beta0 < np.pi):
        raise DomainError(
            "beta0", "0 < beta0 < π (the stick points into the upper half-plane)", beta0
        )


class _Stepper:
    """The four moves between neighbouring sticks, for one h and s."""

    def __init__(self, ar: Arithmetic, h: Scalar, s: Scalar) -> None:
        self.ar, self.h, self.s = ar, h, s
        self.carry = h - s  # distance from a stick's axis end to the tractrix point it carries
        ratio = s / h
        self.keep = (h - s) / h  # not 1 − s/h, which loses digits when s is close to h
        self.widening = ratio * (2 - ratio)  # (h² − (h − s)²)/h²

    def is_cusp(self, sin_b: Scalar) -> bool:
        """No stick can carry this stick's end: d^y = h sin β > h − s."""
        return self.ar.exceeds(sin_b, self.keep, "beta0", "which stick is the cusp stick")

    def pull(self, x: Scalar, cos_b: Scalar, sin_b: Scalar, ahead: bool) -> tuple[Scalar, ...]:
        """The stick whose end is this stick's carried point x + (h − s)u, leader ahead/behind."""
        end_x = x + self.carry * cos_b
        root = self.ar.sqrt(cos_b * cos_b + self.widening * sin_b * sin_b)  # offset / h
        offset = self.h * root
        new_x = end_x + offset if ahead else end_x - offset
        return new_x, (-root if ahead else root), self.keep * sin_b

    def carrier(
        self, x: Scalar, cos_b: Scalar, sin_b: Scalar, lean_back: bool
    ) -> tuple[Scalar, ...]:
        """The stick carrying this stick's end d at distance h − s from its axis point.

        Of the two such sticks (mirror images in the vertical through d) it is the one leaning
        back (β > π/2) on the pursuit side and forward on the mirrored side.
        """
        sin_n = sin_b / self.keep
        cos_n = self.ar.sqrt((1 - sin_n) * (1 + sin_n))
        if lean_back:
            cos_n = -cos_n
        return x + self.h * cos_b - self.carry * cos_n, cos_n, sin_n


@numba.njit(cache=True, inline="always", error_model="numpy")
def _place(axis: Array, tractrix: Array, h: float, k: int, x: float, c: float, s: float) -> None:
    """Stick k's points: x_k = (x, 0) and d_k = x_k + h u_k, u_k = (c, s) (as ``_assemble``)."""
    axis[k, 0] = x
    axis[k, 1] = 0.0
    tractrix[k, 0] = x + h * c
    tractrix[k, 1] = 0.0 + h * s


@numba.njit(cache=True, inline="always", error_model="numpy")
def _forward_stick(
    h: float, carry: float, keep: float, widening: float, x: float, c: float, s: float, side: int
) -> tuple[float, float, float, int]:
    """Stick k (x, cos, sin, side) from stick k − 1: ``_Stepper.pull`` ahead from the cusp or
    the pursuit side, else ``_Stepper.carrier`` leaning forward."""
    if side >= CUSP:  # pull, the leader moves ahead
        root = math.sqrt(c * c + widening * s * s)
        return (x + carry * c) + h * root, -root, keep * s, PURSUIT
    sin_n = s / keep  # carrier leaning forward
    cos_n = math.sqrt((1 - sin_n) * (1 + sin_n))
    return x + h * c - carry * cos_n, cos_n, sin_n, (CUSP if sin_n > keep else MIRRORED)


@numba.njit(cache=True, inline="always", error_model="numpy")
def _backward_stick(
    h: float, carry: float, keep: float, widening: float, x: float, c: float, s: float, side: int
) -> tuple[float, float, float, int]:
    """Stick k (x, cos, sin, side) from stick k + 1: ``_Stepper.pull`` behind from the cusp or
    the mirrored side, else ``_Stepper.carrier`` leaning back."""
    if side <= CUSP:  # pull, the leader moves behind
        root = math.sqrt(c * c + widening * s * s)
        return (x + carry * c) - h * root, root, keep * s, MIRRORED
    sin_n = s / keep  # carrier leaning back
    cos_n = -math.sqrt((1 - sin_n) * (1 + sin_n))
    return x + h * c - carry * cos_n, cos_n, sin_n, (CUSP if sin_n > keep else PURSUIT)


@kernel(
    "Tuple((float64[:, :], float64[:, :], float64[:, :], int64[:]))"
    "(float64, float64, float64, float64, float64, float64, int64, int64)"
)
def _sticks(
    h: float,
    carry: float,
    keep: float,
    widening: float,
    c0: float,
    s0: float,
    k0: int,
    n: int,
) -> tuple[Array, Array, Array, Any]:
    """The float64 ``construct_sticks`` in one pass: (x_i, d_i, u_i, side) of n sticks.

    Stick k0 starts at x = 0 with direction (c0, s0); ``carry``, ``keep`` and ``widening`` are
    the ``_Stepper`` numbers h − s, (h − s)/h and s(2h − s)/h². The moves are ``_Stepper.pull``
    (the next stick is the one whose end is this stick's carried point) and
    ``_Stepper.carrier`` (the next stick is the one carrying this stick's end), chosen by the
    side of the cusp as in ``construct_sticks``. The recursion keeps each stick in the
    ``(n, 2)`` results themselves (x_i = (x, 0), u_i = (cos β, sin β)) and writes
    d_i = x_i + h u_i as ``_assemble`` does (no further arrays, no stacking).
    """
    axis = np.empty((n, 2))
    tractrix = np.empty((n, 2))
    u = np.empty((n, 2))
    side = np.zeros(n, dtype=np.int64)
    u[k0, 0] = c0
    u[k0, 1] = s0
    _place(axis, tractrix, h, k0, 0.0, c0, s0)
    side[k0] = CUSP if s0 > keep else (PURSUIT if c0 < 0 else MIRRORED)
    # The forward chain (sticks k0 + 1 .. n − 1) and the backward one (k0 − 1 .. 0) both start
    # from stick k0 and never meet, so they run side by side, one step of each per turn: the
    # processor overlaps their roots and divisions, and each chain's operations are those of
    # running it alone (the same bits). Each keeps its last stick (x, cos, sin, side) in
    # registers: reading it back from the arrays would wait on the stores just made.
    xf, cf, sf, sidef = 0.0, c0, s0, side[k0]
    xb, cb, sb, sideb = 0.0, c0, s0, side[k0]
    for t in range(max(n - 1 - k0, k0)):
        if t < n - 1 - k0:  # forward: stick k from stick k − 1
            k = k0 + 1 + t
            xf, cf, sf, sidef = _forward_stick(h, carry, keep, widening, xf, cf, sf, sidef)
            u[k, 0] = cf
            u[k, 1] = sf
            _place(axis, tractrix, h, k, xf, cf, sf)
            side[k] = sidef
        if t < k0:  # backward: stick k from stick k + 1
            k = k0 - 1 - t
            xb, cb, sb, sideb = _backward_stick(h, carry, keep, widening, xb, cb, sb, sideb)
            u[k, 0] = cb
            u[k, 1] = sb
            _place(axis, tractrix, h, k, xb, cb, sb)
            side[k] = sideb
    return axis, tractrix, u, side


def construct_sticks(
    ar: Arithmetic, h: float, s: float, beta0: float | None, i_lo: int, i_hi: int
) -> SauerSticks:
    """(D4a), Section 3: the sticks i_lo .. i_hi (i_lo <= 0 <= i_hi) and their tractrix points."""
    validate(h, s, beta0)
    hh, ss = ar.scalar(h), ar.scalar(s)
    step = _Stepper(ar, hh, ss)
    n = i_hi - i_lo + 1
    if beta0 is None:
        c0, s0 = ar.scalar(0), ar.scalar(1)
    else:
        angle = ar.scalar(beta0)
        c0, s0 = ar.cos(angle), ar.sin(angle)
    k0 = -i_lo
    if ar.mode == "float64":
        axis, tractrix, u, side_f = _sticks(hh, step.carry, step.keep, step.widening, c0, s0, k0, n)
        ar.check_time()  # once, after the kernel: ≈ 30 ns per stick
        return SauerSticks(
            first=i_lo,
            axis_points=axis,
            tractrix=tractrix,
            directions=u,
            side=side_f,
        )
    zero = ar.scalar(0)
    x, cos_u, sin_u = [zero] * n, [zero] * n, [zero] * n
    side = np.zeros(n, dtype=np.int64)
    cos_u[k0], sin_u[k0] = c0, s0
    leans_back = ar.exceeds(ar.scalar(0), c0, "beta0", "which way stick 0 leans")
    side[k0] = CUSP if step.is_cusp(s0) else (PURSUIT if leans_back else MIRRORED)
    for k in range(k0 + 1, n):  # forward: stick k from stick k − 1
        if not k % CLOCK_STEPS:
            ar.check_time()
        args = (x[k - 1], cos_u[k - 1], sin_u[k - 1])
        if side[k - 1] >= CUSP:  # d_k lies on stick k − 1; the leader moves ahead
            x[k], cos_u[k], sin_u[k] = step.pull(*args, ahead=True)
            side[k] = PURSUIT
        else:  # d_{k−1} lies on stick k (mirrored side): stick k is the one carrying it
            x[k], cos_u[k], sin_u[k] = step.carrier(*args, lean_back=False)
            side[k] = CUSP if step.is_cusp(sin_u[k]) else MIRRORED
    for k in range(k0 - 1, -1, -1):  # backward: stick k from stick k + 1
        if not k % CLOCK_STEPS:
            ar.check_time()
        args = (x[k + 1], cos_u[k + 1], sin_u[k + 1])
        if side[k + 1] <= CUSP:  # d_k lies on stick k + 1; the leader moves behind
            x[k], cos_u[k], sin_u[k] = step.pull(*args, ahead=False)
            side[k] = MIRRORED
        else:  # d_{k+1} lies on stick k (pursuit side): stick k is the one carrying it
            x[k], cos_u[k], sin_u[k] = step.carrier(*args, lean_back=True)
            side[k] = CUSP if step.is_cusp(sin_u[k]) else PURSUIT
    return _assemble(ar, hh, i_lo, i_hi, ar.array(x), ar.array(cos_u), ar.array(sin_u), side)


def _assemble(
    ar: Arithmetic,
    h: Scalar,
    i_lo: int,
    i_hi: int,
    axis_x: Array,
    cos_u: Array,
    sin_u: Array,
    side: np.ndarray[Any, np.dtype[np.int64]],
) -> SauerSticks:
    """The points of sticks i_lo .. i_hi from their axis points and directions."""
    u = stack_points(cos_u, sin_u)
    axis = stack_points(axis_x, ar.zeros(len(axis_x)))
    return SauerSticks(
        first=i_lo,
        axis_points=axis,
        tractrix=axis + h * u,
        directions=u,
        side=side,
    )


def carried_edges(sticks: SauerSticks) -> tuple[Array, Array]:
    """End points (a_i, b_i) of the tractrix edge on stick i, for the sticks i_lo+1 .. i_hi−1.

    d_i d_{i+1} on the pursuit side and at the cusp, d_{i−1} d_i before the cusp; ``(n − 2, 2)``.
    """
    d = sticks.tractrix
    behind = (sticks.side[1:-1] < CUSP)[:, None]
    first = np.where(behind, d[:-2], d[1:-1])
    second = np.where(behind, d[1:-1], d[2:])
    return first, second


def symmetry_line_meets(ar: Arithmetic, midpoints: Array, normals: Array) -> Array:
    """Where the symmetry line k (through midpoints[k], normal normals[k]) meets line k + 1.

    For lines (q − M_k)·u_k = 0: q = M_k + λ J u_k with J u = (−u^y, u^x) and
    λ = (M_{k+1} − M_k)·u_{k+1} / (u_k × u_{k+1}); ``(m, 2) -> (m − 1, 2)``.
    """
    u, v = normals[:-1], normals[1:]
    gap = midpoints[1:] - midpoints[:-1]
    cross = u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0]
    lam = (gap[:, 0] * v[:, 0] + gap[:, 1] * v[:, 1]) / cross
    return stack_points(midpoints[:-1, 0] - lam * u[:, 1], midpoints[:-1, 1] + lam * u[:, 0])


def hyperbolic_cosine(ar: Arithmetic, sticks: SauerSticks) -> Array:
    """(D4a): p_i where the symmetry lines of the edges carried by sticks i and i+1 meet.

    For sticks i_lo .. i_hi the result holds p_i for i = i_lo + 1 .. i_hi − 2; ``(n − 3, 2)``.
    """
    first, second = carried_edges(sticks)
    return symmetry_line_meets(ar, (first + second) / 2, sticks.directions[1:-1])


def darboux(sticks: SauerSticks) -> Array:
    """e_i, the reflection of x_i in the midpoint of the edge on stick i; i_lo+1 .. i_hi−1."""
    first, second = carried_edges(sticks)
    return first + second - sticks.axis_points[1:-1]
