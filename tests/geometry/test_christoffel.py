"""(D2a) constructions: stereographic projection, sequences, hand-computed vertices, agreement
with the independent reference (tests/reference/d2a.py) in both precisions, and domain errors."""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest

from app.geometry import christoffel, stereographic
from app.geometry.discretizations import d2a_hex, d2a_quad
from app.geometry.errors import DomainError
from app.geometry.precision import Arithmetic, Float64, MultiPrecision
from tests.reference import d2a as reference


def test_projection_of_hand_values(float64: Float64) -> None:
    images = stereographic.project(float64, np.array([1.0, 0.5, 2.0, 3.0]))
    np.testing.assert_allclose(images.x, [0.0, -0.6, 0.6, 0.8], atol=1e-16)
    np.testing.assert_allclose(images.y, [1.0, 0.8, 0.8, 0.6], atol=1e-16)
    np.testing.assert_array_equal(images.hemisphere, [1, -1, 1, 1])
    np.testing.assert_allclose(images.x**2 + images.y**2, 1.0, rtol=1e-15)


def test_chords_keep_their_digits_near_the_poles(float64: Float64) -> None:
    f = np.array([1e6, 2e6])  # images agree with (1, 0) in 12 digits
    edge = stereographic.chords(float64, stereographic.project(float64, f))[0]
    mpmath.mp.dps = 50
    exact = [
        2 / (mpmath.mpf(10) ** 12 + 1) - 2 / (4 * mpmath.mpf(10) ** 12 + 1),
        4 * mpmath.mpf(10) ** 6 / (4 * mpmath.mpf(10) ** 12 + 1)
        - 2 * mpmath.mpf(10) ** 6 / (mpmath.mpf(10) ** 12 + 1),
    ]
    assert edge[0] == pytest.approx(float(exact[0]), rel=1e-15)
    assert edge[1] == pytest.approx(float(exact[1]), rel=1e-15)


def test_quad_sequence_is_the_similarity_of_eq_3(mp40: MultiPrecision) -> None:
    f = christoffel.quad_sequence(mp40, mp40.scalar(2), mp40.scalar(3), mp40.indices(-1, 2))
    expected = [mpmath.mpf(4) / 3, 2, 3, 4.5]
    assert all(abs(a - b) < mpmath.mpf(10) ** -45 for a, b in zip(f, expected, strict=True))


def test_hex_sequence_alternates_similarity_and_convex_combination(mp40: MultiPrecision) -> None:
    a, b, lam = (mp40.scalar(v) for v in (1, 4, 0.25))
    f = christoffel.hex_sequence(mp40, a, b, lam, -2, 3)
    # f_{-2} = 1/4, f_{-1} = λ·1 + (1−λ)/4, f_0 = 1, f_1 = λ·4 + (1−λ), f_2 = 4, f_3 = λ·16 + 3
    expected = [0.25, 0.4375, 1, 1.75, 4, 7]
    assert all(abs(x - y) < mpmath.mpf(10) ** -45 for x, y in zip(f, expected, strict=True))


def test_hand_computed_vertices(float64: Float64) -> None:
    # quad f0 = 1, f1 = 2, r = 0: Δp_0 = (f0 + f1, 1 − f0f1)/(2(f1 − f0)) = (1.5, −0.5),
    # Δp_{−1} (f_{−1} = 1/2, f_0 = 1) = (1.5, 0.5)/(2·0.5)·0.5·2 = (1.5, 0.5)
    quad = christoffel.quad(float64, 1.0, 2.0, 0.0, -1, 1)
    np.testing.assert_allclose(quad.p, [[-1.5, -0.5], [0.0, 0.0], [1.5, -0.5]], atol=1e-15)
    # hexagonal a = 1, b = 4, λ = 1/4: f_1 = 1.75, p_1 = 3(2.75, −0.75)/(2·0.75) = (5.5, −1.5)
    hexagonal = christoffel.hexagonal(float64, 1.0, 4.0, 0.25, 0.0, 0, 1)
    np.testing.assert_allclose(hexagonal.p, [[0.0, 0.0], [5.5, -1.5]], atol=1e-15)


def test_ranges_away_from_zero_and_single_vertices(float64: Float64) -> None:
    whole = christoffel.quad(float64, 0.5, 0.8, 1.0, -6, 6)
    right = christoffel.quad(float64, 0.5, 0.8, 1.0, 3, 6)
    left = christoffel.quad(float64, 0.5, 0.8, 1.0, -6, -4)
    np.testing.assert_array_equal(right.p, whole.p[9:])
    np.testing.assert_array_equal(left.p, whole.p[:3])
    assert right.gauss_edges.shape == (3, 2) and left.gauss_edges.shape == (2, 2)
    single = christoffel.hexagonal(float64, 1.0, 2.0, 0.5, 3.0, 0, 0)
    assert single.p.tolist() == [[0.0, 3.0]] and single.gauss_edges.shape == (0, 2)


