"""An independent refinement study of Theorem 11 (Example 12, Remark 13): plain mpmath, no app code.

Different algorithms on purpose:
- the meridians come from ``tests.reference.curvature.d2b``: each vertex is the root (secant
  method) of the mixed area of a face at angle π/3 along the Gauss image edge, with areas by
  Newell's formula and the mixed area by polarization (the service solves a linear equation on a
  quarter-turn face);
- the points of the catenary use the proof's form c(t) = (−½ log((1 + g)/(1 − g)),
  (1 − g²)^(−1/2)) with g evaluated from its formula (the service uses closed forms of artanh g);
- the distance to C is minimized by golden-section search (``tests.reference.convergence``);
- the Riemann sums of the proof of Lemma 10 are plain loops, g' by ``mpmath.diff``.
"""

from __future__ import annotations

import mpmath

from tests.reference import convergence as reference_convergence, curvature as reference_curvature


def _g(name: str, t):
    return 4 * t * t / (1 + 4 * t * t) if name == "example-12" else t / (1 + t)


def _c(ctx, name: str, t):
    g = _g(name, t)
    return -ctx.log((1 + g) / (1 - g)) / 2, 1 / ctx.sqrt(1 - g * g)


def study(j0: int, levels: int, i_min: int, i_max: int, dps: int = 30):
    """[(1/j, {measure: sup error})] for the measures of GET /convergence/theorem-11."""
    ctx = reference_curvature.context(dps)
    out = []

    def catenary(x):
        return x, ctx.cosh(x)

    for k in range(levels):
        j = j0 * 2**k
        lo, hi = 2**k * i_min, 2**k * i_max
        errors = {}
        for name, first, start in (
            ("example-12", max(lo, 0), 0),
            ("remark-13", lo, -((j - 1) // 2)),
        ):
            s = {i: _g(name, ctx.mpf(i) / j) for i in range(min(start, 0), hi + 1)}
            p, _ = reference_curvature.d2b(ctx, s)
            gap = {}
            for i in s:
                cx, cy = _c(ctx, name, ctx.mpf(i) / j)
                gap[i] = ctx.hypot(p[i][0] - cx, p[i][1] - cy)
            window = range(first, hi + 1)
            errors[name] = max(gap[i] for i in window)
            errors[f"{name}-distance"] = max(
                reference_convergence._distance(ctx, p[i], catenary, p[i][0] - 1, p[i][0] + 1)
                for i in window
            )
            if name == "remark-13":
                errors["remark-13-domain"] = max(gap.values())
            else:
                riemann = difference = ctx.mpf(0)
                worst_r = worst_d = ctx.mpf(0)
                for i in range(0, hi + 1):
                    target = _c(ctx, name, ctx.mpf(i) / j)[0]
                    if i >= first:
                        worst_r = max(worst_r, abs(riemann - target))
                        worst_d = max(worst_d, abs(difference - target))
                    t, u = ctx.mpf(i) / j, ctx.mpf(i + 1) / j
                    g = _g(name, t)
                    slope = ctx.diff(lambda v, name=name: _g(name, v), t)
                    riemann += slope / (1 - g * g) * (t - u)
                    difference += (s[i] - s[i + 1]) / (1 - s[i] ** 2) if i < hi else 0
                errors["riemann-sum"], errors["difference-sum"] = worst_r, worst_d
        out.append((ctx.mpf(1) / j, errors))
    return out


def order(levels: list, measure: str) -> float:
    """Least-squares slope of ln(error) against ln(1/j)."""
    return reference_convergence.order(levels, measure)


def error_integral(name: str, t0, t1, dps: int = 30):
    """(1/6)|∫_{t0}^{t1} u'(t)³ dt|, u = artanh g: the leading error term times j² (by quadrature
    of u' = g'/(1 − g²), g' by numerical differentiation)."""
    ctx = mpmath.MPContext()
    ctx.dps = dps

    def cube(t):
        g = _g(name, t)
        slope = ctx.diff(lambda v: _g(name, v), t)
        return (slope / (1 - g * g)) ** 3

    return abs(ctx.quad(cube, [t0, 0, t1] if t0 < 0 < t1 else [t0, t1])) / 6
