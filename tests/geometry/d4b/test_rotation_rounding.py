"""Theorem 4's rotation angle as one argument (session 22) on true polygons, where it takes the
quotient without an atan2: special values at and beside the blocks' edges fall back to the old
three atan2 with the same NaN and None, a vertex whose angles could wrap keeps its old residual
bit for bit, a perturbed polygon takes one atan2 a vertex, and every residual stays within
``ULPS`` units of the angles of the old ones."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest

from app.geometry.d4b import discretization as d4b, residual_kernels
from app.geometry.precision import Float64
from tests.geometry.bits import same_bits
from tests.geometry.d4b.test_rotation_angle import (
    angle_scale,
    assert_blocks_equal_old,
    old_rotation_angles,
)

BLOCK = 64


def true_polygon(d_ratio: float = 0.5) -> tuple[float, Any, Any, int]:
    data = d4b.polygons(Float64(), 1.0, d_ratio, None, -150, 150)
    return d_ratio, np.array(data.p), np.array(data.axis), data.vertices - 1


def test_true_polygons_take_the_quotient() -> None:
    """A true polygon's blocks are not taken as before, and with a small d every block is small
    (outcome 0: no atan2; at d = 1e-3h, 0.5h some of the printed erratum's residuals are not);
    the residuals near the old ones (also at d = 0.99h, whose coinciding vertices take the old
    blocks)."""
    for ratio in (0.5, 1e-3, 1e-4, 0.99):
        d, p, axis, n = true_polygon(ratio)
        rows = np.empty((6, BLOCK))
        for first in range(1, n, BLOCK):
            stop = min(first + BLOCK, n)
            outcome = residual_kernels._rotation_terms(d, p, axis, first, stop, rows)
            if ratio == 1e-4:
                assert outcome == 0
            elif ratio < 0.9:
                assert outcome != residual_kernels.ROTATION_OLD
        assert_blocks_equal_old(d, p, axis, n, (BLOCK, BLOCK - 1, BLOCK + 1, 1, 8192))


@pytest.mark.parametrize(
    "value", [math.nan, math.inf, -math.inf, 0.0, -0.0, 5e-324, -2.2e-310, 1e300, -1.7e308]
)
def test_special_values_at_block_edges(value: float) -> None:
    d, p, axis, n = true_polygon()
    for where in (0, 1, BLOCK - 1, BLOCK, BLOCK + 1, 2 * BLOCK, n - 1, n):
        for target, column in ((0, 0), (0, 1), (1, 0), (1, 1)):
            pp, aa = p.copy(), axis.copy()
            (pp, aa)[target][where, column] = value
            assert_blocks_equal_old(d, pp, aa, n, (BLOCK,))
            if math.isnan(value):
                largest, worst = residual_kernels.rotation_angle_largest(d, pp, aa, n)
                old = old_rotation_angles(d, pp, aa, n, BLOCK)
                assert math.isnan(largest.value) == math.isnan(old[2])
                assert (worst is None) == (not math.isfinite(old[3]))


def test_angles_that_could_wrap_keep_their_bits() -> None:
    """Heights below |d| (d < 0: 2 atan2(d, p^y) near −π) and dot products below 0: such a
    block is taken as before, the residuals near 2π kept bit for bit."""
    d, p, axis, n = true_polygon()
    p[BLOCK + 5, 1] = 0.01  # vertex BLOCK + 5, the fifth of the second block: residual BLOCK + 4
    axis[BLOCK + 4] = p[BLOCK + 5] + [1.0, 0.0]  # a
    axis[BLOCK + 5] = p[BLOCK + 5] + [-1.0, 0.001]  # b: the angle π − 0.001
    for dd in (-d, d):  # 2 atan2(d, 0.01) = ∓(π − 0.04): the difference 2π − 0.04 or 0.04
        found = residual_kernels._rotation_angles(dd, p, axis, n, True, BLOCK)
        old = old_rotation_angles(dd, p, axis, n, BLOCK)
        second = slice(BLOCK, 2 * BLOCK)
        assert same_bits(found[0][second], old[0][second])
        assert same_bits(found[1][second], old[1][second])
        assert (found[0][BLOCK + 4] > 6) == (dd < 0)
        assert_blocks_equal_old(dd, p, axis, n, (BLOCK,))


def test_perturbed_polygons_take_one_atan2() -> None:
    """Residuals above 2^-27 (a perturbed axis): one atan2 a vertex (numpy's for a long block,
    libm's for a short one), near the old residuals; the largest unchanged where a check's
    verdict reads it."""
    d, p, axis, n = true_polygon()
    rng = np.random.default_rng(22)
    axis = axis * (1 + rng.normal(size=axis.shape) * 1e-4)
    rows = np.empty((6, n))
    assert residual_kernels._rotation_terms(d, p, axis, 1, n, rows) == (
        residual_kernels.ROTATION_WRAPPED
    )
    for block in (BLOCK, 8192):
        assert_blocks_equal_old(d, p, axis, n, (block,))
    scale, _ = angle_scale(d, p, axis, n)
    found = residual_kernels.rotation_angles(d, p, axis, n)[0]
    assert found.max() > 1e-6 and np.all(found <= scale + np.spacing(scale) * 16)


@pytest.mark.parametrize("n", [0, 1, 2, 3, BLOCK - 1, BLOCK, BLOCK + 1, BLOCK + 2])
def test_counts_and_block_edges(n: int) -> None:
    d, p, axis, _ = true_polygon()
    p, axis = p[: n + 1], axis[: n + 1]
    assert_blocks_equal_old(d, p, axis, n, (BLOCK, 1, 7))
    largest, worst = residual_kernels.rotation_angle_largest(d, p, axis, n)
    assert len(largest) == max(n - 1, 0)
    assert (worst is None) == (n < 2)
