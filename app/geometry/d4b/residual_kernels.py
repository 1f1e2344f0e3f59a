"""Hot float64 checks of Section 4.2 on (D4b), as one compiled pass over the heights.

``discretization`` checks eq. (13), its two-step form and the right angles of Nikolaides on the
polygons with numpy (a dozen passes each, and many small calls on short polygons); the kernels
here compute the same residual arrays entry by entry, with the same operations in the same order
(``closed_forms.recursion_13``, ``closed_forms.two_step``, ``checks.relative_difference``,
``nikolaides.right_angle_residuals``), so they agree with the numpy evaluation bit for bit
(tests/geometry/d4b/test_residual_kernels.py); the rotation angle (since session 22) is one
argument of a complex product instead of a difference of atan2's, and on a true polygon the
quotient that atan rounds to, a few ulp of the angles from the old residuals
(``_rotation_angles``). They hold the proof's formulas, as ``closed_forms`` does, and take the
polygons as given (arrays in, residual arrays out): the construction is never consulted here.
The mp path keeps the numpy/mpmath evaluation.

The distances between two polygons (``point_distance``, ``relative_point_difference``) take
√(x² + y²) where neither square can overflow or lose its bits to underflow, instead of libm's
hypot (50–90 ns an entry here, most of the checks' time at 10^6 vertices): within 2 units in the
last place of hypot, which only residuals at rounding level see; the mp path keeps ``ar.hypot``.

The largest values the checks read without ``detail`` (and the edge resolutions and the proof's
ratios) are taken a block of rows at a time (the end of this module): the same operations in a
loop without branches, which the compiler runs four rows at once, and the scalar pass again for
a block with a NaN or a length off the square-root branch; the same bits as the scalar passes
(tests/geometry/d4b/test_residual_blocks.py).
"""

from __future__ import annotations

import math
from typing import Any

import numba
import numpy as np

from app.geometry import checks, elementary
from app.geometry.checks import Largest
from app.geometry.compiled import (
    INF_BITS,
    MAGNITUDE_BITS,
    bits_value,
    fast_length,
    flat_rows,
    kernel,
    largest_bits,
    leaf_tree,
    length,
    pairwise_leaves,
    pairwise_sum,
    running_largest,
)
from app.geometry.d4b.closed_forms import inversion_pole
from app.geometry.precision import Arithmetic, Array

TINY = float(np.finfo(np.float64).tiny)


@kernel("float64[:](float64[:, :], float64[:, :])")
def _distances(a: Any, b: Any) -> Any:
    """|a_k − b_k| for each row k of two (m, 2) arrays."""
    out = np.empty(a.shape[0])
    for k in range(a.shape[0]):
        out[k] = length(a[k, 0] - b[k, 0], a[k, 1] - b[k, 1])
    return out


@kernel("float64[:](float64[:, :], float64[:, :], float64)")
def _relative_distances(computed: Any, expected: Any, tiny: float) -> Any:
    """|computed_k − expected_k| / max(|expected_k|, tiny) for each row k."""
    out = np.empty(computed.shape[0])
    for k in range(computed.shape[0]):
        ex, ey = expected[k, 0], expected[k, 1]
        scale = length(ex, ey)
        scale = scale if scale > tiny else tiny
        out[k] = length(computed[k, 0] - ex, computed[k, 1] - ey) / scale
    return out


@kernel("float64[:](float64[:, :], float64[:, :], float64, float64[:])")
def _scaled_relative_distances(computed: Any, expected: Any, tiny: float, scale: Any) -> Any:
    """``_relative_distances`` times scale_k, in the same pass (the product as numpy's)."""
    out = np.empty(computed.shape[0])
    for k in range(computed.shape[0]):
        ex, ey = expected[k, 0], expected[k, 1]
        size = length(ex, ey)
        size = size if size > tiny else tiny
        out[k] = length(computed[k, 0] - ex, computed[k, 1] - ey) / size * scale[k]
    return out


@numba.njit(cache=True, inline="always", error_model="numpy")
def _one_step(d: float, a: float, b: float, after: float, tiny: float) -> float:
    """(13)'s residual of ``after`` = p_{i+1}^y from a = p_{i−1}^y, b = p_i^y."""
    predicted = (b * (b / a) + 2 * d * (d / a) + d * (d / b)) / (1 - (d / a) * (d / b))
    scale = abs(predicted)
    return abs(after - predicted) / (scale if scale > tiny else tiny)


@numba.njit(cache=True, inline="always", error_model="numpy")
def _two_steps(d: float, a: float, b: float, later: float, tiny: float) -> float:
    """The two-step form's residual of ``later`` = p_{i+2}^y from a = p_{i−1}^y, b = p_i^y."""
    e = d / a
    f = d / b
    numerator = b * (b / a) * (b / a) + (d * f) * (a / b + 2 + 3 * (b / a) + 4 * (b / a) * (b / a))
    numerator = numerator + (d * e) * (e * f) * (2 * (a / b) + 3)
    predicted = numerator / ((1 - e * f) * (1 - e * f))
    scale = abs(predicted)
    return abs(later - predicted) / (scale if scale > tiny else tiny)


@kernel("Tuple((float64[:], float64[:], float64, float64))(float64, float64[:], float64, boolean)")
def _recursions(d: float, y: Any, tiny: float, store: bool) -> tuple[Any, Any, float, float]:
    """Relative differences of p_{i+1}^y from (13) and of p_{i+2}^y from its two-step form,
    stored if ``store`` (else two empty arrays), and the largest of each (NaN if one is NaN).

    (13): (b(b/a) + 2d(d/a) + d(d/b)) / (1 − (d/a)(d/b)); two steps, with e = d/a, f = d/b:
    (b(b/a)(b/a) + (df)(a/b + 2 + 3(b/a) + 4(b/a)(b/a)) + (de)(ef)(2(a/b) + 3)) / ((1 − ef)²),
    a = p_{i−1}^y, b = p_i^y; each residual is |y − predicted| / max(|predicted|, tiny).
    """
    n = y.shape[0]
    one = np.empty(max(n - 2, 0) if store else 0)
    two = np.empty(max(n - 3, 0) if store else 0)
    largest_one, largest_two = 0.0, 0.0
    for k in range(n - 2):
        residual = _one_step(d, y[k], y[k + 1], y[k + 2], tiny)
        largest_one = running_largest(residual, largest_one)
        if store:
            one[k] = residual
        if k < n - 3:
            residual = _two_steps(d, y[k], y[k + 1], y[k + 3], tiny)
            largest_two = running_largest(residual, largest_two)
            if store:
                two[k] = residual
    return one, two, largest_one, largest_two


@numba.njit(cache=True, inline="always", error_model="numpy")
def _two_step_printed_at(d2: float, d4: float, y: Any, k: int, tiny: float) -> float:
    """The relative difference of p_{k+3}^y from the two-step form as printed
    (``closed_forms.two_step_printed``), d2 = d**2 and d4 = d**4 given; the powers as products
    (b⁵ = (b²)² b, a³ = a² a), within a few units in the last place of libm's pow, which cost
    four calls an entry (a printed formula's residual: far from rounding level)."""
    a, b = y[k], y[k + 1]
    aa, bb = a * a, b * b
    b3 = bb * b
    numerator = (
        bb * bb * b
        + d2 * (aa * a + 2 * aa * b + 3 * a * bb + 4 * b3)
        + d4 * (2 * b3 + 2 * a + 3 * b)
    )
    denominator = d2 - a * b
    predicted = numerator / (denominator * denominator)
    scale = abs(predicted)
    return abs(y[k + 3] - predicted) / (scale if scale > tiny else tiny)


@kernel("float64[:](float64, float64, float64[:], float64)")
def _two_step_printed(d2: float, d4: float, y: Any, tiny: float) -> Any:
    """``_two_step_printed_at`` for every k."""
    count = max(y.shape[0] - 3, 0)
    out = np.empty(count)
    for k in range(count):
        out[k] = _two_step_printed_at(d2, d4, y, k, tiny)
    return out


@numba.njit(cache=True, inline="always", error_model="numpy")
def _right_angle_at(tractrix: Any, axis: Any, p: Any, k: int) -> float:
    """``_right_angles``' residual at row k: the larger of the two angles' (NaN wins)."""
    vx, vy = tractrix[k, 0], tractrix[k, 1]
    ux, uy = axis[k, 0] - vx, axis[k, 1] - vy
    size_a = abs(axis[k, 0]) + abs(axis[k, 1]) + abs(vx) + abs(vy)
    wx, wy = p[k, 0] - vx, p[k, 1] - vy
    size_b = abs(p[k, 0]) + abs(p[k, 1]) + abs(vx) + abs(vy)
    at_p = abs(ux * wx + uy * wy) / (size_a * size_b)
    wx, wy = p[k + 1, 0] - vx, p[k + 1, 1] - vy
    size_b = abs(p[k + 1, 0]) + abs(p[k + 1, 1]) + abs(vx) + abs(vy)
    at_next = abs(ux * wx + uy * wy) / (size_a * size_b)
    return at_p if (at_p >= at_next or at_p != at_p) else at_next  # np.maximum: NaN wins


@kernel("Tuple((float64[:], float64))(float64[:, :], float64[:, :], float64[:, :], int64, boolean)")
def _right_angles(tractrix: Any, axis: Any, p: Any, n: int, store: bool) -> tuple[Any, float]:
    """max over the angles x_i d_i p_i and x_i d_i p_{i+1} of |cos| measured as Nikolaides',
    stored if ``store`` (else an empty array), and the largest (NaN if one is NaN).

    For a vertex v = d_i and ends a = x_i, b = p_i (then p_{i+1}):
    |(a − v)·(b − v)| / ((|a^x| + |a^y| + |v^x| + |v^y|)(|b^x| + |b^y| + |v^x| + |v^y|)).
    """
    out = np.empty(n if store else 0)
    largest = 0.0
    for k in range(n):
        residual = _right_angle_at(tractrix, axis, p, k)
        largest = running_largest(residual, largest)
        if store:
            out[k] = residual
    return out, largest


def recursion_residuals(d: float, y: Any) -> tuple[Any, Any]:
    """(residuals of (13) for p_{i+1}^y, of the two-step form for p_{i+2}^y) on heights y."""
    one, two, _, _ = _recursions(float(d), np.asarray(y, dtype=np.float64), TINY, True)
    return one, two


def recursion_largest(
    d: float, y: Any, found: tuple[float, float] | None = None
) -> tuple[Largest, Largest]:
    """``recursion_residuals`` as their largest values (``checks.Largest``), not stored;
    ``found``: those values, computed already (``fused_checks.section_numbers``)."""
    heights = np.asarray(y, dtype=np.float64)
    if found is not None:
        one, two = found
    elif (pairs := _paired(heights)) is not None:  # the heights read in place from their rows
        one, two = _largest_recursions_pairs(float(d), pairs, TINY)
    else:
        one, two = _largest_recursions(float(d), heights, TINY)
    count = len(heights)
    return (
        Largest(float(one), max(count - 2, 0), lambda: recursion_residuals(d, heights)[0]),
        Largest(float(two), max(count - 3, 0), lambda: recursion_residuals(d, heights)[1]),
    )


def two_step_printed_residuals(d: float, y: Any) -> Any:
    """Residuals of p_{i+2}^y against the printed two-step form (erratum E3) on heights y."""
    d = float(d)
    return _two_step_printed(d**2, d**4, np.asarray(y, dtype=np.float64), TINY)


