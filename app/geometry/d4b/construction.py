"""Wunderlich's kinematic discrete tractrix (D4b), built from its definition (Section 3).

A stick of length h has one end x_i = (2di, 0) on the x-axis and the other end d_i above it.
Stick i−1 is carried to stick i by a rotation; its centre p_i lies on the perpendicular
bisector of x_{i−1} x_i (the line x = (2i−1)d) and on the line through d_{i−1} orthogonal to
stick i−1. The rotation maps x_{i−1} to x_i and d_{i−1} to d_i. The centres p_i form the
discrete hyperbolic cosine, the ends d_i the discrete tractrix.

Conventions (as in Theorem 5): stick 0 starts at x_0 = (0, 0) with angle ``beta0`` to the
positive x-axis, measured counter-clockwise in radians (π/2: vertical, d_0 = (0, h)); p_i is the
centre of the rotation from stick i−1 to stick i, so p_i^x = (2i − 1)d; indices may be negative,
the backward steps use the inverse rotations.

Nothing here uses the closed forms of Theorems 5 and 6: the checks compare the two.

The recursion is sequential (each step needs where the previous stick points). In float64 it
runs as one compiled kernel (``_sticks``, app/geometry/compiled.py, ≈ 20 ns per stick); on balls
(precision=mp) as one compiled loop of libflint calls (``arb_loops.sticks``: the calls
python-flint's operators make in the Python loop of ``construct``, so the same balls); on mpmath
numbers as that Python loop. All are the same steps: the centre on the bisector and the normal,
then the rotation of ``rotation_about``.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from functools import cached_property
from typing import Any, Literal, NamedTuple

import flint
import numba
import numpy as np

from app.geometry import arb_loops
from app.geometry.compiled import kernel
from app.geometry.errors import DomainError
from app.geometry.precision import CLOCK_STEPS, Arithmetic, Array, Scalar, stack_points

PointName = Literal["axis_points", "tractrix", "centres", "directions"]


class Recursion(NamedTuple):
    """The float64 recursion of one construction (``_sticks``): h, d, cos β_j, sin β_j and p_j^y
    for j = first .. first + len − 1."""

    h: float
    d: float
    cos_u: Array
    sin_u: Array
    centre_y: Array
    first: int


class KinematicTractrix:
    """The construction (D4b) on the indices i_min .. i_max; every array is ``(n, 2)``.

    The recursion gives each stick's direction u_i and centre height p_i^y; the four point
    arrays are made from them when first read (``points(name)``), so a request that returns p
    alone never holds the other three (a 10^6-vertex ``format=npy`` answer, issue 12).
    """

    def __init__(
        self,
        i_min: int,
        i_max: int,
        points: Callable[[PointName], Array],
        recursion: Recursion | None = None,
    ) -> None:
        self.i_min, self.i_max = i_min, i_max
        self._points = points
        self.recursion = recursion
        """Float64: the recursion's own arrays, which the compiled companions read
        (``app.geometry.companion_kernels.d4b_companions``); None in mp."""

    @property
    def indices(self) -> np.ndarray[Any, np.dtype[np.int64]]:
        """i_min .. i_max (made when read: no computation needs them)."""
        return np.arange(self.i_min, self.i_max + 1, dtype=np.int64)

    @cached_property
    def axis_points(self) -> Array:
        """x_i = (2di, 0)."""
        return self._points("axis_points")

    @cached_property
    def tractrix(self) -> Array:
        """d_i, the free end of stick i."""
        return self._points("tractrix")

    @cached_property
    def centres(self) -> Array:
        """p_i, the centre of the rotation taking stick i−1 to stick i."""
        return self._points("centres")

    @cached_property
    def directions(self) -> Array:
        """u_i, the unit vector from x_i to d_i."""
        return self._points("directions")


def validate(h: float, d: float, beta0: float | None) -> None:
    """Raise ``DomainError`` unless 0 < d < h and 0 < beta0 < π."""
    if not math.isfinite(h) or h <= 0:
        raise DomainError("h", "h > 0", h)
    if not math.isfinite(d) or d <= 0:
        raise DomainError("d", "0 < d < h", d)
    if d >= h:
        raise DomainError("d", "0 < d < h", d, f"the stick length is h = {h!r}")
    if beta0 is not None and not (0 < beta0 < math.pi):
        raise DomainError(
            "beta0", "0 < beta0 < π (the stick points into the upper half-plane)", beta0
        )


def initial_direction(ar: Arithmetic, beta0: float | None) -> tuple[Scalar, Scalar]:
    """u_0 = (cos β0, sin β0); exactly (0, 1) for the vertical start."""
    if beta0 is None:
        return ar.scalar(0), ar.scalar(1)
    angle = ar.scalar(beta0)
    return ar.cos(angle), ar.sin(angle)


def rotation_about(p_y: Scalar, d: Scalar) -> tuple[Scalar, Scalar]:
    """cos α and sin α of the rotation about p = ((2i−1)d, p_y) that maps x_{i−1} to x_i.

    x_{i−1} − p = (−d, −p_y) turns into x_i − p = (d, −p_y); with r = d/p_y this is
    cos α = (1 − r²)/(1 + r²), sin α = 2r/(1 + r²) (written with r so that nothing overflows).
    """
    r = d / p_y
    q = 1 + r * r
    return (1 - r * r) / q, 2 * r / q


@numba.njit(cache=True, inline="always", error_model="numpy")
def _forward_stick(h: float, d: float, c: float, s: float) -> tuple[float, float, float]:
    """(p_j^y, cos β_j, sin β_j) from stick j−1 = (c, s): p_j on the normal of stick j−1 at
    d_{j−1}, then the rotation about p_j (``rotation_about`` in float64)."""
    p_y = (h - d * c) / s
    r = d / p_y
    q = 1 + r * r
    ca = (1 - r * r) / q
    sa = 2 * r / q
    return p_y, ca * c - sa * s, sa * c + ca * s


@numba.njit(cache=True, inline="always", error_model="numpy")
def _backward_stick(h: float, d: float, c: float, s: float) -> tuple[float, float, float]:
    """(p_j^y, cos β_{j−1}, sin β_{j−1}) from stick j = (c, s): p_j on the normal of stick j at
    d_j, then the inverse rotation about p_j."""
    p_y = (h + d * c) / s
    r = d / p_y
    q = 1 + r * r
    ca = (1 - r * r) / q
    sa = 2 * r / q
    return p_y, ca * c + sa * s, ca * s - sa * c


@kernel("float64[:, ::1](float64, float64, float64, float64, int64, int64)")
def _sticks(h: float, d: float, c0: float, s0: float, lo: int, hi: int) -> Array:
    """The float64 recursion of ``construct``: rows cos β_j, sin β_j, p_j^y for j = lo .. hi,
    ``(3, hi − lo + 1)``.

    Stick 0 has direction (c0, s0). Forwards, p_j lies on x = (2j − 1)d and on the normal of
    stick j−1 at d_{j−1}: p_j^y = (h − d cos β_{j−1})/sin β_{j−1}; the rotation about p_j with
    cos α = (1 − r²)/(1 + r²), sin α = 2r/(1 + r²), r = d/p_j^y, turns stick j−1 into stick j.
    Backwards, p_j is on the normal of stick j at d_j, p_j^y = (h + d cos β_j)/sin β_j, and the
    inverse rotation turns stick j into stick j−1. Entry 0 of p^y (no rotation into stick 0 is
    computed when lo = 0) stays 0, as in the mp loop.
    """
    out = np.zeros((3, hi - lo + 1))
    cos_u, sin_u, centre_y = out[0], out[1], out[2]
    cos_u[-lo] = c0
    sin_u[-lo] = s0
    # The forward chain (sticks 1 .. hi) and the backward one (sticks −1 .. lo) both start from
    # stick 0 and never meet, so they run side by side, one step of each per turn: the processor
    # overlaps their divisions, and each chain's operations are those of running it alone (the
    # same bits). Each keeps its last stick in registers.
    cf, sf, cb, sb = c0, s0, c0, s0
    for t in range(max(hi, -lo)):
        if t < hi:  # forward: stick j−1 -> stick j about p_j, j = t + 1
            p_y, cf, sf = _forward_stick(h, d, cf, sf)
            centre_y[t + 1 - lo] = p_y
            cos_u[t + 1 - lo] = cf
            sin_u[t + 1 - lo] = sf
        if t < -lo:  # backward: stick j -> stick j−1 about p_j, j = −t
            p_y, cb, sb = _backward_stick(h, d, cb, sb)
            centre_y[-t - lo] = p_y
            cos_u[-t - 1 - lo] = cb
            sin_u[-t - 1 - lo] = sb
    return out


#: The four point arrays of ``KinematicTractrix``, in the order of ``_point_array``'s ``which``.
_POINT_NAMES: tuple[PointName, ...] = ("axis_points", "tractrix", "centres", "directions")


@kernel(
    "float64[:, :]"
    "(int64, float64, float64, float64[:], float64[:], float64[:], int64, int64, int64)"
)
def _point_array(
    which: int,
    h: float,
    d: float,
    cos_u: Array,
    sin_u: Array,
    centre_y: Array,
    first: int,
    i_min: int,
    i_max: int,
) -> Array:
    """One ``(n, 2)`` array of sticks i_min .. i_max (``which`` indexes ``_POINT_NAMES``):
    x_i = (2di, 0), d_i = x_i + h u_i, p_i = ((2i − 1)d, p_i^y) or u_i.

    Entry ``first`` of the recursion's arrays is index i_min; the same operations as
    ``_assemble`` (which mp uses). One loop per array, without branches (the compiler vectorizes
    them: ≈ 3 ms instead of 3.6–4.6 at 10^6 sticks, most of it the fresh array's pages).
    """
    n = i_max - i_min + 1
    out = np.empty((n, 2))
    two_d = 2 * d
    cs, ss = cos_u[first : first + n], sin_u[first : first + n]  # indices from 0
    if which == 0:
        for k in range(n):
            out[k, 0] = two_d * float(i_min + k)
            out[k, 1] = 0.0
    elif which == 1:
        for k in range(n):
            out[k, 0] = two_d * float(i_min + k) + h * cs[k]
            out[k, 1] = 0.0 + h * ss[k]
    elif which == 2:
        heights = centre_y[first : first + n]
        for k in range(n):
            out[k, 0] = (2 * float(i_min + k) - 1) * d
            out[k, 1] = heights[k]
    else:
        for k in range(n):
            out[k, 0] = cs[k]
            out[k, 1] = ss[k]
    return out


def construct(
    ar: Arithmetic,
    h: float,
    d: float,
    beta0: float | None,
    i_min: int,
    i_max: int,
) -> KinematicTractrix:
    """(D4b), Section 3: sticks, rotation centres and tractrix for i = i_min .. i_max.

    The step from one stick to the next depends on where the previous stick points, so the
    recursion is sequential over max(|i_min − 1|, |i_max|) sticks: the compiled ``_sticks`` in
    float64, this loop in mp (measured in bench/; method="closed-form" serves very long ranges
    from Theorems 5 and 6 instead).
    """
    validate(h, d, beta0)
    hh, dd = ar.scalar(h), ar.scalar(d)
    lo, hi = stick_range(i_min, i_max)
    window = slice(i_min - lo, i_max - lo + 1)
    if ar.mode == "float64":
        c0, s0 = initial_direction(ar, beta0)
        sticks = _sticks(float(h), float(d), float(c0), float(s0), lo, hi)
        ar.check_time()  # once, after the kernel: ≈ 25–35 ns per stick
        return from_sticks(float(h), float(d), i_min, i_max, lo, sticks)
    c0, s0 = initial_direction(ar, beta0)
    if arb_loops.AVAILABLE and all(type(x) is flint.arb for x in (hh, dd, c0, s0)):
        # on balls: the loop below compiled (the same libflint calls, the same balls)
        cos_b, sin_b, centre_b = arb_loops.sticks(hh, dd, c0, s0, lo, hi, ar.check_time)
        # _assemble's operations compiled too (the same balls), each array kept read-only
        arrays = arb_loops.stick_points(
            hh, dd, i_min, cos_b[window], sin_b[window], centre_b[window]
        )
        return KinematicTractrix(i_min, i_max, arrays.__getitem__)
    cos_u = [ar.scalar(0)] * (hi - lo + 1)  # mpmath (MultiPrecision)
    sin_u = list(cos_u)
    centre_y = list(cos_u)
    cos_u[-lo], sin_u[-lo] = c0, s0
    for j in range(1, hi + 1):  # forward: stick j−1 -> stick j about p_j
        if not j % CLOCK_STEPS:
            ar.check_time()
        c, s = cos_u[j - 1 - lo], sin_u[j - 1 - lo]
        p_y = (hh - dd * c) / s  # on x = (2j−1)d and on the normal of stick j−1 at d_{j−1}
        ca, sa = rotation_about(p_y, dd)
        centre_y[j - lo] = p_y
        cos_u[j - lo], sin_u[j - lo] = ca * c - sa * s, sa * c + ca * s
    for j in range(0, lo, -1):  # backward: stick j -> stick j−1 about p_j
        if not j % CLOCK_STEPS:
            ar.check_time()
        c, s = cos_u[j - lo], sin_u[j - lo]
        p_y = (hh + dd * c) / s  # on x = (2j−1)d and on the normal of stick j at d_j
        ca, sa = rotation_about(p_y, dd)
        centre_y[j - lo] = p_y
        cos_u[j - 1 - lo], sin_u[j - 1 - lo] = ca * c + sa * s, ca * s - sa * c
    return _assemble(
        ar,
        hh,
        dd,
        i_min,
        i_max,
        ar.array(cos_u[window]),
        ar.array(sin_u[window]),
        ar.array(centre_y[window]),
    )


def stick_range(i_min: int, i_max: int) -> tuple[int, int]:
    """The sticks lo .. hi the recursion of ``construct`` on i_min .. i_max runs over (from
    stick 0, and one before i_min: p_i needs stick i − 1)."""
    return min(0, i_min - 1), max(0, i_max)


def from_sticks(
    h: float, d: float, i_min: int, i_max: int, lo: int, sticks: Array
) -> KinematicTractrix:
    """The float64 construction on i_min .. i_max from its recursion's rows (``_sticks`` on
    ``stick_range(i_min, i_max)``, starting at ``lo``): its points made when read."""
    cos_f, sin_f, centre_f = sticks
    arguments = (h, d, cos_f, sin_f, centre_f, i_min - lo, i_min, i_max)
    return KinematicTractrix(
        i_min,
        i_max,
        lambda name: _point_array(_POINT_NAMES.index(name), *arguments),
        Recursion(h, d, cos_f, sin_f, centre_f, lo),
    )


def centre_rows(recursion: Recursion, i_min: int, i_max: int) -> Array:
    """The rotation centres p_i = ((2i − 1)d, p_i^y), i = i_min .. i_max, of a float64
    recursion ((n, 2)): rows of the hull's whole ``centres`` array, made alone (``_point_array``
    computes each row from its own stick, so the bits are those of the whole array's rows)."""
    h, d, cos_u, sin_u, centre_y, lo = recursion
    return _point_array(2, h, d, cos_u, sin_u, centre_y, i_min - lo, i_min, i_max)


def _assemble(
    ar: Arithmetic,
    h: Scalar,
    d: Scalar,
    i_min: int,
    i_max: int,
    cos_u: Array,
    sin_u: Array,
    centre_y: Array,
) -> KinematicTractrix:
    """The points of sticks i_min .. i_max from their directions and centre heights."""
    i = ar.indices(i_min, i_max)
    u = stack_points(cos_u, sin_u)
    axis = stack_points(2 * d * i, ar.zeros(len(i)))
    points: dict[PointName, Array] = {
        "axis_points": axis,
        "tractrix": axis + h * u,
        "centres": stack_points((2 * i - 1) * d, centre_y),
        "directions": u,
    }
    return KinematicTractrix(i_min, i_max, points.__getitem__)
