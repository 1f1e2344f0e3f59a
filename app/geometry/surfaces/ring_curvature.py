"""Checks of Section 5 shared by (D4b) and (D2b): curvatures of one ring of rotational faces.

Every ring of a discrete surface of revolution is congruent to the others, so the face-wise
statements (17), Theorems 7, 8 and (D2b)'s H = 0 are evaluated on the faces between the angles 0
and π/RING_M of the mixed-area definition (``curvature``), built in three dimensions from the
meridians (``surfaces.ring_faces``). The ``/surfaces`` endpoint evaluates every face of a mesh.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from app.geometry.catalog.section5 import (
    RING_EQUATION_17 as EQUATION_17,
)
from app.geometry.checks import Check, Indices, Largest, check_residuals, not_applicable
from app.geometry.curvature import FaceCurvatures, face_curvatures, from_areas
from app.geometry.polygon import magnitude
from app.geometry.precision import Arithmetic, Array
from app.geometry.surfaces import arb_rings, ring_kernel
from app.geometry.surfaces.mesh import ring_faces
from app.geometry.surfaces.revolution_formulas import equation_17_residuals

#: The faces used for the ring checks span the angle π/RING_M.
RING_M = 16


def ring_rotation(ar: Arithmetic) -> tuple[Any, Any]:
    """cos and sin of the angle π/RING_M between a ring's meridians, in ``ar``."""
    theta = ar.pi / RING_M
    return ar.cos(theta), ar.sin(theta)


def ring_curvatures(ar: Arithmetic, meridian: Array, gauss: Array) -> FaceCurvatures:
    """Mixed-area curvatures of the ring of faces of two meridians ``(n, 2)``; ``(n−1,)``."""
    cos, sin = ring_rotation(ar)
    if ar.mode == "float64":  # the same arithmetic in one compiled pass (``ring_kernel``)
        compiled = ring_kernel.ring_curvatures(meridian, gauss, cos, sin)
        if compiled is not None:
            return compiled
    if ar.mode == "mp" and len(meridian) >= 2:
        planar = _ring_curvatures_in_the_meridian_plane(ar, meridian, gauss, cos, sin)
        if planar is not None:
            return planar
    f = ring_faces(ar, meridian[:-1], meridian[1:], cos, sin)
    g = ring_faces(ar, gauss[:-1], gauss[1:], cos, sin)
    return face_curvatures(ar, f, g)


def _ring_curvatures_in_the_meridian_plane(
    ar: Arithmetic, meridian: Array, gauss: Array, cos: Any, sin: Any
) -> FaceCurvatures | None:
    """``face_curvatures`` of the ring faces (``ring_faces``), each written out in its meridian
    coordinates: the same areas of the definition ([3]), with the vanishing and repeated terms
    of the three-dimensional faces left out (about a fifth of the operations on mp numbers,
    where each is a Python call). None where a face's area is not certainly positive (the
    general code names it).

    For the face (x0, y0, 0), (x0, y0 c, y0 s), (x1, y1 c, y1 s), (x1, y1, 0) of a meridian edge
    (c, s: cos θ, sin θ) the diagonals' cross product is (y0 + y1)·w with
    w = (−s Δy, s Δx, (1 − c) Δx), so the vector area is ½ S w (S = y0 + y1), the mixed vector
    area of two such faces ¼ (S_f w_n + S_n w_f) (the polarization of that quadratic form), and
    A(f)⃗ × A(n)⃗ = ¼ S_f S_n s (0, (1 − c)(Δy Δu − Δx Δv), s (Δx Δv − Δy Δu)). The
    magnitudes are ``diagonal_magnitude``'s sums of absolute coordinates (c, s > 0).
    """
    x, y = meridian[:, 0], meridian[:, 1]
    u, v = gauss[:, 0], gauss[:, 1]
    s_f = y[:-1] + y[1:]
    if not bool(np.all(s_f > 0)):
        return None
    s_n = v[:-1] + v[1:]
    dx, dy = x[1:] - x[:-1], y[1:] - y[:-1]
    du, dv = u[1:] - u[:-1], v[1:] - v[:-1]
    k = 1 - cos
    q, r = sin * sin, sin * sin + k * k  # w_f · w_n = q Δy Δv + r Δx Δu
    length = ar.sqrt(q * dy * dy + r * dx * dx)  # |w_f|
    if not bool(np.all(length > 0)):
        return None
    inner = q * dy * dv + r * dx * du
    area = s_f * length / 2
    gauss_area = s_n * inner / (2 * length)
    mixed = (s_f * inner + s_n * length * length) / (4 * length)
    cs = cos + sin
    x_abs, y_abs, u_abs, v_abs = abs(x), abs(y), abs(u), abs(v)  # each vertex once
    ax, ay, bx, by = x_abs[:-1], y_abs[:-1], x_abs[1:], y_abs[1:]
    au, av, bu, bv = u_abs[:-1], v_abs[:-1], u_abs[1:], v_abs[1:]
    f1, f2 = ax + ay + bx + by * cs, ax + ay * cs + bx + by
    n1, n2 = au + av + bu + bv * cs, au + av * cs + bu + bv
    mag_f, mag_n = f1 * f2 / 2, n1 * n2 / 2
    mag_fn = (f1 * n2 + n1 * f2) / 4
    turn = abs(dy * du - dx * dv) * sin * ar.sqrt(r)  # |w_f × w_n|
    turned = abs(s_f * s_n) * turn / 4
    return from_areas(ar, area, gauss_area, mixed, turned, (mag_f, mag_n, mag_fn))


