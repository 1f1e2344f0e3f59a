"""Eq. (17) multiplied out, face by face, as one compiled float64 pass.

``revolution_formulas.face_residuals`` (the paper's formula (17) for surfaces of revolution,
compared with the mixed-area curvatures of [3]) evaluates about forty numpy passes over the
faces; ``face_residuals`` here does the same operations face by face, in the same order, so its
residuals have the same bits (tests/geometry/surfaces/test_ring_kernel.py). It holds the
formula only; the definition it is compared with is ``curvature`` / ``ring_kernel``.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from app.geometry.compiled import kernel

TINY = float(np.finfo(np.float64).tiny)


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
    """Rows: the K residual, the H residual and Δ = q1² − q0² of every face (see the caller)."""
    out = np.empty((3, p0.shape[0]))
    for k in range(p0.shape[0]):
        c = max(abs(p0[k]), abs(p1[k]))
        if not c > tiny:
            c = 1.0
        q0 = p0[k] / c
        q1 = p1[k] / c
        dp = q1 * q1 - q0 * q0
        sp = q1 * q1 + q0 * q0
        area_k = area[k] / c / c
        mag_k = area_magnitude[k] / c / c
        area_h = area[k] / c
        mag_h = area_magnitude[k] / c
        a0, a1 = n0[k], n1[k]
        k_scale = gauss_area_magnitude[k] * sp + mag_k * (a1 * a1 + a0 * a0)
        h_scale = mixed_area_magnitude[k] * sp + mag_h * (abs(q0 * a0) + abs(q1 * a1))
        k_res = abs(gauss_area[k] * dp - area_k * (a1 * a1 - a0 * a0))
        h_res = abs(mixed_area[k] * dp + area_h * (q0 * a0 - q1 * a1))
        out[0, k] = k_res / (k_scale if k_scale > tiny else tiny)
        out[1, k] = h_res / (h_scale if h_scale > tiny else tiny)
        out[2, k] = dp
    return out


def face_residuals(
    p0: Any, p1: Any, n0: Any, n1: Any, areas: Any
) -> tuple[Any, Any, np.ndarray[Any, np.dtype[np.bool_]]]:
    """``revolution_formulas.face_residuals`` in float64: (K residuals, H residuals, p1 ≠ p0)."""

    def f64(values: Any) -> Any:
        return np.ascontiguousarray(values, dtype=np.float64)

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
