"""Eq. (17) multiplied out, face by face, as one compiled float64 pass.

``revolution_formulas.face_residuals`` (the paper's formula (17) for surfaces of revolution,
compared with the mixed-area curvatures of [3]) evaluates about forty numpy passes over the
faces; ``face_residuals`` here does the same operations face by face, in the same order, so its
residuals have the same bits (tests/geometry/surfaces/test_ring_kernel.py). It holds the
formula only; the definition it is compared with is ``curvature`` / ``ring_kernel``.
"""

from __future__ import annotations

from typing import Any

import numba
import numpy as np

from app.geometry.compiled import kernel

TINY = float(np.finfo(np.float64).tiny)


@numba.njit(cache=True, inline="always", error_model="numpy")
def one_face(
    p0: float,
    p1: float,
    a0: float,
    a1: float,
    area: float,
    gauss_area: float,
    mixed_area: float,
    area_magnitude: float,
    gauss_area_magnitude: float,
    mixed_area_magnitude: float,
    tiny: float,
) -> tuple[float, float, float]:
    """One face: the K residual, the H residual and Δ = q1² − q0² (see the caller)."""
    c = max(abs(p0), abs(p1))
    if not c > tiny:
        c = 1.0
    q0 = p0 / c
    q1 = p1 / c
    dp = q1 * q1 - q0 * q0
    sp = q1 * q1 + q0 * q0
    area_k = area / c / c
    mag_k = area_magnitude / c / c
    area_h = area / c
    mag_h = area_magnitude / c
    k_scale = gauss_area_magnitude * sp + mag_k * (a1 * a1 + a0 * a0)
    h_scale = mixed_area_magnitude * sp + mag_h * (abs(q0 * a0) + abs(q1 * a1))
    k_res = abs(gauss_area * dp - area_k * (a1 * a1 - a0 * a0))
    h_res = abs(mixed_area * dp + area_h * (q0 * a0 - q1 * a1))
    return (
        k_res / (k_scale if k_scale > tiny else tiny),
        h_res / (h_scale if h_scale > tiny else tiny),
        dp,
    )


@kernel(
    "float64[:, :](float64[:], float64[:], float64[:], float64[:], float64[:], float64[:], "
    "float64[:], float64[:], float64[:], float64[:], float64)"
)
def _residuals(
    p0: Any,
    p1: Any,
    n0: Any,
    n1: Any,
    area: Any,
    gauss_area: Any,
    mixed_area: Any,
    area_magnitude: Any,
    gauss_area_magnitude: Any,
    mixed_area_magnitude: Any,
    tiny: float,
) -> Any:
    """Rows: the K residual, the H residual and Δ = q1² − q0² of every face (``one_face``)."""
    out = np.empty((3, p0.shape[0]))
    for k in range(p0.shape[0]):
        out[0, k], out[1, k], out[2, k] = one_face(
            p0[k],
            p1[k],
            n0[k],
            n1[k],
            area[k],
            gauss_area[k],
            mixed_area[k],
            area_magnitude[k],
            gauss_area_magnitude[k],
            mixed_area_magnitude[k],
            tiny,
        )
    return out


def face_residuals(
    p0: Any, p1: Any, n0: Any, n1: Any, areas: Any
) -> tuple[Any, Any, np.ndarray[Any, np.dtype[np.bool_]]]:
    """``revolution_formulas.face_residuals`` in float64: (K residuals, H residuals, p1 ≠ p0)."""

    def f64(values: Any) -> Any:
        return np.asarray(values, dtype=np.float64)

    rows = _residuals(
        f64(p0),
        f64(p1),
        f64(n0),
        f64(n1),
        f64(areas.area),
        f64(areas.gauss_area),
        f64(areas.mixed_area),
        f64(areas.area_magnitude),
        f64(areas.gauss_area_magnitude),
        f64(areas.mixed_area_magnitude),
        TINY,
    )
    return rows[0], rows[1], rows[2] != 0
