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
