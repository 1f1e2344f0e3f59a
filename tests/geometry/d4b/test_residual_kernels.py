"""The compiled Section 4.2 residuals of (D4b) equal the numpy evaluation bit for bit."""

from __future__ import annotations

import numpy as np
import pytest

from app.geometry import checks, nikolaides
from app.geometry.checks import relative_difference
from app.geometry.d4b import closed_forms, discretization as d4b, residual_kernels
from app.geometry.precision import Float64, MultiPrecision, stack_points
from tests.geometry.d4b.test_residual_blocks import ref_printed_ratios


def polygons(seed: int) -> list[d4b.D4bPolygons]:
    ar = Float64()
    rng = np.random.default_rng(seed)
    h = float(rng.uniform(0.5, 3))
    d = h * float(rng.uniform(0.001, 0.95))
    beta0 = float(rng.uniform(0.2, 2.9))
    return [
        d4b.polygons(ar, h, d, beta0, -60, 70),
        d4b.polygons(ar, h, d, None, 5, 9),
        d4b.polygons(ar, h, d, beta0, -30, 40, "closed-form"),
    ]


def perturbed(data: d4b.D4bPolygons, seed: int) -> tuple[np.ndarray, ...]:
    """The polygons with noise, so that the residuals are far from zero too."""
    rng = np.random.default_rng(seed)
    return tuple(
        a * (1 + rng.normal(size=a.shape) * 1e-3) for a in (data.p, data.tractrix, data.axis)
    )


@pytest.mark.parametrize("seed", [1, 2, 3, 4])
def test_recursion_residuals_equal_numpy(seed: int) -> None:
    ar = Float64()
    for data in polygons(seed):
        for p in (data.p, perturbed(data, seed)[0]):
            y = p[:, 1]
            d = float(data.p[1, 0] - data.p[0, 0]) / 2
            one, two = residual_kernels.recursion_residuals(d, y)
            expected_one = relative_difference(
                ar, y[2:], closed_forms.recursion_13(d, y[:-2], y[1:-1])
            )
            expected_two = relative_difference(ar, y[3:], closed_forms.two_step(d, y[:-3], y[1:-2]))
            np.testing.assert_array_equal(one, expected_one)
            np.testing.assert_array_equal(two, expected_two)


@pytest.mark.parametrize("seed", [1, 2, 3, 4])
def test_right_angle_residuals_equal_numpy(seed: int) -> None:
    for data in polygons(seed):
        n = len(data.p) - 1
        for p, tractrix, axis in ((data.p, data.tractrix, data.axis), perturbed(data, seed)):
            got = residual_kernels.right_angle_residuals(tractrix, axis, p, n)
            expected = np.maximum(
                nikolaides.right_angle_residuals(tractrix[:n], axis[:n], p[:n]),
                nikolaides.right_angle_residuals(tractrix[:n], axis[:n], p[1 : n + 1]),
            )
            np.testing.assert_array_equal(got, expected)


def test_short_polygons_give_empty_residuals() -> None:
    one, two = residual_kernels.recursion_residuals(0.1, np.array([1.0, 1.1]))
    assert one.shape == (0,) and two.shape == (0,)


def within_ulps(got: np.ndarray, expected: np.ndarray, ulps: int) -> bool:
    """Entry by entry within ``ulps`` units in the last place of the larger (NaN where NaN)."""
    same_nan = np.isnan(got) == np.isnan(expected)
    both = ~np.isnan(got)
    scale = np.spacing(np.maximum(abs(got[both]), abs(expected[both])))
    return bool(np.all(same_nan) and np.all(abs(got[both] - expected[both]) <= ulps * scale))


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_point_distances_within_two_ulps_of_hypot(seed: int) -> None:
    ar = Float64()
    rng = np.random.default_rng(seed)
    size = 4000
    # magnitudes from subnormal to near overflow, zeros, and equal points
    a = rng.normal(size=(size, 2)) * 10.0 ** rng.integers(-320, 300, size=(size, 2))
    b = a * (1 + rng.normal(size=(size, 2)) * 10.0 ** rng.integers(-16, 1, size=(size, 2)))
    a[:10], b[5:15] = 0.0, a[5:15]
    for got, expected in (
        (residual_kernels.point_distance(ar, a, b), checks.point_distance(ar, a, b)),
        (
            residual_kernels.relative_point_difference(ar, a, b),
            checks.relative_point_difference(ar, a, b),
        ),
    ):
        assert within_ulps(got, expected, 2)
    for data in polygons(seed):
        for built, closed in ((data.p, data.closed_p), (data.tractrix, data.closed_tractrix)):
            got = residual_kernels.relative_point_difference(ar, built, closed)
            assert within_ulps(got, checks.relative_point_difference(ar, built, closed), 2)


