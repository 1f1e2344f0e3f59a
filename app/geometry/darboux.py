"""Darboux transforms of the axis polygon (x_i) by reflection, (D4a) and (D4b), Section 3.

A polygon (e_i) is a Darboux transform of (x_i) when |x_i − e_i| is constant and corresponding
edges have equal length, |e_i − e_{i+1}| = |x_i − x_{i+1}|.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from app.geometry.checks import point_distance
from app.geometry.compiled import kernel, length
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
    if ar.mode == "float64":  # the same operations in one compiled pass
        return _edge_length_residuals(_f64(x), _f64(e))
    ex = point_distance(ar, x[1:], x[:-1])
    ee = point_distance(ar, e[1:], e[:-1])
    return abs(ee - ex) / magnitude(x[1:], x[:-1], e[1:], e[:-1])


def distance_residuals(ar: Arithmetic, x: Array, e: Array, expected: object) -> Array:
    """| |x_i − e_i| − expected | relative to the magnitude of x_i and e_i; ``(n,)``."""
    if ar.mode == "float64":  # the same operations in one compiled pass
        return _distance_residuals(_f64(x), _f64(e), float(expected))  # type: ignore[arg-type]
    return abs(point_distance(ar, x, e) - expected) / magnitude(x, e)


def mean(values: Array) -> object:
    """Arithmetic mean of an ``(n,)`` array in its own precision."""
    return np.sum(values) / len(values)


def _f64(points: Array) -> Any:
    return np.asarray(points, dtype=np.float64)


@kernel("float64[:](float64[:, :], float64[:, :])")
def _edge_length_residuals(x: Any, e: Any) -> Any:
    """``edge_length_residuals`` entry by entry, the lengths by ``compiled.length`` (the square
    root of the sum of squares, within 2 ulp of libm's hypot, which costs ≈ 4.7 ns an entry
    here against ≈ 1.8; hypot where squares overflow or underflow)."""
    out = np.empty(max(x.shape[0] - 1, 0))
    for k in range(x.shape[0] - 1):
        ex = length(x[k + 1, 0] - x[k, 0], x[k + 1, 1] - x[k, 1])
        ee = length(e[k + 1, 0] - e[k, 0], e[k + 1, 1] - e[k, 1])
        size = abs(x[k + 1, 0]) + abs(x[k + 1, 1]) + abs(x[k, 0]) + abs(x[k, 1])
        size = size + abs(e[k + 1, 0]) + abs(e[k + 1, 1]) + abs(e[k, 0]) + abs(e[k, 1])
        out[k] = abs(ee - ex) / size
    return out


@kernel("float64[:](float64[:, :], float64[:, :], float64)")
def _distance_residuals(x: Any, e: Any, expected: float) -> Any:
    """``distance_residuals`` entry by entry, the distance by ``compiled.length``."""
    out = np.empty(x.shape[0])
    for k in range(x.shape[0]):
        distance = length(x[k, 0] - e[k, 0], x[k, 1] - e[k, 1])
        size = abs(x[k, 0]) + abs(x[k, 1]) + abs(e[k, 0]) + abs(e[k, 1])
        out[k] = abs(distance - expected) / size
    return out
