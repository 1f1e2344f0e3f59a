"""The discrete hyperbolic cosine (D2a): Christoffel duals of stereographic conformal meshes.

Definition (Section 4.1). A rotationally symmetric conformal mesh of the yz-plane has a discrete
parameter line (f_i) on the y-axis; the stereographic projection (``stereographic.project``)
maps it to the meridian polygon φ_i = Φ(f_i) of a discrete Gaussian image on the unit sphere; the
discrete Christoffel dual of that polygon is the discrete hyperbolic cosine:

    quad mesh, eq. (4):      p_i = p_{i−1} + Δφ_{i−1}/‖Δφ_{i−1}‖²,
    hexagonal mesh, eq. (6): p_{i+1} = p_i + k_i Δφ_i/‖Δφ_i‖², k_i = 3 (i even), 2 (i odd),

with Δφ_i = φ_{i+1} − φ_i and p_0 = (0, r). The parameter lines are
    quad, eq. (3):  f_i = f_{i−1} f_1/f_0, so f_i = f_0 (f_1/f_0)^i,
    hexagonal:      f_i = f_{i−2} b/a for even i (f_0 = a, f_2 = b, so f_{2k} = a (b/a)^k) and
                    f_i = λ f_{i+1} + (1 − λ) f_{i−1} for odd i.

Coordinates: the first coordinate of φ (the symmetry axis) is x, the second (the distance from
the axis) is y; then the x-steps of p are constant (quad) or 2-periodic (hexagonal), as the proofs
state. With this orientation and (4) as printed, the polygon of Theorem 1 lies below the x-axis
(its heights are −K(f_i + 1/f_i), see docs/errata.md, Section 4.1).

The polygon is a cumulative sum of its edge vectors (numpy ``cumsum``, also on mp object
arrays): forwards from p_0 for i > 0, backwards for i < 0. Nothing here uses a formula of the
proofs of Theorems 1–3; ``christoffel_closed_forms`` holds those, and the checks compare.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from app.geometry.d2a.stereographic import CircleImages, chords, project
from app.geometry.errors import DomainError
from app.geometry.precision import Arithmetic, Array, Scalar, stack_points
from app.geometry.tolerances import exact


@dataclass(frozen=True)
class ChristoffelDual:
    """(D2a) on the indices i_min .. i_max; arrays are aligned with ``indices``."""

    indices: np.ndarray[Any, np.dtype[np.int64]]
    f: Array
    """f_i, the parameter line of the conformal mesh on the y-axis, ``(n,)``."""
    gauss: Array
    """φ_i = Φ(f_i) on the unit circle, ``(n, 2)``."""
    gauss_edges: Array
    """Δφ_i = φ_{i+1} − φ_i for i = i_min .. i_max − 1, ``(n − 1, 2)``."""
    p: Array
    """p_i, the discrete hyperbolic cosine, ``(n, 2)``."""


def _finite_positive(name: str, value: float, constraint: str) -> None:
    if not math.isfinite(value) or value <= 0:
        raise DomainError(name, constraint, value)


def validate_quad(f0: float, f1: float, r: float | None = None) -> None:
    """Raise ``DomainError`` unless 0 < f0 < f1 (and r, if given, is finite)."""
    _finite_positive("f0", f0, "0 < f0 < f1")
    # orders compared exactly (as written): in mp 1 < 1 + 1e-300, equal as floats (float64 then
    # refuses the gap, ``FLOAT64_MIN_GAP``)
    if not math.isfinite(f1) or exact(f1) <= exact(f0):
        raise DomainError(
            "f1",
            "0 < f0 < f1",
            f1,
            f"f0 = {f0!r}; f1 = f0 makes every Gauss image edge vanish (no dual), and the "
            "paper orders f0 < f1",
        )
    _validate_r(r)


def validate_hex(a: float, b: float, lam: float, r: float | None = None) -> None:
    """Raise ``DomainError`` unless 0 < a < b and 0 < λ < 1 (and r, if given, is finite)."""
    _finite_positive("a", a, "0 < a < b")
    if not math.isfinite(b) or exact(b) <= exact(a):
        raise DomainError(
            "b", "0 < a < b", b, f"a = {a!r}; b = a makes every Gauss image edge vanish"
        )
    if not math.isfinite(lam) or not 0 < exact(lam) < 1:
        raise DomainError(
            "lambda",
            "0 < lambda < 1",
            lam,
            "at λ = 0 or 1 an odd point coincides with an even neighbour, and the dual edge "
            "Δφ/‖Δφ‖² is infinite",
        )
    _validate_r(r)


def _validate_r(r: float | None) -> None:
    if r is not None and not math.isfinite(r):
        raise DomainError("r", "r is a finite number", r)


def quad_sequence(ar: Arithmetic, f0: Scalar, f1: Scalar, i: Array) -> Array:
    """Eq. (3): f_i = f_{i−1} f_1/f_0, i.e. f_0 (f_1/f_0)^i (the similarity applied i times)."""
    rate = ar.log(f1 / f0)
    return ar.values(lambda i: f0 * ar.exp(i * rate), i)


def hex_sequence(
    ar: Arithmetic, a: Scalar, b: Scalar, lam: Scalar, i_min: int, i_max: int
) -> Array:
    """Section 4.1, hexagonal case: f_{2k} = a (b/a)^k; odd f_i = λ f_{i+1} + (1 − λ) f_{i−1}."""
    i = np.arange(i_min, i_max + 1, dtype=np.int64)
    odd = (i % 2) == 1
    k = ar.array((i - (i % 2)) // 2)  # even index 2k at or below i
    log_s = ar.log(b / a)

    def kernel(odd: Array, k: Array) -> Array:
        below = a * ar.exp(k * log_s)  # f_{i} (i even) or f_{i−1} (i odd)
        above = a * ar.exp((k + 1) * log_s)  # f_{i+1} for odd i
        return np.where(odd, lam * above + (1 - lam) * below, below)

    return ar.values(kernel, odd, k)


def dual_edges(ar: Arithmetic, edges: Array, weights: Array | int) -> Array:
    """The Christoffel dual edges k Δφ/‖Δφ‖² of eqs. (4), (6); ``(m, 2) -> (m, 2)``."""

    def kernel(dx: Array, dy: Array, k: Array | int) -> tuple[Array, Array]:
        scale = k / (dx * dx + dy * dy)
        return dx * scale, dy * scale

    if isinstance(weights, int):
        return ar.points(lambda dx, dy: kernel(dx, dy, weights), edges[:, 0], edges[:, 1])
    return ar.points(kernel, edges[:, 0], edges[:, 1], weights)


def accumulate(ar: Arithmetic, start: Array, edges: Array, lo: int) -> Array:
    """Vertices from p_0 = ``start`` and the edges e_k = p_{k+1} − p_k, k = lo .. hi − 1.

    ``lo <= 0``; returns p_lo .. p_hi, ``(hi − lo + 1, 2)``: forward partial sums for k >= 0,
    backward (subtracting) partial sums for k < 0, written in place into the result.
    """
    zero = -lo  # the row of p_0
    out = np.empty((len(edges) + 1, 2), dtype=edges.dtype)
    out[zero] = start
    for axis in (0, 1):
        origin = start[axis]
        if zero > 0:  # p_k = p_0 − (e_k + … + e_{−1}), summed from e_{−1} backwards
            np.cumsum(edges[zero - 1 :: -1, axis], out=out[zero - 1 :: -1, axis])
            np.subtract(origin, out[:zero, axis], out=out[:zero, axis])
        if zero < len(edges):  # p_k = p_0 + (e_0 + … + e_{k−1})
            after = out[zero + 1 :, axis]
            np.cumsum(edges[zero:, axis], out=after)
            after += origin
    return out


def _assemble(
    ar: Arithmetic,
    f: Array,
    weights: Array | int,
    r: Scalar,
    lo: int,
    i_min: int,
    i_max: int,
) -> ChristoffelDual:
    images: CircleImages = project(ar, f)
    gauss_edges = chords(ar, images)
    start = ar.array([0, r])
    p = accumulate(ar, start, dual_edges(ar, gauss_edges, weights), lo)
    window = slice(i_min - lo, i_max - lo + 1)
    return ChristoffelDual(
        indices=np.arange(i_min, i_max + 1, dtype=np.int64),
        f=f[window],
        gauss=images.points()[window],
        gauss_edges=gauss_edges[i_min - lo : i_max - lo],
        p=p[window],
    )


def quad(
    ar: Arithmetic, f0: float, f1: float, r: Scalar, i_min: int, i_max: int
) -> ChristoffelDual:
    """(D2a), quad mesh: eqs. (3), (4) with p_0 = (0, r), on i_min .. i_max.

    Vectorized: the edges come from the whole sequence at once, the vertices are their
    cumulative sums from p_0 (so the work is max(|i_min|, |i_max|) edges).
    """
    validate_quad(f0, f1)
    lo, hi = min(0, i_min), max(0, i_max)
    f = quad_sequence(ar, ar.scalar(f0), ar.scalar(f1), ar.indices(lo, hi))
    return _assemble(ar, f, 1, r, lo, i_min, i_max)


def hexagonal(
    ar: Arithmetic, a: float, b: float, lam: float, r: Scalar, i_min: int, i_max: int
) -> ChristoffelDual:
    """(D2a), hexagonal mesh: the sequence of Section 4.1 and eq. (6), p_0 = (0, r)."""
    validate_hex(a, b, lam)
    lo, hi = min(0, i_min), max(0, i_max)
    f = hex_sequence(ar, ar.scalar(a), ar.scalar(b), ar.scalar(lam), lo, hi)
    k = np.arange(lo, hi, dtype=np.int64)
    weights = ar.array(np.where(k % 2 == 0, 3, 2))
    return _assemble(ar, f, weights, r, lo, i_min, i_max)


# --- the planar conformal meshes themselves (Figures 5 and 6, left) ------------------------------


@dataclass(frozen=True)
class PlanarMesh:
    """A mesh of the yz-plane (read as ℂ, y real): vertices, edges and faces by vertex number.

    Vertex ``k`` sits on ray (or column) ``rays[k]`` at local index ``rows[k]``; the vertices of
    ray 0 are the parameter line f_i of the meridian (``rows`` = i there).
    """

    vertices: Array
    """``(n, 2)``: (y, z)."""
    rows: np.ndarray[Any, np.dtype[np.int64]]
    rays: np.ndarray[Any, np.dtype[np.int64]]
    edges: np.ndarray[Any, np.dtype[np.int64]]
    """``(m, 2)`` vertex numbers."""
    faces: np.ndarray[Any, np.dtype[np.int64]]
    """``(k, 4)`` (quads) or ``(k, 6)`` (hexagons), vertex numbers in cyclic order."""
    angle: Scalar
    """Angle between neighbouring rays (columns)."""


#: f_1/f_0 below this bound admit a conformal quad mesh (sin(v/2) < 1): (1 + √2)² = 3 + 2√2.
QUAD_MESH_RATIO_BOUND = 3 + 2 * math.sqrt(2)


def conformal_quad_angle(ar: Arithmetic, f0: float, f1: float) -> Scalar:
    """The column angle v of the conformal quad mesh through f_i: sin(v/2) = (f1 − f0)/(2√(f0 f1)).

    Definition (Section 1): a quad with edges a, b, a', b' (in this order around it) is
    conformal when a a'/(b b') = −1. For the quad f_i e^{ijv}, f_{i+1} e^{ijv}, f_{i+1}
    e^{i(j+1)v}, f_i e^{i(j+1)v} with f_{i+1}/f_i = q that ratio is −(q − 1)²/(4q sin²(v/2)),
    so the quads are conformal exactly when sin(v/2) = (q − 1)/(2√q).
    """
    validate_quad(f0, f1)
    if f1 / f0 >= QUAD_MESH_RATIO_BOUND:
        raise DomainError(
            "f1",
            "f1/f0 < 3 + 2√2 for a planar conformal quad mesh (Figure 5)",
            f1,
            "then (f1 − f0)/(2√(f0·f1)) = sin(v/2) < 1; at the bound the columns are π apart",
        )
    a, b = ar.scalar(f0), ar.scalar(f1)
    sine = (b - a) / (2 * ar.sqrt(a * b))
    return 2 * ar.atan2(sine, ar.sqrt((1 - sine) * (1 + sine)))


def conformal_quad_mesh(
    ar: Arithmetic, f0: float, f1: float, i_min: int, i_max: int, columns: int
) -> PlanarMesh:
    """Figure 5 (left): the rotationally symmetric conformal quad mesh through f_i of eq. (3).

    Vertex (i, j) = f_i e^{ijv} for i_min <= i <= i_max, 0 <= j <= ``columns``, v from
    ``conformal_quad_angle``: column 0 is the parameter line f_i on the y-axis, and every quad
    is the similar image of one quad (z ↦ (f_1/f_0) z and the rotation by v). Vectorized.
    """
    if i_max < i_min:
        raise DomainError("i_max", "i_min <= i_max", i_max, f"i_min = {i_min}")
    if columns < 1:
        raise DomainError("columns", "columns >= 1", columns)
    v = conformal_quad_angle(ar, f0, f1)
    if columns * ar.to_float(v) > 2 * math.pi * (1 + 1e-12):
        turn = math.floor(2 * math.pi / ar.to_float(v) + 1e-9)
        raise DomainError(
            "columns",
            f"columns·v <= 2π: at most {turn} quads around for this f1/f0",
            columns,
            f"the columns are v = {ar.to_float(v):.6g} rad apart",
        )
    f = quad_sequence(ar, ar.scalar(f0), ar.scalar(f1), ar.indices(i_min, i_max))
    n_rows, n_cols = i_max - i_min + 1, columns + 1
    rows = np.repeat(np.arange(i_min, i_max + 1, dtype=np.int64), n_cols)
    rays = np.tile(np.arange(n_cols, dtype=np.int64), n_rows)
    angles = ar.array(rays) * v
    radii = np.repeat(f, n_cols)
    vertices = stack_points(radii * ar.cos(angles), radii * ar.sin(angles))
    number = np.arange(n_rows * n_cols, dtype=np.int64).reshape(n_rows, n_cols)
    radial = np.stack([number[:-1, :].ravel(), number[1:, :].ravel()], axis=1)
    around = np.stack([number[:, :-1].ravel(), number[:, 1:].ravel()], axis=1)
    faces = np.stack(
        [
            number[:-1, :-1].ravel(),
            number[1:, :-1].ravel(),
            number[1:, 1:].ravel(),
            number[:-1, 1:].ravel(),
        ],
        axis=1,
    )
    edges = np.concatenate([radial, around]).astype(np.int64)
    return PlanarMesh(vertices, rows, rays, edges, faces, v)


def conformal_hexagonal_mesh(
    ar: Arithmetic, a: float, b: float, lam: float, i_min: int, i_max: int, m: int
) -> PlanarMesh:
    """Figure 6 (left): a rotationally symmetric conformal hexagonal mesh through f_i.

    The 2m rays are θ = π/m apart. Ray 0 carries the parameter line of Section 4.1: even f_i by
    the similarity f_i = f_{i−2} b/a, odd f_i = λ f_{i+1} + (1 − λ) f_{i−1}; every even ray
    is ray 0 turned, every odd ray is ray 0 turned and scaled by √(a/b) with its indices shifted
    by one (vertex (j, k) = √(a/b) f_{j+1} e^{ikθ} for odd k). Edges: along a ray between
    vertices j, j+1 with j + k odd (on ray 0: f_i f_{i+1} for odd i, so the meridian runs
    alternately along an edge and across a hexagon, the diagonal f_i f_{i+1} for even i), and
    between (j, k) and (j, k+1) on neighbouring rays. Every vertex has three neighbours and every
    hexagon (j, k), (j, k+1), (j+1, k+1), (j+1, k), (j+1, k−1), (j, k−1) (j + k even) has
    multi-ratio −1, the conformality of [10], for every θ: the picture's one free choice is m.
    Vectorized.
    """
    validate_hex(a, b, lam)
    if i_max < i_min:
        raise DomainError("i_max", "i_min <= i_max", i_max, f"i_min = {i_min}")
    if m < 2:
        raise DomainError("m", "m >= 2 (2m rays)", m)
    f = hex_sequence(ar, ar.scalar(a), ar.scalar(b), ar.scalar(lam), i_min, i_max + 1)
    shrink = ar.sqrt(ar.scalar(a) / ar.scalar(b))
    n_rows, n_rays = i_max - i_min + 1, 2 * m
    theta = ar.pi / m
    rows = np.tile(np.arange(i_min, i_max + 1, dtype=np.int64), n_rays)
    rays = np.repeat(np.arange(n_rays, dtype=np.int64), n_rows)
    radii = np.where(rays % 2 == 0, np.tile(f[:-1], n_rays), shrink * np.tile(f[1:], n_rays))
    angles = ar.array(rays) * theta
    vertices = stack_points(radii * ar.cos(angles), radii * ar.sin(angles))
    number = np.arange(n_rays * n_rows, dtype=np.int64).reshape(n_rays, n_rows)
    k = np.arange(n_rays, dtype=np.int64)[:, None]
    j = np.arange(i_min, i_max, dtype=np.int64)[None, :]
    along = ((j + k) % 2 == 1).ravel()
    ray_edges = np.stack([number[:, :-1].ravel(), number[:, 1:].ravel()], axis=1)[along]
    following = np.roll(number, -1, axis=0)  # ray k + 1, ray 2m being ray 0 again
    cross = np.stack([number.ravel(), following.ravel()], axis=1)
    centre = ~along  # hexagons across the diagonals (j, k)-(j+1, k), j + k even
    previous = np.roll(number, 1, axis=0)
    faces = np.stack(
        [
            number[:, :-1].ravel()[centre],
            following[:, :-1].ravel()[centre],
            following[:, 1:].ravel()[centre],
            number[:, 1:].ravel()[centre],
            previous[:, 1:].ravel()[centre],
            previous[:, :-1].ravel()[centre],
        ],
        axis=1,
    )
    edges = np.concatenate([ray_edges, cross]).astype(np.int64)
    return PlanarMesh(vertices, rows, rays, edges, faces, theta)