def test_point_distances_in_mp_are_the_generic_ones() -> None:
    ar = MultiPrecision(30)
    a = stack_points(ar.array([1, 3]), ar.array([2, 4]))
    b = stack_points(ar.array([1, 0]), ar.array([1, 0]))
    assert list(residual_kernels.point_distance(ar, a, b)) == [1, 5]
    assert list(residual_kernels.relative_point_difference(ar, a, b)) == list(
        checks.relative_point_difference(ar, a, b)
    )


@pytest.mark.parametrize("seed", [1, 2])
def test_pole_by_inversion_equals_numpy(seed: int) -> None:
    rng = np.random.default_rng(seed)
    before, after = rng.normal(size=(500, 2)), rng.normal(size=(500, 2))
    total = before + after
    squared = total[:, 0] * total[:, 0] + total[:, 1] * total[:, 1]
    expected = np.stack([2 * total[:, 0] / squared, 2 * total[:, 1] / squared], axis=1)
    np.testing.assert_array_equal(closed_forms.pole_by_inversion(before, after), expected)
    contact = rng.normal(size=(50, 2))  # views of one array, as the check passes them
    np.testing.assert_array_equal(
        closed_forms.pole_by_inversion(contact[:-1], contact[1:]),
        closed_forms.pole_by_inversion(contact[:-1].copy(), contact[1:].copy()),
    )


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_along_and_edge_resolution_equal_numpy(seed: int) -> None:
    """The edge-direction residual of (18) bit for bit, the edge resolution within 2 ulp."""
    rng = np.random.default_rng(seed)
    points = rng.normal(size=(300, 2)) * 10.0 ** rng.integers(-5, 5, size=(300, 1))
    vectors = rng.normal(size=(299, 2))
    edges = points[1:] - points[:-1]
    size = abs(points[:-1, 0]) + abs(points[:-1, 1]) + abs(points[1:, 0]) + abs(points[1:, 1])
    crossed = abs(vectors[:, 0] * edges[:, 1] - vectors[:, 1] * edges[:, 0])
    backwards = vectors[:, 0] * edges[:, 0] + vectors[:, 1] * edges[:, 1] < 0
    assert backwards.any() and not backwards.all()
    np.testing.assert_array_equal(
        residual_kernels.along(vectors, points), np.where(backwards, 1.0, crossed / size)
    )
    expected = np.hypot(edges[:, 0], edges[:, 1]) / size
    assert within_ulps(residual_kernels.edge_resolution(points), expected, 2)
    assert residual_kernels.edge_resolution(points[:1]).shape == (0,)


@pytest.mark.parametrize("seed", [1, 2, 3, 4])
def test_rotation_angles_equal_numpy(seed: int) -> None:
    """Theorem 4's rotation angle, corrected and printed, as the numpy evaluation (atan2 of
    libm in both: equal to a few units of the angles, which are below π)."""
    for data in polygons(seed):
        n = len(data.p) - 1
        d = float(data.p[1, 0] - data.p[0, 0]) / 2
        for p, _, axis in ((data.p, data.tractrix, data.axis), perturbed(data, seed)):
            corrected, printed = residual_kernels.rotation_angles(d, p, axis, n)
            formula = 2 * np.arctan2(d, p[1:n, 1])

            def angle(a: np.ndarray, b: np.ndarray) -> np.ndarray:
                cross = a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]
                return np.arctan2(cross, a[:, 0] * b[:, 0] + a[:, 1] * b[:, 1])

            expected = abs(angle(axis[: n - 1] - p[1:n], axis[1:n] - p[1:n]) - formula)
            expected_printed = abs(angle(axis[1:n] - p[1:n], axis[2 : n + 1] - p[1:n]) - formula)
            unit = 4 * np.spacing(np.pi)
            np.testing.assert_allclose(corrected, expected, rtol=0, atol=unit)
            np.testing.assert_allclose(printed, expected_printed, rtol=0, atol=unit)


