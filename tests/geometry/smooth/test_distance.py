"""Distances to the catenary and the tractrix, against exact constructions and brute force."""

from __future__ import annotations

import mpmath
import numpy as np
import pytest

from app.geometry.precision import Arithmetic, Float64, MultiPrecision, stack_points
from app.geometry.smooth.distance import (
    bracketed_root,
    distance_to_catenary,
    distance_to_tractrix,
)

PRECISIONS = [(Float64(), 1e-13), (MultiPrecision(40), 1e-36)]


def _floats(ar: Arithmetic, values: np.ndarray) -> np.ndarray:
    return ar.to_floats(values)


@pytest.mark.parametrize(("ar", "tol"), PRECISIONS, ids=["float64", "mp40"])
def test_points_offset_along_the_normal_are_at_the_offset(ar: Arithmetic, tol: float) -> None:
    """A point r·n away from the curve along its normal, r below the curvature radius."""
    h = ar.scalar(1.2)
    s = ar.array([-2.5, -1.0, -0.6, 0.4, 1.1, 2.8])
    r = ar.scalar(0.01)
    # catenary (s, h cosh(s/h)): unit normal (−sinh, 1)/cosh, radius h cosh² >= h
    c, sh = ar.cosh(s / h), ar.sinh(s / h)
    below = stack_points(s + r * sh / c, h * c - r / c)
    above = stack_points(s - r * sh / c, h * c + r / c)
    for q in (below, above):
        got = _floats(ar, distance_to_catenary(ar, h, q))
        np.testing.assert_allclose(got, 0.01, rtol=tol * 1e3)
    # tractrix T(s): unit tangent ±(tanh, −sech), normal (sech, tanh); radius h|sinh(s/h)|,
    # so stay on the convex side or within the radius (|s| >= 0.4 here: radius >= 0.49)
    t, sech = ar.tanh(s / h), 1 / ar.cosh(s / h)
    on = stack_points(s - h * t, h * sech)
    for sign in (1, -1):
        q = stack_points(on[:, 0] + sign * r * sech, on[:, 1] + sign * r * t)
        got = _floats(ar, distance_to_tractrix(ar, h, q))
        np.testing.assert_allclose(got, 0.01, rtol=tol * 1e3)


@pytest.mark.parametrize(("ar", "tol"), PRECISIONS, ids=["float64", "mp40"])
def test_points_on_the_curves_are_at_distance_zero(ar: Arithmetic, tol: float) -> None:
    h = ar.scalar(0.7)
    s = ar.array([-3.0, -0.5, 0.0, 0.3, 2.0])
    on_catenary = stack_points(s, h * ar.cosh(s / h))
    on_tractrix = stack_points(s - h * ar.tanh(s / h), h / ar.cosh(s / h))
    assert np.max(_floats(ar, distance_to_catenary(ar, h, on_catenary))) < tol
    assert np.max(_floats(ar, distance_to_tractrix(ar, h, on_tractrix))) < tol


def _brute_force(curve, point, lo: float, hi: float) -> float:
    """min over a dense grid refined five times, in plain mpmath at 30 digits."""
    ctx = mpmath.MPContext()
    ctx.dps = 30
    qx, qy = ctx.mpf(point[0]), ctx.mpf(point[1])
    a, b = ctx.mpf(lo), ctx.mpf(hi)
    best = None
    for _ in range(6):
        grid = [a + (b - a) * k / 400 for k in range(401)]
        values = [ctx.hypot(curve(ctx, s)[0] - qx, curve(ctx, s)[1] - qy) for s in grid]
        k = min(range(401), key=lambda j: values[j])
        best = values[k]
        a, b = grid[max(k - 1, 0)], grid[min(k + 1, 400)]
    return float(best)


