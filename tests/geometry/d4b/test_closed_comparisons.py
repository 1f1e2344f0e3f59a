"""The blocked closed-form comparisons of (18)–(20) and Theorems 5, 6 (``fused_checks``) give the
numbers of the scalar loops they replaced: those loops are copied here as the reference (session
21), and both are run on real polygons at several sizes, tilted starts, and on images with NaN,
±inf, ±0, subnormal and huge entries at block edges and inside blocks. Since session 22 the blocks
make the closed forms from one exponential a row and take one square root a block, so a residual
may move at its last bits (``close_residuals``: ``ULPS`` units of the row's scale); None, NaN,
±inf and each residual's place are the reference's exactly, and a block the fast path sends back
(an argument past ``DECAY_LIMIT``, a NaN, a length off its square-root branch) gives the old
bits."""

from __future__ import annotations

from typing import Any

import numba
import numpy as np
import pytest

from app.geometry import elementary
from app.geometry.compiled import all_finite_vector, length, running_largest
from app.geometry.conditions import TINY
from app.geometry.d4b import closed_forms, discretization, residual_kernels
from app.geometry.d4b.fused_checks import (
    _closed_arguments,
    closed_image_comparisons,
    closed_kinematic_comparisons,
)
from app.geometry.precision import BLOCK_SIZE, Float64
from tests.geometry.bits import same_bits

#: How far a residual of the blocks may be from the reference's, in units of 2^-52 times the
#: row's scale: the closed point's coordinates from one exponential are within 2–4 ulp of numpy's
#: (``_sech_tanh``, test_closed_rounding.py), but a residual sees the difference of the two
#: closed points' errors, and its own rounding changes by an ulp (a division by a computed unit
#: length dropped, one square root of the largest square; the printed (20)'s Möbius form scales
#: the point's error by at most (h² + d²)/(h − d)² over its length, 1.7 at d = 0.5h). Measured:
#: at most 1.0 ulp on D4b polygons up to n = 10^5 (d = 0.5h, 0.1h, 1e-3h, 1e-4h, tilted).
ULPS = 4


def close_residuals(found: Any, expected: Any, scales: Any) -> bool:
    """``found`` within ``ULPS`` ulp of ``expected``, entry by entry, relative to the larger of
    the entry and its ``scales`` entry (the rows' largest resolution for (19) and (20), 1 for a
    relative residual); None only with None; NaN, ±inf only with the same bits."""
    if found is None or expected is None:
        return found is expected
    for f, e, s in zip(found, expected, scales, strict=True):
        if not (np.isfinite(f) and np.isfinite(e)):
            if not same_bits(f, e):
                return False
        elif abs(f - e) > ULPS * 2.0**-52 * max(abs(e), s):
            return False
    return True


def _scale(values: Any) -> float:
    """The largest finite magnitude of ``values`` (1.0 at least): a residual's row scale."""
    finite = np.abs(values[np.isfinite(values)])
    return max(1.0, float(finite.max())) if finite.size else 1.0


# ---- the reference: the session 20 loops, as they were ------------------------------------------


@numba.njit(cache=True, error_model="numpy")
def _old_kinematic_block(  # type: ignore[no-untyped-def]
    i_min, i_max, cosh, sinh, h, d, amplitude, p, tractrix, axis, offset, n, tiny, t5, t6, th5, th6
):
    rows = i_max - i_min + 2
    step = 2 * d
    for k in range(min(rows, n - offset)):
        at = offset + k
        x = float(i_min + k) * step
        if t5:
            ex, ey = x - d, amplitude * cosh[k]
            size = length(ex, ey)
            size = size if size > tiny else tiny
            residual = length(p[at, 0] - ex, p[at, 1] - ey) / size
            th5 = running_largest(residual, th5)
        if t6:
            sech = 1 / cosh[rows + k]
            tx, ty = x - h * (sinh[k] * sech), h * sech
            distance = length(tractrix[at, 0] - tx, tractrix[at, 1] - ty)
            scale = abs(axis[at, 0]) + h
            scale = scale if scale > tiny else tiny
            th6 = running_largest(abs(distance) / scale, th6)
    return th5, th6


