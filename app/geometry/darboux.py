"""Darboux transforms of the axis polygon (x_i) by reflection, (D4a) and (D4b), Section 3.

A polygon (e_i) is a Darboux transform of (x_i) when |x_i − e_i| is constant and corresponding
edges have equal length, |e_i − e_{i+1}| = |x_i − x_{i+1}|.
"""

from __future__ import annotations

import numpy as np

from app.geometry.checks import point_distance
from app.geometry.polygon import magnitude
from app.geometry.precision import Arithmetic, Array


def reflect_in_points(x: Array, centres: Array) -> Array:
    """e_i = 2c_i − x_i, the reflection of x_i in c_i ((D4b): c_i = d_i); ``(n, 2)``."""
    return 2 * centres - x


def edge_length_residuals(ar: Arithmetic, x: Array, e: Array) -> Array:
    """| |e_{i+1} − e_i| − |x_{i+1} − x_i| | relative to the four points' magnitude; ``(n-1,)``.

    The magnitude (sum of absolute coordinates, at least the edge length) is what the stored
    points resolve a short edge against, see ``polygon``.
    """
    ex = point_distance(ar, x[1:], x[:-1])
    ee = point_distance(ar, e[1:], e[:-1])
    return abs(ee - ex) / magnitude(x[1:], x[:-1], e[1:], e[:-1])


def distance_residuals(ar: Arithmetic, x: Array, e: Array, expected: object) -> Array:
    """| |x_i − e_i| − expected | relative to the magnitude of x_i and e_i; ``(n,)``."""
    return abs(point_distance(ar, x, e) - expected) / magnitude(x, e)


def mean(values: Array) -> object:
    """Arithmetic mean of an ``(n,)`` array in its own precision."""
    return np.sum(values) / len(values)
