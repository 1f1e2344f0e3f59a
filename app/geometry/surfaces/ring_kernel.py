"""The mixed-area curvatures of one ring of rotational faces, as one compiled float64 pass.

``ring_curvature.ring_curvatures`` builds the faces between the angles 0 and θ in three
dimensions (``mesh.ring_faces``, ``(F, 4, 3)``) and evaluates the definition of [3] on them
(``curvature.face_curvatures``): about forty numpy passes over F faces, each into a fresh array.
``ring_curvatures`` here does the same arithmetic face by face in one compiled loop (no face array
is stored), operation for operation in the same order, so every area, curvature and magnitude has
the same bits as the numpy evaluation (tests/geometry/surfaces/test_ring_kernel.py). It is the
definition of Bobenko–Pottmann–Wallner [3] still, not the paper's formula (17), which
``revolution_formulas`` holds and the check compares with.
"""

from __future__ import annotations

import math
from typing import Any

import numba
import numpy as np

from app.geometry.compiled import (
    MAGNITUDE_BITS,
    SQUARES_HIGH,
    SQUARES_LOW,
    flat_rows,
    hypot,
    kernel,
    length3,
    running_largest,
)
from app.geometry.curvature import FaceCurvatures

TINY = float(np.finfo(np.float64).tiny)

#: Areas from which 1/area is finite with room (``_face_residuals``).
RECIPROCAL_FROM = 2.0**-1000

_FIELDS = 9


@numba.njit(cache=True, inline="always", error_model="numpy")
def _areas(
    f0: Any, f1: Any, f2: Any, f3: Any, g0: Any, g1: Any, g2: Any, g3: Any
) -> tuple[Any, Any, Any]:
    """A face's vector areas ½ (v2 − v0) × (v3 − v1) of f and of n, and the mixed one
    ¼ (d1(f) × d2(n) + d1(n) × d2(f)) of [3], from the corners of f (``f0`` … ``f3``) and of n
    (``g0`` … ``g3``), as ``curvature.face_curvatures`` writes them."""
    fa = (f2[0] - f0[0], f2[1] - f0[1], f2[2] - f0[2])
    fb = (f3[0] - f1[0], f3[1] - f1[1], f3[2] - f1[2])
    ga = (g2[0] - g0[0], g2[1] - g0[1], g2[2] - g0[2])
    gb = (g3[0] - g1[0], g3[1] - g1[1], g3[2] - g1[2])
    af = (
        (fa[1] * fb[2] - fa[2] * fb[1]) / 2,
        (fa[2] * fb[0] - fa[0] * fb[2]) / 2,
        (fa[0] * fb[1] - fa[1] * fb[0]) / 2,
    )
    an = (
        (ga[1] * gb[2] - ga[2] * gb[1]) / 2,
        (ga[2] * gb[0] - ga[0] * gb[2]) / 2,
        (ga[0] * gb[1] - ga[1] * gb[0]) / 2,
    )
    mixed = (
        ((fa[1] * gb[2] - fa[2] * gb[1]) + (ga[1] * fb[2] - ga[2] * fb[1])) / 4,
        ((fa[2] * gb[0] - fa[0] * gb[2]) + (ga[2] * fb[0] - ga[0] * fb[2])) / 4,
        ((fa[0] * gb[1] - fa[1] * gb[0]) + (ga[0] * fb[1] - ga[1] * fb[0])) / 4,
    )
    return af, an, mixed