def _old_kinematic(data: Any, n: int, theorem_5: bool, theorem_6: bool) -> Any:
    rows = data.vertices
    ar, h, d = data.ar, float(data.h), float(data.d)
    L = float(closed_forms.log_ratio(ar, data.h, data.d))
    shift = float(data.shift)
    amplitude = float(ar.sqrt((data.h - data.d) * (data.h + data.d)))
    block = min(rows, BLOCK_SIZE)
    cosh, sinh = np.empty(2 * block), np.empty(block)
    largest_5 = largest_6 = 0.0
    none = np.empty((0, 2))
    # C-contiguous copies: one compiled specialization of the reference for every layout given
    p = np.ascontiguousarray(data.p) if theorem_5 else none
    tractrix, axis = (
        (np.ascontiguousarray(data.tractrix), np.ascontiguousarray(data.axis))
        if theorem_6
        else (none, none)
    )
    for start in range(0, min(rows, n), block):
        count = min(block, rows - start)
        first = data.i_min + start
        arguments = _closed_arguments(first, first + count - 2, L, shift)
        lo, hi = (0 if theorem_5 else count), (2 * count if theorem_6 else count)
        with np.errstate(over="ignore"):
            elementary.cosh(arguments[lo:hi], out=cosh[lo:hi])
        if not all_finite_vector(cosh[lo:hi]):
            return None
        if theorem_6:
            elementary.sinh(arguments[count : 2 * count], out=sinh[:count])
        largest_5, largest_6 = _old_kinematic_block(
            first, first + count - 2, cosh, sinh, h, d, amplitude, p, tractrix, axis, start, n,
            TINY, theorem_5, theorem_6, largest_5, largest_6,
        )  # fmt: skip
    return largest_5, largest_6


@numba.njit(cache=True, error_model="numpy")
def _old_image_block(  # type: ignore[no-untyped-def]
    i_min, i_max, cosh, tanh, h, d, ga, normals, contact, gauss, s19, s20, offset, n, tiny, w, big
):
    rows = i_max - i_min + 2
    for k in range(min(rows, n - offset)):
        at = offset + k
        sech, th = 1.0 / cosh[2 * rows + 1 + k], tanh[1 + k]
        if w[0]:
            size = length(sech, th)
            size = size if size > tiny else tiny
            value = length(normals[at, 0] - sech, normals[at, 1] - th) / size
            big[0] = running_largest(value, big[0])
        if w[3]:
            size = length(sech, -th)
            size = size if size > tiny else tiny
            value = length(normals[at, 0] - sech, normals[at, 1] - -th) / size
            big[3] = running_largest(value, big[3])
        if w[1] or w[4]:
            cx, cy = -th, sech
            if w[1]:
                size = length(cx, cy)
                size = size if size > tiny else tiny
                value = length(contact[at + 1, 0] - cx, contact[at + 1, 1] - cy) / size
                big[1] = running_largest(value * s19[at], big[1])
            if w[4]:
                x, y = -cx, cy
                size = length(x, y)
                size = size if size > tiny else tiny
                value = length(contact[at + 1, 0] - x, contact[at + 1, 1] - y) / size
                big[4] = running_largest(value, big[4])
        if w[2]:
            mx, my = -tanh[rows + 1 + k], ga / cosh[3 * rows + 1 + k]
            size = length(mx, my)
            size = size if size > tiny else tiny
            value = length(gauss[at, 0] - mx, gauss[at, 1] - my) / size
            big[2] = running_largest(value * s20[at], big[2])
        if w[5]:
            denominator = h + d * th
            x, y = (h * th - d) / denominator, h * sech / denominator
            size = length(x, y)
            size = size if size > tiny else tiny
            value = length(gauss[at, 0] - x, gauss[at, 1] - y) / size
            big[5] = running_largest(value, big[5])