@pytest.mark.parametrize("seed", [1, 2, 3, 4])
def test_hypothesis_pass_equals_numpy(seed: int) -> None:
    """Theorem 4's hypothesis in one pass: the largest violation and the smallest ratio of the
    numpy evaluation, bit for bit (heights pushed below d so that violations are not all 0)."""
    for data in polygons(seed):
        d = float(data.p[1, 0] - data.p[0, 0]) / 2
        for p in (data.p, perturbed(data, seed)[0], data.p * [1.0, 0.0] + [0.0, 0.9 * d]):
            n = len(p) - 1
            y = p[:n, 1]
            products = y[:-1] * y[1:]
            violation = np.maximum(d * d - products, 0.0) / (d * d)
            largest, smallest = residual_kernels.hypothesis_largest(p, n, d)
            assert (largest.value, len(largest)) == (np.max(np.abs(violation)), n - 1)
            assert smallest == np.min(products / (d * d))
            np.testing.assert_array_equal(largest.residuals(), violation)
    nan = np.array([[0.0, 1.0], [1.0, np.nan], [2.0, 1.0]])
    largest, smallest = residual_kernels.hypothesis_largest(nan, 3, 0.5)
    assert np.isnan(largest.value) and np.isnan(smallest)


@pytest.mark.parametrize("seed", [1, 2, 3, 4])
def test_contact_rotation_pass_equals_numpy(seed: int) -> None:
    """(19) as n turned a quarter: the one pass gives the numpy path's residuals bit for bit."""
    ar = Float64()
    rng = np.random.default_rng(seed)
    for data in polygons(seed):
        n = data.vertices - 1
        images = data.gauss
        for contact in (images.contact, images.contact * (1 + rng.normal(size=(n + 2, 2)) * 1e-6)):
            scale = rng.uniform(0, 1, n)
            normals = images.tractrix_gauss
            rotated = np.stack([-normals[:, 1], normals[:, 0]], axis=1)
            expected = residual_kernels.point_distance(ar, contact[1 : n + 1], rotated[:n]) * scale
            largest = residual_kernels.contact_rotation_largest(contact, normals, scale, n)
            assert (largest.value, len(largest)) == (np.max(expected), n)
            np.testing.assert_array_equal(largest.residuals(), expected)


@pytest.mark.parametrize("seed", [1, 2, 3, 4])
def test_pole_inversion_pass_equals_numpy(seed: int) -> None:
    """(20) as the inverted midpoint: the one pass gives the numpy path's residuals bit for
    bit."""
    ar = Float64()
    rng = np.random.default_rng(seed)
    for data in polygons(seed):
        n = data.vertices - 1
        images = data.gauss
        for gauss in (images.gauss, images.gauss * (1 + rng.normal(size=(n + 1, 2)) * 1e-6)):
            scale = rng.uniform(0, 1, n)
            contact = images.contact
            inverted = closed_forms.pole_by_inversion(contact[:-1], contact[1:])
            expected = residual_kernels.relative_point_difference(ar, gauss[:n], inverted[:n])
            expected = expected * scale
            largest = residual_kernels.pole_inversion_largest(gauss, contact, scale, n)
            assert (largest.value, len(largest)) == (np.max(expected), n)
            np.testing.assert_array_equal(largest.residuals(), expected)


