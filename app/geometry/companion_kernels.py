"""Float64 kernels of the Gauss image companions (``gauss_image``): each pass over a meridian
polygon's edges done once, compiled, instead of a dozen numpy calls on short arrays.

``contact_points`` is the whole construction (19) in one pass: the edge, its length by libm's
hypot (``compiled.hypot``), the unit normal on the chosen side. ``circumscribed`` (20) needs
three transcendental functions a vertex, which numpy evaluates with its own vectorized routines
(whose last bits differ from libm's): so numpy still evaluates them, on contiguous arrays as
before, and the kernels do everything around them: the cross and dot products of consecutive
edges and the normal's direction in one pass (``circumscribed_arguments``), the half turn and
the bisector (``circumscribed_angles``), the pole at distance 1/cos(δ/2) on the bisector
(``circumscribed_points``). Every operation is the one ``gauss_image`` writes, in its order,
without fused multiply-adds (``compiled.kernel``): the same bits as the numpy formulas
(tests/geometry/test_companion_kernels.py compares them).

A zero-length (or NaN) edge is reported by the returned flag, as ``compiled.all_positive_lengths``
does, so that the caller raises the domain error it always raised.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from app.geometry.compiled import hypot, kernel


@kernel("Tuple((float64[:, :], boolean))(float64[:, :], float64)")
def contact_points(polygon: Any, sign: float) -> Any:
    """ñ_k = (−sign·e_k^y, sign·e_k^x)/|e_k| for the edges e_k = q_{k+1} − q_k of ``polygon``;
    ``(n − 1, 2)``, and whether every edge has a positive length."""
    count = max(polygon.shape[0] - 1, 0)
    out = np.empty((count, 2))
    positive = True
    for k in range(count):
        ex = polygon[k + 1, 0] - polygon[k, 0]
        ey = polygon[k + 1, 1] - polygon[k, 1]
        length = hypot(ex, ey)
        if not length > 0:
            positive = False
        out[k, 0] = -sign * ey / length
        out[k, 1] = sign * ex / length
    return out, positive


@kernel("Tuple((float64[:, :], float64[:, :], boolean))(float64[:, :], float64)")
def circumscribed_arguments(polygon: Any, sign: float) -> Any:
    """The arguments of the two arctangents of (20) for the interior vertices, ``(2, n − 2)``
    each: row 0 the turning angle's (a × b, a · b), row 1 the normal direction's
    (sign·a^x, −sign·a^y), a = e_{k−1}, b = e_k; and whether every edge has a positive length."""
    edges = max(polygon.shape[0] - 1, 0)
    count = max(edges - 1, 0)
    y = np.empty((2, count))
    x = np.empty((2, count))
    positive = True
    for k in range(edges):
        ex = polygon[k + 1, 0] - polygon[k, 0]
        ey = polygon[k + 1, 1] - polygon[k, 1]
        if not hypot(ex, ey) > 0:
            positive = False
    for k in range(count):
        a0 = polygon[k + 1, 0] - polygon[k, 0]
        a1 = polygon[k + 1, 1] - polygon[k, 1]
        b0 = polygon[k + 2, 0] - polygon[k + 1, 0]
        b1 = polygon[k + 2, 1] - polygon[k + 1, 1]
        y[0, k] = a0 * b1 - a1 * b0
        x[0, k] = a0 * b0 + a1 * b1
        y[1, k] = sign * a0
        x[1, k] = -sign * a1
    return y, x, positive


@kernel("float64[:, :](float64[:, :])")
def circumscribed_angles(angles: Any) -> Any:
    """From the turning angles δ (row 0) and normal directions ν (row 1): δ/2 and ν + δ/2."""
    count = angles.shape[1]
    out = np.empty((2, count))
    for k in range(count):
        half = angles[0, k] / 2
        out[0, k] = half
        out[1, k] = angles[1, k] + half
    return out


@kernel("float64[:, :](float64[:, :], float64[:])")
def circumscribed_points(cosines: Any, sines: Any) -> Any:
    """m_k = (1/cos(δ/2))·(cos β, sin β) from the cosines of δ/2 (row 0) and β (row 1) and the
    sines of β; ``(n − 2, 2)``."""
    count = sines.shape[0]
    out = np.empty((count, 2))
    for k in range(count):
        distance = 1 / cosines[0, k]
        out[k, 0] = distance * cosines[1, k]
        out[k, 1] = distance * sines[k]
    return out