def largest_two_step_printed_residual(d: float, y: Any, found: float | None = None) -> float | None:
    """The largest of ``two_step_printed_residuals`` as ``checks.printed_residual`` reports it
    (None for none, or one that is not finite), without the array; ``found``: the largest,
    computed already (``fused_checks.section_numbers``)."""
    if len(y) < 4:
        return None
    d = float(d)
    heights = np.asarray(y, dtype=np.float64)
    if found is not None:
        worst = found
    elif (pairs := _paired(heights)) is not None:  # the heights read in place from their rows
        worst = float(_largest_two_step_printed_pairs(d**2, d**4, pairs, TINY))
    else:
        worst = float(_largest_two_step_printed_blocked(d**2, d**4, heights, TINY))
    return worst if math.isfinite(worst) else None


def right_angle_residuals(tractrix: Any, axis: Any, p: Any, n: int) -> Any:
    """Nikolaides' right angles at d_i (to p_i and to p_{i+1}) for i = 0 .. n − 1, the larger."""

    def f64(points: Any) -> Any:
        return np.asarray(points, dtype=np.float64)

    return _right_angles(f64(tractrix), f64(axis), f64(p), n, True)[0]


def right_angle_largest(
    tractrix: Any, axis: Any, p: Any, n: int, found: float | None = None
) -> Largest:
    """``right_angle_residuals`` as their largest value (``checks.Largest``), not stored;
    ``found``: that value, computed already (``fused_checks.section_numbers``)."""
    if found is not None:
        largest = found
    else:
        largest = _largest_right_angle(_contiguous(tractrix), _contiguous(axis), _contiguous(p), n)
    return Largest(float(largest), max(n, 0), lambda: right_angle_residuals(tractrix, axis, p, n))


@numba.njit(cache=True, inline="always", error_model="numpy")
def _hypothesis_rows(
    p: Any, start: int, stop: int, d2: float, largest: float, smallest: float
) -> tuple[float, float]:
    """Theorem 4's hypothesis on k = start .. stop − 1 as ``checks._hypothesis`` computes it
    entry by entry, from the running values given: the largest violation max(d² − p_{k−1}^y
    p_k^y, 0)/d² (NaN wins, as ``np.maximum`` and the largest magnitude give it) and the smallest
    p_{k−1}^y p_k^y / d² (NaN wins, as ``np.min``)."""
    for k in range(start, stop):
        product = p[k - 1, 1] * p[k, 1]
        excess = d2 - product
        violation = excess if (excess >= 0.0 or excess != excess) else 0.0
        largest = running_largest(violation / d2, largest)
        ratio = product / d2
        if smallest == smallest and (ratio != ratio or ratio < smallest):
            smallest = ratio
    return largest, smallest


def hypothesis_largest(
    p: Any, n: int, d: float, found: tuple[float, float] | None = None
) -> tuple[Largest, float]:
    """Float64: Theorem 4's hypothesis on p_0 .. p_{n−1} (n >= 2) in one pass: its largest
    violation (``checks.Largest``; the array, as ``checks._hypothesis`` builds it, on demand)
    and the smallest p_{k−1}^y p_k^y / d²; ``found``: those two, computed already
    (``fused_checks.section_numbers``)."""
    d2 = float(d) * float(d)
    points = _contiguous(p)
    largest, smallest = _hypothesis_blocked(points, n, d2) if found is None else found

    def violations() -> Any:
        products = points[: n - 1, 1] * points[1:n, 1]
        return np.maximum(d2 - products, 0.0) / d2

    return Largest(float(largest), n - 1, violations), float(smallest)


@numba.njit(cache=True, inline="always", error_model="numpy")
def _contact_rotation_at(contact: Any, normals: Any, scale: Any, k: int) -> float:
    """``_contact_rotation``'s residual at row k."""
    distance = length(contact[k + 1, 0] - (-normals[k, 1]), contact[k + 1, 1] - normals[k, 0])
    return distance * scale[k]


@kernel("Tuple((float64[:], float64))(float64[:, :], float64[:, :], float64[:], int64, boolean)")
def _contact_rotation(contact: Any, normals: Any, scale: Any, count: int, store: bool) -> Any:
    """(19) as the rotation of n by a quarter turn, k = 0 .. count − 1: |ñ_{k+1} − (−n_k^y,
    n_k^x)| times scale_k, as ``curvature.evaluate``'s ``rotation`` computes it
    (``point_distance`` of the stacked rotated points, then the product); the array if
    ``store`` (else empty) and the largest (NaN if one is NaN)."""
    out = np.empty(count if store else 0)
    largest = 0.0
    for k in range(count):
        value = _contact_rotation_at(contact, normals, scale, k)
        largest = running_largest(value, largest)
        if store:
            out[k] = value
    return out, largest


def contact_rotation_largest(
    contact: Any, normals: Any, scale: Any, count: int, found: float | None = None
) -> Largest:
    """Float64: the largest of ``_contact_rotation``'s residuals (``checks.Largest``, the
    array on demand); ``contact`` needs count + 1 rows, ``normals`` and ``scale`` count.
    ``found``: the largest, computed already (``fused_checks.image_numbers``)."""
    arrays = (
        _contiguous(contact),
        _contiguous(normals),
        np.ascontiguousarray(scale, dtype=np.float64),
    )
    largest = _largest_contact_rotation(*arrays, count) if found is None else found
    return Largest(float(largest), count, lambda: _contact_rotation(*arrays, count, True)[0])


@numba.njit(cache=True, inline="always", error_model="numpy")
def _pole_inversion_at(gauss: Any, contact: Any, scale: Any, k: int, tiny: float) -> float:
    """``_pole_inversion``'s residual at row k."""
    ex, ey = inversion_pole(contact[k, 0], contact[k, 1], contact[k + 1, 0], contact[k + 1, 1])
    size = length(ex, ey)
    size = size if size > tiny else tiny
    return length(gauss[k, 0] - ex, gauss[k, 1] - ey) / size * scale[k]


@kernel(
    "Tuple((float64[:], float64))(float64[:, :], float64[:, :], float64[:], int64, float64, "
    "boolean)"
)
def _pole_inversion(
    gauss: Any, contact: Any, scale: Any, count: int, tiny: float, store: bool
) -> Any:
    """(20)'s first form, k = 0 .. count − 1: m_k against the pole of the chord ñ_k ñ_{k+1}
    inverted in the circle (``closed_forms.pole_by_inversion``), relative to its length
    (``relative_point_difference``) and times scale_k, the same operations as
    ``curvature.evaluate``'s ``inversion``; the array if ``store`` and the largest (NaN wins)."""
    out = np.empty(count if store else 0)
    largest = 0.0
    for k in range(count):
        value = _pole_inversion_at(gauss, contact, scale, k, tiny)
        largest = running_largest(value, largest)
        if store:
            out[k] = value
    return out, largest


def pole_inversion_largest(
    gauss: Any, contact: Any, scale: Any, count: int, found: float | None = None
) -> Largest:
    """Float64: the largest of ``_pole_inversion``'s residuals (``checks.Largest``, the array
    on demand); ``contact`` needs count + 1 rows, ``gauss`` and ``scale`` count. ``found``: the
    largest, computed already (``fused_checks.image_numbers``)."""
    arrays = _contiguous(gauss), _contiguous(contact), np.ascontiguousarray(scale, dtype=np.float64)
    largest = _largest_pole_inversion(*arrays, count, TINY) if found is None else found
    return Largest(float(largest), count, lambda: _pole_inversion(*arrays, count, TINY, True)[0])


@numba.njit(cache=True, inline="always", error_model="numpy")
def _minimum(a: float, b: float) -> float:
    """``np.minimum`` of two floats, without a branch: NaN if either is NaN."""
    return a if ((a < b) | (a != a)) else b


@numba.njit(cache=True, inline="always", error_model="numpy")
def _rotation_and_inversion_rows(
    p: Any,
    contact: Any,
    normals: Any,
    gauss: Any,
    start: int,
    stop: int,
    rotation: bool,
    inversion: bool,
    tiny: float,
    previous: float,
    largest_rotation: float,
    largest_inversion: float,
) -> tuple[float, float, float]:
    """(19) as a rotation and (20) by inversion, their largest residuals on rows start .. stop − 1
    in one scalar pass that makes their scales as it goes (from the previous edge's resolution
    and the running largest values): (the last edge's resolution, the two largest). The
    ``_contact_rotation`` (if ``rotation``) and ``_pole_inversion`` (if ``inversion``) of the
    edge resolution of p_k p_{k+1} (``_edge_resolution``) and of the pole's, the smaller of it
    and the previous edge's (np.minimum's, NaN if either is), so that neither scale is stored:
    the same numbers as the passes over the stored scales."""
    for k in range(start, stop):
        ex = p[k + 1, 0] - p[k, 0]
        ey = p[k + 1, 1] - p[k, 1]
        size = abs(p[k, 0]) + abs(p[k, 1]) + abs(p[k + 1, 0]) + abs(p[k + 1, 1])
        resolution = length(ex, ey) / size
        if rotation:
            distance = length(
                contact[k + 1, 0] - (-normals[k, 1]), contact[k + 1, 1] - normals[k, 0]
            )
            largest_rotation = running_largest(distance * resolution, largest_rotation)
        if inversion:
            scale = _minimum(previous, resolution)
            px, py = inversion_pole(
                contact[k, 0], contact[k, 1], contact[k + 1, 0], contact[k + 1, 1]
            )
            pole = length(px, py)
            pole = pole if pole > tiny else tiny
            value = length(gauss[k, 0] - px, gauss[k, 1] - py) / pole * scale
            largest_inversion = running_largest(value, largest_inversion)
        previous = resolution
    return previous, largest_rotation, largest_inversion


@numba.njit(cache=True, inline="always", error_model="numpy")
def _resolution_before(before: Any) -> float:
    """The edge resolution of ``before``'s one edge (the edge before the range)."""
    ex = before[1, 0] - before[0, 0]
    ey = before[1, 1] - before[0, 1]
    size = abs(before[0, 0]) + abs(before[0, 1]) + abs(before[1, 0]) + abs(before[1, 1])
    return length(ex, ey) / size


def rotation_and_inversion_largest(
    p: Any,
    before: Any,
    contact: Any,
    normals: Any,
    gauss: Any,
    count: int,
    rotation: bool,
    inversion: bool,
) -> tuple[float, float]:
    """Float64: the largest residuals of (19) as a rotation and of (20) by inversion
    (``contact_rotation_largest`` with ``edge_resolution(p)``, ``pole_inversion_largest`` with
    the pole resolution ``curvature.evaluate`` makes from it and ``before``), those asked for
    (0.0 for the other), from one pass without the scales' arrays; ``p`` and ``contact`` need
    count + 1 rows, ``normals`` and ``gauss`` count, ``before`` two."""
    found = _rotation_and_inversion_blocked(
        _contiguous(p),
        _contiguous(before),
        _contiguous(contact),
        _contiguous(normals),
        _contiguous(gauss),
        count,
        rotation,
        inversion,
        TINY,
    )
    return float(found[0]), float(found[1])


#: Vertices per block of the rotation angle's passes (its scratch rows stay in the cache).
ROTATION_BLOCK = 8192