@pytest.mark.parametrize("seed", [1, 2, 3, 4])
def test_blocked_rotation_angles_equal_the_one_pass(seed: int) -> None:
    """The blocks (numpy's vectorized arctan2) give the one libm pass's residuals to an ulp of
    the angles, and the same largest ones, whatever the block size (long polygons take them)."""
    for data in polygons(seed):
        n = len(data.p) - 1
        d = float(data.p[1, 0] - data.p[0, 0]) / 2
        for p, _, axis in ((data.p, data.tractrix, data.axis), perturbed(data, seed)):
            one_pass = residual_kernels._rotation_angles(d, p, axis, n, True)
            unit = 2 * np.spacing(np.pi)
            for block in (1, 7, n - 1, 4096):
                corrected, printed, largest, worst = residual_kernels._rotation_angles(
                    d, p, axis, n, True, block
                )
                np.testing.assert_allclose(corrected, one_pass[0], rtol=0, atol=unit)
                np.testing.assert_allclose(printed, one_pass[1], rtol=0, atol=unit)
                assert (largest, worst) == (np.max(corrected), np.max(printed))
                _, _, alone, worst_alone = residual_kernels._rotation_angles(
                    d, p, axis, n, False, block
                )
                assert (alone, worst_alone) == (largest, worst)
    long = d4b.polygons(Float64(), 1.0, 1e-3, None, -3000, 3000)  # past ROTATION_LIBM_BELOW
    n = long.vertices - 1
    corrected, printed = residual_kernels.rotation_angles(1e-3, long.p, long.axis, n)
    libm = residual_kernels._rotation_angles_libm(1e-3, long.p, long.axis, n, True)
    np.testing.assert_allclose(corrected, libm[0], rtol=0, atol=2 * np.spacing(np.pi))
    np.testing.assert_allclose(printed, libm[1], rtol=0, atol=2 * np.spacing(np.pi))


@pytest.mark.parametrize("seed", [1, 2, 3, 4])
def test_printed_two_step_residuals_equal_numpy(seed: int) -> None:
    ar = Float64()
    for data in polygons(seed):
        for p in (data.p, perturbed(data, seed)[0]):
            y = p[:, 1]
            d = float(data.p[1, 0] - data.p[0, 0]) / 2
            with np.errstate(over="ignore", invalid="ignore"):  # 5th powers of long ranges
                expected = relative_difference(
                    ar, y[3:], closed_forms.two_step_printed(d, y[:-3], y[1:-2])
                )
            got = residual_kernels.two_step_printed_residuals(d, y)
            # numpy's power may be its own vectorized one: the predicted heights agree to a few
            # units in the last place, so the residuals to a few eps
            eps = np.finfo(np.float64).eps
            np.testing.assert_allclose(got, expected, rtol=8 * eps, atol=8 * eps)
    assert residual_kernels.two_step_printed_residuals(0.1, np.ones(3)).shape == (0,)


@pytest.mark.parametrize("seed", [1, 2, 3, 4])
def test_scaled_and_largest_relative_differences_equal_the_array_path(seed: int) -> None:
    """One pass each: the scaled residuals and the largest one, as the array and numpy give."""
    ar = Float64()
    for data in polygons(seed):
        p = perturbed(data, seed)[0]
        scale = np.random.default_rng(seed).uniform(0, 1, len(p))
        residuals = residual_kernels.relative_point_difference(ar, p, data.p)
        np.testing.assert_array_equal(
            residual_kernels.scaled_relative_point_difference(p, data.p, scale),
            residuals * scale,
        )
        assert residual_kernels.largest_relative_point_difference(
            p, data.p
        ) == checks.printed_residual(ar, residuals)
    assert (
        residual_kernels.largest_relative_point_difference(np.empty((0, 2)), np.empty((0, 2)))
        is None
    )
    nan = np.array([[1.0, 2.0], [np.nan, 1.0]])
    assert residual_kernels.largest_relative_point_difference(nan, np.ones((2, 2))) is None


@pytest.mark.parametrize("seed", [1, 2, 3, 4])
def test_largest_residuals_are_the_arrays_largest(seed: int) -> None:
    """Without ``detail`` the kernels return the largest residual alone: the arrays' maximum."""
    for data in polygons(seed):
        n = len(data.p) - 1
        d = float(data.p[1, 0] - data.p[0, 0]) / 2
        for p, tractrix, axis in ((data.p, data.tractrix, data.axis), perturbed(data, seed)):
            one, two = residual_kernels.recursion_residuals(d, p[:, 1])
            largest_one, largest_two = residual_kernels.recursion_largest(d, p[:, 1])
            assert (largest_one.value, largest_one.count) == (np.max(one), len(one))
            assert (largest_two.value, largest_two.count) == (np.max(two), len(two))
            right = residual_kernels.right_angle_residuals(tractrix, axis, p, n)
            assert residual_kernels.right_angle_largest(tractrix, axis, p, n).value == np.max(right)
            corrected, printed = residual_kernels.rotation_angles(d, p, axis, n)
            largest, worst = residual_kernels.rotation_angle_largest(d, p, axis, n)
            assert (largest.value, len(largest), worst) == (
                np.max(corrected),
                len(corrected),
                np.max(printed),
            )
            np.testing.assert_array_equal(largest.residuals(), corrected)
            y = p[:, 1]
            assert residual_kernels.largest_two_step_printed_residual(
                d, y
            ) == checks.printed_residual(
                Float64(), residual_kernels.two_step_printed_residuals(d, y)
            )
    assert residual_kernels.largest_two_step_printed_residual(0.1, np.ones(3)) is None


