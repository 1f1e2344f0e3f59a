"""Distances from points to the smooth catenary and tractrix (the error measure "distance to the
curve" of the refinement studies).

Both are found from the critical points of the squared distance along the curve, located by a
vectorized safeguarded Newton iteration (``bracketed_root``): a Newton step where it stays in a
bracket known to hold the root, a bisection step otherwise. Each result is the distance to an
actual point of the curve, so it never underestimates; with the brackets below it is the exact
distance for the points the studies measure (near the curves, in the upper half-plane).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from app.geometry.precision import Arithmetic, Array, Scalar
from app.geometry.tolerances import log2_working_unit, working_unit

#: |x|/h beyond which h cosh(x/h) is not evaluated (float64's cosh overflows past ~710)
FAR = 700.0

RootFunction = Callable[[Array, np.ndarray[Any, np.dtype[np.intp]]], tuple[Array, Array]]
"""``f(s, where) -> (value, slope)`` at the points ``s`` for the entries ``where``."""


def bracketed_root(
    ar: Arithmetic, func: RootFunction, lo: Array, hi: Array, increasing: bool, scale: float = 1.0
) -> Array:
    """A root of ``func`` in [lo, hi] for every entry, where func rises (or falls) through it.

    Safeguarded Newton: the bracket shrinks to the side where the sign says the root lies; a
    Newton step that leaves it is replaced by bisection. Entries stop when their step is below
    the working precision relative to ``scale + |s|`` (``scale``: the size of the variable, so
    that the result does not depend on units); only the entries still moving are evaluated (a
    Python loop over iterations, each vectorized over the entries). At most enough iterations
    for bisection to reach the working precision from the widest bracket.
    """
    lo, hi = lo.copy(), hi.copy()
    s = (lo + hi) / 2
    width = float(np.max(ar.to_floats(abs(hi - lo)))) if len(s) else 0.0
    size = float(np.max(ar.to_floats(abs(s)))) + scale if len(s) else scale
    # a number of ``ar`` (in mp a float 10^−(digits+guard) is 0 from 314 digits on)
    tolerance = 4 * working_unit(ar)
    if 0 < width < math.inf and 0 < size < math.inf:
        log2_tolerance = 2 + log2_working_unit(ar)
        cap = 8 + max(0, math.ceil(math.log2(width) - log2_tolerance - math.log2(size)))
    else:  # an empty bracket needs no iteration; a non-finite one gets bisection's worst case
        cap = 8 if width == 0 else 8 + 2100
    unit = ar.scalar(scale)
    active = np.arange(len(s))
    for _ in range(cap):
        if not len(active):
            break
        x, a, b = s[active], lo[active], hi[active]
        value, slope = func(x, active)
        root_beyond = np.asarray(value < 0 if increasing else value > 0, dtype=bool)
        exact = np.asarray(value == 0, dtype=bool)
        a = np.where(root_beyond, x, a)
        b = np.where(root_beyond | exact, b, x)
        usable = np.asarray(slope != 0, dtype=bool)
        newton = x - value / np.where(usable, slope, 1)
        inside = usable & np.asarray((newton >= a) & (newton <= b), dtype=bool)
        following = np.where(exact, x, np.where(inside, newton, (a + b) / 2))
        moved = np.asarray(abs(following - x) > tolerance * (unit + abs(x)), dtype=bool)
        s[active], lo[active], hi[active] = following, a, b
        active = active[moved & ~exact]
    return s


def distance_to_catenary(ar: Arithmetic, h: Scalar, q: Array) -> Array:
    """Distance from each point of ``(n, 2)`` q to the catenary y = h cosh(x/h); ``(n,)``.

    The nearest point (s, h cosh(s/h)) has |s − q^x| ≤ v, v = |q^y − h cosh(q^x/h)| the vertical
    distance, hence h cosh(s/h) ≤ |q^y| + v, and is a root of
    F(s) = (s − q^x) + (h cosh(s/h) − q^y) sinh(s/h) (half the derivative of the squared
    distance), which rises through it when q^y < 2h cosh(s/h) (any point within h of the
    curve). The result is the smaller of the distances to that point and
    to (q^x, h cosh(q^x/h)).
    """
    qx, qy = q[:, 0], q[:, 1]
    # the vertex (0, h) is a point of the curve too: its distance bounds the answer where
    # h cosh(q^x/h) itself is beyond float64 (|q^x| ≥ 700 h)
    lowest = ar.hypot(qx, qy - h)
    near = np.asarray(abs(qx / h) < FAR, dtype=bool)
    height = h * ar.cosh(np.where(near, qx / h, 0))
    vertical = np.where(near, abs(qy - height), lowest)
    reach = np.minimum(vertical, lowest)

    def f(s: Array, where: np.ndarray[Any, np.dtype[np.intp]]) -> tuple[Array, Array]:
        c, sh = ar.cosh(s / h), ar.sinh(s / h)
        gap = h * c - qy[where]
        return (s - qx[where]) + gap * sh, c * c + gap * c / h

    # the nearest point is no farther than `reach`, so no higher than |q^y| + reach:
    # |s| <= h acosh((|q^y| + reach)/h) keeps cosh(s/h) finite wherever the answer is
    bound = h * ar.acosh(np.maximum((abs(qy) + reach) / h, 1))
    lo = np.maximum(qx - reach, -bound)
    hi = np.maximum(np.minimum(qx + reach, bound), lo)
    s = bracketed_root(ar, f, lo, hi, True, ar.to_float(h))
    nearest = ar.hypot(s - qx, h * ar.cosh(s / h) - qy)
    return np.minimum(nearest, reach)


def _sech(ar: Arithmetic, u: Array) -> Array:
    """1/cosh(u) as 2e/(1 + e²), e = exp(−|u|): no overflow for any u."""
    e = ar.exp(-abs(u))
    return 2 * e / (1 + e * e)


def distance_to_tractrix(ar: Arithmetic, h: Scalar, q: Array) -> Array:
    """Distance from each point of ``(n, 2)`` q to the tractrix (S4); ``(n,)``.

    T(s) = (s − h tanh(s/h), h/cosh(s/h)), with the cusp T(0) = (0, h).

    d/ds |q − T(s)|² = −2 tanh(s/h) G(s)/cosh(s/h) with G(s) = (q^x − s) sinh(s/h) − q^y
    + h cosh(s/h), G'(s) = (q^x − s) cosh(s/h)/h. So the critical points are the cusp s = 0 and
    the roots of G (found as the roots of G/cosh(s/h), which cannot overflow): G rises on
    (−∞, q^x) and falls on (q^x, ∞), G(q^x) = h cosh(q^x/h) − q^y ≥ 0
    for points below the catenary, and G < 0 at min(q^x, 0) − 2h and max(q^x, 0) + 2h for
    q^y ≥ 0; so there is one root in each of those brackets. The distance is the smallest of
    the three (exact for points of the upper half-plane below the catenary).
    """
    qx, qy = q[:, 0], q[:, 1]
    zero = ar.scalar(0)
    two_h = 2 * h

    def g(s: Array, where: np.ndarray[Any, np.dtype[np.intp]]) -> tuple[Array, Array]:
        """G(s)/cosh(s/h): the same sign and roots as G, and no overflow for any s."""
        t, e = ar.tanh(s / h), _sech(ar, s / h)
        lever, y = qx[where] - s, qy[where]
        return lever * t + h - y * e, -t + lever * e * e / h + y * e * t / h

    unit = ar.to_float(h)
    right = bracketed_root(ar, g, qx.copy(), np.maximum(qx, zero) + two_h, False, unit)
    left = bracketed_root(ar, g, np.minimum(qx, zero) - two_h, qx.copy(), True, unit)

    def to(s: Array) -> Array:
        return ar.hypot(s - h * ar.tanh(s / h) - qx, h * _sech(ar, s / h) - qy)

    cusp = ar.hypot(qx, qy - h)
    return np.minimum(np.minimum(to(right), to(left)), cusp)