#: Below this many angles one compiled pass with libm's atan2 is cheaper than the blocks' five
#: calls (≈ 12 µs). The blocks call the same function (``elementary.atan2``); when they called
#: numpy's arctan2, SVML's on a processor with AVX-512, that saved ≈ 25 ns an angle there.
ROTATION_LIBM_BELOW = 512


@kernel("void(float64[:, ::1], float64[:, ::1], int64, int64, float64[:, ::1])")
def _rotation_arguments(p: Any, axis: Any, start: int, stop: int, rows: Any) -> None:
    """The atan2 arguments of Theorem 4's rotation angle at p_k, k = start .. stop − 1, into
    column k − start of ``rows``: p_k^y, then a × b and a · b for a = x_{k−1} − p_k, b = x_k − p_k
    (corrected), then b × c and b · c for c = x_{k+1} − p_k (printed), as
    ``checks._signed_angle`` writes them. C-contiguous ``(n, 2)`` points and rows: the loop has
    no branch, and the compiler vectorizes it (it reads the points' rows as pairs)."""
    count = stop - start
    here, around = flat_rows(p, start, count), flat_rows(axis, start - 1, count + 2)  # from 0
    for j in range(count):
        px, py = here[2 * j], here[2 * j + 1]
        ax, ay = around[2 * j] - px, around[2 * j + 1] - py
        bx, by = around[2 * j + 2] - px, around[2 * j + 3] - py
        cx, cy = around[2 * j + 4] - px, around[2 * j + 5] - py
        rows[0, j] = py
        rows[1, j] = ax * by - ay * bx
        rows[2, j] = ax * bx + ay * by
        rows[3, j] = bx * cy - by * cx
        rows[4, j] = bx * cx + by * cy


@kernel("UniTuple(float64, 2)(float64[::1], float64[::1], float64[::1], int64, float64, float64)")
def _rotation_residuals(
    halves: Any,
    corrected: Any,
    printed: Any,
    count: int,
    largest: float,
    largest_printed: float,
) -> tuple[float, float]:
    """|angle − 2 atan2(d, p^y)| for the corrected and the printed angles of one block
    (``halves``: atan2(d, p^y); ``corrected``, ``printed``: the angles, overwritten by their
    residuals), and the running largest of each (NaN once one is NaN).

    Without branches (vectorized by the compiler): the residuals, whether one is NaN, and the
    largest of each as the largest bit pattern of the magnitudes (for floats without NaN the
    order of the patterns as integers is the order of the numbers: the same value as the running
    largest). A block with a NaN is folded residual by residual, as before."""
    for j in range(count):
        formula = 2 * halves[j]
        corrected[j] = abs(corrected[j] - formula)
        printed[j] = abs(printed[j] - formula)
    corrected_bits, printed_bits = corrected.view(np.int64), printed.view(np.int64)
    plain = True
    top, top_printed = 0, 0
    for j in range(count):
        plain &= (corrected[j] == corrected[j]) & (printed[j] == printed[j])
        bits = corrected_bits[j] & MAGNITUDE_BITS
        top = bits if bits > top else top
        bits = printed_bits[j] & MAGNITUDE_BITS
        top_printed = bits if bits > top_printed else top_printed
    if not plain:  # a NaN: the running largest residual by residual
        for j in range(count):
            largest = running_largest(corrected[j], largest)
            largest_printed = running_largest(printed[j], largest_printed)
        return largest, largest_printed
    found = np.empty(2, dtype=np.int64)
    found[0], found[1] = top, top_printed
    values = found.view(np.float64)
    return running_largest(values[0], largest), running_largest(values[1], largest_printed)


@kernel(
    "Tuple((float64[:], float64[:], float64, float64))"
    "(float64, float64[:, :], float64[:, :], int64, boolean)"
)
def _rotation_angles_libm(
    d: float, p: Any, axis: Any, n: int, store: bool
) -> tuple[Any, Any, float, float]:
    """Theorem 4's rotation angle at p_i, i = 1 .. n − 1: |angle − 2 atan2(d, p_i^y)| for the
    angle between x_{i−1} − p_i and x_i − p_i (corrected), and for x_i − p_i, x_{i+1} − p_i
    (printed); each angle atan2(a × b, a · b) as ``checks._signed_angle``, libm's atan2 in one
    pass (``_rotation_angles`` takes it for short polygons). Both arrays stored if ``store``
    (else empty), and the largest of each (NaN if one is NaN)."""
    count = max(n - 1, 0)
    corrected = np.empty(count if store else 0)
    printed = np.empty(count if store else 0)
    largest, largest_printed = 0.0, 0.0
    for k in range(1, n):
        px, py = p[k, 0], p[k, 1]
        formula = 2 * math.atan2(d, py)
        ax, ay = axis[k - 1, 0] - px, axis[k - 1, 1] - py
        bx, by = axis[k, 0] - px, axis[k, 1] - py
        residual = abs(math.atan2(ax * by - ay * bx, ax * bx + ay * by) - formula)
        cx, cy = axis[k + 1, 0] - px, axis[k + 1, 1] - py
        residual_printed = abs(math.atan2(bx * cy - by * cx, bx * cx + by * cy) - formula)
        largest = running_largest(residual, largest)
        largest_printed = running_largest(residual_printed, largest_printed)
        if store:
            corrected[k - 1] = residual
            printed[k - 1] = residual_printed
    return corrected, printed, largest, largest_printed


#: Outcomes of a block of ``_rotation_blocks``: every angle from its quotient (done), some
#: angle not small (``ROTATION_WRAPPED``: one atan2 each, if none can wrap), or a row off the
#: conditions (``ROTATION_OLD``: the block as before, three atan2 a vertex).
ROTATION_WRAPPED, ROTATION_OLD = 1, 2

#: |im / re| up to this, atan(im / re) rounds to the quotient itself (atan t = t (1 − t²/3 + …),
#: and t²/3 < 2^-55 is below half a unit in the last place); its bit pattern.
ROTATION_SMALL = 2.0**-27
ROTATION_SMALL_BITS = 0x3E40_0000_0000_0000

#: re between these: the products that make re and im lose no relative 2^-100 to underflow
#: (an error of 2^-1074 at most each), and none of them overflows.
ROTATION_LOW, ROTATION_HIGH = 2.0**-900, 2.0**1000


@numba.njit(cache=True, inline="always", error_model="numpy")
def _height_scale(here: Any, count: int) -> float:
    """The power of two that scales w = p^y + i d in a block of the rotation angle (its rows
    ``here`` flat): about 1/p^y at the block's first vertex (exact, so no division a row); inf
    for a subnormal first height, 1 for an empty block."""
    return math.ldexp(1.0, -math.frexp(here[1])[1]) if count else 1.0


@numba.njit(cache=True, inline="always", error_model="numpy")
def _rotation_products(
    u: float, v: float, here: Any, around: Any, j: int
) -> tuple[float, float, float, float, float, float]:
    """(re, im) of z conj(w)² s² for the corrected and the printed angle at p = row j of
    ``here`` (x_{k−1}, x_k, x_{k+1} = rows j, j + 1, j + 2 of ``around``; both flat,
    ``compiled.flat_rows``), u + iv = s w = s (p^y + i d) for a power of two s, and the two dot
    products."""
    px, py = here[2 * j], here[2 * j + 1]
    ax, ay = around[2 * j] - px, around[2 * j + 1] - py
    bx, by = around[2 * j + 2] - px, around[2 * j + 3] - py
    cx, cy = around[2 * j + 4] - px, around[2 * j + 5] - py
    cross, dot = ax * by - ay * bx, ax * bx + ay * by
    cross_printed, dot_printed = bx * cy - by * cx, bx * cx + by * cy
    real, imaginary = (u - v) * (u + v), 2 * u * v  # conj(s w)² = real − i imaginary
    re = dot * real + cross * imaginary
    im = cross * real - dot * imaginary
    re_printed = dot_printed * real + cross_printed * imaginary
    im_printed = cross_printed * real - dot_printed * imaginary
    return re, im, re_printed, im_printed, dot, dot_printed


@numba.njit(cache=True, error_model="numpy")
def _rotation_terms(d: float, p: Any, axis: Any, start: int, stop: int, rows: Any) -> int:
    """Theorem 4's rotation angle at p_k, k = start .. stop − 1, less 2 atan2(d, p_k^y), as
    one argument each: with w = p_k^y + i d, that of z conj(w)², z = a · b + i a × b (corrected:
    a = x_{k−1} − p_k, b = x_k − p_k; printed: b and c = x_{k+1} − p_k), the angle of a product
    being the sum of the angles; w scaled by the power of two nearest the block's first height
    (exact: no division a row). |im / re| to ``rows`` 0 (corrected) and 1 (printed), NaN where
    p_k^y ≤ |d| or re is near under- or overflow. A loop without branches (vectorized by the
    compiler), then the largest bit pattern of each row (``compiled.largest_bits``).

    The outcome: 0 if every |im / re| ≤ ``ROTATION_SMALL`` (then rows 0 and 1 are the residuals:
    atan(im / re) rounds to the quotient, and the argument is the old difference of atan2's:
    with |2 atan2(d, p^y)| < π/2 the difference is within 3π/2 of 0, and so not 2π from a small
    one), ``ROTATION_OLD`` if a row is NaN, else ``ROTATION_WRAPPED``."""
    count = stop - start
    here, around = flat_rows(p, start, count), flat_rows(axis, start - 1, count + 2)  # from 0
    size = abs(d)
    s = _height_scale(here, count)
    if not s < math.inf:  # a subnormal first height: its scale overflows
        return ROTATION_OLD
    v = d * s
    corrected, printed = rows[0], rows[1]
    for j in range(count):
        u = here[2 * j + 1] * s
        re, im, re_printed, im_printed, _, _ = _rotation_products(u, v, here, around, j)
        plain = (here[2 * j + 1] > size) & (re > ROTATION_LOW) & (re < ROTATION_HIGH)
        plain &= (re_printed > ROTATION_LOW) & (re_printed < ROTATION_HIGH)
        t, t_printed = abs(im / re), abs(im_printed / re_printed)
        corrected[j] = t if plain else math.nan
        printed[j] = t_printed if plain else math.nan
    top = max(largest_bits(corrected, count), largest_bits(printed, count))
    if top > INF_BITS:
        return ROTATION_OLD
    return 0 if top <= ROTATION_SMALL_BITS else ROTATION_WRAPPED


@kernel("boolean(float64, float64[:, ::1], float64[:, ::1], int64, int64, float64[:, ::1])")
def _rotation_arguments_wrapped(
    d: float, p: Any, axis: Any, start: int, stop: int, rows: Any
) -> bool:
    """A ``ROTATION_WRAPPED`` block's (re, im) into ``rows`` 0, 1 (corrected) and 2, 3
    (printed), for an atan2 each, as ``_rotation_terms`` scales them: whether none can wrap
    (a · b > 0 and b · c > 0 too: both angles within π/2 of 0, their difference within π) and
    every im is finite."""
    count = stop - start
    here, around = flat_rows(p, start, count), flat_rows(axis, start - 1, count + 2)
    size = abs(d)
    s = _height_scale(here, count)
    v = d * s
    plain = True
    for j in range(count):
        u = here[2 * j + 1] * s
        re, im, re_printed, im_printed, dot, dot_printed = _rotation_products(u, v, here, around, j)
        rows[0, j], rows[1, j], rows[2, j], rows[3, j] = re, im, re_printed, im_printed
        plain &= (here[2 * j + 1] > size) & (dot > 0) & (dot_printed > 0)
        plain &= (re > ROTATION_LOW) & (re < ROTATION_HIGH)
        plain &= (re_printed > ROTATION_LOW) & (re_printed < ROTATION_HIGH)
        plain &= (abs(im) < ROTATION_HIGH) & (abs(im_printed) < ROTATION_HIGH)
    return plain


