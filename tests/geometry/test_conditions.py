"""(D1), (D3), eq. (2) residuals and fitted constants on hand-made polygons."""

from __future__ import annotations

import numpy as np
import pytest

from app.geometry import conditions
from app.geometry.d1 import construction as hanging_chain
from app.geometry.polygon import edge_lengths, second_difference, signed_areas
from app.geometry.precision import Float64


def test_polygon_quantities_by_hand(float64: Float64) -> None:
    p = np.array([[0.0, 1.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]])
    np.testing.assert_allclose(second_difference(p[:, 1]), [-1.0, -2.0])
    np.testing.assert_allclose(edge_lengths(float64, p), [np.sqrt(2), 2.0, np.sqrt(5)])
    np.testing.assert_allclose(signed_areas(p), [1.5, 4.0, 1.0])
    # an edge running backwards has negative area
    assert signed_areas(p[::-1])[0] == pytest.approx(-1.0)


def test_d3_fit_finds_the_constant_of_a_horizontal_line(float64: Float64) -> None:
    p = np.column_stack([np.linspace(-1, 2, 7), np.full(7, 0.75)])
    fit = conditions.d3(float64, p)
    assert fit.constant == pytest.approx(0.75, rel=1e-15)
    assert np.max(fit.residuals) < 1e-15


def test_d1_on_a_polygon_built_to_satisfy_it(float64: Float64) -> None:
    # choose y by (D1) itself: y_{i+2} solves Δ²y_i = c(l_i + l_{i+1}) for constant spacing
    c, dx = 0.2, 0.5
    y = [1.0, 1.1]
    for _ in range(8):
        y0, y1 = y[-2], y[-1]
        l0 = np.hypot(dx, y1 - y0)
        # y2 − 2y1 + y0 = c(l0 + sqrt(dx² + (y2 − y1)²)): solve the quadratic for t = y2 − y1
        a, b = 1 - c * c, -2 * (y1 - y0 + c * l0)
        k = (y1 - y0 + c * l0) ** 2 - c * c * dx * dx
        t = (-b + np.sqrt(b * b - 4 * a * k)) / (2 * a)
        y.append(y1 + t)
    p = np.column_stack([dx * np.arange(len(y)), y])
    fit = conditions.d1(float64, p)
    assert fit.constant == pytest.approx(c, rel=1e-12)
    assert np.max(fit.residuals) < 1e-14
    assert np.max(conditions.d3(float64, p).residuals) > 1e-4  # (D1) does not imply (D3)


def test_a_small_perturbation_is_far_above_the_float64_tolerance(float64: Float64) -> None:
    p = np.column_stack([np.linspace(-1, 1, 9), np.full(9, 2.0)])
    assert np.max(conditions.d3(float64, p).residuals) < float64.tolerance(16)
    p[4, 1] *= 1 + 1e-6
    # residuals are relative to the coordinates' magnitude (|y| = 2 against a spacing of 0.25)
    assert np.max(conditions.d3(float64, p).residuals) > 1e4 * float64.tolerance(16)


def test_equilibrium_is_d1_over_the_spacing_when_the_spacing_is_constant(float64: Float64) -> None:
    p = hanging_chain.construct(float64, 0.2, 0.3, 2.0, 2.1, -6, 6).vertices
    assert conditions.d1(float64, p).constant == pytest.approx(0.2, rel=1e-13)
    assert conditions.equilibrium(float64, p).constant == pytest.approx(0.2 / 0.3, rel=1e-13)
    assert np.max(conditions.equilibrium(float64, p).residuals) < 1e-14


def test_hanging_sticks_with_uneven_spacing_are_in_equilibrium_but_not_d1(float64: Float64) -> None:
    # sticks of any horizontal extents: the hinge balance fixes each next slope
    # k_{i+1} = k_i + c(l_i + l_{i+1}), solved for k_{i+1} (l_{i+1} depends on it)
    c = 0.2
    spacing = [0.5, 0.3, 0.7, 0.4, 0.6, 0.2, 0.5]
    x, y, k = [0.0, 0.5], [1.0, 0.8], (0.8 - 1.0) / 0.5
    for dx in spacing[1:]:
        length = (
            np.hypot(spacing[0], k * spacing[0])
            if len(x) == 2
            else np.hypot(x[-1] - x[-2], y[-1] - y[-2])
        )
        # k' − c·dx·√(1 + k'²) = k + c·length: monotone in k', solve by bisection
        lo, hi = -100.0, 100.0
        for _ in range(200):
            mid = (lo + hi) / 2
            if mid - c * dx * np.hypot(1, mid) < k + c * length:
                lo = mid
            else:
                hi = mid
        k = (lo + hi) / 2
        x.append(x[-1] + dx)
        y.append(y[-1] + k * dx)
    p = np.column_stack([x, y])
    fit = conditions.equilibrium(float64, p)
    assert fit.constant == pytest.approx(c, rel=1e-12)
    assert np.max(fit.residuals) < 1e-13
    assert np.max(conditions.d1(float64, p).residuals) > 1e-2  # (D1) needs equal spacing


def test_fit_does_not_overflow_for_tiny_left_hand_sides(float64: Float64) -> None:
    # areas of 1e-300 against lengths of 2: the normalized right-hand sides are about 1e300
    p = np.array([[0.0, 0.0], [2.0, 1e-300], [4.0, 3e-300]])
    with np.errstate(all="raise"):
        fit = conditions.d3(float64, p)
    assert fit.constant == pytest.approx(np.sum(signed_areas(p) * 2) / 8, rel=1e-6)


def test_fit_does_not_overflow_when_a_row_has_no_magnitude(float64: Float64) -> None:
    # found by fuzzing (D1 with δ ≈ 1.8e16 through p_0 = (0, 0)): an edge on the axis has area 0
    # and area magnitude 0, so its weight is the smallest normal float and rhs/weight overflowed;
    # that exact row demands c·l = 0, so the weighted fit is c = 0, with the other rows failing
    lhs, lhs_magnitude = np.array([0.0, 2e36, 4e36]), np.array([0.0, 4e37, 8e37])
    rhs = np.array([1.8e16, 1e20, 2e20])
    with np.errstate(over="raise", invalid="raise", divide="raise"):
        found = conditions.fit(float64, lhs, rhs, lhs_magnitude, rhs)
    assert found.constant == 0.0
    assert found.residuals[0] == 0.0 and np.all(found.residuals[1:] > 0.04)
    # without that row the constant is 2e16, recovered through the scalings
    with np.errstate(over="raise", invalid="raise", divide="raise"):
        found = conditions.fit(float64, lhs[1:], rhs[1:], lhs_magnitude[1:], rhs[1:])
    assert found.constant == pytest.approx(2e16, rel=1e-15)
    assert np.max(found.residuals) < 1e-15