@numba.njit(cache=True, inline="always", error_model="numpy")
def _magnitudes(
    f0: Any,
    f1: Any,
    f2: Any,
    f3: Any,
    g0: Any,
    g1: Any,
    g2: Any,
    g3: Any,
    af: Any,
    an: Any,
    tiny: float,
) -> tuple[float, float, float, float]:
    """The sizes of the numbers a face's areas come from (``mag_f``, ``mag_n``, ``mag_fn``: the
    1-norms |v0| + |v2| and |v1| + |v3| of each diagonal's corners, multiplied as the areas
    multiply them) and the parallel residual |a(f) × a(n)| / (mag_f · mag_n)."""
    f_1 = (abs(f0[0]) + abs(f0[1]) + abs(f0[2])) + (abs(f2[0]) + abs(f2[1]) + abs(f2[2]))
    f_2 = (abs(f1[0]) + abs(f1[1]) + abs(f1[2])) + (abs(f3[0]) + abs(f3[1]) + abs(f3[2]))
    n_1 = (abs(g0[0]) + abs(g0[1]) + abs(g0[2])) + (abs(g2[0]) + abs(g2[1]) + abs(g2[2]))
    n_2 = (abs(g1[0]) + abs(g1[1]) + abs(g1[2])) + (abs(g3[0]) + abs(g3[1]) + abs(g3[2]))
    mag_f = f_1 * f_2 / 2
    mag_n = n_1 * n_2 / 2
    mag_fn = (f_1 * n_2 + n_1 * f_2) / 4
    both = mag_f * mag_n
    crossed = (
        af[1] * an[2] - af[2] * an[1],
        af[2] * an[0] - af[0] * an[2],
        af[0] * an[1] - af[1] * an[0],
    )
    # a residual: the fast length (within 2 ulp of the nested hypot, ``compiled.length3``)
    parallel = length3(crossed[0], crossed[1], crossed[2]) / (both if both > tiny else tiny)
    return mag_f, mag_n, mag_fn, parallel


@numba.njit(cache=True, inline="always", error_model="numpy")
def _face(
    meridian: Any, gauss: Any, k: int, cos: float, sin: float, tiny: float
) -> tuple[float, float, float, float, float, float, float, float, float]:
    """Face k of the ring: A(f), A(n), A(f, n), K, H, parallel, and the three magnitudes.

    Face k has the corners v0 = (s, 0), v1 = (s, θ), v2 = (e, θ), v3 = (e, 0) of the edge s e
    (s = meridian[k], e = meridian[k + 1], (x, y) turned by the angle about the x-axis: (x, y·cos,
    y·sin)); its vector area is ½ (v2 − v0) × (v3 − v1), the mixed one ¼ (d1(f) × d2(n) + d1(n) ×
    d2(f)), all as ``curvature.face_curvatures`` writes them.
    """
    # the corners of f and of n (as ring_faces: (x, y·1, y·0), (x, y·cos, y·sin))
    sx, sy, ex, ey = meridian[k, 0], meridian[k, 1], meridian[k + 1, 0], meridian[k + 1, 1]
    f0 = (sx, sy * 1.0, sy * 0.0)
    f1 = (sx, sy * cos, sy * sin)
    f2 = (ex, ey * cos, ey * sin)
    f3 = (ex, ey * 1.0, ey * 0.0)
    sx, sy, ex, ey = gauss[k, 0], gauss[k, 1], gauss[k + 1, 0], gauss[k + 1, 1]
    g0 = (sx, sy * 1.0, sy * 0.0)
    g1 = (sx, sy * cos, sy * sin)
    g2 = (ex, ey * cos, ey * sin)
    g3 = (ex, ey * 1.0, ey * 0.0)
    af, an, mixed = _areas(f0, f1, f2, f3, g0, g1, g2, g3)
    size = hypot(hypot(af[0], af[1]), af[2])  # libm's, bit for bit (inline)
    unit = (af[0] / size, af[1] / size, af[2] / size)
    a_n = an[0] * unit[0] + an[1] * unit[1] + an[2] * unit[2]
    a_fn = mixed[0] * unit[0] + mixed[1] * unit[1] + mixed[2] * unit[2]
    mag_f, mag_n, mag_fn, parallel = _magnitudes(f0, f1, f2, f3, g0, g1, g2, g3, af, an, tiny)
    return size, a_n, a_fn, a_n / size, -a_fn / size, parallel, mag_f, mag_n, mag_fn


@kernel("float64[:, :](float64[:, :], float64[:, :], float64, float64, float64)")
def _ring(meridian: Any, gauss: Any, cos: float, sin: float, tiny: float) -> Any:
    """Rows: A(f), A(n), A(f, n), K, H, parallel, and the three magnitudes, per meridian edge
    (``_face``)."""
    faces = meridian.shape[0] - 1
    out = np.empty((_FIELDS, faces))
    for k in range(faces):
        values = _face(meridian, gauss, k, cos, sin, tiny)
        for row in range(_FIELDS):
            out[row, k] = values[row]
    return out