@kernel(
    "Tuple((int64, float64, float64, int64))(float64, float64[:, ::1], float64[:, ::1], int64, "
    "int64, int64, float64[:, ::1], float64[::1], float64[::1], boolean, float64, float64)"
)
def _rotation_blocks(
    d: float,
    p: Any,
    axis: Any,
    start: int,
    n: int,
    block: int,
    rows: Any,
    corrected: Any,
    printed: Any,
    store: bool,
    largest: float,
    largest_printed: float,
) -> tuple[int, float, float, int]:
    """``_rotation_terms`` block after block from vertex ``start`` while every angle is small:
    the residuals |im / re| (stored if ``store``) and the running largest of each, as the largest
    bit pattern (no NaN there). Stops at the first block that is not: (its first vertex, the
    largest so far, its outcome); (n, …, 0) when done."""
    for first in range(start, n, block):
        stop = min(first + block, n)
        outcome = _rotation_terms(d, p, axis, first, stop, rows)
        if outcome != 0:
            return first, largest, largest_printed, outcome
        m = stop - first
        largest = running_largest(bits_value(largest_bits(rows[0], m)), largest)
        largest_printed = running_largest(bits_value(largest_bits(rows[1], m)), largest_printed)
        if store:
            corrected[first - 1 : stop - 1] = rows[0, :m]
            printed[first - 1 : stop - 1] = rows[1, :m]
    return n, largest, largest_printed, 0


@kernel("UniTuple(float64, 2)(float64[:, ::1], int64, boolean, float64, float64)")
def _rotation_wrapped(
    rows: Any, count: int, libm: bool, largest: float, largest_printed: float
) -> tuple[float, float]:
    """A ``ROTATION_WRAPPED`` block: |atan2(im, re)| into rows 4 and 5 (libm's here if ``libm``,
    else already numpy's there) and the running largest of each (no NaN there)."""
    if libm:
        for j in range(count):
            rows[4, j] = math.atan2(rows[1, j], rows[0, j])
            rows[5, j] = math.atan2(rows[3, j], rows[2, j])
    for j in range(count):
        rows[4, j] = abs(rows[4, j])
        rows[5, j] = abs(rows[5, j])
    largest = running_largest(bits_value(largest_bits(rows[4], count)), largest)
    return largest, running_largest(bits_value(largest_bits(rows[5], count)), largest_printed)


def _rotation_old_block(
    d: float, p: Any, axis: Any, start: int, stop: int, largest: float, largest_printed: float
) -> tuple[Any, Any, float, float]:
    """Vertices start .. stop − 1 as before session 22 (a ``ROTATION_OLD`` block): three atan2
    a vertex, libm's in one pass for fewer than ``ROTATION_LIBM_BELOW``, else on blocks
    (``elementary.atan2``)."""
    m = stop - start
    if m < ROTATION_LIBM_BELOW:
        corrected, printed, top, top_printed = _rotation_angles_libm(
            d, p[start - 1 : stop + 1], axis[start - 1 : stop + 1], m + 1, True
        )
        return corrected, printed, _fold(top, largest), _fold(top_printed, largest_printed)
    rows, angles = np.empty((5, m)), np.empty((3, m))
    _rotation_arguments(p, axis, start, stop, rows)
    elementary.atan2(np.full(m, d), rows[0], out=angles[0])
    elementary.atan2(rows[1], rows[2], out=angles[1])
    elementary.atan2(rows[3], rows[4], out=angles[2])
    largest, largest_printed = _rotation_residuals(
        angles[0], angles[1], angles[2], m, largest, largest_printed
    )
    return angles[1], angles[2], largest, largest_printed


def _fold(value: float, largest: float) -> float:
    """``compiled.running_largest`` in Python (a block's largest into the running one): the
    njit function called from Python would be compiled for it at the first such request, and
    the app compiles only on import (tests/geometry/test_compiled.py)."""
    if largest != largest:
        return largest
    magnitude = abs(value)
    return magnitude if not magnitude <= largest else largest


def _rotation_angles(
    d: float, p: Any, axis: Any, n: int, store: bool, block: int | None = None
) -> tuple[Any, Any, float, float]:
    """Theorem 4's rotation angle at p_i, i = 1 .. n − 1: |angle − 2 atan2(d, p_i^y)| for the
    angle between x_{i−1} − p_i and x_i − p_i (corrected), and for x_i − p_i, x_{i+1} − p_i
    (printed), each angle as ``checks._signed_angle`` defines it. Both arrays stored if
    ``store`` (else empty), and the largest of each (NaN if one is NaN).

    Since session 22 the difference is one argument, not a difference of atan2's: that of
    z conj(w)², z = a · b + i a × b, w = p_i^y + i d (the angle of a product is the sum of the
    angles), and where it is below 2^-27 (every vertex of a true polygon: the residuals are
    rounding) the quotient im / re itself, which atan rounds to: a compiled pass without a
    transcendental call (``_rotation_terms``, ``_rotation_blocks``), in blocks of ``block``
    vertices (``ROTATION_BLOCK``). A block with a larger one takes one atan2 a vertex (numpy's,
    libm's below ``ROTATION_LIBM_BELOW`` vertices); a block where the angles could wrap, or with a
    NaN, an infinity or a product near underflow, is taken as before (three atan2 a vertex,
    ``_rotation_old_block``). The residuals move at rounding level (a few units in the last place
    of the angles, tests/geometry/d4b/test_rotation_rounding.py); points that are not
    C-contiguous are copied first.
    """
    count = max(n - 1, 0)
    block = ROTATION_BLOCK if block is None else block
    p, axis = np.ascontiguousarray(p, dtype=np.float64), np.ascontiguousarray(axis, np.float64)
    corrected = np.empty(count if store else 0)
    printed = np.empty(count if store else 0)
    largest, largest_printed = 0.0, 0.0
    rows = np.empty((6, max(min(block, count), 1)))
    first = 1
    while first < n:
        first, largest, largest_printed, outcome = _rotation_blocks(
            d, p, axis, first, n, block, rows, corrected, printed, store, largest, largest_printed
        )
        if first >= n:
            break
        stop = min(first + block, n)
        m = stop - first
        libm = m < ROTATION_LIBM_BELOW
        if outcome == ROTATION_WRAPPED and not _rotation_arguments_wrapped(
            d, p, axis, first, stop, rows
        ):
            outcome = ROTATION_OLD
        if outcome == ROTATION_WRAPPED:
            if not libm:
                elementary.atan2(rows[1, :m], rows[0, :m], out=rows[4, :m])
                elementary.atan2(rows[3, :m], rows[2, :m], out=rows[5, :m])
            largest, largest_printed = _rotation_wrapped(rows, m, libm, largest, largest_printed)
            found, found_printed = rows[4, :m], rows[5, :m]
        else:
            found, found_printed, largest, largest_printed = _rotation_old_block(
                d, p, axis, first, stop, largest, largest_printed
            )
        if store:
            corrected[first - 1 : stop - 1] = found
            printed[first - 1 : stop - 1] = found_printed
        first = stop
    return corrected, printed, largest, largest_printed


@kernel("float64[:](float64[:, :], float64[:, :])")
def _along(vectors: Any, points: Any) -> Any:
    """``curvature._along`` row by row: |v × e| / (|p_i| + |p_{i+1}|), 1 where v · e < 0."""
    out = np.empty(vectors.shape[0])
    for k in range(vectors.shape[0]):
        ex = points[k + 1, 0] - points[k, 0]
        ey = points[k + 1, 1] - points[k, 1]
        vx, vy = vectors[k, 0], vectors[k, 1]
        size = abs(points[k, 0]) + abs(points[k, 1]) + abs(points[k + 1, 0]) + abs(points[k + 1, 1])
        residual = abs(vx * ey - vy * ex) / size
        out[k] = 1.0 if vx * ex + vy * ey < 0 else residual
    return out


@kernel("float64[:](float64[:, :])")
def _edge_resolution(points: Any) -> Any:
    """``curvature._edge_resolution``: |p_{i+1} − p_i| / (|p_i| + |p_{i+1}|) per edge, the
    length by ``compiled.length``."""
    out = np.empty(max(points.shape[0] - 1, 0))
    for k in range(points.shape[0] - 1):
        ex = points[k + 1, 0] - points[k, 0]
        ey = points[k + 1, 1] - points[k, 1]
        size = abs(points[k, 0]) + abs(points[k, 1]) + abs(points[k + 1, 0]) + abs(points[k + 1, 1])
        out[k] = length(ex, ey) / size
    return out


def rotation_angles(d: float, p: Any, axis: Any, n: int) -> tuple[Any, Any]:
    """(corrected, printed) residuals of Theorem 4's rotation angle at i = 1 .. n − 1."""
    corrected, printed, _, _ = _rotation_angles(float(d), _points(p), _points(axis), n, True)
    return corrected, printed


def rotation_angle_largest(
    d: float, p: Any, axis: Any, n: int, found: tuple[float, float] | None = None
) -> tuple[Largest, float | None]:
    """``rotation_angles`` as the corrected residuals' largest (``checks.Largest``) and the
    printed ones' as ``checks.printed_residual`` reports it, neither stored; ``found``: the two
    largest, computed already (``fused_checks.section_numbers``)."""
    if found is not None:
        largest, printed = found
    else:
        _, _, largest, printed = _rotation_angles(float(d), _points(p), _points(axis), n, False)
    count = max(n - 1, 0)
    corrected = Largest(float(largest), count, lambda: rotation_angles(d, p, axis, n)[0])
    return corrected, (float(printed) if count and math.isfinite(printed) else None)


def along(vectors: Any, points: Any) -> Any:
    """How far unit vectors v_i are from the edges p_i p_{i+1} (``curvature._along``), float64."""
    return _along(_points(vectors), _points(points))


def edge_resolution(points: Any) -> Any:
    """|e_i| / (|p_i| + |p_{i+1}|) per edge (``curvature._edge_resolution``), float64."""
    return _edge_resolution_blocked(_contiguous(points))


def _points(points: Any) -> Any:
    return np.asarray(points, dtype=np.float64)


def point_distance(ar: Arithmetic, a: Array, b: Array) -> Array:
    """``checks.point_distance``: |a_i − b_i| of two ``(m, 2)`` arrays, compiled in float64."""
    if ar.mode != "float64":
        return checks.point_distance(ar, a, b)
    return _distances(_points(a), _points(b))


def relative_point_difference(ar: Arithmetic, computed: Array, expected: Array) -> Array:
    """``checks.relative_point_difference`` (the difference relative to |expected_i|), compiled
    in float64."""
    if ar.mode != "float64":
        return checks.relative_point_difference(ar, computed, expected)
    return _relative_distances(_points(computed), _points(expected), TINY)


def scaled_relative_point_difference(computed: Array, expected: Array, scale: Array) -> Array:
    """Float64: ``relative_point_difference`` times ``scale`` entry by entry, in one pass."""
    return _scaled_relative_distances(
        _points(computed), _points(expected), TINY, np.asarray(scale, dtype=np.float64)
    )


