"""The compiled ring of faces gives the bits of the numpy definition (faces, then [3]).

The parallelism residual alone is within 2 ulp: |crossed| by ``compiled.length3``. The fused
checks of a ring (``ring_checks``) multiply by reciprocals: their residuals are within a few
units of rounding of the numpy evaluation's.
"""

from __future__ import annotations

import numpy as np
import pytest

from app.geometry.curvature import face_curvatures
from app.geometry.d4b import discretization as d4b
from app.geometry.errors import DomainError
from app.geometry.precision import Float64
from app.geometry.surfaces import revolution_formulas, ring_curvature, ring_kernel
from app.geometry.surfaces.mesh import ring_faces
from app.geometry.surfaces.ring_kernel import ring_curvatures

FIELDS = (
    "area",
    "gauss_area",
    "mixed_area",
    "K",
    "H",
    "parallel",
    "area_magnitude",
    "gauss_area_magnitude",
    "mixed_area_magnitude",
)


def numpy_ring(ar: Float64, meridian: np.ndarray, gauss: np.ndarray) -> object:
    theta = ar.pi / ring_curvature.RING_M
    cos, sin = ar.cos(theta), ar.sin(theta)
    f = ring_faces(ar, meridian[:-1], meridian[1:], cos, sin)
    g = ring_faces(ar, gauss[:-1], gauss[1:], cos, sin)
    return face_curvatures(ar, f, g)


def meridians(seed: int) -> list[tuple[np.ndarray, np.ndarray]]:
    """Catenoid and pseudosphere rings of D4b, and random meridians with random parallels."""
    ar = Float64()
    data = d4b.polygons(ar, 1.0, 0.3, 1.2, -40, 40)
    rng = np.random.default_rng(seed)
    x = np.cumsum(rng.uniform(0.1, 1.0, 300))
    y = rng.uniform(0.5, 3.0, 300) * rng.choice([1.0, 1e-5, 1e5], 300)
    noise = rng.normal(size=(300, 2)) * rng.choice([1.0, 1e-9], (300, 1))
    return [
        (data.p, data.gauss.gauss),
        (data.tractrix, data.gauss.tractrix_gauss),
        (np.stack([x, y], axis=1), np.stack([x, y], axis=1) * 0.5 + noise),
    ]


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_compiled_ring_equals_the_numpy_definition_bit_for_bit(seed: int) -> None:
    ar = Float64()
    for meridian, gauss in meridians(seed):
        n = min(len(meridian), len(gauss))
        expected = numpy_ring(ar, meridian[:n], gauss[:n])
        theta = ar.pi / ring_curvature.RING_M
        got = ring_curvatures(meridian[:n], gauss[:n], ar.cos(theta), ar.sin(theta))
        assert got is not None
        for name in FIELDS:
            if name == "parallel":  # a residual: √ of the sum of squares for the nested hypot
                a, b = got.parallel, expected.parallel
                assert np.all(abs(a - b) <= 2 * np.spacing(np.maximum(abs(a), abs(b)))), name
                continue
            np.testing.assert_array_equal(getattr(got, name), getattr(expected, name), name)


def test_a_face_without_area_is_still_a_domain_error() -> None:
    meridian = np.array([[0.0, 1.0], [1.0, 1.0], [1.0, 1.0], [2.0, 2.0]])
    gauss = np.array([[0.0, 1.0], [0.5, 1.0], [0.7, 1.0], [1.0, 1.5]])
    with pytest.raises(DomainError, match="positive area"):
        ring_curvature.ring_curvatures(Float64(), meridian, gauss)


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_compiled_equation_17_residuals_equal_the_numpy_ones(seed: int) -> None:
    """(17) multiplied out: the kernel against the numpy lines it replaces, bit for bit."""
    ar = Float64()
    for meridian, gauss in meridians(seed):
        n = min(len(meridian), len(gauss))
        p_y, n_y = meridian[:n, 1], gauss[:n, 1]
        areas = numpy_ring(ar, meridian[:n], gauss[:n])
        got = revolution_formulas.face_residuals(ar, p_y[:-1], p_y[1:], n_y[:-1], n_y[1:], areas)
        expected = numpy_face_residuals(p_y[:-1], p_y[1:], n_y[:-1], n_y[1:], areas)
        for a, b in zip(got, expected, strict=True):
            np.testing.assert_array_equal(a, b)


