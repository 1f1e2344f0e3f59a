"""Eq. (17): K and H of a discrete surface of revolution from the radii of two meridians.

For a surface whose meridian polygon has radii p_i^y, rotated about the x-axis, and a parallel
Gauss image whose meridian has radii n_i^y, Section 5 states for the face between meridian
vertices i and i+1

    (17)  K = (n_{i+1}^y² − n_i^y²) / (p_{i+1}^y² − p_i^y²),
          H = (p_i^y n_i^y − p_{i+1}^y n_{i+1}^y) / (p_{i+1}^y² − p_i^y²).

This is the *theorem*: ``curvature`` holds the general mixed-area definition, and the checks
compare the two on three-dimensional faces.

0/0 faces. When p_{i+1}^y = p_i^y (a meridian edge parallel to the axis: the face is a band of a
cylinder) the edge of the Gauss image is parallel to it, so n_{i+1}^y = n_i^y too, and (17) reads
0/0. The mixed-area definition still gives values there: with λ the ratio of the parallel edges
(n_{i+1} − n_i = λ (p_{i+1} − p_i)), K = λ (n_i^y + n_{i+1}^y)/(p_i^y + p_{i+1}^y) and
H = −(λ + (n_i^y + n_{i+1}^y)/(p_i^y + p_{i+1}^y))/2; (17) is the special case λ = Δn^y/Δp^y.
``equation_17`` reports such faces in its ``defined`` mask instead of dividing.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Protocol

import numpy as np

from app.geometry.precision import Arithmetic, Array
from app.geometry.surfaces import equation_17_kernel


@dataclass(frozen=True)
class Equation17:
    """(17) on each face; K and H are 0 where ``defined`` is false (the 0/0 faces)."""

    K: Array
    H: Array
    defined: np.ndarray[Any, np.dtype[np.bool_]]


def equation_17(ar: Arithmetic, p_y: Array, n_y: Array) -> Equation17:
    """Eq. (17): K and H from the radii p_i^y of the surface and n_i^y of the Gauss image."""
    p0, p1, n0, n1 = p_y[:-1], p_y[1:], n_y[:-1], n_y[1:]
    denominator = p1 * p1 - p0 * p0
    defined = np.asarray(denominator != 0, dtype=bool)
    one = ar.scalar(1)
    safe = np.where(defined, denominator, one)
    zero = 0 * denominator
    K = np.where(defined, (n1 * n1 - n0 * n0) / safe, zero)
    H = np.where(defined, (p0 * n0 - p1 * n1) / safe, zero)
    return Equation17(K, H, defined)


def equation_17_residuals(
    ar: Arithmetic, p_y: Array, n_y: Array, areas: FaceAreas
) -> tuple[Array, Array, np.ndarray[Any, np.dtype[np.bool_]]]:
    """How far faces (one per meridian edge) are from (17); see ``face_residuals``."""
    return face_residuals(ar, p_y[:-1], p_y[1:], n_y[:-1], n_y[1:], areas)


class FaceAreas(Protocol):
    """A(f), A(n), A(f, n) of faces and the magnitudes they are computed from (``curvature``)."""

    @property
    def area(self) -> Array: ...
    @property
    def gauss_area(self) -> Array: ...
    @property
    def mixed_area(self) -> Array: ...
    @property
    def area_magnitude(self) -> Array: ...
    @property
    def gauss_area_magnitude(self) -> Array: ...
    @property
    def mixed_area_magnitude(self) -> Array: ...


def face_residuals(
    ar: Arithmetic, p0: Array, p1: Array, n0: Array, n1: Array, areas: FaceAreas
) -> tuple[Array, Array, np.ndarray[Any, np.dtype[np.bool_]]]:
    """(17) multiplied out, for faces with radii p0, p1 (surface) and n0, n1 (Gauss image).

    With K = A(n)/A(f) and H = −A(f,n)/A(f), (17) reads A(n)(p1² − p0²) = A(f)(n1² − n0²) and
    A(f,n)(p1² − p0²) = −A(f)(p0 n0 − p1 n1). The residuals are the differences of the two sides
    over the magnitudes of the numbers they are computed from (the areas' magnitudes, not their
    values), so they measure the formula, not the rounding of tiny or vanishing areas:

        K: |A(n) Δ − A(f)(n1² − n0²)| / (|A(n)|~ Σ + |A(f)|~ (n1² + n0²)),
        H: |A(f,n) Δ + A(f)(p0 n0 − p1 n1)| / (|A(f,n)|~ Σ + |A(f)|~ (|p0 n0| + |p1 n1|)),

    Δ = p1² − p0², Σ = p1² + p0², ~ the magnitude (computed with the radii p scaled to at most
    1 per face, which leaves the ratios unchanged). The mask tells the faces where (17) is not
    0/0 (p1 ≠ p0).
    """
    if ar.mode == "float64":  # the same operations in one compiled pass
        return equation_17_kernel.face_residuals(p0, p1, n0, n1, areas)
    tiny = ar.scalar(np.finfo(np.float64).tiny)
    if ar.may_overflow:
        # (17) is homogeneous in the radii p: divide them by c = max(|p0|, |p1|) per face, and
        # A(f) by c² (K equation) or c (H equation), so that no product overflows
        c = np.maximum(abs(p0), abs(p1))
        c = np.where(c > tiny, c, ar.scalar(1))
        q0, q1 = p0 / c, p1 / c
        area_k, mag_k = areas.area / c / c, areas.area_magnitude / c / c
        area_h, mag_h = areas.area / c, areas.area_magnitude / c
    else:  # mp numbers do not overflow: the same ratios unscaled (a fifth of the operations)
        q0, q1 = p0, p1
        area_k, mag_k = area_h, mag_h = areas.area, areas.area_magnitude
    dp = q1 * q1 - q0 * q0
    sp = q1 * q1 + q0 * q0
    k_scale = areas.gauss_area_magnitude * sp + mag_k * (n1 * n1 + n0 * n0)
    h_scale = areas.mixed_area_magnitude * sp + mag_h * (abs(q0 * n0) + abs(q1 * n1))
    k_res = abs(areas.gauss_area * dp - area_k * (n1 * n1 - n0 * n0))
    h_res = abs(areas.mixed_area * dp + area_h * (q0 * n0 - q1 * n1))
    k_res = k_res / np.where(k_scale > tiny, k_scale, tiny)
    h_res = h_res / np.where(h_scale > tiny, h_scale, tiny)
    return k_res, h_res, np.asarray(dp != 0, dtype=bool)