@kernel("float64(float64[:, :], float64[:, :], float64, float64[:], boolean)")
def _largest_scaled_relative_distance(
    computed: Any, expected: Any, tiny: float, scale: Any, scaled: bool
) -> float:
    """max_k of ``_relative_distances`` (times scale_k if ``scaled``, as
    ``_scaled_relative_distances``) without storing them: NaN if one is NaN, as the largest
    magnitude of the array."""
    largest = 0.0
    for k in range(computed.shape[0]):
        ex, ey = expected[k, 0], expected[k, 1]
        size = length(ex, ey)
        size = size if size > tiny else tiny
        value = length(computed[k, 0] - ex, computed[k, 1] - ey) / size
        if scaled:
            value = value * scale[k]
        largest = running_largest(value, largest)
    return largest


_NO_SCALE = np.empty(0)


def largest_scaled_relative_point_difference(
    computed: Array, expected: Array, scale: Array | None
) -> Largest:
    """Float64: the largest ``relative_point_difference`` (times ``scale`` if given, as
    ``scaled_relative_point_difference``) in one pass, the array on demand (``checks.Largest``:
    ``check_residuals`` asks for it only when the largest is not finite)."""
    a, b = _points(computed), _points(expected)
    factors = _NO_SCALE if scale is None else np.asarray(scale, dtype=np.float64)

    def residuals() -> Any:
        if scale is None:
            return _relative_distances(a, b, TINY)
        return _scaled_relative_distances(a, b, TINY, factors)

    value = float(_largest_scaled_relative_distance(a, b, TINY, factors, scale is not None))
    return Largest(value, len(a), residuals)


def largest_relative_point_difference(computed: Array, expected: Array) -> float | None:
    """Float64: the largest ``relative_point_difference`` as ``checks.printed_residual`` reports
    it (None for no rows or a value that is not finite), without the array."""
    if len(computed) == 0:
        return None
    worst = float(
        _largest_scaled_relative_distance(
            _points(computed), _points(expected), TINY, _NO_SCALE, False
        )
    )
    return worst if math.isfinite(worst) else None


# --- the printed Gauss images (18), (19), (20) and the printed (18) from slopes, compared with
# the built ones without storing either: only their largest difference is reported (errata) ---

#: ``_largest_printed_gauss`` kinds: (18), (19), (20) as printed.
PRINTED_18, PRINTED_19, PRINTED_20 = 18, 19, 20


@kernel("float64(int64, float64[:, :], float64[:, :], float64, float64, float64)")
def _largest_printed_gauss(
    kind: int, built: Any, closed: Any, h: float, d: float, tiny: float
) -> float:
    """max_k |built_k − printed_k| / max(|printed_k|, tiny) for the printed (18), (19) or (20)
    (``closed_forms.*_printed``), read off the corrected closed form at the same t = (i + τ)L
    (NaN if one is NaN): (18) printed is (sech t, −tanh t) and ``closed`` n_i = (sech t,
    tanh t); (19) printed (tanh t, sech t) and ``closed`` ñ_i = (−tanh t, sech t); (20)
    printed ((h tanh t − d), h sech t)/(h + d tanh t) from ``closed`` n_i. The same numbers as
    the printed forms evaluated anew (the same operations on the same tanh t and sech t)."""
    largest = 0.0
    for k in range(built.shape[0]):
        if kind == PRINTED_18:
            x, y = closed[k, 0], -closed[k, 1]
        elif kind == PRINTED_19:
            x, y = -closed[k, 0], closed[k, 1]
        else:
            sech, tanh = closed[k, 0], closed[k, 1]
            denominator = h + d * tanh
            x, y = (h * tanh - d) / denominator, h * sech / denominator
        size = length(x, y)
        size = size if size > tiny else tiny
        value = length(built[k, 0] - x, built[k, 1] - y) / size
        largest = running_largest(value, largest)
    return largest


@kernel("float64(int64, float64[:, :])")
def _largest_along_printed_slope(count: int, points: Any) -> float:
    """The largest ``_along`` of the printed (18) from the slopes k of the edges p_k p_{k+1}
    (``closed_forms.normal_from_slope_printed``: (√(1/(1 + k²)), √(k²/(1 + k²)))) against those
    edges, for the first ``count`` edges; NaN if one is NaN."""
    largest = 0.0
    for k in range(count):
        ex = points[k + 1, 0] - points[k, 0]
        ey = points[k + 1, 1] - points[k, 1]
        slope = ey / ex
        vx = math.sqrt(1 / (1 + slope * slope))
        vy = math.sqrt(slope * slope / (1 + slope * slope))
        size = abs(points[k, 0]) + abs(points[k, 1]) + abs(points[k + 1, 0]) + abs(points[k + 1, 1])
        residual = abs(vx * ey - vy * ex) / size
        largest = running_largest(1.0 if vx * ex + vy * ey < 0 else residual, largest)
    return largest


def largest_printed_gauss_difference(
    kind: int, built: Any, closed: Any, h: float, d: float
) -> float | None:
    """The printed residual (``checks.printed_residual``) of the printed (18), (19) or (20)
    against ``built``, the printed form read off the corrected one ``closed`` (n_i for (18) and
    (20), ñ_i for (19), on the same indices): one pass, no arrays."""
    if len(built) == 0:
        return None
    worst = float(
        _largest_printed_gauss(kind, _points(built), _points(closed), float(h), float(d), TINY)
    )
    return worst if math.isfinite(worst) else None


@numba.njit(cache=True, inline="always", error_model="numpy")
def _along_both_rows(
    vectors: Any, points: Any, start: int, stop: int, largest: float, printed: float
) -> tuple[float, float]:
    """``_along`` of ``vectors`` and ``_largest_along_printed_slope`` (erratum E61) on the
    edges start .. stop − 1 in one pass, each edge and its size made once for both, every
    quotient as the two passes make it: the running largest of each (NaN wins)."""
    for k in range(start, stop):
        ex = points[k + 1, 0] - points[k, 0]
        ey = points[k + 1, 1] - points[k, 1]
        size = abs(points[k, 0]) + abs(points[k, 1]) + abs(points[k + 1, 0]) + abs(points[k + 1, 1])
        vx, vy = vectors[k, 0], vectors[k, 1]
        residual = abs(vx * ey - vy * ex) / size
        largest = running_largest(1.0 if vx * ex + vy * ey < 0 else residual, largest)
        slope = ey / ex
        wx = math.sqrt(1 / (1 + slope * slope))
        wy = math.sqrt(slope * slope / (1 + slope * slope))
        residual = abs(wx * ey - wy * ex) / size
        printed = running_largest(1.0 if wx * ex + wy * ey < 0 else residual, printed)
    return largest, printed


def along_largest(
    vectors: Any, points: Any, found: tuple[float, float] | None = None
) -> tuple[Largest, float | None]:
    """Float64: ``along(vectors, points)`` as its largest (``checks.Largest``, the rows made only
    if asked) and ``largest_along_printed_slope(len(vectors), points)``, from one pass (the
    check of (18) by slopes and its erratum E61); ``points`` has len(vectors) + 1 rows or
    more. ``found``: those two, computed already (``fused_checks.image_numbers``)."""
    v, q = _contiguous(vectors), _contiguous(points)
    count = len(v)
    largest, printed = _largest_along_both_blocked(v, q) if found is None else found
    worst = float(printed) if count > 0 and math.isfinite(printed) else None
    return Largest(float(largest), count, lambda: along(v, q[: count + 1])), worst


def largest_along_printed_slope(count: int, points: Any) -> float | None:
    """The printed residual of (18) from the slopes (``curvature.slope_erratum``): the largest
    ``along`` of the printed unit vectors of the first ``count`` edges of ``points``."""
    if count <= 0:
        return None
    worst = float(_largest_along_printed_slope(count, _points(points)))
    return worst if math.isfinite(worst) else None


@kernel("float64(float64[:], float64, float64)")
def _largest_spread(values: Any, mean: float, tiny: float) -> float:
    """max_k |v_k − mean| / max(|mean|, tiny) (``checks.relative_difference`` against the
    constant mean, the largest alone; NaN if one is NaN)."""
    scale = abs(mean)
    scale = scale if scale > tiny else tiny
    largest = 0.0
    for k in range(values.shape[0]):
        largest = running_largest(abs(values[k] - mean) / scale, largest)
    return largest


def ratio_spread(p: Any, found: tuple[int, float, float, float] | None = None) -> float | None:
    """Float64: the printed residual of erratum E2 (the spread of the proof's ratio about its
    mean, ``checks._ratio_erratum``): None for fewer than two ratios, or one not finite.
    ``found``: the ratios' count, numpy's sum of them, their smallest and largest, computed
    already (``fused_checks.section_numbers``)."""
    if found is None:
        summary = _printed_ratio_summary(_contiguous(p))
        count = int(summary[RATIO_COUNT])
        total, low, high = (float(summary[k]) for k in (RATIO_SUM, RATIO_LOW, RATIO_HIGH))
    else:
        count, total, low, high = found
    if count < 2:
        return None
    mean = float(np.float64(total) / count)
    # |v − mean| / scale grows with v on either side of the mean (a rounded difference and a
    # quotient by a positive scale are monotone): its largest is at the smallest or the largest
    # ratio, the same number ``_largest_spread`` finds in a pass with a division per entry
    scale = abs(mean)
    scale = scale if scale > TINY else TINY
    worst = max(abs(high - mean) / scale, abs(low - mean) / scale)
    return worst if math.isfinite(worst) else None


# --- the passes above a block at a time (issue 13, session 21). Each block's residuals are
# computed in a loop without branches that reads the (m, 2) arrays as flat contiguous rows (x_k at
# 2k, y_k at 2k + 1 of a slice starting at the block) or, for the heights of a strided column, a
# contiguous copy of the block; the compiler runs four rows at once in the vector registers (IEEE
# quotients and square roots are correctly rounded in each lane and nothing is contracted, so
# every residual has the bits of the scalar pass). The block is reduced at once: its largest
# magnitude as the largest bit pattern. A block with a NaN or a length off ``compiled.length``'s
# square-root branch is taken again row by row by the scalar pass, so that edge cases keep exactly
# the old behaviour. The scalar kernels above stay the reference (``store`` and the tests). ---

#: Rows a block of the blocked passes (their scratch rows, 8 KB each, stay in the cache).
EDGE_BLOCK = 1024


@numba.njit(cache=True, error_model="numpy")
def _all(flags: Any, count: int) -> bool:
    """Whether flags[j] for every j < count."""
    every = True
    for j in range(count):
        every &= flags[j]
    return every


def _contiguous(points: Any) -> Any:
    """A float64 array, C-contiguous (the blocked passes read its rows as flat entries)."""
    return np.ascontiguousarray(points, dtype=np.float64)


# (18) by slopes and erratum E61 (``_along_both_rows``)


