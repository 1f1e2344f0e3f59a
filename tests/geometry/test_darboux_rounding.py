"""Darboux's edge lengths as squares (session 22) on true (D4b) transforms, where every block
takes them: special values at and beside the blocks' edges fall back to the old passes with
the same NaN, a perturbed transform keeps its bits, and every residual stays within ``ULPS``
units of (l + l') / size of the old one."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest

from app.geometry import darboux
from app.geometry.compiled import INF_BITS
from app.geometry.d4b import discretization as d4b
from app.geometry.precision import Float64
from tests.geometry.bits import same_bits
from tests.geometry.test_darboux_kernels import BLOCK, assert_equal_old, old_edge_lengths


def true_transform(h: float = 1.0, ratio: float = 0.5) -> tuple[Any, Any, float]:
    data = d4b.polygons(Float64(), h, h * ratio, None, -(BLOCK + 300), BLOCK + 300)
    n = data.vertices
    return np.array(data.axis[:n]), np.array(data.darboux[:n]), 2 * h


def test_true_transforms_take_the_squares() -> None:
    for h, ratio in ((1.0, 0.5), (100.0, 1e-4), (1.0, 0.99)):
        x, e, expected = true_transform(h, ratio)
        target = np.empty(BLOCK)
        for start in range(0, len(x) - 1, BLOCK):
            count = min(BLOCK, len(x) - 1 - start)
            assert darboux._edge_squares_block(x, e, start, count, target) < INF_BITS
        assert_equal_old(x, e, expected)


@pytest.mark.parametrize(
    "value", [math.nan, math.inf, -math.inf, 0.0, -0.0, 5e-324, -2.2e-310, 1e300, -1.7e308]
)
def test_special_values_at_block_edges(value: float) -> None:
    x, e, expected = true_transform()
    for where in (0, 1, BLOCK - 1, BLOCK, BLOCK + 1, len(x) - 1):
        for target, column in ((0, 0), (1, 1)):
            xx, ee = x.copy(), e.copy()
            (xx, ee)[target][where, column] = value
            assert_equal_old(xx, ee, expected)


def test_perturbed_and_degenerate_transforms_keep_their_bits() -> None:
    """Edges whose lengths differ by more than 2^-26 relative, and zero-length edges, take the
    old passes: the same bits."""
    x, e, _ = true_transform()
    e = e * (1 + np.random.default_rng(22).normal(size=e.shape) * 1e-6)
    assert same_bits(darboux.edge_length_residuals(Float64(), x, e), old_edge_lengths(x, e))
    x[BLOCK : BLOCK + 3] = x[BLOCK]
    e[BLOCK : BLOCK + 3] = e[BLOCK]
    assert_equal_old(x, e, 2.0)


@pytest.mark.parametrize("count", [0, 1, 2, BLOCK - 1, BLOCK, BLOCK + 1])
def test_counts_and_block_edges(count: int) -> None:
    x, e, expected = true_transform()
    assert_equal_old(x[:count], e[:count], expected)
