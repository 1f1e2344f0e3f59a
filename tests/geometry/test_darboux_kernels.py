"""The Darboux residuals' float64 passes in blocks without branches (session 21) equal the
one-pass kernels they replaced: the distances bit for bit, the edge lengths' residuals (squares
without a square root since session 22) to ``ULPS`` units of (l + l') / size; NaN's rules."""

from __future__ import annotations

import math
from typing import Any

import numba
import numpy as np
import pytest

from app.geometry import darboux
from app.geometry.checks import Largest
from app.geometry.compiled import length
from app.geometry.d4b import discretization as d4b
from app.geometry.precision import Float64
from tests.geometry.bits import D4B_POLYGONS, assert_within_ulps, same_bits

BLOCK = darboux.DARBOUX_BLOCK


@numba.njit(cache=False, error_model="numpy")
def old_edge_lengths(x: Any, e: Any) -> Any:
    """``darboux._edge_length_residuals`` before session 21."""
    out = np.empty(max(x.shape[0] - 1, 0))
    for k in range(x.shape[0] - 1):
        ex = length(x[k + 1, 0] - x[k, 0], x[k + 1, 1] - x[k, 1])
        ee = length(e[k + 1, 0] - e[k, 0], e[k + 1, 1] - e[k, 1])
        size = abs(x[k + 1, 0]) + abs(x[k + 1, 1]) + abs(x[k, 0]) + abs(x[k, 1])
        size = size + abs(e[k + 1, 0]) + abs(e[k + 1, 1]) + abs(e[k, 0]) + abs(e[k, 1])
        out[k] = abs(ee - ex) / size
    return out


@numba.njit(cache=False, error_model="numpy")
def old_distances(x: Any, e: Any, expected: float) -> Any:
    """``darboux._distance_residuals`` before session 21."""
    out = np.empty(x.shape[0])
    for k in range(x.shape[0]):
        distance = length(x[k, 0] - e[k, 0], x[k, 1] - e[k, 1])
        size = abs(x[k, 0]) + abs(x[k, 1]) + abs(e[k, 0]) + abs(e[k, 1])
        out[k] = abs(distance - expected) / size
    return out


#: How far an edge's residual may move (session 22: |l² − l'²| / √(2(l² + l'²)) instead of
#: |l − l'|), in units of (l + l') / size: each way is within about one of the exact value.
ULPS = 8


def edge_scale(x: Any, e: Any) -> Any:
    """(|x_{k+1} − x_k| + |e_{k+1} − e_k|) / size per edge: what an edge residual's rounding is
    measured against."""
    with np.errstate(all="ignore"):
        lengths = np.hypot(*(x[1:] - x[:-1]).T) + np.hypot(*(e[1:] - e[:-1]).T)
        size = abs(x[1:]).sum(axis=1) + abs(x[:-1]).sum(axis=1)
        return lengths / (size + abs(e[1:]).sum(axis=1) + abs(e[:-1]).sum(axis=1))


def assert_near(found: Any, expected: Any, scale: Any) -> None:
    """``ULPS`` units of ``scale`` apart entry by entry, NaN exactly where expected is."""
    assert_within_ulps(found, expected, scale, ULPS)


def old_largest(values: Any) -> float:
    """``checks.largest_magnitude`` as the checks took it of the arrays (NaN if one is NaN)."""
    return float(np.max(np.abs(values))) if len(values) else 0.0


def assert_equal_old(x: Any, e: Any, expected: float) -> None:
    ar = Float64()
    with np.errstate(all="ignore"):
        edges, distances = old_edge_lengths(x, e), old_distances(x, e, expected)
        found_edges = darboux.edge_length_residuals(ar, x, e)
        found_distances = darboux.distance_residuals(ar, x, e, expected)
        largest_edges = darboux.edge_length_largest(x, e)
        largest_distances = darboux.distance_largest(x, e, expected)
        assert isinstance(largest_edges, Largest) and isinstance(largest_distances, Largest)
        scale = edge_scale(x, e)
        assert_near(found_edges, edges, scale)
        assert same_bits(found_distances, distances)
        top = np.max(scale) if len(scale) and not np.isnan(scale).any() else np.inf
        assert_near(largest_edges.value, old_largest(edges), top)
        assert same_bits(largest_edges.value, old_largest(found_edges))
        assert same_bits(largest_distances.value, old_largest(distances))
        assert len(largest_edges) == len(edges) and len(largest_distances) == len(distances)
        assert same_bits(largest_edges.residuals(), found_edges)
        assert same_bits(largest_distances.residuals(), distances)