def test_tractrix_distance_near_the_cusp_and_across_branches(float64: Float64) -> None:
    """Points where the nearest point is the cusp, or on the other branch."""
    h = 1.0
    points = np.array([[0.0, 1.2], [0.05, 1.05], [-0.02, 0.9], [0.3, 0.5], [-1.5, 0.2]])

    def tractrix(ctx, s):
        return s - h * ctx.tanh(s / h), h / ctx.cosh(s / h)

    got = distance_to_tractrix(float64, h, points)
    expected = [_brute_force(tractrix, p, -6, 6) for p in points]
    np.testing.assert_allclose(got, expected, rtol=1e-9)


def test_catenary_distance_against_brute_force(float64: Float64) -> None:
    h = 0.8
    points = np.array([[0.3, 0.5], [-1.0, 1.9], [2.0, 3.0], [0.0, 0.79]])

    def catenary(ctx, s):
        return s, h * ctx.cosh(s / h)

    got = distance_to_catenary(float64, h, points)
    expected = [_brute_force(catenary, p, -5, 5) for p in points]
    np.testing.assert_allclose(got, expected, rtol=1e-9)


def test_catenary_distance_far_above_a_narrow_catenary(float64: Float64) -> None:
    # the bracket q^x ± v reached s ≈ 500 = 2000 h, where cosh(s/h) overflows (found by
    # fuzzing: a convergence study at h = 0.25 reported a distance order of 3.1 instead of 2)
    h = 0.25
    points = np.array([[1.0, 500.0], [-2.0, 60.0], [0.5, 1e6]])

    def catenary(ctx, s):
        return s, h * ctx.cosh(s / h)

    with np.errstate(over="raise", invalid="raise"):
        got = distance_to_catenary(float64, h, points)
    expected = [_brute_force(catenary, p, -5, 5) for p in points]
    np.testing.assert_allclose(got, expected, rtol=1e-9)


def test_points_hundreds_of_h_along_the_axis(float64: Float64, mp40: MultiPrecision) -> None:
    # there h cosh(x/h) and cosh(s/h) are beyond float64: the catenary's bracket falls back on
    # the distance to its vertex, the tractrix's root function is G/cosh(s/h)
    h = 0.01
    points = np.array([[10.0, 0.5], [-10.0, 2.0]])

    def catenary(ctx, s):
        return s, h * ctx.cosh(s / h)

    with np.errstate(over="raise", invalid="raise", divide="raise"):
        got = distance_to_catenary(float64, h, points)
    expected = [_brute_force(catenary, p, -1, 1) for p in points]
    np.testing.assert_allclose(got, expected, rtol=1e-9)
    mp_points = stack_points(mp40.array(points[:, 0]), mp40.array(points[:, 1]))
    exact = _floats(mp40, distance_to_catenary(mp40, mp40.scalar(h), mp_points))
    np.testing.assert_allclose(exact, expected, rtol=1e-12)
    # far out the tractrix is within h·2e^{−|x|/h} of the axis: the distance is the height
    far = np.array([[10.0, 0.001], [-10.0, 0.5], [800 * h, 0.1]])
    with np.errstate(over="raise", invalid="raise", divide="raise"):
        got = distance_to_tractrix(float64, h, far)
    np.testing.assert_allclose(got, far[:, 1], rtol=1e-12)


def test_bracketed_root_falls_back_to_bisection(mp40: MultiPrecision) -> None:
    """f(s) = s³ − 2 (Newton from 0 has slope 0) and g(s) = atan(s) − 1 (Newton overshoots)."""
    ar = mp40

    def f(s, where):
        return s**3 - 2, 3 * s * s

    def g(s, where):
        return ar.atan2(s, ar.scalar(1)) - 1, 1 / (1 + s * s)

    lo, hi = ar.array([-1.0]), ar.array([1000.0])
    root = bracketed_root(ar, f, ar.array([0.0]), ar.array([1.0e6]), increasing=True)
    assert abs(float(root[0] ** 3) - 2) < 1e-40
    root = bracketed_root(ar, g, lo, hi, increasing=True)
    assert abs(float(root[0]) - float(mpmath.tan(1))) < 1e-15