def numpy_face_residuals(p0, p1, n0, n1, areas):
    """The numpy evaluation of ``revolution_formulas.face_residuals`` (its mp path, in floats)."""
    tiny = np.finfo(np.float64).tiny
    c = np.maximum(abs(p0), abs(p1))
    c = np.where(c > tiny, c, 1.0)
    q0, q1 = p0 / c, p1 / c
    dp = q1 * q1 - q0 * q0
    sp = q1 * q1 + q0 * q0
    area_k, mag_k = areas.area / c / c, areas.area_magnitude / c / c
    area_h, mag_h = areas.area / c, areas.area_magnitude / c
    k_scale = areas.gauss_area_magnitude * sp + mag_k * (n1 * n1 + n0 * n0)
    h_scale = areas.mixed_area_magnitude * sp + mag_h * (abs(q0 * n0) + abs(q1 * n1))
    k_res = abs(areas.gauss_area * dp - area_k * (n1 * n1 - n0 * n0))
    h_res = abs(areas.mixed_area * dp + area_h * (q0 * n0 - q1 * n1))
    k_res = k_res / np.where(k_scale > tiny, k_scale, tiny)
    h_res = h_res / np.where(h_scale > tiny, h_scale, tiny)
    return k_res, h_res, dp != 0


@pytest.mark.parametrize("seed", [1, 2, 3])
@pytest.mark.parametrize("curvature", [-1.0, -0.37, None])
def test_fused_ring_checks_equal_the_ring_and_its_residuals(
    seed: int, curvature: float | None
) -> None:
    """Theorem 7's / 8's and (17)'s residuals in one pass: the steps they fuse
    (``ring_curvatures``, ``constant_curvature_residuals`` or ``minimal_residuals`` with
    ``np.maximum``, ``face_residuals``) to a few units of rounding of the residuals' scales (the
    pass multiplies by reciprocals where those divide), faces where (17) is 0/0 counted as
    skipped."""
    ar = Float64()
    cases = meridians(seed)
    flat = np.array([[0.0, 1.0], [1.0, 1.0], [2.0, 1.5], [3.0, 1.5], [4.0, 2.0]])
    cases.append((flat, flat * 0.5 + 0.25))
    for meridian, gauss in cases:
        n = min(len(meridian), len(gauss))
        meridian, gauss = meridian[:n], gauss[:n]
        fused = ring_curvature.ring_checks(ar, meridian, gauss, curvature)
        assert fused is not None
        ring = ring_curvature.ring_curvatures(ar, meridian, gauss)
        own = (
            ring_curvature.minimal_residuals(ring)
            if curvature is None
            else ring_curvature.constant_curvature_residuals(ring, curvature)
        )
        _close(fused[0], np.maximum(own, ring.parallel))
        k_res, h_res, defined = revolution_formulas.equation_17_residuals(
            ar, meridian[:, 1], gauss[:, 1], ring
        )
        _close(fused[1], np.where(defined, np.maximum(k_res, h_res), 0.0))
        assert fused[2] == int(np.count_nonzero(~defined))
        largest = ring_curvature.ring_largest(ar, meridian, gauss, curvature)
        assert largest is not None
        assert (largest[0].value, largest[1].value, largest[2]) == (
            np.max(fused[0]),
            np.max(fused[1]),
            fused[2],
        )
        np.testing.assert_array_equal(largest[1].residuals(), fused[1])


