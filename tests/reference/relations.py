"""An independent high-precision evaluation of (D1), (D3), (2) and (7) on a polygon: plain mpmath.

Same definitions as docs/checks.md (weighted least squares, each equation divided by the
magnitude of the numbers its left side is computed from; residual relative to the magnitudes of
both sides), different algorithm: the quantities are computed vertex by vertex from a dict
i -> (x, y), and the constants solve the weighted system with ``mpmath.qr_solve``.
"""

from __future__ import annotations

import mpmath


def _context(dps: int) -> mpmath.MPContext:
    ctx = mpmath.MPContext()
    ctx.dps = dps
    return ctx


def _quantities(ctx, p: dict):
    """Per index i (sorted): Δ²y, l, A and their magnitudes, as dicts keyed by i."""
    keys = sorted(p)
    x = {i: ctx.mpf(p[i][0]) for i in keys}
    y = {i: ctx.mpf(p[i][1]) for i in keys}
    inner = keys[:-1]
    length = {i: ctx.sqrt((x[i + 1] - x[i]) ** 2 + (y[i + 1] - y[i]) ** 2) for i in inner}
    length_mag = {i: abs(x[i]) + abs(y[i]) + abs(x[i + 1]) + abs(y[i + 1]) for i in inner}
    area = {i: (y[i] + y[i + 1]) * (x[i + 1] - x[i]) / 2 for i in inner}
    area_mag = {i: (abs(y[i]) + abs(y[i + 1])) * (abs(x[i]) + abs(x[i + 1])) / 2 for i in inner}
    second = {i: y[i + 2] - 2 * y[i + 1] + y[i] for i in keys[:-2]}
    second_mag = {i: abs(y[i + 2]) + 2 * abs(y[i + 1]) + abs(y[i]) for i in keys[:-2]}
    return keys, second, second_mag, length, length_mag, area, area_mag


def _fit(ctx, rows: list[tuple]):
    """rows: (lhs, lhs_magnitude, [(rhs_k, rhs_magnitude_k), ...]) -> (constants, residuals)."""
    columns = len(rows[0][2])
    a = ctx.matrix(len(rows), columns)
    b = ctx.matrix(len(rows), 1)
    for r, (lhs, weight, terms) in enumerate(rows):
        for k, (rhs, _) in enumerate(terms):
            a[r, k] = rhs / weight
        b[r] = lhs / weight
    solution, _ = ctx.qr_solve(a, b)
    constants = [solution[k] for k in range(columns)]
    residuals = []
    for lhs, weight, terms in rows:
        fitted = sum(c * rhs for c, (rhs, _) in zip(constants, terms, strict=True))
        scale = weight + sum(abs(c) * size for c, (_, size) in zip(constants, terms, strict=True))
        residuals.append(abs(lhs - fitted) / scale)
    return constants, residuals


def conditions(p: dict, dps: int = 60) -> dict[str, tuple[list, object]]:
    """{"d1", "d3", "equation-2", "equation-7"} -> (constants, largest residual)."""
    ctx = _context(dps)
    keys, second, second_mag, length, length_mag, area, area_mag = _quantities(ctx, p)
    out = {}
    rows = [
        (second[i], second_mag[i], [(length[i] + length[i + 1], length_mag[i] + length_mag[i + 1])])
        for i in keys[:-2]
    ]
    constants, residuals = _fit(ctx, rows)
    out["d1"] = (constants, max(residuals))
    rows = [(area[i], area_mag[i], [(length[i], length_mag[i])]) for i in keys[:-1]]
    constants, residuals = _fit(ctx, rows)
    out["d3"] = (constants, max(residuals))
    rows = [
        (second[i], second_mag[i], [(area[i] + area[i + 1], area_mag[i] + area_mag[i + 1])])
        for i in keys[:-2]
    ]
    constants, residuals = _fit(ctx, rows)
    out["equation-2"] = (constants, max(residuals))
    rows = []
    for i in keys[:-2]:
        first, next_ = (area[i], area_mag[i]), (area[i + 1], area_mag[i + 1])
        terms = [first, next_] if i % 2 == 0 else [next_, first]  # c_1 multiplies terms[0]
        rows.append((second[i], second_mag[i], terms))
    constants, residuals = _fit(ctx, rows)
    out["equation-7"] = (constants, max(residuals))
    return out


# --- the curvature columns: H = 0 and K constant ------------------------------------------------
#
# Faces of the surfaces of revolution on one ring (angle π/16) from tests.reference.curvature
# (rotation matrices, Newell's area, the mixed area by polarization); the residuals use the same
# definitions as docs/checks.md: each area against the magnitude of the numbers it is computed
# from (products of the absolute coordinates of the diagonals' end points).

RING_ANGLE_DIVISOR = 16


