"""The construction of Nikolaides, (S4) and its discrete versions (D4a), (D4b).

In the smooth case the triangle (x, 0), p(x), d(x) has a right angle at d(x): the evolute p of
the tractrix d lies on the tractrix normal. Discretely the normal at d_i is the edge p_i p_{i+1}.
"""

from __future__ import annotations

from app.geometry.polygon import magnitude
from app.geometry.precision import Array


def right_angle_residuals(vertex: Array, a: Array, b: Array) -> Array:
    """|(a_i − v_i)·(b_i − v_i)| / (|a_i, v_i| · |b_i, v_i|): zero when the angle at v_i is right.

    |a, v| is the sum of the absolute coordinates of a_i and v_i, an upper bound of |a_i − v_i|
    and the size against which the stored points resolve that vector (see ``polygon``); for
    points near the origin the residual is at most |cos| of the angle. ``(n, 2) -> (n,)``.
    """
    u = a - vertex
    w = b - vertex
    dot = u[:, 0] * w[:, 0] + u[:, 1] * w[:, 1]
    return abs(dot) / (magnitude(a, vertex) * magnitude(b, vertex))
