"""Elementary quantities of a planar polygon (p_i): the paper's Section 3 notation.

For ``(n, 2)`` vertex arrays ``p`` with consecutive indices:
- ``second_difference(y)[k]`` is Δ²y_i = y_{i+2} − 2y_{i+1} + y_i for the k-th index i;
- ``edge_lengths(p)[k]`` is l_i = |p_{i+1} − p_i|;
- ``signed_areas(p)[k]`` is A_i, the signed trapezoid area between the edge p_i p_{i+1} and the
  x-axis: (p_i^y + p_{i+1}^y)/2 · (p_{i+1}^x − p_i^x), positive above the axis for increasing x.

The ``*_magnitude`` functions give the size of the stored numbers that a quantity is computed
from. Vertices far from the origin determine short edges only to eps·|coordinates|, so residuals
are measured against these magnitudes (see ``conditions``).
"""

from __future__ import annotations

from app.geometry.precision import Arithmetic, Array


def second_difference(y: Array) -> Array:
    """Δ²y_i = y_{i+2} − 2y_{i+1} + y_i (Section 3, (D1)); ``(n,) -> (n-2,)``."""
    return y[2:] - 2 * y[1:-1] + y[:-2]


def second_difference_magnitude(y: Array) -> Array:
    """|y_i| + 2|y_{i+1}| + |y_{i+2}|, the size of the terms of Δ²y_i; ``(n-2,)``."""
    a = abs(y)
    return a[2:] + 2 * a[1:-1] + a[:-2]


def edge_vectors(p: Array) -> Array:
    """p_{i+1} − p_i; ``(n, 2) -> (n-1, 2)``."""
    return p[1:] - p[:-1]


def edge_lengths(ar: Arithmetic, p: Array) -> Array:
    """l_i = |p_{i+1} − p_i| (Section 3); ``(n, 2) -> (n-1,)``."""
    e = edge_vectors(p)
    return ar.hypot(e[:, 0], e[:, 1])


def magnitude(*points: Array) -> Array:
    """Sum of the absolute coordinates of the given ``(n, 2)`` point arrays; ``(n,)``."""
    total = abs(points[0][:, 0]) + abs(points[0][:, 1])
    for q in points[1:]:
        total = total + abs(q[:, 0]) + abs(q[:, 1])
    return total


def edge_magnitude(p: Array) -> Array:
    """|p_i^x| + |p_i^y| + |p_{i+1}^x| + |p_{i+1}^y| (bounds l_i); ``(n-1,)``."""
    return magnitude(p[:-1], p[1:])


def signed_areas(p: Array) -> Array:
    """A_i, signed trapezoid area under the edge p_i p_{i+1} ((D3), eq. (2)); ``(n-1,)``."""
    return (p[:-1, 1] + p[1:, 1]) / 2 * (p[1:, 0] - p[:-1, 0])


def area_magnitude(p: Array) -> Array:
    """(|p_i^y| + |p_{i+1}^y|)/2 · (|p_i^x| + |p_{i+1}^x|) (bounds |A_i|); ``(n-1,)``."""
    return (abs(p[:-1, 1]) + abs(p[1:, 1])) / 2 * (abs(p[:-1, 0]) + abs(p[1:, 0]))
