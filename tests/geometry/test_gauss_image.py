"""Gauss image constructions on polygons whose answer is known by hand."""

from __future__ import annotations

import numpy as np
import pytest

from app.geometry import gauss_image
from app.geometry.errors import DomainError
from app.geometry.precision import Float64, MultiPrecision


def _circle(radius: float, count: int, start: float = 0.0) -> np.ndarray:
    angles = start + np.arange(count) * 2 * np.pi / 12
    return radius * np.stack([np.cos(angles), np.sin(angles)], axis=1)


def test_inscribed_polygon_of_a_scaled_circle_polygon_is_the_unit_one(float64: Float64) -> None:
    # edges of a regular polygon of radius 3 are parallel to those of radius 1 through the same
    # first vertex, from any start index and in both directions
    meridian = _circle(3.0, 9, 0.2)
    for start in (0, 4, 8):
        got = gauss_image.inscribed_parallel(float64, meridian, start, meridian[start] / 3)
        np.testing.assert_allclose(got, meridian / 3, atol=1e-15)


def test_inscribed_polygon_zigzags_from_a_different_start(float64: Float64) -> None:
    # the one-parameter family: a straight meridian along x gives n_{k+1} = reflection of n_k
    meridian = np.array([[0.0, 1.0], [1.0, 1.0], [2.0, 1.0]])
    start = np.array([0.6, 0.8])
    got = gauss_image.inscribed_parallel(float64, meridian, 0, start)
    np.testing.assert_allclose(got, [[0.6, 0.8], [-0.6, 0.8], [0.6, 0.8]], atol=1e-15)


def test_contact_points_are_left_unit_normals(float64: Float64) -> None:
    meridian = np.array([[0.0, 1.0], [3.0, 5.0], [4.0, 5.0]])
    got = gauss_image.contact_points(float64, meridian)
    np.testing.assert_allclose(got, [[-0.8, 0.6], [0.0, 1.0]], atol=1e-16)
    # a meridian running towards −x keeps the normals on the side away from the axis
    back = gauss_image.contact_points(float64, meridian[::-1])
    np.testing.assert_allclose(back, [[0.0, 1.0], [-0.8, 0.6]], atol=1e-16)


def test_circumscribed_vertices_are_tangent_intersections(float64: Float64) -> None:
    # edges with normals (−0.8, 0.6) and (0, 1): tangents −0.8x + 0.6y = 1 and y = 1 meet at
    # (−0.5, 1)
    meridian = np.array([[0.0, 1.0], [3.0, 5.0], [4.0, 5.0]])
    got = gauss_image.circumscribed(float64, meridian)
    np.testing.assert_allclose(got, [[-0.5, 1.0]], atol=1e-15)
    # parallel consecutive edges: the pole is the contact point itself
    straight = np.array([[0.0, 2.0], [1.0, 2.0], [2.0, 2.0]])
    np.testing.assert_allclose(
        gauss_image.circumscribed(float64, straight), [[0.0, 1.0]], atol=1e-16
    )


def test_circumscribed_polygon_of_a_regular_polygon(mp40: MultiPrecision) -> None:
    ar = mp40
    count = 6
    angles = [ar.pi * k / 6 for k in range(count)]
    meridian = np.array([[ar.cos(a), ar.sin(a)] for a in angles], dtype=object)
    got = gauss_image.circumscribed(ar, meridian)
    # vertex k is at distance 1/cos(π/12) on the bisector of edges k−1 and k
    for k in range(1, count - 1):
        expected_angle = ar.pi * k / 6
        radius = 1 / ar.cos(ar.pi / 12)
        assert abs(got[k - 1, 0] - radius * ar.cos(expected_angle)) < 1e-45
        assert abs(got[k - 1, 1] - radius * ar.sin(expected_angle)) < 1e-45


def test_zero_length_edges_are_domain_errors(float64: Float64) -> None:
    meridian = np.array([[0.0, 1.0], [0.0, 1.0], [1.0, 1.0]])
    with pytest.raises(DomainError, match="consecutive vertices are distinct"):
        gauss_image.contact_points(float64, meridian)
    with pytest.raises(DomainError, match="consecutive vertices are distinct"):
        gauss_image.inscribed_parallel(float64, meridian, 0, np.array([1.0, 0.0]))