def test_fused_ring_checks_stay_finite_where_areas_are_far_from_1() -> None:
    """D4b with d = h/2 on -200 .. 300: the catenoid's faces reach areas of 1e266 and the
    pseudosphere's 1e-135; the residuals (17) and the theorems' stay within rounding of the
    numpy evaluation's (a product with 1/|a(f)| in place of a quotient overflowed here)."""
    ar = Float64()
    data = d4b.polygons(ar, 1.0, 0.5, None, -200, 300)
    pairs = [(data.tractrix, data.gauss.tractrix_gauss, -1.0), (data.p, data.gauss.gauss, None)]
    for meridian, gauss, curvature in pairs:
        fused = ring_curvature.ring_checks(ar, meridian, gauss, curvature)
        assert fused is not None
        ring = ring_curvature.ring_curvatures(ar, meridian, gauss)
        own = (
            ring_curvature.minimal_residuals(ring)
            if curvature is None
            else ring_curvature.constant_curvature_residuals(ring, curvature)
        )
        _close(fused[0], np.maximum(own, ring.parallel))
        k_res, h_res, defined = revolution_formulas.equation_17_residuals(
            ar, meridian[:, 1], gauss[:, 1], ring
        )
        _close(fused[1], np.where(defined, np.maximum(k_res, h_res), 0.0))
        assert fused[2] == int(np.count_nonzero(~defined))


def _close(fused: np.ndarray, expected: np.ndarray) -> None:
    """Residuals (each relative to its own scale) within 32 units of rounding of max(1, |r|),
    finite where the numpy evaluation's are."""
    assert fused.shape == expected.shape
    finite = np.isfinite(expected)
    np.testing.assert_array_equal(np.isfinite(fused), finite)
    bound = 32 * np.finfo(np.float64).eps * np.maximum(1.0, abs(expected[finite]))
    difference = abs(fused[finite] - expected[finite])
    assert bool(np.all(difference <= bound)), np.max(difference)


def test_fused_ring_checks_leave_a_face_without_area_to_the_numpy_path() -> None:
    meridian = np.array([[0.0, 1.0], [1.0, 1.0], [1.0, 1.0], [2.0, 2.0]])
    gauss = np.array([[0.0, 1.0], [0.5, 1.0], [0.7, 1.0], [1.0, 1.5]])
    assert ring_curvature.ring_checks(Float64(), meridian, gauss, -1.0) is None


def _scalar_largest(
    meridian: np.ndarray, gauss: np.ndarray, curvature: float | None
) -> tuple[float, float, int] | None:
    """``ring_kernel.ring_largest`` as the face-by-face pass computes it (``_ring_checks``)."""
    ar = Float64()
    theta = ar.pi / ring_curvature.RING_M
    _, skipped, valid, largest, largest_17 = ring_kernel._one_ring(
        meridian, gauss, ar.cos(theta), ar.sin(theta), curvature, False
    )
    return (float(largest), float(largest_17), int(skipped)) if valid else None


def _blocked_largest(
    meridian: np.ndarray, gauss: np.ndarray, curvature: float | None
) -> tuple[float, float, int] | None:
    ar = Float64()
    theta = ar.pi / ring_curvature.RING_M
    return ring_kernel.ring_largest(meridian, gauss, ar.cos(theta), ar.sin(theta), curvature)


def _same(found: object, expected: object) -> None:
    """Equal tuples, NaN equal to NaN, floats compared bit for bit."""
    assert (found is None) == (expected is None)
    if found is not None and expected is not None:
        assert isinstance(found, tuple) and isinstance(expected, tuple)
        np.testing.assert_array_equal(np.array(found[:2]), np.array(expected[:2]))
        assert found[2] == expected[2]


@pytest.mark.parametrize(
    ("d", "i_min", "i_max"), [(1e-3, -700, 900), (0.5, -200, 300), (0.99, -40, 60)]
)
def test_blocked_ring_largest_has_the_bits_of_the_face_by_face_pass(
    d: float, i_min: int, i_max: int
) -> None:
    """Both rings of a D4b over several blocks (areas from 1e-135 to 1e266 at d = h/2, where
    some faces leave the unscaled square root or the reciprocal and are redone face by face)."""
    ar = Float64()
    data = d4b.polygons(ar, 1.0, d, None, i_min, i_max)
    pairs = [(data.tractrix, data.gauss.tractrix_gauss, -1.0), (data.p, data.gauss.gauss, None)]
    for meridian, gauss, curvature in pairs:
        m, g = np.ascontiguousarray(meridian), np.ascontiguousarray(gauss)
        _same(_blocked_largest(m, g, curvature), _scalar_largest(m, g, curvature))


