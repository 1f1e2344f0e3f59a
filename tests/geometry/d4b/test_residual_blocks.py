"""The blocked Section 4.2 / Section 5 passes of ``residual_kernels`` (issue 13, session 21)
give the bits of the scalar passes they replace (kept in the module as the reference), on the
real polygons and on adversarial inputs: NaN and ±inf at block edges and inside blocks, zero
edges, subnormal and huge coordinates (hypot's ranges), ±0, counts around the block size."""

from __future__ import annotations

import math
import platform
import re

import numba
import numpy as np
import pytest

from app.geometry.compiled import length, running_largest
from app.geometry.d4b import discretization as d4b, residual_kernels as rk
from app.geometry.precision import Float64

BLOCK = rk.EDGE_BLOCK
COUNTS = [0, 1, 2, 3, 4, 5, BLOCK - 1, BLOCK, BLOCK + 1, 2 * BLOCK + 3, 3000]
SPECIALS = [
    math.nan,
    math.inf,
    -math.inf,
    0.0,
    -0.0,
    5e-324,
    1e-310,
    1e-200,
    2.0**-470,
    2.0**500,
    1e300,
    -1e300,
    1.7976931348623157e308,
]


def same(got: float, expected: float) -> bool:
    """The same float64: both NaN, or the same bits (±0 told apart)."""
    if math.isnan(expected):
        return math.isnan(got)
    return np.float64(got).tobytes() == np.float64(expected).tobytes()


def same_arrays(got: np.ndarray, expected: np.ndarray) -> bool:
    nan = np.isnan(expected)
    return bool(
        got.shape == expected.shape
        and np.array_equal(np.isnan(got), nan)
        and np.array_equal(got[~nan].view(np.int64), expected[~nan].view(np.int64))
    )


# ---- the references: the scalar passes the blocked ones replaced (session 20), row by row -----


@numba.njit(cache=True, error_model="numpy")
def ref_largest_along_both(vectors: np.ndarray, points: np.ndarray) -> tuple[float, float]:
    return rk._along_both_rows(vectors, points, 0, vectors.shape[0], 0.0, 0.0)


@numba.njit(cache=True, error_model="numpy")
def ref_hypothesis(p: np.ndarray, n: int, d2: float) -> tuple[float, float]:
    return rk._hypothesis_rows(p, 1, n, d2, 0.0, math.inf)


@numba.njit(cache=True, error_model="numpy")
def ref_largest_two_step_printed(d2: float, d4: float, y: np.ndarray, tiny: float) -> float:
    largest = 0.0
    for k in range(max(y.shape[0] - 3, 0)):
        largest = running_largest(rk._two_step_printed_at(d2, d4, y, k, tiny), largest)
    return largest


@numba.njit(cache=True, error_model="numpy")
def ref_printed_ratios(p: np.ndarray) -> np.ndarray:
    count = max(p.shape[0] - 3, 0)
    out = np.empty(count)
    if count == 0:
        return out
    after = length(p[1, 0] - p[0, 0], p[1, 1] - p[0, 1])
    for k in range(count):
        before = after
        after = length(p[k + 2, 0] - p[k + 1, 0], p[k + 2, 1] - p[k + 1, 1])
        second = p[k + 3, 1] - 2 * p[k + 2, 1] + p[k + 1, 1]
        out[k] = second / (before + after)
    return out


def same_summary(summary: np.ndarray, ratios: np.ndarray) -> bool:
    """``_printed_ratio_summary`` against the reference's ratios: their count, ``np.sum`` (the
    same bits), ``np.min`` and ``np.max`` (equal, or both NaN: ±0 alike); zeros when empty."""
    if len(ratios) == 0:
        return bool(np.array_equal(summary, np.zeros(4)))
    with np.errstate(all="ignore"):  # ±inf ratios sum to NaN
        total = np.sum(ratios)
    extremes = zip(summary[2:], (np.min(ratios), np.max(ratios)), strict=True)
    return (
        summary[0] == len(ratios)
        and same(summary[1], total)
        and all(
            got == expected or (math.isnan(got) and math.isnan(expected))
            for got, expected in extremes
        )
    )