def test_real_polygons() -> None:
    """The (D4b) axis and Darboux transform: d = 0.5h, 1e-4h, 0.99h, h = 100, tilted starts."""
    ar = Float64()
    for h, ratio, beta0, lo, hi in D4B_POLYGONS:
        data = d4b.polygons(ar, h, h * ratio, beta0, lo, hi)
        n = data.vertices
        assert_equal_old(data.axis[:n], data.darboux[:n], 2 * h)


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_random_points(seed: int) -> None:
    """Random points of every scale (hypot's ranges in whole blocks too), counts 0, 1, 2,
    a block and one past it."""
    rng = np.random.default_rng(seed)
    for n in (0, 1, 2, 3, BLOCK - 1, BLOCK, BLOCK + 1, 2 * BLOCK + 7):
        for scale in (1.0, 1e-150, 1e150, 2.0**-490, 2.0**490, 1e-310):
            x = rng.normal(size=(n, 2)) * scale
            e = x + rng.normal(size=(n, 2)) * scale * rng.uniform(1e-8, 1)
            assert_equal_old(x, e, float(rng.uniform(0, 2)) * scale)


def test_adversarial_points() -> None:
    """NaN, ±inf, zero-length edges, ±0, subnormal and huge coordinates at the edges of blocks
    and inside them."""
    rng = np.random.default_rng(21)
    n = 2 * BLOCK + 5
    specials = (np.nan, np.inf, -np.inf, 0.0, -0.0, 5e-324, -2.2e-310, 1e300, -1.7e308, 2.0**-500)
    for value in specials:
        for where in (0, 1, BLOCK - 1, BLOCK, BLOCK + 1, 2 * BLOCK - 1, 2 * BLOCK, n - 1, 77):
            x, e = rng.normal(size=(n, 2)), rng.normal(size=(n, 2))
            target = (x, e)[where % 2]
            target[where, where % 3 % 2] = value
            assert_equal_old(x, e, 1.5)
    x = rng.normal(size=(n, 2))
    x[100:200] = x[100]  # zero-length edges
    assert_equal_old(x, x.copy(), 0.0)
    assert_equal_old(x, -x, 1.0)
    assert_equal_old(np.zeros((n, 2)), -np.zeros((n, 2)), 0.0)  # 0/0 everywhere


def test_layouts() -> None:
    """Points that are not C-contiguous are copied: the same bits."""
    rng = np.random.default_rng(4)
    x, e = rng.normal(size=(5000, 2)), rng.normal(size=(5000, 2))
    wide = np.zeros((5000, 3))
    wide[:, 1:] = e
    edges, distances = old_edge_lengths(x, e), old_distances(x, e, 0.5)
    ar = Float64()
    for xx, ee in ((np.asfortranarray(x), e), (x, wide[:, 1:])):
        assert same_bits(darboux.edge_length_residuals(ar, xx, ee), edges)
        assert same_bits(darboux.distance_residuals(ar, xx, ee, 0.5), distances)
        assert same_bits(darboux.edge_length_largest(xx, ee).value, old_largest(edges))
        assert same_bits(darboux.distance_largest(xx, ee, 0.5).value, old_largest(distances))


def test_nan_largest() -> None:
    x = np.random.default_rng(3).normal(size=(BLOCK + 10, 2))
    e = x + 1
    e[BLOCK + 3, 0] = np.nan
    assert math.isnan(darboux.edge_length_largest(x, e).value)
    assert math.isnan(darboux.distance_largest(x, e, 1.0).value)