@numba.njit(cache=True, error_model="numpy")
def _along_both_block(v: Any, q: Any, count: int, along: Any, printed: Any) -> None:
    """One block of ``_along_both_rows``' residuals (flat vectors v, flat points q with one row
    more), without branches: the same operations."""
    for j in range(count):
        x0, y0, x1, y1 = q[2 * j], q[2 * j + 1], q[2 * j + 2], q[2 * j + 3]
        ex = x1 - x0
        ey = y1 - y0
        size = abs(x0) + abs(y0) + abs(x1) + abs(y1)
        vx, vy = v[2 * j], v[2 * j + 1]
        residual = abs(vx * ey - vy * ex) / size
        along[j] = 1.0 if vx * ex + vy * ey < 0 else residual
        slope = ey / ex
        wx = math.sqrt(1 / (1 + slope * slope))
        wy = math.sqrt(slope * slope / (1 + slope * slope))
        residual = abs(wx * ey - wy * ex) / size
        printed[j] = 1.0 if wx * ex + wy * ey < 0 else residual


@kernel("UniTuple(float64, 2)(float64[:, ::1], float64[:, ::1])")
def _largest_along_both_blocked(vectors: Any, points: Any) -> tuple[float, float]:
    """``_along_both_rows`` over every edge, a block at a time: the same two largest values."""
    count = vectors.shape[0]
    v, q = vectors.reshape(-1), points.reshape(-1)
    along, printed_rows = np.empty(EDGE_BLOCK), np.empty(EDGE_BLOCK)
    largest, printed = 0.0, 0.0
    for start in range(0, count, EDGE_BLOCK):
        m = min(EDGE_BLOCK, count - start)
        _along_both_block(
            flat_rows(v, start, m), flat_rows(q, start, m + 1), m, along, printed_rows
        )
        top, top_printed = largest_bits(along, m), largest_bits(printed_rows, m)
        if top > INF_BITS or top_printed > INF_BITS:  # a NaN: the block row by row
            largest, printed = _along_both_rows(vectors, points, start, start + m, largest, printed)
        else:
            largest = running_largest(bits_value(top), largest)
            printed = running_largest(bits_value(top_printed), printed)
    return largest, printed


# (20) by inversion (``_pole_inversion``) and (19) as a rotation (``_contact_rotation``)


@numba.njit(cache=True, inline="always", error_model="numpy")
def _pole_inversion_rows(
    gauss: Any, contact: Any, scale: Any, start: int, stop: int, tiny: float, largest: float
) -> float:
    """``_pole_inversion``'s largest on rows start .. stop − 1, from the running largest."""
    for k in range(start, stop):
        largest = running_largest(_pole_inversion_at(gauss, contact, scale, k, tiny), largest)
    return largest


@numba.njit(cache=True, error_model="numpy")
def _pole_inversion_block(
    g: Any, c: Any, s: Any, count: int, tiny: float, out: Any, usual: Any
) -> None:
    """One block of ``_pole_inversion``'s residuals (flat m, flat ñ with one row more, the
    scales), both lengths on the square-root branch (``usual`` says where ``length`` takes it)."""
    for j in range(count):
        ex, ey = inversion_pole(c[2 * j], c[2 * j + 1], c[2 * j + 2], c[2 * j + 3])
        size, plain = fast_length(ex, ey)
        size = size if size > tiny else tiny
        distance, plain_distance = fast_length(g[2 * j] - ex, g[2 * j + 1] - ey)
        out[j] = distance / size * s[j]
        usual[j] = plain & plain_distance


@kernel("float64(float64[:, ::1], float64[:, ::1], float64[::1], int64, float64)")
def _largest_pole_inversion(gauss: Any, contact: Any, scale: Any, count: int, tiny: float) -> float:
    """``_pole_inversion``'s largest (``store`` false) a block at a time: the same number."""
    g, c = gauss.reshape(-1), contact.reshape(-1)
    out = np.empty(EDGE_BLOCK)
    usual = np.empty(EDGE_BLOCK, dtype=np.bool_)
    largest = 0.0
    for start in range(0, count, EDGE_BLOCK):
        m = min(EDGE_BLOCK, count - start)
        s = scale[start : start + m]
        _pole_inversion_block(
            flat_rows(g, start, m), flat_rows(c, start, m + 1), s, m, tiny, out, usual
        )
        top = largest_bits(out, m)
        if top > INF_BITS or not _all(usual, m):
            largest = _pole_inversion_rows(gauss, contact, scale, start, start + m, tiny, largest)
        else:
            largest = running_largest(bits_value(top), largest)
    return largest


@numba.njit(cache=True, inline="always", error_model="numpy")
def _contact_rotation_rows(
    contact: Any, normals: Any, scale: Any, start: int, stop: int, largest: float
) -> float:
    """``_contact_rotation``'s largest on rows start .. stop − 1, from the running largest."""
    for k in range(start, stop):
        largest = running_largest(_contact_rotation_at(contact, normals, scale, k), largest)
    return largest


@numba.njit(cache=True, error_model="numpy")
def _contact_rotation_block(c: Any, nrm: Any, s: Any, count: int, out: Any, usual: Any) -> None:
    """One block of ``_contact_rotation``'s residuals (flat ñ_{k+1}, flat n_k, the scales), the
    length on the square-root branch (``usual`` says where ``length`` takes it)."""
    for j in range(count):
        distance, plain = fast_length(c[2 * j] - (-nrm[2 * j + 1]), c[2 * j + 1] - nrm[2 * j])
        out[j] = distance * s[j]
        usual[j] = plain


@kernel("float64(float64[:, ::1], float64[:, ::1], float64[::1], int64)")
def _largest_contact_rotation(contact: Any, normals: Any, scale: Any, count: int) -> float:
    """``_contact_rotation``'s largest (``store`` false) a block at a time: the same number."""
    c, nrm = contact.reshape(-1), normals.reshape(-1)
    out = np.empty(EDGE_BLOCK)
    usual = np.empty(EDGE_BLOCK, dtype=np.bool_)
    largest = 0.0
    for start in range(0, count, EDGE_BLOCK):
        m = min(EDGE_BLOCK, count - start)
        s = scale[start : start + m]
        _contact_rotation_block(
            flat_rows(c, start + 1, m), flat_rows(nrm, start, m), s, m, out, usual
        )
        top = largest_bits(out, m)
        if top > INF_BITS or not _all(usual, m):
            largest = _contact_rotation_rows(contact, normals, scale, start, start + m, largest)
        else:
            largest = running_largest(bits_value(top), largest)
    return largest


# the edge resolution |e_i| / (|p_i| + |p_{i+1}|) and the pole's (the smaller of consecutive ones)


@numba.njit(cache=True, error_model="numpy")
def _edge_resolution_block(q: Any, count: int, out: Any, usual: Any) -> None:
    """One block of ``_edge_resolution`` (flat points, one row more) into ``out``, the length on
    the square-root branch (``usual``: where ``length`` takes it and the quotient is a number)."""
    for j in range(count):
        x0, y0, x1, y1 = q[2 * j], q[2 * j + 1], q[2 * j + 2], q[2 * j + 3]
        size = abs(x0) + abs(y0) + abs(x1) + abs(y1)
        edge, plain = fast_length(x1 - x0, y1 - y0)
        value = edge / size
        out[j] = value
        usual[j] = plain & (value == value)


@numba.njit(cache=True, inline="always", error_model="numpy")
def _resolutions_into(points: Any, start: int, count: int, out: Any, usual: Any) -> None:
    """``_edge_resolution`` of edges start .. start + count − 1 of C-contiguous points into
    out[:count] (``usual``: count flags of scratch), a loop without branches and the rows off
    the square-root branch, or NaN, made again by the scalar formula. Each entry depends on
    its edge alone: any blocks give the same numbers."""
    _edge_resolution_block(flat_rows(points.reshape(-1), start, count + 1), count, out, usual)
    if _all(usual, count):
        return
    for k in range(start, start + count):
        if not usual[k - start]:
            ex = points[k + 1, 0] - points[k, 0]
            ey = points[k + 1, 1] - points[k, 1]
            size = abs(points[k, 0]) + abs(points[k, 1])
            size = size + abs(points[k + 1, 0]) + abs(points[k + 1, 1])
            out[k - start] = length(ex, ey) / size


@kernel("float64[:](float64[:, ::1])")
def _edge_resolution_blocked(points: Any) -> Any:
    """``_edge_resolution`` a block at a time (``_resolutions_into``): the same array."""
    count = max(points.shape[0] - 1, 0)
    out = np.empty(count)
    usual = np.empty(EDGE_BLOCK, dtype=np.bool_)
    for start in range(0, count, EDGE_BLOCK):
        m = min(EDGE_BLOCK, count - start)
        _resolutions_into(points, start, m, out[start : start + m], usual)
    return out


@kernel(
    "void(float64[:, ::1], float64, int64, int64, float64[::1], float64[::1], float64[::1], "
    "boolean[::1])"
)
def block_resolutions(
    points: Any,
    before: float,
    start: int,
    count: int,
    edges: Any,
    poles: Any,
    scratch: Any,
    usual: Any,
) -> None:
    """The scales of (19) and (20) on rows start .. start + count − 1 without their (n,)
    arrays: the resolutions of the edges p_k p_{k+1} into edges[:count] and the poles' into
    poles[:count], min(r_{k−1}, r_k) with r_{−1} = ``before`` (np.minimum's, NaN if either is):
    the numbers of ``_edge_resolution_blocked`` and ``_pole_resolution`` at those rows.
    ``scratch`` and ``usual`` hold count + 1 entries."""
    if count <= 0:
        return
    if start == 0:
        scratch[0] = before
        _resolutions_into(points, 0, count, scratch[1:], usual)
    else:
        _resolutions_into(points, start - 1, count + 1, scratch, usual)
    for j in range(count):
        edges[j] = scratch[j + 1]
        poles[j] = _minimum(scratch[j], scratch[j + 1])


@kernel("float64[:](float64, float64[::1])")
def _pole_resolution(before: float, resolution: Any) -> Any:
    """min(r_{k−1}, r_k) per edge, r_{−1} = ``before``: ``np.minimum`` of the resolutions
    shifted by one (``before`` first) and the resolutions, NaN where either is NaN, in one
    pass."""
    count = resolution.shape[0]
    out = np.empty(count)
    if count == 0:
        return out
    out[0] = _minimum(before, resolution[0])
    for k in range(1, count):
        out[k] = _minimum(resolution[k - 1], resolution[k])
    return out


def pole_resolution(before: Any, resolution: Any) -> Any:
    """Float64: ``np.minimum(np.concatenate([before, resolution[:-1]]), resolution)`` (the pole
    resolution of (20): the smaller resolution of the two edges at ñ_i), for one ``before`` and
    at least one resolution in one compiled pass, the numpy evaluation otherwise; (r,) → (r,)."""
    first, rows = np.asarray(before, dtype=np.float64), np.asarray(resolution, dtype=np.float64)
    if first.shape == (1,) and rows.ndim == 1 and len(rows) > 0:
        return _pole_resolution(float(first[0]), np.ascontiguousarray(rows))
    return np.minimum(np.concatenate([first, rows[:-1]]), rows)