@numba.njit(cache=True, error_model="numpy")
def ref_rotation_and_inversion(
    p: np.ndarray,
    before: np.ndarray,
    contact: np.ndarray,
    normals: np.ndarray,
    gauss: np.ndarray,
    count: int,
    rotation: bool,
    inversion: bool,
    tiny: float,
) -> tuple[float, float]:
    previous = rk._resolution_before(before)
    found = rk._rotation_and_inversion_rows(
        p, contact, normals, gauss, 0, count, rotation, inversion, tiny, previous, 0.0, 0.0
    )
    return found[1], found[2]


def noisy(rng: np.random.Generator, rows: int, mode: str, cols: int = 2) -> np.ndarray:
    """Rows of moderate numbers; "edges": special values at the block edges; "inside": special
    values at random places; "ranges": magnitudes from subnormal to near overflow; "smooth":
    a smooth curve (the usual branch everywhere)."""
    shape = (rows, cols) if cols else (rows,)
    if mode == "smooth":
        t = np.linspace(-3, 3, rows)
        values = np.stack([t, np.cosh(t)], axis=1) if cols else np.cosh(t) + 0.5
        return np.ascontiguousarray(values * (1 + rng.normal(size=values.shape) * 1e-9))
    values = rng.normal(size=shape) * 10.0 ** rng.uniform(-2, 2, size=shape)
    flat = values.reshape(-1)
    if mode == "edges":
        for index in (0, BLOCK - 1, BLOCK, BLOCK + 1, 2 * BLOCK, rows - 1):
            if 0 <= index < rows:
                values[index] = rng.choice(SPECIALS)
    elif mode == "inside" and flat.size:
        where = rng.integers(0, flat.size, size=max(flat.size // 200, 1))
        flat[where] = rng.choice(SPECIALS, size=len(where))
    elif mode == "ranges":
        flat *= 10.0 ** rng.integers(-320, 300, size=flat.size)
    elif mode == "zeros" and rows > 1:  # repeated points: zero edges and zero lengths
        values[1::3] = values[0:-1:3][: len(values[1::3])]
    return values


MODES = ["plain", "edges", "inside", "ranges", "zeros", "smooth"]


def cases() -> list[tuple[int, str, int]]:
    return [(count, mode, seed) for count in COUNTS for mode in MODES for seed in (1, 2)]


@pytest.mark.parametrize(("count", "mode", "seed"), cases())
def test_blocked_edge_passes_equal_the_scalar_ones(count: int, mode: str, seed: int) -> None:
    rng = np.random.default_rng(seed * 1000 + count)
    points = noisy(rng, count + 1, mode)
    vectors = noisy(rng, count, mode if mode != "smooth" else "plain")
    other = noisy(rng, count, mode if mode != "smooth" else "plain")
    scale = np.abs(noisy(rng, count, mode, cols=0))
    got, expected = (
        rk._largest_along_both_blocked(vectors, points),
        ref_largest_along_both(vectors, points),
    )
    assert same(got[0], expected[0]) and same(got[1], expected[1])
    got_one = rk._largest_pole_inversion(other, points, scale, count, rk.TINY)
    assert same(got_one, rk._pole_inversion(other, points, scale, count, rk.TINY, False)[1])
    got_one = rk._largest_contact_rotation(points, vectors, scale, count)
    assert same(got_one, rk._contact_rotation(points, vectors, scale, count, False)[1])
    before = noisy(rng, 2, mode if mode != "smooth" else "plain")
    for rotation, inversion in ((True, True), (True, False), (False, True)):
        args = (points, before, points, vectors, other, count, rotation, inversion, rk.TINY)
        found, reference = (
            rk._rotation_and_inversion_blocked(*args),
            ref_rotation_and_inversion(*args),
        )
        assert same(found[0], reference[0]) and same(found[1], reference[1])
    assert same_arrays(rk._edge_resolution_blocked(points), rk._edge_resolution(points))
    assert same_summary(rk._printed_ratio_summary(points), ref_printed_ratios(points))
    axis = noisy(rng, count, mode if mode != "smooth" else "plain")
    got_one = rk._largest_right_angle(vectors, axis, points, count)
    assert same(got_one, rk._right_angles(vectors, axis, points, count, False)[1])
    for d2 in (1e-4, 0.0, 2.5):
        found, reference = (
            rk._hypothesis_blocked(points, count + 1, d2),
            ref_hypothesis(points, count + 1, d2),
        )
        assert same(found[0], reference[0]) and same(found[1], reference[1])


@pytest.mark.parametrize(("count", "mode", "seed"), cases())
def test_blocked_height_passes_equal_the_scalar_ones(count: int, mode: str, seed: int) -> None:
    rng = np.random.default_rng(seed * 7000 + count)
    points = noisy(rng, count, mode)
    for y in (points[:, 1], np.ascontiguousarray(points[:, 1])):  # strided, as the checks pass
        for d in (1e-3, 0.7, 0.0):
            got = rk._largest_recursions(d, y, rk.TINY)
            expected = rk._recursions(d, y, rk.TINY, False)
            assert same(got[0], expected[2]) and same(got[1], expected[3])
            got_one = rk._largest_two_step_printed_blocked(d * d, d**4, y, rk.TINY)
            assert same(got_one, ref_largest_two_step_printed(d * d, d**4, y, rk.TINY))
            # the heights read in place from their rows (the checks' p[:, 1])
            got = rk._largest_recursions_pairs(d, points, rk.TINY)
            assert same(got[0], expected[2]) and same(got[1], expected[3])
            got_one = rk._largest_two_step_printed_pairs(d * d, d**4, points, rk.TINY)
            assert same(got_one, ref_largest_two_step_printed(d * d, d**4, y, rk.TINY))
    for d in (1e-3, 0.7):  # the public functions, on the column and on a copy of it
        for y in (points[:, 1], np.ascontiguousarray(points[:, 1]), points[1:, 1]):
            one, two = rk.recursion_largest(d, y)
            expected = rk._recursions(d, np.ascontiguousarray(y), rk.TINY, False)
            assert same(one.value, expected[2]) and same(two.value, expected[3])
            if len(y) >= 4:
                worst = ref_largest_two_step_printed(d * d, d**4, y, rk.TINY)
                printed = rk.largest_two_step_printed_residual(d, y)
                assert printed == (worst if math.isfinite(worst) else None)


def test_paired_heights_are_the_rows_they_are_a_column_of() -> None:
    rows = np.arange(40.0).reshape(20, 2)
    assert rk._paired(rows[:, 1]) is not None
    np.testing.assert_array_equal(rk._paired(rows[:, 1])[:, 1], rows[:, 1])
    np.testing.assert_array_equal(rk._paired(rows[3:9, 1]), rows[3:9])
    np.testing.assert_array_equal(rk._paired(rows[1:, 0])[:, 1], rows[1:, 0])
    assert rk._paired(rows[:, 0]) is None  # the first column: no entry before it
    assert rk._paired(rows[::2, 1]) is None  # every other row
    assert rk._paired(np.ascontiguousarray(rows[:, 1])) is None
    assert rk._paired(np.arange(60.0).reshape(20, 3)[:, 1]) is None
    assert rk._paired(np.asfortranarray(rows)[:, 1]) is None
    fixed = rows.copy()
    fixed.flags.writeable = False
    assert rk._paired(fixed[:, 1]) is None


def test_hypothesis_smallest_keeps_the_first_of_two_zeros() -> None:
    """−0 and +0 are equal to ``<``: the scalar pass keeps the first; so does the blocked."""
    for first, second in ((0.0, -0.0), (-0.0, 0.0)):
        p = np.ones((3 * BLOCK, 2))
        p[BLOCK + 5, 1], p[BLOCK + 7, 1] = first, second
        p[BLOCK + 6, 1] = 1.0
        p[2 * BLOCK + 1, 1] = -1.0
        got, expected = rk._hypothesis_blocked(p, len(p), 1.0), ref_hypothesis(p, len(p), 1.0)
        assert same(got[0], expected[0]) and same(got[1], expected[1])
        q = p.copy()
        q[2 * BLOCK + 1, 1] = 1.0  # no negative ratio: the smallest is a zero, the first one
        got, expected = rk._hypothesis_blocked(q, len(q), 1.0), ref_hypothesis(q, len(q), 1.0)
        assert same(got[1], expected[1]) and math.copysign(1, got[1]) == math.copysign(
            1, expected[1]
        )


@pytest.mark.parametrize("before", [0.5, 0.0, math.nan, 1e-300])
def test_pole_resolution_is_numpys_minimum(before: float) -> None:
    rng = np.random.default_rng(5)
    for count in (1, 2, BLOCK + 1, 3000):
        resolution = np.abs(noisy(rng, count, "inside", cols=0))
        first = np.array([before])
        expected = np.minimum(np.concatenate([first, resolution[:-1]]), resolution)
        assert same_arrays(rk.pole_resolution(first, resolution), expected)
    # shapes the compiled pass does not take: numpy's evaluation
    assert rk.pole_resolution(np.array([0.5]), np.empty(0)).shape == (0,)


@pytest.mark.parametrize("n", [7, 130, 2500, 40000])
def test_blocked_passes_on_the_real_polygons(n: int) -> None:
    ar = Float64()
    data = d4b.polygons(ar, 1.0, 1e-2, None, -(n // 2), n - n // 2 - 1)
    p, tractrix, axis = data.p, data.tractrix, data.axis
    m = len(p) - 1
    y = p[:, 1]
    for d in (1e-2, 1e-2 * (1 + 1e-9)):
        got = rk._largest_recursions(d, y, rk.TINY)
        expected = rk._recursions(d, y, rk.TINY, False)
        assert same(got[0], expected[2]) and same(got[1], expected[3])
        got_one = rk._largest_two_step_printed_blocked(d * d, d**4, y, rk.TINY)
        assert same(got_one, ref_largest_two_step_printed(d * d, d**4, y, rk.TINY))
        found, reference = rk._hypothesis_blocked(p, m + 1, d * d), ref_hypothesis(p, m + 1, d * d)
        assert same(found[0], reference[0]) and same(found[1], reference[1])
    count = min(m, len(tractrix), len(axis))
    got_one = rk._largest_right_angle(tractrix, axis, p, count)
    assert same(got_one, rk._right_angles(tractrix, axis, p, count, False)[1])
    edges = p[1:] - p[:-1]
    unit = edges / np.hypot(edges[:, :1], edges[:, 1:])
    normals = np.ascontiguousarray(np.stack([unit[:, 1], -unit[:, 0]], axis=1))
    got_pair = rk._largest_along_both_blocked(unit, p)
    expected_pair = ref_largest_along_both(unit, p)
    assert same(got_pair[0], expected_pair[0]) and same(got_pair[1], expected_pair[1])
    resolution = rk._edge_resolution_blocked(p)
    assert same_arrays(resolution, rk._edge_resolution(p))
    assert same_summary(rk._printed_ratio_summary(p), ref_printed_ratios(p))
    contact = np.concatenate([normals[:1], normals])
    got_one = rk._largest_contact_rotation(contact, normals, resolution, m)
    assert same(got_one, rk._contact_rotation(contact, normals, resolution, m, False)[1])
    got_one = rk._largest_pole_inversion(normals, contact, resolution, m, rk.TINY)
    assert same(got_one, rk._pole_inversion(normals, contact, resolution, m, rk.TINY, False)[1])


def test_the_public_largest_functions_take_the_blocked_passes() -> None:
    rng = np.random.default_rng(11)
    p = noisy(rng, 3000, "smooth")
    y = p[:, 1]
    one, two = rk.recursion_largest(0.01, y)
    expected = rk._recursions(0.01, y, rk.TINY, False)
    assert same(one.value, expected[2]) and same(two.value, expected[3])
    largest, smallest = rk.hypothesis_largest(p, len(p), 0.01)
    reference = ref_hypothesis(p, len(p), 0.01 * 0.01)
    assert same(largest.value, reference[0]) and same(smallest, reference[1])
    assert same_arrays(rk.edge_resolution(p), rk._edge_resolution(p))


@pytest.mark.skipif(platform.machine() not in ("x86_64", "AMD64"), reason="x86-64 code")
@pytest.mark.parametrize(
    "name",
    [
        "_largest_along_both_blocked",
        "_largest_pole_inversion",
        "_rotation_and_inversion_blocked",
        "_largest_recursions",
        "_largest_two_step_printed_pairs",
        "_edge_resolution_blocked",
    ],
)
def test_the_block_loops_are_vectorized(name: str) -> None:
    """The block loops run on vector registers: packed divisions or square roots on ymm/zmm
    (AVX2 or AVX-512), or at least xmm (SSE2, which every x86-64 host has). Compiled afresh:
    numba shows no machine code for a kernel loaded from its cache."""
    kernel = getattr(rk, name)
    fresh = numba.njit(kernel.signatures[0], error_model="numpy")(kernel.py_func)
    asm = fresh.inspect_asm(fresh.signatures[0])
    packed = re.compile(r"\s(v?(div|sqrt)pd)\s.*%[xyz]mm")
    assert any(packed.search(line) for line in asm.splitlines())
