"""The mixed-area definition (curvature) and eq. (17) (revolution_formulas), with real values."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from app.geometry.curvature import face_curvatures, planarity
from app.geometry.errors import DomainError
from app.geometry.precision import Float64, MultiPrecision
from app.geometry.surfaces.mesh import ring_faces
from app.geometry.surfaces.revolution_formulas import equation_17, equation_17_residuals
from tests.reference import curvature as reference

SQUARE = np.array([[[0.0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]])


def test_a_face_against_itself_has_k_1_and_h_minus_1(float64: Float64) -> None:
    # the unit sphere with n = f: A(n) = A(f), A(f, n) = A(f)
    result = face_curvatures(float64, SQUARE, SQUARE)
    assert result.K[0] == 1.0 and result.H[0] == -1.0
    assert result.area[0] == 1.0


def test_scaling_the_surface_by_r_gives_k_1_over_r2_and_h_minus_1_over_r(float64: Float64) -> None:
    result = face_curvatures(float64, 3 * SQUARE, SQUARE)
    assert result.K[0] == pytest.approx(1 / 9, rel=1e-15)
    assert result.H[0] == pytest.approx(-1 / 3, rel=1e-15)
    # a translated face has the same areas
    moved = face_curvatures(float64, 3 * SQUARE + np.array([5.0, -2, 7]), SQUARE)
    assert moved.K[0] == pytest.approx(1 / 9, rel=1e-15)


def test_a_cylinder_band_has_k_0_and_h_minus_half_over_r(float64: Float64) -> None:
    # face of the cylinder of radius 2 between angles 0, θ: the Gauss image face is a segment
    theta = 0.3
    f = ring_faces(
        float64, np.array([[0.0, 2.0]]), np.array([[1.0, 2.0]]), np.cos(theta), np.sin(theta)
    )
    n = ring_faces(
        float64, np.array([[0.0, 1.0]]), np.array([[0.0, 1.0]]), np.cos(theta), np.sin(theta)
    )
    result = face_curvatures(float64, f, n)
    assert abs(result.K[0]) < 1e-16
    assert result.H[0] == pytest.approx(-0.25, rel=1e-14)


def test_opposite_gauss_image_flips_h_and_keeps_k(float64: Float64) -> None:
    f = 2 * SQUARE
    result = face_curvatures(float64, f, -SQUARE)
    assert result.K[0] == pytest.approx(0.25) and result.H[0] == pytest.approx(0.5)


def test_degenerate_face_is_a_domain_error(float64: Float64) -> None:
    flat = np.zeros((1, 4, 3))
    with pytest.raises(DomainError, match="positive area"):
        face_curvatures(float64, flat, SQUARE)


def test_planarity_is_zero_for_a_planar_quad_and_positive_for_a_twisted_one(
    float64: Float64,
) -> None:
    twisted = SQUARE.copy()
    twisted[0, 2, 2] = 0.1
    values = planarity(float64, np.concatenate([SQUARE, twisted]))
    assert values[0] == 0.0
    # diagonals (1, 1, 0.1) and (−1, 1, 0): normal (−0.1, −0.1, 2), distance 0.1/√4.02
    expected = 0.1 / np.sqrt(4.02) / ((np.sqrt(2.01) + np.sqrt(2)) / 2)
    assert values[1] == pytest.approx(expected, rel=1e-14)


def _parallel_pair(rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
    """A random meridian and a parallel one (edges scaled by random factors)."""
    p = np.cumsum(rng.uniform(0.1, 1.0, (7, 2)), axis=0) + np.array([0.0, 0.5])
    factors = rng.uniform(-2, 2, 6)
    steps = 0.3 * np.cumsum(factors[:, None] * np.diff(p, axis=0), axis=0)
    n = np.concatenate([np.zeros((1, 2)), steps]) + np.array([0.3, 0.8])
    return p, n


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_equation_17_equals_the_mixed_area_definition_on_random_parallel_meridians(
    float64: Float64, seed: int
) -> None:
    p, n = _parallel_pair(np.random.default_rng(seed))
    f = ring_faces(float64, p[:-1], p[1:], np.cos(0.4), np.sin(0.4))
    g = ring_faces(float64, n[:-1], n[1:], np.cos(0.4), np.sin(0.4))
    defined = face_curvatures(float64, f, g)
    formula = equation_17(float64, p[:, 1], n[:, 1])
    assert formula.defined.all()
    np.testing.assert_allclose(defined.K, formula.K, rtol=1e-12)
    np.testing.assert_allclose(defined.H, formula.H, rtol=1e-12)
    k_res, h_res, _ = equation_17_residuals(float64, p[:, 1], n[:, 1], defined)
    assert max(k_res.max(), h_res.max()) < 1e-14
    # and they fail for values that are off
    off = replace(defined, gauss_area=defined.gauss_area * 1.001)
    k_res, _, _ = equation_17_residuals(float64, p[:, 1], n[:, 1], off)
    assert k_res.max() > 1e-8  # far above the float64 tolerance (~1e-13)


def test_the_mixed_area_agrees_with_newell_and_polarization_at_40_digits(
    mp40: MultiPrecision,
) -> None:
    ctx = reference.context()
    p = [(ctx.mpf("0.1"), ctx.mpf("1.3")), (ctx.mpf("0.7"), ctx.mpf("2.1"))]
    n = [(ctx.mpf("0.5"), ctx.mpf("0.4")), (ctx.mpf("0.2"), ctx.mpf("0.0"))]  # edge (−0.3, −0.4)
    # n's edge must be parallel to p's (0.6, 0.8): it is −½ of it
    angle = ctx.pi / 5
    K_ref, H_ref = reference.curvatures(
        ctx, reference.face(ctx, *p, angle), reference.face(ctx, *n, angle)
    )
    ar = mp40
    pp = ar.array(["0.1", "1.3", "0.7", "2.1"]).reshape(2, 2)
    nn = ar.array(["0.5", "0.4", "0.2", "0.0"]).reshape(2, 2)
    theta = ar.pi / 5
    result = face_curvatures(
        ar,
        ring_faces(ar, pp[:-1], pp[1:], ar.cos(theta), ar.sin(theta)),
        ring_faces(ar, nn[:-1], nn[1:], ar.cos(theta), ar.sin(theta)),
    )
    assert abs(result.K[0] - K_ref) < 1e-38 * abs(K_ref)
    assert abs(result.H[0] - H_ref) < 1e-38 * abs(H_ref)
    # and (17): K = (0 − 0.16)/(4.41 − 1.69), H = (1.3·0.4 − 0)/(4.41 − 1.69)
    assert abs(result.K[0] + ar.scalar("0.16") / ar.scalar("2.72")) < 1e-38
    assert abs(result.H[0] - ar.scalar("0.52") / ar.scalar("2.72")) < 1e-38


def test_zero_over_zero_faces_are_reported_not_divided(float64: Float64) -> None:
    # a meridian edge parallel to the axis: a cylinder band; (17) is 0/0 there
    p = np.array([[0.0, 1.0], [1.0, 1.0], [2.0, 1.5]])
    n = np.array([[0.0, 0.8], [0.5, 0.8], [0.6, 0.85]])  # parallel edges: (0.5, 0) and (0.1, 0.05)
    formula = equation_17(float64, p[:, 1], n[:, 1])
    assert formula.defined.tolist() == [False, True]
    assert formula.K[0] == 0.0 and np.isfinite(formula.K).all()
    f = ring_faces(float64, p[:-1], p[1:], np.cos(0.2), np.sin(0.2))
    g = ring_faces(float64, n[:-1], n[1:], np.cos(0.2), np.sin(0.2))
    defined = face_curvatures(float64, f, g)
    # on the band: λ = 0.5, K = λ·(0.8 + 0.8)/(1 + 1), H = −(λ + 0.8)/2
    assert defined.K[0] == pytest.approx(0.4, rel=1e-14)
    assert defined.H[0] == pytest.approx(-0.65, rel=1e-14)