@numba.njit(cache=True, inline="always", error_model="numpy")
def _turned_corners(
    sx: float,
    sy: float,
    ex: float,
    ey: float,
    nsx: float,
    nsy: float,
    nex: float,
    ney: float,
    cos: float,
    sin: float,
) -> Any:
    """A face's corners (x, y·1, y·0), (x, y·cos, y·sin) of the meridian's edge (s, e) (f0 … f3)
    and of its Gauss image's edge (ns, ne) (g0 … g3), as ``_face`` turns them; y·1 is y."""
    return (
        (sx, sy, sy * 0.0),
        (sx, sy * cos, sy * sin),
        (ex, ey * cos, ey * sin),
        (ex, ey, ey * 0.0),
        (nsx, nsy, nsy * 0.0),
        (nsx, nsy * cos, nsy * sin),
        (nex, ney * cos, ney * sin),
        (nex, ney, ney * 0.0),
    )


@numba.njit(cache=True, inline="always", error_model="numpy")
def _corners(meridian: Any, gauss: Any, k: int, cos: float, sin: float) -> Any:
    """Face k's corners (``_turned_corners``) from the (n, 2) meridian and Gauss image."""
    return _turned_corners(
        meridian[k, 0],
        meridian[k, 1],
        meridian[k + 1, 0],
        meridian[k + 1, 1],
        gauss[k, 0],
        gauss[k, 1],
        gauss[k + 1, 0],
        gauss[k + 1, 1],
        cos,
        sin,
    )


@numba.njit(cache=True, inline="always", error_model="numpy")
def _split_corners(x: Any, y: Any, u: Any, v: Any, k: int, cos: float, sin: float) -> Any:
    """Face k's corners (``_turned_corners``) from the columns x, y (meridian) and u, v (Gauss
    image)."""
    return _turned_corners(x[k], y[k], x[k + 1], y[k + 1], u[k], v[k], u[k + 1], v[k + 1], cos, sin)


@numba.njit(cache=True, inline="always", error_model="numpy")
def _theorem_and_17(
    f0: Any,
    f3: Any,
    g0: Any,
    g3: Any,
    area: float,
    gauss_area: float,
    mixed_area: float,
    mag_f: float,
    mag_n: float,
    mag_fn: float,
    parallel: float,
    curvature: float,
    minimal: bool,
    tiny: float,
) -> tuple[float, float, float, float]:
    """A face's theorem residual (8 if ``minimal``, else 7 with K = ``curvature``; the larger
    with the parallel residual), then (17)'s K and H residuals and Δ, from the face's areas and
    magnitudes and the radii y of its corners f0, f3 and g0, g3."""
    sy, ey, nsy, ney = f0[1], f3[1], g0[1], g3[1]
    if minimal:
        own = abs(mixed_area) / mag_fn
    else:
        own = abs(gauss_area - curvature * area) / (mag_n + abs(curvature) * mag_f)
    theorem = own if (own >= parallel or own != own) else parallel  # np.maximum: NaN wins
    # (17), as ``equation_17_kernel.one_face`` with one reciprocal of c
    c = max(abs(sy), abs(ey))
    if not c > tiny:
        c = 1.0
    rc = 1.0 / c
    q0 = sy * rc
    q1 = ey * rc
    dp = q1 * q1 - q0 * q0
    sp = q1 * q1 + q0 * q0
    area_h = area * rc
    mag_h = mag_f * rc
    k_scale = mag_n * sp + mag_h * rc * (ney * ney + nsy * nsy)
    h_scale = mag_fn * sp + mag_h * (abs(q0 * nsy) + abs(q1 * ney))
    k_res = abs(gauss_area * dp - area_h * rc * (ney * ney - nsy * nsy))
    h_res = abs(mixed_area * dp + area_h * (q0 * nsy - q1 * ney))
    k_res = k_res / (k_scale if k_scale > tiny else tiny)
    h_res = h_res / (h_scale if h_scale > tiny else tiny)
    return theorem, k_res, h_res, dp