def test_a_largest_that_is_not_finite_takes_the_array_path() -> None:
    """A NaN among unstored residuals: the check asks for the array to count them, as before."""
    ar = Float64()
    residuals = np.array([1e-17, np.nan, 2e-17])
    largest = checks.Largest(float("nan"), 3, lambda: residuals)
    statement = d4b.STATEMENTS[0]
    indices = np.arange(3, dtype=np.int64)
    got = checks.check_residuals(statement, ar, indices, largest, 1e-15, False)
    assert got == checks.check_residuals(statement, ar, indices, residuals, 1e-15, False)
    assert got.note is not None and "1 of 3 residuals" in got.note
    finite = checks.Largest(2e-17, 3, lambda: residuals)
    kept = checks.check_residuals(statement, ar, indices, finite, 1e-15, False)
    assert (kept.residual, kept.holds, kept.per_index) == (2e-17, True, None)
    empty = checks.check_residuals(
        statement, ar, indices, checks.Largest(0.0, 0, lambda: residuals[:0]), 1e-15, False
    )
    assert empty.holds is None


@pytest.mark.parametrize("seed", [1, 2, 3, 4])
def test_printed_gauss_images_in_one_pass_equal_the_arrays(seed: int) -> None:
    """The errata of (18), (19), (20) and (18) from slopes without arrays: the printed forms
    read off the corrected closed forms, and the slopes' form, to the bit."""
    from app.geometry.d4b import curvature

    ar = Float64()
    for data in polygons(seed):
        n = len(data.p) - 1
        forms = curvature.printed_forms(ar, data.h, data.d, data.shift, data.i_min, data.i_max)
        images = data.gauss
        for key, built in (
            ("18", images.tractrix_gauss),
            ("19", images.contact[1:]),
            ("20", images.gauss),
        ):
            for points in (built, built * 1.01):
                got = forms.largest(key, points[:n], images)
                expected = residual_kernels.largest_relative_point_difference(
                    points[:n], forms(key)[:n]
                )
                assert got is not None and got == expected
        p = data.p
        edges = p[1:] - p[:-1]
        vectors = closed_forms.normal_from_slope_printed(ar, edges[:, 1] / edges[:, 0])
        expected = checks.printed_residual(ar, residual_kernels.along(vectors[:n], p[: n + 1]))
        assert residual_kernels.largest_along_printed_slope(n, p) == expected
    assert residual_kernels.largest_along_printed_slope(0, np.ones((1, 2))) is None