def edge_parallel_residuals(meridian: Array, gauss: Array) -> Array:
    """|e(p) × e(n)| / (|p_i, p_{i+1}| · |n_i, n_{i+1}|) per edge: 0 when edges are parallel."""
    a = meridian[1:] - meridian[:-1]
    b = gauss[1:] - gauss[:-1]
    crossed = abs(a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0])
    return crossed / (magnitude(meridian[:-1], meridian[1:]) * magnitude(gauss[:-1], gauss[1:]))


def constant_curvature_residuals(curvature: FaceCurvatures, K: Any) -> Array:
    """|A(n) − K A(f)| relative to the magnitudes: 0 when the face has Gaussian curvature K."""
    scale = curvature.gauss_area_magnitude + abs(K) * curvature.area_magnitude
    return abs(curvature.gauss_area - K * curvature.area) / scale


def minimal_residuals(curvature: FaceCurvatures) -> Array:
    """|A(f, n)| relative to its magnitude: 0 when H = 0 on the face."""
    return abs(curvature.mixed_area) / curvature.mixed_area_magnitude


def equation_17_check(
    ar: Arithmetic,
    indices: Indices,
    pairs: list[tuple[Array, Array]],
    tolerance: float,
    detail: bool,
    curvatures: list[FaceCurvatures] | None = None,
) -> Check:
    """(17) against the mixed-area definition on each pair (meridian, Gauss image meridian).

    ``curvatures``, if given, are the pairs' ``ring_curvatures`` already computed (by the
    checks of Theorems 7, 8), so that they are not computed twice.
    """
    per_pair: list[Array] = []
    skipped = 0
    for k, (meridian, gauss) in enumerate(pairs):
        curvature = ring_curvatures(ar, meridian, gauss) if curvatures is None else curvatures[k]
        k_res, h_res, defined = equation_17_residuals(ar, meridian[:, 1], gauss[:, 1], curvature)
        # balls stay balls (floats of their bounds would underflow from 324 digits on)
        both = (
            ar.maximum(k_res, h_res)
            if ar.certified
            else np.maximum(ar.to_floats(k_res), ar.to_floats(h_res))
        )
        per_pair.append(np.where(defined, both, ar.scalar(0) if ar.certified else 0.0))
        skipped += int(np.count_nonzero(~defined))
    return equation_17_result(ar, indices, per_pair, skipped, tolerance, detail)