@numba.njit(cache=True, inline="always", error_model="numpy")
def _face_residuals(
    meridian: Any,
    gauss: Any,
    k: int,
    cos: float,
    sin: float,
    curvature: float,
    minimal: bool,
    tiny: float,
) -> tuple[float, float, float, float, float]:
    """Face k's residuals for the checks: (area, the theorem's, (17)'s K and H residuals, Δ).

    The same definition as ``_face`` followed by ``equation_17_kernel.one_face`` (the corners
    turned about the x-axis, the vector and mixed areas of [3], then (17) multiplied out), with
    the divisions by one number replaced by a product with its reciprocal: the unit normal's
    three quotients by |a(f)| one reciprocal (the products stay within the range where the
    quotients are: |a(f)_j| / |a(f)| <= 1), and the four quotients by c of (17)'s scaling
    one. 8 divisions a face instead of 17 (the
    ring's time at 10^6 vertices is mostly divisions), and |a(f)| as the square root of its sum
    of squares (``compiled.length3``) instead of two nested hypots; the residuals move by a few
    units of rounding of their scales, which only residuals at rounding level see
    (tests/geometry/surfaces/test_ring_kernel.py bounds the difference, tests/test_golden.py).
    """
    f0, f1, f2, f3, g0, g1, g2, g3 = _corners(meridian, gauss, k, cos, sin)
    af, an, mixed = _areas(f0, f1, f2, f3, g0, g1, g2, g3)
    # |a(f)| for residuals only: √ of the sum of squares (within 2 ulp of the nested hypots
    # ``_face`` takes, which cost ≈ 9 ns a face here against ≈ 2), hypot where squares underflow
    area = length3(af[0], af[1], af[2])
    if area > RECIPROCAL_FROM:  # the unit normal by one reciprocal (|a(f)| / area <= 1)
        inverse = 1.0 / area
        unit = (af[0] * inverse, af[1] * inverse, af[2] * inverse)
    else:  # 1/area would overflow
        unit = (af[0] / area, af[1] / area, af[2] / area)
    gauss_area = an[0] * unit[0] + an[1] * unit[1] + an[2] * unit[2]
    mixed_area = mixed[0] * unit[0] + mixed[1] * unit[1] + mixed[2] * unit[2]
    mag_f, mag_n, mag_fn, parallel = _magnitudes(f0, f1, f2, f3, g0, g1, g2, g3, af, an, tiny)
    theorem, k_res, h_res, dp = _theorem_and_17(
        f0,
        f3,
        g0,
        g3,
        area,
        gauss_area,
        mixed_area,
        mag_f,
        mag_n,
        mag_fn,
        parallel,
        curvature,
        minimal,
        tiny,
    )
    return area, theorem, k_res, h_res, dp


@kernel(
    "Tuple((float64[:, :], int64, boolean, float64, float64))"
    "(float64[:, :], float64[:, :], float64, float64, float64, boolean, float64, boolean)"
)
def _ring_checks(
    meridian: Any,
    gauss: Any,
    cos: float,
    sin: float,
    curvature: float,
    minimal: bool,
    tiny: float,
    store: bool,
) -> tuple[Any, int, bool, float, float]:
    """The Section 5 residuals of one ring in one pass, without its nine curvature rows.

    Row 0: the theorem's residual per face, max(constant curvature or H = 0, parallel), as
    ``constant_curvature_residuals(·, curvature)`` or ``minimal_residuals`` with
    ``np.maximum``; row 1: (17) per face, max of its K and H residuals, 0 where it is 0/0
    (``_face_residuals``). Then the number of such faces and whether every face has a positive
    area (if not, the caller takes the numpy path, which names the face). The rows are stored
    if ``store`` (else empty); last, the largest of each row (NaN if one is NaN).
    """
    faces = meridian.shape[0] - 1
    out = np.empty((2, faces if store else 0))
    skipped = 0
    largest, largest_17 = 0.0, 0.0
    for k in range(faces):
        area, theorem, k_res, h_res, dp = _face_residuals(
            meridian, gauss, k, cos, sin, curvature, minimal, tiny
        )
        if not area > 0:
            return out, skipped, False, largest, largest_17
        equation_17 = 0.0
        if dp != 0:
            equation_17 = k_res if (k_res >= h_res or k_res != k_res) else h_res
        else:
            skipped += 1
        largest = running_largest(theorem, largest)
        largest_17 = running_largest(equation_17, largest_17)
        if store:
            out[0, k] = theorem
            out[1, k] = equation_17
    return out, skipped, True, largest, largest_17


