"""Theorem 4's rotation angle in blocks without branches (session 21) and as one argument
(session 22) agrees with the passes it replaced: the residuals to a few units in the last place
of the angles (``ULPS``), their largest likewise, and NaN where they had NaN."""

from __future__ import annotations

import math
from typing import Any

import numba
import numpy as np
import pytest

from app.geometry import elementary
from app.geometry.compiled import running_largest
from app.geometry.d4b import discretization as d4b, residual_kernels
from app.geometry.precision import Float64
from tests.geometry.bits import D4B_POLYGONS, assert_within_ulps, same_bits


@numba.njit(cache=False, error_model="numpy")
def _old_arguments(p: Any, axis: Any, start: int, stop: int, rows: Any) -> None:
    """``residual_kernels._rotation_arguments`` before session 21 (any layout)."""
    for k in range(start, stop):
        j = k - start
        px, py = p[k, 0], p[k, 1]
        ax, ay = axis[k - 1, 0] - px, axis[k - 1, 1] - py
        bx, by = axis[k, 0] - px, axis[k, 1] - py
        cx, cy = axis[k + 1, 0] - px, axis[k + 1, 1] - py
        rows[0, j] = py
        rows[1, j] = ax * by - ay * bx
        rows[2, j] = ax * bx + ay * by
        rows[3, j] = bx * cy - by * cx
        rows[4, j] = bx * cx + by * cy


@numba.njit(cache=False, error_model="numpy")
def _old_residuals(
    angles: Any,
    count: int,
    largest: float,
    largest_printed: float,
    corrected: Any,
    printed: Any,
    offset: int,
    store: bool,
) -> tuple[float, float]:
    """``residual_kernels._rotation_residuals`` before session 21 (a running largest)."""
    for j in range(count):
        formula = 2 * angles[0, j]
        residual = abs(angles[1, j] - formula)
        residual_printed = abs(angles[2, j] - formula)
        largest = running_largest(residual, largest)
        largest_printed = running_largest(residual_printed, largest_printed)
        if store:
            corrected[offset + j] = residual
            printed[offset + j] = residual_printed
    return largest, largest_printed


def old_rotation_angles(
    d: float, p: Any, axis: Any, n: int, block: int
) -> tuple[Any, Any, float, float]:
    """``residual_kernels._rotation_angles`` in blocks, as before session 21."""
    count = max(n - 1, 0)
    corrected, printed = np.empty(count), np.empty(count)
    largest, largest_printed = 0.0, 0.0
    size = min(block, count)
    rows, angles, steps = np.empty((5, size)), np.empty((3, size)), np.full(size, d)
    for start in range(1, n, block):
        stop = min(start + block, n)
        m = stop - start
        _old_arguments(p, axis, start, stop, rows)
        elementary.atan2(steps[:m], rows[0, :m], out=angles[0, :m])
        elementary.atan2(rows[1, :m], rows[2, :m], out=angles[1, :m])
        elementary.atan2(rows[3, :m], rows[4, :m], out=angles[2, :m])
        largest, largest_printed = _old_residuals(
            angles, m, largest, largest_printed, corrected, printed, start - 1, True
        )
    return corrected, printed, largest, largest_printed


#: How far the residuals may move (session 22: one argument of z conj(w)² instead of a
#: difference of atan2's), in units in the last place of the larger of the two angles at the
#: vertex: the cross and dot products are the same, the product's parts add three roundings each
#: to the terms of the difference (up to 12 units of the larger angle in the worst case; 3.6
#: measured at 10^6 vertices), atan2 one.
ULPS = 16


def angle_scale(d: float, p: Any, axis: Any, n: int) -> tuple[Any, Any]:
    """The larger of |angle| and |2 atan2(d, p^y)| at each vertex, corrected and printed (the
    scale a residual's rounding is measured against)."""
    k = np.arange(1, max(n, 1))
    a, b, c = axis[k - 1] - p[k], axis[k] - p[k], axis[k + 1] - p[k]
    with np.errstate(invalid="ignore", over="ignore"):
        formula = abs(2 * np.arctan2(d, p[k, 1]))

        def angle(u: Any, v: Any) -> Any:
            cross = u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0]
            return abs(np.arctan2(cross, u[:, 0] * v[:, 0] + u[:, 1] * v[:, 1]))

        return np.fmax(angle(a, b), formula), np.fmax(angle(b, c), formula)


def assert_close(found: Any, expected: Any, scale: Any) -> None:
    """Equal to ``ULPS`` units of ``scale`` entry by entry, NaN exactly where expected is."""
    assert_within_ulps(found, expected, scale, ULPS)


def assert_blocks_equal_old(d: float, p: Any, axis: Any, n: int, blocks: tuple[int, ...]) -> None:
    """The residuals and their largest near the old blocks' (``assert_close``); the largest
    NaN exactly when the old one is."""
    scale, scale_printed = angle_scale(d, p, axis, n)
    top = np.max(scale) if scale.size and not np.isnan(scale).any() else np.pi
    top_printed = (
        np.max(scale_printed) if scale_printed.size and not np.isnan(scale_printed).any() else np.pi
    )
    for block in blocks:
        expected = old_rotation_angles(d, p, axis, n, block)
        found = residual_kernels._rotation_angles(d, p, axis, n, True, block)
        assert_close(found[0], expected[0], scale)
        assert_close(found[1], expected[1], scale_printed)
        assert_close(found[2], expected[2], top)
        assert_close(found[3], expected[3], top_printed)
        alone = residual_kernels._rotation_angles(d, p, axis, n, False, block)
        assert same_bits(alone[2], found[2]) and same_bits(alone[3], found[3])
        assert alone[0].shape == alone[1].shape == (0,)