def _old_images(
    data: Any,
    n: int,
    wanted: tuple[bool, ...],
    normals: Any,
    contact: Any,
    gauss: Any,
    s19: Any,
    s20: Any,
) -> Any:
    ar = data.ar
    rows = n + 1
    h, d = float(data.h), float(data.d)
    L = float(closed_forms.log_ratio(ar, data.h, data.d))
    shift = float(data.shift)
    ga = float(data.h / ar.sqrt((data.h - data.d) * (data.h + data.d)))
    block = min(rows, BLOCK_SIZE)
    cosh, tanh = np.empty(4 * block + 1), np.empty(2 * block + 1)
    largest = np.zeros(6)
    flags = np.array(wanted, dtype=np.bool_)
    for start in range(0, min(rows, n), block):
        count = min(block, rows - start)
        first = data.i_min + start
        arguments = _closed_arguments(first, first + count - 2, L, shift)
        with np.errstate(over="ignore"):
            elementary.cosh(arguments[2 * count :], out=cosh[2 * count : 4 * count + 1])
        if not all_finite_vector(cosh[2 * count : 4 * count + 1]):
            return None
        elementary.tanh(arguments[2 * count :], out=tanh[: 2 * count + 1])
        _old_image_block(
            first, first + count - 2, cosh, tanh, h, d, ga, normals, contact, gauss, s19, s20,
            start, n, TINY, flags, largest,
        )  # fmt: skip
    return [float(v) for v in largest]


# ---- the comparisons -----------------------------------------------------------------------------

_ALL = (True,) * 6
_WANTED = [
    _ALL,
    (True, False, False, True, False, False),
    (False, True, False, False, True, False),
    (False, False, True, False, False, True),
    (True, True, True, False, False, False),
    (False, False, False, False, False, True),
    (False,) * 6,
]


def _images(data: Any, n: int) -> tuple[Any, Any, Any, Any, Any]:
    images = data.gauss
    rng = np.random.default_rng(n)
    s19 = np.exp(rng.uniform(-3, 12, n + 1))
    s20 = np.exp(rng.uniform(-3, 12, n + 1))
    return (
        np.array(images.tractrix_gauss[:n]),
        np.array(images.contact[: n + 1]),
        np.array(images.gauss[:n]),
        s19,
        s20,
    )


def _check_images(data: Any, n: int, arrays: tuple[Any, ...], wanted: tuple[bool, ...]) -> None:
    normals, contact, gauss, s19, s20 = arrays
    same = (np.ascontiguousarray(a) for a in arrays)  # the reference compiled once, for C layout
    expected = _old_images(data, n, wanted, *same)
    found = closed_image_comparisons(
        data.ar, data.h, data.d, data.shift, data.i_min, n, wanted, normals, contact, gauss,
        s19, s20,
    )  # fmt: skip
    scales = [1.0, _scale(s19[:n]), _scale(s20[:n]), 1.0, 1.0, 1.0]
    assert close_residuals(found, expected, scales), (found, expected)


def _check_kinematic(data: Any, n: int) -> None:
    for theorem_5, theorem_6 in [(True, True), (True, False), (False, True), (False, False)]:
        expected = _old_kinematic(data, n, theorem_5, theorem_6)
        found = closed_kinematic_comparisons(data, n, theorem_5, theorem_6)
        # Theorem 6's row scale: the tractrix point's x (rounded as before) over |a_x| + h
        x, axis = np.asarray(data.tractrix)[:n, 0], np.asarray(data.axis)[:n, 0]
        h = float(data.h)
        scale_6 = _scale((np.abs(x) + h) / (np.abs(axis) + h)) if theorem_6 else 1.0
        assert close_residuals(found, expected, [1.0, scale_6]), (
            theorem_5,
            theorem_6,
            found,
            expected,
        )


_SIZES = [1, 2, 3, BLOCK_SIZE - 1, BLOCK_SIZE, BLOCK_SIZE + 1, 2 * BLOCK_SIZE + 5, 10**5]