#: Faces a block of ``_ring_largest`` (six 4 KB rows, cache-resident).
RING_BLOCK = 512


@numba.njit(cache=True, inline="always", error_model="numpy")
def _face_unbranched(
    x: Any,
    y: Any,
    u: Any,
    v: Any,
    k: int,
    cos: float,
    sin: float,
    curvature: float,
    minimal: bool,
    tiny: float,
) -> tuple[float, float, float, float, bool]:
    """``_face_residuals`` on its usual branch, with no branch the compiler cannot make a
    select: (area, the theorem's residual, (17)'s residual (0 where 0/0), Δ, usual).

    The same operations in the same order as ``_face_residuals`` takes when both of its
    lengths are square roots of sums of squares (``compiled.length3``'s unscaled branch) and
    the unit normal is a product with 1/|a(f)| (|a(f)| > ``RECIPROCAL_FROM``): ``usual`` says
    whether the face is on that branch; the other faces' numbers are to be taken from
    ``_face_residuals`` (``_ring_largest``). Without branches, the compiler runs four faces at
    once in the vector registers (the quotients and square roots are IEEE's, correctly rounded
    in each lane, and numba contracts no product into an FMA): the same bits.
    """
    f0, f1, f2, f3, g0, g1, g2, g3 = _split_corners(x, y, u, v, k, cos, sin)
    af, an, mixed = _areas(f0, f1, f2, f3, g0, g1, g2, g3)
    big = max(abs(af[0]), abs(af[1]), abs(af[2]))
    area = math.sqrt(af[0] * af[0] + af[1] * af[1] + af[2] * af[2])
    inverse = 1.0 / area
    unit = (af[0] * inverse, af[1] * inverse, af[2] * inverse)
    gauss_area = an[0] * unit[0] + an[1] * unit[1] + an[2] * unit[2]
    mixed_area = mixed[0] * unit[0] + mixed[1] * unit[1] + mixed[2] * unit[2]
    # ``_magnitudes`` with its length3 on the unscaled branch
    f_1 = (abs(f0[0]) + abs(f0[1]) + abs(f0[2])) + (abs(f2[0]) + abs(f2[1]) + abs(f2[2]))
    f_2 = (abs(f1[0]) + abs(f1[1]) + abs(f1[2])) + (abs(f3[0]) + abs(f3[1]) + abs(f3[2]))
    n_1 = (abs(g0[0]) + abs(g0[1]) + abs(g0[2])) + (abs(g2[0]) + abs(g2[1]) + abs(g2[2]))
    n_2 = (abs(g1[0]) + abs(g1[1]) + abs(g1[2])) + (abs(g3[0]) + abs(g3[1]) + abs(g3[2]))
    mag_f = f_1 * f_2 / 2
    mag_n = n_1 * n_2 / 2
    mag_fn = (f_1 * n_2 + n_1 * f_2) / 4
    both = mag_f * mag_n
    c0 = af[1] * an[2] - af[2] * an[1]
    c1 = af[2] * an[0] - af[0] * an[2]
    c2 = af[0] * an[1] - af[1] * an[0]
    crossed_big = max(abs(c0), abs(c1), abs(c2))
    crossed = math.sqrt(c0 * c0 + c1 * c1 + c2 * c2)
    parallel = crossed / (both if both > tiny else tiny)
    usual = (
        (SQUARES_LOW < big < SQUARES_HIGH)
        and (SQUARES_LOW < crossed_big < SQUARES_HIGH or crossed_big == 0)
        and area > RECIPROCAL_FROM
    )
    theorem, k_res, h_res, dp = _theorem_and_17(
        f0,
        f3,
        g0,
        g3,
        area,
        gauss_area,
        mixed_area,
        mag_f,
        mag_n,
        mag_fn,
        parallel,
        curvature,
        minimal,
        tiny,
    )
    equation_17 = k_res if (k_res >= h_res or k_res != k_res) else h_res
    return area, theorem, (equation_17 if dp != 0 else 0.0), dp, usual


