"""Shared by the tests that compare a compiled pass with the code it replaced, bit for bit."""

from __future__ import annotations

from typing import Any

import numpy as np

#: (h, d/h, β0, i_min, i_max) of (D4b) polygons whose residuals span the cases of the float64
#: passes: d = 0.5h, 1e-4h (steep, long), 0.99h, h = 100, tilted starts.
D4B_POLYGONS = (
    (1.0, 0.5, None, -3000, 3000),
    (100.0, 1e-4, None, -20000, 20000),
    (100.0, 0.99, 0.4, -2000, 2500),
    (1.0, 0.3, 2.5, -9000, 100),
)


def same_bits(a: Any, b: Any) -> bool:
    """Equal as float64, bit for bit: the same shape and bytes (a NaN's pattern and the sign of
    zero included); None only equal to None."""
    if a is None or b is None:
        return a is b
    a, b = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
    return a.shape == b.shape and a.tobytes() == b.tobytes()
