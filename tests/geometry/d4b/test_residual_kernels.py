"""The compiled Section 4.2 residuals of (D4b) equal the numpy evaluation bit for bit."""

from __future__ import annotations

import numpy as np
import pytest

from app.geometry import nikolaides
from app.geometry.checks import relative_difference
from app.geometry.d4b import closed_forms, discretization as d4b, residual_kernels
from app.geometry.precision import Float64


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
