"""Gauss images of meridian polygons (Sections 5, 6), built from their geometric descriptions.

A discrete surface of revolution is paired with a Gauss image: another surface of revolution
whose meridian has edges parallel to the meridian's edges. Three constructions appear in the
paper, each written here from its description and nothing else (the closed forms (18), (19),
(20) live in ``kinematic_closed_forms`` and are compared by the checks):

- **inscribed** (Theorem 7, (18); Theorem 11): vertices on the unit circle, edge k parallel to
  edge k of the meridian, one vertex prescribed. Edge k is the chord through n_k parallel to
  e_k = q_{k+1} − q_k, so n_{k+1} is the reflection of n_k in the diameter orthogonal to e_k:
  with angles, θ_k + θ_{k+1} = 2ψ_k + π (mod 2π), ψ_k the direction angle of e_k. Written as
  an alternating cumulative sum, the recursion is vectorized (both directions from the
  prescribed vertex at once).
- **contact points** ñ_k ((19)): the points where the circle touches the tangent parallel to
  edge k, i.e. the unit normals of the edges, all on one side (the left of the direction in
  which the meridian runs along the x-axis).
- **circumscribed** (Theorem 8, (20)): the polygon whose edge k lies on the tangent at ñ_k;
  its vertex m_k is the pole of the chord ñ_{k−1} ñ_k (the intersection of the two tangents).
  It lies on the bisector of ñ_{k−1} and ñ_k at distance 1/cos(δ/2), δ the turning angle
  between the edges, which is how it is computed (stable for tiny turning angles).
- **unit circle from x** (Theorem 11): n = (s, √(1 − s²)) on the upper half circle.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from app.geometry import companion_kernels
from app.geometry.compiled import all_positive_lengths
from app.geometry.errors import DomainError
from app.geometry.polygon import edge_vectors
from app.geometry.precision import Arithmetic, Array, stack_points


def _require_edges(ar: Arithmetic, edges: Array) -> None:
    if ar.mode == "float64":  # the same test without the array of lengths
        positive = all_positive_lengths(np.asarray(edges, dtype=np.float64))
    else:
        positive = not len(edges) or bool(np.all(ar.hypot(edges[:, 0], edges[:, 1]) > 0))
    _require_positive(positive)


def _require_positive(positive: bool) -> None:
    if not positive:
        raise DomainError("meridian", "consecutive vertices are distinct", "a zero-length edge")


def _alternating(count: int) -> np.ndarray[tuple[int], np.dtype[np.int64]]:
    """(−1)^k for k = 0 .. count − 1, as integers (exact in both precisions)."""
    return 1 - 2 * (np.arange(count, dtype=np.int64) % 2)


def inscribed_parallel(ar: Arithmetic, polygon: Array, start: int, start_point: Array) -> Array:
    """Inscribed polygon with edges parallel to ``polygon``'s, through ``start_point`` (18).

    ``polygon`` is ``(n, 2)``; ``start`` is the local index (0 .. n−1) of the prescribed vertex,
    which must lie on the unit circle. Returns ``(n, 2)``. Vectorized: with φ_k = (−1)^k θ_k the
    relation θ_k + θ_{k+1} = 2ψ_k + π becomes φ_{k+1} = φ_k + (−1)^{k+1}(2ψ_k + π), a
    cumulative sum whose alternating terms keep it bounded.
    """
    edges = edge_vectors(polygon)
    _require_edges(ar, edges)
    n = len(polygon)
    signs = _alternating(n)
    psi = ar.atan2(edges[:, 1], edges[:, 0])
    steps = -signs[:-1] * (2 * psi + ar.pi)  # (−1)^{k+1}(2ψ_k + π)
    partial = np.concatenate([ar.zeros(1), np.cumsum(steps)])  # W_k = Σ_{j<k} steps_j
    theta_start = ar.atan2(start_point[1], start_point[0])
    phi = signs[start] * theta_start + (partial - partial[start])
    theta = signs * phi
    return stack_points(ar.cos(theta), ar.sin(theta))


def orientation(polygon: Array) -> int:
    """+1 if the meridian runs towards +x overall (last x ≥ first x), else −1."""
    return 1 if polygon[-1, 0] >= polygon[0, 0] else -1


def contact_points(ar: Arithmetic, polygon: Array) -> Array:
    """ñ_k: the unit normal of edge k on the left of the overall direction (19); ``(n−1, 2)``."""
    if ar.mode == "float64":  # the same operations in one compiled pass
        points, positive = companion_kernels.contact_points(
            np.asarray(polygon, dtype=np.float64), float(orientation(polygon))
        )
        _require_positive(positive)
        return points
    edges = edge_vectors(polygon)
    _require_edges(ar, edges)
    length = ar.hypot(edges[:, 0], edges[:, 1])
    sign = orientation(polygon)
    return stack_points(-sign * edges[:, 1] / length, sign * edges[:, 0] / length)


def circumscribed(ar: Arithmetic, polygon: Array) -> Array:
    """m_k, the pole of the chord ñ_{k−1} ñ_k, for the interior vertices (20); ``(n−2, 2)``.

    The tangents at ñ_{k−1} and ñ_k meet on their bisector at distance 1/cos(δ_k/2), where δ_k
    is the turning angle from edge k−1 to edge k (0 for parallel edges: then m_k = ñ_k).
    """
    if ar.mode == "float64":
        return _circumscribed_float64(np.asarray(polygon, dtype=np.float64))
    edges = edge_vectors(polygon)
    _require_edges(ar, edges)
    a, b = edges[:-1], edges[1:]
    turn = ar.atan2(a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0], a[:, 0] * b[:, 0] + a[:, 1] * b[:, 1])
    sign = orientation(polygon)
    # direction angle of ñ_{k−1}: the edge angle turned by ±π/2 to the left of the run
    normal_angle = ar.atan2(sign * a[:, 0], -sign * a[:, 1])
    bisector = normal_angle + turn / 2
    distance = 1 / ar.cos(turn / 2)
    return stack_points(distance * ar.cos(bisector), distance * ar.sin(bisector))


def _circumscribed_float64(polygon: np.ndarray[Any, np.dtype[np.float64]]) -> Array:
    """``circumscribed`` in float64: the formulas above in one compiled pass
    (``companion_kernels.circumscribed_poles``)."""
    poles, positive = companion_kernels.circumscribed_poles(polygon, float(orientation(polygon)))
    _require_positive(positive)
    return poles


def unit_circle_points(ar: Arithmetic, s: Array, one_minus_s_squared: Array) -> Array:
    """n = (s, √(1 − s²)): points of the upper unit half circle with given x (Theorem 11).

    ``one_minus_s_squared`` is passed in so that a caller who knows 1 − s² more accurately than
    the rounded s can tell (see ``vanishing_mean_curvature``).
    """
    return stack_points(s, ar.sqrt(one_minus_s_squared))