def ring_checks(
    ar: Arithmetic, meridian: Array, gauss: Array, curvature: Any, reduce: bool = False
) -> tuple[Array, Array, int] | None:
    """Theorem 7's (``curvature`` K) or 8's (None: H = 0) residuals and (17)'s on one ring, in
    one compiled pass: in float64 ``ring_kernel.ring_checks``, on balls ``arb_rings.ring_checks``
    (the numpy code's residuals, their scales at 64 bits; ``reduce``: the theorem's as the two
    balls a check without per-index residuals reads); None on mpmath numbers, or where the
    numpy path must name a face without area."""
    if ar.certified:
        cos, sin = ring_rotation(ar)
        return arb_rings.ring_checks(meridian, gauss, cos, sin, curvature, reduce)
    if ar.mode != "float64":
        return None
    cos, sin = ring_rotation(ar)
    return ring_kernel.ring_checks(meridian, gauss, cos, sin, curvature)


def ring_largest(
    ar: Arithmetic,
    meridian: Array,
    gauss: Array,
    curvature: float | None,
    found: tuple[bool, float, float, int] | None = None,
) -> tuple[Largest, Largest, int] | None:
    """Float64: ``ring_checks`` as the largest residuals (``checks.Largest``), the rows not
    stored (the checks without ``detail``); None as ``ring_checks``. ``found``: the pass's
    (valid, largest, largest (17), 0/0 faces), computed already
    (``d4b.fused_checks.image_numbers``)."""
    if ar.mode != "float64":
        return None
    cos, sin = ring_rotation(ar)
    if found is None:
        made = ring_kernel.ring_largest(meridian, gauss, cos, sin, curvature)
    else:
        valid, largest_found, largest_17_found, skipped_found = found
        made = (largest_found, largest_17_found, skipped_found) if valid else None
    if made is None:
        return None
    largest, largest_17, skipped = made

    def rows() -> tuple[Array, Array, int]:
        fused = ring_kernel.ring_checks(meridian, gauss, cos, sin, curvature)
        assert fused is not None  # the same faces have area
        return fused

    faces = max(len(meridian) - 1, 0)
    return (
        Largest(largest, faces, lambda: rows()[0]),
        Largest(largest_17, faces, lambda: rows()[1]),
        skipped,
    )


def _maximum(arrays: list[Any]) -> Array:
    """Entry by entry the largest of equal-length arrays (NaN wins, as ``np.maximum``)."""
    worst = arrays[0]
    for both in arrays[1:]:
        worst = np.maximum(worst, both)
    return worst


def equation_17_result(
    ar: Arithmetic,
    indices: Indices,
    per_pair: list[Array] | list[Largest],
    skipped: int,
    tolerance: float,
    detail: bool,
) -> Check:
    """The check of (17) from each pair's residuals per face (0 where 0/0, ``skipped`` such),
    or from each pair's largest (``checks.Largest``)."""
    worst: Array | Largest
    if all(isinstance(pair, Largest) for pair in per_pair):
        largest = [pair for pair in per_pair if isinstance(pair, Largest)]
        values = [pair.value for pair in largest]
        worst = Largest(
            math.nan if any(math.isnan(v) for v in values) else max(values),
            largest[0].count,
            lambda: _maximum([pair.residuals() for pair in largest]),
        )
    else:
        worst = per_pair[0]
        for k, both in enumerate(per_pair[1:], 2):
            # on balls a ball holding each maximum: in one compiled pass, the last one without
            # ``detail`` reduced to what the check reads (``arb_rings.maximum``)
            last = not detail and k == len(per_pair)
            compiled = arb_rings.maximum(worst, both, last) if ar.certified else None
            worst = compiled if compiled is not None else ar.maximum(worst, both)
    if skipped == len(per_pair[0]) * len(per_pair):
        return not_applicable(EQUATION_17, tolerance, "(17) is 0/0 on every face of the range")
    note = (
        f"(17) is 0/0 on {skipped} face(s) with p_(i+1)^y = p_i^y (skipped; the mixed-area "
        "definition gives K and H there, see docs/errata.md)"
        if skipped
        else None
    )
    return check_residuals(
        EQUATION_17, ar, indices[: len(worst)], worst, tolerance, detail, note=note
    )
