"""Darboux transforms of the axis polygon (x_i) by reflection, (D4a) and (D4b), Section 3.

A polygon (e_i) is a Darboux transform of (x_i) when |x_i − e_i| is constant and corresponding
edges have equal length, |e_i − e_{i+1}| = |x_i − x_{i+1}|.
"""

from __future__ import annotations

import math
from typing import Any

import numba
import numpy as np

from app.geometry.checks import Largest, point_distance
from app.geometry.compiled import (
    INF_BITS,
    bits_value,
    fast_length,
    flat_rows,
    kernel,
    largest_bits,
    length,
    running_largest,
)
from app.geometry.polygon import magnitude
from app.geometry.precision import Arithmetic, Array


def reflect_in_points(x: Array, centres: Array) -> Array:
    """e_i = 2c_i − x_i, the reflection of x_i in c_i ((D4b): c_i = d_i); ``(n, 2)``."""
    return 2 * centres - x


def edge_length_residuals(ar: Arithmetic, x: Array, e: Array) -> Array:
    """| |e_{i+1} − e_i| − |x_{i+1} − x_i| | relative to the four points' magnitude; ``(n-1,)``.

    The magnitude (sum of absolute coordinates, at least the edge length) is what the stored
    points resolve a short edge against, see ``polygon``.
    """
    if ar.mode == "float64":  # the same operations in one compiled pass
        return _edge_lengths(_f64(x), _f64(e), True)[0]
    ex = point_distance(ar, x[1:], x[:-1])
    ee = point_distance(ar, e[1:], e[:-1])
    return abs(ee - ex) / magnitude(x[1:], x[:-1], e[1:], e[:-1])


def distance_residuals(ar: Arithmetic, x: Array, e: Array, expected: object) -> Array:
    """| |x_i − e_i| − expected | relative to the magnitude of x_i and e_i; ``(n,)``."""
    if ar.mode == "float64":  # the same operations in one compiled pass
        return _distances(_f64(x), _f64(e), float(expected), True)[0]  # type: ignore[arg-type]
    return abs(point_distance(ar, x, e) - expected) / magnitude(x, e)


def edge_length_largest(x: Any, e: Any, found: float | None = None) -> Largest:
    """``edge_length_residuals`` of float64 ``(n, 2)`` points as their largest
    (``checks.Largest``), not stored; the array only if asked for. ``found``: the largest,
    computed already (``d4b.fused_checks.section_numbers``)."""
    x, e = _f64(x), _f64(e)
    largest = _edge_lengths(x, e, False)[1] if found is None else found
    count = max(x.shape[0] - 1, 0)
    return Largest(float(largest), count, lambda: _edge_lengths(x, e, True)[0])


def distance_largest(x: Any, e: Any, expected: object, found: float | None = None) -> Largest:
    """``distance_residuals`` of float64 ``(n, 2)`` points as their largest (``checks.Largest``),
    not stored; the array only if asked for. ``found``: the largest, computed already
    (``d4b.fused_checks.section_numbers``)."""
    x, e, value = _f64(x), _f64(e), float(expected)  # type: ignore[arg-type]
    largest = _distances(x, e, value, False)[1] if found is None else found
    return Largest(float(largest), x.shape[0], lambda: _distances(x, e, value, True)[0])


def mean(values: Array) -> object:
    """Arithmetic mean of an ``(n,)`` array in its own precision."""
    return np.sum(values) / len(values)


def _f64(points: Array) -> Any:
    return np.ascontiguousarray(points, dtype=np.float64)


#: Rows per block of the float64 passes (a block's residuals stay in the cache).
DARBOUX_BLOCK = 4096


@numba.njit(cache=True, inline="always", error_model="numpy")
def _edge_length_at(x: Any, e: Any, k: int) -> float:
    """``edge_length_residuals`` at edge k, the lengths by ``compiled.length`` (the square root
    of the sum of squares, within 2 ulp of libm's hypot, which costs ≈ 4.7 ns an entry here
    against ≈ 1.8; hypot where squares overflow or underflow)."""
    ex = length(x[k + 1, 0] - x[k, 0], x[k + 1, 1] - x[k, 1])
    ee = length(e[k + 1, 0] - e[k, 0], e[k + 1, 1] - e[k, 1])
    size = abs(x[k + 1, 0]) + abs(x[k + 1, 1]) + abs(x[k, 0]) + abs(x[k, 1])
    size = size + abs(e[k + 1, 0]) + abs(e[k + 1, 1]) + abs(e[k, 0]) + abs(e[k, 1])
    return abs(ee - ex) / size


