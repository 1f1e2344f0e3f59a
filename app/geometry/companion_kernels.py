"""Float64 kernels of the Gauss image companions (``gauss_image``): each pass over a meridian
polygon's edges done once, compiled, instead of a dozen numpy calls on short arrays.

``contact_points`` is the whole construction (19) in one pass: the edge, its length by libm's
hypot (``compiled.hypot``), the unit normal on the chosen side. ``circumscribed_poles`` (20)
is one pass too: the cross and dot products of consecutive edges and the normal's direction,
the two arctangents of them, the half turn and the bisector, and the pole at distance
1/cos(δ/2) on it, with the C library's atan2, cos and sin, the functions the float64
arithmetic calls everywhere (``elementary``). Every operation is the one ``gauss_image``
writes, in its order, without fused multiply-adds (``compiled.kernel``): the same bits as its
formulas in the float64 arithmetic (tests/geometry/test_companion_kernels.py compares them).

A zero-length (or NaN) edge is reported by the returned flag, as ``compiled.all_positive_lengths``
does, so that the caller raises the domain error it always raised.
"""

from __future__ import annotations

import math
from typing import Any

import numba
import numpy as np

from app.geometry.compiled import hypot, kernel
from app.geometry.d4b.construction import _sticks


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


@numba.njit(cache=True, error_model="numpy")
def _poles_into(polygon: Any, sign: float, out: Any) -> None:
    """(20) for the interior vertices of ``polygon`` into ``out`` (``(n − 2, 2)``): with
    a = e_{k−1}, b = e_k, the turning angle δ_k = atan2(a × b, a · b) and the normal's direction
    ν_k = atan2(sign·a^x, −sign·a^y), the pole m_k = (1/cos(δ_k/2))·(cos β_k, sin β_k),
    β_k = ν_k + δ_k/2."""
    for k in range(out.shape[0]):
        a0 = polygon[k + 1, 0] - polygon[k, 0]
        a1 = polygon[k + 1, 1] - polygon[k, 1]
        b0 = polygon[k + 2, 0] - polygon[k + 1, 0]
        b1 = polygon[k + 2, 1] - polygon[k + 1, 1]
        half = math.atan2(a0 * b1 - a1 * b0, a0 * b0 + a1 * b1) / 2
        bisector = math.atan2(sign * a0, -sign * a1) + half
        distance = 1 / math.cos(half)
        out[k, 0] = distance * math.cos(bisector)
        out[k, 1] = distance * math.sin(bisector)


@kernel("Tuple((float64[:, :], boolean))(float64[:, :], float64)")
def circumscribed_poles(polygon: Any, sign: float) -> Any:
    """(20): the poles of ``polygon``'s interior vertices (``_poles_into``), ``(n − 2, 2)``, and
    whether every edge has a positive length."""
    edges = max(polygon.shape[0] - 1, 0)
    positive = True
    for k in range(edges):
        ex = polygon[k + 1, 0] - polygon[k, 0]
        ey = polygon[k + 1, 1] - polygon[k, 1]
        if not hypot(ex, ey) > 0:
            positive = False
    out = np.empty((max(edges - 1, 0), 2))
    _poles_into(polygon, sign, out)
    return out, positive