@numba.njit(cache=True, error_model="numpy")
def _rotation_and_inversion_block(
    q: Any, c: Any, nrm: Any, g: Any, count: int, tiny: float, out: Any, usual: Any
) -> None:
    """One block of ``_rotation_and_inversion_rows`` without branches (flat p and ñ with one row
    more, flat n and m; ``out[0, 0]`` the previous edge's resolution on entry): the edges'
    resolutions into out[0, 1 ..] (``_edge_resolution_block``), (19)'s residuals into out[1],
    (20)'s into out[2]; ``usual`` says where every length is on ``compiled.length``'s
    square-root branch and every resolution a number."""
    resolution, rotated, inverted = out[0], out[1], out[2]
    _edge_resolution_block(q, count, resolution[1:], usual)
    for j in range(count):
        previous, here = resolution[j], resolution[j + 1]
        distance, plain = fast_length(c[2 * j + 2] - (-nrm[2 * j + 1]), c[2 * j + 3] - nrm[2 * j])
        rotated[j] = distance * here
        scale = _minimum(previous, here)
        px, py = inversion_pole(c[2 * j], c[2 * j + 1], c[2 * j + 2], c[2 * j + 3])
        pole, plain_pole = fast_length(px, py)
        pole = pole if pole > tiny else tiny
        distance, plain_distance = fast_length(g[2 * j] - px, g[2 * j + 1] - py)
        inverted[j] = distance / pole * scale
        usual[j] &= plain & plain_pole & plain_distance


@kernel(
    "UniTuple(float64, 2)(float64[:, ::1], float64[:, ::1], float64[:, ::1], float64[:, ::1], "
    "float64[:, ::1], int64, boolean, boolean, float64)"
)
def _rotation_and_inversion_blocked(
    p: Any,
    before: Any,
    contact: Any,
    normals: Any,
    gauss: Any,
    count: int,
    rotation: bool,
    inversion: bool,
    tiny: float,
) -> tuple[float, float]:
    """The largest residuals of (19) as a rotation and (20) by inversion, k = 0 .. count − 1,
    those asked for (0.0 for the other; the edge before the range is ``before``'s one edge):
    ``_rotation_and_inversion_rows`` a block of ``EDGE_BLOCK`` rows at a time (both residuals of
    a block in a loop the compiler vectorizes, ``_rotation_and_inversion_block``; a block with a
    NaN or a length off the square-root branch row by row), the same two numbers, bit for bit."""
    q, c, nrm, g = p.reshape(-1), contact.reshape(-1), normals.reshape(-1), gauss.reshape(-1)
    out = np.empty((3, EDGE_BLOCK + 1))
    usual = np.empty(EDGE_BLOCK, dtype=np.bool_)
    previous = _resolution_before(before)
    largest_rotation, largest_inversion = 0.0, 0.0
    for start in range(0, count, EDGE_BLOCK):
        m = min(EDGE_BLOCK, count - start)
        out[0, 0] = previous
        _rotation_and_inversion_block(
            flat_rows(q, start, m + 1), flat_rows(c, start, m + 1), flat_rows(nrm, start, m),
            flat_rows(g, start, m), m, tiny, out, usual,
        )  # fmt: skip
        top_rotation = largest_bits(out[1], m) if rotation else 0
        top_inversion = largest_bits(out[2], m) if inversion else 0
        if top_rotation > INF_BITS or top_inversion > INF_BITS or not _all(usual, m):
            previous, largest_rotation, largest_inversion = _rotation_and_inversion_rows(
                p, contact, normals, gauss, start, start + m, rotation, inversion, tiny,
                previous, largest_rotation, largest_inversion,
            )  # fmt: skip
            continue
        if rotation:
            largest_rotation = running_largest(bits_value(top_rotation), largest_rotation)
        if inversion:
            largest_inversion = running_largest(bits_value(top_inversion), largest_inversion)
        previous = out[0, m]
    return largest_rotation, largest_inversion


@numba.njit(cache=True, inline="always", error_model="numpy")
def _copy_vector(values: Any, start: int, count: int, out: Any) -> None:
    """values[start .. start + count − 1] into out (a strided column made contiguous; read
    through a slice, whose indices the compiler knows are not negative)."""
    segment = values[start : start + count]
    for j in range(count):
        out[j] = segment[j]


@numba.njit(cache=True, error_model="numpy")
def _copy_heights(q: Any, start: int, count: int, out: Any) -> None:
    """The heights y_start .. y_(start + count − 1) of flat rows q (y_k at 2k + 1) into out.
    A copy the compiler vectorizes (it deinterleaves with shuffles): the blocks that read the
    heights in place, at a stride of two, took gathers (issue 13, session 30)."""
    rows = flat_rows(q, start, count)
    for j in range(count):
        out[j] = rows[2 * j + 1]


# (13) and its two-step form (``_recursions``), the printed two-step form (erratum E3)


@numba.njit(cache=True, inline="always", error_model="numpy")
def _recursion_rows(
    d: float, y: Any, start: int, stop: int, tiny: float, largest_one: float, largest_two: float
) -> tuple[float, float]:
    """``_recursions``' largest values (``store`` false) on k = start .. stop − 1, from the
    running largest of each."""
    n = y.shape[0]
    for k in range(start, stop):
        largest_one = running_largest(_one_step(d, y[k], y[k + 1], y[k + 2], tiny), largest_one)
        if k < n - 3:
            residual = _two_steps(d, y[k], y[k + 1], y[k + 3], tiny)
            largest_two = running_largest(residual, largest_two)
    return largest_one, largest_two


@numba.njit(cache=True, inline="always", error_model="numpy")
def _recursion_pair(
    d: float, a: float, b: float, after: float, later: float, tiny: float
) -> tuple[float, float]:
    """``_recursions``' two residuals at k from a = y_k, b = y_{k+1}, after = y_{k+2} and
    later = y_{k+3}: the same operations."""
    return _one_step(d, a, b, after, tiny), _two_steps(d, a, b, later, tiny)


@numba.njit(cache=True, error_model="numpy")
def _recursion_block(d: float, y: Any, count: int, tiny: float, one: Any, two: Any) -> None:
    """One block of ``_recursions``' residuals from contiguous heights y (count + 3 of them:
    the two-step residual of the last row reads y[count + 2])."""
    for k in range(count):
        one[k], two[k] = _recursion_pair(d, y[k], y[k + 1], y[k + 2], y[k + 3], tiny)


@numba.njit(cache=True, inline="always", error_model="numpy")
def _recursions_blocked(d: float, y: Any, q: Any, paired: bool, tiny: float) -> tuple[float, float]:
    """``_recursions``' two largest values (``store`` false) a block at a time: the same
    numbers. Each block's heights are copied to a contiguous vector, from the odd entries of
    the flat rows q if ``paired`` (y the second column of C-contiguous (n, 2) rows, read by
    ``_copy_heights``), else from y; past the last height it holds 1.0 (the two-step residual
    of the last row of (13) is computed there and left out)."""
    n = y.shape[0]
    count = max(n - 2, 0)
    heights = np.ones(EDGE_BLOCK + 3)
    one, two = np.empty(EDGE_BLOCK), np.empty(EDGE_BLOCK)
    largest_one, largest_two = 0.0, 0.0
    for start in range(0, count, EDGE_BLOCK):
        m = min(EDGE_BLOCK, count - start)
        rows = min(m + 3, n - start)
        if paired:
            _copy_heights(q, start, rows, heights)
        else:
            _copy_vector(y, start, rows, heights)
        heights[rows:] = 1.0
        _recursion_block(d, heights, m, tiny, one, two)
        m_two = min(m, max(n - 3 - start, 0))
        top_one, top_two = largest_bits(one, m), largest_bits(two, m_two)
        if top_one > INF_BITS or top_two > INF_BITS:
            largest_one, largest_two = _recursion_rows(
                d, y, start, start + m, tiny, largest_one, largest_two
            )
        else:
            largest_one = running_largest(bits_value(top_one), largest_one)
            largest_two = running_largest(bits_value(top_two), largest_two)
    return largest_one, largest_two


@kernel("UniTuple(float64, 2)(float64, float64[:], float64)")
def _largest_recursions(d: float, y: Any, tiny: float) -> tuple[float, float]:
    """``_recursions``' two largest values (``store`` false) a block at a time (any heights)."""
    return _recursions_blocked(d, y, np.empty(0), False, tiny)


@kernel("UniTuple(float64, 2)(float64, float64[:, ::1], float64)")
def _largest_recursions_pairs(d: float, points: Any, tiny: float) -> tuple[float, float]:
    """``_largest_recursions`` on the heights of C-contiguous (n, 2) rows, read in place."""
    return _recursions_blocked(d, points[:, 1], points.reshape(-1), True, tiny)


@numba.njit(cache=True, inline="always", error_model="numpy")
def _two_step_printed_pair(
    d2: float, d4: float, a: float, b: float, later: float, tiny: float
) -> float:
    """``_two_step_printed_at`` from a = y_k, b = y_{k+1}, later = y_{k+3}: the same
    operations."""
    aa, bb = a * a, b * b
    b3 = bb * b
    numerator = (
        bb * bb * b
        + d2 * (aa * a + 2 * aa * b + 3 * a * bb + 4 * b3)
        + d4 * (2 * b3 + 2 * a + 3 * b)
    )
    denominator = d2 - a * b
    predicted = numerator / (denominator * denominator)
    scale = abs(predicted)
    return abs(later - predicted) / (scale if scale > tiny else tiny)


@numba.njit(cache=True, error_model="numpy")
def _two_step_printed_block(
    d2: float, d4: float, y: Any, count: int, tiny: float, out: Any
) -> None:
    """One block of ``_two_step_printed_at`` from contiguous heights (count + 3 of them)."""
    for k in range(count):
        out[k] = _two_step_printed_pair(d2, d4, y[k], y[k + 1], y[k + 3], tiny)


@numba.njit(cache=True, inline="always", error_model="numpy")
def _two_step_printed_largest(
    d2: float, d4: float, y: Any, q: Any, paired: bool, tiny: float
) -> float:
    """The largest ``_two_step_printed_at`` (NaN wins) a block at a time (the heights read as
    ``_recursions_blocked`` reads them)."""
    count = max(y.shape[0] - 3, 0)
    heights = np.empty(EDGE_BLOCK + 3)
    out = np.empty(EDGE_BLOCK)
    largest = 0.0
    for start in range(0, count, EDGE_BLOCK):
        m = min(EDGE_BLOCK, count - start)
        if paired:
            _copy_heights(q, start, m + 3, heights)
        else:
            _copy_vector(y, start, m + 3, heights)
        _two_step_printed_block(d2, d4, heights, m, tiny, out)
        top = largest_bits(out, m)
        if top > INF_BITS:
            for k in range(start, start + m):
                largest = running_largest(_two_step_printed_at(d2, d4, y, k, tiny), largest)
        else:
            largest = running_largest(bits_value(top), largest)
    return largest


@kernel("float64(float64, float64, float64[:], float64)")
def _largest_two_step_printed_blocked(d2: float, d4: float, y: Any, tiny: float) -> float:
    """The largest ``_two_step_printed_at`` (NaN wins), a block at a time (any heights)."""
    return _two_step_printed_largest(d2, d4, y, np.empty(0), False, tiny)


@kernel("float64(float64, float64, float64[:, ::1], float64)")
def _largest_two_step_printed_pairs(d2: float, d4: float, points: Any, tiny: float) -> float:
    """``_largest_two_step_printed_blocked`` on the heights of C-contiguous (n, 2) rows, read
    in place."""
    return _two_step_printed_largest(d2, d4, points[:, 1], points.reshape(-1), True, tiny)


