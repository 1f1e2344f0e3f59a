"""The conditions (D1), (D3), eqs. (2) and (7) as residuals of a polygon, with fitted constants.

Each condition has the form lhs_i = c · rhs_i for one constant c > 0 (eq. (7): two constants,
``equation_7``). ``fit`` finds c by least squares and reports, for each equation,
|lhs_i − c·rhs_i| / (|lhs|_i + |c|·|rhs|_i), where
|lhs|_i and |rhs|_i are the magnitudes of the stored numbers the two sides are computed from
(``polygon.*_magnitude``). So a residual is relative to what the data can resolve: cancellation
in Δ² or in the edges of vertices far from the origin does not inflate it, and a polygon that
misses the condition by a relative δ shows a residual of about δ.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numba
import numpy as np

from app.geometry.compiled import hypot, kernel
from app.geometry.polygon import (
    area_magnitude,
    edge_lengths,
    edge_magnitude,
    second_difference,
    second_difference_magnitude,
    signed_areas,
)
from app.geometry.precision import Arithmetic, Array, Scalar
from app.geometry.tolerances import unit


@dataclass(frozen=True)
class ConditionFit:
    """Fitted constant and per-equation residuals of one condition on one polygon."""

    constant: Scalar | None
    """Least-squares constant; ``None`` when every right-hand side vanishes."""
    residuals: Array
    """``(m,)`` relative residuals; equation k has index i = i_min + k."""

    def indices(self, i_min: int) -> np.ndarray[Any, np.dtype[np.int64]]:
        """The index i of each equation."""
        return np.arange(i_min, i_min + len(self.residuals), dtype=np.int64)


def fit(
    ar: Arithmetic, lhs: Array, rhs: Array, lhs_magnitude: Array, rhs_magnitude: Array
) -> ConditionFit:
    """Least-squares c in lhs = c·rhs and the relative residuals; all arrays ``(m,)``."""
    tiny = ar.scalar(np.finfo(np.float64).tiny)
    if ar.mode == "float64":  # the same operations, the elementwise ones in compiled passes
        return _fit_float64(lhs, lhs_magnitude, rhs, rhs_magnitude)
    weight = np.where(lhs_magnitude > tiny, lhs_magnitude, tiny)
    if not ar.may_overflow:  # mp numbers do not overflow: no scaling (a third of the operations)
        u, v = lhs / weight, rhs / weight
        vv = np.sum(v * v) if len(v) else ar.scalar(0)
        constant = np.sum(u * v) / vv if vv > 0 else None
        c = constant if constant is not None else ar.scalar(0)
        return ConditionFit(constant, misfit(ar, lhs, rhs, lhs_magnitude, rhs_magnitude, c))
    # each side scaled to at most 1 before and after the weighting, so that neither the
    # quotients (weights can be as small as the smallest normal float) nor the squares can
    # overflow; the constant scales back
    lhs_scale, rhs_scale = _largest_magnitude(ar, lhs), _largest_magnitude(ar, rhs)
    u, v = lhs / lhs_scale / weight, rhs / rhs_scale / weight
    u_scale, v_scale = _largest_magnitude(ar, u), _largest_magnitude(ar, v)
    u, v = u / u_scale, v / v_scale
    vv = np.sum(v * v) if len(v) else ar.scalar(0)
    constant = (
        np.sum(u * v) / vv * (u_scale / v_scale) * (lhs_scale / rhs_scale) if vv > 0 else None
    )
    c = constant if constant is not None else ar.scalar(0)
    return ConditionFit(constant, misfit(ar, lhs, rhs, lhs_magnitude, rhs_magnitude, c))


def misfit(
    ar: Arithmetic, lhs: Array, rhs: Array, lhs_magnitude: Array, rhs_magnitude: Array, c: Scalar
) -> Array:
    """|lhs_i − c·rhs_i| / (|lhs|_i + |c|·|rhs|_i) for a given constant c; ``(m,)``."""
    tiny = ar.scalar(np.finfo(np.float64).tiny)
    if ar.mode == "float64":  # the same operations in one compiled pass
        left, right, left_size, right_size = _f64(lhs, rhs, lhs_magnitude, rhs_magnitude)
        return _misfit(left, right, left_size, right_size, float(c), TINY)
    scale = lhs_magnitude + abs(c) * rhs_magnitude
    scale = np.where(scale > tiny, scale, tiny)
    return abs(lhs - c * rhs) / scale


def d1(ar: Arithmetic, p: Array) -> ConditionFit:
    """(D1): Δ²p_i^y = c (l_i + l_{i+1}); equations i = i_min .. i_max − 2."""
    if ar.mode == "float64":
        return Columns(p).fit(D1)
    y = p[:, 1]
    lengths = edge_lengths(ar, p)
    sizes = edge_magnitude(p)
    return fit(
        ar,
        second_difference(y),
        lengths[:-1] + lengths[1:],
        second_difference_magnitude(y),
        sizes[:-1] + sizes[1:],
    )


def d3(ar: Arithmetic, p: Array) -> ConditionFit:
    """(D3): A_i = c l_i; equations i = i_min .. i_max − 1."""
    if ar.mode == "float64":
        return Columns(p).fit(D3)
    return fit(ar, signed_areas(p), edge_lengths(ar, p), area_magnitude(p), edge_magnitude(p))


def equation_2(ar: Arithmetic, p: Array) -> ConditionFit:
    """Eq. (2): Δ²p_i^y = c (A_i + A_{i+1}); equations i = i_min .. i_max − 2."""
    if ar.mode == "float64":
        return Columns(p).fit(EQUATION_2)
    y = p[:, 1]
    areas = signed_areas(p)
    sizes = area_magnitude(p)
    return fit(
        ar,
        second_difference(y),
        areas[:-1] + areas[1:],
        second_difference_magnitude(y),
        sizes[:-1] + sizes[1:],
    )


def equation_2_misfit(ar: Arithmetic, p: Array, c: Scalar) -> Array:
    """Eq. (2) with a given c: the residual of each equation, measured as in ``fit``."""
    if ar.mode == "float64":
        return Columns(p).misfit(EQUATION_2, c)
    y = p[:, 1]
    areas = signed_areas(p)
    sizes = area_magnitude(p)
    return misfit(
        ar,
        second_difference(y),
        areas[:-1] + areas[1:],
        second_difference_magnitude(y),
        sizes[:-1] + sizes[1:],
        c,
    )


@dataclass(frozen=True)
class TwoConstantFit:
    """Fitted constants (c_1, c_2) and per-equation residuals of eq. (7) on one polygon."""

    constants: tuple[Scalar, Scalar] | None
    """Least-squares (c_1, c_2); ``None`` when they are not determined (too few equations)."""
    residuals: Array
    """``(m,)`` relative residuals; equation k has index i = i_min + k."""


def equation_7(ar: Arithmetic, p: Array, i_min: int) -> TwoConstantFit:
    """Eq. (7): Δ²p_i^y = c_1 A_i + c_2 A_{i+1} (i even), c_2 A_i + c_1 A_{i+1} (i odd).

    ``p`` holds p_{i_min} .. p_{i_max}; equations i = i_min .. i_max − 2. (c_1, c_2) solve the
    weighted least-squares problem (each equation divided by the magnitude of its Δ²) through
    its 2×2 normal equations; the residual of equation i is
    |Δ²p_i^y − c_1 u_i − c_2 v_i| / (|Δ²|_i + |c_1| |u|_i + |c_2| |v|_i) with (u_i, v_i) the areas
    multiplying c_1 and c_2.
    """
    y = p[:, 1]
    lhs = second_difference(y)
    areas = signed_areas(p)
    sizes = area_magnitude(p)
    even = (np.arange(i_min, i_min + len(lhs)) % 2) == 0
    u = np.where(even, areas[:-1], areas[1:])  # multiplies c_1
    v = np.where(even, areas[1:], areas[:-1])  # multiplies c_2
    u_size = np.where(even, sizes[:-1], sizes[1:])
    v_size = np.where(even, sizes[1:], sizes[:-1])
    lhs_size = second_difference_magnitude(y)
    tiny = ar.scalar(np.finfo(np.float64).tiny)
    weight = np.where(lhs_size > tiny, lhs_size, tiny)
    # each column scaled to at most 1 in magnitude, so that the sums of products cannot
    # overflow (areas can be ~1e150 times the second differences); the constants scale back
    mu, mv, ml = (_largest_magnitude(ar, column / weight) for column in (u, v, lhs))
    uw, vw, lw = u / weight / mu, v / weight / mv, lhs / weight / ml
    zero = ar.scalar(0)
    suu, svv, suv = np.sum(uw * uw), np.sum(vw * vw), np.sum(uw * vw)
    slu, slv = np.sum(lw * uw), np.sum(lw * vw)
    det = suu * svv - suv * suv if len(lhs) else zero
    # determined when det is not 0 to within the rounding of its products (in mp the unit as a
    # number of ``ar``: a float eps² is 0 from about 162 digits on)
    eps = unit(ar)
    if len(lhs) >= 2 and abs(det) > eps * eps * abs(suu * svv):
        c1 = (slu * svv - slv * suv) / det * (ml / mu)
        c2 = (suu * slv - suv * slu) / det * (ml / mv)
        constants: tuple[Scalar, Scalar] | None = (c1, c2)
    else:
        c1 = c2 = zero
        constants = None
    scale = lhs_size + abs(c1) * u_size + abs(c2) * v_size
    scale = np.where(scale > tiny, scale, tiny)
    return TwoConstantFit(constants, abs(lhs - c1 * u - c2 * v) / scale)


def _largest_magnitude(ar: Arithmetic, values: Array) -> Scalar:
    """max |value|, or 1 when every value is 0 (a column scale that never divides by zero)."""
    largest = np.max(np.abs(values)) if len(values) else ar.scalar(0)
    return largest if largest > 0 else ar.scalar(1)


def equilibrium(ar: Arithmetic, p: Array) -> ConditionFit:
    """Hanging sticks in equilibrium: k_{i+1} − k_i = c (l_i + l_{i+1}) for the edge slopes k_i.

    Homogeneous sticks on the edges (weight w per length), joined by weightless hinges: each
    stick's moment balance puts half of its weight on each end, and the hinge balance with a
    constant horizontal tension T gives T (k_{i+1} − k_i) = (w/2)(l_i + l_{i+1}), so c = w/(2T).
    With constant spacing δ this is (D1) divided by δ. For polygons with increasing x;
    equations i = i_min .. i_max − 2. A slope's magnitude is (|y_i| + |y_{i+1}| + |k_i|(|x_i| +
    |x_{i+1}|))/|x_{i+1} − x_i|, the size of the numbers it is computed from.
    """
    x, y = p[:, 0], p[:, 1]
    dx = x[1:] - x[:-1]
    slopes = (y[1:] - y[:-1]) / dx
    sizes = (abs(y[1:]) + abs(y[:-1]) + abs(slopes) * (abs(x[1:]) + abs(x[:-1]))) / abs(dx)
    lengths = edge_lengths(ar, p)
    edge_sizes = edge_magnitude(p)
    return fit(
        ar,
        slopes[1:] - slopes[:-1],
        lengths[:-1] + lengths[1:],
        sizes[:-1] + sizes[1:],
        edge_sizes[:-1] + edge_sizes[1:],
    )


# --- float64: the same numbers in compiled passes (no temporary arrays but the columns) ---

TINY = float(np.finfo(np.float64).tiny)


@kernel("UniTuple(float64[:], 6)(float64[:, :])")
def _shared_columns(p: Any) -> tuple[Any, Any, Any, Any, Any, Any]:
    """What (D1), (D3) and eq. (2) are made of, in one pass over the polygon, entry by entry as
    the ``polygon`` functions compute them (the same operations in the same order; edge lengths
    by libm's hypot, inline): per edge k the length l_k, its magnitude |x_k| + |y_k| + |x_{k+1}|
    + |y_{k+1}|, the signed area A_k and its magnitude; per inner vertex Δ²y_k and its magnitude.

    (D1)'s right side l_k + l_{k+1} and eq. (2)'s A_k + A_{k+1} (with their magnitudes) are the
    sums of neighbouring entries, which the fit kernels form as they go (``paired``): the same
    numbers as computing each sum from the coordinates.
    """
    n = p.shape[0]
    edges = max(n - 1, 0)
    inner = max(n - 2, 0)
    lengths = np.empty(edges)
    sizes = np.empty(edges)
    areas = np.empty(edges)
    area_sizes = np.empty(edges)
    second = np.empty(inner)
    second_sizes = np.empty(inner)
    for k in range(edges):
        x0, y0, x1, y1 = p[k, 0], p[k, 1], p[k + 1, 0], p[k + 1, 1]
        areas[k] = (y0 + y1) / 2 * (x1 - x0)
        lengths[k] = hypot(x1 - x0, y1 - y0)
        area_sizes[k] = (abs(y0) + abs(y1)) / 2 * (abs(x0) + abs(x1))
        sizes[k] = abs(x0) + abs(y0) + abs(x1) + abs(y1)
        if k < inner:
            y2 = p[k + 2, 1]
            second[k] = y2 - 2 * y1 + y0
            second_sizes[k] = abs(y2) + 2 * abs(y1) + abs(y0)
    return lengths, sizes, areas, area_sizes, second, second_sizes


class Columns:
    """The shared columns of (D1), (D3) and eq. (2) of one float64 polygon (``_shared_columns``),
    computed once for all three fits and eq. (2)'s misfit with another constant."""

    def __init__(self, p: Array) -> None:
        columns = _shared_columns(np.asarray(p, dtype=np.float64))
        self.lengths, self.sizes, self.areas, self.area_sizes = columns[:4]
        self.second, self.second_sizes = columns[4:]

    def sides(self, kind: int) -> tuple[Any, Any, Any, Any, bool]:
        """(lhs, |lhs|~, r, |r|~, paired) of ``kind``: rhs_k = r_k (+ r_{k+1} when paired)."""
        if kind == D3:
            return self.areas, self.area_sizes, self.lengths, self.sizes, False
        if kind == D1:
            return self.second, self.second_sizes, self.lengths, self.sizes, True
        return self.second, self.second_sizes, self.areas, self.area_sizes, True

    def fit(self, kind: int) -> ConditionFit:
        """The fit of ``kind`` (``D1``, ``D3``, ``EQUATION_2``), as ``fit`` computes it."""
        return _fit_float64(*self.sides(kind))

    def misfit(self, kind: int, c: Scalar) -> Any:
        """``misfit`` of ``kind`` with the constant c."""
        lhs, lhs_size, r, r_size, paired = self.sides(kind)
        out = np.empty(len(lhs))
        _misfit_into(lhs, lhs_size, r, r_size, paired, float(c), TINY, out)
        return out


#: The kinds of ``Columns``: the two sides of (D1), (D3) and eq. (2) with their magnitudes.
D1, D3, EQUATION_2 = 0, 1, 2


def _f64(*arrays: Array) -> list[Any]:
    """Contiguous float64 vectors: the kernels below take no strides, so that the compiler
    vectorizes their loops (3× faster; the same operations on each entry, the same bits)."""
    return [np.ascontiguousarray(a, dtype=np.float64) for a in arrays]


@numba.njit(cache=True, inline="always", error_model="numpy")
def _largest(value: float, nan: bool, largest: float) -> tuple[float, bool]:
    """One step of max |v| with numpy's NaN propagation: (largest so far, NaN seen)."""
    if value != value:
        return largest, True
    magnitude = abs(value)
    return (magnitude if magnitude > largest else largest), nan


@numba.njit(cache=True, inline="always", error_model="numpy")
def _column_scale(largest: float, nan: bool) -> float:
    """``_largest_magnitude``: max |v|, or 1 when it is 0 or NaN (NaN > 0 is false)."""
    return largest if (not nan and largest > 0) else 1.0


@numba.njit(cache=True, inline="always", error_model="numpy")
def _side(values: Any, k: int, paired: bool) -> float:
    """The k-th right side: values_k, or values_k + values_{k+1} (``Columns``)."""
    return values[k] + values[k + 1] if paired else values[k]


@kernel(
    "UniTuple(float64, 4)(float64[::1], float64[::1], float64[::1], boolean, float64, "
    "float64[::1], float64[::1])"
)
def _fit_scales(
    lhs: Any, lhs_size: Any, r: Any, paired: bool, tiny: float, u: Any, v: Any
) -> tuple[float, float, float, float]:
    """``fit``'s four column scales (lhs, rhs, then u and v), as it computes them, in two
    passes; the second leaves u_k and v_k before their own scaling in ``u`` and ``v``
    (``_fit_terms`` divides them by their scales: the same quotients as dividing anew)."""
    n = lhs.shape[0]
    big_l, nan_l, big_r, nan_r = 0.0, False, 0.0, False
    for k in range(n):
        big_l, nan_l = _largest(lhs[k], nan_l, big_l)
        big_r, nan_r = _largest(_side(r, k, paired), nan_r, big_r)
    lhs_scale, rhs_scale = _column_scale(big_l, nan_l), _column_scale(big_r, nan_r)
    big_u, nan_u, big_v, nan_v = 0.0, False, 0.0, False
    for k in range(n):
        weight = lhs_size[k] if lhs_size[k] > tiny else tiny
        u_k = lhs[k] / lhs_scale / weight
        v_k = _side(r, k, paired) / rhs_scale / weight
        u[k] = u_k
        v[k] = v_k
        big_u, nan_u = _largest(u_k, nan_u, big_u)
        big_v, nan_v = _largest(v_k, nan_v, big_v)
    return lhs_scale, rhs_scale, _column_scale(big_u, nan_u), _column_scale(big_v, nan_v)


@kernel("void(float64, float64, float64[::1], float64[::1])")
def _fit_terms(u_scale: float, v_scale: float, u: Any, v: Any) -> None:
    """The terms of ``fit``'s two sums in one pass, in place: v_k² into ``v``, u_k v_k into
    ``u`` (both as ``_fit_scales`` left them, divided by their scales here)."""
    for k in range(u.shape[0]):
        v_k = v[k] / v_scale
        v[k] = v_k * v_k
        u[k] = u[k] / u_scale * v_k


@kernel(
    "void(float64[::1], float64[::1], float64[::1], float64[::1], boolean, float64, float64, "
    "float64[::1])"
)
def _misfit_into(
    lhs: Any, lhs_size: Any, r: Any, r_size: Any, paired: bool, c: float, tiny: float, out: Any
) -> None:
    """``misfit`` entry by entry into ``out``: |lhs − c·rhs| / max(|lhs|~ + |c|·|rhs|~, tiny)."""
    for k in range(lhs.shape[0]):
        scale = lhs_size[k] + abs(c) * _side(r_size, k, paired)
        out[k] = abs(lhs[k] - c * _side(r, k, paired)) / (scale if scale > tiny else tiny)


def _misfit(lhs: Any, rhs: Any, lhs_size: Any, rhs_size: Any, c: float, tiny: float) -> Any:
    lhs, rhs, lhs_size, rhs_size = _f64(lhs, rhs, lhs_size, rhs_size)
    out = np.empty(len(lhs))
    _misfit_into(lhs, lhs_size, rhs, rhs_size, False, c, tiny, out)
    return out


def _fit_float64(
    lhs: Array, lhs_size: Array, r: Array, r_size: Array, paired: bool = False
) -> ConditionFit:
    """``fit`` in float64: its elementwise passes compiled, its two sums numpy's; the right
    side is r (or the sums of neighbouring entries of r, ``paired``); one array holds the terms
    of v², then the residuals."""
    lhs, lhs_size, r, r_size = _f64(lhs, lhs_size, r, r_size)
    out, products = np.empty(len(lhs)), np.empty(len(lhs))
    lhs_scale, rhs_scale, u_scale, v_scale = _fit_scales(
        lhs, lhs_size, r, paired, TINY, products, out
    )
    _fit_terms(u_scale, v_scale, products, out)
    vv = np.sum(out) if len(out) else np.float64(0)
    constant = None
    if vv > 0:
        constant = np.sum(products) / vv * (u_scale / v_scale) * (lhs_scale / rhs_scale)
    c = float(constant) if constant is not None else 0.0
    _misfit_into(lhs, lhs_size, r, r_size, paired, c, TINY, out)
    return ConditionFit(constant, out)