@numba.njit(cache=True, error_model="numpy")
def _faces_unbranched(
    x: Any,
    y: Any,
    u: Any,
    v: Any,
    count: int,
    cos: float,
    sin: float,
    curvature: float,
    minimal: bool,
    tiny: float,
    areas: Any,
    theorems: Any,
    equations: Any,
    differences: Any,
    usual: Any,
) -> None:
    """``_face_unbranched`` on faces 0 .. len(meridian) − 2 into the rows given (a function of
    its own: the compiler vectorizes this loop alone)."""
    for j in range(count):
        found = _face_unbranched(x, y, u, v, j, cos, sin, curvature, minimal, tiny)
        areas[j], theorems[j], equations[j], differences[j], usual[j] = found


@numba.njit(cache=True, error_model="numpy")
def _block_largest(
    count: int, areas: Any, theorems: Any, equations: Any, differences: Any, usual: Any
) -> tuple[bool, int, float, float]:
    """A block's faces reduced without branches (the compiler vectorizes it): whether every
    face is on the usual branch with a positive area and no residual is NaN (if not, the caller
    takes the block face by face), the faces where Δ = 0 and the largest |residual| of each row.

    The largest is taken on the bit patterns of the magnitudes: for floats without NaN and
    sign, the order of their patterns as integers is the order of the numbers, so the largest
    pattern is that of the largest number (the same value as the running ``np.maximum``; a
    maximum of integers needs no fast-math flags to become vector instructions)."""
    theorem_bits, equation_bits = theorems.view(np.int64), equations.view(np.int64)
    plain = True
    zeros = 0
    top, top_17 = 0, 0
    for j in range(count):
        theorem, equation_17 = theorems[j], equations[j]
        plain &= usual[j] & (areas[j] > 0) & (theorem == theorem) & (equation_17 == equation_17)
        zeros += differences[j] == 0
        bits = theorem_bits[j] & MAGNITUDE_BITS
        top = bits if bits > top else top
        bits = equation_bits[j] & MAGNITUDE_BITS
        top_17 = bits if bits > top_17 else top_17
    found = np.empty(2, dtype=np.int64)
    found[0], found[1] = top, top_17
    values = found.view(np.float64)
    return plain, zeros, values[0], values[1]


@kernel(
    "Tuple((int64, boolean, float64, float64))"
    "(float64[:, ::1], float64[:, ::1], float64, float64, float64, boolean, float64)"
)
def _ring_largest(
    meridian: Any,
    gauss: Any,
    cos: float,
    sin: float,
    curvature: float,
    minimal: bool,
    tiny: float,
) -> tuple[int, bool, float, float]:
    """``_ring_checks`` without rows, a block of ``RING_BLOCK`` faces at a time: the faces'
    numbers in a loop without branches (``_face_unbranched``, vectorized by the compiler),
    then, face by face in order, those off its branch recomputed by ``_face_residuals``, the
    test of a positive area, the 0/0 count and the running largest, as ``_ring_checks`` takes
    them: the same (skipped, valid, largest, largest (17)). ``meridian`` and ``gauss`` are
    C-contiguous (the compiler reads their rows as pairs)."""
    faces = meridian.shape[0] - 1
    x, y = np.empty(RING_BLOCK + 1), np.empty(RING_BLOCK + 1)
    u, v = np.empty(RING_BLOCK + 1), np.empty(RING_BLOCK + 1)
    areas = np.empty(RING_BLOCK)
    theorems = np.empty(RING_BLOCK)
    equations = np.empty(RING_BLOCK)
    differences = np.empty(RING_BLOCK)
    usual = np.empty(RING_BLOCK, dtype=np.bool_)
    skipped = 0
    largest, largest_17 = 0.0, 0.0
    for start in range(0, faces, RING_BLOCK):
        count = min(RING_BLOCK, faces - start)
        rows, images = flat_rows(meridian, start, count + 1), flat_rows(gauss, start, count + 1)
        for j in range(count + 1):  # the block's columns, contiguous
            x[j], y[j] = rows[2 * j], rows[2 * j + 1]
            u[j], v[j] = images[2 * j], images[2 * j + 1]
        _faces_unbranched(
            x,
            y,
            u,
            v,
            count,
            cos,
            sin,
            curvature,
            minimal,
            tiny,
            areas,
            theorems,
            equations,
            differences,
            usual,
        )
        plain, zeros, top, top_17 = _block_largest(
            count, areas, theorems, equations, differences, usual
        )
        if plain:  # every face on the usual branch, with area, no NaN: the block at once
            skipped += zeros
            largest = running_largest(top, largest)
            largest_17 = running_largest(top_17, largest_17)
            continue
        for j in range(count):
            area, theorem, equation_17, dp = areas[j], theorems[j], equations[j], differences[j]
            if not usual[j]:  # a length or 1/|a(f)| off the usual branch: the scalar face
                area, theorem, k_res, h_res, dp = _face_residuals(
                    meridian, gauss, start + j, cos, sin, curvature, minimal, tiny
                )
                equation_17 = 0.0
                if dp != 0:
                    equation_17 = k_res if (k_res >= h_res or k_res != k_res) else h_res
            if not area > 0:
                return skipped, False, largest, largest_17
            if dp == 0:
                skipped += 1
            largest = running_largest(theorem, largest)
            largest_17 = running_largest(equation_17, largest_17)
    return skipped, True, largest, largest_17