@pytest.mark.parametrize("seed", [1, 2, 3, 4])
def test_ratio_spread_equals_numpy(seed: int) -> None:
    """Erratum E2's printed residual in compiled passes: the numpy evaluation's bits."""
    ar = Float64()
    for data in polygons(seed):
        for p in (data.p, perturbed(data, seed)[0]):
            y = p[:, 1]
            lengths = np.hypot(p[1:, 0] - p[:-1, 0], y[1:] - y[:-1])
            ratio = (y[3:] - 2 * y[2:-1] + y[1:-2]) / (lengths[:-2] + lengths[1:-1])
            mean = np.full_like(ratio, np.sum(ratio) / len(ratio))
            expected = checks.printed_residual(ar, relative_difference(ar, ratio, mean))
            assert residual_kernels.ratio_spread(p) == expected
    assert residual_kernels.ratio_spread(np.ones((4, 2))) is None


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_largest_scaled_relative_point_difference_is_the_arrays_largest(seed: int) -> None:
    """(18)-(20) against their closed forms without ``detail``: the largest of the residuals the
    array passes give, bit for bit (NaN if one is NaN), and those arrays on demand."""
    rng = np.random.default_rng(seed)
    computed, expected = rng.normal(size=(300, 2)), rng.normal(size=(300, 2))
    expected[7] = 0.0  # floored at tiny
    scale = rng.uniform(0.0, 1.0, 300)
    for factors in (None, scale):
        found = residual_kernels.largest_scaled_relative_point_difference(
            computed, expected, factors
        )
        if factors is None:
            array = residual_kernels.relative_point_difference(Float64(), computed, expected)
        else:
            array = residual_kernels.scaled_relative_point_difference(computed, expected, factors)
        assert found.value == float(np.max(np.abs(array))) and found.count == 300
        np.testing.assert_array_equal(found.residuals(), array)
    broken = computed.copy()
    broken[11, 1] = np.nan
    found = residual_kernels.largest_scaled_relative_point_difference(broken, expected, scale)
    assert np.isnan(found.value)


@pytest.mark.parametrize("seed", [1, 2, 3, 4])
def test_ratio_spread_from_the_extremes_equals_the_pass_over_every_ratio(seed: int) -> None:
    """The spread read at the smallest and largest ratio is the pass's (a division an entry)."""
    rng = np.random.default_rng(seed)
    for data in polygons(seed):
        for p in (data.p, perturbed(data, seed)[0], data.p * rng.uniform(0.5, 2, data.p.shape)):
            ratio = ref_printed_ratios(np.ascontiguousarray(p, dtype=np.float64))
            if len(ratio) < 2:
                continue
            mean = float(np.sum(ratio) / len(ratio))
            expected = float(residual_kernels._largest_spread(ratio, mean, residual_kernels.TINY))
            assert residual_kernels.ratio_spread(p) == expected


@pytest.mark.parametrize("seed", [1, 2, 3, 4])
def test_along_and_its_printed_slope_in_one_pass_equal_the_two_passes(seed: int) -> None:
    for data in polygons(seed):
        p = perturbed(data, seed)[0]
        n = len(p) - 1
        for vectors in (data.gauss.tractrix_gauss[:n], -data.gauss.tractrix_gauss[:n]):
            largest, printed = residual_kernels.along_largest(vectors, p)
            rows = residual_kernels.along(vectors, p[: n + 1])
            assert largest.value == checks.largest_magnitude(rows)
            np.testing.assert_array_equal(largest.residuals(), rows)
            assert printed == residual_kernels.largest_along_printed_slope(n, p)


@pytest.mark.parametrize("seed", [1, 2, 3, 4])
def test_rotation_and_inversion_in_one_pass_equal_the_passes_over_stored_scales(seed: int) -> None:
    """(19) as a rotation and (20) by inversion with their resolutions made as the pass goes:
    the largest residuals of the passes over the stored resolution and pole resolution (as
    ``curvature.evaluate`` makes them), NaN included."""
    rng = np.random.default_rng(seed)
    for data in polygons(seed):
        images = data.gauss
        before = images.contact_edges_before
        p, c, nt, m = data.p, images.contact, images.tractrix_gauss, images.gauss
        noisy = p * (1 + rng.normal(size=p.shape) * 1e-6)
        with_nan = p.copy()
        with_nan[len(p) // 2, 1] = np.nan
        for points in (p, noisy, with_nan):
            n = len(points) - 1
            resolution = residual_kernels.edge_resolution(points)
            previous = np.concatenate([residual_kernels.edge_resolution(before), resolution[:-1]])
            pole = np.minimum(previous, resolution)
            rotation = residual_kernels.contact_rotation_largest(c, nt, resolution, n)
            inversion = residual_kernels.pole_inversion_largest(m, c, pole, n)
            found = residual_kernels.rotation_and_inversion_largest(
                points, before, c, nt, m, n, True, True
            )
            np.testing.assert_array_equal(found, (rotation.value, inversion.value))
            alone = residual_kernels.rotation_and_inversion_largest(
                points, before, c, nt, m, n, False, True
            )
            np.testing.assert_array_equal(alone, (0.0, inversion.value))
