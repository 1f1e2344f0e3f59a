"""Discrete curvatures from mesh parallelity (Bobenko–Pottmann–Wallner [3]): the definition.

A quad mesh f and a *parallel* mesh n (its Gauss image: corresponding edges parallel) have, face
by face, the areas A(f), A(n) and the mixed area A(f, n), defined by

    A(f + t n) = A(f) + 2t A(f, n) + t² A(n).

The curvatures of a face are

    K = A(n) / A(f),        H = −A(f, n) / A(f),

all three areas taken with sign along the unit normal of the face of f. This is the convention
under which the paper's formula (17) for surfaces of revolution holds, and under which the unit
sphere with n = f has K = 1, H = −1 (checked in the tests).

For a quad with vertices v0..v3 the vector area is ½ (v2 − v0) × (v3 − v1) (product of the
diagonals), so it depends on differences of vertices only, and the mixed vector area of two quads
is ¼ (d1(f) × d2(n) + d1(n) × d2(f)). Nothing here knows about surfaces of revolution: the
module ``revolution_formulas`` holds (17), and the checks compare the two.

Arrays: ``faces`` are ``(F, 4, 3)`` vertex arrays (a degenerate quad with two equal vertices is a
triangle and is fine).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from app.geometry.errors import DomainError
from app.geometry.precision import Arithmetic, Array


def cross(a: Array, b: Array) -> Array:
    """Row-wise cross product of two ``(F, 3)`` arrays (works for float64 and mp objects)."""
    return np.stack(
        [
            a[:, 1] * b[:, 2] - a[:, 2] * b[:, 1],
            a[:, 2] * b[:, 0] - a[:, 0] * b[:, 2],
            a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0],
        ],
        axis=1,
    )


def dot(a: Array, b: Array) -> Array:
    """Row-wise dot product of two ``(F, 3)`` arrays; ``(F,)``."""
    return a[:, 0] * b[:, 0] + a[:, 1] * b[:, 1] + a[:, 2] * b[:, 2]


def norm(ar: Arithmetic, a: Array) -> Array:
    """Row-wise Euclidean length of an ``(F, 3)`` array; ``(F,)``."""
    return ar.hypot(ar.hypot(a[:, 0], a[:, 1]), a[:, 2])


def diagonals(faces: Array) -> tuple[Array, Array]:
    """The diagonals v2 − v0 and v3 − v1 of each quad; two ``(F, 3)`` arrays."""
    return faces[:, 2] - faces[:, 0], faces[:, 3] - faces[:, 1]


def vector_area(faces: Array) -> Array:
    """Oriented vector area ½ (v2 − v0) × (v3 − v1) of each quad; ``(F, 4, 3) -> (F, 3)``."""
    d1, d2 = diagonals(faces)
    return cross(d1, d2) / 2


def mixed_vector_area(f: Array, g: Array) -> Array:
    """Mixed vector area ¼ (d1(f) × d2(g) + d1(g) × d2(f)) of corresponding quads; ``(F, 3)``."""
    f1, f2 = diagonals(f)
    g1, g2 = diagonals(g)
    return (cross(f1, g2) + cross(g1, f2)) / 4


def _size(vectors: Array) -> Array:
    """Sum of the absolute coordinates of ``(F, 3)`` vectors."""
    return abs(vectors[:, 0]) + abs(vectors[:, 1]) + abs(vectors[:, 2])


def diagonal_magnitude(faces: Array) -> tuple[Array, Array]:
    """Size of the stored numbers each diagonal is computed from (|v0| + |v2|, |v1| + |v3|)."""
    return (
        _size(faces[:, 0]) + _size(faces[:, 2]),
        _size(faces[:, 1]) + _size(faces[:, 3]),
    )


@dataclass(frozen=True)
class FaceCurvatures:
    """Areas and curvatures of each face of a mesh f with respect to a parallel mesh n; ``(F,)``.

    The ``*_magnitude`` arrays bound the size of the products the areas are computed from, so
    that residuals can be measured against what the data resolves (docs/checks.md).
    """

    area: Array
    """A(f) > 0 (the face normal is chosen along f's own vector area)."""
    gauss_area: Array
    """A(n), signed along f's normal."""
    mixed_area: Array
    """A(f, n), signed along f's normal."""
    K: Array
    H: Array
    parallel: Array
    """|A(f)⃗ × A(n)⃗| relative to the magnitudes: 0 when the faces are parallel."""
    area_magnitude: Array
    gauss_area_magnitude: Array
    mixed_area_magnitude: Array


def face_curvatures(ar: Arithmetic, f: Array, n: Array) -> FaceCurvatures:
    """K = A(n)/A(f) and H = −A(f,n)/A(f) of every face ([3]; the definition behind (17))."""
    area_f = vector_area(f)
    area_n = vector_area(n)
    mixed = mixed_vector_area(f, n)
    size = norm(ar, area_f)
    if len(size) and not bool(np.all(size > 0)):
        bad = int(np.argmin(ar.to_floats(size)))
        raise DomainError(
            "meridian",
            "every face has positive area (no meridian edge of zero length or on the axis)",
            bad,
            "face number given as value",
        )
    unit = area_f / size[:, None]
    a_f = size
    a_n = dot(area_n, unit)
    a_fn = dot(mixed, unit)
    f1, f2 = diagonal_magnitude(f)
    n1, n2 = diagonal_magnitude(n)
    mag_f = f1 * f2 / 2
    mag_n = n1 * n2 / 2
    mag_fn = (f1 * n2 + n1 * f2) / 4
    turned = norm(ar, cross(area_f, area_n))
    return from_areas(ar, a_f, a_n, a_fn, turned, (mag_f, mag_n, mag_fn))


def from_areas(
    ar: Arithmetic,
    area: Array,
    gauss_area: Array,
    mixed: Array,
    turned: Array,
    magnitudes: tuple[Array, Array, Array],
) -> FaceCurvatures:
    """K and H of faces from their areas A(f), A(n), A(f,n) (all (faces,)); ``turned`` is
    |A(f)⃗ × A(n)⃗|, whose ratio to the magnitudes' product is the parallel residual."""
    mag_f, mag_n, mag_fn = magnitudes
    tiny = ar.scalar(np.finfo(np.float64).tiny)
    both = mag_f * mag_n
    parallel = turned / np.where(both > tiny, both, tiny)
    return FaceCurvatures(
        area=area,
        gauss_area=gauss_area,
        mixed_area=mixed,
        K=gauss_area / area,
        H=-mixed / area,
        parallel=parallel,
        area_magnitude=mag_f,
        gauss_area_magnitude=mag_n,
        mixed_area_magnitude=mag_fn,
    )


def planarity(ar: Arithmetic, faces: Array) -> Array:
    """Distance between the two diagonals of each quad over their mean length; 0 when planar.

    A degenerate quad (a triangle, or diagonals parallel) counts as planar. The measure is
    scale-invariant (offset and scale are both cubic in the coordinates), so in float64 each
    face is first scaled by the power of two that brings its largest coordinate into [½, 1):
    nothing overflows for any finite face (faces near 1e103 overflowed the cubic products, and
    an infinite scale made every such face "planar"), and the scaling is exact, so every other
    face gives the same bits as before. mp numbers do not overflow.
    """
    if ar.may_overflow and len(faces):
        largest = np.max(np.max(np.abs(faces), axis=2), axis=1)
        _, exponent = np.frexp(largest)
        faces = np.ldexp(faces, -exponent[:, None, None])
    d1, d2 = diagonals(faces)
    normal = cross(d1, d2)
    length = norm(ar, normal)
    tiny = ar.scalar(np.finfo(np.float64).tiny)
    offset = abs(dot(faces[:, 1] - faces[:, 0], normal))
    mean_diagonal = (norm(ar, d1) + norm(ar, d2)) / 2
    scale = length * mean_diagonal
    return np.where(scale > tiny, offset / np.where(scale > tiny, scale, tiny), 0 * offset)
