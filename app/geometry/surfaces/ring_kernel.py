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

import numpy as np

from app.geometry.compiled import kernel, length3
from app.geometry.curvature import FaceCurvatures

TINY = float(np.finfo(np.float64).tiny)

_FIELDS = 9


@kernel("float64[:, :](float64[:, :], float64[:, :], float64, float64, float64)")
def _ring(meridian: Any, gauss: Any, cos: float, sin: float, tiny: float) -> Any:
    """Rows: A(f), A(n), A(f, n), K, H, parallel, and the three magnitudes, per meridian edge.

    Face k has the corners v0 = (s, 0), v1 = (s, θ), v2 = (e, θ), v3 = (e, 0) of the edge s e
    (s = meridian[k], e = meridian[k + 1], (x, y) turned by the angle about the x-axis: (x, y·cos,
    y·sin)); its vector area is ½ (v2 − v0) × (v3 − v1), the mixed one ¼ (d1(f) × d2(n) + d1(n) ×
    d2(f)), all as ``curvature.face_curvatures`` writes them.
    """
    faces = meridian.shape[0] - 1
    out = np.empty((_FIELDS, faces))
    for k in range(faces):
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
        # diagonals v2 − v0, v3 − v1
        fa = (f2[0] - f0[0], f2[1] - f0[1], f2[2] - f0[2])
        fb = (f3[0] - f1[0], f3[1] - f1[1], f3[2] - f1[2])
        ga = (g2[0] - g0[0], g2[1] - g0[1], g2[2] - g0[2])
        gb = (g3[0] - g1[0], g3[1] - g1[1], g3[2] - g1[2])
        # vector areas ½ fa × fb, ½ ga × gb and the mixed ¼ (fa × gb + ga × fb)
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
        size = math.hypot(math.hypot(af[0], af[1]), af[2])
        unit = (af[0] / size, af[1] / size, af[2] / size)
        a_n = an[0] * unit[0] + an[1] * unit[1] + an[2] * unit[2]
        a_fn = mixed[0] * unit[0] + mixed[1] * unit[1] + mixed[2] * unit[2]
        # sizes of the numbers each diagonal comes from: |v0| + |v2|, |v1| + |v3| (1-norms)
        f_1 = (abs(f0[0]) + abs(f0[1]) + abs(f0[2])) + (abs(f2[0]) + abs(f2[1]) + abs(f2[2]))
        f_2 = (abs(f1[0]) + abs(f1[1]) + abs(f1[2])) + (abs(f3[0]) + abs(f3[1]) + abs(f3[2]))
        n_1 = (abs(g0[0]) + abs(g0[1]) + abs(g0[2])) + (abs(g2[0]) + abs(g2[1]) + abs(g2[2]))
        n_2 = (abs(g1[0]) + abs(g1[1]) + abs(g1[2])) + (abs(g3[0]) + abs(g3[1]) + abs(g3[2]))
        mag_f = f_1 * f_2 / 2
        mag_n = n_1 * n_2 / 2
        both = mag_f * mag_n
        crossed = (
            af[1] * an[2] - af[2] * an[1],
            af[2] * an[0] - af[0] * an[2],
            af[0] * an[1] - af[1] * an[0],
        )
        out[0, k] = size
        out[1, k] = a_n
        out[2, k] = a_fn
        out[3, k] = a_n / size
        out[4, k] = -a_fn / size
        # a residual: the fast length (within 2 ulp of the nested hypot, ``compiled.length3``)
        out[5, k] = length3(crossed[0], crossed[1], crossed[2]) / (both if both > tiny else tiny)
        out[6, k] = mag_f
        out[7, k] = mag_n
        out[8, k] = (f_1 * n_2 + n_1 * f_2) / 4
    return out


def ring_curvatures(meridian: Any, gauss: Any, cos: float, sin: float) -> FaceCurvatures | None:
    """``FaceCurvatures`` of the ring between the angles 0 and θ (cos θ, sin θ given).

    None when a face has no positive area: the caller's numpy path then reports it as a
    ``DomainError`` naming the face, exactly as before.
    """
    rows = _ring(
        np.ascontiguousarray(meridian, dtype=np.float64),
        np.ascontiguousarray(gauss, dtype=np.float64),
        float(cos),
        float(sin),
        TINY,
    )
    if rows.shape[1] and not bool(np.all(rows[0] > 0)):
        return None
    return FaceCurvatures(*rows)