@pytest.mark.parametrize("n", _SIZES)
@pytest.mark.parametrize(("d", "beta0"), [(1e-4, None), (1e-4, 0.7), (1e-3, 2.9), (0.5, None)])
def test_real_polygons_give_the_old_loops_residuals(n: int, d: float, beta0: float | None) -> None:
    if d == 0.5 and n > 3000:  # cosh overflows: both None (see the overflow test)
        n = 1200
    data = discretization.polygons(Float64(), 1.0, d, beta0, -(n // 2), n - n // 2 - 1)
    assert data.vertices == n + 1
    _check_kinematic(data, n)
    arrays = _images(data, n)
    for wanted in _WANTED:
        _check_images(data, n, arrays, wanted)


def test_tilted_start_at_an_offset_and_fewer_rows() -> None:
    data = discretization.polygons(Float64(), 2.5, 0.7, 3.1, -3, 40)
    for n in (0, 1, 5, data.vertices - 1):
        _check_kinematic(data, n)
        for wanted in _WANTED:
            _check_images(data, n, _images(data, n), wanted)


def test_overflow_gives_none_as_before() -> None:
    for i_min, i_max in [(0, 700), (-650, 10), (0, BLOCK_SIZE + 5), (600, 640)]:
        data = discretization.polygons(Float64(), 1.0, 0.5, None, i_min, i_max)
        n = data.vertices - 1
        _check_kinematic(data, n)
        rng = np.random.default_rng(n)  # (the constructed images have zero-length edges here)
        arrays = (*rng.uniform(-1, 1, (3, n + 1, 2)), *rng.uniform(0, 9, (2, n + 1)))
        for wanted in _WANTED:
            _check_images(data, n, arrays, wanted)
    data = discretization.polygons(Float64(), 1.0, 0.5, None, 0, 700)
    assert closed_kinematic_comparisons(data, 701) is None


_ODD = [np.nan, np.inf, -np.inf, 0.0, -0.0, 5e-324, 1e-310, 1e-200, 1e200, 1e308, -1e300, 2.0**480]


@pytest.mark.parametrize("seed", range(6))
def test_odd_entries_at_block_edges_and_inside_give_the_old_loops_residuals(seed: int) -> None:
    rng = np.random.default_rng(seed)
    n = 2 * BLOCK_SIZE + 17
    data = discretization.polygons(Float64(), 1.0, 1e-3, [None, 0.4][seed % 2], -9000, n - 9001)
    rows = [0, 1, BLOCK_SIZE - 1, BLOCK_SIZE, BLOCK_SIZE + 1, 2 * BLOCK_SIZE - 1, n - 1]
    rows += list(rng.integers(0, n, 3))
    for row in rows:
        for _ in range(2):
            value = _ODD[rng.integers(len(_ODD))]
            arrays = [np.array(a) for a in _images(data, n)]
            which = rng.integers(5)
            target = arrays[which]
            if target.ndim == 2:
                target[min(row + (which == 1), len(target) - 1), rng.integers(2)] = value
            else:
                target[row] = value
            for wanted in _WANTED[:4]:
                _check_images(data, n, tuple(arrays), wanted)
            moved = {
                "p": np.array(data.p),
                "tractrix": np.array(data.tractrix),
                "axis": np.array(data.axis),
            }
            name = ["p", "tractrix", "axis"][rng.integers(3)]
            moved[name][row, rng.integers(2)] = value
            _check_kinematic(data.replaced(**moved), n)


def test_exact_images_and_closed_points_give_zero_lengths() -> None:
    """Images equal to their closed forms (zero differences: both lengths +0) and images at
    the closed points' scale of the smallest and largest lengths."""
    n = BLOCK_SIZE + 3
    data = discretization.polygons(Float64(), 1.0, 1e-4, None, -(n // 2), n - n // 2 - 1)
    normals, contact, gauss, s19, s20 = _images(data, n)
    ar = data.ar
    L = float(closed_forms.log_ratio(ar, data.h, data.d))
    t = (np.arange(data.i_min - 1, data.i_min + n, dtype=np.float64) + float(data.shift)) * L
    exact_n = np.stack([1.0 / np.cosh(t[1:]), np.tanh(t[1:])], axis=1)
    exact_c = np.stack([-np.tanh(t), 1.0 / np.cosh(t)], axis=1)
    for wanted in _WANTED:
        _check_images(data, n, (exact_n, exact_c, gauss, s19, s20), wanted)
        _check_images(data, n, (exact_n * 1e-300, exact_c * 1e300, gauss, s19, s20), wanted)
        _check_images(data, n, (normals, contact, gauss * 0.0, s19 * 0.0, s20 * np.inf), wanted)
    same = data.replaced(p=np.zeros_like(data.p), tractrix=np.full_like(data.tractrix, -0.0))
    _check_kinematic(same, n)
    tiny = data.replaced(p=data.p * 1e-305, axis=data.axis * 1e-320)
    _check_kinematic(tiny, n)


def test_non_contiguous_images_are_read_as_given() -> None:
    n = 3000
    data = discretization.polygons(Float64(), 1.0, 1e-3, 1.1, -1000, n - 1001)
    normals, contact, gauss, s19, s20 = _images(data, n)
    wide = np.empty((n, 4))
    wide[:, 1:3] = normals
    columns = np.asfortranarray(contact)
    _check_images(data, n, (wide[:, 1:3], columns, gauss, s19[::-1][::-1], s20), _ALL)
    strided = np.empty((2 * (n + 1), 2))
    strided[::2] = data.p
    _check_kinematic(data.replaced(p=strided[::2]), n)


@pytest.mark.parametrize("n", [1, 2, BLOCK_SIZE - 1, BLOCK_SIZE + 1, 2 * BLOCK_SIZE + 5, 60_000])
@pytest.mark.parametrize("d", [1e-4, 0.5])
def test_scales_made_a_block_at_a_time_give_the_arrays_numbers(n: int, d: float) -> None:
    """(19) and (20) compared with their scales made a block at a time from p
    (``residual_kernels.block_resolutions``, issue 13, session 30) give the bits the (n,)
    arrays of the edges' and the poles' resolutions give, for every choice of comparisons; on a
    perturbed polygon too (rows off the square-root branch, a NaN)."""
    if d == 0.5 and n > 3000:  # cosh overflows: both None (see the overflow test)
        n = 1200
    data = discretization.polygons(Float64(), 1.0, d, None, -(n // 2), n - n // 2 - 1)
    images = data.gauss
    p = np.ascontiguousarray(data.p, dtype=np.float64)
    rng = np.random.default_rng(n)
    perturbed = p.copy()
    perturbed[rng.integers(0, len(p), 5)] *= 1 + 1e-3 * rng.standard_normal((5, 1))
    perturbed[len(p) // 2, 0] = 1e200  # off the square-root branch
    if n > 10:
        perturbed[len(p) // 3, 1] = np.nan
    for points in (p, perturbed):
        before_points = np.ascontiguousarray(images.contact_edges_before, dtype=np.float64)
        before = float(residual_kernels._edge_resolution_blocked(before_points)[0])
        s19 = residual_kernels._edge_resolution_blocked(points)
        s20 = residual_kernels._pole_resolution(before, s19)
        windows = ((0, min(n, 7)), (1, min(n, 3)), (n // 2, n - n // 2), (0, n))
        for start, count in (w for w in windows if w[0] + w[1] <= len(s19)):
            edges, poles = np.empty(count), np.empty(count)
            scratch, usual = np.empty(count + 1), np.empty(count + 1, dtype=np.bool_)
            residual_kernels.block_resolutions(
                points, before, start, count, edges, poles, scratch, usual
            )
            assert same_bits(edges, s19[start : start + count])
            assert same_bits(poles, s20[start : start + count])
        arrays = (
            np.array(images.tractrix_gauss[:n]),
            np.array(images.contact[: n + 1]),
            np.array(images.gauss[:n]),
        )
        for wanted in _WANTED:
            stored = closed_image_comparisons(
                data.ar, data.h, data.d, data.shift, data.i_min, n, wanted, *arrays, s19, s20
            )
            made = closed_image_comparisons(
                data.ar, data.h, data.d, data.shift, data.i_min, n, wanted, *arrays, None, None,
                (points, before),
            )  # fmt: skip
            assert (stored is None) == (made is None)
            if stored is not None and made is not None:
                assert same_bits(np.array(made), np.array(stored)), (wanted, made, stored)
