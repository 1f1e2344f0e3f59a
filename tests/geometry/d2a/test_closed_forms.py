"""The formulas of Section 4.1 as implemented: hand values, stable forms against the literal
printed powers, and the signs of the constants of (11)."""

from __future__ import annotations

import numpy as np
import pytest

from app.geometry.d2a import closed_forms as cf
from app.geometry.precision import Float64, MultiPrecision


def test_theorem_1_constants_by_hand(mp40: MultiPrecision) -> None:
    f0, f1 = mp40.scalar(1), mp40.scalar(1.5)
    tiny = mp40.scalar("1e-45")
    assert abs(cf.theorem_1_constant(f0, f1) - mp40.scalar("0.032")) < tiny  # 4(0.5/2.5)³
    assert abs(cf.theorem_1_constant_printed(f0, f1) + mp40.scalar("0.032")) < tiny
    assert cf.theorem_1_radius(f0, f1) == -6  # −1.5·2/(2·0.25)
    assert cf.quad_x_step(f0, f1) == mp40.scalar("2.5")
    assert cf.quad_x_step_printed(f0, f1) == -mp40.scalar("2.5")


def test_equation_11_and_the_start_height_by_hand(mp40: MultiPrecision) -> None:
    a, b, lam = mp40.scalar(1), mp40.scalar(2), mp40.scalar(0.5)
    c1, c2 = cf.theorem_2_constants(a, b, lam)
    tiny = mp40.scalar("1e-45")
    # c_1 = 4λ(a−b)(3a(λ−1) + b(7λ−3)) / [3(a(λ−2) − bλ)(3a(λ−1) − b(λ+3))] = 1/63.75
    assert abs(c1 - 1 / mp40.scalar("63.75")) < tiny
    assert c2 == 0  # a(4λ − 3) + bλ = 0
    # numerator 3·¼ − 5·2·(−½)·½ + 2·4·¼ − 2·(−2.5) = 0.75 + 2.5 + 2 + 5 = 10.25,
    # corrected denominator 2λ(λ−1)(a−b)² = −½, printed [2λ(λ−1)a − b]² = (−2.5)² = 6.25
    assert cf.theorem_2_radius(a, b, lam) == mp40.scalar("-20.5")
    assert abs(cf.theorem_2_radius_printed(a, b, lam) - mp40.scalar("1.64")) < tiny


@pytest.mark.parametrize(("a", "b", "lam"), [(1, 2.5, 0.5), (1.3, 2.1, 0.3), (0.4, 0.9, 0.8)])
def test_stable_forms_of_8_and_9_equal_the_literal_powers(
    mp40: MultiPrecision, a: float, b: float, lam: float
) -> None:
    A, B, L, r = (mp40.scalar(v) for v in (a, b, lam, 0.25))
    even = mp40.array(range(-12, 13, 2))
    odd = mp40.array(range(-11, 12, 2))
    stable_even = cf.theorem_3_y_even(mp40, A, B, L, r, even)
    printed_even = cf.theorem_3_y_even_printed(A, B, L, r, even)
    # (8) as printed is the stable form reflected in the line y = r (E43)
    assert np.max(abs(stable_even - (2 * r - printed_even))) < mp40.scalar("1e-40")
    stable_odd = cf.theorem_3_y_odd(mp40, A, B, L, r, odd)
    printed_odd = cf.theorem_3_y_odd_printed(mp40, A, B, L, r, odd)
    assert np.max(abs(stable_odd - printed_odd)) < mp40.scalar("1e-38")


def test_stable_forms_do_not_overflow_where_the_printed_powers_do(float64: Float64) -> None:
    i = np.array([400.0, 402.0])
    y = cf.theorem_3_y_even(float64, 1.0, 5.0, 0.5, 0.0, i)
    assert np.all(np.isfinite(y)) and np.all(np.abs(y) > 1e100)
    with np.errstate(all="ignore"):
        assert not np.all(np.isfinite(cf.theorem_3_y_even_printed(1e-3, 5e-3, 0.5, 0.0, i)))


@pytest.mark.parametrize("lam", [0.05, 0.3, 0.45, 0.5, 0.6, 0.75, 0.95])
@pytest.mark.parametrize("s", [1.1, 1.5, 2.0, 2.5, 3.0, 10.0])
def test_signs_of_the_constants_of_11(float64: Float64, lam: float, s: float) -> None:
    c1, c2 = cf.theorem_2_constants(1.0, s, lam)
    assert np.sign(c1) == np.sign(3 * (1 - lam) - s * (7 * lam - 3))
    assert np.sign(c2) == np.sign(s * lam - (3 - 4 * lam))