@numba.njit(cache=True, inline="always", error_model="numpy")
def _distance_at(x: Any, e: Any, expected: float, k: int) -> float:
    """``distance_residuals`` at point k, the distance by ``compiled.length``."""
    distance = length(x[k, 0] - e[k, 0], x[k, 1] - e[k, 1])
    size = abs(x[k, 0]) + abs(x[k, 1]) + abs(e[k, 0]) + abs(e[k, 1])
    return abs(distance - expected) / size


@numba.njit(cache=True, error_model="numpy")
def _edge_length_block(x: Any, e: Any, start: int, count: int, target: Any) -> bool:
    """``edge_length_residuals`` at edges start .. start + count − 1 into ``target``, each
    length √(x² + y²), in a loop without branches (vectorized by the compiler; a function of
    its own, as the compiler vectorizes it there): whether every length took
    ``compiled.length``'s fast path and no residual is NaN (then they are its residuals)."""
    xs, es = flat_rows(x, start, count + 1), flat_rows(e, start, count + 1)  # from 0
    plain = True
    for j in range(count):
        x0, y0, x1, y1 = xs[2 * j], xs[2 * j + 1], xs[2 * j + 2], xs[2 * j + 3]
        e0, f0, e1, f1 = es[2 * j], es[2 * j + 1], es[2 * j + 2], es[2 * j + 3]
        ex, plain_x = fast_length(x1 - x0, y1 - y0)
        ee, plain_e = fast_length(e1 - e0, f1 - f0)
        size = abs(x1) + abs(y1) + abs(x0) + abs(y0)
        size = size + abs(e1) + abs(f1) + abs(e0) + abs(f0)
        residual = abs(ee - ex) / size
        target[j] = residual
        plain &= plain_x & plain_e & (residual == residual)
    return plain


@numba.njit(cache=True, error_model="numpy")
def _distance_block(x: Any, e: Any, expected: float, start: int, count: int, target: Any) -> bool:
    """``distance_residuals`` at points start .. start + count − 1 into ``target`` as
    ``_edge_length_block``: whether every distance took the fast path and none is NaN."""
    xs, es = flat_rows(x, start, count), flat_rows(e, start, count)
    plain = True
    for j in range(count):
        x0, y0, e0, f0 = xs[2 * j], xs[2 * j + 1], es[2 * j], es[2 * j + 1]
        distance, plain_distance = fast_length(x0 - e0, y0 - f0)
        size = abs(x0) + abs(y0) + abs(e0) + abs(f0)
        residual = abs(distance - expected) / size
        target[j] = residual
        plain &= plain_distance & (residual == residual)
    return plain


#: The squares' pass (session 22): where |D| ≤ ``NEAR`` T for D = l² − l'², T = l² + l'² of two
#: lengths l, l', √(2T) is l + l' to a relative 2^-55 (its square is (l + l')² + (l − l')²), so
#: |l − l'| = |D| / (l + l') is |D| / √(2T) to rounding; the sums of squares between
#: ``SQUARES_SUM`` and the sizes between ``SIZES`` keep every square of the quotient normal.
NEAR = 2.0**-26
SQUARES_SUM = (2.0**-400, 2.0**400)
SIZES = (2.0**-200, 2.0**200)


@numba.njit(cache=True, inline="always", error_model="numpy")
def _squared_residual(difference: float, total: float, size: float) -> float:
    """(|l − l'| / size)² as D² / (2T size²) (``NEAR``), or NaN where its conditions fail (a NaN
    argument included)."""
    plain = (abs(difference) <= NEAR * total) & (total > SQUARES_SUM[0]) & (total < SQUARES_SUM[1])
    plain &= (size > SIZES[0]) & (size < SIZES[1])
    squared = difference * difference / ((total + total) * (size * size))
    return squared if plain else math.nan


