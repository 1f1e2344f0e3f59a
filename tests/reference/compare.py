"""Comparing computed points with a reference at the reference's own precision."""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from typing import Any

import mpmath

_CTX = mpmath.MPContext()
_CTX.dps = 80


def worst_relative(points: Any, reference: Mapping[int, Any], indices: Iterable[int]) -> float:
    """Largest |p_i − r_i| / |r_i| over the indices (points aligned with ``indices``).

    A reference point at the origin is compared absolutely.

    Everything is converted to an 80-digit context first, so that mp results are compared at
    their own precision (mixing mpmath contexts would round to the global 15 digits).
    """
    worst = _CTX.mpf(0)
    for k, i in enumerate(indices):
        px, py = (_CTX.mpf(v) for v in points[k])
        rx, ry = (_CTX.mpf(v) for v in reference[i])
        size = _CTX.sqrt(rx**2 + ry**2)
        gap = _CTX.sqrt((px - rx) ** 2 + (py - ry) ** 2)
        worst = max(worst, gap / size if size else gap)  # the origin: absolute
    return float(worst)