def _faces(ctx, meridian: dict, gauss: dict):
    """[(f, n)] for the faces of consecutive indices, f and n lists of four 3-vectors."""
    from tests.reference import curvature

    angle = ctx.pi / RING_ANGLE_DIVISOR
    keys = sorted(meridian)
    return [
        (
            curvature.face(ctx, meridian[i], meridian[i + 1], angle),
            curvature.face(ctx, gauss[i], gauss[i + 1], angle),
        )
        for i in keys[:-1]
    ]


def _abs_sum(v) -> object:
    return abs(v[0]) + abs(v[1]) + abs(v[2])


def _areas(ctx, f, n):
    """A(f) > 0, A(n), A(f, n) along f's normal and their magnitudes, and the parallel defect."""
    from tests.reference import curvature

    area_f, area_n = curvature.newell(ctx, f), curvature.newell(ctx, n)
    unit = area_f / ctx.norm(area_f)
    plus = curvature.newell(ctx, [a + b for a, b in zip(f, n, strict=True)])
    minus = curvature.newell(ctx, [a - b for a, b in zip(f, n, strict=True)])
    mixed = ctx.fdot((plus - minus) / 4, unit)
    f1, f2 = _abs_sum(f[0]) + _abs_sum(f[2]), _abs_sum(f[1]) + _abs_sum(f[3])
    n1, n2 = _abs_sum(n[0]) + _abs_sum(n[2]), _abs_sum(n[1]) + _abs_sum(n[3])
    mag_f, mag_n, mag_fn = f1 * f2 / 2, n1 * n2 / 2, (f1 * n2 + n1 * f2) / 4
    crossed = (
        area_f[1] * area_n[2] - area_f[2] * area_n[1],
        (area_f[2] * area_n[0] - area_f[0] * area_n[2]),
        area_f[0] * area_n[1] - area_f[1] * area_n[0],
    )
    parallel = ctx.sqrt(sum(c * c for c in crossed)) / (mag_f * mag_n)
    return ctx.norm(area_f), ctx.fdot(area_n, unit), mixed, mag_f, mag_n, mag_fn, parallel


def mean_curvature_cell(p: dict, gauss: dict | None, dps: int = 60):
    """(a, largest residual) of the H = 0 column for a meridian p (dict i -> (x, y)).

    ``gauss`` None: the circumscribed Gauss image built from p (tangents at the edges' unit
    normals meet; ``lu_solve``) on the interior vertices, the residual of each face multiplied by
    the worst resolution |e| / (|p_k| + |p_{k+1}|) of the three edges it is built from.
    """
    from tests.reference import curvature

    ctx = _context(dps)
    p = {i: (ctx.mpf(v[0]), ctx.mpf(v[1])) for i, v in p.items()}
    keys = sorted(p)
    resolution = None
    if gauss is None:
        gauss = curvature.circumscribed(ctx, curvature.contact_points(ctx, p))
        res = {}
        for i in keys[:-1]:
            ex, ey = p[i + 1][0] - p[i][0], p[i + 1][1] - p[i][1]
            size = abs(p[i][0]) + abs(p[i][1]) + abs(p[i + 1][0]) + abs(p[i + 1][1])
            res[i] = ctx.sqrt(ex * ex + ey * ey) / size
        resolution = {i: min(res[i - 1], res[i], res[i + 1]) for i in keys[1:-2]}
        p = {i: p[i] for i in keys[1:-1]}
    else:
        gauss = {i: (ctx.mpf(v[0]), ctx.mpf(v[1])) for i, v in gauss.items()}
    residuals = []
    for i, (f, n) in zip(sorted(p)[:-1], _faces(ctx, p, gauss), strict=True):
        _, _, mixed, _, _, mag_fn, parallel = _areas(ctx, f, n)
        r = max(abs(mixed) / mag_fn, parallel)
        residuals.append(r * resolution[i] if resolution is not None else r)
    products = [p[i][1] * gauss[i][1] for i in sorted(p)]
    a = None  # undefined when a vertex lies on the axis (it would take all the weight)
    if all(v != 0 for v in products):
        (a,), _ = _fit(ctx, [(v, abs(v), [(1, 0)]) for v in products])
    return a, max(residuals)


def gaussian_curvature_cell(tractrix: dict, gauss: dict, dps: int = 60):
    """(K, largest residual) of the K constant column: K fitted by weighted least squares."""
    ctx = _context(dps)
    tractrix = {i: (ctx.mpf(v[0]), ctx.mpf(v[1])) for i, v in tractrix.items()}
    gauss = {i: (ctx.mpf(v[0]), ctx.mpf(v[1])) for i, v in gauss.items()}
    rows, parallel = [], []
    for f, n in _faces(ctx, tractrix, gauss):
        a_f, a_n, _, mag_f, mag_n, _, defect = _areas(ctx, f, n)
        rows.append((a_n, mag_n, [(a_f, mag_f)]))
        parallel.append(defect)
    (K,), residuals = _fit(ctx, rows)
    return K, max(max(residuals), max(parallel))