@numba.njit(cache=True, error_model="numpy")
def _edge_squares_block(x: Any, e: Any, start: int, count: int, target: Any) -> int:
    """The squares of ``edge_length_residuals`` at edges start .. start + count − 1 into
    ``target`` by ``_squared_residual`` (no square root, one division an edge), in a loop
    without branches (vectorized by the compiler): their largest bit pattern (above
    ``INF_BITS`` if one is off the conditions)."""
    xs, es = flat_rows(x, start, count + 1), flat_rows(e, start, count + 1)  # from 0
    for j in range(count):
        x0, y0, x1, y1 = xs[2 * j], xs[2 * j + 1], xs[2 * j + 2], xs[2 * j + 3]
        e0, f0, e1, f1 = es[2 * j], es[2 * j + 1], es[2 * j + 2], es[2 * j + 3]
        dx, dy, fx, fy = x1 - x0, y1 - y0, e1 - e0, f1 - f0
        squared_x, squared_e = dx * dx + dy * dy, fx * fx + fy * fy
        size = abs(x1) + abs(y1) + abs(x0) + abs(y0)
        size = size + abs(e1) + abs(f1) + abs(e0) + abs(f0)
        target[j] = _squared_residual(squared_e - squared_x, squared_e + squared_x, size)
    return largest_bits(target, count)


@numba.njit(cache=True, inline="always", error_model="numpy")
def _roots(target: Any, count: int) -> None:
    """√ of ``target[:count]`` in place (a stored block of squares)."""
    for j in range(count):
        target[j] = math.sqrt(target[j])


@kernel("Tuple((float64[::1], float64))(float64[:, ::1], float64[:, ::1], boolean)")
def _edge_lengths(x: Any, e: Any, store: bool) -> tuple[Any, float]:
    """``edge_length_residuals`` of C-contiguous ``(n, 2)`` points x, e: the ``(n − 1,)``
    residuals if ``store`` (else an empty array) and their largest (NaN if one is NaN).

    In blocks of ``DARBOUX_BLOCK`` edges, since session 22 first as squares without a square
    root (``_edge_squares_block``): the largest residual is the root of the largest square (the
    block's largest bit pattern, ``compiled.largest_bits``), the stored ones the roots of the
    squares; they move at rounding level (a few units of (l + l') / size,
    tests/geometry/test_darboux_rounding.py). A block with an edge off the squares' conditions
    (``NEAR``: also a perturbed polygon's edges, a NaN or inf) is taken as before: the residuals
    in a loop without branches, each length √(x² + y²) with a flag where ``compiled.length``
    would leave that path, and a block with such an edge or a NaN edge by edge
    (``_edge_length_at``)."""
    rows = max(x.shape[0] - 1, 0)
    out = np.empty(rows if store else 0)
    scratch = np.empty(0 if store else DARBOUX_BLOCK)
    largest = 0.0
    for start in range(0, rows, DARBOUX_BLOCK):
        count = min(DARBOUX_BLOCK, rows - start)
        target = out[start : start + count] if store else scratch[:count]
        top = _edge_squares_block(x, e, start, count, target)
        if top < INF_BITS:  # √ is monotonic and correctly rounded: √ of the largest square
            largest = running_largest(math.sqrt(bits_value(top)), largest)
            if store:
                _roots(target, count)
        elif _edge_length_block(x, e, start, count, target):
            largest = running_largest(bits_value(largest_bits(target, count)), largest)
        else:  # hypot's ranges, inf or NaN: edge by edge
            for j in range(count):
                target[j] = _edge_length_at(x, e, start + j)
                largest = running_largest(target[j], largest)
    return out, largest


@kernel("Tuple((float64[::1], float64))(float64[:, ::1], float64[:, ::1], float64, boolean)")
def _distances(x: Any, e: Any, expected: float, store: bool) -> tuple[Any, float]:
    """``distance_residuals`` of C-contiguous ``(n, 2)`` points x, e: the ``(n,)`` residuals if
    ``store`` (else an empty array) and their largest (NaN if one is NaN); in blocks without
    branches as ``_edge_lengths`` before session 22, a block off the fast path point by point
    (``_distance_at``). The same residuals and largest, bit for bit (one square root a point:
    its squares' pass measured no faster, the pass is bound by reading the points)."""
    rows = x.shape[0]
    out = np.empty(rows if store else 0)
    scratch = np.empty(0 if store else DARBOUX_BLOCK)
    largest = 0.0
    for start in range(0, rows, DARBOUX_BLOCK):
        count = min(DARBOUX_BLOCK, rows - start)
        target = out[start : start + count] if store else scratch[:count]
        if _distance_block(x, e, expected, start, count, target):
            largest = running_largest(bits_value(largest_bits(target, count)), largest)
        else:  # hypot's ranges, inf or NaN: point by point
            for j in range(count):
                target[j] = _distance_at(x, e, expected, start + j)
                largest = running_largest(target[j], largest)
    return out, largest
