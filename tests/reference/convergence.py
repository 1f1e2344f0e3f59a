"""An independent refinement study of Theorems 14 and 15: plain mpmath, no code from app.

Different algorithms on purpose:
- the vertices come from ``tests.reference.d4b`` (rotation centres by ``lu_solve``, rotations
  by angle);
- the smooth interpolating curves are the *printed* power forms of Theorems 14 and 15, not the
  cosh/tanh forms;
- a sup over the compact set is not read off a grid: the largest of a coarse grid is refined by
  golden-section search on its neighbouring cells (so it is the true maximum, up to the grid's
  resolution of local maxima);
- the distance from a point to a smooth curve is minimized by golden-section search in the curve
  parameter around the best point of a dense grid (no root finding, no formula for the foot).

``study(kind, ...)`` returns, per level, d and the sup error of each measure, and
``order(steps, errors)`` the least-squares slope of ln(error) against ln(d).
"""

from __future__ import annotations

import mpmath

from tests.reference import d4b as reference_d4b

GOLDEN = (mpmath.sqrt(5) - 1) / 2


def _golden_max(ctx, f, a, b, iterations: int = 50):
    """The largest value of f on [a, b] by golden-section search (f unimodal there)."""
    g = ctx.mpf(GOLDEN)
    c, d = b - g * (b - a), a + g * (b - a)
    fc, fd = f(c), f(d)
    for _ in range(iterations):
        if fc > fd:
            b, d, fd = d, c, fc
            c = b - g * (b - a)
            fc = f(c)
        else:
            a, c, fc = c, d, fd
            d = a + g * (b - a)
            fd = f(d)
    return max(fc, fd, f(a), f(b))


def _sup(ctx, f, lo, hi, grid: int = 41, refine: bool = True):
    """sup of f over [lo, hi]: a grid, then golden-section refinement around its 3 best cells."""
    xs = [lo + (hi - lo) * k / (grid - 1) for k in range(grid)]
    values = [f(x) for x in xs]
    best = sorted(range(grid), key=lambda k: values[k], reverse=True)[:3] if refine else []
    out = max(values)
    for k in best:
        a, b = xs[max(k - 1, 0)], xs[min(k + 1, grid - 1)]
        out = max(out, _golden_max(ctx, f, a, b))
    return out


def _distance(ctx, point, curve, s_lo, s_hi, grid: int = 80):
    """min over s in [s_lo, s_hi] of |point − curve(s)|: dense grid, then golden section."""
    qx, qy = point

    def dist(s):
        x, y = curve(s)
        return ctx.hypot(x - qx, y - qy)

    ss = [s_lo + (s_hi - s_lo) * k / grid for k in range(grid + 1)]
    values = [dist(s) for s in ss]
    k = min(range(len(ss)), key=lambda j: values[j])
    a, b = ss[max(k - 1, 0)], ss[min(k + 1, grid)]
    best = -_golden_max(ctx, lambda s: -dist(s), a, b)
    return min(best, values[k])


def study(kind: str, h: str, d0: str, levels: int, x_max: str, dps: int = 20):
    """[(d, {measure: sup error})] for kind ``theorem-14`` or ``theorem-15``."""
    ctx = mpmath.MPContext()
    ctx.dps = dps
    hh, big_x = ctx.mpf(h), ctx.mpf(x_max)
    out = []
    for k in range(levels):
        d = ctx.mpf(d0) / 2**k
        # vertices with |(2i − 1)d| <= x_max
        i_min = int(ctx.ceil((1 - big_x / d) / 2))
        i_max = int(ctx.floor((1 + big_x / d) / 2))
        centres, tips, axis = reference_d4b.construct(h, ctx.nstr(d, dps), None, i_min, i_max, dps)
        if kind == "theorem-14":
            out.append((d, _catenary_level(ctx, hh, d, big_x, centres)))
        else:
            out.append((d, _tractrix_level(ctx, hh, d, big_x, tips, axis)))
    return out


def _catenary_level(ctx, h, d, big_x, centres):
    def curve(x):  # Theorem 14 as printed
        up, down = (x + d) / (2 * d), (x - d) / (2 * d)
        return (h - d) ** up / (2 * (h + d) ** down) + (h + d) ** up / (2 * (h - d) ** down)

    def catenary(s):
        return s, h * ctx.cosh(s / h)

    def parametric(x):
        return abs(curve(x) - h * ctx.cosh(x / h))

    def to_curve(x):
        return _distance(ctx, (x, curve(x)), catenary, x - h / 2, x + h / 2)

    def limit_21(x):
        return abs((1 - d / h) ** ((x + d) / (2 * d)) - ctx.exp(-x / (2 * h)))

    vertices = max(abs(p[1] - h * ctx.cosh(p[0] / h)) for p in centres.values())
    return {
        "parametric": _sup(ctx, parametric, -big_x, big_x),
        "distance": _sup(ctx, to_curve, -big_x, big_x, refine=False),
        "vertices": vertices,
        "equation-21": _sup(ctx, limit_21, -big_x, big_x),
    }


def _tractrix_level(ctx, h, d, big_x, tips, axis):
    def curve(x):  # Theorem 15 as printed
        t = (x + d) / d
        a, b = (h - d) ** t, (h + d) ** t
        return h * (a - b) / (a + b) + x + d, 2 * h * (h * h - d * d) ** (t / 2) / (a + b)

    def tractrix(s):
        return s - h * ctx.tanh(s / h), h / ctx.cosh(s / h)

    def parametric(x):
        cx, cy = curve(x)
        tx, ty = tractrix(x)
        return ctx.hypot(cx - tx, cy - ty)

    def to_curve(x):
        return _distance(ctx, curve(x), tractrix, x - h, x + h)

    def ineq_y(x):
        ratio = (1 - d / h) / (1 + d / h)
        f = ratio ** ((x + d) / (2 * d))
        return abs(1 / (f + 1 / f) - 1 / (2 * ctx.cosh(x / h)))

    def ineq_x(x):
        t = (x + d) / d
        f, g = (1 - d / h) ** t, (1 + d / h) ** t
        return abs((f - g) / (f + g) + ctx.tanh(x / h))

    natural = max(
        ctx.hypot(tip[0] - tractrix(axis[i][0])[0], tip[1] - tractrix(axis[i][0])[1])
        for i, tip in tips.items()
    )
    distance = max(
        _distance(ctx, tip, tractrix, axis[i][0] - h, axis[i][0] + h) for i, tip in tips.items()
    )
    return {
        "parametric": _sup(ctx, parametric, -big_x, big_x),
        "distance": _sup(ctx, to_curve, -big_x, big_x, refine=False),
        "vertices-distance": distance,
        "natural": natural,
        "inequality-22-y": _sup(ctx, ineq_y, -big_x, big_x),
        "inequality-22-x": _sup(ctx, ineq_x, -big_x, big_x),
    }


def order(levels: list, measure: str) -> float:
    """Least-squares slope of ln(error) against ln(d)."""
    xs = [mpmath.log(d) for d, _ in levels]
    ys = [mpmath.log(errors[measure]) for _, errors in levels]
    n = len(xs)
    xm, ym = sum(xs) / n, sum(ys) / n
    slope = sum((x - xm) * (y - ym) for x, y in zip(xs, ys, strict=True)) / sum(
        (x - xm) ** 2 for x in xs
    )
    return float(slope)