def test_real_polygons_equal_old_blocks() -> None:
    """Constructed and closed-form polygons, d = 0.5h, 1e-4h, 0.99h, h = 100, tilted starts."""
    ar = Float64()
    for h, ratio, beta0, lo, hi in D4B_POLYGONS:
        for method in ("construction", "closed-form"):
            data = d4b.polygons(ar, h, h * ratio, beta0, lo, hi, method)
            n = data.vertices - 1
            with np.errstate(over="ignore", invalid="ignore"):  # far closed forms overflow
                p, axis = data.p, data.axis
            assert_blocks_equal_old(h * ratio, p, axis, n, (residual_kernels.ROTATION_BLOCK, 999))
            corrected, printed = residual_kernels.rotation_angles(h * ratio, p, axis, n)
            old = old_rotation_angles(h * ratio, p, axis, n, residual_kernels.ROTATION_BLOCK)
            scale, scale_printed = angle_scale(h * ratio, p, axis, n)
            assert_close(corrected, old[0], scale)
            assert_close(printed, old[1], scale_printed)
            largest, worst = residual_kernels.rotation_angle_largest(h * ratio, p, axis, n)
            assert same_bits(largest.value, np.max(corrected, initial=0.0))
            assert (worst is None) == (not math.isfinite(old[3]) or n < 2)
            assert worst is None or worst == np.max(printed)


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_random_points_equal_old_blocks(seed: int) -> None:
    """Random points, every block size from 1 to past the count, counts 0 and 1 included."""
    rng = np.random.default_rng(seed)
    for n in (0, 1, 2, 3, 17, 100, 1000):
        p = rng.normal(size=(n + 1, 2)) * rng.uniform(0.1, 10)
        axis = rng.normal(size=(n + 1, 2))
        assert_blocks_equal_old(float(rng.uniform(0.01, 2)), p, axis, n, (1, 2, 3, 7, 64, 4096))


def adversarial(rng: Any, n: int) -> list[tuple[Any, Any]]:
    """Points with NaN, ±inf, zero-length vectors, ±0, subnormal and huge coordinates, at and
    inside the edges of blocks of 7 and 64."""
    specials = [
        np.nan,
        np.inf,
        -np.inf,
        0.0,
        -0.0,
        5e-324,
        -2.2e-310,
        1e300,
        -1.7e308,
        2.0**-500,
        2.0**500,
    ]
    cases = []
    for value in specials:
        for where in (0, 1, 6, 7, 8, 63, 64, 65, n // 2, n - 1, n):
            p = rng.normal(size=(n + 1, 2))
            axis = rng.normal(size=(n + 1, 2))
            target = (p, axis)[where % 2]
            target[min(where, n), where % 3 % 2] = value
            cases.append((p, axis))
    p = rng.normal(size=(n + 1, 2))
    cases.append((p, p.copy()))  # a = b = c = 0: atan2(0, 0) everywhere
    cases.append((np.zeros((n + 1, 2)), -np.zeros((n + 1, 2))))
    return cases


def test_adversarial_points_equal_old_blocks() -> None:
    rng = np.random.default_rng(21)
    for n in (70, 131):
        for p, axis in adversarial(rng, n):
            assert_blocks_equal_old(0.25, p, axis, n, (7, 64, 4096))
            assert_blocks_equal_old(1e-300, p, axis, n, (7,))


def test_layouts_are_copied_not_misread() -> None:
    """Points that are not C-contiguous (Fortran order, strided views) give the same bits as
    C-contiguous ones, near the old blocks."""
    rng = np.random.default_rng(5)
    n = 600
    p, axis = rng.normal(size=(n + 1, 2)), rng.normal(size=(n + 1, 2))
    expected = residual_kernels.rotation_angles(0.5, p, axis, n)
    old = old_rotation_angles(0.5, p, axis, n, residual_kernels.ROTATION_BLOCK)
    scale, scale_printed = angle_scale(0.5, p, axis, n)
    assert_close(expected[0], old[0], scale)
    assert_close(expected[1], old[1], scale_printed)
    wide = np.zeros((n + 1, 4))
    wide[:, 1:3] = axis
    for pp, aa in ((np.asfortranarray(p), axis), (p, wide[:, 1:3]), (p[::-1][::-1], axis)):
        corrected, printed = residual_kernels.rotation_angles(0.5, pp, aa, n)
        assert same_bits(corrected, expected[0]) and same_bits(printed, expected[1])


def test_nan_largest_and_the_erratum() -> None:
    """A NaN anywhere makes the largest NaN (then the check asks for the residuals) and the
    printed residual None, as before."""
    rng = np.random.default_rng(9)
    n = 2000
    p, axis = rng.normal(size=(n + 1, 2)), rng.normal(size=(n + 1, 2))
    p[1500, 1] = np.nan
    largest, worst = residual_kernels.rotation_angle_largest(0.5, p, axis, n)
    assert math.isnan(largest.value) and worst is None and len(largest) == n - 1
    expected = old_rotation_angles(0.5, p, axis, n, residual_kernels.ROTATION_BLOCK)
    assert_close(largest.residuals(), expected[0], angle_scale(0.5, p, axis, n)[0])
