"""Shared by the tests that compare a compiled pass with the code it replaced: bit for bit, or
within a few units in the last place where the new pass rounds differently."""

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


BIG = float(np.finfo(np.float64).max)


def assert_within_ulps(found: Any, expected: Any, scale: Any, ulps: float) -> None:
    """``found`` within ``ulps`` units in the last place of ``scale`` of ``expected``, entry by
    entry (``scale`` an entry each or one for all; a NaN or infinite scale is read as the largest
    float, whose spacing is inf: any difference is allowed there), NaN exactly where expected
    has NaN."""
    found, expected = np.atleast_1d(found), np.atleast_1d(expected)
    assert found.shape == expected.shape
    nan = np.isnan(expected)
    assert (np.isnan(found) == nan).all(), (found, expected)
    with np.errstate(all="ignore"):
        room = ulps * np.spacing(np.nan_to_num(np.atleast_1d(scale), nan=BIG, posinf=BIG))
    room = np.broadcast_to(room, found.shape)
    assert (abs(found[~nan] - expected[~nan]) <= room[~nan]).all(), (found, expected)
