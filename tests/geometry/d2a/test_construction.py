"""(D2a) constructions: stereographic projection, sequences, hand-computed vertices, agreement
with the independent reference (tests/reference/d2a.py) in both precisions, and domain errors."""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest

from app.geometry.d2a import (
    construction as christoffel,
    hex as d2a_hex,
    quad as d2a_quad,
    stereographic,
)
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


# --- the planar meshes of Figures 5 and 6 (left) -------------------------------------------------


def complex_vertices(mesh: christoffel.PlanarMesh) -> list[mpmath.mpc]:
    """The vertices as mpmath complex numbers y + iz (exact copies of the mesh's numbers)."""
    return [mpmath.mpc(y, z) for y, z in mesh.vertices.tolist()]


def cross_ratios(mesh: christoffel.PlanarMesh) -> list[mpmath.mpc]:
    """a a'/(b b') of every quad, edges a, b, a', b' in order around it (Section 1)."""
    z = complex_vertices(mesh)
    out = []
    for f in mesh.faces.tolist():
        w = [z[k] for k in f]
        a, b, a2, b2 = (w[(k + 1) % 4] - w[k] for k in range(4))
        out.append(a * a2 / (b * b2))
    return out


def multi_ratios(mesh: christoffel.PlanarMesh) -> list[mpmath.mpc]:
    """(z1 − z2)(z3 − z4)(z5 − z6)/((z2 − z3)(z4 − z5)(z6 − z1)) of every hexagon."""
    z = complex_vertices(mesh)
    out = []
    for f in mesh.faces.tolist():
        w = [z[k] for k in f]
        out.append(
            (w[0] - w[1])
            * (w[2] - w[3])
            * (w[4] - w[5])
            / ((w[1] - w[2]) * (w[3] - w[4]) * (w[5] - w[0]))
        )
    return out


@pytest.mark.parametrize(
    ("ar", "bound"), [(Float64(), 1e-13), (MultiPrecision(40), 1e-35)], ids=["f64", "mp40"]
)
@pytest.mark.parametrize("case", [(1.0, 1.5, -3, 3, 8), (0.2, 1.1, -2, 4, 2), (2.0, 11.0, 0, 2, 2)])
def test_quad_mesh_quads_are_conformal_and_similar(
    ar: Arithmetic, bound: float, case: tuple[float, float, int, int, int]
) -> None:
    f0, f1, i_min, i_max, columns = case
    mpmath.mp.dps = 50
    mesh = christoffel.conformal_quad_mesh(ar, f0, f1, i_min, i_max, columns)
    assert mesh.faces.shape == ((i_max - i_min) * columns, 4)
    assert len(mesh.edges) == (i_max - i_min) * (columns + 1) + (i_max - i_min + 1) * columns
    assert max(abs(q + 1) for q in cross_ratios(mesh)) < bound
    # column 0 is the parameter line f_i of (D2a) on the y-axis
    f = christoffel.quad_sequence(ar, ar.scalar(f0), ar.scalar(f1), ar.indices(i_min, i_max))
    column = mesh.vertices[mesh.rays == 0]
    assert max(abs(column[:, 0] - f) / f) < bound and max(abs(column[:, 1])) < bound
    # every quad is the first one scaled and turned: the ratios of its edges are all equal
    z = complex_vertices(mesh)
    shapes = [(z[q[1]] - z[q[0]]) / (z[q[3]] - z[q[0]]) for q in mesh.faces.tolist()]
    assert max(abs(s - shapes[0]) for s in shapes) < bound * 10


def test_quad_mesh_angle_is_the_conformal_one(float64: Float64) -> None:
    # f1/f0 = 4: sin(v/2) = 3/4 (hand value); f1/f0 → 3 + 2√2: v → π
    assert float64.to_float(christoffel.conformal_quad_angle(float64, 1.0, 4.0)) == pytest.approx(
        2 * math.asin(0.75), rel=1e-15
    )
    near = christoffel.conformal_quad_angle(float64, 1.0, 3 + 2 * math.sqrt(2) - 1e-9)
    assert near == pytest.approx(math.pi, abs=1e-3)


def test_a_perturbed_quad_mesh_is_not_conformal(float64: Float64) -> None:
    mesh = christoffel.conformal_quad_mesh(float64, 1.0, 1.5, -2, 2, 4)
    mesh.vertices[7] += [1e-3, 0]
    ratios = cross_ratios(mesh)
    assert max(abs(q + 1) for q in ratios) > 1e-4
    assert sum(abs(q + 1) > 1e-12 for q in ratios) == 4  # the quads around vertex 7


