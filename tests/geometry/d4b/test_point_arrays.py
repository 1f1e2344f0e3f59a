"""The construction's point arrays, one loop per array (session 21), equal the one loop with
branches they replaced, bit for bit."""

from __future__ import annotations

from typing import Any

import numba
import numpy as np
import pytest

from app.geometry.d4b import construction


@numba.njit(cache=False, error_model="numpy")
def old_point_array(
    which: int, h: float, d: float, cos_u: Any, sin_u: Any, centre_y: Any, first: int,
    i_min: int, i_max: int,
) -> Any:  # fmt: skip
    """``construction._point_array`` before session 21."""
    n = i_max - i_min + 1
    out = np.empty((n, 2))
    two_d = 2 * d
    for k in range(n):
        i = float(i_min + k)
        c, s = cos_u[first + k], sin_u[first + k]
        if which == 0:
            out[k, 0] = two_d * i
            out[k, 1] = 0.0
        elif which == 1:
            out[k, 0] = two_d * i + h * c
            out[k, 1] = 0.0 + h * s
        elif which == 2:
            out[k, 0] = (2 * i - 1) * d
            out[k, 1] = centre_y[first + k]
        else:
            out[k, 0] = c
            out[k, 1] = s
    return out


@pytest.mark.parametrize("seed", [1, 2])
def test_point_arrays_equal_the_old_loop(seed: int) -> None:
    rng = np.random.default_rng(seed)
    for size in (1, 2, 7, 1000):
        cos_u = rng.normal(size=size + 5)
        sin_u = rng.normal(size=size + 5)
        centre_y = rng.normal(size=size + 5)
        for specials in ((np.nan, -0.0), (np.inf, 5e-324), (-np.inf, 1e308)):
            cos_u[rng.integers(0, size + 5)] = specials[0]
            sin_u[rng.integers(0, size + 5)] = specials[1]
            centre_y[rng.integers(0, size + 5)] = specials[0]
            for which in range(4):
                for h, d, first, i_min in (
                    (1.0, 1e-4, 0, -3),
                    (100.0, 99.0, 5, 10**9),
                    (0.5, 0.25, 2, 0),
                ):
                    i_max = i_min + size - 1
                    args = (which, h, d, cos_u, sin_u, centre_y, min(first, 5), i_min, i_max)
                    found = construction._point_array(*args)
                    expected = old_point_array(*args)
                    assert found.shape == expected.shape
                    assert found.tobytes() == expected.tobytes()


def test_constructed_polygon_points() -> None:
    """The four arrays of a long construction (the real inputs)."""
    from app.geometry.precision import Float64

    built = construction.construct(Float64(), 1.0, 1e-3, 0.7, -20000, 15000)
    assert built.recursion is not None
    h, d, cos_u, sin_u, centre_y, lo = built.recursion
    for which in range(4):  # entry i_min − lo is stick i_min (``from_sticks``)
        args = (which, h, d, cos_u, sin_u, centre_y, built.i_min - lo, built.i_min, built.i_max)
        assert construction._point_array(*args).tobytes() == old_point_array(*args).tobytes()
