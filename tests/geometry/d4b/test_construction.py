"""(D4b) construction: hand-computed cases, invariants, and an independent mp implementation."""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest

from app.geometry.d4b.construction import construct
from app.geometry.errors import DomainError
from app.geometry.precision import Float64, MultiPrecision
from tests.reference import d4b as reference


def test_first_centres_are_d_h_and_mirror(float64: Float64) -> None:
    h, d = 1.0, 0.3
    built = construct(float64, h, d, None, -1, 2)
    p = dict(zip(built.indices.tolist(), built.centres, strict=True))
    assert p[1] == pytest.approx([d, h], rel=1e-15)
    assert p[0] == pytest.approx([-d, h], rel=1e-15)
    # proof of Theorem 5: p_2 = (3d, (h³ + 3d²h)/(h² − d²))
    assert p[2] == pytest.approx([3 * d, (h**3 + 3 * d**2 * h) / (h**2 - d**2)], rel=1e-14)
    assert p[-1] == pytest.approx([-3 * d, p[2][1]], rel=1e-14)


def test_sticks_have_length_h_and_start_on_the_axis(float64: Float64) -> None:
    built = construct(float64, 2.0, 0.7, 1.1, -30, 30)
    lengths = np.hypot(*(built.tractrix - built.axis_points).T)
    np.testing.assert_allclose(lengths, 2.0, rtol=1e-13)
    np.testing.assert_allclose(built.axis_points[:, 0], 1.4 * np.arange(-30, 31), rtol=1e-15)
    assert np.all(built.axis_points[:, 1] == 0)


def test_tilted_start_puts_d0_at_the_given_angle(float64: Float64) -> None:
    built = construct(float64, 1.5, 0.2, 0.8, 0, 3)
    assert built.tractrix[0] == pytest.approx([1.5 * math.cos(0.8), 1.5 * math.sin(0.8)])


def test_rotation_centre_is_equidistant_from_consecutive_sticks(float64: Float64) -> None:
    built = construct(float64, 1.0, 0.4, 2.0, -20, 20)
    p, x, tip = built.centres[1:], built.axis_points, built.tractrix
    np.testing.assert_allclose(np.hypot(*(p - x[:-1]).T), np.hypot(*(p - x[1:]).T), rtol=1e-13)
    np.testing.assert_allclose(np.hypot(*(p - tip[:-1]).T), np.hypot(*(p - tip[1:]).T), rtol=1e-13)


@pytest.mark.parametrize(
    ("h", "d", "beta0", "i_min", "i_max"),
    [
        ("1", "0.1", None, -12, 12),
        ("2.5", "0.3", "0.7", -8, 15),
        ("1", "0.9", "2.6", -5, 6),
        ("3", "0.01", "1.2", 3, 40),
        ("1", "0.5", None, -40, -20),
    ],
)
def test_float64_agrees_with_independent_mp_reference(
    float64: Float64, h: str, d: str, beta0: str | None, i_min: int, i_max: int
) -> None:
    centres, tips, _ = reference.construct(h, d, beta0, i_min, i_max)
    built = construct(
        float64, float(h), float(d), None if beta0 is None else float(beta0), i_min, i_max
    )
    expected_p = np.array([[float(v) for v in centres[i]] for i in range(i_min, i_max + 1)])
    expected_d = np.array([[float(v) for v in tips[i]] for i in range(i_min, i_max + 1)])
    scale = np.hypot(*expected_p.T)[:, None]
    assert np.max(np.abs(built.centres - expected_p) / scale) < 1e-12
    scale = np.hypot(*expected_d.T)[:, None]
    assert np.max(np.abs(built.tractrix - expected_d) / scale) < 1e-12


@pytest.mark.parametrize(("beta0", "i_min", "i_max"), [(None, -10, 10), ("0.7", -6, 9)])
def test_mp_agrees_with_independent_reference_to_1e_35(
    mp40: MultiPrecision, beta0: str | None, i_min: int, i_max: int
) -> None:
    centres, tips, _ = reference.construct("1.25", "0.35", beta0, i_min, i_max)
    built = construct(mp40, 1.25, 0.35, None if beta0 is None else float(beta0), i_min, i_max)
    worst = mpmath.mpf(0)
    for k, i in enumerate(range(i_min, i_max + 1)):
        for got, want in ((built.centres[k], centres[i]), (built.tractrix[k], tips[i])):
            norm = mpmath.sqrt(want[0] ** 2 + want[1] ** 2)
            error = mpmath.sqrt((got[0] - want[0]) ** 2 + (got[1] - want[1]) ** 2) / norm
            worst = max(worst, error)
    assert worst < mpmath.mpf("1e-35")


@pytest.mark.parametrize(
    ("h", "d", "beta0", "parameter"),
    [
        (1.0, 1.0, None, "d"),
        (1.0, 1.5, None, "d"),
        (1.0, 0.0, None, "d"),
        (1.0, -0.1, None, "d"),
        (0.0, 0.1, None, "h"),
        (-1.0, 0.1, None, "h"),
        (math.inf, 0.1, None, "h"),
        (1.0, math.nan, None, "d"),
        (1.0, 0.1, 0.0, "beta0"),
        (1.0, 0.1, math.pi, "beta0"),
        (1.0, 0.1, -0.5, "beta0"),
    ],
)
def test_domain_errors_name_the_parameter(
    float64: Float64, h: float, d: float, beta0: float | None, parameter: str
) -> None:
    with pytest.raises(DomainError, match=f"^{parameter} must satisfy") as info:
        construct(float64, h, d, beta0, 0, 3)
    assert info.value.parameter == parameter