@numba.njit(cache=True, error_model="numpy")
def _companions_into(
    h: float,
    d: float,
    recursion: Any,
    first: int,
    i_min: int,
    i_max: int,
    points: Any,
    centres: Any,
) -> Any:
    """The companions of a (D4b) construction in one pass over its ``recursion`` (cos β_j,
    sin β_j, p_j^y for j = first, first + 1, …): on i = i_min .. i_max + 1 the
    axis points x_i = (2di, 0), the tractrix d_i = x_i + h u_i, the Darboux transform
    e_i = 2d_i − x_i and the inscribed Gauss image n_i = J u_i = (u_i^y, −u_i^x), written into
    points[0] … points[3] (``(4, n + 1, 2)``), and the centres p_j = ((2j − 1)d, p_j^y),
    j = i_min − 1 .. i_max + 2, into ``centres`` (``(n + 3, 2)``, as ``construction._point_array``
    makes them); returns the contact points of their edges (``contact_points``, from
    i_min − 1), the circumscribed Gauss image (``_poles_into``) and whether every edge of p is
    positive.

    The operations and their order are those of ``construction._point_array``,
    ``darboux.reflect_in_points``, ``curvature.build`` and the kernels above, so each array has
    the bits the separate constructions give.
    """
    rows = i_max - i_min + 2
    cos_u, sin_u, centre_y = recursion
    axis, tractrix, darboux, inscribed = points[0], points[1], points[2], points[3]
    two_d = 2 * d
    for k in range(rows):
        i = float(i_min + k)
        c, s = cos_u[i_min + k - first], sin_u[i_min + k - first]
        axis[k, 0] = two_d * i
        axis[k, 1] = 0.0
        tractrix[k, 0] = two_d * i + h * c
        tractrix[k, 1] = 0.0 + h * s
        darboux[k, 0] = 2 * tractrix[k, 0] - axis[k, 0]
        darboux[k, 1] = 2 * tractrix[k, 1] - axis[k, 1]
        inscribed[k, 0] = s
        inscribed[k, 1] = -c
    for k in range(rows + 2):
        j = float(i_min - 1 + k)
        centres[k, 0] = (2 * j - 1) * d
        centres[k, 1] = centre_y[i_min - 1 + k - first]
    sign = 1.0 if centres[rows + 1, 0] >= centres[0, 0] else -1.0
    contact, positive = contact_points(centres, sign)
    poles = np.empty((rows, 2))
    _poles_into(centres, sign, poles)
    return contact, poles, positive


@kernel(
    "Tuple((float64[:, :], float64[:, :], float64[:, :], float64[:, :], float64[:, :],"
    " float64[:, :], boolean))"
    "(float64, float64, float64[:], float64[:], float64[:], int64, int64, int64)"
)
def d4b_companions(
    h: float,
    d: float,
    cos_u: Any,
    sin_u: Any,
    centre_y: Any,
    first: int,
    i_min: int,
    i_max: int,
) -> Any:
    """``_companions_into`` of a recursion: the axis points, the tractrix, the Darboux
    transform and the inscribed Gauss image (``(n + 1, 2)`` each, the rows of one array), the
    contact points, the circumscribed Gauss image and whether every edge of p is positive."""
    points = np.empty((4, i_max - i_min + 2, 2))
    recursion = (cos_u, sin_u, centre_y)
    centres = np.empty((i_max - i_min + 4, 2))
    contact, poles, positive = _companions_into(
        h, d, recursion, first, i_min, i_max, points, centres
    )
    return points[0], points[1], points[2], points[3], contact, poles, positive


@kernel(
    "Tuple((float64[:, :], float64[:, :, :], float64[:, :], float64[:, :], float64[:, :],"
    " boolean))(float64, float64, float64, float64, int64, int64, int64, int64)"
)
def d4b_construction(
    h: float, d: float, c0: float, s0: float, lo: int, hi: int, i_min: int, i_max: int
) -> Any:
    """A float64 (D4b) construction and its companions in one compiled call: the recursion
    (``construction._sticks`` over sticks lo .. hi, stick 0 pointing along (c0, s0)), then
    ``_companions_into`` on it: one dispatch for what a default small request returns, the same
    bits as the separate kernels. Each writes straight into the arrays returned (no array made
    and then copied: at 10^6 vertices those were 104 MB of fresh pages).

    Five arrays (each array handed back to Python costs about as much as a short pass): rows
    cos β_j, sin β_j, p_j^y of the recursion (from j = lo); the axis points, the tractrix, the
    Darboux transform and the inscribed Gauss image, ``(4, n + 1, 2)``; the centres p_j on
    j = i_min − 1 .. i_max + 2, ``(n + 3, 2)`` (p is its rows 1 .. n + 1); the contact points;
    the circumscribed Gauss image (``_poles_into``), ``(n, 2)``; and whether every edge of p is
    positive.
    """
    sticks = _sticks(h, d, c0, s0, lo, hi)
    points = np.empty((4, i_max - i_min + 2, 2))
    centres = np.empty((i_max - i_min + 4, 2))
    recursion = (sticks[0], sticks[1], sticks[2])
    contact, poles, positive = _companions_into(h, d, recursion, lo, i_min, i_max, points, centres)
    return sticks, points, centres, contact, poles, positive
