"""Block evaluation of elementwise kernels, and the overflow fallbacks of the fast forms."""

from __future__ import annotations

import mpmath
import numpy as np
import pytest

from app.geometry import precision
from app.geometry.d1.closed_forms import sinh_product
from app.geometry.d4b.closed_forms import amplitude_cosh, amplitude_sech, tanh_and_sech
from app.geometry.precision import BLOCK_SIZE, Float64, MultiPrecision

float64 = Float64()


def _kernel(a: np.ndarray, b: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    return a * b + 1, np.exp(-abs(a)), a - b


@pytest.mark.parametrize("n", [0, 1, BLOCK_SIZE, BLOCK_SIZE + 1, 3 * BLOCK_SIZE + 5])
def test_blocks_give_the_kernel_on_the_whole_arrays(n: int) -> None:
    rng = np.random.default_rng(n)
    a, b = rng.normal(size=n), rng.normal(size=n)
    whole = _kernel(a, b)
    points = float64.points(lambda a, b: _kernel(a, b)[:2], a, b)
    table = float64.columns(_kernel, 3, a, b)
    values = float64.values(lambda a, b: _kernel(a, b)[2], a, b)
    assert points.shape == (n, 2) and table.shape == (n, 3) and values.shape == (n,)
    np.testing.assert_array_equal(points, np.stack(whole[:2], axis=1))
    np.testing.assert_array_equal(table, np.stack(whole, axis=1))
    np.testing.assert_array_equal(values, whole[2])


def test_blocks_see_one_block_at_a_time(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(precision, "BLOCK_SIZE", 4)
    seen: list[int] = []

    def kernel(a: np.ndarray) -> np.ndarray:
        seen.append(len(a))
        return 2 * a

    np.testing.assert_array_equal(float64.values(kernel, np.arange(10.0)), 2 * np.arange(10.0))
    assert seen == [4, 4, 2]


@pytest.mark.parametrize("ar", [float64, MultiPrecision(30)], ids=["float64", "mp"])
def test_one_kernel_serves_both_precisions(ar: precision.Arithmetic) -> None:
    a, b = ar.array([1, 2, 3]), ar.array([0.5, 0.25, 0.125])
    points = ar.points(lambda a, b: (a * b + 1, ar.exp(-abs(a))), a, b)
    assert points.shape == (3, 2)
    assert points[1, 0] == ar.scalar(1.5) and points[2, 1] == ar.exp(ar.scalar(-3))


def _mp(function: object, *args: float) -> float:
    with mpmath.workdps(50):
        return float(function(*(mpmath.mpf(a) for a in args)))  # type: ignore[operator]


@pytest.mark.parametrize(("a", "u"), [(1e-300, 750.0), (1e-300, -760.0), (2.5, 3.0), (1e-200, 0.0)])
def test_amplitude_cosh_where_cosh_alone_overflows(a: float, u: float) -> None:
    expected = _mp(lambda a, u: a * mpmath.cosh(u), a, u)
    got = amplitude_cosh(float64, a, np.array([u, u]))
    np.testing.assert_allclose(got, expected, rtol=1e-13)


@pytest.mark.parametrize(("a", "u"), [(1e300, 750.0), (1e300, -745.5), (3.0, 0.5)])
def test_amplitude_sech_where_cosh_alone_overflows(a: float, u: float) -> None:
    expected = _mp(lambda a, u: a / mpmath.cosh(u), a, u)
    got = amplitude_sech(float64, a, np.array([u]))
    np.testing.assert_allclose(got, expected, rtol=1e-13)


def test_tanh_and_sech_small_large_and_overflowing() -> None:
    t = np.array([1e-300, -2e-9, 0.3, -20.0, 700.0])
    tanh, sech = tanh_and_sech(float64, t)
    np.testing.assert_allclose(tanh, [_mp(mpmath.tanh, v) for v in t], rtol=4e-16)
    np.testing.assert_allclose(sech, [_mp(mpmath.sech, v) for v in t], rtol=4e-16)
    tanh, sech = tanh_and_sech(float64, np.array([0.5, -800.0]))  # cosh(800) overflows
    np.testing.assert_allclose(tanh, [_mp(mpmath.tanh, 0.5), -1.0], rtol=4e-16)
    np.testing.assert_allclose(sech, [_mp(mpmath.sech, 0.5), 0.0], rtol=4e-16, atol=1e-320)


def test_sinh_product_where_one_sinh_overflows() -> None:
    a = np.array([720.0, 0.0, -1e-5, 3.0])
    b = np.array([-1e-3, 5.0, 2e-3, -1e-200])
    factor = 1e-300
    expected = [
        _mp(lambda f, x, y: f * mpmath.sinh(x) * mpmath.sinh(y), factor, x, y)
        for x, y in zip(a, b, strict=True)
    ]
    got = sinh_product(float64, factor, a, b)
    assert got[1] == 0.0
    np.testing.assert_allclose(got, expected, rtol=1e-12)
    direct = sinh_product(float64, 2.0, a[1:], b[1:])  # no overflow: the direct form
    np.testing.assert_allclose(direct, 2 * np.sinh(a[1:]) * np.sinh(b[1:]), rtol=1e-15)


def test_stack_points_is_numpy_stack() -> None:
    rng = np.random.default_rng(0)
    x, y = rng.normal(size=7), rng.normal(size=(7, 2))[:, 1]
    for a, b in ((x, y), (np.arange(7), y), (x[:0], y[:0])):
        got, expected = precision.stack_points(a, b), np.stack([a, b], axis=1)
        assert got.dtype == expected.dtype
        np.testing.assert_array_equal(got, expected)
    mp = MultiPrecision(20)
    got = precision.stack_points(mp.array([1, 2]), mp.array([3, 4]))
    assert got.dtype == object and got.tolist() == [[1, 3], [2, 4]]
    with pytest.raises(ValueError, match="same shape"):
        precision.stack_points(x, y[:3])


def test_the_mpmath_context_is_made_when_first_used() -> None:
    mp = MultiPrecision(25)
    assert "ctx" not in mp.__dict__  # a request served on balls never needs it
    assert mp.digits == 25 and mp.eps == 1e-25
    assert abs(mp.sqrt(mp.scalar(2)) ** 2 - 2) < 1e-30
    assert mp.ctx.dps == 35 and "ctx" in mp.__dict__
    with pytest.raises(AttributeError):
        mp.not_a_function  # noqa: B018
