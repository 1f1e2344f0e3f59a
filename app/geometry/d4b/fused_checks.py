"""(D4b) float64 at small n: several checks' numbers from one compiled call each.

At 100 vertices a check's own arithmetic takes a few microseconds; what a request paid for was
the calls around it (a numba dispatch, numpy's reductions, temporary arrays), each ≈ 3 µs warm
and far more when the request runs cold after the server's own code. The kernels here do in
one call what took a dozen, calling the same compiled passes (``conditions``) in the same
order, so every number is the same, bit for bit (tests/geometry/test_checks_fused.py).

``fits``: the three least-squares fits of Theorem 4 (i)–(iii) ((D1), (D3), eq. (2)) from one
set of columns, eq. (2)'s misfit with c_(D1)/c_(D3), and the largest residual of each check,
where ``conditions.Columns`` and the check took 13 calls and 6 numpy sums.

``section_numbers``: the numbers of ten checks of Sections 3 and 4.2 (Theorem 4's hypothesis,
rotation angle, fits and erratum E2's ratio, (13) and its two-step form with erratum E3, the
Darboux transform's edge lengths and distances, Nikolaides' right angles) from one call of the
same compiled passes, where each check's own call took one (and, at 100 vertices, ≈ 10–40 µs
of a request in all, mostly the code around each pass: issue 13, session 25).

``image_numbers``: likewise for Section 5 (``curvature``): the resolutions of p's edges and of
the poles, (18) by slopes with erratum E61, (19) as a rotation, (20) by inversion and both
rings (Theorems 7, 8 and (17)), from one call where they took seven.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numba
import numpy as np

from app.geometry import elementary
from app.geometry.compiled import (
    HYPOT_EPS,
    HYPOT_LARGE,
    HYPOT_TINY,
    INF_BITS,
    MAGNITUDE_BITS,
    SQUARES_HIGH,
    SQUARES_LOW,
    _hypot_kernel,
    all_finite_vector,
    bits_value,
    flat_rows,
    float_bits,
    hypot,
    kernel,
    largest_bits,
    largest_of_magnitudes,
    leaf_tree,
    length,
    numpy_sum,
    pairwise_leaves,
    pairwise_sum,
    running_largest,
)
from app.geometry.conditions import (
    TINY,
    ConditionFit,
    _column_scale,
    _fit_scales,
    _fit_terms,
    _misfit_into,
    _shared_columns,
)
from app.geometry.d4b import closed_forms, residual_kernels
from app.geometry.darboux import _distances, _edge_lengths
from app.geometry.precision import BLOCK_SIZE, Arithmetic, Array, Scalar
from app.geometry.surfaces import ring_kernel

if TYPE_CHECKING:
    from app.geometry.d4b.discretization import D4bPolygons


@numba.njit(cache=True, error_model="numpy")
def _fit(
    lhs: Any, lhs_size: Any, r: Any, r_size: Any, paired: bool, out: Any, products: Any
) -> tuple[float, bool]:
    """``conditions._fit_float64`` into ``out`` (its residuals): (constant, whether there is
    one)."""
    lhs_scale, rhs_scale, u_scale, v_scale = _fit_scales(
        lhs, lhs_size, r, paired, TINY, products, out
    )
    _fit_terms(u_scale, v_scale, products, out)
    vv = numpy_sum(out)
    constant, exists = 0.0, False
    if vv > 0:
        constant = numpy_sum(products) / vv * (u_scale / v_scale) * (lhs_scale / rhs_scale)
        exists = True
    _misfit_into(lhs, lhs_size, r, r_size, paired, constant, TINY, out)
    return constant, exists


@kernel(
    "Tuple((float64[::1], float64[::1], float64[::1], float64[::1], float64[::1]))(float64[:, :])"
)
def _fits(p: Any) -> tuple[Any, Any, Any, Any, Any]:
    """(summary, (D1)'s residuals, (D3)'s, eq. (2)'s, eq. (2)'s with its misfit at
    c_(D1)/c_(D3)); summary: the three constants, whether each exists (1.0 or 0.0), and the
    largest residual of (D1), (D3) and eq. (2) with its misfit (``largest_of_magnitudes``)."""
    columns = _shared_columns(p)
    lengths, sizes = np.ascontiguousarray(columns[0]), np.ascontiguousarray(columns[1])
    areas, area_sizes = np.ascontiguousarray(columns[2]), np.ascontiguousarray(columns[3])
    second, second_sizes = np.ascontiguousarray(columns[4]), np.ascontiguousarray(columns[5])
    inner, edges = second.shape[0], lengths.shape[0]
    d1, d3, eq2 = np.empty(inner), np.empty(edges), np.empty(inner)
    scratch = np.empty(max(inner, edges))
    c1, has1 = _fit(second, second_sizes, lengths, sizes, True, d1, scratch[:inner])
    c3, has3 = _fit(areas, area_sizes, lengths, sizes, False, d3, scratch[:edges])
    c2, has2 = _fit(second, second_sizes, areas, area_sizes, True, eq2, scratch[:inner])
    both = eq2.copy()
    if has1 and has3 and c3 != 0 and inner > 0:  # ``checks._equation_2``
        misfit = scratch[:inner]
        _misfit_into(second, second_sizes, areas, area_sizes, True, c1 / c3, TINY, misfit)
        for k in range(inner):  # np.maximum: NaN wins
            a, b = both[k], misfit[k]
            both[k] = a if (a != a or a >= b) else b
    summary = np.empty(9)
    summary[0], summary[1], summary[2] = c1, c3, c2
    summary[3] = 1.0 if has1 else 0.0
    summary[4] = 1.0 if has3 else 0.0
    summary[5] = 1.0 if has2 else 0.0
    summary[6] = largest_of_magnitudes(d1) if inner else 0.0
    summary[7] = largest_of_magnitudes(d3) if edges else 0.0
    summary[8] = largest_of_magnitudes(both) if inner else 0.0
    return summary, d1, d3, eq2, both


# --- the fits' summary without their columns: four passes over p in blocks; of size n only l ---

#: Edges a block of the summary passes holds (its columns ≈ 100 KB, in cache while read). Every
#: loop over a block runs on one-dimensional buffers, which the compiler vectorizes.
FIT_BLOCK = 1024


@numba.njit(cache=True, error_model="numpy")
def _block_columns(p: Any, k0: int, buffers: Any, first: bool, lengths: Any) -> tuple[int, int]:
    """The points k0, k0 + 1, … of a block (up to FIT_BLOCK + 1 edges, FIT_BLOCK inner
    vertices) as columns x and y of ``buffers`` (``_buffers``); returns (edges, inner vertices).

    ``first`` (pass 1): also A, l and Δ²y of ``conditions._shared_columns`` into ``buffers``,
    each entry computed as there, and l into ``lengths`` (one entry an edge of p): glibc's hypot
    in its unscaled range for every edge (``compiled._hypot_kernel``, the same operations), then
    libm's whole ``hypot`` for those outside that range. The later passes read the lengths from
    ``lengths`` and compute the other columns in their own loops (``_area`` …): the same numbers
    without a square root and a division an edge, nor a column written and read back."""
    x, y, dx, dy = buffers[0], buffers[1], buffers[2], buffers[3]
    area, edge, second = buffers[4], buffers[5], buffers[8]
    n = p.shape[0]
    edges = min(FIT_BLOCK + 1, max(n - 1 - k0, 0))
    inner = min(FIT_BLOCK, max(n - 2 - k0, 0))
    points = edges + 1 if edges else 0
    rows = flat_rows(p, k0, points)  # C-contiguous p: the copy vectorizes
    for j in range(points):
        x[j] = rows[2 * j]
        y[j] = rows[2 * j + 1]
    if first:
        if _edge_columns(x, y, dx, dy, area, edge, edges):
            for j in range(edges):
                a, b = abs(dx[j]), abs(dy[j])
                big, small = (a, b) if a >= b else (b, a)
                if not (big <= HYPOT_LARGE and small >= HYPOT_TINY):
                    edge[j] = hypot(dx[j], dy[j])
        for j in range(edges):
            lengths[k0 + j] = edge[j]
        for j in range(inner):
            second[j] = _second(y, j)
    return edges, inner


@numba.njit(cache=True, inline="always", error_model="numpy")
def _area(x: Any, y: Any, j: int) -> float:
    """A_j = (y_j + y_{j+1}) / 2 · (x_{j+1} − x_j), as ``_shared_columns`` computes it."""
    return (y[j] + y[j + 1]) / 2 * (x[j + 1] - x[j])


@numba.njit(cache=True, inline="always", error_model="numpy")
def _area_size(x: Any, y: Any, j: int) -> float:
    """|A_j|~ = (|y_j| + |y_{j+1}|) / 2 · (|x_j| + |x_{j+1}|), as ``_shared_columns``."""
    return (abs(y[j]) + abs(y[j + 1])) / 2 * (abs(x[j]) + abs(x[j + 1]))


@numba.njit(cache=True, inline="always", error_model="numpy")
def _size(x: Any, y: Any, j: int) -> float:
    """|l_j|~ = |x_j| + |y_j| + |x_{j+1}| + |y_{j+1}|, as ``_shared_columns``."""
    return abs(x[j]) + abs(y[j]) + abs(x[j + 1]) + abs(y[j + 1])


@numba.njit(cache=True, inline="always", error_model="numpy")
def _second(y: Any, j: int) -> float:
    """Δ²y_j = y_{j+2} − 2 y_{j+1} + y_j, as ``_shared_columns``."""
    return y[j + 2] - 2 * y[j + 1] + y[j]


@numba.njit(cache=True, inline="always", error_model="numpy")
def _second_size(y: Any, j: int) -> float:
    """|Δ²y_j|~ = |y_{j+2}| + 2 |y_{j+1}| + |y_j|, as ``_shared_columns``."""
    return abs(y[j + 2]) + 2 * abs(y[j + 1]) + abs(y[j])


@numba.njit(cache=True, error_model="numpy")
def _edge_columns(x: Any, y: Any, dx: Any, dy: Any, area: Any, edge: Any, count: int) -> bool:
    """A_k and the unscaled hypot of the edges 0 .. count − 1 of (x, y) (a + b where b ≤ 2^-54
    a, as ``hypot`` has it: on a long polygon's steep ends most edges); whether an edge is
    outside hypot's unscaled range (or not finite)."""
    outside = 0
    for j in range(count):
        x0, y0, x1, y1 = x[j], y[j], x[j + 1], y[j + 1]
        area[j] = (y0 + y1) / 2 * (x1 - x0)
        dx[j], dy[j] = x1 - x0, y1 - y0
        a, b = abs(x1 - x0), abs(y1 - y0)
        big, small = (a, b) if a >= b else (b, a)
        edge[j] = big + small if small <= big * HYPOT_EPS else _hypot_kernel(big, small)
        inside = big <= HYPOT_LARGE and small >= HYPOT_TINY
        outside += 0 if inside else 1
    return outside > 0


@numba.njit(cache=True, error_model="numpy")
def _buffers(edges: int) -> Any:
    """The block buffers of a polygon with ``edges`` edges: x, y (up to FIT_BLOCK + 2 points),
    dx, dy and the six columns, then the six terms of the sums (``_fill_terms``).

    As wide as its largest block: a short polygon's fits take a few KiB instead of the 16 ×
    (FIT_BLOCK + 2) floats of a long one's. Those are just over glibc's mmap threshold as the
    server sets it (128 KiB, ``MALLOC_MMAP_THRESHOLD_``): where the heap has no free chunk that
    large (in the served worker, three calls in four) each call mapped them, faulted their pages
    in and unmapped them (docs/performance.md, issue 13, session 26)."""
    return np.empty((16, min(edges, FIT_BLOCK) + 2))


@numba.njit(cache=True, inline="always", error_model="numpy")
def _weight(size: float) -> float:
    """``fit``'s weight of an equation: its left side's magnitude, at least the tiniest normal."""
    return size if size > TINY else TINY


@numba.njit(cache=True, inline="always", error_model="numpy")
def _scale_of(big: Any, nan: Any, at: int) -> float:
    """``_column_scale`` of the largest magnitude whose bits are big[at], and of whether a NaN
    was seen (nan[at])."""
    return _column_scale(big.view(np.float64)[at], nan[at])


#: Positions in ``_summary_passes``'s scale vector: the column scales of the first pass (Δ²y
#: serves (D1) and eq. (2) alike), then those of u and v (u of Δ²y again shared).
_S_SECOND, _S_PAIRED_L, _S_AREA, _S_L, _S_PAIRED_A = 0, 1, 2, 3, 4
_S_U, _S_V1, _S_U3, _S_V3, _S_V2 = 5, 6, 7, 8, 9

#: Where the scale vector holds 1/s of scale k (``_INVERSE + k``) and whether the terms are
#: taken by reciprocals (``_BY_RECIPROCALS``: 1.0 or 0.0; ``_ratio_scales``).
_INVERSE, _BY_RECIPROCALS = 10, 20

#: Scales whose reciprocals the terms multiply by: 1/s is then normal and finite, and x·(1/s)
#: within an ulp or so of x/s wherever that is normal (``_ratio_scales``).
RECIPROCAL_LOW, RECIPROCAL_HIGH = 2.0**-1000, 2.0**1000


@numba.njit(cache=True, inline="always", error_model="numpy")
def _scan_step(largest: int, seen: int, value: float) -> Any:
    """One value folded into ``_scan``'s two maxima of magnitudes' bit patterns
    (``MAGNITUDE_BITS``): (the largest of the non-NaN, the largest of all; above ``INF_BITS``
    once a NaN was seen). Integer maxima, which the compiler vectorizes."""
    magnitude = np.int64(float_bits(value) & np.uint64(MAGNITUDE_BITS))
    return max(largest, magnitude if magnitude <= INF_BITS else 0), max(seen, magnitude)


@numba.njit(cache=True, inline="always", error_model="numpy")
def _scan(values: Any, count: int, big: Any, nan: Any, at: int) -> None:
    """Fold max |v| of the non-NaN v of values[:count] (as bits: ``MAGNITUDE_BITS``) into big[at],
    and whether a v is NaN into nan[at]: ``_largest``'s result, found as integers."""
    largest, seen = big[at], 0
    for j in range(count):
        largest, seen = _scan_step(largest, seen, values[j])
    big[at] = largest
    nan[at] |= seen > INF_BITS


@numba.njit(cache=True, inline="always", error_model="numpy")
def _fold(values: Any, count: int, worst: Any, at: int) -> None:
    """``running_largest`` over values[:count] from worst[at], as bits (``MAGNITUDE_BITS``): the
    largest magnitude, or bits above ``INF_BITS`` (a NaN) once a value is NaN."""
    bits = values.view(np.int64)
    largest = worst[at]
    for j in range(count):
        largest = max(largest, bits[j] & MAGNITUDE_BITS)
    worst[at] = largest


@numba.njit(cache=True, error_model="numpy")
def _first_pass(buffers: Any, edges: int, inner: int, big: Any, nan: Any) -> None:
    """Pass 1 on a block: the largest |Δ²y|, |l_k + l_{k+1}|, |A|, |l|, |A_k + A_{k+1}| into
    ``big`` (NaN seen into ``nan``), at the positions of their scales (``_S_*``); then the
    largest |u| and |v| of the fits before their column scales (Δ²y / w, (l_k + l_{k+1}) / w …
    as the products with 1/w) at 10 + the positions of u's and v's scales.

    Two loops, one over the edges and one over the inner vertices, each computing its values
    and folding them at once (``_scan_step``, as ``_scan`` folds a stored column): the same
    values, so the same maxima."""
    x, y = buffers[0], buffers[1]
    area, edge, second = buffers[4], buffers[5], buffers[8]
    l_area, l_edge, l_u3, l_v3 = big[_S_AREA], big[_S_L], big[10 + _S_U3], big[10 + _S_V3]
    s_area = s_edge = s_u3 = s_v3 = 0
    for j in range(edges):
        by_weight = 1.0 / _weight(_area_size(x, y, j))
        l_area, s_area = _scan_step(l_area, s_area, area[j])
        l_edge, s_edge = _scan_step(l_edge, s_edge, edge[j])
        l_u3, s_u3 = _scan_step(l_u3, s_u3, area[j] * by_weight)
        l_v3, s_v3 = _scan_step(l_v3, s_v3, edge[j] * by_weight)
    big[_S_AREA], big[_S_L], big[10 + _S_U3], big[10 + _S_V3] = l_area, l_edge, l_u3, l_v3
    nan[_S_AREA] |= s_area > INF_BITS
    nan[_S_L] |= s_edge > INF_BITS
    nan[10 + _S_U3] |= s_u3 > INF_BITS
    nan[10 + _S_V3] |= s_v3 > INF_BITS
    l_second, l_pl, l_pa = big[_S_SECOND], big[_S_PAIRED_L], big[_S_PAIRED_A]
    l_u, l_v1, l_v2 = big[10 + _S_U], big[10 + _S_V1], big[10 + _S_V2]
    s_second = s_pl = s_pa = s_u = s_v1 = s_v2 = 0
    for j in range(inner):
        by_weight = 1.0 / _weight(_second_size(y, j))
        paired_l, paired_a = edge[j] + edge[j + 1], area[j] + area[j + 1]
        l_second, s_second = _scan_step(l_second, s_second, second[j])
        l_pl, s_pl = _scan_step(l_pl, s_pl, paired_l)
        l_pa, s_pa = _scan_step(l_pa, s_pa, paired_a)
        l_u, s_u = _scan_step(l_u, s_u, second[j] * by_weight)
        l_v1, s_v1 = _scan_step(l_v1, s_v1, paired_l * by_weight)
        l_v2, s_v2 = _scan_step(l_v2, s_v2, paired_a * by_weight)
    big[_S_SECOND], big[_S_PAIRED_L], big[_S_PAIRED_A] = l_second, l_pl, l_pa
    big[10 + _S_U], big[10 + _S_V1], big[10 + _S_V2] = l_u, l_v1, l_v2
    nan[_S_SECOND] |= s_second > INF_BITS
    nan[_S_PAIRED_L] |= s_pl > INF_BITS
    nan[_S_PAIRED_A] |= s_pa > INF_BITS
    nan[10 + _S_U] |= s_u > INF_BITS
    nan[10 + _S_V1] |= s_v1 > INF_BITS
    nan[10 + _S_V2] |= s_v2 > INF_BITS


@numba.njit(cache=True, error_model="numpy")
def _second_pass(
    buffers: Any, edge: Any, edges: int, inner: int, scales: Any, big: Any, nan: Any
) -> None:
    """Pass 2 on a block (its points in ``buffers``, its edges' lengths ``edge``): the largest
    |u| and |v| of the three fits (``_fit_scales``'s second loop, u of Δ²y shared by (D1) and
    eq. (2)) into ``big``, ``nan`` (``_S_U`` … ``_S_V2``); the quotients first into buffers (a
    loop the compiler vectorizes, the columns computed in it), then their largest."""
    x, y = buffers[0], buffers[1]
    u, v1, v2, u3, v3 = buffers[10], buffers[11], buffers[12], buffers[13], buffers[14]
    s_second, s_pl, s_area = scales[_S_SECOND], scales[_S_PAIRED_L], scales[_S_AREA]
    s_l, s_pa = scales[_S_L], scales[_S_PAIRED_A]
    for j in range(edges):
        weight = _weight(_area_size(x, y, j))
        u3[j] = _area(x, y, j) / s_area / weight
        v3[j] = edge[j] / s_l / weight
    for j in range(inner):
        weight = _weight(_second_size(y, j))
        u[j] = _second(y, j) / s_second / weight
        v1[j] = (edge[j] + edge[j + 1]) / s_pl / weight
        v2[j] = (_area(x, y, j) + _area(x, y, j + 1)) / s_pa / weight
    _scan(u3, edges, big, nan, _S_U3)
    _scan(v3, edges, big, nan, _S_V3)
    _scan(u, inner, big, nan, _S_U)
    _scan(v1, inner, big, nan, _S_V1)
    _scan(v2, inner, big, nan, _S_V2)


@numba.njit(cache=True, error_model="numpy")
def _fill_terms(p: Any, k0: int, scales: Any, buffers: Any, lengths: Any) -> tuple[int, int]:
    """The terms of the fits' sums (``_fit_terms``'s v² and u·v) on the equations k0, k0 + 1,
    … of a block: (D1)'s and eq. (2)'s into ``buffers[10:14]``, (D3)'s into ``buffers[14:16]``;
    returns how many of each ((D1) and eq. (2), (D3)).

    By reciprocals (``_ratio_scales``): u = Δ²y · (1/w) · (1/U), U the largest |Δ²y · (1/w)|
    (pass 1), and so on, one division a row; else each computed as ``_fit_scales`` and
    ``_fit_terms`` compute it (nine quotients a row of (D1) and eq. (2), seven of (D3))."""
    edges, inner = _block_columns(p, k0, buffers, False, lengths)
    edges = min(edges, FIT_BLOCK)
    x, y, edge = buffers[0], buffers[1], buffers[5]
    for j in range(min(edges + 1, lengths.shape[0] - k0)):
        edge[j] = lengths[k0 + j]
    t0, t1, t2, t3 = buffers[10], buffers[11], buffers[12], buffers[13]
    t4, t5 = buffers[14], buffers[15]
    area, area_size = buffers[4], buffers[6]  # first: a loop of divisions reading them vectorizes
    for j in range(max(edges, inner + 1 if inner else 0)):  # A_j of both kinds of rows
        area[j], area_size[j] = _area(x, y, j), _area_size(x, y, j)
    if scales[_BY_RECIPROCALS] != 0:
        inverse = scales[_INVERSE:]
        i_u, i_v1, i_v2 = inverse[_S_U], inverse[_S_V1], inverse[_S_V2]
        for j in range(inner):
            by_weight = 1.0 / _weight(_second_size(y, j))
            u_k = _second(y, j) * by_weight * i_u
            v1 = (edge[j] + edge[j + 1]) * by_weight * i_v1
            v2 = (area[j] + area[j + 1]) * by_weight * i_v2
            t0[j] = v1 * v1
            t1[j] = u_k * v1
            t2[j] = v2 * v2
            t3[j] = u_k * v2
        i_u3, i_v3 = inverse[_S_U3], inverse[_S_V3]
        for j in range(edges):
            by_weight = 1.0 / _weight(area_size[j])
            v3 = edge[j] * by_weight * i_v3
            t4[j] = v3 * v3
            t5[j] = area[j] * by_weight * i_u3 * v3
        return inner, edges
    s_second, s_pl, s_pa = scales[_S_SECOND], scales[_S_PAIRED_L], scales[_S_PAIRED_A]
    s_u, s_v1, s_v2 = scales[_S_U], scales[_S_V1], scales[_S_V2]
    for j in range(inner):
        weight = _weight(_second_size(y, j))
        u_k = _second(y, j) / s_second / weight / s_u
        v1 = (edge[j] + edge[j + 1]) / s_pl / weight / s_v1
        v2 = (_area(x, y, j) + _area(x, y, j + 1)) / s_pa / weight / s_v2
        t0[j] = v1 * v1
        t1[j] = u_k * v1
        t2[j] = v2 * v2
        t3[j] = u_k * v2
    s_area, s_l, s_u3, s_v3 = scales[_S_AREA], scales[_S_L], scales[_S_U3], scales[_S_V3]
    for j in range(edges):
        weight = _weight(area_size[j])
        v3 = edge[j] / s_l / weight / s_v3
        t4[j] = v3 * v3
        t5[j] = area[j] / s_area / weight / s_u3 * v3
    return inner, edges


@numba.njit(cache=True, error_model="numpy")
def _refill(
    p: Any, k0: int, scales: Any, buffers: Any, lengths: Any, window: Any, leaves: Any, sums: Any
) -> None:
    """The terms of the block from k0 (``_fill_terms``), then the sums of (D3)'s leaves that lie
    in it, in order (window: first index, end of (D1)'s terms, end of (D3)'s, next leaf)."""
    inner, edges = _fill_terms(p, k0, scales, buffers, lengths)
    window[0], window[1], window[2] = k0, k0 + inner, k0 + edges
    at = window[3]
    while at < leaves.shape[0]:
        first, count = leaves[at, 0], leaves[at, 1]
        if first < k0 or first + count > k0 + edges:
            break
        sums[at, 0] = pairwise_sum(buffers[14], first - k0, count)
        sums[at, 1] = pairwise_sum(buffers[15], first - k0, count)
        at += 1
    window[3] = at


@kernel(
    "UniTuple(float64, 4)(float64[:, ::1], int64, int64, float64[::1], float64[:, ::1], "
    "float64[::1], int64[::1], int64[:, ::1], float64[:, ::1])"
)
def _tree_sums(
    p: Any,
    start: int,
    count: int,
    scales: Any,
    buffers: Any,
    lengths: Any,
    window: Any,
    leaves: Any,
    sums: Any,
) -> tuple[float, float, float, float]:
    """numpy's pairwise sums (``pairwise_sum``'s tree) of (D1)'s and eq. (2)'s terms start ..
    start + count − 1 (``_fill_terms``). The leaves (≤ 128 terms) are read from the term
    buffers, refilled (``_refill``) from a leaf's first term, or from the first of (D3)'s
    leaves still to sum if that is before it, when the leaf is not in them (leaves come left to
    right); each refill also sums (D3)'s leaves ``leaves`` it holds into ``sums``."""
    if count == 0:
        return 0.0, 0.0, 0.0, 0.0
    if count <= 128:
        if start < window[0] or start + count > window[1]:
            k0 = start
            if window[3] < leaves.shape[0]:
                k0 = min(k0, leaves[window[3], 0])
            _refill(p, k0, scales, buffers, lengths, window, leaves, sums)
        at = start - window[0]
        first, second = pairwise_sum(buffers[10], at, count), pairwise_sum(buffers[11], at, count)
        third, fourth = pairwise_sum(buffers[12], at, count), pairwise_sum(buffers[13], at, count)
        return first, second, third, fourth
    half = count // 2
    half -= half % 8
    a = _tree_sums(p, start, half, scales, buffers, lengths, window, leaves, sums)
    b = _tree_sums(p, start + half, count - half, scales, buffers, lengths, window, leaves, sums)
    return a[0] + b[0], a[1] + b[1], a[2] + b[2], a[3] + b[3]


#: A residual |lhs − c·rhs| / d whose numerator is below b·d, b = (1 − 2^-40) times the largest
#: residual so far (b·d rounded, and normal), is at most that largest: b·d ≤ (1 − 2^-40)(1 +
#: 2^-53)² × largest × d, so the quotient is below the largest before its rounding, which keeps
#: it there (rounding is monotone; the largest is a float). NaN (numerator or bound) fails the
#: test, as does a bound of 0 (nothing seen yet) or a subnormal one (rounded by more than 2^-53).
_BELOW = 1.0 - 2.0**-40


@numba.njit(cache=True, inline="always", error_model="numpy")
def _may_raise(numerator: float, scale: float, bound: float) -> int:
    """1 unless ``numerator / max(scale, TINY)`` is certainly at most the largest residual so
    far (``_BELOW``; bound = (1 − 2^-40) × that largest): a test without a division."""
    below = bound * (scale if scale > TINY else TINY)
    return 0 if ((numerator < below) & (below >= TINY)) else 1


@numba.njit(cache=True, error_model="numpy")
def _fourth_pass(buffers: Any, edge: Any, edges: int, inner: int, c: Any, worst: Any) -> None:
    """Pass 4 on a block (its points in ``buffers``, its edges' lengths ``edge``): the largest
    residual of (D1), (D3) and eq. (2) (with its misfit at c_(D1)/c_(D3) when c[3] is 1) into
    ``worst`` (``_misfit_into``, then ``largest_of_magnitudes`` of eq. (2)'s maximum with its
    misfit, NaN winning), as bits (``_fold``).

    Most residuals cannot raise the largest so far: a loop without divisions (``_may_raise``)
    counts those that might, by check; only a check with one computes the block's residuals (a
    loop the compiler vectorizes, with the same operations as ``_misfit_into``) and folds their
    largest in. ``_fold`` is an integer maximum, so the skipped residuals change no bit."""
    x, y = buffers[0], buffers[1]
    r3, r1, r2, misfit = buffers[10], buffers[11], buffers[12], buffers[13]
    c1, c3, c2, ratio, c_ratio = c[0], c[1], c[2], c[3] != 0, c[4]
    largest = worst.view(np.float64)
    b1, b3, b2 = largest[0] * _BELOW, largest[1] * _BELOW, largest[2] * _BELOW
    raise3 = 0
    for j in range(edges):
        scale = _area_size(x, y, j) + abs(c3) * _size(x, y, j)
        raise3 += _may_raise(abs(_area(x, y, j) - c3 * edge[j]), scale, b3)
    raise1, raise2, raise_misfit = 0, 0, 0
    for j in range(inner):  # the misfit's test too, counted only with a ratio (c[3])
        second, second_size = _second(y, j), _second_size(y, j)
        scale = second_size + abs(c1) * (_size(x, y, j) + _size(x, y, j + 1))
        raise1 += _may_raise(abs(second - c1 * (edge[j] + edge[j + 1])), scale, b1)
        paired, paired_size = (
            _area(x, y, j) + _area(x, y, j + 1),
            _area_size(x, y, j) + _area_size(x, y, j + 1),
        )
        scale = second_size + abs(c2) * paired_size
        raise2 += _may_raise(abs(second - c2 * paired), scale, b2)
        scale = second_size + abs(c_ratio) * paired_size
        raise_misfit += _may_raise(abs(second - c_ratio * paired), scale, b2)
    if ratio:
        raise2 += raise_misfit
    if raise3:
        for j in range(edges):
            scale = _area_size(x, y, j) + abs(c3) * _size(x, y, j)
            r3[j] = abs(_area(x, y, j) - c3 * edge[j]) / (scale if scale > TINY else TINY)
        _fold(r3, edges, worst, 1)
    if raise1:
        for j in range(inner):
            scale = _second_size(y, j) + abs(c1) * (_size(x, y, j) + _size(x, y, j + 1))
            residual = abs(_second(y, j) - c1 * (edge[j] + edge[j + 1]))
            r1[j] = residual / (scale if scale > TINY else TINY)
        _fold(r1, inner, worst, 0)
    if raise2:
        for j in range(inner):
            paired, paired_size = (
                _area(x, y, j) + _area(x, y, j + 1),
                _area_size(x, y, j) + _area_size(x, y, j + 1),
            )
            scale = _second_size(y, j) + abs(c2) * paired_size
            r2[j] = abs(_second(y, j) - c2 * paired) / (scale if scale > TINY else TINY)
        _fold(r2, inner, worst, 2)
        if ratio:  # np.maximum of eq. (2)'s residual and its misfit, NaN winning: both folded
            for j in range(inner):
                paired, paired_size = (
                    _area(x, y, j) + _area(x, y, j + 1),
                    _area_size(x, y, j) + _area_size(x, y, j + 1),
                )
                scale = _second_size(y, j) + abs(c_ratio) * paired_size
                misfit[j] = abs(_second(y, j) - c_ratio * paired) / (
                    scale if scale > TINY else TINY
                )
            _fold(misfit, inner, worst, 2)


@numba.njit(cache=True, inline="always", error_model="numpy")
def _constant(uv: float, vv: float, scales: Any, lhs: int, rhs: int, u: int, v: int) -> Any:
    """``_fit``'s constant from its two sums (``numpy_sum``: from +0.0) and its four scales:
    (constant, whether there is one)."""
    uv, vv = 0.0 + uv, 0.0 + vv
    if vv > 0:
        return uv / vv * (scales[u] / scales[v]) * (scales[lhs] / scales[rhs]), True
    return 0.0, False


@numba.njit(cache=True, error_model="numpy")
def _ratio_scales(big: Any, nan: Any, scales: Any) -> bool:
    """Whether the terms are taken by reciprocals: no ratio of pass 1 NaN and the largest of
    each (U, V: the largest |u| and |v| before the column scales) in [RECIPROCAL_LOW,
    RECIPROCAL_HIGH]; then U and V become the scales of u and v, their reciprocals beside them
    (``_INVERSE``).

    The fits' constants do not depend on the scales: c = Σ u v / Σ v² · (s_u s_lhs) / (s_v s_rhs)
    for any positive scales, and s_lhs · s_u is the largest |lhs / w| as U is, to rounding. So
    u = (lhs · 1/w) · 1/U is ``_fit_scales``'s (lhs / s_lhs / w) / s_u to a few ulp, without
    pass 2 (the scales of u and v) and with one division a row instead of up to nine; the
    constants move by a few ulp of the sums (tests/geometry/d4b/test_fits_rounding.py). Any
    other polygon (a NaN, an infinite or zero column, ratios beyond 2^±1000) keeps the
    quotients, which give ``_fits``'s bits."""
    for k in range(5, 10):
        value = big.view(np.float64)[10 + k]
        if nan[10 + k] or not (RECIPROCAL_LOW <= value <= RECIPROCAL_HIGH):
            return False
    for k in range(5, 10):
        value = big.view(np.float64)[10 + k]
        scales[k], scales[_INVERSE + k] = value, 1.0 / value
    return True


@numba.njit(cache=True, inline="always", error_model="numpy")
def _ratio_constant(uv: float, vv: float, scales: Any, u: int, v: int) -> Any:
    """``_constant`` of terms taken by reciprocals: Σ u v / Σ v² · U / V (``_ratio_scales``)."""
    uv, vv = 0.0 + uv, 0.0 + vv
    if vv > 0:
        return uv / vv * (scales[u] / scales[v]), True
    return 0.0, False


@numba.njit(cache=True, error_model="numpy")
def _summary_body(p: Any, lengths: Any) -> Any:
    """``_fits``'s summary (its first array) without its columns and residuals: four passes
    over p in blocks of FIT_BLOCK edges, each computing the columns it reads from the
    coordinates (``_block_columns``, ``_area`` …) with the same operations on each entry as
    ``_fit_scales``, ``_fit_terms`` and ``_misfit_into``, the edges' lengths once (pass 1
    writes them to ``lengths``, one entry an edge of p); the sums by ``pairwise_sum``'s tree
    (``_tree_sums``), the largest values as ``largest_of_magnitudes``. Pass 2 (the scales of u
    and v) only where the terms cannot be taken by reciprocals (``_ratio_scales``): there every
    number has the bits of ``_fits``'s, elsewhere the constants are within a few ulp of their
    sums' rounding and the largest residuals move with them (tests/geometry/fit_rounding.py)."""
    n = p.shape[0]
    edges, inner = max(n - 1, 0), max(n - 2, 0)
    buffers = _buffers(edges)
    big, nan = np.zeros(20, dtype=np.int64), np.zeros(20, dtype=np.bool_)
    scales = np.zeros(21)  # the ten scales, their reciprocals, whether those are taken
    for k0 in range(0, edges, FIT_BLOCK):  # pass 1: the columns' scales, the ratios' largest
        block, block_inner = _block_columns(p, k0, buffers, True, lengths)
        _first_pass(buffers, min(block, FIT_BLOCK), block_inner, big, nan)
    for k in range(5):
        scales[k] = _scale_of(big, nan, k)
    by_reciprocals = _ratio_scales(big, nan, scales)
    scales[_BY_RECIPROCALS] = 1.0 if by_reciprocals else 0.0
    if not by_reciprocals:
        for k0 in range(0, edges, FIT_BLOCK):  # pass 2: the scales of u and v
            block, block_inner = _block_columns(p, k0, buffers, False, lengths)
            edge = lengths[k0 : k0 + block]
            _second_pass(buffers, edge, min(block, FIT_BLOCK), block_inner, scales, big, nan)
        for k in range(5, 10):
            scales[k] = _scale_of(big, nan, k)
    # pass 3: the sums, in numpy's order; (D3)'s leaves from the same blocks as the others'
    leaves = np.empty((edges // 64 + 2, 2), dtype=np.int64)
    leaves = leaves[: pairwise_leaves(0, edges, leaves, 0) if edges else 0]
    sums = np.empty((leaves.shape[0], 2))
    window = np.zeros(4, dtype=np.int64)
    vv1, uv1, vv2, uv2 = _tree_sums(p, 0, inner, scales, buffers, lengths, window, leaves, sums)
    while window[3] < leaves.shape[0]:  # (D3)'s last leaves, past (D1)'s equations
        _refill(p, leaves[window[3], 0], scales, buffers, lengths, window, leaves, sums)
    vv3, uv3 = leaf_tree(edges, sums, np.zeros(1, dtype=np.int64))
    if by_reciprocals:
        c1, has1 = _ratio_constant(uv1, vv1, scales, _S_U, _S_V1)
        c3, has3 = _ratio_constant(uv3, vv3, scales, _S_U3, _S_V3)
        c2, has2 = _ratio_constant(uv2, vv2, scales, _S_U, _S_V2)
    else:
        c1, has1 = _constant(uv1, vv1, scales, _S_SECOND, _S_PAIRED_L, _S_U, _S_V1)
        c3, has3 = _constant(uv3, vv3, scales, _S_AREA, _S_L, _S_U3, _S_V3)
        c2, has2 = _constant(uv2, vv2, scales, _S_SECOND, _S_PAIRED_A, _S_U, _S_V2)
    ratio = has1 and has3 and c3 != 0 and inner > 0
    constants = np.array([c1, c3, c2, 1.0 if ratio else 0.0, c1 / c3 if ratio else 0.0])
    worst = np.zeros(3, dtype=np.int64)  # the bits of the largest residuals (``_fold``)
    for k0 in range(0, edges, FIT_BLOCK):  # pass 4: the largest residuals
        block, block_inner = _block_columns(p, k0, buffers, False, lengths)
        edge = lengths[k0 : k0 + block]
        _fourth_pass(buffers, edge, min(block, FIT_BLOCK), block_inner, constants, worst)
    summary = np.empty(9)
    summary[0], summary[1], summary[2] = c1, c3, c2
    summary[3] = 1.0 if has1 else 0.0
    summary[4] = 1.0 if has3 else 0.0
    summary[5] = 1.0 if has2 else 0.0
    largest = worst.view(np.float64)
    summary[6], summary[7], summary[8] = largest[0], largest[1], largest[2]
    return summary


@kernel("float64[::1](float64[:, ::1], float64[::1])")
def _summary_passes(p: Any, lengths: Any) -> Any:
    """``_summary_body`` of a C-contiguous polygon (its blocks' copies read its rows flat:
    ``compiled.flat_rows``)."""
    return _summary_body(p, lengths)


def fits_summary(p: Array) -> Any:
    """The fits' summary of the float64 polygon ``p`` ((m, 2)): ``_fits``'s first array (to
    rounding, ``_ratio_scales``), with one array of size m − 1 (the edges' lengths) instead of
    ``_fits``'s columns and residuals (``_summary_passes``). A pure function of ``p`` that
    releases the GIL: ``d4b.checks`` runs it on a second thread at large m."""
    lengths = np.empty(max(len(p) - 1, 0))  # the edges' lengths, written by the first pass
    return _summary_passes(np.ascontiguousarray(p, dtype=np.float64), lengths)


def fits_arrays(p: Array) -> tuple[Any, Any, Any, Any, Any]:
    """``_fits``: the summary and the per-equation residuals (``detail``); pure, as
    ``fits_summary``."""
    return _fits(p)


class Fits:
    """Theorem 4 (i)–(iii) of one float64 polygon from one compiled call (``_summary_passes``,
    or ``_fits`` when the residuals are wanted).

    ``constants`` are the three fitted constants (numpy floats, ``None`` where there is none),
    ``largest`` the largest residual of each check by its key (``"d1"``, ``"d3"``, ``"eq2"``:
    the last with eq. (2)'s misfit at c_(D1)/c_(D3)) and ``counts`` its number of equations;
    ``fits`` (the three ``ConditionFit`` of ``conditions.Columns``, the same constants and
    residuals) and ``equation_2`` (eq. (2)'s residuals with the misfit, as
    ``checks._equation_2`` takes them) are computed when first read. ``found`` is what
    ``fits_summary`` or ``fits_arrays`` gave for ``p``, when it was computed elsewhere.
    """

    __slots__ = ("_arrays", "_p", "constants", "counts", "largest")

    def __init__(self, p: Array, found: Any = None) -> None:
        if found is None:
            found = fits_summary(p)
        self._p = p
        self._arrays: tuple[Any, Any, Any, Any, Any] | None = None
        if isinstance(found, tuple):
            self._arrays = found
            found = found[0]
        summary = found.tolist()  # Python floats, as a check's residual is
        keys = ("d1", "d3", "eq2")
        self.constants = {
            key: np.float64(summary[k]) if summary[k + 3] else None for k, key in enumerate(keys)
        }
        self.largest = {key: summary[6 + k] for k, key in enumerate(keys)}
        inner, edges = max(len(p) - 2, 0), max(len(p) - 1, 0)
        self.counts = {"d1": inner, "d3": edges, "eq2": inner}

    def _residuals(self) -> tuple[Any, Any, Any, Any, Any]:
        if self._arrays is None:
            self._arrays = fits_arrays(self._p)
        return self._arrays

    @property
    def fits(self) -> dict[str, ConditionFit]:
        """The three fits with their residuals (``_fits``'s arrays, computed once), each with
        the constant its residuals were computed with (``_fits``'s: without ``detail`` the
        summary's ``constants`` may differ from it by a few ulp, ``_ratio_scales``)."""
        summary, d1, d3, eq2, _ = self._residuals()
        own = summary.tolist()
        found = {"d1": d1, "d3": d3, "eq2": eq2}
        return {
            key: ConditionFit(np.float64(own[k]) if own[k + 3] else None, found[key])
            for k, key in enumerate(found)
        }

    @property
    def equation_2(self) -> Any:
        """Eq. (2)'s residuals with its misfit at c_(D1)/c_(D3) (``np.maximum``)."""
        return self._residuals()[4]


@kernel("float64[::1](int64, int64, float64, float64)")
def _closed_arguments(i_min: int, i_max: int, L: float, shift: float) -> Any:
    """The hyperbolic functions' arguments of the five closed forms, one after the other, each
    computed as ``closed_forms`` computes it: (14)'s i·L + (τ − ½)L and (16)'s i·L + τL on
    i_min .. i_max + 1, (19)'s (i + τ)L on i_min − 1 .. i_max + 1 (whose last n + 1 are (18)'s),
    (20)'s (i − ½ + τ)L on i_min .. i_max + 1."""
    rows = i_max - i_min + 2
    out = np.empty(4 * rows + 1)
    offset_p, offset_t = (shift - 0.5) * L, shift * L
    for k in range(rows):
        i = float(i_min + k)
        u = i * L
        out[k] = u + offset_p
        out[rows + k] = u + offset_t
        out[3 * rows + 1 + k] = (i - 0.5 + shift) * L
    for k in range(rows + 1):
        out[2 * rows + k] = (float(i_min - 1 + k) + shift) * L
    return out


@kernel(
    "void(int64, int64, float64[::1], float64[::1], float64[::1], float64, float64, float64, "
    "float64, boolean, boolean, int64, float64[:, ::1], float64[:, ::1], float64[:, ::1], "
    "float64[:, ::1], float64[:, ::1])"
)
def _closed_points(
    i_min: int,
    i_max: int,
    cosh: Any,
    sinh: Any,
    tanh: Any,
    h: float,
    d: float,
    amplitude: float,
    gauss_amplitude: float,
    kinematic: bool,
    images: bool,
    offset: int,
    p: Any,
    tractrix: Any,
    normal: Any,
    contact: Any,
    gauss: Any,
) -> None:
    """The closed forms on i_min .. i_max + 1 (ñ from i_min − 1) from the hyperbolic functions
    of ``_closed_arguments`` (cosh of all, sinh of (16)'s, tanh of (19)'s and (20)'s), by the
    operations of ``closed_forms``, into rows ``offset`` .. of p and the tractrix (if
    ``kinematic``) and of n, ñ, m (if ``images``; ñ's first row is index i_min − 1)."""
    rows = i_max - i_min + 2
    step = 2 * d
    for k in range(rows):
        i = float(i_min + k)
        at = offset + k
        if kinematic:
            x = i * step
            p[at, 0] = x - d
            p[at, 1] = amplitude * cosh[k]
            sech = 1 / cosh[rows + k]
            tractrix[at, 0] = x - h * (sinh[k] * sech)
            tractrix[at, 1] = h * sech
        if images:
            normal[at, 0] = 1.0 / cosh[2 * rows + 1 + k]
            normal[at, 1] = tanh[1 + k]
            gauss[at, 0] = -tanh[rows + 1 + k]
            gauss[at, 1] = gauss_amplitude / cosh[3 * rows + 1 + k]
    if images:
        for k in range(rows + 1):
            contact[offset + k, 0] = -tanh[k]
            contact[offset + k, 1] = 1.0 / cosh[2 * rows + k]


_CLOSED_KINEMATIC = frozenset({"closed_p", "closed_tractrix"})
#: The closed forms of (18), (19), (20) on ``GaussImages``.
CLOSED_IMAGES = frozenset({"closed_tractrix_gauss", "closed_contact", "closed_gauss"})


def fill_closed_forms(data: D4bPolygons, images: bool = True, kinematic: bool = True) -> None:
    """Float64: Theorems 5, 6 (``kinematic``) and (18)–(20)'s (``images``) closed forms of
    ``data`` from the C library's cosh, sinh and tanh (``elementary``, which the float64
    arithmetic of ``closed_forms`` calls, so the same bits; a contiguous slice of an argument
    array gives each entry the bits the separate array gave) and one compiled call, a block of
    ``BLOCK_SIZE`` indices at a time (the arguments and the hyperbolic functions of a block stay
    in the cache; each point is written once, into its polygon), kept as if each had been
    computed on its own; those computed already stay. Nothing is kept when a cosh overflows
    (``closed_forms`` has its other branch for those)."""
    rows = data.vertices
    # those all there already (e.g. method=closed-form's polygons and companions) are not redone
    kinematic = kinematic and not vars(data).keys() >= _CLOSED_KINEMATIC
    images = images and not vars(data.gauss).keys() >= CLOSED_IMAGES
    if not (images or kinematic) or rows == 0:
        return
    ar, h, d = data.ar, float(data.h), float(data.d)
    L = float(closed_forms.log_ratio(ar, data.h, data.d))
    shift = float(data.shift)
    amplitude = float(ar.sqrt((data.h - data.d) * (data.h + data.d)))
    gauss_amplitude = float(data.h / ar.sqrt((data.h - data.d) * (data.h + data.d)))
    wide, tall = (rows, 2) if kinematic else (0, 2), (rows, 2) if images else (0, 2)
    p, tractrix = np.empty(wide), np.empty(wide)
    normal, gauss = np.empty(tall), np.empty(tall)
    contact = np.empty((rows + 1, 2) if images else (0, 2))
    block = min(rows, BLOCK_SIZE)
    cosh, sinh, tanh = np.empty(4 * block + 1), np.empty(block), np.empty(2 * block + 1)
    for start in range(0, rows, block):
        count = min(block, rows - start)  # indices i_min + start .. + count − 1
        first = data.i_min + start
        arguments = _closed_arguments(first, first + count - 2, L, shift)
        # cosh of (14)'s and (16)'s arguments if kinematic, of (19)'s and (20)'s if images
        lo, hi = (0 if kinematic else 2 * count), (4 * count + 1 if images else 2 * count)
        elementary.cosh_into(arguments[lo:hi], cosh[lo:hi])  # libm's bits, inf on overflow
        if not all_finite_vector(cosh[lo:hi]):
            return
        if kinematic:
            elementary.sinh(arguments[count : 2 * count], out=sinh[:count])
        if images:
            elementary.tanh(arguments[2 * count :], out=tanh[: 2 * count + 1])
        _closed_points(
            first,
            first + count - 2,
            cosh,
            sinh,
            tanh,
            h,
            d,
            amplitude,
            gauss_amplitude,
            kinematic,
            images,
            start,
            p,
            tractrix,
            normal,
            contact,
            gauss,
        )
    if kinematic:
        kept = data.__dict__
        kept.setdefault("closed_p", p)
        kept.setdefault("closed_tractrix", tractrix)
    if images:
        kept = data.gauss.__dict__
        kept.setdefault("closed_tractrix_gauss", normal)
        kept.setdefault("closed_contact", contact)
        kept.setdefault("closed_gauss", gauss)


@kernel(
    "UniTuple(float64, 2)(float64[:, :], float64[:, :], float64[:, :], float64[:, :], "
    "float64[:, :], int64, float64, float64, boolean, boolean)"
)
def _closed_comparisons(
    p: Any,
    closed_p: Any,
    tractrix: Any,
    closed_tractrix: Any,
    axis: Any,
    n: int,
    h: float,
    tiny: float,
    theorem_5_wanted: bool,
    theorem_6_wanted: bool,
) -> tuple[float, float]:
    """The largest residuals of Theorems 5 and 6 on rows 0 .. n − 1, as ``checks._closed_form``
    computes them (``residual_kernels``' relative point difference; the point distance over
    |x_i| + h floored at ``tiny``), without the arrays: NaN if one is NaN; 0.0 for a theorem
    not wanted (its polygons are not read)."""
    theorem_5 = theorem_6 = 0.0
    for k in range(n):
        if theorem_5_wanted:
            ex, ey = closed_p[k, 0], closed_p[k, 1]
            size = length(ex, ey)
            size = size if size > tiny else tiny
            theorem_5 = running_largest(length(p[k, 0] - ex, p[k, 1] - ey) / size, theorem_5)
        if theorem_6_wanted:
            distance = length(
                tractrix[k, 0] - closed_tractrix[k, 0], tractrix[k, 1] - closed_tractrix[k, 1]
            )
            scale = abs(axis[k, 0]) + h
            scale = scale if scale > tiny else tiny
            theorem_6 = running_largest(abs(distance) / scale, theorem_6)
    return theorem_5, theorem_6


_NO_POINTS = np.empty((0, 2))
_NO_ENTRIES = np.empty(0)


@numba.njit(cache=True, inline="always", error_model="numpy")
def _on_fast_path(x: float, y: float) -> bool:
    """Whether ``length(x, y)`` is √(x² + y²): max(|x|, |y|) inside its moderate range, or
    both zero (then both give +0); false for a NaN. Without branches."""
    ax, ay = abs(x), abs(y)
    below = (ax < SQUARES_HIGH) & (ay < SQUARES_HIGH)
    return below & ((ax > SQUARES_LOW) | (ay > SQUARES_LOW) | ((ax == 0.0) & (ay == 0.0)))


@numba.njit(cache=True, inline="always", error_model="numpy")
def _all_finite(values: Any, start: int, stop: int) -> bool:
    """``all_finite_vector(values[start:stop])`` without branches (the compiler vectorizes it)."""
    finite = True
    for k in range(start, stop):
        finite &= abs(values[k]) < np.inf
    return finite


@kernel("void(int64, int64, float64, float64, float64[::1])")
def _kinematic_arguments(first: int, count: int, L: float, shift: float, out: Any) -> None:
    """(14)'s i·L + (τ − ½)L into ``out[:count]`` and (16)'s i·L + τL into ``out[count:2count]``
    for i = first .. first + count − 1, as ``_closed_arguments`` computes them."""
    offset_p, offset_t = (shift - 0.5) * L, shift * L
    for k in range(count):
        u = float(first + k) * L
        out[k] = u + offset_p
        out[count + k] = u + offset_t


@kernel("void(int64, int64, float64, float64, float64[::1])")
def _image_arguments(first: int, count: int, L: float, shift: float, out: Any) -> None:
    """(19)'s (i + τ)L for i = first − 1 .. first + count − 1 into ``out[:count + 1]`` and (20)'s
    (i − ½ + τ)L for i = first .. first + count − 1 into ``out[count + 1:2count + 1]``, as
    ``_closed_arguments`` computes them."""
    for k in range(count + 1):
        out[k] = (float(first - 1 + k) + shift) * L
    for k in range(count):
        out[count + 1 + k] = (float(first + k) - 0.5 + shift) * L


#: The largest |t| whose closed forms the blocks make from w = e^(−|t|) (``_sech_tanh``): w stays
#: a normal number there, 1/w and cosh t finite. The C library's cosh overflows only past
#: 710.47, so a block within the limit is one the old path would not have refused; a block with
#: an argument beyond it (or a NaN) takes the old path, ``elementary.cosh`` and its None on
#: overflow.
DECAY_LIMIT = 700.0


@numba.njit(cache=True, inline="always", error_model="numpy")
def _within(lowest: float, highest: float) -> bool:
    """Whether the arguments of a run, from ``lowest`` to ``highest`` (t rises or falls with the
    index: float(i)·L and the offset's addition are rounded monotonically, so the ends are its
    largest magnitudes), all have |t| ≤ ``DECAY_LIMIT``; false for a NaN."""
    return (abs(lowest) <= DECAY_LIMIT) & (abs(highest) <= DECAY_LIMIT)


@kernel("boolean(int64, int64, float64, float64, float64[::1])")
def _kinematic_decays(first: int, count: int, L: float, shift: float, out: Any) -> bool:
    """−|t| for (14)'s and (16)'s arguments t as ``_kinematic_arguments`` computes them, into
    ``out[:count]`` and ``out[count:2count]`` (``elementary.exp_into`` then makes w =
    e^(−|t|) of them), and whether every |t| ≤ ``DECAY_LIMIT``, for each of the two."""
    offset_p, offset_t = (shift - 0.5) * L, shift * L
    for k in range(count):
        u = float(first + k) * L
        out[k] = -abs(u + offset_p)
        out[count + k] = -abs(u + offset_t)
    last = float(first + count - 1) * L
    return _within(float(first) * L + offset_p, last + offset_p) & _within(
        float(first) * L + offset_t, last + offset_t
    )


@kernel("boolean(int64, int64, float64, float64, float64[::1])")
def _image_decays(first: int, count: int, L: float, shift: float, out: Any) -> bool:
    """−|t| for (19)'s and (20)'s arguments t as ``_image_arguments`` computes them, into
    ``out[:count + 1]`` and ``out[count + 1:2count + 1]`` (``elementary.exp_into`` then makes w =
    e^(−|t|)), and whether every |t| ≤ ``DECAY_LIMIT``."""
    for k in range(count + 1):
        out[k] = -abs((float(first - 1 + k) + shift) * L)
    for k in range(count):
        out[count + 1 + k] = -abs((float(first + k) - 0.5 + shift) * L)
    return _within((float(first - 1) + shift) * L, (float(first + count - 1) + shift) * L) & (
        _within((float(first) - 0.5 + shift) * L, (float(first + count - 1) - 0.5 + shift) * L)
    )


@numba.njit(cache=True, inline="always", error_model="numpy")
def _sech_tanh(t: float, w: float) -> tuple[float, float]:
    """(sech t, tanh t) from w = e^(−|t|), |t| ≤ ``DECAY_LIMIT``, in the fraction form the paper
    gives (18) in (with w = ((h − d)/(h + d))^i): 2w/(1 + w²) and ±(1 − w)(1 + w)/(1 + w²) with
    the sign of t, one division. 1 − w is exact for w ≥ ½ (near t = 0, where tanh is small), so
    tanh's error there is w's, about an ulp of 1: the scale of the unit vectors it makes. No
    branch (the loops calling it vectorize)."""
    r = 1.0 / (1.0 + w * w)
    return 2.0 * w * r, math.copysign((1.0 - w) * (1.0 + w) * r, t)


#: The squares of ``SQUARES_LOW`` and ``SQUARES_HIGH``: a sum of squares between them is normal
#: and its square root within an ulp or two of hypot's.
SQUARE_LOW, SQUARE_HIGH = SQUARES_LOW**2, SQUARES_HIGH**2


@numba.njit(cache=True, inline="always", error_model="numpy")
def _usual(square: float) -> bool:
    """Whether a sum of squares (a squared length or scale) already computed is 0 or between
    2^−960 and 2^960, false for a NaN: a three-comparison stand-in for ``_on_fast_path`` on its
    components. It admits less at the top; at the bottom it also admits a length whose
    components are both below 2^−537 (their squares underflow to 0): a length of at most 2^−536
    taken as 0, below an ulp of any residual's scale here (a scale's square of 0 is not a
    denominator's: a zero denominator gives an infinite or NaN square, which sends the block
    back). Without branches."""
    return (square < SQUARE_HIGH) & ((square > SQUARE_LOW) | (square == 0.0))


@kernel(
    "Tuple((boolean, float64, float64))(int64, int64, float64, float64, float64[::1], float64, "
    "float64, float64, float64[::1], float64[::1], float64[::1], int64, int64, boolean, boolean, "
    "float64, float64, float64[:, ::1])"
)
def _kinematic_block_from_decays(
    first: int,
    count: int,
    L: float,
    shift: float,
    decays: Any,
    h: float,
    d: float,
    amplitude: float,
    p: Any,
    tractrix: Any,
    axis: Any,
    offset: int,
    n: int,
    theorem_5_wanted: bool,
    theorem_6_wanted: bool,
    theorem_5: float,
    theorem_6: float,
    scratch: Any,
) -> tuple[bool, float, float]:
    """One block of Theorems 5 and 6's comparisons (indices first .. first + count − 1, rows
    ``offset`` .., those below ``n``; w = e^(−|t|) of (14)'s arguments t at ``[:count]``, of
    (16)'s at ``[count:2count]``, every |t| ≤ ``DECAY_LIMIT``; t's sign as
    ``_kinematic_arguments`` computes t), folded into the running largest of each
    theorem: (False, the largest given) when a row needs the old path.

    The closed forms from one exponential a row: (14)'s y = √(h² − d²)·cosh t with cosh t =
    (1/w + w)/2, (16)'s point (x − h·tanh t, h·sech t) by ``_sech_tanh``. No square root a row:
    Theorem 5's residual |p − p̃|/|p̃| is the root of (|p − p̃|²/|p̃|²) and Theorem 6's
    |d − d̃|/(|a_x| + h) the root of |d − d̃|²/(|a_x| + h)², so each block keeps the largest
    square (an integer maximum of bit patterns) and takes one square root of it (√ is monotone
    and correctly rounded: the root of the largest square is the largest root). The rounding
    moves at the last bits of the residuals (tests/test_golden.py, session 22). A NaN, an
    infinite or out-of-range square (a squared length or scale not ``_usual``, a zero closed
    point) sends the block back."""
    rows = min(count, n - offset)
    if rows <= 0:
        return True, theorem_5, theorem_6
    step = 2 * d
    plain = True
    values_5, values_6 = scratch[0], scratch[1]
    top_5 = top_6 = 0
    if theorem_5_wanted:
        block_w, block_p = decays[:rows], p[2 * offset : 2 * (offset + rows)]
        for k in range(rows):
            w = block_w[k]
            ex, ey = float(first + k) * step - d, amplitude * (0.5 / w + 0.5 * w)
            dx, dy = block_p[2 * k] - ex, block_p[2 * k + 1] - ey
            distance, size = dx * dx + dy * dy, ex * ex + ey * ey
            values_5[k] = distance / size
            plain &= _usual(distance) & _usual(size)
        top_5 = largest_bits(values_5, rows)
    if theorem_6_wanted:
        block_w, offset_t = decays[count : count + rows], shift * L
        block_d = tractrix[2 * offset : 2 * (offset + rows)]
        block_axis = axis[2 * offset : 2 * (offset + rows)]
        for k in range(rows):
            sech, th = _sech_tanh(float(first + k) * L + offset_t, block_w[k])
            tx, ty = float(first + k) * step - h * th, h * sech
            dx, dy = block_d[2 * k] - tx, block_d[2 * k + 1] - ty
            scale = abs(block_axis[2 * k]) + h
            distance, scale = dx * dx + dy * dy, scale * scale
            values_6[k] = distance / scale
            plain &= _usual(distance) & _usual(scale)
        top_6 = largest_bits(values_6, rows)
    if not (plain and top_5 < INF_BITS and top_6 < INF_BITS):
        return False, theorem_5, theorem_6
    if theorem_5_wanted:
        theorem_5 = running_largest(math.sqrt(bits_value(top_5)), theorem_5)
    if theorem_6_wanted:
        theorem_6 = running_largest(math.sqrt(bits_value(top_6)), theorem_6)
    return True, theorem_5, theorem_6


@numba.njit(cache=True, error_model="numpy")
def _kinematic_rows(
    first: int,
    count: int,
    rows: int,
    cosh: Any,
    sinh: Any,
    h: float,
    d: float,
    amplitude: float,
    p: Any,
    tractrix: Any,
    axis: Any,
    offset: int,
    tiny: float,
    theorem_5_wanted: bool,
    theorem_6_wanted: bool,
    theorem_5: float,
    theorem_6: float,
) -> tuple[float, float]:
    """The old row loop of ``_closed_kinematic_block`` on ``rows`` rows of a block (cosh of (14)
    at ``[:count]``, of (16) at ``[count:]``): lengths with hypot's branch, NaN first."""
    step = 2 * d
    for k in range(rows):
        at = offset + k
        x = float(first + k) * step
        if theorem_5_wanted:
            ex, ey = x - d, amplitude * cosh[k]
            size = length(ex, ey)
            size = size if size > tiny else tiny
            residual = length(p[2 * at] - ex, p[2 * at + 1] - ey) / size
            theorem_5 = running_largest(residual, theorem_5)
        if theorem_6_wanted:
            sech = 1 / cosh[count + k]
            tx, ty = x - h * (sinh[k] * sech), h * sech
            distance = length(tractrix[2 * at] - tx, tractrix[2 * at + 1] - ty)
            scale = abs(axis[2 * at]) + h
            scale = scale if scale > tiny else tiny
            theorem_6 = running_largest(abs(distance) / scale, theorem_6)
    return theorem_5, theorem_6


@kernel(
    "Tuple((boolean, float64, float64))(int64, int64, float64[::1], float64[::1], float64, "
    "float64, float64, float64[::1], float64[::1], float64[::1], int64, int64, "
    "float64, boolean, boolean, float64, float64, float64[:, ::1])"
)
def _closed_kinematic_block(
    first: int,
    count: int,
    cosh: Any,
    sinh: Any,
    h: float,
    d: float,
    amplitude: float,
    p: Any,
    tractrix: Any,
    axis: Any,
    offset: int,
    n: int,
    tiny: float,
    theorem_5_wanted: bool,
    theorem_6_wanted: bool,
    theorem_5: float,
    theorem_6: float,
    scratch: Any,
) -> tuple[bool, float, float]:
    """One block of Theorems 5 and 6's comparisons (indices first .. first + count − 1, rows
    ``offset`` .., those below ``n``; cosh of (14)'s arguments at ``[:count]``, of (16)'s at
    ``[count:2count]``, sinh of (16)'s): each closed point made as ``_closed_points`` makes it
    and compared at once, as ``_closed_comparisons`` compares the stored ones, folded into the
    running largest of each theorem. False (and nothing compared) when a cosh read is not
    finite. The rows go through a loop without branches (the compiler vectorizes it, the
    largest as an integer maximum of bit patterns); a block with a NaN or a length off its fast
    path is redone by the scalar loop, so the numbers are the old loop's, bit for bit."""
    lo, hi = (0 if theorem_5_wanted else count), (2 * count if theorem_6_wanted else count)
    if not _all_finite(cosh, lo, hi):
        return False, theorem_5, theorem_6
    rows = min(count, n - offset)
    if rows <= 0:
        return True, theorem_5, theorem_6
    step = 2 * d
    plain = True
    values_5, values_6 = scratch[0], scratch[1]
    # the block's rows as slices from its first (the compiler vectorizes loops over these)
    block_cosh, block_sech = cosh[:rows], cosh[count : count + rows]
    if theorem_5_wanted:
        block_p = p[2 * offset : 2 * (offset + rows)]
        for k in range(rows):
            ex, ey = float(first + k) * step - d, amplitude * block_cosh[k]
            size = math.sqrt(ex * ex + ey * ey)
            size = size if size > tiny else tiny
            dx, dy = block_p[2 * k] - ex, block_p[2 * k + 1] - ey
            values_5[k] = math.sqrt(dx * dx + dy * dy) / size
            plain &= _on_fast_path(ex, ey) & _on_fast_path(dx, dy)
    if theorem_6_wanted:
        block_t = tractrix[2 * offset : 2 * (offset + rows)]
        block_axis = axis[2 * offset : 2 * (offset + rows)]
        block_sinh = sinh[:rows]
        for k in range(rows):
            sech = 1 / block_sech[k]
            tx, ty = float(first + k) * step - h * (block_sinh[k] * sech), h * sech
            dx, dy = block_t[2 * k] - tx, block_t[2 * k + 1] - ty
            scale = abs(block_axis[2 * k]) + h
            scale = scale if scale > tiny else tiny
            values_6[k] = math.sqrt(dx * dx + dy * dy) / scale
            plain &= _on_fast_path(dx, dy)
    top_5 = largest_bits(values_5, rows) if theorem_5_wanted else 0
    top_6 = largest_bits(values_6, rows) if theorem_6_wanted else 0
    if plain and top_5 <= INF_BITS and top_6 <= INF_BITS:
        if theorem_5_wanted:
            theorem_5 = running_largest(bits_value(top_5), theorem_5)
        if theorem_6_wanted:
            theorem_6 = running_largest(bits_value(top_6), theorem_6)
        return True, theorem_5, theorem_6
    theorem_5, theorem_6 = _kinematic_rows(
        first,
        count,
        rows,
        cosh,
        sinh,
        h,
        d,
        amplitude,
        p,
        tractrix,
        axis,
        offset,
        tiny,
        theorem_5_wanted,
        theorem_6_wanted,
        theorem_5,
        theorem_6,
    )
    return True, theorem_5, theorem_6


def _flat(points: Any) -> Any:
    """A float64 (rows, 2) array's entries x_0, y_0, x_1, .. as one vector (a view of it when it
    is C-contiguous)."""
    return np.ascontiguousarray(points, dtype=np.float64).reshape(-1)


def closed_kinematic_comparisons(
    data: D4bPolygons, n: int, theorem_5: bool = True, theorem_6: bool = True
) -> tuple[float, float] | None:
    """Float64: ``closed_comparisons`` (Theorems 5 and 6's largest residuals, a pair of floats)
    with the closed forms (14), (16) made a block at a time and compared at once
    (``fill_closed_forms``' arguments and numpy calls, so the same closed points and the same
    largest residuals), none stored: two (n, 2) arrays fewer to write. None when a cosh
    overflows (the separate closed forms have their other branch for those)."""
    rows = data.vertices
    ar, h, d = data.ar, float(data.h), float(data.d)
    L = float(closed_forms.log_ratio(ar, data.h, data.d))
    shift = float(data.shift)
    amplitude = float(ar.sqrt((data.h - data.d) * (data.h + data.d)))
    block = min(rows, BLOCK_SIZE)
    arguments, decays = np.empty(2 * block), np.empty(2 * block)
    cosh, sinh = np.empty(2 * block), np.empty(block)
    scratch = np.empty((2, block))
    largest_5 = largest_6 = 0.0
    p = _flat(data.p) if theorem_5 else _NO_ENTRIES
    tractrix, axis = (
        (_flat(data.tractrix), _flat(data.axis)) if theorem_6 else (_NO_ENTRIES, _NO_ENTRIES)
    )
    for start in range(0, min(rows, n), block):
        count = min(block, rows - start)
        first = data.i_min + start
        lo, hi = (0 if theorem_5 else count), (2 * count if theorem_6 else count)
        if _kinematic_decays(first, count, L, shift, decays):
            elementary.exp_into(decays[lo:hi], decays[lo:hi])
            done, largest_5, largest_6 = _kinematic_block_from_decays(
                first,
                count,
                L,
                shift,
                decays,
                h,
                d,
                amplitude,
                p,
                tractrix,
                axis,
                start,
                n,
                theorem_5,
                theorem_6,
                largest_5,
                largest_6,
                scratch,
            )
            if done:
                continue
        # the old path: cosh and sinh, the old block (its rows with hypot's branch)
        _kinematic_arguments(first, count, L, shift, arguments)
        elementary.cosh_into(arguments[lo:hi], cosh[lo:hi])  # libm's bits, inf on overflow
        with np.errstate(over="ignore"):
            if theorem_6:  # (an overflow here is a cosh's too: the block returns None)
                elementary.sinh(arguments[count : 2 * count], out=sinh[:count])
        finite, largest_5, largest_6 = _closed_kinematic_block(
            first,
            count,
            cosh,
            sinh,
            h,
            d,
            amplitude,
            p,
            tractrix,
            axis,
            start,
            n,
            TINY,
            theorem_5,
            theorem_6,
            largest_5,
            largest_6,
            scratch,
        )
        if not finite:
            return None
    return largest_5, largest_6


def closed_comparisons(
    data: D4bPolygons, n: int, theorem_5: bool = True, theorem_6: bool = True
) -> tuple[float, float]:
    """Float64: the largest residuals of Theorems 5 and 6 (construction against closed form on
    i_min .. i_max) in one compiled pass; a theorem not asked for reads none of its polygons
    (its closed form is not made for the other) and gives 0.0."""
    return _closed_comparisons(
        data.p if theorem_5 else _NO_POINTS,
        data.closed_p if theorem_5 else _NO_POINTS,
        data.tractrix if theorem_6 else _NO_POINTS,
        data.closed_tractrix if theorem_6 else _NO_POINTS,
        data.axis if theorem_6 else _NO_POINTS,
        n,
        float(data.h),
        TINY,
        theorem_5,
        theorem_6,
    )


#: The largest residuals ``closed_image_comparisons`` gives, in this order: (18), (19), (20)
#: against their corrected closed forms, then each against its printed form (the errata).
IMAGE_COMPARISONS = ("18", "19", "20", "18 printed", "19 printed", "20 printed")


@numba.njit(cache=True, error_model="numpy")
def _image_rows(
    count: int,
    rows: int,
    cosh: Any,
    tanh: Any,
    h: float,
    d: float,
    gauss_amplitude: float,
    normals: Any,
    contact: Any,
    gauss: Any,
    contact_scale: Any,
    gauss_scale: Any,
    offset: int,
    scale_offset: int,
    tiny: float,
    wanted: Any,
    largest: Any,
) -> None:
    """The old row loop of ``_closed_image_block`` on ``rows`` rows of a block (cosh and tanh of
    (19)'s arguments at ``[:count + 1]``, of (20)'s at ``[count + 1:]``): lengths with hypot's
    branch, NaN first. Row ``at``'s scales are at ``at − scale_offset``."""
    for k in range(rows):
        at = offset + k
        # n_i = (sech t, tanh t) and ñ_i = (−tanh t, sech t), t = (i + τ)L; m_i
        sech, th = 1.0 / cosh[1 + k], tanh[1 + k]
        if wanted[0]:
            size = length(sech, th)
            size = size if size > tiny else tiny
            value = length(normals[2 * at] - sech, normals[2 * at + 1] - th) / size
            largest[0] = running_largest(value, largest[0])
        if wanted[3]:  # (18) printed: (sech t, −tanh t)
            size = length(sech, -th)
            size = size if size > tiny else tiny
            value = length(normals[2 * at] - sech, normals[2 * at + 1] - -th) / size
            largest[3] = running_largest(value, largest[3])
        if wanted[1] or wanted[4]:
            cx, cy = -th, sech  # ñ_i at row k + 1 of the contact points (from i_min − 1)
            if wanted[1]:
                size = length(cx, cy)
                size = size if size > tiny else tiny
                value = length(contact[2 * at + 2] - cx, contact[2 * at + 3] - cy) / size
                largest[1] = running_largest(value * contact_scale[at - scale_offset], largest[1])
            if wanted[4]:  # (19) printed: (tanh t, sech t)
                x, y = -cx, cy
                size = length(x, y)
                size = size if size > tiny else tiny
                value = length(contact[2 * at + 2] - x, contact[2 * at + 3] - y) / size
                largest[4] = running_largest(value, largest[4])
        if wanted[2]:
            mx, my = -tanh[count + 1 + k], gauss_amplitude / cosh[count + 1 + k]
            size = length(mx, my)
            size = size if size > tiny else tiny
            value = length(gauss[2 * at] - mx, gauss[2 * at + 1] - my) / size
            largest[2] = running_largest(value * gauss_scale[at - scale_offset], largest[2])
        if wanted[5]:  # (20) printed, from n_i: ((h tanh t − d), h sech t)/(h + d tanh t)
            denominator = h + d * th
            x, y = (h * th - d) / denominator, h * sech / denominator
            size = length(x, y)
            size = size if size > tiny else tiny
            value = length(gauss[2 * at] - x, gauss[2 * at + 1] - y) / size
            largest[5] = running_largest(value, largest[5])


@kernel(
    "boolean(int64, float64[::1], float64[::1], float64, float64, float64, float64[::1], "
    "float64[::1], float64[::1], float64[::1], float64[::1], int64, int64, int64, float64, "
    "boolean[::1], float64[::1], float64[:, ::1])"
)
def _closed_image_block(
    count: int,
    cosh: Any,
    tanh: Any,
    h: float,
    d: float,
    gauss_amplitude: float,
    normals: Any,
    contact: Any,
    gauss: Any,
    contact_scale: Any,
    gauss_scale: Any,
    offset: int,
    scale_offset: int,
    n: int,
    tiny: float,
    wanted: Any,
    largest: Any,
    scratch: Any,
) -> bool:
    """One block of (18)–(20)'s comparisons (``count`` indices, rows ``offset`` .., those below
    ``n``; cosh and tanh of (19)'s arguments from one index before at ``[:count + 1]``, of
    (20)'s at ``[count + 1:2count + 1]``): n_i, ñ_i and m_i's closed forms made as
    ``_closed_points`` makes them and compared at once, as ``curvature.evaluate`` compares the
    stored ones (``closed``: the relative point difference, times the resolution for (19) and
    (20); ``PrintedForms.largest``: ``residual_kernels._largest_printed_gauss``), into the
    running ``largest`` of each ``wanted`` entry of ``IMAGE_COMPARISONS``. False (and nothing
    compared) when a cosh is not finite.

    The rows go through loops without branches (the compiler vectorizes them; the largest as
    an integer maximum of bit patterns). The four corrected and printed forms of n_i and ñ_i
    have one length, |(sech t, ±tanh t)| (the same squares, added in either order), taken once.
    A block with a NaN or a length off its fast path is redone by the scalar loop
    (``_image_rows``), so the numbers are the old loop's, bit for bit."""
    if not _all_finite(cosh, 0, 2 * count + 1):
        return False
    rows = min(count, n - offset)
    if rows <= 0:
        return True
    sechs, sizes = scratch[6], scratch[7]
    plain = True
    # the block's rows as slices from its first (the compiler vectorizes loops over these)
    cosh_19, tanh_19 = cosh[1 : rows + 1], tanh[1 : rows + 1]
    if wanted[0] or wanted[1] or wanted[3] or wanted[4] or wanted[5]:
        for k in range(rows):
            sech, th = 1.0 / cosh_19[k], tanh_19[k]
            size = math.sqrt(sech * sech + th * th)
            sechs[k] = sech
            sizes[k] = size if size > tiny else tiny
            plain &= _on_fast_path(sech, th)
    if wanted[0] or wanted[3]:
        block_n = normals[2 * offset : 2 * (offset + rows)]
    if wanted[0]:
        values = scratch[0]
        for k in range(rows):
            dx, dy = block_n[2 * k] - sechs[k], block_n[2 * k + 1] - tanh_19[k]
            values[k] = math.sqrt(dx * dx + dy * dy) / sizes[k]
            plain &= _on_fast_path(dx, dy)
    if wanted[3]:  # (18) printed: (sech t, −tanh t)
        values = scratch[3]
        for k in range(rows):
            dx, dy = block_n[2 * k] - sechs[k], block_n[2 * k + 1] - -tanh_19[k]
            values[k] = math.sqrt(dx * dx + dy * dy) / sizes[k]
            plain &= _on_fast_path(dx, dy)
    if wanted[1] or wanted[4]:  # ñ_i at row k + 1 of the contact points (from i_min − 1)
        block_c = contact[2 * offset + 2 : 2 * (offset + rows) + 2]
    if wanted[1]:
        at = offset - scale_offset  # where the block's scales start
        values, block_scale = scratch[1], contact_scale[at : at + rows]
        for k in range(rows):
            dx, dy = block_c[2 * k] - -tanh_19[k], block_c[2 * k + 1] - sechs[k]
            values[k] = math.sqrt(dx * dx + dy * dy) / sizes[k] * block_scale[k]
            plain &= _on_fast_path(dx, dy)
    if wanted[4]:  # (19) printed: (tanh t, sech t)
        values = scratch[4]
        for k in range(rows):
            dx, dy = block_c[2 * k] - tanh_19[k], block_c[2 * k + 1] - sechs[k]
            values[k] = math.sqrt(dx * dx + dy * dy) / sizes[k]
            plain &= _on_fast_path(dx, dy)
    if wanted[2] or wanted[5]:
        block_m = gauss[2 * offset : 2 * (offset + rows)]
    if wanted[2]:
        at = offset - scale_offset
        values, block_scale = scratch[2], gauss_scale[at : at + rows]
        cosh_20, tanh_20 = cosh[count + 1 : count + 1 + rows], tanh[count + 1 : count + 1 + rows]
        for k in range(rows):
            mx, my = -tanh_20[k], gauss_amplitude / cosh_20[k]
            size = math.sqrt(mx * mx + my * my)
            size = size if size > tiny else tiny
            dx, dy = block_m[2 * k] - mx, block_m[2 * k + 1] - my
            values[k] = math.sqrt(dx * dx + dy * dy) / size * block_scale[k]
            plain &= _on_fast_path(mx, my) & _on_fast_path(dx, dy)
    if wanted[5]:  # (20) printed, from n_i: ((h tanh t − d), h sech t)/(h + d tanh t)
        values = scratch[5]
        for k in range(rows):
            th = tanh_19[k]
            denominator = h + d * th
            x, y = (h * th - d) / denominator, h * sechs[k] / denominator
            size = math.sqrt(x * x + y * y)
            size = size if size > tiny else tiny
            dx, dy = block_m[2 * k] - x, block_m[2 * k + 1] - y
            values[k] = math.sqrt(dx * dx + dy * dy) / size
            plain &= _on_fast_path(x, y) & _on_fast_path(dx, dy)
    tops = np.zeros(6, dtype=np.int64)
    for j in range(6):
        if wanted[j]:
            tops[j] = largest_bits(scratch[j], rows)
            plain &= tops[j] <= INF_BITS
    if plain:
        for j in range(6):
            if wanted[j]:
                largest[j] = running_largest(bits_value(tops[j]), largest[j])
        return True
    _image_rows(
        count,
        rows,
        cosh,
        tanh,
        h,
        d,
        gauss_amplitude,
        normals,
        contact,
        gauss,
        contact_scale,
        gauss_scale,
        offset,
        scale_offset,
        tiny,
        wanted,
        largest,
    )
    return True


@numba.njit(cache=True, inline="always", error_model="numpy")
def _square_distance(px: float, py: float, qx: float, qy: float) -> float:
    """|p − q|² of two points given by their coordinates."""
    dx, dy = px - qx, py - qy
    return dx * dx + dy * dy


@numba.njit(cache=True, inline="always", error_model="numpy")
def _gauss_square(gx: float, gy: float, sech: float, th: float, amplitude: float, s: float) -> Any:
    """(20)'s squared residual at a row, |m_i − (−tanh t, amplitude · sech t)|² · s² / |closed|²
    (s: the row's resolution), and whether its three squares are ``_usual``."""
    mx, my = -th, amplitude * sech
    distance, size, scale = _square_distance(gx, gy, mx, my), mx * mx + my * my, s * s
    return distance * scale / size, _usual(distance) & _usual(size) & _usual(scale)


@numba.njit(cache=True, inline="always", error_model="numpy")
def _printed_gauss_square(gx: float, gy: float, sech: float, th: float, h: float, d: float) -> Any:
    """The printed (20)'s squared relative residual at a row, from n_i's (sech t, tanh t): the
    point ((h tanh t − d), h sech t) · 1/(h + d tanh t); and whether its squares are ``_usual``."""
    reciprocal = 1.0 / (h + d * th)
    x, y = (h * th - d) * reciprocal, h * sech * reciprocal
    distance, size = _square_distance(gx, gy, x, y), x * x + y * y
    return distance / size, _usual(distance) & _usual(size)


@kernel(
    "boolean(int64, int64, float64, float64, float64[::1], float64, float64, float64, "
    "float64[::1], float64[::1], float64[::1], float64[::1], float64[::1], int64, int64, "
    "int64, boolean[::1], float64[::1], float64[:, ::1])"
)
def _image_block_from_decays(
    first: int,
    count: int,
    L: float,
    shift: float,
    decays: Any,
    h: float,
    d: float,
    gauss_amplitude: float,
    normals: Any,
    contact: Any,
    gauss: Any,
    contact_scale: Any,
    gauss_scale: Any,
    offset: int,
    scale_offset: int,
    n: int,
    wanted: Any,
    largest: Any,
    scratch: Any,
) -> bool:
    """One block of (18)–(20)'s comparisons as ``_closed_image_block`` (indices first .. first +
    count − 1; w = e^(−|t|) of its arguments t at the same places in ``decays``, every |t| ≤
    ``DECAY_LIMIT``; t's sign as ``_image_arguments`` computes t), into the running
    ``largest`` of each ``wanted`` entry of ``IMAGE_COMPARISONS``; False (``largest`` untouched)
    when a row needs the old path.

    sech t and tanh t from one exponential a row (``_sech_tanh``, the fraction form of (18)).
    n_i, ñ_i and their printed forms (sech t, ±tanh t), (∓tanh t, sech t) are unit vectors:
    their residual is the distance itself, not divided by its computed length (1 within an
    ulp). No square root a row: each block keeps the largest squared residual, |q − q̃|² (times
    the resolution's square for (19) and (20), over |q̃|² for m_i and the printed (20)), an
    integer maximum of bit patterns, and takes one square root of it (√ is monotone and
    correctly rounded). The printed (20) multiplies by the reciprocal of its denominator
    h + d·tanh t. The rounding moves at the last bits of the residuals (tests/test_golden.py,
    session 22). A NaN, an infinite or out-of-range square (a squared length or resolution not
    ``_usual``) sends the block back.

    With all six wanted (every check) one loop reads each row of n, ñ and m once; otherwise a
    loop a comparison (sech t, tanh t of (19)'s arguments made once into ``scratch[6:8]``). Each
    comparison's square comes from the same helper with the same arguments either way
    (``_square_distance``, ``_gauss_square``, ``_printed_gauss_square``): the same numbers."""
    rows = min(count, n - offset)
    if rows <= 0:
        return True
    plain = True
    # n_i and ñ_i at row k + 1 of (19)'s arguments and of the contact points (from i_min − 1)
    block_n = normals[2 * offset : 2 * (offset + rows)]
    block_c = contact[2 * offset + 2 : 2 * (offset + rows) + 2]
    block_m = gauss[2 * offset : 2 * (offset + rows)]
    at = offset - scale_offset  # where the block's scales start
    scale_19, scale_20 = contact_scale[at : at + rows], gauss_scale[at : at + rows]
    w_19, w_20 = decays[1 : rows + 1], decays[count + 1 : count + 1 + rows]
    if wanted[0] & wanted[1] & wanted[2] & wanted[3] & wanted[4] & wanted[5]:
        for k in range(rows):
            sech, th = _sech_tanh((float(first + k) + shift) * L, w_19[k])
            nx, ny, cx, cy = block_n[2 * k], block_n[2 * k + 1], block_c[2 * k], block_c[2 * k + 1]
            gx, gy = block_m[2 * k], block_m[2 * k + 1]
            # (18) and its printed form (sech t, −tanh t)
            a, b = _square_distance(nx, ny, sech, th), _square_distance(nx, ny, sech, -th)
            # (19) and its printed form (tanh t, sech t)
            e, f = _square_distance(cx, cy, -th, sech), _square_distance(cx, cy, th, sech)
            s = scale_19[k] * scale_19[k]
            scratch[0, k], scratch[3, k], scratch[1, k], scratch[4, k] = a, b, e * s, f
            plain &= _usual(a) & _usual(b) & _usual(e) & _usual(f) & _usual(s)
            # (20) and its printed form from n_i
            sech_20, th_20 = _sech_tanh((float(first + k) - 0.5 + shift) * L, w_20[k])
            g, plain_g = _gauss_square(gx, gy, sech_20, th_20, gauss_amplitude, scale_20[k])
            q, plain_q = _printed_gauss_square(gx, gy, sech, th, h, d)
            scratch[2, k], scratch[5, k] = g, q
            plain &= plain_g & plain_q
    else:
        sechs, tanhs = scratch[6], scratch[7]
        if wanted[0] or wanted[1] or wanted[3] or wanted[4] or wanted[5]:
            for k in range(rows):
                sechs[k], tanhs[k] = _sech_tanh((float(first + k) + shift) * L, w_19[k])
        if wanted[0]:
            values = scratch[0]
            for k in range(rows):
                values[k] = _square_distance(block_n[2 * k], block_n[2 * k + 1], sechs[k], tanhs[k])
                plain &= _usual(values[k])
        if wanted[3]:  # (18) printed: (sech t, −tanh t)
            values = scratch[3]
            for k in range(rows):
                values[k] = _square_distance(
                    block_n[2 * k], block_n[2 * k + 1], sechs[k], -tanhs[k]
                )
                plain &= _usual(values[k])
        if wanted[1]:
            values = scratch[1]
            for k in range(rows):
                e = _square_distance(block_c[2 * k], block_c[2 * k + 1], -tanhs[k], sechs[k])
                s = scale_19[k] * scale_19[k]
                values[k] = e * s
                plain &= _usual(e) & _usual(s)
        if wanted[4]:  # (19) printed: (tanh t, sech t)
            values = scratch[4]
            for k in range(rows):
                values[k] = _square_distance(block_c[2 * k], block_c[2 * k + 1], tanhs[k], sechs[k])
                plain &= _usual(values[k])
        if wanted[2]:
            values = scratch[2]
            for k in range(rows):
                sech_20, th_20 = _sech_tanh((float(first + k) - 0.5 + shift) * L, w_20[k])
                gx, gy = block_m[2 * k], block_m[2 * k + 1]
                g, plain_g = _gauss_square(gx, gy, sech_20, th_20, gauss_amplitude, scale_20[k])
                values[k] = g
                plain &= plain_g
        if wanted[5]:  # (20) printed, from n_i: ((h tanh t − d), h sech t)/(h + d tanh t)
            values = scratch[5]
            for k in range(rows):
                gx, gy = block_m[2 * k], block_m[2 * k + 1]
                q, plain_q = _printed_gauss_square(gx, gy, sechs[k], tanhs[k], h, d)
                values[k] = q
                plain &= plain_q
    tops = np.zeros(6, dtype=np.int64)
    for j in range(6):
        if wanted[j]:
            tops[j] = largest_bits(scratch[j], rows)
            plain &= tops[j] < INF_BITS
    if not plain:
        return False
    for j in range(6):
        if wanted[j]:
            largest[j] = running_largest(math.sqrt(bits_value(tops[j])), largest[j])
    return True


def closed_image_comparisons(
    ar: Arithmetic,
    h_scalar: Scalar,
    d_scalar: Scalar,
    shift_scalar: Scalar,
    i_min: int,
    n: int,
    wanted: tuple[bool, ...],
    normals: Array,
    contact: Array,
    gauss: Array,
    contact_scale: Array | None,
    gauss_scale: Array | None,
    resolutions: tuple[Array, float] | None = None,
) -> list[float] | None:
    """Float64: the largest residuals of ``IMAGE_COMPARISONS`` (six floats, those ``wanted``;
    0.0 for the others) of the Gauss images n, ñ (from i_min − 1) and m ((n, 2), (n + 1, 2),
    (n, 2)) against their closed forms, made a block at a time with ``fill_closed_forms``'
    arguments and numpy calls and compared at once, none stored (three (n, 2) arrays fewer to
    write); the polygon's h, d, τ and i_min given, its rows i_min .. i_min + n. None when a
    cosh overflows.

    The scales of (19) and (20): ``contact_scale`` and ``gauss_scale`` ((n,) arrays: the edges'
    and the poles' resolutions), or, with ``resolutions`` = (p, the resolution of the edge
    before p's first), made a block at a time from p (``residual_kernels.block_resolutions``:
    the same numbers, without the two arrays; issue 13, session 30)."""
    rows = n + 1
    h, d = float(h_scalar), float(d_scalar)
    L = float(closed_forms.log_ratio(ar, h_scalar, d_scalar))
    shift = float(shift_scalar)
    gauss_amplitude = float(h_scalar / ar.sqrt((h_scalar - d_scalar) * (h_scalar + d_scalar)))
    block = min(rows, BLOCK_SIZE)
    arguments, decays, cosh, tanh = (np.empty(2 * block + 1) for _ in range(4))
    scratch = np.empty((8, block))
    largest = np.zeros(len(IMAGE_COMPARISONS))
    flags = np.array(wanted, dtype=np.bool_)
    none = np.empty(0)
    scale_19 = none if contact_scale is None else np.ascontiguousarray(contact_scale, np.float64)
    scale_20 = none if gauss_scale is None else np.ascontiguousarray(gauss_scale, np.float64)
    blockwise = resolutions if flags[1] or flags[2] else None  # the scales made per block
    if blockwise is not None:
        points, before = np.ascontiguousarray(blockwise[0], np.float64), float(blockwise[1])
        scale_19, scale_20, edges = np.empty(block), np.empty(block), np.empty(block + 1)
        usual = np.empty(block + 1, dtype=np.bool_)
    normals, contact, gauss = _flat(normals), _flat(contact), _flat(gauss)
    for start in range(0, min(rows, n), block):
        count = min(block, rows - start)
        scale_offset = 0
        if blockwise is not None:
            scale_offset = start
            measured = min(count, n - start)  # the rows the block compares
            residual_kernels.block_resolutions(
                points, before, start, measured, scale_19, scale_20, edges, usual
            )
        if _image_decays(i_min + start, count, L, shift, decays):
            exps = 2 * count + 1 if flags[2] else count + 1  # (20)'s only where it is compared
            elementary.exp_into(decays[:exps], decays[:exps])
            if _image_block_from_decays(
                i_min + start,
                count,
                L,
                shift,
                decays,
                h,
                d,
                gauss_amplitude,
                normals,
                contact,
                gauss,
                scale_19,
                scale_20,
                start,
                scale_offset,
                n,
                flags,
                largest,
                scratch,
            ):
                continue
        # the old path: cosh and tanh, the old block (its rows with hypot's branch)
        _image_arguments(i_min + start, count, L, shift, arguments)
        # tanh of (20)'s arguments only where (20) itself is compared
        tanhs = 2 * count + 1 if flags[2] else count + 1
        elementary.cosh_into(arguments[: 2 * count + 1], cosh[: 2 * count + 1])  # inf on overflow
        elementary.tanh(arguments[:tanhs], out=tanh[:tanhs])
        finite = _closed_image_block(
            count,
            cosh,
            tanh,
            h,
            d,
            gauss_amplitude,
            normals,
            contact,
            gauss,
            scale_19,
            scale_20,
            start,
            scale_offset,
            n,
            TINY,
            flags,
            largest,
            scratch,
        )
        if not finite:
            return None
    return [float(v) for v in largest]


# --- Sections 3 and 4.2 in one call (``section_numbers``) ---

#: The checks take ``section_numbers`` below this many indices: there the rotation angle's pass
#: is compiled throughout (libm's atan2 where a block takes one), and beyond it the calls it
#: saves are a small part of the checks.
SECTION_BELOW = residual_kernels.ROTATION_LIBM_BELOW

#: Entries of ``_section_numbers``' vector: Theorem 4's hypothesis (largest violation, smallest
#: ratio), erratum E2's ratios (count, numpy's sum, smallest, largest), the rotation angle
#: (corrected, printed; ``ROTATION_FOUND`` 1.0 when the pass took every vertex), (13) and its
#: two-step form, max |p^y| (``checks._two_step``'s guard), the printed two-step form (E3), the
#: Darboux edge lengths and distances, Nikolaides' right angles; then the fits' summary
#: (``_summary_body``) from ``FITS_AT``.
(
    HYPOTHESIS_LARGEST,
    HYPOTHESIS_SMALLEST,
    RATIO_COUNT,
    RATIO_SUM,
    RATIO_LOW,
    RATIO_HIGH,
    ROTATION_LARGEST,
    ROTATION_PRINTED,
    ROTATION_FOUND,
    RECURSION_ONE,
    RECURSION_TWO,
    HEIGHT_LARGEST,
    TWO_STEP_PRINTED,
    DARBOUX_EDGES,
    DARBOUX_DISTANCES,
    RIGHT_ANGLES,
    FITS_AT,
) = range(17)


@numba.njit(cache=True, error_model="numpy")
def _rotation_largest(d: float, p: Any, axis: Any, n: int) -> tuple[bool, float, float]:
    """``residual_kernels._rotation_angles`` without ``store``, block by block as it goes, for
    blocks of fewer than ``ROTATION_LIBM_BELOW`` vertices (libm's atan2 where a block takes
    one): (whether it got to the end, the largest corrected and printed residuals). It stops
    at a block that takes ``elementary.atan2`` (False: the wrapper's pass goes on from the
    start)."""
    count = max(n - 1, 0)
    block = residual_kernels.ROTATION_BLOCK
    rows = np.empty((6, max(min(block, count), 1)))
    none = np.empty(0)
    largest, largest_printed = 0.0, 0.0
    first = 1
    while first < n:
        first, largest, largest_printed, outcome = residual_kernels._rotation_blocks(
            d, p, axis, first, n, block, rows, none, none, False, largest, largest_printed
        )
        if first >= n:
            break
        stop = min(first + block, n)
        m = stop - first
        if m >= residual_kernels.ROTATION_LIBM_BELOW:
            return False, largest, largest_printed
        if outcome == residual_kernels.ROTATION_WRAPPED and not (
            residual_kernels._rotation_arguments_wrapped(d, p, axis, first, stop, rows)
        ):
            outcome = residual_kernels.ROTATION_OLD
        if outcome == residual_kernels.ROTATION_WRAPPED:
            largest, largest_printed = residual_kernels._rotation_wrapped(
                rows, m, True, largest, largest_printed
            )
        else:  # ``_rotation_old_block`` below ``ROTATION_LIBM_BELOW``
            _, _, top, top_printed = residual_kernels._rotation_angles_libm(
                d, p[first - 1 : stop + 1], axis[first - 1 : stop + 1], m + 1, True
            )
            largest = running_largest(top, largest)
            largest_printed = running_largest(top_printed, largest_printed)
        first = stop
    return True, largest, largest_printed


@kernel(
    "float64[::1](float64[:, ::1], float64[:, ::1], float64[:, ::1], float64[:, ::1], "
    "float64[:, ::1], float64[:, ::1], int64, float64, float64, float64, float64, float64)"
)
def _section_numbers(
    p: Any,
    fitted: Any,
    axis: Any,
    shown_axis: Any,
    shown_darboux: Any,
    tractrix: Any,
    n: int,
    d: float,
    d_squared: float,
    d_squared_pow: float,
    d_fourth: float,
    distance: float,
) -> Any:
    """The numbers of ten checks (``d4b.checks._SECTION``) on p_0 .. p_n ((n + 1, 2), n >= 4): each
    from the pass its wrapper calls (``residual_kernels``, ``darboux``, ``_summary_body``), with
    the same arguments (``fitted`` = p[:n], the shown rows of x and e = x[:n], e[:n]; d² as
    d·d for the hypothesis and as Python's d**2 with d**4 for E3), so the same bits."""
    lengths = np.empty(max(fitted.shape[0] - 1, 0))
    summary = _summary_body(fitted, lengths)
    out = np.empty(FITS_AT + summary.shape[0])
    out[FITS_AT:] = summary
    out[HYPOTHESIS_LARGEST], out[HYPOTHESIS_SMALLEST] = residual_kernels._hypothesis_blocked(
        p, n, d_squared
    )
    out[RATIO_COUNT : RATIO_HIGH + 1] = residual_kernels._printed_ratio_summary(p)
    found, out[ROTATION_LARGEST], out[ROTATION_PRINTED] = _rotation_largest(d, p, axis, n)
    out[ROTATION_FOUND] = 1.0 if found else 0.0
    tiny = residual_kernels.TINY
    out[RECURSION_ONE], out[RECURSION_TWO] = residual_kernels._largest_recursions_pairs(d, p, tiny)
    out[HEIGHT_LARGEST] = largest_of_magnitudes(p[:, 1])
    out[TWO_STEP_PRINTED] = residual_kernels._largest_two_step_printed_pairs(
        d_squared_pow, d_fourth, p, tiny
    )
    out[DARBOUX_EDGES] = _edge_lengths(shown_axis, shown_darboux, False)[1]
    out[DARBOUX_DISTANCES] = _distances(shown_axis, shown_darboux, distance, False)[1]
    out[RIGHT_ANGLES] = residual_kernels._largest_right_angle(tractrix, axis, p, n)
    return out


class SectionNumbers:
    """``_section_numbers`` of one float64 polygon, read as each check's wrapper returns it
    (``found`` of ``residual_kernels`` and ``darboux``'s ``*_largest``)."""

    __slots__ = ("fits", "values")

    def __init__(self, found: Any) -> None:
        self.fits = found[FITS_AT:]
        self.values: list[float] = found[:FITS_AT].tolist()

    @property
    def hypothesis(self) -> tuple[float, float]:
        """Theorem 4's hypothesis: the largest violation and the smallest ratio."""
        return self.values[HYPOTHESIS_LARGEST], self.values[HYPOTHESIS_SMALLEST]

    @property
    def recursion(self) -> tuple[float, float]:
        """The largest residuals of (13) and of its two-step form."""
        return self.values[RECURSION_ONE], self.values[RECURSION_TWO]

    @property
    def height(self) -> float:
        """max |p^y| (NaN if one is NaN): the guard of E3's printed form."""
        return self.values[HEIGHT_LARGEST]

    @property
    def two_step_printed(self) -> float:
        """The largest residual of E3's printed two-step form."""
        return self.values[TWO_STEP_PRINTED]

    @property
    def darboux_edges(self) -> float:
        """The largest residual of the Darboux transform's edge lengths."""
        return self.values[DARBOUX_EDGES]

    @property
    def darboux_distances(self) -> float:
        """The largest residual of the Darboux transform's distances."""
        return self.values[DARBOUX_DISTANCES]

    @property
    def right_angles(self) -> float:
        """The largest residual of Nikolaides' right angles."""
        return self.values[RIGHT_ANGLES]

    @property
    def ratio(self) -> tuple[int, float, float, float]:
        """Erratum E2's ratios: their count, numpy's sum, smallest and largest."""
        count, total, low, high = self.values[RATIO_COUNT : RATIO_HIGH + 1]
        return int(count), total, low, high

    @property
    def rotation(self) -> tuple[float, float] | None:
        """The rotation angle's largest residuals (corrected, printed), None where the pass
        stopped at a block it does not take (``residual_kernels._rotation_angles`` goes on)."""
        values = self.values
        if values[ROTATION_FOUND] != 1.0:
            return None
        return values[ROTATION_LARGEST], values[ROTATION_PRINTED]


def _contiguous_rows(points: Any, least: int) -> bool:
    """Whether ``points`` is a C-contiguous float64 (m, 2) array with at least ``least`` rows."""
    return (
        type(points) is np.ndarray
        and points.dtype == np.float64
        and points.ndim == 2
        and points.shape[1] == 2
        and points.shape[0] >= least
        and points.flags.c_contiguous
    )


def section_numbers(
    p: Array, axis: Array, darboux: Array, tractrix: Array, n: int, d: float, h: float
) -> SectionNumbers | None:
    """``_section_numbers`` on the polygon p_0 .. p_n and its companions (x, e, d as the
    checks read them), None unless each is a C-contiguous float64 (m, 2) array with the rows
    the checks read (then each check calls its own pass)."""
    if n < 4 or len(p) != n + 1:
        return None
    shapes = ((p, n + 1), (axis, n + 1), (darboux, n), (tractrix, n))
    if not all(_contiguous_rows(points, least) for points, least in shapes):
        return None
    d = float(d)
    found = _section_numbers(
        p, p[:n], axis, axis[:n], darboux[:n], tractrix, n, d, d * d, d**2, d**4, float(2 * h)
    )
    return SectionNumbers(found)


# --- Section 5 in one call (``image_numbers``) ---

#: Entries of ``_image_numbers``' vector: (18) by slopes (largest, printed: E61), (19) as a
#: rotation, (20) by inversion, then each ring's (pseudosphere: Theorem 7, catenoid: Theorem 8)
#: validity (1.0: every face has area), largest theorem residual, largest (17) residual and
#: faces where (17) is 0/0.
(
    ALONG_LARGEST,
    ALONG_PRINTED,
    CONTACT_ROTATION,
    POLE_INVERSION,
    PSEUDOSPHERE_RING,
    CATENOID_RING,
) = (0, 1, 2, 3, 4, 8)
IMAGE_NUMBERS = 12


@kernel(
    "Tuple((float64[::1], float64[::1], float64[::1]))(float64[:, ::1], float64[:, ::1], "
    "float64[:, ::1], float64[:, ::1], float64[:, ::1], float64[:, ::1], float64[:, ::1], "
    "float64[:, ::1], int64, float64, float64, float64)"
)
def _image_numbers(
    p: Any,
    edges: Any,
    tractrix: Any,
    normals: Any,
    shown_normals: Any,
    contact: Any,
    gauss: Any,
    before: Any,
    n: int,
    cos: float,
    sin: float,
    curvature: float,
) -> tuple[Any, Any, Any]:
    """Section 5's numbers on p_0 .. p_n and its Gauss images, each from the pass the check's
    wrapper calls with the same arguments (``edges`` = p[:n + 1], ``shown_normals`` = ñ[:n]; the
    ring's cos, sin and the pseudosphere's curvature −1/h² as Python makes them): the edges'
    resolutions (n,), the poles' (n,) and the vector of ``IMAGE_NUMBERS`` entries."""
    resolution = np.ascontiguousarray(residual_kernels._edge_resolution_blocked(p))
    first = residual_kernels._edge_resolution_blocked(before)[0]
    poles = np.ascontiguousarray(residual_kernels._pole_resolution(first, resolution))
    out = np.empty(IMAGE_NUMBERS)
    out[ALONG_LARGEST], out[ALONG_PRINTED] = residual_kernels._largest_along_both_blocked(
        shown_normals, edges
    )
    out[CONTACT_ROTATION] = residual_kernels._largest_contact_rotation(
        contact, normals, resolution, n
    )
    out[POLE_INVERSION] = residual_kernels._largest_pole_inversion(
        gauss, contact, poles, n, residual_kernels.TINY
    )
    for at, meridian, image, k, minimal in (
        (PSEUDOSPHERE_RING, tractrix, normals, curvature, False),
        (CATENOID_RING, p, gauss, 0.0, True),
    ):
        skipped, valid, largest, largest_17 = ring_kernel._ring_largest(
            meridian, image, cos, sin, k, minimal, ring_kernel.TINY
        )
        out[at] = 1.0 if valid else 0.0
        out[at + 1], out[at + 2], out[at + 3] = largest, largest_17, skipped
    return resolution, poles, out


class ImageNumbers:
    """``_image_numbers`` of one float64 polygon and its Gauss images, read as each wrapper
    takes them (``found`` of ``residual_kernels`` and ``ring_curvature.ring_largest``)."""

    __slots__ = ("poles", "resolution", "values")

    def __init__(self, found: tuple[Any, Any, Any]) -> None:
        self.resolution, self.poles = found[0], found[1]
        self.values: list[float] = found[2].tolist()

    @property
    def along(self) -> tuple[float, float]:
        """(18) by slopes: its largest residual and erratum E61's printed one."""
        return self.values[ALONG_LARGEST], self.values[ALONG_PRINTED]

    @property
    def rotation(self) -> float:
        """(19) as a rotation: its largest residual."""
        return self.values[CONTACT_ROTATION]

    @property
    def inversion(self) -> float:
        """(20) by inversion: its largest residual."""
        return self.values[POLE_INVERSION]

    def ring(self, pseudosphere: bool) -> tuple[bool, float, float, int]:
        """A ring's (valid, largest theorem residual, largest (17) residual, 0/0 faces)."""
        at = PSEUDOSPHERE_RING if pseudosphere else CATENOID_RING
        valid, largest, largest_17, skipped = self.values[at : at + 4]
        return valid == 1.0, largest, largest_17, int(skipped)


def image_numbers(
    p: Array,
    tractrix: Array,
    normals: Array,
    contact: Array,
    gauss: Array,
    before: Array,
    n: int,
    ring: tuple[float, float],
    curvature: float,
) -> ImageNumbers | None:
    """``_image_numbers`` on p_0 .. p_n, the tractrix (as many rows), ñ (n rows or more), the
    contact points (n + 1 or more) and m (n or more), and the edge before them
    (``GaussImages.contact_edges_before``, two rows); ``ring`` is the ring's (cos, sin). None
    unless each is a C-contiguous float64 (m, 2) array of those rows (then each check calls
    its own pass)."""
    if n < 1 or len(p) != n + 1 or len(tractrix) != n + 1 or len(before) != 2:
        return None
    shapes = (
        (p, n + 1),
        (tractrix, n + 1),
        (normals, n),
        (contact, n + 1),
        (gauss, n),
        (before, 2),
    )
    if not all(_contiguous_rows(points, least) for points, least in shapes):
        return None
    cos, sin = ring
    found = _image_numbers(
        p,
        p[: n + 1],
        tractrix,
        normals,
        normals[:n],
        contact,
        gauss,
        before,
        n,
        float(cos),
        float(sin),
        float(curvature),
    )
    return ImageNumbers(found)