def _paired(y: Any) -> Any:
    """C-contiguous float64 (len(y), 2) rows over y's memory whose second column is the vector
    y, when y has a stride of two entries inside one writable contiguous buffer (a column view
    of such rows, as the checks pass the heights p[:, 1]), else None. Only the second column
    is read."""
    owner = y.base if isinstance(y, np.ndarray) else None
    if not (
        isinstance(owner, np.ndarray)
        and owner.flags.c_contiguous
        and owner.flags.writeable
        and y.ndim == 1
        and y.dtype == np.float64
        and y.strides == (16,)
        and len(y) > 0
    ):
        return None
    start = y.__array_interface__["data"][0] - 8 - owner.__array_interface__["data"][0]
    if start < 0 or start % 8 or start + 16 * len(y) > owner.nbytes:
        return None
    return np.ndarray((len(y), 2), dtype=np.float64, buffer=owner, offset=start, strides=(16, 8))


# Nikolaides' right angles (``_right_angles``)


@numba.njit(cache=True, inline="always", error_model="numpy")
def _right_angle_rows(
    tractrix: Any, axis: Any, p: Any, start: int, stop: int, largest: float
) -> float:
    """``_right_angles``' largest on rows start .. stop − 1, from the running largest."""
    for k in range(start, stop):
        largest = running_largest(_right_angle_at(tractrix, axis, p, k), largest)
    return largest


@numba.njit(cache=True, error_model="numpy")
def _right_angle_block(t: Any, a: Any, q: Any, count: int, out: Any) -> None:
    """One block of ``_right_angles``' residuals (flat d_i, x_i, and p_i with one row more),
    without branches."""
    for k in range(count):
        vx, vy = t[2 * k], t[2 * k + 1]
        ax, ay = a[2 * k], a[2 * k + 1]
        ux, uy = ax - vx, ay - vy
        size_a = abs(ax) + abs(ay) + abs(vx) + abs(vy)
        px, py = q[2 * k], q[2 * k + 1]
        wx, wy = px - vx, py - vy
        size_b = abs(px) + abs(py) + abs(vx) + abs(vy)
        at_p = abs(ux * wx + uy * wy) / (size_a * size_b)
        px, py = q[2 * k + 2], q[2 * k + 3]
        wx, wy = px - vx, py - vy
        size_b = abs(px) + abs(py) + abs(vx) + abs(vy)
        at_next = abs(ux * wx + uy * wy) / (size_a * size_b)
        out[k] = at_p if ((at_p >= at_next) | (at_p != at_p)) else at_next


@kernel("float64(float64[:, ::1], float64[:, ::1], float64[:, ::1], int64)")
def _largest_right_angle(tractrix: Any, axis: Any, p: Any, n: int) -> float:
    """``_right_angles``' largest (``store`` false) a block at a time: the same number."""
    t, a, q = tractrix.reshape(-1), axis.reshape(-1), p.reshape(-1)
    out = np.empty(EDGE_BLOCK)
    largest = 0.0
    for start in range(0, n, EDGE_BLOCK):
        m = min(EDGE_BLOCK, n - start)
        _right_angle_block(
            flat_rows(t, start, m), flat_rows(a, start, m), flat_rows(q, start, m + 1), m, out
        )
        top = largest_bits(out, m)
        if top > INF_BITS:
            largest = _right_angle_rows(tractrix, axis, p, start, start + m, largest)
        else:
            largest = running_largest(bits_value(top), largest)
    return largest


# the proof's ratio (erratum E2)


@numba.njit(cache=True, error_model="numpy")
def _edge_lengths_block(q: Any, count: int, out: Any, usual: Any) -> None:
    """|p_{j+1} − p_j| for j < count (flat points) into ``out``, on the square-root branch
    (``usual``)."""
    for j in range(count):
        out[j], usual[j] = fast_length(q[2 * j + 2] - q[2 * j], q[2 * j + 3] - q[2 * j + 1])


@numba.njit(cache=True, error_model="numpy")
def _ratios_block(q: Any, lengths: Any, count: int, out: Any) -> None:
    """The ratios Δ²p^y / (l'_j + l'_{j+1}) of one block into ``out`` (flat points p_j, edge
    lengths l'_j = |p_{j+1} − p_j|)."""
    for j in range(count):
        second = q[2 * j + 7] - 2 * q[2 * j + 5] + q[2 * j + 3]
        out[j] = second / (lengths[j] + lengths[j + 1])


#: Entries of ``_printed_ratio_summary``: the ratios' count, numpy's sum of them, their
#: smallest and largest.
RATIO_COUNT, RATIO_SUM, RATIO_LOW, RATIO_HIGH = 0, 1, 2, 3


#: The bits below the sign: xor'ed into a negative float's pattern, they make the patterns of
#: all floats ordered as the numbers (``_hypothesis_block``, ``_ordered_extremes``).
_ORDER_BITS = 0x7FFF_FFFF_FFFF_FFFF


@numba.njit(cache=True, inline="always", error_model="numpy")
def _ordered_key(pattern: int) -> int:
    """A float's bit pattern as an ordered integer: its lower bits flipped if negative, so that
    the integers order as the numbers (−0 below +0)."""
    return pattern ^ ((pattern >> 63) & _ORDER_BITS)


@numba.njit(cache=True, error_model="numpy")
def _ordered_extremes(values: Any, count: int, low: int, high: int) -> tuple[int, int, bool]:
    """The smallest and largest of values[:count] folded into ``low`` and ``high`` as ordered
    integers (a float's pattern, its lower bits flipped if negative: ordered as the numbers,
    −0 below +0; integer extremes, which the compiler vectorizes) and whether one is NaN."""
    bits = values.view(np.int64)
    nan = False
    for k in range(count):
        key = _ordered_key(bits[k])
        low = key if key < low else low
        high = key if key > high else high
        nan |= values[k] != values[k]
    return low, high, nan


@numba.njit(cache=True, inline="always", error_model="numpy")
def _ordered_value(key: int) -> float:
    """The float of an ordered integer (``_ordered_key``: the flip undoes itself)."""
    return bits_value(_ordered_key(key))


@kernel("float64[::1](float64[:, ::1])")
def _printed_ratio_summary(p: Any) -> Any:
    """The proof's ratio Δ²p_i^y / (l'_i + l'_{i+1}), l'_i = |p_i − p_{i−1}| (erratum E2), as
    ``checks._ratio_erratum`` computes it (entry k from p_k .. p_{k+3}), reduced to what
    ``ratio_spread`` reads: (count, ``np.sum`` of the ratios, bit for bit, smallest, largest;
    both NaN once a ratio is NaN), without an array of them.

    The ratios are made in blocks of whole leaves of numpy's summation tree (≤ ``EDGE_BLOCK``
    entries; leaves of ≤ 128, ``compiled.pairwise_leaves``), each edge's length by the
    square-root branch or, off it, ``compiled.length`` (within 2 ulp of libm's hypot, which
    numpy's evaluation takes: a printed residual, far from rounding level, moves in its last
    bits); each leaf is summed as numpy sums it and the leaves' sums combined in its tree
    (``compiled.leaf_tree``). Until session 30 the pass stored the ratios (8 MB at 10^6
    vertices) and numpy summed them and took their extremes."""
    count = max(p.shape[0] - 3, 0)
    q = p.reshape(-1)
    out = np.zeros(4)
    out[RATIO_COUNT] = count
    if count == 0:
        return out
    leaves = np.empty((count // 64 + 2, 2), dtype=np.int64)
    leaves = leaves[: pairwise_leaves(0, count, leaves, 0)]
    sums = np.zeros((leaves.shape[0], 2))  # the leaves' sums in column 0 (``leaf_tree``)
    lengths, usual = np.empty(EDGE_BLOCK + 1), np.empty(EDGE_BLOCK + 1, dtype=np.bool_)
    ratios = np.empty(EDGE_BLOCK)
    low, high, nan = _ORDER_BITS, -_ORDER_BITS - 1, False
    leaf = 0
    while leaf < leaves.shape[0]:
        start, end, m = leaves[leaf, 0], leaf, 0
        while end < leaves.shape[0] and m + leaves[end, 1] <= EDGE_BLOCK:  # whole leaves
            m += leaves[end, 1]
            end += 1
        # the lengths of edges start .. start + m (edge k is p_k p_{k+1})
        _edge_lengths_block(flat_rows(q, start, m + 2), m + 1, lengths, usual)
        if not _all(usual, m + 1):
            for j in range(m + 1):
                if not usual[j]:
                    k = start + j
                    lengths[j] = length(p[k + 1, 0] - p[k, 0], p[k + 1, 1] - p[k, 1])
        _ratios_block(flat_rows(q, start, m + 3), lengths, m, ratios)
        for row in range(leaf, end):
            sums[row, 0] = pairwise_sum(ratios, leaves[row, 0] - start, leaves[row, 1])
        low, high, seen = _ordered_extremes(ratios, m, low, high)
        nan |= seen
        leaf = end
    out[RATIO_SUM] = 0.0 + leaf_tree(count, sums, np.zeros(1, dtype=np.int64))[0]
    extremes = (math.nan, math.nan) if nan else (_ordered_value(low), _ordered_value(high))
    out[RATIO_LOW], out[RATIO_HIGH] = extremes  # NaN both once one is NaN, as np.min's
    return out


# Theorem 4's hypothesis (``_hypothesis_rows``)


@numba.njit(cache=True, error_model="numpy")
def _hypothesis_block(
    q: Any, count: int, d2: float, violations: Any, ratios: Any
) -> tuple[int, int, bool]:
    """One block of ``_hypothesis_rows`` from flat points (count + 1 rows, the first p_{k−1}): the
    largest bit pattern of the violations (``compiled.largest_bits``), the smallest ratio as an
    ordered integer (a float's pattern, its lower bits flipped if negative: ordered as the
    numbers, −0 below +0) and whether the block is plain (no NaN ratio, no ratio ±0, which
    ``<`` does not tell apart as the integers do)."""
    for k in range(count):
        product = q[2 * k + 1] * q[2 * k + 3]
        excess = d2 - product
        violation = excess if ((excess >= 0.0) | (excess != excess)) else 0.0
        violations[k] = violation / d2
        ratios[k] = product / d2
    bits = ratios.view(np.int64)
    low = _ORDER_BITS  # the largest int64: above every key
    plain = True
    for k in range(count):
        key = _ordered_key(bits[k])
        low = key if key < low else low
        ratio = ratios[k]
        plain &= (ratio == ratio) & (ratio != 0.0)
    return largest_bits(violations, count), low, plain


@kernel("UniTuple(float64, 2)(float64[:, ::1], int64, float64)")
def _hypothesis_blocked(p: Any, n: int, d2: float) -> tuple[float, float]:
    """``_hypothesis_rows`` on k = 1 .. n − 1, a block at a time: the same two numbers."""
    q = p.reshape(-1)
    violations, ratios = np.empty(EDGE_BLOCK), np.empty(EDGE_BLOCK)
    largest, smallest = 0.0, math.inf
    for start in range(1, n, EDGE_BLOCK):
        m = min(EDGE_BLOCK, n - start)
        top, low, plain = _hypothesis_block(
            flat_rows(q, start - 1, m + 1), m, d2, violations, ratios
        )
        if top > INF_BITS or not plain:
            largest, smallest = _hypothesis_rows(p, start, start + m, d2, largest, smallest)
            continue
        largest = running_largest(bits_value(top), largest)
        ratio = _ordered_value(low)
        if smallest == smallest and ratio < smallest:
            smallest = ratio
    return largest, smallest