@pytest.mark.parametrize(
    ("ar", "bound"), [(Float64(), 1e-12), (MultiPrecision(40), 1e-35)], ids=["f64", "mp40"]
)
@pytest.mark.parametrize(
    "case", [(1.0, 2.5, 0.5, -3, 3, 12), (0.5, 4.0, 0.2, -2, 4, 5), (1.0, 1.2, 0.9, 0, 3, 2)]
)
def test_hexagonal_mesh_hexagons_have_multi_ratio_minus_one(
    ar: Arithmetic, bound: float, case: tuple[float, float, float, int, int, int]
) -> None:
    a, b, lam, i_min, i_max, m = case
    mpmath.mp.dps = 50
    mesh = christoffel.conformal_hexagonal_mesh(ar, a, b, lam, i_min, i_max, m)
    assert mesh.faces.shape[1] == 6 and len(mesh.faces) > 0
    assert max(abs(q + 1) for q in multi_ratios(mesh)) < bound
    # ray 0 carries f_i of Section 4.1; odd rays √(a/b) f_{i+1}, even rays f_i
    f = christoffel.hex_sequence(ar, ar.scalar(a), ar.scalar(b), ar.scalar(lam), i_min, i_max + 1)
    ray0 = mesh.vertices[mesh.rays == 0]
    assert max(abs(ray0[:, 0] - f[:-1]) / f[:-1]) < bound and max(abs(ray0[:, 1])) < bound
    radius = np.array([mpmath.sqrt(y * y + z * z) for y, z in mesh.vertices.tolist()])
    expected = np.where(
        mesh.rays % 2 == 0,
        np.tile(f[:-1], 2 * m),
        np.tile(f[1:], 2 * m) * ar.sqrt(ar.scalar(a) / ar.scalar(b)),
    )
    assert max(abs(radius - expected) / expected) < bound
    # three edges at every vertex with neighbours on both sides along its ray
    degree = np.bincount(mesh.edges.ravel(), minlength=len(mesh.vertices))
    inner = (mesh.rows > i_min) & (mesh.rows < i_max)
    assert set(degree[inner].tolist()) == {3} and set(degree.tolist()) <= {2, 3}
    # every hexagon's six corners are distinct vertices joined by mesh edges
    edges = {tuple(sorted(e)) for e in mesh.edges.tolist()}
    for face in mesh.faces.tolist():
        assert len(set(face)) == 6
        assert all(tuple(sorted((face[k], face[(k + 1) % 6]))) in edges for k in range(6))


def test_hexagonal_meridian_alternates_edges_and_diagonals(float64: Float64) -> None:
    mesh = christoffel.conformal_hexagonal_mesh(float64, 1.0, 2.5, 0.5, -3, 3, 6)
    edges = {tuple(sorted(e)) for e in mesh.edges.tolist()}
    number = {(r, k): n for n, (r, k) in enumerate(zip(mesh.rows, mesh.rays, strict=True))}
    along = [(number[(i, 0)], number[(i + 1, 0)]) in edges for i in range(-3, 3)]
    assert along == [True, False, True, False, True, False]  # f_i f_{i+1} an edge iff i is odd


def test_a_perturbed_hexagonal_mesh_is_not_conformal(float64: Float64) -> None:
    mesh = christoffel.conformal_hexagonal_mesh(float64, 1.0, 2.5, 0.5, -2, 2, 4)
    mesh.vertices[3] *= 1.001
    ratios = multi_ratios(mesh)
    assert 0 < sum(abs(q + 1) > 1e-6 for q in ratios) <= 3  # the hexagons around vertex 3


@pytest.mark.parametrize(
    ("call", "message"),
    [
        (lambda ar: christoffel.conformal_quad_mesh(ar, 1.0, 6.0, 0, 2, 3), "f1/f0 < 3 \\+ 2√2"),
        (lambda ar: christoffel.conformal_quad_mesh(ar, 1.0, 1.5, 0, 2, 0), "columns >= 1"),
        (lambda ar: christoffel.conformal_quad_mesh(ar, 1.0, 1.5, 2, 0, 3), "i_min <= i_max"),
        (lambda ar: christoffel.conformal_quad_mesh(ar, 2.0, 1.5, 0, 2, 3), "0 < f0 < f1"),
        (lambda ar: christoffel.conformal_hexagonal_mesh(ar, 1, 2, 0.5, 0, 2, 1), "m >= 2"),
        (lambda ar: christoffel.conformal_hexagonal_mesh(ar, 1, 2, 1.0, 0, 2, 3), "lambda"),
        (lambda ar: christoffel.conformal_hexagonal_mesh(ar, 1, 2, 0.5, 3, 2, 3), "i_min"),
    ],
)
def test_mesh_domain_errors_name_the_parameter(call, message: str, float64: Float64) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(DomainError, match=message):
        call(float64)
