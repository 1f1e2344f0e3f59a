"""The defining conditions (D1), (D3) and eq. (2) as residuals of a polygon, with fitted constants.

Each condition has the form lhs_i = c · rhs_i for one constant c > 0. ``fit`` finds c by least
squares and reports, for each equation, |lhs_i − c·rhs_i| / (|lhs|_i + |c|·|rhs|_i), where
|lhs|_i and |rhs|_i are the magnitudes of the stored numbers the two sides are computed from
(``polygon.*_magnitude``). So a residual is relative to what the data can resolve: cancellation
in Δ² or in the edges of vertices far from the origin does not inflate it, and a polygon that
misses the condition by a relative δ shows a residual of about δ.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from app.geometry.polygon import (
    area_magnitude,
    edge_lengths,
    edge_magnitude,
    second_difference,
    second_difference_magnitude,
    signed_areas,
)
from app.geometry.precision import Arithmetic, Array, Scalar


@dataclass(frozen=True)
class ConditionFit:
    """Fitted constant and per-equation residuals of one condition on one polygon."""

    constant: Scalar | None
    """Least-squares constant; ``None`` when every right-hand side vanishes."""
    residuals: Array
    """``(m,)`` relative residuals; equation k has index i = i_min + k."""

    def indices(self, i_min: int) -> np.ndarray[Any, np.dtype[np.int64]]:
        """The index i of each equation."""
        return np.arange(i_min, i_min + len(self.residuals), dtype=np.int64)


def fit(
    ar: Arithmetic, lhs: Array, rhs: Array, lhs_magnitude: Array, rhs_magnitude: Array
) -> ConditionFit:
    """Least-squares c in lhs = c·rhs and the relative residuals; all arrays ``(m,)``."""
    tiny = ar.scalar(np.finfo(np.float64).tiny)
    weight = np.where(lhs_magnitude > tiny, lhs_magnitude, tiny)
    u, v = lhs / weight, rhs / weight
    largest = np.max(abs(v)) if len(v) else ar.scalar(0)
    if largest > 0:  # scaled so that the squares cannot overflow
        u, v = u / largest, v / largest
    vv = np.sum(v * v) if len(v) else ar.scalar(0)
    constant = np.sum(u * v) / vv if vv > 0 else None
    c = constant if constant is not None else ar.scalar(0)
    scale = lhs_magnitude + abs(c) * rhs_magnitude
    scale = np.where(scale > tiny, scale, tiny)
    return ConditionFit(constant, abs(lhs - c * rhs) / scale)


def d1(ar: Arithmetic, p: Array) -> ConditionFit:
    """(D1): Δ²p_i^y = c (l_i + l_{i+1}); equations i = i_min .. i_max − 2."""
    y = p[:, 1]
    lengths = edge_lengths(ar, p)
    sizes = edge_magnitude(p)
    return fit(
        ar,
        second_difference(y),
        lengths[:-1] + lengths[1:],
        second_difference_magnitude(y),
        sizes[:-1] + sizes[1:],
    )


def d3(ar: Arithmetic, p: Array) -> ConditionFit:
    """(D3): A_i = c l_i; equations i = i_min .. i_max − 1."""
    return fit(ar, signed_areas(p), edge_lengths(ar, p), area_magnitude(p), edge_magnitude(p))


def equation_2(ar: Arithmetic, p: Array) -> ConditionFit:
    """Eq. (2): Δ²p_i^y = c (A_i + A_{i+1}); equations i = i_min .. i_max − 2."""
    y = p[:, 1]
    areas = signed_areas(p)
    sizes = area_magnitude(p)
    return fit(
        ar,
        second_difference(y),
        areas[:-1] + areas[1:],
        second_difference_magnitude(y),
        sizes[:-1] + sizes[1:],
    )


def equilibrium(ar: Arithmetic, p: Array) -> ConditionFit:
    """Hanging sticks in equilibrium: k_{i+1} − k_i = c (l_i + l_{i+1}) for the edge slopes k_i.

    Homogeneous sticks on the edges (weight w per length), joined by weightless hinges: each
    stick's moment balance puts half of its weight on each end, and the hinge balance with a
    constant horizontal tension T gives T (k_{i+1} − k_i) = (w/2)(l_i + l_{i+1}), so c = w/(2T).
    With constant spacing δ this is (D1) divided by δ. For polygons with increasing x;
    equations i = i_min .. i_max − 2. A slope's magnitude is (|y_i| + |y_{i+1}| + |k_i|(|x_i| +
    |x_{i+1}|))/|x_{i+1} − x_i|, the size of the numbers it is computed from.
    """
    x, y = p[:, 0], p[:, 1]
    dx = x[1:] - x[:-1]
    slopes = (y[1:] - y[:-1]) / dx
    sizes = (abs(y[1:]) + abs(y[:-1]) + abs(slopes) * (abs(x[1:]) + abs(x[:-1]))) / abs(dx)
    lengths = edge_lengths(ar, p)
    edge_sizes = edge_magnitude(p)
    return fit(
        ar,
        slopes[1:] - slopes[:-1],
        lengths[:-1] + lengths[1:],
        sizes[:-1] + sizes[1:],
        edge_sizes[:-1] + edge_sizes[1:],
    )