def test_blocked_ring_largest_takes_faces_off_the_usual_branch_face_by_face() -> None:
    """Tiny and huge faces (lengths by hypot, quotients by |a(f)|), a 0/0 face of (17), a NaN
    and a face without area, in the middle of blocks: the same as the face-by-face pass."""
    rng = np.random.default_rng(19)
    count = 3 * ring_kernel.RING_BLOCK + 7
    x = np.cumsum(rng.uniform(0.1, 1.0, count))
    meridian = np.column_stack([x, rng.uniform(0.5, 2.0, count)])
    gauss = np.column_stack([rng.uniform(-1, 1, count), rng.uniform(0.5, 2.0, count)])
    meridian[100:103] *= 1e-170  # squares underflow
    meridian[700:702] *= 1e170  # squares overflow
    meridian[900, 1] = meridian[901, 1]  # (17) 0/0
    for curvature in (-1.0, None):
        _same(
            _blocked_largest(meridian, gauss, curvature),
            _scalar_largest(meridian, gauss, curvature),
        )
    with_nan = meridian.copy()
    with_nan[1200, 0] = np.nan
    for curvature in (-1.0, None):
        _same(
            _blocked_largest(with_nan, gauss, curvature),
            _scalar_largest(with_nan, gauss, curvature),
        )
    flat = meridian.copy()
    flat[1300] = flat[1301]  # a face without area: both refuse it (None)
    assert _scalar_largest(flat, gauss, -1.0) is None
    assert _blocked_largest(flat, gauss, -1.0) is None


def test_ring_largest_of_strided_meridians_takes_the_face_by_face_pass() -> None:
    ar = Float64()
    data = d4b.polygons(ar, 1.0, 0.1, None, -50, 50)
    wide = np.zeros((len(data.p), 4))
    wide[:, :2] = data.p
    strided = wide[:, :2]
    assert not strided.flags.c_contiguous
    _same(
        _blocked_largest(strided, data.gauss.gauss, None),
        _scalar_largest(np.ascontiguousarray(strided), data.gauss.gauss, None),
    )