def ring_curvatures(meridian: Any, gauss: Any, cos: float, sin: float) -> FaceCurvatures | None:
    """``FaceCurvatures`` of the ring between the angles 0 and θ (cos θ, sin θ given).

    None when a face has no positive area: the caller's numpy path then reports it as a
    ``DomainError`` naming the face, exactly as before.
    """
    rows = _ring(
        np.asarray(meridian, dtype=np.float64),
        np.asarray(gauss, dtype=np.float64),
        float(cos),
        float(sin),
        TINY,
    )
    if rows.shape[1] and not bool(np.all(rows[0] > 0)):
        return None
    return FaceCurvatures(*rows)


def ring_checks(
    meridian: Any, gauss: Any, cos: float, sin: float, curvature: float | None
) -> tuple[Any, Any, int] | None:
    """(theorem residuals, (17) residuals, faces where (17) is 0/0) of one ring, float64.

    The theorem's residual is max(constant curvature ``curvature``, parallel) (Theorem 7) or,
    for ``curvature=None``, max(H = 0, parallel) (Theorem 8), as ``d4b.curvature.evaluate``
    computes them from ``ring_curvatures``; the same bits (tests/geometry/surfaces/
    test_ring_kernel.py). None when a face has no positive area (the numpy path names it).
    """
    rows, skipped, valid, _, _ = _one_ring(meridian, gauss, cos, sin, curvature, True)
    if not valid:
        return None
    return rows[0], rows[1], skipped


def ring_largest(
    meridian: Any, gauss: Any, cos: float, sin: float, curvature: float | None
) -> tuple[float, float, int] | None:
    """``ring_checks`` without the rows: the largest theorem residual, the largest (17) residual
    (NaN if one is NaN) and the faces where (17) is 0/0; None as ``ring_checks``."""
    m, g = np.asarray(meridian, dtype=np.float64), np.asarray(gauss, dtype=np.float64)
    if m.flags.c_contiguous and g.flags.c_contiguous and m.ndim == g.ndim == 2:
        skipped, valid, largest, largest_17 = _ring_largest(
            m,
            g,
            float(cos),
            float(sin),
            0.0 if curvature is None else float(curvature),
            curvature is None,
            TINY,
        )
    else:
        _, skipped, valid, largest, largest_17 = _one_ring(m, g, cos, sin, curvature, False)
    return (float(largest), float(largest_17), int(skipped)) if valid else None


def _one_ring(
    meridian: Any, gauss: Any, cos: float, sin: float, curvature: float | None, rows: bool
) -> Any:
    """``_ring_checks`` on one ring's float64 arrays (``rows``: keep the residual rows)."""
    return _ring_checks(
        np.asarray(meridian, dtype=np.float64),
        np.asarray(gauss, dtype=np.float64),
        float(cos),
        float(sin),
        0.0 if curvature is None else float(curvature),
        curvature is None,
        TINY,
        rows,
    )
