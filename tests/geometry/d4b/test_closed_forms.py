"""Closed forms of Theorems 5 and 6 and the recursion (13), independent of the construction."""

from __future__ import annotations

import mpmath
import numpy as np
import pytest

from app.geometry.d4b import closed_forms as cf
from app.geometry.precision import Float64, MultiPrecision


def test_stable_forms_equal_the_printed_power_forms(mp40: MultiPrecision) -> None:
    h, d = mp40.scalar(1.3), mp40.scalar(0.4)
    i = mp40.indices(-15, 15)
    zero = mp40.scalar(0)
    stable_p = cf.hyperbolic_cosine(mp40, h, d, i, zero)
    printed_p = cf.hyperbolic_cosine_printed(mp40, h, d, i)
    stable_d = cf.tractrix(mp40, h, d, i, zero)
    printed_d = cf.tractrix_printed(mp40, h, d, i)
    for stable, printed in ((stable_p, printed_p), (stable_d, printed_d)):
        worst = max(
            abs(a - b) / (abs(b) + 1) for a, b in zip(stable.ravel(), printed.ravel(), strict=True)
        )
        assert worst < mpmath.mpf("1e-45")


def test_p1_is_d_h_and_p0_mirrors_it(float64: Float64) -> None:
    p = cf.hyperbolic_cosine(float64, 2.0, 0.5, np.array([0.0, 1.0]), 0.0)
    np.testing.assert_allclose(p, [[-0.5, 2.0], [0.5, 2.0]], rtol=1e-15)


def test_stable_form_is_finite_where_the_printed_one_overflows(float64: Float64) -> None:
    # (h + d)^i overflows at i ≈ 154 for h = 100, d = 1, yet p_i^y is about 100·1.02^i
    h, d, i = 100.0, 1.0, np.array([200.0, 300.0])
    with np.errstate(over="ignore", invalid="ignore"):
        printed = cf.hyperbolic_cosine_printed(float64, h, d, i)
    assert not np.all(np.isfinite(printed))
    stable = cf.hyperbolic_cosine(float64, h, d, i, 0.0)
    mp = MultiPrecision(30)
    exact = cf.hyperbolic_cosine_printed(mp, mp.scalar(h), mp.scalar(d), mp.array(i))
    expected = np.array([float(v) for v in exact[:, 1]])
    np.testing.assert_allclose(stable[:, 1], expected, rtol=1e-12)


def test_tractrix_height_underflows_gradually(float64: Float64) -> None:
    # h / cosh(iL) ≈ 1e-300 is representable although cosh(iL) alone would overflow
    h, d = 1.0, 0.5
    L = 2 * np.arctanh(d / h)
    i = np.array([np.floor(np.log(2e300) / L)])
    y = cf.tractrix(float64, h, d, i, 0.0)[:, 1]
    assert 0 < y[0] < 1e-290
    np.testing.assert_allclose(y, 2 * np.exp(-i * L), rtol=1e-12)


def test_recursion_13_reproduces_the_closed_form(mp40: MultiPrecision) -> None:
    h, d = mp40.scalar(1), mp40.scalar(0.3)
    y = cf.hyperbolic_cosine(mp40, h, d, mp40.indices(-6, 8), mp40.scalar(0))[:, 1]
    predicted = cf.recursion_13(d, y[:-2], y[1:-1])
    assert max(abs(a - b) / b for a, b in zip(predicted, y[2:], strict=True)) < mpmath.mpf("1e-45")


def test_two_step_formula_corrected_holds_and_printed_fails(mp40: MultiPrecision) -> None:
    h, d = mp40.scalar(1), mp40.scalar(0.3)
    y = cf.hyperbolic_cosine(mp40, h, d, mp40.indices(-6, 8), mp40.scalar(0))[:, 1]
    corrected = cf.two_step(d, y[:-3], y[1:-2])
    printed = cf.two_step_printed(d, y[:-3], y[1:-2])
    assert max(abs(a - b) / b for a, b in zip(corrected, y[3:], strict=True)) < mpmath.mpf("1e-45")
    assert max(abs(a - b) / b for a, b in zip(printed, y[3:], strict=True)) > mpmath.mpf("1e-3")


def test_tilt_shift_is_zero_for_a_vertical_stick_and_odd_in_the_tilt(float64: Float64) -> None:
    assert cf.tilt_shift(float64, 1.0, 0.2, None) == 0
    a = cf.tilt_shift(float64, 1.0, 0.2, np.pi / 2 + 0.3)
    b = cf.tilt_shift(float64, 1.0, 0.2, np.pi / 2 - 0.3)
    assert a == pytest.approx(-b, rel=1e-14)
    assert a > 0  # leaning back is the state of a later stick