def _unbranched_rows(
    meridian: np.ndarray, gauss: np.ndarray, curvature: float | None
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The branch-free pass over every face (the blocks' loop, on whole columns): the theorem
    and (17) rows and which faces are on its branch."""
    ar = Float64()
    theta = ar.pi / ring_curvature.RING_M
    faces = len(meridian) - 1
    areas, theorem, equation_17, differences = (np.empty(faces) for _ in range(4))
    usual = np.empty(faces, dtype=np.bool_)
    x, y, u, v = (np.ascontiguousarray(a[:, k]) for a in (meridian, gauss) for k in (0, 1))
    ring_kernel._faces_unbranched(
        x,
        y,
        u,
        v,
        faces,
        ar.cos(theta),
        ar.sin(theta),
        0.0 if curvature is None else curvature,
        curvature is None,
        ring_kernel.TINY,
        areas,
        theorem,
        equation_17,
        differences,
        usual,
    )
    return theorem, equation_17, usual


@pytest.mark.parametrize("curvature", [-1.0, None])
def test_the_branch_free_faces_have_the_bits_of_the_face_by_face_pass(
    curvature: float | None,
) -> None:
    """Face by face, on the faces the branch-free loop keeps (a D4b over 1e-135 .. 1e266, a
    Gauss image equal to its meridian: every parallel cross product exactly 0, which stays on
    the branch), the theorem's and (17)'s residuals of the scalar face, bit for bit."""
    ar = Float64()
    data = d4b.polygons(ar, 1.0, 0.5, None, -200, 300)
    rng = np.random.default_rng(5)
    x = np.cumsum(rng.uniform(0.1, 1.0, 700))
    same = np.column_stack([x, rng.uniform(0.5, 2.0, 700)])
    cases = [(data.tractrix, data.gauss.tractrix_gauss), (data.p, data.gauss.gauss), (same, same)]
    for meridian, gauss in cases:
        m, g = np.ascontiguousarray(meridian), np.ascontiguousarray(gauss)
        fused = ring_kernel.ring_checks(m, g, *_angle(), curvature)
        assert fused is not None
        theorem, equation_17, usual = _unbranched_rows(m, g, curvature)
        assert usual.sum() > 200  # faces compared (at d = h/2 about half leave the branch)
        np.testing.assert_array_equal(theorem[usual], fused[0][usual])
        np.testing.assert_array_equal(equation_17[usual], fused[1][usual])
    _, _, usual = _unbranched_rows(same, same, curvature)
    assert usual.all()


def _angle() -> tuple[float, float]:
    ar = Float64()
    theta = ar.pi / ring_curvature.RING_M
    return ar.cos(theta), ar.sin(theta)


def test_a_block_is_reduced_at_once_only_without_nan_or_an_unusual_face() -> None:
    """The largest magnitude of a block by the bit patterns: the value of ``np.max`` of the
    magnitudes (zeros of either sign, subnormals, infinities); a NaN, a face off the branch or
    without area sends the block face by face."""
    rng = np.random.default_rng(23)
    count = 300
    theorems = rng.uniform(0, 1, count) * 10.0 ** rng.integers(-300, 300, count)
    equations = rng.uniform(0, 1, count) * 10.0 ** rng.integers(-300, 300, count)
    theorems[:3] = [5e-324, -0.0, 0.0]
    equations[7] = np.inf
    differences = rng.uniform(-1, 1, count)
    differences[[4, 40, 299]] = 0.0
    areas = rng.uniform(0.5, 1.0, count)
    usual = np.ones(count, dtype=np.bool_)
    block = ring_kernel._block_largest
    plain, zeros, top, top_17 = block(count, areas, theorems, equations, differences, usual)
    assert plain and zeros == 3
    assert top == np.abs(theorems).max() and top_17 == np.inf
    assert block(0, areas, theorems, equations, differences, usual) == (True, 0, 0.0, 0.0)
    for row, index, value in [(1, 10, np.nan), (2, 11, np.nan), (0, 12, 0.0), (0, 13, np.nan)]:
        rows = [a.copy() for a in (areas, theorems, equations)]
        rows[row][index] = value
        assert not block(count, rows[0], rows[1], rows[2], differences, usual)[0]
    off = usual.copy()
    off[20] = False
    assert not block(count, areas, theorems, equations, differences, off)[0]


@pytest.mark.parametrize("curvature", [-1.0, None])
def test_blocked_ring_largest_of_parallel_faces_and_nan_residuals(curvature: float | None) -> None:
    """Every cross product 0 (the Gauss image equal to the meridian), residuals rising over
    the blocks, and a residual NaN in the last block but no coordinate NaN: the same as the
    face-by-face pass."""
    rng = np.random.default_rng(31)
    count = 4 * ring_kernel.RING_BLOCK + 3
    x = np.cumsum(rng.uniform(0.1, 1.0, count))
    meridian = np.column_stack([x, np.linspace(0.5, 40.0, count)])
    _same(
        _blocked_largest(meridian, meridian.copy(), curvature),
        _scalar_largest(meridian, meridian.copy(), curvature),
    )
    gauss = np.column_stack([rng.uniform(-1, 1, count), rng.uniform(0.5, 2.0, count)])
    gauss[-5, 1] = np.inf  # inf − inf: residuals NaN, areas finite
    found = _blocked_largest(meridian, gauss, curvature)
    _same(found, _scalar_largest(meridian, gauss, curvature))