QUAD_CASES = [
    ("1", "1.5", None, -10, 10),
    ("0.2", "0.7", "1.25", -8, 12),
    ("3", "4", None, 5, 25),
    ("0.01", "0.05", "-2", -15, -3),
    ("1", "1.01", None, -30, 30),
]
HEX_CASES = [
    ("1", "2.5", "0.5", None, -10, 10),
    ("1.3", "2.1", "0.3", "0.7", -9, 11),
    ("0.4", "0.9", "0.8", None, 3, 20),
    ("2", "7", "0.05", "-4", -12, -1),
    ("1", "1.05", "0.9", None, -30, 30),
]


def _relative_error(ar: Arithmetic, points: np.ndarray, expected: dict, first: int) -> float:
    worst = 0.0
    for k, row in enumerate(points):
        ex, ey = expected[first + k]
        norm = mpmath.sqrt(ex * ex + ey * ey)
        dx, dy = mpmath.mpf(str(row[0])) - ex, mpmath.mpf(str(row[1])) - ey
        error = mpmath.sqrt(dx * dx + dy * dy) / norm if norm else mpmath.sqrt(dx * dx + dy * dy)
        worst = max(worst, float(error))
    return worst


@pytest.mark.parametrize(
    ("ar", "bound"), [(Float64(), 1e-12), (MultiPrecision(40), 1e-35)], ids=["float64", "mp40"]
)
@pytest.mark.parametrize("case", QUAD_CASES)
def test_quad_agrees_with_the_reference(ar: Arithmetic, bound: float, case: tuple) -> None:
    f0, f1, r, i_min, i_max = case
    p_ref, phi_ref, f_ref = reference.quad(f0, f1, r, i_min, i_max)
    curve = d2a_quad.compute(
        ar, float(f0), float(f1), None if r is None else float(r), i_min, i_max
    )
    mpmath.mp.dps = 80
    p = curve.polygon.vertices
    assert _relative_error(ar, p, p_ref, i_min) < bound
    assert _relative_error(ar, curve.companions["gauss_image"].vertices, phi_ref, i_min) < bound
    conformal = curve.companions["conformal"].vertices
    assert _relative_error(ar, conformal, {i: (v, 0) for i, v in f_ref.items()}, i_min) < bound


@pytest.mark.parametrize(
    ("ar", "bound"), [(Float64(), 1e-12), (MultiPrecision(40), 1e-35)], ids=["float64", "mp40"]
)
@pytest.mark.parametrize("case", HEX_CASES)
def test_hex_agrees_with_the_reference(ar: Arithmetic, bound: float, case: tuple) -> None:
    a, b, lam, r, i_min, i_max = case
    p_ref, phi_ref, f_ref = reference.hexagonal(a, b, lam, r, i_min, i_max)
    curve = d2a_hex.compute(
        ar, float(a), float(b), float(lam), None if r is None else float(r), i_min, i_max
    )
    mpmath.mp.dps = 80
    assert _relative_error(ar, curve.polygon.vertices, p_ref, i_min) < bound
    assert _relative_error(ar, curve.companions["gauss_image"].vertices, phi_ref, i_min) < bound
    conformal = curve.companions["conformal"].vertices
    assert _relative_error(ar, conformal, {i: (v, 0) for i, v in f_ref.items()}, i_min) < bound


@pytest.mark.parametrize(
    ("call", "message"),
    [
        (lambda: christoffel.validate_quad(0.0, 1.0), "f0 must satisfy 0 < f0 < f1, got 0.0"),
        (lambda: christoffel.validate_quad(-1.0, 1.0), "f0 must satisfy 0 < f0 < f1"),
        (lambda: christoffel.validate_quad(math.nan, 1.0), "f0 must satisfy 0 < f0 < f1"),
        (lambda: christoffel.validate_quad(1.0, 1.0), "f1 must satisfy 0 < f0 < f1, got 1.0"),
        (lambda: christoffel.validate_quad(2.0, 1.0), "f1 must satisfy 0 < f0 < f1"),
        (lambda: christoffel.validate_quad(1.0, 2.0, math.inf), "r must satisfy r is a finite"),
        (lambda: christoffel.validate_hex(0.0, 1.0, 0.5), "a must satisfy 0 < a < b"),
        (lambda: christoffel.validate_hex(1.0, 1.0, 0.5), "b must satisfy 0 < a < b, got 1.0"),
        (lambda: christoffel.validate_hex(1.0, 2.0, 0.0), "lambda must satisfy 0 < lambda < 1"),
        (lambda: christoffel.validate_hex(1.0, 2.0, 1.0), "lambda must satisfy 0 < lambda < 1"),
        (lambda: christoffel.validate_hex(1.0, 2.0, 0.5, math.nan), "r must satisfy"),
    ],
)
def test_domain_errors_name_the_parameter(call, message: str) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(DomainError, match=message.replace("(", r"\(").replace(")", r"\)")):
        call()
